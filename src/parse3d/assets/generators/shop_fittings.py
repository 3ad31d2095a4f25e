"""Shop fittings: hanging produce scales.

A hanging scale hangs from the ceiling by its ``hook`` (``HANGING_BELOW ceiling`` with the
hook's top): the round ``dial`` housing, then ``chain``s down to the ``pan`` that holds the
produce being weighed (``IN hanging_scale:pan``).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring, shell


@register("hanging_scale", parts=("hook", "dial", "pan"), extra_parts=("chain", "face", "pointer", "hanger", "glass", "bezel", "ring", "knob", "hub",
                                                                                "s_hook", "rim"),
          size_range=(0.45, 0.9), density=1500, variants=("dish", "basket", "deep_pan"), placement="ceiling")
def hanging_scale(rng: np.random.Generator, variant: str) -> list[Part]:
    metal = M.metal(rng) if rng.random() < 0.6 else Material(M.jitter(rng, (0.85, 0.2, 0.15), 0.05), 0.4, 0.3, "metal")
    steel = Material((0.8, 0.8, 0.82, 1.0), 0.2, 0.95, "metal")
    rp = rng.uniform(0.16, 0.22)
    hp = {"dish": 0.04, "basket": 0.1, "deep_pan": 0.08}[variant]
    parts = [make_part("pan", "pan", shell([(rp * 0.8, 0.0), (rp, hp)], 0.003, sections=28), steel)]
    drop = rng.uniform(0.22, 0.3)
    zr = hp + drop  # where the chains meet under the dial
    for k in range(3):
        a = 2 * np.pi * k / 3
        p = np.array([rp * 0.97 * np.cos(a), rp * 0.97 * np.sin(a), hp - 0.002])
        parts.append(make_part(f"chain_{k}", "chain", S.tube([p, (0, 0, zr)], 0.002, sections=5), steel))
    parts.append(make_part("hanger", "hanger", S.tube([(0, 0, zr - 0.004), (0, 0, zr + 0.04)], 0.004, sections=6), steel))
    rd = rng.uniform(0.1, 0.13)
    zd = zr + 0.04 + rd
    dial = S.cylinder(rd, 0.06, center=(0, 0, zd), axis=(0, 1, 0), sections=28)
    parts.append(make_part("dial", "dial", dial, metal))
    parts.append(make_part("face", "face", S.cylinder(rd * 0.88, 0.002, center=(0, 0.031, zd), axis=(0, 1, 0), sections=28),
                           Material((0.97, 0.97, 0.95, 1.0), 0.5, 0.0, "paper")))
    parts.append(make_part("pointer", "pointer", S.box((0.004, 0.002, rd * 0.75), center=(0, 0.0335, zd + rd * 0.3)),
                           Material((0.8, 0.1, 0.1, 1.0), 0.5, 0.0, "metal")))
    zt = zd + rd
    hook = S.tube([(0, 0, zt - 0.005), (0, 0, zt + 0.05), (0.015, 0, zt + 0.07), (0.03, 0, zt + 0.06),
                   (0.03, 0, zt + 0.045)], 0.004, sections=6)
    parts.append(make_part("hook", "hook", hook, steel))
    # the glass over the face in its bezel, the pointer's hub, the tare knob on top of the case,
    # and the ring the three chains are gathered in under the dial
    parts.append(make_part("glass", "glass", S.cylinder(rd * 0.9, 0.002, center=(0, 0.0365, zd), axis=(0, 1, 0), sections=28),
                           Material((0.9, 0.95, 1.0, 0.3), 0.05, 0.0, "glass")))
    parts.append(make_part("bezel", "bezel", ring([(rd * 0.88, 0.0), (rd * 0.94, -0.004), (rd * 1.0, 0.0), (rd * 0.94, 0.004)],
                                                  sections=28).apply(np.array([[1, 0, 0, 0], [0, 0, -1, 0.034], [0, 1, 0, zd],
                                                                               [0, 0, 0, 1.0]])), metal))
    parts.append(make_part("hub", "hub", S.cylinder(0.008, 0.004, center=(0, 0.0375, zd), axis=(0, 1, 0), sections=10), steel))
    parts.append(make_part("knob", "knob", S.cylinder(0.01, 0.015, center=(rd * 0.5, 0, zd + rd * 0.87 + 0.006), sections=10),
                           Material((0.1, 0.1, 0.1, 1.0), 0.5, 0.0, "plastic")))
    parts.append(make_part("ring", "ring", ring([(0.006, zr), (0.009, zr - 0.003), (0.012, zr), (0.009, zr + 0.003)],
                                                sections=12), steel))
    # the rolled rim round the pan's edge, and the S-hook joining each chain to it
    parts.append(make_part("rim", "rim", ring([(rp - 0.003, hp - 0.004), (rp + 0.002, hp - 0.002), (rp - 0.003, hp)], sections=28), steel))
    for k in range(3):
        a = 2 * np.pi * k / 3
        c = np.array([rp * 0.97 * np.cos(a), rp * 0.97 * np.sin(a), hp + 0.008])
        parts.append(make_part(f"s_hook_{k}", "s_hook", S.tube([c - (0, 0, 0.01), c + (0, 0, 0.008)], 0.0025, sections=6), steel))
    return parts
