"""The whole per-scene pipeline: solve, settle, extract contacts, write, preview.

Used by ``parse3d solve``, ``parse3d generate``, ``parse3d demo`` and the dataset builder, so
they all produce the same files (DESIGN §5).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

from .pag.model import PAG
from .scene.model import Scene
from .solver import SolverConfig, solve

__all__ = ["PipelineOptions", "run_pipeline"]


@dataclass(frozen=True)
class PipelineOptions:
    """What to run after solving.

    Attributes
    ----------
    settle : bool
        Settle in SAPIEN and extract the part-level contact graph.
    preview : bool
        Render ``preview.png``.
    solver : SolverConfig
    formats : tuple of str
        Export formats written next to ``scene.json`` (names of ``parse3d.export.FORMATS``).
    """

    settle: bool = True
    preview: bool = True
    solver: SolverConfig = SolverConfig()
    formats: tuple[str, ...] = ("glb",)


def run_pipeline(pag: PAG, *, seed: int, out: str | Path | None,
                 options: PipelineOptions = PipelineOptions(), library=None) -> Scene:
    """Solve ``pag`` and, per ``options``, settle, extract contacts, write and preview.

    Returns the scene; ``scene.ok`` tells whether every object was placed.
    """
    scene = solve(pag, seed=seed, config=options.solver, library=library)
    if options.settle and scene.placed:
        from .physics import extract_contacts, settle

        t = time.perf_counter()
        settle(scene)
        scene.timings["settle"] = time.perf_counter() - t
        t = time.perf_counter()
        scene.contacts = extract_contacts(scene)
        scene.timings["contacts"] = time.perf_counter() - t
    if out is not None:
        from .export import ExportOptions, export_scene
        from .physics.mujoco import settling_friction
        from .scene.io import write_scene

        write_scene(scene, out)
        export_scene(scene, out, options.formats, ExportOptions(friction=settling_friction()))
        if options.preview:
            from .render import save_preview

            t = time.perf_counter()
            save_preview(scene, Path(out) / "preview.png")
            scene.timings["preview"] = time.perf_counter() - t
            write_scene(scene, out)
    return scene
