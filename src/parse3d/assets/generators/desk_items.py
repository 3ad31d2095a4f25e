"""Small things on desks, tables and shelves: saucer, bookend, computer mouse, telephone, a
stack of paper, CD case, headphones, water pitcher, soap dish, soap dispenser, squeeze tube,
ball, hat, bathroom scale, dumbbell, paper cutter and a case of water bottles.

Each stands or lies on its bottom at z = 0, front toward +Y.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Part, make_part
from ..registry import register
from ._casework import black, white
from ._household import ring, shell
from ._kit import revolute, rot


@register("saucer", parts=("body",), extra_parts=("well", "rim", "foot_ring"),
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
    return [make_part("well", "well", base, mat), make_part("rim", "rim", rim, mat),
            make_part("foot_ring", "foot_ring", foot, mat)]


@register("bookend", parts=("base", "upright"), extra_parts=("brace", "ornament", "pad"),
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
                         M.solid((0.1, 0.1, 0.1), "rubber"))]
        return out
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
    return out


@register("mouse", parts=("body", "button"), extra_parts=("scroll_wheel", "cable", "foot"),
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
    out.append(make_part("foot", "foot", S.box((w * 0.5, L * 0.6, 0.003), center=(0, 0, 0.0015)),
                         M.solid((0.9, 0.9, 0.9), "plastic", 0.2)))
    return out


@register("telephone", parts=("base", "handset"), extra_parts=("keypad", "key", "cord", "display"),
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
    keys = []
    x0 = w * 0.05
    for i in range(3):
        for j in range(4):
            y = d * 0.3 - j * d * 0.14
            z = h * 0.45 + (h * 0.55) * (d / 2 - y) / d + 0.003
            keys.append(S.box((0.014, 0.012, 0.006), center=(x0 + i * 0.02, y, z - 0.005)))
    out.append(make_part("keypad", "keypad", keys, M.solid((0.7, 0.7, 0.72), "plastic", 0.5)))
    if variant == "office":
        out.append(make_part("display", "display", S.box((w * 0.5, 0.004, 0.03),
                                                         center=(w * 0.1, -d / 2 + 0.04, h * 0.9)),
                             M.solid((0.3, 0.5, 0.4), "glass", 0.1)))
    return out


@register("paper", parts=("sheet",), extra_parts=("clip", "wrapper"),
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
    return out


@register("cd_case", parts=("tray", "lid"), extra_parts=("disc", "hinge", "insert"),
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
    out.append(revolute("lid_hinge", "tray", "lid", axis=(0, 1, 0), origin=(-w / 2, 0, t * 0.6), opens=-1.6))
    out.append(Joint("insert_mount", "prismatic", "lid", "insert", (0.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0)))
    return out


@register("headphones", parts=("headband", "ear_cup"), extra_parts=("cushion", "cable", "slider"),
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
    return out


@register("water_pitcher", parts=("body", "handle"), extra_parts=("spout", "lid", "filter"),
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
    if variant == "filter_jug":
        out.append(make_part("lid", "lid", S.cylinder(r * 0.95, 0.012, center=(0, 0, h + 0.006)), white(rng, "plastic")))
        out.append(make_part("filter", "filter", S.cylinder(r * 0.35, h * 0.35, center=(0, 0, h - h * 0.175)),
                             white(rng, "plastic")))
    return out


@register("soap_dish", parts=("dish",), extra_parts=("rib", "foot"),
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
    n = 4
    out.append(make_part("rib", "rib", [S.box((0.004, d - 2 * t, 0.004), center=(-w / 3 + k * w / 4.5, 0, fh + t + 0.002))
                                        for k in range(n)], mat))
    if fh:
        out.append(make_part("foot", "foot", [S.cylinder(0.006, fh, center=(sx * (w / 2 - 0.012), sy * (d / 2 - 0.012), fh / 2),
                                                         sections=10) for sx in (-1, 1) for sy in (-1, 1)], mat))
    return out


@register("soap_dispenser", parts=("body", "pump"), extra_parts=("nozzle", "collar", "label"),
          size_range=(0.12, 0.26), density=1000, variants=("pump_bottle", "wall_mounted", "ceramic"),
          placement="surface")
def soap_dispenser(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "wall_mounted":
        w, d, h = rng.uniform(0.1, 0.13), rng.uniform(0.08, 0.1), rng.uniform(0.16, 0.22)
        mat = white(rng, "plastic")
        return [make_part("body", "body", S.box((w, d, h), center=(0, 0, h / 2 + 0.02), bevel=0.01), mat),
                make_part("pump", "pump", S.box((w * 0.5, 0.02, 0.02), center=(0, d / 2 - 0.01, 0.01)), black()),
                make_part("nozzle", "nozzle", S.cylinder(0.005, 0.02, center=(0, d / 2 - 0.02, 0.01)), black())]
    r, h = rng.uniform(0.03, 0.04), rng.uniform(0.12, 0.17)
    mat = M.ceramic(rng) if variant == "ceramic" else M.glass(rng)
    metal = M.metal(rng)
    out = [make_part("body", "body", S.lathe([(r, 0.0), (r, h * 0.85), (r * 0.4, h)]), mat),
           make_part("collar", "collar", S.cylinder(r * 0.45, 0.015, center=(0, 0, h + 0.0075)), metal),
           make_part("pump", "pump", S.cylinder(r * 0.2, 0.035, center=(0, 0, h + 0.015 + 0.0175)), metal),
           make_part("nozzle", "nozzle", S.box((0.008, 0.04, 0.01), center=(0, 0.015, h + 0.05 + 0.005)), metal)]
    if variant != "ceramic":
        out.append(make_part("label", "label", S.cylinder(r + 0.0005, h * 0.3, center=(0, 0, h * 0.4)), M.paper(rng)))
    return out


@register("tube", parts=("body", "cap"), extra_parts=("crimp",),
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
            make_part("crimp", "crimp", S.box((0.01, r * 2.8, r * 0.25), center=(L / 2 - 0.005, 0, r * 0.8)), mat)]


@register("ball", parts=("body",), extra_parts=("seam", "valve"),
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
    return out


@register("hat", parts=("crown", "brim"), extra_parts=("band", "button"),
          size_range=(0.2, 0.42), density=150, variants=("cap", "fedora", "sun_hat"),
          placement="surface")
def hat(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.fabric(rng)
    if variant == "cap":
        r = rng.uniform(0.09, 0.1)
        crown = S.hull(np.vstack([S.ellipsoid((r, r * 1.1, r * 0.9)).mesh.vertices * [1, 1, 1]]).clip(min=[-1, -1, 0])
                       + [0, 0, 0.001])
        return [make_part("crown", "crown", crown, mat),
                make_part("brim", "brim", S.box((r * 1.6, r * 0.9, 0.004), center=(0, r * 1.1 + r * 0.4, 0.004)), mat),
                make_part("button", "button", S.cylinder(0.008, 0.006, center=(0, 0, r * 0.9 + 0.003)), mat)]
    rb = rng.uniform(0.15, 0.19) if variant == "fedora" else rng.uniform(0.18, 0.21)
    rc, hc = rng.uniform(0.08, 0.09), rng.uniform(0.1, 0.13)
    out = [make_part("brim", "brim", S.cylinder(rb, 0.004, center=(0, 0, 0.002), sections=32), mat),
           make_part("crown", "crown", S.lathe([(rc, 0.004), (rc * 0.95, hc * 0.8), (rc * 0.7, hc)]), mat),
           make_part("band", "band", S.cylinder(rc + 0.002, 0.02, center=(0, 0, 0.015), sections=28),
                     M.solid(M.jitter(rng, (0.15, 0.1, 0.08), 0.03), "fabric", 0.8))]
    return out


@register("scale", parts=("platform",), extra_parts=("display", "foot", "button"),
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
    out.append(make_part("foot", "foot", [S.cylinder(0.012, fh, center=(sx * (w / 2 - 0.03), sy * (d / 2 - 0.03), fh / 2),
                                                     sections=10) for sx in (-1, 1) for sy in (-1, 1)],
                         black("rubber")))
    return out


@register("dumbbell", parts=("handle", "plate"), extra_parts=("collar",),
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
            out.append(make_part(f"collar_{k}", "collar", S.cylinder(0.025, 0.02, center=(sx * (L / 2 - pw - 0.01), 0, r),
                                                                    axis=(1, 0, 0), sections=16), steel))
    return out


@register("paper_cutter", parts=("base", "blade_arm"), extra_parts=("handle", "guide", "hinge"),
          size_range=(0.3, 0.52), density=900, variants=("guillotine", "rotary", "compact"),
          placement="surface")
def paper_cutter(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d = rng.uniform(0.32, 0.5), rng.uniform(0.25, 0.38)
    base_t = 0.02
    out: list[Part | Joint] = [make_part("base", "base", S.box((w, d, base_t), center=(0, 0, base_t / 2)), M.wood(rng) if variant != "compact" else white(rng, "plastic")),
                               make_part("guide", "guide", S.box((0.012, d, 0.012), center=(-w / 2 + 0.006, 0, base_t + 0.006)),
                                         M.metal(rng))]
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
    out.append(revolute("blade_hinge", "base", "blade_arm", axis=(1, 0, 0), origin=(w / 2 - 0.0125, -d * 0.475, base_t),
                        opens=1.2))
    return out


@register("case_of_water_bottles", parts=("bottle", "wrap"), extra_parts=("tray", "cap"),
          size_range=(0.25, 0.42), density=900, variants=("6x4", "4x3", "6x2"),
          placement="floor")
def case_of_water_bottles(rng: np.random.Generator, variant: str) -> list[Part]:
    nx, ny = (int(v) for v in variant.split("x"))
    r = rng.uniform(0.031, 0.034)
    h = rng.uniform(0.2, 0.23)
    clear = M.solid(M.jitter(rng, (0.75, 0.85, 0.95), 0.02), "plastic", 0.1)
    out: list[Part] = []
    caps = []
    for i in range(nx):
        for j in range(ny):
            x = (i - (nx - 1) / 2) * 2 * r
            y = (j - (ny - 1) / 2) * 2 * r
            out.append(make_part(f"bottle_{i}_{j}", "bottle", S.lathe([(r * 0.97, 0.0), (r * 0.97, h * 0.75), (r * 0.4, h * 0.92),
                                                                       (r * 0.4, h - 0.012)], sections=14), clear))
            out[-1] = make_part(f"bottle_{i}_{j}", "bottle", S.transformed(
                S.lathe([(r * 0.97, 0.0), (r * 0.97, h * 0.75), (r * 0.4, h * 0.92), (r * 0.4, h - 0.012)], sections=14),
                np.array([[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, 0.004], [0, 0, 0, 1.0]])), clear)
            caps.append(S.cylinder(r * 0.42, 0.012, center=(x, y, h - 0.006 + 0.004), sections=12))
    out.append(make_part("cap", "cap", caps, M.solid(M.jitter(rng, (0.1, 0.3, 0.8), 0.05))))
    W, D = nx * 2 * r, ny * 2 * r
    out.append(make_part("tray", "tray", S.box((W + 0.004, D + 0.004, 0.004), center=(0, 0, 0.002)), M.paper(rng)))
    out.append(make_part("wrap", "wrap", [S.box((W + 0.004, 0.001, h * 0.5), center=(0, sy * (D / 2 + 0.0025), h * 0.4))
                                          for sy in (-1, 1)], M.glass(rng)))
    return out
