"""Lamps: floor lamps (straight, arc, tripod), table lamps and pendant lamps.

Lamp bodies are revolved (``lathe``) solids; shades are open shells of revolution built by
:func:`shell`, whose convex pieces are the exact wall cells, so collision volume matches the
visual shell. Pendant lamps hang from a flat ``canopy`` at the asset's top.
"""

from __future__ import annotations

import numpy as np
import trimesh

from ...geometry import shapes as S
from ...geometry.frames import rot_x
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring

__all__ = ["shell", "shade_material", "bulb_material"]

_SHADE_COLOURS = [(0.93, 0.90, 0.82), (0.97, 0.96, 0.93), (0.62, 0.60, 0.56), (0.18, 0.18, 0.19),
                  (0.80, 0.72, 0.58), (0.45, 0.55, 0.60)]


def shade_material(rng: np.random.Generator) -> Material:
    """A linen or paper lampshade colour."""
    c = _SHADE_COLOURS[int(rng.integers(len(_SHADE_COLOURS)))]
    return Material(M.jitter(rng, c, 0.02), 0.9, 0.0, "fabric")


def bulb_material() -> Material:
    """Frosted warm-white glass of a light bulb."""
    return Material((1.0, 0.97, 0.86, 1.0), 0.1, 0.0, "glass")


def shell(outer, thickness: float, *, sections: int = 24, linear=None, offset=None) -> S.Shape:
    """An open-ended shell of revolution about +Z: a lampshade, a ring, a rim.

    Parameters
    ----------
    outer : sequence of (r, z), metres
        Outer wall profile, z non-decreasing, every r > ``thickness``.
    thickness : float, metres
        Wall thickness, measured radially inwards.
    sections : int
        Angular resolution. Every wall cell (one profile segment by one angular sector) is one
        convex piece, so the pieces tile the shell exactly.
    linear : (3, 3) float, optional
        Linear map (rotation, stretch) applied to the shell about the origin, before ``offset``;
        cheaper than moving the finished shape.
    offset : (3,) float, metres, optional
        Translation applied last.

    Returns
    -------
    Shape
        Watertight shell with ``(len(outer) - 1) * sections`` convex pieces.
    """
    out = np.asarray(outer, float)
    inn = out.copy()
    inn[:, 0] -= thickness
    prof = np.vstack([out, inn[::-1]])  # closed loop: outer upwards, inner downwards
    n = len(prof)
    a = np.linspace(0, 2 * np.pi, sections, endpoint=False)
    ca, sa = np.cos(a), np.sin(a)
    verts = np.concatenate([np.c_[r * ca, r * sa, np.full(sections, z)] for r, z in prof])
    if linear is not None:
        verts = verts @ np.asarray(linear, float).T
    if offset is not None:
        verts = verts + np.asarray(offset, float)
    i = np.repeat(np.arange(n), sections)
    k = np.tile(np.arange(sections), n)
    a0 = i * sections + k
    a1 = i * sections + (k + 1) % sections
    b0 = ((i + 1) % n) * sections + k
    b1 = ((i + 1) % n) * sections + (k + 1) % sections
    faces = np.concatenate([np.c_[a0, b0, a1], np.c_[a1, b0, b1]])
    mesh = trimesh.Trimesh(verts, faces, process=False)
    if mesh.volume < 0:
        mesh.invert()
    m = len(out)
    grid = verts.reshape(n, sections, 3)
    side = np.c_[np.arange(sections), (np.arange(sections) + 1) % sections]  # (sections, 2)
    corners = []
    for j in range(m - 1):
        if np.abs(out[j + 1] - out[j]).max() < 1e-7:
            continue
        loop = grid[[j, j + 1, 2 * m - 2 - j, 2 * m - 1 - j]]  # outer j, j+1, inner j+1, j
        corners.append(loop[:, side].transpose(1, 0, 2, 3))  # (sections, 4, 2, 3)
    pieces = _cells(np.concatenate(corners)) if corners else []
    return S.Shape(mesh, pieces)


# faces of a hexahedral wall cell: vertex (row, side) -> 2 * row + side, rows in a closed loop
_CELL_FACES = np.array([[0, 2, 1], [1, 2, 3], [2, 4, 3], [3, 4, 5], [4, 6, 5], [5, 6, 7],
                        [6, 0, 7], [7, 0, 1], [0, 4, 2], [0, 6, 4], [1, 3, 5], [1, 5, 7]])


