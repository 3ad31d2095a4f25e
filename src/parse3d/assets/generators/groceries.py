"""Groceries: bottles, canned food, cereal boxes, detergent bottles and apples.

Bottles, cans and apples are closed lathe solids (their contents are not modelled). A cereal
box shows its large printed face at +Y; a detergent jug has its handle at the back (-Y) and its
spout/cap towards the front.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring
from ._kit import rot


@register("bottle", parts=("body", "cap"),
          extra_parts=("label", "neck_ring", "neck_label", "tamper_ring", "back_label", "foot"),
          size_range=(0.18, 0.36),
          density=1000, variants=("wine", "water", "soda"), placement="surface")
def bottle(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "wine":
        r, h = rng.uniform(0.036, 0.039), rng.uniform(0.29, 0.32)
        neck = 0.0145
        prof = [(r * 0.97, 0.0), (r, 0.004), (r, h * 0.6), (r * 0.85, h * 0.68),
                (neck * 1.15, h * 0.78), (neck, h * 0.97)]
        mat = Material(M.jitter(rng, (0.15, 0.28, 0.15), 0.05), 0.1, 0.0, "glass")
        cap = S.cylinder(neck + 0.0008, h * 0.03 + 0.035, center=(0, 0, h * 0.97 - 0.0175 + h * 0.015),
                         sections=16)
        cap_mat = Material(M.jitter(rng, (0.55, 0.1, 0.12), 0.08), 0.4, 0.6, "metal")
        z_label = (h * 0.12, h * 0.45)
    else:
        r = rng.uniform(0.03, 0.04)
        h = rng.uniform(0.2, 0.28) if variant == "water" else rng.uniform(0.22, 0.31)
        neck = 0.0125
        if variant == "water":
            prof = [(r * 0.9, 0.0), (r, 0.01), (r, h * 0.3), (r * 0.93, h * 0.36), (r, h * 0.42),
                    (r, h * 0.62), (neck * 1.2, h * 0.9), (neck, h * 0.95)]
        else:
            # the body narrows to the petaloid base; its five feet are parts of their own
            prof = [(r * 0.75, 0.0), (r, h * 0.06), (r, h * 0.55), (r * 0.85, h * 0.7),
                    (neck * 1.1, h * 0.9), (neck, h * 0.95)]
        mat = Material((0.82, 0.9, 0.95, 0.4), 0.1, 0.0, "plastic") if variant == "water" else \
            Material(M.jitter(rng, (0.6, 0.3, 0.1), 0.1)[:3] + (0.6,), 0.1, 0.0, "plastic")
        cap = S.cylinder(neck + 0.002, h * 0.06, center=(0, 0, h * 0.97), sections=16)
        cap_mat = M.plastic(rng)
        z_label = (h * 0.42, h * 0.62) if variant == "water" else (h * 0.15, h * 0.5)
    parts = [make_part("body", "body", S.lathe(prof, sections=24), mat),
             make_part("cap", "cap", cap, cap_mat)]
    # the label wraps the straight part of the body
    rl = float(np.interp(np.mean(z_label), [p[1] for p in prof], [p[0] for p in prof]))
    label = ring([(rl - 0.0005, z_label[0]), (rl + 0.0006, z_label[0]), (rl + 0.0006, z_label[1]),
                  (rl - 0.0005, z_label[1])], sections=24)
    parts.append(make_part("label", "label", label, M.paper(rng)))
    # the finish below the cap: the glass lip (wine) or the support ledge and the tamper ring
    # the cap leaves behind when opened (water, soda)
    zc = float(cap.mesh.bounds[0, 2])
    rn = float(np.interp(zc, [p[1] for p in prof], [p[0] for p in prof]))
    if variant == "wine":
        # the neck label (the collar below the capsule)
        zn0 = h * 0.8
        rn0 = float(np.interp(zn0 + 0.01, [p[1] for p in prof], [p[0] for p in prof]))
        parts.append(make_part("neck_label", "neck_label", ring(
            [(rn0 - 0.0006, zn0), (rn0 + 0.0006, zn0), (rn0 + 0.0006, zn0 + 0.02),
             (rn0 - 0.0006, zn0 + 0.02)], sections=16), M.paper(rng)))
        zr = zc - 0.006
        parts.append(make_part("neck_ring", "neck_ring", ring(
            [(rn - 0.001, zr), (rn + 0.0025, zr + 0.001), (rn + 0.0025, zr + 0.004),
             (rn - 0.001, zr + 0.005)], sections=16), mat))
    else:
        parts.append(make_part("tamper_ring", "tamper_ring", ring(
            [(rn - 0.0008, zc - 0.004), (rn + 0.0028, zc - 0.004), (rn + 0.0028, zc - 0.0005),
             (rn - 0.0008, zc - 0.0005)], sections=16), cap_mat))
        zr = zc - 0.009
        parts.append(make_part("neck_ring", "neck_ring", ring(
            [(rn - 0.001, zr), (rn + 0.006, zr + 0.0008), (rn + 0.006, zr + 0.0022),
             (rn - 0.001, zr + 0.003)], sections=16), mat))
    if variant == "soda":  # the five lobes of the petaloid base the bottle stands on
        for k in range(5):
            a = 2 * np.pi * k / 5 + np.pi / 2
            c = (r * 0.55 * np.cos(a), r * 0.55 * np.sin(a), h * 0.035)
            parts.append(make_part(f"foot_{k}", "foot", S.ellipsoid((r * 0.3, r * 0.3, h * 0.035), center=c, subdivisions=1), mat))
    if variant == "wine":  # the back label, opposite the front one, its face flush with the front label's
        # (a bottle lying in a rack's cradle rests on its back: a proud label would lift it off)
        parts.append(make_part("back_label", "back_label", S.box((0.045, 0.0008, (z_label[1] - z_label[0]) * 0.6),
                                                                center=(0, -(rl + 0.0002), np.mean(z_label) + 0.01)),
                               Material((0.93, 0.9, 0.82, 1.0), 0.7, 0.0, "paper")))
    return parts


@register("canned_food", parts=("body",), extra_parts=("label", "lid", "pull_tab", "rivet", "seam"),
          size_range=(0.06, 0.18),
          density=1100, variants=("standard", "tall", "flat"), placement="surface")
def canned_food(rng: np.random.Generator, variant: str) -> list[Part]:
    r, h = {"standard": (rng.uniform(0.036, 0.042), rng.uniform(0.1, 0.12)),
            "tall": (rng.uniform(0.032, 0.038), rng.uniform(0.13, 0.16)),
            "flat": (rng.uniform(0.04, 0.05), rng.uniform(0.045, 0.06))}[variant]
    bead = 0.0025
    prof = [(r - 0.003, 0.0), (r, 0.004), (r, 0.007), (r - bead, 0.008), (r - bead, h - 0.008),
            (r, h - 0.007), (r, h - 0.004), (r - 0.003, h)]
    parts = [make_part("body", "body", S.lathe(prof, sections=28), M.metal(rng))]
    # the paper label sits in the recess between the rolled rims
    label = ring([(r - bead - 0.0002, 0.0085), (r - 0.0002, 0.0085), (r - 0.0002, h - 0.0085),
                  (r - bead - 0.0002, h - 0.0085)], sections=28)
    parts.append(make_part("label", "label", label, M.paper(rng)))
    # the label's glued overlap, at the back
    parts.append(make_part("seam", "seam", S.box((0.006, 0.0006, h - 0.02),
                                                center=(0, -(r - 0.0002) + 0.0003, h / 2)),
                           M.paper(rng)))
    # the lid panel on top, with the ring-pull's rivet and tab on it, in low relief (a twentieth
    # of a millimetre): a can stacked on another rests level on them, as real cans rest on
    # the rim that stands above their ring-pull
    tin = M.metal(rng)
    parts.append(make_part("lid", "lid", S.cylinder(r - 0.004, 0.0002, center=(0, 0, h - 0.00008),
                                                    sections=24), tin))
    parts.append(make_part("rivet", "rivet", S.cylinder(0.0025, 0.0003, center=(0, 0, h - 0.0001),
                                                        sections=10), tin))
    tab_l = min(0.022, r * 0.6)
    parts.append(make_part("pull_tab", "pull_tab", S.box((0.011, tab_l, 0.0002),
                                                         center=(0, tab_l / 2 - 0.004, h - 0.00006)),
                           tin))
    return parts


@register("cereal_box", parts=("body",),
          extra_parts=("label", "flap", "nutrition_panel", "tuck_tab", "ingredients_panel", "logo", "barcode",
                       "back_panel"),
          size_range=(0.2, 0.4),
          density=250, variants=("standard", "family", "slim"), placement="surface")
def cereal_box(rng: np.random.Generator, variant: str) -> list[Part]:
    """Width along x, the large printed face at +Y, thin along y."""
    w, d, h = {"standard": (rng.uniform(0.19, 0.21), rng.uniform(0.06, 0.075), rng.uniform(0.27, 0.3)),
               "family": (rng.uniform(0.25, 0.28), rng.uniform(0.08, 0.09), rng.uniform(0.33, 0.37)),
               "slim": (rng.uniform(0.14, 0.17), rng.uniform(0.05, 0.06), rng.uniform(0.22, 0.26))}[variant]
    card = M.paper(rng)
    body = S.box((w, d, h), center=(0, 0, h / 2), bevel=0.002)
    # the glued top flap
    flap = S.box((w - 0.004, d * 0.5, 0.004), center=(0, 0, h + 0.002), bevel=0.001)
    parts = [make_part("body", "body", body, card), make_part("flap", "flap", flap, card)]
    # a printed panel on the front face (+Y)
    panel = S.box((w * 0.8, 0.001, h * 0.55), center=(0, d / 2 + 0.0005, h * 0.45))
    parts.append(make_part("label", "label", panel, M.paper(rng)))
    # the brand's logo band above the picture, the nutrition facts on the right side, the
    # barcode low on the left side and the tuck tab that locks the top flap at the front
    white = Material((0.95, 0.95, 0.93, 1.0), 0.7, 0.0, "paper")
    parts.append(make_part("nutrition_panel", "nutrition_panel",
                           S.box((0.001, d * 0.8, h * 0.4), center=(w / 2 + 0.0005, 0, h * 0.45)), white))
    parts.append(make_part("tuck_tab", "tuck_tab",
                           S.box((w * 0.3, 0.002, 0.012), center=(0, d / 2 - 0.002, h - 0.007)), card))
    # the ingredients above the barcode on the left side, and the lot code stamped on the top
    parts.append(make_part("ingredients_panel", "ingredients_panel",
                           S.box((0.001, d * 0.8, h * 0.3), center=(-w / 2 - 0.0005, 0, h * 0.55)), white))
    # the brand's logo band above the picture, the barcode low on the left side and the game
    # printed on the back
    parts.append(make_part("logo", "logo", S.box((w * 0.7, 0.001, h * 0.1), center=(0, d / 2 + 0.0005, h * 0.83)),
                           M.paper(rng)))
    parts.append(make_part("barcode", "barcode", S.box((0.001, d * 0.5, 0.025), center=(-w / 2 - 0.0005, 0, h * 0.2)), white))
    parts.append(make_part("back_panel", "back_panel", S.box((w * 0.8, 0.001, h * 0.6), center=(0, -d / 2 - 0.0005, h * 0.5)),
                           M.paper(rng)))
    return parts


@register("detergent_bottle", parts=("body", "cap"),
          extra_parts=("handle", "label", "back_label", "neck_ring", "flip_lid", "window"),
          size_range=(0.18, 0.36), density=1000, variants=("jug", "oval"), placement="surface")
def detergent_bottle(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.plastic(rng)
    if variant == "jug":
        w, d, h = rng.uniform(0.15, 0.19), rng.uniform(0.09, 0.11), rng.uniform(0.22, 0.29)
        hb = h * 0.68
        base = S.box((w, d, hb), center=(0, 0, hb / 2), bevel=0.015)
        # the shoulder narrows to the spout, which sits towards the front (+Y)
        sh = h * 0.18
        shoulder = S.hull(np.vstack([
            [[x, y, hb - 0.01] for x in (-w / 2 + 0.01, w / 2 - 0.01) for y in (-d / 2 + 0.01, d / 2 - 0.01)],
            [[x, y, hb + sh] for x in (-0.03, 0.03) for y in (d * 0.05, d / 2 - 0.015)]]))
        neck_y = d / 2 - 0.03
        neck = S.cylinder(0.018, 0.03, center=(0, neck_y, hb + sh + 0.013), sections=16)
        parts = [make_part("body", "body", [base, shoulder, neck], mat)]
        # the grip: a loop at the back (-Y) from the shoulder's top down into the body
        top_z = hb + sh * 0.7
        path = np.array([[0, -0.005, top_z], [0, -d / 2 + 0.015, top_z + 0.012],
                         [0, -d / 2 - 0.01, top_z - 0.01], [0, -d / 2 - 0.012, hb - 0.03],
                         [0, -d / 2 + 0.01, hb - 0.07]])
        parts.append(make_part("handle", "handle", S.tube(path, 0.012, sections=10), mat))
        cap = S.cylinder(0.022, 0.035, center=(0, neck_y, hb + sh + 0.028 + 0.0175), sections=16)
        zn, rn, cn = hb + sh + 0.024, 0.018, (0, neck_y)
        lw, lh, ly = w * 0.75, hb * 0.6, d / 2
    else:
        w, d, h = rng.uniform(0.09, 0.12), rng.uniform(0.05, 0.065), rng.uniform(0.2, 0.26)
        s = np.array([w / 2, d / 2, 1.0])
        prof = [(0.9, 0.0), (1.0, h * 0.08), (1.0, h * 0.7), (0.55, h * 0.88), (0.3, h * 0.92)]
        body = S.lathe(prof, sections=24)
        body = body.apply(np.diag([*s, 1.0]))
        parts = [make_part("body", "body", body, mat)]
        cap = S.lathe([(0.017, h * 0.92), (0.017, h * 0.92 + 0.03), (0.012, h * 0.92 + 0.036)],
                      sections=16)
        zn, rn, cn = h * 0.92 - 0.004, 0.3 * w / 2, (0, 0)
        lw, lh, ly = w * 0.7, h * 0.45, d / 2
        # the flip-top lid hinged at the back of the cap
        parts.append(make_part("flip_lid", "flip_lid", S.box((0.014, 0.016, 0.005),
                                                             center=(0, -0.002, h * 0.92 + 0.031)),
                               M.plastic(rng)))
    cap_mat = M.plastic(rng)
    parts.append(make_part("cap", "cap", cap, cap_mat))
    # the collar under the cap, and the printed labels front and back
    parts.append(make_part("neck_ring", "neck_ring",
                           S.cylinder(rn + 0.003, 0.004, center=(*cn, zn), sections=16), mat))
    if variant == "jug":
        front = S.box((lw, 0.001, lh), center=(0, ly + 0.0005, hb * 0.45))
        back = S.box((lw * 0.8, 0.001, lh * 0.7), center=(0, -ly - 0.0005, hb * 0.4))
    else:
        # the oval body's flattest faces are at +-Y: its half-depth at mid height
        front = S.box((lw, 0.001, lh), center=(0, ly + 0.0005, h * 0.38))
        back = S.box((lw * 0.8, 0.001, lh * 0.7), center=(0, -ly - 0.0005, h * 0.36))
    parts.append(make_part("label", "label", front, M.paper(rng)))
    parts.append(make_part("back_label", "back_label", back, M.paper(rng)))
    # the clear stripe on the side that shows how much is left, and the lot code under it
    hs = hb if variant == "jug" else h * 0.7
    xs = w / 2 if variant == "jug" else w / 2 * 0.999
    parts.append(make_part("window", "window", S.box((0.001, 0.012, hs * 0.7), center=(xs + 0.0005, 0, hs * 0.45)),
                           Material((0.85, 0.9, 0.95, 0.5), 0.1, 0.0, "plastic")))
    return parts


@register("apple", parts=("body",), extra_parts=("stem", "leaf", "calyx", "sepal", "sticker"), size_range=(0.06, 0.095),
          density=850, variants=("round", "conical", "leafy"), placement="surface")
def apple(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.032, 0.042)
    if variant == "conical":
        h = r * rng.uniform(1.65, 1.85)
        prof = [(r * 0.35, 0.0), (r * 0.7, h * 0.08), (r * 0.9, h * 0.3), (r, h * 0.62),
                (r * 0.85, h * 0.88), (r * 0.35, h)]
    else:
        h = r * rng.uniform(1.55, 1.7)
        prof = [(r * 0.4, 0.0), (r * 0.78, h * 0.1), (r, h * 0.42), (r * 0.95, h * 0.72),
                (r * 0.7, h * 0.92), (r * 0.3, h)]
    hues = [(0.75, 0.1, 0.1), (0.55, 0.75, 0.2), (0.85, 0.65, 0.15), (0.6, 0.08, 0.12)]
    skin = M.food(rng, hues[int(rng.integers(len(hues)))])
    parts = [make_part("body", "body", S.lathe(prof, sections=20), skin)]
    lean = rng.uniform(-0.004, 0.004)
    stem = S.tube([[0, 0, h - 0.003], [lean * 0.5, 0, h + 0.006], [lean, 0.002, h + 0.013]], 0.0015,
                  sections=6)
    parts.append(make_part("stem", "stem", stem, M.food(rng, (0.35, 0.22, 0.1))))
    if variant == "leafy":
        leaf = S.ellipsoid((0.014, 0.006, 0.0015), center=(0.014, 0.002, h + 0.008), subdivisions=1)
        leaf = leaf.apply(np.array([[np.cos(0.4), 0, -np.sin(0.4), 0], [0, 1, 0, 0],
                                    [np.sin(0.4), 0, np.cos(0.4), -0.004], [0, 0, 0, 1]]))
        parts.append(make_part("leaf", "leaf", leaf, M.plant(rng)))
    # the dried calyx in the dimple at the bottom, and the grocer's price sticker on the side
    parts.append(make_part("calyx", "calyx", S.cylinder(r * 0.14, 0.002, center=(0, 0, 0.001), sections=8),
                           M.food(rng, (0.3, 0.22, 0.12))))
    # the calyx keeps the flower's five dried sepals, folded in round its eye
    dry = M.food(rng, (0.28, 0.2, 0.1))
    for k in range(5):
        a = 2 * np.pi * k / 5
        parts.append(make_part(f"sepal_{k}", "sepal",
                               S.box((r * 0.12, 0.0016, 0.0012), center=(r * 0.16 * np.cos(a), r * 0.16 * np.sin(a), 0.0026),
                                     R=rot((0, 0, 1), a)), dry))
    zs = h * 0.5
    rs = float(np.interp(zs, [p[1] for p in prof], [p[0] for p in prof]))
    parts.append(make_part("sticker", "sticker", S.cylinder(0.009, 0.0008, center=(0, rs - 0.0006, zs),
                                                            axis=(0, 1, 0), sections=10),
                           Material((0.95, 0.85, 0.2, 1.0), 0.7, 0.0, "paper")))
    return parts
