"""Assorted objects people name in rooms: stationery, kitchen tools and food, music gear,
workshop tools, clothes and bags, lights and decor, pet and game things, and a few room pieces
(a window unit, a fireplace).

Compact generators: each has several labelled parts, built from boxes, cylinders and hulls in
the canonical frame (front +Y, standing or lying on z = 0; long thin things lie along X).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Part, make_part
from ..registry import register
from ._casework import black, white
from ._household import ring, shell
from ._kit import legs4, revolute, rot


def _b(name, label, size, center, mat, bevel=0.0, R=None) -> Part:
    return make_part(name, label, S.box(size, center=center, bevel=bevel, R=R), mat)


def _c(name, label, r, h, center, mat, axis=(0, 0, 1), sections=20) -> Part:
    return make_part(name, label, S.cylinder(r, h, center=center, axis=axis, sections=sections), mat)


def _colour(rng, name="plastic"):
    return M.solid(M.jitter(rng, (0.5, 0.5, 0.5), 0.35)[:3], name, 0.5)


# ------------------------------------------------------------------ stationery and desk things
def _stick(rng, variant, *, L, r, body_mat, cap_mat, tip_mat) -> list[Part]:
    x0 = -L / 2
    return [_c("barrel", "barrel", r, L * 0.75, (x0 + L * 0.375, 0, r), body_mat, axis=(1, 0, 0), sections=8),
            _c("cap", "cap", r * 1.1, L * 0.2, (x0 + L * 0.85, 0, r), cap_mat, axis=(1, 0, 0), sections=10),
            make_part("tip", "tip", S.frustum(r, r * 0.3, L * 0.05, center=(x0 + L * 0.75, 0, r), axis=(-1, 0, 0),
                                              sections=8), tip_mat)]


@register("pen", parts=("barrel", "tip"), extra_parts=("cap",), size_range=(0.12, 0.2), density=900,
          variants=("ballpoint", "pencil", "fountain"), placement="surface")
def pen(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.13, 0.19)
    body = M.wood(rng) if variant == "pencil" else _colour(rng)
    return _stick(rng, variant, L=L, r=0.004, body_mat=body, cap_mat=black("metal") if variant == "fountain" else body,
                  tip_mat=black())


@register("marker", parts=("barrel", "tip"), extra_parts=("cap",), size_range=(0.1, 0.16), density=800,
          variants=("whiteboard", "permanent", "highlighter"), placement="surface")
def marker(rng: np.random.Generator, variant: str) -> list[Part]:
    return _stick(rng, variant, L=rng.uniform(0.11, 0.14), r=0.008, body_mat=white(rng, "plastic"),
                  cap_mat=_colour(rng), tip_mat=black())


@register("whiteboard_eraser", parts=("block", "felt"), extra_parts=("grip",), size_range=(0.1, 0.17), density=300,
          variants=("felt", "magnetic", "sponge"), placement="surface")
def whiteboard_eraser(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.11, 0.16), rng.uniform(0.045, 0.06)
    out = [_b("felt", "felt", (w, d, 0.01), (0, 0, 0.005), M.fabric(rng)),
           _b("block", "block", (w, d, 0.025), (0, 0, 0.0225), _colour(rng), bevel=0.004)]
    if variant != "sponge":
        out.append(_b("grip", "grip", (w * 0.6, d * 0.5, 0.012), (0, 0, 0.041), _colour(rng), bevel=0.004))
    return out


@register("sticky_note", parts=("pad",), extra_parts=("top_sheet",), size_range=(0.05, 0.13), density=700,
          variants=("square", "large", "strip"), placement="surface")
def sticky_note(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = {"square": (0.076, 0.076), "large": (0.1, 0.125), "strip": (0.076, 0.05)}[variant]
    h = rng.uniform(0.004, 0.015)
    col = M.solid(M.jitter(rng, [(0.98, 0.92, 0.4), (0.95, 0.6, 0.7), (0.6, 0.9, 0.7)][int(rng.integers(3))], 0.02),
                  "paper", 0.9)
    return [_b("pad", "pad", (w, d, h), (0, 0, h / 2), col), _b("top_sheet", "top_sheet", (w, d, 0.0005), (0, 0, h + 0.00025), col)]


@register("binder", parts=("cover", "spine"), extra_parts=("ring", "pages"), size_range=(0.28, 0.34), density=500,
          variants=("ring", "lever_arch", "slim"), placement="surface")
def binder(rng: np.random.Generator, variant: str) -> list[Part]:
    # standing upright on its bottom edge like a book: covers at +-Y, spine at -X
    h, w = rng.uniform(0.29, 0.32), rng.uniform(0.26, 0.29)
    t = {"ring": 0.045, "lever_arch": 0.075, "slim": 0.025}[variant]
    c = 0.003
    mat = _colour(rng)
    return [make_part("cover", "cover", [S.box((w, c, h), center=(0, sy * (t / 2 - c / 2), h / 2)) for sy in (-1, 1)], mat),
            _b("spine", "spine", (c * 2, t, h), (-w / 2 + c, 0, h / 2), mat),
            _b("pages", "pages", (w * 0.85, t - 2 * c - 0.006, h * 0.93), (0.01, 0, h / 2), white(rng, "paper")),
            _c("ring", "ring", 0.004, t * 0.6, (-w / 2 + 0.03, 0, h * 0.5), M.metal(rng), axis=(0, 1, 0), sections=8)]


@register("brochure_holder", parts=("base", "pocket"), extra_parts=("brochure",), size_range=(0.15, 0.35), density=1200,
          variants=("single", "tiered", "wide"), placement="surface")
def brochure_holder(rng: np.random.Generator, variant: str) -> list[Part]:
    n = 3 if variant == "tiered" else 1
    w = 0.3 if variant == "wide" else 0.16
    clear = M.glass(rng)
    out = [_b("base", "base", (w, 0.08 * n + 0.02, 0.008), (0, 0, 0.004), clear)]
    for k in range(n):
        y = -0.04 * (n - 1) + 0.08 * k
        z = 0.06 + 0.05 * (n - 1 - k)
        out.append(_b(f"pocket_{k}", "pocket", (w, 0.004, z), (0, y + 0.03, 0.008 + z / 2), clear))
        out.append(_b(f"brochure_{k}", "brochure", (w * 0.7, 0.006, z + 0.08), (0, y + 0.02, 0.008 + (z + 0.08) / 2), M.paper(rng)))
    return out


@register("globe", parts=("sphere", "stand"), extra_parts=("meridian", "base"), size_range=(0.2, 0.95), density=300,
          variants=("desk", "floor", "small"), placement="surface")
def globe(rng: np.random.Generator, variant: str) -> list[Part]:
    r = {"desk": rng.uniform(0.13, 0.16), "floor": rng.uniform(0.15, 0.2), "small": rng.uniform(0.08, 0.1)}[variant]
    ph = r * 0.6 if variant != "floor" else rng.uniform(0.45, 0.5)
    wood = M.wood(rng)
    z = ph + r
    out = [_c("base", "base", r * 0.6, 0.02, (0, 0, 0.01), wood),
           _c("stand", "stand", 0.012, ph - 0.02, (0, 0, 0.02 + (ph - 0.02) / 2), wood),
           make_part("sphere", "sphere", S.ellipsoid((r, r, r), center=(0, 0, z), subdivisions=3),
                     M.solid(M.jitter(rng, (0.3, 0.5, 0.7), 0.05), "paper", 0.5)),
           make_part("meridian", "meridian", S.transformed(ring([(r + 0.004, -0.004), (r + 0.012, -0.004), (r + 0.012, 0.004),
                                                                 (r + 0.004, 0.004)], sections=28),
                                                            np.array([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, z], [0, 0, 0, 1.0]])),
                     M.metal(rng))]
    return out


# --------------------------------------------------------------------- kitchen tools and food
@register("cutting_board", parts=("board",), extra_parts=("handle", "groove", "foot"), size_range=(0.25, 0.5),
          density=700, variants=("wood", "plastic", "paddle"), placement="surface")
def cutting_board(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.28, 0.42), rng.uniform(0.2, 0.3)
    t = rng.uniform(0.015, 0.03)
    mat = M.wood(rng) if variant != "plastic" else white(rng, "plastic")
    out = [_b("board", "board", (w, d, t), (0, 0, t / 2), mat, bevel=0.003)]
    if variant == "paddle":
        out.append(_b("handle", "handle", (0.1, 0.05, t), (w / 2 + 0.05, 0, t / 2), mat, bevel=0.003))
    else:
        out.append(_b("groove", "groove", (w * 0.9, 0.006, 0.002), (0, d / 2 - 0.015, t + 0.001), mat))
    return out


@register("knife", parts=("blade", "handle"), extra_parts=("bolster",), size_range=(0.18, 0.36), density=5000,
          variants=("chef", "bread", "paring"), placement="surface")
def knife(rng: np.random.Generator, variant: str) -> list[Part]:
    bl = {"chef": rng.uniform(0.18, 0.22), "bread": rng.uniform(0.2, 0.24), "paring": rng.uniform(0.08, 0.1)}[variant]
    hl = rng.uniform(0.1, 0.13)
    bw = 0.045 if variant == "chef" else 0.028
    x0 = -(bl + hl) / 2
    return [_b("handle", "handle", (hl, 0.022, 0.018), (x0 + hl / 2, 0, 0.009), black(), bevel=0.004),
            _b("bolster", "bolster", (0.01, 0.024, 0.02), (x0 + hl + 0.005, 0, 0.01), M.metal(rng)),
            make_part("blade", "blade", S.hull(np.array([[x0 + hl + 0.01, -bw / 2, 0], [x0 + hl + 0.01, -bw / 2, 0.002],
                                                        [x0 + hl + 0.01, bw / 2, 0], [x0 + hl + 0.01, bw / 2, 0.002],
                                                        [x0 + hl + bl, bw / 2, 0], [x0 + hl + bl, bw / 2, 0.002]])),
                      M.metal(rng))]


@register("fork", parts=("handle", "tines"), extra_parts=("neck",), size_range=(0.15, 0.22), density=7800,
          variants=("dinner", "salad", "serving"), placement="surface")
def fork(rng: np.random.Generator, variant: str) -> list[Part]:
    L = {"dinner": 0.19, "salad": 0.16, "serving": 0.21}[variant] * rng.uniform(0.95, 1.03)
    steel = M.metal(rng)
    x0 = -L / 2
    return [_b("handle", "handle", (L * 0.6, 0.018, 0.004), (x0 + L * 0.3, 0, 0.002), steel, bevel=0.001),
            _b("neck", "neck", (L * 0.12, 0.01, 0.004), (x0 + L * 0.66, 0, 0.004), steel),
            make_part("tines", "tines", [S.box((L * 0.25, 0.003, 0.003), center=(x0 + L * 0.845, y, 0.006))
                                         for y in np.linspace(-0.009, 0.009, 4)], steel)]


@register("knife_block", parts=("block", "handle"), extra_parts=("foot",), size_range=(0.22, 0.36), density=600,
          variants=("angled", "upright", "round"), placement="surface")
def knife_block(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.1, 0.14), rng.uniform(0.15, 0.2), rng.uniform(0.2, 0.25)
    wood = M.wood(rng)
    if variant == "round":
        block = S.cylinder(w * 0.7, h, center=(0, 0, h / 2), sections=20)
    else:
        R = rot((1, 0, 0), -0.3) if variant == "angled" else None
        block = S.box((w, d * 0.7, h * 0.9), center=(0, 0, h * 0.45 + 0.02), R=R, bevel=0.005)
    out = [make_part("block", "block", block, wood)]
    out.append(make_part("handle", "handle", [S.box((0.02, 0.015, 0.09), center=(x, -0.02 if variant == "angled" else 0,
                                                                              h + 0.045 + (0.02 if variant != "round" else 0)))
                                              for x in np.linspace(-w * 0.3, w * 0.3, 4)], black()))
    out.append(make_part("foot", "foot", S.box((w, d * 0.8, 0.02), center=(0, 0, 0.01)), wood))
    return out


@register("jar", parts=("body", "lid"), extra_parts=("label", "contents"), size_range=(0.08, 0.3), density=1500,
          variants=("mason", "canister", "spice"), placement="surface")
def jar(rng: np.random.Generator, variant: str) -> list[Part]:
    r = {"mason": rng.uniform(0.04, 0.05), "canister": rng.uniform(0.06, 0.08), "spice": rng.uniform(0.02, 0.025)}[variant]
    h = {"mason": rng.uniform(0.12, 0.16), "canister": rng.uniform(0.18, 0.25), "spice": rng.uniform(0.08, 0.1)}[variant]
    out = [make_part("body", "body", shell([(r, 0.0), (r, h * 0.92)], 0.003, bottom=0.004, sections=20), M.glass(rng)),
           _c("lid", "lid", r * 1.02, h * 0.08, (0, 0, h * 0.96), M.metal(rng) if variant != "canister" else M.wood(rng)),
           _c("contents", "contents", r * 0.9, h * 0.5, (0, 0, 0.004 + h * 0.25), M.food(rng, (0.7, 0.5, 0.3)))]
    return out


def _veg(rng, name, *, radii, col, top=None, top_col=(0.2, 0.5, 0.15)):
    body = S.ellipsoid(radii, center=(0, 0, radii[2]), subdivisions=2)
    out = [make_part("body", "body", body, M.food(rng, col))]
    if top is not None:
        out.append(make_part(top, top, S.cylinder(radii[0] * 0.15, radii[2] * 0.3, center=(0, 0, radii[2] * 2.1)),
                             M.food(rng, top_col)))
    return out


@register("potato", parts=("body",), extra_parts=("eye",), size_range=(0.05, 0.14), density=1080,
          variants=("russet", "red", "small"), placement="surface")
def potato(rng: np.random.Generator, variant: str) -> list[Part]:
    s = {"russet": 1.0, "red": 0.8, "small": 0.55}[variant]
    rx, ry, rz = (0.055 * s * rng.uniform(0.9, 1.1), 0.035 * s, 0.03 * s)
    col = (0.6, 0.45, 0.3) if variant != "red" else (0.6, 0.25, 0.2)
    out = _veg(rng, "potato", radii=(rx, ry, rz), col=col)
    out.append(_c("eye", "eye", 0.004, 0.002, (rx * 0.4, 0, rz * 2 - 0.0005), M.food(rng, (0.4, 0.3, 0.2)), sections=8))
    return out


@register("onion", parts=("body",), extra_parts=("stem", "root"), size_range=(0.05, 0.12), density=950,
          variants=("yellow", "red", "white"), placement="surface")
def onion(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.03, 0.045)
    col = {"yellow": (0.75, 0.55, 0.3), "red": (0.55, 0.2, 0.3), "white": (0.92, 0.9, 0.85)}[variant]
    out = _veg(rng, "onion", radii=(r, r, r * 0.9), col=col, top="stem", top_col=col)
    out.append(_c("root", "root", r * 0.2, 0.004, (0, 0, 0.002), M.food(rng, (0.6, 0.55, 0.45)), sections=8))
    out[0] = make_part("body", "body", S.ellipsoid((r, r, r * 0.9), center=(0, 0, r * 0.9 + 0.003), subdivisions=2), M.food(rng, col))
    out[1] = make_part("stem", "stem", S.cylinder(r * 0.15, r * 0.3, center=(0, 0, r * 1.8 + 0.003 + r * 0.15)), M.food(rng, col))
    return out


@register("tomato", parts=("body",), extra_parts=("stem", "calyx"), size_range=(0.025, 0.11), density=1000,
          variants=("round", "cherry", "beefsteak"), placement="surface")
def tomato(rng: np.random.Generator, variant: str) -> list[Part]:
    r = {"round": rng.uniform(0.03, 0.04), "cherry": rng.uniform(0.013, 0.016), "beefsteak": rng.uniform(0.045, 0.05)}[variant]
    out = [make_part("body", "body", S.ellipsoid((r, r, r * 0.85), center=(0, 0, r * 0.85), subdivisions=2),
                     M.food(rng, (0.85, 0.15, 0.1))),
           _c("calyx", "calyx", r * 0.35, 0.003, (0, 0, r * 1.7 + 0.0015), M.food(rng, (0.2, 0.5, 0.15)), sections=10),
           _c("stem", "stem", r * 0.06, r * 0.2, (0, 0, r * 1.7 + 0.003 + r * 0.1), M.food(rng, (0.2, 0.45, 0.15)), sections=8)]
    return out


@register("carrot", parts=("root",), extra_parts=("greens",), size_range=(0.12, 0.3), density=1000,
          variants=("plain", "with_greens", "baby"), placement="surface")
def carrot(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.14, 0.2) if variant != "baby" else rng.uniform(0.12, 0.13)
    r = L * 0.12
    out = [make_part("root", "root", S.frustum(r, r * 0.15, L, center=(-L / 2, 0, r), axis=(1, 0, 0), sections=12),
                     M.food(rng, (0.95, 0.5, 0.1)))]
    if variant == "with_greens":
        out.append(make_part("greens", "greens", S.frustum(r * 0.4, r * 1.2, L * 0.5, center=(-L / 2, 0, r), axis=(-1, 0, 0),
                                                           sections=8), M.food(rng, (0.25, 0.55, 0.2))))
    return out


@register("flowers", parts=("stem", "bloom"), extra_parts=("wrap", "leaf"), size_range=(0.25, 0.6), density=300,
          variants=("bouquet", "single", "wrapped"), placement="surface")
def flowers(rng: np.random.Generator, variant: str) -> list[Part]:
    n = 1 if variant == "single" else int(rng.integers(5, 10))
    L = rng.uniform(0.3, 0.5)
    green = M.plant(rng)
    stems, blooms = [], []
    for _ in range(n):
        a = rng.uniform(-0.35, 0.35)
        y = rng.uniform(-0.03, 0.03) if n > 1 else 0.0
        end = np.array([-L / 2 + L, y + np.sin(a) * 0.05, 0.003])
        stems.append(S.tube([(-L / 2, y * 0.3, 0.003), end], 0.003, sections=6))
        blooms.append(S.ellipsoid((0.025, 0.03, 0.02), center=end + [0.015, 0, 0.017]))
    out = [make_part("stem", "stem", stems, green),
           make_part("bloom", "bloom", blooms, M.solid(M.jitter(rng, (0.9, 0.4, 0.5), 0.2)[:3], "plant", 0.8))]
    if variant == "wrapped":
        out.append(make_part("wrap", "wrap", S.frustum(0.02, 0.06, L * 0.5, center=(-L / 2, 0, 0.04), axis=(1, 0, 0)), M.paper(rng)))
    return out


@register("thermos", parts=("body", "cap"), extra_parts=("handle", "cup"), size_range=(0.14, 0.38), density=700,
          variants=("bottle", "jug", "food_jar"), placement="surface")
def thermos(rng: np.random.Generator, variant: str) -> list[Part]:
    r = {"bottle": rng.uniform(0.035, 0.04), "jug": rng.uniform(0.07, 0.08), "food_jar": rng.uniform(0.05, 0.06)}[variant]
    h = {"bottle": rng.uniform(0.22, 0.3), "jug": rng.uniform(0.28, 0.34), "food_jar": rng.uniform(0.14, 0.16)}[variant]
    mat = M.metal(rng)
    out = [make_part("body", "body", S.lathe([(r, 0.0), (r, h * 0.85), (r * 0.7, h * 0.9)]), mat),
           _c("cap", "cap", r * 0.75, h * 0.1, (0, 0, h * 0.95), black())]
    if variant == "jug":
        out.append(make_part("handle", "handle", S.tube([(0, -r + 0.003, h * 0.75), (0, -r - 0.035, h * 0.7), (0, -r - 0.035, h * 0.35),
                                                         (0, -r + 0.003, h * 0.3)], 0.008), black()))
    return out


@register("stand_mixer", parts=("base", "head", "bowl"), extra_parts=("column", "beater", "knob"), size_range=(0.3, 0.42),
          density=800, variants=("tilt_head", "bowl_lift", "compact"), placement="surface")
def stand_mixer(rng: np.random.Generator, variant: str) -> list[Part]:
    L, w = rng.uniform(0.32, 0.38), rng.uniform(0.2, 0.24)
    h = rng.uniform(0.33, 0.38) if variant != "compact" else rng.uniform(0.3, 0.32)
    mat = M.solid(M.jitter(rng, [(0.8, 0.1, 0.1), (0.9, 0.9, 0.88), (0.2, 0.3, 0.5)][int(rng.integers(3))], 0.03), "metal", 0.3)
    out = [_b("base", "base", (w, L, 0.05), (0, 0, 0.025), mat, bevel=0.015),
           _b("column", "column", (w * 0.6, 0.1, h - 0.15), (0, -L / 2 + 0.05, 0.05 + (h - 0.15) / 2), mat, bevel=0.02),
           _b("head", "head", (w * 0.65, L * 0.85, 0.1), (0, -L * 0.05, h - 0.05), mat, bevel=0.03),
           make_part("bowl", "bowl", shell([(0.05, 0.05), (0.1, 0.12), (0.1, 0.2)], 0.003, bottom=0.004, sections=20), M.metal(rng)),
           _c("beater", "beater", 0.01, 0.08, (0, 0, h - 0.1 - 0.04), M.metal(rng), sections=8),
           _c("knob", "knob", 0.015, 0.015, (w * 0.3 + 0.0075, -L / 2 + 0.05, h * 0.6), black(), axis=(1, 0, 0), sections=10)]
    out[3] = make_part("bowl", "bowl", S.transformed(shell([(0.05, 0.0), (0.1, 0.07), (0.1, 0.15)], 0.003, bottom=0.004, sections=20),
                                                     np.array([[1, 0, 0, 0], [0, 1, 0, L * 0.08], [0, 0, 1, 0.05], [0, 0, 0, 1.0]])),
                       M.metal(rng))
    return out


@register("pot_rail", parts=("rail", "hook"), extra_parts=("bracket", "utensil"), size_range=(0.4, 1.05), density=3000,
          variants=("rail", "rail_with_utensils", "bar"), placement="wall")
def pot_rail(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.45, 1.0)
    steel = M.metal(rng)
    y, z = 0.05, 0.2
    out = [_c("rail", "rail", 0.008, L, (0, y, z), steel, axis=(1, 0, 0), sections=12),
           make_part("bracket", "bracket", [S.box((0.02, y, 0.02), center=(sx * (L / 2 - 0.03), y / 2, z)) for sx in (-1, 1)], steel)]
    n = int(rng.integers(3, 7))
    for k in range(n):
        x = -L / 2 + 0.08 + (L - 0.16) * k / max(n - 1, 1)
        out.append(make_part(f"hook_{k}", "hook", S.tube([(x, y, z), (x, y, z - 0.06), (x, y + 0.015, z - 0.07)], 0.0025, sections=6), steel))
        if variant == "rail_with_utensils":
            out.append(_b(f"utensil_{k}", "utensil", (0.02, 0.004, 0.16), (x, y + 0.015, z - 0.07 - 0.08), steel))
    return out


# ------------------------------------------------------------------------------- music gear
@register("metronome", parts=("body", "pendulum"), extra_parts=("weight", "base", "key"), size_range=(0.08, 0.26),
          density=600, variants=("pyramid", "digital", "mini"), placement="surface")
def metronome(rng: np.random.Generator, variant: str) -> list[Part]:
    h = rng.uniform(0.18, 0.24) if variant == "pyramid" else rng.uniform(0.08, 0.12)
    w = h * 0.5
    wood = M.wood(rng) if variant == "pyramid" else black()
    if variant == "digital":
        return [_b("body", "body", (w * 1.4, 0.06, h * 0.8), (0, 0, h * 0.4), wood, bevel=0.006),
                _b("pendulum", "pendulum", (0.004, 0.004, h * 0.6), (0, 0.032, h * 0.4), white(rng, "plastic")),
                _b("base", "base", (w * 1.4, 0.07, 0.01), (0, 0, 0.005), black())]
    body = S.hull(np.array([[sx * w / 2, sy * w / 2 * 0.8, 0] for sx in (-1, 1) for sy in (-1, 1)]
                           + [[sx * w * 0.12, sy * w * 0.1, h] for sx in (-1, 1) for sy in (-1, 1)]))
    return [make_part("body", "body", body, wood),
            _b("pendulum", "pendulum", (0.004, 0.004, h * 0.7), (0, w * 0.42 + 0.004, h * 0.45), M.metal(rng)),
            _b("weight", "weight", (0.012, 0.008, 0.012), (0, w * 0.42 + 0.006, h * 0.6), M.metal(rng)),
            _c("key", "key", 0.006, 0.02, (w / 2 + 0.005, 0, h * 0.25), M.metal(rng), axis=(1, 0, 0), sections=8)]


@register("vinyl_record", parts=("disc", "label"), extra_parts=("sleeve",), size_range=(0.17, 0.32), density=1300,
          variants=("lp", "single", "in_sleeve"), placement="surface")
def vinyl_record(rng: np.random.Generator, variant: str) -> list[Part]:
    r = 0.15 if variant != "single" else 0.0875
    out = [_c("disc", "disc", r, 0.0015, (0, 0, 0.00075), black(), sections=40),
           _c("label", "label", r * 0.33, 0.0004, (0, 0, 0.0017), M.paper(rng), sections=24)]
    if variant == "in_sleeve":
        out = [_b("sleeve", "sleeve", (0.31, 0.31, 0.004), (0, 0, 0.002), M.paper(rng)),
               _c("disc", "disc", r, 0.0015, (0, 0, 0.004 + 0.00075), black(), sections=40),
               _c("label", "label", r * 0.33, 0.0004, (0, 0, 0.004 + 0.0017), M.paper(rng), sections=24)]
    return out


@register("record_player", parts=("plinth", "platter", "tonearm"), extra_parts=("lid", "foot", "knob", "hinge"),
          size_range=(0.38, 0.5), density=500, variants=("lidded", "open", "suitcase"), placement="surface")
def record_player(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d, h = rng.uniform(0.42, 0.47), rng.uniform(0.33, 0.37), rng.uniform(0.08, 0.12)
    mat = M.wood(rng) if variant != "suitcase" else M.leather(rng)
    out: list[Part | Joint] = [_b("plinth", "plinth", (w, d, h - 0.01), (0, 0, 0.01 + (h - 0.01) / 2), mat, bevel=0.004),
                               _c("platter", "platter", 0.15, 0.015, (-w * 0.08, 0, h + 0.0075), M.metal(rng), sections=36),
                               make_part("tonearm", "tonearm", S.tube([(w * 0.38, -d * 0.3, h + 0.03), (w * 0.3, d * 0.2, h + 0.03)], 0.004,
                                                                      sections=8), M.metal(rng)),
                               _c("knob", "knob", 0.012, 0.01, (w * 0.38, d * 0.38, h + 0.005), M.metal(rng), sections=10),
                               make_part("foot", "foot", [S.cylinder(0.015, 0.01, center=(sx * (w / 2 - 0.03), sy * (d / 2 - 0.03), 0.005))
                                                          for sx in (-1, 1) for sy in (-1, 1)], black("rubber"))]
    if variant == "lidded":
        out.append(_b("lid", "lid", (w, d, 0.08), (0, 0, h + 0.04), M.glass(rng)))
        out.append(revolute("lid_hinge", "plinth", "lid", axis=(1, 0, 0), origin=(0, -d / 2, h), opens=1.3))
    return out


def _instrument_case(rng, *, L, wl, wu, t, mat) -> list[Part | Joint]:
    outline = np.array([[-L / 2, -wl / 2], [-L / 2 + L * 0.35, -wl / 2], [-L / 2 + L * 0.55, -wu / 2], [L / 2, -wu * 0.3],
                        [L / 2, wu * 0.3], [-L / 2 + L * 0.55, wu / 2], [-L / 2 + L * 0.35, wl / 2], [-L / 2, wl / 2]])
    base = S.hull(np.vstack([np.c_[outline, np.zeros(8)], np.c_[outline, np.full(8, t * 0.6)]]))
    lid = S.hull(np.vstack([np.c_[outline, np.full(8, t * 0.6)], np.c_[outline * 0.97, np.full(8, t)]]))
    return [make_part("shell", "shell", base, mat), make_part("lid", "lid", lid, mat),
            _b("handle", "handle", (0.1, 0.025, 0.02), (-L / 2 + L * 0.45, wu / 2 + 0.012, t * 0.5), black("leather")),
            make_part("latch", "latch", [S.box((0.025, 0.01, 0.015), center=(x, wl / 2 - 0.004, t * 0.6))
                                         for x in (-L / 2 + L * 0.15, -L / 2 + L * 0.7)], M.metal(rng)),
            revolute("lid_hinge", "shell", "lid", axis=(1, 0, 0), origin=(0, -wl / 2, t * 0.6), opens=1.3)]


@register("violin_case", parts=("shell", "lid", "handle"), extra_parts=("latch",), size_range=(0.7, 0.85), density=250,
          variants=("shaped", "oblong", "dart"), placement="floor")
def violin_case(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    L = rng.uniform(0.72, 0.82)
    wl = rng.uniform(0.23, 0.26) if variant != "oblong" else 0.26
    wu = wl * (0.65 if variant != "oblong" else 0.98)
    return _instrument_case(rng, L=L, wl=wl, wu=wu, t=rng.uniform(0.1, 0.13), mat=black() if variant != "dart" else M.fabric(rng))


@register("cello", parts=("body", "neck", "scroll"), extra_parts=("endpin", "string", "bridge", "fingerboard"),
          size_range=(1.15, 1.5), density=400, variants=("upright", "on_stand", "lying"))
def cello(rng: np.random.Generator, variant: str) -> list[Part]:
    # standing on its endpin, front (strings) toward +Y
    L = rng.uniform(0.74, 0.78)
    pin = rng.uniform(0.2, 0.3)
    wl, d = rng.uniform(0.42, 0.46), rng.uniform(0.2, 0.24)
    wood = M.wood(rng)
    z0 = pin
    pts = []
    for z, hw in ((0.0, wl * 0.35), (0.15, wl / 2), (0.35, wl * 0.32), (0.55, wl * 0.43), (L, wl * 0.2)):
        for sx in (-1, 1):
            for sy in (-1, 1):
                pts.append([sx * hw, sy * d / 2, z0 + z])
    out = [make_part("body", "body", S.hull(np.array(pts)), wood),
           _c("endpin", "endpin", 0.006, pin, (0, 0, pin / 2), M.metal(rng), sections=8),
           _b("neck", "neck", (0.04, 0.04, 0.32), (0, d / 2 - 0.02, z0 + L + 0.16), wood),
           _b("fingerboard", "fingerboard", (0.05, 0.01, 0.5), (0, d / 2 + 0.005, z0 + L * 0.8 + 0.1), black("wood")),
           make_part("scroll", "scroll", S.ellipsoid((0.025, 0.04, 0.06), center=(0, d / 2 - 0.02, z0 + L + 0.32 + 0.05)), wood),
           make_part("string", "string", [S.box((0.0015, 0.0015, L * 0.75), center=(x, d / 2 + 0.014, z0 + L * 0.55))
                                          for x in (-0.012, -0.004, 0.004, 0.012)], M.metal(rng)),
           _b("bridge", "bridge", (0.08, 0.01, 0.06), (0, d / 2 + 0.005, z0 + L * 0.35), M.wood(rng))]
    return out


@register("drum", parts=("shell", "head"), extra_parts=("rim", "lug", "stand", "leg"), size_range=(0.3, 0.75), density=300,
          variants=("snare", "floor_tom", "djembe"), placement="floor")
def drum(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "djembe":
        r, h = rng.uniform(0.15, 0.17), rng.uniform(0.55, 0.62)
        wood = M.wood(rng)
        return [make_part("shell", "shell", S.lathe([(r * 0.7, 0.0), (r * 0.45, h * 0.45), (r, h * 0.95)]), wood),
                _c("head", "head", r * 1.01, 0.006, (0, 0, h * 0.95 + 0.003), M.leather(rng)),
                make_part("rim", "rim", ring([(r, h * 0.9), (r + 0.01, h * 0.9), (r + 0.01, h * 0.93), (r, h * 0.93)], sections=24),
                          M.fabric(rng))]
    r = rng.uniform(0.17, 0.19) if variant == "snare" else rng.uniform(0.2, 0.23)
    dh = rng.uniform(0.12, 0.15) if variant == "snare" else rng.uniform(0.35, 0.42)
    z0 = 0.45 if variant == "snare" else 0.12
    steel = M.metal(rng)
    out = [_c("shell", "shell", r, dh, (0, 0, z0 + dh / 2), _colour(rng, "wood"), sections=28),
           _c("head", "head", r * 1.01, 0.004, (0, 0, z0 + dh + 0.002), white(rng, "plastic"), sections=28),
           make_part("rim", "rim", ring([(r, z0 + dh - 0.01), (r + 0.008, z0 + dh - 0.01), (r + 0.008, z0 + dh + 0.006), (r, z0 + dh + 0.006)],
                                        sections=28), steel)]
    out.append(make_part("leg", "leg", [S.tube([(np.cos(a) * r * 0.9, np.sin(a) * r * 0.9, z0 + 0.02),
                                                (np.cos(a) * (r + 0.08), np.sin(a) * (r + 0.08), 0.01)], 0.008, sections=8)
                                        for a in np.linspace(0, 2 * np.pi, 3, endpoint=False)], steel))
    return out


@register("guitar_stand", parts=("frame", "cradle"), extra_parts=("neck_rest", "leg", "foot"), size_range=(0.35, 0.95),
          density=2000, variants=("a_frame", "tripod", "neck_hold"), placement="floor")
def guitar_stand(rng: np.random.Generator, variant: str) -> list[Part]:
    steel = black("metal")
    w = rng.uniform(0.28, 0.34)
    if variant == "a_frame":
        h = rng.uniform(0.35, 0.42)
        return [make_part("frame", "frame", [S.tube([(sx * w / 2, -0.15, 0.01), (sx * w / 2, 0.0, h), (sx * w / 2, 0.1, 0.01)], 0.009)
                                             for sx in (-1, 1)], steel),
                make_part("cradle", "cradle", S.tube([(-w / 2, 0.08, 0.12), (w / 2, 0.08, 0.12)], 0.012), black("rubber")),
                make_part("foot", "foot", [S.box((0.03, 0.03, 0.01), center=(sx * w / 2, sy, 0.005)) for sx in (-1, 1) for sy in (-0.15, 0.1)],
                          black("rubber"))]
    h = rng.uniform(0.75, 0.9)
    # the tripod's legs stand on the floor; the pole starts above their feet
    out = [_c("frame", "frame", 0.012, h - 0.03, (0, 0, 0.03 + (h - 0.03) / 2), steel, sections=10),
           make_part("leg", "leg", [S.tube([(0, 0, 0.2), (np.cos(a) * 0.25, np.sin(a) * 0.25, 0.008)], 0.008)
                                    for a in np.linspace(0, 2 * np.pi, 3, endpoint=False) + np.pi / 2], steel),
           make_part("cradle", "cradle", S.tube([(-w / 2, 0.08, 0.32), (0, 0.01, 0.3), (w / 2, 0.08, 0.32)], 0.012), black("rubber")),
           make_part("neck_rest", "neck_rest", S.tube([(-0.04, 0.04, h), (0, 0.0, h - 0.02), (0.04, 0.04, h)], 0.008), black("rubber"))]
    return out


@register("piano_bench", parts=("seat", "leg"), extra_parts=("knob", "lid", "stretcher"), size_range=(0.5, 0.95),
          density=600, variants=("duet", "adjustable", "storage"))
def piano_bench(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.55, 0.9) if variant != "adjustable" else rng.uniform(0.52, 0.6)
    d, h = rng.uniform(0.32, 0.38), rng.uniform(0.47, 0.52)
    wood = M.wood(rng)
    out = [_b("seat", "seat", (w, d, 0.05), (0, 0, h - 0.025), M.leather(rng) if variant != "storage" else wood, bevel=0.01)]
    out += legs4("leg", "leg", w=w, d=d, h=h - 0.05, size=0.04, mat=wood, inset=0.02)
    if variant == "adjustable":
        out += [_c(f"knob_{k}", "knob", 0.025, 0.02, (sx * (w / 2 + 0.01), 0, h * 0.6), black(), axis=(1, 0, 0))
                for k, sx in enumerate((-1, 1))]
    else:
        out.append(_b("stretcher", "stretcher", (w - 0.08, 0.02, 0.03), (0, 0, 0.12), wood))
    return out


@register("midi_keyboard", parts=("body", "keys"), extra_parts=("pad", "knob", "wheel"), size_range=(0.3, 1.0), density=500,
          variants=("25_key", "49_key", "61_key"), placement="surface")
def midi_keyboard(rng: np.random.Generator, variant: str) -> list[Part]:
    n = int(variant.split("_")[0])
    w = n * 0.0145 + 0.08
    d = rng.uniform(0.18, 0.25)
    out = [_b("body", "body", (w, d, 0.04), (0, 0, 0.02), black(), bevel=0.005),
           _b("keys", "keys", (n * 0.0145, d * 0.55, 0.015), (0.03, d * 0.2, 0.0475), white(rng, "plastic")),
           make_part("knob", "knob", [S.cylinder(0.008, 0.012, center=(-w / 2 + 0.03 + k * 0.025, -d * 0.3, 0.046))
                                      for k in range(4)], M.metal(rng)),
           make_part("wheel", "wheel", [S.cylinder(0.012, 0.012, center=(-w / 2 + 0.02 + k * 0.02, d * 0.2, 0.04), axis=(1, 0, 0))
                                        for k in range(2)], black())]
    if n <= 49:
        out.append(make_part("pad", "pad", [S.box((0.03, 0.03, 0.006), center=(w / 2 - 0.12 + 0.04 * i, -d * 0.28, 0.043))
                                            for i in range(3)], _colour(rng)))
    return out


# ---------------------------------------------------------------------- workshop and cleaning
@register("toolbox", parts=("box", "lid", "handle"), extra_parts=("latch", "tray", "hinge"), size_range=(0.3, 0.6),
          density=600, variants=("metal", "plastic", "cantilever"), placement="floor")
def toolbox(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d, h = rng.uniform(0.35, 0.55), rng.uniform(0.18, 0.25), rng.uniform(0.15, 0.22)
    mat = M.solid(M.jitter(rng, (0.8, 0.1, 0.1), 0.05), "metal", 0.4, 0.5) if variant != "plastic" else _colour(rng)
    t = 0.004
    out: list[Part | Joint] = [make_part("box", "box", [S.box((w, d, t), center=(0, 0, t / 2)),
                                                        S.box((w, t, h), center=(0, -d / 2 + t / 2, h / 2)), S.box((w, t, h), center=(0, d / 2 - t / 2, h / 2)),
                                                        S.box((t, d - 2 * t, h), center=(-w / 2 + t / 2, 0, h / 2)),
                                                        S.box((t, d - 2 * t, h), center=(w / 2 - t / 2, 0, h / 2))], mat),
                               _b("lid", "lid", (w, d, 0.03), (0, 0, h + 0.015), mat, bevel=0.004),
                               make_part("handle", "handle", S.tube([(-w * 0.3, 0, h + 0.03), (-w * 0.3, 0, h + 0.06), (w * 0.3, 0, h + 0.06),
                                                                     (w * 0.3, 0, h + 0.03)], 0.008), black()),
                               make_part("latch", "latch", [S.box((0.03, 0.006, 0.03), center=(sx * w * 0.35, d / 2 + 0.003, h))
                                                            for sx in (-1, 1)], M.metal(rng))]
    out.append(Joint("handle_mount", "prismatic", "lid", "handle", (0.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0)))
    out.append(revolute("lid_hinge", "box", "lid", axis=(1, 0, 0), origin=(0, -d / 2, h), opens=1.6))
    return out


@register("pliers", parts=("jaw", "handle"), extra_parts=("pivot", "grip"), size_range=(0.12, 0.26), density=7800,
          variants=("combination", "needle_nose", "locking"), placement="surface")
def pliers(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.15, 0.24)
    steel = M.metal(rng)
    jl = L * (0.35 if variant == "needle_nose" else 0.25)
    x0 = -L / 2
    grip = M.solid(M.jitter(rng, (0.8, 0.15, 0.1), 0.05), "rubber", 0.8)
    out = [make_part("handle", "handle", [S.box((L - jl, 0.012, 0.01), center=(x0 + (L - jl) / 2, sy * 0.018, 0.005),
                                                R=rot((0, 0, 1), -sy * 0.08)) for sy in (-1, 1)], steel),
           make_part("grip", "grip", [S.box((L * 0.4, 0.016, 0.012), center=(x0 + L * 0.22, sy * 0.024, 0.006),
                                            R=rot((0, 0, 1), -sy * 0.08)) for sy in (-1, 1)], grip),
           _c("pivot", "pivot", 0.008, 0.014, (x0 + L - jl, 0, 0.007), steel, sections=12),
           make_part("jaw", "jaw", S.hull(np.array([[x0 + L - jl, -0.012, 0], [x0 + L - jl, 0.012, 0], [x0 + L - jl, -0.012, 0.012],
                                                    [x0 + L - jl, 0.012, 0.012], [x0 + L, -0.003, 0.002], [x0 + L, 0.003, 0.002],
                                                    [x0 + L, -0.003, 0.008], [x0 + L, 0.003, 0.008]])), steel)]
    return out


@register("vise", parts=("body", "jaw"), extra_parts=("screw", "handle", "base"), size_range=(0.15, 0.4), density=7000,
          variants=("bench", "drill_press", "woodworking"), placement="surface")
def vise(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.1, 0.18)
    L = rng.uniform(0.2, 0.32)
    iron = M.solid(M.jitter(rng, (0.2, 0.35, 0.6), 0.05), "metal", 0.5, 0.6)
    steel = M.metal(rng)
    return [_b("base", "base", (w * 1.2, L * 0.5, 0.02), (0, -L * 0.2, 0.01), iron),
            _b("body", "body", (w * 0.6, L * 0.6, 0.06), (0, -L * 0.15, 0.05), iron),
            make_part("jaw", "jaw", [S.box((w, 0.03, 0.06), center=(0, y, 0.1)) for y in (-L * 0.05, L * 0.2)], iron),
            _c("screw", "screw", 0.008, L * 0.4, (0, L * 0.3, 0.06), steel, axis=(0, 1, 0), sections=10),
            _c("handle", "handle", 0.006, w * 1.1, (0, L / 2 - 0.01, 0.06), steel, axis=(1, 0, 0), sections=8)]


@register("paint_can", parts=("can", "lid"), extra_parts=("handle", "label", "rim"), size_range=(0.08, 0.42), density=1200,
          variants=("gallon", "quart", "bucket"), placement="floor")
def paint_can(rng: np.random.Generator, variant: str) -> list[Part]:
    r, h = {"gallon": (0.084, 0.19), "quart": (0.054, 0.12), "bucket": (0.15, 0.33)}[variant]
    r, h = r * rng.uniform(0.97, 1.03), h * rng.uniform(0.97, 1.03)
    steel = M.metal(rng)
    return [_c("can", "can", r, h, (0, 0, h / 2), steel, sections=28),
            _c("lid", "lid", r * 0.95, 0.006, (0, 0, h + 0.003), steel, sections=28),
            _c("label", "label", r + 0.0008, h * 0.5, (0, 0, h * 0.45), M.paper(rng), sections=28),
            make_part("handle", "handle", S.tube([(-r, 0, h * 0.8), (-r * 0.7, 0, h + 0.06), (r * 0.7, 0, h + 0.06), (r, 0, h * 0.8)],
                                                 0.002, sections=6), steel)]


@register("iron", parts=("soleplate", "body", "handle"), extra_parts=("dial", "cord", "heel"), size_range=(0.22, 0.3),
          density=800, variants=("steam", "travel", "cordless"), placement="surface")
def iron(rng: np.random.Generator, variant: str) -> list[Part]:
    # standing on its heel, the soleplate's point toward +Z... kept simple: lying on the soleplate
    L = rng.uniform(0.24, 0.28) if variant != "travel" else 0.22
    w = L * 0.42
    plate = S.hull(np.array([[-L / 2, -w / 2, 0], [-L / 2, w / 2, 0], [L / 2, 0, 0], [-L / 2, -w / 2, 0.008],
                             [-L / 2, w / 2, 0.008], [L / 2, 0, 0.008]]))
    body = S.hull(np.array([[-L / 2, -w / 2, 0.008], [-L / 2, w / 2, 0.008], [L / 2, 0, 0.008], [-L / 2 + 0.02, -w / 2 + 0.01, 0.06],
                            [-L / 2 + 0.02, w / 2 - 0.01, 0.06], [L / 2 - 0.05, 0, 0.05]]))
    col = _colour(rng)
    out = [make_part("soleplate", "soleplate", plate, M.metal(rng)), make_part("body", "body", body, col),
           make_part("handle", "handle", [S.box((L * 0.6, 0.025, 0.02), center=(-0.01, 0, 0.12)),
                                          S.box((0.02, 0.025, 0.06), center=(-L / 2 + 0.04, 0, 0.09)),
                                          S.box((0.02, 0.025, 0.06), center=(L * 0.2, 0, 0.08))], col),
           _c("dial", "dial", 0.015, 0.01, (-L * 0.05, w * 0.3, 0.055), black(), sections=12),
           _b("heel", "heel", (0.02, w * 0.8, 0.06), (-L / 2 + 0.01, 0, 0.038), col)]
    return out


@register("mop", parts=("handle", "head"), extra_parts=("strands", "bucket", "wringer"), size_range=(1.1, 1.45),
          density=400, variants=("string", "flat", "with_bucket"), placement="floor")
def mop(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(1.15, 1.35)
    out = [_c("handle", "handle", 0.012, L, (0, 0, 0.04 + L / 2), M.metal(rng), sections=10)]
    if variant == "flat":
        out += [_b("head", "head", (0.4, 0.12, 0.02), (0, 0, 0.02), _colour(rng)),
                _b("strands", "strands", (0.42, 0.13, 0.012), (0, 0, 0.006), M.fabric(rng))]
        out[0] = _c("handle", "handle", 0.012, L, (0, 0, 0.03 + L / 2), M.metal(rng), sections=10)
        return out
    out += [_c("head", "head", 0.03, 0.04, (0, 0, 0.04 + 0.02), _colour(rng)),
            make_part("strands", "strands", S.frustum(0.12, 0.03, 0.06, center=(0, 0, 0.0)), M.fabric(rng))]
    out[0] = _c("handle", "handle", 0.012, L, (0, 0, 0.08 + L / 2), M.metal(rng), sections=10)
    if variant == "with_bucket":
        out.append(make_part("bucket", "bucket", shell([(0.14, 0.0), (0.16, 0.28)], 0.004, bottom=0.005, sections=20),
                             _colour(rng)))
        out[1:3] = [_c("head", "head", 0.03, 0.04, (0, 0, 0.1), _colour(rng)),
                    make_part("strands", "strands", S.frustum(0.1, 0.03, 0.06, center=(0, 0, 0.02)), M.fabric(rng))]
        out[0] = _c("handle", "handle", 0.012, L, (0, 0, 0.12 + L / 2), M.metal(rng), sections=10)
    return out


@register("toilet_brush", parts=("handle", "holder"), extra_parts=("brush",), size_range=(0.32, 0.45), density=500,
          variants=("round", "square", "steel"), placement="floor")
def toilet_brush(rng: np.random.Generator, variant: str) -> list[Part]:
    h = rng.uniform(0.35, 0.42)
    r = rng.uniform(0.045, 0.055)
    mat = M.metal(rng) if variant == "steel" else white(rng, "plastic")
    holder = (shell([(r, 0.0), (r, 0.14)], 0.003, bottom=0.005, sections=20) if variant != "square" else
              S.box((2 * r, 2 * r, 0.14), center=(0, 0, 0.07), bevel=0.006))
    return [make_part("holder", "holder", holder, mat),
            _c("brush", "brush", r * 0.75, 0.06, (0, 0, 0.04), M.solid((0.2, 0.2, 0.2), "plastic", 0.9), sections=16),
            _c("handle", "handle", 0.008, h - 0.07, (0, 0, 0.07 + (h - 0.07) / 2), mat, sections=10)]


@register("toothbrush", parts=("handle", "head"), extra_parts=("bristles", "holder"), size_range=(0.16, 0.21), density=900,
          variants=("manual", "electric", "in_cup"), placement="surface")
def toothbrush(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "in_cup":
        r = 0.035
        return [make_part("holder", "holder", shell([(r, 0.0), (r * 1.1, 0.1)], 0.003, bottom=0.004, sections=20), M.ceramic(rng)),
                _c("handle", "handle", 0.006, 0.16, (0.01, 0, 0.004 + 0.08), _colour(rng), sections=8),
                _b("head", "head", (0.012, 0.01, 0.025), (0.01, 0, 0.164 + 0.0125), _colour(rng)),
                _b("bristles", "bristles", (0.012, 0.012, 0.02), (0.01, 0.011, 0.164 + 0.0125), white(rng, "plastic"))]
    L = 0.19 if variant == "manual" else 0.2
    r = 0.006 if variant == "manual" else 0.014
    col = _colour(rng)
    return [_c("handle", "handle", r, L * 0.78, (-L / 2 + L * 0.39, 0, r), col, axis=(1, 0, 0), sections=10),
            _b("head", "head", (L * 0.15, 0.012, 0.006), (L / 2 - L * 0.11, 0, r), col),
            _b("bristles", "bristles", (L * 0.13, 0.011, 0.012), (L / 2 - L * 0.11, 0, r + 0.009), white(rng, "plastic"))]


# ----------------------------------------------------------------------------- clothes and bags
@register("shirt", parts=("body", "sleeve"), extra_parts=("collar", "button"), size_range=(0.25, 1.6), density=200,
          variants=("folded", "laid_flat", "t_shirt"), placement="surface")
def shirt(rng: np.random.Generator, variant: str) -> list[Part]:
    fab = M.solid(M.jitter(rng, (0.6, 0.6, 0.7), 0.3)[:3], "fabric", 0.9)
    if variant == "folded":
        w, d = rng.uniform(0.26, 0.32), rng.uniform(0.2, 0.26)
        return [_b("body", "body", (w, d, 0.025), (0, 0, 0.0125), fab, bevel=0.006),
                _b("sleeve", "sleeve", (w * 0.9, 0.04, 0.01), (0, -d * 0.2, 0.03), fab),
                _b("collar", "collar", (0.12, 0.03, 0.008), (0, d / 2 - 0.03, 0.029), fab)]
    w, L = rng.uniform(0.45, 0.55), rng.uniform(0.65, 0.75)
    out = [_b("body", "body", (w, L, 0.01), (0, 0, 0.005), fab, bevel=0.003)]
    sl = 0.2 if variant == "t_shirt" else 0.55
    out += [_b(f"sleeve_{k}", "sleeve", (sl, 0.18, 0.008), (sx * (w / 2 + sl / 2 - 0.01), L * 0.3, 0.004), fab,
               R=rot((0, 0, 1), sx * -0.4)) for k, sx in enumerate((-1, 1))]
    out.append(_b("collar", "collar", (0.16, 0.05, 0.006), (0, L / 2 - 0.025, 0.013), fab))
    if variant == "laid_flat":
        out.append(make_part("button", "button", [S.cylinder(0.006, 0.003, center=(0, y, 0.0115)) for y in np.linspace(-L * 0.4, L * 0.4, 6)],
                             white(rng, "plastic")))
    return out


@register("socks", parts=("sock",), extra_parts=("cuff",), size_range=(0.08, 0.3), density=200,
          variants=("pair", "rolled", "single"), placement="surface")
def socks(rng: np.random.Generator, variant: str) -> list[Part]:
    fab = M.solid(M.jitter(rng, (0.5, 0.5, 0.5), 0.35)[:3], "fabric", 0.9)
    if variant == "rolled":
        r = rng.uniform(0.035, 0.045)
        return [make_part("sock", "sock", S.ellipsoid((r * 1.3, r, r * 0.9), center=(0, 0, r * 0.9)), fab),
                make_part("cuff", "cuff", S.ellipsoid((r * 0.6, r * 1.02, r * 0.6), center=(r * 0.5, 0, r * 0.9)), fab)]
    n = 2 if variant == "pair" else 1
    L = rng.uniform(0.2, 0.27)
    out = []
    for k in range(n):
        y = (k - (n - 1) / 2) * 0.1
        out.append(make_part(f"sock_{k}", "sock", [S.box((L * 0.65, 0.08, 0.012), center=(-L * 0.175, y, 0.006)),
                                                   S.box((L * 0.4, 0.08, 0.012), center=(L * 0.3, y + 0.02, 0.006), R=rot((0, 0, 1), 0.5))], fab))
        out.append(_b(f"cuff_{k}", "cuff", (0.04, 0.082, 0.014), (-L / 2 + 0.02, y, 0.007), fab))
    return out


@register("duffel_bag", parts=("body", "handle"), extra_parts=("strap", "zipper", "pocket", "end_cap"), size_range=(0.45, 0.8),
          density=150, variants=("gym", "travel", "barrel"), placement="floor")
def duffel_bag(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.5, 0.75)
    r = rng.uniform(0.13, 0.18)
    fab = M.fabric(rng)
    body = (S.cylinder(r, L, center=(0, 0, r), axis=(1, 0, 0), sections=20) if variant != "travel" else
            S.box((L, 2 * r, 1.6 * r), center=(0, 0, 0.8 * r), bevel=0.04))
    top = 2 * r if variant != "travel" else 1.6 * r
    out = [make_part("body", "body", body, fab),
           make_part("handle", "handle", [S.tube([(x - 0.05, -0.03, top - 0.01), (x, -0.03, top + 0.06), (x + 0.05, -0.03, top - 0.01)], 0.008)
                                          for x in (-0.06, 0.06)], black("fabric")),
           _b("zipper", "zipper", (L * 0.8, 0.012, 0.004), (0, 0.0, top + 0.001), M.metal(rng))]
    if variant == "gym":
        out.append(make_part("end_cap", "end_cap", [S.cylinder(r * 1.01, 0.01, center=(sx * (L / 2 - 0.005), 0, r), axis=(1, 0, 0))
                                                    for sx in (-1, 1)], black("fabric")))
    return out


@register("garment_bag", parts=("body", "hook"), extra_parts=("zipper", "handle", "window"), size_range=(0.55, 1.5), density=150,
          variants=("hanging", "folded", "long"), placement="wall")
def garment_bag(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.55, 0.62)
    fab = M.solid(M.jitter(rng, (0.2, 0.2, 0.25), 0.05), "fabric", 0.9)
    if variant == "folded":  # folded in half, lying flat on a bed or a rack
        return [_b("body", "body", (w, 0.55, 0.08), (0, 0, 0.04), fab, bevel=0.02),
                make_part("hook", "hook", S.tube([(0, 0.28, 0.06), (0, 0.33, 0.06), (0, 0.34, 0.03)], 0.003), M.metal(rng)),
                _b("handle", "handle", (0.15, 0.03, 0.02), (0, -0.2, 0.09), black("fabric"))]
    L = rng.uniform(0.9, 1.05) if variant == "hanging" else rng.uniform(1.3, 1.4)
    return [_b("body", "body", (w, 0.08, L), (0, 0.06, L / 2), fab, bevel=0.02),
            make_part("hook", "hook", S.tube([(0, 0.06, L), (0, 0.06, L + 0.06), (0, 0.02, L + 0.08)], 0.003), M.metal(rng)),
            _b("zipper", "zipper", (0.01, 0.004, L * 0.9), (0, 0.1 + 0.002, L / 2), M.metal(rng)),
            _b("window", "window", (w * 0.4, 0.002, 0.12), (0, 0.101, L * 0.75), M.glass(rng))]


# --------------------------------------------------------------------- lights, signs and decor
@register("lantern", parts=("body", "top"), extra_parts=("handle", "base", "tassel", "candle", "cord"), size_range=(0.2, 0.9),
          density=300, variants=("paper", "hurricane", "chinese"), placement="ceiling")
def lantern(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.1, 0.18) if variant != "hurricane" else rng.uniform(0.07, 0.09)
    h = r * (1.3 if variant == "chinese" else 1.6)
    glow = M.solid(M.jitter(rng, (0.85, 0.15, 0.1) if variant == "chinese" else (0.95, 0.92, 0.85), 0.03), "paper", 0.7)
    base_h = 0.02
    if variant == "hurricane":
        body = S.lathe([(r * 0.8, base_h), (r, base_h + h * 0.5), (r * 0.6, base_h + h)])
        glow = M.glass(rng)
    else:
        body = S.ellipsoid((r, r, h / 2), center=(0, 0, base_h + h / 2))
    out = [_c("base", "base", r * 0.6, base_h, (0, 0, base_h / 2), black("wood")), make_part("body", "body", body, glow),
           _c("top", "top", r * 0.45, 0.02, (0, 0, base_h + h + 0.01), black("wood")),
           make_part("handle", "handle", S.tube([(-r * 0.3, 0, base_h + h + 0.02), (0, 0, base_h + h + 0.08), (r * 0.3, 0, base_h + h + 0.02)],
                                                0.003), M.metal(rng))]
    if variant != "hurricane":  # paper lanterns hang by a cord from their top
        out.append(_c("cord", "cord", 0.003, 0.25, (0, 0, base_h + h + 0.08 + 0.125), black("fabric"), sections=6))
    if variant == "chinese":
        out[0] = _c("base", "base", r * 0.6, base_h, (0, 0, 0.06 + base_h / 2), black("wood"))
        out.append(_c("tassel", "tassel", 0.012, 0.06, (0, 0, 0.03), M.solid((0.9, 0.7, 0.1), "fabric", 0.8), sections=8))
    return out


@register("neon_sign", parts=("tube", "backing"), extra_parts=("standoff", "cable"), size_range=(0.3, 1.05), density=800,
          variants=("word", "shape", "boxed"), placement="wall")
def neon_sign(rng: np.random.Generator, variant: str) -> list[Part]:
    w, h = rng.uniform(0.35, 1.0), rng.uniform(0.18, 0.45)
    glow = M.solid(M.jitter(rng, [(1.0, 0.2, 0.6), (0.2, 0.8, 1.0), (1.0, 0.6, 0.1)][int(rng.integers(3))], 0.02), "glass", 0.1)
    n = int(rng.integers(4, 9))
    xs = np.linspace(-w * 0.42, w * 0.42, n)
    path = [(x, 0.04, h / 2 + (0.3 if k % 2 else -0.3) * h) for k, x in enumerate(xs)]
    out = [make_part("tube", "tube", S.tube(path, 0.006, sections=8), glow),
           _b("backing", "backing", (w, 0.01 if variant != "boxed" else 0.06, h), (0, 0.005 if variant != "boxed" else 0.03, h / 2),
              M.glass(rng) if variant != "boxed" else black()),
           make_part("standoff", "standoff", [S.cylinder(0.006, 0.02, center=(x, 0.02, h / 2), axis=(0, 1, 0)) for x in (-w * 0.4, w * 0.4)],
                     M.metal(rng))]
    if variant == "boxed":
        out[0] = make_part("tube", "tube", S.tube([(x, 0.07, z) for x, _, z in path], 0.006, sections=8), glow)
    return out


@register("hanging_scroll", parts=("scroll", "rod"), extra_parts=("cord", "knob", "painting"), size_range=(0.6, 2.0), density=400,
          variants=("vertical", "long", "calligraphy"), placement="wall")
def hanging_scroll(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.3, 0.5)
    L = rng.uniform(0.6, 1.0) if variant != "long" else rng.uniform(1.4, 1.8)
    silk = M.solid(M.jitter(rng, (0.85, 0.8, 0.65), 0.03), "paper", 0.9)
    wood = M.wood(rng)
    return [_b("scroll", "scroll", (w, 0.002, L), (0, 0.012, 0.02 + L / 2), silk),
            _b("painting", "painting", (w * 0.75, 0.001, L * 0.6), (0, 0.0135, 0.02 + L * 0.55), M.solid((0.2, 0.2, 0.2), "paper", 0.9)),
            make_part("rod", "rod", [S.cylinder(0.012, w + 0.04, center=(0, 0.012, z), axis=(1, 0, 0), sections=12)
                                     for z in (0.012, 0.02 + L + 0.012)], wood),
            make_part("cord", "cord", S.tube([(-w * 0.3, 0.012, L + 0.04), (0, 0.006, L + 0.14), (w * 0.3, 0.012, L + 0.04)], 0.002),
                      M.fabric(rng))]


@register("bird_cage", parts=("base", "bars", "top"), extra_parts=("door", "perch", "hook", "feeder"), size_range=(0.3, 0.6),
          density=800, variants=("round", "square", "dome"), placement="surface")
def bird_cage(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.14, 0.2)
    h = rng.uniform(0.3, 0.45)
    metal = M.metal(rng) if variant != "round" else M.solid((0.85, 0.75, 0.4), "metal", 0.3, 0.8)
    n = 16
    bars = [S.cylinder(0.002, h - 0.03, center=(np.cos(a) * r, np.sin(a) * r, 0.03 + (h - 0.03) / 2), sections=6)
            for a in np.linspace(0, 2 * np.pi, n, endpoint=False)]
    base = (S.cylinder(r + 0.01, 0.03, center=(0, 0, 0.015)) if variant != "square" else
            S.box((2 * r + 0.02, 2 * r + 0.02, 0.03), center=(0, 0, 0.015)))
    top = (S.lathe([(r, h), (r * 0.6, h + r * 0.35), (0.02, h + r * 0.5)]) if variant != "square" else
           S.box((2 * r, 2 * r, 0.02), center=(0, 0, h + 0.01)))
    top_z = h + (r * 0.5 if variant != "square" else 0.02)
    return [make_part("base", "base", base, M.wood(rng)), make_part("bars", "bars", bars, metal),
            make_part("top", "top", top, metal),
            _c("perch", "perch", 0.005, r * 1.6, (0, 0, h * 0.4), M.wood(rng), axis=(1, 0, 0), sections=8),
            make_part("hook", "hook", ring([(0.02, top_z - 0.005), (0.028, top_z - 0.005), (0.028, top_z + 0.005), (0.02, top_z + 0.005)],
                                           sections=12), metal)]


@register("table_runner", parts=("runner",), extra_parts=("fringe", "border"), size_range=(0.9, 2.4), density=300,
          variants=("plain", "fringed", "embroidered"), placement="surface")
def table_runner(rng: np.random.Generator, variant: str) -> list[Part]:
    L, w = rng.uniform(1.0, 2.2), rng.uniform(0.3, 0.4)
    fab = M.fabric(rng)
    out = [_b("runner", "runner", (L, w, 0.003), (0, 0, 0.0015), fab)]
    if variant == "fringed":
        out.append(make_part("fringe", "fringe", [S.box((0.05, w, 0.002), center=(sx * (L / 2 + 0.025), 0, 0.001)) for sx in (-1, 1)], fab))
    elif variant == "embroidered":
        out.append(make_part("border", "border", [S.box((L, 0.03, 0.001), center=(0, sy * (w / 2 - 0.03), 0.0035)) for sy in (-1, 1)],
                             M.solid((0.85, 0.7, 0.2), "fabric", 0.7)))
    return out


@register("coat_hook", parts=("plate", "hook"), extra_parts=("knob",), size_range=(0.06, 0.8), density=3000,
          variants=("single", "rail", "double"), placement="wall")
def coat_hook(rng: np.random.Generator, variant: str) -> list[Part]:
    metal = M.metal(rng)
    n = int(rng.integers(3, 6)) if variant == "rail" else 1
    w = 0.05 if n == 1 else 0.15 * n
    out = [_b("plate", "plate", (w, 0.012 if n > 1 else 0.006, 0.05 if n == 1 else 0.08), (0, 0.006 if n > 1 else 0.003, 0.04),
              M.wood(rng) if n > 1 else metal)]
    for k in range(n):
        x = (k - (n - 1) / 2) * 0.15
        y0 = 0.012 if n > 1 else 0.006
        path = [(x, y0, 0.04), (x, y0 + 0.05, 0.03), (x, y0 + 0.06, 0.06)]
        out.append(make_part(f"hook_{k}", "hook", S.tube(path, 0.005, sections=8), metal))
        if variant == "double":
            out.append(make_part(f"hook_{k}_upper", "hook", S.tube([(x, y0, 0.05), (x, y0 + 0.03, 0.07), (x, y0 + 0.035, 0.085)], 0.004,
                                                                 sections=8), metal))
    return out


@register("service_bell", parts=("base", "dome"), extra_parts=("plunger",), size_range=(0.07, 0.11), density=3000,
          variants=("classic", "brass", "wooden_base"), placement="surface")
def service_bell(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.038, 0.048)
    dome_mat = M.solid((0.85, 0.7, 0.3), "metal", 0.2, 1.0) if variant == "brass" else M.metal(rng)
    base_mat = M.wood(rng) if variant == "wooden_base" else black("metal")
    return [_c("base", "base", r * 1.05, 0.012, (0, 0, 0.006), base_mat, sections=24),
            make_part("dome", "dome", S.ellipsoid((r, r, r * 0.75), center=(0, 0, 0.012), subdivisions=2), dome_mat),
            _c("plunger", "plunger", 0.006, 0.015, (0, 0, 0.012 + r * 0.75 + 0.0075 - 0.003), M.metal(rng), sections=10)]


@register("window", parts=("frame", "glass"), extra_parts=("sill", "mullion", "sash", "handle"), size_range=(0.6, 2.2),
          density=800, variants=("casement", "double_hung", "picture"), placement="wall")
def window(rng: np.random.Generator, variant: str) -> list[Part]:
    """A window unit as seen from the room: frame, panes and sill on the wall's face."""
    w, h = rng.uniform(0.6, 1.6), rng.uniform(0.8, 1.5)
    f, t = 0.06, 0.05
    frame_mat = white(rng, "wood")
    out = [make_part("frame", "frame", [S.box((w, t, f), center=(0, t / 2, f / 2)), S.box((w, t, f), center=(0, t / 2, h - f / 2)),
                                        S.box((f, t, h - 2 * f), center=(-w / 2 + f / 2, t / 2, h / 2)),
                                        S.box((f, t, h - 2 * f), center=(w / 2 - f / 2, t / 2, h / 2))], frame_mat),
           _b("glass", "glass", (w - 2 * f, 0.006, h - 2 * f), (0, t / 2, h / 2), M.glass(rng)),
           _b("sill", "sill", (w + 0.08, 0.12, 0.025), (0, 0.06, -0.0125 + 0.0125), frame_mat)]
    out[0] = make_part("frame", "frame", [S.box((w, t, f), center=(0, t / 2, 0.025 + f / 2)), S.box((w, t, f), center=(0, t / 2, 0.025 + h - f / 2)),
                                          S.box((f, t, h - 2 * f), center=(-w / 2 + f / 2, t / 2, 0.025 + h / 2)),
                                          S.box((f, t, h - 2 * f), center=(w / 2 - f / 2, t / 2, 0.025 + h / 2))], frame_mat)
    out[1] = _b("glass", "glass", (w - 2 * f, 0.006, h - 2 * f), (0, t / 2, 0.025 + h / 2), M.glass(rng))
    out[2] = _b("sill", "sill", (w + 0.08, 0.12, 0.025), (0, 0.06, 0.0125), frame_mat)
    if variant == "double_hung":
        out.append(_b("sash", "sash", (w - 2 * f, t * 0.6, 0.04), (0, t * 0.6, 0.025 + h / 2), frame_mat))
    elif variant == "casement":
        out.append(_b("mullion", "mullion", (0.04, t * 0.8, h - 2 * f), (0, t / 2, 0.025 + h / 2), frame_mat))
        out.append(_b("handle", "handle", (0.02, 0.03, 0.08), (0.04, t + 0.015, 0.025 + h / 2), M.metal(rng)))
    return out