def _cells(corners: np.ndarray) -> list[trimesh.Trimesh]:
    """Convex wall cells from (N, 4 loop rows, 2 angular sides, 3) corner points, all with the
    same handedness (so one orientation test serves them all)."""
    faces = _CELL_FACES
    first = trimesh.Trimesh(corners[0].reshape(8, 3), faces, process=False)
    if first.volume < 0:
        faces = faces[:, ::-1]
    return [trimesh.Trimesh(c.reshape(8, 3), faces, process=False) for c in corners]


def _hood(prof, thickness: float, top, *, sections: int = 20) -> S.Shape:
    """A shade open at the bottom and closed at the top: ``prof`` (r, z) is built upwards from
    its closed end at z = 0, then turned upside down so that end's centre sits at ``top`` (3,)."""
    top = np.asarray(top, float)
    r0 = prof[0][0]
    cap = S.cylinder(r0, thickness, center=top - (0, 0, thickness / 2), sections=sections)
    wall = shell(prof, thickness, sections=sections, linear=rot_x(np.pi), offset=top)
    return S.union([wall, cap])


def _drum_shade(rng, r_bot: float, height: float, z0: float, mat: Material) -> Part:
    r_top = r_bot * rng.uniform(0.6, 0.95)
    prof = [(r_bot, z0), (r_top, z0 + height)]
    return make_part("shade", "shade", shell(prof, rng.uniform(0.003, 0.005), sections=24), mat)


def _bulb(cx: float, cy: float, z_socket_top: float, r: float) -> Part:
    b = S.ellipsoid((r, r, r * 1.3), center=(cx, cy, z_socket_top + r * 1.2), subdivisions=1)
    return make_part("bulb", "bulb", b, bulb_material())


def _socket(cx: float, cy: float, z: float, h: float, mat: Material) -> Part:
    return make_part("socket", "socket", S.cylinder(0.017, h, center=(cx, cy, z + h / 2), sections=12),
                     mat)


def _harp(z_socket: float, z_top: float, mat: Material) -> list[Part]:
    """The turn switch on a socket standing at ``z_socket`` on the axis, the wire harp rising
    from the socket to the top of a drum shade at ``z_top``, and the finial screwed onto the
    harp's saddle above the shade."""
    switch = S.cylinder(0.005, 0.014, center=(0.017 + 0.007, 0, z_socket + 0.025), axis=(1, 0, 0), sections=8)
    harp = [S.tube([[sx * 0.018, 0, z_socket + 0.012], [sx * 0.05, 0, z_socket + 0.09],
                    [sx * 0.012, 0, z_top - 0.004], [0, 0, z_top - 0.004]], 0.0025, sections=6)
            for sx in (-1, 1)]
    finial = S.ellipsoid((0.012, 0.012, 0.015), center=(0, 0, z_top + 0.012), subdivisions=1)
    # the two sleeves slid down over the harp legs' ends that lock them in the saddle
    zs = z_socket + 0.03
    xs = 0.018 + 0.032 * (zs - z_socket - 0.012) / 0.078
    sleeves = [make_part(f"sleeve_{k}", "sleeve", S.cylinder(0.0042, 0.014, center=(sx * xs, 0, zs), sections=8), mat)
               for k, sx in enumerate((-1, 1))]
    return [make_part("switch", "switch", switch, mat), make_part("harp", "harp", harp, mat),
            make_part("finial", "finial", finial, mat), *sleeves]


def _shade_fittings(shade: Part, metal: Material) -> list[Part]:
    """The bound ``trim`` band round a drum shade's bottom edge and the wire ``spider`` fitter
    across its top that rests on the harp."""
    v = np.asarray(shade.mesh.vertices, float)
    r = np.hypot(v[:, 0], v[:, 1])
    z0, z1 = float(v[:, 2].min()), float(v[:, 2].max())
    r0, r1 = float(r[v[:, 2] < z0 + 1e-6].max()), float(r[v[:, 2] > z1 - 1e-6].max())
    band = 0.008
    trim = Material(tuple(min(1.0, c * 0.8) for c in shade.material.color[:3]) + (1.0,), 0.8, 0.0, "fabric")
    # a triangular section (no flat annulus: the costliest surface to resolve)
    rb = r0 - (r0 - r1) * band / (z1 - z0)
    out = [make_part("trim_0", "trim", ring([(r0 - 0.001, z0), (r0 + 0.0025, z0 + band * 0.5), (rb - 0.001, z0 + band)], sections=24),
                     trim)]
    zs = z1 - 0.004
    out.append(make_part("spider", "spider", [S.tube([[0, 0, zs], [np.cos(a) * (r1 - 0.004), np.sin(a) * (r1 - 0.004), zs]], 0.0015,
                                                     sections=6) for a in (np.pi / 2, np.pi / 2 + 2 * np.pi / 3, np.pi / 2 + 4 * np.pi / 3)],
                         metal))
    return out


