"""Large leisure items: pianos (upright and grand), pool tables and standing coat racks.

Pianos put the keyboard at +Y (the player sits in front of the asset, facing −Y); a grand's
straight long side is at +X and its curved bentside at −X.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from ...geometry.frames import axis_angle, make_transform
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._casework import black, felt
from ._dC_keys import white_keys


def _keyboard(x0: float, x1: float, y_front: float, z: float, depth: float, ivory, ebony) -> list[Part]:
    """The keys: the key bed they rest on (``keyboard``), the 52 white keys on it and the 36
    raised black keys, each key its own part (``white_key_k`` and ``black_key_k``, label ``key``);
    ``z`` is the top of the white keys, ``y_front`` their front."""
    w = x1 - x0
    shapes = [S.box((w, depth, 0.01), center=((x0 + x1) / 2, y_front - depth / 2, z - 0.02), bevel=0.002)]
    n_white = 52
    kw = w / n_white
    for i in range(n_white - 1):
        # the keyboard runs A0 to C8: a black key follows every A, C, D, F and G (A#0 to A#7)
        if "ABCDEFG"[i % 7] in "ACDFG":
            shapes.append(S.box((kw * 0.55, depth * 0.62, 0.012),
                                center=(x0 + (i + 1) * kw, y_front - depth + depth * 0.31, z + 0.006)))
    bed = make_part("keyboard", "keyboard", shapes[0], ivory)
    whites = white_keys(x0, x1, y_front=y_front, depth=depth, z0=z - 0.015, z1=z, mat=ivory, n=n_white)
    return [bed] + whites + [make_part(f"black_key_{k}", "key", sh, ebony) for k, sh in enumerate(shapes[1:])]


def _grand_outline(w: float, length: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Sample the grand's case outline: for each y (tail at −length to keyboard at 0) the x of
    the curved bentside; the straight side is x = +w/2."""
    ys = np.linspace(-length, 0.0, n + 1)
    s = (ys + length) / length  # 0 at the tail, 1 at the keyboard
    tail_w = 0.28
    # narrow at the tail, an S-curve widening toward the keyboard end
    frac = tail_w / w + (1 - tail_w / w) * (0.5 - 0.5 * np.cos(np.pi * np.clip(s * 1.25, 0, 1)))
    xs = w / 2 - frac * w
    return ys, xs


@register("piano", parts=("body", "keyboard", "lid"), extra_parts=("leg", "pedal", "music_rest", "prop", "key"),
          size_range=(1.2, 2.9), density=700, variants=("upright", "grand", "baby_grand"))
