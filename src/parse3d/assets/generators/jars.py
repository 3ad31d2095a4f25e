"""Jars: mason jars, glass canisters, lidded ceramic (tea, ginger) jars and large water jars.

Every jar is an open vessel (its inside floor is an internal support, so ``IN jar:body`` works)
closed by a ``lid`` resting on its mouth; ``jar:lid@top`` is where a stacked jar stands.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring


@register("jar", parts=("body", "lid"), extra_parts=("band", "label", "knob", "clamp", "ear", "neck", "gasket", "hinge", "foot_ring",
                                                       "button", "scale"),
          size_range=(0.08, 0.75), density=900, variants=("mason", "canister", "ceramic", "water"), placement="surface")
def jar(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "mason":
        r, h = rng.uniform(0.037, 0.045), rng.uniform(0.11, 0.17)
        rn = r * 0.85
        prof = [(r * 0.92, 0.0), (r, 0.008), (r, h * 0.8), (rn, h * 0.9), (rn, h)]
        mat = M.glass(rng)
        t = 0.003
    elif variant == "canister":
        r, h = rng.uniform(0.05, 0.07), rng.uniform(0.12, 0.22)
        rn = r
        prof = [(r * 0.97, 0.0), (r, 0.005), (r, h)]
        mat = M.glass(rng)
        t = 0.003
    elif variant == "ceramic":  # a bulbous tea or ginger jar
        r, h = rng.uniform(0.05, 0.075), rng.uniform(0.1, 0.18)
        rn = r * 0.6
        prof = [(r * 0.65, 0.0), (r * 0.9, h * 0.2), (r, h * 0.45), (r * 0.9, h * 0.72), (rn, h * 0.9), (rn, h)]
        mat = M.ceramic(rng)
        t = 0.005
    else:  # a large earthenware water jar
        r, h = rng.uniform(0.17, 0.24), rng.uniform(0.45, 0.6)
        rn = r * 0.55
        prof = [(r * 0.55, 0.0), (r * 0.9, h * 0.25), (r, h * 0.5), (r * 0.85, h * 0.78), (rn, h * 0.92), (rn * 1.1, h)]
        mat = Material(M.jitter(rng, (0.6, 0.35, 0.2), 0.05), 0.8, 0.0, "ceramic")
        t = 0.012
    parts = [make_part("body", "body", S.vessel(prof, t, bottom=t, sections=12, piece_sections=12), mat)]
    rl = prof[-1][0]
    if variant == "mason":  # a metal lid disc inside a screw band
        metal = M.solid(M.jitter(rng, (0.8, 0.7, 0.35), 0.05)[:3], "metal", 0.3, 0.8)
        parts.append(make_part("lid", "lid", S.cylinder(rl + 0.001, 0.003, center=(0, 0, h + 0.0015), sections=16), metal))
        parts.append(make_part("band", "band", ring([(rl + 0.001, h - 0.01), (rl + 0.004, h - 0.01), (rl + 0.004, h + 0.004),
                                                     (rl + 0.001, h + 0.004)], sections=16), metal))
        parts.append(make_part("label", "label", ring([(r, h * 0.3), (r + 0.0006, h * 0.3), (r + 0.0006, h * 0.55), (r, h * 0.55)],
                                                      sections=16), M.paper(rng)))
        # the lid's vacuum button, below the band's top, and the cup marks moulded up the back
        parts.append(make_part("button", "button", S.cylinder(rl * 0.35, 0.0005, center=(0, 0, h + 0.00325), sections=12), metal))
        parts.append(make_part("scale", "scale", [S.box((0.012 if k % 2 else 0.007, 0.0006, 0.0012),
                                                        center=(0, -(r + 0.0002), h * (0.6 + 0.06 * k))) for k in range(4)],
                               mat))
    elif variant == "canister":  # a wooden or glass lid with a seal, a wire clamp at the front
        lidm = M.wood(rng) if rng.random() < 0.5 else mat
        parts.append(make_part("lid", "lid", S.cylinder(r + 0.003, 0.02, center=(0, 0, h + 0.01), sections=24), lidm))
        parts.append(make_part("knob", "knob", S.ellipsoid((0.012, 0.012, 0.012), center=(0, 0, h + 0.026), subdivisions=1), lidm))
        wire = M.solid((0.75, 0.75, 0.77), "metal", 0.3, 0.9)
        parts.append(make_part("clamp", "clamp", S.box((0.012, 0.006, 0.03), center=(0, r + 0.006, h)), wire))
        # the rubber seal showing between lid and rim, and the wire hinge at the back
        parts.append(make_part("gasket", "gasket", ring([(r - 0.003, h + 0.001), (r + 0.001, h - 0.0005), (r + 0.005, h + 0.001),
                                                         (r + 0.001, h + 0.0025)], sections=24), M.solid((0.9, 0.45, 0.15), "rubber", 0.6)))
        parts.append(make_part("hinge", "hinge", S.cylinder(0.004, 0.03, center=(0, -r - 0.006, h + 0.004), axis=(1, 0, 0), sections=8),
                               wire))
    else:  # a domed lid on the mouth, a knob on top
        hl = rn * (0.6 if variant == "ceramic" else 0.35)
        parts.append(make_part("lid", "lid", S.lathe([(0.001, h), (rn + 0.006, h), (rn + 0.006, h + 0.008), (rn * 0.7, h + hl * 0.7),
                                                      (0.001, h + hl)], sections=24), mat))
        parts.append(make_part("knob", "knob", S.lathe([(0.001, h + hl - 0.003), (rn * 0.2, h + hl - 0.003), (rn * 0.25, h + hl + 0.01),
                                                        (0.001, h + hl + 0.018)], sections=12), mat))
        parts.append(make_part("neck", "neck", ring([(rn, h * 0.86), (rn + 0.004, h * 0.86), (rn + 0.004, h * 0.9), (rn, h * 0.9)],
                                                    sections=24), mat))
        # the unglazed foot ring it stands on
        parts.append(make_part("foot_ring", "foot_ring", ring([(r * 0.45, 0.0), (prof[0][0] + 0.002, 0.0),
                                                               ((r * 0.45 + prof[0][0]) / 2, 0.004)], sections=24), mat))
        if variant == "water":  # two lug ears at the shoulder
            for k, sx in enumerate((-1, 1)):
                parts.append(make_part(f"ear_{k}", "ear", S.box((0.04, 0.05, 0.03), center=(sx * (r * 0.88 + 0.015), 0, h * 0.75),
                                                                bevel=0.008), mat))
    return parts