def _straight(rng, metal: Material, shade_mat: Material) -> list[Part]:
    r_b, h_b = rng.uniform(0.12, 0.17), rng.uniform(0.025, 0.04)
    base = S.lathe([(r_b, 0.0), (r_b, h_b * 0.5), (r_b * 0.75, h_b), (0.03, h_b + 0.012)], sections=28)
    top = rng.uniform(1.3, 1.52)
    pole = S.cylinder(rng.uniform(0.011, 0.015), top - h_b, center=(0, 0, (top + h_b) / 2), sections=14)
    r_s, h_s = rng.uniform(0.17, 0.24), rng.uniform(0.22, 0.32)
    z_s = top + 0.05 - h_s * 0.4
    shade = _drum_shade(rng, r_s, h_s, z_s, shade_mat)
    return [make_part("base", "base", base, metal), make_part("pole", "pole", pole, metal),
            _socket(0, 0, top, 0.05, metal), _bulb(0, 0, top + 0.05, 0.03), shade,
            *_harp(top, z_s + h_s, metal), *_shade_fittings(shade, metal)]


def _arc(rng, metal: Material, shade_mat: Material) -> list[Part]:
    if rng.random() < 0.5:
        w = rng.uniform(0.26, 0.34)
        base = S.box((w, w, 0.05), center=(0, 0, 0.025), bevel=0.008)
        base_mat = M.stone(rng)
        h_b = 0.05
    else:
        r_b, h_b = rng.uniform(0.15, 0.19), 0.045
        base = S.lathe([(r_b, 0.0), (r_b, 0.03), (r_b * 0.8, h_b)], sections=28)
        base_mat = metal
    r_arc = rng.uniform(0.55, 0.8)
    z1 = rng.uniform(1.05, 1.3)
    t = np.linspace(0.0, np.pi * rng.uniform(0.62, 0.72), 10)
    arc = np.c_[np.zeros_like(t), r_arc * (1 - np.cos(t)), z1 + r_arc * np.sin(t)]
    path = np.vstack([[0, 0, h_b], arc])
    r_pole = rng.uniform(0.011, 0.014)
    end = path[-1]
    # a short drop straight down from the arc's tip carries the shade
    drop = np.array([end, end - (0, 0, 0.06)])
    pole = S.union([S.tube(path, r_pole, sections=10), S.tube(drop, r_pole * 0.8, sections=8)])
    r_s, h_s = rng.uniform(0.16, 0.22), rng.uniform(0.12, 0.18)
    top = end[2] - 0.05
    prof = [(r_s * 0.3, 0.0), (r_s * 0.8, h_s * 0.45), (r_s, h_s)]
    shade = _hood(prof, rng.uniform(0.003, 0.004), (0, end[1], top))
    sock = _socket(0, end[1], top - 0.05 - 0.003, 0.05, metal)
    bulb = S.ellipsoid((0.03, 0.03, 0.038), center=(0, end[1], top - 0.09), subdivisions=1)
    # the collar joining the pole to its base and the in-line dimmer on the pole
    return [make_part("base", "base", base, base_mat), make_part("pole", "pole", pole, metal),
            make_part("shade", "shade", shade, shade_mat), sock,
            make_part("bulb", "bulb", bulb, bulb_material()),
            make_part("collar", "collar", S.cylinder(r_pole * 2.2, 0.03, center=(0, 0, h_b + 0.015), sections=12), metal),
            make_part("switch", "switch", S.box((0.03, 0.02, 0.05), center=(0, 0.0, 0.8), bevel=0.005),
                      Material((0.1, 0.1, 0.1, 1.0), 0.5, 0.0, "plastic"))]


