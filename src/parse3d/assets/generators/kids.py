"""Children's things: picture books and toy blocks.

A picture book lies closed on its back cover (like ``book``, whose labels it shares: ``cover``,
``pages``, ``spine``); a set of toy blocks is a small stack or scatter of cubes, each its own
``block`` part.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._kit import rot


@register("picture_book", parts=("cover", "pages"), extra_parts=("spine",), size_range=(0.15, 0.36), density=650,
          variants=("square", "landscape", "board_book"), placement="surface")
def picture_book(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = {"square": (rng.uniform(0.2, 0.26),) * 2, "landscape": (rng.uniform(0.28, 0.34), rng.uniform(0.2, 0.24)),
            "board_book": (rng.uniform(0.15, 0.18), rng.uniform(0.15, 0.18))}[variant]
    t = rng.uniform(0.006, 0.012) if variant != "board_book" else rng.uniform(0.015, 0.025)
    ct = 0.003 if variant != "board_book" else 0.004
    art = M.paper(rng)
    pages = M.solid((0.96, 0.95, 0.9), "paper", 0.9)
    return [make_part("cover_0", "cover", S.box((w, d, ct), center=(0, 0, ct / 2)), art),
            make_part("pages", "pages", S.box((w - 0.006, d - 0.006, t), center=(0.001, 0, ct + t / 2)), pages),
            make_part("cover_1", "cover", S.box((w, d, ct), center=(0, 0, 1.5 * ct + t)), art),
            make_part("spine", "spine", S.box((ct, d, t + 2 * ct), center=(-w / 2 - ct / 2, 0, (t + 2 * ct) / 2)), art)]


@register("toy_blocks", parts=("block",), size_range=(0.08, 0.4), density=600, variants=("tower", "scatter", "pyramid"),
          placement="surface")
def toy_blocks(rng: np.random.Generator, variant: str) -> list[Part]:
    s = rng.uniform(0.035, 0.05)
    cols = [(0.9, 0.15, 0.1), (0.1, 0.4, 0.85), (0.95, 0.8, 0.1), (0.2, 0.7, 0.3), (0.9, 0.5, 0.1)]
    centres = []
    if variant == "tower":
        for k in range(int(rng.integers(3, 7))):
            centres.append((rng.uniform(-0.004, 0.004), rng.uniform(-0.004, 0.004), s / 2 + k * s, rng.uniform(-0.2, 0.2)))
    elif variant == "pyramid":
        n = int(rng.integers(3, 5))
        for row in range(n):
            for j in range(n - row):
                centres.append(((j - (n - row - 1) / 2) * s * 1.02, 0.0, s / 2 + row * s, 0.0))
    else:
        for k in range(int(rng.integers(5, 10))):
            x, y = rng.uniform(-0.15, 0.15, 2)
            centres.append((x + (k % 3) * 0.001, y, s / 2, rng.uniform(0, np.pi / 2)))
    return [make_part(f"block_{k}", "block", S.box((s, s, s), center=c[:3], bevel=0.002, R=rot((0, 0, 1), c[3])),
                      M.solid(M.jitter(rng, cols[k % 5], 0.02)[:3], "wood", 0.6)) for k, c in enumerate(centres)]
