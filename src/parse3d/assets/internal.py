"""Internal support surfaces for ``IN``: upward surfaces inside an object's volume.

A shelf inside a bookcase or a cabinet, a refrigerator shelf, the inside bottom of a bowl, a
basket, a bucket, a pot or a bathtub. Found geometrically, so loaded assets get them too: an
upward-facing patch is *internal* when, seen from just above it,

* something of the asset covers it (an upward ray hits) and the asset surrounds it on at least
  three of eight horizontal directions (a shelf in an open-fronted bookcase), or
* nothing covers it but the asset surrounds it on at least seven of eight horizontal directions
  (an open container such as a bowl).
"""

from __future__ import annotations

import numpy as np
import shapely
import trimesh

from ..geometry.frames import cross_rows
from ..geometry.surfaces import (
    SURFACE_BASIS,
    Surface,
    component_roots,
    face_data,
    plane_polygon,
    unit_normals,
)

__all__ = ["find_internal_surfaces", "MIN_INTERNAL_AREA"]

MIN_INTERNAL_AREA = 6e-4  # m^2 (6 cm^2): smaller patches hold nothing
MIN_CLEARANCE = 0.04  # m: less free height above a surface holds nothing either
_UP_COS = np.cos(np.deg2rad(12.0))
_REST = 0.001  # m: a solid this close above a patch rests on it
_DIRS = np.array([[np.cos(a), np.sin(a), 0.0] for a in np.linspace(0, 2 * np.pi, 8, endpoint=False)])


def _intersector(mesh: trimesh.Trimesh):
    try:
        from trimesh.ray.ray_pyembree import RayMeshIntersector

        return RayMeshIntersector(mesh)
    except Exception:  # embree missing: fall back to the slow pure-numpy caster
        from trimesh.ray.ray_triangle import RayMeshIntersector

        return RayMeshIntersector(mesh)


def _first_hit(caster, normals, origins: np.ndarray, dirs: np.ndarray):
    """Distance to the first hit for each ray (inf when it misses), and whether that hit was
    a back face (the ray started inside a solid)."""
    locs, ray_idx, tri = caster.intersects_location(origins, dirs, multiple_hits=False)
    dist = np.full(len(origins), np.inf)
    inside = np.zeros(len(origins), bool)
    if len(ray_idx):
        d = np.linalg.norm(locs - origins[ray_idx], axis=1)
        dist[ray_idx] = d
        inside[ray_idx] = np.einsum("ij,ij->i", normals[tri], dirs[ray_idx]) > 0
    return dist, inside


def _exit_distances(hull, xy: np.ndarray, reach: float) -> np.ndarray:
    """(N, 8) distance from each point to where each horizontal direction leaves ``hull``."""
    out = np.zeros((len(xy), len(_DIRS)))
    for i, p in enumerate(xy):
        ends = p + _DIRS[:, :2] * reach
        lines = shapely.linestrings([[p, e] for e in ends])
        out[i] = shapely.length(shapely.intersection(lines, hull))
    return out


def _raw(mesh: trimesh.Trimesh) -> tuple[np.ndarray, np.ndarray]:
    """(V, 3) vertices and (F, 3) faces of ``mesh`` as plain arrays (no cache bookkeeping)."""
    return (np.asarray(mesh.vertices, float).view(np.ndarray),
            np.asarray(mesh.faces, np.int64).view(np.ndarray))


def _whole(asset, faces: dict) -> tuple[trimesh.Trimesh, np.ndarray]:
    """All parts as one mesh for ray casting, and its (F, 3) face normals.

    The parts' vertices and faces are stacked directly, and their normals taken from the face
    data already computed: ``trimesh.util.concatenate`` would also merge visuals and recompute
    every cached property, which costs more than the rays.
    """
    verts, tris, normals = [], [], []
    offset = 0
    for p in asset.parts:
        v, f = _raw(p.mesh)
        verts.append(v)
        tris.append(f + offset)
        offset += len(v)
        fd = faces.get(p.name) or face_data(p.mesh)
        normals.append(fd.normals)
    return (trimesh.Trimesh(np.vstack(verts), np.vstack(tris), process=False),
            np.vstack(normals))


def _planes(piece: trimesh.Trimesh) -> tuple[np.ndarray, np.ndarray]:
    """A convex piece's face planes: (F, 3) unit normals ``n`` and (F,) offsets ``d`` with
    ``n . x = d`` on face F (trimesh's face normals, computed without its cache)."""
    v, f = _raw(piece)
    tri = v[f]
    e = tri[:, 1:, :] - tri[:, :2, :]
    n = unit_normals(cross_rows(e[:, 0], e[:, 1]))
    return n, np.einsum("ij,ij->i", n, tri[:, 0])


def _stack_planes(planes: list) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """All pieces' face planes in one array: (F, 3) normals, (F,) offsets and the (K,) index of
    each piece's first face (pieces without faces left out)."""
    planes = [(n, d) for n, d in planes if len(d)]
    if not planes:
        return np.zeros((0, 3)), np.zeros(0), np.zeros(0, np.int64)
    starts = np.cumsum([0] + [len(d) for _, d in planes[:-1]])
    return (np.vstack([n for n, _ in planes]), np.concatenate([d for _, d in planes]),
            starts.astype(np.int64))


