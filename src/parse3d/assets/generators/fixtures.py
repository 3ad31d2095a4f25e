"""Fixtures every room has: curtains, window blinds, radiators, light switches, power outlets,
ceiling fans and air conditioners.

Wall fixtures have their back at -Y (``SECURED_TO`` a wall by ``back``); a ceiling fan's canopy
is its top (``HANGING_BELOW`` the ceiling, or ``SECURED_TO``). Blinds are built slat by slat and
radiators section by section: people name those parts.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._casework import black, white
from ._kit import rot


@register("curtain", parts=("panel", "rod"), extra_parts=("finial", "ring", "tieback", "bracket", "screw", "clip", "tieback_hook"),
          size_range=(1.0, 3.2),
          density=200, variants=("pair", "single", "tied_back"), placement="wall")
def curtain(rng: np.random.Generator, variant: str) -> list[Part]:
    W, H = rng.uniform(1.0, 2.6), rng.uniform(1.4, 2.6)
    cloth = M.fabric(rng)
    metal = M.metal(rng)
    yr = 0.1
    parts = [make_part("rod", "rod", S.cylinder(0.012, W + 0.2, center=(0, yr, H), axis=(1, 0, 0), sections=12), metal)]
    for i, s in enumerate((-1, 1)):
        parts.append(make_part(f"finial_{i}", "finial", S.ellipsoid((0.03, 0.025, 0.025), center=(s * (W / 2 + 0.12), yr, H)), metal))
        parts.append(make_part(f"bracket_{i}", "bracket", S.box((0.02, yr, 0.03), center=(s * (W / 2 + 0.04), yr / 2, H)), metal))
        # two screws through each bracket's foot into the wall, above and below the arm
        parts += [make_part(f"screw_{2 * i + j}", "screw", S.cylinder(0.004, 0.003, center=(s * (W / 2 + 0.04), 0.0015, H + dz), axis=(0, 1, 0),
                                                                      sections=8), metal) for j, dz in enumerate((-0.02, 0.02))]
    panels = [(-W / 2, 0.0), (0.0, W / 2)] if variant != "single" else [(-W / 2, W / 2)]
    k = 0
    for i, (x0, x1) in enumerate(panels):
        folds = max(3, int((x1 - x0) / 0.12))
        if variant == "tied_back":  # gathered to the side: narrower, thicker
            xc = x0 + 0.2 if i == 0 else x1 - 0.2
            x0, x1 = xc - 0.15, xc + 0.15
        pitch = (x1 - x0) / folds
        pleats = [S.box((pitch * 0.9, 0.04, H - 0.05), center=(x0 + pitch * (j + 0.5), yr + 0.02 * (j % 2 - 0.5), (H - 0.05) / 2 + 0.01))
                  for j in range(folds)]
        parts.append(make_part(f"panel_{i}", "panel", pleats, cloth))
        for j in range(0, folds, 2):
            parts.append(make_part(f"ring_{k}", "ring", S.cylinder(0.02, 0.01, center=(x0 + pitch * (j + 0.5), yr, H - 0.02), axis=(1, 0, 0),
                                                                  sections=10), metal))
            # the clip hanging from the ring's eyelet that grips the panel's heading
            parts.append(make_part(f"clip_{k}", "clip", S.box((0.008, 0.006, 0.022), center=(x0 + pitch * (j + 0.5), yr, H - 0.045)), metal))
            k += 1
        if variant == "tied_back":
            parts.append(make_part(f"tieback_{i}", "tieback", S.box((0.34, 0.09, 0.04), center=((x0 + x1) / 2, yr, H * 0.45)), cloth))
            # the wall hook the tieback is looped over, at the panel's outer side
            xh = x0 - 0.02 if i == 0 else x1 + 0.02
            parts.append(make_part(f"tieback_hook_{i}", "tieback_hook", S.box((0.015, yr - 0.045, 0.015), center=(xh, (yr - 0.045) / 2, H * 0.45)),
                                   metal))
    return parts


@register("window_blind", parts=("slat", "headrail"), extra_parts=("bottom_rail", "cord", "wand", "bracket", "pull", "end_cap",
                                                                  "vane_weight", "cord_plug",
                                                                  "carrier", "chain", "lift_cord", "tassel"),
          size_range=(0.5, 2.0),
          density=400, variants=("venetian", "roller", "vertical"), placement="wall")
def window_blind(rng: np.random.Generator, variant: str) -> list[Part]:
    W, H = rng.uniform(0.6, 1.6), rng.uniform(0.8, 1.6)
    mat = M.solid(M.jitter(rng, [(0.95, 0.95, 0.93), (0.75, 0.6, 0.42), (0.3, 0.3, 0.32)][int(rng.integers(3))], 0.02), "plastic", 0.5)
    parts = [make_part("headrail", "headrail", S.box((W, 0.05, 0.05), center=(0, 0.025, H - 0.025), bevel=0.004), mat)]
    # the two mounting brackets at the headrail's ends, against the wall
    metal = M.solid((0.8, 0.8, 0.8), "metal", 0.4, 0.8)
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"bracket_{k}", "bracket", S.box((0.02, 0.052, 0.056), center=(sx * (W / 2 - 0.03), 0.026, H - 0.028)),
                               metal))
    if variant == "roller":
        parts.append(make_part("slat", "slat", S.box((W - 0.04, 0.003, H - 0.1), center=(0, 0.03, (H - 0.1) / 2 + 0.03)),
                               M.fabric(rng)))
        parts.append(make_part("bottom_rail", "bottom_rail", S.box((W - 0.03, 0.015, 0.03), center=(0, 0.03, 0.015)), mat))
        parts.append(make_part("cord", "cord", S.cylinder(0.002, H * 0.6, center=(W / 2 - 0.04, 0.06, H - 0.05 - H * 0.3), sections=6), mat))
        # the weighted toggle at the end of the pull cord
        parts.append(make_part("pull", "pull", S.cylinder(0.007, 0.03, center=(W / 2 - 0.04, 0.06, H - 0.05 - H * 0.6 - 0.015),
                                                          sections=8), mat))
        # the caps closing the bottom rail's ends
        parts += [make_part(f"end_cap_{k}", "end_cap", S.box((0.006, 0.017, 0.032), center=(sx * ((W - 0.03) / 2 + 0.003), 0.03, 0.016)), mat)
                  for k, sx in enumerate((-1, 1))]
        return parts
    if variant == "vertical":
        n = int((W - 0.04) / 0.09)
        for k in range(n):
            x = -W / 2 + 0.02 + 0.09 * (k + 0.5)
            parts.append(make_part(f"slat_{k}", "slat", S.box((0.08, 0.003, H - 0.08), center=(x, 0.025, (H - 0.08) / 2 + 0.02),
                                                              R=rot((0, 0, 1), 0.5)), mat))
        parts.append(make_part("wand", "wand", S.cylinder(0.005, H * 0.6, center=(W / 2 - 0.03, 0.06, H - 0.05 - H * 0.3), sections=8), mat))
        # the carrier clip each vane hangs from under the headrail, and the chain linking the
        # vanes' bottoms so they turn together
        for k in range(n):
            x = -W / 2 + 0.02 + 0.09 * (k + 0.5)
            parts.append(make_part(f"carrier_{k}", "carrier", S.box((0.012, 0.012, 0.012), center=(x, 0.025, H - 0.05 - 0.006)), metal))
            # the weight in the vane's bottom hem that keeps it hanging straight
            parts.append(make_part(f"vane_weight_{k}", "vane_weight", S.box((0.07, 0.004, 0.018), center=(x, 0.025, 0.03),
                                                                            R=rot((0, 0, 1), 0.5)), mat))
        parts.append(make_part("chain", "chain", S.cylinder(0.0015, 0.09 * (n - 1), center=(-W / 2 + 0.02 + 0.09 * n / 2, 0.025, 0.035),
                                                            axis=(1, 0, 0), sections=6), metal))
        return parts
    n = int((H - 0.08) / 0.025)
    tilt = rot((1, 0, 0), rng.uniform(0.1, 0.6))
    for k in range(n):
        z = 0.04 + k * 0.025
        parts.append(make_part(f"slat_{k}", "slat", S.box((W - 0.02, 0.025, 0.0015), center=(0, 0.025, z + 0.01), R=tilt), mat))
    parts.append(make_part("bottom_rail", "bottom_rail", S.box((W - 0.01, 0.03, 0.02), center=(0, 0.025, 0.01)), mat))
    # the caps on the bottom rail's ends, and the plugs closing the ladder cords' holes under it
    parts += [make_part(f"end_cap_{k}", "end_cap", S.box((0.004, 0.03, 0.02), center=(sx * ((W - 0.01) / 2 - 0.002), 0.025, 0.01)), mat)
              for k, sx in enumerate((-1, 1))]
    parts += [make_part(f"cord_plug_{k}", "cord_plug", S.cylinder(0.006, 0.002, center=(sx * W * 0.3, 0.025, 0.001), sections=8), mat)
              for k, sx in enumerate((-1, 1))]
    # the ladder cords running down through the slats from the headrail to the bottom rail
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"cord_{k}", "cord", S.cylinder(0.0015, H - 0.07, center=(sx * W * 0.3, 0.025, 0.02 + (H - 0.07) / 2),
                                                               sections=6), M.solid((0.9, 0.9, 0.88), "fabric", 0.8)))
    parts.append(make_part("wand", "wand", S.cylinder(0.005, H * 0.5, center=(-W / 2 + 0.03, 0.06, H - 0.05 - H * 0.25), sections=8), mat))
    # the lift cord hanging from the headrail's right end, and its tassel
    cord = M.solid((0.9, 0.9, 0.88), "fabric", 0.8)
    parts.append(make_part("lift_cord", "lift_cord", S.cylinder(0.0015, H * 0.5, center=(W / 2 - 0.04, 0.055, H - 0.05 - H * 0.25),
                                                                sections=6), cord))
    parts.append(make_part("tassel", "tassel", S.frustum(0.006, 0.003, 0.03, center=(W / 2 - 0.04, 0.055, H - 0.05 - H * 0.5 - 0.03),
                                                         sections=8), mat))
    return parts


@register("radiator", parts=("section",), extra_parts=("pipe", "valve", "bracket", "panel", "bleed_valve", "top_grille", "side_cover"),
          size_range=(0.4, 1.7), density=900,
          variants=("column", "panel", "towel_rail"), placement="wall")
def radiator(rng: np.random.Generator, variant: str) -> list[Part]:
    enamel = white(rng)
    chrome = M.solid((0.8, 0.8, 0.82), "metal", 0.25, 0.9)
    if variant == "panel":
        W, H = rng.uniform(0.6, 1.6), rng.uniform(0.4, 0.7)
        parts = [make_part(f"panel_{i}", "panel", S.box((W, 0.025, H), center=(0, 0.04 + 0.045 * i, H / 2 + 0.1), bevel=0.006), enamel)
                 for i in range(2)]
        fins = [S.box((W - 0.04, 0.02, H - 0.06), center=(0, 0.0625, H / 2 + 0.1))]
        parts.append(make_part("section", "section", fins, enamel))
        # the slotted grille over the gap between the panels, flush with their tops, and the
        # cover closing each end of the gap
        parts.append(make_part("top_grille", "top_grille", S.box((W - 0.008, 0.02, 0.004), center=(0, 0.0625, H + 0.1 - 0.002)), enamel))
        parts += [make_part(f"side_cover_{k}", "side_cover", S.box((0.004, 0.02, H - 0.004), center=(sx * (W / 2 - 0.002), 0.0625, H / 2 + 0.1 - 0.002)),
                            enamel) for k, sx in enumerate((-1, 1))]
        z_pipe, x_end = 0.1, W / 2
    elif variant == "towel_rail":
        W, H = rng.uniform(0.45, 0.6), rng.uniform(0.8, 1.5)
        parts = [make_part(f"section_{i}", "section", S.cylinder(0.014, H, center=(s * W / 2, 0.06, H / 2 + 0.15), sections=12), chrome)
                 for i, s in enumerate((-1, 1))]
        n = int(H / 0.07)
        for k in range(n):
            parts.append(make_part(f"rail_{k}", "section", S.cylinder(0.01, W, center=(0, 0.06, 0.2 + k * (H - 0.1) / n), axis=(1, 0, 0),
                                                                      sections=10), chrome))
        z_pipe, x_end = 0.15, W / 2
    else:
        n = int(rng.integers(6, 16))
        H = rng.uniform(0.45, 0.75)
        p = 0.05
        W = n * p
        parts = [make_part(f"section_{k}", "section", S.box((p * 0.8, 0.1, H), center=(-W / 2 + p * (k + 0.5), 0.07, 0.12 + H / 2), bevel=0.012),
                           enamel) for k in range(n)]
        parts.append(make_part("header", "pipe", [S.cylinder(0.014, W, center=(0, 0.07, z), axis=(1, 0, 0), sections=10)
                                                  for z in (0.12 + 0.04, 0.12 + H - 0.04)], enamel))
        z_pipe, x_end = 0.12, W / 2
    parts.append(make_part("pipe", "pipe", S.cylinder(0.01, z_pipe + 0.02, center=(x_end + 0.03, 0.07, (z_pipe + 0.02) / 2), sections=10),
                           chrome))
    parts.append(make_part("valve", "valve", S.cylinder(0.02, 0.06, center=(x_end + 0.03, 0.07, z_pipe + 0.05), sections=12), chrome))
    for i, s in enumerate((-1, 1)):
        parts.append(make_part(f"bracket_{i}", "bracket", S.box((0.03, 0.04, 0.05), center=(s * (x_end - 0.08), 0.02, z_pipe + 0.2)), black()))
    # the return pipe and its lockshield valve at the other end, and the air bleed valve in
    # the top corner above the flow valve
    parts.append(make_part("pipe_1", "pipe", S.cylinder(0.01, z_pipe + 0.02, center=(-x_end - 0.03, 0.07, (z_pipe + 0.02) / 2), sections=10),
                           chrome))
    parts.append(make_part("valve_1", "valve", S.cylinder(0.017, 0.045, center=(-x_end - 0.03, 0.07, z_pipe + 0.0425), sections=10), chrome))
    zt = max(float(p.bounds[1, 2]) for p in parts if p.label in ("section", "panel"))
    parts.append(make_part("bleed_valve", "bleed_valve", S.cylinder(0.006, 0.014, center=(x_end + 0.007, 0.07, zt - 0.03), axis=(1, 0, 0),
                                                                    sections=8), chrome))
    return parts


@register("light_switch", parts=("plate", "rocker"), extra_parts=("screw", "bezel", "pilot_light"),
          size_range=(0.07, 0.16), density=900,
          variants=("single", "double", "triple"), placement="wall")
def light_switch(rng: np.random.Generator, variant: str) -> list[Part]:
    n = {"single": 1, "double": 2, "triple": 3}[variant]
    col = (0.96, 0.96, 0.94) if rng.random() < 0.8 else (0.15, 0.15, 0.16)
    plastic = M.solid(M.jitter(rng, col, 0.01), "plastic", 0.35)
    w = 0.072 if n == 1 else 0.072 * (1 + 0.55 * (n - 1)) * 0.9
    h = 0.115 if n < 3 else 0.118
    parts = [make_part("plate", "plate", S.box((w, 0.008, h), center=(0, 0.004, h / 2), bevel=0.0015), plastic)]
    rw = (w - 0.02) / n
    # the bezel framing the rockers, and each rocker's little locator light
    parts.append(make_part("bezel", "bezel", [S.box((w - 0.016, 0.002, 0.004), center=(0, 0.009, h / 2 + sz * 0.0255))
                                              for sz in (-1, 1)]
                           + [S.box((0.004, 0.002, 0.047), center=(sx * (w / 2 - 0.01), 0.009, h / 2)) for sx in (-1, 1)],
                           plastic))
    for k in range(n):
        x = -w / 2 + 0.01 + rw * (k + 0.5)
        parts.append(make_part(f"rocker_{k}", "rocker", S.box((rw * 0.8, 0.008, 0.045), center=(x, 0.011, h / 2), bevel=0.001,
                                                              R=rot((1, 0, 0), 0.06)), plastic))
        parts.append(make_part(f"pilot_light_{k}", "pilot_light", S.box((0.004, 0.0012, 0.002), center=(x, 0.0155, h / 2 - 0.016)),
                               M.solid((0.9, 0.5, 0.1), "glass", 0.1)))
    for i, s in enumerate((-1, 1)):
        parts.append(make_part(f"screw_{i}", "screw", S.cylinder(0.003, 0.002, center=(0, 0.0085, h / 2 + s * (h / 2 - 0.012)),
                                                                 axis=(0, 1, 0), sections=8), M.solid((0.8, 0.8, 0.8), "metal", 0.3, 0.9)))
    return parts


@register("power_outlet", parts=("plate", "socket"), extra_parts=("screw", "usb_port", "slot", "ground_hole"),
          size_range=(0.07, 0.16), density=900,
          variants=("single", "double", "usb"), placement="wall")
def power_outlet(rng: np.random.Generator, variant: str) -> list[Part]:
    n = 1 if variant == "single" else 2
    plastic = M.solid(M.jitter(rng, (0.95, 0.95, 0.93), 0.01), "plastic", 0.35)
    w, h = (0.072, 0.115) if n == 1 else (0.146, 0.086)
    parts = [make_part("plate", "plate", S.box((w, 0.008, h), center=(0, 0.004, h / 2), bevel=0.0015), plastic)]
    for k in range(n):
        x = 0.0 if n == 1 else (k - 0.5) * 0.068
        parts.append(make_part(f"socket_{k}", "socket", S.cylinder(0.022, 0.004, center=(x, 0.009, h / 2), axis=(0, 1, 0), sections=20),
                               plastic))
        # the two blade slots and the round earth hole in the socket's face (dark, just proud of it)
        for j, sx in enumerate((-1, 1)):
            parts.append(make_part(f"slot_{2 * k + j}", "slot", S.box((0.0025, 0.0008, 0.009),
                                                                     center=(x + sx * 0.0065, 0.0114, h / 2 + 0.003)), black()))
        parts.append(make_part(f"ground_hole_{k}", "ground_hole", S.cylinder(0.0025, 0.0008, center=(x, 0.0114, h / 2 - 0.009),
                                                                            axis=(0, 1, 0), sections=8), black()))
    if variant == "usb":
        parts.append(make_part("usb_port", "usb_port", S.box((0.014, 0.002, 0.006), center=(0, 0.0085, h * 0.15)), black()))
    steel = M.solid((0.8, 0.8, 0.8), "metal", 0.3, 0.9)
    if n == 1:  # one screw between the sockets' top and the plate's edge
        parts.append(make_part("screw", "screw", S.cylinder(0.003, 0.002, center=(0, 0.0085, h * 0.85), axis=(0, 1, 0), sections=8), steel))
    else:  # a double plate is screwed at both ends
        parts += [make_part("screw" if k == 0 else f"screw_{k}", "screw", S.cylinder(0.003, 0.002, center=(sx * (w / 2 - 0.008), 0.0085, h / 2),
                                                                                      axis=(0, 1, 0), sections=8), steel)
                  for k, sx in enumerate((-1, 1))]
    return parts


@register("ceiling_fan", parts=("blade", "motor"), extra_parts=("canopy", "downrod", "blade_arm", "light", "pull_chain", "blade_screw",
                                                                 "coupling_cover", "switch_housing", "screw"),
          size_range=(0.8, 1.45), density=600, variants=("four_blade", "five_blade", "with_light"), placement="ceiling")
def ceiling_fan(rng: np.random.Generator, variant: str) -> list[Part]:
    D = rng.uniform(0.9, 1.4)
    n = 4 if variant == "four_blade" else 5
    rod = rng.uniform(0.1, 0.3)
    metal = M.metal(rng)
    blade_mat = M.wood(rng)
    top = 0.0
    parts = [make_part("canopy", "canopy", S.frustum(0.05, 0.07, 0.06, center=(0, 0, top - 0.06), sections=20), metal),
             make_part("downrod", "downrod", S.cylinder(0.01, rod, center=(0, 0, top - 0.06 - rod / 2), sections=10), metal)]
    zm = top - 0.06 - rod
    parts.append(make_part("motor", "motor", S.union([S.cylinder(0.1, 0.09, center=(0, 0, zm - 0.045), sections=24)]), metal))
    for k in range(n):
        a = 2 * np.pi * k / n
        R = rot((0, 0, 1), a)
        c = R @ np.array([0.1 + (D / 2 - 0.1) / 2 + 0.05, 0, 0])
        parts.append(make_part(f"blade_{k}", "blade", S.box((D / 2 - 0.16, 0.12, 0.008), center=(c[0], c[1], zm - 0.07),
                                                            R=R @ rot((1, 0, 0), 0.2)), blade_mat))
        ca = R @ np.array([0.12, 0, 0])
        parts.append(make_part(f"blade_arm_{k}", "blade_arm", S.box((0.1, 0.03, 0.01), center=(ca[0], ca[1], zm - 0.075), R=R), metal))
        # the two screws fixing the blade to its arm, heads under the arm
        for j, rx in enumerate((0.15, 0.16)):
            cs = R @ np.array([rx, (-1) ** j * 0.008, 0])
            parts.append(make_part(f"blade_screw_{2 * k + j}", "blade_screw",
                                   S.cylinder(0.004, 0.003, center=(cs[0], cs[1], zm - 0.0815), sections=8), metal))
    # the two screws through the canopy's side into the ceiling bracket
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"screw_{k}", "screw", S.cylinder(0.004, 0.004, center=(sx * 0.062, 0, top - 0.03), axis=(1, 0, 0), sections=8),
                               metal))
    # the cover over the downrod's coupling on the motor, and the switch housing under the motor
    parts.append(make_part("coupling_cover", "coupling_cover", S.frustum(0.045, 0.02, 0.04, center=(0, 0, zm), sections=16), metal))
    parts.append(make_part("switch_housing", "switch_housing", S.cylinder(0.06, 0.03, center=(0, 0, zm - 0.09 - 0.015 + 0.03), sections=20),
                           metal))
    zb = zm - 0.09
    if variant == "with_light":
        parts.append(make_part("light", "light", S.ellipsoid((0.09, 0.09, 0.06), center=(0, 0, zb - 0.03)),
                               M.solid((0.95, 0.93, 0.85), "glass", 0.1)))
        zb -= 0.09
    parts.append(make_part("pull_chain", "pull_chain", S.cylinder(0.002, 0.12, center=(0.03, 0, zb - 0.06 + 0.005), sections=6), metal))
    return parts


@register("air_conditioner", parts=("body",), extra_parts=("front_panel", "louver", "vent", "display", "pipe", "vane", "filter",
                                                            "knob", "button", "exhaust_port", "handle", "side_curtain", "drain_plug",
                                                            "indicator"),
          size_range=(0.45, 1.2), density=500, variants=("split", "window", "portable"), placement="wall")
def air_conditioner(rng: np.random.Generator, variant: str) -> list[Part]:
    shell = white(rng, "plastic")
    if variant == "split":
        w, d, h = rng.uniform(0.75, 1.1), rng.uniform(0.2, 0.26), rng.uniform(0.26, 0.32)
        parts = [make_part("body", "body", S.box((w, d, h), center=(0, d / 2, h / 2), bevel=0.03), shell),
                 make_part("front_panel", "front_panel", S.box((w - 0.02, 0.01, h * 0.6), center=(0, d + 0.004, h * 0.6)), shell),
                 make_part("louver", "louver", S.box((w * 0.8, 0.05, 0.006), center=(0, d - 0.02, 0.03), R=rot((1, 0, 0), 0.5)), shell),
                 make_part("display", "display", S.box((0.06, 0.004, 0.02), center=(w / 2 - 0.1, d + 0.01, h * 0.35)),
                           M.solid((0.1, 0.3, 0.5), "glass", 0.1)),
                 # the intake grille's slats across the top
                 *[make_part("vent" if i == -2 else f"vent_{i + 2}", "vent",
                             S.box((w - 0.06, 0.012, 0.004), center=(0, d / 2 + 0.02 * i, h + 0.001)),
                             M.solid((0.8, 0.8, 0.8), "plastic")) for i in range(-2, 3)]]
        parts.append(make_part("pipe", "pipe", S.tube([(-w / 2 + 0.05, 0.02, 0.02), (-w / 2 + 0.05, 0.02, -0.15)], 0.012), shell))
        # the vertical vanes steering the air behind the louver, and the two mesh filters
        # under the front panel (it lifts to take them out)
        grey = M.solid((0.8, 0.8, 0.8), "plastic")
        for k, x in enumerate(np.linspace(-w * 0.3, w * 0.3, 4)):
            parts.append(make_part(f"vane_{k}", "vane", S.box((0.004, 0.04, 0.035), center=(x, d - 0.04, 0.04)), grey))
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"filter_{k}", "filter", S.box((w * 0.42, 0.004, h * 0.45), center=(sx * w * 0.23, d - 0.003, h * 0.6)),
                                   M.solid((0.6, 0.65, 0.7), "fabric", 0.8)))
        # the power, timer and sleep lights beside the display
        parts += [make_part(f"indicator_{k}", "indicator", S.cylinder(0.003, 0.003, center=(w / 2 - 0.15 - 0.015 * k, d + 0.0075, h * 0.35),
                                                                      axis=(0, 1, 0), sections=8), M.solid((0.2, 0.8, 0.3), "glass", 0.2))
                  for k in range(3)]
        return parts
    if variant == "window":
        w, d, h = rng.uniform(0.48, 0.66), rng.uniform(0.45, 0.6), rng.uniform(0.32, 0.42)
    else:
        w, d, h = rng.uniform(0.35, 0.45), rng.uniform(0.3, 0.4), rng.uniform(0.7, 0.8)
    parts = [make_part("body", "body", S.box((w, d, h), center=(0, d / 2, h / 2), bevel=0.015), shell),
             make_part("front_panel", "front_panel", S.box((w - 0.03, 0.01, h * 0.7), center=(0, d + 0.004, h * 0.45)), shell)]
    n = 6
    for k in range(n):
        parts.append(make_part(f"louver_{k}", "louver", S.box((w * 0.55, 0.015, 0.006), center=(0, d + 0.012, h * 0.15 + k * h * 0.1),
                                                               R=rot((1, 0, 0), 0.4)), M.solid((0.8, 0.8, 0.8), "plastic")))
    parts.append(make_part("display", "display", S.box((0.08, 0.004, 0.03), center=(w / 2 - 0.08, d + 0.008, h * 0.85)),
                           M.solid((0.1, 0.3, 0.5), "glass", 0.1)))
    parts.append(make_part("vent", "vent", S.box((w * 0.8, 0.004, h * 0.3), center=(0, -0.001, h * 0.6)), black()))
    # the washable filter behind the front grille, and the controls: a window unit's two dials
    # beside the louvers, a portable one's buttons on the top, its exhaust hose port at the
    # back and the recessed grips on its sides
    parts.append(make_part("filter", "filter", S.box((w * 0.6, 0.004, h * 0.3), center=(-w * 0.05, d - 0.003, h * 0.45)),
                           M.solid((0.6, 0.65, 0.7), "fabric", 0.8)))
    # the condensate drain plug low on the back
    parts.append(make_part("drain_plug", "drain_plug", S.cylinder(0.012, 0.01, center=(w * 0.3, -0.005 + 0.002, 0.04), axis=(0, 1, 0),
                                                                  sections=10), black()))
    if variant == "window":
        for k, z in enumerate((h * 0.55, h * 0.3)):
            parts.append(make_part(f"knob_{k}", "knob", S.cylinder(0.02, 0.015, center=(w / 2 - 0.08, d + 0.0125, z), axis=(0, 1, 0),
                                                                  sections=12), M.solid((0.8, 0.8, 0.8), "plastic")))
        # the folded accordion side curtains that fill the window opening either side, drawn in
        parts += [make_part(f"side_curtain_{k}", "side_curtain", S.box((0.012, 0.06, h * 0.9), center=(sx * (w / 2 - 0.006), d * 0.35, h * 0.5)),
                            black()) for k, sx in enumerate((-1, 1))]
    else:
        for k in range(3):
            parts.append(make_part(f"button_{k}", "button", S.cylinder(0.008, 0.004, center=((k - 1) * 0.03, d * 0.75, h + 0.001),
                                                                      sections=10), black()))
        parts.append(make_part("exhaust_port", "exhaust_port", S.cylinder(0.07, 0.02, center=(0, -0.01 + 0.012, h * 0.3),
                                                                        axis=(0, 1, 0), sections=12), black()))
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"handle_{k}", "handle", S.box((0.004, 0.08, 0.025), center=(sx * (w / 2 - 0.001), d / 2, h * 0.85)),
                                   black()))
    return parts
