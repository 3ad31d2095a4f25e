"""The asset model: a part-labelled object in its canonical frame.

Canonical frame (DESIGN §3): +Z up, the asset's front faces +Y, its right-hand side is +X, the
origin is the centre of the bottom face of its bounding box. Every part has a unique ``name``
(``leg_2``), a ``label`` from its category's part vocabulary (``leg``), a triangle mesh, a
material, convex collision pieces that cover it, and its six directional surfaces.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from ..geometry.frames import rotation_about
from ..geometry.meshes import MeshArrays, concatenate_arrays
from ..geometry.surfaces import FaceData, Surface, face_data, resolve_surfaces_steady

if TYPE_CHECKING:
    import trimesh

    from ..geometry.shapes import Shape

__all__ = ["Material", "Part", "InternalSurface", "Joint", "JOINT_TYPES", "Asset", "make_part",
           "BASE_LINK", "link_groups",
           "finalize_asset", "joint_order", "hull_points"]


@dataclass(frozen=True)
class Material:
    """A simple PBR material.

    Attributes
    ----------
    color : (4,) float in [0, 1]
        Base colour RGBA.
    roughness, metallic : float in [0, 1]
    name : str
        Material family (``wood``, ``metal``, ``fabric``, ``ceramic``, ``glass``, ``plastic``,
        ``paper``, ``stone``, ``plant``, ``food``, ``leather``); physics reads friction and
        restitution from it.
    texture : str or None
        Reserved for an image texture path.
    """

    color: tuple[float, float, float, float] = (0.7, 0.7, 0.7, 1.0)
    roughness: float = 0.6
    metallic: float = 0.0
    name: str = "plastic"
    texture: str | None = None

    def to_dict(self) -> dict[str, Any]:
        return {
            "color": [round(float(c), 4) for c in self.color],
            "roughness": self.roughness,
            "metallic": self.metallic,
            "name": self.name,
            "texture": self.texture,
        }

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Material:
        return cls(tuple(d["color"]), d["roughness"], d["metallic"], d["name"], d.get("texture"))


class Part:
    """One part of an asset.

    Attributes
    ----------
    name : str
        Unique within the asset (``leg_0``, ``shelf_2``).
    label : str
        From the category's part vocabulary (``leg``, ``shelf``).
    mesh : trimesh.Trimesh
        Visual mesh in the asset frame, metres.
    material : Material
    pieces : list of trimesh.Trimesh
        Convex collision pieces covering the mesh; every piece belongs to this part only.
    surfaces : dict of str to Surface
        The six directional surfaces (filled in by :func:`finalize_asset`).
    watertight : bool
        Whether the part is meant to be a closed solid (cloth, cards and open sheets are not).

    Notes
    -----
    ``mesh`` and ``pieces`` may be given as :class:`~parse3d.geometry.meshes.MeshArrays` (what
    loading a cached asset does): they become ``trimesh.Trimesh`` objects when first asked for.
    :attr:`vertices`, :attr:`faces`, :attr:`bounds` and :attr:`piece_arrays` read the arrays
    without making any, so a solve never imports trimesh.
    """

    def __init__(self, name: str, label: str, mesh, material: Material | None = None,
                 pieces: list | None = None, surfaces: dict[str, Surface] | None = None,
                 watertight: bool = True):
        self.name = name
        self.label = label
        self._mesh = mesh
        self.material = Material() if material is None else material
        self._pieces = [] if pieces is None else pieces
        self.surfaces = {} if surfaces is None else surfaces
        self.watertight = watertight

    def __repr__(self) -> str:
        return (f"Part(name={self.name!r}, label={self.label!r}, vertices={len(self.vertices)}, "
                f"pieces={len(self._pieces)}, material={self.material.name!r})")

    @property
    def mesh(self) -> trimesh.Trimesh:
        m = self._mesh
        if isinstance(m, MeshArrays):
            m = self._mesh = m.to_trimesh()
        return m

    @property
    def pieces(self) -> list[trimesh.Trimesh]:
        if any(isinstance(pc, MeshArrays) for pc in self._pieces):
            self._pieces = [pc.to_trimesh() if isinstance(pc, MeshArrays) else pc
                            for pc in self._pieces]
        return self._pieces

    @property
    def vertices(self) -> np.ndarray:
        """(V, 3) float vertices of the visual mesh (asset frame, metres)."""
        return self._mesh.vertices

    @property
    def faces(self) -> np.ndarray:
        """(F, 3) int faces of the visual mesh."""
        return self._mesh.faces

    @property
    def mesh_arrays(self) -> MeshArrays:
        """The visual mesh's vertices and faces, without making a ``trimesh.Trimesh``."""
        m = self._mesh
        return m if isinstance(m, MeshArrays) else MeshArrays(m.vertices, m.faces)

    @property
    def piece_arrays(self) -> list:
        """The convex pieces as they are held: each has ``vertices`` and ``faces``."""
        return self._pieces

    @property
    def bounds(self) -> np.ndarray:
        m = self._mesh
        return np.asarray(m.bounds)


