"""Optional dependencies: name the extra to install before any work starts.

A command whose optional package is missing must say so before it touches the disk, in one
line that names the ``pip install 'parse3d[EXTRA]'`` to run.
"""

from __future__ import annotations

import importlib.util

from .errors import DependencyError

__all__ = ["EXTRAS", "require"]

#: The extra of ``pyproject.toml`` that provides each optional top-level module.
EXTRAS = {
    "sapien": "physics", "coacd": "physics", "moderngl": "render", "pyarrow": "dataset",
    "ray": "cluster", "mujoco": "check", "pxr": "export", "yourdfpy": "export", "torch": "ml",
    "diffusers": "ml", "transformers": "ml", "peft": "ml", "fastapi": "web", "uvicorn": "web",
}


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
