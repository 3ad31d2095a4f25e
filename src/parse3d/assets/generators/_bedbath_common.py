"""Shared builders for bedroom, seating and bathroom generators.

Cabinet carcasses, drawers, doors, handles, legs and rounded cushions, all in the asset's
canonical frame (+Z up, front +Y, metres). Every builder returns a :class:`Shape` whose convex
pieces cover its mesh exactly (boxes, hulls) or closely (tubes).
"""

from __future__ import annotations

import numpy as np
import trimesh

from ...geometry import shapes as S

__all__ = ["carcass", "carcass_panels", "CARCASS_GROUP", "drawer_shape", "bar_handle", "knob", "cushion", "soft_hull", "scaled",
           "post", "rounded_rect", "loft", "bevel_box"]


def scaled(shape: S.Shape, sx: float, sy: float, sz: float, offset=(0.0, 0.0, 0.0)) -> S.Shape:
    """``shape`` scaled about the origin by positive factors, then moved by ``offset``.

    Affine maps keep convex pieces convex, so the decomposition stays exact.
    """
    T = np.diag([sx, sy, sz, 1.0])
    T[:3, 3] = offset
    return shape.apply(T)


def carcass(w: float, d: float, h: float, t: float, *, z0: float = 0.0, top: bool = True,
            back: bool = True, dividers: tuple[float, ...] = ()) -> S.Shape:
    """An open-fronted cabinet box: two sides, bottom, optional top and back panel.

    Parameters
    ----------
    w, d, h : float, metres
        Outer width (x), depth (y) and height (z); centred on x = y = 0, bottom at ``z0``.
    t : float, metres
        Panel thickness.
    dividers : tuple of float
        x positions of full-height vertical partitions.
    """
    zc = z0 + h / 2
    parts = [
        S.box((t, d, h), center=(-w / 2 + t / 2, 0, zc)),
        S.box((t, d, h), center=(w / 2 - t / 2, 0, zc)),
        S.box((w - 2 * t, d, t), center=(0, 0, z0 + t / 2)),
    ]
    if top:
        parts.append(S.box((w - 2 * t, d, t), center=(0, 0, z0 + h - t / 2)))
    if back:
        zb = z0 + t if top else z0 + t
        hb = h - 2 * t if top else h - t
        parts.append(S.box((w - 2 * t, t * 0.6, hb), center=(0, -d / 2 + t * 0.3, zb + hb / 2)))
    for x in dividers:
        inner_h = h - 2 * t if top else h - t
        parts.append(S.box((t, d - t * 0.6, inner_h),
                           center=(x, t * 0.3, z0 + t + inner_h / 2)))
    return S.union(parts)


#: The group label ``body`` of a carcass built from :func:`carcass_panels`: the panels together
#: are the old one-piece ``body``, so ``body``, ``body@top`` and the like name the same geometry.
CARCASS_GROUP = {"body": ("side_panel", "bottom_panel", "back_panel", "top_board", "partition")}


def carcass_panels(w: float, d: float, h: float, t: float, mat, *, z0: float = 0.0, top: bool = True,
                   back: bool = True, dividers: tuple[float, ...] = ()) -> list:
    """The panels of :func:`carcass` (same arguments, same geometry), each a part of its own:
    ``side_panel_0`` (left) and ``side_panel_1`` (right), the bottom (named ``body``, as the
    part doors and drawers hang on, label ``bottom_panel``), the ``top_board`` with ``top``,
    the ``back_panel`` with ``back`` and a ``partition`` at each of ``dividers``. Register the
    category with ``groups=CARCASS_GROUP`` so ``body`` covers them all.
    """
    from ..model import make_part

    zc = z0 + h / 2
    out = [make_part("side_panel_0", "side_panel", S.box((t, d, h), center=(-w / 2 + t / 2, 0, zc)), mat),
           make_part("side_panel_1", "side_panel", S.box((t, d, h), center=(w / 2 - t / 2, 0, zc)), mat),
           make_part("body", "bottom_panel", S.box((w - 2 * t, d, t), center=(0, 0, z0 + t / 2)), mat)]
    if top:
        out.append(make_part("top_board", "top_board",
                             S.box((w - 2 * t, d, t), center=(0, 0, z0 + h - t / 2)), mat))
    inner_h = h - 2 * t if top else h - t
    if back:
        out.append(make_part("back_panel", "back_panel",
                             S.box((w - 2 * t, t * 0.6, inner_h), center=(0, -d / 2 + t * 0.3, z0 + t + inner_h / 2)),
                             mat))
    for k, x in enumerate(dividers):
        out.append(make_part(f"partition_{k}", "partition",
                             S.box((t, d - t * 0.6, inner_h), center=(x, t * 0.3, z0 + t + inner_h / 2)), mat))
    return out


