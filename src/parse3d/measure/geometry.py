"""Per-asset geometry that relation checks and the solver need, cached per asset: hull points,
centre of mass, bounds, ray casters."""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ..assets.model import Asset, Part
from ..geometry.hulls import hull_indices_2d
from ..geometry.rays import RayCaster

__all__ = ["AssetGeometry", "asset_geometry", "outline_indices", "part_points", "ray_caster",
           "enclosure_directions", "drop_distance", "exact_drop", "is_round"]


@dataclass
class AssetGeometry:
    """Scale-free geometry of an asset in its own frame.

    Attributes
    ----------
    hull : (N, 3) float
        Vertices of the convex hull of all collision pieces.
    com : (3,) float
        Centre of mass (collision volume).
    center : (3,) float
        Bounding-box centre.
    bounds : (2, 3) float
        Bounding box of the visual mesh.
    """

    hull: np.ndarray
    com: np.ndarray
    center: np.ndarray
    bounds: np.ndarray

    @property
    def size(self) -> float:
        return float((self.bounds[1] - self.bounds[0]).max())


_GEOM: dict[str, AssetGeometry] = {}


def asset_geometry(asset: Asset) -> AssetGeometry:
    g = _GEOM.get(asset.asset_id)
    if g is None or len(_GEOM) > 4096:
        if len(_GEOM) > 4096:
            _GEOM.clear()
        hull = asset.hull_vertices()
        # centre of mass of the closed pieces by the divergence theorem, all in one pass:
        # each triangle with the origin spans a signed tetrahedron
        tris = [pc.vertices[pc.faces] for p in asset.parts for pc in p.piece_arrays]
        if tris:
            T = np.concatenate(tris)
            v = np.einsum("ij,ij->i", T[:, 0], np.cross(T[:, 1], T[:, 2])) / 6.0
            vol = float(v.sum())
            com = (v[:, None] * T.sum(axis=1) / 4.0).sum(axis=0) / vol if abs(vol) > 1e-12 \
                else asset.bounds.mean(axis=0)
        else:
            com = asset.bounds.mean(axis=0)
        b = asset.bounds
        g = AssetGeometry(np.asarray(hull), np.asarray(com), b.mean(axis=0), b)
        _GEOM[asset.asset_id] = g
    return g


_OUTLINE: dict[tuple, np.ndarray | None] = {}


def outline_indices(asset: Asset, direction: np.ndarray) -> np.ndarray | None:
    """Indices into ``asset_geometry(asset).hull`` of the points whose projections along
    ``direction`` (asset frame) are the vertices of the projected hull: the asset's outline
    seen along that direction, cached per (asset, direction rounded to 1e-9).

    Any pose of the asset projected onto a plane whose normal is ``direction`` in the asset's
    frame has its convex footprint at these points (a turn about the plane normal, a scale
    and a shift keep a point set's hull vertices), so a footprint costs a gather instead of a
    hull. None when the projection is degenerate (a flat outline seen edge on).
    """
    d = np.asarray(direction, float)
    key = (asset.asset_id, *d.round(9).tolist())
    if key in _OUTLINE:
        return _OUTLINE[key]
    if len(_OUTLINE) > 16384:
        _OUTLINE.clear()
    hull = asset_geometry(asset).hull
    d = d / np.linalg.norm(d)
    a = np.cross(d, [1.0, 0, 0] if abs(d[0]) < 0.9 else [0, 1.0, 0])
    a /= np.linalg.norm(a)
    b = np.cross(d, a)
    idx = hull_indices_2d(np.c_[hull @ a, hull @ b])
    _OUTLINE[key] = idx
    return idx


def part_points(parts: list[Part]) -> np.ndarray:
    """(N, 3) vertices of the parts' convex pieces (their meshes when they have none)."""
    pts = [pc.vertices for p in parts for pc in p.piece_arrays] or [p.vertices for p in parts]
    return np.vstack(pts)


_POINTS: dict[str, np.ndarray] = {}


def asset_points(asset: Asset) -> np.ndarray:
    """:func:`part_points` of all the asset's parts, stacked once per asset (read-only)."""
    pts = _POINTS.get(asset.asset_id)
    if pts is None:
        if len(_POINTS) > 4096:
            _POINTS.clear()
        pts = part_points(asset.parts)
        pts.flags.writeable = False
        _POINTS[asset.asset_id] = pts
    return pts


