"""MJCF for MuJoCo (``scene.xml`` + ``meshes/``).

:func:`build_xml` writes the model as an MJCF document directly (MuJoCo's documented format;
letting MuJoCo write it would compile every mesh first); :func:`write` saves it, and
:func:`build_spec` parses the same document into a ``mujoco.MjSpec`` for :func:`to_mujoco`,
so the file and the live model are one description. It holds:

- One body per object at its world pose: a free joint for a loose object, none for a fixed
  one (SECURED_TO, HANGING_BELOW: welded to the world by being a plain child of it).
- Per part a visual mesh geom (group 1, the part's colour, no collisions, no mass) and a
  collision mesh geom per convex piece (group 3, the density that gives the part its mass,
  :meth:`~parse3d.export.walk.LinkRecord.part_density`; the part material's friction); MuJoCo takes a mesh geom's convex hull for collisions, which the pieces are.
- Articulated parts are child bodies with a ``hinge`` or ``slide`` joint (axis, anchor,
  range, ``ref`` = the stored value, so the model's initial configuration is the exported
  one); each is locked at that value by a joint equality unless ``lock_joints=False``, so a
  closed door does not swing open while the scene is simulated.
- The room shell: static world geoms (visual and convex collision pieces).
- Options for resting contact: elliptic friction cones, ``impratio`` 10, 3 no-slip
  iterations.

:func:`write` puts the visual meshes as STL files in ``meshes/`` (one per part, shared by
objects using the same asset) and the collision pieces inline in ``scene.xml``; without an
output folder every mesh is inline. Body names are object ids; part geoms are named
``<object_id>:<part_name>`` and pieces ``<object_id>:<part_name>:c<i>``.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from ..errors import DependencyError
from ..geometry.frames import matrix_to_quat
from ..scene.io import atomic_write_text
from ..scene.model import Scene
from . import MARKERS
from ._files import MeshFiles, mesh_digest, remove_stale, safe_name
from .walk import ExportOptions, ObjectRecord, SceneRecord, walk_scene

__all__ = ["NAME", "FILES", "MARKER", "build_spec", "build_xml", "write", "to_mujoco"]

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


def _num(x) -> str:
    return f"{float(x):.12g}"


def _vec(xs) -> str:
    return " ".join(f"{float(x):.12g}" for x in xs)


class _XmlMeshes:
    """Mesh assets of an MJCF document: visual meshes as STL files under ``meshes/`` (inline
    without an output folder), collision pieces inline (``vertex`` / ``face`` attributes),
    each asset written once."""

    def __init__(self, asset, out: Path | None) -> None:
        self.asset = asset
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
        attrs = {"name": key}
        if inline or self.files is None:
            v = np.asarray(vertices, float).ravel().tolist()
            f = np.asarray(faces, np.int64).ravel().tolist()
            attrs["vertex"] = ("%.9g " * len(v) % tuple(v)).rstrip()
            attrs["face"] = ("%d " * len(f) % tuple(f)).rstrip()
        else:
            attrs["file"] = self.files.get(file_stem, vertices, faces)
        if abs(scale - 1.0) >= 1e-12:
            attrs["scale"] = _vec([scale] * 3)
        ET.SubElement(self.asset, "mesh", attrs)
        self.names.add(key)
        return key


def _xml_collision(parent, mesh: str, name: str, density: float, friction: float | None,
                   rgba: str = "0.5 0.5 0.5 0.4"):
    a = {"name": name, "type": "mesh", "mesh": mesh, "group": str(_COLLISION_GROUP),
         "density": _num(density), "rgba": rgba}
    if friction is not None:
        a["friction"] = f"{_num(friction)} 0.005 0.0001"
    ET.SubElement(parent, "geom", a)


def _xml_visual(parent, mesh: str, name: str, mat):
    ET.SubElement(parent, "geom", {"name": name, "type": "mesh", "mesh": mesh,
                                   "group": str(_VISUAL_GROUP), "contype": "0",
                                   "conaffinity": "0", "density": "0", "mass": "0",
                                   "rgba": _vec(mat.color)})


def _xml_object(world, equality, meshes: _XmlMeshes, rec: SceneRecord, o: ObjectRecord, *,
                visual: bool, lock_joints: bool) -> None:
    s = o.scale
    root = ET.SubElement(world, "body", {"name": o.id, "pos": _vec(o.position),
                                         "quat": _vec(matrix_to_quat(o.rotation))})
    if not o.fixed:
        ET.SubElement(root, "freejoint", {"name": f"{o.id}:free"})
    bodies = {}
    motion = {lk.name: lk.motion for lk in o.links}
    parent_of = {j.child_link: j for j in o.joints}
    for lk in o.links:
        if lk.name not in parent_of:
            body = root
        else:
            j = parent_of[lk.name]
            rel = np.linalg.inv(motion[j.parent_link]) @ motion[lk.name]
            body = ET.SubElement(bodies[j.parent_link], "body", {
                "name": f"{o.id}:{lk.name}", "pos": _vec(rel[:3, 3] * s),
                "quat": _vec(matrix_to_quat(rel[:3, :3]))})
            hinge = j.joint.type == "revolute"
            k = 1.0 if hinge else s
            lo, hi = sorted(float(v) for v in j.joint.limits)
            name = f"{o.id}:{j.name}"
            ET.SubElement(body, "joint", {
                "name": name, "type": "hinge" if hinge else "slide",
                "axis": _vec(j.joint.axis), "pos": _vec(np.asarray(j.joint.origin) * s),
                "range": _vec([lo * k, hi * k]), "limited": "true", "ref": _num(j.value * k),
                "damping": "0.1"})
            if lock_joints:
                # MuJoCo measures joint equalities from the reference configuration (``ref``,
                # the exported value): a zero polynomial holds the joint there
                ET.SubElement(equality, "joint", {"name": f"{name}:lock", "joint1": name,
                                                  "polycoef": "0 0 0 0 0"})
        bodies[lk.name] = body
        for p in lk.parts:
            stem = f"{o.asset_id}__{p.name}"
            if visual:
                vm = meshes.get(f"{o.asset_id}:{p.name}", stem, p.mesh.vertices, p.mesh.faces,
                                s)
                _xml_visual(body, vm, p.key, p.material)
            fr = rec.friction(p.material.name)
            for i, (v, f) in enumerate(p.pieces):
                cm = meshes.get(f"{o.asset_id}:{p.name}:c{i}", f"{stem}_c{i}", v, f, s,
                                inline=True)
                _xml_collision(body, cm, f"{p.key}:c{i}", lk.part_density(p), fr)


def build_xml(rec: SceneRecord, out: Path | None = None, *, timestep: float = 0.002,
              visual: bool = True, lock_joints: bool = True) -> tuple[str, MeshFiles | None]:
    """The MJCF document of a walked scene, written as text without compiling a model.

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
    root = ET.Element("mujoco", {"model": safe_name(rec.name or "parse3d")})
    ET.SubElement(root, "compiler", {"angle": "radian", "boundmass": "1e-05",
                                     "boundinertia": "1e-10"})
    ET.SubElement(root, "option", {"timestep": _num(timestep), "cone": "elliptic",
                                   "impratio": "10", "noslip_iterations": "3"})
    asset = ET.SubElement(root, "asset")
    world = ET.SubElement(root, "worldbody")
    equality = ET.Element("equality")
    meshes = _XmlMeshes(asset, None if out is None else Path(out))
    fr = rec.friction("room")
    for s in rec.shell:
        if visual:
            vm = meshes.get(s.key, f"room__{s.name}", s.mesh.vertices, s.mesh.faces)
            _xml_visual(world, vm, s.key, s.material)
        for i, (v, f) in enumerate(s.pieces):
            cm = meshes.get(f"{s.key}:c{i}", f"room__{s.name}_c{i}", v, f, inline=True)
            _xml_collision(world, cm, f"{s.key}:c{i}", 0.0, fr, "0.8 0.8 0.8 0.2")
    for o in rec.objects:
        _xml_object(world, equality, meshes, rec, o, visual=visual, lock_joints=lock_joints)
    if len(equality):
        root.append(equality)
    ET.indent(root, space=" ")
    return ET.tostring(root, encoding="unicode") + "\n", meshes.files


