"""Beds and bunk beds.

A ``bed`` lies along Y with its ``headboard`` at -Y and its foot at +Y; the ``mattress`` top is
where pillows go. Variants: a low upholstered ``platform``, a ``four_poster`` with posts, canopy
rails and a footboard, and a ``storage`` bed whose base holds drawers at the foot.

A ``bunk_bed`` lies along X with its open, accessible side at +Y: ``mattress_0`` (lower) and
``mattress_1`` (upper), a guard rail around the upper bunk and a ``ladder`` at the front or at
the +X end.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._bedbath_common import bar_handle, bevel_box, cushion, drawer_shape, post

_MATTRESS_WIDTHS = (0.9, 1.2, 1.4, 1.6, 1.8)


def _mattress(name: str, w: float, d: float, t: float, center, mat) -> Part:
    shape = cushion(w, d, t, center, round_xy=0.05, round_z=min(0.04, t * 0.3))
    return make_part(name, "mattress", shape, mat)


def _mattress_details(k: int, w: float, d: float, t: float, center, mat) -> list[Part]:
    """The pieces sewn onto mattress ``k`` (``w`` x ``d`` x ``t`` centred at ``center``): the tape
    edges binding its top and bottom borders (``tape_edge``), four air ``vent`` grommets in its
    long sides and the law ``tag`` on one side near the head. None rises above its top."""
    cx, cy, cz = center
    tape = M.solid(np.asarray(mat.color[:3]) * 0.85, "fabric", 0.9)
    out = []
    for j, z in enumerate((cz - t / 2 + 0.015, cz + t / 2 - 0.015)):
        e, hgt = 0.004, 0.016
        ring_ = [S.box((w - 0.08, e, hgt), center=(cx, cy + sy * (d / 2 + e / 2 - 0.001), z)) for sy in (-1, 1)]
        ring_ += [S.box((e, d - 0.08, hgt), center=(cx + sx * (w / 2 + e / 2 - 0.001), cy, z)) for sx in (-1, 1)]
        out.append(make_part(f"tape_edge_{2 * k + j}", "tape_edge", ring_, tape))
    metal = M.solid((0.75, 0.75, 0.72), "metal", 0.4, 0.8)
    for j, (sx, fy) in enumerate([(-1, -0.35), (-1, 0.35), (1, -0.35), (1, 0.35)]):
        out.append(make_part(f"vent_{4 * k + j}", "vent", S.cylinder(0.012, 0.004, center=(cx + sx * (w / 2 + 0.001), cy + fy * d, cz),
                                                                    axis=(1, 0, 0), sections=10), metal))
    out.append(make_part(f"tag_{k}" if k else "tag", "tag", S.box((0.002, 0.05, 0.07), center=(cx + w / 2 + 0.002, cy - d / 2 + 0.15, cz)),
                         M.solid((0.95, 0.95, 0.93), "paper", 0.8)))
    return out


def _bed_frame_rails(w: float, d: float, z_top: float, rail_h: float, rail_t: float, mat) -> list[Part]:
    """The rails round a ``w`` x ``d`` mattress opening whose tops are at ``z_top`` (the
    ``frame`` group): the two ``side_rail``s and the ``foot_rail``; the head end is the
    headboard. A bed 1.4 m wide or more also has a ``center_rail`` under the slats, carried
    by two ``support_leg``s."""
    zc = z_top - rail_h / 2
    out = [make_part(f"side_rail_{k}", "side_rail", bevel_box((rail_t, d, rail_h), center=(sx * (w / 2 + rail_t / 2), 0, zc), bevel=0.004),
                     mat) for k, sx in enumerate((-1, 1))]
    out.append(make_part("frame", "foot_rail", bevel_box((w + 2 * rail_t, rail_t, rail_h), center=(0, d / 2 + rail_t / 2, zc),
                                                         bevel=0.004), mat))
    # the hook-on bracket at each end of each side rail, let into its inner face
    steel = M.solid((0.3, 0.3, 0.32), "metal", 0.4, 0.8)
    out += [make_part(f"rail_bracket_{2 * k + j}", "rail_bracket", S.box((0.004, 0.05, rail_h * 0.7),
                                                                        center=(sx * (w / 2 + 0.002), fy * (d / 2 - 0.03), zc)), steel)
            for k, sx in enumerate((-1, 1)) for j, fy in enumerate((-1, 1))]
    if w >= 1.4 - 0.03:
        zr = z_top - 0.03 - 0.02  # under the slats
        out.append(make_part("center_rail", "center_rail", S.box((0.05, d, 0.06), center=(0, 0, zr - 0.03)), mat))
        out += [make_part(f"support_leg_{k}", "support_leg", S.cylinder(0.025, zr - 0.06, center=(0, fy * d, (zr - 0.06) / 2),
                                                                        sections=10), mat)
                for k, fy in enumerate((-0.25, 0.25))]
    return out


def _slats(w: float, d: float, z: float, mat, *, pitch: float = 0.16) -> list[Part]:
    """Bed slats across the frame (``slat_k``, along X) whose tops are at ``z``."""
    n = max(6, int(d / pitch))
    return [make_part(f"slat_{k}", "slat", S.box((w, 0.07, 0.02), center=(0, -d / 2 + d * (k + 0.5) / n, z - 0.01)), mat)
            for k in range(n)]


@register("bed", parts=("frame", "mattress", "headboard"),
          extra_parts=("leg", "post", "canopy", "footboard", "drawer", "handle", "slat", "button", "mattress_handle",
                       "tape_edge", "vent", "tag", "glide", "finial", "caster", "rail_bracket"),
          size_range=(1.9, 2.5), density=250, variants=("platform", "four_poster", "storage"),
          groups={"frame": ("frame", "side_rail", "foot_rail", "center_rail", "support_leg", "plinth", "deck")})
def bed(rng: np.random.Generator, variant: str) -> list[Part]:
    w = float(rng.choice(_MATTRESS_WIDTHS)) + rng.uniform(-0.02, 0.02)
    d = rng.uniform(1.95, 2.08)
    t_mat = rng.uniform(0.18, 0.28)
    wood = M.wood(rng)
    cloth = M.fabric(rng)
    ticking = M.solid((0.93, 0.92, 0.9), "fabric", roughness=0.95)
    upholstered = variant == "platform" or (variant == "storage" and rng.random() < 0.5)
    head_mat = cloth if upholstered else wood
    rail_t = rng.uniform(0.04, 0.07)
    parts: list[Part] = []
    head_t = rng.uniform(0.06, 0.1)
    y_head = -d / 2 - head_t / 2
    # a platform's deck and a storage bed's base are as wide as the headboard at their head:
    # the bed goes flush along a wall by its frame's side (``frame@left``/``frame@right``)
    fw = w + 2 * rail_t + 0.04
    if variant == "platform":
        z_top = rng.uniform(0.16, 0.28)
        plinth_h = z_top * 0.35
        base = S.box((fw - 0.16, d - 0.16, plinth_h), center=(0, 0, plinth_h / 2))
        deck = cushion(fw, d + rail_t, z_top - plinth_h,
                       (0, rail_t / 2, (z_top + plinth_h) / 2), round_xy=0.03, round_z=0.015)
        # the recessed plinth and the upholstered deck on it (``frame`` covers both)
        parts.append(make_part("plinth", "plinth", base, cloth))
        parts.append(make_part("frame", "deck", deck, cloth))
        # the glides under the plinth's corners, set into it
        bx, by = (fw - 0.16) / 2 - 0.03, (d - 0.16) / 2 - 0.03
        nylon = M.solid((0.85, 0.85, 0.82), "plastic", 0.4)
        parts += [make_part(f"glide_{k}", "glide", S.cylinder(0.015, 0.005, center=(sx * bx, sy * by, 0.0025), sections=10), nylon)
                  for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)])]
        head_h = rng.uniform(0.9, 1.25)
        parts.append(make_part("headboard", "headboard", cushion(
            fw, head_t, head_h, (0, y_head, head_h / 2),
            round_xy=0.02, round_z=0.04), head_mat))
    elif variant == "four_poster":
        z_top = rng.uniform(0.35, 0.45)
        rail_h = rng.uniform(0.14, 0.2)
        parts += _bed_frame_rails(w, d, z_top, rail_h, rail_t, wood)
        # the slats the mattress rests on, a little below the rail tops
        parts += _slats(w, d, z_top - 0.03, wood)
        top = rng.uniform(1.9, 2.2)
        ps = rng.uniform(0.07, 0.1)
        turned = rng.random() < 0.5
        xs = (-w / 2 - rail_t - ps / 2, w / 2 + rail_t + ps / 2)
        ys = (-d / 2 - head_t - ps / 2, d / 2 + rail_t + ps / 2)
        i = 0
        for y in ys:
            for x in xs:
                shp = post(x, y, 0.0, top, ps, turned=turned)
                parts.append(make_part(f"post_{i}", "post", shp, wood))
                # the turned finial crowning the post above the canopy
                parts.append(make_part(f"finial_{i}", "finial", S.lathe([(ps * 0.3, top), (ps * 0.42, top + 0.03), (ps * 0.25, top + 0.06),
                                                                         (ps * 0.05, top + 0.075)], sections=12), wood))
                i += 1
        cr = 0.035
        canopy = [S.box((xs[1] - xs[0] + ps, cr * 1.6, cr), center=(0, y, top - cr / 2))
                  for y in ys]
        canopy += [S.box((cr * 1.6, ys[1] - ys[0] - ps, cr), center=(x, 0, top - cr / 2 - 0.002))
                   for x in xs]
        parts.append(make_part("canopy", "canopy", canopy, wood))
        head_h = rng.uniform(1.0, 1.3)
        head = bevel_box((xs[1] - xs[0] - ps, head_t, head_h - 0.1),
                     center=(0, y_head, 0.1 + (head_h - 0.1) / 2), bevel=0.008)
        parts.append(make_part("headboard", "headboard", head, wood))
        foot_h = rng.uniform(0.55, 0.75)
        foot = bevel_box((xs[1] - xs[0] - ps, 0.05, foot_h - 0.12),
                     center=(0, ys[1], 0.12 + (foot_h - 0.12) / 2), bevel=0.006)
        parts.append(make_part("footboard", "footboard", foot, wood))
    else:  # storage
        z_top = rng.uniform(0.38, 0.48)
        base = bevel_box((fw, d + rail_t, z_top - 0.03),
                     center=(0, rail_t / 2 - 0.025, (z_top - 0.03) / 2), bevel=0.006)
        base_mat = cloth if upholstered else wood
        parts.append(make_part("frame", "frame", base, base_mat))
        y_face = d / 2 + rail_t - 0.025
        n_dr = 2
        dw = (fw - 0.12) / n_dr
        dh = (z_top - 0.03) * 0.62
        zc = 0.05 + dh / 2
        for k in range(n_dr):
            x = -fw / 2 + 0.06 + dw * (k + 0.5)
            parts.append(make_part(f"drawer_{k}", "drawer", drawer_shape(
                x, zc, dw - 0.02, dh, y_face + 0.02, 0.5), base_mat))
            parts.append(make_part(f"handle_{k}", "handle",
                                   bar_handle((x, y_face + 0.02, zc + dh * 0.25), 0.16),
                                   M.metal(rng)))
            # the two casters the drawer rolls out on, under its box
            for j, sx in enumerate((-1, 1)):
                parts.append(make_part(f"caster_{2 * k + j}", "caster",
                                       S.cylinder(0.02, 0.015, center=(x + sx * (dw / 2 - 0.06), y_face - 0.25, 0.02),
                                                  axis=(1, 0, 0), sections=10), M.solid((0.1, 0.1, 0.1), "rubber", 0.8)))
        head_h = rng.uniform(1.0, 1.3)
        head = cushion(fw, head_t, head_h, (0, y_head, head_h / 2),
                       round_xy=0.02, round_z=0.03 if upholstered else 0.008)
        parts.append(make_part("headboard", "headboard", head, head_mat))
    parts.append(_mattress("mattress", w - 0.01, d - 0.02, t_mat,
                           (0, 0, z_top - 0.04 + t_mat / 2), ticking))
    parts += _mattress_details(0, w - 0.01, d - 0.02, t_mat, (0, 0, z_top - 0.04 + t_mat / 2), ticking)
    # the strap handles sewn to the mattress's long sides, for turning it
    zm = z_top - 0.04 + t_mat / 2
    for k, (sx, y) in enumerate([(-1, -d * 0.2), (-1, d * 0.2), (1, -d * 0.2), (1, d * 0.2)]):
        x = sx * ((w - 0.01) / 2 + 0.004)
        parts.append(make_part(f"mattress_handle_{k}", "mattress_handle",
                               S.box((0.008, 0.12, 0.025), center=(x, y, zm), bevel=0.002), ticking))
    if upholstered:
        parts += _tufting(w, -d / 2, z_top - 0.04 + t_mat + 0.12, head_h - 0.1, cloth)
    return parts


def _tufting(w: float, y_face: float, z0: float, z1: float, cloth) -> list[Part]:
    """Diamond-tufted buttons (``button_k``) on an upholstered headboard whose front is at
    ``y_face``, in rows between heights ``z0`` and ``z1``: alternate rows of four and three."""
    if z1 - z0 < 0.1:
        return []
    rows = 2 if z1 - z0 < 0.35 else 3
    dz = (z1 - z0) / (rows - 1)
    pitch = w / 4
    out = []
    mat = M.solid(np.asarray(cloth.color[:3]) * 0.8, "fabric", 0.9)  # a shade darker than the cloth
    for r in range(rows):
        n = 4 if r % 2 == 0 else 3
        for k in range(n):
            x = (k - (n - 1) / 2) * pitch
            out.append(make_part(f"button_{len(out)}", "button",
                                 S.cylinder(0.012, 0.012, center=(x, y_face + 0.001, z0 + r * dz), axis=(0, 1, 0),
                                            sections=10), mat))
    return out


@register("bunk_bed", parts=("frame", "mattress", "ladder"),
          extra_parts=("guard_rail", "end_panel", "drawer", "handle", "slat", "tape_edge", "vent", "tag", "bolt_cap", "glide"),
          size_range=(1.9, 2.4), density=300,
          variants=("front_ladder", "end_ladder", "trundle"))
def bunk_bed(rng: np.random.Generator, variant: str) -> list[Part]:
    length = rng.uniform(1.95, 2.05)  # mattress, along X
    width = rng.uniform(0.88, 1.0)  # mattress, along Y
    t_mat = rng.uniform(0.12, 0.16)
    wood = M.wood(rng) if rng.random() < 0.7 else M.metal(rng)
    ps = rng.uniform(0.06, 0.08)
    top = rng.uniform(1.6, 1.8)
    z_low = rng.uniform(0.28, 0.36) if variant == "trundle" else rng.uniform(0.22, 0.32)
    z_up = rng.uniform(1.15, 1.3)
    rail_h, rail_t = 0.12, 0.035
    xs = (-length / 2 - ps / 2, length / 2 + ps / 2)
    ys = (-width / 2 - ps / 2, width / 2 + ps / 2)
    frame = [post(x, y, 0.0, top, ps, bevel=0.006) for y in ys for x in xs]
    for z in (z_low, z_up):
        for y in ys:
            frame.append(bevel_box((length, rail_t, rail_h), center=(0, y, z - rail_h / 2)))
    parts = [make_part("frame", "frame", frame, wood)]
    # each bunk's mattress rests on slats across the width
    n_slat = 12
    for b, z in enumerate((z_low, z_up)):
        parts += [make_part(f"slat_{b}_{k}", "slat", S.box((length / n_slat * 0.55, width, 0.018),
                                                            center=(-length / 2 + length * (k + 0.5) / n_slat, 0, z - 0.05)),
                            wood) for k in range(n_slat)]
    for i, x in enumerate(xs):
        panels = [bevel_box((0.03, width, h), center=(x, 0, z0 + h / 2), bevel=0.005)
                  for z0, h in ((z_low - 0.05, 0.3), (z_up - 0.05, top - z_up - 0.02))]
        parts.append(make_part(f"end_panel_{i}", "end_panel", panels, wood))
    mat = M.solid((0.93, 0.92, 0.9), "fabric", roughness=0.95)
    parts.append(_mattress("mattress_0", length - 0.01, width - 0.01, t_mat,
                           (0, 0, z_low - 0.04 + t_mat / 2), mat))
    parts.append(_mattress("mattress_1", length - 0.01, width - 0.01, t_mat,
                           (0, 0, z_up - 0.04 + t_mat / 2), mat))
    for b, z in enumerate((z_low, z_up)):
        parts += _mattress_details(b, length - 0.01, width - 0.01, t_mat, (0, 0, z - 0.04 + t_mat / 2), mat)
    # guard rails of the upper bunk: full length at the back, leaving a gap for the ladder
    g_z = z_up + rng.uniform(0.28, 0.34)
    gap = 0.5
    back = bevel_box((length, rail_t, 0.08), center=(0, ys[0], g_z))
    front_len = length - gap if variant != "end_ladder" else length
    x_front = xs[0] + ps / 2 + front_len / 2
    front = S.box((front_len, rail_t, 0.08), center=(x_front, ys[1], g_z))
    parts.append(make_part("guard_rail_0", "guard_rail", back, wood))
    parts.append(make_part("guard_rail_1", "guard_rail", front, wood))
    # ladder: two stiles and round rungs
    rung_r = 0.015
    z_rungs = np.linspace(z_low + 0.15, z_up + 0.2, 4)
    if variant == "end_ladder":
        lx = xs[1] + ps / 2 + 0.03
        lw = min(width * 0.55, 0.45)
        stiles = [bevel_box((0.035, 0.05, z_up + 0.3), center=(lx, y, (z_up + 0.3) / 2), bevel=0.004)
                  for y in (-lw / 2, lw / 2)]
        rungs = [S.cylinder(rung_r, lw, center=(lx, 0, z), axis=(0, 1, 0), sections=10)
                 for z in z_rungs]
    else:
        ly = ys[1] + ps / 2 + 0.03
        lw = 0.42
        x0 = xs[1] - ps / 2 - gap / 2
        stiles = [bevel_box((0.05, 0.035, z_up + 0.3), center=(x, ly, (z_up + 0.3) / 2), bevel=0.004)
                  for x in (x0 - lw / 2, x0 + lw / 2)]
        rungs = [S.cylinder(rung_r, lw, center=(x0, ly, z), axis=(1, 0, 0), sections=10)
                 for z in z_rungs]
    parts.append(make_part("ladder", "ladder", stiles + rungs, wood))
    # the bed bolts drawing each rail end to its post, their caps let flush into the post's
    # outer face; a glide under each post
    metal = M.solid((0.72, 0.7, 0.66), "metal", 0.3, 0.9)
    k = 0
    for z in (z_low, z_up):
        for y in ys:
            for x in xs:
                sx = 1.0 if x > 0 else -1.0
                parts.append(make_part(f"bolt_cap_{k}", "bolt_cap", S.cylinder(0.011, 0.002, center=(x + sx * (ps / 2 - 0.001), y, z - rail_h / 2),
                                                                             axis=(1, 0, 0), sections=10), metal))
                k += 1
    # the bolts holding the guard rails to the upper posts: both ends of the back rail, and the
    # front rail's ends that meet a post (one where the ladder leaves a gap)
    ends = [(x, ys[0]) for x in xs] + ([(x, ys[1]) for x in xs] if variant == "end_ladder" else [(xs[0], ys[1])])
    for x, y in ends:
        sx = 1.0 if x > 0 else -1.0
        parts.append(make_part(f"bolt_cap_{k}", "bolt_cap", S.cylinder(0.011, 0.002, center=(x + sx * (ps / 2 - 0.001), y, g_z),
                                                                     axis=(1, 0, 0), sections=10), metal))
        k += 1
    # a glide under the foot of each ladder stile
    parts += [make_part(f"ladder_glide_{i}", "glide", S.cylinder(0.012, 0.003, center=(float(s.mesh.bounds[:, 0].mean()), float(s.mesh.bounds[:, 1].mean()), 0.0015),
                                                                 sections=10), M.solid((0.25, 0.25, 0.26), "plastic", 0.6))
              for i, s in enumerate(stiles)]
    parts += [make_part(f"glide_{i}", "glide", S.cylinder(min(0.012, ps * 0.3), 0.003, center=(x, y, 0.0015), sections=10),
                        M.solid((0.25, 0.25, 0.26), "plastic", 0.6)) for i, (x, y) in enumerate((x, y) for y in ys for x in xs)]
    if variant == "trundle":
        dh = z_low - 0.1
        dw = length * 0.9
        y_face = ys[1] - ps / 2 + 0.01
        parts.append(make_part("drawer", "drawer", drawer_shape(
            0, 0.025 + dh / 2, dw, dh, y_face, width * 0.85), wood))
        parts.append(make_part("handle", "handle",
                               bar_handle((0, y_face, 0.025 + dh * 0.6), 0.2), M.metal(rng)))
    return parts
