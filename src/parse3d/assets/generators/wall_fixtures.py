"""Things fixed to walls and ceilings: toilet paper and its holder, paper towel dispenser and
roll, grab bar, shower head, curtain and closet rods, smoke detector, air vent, ceiling light,
mailbox, sign, poster, calendar, bulletin board and blackboard; and a power strip.

Wall items have their back (-Y) on the wall and face +Y; ceiling items hang from their top.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Part, make_part
from ..registry import register
from ._casework import black, white
from ._detail_b import ring_points, studs
from ._household import ring
from ._kit import hinge_parts, mount, revolute


@register("toilet_paper", parts=("roll",), extra_parts=("core", "sheet", "wrapper"),
          size_range=(0.09, 0.2), density=300, variants=("standard", "double", "flat_packed"),
          placement="surface")
def toilet_paper(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.095, 0.105)
    r = {"standard": rng.uniform(0.05, 0.056), "double": rng.uniform(0.06, 0.066),
         "flat_packed": rng.uniform(0.045, 0.05)}[variant]
    white_p = white(rng, "paper")
    # lying on its side, the axis along X
    roll = ring([(0.02, -w / 2), (r, -w / 2), (r, w / 2), (0.02, w / 2)], sections=28)
    T = np.array([[0, 0, 1, 0], [0, 1, 0, 0], [-1, 0, 0, r], [0, 0, 0, 1.0]])
    out = [make_part("roll", "roll", S.transformed(roll, T), white_p),
           make_part("core", "core", S.transformed(ring([(0.018, -w / 2 + 0.001), (0.02, -w / 2 + 0.001),
                                                         (0.02, w / 2 - 0.001), (0.018, w / 2 - 0.001)],
                                                        sections=20), T), M.paper(rng))]
    out.append(make_part("sheet", "sheet", S.box((w * 0.98, 0.06, 0.001), center=(0, r + 0.03, 0.0005)), white_p))
    if variant == "flat_packed":  # a hotel roll comes in its own paper band round the middle
        band = ring([(r, -w * 0.2), (r + 0.0008, -w * 0.2), (r + 0.0008, w * 0.2), (r, w * 0.2)], sections=28)
        out.append(make_part("wrapper", "wrapper", S.transformed(band, T), M.solid((0.85, 0.85, 0.8), "paper", 0.8)))
    return out


@register("toilet_paper_holder", parts=("bar", "bracket"),
          extra_parts=("roll", "cover", "plate", "screw", "end_cap"),
          size_range=(0.12, 0.3), density=3000, variants=("bar", "covered", "double"),
          placement="wall")
def toilet_paper_holder(rng: np.random.Generator, variant: str) -> list[Part]:
    metal = M.metal(rng)
    w = 0.15 if variant != "double" else 0.28
    out: list[Part] = []
    n = 2 if variant == "double" else 1
    for k in range(n):
        x = (k - (n - 1) / 2) * 0.14
        out.append(make_part(f"bracket_{k}", "bracket", S.box((0.02, 0.09, 0.025), center=(x - 0.065, 0.045, 0.06)), metal))
        out.append(make_part(f"bar_{k}", "bar", S.cylinder(0.01, 0.12, center=(x, 0.075, 0.06), axis=(1, 0, 0),
                                                          sections=14), metal))
        out.append(make_part(f"roll_{k}", "roll",
                             S.transformed(ring([(0.02, -0.05), (0.055, -0.05), (0.055, 0.05), (0.02, 0.05)], sections=24),
                                           np.array([[0, 0, 1, x], [0, 1, 0, 0.075], [-1, 0, 0, 0.06], [0, 0, 0, 1.0]])),
                             white(rng, "paper")))
    out.append(make_part("plate", "plate", S.box((w, 0.008, 0.05), center=(0, 0.004, 0.06)), metal))
    # the plate is screwed to the wall at both ends; each bar ends in a cap that holds the roll
    out += studs("screw", "screw", [(sx * (w / 2 - 0.012), 0.0085, 0.06) for sx in (-1, 1)], r=0.004, h=0.001,
                 mat=metal, axis=(0, 1, 0))
    out += studs("end_cap", "end_cap", [((k - (n - 1) / 2) * 0.14 + 0.062, 0.075, 0.06) for k in range(n)],
                 r=0.013, h=0.004, mat=metal, axis=(1, 0, 0), sections=12)
    if variant == "covered":
        out.append(make_part("cover", "cover", S.box((0.14, 0.1, 0.006), center=(0, 0.06, 0.12)), metal))
    return out


@register("paper_towel_dispenser", parts=("housing", "cover"),
          extra_parts=("window", "lever", "lock", "hinge", "tear_bar", "towel", "screw"),
          size_range=(0.25, 0.45), density=500, variants=("roll", "folded", "lever"),
          placement="wall")
def paper_towel_dispenser(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d, h = rng.uniform(0.27, 0.33), rng.uniform(0.1, 0.22), rng.uniform(0.25, 0.42)
    mat = white(rng, "plastic") if rng.uniform() < 0.6 else black()
    out: list[Part | Joint] = [make_part("housing", "housing", S.box((w, d * 0.6, h), center=(0, d * 0.3, h / 2), bevel=0.006), mat),
                               make_part("cover", "cover", S.box((w, d * 0.4, h * 0.9), center=(0, d * 0.6 + d * 0.2, h * 0.55),
                                                                 bevel=0.01), mat),
                               make_part("window", "window", S.box((0.04, 0.004, h * 0.3), center=(w * 0.3, d + 0.001, h * 0.6)),
                                         M.glass(rng)),
                               make_part("lock", "lock", S.cylinder(0.008, 0.006, center=(0, d + 0.002, h * 0.9), axis=(0, 1, 0)),
                                         M.metal(rng))]
    if variant == "lever":
        out.append(make_part("lever", "lever", S.box((0.04, 0.03, 0.12), center=(w / 2 + 0.02, d * 0.5, h * 0.5)), black()))
    # under the cover: the serrated tear bar along the outlet and the towel hanging out of it
    out.append(make_part("tear_bar", "tear_bar", S.box((w * 0.8, 0.012, 0.004), center=(0, d * 0.55, h * 0.1 - 0.002)),
                         M.solid((0.6, 0.6, 0.62), "metal", 0.4)))
    out.append(make_part("towel", "towel", S.box((w * 0.7, 0.002, h * 0.06), center=(0, d * 0.5, h * 0.1 - h * 0.03 - 0.004)),
                         M.solid((0.95, 0.95, 0.93), "paper", 0.9)))
    # the two keyhole screws the housing hangs on, inside above the roll
    out += studs("screw", "screw", [(sx * w * 0.3, 0.004, h * 0.85) for sx in (-1, 1)], r=0.005, h=0.003,
                 mat=M.solid((0.6, 0.6, 0.62), "metal", 0.4), axis=(0, 1, 0))
    out += hinge_parts("cover_hinge", x=h * 0.1, y=d * 0.6, z0=-w * 0.35, z1=w * 0.35, mat=mat, axis="x",
                       radius=0.006, length=0.03)
    out.append(revolute("cover_hinge", "housing", "cover", axis=(1, 0, 0), origin=(0, d * 0.6, h * 0.1), opens=-1.2))
    out.append(Joint("window_mount", "prismatic", "cover", "window", (0.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0)))
    out.append(Joint("lock_mount", "prismatic", "cover", "lock", (0.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0)))
    return out


@register("paper_towel_roll", parts=("roll",), extra_parts=("core", "holder", "pole", "sheet", "finial"),
          size_range=(0.2, 0.36), density=300, variants=("roll", "on_holder", "lying"),
          placement="surface")
def paper_towel_roll(rng: np.random.Generator, variant: str) -> list[Part]:
    h, r = rng.uniform(0.22, 0.28), rng.uniform(0.055, 0.07)
    base_h = 0.015 if variant == "on_holder" else 0.0
    roll = ring([(0.02, base_h), (r, base_h), (r, base_h + h), (0.02, base_h + h)], sections=28)
    core = ring([(0.018, base_h), (0.02, base_h), (0.02, base_h + h), (0.018, base_h + h)], sections=20)
    if variant == "lying":
        T = np.array([[0, 0, 1, -h / 2], [0, 1, 0, 0], [-1, 0, 0, r], [0, 0, 0, 1.0]])
        roll, core = S.transformed(roll, T), S.transformed(core, T)
    out = [make_part("roll", "roll", roll, white(rng, "paper")), make_part("core", "core", core, M.paper(rng))]
    if variant == "on_holder":
        wood = M.wood(rng)
        out.append(make_part("holder", "holder", S.cylinder(r * 1.2, base_h, center=(0, 0, base_h / 2), sections=24), wood))
        out.append(make_part("pole", "pole", S.cylinder(0.012, h + 0.03, center=(0, 0, base_h + (h + 0.03) / 2),
                                                        sections=12), wood))
        # a knob on the pole's top keeps the roll on
        out.append(make_part("finial", "finial", S.ellipsoid((0.018, 0.018, 0.014), center=(0, 0, base_h + h + 0.03 + 0.01)),
                             wood))
    elif variant == "roll":
        out.append(make_part("sheet", "sheet", S.box((0.002, 0.06, h * 0.95), center=(r * 0.7, r + 0.03 - 0.03, h / 2),
                                                     ), white(rng, "paper")))
    else:  # lying, its loose sheet unrolled flat in front of it
        out.append(make_part("sheet", "sheet", S.box((h * 0.95, 0.08, 0.001), center=(0, r * 0.9 + 0.04, 0.0005)), white(rng, "paper")))
    return out


@register("grab_bar", parts=("bar", "flange"), extra_parts=("screw_cover", "screw", "grip"),
          size_range=(0.3, 0.95), density=3000, variants=("straight", "angled", "l_shaped"),
          placement="wall")
def grab_bar(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.3, 0.9)
    metal = M.metal(rng)
    y = 0.05
    if variant == "straight":
        path = [(-L / 2, y, 0.04), (L / 2, y, 0.04)]
        ends = [(-L / 2, 0.04), (L / 2, 0.04)]
    elif variant == "angled":
        path = [(-L / 2, y, 0.04), (L / 2, y, 0.04 + L * 0.5)]
        ends = [(-L / 2, 0.04), (L / 2, 0.04 + L * 0.5)]
    else:
        path = [(-L / 2, y, 0.04), (L / 2, y, 0.04), (L / 2, y, 0.04 + L * 0.7)]
        ends = [(-L / 2, 0.04), (L / 2, 0.04 + L * 0.7)]
    out = [make_part("bar", "bar", S.tube(path, 0.016, sections=14), metal)]
    # the knurled grip band round the middle of the first run, a hair proud of the tube
    p0, p1 = np.asarray(path[0], float), np.asarray(path[1], float)
    u = (p1 - p0) / np.linalg.norm(p1 - p0)
    out.append(make_part("grip", "grip", S.cylinder(0.0168, float(np.linalg.norm(p1 - p0)) * 0.35, center=tuple((p0 + p1) / 2), axis=tuple(u),
                                                    sections=14), metal))
    for k, (x, z) in enumerate(ends):
        out.append(make_part(f"flange_{k}", "flange", [S.cylinder(0.035, 0.008, center=(x, 0.004, z), axis=(0, 1, 0)),
                                                       S.cylinder(0.014, y - 0.008, center=(x, 0.008 + (y - 0.008) / 2, z),
                                                                  axis=(0, 1, 0), sections=12)], metal))
        # three screws through each flange plate, round the post
        out += studs("screw", "screw", ring_points(3, 0.025, center=(x, 0.0085, z), plane="xz", phase=np.pi / 2),
                     r=0.004, h=0.001, mat=metal, axis=(0, 1, 0), start=3 * k)
    return out


@register("shower_head", parts=("head", "arm"),
          extra_parts=("flange", "face", "hose", "slide_bar", "nozzle", "swivel", "outlet", "hose_nut"),
          size_range=(0.18, 1.1), density=2000, variants=("fixed", "rain", "handheld"),
          placement="wall")
def shower_head(rng: np.random.Generator, variant: str) -> list[Part]:
    metal = M.metal(rng)
    if variant == "handheld":
        L = rng.uniform(0.6, 1.0)
        out = [make_part("slide_bar", "slide_bar", S.cylinder(0.012, L, center=(0, 0.04, L / 2)), metal),
               make_part("flange", "flange", [S.cylinder(0.025, 0.04, center=(0, 0.02, z), axis=(0, 1, 0)) for z in (0.02, L - 0.02)],
                         metal),
               make_part("arm", "arm", S.box((0.03, 0.05, 0.04), center=(0, 0.07, L * 0.75)), metal),
               make_part("head", "head", S.cylinder(0.012, 0.2, center=(0, 0.1, L * 0.75 + 0.02), sections=14), metal),
               make_part("face", "face", S.cylinder(0.045, 0.015, center=(0, 0.1, L * 0.75 + 0.12 + 0.0075)), metal),
               make_part("hose", "hose", S.tube([(0, 0.1, L * 0.75 - 0.08), (0, 0.12, L * 0.3), (0, 0.06, 0.1)], 0.008),
                         metal)]
        # rubber nozzles on the spray face (a ring and the centre one), the nut joining the hose
        # to the handle, and the outlet elbow at the bottom the hose comes from
        zf = L * 0.75 + 0.12 + 0.015
        out += studs("nozzle", "nozzle", np.vstack([ring_points(6, 0.028, center=(0, 0.1, zf + 0.0015)), [(0, 0.1, zf + 0.0015)]]),
                     r=0.0035, h=0.003, mat=black("rubber"), sections=8)
        # the inner ring round the centre nozzle and the outer ring near the face's edge
        out += studs("nozzle", "nozzle", np.vstack([ring_points(4, 0.014, center=(0, 0.1, zf + 0.0015), phase=0.4),
                                                    ring_points(10, 0.039, center=(0, 0.1, zf + 0.0015), phase=0.3)]),
                     r=0.0035, h=0.003, mat=black("rubber"), sections=8, start=7)
        out.append(make_part("hose_nut", "hose_nut", S.cylinder(0.013, 0.02, center=(0, 0.1, L * 0.75 - 0.08 + 0.01), sections=8),
                             metal))
        out.append(make_part("outlet", "outlet", S.cylinder(0.014, 0.05, center=(0, 0.055, 0.1), axis=(0, 1, 0),
                                                            sections=10), metal))
        return out
    r = rng.uniform(0.05, 0.07) if variant == "fixed" else rng.uniform(0.1, 0.15)
    reach = rng.uniform(0.15, 0.3) if variant == "fixed" else rng.uniform(0.3, 0.4)
    z = 0.1
    out = [make_part("flange", "flange", S.cylinder(0.03, 0.01, center=(0, 0.005, z), axis=(0, 1, 0)), metal),
           make_part("arm", "arm", S.tube([(0, 0.01, z), (0, reach, z), (0, reach, z - 0.04)] if variant == "rain"
                                          else [(0, 0.01, z), (0, reach, z - 0.06)], 0.01), metal)]
    zc = z - (0.05 if variant == "rain" else 0.08)
    out.append(make_part("head", "head", S.frustum(r * 0.5, r, 0.03, center=(0, reach, zc - 0.03), axis=(0, 0, 1)), metal))
    out.append(make_part("face", "face", S.cylinder(r * 0.95, 0.004, center=(0, reach, zc - 0.032)), M.solid((0.7, 0.7, 0.72), "metal")))
    # the ball swivel between arm and head, and the rubber nozzles on the face (rings of them
    # round the centre one)
    out.append(make_part("swivel", "swivel", S.ellipsoid((0.016, 0.016, 0.016), center=(0, reach, zc + 0.004)), metal))
    rings = [ring_points(6, r * 0.45, center=(0, reach, zc - 0.0355))]
    if variant == "rain":
        rings.append(ring_points(10, r * 0.78, center=(0, reach, zc - 0.0355), phase=0.3))
    out += studs("nozzle", "nozzle", np.vstack(rings + [[(0, reach, zc - 0.0355)]]), r=0.0035, h=0.003,
                 mat=black("rubber"), sections=8)
    # the outer ring of nozzles (a fixed head's second ring, a rain head's third)
    n0 = sum(len(rg) for rg in rings) + 1
    outer = ring_points(10, r * 0.78, center=(0, reach, zc - 0.0355), phase=0.3) if variant != "rain" else \
        ring_points(14, r * 0.9, center=(0, reach, zc - 0.0355), phase=0.1)
    out += studs("nozzle", "nozzle", outer, r=0.0035, h=0.003, mat=black("rubber"), sections=8, start=n0)
    return out


def _rod(rng, *, label_rod: str, span: float, y: float, z: float, r: float, variant_finials: bool) -> list[Part]:
    metal = M.metal(rng)
    out = [make_part("rod", label_rod, S.cylinder(r, span, center=(0, y, z), axis=(1, 0, 0), sections=14), metal)]
    for k, sx in enumerate((-1, 1)):
        x = sx * (span / 2 - 0.04)
        out.append(make_part(f"bracket_{k}", "bracket", [S.cylinder(0.025, 0.008, center=(x, 0.004, z), axis=(0, 1, 0)),
                                                         S.cylinder(0.007, y, center=(x, y / 2, z), axis=(0, 1, 0), sections=10)],
                             metal))
        # each bracket's round plate is held by two screws, above and below the arm
        out += studs("screw", "screw", [(x, 0.0085, z + 0.016), (x, 0.0085, z - 0.016)], r=0.0035, h=0.001,
                     mat=metal, axis=(0, 1, 0), start=2 * k)
        if variant_finials:
            out.append(make_part(f"finial_{k}", "finial", S.ellipsoid((0.025, 0.025, 0.025), center=(sx * (span / 2 + 0.02), y, z)),
                                 metal))
    return out


@register("curtain_rod", parts=("rod", "bracket"), extra_parts=("finial", "ring", "screw"),
          size_range=(0.8, 3.1), density=2000, variants=("finials", "tension", "shower"),
          placement="wall")
def curtain_rod(rng: np.random.Generator, variant: str) -> list[Part]:
    span = rng.uniform(0.8, 2.8)
    out = _rod(rng, label_rod="rod", span=span, y=0.08, z=0.03, r=0.012, variant_finials=variant == "finials")
    # the rings the curtain hangs from, each its own part, bunched at the left end
    ring_mat = M.plastic(rng) if variant == "shower" else out[0].material
    # a diamond section: no flat annulus, the costliest surface to resolve
    hoop = ring([(0.014, 0.0), (0.017, -0.003), (0.02, 0.0), (0.017, 0.003)], sections=12)
    n = 6 if variant == "shower" else 8
    for k, x in enumerate(np.linspace(-span / 2 + 0.1, -span / 2 + 0.1 + 0.08 * (n - 1), n)):
        out.append(make_part("ring" if k == 0 else f"ring_{k}", "ring",
                             S.transformed(hoop, np.array([[0, 0, 1, x], [0, 1, 0, 0.08], [-1, 0, 0, 0.03], [0, 0, 0, 1.0]])),
                             ring_mat))
    return out


@register("closet_rod", parts=("rod", "bracket"), extra_parts=("finial", "screw", "support", "end_cap"),
          size_range=(0.6, 2.5), density=2000, variants=("round", "oval", "wooden"),
          placement="wall")
def closet_rod(rng: np.random.Generator, variant: str) -> list[Part]:
    span = rng.uniform(0.6, 2.4)
    r = 0.016 if variant != "oval" else 0.013
    out = _rod(rng, label_rod="rod", span=span, y=0.3, z=0.03, r=r, variant_finials=False)
    # the plastic caps closing the rod's two cut ends
    out += [make_part(f"end_cap_{k}", "end_cap", S.cylinder(r + 0.001, 0.006, center=(sx * (span / 2 - 0.003), 0.3, 0.03), axis=(1, 0, 0),
                                                            sections=12), M.solid((0.9, 0.9, 0.9), "plastic", 0.4)) for k, sx in enumerate((-1, 1))]
    if span > 1.2:  # a long rod sags without a centre support: a plate on the wall, an arm, a hook under the rod
        metal = out[0].material
        out.append(make_part("support", "support", [S.box((0.05, 0.006, 0.1), center=(0, 0.003, 0.06)),
                                                    S.box((0.02, 0.3 - r - 0.006, 0.008), center=(0, (0.3 - r + 0.006) / 2, 0.03 - r - 0.004)),
                                                    S.box((0.02, 2 * r + 0.008, 0.006), center=(0, 0.3, 0.03 - r - 0.003))], metal))
        out += studs("screw", "screw", [(0, 0.0065, 0.085), (0, 0.0065, 0.035)], r=0.0035, h=0.001, mat=metal, axis=(0, 1, 0), start=4)
    return out


@register("smoke_detector", parts=("base", "cover"), extra_parts=("light", "grille", "test_button", "vent", "hush_button"),
          size_range=(0.09, 0.16), density=600, variants=("round", "square", "combo"),
          placement="ceiling")
def smoke_detector(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.05, 0.075)
    h = rng.uniform(0.035, 0.05)
    mat = white(rng, "plastic")
    if variant == "square":
        cover = S.box((2 * r, 2 * r, h - 0.01), center=(0, 0, (h - 0.01) / 2), bevel=0.008)
    else:
        cover = S.lathe([(r * 0.7, 0.0), (r, h * 0.5), (r, h - 0.01)])
    out = [make_part("base", "base", S.cylinder(r * 0.95, 0.01, center=(0, 0, h - 0.005)), mat),
           make_part("cover", "cover", cover, mat),
           make_part("light", "light", S.cylinder(0.003, 0.004, center=(r * 0.35, 0, 0.002), sections=8),
                     M.solid((0.9, 0.1, 0.1), "plastic", 0.2)),
           make_part("test_button", "test_button", S.cylinder(0.01, 0.003, center=(0, 0, 0.0015)), mat)]
    # the green power light beside the red alarm light, the hush button beside the test
    # button, and the sounder's grille in the face
    out.append(make_part("light_1", "light", S.cylinder(0.003, 0.004, center=(r * 0.35, 0.012, 0.002), sections=8),
                         M.solid((0.1, 0.8, 0.2), "plastic", 0.2)))
    out.append(make_part("hush_button", "hush_button", S.cylinder(0.007, 0.003, center=(-r * 0.4, 0, 0.0015), sections=10), mat))
    out.append(make_part("grille", "grille", S.box((r * 0.5, 0.012, 0.002), center=(0, -r * 0.45, 0.001)),
                         M.solid((0.25, 0.25, 0.27), "plastic", 0.6)))
    # the smoke enters through vents round the cover's side
    dark = M.solid((0.25, 0.25, 0.27), "plastic", 0.6)
    if variant == "square":
        vents = [(sx * (r + 0.0005), 0, h * 0.45) for sx in (-1, 1)] + [(0, sy * (r + 0.0005), h * 0.45) for sy in (-1, 1)]
        out += [make_part(f"vent_{k}", "vent", S.box((0.002, r, 0.006) if k < 2 else (r, 0.002, 0.006), center=c), dark)
                for k, c in enumerate(vents)]
    else:
        for k, a in enumerate(np.linspace(0, 2 * np.pi, 6, endpoint=False)):
            c = (np.cos(a) * r * 0.985, np.sin(a) * r * 0.985, h * 0.7)
            rm = np.array([[np.cos(a), -np.sin(a), 0, c[0]], [np.sin(a), np.cos(a), 0, c[1]], [0, 0, 1, c[2]], [0, 0, 0, 1.0]])
            out.append(make_part(f"vent_{k}", "vent", S.transformed(S.box((0.003, r * 0.4, 0.006)), rm), dark))
    return out


@register("vent", parts=("frame", "louver"), extra_parts=("damper", "screw", "lever"),
          size_range=(0.15, 0.65), density=2000, variants=("wall_grille", "ceiling_diffuser", "floor_register"),
          placement="wall")
def vent(rng: np.random.Generator, variant: str) -> list[Part]:
    w, h = rng.uniform(0.2, 0.6), rng.uniform(0.12, 0.3)
    mat = white(rng, "metal")
    t, f = 0.012, 0.02
    out = [make_part("frame", "frame", [S.box((w, t, f), center=(0, t / 2, f / 2)), S.box((w, t, f), center=(0, t / 2, h - f / 2)),
                                        S.box((f, t, h - 2 * f), center=(-w / 2 + f / 2, t / 2, h / 2)),
                                        S.box((f, t, h - 2 * f), center=(w / 2 - f / 2, t / 2, h / 2))], mat)]
    n = max(3, int((h - 2 * f) / 0.02))
    for k in range(n):
        z = f + (h - 2 * f) * (k + 0.5) / n
        out.append(make_part(f"louver_{k}", "louver", S.box((w - 2 * f, 0.004, (h - 2 * f) / n * 0.6),
                                                            center=(0, t * 0.6, z)), mat))
    out += studs("screw", "screw", [(sx * (w / 2 - f / 2), t + 0.0005, z) for z in (f / 2, h - f / 2) for sx in (-1, 1)],
                 r=0.0035, h=0.001, mat=mat, axis=(0, 1, 0))
    if variant == "wall_grille":  # the damper's lever in a slot between two louvres
        out.append(make_part("lever", "lever", S.box((0.012, 0.008, 0.01), center=(w / 2 - f - 0.03, t + 0.004, h / 2)), black("metal")))
    if variant == "floor_register":
        out.append(make_part("damper", "damper", S.box((0.03, 0.006, 0.015), center=(w / 2 - f - 0.03, t + 0.003, h / 2)),
                             black("metal")))
    return out


@register("ceiling_light", parts=("canopy", "diffuser"), extra_parts=("trim", "bulb", "screw", "thumbscrew", "finial", "socket"),
          size_range=(0.2, 0.65), density=800, variants=("dome", "flat_panel", "drum"),
          placement="ceiling")
def ceiling_light(rng: np.random.Generator, variant: str) -> list[Part]:
    metal = white(rng, "metal")
    glow = M.solid((0.98, 0.96, 0.9), "glass", 0.2)
    if variant == "flat_panel":
        w = rng.uniform(0.3, 0.6)
        # the trim frame's four corner screws, flush with its face
        return [make_part("canopy", "canopy", S.box((w, w, 0.03), center=(0, 0, 0.04 + 0.015)), metal),
                make_part("diffuser", "diffuser", S.box((w - 0.02, w - 0.02, 0.01), center=(0, 0, 0.035)), glow),
                make_part("trim", "trim", S.box((w + 0.01, w + 0.01, 0.03), center=(0, 0, 0.015)), metal),
                *studs("screw", "screw", [(sx * w * 0.47, sy * w * 0.47, 0.0005) for sy in (-1, 1) for sx in (-1, 1)],
                       r=0.003, h=0.001, mat=metal)]
    r = rng.uniform(0.12, 0.25)
    h = rng.uniform(0.08, 0.15)
    if variant == "dome":
        diff = S.ellipsoid((r, r, h), center=(0, 0, h))
        pts = diff.mesh.vertices
        diff = S.hull(np.clip(pts, [-1, -1, 0], [1, 1, h]))
    else:
        diff = S.cylinder(r, h, center=(0, 0, h / 2), sections=28)
    out = [make_part("diffuser", "diffuser", diff, glow),
           make_part("canopy", "canopy", S.cylinder(r * 0.5, 0.025, center=(0, 0, h + 0.0125)), metal),
           make_part("trim", "trim", S.cylinder(r * 1.03, 0.012, center=(0, 0, h - 0.006), sections=28), metal)]
    # three thumbscrews through the trim ring hold the glass; a dome hangs on a centre rod
    # ending in a finial nut under it
    for k, a in enumerate(np.linspace(0, 2 * np.pi, 3, endpoint=False)):
        c = (np.cos(a) * (r * 1.03 + 0.005), np.sin(a) * (r * 1.03 + 0.005), h - 0.006)
        out.append(make_part(f"thumbscrew_{k}", "thumbscrew", S.cylinder(0.004, 0.012, center=c, axis=(np.cos(a), np.sin(a), 0),
                                                                         sections=8), metal))
    if variant == "dome":
        out.append(make_part("finial", "finial", S.cylinder(0.01, 0.012, center=(0, 0, -0.004), sections=10), metal))
    # the two bulbs in their sockets under the canopy, inside the glass
    frosted = M.solid((0.98, 0.97, 0.92), "glass", 0.1)
    for k, sx in enumerate((-1, 1)):
        x = sx * r * 0.3
        out.append(make_part(f"socket_{k}", "socket", S.cylinder(0.014, 0.025, center=(x, 0, h - 0.0125), sections=10),
                             M.solid((0.9, 0.9, 0.88), "ceramic", 0.5)))
        out.append(make_part(f"bulb_{k}", "bulb", S.ellipsoid((0.03, 0.03, 0.04), center=(x, 0, h - 0.025 - 0.04), subdivisions=1),
                             frosted))
    return out


@register("mailbox", parts=("body", "door"),
          extra_parts=("flag", "post", "hinge", "slot", "lock", "handle", "name_plate", "flag_pivot", "bracket", "flap", "window",
                       "reflector", "latch"),
          size_range=(0.3, 1.35), density=900, variants=("wall", "post", "locker"),
          placement="wall")
def mailbox(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    metal = M.metal(rng)
    if variant == "post":
        w, d, h = rng.uniform(0.17, 0.2), rng.uniform(0.45, 0.5), rng.uniform(0.2, 0.24)
        ph = rng.uniform(0.95, 1.05)
        out: list[Part | Joint] = [make_part("post", "post", S.box((0.09, 0.09, ph), center=(0, 0, ph / 2)), M.wood(rng)),
                                   make_part("body", "body", [S.box((w, d - 0.01, h * 0.6), center=(0, -0.005, ph + h * 0.3)),
                                                              S.cylinder(w / 2, d - 0.01, center=(0, -0.005, ph + h * 0.6), axis=(0, 1, 0),
                                                                         sections=20)], metal),
                                   make_part("flag", "flag", S.box((0.006, 0.08, 0.12), center=(w / 2 + 0.003, -d * 0.2, ph + h * 0.6)),
                                             M.solid((0.85, 0.1, 0.1), "metal"))]
        out.append(make_part("door", "door", S.box((w, 0.01, h * 0.6 + w / 2), center=(0, d / 2 - 0.005, ph + (h * 0.6 + w / 2) / 2)),
                             metal))
        out.append(revolute("door_hinge", "body", "door", axis=(0, 0, 1), origin=(-w / 2, d / 2 - 0.01, ph)))
        # the door's pull, its two hinge barrels, the flag's pivot and the two brackets that
        # fix the box to the post
        out.append(make_part("handle", "handle", S.box((0.03, 0.015, 0.02), center=(w * 0.25, d / 2 + 0.0075, ph + h * 0.35)),
                             metal))
        out.append(mount("door", "handle"))
        out += hinge_parts("door_hinge", x=-w / 2, y=d / 2 - 0.01, z0=ph, z1=ph + h * 0.6 + w / 2, mat=metal,
                           radius=0.005, length=0.03)
        out.append(make_part("flag_pivot", "flag_pivot", S.cylinder(0.008, 0.012, center=(w / 2 + 0.006, -d * 0.2, ph + h * 0.6),
                                                                    axis=(1, 0, 0), sections=10), metal))
        out += [make_part(f"bracket_{k}", "bracket", S.box((0.006, 0.08, 0.06), center=(sx * 0.048, 0, ph - 0.03)), metal)
                for k, sx in enumerate((-1, 1))]
        # the red reflector on the door, and the spring latch on the body's lip the door snaps onto
        out.append(make_part("reflector", "reflector", S.cylinder(0.02, 0.003, center=(0, d / 2 + 0.0015, ph + h * 0.55), axis=(0, 1, 0),
                                                                  sections=12), M.solid((0.85, 0.1, 0.1), "glass", 0.2)))
        out.append(mount("door", "reflector"))
        out.append(make_part("latch", "latch", S.box((0.02, 0.012, 0.008), center=(0, d / 2 - 0.016, ph + h * 0.6 + w / 2 - 0.004)), metal))
        return out
    w, d, h = rng.uniform(0.3, 0.4), rng.uniform(0.1, 0.14), rng.uniform(0.35, 0.45)
    out = [make_part("body", "body", S.box((w, d - 0.012, h), center=(0, (d - 0.012) / 2, h / 2)), metal),
           make_part("door", "door", S.box((w, 0.012, h * 0.75), center=(0, d - 0.006, h * 0.375)), metal),
           make_part("slot", "slot", S.box((w * 0.7, 0.004, 0.02), center=(0, d - 0.002 - 0.012, h * 0.88)), black())]
    out.append(make_part("lock", "lock", S.cylinder(0.008, 0.008, center=(w * 0.35, d + 0.004, h * 0.6), axis=(0, 1, 0)),
                         M.metal(rng)))
    out += hinge_parts("door_hinge", x=-w / 2, y=d - 0.012, z0=0.0, z1=h * 0.75, mat=metal, radius=0.005, length=0.03)
    out.append(revolute("door_hinge", "body", "door", axis=(0, 0, 1), origin=(-w / 2, d - 0.012, 0.0)))
    out.append(Joint("lock_mount", "prismatic", "door", "lock", (0.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0)))
    # the card holder for the name on the door, and the knob it is pulled open by
    out.append(make_part("name_plate", "name_plate", S.box((w * 0.4, 0.003, 0.03), center=(-w * 0.05, d + 0.0015, h * 0.6)),
                         M.solid((0.85, 0.75, 0.45), "metal", 0.3, 0.8)))
    out.append(mount("door", "name_plate"))
    out.append(make_part("handle", "handle", S.cylinder(0.009, 0.015, center=(w * 0.35, d + 0.0075, h * 0.35), axis=(0, 1, 0),
                                                        sections=10), metal))
    out.append(mount("door", "handle"))
    # the hinged flap over the letter slot, and the row of viewing slots in the door that show
    # when post is in
    out.append(make_part("flap", "flap", S.box((w * 0.74, 0.004, 0.032), center=(0, d + 0.002 - 0.004, h * 0.88)), metal))
    out += [make_part(f"window_{k}", "window", S.box((w * 0.08, 0.002, 0.012), center=(x, d + 0.001, h * 0.2)), black())
            for k, x in enumerate(np.linspace(-w * 0.25, w * 0.05, 3))]
    out += [mount("door", f"window_{k}") for k in range(3)]
    return out


@register("sign", parts=("panel",),
          extra_parts=("lettering", "frame", "standoff", "post", "base", "clamp", "pictogram", "arrow", "foot", "end_cap",
                       "test_button", "indicator"),
          size_range=(0.15, 1.9), density=900, variants=("wall_plaque", "exit", "standing"),
          placement="wall")
def sign(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "standing":
        w, h = rng.uniform(0.3, 0.5), rng.uniform(0.4, 0.6)
        ph = rng.uniform(1.0, 1.3)
        metal = M.metal(rng)
        return [make_part("base", "base", S.cylinder(0.18, 0.03, center=(0, 0, 0.015), sections=24), metal),
                make_part("post", "post", S.cylinder(0.015, ph, center=(0, 0, 0.03 + ph / 2)), metal),
                make_part("panel", "panel", S.box((w, 0.01, h), center=(0, 0.02, 0.03 + ph + h / 2)), white(rng, "plastic")),
                make_part("lettering", "lettering", S.box((w * 0.7, 0.002, h * 0.2), center=(0, 0.026, 0.03 + ph + h * 0.6)),
                          black()),
                # the frame round the panel, the two clamps holding it on the post, a rubber
                # ring under the base
                make_part("frame", "frame", [S.box((w + 0.02, 0.016, 0.01), center=(0, 0.02, 0.03 + ph + z)) for z in (-0.005, h + 0.005)]
                          + [S.box((0.01, 0.016, h), center=(sx * (w / 2 + 0.005), 0.02, 0.03 + ph + h / 2)) for sx in (-1, 1)], metal),
                *[make_part(f"clamp_{k}", "clamp", S.box((0.04, 0.02, 0.025), center=(0, 0.005, 0.03 + ph + z)), metal)
                  for k, z in enumerate((h * 0.15, h * 0.85))],
                make_part("foot", "foot", ring([(0.15, 0.0), (0.182, 0.0), (0.182, 0.004), (0.15, 0.004)], sections=24),
                          black("rubber")),
                # the cap closing the post's top end, behind the panel
                make_part("end_cap", "end_cap", S.cylinder(0.017, 0.01, center=(0, 0, 0.03 + ph + h * 0.95), sections=10), black())]
    w, h = (rng.uniform(0.2, 0.5), rng.uniform(0.1, 0.3)) if variant == "wall_plaque" else (0.36, 0.18)
    col = (0.1, 0.6, 0.2) if variant == "exit" else M.jitter(rng, (0.2, 0.3, 0.5), 0.1)[:3]
    out = [make_part("panel", "panel", S.box((w, 0.006, h), center=(0, 0.015, h / 2)), M.solid(col, "plastic", 0.4)),
           make_part("lettering", "lettering", S.box((w * 0.7, 0.002, h * 0.35), center=(0, 0.019, h / 2)),
                     M.solid((0.95, 0.95, 0.95)))]
    # four standoffs hold the panel off the wall, one near each corner
    metal = M.metal(rng)
    for k, (sx, sz) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        c = (sx * (w / 2 - 0.02), 0.006, h / 2 + sz * (h / 2 - 0.025))
        out.append(make_part("standoff" if k == 0 else f"standoff_{k}", "standoff",
                             [S.cylinder(0.006, 0.012, center=c, axis=(0, 1, 0), sections=10),
                              S.cylinder(0.007, 0.004, center=(c[0], 0.02, c[2]), axis=(0, 1, 0), sections=10)], metal))
    if variant == "exit":  # the running figure and the arrow beside the letters
        white_ = M.solid((0.95, 0.95, 0.95))
        out.append(make_part("pictogram", "pictogram", S.box((h * 0.3, 0.002, h * 0.5), center=(-w * 0.42, 0.019, h / 2)), white_))
        out.append(make_part("arrow", "arrow", S.prism([(0, 0.02), (0.03, 0), (0, -0.02)], 0, 0.002).apply(
            np.array([[1, 0, 0, w * 0.4], [0, 0, -1, 0.02], [0, 1, 0, h / 2], [0, 0, 0, 1.0]])), white_))
        # the emergency battery's test button and charge light low on the panel's face
        out.append(make_part("test_button", "test_button", S.cylinder(0.004, 0.003, center=(w * 0.3, 0.0195, h * 0.1), axis=(0, 1, 0),
                                                                      sections=8), black()))
        out.append(make_part("indicator", "indicator", S.cylinder(0.0025, 0.002, center=(w * 0.38, 0.019, h * 0.1), axis=(0, 1, 0),
                                                                  sections=8), M.solid((0.1, 0.8, 0.2), "plastic", 0.2)))
    return out


@register("poster", parts=("sheet",), extra_parts=("tape", "frame", "image", "clip", "backing", "pin", "curl"),
          size_range=(0.3, 1.05), density=700, variants=("taped", "clip_frame", "rolled_edges"),
          placement="wall")
def poster(rng: np.random.Generator, variant: str) -> list[Part]:
    w, h = rng.uniform(0.3, 0.7), rng.uniform(0.42, 1.0)
    out = [make_part("sheet", "sheet", S.box((w, 0.001, h), center=(0, 0.0005, h / 2)), white(rng, "paper")),
           make_part("image", "image", S.box((w * 0.9, 0.0005, h * 0.9), center=(0, 0.00125, h / 2)),
                     M.solid(M.jitter(rng, (0.4, 0.4, 0.5), 0.3)[:3], "paper", 0.8))]
    if variant == "taped":  # a strip of tape on each corner
        tape = M.glass(rng)
        out += [make_part("tape" if k == 0 else f"tape_{k}", "tape", S.box((0.04, 0.0004, 0.02), center=(sx * (w / 2 - 0.01), 0.0017, z)),
                          tape) for k, (sx, z) in enumerate((sx, z) for sx in (-1, 1) for z in (0.01, h - 0.01))]
    elif variant == "clip_frame":
        out.append(make_part("frame", "frame", S.box((w + 0.01, 0.003, h + 0.01), center=(0, 0.0035, h / 2)), M.glass(rng)))
        out[0] = make_part("sheet", "sheet", S.box((w, 0.001, h), center=(0, 0.0005, 0.005 + h / 2)), white(rng, "paper"))
        out[1] = make_part("image", "image", S.box((w * 0.9, 0.0005, h * 0.9), center=(0, 0.00125, 0.005 + h / 2)),
                           M.solid((0.5, 0.4, 0.3), "paper", 0.8))
        # the hardboard behind the sheet, and the spring clips (two a side) pressing the glass
        # onto it
        out.append(make_part("backing", "backing", S.box((w + 0.01, 0.003, h + 0.01), center=(0, -0.0015, h / 2 + 0.005)),
                             M.paper(rng)))
        clip = M.metal(rng)
        pos = [(sx * (w / 2 + 0.005), z) for sx in (-1, 1) for z in (h * 0.25, h * 0.75)]
        pos += [(x, z) for x in (-w * 0.25, w * 0.25) for z in (-0.005, h + 0.005)]
        out += [make_part(f"clip_{k}", "clip", S.box((0.012, 0.008, 0.012), center=(x, 0.002, z)), clip)
                for k, (x, z) in enumerate(pos)]
    else:  # pinned at the top corners; the free bottom edge has rolled up
        pin = M.solid((0.85, 0.15, 0.1), "plastic", 0.4)
        out += studs("pin", "pin", [(sx * (w / 2 - 0.015), 0.004, h - 0.015) for sx in (-1, 1)], r=0.005, h=0.006, mat=pin,
                     axis=(0, 1, 0))
        out.append(make_part("curl", "curl", S.cylinder(0.006, w, center=(0, 0.006, 0.006), axis=(1, 0, 0), sections=10),
                             out[0].material))
    return out


@register("calendar", parts=("page",), extra_parts=("binding", "hanger", "backing", "picture"),
          size_range=(0.2, 0.62), density=700, variants=("wall", "desk", "poster"),
          placement="wall")
def calendar(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "desk":  # a tent standing on a desk
        w, h = rng.uniform(0.18, 0.24), rng.uniform(0.12, 0.16)
        d = h * 0.6
        back = S.hull(np.array([[-w / 2, -d / 2, 0], [w / 2, -d / 2, 0], [-w / 2, -d / 2 + 0.003, 0], [w / 2, -d / 2 + 0.003, 0],
                                [-w / 2, -0.002, h], [w / 2, -0.002, h], [-w / 2, 0.001, h], [w / 2, 0.001, h]]))
        page = S.hull(np.array([[-w / 2, d / 2, 0], [w / 2, d / 2, 0], [-w / 2, d / 2 - 0.003, 0], [w / 2, d / 2 - 0.003, 0],
                                [-w / 2, 0.002, h], [w / 2, 0.002, h], [-w / 2, 0.005, h], [w / 2, 0.005, h]]))
        paper = white(rng, "paper")
        out = [make_part("backing", "backing", back, M.paper(rng)), make_part("page", "page", page, paper),
               make_part("binding", "binding", S.cylinder(0.006, w, center=(0, 0.0015, h), axis=(1, 0, 0), sections=10),
                         black("metal"))]
        # the other eleven months' pages under this month's, on the same rings
        pt = 0.0002
        for k in range(1, 12):
            yb0, yb1 = d / 2 - 0.003 - pt * k, d / 2 - 0.003 - pt * (k - 1)
            yt0, yt1 = 0.002 - pt * k, 0.002 - pt * (k - 1)
            out.append(make_part(f"page_{k}", "page", S.hull(np.array([[sx * w / 2, y, 0.0] for sx in (-1, 1) for y in (yb0, yb1)]
                                                                      + [[sx * w / 2, y, h] for sx in (-1, 1) for y in (yt0, yt1)])), paper))
        return out
    w = rng.uniform(0.22, 0.32) if variant == "wall" else rng.uniform(0.4, 0.6)
    h = w * (1.4 if variant == "wall" else 1.0)
    # the twelve month pages under the binding, this month's in front; the month's picture on
    # the upper half
    paper = white(rng, "paper")
    out = [make_part("backing", "backing", S.box((w, 0.002, h), center=(0, 0.001, h / 2)), M.paper(rng)),
           make_part("page", "page", S.box((w * 0.96, 0.0005, h * 0.5), center=(0, 0.00575, h * 0.25)), paper)]
    pt = 0.0035 / 11
    out += [make_part(f"page_{k}", "page", S.box((w * 0.96, pt, h * 0.5), center=(0, 0.0055 - pt * (k - 0.5), h * 0.25)), paper)
            for k in range(1, 12)]
    out.append(make_part("picture", "picture", S.box((w * 0.96, 0.0005, h * 0.46), center=(0, 0.00225, h * 0.75)),
                         M.solid((0.45, 0.55, 0.5), "paper", 0.8)))
    out.append(make_part("binding", "binding", S.cylinder(0.005, w * 0.9, center=(0, 0.006, h * 0.5), axis=(1, 0, 0),
                                                          sections=10), black("metal")))
    out.append(make_part("hanger", "hanger", S.box((0.02, 0.003, 0.02), center=(0, 0.0015, h - 0.01)), black("metal")))
    return out


def _board(rng, *, w: float, h: float, surface_mat, frame_mat, label: str) -> list[Part]:
    f, t = 0.02, 0.018
    return [make_part(label, label, S.box((w - 2 * f, t * 0.6, h - 2 * f), center=(0, t * 0.3, h / 2)),
                      surface_mat),
            make_part("frame", "frame", [S.box((w, t, f), center=(0, t / 2, f / 2)), S.box((w, t, f), center=(0, t / 2, h - f / 2)),
                                         S.box((f, t, h - 2 * f), center=(-w / 2 + f / 2, t / 2, h / 2)),
                                         S.box((f, t, h - 2 * f), center=(w / 2 - f / 2, t / 2, h / 2))], frame_mat)]


@register("bulletin_board", parts=("board", "frame"), extra_parts=("pin", "note", "screw"),
          size_range=(0.4, 1.85), density=400, variants=("cork", "fabric", "large"),
          placement="wall")
def bulletin_board(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.45, 0.9) if variant != "large" else rng.uniform(1.2, 1.8)
    h = w * rng.uniform(0.6, 0.8)
    surf = (M.solid(M.jitter(rng, (0.7, 0.55, 0.38), 0.03), "wood", 0.9) if variant != "fabric"
            else M.fabric(rng))
    out = _board(rng, w=w, h=h, surface_mat=surf, frame_mat=M.wood(rng), label="board")
    n = int(rng.integers(2, 7))
    for k in range(n):
        x, z = (rng.uniform(-0.35, 0.35) * w, rng.uniform(0.25, 0.75) * h)
        out.append(make_part(f"note_{k}", "note", S.box((0.1, 0.001, 0.12), center=(x, 0.0115, z)),
                             M.solid(M.jitter(rng, (0.95, 0.9, 0.5), 0.1)[:3], "paper", 0.9)))
        out.append(make_part(f"pin_{k}", "pin", S.cylinder(0.005, 0.008, center=(x, 0.016, z + 0.05), axis=(0, 1, 0),
                                                          sections=8), M.solid((0.9, 0.1, 0.1))))
    # the four screws through the frame's corners into the wall
    out += studs("screw", "screw", [(sx * (w / 2 - 0.01), 0.0185, z) for z in (0.01, h - 0.01) for sx in (-1, 1)], r=0.003, h=0.001,
                 mat=M.solid((0.6, 0.6, 0.62), "metal", 0.4), axis=(0, 1, 0))
    return out


@register("blackboard", parts=("board", "frame"), extra_parts=("tray", "chalk", "eraser", "leg", "map_rail", "hook", "screw", "bracket"),
          size_range=(0.5, 3.1), density=700, variants=("wall", "classroom", "easel"),
          placement="wall")
def blackboard(rng: np.random.Generator, variant: str) -> list[Part]:
    w = {"wall": rng.uniform(0.5, 1.0), "classroom": rng.uniform(1.8, 3.0), "easel": rng.uniform(0.5, 0.7)}[variant]
    h = w * (0.6 if variant != "easel" else 1.2)
    slate = M.solid(M.jitter(rng, (0.12, 0.2, 0.16), 0.03), "stone", 0.9)
    z0 = 0.0 if variant != "easel" else 0.7
    shift = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, z0], [0, 0, 0, 1.0]])
    f, t = 0.02, 0.018
    out = [make_part("board", "board", S.transformed(S.box((w - 2 * f, t * 0.6, h - 2 * f), center=(0, t * 0.3, h / 2)),
                                                     shift), slate),
           make_part("frame", "frame", [S.transformed(s, shift) for s in (
               S.box((w, t, f), center=(0, t / 2, f / 2)), S.box((w, t, f), center=(0, t / 2, h - f / 2)),
               S.box((f, t, h - 2 * f), center=(-w / 2 + f / 2, t / 2, h / 2)),
               S.box((f, t, h - 2 * f), center=(w / 2 - f / 2, t / 2, h / 2)))], M.wood(rng))]
    if z0:  # an easel: three legs
        wood = M.wood(rng)
        out.append(make_part("leg_0", "leg", S.box((0.03, 0.03, z0 + h), center=(-w / 2 + 0.05, -0.02, (z0 + h) / 2)), wood))
        out.append(make_part("leg_1", "leg", S.box((0.03, 0.03, z0 + h), center=(w / 2 - 0.05, -0.02, (z0 + h) / 2)), wood))
        out.append(make_part("leg_2", "leg", S.box((0.03, 0.03, z0 + h * 0.9), center=(0, -0.4, (z0 + h * 0.9) / 2)), wood))
    out.append(make_part("tray", "tray", S.box((w * 0.9, 0.06, 0.015), center=(0, 0.03, z0 + 0.0075 + 0.005)), M.wood(rng)))
    chalk = white(rng, "plastic")
    out.append(make_part("chalk", "chalk", S.cylinder(0.005, 0.08, center=(w * 0.2, 0.04, z0 + 0.0175), axis=(1, 0, 0),
                                                      sections=8), chalk))
    # two more sticks of chalk and a felt eraser lying in the tray
    out += [make_part(f"chalk_{k}", "chalk", S.cylinder(0.005, 0.06, center=(w * 0.2 + 0.1 * k, 0.025, z0 + 0.0175),
                                                       axis=(1, 0, 0), sections=8), chalk) for k in (1, 2)]
    out.append(make_part("eraser", "eraser", [S.box((0.12, 0.045, 0.012), center=(-w * 0.25, 0.03, z0 + 0.0185), bevel=0.002),
                                              S.box((0.12, 0.045, 0.018), center=(-w * 0.25, 0.03, z0 + 0.0335), bevel=0.004)],
                         M.solid((0.55, 0.4, 0.25), "wood", 0.7)))
    if z0:  # the tray's two brackets under it, and the hinge bracket joining the back leg
        wood = out[2].material
        out += [make_part(f"bracket_{k}", "bracket", S.box((0.02, 0.05, 0.04), center=(sx * w * 0.35, 0.025, z0 - 0.02)), wood)
                for k, sx in enumerate((-1, 1))]
    else:  # the four screws through the frame's corners into the wall
        out += studs("screw", "screw", [(sx * (w / 2 - 0.01), t + 0.0005, z) for z in (0.01, h - 0.01) for sx in (-1, 1)], r=0.003,
                     h=0.001, mat=M.solid((0.6, 0.6, 0.62), "metal", 0.4), axis=(0, 1, 0))
    if variant == "classroom":  # a map rail along the top with hooks for maps and charts
        out.append(make_part("map_rail", "map_rail", S.box((w, 0.025, 0.04), center=(0, 0.0125, h + 0.02)), out[1].material))
        out += [make_part(f"hook_{k}", "hook", S.box((0.01, 0.012, 0.03), center=(x, 0.031, h + 0.02)), M.metal(rng))
                for k, x in enumerate(np.linspace(-w * 0.4, w * 0.4, 4))]
    return out


@register("power_strip", parts=("body", "socket"), extra_parts=("switch", "cord", "plug", "indicator", "slot", "ground_hole", "screw",
                                                              "keyhole", "foot", "reset_button"),
          size_range=(0.2, 0.56), density=900, variants=("four", "six", "surge"),
          placement="floor")
def power_strip(rng: np.random.Generator, variant: str) -> list[Part]:
    n = {"four": 4, "six": 6, "surge": 8}[variant]
    pitch = 0.045
    L = n * pitch + 0.06
    w, h = 0.055, 0.04
    mat = white(rng, "plastic") if rng.uniform() < 0.6 else black()
    out = [make_part("body", "body", S.box((L, w, h), center=(0, 0, h / 2), bevel=0.006), mat)]
    for k in range(n):
        x = -L / 2 + 0.03 + pitch * (k + 0.5)
        out.append(make_part(f"socket_{k}", "socket", S.cylinder(0.016, 0.002, center=(x, 0, h + 0.001), sections=14),
                             M.solid((0.85, 0.85, 0.85))))
        # each socket's two blade slots and round earth hole (dark, just proud of its face)
        for j, sy in enumerate((-1, 1)):
            out.append(make_part(f"slot_{2 * k + j}", "slot", S.box((0.009, 0.0025, 0.0008), center=(x + 0.003, sy * 0.0065, h + 0.0024)),
                                 black()))
        out.append(make_part(f"ground_hole_{k}", "ground_hole", S.cylinder(0.0025, 0.0008, center=(x - 0.009, 0, h + 0.0024), sections=8),
                             black()))
    out.append(make_part("switch", "switch", S.box((0.02, 0.03, 0.008), center=(L / 2 - 0.018, 0, h + 0.004)),
                         M.solid((0.85, 0.1, 0.1))))
    out.append(make_part("cord", "cord", S.tube([(-L / 2 + 0.002, 0, h / 2), (-L / 2 - 0.05, 0.0, 0.005), (-L / 2 - 0.08, 0.04, 0.005)],
                                                0.004, sections=6), black()))
    # the plug at the cord's end and the switch's pilot light
    out.append(make_part("plug", "plug", [S.box((0.03, 0.04, 0.02), center=(-L / 2 - 0.08, 0.06, 0.01), bevel=0.003)]
                         + [S.box((0.002, 0.015, 0.006), center=(-L / 2 - 0.08 + dx, 0.0875, 0.01)) for dx in (-0.006, 0.006)],
                         mat))
    out.append(make_part("indicator", "indicator", S.cylinder(0.003, 0.002, center=(L / 2 - 0.018, -0.02, h + 0.001), sections=8),
                         M.solid((0.9, 0.2, 0.1), "plastic", 0.2)))
    # the two screws closing the case from underneath, their heads sunk flush with its bottom
    out += studs("screw", "screw", [(sx * L * 0.3, 0, 0.001) for sx in (-1, 1)], r=0.003, h=0.002, mat=M.solid((0.6, 0.6, 0.62), "metal", 0.4))
    # underneath: the two keyhole slots it hangs on a wall by and four rubber feet, all flush
    out += [make_part(f"keyhole_{k}", "keyhole", S.box((0.012, 0.006, 0.001), center=(sx * L * 0.4, 0.01, 0.0005)), black())
            for k, sx in enumerate((-1, 1))]
    out += studs("foot", "foot", [(sx * (L / 2 - 0.015), sy * (w / 2 - 0.012), 0.001) for sx in (-1, 1) for sy in (-1, 1)],
                 r=0.004, h=0.002, mat=M.solid((0.1, 0.1, 0.1), "rubber", 0.8))
    if variant == "surge":  # the overload breaker's reset button and the "protected" light, flush in the top
        out.append(make_part("reset_button", "reset_button", S.cylinder(0.006, 0.004, center=(L / 2 - 0.018, 0.018, h - 0.002),
                                                                        sections=10), black()))
        out.append(make_part("protected_light", "indicator", S.cylinder(0.003, 0.002, center=(-L / 2 + 0.015, -0.018, h - 0.001),
                                                                        sections=8), M.solid((0.2, 0.8, 0.3), "plastic", 0.2)))
    return out


@register("toilet_seat_cover_dispenser", parts=("housing", "slot"), extra_parts=("cover_stack", "window", "lock", "label", "flange",
                                                                                  "hinge", "tab"),
          size_range=(0.3, 0.48), density=700, variants=("steel", "plastic", "recessed"),
          placement="wall")
def toilet_seat_cover_dispenser(rng: np.random.Generator, variant: str) -> list[Part]:
    w, h = rng.uniform(0.38, 0.44), rng.uniform(0.26, 0.32)
    d = 0.05 if variant != "recessed" else 0.02
    mat = M.metal(rng) if variant != "plastic" else white(rng, "plastic")
    out = [make_part("housing", "housing", S.box((w, d, h), center=(0, d / 2, h / 2), bevel=0.004), mat),
           make_part("slot", "slot", S.box((w * 0.5, 0.004, 0.08), center=(0, d + 0.001, h * 0.4)), black()),
           make_part("cover_stack", "cover_stack", S.box((w * 0.45, 0.003, 0.07), center=(0, d + 0.0045, h * 0.4)),
                     white(rng, "paper"))]
    if variant == "plastic":
        out.append(make_part("window", "window", S.box((0.06, 0.003, 0.03), center=(w * 0.3, d + 0.0015, h * 0.8)),
                             M.glass(rng)))
    # the keyed lock on the front's top edge, the printed label above the slot and, recessed,
    # the trim flange that covers the cut in the wall
    out.append(make_part("lock", "lock", S.cylinder(0.008, 0.004, center=(0, d + 0.002, h * 0.88), axis=(0, 1, 0), sections=10),
                         M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)))
    out.append(make_part("label", "label", S.box((w * 0.4, 0.001, 0.025), center=(0, d + 0.0005, h * 0.66)),
                         M.solid((0.2, 0.3, 0.6), "plastic", 0.5)))
    # the front opens down on a piano hinge along its bottom edge to refill it; the first cover's
    # tab hangs out of the slot for the next user
    out.append(make_part("hinge", "hinge", S.cylinder(0.003, w * 0.8, center=(0, d + 0.001, 0.004), axis=(1, 0, 0), sections=8),
                         M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)))
    out.append(make_part("tab", "tab", S.box((0.05, 0.001, 0.03), center=(0, d + 0.0065, h * 0.4 - 0.04)), white(rng, "paper")))
    if variant == "recessed":
        f = 0.015
        out.append(make_part("flange", "flange", [S.box((w + 2 * f, 0.003, f), center=(0, d - 0.0015, z)) for z in (-f / 2, h + f / 2)]
                             + [S.box((f, 0.003, h), center=(sx * (w / 2 + f / 2), d - 0.0015, h / 2)) for sx in (-1, 1)], mat))
    return out