_CASTERS: dict[str, RayCaster] = {}


def ray_caster(asset: Asset) -> RayCaster:
    """A cached ray caster over the asset's mesh (asset frame, unit scale)."""
    c = _CASTERS.get(asset.asset_id)
    if c is None:
        if len(_CASTERS) > 512:
            _CASTERS.clear()
        m = asset.mesh_arrays()
        c = RayCaster(m.vertices, m.faces)
        _CASTERS[asset.asset_id] = c
    return c


@lru_cache(maxsize=1)
def enclosure_directions() -> np.ndarray:
    """(9, 3) unit rays for the IN enclosure test: 8 horizontal and straight up."""
    a = np.linspace(0, 2 * np.pi, 8, endpoint=False)
    d = np.c_[np.cos(a), np.sin(a), np.zeros(8)]
    return np.vstack([d, [0, 0, 1.0]])


def hull_extents(asset: Asset) -> tuple[np.ndarray, np.ndarray]:
    """The extents of the asset's hull along the asset axes (3,) and the axes in increasing
    order of extent (``argsort``), once per asset (read-only)."""
    got = _EXTENTS.get(asset.asset_id)
    if got is None:
        if len(_EXTENTS) > 4096:
            _EXTENTS.clear()
        ext = np.ptp(asset_geometry(asset).hull, axis=0)
        order = np.argsort(ext)
        ext.flags.writeable = order.flags.writeable = False
        got = _EXTENTS[asset.asset_id] = (ext, order)
    return got


_EXTENTS: dict[str, tuple[np.ndarray, np.ndarray]] = {}


def is_round(obj) -> bool:
    """Whether a placed object is about as wide as it is deep and tall (extents within 30%: an
    apple, a ball): it rolls rather than tips, and rests in any orientation."""
    ext = hull_extents(obj.asset)[0]
    return float(ext.max()) <= 1.3 * float(ext.min())


#: A flat thing standing on an edge is at most this thick for its smaller other extent.
ON_EDGE_THIN = 0.2


def side_frame(obj, R: np.ndarray) -> np.ndarray:
    """The frame (columns: right, front, up) in which the sides of ``obj`` at rotation ``R``
    are read: ``R`` itself, except for a flat thing modelled lying that stands on an edge face
    (``rests_on`` a side: a record filed on a shelf), whose right is its thin axis across the
    row (horizontal) and whose up is the world's, as a book standing in a row has them."""
    if getattr(obj, "rests_on", None) not in ("left", "right", "front", "back"):
        return R
    ext = hull_extents(obj.asset)[0]
    if float(ext[2]) > ON_EDGE_THIN * float(min(ext[0], ext[1])):
        return R
    right = np.asarray(R, float)[:, 2].copy()
    right[2] = 0.0
    norm = float(np.linalg.norm(right))
    if norm < 0.5:  # not standing on an edge after all
        return R
    right /= norm
    up = np.array([0.0, 0.0, 1.0])
    return np.c_[right, np.cross(up, right), up]


