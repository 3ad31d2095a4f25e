"""Dining and shop furniture and what dresses it: sideboards, display tables, table runners and
bouquets of flowers.

A sideboard's ``top_panel`` is where lamps and dishes stand, and the ``shelf`` boards behind its
doors are internal supports (``IN sideboard:shelf``); its drawers slide out as a dresser's do.
A display table's ``tabletop``, its ``riser`` and its lower ``shelf`` are supports for goods.
A table runner is a fabric strip laid along a table (its ``runner`` top holds what stands on
it). A bouquet stands on the ends of its ``stem``s, for ``IN vase``.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Material, Part, make_part
from ..registry import register
from ._casework import door_parts, drawer_parts
from ._dA_fixings import screws_under
from ._kit import rot


@register("sideboard", parts=("top_panel", "body", "shelf"),
          extra_parts=("door", "drawer", "drawer_box", "handle", "hinge", "leg", "shelf_pin"),
          size_range=(0.9, 2.2), density=550, variants=("drawers_over_doors", "three_door", "legged"),
          placement="floor",
          groups={"body": ("side_panel", "bottom_panel", "carcass_top", "back_panel", "partition", "drawer_rail", "plinth")})
def sideboard(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    """A low cabinet: bays with doors (a shelf behind each), a row of drawers under the top in
    ``drawers_over_doors`` and ``legged``; on a plinth or on four tapered legs."""
    w, d, h = rng.uniform(1.2, 2.0), rng.uniform(0.4, 0.5), rng.uniform(0.75, 0.9)
    t = 0.018
    mat = M.wood(rng)
    hmat = M.metal(rng)
    legged = variant == "legged"
    z0 = rng.uniform(0.16, 0.24) if legged else rng.uniform(0.06, 0.1)
    hb = h - t  # carcass top, under the top panel
    n = 3 if (variant == "three_door" or w > 1.5) else 2
    bay = (w - 2 * t) / n
    zd = hb - t - rng.uniform(0.13, 0.16) if variant != "three_door" else hb - t
    # the carcass panel by panel, all covered by ``body``: the plinth is named body (so body
    # stands on the floor), or on legs the bottom panel is
    parts: list[Part | Joint] = [
        make_part(f"side_panel_{k}", "side_panel", S.box((t, d, hb - z0), center=(sx * (w / 2 - t / 2), 0, (z0 + hb) / 2), bevel=0.002),
                  mat) for k, sx in enumerate((-1, 1))]
    parts += [make_part("body" if legged else "bottom_panel", "bottom_panel", S.box((w - 2 * t, d, t), center=(0, 0, z0 + t / 2)), mat),
              make_part("carcass_top", "carcass_top", S.box((w - 2 * t, d, t), center=(0, 0, hb - t / 2)), mat),
              make_part("back_panel", "back_panel", S.box((w - 2 * t, 0.008, hb - z0 - 2 * t), center=(0, -d / 2 + 0.004, (z0 + hb) / 2)),
                        mat)]
    for i in range(1, n):
        x = -w / 2 + t + i * bay
        parts.append(make_part(f"partition_{i - 1}", "partition",
                               S.box((t, d - 0.008, hb - z0 - 2 * t), center=(x, 0.004, (z0 + hb) / 2)), mat))
    if zd < hb - t - 1e-6:  # the rail the drawers run above
        parts.append(make_part("drawer_rail", "drawer_rail", S.box((w - 2 * t, d - 0.008, t), center=(0, 0.004, zd + t / 2)), mat))
    if not legged:
        parts.append(make_part("body", "plinth", S.box((w - 0.04, d - 0.04, z0), center=(0, -0.01, z0 / 2)), mat))
    parts.append(make_part("top_panel", "top_panel",
                           S.box((w + 0.02, d + 0.02, t), center=(0, 0.01, h - t / 2), bevel=0.004), mat))
    if legged:
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            x, y = sx * (w / 2 - 0.05), sy * (d / 2 - 0.05)
            parts.append(make_part(f"leg_{i}", "leg", S.frustum(0.014, 0.022, z0, center=(x, y, 0),
                                                                 sections=12), mat))
    for b in range(n):
        sx0 = -w / 2 + t + b * bay + (t / 2 if b > 0 else 0)
        sx1 = -w / 2 + t + (b + 1) * bay - (t / 2 if b < n - 1 else 0)
        if zd < hb - t - 1e-6:
            parts += drawer_parts(f"drawer_{b}", x0=sx0 + 0.002, x1=sx1 - 0.002, z0=zd + t + 0.003,
                                  z1=hb - t - 0.003, y_front=d / 2, depth=d - 0.06, thick=0.018,
                                  mat=mat, handle_mat=hmat, knob_style=legged)
        parts += door_parts(f"door_{b}", x0=sx0 + 0.002, x1=sx1 - 0.002, z0=z0 + t + 0.003,
                            z1=zd - 0.003, y_back=d / 2 - 0.018, thick=0.018, mat=mat,
                            handle_mat=hmat, hinge_left=b < n / 2, style="flat" if legged else "shaker",
                            handle_len=0.1)
        # a shelf half way up the bay behind the door
        zs = (z0 + t + zd) / 2
        parts.append(make_part(f"shelf_{b}", "shelf",
                               S.box((sx1 - sx0, d - 0.04, t), center=((sx0 + sx1) / 2, -0.012, zs)),
                               mat))
        # the four pins in the bay's drilled sides that carry the shelf
        for j, (ex, fy) in enumerate([(0, -1), (1, -1), (0, 1), (1, 1)]):
            x = sx0 + 0.006 if ex == 0 else sx1 - 0.006
            parts.append(make_part(f"shelf_pin_{4 * b + j}", "shelf_pin",
                                   S.cylinder(0.003, 0.012, center=(x, -0.012 + fy * (d - 0.04) * 0.35, zs - t / 2 - 0.003),
                                              axis=(1, 0, 0), sections=8), hmat))
    return parts


@register("display_table", parts=("tabletop", "leg"),
          extra_parts=("shelf", "riser", "apron", "foot", "collar", "top_plate", "glide", "corner_block", "screw"), size_range=(0.8, 2.0),
          density=500,
          variants=("two_tier", "riser", "round"), placement="floor")
def display_table(rng: np.random.Generator, variant: str) -> list[Part]:
    """A shop's merchandising table: a top at 0.7-0.8 m, a lower shelf (``two_tier``) or a
    riser box standing on the top (``riser``); ``round`` tables stand on a pedestal."""
    mat = M.wood(rng) if rng.random() < 0.7 else Material(M.jitter(rng, (0.92, 0.92, 0.9), 0.02),
                                                          0.5, 0.0, "wood")
    leg_mat = mat if rng.random() < 0.5 else Material((0.1, 0.1, 0.1, 1.0), 0.5, 0.7, "metal")
    h = rng.uniform(0.7, 0.8)
    t = 0.03
    parts: list[Part] = []
    if variant == "round":
        r = rng.uniform(0.45, 0.6)
        parts.append(make_part("tabletop", "tabletop", S.cylinder(r, t, center=(0, 0, h - t / 2),
                                                                  sections=40), mat))
        parts.append(make_part("leg", "leg", S.cylinder(0.05, h - t - 0.03, center=(0, 0, (h - t + 0.03) / 2),
                                                       sections=16), leg_mat))
        parts.append(make_part("foot", "foot", S.cylinder(r * 0.6, 0.03, center=(0, 0, 0.015), sections=32),
                               leg_mat))
        # the collars where the column meets the foot and the top
        for k, z in enumerate((0.03 + 0.02, h - t - 0.02)):
            parts.append(make_part(f"collar_{k}", "collar", S.cylinder(0.075, 0.04, center=(0, 0, z), sections=16), leg_mat))
        # a smaller top tier on a short column
        r2, h2 = r * 0.5, rng.uniform(0.25, 0.35)
        parts.append(make_part("riser_post", "leg", S.cylinder(0.03, h2, center=(0, 0, h + h2 / 2 - 0.001),
                                                               sections=12), leg_mat))
        parts.append(make_part("riser", "riser", S.cylinder(r2, 0.025, center=(0, 0, h + h2 + 0.0125 - 0.002),
                                                             sections=32), mat))
        # the cross plate under the top that fixes it to the column, and four glides let into
        # the foot's underside
        parts.append(make_part("top_plate", "top_plate", [S.box((r * 1.1, 0.06, 0.012), center=(0, 0, h - t - 0.006)),
                                                          S.box((0.06, r * 1.1, 0.012), center=(0, 0, h - t - 0.006))], leg_mat))
        rubber = Material((0.08, 0.08, 0.08, 1.0), 0.9, 0.0, "rubber")
        for k in range(4):
            a = np.pi / 4 + k * np.pi / 2
            parts.append(make_part(f"glide_{k}", "glide", S.cylinder(0.015, 0.004, center=(r * 0.5 * np.cos(a), r * 0.5 * np.sin(a), 0.002),
                                                                    sections=10), rubber))
        return parts
    w, d = rng.uniform(1.2, 1.8), rng.uniform(0.7, 0.95)
    parts.append(make_part("tabletop", "tabletop", S.box((w, d, t), center=(0, 0, h - t / 2), bevel=0.004),
                           mat))
    leg = 0.05
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        x, y = sx * (w / 2 - leg / 2 - 0.02), sy * (d / 2 - leg / 2 - 0.02)
        parts.append(make_part(f"leg_{i}", "leg", S.box((leg, leg, h - t), center=(x, y, (h - t) / 2),
                                                        bevel=0.003), leg_mat))
        # a glide cap round each leg's foot (the legs still reach the floor)
        parts.append(make_part(f"foot_{i}", "foot", S.box((leg + 0.006, leg + 0.006, 0.012), center=(x, y, 0.006), bevel=0.002),
                               Material((0.08, 0.08, 0.08, 1.0), 0.9, 0.0, "rubber")))
    ah = 0.08
    za = h - t - ah / 2
    for k, (size, c) in enumerate([((w - 2 * leg - 0.04, 0.02, ah), (0, d / 2 - 0.03, za)),
                                   ((w - 2 * leg - 0.04, 0.02, ah), (0, -d / 2 + 0.03, za)),
                                   ((0.02, d - 2 * leg - 0.04, ah), (w / 2 - 0.03, 0, za)),
                                   ((0.02, d - 2 * leg - 0.04, ah), (-w / 2 + 0.03, 0, za))]):
        parts.append(make_part(f"apron_{k}", "apron", S.box(size, center=c), mat))
    # the glued blocks in the apron's corners, inside each leg
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        x, y = sx * (w / 2 - leg - 0.02 - 0.025), sy * (d / 2 - leg - 0.02 - 0.025)
        parts.append(make_part(f"corner_block_{i}", "corner_block", S.box((0.05, 0.05, ah * 0.6), center=(x, y, h - t - ah * 0.3)), mat))
    parts += screws_under(parts, "corner_block")
    if variant == "two_tier":
        zs = rng.uniform(0.15, 0.25)
        parts.append(make_part("shelf", "shelf", S.box((w - 2 * leg - 0.04, d - 2 * leg - 0.04, 0.02),
                                                       center=(0, 0, zs)), mat))
    else:
        rw, rd, rh = w * rng.uniform(0.35, 0.5), d * rng.uniform(0.4, 0.55), rng.uniform(0.2, 0.32)
        parts.append(make_part("riser", "riser", S.box((rw, rd, rh), center=(0, -d * 0.1, h + rh / 2 - 0.001),
                                                       bevel=0.004), mat))
    return parts


@register("table_runner", parts=("runner",), extra_parts=("hem", "border", "tassel", "label", "binding", "tassel_cap"),
          size_range=(0.9, 2.8), density=300, variants=("plain", "bordered", "tasselled"),
          placement="surface", groups={"body": ("runner", "hem", "border")})
def table_runner(rng: np.random.Generator, variant: str) -> list[Part]:
    """A fabric strip along X; laid ON a table's top, it holds what stands on it."""
    cloth = M.fabric(rng)
    L, W = rng.uniform(1.2, 2.4), rng.uniform(0.3, 0.42)
    t = 0.003
    pointed = variant == "tasselled"
    if pointed:
        tip = W * 0.4
        outline = [(-L / 2 + tip, -W / 2), (L / 2 - tip, -W / 2), (L / 2, 0), (L / 2 - tip, W / 2),
                   (-L / 2 + tip, W / 2), (-L / 2, 0)]
        runner = S.prism(outline, 0.0, t)
    else:
        runner = S.box((L, W, t), center=(0, 0, t / 2))
    parts = [make_part("runner", "runner", runner, cloth)]
    if not pointed:  # a stitched hem across each end, and along each long side between them
        for k, sx in enumerate((-1, 1)):
            hem = S.box((0.03, W - 0.004, 0.0015), center=(sx * (L / 2 - 0.017), 0, t + 0.0006))
            parts.append(make_part(f"hem_{k}", "hem", hem, cloth))
        for k, sy in enumerate((-1, 1)):
            hem = S.box((L - 0.07, 0.012, 0.0015), center=(0, sy * (W / 2 - 0.008), t + 0.0006))
            parts.append(make_part(f"hem_{2 + k}", "hem", hem, cloth))
    # the maker's care label sewn on underneath, near one end
    parts.append(make_part("label", "label", S.box((0.03, 0.05, 0.0008), center=(-L / 2 + 0.2, 0, 0.0004)),
                           Material((0.92, 0.92, 0.9, 1.0), 0.8, 0.0, "fabric")))
    if variant == "bordered":
        edge = Material(M.jitter(rng, (0.85, 0.75, 0.45), 0.05), 0.6, 0.2, "fabric")
        b = 0.025
        for k, (size, c) in enumerate([((L - 0.04, b, 0.001), (0, W / 2 - 0.02 - b / 2, t + 0.0005)),
                                       ((L - 0.04, b, 0.001), (0, -W / 2 + 0.02 + b / 2, t + 0.0005)),
                                       ((b, W - 0.04 - 2 * b, 0.001), (L / 2 - 0.02 - b / 2, 0, t + 0.0005)),
                                       ((b, W - 0.04 - 2 * b, 0.001), (-L / 2 + 0.02 + b / 2, 0, t + 0.0005))]):
            parts.append(make_part(f"border_{k}", "border", S.box(size, center=c), edge))
    if pointed:
        for k, sx in enumerate((-1, 1)):
            tassel = S.frustum(0.004, 0.009, 0.05, center=(sx * L / 2, 0, 0.0045), axis=(sx, 0, 0),
                               sections=10)
            parts.append(make_part(f"tassel_{k}", "tassel", tassel, cloth))
            # the wrapped cap binding the tassel's threads where it hangs from the point
            parts.append(make_part(f"tassel_cap_{k}", "tassel_cap", S.cylinder(0.006, 0.01, center=(sx * (L / 2 + 0.005), 0, 0.0045),
                                                                               axis=(1, 0, 0), sections=10), cloth))
        # the bias binding round the six edges, lying along them on the top face
        edge = Material(M.jitter(rng, (0.3, 0.25, 0.2), 0.05), 0.7, 0.0, "fabric")
        pts = np.asarray(outline, float)
        for k in range(len(pts)):
            p0, p1 = pts[k], pts[(k + 1) % len(pts)]
            u = (p1 - p0) / np.linalg.norm(p1 - p0)
            inward = np.array([-u[1], u[0]])  # the outline runs anticlockwise
            c = (p0 + p1) / 2 + inward * 0.004
            a = float(np.arctan2(u[1], u[0]))
            R = np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])
            parts.append(make_part(f"binding_{k}", "binding", S.box((float(np.linalg.norm(p1 - p0)) - 0.004, 0.008, 0.001),
                                                                    center=(c[0], c[1], t), R=R), edge))
    return parts


