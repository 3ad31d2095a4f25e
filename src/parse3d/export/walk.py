"""The one walk over a scene that every exporter reads.

:func:`walk_scene` turns a :class:`~parse3d.scene.model.Scene` into plain export records:
objects → links → parts, with meshes and convex collision pieces in the **asset frame** (so two
objects sharing an asset share geometry), the object's world pose and uniform scale, material,
mass, joints with their values, fixed or loose, a relation summary, and the room shell.

Links: an asset without joints is one rigid link (``base``). With joints, every joint's child
part is a link of its own, hanging from the link that holds the joint's parent part; all other
parts form the ``base`` link. A part's ``motion`` is where its link sits at the exported joint
values, as a (4, 4) transform in the asset frame (identity for the base link).

World frame: +Z up, metres. An object's ``transform`` maps asset-frame points ``x`` to
``R @ (scale * x) + t``.
"""

from __future__ import annotations

import hashlib
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from .._lru import LRU
from ..assets.model import BASE_LINK, Asset, Joint, Material, Part, link_groups
from ..geometry.frames import make_transform
from ..geometry.meshes import MeshArrays
from ..pag.refs import RefSyntaxError, parse_ref
from ..scene.model import PlacedObject, Scene
from .mass import is_shell, part_mass, pieces_area

if TYPE_CHECKING:
    import trimesh

__all__ = ["ExportOptions", "PartRecord", "LinkRecord", "JointRecord", "ObjectRecord",
           "ShellRecord", "SceneRecord", "walk_scene", "SHELL_MATERIALS", "BASE_LINK",
           "convex_pieces", "clear_cache", "NODE_SEPARATOR", "node_name", "split_node_name"]

#: What stands for the colon of ``object:part`` in the node names of the viewer formats (glTF,
#: USD). three.js drops ``[ ] . : /`` from node names and turns white space into ``_``; USD
#: prim names allow ``[A-Za-z0-9_]`` only; Blender keeps both as they are. Part names never
#: hold two underscores in a row, so a name splits back at its last ``__``.
NODE_SEPARATOR = "__"


def node_name(key: str) -> str:
    """The node name of ``object:part`` (or of an object id) in glTF and USD.

    ``desk:tabletop`` -> ``desk__tabletop``, ``room:wall_0`` -> ``room__wall_0``; characters
    outside ``[A-Za-z0-9_]`` (a ``-`` in an object id) become ``_``, and a leading digit gets
    a ``_`` before it. The exact name stays in each node's ``extras`` / attributes.

    >>> node_name("reading-lamp:shade_0")
    'reading_lamp__shade_0'
    """
    s = re.sub(r"[^A-Za-z0-9_]", "_", key.replace(":", NODE_SEPARATOR, 1)) or "_"
    return "_" + s if s[0].isdigit() else s


def split_node_name(name: str) -> tuple[str, str | None]:
    """``(object, part)`` of a node name (``part`` None for an object's own node); the
    object is the node name of its id (the exact id is in the node's ``extras``).

    >>> split_node_name("desk__leg_0")
    ('desk', 'leg_0')
    """
    obj, sep, part = name.rpartition(NODE_SEPARATOR)
    return (obj, part) if sep else (name, None)


def _unique(name: str, taken: set[str]) -> str:
    """``name``, or ``name_<k>`` with the smallest k >= 2 not taken (two ids that differ only
    in a ``-`` against a ``_``); remembers the result."""
    out, k = name, 2
    while out in taken:
        out, k = f"{name}_{k}", k + 1
    taken.add(out)
    return out


#: Display materials of the room shell, by element kind.
SHELL_MATERIALS = {"floor": Material((0.78, 0.74, 0.68, 1.0), 0.8, 0.0, "wood"),
                   "wall": Material((0.93, 0.92, 0.89, 1.0), 0.9, 0.0, "stone"),
                   "ceiling": Material((0.97, 0.97, 0.96, 1.0), 0.9, 0.0, "stone")}


