"""Where user-added assets live, and loading them into the registry at start-up."""

from __future__ import annotations

import os
from pathlib import Path

from ..errors import InputError, Problem

__all__ = ["user_library_dir", "cache_dir", "load_user_library"]


def cache_dir() -> Path:
    """Root of parse3d's on-disk caches: ``$PARSE3D_CACHE`` or ``~/.cache/parse3d``.

    Raises
    ------
    InputError
        ``PARSE3D_CACHE`` is set but empty or blank (the pool would land in the working
        folder), contains a NUL, or names something that is not a folder (a file, or a path
        through a file).
    """
    env = os.environ.get("PARSE3D_CACHE")
    if env is None:
        return Path.home() / ".cache" / "parse3d"
    if not env.strip() or "\0" in env:
        raise InputError(Problem("", "PARSE3D_CACHE is set but empty: unset it (the default is "
                                     "~/.cache/parse3d) or give a folder", "PARSE3D_CACHE",
                                 "io"))
    root = Path(env).expanduser()
    for p in (root, *root.parents):
        if p.exists():
            if not p.is_dir():
                what = "" if p == root else f" (its parent {p} is a file)"
                raise InputError(Problem("", f"PARSE3D_CACHE={env} is not a folder{what}: give "
                                             "a folder parse3d may write its asset cache to",
                                         "PARSE3D_CACHE", "io"))
            break
    return root


def user_library_dir() -> Path:
    """Folder of categories registered with ``parse3d assets add``."""
    return cache_dir() / "library"


def load_user_library() -> None:
    """Register every category found in the user library.

    A folder with a broken ``category.json`` is skipped with a warning naming the file.
    """
    from .loaders import register_library  # the loaders import the registry, which calls us

    register_library(user_library_dir())
