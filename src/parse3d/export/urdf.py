"""URDF (``urdf/<object_id>.urdf`` + ``urdf/scene.json``) for SAPIEN, ManiSkill, PyBullet.

URDF describes one robot, not a scene, so every object is its own file and
``urdf/scene.json`` places them::

    [{"id": "desk", "urdf": "desk.urdf", "position": [x, y, z],
      "quaternion": [w, x, y, z], "fixed": false, "joints": {"door_0_hinge": 0.0}}, ...]

(world frame, +Z up; ``fixed``: load with the root link fixed, for SECURED_TO and
HANGING_BELOW objects; ``joints``: the joint values to set after loading). The room shell is
``urdf/room.urdf``, one link per element, to be loaded fixed at the origin (listed with id
``room``).

In an object's file every part is a link named after the part. The first part of the rigid
base is the root; the other base parts hang from it by ``fixed`` joints; a part moved by an
asset joint hangs from its parent part by a ``revolute`` or ``prismatic`` joint with axis and
limits. Link frames sit on the asset origin (the root and fixed parts) or on the joint's
anchor (moving parts), so meshes, written once per asset part in the asset frame to
``urdf/meshes/``, are placed with a visual/collision origin offset; the object's scale is
baked in (mesh ``scale``, offsets, prismatic limits). Each link carries its visual mesh (an
OBJ whose ``.mtl`` holds the part's colour: URDF ``<material>`` tags would make SAPIEN's
loader ask for a rendering device even for physics-only use), one collision mesh holding the
part's convex pieces as one OBJ object each, and its mass with the inertia of a solid box over
its pieces. Where a part's visual mesh is its pieces joined, as for most generated parts,
visual and collision name the same file, so a part usually costs one mesh file.

Documents are built as ``yourdfpy`` objects (``Robot``, ``Link``, ``Joint``, ...) and written by
yourdfpy.

Loaders read an OBJ object as one convex shape: PyBullet does by default, SAPIEN with
``loader.load_multiple_collisions_from_file = True`` (set by :mod:`parse3d.export.sapien`);
a loader that takes the file as a single convex shape gets the hull of the whole part.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np

from .._files import user_mode
from ..errors import DependencyError
from ..geometry.frames import matrix_to_quat
from ..scene.io import atomic_write_text
from . import MARKERS
from ._files import MeshFiles, join_pieces, remove_stale, safe_name, write_file
from .walk import ObjectRecord, PartRecord, SceneRecord

__all__ = ["NAME", "FILES", "MARKER", "write", "object_urdf"]

NAME = "urdf"
FILES = ("urdf/",)
#: The file whose presence (and age) marks this export in a folder (written last).
MARKER = MARKERS["urdf"]


def _yourdfpy():
    try:
        import yourdfpy
    except ImportError as e:  # pragma: no cover - yourdfpy is a declared dependency
        raise DependencyError("URDF export needs yourdfpy: pip install 'parse3d[export]'") from e
    return yourdfpy


def _at(xyz) -> np.ndarray:
    """(4, 4) translation by ``xyz``."""
    T = np.eye(4)
    T[:3, 3] = np.round(np.asarray(xyz, float), 9) + 0.0  # no "-0.0" in the file
    return T


def _inertial(urdf, pieces: list[tuple[np.ndarray, np.ndarray]], mass: float, scale: float,
              offset: np.ndarray):
    """``<inertial>`` of a solid box over the pieces (link frame = asset frame + offset)."""
    if not pieces or mass <= 0:
        return urdf.Inertial(origin=_at((0, 0, 0)), mass=0.001, inertia=np.eye(3) * 1e-6)
    pts = np.vstack([v for v, _ in pieces]) * scale
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    e = np.maximum(hi - lo, 1e-4)
    diag = mass * np.array([e[1] ** 2 + e[2] ** 2, e[0] ** 2 + e[2] ** 2, e[0] ** 2 + e[1] ** 2]) / 12
    return urdf.Inertial(origin=_at((lo + hi) / 2 + offset), mass=float(f"{mass:.7g}"),
                         inertia=np.diag([float(f"{d:.7g}") for d in diag]))


def _link(urdf, name: str, part: PartRecord | None, visual_mesh: str | None,
          collision_mesh: str | None, mass: float, scale: float, offset: np.ndarray):
    def geometry(filename: str):
        return urdf.Geometry(mesh=urdf.Mesh(filename=filename, scale=np.full(3, float(scale))))

    return urdf.Link(
        name=name,
        inertial=None if part is None else _inertial(urdf, part.pieces, mass, scale, offset),
        visuals=[urdf.Visual(origin=_at(offset), geometry=geometry(visual_mesh))]
        if visual_mesh else [],
        collisions=[urdf.Collision(name=None, origin=_at(offset), geometry=geometry(collision_mesh))]
        if collision_mesh else [])


def _document(urdf, robot) -> str:
    """The URDF text of a ``yourdfpy.Robot``, as yourdfpy writes it."""
    from lxml import etree

    xml = urdf.URDF(robot=robot, build_scene_graph=False, load_meshes=False).write_xml()
    return '<?xml version="1.0"?>\n' + etree.tostring(xml, encoding="unicode") + "\n"


def _part_meshes(meshes: MeshFiles, stem: str, mesh, material,
                 pieces: list[tuple[np.ndarray, np.ndarray]]) -> tuple[str, str | None]:
    """The visual and collision mesh files of one part (or shell element).

    The collision file holds every convex piece as its own OBJ object. When the visual mesh
    is exactly the pieces joined (most generated parts), the visual file is that same OBJ
    with the part's colour, and the collision names it too: one file for the part.
    """
    if pieces:
        v, f = join_pieces(pieces)
        if np.array_equal(v, mesh.vertices) and np.array_equal(f, mesh.faces):
            rel = meshes.get_pieces(stem, pieces, material)
            return rel, rel
    visual = meshes.get(stem, mesh.vertices, mesh.faces, material)
    return visual, meshes.get_pieces(f"{stem}_c", pieces) if pieces else None


def object_urdf(o: ObjectRecord, meshes: MeshFiles) -> str:
    """The URDF document of one object (meshes written through ``meshes``), built as
    ``yourdfpy`` objects and written by yourdfpy."""
    urdf = _yourdfpy()
    s = o.scale
    joint_of = {j.child_link: j for j in o.joints}
    # the frame of each link, in the asset frame at the modelled (closed) pose: the asset
    # origin for rigid parts, the joint anchor for moving ones
    anchor = {p.name: (np.asarray(joint_of[p.name].joint.origin, float) if p.name in joint_of
                       else np.zeros(3)) for p in o.parts}
    links, joints = [], []
    base = o.link("base").parts
    root = base[0].name if base else o.parts[0].name
    for p in o.parts:
        vm, cm = _part_meshes(meshes, f"{o.asset_id}__{p.name}", p.mesh, p.material,
                              p.pieces)
        mass = o.link(p.link).part_mass(p)
        links.append(_link(urdf, p.name, p, vm, cm, mass, s, -anchor[p.name] * s))
        if p.name == root:
            continue
        if p.name in joint_of:
            j = joint_of[p.name]
            parent = j.joint.parent_part if j.joint.parent_part in anchor else root
            lo, hi = sorted(float(v) for v in j.joint.limits)
            k = 1.0 if j.joint.type == "revolute" else s
            joints.append(urdf.Joint(
                name=j.name, type=j.joint.type, parent=parent, child=p.name,
                origin=_at((anchor[p.name] - anchor[parent]) * s),
                axis=np.asarray(j.joint.axis, float),
                limit=urdf.Limit(effort=100.0, velocity=1.0, lower=float(f"{lo * k:.7g}"),
                                 upper=float(f"{hi * k:.7g}")),
                dynamics=urdf.Dynamics(damping=0.1)))
        else:
            joints.append(urdf.Joint(name=f"{root}__{p.name}", type="fixed", parent=root,
                                     child=p.name, origin=_at(-anchor[root] * s)))
    # URDF needs the root link first and parents before children in no particular order
    return _document(urdf, urdf.Robot(name=o.id, links=links, joints=joints))


def _room_urdf(rec: SceneRecord, meshes: MeshFiles) -> str:
    urdf = _yourdfpy()
    links, joints = [], []
    root = rec.shell[0].name
    for s in rec.shell:
        vm, cm = _part_meshes(meshes, f"room__{s.name}", s.mesh, s.material, s.pieces)
        links.append(_link(urdf, s.name, None, vm, cm, 0.0, 1.0, np.zeros(3)))
        if s.name != root:
            joints.append(urdf.Joint(name=f"{root}__{s.name}", type="fixed", parent=root,
                                     child=s.name, origin=_at((0, 0, 0))))
    return _document(urdf, urdf.Robot(name="room", links=links, joints=joints))


def _previous_files(folder: Path) -> set[str]:
    """Files (relative to ``folder``) an earlier export there wrote: the documents its
    ``scene.json`` lists and the meshes they name."""
    try:
        rows = json.loads((folder / "scene.json").read_text(encoding="utf-8"))
        docs = {str(r["urdf"]) for r in rows}
    except (OSError, ValueError, TypeError, KeyError):
        return set()
    found = set(docs)
    for d in docs:
        try:
            text = (folder / d).read_text(encoding="utf-8", errors="replace")
        except OSError:
            continue
        found.update(re.findall(r'<mesh\b[^>]*\bfilename="([^"]+)"', text))
    return found


def write(rec: SceneRecord, out: Path) -> list[Path]:
    """Write ``urdf/<object_id>.urdf``, ``urdf/room.urdf``, ``urdf/meshes/`` and
    ``urdf/scene.json`` into the folder ``out``; returns the paths written.

    Files of an earlier URDF export in ``out`` that this one no longer uses (the document of
    an object gone from the scene, meshes no part references) are removed.
    """
    folder = Path(out) / "urdf"
    folder.mkdir(parents=True, exist_ok=True)
    before = _previous_files(folder)
    meshes = MeshFiles(folder)
    written, rows = [], []
    taken: set[str] = set()
    mode = user_mode()
    for o in rec.objects:
        name = safe_name(o.id)
        while name in taken or name == "room":
            name += "_"
        taken.add(name)
        path = folder / f"{name}.urdf"
        write_file(path, object_urdf(o, meshes).encode(), mode)
        written.append(path)
        rows.append({"id": o.id, "urdf": path.name,
                     "position": [round(float(x), 7) for x in o.position],
                     "quaternion": [round(float(x), 9) for x in matrix_to_quat(o.rotation)],
                     "fixed": bool(o.fixed),
                     "joints": {j.name: round(float(j.value) * (1.0 if j.joint.type == "revolute"
                                                                  else o.scale), 9)
                                for j in o.joints}})
    if rec.shell:
        path = folder / "room.urdf"
        write_file(path, _room_urdf(rec, meshes).encode(), mode)
        written.append(path)
        rows.append({"id": "room", "urdf": "room.urdf", "position": [0.0, 0.0, 0.0],
                     "quaternion": [1.0, 0.0, 0.0, 0.0], "fixed": True, "joints": {}})
    mesh_files = meshes.close()
    index = folder / "scene.json"
    atomic_write_text(index, json.dumps(rows, indent=1) + "\n")
    remove_stale(folder, before, {p.name for p in written} | set(meshes.written))
    return [index, *written, *mesh_files]
