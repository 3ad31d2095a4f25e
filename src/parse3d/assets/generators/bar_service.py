"""Bar and shop counter equipment: bar mats, beer taps and cash registers.

A bar mat lies on a counter: glasses stand ON its ``mat`` sheet, inside its raised ``rim``. A beer
tap stands on the counter, its ``faucet``s at the front (+Y) with a ``tap_handle`` on each that
pulls forward on a hinge, over a ``drip_tray``. A cash register faces the cashier at +Y: its
``cash_drawer`` slides out of the ``body`` towards +Y, the ``keypad`` sits on the sloping top and
a ``display`` faces the customer at the back.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Material, Part, make_part
from ..registry import register
from ._casework import black
from ._kit import DRAWER_TRAVEL, mount, prismatic, revolute


def _rubber(rng: np.random.Generator) -> Material:
    base = [(0.08, 0.08, 0.09), (0.1, 0.12, 0.1), (0.35, 0.1, 0.1)][int(rng.integers(3))]
    return Material(M.jitter(rng, base, 0.02), 0.9, 0.0, "rubber")


def _white_plastic(rng: np.random.Generator) -> Material:
    return Material(M.jitter(rng, (0.92, 0.92, 0.9), 0.02), 0.4, 0.0, "plastic")


@register("bar_mat", parts=("mat",), extra_parts=("channel", "rim"), size_range=(0.25, 0.75),
          density=1100, variants=("service", "square", "runner"), placement="surface")
def bar_mat(rng: np.random.Generator, variant: str) -> list[Part]:
    """A rubber mat along X: a sheet whose top holds the glasses, drainage ``channel``s moulded
    into it and a raised ``rim`` round the edge that keeps the spill in."""
    rubber = _rubber(rng)
    w, d = {"service": (rng.uniform(0.45, 0.6), rng.uniform(0.13, 0.16)),
            "square": (rng.uniform(0.28, 0.32), rng.uniform(0.28, 0.32)),
            "runner": (rng.uniform(0.6, 0.7), rng.uniform(0.08, 0.1))}[variant]
    tb, rh, rw = 0.007, 0.011, 0.008
    parts = [make_part("mat", "mat", S.box((w - 2 * rw + 0.002, d - 2 * rw + 0.002, tb),
                                           center=(0, 0, tb / 2)), rubber)]
    rim = [S.box((w, rw, rh), center=(0, d / 2 - rw / 2, rh / 2), bevel=0.001),
           S.box((w, rw, rh), center=(0, -d / 2 + rw / 2, rh / 2), bevel=0.001),
           S.box((rw, d - 2 * rw, rh), center=(w / 2 - rw / 2, 0, rh / 2), bevel=0.001),
           S.box((rw, d - 2 * rw, rh), center=(-w / 2 + rw / 2, 0, rh / 2), bevel=0.001)]
    parts.append(make_part("rim", "rim", rim, rubber))
    # the channels between the ribs, moulded into the sheet just below its top
    groove = Material(tuple(max(0.0, c * 0.6) for c in rubber.color[:3]) + (1.0,), 0.9, 0.0, "rubber")
    pitch = 0.02
    n = int((w - 2 * rw) / pitch) - 1
    for k in range(n):
        x = -w / 2 + rw + pitch * (k + 1)
        parts.append(make_part(f"channel_{k}", "channel",
                               S.box((0.006, d - 2 * rw - 0.01, 0.003), center=(x, 0, tb - 0.0018)), groove))
    return parts


@register("beer_tap", parts=("tower", "faucet", "tap_handle"),
          extra_parts=("base", "drip_tray", "grate", "collar", "badge", "ferrule", "cap", "screw"),
          size_range=(0.35, 0.85), density=2500, variants=("t_bar", "column", "double_column"),
          placement="surface")
def beer_tap(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    """A draught tower: a base flange, the tower, faucets facing +Y, a tap handle rising from
    each (pulled forward to pour) and a drip tray in front."""
    steel = Material(M.jitter(rng, (0.8, 0.8, 0.82), 0.01), 0.2, 0.95, "metal")
    chrome = Material((0.9, 0.9, 0.92, 1.0), 0.05, 1.0, "metal")
    H = rng.uniform(0.35, 0.45)
    parts: list[Part | Joint] = []
    rb = 0.06
    parts.append(make_part("base", "base", S.cylinder(rb, 0.015, center=(0, 0, 0.0075), sections=24), steel))
    if variant == "t_bar":
        n = int(rng.integers(2, 4))
        wt = 0.12 * n
        col = S.cylinder(0.035, H - 0.05, center=(0, 0, 0.015 + (H - 0.05) / 2 - 0.001), sections=20)
        bar = S.cylinder(0.04, wt, center=(0, 0, H - 0.035), axis=(1, 0, 0), sections=20)
        parts.append(make_part("tower", "tower", [col, bar], steel))
        spots = [((k - (n - 1) / 2) * 0.12, 0.04, H - 0.035) for k in range(n)]
    else:
        n = 1 if variant == "column" else 2
        col = S.cylinder(0.04, H, center=(0, 0, 0.015 + H / 2 - 0.001), sections=20)
        parts.append(make_part("tower", "tower", col, steel))
        if n == 1:
            spots = [(0.0, 0.04, H * 0.8)]
        else:
            spots = [(-0.025, 0.035, H * 0.8), (0.025, 0.035, H * 0.8)]
    for k, (x, y, z) in enumerate(spots):
        shank = S.cylinder(0.012, 0.045, center=(x, y + 0.02, z), axis=(0, 1, 0), sections=12)
        spout = S.cylinder(0.009, 0.045, center=(x, y + 0.04, z - 0.022), sections=12)
        parts.append(make_part(f"faucet_{k}", "faucet", [shank, spout], chrome))
        parts.append(make_part(f"collar_{k}", "collar", S.cylinder(0.016, 0.012, center=(x, y + 0.006, z),
                                                                   axis=(0, 1, 0), sections=16), chrome))
        hl = rng.uniform(0.12, 0.2)
        wood = M.wood(rng) if rng.random() < 0.5 else M.plastic(rng)
        lever = S.frustum(0.009, 0.015, hl, center=(x, y + 0.042, z + 0.01), sections=12)
        parts.append(make_part(f"tap_handle_{k}", "tap_handle", lever, wood))
        # the handle tips forward (+Y at its top) about the faucet's lever pin
        parts.append(revolute(f"tap_handle_{k}_pull", f"faucet_{k}", f"tap_handle_{k}", axis=(1, 0, 0),
                              origin=(x, y + 0.042, z + 0.01), opens=-0.6))
        # the brand badge on the handle's front and the chrome ferrule at its foot (both move with it)
        parts.append(make_part(f"badge_{k}", "badge", S.box((0.022, 0.003, 0.035), center=(x, y + 0.042 + 0.013, z + 0.01 + hl * 0.65)),
                               M.paper(rng)))
        parts.append(make_part(f"ferrule_{k}", "ferrule", S.cylinder(0.0105, 0.015, center=(x, y + 0.042, z + 0.01 + 0.0075),
                                                                   sections=12), chrome))
        parts += [mount(f"tap_handle_{k}", f"badge_{k}"), mount(f"tap_handle_{k}", f"ferrule_{k}")]
    # the drip tray in front of the tower, under the faucets
    y_tray = max(s[1] for s in spots) + 0.04
    tw = max(0.2, 0.12 * len(spots) + 0.08)
    tray = [S.box((tw, 0.12, 0.006), center=(0, y_tray, 0.003))]
    for sx in (-1, 1):
        tray.append(S.box((0.006, 0.12, 0.02), center=(sx * (tw / 2 - 0.003), y_tray, 0.01)))
    for sy in (-1, 1):
        tray.append(S.box((tw - 0.012, 0.006, 0.02), center=(0, y_tray + sy * 0.057, 0.01)))
    parts.append(make_part("drip_tray", "drip_tray", tray, steel))
    parts.append(make_part("grate", "grate", S.box((tw - 0.014, 0.106, 0.003), center=(0, y_tray, 0.0165)),
                           steel))
    # the tower's top cap, and the screws fixing the base flange to the counter
    top = max(p.mesh.bounds[1, 2] for p in parts if getattr(p, "label", None) == "tower")
    if variant != "t_bar":
        parts.append(make_part("cap", "cap", S.cylinder(0.042, 0.01, center=(0, 0, top + 0.004), sections=20), chrome))
    else:  # a chrome end cap on each end of the T's bar
        parts += [make_part("cap" if k == 0 else f"cap_{k}", "cap",
                            S.cylinder(0.042, 0.01, center=(sx * (wt / 2 + 0.003), 0, H - 0.035), axis=(1, 0, 0), sections=20), chrome)
                  for k, sx in enumerate((-1, 1))]
    for k, a in enumerate(np.radians([-160, -90, -20])):  # the back half: the drip tray covers the front
        parts.append(make_part(f"screw_{k}", "screw", S.cylinder(0.005, 0.003, center=(0.048 * np.cos(a), 0.048 * np.sin(a), 0.0155),
                                                                 sections=8), chrome))
    return parts


@register("cash_register", parts=("body", "cash_drawer"),
          extra_parts=("keypad", "key", "display", "screen", "printer", "drawer_box", "stand", "handle", "receipt",
                       "card_reader"),
          size_range=(0.3, 0.6), density=700, variants=("classic", "pos_terminal"),
          placement="surface")
def cash_register(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    """The cashier stands at +Y: the cash drawer slides out towards them."""
    shell_mat = M.plastic(rng) if rng.random() < 0.4 else black()
    w, d = rng.uniform(0.38, 0.45), rng.uniform(0.38, 0.45)
    hd = rng.uniform(0.09, 0.11)  # the drawer unit
    parts: list[Part | Joint] = []
    t = 0.006
    base = [S.box((w, d, t), center=(0, 0, t / 2)), S.box((w, d, t), center=(0, 0, hd - t / 2)),
            S.box((t, d, hd - 2 * t), center=(-w / 2 + t / 2, 0, hd / 2)),
            S.box((t, d, hd - 2 * t), center=(w / 2 - t / 2, 0, hd / 2)),
            S.box((w - 2 * t, t, hd - 2 * t), center=(0, -d / 2 + t / 2, hd / 2))]
    dd = d - 0.03
    box = [S.box((w - 0.03, dd, 0.006), center=(0, d / 2 - dd / 2 - 0.012, t + 0.004)),
           S.box((0.006, dd, hd * 0.55), center=(-(w - 0.03) / 2 + 0.003, d / 2 - dd / 2 - 0.012,
                                                  t + 0.007 + hd * 0.275)),
           S.box((0.006, dd, hd * 0.55), center=((w - 0.03) / 2 - 0.003, d / 2 - dd / 2 - 0.012,
                                                 t + 0.007 + hd * 0.275)),
           S.box((w - 0.042, 0.006, hd * 0.55), center=(0, d / 2 - 0.012 - dd + 0.003, t + 0.007 + hd * 0.275))]
    for k in range(1, 4):  # bill dividers
        box.append(S.box((0.003, dd * 0.5, hd * 0.4), center=(-(w - 0.03) / 2 + (w - 0.03) * k / 4,
                                                               d / 2 - 0.012 - dd * 0.7, t + 0.007 + hd * 0.2)))
    parts.append(make_part("cash_drawer_box", "drawer_box", box, black()))
    front = S.box((w - 0.014, 0.012, hd - 2 * t - 0.004), center=(0, d / 2 - 0.006, hd / 2))
    parts.append(make_part("cash_drawer", "cash_drawer", front, shell_mat))
    parts.append(make_part("cash_drawer_handle", "handle",
                           S.box((w * 0.3, 0.012, 0.012), center=(0, d / 2 + 0.004, hd * 0.35), bevel=0.003),
                           black()))
    parts += [prismatic("cash_drawer_slide", "body", "cash_drawer_box", travel=DRAWER_TRAVEL * dd * 0.8),
              mount("cash_drawer_box", "cash_drawer"), mount("cash_drawer", "cash_drawer_handle")]
    if variant == "classic":
        # the register housing on the drawer: a wedge sloping down to the cashier
        hh = rng.uniform(0.08, 0.1)
        top = S.hull(np.array([(x, y, z) for x in (-w / 2 + 0.01, w / 2 - 0.01)
                               for y, z in ((-d / 2 + 0.01, hd), (d / 2 - 0.02, hd), (-d / 2 + 0.01, hd + hh),
                                            (d / 2 - 0.06, hd + hh * 0.35))]))
        parts.append(make_part("body", "body", base + [top], shell_mat))
        # keys on the sloping face
        p0 = np.array([0.0, d / 2 - 0.06, hd + hh * 0.35])
        p1 = np.array([0.0, -d / 2 + 0.01, hd + hh])
        slope = np.arctan2(p1[2] - p0[2], p0[1] - p1[1])
        kp_c = p0 + (p1 - p0) * 0.35
        pad = S.box((w * 0.6, 0.14, 0.004), center=(0, 0, 0))
        R = np.eye(4)
        c, s = np.cos(slope), np.sin(slope)
        R[:3, :3] = np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
        R[:3, 3] = kp_c + np.array([0, 0, 0.002])
        parts.append(make_part("keypad", "keypad", pad.apply(R), black()))
        # the twenty keys, each a part of its own
        key_mat = Material((0.85, 0.85, 0.82, 1.0), 0.5, 0.0, "plastic")
        for i in range(5):
            for j in range(4):
                kb = S.box((0.018, 0.018, 0.006), center=((i - 2) * 0.03, (j - 1.5) * 0.028, 0.004))
                parts.append(make_part("key" if (i, j) == (0, 0) else f"key_{4 * i + j}", "key", kb.apply(R), key_mat))
        printer = S.box((w * 0.22, 0.06, 0.012), center=(w * 0.3, -d / 2 + 0.05, hd + hh + 0.005), bevel=0.003)
        parts.append(make_part("printer", "printer", printer, shell_mat))
        disp = S.box((w * 0.3, 0.02, 0.06), center=(-w * 0.2, -d / 2 + 0.025, hd + hh + 0.03 - 0.001), bevel=0.004)
        parts.append(make_part("display", "display", disp, black()))
        parts.append(make_part("screen", "screen", S.box((w * 0.26, 0.002, 0.04),
                                                         center=(-w * 0.2, -d / 2 + 0.014, hd + hh + 0.03)),
                               Material((0.2, 0.5, 0.3, 1.0), 0.2, 0.0, "glass")))
    else:
        parts.append(make_part("body", "body", base, shell_mat))
        # a touchscreen on a stand on top of the drawer, tilted towards the cashier
        parts.append(make_part("stand", "stand", [S.box((0.14, 0.12, 0.01), center=(0, -0.02, hd + 0.005)),
                                                  S.box((0.04, 0.03, 0.16), center=(0, -0.04, hd + 0.085))],
                               black()))
        sw, sh = rng.uniform(0.3, 0.36), rng.uniform(0.2, 0.24)
        tilt = 0.3
        T = np.eye(4)
        T[:3, :3] = np.array([[1, 0, 0], [0, np.cos(tilt), -np.sin(tilt)], [0, np.sin(tilt), np.cos(tilt)]])
        T[:3, 3] = (0, -0.02, hd + 0.16 + sh / 2 * np.cos(tilt) - 0.03)
        monitor = S.box((sw, 0.03, sh), center=(0, 0, 0), bevel=0.005).apply(T)
        parts.append(make_part("display", "display", monitor, black()))
        T2 = T.copy()
        T2[:3, 3] = T[:3, 3] + T[:3, :3] @ np.array([0, 0.0155, 0])
        parts.append(make_part("screen", "screen", S.box((sw - 0.03, 0.002, sh - 0.03)).apply(T2),
                               Material((0.15, 0.25, 0.4, 1.0), 0.1, 0.0, "glass")))
        printer = S.box((0.1, 0.14, 0.1), center=(w / 2 - 0.06, -0.1, hd + 0.05 - 0.001), bevel=0.01)
        parts.append(make_part("printer", "printer", printer, _white_plastic(rng)))
        # the receipt curling out of the printer's slot, and the card reader beside the screen
        parts.append(make_part("receipt", "receipt", S.box((0.058, 0.002, 0.05), center=(w / 2 - 0.06, -0.1 + 0.02, hd + 0.1 + 0.024)),
                               M.solid((0.97, 0.97, 0.95), "paper", 0.8)))
        parts.append(make_part("card_reader", "card_reader", S.box((0.07, 0.12, 0.035), center=(-w / 2 + 0.06, -0.08, hd + 0.0175),
                                                                   bevel=0.006), black()))
    return parts
