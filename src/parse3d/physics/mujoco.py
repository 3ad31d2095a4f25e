"""The same scene in MuJoCo: an independent engine to check that a settled scene is at rest.

:func:`scene_to_mjcf` writes an MJCF model from the collision pieces that settling used,
through the MJCF exporter (:mod:`parse3d.export.mjcf`, built on ``mujoco.MjSpec``): one mesh
geom per convex piece (MuJoCo takes their convex hulls), a free joint per dynamic object,
fixed objects welded to the world and the room shell as static world geoms, with the
friction of every part's material family as settling uses it. :func:`mujoco_motion`
simulates it and reports how far every object moved.

The solver options follow MuJoCo's advice for resting contact: elliptic friction cones, a high
``impratio`` and a few no-slip iterations, so objects do not creep on inclined or light
contacts.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import DependencyError
from ..geometry.frames import quat_to_matrix
from ..scene.model import Scene
from .bodies import MATERIALS, SHELL_MATERIAL

__all__ = ["scene_to_mjcf", "mujoco_motion", "MujocoMotion", "settling_friction"]


def settling_friction() -> dict[str, float]:
    """Static friction per material family as settling uses it, plus ``room`` for the shell
    (the table exporters write into simulator formats)."""
    table = {k: m.static_friction for k, m in MATERIALS.items()}
    table["room"] = SHELL_MATERIAL.static_friction
    return table


def _spec(scene: Scene, settled: bool, timestep: float):
    from ..export.mjcf import build_spec
    from ..export.walk import ExportOptions, walk_scene

    rec = walk_scene(scene, ExportOptions(settled=settled, friction=settling_friction()))
    return build_spec(rec, timestep=timestep, visual=False)


def scene_to_mjcf(scene: Scene, *, settled: bool = True, timestep: float = 0.002) -> str:
    """An MJCF document of ``scene`` (objects at their settled pose by default).

    Parameters
    ----------
    scene : Scene
    settled : bool
        Start from the settled poses (where present) instead of the solved ones.
    timestep : float
        MuJoCo time step, seconds.

    Returns
    -------
    str
        The MJCF XML (meshes inline); bodies are named by object id.
    """
    return _spec(scene, settled, timestep).to_xml()


@dataclass
class MujocoMotion:
    """Displacement (m) and rotation (deg) of one object over a MuJoCo run."""

    id: str
    displacement: float
    rotation_deg: float


def mujoco_motion(scene: Scene, *, seconds: float = 1.0, timestep: float = 0.002,
                  settled: bool = True) -> dict[str, MujocoMotion]:
    """Simulate ``scene`` in MuJoCo for ``seconds`` and measure every object's motion.

    Returns
    -------
    dict of str to MujocoMotion
        Per object id (fixed objects included, with zero motion).
    """
    try:
        import mujoco
    except ImportError as e:  # pragma: no cover - mujoco is a declared dependency
        raise DependencyError("the MuJoCo check needs mujoco: pip install 'parse3d[check]'") from e
    model = _spec(scene, settled, timestep).compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    ids = [o.id for o in scene.placed if o.asset is not None]
    bid = {i: mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, i) for i in ids}
    p0 = {i: data.xpos[b].copy() for i, b in bid.items()}
    q0 = {i: data.xquat[b].copy() for i, b in bid.items()}
    for _ in range(int(round(seconds / timestep))):
        mujoco.mj_step(model, data)
    out = {}
    for i, b in bid.items():
        R = quat_to_matrix(data.xquat[b]) @ quat_to_matrix(q0[i]).T
        ang = float(np.degrees(np.arccos(np.clip((np.trace(R) - 1) / 2, -1, 1))))
        out[i] = MujocoMotion(i, float(np.linalg.norm(data.xpos[b] - p0[i])), ang)
    return out
