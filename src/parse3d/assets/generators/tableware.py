"""Tableware: bowls, plates, wine glasses, vases and candles.

Vessels are revolved (``vessel``) so they have a real inside: a bowl's inner floor is an
internal support surface (fruit goes IN it). Bowls, plates and vases stand on a foot ring. A
plate is a solid ``well`` with a raised ``rim`` ring on top, so it has a flat well and stacks; a
vase is its ``body``, a ``neck`` band and a flared ``lip``. Where a category's one part was split
so, its old label is a group label over the new parts (``plate:body`` is the whole plate).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring, shell


def _lip(r_out: float, z: float, t: float, bead: float) -> S.Shape:
    """A rolled lip round a wall's top edge (outer radius ``r_out`` at height ``z``, thickness
    ``t``), bulging ``bead`` outwards: a triangular section whose faces slope 27 degrees, so it
    adds no flat annulus (the costliest surface to resolve) and no ledge to stand things on."""
    k = 0.5 * (t + bead)
    return ring([(r_out - t, z - 0.5 * k), (r_out + bead, z + 0.5 * k), (r_out - t, z + 1.5 * k)],
                sections=16)


def _foot_ring(r: float, width: float, h: float) -> S.Shape:
    """A foot ring of outer radius ``r`` standing on z = 0: a triangular section ``width`` wide
    whose ridge reaches 0.5 mm into the underside at height ``h``."""
    return ring([(r - width, 0.0), (r, 0.0), (r - width * 0.5, h + 0.0005)], sections=16)


@register("bowl", parts=("body",), extra_parts=("foot_ring", "rim", "band"), size_range=(0.10, 0.28),
          density=1200, variants=("shallow", "deep", "footed"), placement="surface")
def bowl(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.06, 0.11)
    t = rng.uniform(0.004, 0.006)
    mat = M.ceramic(rng) if rng.random() < 0.75 else M.wood(rng)
    # every bowl stands on a foot ring; a footed bowl's is a tall one
    z0 = rng.uniform(0.008, 0.014) if variant == "footed" else rng.uniform(0.003, 0.005)
    if variant == "shallow":
        h = r * rng.uniform(0.38, 0.48) + 0.012  # deep enough to hold fruit
        prof = [(r * 0.5, 0.0), (r * 0.53, 0.009), (r * 0.88, h * 0.5), (r, h)]
    else:
        h = r * rng.uniform(0.55, 0.75)
        prof = [(r * 0.45, 0.0), (r * 0.85, h * 0.45), (r, h)]
    rb = prof[0][0] * 0.9
    prof = [(pr, pz + z0) for pr, pz in prof]
    body = shell(prof, t, bottom=t * 1.2, sections=20)
    foot = _foot_ring(rb, min(0.008, rb * 0.25), z0)
    rim = _lip(r, h + z0, t, rng.uniform(0.0015, 0.0025))
    # a painted band round the outside just under the rim (a triangular section: no flat
    # annulus to resolve)
    zb0, zb1 = z0 + h * 0.72, z0 + h * 0.82
    ro0, rom, ro1 = (float(np.interp(z, [p_[1] for p_ in prof], [p_[0] for p_ in prof])) for z in (zb0, (zb0 + zb1) / 2, zb1))
    band = ring([(ro0 - 0.001, zb0), (rom + 0.0008, (zb0 + zb1) / 2), (ro1 - 0.001, zb1)], sections=20)
    return [make_part("body", "body", body, mat), make_part("foot_ring", "foot_ring", foot, mat),
            make_part("rim", "rim", rim, mat),
            make_part("band", "band", band, M.solid((0.2, 0.3, 0.6), "ceramic", 0.3))]


@register("plate", parts=("body",), extra_parts=("foot_ring",), size_range=(0.15, 0.30),
          density=2000, variants=("dinner", "side", "deep"), placement="surface",
          groups={"body": ("well", "rim", "foot_ring")})
def plate(rng: np.random.Generator, variant: str) -> list[Part]:
    r = {"dinner": rng.uniform(0.125, 0.14), "side": rng.uniform(0.085, 0.10),
         "deep": rng.uniform(0.105, 0.12)}[variant]
    base_h = rng.uniform(0.006, 0.009)
    rim_h = rng.uniform(0.018, 0.026) if variant == "deep" else rng.uniform(0.006, 0.01)
    well = r * (rng.uniform(0.62, 0.7) if variant == "deep" else rng.uniform(0.7, 0.8))
    mat = M.ceramic(rng)
    fh = 0.003  # the foot ring under the well
    rb = well + (r - well) * 0.4  # outer edge of the base, under the rim
    base = S.lathe([(well * 0.62, fh), (well * 0.64, fh + 0.002), (rb, base_h)], sections=40)
    foot = _foot_ring(well * 0.6, min(0.008, well * 0.1), fh)
    # the rim sits on the base's flat top and flares outwards; the well stays a flat disc
    rim = ring([(well, base_h), (rb, base_h), (r, base_h + rim_h), (r - 0.008, base_h + rim_h)],
               sections=32)
    return [make_part("well", "well", base, mat), make_part("rim", "rim", rim, mat),
            make_part("foot_ring", "foot_ring", foot, mat)]


@register("wine_glass", parts=("bowl", "stem", "foot"), extra_parts=("rim", "knop"), size_range=(0.13, 0.26), density=2500,
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
    # the fire-polished rim: a bead round the mouth, no wider than the bowl below it
    r_top = prof[-1][0]
    rim = ring([(r_top - t, z_bowl + h - 0.002), (r_top + 0.0004, z_bowl + h - 0.001), (r_top - t * 0.5, z_bowl + h - 0.0001)],
               sections=20)
    # the knop: the bead blown round the stem a third of the way up, where fingers hold it
    zk = foot_h + stem_h * 0.35
    knop = S.lathe([(stem_r * 0.9, zk - 0.004), (stem_r * 1.9, zk), (stem_r * 0.9, zk + 0.004)], sections=12)
    return [make_part("bowl", "bowl", cup, mat), make_part("stem", "stem", stem, mat),
            make_part("foot", "foot", foot, mat), make_part("rim", "rim", rim, mat),
            make_part("knop", "knop", knop, mat)]


@register("vase", parts=("body",), extra_parts=("neck", "lip", "foot_ring"),
          size_range=(0.15, 0.46), density=1800, variants=("amphora", "cylinder", "bud"),
          placement="surface", groups={"body": ("neck", "lip", "foot_ring")})
def vase(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.ceramic(rng) if rng.random() < 0.7 else M.glass(rng)
    fh = 0.004  # the foot ring it stands on
    if variant == "cylinder":
        r, h = rng.uniform(0.045, 0.07), rng.uniform(0.2, 0.35)
        r_top = r * rng.uniform(1.0, 1.15)
        t = 0.004
        z_lip = h * 0.93
        r_lip = r + (r_top - r) * 0.93
        body = shell([(r, fh), (r_lip, z_lip)], t, bottom=t * 2, sections=24)
        parts = [make_part("body", "body", body, mat)]
    else:
        if variant == "amphora":
            r, h = rng.uniform(0.07, 0.1), rng.uniform(0.25, 0.4)
            neck = r * rng.uniform(0.45, 0.6)
            prof = [(r * 0.6, fh), (r, h * 0.35), (neck, h * 0.75)]
            t = 0.005
        else:
            r, h = rng.uniform(0.045, 0.06), rng.uniform(0.16, 0.25)
            neck = rng.uniform(0.012, 0.016)
            prof = [(r * 0.7, fh), (r, h * 0.25), (neck, h * 0.7)]
            t = 0.004
        n = 20 if variant == "bud" else 24
        z_neck, z_lip = prof[-1][1], h * 0.9
        body = shell(prof, t, bottom=t * 2, sections=n)
        neck_band = ring([(neck, z_neck), (neck, z_lip), (neck - t, z_lip), (neck - t, z_neck)],
                         sections=16)
        parts = [make_part("body", "body", body, mat), make_part("neck", "neck", neck_band, mat)]
        r_lip, r_top = neck, neck * (1.4 if variant == "bud" else 1.3)
    # the lip flares from the neck (or the wall) to the mouth
    lip = ring([(r_lip, z_lip), (r_top, h), (r_top - t, h), (r_lip - t, z_lip)], sections=16)
    r0 = r if variant == "cylinder" else r * (0.6 if variant == "amphora" else 0.7)
    foot = _foot_ring(r0 * 0.92, min(0.01, r0 * 0.2), fh)
    return parts + [make_part("lip", "lip", lip, mat), make_part("foot_ring", "foot_ring", foot, mat)]


def _wax(rng: np.random.Generator) -> Material:
    rgb = [(0.96, 0.94, 0.88), (0.92, 0.86, 0.70), (0.75, 0.15, 0.15), (0.85, 0.80, 0.90)]
    return Material(M.jitter(rng, rgb[int(rng.integers(len(rgb)))], 0.02), 0.7, 0.0, "plastic")


@register("candle", parts=("body",), extra_parts=("wick", "holder", "drip", "bobeche", "lid", "label", "wick_tab"),
          size_range=(0.06, 0.40),
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
    if variant == "pillar":  # wax that ran down the side when it burned
        parts += [make_part(f"drip_{k}", "drip", S.ellipsoid((0.004, 0.003, 0.012), center=(np.cos(a) * r, np.sin(a) * r, h - 0.016),
                                                             subdivisions=1), wax) for k, a in enumerate((0.4, 2.5))]
    elif variant == "taper":  # the bobeche collar catching drips at the socket
        parts.append(make_part("bobeche", "bobeche", S.cylinder(r * 2.6, 0.004, center=(0, 0, hz + 0.002), sections=16),
                               parts[0].material))
    else:  # the jar's label and the metal tab anchoring the wick
        parts.append(make_part("label", "label", S.cylinder(r * 1.01 + 0.0005, h * 0.35, center=(0, 0, h * 0.45), sections=24),
                               M.solid((0.95, 0.93, 0.88), "paper", 0.6)))
        parts.append(make_part("wick_tab", "wick_tab", S.cylinder(0.005, 0.002, center=(0, 0, 0.006 + 0.001), sections=8),
                               M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)))
    return parts
