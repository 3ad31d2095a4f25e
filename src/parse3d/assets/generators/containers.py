"""Containers: baskets, storage boxes, buckets, trash cans and laundry baskets.

Every container is built so that :func:`parse3d.assets.internal.find_internal_surfaces` finds a
support surface on its ``body`` (the inner floor): open containers wall it on every side,
lidded ones (storage box, pedal bin) cover it with the ``lid`` part.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import arc, open_box, ring, shell
from ._kit import OPEN_DOOR, hinge_parts, revolute, rot


def _wicker(rng: np.random.Generator) -> Material:
    rgb = [(0.72, 0.58, 0.38), (0.55, 0.40, 0.25), (0.82, 0.72, 0.55), (0.35, 0.25, 0.18)]
    return Material(M.jitter(rng, rgb[int(rng.integers(len(rgb)))], 0.03), 0.9, 0.0, "wood")


def _hoops(r_at, zs, *, bulge: float, width: float, sections: int = 20) -> list[S.Shape]:
    """Horizontal hoops (woven bands) around a round wall whose outer radius at height z is
    ``r_at(z)``; each hoop overlaps the wall by half its bulge so it reads as woven rows."""
    out = []
    for z in zs:
        r0 = r_at(z) - bulge
        out.append(ring([(r0, z - width / 2), (r0 + 2 * bulge, z - width / 4),
                         (r0 + 2 * bulge, z + width / 4), (r0, z + width / 2)],
                        sections=sections))
    return out


@register("basket", parts=("body",), extra_parts=("handle", "slat", "band", "rim", "stake", "post", "foot_ring", "lashing"),
          size_range=(0.18, 0.46),
          density=500, variants=("round", "rectangular", "handled"), placement="surface")
def basket(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = _wicker(rng)
    parts = []
    if variant == "rectangular":
        w, d = rng.uniform(0.26, 0.38), rng.uniform(0.18, 0.26)
        h = rng.uniform(0.1, 0.16)
        t = 0.008
        flare = rng.uniform(0.01, 0.02)
        shapes = open_box(w, d, h, t, taper=flare)
        parts.append(make_part("body", "body", shapes, mat))
        # woven rows: thin bevelled slats proud of the front and back walls
        for k, z in enumerate(np.linspace(0.025, h - 0.02, 3)):
            g = flare * z / h
            for i, sy in enumerate((1, -1)):
                slat = S.box((w + 2 * g - 0.01, 0.006, 0.018),
                             center=(0, sy * (d / 2 + g + 0.001), z), bevel=0.002)
                parts.append(make_part(f"slat_{2 * k + i}", "slat", slat, mat))
        # the corner posts the weave is worked round, and the wrapped border along the top
        for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"post_{k}", "post", S.hull(np.array(
                [[sx * (w / 2 + dx), sy * (d / 2 + dy), 0.0] for dx in (0.0, 0.006) for dy in (0.0, 0.006)]
                + [[sx * (w / 2 + flare + dx), sy * (d / 2 + flare + dy), h] for dx in (0.0, 0.006) for dy in (0.0, 0.006)])), mat))
        bt = 0.012
        border = [S.box((w + 2 * flare + 0.012, bt, bt), center=(0, sy * (d / 2 + flare), h - bt / 2)) for sy in (-1, 1)]
        border += [S.box((bt, d + 2 * flare - bt, bt), center=(sx * (w / 2 + flare), 0, h - bt / 2)) for sx in (-1, 1)]
        parts.append(make_part("rim", "rim", border, mat))
        top = h
        span = d / 2 + flare - 0.01
    else:
        r = rng.uniform(0.1, 0.16)
        h = r * rng.uniform(0.6, 0.9)
        prof = [(r * 0.78, 0.0), (r, h)]

        def r_at(z: float) -> float:
            return float(np.interp(z, [0.0, h], [r * 0.78, r]))

        body = shell(prof, 0.007, bottom=0.01, sections=16)
        hoops = _hoops(r_at, np.linspace(h * 0.25, h * 0.65, 2), bulge=0.003, width=0.025,
                       sections=16)
        rim = ring([(r - 0.01, h - 0.004), (r + 0.004, h - 0.004), (r + 0.004, h + 0.006),
                    (r - 0.01, h + 0.006)], sections=16)
        parts.append(make_part("body", "body", body, mat))
        parts += [make_part(f"band_{i}", "band", hp, mat) for i, hp in enumerate(hoops)]
        parts.append(make_part("rim", "rim", rim, mat))
        # the stakes the weave runs round, standing proud of the wall, and the foot ring
        for k, a in enumerate(np.linspace(0, 2 * np.pi, 12, endpoint=False) + np.pi / 12):
            d0, d1 = np.array([np.cos(a), np.sin(a)]) * (r * 0.78 + 0.002), np.array([np.cos(a), np.sin(a)]) * (r + 0.002)
            parts.append(make_part(f"stake_{k}", "stake", S.tube([(*d0, 0.012), (*d1, h - 0.006)], 0.003, sections=6), mat))
        parts.append(make_part("foot_ring", "foot_ring", ring([(r * 0.78 - 0.008, 0.0), (r * 0.78 + 0.004, 0.0),
                                                               (r * 0.78 + 0.004, 0.012), (r * 0.78 - 0.008, 0.012)],
                                                              sections=16), mat))
        top = h + 0.006
        span = r - 0.01
    if variant == "handled" or (variant == "rectangular" and rng.random() < 0.5):
        rise = rng.uniform(0.12, 0.18)
        # the handle arches from the front rim to the back rim, straight over the middle
        path = arc((0, 0, top - 0.03), span, 0.0, np.pi, n=9, u=(0, 1, 0),
                   squash=(rise + 0.03) / span)
        parts.append(make_part("handle", "handle", S.tube(path, 0.008, sections=8), mat))
        # the cane lashing wrapped round each handle end where it is bound to the rim
        parts += [make_part(f"lashing_{k}", "lashing", S.cylinder(0.012, 0.03, center=tuple(p), axis=tuple(q - p), sections=8), mat)
                  for k, (p, q) in enumerate(((path[1], path[2]), (path[-2], path[-3])))]
    return parts


@register("storage_box", parts=("body", "lid"),
          extra_parts=("handle", "label", "latch", "hinge", "hasp", "tape", "foot", "hand_hole", "staple", "corner"),
          size_range=(0.2, 0.7),
          density=700, variants=("plastic_bin", "wooden", "cardboard"), placement="surface")
def storage_box(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.3, 0.6)
    d = w * rng.uniform(0.6, 0.8)
    h = rng.uniform(0.16, 0.32)
    taper = 0.0
    if variant == "plastic_bin":
        mat, lid_mat = M.plastic(rng), M.plastic(rng)
        t, taper = 0.004, rng.uniform(0.01, 0.02)
        walls = open_box(w, d, h, t, taper=taper)
        tw, td = w + 2 * taper, d + 2 * taper
    else:
        mat = M.wood(rng) if variant == "wooden" else M.paper(rng)
        lid_mat = mat
        t = 0.012 if variant == "wooden" else 0.004
        walls = open_box(w, d, h, t, bevel=0.002 if variant == "wooden" else 0.0)
        tw, td = w, d
    parts = [make_part("body", "body", walls, mat)]
    # the lid overhangs the walls a little and drops a skirt around them
    lt = 0.008 if variant != "cardboard" else 0.004
    ov = 0.004
    lid = [S.box((tw + 2 * ov, td + 2 * ov, lt), center=(0, 0, h + lt / 2), bevel=lt / 4)]
    skirt = 0.025 if variant != "wooden" else 0.0
    if skirt:
        st = 0.003
        lid += [S.box((tw + 2 * ov, st, skirt), center=(0, s * (td / 2 + ov - st / 2), h - skirt / 2))
                for s in (1, -1)]
        lid += [S.box((st, td + 2 * ov - 2 * st, skirt),
                      center=(s * (tw / 2 + ov - st / 2), 0, h - skirt / 2)) for s in (1, -1)]
    parts.append(make_part("lid", "lid", lid, lid_mat))
    # the lid lifts on its back edge (the box's hinge line or, for a loose lid, where it pivots)
    parts.append(revolute("lid_hinge", "body", "lid", axis=(1, 0, 0), origin=(0, -(td / 2 + ov), h), opens=OPEN_DOOR))
    if variant != "cardboard":
        # a grip on each side (x), below the lid
        for i, sx in enumerate((1, -1)):
            x = sx * (tw / 2 + (ov + 0.003 if skirt else 0.0))
            zg = h - skirt - 0.03
            grip = S.box((0.02, min(0.12, d * 0.4), 0.014), center=(x + sx * 0.008, 0, zg), bevel=0.003)
            parts.append(make_part(f"handle_{i}", "handle", grip, lid_mat if variant == "plastic_bin" else M.metal(rng)))
    # the label card on the front wall (which leans out by half the taper at mid height)
    zl = h * 0.45
    yl = d / 2 + taper * zl / h
    parts.append(make_part("label", "label", S.box((min(0.09, w * 0.3), 0.0015, 0.05),
                                                   center=(0, yl + 0.00075, zl)), M.paper(rng)))
    if variant == "plastic_bin":
        # two clip latches on the front, under the lid's skirt, that snap the lid shut
        z0 = h - skirt - 0.03
        y0, y1 = d / 2 + taper * z0 / h, td / 2 + ov + 0.004
        for i, sx in enumerate((-1, 1)):
            parts.append(make_part(f"latch_{i}", "latch",
                                   S.box((0.04, y1 - y0, 0.031), center=(sx * tw * 0.3, (y0 + y1) / 2,
                                                                         z0 + 0.0155), bevel=0.002),
                                   lid_mat))
    elif variant == "wooden":
        # the lid's two butt hinges on the back edge and the hasp on the front
        metal = M.metal(rng)
        parts += hinge_parts("hinge", x=h, y=-(td / 2 + ov), z0=-w / 2, z1=w / 2, mat=metal,
                             radius=0.005, length=0.05, axis="x")
        parts.append(make_part("hasp", "hasp", S.box((0.03, 0.004, 0.05),
                                                     center=(0, d / 2 + 0.002, h - 0.02)), metal))
        # the staple the hasp drops over, and the brass corner guards on the lid's corners
        parts.append(make_part("staple", "staple", S.box((0.012, 0.008, 0.02), center=(0, d / 2 + 0.004 + 0.002, h - 0.045)), metal))
        parts += [make_part(f"corner_{k}", "corner", S.box((0.03, 0.03, lt + 0.002), center=(sx * (tw / 2 + ov - 0.015), sy * (td / 2 + ov - 0.015),
                                                                                           h + (lt + 0.002) / 2 - 0.002)),
                            M.solid((0.78, 0.62, 0.3), "metal", 0.3, 0.9))
                  for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)])]
    else:
        # the packing tape along the lid's front edge, down onto the front wall
        tape = Material(M.jitter(rng, (0.75, 0.6, 0.4), 0.03)[:3] + (0.8,), 0.3, 0.0, "plastic")
        parts.append(make_part("tape", "tape", S.box((0.05, 0.001, 0.04),
                                                     center=(0, d / 2 + 0.0005, h - skirt - 0.02)), tape))
        # the punched hand holes in the two ends, below the lid's skirt
        parts += [make_part(f"hand_hole_{k}", "hand_hole", S.box((0.001, 0.09, 0.025), center=(sx * (w / 2 + 0.0005), 0, h - skirt - 0.035)),
                            M.solid((0.2, 0.15, 0.1), "paper", 0.9)) for k, sx in enumerate((-1, 1))]
    if variant != "cardboard":  # four feet set into the floor's underside
        pad = Material((0.1, 0.1, 0.1, 1.0), 0.8, 0.0, "rubber")
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"foot_{i}", "foot", S.cylinder(0.01, 0.003, center=(sx * (w / 2 - 0.03), sy * (d / 2 - 0.03), 0.0015),
                                                                  sections=8), pad))
    return parts


@register("bucket", parts=("body", "handle"), extra_parts=("grip", "rim", "band", "ear", "spout", "foot_ring", "rivet", "rib"),
          size_range=(0.22, 0.42),
          density=900, variants=("metal", "plastic"), placement="surface")
def bucket(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.12, 0.15)
    h = rng.uniform(0.24, 0.3)
    rb = r * rng.uniform(0.75, 0.85)
    mat = M.metal(rng) if variant == "metal" else M.plastic(rng)
    t = 0.002 if variant == "metal" else 0.004

    def r_at(z: float) -> float:
        return float(np.interp(z, [0.0, h], [rb, r]))

    parts = [make_part("body", "body", shell([(rb, 0.0), (r, h)], t, bottom=0.004, sections=20), mat)]
    # a rolled rim and, on metal buckets, a pressed hoop
    rim = ring([(r - t, h - 0.008), (r + 0.004, h - 0.006), (r + 0.004, h + 0.002),
                (r - t, h + 0.002)], sections=20)
    parts.append(make_part("rim", "rim", rim, mat))
    if variant == "metal":  # two pressed hoops stiffening the wall
        hoops = _hoops(r_at, [h * 0.45, h * 0.2], bulge=0.002, width=0.014)
        parts += [make_part(f"band_{i}", "band", hp, mat) for i, hp in enumerate(hoops)]
        # each ear riveted to the wall, a rivet above and below the pivot
        for i, sx in enumerate((1, -1)):
            x = sx * (r_at(h - 0.03) + 0.0105)
            parts += [make_part(f"rivet_{2 * i + j}", "rivet", S.cylinder(0.0035, 0.002, center=(x, 0, h - 0.03 + dz), axis=(1, 0, 0),
                                                                          sections=8), mat) for j, dz in enumerate((-0.01, 0.01))]
    else:  # the moulded ribs under the rim that stiffen it, between the ears
        for k, a in enumerate(np.linspace(0, 2 * np.pi, 8, endpoint=False) + np.pi / 8):
            rr = r_at(h - 0.025)
            parts.append(make_part(f"rib_{k}", "rib", S.box((0.008, 0.004, 0.03), center=(np.cos(a) * (rr + 0.0015), np.sin(a) * (rr + 0.0015),
                                                                                          h - 0.025), R=rot((0, 0, 1), a)), mat))
    # the ears the handle pivots in
    for i, sx in enumerate((1, -1)):
        ear = S.box((0.012, 0.03, 0.03), center=(sx * (r_at(h - 0.03) + 0.004), 0, h - 0.03))
        parts.append(make_part(f"ear_{i}", "ear", ear, mat))
    # the wire handle pivots on the ears and has fallen towards the back (-Y), so the opening
    # stays free
    tilt = np.deg2rad(rng.uniform(40, 70))
    span = r_at(h - 0.03) + 0.012
    up = np.array([0.0, -np.sin(tilt), np.cos(tilt)])
    path = arc((0, 0, h - 0.03), span, 0.0, np.pi, n=11, u=(1, 0, 0), v=up, squash=0.9)
    parts.append(make_part("handle", "handle", S.tube(path, 0.0025, sections=8), M.metal(rng)))
    mid = path[len(path) // 2]
    grip = S.cylinder(0.008, 0.1, center=mid, axis=(1, 0, 0), sections=10)
    parts.append(make_part("grip", "grip", grip, M.plastic(rng)))
    # the rolled foot ring it stands on, and (plastic) the pouring lip on the front
    parts.append(make_part("foot_ring", "foot_ring", ring([(rb - 0.006, 0.0), (rb + 0.003, 0.0), (rb + 0.003, 0.01),
                                                           (rb - 0.006, 0.01)], sections=20), mat))
    if variant == "plastic":
        parts.append(make_part("spout", "spout", S.hull(np.array(
            [[sx * 0.03, r_at(h - 0.04) - 0.002, h - 0.04] for sx in (-1, 1)]
            + [[sx * 0.035, r + 0.004, h + 0.002] for sx in (-1, 1)] + [[0, r + 0.02, h + 0.002]]
            + [[sx * 0.035, r - 0.004, h + 0.002] for sx in (-1, 1)])), mat))
    return parts


@register("trash_can", parts=("body",),
          extra_parts=("lid", "pedal", "rim", "liner", "base", "label", "hinge", "lid_handle", "handle", "rod", "damper"),
          size_range=(0.28, 0.8),
          density=900, variants=("round", "square", "pedal"), placement="floor")
def trash_can(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.metal(rng) if variant == "pedal" or rng.random() < 0.4 else M.plastic(rng)
    parts = []
    if variant == "square":
        w = rng.uniform(0.26, 0.34)
        h = rng.uniform(0.4, 0.65)
        d = w * rng.uniform(0.7, 0.9)
        taper = rng.uniform(0.01, 0.025)
        body = open_box(w, d, h, 0.004, bottom=0.008, taper=taper)
        parts.append(make_part("body", "body", body, mat))
        tw, td = w + 2 * taper, d + 2 * taper
        # the rolled rim round the top, the bin bag folded over it, the bumper round the foot
        rt = 0.008
        rim = [S.box((tw + 2 * rt, rt, 0.012), center=(0, sy * (td / 2 + rt / 2 - 0.004), h - 0.006))
               for sy in (1, -1)]
        rim += [S.box((rt, td - 0.008, 0.012), center=(sx * (tw / 2 + rt / 2 - 0.004), 0, h - 0.006))
                for sx in (1, -1)]
        parts.append(make_part("rim", "rim", rim, mat))
        lt, ld = 0.0015, 0.05
        bag = [S.box((tw + 2 * rt + 2 * lt, lt, ld), center=(0, sy * (td / 2 + rt - 0.004 + lt / 2), h - ld / 2))
               for sy in (1, -1)]
        bag += [S.box((lt, td + 2 * rt - 0.008, ld), center=(sx * (tw / 2 + rt - 0.004 + lt / 2), 0, h - ld / 2))
                for sx in (1, -1)]
        parts.append(make_part("liner", "liner", bag, _bag_material(rng)))
        bh = 0.02
        base = [S.box((w + 0.006, 0.003, bh), center=(0, sy * (d / 2 + 0.0015), bh / 2)) for sy in (1, -1)]
        base += [S.box((0.003, d, bh), center=(sx * (w / 2 + 0.0015), 0, bh / 2)) for sx in (1, -1)]
        parts.append(make_part("base", "base", base, M.plastic(rng)))
        zl = h * 0.55
        parts.append(make_part("label", "label", S.box((0.06, 0.001, 0.06),
                                                       center=(0, d / 2 + taper * zl / h + 0.0005, zl)),
                               M.paper(rng)))
        # a moulded hand grip on each side, under the rim
        zg = h - 0.06
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"handle_{k}", "handle", S.box((0.012, d * 0.35, 0.02),
                                                                 center=(sx * (w / 2 + taper * zg / h + 0.006), 0, zg), bevel=0.003),
                                   mat))
        return parts
    r = rng.uniform(0.13, 0.18)
    h = rng.uniform(0.35, 0.6) if variant == "round" else rng.uniform(0.4, 0.65)
    rb = r * (rng.uniform(0.8, 0.9) if variant == "round" else 1.0)
    body = shell([(rb, 0.0), (r, h)], 0.004, bottom=0.008, sections=20)
    rim = ring([(r - 0.004, h - 0.012), (r + 0.004, h - 0.01), (r + 0.004, h),
                (r - 0.004, h)], sections=20)
    parts.append(make_part("body", "body", body, mat))
    parts.append(make_part("rim", "rim", rim, mat))
    # the bumper ring round the foot and the label on the front
    parts.append(make_part("base", "base", ring([(rb - 0.002, 0.0), (rb + 0.004, 0.0), (rb + 0.004, 0.02),
                                                 (rb - 0.002, 0.02)], sections=20), M.plastic(rng)))
    zl = h * 0.55
    rl = rb + (r - rb) * zl / h
    parts.append(make_part("label", "label", S.box((0.06, 0.001, 0.06), center=(0, rl + 0.0003, zl)),
                           M.paper(rng)))
    if variant == "pedal":
        lid = S.lathe([(r + 0.006, h), (r + 0.006, h + 0.008), (r * 0.9, h + r * 0.2),
                       (r * 0.3, h + r * 0.27)], sections=28)
        parts.append(make_part("lid", "lid", lid, mat))
        pedal = S.box((0.1, 0.06, 0.02), center=(0, r + 0.025, 0.03), bevel=0.004)
        parts.append(make_part("pedal", "pedal", pedal, M.plastic(rng)))
        # the lid's hinge at the back, its lifting tab at the front, the removable inner bucket
        parts.append(make_part("hinge", "hinge", S.box((0.05, 0.012, 0.016), center=(0, -r - 0.004, h - 0.002)),
                               M.plastic(rng)))
        parts.append(make_part("lid_handle", "lid_handle",
                               S.box((0.04, 0.012, 0.006), center=(0, r + 0.009, h + 0.004)), mat))
        bucket = shell([(r - 0.012, 0.012), (r - 0.006, h - 0.004)], 0.002, bottom=0.002, sections=20)
        parts.append(make_part("liner", "liner", bucket, M.plastic(rng)))
        # the inner bucket's carrying bail folded down inside its rim, the rod from the pedal up
        # the back to the lid, and the soft-close damper beside the hinge
        parts.append(make_part("handle", "handle", S.tube([(-(r - 0.02), 0, h - 0.012), (0, -(r - 0.03) * 0.3, h - 0.01),
                                                           ((r - 0.02), 0, h - 0.012)], 0.0025, sections=6), M.metal(rng)))
        parts.append(make_part("rod", "rod", S.cylinder(0.004, h - 0.06, center=(0, -r - 0.001, 0.03 + (h - 0.06) / 2), sections=8),
                               M.metal(rng)))
        parts.append(make_part("damper", "damper", S.cylinder(0.008, 0.05, center=(0.045, -r + 0.002, h - 0.04), sections=10),
                               M.plastic(rng)))
    else:
        # the bin bag folded over the rim, and a moulded hand grip each side under it
        parts.append(make_part("liner", "liner", ring([(r + 0.004, h - 0.05), (r + 0.0055, h - 0.05),
                                                       (r + 0.0055, h), (r + 0.004, h)], sections=20),
                               _bag_material(rng)))
        zg = h - 0.07
        rg = rb + (r - rb) * zg / h
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"handle_{k}", "handle", S.box((0.014, 0.08, 0.02), center=(sx * (rg + 0.005), 0, zg), bevel=0.003),
                                   mat))
    return parts


def _bag_material(rng) -> Material:
    return Material(M.jitter(rng, (0.12, 0.12, 0.13), 0.03), 0.4, 0.0, "plastic")


@register("laundry_basket", parts=("body",), extra_parts=("handle", "rib", "band", "rim", "foot_ring"), size_range=(0.35, 0.72),
          density=900, variants=("rectangular", "round"), placement="floor")
def laundry_basket(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.plastic(rng) if rng.random() < 0.6 else _wicker(rng)
    parts = []
    if variant == "rectangular":
        w, d = rng.uniform(0.5, 0.62), rng.uniform(0.36, 0.44)
        h = rng.uniform(0.25, 0.32)
        t = 0.006
        slot_w, slot_h = 0.11, 0.035
        z_slot = h - 0.025 - slot_h / 2
        shapes = [S.box((w, t, h), center=(0, s * (d / 2 - t / 2), h / 2), bevel=0.002)
                  for s in (1, -1)]
        shapes.append(S.box((w - 2 * t, d - 2 * t, t), center=(0, 0, t / 2)))
        # the side walls (x) have a hand-hold slot cut through them near the top
        inner_d = d - 2 * t
        for s in (1, -1):
            x = s * (w / 2 - t / 2)
            z_lo, z_hi = z_slot - slot_h / 2, z_slot + slot_h / 2
            side = (inner_d - slot_w) / 2
            for sy in (1, -1):
                shapes.append(S.box((t, side, h), center=(x, sy * (slot_w + side) / 2, h / 2)))
            # below the slot: chamfered so the slot's sill is no shelf of its own
            shapes.append(S.box((t, slot_w, z_lo), center=(x, 0, z_lo / 2), bevel=0.002))
            shapes.append(S.box((t, slot_w, h - z_hi), center=(x, 0, (h + z_hi) / 2)))
        parts.append(make_part("body", "body", shapes, mat))
        # moulded vertical ribs on the front and back
        for i, s in enumerate((1, -1)):
            for k, x in enumerate(np.linspace(-w * 0.38, w * 0.38, 6)):
                rib = S.box((0.014, 0.004, h * 0.7), center=(x, s * (d / 2 + 0.002), h * 0.45))
                parts.append(make_part(f"rib_{6 * i + k}", "rib", rib, mat))
        # two more on each end either side of the hand hold (below it), and the rolled rim round the top
        for i, s in enumerate((1, -1)):
            for k, sy in enumerate((-1, 1)):
                rib = S.box((0.004, 0.014, z_slot - slot_h / 2 - 0.03), center=(s * (w / 2 + 0.002), sy * inner_d * 0.35, (z_slot - slot_h / 2) / 2))
                parts.append(make_part(f"rib_{12 + 2 * i + k}", "rib", rib, mat))
        rim = [S.box((w + 0.008, 0.01, 0.012), center=(0, sy * (d / 2 - 0.001), h - 0.006)) for sy in (-1, 1)]
        rim += [S.box((0.01, d - 0.012, 0.012), center=(sx * (w / 2 - 0.001), 0, h - 0.006)) for sx in (-1, 1)]
        parts.append(make_part("rim", "rim", rim, mat))
        return parts
    r = rng.uniform(0.2, 0.26)
    h = rng.uniform(0.3, 0.45)
    rb = r * 0.88

    def r_at(z: float) -> float:
        return float(np.interp(z, [0.0, h], [rb, r]))

    body = shell([(rb, 0.0), (r, h)], 0.006, bottom=0.008, sections=20)
    parts.append(make_part("body", "body", body, mat))
    hoops = _hoops(r_at, np.linspace(h * 0.25, h * 0.7, 2), bulge=0.003, width=0.03, sections=20)
    parts += [make_part(f"band_{i}", "band", hp, mat) for i, hp in enumerate(hoops)]
    for i, sx in enumerate((1, -1)):
        grip = S.tube(arc((sx * (r - 0.002), 0, h - 0.05), 0.06, 0.0, np.pi, n=7,
                          u=(0, 1, 0), v=(sx, 0, 0), squash=0.45), 0.008, sections=8)
        parts.append(make_part(f"handle_{i}", "handle", grip, mat))
    # the rolled rim round the top and the foot ring it stands on
    parts.append(make_part("rim", "rim", ring([(r - 0.006, h - 0.012), (r + 0.005, h - 0.01), (r + 0.005, h), (r - 0.006, h)],
                                              sections=20), mat))
    parts.append(make_part("foot_ring", "foot_ring", ring([(rb - 0.008, 0.0), (rb + 0.003, 0.0), (rb + 0.003, 0.012),
                                                           (rb - 0.008, 0.012)], sections=20), mat))
    # moulded vertical ribs round the wall between the bands, clear of the handles
    for k, a in enumerate(np.linspace(0, 2 * np.pi, 8, endpoint=False) + np.pi / 8):
        zc = h * 0.475
        rr = r_at(zc)
        parts.append(make_part(f"rib_{k}", "rib", S.box((0.004, 0.014, h * 0.3), center=(np.cos(a) * (rr + 0.002), np.sin(a) * (rr + 0.002), zc),
                                                        R=rot((0, 0, 1), a)), mat))
    return parts
