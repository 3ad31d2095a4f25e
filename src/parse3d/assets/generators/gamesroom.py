"""The games room beside the tables: pool balls, cues and the rack they hang in, game consoles
and their controllers, bean bags and neon signs.

A pool cue stands upright (butt down, tip up) as it leans on a wall or stands in a rack; a cue
rack hangs on a wall with its cues' butts in the cups on its lower ``rest`` and their shafts in
the slots of the upper ``clip``; ``holder`` names the cups and the clip together, so a cue IN
``cue_rack:holder`` stands in a cup. A neon sign's tubes face +Y in front of its backplate.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._dF_slots import slots
from ._kit import feet4, rot
from ._rods import rod, segments

_BALL_COLOURS = [(0.95, 0.8, 0.1), (0.1, 0.2, 0.7), (0.85, 0.1, 0.1), (0.4, 0.1, 0.5), (0.95, 0.45, 0.05),
                 (0.05, 0.45, 0.2), (0.5, 0.1, 0.1), (0.05, 0.05, 0.05)]


@register("pool_ball", parts=("ball",), extra_parts=("stripe", "number"),
          size_range=(0.05, 0.062), density=1700, variants=("solid", "striped", "cue"), placement="surface")
def pool_ball(rng: np.random.Generator, variant: str) -> list[Part]:
    r = 0.0286 if rng.random() < 0.8 else 0.0262  # 57.2 mm pool, 52.4 mm snooker
    white = M.solid((0.95, 0.94, 0.88), "plastic", 0.15)
    colour = M.solid(_BALL_COLOURS[int(rng.integers(len(_BALL_COLOURS)))], "plastic", 0.15)
    main = white if variant in ("cue", "striped") else colour
    parts = [make_part("ball", "ball", S.ellipsoid((r, r, r), center=(0, 0, r), subdivisions=2), main)]
    if variant == "striped":
        parts.append(make_part("stripe", "stripe", S.cylinder(r * 1.005, r * 0.9, center=(0, 0, r), axis=(0, 1, 0),
                                                              sections=24), colour))
    ink = M.solid((0.05, 0.05, 0.05), "plastic", 0.3)
    if variant != "cue":  # the number, on opposite sides, one facing the viewer
        for k, sy in enumerate((1, -1)):
            parts.append(make_part(f"number_{k}", "number", S.box((r * 0.2, 0.0006, r * 0.35),
                                                                  center=(0, sy * (r * 0.97 + 0.0013), r)), ink))
    return parts


@register("pool_cue", parts=("shaft", "butt"), extra_parts=("tip", "ferrule", "joint", "wrap", "bumper", "ring", "inlay"),
          size_range=(1.2, 1.5), density=700, variants=("one_piece", "two_piece", "short"))
def pool_cue(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(1.45, 1.48) if variant != "short" else rng.uniform(1.22, 1.32)
    wood = M.wood(rng)
    dark = Material(M.jitter(rng, (0.15, 0.08, 0.05), 0.03), 0.4, 0.0, "wood")
    zb = 0.012
    lb = L * 0.48
    zj = zb + lb
    parts = [make_part("bumper", "bumper", S.cylinder(0.0145, zb, center=(0, 0, zb / 2), sections=16),
                       M.solid((0.05, 0.05, 0.05), "rubber", 0.9)),
             make_part("butt", "butt", S.frustum(0.015, 0.0105, lb, center=(0, 0, zb), sections=16), dark)]
    parts.append(make_part("wrap", "wrap", S.frustum(0.0138, 0.0124, 0.25, center=(0, 0, zb + lb * 0.22), sections=16),
                           M.solid((0.1, 0.1, 0.12), "leather", 0.8)))
    if variant == "two_piece":
        parts.append(make_part("joint", "joint", S.cylinder(0.011, 0.025, center=(0, 0, zj + 0.0125), sections=16),
                               M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9)))
        zs = zj + 0.025
    else:
        zs = zj
    ls = L - zs - 0.028
    parts.append(make_part("shaft", "shaft", S.frustum(0.0104, 0.0065, ls, center=(0, 0, zs), sections=16), wood))
    parts.append(make_part("ferrule", "ferrule", S.cylinder(0.0065, 0.02, center=(0, 0, zs + ls + 0.01), sections=12),
                           M.solid((0.95, 0.95, 0.92), "plastic", 0.3)))
    parts.append(make_part("tip", "tip", S.cylinder(0.0062, 0.008, center=(0, 0, zs + ls + 0.024), sections=12),
                           M.solid((0.15, 0.3, 0.6), "leather", 0.9)))
    # the trim rings either end of the wrap, and four pearl diamonds inlaid round the forearm
    # above it
    zw0, zw1 = zb + lb * 0.22, zb + lb * 0.22 + 0.25

    def r_butt(z: float) -> float:
        return float(np.interp(z, [zb, zb + lb], [0.015, 0.0105]))

    pearl = M.solid((0.93, 0.92, 0.88), "plastic", 0.2)
    for k, z in enumerate((zw0, zw1)):
        rr = r_butt(z)
        parts.append(make_part(f"ring_{k}", "ring", S.cylinder(rr + 0.0004, 0.004, center=(0, 0, z + (0.002 if k == 0 else -0.002)),
                                                               sections=16), pearl))
    zi = zw1 + 0.06
    ri = r_butt(zi)
    for k in range(4):
        a = np.pi / 4 + k * np.pi / 2
        parts.append(make_part(f"inlay_{k}", "inlay", S.box((0.006, 0.0008, 0.03), center=(np.cos(a) * ri, np.sin(a) * ri, zi),
                                                            R=rot((0, 0, 1), a + np.pi / 2)), pearl))
    return parts


def _cup() -> S.Shape:
    """A cup a cue's butt stands in: 4.4 cm across, 2.5 cm deep, its floor an internal support."""
    return S.vessel([(0.022, 0.0), (0.022, 0.025)], 0.003, bottom=0.003, sections=12, piece_sections=12)


