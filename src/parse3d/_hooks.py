"""Late bindings from lower layers to higher ones, set by the package root.

A :class:`parse3d.scene.Scene` can save, export, render and show itself, which needs the
exporters and the renderer that sit above the scene layer (DESIGN §2). The scene layer asks
this module for them; the package root (``parse3d/__init__.py``) tells it where they are.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

_SCENE_OUTPUTS: Callable[[], Any] | None = None


def use_scene_outputs(provider: Callable[[], Any]) -> None:
    """Set the function giving the module behind ``Scene.save``/``export``/``render``/``show``
    (:mod:`parse3d.outputs`)."""
    global _SCENE_OUTPUTS
    _SCENE_OUTPUTS = provider


def scene_outputs() -> Any:
    """The module behind ``Scene.save``/``export``/``render``/``show``."""
    if _SCENE_OUTPUTS is None:  # pragma: no cover - the package root always sets it
        raise RuntimeError("parse3d's package root did not set the scene outputs")
    return _SCENE_OUTPUTS()
