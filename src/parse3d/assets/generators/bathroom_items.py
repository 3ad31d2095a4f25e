"""Bathroom items: toothbrushes, toilet brushes in their holders and mirror cabinets.

A toothbrush lies on its side with the head (and ``bristles``) at +X. A toilet brush stands in
its ``holder``; the brush's ``handle`` rises through the holder's ``collar`` and its
``brush_head`` sits inside. A mirror cabinet hangs on the wall (back at -Y): its doors carry the
``mirror`` panes and open on hinges, and its glass ``shelf`` boards are internal supports
(``IN mirror_cabinet:shelf``).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Material, Part, make_part
from ..registry import register
from ._casework import door_parts, white
from ._household import shell
from ._kit import mount


def _mirror(rng: np.random.Generator) -> Material:
    return Material(M.jitter(rng, (0.85, 0.88, 0.9), 0.01), 0.02, 1.0, "glass")


@register("toothbrush", parts=("handle", "head", "bristles"),
          extra_parts=("neck", "grip", "button", "thumb_rest", "tongue_cleaner", "indicator", "end_cap"),
          size_range=(0.14, 0.26), density=900, variants=("manual", "electric"), placement="surface")
def toothbrush(rng: np.random.Generator, variant: str) -> list[Part]:
    """Lying flat along X, bristles towards +X pointing sideways (+Y) as it rests on its side."""
    body = M.plastic(rng)
    rubber = Material(M.jitter(rng, (0.3, 0.6, 0.8), 0.1), 0.8, 0.0, "rubber")
    bristle = Material((0.95, 0.95, 0.97, 1.0), 0.9, 0.0, "plastic")
    parts: list[Part] = []
    if variant == "manual":
        lh = rng.uniform(0.11, 0.12)
        handle = S.hull(np.array([(x, y, z) for x, w in ((-lh, 0.016), (-0.02, 0.012))
                                  for y in (-w / 2, w / 2) for z in (0.0, 0.011)]))
        parts.append(make_part("handle", "handle", handle, body))
        grip = S.box((0.04, 0.004, 0.009), center=(-lh * 0.6, 0.006, 0.0055), bevel=0.001)
        parts.append(make_part("grip", "grip", grip, rubber))
        neck = S.hull(np.array([(x, y, z) for x, w in ((-0.0205, 0.012), (0.025, 0.006))
                                for y in (-w / 2, w / 2) for z in (0.0015, 0.0075)]))
        parts.append(make_part("neck", "neck", neck, body))
        # the ribbed thumb rest on the handle's top face, near the neck
        parts.append(make_part("thumb_rest", "thumb_rest", S.box((0.016, 0.008, 0.0015), center=(-0.03, 0, 0.0115)), rubber))
        z0, zh = 0.0015, 0.006
    else:
        lh = rng.uniform(0.15, 0.17)
        parts.append(make_part("handle", "handle", S.cylinder(0.0135, lh, center=(-lh / 2, 0, 0.0135),
                                                              axis=(1, 0, 0), sections=16), body))
        parts.append(make_part("button", "button", S.cylinder(0.005, 0.003, center=(-lh * 0.55, 0, 0.0275),
                                                              sections=12), rubber))
        parts.append(make_part("grip", "grip", S.box((0.05, 0.006, 0.012), center=(-lh * 0.35, -0.012, 0.0135),
                                                     bevel=0.001), rubber))
        neck = S.frustum(0.008, 0.0045, 0.06, center=(-0.002, 0, 0.0135), axis=(1, 0, 0), sections=12)
        parts.append(make_part("neck", "neck", neck, white(rng, "plastic")))
        # the battery light under the button, the mode button, and the charging end cap
        parts.append(make_part("indicator", "indicator", S.box((0.008, 0.003, 0.0015), center=(-lh * 0.72, 0, 0.02705)),
                               M.solid((0.2, 0.8, 0.3), "glass", 0.1)))
        parts.append(make_part("button_1", "button", S.cylinder(0.004, 0.003, center=(-lh * 0.45, 0, 0.0275), sections=12), rubber))
        parts.append(make_part("end_cap", "end_cap", S.cylinder(0.0138, 0.01, center=(-lh + 0.005, 0, 0.0138),
                                                                axis=(1, 0, 0), sections=16), white(rng, "plastic")))
        z0, zh = 0.0095, 0.008
    hl = 0.028
    xh = 0.024 if variant == "manual" else 0.056
    head = S.box((hl, 0.012, zh), center=(xh + hl / 2, 0, z0 + zh / 2), bevel=0.0015)
    parts.append(make_part("head", "head", head, body))
    tuft = S.box((hl - 0.004, 0.011, 0.006), center=(xh + hl / 2, 0, z0 + zh + 0.003 - 0.0005),
                 bevel=0.001)
    parts.append(make_part("bristles", "bristles", tuft, bristle))
    # the ridged tongue cleaner on the back of the head
    parts.append(make_part("tongue_cleaner", "tongue_cleaner", S.box((hl * 0.7, 0.009, 0.0012),
                                                                     center=(xh + hl / 2, 0, z0 + 0.0004)), rubber))
    return parts


@register("toilet_brush", parts=("holder", "handle"), extra_parts=("brush_head", "collar", "knob", "foot", "bracket", "insert",
                                                                   "rim_brush", "tip", "screw"),
          size_range=(0.3, 0.5), density=600, variants=("round", "square", "wall_hung"),
          placement="floor")
def toilet_brush(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.plastic(rng) if rng.random() < 0.6 else M.metal(rng)
    r = rng.uniform(0.045, 0.055)
    hh = rng.uniform(0.12, 0.16)
    parts: list[Part] = []
    if variant == "square":
        holder = [S.box((2 * r, 2 * r, 0.006), center=(0, 0, 0.003))]
        for sx, sy, w, d in ((1, 0, 0.005, 2 * r), (-1, 0, 0.005, 2 * r), (0, 1, 2 * r - 0.01, 0.005),
                             (0, -1, 2 * r - 0.01, 0.005)):
            holder.append(S.box((w, d, hh), center=(sx * (r - 0.0025), sy * (r - 0.0025), hh / 2)))
        parts.append(make_part("holder", "holder", holder, mat))
    else:
        cup = shell([(r * 0.85, 0.0), (r, hh * 0.3), (r, hh)], 0.003, sections=24)
        parts.append(make_part("holder", "holder", cup, mat))
    if variant == "wall_hung":
        plate = S.box((0.05, 0.008, hh * 1.6), center=(0, -r - 0.004 - 0.01, hh * 0.8), bevel=0.002)
        arm = S.box((0.03, 0.014, 0.02), center=(0, -r - 0.005, hh * 0.75), bevel=0.002)
        parts.append(make_part("bracket", "bracket", [plate, arm], mat))
    else:
        foot = S.cylinder(r * 0.9, 0.004, center=(0, 0, 0.002), sections=20) if variant == "round" else \
            S.box((2 * r - 0.006, 2 * r - 0.006, 0.004), center=(0, 0, 0.002))
        parts.append(make_part("foot", "foot", foot.moved((0, 0, -0.004)), M.solid((0.1, 0.1, 0.1), "rubber")))
    # the removable drip insert in the holder's bottom
    parts.append(make_part("insert", "insert", S.cylinder(r * 0.7, 0.012, center=(0, 0, 0.006 + 0.006), sections=16)
                           if variant != "square" else S.box((2 * r - 0.014, 2 * r - 0.014, 0.012), center=(0, 0, 0.012)),
                           M.solid((0.85, 0.85, 0.85), "plastic", 0.6)))
    collar_z = hh - 0.004
    collar = S.cylinder(r * 0.55, 0.012, center=(0, 0, collar_z + 0.006), sections=20)
    parts.append(make_part("collar", "collar", collar, mat))
    head_h = hh * 0.55
    bristle = Material(M.jitter(rng, (0.2, 0.2, 0.22), 0.05), 0.9, 0.0, "plastic")
    head = S.cylinder(r * 0.7, head_h, center=(0, 0, 0.02 + head_h / 2), sections=16)
    parts.append(make_part("brush_head", "brush_head", head, bristle))
    lh = rng.uniform(0.3, 0.36) - hh
    handle = S.cylinder(0.007, lh + hh - 0.02 - head_h, center=(0, 0, 0.02 + head_h + (lh + hh - 0.02 - head_h) / 2 - 0.001),
                        sections=12)
    parts.append(make_part("handle", "handle", handle, mat))
    parts.append(make_part("knob", "knob", S.ellipsoid((0.012, 0.012, 0.01), center=(0, 0, lh + hh),
                                                       subdivisions=1), mat))
    # the under-rim tuft over the head, the cap on the head's end, and the plate's two screws
    parts.append(make_part("rim_brush", "rim_brush", S.frustum(r * 0.45, r * 0.2, 0.02, center=(0, 0, 0.02 + head_h), sections=12), bristle))
    parts.append(make_part("tip", "tip", S.cylinder(r * 0.25, 0.006, center=(0, 0, 0.02 - 0.003), sections=10), mat))
    if variant == "wall_hung":
        for k, sz in enumerate((-1, 1)):
            parts.append(make_part(f"screw_{k}", "screw", S.cylinder(0.004, 0.002, center=(0, -r - 0.004 - 0.01 + 0.005, hh * 0.8 + sz * hh * 0.6),
                                                                     axis=(0, 1, 0), sections=8), M.solid((0.8, 0.8, 0.8), "metal", 0.3, 0.9)))
    return parts


@register("mirror_cabinet", parts=("body", "door", "mirror", "shelf"),
          extra_parts=("hinge", "light", "handle", "glass", "shelf_pin", "bumper", "screw", "switch", "socket"),
          size_range=(0.35, 1.25), density=600, variants=("single", "double", "lit"), placement="wall")
def mirror_cabinet(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    """A shallow wall cabinet whose doors are mirrors; glass shelves inside; ``lit`` adds a
    light bar over the doors."""
    n = 1 if variant == "single" else 2
    w = rng.uniform(0.4, 0.55) if n == 1 else rng.uniform(0.6, 1.0)
    h, d = rng.uniform(0.5, 0.75), rng.uniform(0.12, 0.16)
    t = 0.015
    mat = white(rng, "wood") if rng.random() < 0.6 else M.wood(rng)
    db = d - 0.02
    hb = h - (0.06 if variant == "lit" else 0.0)
    body = [S.box((t, db, hb), center=(-w / 2 + t / 2, -0.01, hb / 2)),
            S.box((t, db, hb), center=(w / 2 - t / 2, -0.01, hb / 2)),
            S.box((w - 2 * t, db, t), center=(0, -0.01, t / 2)),
            S.box((w - 2 * t, db, t), center=(0, -0.01, hb - t / 2)),
            S.box((w - 2 * t, 0.006, hb - 2 * t), center=(0, -d / 2 + 0.003, hb / 2))]
    parts: list[Part | Joint] = [make_part("body", "body", body, mat)]
    ns = 2 if hb > 0.55 else 1
    for k in range(ns):
        zs = t + (hb - 2 * t) * (k + 1) / (ns + 1)
        parts.append(make_part(f"shelf_{k}", "shelf",
                               S.box((w - 2 * t, db - 0.03, 0.006), center=(0, -0.02, zs)), M.glass(rng)))
        # the four pins in the sides' drilled rows that the glass shelf rests on
        for j, (sx, fy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"shelf_pin_{4 * k + j}", "shelf_pin",
                                   S.cylinder(0.0025, 0.012, center=(sx * (w / 2 - t - 0.005), -0.02 + fy * (db - 0.03) * 0.35, zs - 0.0055),
                                              axis=(1, 0, 0), sections=8), M.solid((0.75, 0.75, 0.77), "metal", 0.3, 0.9)))
    # the four screws through the back into the wall, their heads flush with its inner face
    steel = M.solid((0.75, 0.75, 0.77), "metal", 0.3, 0.9)
    parts += [make_part(f"screw_{k}", "screw", S.cylinder(0.005, 0.002, center=(sx * (w / 2 - t - 0.03), -d / 2 + 0.005, zc),
                                                          axis=(0, 1, 0), sections=8), steel)
              for k, (sx, zc) in enumerate((sx, zc) for sx in (-1, 1) for zc in (t + 0.03, hb - t - 0.03))]
    yf = d / 2 - 0.02
    hmat = M.metal(rng)
    dw = w / n
    for i in range(n):
        x0, x1 = -w / 2 + i * dw + 0.002, -w / 2 + (i + 1) * dw - 0.002
        name = "door" if n == 1 else f"door_{i}"
        door = door_parts(name, x0=x0, x1=x1, z0=0.002, z1=hb - 0.002, y_back=yf, thick=0.016,
                          mat=mat, handle_mat=hmat, hinge_left=i == 0, style="flat", handle_len=0.06)
        parts += door
        pane = S.box((x1 - x0 - 0.01, 0.003, hb - 0.014), center=((x0 + x1) / 2, yf + 0.016 + 0.0015, hb / 2))
        parts.append(make_part(f"{name}_mirror", "mirror", pane, _mirror(rng)))
        parts.append(mount(name, f"{name}_mirror"))
        # the clear bumpers on the carcass front that the door closes on, near its free edge
        xb = x1 - 0.03 if i == 0 else x0 + 0.03
        for j, zb in enumerate((0.004, hb - 0.004)):
            parts.append(make_part(f"{name}_bumper_{j}", "bumper",
                                   S.cylinder(0.005, 0.002, center=(xb, yf - 0.001, zb + (0.006 if j == 0 else -0.006)),
                                              axis=(0, 1, 0), sections=8), M.solid((0.9, 0.92, 0.92), "plastic", 0.2)))
    if variant == "lit":
        parts.append(make_part("light_housing", "body", S.box((w, d - 0.02, h - hb), center=(0, -0.01, (h + hb) / 2)), mat))
        parts.append(make_part("light", "light", S.box((w * 0.8, 0.01, 0.025), center=(0, d / 2 - 0.02 + 0.005, (h + hb) / 2)),
                               Material((1.0, 0.97, 0.9, 1.0), 0.2, 0.0, "glass")))
        # the light's switch in the housing's right end and the shaver socket in its left end,
        # flush with them
        parts.append(make_part("switch", "switch", S.box((0.002, 0.012, 0.02), center=(w / 2 - 0.001, -0.01, (h + hb) / 2)), white(rng, "plastic")))
        parts.append(make_part("socket", "socket", S.box((0.002, 0.03, 0.04), center=(-w / 2 + 0.001, -0.01, (h + hb) / 2)), white(rng, "plastic")))
    return parts
