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

__all__ = ["Surface", "SURFACE_BASIS", "resolve_surfaces", "surface_from_bbox", "plane_polygon"]

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
    try:
        h = ConvexHull(pts)
        if abs(h.volume - float(areas.sum())) <= 1e-6 * max(h.volume, 1e-12):
            return Polygon(pts[h.vertices])
    except (QhullError, ValueError):
        pass
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


def _patches(face_bin: np.ndarray, adjacency: np.ndarray, nbins: int) -> list[list[np.ndarray]]:
    """Connected patches of faces sharing a bin, per bin, each ordered by its lowest face index
    (bins < 0 are ignored)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    out: list[list[np.ndarray]] = [[] for _ in range(nbins)]
    idx = np.nonzero(face_bin >= 0)[0]
    if len(idx) == 0:
        return out
    a, b = adjacency[:, 0], adjacency[:, 1]
    keep = (face_bin[a] == face_bin[b]) & (face_bin[a] >= 0)
    n = len(face_bin)
    g = coo_matrix((np.ones(int(keep.sum()), bool), (a[keep], b[keep])), shape=(n, n))
    _, comp = connected_components(g, directed=False)
    comp = comp[idx]
    order = np.argsort(comp, kind="stable")
    cuts = np.nonzero(np.diff(comp[order]))[0] + 1
    groups = np.split(idx[order], cuts)
    groups.sort(key=lambda g_: int(g_[0]))
    for g_ in groups:
        out[int(face_bin[g_[0]])].append(g_)
    return out


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
    areas = mesh.area_faces
    centers = mesh.triangles_center
    adjacency = mesh.face_adjacency
    # The six directions are 90 degrees apart, so a face aligns with at most one of them: label
    # every face once, then find the patches of all six labels in a single graph pass.
    labels = list(SURFACES)
    dirs = np.array([SURFACES[k] for k in labels], float)
    align = normals @ dirs.T
    best_dir = np.argmax(align, axis=1)
    face_bin = np.where(align[np.arange(len(align)), best_dir] > _ALIGN_COS, best_dir, -1)
    comps_by_bin = _patches(face_bin, adjacency, len(labels))
    out: dict[str, Surface] = {}
    for li, (label, nrm) in enumerate(SURFACES.items()):
        n = np.array(nrm)
        comps = comps_by_bin[li]
        if not comps:
            out[label] = surface_from_bbox(label, bounds)
            continue
        axis = int(np.argmax(np.abs(n)))
        face_coord = bounds[1, axis] if n[axis] > 0 else bounds[0, axis]
        extent = bounds[1, axis] - bounds[0, axis]
        tol = tolerance if tolerance is not None else max(0.002, 0.03 * extent)
        best = None
        cands = []
        for comp in comps:
            comp = np.asarray(comp)
            a = areas[comp].sum()
            if a <= 1e-10:
                continue
            off = float((centers[comp] @ n * areas[comp]).sum() / a)
            dist = abs(face_coord * np.sign(n[axis]) - off)
            cands.append((dist, a, comp, off))
        if not cands:
            out[label] = surface_from_bbox(label, bounds)
            continue
        dmin = min(c[0] for c in cands)
        close = [c for c in cands if c[0] <= dmin + tol]
        best = max(close, key=lambda c: c[1])
        _, _, comp, off = best
        u, v = (np.array(x) for x in SURFACE_BASIS[label])
        tri = mesh.triangles[comp]
        tri2d = np.stack([tri @ u, tri @ v], axis=-1)
        poly = plane_polygon(tri2d)
        if poly.is_empty or poly.area <= 1e-10:
            out[label] = surface_from_bbox(label, bounds)
            continue
        c2 = np.asarray(poly.centroid.coords[0])
        origin = c2[0] * u + c2[1] * v + off * n
        poly = shapely.affinity.translate(poly, -c2[0], -c2[1])
        out[label] = Surface(label, origin, n, u, v, poly, "mesh")
    return out