@register("cue_rack", parts=("holder", "rest"), extra_parts=("back_panel", "shelf", "cup", "clip", "screw", "base", "post",
                                                             "lip"),
          groups={"holder": ("clip", "cup")},
          size_range=(0.6, 1.4), density=600, variants=("wall", "wall_shelf", "floor"), placement="wall")
def cue_rack(rng: np.random.Generator, variant: str) -> list[Part]:
    wood = M.wood(rng)
    brass = M.solid((0.8, 0.65, 0.3), "metal", 0.3, 0.9)
    n = int(rng.integers(4, 9))
    pitch = 0.06
    w = n * pitch + 0.06
    h = rng.uniform(0.95, 1.2) if variant != "floor" else rng.uniform(1.1, 1.3)
    parts = []
    if variant == "floor":  # a round base with a post; a slotted holder and a cupped rest around it
        parts.append(make_part("base", "base", S.cylinder(w / 2, 0.04, center=(0, 0, 0.02), sections=32), wood))
        parts.append(make_part("post", "post", S.cylinder(0.025, h - 0.04, center=(0, 0, 0.04 + (h - 0.04) / 2), sections=16),
                               wood))
        parts.append(make_part("rest", "rest", S.cylinder(w / 2 - 0.01, 0.03, center=(0, 0, 0.055), sections=32), wood))
        parts.append(make_part("clip", "clip", S.cylinder(w / 2 - 0.01, 0.03, center=(0, 0, h - 0.25), sections=32), wood))
        for k in range(n):  # a cup for each butt round the rest
            a = 2 * np.pi * k / n
            c = ((w / 2 - 0.04) * np.cos(a), (w / 2 - 0.04) * np.sin(a))
            parts.append(make_part(f"cup_{k}", "cup", _cup().moved((c[0], c[1], 0.07)), wood))
        parts.append(make_part("lip", "lip", S.cylinder(0.05, 0.03, center=(0, 0, h - 0.015), sections=16), wood))
        return parts
    t = 0.02
    parts.append(make_part("back_panel", "back_panel", S.box((w, t, h), center=(0, t / 2, h / 2), bevel=0.003), wood))
    d = 0.07
    # the rest: a ledge along the bottom with a cup for each butt
    parts.append(make_part("rest", "rest", S.box((w, d, 0.03), center=(0, t + d / 2, 0.015), bevel=0.003), wood))
    for k in range(n):
        x = -w / 2 + 0.03 + pitch * (k + 0.5)
        parts.append(make_part(f"cup_{k}", "cup", _cup().moved((x, t + 0.048, 0.03)), brass))
    # the clip: a bar near the top with a tooth between neighbouring slots (the cups and the clip
    # together are what a person calls the holder)
    zh = h - 0.2
    parts.append(make_part("clip", "clip", S.box((w, 0.03, 0.04), center=(0, t + 0.015, zh), bevel=0.003), wood))
    for k in range(n + 1):
        x = -w / 2 + 0.03 + pitch * k
        parts.append(make_part(f"clip_tooth_{k}", "clip", S.box((0.016, d - 0.03, 0.04),
                                                                    center=(x, t + 0.03 + (d - 0.03) / 2, zh), bevel=0.002),
                               wood))
    if variant == "wall_shelf":  # a small shelf at the top for the balls and chalk
        parts.append(make_part("shelf", "shelf", S.box((w, 0.1, 0.02), center=(0, t + 0.05, h - 0.06)), wood))
        parts.append(make_part("shelf_lip", "lip", S.box((w, 0.012, 0.03), center=(0, t + 0.094, h - 0.035)), wood))
    # the screws fixing the back panel to the wall: two at its top, two just above the rest
    for k, (x, z) in enumerate(((-w / 2 + 0.015, h - 0.03), (w / 2 - 0.015, h - 0.03), (-w / 2 + 0.015, 0.06), (w / 2 - 0.015, 0.06))):
        parts.append(make_part(f"screw_{k}", "screw", S.cylinder(0.005, 0.003, center=(x, t + 0.0015, z), axis=(0, 1, 0),
                                                                 sections=8), brass))
    return parts


