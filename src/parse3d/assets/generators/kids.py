"""Children's things: picture books and toy blocks.

A picture book stands like ``book`` and shares its labels (``front_cover``, ``back_cover``,
``spine``, ``pages``), so the two can be candidates of one PAG object; a set of toy blocks is a small stack or scatter of cubes, each its own
``block`` part with the painted ``letter`` on its front face.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._kit import rot


@register("picture_book", parts=("front_cover", "back_cover", "spine", "pages"), extra_parts=("endpaper", "headband"),
          size_range=(0.15, 0.36), density=650,
          variants=("square", "landscape", "board_book"), placement="surface")
def picture_book(rng: np.random.Generator, variant: str) -> list[Part]:
    """Standing upright like ``book`` (same labels and frame): front cover at +Y, spine at -X."""
    w, h = {"square": (rng.uniform(0.2, 0.26),) * 2, "landscape": (rng.uniform(0.28, 0.34), rng.uniform(0.2, 0.24)),
            "board_book": (rng.uniform(0.15, 0.18), rng.uniform(0.15, 0.18))}[variant]
    t = rng.uniform(0.008, 0.014) if variant != "board_book" else rng.uniform(0.02, 0.03)
    c = 0.003 if variant != "board_book" else 0.004
    art = M.paper(rng)
    pages = M.solid((0.96, 0.95, 0.9), "paper", 0.9)
    pw = w - c - 0.003
    out = [make_part("front_cover", "front_cover", S.box((w - c, c, h), center=(c / 2, t / 2 - c / 2, h / 2)), art),
           make_part("back_cover", "back_cover", S.box((w - c, c, h), center=(c / 2, -t / 2 + c / 2, h / 2)), art),
           make_part("spine", "spine", S.box((c, t, h), center=(-w / 2 + c / 2, 0, h / 2)), art),
           make_part("pages", "pages", S.box((pw, t - 2 * c, h - 0.006), center=(-w / 2 + c + pw / 2, 0, h / 2)), pages)]
    # the coloured endpapers pasted inside each cover, the first and last leaves of the block
    endpaper = M.paper(rng)
    out += [make_part(f"endpaper_{k}", "endpaper", S.box((pw, 0.0004, h - 0.006), center=(-w / 2 + c + pw / 2, sy * (t / 2 - c - 0.0002), h / 2)),
                      endpaper) for k, sy in enumerate((1, -1))]
    if variant != "board_book":  # a cased book: the headbands at the head and tail of the spine
        band = M.solid((0.7, 0.15, 0.15), "fabric", 0.8)
        out += [make_part(f"headband_{k}", "headband", S.box((0.003, t - 2 * c, 0.0025), center=(-w / 2 + c + 0.0015, 0, z)), band)
                for k, z in enumerate((0.0015, h - 0.0015))]
    return out


@register("toy_blocks", parts=("block",), extra_parts=("letter",), size_range=(0.08, 0.4), density=600,
          variants=("tower", "scatter", "pyramid"),
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
    blocks = [make_part(f"block_{k}", "block", S.box((s, s, s), center=c[:3], bevel=0.002, R=rot((0, 0, 1), c[3])),
                        M.solid(M.jitter(rng, cols[k % 5], 0.02)[:3], "wood", 0.6)) for k, c in enumerate(centres)]
    # each block's painted letter, raised a little on the face turned to the front
    ink = M.solid((0.97, 0.97, 0.95), "plastic", 0.5)
    letters = []
    for k, c in enumerate(centres):
        R = rot((0, 0, 1), c[3])
        centre = np.asarray(c[:3]) + R @ np.array([0.0, s / 2 + 0.0004, 0.0])
        letters.append(make_part(f"letter_{k}", "letter", S.box((s * 0.55, 0.0008, s * 0.55), center=centre, R=R), ink))
    return blocks + letters
