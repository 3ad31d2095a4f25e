"""MJCF for MuJoCo (``scene.xml`` + ``meshes/``).

:func:`build_spec` builds the model as a ``mujoco.MjSpec``, element by element through
MuJoCo's model-editing API; :func:`to_mujoco` compiles it and :func:`write` has MuJoCo write it
(``MjSpec.to_xml``), so the file and the live model are one description. It holds:

- One body per object at its world pose: a free joint for a loose object, none for a fixed
  one (SECURED_TO, HANGING_BELOW: welded to the world by being a plain child of it).
- Per part a visual mesh geom (group 1, the part's colour, no collisions, no mass) and a
  collision mesh geom per convex piece (group 3, the density that gives the part its mass,
  :meth:`~parse3d.export.walk.LinkRecord.part_density`; the part material's friction);
  MuJoCo takes a mesh geom's convex hull for collisions, which the pieces are.
- Articulated parts are child bodies with a ``hinge`` or ``slide`` joint (axis, anchor,
  range, ``ref`` = the stored value, so the model's initial configuration is the exported
  one); each is locked at that value by a joint equality unless ``lock_joints=False``, so a
  closed door does not swing open while the scene is simulated.
- The room shell: static world geoms (visual and convex collision pieces).
- Options for resting contact (:data:`OPTIONS`): elliptic friction cones, ``impratio`` 10,
  no no-slip pass (it cost more than half of each step of a 64-object room, and the settled
  room rests as well without it).

:func:`write` puts the visual meshes as STL files in ``meshes/`` (one per part, shared by
objects using the same asset) and the collision pieces inline in ``scene.xml``; without an
output folder every mesh is inline. Body names are object ids; part geoms are named
``<object_id>:<part_name>`` and pieces ``<object_id>:<part_name>:c<i>``.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from ..errors import DependencyError
from ..geometry.frames import matrix_to_quat
from ..scene.io import atomic_write_text
from ..scene.model import Scene
from . import MARKERS
from ._files import MeshFiles, mesh_digest, remove_stale, safe_name
from .walk import ExportOptions, ObjectRecord, SceneRecord, walk_scene

__all__ = ["NAME", "FILES", "MARKER", "OPTIONS", "build_spec", "build_xml", "write", "to_mujoco"]

NAME = "mjcf"
FILES = ("scene.xml", "meshes/")
#: The file whose presence (and age) marks this export in a folder (written last).
MARKER = MARKERS["mjcf"]

_VISUAL_GROUP, _COLLISION_GROUP = 1, 3


def _mujoco():
    try:
        import mujoco
    except ImportError as e:  # pragma: no cover - mujoco is a declared dependency
        raise DependencyError("MJCF export needs mujoco: pip install 'parse3d[export]'") from e
    return mujoco


def _mesh_refs(xml: Path) -> set[str]:
    """Mesh files (relative to the folder) named by an earlier ``scene.xml``."""
    try:
        text = xml.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return set()
    return set(re.findall(r'<mesh\b[^>]*\bfile="([^"]+)"', text))


#: Simulation options for resting contact (see the module docstring).
OPTIONS = {"cone": "elliptic", "impratio": 10.0, "noslip_iterations": 0}


class _SpecMeshes:
    """Mesh assets of a spec: visual meshes as STL files under ``meshes/`` (inline without an
    output folder), collision pieces inline (``uservert`` / ``userface``), each written
    once."""

    def __init__(self, spec, out: Path | None) -> None:
        self.spec = spec
        self.files = None if out is None else MeshFiles(out)
        self.names: set[str] = set()
        self._by_content: dict[tuple[str, float], str] = {}

    def get(self, name: str, file_stem: str, vertices, faces, scale: float = 1.0, *,
            inline: bool = False) -> str:
        key = name if abs(scale - 1.0) < 1e-12 else f"{name}@{scale:.9g}"
        if key in self.names:
            return key
        content = (mesh_digest(vertices, faces), round(float(scale), 9))
        if content in self._by_content:
            return self._by_content[content]
        self._by_content[content] = key
        mesh = self.spec.add_mesh(name=key)
        if inline or self.files is None:
            mesh.uservert = np.asarray(vertices, np.float32).ravel()
            mesh.userface = np.asarray(faces, np.int32).ravel()
        else:
            mesh.file = self.files.get(file_stem, vertices, faces)
        if abs(scale - 1.0) >= 1e-12:
            mesh.scale = [float(scale)] * 3
        self.names.add(key)
        return key


def _collision(mujoco, parent, mesh: str, name: str, density: float, friction: float | None,
               rgba=(0.5, 0.5, 0.5, 0.4)) -> None:
    g = parent.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_MESH, meshname=mesh,
                        group=_COLLISION_GROUP, density=float(density), rgba=list(rgba))
    if friction is not None:
        g.friction = [float(friction), 0.005, 0.0001]


def _visual(mujoco, parent, mesh: str, name: str, mat) -> None:
    parent.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_MESH, meshname=mesh,
                    group=_VISUAL_GROUP, contype=0, conaffinity=0, density=0.0, mass=0.0,
                    rgba=[float(c) for c in mat.color])


def _object(mujoco, spec, meshes: _SpecMeshes, rec: SceneRecord, o: ObjectRecord, *,
            visual: bool, lock_joints: bool) -> None:
    s = o.scale
    root = spec.worldbody.add_body(name=o.id, pos=[float(x) for x in o.position],
                                   quat=[float(x) for x in matrix_to_quat(o.rotation)])
    if not o.fixed:
        root.add_freejoint(name=f"{o.id}:free")
    bodies = {}
    motion = {lk.name: lk.motion for lk in o.links}
    parent_of = {j.child_link: j for j in o.joints}
    for lk in o.links:
        if lk.name not in parent_of:
            body = root
        else:
            j = parent_of[lk.name]
            rel = np.linalg.inv(motion[j.parent_link]) @ motion[lk.name]
            body = bodies[j.parent_link].add_body(
                name=f"{o.id}:{lk.name}", pos=[float(x) for x in rel[:3, 3] * s],
                quat=[float(x) for x in matrix_to_quat(rel[:3, :3])])
            hinge = j.joint.type == "revolute"
            k = 1.0 if hinge else s
            lo, hi = sorted(float(v) for v in j.joint.limits)
            name = f"{o.id}:{j.name}"
            body.add_joint(name=name,
                           type=mujoco.mjtJoint.mjJNT_HINGE if hinge else mujoco.mjtJoint.mjJNT_SLIDE,
                           axis=[float(x) for x in j.joint.axis],
                           pos=[float(x) for x in np.asarray(j.joint.origin) * s],
                           range=[lo * k, hi * k], limited=mujoco.mjtLimited.mjLIMITED_TRUE,
                           ref=float(j.value * k), damping=0.1)
            if lock_joints:
                # MuJoCo measures joint equalities from the reference configuration (``ref``,
                # the exported value): a zero polynomial holds the joint there
                eq = spec.add_equality(name=f"{name}:lock", type=mujoco.mjtEq.mjEQ_JOINT,
                                       objtype=mujoco.mjtObj.mjOBJ_JOINT, name1=name)
                data = np.array(eq.data)  # MuJoCo's defaults, with the polynomial zeroed
                data[:5] = 0.0
                eq.data = data
        bodies[lk.name] = body
        for p in lk.parts:
            stem = f"{o.asset_id}__{p.name}"
            if visual:
                vm = meshes.get(f"{o.asset_id}:{p.name}", stem, p.mesh.vertices, p.mesh.faces,
                                s)
                _visual(mujoco, body, vm, p.key, p.material)
            fr = rec.friction(p.material.name)
            density = lk.part_density(p)
            for i, (v, f) in enumerate(p.pieces):
                cm = meshes.get(f"{o.asset_id}:{p.name}:c{i}", f"{stem}_c{i}", v, f, s,
                                inline=True)
                _collision(mujoco, body, cm, f"{p.key}:c{i}", density, fr)


def _build(rec: SceneRecord, out: Path | None, *, timestep: float, visual: bool,
           lock_joints: bool):
    mujoco = _mujoco()
    spec = mujoco.MjSpec()
    spec.modelname = safe_name(rec.name or "parse3d")
    spec.compiler.degree = False
    spec.compiler.boundmass = 1e-5
    spec.compiler.boundinertia = 1e-10
    spec.option.timestep = float(timestep)
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.option.impratio = OPTIONS["impratio"]
    spec.option.noslip_iterations = OPTIONS["noslip_iterations"]
    meshes = _SpecMeshes(spec, None if out is None else Path(out))
    fr = rec.friction("room")
    for sh in rec.shell:
        if visual:
            vm = meshes.get(sh.key, f"room__{sh.name}", sh.mesh.vertices, sh.mesh.faces)
            _visual(mujoco, spec.worldbody, vm, sh.key, sh.material)
        for i, (v, f) in enumerate(sh.pieces):
            cm = meshes.get(f"{sh.key}:c{i}", f"room__{sh.name}_c{i}", v, f, inline=True)
            _collision(mujoco, spec.worldbody, cm, f"{sh.key}:c{i}", 0.0, fr,
                       (0.8, 0.8, 0.8, 0.2))
    for o in rec.objects:
        _object(mujoco, spec, meshes, rec, o, visual=visual, lock_joints=lock_joints)
    if out is not None:
        spec.modelfiledir = str(out)
    return spec, meshes.files


def build_spec(rec: SceneRecord, *, out: Path | None = None, timestep: float = 0.002,
               visual: bool = True, lock_joints: bool = True):
    """A ``mujoco.MjSpec`` of a walked scene, built element by element.

    The file export is this spec written out (:func:`build_xml`), so ``scene.xml`` and
    :func:`to_mujoco` are one description and cannot drift apart.

    Parameters
    ----------
    rec : SceneRecord
    out : Path or None
        Folder whose ``meshes/`` receives the visual mesh files (written now, and closed; the
        spec's ``modelfiledir``); None keeps every mesh inline in the spec.
    timestep : float
        Seconds.
    visual : bool
        Add the visual mesh geoms (the collision geoms are always there).
    lock_joints : bool
        Hold every articulation at its exported value with a joint equality.

    Returns
    -------
    mujoco.MjSpec
    """
    spec, files = _build(rec, out, timestep=timestep, visual=visual, lock_joints=lock_joints)
    if files is not None:
        files.close()
    return spec


def build_xml(rec: SceneRecord, out: Path | None = None, *, timestep: float = 0.002,
              visual: bool = True, lock_joints: bool = True) -> tuple[str, MeshFiles | None]:
    """The MJCF document of a walked scene: :func:`build_spec`'s spec, as MuJoCo writes it.

    Parameters
    ----------
    rec : SceneRecord
    out : Path or None
        Folder whose ``meshes/`` receives the visual meshes as files (written now); None
        keeps every mesh inline in the document. Collision pieces are always inline.
    timestep : float
        Seconds.
    visual : bool
        Add the visual mesh geoms (the collision geoms are always there).
    lock_joints : bool
        Hold every articulation at its exported value with a joint equality.

    Returns
    -------
    xml : str
    files : MeshFiles or None
        The mesh files written (call ``close()`` for the material library); None without
        ``out``.
    """
    spec, files = _build(rec, out, timestep=timestep, visual=visual, lock_joints=lock_joints)
    return spec.to_xml(), files


def write(rec: SceneRecord, out: Path, *, lock_joints: bool = True) -> list[Path]:
    """Write ``scene.xml`` and ``meshes/`` into the folder ``out``; returns the paths.

    The document is :func:`build_spec`'s spec as MuJoCo writes it (``MjSpec.to_xml``, which
    compiles the model first). Mesh files an earlier ``scene.xml`` in ``out`` named and this one does not are removed.
    """
    out = Path(out)
    path = out / "scene.xml"
    before = _mesh_refs(path)
    xml, files = build_xml(rec, out, lock_joints=lock_joints)
    atomic_write_text(path, xml)
    written = files.close()
    remove_stale(out, before, set(files.written))
    return [path, *written]


def to_mujoco(scene: Scene, options: ExportOptions = ExportOptions(), *,
              timestep: float = 0.002, visual: bool = True, lock_joints: bool = True):
    """A live MuJoCo model of ``scene``: ``(MjModel, MjData)`` after ``mj_forward``.

    Parameters
    ----------
    scene : Scene
    options : ExportOptions
        Pose, ceiling, joint opening and friction table (see :class:`ExportOptions`).
    timestep : float
        Seconds.
    visual : bool
        Include the visual geoms.
    lock_joints : bool
        Hold articulations at their exported values.
    """
    mujoco = _mujoco()
    spec = build_spec(walk_scene(scene, options), timestep=timestep, visual=visual,
                      lock_joints=lock_joints)
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    return model, data
