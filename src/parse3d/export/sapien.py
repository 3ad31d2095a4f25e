"""A live SAPIEN 3 scene of a parse3d scene, through the URDF export.

:func:`to_sapien` writes the URDF export into a temporary folder and loads every object with
SAPIEN's own URDF loader — so what a user loads from ``urdf/`` and what this function builds
are the same bodies — at its pose from ``urdf/scene.json``, root fixed for fixed objects and
the room, joints set to their exported values (free, or held there by stiff drives with
``free_joints=False``). Without a rendering device (a headless
machine) visual shapes are skipped and the scene is physics-only.
"""

from __future__ import annotations

import json
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import DependencyError
from ..scene.model import Scene
from . import urdf
from .walk import ExportOptions, walk_scene

__all__ = ["SapienScene", "to_sapien", "load_urdf_scene"]


@dataclass
class SapienScene:
    """What :func:`to_sapien` built.

    Attributes
    ----------
    scene : sapien.Scene
    articulations : dict of str to sapien.physx.PhysxArticulation
        Per object id (and ``room``) for multi-part objects.
    actors : dict of str to sapien.Entity
        Per object id for one-part objects (SAPIEN's loader makes a single-link URDF a plain
        rigid body: dynamic, or static when fixed).
    rendered : bool
        Whether visual shapes were loaded (a rendering device was found).
    """

    scene: object
    articulations: dict[str, object] = field(default_factory=dict)
    actors: dict[str, object] = field(default_factory=dict)
    rendered: bool = False


def _sapien():
    import warnings

    try:
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message=".*libvulkan.*")
            import sapien
    except ImportError as e:  # pragma: no cover - sapien is a declared dependency
        raise DependencyError("to_sapien needs SAPIEN 3: pip install 'parse3d[physics]'") from e
    return sapien


#: Drive holding a locked joint at its value: stiffness (N·m/rad or N/m) and damping.
LOCK_STIFFNESS, LOCK_DAMPING = 1e5, 1e3


def load_urdf_scene(folder: str | Path, *, timestep: float = 0.01,
                    render: bool | None = None, free_joints: bool = True) -> SapienScene:
    """Load a ``urdf/`` export (its ``scene.json``) into a new SAPIEN scene.

    Parameters
    ----------
    folder : path
        The ``urdf`` folder of an export.
    timestep : float
        Physics time step, seconds.
    render : bool or None
        Load visual shapes: None tries and falls back to physics-only when no rendering
        device is found; False never loads them.
    free_joints : bool
        Leave the joints free (doors swing, drawers slide); False holds each at its value
        with a stiff drive (:data:`LOCK_STIFFNESS`), as settling keeps joints locked.
    """
    sapien = _sapien()
    physx = sapien.physx
    folder = Path(folder)
    rows = json.loads((folder / "scene.json").read_text())
    physx.set_scene_config(gravity=np.array([0.0, 0.0, -9.81], np.float32), cpu_workers=0)
    systems = [physx.PhysxCpuSystem()]
    rendered = False
    if render is not False:
        try:
            systems.append(sapien.render.RenderSystem())
            rendered = True
        except RuntimeError:  # no rendering device: physics only
            if render:
                raise
    scene = sapien.Scene(systems=systems)
    scene.set_timestep(float(timestep))
    out = SapienScene(scene, rendered=rendered)
    for r in rows:
        loader = scene.create_urdf_loader()
        # a part's collision file holds its convex pieces as OBJ objects, one shape each
        loader.load_multiple_collisions_from_file = True
        builders, actors, _ = loader.parse(str(folder / r["urdf"]))
        pose = sapien.Pose(np.asarray(r["position"], np.float32),
                           np.asarray(r["quaternion"], np.float32))
        if not builders:
            b = actors[0]
            if not rendered:
                b.visual_records = []
            b.initial_pose = pose
            b.set_physx_body_type("static" if r["fixed"] else "dynamic")
            out.actors[r["id"]] = b.build(name=r["id"])
            continue
        b = builders[0]
        if not rendered:
            for lb in b.link_builders:
                lb.visual_records = []
        b.initial_pose = pose
        art = b.build(fix_root_link=bool(r["fixed"]))
        art.name = r["id"]
        names = [j.name for j in art.active_joints]
        q = np.array([r["joints"].get(n, 0.0) for n in names], np.float32)
        if r["joints"]:
            art.set_qpos(q)
        if not free_joints:
            for j, v in zip(art.active_joints, q, strict=True):
                j.set_drive_property(LOCK_STIFFNESS, LOCK_DAMPING)
                j.set_drive_target(float(v))
        out.articulations[r["id"]] = art
    return out


def to_sapien(scene: Scene, options: ExportOptions = ExportOptions(), *,
              timestep: float = 0.01, render: bool | None = None,
              free_joints: bool = True) -> SapienScene:
    """A live SAPIEN scene of ``scene`` (see the module docstring).

    Parameters
    ----------
    scene : Scene
    options : ExportOptions
        Pose, ceiling and joint opening.
    timestep : float
        Physics time step, seconds.
    render, free_joints : bool or None, bool
        As :func:`load_urdf_scene`.
    """
    with tempfile.TemporaryDirectory(prefix="parse3d-sapien-") as tmp:
        urdf.write(walk_scene(scene, options), Path(tmp))
        return load_urdf_scene(Path(tmp) / "urdf", timestep=timestep, render=render,
                               free_joints=free_joints)