def build_spec(rec: SceneRecord, *, out: Path | None = None, timestep: float = 0.002,
               visual: bool = True, lock_joints: bool = True):
    """An ``mujoco.MjSpec`` of a walked scene: the document of :func:`build_xml`, parsed.

    One description of the model serves both the file export and live models, so
    ``scene.xml`` and :func:`to_mujoco` cannot drift apart.

    Parameters
    ----------
    rec : SceneRecord
    out : Path or None
        Folder whose ``meshes/`` receives the visual mesh files (written now; the spec's
        ``modelfiledir``); None keeps every mesh inline in the spec.
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
    xml, files = build_xml(rec, out, timestep=timestep, visual=visual, lock_joints=lock_joints)
    spec = _mujoco().MjSpec.from_string(xml)
    if files is not None:
        files.close()
        spec.modelfiledir = str(out)
    return spec


def write(rec: SceneRecord, out: Path, *, lock_joints: bool = True) -> list[Path]:
    """Write ``scene.xml`` and ``meshes/`` into the folder ``out``; returns the paths.

    The document is written directly (MuJoCo's documented MJCF), not by compiling an
    ``MjSpec``: compiling every mesh of a large scene costs more than the whole export.
    Mesh files an earlier ``scene.xml`` in ``out`` named and this one does not are removed.
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
