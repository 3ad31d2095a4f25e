"""Directional surfaces: the paper's geometric resolution of a part's six faces.

For each face of a part's axis-aligned bounding box (``top`` +Z, ``bottom`` -Z, ``front`` +Y,
``back`` -Y, ``right`` +X, ``left`` -X), find the connected mesh patches whose normals align with
the face normal, keep those closest to the bbox face, and among them the one with the largest
area. That patch, projected into its plane, is the *directional surface*. Without such a patch
the bbox face itself is used.

A :class:`Surface` is a plane (origin, unit normal and an in-plane basis ``u``, ``v`` with
``u x v = normal``) and a 2D polygon in ``(u, v)`` coordinates around the origin.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon
from shapely.geometry import box as shapely_box

from ..relations import SURFACES
from .frames import cross_rows

if TYPE_CHECKING:
    import trimesh

__all__ = [
    "Surface",
    "SURFACE_BASIS",
    "FaceData",
    "face_data",
    "resolve_surfaces",
    "resolve_surfaces_steady",
    "surface_from_bbox",
    "plane_polygon",
    "component_roots",
    "hull_area_2d",
]

#: In-plane basis (u, v) of each label, chosen so that u x v = the outward normal.
SURFACE_BASIS: dict[str, tuple[tuple[float, ...], tuple[float, ...]]] = {
    "top": ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0)),
    "bottom": ((1.0, 0.0, 0.0), (0.0, -1.0, 0.0)),
    "front": ((-1.0, 0.0, 0.0), (0.0, 0.0, 1.0)),
    "back": ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0)),
    "right": ((0.0, 1.0, 0.0), (0.0, 0.0, 1.0)),
    "left": ((0.0, -1.0, 0.0), (0.0, 0.0, 1.0)),
}

_ALIGN_COS = np.cos(np.deg2rad(12.0))
_LABELS = tuple(SURFACES)
_DIRS = np.array([SURFACES[k] for k in _LABELS], float)
_NORMALS = [np.array(SURFACES[k], float) for k in _LABELS]
_AXIS = [int(np.argmax(np.abs(d))) for d in _DIRS]
_BASIS = [tuple(np.array(a) for a in SURFACE_BASIS[k]) for k in _LABELS]


_SCALED: dict[tuple[int, float], tuple] = {}


def _scaled(poly, s: float):
    """``poly`` scaled by ``s`` about the origin, once per (polygon object, scale): a parent's
    surfaces are carried to the world again for every candidate placed on it."""
    k = (id(poly), s)
    got = _SCALED.get(k)
    if got is not None and got[0] is poly:
        return got[1]
    if len(_SCALED) > 4096:
        _SCALED.clear()
    out = shapely.affinity.scale(poly, s, s, origin=(0, 0))
    _SCALED[k] = (poly, out)  # holding the polygon keeps its id valid
    return out


@dataclass
class Surface:
    """A planar surface patch.

    Attributes
    ----------
    label : str
        ``top``, ``bottom``, ``front``, ``back``, ``right`` or ``left``.
    origin : (3,) float
        A point of the plane (the polygon's centroid), metres, in the frame it was built in.
    normal : (3,) float
        Unit outward normal.
    u, v : (3,) float
        Unit in-plane axes with ``u x v = normal``.
    polygon : shapely Polygon or MultiPolygon
        The patch in ``(u, v)`` coordinates relative to ``origin``.
    source : str
        ``"mesh"`` (a resolved patch) or ``"bbox"`` (fallback to the bounding-box face).
    """

    label: str
    origin: np.ndarray
    normal: np.ndarray
    u: np.ndarray
    v: np.ndarray
    polygon: Polygon | MultiPolygon
    source: str = "mesh"

    @property
    def area(self) -> float:
        return float(self.polygon.area)

    def to_3d(self, pts2d) -> np.ndarray:
        """Map (N, 2) plane coordinates to (N, 3) points."""
        p = np.asarray(pts2d, float).reshape(-1, 2)
        return self.origin + p[:, :1] * self.u + p[:, 1:] * self.v

    def to_2d(self, pts3d) -> np.ndarray:
        """Project (N, 3) points into (N, 2) plane coordinates."""
        d = np.asarray(pts3d, float).reshape(-1, 3) - self.origin
        return np.c_[d @ self.u, d @ self.v]

    def outline_3d(self) -> np.ndarray:
        """(N, 3) exterior ring of the largest polygon piece, in 3D."""
        poly = self.polygon
        if isinstance(poly, MultiPolygon):
            poly = max(poly.geoms, key=lambda g: g.area)
        return self.to_3d(np.asarray(poly.exterior.coords))

    def transformed(self, T: np.ndarray) -> Surface:
        """This surface moved by a (4, 4) similarity transform (rotation x uniform scale + t).

        The polygon is rescaled by the transform's scale so areas stay right.
        """
        A = T[:3, :3]
        s = float(np.cbrt(abs(np.linalg.det(A))))
        R = A / s
        poly = _scaled(self.polygon, s) if s != 1.0 else self.polygon
        return Surface(
            self.label,
            A @ self.origin + T[:3, 3],
            R @ self.normal,
            R @ self.u,
            R @ self.v,
            poly,
            self.source,
        )

    def to_dict(self) -> dict:
        return {
            "label": self.label,
            "origin": [round(float(x), 6) for x in self.origin],
            "normal": [round(float(x), 6) for x in self.normal],
            "area": round(self.area, 6),
            "source": self.source,
        }


def _hull_ccw(pts: np.ndarray) -> np.ndarray:
    """(K, 2) convex hull vertices of (N, 2) points, counter-clockwise, collinear points dropped.

    Andrew's monotone chain: for the few dozen points of a part's face it is many times faster
    than setting up qhull.
    """
    if len(pts) > 4096:
        from scipy.spatial import ConvexHull, QhullError

        try:
            h = ConvexHull(pts)
        except (QhullError, ValueError):
            return np.empty((0, 2))
        return pts[h.vertices]
    order = np.lexsort((pts[:, 1], pts[:, 0]))
    p = pts[order]
    keep = np.ones(len(p), bool)
    keep[1:] = np.any(p[1:] != p[:-1], axis=1)
    p = p[keep].tolist()
    if len(p) < 3:
        return np.empty((0, 2))

    def chain(seq):
        out: list = []
        for q in seq:
            while len(out) >= 2:
                (ax, ay), (bx, by) = out[-2], out[-1]
                if (bx - ax) * (q[1] - ay) - (by - ay) * (q[0] - ax) > 0:
                    break
                out.pop()
            out.append(q)
        return out

    lower = chain(p)
    upper = chain(reversed(p))
    return np.array(lower[:-1] + upper[:-1], float)


def hull_area_2d(pts: np.ndarray) -> float:
    """Area of the convex hull of (N, 2) points (0 when they span none), m^2."""
    h = _hull_ccw(np.asarray(pts, float))
    if len(h) < 3:
        return 0.0
    x, y = h[:, 0], h[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def _convex_or_union(tri2d: np.ndarray):
    """Union of (M, 3, 2) triangles: ``(hull, area)`` when it is convex (its (K, 2) hull,
    counter-clockwise, and the area), else ``(geometry, None)``."""
    tri2d = np.asarray(tri2d, float)
    if len(tri2d) == 0:
        return Polygon(), None
    e1 = tri2d[:, 1] - tri2d[:, 0]
    e2 = tri2d[:, 2] - tri2d[:, 0]
    areas = 0.5 * np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])
    big = areas > 1e-12
    tri2d = tri2d[big]
    areas = areas[big]
    if len(tri2d) == 0:
        return Polygon(), None
    if len(tri2d) == 1:
        return Polygon(tri2d[0]), None
    # fast path: a convex patch (a box face, a disc, a tabletop) is its vertices' hull, which
    # we recognise by the triangles' areas adding up to the hull's area
    pts = tri2d.reshape(-1, 2)
    hull = _hull_ccw(pts)
    if len(hull) >= 3:
        x, y = hull[:, 0], hull[:, 1]
        hull_area = 0.5 * float(x[:-1] @ y[1:] - x[1:] @ y[:-1] + x[-1] * y[0] - x[0] * y[-1])
        if abs(hull_area - float(areas.sum())) <= 1e-6 * max(hull_area, 1e-12):
            return hull, hull_area
    polys = shapely.polygons(np.concatenate([tri2d, tri2d[:, :1]], axis=1))
    u = shapely.union_all(shapely.buffer(polys, 1e-7, join_style="mitre"))
    u = shapely.buffer(u, -1e-7, join_style="mitre")
    return u.simplify(1e-6), None


def plane_polygon(tri2d: np.ndarray) -> Polygon | MultiPolygon:
    """Union of (M, 3, 2) triangles as a cleaned shapely geometry."""
    geom, _ = _convex_or_union(tri2d)
    return Polygon(geom) if isinstance(geom, np.ndarray) else geom


def _ring_centroid(ring: np.ndarray, area: float) -> np.ndarray:
    """(2,) centroid of the simple polygon ``ring`` (K, 2) of signed area ``area``."""
    x, y = ring[:, 0] - ring[0, 0], ring[:, 1] - ring[0, 1]
    xn, yn = np.r_[x[1:], x[:1]], np.r_[y[1:], y[:1]]
    cr = x * yn - xn * y
    return np.array([((x + xn) @ cr), ((y + yn) @ cr)]) / (6.0 * area) + ring[0]


@dataclass
class FaceData:
    """Per-face arrays of a triangle mesh, computed once and shared by the surface finders.

    Reading them from a trimesh object re-verifies its cache (hashing the arrays) on every
    access; the directional and the internal surfaces of an asset read each several times.

    Attributes
    ----------
    bounds : (2, 3) float
        Axis-aligned bounds of the vertices, metres.
    triangles : (F, 3, 3) float
        Corner positions of every face.
    normals : (F, 3) float
        Unit face normals (zero for degenerate faces), as trimesh reports them.
    areas : (F,) float
        Face areas, m^2.
    centers : (F, 3) float
        Face centroids.
    adjacency : (E, 2) int
        Pairs of faces sharing an edge that exactly two faces use, each pair sorted.
    """

    bounds: np.ndarray
    triangles: np.ndarray
    normals: np.ndarray
    areas: np.ndarray
    centers: np.ndarray
    adjacency: np.ndarray


def _face_adjacency(faces: np.ndarray) -> np.ndarray:
    """(E, 2) sorted pairs of faces sharing an edge used by exactly two faces (trimesh's rule)."""
    nf = len(faces)
    if nf == 0:
        return np.empty((0, 2), np.int64)
    e = faces[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2).astype(np.int64)
    e.sort(axis=1)
    key = e[:, 0] * (int(e[:, 1].max()) + 1) + e[:, 1]
    order = np.argsort(key, kind="stable")
    k = key[order]
    # runs of equal keys of length exactly two
    start = np.r_[True, k[1:] != k[:-1]]
    starts = np.nonzero(start)[0]
    lengths = np.diff(np.r_[starts, len(k)])
    two = starts[lengths == 2]
    fa = order[two] // 3
    fb = order[two + 1] // 3
    adj = np.stack([fa, fb], axis=1)
    adj = adj[adj[:, 0] != adj[:, 1]]
    adj.sort(axis=1)
    return adj


def unit_normals(crosses: np.ndarray) -> np.ndarray:
    """(F, 3) unit face normals from the (F, 3) cross products of each face's edges
    ``(v1 - v0) x (v2 - v1)``: what ``trimesh.Trimesh.face_normals`` computes (zero rows for
    degenerate faces), without reading through the mesh's cache."""
    import trimesh

    unit, ok = trimesh.util.unitize(crosses, check_valid=True)
    if ok.all():
        return unit
    out = np.zeros((len(crosses), 3))
    out[ok] = unit
    return out


def face_data(mesh: trimesh.Trimesh) -> FaceData:
    """The :class:`FaceData` of ``mesh`` (a trimesh.Trimesh)."""
    v = np.asarray(mesh.vertices, float).view(np.ndarray)
    f = np.asarray(mesh.faces).view(np.ndarray)
    tri = v[f]
    e = tri[:, 1:, :] - tri[:, :2, :]  # the edge vectors trimesh crosses, so areas match it
    cr = cross_rows(e[:, 0], e[:, 1])
    areas = np.sqrt((cr**2).sum(axis=1)) / 2.0
    if "face_normals" in mesh._cache:  # normals given or carried through a transform win
        normals = np.asarray(mesh.face_normals, float).view(np.ndarray)
    else:
        normals = unit_normals(cr)
    used = tri.reshape(-1, 3)  # trimesh's bounds count only vertices that faces use
    bounds = np.array([used.min(axis=0), used.max(axis=0)]) if len(used) else np.zeros((2, 3))
    return FaceData(bounds, tri, normals, areas, tri.mean(axis=1), _face_adjacency(f))


def surface_from_bbox(label: str, bounds: np.ndarray) -> Surface:
    """The face ``label`` of the axis-aligned box ``bounds`` (2, 3) as a Surface."""
    n = np.array(SURFACES[label])
    u, v = (np.array(a) for a in SURFACE_BASIS[label])
    lo, hi = bounds
    c = (lo + hi) / 2.0
    axis = int(np.argmax(np.abs(n)))
    c[axis] = hi[axis] if n[axis] > 0 else lo[axis]
    ext = hi - lo
    hu = float(np.abs(u) @ ext) / 2.0
    hv = float(np.abs(v) @ ext) / 2.0
    return Surface(label, c, n, u, v, shapely_box(-hu, -hv, hu, hv), "bbox")


def component_roots(n: int, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """(n,) the lowest node index of each node's connected component over edges ``(a, b)``.

    Vectorised union-find (hook every root onto the smallest root it touches, then jump
    pointers): far cheaper than building a sparse graph for the few hundred faces of a part.
    """
    parent = np.arange(n)
    while len(a):
        while True:
            pp = parent[parent]
            if np.array_equal(pp, parent):
                break
            parent = pp
        ra, rb = parent[a], parent[b]
        m = ra != rb
        if not m.any():
            break
        a, b, ra, rb = a[m], b[m], ra[m], rb[m]
        np.minimum.at(parent, np.maximum(ra, rb), np.minimum(ra, rb))
    return parent


def resolve_surfaces(mesh: trimesh.Trimesh, *, tolerance: float | None = None,
                     faces: FaceData | None = None) -> dict[str, Surface]:
    """The six directional surfaces of a part mesh (in its own frame).

    Parameters
    ----------
    mesh : trimesh.Trimesh
        The part, in the asset's canonical frame.
    tolerance : float, optional
        How much farther from the bbox face than the closest patch a patch may lie and still
        count as "closest", metres. Defaults to max(2 mm, 3% of the part's extent along the
        face normal).
    faces : FaceData, optional
        ``face_data(mesh)`` when the caller already has it.

    Returns
    -------
    dict of str to Surface
        Keyed by label, always all six.
    """
    return _resolve(faces if faces is not None else face_data(mesh), tolerance)[0]


def _near(a, b) -> bool:
    return bool(np.any(np.abs(np.asarray(a) - b) <= 1e-9 * np.maximum(1.0, np.abs(b))))


def resolve_surfaces_steady(fd: FaceData, tolerance: float | None = None) -> tuple[dict[str, Surface], bool]:
    """:func:`resolve_surfaces` from face data, with the *steady* flag of :func:`_resolve`."""
    return _resolve(fd, tolerance)


def _resolve(fd: FaceData, tolerance: float | None) -> tuple[dict[str, Surface], bool]:
    """:func:`resolve_surfaces` of ``fd``, and whether the result is *steady*: no decision
    (a face's alignment, a patch's distance, equal-area patches; a non-convex patch's union,
    which shapely does not compute translation-exactly) came within
    rounding of flipping, so a translated copy of the mesh resolves to these surfaces moved."""
    steady = True
    bounds = fd.bounds
    normals = fd.normals
    tri = fd.triangles
    areas = fd.areas
    centers = fd.centers
    # The six directions are 90 degrees apart, so a face aligns with at most one of them: label
    # every face once, then find the connected patches of all six labels in one pass.
    dirs = _DIRS
    align = normals @ dirs.T
    best_dir = np.argmax(align, axis=1)
    best_align = align[np.arange(len(align)), best_dir]
    face_bin = np.where(best_align > _ALIGN_COS, best_dir, -1)
    steady = not _near(best_align, _ALIGN_COS)
    binned = face_bin >= 0
    if binned.any():
        ea, eb = fd.adjacency[:, 0], fd.adjacency[:, 1]
        keep = (face_bin[ea] == face_bin[eb]) & binned[ea]
        root = component_roots(len(face_bin), ea[keep], eb[keep])
    else:
        root = np.arange(len(face_bin))
    idx = np.nonzero(binned)[0]
    lab = root[idx]
    # per patch (keyed by its lowest face index): area and area-weighted offset along its normal
    roots, pos = np.unique(lab, return_inverse=True)
    p_area = np.bincount(pos, areas[idx], minlength=len(roots))
    offs_all = (centers[idx] * dirs[face_bin[idx]]).sum(axis=1)
    p_moment = np.bincount(pos, offs_all * areas[idx], minlength=len(roots))
    p_bin = face_bin[roots]
    # faces of each patch, in face order: sort once instead of scanning per patch
    order = np.argsort(pos, kind="stable")
    cuts = np.searchsorted(pos[order], np.arange(len(roots) + 1))
    out: dict[str, Surface] = {}
    for li, label in enumerate(_LABELS):
        n = dirs[li]
        sel = np.nonzero((p_bin == li) & (p_area > 1e-10))[0]
        if len(sel) == 0:
            out[label] = surface_from_bbox(label, bounds)
            continue
        axis = _AXIS[li]
        face_coord = bounds[1, axis] if n[axis] > 0 else bounds[0, axis]
        extent = bounds[1, axis] - bounds[0, axis]
        tol = tolerance if tolerance is not None else max(0.002, 0.03 * extent)
        dist = np.abs(face_coord * np.sign(n[axis]) - p_moment[sel] / p_area[sel])
        limit = dist.min() + tol
        close = sel[dist <= limit]
        if steady and len(sel) > len(close) and _near(dist, limit):
            steady = False
        # the largest close patch (the first of equals, in face order), its sums taken exactly;
        # patches clearly smaller than the largest (by the binned sums) cannot win
        ca = p_area[close]
        if len(close) > 1:
            close = close[ca >= ca.max() * (1.0 - 1e-9)]
            if len(close) > 1:
                steady = False  # (nearly) equal patches: rounding picks one
        best_a, comp = -1.0, None
        for k in close:
            c = idx[order[cuts[k]:cuts[k + 1]]]
            a_ = areas[c].sum()
            if a_ > best_a:
                best_a, comp = a_, c
        off = float((centers[comp] @ n * areas[comp]).sum() / best_a)
        u, v = _BASIS[li]
        t = tri[comp]
        geom, area = _convex_or_union(np.stack([t @ u, t @ v], axis=-1))
        if area is None:
            steady = False  # shapely's union is not translation-exact
        if area is not None:  # a convex patch: its hull ring, centroid by the shoelace formula
            if area <= 1e-10:
                out[label] = surface_from_bbox(label, bounds)
                continue
            c2 = _ring_centroid(geom, area)
            poly = Polygon(geom - c2)
        else:
            if geom.is_empty or geom.area <= 1e-10:
                out[label] = surface_from_bbox(label, bounds)
                continue
            c2 = np.asarray(geom.centroid.coords[0])
            poly = shapely.transform(geom, lambda xy, c2=c2: xy - c2)
        origin = c2[0] * u + c2[1] * v + off * n
        out[label] = Surface(label, origin, _NORMALS[li].copy(), u.copy(), v.copy(), poly, "mesh")
    return out, steady