def _tripod(rng, shade_mat: Material) -> list[Part]:
    wood = M.wood(rng)
    hub = rng.uniform(1.15, 1.35)
    spread = rng.uniform(0.26, 0.34)
    r_leg = rng.uniform(0.012, 0.016)
    legs, pads = [], []
    for k in range(3):
        phi = np.pi / 2 + 2 * np.pi * k / 3  # one leg straight to the back, two to the front
        d = np.array([np.cos(phi), -np.sin(phi)])
        foot = np.array([*(spread * d), 0.012])
        legs.append(S.tube([foot, [*(0.012 * d), hub]], r_leg, sections=8))
        pads.append(S.cylinder(r_leg * 1.4, 0.012, center=(*(spread * d), 0.006), sections=10))
    top = hub + rng.uniform(0.08, 0.16)
    pole = S.cylinder(0.02, top - hub + 0.04, center=(0, 0, (top + hub - 0.04) / 2), sections=14)
    r_s, h_s = rng.uniform(0.2, 0.26), rng.uniform(0.26, 0.36)
    z_s = top + 0.05 - h_s * 0.45
    metal = M.metal(rng)
    shade = _drum_shade(rng, r_s, h_s, z_s, shade_mat)
    return [make_part("base", "base", legs + pads, wood), make_part("pole", "pole", pole, wood),
            _socket(0, 0, top, 0.05, metal), _bulb(0, 0, top + 0.05, 0.03),
            shade, *_harp(top, z_s + h_s, metal), *_shade_fittings(shade, metal)]


@register("floor_lamp", parts=("base", "pole", "shade"),
          extra_parts=("bulb", "socket", "switch", "harp", "finial", "trim", "spider", "collar", "sleeve"),
          size_range=(1.2, 2.1), density=700, variants=("straight", "arc", "tripod"))
def floor_lamp(rng: np.random.Generator, variant: str) -> list[Part]:
    shade_mat = shade_material(rng)
    if variant == "arc":
        return _arc(rng, M.metal(rng), shade_mat)
    if variant == "tripod":
        return _tripod(rng, shade_mat)
    return _straight(rng, M.metal(rng), shade_mat)


@register("table_lamp", parts=("base", "stem", "shade"), extra_parts=("bulb", "socket", "switch", "harp", "finial", "trim", "spider", "sleeve"),
          size_range=(0.3, 0.8), density=900, variants=("vase", "column", "candlestick"),
          placement="surface")
def table_lamp(rng: np.random.Generator, variant: str) -> list[Part]:
    metal = M.metal(rng)
    if variant == "vase":
        rb, hb = rng.uniform(0.07, 0.11), rng.uniform(0.18, 0.3)
        rf = rb * 0.55
        prof = [(rf, 0.0), (rf, 0.012), (rb * 0.7, 0.03), (rb, hb * 0.45), (rb * 0.85, hb * 0.75),
                (rb * 0.3, hb * 0.95), (rb * 0.25, hb)]
        base_mat = M.ceramic(rng)
        stem_h = rng.uniform(0.05, 0.09)
    elif variant == "column":
        rc, hb = rng.uniform(0.045, 0.065), rng.uniform(0.22, 0.36)
        rf = rc * rng.uniform(1.4, 1.8)
        prof = [(rf, 0.0), (rf, 0.02), (rc, 0.03), (rc, hb)]
        base_mat = M.wood(rng) if rng.random() < 0.5 else M.ceramic(rng)
        stem_h = rng.uniform(0.04, 0.07)
    else:
        rf, hb = rng.uniform(0.07, 0.09), rng.uniform(0.02, 0.03)
        prof = [(rf, 0.0), (rf, hb * 0.6), (rf * 0.8, hb), (0.025, hb + 0.01)]
        hb += 0.01
        base_mat = metal
        stem_h = rng.uniform(0.25, 0.4)
    base = S.lathe(prof, sections=24)
    r_stem = rng.uniform(0.007, 0.011) if variant != "candlestick" else rng.uniform(0.008, 0.012)
    stem = S.cylinder(r_stem, stem_h, center=(0, 0, hb + stem_h / 2), sections=12)
    top = hb + stem_h
    r_s = rng.uniform(0.12, 0.19) if variant != "candlestick" else rng.uniform(0.1, 0.15)
    h_s = r_s * rng.uniform(0.9, 1.3)
    z_s = top + 0.05 - h_s * 0.45
    shade_mat = shade_material(rng)
    shade = _drum_shade(rng, r_s, h_s, z_s, shade_mat)
    return [make_part("base", "base", base, base_mat), make_part("stem", "stem", stem, metal),
            _socket(0, 0, top, 0.04, metal), _bulb(0, 0, top + 0.04, 0.026),
            shade, *_harp(top, z_s + h_s, metal), *_shade_fittings(shade, metal)]


