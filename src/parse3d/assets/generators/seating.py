"""Seating: office chairs, dining chairs, armchairs, sofas and bar stools.

Everything faces +Y: the ``back`` (or the back cushions) sits at -Y, the sitter's right is +X,
``armrest_0`` is the left arm (-X) and ``armrest_1`` the right arm (+X). Seats and cushions are
rounded, with real thickness; backs lean back a few degrees. The structure people point at is
modelled too: an office chair's seat ``shell``, height ``lever`` and tilt ``knob``; a dining
chair's ``apron`` rails and ``corner_block`` s under the seat; the tufting ``button`` s of
upholstered backs; a sofa's arm ``panel`` s and the ``piping`` of its seat cushions; a bar
stool's seat ``plate`` and footrest ``bracket`` s.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from ...geometry.frames import make_transform, rot_x, rot_z
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._bedbath_common import bevel_box, cushion
from ._household import ring as ring_
from ._rods import leg_caps

_UP = np.array([0.0, 0.0, 1.0])


def _leaning(shape: S.Shape, angle: float, pivot) -> S.Shape:
    """``shape`` built around the origin, tilted back (top towards -Y) by ``angle`` radians,
    then moved so the origin lands on ``pivot``."""
    return shape.apply(make_transform(rot_x(angle), pivot))


def _leg(foot, top, r_foot: float, r_top: float) -> S.Shape:
    foot, top = np.asarray(foot, float), np.asarray(top, float)
    return S.frustum(r_foot, r_top, float(np.linalg.norm(top - foot)), center=foot,
                     axis=top - foot, sections=10)


def _upholstery(rng: np.random.Generator) -> Material:
    return M.fabric(rng) if rng.random() < 0.75 else M.leather(rng)


@register("office_chair", parts=("seat", "back", "base"),
          extra_parts=("column", "caster", "armrest", "headrest", "shell", "lever", "knob", "hub_cap"), size_range=(0.8, 1.35),
          density=400, variants=("task", "arms", "executive"))
def office_chair(rng: np.random.Generator, variant: str) -> list[Part]:
    sw, sd = rng.uniform(0.46, 0.52), rng.uniform(0.44, 0.5)
    st = rng.uniform(0.07, 0.09)
    z_seat = rng.uniform(0.45, 0.5)  # top of the seat
    pad = _upholstery(rng)
    shell = M.solid((0.12, 0.12, 0.13), "plastic", roughness=0.5)
    chrome = M.metal(rng)
    r_star = rng.uniform(0.3, 0.34)
    wheel_r = 0.025
    z_spoke = 2 * wheel_r + 0.035
    parts: list[Part] = []
    # five-star base: hub and five spokes dipping towards their tips
    base = [S.cylinder(0.045, 0.06, center=(0, 0, z_spoke + 0.015), sections=16)]
    for k in range(5):
        a = 2 * np.pi * k / 5 + np.pi / 2
        mid = np.array([np.cos(a), np.sin(a), 0.0]) * r_star / 2
        base.append(S.box((r_star, 0.045, 0.03), center=mid + [0, 0, z_spoke], R=rot_z(a)))
    parts.append(make_part("base", "base", base, chrome if rng.random() < 0.5 else shell))
    for k in range(5):
        a = 2 * np.pi * k / 5 + np.pi / 2
        tip = np.array([np.cos(a), np.sin(a), 0.0]) * (r_star - 0.02)
        tangent = (-np.sin(a), np.cos(a), 0.0)
        fork = S.box((0.03, 0.03, 0.03), center=tip + [0, 0, z_spoke - 0.025])
        wheel = S.cylinder(wheel_r, 0.022, center=tip + [0, 0, wheel_r], axis=tangent, sections=12)
        parts.append(make_part(f"caster_{k}", "caster", [fork, wheel], shell))
        # the cap over the wheel's axle on its outer face
        cap_c = tip + np.array(tangent) * (0.011 + 0.0015) + [0, 0, wheel_r]
        parts.append(make_part(f"hub_cap_{k}", "hub_cap", S.cylinder(0.011, 0.003, center=tuple(cap_c), axis=tangent, sections=10),
                               chrome))
    z_under = z_seat - st - 0.05
    col = [S.cylinder(0.034, 0.16, center=(0, 0, z_spoke + 0.045 + 0.08), sections=14),
           S.cylinder(0.014, z_under - z_spoke - 0.1, center=(0, 0, (z_under + z_spoke + 0.1) / 2),
                      sections=12),
           bevel_box((0.2, 0.22, 0.05), center=(0, 0, z_under + 0.025), bevel=0.01)]
    parts.append(make_part("column", "column", col, shell))
    parts.append(make_part("seat", "seat", cushion(sw, sd, st, (0, 0.01, z_seat - st / 2),
                                                   round_xy=0.06, round_z=0.025), pad))
    # the moulded shell under the seat's foam, the gas lift's lever and the tilt tension knob
    # under the mechanism
    parts.append(make_part("shell", "shell", bevel_box((sw * 0.92, sd * 0.9, 0.015), center=(0, 0.01, z_seat - st - 0.0075 + 0.001),
                                                       bevel=0.005), shell))
    parts.append(make_part("lever", "lever", S.tube([[0.09, 0.05, z_under + 0.025], [sw / 2 - 0.03, 0.09, z_under + 0.02]], 0.006,
                                                    sections=8), shell))
    parts.append(make_part("knob", "knob", S.cylinder(0.03, 0.025, center=(0, 0.09, z_under - 0.0125), sections=12), shell))
    # the tilt lock's lever out of the mechanism's other side
    parts.append(make_part("lever_1", "lever", S.tube([[-0.09, 0.05, z_under + 0.025], [-(sw / 2 - 0.03), 0.09, z_under + 0.02]], 0.006,
                                                      sections=8), shell))
    # back: a padded panel on an L-shaped spine from under the seat
    bh = rng.uniform(0.45, 0.58) if variant != "executive" else rng.uniform(0.52, 0.6)
    bw = sw * rng.uniform(0.88, 0.98)
    lean = np.deg2rad(rng.uniform(8, 14))
    y_back = -sd / 2 - 0.04
    z_back0 = z_seat + 0.06
    panel = _leaning(cushion(bw, 0.07, bh, (0, 0, bh / 2), round_xy=0.06, round_z=0.025),
                     lean, (0, y_back, z_back0))
    spine_top = np.array([0, y_back - 0.045, z_back0 + 0.12])
    spine = S.tube([[0, -sd / 2 + 0.08, z_under + 0.02], [0, y_back - 0.04, z_under + 0.02],
                    spine_top], 0.016, sections=8)
    parts.append(make_part("back", "back", [panel, spine], pad))
    if variant == "executive":
        hz = z_back0 + bh * np.cos(lean) + 0.04
        hy = y_back - bh * np.sin(lean) - 0.01
        head = _leaning(cushion(bw * 0.6, 0.08, 0.14, (0, 0, 0.07), round_xy=0.05, round_z=0.03),
                        lean, (0, hy, hz))
        parts.append(make_part("headrest", "headrest", head, pad))
    if variant != "task":
        arm_z = z_seat + rng.uniform(0.19, 0.24)
        for i, sx in enumerate((-1, 1)):
            x = sx * (sw / 2 + 0.035)
            post = S.tube([[sx * (sw / 2 - 0.08), -0.05, z_under + 0.02],
                           [x, -0.05, z_under + 0.02], [x, -0.03, arm_z - 0.02]], 0.014, sections=8)
            pad_ = bevel_box((0.07, 0.25, 0.03), center=(x, -0.03, arm_z), bevel=0.01)
            parts.append(make_part(f"armrest_{i}", "armrest", [post, pad_], shell))
    return parts


@register("dining_chair", parts=("seat", "back", "leg"),
          extra_parts=("stretcher", "back_post", "spindle", "splat", "foot", "apron", "corner_block", "button", "screw"),
          size_range=(0.75, 1.1), density=550, variants=("spindle", "solid", "upholstered"))
def dining_chair(rng: np.random.Generator, variant: str) -> list[Part]:
    sw, sd = rng.uniform(0.42, 0.5), rng.uniform(0.42, 0.48)
    z_seat = rng.uniform(0.44, 0.48)
    wood = M.wood(rng)
    upholstered = variant == "upholstered"
    st = rng.uniform(0.06, 0.08) if upholstered else rng.uniform(0.025, 0.04)
    seat_mat = _upholstery(rng) if upholstered else wood
    leg = rng.uniform(0.032, 0.042)
    z_leg = z_seat - st
    parts: list[Part] = []
    if upholstered:
        seat = cushion(sw, sd, st, (0, 0, z_seat - st / 2), round_xy=0.03, round_z=0.02)
    else:
        seat = bevel_box((sw, sd, st), center=(0, 0, z_seat - st / 2), bevel=0.006)
    parts.append(make_part("seat", "seat", seat, seat_mat))
    tapered = rng.random() < 0.5
    i = 0
    for sy in (-1, 1):
        for sx in (-1, 1):
            top = np.array([sx * (sw / 2 - leg / 2 - 0.01), sy * (sd / 2 - leg / 2 - 0.01), z_leg])
            foot = top * [1.0, 1.0, 0.0] + [sx * 0.01, sy * 0.015, 0.0]
            if tapered:
                shape = _leg(foot, top, leg * 0.32, leg * 0.55)
            else:
                shape = bevel_box((leg, leg, z_leg), center=(top[0], top[1], z_leg / 2),
                                  bevel=0.004)
            parts.append(make_part(f"leg_{i}", "leg", shape, wood))
            # a felt pad under the leg (the chair stands on its four pads)
            pad = S.cylinder(leg * (0.3 if tapered else 0.42), 0.004,
                             center=(foot[0] if tapered else top[0], foot[1] if tapered else top[1], -0.002),
                             sections=10)
            parts.append(make_part(f"foot_{i}", "foot", pad, M.solid((0.2, 0.2, 0.2), "fabric", 0.95)))
            i += 1
    # the seat rails between the legs' tops and a glue block in each inside corner
    ah = 0.05
    ax, ay = sw - 2 * (leg + 0.01), sd - 2 * (leg + 0.01)
    xa, ya = sw / 2 - leg / 2 - 0.01, sd / 2 - leg / 2 - 0.01
    parts += [make_part(f"apron_{k}", "apron", S.box(size, center=c), wood) for k, (size, c) in enumerate([
        ((ax, 0.02, ah), (0, -ya, z_leg - ah / 2)), ((ax, 0.02, ah), (0, ya, z_leg - ah / 2)),
        ((0.02, ay, ah), (-xa, 0, z_leg - ah / 2)), ((0.02, ay, ah), (xa, 0, z_leg - ah / 2))])]
    cb = 0.035
    parts += [make_part(f"corner_block_{k}", "corner_block",
                        S.box((cb, cb, ah * 0.7), center=(sx * (xa - leg / 2 - cb / 2), sy * (ya - 0.01 - cb / 2), z_leg - ah * 0.35)), wood)
              for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)])]
    # the screw up through each block into the seat, its head just under the block
    steel = M.solid((0.55, 0.55, 0.57), "metal", 0.35, 0.9)
    parts += [make_part(f"screw_{k}", "screw",
                        S.cylinder(0.0045, 0.002, center=(sx * (xa - leg / 2 - cb / 2), sy * (ya - 0.01 - cb / 2), z_leg - ah * 0.7 - 0.001),
                                   sections=8), steel)
              for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)])]
    if rng.random() < 0.5:
        z_st = z_leg * 0.3
        parts += [make_part(f"stretcher_{i}", "stretcher",
                            S.cylinder(0.011, sd - 2 * leg, center=(sx * (sw / 2 - leg / 2 - 0.01), 0, z_st),
                                       axis=(0, 1, 0), sections=8), wood) for i, sx in enumerate((-1, 1))]
    # back
    bh = rng.uniform(0.38, 0.5)
    lean = np.deg2rad(rng.uniform(6, 12))
    y0 = -sd / 2 + leg / 2 + 0.01
    pivot = (0, y0, z_seat)
    back: list[S.Shape] = []
    if upholstered:
        back.append(cushion(sw * 0.94, 0.07, bh, (0, 0, bh / 2 - 0.02), round_xy=0.03,
                            round_z=0.025))
        mat = seat_mat
    else:
        post_w = leg * 0.9
        for sx in (-1, 1):
            back.append(bevel_box((post_w, post_w, bh), center=(sx * (sw / 2 - post_w / 2 - 0.01),
                                                                0, bh / 2), bevel=0.004))
        rail_h = rng.uniform(0.06, 0.1)
        inner = sw - 2 * post_w - 0.02
        back.append(bevel_box((inner + 0.01, 0.025, rail_h), center=(0, 0, bh - rail_h / 2),
                              bevel=0.005))
        if variant == "spindle":
            n = int(rng.integers(3, 7))
            span = bh - rail_h
            for x in np.linspace(-inner / 2, inner / 2, n + 2)[1:-1]:
                back.append(S.cylinder(0.009, span, center=(x, 0, span / 2), sections=8))
        else:
            ph = (bh - rail_h) * rng.uniform(0.45, 0.7)
            back.append(bevel_box((inner + 0.01, 0.018, ph), center=(0, 0, bh - rail_h - ph / 2),
                                  bevel=0.004))
        mat = wood
    if upholstered:
        parts.append(make_part("back", "back", [_leaning(s, lean, pivot) for s in back], mat))
        # the back is buttoned: two rows of three covered buttons on its front
        pts = [(x, 0.035, z) for z in (bh * 0.45, bh * 0.7) for x in (-sw * 0.25, 0.0, sw * 0.25)]
        parts += [make_part(f"button_{k}", "button", _leaning(S.cylinder(0.008, 0.006, center=p, axis=(0, 1, 0), sections=8),
                                                              lean, pivot), mat) for k, p in enumerate(pts)]
        return parts
    # the crest rail keeps the ``back`` label (it carries the back's front face); posts, spindles
    # and the splat are parts of their own
    posts, rail, rest = back[:2], back[2], back[3:]
    parts.append(make_part("back", "back", _leaning(rail, lean, pivot), mat))
    parts += [make_part(f"back_post_{i}", "back_post", _leaning(p, lean, pivot), mat) for i, p in enumerate(posts)]
    label = "spindle" if variant == "spindle" else "splat"
    parts += [make_part(f"{label}_{i}", label, _leaning(p, lean, pivot), mat) for i, p in enumerate(rest)]
    return parts


def _arm_block(name: str, x: float, w: float, d: float, z0: float, z1: float, y: float,
               mat: Material, roll: float) -> Part:
    return make_part(name, "armrest", cushion(w, d, z1 - z0, (x, y, (z0 + z1) / 2),
                                             round_xy=min(roll, w / 2.2), round_z=roll), mat)


def _short_legs(rng, xs, ys, h: float, mat: Material, start: int = 0) -> list[Part]:
    r = rng.uniform(0.017, 0.025)
    parts = []
    i = start
    for y in ys:
        for x in xs:
            parts.append(make_part(f"leg_{i}", "leg", S.frustum(r * 0.7, r, h, center=(x, y, 0),
                                                                sections=10), mat))
            i += 1
    return parts


@register("armchair", parts=("seat", "back", "armrest"), extra_parts=("frame", "leg", "wing", "button", "piping", "panel", "ferrule"),
          size_range=(0.7, 1.25), density=250, variants=("club", "wingback", "mid_century"))
def armchair(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.75, 0.95)
    d = rng.uniform(0.78, 0.92)
    h_leg = rng.uniform(0.06, 0.1) if variant == "club" else rng.uniform(0.12, 0.2)
    z_seat = rng.uniform(0.42, 0.47)
    pad = _upholstery(rng)
    wood = M.wood(rng)
    arm_w = rng.uniform(0.16, 0.22) if variant == "club" else rng.uniform(0.1, 0.14)
    arm_h = z_seat + rng.uniform(0.17, 0.24)
    back_t = rng.uniform(0.14, 0.2)
    deck_z = z_seat - rng.uniform(0.1, 0.14)
    inner_w = w - 2 * arm_w
    parts: list[Part] = []
    parts += _short_legs(rng, (-w / 2 + 0.05, w / 2 - 0.05), (-d / 2 + 0.05, d / 2 - 0.05),
                         h_leg, wood)
    if variant == "mid_century":
        # open wooden arms on the frame; the base is a slim rail box
        parts.append(make_part("frame", "frame", bevel_box(
            (w, d, deck_z - h_leg), center=(0, 0, (deck_z + h_leg) / 2), bevel=0.008), wood))
        for i, sx in enumerate((-1, 1)):
            x = sx * (w / 2 - arm_w / 2)
            bar = bevel_box((arm_w * 0.6, d * 0.9, 0.035), center=(x, 0.0, arm_h - 0.0175),
                            bevel=0.008)
            post = bevel_box((0.035, 0.04, arm_h - deck_z), center=(x, d * 0.35,
                                                                    (arm_h + deck_z) / 2))
            parts.append(make_part(f"armrest_{i}", "armrest", [bar, post], wood))
        back_h = rng.uniform(0.75, 0.85)
    else:
        parts.append(make_part("frame", "frame", cushion(
            w, d, deck_z - h_leg, (0, 0, (deck_z + h_leg) / 2), round_xy=0.03, round_z=0.02), pad))
        for i, sx in enumerate((-1, 1)):
            parts.append(_arm_block(f"armrest_{i}", sx * (w / 2 - arm_w / 2), arm_w, d - back_t * 0.5,
                                    deck_z - 0.001, arm_h, back_t * 0.25, pad, 0.04))
        back_h = rng.uniform(0.78, 0.9) if variant == "club" else rng.uniform(1.0, 1.15)
    parts.append(make_part("seat", "seat", cushion(
        inner_w - 0.01, d - back_t - 0.02, z_seat - deck_z, (0, back_t / 2, (z_seat + deck_z) / 2),
        round_xy=0.04, round_z=0.03), pad))
    lean = np.deg2rad(rng.uniform(5, 10))
    bh = back_h - deck_z
    back = cushion(inner_w if variant != "mid_century" else w - 0.02, back_t, bh, (0, 0, bh / 2),
                   round_xy=0.04, round_z=0.04)
    parts.append(make_part("back", "back", _leaning(back, lean, (0, -d / 2 + back_t / 2, deck_z)),
                           pad))
    # the cord piping along the back's top front seam
    bw = inner_w if variant != "mid_century" else w - 0.02
    welt = S.cylinder(0.006, bw - 0.08, center=(0, back_t / 2 - 0.012, bh - 0.014), axis=(1, 0, 0), sections=8)
    parts.append(make_part("piping_back", "piping", _leaning(welt, lean, (0, -d / 2 + back_t / 2, deck_z)), pad))
    if variant == "wingback":
        for i, sx in enumerate((-1, 1)):
            wing = cushion(0.08, d * 0.35, back_h - arm_h, (0, 0, (back_h - arm_h) / 2),
                           round_xy=0.03, round_z=0.03)
            wing = _leaning(wing, lean * 0.5, (sx * (w / 2 - 0.04), -d / 2 + d * 0.175, arm_h))
            parts.append(make_part(f"wing_{i}", "wing", wing, pad))
    # the back is tufted: two rows of covered buttons on its front
    y_front = -d / 2 + back_t
    xs = np.linspace(-inner_w * 0.3, inner_w * 0.3, 3)
    pts = [(x, back_t / 2, z) for z in (bh * 0.55, bh * 0.8) for x in xs]
    parts += [make_part(f"button_{k}", "button", _leaning(S.cylinder(0.009, 0.008, center=p, axis=(0, 1, 0), sections=8), lean,
                                                          (0, y_front - back_t / 2, deck_z)), pad) for k, p in enumerate(pts)]
    if variant != "mid_century":
        # the cord piping the seat cushion's front edge and the panels facing the arms' fronts
        parts.append(make_part("piping", "piping", S.cylinder(0.006, inner_w - 0.03, center=(0, d / 2 - 0.01, z_seat - 0.004),
                                                              axis=(1, 0, 0), sections=8), pad))
        parts += [make_part(f"panel_{i}", "panel", bevel_box((arm_w * 0.8, 0.012, (arm_h - deck_z) * 0.8),
                                                             center=(sx * (w / 2 - arm_w / 2), d / 2 + 0.002,
                                                                     (arm_h + deck_z) / 2 - 0.01), bevel=0.004), wood)
                  for i, sx in enumerate((-1, 1))]
    else:  # brass ferrules on the tapered legs' feet
        parts += leg_caps(parts, label="ferrule", mat=M.solid((0.78, 0.62, 0.3), "metal", 0.3, 0.9), height=0.035)
    return parts


@register("sofa", parts=("seat_cushion", "back_cushion", "armrest"), extra_parts=("frame", "leg", "panel", "piping", "button"),
          size_range=(1.4, 3.3), density=200, variants=("two_seat", "three_seat", "sectional"))
def sofa(rng: np.random.Generator, variant: str) -> list[Part]:
    n = 2 if variant == "two_seat" else 3
    cw = rng.uniform(0.55, 0.68)
    arm_w = rng.uniform(0.12, 0.24)
    w = n * cw + 2 * arm_w
    d = rng.uniform(0.85, 0.98)
    h_leg = rng.uniform(0.05, 0.14)
    z_seat = rng.uniform(0.42, 0.47)
    deck_z = z_seat - rng.uniform(0.12, 0.16)
    back_z = rng.uniform(0.78, 0.9)
    arm_h = z_seat + rng.uniform(0.14, 0.22)
    back_t = rng.uniform(0.14, 0.2)
    pad = _upholstery(rng)
    wood = M.wood(rng)
    chaise = rng.uniform(0.6, 0.75) if variant == "sectional" else 0.0
    depth_r = d + chaise  # the right end is deeper on a sectional
    parts: list[Part] = []
    frame = [cushion(w, d, deck_z - h_leg, (0, 0, (deck_z + h_leg) / 2), round_xy=0.03,
                     round_z=0.02),
             cushion(w - 2 * arm_w + 0.02, back_t, back_z - deck_z,
                     (0, -d / 2 + back_t / 2, (back_z + deck_z) / 2), round_xy=0.03,
                     round_z=0.05)]
    if chaise:
        cx = w / 2 - arm_w - cw / 2
        frame.append(cushion(cw + arm_w, chaise + 0.02, deck_z - h_leg,
                             (cx + arm_w / 2, d / 2 + chaise / 2 - 0.01, (deck_z + h_leg) / 2),
                             round_xy=0.03, round_z=0.02))
    parts.append(make_part("frame", "frame", frame, pad))
    ys = (-d / 2 + 0.05, d / 2 - 0.05)
    parts += _short_legs(rng, (-w / 2 + 0.06, w / 2 - 0.06), ys, h_leg, wood)
    if chaise:
        parts += _short_legs(rng, (w / 2 - arm_w - cw, w / 2 - 0.06), (depth_r - d / 2 - 0.05,),
                             h_leg, wood, start=4)
    # the centre support legs under the frame's middle rail, front and back (the same height as
    # the corner legs, so the sofa stands level on them all)
    n_leg = sum(p.label == "leg" for p in parts)
    parts += [p for p in _short_legs(rng, (0.0,), ys, h_leg, wood, start=n_leg)]
    roll = rng.uniform(0.03, 0.06)
    parts.append(_arm_block("armrest_0", -w / 2 + arm_w / 2, arm_w, d, deck_z - 0.001, arm_h, 0,
                            pad, roll))
    parts.append(_arm_block("armrest_1", w / 2 - arm_w / 2, arm_w, depth_r, deck_z - 0.001, arm_h,
                            (depth_r - d) / 2, pad, roll))
    sd = d - back_t - 0.01
    ct = z_seat - deck_z
    x0 = -w / 2 + arm_w
    for k in range(n):
        x = x0 + cw * (k + 0.5)
        depth = sd + (chaise if (chaise and k == n - 1) else 0.0)
        y = -d / 2 + back_t + depth / 2 + 0.005
        seat = cushion(cw - 0.008, depth, ct, (x, y, deck_z + ct / 2), round_xy=0.05,
                       round_z=ct * 0.35)
        parts.append(make_part(f"seat_cushion_{k}", "seat_cushion", seat, pad))
    # back cushions lean on the back frame, above the seat cushions
    lean = np.deg2rad(rng.uniform(10, 16))
    bc_t = rng.uniform(0.15, 0.2)
    bc_h = back_z - z_seat + rng.uniform(0.0, 0.06)
    for k in range(n):
        x = x0 + cw * (k + 0.5)
        c = cushion(cw - 0.012, bc_t, bc_h, (0, 0, bc_h / 2), round_xy=0.05, round_z=0.05)
        c = _leaning(c, lean, (x, -d / 2 + back_t + bc_t / 2 - 0.005 + bc_h * 0.5 * np.sin(lean),
                               z_seat + 0.005))
        parts.append(make_part(f"back_cushion_{k}", "back_cushion", c, pad))
        # the cord piping along the cushion's top front seam
        welt = S.cylinder(0.006, cw - 0.07, center=(0, bc_t / 2 - 0.01, bc_h - 0.012), axis=(1, 0, 0), sections=8)
        parts.append(make_part(f"piping_{n + k}", "piping",
                               _leaning(welt, lean, (x, -d / 2 + back_t + bc_t / 2 - 0.005 + bc_h * 0.5 * np.sin(lean), z_seat + 0.005)),
                               pad))
        # each back cushion is buttoned in its middle
        parts.append(make_part(f"button_{k}", "button", _leaning(S.cylinder(0.01, 0.008, center=(0, bc_t / 2, bc_h * 0.55), axis=(0, 1, 0),
                                                                           sections=8), lean,
                                                                (x, -d / 2 + back_t + bc_t / 2 - 0.005 + bc_h * 0.5 * np.sin(lean),
                                                                 z_seat + 0.005)), pad))
    # the cord piping along each seat cushion's front edge, and the panels facing the arms
    for k in range(n):
        x = x0 + cw * (k + 0.5)
        depth = sd + (chaise if (chaise and k == n - 1) else 0.0)
        yf = -d / 2 + back_t + depth + 0.005
        parts.append(make_part(f"piping_{k}", "piping", S.cylinder(0.006, cw - 0.06, center=(x, yf - 0.004, z_seat - ct * 0.5),
                                                                   axis=(1, 0, 0), sections=8), pad))
    for i, (sx, yf) in enumerate(((-1, d / 2), (1, depth_r - d / 2))):
        parts.append(make_part(f"panel_{i}", "panel", bevel_box((arm_w * 0.8, 0.012, (arm_h - deck_z) * 0.8),
                                                                center=(sx * (w / 2 - arm_w / 2), yf + 0.004, (arm_h + deck_z) / 2 - 0.01),
                                                                bevel=0.004), pad))
    return parts


@register("bar_stool", parts=("seat", "leg"), extra_parts=("footrest", "base", "foot", "plate", "bracket", "lever", "collar",
                                                         "screw"),
          size_range=(0.6, 1.0), density=600, variants=("four_leg", "three_leg", "pedestal"))
def bar_stool(rng: np.random.Generator, variant: str) -> list[Part]:
    z_seat = rng.uniform(0.63, 0.78)
    r = rng.uniform(0.17, 0.2)
    st = rng.uniform(0.04, 0.07)
    frame_mat = M.metal(rng) if rng.random() < 0.6 else M.wood(rng)
    seat_mat = _upholstery(rng) if rng.random() < 0.5 else M.wood(rng)
    seat = S.lathe([(r * 0.8, 0), (r, st * 0.35), (r, st * 0.65), (r * 0.9, st)], sections=28)
    parts = [make_part("seat", "seat", seat.moved((0, 0, z_seat - st)), seat_mat)]
    z_ring = rng.uniform(0.24, 0.32)
    if variant == "pedestal":
        rb = rng.uniform(0.2, 0.24)
        base = S.lathe([(rb, 0.0), (rb, 0.012), (rb * 0.5, 0.04), (0.04, 0.06)], sections=28)
        parts.append(make_part("base", "base", base, frame_mat))
        col = S.union([S.cylinder(0.025, z_seat - st - 0.06, center=(0, 0, (z_seat - st + 0.06) / 2),
                                  sections=14),
                       S.cylinder(0.07, 0.02, center=(0, 0, z_seat - st - 0.01), sections=20)])
        parts.append(make_part("leg_0", "leg", col, frame_mat))
        rr = rng.uniform(0.15, 0.18)
        a = np.linspace(0, 2 * np.pi, 20, endpoint=False)
        ring = S.tube(np.c_[rr * np.cos(a), rr * np.sin(a), np.full(20, z_ring)], 0.011,
                      sections=8, closed=True)
        spokes = [S.tube([[0, 0, z_ring], [sx * rr, 0, z_ring]], 0.009, sections=8)
                  for sx in (-1, 1)]
        parts.append(make_part("footrest", "footrest", [ring, *spokes], frame_mat))
        # the gas lift's lever under the seat and the glide ring round the base's rim
        parts.append(make_part("lever", "lever", S.tube([[0.05, 0, z_seat - st - 0.015], [r * 0.9, 0.02, z_seat - st - 0.02]], 0.005,
                                                        sections=8), frame_mat))
        parts.append(make_part("foot", "foot", ring_([(rb - 0.012, 0.0), (rb + 0.002, 0.0), (rb + 0.002, 0.006), (rb - 0.012, 0.006)]),
                               M.solid((0.08, 0.08, 0.08), "plastic", 0.7)))
        # the clamp collar holding the footrest's spokes on the column
        parts.append(make_part("collar", "collar", S.cylinder(0.036, 0.044, center=(0, 0, z_ring), sections=12), frame_mat))
        return parts + _seat_screws(0.05, z_seat - st - 0.02)
    n = 4 if variant == "four_leg" else 3
    r_top, r_foot = r * 0.62, r * rng.uniform(1.05, 1.25)
    phase = np.pi / 4 if n == 4 else np.pi / 2
    lr = rng.uniform(0.013, 0.02)
    for k in range(n):
        a = phase + 2 * np.pi * k / n
        d = np.array([np.cos(a), np.sin(a), 0.0])
        foot, top = d * r_foot, d * r_top + [0, 0, z_seat - st]
        parts.append(make_part(f"leg_{k}", "leg", _leg(foot, top, lr * 0.85, lr), frame_mat))
        # a plastic glide cap under each leg
        parts.append(make_part(f"foot_{k}", "foot", S.cylinder(lr * 0.95, 0.006, center=foot - [0, 0, 0.003],
                                                               sections=10),
                               M.solid((0.08, 0.08, 0.08), "plastic", 0.7)))
    # the footrest ring runs through the legs at z_ring
    rr = r_foot + (r_top - r_foot) * z_ring / (z_seat - st)
    a = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    ring = S.tube(np.c_[rr * np.cos(a), rr * np.sin(a), np.full(24, z_ring)], 0.01, sections=8,
                  closed=True)
    parts.append(make_part("footrest", "footrest", ring, frame_mat))
    # the ring is welded to each leg through a bracket; the seat is screwed to a mounting plate
    # on the legs' tops
    for k in range(n):
        a = phase + 2 * np.pi * k / n
        c = np.array([np.cos(a), np.sin(a), 0.0]) * rr + [0, 0, z_ring + 0.0]
        parts.append(make_part(f"bracket_{k}", "bracket", S.box((0.03, 0.03, 0.024), center=c, R=rot_z(a)), frame_mat))
    parts.append(make_part("plate", "plate", S.cylinder(r_top + lr, 0.008, center=(0, 0, z_seat - st - 0.004), sections=16),
                           frame_mat))
    return parts + _seat_screws(r_top * 0.5, z_seat - st - 0.008)


def _seat_screws(radius: float, z: float) -> list[Part]:
    """The four screws up through a stool's mounting plate (underside at ``z``) into its seat,
    their heads on a circle of ``radius``."""
    steel = M.solid((0.6, 0.6, 0.62), "metal", 0.35, 0.9)
    return [make_part(f"screw_{k}", "screw", S.cylinder(0.006, 0.003, center=(radius * np.cos(a), radius * np.sin(a), z - 0.0015),
                                                        sections=8), steel)
            for k, a in enumerate(np.pi / 4 + np.pi / 2 * np.arange(4))]
