"""Bicycles: a city bike, a road bike and a mountain bike.

A bicycle is long along X (front wheel at +X) and narrow in Y, so its side faces +Y and its back
(-Y) is what leans against a wall. Wheels are tyre rings with hubs and spokes; the frame's tubes
are one part, the fork, handlebar, saddle, cranks and pedals each their own.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._detail_b import each
from ._household import ring
from ._kit import rot
from ._rods import rod, segments


def _wheel_ring(c, R: float, half: float) -> S.Shape:
    """A ring (tyre or rim) in the x-z plane around centre ``c``: outer radius ``R``, ``half`` its
    half section."""
    T = np.eye(4)
    T[:3, :3] = rot((1, 0, 0), np.pi / 2)
    T[:3, 3] = c
    sec = [(R - 2 * half, -half), (R, -half), (R, half), (R - 2 * half, half)]
    return S.transformed(ring(sec, sections=16, piece_sections=16), T)


@register("bicycle", parts=("wheel", "frame", "handlebar", "saddle"),
          extra_parts=("rim", "hub", "spoke", "fork", "stem", "seat_post", "crank", "pedal", "chainring", "grip", "kickstand",
                       "fender", "basket", "chain", "valve", "brake", "brake_lever", "cassette", "derailleur"),
          size_range=(1.4, 1.95), density=120, variants=("city", "road", "mountain"))
def bicycle(rng: np.random.Generator, variant: str) -> list[Part]:
    paint = Material(M.jitter(rng, [(0.1, 0.3, 0.6), (0.7, 0.1, 0.1), (0.1, 0.1, 0.1), (0.85, 0.85, 0.85), (0.2, 0.45, 0.3)]
                              [int(rng.integers(5))], 0.03), 0.4, 0.5, "metal")
    rubber = M.solid((0.06, 0.06, 0.06), "rubber", 0.9)
    alu = M.solid((0.75, 0.75, 0.77), "metal", 0.3, 0.9)
    R = {"city": 0.35, "road": 0.34, "mountain": 0.37}[variant] * rng.uniform(0.98, 1.02)
    tyre = {"city": 0.02, "road": 0.013, "mountain": 0.028}[variant]
    wb = rng.uniform(1.0, 1.08) if variant != "road" else rng.uniform(0.97, 1.0)
    xr, xf = -wb / 2, wb / 2
    zA = R  # axle height
    parts = []
    for k, x in enumerate((xr, xf)):
        c = (x, 0.0, zA)
        parts.append(make_part(f"wheel_{k}", "wheel", _wheel_ring(c, R, tyre), rubber))
        parts.append(make_part(f"rim_{k}", "rim", _wheel_ring(c, R - 2 * tyre, 0.009), alu))
        parts.append(make_part(f"hub_{k}", "hub", S.cylinder(0.022, 0.1, center=c, axis=(0, 1, 0), sections=12), alu))
        rs = R - 2 * tyre - 0.018
        spokes = []
        for s in range(32):  # 32 spokes, laced alternately to the left and right hub flanges
            a = 2 * np.pi * s / 32
            side = 0.03 if s % 2 else -0.03
            spokes.append(rod((x + 0.02 * np.cos(a), side, zA + 0.02 * np.sin(a)), (x + rs * np.cos(a), 0.0, zA + rs * np.sin(a)),
                              0.0015, sections=5))
        parts += each(f"spoke_{k}", "spoke", spokes, alu)  # each spoke a piece of its own
        # the tyre's valve through the rim at the bottom, and the rim-brake caliper gripping the
        # rim just behind the top of the wheel
        r_in = R - 2 * tyre - 0.018
        parts.append(make_part(f"valve_{k}", "valve", S.cylinder(0.003, 0.026, center=(x, 0.0, zA - r_in + 0.011), sections=8),
                               M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)))
        ab = np.deg2rad(100 if k == 1 else 80)
        rb = R - 2 * tyre - 0.009
        parts.append(make_part(f"brake_{k}", "brake", S.box((0.03, 0.05, 0.035), center=(x + rb * np.cos(ab), 0.0, zA + rb * np.sin(ab)),
                                                              R=rot((0, 1, 0), np.pi / 2 - ab)), M.solid((0.2, 0.2, 0.22), "metal", 0.4, 0.7)))
    # the sprocket cassette on the rear hub's drive side and the rear derailleur hanging below it
    parts.append(make_part("cassette", "cassette", S.cylinder(0.05, 0.03, center=(xr, 0.045, zA), axis=(0, 1, 0), sections=16),
                           M.solid((0.6, 0.6, 0.62), "metal", 0.3, 0.9)))
    parts.append(make_part("derailleur", "derailleur", S.box((0.03, 0.015, 0.07), center=(xr + 0.01, 0.07, zA - 0.075)),
                           M.solid((0.25, 0.25, 0.27), "metal", 0.4, 0.8)))
    # frame geometry: bottom bracket, seat cluster, head tube
    bb = np.array([xr + 0.42, 0.0, 0.28])
    st_top = np.array([bb[0] - 0.12, 0.0, bb[2] + 0.5])
    ht_bot = np.array([xf - 0.17, 0.0, 0.62])
    ht_top = np.array([xf - 0.2, 0.0, 0.76])
    rt = 0.017
    tubes = segments([bb, st_top], rt)  # seat tube
    if variant == "city":  # step-through: a low curved down tube, no top tube
        tubes += segments([bb, (bb[0] + 0.2, 0, bb[2] + 0.05), ht_bot], rt)
        tubes += segments([(bb[0] - 0.05, 0, bb[2] + 0.32), (bb[0] + 0.25, 0, bb[2] + 0.12)], rt * 0.8)
    else:
        tubes += segments([bb, ht_bot], rt * 1.2)
        tubes += segments([st_top - (0, 0, 0.03), ht_top], rt)
    tubes += segments([ht_bot, ht_top], rt * 1.3)  # head tube
    for sy in (-1, 1):  # chain stays and seat stays to the rear dropouts
        tubes += segments([bb + (0, sy * 0.03, 0), (xr, sy * 0.055, zA)], 0.009)
        tubes += segments([st_top - (0, 0, 0.04) + (0, sy * 0.02, 0), (xr, sy * 0.055, zA)], 0.008)
    parts.append(make_part("frame", "frame", tubes, paint))
    fork = []
    for sy in (-1, 1):
        fork += segments([ht_bot + (0, sy * 0.03, 0), (xf - 0.02, sy * 0.055, zA + 0.05), (xf, sy * 0.055, zA)],
                          0.012 if variant == "mountain" else 0.009)
    parts.append(make_part("fork", "fork", fork, paint if variant != "mountain" else alu))
    # stem and handlebar
    st = ht_top + (0.0, 0.0, 0.06)
    bar_c = ht_top + (0.08 if variant != "city" else -0.05, 0.0, 0.1 if variant != "road" else 0.04)
    parts.append(make_part("stem", "stem", segments([ht_top, st, bar_c], 0.012), alu))
    hw = {"city": 0.29, "road": 0.21, "mountain": 0.36}[variant]
    if variant == "road":  # drop bars: out, forward and down, back
        bar = []
        for sy in (-1, 1):
            bar += segments([bar_c, bar_c + (0, sy * hw, 0), bar_c + (0.08, sy * hw, -0.04), bar_c + (0.06, sy * hw, -0.13),
                              bar_c + (-0.05, sy * hw, -0.14)], 0.012)
        parts.append(make_part("handlebar", "handlebar", bar, alu))
        grips = [(bar_c + (-0.02, sy * hw, -0.14)) for sy in (-1, 1)]
    else:
        back = -0.08 if variant == "city" else 0.0
        parts.append(make_part("handlebar", "handlebar", segments([bar_c + (back, -hw, 0.02), bar_c + (0, -0.1, 0), bar_c + (0, 0.1, 0),
                                                                   bar_c + (back, hw, 0.02)], 0.012), alu))
        grips = [bar_c + (back, sy * (hw - 0.05), 0.02) for sy in (-1, 1)]
    for k, g in enumerate(grips):  # each grip with its brake lever (no wider than the bar it is on)
        sy = 1 if k == 1 else -1
        lever = (S.box((0.025, 0.022, 0.06), center=tuple(bar_c + (0.075, sy * hw, -0.055)), R=rot((0, 1, 0), 0.3)) if variant == "road"
                 else S.box((0.014, 0.1, 0.012), center=tuple(g + (0.045, -sy * 0.01, -0.005)), R=rot((0, 0, 1), -sy * 0.2)))
        parts.append(make_part(f"brake_lever_{k}", "brake_lever", lever, alu))
        if variant == "road":
            parts.append(make_part(f"grip_{k}", "grip", S.cylinder(0.016, 0.06, center=tuple(g), axis=(1, 0, 0), sections=10), rubber))
        else:
            parts.append(make_part(f"grip_{k}", "grip", S.cylinder(0.017, 0.11, center=tuple(g), axis=(0, 1, 0), sections=10), rubber))
    # seat post and saddle
    sp_top = st_top + np.array([-0.04, 0.0, 0.16])
    parts.append(make_part("seat_post", "seat_post", rod(st_top - (0, 0, 0.05), sp_top, 0.0135, sections=10), alu))
    sw = 0.16 if variant == "city" else 0.13
    saddle = [S.box((0.16, sw, 0.05), center=(sp_top[0] - 0.03, 0, sp_top[2] + 0.025), bevel=0.015),
              S.hull(np.array([[sp_top[0] + 0.05, sy * 0.02, sp_top[2] + sz] for sy in (-1, 1) for sz in (0.01, 0.045)]
                              + [[sp_top[0] + 0.13, sy * 0.02, sp_top[2] + sz] for sy in (-1, 1) for sz in (0.015, 0.045)]))]
    parts.append(make_part("saddle", "saddle", saddle, Material(M.jitter(rng, (0.12, 0.1, 0.08), 0.03), 0.6, 0.0, "leather")))
    # drivetrain: chainring on the right (+Y... the drive side faces the viewer), cranks and pedals
    parts.append(make_part("chainring", "chainring", S.cylinder(0.1, 0.005, center=(bb[0], 0.06, bb[2]), axis=(0, 1, 0), sections=24),
                           alu))
    chain = segments([(bb[0], 0.06, bb[2] + 0.1), (xr, 0.06, zA + 0.04)], 0.004) + segments([(bb[0], 0.06, bb[2] - 0.1),
                                                                                              (xr, 0.06, zA - 0.04)], 0.004)
    parts.append(make_part("chain", "chain", chain, M.solid((0.3, 0.3, 0.3), "metal", 0.5, 0.8)))
    a = rng.uniform(0, np.pi)
    for k, sy in enumerate((1, -1)):
        ang = a + np.pi * k
        end = bb + (0.17 * np.cos(ang), sy * 0.075, 0.17 * np.sin(ang))
        parts.append(make_part(f"crank_{k}", "crank", rod(bb + (0, sy * 0.07, 0), end, 0.01, sections=8), alu))
        parts.append(make_part(f"pedal_{k}", "pedal", S.box((0.1, 0.075, 0.02), center=tuple(end + (0, sy * 0.05, 0))), rubber))
    if variant != "road":  # a side kickstand behind the bottom bracket, folded along the chain stay
        parts.append(make_part("kickstand", "kickstand", rod(bb + (-0.05, -0.05, 0), (bb[0] - 0.3, -0.08, 0.1), 0.008,
                                                               sections=8), alu))
    if variant == "city":
        for k, (x, a0, a1) in enumerate(((xr, 0.3, 2.4), (xf, 0.5, 2.2))):
            ts = np.linspace(a0, a1, 6)
            pts = [(x - (R + 0.02) * np.cos(t) * (1 if k == 1 else -1), 0.0, zA + (R + 0.02) * np.sin(t)) for t in ts]
            parts.append(make_part(f"fender_{k}", "fender", segments(pts, 0.025, sections=8), paint))
        bx = xf + 0.02
        bz = ht_top[2] - 0.02
        walls = [S.box((0.3, 0.005, 0.2), center=(bx + 0.05, sy * 0.15, bz + 0.1)) for sy in (-1, 1)]
        walls += [S.box((0.005, 0.3, 0.2), center=(bx + 0.05 + sx * 0.15, 0, bz + 0.1)) for sx in (-1, 1)]
        walls.append(S.box((0.3, 0.3, 0.005), center=(bx + 0.05, 0, bz)))
        parts.append(make_part("basket", "basket", walls, Material(M.jitter(rng, (0.6, 0.45, 0.25), 0.04), 0.8, 0.0, "wood")))
    return parts
