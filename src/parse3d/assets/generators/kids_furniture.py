"""Children's furniture: high chairs.

A high chair stands on four splayed ``leg``s; the child sits on the ``seat`` against the
``back`` between two ``armrest``s, feet on the ``footrest``; the ``tray`` in front (+Y) at table
height holds cups and bowls (``ON high_chair:tray``).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._kit import rot


@register("high_chair", parts=("seat", "leg", "tray"),
          extra_parts=("back", "armrest", "footrest", "stretcher", "strap", "tray_rim", "leg_cap", "buckle", "latch"),
          size_range=(0.85, 1.15), density=500, variants=("wooden", "plastic", "folding"),
          placement="floor")
def high_chair(rng: np.random.Generator, variant: str) -> list[Part]:
    frame = M.wood(rng) if variant == "wooden" else (
        Material(M.jitter(rng, (0.92, 0.92, 0.9), 0.02), 0.4, 0.0, "plastic") if variant == "plastic"
        else Material((0.75, 0.76, 0.78, 1.0), 0.3, 0.9, "metal"))
    shell = M.plastic(rng) if variant != "wooden" else frame
    zs = rng.uniform(0.55, 0.6)  # seat height
    sw, sd = rng.uniform(0.34, 0.4), rng.uniform(0.3, 0.34)
    splay = rng.uniform(0.1, 0.14)
    parts: list[Part] = []
    top = np.array([(sx * (sw / 2 - 0.03), sy * (sd / 2 - 0.03)) for sx, sy in
                    [(-1, -1), (1, -1), (-1, 1), (1, 1)]])
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        foot = top[i] + (sx * splay, sy * splay * 1.1)
        path = [(foot[0], foot[1], 0.015), (top[i][0], top[i][1], zs - 0.02)]
        parts.append(make_part(f"leg_{i}", "leg", S.tube(path, 0.016, sections=10), frame))
    # the footrest bar across the front legs and stretchers at the back and sides
    zf = zs * 0.45
    f = zf / zs
    fl = top[2] + (-splay, splay * 1.1) * np.array(1 - f)
    fr = top[3] + (splay, splay * 1.1) * np.array(1 - f)
    parts.append(make_part("footrest", "footrest", S.box((fr[0] - fl[0] + 0.02, 0.06, 0.018),
                                                         center=(0, fl[1] + 0.01, zf)), frame))
    zt = zs * 0.3
    g = zt / zs
    bl = top[0] + (-splay, -splay * 1.1) * np.array(1 - g)
    br = top[1] + (splay, -splay * 1.1) * np.array(1 - g)
    parts.append(make_part("stretcher", "stretcher", S.tube([(bl[0] + 0.01, bl[1], zt), (br[0] - 0.01, br[1], zt)],
                                                            0.01, sections=8), frame))
    parts.append(make_part("seat", "seat", S.box((sw, sd, 0.03), center=(0, 0, zs - 0.015), bevel=0.006), shell))
    hb = rng.uniform(0.32, 0.4)
    back = S.box((sw - 0.02, 0.03, hb), center=(0, -sd / 2 + 0.015, zs + hb / 2 - 0.002), bevel=0.008)
    parts.append(make_part("back", "back", back, shell))
    za = zs + rng.uniform(0.17, 0.2)
    for k, sx in enumerate((-1, 1)):
        arm = [S.box((0.03, sd - 0.03, 0.03), center=(sx * (sw / 2 - 0.015), 0.0, za), bevel=0.006),
               S.box((0.025, 0.025, za - zs), center=(sx * (sw / 2 - 0.015), sd / 2 - 0.03, (za + zs) / 2 - 0.01))]
        parts.append(make_part(f"armrest_{k}", "armrest", arm, frame))
    # the tray clips onto the armrests and reaches forward
    tw, td = sw + rng.uniform(0.12, 0.18), rng.uniform(0.26, 0.3)
    zt_ = za + 0.015
    ty = sd / 2 - 0.06 + td / 2
    tray = S.box((tw, td, 0.012), center=(0, ty, zt_ + 0.006), bevel=0.004)
    parts.append(make_part("tray", "tray", tray, shell))
    rim = [S.box((tw, 0.012, 0.018), center=(0, ty + td / 2 - 0.006, zt_ + 0.009)),
           S.box((0.012, td - 0.024, 0.018), center=(tw / 2 - 0.006, ty, zt_ + 0.009)),
           S.box((0.012, td - 0.024, 0.018), center=(-tw / 2 + 0.006, ty, zt_ + 0.009))]
    parts.append(make_part("tray_rim", "tray_rim", rim, shell))
    strap = S.box((0.04, 0.012, za - zs - 0.02), center=(0, sd * 0.1, (zs + za) / 2 - 0.01))
    webbing = Material(M.jitter(rng, (0.2, 0.3, 0.5), 0.1), 0.9, 0.0, "fabric")
    parts.append(make_part("strap", "strap", strap, webbing))
    # the rest of the harness: the two waist straps from the back to the buckle where they
    # meet the crotch strap; the tray's two release latches under its side edges; and the
    # side stretchers joining front and back legs at the footrest's height
    zw = zs + 0.04
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"strap_{k + 1}", "strap", S.box((sw * 0.42, 0.008, 0.03),
                                                                center=(sx * sw * 0.21, -sd * 0.05, zw), R=rot((0, 0, 1), -sx * 0.5)), webbing))
    parts.append(make_part("buckle", "buckle", S.box((0.045, 0.014, 0.035), center=(0, sd * 0.1 + 0.002, zw), bevel=0.004),
                           Material((0.15, 0.15, 0.16, 1.0), 0.5, 0.0, "plastic")))
    parts += [make_part(f"latch_{k}", "latch", S.box((0.02, 0.04, 0.01), center=(sx * (tw / 2 - 0.03), sd / 2, zt_ - 0.005)), shell)
              for k, sx in enumerate((-1, 1))]
    for k, sx in enumerate((-1, 1)):
        a = top[0 if sx < 0 else 1] + (sx * splay, -splay * 1.1) * np.array(1 - f)
        b = top[2 if sx < 0 else 3] + (sx * splay, splay * 1.1) * np.array(1 - f)
        parts.append(make_part(f"stretcher_{k + 1}", "stretcher", S.tube([(a[0], a[1] + 0.01, zf), (b[0], b[1] - 0.01, zf)], 0.009,
                                                                         sections=8), frame))
    # non-slip rubber caps sleeving the splayed legs just above their ends (the legs still
    # stand on the floor)
    rubber = M.solid((0.1, 0.1, 0.1), "rubber", 0.85)
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        foot = np.array([*(top[i] + (sx * splay, sy * splay * 1.1)), 0.015])
        u = np.array([*top[i], zs - 0.02]) - foot
        u /= np.linalg.norm(u)
        parts.append(make_part(f"leg_cap_{i}", "leg_cap", S.cylinder(0.017, 0.035, center=tuple(foot + u * (0.01 + 0.0175)),
                                                                     axis=tuple(u), sections=10), rubber))
    return parts
