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

Loaders read an OBJ object as one convex shape: PyBullet does by default, SAPIEN with
``loader.load_multiple_collisions_from_file = True`` (set by :mod:`parse3d.export.sapien`);
a loader that takes the file as a single convex shape gets the hull of the whole part.
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from .._files import user_mode
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


def _f(a) -> str:
    return " ".join(f"{float(x):.7g}" for x in np.asarray(a, float).ravel())


def _inertial(pieces: list[tuple[np.ndarray, np.ndarray]], mass: float, scale: float,
              offset: np.ndarray) -> str:
    """``<inertial>`` of a solid box over the pieces (link frame = asset frame + offset)."""
    if not pieces or mass <= 0:
        return ('<inertial><origin xyz="0 0 0"/><mass value="0.001"/>'
                '<inertia ixx="1e-06" iyy="1e-06" izz="1e-06" ixy="0" ixz="0" iyz="0"/>'
                '</inertial>')
    pts = np.vstack([v for v, _ in pieces]) * scale
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    c = (lo + hi) / 2 + offset
    e = np.maximum(hi - lo, 1e-4)
    ixx = mass * (e[1] ** 2 + e[2] ** 2) / 12
    iyy = mass * (e[0] ** 2 + e[2] ** 2) / 12
    izz = mass * (e[0] ** 2 + e[1] ** 2) / 12
    return (f'<inertial><origin xyz="{_f(c)}"/><mass value="{mass:.7g}"/>'
            f'<inertia ixx="{ixx:.7g}" iyy="{iyy:.7g}" izz="{izz:.7g}" ixy="0" ixz="0" '
            'iyz="0"/></inertial>')


def _link(name: str, part: PartRecord | None, visual_mesh: str | None,
          collision_mesh: str | None, mass: float, scale: float, offset: np.ndarray) -> str:
    xml = [f"<link name={quoteattr(name)}>"]
    sc = _f([scale] * 3)
    o = f'<origin xyz="{_f(offset)}"/>'
    if part is not None:
        xml.append(_inertial(part.pieces, mass, scale, offset))
    if visual_mesh:
        xml.append(f"<visual>{o}<geometry><mesh filename={quoteattr(visual_mesh)} "
                   f'scale="{sc}"/></geometry></visual>')
    if collision_mesh:
        xml.append(f"<collision>{o}<geometry><mesh filename={quoteattr(collision_mesh)} "
                   f'scale="{sc}"/></geometry></collision>')
    xml.append("</link>")
    return "".join(xml)


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
    """The URDF document of one object (meshes written through ``meshes``)."""
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
        links.append(_link(p.name, p, vm, cm, mass, s, -anchor[p.name] * s))
        if p.name == root:
            continue
        if p.name in joint_of:
            j = joint_of[p.name]
            parent = j.joint.parent_part if j.joint.parent_part in anchor else root
            xyz = (anchor[p.name] - anchor[parent]) * s
            lo, hi = sorted(float(v) for v in j.joint.limits)
            k = 1.0 if j.joint.type == "revolute" else s
            joints.append(
                f'<joint name={quoteattr(j.name)} type="{j.joint.type}">'
                f"<parent link={quoteattr(parent)}/><child link={quoteattr(p.name)}/>"
                f'<origin xyz="{_f(xyz)}"/><axis xyz="{_f(j.joint.axis)}"/>'
                f'<limit lower="{lo * k:.7g}" upper="{hi * k:.7g}" effort="100" velocity="1"/>'
                '<dynamics damping="0.1"/></joint>')
        else:
            joints.append(f'<joint name={quoteattr(f"{root}__{p.name}")} type="fixed">'
                          f"<parent link={quoteattr(root)}/><child link={quoteattr(p.name)}/>"
                          f'<origin xyz="{_f(-anchor[root] * s)}"/></joint>')
    # URDF needs the root link first and parents before children in no particular order
    return (f'<?xml version="1.0"?>\n<robot name={quoteattr(o.id)}>' + "".join(links) + "".join(joints) + "</robot>\n")


def _room_urdf(rec: SceneRecord, meshes: MeshFiles) -> str:
    links, joints = [], []
    root = rec.shell[0].name
    for s in rec.shell:
        vm, cm = _part_meshes(meshes, f"room__{s.name}", s.mesh, s.material, s.pieces)
        links.append(_link(s.name, None, vm, cm, 0.0, 1.0, np.zeros(3)))
        if s.name != root:
            joints.append(f'<joint name="{root}__{s.name}" type="fixed"><parent link="{root}"/>'
                          f'<child link="{s.name}"/></joint>')
    return ('<?xml version="1.0"?>\n<robot name="room">' + "".join(links) + "".join(joints)
            + "</robot>\n")


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
