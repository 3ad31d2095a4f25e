"""Tableware: bowls, plates, wine glasses, vases and candles.

Vessels are revolved (``vessel``) so they have a real inside: a bowl's inner floor is an
internal support surface (fruit goes IN it). Plates are a solid lathe base with a raised rim
ring on top, so they have a flat bottom and a flat well and stack.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring, shell


@register("bowl", parts=("body",), size_range=(0.10, 0.28), density=1200,
          variants=("shallow", "deep", "footed"), placement="surface")
def bowl(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.06, 0.11)
    t = rng.uniform(0.004, 0.006)
    mat = M.ceramic(rng) if rng.random() < 0.75 else M.wood(rng)
    z0 = 0.0
    shapes = []
    if variant == "footed":
        z0 = rng.uniform(0.008, 0.014)
        rb = r * 0.45
        # a triangular foot ring: no flat top of its own for fruit to be "in"
        shapes.append(ring([(rb * 0.8, 0.0), (rb, 0.0), (rb * 0.92, z0 + 0.0005)],
                           sections=24))
    if variant == "shallow":
        h = r * rng.uniform(0.38, 0.48) + 0.012  # deep enough to hold fruit
        prof = [(r * 0.5, 0.0), (r * 0.53, 0.009), (r * 0.88, h * 0.5), (r, h)]
    else:
        h = r * rng.uniform(0.55, 0.75)
        prof = [(r * 0.45, 0.0), (r * 0.85, h * 0.45), (r, h)]
    prof = [(pr, pz + z0) for pr, pz in prof]
    shapes.append(shell(prof, t, bottom=t * 1.2, sections=20))
    return [make_part("body", "body", shapes, mat)]


@register("plate", parts=("body",), size_range=(0.15, 0.30), density=2000,
          variants=("dinner", "side", "deep"), placement="surface")
def plate(rng: np.random.Generator, variant: str) -> list[Part]:
    r = {"dinner": rng.uniform(0.125, 0.14), "side": rng.uniform(0.085, 0.10),
         "deep": rng.uniform(0.105, 0.12)}[variant]
    base_h = rng.uniform(0.006, 0.009)
    rim_h = rng.uniform(0.018, 0.026) if variant == "deep" else rng.uniform(0.006, 0.01)
    well = r * (rng.uniform(0.62, 0.7) if variant == "deep" else rng.uniform(0.7, 0.8))
    mat = M.ceramic(rng)
    rb = well + (r - well) * 0.4  # outer edge of the base, under the rim
    base = S.lathe([(well * 0.6, 0.0), (well * 0.62, 0.002), (rb, base_h)], sections=40)
    # the rim sits on the base's flat top and flares outwards; the well stays a flat disc
    rim = ring([(well, base_h), (rb, base_h), (r, base_h + rim_h), (r - 0.008, base_h + rim_h)],
               sections=32)
    return [make_part("body", "body", [base, rim], mat)]


@register("wine_glass", parts=("bowl", "stem", "foot"), size_range=(0.13, 0.26), density=2500,
          variants=("red", "white", "flute"), placement="surface")
def wine_glass(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.glass(rng)
    foot_r = rng.uniform(0.032, 0.04)
    foot_h = 0.004
    stem_h = rng.uniform(0.06, 0.09)
    stem_r = rng.uniform(0.0035, 0.0045)
    t = 0.0016
    if variant == "red":
        r, h = rng.uniform(0.042, 0.05), rng.uniform(0.09, 0.11)
        prof = [(0.012, 0.0), (r, h * 0.5), (r * 0.82, h)]
    elif variant == "white":
        r, h = rng.uniform(0.034, 0.04), rng.uniform(0.08, 0.1)
        prof = [(0.01, 0.0), (r, h * 0.55), (r * 0.88, h)]
    else:
        r, h = rng.uniform(0.024, 0.029), rng.uniform(0.11, 0.13)
        prof = [(0.008, 0.0), (r, h * 0.6), (r * 0.93, h)]
        stem_h *= 0.85
    z_bowl = foot_h + stem_h
    cup = shell([(pr, pz + z_bowl) for pr, pz in prof], t, bottom=0.006, sections=20)
    stem = S.lathe([(stem_r * 2.2, foot_h), (stem_r, foot_h + 0.006), (stem_r, z_bowl - 0.006),
                    (prof[0][0] * 0.9, z_bowl)], sections=16)
    foot = S.lathe([(foot_r, 0.0), (foot_r * 0.97, foot_h * 0.6), (foot_r * 0.5, foot_h)],
                   sections=32)
    return [make_part("bowl", "bowl", cup, mat), make_part("stem", "stem", stem, mat),
            make_part("foot", "foot", foot, mat)]


@register("vase", parts=("body",), size_range=(0.15, 0.46), density=1800,
          variants=("amphora", "cylinder", "bud"), placement="surface")
def vase(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.ceramic(rng) if rng.random() < 0.7 else M.glass(rng)
    if variant == "amphora":
        r, h = rng.uniform(0.07, 0.1), rng.uniform(0.25, 0.4)
        neck = r * rng.uniform(0.45, 0.6)
        prof = [(r * 0.6, 0.0), (r, h * 0.35), (neck, h * 0.75), (neck, h * 0.9), (neck * 1.3, h)]
        t = 0.005
    elif variant == "cylinder":
        r, h = rng.uniform(0.045, 0.07), rng.uniform(0.2, 0.35)
        prof = [(r, 0.0), (r * rng.uniform(1.0, 1.15), h)]
        t = 0.004
    else:
        r, h = rng.uniform(0.045, 0.06), rng.uniform(0.16, 0.25)
        neck = rng.uniform(0.012, 0.016)
        prof = [(r * 0.7, 0.0), (r, h * 0.25), (neck, h * 0.7), (neck, h * 0.92), (neck * 1.4, h)]
        t = 0.004
    n = 20 if variant == "bud" else 24
    body = shell(prof, t, bottom=t * 2, sections=n)
    return [make_part("body", "body", body, mat)]


def _wax(rng: np.random.Generator) -> Material:
    rgb = [(0.96, 0.94, 0.88), (0.92, 0.86, 0.70), (0.75, 0.15, 0.15), (0.85, 0.80, 0.90)]
    return Material(M.jitter(rng, rgb[int(rng.integers(len(rgb)))], 0.02), 0.7, 0.0, "plastic")


@register("candle", parts=("body",), extra_parts=("wick", "holder"), size_range=(0.06, 0.40),
          density=900, variants=("pillar", "taper", "jar"), placement="surface")
def candle(rng: np.random.Generator, variant: str) -> list[Part]:
    wax = _wax(rng)
    wick_mat = M.solid((0.12, 0.10, 0.08), "fabric", 0.9)
    parts = []
    if variant == "pillar":
        r, h = rng.uniform(0.03, 0.045), rng.uniform(0.07, 0.2)
        body = S.lathe([(r, 0.0), (r, h - 0.004), (r * 0.9, h)], sections=32)
        z_top = h
    elif variant == "taper":
        r, h = rng.uniform(0.009, 0.012), rng.uniform(0.18, 0.26)
        hold_r = rng.uniform(0.035, 0.045)
        hz = rng.uniform(0.05, 0.09)
        holder = S.lathe([(hold_r, 0.0), (hold_r * 0.95, 0.006), (hold_r * 0.35, 0.015),
                          (hold_r * 0.2, hz * 0.7), (r * 1.6, hz - 0.012), (r * 1.6, hz)],
                         sections=24)
        parts.append(make_part("holder", "holder", holder, M.metal(rng)))
        # the taper stands in the holder's socket and narrows towards its tip
        body = S.lathe([(r, hz), (r * 0.9, hz + h - 0.01), (r * 0.55, hz + h)], sections=20)
        z_top = hz + h
    else:
        r, h = rng.uniform(0.035, 0.05), rng.uniform(0.07, 0.11)
        jar = shell([(r, 0.0), (r * 1.02, h)], 0.003, bottom=0.006, sections=24)
        parts.append(make_part("holder", "holder", jar, M.glass(rng)))
        # wax fills the jar's lower part and touches its inner wall
        z_top = h * rng.uniform(0.55, 0.8)
        def r_in(z: float) -> float:
            return r * (1 + 0.02 * z / h) - 0.003 - 0.0003

        body = S.lathe([(r_in(0.006), 0.006), (r_in(z_top), z_top)], sections=32)
    wick = S.cylinder(0.0012, 0.012, center=(0, 0, z_top + 0.006), sections=8)
    parts += [make_part("body", "body", body, wax), make_part("wick", "wick", wick, wick_mat)]
    return parts
