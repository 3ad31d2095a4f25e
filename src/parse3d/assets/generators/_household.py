"""Building blocks shared by the tableware, kitchenware, container and grocery generators.

Everything is built in the asset's canonical frame (metres, +Z up, front +Y) and returns
:class:`~parse3d.geometry.shapes.Shape` objects that carry exact convex pieces.
"""

from __future__ import annotations

import numpy as np
import trimesh

from ...geometry import shapes as S

__all__ = ["ring", "shell", "arc", "loop_handle", "open_box"]


def ring(section, *, sections: int = 24, piece_sections: int | None = None) -> S.Shape:
    """A ring of revolution about +Z swept from a convex cross-section.

    Parameters
    ----------
    section : (N, 2) float, metres
        Convex polygon in the (r, z) half-plane, r > 0 everywhere (the ring does not touch the
        axis), in any orientation.
    sections : int
        Angular resolution of the mesh.
    piece_sections : int, optional
        Number of convex pieces around the ring (defaults to ``sections``: exact pieces).

    Returns
    -------
    Shape
        A watertight torus-like mesh; each piece is the hull of consecutive angular copies of
        the section, so the pieces hug the mesh (exactly when ``piece_sections == sections``).
    """
    sec = _ccw(section)
    verts = _copies(sec, sections)
    mesh = _revolve_mesh(sec, verts)
    per = max(1, sections // (piece_sections or sections))
    return S.Shape(mesh, _wedges(sec, verts, per))


def _ccw(section) -> np.ndarray:
    sec = np.asarray(section, float)
    x, y = sec[:, 0], sec[:, 1]
    if (x * np.roll(y, -1) - np.roll(x, -1) * y).sum() < 0:
        sec = sec[::-1]  # counter-clockwise in (r, z)
    return sec


def _copies(sec: np.ndarray, sections: int) -> np.ndarray:
    """(sections, N, 3) copies of the (r, z) polygon rotated about +Z."""
    a = np.linspace(0, 2 * np.pi, sections, endpoint=False)
    return np.stack([sec[None, :, 0] * np.cos(a)[:, None], sec[None, :, 0] * np.sin(a)[:, None],
                     np.broadcast_to(sec[None, :, 1], (sections, len(sec)))], axis=-1)


def _revolve_mesh(sec: np.ndarray, verts: np.ndarray) -> trimesh.Trimesh:
    """Watertight surface of revolution of a simple polygon that stays off the axis."""
    sections, n = verts.shape[:2]
    k = np.arange(sections)[:, None]
    i = np.arange(n)[None, :]
    k2, i2 = (k + 1) % sections, (i + 1) % n
    v00, v01, v10, v11 = k * n + i, k * n + i2, k2 * n + i, k2 * n + i2
    faces = np.concatenate([np.stack([v00, v10, v11], -1).reshape(-1, 3),
                            np.stack([v00, v11, v01], -1).reshape(-1, 3)])
    mesh = trimesh.Trimesh(verts.reshape(-1, 3), faces, process=False)
    if mesh.volume < 0:
        mesh.invert()
    return mesh


def _wedges(sec: np.ndarray, verts: np.ndarray, per: int) -> list[trimesh.Trimesh]:
    """Convex pieces of a ring with a convex section: the wedges between angular copies."""
    sections, n = verts.shape[:2]
    if per > 1:
        return [trimesh.convex.convex_hull(verts[[(k0 + j) % sections for j in range(per + 1)]]
                                           .reshape(-1, 3)) for k0 in range(0, sections, per)]
    # each piece is the wedge between two consecutive copies of the section: two caps and the
    # side quads, built directly (a convex hull per piece would be far slower)
    fan = np.array([[0, j + 1, j] for j in range(1, n - 1)])
    side = np.array([[j, (j + 1) % n, n + (j + 1) % n] for j in range(n)]
                    + [[j, n + (j + 1) % n, n + j] for j in range(n)])
    pf = np.vstack([fan[:, ::-1], fan + n, side[:, ::-1]])
    if trimesh.Trimesh(np.vstack([verts[0], verts[1]]), pf, process=False).volume < 0:
        pf = pf[:, ::-1]
    return [trimesh.Trimesh(np.vstack([verts[k0], verts[(k0 + 1) % sections]]), pf, process=False)
            for k0 in range(sections)]


def arc(center, radius: float, a0: float, a1: float, *, n: int = 9, u=(1.0, 0.0, 0.0),
        v=(0.0, 0.0, 1.0), squash: float = 1.0) -> np.ndarray:
    """Points on a circular (or squashed) arc, for handle and spout paths.

    Parameters
    ----------
    center : (3,) float
        Arc centre, metres.
    radius : float
        Radius along ``u``; the radius along ``v`` is ``radius * squash``.
    a0, a1 : float, radians
        Start and end angles measured from ``u`` towards ``v``.
    u, v : (3,) float
        Orthonormal in-plane axes.

    Returns
    -------
    (n, 3) float
    """
    t = np.linspace(a0, a1, n)
    c, u, v = (np.asarray(x, float) for x in (center, u, v))
    return c + radius * np.cos(t)[:, None] * u + radius * squash * np.sin(t)[:, None] * v


def loop_handle(root, direction, *, reach: float, width: float, thick: float,
                z_up: bool = False, n: int = 7) -> S.Shape:
    """A side handle: a U-shaped tube leaving a wall at ``root`` along ``direction``.

    Parameters
    ----------
    root : (3,) float
        Midpoint where the handle meets the wall, metres (the legs start slightly inside it).
    direction : (3,) float
        Horizontal outward direction.
    reach : float
        How far the loop sticks out, metres.
    width : float
        Distance between the two legs, metres (measured horizontally, or vertically when
        ``z_up`` is set: a vertical loop such as a teapot handle).
    thick : float
        Tube radius, metres.
    """
    d = np.asarray(direction, float)
    d = d / np.linalg.norm(d)
    side = np.array([0.0, 0.0, 1.0]) if z_up else np.cross([0.0, 0.0, 1.0], d)
    root = np.asarray(root, float) - d * thick
    t = np.linspace(-np.pi / 2, np.pi / 2, n)
    path = root + np.outer(np.cos(t) * (reach + thick), d) + np.outer(np.sin(t) * width / 2, side)
    return S.tube(path, thick, sections=8)


def open_box(w: float, d: float, h: float, t: float, *, bottom: float | None = None,
             taper: float = 0.0, bevel: float = 0.0) -> list[S.Shape]:
    """Four walls and a floor of an open-topped box centred on the z axis, standing on z = 0.

    Parameters
    ----------
    w, d, h : float
        Outer width (x), depth (y) and height (z) at the bottom, metres.
    t : float
        Wall thickness.
    bottom : float, optional
        Floor thickness (defaults to ``t``).
    taper : float
        How much each wall leans outwards over the height, metres (0 = straight box).
    bevel : float
        Edge chamfer of straight walls.
    """
    b = t if bottom is None else bottom
    if taper <= 0:
        return [
            S.box((w, t, h), center=(0, d / 2 - t / 2, h / 2), bevel=bevel),
            S.box((w, t, h), center=(0, -d / 2 + t / 2, h / 2), bevel=bevel),
            S.box((t, d - 2 * t, h), center=(w / 2 - t / 2, 0, h / 2), bevel=bevel),
            S.box((t, d - 2 * t, h), center=(-w / 2 + t / 2, 0, h / 2), bevel=bevel),
            S.box((w - 2 * t, d - 2 * t, b), center=(0, 0, b / 2)),
        ]
    g = taper
    hw, hd = w / 2, d / 2
    walls = [
        _lean_slab([(-hw, hd - t), (hw, hd - t), (hw, hd), (-hw, hd)], (0, 1), g, h, w_span=True),
        _lean_slab([(-hw, -hd), (hw, -hd), (hw, -hd + t), (-hw, -hd + t)], (0, -1), g, h,
                   w_span=True),
        _lean_slab([(hw - t, -hd + t), (hw, -hd + t), (hw, hd - t), (hw - t, hd - t)], (1, 0), g, h),
        _lean_slab([(-hw, -hd + t), (-hw + t, -hd + t), (-hw + t, hd - t), (-hw, hd - t)], (-1, 0),
                   g, h),
        S.box((w - 2 * t, d - 2 * t, b), center=(0, 0, b / 2)),
    ]
    return walls


def _lean_slab(quad, outward, grow: float, h: float, *, w_span: bool = False) -> S.Shape:
    """A wall slab (footprint ``quad`` at z = 0) pushed ``grow`` outwards at its top; its ends
    spread with the neighbouring walls so the corners stay closed."""
    q = np.asarray(quad, float)
    o = np.asarray(outward, float)
    top = q + o * grow
    # spread the ends along the wall so the corners of the tapered box stay closed
    along = np.array([1.0, 0.0]) if w_span else np.array([0.0, 1.0])
    s = np.sign((q - q.mean(axis=0)) @ along)
    top = top + np.outer(s, along) * grow
    pts = np.vstack([np.c_[q, np.zeros(4)], np.c_[top, np.full(4, h)]])
    return S.hull(pts)


def shell(outer, thickness: float, *, bottom: float | None = None, sections: int = 24) -> S.Shape:
    """An open-topped vessel of revolution built from a floor disc and stacked wall rings.

    Same role as :func:`parse3d.geometry.shapes.vessel`, but every wall band is a
    :func:`ring` whose convex pieces are built directly (no convex hull per piece), which
    makes it several times faster; the pieces match the mesh exactly.

    Parameters
    ----------
    outer : sequence of (r, z), metres
        Outer wall profile from the outer bottom rim up to the lip, z increasing.
    thickness : float
        Radial wall thickness.
    bottom : float, optional
        Floor thickness (defaults to ``thickness``).
    sections : int
        Angular resolution (and number of pieces per wall band).
    """
    out = np.asarray(outer, float)
    b = thickness if bottom is None else bottom
    z0 = out[0, 1]
    zf = z0 + b

    def ro(z: float) -> float:
        return float(np.interp(z, out[:, 1], out[:, 0]))

    def ri(z: float) -> float:
        return max(ro(z) - thickness, 1e-3)

    r_floor = ri(zf)
    # the floor disc never reaches past the outer wall (a flared bowl is narrower at z0)
    r_base = min(r_floor, ro(z0))
    floor = S.frustum(r_base, r_floor, b, center=(0, 0, z0), sections=sections)
    zs = np.unique(np.concatenate([out[:, 1], [zf]]))
    zs = zs[zs > zf + 1e-9]
    pieces = list(floor.pieces)
    outer_pts = [(ro(z0), z0)] + [(ro(z), z) for z in zs]
    inner_pts = [(ri(z), z) for z in zs[::-1]] + [(r_floor, zf)]
    for k, zb in enumerate(zs):
        if k == 0:
            # the first band also wraps the floor's rim: its inner edge drops to the floor
            sec = [(ro(z0), z0), (ro(zb), zb), (ri(zb), zb), (r_floor, zf)]
            if r_base < ro(z0) - 1e-9:
                sec.append((r_base, z0))
        else:
            za = zs[k - 1]
            sec = [(ro(za), za), (ro(zb), zb), (ri(zb), zb), (ri(za), za)]
        sec = _ccw(sec)
        pieces += _wedges(sec, _copies(sec, sections), 1)
    # one surface for the whole wall, so no hidden faces lie between the bands
    wall = _ccw(outer_pts + inner_pts + ([(r_base, z0)] if r_base < ro(z0) - 1e-9 else []))
    wall_mesh = _revolve_mesh(wall, _copies(wall, sections))
    return S.Shape(trimesh.util.concatenate([floor.mesh, wall_mesh]), pieces)