@register("fireplace", parts=("firebox", "mantel", "hearth"), extra_parts=("surround", "grate", "log", "screen"),
          size_range=(1.0, 1.9), density=1500, variants=("brick", "stone", "electric"))
def fireplace(rng: np.random.Generator, variant: str) -> list[Part]:
    """A fireplace against a wall: the hearth on the floor, the surround and firebox, the mantel
    shelf on top (things stand ON its mantel)."""
    w, h, d = rng.uniform(1.1, 1.8), rng.uniform(1.0, 1.25), rng.uniform(0.3, 0.45)
    mat = M.stone(rng) if variant != "brick" else M.solid(M.jitter(rng, (0.55, 0.25, 0.18), 0.04), "stone", 0.9)
    ow, oh = w * 0.45, h * 0.5
    hearth_h = 0.05
    out = [_b("hearth", "hearth", (w + 0.1, d + 0.2, hearth_h), (0, 0.1, hearth_h / 2), mat),
           make_part("surround", "surround", [S.box(((w - ow) / 2, d, h - hearth_h - 0.06), center=(sx * (w / 2 - (w - ow) / 4), 0, hearth_h + (h - hearth_h - 0.06) / 2))
                                              for sx in (-1, 1)] + [S.box((ow, d, h - hearth_h - 0.06 - oh), center=(0, 0, hearth_h + oh + (h - hearth_h - 0.06 - oh) / 2))],
                     mat),
           _b("firebox", "firebox", (ow, d * 0.6, oh), (0, -d * 0.2, hearth_h + oh / 2), black("stone")),
           _b("mantel", "mantel", (w + 0.12, d + 0.08, 0.06), (0, 0.04, h - 0.03), M.wood(rng), bevel=0.005)]
    if variant == "electric":
        out.append(_b("screen", "screen", (ow, 0.01, oh), (0, d / 2 - 0.005, hearth_h + oh / 2), M.glass(rng)))
    else:
        out.append(make_part("log", "log", [S.cylinder(0.05, ow * 0.7, center=(0, -d * 0.1 + k * 0.06, hearth_h + 0.05 + k * 0.04), axis=(1, 0, 0))
                                            for k in range(2)], M.wood(rng)))
    return out