def drop_distance(child_pts: np.ndarray, child_asset: Asset, T_child: np.ndarray,
                  parent_pts: np.ndarray, parent_asset: Asset, T_parent: np.ndarray,
                  down: np.ndarray) -> float:
    """How far the child can move along ``down`` before touching the parent (inf: never).

    Rays from the child's points along ``down`` against the parent's mesh, and from the
    parent's points against ``-down`` against the child's mesh (both exact, by ray casting).
    Points are world-frame; ``T_*`` are asset-to-world similarity transforms.
    """
    best = np.inf
    # a ray can only hit the other body when its origin lies in the other's shadow: keep the
    # points inside the bounding box of the other's points seen along ``down`` (exact, fewer rays)
    d0 = np.asarray(down, float) / np.linalg.norm(down)
    x, y, z = d0.tolist()
    # two axes across ``down`` (numpy's cross is slow on single 3-vectors)
    e1 = np.array([0.0, -z, y]) if abs(x) <= min(abs(y), abs(z)) else \
        np.array([-y, x, 0.0]) if abs(z) <= abs(y) else np.array([z, 0.0, -x])
    e1 /= np.linalg.norm(e1)
    a, b, c = e1.tolist()
    E = np.column_stack([e1, [y * c - z * b, z * a - x * c, x * b - y * a]])
    pc, pp = child_pts @ E, parent_pts @ E
    for pts, proj, other, d, asset, T in ((child_pts, pc, pp, down, parent_asset, T_parent),
                                          (parent_pts, pp, pc, -down, child_asset, T_child)):
        lo, hi = other.min(axis=0) - 1e-6, other.max(axis=0) + 1e-6
        pts = pts[np.all((proj >= lo) & (proj <= hi), axis=1)]
        if not len(pts):
            continue
        Ti = _inverse(T)
        o = pts @ Ti[:3, :3].T + Ti[:3, 3]
        v = Ti[:3, :3] @ d
        scale = np.linalg.norm(v)
        v = v / scale
        locs, idx, _ = ray_caster(asset).first_hits(o, np.tile(v, (len(o), 1)))
        if len(idx):
            dist = np.linalg.norm(locs - o[idx], axis=1) / scale
            best = min(best, float(dist.min()))
    return best


_INVERSES: dict[bytes, np.ndarray] = {}


def _inverse(T: np.ndarray) -> np.ndarray:
    """``np.linalg.inv(T)`` of a (4, 4) transform, kept per transform (a parent's, met again
    by every child dropped onto it); read-only."""
    T = np.asarray(T, float)
    key = T.tobytes()
    got = _INVERSES.get(key)
    if got is None:
        if len(_INVERSES) > 4096:
            _INVERSES.clear()
        got = np.linalg.inv(T)
        got.flags.writeable = False
        _INVERSES[key] = got
    return got


_BVHS: dict[tuple[str, float], object] = {}


def _collision_object(asset: Asset, T: np.ndarray):
    """An FCL object of the asset's mesh at the similarity transform ``T`` (4, 4), its BVH
    built once per (asset, scale) with the scale baked in (FCL moves rigidly only)."""
    import fcl

    s = float(np.linalg.norm(T[:3, 0]))
    key = (asset.asset_id, round(s, 9))
    g = _BVHS.get(key)
    if g is None:
        if len(_BVHS) > 1024:
            _BVHS.clear()
        m = asset.mesh()
        g = fcl.BVHModel()
        g.beginModel(len(m.vertices), len(m.faces))
        g.addSubModel(np.asarray(m.vertices, dtype=np.float64) * s,
                      np.asarray(m.faces, dtype=np.int32))
        g.endModel()
        _BVHS[key] = g
    return fcl.CollisionObject(g, fcl.Transform(T[:3, :3] / s, T[:3, 3]))


def exact_drop(child_asset: Asset, T_child: np.ndarray, parent_asset: Asset,
               T_parent: np.ndarray, down: np.ndarray, upper: float, *,
               tol: float = 2.5e-4) -> float:
    """How far the child can move along ``down`` before its mesh touches the parent's, when
    :func:`drop_distance` found at most ``upper`` (m).

    ``drop_distance`` casts rays from mesh vertices, so two round bodies touching between
    vertices (an apple leaning on another, or on a bowl's curved wall) read a few millimetres
    apart. Here the drop is bisected on mesh-mesh collision (FCL) to within ``tol``: the
    smallest shift along ``down`` at which the meshes intersect. ``upper`` when they do not
    even there; 0 when they already do.
    """
    import fcl

    d0 = np.asarray(down, float) / np.linalg.norm(down)
    other = _collision_object(parent_asset, T_parent)

    def hits(shift: float) -> bool:
        T = np.array(T_child, float)
        T[:3, 3] = T[:3, 3] + shift * d0
        return fcl.collide(_collision_object(child_asset, T), other, fcl.CollisionRequest()) > 0

    if not np.isfinite(upper) or not hits(upper):
        return float(upper)
    if hits(0.0):
        return 0.0
    lo, hi = 0.0, float(upper)
    while hi - lo > tol:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if hits(mid) else (mid, hi)
    return hi