@dataclass
class InternalSurface:
    """An upward-facing support surface inside an object's volume, for ``IN``.

    Attributes
    ----------
    part : str
        Name of the part the surface belongs to.
    surface : Surface
        The patch (normal +Z) in the asset frame.
    clearance : float
        Free height above the surface before the asset is hit again, metres (``inf`` when the
        container is open at the top, like a bowl).
    depth : float
        Height of the surrounding walls above the surface, metres (how deep the container is).
    """

    part: str
    surface: Surface
    clearance: float
    depth: float


#: The kinds of articulation an asset can record.
JOINT_TYPES = ("revolute", "prismatic")


@dataclass(frozen=True)
class Joint:
    """An articulation between two parts of an asset (a door hinge, a drawer slide, a lid).

    Attributes
    ----------
    name : str
        Unique within the asset (``door_0_hinge``).
    type : str
        ``revolute`` (angle, radians) or ``prismatic`` (travel, metres).
    parent_part, child_part : str
        Part names; the child moves relative to the parent.
    axis : (3,) float
        Unit axis in the asset frame.
    origin : (3,) float
        A point on the axis in the asset frame, metres (the hinge line for revolute joints).
    limits : (2,) float
        Lower and upper joint value; 0 is the pose the part meshes are modelled in (closed).
    """

    name: str
    type: str
    parent_part: str
    child_part: str
    axis: tuple[float, float, float]
    origin: tuple[float, float, float]
    limits: tuple[float, float]

    def to_dict(self) -> dict[str, Any]:
        return {"name": self.name, "type": self.type, "parent_part": self.parent_part,
                "child_part": self.child_part, "axis": [float(x) for x in self.axis],
                "origin": [float(x) for x in self.origin],
                "limits": [float(x) for x in self.limits]}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Joint:
        return cls(d["name"], d["type"], d["parent_part"], d["child_part"],
                   tuple(float(x) for x in d["axis"]), tuple(float(x) for x in d["origin"]),
                   tuple(float(x) for x in d["limits"]))

    def transform(self, value: float) -> np.ndarray:
        """(4, 4) motion of the child part, in the asset frame, at joint ``value``."""
        T = np.eye(4)
        axis = np.asarray(self.axis, float)
        if self.type == "prismatic":
            T[:3, 3] = axis * value
            return T
        origin = np.asarray(self.origin, float)
        R = rotation_about(axis, value)
        T[:3, :3] = R
        T[:3, 3] = origin - R @ origin
        return T

    @property
    def is_mount(self) -> bool:
        """A joint with no travel (limits ``(0, 0)``) rigidly mounts a part on a moving one (the
        handle on a door), so the part follows its parent when the parent's joint moves."""
        return self.limits[0] == 0.0 and self.limits[1] == 0.0

    def at_ratio(self, ratio: float) -> float:
        """The joint value ``ratio`` of the way from closed (0) to fully open (the limit away
        from 0), clipped to ``[0, 1]``."""
        r = float(np.clip(ratio, 0.0, 1.0))
        far = self.limits[1] if abs(self.limits[1]) >= abs(self.limits[0]) else self.limits[0]
        return r * float(far)

    def moved(self, offset) -> Joint:
        """The same joint with its origin translated by ``offset`` (3,), metres."""
        o = np.asarray(self.origin, float) + np.asarray(offset, float)
        return Joint(self.name, self.type, self.parent_part, self.child_part, self.axis,
                     tuple(float(x) for x in o), self.limits)


