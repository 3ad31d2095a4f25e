"""The Part-Aware Spatial Configuration Solver (Algorithm 1 of the paper).

>>> import parse3d
>>> scene = parse3d.solve(parse3d.load_pag("examples/study.json"), seed=0)  # doctest: +SKIP
"""

from __future__ import annotations

from ..measure.checks import check_relations
from ..pag.model import PAG
from ..scene.model import Scene
from .core import SolverConfig, solve_scene
from .library import AssetLibrary

__all__ = ["solve", "SolverConfig", "AssetLibrary", "check_relations"]


def solve(pag: PAG, seed: int = 0, *, library: AssetLibrary | None = None,
          config: SolverConfig | None = None, validate: bool = True) -> Scene:
    """Turn a PAG into a Scene.

    Parameters
    ----------
    pag : PAG
        The graph (validated first, against the asset registry's vocabulary, unless
        ``validate=False``).
    seed : int
        Scene seed; the same PAG, seed and library give the same scene.
    library : AssetLibrary, optional
        Where assets come from (default: a process-wide in-memory pool).
    config : SolverConfig, optional

    Returns
    -------
    Scene
        Failed objects are marked ``failed`` with the constraint that could not be met; check
        ``scene.ok``. (The CLI turns failures into exit code 3.)

    Raises
    ------
    InputError
        The PAG is invalid.
    """
    if validate:
        from ..assets.registry import vocabulary

        pag.validate(vocabulary=vocabulary())
    return solve_scene(pag, seed=seed, library=library, config=config)