@register("flowers", parts=("stem", "bloom"), extra_parts=("leaf", "wrap", "ribbon", "calyx"),
          size_range=(0.25, 0.7), density=400, variants=("roses", "tulips", "wrapped", "wildflowers"),
          placement="surface")
def flowers(rng: np.random.Generator, variant: str) -> list[Part]:
    """A bouquet standing on its cut stem ends: stems fanning out from a tied waist, a bloom on
    each; ``wrapped`` bouquets stand in a paper cone."""
    n = int(rng.integers(5, 9)) if variant != "wildflowers" else int(rng.integers(7, 11))
    H = rng.uniform(0.32, 0.55)
    green = M.plant(rng)
    hue = [(0.8, 0.1, 0.15), (0.95, 0.85, 0.9), (0.95, 0.75, 0.15), (0.85, 0.45, 0.65),
           (0.55, 0.3, 0.7)][int(rng.integers(5))]
    waist = H * 0.35
    parts: list[Part] = []
    for k in range(n):
        a = 2 * np.pi * k / n + rng.uniform(-0.3, 0.3)
        ring_r = 0.006 + 0.01 * (k % 3) / 2
        base = np.array([ring_r * np.cos(a) * 0.6, ring_r * np.sin(a) * 0.6, 0.0])
        spread = rng.uniform(0.04, 0.09) if variant != "tulips" else rng.uniform(0.03, 0.06)
        hk = H * rng.uniform(0.85, 1.0)
        top = np.array([spread * np.cos(a), spread * np.sin(a), hk])
        mid = np.array([ring_r * np.cos(a) * 0.5, ring_r * np.sin(a) * 0.5, waist])
        parts.append(make_part(f"stem_{k}", "stem", S.tube([base, mid, top], 0.0025, sections=6), green))
        col = Material(M.jitter(rng, hue if variant != "wildflowers" else
                                [(0.95, 0.85, 0.2), (0.6, 0.3, 0.8), (0.95, 0.95, 0.95),
                                 (0.9, 0.4, 0.2)][k % 4]), 0.7, 0.0, "plant")
        if variant == "tulips":
            bloom = S.lathe([(0.008, 0.0), (0.017, 0.012), (0.016, 0.035), (0.01, 0.045)], sections=12)
        elif variant == "wildflowers":
            rb = rng.uniform(0.012, 0.022)
            bloom = S.lathe([(0.003, 0.0), (rb, 0.004), (rb * 0.9, 0.008), (0.004, 0.01)], sections=12)
        else:
            rb = rng.uniform(0.02, 0.028)
            bloom = S.lathe([(0.006, 0.0), (rb, rb * 0.6), (rb * 0.95, rb * 1.3), (rb * 0.5, rb * 1.6)],
                            sections=12)
        bloom = bloom.moved(top - (0, 0, 0.002))
        parts.append(make_part(f"bloom_{k}", "bloom", bloom, col))
        if variant != "tulips":  # the green calyx cupping the bloom's base, where the sepals are
            parts.append(make_part(f"calyx_{k}", "calyx", S.frustum(0.003, 0.0065, 0.006, center=tuple(top - (0, 0, 0.006)), sections=8),
                                   green))
        if k % 2 == 0 or variant == "roses":
            leaf = S.ellipsoid((0.03, 0.008, 0.0015), center=(0.03, 0, 0), subdivisions=1)
            p = mid + (top - mid) * 0.3
            leaf = leaf.apply(np.vstack([np.c_[rot((0, 0, 1), a) @ rot((0, 1, 0), -0.5), p],
                                         [0, 0, 0, 1]]))
            parts.append(make_part(f"leaf_{k}", "leaf", leaf, green))
    if variant == "wrapped":
        paper = M.paper(rng)
        wrap = S.frustum(0.03, 0.11, H * 0.6, center=(0, 0, 0.0), sections=16)
        parts.append(make_part("wrap", "wrap", wrap, paper, watertight=True))
    ribbon = S.cylinder(0.014, 0.02, center=(0, 0, waist), sections=14)
    ribbon_mat = Material(M.jitter(rng, (0.8, 0.2, 0.3), 0.1), 0.5, 0.0, "fabric")
    parts.append(make_part("ribbon", "ribbon", ribbon, ribbon_mat))
    return parts