# ------------------------------------------------------------------- bar, shop and game room
@register("beer_tap", parts=("tower", "handle"), extra_parts=("spout", "drip_tray", "base"), size_range=(0.3, 0.65),
          density=3000, variants=("single", "double", "triple"), placement="surface")
def beer_tap(rng: np.random.Generator, variant: str) -> list[Part]:
    n = {"single": 1, "double": 2, "triple": 3}[variant]
    w = 0.12 + 0.12 * (n - 1)
    h = rng.uniform(0.4, 0.5)
    steel = M.metal(rng)
    out = [_b("base", "base", (w, 0.1, 0.02), (0, 0, 0.01), steel),
           _b("tower", "tower", (w, 0.08, h - 0.1), (0, 0, 0.02 + (h - 0.1) / 2), steel, bevel=0.01),
           _b("drip_tray", "drip_tray", (w + 0.05, 0.12, 0.02), (0, 0.11, 0.01), steel)]
    for k in range(n):
        x = (k - (n - 1) / 2) * 0.12
        out.append(_c(f"spout_{k}", "spout", 0.008, 0.06, (x, 0.06, h - 0.18), steel, axis=(0, 1, 0), sections=10))
        out.append(_c(f"handle_{k}", "handle", 0.015, 0.12, (x, 0.07, h - 0.1 + 0.06), black(), sections=10))
    return out


