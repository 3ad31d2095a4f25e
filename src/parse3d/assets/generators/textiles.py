"""Blankets: a folded throw, a blanket spread flat, a quilted duvet.

A folded blanket is a stack of layers whose rounded ``fold`` edges face +Y; a spread one is a
thin sheet with a hemmed ``binding`` round its edge (a throw's short ends carry a ``fringe``). The
label ``body`` names the blanket's main cloth in every variant.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register


@register("blanket", parts=("body",), extra_parts=("fold", "binding", "fringe", "seam", "layer"),
          size_range=(0.3, 2.5), density=120, variants=("folded", "spread", "duvet"), placement="surface")
def blanket(rng: np.random.Generator, variant: str) -> list[Part]:
    cloth = M.fabric(rng)
    trim = M.fabric(rng)
    parts = []
    if variant == "folded":
        w, d = rng.uniform(0.4, 0.6), rng.uniform(0.3, 0.42)
        n = int(rng.integers(3, 6))
        t = rng.uniform(0.012, 0.02)
        # the bottom layer is the body; every layer above it ends in a rounded fold at the front
        parts.append(make_part("body", "body", S.box((w, d, t), center=(0, 0, t / 2), bevel=t / 4), cloth))
        for k in range(1, n):
            z = k * t
            parts.append(make_part(f"layer_{k}", "layer", S.box((w, d - t, t), center=(0, -t / 2, z + t / 2), bevel=t / 4), cloth))
            parts.append(make_part(f"fold_{k}", "fold", S.cylinder(t, w, center=(0, d / 2 - t, z), axis=(1, 0, 0), sections=12), cloth))
        if rng.random() < 0.5:
            parts.append(make_part("fringe", "fringe", S.box((0.012, d - 0.01, n * t * 0.8), center=(w / 2 + 0.006, 0, n * t * 0.45)),
                                   trim))
        return parts
    if variant == "spread":
        w, d = rng.uniform(1.2, 1.6), rng.uniform(1.5, 2.1)
        t = rng.uniform(0.006, 0.01)
        parts.append(make_part("body", "body", S.box((w, d, t), center=(0, 0, t / 2)), cloth))
        b = 0.03
        for k, sy in enumerate((-1, 1)):
            parts.append(make_part(f"binding_{k}", "binding", S.box((w, b, t + 0.003), center=(0, sy * (d / 2 - b / 2), (t + 0.003) / 2)),
                                   trim))
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"binding_{k + 2}", "binding", S.box((b, d - 2 * b, t + 0.003),
                                                                         center=(sx * (w / 2 - b / 2), 0, (t + 0.003) / 2)), trim))
        if rng.random() < 0.5:  # a throw's tasselled short ends
            for k, sy in enumerate((-1, 1)):
                parts.append(make_part(f"fringe_{k}", "fringe", S.box((w - 0.04, 0.06, 0.003), center=(0, sy * (d / 2 + 0.03), 0.0015)),
                                       cloth))
        return parts
    # a duvet lying flat: a thick quilt, its baffles stitched into squares (seams as grooves' ridges)
    w, d = rng.uniform(1.35, 2.3), rng.uniform(2.0, 2.25)
    t = rng.uniform(0.04, 0.07)
    white = M.solid(M.jitter(rng, (0.95, 0.95, 0.93), 0.02)[:3], "fabric", 0.95)
    parts.append(make_part("body", "body", S.box((w, d, t), center=(0, 0, t / 2), bevel=t / 3), white))
    n_x, n_y = int(w / 0.4), int(d / 0.4)
    for i in range(1, n_x):
        parts.append(make_part(f"seam_x_{i}", "seam", S.box((0.006, d - 0.1, 0.004), center=(-w / 2 + i * w / n_x, 0, t + 0.002)), white))
    for j in range(1, n_y):
        parts.append(make_part(f"seam_y_{j}", "seam", S.box((w - 0.1, 0.006, 0.004), center=(0, -d / 2 + j * d / n_y, t + 0.002)), white))
    parts.append(make_part("binding", "binding", [S.box((w, 0.012, t * 0.5), center=(0, sy * (d / 2 + 0.006), t / 2)) for sy in (-1, 1)],
                           white))
    return parts
