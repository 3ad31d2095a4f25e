"""Clothes lying about: a stack of folded garments, a heap, a folded shirt.

A stack's garments are each a ``garment`` (bottom to top); a folded shirt shows its ``collar``
on top. ``clothes@top`` is where another pile goes.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register


@register("clothes", parts=("garment",), extra_parts=("collar", "sleeve", "fold", "button", "pocket"),
          size_range=(0.2, 0.7), density=200, variants=("folded_stack", "heap", "folded_shirt"), placement="surface")
def clothes(rng: np.random.Generator, variant: str) -> list[Part]:
    parts = []
    if variant == "folded_shirt":
        w, d, t = rng.uniform(0.24, 0.3), rng.uniform(0.3, 0.36), rng.uniform(0.025, 0.04)
        cloth = M.fabric(rng)
        parts.append(make_part("garment", "garment", S.box((w, d, t), center=(0, 0, t / 2), bevel=t / 4), cloth))
        parts.append(make_part("collar", "collar", S.box((0.12, 0.04, 0.012), center=(0, -d / 2 + 0.04, t + 0.006), bevel=0.004), cloth))
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"sleeve_{k}", "sleeve", S.box((0.05, d * 0.6, 0.008), center=(sx * w * 0.25, d * 0.05, t + 0.004),
                                                                  bevel=0.002), cloth))
        # the placket's buttons down the middle and a chest pocket
        btn = M.solid((0.95, 0.95, 0.93), "plastic", 0.4)
        for k, y in enumerate((-d * 0.2, d * 0.05, d * 0.3)):
            parts.append(make_part(f"button_{k}", "button", S.cylinder(0.005, 0.002, center=(0, y, t + 0.001), sections=10), btn))
        parts.append(make_part("pocket", "pocket", S.box((0.06, 0.07, 0.002), center=(-w * 0.12, -d * 0.15, t + 0.001)), cloth))
        return parts
    if variant == "heap":  # crumpled garments as squashed lumps
        n = int(rng.integers(3, 6))
        r = rng.uniform(0.12, 0.2)
        for k in range(n):
            a = rng.uniform(0, 2 * np.pi)
            c = (r * 0.5 * np.cos(a), r * 0.5 * np.sin(a), 0.0)
            rz = rng.uniform(0.03, 0.06)
            parts.append(make_part(f"garment_{k}", "garment", S.ellipsoid((rng.uniform(0.1, 0.18), rng.uniform(0.08, 0.15), rz),
                                                                          center=(c[0], c[1], rz + k * 0.02), subdivisions=1), M.fabric(rng)))
        # sleeves trailing out of the heap onto the surface
        for k in range(2):
            a = rng.uniform(0, 2 * np.pi)
            p0 = np.array([np.cos(a), np.sin(a)]) * r * 0.4
            p1 = np.array([np.cos(a + 0.3), np.sin(a + 0.3)]) * r * 1.05
            parts.append(make_part(f"sleeve_{k}", "sleeve", S.tube([(*p0, 0.03), (*p1, 0.018)], 0.018, sections=8), M.fabric(rng)))
        return parts
    w, d = rng.uniform(0.25, 0.32), rng.uniform(0.2, 0.3)
    z = 0.0
    for k in range(int(rng.integers(2, 6))):  # folded garments, slightly offset, each with a rounded fold at the front
        t = rng.uniform(0.02, 0.045)
        dx, dy = rng.uniform(-0.01, 0.01), rng.uniform(-0.01, 0.01)
        cloth = M.fabric(rng)
        parts.append(make_part(f"garment_{k}", "garment", S.box((w, d - t, t), center=(dx, dy - t / 2, z + t / 2), bevel=t / 4), cloth))
        parts.append(make_part(f"fold_{k}", "fold", S.cylinder(t / 2, w, center=(dx, dy + d / 2 - t / 2, z + t / 2), axis=(1, 0, 0), sections=10),
                               cloth))
        z += t
    return parts
