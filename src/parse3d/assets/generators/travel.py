"""Hotels and dormitories: suitcases, luggage racks, bed benches, backpacks and handbags.

A suitcase stands on its wheels with its telescoping handle at the back top; a luggage rack's
straps are separate ``strap`` parts whose tops carry the bag (``ON luggage_rack:strap``).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._casework import black
from ._kit import legs4
from ._rods import leg_caps


@register("suitcase", parts=("shell",), extra_parts=("handle", "wheel", "zipper", "corner", "trolley_handle", "pull", "lock", "tag",
                                                     "foot", "side_handle", "latch", "wheel_housing", "sleeve", "button",
                                                     "hinge"),
          size_range=(0.45, 0.95), density=180, variants=("spinner", "two_wheel", "hard_trunk"), placement="floor")
def suitcase(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.36, 0.5), rng.uniform(0.2, 0.3), rng.uniform(0.52, 0.78)
    if variant == "hard_trunk":
        w, d, h = rng.uniform(0.6, 0.8), rng.uniform(0.35, 0.45), rng.uniform(0.35, 0.45)
    shell_mat = M.solid(M.jitter(rng, [(0.1, 0.1, 0.12), (0.15, 0.25, 0.5), (0.6, 0.12, 0.12), (0.75, 0.75, 0.78),
                                       (0.45, 0.3, 0.2)][int(rng.integers(5))], 0.03), "plastic", 0.35)
    wz = 0.06 if variant != "hard_trunk" else 0.0
    parts = [make_part("shell", "shell", S.box((w, d, h), center=(0, 0, wz + h / 2), bevel=0.03), shell_mat),
             make_part("zipper", "zipper", S.box((w + 0.004, 0.012, h - 0.04), center=(0, 0, wz + h / 2)), black())]
    if variant == "spinner":
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"wheel_{i}", "wheel", S.cylinder(0.025, 0.02, center=(sx * (w / 2 - 0.04), sy * (d / 2 - 0.04), 0.03),
                                                                     axis=(1, 0, 0), sections=12), black()))
    elif variant == "two_wheel":
        for i, sx in enumerate((-1, 1)):
            parts.append(make_part(f"wheel_{i}", "wheel", S.cylinder(0.03, 0.025, center=(sx * (w / 2 - 0.04), -d / 2 + 0.04, 0.03),
                                                                     axis=(1, 0, 0), sections=12), black()))
            parts.append(make_part(f"corner_{i}", "corner", S.box((0.04, 0.04, 0.06), center=(sx * (w / 2 - 0.04), d / 2 - 0.04, 0.03)),
                                   black()))
    else:
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"corner_{i}", "corner", S.box((0.05, 0.05, h), center=(sx * (w / 2 - 0.02), sy * (d / 2 - 0.02), h / 2)),
                                   M.solid((0.7, 0.55, 0.3), "metal", 0.4, 0.8)))
        # two draw latches across the lid's seam on the front, no prouder than the corners
        parts += [make_part(f"latch_{k}", "latch", S.box((0.05, 0.008, 0.07), center=(sx * w * 0.3, d / 2 + 0.001, h * 0.62)),
                            M.solid((0.7, 0.55, 0.3), "metal", 0.4, 0.8)) for k, sx in enumerate((-1, 1))]
    top = wz + h
    # the zip's two pulls meeting at the combination lock, the name tag on the top handle's
    # side and the carry handle on the side
    dark = black()
    parts += [make_part(f"pull_{k}", "pull", S.box((0.012, 0.02, 0.03), center=(w / 2 + 0.004, sy * 0.02, wz + h * 0.6)), dark)
              for k, sy in enumerate((-1, 1))]
    parts.append(make_part("lock", "lock", S.box((0.008, 0.05, 0.03), center=(w / 2 + 0.004, 0, wz + h * 0.7), bevel=0.002),
                           M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8)))
    parts.append(make_part("side_handle", "side_handle", S.tube([(-w / 2 + 0.005, 0, wz + h * 0.4), (-w / 2 - 0.025, 0, wz + h * 0.45),
                                                                 (-w / 2 - 0.025, 0, wz + h * 0.55), (-w / 2 + 0.005, 0, wz + h * 0.6)],
                                                                0.008), dark))
    parts.append(make_part("tag", "tag", S.box((0.06, 0.004, 0.04), center=(0.09, 0.02, top)), M.solid((0.45, 0.3, 0.2), "leather", 0.6)))
    parts.append(make_part("handle", "handle", S.tube([(-0.06, 0, top - 0.005), (-0.06, 0, top + 0.025), (0.06, 0, top + 0.025),
                                                       (0.06, 0, top - 0.005)], 0.01), black()))
    if variant != "hard_trunk":
        tz = rng.uniform(0.03, 0.08)  # retracted
        y = -d / 2 + 0.02
        parts.append(make_part("trolley_handle", "trolley_handle",
                               S.tube([(-w * 0.3, y, top - 0.01), (-w * 0.3, y, top + tz), (w * 0.3, y, top + tz),
                                       (w * 0.3, y, top - 0.01)], 0.011), M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8)))
        # the release button on the trolley's grip, the two sleeves its tubes slide out of on
        # the shell's top, the moulded housing over each wheel, and the four feet on the
        # right side it lies on
        parts.append(make_part("button", "button", S.box((0.04, 0.012, 0.006), center=(0, y, top + tz + 0.012)), dark))
        parts += [make_part(f"sleeve_{k}", "sleeve", S.cylinder(0.016, 0.01, center=(sx * w * 0.3, y, top - 0.004), sections=10), dark)
                  for k, sx in enumerate((-1, 1))]
        wheels = [p for p in parts if p.label == "wheel"]
        for k, p in enumerate(wheels):
            c = p.mesh.bounds.mean(axis=0)
            parts.append(make_part(f"wheel_housing_{k}", "wheel_housing", S.box((0.04, 0.05, 0.012), center=(c[0], c[1], wz - 0.006)),
                                   dark))
        parts += [make_part(f"foot_{k}", "foot", S.cylinder(0.01, 0.006, center=(w / 2 + 0.003, sy * (d / 2 - 0.045), wz + z), axis=(1, 0, 0),
                                                            sections=8), dark)
                  for k, (sy, z) in enumerate((sy, z) for sy in (-1, 1) for z in (0.06, h - 0.06))]
    else:  # the two hinges along the back of the lid's seam
        parts += [make_part(f"hinge_{k}", "hinge", S.box((0.06, 0.006, 0.04), center=(sx * w * 0.3, -d / 2 - 0.001, h * 0.62)),
                            M.solid((0.7, 0.55, 0.3), "metal", 0.4, 0.8)) for k, sx in enumerate((-1, 1))]
    return parts


@register("luggage_rack", parts=("strap", "leg"), extra_parts=("rail", "stretcher", "pivot", "leg_cap", "tack"), size_range=(0.5, 0.8), density=600,
          variants=("folding", "bench"))
def luggage_rack(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.6, 0.75), rng.uniform(0.38, 0.45), rng.uniform(0.5, 0.58)
    frame = M.wood(rng) if rng.random() < 0.6 else M.solid((0.75, 0.65, 0.35), "metal", 0.3, 0.9)
    strap = M.solid(M.jitter(rng, (0.15, 0.15, 0.2), 0.05), "fabric", 0.9)
    parts = []
    if variant == "folding":
        r = 0.014
        for i, sx in enumerate((-1, 1)):
            x = sx * (w / 2 - 0.05)
            parts.append(make_part(f"leg_{2 * i}", "leg", S.tube([(x, -d / 2 + r, r), (x, d / 2 - r, h - r)], r), frame))
            parts.append(make_part(f"leg_{2 * i + 1}", "leg", S.tube([(x + sx * 0.03, d / 2 - r, r), (x + sx * 0.03, -d / 2 + r, h - r)],
                                                                    r), frame))
        for i, sy in enumerate((-1, 1)):
            parts.append(make_part(f"rail_{i}", "rail", S.cylinder(r, w, center=(0, sy * (d / 2 - r), h - r), axis=(1, 0, 0),
                                                                   sections=10), frame))
    else:
        parts += legs4("leg", "leg", w=w, d=d, h=h - 0.04, size=0.04, mat=frame)
        for i, sy in enumerate((-1, 1)):
            parts.append(make_part(f"rail_{i}", "rail", S.box((w, 0.04, 0.04), center=(0, sy * (d / 2 - 0.02), h - 0.02)), frame))
        for i, sy in enumerate((-1, 1)):
            parts.append(make_part(f"stretcher_{i}", "stretcher", S.box((w - 0.08, 0.025, 0.025), center=(0, sy * (d / 2 - 0.02), 0.12)),
                                   frame))
    brass = M.solid((0.78, 0.62, 0.3), "metal", 0.3, 0.9)
    for k in range(3):
        x = (k - 1) * w * 0.3
        parts.append(make_part(f"strap_{k}", "strap", S.box((0.05, d - 0.01, 0.004), center=(x, 0, h + 0.002)), strap))
        # the strap's ends wrap under the rails, each held by a tack on the rail's outer face
        parts += [make_part(f"tack_{2 * k + j}", "tack", S.cylinder(0.006, 0.003, center=(x, sy * (d / 2 + 0.0015 - (0.0 if variant == "bench" else 0.005)),
                                                                                       h - 0.02), axis=(0, 1, 0), sections=8), brass)
                  for j, sy in enumerate((-1, 1))]
    if variant == "folding":  # the bars joining the crossed legs' feet across the rack
        parts += [make_part(f"stretcher_{i}", "stretcher", S.cylinder(0.01, w - 0.1 + 0.06, center=(0, sy * (d / 2 - 0.014), 0.014), axis=(1, 0, 0),
                                                                      sections=10), frame) for i, sy in enumerate((-1, 1))]
    if variant == "folding":  # the bolt each side where the crossed legs pivot
        steel = M.solid((0.55, 0.55, 0.57), "metal", 0.35, 0.9)
        for i, sx in enumerate((-1, 1)):
            x = sx * (w / 2 - 0.05) + sx * 0.015
            parts.append(make_part(f"pivot_{i}", "pivot", S.cylinder(0.007, 0.03 + 2 * r + 0.006, center=(x, 0, h / 2), axis=(1, 0, 0),
                                                                     sections=8), steel))
    else:  # rubber caps on the square feet
        parts += leg_caps(parts, label="leg_cap", mat=M.solid((0.08, 0.08, 0.08), "rubber", 0.8))
    return parts


@register("bed_bench", parts=("seat", "leg"), extra_parts=("cushion", "shelf", "stretcher", "apron", "button", "ferrule", "corner_block",
                                                           "piping"),
          size_range=(0.8, 1.7), density=400, variants=("upholstered", "slatted_shelf", "tufted"))
def bed_bench(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.9, 1.6), rng.uniform(0.35, 0.48), rng.uniform(0.42, 0.5)
    wood = M.wood(rng)
    cloth = M.fabric(rng)
    st = 0.03
    parts = legs4("leg", "leg", w=w, d=d, h=h - st, size=0.045, mat=wood)
    parts.append(make_part("seat", "seat", S.box((w, d, st), center=(0, 0, h - st / 2), bevel=0.004), wood))
    ch = rng.uniform(0.05, 0.09)
    parts.append(make_part("cushion", "cushion", S.box((w - 0.02, d - 0.02, ch), center=(0, 0, h + ch / 2), bevel=ch / 3), cloth))
    for i, sy in enumerate((-1, 1)):
        parts.append(make_part(f"apron_{i}", "apron", S.box((w - 0.09, 0.02, 0.07), center=(0, sy * (d / 2 - 0.02), h - st - 0.035)),
                               wood))
    if variant == "slatted_shelf":
        n = int(rng.integers(5, 9))
        for k in range(n):
            parts.append(make_part(f"shelf_{k}", "shelf", S.box(((w - 0.09) / n * 0.75, d - 0.09, 0.018),
                                                                 center=(-w / 2 + 0.045 + (w - 0.09) * (k + 0.5) / n, 0, 0.14)), wood))
    else:
        for i, sx in enumerate((-1, 1)):
            parts.append(make_part(f"stretcher_{i}", "stretcher", S.box((0.025, d - 0.09, 0.025), center=(sx * (w / 2 - 0.0225), 0, 0.12)),
                                   wood))
    if variant == "tufted":
        for k in range(int(rng.integers(4, 8))):
            x = -w / 2 + w * (k + 0.5) / 7 if k < 7 else 0.0
            parts.append(make_part(f"button_{k}", "button", S.cylinder(0.01, 0.008, center=(x, 0, h + ch - 0.002), sections=8), cloth))
    # the glued blocks in the seat frame's corners behind the aprons, and the piping round the
    # cushion's top seam
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        parts.append(make_part(f"corner_block_{i}", "corner_block", S.box((0.04, 0.04, 0.05), center=(sx * (w / 2 - 0.045 - 0.02), sy * (d / 2 - 0.045 - 0.02),
                                                                                                   h - st - 0.025)), wood))
    parts.append(make_part("piping", "piping", [S.box((w - 0.02, 0.008, 0.008), center=(0, sy * (d / 2 - 0.014), h + ch - ch / 3)) for sy in (-1, 1)]
                           + [S.box((0.008, d - 0.036, 0.008), center=(sx * (w / 2 - 0.014), 0, h + ch - ch / 3)) for sx in (-1, 1)], cloth))
    # brass ferrules capping the legs' feet
    return parts + leg_caps(parts, label="ferrule", mat=M.solid((0.78, 0.62, 0.3), "metal", 0.3, 0.9), height=0.04)


@register("backpack", parts=("body",), extra_parts=("front_pocket", "strap", "top_handle", "flap", "zipper", "pull", "side_pocket",
                                                   "buckle", "back_panel", "sternum_strap", "hip_belt"),
          size_range=(0.3, 0.65), density=150, variants=("daypack", "rucksack", "school"), placement="floor")
def backpack(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.28, 0.34), rng.uniform(0.14, 0.2), rng.uniform(0.38, 0.48)
    if variant == "rucksack":
        w, d, h = rng.uniform(0.32, 0.38), rng.uniform(0.2, 0.26), rng.uniform(0.45, 0.58)
    cloth = M.fabric(rng)
    parts = [make_part("body", "body", S.box((w, d, h), center=(0, 0, h / 2), bevel=min(0.05, d / 3.2)), cloth),
             make_part("front_pocket", "front_pocket", S.box((w * 0.75, 0.05, h * 0.4), center=(0, d / 2 + 0.02, h * 0.28), bevel=0.015),
                       cloth),
             make_part("top_handle", "top_handle", S.tube([(-0.04, -d * 0.2, h - 0.01), (-0.03, -d * 0.2, h + 0.03),
                                                           (0.03, -d * 0.2, h + 0.03), (0.04, -d * 0.2, h - 0.01)], 0.006), black())]
    for i, sx in enumerate((-1, 1)):
        x = sx * w * 0.25
        parts.append(make_part(f"strap_{i}", "strap", S.tube([(x, -d / 2 + 0.005, h * 0.88), (x, -d / 2 - 0.03, h * 0.6),
                                                              (x * 1.2, -d / 2 - 0.02, h * 0.2), (x * 1.3, -d / 2 + 0.01, 0.04)],
                                                             0.012), cloth))
    if variant == "rucksack":
        parts.append(make_part("flap", "flap", S.box((w * 0.9, d * 0.8, 0.03), center=(0, 0.01, h + 0.012), bevel=0.01),
                               M.fabric(rng)))
        # the flap's two buckles down the front
        parts += [make_part(f"buckle_{k}", "buckle", S.box((0.03, 0.008, 0.04), center=(sx * w * 0.25, d / 2 + 0.004, h * 0.82)), black())
                  for k, sx in enumerate((-1, 1))]
    else:
        parts.append(make_part("zipper", "zipper", S.box((w * 0.8, 0.006, 0.012), center=(0, d / 2 - 0.01, h * 0.8)), black()))
        parts += [make_part(f"pull_{k}", "pull", S.box((0.01, 0.006, 0.03), center=(sx * w * 0.3, d / 2 - 0.004, h * 0.8 - 0.02)), black())
                  for k, sx in enumerate((-1, 1))]
    # the mesh bottle pockets on the sides, the padded back panel and the strap across the chest
    parts += [make_part(f"side_pocket_{k}", "side_pocket", S.box((0.03, d * 0.7, h * 0.3), center=(sx * (w / 2 + 0.01), 0, h * 0.2), bevel=0.008),
                        cloth) for k, sx in enumerate((-1, 1))]
    parts.append(make_part("back_panel", "back_panel", S.box((w * 0.8, 0.02, h * 0.75), center=(0, -d / 2 - 0.005, h * 0.5), bevel=0.006),
                           black("fabric")))
    parts.append(make_part("sternum_strap", "sternum_strap", S.box((w * 0.5 * 1.0, 0.008, 0.02), center=(0, -d / 2 - 0.035, h * 0.62)),
                           black()))
    # the sternum strap's clip, the ladder-lock adjuster low on each shoulder strap, and the
    # front pocket's own zip and pull
    nb = sum(p.label == "buckle" for p in parts)
    parts.append(make_part(f"buckle_{nb}", "buckle", S.box((0.03, 0.01, 0.024), center=(0, -d / 2 - 0.04, h * 0.62)), black()))
    parts += [make_part(f"buckle_{nb + 1 + k}", "buckle", S.box((0.034, 0.012, 0.02), center=(sx * w * 0.25 * 1.25, -d / 2 - 0.01, h * 0.14)),
                        black()) for k, sx in enumerate((-1, 1))]
    zy = d / 2 + 0.045
    parts.append(make_part("zipper_1", "zipper", S.box((w * 0.6, 0.004, 0.01), center=(0, zy, h * 0.44)), black()))
    parts.append(make_part("pull_2", "pull", S.box((0.01, 0.005, 0.03), center=(w * 0.28, zy, h * 0.44 - 0.02)), black()))
    if variant == "rucksack":  # a padded hip belt round the bottom of the back panel
        parts.append(make_part("hip_belt", "hip_belt", S.box((w * 0.95, 0.03, 0.08), center=(0, -d / 2 - 0.02, h * 0.12), bevel=0.01),
                               black("fabric")))
    return parts


@register("handbag", parts=("body", "handle"), extra_parts=("flap", "clasp", "strap", "foot", "ring", "zipper", "pull", "buckle",
                                                                             "clip"),
          size_range=(0.18, 0.45),
          density=200, variants=("tote", "satchel", "clutch"), placement="surface")
def handbag(rng: np.random.Generator, variant: str) -> list[Part]:
    leather = M.leather(rng)
    metal = M.solid((0.8, 0.68, 0.4), "metal", 0.3, 0.9)
    if variant == "clutch":
        w, d, h = rng.uniform(0.22, 0.28), rng.uniform(0.03, 0.05), rng.uniform(0.12, 0.15)
    else:
        w, d, h = rng.uniform(0.28, 0.4), rng.uniform(0.12, 0.16), rng.uniform(0.2, 0.28)
    body = S.hull([[-w / 2, -d / 2, 0], [w / 2, -d / 2, 0], [-w / 2, d / 2, 0], [w / 2, d / 2, 0],
                   [-w / 2 * 0.85, -d / 2 * 0.7, h], [w / 2 * 0.85, -d / 2 * 0.7, h], [-w / 2 * 0.85, d / 2 * 0.7, h],
                   [w / 2 * 0.85, d / 2 * 0.7, h]])
    parts = [make_part("body", "body", body, leather)]
    if variant == "clutch":
        parts.append(make_part("handle", "handle", S.tube([(w / 2 * 0.85, 0, h * 0.6), (w / 2 + 0.03, 0, h * 0.5),
                                                           (w / 2 + 0.03, 0, h * 0.2), (w / 2 * 0.95, 0, h * 0.15)], 0.004), leather))
    else:
        for i, sy in enumerate((-1, 1)) if variant == "tote" else enumerate((0,)):
            y = sy * d / 2 * 0.5
            hh = h * (0.45 if variant == "tote" else 0.3)
            parts.append(make_part(f"handle_{i}", "handle", S.tube([(-w * 0.25, y, h - 0.005), (-w * 0.2, y, h + hh),
                                                                    (w * 0.2, y, h + hh), (w * 0.25, y, h - 0.005)], 0.007), leather))
    if variant != "tote":
        parts.append(make_part("flap", "flap", S.box((w * 0.8, 0.006, h * 0.45), center=(0, d / 2 * 0.85 + 0.004, h * 0.72),
                                                     R=rot_x(0.12 if variant == "satchel" else 0.05)), leather))
        parts.append(make_part("clasp", "clasp", S.box((0.025, 0.008, 0.02), center=(0, d / 2 * 0.85 + 0.012, h * 0.52)), metal))
    else:
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"foot_{i}", "foot", S.cylinder(0.006, 0.004, center=(sx * (w / 2 - 0.03), sy * (d / 2 - 0.02), -0.002),
                                                                   sections=8), metal))
        # the zip across the mouth and its pull
        parts.append(make_part("zipper", "zipper", S.box((w * 0.8, d * 0.7 * 0.3, 0.003), center=(0, 0, h + 0.0015)), black()))
        parts.append(make_part("pull", "pull", S.box((0.012, 0.004, 0.03), center=(w * 0.38, d * 0.1, h - 0.012)), metal))
    if variant != "clutch":  # a metal ring holds each handle end
        hands = [(sx * w * 0.25, sy * d / 2 * 0.5) for sy in ((-1, 1) if variant == "tote" else (0,)) for sx in (-1, 1)]
        parts += [make_part(f"ring_{k}", "ring", S.cylinder(0.011, 0.006, center=(x, y, h + 0.006), axis=(1, 0, 0), sections=10), metal)
                  for k, (x, y) in enumerate(hands)]
    else:  # the D-ring on the side the wrist strap is clipped to
        parts.append(make_part("ring", "ring", S.cylinder(0.008, 0.005, center=(w / 2 * 0.9, 0, h * 0.6), axis=(1, 0, 0), sections=10),
                               metal))
    if variant == "satchel":  # the two buckled straps over the flap either side of the clasp
        R = rot_x(0.12)
        for k, sx in enumerate((-1, 1)):
            c = np.array([sx * w * 0.25, d / 2 * 0.85 + 0.009, h * 0.75])
            parts.append(make_part(f"strap_{k}", "strap", S.box((0.025, 0.003, h * 0.4), center=c, R=R), leather))
            parts.append(make_part(f"buckle_{k}", "buckle", S.box((0.032, 0.005, 0.022), center=c + R @ np.array([0, 0.003, -h * 0.12]), R=R),
                                   metal))
    elif variant == "clutch":  # the clip on the wrist strap's end, hooked on the D-ring
        parts.append(make_part("clip", "clip", S.box((0.006, 0.01, 0.022), center=(w / 2 * 0.9 + 0.004, 0, h * 0.6 - 0.014)), metal))
    if variant == "satchel":  # it stands on four metal feet, like a tote
        parts += [make_part(f"foot_{i}", "foot", S.cylinder(0.006, 0.004, center=(sx * (w / 2 - 0.03), sy * (d / 2 - 0.02), -0.002),
                                                            sections=8), metal)
                  for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)])]
    return parts


def rot_x(a: float) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
