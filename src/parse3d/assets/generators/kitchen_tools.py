"""Kitchen tools: knife blocks, cutting boards, stand mixers, vacuum flasks and pot rails.

A knife block's knives stand in its slots (their ``handle``s are parts of the block, as one
sees it on a counter). A cutting board's ``board`` top is the support for what is cut on it.
A stand mixer's ``head`` tilts back on a hinge at the top of its ``column`` (the beater goes
with it) and its ``bowl`` is an internal surface. A pot rail is fixed to the wall (its back at
-Y) and its S-``hook``s are where pots and utensils hang (``HANGING_BELOW pot_rail:hook``).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._casework import black
from ._dD_detail import rivets_through
from ._household import ring, shell
from ._kit import feet4, mount, revolute


@register("knife_block", parts=("block", "handle"), extra_parts=("slot", "foot", "bolster", "rivet"),
          size_range=(0.2, 0.42), density=700, variants=("slanted", "upright", "round"),
          placement="surface")
def knife_block(rng: np.random.Generator, variant: str) -> list[Part]:
    """A wooden block whose slots open on its top face, one knife handle standing in each."""
    wood = M.wood(rng)
    n = int(rng.integers(4, 7))
    w = rng.uniform(0.1, 0.14)
    d = rng.uniform(0.14, 0.2) if variant != "round" else w
    h = rng.uniform(0.2, 0.25)
    top_d = d * (0.45 if variant == "slanted" else 1.0)
    if variant == "round":
        block = S.cylinder(w / 2, h, center=(0, 0, h / 2), sections=24)
        slots_xy = [(w * 0.28 * np.cos(2 * np.pi * k / n), w * 0.28 * np.sin(2 * np.pi * k / n))
                    for k in range(n)]
    else:
        bot = [(x, y, 0.0) for x in (-w / 2, w / 2) for y in (-d / 2, d / 2)]
        top = [(x, y, h) for x in (-w / 2, w / 2) for y in (-d / 2, -d / 2 + top_d)]
        block = S.hull(np.array(bot + top))
        cols = 2 if n > 4 else 1
        rows = int(np.ceil(n / cols))
        slots_xy = []
        for k in range(n):
            c, r = k % cols, k // cols
            x = (c - (cols - 1) / 2) * w * 0.4
            y = -d / 2 + top_d * (r + 0.5) / rows
            slots_xy.append((x, y))
    parts = [make_part("block", "block", block, wood)]
    dark = black()
    handle_mat = M.wood(rng) if rng.random() < 0.5 else black()
    steel = Material(M.jitter(rng, (0.78, 0.79, 0.8), 0.015), 0.25, 0.95, "metal")
    for k, (x, y) in enumerate(slots_xy):
        parts.append(make_part(f"slot_{k}", "slot", S.box((0.022, 0.005, 0.002),
                                                          center=(x, y, h + 0.0005)), dark))
        bl = 0.01
        parts.append(make_part(f"bolster_{k}", "bolster",
                               S.box((0.018, 0.008, bl), center=(x, y, h + bl / 2)), steel))
        hl = rng.uniform(0.09, 0.12)
        handle = S.box((0.02, 0.013, hl), center=(x, y, h + bl + hl / 2), bevel=0.003)
        parts.append(make_part(f"handle_{k}", "handle", handle, handle_mat))
        # the two rivets through the handle's scales and the tang between them, their heads
        # flush with both faces
        zr = [h + bl + hl * f for f in (0.3, 0.72)]
        parts += rivets_through(f"rivet_{k}", [(x, y, z) for z in zr], length=0.013, radius=0.002,
                                start=0)
    if variant != "round":
        parts += feet4("foot", w=w, d=d, r=0.008, h=0.004, mat=dark, inset=0.005)
        for p in parts[-4:]:
            p.mesh.apply_translation((0, 0, -0.004))
            for q in p.pieces:
                q.apply_translation((0, 0, -0.004))
    return parts


@register("cutting_board", parts=("board",), extra_parts=("handle", "groove", "foot", "hang_hole", "strap"),
          size_range=(0.2, 0.55), density=700, variants=("rectangular", "paddle", "round"),
          placement="surface")
def cutting_board(rng: np.random.Generator, variant: str) -> list[Part]:
    """A board lying flat; its top is where food is cut. A paddle's handle points to +X."""
    wood = M.wood(rng) if rng.random() < 0.75 else Material(M.jitter(rng, (0.92, 0.92, 0.9), 0.02),
                                                            0.5, 0.0, "plastic")
    t = rng.uniform(0.015, 0.03)
    feet = variant == "rectangular" and rng.random() < 0.5
    z0 = 0.006 if feet else 0.0
    if variant == "round":
        r = rng.uniform(0.13, 0.18)
        board = S.cylinder(r, t, center=(0, 0, z0 + t / 2), sections=32)
        w = d = 2 * r
    else:
        w = rng.uniform(0.3, 0.45) if variant == "rectangular" else rng.uniform(0.26, 0.34)
        d = rng.uniform(0.2, 0.3) if variant == "rectangular" else rng.uniform(0.18, 0.22)
        board = S.box((w, d, t), center=(0, 0, z0 + t / 2), bevel=min(0.006, t / 3))
    parts = [make_part("board", "board", board, wood)]
    if variant == "paddle":
        hl = rng.uniform(0.08, 0.11)
        handle = S.box((hl + 0.01, d * 0.3, t), center=(w / 2 + hl / 2 - 0.005, 0, t / 2), bevel=0.004)
        parts.append(make_part("handle", "handle", handle, wood))
    if variant == "rectangular":
        # the juice groove: four strips just inside the edge, sunk into the top
        g, m = 0.006, 0.022
        z = z0 + t - 0.0015
        strips = [((w - 2 * m, g), (0, d / 2 - m)), ((w - 2 * m, g), (0, -d / 2 + m)),
                  ((g, d - 2 * m), (w / 2 - m, 0)), ((g, d - 2 * m), (-w / 2 + m, 0))]
        for k, ((sx, sy), (cx, cy)) in enumerate(strips):
            parts.append(make_part(f"groove_{k}", "groove",
                                   S.box((sx, sy, 0.002), center=(cx, cy, z)), wood))
    elif variant == "round":
        r = w / 2 - 0.02
        parts.append(make_part("groove", "groove",
                               ring([(r - 0.006, z0 + t - 0.0025), (r, z0 + t - 0.0025),
                                     (r, z0 + t - 0.0005), (r - 0.006, z0 + t - 0.0005)],
                                    sections=32), wood))
    if feet:
        parts += feet4("foot", w=w, d=d, r=0.012, h=z0 + 0.001, mat=black(), inset=0.02)
    if variant != "rectangular":
        # a hole near the end (in the paddle's handle) with a leather strap looped through it
        hx = (w / 2 + _beyond_board(parts) * 0.6) if variant == "paddle" else (w / 2 - 0.012)
        rh = 0.008 if variant == "paddle" else 0.005
        parts.append(make_part("hang_hole", "hang_hole", S.cylinder(rh, t + 0.0004, center=(hx, 0, z0 + t / 2), sections=12),
                               M.solid((0.05, 0.05, 0.05), "wood", 0.9)))
        parts.append(make_part("strap", "strap", S.tube([(hx - rh * 0.5, -rh * 0.75, z0 + t + 0.002), (hx + 0.03, 0, z0 + t + 0.002),
                                                         (hx - rh * 0.5, rh * 0.75, z0 + t + 0.002)], 0.003, sections=6),
                               M.solid((0.45, 0.28, 0.15), "leather", 0.6)))
    return parts


