"""The hotel lobby's luggage cart: a carpeted deck on casters, two uprights and the arched
hanger rail over it.

``luggage_cart:deck@top`` is where suitcases stand; garments hang from the ``rail``.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register


@register("luggage_cart", parts=("deck", "post", "rail"), extra_parts=("caster", "bumper", "hanger_bar", "basket", "flange", "hook", "bolt"),
          groups={"wheel": ("caster",)},
          size_range=(1.6, 2.0), density=300, variants=("arched", "square", "two_tier"))
def luggage_cart(rng: np.random.Generator, variant: str) -> list[Part]:
    brass = M.solid((0.8, 0.65, 0.3), "metal", 0.25, 0.9) if rng.random() < 0.6 else M.solid((0.8, 0.8, 0.82), "metal", 0.2, 0.95)
    w, d = rng.uniform(1.0, 1.2), rng.uniform(0.6, 0.7)
    H = rng.uniform(1.7, 1.9)
    rc = 0.06
    zd = 2 * rc + 0.03
    td = 0.04
    parts = []
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        parts.append(make_part(f"caster_{k}", "caster", [S.cylinder(rc, 0.035, center=(sx * (w / 2 - 0.08), sy * (d / 2 - 0.08), rc),
                                                                    axis=(0, 1, 0), sections=14),
                                                         S.box((0.05, 0.05, zd - 2 * rc), center=(sx * (w / 2 - 0.08), sy * (d / 2 - 0.08),
                                                                                                 2 * rc + (zd - 2 * rc) / 2))],
                               M.solid((0.1, 0.1, 0.1), "rubber", 0.8)))
    # the deck with its carpet (one part: the carpet's top is where luggage stands)
    parts.append(make_part("deck", "deck", [S.box((w, d, td), center=(0, 0, zd + td / 2), bevel=0.01),
                                            S.box((w - 0.04, d - 0.04, 0.006), center=(0, 0, zd + td + 0.003))], M.fabric(rng)))
    parts += [make_part("bumper" if k == 0 else f"bumper_{k}", "bumper", S.box((w + 0.03, 0.02, 0.04), center=(0, sy * (d / 2 + 0.01), zd + td / 2)),
                        M.solid((0.15, 0.15, 0.15), "rubber", 0.8)) for k, sy in enumerate((-1, 1))]
    r = 0.019
    zt = zd + td + 0.006
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"post_{k}", "post", S.cylinder(r, H - zt - 0.25, center=(sx * (w / 2 - 0.03), 0, zt + (H - zt - 0.25) / 2),
                                                               sections=12), brass))
    z0 = H - 0.25
    if variant == "square":
        path = [(-w / 2 + 0.03, 0, z0), (-w / 2 + 0.03, 0, H - r), (w / 2 - 0.03, 0, H - r), (w / 2 - 0.03, 0, z0)]
    else:
        a = np.linspace(np.pi, 0, 9)
        path = [((w / 2 - 0.03) * np.cos(t), 0.0, z0 + (0.25 - r) * np.sin(t)) for t in a]
    parts.append(make_part("rail", "rail", [S.tube([p, q], r, sections=10) for p, q in zip(path[:-1], path[1:], strict=True)], brass))
    parts.append(make_part("hanger_bar", "hanger_bar", S.cylinder(0.012, w - 0.06, center=(0, 0, z0 - 0.05), axis=(1, 0, 0), sections=10),
                           brass))
    # the flanges bolting the posts to the deck, and the garment hooks on the posts
    parts += [make_part(f"flange_{k}", "flange", S.cylinder(0.045, 0.01, center=(sx * (w / 2 - 0.03), 0, zt + 0.005), sections=14), brass)
              for k, sx in enumerate((-1, 1))]
    parts += [make_part(f"hook_{k}", "hook", S.tube([(sx * (w / 2 - 0.03 - r * 0.5), 0, z0 - 0.15), (sx * (w / 2 - 0.09), 0, z0 - 0.14),
                                                     (sx * (w / 2 - 0.1), 0, z0 - 0.11)], 0.005, sections=6), brass)
              for k, sx in enumerate((-1, 1))]
    # three bolts through each flange into the deck
    for k, sx in enumerate((-1, 1)):
        for j, a in enumerate(np.linspace(0, 2 * np.pi, 3, endpoint=False) + np.pi / 2):
            c = (sx * (w / 2 - 0.03) + 0.033 * np.cos(a), 0.033 * np.sin(a), zt + 0.0115)
            parts.append(make_part(f"bolt_{3 * k + j}", "bolt", S.cylinder(0.006, 0.003, center=c, sections=8), brass))
    if variant == "two_tier":
        parts.append(make_part("basket", "basket", [S.box((w * 0.6, d * 0.5, 0.01), center=(0, 0, zt + 0.7))]
                               + [S.box((w * 0.6, 0.01, 0.08), center=(0, sy * d * 0.25, zt + 0.74)) for sy in (-1, 1)]
                               + [S.tube([(sx * (w / 2 - 0.03), 0, zt + 0.7), (sx * w * 0.3, 0, zt + 0.7)], 0.01, sections=8)
                                  for sx in (-1, 1)], brass))
    return parts