@dataclass(frozen=True)
class ExportOptions:
    """What an export shows.

    Attributes
    ----------
    settled : bool or None
        Pose to export: the settled pose (True), the solved one (False), or None for the
        scene's own state (settled when the scene was settled, else solved).
    ceiling : bool
        Include the ceiling (it stays a separate node or prim that viewers can hide).
    open_ratio : float or None
        Set every joint to this fraction (0 closed .. 1 fully open) of its travel, instead of
        the joint values stored with the scene.
    friction : mapping of str to float, or None
        Static friction coefficient per material family (``Material.name``), plus ``room``
        for the shell, written into the simulator formats; families not listed use
        ``plastic``. None leaves each simulator's default. The command line passes the table
        settling uses (``parse3d.physics.bodies.MATERIALS``).
    """

    settled: bool | None = None
    ceiling: bool = True
    open_ratio: float | None = None
    friction: Mapping[str, float] | None = None


_HULLS_SIZE = 8192
_HULLS: LRU[str, tuple[list[tuple[np.ndarray, np.ndarray]], float]] = LRU(_HULLS_SIZE)


def _piece_key(part: Part) -> str:
    h = hashlib.blake2b(digest_size=16)
    for pc in part.piece_arrays:
        h.update(np.ascontiguousarray(pc.vertices, np.float64).tobytes())
        h.update(np.ascontiguousarray(pc.faces, np.int64).tobytes())
    return h.hexdigest()


def clear_cache() -> None:
    """Forget the convex pieces cached in this process."""
    _HULLS.clear()


class _HullCache:
    """Convex pieces per asset part: computed once per part object in a walk, and once per
    piece content in the process (scenes of a dataset share assets). The parts a walk
    registers are computed together on the first request, in one vectorised pass."""

    def __init__(self) -> None:
        self._by_part: dict[int, tuple[list[tuple[np.ndarray, np.ndarray]], float]] = {}
        self._keep: list[Part] = []  # keeps ids valid while the cache lives
        self._pending: list[Part] = []

    def register(self, part: Part) -> None:
        """Note a part whose pieces may be asked for (nothing is computed yet)."""
        self._pending.append(part)

    def get(self, part: Part) -> tuple[list[tuple[np.ndarray, np.ndarray]], float]:
        hit = self._by_part.get(id(part))
        if hit is None:
            self._fill([part, *self._pending])
            self._pending = []
            hit = self._by_part[id(part)]
        return hit

    def _fill(self, parts: list[Part]) -> None:
        todo: list[tuple[Part, str]] = []
        for part in parts:
            if id(part) in self._by_part:
                continue
            key = _piece_key(part)
            hit = _HULLS.get(key)
            if hit is None:
                todo.append((part, key))
                hit = _HULLS[key] = ([], 0.0)  # placeholder, filled below
            self._by_part[id(part)] = hit
            self._keep.append(part)
        meshes = [pc for part, _ in todo for pc in part.piece_arrays
                  if len(pc.faces) and len(pc.vertices) >= 4]
        closed = dict(zip(map(id, meshes), _closed_volumes(meshes), strict=True))
        for part, key in todo:
            hit = _HULLS[key] = convex_pieces(part.piece_arrays, closed=closed)
            self._by_part[id(part)] = hit


@dataclass
class PartRecord:
    """One part of an exported object.

    Attributes
    ----------
    name, label : str
        Unique part name (``leg_0``) and vocabulary label (``leg``).
    key : str
        ``<object_id>:<part_name>``, the exact name (MJCF, URDF and OBJ name the part so;
        glTF and USD keep it in ``extras`` and attributes).
    node : str
        The part's node name in glTF and USD, unique in the scene (:func:`node_name`).
    mesh : MeshArrays
        Visual mesh (``vertices``, ``faces``), asset frame, unscaled (shared with the asset: do
        not modify).
    material : Material
    link : str
        The link the part belongs to.
    relations : list of dict
        PAG relations naming this part's label on this object.
    contacts : list of str
        Parts (``object:part``) this part touches in the contact graph.
    source : Part
        The asset's part.
    """

    name: str
    label: str
    key: str
    mesh: MeshArrays
    material: Material
    link: str
    relations: list[dict[str, Any]]
    contacts: list[str]
    source: Part
    node: str = ""
    _hulls: _HullCache = field(repr=False, default=None)
    _area: float | None = field(repr=False, default=None)

    @property
    def pieces(self) -> list[tuple[np.ndarray, np.ndarray]]:
        """Convex collision pieces as hull ``(vertices (V, 3), triangles (F, 3))``, asset
        frame, unscaled (flat pieces dropped); computed on first use and shared by the parts
        of objects that share an asset."""
        return self._hulls.get(self.source)[0]

    @property
    def volume(self) -> float:
        """Collision volume of the pieces, m^3, unscaled."""
        return self._hulls.get(self.source)[1]

    @property
    def area(self) -> float:
        """Surface area of the pieces, m^2, unscaled."""
        if self._area is None:
            self._area = pieces_area(self.pieces)
        return self._area


