"""Household and office appliances: microwave, toaster, toaster oven, coffee maker, mini
fridge, dishwasher, clothes dryer, water cooler, range hood, printer, copier and computer tower.

Fronts face +Y. Appliances with a cavity (microwave, toaster oven, mini fridge) are built from
walls, so the cavity floor is an internal support surface (``IN``); their doors are hinged
(revolute joints) and drawers and trays slide (prismatic).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Part, make_part
from ..registry import register
from ._casework import black, door_parts, drawer_parts, knob, white
from ._dD_detail import back_screws, flush_screws
from ._household import ring
from ._kit import feet4, hinge_parts, mount, prismatic, revolute


def _shell(w: float, d: float, h: float, *, z0: float = 0.0, x0: float | None = None,
           x1: float | None = None, t: float = 0.015) -> list[S.Shape]:
    """Five walls (bottom, top, left, right, back) of a box open at the front (+Y), spanning
    ``[x0, x1] x [-d/2, d/2] x [z0, z0 + h]``."""
    x0 = -w / 2 if x0 is None else x0
    x1 = w / 2 if x1 is None else x1
    cw, cx = x1 - x0, (x0 + x1) / 2
    return [S.box((cw, d, t), center=(cx, 0, z0 + t / 2)),
            S.box((cw, d, t), center=(cx, 0, z0 + h - t / 2)),
            S.box((t, d, h - 2 * t), center=(x0 + t / 2, 0, z0 + h / 2)),
            S.box((t, d, h - 2 * t), center=(x1 - t / 2, 0, z0 + h / 2)),
            S.box((cw - 2 * t, t, h - 2 * t), center=(cx, -d / 2 + t / 2, z0 + h / 2))]


def _pads(w: float, d: float, inset: float = 0.025, r: float = 0.01, h: float = 0.004) -> list[Part]:
    """Four rubber pads let into the underside of a ``w`` x ``d`` appliance (flush with it)."""
    rubber = M.solid((0.08, 0.08, 0.08), "rubber", 0.9)
    return [make_part(f"foot_{k}", "foot", S.cylinder(r, h, center=(sx * (w / 2 - inset), sy * (d / 2 - inset), h / 2),
                                                      sections=10), rubber)
            for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)])]


def _buttons(prefix: str, x: float, y: float, zs, mat, r: float = 0.008) -> list[Part]:
    return [make_part(f"{prefix}_{k}", "button", S.cylinder(r, 0.006, center=(x, y + 0.002, z),
                                                            axis=(0, 1, 0), sections=12), mat)
            for k, z in enumerate(zs)]


@register("microwave", parts=("body", "door"),
          extra_parts=("control_panel", "button", "handle", "glass", "hinge", "foot", "turntable", "display", "vent",
                       "waveguide_cover", "latch", "roller_ring", "key", "screw"),
          size_range=(0.42, 0.62), density=250, variants=("countertop", "white", "steel"),
          placement="surface")
def microwave(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d, h = rng.uniform(0.45, 0.6), rng.uniform(0.33, 0.42), rng.uniform(0.26, 0.33)
    mat = white(rng) if variant == "white" else (M.metal(rng) if variant == "steel" else black())
    fh = 0.012
    panel = w * 0.26
    xc = w / 2 - panel  # the cavity runs from the left side to the control panel
    out: list[Part | Joint] = [make_part("body", "body", _shell(w, d, h - fh, z0=fh, x1=xc + 0.015), mat)]
    out.append(make_part("control_panel", "control_panel",
                         S.box((panel, d, h - fh), center=(xc + panel / 2, 0, fh + (h - fh) / 2)), mat))
    out += _buttons("button", xc + panel / 2, d / 2, np.linspace(fh + 0.06, h - 0.06, 4), black())
    # the ten number keys in two columns either side of the function buttons
    for k, z in enumerate(np.repeat(np.linspace(fh + 0.05, h - 0.08, 5), 2)):
        x = xc + panel / 2 + (0.03 if k % 2 else -0.03)
        out.append(make_part(f"key_{k}", "key", S.box((0.014, 0.004, 0.012), center=(x, d / 2 + 0.002, z), bevel=0.001),
                             M.solid((0.85, 0.85, 0.85), "plastic", 0.4)))
    out += feet4("foot", w=w, d=d, r=0.012, h=fh, mat=black("rubber"), inset=0.02)
    out.append(make_part("turntable", "turntable", S.cylinder(min(xc + w / 2, d) * 0.4, 0.006,
                                                              center=((xc - w / 2) / 2, 0, fh + 0.018)),
                         M.glass(rng)))
    # the display above the keys, the vent grille on the left side, the mica cover over the
    # waveguide on the cavity's right wall, the ring of rollers under the turntable, and the
    # door's two latch hooks entering the front frame beside the control panel
    out.append(make_part("display", "display", S.box((panel * 0.6, 0.003, 0.03), center=(xc + panel / 2, d / 2 + 0.0015, h - 0.035)),
                         M.solid((0.1, 0.2, 0.15), "glass", 0.1)))
    out.append(make_part("vent", "vent", S.box((0.003, d * 0.4, (h - fh) * 0.35), center=(-w / 2 - 0.0015, -d * 0.1, fh + (h - fh) * 0.6)),
                         black()))
    out.append(make_part("waveguide_cover", "waveguide_cover", S.box((0.002, d * 0.25, (h - fh) * 0.25),
                                                                     center=(xc - 0.001, 0.0, fh + (h - fh) * 0.6)),
                         M.solid((0.75, 0.7, 0.55), "paper", 0.8)))
    rt = min(xc + w / 2, d) * 0.4
    out.append(make_part("roller_ring", "roller_ring", S.cylinder(rt * 0.6, 0.004, center=((xc - w / 2) / 2, 0, fh + 0.013), sections=16),
                         black()))
    out += [make_part(f"latch_{k}", "latch", S.box((0.008, 0.02, 0.025), center=(xc - 0.01, d / 2 - 0.006, z)), black())
            for k, z in enumerate((fh + (h - fh) * 0.3, fh + (h - fh) * 0.7))]
    # the four screws holding the outer cabinet's wrap at the corners of the back
    out += back_screws("screw", x0=-w / 2, x1=w / 2, z0=fh, z1=h, y=-d / 2)
    out += door_parts("door", x0=-w / 2, x1=xc, z0=fh, z1=h, y_back=d / 2, thick=0.02, mat=mat,
                      handle_mat=mat, hinge_left=True, style="glass", glass=M.glass(rng),
                      handle_len=(h - fh) * 0.6)
    return out


@register("toaster", parts=("body", "slot"), extra_parts=("lever", "knob", "foot", "crumb_tray", "button", "cord", "end_cap", "tab"),
          size_range=(0.2, 0.42), density=300, variants=("two_slot", "four_slot", "long_slot"),
          placement="surface")
def toaster(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    n = 4 if variant == "four_slot" else 2
    w = rng.uniform(0.26, 0.32) if variant == "four_slot" else rng.uniform(0.22, 0.28)
    d = rng.uniform(0.15, 0.19) if variant != "four_slot" else rng.uniform(0.26, 0.3)
    h = rng.uniform(0.18, 0.21)
    mat = M.metal(rng) if rng.uniform() < 0.5 else white(rng)
    fh = 0.008
    out: list[Part | Joint] = [make_part("body", "body", S.box((w, d, h - fh), center=(0, 0, fh + (h - fh) / 2),
                                                               bevel=0.02), mat)]
    rows = 2 if n == 4 else 1
    cols = 2 if variant != "long_slot" else 1
    sl = (d * 0.8) if variant == "long_slot" else (d * 0.75 / rows)
    for i in range(cols):
        for j in range(rows):
            x = (i - (cols - 1) / 2) * w * 0.3
            y = (j - (rows - 1) / 2) * d * 0.45
            if variant == "long_slot":
                x, sl_w, sl_d = (i - 0.5) * 0.04, 0.012, w * 0.8
                out.append(make_part(f"slot_{i}_{j}", "slot", S.box((sl_d, sl_w, 0.004),
                                                                    center=(0, y + (i - 0.5) * 0.04, h + 0.001)),
                                     black()))
                continue
            out.append(make_part(f"slot_{i}_{j}", "slot", S.box((0.014, sl, 0.004), center=(x, y, h + 0.001)),
                                 black()))
    out.append(make_part("lever", "lever", S.box((0.03, 0.03, 0.015), center=(w / 2 + 0.012, 0, h * 0.7)),
                         black()))
    out.append(make_part("knob", "knob", knob((w / 2, 0, h * 0.35), 0.012, 0.01, axis=(1, 0, 0)), black()))
    out.append(make_part("crumb_tray", "crumb_tray", S.box((w * 0.8, d * 0.8, 0.006),
                                                           center=(0, 0, fh + 0.004)), mat))
    # the cancel, bagel and defrost buttons on the side panel, and the mains cord out of the back
    for k in range(3):
        out.append(make_part(f"button_{k}", "button", S.box((0.004, 0.012, 0.008), center=(w / 2 + 0.002, d * 0.25, h * (0.6 - 0.12 * k))),
                             black()))
    out.append(make_part("cord", "cord", S.tube([(0, -d / 2 + 0.002, fh + 0.02), (0, -d / 2 - 0.025, fh + 0.012),
                                                 (0.04, -d / 2 - 0.03, 0.004)], 0.003, sections=6), black("rubber")))
    out += feet4("foot", w=w, d=d, r=0.01, h=fh, mat=black("rubber"), inset=0.02)
    # the crumb tray's pull tab at the front, the moulded end caps on the two short sides, and
    # a four-slot toaster's second lever and browning knob for its other pair of slots
    out.append(make_part("tab", "tab", S.box((0.03, 0.006, 0.006), center=(0, d / 2 + 0.003, fh + 0.004)), black()))
    out += [make_part(f"end_cap_{k}", "end_cap", S.box((0.006, d * 0.85, (h - fh) * 0.85), center=(sx * (w / 2 - 0.001), 0, fh + (h - fh) / 2),
                                                      bevel=0.002), black()) for k, sx in enumerate((-1, 1))]
    if n == 4:
        out.append(make_part("lever_1", "lever", S.box((0.03, 0.03, 0.015), center=(-w / 2 - 0.012, 0, h * 0.7)), black()))
        out.append(make_part("knob_1", "knob", knob((-w / 2, 0, h * 0.35), 0.012, 0.01, axis=(-1, 0, 0)), black()))
    return out


@register("toaster_oven", parts=("body", "door"),
          extra_parts=("control_panel", "knob", "handle", "glass", "hinge", "rack", "foot", "heating_element",
                       "crumb_tray", "vent", "screw"),
          size_range=(0.38, 0.56), density=300, variants=("steel", "black", "white"),
          placement="surface")
def toaster_oven(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d, h = rng.uniform(0.4, 0.52), rng.uniform(0.3, 0.38), rng.uniform(0.22, 0.28)
    mat = {"steel": M.metal(rng), "black": black(), "white": white(rng)}[variant]
    fh = 0.02
    panel = w * 0.22
    xc = w / 2 - panel
    out: list[Part | Joint] = [make_part("body", "body", _shell(w, d, h - fh, z0=fh, x1=xc + 0.015), mat)]
    out.append(make_part("control_panel", "control_panel",
                         S.box((panel, d, h - fh), center=(xc + panel / 2, 0, fh + (h - fh) / 2)), mat))
    for k, z in enumerate(np.linspace(fh + 0.05, h - 0.05, 3)):
        out.append(make_part(f"knob_{k}", "knob", knob((xc + panel / 2, d / 2, z), 0.016, 0.018), black()))
    out.append(make_part("rack", "rack", [S.box((xc + w / 2 - 0.04, 0.006, 0.006),
                                                center=((xc - w / 2) / 2, y, fh + (h - fh) * 0.4))
                                          for y in np.linspace(-d / 2 + 0.04, d / 2 - 0.05, 6)],
                         M.metal(rng)))
    out += feet4("foot", w=w, d=d, r=0.012, h=fh, mat=black("rubber"), inset=0.02)
    # the quartz heating elements under the cavity's roof and over its floor, the crumb tray
    # on the floor, the vent slots along the top's back edge
    cw = xc + w / 2 - 0.03
    for k, z in enumerate((h - 0.015 - 0.012, fh + 0.015 + 0.01)):
        out.append(make_part(f"heating_element_{k}", "heating_element",
                             S.cylinder(0.005, cw, center=((xc - w / 2) / 2, 0.0, z), axis=(1, 0, 0), sections=8),
                             M.solid((0.55, 0.5, 0.45), "metal", 0.5, 0.6)))
    out.append(make_part("crumb_tray", "crumb_tray", S.box((cw, d - 0.05, 0.004), center=((xc - w / 2) / 2, 0.0, fh + 0.015 + 0.002)),
                         M.metal(rng)))
    out.append(make_part("vent", "vent", S.box((w * 0.6, 0.04, 0.002), center=(0, -d / 2 + 0.04, h - 0.0009)), black()))
    # the four screws holding the outer cabinet at the corners of the back
    out += back_screws("screw", x0=-w / 2, x1=w / 2, z0=fh, z1=h, y=-d / 2)
    out += door_parts("door", x0=-w / 2, x1=xc, z0=fh, z1=h, y_back=d / 2, thick=0.015, mat=mat,
                      handle_mat=M.metal(rng), hinge_left=True, style="glass", glass=M.glass(rng),
                      handle_len=(xc + w / 2) * 0.7, handle_at="top")
    return out


@register("coffee_maker", parts=("base", "reservoir", "head"),
          extra_parts=("carafe", "handle", "button", "drip_tray", "lid", "foot", "warming_plate", "carafe_lid",
                       "water_window", "portafilter", "steam_wand", "pod_holder", "power_switch", "spout",
                       "brew_basket", "display", "screw"),
          size_range=(0.25, 0.45), density=400, variants=("drip", "pod", "espresso"),
          placement="surface")
def coffee_maker(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.18, 0.28), rng.uniform(0.22, 0.3), rng.uniform(0.28, 0.4)
    mat = black() if rng.uniform() < 0.5 else M.metal(rng)
    bh = 0.04
    out = [make_part("base", "base", S.box((w, d, bh), center=(0, 0, bh / 2), bevel=0.005), mat),
           make_part("reservoir", "reservoir", S.box((w, d * 0.35, h - bh), center=(0, -d / 2 + d * 0.175, bh + (h - bh) / 2),
                                                     bevel=0.006), M.glass(rng)),
           make_part("head", "head", S.box((w, d * 0.65, h * 0.22), center=(0, d * 0.175, h - h * 0.11),
                                           bevel=0.008), mat)]
    out.append(make_part("lid", "lid", S.box((w * 0.9, d * 0.3, 0.01), center=(0, -d / 2 + d * 0.175, h + 0.005)),
                         mat))
    if variant == "drip":
        r = min(w, d * 0.6) * 0.38
        ch = (h - bh) - h * 0.22 - 0.02
        yc = d * 0.175
        out.append(make_part("carafe", "carafe", S.transformed(
            S.lathe([(r * 0.9, 0.0), (r, ch * 0.5), (r * 0.8, ch)]),
            np.array([[1, 0, 0, 0], [0, 1, 0, yc], [0, 0, 1, bh], [0, 0, 0, 1.0]])), M.glass(rng)))
        out.append(make_part("handle", "handle", S.tube([(0, yc + r - 0.002, bh + ch * 0.8),
                                                         (0, yc + r + 0.03, bh + ch * 0.8),
                                                         (0, yc + r + 0.03, bh + ch * 0.3),
                                                         (0, yc + r - 0.002, bh + ch * 0.3)], 0.006),
                             black()))
        # the warming plate under the carafe and the carafe's lid
        out.append(make_part("warming_plate", "warming_plate", S.cylinder(r * 1.05, 0.004, center=(0, yc, bh + 0.001),
                                                                          sections=20), black("metal")))
        out.append(make_part("carafe_lid", "carafe_lid", S.cylinder(r * 0.82, 0.012, center=(0, yc, bh + ch - 0.001),
                                                                    sections=16), black()))
    else:
        out.append(make_part("drip_tray", "drip_tray", S.box((w * 0.7, d * 0.35, 0.015),
                                                             center=(0, d * 0.25, bh + 0.0075)),
                             M.metal(rng)))
        zh = h - h * 0.22
        if variant == "espresso":
            # the portafilter locked under the group head, and the steam wand at the side
            out.append(make_part("portafilter", "portafilter",
                                 [S.cylinder(0.03, 0.025, center=(0, d * 0.2, zh - 0.0125), sections=16),
                                  S.box((0.025, 0.11, 0.02), center=(0, d * 0.2 + 0.08, zh - 0.015))], black("metal")))
            out.append(make_part("steam_wand", "steam_wand", S.tube([(w / 2 - 0.025, d * 0.3, zh), (w / 2 - 0.025, d * 0.38, zh - 0.04),
                                                                     (w / 2 - 0.02, d * 0.4, bh + 0.06)], 0.004, sections=8),
                                 M.metal(rng)))
        else:
            out.append(make_part("pod_holder", "pod_holder", S.cylinder(0.025, 0.02, center=(0, d * 0.2, zh - 0.01), sections=16),
                                 black()))
    # the water level window on the reservoir's side and the rubber feet
    out.append(make_part("water_window", "water_window", S.box((0.001, d * 0.2, (h - bh) * 0.5),
                                                                center=(w / 2 + 0.0005, -d / 2 + d * 0.175, bh + (h - bh) * 0.45)),
                         M.solid((0.6, 0.75, 0.9), "glass", 0.1)))
    out += _pads(w, d)
    # the four screws up into the base's underside, between the pads, holding its bottom plate
    out += flush_screws("screw", [(sx * w * 0.25, sy * d * 0.25, 0.0) for sy in (-1, 1) for sx in (-1, 1)],
                        axis=(0.0, 0.0, -1.0), radius=0.0035)
    # the row of buttons on the head's front (power, and the cup sizes or the clock's setting
    # keys) and the small display beside them
    out += [make_part(f"button_{k}", "button", S.cylinder(0.007, 0.006, center=(x, d / 2 + 0.002, h - h * 0.11), axis=(0, 1, 0),
                                                          sections=12), black())
            for k, x in enumerate(np.linspace(w * 0.3, -w * 0.3, 4))]
    out.append(make_part("display", "display", S.box((0.05, 0.002, 0.018), center=(0, d / 2 + 0.001, h - h * 0.11 + 0.022)),
                         M.solid((0.2, 0.4, 0.6), "glass", 0.1)))
    # the rocker switch on the base's right side and the outlet under the head the coffee
    # runs from; a drip machine's swing-out brew basket in the head over the carafe
    out.append(make_part("power_switch", "power_switch", S.box((0.004, 0.02, 0.012), center=(w / 2 + 0.001, d * 0.2, bh / 2)),
                         black()))
    zh = h - h * 0.22
    out.append(make_part("spout", "spout", S.cylinder(0.008, 0.01, center=(0, d * 0.2, zh - 0.004), sections=10), black()))
    if variant == "drip":
        out.append(make_part("brew_basket", "brew_basket", S.frustum(0.03, 0.045, 0.006, center=(0, d * 0.2, zh - 0.003), sections=12),
                             black()))
    return out


@register("mini_fridge", parts=("body", "door"),
          extra_parts=("handle", "shelf", "hinge", "foot", "freezer_compartment", "glass", "thermostat", "crisper",
                       "vent", "gasket", "door_shelf", "light", "screw"),
          size_range=(0.45, 0.95), density=250, variants=("cube", "under_counter", "glass_door"),
          placement="floor")
def mini_fridge(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    if variant == "cube":
        w, d, h = rng.uniform(0.42, 0.48), rng.uniform(0.44, 0.5), rng.uniform(0.48, 0.55)
    else:
        w, d, h = rng.uniform(0.48, 0.55), rng.uniform(0.5, 0.58), rng.uniform(0.8, 0.88)
    mat = white(rng) if variant != "glass_door" else black()
    fh = 0.02
    t = 0.04  # insulated walls
    out: list[Part | Joint] = [make_part("body", "body", _shell(w, d - 0.05, h - fh, z0=fh, t=t), mat)]
    out[0] = make_part("body", "body", [S.transformed(s, np.array([[1, 0, 0, 0], [0, 1, 0, -0.025],
                                                                   [0, 0, 1, 0], [0, 0, 0, 1.0]]))
                                        for s in _shell(w, d - 0.05, h - fh, z0=fh, t=t)], mat)
    zi = fh + (h - fh) * 0.5
    out.append(make_part("shelf", "shelf", S.box((w - 2 * t, d - 0.05 - t - 0.02, 0.006),
                                                 center=(0, -0.025 + t / 2 - 0.01, zi)), M.glass(rng)))
    if variant != "glass_door":
        out.append(make_part("freezer_compartment", "freezer_compartment",
                             S.box((w - 2 * t - 0.02, (d - 0.05) * 0.6, 0.1),
                                   center=(0, -0.025, h - t - 0.06)), white(rng)))
    out += feet4("foot", w=w, d=d - 0.05, r=0.015, h=fh, mat=black("rubber"), inset=0.02)
    # the thermostat dial on the inner side wall, the crisper drawer on the floor, the condenser
    # grille on the back
    out.append(make_part("thermostat", "thermostat", S.cylinder(0.018, 0.012, center=(w / 2 - t - 0.006, d / 2 - 0.12, h - t - 0.16),
                                                                axis=(1, 0, 0), sections=12), white(rng, "plastic")))
    out.append(make_part("crisper", "crisper", S.box((w - 2 * t - 0.01, (d - 0.05) * 0.6, 0.08),
                                                     center=(0, -0.025 + 0.01, fh + t + 0.04 + 0.001)), M.glass(rng)))
    out.append(make_part("vent", "vent", S.box((w * 0.7, 0.004, (h - fh) * 0.5), center=(0, -d / 2 - 0.002, fh + (h - fh) * 0.4)),
                         black()))
    # the four screws holding the back panel at its corners, outside the grille
    out += back_screws("screw", x0=-w / 2, x1=w / 2, z0=fh, z1=h, y=-d / 2)
    # the lamp in the cabinet's roof beside the thermostat, and a tall fridge's second shelf:
    # the glass cover over the crisper drawer (a bottle still stands on it below the shelf)
    out.append(make_part("light", "light", S.box((0.05, 0.03, 0.01), center=(-w * 0.15, d / 2 - 0.15, h - t - 0.005)),
                         M.solid((1.0, 0.98, 0.9), "glass", 0.1)))
    if variant != "cube":
        out.append(make_part("shelf_1", "shelf", S.box((w - 2 * t, d - 0.05 - t - 0.02, 0.006),
                                                       center=(0, -0.025 + t / 2 - 0.01, fh + t + 0.085)), M.glass(rng)))
    out += door_parts("door", x0=-w / 2, x1=w / 2, z0=fh, z1=h, y_back=d / 2 - 0.05, thick=0.05, mat=mat,
                      handle_mat=M.metal(rng), hinge_left=False, style="glass" if variant == "glass_door"
                      else "flat", glass=M.glass(rng), handle_len=min(0.3, (h - fh) * 0.4))
    # the magnetic gasket round the door's inner face, and a solid door's two shelves (bins)
    # on its inner face; all ride on the door
    yg = d / 2 - 0.05 - 0.004
    seal = black("rubber")
    gasket = [S.box((w - 0.02, 0.008, 0.015), center=(0, yg, z)) for z in (fh + 0.0175, h - 0.0175)]
    gasket += [S.box((0.015, 0.008, h - fh - 0.05), center=(x, yg, fh + (h - fh) / 2)) for x in (-w / 2 + 0.0175, w / 2 - 0.0175)]
    out.append(make_part("gasket", "gasket", gasket, seal))
    out.append(mount("door", "gasket"))
    if variant != "glass_door":
        for k, z in enumerate((fh + (h - fh) * 0.3, fh + (h - fh) * 0.65)):
            out.append(make_part(f"door_shelf_{k}", "door_shelf", S.box((w - 2 * t - 0.02, 0.035, 0.05), center=(0, yg - 0.022, z)),
                                 white(rng, "plastic")))
            out.append(mount("door", f"door_shelf_{k}"))
    return out


@register("dishwasher", parts=("body", "door"),
          extra_parts=("handle", "control_panel", "rack", "hinge", "toe_kick", "button", "spray_arm", "cutlery_basket",
                       "filter", "detergent_dispenser", "foot", "indicator", "rinse_aid_cap", "bracket", "screw"),
          size_range=(0.8, 0.9), density=300, variants=("steel", "white", "panel_ready"))
def dishwasher(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d, h = rng.uniform(0.45, 0.6), rng.uniform(0.55, 0.62), rng.uniform(0.82, 0.88)
    mat = {"steel": M.metal(rng), "white": white(rng), "panel_ready": M.wood(rng)}[variant]
    tk = 0.1
    out: list[Part | Joint] = [make_part("body", "body", _shell(w, d - 0.03, h - tk, z0=tk, t=0.02), mat)]
    out[0] = make_part("body", "body", [S.transformed(s, np.array([[1, 0, 0, 0], [0, 1, 0, -0.015],
                                                                   [0, 0, 1, 0], [0, 0, 0, 1.0]]))
                                        for s in _shell(w, d - 0.03, h - tk, z0=tk, t=0.02)], mat)
    out.append(make_part("toe_kick", "toe_kick", S.box((w, d - 0.1, tk), center=(0, -0.05, tk / 2)),
                         black()))
    for k, z in enumerate((tk + 0.1, tk + 0.4)):
        out.append(make_part(f"rack_{k}", "rack", S.box((w - 0.08, d - 0.12, 0.1),
                                                        center=(0, -0.03, z + 0.05)), M.metal(rng)))
        # the spray arm turning under each rack
        out.append(make_part(f"spray_arm_{k}", "spray_arm", S.box((w - 0.14, 0.04, 0.012), center=(0, -0.03, z - 0.015)),
                             M.solid((0.6, 0.6, 0.62), "plastic", 0.5)))
    # the cutlery basket standing in the lower rack
    out.append(make_part("cutlery_basket", "cutlery_basket", S.box((0.2, 0.12, 0.12), center=(w / 2 - 0.16, d / 2 - 0.17, tk + 0.1 + 0.07)),
                         M.solid((0.6, 0.6, 0.62), "plastic", 0.5)))
    out.append(make_part("control_panel", "control_panel",
                         S.box((w, 0.03, 0.08), center=(0, d / 2 - 0.015, h - 0.04)), mat))
    out += _buttons("button", w * 0.3, d / 2, [h - 0.04], black(), r=0.006)
    # the programme buttons in a row beside the power button, each with its light above it
    for k in range(4):
        x = w * 0.3 - 0.035 * (k + 1)
        out.append(make_part(f"button_{k + 1}", "button", S.cylinder(0.006, 0.006, center=(x, d / 2 + 0.002, h - 0.045), axis=(0, 1, 0),
                                                                     sections=12), black()))
        out.append(make_part(f"indicator_{k}", "indicator", S.cylinder(0.0025, 0.002, center=(x, d / 2 + 0.001, h - 0.025), axis=(0, 1, 0),
                                                                        sections=8), M.solid((0.2, 0.6, 0.95), "glass", 0.1)))
    out += door_parts("door", x0=-w / 2, x1=w / 2, z0=tk, z1=h - 0.08, y_back=d / 2 - 0.03,
                      thick=0.03, mat=mat, handle_mat=M.metal(rng), hinge_left=True, style="flat",
                      handle_len=w * 0.6, handle_at="top")
    # the filter in the tub's floor, the detergent dispenser on the door's inner face (it rides
    # on the door), and the two front levelling feet behind the toe kick
    grey = M.solid((0.6, 0.6, 0.62), "plastic", 0.5)
    out.append(make_part("filter", "filter", S.cylinder(0.035, 0.01, center=(0, -0.03, tk + 0.02 + 0.005), sections=12), grey))
    out.append(make_part("detergent_dispenser", "detergent_dispenser",
                         S.box((0.12, 0.02, 0.07), center=(0, d / 2 - 0.03 - 0.01, tk + (h - 0.08 - tk) * 0.55)), grey))
    out.append(mount("door", "detergent_dispenser"))
    # the rinse-aid reservoir's screw cap beside the dispenser, riding on the door too
    out.append(make_part("rinse_aid_cap", "rinse_aid_cap", S.cylinder(0.018, 0.012, center=(0.1, d / 2 - 0.03 - 0.006, tk + (h - 0.08 - tk) * 0.55),
                                                                      axis=(0, 1, 0), sections=12), grey))
    out.append(mount("door", "rinse_aid_cap"))
    out += [make_part(f"foot_{k}", "foot", S.cylinder(0.012, tk * 0.5, center=(sx * (w / 2 - 0.04), d / 2 - 0.13, tk * 0.25),
                                                      sections=10), black("rubber"))
            for k, sx in enumerate((-1, 1))]
    # the two mounting brackets let into the top's front corners, each screwed up into the
    # underside of the counter above through its tab (flush with the top)
    zt = h - 0.001
    for k, sx in enumerate((-1, 1)):
        x = sx * (w / 2 - 0.05)
        out.append(make_part(f"bracket_{k}", "bracket", S.box((0.03, 0.03, 0.002), center=(x, d / 2 - 0.05, zt)), M.metal(rng)))
        out += flush_screws("screw", [(x, d / 2 - 0.05, h)], axis=(0.0, 0.0, 1.0), radius=0.004, start=k)
    return out


@register("clothes_dryer", parts=("body", "door"),
          extra_parts=("control_panel", "knob", "display", "drum", "foot", "hinge", "lint_filter", "button", "handle",
                       "gasket", "exhaust_vent", "indicator", "screw"),
          size_range=(0.8, 1.0), density=300, variants=("front_load", "stacked_steel", "compact"))
def clothes_dryer(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    if variant == "compact":
        w, d, h = rng.uniform(0.58, 0.6), rng.uniform(0.45, 0.5), rng.uniform(0.8, 0.84)
    else:
        w, d, h = rng.uniform(0.6, 0.69), rng.uniform(0.6, 0.7), rng.uniform(0.84, 0.98)
    mat = white(rng) if variant != "stacked_steel" else M.metal(rng)
    fh = 0.02
    out: list[Part | Joint] = [make_part("body", "body", S.box((w, d, h - fh - 0.12),
                                                               center=(0, 0, fh + (h - fh - 0.12) / 2),
                                                               bevel=0.006), mat)]
    out.append(make_part("control_panel", "control_panel",
                         S.box((w, d, 0.12), center=(0, 0, h - 0.06), bevel=0.006), mat))
    out.append(make_part("knob", "knob", knob((-w * 0.3, d / 2, h - 0.06), 0.025, 0.02), black()))
    out.append(make_part("display", "display", S.box((0.1, 0.004, 0.04), center=(w * 0.15, d / 2 + 0.001, h - 0.06)),
                         black()))
    out.append(make_part("lint_filter", "lint_filter", S.box((0.12, 0.01, 0.04),
                                                             center=(w * 0.3, d / 2 + 0.004, fh + 0.05)),
                         M.plastic(rng)))
    out += feet4("foot", w=w, d=d, r=0.02, h=fh, mat=black("rubber"), inset=0.03)
    r = min(w, h - 0.14) * 0.33
    zc = fh + (h - fh - 0.12) / 2
    out.append(make_part("drum", "drum", S.cylinder(r * 0.9, 0.004, center=(0, d / 2 + 0.002, zc),
                                                    axis=(0, 1, 0), sections=28), M.metal(rng)))
    door = S.cylinder(r, 0.04, center=(0, d / 2 + 0.024, zc), axis=(0, 1, 0), sections=28)
    out.append(make_part("door", "door", door, M.glass(rng)))
    out += hinge_parts("door_hinge", x=-r, y=d / 2 + 0.004, z0=zc - r * 0.5, z1=zc + r * 0.5,
                       mat=M.metal(rng), radius=0.006, length=0.03)
    out.append(revolute("door_hinge", "body", "door", axis=(0, 0, 1), origin=(-r, d / 2 + 0.004, zc)))
    # the door's pull on its free edge (it swings with the door), the rubber gasket round the
    # door opening, the start and option buttons, the exhaust duct's collar at the back
    out.append(make_part("handle", "handle", S.box((0.025, 0.02, r * 0.6), center=(r - 0.005, d / 2 + 0.044 + 0.01, zc)), black()))
    out.append(mount("door", "handle"))
    out.append(make_part("gasket", "gasket", ring([(r * 0.92, 0.0), (r * 1.04, 0.0), (r * 1.04, 0.003), (r * 0.92, 0.003)],
                                                  sections=20).apply(_facing_front(d / 2, zc)), black("rubber")))
    out += _buttons("button", w * 0.3, d / 2, [h - 0.085, h - 0.035], black(), r=0.007)
    # the option buttons under the display (dryness, delay), their lights beside them
    for k in range(2):
        out.append(make_part(f"button_{k + 2}", "button", S.cylinder(0.007, 0.006, center=(w * 0.15 + (k - 0.5) * 0.05, d / 2 + 0.002, h - 0.1),
                                                                     axis=(0, 1, 0), sections=12), black()))
        out.append(make_part(f"indicator_{k}", "indicator", S.cylinder(0.0025, 0.002, center=(w * 0.15 + (k - 0.5) * 0.05 + 0.015, d / 2 + 0.001,
                                                                                               h - 0.1), axis=(0, 1, 0), sections=8),
                             M.solid((0.95, 0.6, 0.1), "glass", 0.1)))
    out.append(make_part("exhaust_vent", "exhaust_vent", S.cylinder(0.05, 0.02, center=(0, -d / 2 - 0.01 + 0.015, fh + 0.12),
                                                                    axis=(0, 1, 0), sections=12), M.metal(rng)))
    # the four screws holding the back panel at its corners
    out += back_screws("screw", x0=-w / 2, x1=w / 2, z0=fh, z1=h - 0.12, y=-d / 2, inset=0.03)
    return out


def _facing_front(y: float, z: float) -> np.ndarray:
    """(4, 4) transform turning a ring about +Z into one facing +Y, centred at (0, y, z)."""
    T = np.eye(4)
    T[:3, :3] = np.array([[1.0, 0, 0], [0, 0, 1.0], [0, -1.0, 0]])
    T[:3, 3] = (0.0, y, z)
    return T


@register("water_cooler", parts=("body", "bottle"),
          extra_parts=("tap", "drip_tray", "cabinet_door", "collar", "foot", "indicator", "vent", "cup_dispenser",
                       "power_switch", "child_lock", "grille", "screw"),
          size_range=(0.55, 1.55), density=300, variants=("top_load", "bottom_load", "countertop"))
def water_cooler(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.3, 0.34)
    h = rng.uniform(0.9, 1.05) if variant != "countertop" else rng.uniform(0.5, 0.6)
    mat = white(rng)
    out = [make_part("body", "body", S.box((w, w, h), center=(0, 0, h / 2), bevel=0.01), mat)]
    blue = M.solid(M.jitter(rng, (0.55, 0.75, 0.95), 0.03), "plastic", 0.2)
    rb = w * 0.42
    bh = rng.uniform(0.4, 0.48)
    if variant == "bottom_load":
        out.append(make_part("bottle", "bottle", S.cylinder(rb * 0.9, 0.04, center=(0, 0, h + 0.02)), blue))
        out.append(make_part("cabinet_door", "cabinet_door", S.box((w * 0.8, 0.01, h * 0.5),
                                                                   center=(0, w / 2 + 0.005, h * 0.3)), mat))
    else:
        out.append(make_part("collar", "collar", S.cylinder(rb * 0.6, 0.03, center=(0, 0, h + 0.015)), mat))
        out.append(make_part("bottle", "bottle", S.lathe([(rb * 0.25, h + 0.03), (rb, h + 0.1),
                                                          (rb, h + 0.03 + bh - 0.05), (rb * 0.9, h + 0.03 + bh)]),
                             blue))
    for k, sx in enumerate((-1, 1)):
        col = (0.8, 0.1, 0.1) if sx > 0 else (0.1, 0.3, 0.8)
        out.append(make_part(f"tap_{k}", "tap", S.box((0.03, 0.04, 0.04),
                                                      center=(sx * w * 0.2, w / 2 + 0.02, h * 0.85)),
                             M.solid(col)))
    out.append(make_part("drip_tray", "drip_tray", S.box((w * 0.6, 0.06, 0.015),
                                                         center=(0, w / 2 + 0.03, h * 0.65)), black()))
    # the removable grille on the tray, and the hot tap's child-safety catch on its top
    out.append(make_part("grille", "grille", S.box((w * 0.55, 0.05, 0.003), center=(0, w / 2 + 0.03, h * 0.65 + 0.006)),
                         M.solid((0.6, 0.6, 0.62), "plastic", 0.5)))
    out.append(make_part("child_lock", "child_lock", S.box((0.012, 0.02, 0.006), center=(w * 0.2, w / 2 + 0.02, h * 0.85 + 0.023)),
                         M.solid((0.85, 0.85, 0.85), "plastic", 0.4)))
    # the power and heating lights, the condenser vent at the back, the levelling feet
    for k, col in enumerate(((0.2, 0.9, 0.2), (0.95, 0.3, 0.1))):
        out.append(make_part(f"indicator_{k}", "indicator", S.cylinder(0.004, 0.002, center=((k - 0.5) * 0.03, w / 2 + 0.001, h * 0.93),
                                                                        axis=(0, 1, 0), sections=8), M.solid(col, "glass", 0.1)))
    out.append(make_part("vent", "vent", S.box((w * 0.6, 0.003, h * 0.25), center=(0, -w / 2 - 0.0015, h * 0.35)), black()))
    out += _pads(w, w, inset=0.03, r=0.015, h=0.006)
    # the paper-cup tube on the right side and the heater's switch on the back
    out.append(make_part("cup_dispenser", "cup_dispenser", S.cylinder(0.04, h * 0.3, center=(w / 2 + 0.04, 0.0, h * 0.55), sections=12),
                         M.plastic(rng)))
    out.append(make_part("power_switch", "power_switch", S.box((0.02, 0.004, 0.012), center=(w * 0.25, -w / 2 - 0.002, h * 0.6)), black()))
    # the four screws holding the back panel at its corners
    out += back_screws("screw", x0=-w / 2, x1=w / 2, z0=0.0, z1=h, y=-w / 2, inset=0.03)
    return out


@register("range_hood", parts=("canopy", "chimney"), extra_parts=("filter", "light", "button", "filter_handle", "grease_channel",
                                                                 "screw", "indicator", "filter_latch"),
          size_range=(0.6, 1.25), density=200, variants=("chimney", "slim", "island"),
          placement="wall")
def range_hood(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.6, 0.9), rng.uniform(0.45, 0.55)
    steel = M.metal(rng)
    ch = rng.uniform(0.08, 0.15)
    chimney_h = rng.uniform(0.35, 0.6) if variant != "slim" else 0.1
    top_w = w * 0.4
    canopy = S.hull(np.array([[-w / 2, -d / 2, 0], [w / 2, -d / 2, 0], [-w / 2, d / 2, 0], [w / 2, d / 2, 0],
                              [-top_w / 2, -d / 2, ch + 0.08], [top_w / 2, -d / 2, ch + 0.08],
                              [-top_w / 2, -d / 2 + 0.25, ch + 0.08], [top_w / 2, -d / 2 + 0.25, ch + 0.08],
                              [-w / 2, -d / 2, ch * 0.4], [w / 2, -d / 2, ch * 0.4],
                              [-w / 2, d / 2, ch * 0.4], [w / 2, d / 2, ch * 0.4]]))
    out = [make_part("canopy", "canopy", canopy, steel),
           make_part("chimney", "chimney", S.box((top_w * 0.9, 0.22, chimney_h),
                                                 center=(0, -d / 2 + 0.125, ch + 0.08 + chimney_h / 2)),
                     steel)]
    # two baffle filters side by side under the canopy
    for k, sx in enumerate((-1, 1)):
        out.append(make_part("filter" if k == 0 else "filter_1", "filter",
                             S.box((w * 0.39, d * 0.7, 0.006), center=(sx * w * 0.2, 0.02, 0.004)),
                             M.solid((0.5, 0.5, 0.52), "metal", 0.5, 0.8)))
    for k, sx in enumerate((-1, 1)):
        out.append(make_part(f"light_{k}", "light", S.cylinder(0.025, 0.004, center=(sx * w * 0.35, d * 0.3, 0.003)),
                             M.solid((1.0, 0.97, 0.85), "glass", 0.1)))
    for k in range(4):  # the fan speeds and the light switch along the front edge
        out.append(make_part(f"button_{k}", "button", S.cylinder(0.006, 0.006, center=((k - 1.5) * 0.03, d / 2 + 0.002, ch * 0.2),
                                                                axis=(0, 1, 0), sections=12), black()))
    # each filter's pull handle, the grease channel along the canopy's back edge, and the two
    # screws fixing the chimney cover to the canopy
    for k, sx in enumerate((-1, 1)):
        out.append(make_part(f"filter_handle_{k}", "filter_handle", S.box((0.05, 0.012, 0.004), center=(sx * w * 0.2, d * 0.3, 0.0)),
                             M.solid((0.5, 0.5, 0.52), "metal", 0.5, 0.8)))
    out.append(make_part("grease_channel", "grease_channel", S.box((w * 0.8, 0.015, 0.008), center=(0, -d * 0.35, 0.005)), steel))
    # the fan-on light beside the buttons, and the spring latch at each filter's front edge
    out.append(make_part("indicator", "indicator", S.cylinder(0.003, 0.003, center=(0.075, d / 2 + 0.0015, ch * 0.2), axis=(0, 1, 0),
                                                              sections=8), M.solid((0.2, 0.6, 0.95), "glass", 0.1)))
    out += [make_part(f"filter_latch_{k}", "filter_latch", S.box((0.03, 0.01, 0.004), center=(sx * w * 0.2, d * 0.35 + 0.01, 0.0)),
                      M.solid((0.5, 0.5, 0.52), "metal", 0.5, 0.8)) for k, sx in enumerate((-1, 1))]
    for k, sx in enumerate((-1, 1)):
        out.append(make_part(f"screw_{k}", "screw", S.cylinder(0.003, 0.002, center=(sx * top_w * 0.3, -d / 2 + 0.125 + 0.111, ch + 0.1),
                                                              axis=(0, 1, 0), sections=8), steel))
    return out


@register("printer", parts=("body", "paper_tray"),
          extra_parts=("lid", "output_tray", "control_panel", "button", "display", "hinge", "foot", "paper", "usb_port",
                       "paper_guide", "power_inlet", "indicator", "screw"),
          size_range=(0.35, 0.6), density=400, variants=("inkjet", "laser", "all_in_one"),
          placement="surface")
def printer(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d = rng.uniform(0.38, 0.5), rng.uniform(0.3, 0.42)
    h = rng.uniform(0.14, 0.2) if variant == "inkjet" else rng.uniform(0.22, 0.32)
    mat = black() if rng.uniform() < 0.5 else white(rng, "plastic")
    lid_h = 0.04 if variant == "all_in_one" else 0.0
    bh = h - lid_h
    out: list[Part | Joint] = [make_part("body", "body", S.box((w, d, bh), center=(0, 0, bh / 2), bevel=0.008),
                                         mat)]
    out.append(make_part("paper_tray", "paper_tray", S.box((w * 0.7, d * 0.6, 0.04),
                                                           center=(0, d / 2 + 0.005 - d * 0.3, 0.03)), mat))
    out.append(prismatic("paper_tray_slide", "body", "paper_tray", travel=d * 0.45))
    # the paper stacked in the tray (it slides out with it), the USB port at the back, the feet
    out.append(make_part("paper", "paper", S.box((0.21, d * 0.5, 0.012), center=(0, d / 2 - d * 0.3, 0.05 + 0.006)),
                         M.solid((0.97, 0.97, 0.97), "paper", 0.9)))
    out.append(mount("paper_tray", "paper"))
    # the tray's two sliding width guides either side of the paper, riding with the tray
    for k, sx in enumerate((-1, 1)):
        out.append(make_part(f"paper_guide_{k}", "paper_guide", S.box((0.006, d * 0.3, 0.03), center=(sx * 0.109, d / 2 - d * 0.3, 0.055)),
                             mat))
        out.append(mount("paper_tray", f"paper_guide_{k}"))
    out.append(make_part("power_inlet", "power_inlet", S.box((0.03, 0.003, 0.02), center=(-w * 0.3, -d / 2 - 0.0015, bh * 0.3)), black()))
    out.append(make_part("usb_port", "usb_port", S.box((0.014, 0.002, 0.007), center=(w * 0.3, -d / 2 - 0.001, bh * 0.3)),
                         M.solid((0.2, 0.2, 0.2), "metal", 0.4, 0.6)))
    out += _pads(w, d, inset=0.04)
    # the four screws holding the rear cover at its corners
    out += back_screws("screw", x0=-w / 2, x1=w / 2, z0=0.0, z1=bh, y=-d / 2, inset=0.02, radius=0.003)
    out.append(make_part("output_tray", "output_tray", S.box((w * 0.6, 0.12, 0.006),
                                                             center=(0, d / 2 + 0.06, bh * 0.55)), mat))
    out.append(make_part("control_panel", "control_panel", S.box((w * 0.3, 0.04, 0.03),
                                                                 center=(w * 0.3, d / 2 - 0.02, bh + 0.001 - 0.015)),
                         black()))
    out.append(make_part("display", "display", S.box((0.06, 0.002, 0.02),
                                                     center=(w * 0.3, d / 2 + 0.0005, bh - 0.015)),
                         M.solid((0.2, 0.4, 0.6), "glass", 0.1)))
    out += _buttons("button", w * 0.42, d / 2, [bh - 0.015], M.solid((0.3, 0.8, 0.3)), r=0.005)
    # the cancel, copy and Wi-Fi buttons below the display, and the power and ink lights
    for k in range(3):
        out.append(make_part(f"button_{k + 1}", "button", S.cylinder(0.004, 0.004, center=(w * 0.3 + (k - 1) * 0.02, d / 2 + 0.002, bh - 0.027),
                                                                     axis=(0, 1, 0), sections=10), black()))
    for k, col in enumerate(((0.2, 0.9, 0.2), (0.95, 0.6, 0.1))):
        out.append(make_part(f"indicator_{k}", "indicator", S.cylinder(0.002, 0.002, center=(w * 0.42 + (k * 2 - 1) * 0.012, d / 2 + 0.001, bh - 0.027),
                                                                        axis=(0, 1, 0), sections=8), M.solid(col, "glass", 0.1)))
    if variant == "all_in_one":
        out.append(make_part("lid", "lid", S.box((w, d * 0.8, lid_h), center=(0, -d * 0.1, bh + lid_h / 2),
                                                 bevel=0.004), mat))
        out += hinge_parts("lid_hinge", x=bh, y=-d / 2, z0=-w * 0.3, z1=w * 0.3, mat=black(), axis="x",
                           radius=0.005, length=0.03)
        out.append(revolute("lid_hinge", "body", "lid", axis=(1, 0, 0), origin=(0, -d / 2, bh), opens=1.2))
    return out


@register("copier", parts=("body", "scanner", "drawer"),
          extra_parts=("lid", "output_tray", "control_panel", "display", "drawer_box", "handle",
                       "caster", "hinge", "key", "button", "screw"),
          size_range=(0.9, 1.3), density=350, variants=("floor", "floor_finisher", "cabinet"))
def copier(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d = rng.uniform(0.58, 0.68), rng.uniform(0.6, 0.72)
    h = rng.uniform(0.95, 1.2)
    mat = white(rng, "plastic")
    ch = 0.06
    sh = 0.12  # the scanner on top
    bh = h - sh - ch - 0.03
    out: list[Part | Joint] = [make_part("body", "body", S.box((w, d - 0.03, bh - 0.05), center=(0, -0.015, ch + 0.05 + (bh - 0.05) / 2)),
                                         mat)]
    out.append(make_part("body_plinth", "body", S.box((w, d, 0.05), center=(0, 0, ch + 0.025)), mat))
    # the four screws holding the rear cover at its corners
    out += back_screws("screw", x0=-w / 2, x1=w / 2, z0=ch + 0.05, z1=ch + bh, y=-d / 2, inset=0.03)
    n = 3 if variant != "cabinet" else 2
    zt = ch + 0.05
    dh = (bh * 0.55 - 0.05) / n
    for k in range(n):
        out += drawer_parts(f"drawer_{k}", x0=-w / 2 + 0.01, x1=w / 2 - 0.01, z0=zt + k * dh,
                            z1=zt + (k + 1) * dh - 0.005, y_front=d / 2, depth=d * 0.6, thick=0.02,
                            mat=mat, handle_mat=black(), parent="body")
    out.append(make_part("scanner", "scanner", S.box((w, d, sh), center=(0, 0, ch + bh + sh / 2),
                                                     bevel=0.006), mat))
    out.append(make_part("scanner_post", "body", S.box((w * 0.3, d * 0.9, 0.03),
                                                       center=(-w * 0.35, 0, ch + bh - 0.015)), mat))
    out.append(make_part("lid", "lid", S.box((w, d * 0.9, 0.03), center=(0, -d * 0.05, ch + bh + sh + 0.015)),
                         mat))
    out += hinge_parts("lid_hinge", x=ch + bh + sh, y=-d / 2, z0=-w * 0.3, z1=w * 0.3, mat=black(), axis="x",
                       radius=0.006, length=0.04)
    out.append(revolute("lid_hinge", "scanner", "lid", axis=(1, 0, 0), origin=(0, -d / 2, ch + bh + sh),
                        opens=1.2))
    out.append(make_part("control_panel", "control_panel", S.box((w * 0.45, 0.1, 0.03),
                                                                 center=(w * 0.2, d / 2 - 0.05, ch + bh + sh + 0.016)),
                         black()))
    # on the control panel: the touch screen, the twelve-key number pad beside it and the
    # green start and red stop buttons, each key let into the panel and standing a millimetre
    # proud of it
    zp = ch + bh + sh + 0.031
    out.append(make_part("display", "display", S.box((w * 0.2, 0.07, 0.002), center=(w * 0.2 - w * 0.1, d / 2 - 0.05, zp)),
                         M.solid((0.15, 0.3, 0.45), "glass", 0.1)))
    xk = w * 0.2 + w * 0.06
    for k in range(12):
        col, row = k % 3, k // 3
        out.append(make_part(f"key_{k}", "key", S.box((0.012, 0.012, 0.003), center=(xk + (col - 1) * 0.016, d / 2 - 0.026 - row * 0.016, zp),
                                                      bevel=0.001), M.solid((0.85, 0.85, 0.85), "plastic", 0.4)))
    for k, colr in enumerate(((0.1, 0.7, 0.2), (0.85, 0.1, 0.1))):
        out.append(make_part(f"button_{k}", "button", S.cylinder(0.009, 0.003, center=(xk + 0.05, d / 2 - 0.035 - k * 0.03, zp), sections=10),
                             M.solid(colr, "plastic", 0.3)))
    out.append(make_part("output_tray", "output_tray", S.box((w * 0.5, d * 0.6, 0.01),
                                                             center=(-w * 0.1, 0.0, ch + bh - 0.02)),
                         M.plastic(rng)))
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        out.append(make_part(f"caster_{k}", "caster", S.cylinder(ch / 2, 0.03, center=(sx * (w / 2 - 0.05), sy * (d / 2 - 0.05), ch / 2),
                                                                  axis=(1, 0, 0), sections=14), black()))
    return out


@register("computer_tower", parts=("case",),
          extra_parts=("front_panel", "power_button", "drive_bay", "vent", "foot", "side_panel", "usb_port",
                       "audio_jack", "io_shield", "fan", "psu_grille", "power_inlet", "reset_button", "indicator",
                       "thumbscrew", "slot_cover", "screw"),
          size_range=(0.3, 0.58), density=400, variants=("mid_tower", "full_tower", "mini"),
          placement="floor")
def computer_tower(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.18, 0.23)
    d, h = {"mid_tower": (rng.uniform(0.4, 0.48), rng.uniform(0.42, 0.48)),
            "full_tower": (rng.uniform(0.48, 0.55), rng.uniform(0.5, 0.55)),
            "mini": (rng.uniform(0.28, 0.34), rng.uniform(0.3, 0.36))}[variant]
    mat = black() if rng.uniform() < 0.7 else white(rng, "metal")
    fh = 0.015
    out = [make_part("case", "case", S.box((w, d, h - fh), center=(0, -0.01, fh + (h - fh) / 2)), mat),
           make_part("front_panel", "front_panel", S.box((w, 0.02, h - fh), center=(0, d / 2 - 0.01, fh + (h - fh) / 2),
                                                         bevel=0.004), mat),
           make_part("side_panel", "side_panel", S.box((0.004, d * 0.7, (h - fh) * 0.7),
                                                       center=(w / 2 + 0.002 - 0.004, -0.02, fh + (h - fh) * 0.5)),
                     M.glass(rng))]
    out.append(make_part("power_button", "power_button", S.cylinder(0.008, 0.006, center=(0, d / 2 + 0.002, h - 0.04),
                                                                    axis=(0, 1, 0), sections=12),
                         M.solid((0.3, 0.5, 0.9))))
    if variant != "mini":
        out.append(make_part("drive_bay", "drive_bay", S.box((w * 0.8, 0.004, 0.045),
                                                             center=(0, d / 2 + 0.001, h - 0.1)), black()))
    out.append(make_part("vent", "vent", S.box((w * 0.6, 0.004, 0.12), center=(0, d / 2 + 0.001, fh + 0.12)),
                         black()))
    out += feet4("foot", w=w, d=d - 0.02, r=0.012, h=fh, mat=black("rubber"), inset=0.01)
    # the front USB ports and audio jack under the power button, the back's I/O shield, the
    # power supply's fan grille and inlet, and the rear exhaust fan
    io = M.solid((0.2, 0.2, 0.22), "metal", 0.4, 0.6)
    for k in range(2):
        out.append(make_part(f"usb_port_{k}", "usb_port", S.box((0.014, 0.002, 0.006),
                                                                center=((k - 0.5) * 0.025, d / 2 + 0.001, h - 0.065)), io))
    out.append(make_part("audio_jack", "audio_jack", S.cylinder(0.004, 0.002, center=(0.035, d / 2 + 0.001, h - 0.065),
                                                                axis=(0, 1, 0), sections=8), io))
    yb = -d / 2 - 0.01
    out.append(make_part("io_shield", "io_shield", S.box((0.045, 0.002, 0.16), center=(-w * 0.2, yb - 0.001, h - 0.12)), io))
    out.append(make_part("fan", "fan", S.cylinder(0.055, 0.003, center=(w * 0.15, yb - 0.0015, h - 0.12), axis=(0, 1, 0),
                                                  sections=16), black()))
    out.append(make_part("psu_grille", "psu_grille", S.box((0.1, 0.002, 0.07), center=(-w / 2 + 0.06, yb - 0.001, fh + 0.05)), io))
    out.append(make_part("power_inlet", "power_inlet", S.box((0.03, 0.003, 0.02), center=(w / 2 - 0.02, yb - 0.0015, fh + 0.05)), black()))
    # the reset button and the power and disk lights beside the power button; at the back the
    # two thumbscrews holding the side panel and the expansion slot covers under the I/O shield
    out.append(make_part("reset_button", "reset_button", S.cylinder(0.004, 0.004, center=(0.02, d / 2 + 0.002, h - 0.04), axis=(0, 1, 0),
                                                                    sections=10), black()))
    out += [make_part(f"indicator_{k}", "indicator", S.cylinder(0.002, 0.002, center=(-0.02 - 0.008 * k, d / 2 + 0.001, h - 0.04), axis=(0, 1, 0),
                                                                sections=8), M.solid(col, "glass", 0.1))
            for k, col in enumerate(((0.2, 0.5, 0.95), (0.95, 0.5, 0.1)))]
    out += [make_part(f"thumbscrew_{k}", "thumbscrew", S.cylinder(0.005, 0.006, center=(w / 2 - 0.008, yb - 0.003, z), axis=(0, 1, 0),
                                                                  sections=10), io) for k, z in enumerate((h * 0.35, h * 0.8))]
    n_slots = 2 if variant == "mini" else 4
    out += [make_part(f"slot_cover_{k}", "slot_cover", S.box((0.1, 0.002, 0.014), center=(-w * 0.05, yb - 0.001, h - 0.22 - 0.02 * k)), io)
            for k in range(n_slots)]
    # the four screws holding the power supply at the corners of its grille, and the four
    # through the corners of the rear fan's frame into the case
    xp, zp = -w / 2 + 0.06, fh + 0.05
    pts = [(xp + sx * 0.056, yb, zp + sz * 0.04) for sz in (-1, 1) for sx in (-1, 1)]
    pts += [(w * 0.15 + sx * 0.045, yb, h - 0.12 + sz * 0.045) for sz in (-1, 1) for sx in (-1, 1)]
    out += flush_screws("screw", pts, axis=(0.0, -1.0, 0.0), radius=0.0035)
    return out