def joint_order(joints: list[Joint]) -> list[Joint]:
    """Joints ordered parents first, so that composing their motions in order poses a tree.

    Joints form a tree over parts: each part is the child of at most one joint. A joint whose
    parent part is itself moved by another joint comes after that joint.
    """
    by_child = {j.child_part: j for j in joints}
    done: set[str] = set()
    out: list[Joint] = []

    def visit(j: Joint, stack: tuple[str, ...] = ()) -> None:
        if j.name in done or j.name in stack:
            return
        up = by_child.get(j.parent_part)
        if up is not None:
            visit(up, stack + (j.name,))
        done.add(j.name)
        out.append(j)

    for j in joints:
        visit(j)
    return out


#: :meth:`Asset.parts_by_label` results: ``{(id(asset), label): (asset, parts, n, found)}``.
_BY_LABEL: dict[tuple, tuple] = {}


@dataclass
class Asset:
    """A part-labelled 3D asset in its canonical frame.

    Attributes
    ----------
    category : str
    asset_id : str
        Unique and stable: ``<category>-<variant>-<seed>`` for generated assets.
    parts : list of Part
    size_range : (2,) float
        The category's real-world range of the largest bbox extent, metres.
    density : float
        kg / m^3 for physics.
    internal : list of InternalSurface
    meta : dict
        Provenance: generator, variant, seed, source file; ``label_groups`` (see
        :attr:`label_groups`) where the category has group labels.
    joints : list of Joint
        Articulations between parts (doors, drawers, lids); empty for rigid assets.
    hull : (H, 3) float, optional
        Vertices of the convex hull of the pieces' vertices (:func:`hull_points`), as the asset
        cache stores it; computed when first asked for where it was not given.
    """

    category: str
    asset_id: str
    parts: list[Part]
    size_range: tuple[float, float] = (0.1, 1.0)
    density: float = 500.0
    internal: list[InternalSurface] = field(default_factory=list)
    meta: dict[str, Any] = field(default_factory=dict)
    joints: list[Joint] = field(default_factory=list)
    hull: np.ndarray | None = field(default=None, repr=False, compare=False)

    def hull_vertices(self) -> np.ndarray:
        """(H, 3) vertices of the convex hull of every convex piece's vertices (of the part
        meshes when no part has pieces), asset frame; every point for a flat asset."""
        if self.hull is None:
            pts = [pc.vertices for p in self.parts for pc in p.piece_arrays] or \
                  [p.vertices for p in self.parts]
            self.hull = hull_points(np.vstack(pts))
        return self.hull

    @property
    def bounds(self) -> np.ndarray:
        """(2, 3) axis-aligned bounds over all parts."""
        b = np.array([p.bounds for p in self.parts])
        return np.array([b[:, 0].min(axis=0), b[:, 1].max(axis=0)])

    @property
    def extents(self) -> np.ndarray:
        b = self.bounds
        return b[1] - b[0]

    @property
    def size(self) -> float:
        """The largest bbox extent, metres (what ``size_range`` bounds)."""
        return float(self.extents.max())

    @property
    def labels(self) -> list[str]:
        return sorted({p.label for p in self.parts})

    @property
    def label_groups(self) -> dict[str, list[str]]:
        """Group labels: a label naming the parts of several labels (a plate's ``body`` covers
        its ``well`` and ``rim``), ``{group: [labels]}``; kept in ``meta`` so that cached
        assets keep them."""
        return self.meta.get("label_groups") or {}

    def part(self, name: str) -> Part:
        for p in self.parts:
            if p.name == name:
                return p
        raise KeyError(f"{self.asset_id} has no part {name!r}")

    def parts_by_label(self, label: str) -> list[Part]:
        """Parts with ``label`` in the order ``#k`` indexes (0-based); for a group label (see
        :attr:`label_groups`) the parts of every label it covers.

        Lexicographic: by the bottom of the part's bounding box (bottom-to-top), then by its
        centre's x (left-to-right, the asset's own +X is its right), then by its centre's y
        (back-to-front). Values within 1 cm count as equal, so parts of one row or level share
        a rank however they are modelled. A 2 x 2 cooktop: back-left, front-left, back-right,
        front-right.
        """
        # kept per asset, parts list and label (the checks and the solver ask again and again)
        key = (id(self), label)
        got = _BY_LABEL.get(key)
        if got is not None and got[0] is self and got[1] is self.parts \
                and got[2] == len(self.parts):
            return list(got[3])
        members = self.label_groups.get(label, ())
        ps = [p for p in self.parts if p.label == label or p.label in members]
        if len(ps) >= 2:
            b = np.array([p.bounds for p in ps])
            keys = np.c_[b[:, 0, 2], b.mean(axis=1)[:, :2]]
            ranks = np.stack([_tolerant_ranks(keys[:, j], 0.01) for j in range(3)], axis=1)
            order = sorted(range(len(ps)), key=lambda i: (*ranks[i], i))
            ps = [ps[i] for i in order]
        if len(_BY_LABEL) > 8192:
            _BY_LABEL.clear()
        _BY_LABEL[key] = (self, self.parts, len(self.parts), tuple(ps))
        return ps

    def mesh(self) -> trimesh.Trimesh:
        """All parts as one mesh (a fresh copy)."""
        import trimesh

        return trimesh.util.concatenate([p.mesh for p in self.parts])

    def mesh_arrays(self) -> MeshArrays:
        """All parts as one mesh of arrays (a fresh copy): :meth:`mesh`'s vertices and faces,
        without making any ``trimesh.Trimesh``."""
        return concatenate_arrays([p._mesh for p in self.parts])

    @property
    def volume(self) -> float:
        """Collision volume (sum of convex pieces), m^3."""
        return float(sum(pc.volume for p in self.parts for pc in p.pieces))

    @property
    def mass(self) -> float:
        return self.volume * self.density

    def summary(self) -> dict[str, Any]:
        return {
            "category": self.category,
            "asset_id": self.asset_id,
            "extents": [round(float(x), 4) for x in self.extents],
            "parts": [{"name": p.name, "label": p.label,
                       "surfaces": {k: s.to_dict() for k, s in p.surfaces.items()},
                       "pieces": len(p.pieces)} for p in self.parts],
            "internal": [{"part": s.part, "surface": s.surface.to_dict(),
                          "clearance": None if np.isinf(s.clearance) else round(s.clearance, 4),
                          "depth": round(s.depth, 4)} for s in self.internal],
            "size_range": list(self.size_range),
            "density": self.density,
            "meta": self.meta,
            "joints": [j.to_dict() for j in self.joints],
        }

    def part_transforms(self, values: dict[str, float] | None = None, *,
                        ratio: float | None = None) -> dict[str, np.ndarray]:
        """(4, 4) motion of every part moved by a joint, in the asset frame.

        Parameters
        ----------
        values : dict of joint name to value, optional
            Radians (revolute) or metres (prismatic); missing joints stay at 0 (closed).
            Values are clipped into the joint's limits.
        ratio : float in [0, 1], optional
            Instead of ``values``: every joint opened this far (``Joint.at_ratio``).

        Returns
        -------
        dict of part name to (4, 4) float
            Only parts below a joint appear; a part mounted on a moved part (a handle on a
            door) follows it. Apply ``T`` to the part's mesh in the asset frame.
        """
        values = values or {}
        out: dict[str, np.ndarray] = {}
        for j in joint_order(self.joints):
            if ratio is not None:
                v = j.at_ratio(ratio)
            else:
                v = float(np.clip(values.get(j.name, 0.0), j.limits[0], j.limits[1]))
            T = j.transform(v)
            up = out.get(j.parent_part)
            out[j.child_part] = T if up is None else up @ T
        return out

    def posed(self, values: dict[str, float] | None = None, *, ratio: float | None = None) -> Asset:
        """A copy of the asset with its joints set (what ``render --open RATIO`` draws).

        Parameters are those of :meth:`part_transforms`. Parts below a joint get moved copies
        of their mesh, pieces, surfaces and internal surfaces (labels stay those of the closed
        pose); the other parts are shared with this asset. With no movement this asset itself
        is returned.
        """
        moves = {k: T for k, T in self.part_transforms(values, ratio=ratio).items()
                 if not np.allclose(T, np.eye(4))}
        if not moves:
            return self
        parts = []
        for p in self.parts:
            T = moves.get(p.name)
            if T is None:
                parts.append(p)
                continue
            mesh = p.mesh.copy()
            mesh.apply_transform(T)
            pieces = [pc.copy() for pc in p.pieces]
            for pc in pieces:
                pc.apply_transform(T)
            parts.append(Part(p.name, p.label, mesh, p.material, pieces,
                              {k: sf.transformed(T) for k, sf in p.surfaces.items()}, p.watertight))
        internal = [InternalSurface(s.part, s.surface.transformed(moves[s.part]), s.clearance, s.depth)
                    if s.part in moves else s for s in self.internal]
        return Asset(self.category, self.asset_id, parts, self.size_range, self.density, internal,
                     dict(self.meta), list(self.joints))

    @property
    def articulated(self) -> bool:
        """Whether any joint of the asset can move (mounts alone do not count)."""
        return any(not j.is_mount for j in self.joints)