@dataclass
class LinkRecord:
    """A rigid group of parts of one object.

    Attributes
    ----------
    name : str
        ``base`` or the joint child part's name.
    parts : list of PartRecord
    motion : (4, 4) float
        Pose of the link relative to the asset frame at the exported joint values (identity
        for ``base``), unscaled.
    density : float
        kg / m^3 of the category (the solid model).
    scale : float
        The object's uniform scale.
    shell : bool
        Whether the category is built as a shell (:data:`parse3d.export.mass.SHELLS`): parts
        weigh their shell, not their solid volume.
    """

    name: str
    parts: list[PartRecord]
    motion: np.ndarray
    density: float
    scale: float
    shell: bool = False

    def part_mass(self, part: PartRecord) -> float:
        """kg of one of the link's parts at the object's scale
        (:func:`parse3d.export.mass.part_mass`)."""
        return part_mass(part.volume, part.area if self.shell else 0.0, scale=self.scale,
                         density=self.density, material=part.material.name, shell=self.shell)

    def part_density(self, part: PartRecord) -> float:
        """kg / m^3 that gives the part its :meth:`part_mass` over its solid collision volume
        (what simulators that take a density per shape need); the category density for a
        solid category."""
        v = part.volume * self.scale**3
        if not self.shell or v <= 0:
            return self.density
        return self.part_mass(part) / v

    @property
    def mass(self) -> float:
        """kg: the sum of the parts' masses (solid volume times the category density, or the
        shell's volume times the material density)."""
        return float(sum(self.part_mass(p) for p in self.parts))


@dataclass
class JointRecord:
    """An articulation of an exported object.

    Attributes
    ----------
    joint : Joint
        As stored with the asset (axis and origin in the asset frame, unscaled).
    parent_link, child_link : str
    value : float
        Exported joint value (radians or metres, unscaled).
    """

    joint: Joint
    parent_link: str
    child_link: str
    value: float

    @property
    def name(self) -> str:
        return self.joint.name


@dataclass
class ObjectRecord:
    """One placed object, ready for a writer.

    Attributes
    ----------
    id, category, asset_id : str
    node : str
        The object's node name in glTF and USD, unique in the scene (:func:`node_name`).
    asset : Asset
    scale : float
    rotation : (3, 3) float
        World rotation of the exported pose.
    position : (3,) float
        World position of the asset origin, metres.
    fixed : bool
        Held in place (SECURED_TO and HANGING_BELOW objects): welded to the world.
    support : str or None
        The part-level support used (``desk:tabletop_0@top``).
    density : float
        kg / m^3.
    parts : list of PartRecord
    links : list of LinkRecord
        ``base`` first, then parents before children.
    joints : list of JointRecord
    relations : list of dict
        Every PAG relation with this object as child or parent: relation, child, parent and
        whether it holds (after settling when settled).
    """

    id: str
    category: str
    asset_id: str
    node: str
    asset: Asset
    scale: float
    rotation: np.ndarray
    position: np.ndarray
    fixed: bool
    support: str | None
    density: float
    parts: list[PartRecord]
    links: list[LinkRecord]
    joints: list[JointRecord]
    relations: list[dict[str, Any]]

    @property
    def transform(self) -> np.ndarray:
        """(4, 4) asset-to-world transform, scale included."""
        return make_transform(self.rotation, self.position, self.scale)

    @property
    def mass(self) -> float:
        return float(sum(lk.mass for lk in self.links))

    def link(self, name: str) -> LinkRecord:
        for lk in self.links:
            if lk.name == name:
                return lk
        raise KeyError(name)

    def link_parts(self, name: str) -> list[PartRecord]:
        return self.link(name).parts