def _inside_pieces(stacked, pts: np.ndarray) -> np.ndarray:
    """Whether each point lies strictly inside any convex piece (given by :func:`_stack_planes`):
    behind every face plane of one piece, all pieces tested in one product."""
    n, d, starts = stacked
    if not len(d):
        return np.zeros(len(pts), bool)
    behind = (pts @ n.T) - d < -1e-6
    return np.logical_and.reduceat(behind, starts, axis=1).any(axis=1)


def find_internal_surfaces(asset, *, faces: dict | None = None) -> list:
    """Internal support surfaces of an asset (see the module docstring).

    Parameters
    ----------
    asset : Asset
    faces : dict of part name to FaceData, optional
        ``face_data`` of the parts' meshes when the caller already has them.

    Returns
    -------
    list of InternalSurface
        In the asset frame, ordered bottom-to-top.
    """
    from .model import InternalSurface

    if not any(len(p.mesh.faces) for p in asset.parts):
        return []
    faces = faces or {}
    if faces and all(p.name in faces for p in asset.parts):  # the same numbers, no mesh cache
        fb = np.array([faces[p.name].bounds for p in asset.parts])
        bounds = np.array([fb[:, 0].min(axis=0), fb[:, 1].max(axis=0)])
    else:
        bounds = asset.bounds
    top_z = float(bounds[1, 2])
    reach = float(np.linalg.norm(bounds[1] - bounds[0])) * 2 + 0.1
    u, v = (np.array(a) for a in SURFACE_BASIS["top"])
    found = []
    ray: list = []  # (caster, face normals) of the whole asset, built when a patch first needs it

    def caster_normals():
        if not ray:
            whole, normals = _whole(asset, faces)
            ray.extend((_intersector(whole), normals))
        return ray

    planes: list = []  # the convex pieces' face planes, built when a patch first needs them

    def piece_planes():
        if not planes:
            planes.append(_stack_planes([_planes(pc) for p in asset.parts for pc in p.pieces]))
        return planes[0]

    for part in asset.parts:
        fd = faces.get(part.name) or face_data(part.mesh)
        up = fd.normals[:, 2] > _UP_COS
        if not up.any():
            continue
        idx = np.nonzero(up)[0]
        adj = fd.adjacency
        keep = up[adj[:, 0]] & up[adj[:, 1]]
        root = component_roots(len(up), adj[keep, 0], adj[keep, 1])[idx]
        for r in np.unique(root):
            comp = idx[root == r]
            area = fd.areas[comp].sum()
            if area < MIN_INTERNAL_AREA:
                continue
            z = float((fd.centers[comp, 2] * fd.areas[comp]).sum() / area)
            if top_z - z < 0.02:
                continue
            tri = fd.triangles[comp]
            poly = plane_polygon(np.stack([tri @ u, tri @ v], axis=-1))
            if poly.is_empty:
                continue
            samples = [np.asarray(poly.representative_point().coords[0])]
            c = np.asarray(poly.centroid.coords[0])
            if poly.contains(shapely.Point(c)):
                samples.append(c)
            pts = np.array([[x, y, z] for x, y in samples])
            lift = 0.01
            o_up = pts + [0, 0, lift]
            caster, normals = caster_normals()
            h_up, inside = _first_hit(caster, normals, o_up, np.tile([0, 0, 1.0], (len(pts), 1)))
            if inside.any() or _inside_pieces(piece_planes(),
                                              np.vstack([o_up, pts + [0, 0, _REST]])).any():
                continue  # the patch is covered by a solid standing on it (or resting on it:
                #           a foot ring's top under a bowl's floor thicker than the lift)
            o_h = np.repeat(pts + [0, 0, lift], len(_DIRS), axis=0)
            d_h = np.tile(_DIRS, (len(pts), 1))
            hh, _ = _first_hit(caster, normals, o_h, d_h)
            hh = hh.reshape(len(pts), len(_DIRS))
            # a horizontal hit counts only where the patch ends: a wall around the surface, not
            # an obstacle standing on it (a pedestal's column, a trestle's upright)
            edge = _exit_distances(poly.convex_hull, pts[:, :2], reach)
            hits = (hh >= edge - 0.01) & (hh < reach)
            hits = hits.sum(axis=1)
            covered = np.isfinite(h_up)
            if covered.all() and (hits >= 3).all():
                clearance = float(h_up.min()) + lift
                depth = clearance
            elif (~covered).all() and (hits >= 7).all():
                clearance = float("inf")
                depth = top_z - z
            else:
                continue
            if clearance < MIN_CLEARANCE:
                continue
            if depth < 0.02:
                continue
            c2 = np.asarray(poly.centroid.coords[0])
            origin = np.array([c2[0], c2[1], z])
            surf = Surface("top", origin, np.array([0, 0, 1.0]), u, v,
                           shapely.affinity.translate(poly, -c2[0], -c2[1]), "mesh")
            found.append(InternalSurface(part.name, surf, clearance, float(depth)))
    found.sort(key=lambda s: (round(float(s.surface.origin[2]), 4), s.part))
    return found
