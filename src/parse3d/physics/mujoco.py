"""The same scene in MuJoCo: an independent engine to check that a settled scene is at rest.

:func:`scene_to_mjcf` writes an MJCF model from the collision pieces that settling used (one
mesh geom per convex piece, inline vertices; MuJoCo takes their convex hulls), with a free
joint per dynamic object, fixed objects welded to the world and the room shell as static world
geoms. :func:`mujoco_motion` simulates it and reports how far every object moved.

The solver options follow MuJoCo's advice for resting contact: elliptic friction cones, a high
``impratio`` and a few no-slip iterations, so objects do not creep on inclined or light
contacts.
"""

from __future__ import annotations

from dataclasses import dataclass
from xml.sax.saxutils import quoteattr

import numpy as np

from ..errors import DependencyError
from ..geometry.frames import matrix_to_quat, quat_to_matrix
from ..scene.model import Scene
from .bodies import SHELL_MATERIAL, material_physics
from .collision import ConvexSet, asset_collision, shell_collision

__all__ = ["scene_to_mjcf", "mujoco_motion", "MujocoMotion"]


def _fmt(a) -> str:
    return " ".join(f"{float(x):.7g}" for x in np.asarray(a).ravel())


def _mesh_assets(prefix: str, pieces: ConvexSet, scale: float) -> tuple[list[str], list[str]]:
    names, xml = [], []
    for i in range(len(pieces)):
        name = f"{prefix}_{i}"
        names.append(name)
        xml.append(f'<mesh name={quoteattr(name)} vertex="{_fmt(pieces.piece_vertices(i) * scale)}"/>')
    return names, xml


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
        The MJCF XML; bodies are named by object id.
    """
    assets, world, bodies = [], [], []
    shell = shell_collision(scene.room)
    names, xml = _mesh_assets("room", shell, 1.0)
    assets += xml
    sm = SHELL_MATERIAL
    for n in names:
        world.append(f'<geom type="mesh" mesh="{n}" friction="{sm.static_friction} 0.005 0.0001"/>')
    for k, obj in enumerate(scene.placed):
        if obj.asset is None:
            continue
        data = asset_collision(obj.asset)
        names, xml = _mesh_assets(f"o{k}", data.pieces, obj.scale)
        assets += xml
        R, t = obj.rotation, obj.position
        if settled and obj.settled_position is not None:
            R, t = obj.settled_rotation, obj.settled_position
        geoms = []
        for n, mat in zip(names, data.materials, strict=True):
            mu = material_physics(mat).static_friction
            geoms.append(f'<geom type="mesh" mesh="{n}" density="{data.density:.6g}" '
                         f'friction="{mu} 0.005 0.0001"/>')
        joint = "" if obj.fixed else "<freejoint/>"
        bodies.append(f'<body name={quoteattr(obj.id)} pos="{_fmt(t)}" quat="{_fmt(matrix_to_quat(R))}">'
                      f'{joint}{"".join(geoms)}</body>')
    return (
        '<mujoco model="parse3d">'
        '<compiler angle="radian" boundmass="1e-5" boundinertia="1e-10"/>'
        f'<option timestep="{timestep}" cone="elliptic" impratio="10" noslip_iterations="3"/>'
        f'<asset>{"".join(assets)}</asset>'
        f'<worldbody>{"".join(world)}{"".join(bodies)}</worldbody>'
        '</mujoco>'
    )


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
    model = mujoco.MjModel.from_xml_string(scene_to_mjcf(scene, settled=settled,
                                                         timestep=timestep))
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