def _beyond_board(parts: list[Part]) -> float:
    """The length of a paddle's handle beyond its board, read from the handle part."""
    h = next(p for p in parts if p.label == "handle")
    b = next(p for p in parts if p.label == "board")
    return float(h.bounds[1, 0] - b.bounds[1, 0])


@register("stand_mixer", parts=("base", "column", "head", "bowl"),
          extra_parts=("beater", "bowl_plate", "bowl_arm", "speed_lever", "hinge", "hub", "foot", "lock_lever", "hub_knob"),
          size_range=(0.3, 0.46), density=900, variants=("tilt_head", "bowl_lift"),
          placement="surface")
def stand_mixer(rng: np.random.Generator, variant: str) -> list[Part]:
    """A tilt-head mixer: base plinth, a column at the back, the motor head over the bowl
    (front +Y), the beater hanging from the head into the bowl."""
    enamel = Material(M.jitter(rng, [(0.75, 0.1, 0.12), (0.92, 0.92, 0.9), (0.15, 0.15, 0.17),
                                     (0.55, 0.7, 0.8)][int(rng.integers(4))], 0.03), 0.25, 0.3, "metal")
    steel = Material(M.jitter(rng, (0.8, 0.8, 0.82), 0.01), 0.2, 0.95, "metal")
    bw, bd, bh = rng.uniform(0.2, 0.24), rng.uniform(0.3, 0.34), rng.uniform(0.045, 0.06)
    parts = [make_part("base", "base", S.box((bw, bd, bh), center=(0, 0, bh / 2), bevel=0.02), enamel)]
    parts += feet4("foot", w=bw * 0.9, d=bd * 0.9, r=0.01, h=0.004, mat=black(), inset=0.01)
    for p in parts[-4:]:
        p.mesh.apply_translation((0, 0, -0.004))
        for q in p.pieces:
            q.apply_translation((0, 0, -0.004))
    cw, cd = bw * 0.55, rng.uniform(0.09, 0.11)
    ch = rng.uniform(0.2, 0.24)
    yc = -bd / 2 + cd / 2 + 0.01
    column = S.hull(np.array([(x, y, z) for x in (-cw / 2, cw / 2)
                              for y, z in ((yc - cd / 2, bh - 0.005), (yc + cd / 2, bh - 0.005),
                                           (yc - cd / 2 + 0.005, bh + ch), (yc + cd * 0.3, bh + ch))]))
    parts.append(make_part("column", "column", column, enamel))
    # bowl on its clamp plate in front of the column
    yb = yc + cd / 2 + rng.uniform(0.1, 0.115)
    rb = min(rng.uniform(0.1, 0.115), yb - yc - cd / 2 - 0.005)
    hb = rng.uniform(0.13, 0.15)
    zp = bh
    plate = S.cylinder(rb * 0.6, 0.01, center=(yb * 0, 0, zp + 0.005), sections=24)
    plate = plate.apply(np.array([[1, 0, 0, 0], [0, 1, 0, yb], [0, 0, 1, 0], [0, 0, 0, 1.0]]))
    parts.append(make_part("bowl_plate", "bowl_plate", plate, steel))
    bowl = shell([(rb * 0.55, 0.0), (rb * 0.85, hb * 0.25), (rb, hb * 0.75), (rb, hb)], 0.0025,
                 sections=28)
    bowl = bowl.apply(np.array([[1, 0, 0, 0], [0, 1, 0, yb], [0, 0, 1, zp + 0.01], [0, 0, 0, 1.0]]))
    parts.append(make_part("bowl", "bowl", bowl, steel))
    # the motor head: from over the column forward over the bowl
    zh0 = max(bh + ch - 0.02, zp + 0.01 + hb + 0.03)
    hh = rng.uniform(0.1, 0.12)
    y0, y1 = yc - cd / 2, yb + rb * 0.55
    head = S.hull(np.vstack([
        [(x, y, z) for x in (-cw * 0.55, cw * 0.55) for y in (y0, y1) for z in (zh0 + 0.01, zh0 + hh - 0.02)],
        [(x, y, z) for x in (-cw * 0.45, cw * 0.45) for y in (y0 + 0.01, y1 + 0.025) for z in (zh0, zh0 + hh)],
    ]))
    parts.append(make_part("head", "head", head, enamel))
    hub = S.cylinder(0.03, 0.025, center=(0, y1 + 0.025, zh0 + hh * 0.5), axis=(0, 1, 0), sections=16)
    parts.append(make_part("hub", "hub", hub, steel))
    # the flat beater hangs from under the head into the bowl
    zb0 = zp + 0.01 + 0.045  # the paddle clears the bowl's floor (a support inside the bowl)
    shaft = S.cylinder(0.008, zh0 - zb0 - 0.05 + 0.002, center=(0, yb, (zh0 + 0.001 + zb0 + 0.05) / 2),
                       sections=10)
    paddle = S.hull(np.array([(x, yb + dy, z) for dy in (-0.004, 0.004)
                              for x, z in ((-rb * 0.55, zb0 + 0.05), (rb * 0.55, zb0 + 0.05),
                                           (-rb * 0.3, zb0), (rb * 0.3, zb0))]))
    parts.append(make_part("beater", "beater", [shaft, paddle], steel))
    lever = S.box((0.012, 0.035, 0.01), center=(cw * 0.55 + 0.004, yc, zh0 + hh * 0.3), bevel=0.002)
    parts.append(make_part("speed_lever", "speed_lever", lever, steel))
    pivot = (0.0, yc - cd * 0.1, zh0)
    parts.append(make_part("hinge", "hinge", S.cylinder(0.008, cw * 1.02, center=pivot, axis=(1, 0, 0),
                                                        sections=12), steel))
    # on the column's left side the lever that locks the head down (a bowl-lift's lever that
    # raises the bowl), and on top of the attachment hub the knob that clamps an attachment in
    zl = bh + ch * 0.55
    lock = S.box((0.01, 0.04, 0.012), center=(-cw / 2 - 0.004, yc, zl), bevel=0.002)
    parts.append(make_part("lock_lever", "lock_lever", lock, steel))
    parts.append(make_part("hub_knob", "hub_knob", S.cylinder(0.009, 0.012, center=(0, y1 + 0.03, zh0 + hh * 0.5 + 0.03 + 0.005),
                                                              sections=10), steel))
    if variant == "tilt_head":
        parts += [revolute("head_tilt", "column", "head", axis=(1, 0, 0), origin=pivot, opens=1.0),
                  mount("head", "hub"), mount("head", "beater"), mount("head", "speed_lever"), mount("head", "hub_knob")]
    else:
        # bowl-lift models raise the bowl on arms instead; the head is fixed
        arm = S.box((cw * 1.1, 0.03, 0.02), center=(0, yb - rb + 0.005, zp + 0.01 + hb * 0.5), bevel=0.004)
        parts.append(make_part("bowl_arm", "bowl_arm", arm, enamel))
    return parts


