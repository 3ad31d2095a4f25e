"""Where user-added assets live, and loading them into the registry at start-up."""

from __future__ import annotations

import os
from pathlib import Path

__all__ = ["user_library_dir", "cache_dir", "load_user_library"]


def cache_dir() -> Path:
    """Root of parse3d's on-disk caches: ``$PARSE3D_CACHE`` or ``~/.cache/parse3d``."""
    return Path(os.environ.get("PARSE3D_CACHE", Path.home() / ".cache" / "parse3d"))


def user_library_dir() -> Path:
    """Folder of categories registered with ``parse3d assets add``."""
    return cache_dir() / "library"


def load_user_library() -> None:
    """Register every category found in the user library (no-op until loaders exist)."""
    try:
        from .loaders import register_library
    except ImportError:
        return
    register_library(user_library_dir())