@register("bar_mat", parts=("mat",), extra_parts=("rib", "rim"), size_range=(0.3, 0.9), density=1200,
          variants=("rubber", "service", "runner"), placement="surface")
def bar_mat(rng: np.random.Generator, variant: str) -> list[Part]:
    L = {"rubber": rng.uniform(0.3, 0.45), "service": rng.uniform(0.45, 0.6), "runner": rng.uniform(0.6, 0.85)}[variant]
    w = rng.uniform(0.08, 0.15) if variant == "runner" else rng.uniform(0.2, 0.3)
    rubber = black("rubber")
    return [_b("mat", "mat", (L, w, 0.004), (0, 0, 0.002), rubber),
            make_part("rim", "rim", [S.box((L, 0.008, 0.01), center=(0, sy * (w / 2 - 0.004), 0.005)) for sy in (-1, 1)], rubber),
            make_part("rib", "rib", [S.box((0.004, w - 0.02, 0.006), center=(x, 0, 0.007)) for x in np.linspace(-L / 2 + 0.02, L / 2 - 0.02, 8)],
                      rubber)]


@register("cash_register", parts=("body", "drawer"), extra_parts=("display", "keypad", "printer", "handle"),
          size_range=(0.3, 0.5), density=700, variants=("classic", "pos_terminal", "drawer_only"), placement="surface")