def hull_points(pts: np.ndarray) -> np.ndarray:
    """(H, 3) the vertices of the convex hull of (N, 3) points, in qhull's order; all the
    points where they span no volume (a rug's flat outline)."""
    from scipy.spatial import ConvexHull, QhullError

    try:
        return pts[ConvexHull(pts).vertices]
    except (QhullError, ValueError):
        return pts


def make_part(name: str, label: str, shapes: Shape | list[Shape], material: Material,
              *, watertight: bool = True) -> Part:
    """Build a Part from one or more shapes (meshes concatenated, pieces kept)."""
    from ..geometry.shapes import Shape

    if isinstance(shapes, Shape):
        shapes = [shapes]
    mesh = _stacked([s.mesh for s in shapes])
    pieces = [p for s in shapes for p in s.pieces]
    return Part(name, label, mesh, material, pieces, watertight=watertight)


def _stacked(meshes: list[trimesh.Trimesh]) -> trimesh.Trimesh:
    """A new mesh of ``meshes`` side by side (vertices stacked, faces re-indexed), sharing no
    array with them.

    What ``trimesh.util.concatenate`` (or ``copy`` for one mesh) gives for a part's geometry,
    without merging visuals and metadata or carrying caches, which a generated part has none of
    and which cost more than the stacking.
    """
    import trimesh

    m = concatenate_arrays(meshes)
    return trimesh.Trimesh(m.vertices, m.faces, process=False)


