"""The reception desk's small things: a service (call) bell.

The bell's dome sits on a base; the ``button`` (the plunger) rises through its top.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register


@register("service_bell", parts=("bell", "base", "button"), extra_parts=("foot", "post", "pad", "hammer", "spring"),
          size_range=(0.07, 0.13), density=2500, variants=("classic", "square_base", "wooden_base"), placement="surface")
def service_bell(rng: np.random.Generator, variant: str) -> list[Part]:
    chrome = M.solid((0.8, 0.8, 0.82), "metal", 0.2, 0.95) if rng.random() < 0.6 else M.solid((0.78, 0.62, 0.3), "metal", 0.3, 0.9)
    rb = rng.uniform(0.04, 0.048)
    hb = 0.012
    if variant == "classic":
        parts = [make_part("base", "base", S.cylinder(rb, hb, center=(0, 0, hb / 2), sections=24),
                           M.solid((0.08, 0.08, 0.08), "metal", 0.4, 0.5))]
    elif variant == "square_base":
        parts = [make_part("base", "base", S.box((2 * rb + 0.01, 2 * rb + 0.01, hb), center=(0, 0, hb / 2), bevel=0.002),
                           M.solid((0.08, 0.08, 0.08), "metal", 0.4, 0.5))]
    else:
        parts = [make_part("base", "base", S.box((2 * rb + 0.02, 2 * rb + 0.02, hb + 0.006), center=(0, 0, (hb + 0.006) / 2),
                                                 bevel=0.003), M.wood(rng))]
        hb += 0.006
    for k in range(3):
        a = 2 * np.pi * k / 3 + np.pi / 2
        parts.append(make_part(f"foot_{k}", "foot", S.box((0.006, 0.006, 0.004), center=(rb * 0.6 * np.cos(a), rb * 0.6 * np.sin(a),
                                                                                      hb + 0.002)), chrome))
    rd = rb * 0.85
    hd = rd * 0.6
    z0 = hb + 0.004
    dome = S.lathe([(0.001, z0), (rd, z0), (rd * 0.95, z0 + hd * 0.35), (rd * 0.75, z0 + hd * 0.75), (rd * 0.4, z0 + hd * 0.97),
                    (0.001, z0 + hd)], sections=24)
    parts.append(make_part("bell", "bell", dome, chrome))
    parts.append(make_part("post", "post", S.cylinder(0.0025, 0.012, center=(0, 0, z0 + hd + 0.006), sections=8), chrome))
    parts.append(make_part("button", "button", S.cylinder(0.007, 0.004, center=(0, 0, z0 + hd + 0.014), sections=12),
                           Material((0.1, 0.1, 0.1, 1.0), 0.5, 0.3, "metal")))
    # under the dome: the spring the plunger returns on, round the post's foot, and the
    # hammer arm that strikes the dome's inside wall when the plunger is pressed
    parts.append(make_part("spring", "spring", S.cylinder(0.004, hd * 0.45, center=(0, 0, z0 + hd * 0.5), sections=8),
                           M.solid((0.55, 0.55, 0.57), "metal", 0.35, 0.9)))
    parts.append(make_part("hammer", "hammer", S.box((rd * 0.7, 0.004, 0.004), center=(rd * 0.4, 0, z0 + hd * 0.3)),
                           M.solid((0.55, 0.55, 0.57), "metal", 0.35, 0.9)))
    # the four felt pads set flush into the base's underside
    felt = M.solid((0.12, 0.12, 0.12), "fabric", 0.95)
    for k in range(4):
        a = 2 * np.pi * k / 4 + np.pi / 4
        parts.append(make_part(f"pad_{k}", "pad", S.cylinder(0.005, 0.0015, center=(rb * 0.7 * np.cos(a), rb * 0.7 * np.sin(a), 0.00075),
                                                             sections=10), felt))
    return parts