@dataclass
class ShellRecord:
    """A room shell element (world frame, static).

    Attributes
    ----------
    name : str
        ``floor``, ``wall_i`` or ``ceiling``.
    key : str
        ``room:<name>``.
    node : str
        ``room__<name>``, its node name in glTF and USD.
    mesh : MeshArrays
        World-frame slab (``vertices``, ``faces``).
    material : Material
    pieces : list of ((V, 3) float, (F, 3) int)
        Convex pieces as hulls, world frame (the floor and ceiling of a non-convex room are
        split into convex prisms); computed on first use (the glTF writer needs none).
    """

    name: str
    key: str
    node: str
    mesh: MeshArrays
    material: Material
    _scene: Scene = field(repr=False, default=None)
    _pieces: list[tuple[np.ndarray, np.ndarray]] | None = field(repr=False, default=None)

    @property
    def pieces(self) -> list[tuple[np.ndarray, np.ndarray]]:
        if self._pieces is None:
            self._pieces = _shell_pieces(self._scene, self.name, self.mesh)
        return self._pieces


@dataclass
class SceneRecord:
    """A walked scene: what every exporter writes.

    Attributes
    ----------
    name : str
        The PAG's name.
    settled : bool
        Whether the exported poses are settled ones.
    objects : list of ObjectRecord
        Placed objects in the scene's order.
    shell : list of ShellRecord
        Floor, walls, then the ceiling (when included).
    meta : dict
        Scene-level facts for the files' metadata (name, seed, room type, pose used).
    friction_table : mapping of str to float, or None
        As :attr:`ExportOptions.friction`.
    """

    name: str
    settled: bool
    objects: list[ObjectRecord]
    shell: list[ShellRecord]
    meta: dict[str, Any]
    friction_table: Mapping[str, float] | None = None

    def friction(self, family: str) -> float | None:
        """Static friction of a material family (``room`` for the shell), or None."""
        t = self.friction_table
        if t is None:
            return None
        return float(t.get(family, t.get("plastic", 0.5)))

    def assets(self) -> dict[str, Asset]:
        """Distinct assets by asset id, in first-use order."""
        out: dict[str, Asset] = {}
        for o in self.objects:
            out.setdefault(o.asset_id, o.asset)
        return out