def piano(rng: np.random.Generator, variant: str) -> list[Part]:
    case = M.Material((0.03, 0.03, 0.035, 1.0), 0.15, 0.0, "wood") if rng.random() < 0.6 else M.wood(rng)
    ivory = M.solid((0.96, 0.95, 0.9), "plastic", 0.3)
    ebony = M.solid((0.05, 0.05, 0.05), "plastic", 0.3)
    brass = M.solid((0.8, 0.65, 0.35), "metal", 0.3, 0.9)
    w = rng.uniform(1.42, 1.55)
    kd = 0.15
    parts = []
    if variant == "upright":
        h, d = rng.uniform(1.1, 1.35), rng.uniform(0.55, 0.65)
        cd = d - 0.28  # cabinet depth behind the key bed
        yb = -d / 2
        body = [S.box((w, cd, h - 0.02), center=(0, yb + cd / 2, (h - 0.02) / 2), bevel=0.01),
                S.box((0.05, d - cd, 0.7), center=(-w / 2 + 0.025, yb + cd + (d - cd) / 2, 0.35)),
                S.box((0.05, d - cd, 0.7), center=(w / 2 - 0.025, yb + cd + (d - cd) / 2, 0.35)),
                S.box((w - 0.1, d - cd - 0.02, 0.07), center=(0, yb + cd + (d - cd - 0.02) / 2, 0.665))]
        parts.append(make_part("body", "body", body, case))
        # the lid overhangs the front and the sides; its back is flush with the cabinet's, which
        # stands against the wall
        parts.append(make_part("lid", "lid", S.box((w + 0.02, cd + 0.02, 0.02), center=(0, yb + cd / 2 + 0.01, h - 0.01),
                                                    bevel=0.004), case))
        parts += _keyboard(-w / 2 + 0.06, w / 2 - 0.06, d / 2 - 0.01, 0.725, kd, ivory, ebony)
        parts.append(make_part("music_rest", "music_rest",
                               S.box((w * 0.6, 0.02, 0.18), center=(0, yb + cd + 0.01, 0.9)), case))
        for i, x in enumerate((-w / 2 + 0.05, w / 2 - 0.05)):
            parts.append(make_part(f"leg_{i}", "leg", S.box((0.05, 0.05, 0.63), center=(x, d / 2 - 0.05, 0.315),
                                                             bevel=0.005), case))
        y_ped, z_ped = yb + cd + 0.06, 0.05
    else:
        length = rng.uniform(1.5, 1.75) if variant == "baby_grand" else rng.uniform(2.0, 2.6)
        zb0, zb1 = 0.62, 0.62 + 0.3
        ys, xs = _grand_outline(w, length, 8)
        ys = ys + length / 2  # the case spans y in [-length/2, length/2]; the keys sit in front
        slabs, lid = [], []
        for ya, yb_, xa, xb in zip(ys[:-1], ys[1:], xs[:-1], xs[1:], strict=True):
            poly = [(xa, ya), (w / 2, ya), (w / 2, yb_), (xb, yb_)]
            slabs.append(S.prism(poly, zb0, zb1))
            lid.append(S.prism(poly, zb1, zb1 + 0.02))
        parts.append(make_part("body", "body", slabs, case))
        ang = np.deg2rad(rng.uniform(0.0, 35.0))
        hinge = np.array([w / 2, 0.0, zb1 + 0.02])
        T = make_transform(axis_angle((0, 1, 0), ang), hinge) @ make_transform(None, -hinge)
        parts.append(make_part("lid", "lid", [s.apply(T) for s in lid], case))
        if ang > np.deg2rad(5):
            r = w * 0.55
            parts.append(make_part("prop", "prop", S.tube([[w / 2 - r, -0.1, zb1], [w / 2 - r, -0.1, zb1 + r * np.tan(ang)]],
                                                          0.008, sections=6), case))
        y_kb = length / 2
        parts.append(make_part("key_block", "body",
                               S.box((w, kd + 0.06, 0.1), center=(0, y_kb + (kd + 0.06) / 2, zb0 + 0.05)), case))
        parts += _keyboard(-w / 2 + 0.06, w / 2 - 0.06, y_kb + kd + 0.05, zb0 + 0.125, kd, ivory, ebony)
        leg_pts = [(-w / 2 + 0.12, y_kb - 0.1), (w / 2 - 0.12, y_kb - 0.1), (w / 2 - 0.2, -length / 2 + 0.25)]
        for i, (x, y) in enumerate(leg_pts):
            leg = S.lathe([(0.045, 0.0), (0.035, 0.05), (0.04, zb0 * 0.7), (0.06, zb0)], sections=12)
            parts.append(make_part(f"leg_{i}", "leg", leg.moved((x, y, 0)), case))
        y_ped, z_ped = y_kb - 0.05, 0.05
        parts.append(make_part("pedal_lyre", "pedal", S.box((0.2, 0.05, zb0 - 0.06), center=(0, y_ped - 0.03, zb0 / 2 + 0.03),
                                                            bevel=0.005), case))
    for i, x in enumerate((-0.07, 0.0, 0.07)):
        parts.append(make_part(f"pedal_{i}", "pedal",
                               S.box((0.025, 0.12, 0.012), center=(x, y_ped + 0.06, z_ped)), brass))
    return parts


@register("pool_table", parts=("playing_surface", "rail", "leg"), extra_parts=("pocket", "body", "ball", "sight"),
          size_range=(1.8, 3.0), density=700, variants=("four_leg", "six_leg", "pedestal"))