def cash_register(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d = rng.uniform(0.36, 0.44), rng.uniform(0.38, 0.44)
    dh = 0.1
    mat = black() if variant != "classic" else white(rng, "plastic")
    out: list[Part | Joint] = [_b("body", "body", (w, d - 0.02, dh), (0, -0.01, dh / 2), mat),
                               _b("drawer", "drawer", (w * 0.9, d * 0.8, dh * 0.7), (0, d / 2 - d * 0.4, dh * 0.45), mat),
                               _b("handle", "handle", (0.08, 0.01, 0.015), (0, d / 2 + 0.005, dh * 0.6), M.metal(rng))]
    out.append(prismatic_joint("drawer_slide", "body", "drawer", d * 0.5))
    out.append(Joint("handle_mount", "prismatic", "drawer", "handle", (0.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0)))
    if variant != "drawer_only":
        out.append(_b("keypad", "keypad", (w * 0.6, d * 0.4, 0.05), (0, -d * 0.1, dh + 0.025), mat, bevel=0.005))
        out.append(_b("display", "display", (w * 0.35, 0.02, 0.12), (0, -d * 0.35, dh + 0.06 + 0.05), black("glass")))
        out.append(_b("printer", "printer", (0.1, 0.1, 0.06), (w * 0.32, -d * 0.2, dh + 0.03), mat))
    return out


def prismatic_joint(name: str, parent: str, child: str, travel: float) -> Joint:
    return Joint(name, "prismatic", parent, child, (0.0, 1.0, 0.0), (0.0, 0.0, 0.0), (0.0, float(travel)))


@register("pool_ball", parts=("ball",), extra_parts=("spot",), size_range=(0.05, 0.062), density=1700,
          variants=("solid", "stripe", "cue"), placement="surface")
def pool_ball(rng: np.random.Generator, variant: str) -> list[Part]:
    r = 0.0286
    col = (0.95, 0.95, 0.92) if variant == "cue" else M.jitter(rng, [(0.9, 0.75, 0.1), (0.1, 0.2, 0.7), (0.8, 0.1, 0.1),
                                                                     (0.4, 0.1, 0.5), (0.9, 0.4, 0.1), (0.1, 0.5, 0.2)][int(rng.integers(6))], 0.02)[:3]
    out = [make_part("ball", "ball", S.ellipsoid((r, r, r), center=(0, 0, r), subdivisions=3), M.solid(col, "plastic", 0.1))]
    if variant != "cue":
        out.append(_c("spot", "spot", r * 0.35, 0.002, (0, 0, 2 * r - 0.0005), white(rng, "plastic"), sections=16))
    return out


@register("pool_cue", parts=("shaft", "butt"), extra_parts=("tip", "ferrule", "wrap"), size_range=(1.2, 1.5), density=700,
          variants=("maple", "two_piece", "short"), placement="floor")
def pool_cue(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(1.4, 1.47) if variant != "short" else rng.uniform(1.22, 1.3)
    r0 = 0.015
    wood = M.wood(rng)
    x0 = -L / 2
    return [make_part("butt", "butt", S.frustum(r0, r0 * 0.8, L * 0.45, center=(x0, 0, r0), axis=(1, 0, 0), sections=12),
                      M.solid(M.jitter(rng, (0.3, 0.15, 0.08), 0.03), "wood", 0.4)),
            make_part("wrap", "wrap", S.frustum(r0 * 1.02, r0 * 0.9, L * 0.2, center=(x0 + L * 0.05, 0, r0), axis=(1, 0, 0), sections=12),
                      black("leather")),
            make_part("shaft", "shaft", S.frustum(r0 * 0.8, r0 * 0.45, L * 0.53, center=(x0 + L * 0.45, 0, r0), axis=(1, 0, 0), sections=12), wood),
            _c("ferrule", "ferrule", r0 * 0.45, 0.02, (x0 + L * 0.98 - 0.002, 0, r0), white(rng, "plastic"), axis=(1, 0, 0), sections=10),
            _c("tip", "tip", r0 * 0.44, 0.01, (x0 + L - 0.005, 0, r0), M.solid((0.2, 0.3, 0.6), "leather", 0.9), axis=(1, 0, 0), sections=10)]


@register("chalk", parts=("block",), extra_parts=("cup",), size_range=(0.02, 0.1), density=1500,
          variants=("cue_chalk", "stick", "box"), placement="surface")
def chalk(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "stick":
        return [_c("block", "block", 0.005, 0.08, (0, 0, 0.005), white(rng, "stone"), axis=(1, 0, 0), sections=8),
                _c("cup", "cup", 0.0055, 0.015, (-0.035, 0, 0.005), M.paper(rng), axis=(1, 0, 0), sections=8)]
    if variant == "box":
        return [_b("cup", "cup", (0.09, 0.06, 0.04), (0, 0, 0.02), M.paper(rng)),
                _b("block", "block", (0.08, 0.05, 0.012), (0, 0, 0.046), white(rng, "stone"))]
    col = M.solid(M.jitter(rng, (0.2, 0.4, 0.8), 0.05), "stone", 0.9)
    return [_b("block", "block", (0.022, 0.022, 0.02), (0, 0, 0.01), col),
            _b("cup", "cup", (0.024, 0.024, 0.003), (0, 0, 0.0215), M.paper(rng))]


@register("cue_rack", parts=("frame", "holder"), extra_parts=("shelf", "ball_tray", "cue"), size_range=(0.6, 1.55),
          density=700, variants=("wall", "floor", "corner"), placement="wall")
def cue_rack(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.55, 0.8) if variant != "corner" else 0.5
    h = rng.uniform(0.7, 0.9) if variant != "floor" else rng.uniform(1.3, 1.5)
    wood = M.wood(rng)
    out = [make_part("frame", "frame", [S.box((0.03, 0.06, h), center=(sx * (w / 2 - 0.015), 0.03, h / 2)) for sx in (-1, 1)], wood),
           make_part("holder", "holder", [S.box((w, 0.08, 0.025), center=(0, 0.04, z)) for z in (h * 0.15, h * 0.85)], wood),
           make_part("shelf", "shelf", S.box((w, 0.12, 0.02), center=(0, 0.06, h * 0.45)), wood)]
    if variant != "corner":
        out.append(make_part("cue", "cue", [S.cylinder(0.012, h * 0.85, center=(x, 0.05, h * 0.46)) for x in np.linspace(-w * 0.35, w * 0.35, 5)],
                             M.wood(rng)))
    return out


@register("game_console", parts=("body",), extra_parts=("disc_slot", "button", "stand", "vent"), size_range=(0.18, 0.42),
          density=600, variants=("tower", "flat", "handheld_dock"), placement="surface")
def game_console(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = black() if rng.uniform() < 0.6 else white(rng, "plastic")
    if variant == "tower":
        w, d, h = rng.uniform(0.09, 0.11), rng.uniform(0.25, 0.3), rng.uniform(0.3, 0.38)
        return [_b("body", "body", (w, d, h - 0.01), (0, 0, 0.01 + (h - 0.01) / 2), mat, bevel=0.01),
                _b("stand", "stand", (w * 1.6, d * 0.5, 0.01), (0, 0, 0.005), mat),
                _b("disc_slot", "disc_slot", (0.004, 0.002, 0.13), (0, d / 2 + 0.001, h * 0.6), black()),
                _c("button", "button", 0.006, 0.003, (0, d / 2 + 0.0015, h * 0.2), white(rng, "plastic"), axis=(0, 1, 0), sections=10)]
    w, d, h = rng.uniform(0.26, 0.33), rng.uniform(0.2, 0.27), rng.uniform(0.04, 0.07)
    out = [_b("body", "body", (w, d, h), (0, 0, h / 2), mat, bevel=0.006),
           _b("vent", "vent", (w * 0.6, 0.004, h * 0.5), (0, -d / 2 - 0.001, h / 2), black()),
           _c("button", "button", 0.005, 0.003, (w * 0.4, d / 2 + 0.0015, h / 2), white(rng, "plastic"), axis=(0, 1, 0), sections=10)]
    if variant == "handheld_dock":
        out[0] = _b("body", "body", (w * 0.6, d * 0.4, h * 1.6), (0, 0, h * 0.8), mat, bevel=0.006)
        out[1] = _b("vent", "vent", (w * 0.4, 0.004, h * 0.6), (0, -d * 0.2 - 0.001, h * 0.8), black())
        out[2] = _c("button", "button", 0.005, 0.003, (w * 0.2, d * 0.2 + 0.0015, h * 0.8), white(rng, "plastic"), axis=(0, 1, 0), sections=10)
    return out


@register("game_controller", parts=("body", "grip"), extra_parts=("stick", "button", "trigger"), size_range=(0.1, 0.2),
          density=600, variants=("gamepad", "joystick", "wheel_remote"), placement="surface")
def game_controller(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = black() if rng.uniform() < 0.6 else white(rng, "plastic")
    if variant == "wheel_remote":
        return [_b("body", "body", (0.15, 0.036, 0.03), (0, 0, 0.015), mat, bevel=0.008),
                make_part("grip", "grip", [S.box((0.03, 0.038, 0.032), center=(sx * 0.065, 0, 0.016)) for sx in (-1, 1)], black("rubber")),
                make_part("button", "button", [S.cylinder(0.005, 0.004, center=(x, 0, 0.032)) for x in (-0.03, 0.0, 0.03)], _colour(rng))]
    w = rng.uniform(0.14, 0.16)
    out = [_b("body", "body", (w * 0.6, 0.06, 0.03), (0, 0.01, 0.018), mat, bevel=0.01),
           make_part("grip", "grip", [S.ellipsoid((0.025, 0.045, 0.02), center=(sx * w * 0.35, -0.01, 0.02)) for sx in (-1, 1)], mat),
           make_part("stick", "stick", [S.cylinder(0.008, 0.012, center=(sx * w * 0.15, 0.0, 0.04)) for sx in (-1, 1)], black("rubber")),
           make_part("button", "button", [S.cylinder(0.005, 0.004, center=(w * 0.22 + dx, 0.02 + dy, 0.034))
                                          for dx, dy in ((0.01, 0), (-0.01, 0), (0, 0.01), (0, -0.01))], _colour(rng))]
    if variant == "joystick":
        out[2] = make_part("stick", "stick", S.cylinder(0.012, 0.12, center=(0, 0.01, 0.09)), black("rubber"))
    return out


# ----------------------------------------------------------------------------- home and pets
@register("beanbag", parts=("body",), extra_parts=("seam", "handle"), size_range=(0.6, 1.3), density=60,
          variants=("classic", "lounger", "pouf"), placement="floor")
def beanbag(rng: np.random.Generator, variant: str) -> list[Part]:
    fab = M.fabric(rng)
    if variant == "lounger":
        L, w, h = rng.uniform(1.0, 1.25), rng.uniform(0.7, 0.85), rng.uniform(0.45, 0.6)
        body = S.hull(np.vstack([S.ellipsoid((L / 2, w / 2, h * 0.35), center=(0, 0, h * 0.35)).mesh.vertices,
                                 S.ellipsoid((L * 0.15, w * 0.45, h * 0.5), center=(-L * 0.3, 0, h * 0.5)).mesh.vertices]))
        seam_z = h * 0.35
    else:
        r = rng.uniform(0.35, 0.5) if variant == "classic" else rng.uniform(0.3, 0.35)
        h = r * (1.3 if variant == "classic" else 1.0)
        body = S.lathe([(r * 0.8, 0.0), (r, h * 0.35), (r * 0.85, h * 0.75), (r * 0.3, h)])
        seam_z = h * 0.35
        L = 2 * r
    out = [make_part("body", "body", body, fab),
           _c("handle", "handle", 0.02, 0.06, (0, 0, 0.0), fab, sections=8)]
    out[1] = _b("handle", "handle", (0.1, 0.02, 0.02), (0, 0, seam_z + 0.02), fab) if variant == "pouf" else _b(
        "seam", "seam", (L * 0.6, 0.006, 0.006), (0, 0, seam_z), fab)
    return out


@register("dog_bed", parts=("cushion", "bolster"), extra_parts=("base",), size_range=(0.45, 1.2), density=150,
          variants=("round", "rectangular", "basket"), placement="floor")
def dog_bed(rng: np.random.Generator, variant: str) -> list[Part]:
    fab = M.fabric(rng)
    if variant == "round":
        r = rng.uniform(0.25, 0.5)
        return [_c("cushion", "cushion", r * 0.8, 0.06, (0, 0, 0.03), fab, sections=28),
                make_part("bolster", "bolster", ring([(r * 0.8, 0.0), (r, 0.0), (r, 0.16), (r * 0.8, 0.16)], sections=28), fab)]
    w, d = rng.uniform(0.55, 1.1), rng.uniform(0.45, 0.75)
    out = [_b("cushion", "cushion", (w - 0.16, d - 0.12, 0.07), (0, 0.06 - 0.06, 0.035), fab, bevel=0.02),
           make_part("bolster", "bolster", [S.box((w, 0.08, 0.18), center=(0, -d / 2 + 0.04, 0.09), bevel=0.03),
                                            S.box((0.08, d - 0.08, 0.15), center=(-w / 2 + 0.04, 0.04, 0.075), bevel=0.03),
                                            S.box((0.08, d - 0.08, 0.15), center=(w / 2 - 0.04, 0.04, 0.075), bevel=0.03)], fab)]
    if variant == "basket":
        out.append(_b("base", "base", (w, d, 0.02), (0, 0, 0.01), M.wood(rng)))
        out[0] = _b("cushion", "cushion", (w - 0.16, d - 0.12, 0.07), (0, 0.0, 0.02 + 0.035), fab, bevel=0.02)
    return out


@register("laptop_stand", parts=("platform", "base"), extra_parts=("arm", "lip"), size_range=(0.22, 0.32), density=2700,
          variants=("riser", "folding", "vertical"), placement="surface")
def laptop_stand(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.24, 0.3), rng.uniform(0.22, 0.26)
    alu = M.metal(rng)
    if variant == "vertical":
        return [_b("base", "base", (0.1, 0.22, 0.012), (0, 0, 0.006), alu),
                make_part("platform", "platform", [S.box((0.006, 0.2, 0.06), center=(sx * 0.015, 0, 0.042)) for sx in (-1, 1)], alu),
                _b("lip", "lip", (0.04, 0.2, 0.004), (0, 0, 0.014), black("rubber"))]
    h = rng.uniform(0.12, 0.18)
    tilt = rot((1, 0, 0), -0.25)
    return [_b("base", "base", (w, 0.05, 0.012), (0, -d / 2 + 0.025, 0.006), alu),
            make_part("arm", "arm", [S.box((0.02, 0.02, h), center=(sx * (w / 2 - 0.02), -d / 2 + 0.03, h / 2)) for sx in (-1, 1)], alu),
            _b("platform", "platform", (w, d, 0.006), (0, 0.0, h * 0.75), alu, R=tilt),
            _b("lip", "lip", (w, 0.012, 0.02), (0, d / 2 - 0.01, h * 0.75 - d * 0.12 + 0.01), alu)]


@register("rolling_tv_stand", parts=("base", "pole", "mount"), extra_parts=("caster", "shelf"), size_range=(1.2, 1.9),
          density=1500, variants=("single_pole", "dual_pole", "with_shelf"))
def rolling_tv_stand(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.7, 0.9), rng.uniform(0.5, 0.6)
    h = rng.uniform(1.3, 1.8)
    steel = black("metal")
    ch = 0.08
    xs = (0.0,) if variant == "single_pole" else (-0.2, 0.2)
    out = [make_part("base", "base", [S.box((0.06, d, 0.04), center=(sx * w / 2 - sx * 0.03, 0, ch + 0.02)) for sx in (-1, 1)]
                     + [S.box((w, 0.06, 0.04), center=(0, 0, ch + 0.02))], steel),
           make_part("pole", "pole", [S.box((0.05, 0.05, h - ch - 0.04), center=(x, 0, ch + 0.04 + (h - ch - 0.04) / 2)) for x in xs], steel),
           _b("mount", "mount", (0.4, 0.03, 0.3), (0, 0.04, h * 0.8), steel),
           make_part("caster", "caster", [S.cylinder(ch / 2, 0.03, center=(sx * (w / 2 - 0.03), sy * (d / 2 - 0.04), ch / 2), axis=(1, 0, 0))
                                          for sx in (-1, 1) for sy in (-1, 1)], black("rubber"))]
    if variant == "with_shelf":
        out.append(_b("shelf", "shelf", (0.5, 0.35, 0.012), (0, 0.12, h * 0.45), M.glass(rng)))
    return out


# ---------------------------------------------------------- pub, café, bathroom, tea room
@register("bar_table", parts=("tabletop", "pedestal"), extra_parts=("base", "footrest"), size_range=(0.95, 1.15),
          density=700, variants=("round", "square", "footrest"))
def bar_table(rng: np.random.Generator, variant: str) -> list[Part]:
    h, r = rng.uniform(1.0, 1.08), rng.uniform(0.3, 0.4)
    wood, steel = M.wood(rng), M.metal(rng)
    top = (S.cylinder(r, 0.03, center=(0, 0, h - 0.015), sections=28) if variant != "square" else
           S.box((2 * r, 2 * r, 0.03), center=(0, 0, h - 0.015), bevel=0.004))
    out = [make_part("tabletop", "tabletop", top, wood),
           _c("pedestal", "pedestal", 0.035, h - 0.05, (0, 0, 0.02 + (h - 0.05) / 2), steel, sections=14),
           _c("base", "base", r * 0.8, 0.02, (0, 0, 0.01), steel, sections=24)]
    if variant == "footrest":
        out.append(make_part("footrest", "footrest", ring([(r * 0.6, 0.3), (r * 0.65, 0.3), (r * 0.65, 0.32), (r * 0.6, 0.32)],
                                                          sections=24), steel))
    return out


@register("coaster", parts=("disc",), extra_parts=("backing",), size_range=(0.08, 0.11), density=600,
          variants=("cardboard", "cork", "stone"), placement="surface")
def coaster(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.045, 0.053)
    mat = {"cardboard": M.paper(rng), "cork": M.solid((0.7, 0.55, 0.38), "wood", 0.9), "stone": M.stone(rng)}[variant]
    t = 0.003 if variant == "cardboard" else 0.006
    return [_c("disc", "disc", r, t, (0, 0, 0.001 + t / 2), mat, sections=24),
            _c("backing", "backing", r * 0.95, 0.001, (0, 0, 0.0005), M.solid((0.3, 0.3, 0.3), "rubber", 0.9), sections=24)]


@register("pint_glass", parts=("body",), extra_parts=("beer", "foam"), size_range=(0.14, 0.18), density=2500,
          variants=("empty", "full", "nonic"), placement="surface")
def pint_glass(rng: np.random.Generator, variant: str) -> list[Part]:
    h, r0, r1 = rng.uniform(0.145, 0.16), 0.03, rng.uniform(0.042, 0.045)
    prof = [(r0, 0.0), (r1, h)] if variant != "nonic" else [(r0, 0.0), (r1, h * 0.82), (r1 * 1.06, h * 0.88), (r1, h)]
    out = [make_part("body", "body", shell(prof, 0.003, bottom=0.01, sections=24), M.glass(rng))]
    if variant == "full":
        out.append(make_part("beer", "beer", S.frustum(r0 - 0.003, r1 * 0.94, h * 0.8, center=(0, 0, 0.01), sections=20),
                             M.food(rng, (0.8, 0.5, 0.1))))
        out.append(_c("foam", "foam", r1 * 0.93, h * 0.06, (0, 0, 0.01 + h * 0.83), white(rng, "food"), sections=20))
    return out


@register("jukebox", parts=("cabinet", "dome"), extra_parts=("grille", "window", "button", "light"), size_range=(1.2, 1.6),
          density=300, variants=("classic", "retro", "wall_box"))
def jukebox(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.8, 0.95), rng.uniform(0.5, 0.65), rng.uniform(1.25, 1.5)
    wood = M.wood(rng)
    body_h = h - w / 2
    return [_b("cabinet", "cabinet", (w, d, body_h), (0, 0, body_h / 2), wood, bevel=0.01),
            make_part("dome", "dome", S.transformed(S.cylinder(w / 2, d, sections=24, axis=(0, 1, 0)),
                                                    np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, body_h], [0, 0, 0, 1.0]])), wood),
            _b("window", "window", (w * 0.6, 0.01, body_h * 0.25), (0, d / 2 + 0.003, body_h * 0.75), M.glass(rng)),
            _b("grille", "grille", (w * 0.6, 0.01, body_h * 0.3), (0, d / 2 + 0.003, body_h * 0.3), M.metal(rng)),
            make_part("light", "light", [S.box((0.04, 0.01, body_h * 0.8), center=(sx * (w / 2 - 0.05), d / 2 + 0.003, body_h * 0.5))
                                         for sx in (-1, 1)], M.solid((1.0, 0.6, 0.2), "glass", 0.1))]


@register("faucet", parts=("spout", "base"), extra_parts=("handle", "aerator"), size_range=(0.12, 0.4), density=7000,
          variants=("single_lever", "two_handle", "tall_vessel"), placement="surface")
def faucet(rng: np.random.Generator, variant: str) -> list[Part]:
    h = rng.uniform(0.15, 0.22) if variant != "tall_vessel" else rng.uniform(0.28, 0.35)
    reach = rng.uniform(0.1, 0.16)
    steel = M.metal(rng)
    out = [_c("base", "base", 0.025, 0.02, (0, 0, 0.01), steel, sections=16),
           make_part("spout", "spout", S.tube([(0, 0, 0.02), (0, 0, h), (0, reach, h), (0, reach, h - 0.03)], 0.012, sections=10), steel),
           _c("aerator", "aerator", 0.013, 0.015, (0, reach, h - 0.04), steel, sections=12)]
    if variant == "two_handle":
        out.append(make_part("handle", "handle", [S.cylinder(0.015, 0.05, center=(sx * 0.08, 0, 0.025)) for sx in (-1, 1)], steel))
    else:
        out.append(_b("handle", "handle", (0.012, 0.07, 0.012), (0, -0.035, h * 0.6), steel))
    return out


@register("shower", parts=("tray", "panel", "head", "niche"), extra_parts=("door", "valve", "drain", "hinge"), size_range=(1.9, 2.2),
          density=800, variants=("corner", "alcove", "walk_in"))
def shower(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    """A shower enclosure standing on the floor: a tray, glass panels, a door and a shower head."""
    w, d, h = rng.uniform(0.8, 1.0), rng.uniform(0.8, 1.0), rng.uniform(1.9, 2.05)
    glass, steel = M.glass(rng), M.metal(rng)
    out: list[Part | Joint] = [_b("tray", "tray", (w, d, 0.05), (0, 0, 0.025), white(rng, "ceramic")),
                               _c("drain", "drain", 0.04, 0.003, (0, 0, 0.0515), steel, sections=16),
                               make_part("panel", "panel", [S.box((w, 0.01, h - 0.05), center=(0, -d / 2 + 0.005, 0.05 + (h - 0.05) / 2))]
                                         + ([S.box((0.01, d - 0.01, h - 0.05), center=(-w / 2 + 0.005, 0.005, 0.05 + (h - 0.05) / 2))]
                                            if variant != "alcove" else []), glass if variant != "alcove" else white(rng, "ceramic")),
                               _c("head", "head", 0.1, 0.015, (0, -d / 2 + 0.25, h - 0.1), steel, sections=20),
                               _b("valve", "valve", (0.08, 0.04, 0.08), (w * 0.2, -d / 2 + 0.03, 1.0), steel),
                               # a niche: a small shelf on the back wall for bottles
                               _b("niche", "niche", (0.3, 0.1, 0.015), (-w * 0.2, -d / 2 + 0.06, 1.2), white(rng, "ceramic"))]
    if variant != "walk_in":
        out.append(_b("door", "door", (w - 0.02, 0.008, h - 0.1), (0, d / 2 - 0.004, 0.05 + (h - 0.1) / 2), glass))
        out += hinge_barrels("door_hinge", x=-w / 2 + 0.01, y=d / 2 - 0.008, z0=0.05, z1=h - 0.05, mat=steel)
        out.append(revolute("door_hinge", "tray", "door", axis=(0, 0, 1), origin=(-w / 2 + 0.01, d / 2 - 0.008, 0.05)))
    return out


def hinge_barrels(prefix: str, *, x: float, y: float, z0: float, z1: float, mat) -> list[Part]:
    return [make_part(f"{prefix}_{k}", "hinge", S.cylinder(0.006, 0.05, center=(x, y, z), sections=10), mat)
            for k, z in enumerate((z0 + 0.15, z1 - 0.15))]


@register("shampoo_bottle", parts=("body", "cap"), extra_parts=("label", "pump"), size_range=(0.14, 0.3), density=1000,
          variants=("flip_cap", "pump", "tall"), placement="surface")
def shampoo_bottle(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.06, 0.08), rng.uniform(0.035, 0.05)
    h = rng.uniform(0.15, 0.2) if variant != "tall" else rng.uniform(0.22, 0.26)
    col = _colour(rng)
    out = [_b("body", "body", (w, d, h), (0, 0, h / 2), col, bevel=0.012),
           _c("cap", "cap", 0.016, 0.025, (0, 0, h + 0.0125), white(rng, "plastic"), sections=14),
           _b("label", "label", (w * 0.8, 0.001, h * 0.5), (0, d / 2 + 0.0005, h * 0.45), M.paper(rng))]
    if variant == "pump":
        out.append(_b("pump", "pump", (0.01, 0.04, 0.01), (0, 0.012, h + 0.03), white(rng, "plastic")))
    return out


@register("jewelry_box", parts=("box", "lid"), extra_parts=("drawer", "mirror", "hinge", "clasp"), size_range=(0.15, 0.35),
          density=600, variants=("lidded", "drawers", "music"), placement="surface")
def jewelry_box(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d, h = rng.uniform(0.18, 0.3), rng.uniform(0.12, 0.2), rng.uniform(0.08, 0.15)
    mat = M.wood(rng) if variant != "music" else M.leather(rng)
    out: list[Part | Joint] = [_b("box", "box", (w, d, h), (0, 0, h / 2), mat, bevel=0.003),
                               _b("lid", "lid", (w, d, 0.025), (0, 0, h + 0.0125), mat, bevel=0.004),
                               _b("clasp", "clasp", (0.015, 0.004, 0.015), (0, d / 2 + 0.002, h), M.metal(rng))]
    out.append(revolute("lid_hinge", "box", "lid", axis=(1, 0, 0), origin=(0, -d / 2, h), opens=1.6))
    if variant == "drawers":
        out.append(_b("drawer", "drawer", (w * 0.9, 0.006, h * 0.35), (0, d / 2 + 0.003, h * 0.25), mat))
    return out


@register("croissant", parts=("body",), extra_parts=("tip",), size_range=(0.07, 0.16), density=300,
          variants=("plain", "large", "mini"), placement="surface")
def croissant(rng: np.random.Generator, variant: str) -> list[Part]:
    s = {"plain": 1.0, "large": 1.2, "mini": 0.65}[variant]
    L, r = 0.11 * s, 0.025 * s
    bake = M.food(rng, (0.8, 0.55, 0.25))
    return [make_part("body", "body", S.ellipsoid((L * 0.35, r * 1.3, r), center=(0, 0, r)), bake),
            make_part("tip", "tip", [S.ellipsoid((L * 0.2, r * 0.6, r * 0.55), center=(sx * L * 0.35, -r * 0.6, r * 0.55)) for sx in (-1, 1)],
                      bake)]


@register("wagashi", parts=("sweet",), extra_parts=("leaf", "paper"), size_range=(0.03, 0.09), density=1200,
          variants=("round", "square", "on_paper"), placement="surface")
def wagashi(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.02, 0.03)
    col = M.food(rng, M.jitter(rng, (0.9, 0.6, 0.7), 0.15)[:3])
    z0 = 0.001 if variant == "on_paper" else 0.0
    sweet = (S.ellipsoid((r, r, r * 0.7), center=(0, 0, z0 + r * 0.7)) if variant != "square" else
             S.box((2 * r, 2 * r, r), center=(0, 0, z0 + r / 2), bevel=r * 0.2))
    out = [make_part("sweet", "sweet", sweet, col),
           make_part("leaf", "leaf", S.box((r * 0.8, r * 0.4, 0.002), center=(0, 0, z0 + (r * 1.4 if variant != "square" else r) + 0.001)),
                     M.plant(rng))]
    if variant == "on_paper":
        out.append(_b("paper", "paper", (r * 3.5, r * 3.5, 0.001), (0, 0, 0.0005), M.paper(rng)))
    return out


@register("high_chair", parts=("seat", "leg", "tray"), extra_parts=("back", "footrest", "armrest"), size_range=(0.8, 1.1),
          density=500, variants=("wooden", "plastic", "folding"))
def high_chair(rng: np.random.Generator, variant: str) -> list[Part]:
    hs = rng.uniform(0.55, 0.62)
    w, d = rng.uniform(0.4, 0.48), rng.uniform(0.45, 0.55)
    mat = M.wood(rng) if variant == "wooden" else white(rng, "plastic")
    out = [_b("seat", "seat", (0.32, 0.3, 0.025), (0, 0, hs), mat, bevel=0.004),
           _b("back", "back", (0.32, 0.02, 0.3), (0, -0.15, hs + 0.16), mat, bevel=0.004),
           _b("tray", "tray", (0.4, 0.2, 0.02), (0, 0.2, hs + 0.2), mat, bevel=0.004),
           make_part("armrest", "armrest", [S.box((0.02, 0.3, 0.02), center=(sx * 0.17, 0.05, hs + 0.17)) for sx in (-1, 1)], mat),
           _b("footrest", "footrest", (0.3, 0.08, 0.015), (0, 0.18, hs - 0.25), mat)]
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        out.append(make_part(f"leg_{k}", "leg", S.tube([(sx * 0.15, sy * 0.12, hs - 0.0125), (sx * w / 2, sy * d / 2, 0.015)], 0.015,
                                                      sections=10), mat))
    return out


@register("sippy_cup", parts=("body", "lid"), extra_parts=("spout", "handle"), size_range=(0.1, 0.2), density=1000,
          variants=("handles", "plain", "straw"), placement="surface")
def sippy_cup(rng: np.random.Generator, variant: str) -> list[Part]:
    r, h = rng.uniform(0.035, 0.04), rng.uniform(0.1, 0.13)
    col = _colour(rng)
    out = [_c("body", "body", r, h, (0, 0, h / 2), col, sections=20),
           _c("lid", "lid", r * 1.05, 0.015, (0, 0, h + 0.0075), white(rng, "plastic"), sections=20),
           make_part("spout", "spout", S.frustum(0.012, 0.006, 0.025, center=(0, r * 0.5, h + 0.015)), white(rng, "plastic"))]
    if variant == "handles":
        out.append(make_part("handle", "handle", [S.box((0.02, 0.012, 0.05), center=(sx * (r + 0.01), 0, h * 0.55)) for sx in (-1, 1)], col))
    return out


@register("hutch", parts=("base_cabinet", "upper_shelf"), extra_parts=("door", "handle", "hinge", "back_panel", "top_panel"),
          size_range=(1.4, 2.1), density=600, variants=("open_top", "glass_top", "plate_rack"))
def hutch(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d = rng.uniform(1.0, 1.6), rng.uniform(0.42, 0.5)
    hb, ht = rng.uniform(0.8, 0.9), rng.uniform(0.7, 1.0)
    wood = M.wood(rng)
    out: list[Part | Joint] = [_b("base_cabinet", "base_cabinet", (w, d, hb), (0, 0, hb / 2), wood, bevel=0.004),
                               _b("back_panel", "back_panel", (w, 0.02, ht), (0, -d / 2 + 0.01, hb + ht / 2), wood),
                               _b("top_panel", "top_panel", (w, 0.3, 0.03), (0, -d / 2 + 0.15, hb + ht - 0.015), wood)]
    for k in range(2):
        out.append(_b(f"upper_shelf_{k}", "upper_shelf", (w - 0.04, 0.28, 0.02), (0, -d / 2 + 0.16, hb + ht * (k + 1) / 3), wood))
    for k, sx in enumerate((-1, 1)):
        x0 = -w / 2 + 0.01 if sx < 0 else 0.005
        x1 = -0.005 if sx < 0 else w / 2 - 0.01
        out.append(_b(f"door_{k}", "door", (x1 - x0, 0.02, hb - 0.1), ((x0 + x1) / 2, d / 2 + 0.01, hb / 2), wood))
        out.append(_b(f"door_{k}_handle", "handle", (0.015, 0.02, 0.1), ((x1 - 0.04) if sx < 0 else (x0 + 0.04), d / 2 + 0.03, hb * 0.55),
                      M.metal(rng)))
        xh = x0 if sx < 0 else x1
        out.append(revolute(f"door_{k}_hinge", "base_cabinet", f"door_{k}", axis=(0, 0, 1), origin=(xh, d / 2, 0.05),
                            opens=1.75 if sx < 0 else -1.75))
        out.append(Joint(f"door_{k}_handle_mount", "prismatic", f"door_{k}", f"door_{k}_handle", (0.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0)))
    return out


@register("locker", parts=("body", "door"), extra_parts=("handle", "vent", "shelf", "hinge", "lock"), size_range=(0.9, 1.95),
          density=500, variants=("full_height", "two_tier", "half_height"))
def locker(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d = rng.uniform(0.3, 0.4), rng.uniform(0.45, 0.5)
    h = rng.uniform(1.8, 1.9) if variant != "half_height" else rng.uniform(0.9, 1.0)
    steel = M.solid(M.jitter(rng, (0.4, 0.45, 0.5), 0.1), "metal", 0.4, 0.6)
    t = 0.01
    out: list[Part | Joint] = [make_part("body", "body", [S.box((w, d - 0.02, t), center=(0, -0.01, t / 2)), S.box((w, d - 0.02, t), center=(0, -0.01, h - t / 2)),
                                                          S.box((t, d - 0.02, h - 2 * t), center=(-w / 2 + t / 2, -0.01, h / 2)),
                                                          S.box((t, d - 0.02, h - 2 * t), center=(w / 2 - t / 2, -0.01, h / 2)),
                                                          S.box((w - 2 * t, t, h - 2 * t), center=(0, -d / 2 + t / 2, h / 2))], steel),
                               _b("shelf", "shelf", (w - 2 * t, d - 0.04, 0.01), (0, -0.01, h * 0.8), steel)]
    n = 2 if variant == "two_tier" else 1
    dh = (h - 0.02) / n
    for k in range(n):
        z0 = 0.01 + k * dh
        out.append(_b(f"door_{k}", "door", (w - 0.004, 0.02, dh - 0.01), (0, d / 2 - 0.01, z0 + dh / 2), steel))
        out.append(_b(f"door_{k}_vent", "vent", (w * 0.6, 0.004, 0.08), (0, d / 2 + 0.002, z0 + dh * 0.85), black("metal")))
        out.append(_b(f"door_{k}_handle", "handle", (0.02, 0.025, 0.1), (w / 2 - 0.05, d / 2 + 0.0125, z0 + dh * 0.5), M.metal(rng)))
        out.append(revolute(f"door_{k}_hinge", "body", f"door_{k}", axis=(0, 0, 1), origin=(-w / 2, d / 2 - 0.02, z0)))
        for part in (f"door_{k}_vent", f"door_{k}_handle"):
            out.append(Joint(f"{part}_mount", "prismatic", f"door_{k}", part, (0.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0)))
    return out


@register("toiletry_bag", parts=("body", "handle"), extra_parts=("zipper", "hook"), size_range=(0.2, 0.32), density=200,
          variants=("zip", "hanging", "roll"), placement="surface")
def toiletry_bag(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.22, 0.28), rng.uniform(0.1, 0.14), rng.uniform(0.1, 0.15)
    fab = M.fabric(rng)
    out = [_b("body", "body", (w, d, h), (0, 0, h / 2), fab, bevel=0.02),
           make_part("handle", "handle", S.tube([(-w / 2, 0, h * 0.7), (-w / 2 - 0.03, 0, h * 0.7), (-w / 2 - 0.03, 0, h * 0.3),
                                                 (-w / 2, 0, h * 0.3)], 0.005), fab),
           _b("zipper", "zipper", (w * 0.8, 0.01, 0.004), (0, 0, h + 0.001), M.metal(rng))]
    if variant == "hanging":
        out.append(make_part("hook", "hook", S.tube([(0, 0, h), (0, 0, h + 0.05), (0, 0.02, h + 0.06)], 0.003), M.metal(rng)))
    return out


@register("deodorant", parts=("body", "cap"), extra_parts=("label",), size_range=(0.1, 0.18), density=900,
          variants=("stick", "spray", "roll_on"), placement="surface")
def deodorant(rng: np.random.Generator, variant: str) -> list[Part]:
    col = _colour(rng)
    if variant == "spray":
        r, h = 0.025, rng.uniform(0.13, 0.16)
        return [_c("body", "body", r, h, (0, 0, h / 2), M.metal(rng), sections=20), _c("cap", "cap", r, 0.03, (0, 0, h + 0.015), col, sections=20),
                _c("label", "label", r + 0.0005, h * 0.5, (0, 0, h * 0.45), M.paper(rng), sections=20)]
    w, d, h = 0.065, 0.035, rng.uniform(0.1, 0.12)
    return [_b("body", "body", (w, d, h), (0, 0, h / 2), col, bevel=0.01), _b("cap", "cap", (w, d, 0.03), (0, 0, h + 0.015), col, bevel=0.01),
            _b("label", "label", (w * 0.8, 0.001, h * 0.5), (0, d / 2 + 0.0005, h * 0.45), M.paper(rng))]


@register("chess_board", parts=("board",), extra_parts=("square", "frame"), size_range=(0.3, 0.55), density=700,
          variants=("wood", "folding", "tournament"), placement="surface")
def chess_board(rng: np.random.Generator, variant: str) -> list[Part]:
    s = rng.uniform(0.3, 0.5)
    t = 0.015
    dark = M.solid(M.jitter(rng, (0.35, 0.2, 0.1), 0.03), "wood", 0.5)
    out = [_b("board", "board", (s, s, t), (0, 0, t / 2), M.wood(rng)),
           _b("frame", "frame", (s + 0.02, s + 0.02, t * 0.8), (0, 0, t * 0.4), dark)]
    q = s * 0.9 / 8
    out.append(make_part("square", "square", [S.box((q, q, 0.001), center=((i - 3.5) * q, (j - 3.5) * q, t + 0.0005))
                                              for i in range(8) for j in range(8) if (i + j) % 2 == 0], dark))
    return out


@register("chess_piece", parts=("base", "body"), extra_parts=("head",), size_range=(0.04, 0.11), density=800,
          variants=("pawn", "rook", "king"), placement="surface")
def chess_piece(rng: np.random.Generator, variant: str) -> list[Part]:
    h = {"pawn": 0.05, "rook": 0.06, "king": 0.095}[variant]
    r = h * 0.28 if variant != "king" else h * 0.22
    mat = M.solid((0.92, 0.88, 0.8) if rng.uniform() < 0.5 else (0.12, 0.1, 0.1), "wood", 0.4)
    out = [_c("base", "base", r, h * 0.15, (0, 0, h * 0.075), mat, sections=18),
           make_part("body", "body", S.frustum(r * 0.8, r * 0.45, h * 0.55, center=(0, 0, h * 0.15), sections=16), mat)]
    if variant == "pawn":
        out.append(make_part("head", "head", S.ellipsoid((r * 0.55, r * 0.55, r * 0.55), center=(0, 0, h * 0.7 + r * 0.5)), mat))
    elif variant == "rook":
        out.append(_c("head", "head", r * 0.7, h * 0.3, (0, 0, h * 0.7 + h * 0.15), mat, sections=8))
    else:
        out.append(make_part("head", "head", [S.box((0.006, 0.006, h * 0.25), center=(0, 0, h * 0.82)),
                                              S.box((0.02, 0.006, 0.006), center=(0, 0, h * 0.88))], mat))
    return out


@register("hanging_scale", parts=("dial", "hook", "pan"), extra_parts=("chain",), size_range=(0.4, 0.8), density=1500,
          variants=("dial", "spring", "digital"), placement="ceiling")
def hanging_scale(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.14, 0.2)
    L = rng.uniform(0.25, 0.4)
    steel = M.metal(rng)
    pan = shell([(r * 0.5, 0.0), (r, 0.06)], 0.002, bottom=0.003, sections=24)
    dial_z = 0.06 + L + 0.1
    out = [make_part("pan", "pan", pan, steel),
           make_part("chain", "chain", [S.tube([(np.cos(a) * r * 0.9, np.sin(a) * r * 0.9, 0.06), (0, 0, 0.06 + L)], 0.002, sections=6)
                                        for a in np.linspace(0, 2 * np.pi, 3, endpoint=False)], steel),
           (_c("dial", "dial", 0.1, 0.05, (0, 0, dial_z), white(rng, "metal"), axis=(0, 1, 0), sections=24) if variant != "spring" else
            _c("dial", "dial", 0.025, 0.2, (0, 0, dial_z), steel, sections=14)),
           make_part("hook", "hook", S.tube([(0, 0, dial_z + 0.1), (0, 0, dial_z + 0.16), (0, 0.03, dial_z + 0.18)], 0.005, sections=8), steel)]
    return out


@register("tea_whisk", parts=("handle", "tines"), extra_parts=("holder",), size_range=(0.09, 0.17), density=400,
          variants=("standing", "on_holder", "lying"), placement="surface")
def tea_whisk(rng: np.random.Generator, variant: str) -> list[Part]:
    bamboo = M.solid(M.jitter(rng, (0.85, 0.75, 0.5), 0.03), "wood", 0.6)
    z0 = 0.04 if variant == "on_holder" else 0.0
    out = [make_part("tines", "tines", S.lathe([(0.012, z0), (0.03, z0 + 0.02), (0.028, z0 + 0.06), (0.014, z0 + 0.07)]), bamboo),
           _c("handle", "handle", 0.009, 0.045, (0, 0, z0 + 0.07 + 0.0225), bamboo, sections=12)]
    if variant == "on_holder":
        out.append(make_part("holder", "holder", S.lathe([(0.03, 0.0), (0.03, 0.03), (0.015, 0.045)]), M.ceramic(rng)))
    return out


@register("tea_scoop", parts=("scoop", "handle"), extra_parts=("node",), size_range=(0.16, 0.2), density=600,
          variants=("bamboo", "dark", "spoon"), placement="surface")
def tea_scoop(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.17, 0.19)
    mat = M.solid(M.jitter(rng, (0.8, 0.68, 0.45) if variant != "dark" else (0.3, 0.2, 0.12), 0.03), "wood", 0.6)
    return [_b("handle", "handle", (L * 0.8, 0.009, 0.003), (-L * 0.1, 0, 0.0015), mat),
            _b("scoop", "scoop", (L * 0.2, 0.012 if variant != "spoon" else 0.025, 0.006), (L * 0.4, 0, 0.003), mat),
            _b("node", "node", (0.006, 0.01, 0.005), (-L * 0.05, 0, 0.0025), mat)]


@register("dais", parts=("platform",), extra_parts=("step", "edge"), size_range=(0.8, 2.6), density=600,
          variants=("tatami", "stage", "stepped"))
def dais(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.9, 2.4), rng.uniform(0.9, 1.8)
    h = rng.uniform(0.15, 0.4)
    top = (M.solid(M.jitter(rng, (0.78, 0.75, 0.5), 0.03), "fabric", 0.9) if variant == "tatami" else M.wood(rng))
    out = [_b("platform", "platform", (w, d, h), (0, 0, h / 2), top),
           make_part("edge", "edge", [S.box((w + 0.01, 0.02, h * 0.3), center=(0, sy * (d / 2), h * 0.85)) for sy in (-1, 1)], M.wood(rng))]
    if variant == "stepped":
        out.append(_b("step", "step", (w * 0.5, 0.3, h / 2), (0, d / 2 + 0.15, h / 4), M.wood(rng)))
    return out


@register("incense_burner", parts=("body", "lid"), extra_parts=("foot", "holder", "stick"), size_range=(0.08, 0.3), density=2000,
          variants=("censer", "stick_holder", "cone"), placement="surface")
def incense_burner(rng: np.random.Generator, variant: str) -> list[Part]:
    bronze = M.solid(M.jitter(rng, (0.5, 0.35, 0.2), 0.04), "metal", 0.4, 0.8)
    if variant == "stick_holder":
        L = rng.uniform(0.22, 0.27)
        return [_b("body", "body", (L, 0.035, 0.012), (0, 0, 0.006), M.wood(rng)),
                _c("lid", "lid", 0.006, 0.008, (-L / 2 + 0.02, 0, 0.016), bronze, sections=10),
                make_part("stick", "stick", S.tube([(-L / 2 + 0.02, 0, 0.02), (L / 2 - 0.02, 0, 0.1)], 0.0015, sections=6),
                          M.solid((0.5, 0.3, 0.2), "wood", 0.9))]
    r = rng.uniform(0.05, 0.08)
    out = [make_part("body", "body", S.lathe([(r * 0.6, 0.02), (r, 0.05), (r * 0.9, 0.08)]), bronze),
           make_part("lid", "lid", S.lathe([(r * 0.9, 0.08), (r * 0.5, 0.11), (0.01, 0.13)]), bronze),
           make_part("foot", "foot", [S.cylinder(0.008, 0.02, center=(np.cos(a) * r * 0.5, np.sin(a) * r * 0.5, 0.01), sections=8)
                                      for a in np.linspace(0, 2 * np.pi, 3, endpoint=False)], bronze)]
    return out


@register("brazier", parts=("bowl", "stand"), extra_parts=("grate", "leg", "handle"), size_range=(0.25, 0.7), density=2500,
          variants=("hibachi", "tripod", "box"), placement="floor")
def brazier(rng: np.random.Generator, variant: str) -> list[Part]:
    iron = M.solid((0.15, 0.13, 0.12), "metal", 0.6, 0.7)
    if variant == "hibachi":
        r, h = rng.uniform(0.15, 0.2), rng.uniform(0.22, 0.3)
        return [make_part("bowl", "bowl", shell([(r * 0.8, 0.03), (r, h)], 0.01, bottom=0.015, sections=24), M.ceramic(rng)),
                _c("stand", "stand", r * 0.75, 0.03, (0, 0, 0.015), M.wood(rng), sections=24),
                _c("grate", "grate", r * 0.7, 0.004, (0, 0, h * 0.6), iron, sections=16)]
    w = rng.uniform(0.3, 0.5)
    h = rng.uniform(0.35, 0.6)
    out = [make_part("bowl", "bowl", shell([(w * 0.3, h - 0.12), (w / 2, h)], 0.004, bottom=0.006, sections=20) if variant == "tripod"
                     else S.box((w, w * 0.6, 0.12), center=(0, 0, h - 0.06)), iron),
           _c("stand", "stand", w * 0.2, 0.02, (0, 0, h - 0.13), iron, sections=16),
           make_part("leg", "leg", [S.tube([(np.cos(a) * w * 0.2, np.sin(a) * w * 0.2, h - 0.13), (np.cos(a) * w * 0.45, np.sin(a) * w * 0.45, 0.01)],
                                           0.01, sections=8) for a in np.linspace(0, 2 * np.pi, 3, endpoint=False)], iron)]
    return out
