"""Kitchenware: cooking pots, frying pans, kettles and teapots.

Pots are open vessels whose lid rests on the rim (a lip drops inside the wall to seat it), so
the pot's inner floor is a covered internal surface. Frying pans put their long handle along
+X (the asset's right). Kettles and teapots point their spout at +Y (front); a teapot's handle
is at -Y, a kettle's handle arches over the top or sits at the back.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._detail_b import studs
from ._household import arc, loop_handle, ring, shell


def _cookware_metal(rng: np.random.Generator, variant: str) -> Material:
    if variant in ("dutch_oven", "cast_iron"):
        return Material(M.jitter(rng, (0.12, 0.12, 0.13), 0.02), 0.6, 0.6, "metal")
    return M.metal(rng)


def _lid(rng, r_rim: float, r_in: float, z: float, mat: Material, *, dome: float) -> S.Shape:
    """A lid resting on a rim at height ``z``: a lip inside the wall, a flange, a dome."""
    lip = 0.008
    return S.lathe([(r_in - 0.002, z - lip), (r_in - 0.002, z), (r_rim + 0.003, z),
                    (r_rim + 0.003, z + 0.004), (r_rim * 0.8, z + dome * 0.7), (r_rim * 0.3, z + dome)],
                   sections=28)


def _knob(z: float, *, r: float = 0.016, h: float = 0.022) -> S.Shape:
    return S.lathe([(r * 0.45, z - 0.001), (r * 0.4, z + h * 0.45), (r, z + h * 0.7), (r * 0.8, z + h)],
                   sections=16)


@register("cooking_pot", parts=("body", "lid", "handle"), extra_parts=("lid_knob", "rivet", "base", "vent", "rim", "screw"),
          size_range=(0.2, 0.45), density=2500,
          variants=("stock", "casserole", "dutch_oven"), placement="surface")
def cooking_pot(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = _cookware_metal(rng, variant)
    r = rng.uniform(0.09, 0.14)
    h = {"stock": r * rng.uniform(1.3, 1.8), "casserole": r * rng.uniform(0.55, 0.75),
         "dutch_oven": r * rng.uniform(0.7, 0.9)}[variant]
    t = 0.006 if variant == "dutch_oven" else 0.003
    body = shell([(r * 0.97, 0.0), (r * 0.99, 0.004), (r, h)], t, bottom=t * 1.5, sections=24)
    parts = [make_part("body", "body", body, mat)]
    dome = r * (0.25 if variant == "dutch_oven" else 0.18)
    parts.append(make_part("lid", "lid", _lid(rng, r, r - t, h, mat, dome=dome), mat))
    knob_mat = M.plastic(rng) if variant != "dutch_oven" else mat
    parts.append(make_part("lid_knob", "lid_knob", _knob(h + dome), knob_mat))
    zh = h * (0.8 if variant == "stock" else 0.72)
    for i, sx in enumerate((1, -1)):
        root = np.array([sx * (r - 0.003), 0.0, zh])
        if variant == "casserole":
            shape = S.box((0.03, 0.07, 0.012), center=(sx * (r + 0.012), 0, zh), bevel=0.004)
        else:
            shape = loop_handle(root, (sx, 0, 0), reach=rng.uniform(0.03, 0.045),
                                width=rng.uniform(0.06, 0.09), thick=0.006 if t > 0.004 else 0.005)
        parts.append(make_part(f"handle_{i}", "handle", shape, mat))
        # two rivets hold each handle to the wall, their heads inside the pot
        parts += studs("rivet", "rivet", [(sx * (r - t - 0.001), y, zh) for y in (-0.02, 0.02)], r=0.004, h=0.002, mat=mat,
                       axis=(1, 0, 0), sections=8, start=2 * i)
    # the bonded base disc under a steel pot and the steam vent in the lid
    if variant != "dutch_oven":
        parts.append(make_part("base", "base", S.cylinder(r * 0.85, 0.003, center=(0, 0, 0.0015), sections=24),
                               M.solid((0.6, 0.6, 0.62), "metal", 0.3, 0.9)))
    parts.append(make_part("vent", "vent", S.cylinder(0.004, 0.003, center=(r * 0.5, 0, h + dome * 0.55), sections=8),
                           M.solid((0.05, 0.05, 0.05), "metal", 0.8)))
    # the rolled rim round the wall's top, under the lid's flange, and the screw under the lid
    # holding its knob on
    parts.append(make_part("rim", "rim", ring([(r - t, h - 0.006), (r + 0.002, h - 0.003), (r - t, h - 0.0005)], sections=24), mat))
    parts.append(make_part("screw", "screw", S.cylinder(0.004, 0.003, center=(0, 0, h + dome - 0.0015 - 0.002), sections=8),
                           M.solid((0.6, 0.6, 0.62), "metal", 0.3, 0.9)))
    return parts


@register("frying_pan", parts=("body", "handle"), extra_parts=("grip", "rivet", "hang_hole", "base", "spout", "rim", "flame_guard"),
          size_range=(0.3, 0.62),
          density=2500, variants=("nonstick", "cast_iron", "wok"), placement="surface")
def frying_pan(rng: np.random.Generator, variant: str) -> list[Part]:
    """The handle points along +X (the pan's right), rising slightly from the rim."""
    mat = _cookware_metal(rng, variant)
    r = rng.uniform(0.1, 0.15)
    if variant == "wok":
        h = r * rng.uniform(0.35, 0.45)
        prof = [(r * 0.45, 0.0), (r * 0.75, h * 0.35), (r, h)]
    else:
        h = rng.uniform(0.035, 0.055)
        prof = [(r * 0.8, 0.0), (r * 0.84, h * 0.25), (r, h)]
    t = 0.005 if variant == "cast_iron" else 0.003
    body = shell(prof, t, bottom=0.005, sections=24)
    parts = [make_part("body", "body", body, mat)]
    length = rng.uniform(0.16, 0.22) if variant != "cast_iron" else rng.uniform(0.12, 0.15)
    rise = np.deg2rad(rng.uniform(10, 20))
    z0 = h * 0.8
    start = np.array([r - 0.004, 0.0, z0])
    d = np.array([np.cos(rise), 0.0, np.sin(rise)])
    path = np.array([start + d * s for s in np.linspace(0, length, 4)])
    thick = 0.009 if variant != "cast_iron" else 0.011
    parts.append(make_part("handle", "handle", S.tube(path[:2], thick, sections=10), mat))
    grip_mat = M.plastic(rng) if variant != "cast_iron" else mat
    grip = S.tube(path[1:], thick * 1.35, sections=10)
    parts.append(make_part("grip", "grip", grip, grip_mat))
    # the rolled rim round the pan's lip
    parts.append(make_part("rim", "rim", ring([(r - t, h - 0.005), (r + 0.0015, h - 0.0025), (r - t, h - 0.0005)], sections=24), mat))
    if variant == "cast_iron":
        helper = loop_handle(np.array([-(r - 0.004), 0.0, h * 0.85]), (-1, 0, 0), reach=0.03,
                             width=0.05, thick=0.006)
        parts.append(make_part("handle_1", "handle", helper, mat))
        parts[1].name = "handle_0"
        # the two pouring lips cast into the rim
        parts += [make_part(f"spout_{k}", "spout", S.box((0.03, 0.012, 0.006), center=(0, sy * (r + 0.003), h - 0.003)), mat)
                  for k, sy in enumerate((-1, 1))]
        # the hole cast through the handle's end to hang it by
        parts.append(make_part("hang_hole", "hang_hole", S.cylinder(0.006, thick * 2 * 1.35 * 0.9, center=path[-1] - d * 0.02,
                                                                    axis=(0, 0, 1), sections=10),
                               M.solid((0.05, 0.05, 0.05), "metal", 0.8)))
    else:  # riveted handle, a hole in the grip's end to hang it by, the induction base disc
        parts += studs("rivet", "rivet", [(r - t - 0.001, 0, z0 + dz) for dz in (-0.006, 0.006)], r=0.0045, h=0.002, mat=mat,
                       axis=(1, 0, 0), sections=8)
        parts.append(make_part("hang_hole", "hang_hole", S.cylinder(0.005, thick * 2.7 + 0.0004, center=path[-1] - d * 0.02,
                                                                    axis=(0, 0, 1), sections=10),
                               M.solid((0.05, 0.05, 0.05), "metal", 0.8)))
        parts.append(make_part("base", "base", S.cylinder(prof[0][0] * 0.92, 0.002, center=(0, 0, 0.001), sections=24),
                               M.solid((0.6, 0.6, 0.62), "metal", 0.3, 0.9)))
        # the steel collar shielding the grip where it meets the handle's stem
        parts.append(make_part("flame_guard", "flame_guard", S.cylinder(thick * 1.5, 0.008, center=tuple(path[1] + d * 0.004),
                                                                        axis=tuple(d), sections=10), mat))
        if variant == "wok":  # the loop helper handle opposite the long one
            helper = loop_handle(np.array([-(r - 0.004), 0.0, h * 0.85]), (-1, 0, 0), reach=0.03, width=0.05, thick=0.006)
            parts.append(make_part("handle_1", "handle", helper, grip_mat))
    return parts


def _spout(base, *, length: float, rise: float, r0: float, r1: float) -> list[S.Shape]:
    """A tapering spout leaving a body at ``base`` towards +Y and curving upwards."""
    t = np.linspace(0, 1, 5)
    path = np.c_[np.zeros(5), length * t, rise * t ** 1.6] + np.asarray(base, float)
    return [S.frustum(r0 + (r1 - r0) * a, r0 + (r1 - r0) * b, float(np.linalg.norm(q - p)),
                      center=p, axis=q - p, sections=12)
            for a, b, p, q in zip(t[:-1], t[1:], path[:-1], path[1:], strict=True)]


@register("kettle", parts=("body", "spout", "handle"), extra_parts=("lid", "lid_knob", "base", "whistle", "pivot", "switch",
                                                                  "window", "lid_button", "cord", "trigger", "indicator", "filter"),
          size_range=(0.16, 0.34), density=1500, variants=("stovetop", "electric"),
          placement="surface")
def kettle(rng: np.random.Generator, variant: str) -> list[Part]:
    parts = []
    if variant == "stovetop":
        mat = M.metal(rng)
        r = rng.uniform(0.085, 0.11)
        h = rng.uniform(0.13, 0.17)
        prof = [(r * 0.92, 0.0), (r, h * 0.12), (r, h * 0.45), (r * 0.6, h * 0.88), (r * 0.38, h)]
        body = S.lathe(prof, sections=28)
        parts.append(make_part("body", "body", body, mat))
        lid = S.lathe([(r * 0.38, h), (r * 0.36, h + 0.008), (r * 0.15, h + 0.018)], sections=20)
        parts.append(make_part("lid", "lid", lid, mat))
        parts.append(make_part("lid_knob", "lid_knob", _knob(h + 0.018, r=0.012, h=0.016),
                               M.plastic(rng)))
        # over-the-top handle: an arch across the body from front to back (the y-z plane)
        span = r * 0.62
        top = h + rng.uniform(0.08, 0.11)
        zc = h * 0.72
        path = arc((0, 0, zc), span, 0.0, np.pi, n=9, u=(0, 1, 0), v=(0, 0, 1),
                   squash=(top - zc) / span)
        handle = S.tube(path, 0.008, sections=10)
        spout = _spout((0, r * 0.75, h * 0.35), length=r * 0.75, rise=h * 0.45, r0=0.014, r1=0.008)
    else:
        mat = M.plastic(rng) if rng.random() < 0.6 else M.metal(rng)
        r = rng.uniform(0.07, 0.085)
        h = rng.uniform(0.19, 0.24)
        base = S.lathe([(r * 1.12, 0.0), (r * 1.1, 0.02)], sections=28)
        parts.append(make_part("base", "base", base, M.plastic(rng)))
        body = S.lathe([(r, 0.02), (r * 0.98, 0.02 + h * 0.6), (r * 0.86, 0.02 + h)], sections=28)
        parts.append(make_part("body", "body", body, mat))
        zt = 0.02 + h
        parts.append(make_part("lid", "lid", S.lathe([(r * 0.8, zt), (r * 0.72, zt + 0.01)],
                                                     sections=24), mat))
        # a tall handle at the back (-Y) running from the top down the body
        handle = loop_handle((0, -(r * 0.92), 0.02 + h * 0.55), (0, -1, 0), reach=0.04,
                             width=h * 0.7, thick=0.011, z_up=True)
        spout = _spout((0, r * 0.8, zt - 0.03), length=0.035, rise=0.02, r0=0.016, r1=0.012)
    parts.append(make_part("handle", "handle", handle, M.plastic(rng) if variant == "stovetop" else mat))
    parts.append(make_part("spout", "spout", spout, mat))
    dark = M.solid((0.08, 0.08, 0.08), "plastic", 0.5)
    if variant == "stovetop":
        # the whistle cap on the spout's tip and the two pivots the handle swings on
        tip = np.array([0, r * 0.75 + r * 0.75, h * 0.35 + h * 0.45])
        parts.append(make_part("whistle", "whistle", S.cylinder(0.011, 0.02, center=tuple(tip + (0, -0.008, 0.006)), axis=(0, 0, 1),
                                                                sections=10), dark))
        parts += studs("pivot", "pivot", [(0, sy * span, zc) for sy in (-1, 1)], r=0.01, h=0.012, mat=mat, axis=(0, 1, 0))
        # the thumb trigger on the handle that lifts the whistle cap, and the encapsulated base
        # disc under the body
        parts.append(make_part("trigger", "trigger", S.box((0.012, 0.03, 0.006), center=(0, span * 0.55, top - 0.004)), dark))
        parts.append(make_part("base", "base", S.cylinder(r * 0.8, 0.002, center=(0, 0, 0.001), sections=24),
                               M.solid((0.6, 0.6, 0.62), "metal", 0.3, 0.9)))
    else:
        # the on switch at the handle's foot, the water gauge window, the lid's release button and
        # the cord leaving the base
        parts.append(make_part("switch", "switch", S.box((0.02, 0.025, 0.012), center=(0, -(r * 0.92) - 0.04, 0.02 + h * 0.2)), dark))
        parts.append(make_part("window", "window", S.box((0.02, 0.004, h * 0.5), center=(r * 0.7, r * 0.7, 0.02 + h * 0.4),
                                                         R=np.array([[np.cos(np.pi / 4), -np.sin(np.pi / 4), 0],
                                                                     [np.sin(np.pi / 4), np.cos(np.pi / 4), 0], [0, 0, 1]])),
                               M.glass(rng)))
        parts.append(make_part("lid_button", "lid_button", S.box((0.02, 0.02, 0.008), center=(0, -(r * 0.92) - 0.02, zt + 0.004)),
                               dark))
        # the power light beside the switch and the limescale filter in the spout's mouth
        parts.append(make_part("indicator", "indicator", S.cylinder(0.003, 0.002, center=(0.014, -(r * 0.92) - 0.04, 0.02 + h * 0.2 + 0.005),
                                                                    sections=8), M.solid((0.2, 0.5, 0.95), "plastic", 0.2)))
        parts.append(make_part("filter", "filter", S.cylinder(0.012, 0.002, center=(0, r * 0.8 + 0.02, zt - 0.03 + 0.01), axis=(0, 1, 0),
                                                              sections=10), M.solid((0.85, 0.85, 0.85), "plastic", 0.5)))
        parts.append(make_part("cord", "cord", S.tube([(-r * 1.1, 0, 0.008), (-r * 1.1 - 0.04, 0.02, 0.005), (-r * 1.1 - 0.06, 0.06, 0.005)],
                                                      0.003, sections=6), dark))
    return parts


@register("teapot", parts=("body", "spout", "handle", "lid"), extra_parts=("lid_knob", "foot_ring", "vent", "gallery", "handle_join"),
          size_range=(0.14, 0.34), density=1800, variants=("round", "tall", "squat"),
          placement="surface")
def teapot(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.ceramic(rng) if rng.random() < 0.8 else M.metal(rng)
    r = rng.uniform(0.065, 0.085)
    h = r * {"round": rng.uniform(1.1, 1.3), "tall": rng.uniform(1.5, 1.8),
             "squat": rng.uniform(0.8, 0.95)}[variant]
    prof = [(r * 0.62, 0.0), (r * 0.66, 0.006), (r * 0.93, h * 0.25), (r, h * 0.5),
            (r * 0.85, h * 0.8), (r * 0.55, h)]
    parts = [make_part("body", "body", S.lathe(prof, sections=28), mat)]
    rl = r * 0.5
    lid = S.lathe([(rl, h), (rl * 0.95, h + 0.008), (rl * 0.45, h + r * 0.2)], sections=20)
    parts.append(make_part("lid", "lid", lid, mat))
    parts.append(make_part("lid_knob", "lid_knob", _knob(h + r * 0.2, r=0.01, h=0.014), mat))
    spout = _spout((0, r * 0.75, h * 0.25), length=r * rng.uniform(0.75, 0.95), rise=h * 0.65,
                   r0=r * 0.2, r1=0.007)
    parts.append(make_part("spout", "spout", spout, mat))
    # the handle is a vertical loop at the back (-Y)
    handle = loop_handle((0, -(r * 0.9), h * 0.52), (0, -1, 0), reach=r * rng.uniform(0.45, 0.6),
                         width=h * 0.5, thick=0.007, z_up=True)
    parts.append(make_part("handle", "handle", handle, mat))
    # the unglazed foot ring it stands on and the steam hole in the lid
    parts.append(make_part("foot_ring", "foot_ring", ring([(r * 0.5, 0.0), (r * 0.63, 0.0), (r * 0.56, 0.004)],
                                                          sections=24), mat))
    parts.append(make_part("vent", "vent", S.cylinder(0.0025, 0.003, center=(rl * 0.7, 0, h + 0.008 + 0.0), sections=8),
                           M.solid((0.05, 0.05, 0.05), "plastic", 0.8)))
    # the gallery the lid sits in round the opening, and the pads where the handle is luted on
    parts.append(make_part("gallery", "gallery", ring([(rl * 1.02, h - 0.006), (rl * 1.14, h - 0.004), (rl * 1.14, h), (rl * 1.02, h)],
                                                      sections=20), mat))
    hb = handle.mesh.bounds
    parts += [make_part(f"handle_join_{k}", "handle_join", S.cylinder(0.0105, 0.004, center=(0, -(r * 0.9) - 0.001, z), axis=(0, 1, 0),
                                                                      sections=10), mat)
              for k, z in enumerate((float(hb[1, 2]) - 0.007, float(hb[0, 2]) + 0.007))]
    return parts