@register("thermos", parts=("body", "cup"), extra_parts=("stopper", "band", "handle", "foot", "seal", "label"),
          size_range=(0.18, 0.42), density=600, variants=("classic", "slim", "handled"),
          placement="surface")
def thermos(rng: np.random.Generator, variant: str) -> list[Part]:
    """A vacuum flask: the body, its screw-on cup over the stopper, a grip band and a base."""
    body_mat = M.metal(rng) if rng.random() < 0.6 else M.plastic(rng)
    r = rng.uniform(0.03, 0.036) if variant == "slim" else rng.uniform(0.04, 0.05)
    h = rng.uniform(0.2, 0.26) if variant == "slim" else rng.uniform(0.24, 0.3)
    zf = 0.012
    foot = S.lathe([(r * 0.92, 0.0), (r * 1.01, 0.004), (r * 1.01, zf)], sections=24)
    parts = [make_part("foot", "foot", foot, black())]
    neck = r * 0.62
    prof = [(r, zf), (r, zf + h * 0.8), (neck, zf + h * 0.9), (neck, zf + h)]
    parts.append(make_part("body", "body", S.lathe(prof, sections=24), body_mat))
    zt = zf + h
    stopper = S.cylinder(neck * 0.8, 0.02, center=(0, 0, zt + 0.01 - 0.001), sections=16)
    parts.append(make_part("stopper", "stopper", stopper, black()))
    ch = rng.uniform(0.07, 0.09)
    cup = S.lathe([(r * 1.02, zt - ch * 0.55), (r * 1.05, zt + ch * 0.45 - 0.004),
                   (r * 0.98, zt + ch * 0.45)], sections=24)
    parts.append(make_part("cup", "cup", cup, body_mat if variant != "classic" else M.plastic(rng)))
    band = ring([(r - 0.001, zf + h * 0.35), (r + 0.003, zf + h * 0.35), (r + 0.003, zf + h * 0.5),
                 (r - 0.001, zf + h * 0.5)], sections=24)
    parts.append(make_part("band", "band", band, black("rubber")))
    if variant == "handled":
        path = [(0, -r + 0.002, zf + h * 0.7), (0, -r - 0.03, zf + h * 0.66),
                (0, -r - 0.03, zf + h * 0.3), (0, -r + 0.002, zf + h * 0.25)]
        parts.append(make_part("handle", "handle", S.tube(path, 0.007, sections=8), black()))
    # the silicone seal ring showing under the cup's rim and the printed label on the body
    # (triangular and sloped sections: no flat annulus, the costliest surface to resolve)
    zs = zt - ch * 0.55
    parts.append(make_part("seal", "seal", ring([(r * 0.99, zs - 0.004), (r * 1.025, zs - 0.002), (r * 0.99, zs)], sections=24),
                           black("rubber")))
    parts.append(make_part("label", "label", ring([(r - 0.0005, zf + h * 0.55), (r + 0.0008, zf + h * 0.55 + 0.002),
                                                   (r + 0.0008, zf + h * 0.68 - 0.002), (r - 0.0005, zf + h * 0.68)], sections=24),
                           M.solid((0.95, 0.95, 0.92), "paper", 0.6)))
    return parts


