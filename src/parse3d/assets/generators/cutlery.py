"""Cutlery: knives, forks and spoons, lying flat with their working end towards +X.

Each piece rests on the table as a real one does: a knife on its side (blade and handle flat),
a fork on its tines' ends and handle, a spoon on the bottom of its bowl and the end of its
handle. Handles point to -X, so ``SIDE_OF`` a plate reads naturally after a turn.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import shell


def _steel(rng: np.random.Generator) -> Material:
    return Material(M.jitter(rng, (0.78, 0.79, 0.8), 0.015), 0.25, 0.95, "metal")


def _slab(outline, z0: float, z1: float) -> S.Shape:
    """A flat convex plate over the (x, y) ``outline`` between heights ``z0`` and ``z1``."""
    return S.prism(np.asarray(outline, float), z0, z1)


def _tapered(x0: float, x1: float, w0: float, w1: float, z0a: float, z0b: float,
             t: float) -> S.Shape:
    """A strip from ``x0`` (width ``w0``, bottom at ``z0a``) to ``x1`` (``w1``, ``z0b``), ``t``
    thick: handles that slope from a raised end down to the table."""
    pts = [(x0, -w0 / 2, z0a), (x0, w0 / 2, z0a), (x1, -w1 / 2, z0b), (x1, w1 / 2, z0b)]
    pts = np.array(pts + [(x, y, z + t) for x, y, z in pts])
    return S.hull(pts)


@register("knife", parts=("blade", "handle"), extra_parts=("bolster", "rivet", "edge", "butt", "motif"),
          size_range=(0.16, 0.38), density=4000, variants=("chef", "table", "paring", "bread"),
          placement="surface")
def knife(rng: np.random.Generator, variant: str) -> list[Part]:
    """A knife on its side: the blade (edge towards -Y) towards +X, the handle towards -X."""
    steel = _steel(rng)
    lb, wb, lh = {"chef": (rng.uniform(0.17, 0.21), rng.uniform(0.042, 0.05), rng.uniform(0.11, 0.13)),
                  "table": (rng.uniform(0.1, 0.12), rng.uniform(0.018, 0.022), rng.uniform(0.1, 0.115)),
                  "paring": (rng.uniform(0.07, 0.09), rng.uniform(0.016, 0.02), rng.uniform(0.09, 0.1)),
                  "bread": (rng.uniform(0.2, 0.23), rng.uniform(0.028, 0.032), rng.uniform(0.11, 0.13)),
                  }[variant]
    tb = 0.002
    lbol = 0.012 if variant != "table" else 0.02
    hh = 0.012 if variant != "table" else 0.007  # handle thickness (lying flat)
    hw = 0.022 if variant != "table" else 0.016
    spine = wb / 2
    if variant in ("chef", "paring"):
        # a curved belly rising to the point at the spine
        outline = [(0, -wb / 2), (lb * 0.7, -wb / 2), (lb * 0.9, -wb * 0.2), (lb, spine * 0.85),
                   (0, spine)]
    elif variant == "table":
        outline = [(0, -wb / 2), (lb * 0.85, -wb / 2), (lb, -wb * 0.1), (lb * 0.95, spine * 0.9),
                   (0, spine * 0.7)]
    else:
        outline = [(0, -wb / 2), (lb * 0.97, -wb / 2), (lb, 0.0), (lb * 0.97, spine), (0, spine)]
    blade = _slab([(x + lbol, y) for x, y in outline], 0.0, tb)
    parts = [make_part("blade", "blade", blade, steel)]
    # the ground edge along the blade's lower side, and the maker's mark etched near the heel
    x_edge = lb * (0.7 if variant in ("chef", "paring") else 0.85 if variant == "table" else 0.97)
    parts.append(make_part("edge", "edge", _slab([(lbol + 0.004, -wb / 2), (lbol + x_edge, -wb / 2),
                                                  (lbol + x_edge, -wb / 2 + 0.002), (lbol + 0.004, -wb / 2 + 0.002)],
                                                 tb, tb + 0.0002), Material((0.9, 0.9, 0.92, 1.0), 0.15, 1.0, "metal")))
    bol = S.box((lbol, min(hw, wb) * 0.95, hh * 0.8), center=(lbol / 2, 0, hh * 0.4), bevel=0.001)
    parts.append(make_part("bolster", "bolster", bol, steel))
    if variant == "table":
        handle = _tapered(0.0, -lh, hw * 0.6, hw, 0.0, 0.0, hh)
        parts.append(make_part("handle", "handle", handle, steel))
        # the pattern's motif on the handle's end
        parts.append(_motif(-lh * 0.88, hh, hw * 0.7))
        return parts
    wood = rng.random() < 0.5
    hmat = M.wood(rng) if wood else Material((0.08, 0.08, 0.09, 1.0), 0.5, 0.0, "plastic")
    handle = S.box((lh, hw, hh), center=(-lh / 2, 0, hh / 2), bevel=0.003)
    parts.append(make_part("handle", "handle", handle, hmat))
    for k, f in enumerate((0.2, 0.5, 0.8)):
        rivet = S.cylinder(0.0032, 0.002, center=(-lh * f, 0, hh - 0.0005), sections=10)
        parts.append(make_part(f"rivet_{k}", "rivet", rivet, steel))
    # the steel cap on the handle's butt end
    parts.append(make_part("butt", "butt", S.box((0.006, hw * 0.9, hh * 0.9), center=(-lh - 0.003, 0, hh * 0.45), bevel=0.001),
                           steel))
    return parts


@register("fork", parts=("handle", "tine"), extra_parts=("neck", "head"),
          size_range=(0.13, 0.3), density=7800, variants=("dinner", "salad", "serving"),
          placement="surface")
def fork(rng: np.random.Generator, variant: str) -> list[Part]:
    """Tines towards +X, the handle towards -X; the tines curve up from the table."""
    steel = _steel(rng)
    lh, lt, wh, n = {"dinner": (rng.uniform(0.12, 0.135), rng.uniform(0.038, 0.045), 0.024, 4),
                     "salad": (rng.uniform(0.1, 0.11), rng.uniform(0.032, 0.038), 0.022, 4),
                     "serving": (rng.uniform(0.16, 0.19), rng.uniform(0.045, 0.055), 0.026, 3),
                     }[variant]
    t = 0.0022
    lift = 0.006  # the neck rises so the handle end and the tines touch the table
    ln = 0.02
    # the handle: wide end on the table at -X, narrowing and rising to the neck
    handle = _tapered(-lh, 0.0, wh, wh * 0.35, 0.0, lift, t + 0.0008)
    parts = [make_part("handle", "handle", handle, steel)]
    neck = _tapered(0.0, ln, wh * 0.35, wh * 0.9, lift, lift, t)
    parts.append(make_part("neck", "neck", neck, steel))
    head = _tapered(ln, ln + 0.012, wh * 0.9, wh, lift, lift * 0.7, t)
    parts.append(make_part("head", "head", head, steel))
    x0 = ln + 0.011
    tw = wh / (2 * n - 1)
    for k in range(n):
        y = -wh / 2 + tw * (2 * k + 0.5)
        pts = np.array([(x0, y - tw / 2, lift * 0.7), (x0, y + tw / 2, lift * 0.7),
                        (x0 + lt, y - tw * 0.35, 0.0), (x0 + lt, y + tw * 0.35, 0.0)])
        tine = S.hull(np.vstack([pts, pts + (0, 0, t)]))
        parts.append(make_part(f"tine_{k}", "tine", tine, steel))
    return parts


def _motif(x: float, z: float, w: float) -> Part:
    """The pattern's raised motif (a shell, a bead, a scroll) on the top face of a handle's
    end about ``x`` (its surface at ``z``), ``w`` across."""
    return make_part("motif", "motif", _slab([(x - w * 0.5, 0.0), (x - w * 0.2, -w * 0.4), (x + w * 0.4, -w * 0.3),
                                              (x + w * 0.4, w * 0.3), (x - w * 0.2, w * 0.4)], z - 0.0003, z + 0.0004),
                     Material((0.7, 0.71, 0.72, 1.0), 0.3, 0.95, "metal"))


@register("spoon", parts=("bowl", "handle"), extra_parts=("neck", "tip", "drop", "motif"),
          size_range=(0.1, 0.32), density=7800, variants=("table", "tea", "soup", "serving"),
          placement="surface")
def spoon(rng: np.random.Generator, variant: str) -> list[Part]:
    """The bowl (open upwards) towards +X, the handle rising from its rim and sloping back down
    to the table at -X."""
    steel = _steel(rng)
    rb, elong, lh = {"table": (rng.uniform(0.02, 0.023), 1.5, rng.uniform(0.12, 0.135)),
                     "tea": (rng.uniform(0.014, 0.016), 1.5, rng.uniform(0.085, 0.095)),
                     "soup": (rng.uniform(0.022, 0.026), 1.1, rng.uniform(0.12, 0.135)),
                     "serving": (rng.uniform(0.027, 0.032), 1.45, rng.uniform(0.17, 0.2)),
                     }[variant]
    depth = rb * 0.42
    bowl = shell([(rb * 0.45, 0.0), (rb * 0.82, depth * 0.45), (rb, depth)], 0.0012,
                 bottom=0.0015, sections=20)
    bowl = bowl.apply(np.diag([elong, 1.0, 1.0, 1.0]))
    xb = rb * elong
    bowl = bowl.apply(np.array([[1, 0, 0, xb], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]]))
    parts = [make_part("bowl", "bowl", bowl, steel)]
    t = 0.0025
    z = depth - 0.001
    ln = rb * 0.9
    neck = _tapered(0.003, -ln, rb * 0.35, rb * 0.3, z - t, z - t * 0.8, t)
    parts.append(make_part("neck", "neck", neck, steel))
    w_end = rb * (0.75 if variant != "tea" else 0.8)
    handle = _tapered(-ln, -lh * 0.85, rb * 0.3, w_end, z - t * 0.8, 0.004, t)
    parts.append(make_part("handle", "handle", handle, steel))
    tip = _tapered(-lh * 0.85, -lh, w_end, w_end * 0.7, 0.004, 0.0, t)
    parts.append(make_part("tip", "tip", tip, steel))
    # the drop: the tapering ridge under the bowl's back that stiffens it where the neck joins,
    # and the pattern's motif on the handle's end
    drop = S.hull(np.array([(0.004, -rb * 0.12, depth * 0.62), (0.004, rb * 0.12, depth * 0.62),
                            (rb * 0.7, -0.0015, depth * 0.18), (rb * 0.7, 0.0015, depth * 0.18),
                            (0.004, -rb * 0.12, depth * 0.9), (0.004, rb * 0.12, depth * 0.9),
                            (rb * 0.7, -0.0015, depth * 0.3), (rb * 0.7, 0.0015, depth * 0.3)]))
    parts.append(make_part("drop", "drop", drop, steel))
    xt = -lh * 0.78
    zt = (z - t * 0.8) + (0.004 - (z - t * 0.8)) * (xt + ln) / (-lh * 0.85 + ln) + t
    parts.append(_motif(xt, zt, w_end * 0.6))
    return parts
