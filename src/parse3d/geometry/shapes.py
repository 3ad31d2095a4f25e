"""Mesh primitives that know their own convex decomposition.

Every builder returns a :class:`Shape`: a triangle mesh plus a list of convex pieces whose union
covers it. Procedural asset generators compose parts from shapes, so collision geometry is exact
and CoACD is only needed for meshes loaded from files.

All lengths are metres; shapes are built in the asset's canonical frame (+Z up, front +Y).

Examples
--------
>>> s = box((0.5, 0.3, 0.02), center=(0, 0, 0.71), bevel=0.004)
>>> len(s.pieces)
1
>>> v = vessel([(0.04, 0.0), (0.045, 0.09)], thickness=0.004)
>>> v.mesh.is_watertight
True
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError

from .frames import cross_rows, make_transform, rotation_between

__all__ = [
    "Shape",
    "box",
    "cylinder",
    "frustum",
    "ellipsoid",
    "lathe",
    "vessel",
    "tube",
    "prism",
    "hull",
    "union",
    "transformed",
]


@dataclass
class Shape:
    """A mesh with its convex decomposition.

    Attributes
    ----------
    mesh : trimesh.Trimesh
        Visual mesh.
    pieces : list of trimesh.Trimesh
        Convex pieces covering the mesh (each one convex, in the same frame).
    """

    mesh: trimesh.Trimesh
    pieces: list[trimesh.Trimesh] = field(default_factory=list)

    def apply(self, T: np.ndarray) -> Shape:
        """Return a copy moved by the (4, 4) transform ``T``."""
        return transformed(self, T)

    def moved(self, offset) -> Shape:
        return transformed(self, make_transform(t=offset))


def _convex(points: np.ndarray) -> trimesh.Trimesh:
    """Convex hull of points as a watertight mesh with outward faces.

    qhull directly (with faces oriented by its plane equations) is several times faster than
    building the hull through trimesh's processing pipeline, and gives the same solid.
    """
    pts = np.asarray(points, dtype=float)
    try:
        h = ConvexHull(pts)
    except (QhullError, ValueError):  # flat or degenerate: let trimesh thicken it
        return trimesh.convex.convex_hull(pts)
    faces = h.simplices.copy()
    tri = pts[faces]
    n = cross_rows(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    flip = np.einsum("ij,ij->i", n, h.equations[:, :3]) < 0
    faces[flip] = faces[flip][:, ::-1]
    used, inv = np.unique(faces, return_inverse=True)
    return trimesh.Trimesh(pts[used], inv.reshape(-1, 3), process=False)


def _single(mesh: trimesh.Trimesh) -> Shape:
    return Shape(mesh, [mesh])


def hull(points) -> Shape:
    """The convex hull of ``points`` (N, 3) as a one-piece shape."""
    return _single(_convex(points))


def box(size, center=(0.0, 0.0, 0.0), bevel: float = 0.0, R=None) -> Shape:
    """An axis-aligned box, optionally with chamfered edges.

    Parameters
    ----------
    size : (3,) float, metres
        Full extents along x, y, z.
    center : (3,) float
        Box centre.
    bevel : float, metres
        Chamfer width on every edge (clamped to a third of the smallest extent).
    R : (3, 3) float, optional
        Rotation about the centre.
    """
    size = np.asarray(size, float)
    b = float(min(bevel, size.min() / 3.0))
    T = make_transform(R, center)
    if b <= 1e-6:
        return _single(_plain_box(size, T))
    v, f = _bevel_box_arrays(tuple(float(x) for x in size), b)
    return _single(_moved(v, f, None, T))


@lru_cache(maxsize=256)
def _bevel_box_arrays(size: tuple[float, float, float], b: float) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and faces (read-only) of the chamfered box ``size`` with chamfer ``b``, centred
    on the origin: repeated parts (legs, slats, drawer fronts) ask for the same one, and its
    convex hull costs far more than the copy."""
    h = np.asarray(size) / 2.0
    pts = []
    for sx in (-1, 1):
        for sy in (-1, 1):
            for sz in (-1, 1):
                c = np.array([sx * h[0], sy * h[1], sz * h[2]])
                pts.append(c - np.array([sx * b, 0, 0]))
                pts.append(c - np.array([0, sy * b, 0]))
                pts.append(c - np.array([0, 0, sz * b]))
    m = _convex(np.array(pts))
    v = np.asarray(m.vertices, float).view(np.ndarray).copy()
    f = np.asarray(m.faces, np.int64).view(np.ndarray).copy()
    v.flags.writeable = False
    f.flags.writeable = False
    return v, f


