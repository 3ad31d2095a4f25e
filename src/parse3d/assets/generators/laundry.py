"""Laundry rooms and wardrobes: ironing boards, drying racks, hangers, clothes on hangers and
shoes.

A hanger's hook is its top: clothes hang ``HANGING_BELOW`` a rail or ``IN`` a wardrobe by it; a
jacket or a coat without a hanger hangs on a wall hook or a coat stand by the loop in its collar. A
pair of shoes is one asset (two shoes side by side, each with its sole, upper and laces).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._casework import black


@register("ironing_board", parts=("board", "leg"), extra_parts=("iron_rest", "foot", "cover", "pivot", "lever", "bracket",
                                                                "cord_holder"), size_range=(1.0, 1.55),
          density=500, variants=("standard", "wide", "tabletop"))
def ironing_board(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(1.1, 1.4) if variant != "tabletop" else rng.uniform(1.0, 1.1)
    W = rng.uniform(0.33, 0.38) if variant != "wide" else rng.uniform(0.42, 0.48)
    h = rng.uniform(0.8, 0.92) if variant != "tabletop" else rng.uniform(0.18, 0.24)
    steel = M.solid(M.jitter(rng, (0.75, 0.75, 0.78), 0.03), "metal", 0.4, 0.8)
    tip = L * 0.22
    outline = [(-L / 2, -W / 2), (L / 2 - tip, -W / 2), (L / 2, 0.0), (L / 2 - tip, W / 2), (-L / 2, W / 2)]
    parts = [make_part("board", "board", S.prism(np.array(outline), h - 0.025, h - 0.005), steel),
             make_part("cover", "cover", S.prism(np.array(outline) * [0.995, 0.98], h - 0.005, h), M.fabric(rng)),
             make_part("iron_rest", "iron_rest", S.box((0.12, W * 0.9, 0.01), center=(-L / 2 - 0.06, 0, h - 0.015)), steel)]
    r = 0.011
    a = -L * 0.22
    for i, (xb, xt) in enumerate([(a - L * 0.18, a + L * 0.1), (a + L * 0.18, a - L * 0.1)]):
        for j, sy in enumerate((-1, 1)):
            y = sy * (W / 2 - 0.05 - 0.02 * i)
            parts.append(make_part(f"leg_{2 * i + j}", "leg", S.tube([(xb, y, r), (xt, y, h - 0.03)], r, sections=8), steel))
        parts.append(make_part(f"foot_{i}", "foot", S.cylinder(0.014, W - 0.06 - 0.04 * i, center=(xb, 0, 0.014), axis=(0, 1, 0),
                                                               sections=10), black()))
    # the rivet the two leg frames cross on (each side), the brackets under the board the legs
    # hang in, the height lever at the leg's top and the cord holder clipped to the board's edge
    zc = r + (h - 0.03 - r) * 0.5
    parts += [make_part(f"pivot_{j}", "pivot", S.cylinder(0.01, 0.05, center=(a, sy * (W / 2 - 0.06), zc), axis=(0, 1, 0), sections=10),
                        steel) for j, sy in enumerate((-1, 1))]
    parts += [make_part(f"bracket_{k}", "bracket", S.box((0.08, W * 0.8, 0.012), center=(x, 0, h - 0.031)), steel)
              for k, x in enumerate((a + L * 0.1, a - L * 0.1))]
    parts.append(make_part("lever", "lever", S.box((0.1, 0.02, 0.012), center=(a - L * 0.1 - 0.09, 0, h - 0.045), bevel=0.003), black()))
    parts.append(make_part("cord_holder", "cord_holder", S.tube([(L * 0.05, W / 2 - 0.01, h - 0.025), (L * 0.05, W / 2 + 0.02, h + 0.1),
                                                                  (L * 0.05 - 0.04, W / 2 + 0.02, h + 0.16)], 0.003, sections=6), steel))
    return parts


@register("drying_rack", parts=("rod", "frame"), extra_parts=("leg", "wing", "foot"), size_range=(0.7, 1.8), density=500,
          variants=("gullwing", "a_frame", "tower"))
def drying_rack(rng: np.random.Generator, variant: str) -> list[Part]:
    steel = M.solid(M.jitter(rng, (0.9, 0.9, 0.9), 0.02), "metal", 0.4, 0.6)
    r = 0.005
    parts = []
    if variant == "tower":
        w, d, h = rng.uniform(0.6, 0.8), rng.uniform(0.4, 0.5), rng.uniform(1.2, 1.6)
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"frame_{i}", "frame", S.cylinder(0.01, h, center=(sx * w / 2, sy * d / 2, h / 2), sections=10), steel))
        n = int(rng.integers(3, 5))
        for k in range(n):
            z = h * (k + 1) / n - 0.02
            for j, sy in enumerate(np.linspace(-d / 2 + 0.05, d / 2 - 0.05, 3)):
                parts.append(make_part(f"rod_{3 * k + j}", "rod", S.cylinder(r, w, center=(0, sy, z), axis=(1, 0, 0), sections=8), steel))
        return parts
    w, h = rng.uniform(0.55, 0.7), rng.uniform(0.85, 1.05)
    spread = rng.uniform(0.45, 0.6)
    for i, sy in enumerate((-1, 1)):
        for j, sx in enumerate((-1, 1)):
            parts.append(make_part(f"leg_{2 * i + j}", "leg", S.tube([(sx * w / 2, sy * spread / 2, r), (sx * w / 2, sy * 0.03, h)], 0.008),
                                   steel))
        parts.append(make_part(f"foot_{i}", "foot", S.cylinder(0.008, w + 0.02, center=(0, sy * spread / 2, 0.008), axis=(1, 0, 0),
                                                               sections=8), steel))
    parts.append(make_part("frame", "frame", S.cylinder(0.009, w + 0.02, center=(0, 0, h), axis=(1, 0, 0), sections=8), steel))
    n = int(rng.integers(4, 7))
    k = 0
    for sy in (-1, 1):
        for j in range(n):
            t = (j + 1) / (n + 1)
            parts.append(make_part(f"rod_{k}", "rod", S.cylinder(r, w, center=(0, sy * (0.03 + (spread / 2 - 0.03) * t), h - (h - 0.25) * t),
                                                                axis=(1, 0, 0), sections=8), steel))
            k += 1
    if variant == "gullwing":
        for i, sy in enumerate((-1, 1)):
            wing = [S.cylinder(r, w, center=(0, sy * (0.05 + 0.06 * m), h + 0.02 * m), axis=(1, 0, 0), sections=8) for m in range(1, 5)]
            wing.append(S.tube([(-w / 2, sy * 0.03, h), (-w / 2, sy * 0.3, h + 0.08)], r))
            wing.append(S.tube([(w / 2, sy * 0.03, h), (w / 2, sy * 0.3, h + 0.08)], r))
            parts.append(make_part(f"wing_{i}", "wing", wing, steel))
    return parts


def _hanger(x: float, y: float, top: float, w: float, mat, *, wire: bool) -> list[S.Shape]:
    """A coat hanger whose hook tip is at height ``top``; returns the hook and the shoulder bar."""
    r = 0.0025 if wire else 0.006
    hook = S.tube([(x, y, top - 0.07), (x, y, top - 0.015), (x + 0.015, y, top), (x + 0.03, y, top - 0.015)], 0.002, sections=6)
    z = top - 0.07
    if wire:
        bar = S.union([S.tube([(x - w / 2, y, z - 0.12), (x, y, z), (x + w / 2, y, z - 0.12)], r, sections=6),
                       S.tube([(x - w / 2 + 0.004, y, z - 0.12), (x + w / 2 - 0.004, y, z - 0.12)], r, sections=6)])
    else:
        bar = S.union([S.box((w / 2, 0.012, 0.025), center=(x - w / 4, y, z - 0.04), R=_rot_y(-0.35)),
                       S.box((w / 2, 0.012, 0.025), center=(x + w / 4, y, z - 0.04), R=_rot_y(0.35))])
    return [hook, bar]


def _rot_y(a: float) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


@register("clothes_hanger", parts=("hook", "bar"), extra_parts=("crossbar", "neck", "twist", "strap_hook"), size_range=(0.3, 0.48),
          density=700,
          variants=("wooden", "wire", "plastic"), placement="inside")
def clothes_hanger(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.38, 0.45)
    mat = {"wooden": M.wood(rng), "wire": M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9), "plastic": M.plastic(rng)}[variant]
    hook, bar = _hanger(0.0, 0.0, 0.0, w, mat, wire=variant == "wire")
    parts = [make_part("hook", "hook", hook, M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9)), make_part("bar", "bar", bar, mat)]
    if variant == "wooden":
        parts.append(make_part("crossbar", "crossbar", S.cylinder(0.005, w * 0.8, center=(0, 0, -0.07 - 0.15), axis=(1, 0, 0),
                                                                  sections=8), mat))
        parts += [make_part("crossbar_post" if k == 0 else f"crossbar_post_{k}", "crossbar",
                            S.box((0.012, 0.012, 0.11), center=(s * w * 0.42, 0, -0.07 - 0.1)), mat) for k, s in enumerate((-1, 1))]
    steel = M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9)
    if variant == "wire":  # the wire twisted round itself under the hook
        parts.append(make_part("twist", "twist", S.cylinder(0.0045, 0.025, center=(0, 0, -0.07 - 0.0125 + 0.012), sections=8), steel))
    else:  # the ferrule where the hook screws into the bar
        parts.append(make_part("neck", "neck", S.cylinder(0.006, 0.016, center=(0, 0, -0.07 + 0.002), sections=8), steel))
    if variant == "plastic":  # the little hooks on the shoulders for straps
        for k, sx in enumerate((-1, 1)):
            x = sx * w * 0.3
            z = -0.07 - 0.04 - np.tan(0.35) * (abs(x) - w / 4) + 0.0125  # the shoulder's top there
            parts.append(make_part(f"strap_hook_{k}", "strap_hook", S.box((0.006, 0.01, 0.018), center=(x, 0, z + 0.008)), mat))
    return parts


@register("hanging_clothes", parts=("garment",), extra_parts=("hook", "bar", "loop", "sleeve", "collar", "button", "strap",
                                                           "sash", "pocket", "cuff"),
          size_range=(0.5, 1.3), density=150, variants=("shirt", "coat", "dress", "loop"),
          placement="inside")
def hanging_clothes(rng: np.random.Generator, variant: str) -> list[Part]:
    """A garment on a coat hanger (``shirt``, ``coat``, ``dress``: the hanger's hook is its top),
    or a jacket or a coat without one (``loop``): it hangs on a wall hook or a coat stand by the
    hanging loop sewn into the back of its collar, the loop its top."""
    looped = variant == "loop"
    kind = ("jacket", "coat")[int(rng.integers(2))] if looped else variant
    w = rng.uniform(0.4, 0.46)
    cloth = M.fabric(rng)
    parts = []
    if not looped:
        hook, bar = _hanger(0.0, 0.0, 0.0, w, M.wood(rng), wire=False)
        parts += [make_part("hook", "hook", hook, M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9)),
                  make_part("bar", "bar", bar, M.wood(rng))]
    L = {"shirt": rng.uniform(0.6, 0.75), "jacket": rng.uniform(0.62, 0.78), "coat": rng.uniform(0.85, 1.1),
         "dress": rng.uniform(0.9, 1.15)}[kind]
    th = {"coat": 0.06, "jacket": 0.045}.get(kind, 0.03)
    zt = -0.09
    if kind == "dress":
        body = S.hull([[-w * 0.42, -th, zt], [w * 0.42, -th, zt], [-w * 0.42, th, zt], [w * 0.42, th, zt],
                       [-w * 0.7, -th, zt - L], [w * 0.7, -th, zt - L], [-w * 0.7, th, zt - L], [w * 0.7, th, zt - L]])
    else:
        body = S.box((w * 0.95, 2 * th, L), center=(0, 0, zt - L / 2), bevel=0.01)
    parts.append(make_part("garment", "garment", body, cloth))
    if kind == "dress":  # its shoulder straps over the bar, and the sash at the waist
        parts += [make_part(f"strap_{k}", "strap", S.box((0.025, 2 * th + 0.004, 0.05), center=(sx * w * 0.3, 0, zt + 0.015)), cloth)
                  for k, sx in enumerate((-1, 1))]
        zw = zt - L * 0.3
        ww = w * 0.42 + (w * 0.7 - w * 0.42) * 0.3
        parts.append(make_part("sash", "sash", S.box((2 * ww + 0.006, 2 * th + 0.006, 0.05), center=(0, 0, zw)), M.fabric(rng)))
    else:  # a breast pocket on the front, and a cuff at each sleeve's end
        parts.append(make_part("pocket", "pocket", S.box((0.1, 0.004, 0.12), center=(-w * 0.2, th + 0.002, zt - 0.2)), cloth))
        for i, sx in enumerate((-1, 1)):
            c = np.array([sx * (w * 0.475 + 0.06), 0, zt - 0.03 - L * 0.375]) + _rot_y(sx * 0.08) @ np.array([0, 0, -L * 0.375 + 0.03])
            parts.append(make_part(f"cuff_{i}", "cuff", S.box((0.13, 2 * th * 0.85, 0.06), center=c, R=_rot_y(sx * 0.08)), cloth))
    if kind != "dress":
        for i, s in enumerate((-1, 1)):
            sl = S.box((0.12, 2 * th * 0.8, L * 0.75), center=(s * (w * 0.475 + 0.06), 0, zt - 0.03 - L * 0.375), R=_rot_y(s * 0.08))
            parts.append(make_part(f"sleeve_{i}", "sleeve", sl, cloth))
        # on a hanger the collar stands over the shoulders; hung by its loop it folds down level with them
        zc = zt - 0.02 if looped else zt - 0.01
        parts.append(make_part("collar", "collar", S.box((0.16, 2 * th + 0.01, 0.04), center=(0, 0.003, zc)), cloth))
        nb = 5 if kind == "shirt" else 3
        for k in range(nb):
            parts.append(make_part(f"button_{k}", "button", S.cylinder(0.006, 0.004, center=(0, th + 0.001, zt - 0.08 - k * L * 0.8 / nb),
                                                                       axis=(0, 1, 0), sections=8), M.plastic(rng)))
    if looped:  # the hanging loop, a tape arc rising from the back of the collar
        yb = -th + 0.008
        loop = S.tube([(-0.02, yb, zt - 0.006), (-0.012, yb, zt + 0.01), (0.012, yb, zt + 0.01), (0.02, yb, zt - 0.006)], 0.003,
                      sections=6)
        parts.append(make_part("loop", "loop", loop, cloth))
    return parts


def _shoe(x: float, L: float, W: float, *, kind: str, upper_mat, sole_mat):
    sole = S.box((W, L, 0.025), center=(x, 0, 0.0125), bevel=0.008)
    if kind == "boot":
        upper = S.union([S.box((W * 0.95, L * 0.95, 0.07), center=(x, 0.0, 0.06), bevel=0.02),
                         S.box((W * 0.9, L * 0.4, 0.18), center=(x, -L * 0.28, 0.14), bevel=0.02)])
    elif kind == "heel":
        upper = S.hull([[x - W * 0.45, L * 0.45, 0.025], [x + W * 0.45, L * 0.45, 0.025], [x - W * 0.45, -L * 0.45, 0.09],
                        [x + W * 0.45, -L * 0.45, 0.09], [x - W * 0.4, -L * 0.2, 0.12], [x + W * 0.4, -L * 0.2, 0.12],
                        [x - W * 0.4, L * 0.4, 0.05], [x + W * 0.4, L * 0.4, 0.05]])
    else:
        upper = S.box((W * 0.95, L * 0.95, 0.07), center=(x, 0.0, 0.06), bevel=0.025)
    laces = S.box((W * 0.35, L * 0.3, 0.006), center=(x, L * 0.15, 0.095 if kind != "heel" else 0.06))
    return sole, upper, laces


@register("shoes", parts=("sole", "upper"), extra_parts=("laces", "heel", "tongue", "heel_tab", "toe_cap", "heel_tip"), size_range=(0.2, 0.35), density=300,
          variants=("sneakers", "boots", "heels"), placement="floor")
def shoes(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.24, 0.31)
    W = L * 0.36
    kind = {"sneakers": "sneaker", "boots": "boot", "heels": "heel"}[variant]
    up = M.leather(rng) if variant != "sneakers" else M.fabric(rng)
    sole_mat = M.solid((0.92, 0.92, 0.9), "plastic", 0.7) if variant == "sneakers" else black()
    parts = []
    for i, x in enumerate((-W * 0.6, W * 0.6)):
        sole, upper, laces = _shoe(x, L, W, kind=kind, upper_mat=up, sole_mat=sole_mat)
        parts.append(make_part(f"sole_{i}", "sole", sole, sole_mat))
        parts.append(make_part(f"upper_{i}", "upper", upper, up))
        if variant == "heels":
            parts.append(make_part(f"heel_{i}", "heel", S.box((0.015, 0.015, 0.07), center=(x, -L * 0.43, 0.035 + 0.02)), black()))
            # the hard tip under the heel's end
            parts.append(make_part(f"heel_tip_{i}", "heel_tip", S.box((0.017, 0.017, 0.008), center=(x, -L * 0.43, 0.02 + 0.004)),
                                   M.solid((0.2, 0.2, 0.2), "rubber", 0.8)))
        else:
            parts.append(make_part(f"laces_{i}", "laces", laces, M.solid((0.95, 0.95, 0.95), "fabric")))
            # the tongue under the laces and the pull tab at the back of the collar
            parts.append(make_part(f"tongue_{i}", "tongue", S.box((W * 0.3, L * 0.12, 0.008), center=(x, L * 0.0, 0.099)), up))
            ytab, ztab = (-L * 0.475 - 0.003, 0.085) if variant == "sneakers" else (-L * 0.48 - 0.003, 0.215)
            parts.append(make_part(f"heel_tab_{i}", "heel_tab", S.box((0.02, 0.006, 0.03), center=(x, ytab, ztab)), up))
            if variant == "sneakers":  # the rubber toe cap over the front of the upper
                parts.append(make_part(f"toe_cap_{i}", "toe_cap", S.box((W * 0.9, L * 0.1, 0.035), center=(x, L * 0.44, 0.04),
                                                                          bevel=0.01), sole_mat))
    return parts