def pool_table(rng: np.random.Generator, variant: str) -> list[Part]:
    pl = rng.uniform(1.8, 2.54) if variant != "four_leg" else rng.uniform(1.6, 2.0)  # play field length
    pw = pl / 2
    rail_w, h = rng.uniform(0.12, 0.16), rng.uniform(0.76, 0.8)
    wood, cloth, pocket_m = M.wood(rng), felt(rng), black("leather")
    slab_t, apron = 0.05, 0.18
    z_play = h - 0.04  # the cushions stand 4 cm above the cloth
    W, D = pl + 2 * rail_w, pw + 2 * rail_w
    parts = [make_part("playing_surface", "playing_surface",
                       S.box((pl, pw, slab_t), center=(0, 0, z_play - slab_t / 2)), cloth),
             make_part("body", "body", S.box((W - 0.04, D - 0.04, apron), center=(0, 0, z_play - slab_t - apron / 2),
                                             bevel=0.01), wood)]
    pr = 0.06
    for i, (L, c, along_x) in enumerate([(pl, (0, -pw / 2 - rail_w / 2), True), (pl, (0, pw / 2 + rail_w / 2), True),
                                         (pw, (-pl / 2 - rail_w / 2, 0), False), (pw, (pl / 2 + rail_w / 2, 0), False)]):
        inward = -np.sign(c[1]) if along_x else -np.sign(c[0])
        Lr = L - 2 * pr
        wood_sz = (Lr + 2 * rail_w if along_x else rail_w, rail_w if along_x else Lr + 2 * rail_w, 0.05)
        top = S.box(wood_sz, center=(c[0], c[1], h - 0.025), bevel=0.008)
        # the cushion: a sloped rubber nose on the inner edge of the rail
        e = (c[1] if along_x else c[0]) + inward * rail_w / 2
        a = np.array([-Lr / 2, Lr / 2])
        pts = []
        for t in a:
            for off, z in ((0.0, z_play), (0.0, h - 0.002), (inward * 0.04, h - 0.02), (inward * 0.04, h - 0.032)):
                pts.append([t, e + off, z] if along_x else [e + off, t, z])
        pts = np.array(pts)
        pts[:, 2] = np.maximum(pts[:, 2], z_play)
        cushion = S.hull(pts)
        parts.append(make_part(f"rail_{i}", "rail", [top, cushion], wood))
    for i, (x, y) in enumerate([(sx * pl / 2, sy * pw / 2) for sy in (-1, 1) for sx in (-1, 0, 1)]):
        cup = S.cylinder(pr, 0.1, center=(x, y, z_play + 0.001 - 0.05), sections=16)
        parts.append(make_part(f"pocket_{i}", "pocket", cup, pocket_m))
    # the eighteen diamond sights inlaid flush in the rail tops, three between each pair of
    # pockets
    pearl = M.solid((0.93, 0.92, 0.88), "plastic", 0.2)
    sights = [(pl * f, sy * (pw / 2 + rail_w / 2)) for sy in (-1, 1) for f in (-0.375, -0.25, -0.125, 0.125, 0.25, 0.375)]
    sights += [(sx * (pl / 2 + rail_w / 2), pw * f) for sx in (-1, 1) for f in (-0.25, 0.0, 0.25)]
    parts += [make_part(f"sight_{k}", "sight", S.box((0.012, 0.012, 0.0015), center=(x, y, h - 0.00075), R=axis_angle((0, 0, 1), np.pi / 4)),
                        pearl) for k, (x, y) in enumerate(sights)]
    # a racked set of sixteen balls: fifteen in the triangle at the foot spot, the cue ball
    br = 0.0286
    ball_cols = [(0.95, 0.8, 0.1), (0.1, 0.2, 0.7), (0.8, 0.1, 0.1), (0.4, 0.1, 0.5), (0.95, 0.45, 0.1),
                 (0.1, 0.5, 0.2), (0.5, 0.15, 0.1), (0.05, 0.05, 0.05)]
    k = 0
    for row in range(5):
        for j in range(row + 1):
            x = pl / 4 + row * br * 1.74
            y = (j - row / 2) * br * 2.01
            parts.append(make_part(f"ball_{k}", "ball", S.ellipsoid((br, br, br), center=(x, y, z_play + br), subdivisions=1),
                                   M.solid(ball_cols[k % 8], "plastic", 0.15)))
            k += 1
    parts.append(make_part("ball_cue", "ball", S.ellipsoid((br, br, br), center=(-pl / 4, 0.0, z_play + br), subdivisions=1),
                           M.solid((0.96, 0.95, 0.9), "plastic", 0.15)))
    z_leg = z_play - slab_t - apron
    if variant == "pedestal":
        for i, x in enumerate((-W * 0.28, W * 0.28)):
            plinth = S.box((0.3, D * 0.7, z_leg), center=(x, 0, z_leg / 2), bevel=0.02)
            foot = S.box((0.4, D * 0.8, 0.08), center=(x, 0, 0.04), bevel=0.02)
            parts.append(make_part(f"leg_{i}", "leg", [plinth, foot], wood))
    else:
        xs = (-W / 2 + 0.15, W / 2 - 0.15) if variant == "four_leg" else (-W / 2 + 0.15, 0.0, W / 2 - 0.15)
        k = 0
        for y in (-D / 2 + 0.15, D / 2 - 0.15):
            for x in xs:
                leg = S.lathe([(0.08, 0.0), (0.05, 0.1), (0.065, z_leg * 0.5), (0.045, z_leg * 0.85),
                               (0.06, z_leg)], sections=14)
                parts.append(make_part(f"leg_{k}", "leg", leg.moved((x, y, 0)), wood))
                k += 1
    return parts