def drawer_shape(x: float, z: float, w: float, h: float, y_front: float, depth: float, *,
                 front_t: float = 0.018, bevel: float = 0.004) -> S.Shape:
    """A closed drawer: a bevelled front (outer face at ``y_front``) and the box behind it.

    ``(x, z)`` is the centre of the front; the box is slightly smaller than the front.
    """
    front = bevel_box((w, front_t, h), center=(x, y_front - front_t / 2, z), bevel=bevel)
    bd = max(depth - front_t, 0.05)
    box_ = S.box((w - 0.03, bd, h - 0.03), center=(x, y_front - front_t - bd / 2, z))
    return S.union([front, box_])


def bar_handle(center, length: float, *, vertical: bool = False, standoff: float = 0.028,
               radius: float = 0.006, sections: int = 8) -> S.Shape:
    """A bow handle on a front face: ``center`` (3,) lies on the face (y = face plane)."""
    c = np.asarray(center, float)
    e = np.array([0, 0, 1.0]) if vertical else np.array([1.0, 0, 0])
    out = np.array([0, 1.0, 0])
    a, b = c - e * length / 2, c + e * length / 2
    path = [a - out * 0.004, a + out * standoff, b + out * standoff, b - out * 0.004]
    return S.tube(path, radius, sections=sections)


def knob(center, *, radius: float = 0.014, reach: float = 0.028) -> S.Shape:
    """A mushroom knob on a front face at ``center`` (3,), sticking out along +Y."""
    c = np.asarray(center, float)
    stem = S.frustum(radius * 0.45, radius * 0.55, reach * 0.6, center=c - [0, 0.003, 0],
                     axis=(0, 1, 0), sections=10)
    cap = S.cylinder(radius, reach * 0.45, center=c + [0, reach * 0.75, 0], axis=(0, 1, 0),
                     sections=14)
    return S.union([stem, cap])


def rounded_rect(w: float, d: float, r: float, n: int = 4) -> np.ndarray:
    """(4 (n + 1), 2) outline of a w x d rectangle with corner radius ``r``, counter-clockwise.

    The point count and edge directions depend only on ``n``, so outlines of different sizes
    stacked by :func:`loft` give planar side faces.
    """
    return _rounded_rects(np.array([w]), np.array([d]), np.array([r]), n)[0]


def _rounded_rects(w: np.ndarray, d: np.ndarray, r: np.ndarray, n: int) -> np.ndarray:
    """(K, 4 (n + 1), 2) outlines for K (w, d, r) triples at once."""
    r = np.clip(r, 1e-4, np.minimum(w, d) / 2 - 1e-5)[:, None]
    a = np.concatenate([q * np.pi / 2 + np.linspace(0, np.pi / 2, n + 1) for q in range(4)])
    sx = np.repeat([1.0, -1.0, -1.0, 1.0], n + 1)
    sy = np.repeat([1.0, 1.0, -1.0, -1.0], n + 1)
    cx = sx * (w[:, None] / 2 - r)
    cy = sy * (d[:, None] / 2 - r)
    return np.stack([cx + r * np.cos(a), cy + r * np.sin(a)], axis=-1)


def loft(rings: list[np.ndarray]) -> trimesh.Trimesh:
    """A closed mesh through stacked horizontal rings (each (M, 3), same M, bottom to top,
    counter-clockwise seen from above).

    The bands between rings are quads and both ends are capped with fans; the result is
    watertight. With convex rings whose edges keep their directions from ring to ring and a
    convex vertical profile the solid is convex.
    """
    m = len(rings[0])
    verts = np.vstack(rings)
    k = np.arange(m)
    k2 = (k + 1) % m
    faces = []
    for i in range(len(rings) - 1):
        a0, a1, b0, b1 = i * m + k, i * m + k2, (i + 1) * m + k, (i + 1) * m + k2
        faces.append(np.c_[a0, a1, b1])
        faces.append(np.c_[a0, b1, b0])
    top = (len(rings) - 1) * m
    fan = np.arange(1, m - 1)
    faces.append(np.c_[np.zeros(m - 2, int), fan + 1, fan])
    faces.append(np.c_[np.full(m - 2, top), top + fan, top + fan + 1])
    # rings run counter-clockwise seen from above, so these faces point outwards
    return trimesh.Trimesh(verts, np.vstack(faces), process=False)