def _closed_volumes(meshes: list[trimesh.Trimesh]) -> list[float | None]:
    """The enclosed volume of each triangle mesh, m^3, or None for one that is open (an edge
    not shared by exactly two of its triangles) or wound inward; one vectorised pass over
    all the meshes (per-mesh numpy calls cost more than the arithmetic on small pieces)."""
    if not meshes:
        return []
    verts = [np.asarray(m.vertices, float) for m in meshes]
    faces = [np.asarray(m.faces, np.int64) for m in meshes]
    nv = np.array([len(v) for v in verts])
    nf = np.array([len(f) for f in faces])
    V = np.concatenate(verts)
    F = np.concatenate(faces) + np.repeat(np.cumsum(nv) - nv, nf)[:, None]
    owner = np.repeat(np.arange(len(meshes)), nf)
    e = np.sort(F[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    _, inverse, counts = np.unique(e[:, 0] * (len(V) + 1) + e[:, 1], return_inverse=True,
                                   return_counts=True)
    open_mesh = np.zeros(len(meshes), bool)
    open_mesh[np.repeat(owner, 3)[counts[inverse.ravel()] != 2]] = True
    a, b, c = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    six = np.einsum("ij,ij->i", a, np.cross(b, c))
    vol = np.bincount(owner, weights=six, minlength=len(meshes)) / 6.0
    return [None if open_mesh[i] or vol[i] < 0 else float(vol[i]) for i in range(len(meshes))]


def convex_pieces(meshes, closed: Mapping[int, float | None] | None = None
                  ) -> tuple[list[tuple[np.ndarray, np.ndarray]], float]:
    """The convex hull of each collision piece and their total volume; flat pieces dropped.

    Parameters
    ----------
    meshes : iterable of meshes (anything with ``vertices`` and ``faces``) or (V, 3) arrays
    closed : mapping of int to float or None, optional
        Volumes already known (:func:`_closed_volumes`), by ``id`` of the mesh: a closed
        mesh (a piece is convex and closed by contract) needs no hull.

    Returns
    -------
    hulls : list of ((V_i, 3) float, (F_i, 3) int)
        Vertices and triangles of every piece with volume: a mesh's own triangles, or the
        outward-wound hull of bare points.
    volume : float
        m^3.
    """
    from scipy.spatial import ConvexHull, QhullError

    out, vol = [], 0.0
    for m in meshes:
        pts = np.asarray(getattr(m, "vertices", m), float)
        if len(pts) < 4:
            continue
        known = None if closed is None else closed.get(id(m))
        if known is not None:  # a closed, outward-wound piece: its own volume, no hull
            if known > 1e-12:
                out.append((pts, np.asarray(m.faces)))
                vol += known
            continue
        try:
            h = ConvexHull(pts)
        except QhullError:  # a flat piece has no volume to collide
            continue
        if h.volume <= 1e-12:
            continue
        if hasattr(m, "faces") and len(m.faces):
            # a piece is convex by contract: keep its own triangles (then a box part and its
            # one piece are the same mesh, and writers store it once)
            out.append((pts, np.asarray(m.faces)))
            vol += float(h.volume)
            continue
        used = np.unique(h.simplices)
        remap = np.full(len(pts), -1)
        remap[used] = np.arange(len(used))
        faces = remap[h.simplices]
        v = pts[used]
        tri = v[faces]
        # qhull does not wind its simplices consistently: turn each one outward
        normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        flip = np.einsum("ij,ij->i", normal, h.equations[:, :3]) < 0
        faces[flip] = faces[flip][:, ::-1]
        out.append((v, faces))
        vol += float(h.volume)
    return out, vol


def _ref_key(text: str) -> tuple[str, str | None]:
    try:
        r = parse_ref(text)
    except RefSyntaxError:
        return text, None
    return r.object, r.part


def _relation_rows(scene: Scene, settled: bool) -> list[tuple[dict[str, Any], tuple, tuple]]:
    """Each relation's summary row with its parsed child and parent ``(object, part)``."""
    rows = []
    for c in scene.relations:
        holds = c.holds_settled if settled and c.holds_settled is not None else c.holds
        rows.append(({"relation": c.relation, "child": c.child, "parent": c.parent,
                      "holds": holds}, _ref_key(c.child), _ref_key(c.parent)))
    return rows


def _joint_value(j: Joint, stored: dict[str, float], open_ratio: float | None) -> float:
    lo, hi = float(j.limits[0]), float(j.limits[1])
    if open_ratio is not None:
        # the fully open end is the limit farther from the modelled (closed) pose at 0
        far = hi if abs(hi) >= abs(lo) else lo
        return float(open_ratio) * far
    return float(np.clip(stored.get(j.name, 0.0), min(lo, hi), max(lo, hi)))


def _links(asset: Asset, values: dict[str, float]) -> tuple[dict[str, str], list[tuple[str, np.ndarray]],
                                                           list[tuple[Joint, str, str]]]:
    """Part -> link, links (parents first) with their motion, joints with their link pair.

    A mount (a joint with no travel: a handle on a door, a box behind a drawer front) is no
    joint in the exports: its part rides rigidly on the link of the part it is mounted on.
    """
    part_link, order, moving = link_groups(asset)
    motion: dict[str, np.ndarray] = {BASE_LINK: np.eye(4)}
    for j, parent in moving:  # parents first
        motion[j.child_part] = motion[parent] @ j.transform(values[j.name])
    joints = [(j, parent, j.child_part) for j, parent in moving]
    return part_link, [(n, motion[n]) for n in order], joints


def _object_record(o: PlacedObject, settled: bool, opts: ExportOptions,
                   relations: list[tuple[dict[str, Any], tuple, tuple]],
                   touching: dict[str, list[str]], hulls: _HullCache,
                   taken: set[str]) -> ObjectRecord:
    asset = o.asset
    node = _unique(node_name(o.id), taken)
    values = {j.name: _joint_value(j, o.joints, opts.open_ratio) for j in asset.joints}
    part_link, links, joints = _links(asset, values)
    mine = [r for r in relations if r[1][0] == o.id or r[2][0] == o.id]
    parts = []
    for p in asset.parts:
        prel = [r[0] for r in mine if (o.id, p.label) in (r[1], r[2])]
        key = f"{o.id}:{p.name}"
        parts.append(PartRecord(p.name, p.label, key, p.mesh_arrays, p.material, part_link[p.name],
                                prel, touching.get(key, []), p, _unique(node_name(key), taken),
                                hulls))
        hulls.register(p)
    density = float(asset.density)
    shell = is_shell(o.category)
    link_recs = [LinkRecord(n, [p for p in parts if p.link == n], T, density, float(o.scale), shell)
                 for n, T in links]
    use_settled = settled and o.settled_position is not None
    R = o.settled_rotation if use_settled else o.rotation
    t = o.settled_position if use_settled else o.position
    return ObjectRecord(o.id, o.category, asset.asset_id, node, asset, float(o.scale),
                        np.asarray(R, float), np.asarray(t, float), bool(o.fixed), o.support,
                        density, parts, link_recs,
                        [JointRecord(j, a, b, values[j.name]) for j, a, b in joints],
                        [r[0] for r in mine])


def _shell_pieces(scene: Scene, name: str,
                  mesh: MeshArrays) -> list[tuple[np.ndarray, np.ndarray]]:
    if name not in ("floor", "ceiling"):
        return convex_pieces([mesh])[0]
    from shapely.geometry import Polygon

    room = scene.room
    z0, z1 = float(mesh.bounds[0, 2]), float(mesh.bounds[1, 2])
    outline = Polygon(room.footprint).buffer(room.wall_thickness, join_style="mitre")
    if outline.convex_hull.area - outline.area <= 1e-9 * max(outline.area, 1.0):
        rings = [np.asarray(outline.exterior.coords)[:-1]]
    else:
        import trimesh

        v, f = trimesh.creation.triangulate_polygon(outline, engine="earcut")
        rings = [v[tri] for tri in f]
    prisms = [np.vstack([np.c_[r, np.full(len(r), z0)], np.c_[r, np.full(len(r), z1)]])
              for r in rings]
    return convex_pieces(prisms)[0]


def walk_scene(scene: Scene, options: ExportOptions = ExportOptions()) -> SceneRecord:
    """Walk ``scene`` into the records every exporter writes.

    Parameters
    ----------
    scene : Scene
    options : ExportOptions

    Returns
    -------
    SceneRecord
        Placed objects only (failed objects have no geometry); the room shell with the
        ceiling last, or without it when ``options.ceiling`` is False.
    """
    settled = scene.settled if options.settled is None else bool(options.settled)
    relations = _relation_rows(scene, settled)
    touching: dict[str, list[str]] = {}
    for c in scene.contacts or []:
        touching.setdefault(c.a, []).append(c.b)
        touching.setdefault(c.b, []).append(c.a)
    hulls = _HullCache()
    # shell names first: a user's object may not take ``room__floor`` from the floor
    taken = {node_name(f"room:{n}") for n in scene.room.elements}
    objects = [_object_record(o, settled, options, relations, touching, hulls, taken)
               for o in scene.placed if o.asset is not None]
    shell = []
    names = [n for n in scene.room.elements if n != "ceiling"]
    if options.ceiling and "ceiling" in scene.room.elements:
        names.append("ceiling")
    for n in names:
        el = scene.room.elements[n]
        kind = "wall" if n.startswith("wall_") else n
        shell.append(ShellRecord(n, f"room:{n}", node_name(f"room:{n}"), el.mesh_arrays,
                                 SHELL_MATERIALS[kind], scene))
    meta = {"name": scene.pag.name, "seed": int(scene.seed), "room": scene.pag.room.type,
            "pose": "settled" if settled else "solved", "generator": "parse3d"}
    return SceneRecord(scene.pag.name, settled, objects, shell, meta,
                       None if options.friction is None else dict(options.friction))
