"""Small things on desks, tables and shelves: saucer, bookend, computer mouse, telephone, a
stack of paper, CD case, headphones, water pitcher, soap dish, soap dispenser, squeeze tube,
ball, hat, bathroom scale, dumbbell, paper cutter and a case of water bottles.

Each stands or lies on its bottom at z = 0, front toward +Y.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Material, Part, make_part
from ..registry import register
from ._casework import black, white
from ._detail_b import each
from ._household import ring, shell
from ._kit import revolute, rot


@register("saucer", parts=("body",), extra_parts=("well", "rim", "foot_ring", "trim", "dry_foot", "backstamp"),
          size_range=(0.11, 0.18), density=2000, variants=("tea", "coffee", "espresso"),
          placement="surface", groups={"body": ("well", "rim", "foot_ring")})
def saucer(rng: np.random.Generator, variant: str) -> list[Part]:
    r = {"tea": rng.uniform(0.07, 0.085), "coffee": rng.uniform(0.065, 0.075),
         "espresso": rng.uniform(0.056, 0.064)}[variant]
    mat = M.ceramic(rng)
    fh, bh = 0.003, rng.uniform(0.006, 0.008)
    well = r * rng.uniform(0.42, 0.5)  # the ring the cup stands in
    rb = well + (r - well) * 0.35
    base = S.lathe([(well * 0.8, fh), (well * 0.82, fh + 0.002), (rb, bh)], sections=36)
    rim = ring([(well, bh), (rb, bh), (r, bh + rng.uniform(0.008, 0.012)), (r - 0.006, bh + 0.01)],
               sections=32)
    foot = ring([(well * 0.7, 0.0), (well * 0.82, 0.0), (well * 0.82, fh), (well * 0.7, fh)],
                sections=24)
    rh = rim.mesh.bounds[1, 2]
    gold = M.solid(M.jitter(rng, (0.83, 0.68, 0.3), 0.03), "metal", 0.3, 0.9)
    # the gilded line round the rim's edge
    trim = ring([(r - 0.0045, rh - 0.0025), (r - 0.0005, rh - 0.0006), (r - 0.0005, rh),
                 (r - 0.0045, rh - 0.0018)], sections=32)
    return [make_part("well", "well", base, mat), make_part("rim", "rim", rim, mat),
            make_part("foot_ring", "foot_ring", foot, mat), make_part("trim", "trim", trim, gold),
            # the painted spray on the rim's front
            # the gilded line painted round the well, flush with its floor, where the cup stands
            # the unglazed ring under the foot it was fired standing on
            make_part("dry_foot", "dry_foot", ring([(well * 0.71, 0.0), (well * 0.81, 0.0), (well * 0.81, 0.0006),
                                                    (well * 0.71, 0.0006)], sections=24),
                      Material((0.85, 0.8, 0.72, 1.0), 0.9, 0.0, "ceramic")),
            # the maker's mark printed under the well, inside the foot ring, clear of the table
            make_part("backstamp", "backstamp", S.cylinder(well * 0.45, 0.0003, center=(0, 0, fh - 0.00015), sections=16),
                      M.solid(M.jitter(rng, (0.2, 0.3, 0.6), 0.05)[:3], "paint", 0.5))]


@register("bookend", parts=("base", "upright"), extra_parts=("brace", "ornament", "pad", "foot", "screw", "hem"),
          size_range=(0.1, 0.26), density=3000, variants=("metal_l", "wooden", "figure"),
          placement="surface")
def bookend(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.1, 0.14), rng.uniform(0.1, 0.16), rng.uniform(0.14, 0.22)
    if variant == "metal_l":  # a bent sheet: the base slides under the books, the upright holds
        mat = M.metal(rng)
        t = 0.002
        out = [make_part("base", "base", S.box((w, d, t), center=(0, 0, t / 2)), mat),
               make_part("upright", "upright", S.box((w, t, h), center=(0, -d / 2 + t / 2, h / 2)), mat),
               make_part("pad", "pad", S.box((w * 0.8, d * 0.5, 0.002), center=(0, 0.0, t + 0.001)),
                         M.solid((0.1, 0.1, 0.1), "rubber")),
               # the hemmed top edge of the upright, folded over for stiffness
               make_part("hem", "hem", S.box((w, t * 2, 0.008), center=(0, -d / 2 + t, h - 0.004)), mat)]
        return out + _felt_feet(w, d, 0.0, t)
    mat = M.wood(rng) if variant == "wooden" else M.stone(rng)
    t = rng.uniform(0.015, 0.025)
    out = [make_part("base", "base", S.box((w, d, t), center=(0, 0, t / 2), bevel=0.002), mat),
           make_part("upright", "upright", S.box((w, t * 1.5, h - t), center=(0, -d / 2 + t * 0.75, t + (h - t) / 2),
                                                 bevel=0.002), mat)]
    if variant == "wooden":
        out.append(make_part("brace", "brace", S.hull(np.array(
            [[-0.005, -d / 2 + t * 1.5, t], [0.005, -d / 2 + t * 1.5, t], [-0.005, -d / 2 + t * 1.5, t + h * 0.5],
             [0.005, -d / 2 + t * 1.5, t + h * 0.5], [-0.005, -d / 2 + t * 1.5 + d * 0.4, t],
             [0.005, -d / 2 + t * 1.5 + d * 0.4, t]])), mat))
    else:
        out.append(make_part("ornament", "ornament", S.ellipsoid((w * 0.35, d * 0.25, h * 0.3),
                                                                  center=(0, -d / 2 + t * 1.5 + d * 0.25, t + h * 0.3)),
                             mat))
    # the two screws up through the base into the upright, their heads flush underneath
    steel = M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8)
    out += [make_part(f"screw_{k}", "screw", S.cylinder(0.004, 0.0015, center=(sx * w * 0.25, -d / 2 + t * 0.75, 0.00075), sections=8),
                      steel) for k, sx in enumerate((-1, 1))]
    return out + _felt_feet(w, d, 0.012, t)


def _felt_feet(w: float, d: float, inset: float, t: float) -> list[Part]:
    """Four felt pads let into the underside of a base ``w`` x ``d`` (flush with it)."""
    felt = M.solid((0.2, 0.2, 0.2), "fabric", 0.95)
    r = min(0.008, w / 10)
    return [make_part(f"foot_{k}", "foot",
                      S.cylinder(r, min(0.0015, t * 0.6), center=(sx * (w / 2 - inset - r - 0.002),
                                                                  sy * (d / 2 - inset - r - 0.002),
                                                                  min(0.0015, t * 0.6) / 2), sections=10), felt)
            for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)])]


@register("mouse", parts=("body", "button"),
          extra_parts=("scroll_wheel", "cable", "foot", "side_button", "sensor", "switch", "dpi_button", "battery_cover",
                       "strain_relief"),
          size_range=(0.08, 0.14), density=500, variants=("wired", "wireless", "ergonomic"),
          placement="surface")
def mouse(rng: np.random.Generator, variant: str) -> list[Part]:
    L, w = rng.uniform(0.095, 0.125), rng.uniform(0.055, 0.07)
    h = rng.uniform(0.035, 0.045) if variant != "ergonomic" else rng.uniform(0.05, 0.065)
    mat = black() if rng.uniform() < 0.6 else white(rng, "plastic")
    body = S.ellipsoid((w / 2, L / 2, h), center=(0, 0, 0.0))
    # the lower half of the ellipsoid is cut off by hulling only the points above z = 0.002
    pts = body.mesh.vertices
    pts = np.vstack([pts[pts[:, 2] >= 0.003], np.c_[pts[:, :2] * 0.98, np.full(len(pts), 0.003)]])
    out = [make_part("body", "body", S.hull(pts), mat)]
    for k, sx in enumerate((-1, 1)):
        out.append(make_part(f"button_{k}", "button", S.box((w * 0.38, L * 0.3, 0.004),
                                                             center=(sx * w * 0.2, L * 0.28, h * 0.72)), mat))
    out.append(make_part("scroll_wheel", "scroll_wheel", S.cylinder(0.009, 0.006, center=(0, L * 0.3, h * 0.78),
                                                                    axis=(1, 0, 0), sections=14), black()))
    # the sensitivity (dpi) button behind the wheel, flush with the shell
    out.append(make_part("dpi_button", "dpi_button", S.box((0.006, 0.009, 0.003), center=(0, L * 0.12, h * 0.955)), black()))
    # four glide pads underneath, round the optical sensor's window
    glide = M.solid((0.9, 0.9, 0.9), "plastic", 0.2)
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        out.append(make_part(f"foot_{k}", "foot", S.box((w * 0.22, L * 0.12, 0.003),
                                                         center=(sx * w * 0.2, sy * L * 0.3, 0.0015)), glide))
    out.append(make_part("sensor", "sensor", S.cylinder(0.005, 0.002, center=(0, 0, 0.001), sections=10),
                         M.solid((0.5, 0.05, 0.05), "glass", 0.1)))
    if variant != "wired":
        # thumb buttons on the left flank
        for k in range(2):
            y = L * (0.08 - 0.16 * k)
            out.append(make_part(f"side_button_{k}", "side_button",
                                 S.box((0.004, L * 0.13, 0.007), center=(-w * 0.47, y, h * 0.42), bevel=0.001),
                                 black()))
        # the power switch underneath, behind the sensor
        out.append(make_part("switch", "switch", S.box((0.006, 0.01, 0.002), center=(0, -L * 0.15, 0.001)),
                             black()))
        # the battery door in the shell's underside, between the front glide pads
        out.append(make_part("battery_cover", "battery_cover", S.box((w * 0.3, L * 0.15, 0.001), center=(0, L * 0.14, 0.0025)), mat))
    else:
        out.append(make_part("cable", "cable", S.tube([(0, L / 2 - 0.004, h * 0.3), (0, L / 2 + 0.006, h * 0.15),
                                                       (0.002, L / 2 + 0.009, 0.003)], 0.0018, sections=6),
                             black("rubber")))
        # the rubber sleeve round the cable where it leaves the shell
        out.append(make_part("strain_relief", "strain_relief", S.cylinder(0.003, 0.008, center=(0, L / 2, h * 0.3), axis=(0, 1, 0),
                                                                          sections=8), black("rubber")))
    return out


@register("telephone", parts=("base", "handset"),
          extra_parts=("keypad", "key", "cord", "display", "earpiece", "mouthpiece", "hook_switch",
                       "speaker_grille", "foot", "antenna"),
          size_range=(0.15, 0.26), density=600, variants=("desk", "cordless", "office"),
          placement="surface")
def telephone(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.16, 0.22), rng.uniform(0.16, 0.22)
    h = rng.uniform(0.05, 0.07)
    mat = black() if rng.uniform() < 0.6 else white(rng, "plastic")
    base = S.hull(np.array([[sx * w / 2, sy * d / 2, 0] for sx in (-1, 1) for sy in (-1, 1)]
                           + [[sx * w / 2, -d / 2, h] for sx in (-1, 1)]
                           + [[sx * w / 2, d / 2, h * 0.45] for sx in (-1, 1)]))
    out = [make_part("base", "base", base, mat)]
    if variant == "cordless":
        out.append(make_part("handset", "handset", S.box((0.05, 0.03, 0.16), center=(-w / 2 + 0.04, -d / 2 + 0.02, h + 0.08 - 0.02),
                                                         bevel=0.008), mat))
    else:
        out.append(make_part("handset", "handset", S.box((0.05, d * 0.95, 0.035), center=(-w / 2 + 0.03, 0, h * 0.75 + 0.0175),
                                                         bevel=0.01), mat))
        out.append(make_part("cord", "cord", S.tube([(-w / 2 + 0.005, d * 0.3, h * 0.6), (-w / 2 - 0.005, d * 0.3, 0.02),
                                                     (-w / 2 + 0.01, d * 0.42, 0.01)], 0.003, sections=6), black()))
    # the keypad: a bezel let into the sloping top, twelve keys standing out of it
    x0 = w * 0.05
    slope = np.arctan2(h * 0.55, d)

    def top_z(y):
        return h * 0.45 + (h * 0.55) * (d / 2 - y) / d

    keycol = M.solid((0.7, 0.7, 0.72), "plastic", 0.5)
    yc = d * 0.3 - 1.5 * d * 0.14
    out.append(make_part("keypad", "keypad", S.box((0.07, d * 0.56 + 0.016, 0.004),
                                                   center=(x0 + 0.02, yc, top_z(yc) - 0.0015),
                                                   R=rot((1, 0, 0), -slope)), black()))
    for i in range(3):
        for j in range(4):
            y = d * 0.3 - j * d * 0.14
            out.append(make_part(f"key_{3 * j + i}", "key", S.box((0.014, 0.012, 0.006),
                                                                  center=(x0 + i * 0.02, y, top_z(y) - 0.002),
                                                                  R=rot((1, 0, 0), -slope)), keycol))
    # the handset's earpiece and mouthpiece grilles, the speaker grille and the rubber feet
    if variant == "cordless":
        hx, hy, hz = -w / 2 + 0.04, -d / 2 + 0.02, h + 0.06
        out.append(make_part("earpiece", "earpiece", S.cylinder(0.012, 0.003, center=(hx, hy + 0.0165, hz + 0.05),
                                                                axis=(0, 1, 0), sections=10), black()))
        out.append(make_part("mouthpiece", "mouthpiece", S.box((0.02, 0.003, 0.008),
                                                               center=(hx, hy + 0.0165, hz - 0.06)), black()))
        out.append(make_part("antenna", "antenna", S.cylinder(0.005, 0.03, center=(hx + 0.015, hy, hz + 0.095),
                                                              sections=8), black()))
    else:
        hx, hz = -w / 2 + 0.03, h * 0.75 + 0.035
        for name, y in (("earpiece", -d * 0.38), ("mouthpiece", d * 0.38)):
            out.append(make_part(name, name, S.cylinder(0.02, 0.004, center=(hx, y, hz + 0.002), sections=12),
                                 black()))
        # the hook switch the handset presses down in its cradle
        out.append(make_part("hook_switch", "hook_switch", S.box((0.012, 0.01, 0.012),
                                                                  center=(-w / 2 + 0.06, 0, h * 0.75 - 0.002)),
                             keycol))
    # a column of keys at the right edge of the top: an office phone's three line keys, a desk
    # phone's redial and flash keys, a cordless base's page and speaker keys
    names = {"office": ("line_key_0", "line_key_1", "line_key_2"), "desk": ("redial_key", "flash_key"),
             "cordless": ("page_key", "speaker_key")}[variant]
    for k, name in enumerate(names):
        y = d * 0.1 - 0.02 * k
        out.append(make_part(name, "key", S.box((0.012, 0.01, 0.006), center=(w / 2 - 0.009, y, top_z(y) - 0.002),
                                                R=rot((1, 0, 0), -slope)), keycol))
    out.append(make_part("speaker_grille", "speaker_grille",
                         S.box((0.04, 0.03, 0.003), center=(w * 0.35, d * 0.25, top_z(d * 0.25) - 0.0005),
                               R=rot((1, 0, 0), -slope)), black()))
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        out.append(make_part(f"foot_{k}", "foot", S.cylinder(0.006, 0.002, center=(sx * (w / 2 - 0.015),
                                                                                  sy * (d / 2 - 0.015), 0.001),
                                                             sections=8), black("rubber")))
    if variant == "office":
        out.append(make_part("display", "display", S.box((w * 0.5, 0.004, 0.03),
                                                         center=(w * 0.1, -d / 2 + 0.04, h * 0.9)),
                             M.solid((0.3, 0.5, 0.4), "glass", 0.1)))
    return out


@register("paper", parts=("sheet",), extra_parts=("clip", "lever", "wrapper", "label", "tear_strip", "seal"),
          size_range=(0.2, 0.44), density=800, variants=("stack", "ream", "loose"),
          placement="surface")
def paper(rng: np.random.Generator, variant: str) -> list[Part]:
    a4 = rng.uniform() < 0.6
    w, d = (0.21, 0.297) if a4 else (0.216, 0.279)
    if variant == "ream":
        h = rng.uniform(0.045, 0.055)
        return [make_part("sheet", "sheet", S.box((w, d, h - 0.002), center=(0, 0, h / 2)),
                          white(rng, "paper")),
                make_part("wrapper", "wrapper", S.box((w + 0.002, d * 0.6, h), center=(0, 0, h / 2)),
                          M.paper(rng)),
                # the brand and grade label printed on the wrapper's top
                make_part("label", "label", S.box((w * 0.6, d * 0.3, 0.0006), center=(0, 0, h + 0.0003)),
                          white(rng, "paper")),
                # the barcode on the wrapper's front, the tear strip along its top and the glued
                # seam where the wrapper closes underneath
                make_part("tear_strip", "tear_strip", S.box((w * 0.9, 0.006, 0.0005), center=(0, d * 0.22, h + 0.00025)),
                          Material((0.85, 0.2, 0.15, 1.0), 0.6, 0.0, "paper")),
                make_part("seal", "seal", S.box((w * 0.5, d * 0.6 - 0.002, 0.0005), center=(0, 0, 0.00025)),
                          M.paper(rng))]
    n = int(rng.integers(3, 9))
    out = []
    z = 0.0
    for k in range(n):
        t = 0.0012 if variant == "stack" else 0.0004
        a = rng.uniform(-0.06, 0.06) if variant == "loose" else rng.uniform(-0.01, 0.01)
        out.append(make_part(f"sheet_{k}", "sheet", S.box((w, d, t), center=(0, 0, z + t / 2), R=rot((0, 0, 1), a)),
                             white(rng, "paper")))
        z += t
    if variant == "stack":
        out.append(make_part("clip", "clip", S.box((0.03, 0.02, z + 0.004), center=(0, d / 2 - 0.008, (z + 0.004) / 2)),
                             black("metal")))
        # the binder clip's two wire levers, folded down over the stack
        wire = M.solid((0.75, 0.75, 0.78), "metal", 0.3, 0.9)
        for k, sx in enumerate((-1, 1)):
            out.append(make_part(f"lever_{k}", "lever", S.tube([(sx * 0.011, d / 2 - 0.006, z + 0.0048),
                                                                (sx * 0.011, d / 2 - 0.034, z + 0.0048)], 0.0008, sections=6),
                                 wire))
    return out


@register("cd_case", parts=("tray", "lid"), extra_parts=("disc", "hinge", "insert", "hub", "spine_card"),
          size_range=(0.12, 0.15), density=1100, variants=("jewel", "slim", "double"),
          placement="surface")
def cd_case(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d = 0.142, 0.125
    t = {"jewel": 0.01, "slim": 0.005, "double": 0.024}[variant]
    clear = M.glass(rng)
    out: list[Part | Joint] = [make_part("tray", "tray", S.box((w, d, t * 0.6), center=(0, 0, t * 0.3)),
                                         M.solid((0.1, 0.1, 0.1), "plastic", 0.3)),
                               make_part("disc", "disc", S.cylinder(0.06, 0.0012, center=(0, 0, t * 0.6 + 0.0006),
                                                                    sections=32), M.solid((0.85, 0.85, 0.9), "plastic", 0.1, 0.5)),
                               make_part("lid", "lid", S.box((w, d, t * 0.35), center=(0, 0, t * 0.6 + t * 0.2),
                                                             ), clear),
                               make_part("insert", "insert", S.box((w - 0.01, d - 0.004, 0.0004),
                                                                   center=(0, 0, t * 0.6 + t * 0.35 + 0.0004)),
                                         M.paper(rng))]
    # the rosette hub holding the disc, the hinge knuckles on the spine side, the spine card
    out.append(make_part("hub", "hub", S.cylinder(0.0075, 0.0025, center=(0, 0, t * 0.6 + 0.00125), sections=12),
                         M.solid((0.1, 0.1, 0.1), "plastic", 0.3)))
    for k, sy in enumerate((-1, 1)):
        out.append(make_part(f"hinge_{k}", "hinge", S.cylinder(0.0025, 0.012, center=(-w / 2 + 0.0025, sy * (d / 2 - 0.008),
                                                                                    t * 0.6), axis=(0, 1, 0), sections=8),
                             clear))
    out.append(make_part("spine_card", "spine_card", S.box((0.0006, d - 0.006, t * 0.5),
                                                            center=(-w / 2 - 0.0003, 0, t * 0.3)), M.paper(rng)))
    out.append(revolute("lid_hinge", "tray", "lid", axis=(0, 1, 0), origin=(-w / 2, 0, t * 0.6), opens=-1.6))
    out.append(Joint("insert_mount", "prismatic", "lid", "insert", (0.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0)))
    return out


@register("headphones", parts=("headband", "ear_cup"),
          extra_parts=("cushion", "cable", "slider", "yoke", "band_pad", "jack", "pivot", "button", "port"),
          size_range=(0.15, 0.24), density=500, variants=("over_ear", "on_ear", "studio"),
          placement="surface")
def headphones(rng: np.random.Generator, variant: str) -> list[Part]:
    # lying flat on the desk: the band arcs in the XY plane, the cups lie on their backs
    span = rng.uniform(0.15, 0.19)
    r = rng.uniform(0.035, 0.05) if variant != "on_ear" else rng.uniform(0.028, 0.035)
    mat = black() if rng.uniform() < 0.7 else white(rng, "plastic")
    cup_h = 0.03
    a = np.linspace(0.15 * np.pi, 0.85 * np.pi, 9)
    R = span / 2
    arc = np.c_[R * np.cos(a), R * np.sin(a) * 0.9 - R * 0.35, np.full(len(a), 0.012)]
    out = [make_part("headband", "headband", S.tube(arc, 0.009, sections=8), mat)]
    for k, sx in enumerate((-1, 1)):
        x = sx * R * np.cos(0.15 * np.pi)
        y = -R * 0.35 + R * np.sin(0.15 * np.pi) * 0.9 - r * 0.7
        out.append(make_part(f"ear_cup_{k}", "ear_cup", S.cylinder(r, cup_h * 0.6, center=(x, y, cup_h * 0.3),
                                                                  sections=24), mat))
        out.append(make_part(f"cushion_{k}", "cushion", S.cylinder(r * 0.95, cup_h * 0.4, center=(x, y, cup_h * 0.8),
                                                                  sections=24), M.leather(rng)))
        # the sliding extension out of the band's end, and the yoke forking round the cup
        end = arc[0] if sx > 0 else arc[-1]
        out.append(make_part(f"slider_{k}", "slider", S.tube([end, (x, y + r * 1.05, 0.012)], 0.004, sections=8),
                             M.metal(rng)))
        fork = [(x + 1.05 * r * np.cos(t), y + 1.05 * r * np.sin(t), 0.012) for t in np.radians([35, 70, 110, 145])]
        out.append(make_part(f"yoke_{k}", "yoke", S.tube(fork, 0.003, sections=6), mat))
        # the two pivot pins the cup tilts on, where the yoke's arms meet its rim
        metal = M.solid((0.55, 0.55, 0.57), "metal", 0.35, 0.9)
        for j, t in enumerate(np.radians([35, 145])):
            u = np.array([np.cos(t), np.sin(t), 0.0])
            out.append(make_part(f"pivot_{2 * k + j}", "pivot", S.cylinder(0.0035, 0.004, center=(x + u[0] * (r + 0.001), y + u[1] * (r + 0.001), 0.012),
                                                                        axis=tuple(u), sections=8), metal))
    # the padded cushion under the top of the band
    top = arc[3:6]
    out.append(make_part("band_pad", "band_pad", S.tube(top - [0, 0.008, 0], 0.007, sections=8), M.leather(rng)))
    if variant != "studio":
        # a wireless set: the power and two volume buttons round the right cup's rim, flush with
        # it, and the charging port below them
        xr = R * np.cos(0.15 * np.pi)
        yr = -R * 0.35 + R * np.sin(0.15 * np.pi) * 0.9 - r * 0.7
        for j, a in enumerate(np.radians([-35, -50, -65])):
            u = np.array([np.cos(a), np.sin(a), 0.0])
            out.append(make_part(f"button_{j}", "button", S.cylinder(0.003, 0.0015, center=(xr + u[0] * (r - 0.0003), yr + u[1] * (r - 0.0003),
                                                                                            cup_h * 0.3), axis=tuple(u), sections=8), black()))
        out.append(make_part("port", "port", S.box((0.0015, 0.008, 0.003), center=(xr + np.cos(np.radians(-20)) * (r - 0.0012),
                                                                                   yr + np.sin(np.radians(-20)) * (r - 0.0012), cup_h * 0.3),
                                                   R=rot((0, 0, 1), np.radians(-20))), black()))
    if variant == "studio":
        # the coiled cable leaves the left cup, ending in its jack plug
        xl = -R * np.cos(0.15 * np.pi)
        yl = -R * 0.35 + R * np.sin(0.15 * np.pi) * 0.9 - r * 0.7
        path = [(xl - r * 0.5, yl - r * 0.7, 0.006), (xl - r * 0.2, yl - r * 1.5, 0.006), (xl + r * 0.6, yl - r * 1.8, 0.006)]
        out.append(make_part("cable", "cable", S.tube(path, 0.0025, sections=6), black("rubber")))
        out.append(make_part("jack", "jack", S.cylinder(0.0035, 0.025, center=(xl + r * 0.6 + 0.0125, yl - r * 1.8, 0.006),
                                                        axis=(1, 0, 0), sections=8), M.metal(rng)))
    return out


@register("water_pitcher", parts=("body", "handle"),
          extra_parts=("spout", "lid", "filter", "rim", "foot_ring", "lid_tab", "indicator", "scale", "thumb_rest"),
          size_range=(0.18, 0.32), density=1500, variants=("glass", "filter_jug", "ceramic"),
          placement="surface")
def water_pitcher(rng: np.random.Generator, variant: str) -> list[Part]:
    r, h = rng.uniform(0.055, 0.075), rng.uniform(0.2, 0.28)
    mat = {"glass": M.glass(rng), "filter_jug": M.plastic(rng), "ceramic": M.ceramic(rng)}[variant]
    out = [make_part("body", "body", shell([(r * 0.9, 0.0), (r, h * 0.4), (r * 0.95, h)], 0.004,
                                           bottom=0.006, sections=24), mat),
           make_part("handle", "handle", S.tube([(0, -r + 0.003, h * 0.85), (0, -r - 0.04, h * 0.8),
                                                 (0, -r - 0.04, h * 0.3), (0, -r * 0.95 + 0.003, h * 0.25)],
                                                0.008, sections=8), mat),
           make_part("spout", "spout", S.hull(np.array([[-0.015, r * 0.8, h - 0.03], [0.015, r * 0.8, h - 0.03],
                                                        [-0.02, r * 0.8, h], [0.02, r * 0.8, h],
                                                        [0, r + 0.025, h + 0.005]])), mat)]
    # the lip round the top and the ring the jug stands on
    out.append(make_part("rim", "rim", ring([(r * 0.95 - 0.004, h - 0.006), (r * 0.95 + 0.002, h - 0.004),
                                             (r * 0.95 + 0.002, h), (r * 0.95 - 0.004, h)], sections=24), mat))
    out.append(make_part("foot_ring", "foot_ring", ring([(r * 0.8, 0.0), (r * 0.9 + 0.001, 0.0),
                                                         (r * 0.9 + 0.001, 0.004), (r * 0.8, 0.004)], sections=24),
                         mat))
    # the capacity marks printed up the side
    a = 0.6  # towards the right of the front, clear of the spout
    marks = []
    for k in range(7):
        z = 0.03 + k * h * 0.1
        rz = float(np.interp(z, [0.0, h * 0.4, h], [r * 0.9, r, r * 0.95]))
        marks.append(S.box((0.02 if k % 2 == 0 else 0.012, 0.0008, 0.0015),
                           center=(np.sin(a) * (rz + 0.0002), np.cos(a) * (rz + 0.0002), z), R=rot((0, 0, 1), -a)))
    out.append(make_part("scale", "scale", marks, white(rng, "paper")))
    # the thumb rest on the handle's top, and the maker's mark under the floor
    out.append(make_part("thumb_rest", "thumb_rest", S.box((0.016, 0.02, 0.008), center=(0, -r - 0.03, h * 0.82 + 0.006), bevel=0.002),
                         mat))
    if variant == "filter_jug":
        lid_mat = white(rng, "plastic")
        out.append(make_part("lid", "lid", S.cylinder(r * 0.95, 0.012, center=(0, 0, h + 0.006)), lid_mat))
        out.append(make_part("filter", "filter", S.cylinder(r * 0.35, h * 0.35, center=(0, 0, h - h * 0.175)),
                             white(rng, "plastic")))
        # the flip tab over the spout and the filter-change indicator on the lid
        out.append(make_part("lid_tab", "lid_tab", S.box((0.03, 0.02, 0.004), center=(0, r * 0.8, h + 0.01)), lid_mat))
        out.append(make_part("indicator", "indicator", S.box((0.02, 0.012, 0.002), center=(0, -r * 0.5, h + 0.0125)),
                             M.solid((0.2, 0.25, 0.3), "glass", 0.1)))
    return out


@register("soap_dish", parts=("dish",), extra_parts=("rib", "foot", "lip"),
          size_range=(0.09, 0.16), density=1800, variants=("ceramic", "slotted", "footed"),
          placement="surface")
def soap_dish(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.1, 0.14), rng.uniform(0.07, 0.1)
    mat = M.ceramic(rng) if variant != "slotted" else M.plastic(rng)
    fh = 0.006 if variant == "footed" else 0.0
    t = 0.005
    h = 0.02
    walls = [S.box((w, d, t), center=(0, 0, fh + t / 2)),
             S.box((w, t, h), center=(0, -d / 2 + t / 2, fh + h / 2)),
             S.box((w, t, h), center=(0, d / 2 - t / 2, fh + h / 2)),
             S.box((t, d - 2 * t, h), center=(-w / 2 + t / 2, 0, fh + h / 2)),
             S.box((t, d - 2 * t, h), center=(w / 2 - t / 2, 0, fh + h / 2))]
    out = [make_part("dish", "dish", walls, mat)]
    # the drain lip at the right end, a notch in the wall the water runs out over
    out.append(make_part("lip", "lip", S.box((0.012, 0.025, 0.004), center=(w / 2 + 0.004, 0, fh + t + 0.002)), mat))
    n = 4
    for k in range(n):  # the ribs the soap rests on, so it drains
        out.append(make_part(f"rib_{k}", "rib", S.box((0.004, d - 2 * t, 0.004),
                                                       center=(-w / 3 + k * w / 4.5, 0, fh + t + 0.002)), mat))
    if fh:
        for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            out.append(make_part(f"foot_{k}", "foot", S.cylinder(0.006, fh, center=(sx * (w / 2 - 0.012),
                                                                                  sy * (d / 2 - 0.012), fh / 2),
                                                                 sections=10), mat))
    return out


@register("soap_dispenser", parts=("body", "pump"),
          extra_parts=("nozzle", "collar", "label", "dip_tube", "back_plate", "window", "lock", "pad", "actuator"),
          size_range=(0.12, 0.26), density=1000, variants=("pump_bottle", "wall_mounted", "ceramic"),
          placement="surface")
def soap_dispenser(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "wall_mounted":
        w, d, h = rng.uniform(0.1, 0.13), rng.uniform(0.08, 0.1), rng.uniform(0.16, 0.22)
        mat = white(rng, "plastic")
        # the plate screwed to the wall, the level window, the key lock on top
        return [make_part("body", "body", S.box((w, d, h), center=(0, 0, h / 2 + 0.02), bevel=0.01), mat),
                make_part("pump", "pump", S.box((w * 0.5, 0.02, 0.02), center=(0, d / 2 - 0.01, 0.01)), black()),
                make_part("nozzle", "nozzle", S.cylinder(0.005, 0.02, center=(0, d / 2 - 0.02, 0.01)), black()),
                make_part("back_plate", "back_plate", S.box((w * 0.8, 0.006, h * 0.9),
                                                            center=(0, -d / 2 + 0.003, 0.02 + h * 0.5)), mat),
                make_part("window", "window", S.box((w * 0.2, 0.002, h * 0.35),
                                                    center=(0, d / 2 + 0.0005, 0.02 + h * 0.45)),
                          M.solid((0.6, 0.7, 0.8), "glass", 0.1)),
                make_part("lock", "lock", S.cylinder(0.006, 0.003, center=(0, 0, 0.02 + h + 0.001), sections=10),
                          M.metal(rng))]
    r, h = rng.uniform(0.03, 0.04), rng.uniform(0.12, 0.17)
    mat = M.ceramic(rng) if variant == "ceramic" else M.glass(rng)
    metal = M.metal(rng)
    out = [make_part("body", "body", S.lathe([(r, 0.0), (r, h * 0.85), (r * 0.4, h)]), mat),
           # the cork pad under the base
           make_part("pad", "pad", S.cylinder(r * 0.85, 0.0015, center=(0, 0, 0.00075), sections=16),
                     M.solid((0.65, 0.5, 0.35), "wood", 0.95)),
           make_part("collar", "collar", S.cylinder(r * 0.45, 0.015, center=(0, 0, h + 0.0075)), metal),
           make_part("pump", "pump", S.cylinder(r * 0.2, 0.035, center=(0, 0, h + 0.015 + 0.0175)), metal),
           make_part("nozzle", "nozzle", S.box((0.008, 0.04, 0.01), center=(0, 0.015, h + 0.05 + 0.005)), metal)]
    if variant != "ceramic":
        out.append(make_part("label", "label", S.cylinder(r + 0.0005, h * 0.3, center=(0, 0, h * 0.4)), M.paper(rng)))
        # the dip tube, seen through the glass
        out.append(make_part("dip_tube", "dip_tube", S.cylinder(0.0025, h - 0.01, center=(0, 0, 0.005 + (h - 0.01) / 2),
                                                                sections=8), M.solid((0.9, 0.9, 0.9), "plastic", 0.3)))
    # the press head's finger rest on top of the pump
    out.append(make_part("actuator", "actuator", S.box((0.016, 0.018, 0.004), center=(0, -0.002, h + 0.062)), metal))
    return out


@register("tube", parts=("body", "cap"), extra_parts=("crimp", "shoulder", "label", "cap_ridge"),
          size_range=(0.08, 0.24), density=1000, variants=("toothpaste", "cream", "paint"),
          placement="surface")
def tube(rng: np.random.Generator, variant: str) -> list[Part]:
    L = {"toothpaste": rng.uniform(0.16, 0.2), "cream": rng.uniform(0.12, 0.17),
         "paint": rng.uniform(0.09, 0.12)}[variant]
    r = L * 0.12
    cap_l = 0.02
    mat = M.plastic(rng)
    x0 = -L / 2
    # lying flat: a squeezed, rounded slab from the cap to the crimped end
    body = S.box((L - cap_l - 0.01, r * 2.4, r * 1.6), center=(x0 + cap_l + (L - cap_l - 0.01) / 2, 0, r * 0.8),
                 bevel=r * 0.5)
    return [make_part("body", "body", body, mat),
            make_part("cap", "cap", S.cylinder(r * 0.6, cap_l, center=(x0 + cap_l / 2, 0, r * 0.8), axis=(1, 0, 0),
                                               sections=16), white(rng, "plastic")),
            make_part("crimp", "crimp", S.box((0.01, r * 2.8, r * 0.25), center=(L / 2 - 0.005, 0, r * 0.8)), mat),
            # the shoulder narrowing to the neck the cap screws on, and the printed label
            make_part("shoulder", "shoulder", S.frustum(r * 0.62, r * 0.8, 0.01, center=(x0 + cap_l, 0, r * 0.8),
                                                        axis=(1, 0, 0), sections=12), mat),
            make_part("label", "label", S.box((L * 0.45, r * 1.6, 0.0008),
                                              center=(x0 + cap_l + 0.01 + L * 0.3, 0, r * 1.6 + 0.0004)), M.paper(rng)),
            # the barcode printed near the crimped end
            # the ridges round the cap's edge for grip, and the batch code pressed into the crimp
            make_part("cap_ridge", "cap_ridge", ring([(r * 0.6 - 0.0005, 0.0), (r * 0.6 + 0.0008, 0.0), (r * 0.6 + 0.0008, cap_l * 0.6),
                                                      (r * 0.6 - 0.0005, cap_l * 0.6)], sections=16)
                      .apply(_x_axis(x0 + cap_l * 0.2, r * 0.8)), white(rng, "plastic"))]


def _x_axis(x: float, z: float) -> np.ndarray:
    """(4, 4) transform turning a ring about +Z into one about +X, starting at ``x``, axis at
    height ``z``."""
    T = np.eye(4)
    T[:3, :3] = rot((0, 1, 0), np.pi / 2)
    T[:3, 3] = (x, 0, z)
    return T


@register("ball", parts=("body",), extra_parts=("seam", "valve", "panel", "cover", "number"),
          size_range=(0.06, 0.26), density=100, variants=("soccer", "basketball", "tennis"),
          placement="floor")
def ball(rng: np.random.Generator, variant: str) -> list[Part]:
    r = {"soccer": rng.uniform(0.108, 0.112), "basketball": rng.uniform(0.117, 0.121),
         "tennis": rng.uniform(0.032, 0.034)}[variant]
    col = {"soccer": (0.95, 0.95, 0.95), "basketball": (0.85, 0.4, 0.12), "tennis": (0.8, 0.9, 0.2)}[variant]
    out = [make_part("body", "body", S.ellipsoid((r, r, r), center=(0, 0, r), subdivisions=3),
                     M.solid(M.jitter(rng, col, 0.02), "rubber", 0.7))]
    band = ring([(r * 0.995, r - r * 0.02), (r * 1.01, r - r * 0.02), (r * 1.01, r + r * 0.02),
                 (r * 0.995, r + r * 0.02)], sections=32)
    out.append(make_part("seam", "seam", band, black("rubber")))
    if variant != "tennis":
        out.append(make_part("valve", "valve", S.cylinder(0.004, 0.004, center=(0, 0, 2 * r - 0.0015)), black()))
    if variant == "soccer":
        # the twelve black pentagons, at an icosahedron's vertices (the top one carries the valve)
        phi = (1 + 5 ** 0.5) / 2
        verts = np.array([(0, s1, s2 * phi) for s1 in (-1, 1) for s2 in (-1, 1)]
                         + [(s1, s2 * phi, 0) for s1 in (-1, 1) for s2 in (-1, 1)]
                         + [(s2 * phi, 0, s1) for s1 in (-1, 1) for s2 in (-1, 1)], float)
        verts /= np.linalg.norm(verts, axis=1)[:, None]
        # turn one vertex to the top (the valve's pentagon) and keep the rest in a stable order
        top = verts[0]
        ax = np.cross(top, (0, 0, 1.0))
        ang = np.arccos(np.clip(top[2], -1, 1))
        R = rot(ax / np.linalg.norm(ax), ang)
        ink = black("rubber")
        for k, v in enumerate(verts @ R.T):
            if v[2] < -0.95:  # the pentagon the ball rests on would be inside the floor
                continue
            out.append(make_part(f"panel_{k}", "panel",
                                 S.cylinder(r * 0.2, 0.002, center=(0, 0, r * 0.995 - 0.001), sections=5)
                                 .apply(_place(v, r)), ink))
    elif variant == "basketball":
        # the black channels: a second seam round the poles, and the maker's logo
        band2 = ring([(r * 0.995, r - r * 0.02), (r * 1.01, r - r * 0.02), (r * 1.01, r + r * 0.02),
                      (r * 0.995, r + r * 0.02)], sections=32)
        T = np.eye(4)
        T[:3, :3] = rot((1, 0, 0), np.pi / 2)
        T[:3, 3] = (0, r, r) - T[:3, :3] @ (0, 0, r)
        out.append(make_part("seam_1", "seam", band2.apply(T), black("rubber")))
        # the third channel, the meridian crossing the second at the poles
        T2 = np.eye(4)
        T2[:3, :3] = rot((0, 1, 0), np.pi / 2)
        T2[:3, 3] = (0, 0, r) - T2[:3, :3] @ (0, 0, r)
        out.append(make_part("seam_2", "seam", band2.apply(T2), black("rubber")))
    else:
        # the two felt covers the seam joins (each a half shell round the rubber core), the
        # maker's logo printed on each, and the ball's number under the front one
        felt = M.solid(M.jitter(rng, col, 0.02), "fabric", 0.95)
        th = np.array([0.35, 0.8, 1.2, 1.52])
        ri = r * 0.94
        half = [S.cylinder(ri * np.sin(th[0]), r * 0.05, center=(0, 0, r - ri * np.cos(th[0]) + r * 0.025), sections=12)]
        half += [ring([(ri * np.sin(a), r - ri * np.cos(a)), (r * np.sin(a), r - r * np.cos(a)),
                       (r * np.sin(b), r - r * np.cos(b)), (ri * np.sin(b), r - ri * np.cos(b))], sections=20)
                 for a, b in zip(th[:-1], th[1:], strict=True)]
        flip = np.eye(4)
        flip[:3, :3] = rot((1, 0, 0), np.pi)
        flip[2, 3] = 2 * r
        out.append(make_part("cover", "cover", half, felt))
        out.append(make_part("cover_1", "cover", [h.apply(flip) for h in half], felt))
        out.append(make_part("number", "number", S.box((r * 0.12, 0.0008, r * 0.18), center=(0, r * 0.985, r * 1.12)),
                             black("paper")))
    return out


def _place(v: np.ndarray, r: float) -> np.ndarray:
    """(4, 4) transform taking a patch built on a sphere's top (centre (0, 0, 0), radius ``r``)
    to the direction ``v`` on the ball resting on z = 0 (centre (0, 0, r))."""
    ax = np.cross((0, 0, 1.0), v)
    T = np.eye(4)
    if np.linalg.norm(ax) > 1e-9:
        T[:3, :3] = rot(ax / np.linalg.norm(ax), float(np.arccos(np.clip(v[2], -1, 1))))
    elif v[2] < 0:
        T[:3, :3] = rot((1, 0, 0), np.pi)
    T[:3, 3] = (0, 0, r)
    return T


@register("hat", parts=("crown", "brim"), extra_parts=("band", "button", "eyelet", "strap", "bow", "sweatband", "feather", "chin_strap",
                                                    "binding"),
          size_range=(0.2, 0.42), density=150, variants=("cap", "fedora", "sun_hat"),
          placement="surface")
def hat(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.fabric(rng)
    if variant == "cap":
        r = rng.uniform(0.09, 0.1)
        crown = S.hull(np.vstack([S.ellipsoid((r, r * 1.1, r * 0.9)).mesh.vertices * [1, 1, 1]]).clip(min=[-1, -1, 0])
                       + [0, 0, 0.001])
        out = [make_part("crown", "crown", crown, mat),
               make_part("brim", "brim", S.box((r * 1.6, r * 0.9, 0.004), center=(0, r * 1.1 + r * 0.4, 0.004)), mat),
               make_part("button", "button", S.cylinder(0.008, 0.006, center=(0, 0, r * 0.9 + 0.003)), mat)]
        # the stitched eyelet in each of the crown's six panels and the adjuster strap at the back
        for k, a in enumerate(np.radians([0, 60, 120, 180, 240, 300])):
            el = np.array([np.cos(a) * r * 0.55, np.sin(a) * r * 1.1 * 0.55, r * 0.9 * np.sqrt(1 - 0.55 ** 2)])
            n = el / np.array([r, r * 1.1, r * 0.9]) ** 2
            n /= np.linalg.norm(n)
            out.append(make_part(f"eyelet_{k}", "eyelet", S.cylinder(0.003, 0.002, center=el + 0.001 * n + [0, 0, 0.001],
                                                                     axis=n, sections=8), black("metal")))
        out.append(make_part("strap", "strap", S.box((r * 0.6, 0.004, 0.015), center=(0, -r * 1.1 + 0.003, 0.012)),
                             M.solid((0.1, 0.1, 0.1), "plastic", 0.5)))
        return out
    rb = rng.uniform(0.15, 0.19) if variant == "fedora" else rng.uniform(0.18, 0.21)
    rc, hc = rng.uniform(0.08, 0.09), rng.uniform(0.1, 0.13)
    out = [make_part("brim", "brim", S.cylinder(rb, 0.004, center=(0, 0, 0.002), sections=32), mat),
           make_part("crown", "crown", S.lathe([(rc, 0.004), (rc * 0.95, hc * 0.8), (rc * 0.7, hc)]), mat),
           make_part("band", "band", S.cylinder(rc + 0.002, 0.02, center=(0, 0, 0.015), sections=28),
                     M.solid(M.jitter(rng, (0.15, 0.1, 0.08), 0.03), "fabric", 0.8))]
    # the bow on the band's left side, and the leather sweatband inside the crown's opening
    out.append(make_part("bow", "bow", S.box((0.012, 0.03, 0.024), center=(-rc - 0.006, 0, 0.015), bevel=0.003),
                         M.solid(M.jitter(rng, (0.15, 0.1, 0.08), 0.03), "fabric", 0.8)))
    out.append(make_part("sweatband", "sweatband", ring([(rc - 0.006, 0.004), (rc - 0.002, 0.004), (rc - 0.002, 0.03),
                                                         (rc - 0.006, 0.03)], sections=24), M.leather(rng)))
    # the stitched edge binding round the brim, and an air eyelet each side of the crown
    out.append(make_part("binding", "binding", ring([(rb - 0.004, 0.0), (rb + 0.001, 0.0), (rb + 0.001, 0.005), (rb - 0.004, 0.005)],
                                                    sections=32), out[2].material))
    re = rc * (1 - 0.05 * (hc * 0.5 - 0.004) / (hc * 0.8 - 0.004))
    for k, sx in enumerate((-1, 1)):
        out.append(make_part(f"eyelet_{k}", "eyelet", S.cylinder(0.003, 0.002, center=(sx * (re + 0.0003), 0, hc * 0.5), axis=(1, 0, 0),
                                                                 sections=8), black("metal")))
    if variant == "fedora":  # a small feather tucked in the band beside the bow
        out.append(make_part("feather", "feather", S.ellipsoid((0.004, 0.012, 0.035), center=(-rc - 0.004, 0.02, 0.035), subdivisions=1),
                             M.solid(M.jitter(rng, (0.5, 0.4, 0.3), 0.1), "fabric", 0.9)))
    else:  # the chin cord, lying over the brim at the front
        out.append(make_part("chin_strap", "chin_strap", S.tube([(-rc * 0.9, 0.0, 0.005), (0, rb * 0.7, 0.005), (rc * 0.9, 0.0, 0.005)],
                                                              0.002, sections=6), M.solid((0.3, 0.25, 0.2), "fabric", 0.8)))
    return out


@register("scale", parts=("platform",), extra_parts=("display", "foot", "button", "electrode", "dial", "needle", "battery_cover",
                                                          "unit_button"),
          size_range=(0.25, 0.38), density=800, variants=("glass", "analog", "kitchen"),
          placement="floor")
def scale(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "kitchen":
        w, d, h = rng.uniform(0.18, 0.22), rng.uniform(0.14, 0.18), 0.02
        w = max(w, 0.25)
    else:
        w, d, h = rng.uniform(0.28, 0.34), rng.uniform(0.28, 0.34), rng.uniform(0.02, 0.05)
    mat = M.glass(rng) if variant == "glass" else white(rng, "plastic")
    fh = 0.005
    out = [make_part("platform", "platform", S.box((w, d, h - fh), center=(0, 0, fh + (h - fh) / 2), bevel=0.004), mat),
           make_part("display", "display", S.box((0.06, 0.03, 0.002), center=(0, d / 2 - 0.03, h + 0.001)),
                     M.solid((0.2, 0.25, 0.3), "glass", 0.1))]
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        out.append(make_part(f"foot_{k}", "foot", S.cylinder(0.012, fh, center=(sx * (w / 2 - 0.03), sy * (d / 2 - 0.03),
                                                                              fh / 2), sections=10), black("rubber")))
    # underneath, flush with the platform's bottom: the battery door and the kg/lb unit button
    out.append(make_part("battery_cover", "battery_cover", S.box((0.06, 0.035, 0.001), center=(0, -d * 0.15, fh + 0.0005)), mat))
    out.append(make_part("unit_button", "button" if variant == "kitchen" else "unit_button",
                         S.cylinder(0.004, 0.001, center=(0.05, -d * 0.15, fh + 0.0005), sections=8), black()))
    if variant == "glass":
        # the four steel pads the bare feet stand on (body-fat electrodes)
        for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            out.append(make_part(f"electrode_{k}", "electrode",
                                 S.box((0.05, 0.07, 0.001), center=(sx * w * 0.2, sy * d * 0.2 - 0.02, h + 0.0005)),
                                 M.metal(rng)))
    elif variant == "analog":
        # the dial under the window, and its needle
        out.append(make_part("dial", "dial", S.box((0.09, 0.05, 0.001), center=(0, d / 2 - 0.045, h + 0.0005)),
                             white(rng, "paper")))
        out.append(make_part("needle", "needle", S.box((0.002, 0.03, 0.001), center=(0, d / 2 - 0.045, h + 0.0015)),
                             M.solid((0.8, 0.1, 0.1), "plastic", 0.4)))
    else:
        # the on/off and tare buttons beside the display
        for k, sx in enumerate((-1, 1)):
            out.append(make_part(f"button_{k}", "button", S.box((0.012, 0.008, 0.002),
                                                                 center=(sx * 0.05, d / 2 - 0.03, h + 0.001)), black()))
    return out


@register("dumbbell", parts=("handle", "plate"), extra_parts=("collar", "end_cap", "grip"),
          size_range=(0.2, 0.45), density=7000, variants=("hex", "round", "adjustable"),
          placement="floor")
def dumbbell(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.25, 0.4)
    r = rng.uniform(0.05, 0.09)
    pw = rng.uniform(0.03, 0.05)
    steel = M.metal(rng)
    sec = 6 if variant == "hex" else 24
    body = black("rubber") if variant != "adjustable" else steel
    out = [make_part("handle", "handle", S.cylinder(0.015, L - 2 * pw, center=(0, 0, r), axis=(1, 0, 0)), steel)]
    for k, sx in enumerate((-1, 1)):
        out.append(make_part(f"plate_{k}", "plate", S.cylinder(r, pw, center=(sx * (L / 2 - pw / 2), 0, r),
                                                              axis=(1, 0, 0), sections=sec), body))
        if variant == "adjustable":
            # two smaller plates inside the big one, then the spin-lock collar clamping them
            ti = 0.006
            for j, f in enumerate((0.8, 0.62)):
                out.append(make_part(f"plate_{2 + 2 * k + j}", "plate", S.cylinder(r * f, ti, center=(sx * (L / 2 - pw - ti * (j + 0.5)), 0, r),
                                                                                   axis=(1, 0, 0), sections=sec), body))
            out.append(make_part(f"collar_{k}", "collar", S.cylinder(0.025, 0.018, center=(sx * (L / 2 - pw - 2 * ti - 0.009), 0, r),
                                                                    axis=(1, 0, 0), sections=16), steel))
        else:
            # the steel cap on each head's outer face, stamped with the weight
            out.append(make_part(f"end_cap_{k}", "end_cap", S.cylinder(r * 0.45, 0.003, center=(sx * (L / 2 - 0.0015), 0, r),
                                                                      axis=(1, 0, 0), sections=sec * 2 if sec == 6 else 16),
                                 steel))
    # the knurled grip sleeve in the middle of the handle
    out.append(make_part("grip", "grip", S.cylinder(0.0165, min(0.12, L - 2 * pw - 0.06), center=(0, 0, r),
                                                    axis=(1, 0, 0), sections=12), M.metal(rng)))
    if variant != "adjustable":  # the steel collar where the handle enters each head
        for k, sx in enumerate((-1, 1)):
            out.append(make_part(f"collar_{k}", "collar", S.cylinder(0.022, 0.008, center=(sx * (L / 2 - pw - 0.004), 0, r),
                                                                    axis=(1, 0, 0), sections=12), steel))
    return out


@register("paper_cutter", parts=("base", "blade_arm"),
          extra_parts=("handle", "guide", "hinge", "ruler", "cutting_edge", "foot", "guard"),
          size_range=(0.3, 0.52), density=900, variants=("guillotine", "rotary", "compact"),
          placement="surface")
def paper_cutter(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d = rng.uniform(0.32, 0.5), rng.uniform(0.25, 0.38)
    base_t = 0.02
    out: list[Part | Joint] = [make_part("base", "base", S.box((w, d, base_t), center=(0, 0, base_t / 2)), M.wood(rng) if variant != "compact" else white(rng, "plastic")),
                               make_part("guide", "guide", S.box((0.012, d, 0.012), center=(-w / 2 + 0.006, 0, base_t + 0.006)),
                                         M.metal(rng))]
    # the printed ruler along the back edge, the steel cutting edge the blade shears past, and
    # rubber feet let into the underside
    out.append(make_part("ruler", "ruler", S.box((w - 0.06, 0.02, 0.0006), center=(-0.012, -d / 2 + 0.012, base_t + 0.0003)),
                         white(rng, "paper")))
    out.append(make_part("cutting_edge", "cutting_edge", S.box((0.006, d, 0.0015),
                                                               center=(w / 2 - 0.028, 0, base_t + 0.00075)), M.metal(rng)))
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        out.append(make_part(f"foot_{k}", "foot", S.cylinder(0.008, 0.002, center=(sx * (w / 2 - 0.02), sy * (d / 2 - 0.02), 0.001),
                                                             sections=8), black("rubber")))
    if variant == "rotary":
        out.append(make_part("blade_arm", "blade_arm", S.box((0.03, d, 0.015), center=(w / 2 - 0.03, 0, base_t + 0.0075)),
                             M.metal(rng)))
        out.append(make_part("handle", "handle", S.box((0.04, 0.06, 0.03), center=(w / 2 - 0.03, d * 0.2, base_t + 0.03)),
                             black()))
        return out
    arm = S.box((0.025, d * 0.95, 0.012), center=(w / 2 - 0.0125, 0, base_t + 0.006))
    out.append(make_part("blade_arm", "blade_arm", arm, M.metal(rng)))
    out.append(make_part("handle", "handle", S.cylinder(0.012, 0.08, center=(w / 2 - 0.0125, d * 0.47 - 0.04, base_t + 0.024),
                                                        axis=(0, 1, 0), sections=12), black()))
    out.append(Joint("handle_mount", "prismatic", "blade_arm", "handle", (0.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0)))
    # the clear finger guard along the cutting line, on the base
    out.append(make_part("guard", "guard", S.box((0.004, d * 0.8, 0.02), center=(w / 2 - 0.036, d * 0.05, base_t + 0.01)),
                         M.glass(rng)))
    out.append(revolute("blade_hinge", "base", "blade_arm", axis=(1, 0, 0), origin=(w / 2 - 0.0125, -d * 0.475, base_t),
                        opens=1.2))
    return out


@register("case_of_water_bottles", parts=("bottle", "wrap"), extra_parts=("tray", "cap", "label"),
          size_range=(0.25, 0.42), density=900, variants=("6x4", "4x3", "6x2"),
          placement="floor")
def case_of_water_bottles(rng: np.random.Generator, variant: str) -> list[Part]:
    nx, ny = (int(v) for v in variant.split("x"))
    r = rng.uniform(0.031, 0.034)
    h = rng.uniform(0.2, 0.23)
    clear = M.solid(M.jitter(rng, (0.75, 0.85, 0.95), 0.02), "plastic", 0.1)
    out: list[Part] = []
    caps, labels = [], []
    for i in range(nx):
        for j in range(ny):
            x = (i - (nx - 1) / 2) * 2 * r
            y = (j - (ny - 1) / 2) * 2 * r
            out.append(make_part(f"bottle_{i}_{j}", "bottle", S.transformed(
                S.lathe([(r * 0.97, 0.0), (r * 0.97, h * 0.75), (r * 0.4, h * 0.92), (r * 0.4, h - 0.012)], sections=14),
                np.array([[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, 0.004], [0, 0, 0, 1.0]])), clear))
            caps.append(S.cylinder(r * 0.42, 0.012, center=(x, y, h - 0.006 + 0.004), sections=12))
            labels.append(S.cylinder(r * 0.975, h * 0.22, center=(x, y, 0.004 + h * 0.45), sections=14))
    # each bottle's own cap (``cap``, ``cap_1``, ...) and its printed label wrapped round the body
    out += each("cap", "cap", caps, M.solid(M.jitter(rng, (0.1, 0.3, 0.8), 0.05)))
    out += each("label", "label", labels, M.solid(M.jitter(rng, (0.2, 0.5, 0.85), 0.05), "paper", 0.6))
    W, D = nx * 2 * r, ny * 2 * r
    out.append(make_part("tray", "tray", S.box((W + 0.004, D + 0.004, 0.004), center=(0, 0, 0.002)), M.paper(rng)))
    out.append(make_part("wrap", "wrap", [S.box((W + 0.004, 0.001, h * 0.5), center=(0, sy * (D / 2 + 0.0025), h * 0.4))
                                          for sy in (-1, 1)], M.glass(rng)))
    return out
