"""parse3d: Part-centric Assembly Graphs to collision-free, physically settled 3D scenes.

The main entry points::

    import parse3d
    pag = parse3d.load_pag("examples/study.json")
    scene = parse3d.solve(pag, seed=0)
    scene.save("out/study-0")                   # what parse3d solve writes
    scene = parse3d.load_scene("out/study-0")   # a folder written by parse3d solve
    scene.export("study.usd")                   # the format by suffix
    scene.render(640, 480); scene.show()        # an image array; the three.js viewer

See the README for the command line.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from . import _hooks
from . import words as _words
from .errors import InfeasibleError, InputError, Parse3dError

__version__ = "0.1.0"

__all__ = ["__version__", "InputError", "InfeasibleError", "Parse3dError", "PAG", "load_pag", "solve",
           "load_scene"]

if TYPE_CHECKING:  # pragma: no cover
    from .pag.model import PAG


def _library_vocabulary():
    # the registry's vocabulary, from its snapshot when current (no generator imported)
    from .cli._vocab import cli_vocabulary

    return cli_vocabulary()


_words.use_library(_library_vocabulary)


def _scene_outputs():
    # Scene.save/export/render/show live in parse3d.outputs, above the scene layer
    from . import outputs

    return outputs


_hooks.use_scene_outputs(_scene_outputs)


def __getattr__(name: str) -> Any:
    # Lazy: importing parse3d stays cheap; heavy parts load when first used.
    if name == "PAG":
        from .pag.model import PAG

        return PAG
    if name == "load_pag":
        from .pag.io import load_pag

        return load_pag
    if name == "solve":
        from .solver import solve

        return solve
    if name == "load_scene":
        from .scene.io import read_scene

        return read_scene
    raise AttributeError(f"module 'parse3d' has no attribute {name!r}")