def _translate(mesh: trimesh.Trimesh, shift: np.ndarray) -> None:
    """Move ``mesh`` by ``shift`` (3,) in place: the same vertices as ``apply_translation``,
    without its transform bookkeeping (the mesh's caches are dropped by the vertex change)."""
    if np.abs(shift).max() < 1e-8:  # where trimesh's transform leaves the points alone
        return
    mesh.vertices = np.asarray(mesh.vertices, float).view(np.ndarray) + shift


def finalize_asset(asset: Asset, *, recenter: bool = True, internal: bool = True) -> Asset:
    """Put an asset into canonical form and compute its derived geometry, in place.

    Moves it so the bottom face of its bbox is centred on the origin, resolves the six
    directional surfaces of every part, and finds internal support surfaces.
    """
    if recenter:
        b = asset.bounds
        shift = -np.array([(b[0, 0] + b[1, 0]) / 2, (b[0, 1] + b[1, 1]) / 2, b[0, 2]])
        if np.abs(shift).max() > 1e-9:
            moved: set[int] = set()  # a piece may be its part's mesh or shared: move it once
            for p in asset.parts:
                for m in (p.mesh, *p.pieces):
                    if id(m) not in moved:
                        moved.add(id(m))
                        _translate(m, shift)
            asset.joints = [j.moved(shift) for j in asset.joints]
    fds = {}
    # Parts repeated at another place (legs, slats, knobs, drawer fronts: about half of all
    # parts) resolve once; a repeat gets the first one's surfaces moved along, unless some
    # decision in resolving them came within rounding of going the other way.
    resolved: dict[tuple, tuple] = {}
    for p in asset.parts:
        v = np.asarray(p.mesh.vertices, float).view(np.ndarray)
        f = np.asarray(p.mesh.faces).view(np.ndarray)
        key = (f.tobytes(), np.round(v - v[0], 9).tobytes()) if len(v) else None
        hit = resolved.get(key) if key is not None else None
        if hit is None:
            fds[p.name] = fd = face_data(p.mesh)
            p.surfaces, steady = resolve_surfaces_steady(fd)
            if key is not None and steady:
                resolved[key] = (v[0].copy(), p.surfaces, fd)
            continue
        v0, surfaces, fd0 = hit
        t = v[0] - v0
        tri = v[f]
        fds[p.name] = FaceData(fd0.bounds + t, tri, fd0.normals, fd0.areas, tri.mean(axis=1),
                               fd0.adjacency)
        p.surfaces = {k: Surface(s.label, s.origin + t, s.normal.copy(), s.u.copy(), s.v.copy(),
                                 s.polygon, s.source) for k, s in surfaces.items()}
    if internal:
        from .internal import find_internal_surfaces

        asset.internal = find_internal_surfaces(asset, faces=fds)
        # a drawer's floor is also listed under its front (label ``drawer``, mounted on the
        # box): the part a PAG names for IN a drawer
        fronts = {}
        for j in asset.joints:
            if j.is_mount:
                fronts.setdefault(j.parent_part, []).append(j.child_part)
        labels = {p.name: p.label for p in asset.parts}
        extra = [InternalSurface(c, s.surface, s.clearance, s.depth) for s in asset.internal
                 if labels.get(s.part) == "drawer_box" for c in fronts.get(s.part, ())
                 if labels.get(c) == "drawer"]
        if extra:
            asset.internal = sorted(asset.internal + extra,
                                    key=lambda s: (round(float(s.surface.origin[2]), 4), s.part))
    return asset


