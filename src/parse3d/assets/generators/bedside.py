"""Bedside things: alarm clocks and tissue boxes.

An alarm clock's face looks toward +Y; a tissue box's tissue sticks up out of the slot in its
top.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._casework import black


@register("alarm_clock", parts=("body", "face"), extra_parts=("bell", "hand", "foot", "button", "display", "grille", "hub", "bezel",
                                                               "key", "battery_cover", "power_inlet", "hammer", "alarm_switch", "marker"),
          size_range=(0.07, 0.22), density=700, variants=("twin_bell", "digital", "cube"), placement="surface")
def alarm_clock(rng: np.random.Generator, variant: str) -> list[Part]:
    shell = M.plastic(rng) if variant != "twin_bell" else M.metal(rng)
    if variant == "digital":
        w, d, h = rng.uniform(0.12, 0.2), rng.uniform(0.06, 0.09), rng.uniform(0.06, 0.09)
        parts = [make_part("body", "body", S.box((w, d, h), center=(0, 0, h / 2), bevel=0.01), shell),
                 make_part("face", "face", S.box((w * 0.75, 0.004, h * 0.6), center=(0, d / 2 + 0.001, h / 2)), black()),
                 make_part("display", "display", S.box((w * 0.6, 0.002, h * 0.35), center=(0, d / 2 + 0.003, h / 2)),
                           M.solid((0.9, 0.2, 0.1), "glass", 0.1))]
        parts += [make_part(f"button_{k}", "button", S.box((0.02, 0.012, 0.006), center=((k - 1) * 0.03, 0, h + 0.002)), black())
                  for k in range(3)]
        # the speaker grille on the back, and two rubber pads let into the underside
        parts.append(make_part("grille", "grille", S.box((w * 0.4, 0.002, h * 0.5), center=(0, -d / 2 - 0.0005, h / 2)), black("metal")))
        parts += [make_part(f"foot_{k}", "foot", S.cylinder(0.006, 0.002, center=(sx * w * 0.35, 0, 0.001), sections=8), black("rubber"))
                  for k, sx in enumerate((-1, 1))]
        # the back-up battery's cover let into the underside, and the mains adapter's socket at the back
        parts.append(make_part("battery_cover", "battery_cover", S.box((w * 0.3, d * 0.5, 0.001), center=(0, 0, 0.0005)), shell))
        parts.append(make_part("power_inlet", "power_inlet", S.cylinder(0.004, 0.002, center=(w * 0.3, -d / 2 - 0.0005, h * 0.3),
                                                                        axis=(0, 1, 0), sections=8), black()))
        return parts
    if variant == "cube":
        s = rng.uniform(0.07, 0.09)
        parts = [make_part("body", "body", S.box((s, s, s), center=(0, 0, s / 2), bevel=0.006), shell)]
        r, zc, yf = s * 0.38, s / 2, s / 2
    else:
        r = rng.uniform(0.045, 0.06)
        zc = r + 0.025
        yf = 0.02
        parts = [make_part("body", "body", S.cylinder(r, 0.04, center=(0, 0, zc), axis=(0, 1, 0), sections=28), shell)]
        for i, s in enumerate((-1, 1)):
            parts.append(make_part(f"bell_{i}", "bell", S.ellipsoid((r * 0.45, r * 0.3, r * 0.35),
                                                                    center=(s * r * 0.6, 0, zc + r * 0.95)), shell))
            # a leg splayed sideways onto a pad as deep as the body: on two point feet in one
            # line the clock tips over
            x0, x1, e = s * r * 0.5, s * r * 0.8, r * 0.45
            parts.append(make_part(f"foot_{i}", "foot", S.hull(
                [(x0 + dx, dy, zc - r * 0.8) for dx in (-0.004, 0.004) for dy in (-0.004, 0.004)]
                + [(x1 + dx, dy, z) for dx in (-0.005, 0.005) for dy in (-e, e) for z in (0.0, 0.004)]),
                shell))
    parts.append(make_part("face", "face", S.cylinder(r * 0.9, 0.003, center=(0, yf + 0.001, zc), axis=(0, 1, 0), sections=28),
                           M.solid((0.96, 0.95, 0.9), "paper", 0.5)))
    for k, (L, a) in enumerate([(r * 0.5, rng.uniform(0, 2 * np.pi)), (r * 0.75, rng.uniform(0, 2 * np.pi))]):
        c = (np.cos(a) * L / 2, yf + 0.004 + 0.001 * k, zc + np.sin(a) * L / 2)
        R = np.array([[np.cos(a), 0, -np.sin(a)], [0, 1, 0], [np.sin(a), 0, np.cos(a)]])
        parts.append(make_part(f"hand_{k}", "hand", S.box((L, 0.0015, 0.003), center=c, R=R), black()))
    # the red alarm hand, the cap over the hands' hub, the bezel round the face and the winding
    # and alarm-setting keys on the back
    a = rng.uniform(0, 2 * np.pi)
    R = np.array([[np.cos(a), 0, -np.sin(a)], [0, 1, 0], [np.sin(a), 0, np.cos(a)]])
    parts.append(make_part("hand_2", "hand", S.box((r * 0.4, 0.0012, 0.002), center=(np.cos(a) * r * 0.2, yf + 0.0065, zc + np.sin(a) * r * 0.2),
                                                   R=R), M.solid((0.8, 0.1, 0.1), "metal", 0.4)))
    # the twelve applied hour markers round the dial, longer at 12, 3, 6 and 9
    for k in range(12):
        a_k = np.pi / 2 - k * np.pi / 6
        ln = r * (0.16 if k % 3 == 0 else 0.1)
        rc = r * 0.9 - 0.004 - ln / 2
        R_k = np.array([[np.cos(a_k), 0, -np.sin(a_k)], [0, 1, 0], [np.sin(a_k), 0, np.cos(a_k)]])
        parts.append(make_part(f"marker_{k}", "marker", S.box((ln, 0.0008, 0.0025 if k % 3 == 0 else 0.0016),
                                                              center=(np.cos(a_k) * rc, yf + 0.0029, zc + np.sin(a_k) * rc), R=R_k),
                               black("metal")))
    parts.append(make_part("hub", "hub", S.cylinder(0.003, 0.004, center=(0, yf + 0.007, zc), axis=(0, 1, 0), sections=8), black()))
    parts.append(make_part("bezel", "bezel", S.cylinder(r * 0.97, 0.004, center=(0, yf + 0.0005, zc), axis=(0, 1, 0), sections=28), shell))
    yb = -0.02 if variant == "twin_bell" else -yf
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"key_{k}", "key", [S.cylinder(0.003, 0.008, center=(sx * r * 0.35, yb - 0.004, zc), axis=(0, 1, 0), sections=8),
                                                  S.box((0.016, 0.003, 0.01), center=(sx * r * 0.35, yb - 0.009, zc))], shell))
    # the alarm's on-off slide on the back, above the keys; a twin-bell clock's hammer striking
    # between its bells, or a cube's battery cover at the back
    parts.append(make_part("alarm_switch", "alarm_switch", S.box((0.01, 0.004, 0.006), center=(0, yb - 0.002, zc + r * 0.6)), black()))
    if variant == "twin_bell":
        parts.append(make_part("hammer", "hammer", [S.cylinder(0.0015, r * 0.45, center=(0, 0, zc + r * 0.8 + r * 0.225), sections=6),
                                                    S.ellipsoid((0.004, 0.004, 0.004), center=(0, 0, zc + r * 1.25), subdivisions=1)],
                               M.metal(rng)))
    else:
        parts.append(make_part("battery_cover", "battery_cover", S.box((r * 0.7, 0.001, r * 0.45), center=(0, -yf - 0.0005, zc - r * 0.55)),
                               shell))
    return parts


@register("tissue_box", parts=("box",), extra_parts=("tissue", "opening", "flap", "perforation"),
          size_range=(0.1, 0.27), density=120,
          variants=("rectangular", "cube"), placement="surface")
def tissue_box(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "cube":
        w = d = rng.uniform(0.11, 0.12)
        h = rng.uniform(0.12, 0.13)
    else:
        w, d, h = rng.uniform(0.22, 0.25), rng.uniform(0.11, 0.12), rng.uniform(0.06, 0.09)
    card = M.paper(rng)
    # the clear film round the dispensing slot, the printed pattern on the front, the barcode
    # on the bottom edge of one end
    op_w = min(0.14, w * 0.6)
    return [make_part("box", "box", S.box((w, d, h), center=(0, 0, h / 2)), card),
            make_part("tissue", "tissue", S.hull([[-0.03, -0.004, h], [0.03, -0.004, h], [-0.03, 0.004, h], [0.03, 0.004, h],
                                                  [-0.015, -0.002, h + 0.05], [0.015, 0.002, h + 0.05]]),
                      M.solid((0.97, 0.97, 0.97), "paper", 0.9), watertight=True),
            make_part("opening", "opening", S.box((op_w, 0.035, 0.0008), center=(0, 0, h + 0.0004)),
                      Material((0.9, 0.92, 0.95, 0.5), 0.1, 0.0, "plastic")),
            # the glued end flap on the left end
            make_part("flap", "flap", S.box((0.0008, d * 0.9, h * 0.45), center=(-w / 2 - 0.0004, 0, h * 0.3)), card),
            # its twin glued over the right end
            make_part("flap_1", "flap", S.box((0.0008, d * 0.9, h * 0.45), center=(w / 2 + 0.0004, 0, h * 0.3)), card),
            # the pattern printed on the back too, and the perforated panel torn out round the slot
            make_part("perforation", "perforation",
                      [S.box((op_w + 0.02, 0.002, 0.0005), center=(0, sy * 0.0275, h + 0.00025)) for sy in (-1, 1)]
                      + [S.box((0.002, 0.053, 0.0005), center=(sx * (op_w / 2 + 0.01), 0, h + 0.00025)) for sx in (-1, 1)], card)]