@register("game_console", parts=("body",), extra_parts=("button", "vent", "foot", "stand", "disc_slot", "port", "light",
                                                        "dock", "screen", "controller", "thumbstick", "shoulder_button",
                                                        "power_inlet"),
          size_range=(0.15, 0.42), density=700, variants=("slim", "tower", "dock"), placement="surface")
def game_console(rng: np.random.Generator, variant: str) -> list[Part]:
    shell = M.solid(M.jitter(rng, [(0.08, 0.08, 0.09), (0.9, 0.9, 0.9)][int(rng.integers(2))], 0.02)[:3], "plastic", 0.4)
    black = M.solid((0.04, 0.04, 0.04), "plastic", 0.4)
    light = M.solid((0.3, 0.6, 1.0), "glass", 0.1)
    parts = []
    if variant == "dock":  # a hybrid console: a dock with the tablet standing in it, controllers on its sides
        w, d, h = 0.175, 0.055, 0.105
        parts.append(make_part("body", "body", [S.box((w, d, h * 0.8), center=(0, 0, h * 0.4), bevel=0.006)], black))
        parts.append(make_part("dock", "dock", S.box((w - 0.01, d * 0.5, 0.012), center=(0, d * 0.1, h * 0.8 + 0.006)), black))
        tw = 0.24
        parts.append(make_part("screen", "screen", S.box((0.173, 0.014, 0.102), center=(0, d * 0.1, h * 0.8 + 0.012 + 0.051),
                                                         bevel=0.004), black))
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"controller_{k}", "controller",
                                   S.box(((tw - 0.173) / 2, 0.014, 0.102), center=(sx * (tw / 2 - (tw - 0.173) / 4), d * 0.1,
                                                                                   h * 0.8 + 0.012 + 0.051), bevel=0.005),
                                   M.solid([(0.9, 0.2, 0.2), (0.1, 0.6, 0.9)][k], "plastic", 0.4)))
        parts.append(make_part("light", "light", S.box((0.01, 0.002, 0.003), center=(w / 2 - 0.02, d / 2 + 0.001, 0.02)), light))
        parts.append(make_part("port", "port", S.box((0.012, 0.002, 0.005), center=(-w / 2 + 0.025, d / 2 + 0.001, 0.03)),
                               black))
        # the dock's vent slots in its back
        parts += slots("vent", "vent", n=4, x0=-w * 0.3, x1=w * 0.3, z0=h * 0.3, z1=h * 0.65, y=-d / 2 - 0.001, thick=0.002,
                       mat=black)
        # each controller's thumbstick and face button on its front
        zc = h * 0.8 + 0.012 + 0.051
        yc = d * 0.1 + 0.007
        for k, sx in enumerate((-1, 1)):
            xc = sx * (tw / 2 - (tw - 0.173) / 4)
            parts.append(make_part(f"thumbstick_{k}", "thumbstick", S.cylinder(0.007, 0.006, center=(xc, yc + 0.003, zc + sx * 0.02), axis=(0, 1, 0),
                                                                              sections=10), black))
            parts.append(make_part(f"button_{k}", "button", S.cylinder(0.004, 0.003, center=(xc, yc + 0.0015, zc - sx * 0.02), axis=(0, 1, 0),
                                                                      sections=8), black))
            # the shoulder button on the controller's top edge, and its minus or plus button
            cw = (tw - 0.173) / 2
            parts.append(make_part(f"shoulder_button_{k}", "shoulder_button",
                                   S.box((cw * 0.7, 0.01, 0.003), center=(xc, d * 0.1, zc + 0.051 + 0.0015)), black))
            parts.append(make_part(f"button_{k + 2}", "button", S.cylinder(0.0025, 0.002, center=(xc - sx * cw * 0.25, yc + 0.001, zc + 0.04),
                                                                          axis=(0, 1, 0), sections=8), black))
        return parts
    w, d, h = rng.uniform(0.26, 0.31), rng.uniform(0.24, 0.3), rng.uniform(0.05, 0.07)
    if variant == "slim":
        zf = 0.008
        parts += feet4("foot", w=w, d=d, r=0.01, h=zf, mat=black, inset=0.02)
        parts.append(make_part("body", "body", S.box((w, d, h), center=(0, 0, zf + h / 2), bevel=0.006), shell))
        parts.append(make_part("disc_slot", "disc_slot", S.box((0.13, 0.002, 0.004), center=(-w * 0.1, d / 2 + 0.001, zf + h * 0.6)),
                               black))
        for k in range(2):
            parts.append(make_part(f"button_{k}", "button", S.box((0.012, 0.003, 0.006),
                                                                  center=(w / 2 - 0.03 - 0.02 * k, d / 2 + 0.0015, zf + h * 0.6)),
                                   black))
        parts.append(make_part("light", "light", S.box((w * 0.8, 0.002, 0.002), center=(0, d / 2 + 0.001, zf + h * 0.25)), light))
        # the exhaust grille across the back, six slots
        parts += slots("vent", "vent", n=6, x0=-w * 0.3, x1=w * 0.3, z0=zf + h / 4, z1=zf + 3 * h / 4, y=-d / 2 - 0.001, thick=0.002,
                       mat=black)
        _back_sockets(parts, x0=w / 2 - 0.03, y=-d / 2 - 0.001, z=zf + 0.0075, mat=black, start=2)
        for k in range(2):
            parts.append(make_part(f"port_{k}", "port", S.box((0.014, 0.002, 0.006),
                                                              center=(-w / 2 + 0.03 + 0.02 * k, d / 2 + 0.001, zf + h * 0.3)),
                                   black))
        return parts
    # tower: the console stands on its side in a stand, its front face still +Y
    ww, hh = h * 1.3, w * 1.15
    zs = 0.012
    parts.append(make_part("stand", "stand", S.box((ww + 0.04, d * 0.6, zs), center=(0, 0, zs / 2), bevel=0.003), black))
    parts.append(make_part("body", "body", [S.box((ww, d, hh), center=(0, 0, zs + hh / 2), bevel=0.008)], shell))
    # the exhaust grille on the back, eight slots
    parts += slots("vent", "vent", n=8, x0=-ww * 0.35, x1=ww * 0.35, z0=zs + hh * 0.15, z1=zs + hh * 0.85, y=-d / 2 - 0.001,
                   thick=0.002, mat=black)
    parts.append(make_part("disc_slot", "disc_slot", S.box((0.004, 0.002, 0.13), center=(ww * 0.2, d / 2 + 0.001, zs + hh * 0.55)),
                           black))
    for k in range(2):
        parts.append(make_part(f"button_{k}", "button", S.box((0.008, 0.003, 0.012), center=(-ww * 0.2, d / 2 + 0.0015,
                                                                                           zs + hh * 0.85 - 0.025 * k)),
                               black))
        parts.append(make_part(f"port_{k}", "port", S.box((0.014, 0.002, 0.006), center=(-ww * 0.15, d / 2 + 0.001,
                                                                                       zs + 0.04 + 0.015 * k)), black))
    parts.append(make_part("light", "light", S.box((0.003, 0.002, hh * 0.6), center=(ww / 2 - 0.006, d / 2 + 0.001, zs + hh / 2)),
                           light))
    _back_sockets(parts, x0=0.0, y=-d / 2 - 0.001, z=zs + 0.03, mat=black, start=2, upright=True)
    return parts