@register("pot_rail", parts=("rail", "hook"), extra_parts=("bracket", "end_cap", "screw"),
          size_range=(0.4, 1.25), density=3000, variants=("round_bar", "flat_bar", "double"),
          placement="wall", groups={"bar": ("rail", "hook")})
def pot_rail(rng: np.random.Generator, variant: str) -> list[Part]:
    """A wall rail: brackets against the wall (-Y), the bar in front, S-hooks hanging from it.
    Each hook's bottom curl is where a pot's handle hangs; ``bar`` names the rail with its hooks."""
    mat = M.metal(rng) if rng.random() < 0.7 else Material((0.1, 0.1, 0.1, 1.0), 0.5, 0.7, "metal")
    L = rng.uniform(0.45, 1.2)
    off = rng.uniform(0.05, 0.065)  # bar axis from the wall
    zr = 0.14  # bar height above the asset's bottom (room for the hooks)
    rr = 0.008 if variant != "flat_bar" else 0.0
    parts: list[Part] = []
    rails = [(0.0, zr)] if variant != "double" else [(0.0, zr), (0.0, zr - 0.0)]
    if variant == "double":
        rails = [(off - 0.012, zr), (off + 0.012, zr)]
    else:
        rails = [(off, zr)]
    for k, (y, z) in enumerate(rails):
        if variant == "flat_bar":
            bar = S.box((L, 0.006, 0.03), center=(0, y, z), bevel=0.001)
        else:
            bar = S.cylinder(rr, L, center=(0, y, z), axis=(1, 0, 0), sections=16)
        name = "rail" if len(rails) == 1 else f"rail_{k}"
        parts.append(make_part(name, "rail", bar, mat))
        if variant != "flat_bar":
            for j, sx in enumerate((-1, 1)):
                cap = S.cylinder(rr * 1.5, 0.012, center=(sx * (L / 2 + 0.006), y, z), axis=(1, 0, 0),
                                 sections=12)
                parts.append(make_part(f"end_cap_{k}_{j}", "end_cap", cap, mat))
    nb = 2 if L < 0.9 else 3
    ymax = max(y for y, _ in rails)
    for j in range(nb):
        x = -L / 2 + 0.05 + (L - 0.1) * j / (nb - 1)
        post = S.cylinder(0.006, ymax + 0.004, center=(x, (ymax + 0.004) / 2, zr), axis=(0, 1, 0),
                          sections=10)
        plate = S.cylinder(0.025, 0.008, center=(x, 0.004, zr), axis=(0, 1, 0), sections=16)
        parts.append(make_part(f"bracket_{j}", "bracket", [plate, post], mat))
        # the two screws fixing the bracket's round plate to the wall, above and below the post
        parts += [make_part(f"screw_{2 * j + i}", "screw", S.cylinder(0.0045, 0.002, center=(x, 0.009, zr + sz * 0.016), axis=(0, 1, 0),
                                                                      sections=8), mat)
                  for i, sz in enumerate((1, -1))]
    nh = max(3, int(L / 0.12))
    y, z = rails[-1]
    top_r = (0.015 if variant == "flat_bar" else rr) + 0.004
    for k in range(nh):
        x = -L / 2 + 0.08 + (L - 0.16) * (k + 0.5) / nh
        # an S-hook: a curl over the bar, a shank, a curl open to the front at the bottom
        a = np.linspace(np.pi * 0.15, np.pi * 1.05, 4)
        upper = np.c_[np.full(4, x), y - top_r * np.cos(a), z + top_r * np.sin(a)]
        zb = z - 0.075  # a 7-8 cm S-hook
        b = np.linspace(np.pi, np.pi * 1.9, 4)
        lower = np.c_[np.full(4, x), y + 0.014 + 0.014 * np.cos(b), zb + 0.014 * np.sin(b) + 0.014]
        path = np.vstack([upper[::-1], [(x, y + top_r, z - 0.03)], lower])
        parts.append(make_part(f"hook_{k}", "hook", S.tube(path, 0.0025, sections=6), mat))
    return parts