@register("coat_rack", parts=("base", "pole", "hook"), extra_parts=("finial", "tip", "collar"), size_range=(1.5, 2.0),
          density=650, variants=("tripod", "disc", "tree"))
def coat_rack(rng: np.random.Generator, variant: str) -> list[Part]:
    h = rng.uniform(1.6, 1.9)
    mat = M.wood(rng) if rng.random() < 0.6 else M.metal(rng)
    hmat = mat if rng.random() < 0.5 else M.metal(rng)
    r_pole = rng.uniform(0.018, 0.025)
    if variant == "disc":
        rb = rng.uniform(0.16, 0.22)
        base = S.lathe([(rb, 0.0), (rb, 0.015), (rb * 0.85, 0.035), (r_pole * 1.6, 0.06), (r_pole * 1.3, 0.08)],
                       sections=32)
        z_pole = 0.07
    else:
        legs = []
        n_legs = 3 if variant == "tripod" else 4
        reach = rng.uniform(0.22, 0.3)
        for k in range(n_legs):
            a = 2 * np.pi * k / n_legs + np.pi / 2
            dx, dy = np.cos(a), np.sin(a)
            path = [[dx * r_pole * 0.5, dy * r_pole * 0.5, 0.28], [dx * reach * 0.6, dy * reach * 0.6, 0.08],
                    [dx * reach, dy * reach, 0.015]]
            legs.append(S.tube(path, 0.015, sections=8))
            legs.append(S.cylinder(0.02, 0.015, center=(dx * reach, dy * reach, 0.0075), sections=10))
        base = S.union(legs)
        z_pole = 0.0
    parts = [make_part("base", "base", base, mat),
             make_part("pole", "pole", S.cylinder(r_pole, h - 0.05 - z_pole, center=(0, 0, z_pole + (h - 0.05 - z_pole) / 2),
                                                   sections=16), mat),
             make_part("finial", "finial", S.lathe([(r_pole, 0.0), (r_pole * 1.5, 0.02), (r_pole * 1.2, 0.04),
                                                   (0.004, 0.05)], sections=16).moved((0, 0, h - 0.05)), mat)]
    n_hooks = int(rng.integers(4, 7)) if variant != "tree" else int(rng.integers(6, 9))
    for k in range(n_hooks):
        a = 2 * np.pi * k / n_hooks + np.pi / 2
        dx, dy = np.cos(a), np.sin(a)
        z0 = h - 0.12 - (0.12 if variant == "tree" and k % 2 else 0.0)
        if variant == "tree":  # long curved branches ending in a ball
            t = np.linspace(0, 1, 5)
            rr = r_pole * 0.5 + 0.2 * t
            zz = z0 - 0.02 + 0.18 * t ** 2
            path = np.c_[dx * rr, dy * rr, zz]
            shapes = [S.tube(path, 0.011, sections=8)]
            # the turned ball glued on the branch's end, a tip as on the other racks' hooks
            parts.append(make_part(f"tip_{k}", "tip", S.ellipsoid((0.018, 0.018, 0.018), center=path[-1], subdivisions=1), hmat))
        else:  # a J-hook: out and down, then curling back up
            t = np.linspace(0, np.pi, 4)
            path = np.vstack([[dx * r_pole * 0.5, dy * r_pole * 0.5, z0], [dx * (r_pole + 0.06), dy * (r_pole + 0.06), z0],
                              np.c_[dx * (r_pole + 0.06 + 0.03 * np.sin(t)), dy * (r_pole + 0.06 + 0.03 * np.sin(t)),
                                    z0 - 0.03 * (1 - np.cos(t))][1:]])
            shapes = [S.tube(path, 0.007, sections=8)]
            # the ball tip that keeps a coat from slipping off the hook
            parts.append(make_part(f"tip_{k}", "tip", S.ellipsoid((0.011, 0.011, 0.011), center=path[-1], subdivisions=1), hmat))
        parts.append(make_part(f"hook_{k}", "hook", shapes, hmat))
    # the collars where the hooks ring the pole and where the pole meets its base
    parts.append(make_part("collar", "collar", S.cylinder(r_pole * 1.5, 0.03, center=(0, 0, h - 0.12), sections=12), hmat))
    parts.append(make_part("collar_1", "collar", S.cylinder(r_pole * 1.6, 0.05, center=(0, 0, (z_pole if z_pole else 0.26) + 0.025),
                                                            sections=12), mat))
    return parts