def bevel_box(size, center=(0.0, 0.0, 0.0), bevel: float = 0.005) -> S.Shape:
    """An axis-aligned box with chamfered edges, built directly (no convex hull: fast).

    Same role as :func:`parse3d.geometry.shapes.box` with ``bevel``; one convex piece.
    """
    w, d, h = (float(x) for x in size)
    b = float(min(bevel, min(w, d, h) / 3.0))
    if b <= 1e-5:
        return S.box(size, center=center)
    inset = np.array([b, 0.0, 0.0, b])
    z = np.array([-h / 2, -h / 2 + b, h / 2 - b, h / 2])
    outs = _rounded_rects(w - 2 * inset, d - 2 * inset, np.maximum(b - inset, 1e-4), 1)
    pts = np.concatenate([outs, np.broadcast_to(z[:, None, None], (4, 8, 1))], axis=-1)
    rings = list(pts + np.asarray(center, float))
    mesh = loft(rings)
    return S.Shape(mesh, [mesh])


def cushion(w: float, d: float, h: float, center, *, round_xy: float = 0.04,
            round_z: float | None = None, n: int = 2) -> S.Shape:
    """An upholstered cushion: a box with rounded vertical corners and rounded top/bottom edges.

    One convex piece (a loft of rounded-rectangle outlines). ``center`` is the centre of the
    cushion's bounding box.
    """
    rz = min(round_z if round_z is not None else h * 0.3, h / 2 - 1e-4, w / 4, d / 4)
    a = -np.pi / 2 + np.pi / 2 * np.arange(n + 1) / n
    inset = rz * (1 - np.cos(a))
    z = -h / 2 + rz * (1 + np.sin(a))
    inset = np.concatenate([inset, inset[::-1]])
    z = np.concatenate([z, -z[::-1]])
    outs = _rounded_rects(w - 2 * inset, d - 2 * inset, np.maximum(round_xy - inset, 1e-3), 3)
    m = outs.shape[1]
    pts = np.concatenate([outs, np.broadcast_to(z[:, None, None], (len(z), m, 1))], axis=-1)
    mesh = loft(list(pts + np.asarray(center, float)))
    return S.Shape(mesh, [mesh])


def soft_hull(radii, center=(0.0, 0.0, 0.0), *, power: float = 3.0, flat: float = 0.25,
              n_u: int = 24, n_v: int = 8) -> S.Shape:
    """A superellipsoid-like soft solid (pillow, bolster) with a flattened bottom.

    One convex piece. The horizontal outline is a superellipse; the bottom is cut flat at
    ``flat`` of the lower half so the solid stands on a surface.

    Parameters
    ----------
    radii : (3,) float, metres
        Semi-axes.
    power : float
        Squareness of the horizontal outline (2 = ellipse, larger = boxier).
    flat : float in [0, 1)
        How much of the lower half is cut off flat.
    """
    rx, ry, rz = radii
    u = np.linspace(0, 2 * np.pi, n_u, endpoint=False)
    cu, su = np.cos(u), np.sin(u)
    ex = 2.0 / power
    ox = np.sign(cu) * np.abs(cu) ** ex
    oy = np.sign(su) * np.abs(su) ** ex
    v0 = np.arcsin(-(1.0 - flat))
    rings = []
    for v in np.linspace(v0, np.pi / 2 * 0.93, n_v):
        s = np.cos(v) ** 0.6
        rings.append(np.c_[rx * s * ox, ry * s * oy, np.full(n_u, rz * np.sin(v))])
    mesh = loft(rings)
    mesh.apply_translation(np.asarray(center, float))
    return S.Shape(mesh, [mesh])


def post(x: float, y: float, z0: float, z1: float, size: float, *, turned: bool = False,
         bevel: float = 0.004) -> S.Shape:
    """A vertical post (square bevelled box, or a round tapered turning) from z0 to z1."""
    if turned:
        return S.frustum(size / 2, size * 0.38, z1 - z0, center=(x, y, z0), sections=12)
    return bevel_box((size, size, z1 - z0), center=(x, y, (z0 + z1) / 2), bevel=bevel)