def _back_sockets(parts: list[Part], *, x0: float, y: float, z: float, mat, start: int = 0,
                  upright: bool = False) -> None:
    """Append a console's back sockets on its back face (``y``): the HDMI and LAN ports
    (``port_<start>``, ``port_<start + 1>``) and the power inlet, in a row leftward from
    ``(x0, z)``, or upward from it on a console standing on its side (``upright``)."""
    def at(u: float) -> tuple[float, float]:
        return (x0, z + u) if upright else (x0 - u, z)

    for k, (wd, ht) in enumerate(((0.015, 0.005), (0.016, 0.013))):
        x, zz = at(0.012 + 0.025 * k)
        size = (ht, 0.002, wd) if upright else (wd, 0.002, ht)
        parts.append(make_part(f"port_{start + k}", "port", S.box(size, center=(x, y, zz)), mat))
    x, zz = at(0.075)
    size = (0.012, 0.003, 0.02) if upright else (0.02, 0.003, 0.012)
    parts.append(make_part("power_inlet", "power_inlet", S.box(size, center=(x, y - 0.0005, zz)), mat))


@register("game_controller", parts=("body", "button"), extra_parts=("grip", "thumbstick", "dpad", "trigger", "bumper",
                                                                   "touchpad", "light", "cable"),
          size_range=(0.12, 0.19), density=600, variants=("gamepad", "arcade_pad", "wired"), placement="surface")
