"""Sinks and taps on their own: vessel sinks (a bowl on a counter), pedestal sinks, utility
sinks (a deep tub on legs) and faucets.

A sink's ``basin`` is an open vessel whose floor is an internal support; its ``rim`` the lip
round the top; the faucet stands behind the basin (-Y), its spout reaching forward (+Y).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import open_box, ring
from ._kit import legs4
from ._rods import leg_caps


def _faucet(prefix: str, x: float, y: float, z: float, *, reach: float, h: float, mat: Material, style: str) -> list[Part]:
    """A faucet standing at (x, y, z): deck ``base``, column ``body``, ``spout`` reaching +Y, ``handle``(s),
    the ``collar`` where the column meets the base, the ``aerator`` in the spout's tip and the hot
    and cold ``indicator`` s."""
    out = [make_part(f"{prefix}base", "base", S.cylinder(0.028, 0.008, center=(x, y, z + 0.004), sections=16), mat),
           make_part(f"{prefix}body", "body", S.cylinder(0.017, h, center=(x, y, z + 0.008 + h / 2), sections=12), mat)]
    zt = z + 0.008 + h
    if style == "gooseneck":
        a = np.linspace(0, np.pi, 7)
        path = [(x, y + reach / 2 - reach / 2 * np.cos(t), zt + 0.08 * np.sin(t)) for t in a]
        path = [(x, y, zt - 0.01)] + path + [(x, y + reach, zt - 0.04)]
    else:
        path = [(x, y, zt - 0.015), (x, y + reach, zt - 0.015), (x, y + reach, zt - 0.035)]
    out.append(make_part(f"{prefix}spout", "spout", [S.tube([a, b], 0.011, sections=10) for a, b in zip(path[:-1], path[1:], strict=True)],
                         mat))
    if style == "two_handle":
        for k, sx in enumerate((-1, 1)):
            out.append(make_part(f"{prefix}handle_{k}", "handle", [S.cylinder(0.018, 0.03, center=(x + sx * 0.09, y, z + 0.015), sections=12),
                                                                   S.box((0.04, 0.008, 0.008), center=(x + sx * 0.09, y, z + 0.034))],
                                 mat))
    else:
        # a side lever (nothing reaches behind the base, so the sink's back can meet the wall)
        out.append(make_part(f"{prefix}handle", "handle", S.box((0.06, 0.012, 0.012), center=(x + 0.017 + 0.03, y, zt - 0.03), bevel=0.003), mat))
    out.append(make_part(f"{prefix}collar", "collar", S.cylinder(0.021, 0.012, center=(x, y, z + 0.014), sections=12), mat))
    tip = np.asarray(path[-1], float)
    out.append(make_part(f"{prefix}aerator", "aerator", S.cylinder(0.0115, 0.008, center=tuple(tip - (0, 0, 0.002)), sections=10),
                         M.solid((0.55, 0.55, 0.57), "metal", 0.3, 0.8)))
    red, blue = M.solid((0.85, 0.1, 0.1), "plastic", 0.3), M.solid((0.1, 0.3, 0.85), "plastic", 0.3)
    if style == "two_handle":
        out += [make_part(f"{prefix}indicator_{k}", "indicator", S.cylinder(0.007, 0.002, center=(x + sx * 0.09, y, z + 0.039), sections=10),
                          red if sx < 0 else blue) for k, sx in enumerate((-1, 1))]
    else:
        out.append(make_part(f"{prefix}indicator", "indicator", S.cylinder(0.005, 0.002, center=(x + 0.017 + 0.05, y, zt - 0.023), sections=10),
                             red))
    if style != "gooseneck":  # the pop-up drain's lift rod behind the column, a knob on its top
        out.append(make_part(f"{prefix}lift_rod", "lift_rod", [S.cylinder(0.003, h * 0.55, center=(x, y - 0.022, z + 0.008 + h * 0.275), sections=8),
                                                               S.cylinder(0.005, 0.012, center=(x, y - 0.022, z + 0.008 + h * 0.55 + 0.006),
                                                                          sections=8)], mat))
    else:  # a kitchen tap's pull-down spray head round the spout's end, and its spray button
        out.append(make_part(f"{prefix}spray_head", "spray_head", S.cylinder(0.015, 0.045, center=tuple(tip + (0, 0, 0.0295)), sections=10),
                             mat))
        out.append(make_part(f"{prefix}button", "button", S.box((0.01, 0.004, 0.016), center=tuple(tip + (0, 0.017, 0.03))),
                             M.solid((0.1, 0.1, 0.1), "plastic", 0.5)))
    return out


@register("faucet", parts=("base", "spout"), extra_parts=("body", "handle", "collar", "aerator", "indicator", "lift_rod", "spray_head", "button"),
          size_range=(0.15, 0.45), density=4000, variants=("single_lever", "two_handle", "gooseneck"), placement="surface")
def faucet(rng: np.random.Generator, variant: str) -> list[Part]:
    chrome = M.solid(M.jitter(rng, (0.8, 0.8, 0.82), 0.02)[:3], "metal", 0.15, 0.95) if rng.random() < 0.7 else \
        M.solid((0.1, 0.1, 0.1), "metal", 0.4, 0.6)
    h = rng.uniform(0.12, 0.2) if variant != "gooseneck" else rng.uniform(0.2, 0.3)
    return _faucet("", 0.0, 0.0, 0.0, reach=rng.uniform(0.12, 0.2), h=h, mat=chrome, style=variant)


@register("vessel_sink", parts=("basin",), extra_parts=("rim", "base", "drain_flange", "drain_cap", "overflow"),
          size_range=(0.3, 0.62), density=1500, variants=("round", "oval", "square"), placement="surface")
def vessel_sink(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.ceramic(rng) if rng.random() < 0.7 else M.stone(rng)
    h = rng.uniform(0.12, 0.16)
    zb = 0.01
    if variant == "square":
        w = rng.uniform(0.38, 0.46)
        parts = [make_part("base", "base", S.box((w * 0.6, w * 0.6, zb), center=(0, 0, zb / 2)), mat),
                 make_part("basin", "basin", [s.moved((0, 0, zb)) for s in open_box(w, w, h, 0.012)], mat)]
        parts.append(make_part("rim", "rim", [S.box((w, 0.016, 0.006), center=(0, sy * (w / 2 - 0.008), zb + h + 0.003)) for sy in (-1, 1)]
                               + [S.box((0.016, w - 0.032, 0.006), center=(sx * (w / 2 - 0.008), 0, zb + h + 0.003)) for sx in (-1, 1)],
                               mat))
    else:
        r = rng.uniform(0.19, 0.23)
        prof = [(r * 0.45, 0.0), (r * 0.8, h * 0.3), (r * 0.97, h * 0.75), (r, h)]
        basin = S.vessel(prof, 0.01, bottom=0.012, sections=16, piece_sections=16).moved((0, 0, zb))
        if variant == "oval":
            T = np.diag([1.0, 0.75, 1.0, 1.0])
            basin = S.transformed(basin, T)
        parts = [make_part("base", "base", ring([(r * 0.3, 0.0), (r * 0.45, 0.0), (r * 0.45, zb), (r * 0.3, zb)], sections=16), mat),
                 make_part("basin", "basin", basin, mat)]
        rim = ring([(r - 0.012, zb + h), (r + 0.002, zb + h), (r + 0.002, zb + h + 0.006), (r - 0.012, zb + h + 0.006)], sections=16)
        if variant == "oval":
            rim = S.transformed(rim, np.diag([1.0, 0.75, 1.0, 1.0]))
        parts.append(make_part("rim", "rim", rim, mat))
    return parts + _vessel_drain(variant, h, zb, w / 2 - 0.012 if variant == "square" else None,
                                 None if variant == "square" else prof)


def _vessel_drain(variant: str, h: float, zb: float, half_in: float | None, prof) -> list[Part]:
    """A vessel sink's chrome pop-up drain in the basin floor (the flange and the cap closed in
    it) and the overflow cover on the back wall."""
    chrome = M.solid((0.78, 0.79, 0.8), "metal", 0.15, 0.95)
    z_floor = zb + 0.012
    # both sit in the floor's recess, standing under a millimetre proud of it, so the floor stays
    # the support inside the basin (a cup stands over the drain as on a real one)
    out = [make_part("drain_flange", "drain_flange",
                     ring([(0.016, z_floor - 0.002), (0.033, z_floor - 0.002), (0.016, z_floor + 0.0008)], sections=12), chrome),
           make_part("drain_cap", "drain_cap", S.lathe([(0.0158, z_floor - 0.004), (0.0158, z_floor + 0.0004),
                                                        (0.013, z_floor + 0.0008)], sections=16), chrome)]
    zo = zb + h * 0.72
    if half_in is None:  # the inner wall's radius at that height
        r_out = float(np.interp(zo - zb, [q[1] for q in prof], [q[0] for q in prof]))
        y_wall = -(r_out - 0.01) * (0.75 if variant == "oval" else 1.0)
    else:
        y_wall = -half_in
    # the overflow's slotted cover plate on the back wall
    out.append(make_part("overflow", "overflow", S.cylinder(0.013, 0.003, center=(0, y_wall + 0.0015, zo), axis=(0, 1, 0), sections=10),
                         chrome))
    return out


@register("pedestal_sink", parts=("basin", "pedestal"), extra_parts=("bowl", "deck", "base", "spout", "handle", "body", "overflow",
                                                                 "collar", "aerator", "indicator", "lift_rod", "drain", "bolt_cap",
                                                                 "foot"),
          groups={"basin": ("bowl", "deck")},
          size_range=(0.85, 1.05), density=1400, variants=("round", "square", "console"))
def pedestal_sink(rng: np.random.Generator, variant: str) -> list[Part]:
    porcelain = M.solid(M.jitter(rng, (0.95, 0.95, 0.94), 0.01)[:3], "ceramic", 0.2)
    chrome = M.solid((0.8, 0.8, 0.82), "metal", 0.15, 0.95)
    H = rng.uniform(0.8, 0.88)  # rim height
    w, d = rng.uniform(0.5, 0.62), rng.uniform(0.42, 0.5)
    hb = 0.16
    zb = H - hb
    parts = []
    if variant == "console":  # a basin slab on two front legs
        parts += legs4("pedestal", "pedestal", w=w * 0.9, d=d * 0.8, h=zb, size=0.035, mat=chrome, round_=True)[2:]
        parts.append(make_part("base", "base", S.box((w * 0.9, 0.02, 0.02), center=(0, d * 0.4 - 0.0175, 0.15)), chrome))
        # the levelling foot sleeving each leg's end
        parts += leg_caps(parts, label="foot", legs=("pedestal",), mat=chrome, height=0.03)
    else:
        parts.append(make_part("base", "base", S.box((0.24, 0.22, 0.04), center=(0, -d * 0.1, 0.02), bevel=0.01), porcelain))
        parts.append(make_part("pedestal", "pedestal", S.frustum(0.09, 0.12, zb - 0.04, center=(0, -d * 0.1, 0.04), sections=20), porcelain))
        # the caps over the two floor bolts at the base's front corners
        parts += [make_part(f"bolt_cap_{k}", "bolt_cap", S.cylinder(0.008, 0.006, center=(sx * 0.1, -d * 0.1 + 0.09, 0.043), sections=10),
                            porcelain) for k, sx in enumerate((-1, 1))]
    # the basin: a bowl in front, the flat deck behind it where the faucet stands
    dd = 0.12
    parts.append(make_part("deck", "deck", S.box((w, dd, hb), center=(0, -d / 2 + dd / 2, zb + hb / 2), bevel=0.01), porcelain))
    if variant == "square":
        bw, bd = w, d - dd
        parts.append(make_part("bowl", "bowl", [s.moved((0, -d / 2 + dd + bd / 2, zb)) for s in open_box(bw, bd, hb, 0.02, bottom=0.03)],
                               porcelain))
    else:
        r = min(w / 2, (d - dd))
        bowl = S.vessel([(r * 0.5, 0.0), (r * 0.85, hb * 0.5), (r, hb)], 0.02, bottom=0.03, sections=24, piece_sections=24)
        T = np.diag([1.0, (d - dd) / (2 * r), 1.0, 1.0])
        T[1, 3] = -d / 2 + dd + (d - dd) / 2
        T[2, 3] = zb
        parts.append(make_part("bowl", "bowl", S.transformed(bowl, T), porcelain))
    parts.append(make_part("overflow", "overflow", S.box((0.03, 0.004, 0.012), center=(0, -d / 2 + dd + 0.002, zb + hb - 0.04)), chrome))
    # the drain's chrome flange in the bowl's floor, half a millimetre proud of it
    parts.append(make_part("drain", "drain", S.cylinder(0.02, 0.003, center=(0, -d / 2 + dd + (d - dd) / 2, zb + 0.029), sections=12), chrome))
    parts += _faucet("faucet_", 0.0, -d / 2 + dd / 2 + 0.005, H, reach=dd * 0.8, h=0.1, mat=chrome, style="single_lever")
    return parts


@register("utility_sink", parts=("basin", "rim"), extra_parts=("leg", "faucet", "spout", "handle", "base", "body", "drain",
                                                               "backsplash", "stretcher", "collar", "aerator", "indicator",
                                                               "leg_cap", "spray_head", "button", "trap"),
          size_range=(0.85, 1.2), density=600, variants=("legs", "cabinet", "double"))
def utility_sink(rng: np.random.Generator, variant: str) -> list[Part]:
    tub = M.solid(M.jitter(rng, (0.92, 0.92, 0.9), 0.02)[:3], "plastic", 0.5) if rng.random() < 0.6 else \
        M.solid((0.75, 0.75, 0.77), "metal", 0.3, 0.8)
    chrome = M.solid((0.8, 0.8, 0.82), "metal", 0.15, 0.95)
    w = rng.uniform(0.55, 0.65) if variant != "double" else rng.uniform(0.95, 1.05)
    d = rng.uniform(0.5, 0.6)
    hb = rng.uniform(0.3, 0.36)
    H = rng.uniform(0.86, 0.92)
    zb = H - hb
    parts = []
    if variant == "cabinet":
        parts.append(make_part("base", "base", S.box((w - 0.02, d - 0.02, zb), center=(0, 0, zb / 2)), M.wood(rng)))
    else:
        parts += legs4("leg", "leg", w=w - 0.04, d=d - 0.04, h=zb, size=0.04, mat=tub)
        parts += [make_part(f"stretcher_{k}", "stretcher", S.box((0.02, d - 0.1, 0.02), center=(sx * (w / 2 - 0.04), 0, 0.2)), tub)
                  for k, sx in enumerate((-1, 1))]
    n = 2 if variant == "double" else 1
    bw = w / n
    for k in range(n):
        name = "basin" if n == 1 else f"basin_{k}"
        parts.append(make_part(name, "basin", [s.moved((-w / 2 + bw * (k + 0.5), 0, zb)) for s in open_box(bw, d, hb, 0.012, bottom=0.015)],
                               tub))
        parts.append(make_part("drain" if n == 1 else f"drain_{k}", "drain",
                               S.cylinder(0.025, 0.003, center=(-w / 2 + bw * (k + 0.5), 0.05, zb + 0.0165), sections=12), chrome))
        if variant != "cabinet":  # the waste pipe's trap under the drain, back into the wall
            xk = -w / 2 + bw * (k + 0.5)
            parts.append(make_part("trap" if n == 1 else f"trap_{k}", "trap",
                                   S.tube([(xk, 0.05, zb + 0.005), (xk, 0.05, zb - 0.18), (xk, -0.02, zb - 0.18), (xk, -0.02, zb - 0.1),
                                           (xk, -d / 2, zb - 0.1)], 0.019, sections=10), M.solid((0.9, 0.9, 0.88), "plastic", 0.5)))
    # the rim: a narrow lip at the front and sides, a deck at the back (soap stands on it)
    rim = [S.box((w, 0.03, 0.015), center=(0, d / 2 - 0.015, H + 0.0075)), S.box((w, 0.12, 0.015), center=(0, -d / 2 + 0.06, H + 0.0075))]
    rim += [S.box((0.03, d - 0.06, 0.015), center=(sx * (w / 2 - 0.015), 0, H + 0.0075)) for sx in (-1, 1)]
    parts.append(make_part("rim", "rim", rim, tub))
    parts.append(make_part("backsplash", "backsplash", S.box((w, 0.03, 0.12), center=(0, -d / 2 + 0.015, H + 0.015 + 0.06)), tub))
    fp = _faucet("faucet_", 0.0, -d / 2 + 0.03, H + 0.135, reach=0.18, h=0.05, mat=chrome, style="gooseneck")
    for p in fp:
        if p.label == "body":
            p.label = "faucet"
    parts += fp
    # the plastic levelling feet capping the legs
    return parts + leg_caps(parts, label="leg_cap", mat=M.solid((0.15, 0.15, 0.16), "plastic", 0.6), height=0.04)
