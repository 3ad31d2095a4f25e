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

import numpy as np
import shapely
import trimesh
from scipy.spatial import ConvexHull, QhullError
from shapely.geometry import MultiPolygon, Polygon
from shapely.geometry import box as shapely_box

from ..relations import SURFACES

__all__ = ["Surface", "SURFACE_BASIS", "resolve_surfaces", "surface_from_bbox", "plane_polygon", "component_roots"]

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
        poly = shapely.affinity.scale(self.polygon, s, s, origin=(0, 0)) if s != 1.0 else self.polygon
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


def plane_polygon(tri2d: np.ndarray) -> Polygon | MultiPolygon:
    """Union of (M, 3, 2) triangles as a cleaned shapely geometry."""
    tri2d = np.asarray(tri2d, float)
    if len(tri2d) == 0:
        return Polygon()
    e1 = tri2d[:, 1] - tri2d[:, 0]
    e2 = tri2d[:, 2] - tri2d[:, 0]
    areas = 0.5 * np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])
    tri2d = tri2d[areas > 1e-12]
    areas = areas[areas > 1e-12]
    if len(tri2d) == 0:
        return Polygon()
    if len(tri2d) == 1:
        return Polygon(tri2d[0])
    # fast path: a convex patch (a box face, a disc, a tabletop) is its vertices' hull, which
    # we recognise by the triangles' areas adding up to the hull's area
    pts = tri2d.reshape(-1, 2)
    hull = _hull_ccw(pts)
    if len(hull) >= 3:
        x, y = hull[:, 0], hull[:, 1]
        hull_area = 0.5 * float(x[:-1] @ y[1:] - x[1:] @ y[:-1] + x[-1] * y[0] - x[0] * y[-1])
        if abs(hull_area - float(areas.sum())) <= 1e-6 * max(hull_area, 1e-12):
            return Polygon(hull)
    polys = shapely.polygons(np.concatenate([tri2d, tri2d[:, :1]], axis=1))
    u = shapely.union_all(shapely.buffer(polys, 1e-7, join_style="mitre"))
    u = shapely.buffer(u, -1e-7, join_style="mitre")
    return u.simplify(1e-6)


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


def resolve_surfaces(mesh: trimesh.Trimesh, *, tolerance: float | None = None) -> dict[str, Surface]:
    """The six directional surfaces of a part mesh (in its own frame).

    Parameters
    ----------
    mesh : trimesh.Trimesh
        The part, in the asset's canonical frame.
    tolerance : float, optional
        How much farther from the bbox face than the closest patch a patch may lie and still
        count as "closest", metres. Defaults to max(2 mm, 3% of the part's extent along the
        face normal).

    Returns
    -------
    dict of str to Surface
        Keyed by label, always all six.
    """
    bounds = np.asarray(mesh.bounds, float)
    normals = mesh.face_normals
    tri = mesh.triangles
    areas = mesh.area_faces
    centers = mesh.triangles_center
    # The six directions are 90 degrees apart, so a face aligns with at most one of them: label
    # every face once, then find the connected patches of all six labels in one pass.
    labels = list(SURFACES)
    dirs = np.array([SURFACES[k] for k in labels], float)
    align = normals @ dirs.T
    best_dir = np.argmax(align, axis=1)
    face_bin = np.where(align[np.arange(len(align)), best_dir] > _ALIGN_COS, best_dir, -1)
    binned = face_bin >= 0
    if binned.any():
        adjacency = mesh.face_adjacency
        ea, eb = adjacency[:, 0], adjacency[:, 1]
        keep = (face_bin[ea] == face_bin[eb]) & binned[ea]
        root = component_roots(len(face_bin), ea[keep], eb[keep])
    else:
        root = np.arange(len(face_bin))
    idx = np.nonzero(binned)[0]
    lab = root[idx]
    # per patch (keyed by its lowest face index): area and area-weighted offset along its normal
    roots = np.unique(lab)
    pos = np.searchsorted(roots, lab)
    p_area = np.bincount(pos, areas[idx], minlength=len(roots))
    offs_all = (centers[idx] * dirs[face_bin[idx]]).sum(axis=1)
    p_moment = np.bincount(pos, offs_all * areas[idx], minlength=len(roots))
    p_bin = face_bin[roots]
    out: dict[str, Surface] = {}
    for li, (label, nrm) in enumerate(SURFACES.items()):
        n = dirs[li]
        sel = np.nonzero((p_bin == li) & (p_area > 1e-10))[0]
        if len(sel) == 0:
            out[label] = surface_from_bbox(label, bounds)
            continue
        axis = int(np.argmax(np.abs(n)))
        face_coord = bounds[1, axis] if n[axis] > 0 else bounds[0, axis]
        extent = bounds[1, axis] - bounds[0, axis]
        tol = tolerance if tolerance is not None else max(0.002, 0.03 * extent)
        dist = np.abs(face_coord * np.sign(n[axis]) - p_moment[sel] / p_area[sel])
        close = sel[dist <= dist.min() + tol]
        # the largest close patch (the first of equals, in face order), its sums taken exactly
        best_a, comp, off = -1.0, None, 0.0
        for k in close:
            c = idx[pos == k]
            a_ = areas[c].sum()
            if a_ > best_a:
                best_a, comp = a_, c
                off = float((centers[c] @ n * areas[c]).sum() / a_)
        u, v = (np.array(x) for x in SURFACE_BASIS[label])
        t = tri[comp]
        tri2d = np.stack([t @ u, t @ v], axis=-1)
        poly = plane_polygon(tri2d)
        if poly.is_empty or poly.area <= 1e-10:
            out[label] = surface_from_bbox(label, bounds)
            continue
        c2 = np.asarray(poly.centroid.coords[0])
        origin = c2[0] * u + c2[1] * v + off * n
        poly = shapely.transform(poly, lambda xy, c2=c2: xy - c2)
        out[label] = Surface(label, origin, np.array(nrm, float), u, v, poly, "mesh")
    return out