def game_controller(rng: np.random.Generator, variant: str) -> list[Part]:
    shell = M.solid(M.jitter(rng, [(0.08, 0.08, 0.09), (0.92, 0.92, 0.92), (0.15, 0.2, 0.45)][int(rng.integers(3))], 0.02)[:3],
                    "plastic", 0.45)
    dark = M.solid((0.05, 0.05, 0.05), "rubber", 0.7)
    w = rng.uniform(0.15, 0.165)
    d, h = 0.06, 0.032
    # lying flat: the grips reach towards the player (-Y), buttons on top, shoulder buttons on the far edge (+Y)
    parts = [make_part("body", "body", S.box((w * 0.62, d, h * 0.8), center=(0, 0.01, h * 0.4), bevel=0.01), shell)]
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"grip_{k}", "grip", S.ellipsoid((0.024, 0.045, h * 0.5), center=(sx * (w / 2 - 0.024), -0.01, h * 0.5),
                                                                subdivisions=1), shell))
        parts.append(make_part(f"bumper_{k}", "bumper", S.box((0.035, 0.012, 0.01), center=(sx * w * 0.3, 0.01 + d / 2 - 0.004,
                                                                                           h * 0.75), bevel=0.003), dark))
        if variant != "arcade_pad":
            parts.append(make_part(f"trigger_{k}", "trigger", S.box((0.022, 0.012, 0.012), center=(sx * w * 0.3, 0.01 + d / 2 - 0.01,
                                                                                                 h * 0.35), bevel=0.003), dark))
    zt = h * 0.8
    sticks = [(-0.025, -0.012), (0.025, -0.012)] if variant != "arcade_pad" else []
    for k, (x, y) in enumerate(sticks):
        parts.append(make_part(f"thumbstick_{k}", "thumbstick", [S.cylinder(0.004, 0.006, center=(x, y, zt + 0.003), sections=8),
                                                                 S.cylinder(0.009, 0.004, center=(x, y, zt + 0.008), sections=16)],
                               dark))
    parts.append(make_part("dpad", "dpad", [S.box((0.022, 0.007, 0.004), center=(-w * 0.3, 0.012, zt + 0.002)),
                                            S.box((0.007, 0.022, 0.004), center=(-w * 0.3, 0.012, zt + 0.002))], dark))
    for k, (dx, dy) in enumerate([(0, 0.009), (0.009, 0), (0, -0.009), (-0.009, 0)]):
        parts.append(make_part(f"button_{k}", "button", S.cylinder(0.004, 0.004, center=(w * 0.3 + dx, 0.012 + dy, zt + 0.002),
                                                                    sections=10),
                               M.solid([(0.9, 0.75, 0.1), (0.8, 0.15, 0.15), (0.1, 0.6, 0.2), (0.15, 0.3, 0.8)][k], "plastic", 0.3)))
    # the select and start buttons either side of the centre and the home button between the sticks
    small = M.solid((0.2, 0.2, 0.22), "plastic", 0.4)
    parts += [make_part(f"button_{4 + k}", "button", S.box((0.007, 0.004, 0.003), center=(sx * 0.024, 0.018, zt + 0.0015)), small)
              for k, sx in enumerate((-1, 1))]
    parts.append(make_part("button_6", "button", S.cylinder(0.005, 0.003, center=(0, -0.01, zt + 0.0015), sections=12), small))
    if variant == "gamepad":
        parts.append(make_part("touchpad", "touchpad", S.box((0.035, 0.02, 0.002), center=(0, 0.022, zt + 0.001)), dark))
        parts.append(make_part("light", "light", S.box((0.02, 0.002, 0.003), center=(0, 0.01 + d / 2 + 0.001, h * 0.5)),
                               M.solid((0.3, 0.6, 1.0), "glass", 0.1)))
    if variant == "wired":
        parts.append(make_part("cable", "cable", S.tube([(0, 0.01 + d / 2, h * 0.4), (0, 0.01 + d / 2 + 0.03, h * 0.2),
                                                         (0.02, 0.01 + d / 2 + 0.06, 0.003)], 0.002, sections=6), dark))
    return parts