_I4 = np.eye(4)
_I3 = np.eye(3)
# trimesh's unit box (vertices, faces, face normals), read once
_BOX = trimesh.creation.box()
_BOX_V = np.asarray(_BOX.vertices, float).view(np.ndarray) + 0.5
_BOX_F = np.asarray(_BOX.faces, np.int64).view(np.ndarray).copy()
_BOX_N = np.asarray(_BOX.face_normals, float).view(np.ndarray).copy()


def _plain_box(size: np.ndarray, T: np.ndarray) -> trimesh.Trimesh:
    """``trimesh.creation.box(extents=size)`` moved by ``T`` (4, 4): the same vertices, faces
    and face normals, built directly instead of through a mesh's transform bookkeeping."""
    v = _BOX_V - 0.5
    v *= size
    return _moved(v, _BOX_F, _BOX_N, T)


def _moved(v: np.ndarray, f: np.ndarray, n: np.ndarray | None, T: np.ndarray) -> trimesh.Trimesh:
    """A new mesh of vertices ``v``, faces ``f`` and (optionally) face normals ``n`` moved by
    ``T`` (4, 4): what ``Trimesh.apply_transform`` gives, without its bookkeeping."""
    if not trimesh.util.allclose(T, _I4, 1e-8):
        v = trimesh.transformations.transform_points(v, T)
        if not trimesh.util.allclose(T[:3, :3], _I3, atol=1e-6):
            linear = T[:3, :3]
            adjugate = np.cross(linear.T[[1, 2, 0]], linear.T[[2, 0, 1]])
            if np.linalg.det(linear) < 0.0:
                adjugate = -adjugate
                f = np.ascontiguousarray(np.fliplr(f))
            if n is not None:
                n = trimesh.util.unitize(np.dot(n, adjugate), threshold=0)
    else:
        v = np.array(v)
    return trimesh.Trimesh(v, np.array(f), face_normals=None if n is None else np.array(n),
                           process=False)