def _tolerant_ranks(values: np.ndarray, tol: float) -> np.ndarray:
    """Rank of each value, where sorted neighbours closer than ``tol`` share a rank."""
    order = np.argsort(values, kind="stable")
    ranks = np.empty(len(values), int)
    r = 0
    for k, i in enumerate(order):
        if k and values[i] - values[order[k - 1]] > tol:
            r += 1
        ranks[i] = r
    return ranks


#: The link holding an asset's parts that no joint moves.
BASE_LINK = "base"


def link_groups(asset: Asset) -> tuple[dict[str, str], list[str], list[tuple[Joint, str]]]:
    """Part -> link, links (parents first, ``base`` first), moving joints with the link that
    holds their parent part (the child's link is named after the child part).

    A joint whose parent part is missing or in a loop leaves its child on ``base``.
    """
    moved = {j.child_part for j in asset.joints}
    part_link = {p.name: BASE_LINK for p in asset.parts if p.name not in moved}
    order = [BASE_LINK]
    joints: list[tuple[Joint, str]] = []
    pending = list(asset.joints)
    progressed = True
    while pending and progressed:
        progressed = False
        for j in list(pending):
            parent = part_link.get(j.parent_part)
            if parent is None:
                continue
            if j.is_mount:
                part_link[j.child_part] = parent
            else:
                part_link[j.child_part] = j.child_part
                order.append(j.child_part)
                joints.append((j, parent))
            pending.remove(j)
            progressed = True
    for p in asset.parts:
        part_link.setdefault(p.name, BASE_LINK)
    return part_link, order, joints