@register("beanbag", parts=("body", "seat"), extra_parts=("back", "handle", "piping", "base", "zipper", "tag", "zipper_pull"),
          size_range=(0.6, 1.4), density=60, variants=("classic", "chair", "lounger"))
def beanbag(rng: np.random.Generator, variant: str) -> list[Part]:
    cover = M.fabric(rng) if rng.random() < 0.7 else M.leather(rng)
    r = rng.uniform(0.4, 0.5)
    parts = []
    if variant == "lounger":  # a long flat pad with a raised head end
        L = rng.uniform(1.1, 1.3)
        parts.append(make_part("body", "body", _sack(r, L / 2, 0.24), cover))
        parts.append(make_part("seat", "seat", S.ellipsoid((r * 0.8, L * 0.35, 0.06), center=(0, 0.08, 0.18), subdivisions=2), cover))
        parts.append(make_part("back", "back", S.ellipsoid((r * 0.85, 0.18, 0.16), center=(0, -L / 2 + 0.2, 0.2), subdivisions=2),
                               cover))
        parts.append(make_part("handle", "handle", S.tube([(-0.05, -L / 2 + 0.02, 0.2), (-0.05, -L / 2, 0.17), (0.05, -L / 2, 0.17),
                                                           (0.05, -L / 2 + 0.02, 0.2)], 0.008, sections=6), cover))
        rx, ry, zc = r, L / 2, 0.12
    else:
        hb = rng.uniform(0.3, 0.4)
        parts.append(make_part("base", "base", _sack(r, r, hb), cover))
        parts.append(make_part("body", "body", S.ellipsoid((r * 0.9, r * 0.9, hb * 0.55), center=(0, 0, hb * 0.7), subdivisions=2),
                               cover))
        parts.append(make_part("seat", "seat", S.ellipsoid((r * 0.65, r * 0.55, 0.07), center=(0, 0.08, hb + 0.1), subdivisions=2),
                               cover))
        hback = rng.uniform(0.7, 0.85) if variant == "chair" else rng.uniform(0.55, 0.7)
        parts.append(make_part("back", "back", S.ellipsoid((r * 0.8, 0.17, (hback - hb * 0.5) / 2),
                                                           center=(0, -r * 0.55, hb * 0.5 + (hback - hb * 0.5) / 2),
                                                           subdivisions=2), cover))
        parts.append(make_part("handle", "handle", S.tube([(-0.05, -r * 0.55 - 0.15, hback * 0.75), (-0.05, -r * 0.55 - 0.175, hback * 0.7),
                                                           (0.05, -r * 0.55 - 0.175, hback * 0.7), (0.05, -r * 0.55 - 0.15, hback * 0.75)],
                                                          0.008, sections=6), cover))
        rx, ry, zc = r, r, hb * 0.5
    # the piping round the cover's widest seam, the safety zip at the back, the sewn-in tag
    t = np.linspace(0, 2 * np.pi, 25)
    fc = 1.005 * _sack_share(zc, 2 * zc)
    seam = np.c_[rx * fc * np.cos(t), ry * fc * np.sin(t), np.full(len(t), zc)]
    parts.append(make_part("piping", "piping", S.tube(seam[:-1], 0.007, sections=6, closed=True), cover))
    parts.append(make_part("zipper", "zipper", S.box((0.25, 0.006, 0.012), center=(0, -ry * 0.97, zc * 0.55)),
                           M.solid((0.1, 0.1, 0.1), "plastic", 0.5)))
    # the zip's pull tab, and the piping round the bottom panel's seam
    parts.append(make_part("zipper_pull", "zipper_pull", S.box((0.012, 0.004, 0.03), center=(0.1, -ry * 0.97 - 0.004, zc * 0.55 - 0.012)),
                           M.solid((0.1, 0.1, 0.1), "plastic", 0.5)))
    zs = zc * 0.25
    fs = _sack_share(zs, 2 * zc)
    seam2 = np.c_[rx * fs * 1.005 * np.cos(t), ry * fs * 1.005 * np.sin(t), np.full(len(t), zs)]
    parts.append(make_part("piping_1", "piping", S.tube(seam2[:-1], 0.006, sections=6, closed=True), cover))
    parts.append(make_part("tag", "tag", S.box((0.05, 0.003, 0.03), center=(rx * 0.7, ry * 0.7 + 0.001, zc * 0.7)),
                           M.solid((0.95, 0.95, 0.92), "fabric", 0.8)))
    return parts