@lru_cache(maxsize=256)
def _cylinder_arrays(radius: float, height: float, sections: int) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and faces of ``trimesh.creation.cylinder`` (read-only): repeated parts (legs,
    hinges, knobs, rods) ask for the same one, and building it costs far more than the copy."""
    m = trimesh.creation.cylinder(radius=radius, height=height, sections=sections)
    v = np.asarray(m.vertices, float).view(np.ndarray).copy()
    f = np.asarray(m.faces, np.int64).view(np.ndarray).copy()
    v.flags.writeable = False
    f.flags.writeable = False
    return v, f


def _axis_transform(axis, center) -> np.ndarray:
    R = rotation_between((0, 0, 1), axis) if axis is not None else np.eye(3)
    return make_transform(R, center)


def cylinder(radius: float, height: float, center=(0.0, 0.0, 0.0), axis=(0, 0, 1),
             sections: int = 24) -> Shape:
    """A closed cylinder centred at ``center`` along ``axis``."""
    v, f = _cylinder_arrays(float(radius), float(height), int(sections))
    return _single(_moved(v, f, None, _axis_transform(axis, center)))


def frustum(r_bottom: float, r_top: float, height: float, center=(0.0, 0.0, 0.0),
            axis=(0, 0, 1), sections: int = 24) -> Shape:
    """A truncated cone; ``center`` is the centre of its bottom disc."""
    a = np.linspace(0, 2 * np.pi, sections, endpoint=False)
    bot = np.c_[r_bottom * np.cos(a), r_bottom * np.sin(a), np.zeros_like(a)]
    top = np.c_[max(r_top, 1e-5) * np.cos(a), max(r_top, 1e-5) * np.sin(a), np.full_like(a, height)]
    m = _convex(np.vstack([bot, top]))
    m.apply_transform(_axis_transform(axis, center))
    return _single(m)


def ellipsoid(radii, center=(0.0, 0.0, 0.0), subdivisions: int = 2) -> Shape:
    """An ellipsoid with semi-axes ``radii`` (3,)."""
    m = trimesh.creation.icosphere(subdivisions=subdivisions, radius=1.0)
    m.apply_scale(np.asarray(radii, float))
    m.apply_translation(center)
    return _single(m)


def _ring(r: float, z: float, sections: int, phase: float = 0.0) -> np.ndarray:
    a = np.linspace(0, 2 * np.pi, sections, endpoint=False) + phase
    return np.c_[r * np.cos(a), r * np.sin(a), np.full(sections, z)]


def _revolve_closed(profile: np.ndarray, sections: int) -> trimesh.Trimesh:
    """Revolve a closed (r, z) polygon (counter-clockwise in the r-z plane) about +Z."""
    n = len(profile)
    a = np.linspace(0, 2 * np.pi, sections, endpoint=False)
    verts = []
    for r, z in profile:
        verts.append(np.c_[r * np.cos(a), r * np.sin(a), np.full(sections, z)])
    verts = np.vstack(verts)
    faces = []
    for i in range(n):
        j = (i + 1) % n
        for k in range(sections):
            k2 = (k + 1) % sections
            a0, a1 = i * sections + k, i * sections + k2
            b0, b1 = j * sections + k, j * sections + k2
            faces.append([a0, b0, a1])
            faces.append([a1, b0, b1])
    m = trimesh.Trimesh(verts, np.array(faces), process=True)
    m.merge_vertices()
    m.update_faces(m.nondegenerate_faces())
    m.remove_unreferenced_vertices()
    trimesh.repair.fix_normals(m)
    return m


def lathe(profile: Sequence[tuple[float, float]], sections: int = 32) -> Shape:
    """A solid of revolution about +Z from a radius profile ``[(r, z), ...]`` (z increasing).

    The solid is the region between the axis and the profile, so it decomposes exactly into
    stacked frustums (one convex piece per profile segment). Use for lamp bases, pedestals,
    bottles, vases seen as solids, apples.
    """
    prof = np.asarray(profile, float)
    if np.any(np.diff(prof[:, 1]) < 0):
        raise ValueError("lathe profile must have non-decreasing z")
    closed = [(0.0, prof[0, 1])] + [(max(r, 1e-4), z) for r, z in prof] + [(0.0, prof[-1, 1])]
    # counter-clockwise in (r, z): axis bottom -> outer profile upwards -> axis top
    mesh = _revolve_closed(np.array(closed[::-1]), sections)
    if mesh.volume < 0:
        mesh.invert()
    pieces = []
    for (r0, z0), (r1, z1) in zip(prof[:-1], prof[1:], strict=True):
        if z1 - z0 < 1e-6:
            continue
        pts = np.vstack([_ring(max(r0, 1e-4), z0, sections), _ring(max(r1, 1e-4), z1, sections)])
        pieces.append(_convex(pts))
    return Shape(mesh, pieces)


def vessel(outer: Sequence[tuple[float, float]], thickness: float, bottom: float | None = None,
           sections: int = 32, piece_sections: int = 16) -> Shape:
    """An open-topped container of revolution (cup, bowl, pot, vase, bucket, bathtub-like).

    Parameters
    ----------
    outer : sequence of (r, z)
        Outer wall profile from the outer bottom rim (z = 0 or above) up to the lip, z increasing.
    thickness : float
        Wall thickness (measured radially).
    bottom : float, optional
        Bottom thickness (defaults to ``thickness``).
    sections : int
        Angular resolution of the visual mesh.
    piece_sections : int
        Angular resolution of the convex decomposition: each wall band is split into this many
        convex segments, plus one convex bottom disc.
    """
    out = np.asarray(outer, float)
    bottom = thickness if bottom is None else bottom
    z0 = out[0, 1]
    inner = out.copy()
    inner[:, 0] = np.maximum(out[:, 0] - thickness, 1e-3)
    inner = inner[inner[:, 1] >= z0 + bottom - 1e-9]
    if len(inner) == 0 or inner[0, 1] > z0 + bottom + 1e-9:
        r_at = np.interp(z0 + bottom, out[:, 1], out[:, 0]) - thickness
        inner = np.vstack([[max(r_at, 1e-3), z0 + bottom], inner])
    # closed profile, counter-clockwise in (r, z): axis bottom, outer up, lip, inner down, axis
    prof = [(0.0, z0)] + [tuple(p) for p in out] + [tuple(p) for p in inner[::-1]] + [(0.0, z0 + bottom)]
    mesh = _revolve_closed(np.array(prof), sections)
    if mesh.volume < 0:
        mesh.invert()
    pieces = []
    # bottom disc
    rb = out[0, 0]
    pieces.append(_convex(np.vstack([_ring(rb, z0, sections), _ring(rb, z0 + bottom, sections)])))
    # wall bands x sectors: each (outer arc and inner chord at two heights) is convex. The outer
    # arc follows the visual mesh's own vertices, so the pieces never stick out of the wall.
    per = max(1, sections // piece_sections)
    full = np.linspace(0, 2 * np.pi, sections, endpoint=False)
    zs = np.unique(np.concatenate([out[:, 1], [z0 + bottom]]))
    zs = zs[zs >= z0 + bottom - 1e-9]
    for za, zb in zip(zs[:-1], zs[1:], strict=True):
        ro_a, ro_b = np.interp([za, zb], out[:, 1], out[:, 0])
        ri_a, ri_b = max(ro_a - thickness, 1e-3), max(ro_b - thickness, 1e-3)
        for k in range(0, sections, per):
            idx = [(k + j) % sections for j in range(per + 1)]
            a = full[idx]
            a_in = full[[idx[0], idx[-1]]]
            pts = [np.c_[r * np.cos(a), r * np.sin(a), np.full(len(a), z)]
                   for r, z in ((ro_a, za), (ro_b, zb))]
            pts += [np.c_[r * np.cos(a_in), r * np.sin(a_in), np.full(2, z)]
                    for r, z in ((ri_a, za), (ri_b, zb))]
            pieces.append(_convex(np.vstack(pts)))
    return Shape(mesh, pieces)


def tube(path, radius: float, sections: int = 10, closed: bool = False) -> Shape:
    """A round tube of ``radius`` along a polyline ``path`` (N, 3), capped at its ends.

    One convex piece per segment. Use for handles, frames, rails, poles, hooks, cords.
    """
    path = np.asarray(path, float)
    if closed:
        path = np.vstack([path, path[:1]])
    n = len(path)
    tang = np.zeros_like(path)
    tang[1:-1] = path[2:] - path[:-2]
    tang[0] = path[1] - path[0]
    tang[-1] = path[-1] - path[-2]
    if closed:
        tang[0] = tang[-1] = path[1] - path[-2]
    tang /= np.linalg.norm(tang, axis=1, keepdims=True)
    # parallel transport of a normal frame
    ref = np.array([0, 0, 1.0]) if abs(tang[0][2]) < 0.9 else np.array([1.0, 0, 0])
    nrm = np.cross(tang[0], ref)
    nrm /= np.linalg.norm(nrm)
    a = np.linspace(0, 2 * np.pi, sections, endpoint=False)
    rings = []
    for i in range(n):
        t = tang[i]
        nrm = nrm - np.dot(nrm, t) * t
        nrm /= np.linalg.norm(nrm)
        bin_ = np.cross(t, nrm)
        rings.append(path[i] + radius * (np.outer(np.cos(a), nrm) + np.outer(np.sin(a), bin_)))
    rings = np.array(rings)
    pieces = [_convex(np.vstack([rings[i], rings[i + 1]])) for i in range(n - 1)]
    verts = rings.reshape(-1, 3)
    faces = []
    for i in range(n - 1):
        for k in range(sections):
            k2 = (k + 1) % sections
            a0, a1 = i * sections + k, i * sections + k2
            b0, b1 = (i + 1) * sections + k, (i + 1) * sections + k2
            faces += [[a0, a1, b0], [a1, b1, b0]]
    if not closed:
        c0 = len(verts)
        c1 = c0 + 1
        verts = np.vstack([verts, path[0], path[-1]])
        last = (n - 1) * sections
        for k in range(sections):
            k2 = (k + 1) % sections
            faces.append([c0, k2, k])
            faces.append([c1, last + k, last + k2])
    mesh = trimesh.Trimesh(verts, np.array(faces), process=True)
    if closed:
        mesh.merge_vertices()
    trimesh.repair.fix_normals(mesh)
    return Shape(mesh, pieces)


def prism(polygon, z0: float, z1: float) -> Shape:
    """A vertical prism over a convex 2D polygon ``(N, 2)`` from ``z0`` to ``z1``."""
    p = np.asarray(polygon, float)
    pts = np.vstack([np.c_[p, np.full(len(p), z0)], np.c_[p, np.full(len(p), z1)]])
    return hull(pts)


def union(shapes: Sequence[Shape]) -> Shape:
    """Concatenate shapes into one (meshes appended, pieces kept)."""
    shapes = list(shapes)
    mesh = trimesh.util.concatenate([s.mesh for s in shapes])
    pieces = [p for s in shapes for p in s.pieces]
    return Shape(mesh, pieces)


def transformed(shape: Shape, T: np.ndarray) -> Shape:
    """A copy of ``shape`` moved by the (4, 4) transform ``T``."""
    m = shape.mesh.copy()
    m.apply_transform(T)
    ps = []
    for p in shape.pieces:
        q = p.copy()
        q.apply_transform(T)
        ps.append(q)
    return Shape(m, ps)