@register("pendant_lamp", parts=("cord", "shade"), extra_parts=("canopy", "socket", "bulb", "cord_grip", "screw", "shade_ring"),
          size_range=(0.4, 1.45), density=800, variants=("dome", "cylinder", "globe"),
          placement="ceiling")
def pendant_lamp(rng: np.random.Generator, variant: str) -> list[Part]:
    metal = M.metal(rng)
    r_c, h_c = rng.uniform(0.05, 0.07), rng.uniform(0.02, 0.03)
    cord_len = rng.uniform(0.3, 1.0)
    canopy = S.lathe([(r_c * 0.85, -h_c), (r_c, 0.0)], sections=20)
    z_cord = -h_c - cord_len
    cord = S.cylinder(0.003, cord_len, center=(0, 0, z_cord + cord_len / 2), sections=8)
    parts = [make_part("canopy", "canopy", canopy, metal),
             make_part("cord", "cord", cord, M.solid((0.1, 0.1, 0.1), "plastic"))]
    # the strain-relief grip where the cord leaves the canopy and the two set screws holding the
    # canopy on its ceiling plate
    parts.append(make_part("cord_grip", "cord_grip", S.cylinder(0.008, 0.02, center=(0, 0, -h_c - 0.01), sections=10), metal))
    parts += [make_part(f"screw_{k}", "screw", S.cylinder(0.004, 0.006, center=(sx * (r_c * 0.925 + 0.002), 0, -h_c * 0.5),
                                                          axis=(1, 0, 0), sections=8), metal) for k, sx in enumerate((-1, 1))]
    if variant == "globe":
        r = rng.uniform(0.1, 0.18)
        collar = S.cylinder(0.03, 0.03, center=(0, 0, z_cord - 0.015), sections=14)
        rz = r * rng.uniform(0.9, 1.05)
        shade = S.ellipsoid((r, r, rz), center=(0, 0, z_cord - 0.025 - rz), subdivisions=2)
        glass = M.glass(rng)
        parts += [make_part("socket", "socket", collar, metal),
                  make_part("shade", "shade", shade, glass)]
        # the three thumb screws round the fitter that grip the globe's neck, and the bulb inside
        for k in range(3):
            a = 2 * np.pi * k / 3
            d = np.array([np.cos(a), np.sin(a), 0.0])
            parts.append(make_part(f"screw_{k + 2}", "screw", S.cylinder(0.003, 0.008, center=tuple(d * 0.033 + (0, 0, z_cord - 0.02)),
                                                                         axis=tuple(d), sections=8), metal))
        parts.append(make_part("bulb", "bulb", S.ellipsoid((0.03, 0.03, 0.038), center=(0, 0, z_cord - 0.025 - 0.045),
                                                           subdivisions=1), bulb_material()))
        return parts
    if variant == "dome":
        r, h = rng.uniform(0.15, 0.25), rng.uniform(0.12, 0.2)
        prof = [(0.04, 0.0), (r * 0.55, h * 0.25), (r * 0.85, h * 0.6), (r, h)]
    else:
        r, h = rng.uniform(0.08, 0.15), rng.uniform(0.18, 0.3)
        prof = [(r, 0.0), (r, h)]
    t = rng.uniform(0.002, 0.004)
    shade = _hood(prof, t, (0, 0, z_cord))
    mat = metal if rng.random() < 0.6 else M.ceramic(rng)
    sock_top = z_cord - t
    parts += [make_part("shade", "shade", shade, mat),
              make_part("socket", "socket", S.cylinder(0.017, 0.05, center=(0, 0, sock_top - 0.025),
                                                        sections=12), metal),
              make_part("bulb", "bulb", S.ellipsoid((0.03, 0.03, 0.038),
                                                    center=(0, 0, sock_top - 0.085), subdivisions=1),
                        bulb_material()),
              # the threaded ring on the socket that clamps the shade's top from below
              make_part("shade_ring", "shade_ring", S.cylinder(0.023, 0.006, center=(0, 0, sock_top - 0.003),
                                                                sections=12), metal)]
    return parts