#: Radius of a bean bag's flat bottom panel, as a share of the sack's widest radius: a sack of
#: beads spreads on the floor and stands on that panel (an ellipsoid would touch the floor at
#: one point and roll).
SACK_BOTTOM = 0.7


def _sack_cut(h: float) -> float:
    """Height (m) at which the ellipse of height ``h`` is as wide as the bottom panel."""
    return (1 - np.sqrt(1 - SACK_BOTTOM ** 2)) * h / 2


def _sack_share(z: float, h: float) -> float:
    """Radius of the sack of height ``h`` at height ``z`` (m above its bottom), as a share of
    its widest radius."""
    zc = _sack_cut(h)
    u = 2 * (zc + z * (h - zc) / h) / h - 1  # the ellipse's height, cut and stretched to h
    return float(np.sqrt(max(1 - u * u, 0.05)))


def _sack(rx: float, ry: float, h: float) -> S.Shape:
    """A bean bag's sack: an ellipsoid of semi-axes (rx, ry) with its bottom cut flat (the
    panel of radius ``SACK_BOTTOM``) and stretched back to height ``h``, standing on z = 0."""
    zs = h * (1 - np.cos(np.linspace(0.0, np.pi, 12))) / 2  # finer near the bottom and top
    prof = [(_sack_share(z, h), z) for z in zs[:-1]] + [(0.0, h)]
    return S.transformed(S.lathe(prof, sections=24), np.diag([rx, ry, 1.0, 1.0]))


def _sign_stroke(points, z0: float, scale: float, y: float) -> list[tuple[float, float, float]]:
    return [(x * scale, y, z0 + z * scale) for x, z in points]


_SHAPES = {
    "heart": [(0.0, -0.45), (-0.45, 0.05), (-0.38, 0.35), (-0.15, 0.42), (0.0, 0.2), (0.15, 0.42), (0.38, 0.35), (0.45, 0.05),
              (0.0, -0.45)],
    "bolt": [(0.1, 0.5), (-0.25, 0.0), (0.05, 0.0), (-0.15, -0.5), (0.3, 0.1), (0.0, 0.1), (0.1, 0.5)],
    "star": [(0.0, 0.5), (0.12, 0.15), (0.48, 0.15), (0.19, -0.07), (0.3, -0.45), (0.0, -0.22), (-0.3, -0.45), (-0.19, -0.07),
             (-0.48, 0.15), (-0.12, 0.15), (0.0, 0.5)],
}


@register("neon_sign", parts=("tube", "backplate"), extra_parts=("standoff", "cable", "transformer", "frame", "clip"),
          size_range=(0.3, 1.2), density=900, variants=("word", "shape", "framed"), placement="wall")
