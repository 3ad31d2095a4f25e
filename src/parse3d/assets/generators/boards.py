"""Wall-mounted boards and shelves: whiteboards and wall shelves.

Both hang on a wall: their flat back lies in the plane y = min y (−Y, pressed against the wall)
and their face looks toward +Y.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._casework import black, white


def _frame_loop(w: float, h: float, y: float, zc: float, r: float) -> S.Shape:
    """A closed round-profile frame tracing a ``w x h`` rectangle in the plane y, centred at zc."""
    hw, hh = w / 2, h / 2
    path = [[-hw, y, zc - hh], [hw, y, zc - hh], [hw, y, zc + hh], [-hw, y, zc + hh]]
    return S.tube(path, r, sections=8, closed=True)


@register("whiteboard", parts=("board", "tray"), extra_parts=("frame", "marker", "standoff", "corner", "end_cap", "eraser",
                                                             "tray_bracket", "screw"),
          size_range=(0.6, 2.45), density=700, variants=("framed", "frameless", "wood_frame"), placement="wall")
def whiteboard(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.6, 2.4)
    h = float(np.clip(w * rng.uniform(0.5, 0.75), 0.45, 1.2))
    t = 0.015
    face = white(rng, "plastic") if variant != "frameless" else M.glass(rng)
    alu = M.solid((0.78, 0.79, 0.8), "metal", 0.35, 0.9)
    parts = []
    gap = 0.02 if variant == "frameless" else 0.0  # glass boards stand off the wall on pins
    y_board = gap + t / 2
    # the front face of the board or its frame, and the lowest point of either: the tray runs below
    # them and reaches in front of them, so its usable floor lies wholly in front of the frame
    y_face, below = {"frameless": (gap + t, 0.0), "framed": (y_board + 0.012, 0.012), "wood_frame": (0.025, 0.04)}[variant]
    drop = max(0.02, below + 0.008)  # the tray's floor top sits a few millimetres under the frame
    zc = h / 2 + 0.06 + drop - 0.02
    if variant == "frameless":
        parts.append(make_part("board", "board", S.box((w, t, h), center=(0, y_board, zc), bevel=0.003), face))
        for i, (sx, sz) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            x, z = sx * (w / 2 - 0.05), zc + sz * (h / 2 - 0.05)
            pin = S.cylinder(0.012, gap + t + 0.01, center=(x, (gap + t + 0.01) / 2, z), axis=(0, 1, 0), sections=12)
            parts.append(make_part(f"standoff_{i}", "standoff", pin, alu))
    else:
        parts.append(make_part("board", "board", S.box((w, t, h), center=(0, y_board, zc)), face))
        if variant == "framed":
            parts.append(make_part("frame", "frame", _frame_loop(w, h, y_board, zc, 0.012), alu))
            # the moulded corner pieces joining the frame's rails
            for i, (sx, sz) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
                parts.append(make_part(f"corner_{i}", "corner", S.box((0.04, t + 0.012, 0.04),
                                                                      center=(sx * (w / 2 - 0.008), y_board + 0.003, zc + sz * (h / 2 - 0.008)),
                                                                      bevel=0.004), black()))
        else:
            fw = 0.04
            wood = M.wood(rng)
            bars = [S.box((w + 2 * fw, 0.025, fw), center=(0, 0.0125, zc - h / 2 - fw / 2), bevel=0.004),
                    S.box((w + 2 * fw, 0.025, fw), center=(0, 0.0125, zc + h / 2 + fw / 2), bevel=0.004),
                    S.box((fw, 0.025, h), center=(-w / 2 - fw / 2, 0.0125, zc), bevel=0.004),
                    S.box((fw, 0.025, h), center=(w / 2 + fw / 2, 0.0125, zc), bevel=0.004)]
            parts.append(make_part("frame", "frame", bars, wood))
    # the marker tray: a ledge with a lip along the bottom front edge; 7 cm of floor in front of the frame
    tw = min(w * 0.6, 0.8) if variant == "frameless" else w * 0.9
    z_tray = zc - h / 2 - drop
    y0 = gap + t if variant == "frameless" else 0.0
    td = max(y_face, y0 + 0.006) - y0 + 0.076  # the tray's depth: its back plate, 7 cm of floor, its lip
    y_use = y0 + td - 0.041  # the middle of the usable floor, in front of the frame
    tray = [S.box((tw, td, 0.008), center=(0, y0 + td / 2, z_tray)),
            S.box((tw, 0.006, 0.022), center=(0, y0 + td - 0.003, z_tray + 0.011)),
            S.box((tw, 0.006, 0.04), center=(0, y0 + 0.003, z_tray))]
    parts.append(make_part("tray", "tray", tray, alu))
    # the two brackets screwing the tray's back plate to the wall
    for i, sx in enumerate((-1, 1)):
        parts.append(make_part(f"tray_bracket_{i}", "tray_bracket", S.box((0.03, 0.004, 0.05), center=(sx * tw * 0.35, y0 + 0.008, z_tray - 0.005)),
                               alu))
        # the screw through its foot below the tray into the wall
        parts.append(make_part(f"bracket_screw_{i}", "screw", S.cylinder(0.0035, 0.0015, center=(sx * tw * 0.35, y0 + 0.01 + 0.00075, z_tray - 0.025),
                                                                                axis=(0, 1, 0), sections=8), alu))
    if variant == "wood_frame":  # the screws through the frame's corners into the wall
        for i, (sx, sz) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"screw_{i}", "screw", S.cylinder(0.004, 0.002, center=(sx * (w / 2 + 0.02), 0.026, zc + sz * (h / 2 + 0.02)),
                                                                     axis=(0, 1, 0), sections=8), alu))
    # the tray's end caps and the eraser lying in it
    for i, sx in enumerate((-1, 1)):
        parts.append(make_part(f"end_cap_{i}", "end_cap", S.box((0.008, td, 0.03), center=(sx * (tw / 2 + 0.004), y0 + td / 2, z_tray + 0.007)),
                               black()))
    parts.append(make_part("eraser", "eraser", S.box((0.12, 0.05, 0.03), center=(tw / 2 - 0.1, y_use, z_tray + 0.004 + 0.015),
                                                     bevel=0.004), M.solid((0.15, 0.15, 0.16), "fabric", 0.9)))
    for i in range(int(rng.integers(0, 3))):
        mx = -tw / 2 + 0.1 + i * 0.05
        cap = M.solid([(0.1, 0.1, 0.1), (0.8, 0.15, 0.15), (0.15, 0.3, 0.8)][i], "plastic")
        parts.append(make_part(f"marker_{i}", "marker",
                               S.cylinder(0.009, 0.13, center=(mx, y_use, z_tray + 0.004 + 0.009), axis=(1, 0, 0),
                                          sections=10), cap))
    return parts


@register("wall_shelf", parts=("shelf", "bracket"), extra_parts=("screw", "hook", "edge_band"), size_range=(0.4, 1.6), density=600,
          variants=("bracketed", "floating", "two_tier"), placement="wall")
def wall_shelf(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.45, 1.2)
    d, t = rng.uniform(0.18, 0.3), rng.uniform(0.018, 0.035)
    wood = M.wood(rng)
    steel = M.metal(rng) if rng.random() < 0.7 else M.solid((0.08, 0.08, 0.09), "metal", 0.5, 0.6)
    parts = []
    if variant == "floating":
        # a hidden cleat: a wall plate behind the board (its back is the wall plane)
        zt = rng.uniform(0.05, 0.08)
        parts.append(make_part("shelf", "shelf", S.box((w, d, t), center=(0, d / 2, zt + t / 2), bevel=0.002), wood))
        parts.append(make_part("bracket", "bracket",
                               S.box((w * 0.8, 0.006, zt + t * 0.6), center=(0, -0.003, (zt + t * 0.6) / 2)), steel))
        # the screws through the cleat plate below the board, and the veneer edge band on its front
        for k, x in enumerate(np.linspace(-w * 0.3, w * 0.3, 3)):
            parts.append(make_part(f"screw_{k}", "screw", S.cylinder(0.0045, 0.003, center=(x, 0.0015, zt * 0.45), axis=(0, 1, 0),
                                                                    sections=10), steel))
        parts.append(make_part("edge_band", "edge_band", S.box((w - 0.004, 0.0015, t - 0.004), center=(0, d + 0.00075, zt + t / 2)),
                               wood))
        return parts
    levels = [0.2] if variant == "bracketed" else [0.2, 0.2 + rng.uniform(0.25, 0.35)]
    if variant == "two_tier":
        d = min(d, 0.22)
    arm = d * 0.8
    n_br = 2 if w < 1.0 else 3
    xs = np.linspace(-w / 2 + 0.08, w / 2 - 0.08, n_br)
    lh = rng.uniform(0.12, 0.16)
    for k, zt in enumerate(levels):
        name = "shelf" if len(levels) == 1 else f"shelf_{k}"
        parts.append(make_part(name, "shelf", S.box((w, d, t), center=(0, d / 2, zt - t / 2), bevel=0.002), wood))
    z_low = levels[0] - t
    for i, x in enumerate(xs):
        if variant == "two_tier":  # side standards carrying both boards
            z_top = levels[-1] - t
            shapes = [S.box((0.02, 0.02, z_top - z_low + 0.1), center=(x, 0.01, (z_low + z_top) / 2 - 0.05))]
            for zt in levels:
                shapes.append(S.box((0.015, arm, 0.02), center=(x, 0.02 + arm / 2, zt - t - 0.01)))
        else:  # an L bracket with a diagonal brace swept as a tube
            shapes = [S.box((0.02, 0.005, lh), center=(x, 0.0025, z_low - lh / 2)),
                      S.box((0.02, arm, 0.005), center=(x, arm / 2, z_low - 0.0025)),
                      S.tube([[x, 0.008, z_low - lh * 0.85], [x, arm * 0.85, z_low - 0.008]], 0.005, sections=8)]
        parts.append(make_part(f"bracket_{i}", "bracket", shapes, steel))
        # two screw heads fixing the bracket's wall plate (the standard) to the wall
        if variant == "two_tier":
            y_face, zs = 0.02, (z_low - 0.03, levels[-1] - t - 0.05)
        else:
            y_face, zs = 0.005, (z_low - lh * 0.3, z_low - lh * 0.75)
        for k, z in enumerate(zs):
            parts.append(make_part(f"screw_{2 * i + k}", "screw",
                                   S.cylinder(0.0045, 0.003, center=(x, y_face + 0.0015, z), axis=(0, 1, 0),
                                              sections=10), steel))
    # a screw up through each bracket's arm into each board, and the veneer edge band on each
    # board's front
    n_sc = 2 * len(xs)
    for x in xs:
        for zt in levels:
            parts.append(make_part(f"screw_{n_sc}", "screw", S.cylinder(0.004, 0.003, center=(x, arm * 0.6, zt - t - 0.006 - 0.0015),
                                                                         sections=8), steel))
            n_sc += 1
    for k, zt in enumerate(levels):
        parts.append(make_part("edge_band" if k == 0 else f"edge_band_{k}", "edge_band",
                               S.box((w - 0.004, 0.0015, t - 0.004), center=(0, d + 0.00075, zt - t / 2)), wood))
    if variant == "bracketed":
        # cup hooks under the board between the brackets (mugs, towels hang from them)
        for k, x in enumerate(np.linspace(-w / 2 + 0.15, w / 2 - 0.15, 3 if w < 0.9 else 5)):
            y = d * 0.6
            parts.append(make_part(f"hook_{k}", "hook",
                                   S.tube([(x, y, z_low), (x, y, z_low - 0.04), (x, y + 0.015, z_low - 0.05),
                                           (x, y + 0.025, z_low - 0.035)], 0.0025, sections=6), steel))
    return parts
