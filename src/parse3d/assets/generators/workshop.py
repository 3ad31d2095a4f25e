"""The workshop: ladders, a workbench, a pegboard and hand tools (hammer, screwdriver, wrench).

Ladders stand upright, steps facing +Y; a straight ladder's back (-Y) is what leans against a
wall. Hand tools lie flat, the handle along X with the working end at +X.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Part, make_part
from ..registry import register
from ._casework import drawer_parts
from ._detail_b import each, studs
from ._kit import legs4, rot
from ._rods import leg_caps


@register("ladder", parts=("rail", "step"), extra_parts=("top_cap", "rear_leg", "spreader", "foot", "end_cap", "rivet", "pail_shelf"),
          size_range=(0.9, 3.1), density=900, variants=("step", "straight", "library"))
def ladder(rng: np.random.Generator, variant: str) -> list[Part]:
    metal = M.metal(rng) if variant != "library" else M.wood(rng)
    out: list[Part] = []
    if variant == "straight":
        h, w = rng.uniform(1.8, 3.0), rng.uniform(0.38, 0.46)
        n = int(round(h / 0.28))
        for k, sx in enumerate((-1, 1)):
            out.append(make_part(f"rail_{k}", "rail", S.box((0.025, 0.07, h), center=(sx * (w / 2 - 0.0125), 0,
                                                                                  h / 2)), metal))
            out.append(make_part(f"foot_{k}", "foot", S.box((0.04, 0.08, 0.03),
                                                            center=(sx * (w / 2 - 0.02), 0, 0.015)),
                                 M.solid((0.1, 0.1, 0.1), "rubber")))
        for i in range(n):
            z = 0.28 * (i + 0.8)
            if z > h - 0.1:
                break
            out.append(make_part(f"step_{i}", "step",
                                 S.cylinder(0.015, w - 0.05, center=(0, 0, z), axis=(1, 0, 0),
                                            sections=12), metal))
        # the plastic caps closing the rails' top ends
        out += [make_part(f"end_cap_{k}", "end_cap", S.box((0.027, 0.072, 0.02), center=(sx * (w / 2 - 0.0135), 0, h - 0.01)),
                          M.solid((0.1, 0.1, 0.1), "plastic", 0.6)) for k, sx in enumerate((-1, 1))]
        return out
    # an A-frame: front rails with treads leaning back, rear legs leaning forward
    h = rng.uniform(0.95, 1.9) if variant == "step" else rng.uniform(0.9, 1.3)
    w = rng.uniform(0.42, 0.5)
    spread = h * 0.36
    ang = float(np.arctan2(spread / 2, h))
    n = max(2, int(h / 0.26))
    length = h / np.cos(ang)
    tilt_f, tilt_b = rot((1, 0, 0), -ang), rot((1, 0, 0), ang)
    for k, sx in enumerate((-1, 1)):
        out.append(make_part(f"rail_{k}", "rail", S.box((0.03, 0.07, length), R=tilt_f,
                                                        center=(sx * (w / 2 - 0.015), spread / 4, h / 2)),
                             metal))
        out.append(make_part(f"rear_leg_{k}", "rear_leg",
                             S.box((0.03, 0.03, length), R=tilt_b,
                                   center=(sx * (w / 2 - 0.015), -spread / 4, h / 2)), metal))
    fast = M.solid((0.6, 0.6, 0.62), "metal", 0.35, 0.9) if variant != "library" else M.solid((0.75, 0.6, 0.3), "metal", 0.3, 0.9)
    nr = 0
    for i in range(n):
        z = h * (i + 1) / (n + 1)
        y = spread / 2 * (1 - z / h)
        out.append(make_part(f"step_{i}", "step", S.box((w - 0.06, 0.09, 0.025), center=(0, y - 0.01, z)),
                             metal))
        # two rivets (bolts on a wooden ladder) through each rail into the step's end, their
        # heads on the rail's outer face
        yr = y - 0.01
        for sx in (-1, 1):
            for dy in (-0.02, 0.02):
                out.append(make_part(f"rivet_{nr}", "rivet", S.cylinder(0.005, 0.003, center=(sx * (w / 2 - 0.0015), yr + dy, z), axis=(1, 0, 0),
                                                                        sections=8), fast))
                nr += 1
    # non-slip rubber shoes sleeving the bottom of each rail and rear leg (set a hair up the
    # leg, so the ladder still stands on its legs' ends)
    rubber = M.solid((0.1, 0.1, 0.1), "rubber")
    k = 0
    for sx in (-1, 1):
        for R, yc, size in ((tilt_f, spread / 4, (0.036, 0.076)), (tilt_b, -spread / 4, (0.036, 0.036))):
            u = R @ np.array([0.0, 0.0, 1.0])
            c = np.array([sx * (w / 2 - 0.015), yc, h / 2]) - u * (length / 2 - 0.032)
            c[0] = sx * (w / 2 - size[0] / 2)  # flush with the ladder's side
            out.append(make_part(f"foot_{k}", "foot", S.box((*size, 0.06), R=R, center=tuple(c)), rubber))
            k += 1
    out.append(make_part("top_cap", "top_cap", S.box((w, 0.16, 0.05), center=(0, 0, h - 0.025),
                                                     bevel=0.005), M.plastic(rng)))
    out.append(make_part("spreader", "spreader", S.box((0.02, spread * 0.55, 0.01),
                                                       center=(-w / 2 + 0.05, 0, h * 0.45)), metal))
    # its twin on the right, locking the frames open from both sides
    out.append(make_part("spreader_1", "spreader", S.box((0.02, spread * 0.55, 0.01), center=(w / 2 - 0.05, 0, h * 0.45)), metal))
    if variant == "step":  # the fold-down pail shelf between the rear legs, below the top cap
        out.append(make_part("pail_shelf", "pail_shelf", S.box((w - 0.08, 0.12, 0.012), center=(0, -0.08, h - 0.12)), M.plastic(rng)))
    return out


@register("workbench", parts=("worktop", "leg"),
          extra_parts=("shelf", "drawer", "drawer_box", "handle", "vise", "back_panel", "stretcher", "vise_jaw",
                       "vise_screw", "vise_handle", "screw", "leg_cap", "bolt"),
          size_range=(1.1, 2.1), density=650, variants=("plain", "drawers", "pegboard_back"))
def workbench(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d, h = rng.uniform(1.2, 2.0), rng.uniform(0.6, 0.8), rng.uniform(0.86, 0.95)
    wood, steel = M.wood(rng), M.metal(rng)
    t = rng.uniform(0.04, 0.06)
    out: list[Part | Joint] = [make_part("worktop", "worktop", S.box((w, d, t), center=(0, 0, h - t / 2),
                                                                     bevel=0.004), wood)]
    leg = 0.07
    out += legs4("leg", "leg", w=w, d=d, h=h - t, size=leg, mat=steel if variant != "plain" else wood,
                 inset=0.03)
    zs = 0.18
    out.append(make_part("shelf", "shelf", S.box((w - 0.1, d - 0.1, 0.02), center=(0, 0, zs)), wood))
    out.append(make_part("stretcher", "stretcher",
                         S.box((w - 0.12, 0.04, 0.06), center=(0, -d / 2 + 0.06, h - t - 0.1)), wood))
    # the side stretchers joining front and back legs under the top
    out += [make_part(f"stretcher_{k}", "stretcher", S.box((0.04, d - 0.2, 0.06), center=(sx * (w / 2 - 0.065), 0, h - t - 0.1)),
                      wood) for k, sx in enumerate((-1, 1), start=1)]
    # the low rails along the front and back that carry the shelf's long edges
    out += [make_part(f"stretcher_{k}", "stretcher", S.box((w - 0.14, 0.04, 0.05), center=(0, sy * (d / 2 - 0.07), zs - 0.035)),
                      wood) for k, sy in enumerate((-1, 1), start=3)]
    if variant == "drawers":
        dw = min(0.5, w * 0.3)
        x1 = w / 2 - 0.1
        out.append(make_part("drawer_rail", "stretcher",
                             S.box((dw, d - 0.12, 0.015), center=(x1 - dw / 2, 0.0, h - t - 0.19)),
                             wood))
        out += drawer_parts("drawer_0", x0=x1 - dw, x1=x1, z0=h - t - 0.17, z1=h - t - 0.01,
                            y_front=d / 2 - 0.03, depth=d - 0.2, thick=0.018, mat=wood,
                            handle_mat=steel, parent="worktop")
    if variant != "plain":
        # a bench vise at the front-left corner
        vx = -w / 2 + 0.2
        # its body bolted to the top, the moving jaw in front, the screw and its tommy bar
        out.append(make_part("vise", "vise", S.box((0.16, 0.12, 0.08), center=(vx, d / 2 - 0.02, h + 0.04)), steel))
        out.append(make_part("vise_jaw", "vise_jaw", S.box((0.16, 0.03, 0.1), center=(vx, d / 2 + 0.055, h + 0.03)), steel))
        out.append(make_part("vise_screw", "vise_screw", S.cylinder(0.01, 0.05, center=(vx, d / 2 + 0.095, h + 0.03), axis=(0, 1, 0),
                                                                    sections=10), steel))
        out.append(make_part("vise_handle", "vise_handle", S.cylinder(0.006, 0.16, center=(vx, d / 2 + 0.115, h + 0.03), axis=(1, 0, 0),
                                                                      sections=8), steel))
        out += studs("screw", "screw", [(vx + sx * 0.06, d / 2 - 0.06, h + 0.0015) for sx in (-1, 1)], r=0.007, h=0.003, mat=steel)
    if variant == "pegboard_back":
        ph = rng.uniform(0.5, 0.7)
        out.append(make_part("back_panel", "back_panel",
                             S.box((w, 0.012, ph), center=(0, -d / 2 + 0.006, h + ph / 2)),
                             M.solid(M.jitter(rng, (0.72, 0.58, 0.4), 0.03), "wood", 0.8)))
    # the carriage bolts through each leg into the stretchers: the upper side rails' from the
    # ends, the low shelf rails' from the front and back, heads domed on the legs' faces
    xl, yl = w / 2 - 0.03 - leg / 2, d / 2 - 0.03 - leg / 2
    nb = 0
    for sx in (-1, 1):
        for sy in (-1, 1):
            out.append(make_part(f"bolt_{nb}", "bolt", S.cylinder(0.009, 0.004, center=(sx * (w / 2 - 0.03 + 0.002), sy * yl, h - t - 0.1),
                                                                  axis=(1, 0, 0), sections=10), M.metal(rng)))
            out.append(make_part(f"bolt_{nb + 1}", "bolt", S.cylinder(0.009, 0.004, center=(sx * xl, sy * (d / 2 - 0.03 + 0.002), zs - 0.035),
                                                                      axis=(0, 1, 0), sections=10), M.metal(rng)))
            nb += 2
    # rubber caps on the legs' feet
    return out + leg_caps(out, label="leg_cap", mat=M.solid((0.08, 0.08, 0.08), "rubber", 0.8))


@register("pegboard", parts=("board", "hook"), extra_parts=("frame", "shelf", "bin", "screw"),
          size_range=(0.4, 1.25), density=700, variants=("hardboard", "metal", "framed"),
          placement="wall")
def pegboard(rng: np.random.Generator, variant: str) -> list[Part]:
    w, h = rng.uniform(0.4, 1.2), rng.uniform(0.4, 0.9)
    t = 0.006
    mat = (M.solid(M.jitter(rng, (0.72, 0.58, 0.4), 0.03), "wood", 0.8) if variant != "metal"
           else M.solid(M.jitter(rng, (0.2, 0.3, 0.45), 0.05), "metal", 0.4, 0.6))
    # the board's back is on the wall; a frame of strips around its face holds it (and keeps
    # what hangs on the hooks off the holes)
    out: list[Part] = [make_part("board", "board", S.box((w, t, h), center=(0, t / 2, h / 2)), mat)]
    out += each("frame", "frame", [S.box((w, 0.01, 0.03), center=(0, t + 0.005, z)) for z in (0.015, h - 0.015)], mat)
    # the strips are screwed through the board into the wall, two at each end of each strip
    out += studs("screw", "screw", [(sx * (w / 2 - 0.03), t + 0.0105, z) for z in (0.015, h - 0.015) for sx in (-1, 1)],
                 r=0.005, h=0.001, mat=M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8), axis=(0, 1, 0))
    steel = M.metal(rng)
    n = int(rng.integers(5, 11))
    for k in range(n):
        x = -w / 2 + 0.06 + (w - 0.12) * rng.uniform()
        z = 0.1 + (h - 0.2) * rng.uniform()
        out.append(make_part(f"hook_{k}", "hook",
                             S.tube([(x, t, z), (x, t + 0.06, z), (x, t + 0.065, z + 0.02)], 0.0025,
                                    sections=8), steel))
    if variant == "framed":
        out.append(make_part("shelf", "shelf", S.box((min(0.35, w * 0.6), 0.1, 0.012),
                                                     center=(0, t + 0.05, h * 0.3)), steel))
        out.append(make_part("bin", "bin", S.box((0.12, 0.08, 0.07),
                                                 center=(w / 4, t + 0.04, h * 0.65)),
                             M.plastic(rng)))
    return out


def _grip(rng) -> M.Material:
    return M.solid(M.jitter(rng, [(0.8, 0.15, 0.1), (0.95, 0.75, 0.1), (0.1, 0.3, 0.7),
                                  (0.1, 0.1, 0.1)][int(rng.integers(4))], 0.03), "rubber", 0.8)


@register("hammer", parts=("head", "handle"), extra_parts=("grip", "claw", "face", "wedge", "end_cap", "neck", "collar"),
          size_range=(0.24, 0.42), density=2500, variants=("claw", "ball_peen", "mallet"),
          placement="surface")
def hammer(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.26, 0.38)
    steel = M.metal(rng)
    r = 0.013
    handle_mat = M.wood(rng) if variant != "claw" else M.solid((0.2, 0.2, 0.22), "plastic", 0.5)
    hr = 0.016
    out = [make_part("handle", "handle", S.cylinder(r, L - 0.03, center=(-0.015, 0, hr),
                                                    axis=(1, 0, 0), sections=12), handle_mat),
           make_part("grip", "grip", S.cylinder(r * 1.2, L * 0.35, center=(-L / 2 + L * 0.175, 0, hr),
                                                axis=(1, 0, 0), sections=12), _grip(rng))]
    x = L / 2 - 0.015
    # the cap closing the grip's end
    out.append(make_part("end_cap", "end_cap", S.cylinder(r * 1.25, 0.006, center=(-L / 2 + 0.003 - 0.0, 0, hr), axis=(1, 0, 0),
                                                          sections=12), out[1].material))
    if variant == "mallet":
        out.append(make_part("head", "head", S.cylinder(0.03, 0.11, center=(x, 0, 0.03), axis=(0, 1, 0),
                                                        sections=16), M.solid((0.1, 0.1, 0.1), "rubber")))
        # the two hard striking faces capping the rubber head, and the collar binding the handle
        # where it enters the head
        out += [make_part(f"face_{k}", "face", S.cylinder(0.028, 0.006, center=(x, sy * 0.052, 0.03), axis=(0, 1, 0), sections=16),
                          M.solid((0.9, 0.9, 0.88), "plastic", 0.5)) for k, sy in enumerate((-1, 1))]
        out.append(make_part("collar", "collar", S.cylinder(r * 1.25, 0.012, center=(x - 0.036, 0, hr), axis=(1, 0, 0), sections=12),
                             steel))
        return out
    out.append(make_part("head", "head", S.box((0.03, 0.06, 0.03), center=(x, 0, hr)), steel))
    out.append(make_part("face", "face", S.cylinder(0.014, 0.008, center=(x, 0.058, hr), axis=(0, 1, 0),
                                                    sections=14), steel))
    # the round neck between the head's cheeks and its striking face
    out.append(make_part("neck", "neck", S.cylinder(0.0125, 0.027, center=(x, 0.0405, hr), axis=(0, 1, 0), sections=14), steel))
    # the wedge driven into the handle's end across the head's eye
    out.append(make_part("wedge", "wedge", S.box((0.0015, 0.02, 0.006), center=(x + 0.0155, 0, hr)), M.solid((0.55, 0.55, 0.58),
                                                                                                          "metal", 0.4, 0.8)))
    if variant == "claw":
        out.append(make_part("claw", "claw", [S.box((0.008, 0.06, 0.02), center=(x + sx * 0.008, -0.055, hr),
                                                    R=rot((0, 0, 1), sx * 0.15)) for sx in (-1, 1)], steel))
    else:
        out.append(make_part("claw", "claw", S.cylinder(0.012, 0.03, center=(x, -0.045, hr),
                                                        axis=(0, 1, 0), sections=12), steel))
    return out


@register("screwdriver", parts=("handle", "shaft"), extra_parts=("tip", "grip", "ferrule", "end_cap", "bolster", "hang_hole"),
          size_range=(0.08, 0.36), density=2000, variants=("flat", "phillips", "stubby"),
          placement="surface")
def screwdriver(rng: np.random.Generator, variant: str) -> list[Part]:
    hl = rng.uniform(0.07, 0.11) if variant != "stubby" else rng.uniform(0.05, 0.06)
    sl = rng.uniform(0.08, 0.2) if variant != "stubby" else rng.uniform(0.03, 0.05)
    r = rng.uniform(0.013, 0.018)
    steel = M.metal(rng)
    x0 = -(hl + sl) / 2
    out = [make_part("handle", "handle", S.cylinder(r, hl, center=(x0 + hl / 2, 0, r), axis=(1, 0, 0),
                                                    sections=6), _grip(rng)),
           make_part("grip", "grip", S.cylinder(r * 1.05, hl * 0.4, center=(x0 + hl * 0.45, 0, r),
                                                axis=(1, 0, 0), sections=12),
                     M.solid((0.1, 0.1, 0.1), "rubber")),
           make_part("shaft", "shaft", S.cylinder(0.0035, sl - 0.01, center=(x0 + hl + (sl - 0.01) / 2, 0, r),
                                                  axis=(1, 0, 0), sections=10), steel)]
    tip = (S.box((0.01, 0.006, 0.0015), center=(x0 + hl + sl - 0.005, 0, r)) if variant == "flat"
           else S.frustum(0.0035, 0.0005, 0.01, center=(x0 + hl + sl - 0.01, 0, r), axis=(1, 0, 0),
                          sections=4))
    out.append(make_part("tip", "tip", tip, steel))
    # the bolster where the shaft enters the handle, and the coloured cap on the handle's end
    out.append(make_part("ferrule", "ferrule", S.frustum(r * 0.6, 0.006, 0.01, center=(x0 + hl, 0, r), axis=(1, 0, 0), sections=10),
                         steel))
    out.append(make_part("end_cap", "end_cap", S.cylinder(r * 0.7, 0.004, center=(x0 - 0.002, 0, r), axis=(1, 0, 0), sections=10),
                         M.solid((0.1, 0.1, 0.1), "rubber")))
    # the hex bolster forged on the shaft (a spanner turns it for more torque) and the hole
    # through the handle's end to hang it by
    out.append(make_part("bolster", "bolster", S.cylinder(0.0055, 0.008, center=(x0 + hl + 0.009, 0, r), axis=(1, 0, 0), sections=6),
                         steel))
    out.append(make_part("hang_hole", "hang_hole", S.cylinder(0.0025, 2 * r * 0.92, center=(x0 + hl * 0.1, 0, r), axis=(0, 1, 0),
                                                              sections=8), M.solid((0.05, 0.05, 0.05), "plastic", 0.8)))
    return out


@register("wrench", parts=("handle", "jaw"), extra_parts=("ring", "adjuster", "lower_jaw", "pin", "hang_hole", "neck"),
          size_range=(0.12, 0.36), density=7800, variants=("combination", "adjustable", "open_end"),
          placement="surface")
def wrench(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.14, 0.32)
    s = L / 0.2  # the jaw grows with the length
    steel = M.metal(rng)
    t = 0.006 * s
    jw = 0.022 * s
    xh = L / 2 - jw
    out = [make_part("handle", "handle", S.box((L - 2 * jw, 0.014 * s, t), center=(0, 0, t / 2), bevel=0.001),
                     steel)]
    # the open jaw: two prongs around the gap at +X
    out.append(make_part("jaw", "jaw", [S.box((jw, 0.009 * s, t), center=(xh + jw / 2, sy * 0.012 * s, t / 2))
                                        for sy in (-1, 1)] + [S.box((0.008 * s, 0.033 * s, t),
                                                                    center=(xh + 0.004 * s, 0, t / 2))],
                     steel))
    # the necks where the shank flares into each head
    out += [make_part(f"neck_{k}", "neck", S.box((0.008 * s, 0.018 * s, t), center=(sx * (xh - 0.004 * s - 0.008 * s), 0, t / 2)), steel)
            for k, sx in enumerate((1, -1) if variant != "adjustable" else (1,))]
    if variant == "combination":
        out.append(make_part("ring", "ring", S.cylinder(jw * 0.7, t, center=(-xh - jw * 0.3, 0, t / 2),
                                                        sections=12), steel))
    elif variant == "adjustable":
        out.append(make_part("adjuster", "adjuster", S.cylinder(0.006 * s, 0.012 * s,
                                                                center=(xh - 0.004 * s, 0, t / 2),
                                                                axis=(0, 1, 0), sections=12), steel))
        # the sliding lower jaw riding on the adjuster, the pin the worm turns on and the hole
        # at the handle's end to hang it by
        out.append(make_part("lower_jaw", "lower_jaw", S.box((jw * 0.8, 0.006 * s, t * 0.9), center=(xh + jw * 0.4, -0.0195 * s, t * 0.45)),
                             steel))
        out.append(make_part("pin", "pin", S.cylinder(0.0015 * s, 0.014 * s, center=(xh - 0.004 * s, 0, t / 2), axis=(0, 1, 0),
                                                      sections=8), M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8)))
        out.append(make_part("hang_hole", "hang_hole", S.cylinder(0.004 * s, t + 0.0002, center=(-L / 2 + 2 * jw - 0.01 * s, 0, t / 2),
                                                                  sections=10), M.solid((0.05, 0.05, 0.05), "metal", 0.8)))
    else:  # a second open jaw, one size smaller, at the other end
        out += [make_part("jaw_1", "jaw", [S.box((jw * 0.9, 0.008 * s, t), center=(-xh - jw * 0.45, sy * 0.011 * s, t / 2))
                                           for sy in (-1, 1)] + [S.box((0.008 * s, 0.03 * s, t), center=(-xh - 0.004 * s, 0, t / 2))],
                          steel)]
    return out