def neon_sign(rng: np.random.Generator, variant: str) -> list[Part]:
    glow = M.solid(M.jitter(rng, [(1.0, 0.2, 0.6), (0.2, 0.9, 1.0), (1.0, 0.6, 0.1), (0.6, 0.3, 1.0)][int(rng.integers(4))], 0.03)[:3],
                   "glass", 0.1)
    acrylic = Material((0.9, 0.92, 0.95, 0.3), 0.1, 0.0, "plastic")
    parts = []
    t = 0.006
    yt = t + 0.012  # tubes stand 12 mm in front of the plate
    rt = 0.004
    if variant == "shape":
        s = rng.uniform(0.35, 0.55)
        name = list(_SHAPES)[int(rng.integers(len(_SHAPES)))]
        w, h = s * 1.05, s * 1.05
        path = _sign_stroke(_SHAPES[name], h / 2, s, yt)
        parts.append(make_part("tube_0", "tube", segments(path, rt), glow))
        holds = [path[i] for i in np.linspace(0, len(path) - 1, 4).astype(int)[:3]]
        # two more clips half way between those, so the long tube is held every few bends
        holds += [tuple((np.asarray(path[i]) + np.asarray(path[i + 1])) / 2)
                  for i in np.linspace(0, len(path) - 1, 4).astype(int)[1:3]]
    else:  # a word: letters as zigzag strokes side by side
        n = int(rng.integers(3, 7))
        lw, lh = rng.uniform(0.08, 0.12), rng.uniform(0.14, 0.2)
        w, h = n * lw * 1.25 + 0.08, lh + 0.1
        x0 = -w / 2 + 0.04
        holds = []
        for k in range(n):
            xa = x0 + k * lw * 1.25
            zz = rng.uniform(0.2, 0.8)
            stroke = [(xa, yt, 0.05), (xa, yt, 0.05 + lh), (xa + lw * 0.5, yt, 0.05 + lh * zz), (xa + lw, yt, 0.05 + lh),
                      (xa + lw, yt, 0.05)]
            parts.append(make_part(f"tube_{k}", "tube", segments(stroke, rt), glow))
            holds.append((xa, yt, 0.05 + lh * 0.5))
        # and a second clip on each letter's last stroke: every letter is held at both sides
        holds += [(x0 + k * lw * 1.25 + lw, yt, 0.05 + lh * 0.5) for k in range(n)]
    parts.append(make_part("backplate", "backplate", S.box((w, t, h), center=(0, t / 2, h / 2)), acrylic))
    # the clear clips holding the tubes off the plate
    for k, (x, _, z) in enumerate(holds):
        parts.append(make_part(f"clip_{k}", "clip", S.box((0.008, yt - t, 0.01), center=(x, (t + yt) / 2, z)), acrylic))
    if variant == "framed":
        metal = M.solid((0.1, 0.1, 0.1), "metal", 0.4, 0.6)
        fr = [S.box((w + 0.04, 0.03, 0.02), center=(0, 0.015, -0.0 + 0.01 - 0.02)), S.box((w + 0.04, 0.03, 0.02), center=(0, 0.015, h + 0.01)),
              S.box((0.02, 0.03, h), center=(-w / 2 - 0.01, 0.015, h / 2)), S.box((0.02, 0.03, h), center=(w / 2 + 0.01, 0.015, h / 2))]
        parts.append(make_part("frame", "frame", fr, metal))
    for k, (sx, sz) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        parts.append(make_part(f"standoff_{k}", "standoff", S.cylinder(0.007, 0.012, center=(sx * (w / 2 - 0.02), t + 0.006,
                                                                                            h / 2 + sz * (h / 2 - 0.02)),
                                                                        axis=(0, 1, 0), sections=10),
                               M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9)))
    parts.append(make_part("transformer", "transformer", S.box((0.06, 0.02, 0.04), center=(w / 2 - 0.06, t + 0.01, 0.03)),
                           M.solid((0.1, 0.1, 0.1), "plastic", 0.6)))
    parts.append(make_part("cable", "cable", rod((w / 2 - 0.06, t + 0.01, 0.01), (w / 2 - 0.06, 0.004, 0.004), 0.0025,
                                                    sections=6), M.solid((0.9, 0.9, 0.9), "plastic", 0.6)))
    return parts
