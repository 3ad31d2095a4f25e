"""Desk and classroom things: pens and markers, notebooks, binders and magazines, sticky notes,
chalk, board erasers and globes.

A pen, a marker and a chalk stick lie flat along X (the tip at +X). Notebooks, binders and
magazines stand in a book's frame (``book``): upright, the front cover facing +Y, the spine at
-X, so ``notebook:back_cover@back ON table`` lays one down as it does a book; a notebook's front
cover opens on a hinge along its spine. A globe stands on its base with the sphere's axis tilted
23.4 degrees in its meridian ring.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Material, Part, make_part
from ..registry import register
from ._household import ring
from ._kit import mount, revolute, rot

#: Lying (front cover up, top edge at -Y) to the book frame (front cover +Y, top edge up).
_UP = rot((1, 0, 0), -np.pi / 2)


def _stand_up(items: list) -> list:
    """Parts and joints built lying flat, turned into the book frame (a rotation about X)."""
    T = np.eye(4)
    T[:3, :3] = _UP
    out = []
    for it in items:
        if isinstance(it, Joint):
            out.append(Joint(it.name, it.type, it.parent_part, it.child_part, tuple(float(x) for x in _UP @ it.axis),
                             tuple(float(x) for x in _UP @ it.origin), it.limits))
            continue
        mesh = it.mesh.copy()
        mesh.apply_transform(T)
        pieces = []
        for p in it.pieces:
            q = p.copy()
            q.apply_transform(T)
            pieces.append(q)
        out.append(Part(it.name, it.label, mesh, it.material, pieces, watertight=it.watertight))
    return out


@register("pen", parts=("barrel", "tip"), extra_parts=("cap", "clip", "button", "grip", "nib", "end_cap", "ring"),
          groups={"body": ("barrel", "grip", "cap", "end_cap", "button")},
          size_range=(0.11, 0.17), density=1100, variants=("ballpoint", "capped", "fountain"), placement="surface")
def pen(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.13, 0.15)
    r = rng.uniform(0.0045, 0.0055) if variant != "fountain" else rng.uniform(0.006, 0.007)
    body = M.solid(M.jitter(rng, [(0.1, 0.2, 0.6), (0.05, 0.05, 0.05), (0.8, 0.1, 0.1), (0.9, 0.9, 0.9)][int(rng.integers(4))],
                            0.03)[:3], "plastic", 0.4)
    chrome = M.solid((0.8, 0.8, 0.82), "metal", 0.25, 0.9)
    black = M.solid((0.05, 0.05, 0.05), "rubber", 0.7)
    zc = r + 0.0015  # lying on its clip side up, the clip's thickness above
    lt = 0.018
    x0, x1 = -L / 2, L / 2
    parts = [make_part("tip", "tip", S.frustum(r * 0.9, r * 0.15, lt, center=(x1 - lt, 0, zc), axis=(1, 0, 0), sections=16),
                       chrome if variant != "capped" else body)]
    if variant == "fountain":
        parts.append(make_part("nib", "nib", S.frustum(r * 0.3, 0.0003, 0.008, center=(x1 - 0.0005, 0, zc), axis=(1, 0, 0), sections=8),
                               M.solid((0.85, 0.7, 0.3), "metal", 0.3, 0.9)))
        parts[0] = make_part("tip", "tip", S.frustum(r * 0.9, r * 0.3, lt, center=(x1 - lt - 0.0075, 0, zc), axis=(1, 0, 0), sections=16),
                             black)
        x1 -= 0.0075
    parts.append(make_part("grip", "grip", S.cylinder(r * 1.02, 0.03, center=(x1 - lt - 0.015, 0, zc), axis=(1, 0, 0), sections=16),
                           black))
    lb = (x1 - lt - 0.03) - x0
    if variant == "capped":  # the cap over the tip end; the barrel's tail bare
        lcap = 0.055
        parts.append(make_part("barrel", "barrel", S.cylinder(r, lb, center=(x0 + lb / 2, 0, zc), axis=(1, 0, 0), sections=16), body))
        parts.append(make_part("cap", "cap", S.cylinder(r * 1.18, lcap, center=(x1 - lcap / 2 + 0.002, 0, zc), axis=(1, 0, 0),
                                                        sections=16), body))
        parts.append(make_part("end_cap", "end_cap", S.cylinder(r * 0.9, 0.004, center=(x0 - 0.002, 0, zc), axis=(1, 0, 0),
                                                                sections=12), body))
        xc = x1 - lcap / 2
        rc = r * 1.18
    else:
        parts.append(make_part("barrel", "barrel", S.cylinder(r, lb, center=(x0 + lb / 2, 0, zc), axis=(1, 0, 0), sections=16), body))
        if variant == "ballpoint":
            parts.append(make_part("button", "button", S.cylinder(r * 0.6, 0.01, center=(x0 - 0.005, 0, zc), axis=(1, 0, 0),
                                                                  sections=12), chrome))
        else:
            parts.append(make_part("end_cap", "end_cap", S.cylinder(r * 0.95, 0.008, center=(x0 - 0.004, 0, zc), axis=(1, 0, 0),
                                                                    sections=12), chrome))
        xc = x0 + 0.025
        rc = r
    parts.append(make_part("clip", "clip", S.box((0.04, 0.003, 0.0015), center=(xc, 0, zc + rc + 0.00075)), chrome))
    # the metal band where the barrel meets the grip section
    parts.append(make_part("ring", "ring", S.cylinder(r * 1.04, 0.003, center=(x1 - lt - 0.03 - 0.0015, 0, zc), axis=(1, 0, 0),
                                                      sections=16), chrome))
    return parts


@register("notebook", parts=("front_cover", "back_cover", "pages"),
          extra_parts=("spine", "spiral", "band", "ribbon", "binding", "label", "headband", "tab"),
          groups={"cover": ("front_cover", "back_cover")},
          size_range=(0.14, 0.32), density=600, variants=("spiral", "bound", "legal_pad"), placement="surface")
def notebook(rng: np.random.Generator, variant: str) -> list:
    return _stand_up(_notebook_lying(rng, variant))


def _notebook_lying(rng: np.random.Generator, variant: str) -> list:
    w, d = [(0.148, 0.21), (0.21, 0.297), (0.19, 0.25), (0.13, 0.21)][int(rng.integers(4))]
    if variant == "legal_pad":
        w, d = 0.216, rng.uniform(0.3, 0.31)
    # built lying, its long side along Y with the top edge at -Y, spine at -X; a legal pad is
    # bound at its top edge
    n_pages = rng.uniform(0.008, 0.016) if variant != "legal_pad" else rng.uniform(0.006, 0.012)
    tc = 0.0012 if variant != "bound" else 0.0025
    cover = M.paper(rng) if variant != "bound" else M.leather(rng)
    paper = M.solid((0.95, 0.94, 0.9), "paper", 0.9)
    z = 0.0
    parts = [make_part("back_cover", "back_cover", S.box((w, d, tc), center=(0, 0, tc / 2)), cover if variant != "legal_pad"
                       else M.solid((0.6, 0.5, 0.35), "paper", 0.9))]
    z = tc
    inset = 0.002
    parts.append(make_part("pages", "pages", S.box((w - 2 * inset, d - 2 * inset, n_pages), center=(0, 0, z + n_pages / 2)),
                           paper if variant != "legal_pad" else M.solid((0.98, 0.93, 0.55), "paper", 0.9)))
    z += n_pages
    front = S.box((w, d, tc), center=(0, 0, z + tc / 2))
    parts.append(make_part("front_cover", "front_cover", front, cover))
    zt = z + tc
    # the title label on the front cover (moving with it)
    parts.append(make_part("label", "label", S.box((w * 0.5, d * 0.12, 0.0003), center=(w * 0.05, -d * 0.2, zt + 0.00015)),
                           M.solid((0.97, 0.96, 0.92), "paper", 0.8)))
    parts.append(mount("front_cover", "label"))
    if variant == "spiral":
        n = int(d / 0.0085)
        rr = (zt / 2) + 0.002
        coil = [S.cylinder(rr, 0.0016, center=(-w / 2, -d / 2 + 0.006 + k * (d - 0.012) / max(n - 1, 1), zt / 2), axis=(0, 1, 0),
                           sections=10) for k in range(n)]
        parts.append(make_part("spiral", "spiral", coil, M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)))
        # the subject dividers' tabs standing out of the pages' free edge
        tab_cols = [(0.9, 0.3, 0.3), (0.3, 0.6, 0.9), (0.95, 0.8, 0.3)]
        parts += [make_part(f"tab_{k}", "tab", S.box((0.012, 0.03, 0.0008), center=(w / 2 + 0.006 - 0.001, -d * 0.3 + k * d * 0.25,
                                                                                    tc + n_pages * (k + 1) / 4)),
                            M.solid(c, "plastic", 0.5)) for k, c in enumerate(tab_cols)]
        origin = (-w / 2, 0.0, zt / 2)
    elif variant == "bound":
        parts.append(make_part("spine", "spine", S.box((0.004, d, zt), center=(-w / 2 - 0.002, 0, zt / 2)), cover))
        parts.append(make_part("band", "band", S.box((0.006, d + 0.002, zt + 0.002), center=(w / 2 - 0.025, 0, zt / 2 + 0.001)),
                               M.solid((0.05, 0.05, 0.05), "rubber", 0.8)))
        parts.append(make_part("ribbon", "ribbon", S.box((0.006, 0.05, 0.0005), center=(-w * 0.1, d / 2 + 0.02, 0.00025)),
                               Material(M.jitter(rng, (0.6, 0.1, 0.1)), 0.6, 0.0, "fabric")))
        # the cloth headbands at the top and bottom of the sewn block
        hb = M.solid((0.8, 0.75, 0.6), "fabric", 0.8)
        parts += [make_part(f"headband_{k}", "headband", S.box((0.003, 0.002, n_pages), center=(-w / 2 + 0.0035, sy * (d / 2 - 0.003), tc + n_pages / 2)),
                            hb) for k, sy in enumerate((-1, 1))]
        origin = (-w / 2, 0.0, zt)
    else:
        parts.append(make_part("binding", "binding", S.box((w + 0.002, 0.02, zt + 0.002), center=(0, -d / 2 + 0.009, zt / 2 + 0.001)),
                               M.solid((0.5, 0.1, 0.1), "paper", 0.7)))
        parts.append(make_part("spine", "spine", S.box((w, 0.001, zt), center=(0, -d / 2 - 0.0015, zt / 2)),
                               M.solid((0.6, 0.5, 0.35), "paper", 0.9)))
        # a pad's top sheet flips over its binding at the top edge
        return parts + [revolute("front_cover_hinge", "binding", "front_cover", axis=(1, 0, 0), origin=(0, -d / 2 + 0.02, zt),
                                 opens=np.pi * 0.9)]
    parts.append(revolute("front_cover_hinge", "pages", "front_cover", axis=(0, -1, 0), origin=origin, opens=np.pi * 0.9))
    return parts


@register("chalk", parts=("stick",), extra_parts=("box", "lid", "sleeve"),
          size_range=(0.06, 0.16), density=1500, variants=("stick", "box", "sidewalk"), placement="surface")
def chalk(rng: np.random.Generator, variant: str) -> list[Part]:
    colours = [(0.96, 0.96, 0.94), (0.95, 0.85, 0.3), (0.95, 0.5, 0.6), (0.5, 0.75, 0.95), (0.6, 0.9, 0.5)]

    def chalk_mat():
        return Material(M.jitter(rng, colours[int(rng.integers(len(colours)))], 0.02), 0.95, 0.0, "stone")

    if variant == "stick":
        L, r = rng.uniform(0.07, 0.085), 0.0055
        return [make_part("stick", "stick", S.frustum(r, r * 0.9, L, center=(-L / 2, 0, r), axis=(1, 0, 0), sections=12), chalk_mat()),
                _sleeve("sleeve", r, L * 0.4, (-L / 2 + L * 0.2, 0, r), rng)]
    if variant == "sidewalk":  # each stick in the paper sleeve that keeps the hand clean
        L, r = rng.uniform(0.1, 0.12), rng.uniform(0.012, 0.014)
        return ([make_part(f"stick_{k}", "stick", S.cylinder(r, L, center=(0, (k - 1) * 2.1 * r, r), axis=(1, 0, 0), sections=16),
                           chalk_mat()) for k in range(3)]
                + [_sleeve(f"sleeve_{k}", r, L * 0.45, (-L * 0.275, (k - 1) * 2.1 * r, r), rng) for k in range(3)])
    # an open box of a dozen sticks standing in rows
    n_x, n_y = 4, 3
    r, L = 0.0055, 0.08
    w, d, h = n_x * 2.2 * r + 0.006, n_y * 2.2 * r + 0.006, L * 0.7
    card = M.paper(rng)
    walls = [S.box((w, 0.0015, h), center=(0, sy * (d / 2 - 0.00075), h / 2)) for sy in (-1, 1)]
    walls += [S.box((0.0015, d - 0.003, h), center=(sx * (w / 2 - 0.00075), 0, h / 2)) for sx in (-1, 1)]
    walls.append(S.box((w - 0.003, d - 0.003, 0.0015), center=(0, 0, 0.00075)))
    parts = [make_part("box", "box", walls, card),
             make_part("lid", "lid", S.box((w, 0.0015, h * 0.9), center=(0, -d / 2 - 0.00075 - 0.0003, h * 0.45)), card)]
    for i in range(n_x):
        for j in range(n_y):
            parts.append(make_part(f"stick_{i}_{j}", "stick",
                                   S.cylinder(r, L, center=(-w / 2 + 0.003 + 2.2 * r * (i + 0.5), -d / 2 + 0.003 + 2.2 * r * (j + 0.5),
                                                            0.0015 + L / 2), sections=10), chalk_mat()))
    return parts


def _sleeve(name: str, r: float, length: float, center, rng) -> Part:
    """A paper sleeve of ``length`` wrapped flush round a chalk stick of radius ``r`` lying
    along X (the sleeve's outside is the stick's)."""
    return make_part(name, "sleeve", ring([(r * 0.92, -length / 2), (r, -length / 2), (r, length / 2), (r * 0.92, length / 2)],
                                          sections=12).apply(_x_along(center)), M.paper(rng))


def _x_along(center) -> np.ndarray:
    """A shape about +Z turned to lie along X, centred at ``center``."""
    T = np.eye(4)
    T[:3, :3] = rot((0, 1, 0), np.pi / 2)
    T[:3, 3] = center
    return T


@register("globe", parts=("sphere", "base"), extra_parts=("meridian", "stand", "leg", "axle", "finial", "horizon", "post", "pad", "hour_circle"),
          size_range=(0.2, 1.1), density=250, variants=("desk", "floor", "cradle"), placement="surface")
def globe(rng: np.random.Generator, variant: str) -> list[Part]:
    wood = M.wood(rng)
    brass = M.solid((0.78, 0.62, 0.3), "metal", 0.3, 0.9)
    sea = Material(M.jitter(rng, [(0.35, 0.55, 0.75), (0.75, 0.65, 0.45), (0.1, 0.15, 0.3)][int(rng.integers(3))], 0.03), 0.5, 0.0,
                   "paper")
    R = rng.uniform(0.13, 0.17) if variant != "floor" else rng.uniform(0.2, 0.25)
    tilt = np.deg2rad(23.4)
    parts = []
    if variant == "floor":
        zc = rng.uniform(0.62, 0.7)
        zr = zc - R - 0.05  # the horizon ring's stand top
        for k in range(3):
            a = np.pi / 2 + 2 * np.pi * k / 3
            parts.append(make_part(f"leg_{k}", "leg", S.tube([(0.08 * np.cos(a), 0.08 * np.sin(a), zr),
                                                            (0.3 * np.cos(a), 0.3 * np.sin(a), 0.015)], 0.015, sections=10), wood))
        parts.append(make_part("base", "base", S.cylinder(0.1, 0.04, center=(0, 0, zr + 0.02), sections=24), wood))
        parts.append(make_part("stand", "stand", S.cylinder(0.02, 0.05, center=(0, 0, zr + 0.065), sections=12), wood))
        # the wooden horizon ring round the sphere's equator, on a post rising from each leg
        rh = R + 0.035
        parts.append(make_part("horizon", "horizon", ring([(rh - 0.02, zc - 0.006), (rh, zc - 0.003), (rh, zc + 0.003),
                                                           (rh - 0.02, zc + 0.006)], sections=24), wood))
        rp = rh - 0.01
        z_leg = zr - (zr - 0.015) * (rp - 0.08) / 0.22  # where the leg passes under the ring
        for k in range(3):
            a = np.pi / 2 + 2 * np.pi * k / 3
            parts.append(make_part(f"post_{k}", "post", S.cylinder(0.008, zc - 0.006 - z_leg,
                                                                   center=(rp * np.cos(a), rp * np.sin(a), (zc - 0.006 + z_leg) / 2),
                                                                   sections=8), wood))
    elif variant == "cradle":  # the sphere sits in a low ring on short feet, no meridian
        zc = R * 0.75 + 0.03
        parts.append(make_part("base", "base", ring([(R * 0.6, 0.0), (R * 0.75, 0.0), (R * 0.75, 0.03), (R * 0.6, 0.03)]), wood))
        parts.append(make_part("stand", "stand", ring([(R * 0.62, 0.03), (R * 0.7, 0.03), (R * 0.7, zc - R * 0.6),
                                                       (R * 0.62, zc - R * 0.6)]), brass))
        parts.append(make_part("sphere", "sphere", S.ellipsoid((R, R, R), center=(0, 0, zc), subdivisions=2), sea))
        # three felt pads let into the ring's underside
        parts += [make_part(f"pad_{k}", "pad", S.cylinder(R * 0.06, 0.0015, center=(R * 0.675 * np.cos(a), R * 0.675 * np.sin(a), 0.00075),
                                                          sections=10), M.solid((0.2, 0.2, 0.2), "fabric", 0.95))
                  for k, a in enumerate(np.pi / 2 + 2 * np.pi * np.arange(3) / 3)]
        return parts
    else:
        zc = R + rng.uniform(0.12, 0.16)
        parts.append(make_part("base", "base", S.lathe([(0.001, 0.0), (R * 0.65, 0.0), (R * 0.6, 0.02), (R * 0.2, 0.04), (0.001, 0.045)],
                                                       sections=24), wood))
        parts.append(make_part("stand", "stand", S.cylinder(0.012, zc - R - 0.045 - 0.01, center=(0, 0, 0.045 + (zc - R - 0.055) / 2),
                                                            sections=12), wood))
        # the felt pad let into the base's underside
        parts.append(make_part("pad", "pad", S.cylinder(R * 0.55, 0.0015, center=(0, 0, 0.00075), sections=20),
                               M.solid((0.2, 0.2, 0.2), "fabric", 0.95)))
    # the meridian: a half ring around the sphere in the x-z plane tilted about y, with axle pins
    rm = R + 0.012
    Rm = rot((0, 1, 0), tilt) @ rot((1, 0, 0), np.pi / 2)
    T = np.eye(4)
    T[:3, :3] = Rm
    T[:3, 3] = (0, 0, zc)
    mer = S.transformed(ring([(rm - 0.004, -0.006), (rm + 0.004, -0.006), (rm + 0.004, 0.006), (rm - 0.004, 0.006)], sections=20,
                             piece_sections=20), T)
    parts.append(make_part("meridian", "meridian", mer, brass))
    ax = rot((0, 1, 0), tilt) @ np.array([0, 0, 1.0])
    parts.append(make_part("sphere", "sphere", S.ellipsoid((R, R, R), center=(0, 0, zc), subdivisions=2), sea))
    for k, s in enumerate((-1, 1)):
        c = np.array([0, 0, zc]) + s * ax * (R + 0.006)
        parts.append(make_part(f"axle_{k}", "axle", S.cylinder(0.004, 0.014, center=tuple(c), axis=tuple(ax), sections=8), brass))
    # the hour circle, the small dial round the axle at the north pole
    c = np.array([0, 0, zc]) + ax * (R + 0.003)
    parts.append(make_part("hour_circle", "hour_circle", S.cylinder(0.02, 0.002, center=tuple(c), axis=tuple(ax), sections=16), brass))
    top = np.array([0, 0, zc]) + ax * (rm + 0.012)
    parts.append(make_part("finial", "finial", S.ellipsoid((0.008, 0.008, 0.008), center=tuple(top), subdivisions=1), brass))
    return parts


@register("binder", parts=("front_cover", "back_cover", "spine"),
          extra_parts=("ring", "mechanism", "pages", "label", "finger_hole", "lever", "rivet"),
          groups={"cover": ("front_cover", "back_cover")},
          size_range=(0.24, 0.34), density=450, variants=("ring", "slim", "lever_arch"), placement="surface")
def binder(rng: np.random.Generator, variant: str) -> list:
    return _stand_up(_binder_lying(rng, variant))


def _binder_lying(rng: np.random.Generator, variant: str) -> list:
    w, d = rng.uniform(0.27, 0.29), rng.uniform(0.31, 0.32)  # A4 / letter, lying, top edge at -Y
    T = {"ring": rng.uniform(0.04, 0.06), "slim": rng.uniform(0.02, 0.03), "lever_arch": rng.uniform(0.075, 0.085)}[variant]
    tc = 0.003
    cover = Material(M.jitter(rng, [(0.1, 0.2, 0.6), (0.05, 0.05, 0.05), (0.7, 0.1, 0.1), (0.9, 0.9, 0.9), (0.2, 0.5, 0.3)]
                              [int(rng.integers(5))], 0.03), 0.5, 0.0, "plastic")
    metal = M.solid((0.75, 0.75, 0.77), "metal", 0.3, 0.9)
    parts = [make_part("back_cover", "back_cover", S.box((w, d, tc), center=(0, 0, tc / 2)), cover),
             make_part("spine", "spine", S.box((tc, d, T), center=(-w / 2 - tc / 2, 0, T / 2)), cover),
             make_part("front_cover", "front_cover", S.box((w, d, tc), center=(0, 0, T - tc / 2)), cover)]
    # the ring mechanism on the back cover near the spine, the rings through the punched pages
    xm = -w / 2 + 0.03
    parts.append(make_part("mechanism", "mechanism", S.box((0.03, d * 0.7, 0.004), center=(xm, 0, tc + 0.002)), metal))
    # the two rivets fixing it through the back cover, their heads on its plate
    parts += [make_part(f"rivet_{k}", "rivet", S.cylinder(0.003, 0.0015, center=(xm, sy * d * 0.3, tc + 0.004 + 0.00075), sections=8), metal)
              for k, sy in enumerate((-1, 1))]
    n = 2 if variant != "ring" else 3
    rr = min(T / 2 - tc - 0.002, 0.03)
    Tr = np.eye(4)
    Tr[:3, :3] = rot((1, 0, 0), np.pi / 2)
    for k in range(n):
        y = (k - (n - 1) / 2) * (0.108 if n == 3 else 0.08)
        Tr[:3, 3] = (xm, y, tc + 0.004 + rr)
        parts.append(make_part(f"ring_{k}", "ring", S.transformed(ring([(rr - 0.0025, -0.0015), (rr, -0.0015), (rr, 0.0015),
                                                                        (rr - 0.0025, 0.0015)], sections=12), Tr), metal))
    pw = w - 0.05
    ph = max(T - 2 * tc - 0.006, 0.004) * rng.uniform(0.4, 0.9)
    parts.append(make_part("pages", "pages", S.box((pw, d - 0.01, ph), center=(w / 2 - 0.005 - pw / 2, 0, tc + ph / 2)),
                           M.solid((0.95, 0.94, 0.9), "paper", 0.9)))
    parts.append(make_part("label", "label", S.box((0.0008, d * 0.35, T * 0.6), center=(-w / 2 - tc - 0.0004, -d * 0.15, T / 2)),
                           M.solid((0.95, 0.95, 0.92), "paper", 0.9)))
    if variant == "lever_arch":
        parts.append(make_part("finger_hole", "finger_hole", ring([(0.012, 0), (0.016, 0), (0.016, 0.002), (0.012, 0.002)],
                                                                  sections=12).apply(_x_out(-w / 2 - tc, d * 0.3, T / 2)), metal))
        parts.append(make_part("lever", "lever", S.box((0.012, 0.06, 0.01), center=(xm + 0.02, d * 0.3, tc + 0.009)), metal))
    return parts + [revolute("front_cover_hinge", "spine", "front_cover", axis=(0, -1, 0), origin=(-w / 2, 0.0, T - tc),
                             opens=np.pi * 0.9)]


def _x_out(x: float, y: float, z: float) -> np.ndarray:
    """A ring about +Z turned to face -X and moved to (x, y, z)."""
    T = np.eye(4)
    T[:3, :3] = rot((0, 1, 0), -np.pi / 2)
    T[:3, 3] = (x, y, z)
    return T


@register("magazine", parts=("front_cover", "back_cover", "pages"), extra_parts=("spine", "staple", "mailing_label", "insert_card"),
          groups={"cover": ("front_cover", "back_cover")},
          size_range=(0.2, 0.42), density=800, variants=("glossy", "stapled", "tabloid"), placement="surface")
def magazine(rng: np.random.Generator, variant: str) -> list:
    w, d = (rng.uniform(0.2, 0.23), rng.uniform(0.27, 0.3)) if variant != "tabloid" else (rng.uniform(0.27, 0.29),
                                                                                           rng.uniform(0.36, 0.4))
    T = rng.uniform(0.004, 0.012) if variant == "glossy" else rng.uniform(0.002, 0.005)
    tc = 0.0004
    cover = M.paper(rng)
    parts = [make_part("back_cover", "back_cover", S.box((w, d, tc), center=(0, 0, tc / 2)), cover),
             make_part("pages", "pages", S.box((w - 0.001, d - 0.001, T - 2 * tc), center=(0.0005, 0, T / 2)),
                       M.solid((0.93, 0.92, 0.9), "paper", 0.6)),
             make_part("front_cover", "front_cover", S.box((w, d, tc), center=(0, 0, T - tc / 2)), cover)]
    if variant == "glossy":
        parts.append(make_part("spine", "spine", S.box((0.0008, d, T), center=(-w / 2 - 0.0004, 0, T / 2)), cover))
    else:
        for k, y in enumerate((-d * 0.25, d * 0.25)):
            parts.append(make_part(f"staple_{k}", "staple", S.box((0.0012, 0.012, T + 0.0004), center=(-w / 2 + 0.0006, y, T / 2)),
                                   M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)))
    # the barcode box printed in the front cover's corner, and a subscriber's address label
    parts.append(make_part("mailing_label", "mailing_label", S.box((0.08, 0.03, 0.0002), center=(w * 0.15, -d / 2 + 0.03, T + 0.0001)),
                           M.solid((0.98, 0.98, 0.96), "paper", 0.7)))
    # the subscription card bound in among the pages, its edge showing at the fore-edge
    parts.append(make_part("insert_card", "insert_card", S.box((w * 0.6, d * 0.5, 0.0003), center=(w * 0.2 - 0.0005, 0, T * 0.6)),
                           M.solid((0.9, 0.75, 0.3), "paper", 0.7)))
    return _stand_up(parts)


@register("marker", parts=("barrel", "cap"), extra_parts=("tip", "clip", "end_cap", "grip", "label", "cap_end"),
          groups={"body": ("barrel", "end_cap")},
          size_range=(0.1, 0.16), density=900, variants=("whiteboard", "permanent", "highlighter"), placement="surface")
def marker(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.125, 0.14)
    r = {"whiteboard": 0.0085, "permanent": 0.0065, "highlighter": 0.008}[variant]
    ink = M.solid([(0.05, 0.05, 0.05), (0.1, 0.2, 0.7), (0.75, 0.1, 0.1), (0.1, 0.5, 0.2), (0.95, 0.9, 0.1)][int(rng.integers(5))],
                  "plastic", 0.4)
    body = M.solid((0.95, 0.95, 0.93), "plastic", 0.4) if variant != "highlighter" else ink
    zc = r + (0.002 if variant == "permanent" else 0.0)
    lcap = 0.045
    lb = L - lcap + 0.01
    x0 = -L / 2
    parts = [make_part("barrel", "barrel", S.cylinder(r, lb, center=(x0 + lb / 2, 0, zc), axis=(1, 0, 0), sections=16), body),
             make_part("end_cap", "end_cap", S.cylinder(r * 0.95, 0.008, center=(x0 + 0.004, 0, zc), axis=(1, 0, 0), sections=16), ink),
             make_part("cap", "cap", S.cylinder(r * 1.12, lcap, center=(L / 2 - lcap / 2, 0, zc), axis=(1, 0, 0), sections=16), ink)]
    parts.append(make_part("tip", "tip", S.frustum(r * 0.5, r * 0.3, 0.012, center=(x0 + lb, 0, zc), axis=(1, 0, 0), sections=10),
                           M.solid((0.9, 0.9, 0.9), "fabric", 0.9)))
    if variant == "permanent":
        parts.append(make_part("clip", "clip", S.box((0.03, 0.003, 0.002), center=(L / 2 - 0.02, 0, zc + r * 1.12 + 0.001)), ink))
    # the printed label wrapped round the barrel and the cap's closed end
    parts.append(make_part("label", "label", S.cylinder(r + 0.0003, lb * 0.45, center=(x0 + 0.012 + lb * 0.225, 0, zc), axis=(1, 0, 0),
                                                        sections=16), M.solid((0.2, 0.25, 0.5), "paper", 0.6)))
    parts.append(make_part("cap_end", "cap_end", S.cylinder(r * 0.9, 0.003, center=(L / 2 + 0.0015, 0, zc), axis=(1, 0, 0),
                                                            sections=12), ink))
    return parts


@register("sticky_note", parts=("sheet",), extra_parts=("pad", "holder", "adhesive"),
          size_range=(0.04, 0.135), density=700, variants=("pad", "cube", "single"), placement="surface")
def sticky_note(rng: np.random.Generator, variant: str) -> list[Part]:
    s = [0.076, 0.076, 0.051, 0.127][int(rng.integers(4))]
    col = M.solid(M.jitter(rng, [(0.98, 0.92, 0.4), (0.98, 0.6, 0.7), (0.6, 0.85, 0.95), (0.7, 0.95, 0.5)][int(rng.integers(4))],
                           0.02)[:3], "paper", 0.9)
    if variant == "single":  # the glue strip along the back of its top edge
        return [make_part("sheet", "sheet", S.box((s, s, 0.0003), center=(0, 0, 0.00025)), col),
                make_part("adhesive", "adhesive", S.box((s, 0.016, 0.0001), center=(0, -s / 2 + 0.008, 0.00005)),
                          M.solid((0.9, 0.9, 0.85), "plastic", 0.3))]
    h = rng.uniform(0.005, 0.012) if variant == "pad" else rng.uniform(0.035, 0.05)
    # the pad's block, and its top sheets each a part (the top one is what gets written on)
    n_top, ts = 4, 0.0003
    h0 = h - n_top * ts
    parts = [make_part("pad", "pad", S.box((s, s, h0), center=(0, 0, h0 / 2)), col),
             # the gummed edge of the block, where every sheet is stuck to the next
             make_part("adhesive", "adhesive", S.box((s, 0.0004, h0), center=(0, -s / 2 + 0.0002, h0 / 2)),
                       M.solid((0.9, 0.88, 0.7), "paper", 0.6))]
    for k in range(n_top):
        parts.append(make_part(f"sheet_{k}", "sheet", S.box((s, s, ts), center=(0, 0, h0 + ts * (k + 0.5))), col))
    if variant == "cube":  # in a clear holder open at the top
        t = 0.002
        walls = [S.box((s + 2 * t, t, h * 0.8), center=(0, sy * (s / 2 + t / 2), h * 0.4)) for sy in (-1, 1)]
        walls += [S.box((t, s, h * 0.8), center=(sx * (s / 2 + t / 2), 0, h * 0.4)) for sx in (-1, 1)]
        parts.append(make_part("holder", "holder", walls, Material((0.9, 0.92, 0.95, 0.3), 0.1, 0.0, "plastic")))
    return parts


@register("whiteboard_eraser", parts=("body", "pad"), extra_parts=("grip", "felt_layer", "side_grip", "end_cap"),
          size_range=(0.1, 0.17), density=400, variants=("block", "handled", "magnetic"), placement="surface")
def whiteboard_eraser(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.12, 0.155), rng.uniform(0.05, 0.06)
    felt = M.solid((0.2, 0.2, 0.22) if rng.random() < 0.5 else (0.9, 0.9, 0.88), "fabric", 0.95)
    shell = M.plastic(rng) if variant != "block" else M.wood(rng)
    hp = 0.012
    parts = [make_part("pad", "pad", S.box((w, d, hp), center=(0, 0, hp / 2)), felt)]
    hb = 0.02 if variant != "block" else 0.03
    parts.append(make_part("body", "body", S.box((w, d, hb), center=(0, 0, hp + hb / 2), bevel=0.004), shell))
    if variant == "handled":
        parts.append(make_part("grip", "grip", [S.box((w * 0.7, 0.025, 0.02), center=(0, 0, hp + hb + 0.02), bevel=0.006)]
                               + [S.box((0.015, 0.02, 0.012), center=(sx * w * 0.3, 0, hp + hb + 0.006)) for sx in (-1, 1)], shell))
    # the rubber finger grips set flush into both long sides; a plastic shell's end caps
    rubber = M.solid((0.12, 0.12, 0.13), "rubber", 0.8)
    parts += [make_part(f"side_grip_{k}", "side_grip", S.box((w * 0.5, 0.0012, hb * 0.5), center=(0, sy * (d / 2 - 0.0006), hp + hb / 2)),
                        rubber) for k, sy in enumerate((-1, 1))]
    if variant != "block":
        parts += [make_part(f"end_cap_{k}", "end_cap", S.box((0.002, d - 0.006, hb - 0.006), center=(sx * (w / 2 - 0.001), 0, hp + hb / 2)),
                            shell) for k, sx in enumerate((-1, 1))]
    if variant == "magnetic":
        parts.append(make_part("felt_layer", "felt_layer", S.box((w - 0.01, d - 0.01, 0.004), center=(0, 0, hp + hb + 0.002)),
                               M.solid((0.1, 0.1, 0.1), "rubber", 0.8)))
    return parts
