"""More household things: bicycle, vacuum cleaner, plunger, dustpan, hair dryer, fire
extinguisher, guitar case, dish rack, storage bin, storage organizer, room divider, utility
cart, digital piano, electric fan, sink, blanket, mattress, folded clothes, jacket and paper bag.

Front toward +Y, standing on z = 0 (long floor things lie along X).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Part, make_part
from ..registry import register
from ._casework import black, drawer_parts, white
from ._dC_keys import white_keys
from ._detail_b import each, studs, tufts
from ._household import ring, shell
from ._kit import hinge_parts, revolute, rot


@register("vacuum_cleaner", parts=("body", "hose"),
          extra_parts=("wand", "nozzle", "wheel", "handle", "bin", "bumper", "side_brush", "caster", "button", "sensor",
                       "grip", "switch", "cord_hook", "cuff", "cord", "plug", "contact"),
          size_range=(0.3, 1.45), density=300, variants=("canister", "upright", "robot"),
          placement="floor")
def vacuum_cleaner(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.plastic(rng)
    if variant == "robot":
        r = rng.uniform(0.16, 0.18)
        # the drive wheels, the front caster, the bumper round the front half, two spinning
        # side brushes under the front corners, the start button and the laser turret
        rubber = black("rubber")
        return [make_part("body", "body", S.cylinder(r, 0.07, center=(0, 0, 0.045), sections=32), mat),
                make_part("bin", "bin", S.cylinder(r * 0.5, 0.02, center=(0, -r * 0.3, 0.09), sections=20), black()),
                make_part("hose", "hose", S.cylinder(r * 0.15, 0.012, center=(0, r * 0.6, 0.086)), black()),
                *each("wheel", "wheel", [S.cylinder(0.03, 0.02, center=(sx * r * 0.7, 0, 0.03), axis=(1, 0, 0)) for sx in (-1, 1)],
                      rubber),
                make_part("caster", "caster", S.cylinder(0.012, 0.012, center=(0, r * 0.75, 0.012), axis=(1, 0, 0), sections=10),
                          rubber),
                make_part("bumper", "bumper", [S.box((r * 0.6, 0.012, 0.05), center=(np.sin(a) * (r + 0.006), np.cos(a) * (r + 0.006), 0.045),
                                                     R=rot((0, 0, 1), -a)) for a in np.linspace(-1.2, 1.2, 5)], black()),
                *[make_part(f"side_brush_{k}", "side_brush", [S.cylinder(0.006, 0.01, center=(sx * r * 0.6, r * 0.6, 0.012), sections=8)]
                            + [S.box((0.05, 0.002, 0.002), center=(sx * r * 0.6 + np.cos(a) * 0.025, r * 0.6 + np.sin(a) * 0.025, 0.008),
                                     R=rot((0, 0, 1), a)) for a in (0.3, 2.4, 4.5)], black())
                  for k, sx in enumerate((-1, 1))],
                make_part("button", "button", S.cylinder(0.012, 0.004, center=(0, r * 0.35, 0.082), sections=12), white(rng, "plastic")),
                make_part("sensor", "sensor", S.cylinder(0.04, 0.025, center=(0, r * 0.1, 0.0925), sections=16), black()),
                # the two charging contacts under the front, flush with the underside
                *studs("contact", "contact", [(sx * r * 0.3, r * 0.55, 0.0105) for sx in (-1, 1)], r=0.008, h=0.001,
                       mat=M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9))]
    if variant == "upright":
        h = rng.uniform(1.05, 1.2)
        return [make_part("nozzle", "nozzle", S.box((0.32, 0.25, 0.08), center=(0, 0.05, 0.04), bevel=0.01), mat),
                make_part("body", "body", S.box((0.26, 0.2, h * 0.5), center=(0, -0.07, 0.08 + h * 0.25), bevel=0.02), mat),
                make_part("bin", "bin", S.cylinder(0.07, h * 0.3, center=(0, 0.0, 0.15 + h * 0.15)), M.glass(rng)),
                make_part("hose", "hose", S.tube([(0.1, -0.17, 0.15), (0.1, -0.2, h * 0.6)], 0.02), black()),
                make_part("handle", "handle", S.tube([(0, -0.1, 0.08 + h * 0.5), (0, -0.12, h - 0.02)], 0.016), black()),
                *each("wheel", "wheel", [S.cylinder(0.04, 0.03, center=(sx * 0.14, -0.12, 0.04), axis=(1, 0, 0)) for sx in (-1, 1)],
                      black("rubber")),
                # the grip on the handle's top, the power pedal, the two hooks the cord is wound on
                make_part("grip", "grip", S.cylinder(0.02, 0.1, center=(0, -0.12, h - 0.07), sections=12), black("rubber")),
                make_part("switch", "switch", S.box((0.05, 0.04, 0.02), center=(0.1, -0.17, 0.09)), black()),
                *[make_part(f"cord_hook_{k}", "cord_hook", S.box((0.03, 0.03, 0.015), center=(0, -0.185, z)), mat)
                  for k, z in enumerate((0.08 + h * 0.08, 0.08 + h * 0.45))],
                # the power cord wound between the two hooks, and its plug clipped to the upper one
                make_part("cord", "cord", S.box((0.024, 0.016, h * 0.37 - 0.015), center=(0, -0.188, 0.08 + h * 0.265)), black()),
                make_part("plug", "plug", S.box((0.02, 0.012, 0.03), center=(0.027, -0.185, 0.08 + h * 0.45 - 0.02)), black())]
    L = rng.uniform(0.38, 0.45)
    out = [make_part("body", "body", S.ellipsoid((0.14, L / 2, 0.13), center=(0, 0, 0.14)), mat),
           *each("wheel", "wheel", [S.cylinder(0.07, 0.03, center=(sx * 0.13, -L * 0.25, 0.07), axis=(1, 0, 0)) for sx in (-1, 1)],
                 black("rubber")),
           make_part("hose", "hose", S.tube([(0, L / 2 - 0.02, 0.2), (0, L / 2 + 0.15, 0.3), (0.1, L / 2 + 0.35, 0.25)], 0.02),
                     black()),
           make_part("wand", "wand", S.tube([(0.1, L / 2 + 0.35, 0.25), (0.1, L / 2 + 0.9, 0.04)], 0.016), M.metal(rng)),
           make_part("nozzle", "nozzle", S.box((0.28, 0.08, 0.04), center=(0.1, L / 2 + 0.92, 0.02)), mat)]
    # the swivel caster under the front, the carry handle on top, the cord-rewind button, and
    # the cuff where the hose plugs into the body
    out += [make_part("caster", "caster", S.cylinder(0.015, 0.015, center=(0, L * 0.25, 0.015), axis=(1, 0, 0), sections=10),
                      black("rubber")),
            make_part("handle", "handle", S.tube([(0, -L * 0.15, 0.262), (0, -L * 0.05, 0.3), (0, L * 0.15, 0.262)], 0.012,
                                                 sections=8), black()),
            make_part("button", "button", S.cylinder(0.015, 0.01, center=(0.07, -L * 0.3, 0.222), sections=10), black()),
            make_part("cuff", "cuff", S.cylinder(0.028, 0.04, center=(0, L / 2 - 0.01, 0.2), axis=(0, 1, 0), sections=12), black())]
    # the plug of the cord wound in on its reel, resting in the cord outlet low on the back
    out.append(make_part("plug", "plug", S.box((0.03, 0.02, 0.02), center=(0, -L * 0.475 + 0.002, 0.1), bevel=0.002), black()))
    return out


@register("plunger", parts=("handle", "cup"), extra_parts=("holder", "cap", "collar"),
          size_range=(0.4, 0.62), density=600, variants=("sink", "flange", "with_holder"),
          placement="floor")
def plunger(rng: np.random.Generator, variant: str) -> list[Part]:
    h = rng.uniform(0.42, 0.58)
    r = rng.uniform(0.06, 0.075)
    out = [make_part("cup", "cup", S.lathe([(r, 0.0), (r * 0.95, 0.05), (r * 0.35, 0.08)], sections=24),
                     M.solid(M.jitter(rng, (0.75, 0.1, 0.1), 0.05), "rubber", 0.6)),
           make_part("handle", "handle", S.cylinder(0.012, h - 0.08, center=(0, 0, 0.08 + (h - 0.08) / 2)), M.wood(rng))]
    if variant == "flange":
        out.append(make_part("flange", "cup", S.cylinder(r * 0.5, 0.03, center=(0, 0, 0.015)), out[0].material))
    if variant == "with_holder":
        out.append(make_part("holder", "holder", shell([(r * 1.15, 0.0), (r * 1.2, 0.1)], 0.003, bottom=0.004, sections=20),
                             M.plastic(rng)))
        out[0] = make_part("cup", "cup", S.lathe([(r, 0.004), (r * 0.95, 0.054), (r * 0.35, 0.084)], sections=24),
                           out[0].material)
    # the hanging cap on the handle's top and the collar gripping the handle in the cup's neck
    out.append(make_part("cap", "cap", S.cylinder(0.015, 0.025, center=(0, 0, h - 0.0125), sections=12), black()))
    out.append(make_part("collar", "collar", S.cylinder(0.016, 0.02, center=(0, 0, 0.085 + 0.01), sections=12), out[0].material))
    return out


@register("dustpan", parts=("pan", "handle"), extra_parts=("lip", "brush", "comb", "hang_loop", "bristles", "grip", "pivot"),
          size_range=(0.25, 0.95), density=800, variants=("hand", "upright", "with_brush"),
          placement="floor")
def dustpan(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.22, 0.3), rng.uniform(0.18, 0.25)
    mat = M.plastic(rng)
    t = 0.004
    pan = [S.box((w, d, t), center=(0, 0, t / 2)), S.box((w, t, 0.06), center=(0, -d / 2 + t / 2, 0.03)),
           S.box((t, d, 0.05), center=(-w / 2 + t / 2, 0, 0.025)), S.box((t, d, 0.05), center=(w / 2 - t / 2, 0, 0.025))]
    out = [make_part("pan", "pan", pan, mat),
           make_part("lip", "lip", S.box((w, 0.02, 0.002), center=(0, d / 2 + 0.01, 0.001)), black("rubber"))]
    if variant == "upright":
        out.append(make_part("handle", "handle", S.tube([(0, -d / 2, 0.05), (0, -d / 2 - 0.05, 0.85)], 0.012), mat))
    else:
        out.append(make_part("handle", "handle", S.box((0.04, 0.12, 0.025), center=(0, -d / 2 - 0.06, 0.05)), mat))
    if variant == "with_brush":
        out.append(make_part("brush", "brush", [S.box((w * 0.9, 0.04, 0.02), center=(0, 0.0, t + 0.03)),
                                                S.box((0.03, 0.15, 0.02), center=(0, -0.08, t + 0.05))], M.plastic(rng)))
        # the brush's bristles in two rows of tufts under its back
        out += tufts("bristles", "bristles", nx=6, ny=2, x0=-w * 0.38, x1=w * 0.38, y0=-0.01, y1=0.01, z=t + 0.02,
                     length=0.02 - 0.001, r=0.006, mat=M.solid((0.25, 0.25, 0.25), "plastic", 0.8), down=True)
    # the comb of teeth on the back wall's top edge for cleaning a broom, and where it hangs
    # or pivots
    out.append(make_part("comb", "comb", [S.box((0.004, 0.004, 0.012), center=(x, -d / 2 + t / 2, 0.066))
                                          for x in np.linspace(-w * 0.3, w * 0.3, 9)], mat))
    if variant == "upright":
        out.append(make_part("pivot", "pivot", S.cylinder(0.018, 0.03, center=(0, -d / 2 - 0.01, 0.05), axis=(1, 0, 0), sections=10),
                             black()))
        out.append(make_part("grip", "grip", S.cylinder(0.016, 0.1, center=(0, -d / 2 - 0.05 + 0.003, 0.79), sections=10),
                             black("rubber")))
    else:
        out.append(make_part("hang_loop", "hang_loop", S.tube([(-0.01, -d / 2 - 0.115, 0.05), (0, -d / 2 - 0.14, 0.05),
                                                               (0.01, -d / 2 - 0.115, 0.05)], 0.003, sections=6), black()))
    return out


@register("hair_dryer", parts=("body", "handle"),
          extra_parts=("nozzle", "switch", "cord", "filter", "button", "hang_loop", "plug", "cord_guard", "vent"),
          size_range=(0.15, 0.3), density=500, variants=("classic", "compact", "diffuser"),
          placement="surface")
def hair_dryer(rng: np.random.Generator, variant: str) -> list[Part]:
    # lying on its side on a counter: the barrel along X, the handle along -Y
    L = rng.uniform(0.2, 0.25) if variant != "compact" else rng.uniform(0.16, 0.19)
    r = rng.uniform(0.04, 0.05)
    mat = black() if rng.uniform() < 0.5 else M.plastic(rng)
    out = [make_part("body", "body", S.cylinder(r, L * 0.7, center=(-L * 0.15, 0, r), axis=(1, 0, 0)), mat),
           make_part("filter", "filter", S.cylinder(r * 0.9, 0.01, center=(-L / 2 + 0.005, 0, r), axis=(1, 0, 0)), black()),
           make_part("handle", "handle", S.box((0.035, L * 0.55, 0.03), center=(-L * 0.2, -r - L * 0.27, 0.03 - 0.015 + 0.015),
                                               bevel=0.008), mat),
           make_part("switch", "switch", S.box((0.012, 0.02, 0.008), center=(-L * 0.2, -r - L * 0.2, 0.034)), white(rng, "plastic"))]
    if variant == "diffuser":
        out.append(make_part("nozzle", "nozzle", S.frustum(r * 0.9, r * 1.5, L * 0.3, center=(L * 0.2, 0, r * 1.5), axis=(1, 0, 0)),
                             mat))
    else:
        out.append(make_part("nozzle", "nozzle", S.frustum(r * 0.9, r * 0.55, L * 0.3, center=(L * 0.2, 0, r), axis=(1, 0, 0)),
                             mat))
    # the heat switch beside the speed switch, the cool-shot button, the strain relief where the
    # cord leaves the handle, the cord and its plug, the loop at the handle's end and the air
    # inlet slots round the back of the barrel
    hy = -r - L * 0.545
    light = white(rng, "plastic")
    out += [make_part("switch_1", "switch", S.box((0.012, 0.02, 0.008), center=(-L * 0.2, -r - L * 0.3, 0.034)), light),
            make_part("button", "button", S.box((0.012, 0.012, 0.008), center=(-L * 0.2, -r - 0.015, 0.034)), light),
            make_part("cord_guard", "cord_guard", S.cylinder(0.008, 0.03, center=(-L * 0.2, hy - 0.015, 0.02), axis=(0, 1, 0),
                                                             sections=10), black("rubber")),
            make_part("cord", "cord", S.tube([(-L * 0.2, hy - 0.03, 0.02), (-L * 0.05, hy - 0.04, 0.005),
                                              (L * 0.25, hy - 0.02, 0.005)], 0.003, sections=6), black()),
            make_part("plug", "plug", S.box((0.03, 0.025, 0.012), center=(L * 0.25 + 0.015, hy - 0.02, 0.006), bevel=0.002), black()),
            make_part("hang_loop", "hang_loop", S.tube([(-L * 0.2 - 0.008, hy + 0.01, 0.03), (-L * 0.2, hy - 0.005, 0.03),
                                                        (-L * 0.2 + 0.008, hy + 0.01, 0.03)], 0.002, sections=6), black())]
    out += [make_part(f"vent_{k}", "vent", S.box((L * 0.12, 0.003, 0.006),
                                                 center=(-L * 0.4, np.cos(a) * (r + 0.0005), r + np.sin(a) * (r + 0.0005)),
                                                 R=rot((1, 0, 0), a)), black())
            for k, a in enumerate(np.linspace(0.6, np.pi - 0.6, 4))]
    return out


@register("fire_extinguisher", parts=("cylinder", "valve"),
          extra_parts=("hose", "handle", "gauge", "bracket", "lever", "pin", "pull_ring", "nozzle", "label", "strap", "hose_clip",
                       "tag", "screw"),
          size_range=(0.3, 0.75), density=1200, variants=("standing", "wall_bracket", "small"),
          placement="floor")
def fire_extinguisher(rng: np.random.Generator, variant: str) -> list[Part]:
    h = rng.uniform(0.45, 0.6) if variant != "small" else rng.uniform(0.3, 0.38)
    r = h * rng.uniform(0.14, 0.17)
    red = M.solid(M.jitter(rng, (0.8, 0.08, 0.06), 0.03), "metal", 0.3, 0.4)
    out = [make_part("cylinder", "cylinder", S.lathe([(r, 0.0), (r, h * 0.82), (r * 0.5, h * 0.92), (r * 0.3, h * 0.95)]), red),
           make_part("valve", "valve", S.cylinder(r * 0.28, h * 0.06, center=(0, 0, h * 0.98)), M.metal(rng)),
           make_part("handle", "handle", S.box((0.02, r * 2.2, 0.012), center=(0, 0, h * 1.02)), black("metal")),
           make_part("gauge", "gauge", S.cylinder(0.015, 0.01, center=(0, r * 0.35, h * 0.98), axis=(0, 1, 0)), white(rng, "glass")),
           make_part("hose", "hose", S.tube([(0, -r * 0.3, h * 0.97), (0, -r * 1.1, h * 0.9), (0, -r * 1.1, h * 0.3)], 0.008),
                     black("rubber"))]
    if variant == "wall_bracket":
        out.append(make_part("bracket", "bracket", S.box((r * 1.2, 0.01, h * 0.3), center=(0, -r - 0.005, h * 0.55)), M.metal(rng)))
        out.append(make_part("strap", "strap", ring([(r, h * 0.6 - 0.01), (r + 0.003, h * 0.6 - 0.01), (r + 0.003, h * 0.6 + 0.01),
                                                     (r, h * 0.6 + 0.01)], sections=20), black("metal")))
        # the two screws through the bracket into the wall, their heads on its front between
        # the bracket's edge and the cylinder
        out += studs("screw", "screw", [(sx * r * 0.45, -r - 0.0005, z) for sx in (-1, 1) for z in (h * 0.45,)], r=0.004, h=0.001,
                     mat=M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8), axis=(0, 1, 0))
    # the squeeze lever above the carrying handle, the safety pin through both with its pull
    # ring, the horn at the hose's end and the instruction label (sections with no flat
    # annulus, the costliest surface to resolve)
    steel = out[1].material
    out += [make_part("lever", "lever", S.box((0.02, r * 2.0, 0.01), center=(0, -r * 0.1, h * 1.05), R=rot((1, 0, 0), 0.15)),
                      black("metal")),
            make_part("pin", "pin", S.cylinder(0.002, 0.04, center=(0, r * 0.25, h * 1.035), axis=(1, 0, 0), sections=6), steel),
            make_part("pull_ring", "pull_ring", S.transformed(ring([(0.008, 0.0), (0.0095, -0.0015), (0.011, 0.0), (0.0095, 0.0015)],
                                                                   sections=10),
                                                               np.array([[0, 0, 1, 0.022], [0, 1, 0, r * 0.25],
                                                                         [-1, 0, 0, h * 1.035], [0, 0, 0, 1.0]])), steel),
            make_part("nozzle", "nozzle", S.frustum(0.01, 0.016, 0.05, center=(0, -r * 1.1, h * 0.3 - 0.05 + 0.05),
                                                    axis=(0, 0, -1), sections=10), black()),
            make_part("label", "label", ring([(r - 0.0005, h * 0.3), (r + 0.0008, h * 0.3 + 0.002), (r + 0.0008, h * 0.65 - 0.002),
                                              (r - 0.0005, h * 0.65)], sections=24), M.solid((0.95, 0.95, 0.9), "paper", 0.6))]
    # the clip on the cylinder's side holding the hose's end, and the inspection tag hanging
    # from the safety pin
    out.append(make_part("hose_clip", "hose_clip", S.box((0.03, 0.012, 0.014), center=(0, -r - 0.002, h * 0.3 + 0.01)), black()))
    out.append(make_part("tag", "tag", S.box((0.03, 0.001, 0.045), center=(0.0, r * 0.25 + 0.004, h * 1.035 - 0.026)),
                         M.solid((0.95, 0.85, 0.2), "paper", 0.7)))
    return out


@register("guitar_case", parts=("shell", "handle"), extra_parts=("latch", "lid", "hinge", "strap", "foot", "zipper", "pull",
                                                                "pocket", "handle_mount"),
          size_range=(0.95, 1.3), density=200, variants=("hard", "gig_bag", "electric"),
          placement="floor")
def guitar_case(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    L = rng.uniform(1.0, 1.12) if variant != "electric" else rng.uniform(1.0, 1.05)
    wl, wu = rng.uniform(0.38, 0.44), rng.uniform(0.28, 0.32)
    t = rng.uniform(0.11, 0.14)
    mat = black() if variant != "gig_bag" else M.fabric(rng)
    # lying flat: the body end at -X, the neck toward +X
    outline = np.array([[-L / 2, -wl / 2], [-L / 2 + 0.3, -wl / 2], [-L / 2 + 0.55, -wu / 2], [L / 2, -0.07],
                        [L / 2, 0.07], [-L / 2 + 0.55, wu / 2], [-L / 2 + 0.3, wl / 2], [-L / 2, wl / 2]])
    base = S.hull(np.vstack([np.c_[outline, np.zeros(8)], np.c_[outline, np.full(8, t * 0.6)]]))
    lid = S.hull(np.vstack([np.c_[outline, np.full(8, t * 0.6)], np.c_[outline * 0.98, np.full(8, t)]]))
    out: list[Part | Joint] = [make_part("shell", "shell", base, mat), make_part("lid", "lid", lid, mat),
                               make_part("handle", "handle", S.box((0.12, 0.03, 0.02), center=(-L / 2 + 0.5, wu / 2 + 0.02, t * 0.5)),
                                         black("leather"))]
    if variant != "gig_bag":
        out += each("latch", "latch", [S.box((0.03, 0.012, 0.02), center=(x, wl / 2 + 0.006 - 0.012, t * 0.6))
                                       for x in (-L / 2 + 0.15, -L / 2 + 0.7)], M.metal(rng))
        out += hinge_parts("lid_hinge", x=t * 0.6, y=-wl / 2, z0=-L / 2 + 0.05, z1=-L / 2 + 0.3, mat=M.metal(rng), axis="x",
                           radius=0.005, length=0.03)
        out.append(revolute("lid_hinge", "shell", "lid", axis=(1, 0, 0), origin=(0, -wl / 2, t * 0.6), opens=1.3))
        # the two end mounts holding the handle on the side of the shell
        xh, yh = -L / 2 + 0.5, wu / 2 + 0.02
        out += each("handle_mount", "handle_mount", [S.box((0.014, 0.02, 0.03), center=(xh + sx * 0.066, yh - 0.004, t * 0.5))
                                                     for sx in (-1, 1)], M.metal(rng))
        # four bumper feet on the body end, the case stands upright on them
        out += studs("foot", "foot", [(-L / 2 - 0.004, y, z) for y in (-wl * 0.3, wl * 0.3) for z in (t * 0.25, t * 0.75)],
                     r=0.012, h=0.008, mat=black("rubber"), axis=(1, 0, 0))
    else:  # the zip round the seam with its two pullers, and the accessory pocket on the front
        seam = np.c_[outline * 1.004, np.full(8, t * 0.6)]
        out.append(make_part("zipper", "zipper", S.tube(seam, 0.004, sections=6, closed=True), black()))
        out += studs("pull", "pull", [(L / 2 - 0.02, wu * 0.0 - 0.07 * 1.004 - 0.012, t * 0.6), (L / 2 - 0.02, 0.07 * 1.004 + 0.012, t * 0.6)],
                     r=0.006, h=0.004, mat=M.metal(rng), axis=(0, 1, 0))
        out.append(make_part("pocket", "pocket", S.box((0.3, 0.2, 0.02), center=(-L / 2 + 0.62, 0, t + 0.01 - 0.002), bevel=0.006),
                             mat))
    return out


@register("dish_rack", parts=("rack", "tray"), extra_parts=("tine", "cutlery_holder", "foot", "spout"),
          size_range=(0.3, 0.55), density=500, variants=("wire", "plastic", "two_tier"),
          placement="surface")
def dish_rack(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.35, 0.5), rng.uniform(0.28, 0.36)
    h = rng.uniform(0.1, 0.14)
    wire = M.metal(rng) if variant != "plastic" else M.plastic(rng)
    out = [make_part("tray", "tray", S.box((w + 0.02, d + 0.02, 0.015), center=(0, 0, 0.0075)), M.plastic(rng))]
    rails = [S.tube([(-w / 2, sy * d / 2, z), (w / 2, sy * d / 2, z)], 0.003, sections=6) for sy in (-1, 1) for z in (0.03, h)]
    rails += [S.tube([(sx * w / 2, -d / 2, z), (sx * w / 2, d / 2, z)], 0.003, sections=6) for sx in (-1, 1) for z in (0.03, h)]
    rails += [S.tube([(sx * w / 2, sy * d / 2, 0.015), (sx * w / 2, sy * d / 2, h)], 0.003, sections=6) for sx in (-1, 1) for sy in (-1, 1)]
    # the floor grid plates and glasses stand on, the tines' feet on it
    rails += [S.tube([(-w / 2, y, 0.03), (w / 2, y, 0.03)], 0.0025, sections=6)
              for y in np.linspace(-d / 2, d / 2, round(d / 0.016) + 1)[1:-1]]
    out.append(make_part("rack", "rack", rails, wire))
    # the row of tines plates stand between, each its own wire
    out += each("tine", "tine", [S.tube([(x, -d * 0.3, 0.03), (x, -d * 0.3, 0.03 + h * 0.7)], 0.0025, sections=6)
                                 for x in np.linspace(-w * 0.4, w * 0.2, 8)], wire)
    # the drain spout at the tray's front edge
    out.append(make_part("spout", "spout", S.box((0.04, 0.03, 0.006), center=(w * 0.3, d / 2 + 0.01 + 0.015, 0.006)),
                         out[0].material))
    out.append(make_part("cutlery_holder", "cutlery_holder", S.box((0.08, 0.1, h * 0.9), center=(w / 2 - 0.05, d * 0.2, 0.015 + h * 0.45)),
                         M.plastic(rng)))
    if variant == "two_tier":
        # the cup tier on posts high enough for a dinner plate standing in the tines below
        out.append(make_part("rack_upper", "rack", S.box((w * 0.6, d * 0.9, 0.004), center=(-w * 0.15, 0, h + 0.2)), wire))
        out.append(make_part("post", "rack", [S.tube([(sx * w * 0.3 - w * 0.15, 0, h), (sx * w * 0.3 - w * 0.15, 0, h + 0.2)], 0.003)
                                              for sx in (-1, 1)], wire))
    return out


@register("storage_bin", parts=("body",), extra_parts=("lid", "handle", "label", "wheel", "latch", "rim", "foot", "rib"),
          size_range=(0.3, 0.8), density=400, variants=("lidded", "open", "wheeled"),
          placement="floor")
def storage_bin(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.35, 0.7), rng.uniform(0.28, 0.45), rng.uniform(0.2, 0.4)
    mat = M.solid(M.jitter(rng, [(0.85, 0.87, 0.9), (0.2, 0.3, 0.6), (0.15, 0.15, 0.15)][int(rng.integers(3))], 0.03), "plastic", 0.4)
    wh = 0.04 if variant == "wheeled" else 0.0
    t = 0.005
    walls = [S.box((w * 0.94, d * 0.94, t), center=(0, 0, wh + t / 2)),
             S.box((w, t, h), center=(0, -d / 2 + t / 2, wh + h / 2)), S.box((w, t, h), center=(0, d / 2 - t / 2, wh + h / 2)),
             S.box((t, d - 2 * t, h), center=(-w / 2 + t / 2, 0, wh + h / 2)), S.box((t, d - 2 * t, h), center=(w / 2 - t / 2, 0, wh + h / 2))]
    out = [make_part("body", "body", walls, mat)]
    out += each("handle", "handle", [S.box((0.012, 0.1, 0.02), center=(sx * (w / 2 + 0.006), 0, wh + h * 0.85)) for sx in (-1, 1)],
                mat)
    # the moulded rim round the mouth, thicker than the walls
    rim = [S.box((w + 0.01, 0.005, 0.012), center=(0, sy * (d / 2 + 0.0025), wh + h - 0.006)) for sy in (-1, 1)]
    rim += [S.box((0.005, d, 0.012), center=(sx * (w / 2 + 0.0025), 0, wh + h - 0.006)) for sx in (-1, 1)]
    out.append(make_part("rim", "rim", rim, mat))
    # the moulded ribs stiffening the long walls outside, two on each, under the rim's overhang
    out += [make_part(f"rib_{k}", "rib", S.box((0.012, 0.004, h * 0.8), center=(sx * w / 4, sy * (d / 2 + 0.002), wh + h * 0.5 - 0.006)),
                      mat) for k, (sy, sx) in enumerate((sy, sx) for sy in (-1, 1) for sx in (-1, 1))]
    if variant == "lidded":
        out.append(make_part("lid", "lid", S.box((w + 0.01, d + 0.01, 0.02), center=(0, 0, wh + h + 0.01), bevel=0.004), mat))
        # a latch clipping the lid down at each end
        out += each("latch", "latch", [S.box((0.008, 0.06, 0.04), center=(sx * (w / 2 + 0.009), 0, wh + h + 0.0)) for sx in (-1, 1)],
                    mat)
    if variant == "wheeled":
        out += each("wheel", "wheel", [S.cylinder(wh / 2, 0.02, center=(sx * (w / 2 - 0.05), -d / 2 + 0.05, wh / 2), axis=(1, 0, 0))
                                       for sx in (-1, 1)], black("rubber"))
        # the front stands on two moulded feet, as tall as the wheels
        out += each("foot", "foot", [S.box((0.04, 0.03, wh), center=(sx * (w / 2 - 0.05), d / 2 - 0.05, wh / 2)) for sx in (-1, 1)], mat)

    out.append(make_part("label", "label", S.box((0.1, 0.001, 0.05), center=(0, d / 2 + 0.0005, wh + h * 0.6)), white(rng, "paper")))
    return out


@register("storage_organizer", parts=("frame", "drawer"), extra_parts=("drawer_box", "handle", "top_panel", "caster"),
          size_range=(0.3, 1.05), density=400, variants=("tower", "desktop", "wide"),
          placement="floor")
def storage_organizer(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d = (rng.uniform(0.3, 0.4), rng.uniform(0.35, 0.45)) if variant != "desktop" else (rng.uniform(0.25, 0.35), rng.uniform(0.25, 0.32))
    if variant == "wide":
        w = rng.uniform(0.6, 0.8)
    n = {"tower": int(rng.integers(3, 6)), "desktop": 3, "wide": 3}[variant]
    dh = rng.uniform(0.12, 0.2) if variant != "desktop" else 0.07
    ch = 0.05 if variant == "tower" else 0.0
    h = ch + n * dh + 0.02
    mat = M.plastic(rng)
    t = 0.012
    frame = [S.box((t, d, h - ch), center=(sx * (w / 2 - t / 2), 0, ch + (h - ch) / 2)) for sx in (-1, 1)]
    frame += [S.box((w - 2 * t, t, h - ch), center=(0, -d / 2 + t / 2, ch + (h - ch) / 2)),
              S.box((w - 2 * t, d, t), center=(0, 0, ch + t / 2))]
    out: list[Part | Joint] = [make_part("frame", "frame", frame, mat),
                               make_part("top_panel", "top_panel", S.box((w, d, 0.012), center=(0, 0, h - 0.006)), mat)]
    for k in range(n):
        z0 = ch + t + k * dh
        out += drawer_parts(f"drawer_{k}", x0=-w / 2 + t, x1=w / 2 - t, z0=z0 + 0.003, z1=z0 + dh - 0.003, y_front=d / 2,
                            depth=d - 0.04, thick=0.012, mat=M.solid(M.jitter(rng, (0.9, 0.9, 0.92), 0.05), "plastic", 0.3),
                            handle_mat=mat, parent="frame")
    if ch:
        out += each("caster", "caster", [S.cylinder(ch / 2, 0.02, center=(sx * (w / 2 - 0.04), sy * (d / 2 - 0.04), ch / 2),
                                                    axis=(1, 0, 0)) for sx in (-1, 1) for sy in (-1, 1)], black("rubber"))
    return out


@register("room_divider", parts=("panel", "hinge"), extra_parts=("frame", "foot"),
          size_range=(1.2, 2.6), density=500, variants=("three_panel", "four_panel", "slatted"))
def room_divider(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    n = 4 if variant == "four_panel" else 3
    pw, h = rng.uniform(0.4, 0.5), rng.uniform(1.6, 1.85)
    t = 0.025
    wood = M.wood(rng)
    fill = M.fabric(rng) if variant != "slatted" else wood
    # a zig-zag folded screen: panels alternate +-30 degrees about Z
    out: list[Part | Joint] = []
    ang = 0.5
    x = -(n * pw * np.cos(ang)) / 2
    prev = None
    for k in range(n):
        a = ang if k % 2 == 0 else -ang
        c = np.array([x + pw * np.cos(ang) / 2, 0.0, h / 2 + 0.03])
        R = rot((0, 0, 1), a)
        out.append(make_part(f"panel_{k}", "panel", [S.box((pw, t, h), center=c, R=R)], fill))
        # the panel's wooden frame round the fill: two stiles and the top and bottom rails
        members = [((0.035, t + 0.006, h), (sx * (pw / 2 - 0.0175), 0.0, 0.0)) for sx in (-1, 1)]
        members += [((pw - 0.07, t + 0.006, 0.05), (0.0, 0.0, sz * (h / 2 - 0.025))) for sz in (-1, 1)]
        out += [make_part(f"panel_{k}_{nm}", "frame", S.box(size, center=c + R @ np.asarray(off), R=R), wood)
                for nm, (size, off) in zip(("stile_0", "stile_1", "bottom_rail", "top_rail"), members, strict=True)]
        out.append(make_part(f"panel_{k}_foot", "foot", S.box((0.05, 0.06, 0.03), center=(c[0], 0, 0.015)), wood))
        if prev is not None:
            xh = x
            yh = pw * np.sin(ang) / 2 * (1 if k % 2 == 0 else -1)
            out += hinge_parts(f"hinge_{k}", x=xh, y=-yh, z0=0.3, z1=h - 0.1, mat=M.metal(rng), radius=0.008)
        prev = k
        x += pw * np.cos(ang)
    return out


@register("cart", parts=("shelf", "post"), extra_parts=("caster", "handle", "rail", "bolt"),
          size_range=(0.6, 1.25), density=400, variants=("utility", "rolling_kitchen", "service"))
def cart(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.6, 1.0), rng.uniform(0.38, 0.55), rng.uniform(0.75, 0.95)
    n = 3 if variant != "service" else 2
    mat = M.plastic(rng) if variant == "utility" else M.metal(rng)
    ch = 0.1
    out: list[Part] = []
    for k in range(n):
        z = ch + 0.03 + (h - ch - 0.06) * k / (n - 1)
        out.append(make_part(f"shelf_{k}", "shelf", S.box((w, d, 0.02), center=(0, 0, z)), mat))
        out += each(f"rail_{k}", "rail", [S.box((w, 0.01, 0.04), center=(0, sy * (d / 2 - 0.005), z + 0.03))
                                          for sy in (-1, 1)], mat)
    # four corner posts, and under each a caster: its wheel and the fork it turns in
    out += each("post", "post", [S.cylinder(0.015, h - ch, center=(sx * (w / 2 - 0.02), sy * (d / 2 - 0.02), ch + (h - ch) / 2),
                                            sections=12) for sx in (-1, 1) for sy in (-1, 1)], M.metal(rng))
    out += each("caster", "caster", [S.cylinder(0.045, 0.03, center=(sx * (w / 2 - 0.04), sy * (d / 2 - 0.04), 0.045),
                                                axis=(1, 0, 0)) for sx in (-1, 1) for sy in (-1, 1)], black("rubber"))
    out += each("caster_fork", "caster", [S.box((0.04, 0.04, 0.02), center=(sx * (w / 2 - 0.04), sy * (d / 2 - 0.04), ch - 0.01))
                                          for sx in (-1, 1) for sy in (-1, 1)], M.metal(rng))
    # the bolt through each post into the socket under each shelf's corner, its head on the post's outer face
    zs = [ch + 0.03 + (h - ch - 0.06) * k / (n - 1) for k in range(n)]
    out += [make_part(f"bolt_{k}", "bolt", S.cylinder(0.006, 0.002, center=(sx * (w / 2 - 0.004), sy * (d / 2 - 0.02), z - 0.02), axis=(1, 0, 0),
                                                      sections=8), M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8))
            for k, (z, sx, sy) in enumerate((z, sx, sy) for z in zs for sx in (-1, 1) for sy in (-1, 1))]
    out.append(make_part("handle", "handle", S.tube([(-w / 2 - 0.005, -d * 0.35, h - 0.05), (-w / 2 - 0.08, -d * 0.35, h),
                                                     (-w / 2 - 0.08, d * 0.35, h), (-w / 2 - 0.005, d * 0.35, h - 0.05)], 0.012), black()))
    return out


@register("digital_piano", parts=("body", "keyboard"), extra_parts=("key", "stand", "pedal", "music_rest", "display", "leg"),
          size_range=(0.9, 1.45), density=400, variants=("console", "stage", "portable"))
def digital_piano(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(1.25, 1.4) if variant != "portable" else rng.uniform(0.95, 1.05)
    d = rng.uniform(0.28, 0.4)
    mat = black() if rng.uniform() < 0.7 else M.wood(rng)
    kh = rng.uniform(0.72, 0.78)
    out = [make_part("body", "body", S.box((w, d, 0.1), center=(0, 0, kh + 0.05), bevel=0.006), mat),
           # the key bed, the 52 white keys on it and the black keys above them
           make_part("keyboard", "keyboard", S.box((w * 0.9, d * 0.5, 0.005), center=(0, d * 0.2, kh + 0.1 + 0.0025)), black()),
           *white_keys(-w * 0.45, w * 0.45, y_front=d * 0.45, depth=d * 0.5, z0=kh + 0.105, z1=kh + 0.12, mat=white(rng, "plastic")),
           *each("key", "key", [S.box((0.012, d * 0.28, 0.012), center=(x, d * 0.08, kh + 0.126))
                                for x in np.linspace(-w * 0.43, w * 0.43, 36)], black()),
           make_part("music_rest", "music_rest", S.box((w * 0.5, 0.01, 0.2), center=(0, -d * 0.3, kh + 0.2 + 0.1), R=rot((1, 0, 0), 0.2)),
                     mat)]
    if variant == "console":
        # two side panels and the back panel; three pedals
        out += each("stand", "stand", [S.box((0.03, d, kh), center=(sx * (w / 2 - 0.015), 0, kh / 2)) for sx in (-1, 1)]
                    + [S.box((w - 0.06, 0.02, kh * 0.6), center=(0, -d / 2 + 0.01, kh * 0.5))], mat)
        out += each("pedal", "pedal", [S.box((0.04, 0.1, 0.02), center=(x, 0.0, 0.04)) for x in (-0.08, 0, 0.08)],
                    M.metal(rng))
    else:  # an X stand
        steel = M.metal(rng)
        out += each("leg", "leg", [S.box((0.03, 0.03, kh / np.cos(0.6)), center=(sx * w * 0.2, 0, kh / 2), R=rot((0, 1, 0), a))
                                   for sx in (-1, 1) for a in (0.6, -0.6)], steel)
    return out


@register("fan", parts=("base", "blade", "grille"), extra_parts=("pole", "motor", "button", "knob", "handle", "hub", "guard_clip",
                                                                   "foot"),
          size_range=(0.3, 1.45), density=400, variants=("desk", "pedestal", "box"),
          placement="floor")
def fan(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = white(rng, "plastic") if rng.uniform() < 0.5 else black()
    if variant == "box":
        s = rng.uniform(0.4, 0.55)
        out = [make_part("base", "base", [S.box((s, 0.12, 0.02), center=(0, 0, 0.01 + zz)) for zz in (0.0, s - 0.02)]
                         + [S.box((0.02, 0.12, s - 0.04), center=(sx * (s / 2 - 0.01), 0, s / 2)) for sx in (-1, 1)], mat),
               make_part("grille", "grille", [S.box((s - 0.04, 0.004, 0.004), center=(0, sy * 0.05, z)) for sy in (-1, 1)
                                              for z in np.linspace(0.05, s - 0.05, 8)], mat),
               make_part("motor", "motor", S.cylinder(0.05, 0.06, center=(0, -0.02, s / 2), axis=(0, 1, 0)), mat)]
        out += [make_part(f"blade_{k}", "blade", S.box((s * 0.38, 0.006, 0.08), center=(np.cos(a) * s * 0.2, 0.0, s / 2 + np.sin(a) * s * 0.2),
                                                       R=rot((0, 1, 0), -a)), M.plastic(rng)) for k, a in enumerate(np.linspace(0, 2 * np.pi, 5, endpoint=False))]
        # the carry handle in the top, the speed knob on a corner, the spinner cap at the hub and
        # two feet the frame stands on
        out += [make_part("handle", "handle", S.box((0.12, 0.03, 0.015), center=(0, 0, s + 0.0075), bevel=0.004), mat),
                make_part("knob", "knob", S.cylinder(0.018, 0.015, center=(s / 2 - 0.045, 0.0675, s - 0.05), axis=(0, 1, 0),
                                                     sections=12), black()),
                make_part("hub", "hub", S.cylinder(0.03, 0.02, center=(0, 0.013, s / 2), axis=(0, 1, 0), sections=12), mat),
                *each("foot", "foot", [S.box((0.04, 0.16, 0.008), center=(sx * (s / 2 - 0.05), 0, 0.004)) for sx in (-1, 1)],
                      black("rubber"))]
        return out
    r = rng.uniform(0.14, 0.22)
    hz = rng.uniform(0.3, 0.4) if variant == "desk" else rng.uniform(1.0, 1.25)
    out = [make_part("base", "base", S.cylinder(0.14 if variant != "desk" else 0.1, 0.03, center=(0, 0, 0.015), sections=24), mat),
           make_part("pole", "pole", S.cylinder(0.015, hz - 0.03, center=(0, 0, 0.03 + (hz - 0.03) / 2)), mat),
           make_part("motor", "motor", S.cylinder(0.06, 0.12, center=(0, -0.06, hz), axis=(0, 1, 0)), mat)]
    grille = S.transformed(ring([(r, -0.05), (r + 0.01, -0.05), (r + 0.01, 0.05), (r, 0.05)], sections=28),
                           np.array([[1, 0, 0, 0], [0, 0, -1, 0.05], [0, 1, 0, hz], [0, 0, 0, 1.0]]))
    out.append(make_part("grille", "grille", grille, mat))
    for k, a in enumerate(np.linspace(0, 2 * np.pi, 3, endpoint=False)):
        out.append(make_part(f"blade_{k}", "blade", S.box((r * 0.8, 0.006, r * 0.4), center=(np.cos(a) * r * 0.45, 0.04, hz + np.sin(a) * r * 0.45),
                                                          R=rot((0, 1, 0), -a)), M.glass(rng)))
    out.append(make_part("button", "button", S.box((0.03, 0.02, 0.01), center=(0, 0.05, 0.035)), black()))
    # three more speed buttons beside it, the spinner cap on the blades' hub, the knob that
    # locks the head's tilt, and the clips joining the front guard to the back one
    out += [make_part(f"button_{k}", "button", S.box((0.018, 0.02, 0.01), center=(0.03 * k, 0.05 - 0.012, 0.035)), black())
            for k in (1, 2, 3)]
    out.append(make_part("hub", "hub", S.cylinder(0.035, 0.03, center=(0, 0.058, hz), axis=(0, 1, 0), sections=12), mat))
    out.append(make_part("knob", "knob", S.cylinder(0.015, 0.02, center=(0.06 + 0.01, -0.06, hz), axis=(1, 0, 0), sections=10),
                         mat))
    out += [make_part(f"guard_clip_{k}", "guard_clip", S.box((0.012, 0.03, 0.015),
                                                             center=(np.cos(a) * (r + 0.016), 0.05, hz + np.sin(a) * (r + 0.016)),
                                                             R=rot((0, 1, 0), -a)), mat)
            for k, a in enumerate(np.linspace(0, 2 * np.pi, 4, endpoint=False) + np.pi / 4)]
    return out


@register("sink", parts=("basin", "faucet"), extra_parts=("drain", "pedestal", "bracket", "handle", "countertop", "overflow",
                                                            "aerator", "escutcheon", "trap"),
          size_range=(0.4, 1.1), density=2000, variants=("wall_hung", "pedestal", "utility"),
          placement="floor")
def sink(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.45, 0.6), rng.uniform(0.35, 0.48)
    h = rng.uniform(0.8, 0.88)
    bh = 0.18
    mat = M.ceramic(rng) if variant != "utility" else M.plastic(rng)
    t = 0.02
    z0 = h - bh
    basin = [S.box((w - 2 * t, d - 2 * t, t), center=(0, 0, z0 + t / 2)),
             S.box((w, t, bh), center=(0, -d / 2 + t / 2, z0 + bh / 2)), S.box((w, t, bh), center=(0, d / 2 - t / 2, z0 + bh / 2)),
             S.box((t, d - 2 * t, bh), center=(-w / 2 + t / 2, 0, z0 + bh / 2)), S.box((t, d - 2 * t, bh), center=(w / 2 - t / 2, 0, z0 + bh / 2))]
    out = [make_part("basin", "basin", basin, mat),
           make_part("drain", "drain", S.cylinder(0.02, 0.003, center=(0, 0.02, z0 + t + 0.0015)), M.metal(rng)),
           make_part("faucet", "faucet", S.tube([(0, -d / 2 + 0.03, h), (0, -d / 2 + 0.03, h + 0.15), (0, -d / 2 + 0.15, h + 0.15),
                                                 (0, -d / 2 + 0.15, h + 0.1)], 0.012), M.metal(rng)),
           make_part("handle", "handle", S.box((0.02, 0.07, 0.015), center=(0.06, -d / 2 + 0.04, h + 0.01)), M.metal(rng))]
    # the overflow hole's cover on the back wall, the aerator in the spout's tip, the plate under
    # the faucet and, below the basin, the trap bend of the waste pipe
    chrome = out[1].material
    out += [make_part("overflow", "overflow", S.cylinder(0.015, 0.003, center=(0, -d / 2 + t + 0.0015, h - 0.05), axis=(0, 1, 0),
                                                         sections=12), chrome),
            make_part("aerator", "aerator", S.cylinder(0.011, 0.012, center=(0, -d / 2 + 0.15, h + 0.1 - 0.006), sections=10), chrome),
            make_part("escutcheon", "escutcheon", S.cylinder(0.03, 0.006, center=(0, -d / 2 + 0.03, h + 0.003), sections=16), chrome),
            make_part("trap", "trap", S.tube([(0, 0.02, z0), (0, 0.02, z0 - 0.1), (0, -0.04, z0 - 0.16), (0, -d / 2 + 0.01, z0 - 0.12)],
                                             0.018, sections=10), chrome)]
    if variant == "pedestal":
        out.append(make_part("pedestal", "pedestal", S.lathe([(0.12, 0.0), (0.09, 0.1), (0.08, z0 - 0.1), (0.14, z0)], sections=24), mat))
    elif variant == "utility":
        out += each("pedestal", "pedestal", [S.box((0.04, 0.04, z0), center=(sx * (w / 2 - 0.03), sy * (d / 2 - 0.03), z0 / 2))
                                             for sx in (-1, 1) for sy in (-1, 1)], M.metal(rng))
    else:
        out += each("bracket", "bracket", [S.box((0.03, 0.03, z0), center=(sx * (w / 2 - 0.06), -d / 2 + 0.02, z0 / 2))
                                           for sx in (-1, 1)], M.metal(rng))
    return out


@register("mattress", parts=("body",), extra_parts=("top_panel", "border", "handle", "piping", "tuft", "vent", "label"),
          size_range=(1.85, 2.15), density=150, variants=("twin", "double", "king"))
def mattress(rng: np.random.Generator, variant: str) -> list[Part]:
    w = {"twin": rng.uniform(0.9, 1.0), "double": rng.uniform(1.35, 1.45), "king": rng.uniform(1.8, 1.95)}[variant]
    L, h = rng.uniform(1.9, 2.05), rng.uniform(0.18, 0.3)
    fab = M.solid(M.jitter(rng, (0.93, 0.93, 0.9), 0.02), "fabric", 0.9)
    out = [make_part("body", "body", S.box((w, L, h - 0.03), center=(0, 0, (h - 0.03) / 2), bevel=0.02), fab),
           make_part("top_panel", "top_panel", S.box((w - 0.02, L - 0.02, 0.03), center=(0, 0, h - 0.015), bevel=0.01), fab),
           make_part("piping", "piping", S.box((w + 0.006, L + 0.006, 0.012), center=(0, 0, h - 0.03)), fab)]
    strap = M.fabric(rng)
    # a handle at each end and two on each long side
    out += each("handle", "handle", [S.box((0.15, 0.01, 0.03), center=(0, sy * (L / 2 + 0.005), h / 2)) for sy in (-1, 1)]
                + [S.box((0.01, 0.15, 0.03), center=(sx * (w / 2 + 0.005), sy * L * 0.2, h / 2)) for sx in (-1, 1) for sy in (-1, 1)],
                strap)
    # the tufts quilted through the top panel, the mesh air vents in the border, the law label
    nx = 3 if variant == "twin" else 4
    out += tufts("tuft", "tuft", nx=nx, ny=6, x0=-w * 0.33, x1=w * 0.33, y0=-L * 0.38, y1=L * 0.38, z=h - 0.003, length=0.006,
                 r=0.012, mat=fab)
    out += each("vent", "vent", [S.cylinder(0.02, 0.004, center=(sx * (w / 2 + 0.001), sy * L * 0.35, h * 0.4), axis=(1, 0, 0),
                                            sections=10) for sx in (-1, 1) for sy in (-1, 1)], M.solid((0.7, 0.7, 0.72), "metal", 0.4))
    out.append(make_part("label", "label", S.box((0.08, 0.002, 0.05), center=(w * 0.3, -L / 2 - 0.001, h * 0.35)),
                         M.solid((0.98, 0.98, 0.98), "fabric", 0.8)))
    return out


@register("folded_clothes", parts=("garment",), extra_parts=("collar", "sleeve", "button", "pocket", "waistband", "cuff"),
          size_range=(0.25, 0.45), density=250, variants=("shirts", "sweaters", "jeans"),
          placement="surface")
def folded_clothes(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.28, 0.36), rng.uniform(0.22, 0.3)
    lt = {"shirts": 0.025, "sweaters": 0.05, "jeans": 0.04}[variant] * rng.uniform(0.9, 1.1)
    n = int(rng.integers(2, 6))
    out = []
    for k in range(n):
        c = M.solid(M.jitter(rng, (0.5, 0.5, 0.6), 0.25)[:3], "fabric", 0.9)
        dx, dy = rng.uniform(-0.01, 0.01, 2)
        out.append(make_part(f"garment_{k}", "garment", S.box((w, d, lt), center=(dx, dy, lt * k + lt / 2), bevel=lt * 0.3), c))
    top = lt * n
    if variant == "shirts":
        out.append(make_part("collar", "collar", S.box((0.12, 0.03, 0.008), center=(0, d / 2 - 0.03, lt * n + 0.004)), out[-1].material))
        # the top shirt's placket buttons and its breast pocket
        out += studs("button", "button", [(0, y, top + 0.0005) for y in np.linspace(d / 2 - 0.07, -d / 2 + 0.03, 4)], r=0.005,
                     h=0.001, mat=M.solid((0.95, 0.95, 0.92), "plastic", 0.3), sections=8)
        out.append(make_part("pocket", "pocket", S.box((0.07, 0.08, 0.001), center=(-w * 0.22, d * 0.1, top + 0.0005)),
                             out[-1].material))
    elif variant == "jeans":  # the top pair's waistband with its button, and a back pocket
        out.append(make_part("waistband", "waistband", S.box((w * 0.95, 0.035, 0.003), center=(0, d / 2 - 0.02, top + 0.0015)),
                             out[n - 1].material))
        out += studs("button", "button", [(w * 0.3, d / 2 - 0.02, top + 0.004)], r=0.007, h=0.002,
                     mat=M.solid((0.7, 0.6, 0.4), "metal", 0.3, 0.9))
        out.append(make_part("pocket", "pocket", S.box((0.12, 0.13, 0.002), center=(-w * 0.15, -d * 0.1, top + 0.001)),
                             out[n - 1].material))
    else:  # the ribbed cuffs of the top sweater's sleeves, folded across its front
        out += each("cuff", "cuff", [S.box((0.07, 0.05, 0.006), center=(sx * w * 0.2, -d * 0.3, top + 0.003), bevel=0.002)
                                     for sx in (-1, 1)], out[n - 1].material)
    return out


@register("jacket", parts=("body", "sleeve"), extra_parts=("collar", "pocket", "zipper", "hood", "cuff", "pull", "drawstring",
                                                             "waistband"),
          size_range=(0.55, 1.05), density=200, variants=("laid_flat", "hood", "blazer"),
          placement="surface")
def jacket(rng: np.random.Generator, variant: str) -> list[Part]:
    # laid flat, front up: the torso along Y, sleeves spread along X
    w, L = rng.uniform(0.5, 0.6), rng.uniform(0.6, 0.78)
    t = rng.uniform(0.03, 0.05)
    fab = M.fabric(rng)
    out = [make_part("body", "body", S.box((w, L, t), center=(0, 0, t / 2), bevel=t * 0.3), fab)]
    for k, sx in enumerate((-1, 1)):
        out.append(make_part(f"sleeve_{k}", "sleeve", S.box((0.16, L * 0.75, t * 0.8), center=(sx * (w / 2 + 0.08), -L * 0.05, t * 0.4),
                                                           R=rot((0, 0, 1), sx * 0.15)), fab))
    out.append(make_part("zipper", "zipper", S.box((0.01, L * 0.9, 0.003), center=(0, 0, t + 0.0015)), M.metal(rng)))
    if variant == "hood":
        out.append(make_part("hood", "hood", S.box((0.3, 0.2, t), center=(0, L / 2 + 0.1, t / 2), bevel=t * 0.3), fab))
    else:
        out.append(make_part("collar", "collar", S.box((0.24, 0.06, t * 0.5), center=(0, L / 2 - 0.03, t + t * 0.25)), fab))
    out += each("pocket", "pocket", [S.box((0.12, 0.1, 0.004), center=(sx * w * 0.25, -L * 0.25, t + 0.002)) for sx in (-1, 1)],
                fab)
    # the zip's puller, the ribbed waistband along the hem and a cuff at each sleeve's end
    out += studs("pull", "pull", [(0, L * 0.3, t + 0.004)], r=0.006, h=0.003, mat=out[3].material)
    out.append(make_part("waistband", "waistband", S.box((w, 0.05, t * 1.05), center=(0, -L / 2 + 0.025, t * 1.05 / 2)), fab))
    for k, sx in enumerate((-1, 1)):
        a = sx * 0.15
        c = np.array([sx * (w / 2 + 0.08), -L * 0.05, 0.0]) + rot((0, 0, 1), a) @ np.array([0.0, -L * 0.375 - 0.02, 0.0])
        out.append(make_part(f"cuff_{k}", "cuff", S.box((0.15, 0.04, t * 0.85), center=(c[0], c[1], t * 0.425), R=rot((0, 0, 1), a)),
                             fab))
    if variant == "hood":  # the hood's drawstring ends hanging over the chest
        out += each("drawstring", "drawstring", [S.box((0.006, 0.12, 0.004), center=(sx * 0.05, L / 2 - 0.07, t + 0.002))
                                                 for sx in (-1, 1)], M.solid((0.95, 0.95, 0.95), "fabric", 0.9))
    return out


@register("paper_bag", parts=("body",), extra_parts=("handle", "fold", "patch", "label", "gusset"),
          size_range=(0.22, 0.52), density=150, variants=("grocery", "shopping", "lunch"),
          placement="floor")
def paper_bag(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = {"grocery": (0.3, 0.18, 0.42), "shopping": (0.32, 0.12, 0.4), "lunch": (0.14, 0.09, 0.24)}[variant]
    w, d, h = (v * rng.uniform(0.92, 1.08) for v in (w, d, h))
    mat = M.paper(rng)
    out = [make_part("body", "body", shell([(0.5, 0.0), (0.5, 1.0)], 0.02, bottom=0.02, sections=4), mat)]
    # the square section's corners lie at radius 0.5 on the diagonals: scaled so its sides are
    # w and d
    T = np.diag([w * np.sqrt(2), d * np.sqrt(2), h, 1.0])
    T = T @ np.array([[np.cos(np.pi / 4), -np.sin(np.pi / 4), 0, 0], [np.sin(np.pi / 4), np.cos(np.pi / 4), 0, 0], [0, 0, 1, 0],
                      [0, 0, 0, 1.0]])
    out[0] = make_part("body", "body", S.transformed(shell([(0.5, 0.0), (0.5, 1.0)], 0.005, bottom=0.005, sections=4), T), mat)
    if variant == "shopping":
        yh = d / 2 - 0.009
        out += each("handle", "handle", [S.tube([(-w * 0.2, sy * yh, h - 0.01), (-w * 0.15, sy * yh, h + 0.08),
                                                 (w * 0.15, sy * yh, h + 0.08), (w * 0.2, sy * yh, h - 0.01)], 0.004,
                                                sections=6) for sy in (-1, 1)], mat)
        # the card patches glued inside the mouth that the handle ends are fixed to
        out += [make_part(f"patch_{k}", "patch", S.box((w * 0.5, 0.002, 0.05), center=(0, sy * (d / 2 - 0.004), h - 0.03)), mat)
                for k, sy in enumerate((-1, 1))]
    else:
        out.append(make_part("fold", "fold", S.box((w * 0.98, 0.004, 0.03), center=(0, d * 0.35, h - 0.015)), mat))
    # the printed label on the front and the folded-in gussets at the sides (their crease)
    out.append(make_part("label", "label", S.box((w * 0.5, 0.001, h * 0.25), center=(0, d / 2 + 0.0005, h * 0.5)),
                         M.solid((0.2, 0.35, 0.25), "paper", 0.8)))
    out += [make_part(f"gusset_{k}", "gusset", S.box((0.001, d * 0.08, h * 0.8), center=(sx * (w / 2 + 0.0005), 0, h * 0.45)), mat)
            for k, sx in enumerate((-1, 1))]
    return out


