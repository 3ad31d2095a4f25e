"""Soft goods: pillows, towels and rugs.

Pillows are soft convex solids with a flattened bottom (they stand on a bed or a sofa); folded
towels are stacks of rounded layers, rolled towels flattened rolls along X; rugs are thin slabs
on the floor, optionally with ``fringe`` strips at their short ends.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from ...geometry.frames import make_transform, rot_y
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._bedbath_common import bevel_box, cushion, loft, soft_hull


def _roll(length: float, radius: float, *, squash: float = 0.85, flat: float = 0.3,
          n_u: int = 16) -> S.Shape:
    """A soft roll along X (bolster, rolled towel) with rounded ends and a flat bottom.

    Centred on x = y = 0, bottom at z = 0. One convex piece.
    """
    u = np.linspace(0, 2 * np.pi, n_u, endpoint=False)
    # built along +Z, then turned so the axis runs along X; ring x becomes -z after turning,
    # so clipping x from above flattens the final bottom
    ring = np.c_[radius * np.cos(u), radius * squash * np.sin(u)]
    ring[:, 0] = np.minimum(ring[:, 0], radius * (1 - flat))
    end = min(radius * 0.6, length * 0.2)
    zs, scales = [], []
    for k, a in enumerate(np.linspace(0, np.pi / 2, 4)):
        zs.append(end * (1 - np.cos(a)))
        scales.append(0.55 + 0.45 * np.sin(a))
        if k == 3:
            break
    prof = list(zip(zs, scales, strict=True))
    prof += [(length - z, s) for z, s in prof[::-1]]
    rings = [np.c_[ring * s, np.full(n_u, z - length / 2)] for z, s in prof]
    mesh = loft(rings)
    shape = S.Shape(mesh, [mesh]).apply(make_transform(rot_y(np.pi / 2)))
    return shape.moved((0, 0, -shape.mesh.bounds[0, 2]))


@register("pillow", parts=("body",), size_range=(0.3, 0.95), density=60,
          variants=("bed", "square", "bolster"), placement="surface")
def pillow(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.fabric(rng) if rng.random() < 0.6 else M.solid((0.95, 0.94, 0.92), "fabric", 0.95)
    if variant == "bolster":
        body = _roll(rng.uniform(0.45, 0.9), rng.uniform(0.08, 0.12), squash=1.0, flat=0.25)
    else:
        if variant == "bed":
            w, d = rng.uniform(0.5, 0.75), rng.uniform(0.35, 0.5)
        else:
            w = d = rng.uniform(0.38, 0.55)
        t = rng.uniform(0.1, 0.18)
        body = soft_hull((w / 2, d / 2, t / 2), power=rng.uniform(3.0, 5.0), flat=0.3)
    return [make_part("body", "body", body, mat)]


def _folded(rng, w: float, d: float, t: float, z0: float, n: int) -> list[S.Shape]:
    """``n`` rounded layers of a folded towel, bottom at ``z0``."""
    lt = t / n
    layers = []
    for k in range(n):
        dx, dy = rng.uniform(-0.004, 0.004, 2)
        layers.append(cushion(w - 0.004 * k, d, lt, (dx, dy, z0 + lt * (k + 0.5)),
                              round_xy=0.02, round_z=lt * 0.45, n=2))
    return layers


@register("towel", parts=("body",), size_range=(0.15, 0.5), density=200,
          variants=("folded", "rolled", "stack"), placement="surface")
def towel(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.fabric(rng)
    if variant == "rolled":
        body = _roll(rng.uniform(0.25, 0.4), rng.uniform(0.045, 0.07), squash=0.9, flat=0.2)
        return [make_part("body", "body", body, mat)]
    w, d = rng.uniform(0.25, 0.38), rng.uniform(0.18, 0.28)
    n = int(rng.integers(3, 5))
    t = rng.uniform(0.012, 0.018) * n
    if variant == "folded":
        return [make_part("body", "body", _folded(rng, w, d, t, 0.0, n), mat)]
    parts = []
    z = 0.0
    for i in range(int(rng.integers(2, 4))):
        parts.append(make_part("body" if i == 0 else f"body_{i}", "body",
                               _folded(rng, w, d, t, z, n), mat if i % 2 == 0 else M.fabric(rng)))
        z += t
    return parts


@register("rug", parts=("body",), extra_parts=("fringe",), size_range=(1.2, 3.5), density=300,
          variants=("rectangular", "round", "runner"), placement="floor")
def rug(rng: np.random.Generator, variant: str) -> list[Part]:
    t = rng.uniform(0.008, 0.02)
    mat = M.fabric(rng)
    if variant == "round":
        r = rng.uniform(0.6, 1.2)
        body = S.lathe([(r - 0.006, 0.0), (r, t * 0.5), (r - 0.006, t)], sections=48)
        return [make_part("body", "body", body, mat)]
    if variant == "runner":
        w, d = rng.uniform(2.0, 3.2), rng.uniform(0.6, 0.9)
    else:
        w = rng.uniform(1.4, 3.2)
        d = w * rng.uniform(0.6, 0.8)
    parts = [make_part("body", "body", bevel_box((w, d, t), center=(0, 0, t / 2), bevel=t / 3),
                       mat)]
    if rng.random() < 0.6:
        fl = rng.uniform(0.04, 0.08)
        fringe_mat = M.solid((0.92, 0.9, 0.84), "fabric", 0.95)
        w_total = w + 2 * fl
        if w_total > 3.5:  # keep the largest extent within the category's range
            fl = (3.5 - w) / 2 - 1e-3
        for i, sx in enumerate((-1, 1)):
            strip = S.box((fl + 0.01, d * 0.96, 0.003), center=(sx * (w / 2 + fl / 2 - 0.005), 0,
                                                               0.0015))
            parts.append(make_part(f"fringe_{i}", "fringe", strip, fringe_mat))
    return parts
