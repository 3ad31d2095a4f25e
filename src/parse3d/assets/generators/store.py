"""Grocery stores and storage rooms: baskets, carts, checkout counters, produce and wooden
crates, cardboard boxes, chest freezers, bread and fruit.

Open containers (baskets, crates, boxes, the cart) have a floor with walls around it, so
:mod:`parse3d.assets.internal` finds the floor as an internal support for ``IN``. A chest
freezer's lid is a revolute joint hinged along the back top edge; an open cardboard box's four
flaps are revolute joints folding out from the rim.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Part, make_part
from ..registry import register
from ._casework import bar_pull, black, white
from ._dD_detail import back_screws
from ._detail_b import studs
from ._kit import OPEN_DOOR, feet4, hinge_parts, mount, revolute


def _walls(w: float, d: float, h: float, t: float, z0: float = 0.0) -> list[S.Shape]:
    """Four walls of an open box standing on ``z0`` (outer size ``w x d``)."""
    return [S.box((w, t, h), center=(0, -d / 2 + t / 2, z0 + h / 2)), S.box((w, t, h), center=(0, d / 2 - t / 2, z0 + h / 2)),
            S.box((t, d - 2 * t, h), center=(-w / 2 + t / 2, 0, z0 + h / 2)),
            S.box((t, d - 2 * t, h), center=(w / 2 - t / 2, 0, z0 + h / 2))]


@register("shopping_basket", parts=("basket", "handle"), extra_parts=("rim", "base", "pivot", "label", "grip"), size_range=(0.3, 0.55), density=300,
          variants=("plastic", "wire"), placement="surface")
def shopping_basket(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.4, 0.47), rng.uniform(0.28, 0.33), rng.uniform(0.2, 0.25)
    mat = M.solid(M.jitter(rng, [(0.8, 0.1, 0.1), (0.1, 0.3, 0.7), (0.1, 0.55, 0.25)][int(rng.integers(3))], 0.03), "plastic", 0.4) \
        if variant == "plastic" else M.solid((0.75, 0.75, 0.77), "metal", 0.3, 0.8)
    t = 0.006
    parts = [make_part("base", "base", S.box((w - 0.02, d - 0.02, t), center=(0, 0, t / 2)), mat),
             make_part("basket", "basket", _walls(w, d, h - t, t, z0=t), mat),
             make_part("rim", "rim", _walls(w + 0.01, d + 0.01, 0.015, 0.008, z0=h - 0.015), mat)]
    for i, s in enumerate((-1, 1)):
        y = s * (d / 2 - 0.02)
        parts.append(make_part(f"handle_{i}", "handle", S.tube([(-w * 0.3, y, h - 0.01), (-w * 0.2, y * 0.5, h + 0.12),
                                                                (w * 0.2, y * 0.5, h + 0.12), (w * 0.3, y, h - 0.01)], 0.006),
                               black() if variant == "plastic" else mat))
    # each handle end turns in a pivot on the rim; the store's name plate on the front
    parts += studs("pivot", "pivot", [(sx * w * 0.3, sy * (d / 2 + 0.009), h - 0.012) for sy in (-1, 1) for sx in (-1, 1)],
                   r=0.009, h=0.006, mat=black(), axis=(0, 1, 0))
    parts.append(make_part("label", "label", S.box((0.12, 0.002, 0.04), center=(0, d / 2 + 0.001, h * 0.5)),
                           M.solid((0.95, 0.95, 0.95), "plastic", 0.4)))
    # the moulded grip sleeve round the middle of each handle
    for i, s in enumerate((-1, 1)):
        y = s * (d / 2 - 0.02)
        parts.append(make_part(f"grip_{i}", "grip", S.cylinder(0.011, w * 0.3, center=(0, y * 0.5, h + 0.12), axis=(1, 0, 0), sections=10),
                               black()))
    return parts


@register("shopping_cart", parts=("basket", "wheel", "handle"), extra_parts=("frame", "base", "child_seat", "bumper", "fork",
                                                                            "coin_lock", "end_cap", "hub", "hinge", "ad_panel"),
          size_range=(0.85, 1.15), density=250, variants=("full_size", "compact"))
def shopping_cart(rng: np.random.Generator, variant: str) -> list[Part]:
    k = 1.0 if variant == "full_size" else 0.8
    L, W, H = rng.uniform(0.9, 1.0) * k, rng.uniform(0.52, 0.6) * k, rng.uniform(0.95, 1.05)
    steel = M.solid((0.78, 0.78, 0.8), "metal", 0.3, 0.9)
    zb = 0.45 * (1 if variant == "full_size" else 1.1)
    bh = H - 0.08 - zb
    t = 0.01
    parts = [make_part("base", "base", S.box((L * 0.85, W - 0.04, t), center=(0.03, 0, zb + t / 2)), steel),
             make_part("basket", "basket", _walls(L * 0.85 + 0.02, W, bh, t, z0=zb), steel)]
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        parts.append(make_part(f"wheel_{i}", "wheel", S.cylinder(0.05, 0.03, center=(sx * (L / 2 - 0.08), sy * (W / 2 - 0.06), 0.05),
                                                                 axis=(0, 1, 0), sections=14), black()))
    frame = [S.box((L - 0.1, 0.03, 0.03), center=(0, sy * (W / 2 - 0.06), 0.12)) for sy in (-1, 1)]
    frame += [S.box((0.03, 0.03, zb - 0.12), center=(-L / 2 + 0.12, sy * (W / 2 - 0.06), (zb + 0.12) / 2)) for sy in (-1, 1)]
    parts.append(make_part("frame", "frame", frame, steel))
    parts.append(make_part("bottom_tray", "base", S.box((L * 0.7, W - 0.12, 0.008), center=(0, 0, 0.14)), steel))
    xb = -L / 2 + 0.02
    parts.append(make_part("handle", "handle", S.cylinder(0.015, W - 0.02, center=(xb, 0, H), axis=(0, 1, 0), sections=12),
                           M.solid((0.8, 0.1, 0.1), "plastic", 0.4)))
    parts.append(make_part("handle_arms", "frame", [S.tube([(xb + 0.1, sy * (W / 2 - 0.02), zb + bh * 0.8), (xb, sy * (W / 2 - 0.02), H)],
                                                           0.008) for sy in (-1, 1)], steel))
    if variant == "full_size":
        parts.append(make_part("child_seat", "child_seat", S.box((0.25, W - 0.1, 0.01), center=(-L * 0.3, 0, H - 0.18),
                                                                 R=_rx(0.0)), steel))
    parts.append(make_part("bumper", "bumper", S.box((0.02, W, 0.08), center=(L * 0.85 / 2 + 0.04, 0, zb + 0.1)), black()))
    # the swivel fork each wheel turns in, the coin lock on the handle and the caps on its ends
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        x, y = sx * (L / 2 - 0.08), sy * (W / 2 - 0.06)
        parts.append(make_part(f"fork_{i}", "fork", [S.box((0.05, 0.006, 0.07), center=(x, y + dy, 0.085)) for dy in (-0.02, 0.02)]
                               + [S.box((0.05, 0.046, 0.01), center=(x, y, 0.12))], steel))
    parts.append(make_part("coin_lock", "coin_lock", S.box((0.08, 0.06, 0.05), center=(xb + 0.03, -W * 0.3, H - 0.04), bevel=0.005),
                           M.solid((0.85, 0.7, 0.1), "plastic", 0.4)))
    parts += [make_part(f"end_cap_{k}", "end_cap", S.cylinder(0.017, 0.012, center=(xb, sy * (W / 2 - 0.01 + 0.006), H), axis=(0, 1, 0),
                                                              sections=12), black()) for k, sy in enumerate((-1, 1))]
    # the grey hub in each wheel's outer face, the advertising board across the handle's front,
    # and the child seat's two hinges on the back wall it folds up on
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        parts.append(make_part(f"hub_{i}", "hub", S.cylinder(0.02, 0.034, center=(sx * (L / 2 - 0.08), sy * (W / 2 - 0.06), 0.05), axis=(0, 1, 0),
                                                            sections=10), M.solid((0.5, 0.5, 0.52), "plastic", 0.5)))
    parts.append(make_part("ad_panel", "ad_panel", S.box((0.006, W * 0.5, 0.08), center=(xb + 0.04, 0, H - 0.08)),
                           M.solid((0.95, 0.95, 0.95), "plastic", 0.4)))
    if variant == "full_size":
        parts += [make_part(f"hinge_{k}", "hinge", S.cylinder(0.008, 0.05, center=(-L * 0.3 - 0.125, sy * (W / 2 - 0.1), H - 0.18), axis=(0, 1, 0),
                                                              sections=10), steel) for k, sy in enumerate((-1, 1))]
    return parts


def _rx(a: float) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


@register("checkout_counter", parts=("body", "countertop"), extra_parts=("conveyor", "register", "screen", "card_terminal",
                                                                          "divider", "bag_well", "kick_plate", "scanner",
                                                                          "printer", "cash_drawer", "key", "roller"),
          size_range=(1.4, 2.6), density=400, variants=("conveyor", "compact"))
def checkout_counter(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(1.8, 2.5) if variant == "conveyor" else rng.uniform(1.4, 1.7)
    d, h = rng.uniform(0.6, 0.75), rng.uniform(0.85, 0.92)
    shell = M.solid(M.jitter(rng, [(0.85, 0.85, 0.83), (0.3, 0.3, 0.32), (0.55, 0.4, 0.28)][int(rng.integers(3))], 0.02), "wood", 0.5)
    top_mat = M.stone(rng)
    parts = [make_part("body", "body", S.box((L, d, h - 0.03 - 0.08), center=(0, 0, 0.08 + (h - 0.11) / 2)), shell),
             make_part("kick_plate", "kick_plate", S.box((L - 0.04, d - 0.04, 0.08), center=(0, -0.01, 0.04)), black()),
             make_part("countertop", "countertop", S.box((L, d + 0.02, 0.03), center=(0, 0.01, h - 0.015), bevel=0.004), top_mat)]
    if variant == "conveyor":
        cl = L * 0.55
        parts.append(make_part("conveyor", "conveyor", S.box((cl, d * 0.7, 0.02), center=(-L / 2 + cl / 2 + 0.03, 0.0, h + 0.01)),
                               black()))
        parts.append(make_part("divider", "divider", S.box((0.3, 0.03, 0.05), center=(-L / 2 + 0.4, -0.1, h + 0.045),
                                                           R=_rz(0.4)), M.solid((0.9, 0.7, 0.1), "plastic")))
        parts.append(make_part("bag_well", "bag_well", _walls(0.4, d * 0.8, 0.08, 0.01, z0=h), top_mat))
        x_reg = L / 2 - 0.45
    else:
        x_reg = 0.0
    parts.append(make_part("register", "register", S.box((0.35, 0.35, 0.1), center=(x_reg, -d / 2 + 0.2, h + 0.05), bevel=0.01),
                           black()))
    parts.append(make_part("screen", "screen", S.box((0.3, 0.02, 0.22), center=(x_reg, -d / 2 + 0.2, h + 0.1 + 0.13),
                                                     R=_rx(-0.2)), M.solid((0.1, 0.12, 0.15), "glass", 0.1)))
    parts.append(make_part("card_terminal", "card_terminal", S.box((0.08, 0.14, 0.05), center=(x_reg + 0.3, d / 2 - 0.1, h + 0.025),
                                                                   bevel=0.008), black()))
    # the barcode scanner's glass set in the top beside the register, the receipt printer and
    # the cash drawer under the counter's top on the cashier's side
    parts.append(make_part("scanner", "scanner", S.box((0.2, 0.2, 0.004), center=(x_reg - 0.28, d / 2 - 0.14, h + 0.002)),
                           M.solid((0.1, 0.1, 0.12), "glass", 0.1)))
    parts.append(make_part("printer", "printer", S.box((0.14, 0.18, 0.12), center=(x_reg + 0.27, -d / 2 + 0.12, h + 0.06), bevel=0.01),
                           black()))
    parts.append(make_part("cash_drawer", "cash_drawer", S.box((0.4, 0.02, 0.1), center=(x_reg, -d / 2 - 0.01, h - 0.03 - 0.07)),
                           black()))
    # the register's sixteen-key pad on its top, towards the cashier
    for k in range(16):
        col, row = k % 4, k // 4
        parts.append(make_part(f"key_{k}", "key", S.box((0.03, 0.03, 0.006), center=(x_reg - 0.06 + col * 0.04, -d / 2 + 0.08 + row * 0.04,
                                                                                     h + 0.1 + 0.002), bevel=0.002),
                               M.solid((0.8, 0.8, 0.8), "plastic", 0.4)))
    if variant == "conveyor":  # the belt's end rollers, their tops level with the belt
        cl = L * 0.55
        parts += [make_part(f"roller_{k}", "roller", S.cylinder(0.0095, d * 0.72, center=(x, 0, h + 0.0095), axis=(0, 1, 0), sections=10),
                            M.solid((0.6, 0.6, 0.62), "metal", 0.3, 0.8)) for k, x in enumerate((-L / 2 + 0.03 - 0.006, -L / 2 + 0.03 + cl + 0.006))]
    return parts


def _rz(a: float) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def _slatted_crate(prefix: str, *, w: float, d: float, h: float, n: int, t: float, mat, post: float) -> list[Part]:
    """A crate of horizontal slats on all four sides, a slatted floor and corner posts."""
    parts = []
    k = 0
    pitch = h / n
    for j in range(n):
        z = pitch * j + pitch * 0.35
        sh = pitch * 0.65
        for s in (-1, 1):
            parts.append(make_part(f"slat_{k}", "slat", S.box((w - 2 * post, t, sh), center=(0, s * (d / 2 - t / 2), z + sh / 2 - pitch * 0.35 + 0.002)),
                                   mat))
            k += 1
            parts.append(make_part(f"slat_{k}", "slat", S.box((t, d - 2 * post, sh), center=(s * (w / 2 - t / 2), 0, z + sh / 2 - pitch * 0.35 + 0.002)),
                                   mat))
            k += 1
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        parts.append(make_part(f"post_{i}", "post", S.box((post, post, h), center=(sx * (w / 2 - post / 2), sy * (d / 2 - post / 2), h / 2)),
                               mat))
    # each slat is nailed through the corner posts into its end grain: a nail head on each
    # post's two outer faces at every row
    steel = M.solid((0.35, 0.35, 0.37), "metal", 0.5, 0.7)
    k = 0
    for j in range(n):
        z = pitch * j + pitch * 0.65 / 2 + 0.002
        for sx, sy in [(-1, -1), (1, -1), (-1, 1), (1, 1)]:
            x, y = sx * (w / 2 - post / 2), sy * (d / 2 - post / 2)
            parts.append(make_part(f"nail_{k}", "nail", S.cylinder(0.003, 0.001, center=(x, sy * (d / 2 - 0.0005), z), axis=(0, 1, 0), sections=8),
                                   steel))
            parts.append(make_part(f"nail_{k + 1}", "nail", S.cylinder(0.003, 0.001, center=(sx * (w / 2 - 0.0005), y, z), axis=(1, 0, 0),
                                                                       sections=8), steel))
            k += 2
    parts.append(make_part(f"{prefix}", "bottom", S.box((w - 2 * t, d - 2 * t, t), center=(0, 0, t / 2)), mat))
    return parts


@register("produce_crate", parts=("bottom", "slat"), extra_parts=("post", "handle", "wall", "nail"), size_range=(0.3, 0.7),
          density=500, variants=("wooden", "plastic", "display_bin"), placement="surface")
def produce_crate(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.4, 0.6), rng.uniform(0.3, 0.4)
    h = rng.uniform(0.2, 0.3)
    if variant == "wooden":
        return _slatted_crate("bottom", w=w, d=d, h=h, n=3, t=0.012, mat=M.wood(rng), post=0.02)
    if variant == "display_bin":
        mat = M.wood(rng)
        h = rng.uniform(0.12, 0.18)
        parts = [make_part("bottom", "bottom", S.box((w - 0.024, d - 0.024, 0.012), center=(0, 0, 0.006)), mat)]
        parts += [make_part(f"slat_{i}", "slat", sh, mat) for i, sh in enumerate(_walls(w, d, h, 0.012))]
        # square battens in the inside corners, the boards nailed to them
        b = 0.02
        parts += [make_part(f"post_{k}", "post", S.box((b, b, h - 0.012), center=(sx * (w / 2 - 0.012 - b / 2), sy * (d / 2 - 0.012 - b / 2),
                                                                                 0.012 + (h - 0.012) / 2)), mat)
                  for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)])]
        return parts
    mat = M.solid(M.jitter(rng, [(0.2, 0.5, 0.25), (0.15, 0.2, 0.25), (0.85, 0.45, 0.1)][int(rng.integers(3))], 0.03), "plastic", 0.5)
    t = 0.008
    parts = [make_part("bottom", "bottom", S.box((w - 2 * t, d - 2 * t, t), center=(0, 0, t / 2)), mat)]
    names = ["slat_0", "slat_1", "wall_0", "wall_1"]
    for nm, sh in zip(names, _walls(w, d, h, t), strict=True):
        parts.append(make_part(nm, "slat" if nm.startswith("slat") else "wall", sh, mat))
    for i, s in enumerate((-1, 1)):
        parts.append(make_part(f"handle_{i}", "handle", S.box((0.012, 0.1, 0.03), center=(s * (w / 2 + 0.006), 0, h - 0.03)), mat))
    return parts


@register("wooden_crate", parts=("bottom", "slat"), extra_parts=("post", "lid", "nail"), size_range=(0.3, 0.9), density=450,
          variants=("open", "lidded"))
def wooden_crate(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.4, 0.8), rng.uniform(0.3, 0.6), rng.uniform(0.28, 0.55)
    mat = M.wood(rng)
    parts = _slatted_crate("bottom", w=w, d=d, h=h, n=int(rng.integers(3, 5)), t=0.016, mat=mat, post=0.035)
    if variant == "lidded":
        parts.append(make_part("lid", "lid", [S.box((w * 0.95 / 4, d, 0.016), center=(-w * 0.95 / 2 + w * 0.95 / 4 * (k + 0.5), 0, h + 0.008))
                                              for k in range(4)], mat))
    return parts


@register("cardboard_box", parts=("body",), extra_parts=("flap", "tape", "label", "wall", "bottom", "hand_hole", "tissue", "pouch"), size_range=(0.15, 0.75),
          density=150, variants=("closed", "open", "shoebox"), placement="floor")
def cardboard_box(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    card = M.solid(M.jitter(rng, (0.72, 0.56, 0.38), 0.03), "paper", 0.9)
    if variant == "shoebox":
        w, d, h = rng.uniform(0.3, 0.36), rng.uniform(0.18, 0.22), rng.uniform(0.1, 0.13)
        return [make_part("body", "body", S.box((w - 0.004, d - 0.004, h - 0.004), center=(0, 0, (h - 0.004) / 2)), card),
                make_part("lid", "flap", [S.box((w, d, 0.003), center=(0, 0, h - 0.0015)),
                                          S.box((w, 0.003, 0.03), center=(0, d / 2 - 0.0015, h - 0.015)),
                                          S.box((w, 0.003, 0.03), center=(0, -d / 2 + 0.0015, h - 0.015))], M.paper(rng)),
                make_part("label", "label", S.box((0.08, 0.001, 0.05), center=(w / 4, d / 2 + 0.0005, h / 2)), M.solid((0.95, 0.95, 0.95),
                                                                                                                          "paper")),
                # the size label on one end, and the tissue paper folded over the shoes under the lid
                make_part("label_1", "label", S.box((0.001, d * 0.5, 0.04), center=(w / 2 - 0.002 + 0.0005, 0, h * 0.45)),
                          M.solid((0.95, 0.95, 0.95), "paper")),
                make_part("tissue", "tissue", S.box((w * 0.9, d * 0.9, 0.001), center=(0, 0, h - 0.0045 - 0.0005)),
                          M.solid((0.97, 0.97, 0.97), "paper", 0.9))]
    w, d, h = rng.uniform(0.25, 0.6), rng.uniform(0.2, 0.45), rng.uniform(0.15, 0.45)
    t = 0.005
    if variant == "closed":
        return [make_part("body", "body", S.box((w, d, h), center=(0, 0, h / 2)), card),
                make_part("tape", "tape", S.box((0.05, d + 0.002, 0.001), center=(0, 0, h + 0.0005)),
                          M.solid((0.75, 0.62, 0.4), "plastic", 0.2)),
                make_part("tape_1", "tape", S.box((0.05, 0.001, h * 0.3), center=(0, d / 2 + 0.0005, h * 0.85)),
                          M.solid((0.75, 0.62, 0.4), "plastic", 0.2)),
                make_part("label", "label", S.box((0.1, 0.001, 0.07), center=(w / 4, d / 2 + 0.0005, h / 2)),
                          M.solid((0.95, 0.95, 0.95), "paper")),
                # the tape's other end down the back, and a hand hole cut in each end
                make_part("tape_2", "tape", S.box((0.05, 0.001, h * 0.3), center=(0, -d / 2 - 0.0005, h * 0.85)),
                          M.solid((0.75, 0.62, 0.4), "plastic", 0.2)),
                *[make_part(f"hand_hole_{k}", "hand_hole", S.box((0.001, 0.09, 0.03), center=(sx * (w / 2 + 0.0005), 0, h * 0.75)),
                            M.solid((0.2, 0.15, 0.1), "paper", 0.9)) for k, sx in enumerate((-1, 1))],
                # the clear pouch holding the packing list, stuck on the front beside the label
                make_part("pouch", "pouch", S.box((0.12, 0.002, 0.09), center=(-w / 4, d / 2 + 0.001, h * 0.45)),
                          M.solid((0.9, 0.92, 0.95), "plastic", 0.2))]
    # open: the floor keeps the required label (it carries the internal support for IN)
    parts: list[Part | Joint] = [make_part("body", "body", S.box((w - 2 * t, d - 2 * t, t), center=(0, 0, t / 2)), card)]
    for nm, sh in zip(["wall_back", "wall_front", "wall_left", "wall_right"], _walls(w, d, h, t), strict=True):
        parts.append(make_part(nm, "wall", sh, card))
    # the flaps stand open, leaning out from the rim
    fl, fw = d / 2 - 0.002, w / 2 - 0.002
    lean = 0.35
    for i, s in enumerate((-1, 1)):
        R = _rx(-s * lean)
        c = np.array([0, s * (d / 2 - t / 2), h]) + R @ np.array([0, 0, fl / 2])
        parts.append(make_part(f"flap_{i}", "flap", S.box((w - 0.004, t, fl), center=c, R=R), card))
    for i, s in enumerate((-1, 1)):
        R = np.array([[np.cos(lean), 0, s * np.sin(lean)], [0, 1, 0], [-s * np.sin(lean), 0, np.cos(lean)]])
        c = np.array([s * (w / 2 - t / 2), 0, h]) + R @ np.array([0, 0, fw / 2])
        parts.append(make_part(f"flap_{i + 2}", "flap", S.box((t, d - 0.004, fw), center=c, R=R), card))
    return parts


@register("freezer_chest", parts=("body", "lid"), extra_parts=("handle", "hinge", "foot", "gasket", "basket", "control_panel",
                                                              "lock", "drain_plug", "grille", "light", "spacer", "screw"),
          size_range=(0.7, 1.8), density=300, variants=("small", "large", "glass_top"))
def freezer_chest(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w = {"small": rng.uniform(0.7, 0.95), "large": rng.uniform(1.2, 1.6), "glass_top": rng.uniform(1.4, 1.75)}[variant]
    d, h = rng.uniform(0.6, 0.75), rng.uniform(0.82, 0.9)
    enamel = white(rng)
    t = 0.05
    fh = 0.03
    lid_t = 0.06 if variant != "glass_top" else 0.03
    hb = h - lid_t - fh
    body = [S.box((w - 0.02, d - 0.02, t), center=(0, 0, fh + t / 2))] + _walls(w, d, hb, t, z0=fh)
    parts: list[Part | Joint] = [make_part("body", "body", body, enamel)]
    parts += feet4("foot", w=w, d=d, r=0.025, h=fh, mat=black(), inset=0.03)
    parts.append(make_part("gasket", "gasket", _walls(w - 0.02, d - 0.02, 0.006, 0.02, z0=fh + hb - 0.003), black()))
    # the four screws holding the cabinet's back sheet at its corners
    parts += back_screws("screw", x0=-w / 2, x1=w / 2, z0=fh, z1=fh + hb, y=-d / 2, inset=0.04)
    zt = fh + hb + 0.003
    if variant == "glass_top":
        lid = [S.box((w / 2 - 0.01, d - 0.02, lid_t), center=(-w / 4, 0, zt + lid_t / 2))]
        parts.append(make_part("lid", "lid", lid, M.glass(rng)))
        parts.append(make_part("lid_1", "lid", S.box((w / 2 - 0.01, d - 0.02, lid_t), center=(w / 4, 0.0, zt + lid_t / 2)),
                               M.glass(rng)))
        parts.append(make_part("handle", "handle", S.box((0.03, 0.2, 0.015), center=(-0.05, 0, zt + lid_t + 0.007)), black()))
        parts.append(Joint("lid_slide", "prismatic", "body", "lid", (1.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, w * 0.45)))
        parts.append(mount("lid", "handle"))
        # wire baskets hanging inside
        for k in range(2):
            parts.append(make_part(f"basket_{k}", "basket", [s.moved(((k - 0.5) * 0.45, 0, 0)) for s in
                                                             _walls(0.35, d - 2 * t - 0.04, 0.15, 0.004, z0=zt - 0.2)],
                                   M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.8)))
        return parts
    parts.append(make_part("lid", "lid", S.box((w, d, lid_t), center=(0, 0, zt + lid_t / 2), bevel=0.01), enamel))
    parts.append(make_part("handle", "handle", bar_pull((0, d / 2, zt + lid_t * 0.4), min(0.3, w * 0.4), vertical=False, reach=0.02),
                           M.solid((0.5, 0.5, 0.52), "plastic")))
    parts += hinge_parts("hinge", x=zt, y=-d / 2 - 0.006, z0=-w / 2, z1=w / 2, mat=M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8),
                         radius=0.008, length=0.08, axis="x")
    parts.append(make_part("control_panel", "control_panel", S.box((0.12, 0.006, 0.05), center=(w / 2 - 0.12, d / 2 + 0.003, fh + hb - 0.06)),
                           black()))
    parts.append(revolute("lid_hinge", "body", "lid", axis=(1, 0, 0), origin=(0, -d / 2, zt), opens=OPEN_DOOR * 0.6))
    parts.append(mount("lid", "handle"))
    # the key lock beside the handle, the power and cooling lights on the control panel, the
    # condenser grille low on the right side and the drain plug low on the front
    parts.append(make_part("lock", "lock", S.cylinder(0.009, 0.01, center=(min(0.3, w * 0.4) / 2 + 0.06, d / 2 + 0.005, zt + lid_t * 0.4),
                                                      axis=(0, 1, 0), sections=10), M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8)))
    parts.append(mount("lid", "lock"))
    parts += [make_part(f"light_{k}", "light", S.cylinder(0.004, 0.003, center=(w / 2 - 0.15 + 0.03 * k, d / 2 + 0.0075, fh + hb - 0.06),
                                                          axis=(0, 1, 0), sections=8),
                        M.solid((0.1, 0.8, 0.2) if k == 0 else (0.9, 0.6, 0.1), "plastic", 0.2)) for k in range(2)]
    parts.append(make_part("grille", "grille", S.box((0.004, d * 0.4, 0.12), center=(w / 2 + 0.002, -d * 0.1, fh + 0.1)), black()))
    parts.append(make_part("drain_plug", "drain_plug", S.cylinder(0.012, 0.008, center=(-w / 2 + 0.1, d / 2 + 0.004, fh + 0.04),
                                                                  axis=(0, 1, 0), sections=10), black()))
    # the two plastic spacers on the back that keep the condenser off the wall
    parts += [make_part(f"spacer_{k}", "spacer", S.box((0.04, 0.006, 0.04), center=(sx * (w / 2 - 0.1), -d / 2 - 0.003 + 0.0, fh + hb * 0.75)),
                        black()) for k, sx in enumerate((-1, 1))]
    return parts


@register("bread", parts=("loaf",), extra_parts=("bag", "score", "crust", "heel", "label", "twist_tie"), size_range=(0.12, 0.65), density=250,
          variants=("sandwich_loaf", "baguette", "round"), placement="surface")
def bread(rng: np.random.Generator, variant: str) -> list[Part]:
    crust = M.food(rng, (0.72, 0.48, 0.22))
    if variant == "sandwich_loaf":
        L, W, H = rng.uniform(0.22, 0.3), rng.uniform(0.1, 0.12), rng.uniform(0.1, 0.13)
        return [make_part("loaf", "loaf", S.union([S.box((L, W, H * 0.7), center=(0, 0, H * 0.35), bevel=0.01),
                                                   S.ellipsoid((L / 2, W / 2, H * 0.3), center=(0, 0, H * 0.7))]), crust),
                make_part("bag", "bag", S.box((L + 0.04, W + 0.01, H + 0.01), center=(0.02, 0, (H + 0.01) / 2), bevel=0.01),
                          M.solid((0.9, 0.92, 0.95), "plastic", 0.3)),
                make_part("clip", "bag", S.box((0.01, 0.03, 0.025), center=(L / 2 + 0.045, 0, H / 2)), M.plastic(rng)),
                # the bakery's paper label on the bag's side, the twisted neck of the bag the clip
                # closes, and the two crusty heels at the loaf's ends inside it
                make_part("label", "label", S.box((L * 0.4, 0.0006, H * 0.4), center=(-L * 0.1, -(W + 0.01) / 2 - 0.0003, H * 0.5)),
                          M.solid((0.95, 0.92, 0.8), "paper", 0.8)),
                make_part("twist_tie", "twist_tie", S.cylinder(0.006, 0.02, center=(L / 2 + 0.03, 0, H / 2), axis=(1, 0, 0), sections=8),
                          M.solid((0.9, 0.92, 0.95), "plastic", 0.3)),
                *[make_part(f"heel_{k}", "heel", S.box((0.004, W * 0.9, H * 0.6), center=(sx * (L / 2 + 0.002), 0, H * 0.35)), crust)
                  for k, sx in enumerate((-1, 1))]]
    if variant == "baguette":
        L, r = rng.uniform(0.5, 0.62), rng.uniform(0.028, 0.035)
        # the loaf between its two pointed heels (the crusty ends people break off first)
        parts = [make_part("loaf", "loaf", S.cylinder(r, L - 2 * r, center=(0, 0, r), axis=(1, 0, 0), sections=16), crust),
                 *[make_part(f"heel_{k}", "heel", S.ellipsoid((r, r, r), center=(sx * (L / 2 - r), 0, r)), crust)
                   for k, sx in enumerate((-1, 1))]]
        for k in range(int(rng.integers(3, 6))):
            x = -L * 0.35 + k * L * 0.7 / 5
            parts.append(make_part(f"score_{k}", "score", S.box((0.06, 0.012, 0.004), center=(x, 0, 2 * r - 0.001), R=_rz(0.3)),
                                   M.food(rng, (0.85, 0.7, 0.45))))
        return parts
    R_ = rng.uniform(0.08, 0.12)
    parts = [make_part("loaf", "loaf", S.ellipsoid((R_, R_, R_ * 0.6), center=(0, 0, R_ * 0.6)), crust)]
    # a boule's cross-hatch: two cuts each way, opened up in the oven
    k = 0
    for a in (0.0, np.pi / 2):
        for off in (-0.25, 0.25):
            c = _rz(a) @ np.array([0.0, off * R_, 0.0])
            dz = R_ * 0.6 * (1 - np.sqrt(max(0.0, 1 - (off ** 2))))
            parts.append(make_part(f"score_{k}", "score", S.box((R_ * 1.0, 0.01, 0.005), center=(c[0], c[1], R_ * 1.2 - 0.001 - dz),
                                                               R=_rz(a)), M.food(rng, (0.85, 0.7, 0.45))))
            k += 1
    return parts


@register("banana_bunch", parts=("finger",), extra_parts=("stem", "tip", "crown", "neck", "sticker"), size_range=(0.14, 0.26), density=950,
          variants=("bunch", "single"), placement="surface")
def banana_bunch(rng: np.random.Generator, variant: str) -> list[Part]:
    skin = M.food(rng, (0.95, 0.82, 0.2))
    n = 1 if variant == "single" else int(rng.integers(4, 8))
    L, r = rng.uniform(0.16, 0.22), rng.uniform(0.016, 0.019)
    parts = []
    tips, necks = [], []
    for k in range(n):
        a = (k - (n - 1) / 2) * 0.28
        t = np.linspace(0, 1, 7)
        arc = np.c_[L * 0.9 * t, 0.0 * t, L * 0.35 * (t - 0.5) ** 2 - L * 0.35 * 0.25 + r + 0.002]
        R = _rz(a)
        path = (R @ arc.T).T + [0, 0, 0.0]
        path[:, 2] += k * 0.002
        parts.append(make_part(f"finger_{k}", "finger", S.tube(path, r, sections=10), skin))
        tips.append(path[-1] + (path[-1] - path[-2]) / np.linalg.norm(path[-1] - path[-2]) * 0.004)
        necks.append((path[0], path[1]))
    stalk = M.food(rng, (0.4, 0.3, 0.15))
    parts.append(make_part("stem", "stem", S.cylinder(0.01, 0.03, center=(-0.012, 0, 0.035), axis=(1, 0, 0), sections=8),
                           stalk))
    # each finger's dark blossom end, and the crown where the fingers join the stem
    dark = M.solid((0.2, 0.15, 0.08), "plastic", 0.8)
    parts += studs("tip", "tip", tips, r=r * 0.35, h=0.008, mat=dark, axis=(1, 0, 0), sections=8)
    parts.append(make_part("crown", "crown", S.ellipsoid((0.012, 0.016 + 0.004 * (n - 1), 0.014), center=(0.004, 0, 0.035)), stalk))
    # each finger's green neck (the short stalk between it and the crown), and the grower's
    # paper sticker on the middle finger
    for k, (a, b) in enumerate(necks):
        u = (b - a) / np.linalg.norm(b - a)
        parts.append(make_part(f"neck_{k}", "neck", S.cylinder(r * 0.55, 0.02, center=tuple(a + u * 0.012), axis=tuple(u),
                                                               sections=8), M.food(rng, (0.55, 0.6, 0.25))))
    mid = parts[n // 2].mesh.vertices
    top = mid[np.argmax(mid[:, 2])]
    parts.append(make_part("sticker", "sticker", S.cylinder(0.009, 0.0006, center=(top[0], top[1], top[2] + 0.0003), sections=10),
                           M.solid((0.2, 0.35, 0.75), "paper", 0.6)))
    return parts


@register("citrus_fruit", parts=("body",), extra_parts=("stem", "leaf", "calyx", "blossom_end", "sticker"), size_range=(0.05, 0.13), density=950,
          variants=("orange", "lemon", "lime", "grapefruit"), placement="surface")
def citrus_fruit(rng: np.random.Generator, variant: str) -> list[Part]:
    col, r, ex = {"orange": ((0.95, 0.55, 0.1), rng.uniform(0.035, 0.045), 1.0),
                  "lemon": ((0.95, 0.88, 0.25), rng.uniform(0.028, 0.033), 1.3),
                  "lime": ((0.45, 0.7, 0.2), rng.uniform(0.025, 0.03), 1.1),
                  "grapefruit": ((0.95, 0.65, 0.35), rng.uniform(0.05, 0.062), 0.95)}[variant]
    parts = [make_part("body", "body", S.ellipsoid((r * ex, r, r * 0.95), center=(0, 0, r * 0.95)), M.food(rng, col))]
    parts.append(make_part("stem", "stem", S.cylinder(0.004, 0.006, center=(0, 0, r * 1.9 + 0.002), sections=8),
                           M.food(rng, (0.35, 0.4, 0.15))))
    if rng.random() < 0.5:
        parts.append(make_part("leaf", "leaf", S.box((0.04, 0.018, 0.002), center=(0.02, 0, r * 1.9 + 0.004), R=_rz(0.5)),
                               M.plant(rng)))
    # the green star of sepals round the stem and the small nub of the blossom end underneath,
    # pointed on a lemon
    parts.append(make_part("calyx", "calyx", S.cylinder(0.008, 0.002, center=(0, 0, r * 1.9 - 0.0005), sections=5),
                           M.food(rng, (0.35, 0.45, 0.15))))
    nub = 0.006 if variant == "lemon" else 0.003
    parts.append(make_part("blossom_end", "blossom_end", S.frustum(0.005, 0.002, nub, center=(r * ex - 0.0015, 0, r * 0.95),
                                                                 axis=(1, 0, 0), sections=8), parts[0].material))
    # the grower's oval paper sticker on the shoulder, facing the front
    parts.append(make_part("sticker", "sticker", S.cylinder(0.009, 0.0006, center=(0, -r * 0.999 + 0.0003 - 0.0006, r * 0.95),
                                                            axis=(0, 1, 0), sections=10), M.solid((0.95, 0.95, 0.9), "paper", 0.6)))
    return parts
