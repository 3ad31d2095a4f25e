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
from ._household import arc, loop_handle, shell


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


@register("cooking_pot", parts=("body", "lid", "handle"), extra_parts=("lid_knob",),
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
    return parts


@register("frying_pan", parts=("body", "handle"), extra_parts=("grip",), size_range=(0.3, 0.62),
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
    if variant == "cast_iron":
        helper = loop_handle(np.array([-(r - 0.004), 0.0, h * 0.85]), (-1, 0, 0), reach=0.03,
                             width=0.05, thick=0.006)
        parts.append(make_part("handle_1", "handle", helper, mat))
        parts[1].name = "handle_0"
    return parts


def _spout(base, *, length: float, rise: float, r0: float, r1: float) -> list[S.Shape]:
    """A tapering spout leaving a body at ``base`` towards +Y and curving upwards."""
    t = np.linspace(0, 1, 5)
    path = np.c_[np.zeros(5), length * t, rise * t ** 1.6] + np.asarray(base, float)
    return [S.frustum(r0 + (r1 - r0) * a, r0 + (r1 - r0) * b, float(np.linalg.norm(q - p)),
                      center=p, axis=q - p, sections=12)
            for a, b, p, q in zip(t[:-1], t[1:], path[:-1], path[1:], strict=True)]


@register("kettle", parts=("body", "spout", "handle"), extra_parts=("lid", "lid_knob", "base"),
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
    return parts


@register("teapot", parts=("body", "spout", "handle", "lid"), extra_parts=("lid_knob",),
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
    return parts
