"""Vegetables: tomatoes, onions, carrots and potatoes.

Closed solids (the flesh is not modelled) with the parts a cook names: a tomato's green
``sepal``s and ``stem``, an onion's dry ``neck`` and its ``root_plate`` with roots, a carrot's
``crown`` and ``leaf`` tops, a potato's ``eye``s. Carrots lie along X, their tip at +X.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._kit import rot


def _turned(shape: S.Shape, R: np.ndarray, t=(0.0, 0.0, 0.0)) -> S.Shape:
    T = np.eye(4)
    T[:3, :3] = R
    T[:3, 3] = t
    return shape.apply(T)


@register("tomato", parts=("body",), extra_parts=("stem", "sepal"), size_range=(0.02, 0.12),
          density=950, variants=("round", "beefsteak", "cherry", "plum"), placement="surface")
def tomato(rng: np.random.Generator, variant: str) -> list[Part]:
    r, squash = {"round": (rng.uniform(0.03, 0.038), rng.uniform(0.8, 0.9)),
                 "beefsteak": (rng.uniform(0.04, 0.05), rng.uniform(0.62, 0.72)),
                 "cherry": (rng.uniform(0.011, 0.014), rng.uniform(0.9, 1.0)),
                 "plum": (rng.uniform(0.022, 0.026), rng.uniform(1.4, 1.6))}[variant]
    h = 2 * r * squash
    prof = [(r * 0.35, 0.0), (r * 0.8, h * 0.1), (r, h * 0.45), (r * 0.92, h * 0.75),
            (r * 0.6, h * 0.94), (r * 0.2, h)]
    red = [(0.82, 0.12, 0.08), (0.88, 0.3, 0.08), (0.75, 0.08, 0.1)][int(rng.integers(3))]
    parts = [make_part("body", "body", S.lathe(prof, sections=20), M.food(rng, red))]
    green = M.plant(rng)
    ls = max(r * 0.55, 0.007)
    for k in range(5):
        a = 2 * np.pi * k / 5 + rng.uniform(-0.2, 0.2)
        leaf = S.ellipsoid((ls / 2, ls * 0.14, 0.0012), center=(ls / 2, 0, 0), subdivisions=1)
        # each sepal lies on the shoulder, pointing outwards and slightly down
        leaf = _turned(leaf, rot((0, 0, 1), a) @ rot((0, 1, 0), 0.35), (0, 0, h - 0.0012))
        parts.append(make_part(f"sepal_{k}", "sepal", leaf, green))
    sh = min(0.012, r * 0.4)
    stem = S.cylinder(max(0.0012, r * 0.05), sh, center=(0, 0, h + sh / 2 - 0.001), sections=8)
    parts.append(make_part("stem", "stem", stem, green))
    return parts


@register("onion", parts=("body",), extra_parts=("neck", "root_plate", "root"),
          size_range=(0.022, 0.13), density=900, variants=("yellow", "red", "white", "shallot"),
          placement="surface")
def onion(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.012, 0.016) if variant == "shallot" else rng.uniform(0.032, 0.043)
    h = r * (rng.uniform(1.6, 1.9) if variant == "shallot" else rng.uniform(1.55, 1.75))
    skin = {"yellow": (0.72, 0.5, 0.22), "red": (0.48, 0.15, 0.28), "white": (0.92, 0.9, 0.84),
            "shallot": (0.62, 0.38, 0.3)}[variant]
    mat = M.food(rng, skin)
    z0 = r * 0.08  # the root plate lifts the bulb a little
    prof = [(r * 0.3, z0), (r * 0.8, z0 + h * 0.1), (r, z0 + h * 0.38), (r * 0.85, z0 + h * 0.62),
            (r * 0.35, z0 + h * 0.86), (r * 0.12, z0 + h)]
    parts = [make_part("body", "body", S.lathe(prof, sections=20), mat)]
    dry = M.food(rng, (0.6, 0.45, 0.25))
    nl = r * rng.uniform(0.25, 0.45)
    neck = S.frustum(r * 0.12, r * 0.05, nl, center=(0, 0, z0 + h - 0.001), sections=8)
    parts.append(make_part("neck", "neck", neck, mat))
    plate = S.cylinder(r * 0.3, z0 + 0.001, center=(0, 0, (z0 + 0.001) / 2), sections=12)
    parts.append(make_part("root_plate", "root_plate", plate, dry))
    nr = 10 if variant != "shallot" else 6  # the dried root tuft under the plate
    for k in range(nr):
        a = 2 * np.pi * k / nr + rng.uniform(-0.3, 0.3)
        d = np.array([np.cos(a), np.sin(a), 0.0])
        path = [d * r * 0.15 + (0, 0, z0 * 0.5), d * r * 0.45 + (0, 0, z0 * 0.5)]
        parts.append(make_part(f"root_{k}", "root", S.tube(path, min(0.0008, z0 * 0.4), sections=6),
                               dry))
    return parts


@register("carrot", parts=("body",), extra_parts=("crown", "leaf", "rootlet"), size_range=(0.05, 0.5),
          density=1000, variants=("trimmed", "topped", "baby"), placement="surface")
def carrot(rng: np.random.Generator, variant: str) -> list[Part]:
    """Lying along X: the crown at -X, the tapering root towards +X."""
    L = rng.uniform(0.05, 0.07) if variant == "baby" else rng.uniform(0.15, 0.22)
    r = L * rng.uniform(0.11, 0.14)
    orange = M.food(rng, (0.93, 0.45, 0.08))
    prof = [(r * 0.85, 0.0), (r, L * 0.06), (r * 0.75, L * 0.5), (r * 0.35, L * 0.85),
            (r * 0.06, L)]
    # revolve about Z, then lay the axis along +X with the root resting on z = 0
    body = _turned(S.lathe(prof, sections=14), rot((0, 1, 0), np.pi / 2), (0, 0, r))
    parts = [make_part("body", "body", body, orange)]
    green = M.plant(rng)
    crown = S.cylinder(r * 0.7, r * 0.25, center=(-r * 0.1, 0, r), axis=(1, 0, 0), sections=12)
    parts.append(make_part("crown", "crown", crown, green))
    if variant == "topped":
        n = int(rng.integers(3, 5))
        ll = L * rng.uniform(0.7, 1.0)
        for k in range(n):
            spread = (k - (n - 1) / 2) * 0.22
            d = np.array([-np.cos(spread), np.sin(spread), 0.0])
            start = np.array([-r * 0.2, 0, r])
            path = [start, start + d * ll * 0.5 + (0, 0, r * 0.2), start + d * ll + (0, 0, -r * 0.6)]
            parts.append(make_part(f"leaf_{k}", "leaf", S.tube(path, 0.0025, sections=6), green))
    # the fine side roots growing out of the root's lower half, alternately left and right
    for k, u in enumerate((0.26, 0.35, 0.45, 0.55, 0.64, 0.72)):
        x = L * u
        rr = float(np.interp(x, [p_[1] for p_ in prof], [p_[0] for p_ in prof]))
        sy = 1 if k % 2 == 0 else -1
        path = [(x, sy * rr * 0.7, r), (x + L * 0.04, sy * (rr + L * 0.05), r * 0.8)]
        parts.append(make_part(f"rootlet_{k}", "rootlet", S.tube(path, 0.0006, sections=5), orange))
    return parts


@register("potato", parts=("body",), extra_parts=("eye", "stem_end"), size_range=(0.04, 0.15), density=1080,
          variants=("russet", "round", "fingerling"), placement="surface")
def potato(rng: np.random.Generator, variant: str) -> list[Part]:
    """An egg-shaped tuber lying along X with a few shallow eyes."""
    rx, ry, rz = {"russet": (rng.uniform(0.05, 0.065), rng.uniform(0.03, 0.036), rng.uniform(0.025, 0.03)),
                  "round": (rng.uniform(0.034, 0.04), rng.uniform(0.03, 0.035), rng.uniform(0.026, 0.031)),
                  "fingerling": (rng.uniform(0.035, 0.045), rng.uniform(0.013, 0.016),
                                 rng.uniform(0.012, 0.015))}[variant]
    skin = [(0.62, 0.45, 0.28), (0.78, 0.65, 0.4), (0.55, 0.22, 0.2)][int(rng.integers(3))]
    mat = M.food(rng, skin)
    body = S.ellipsoid((rx, ry, rz), center=(0, 0, rz), subdivisions=2)
    parts = [make_part("body", "body", body, mat)]
    eye_mat = M.food(rng, (0.35, 0.25, 0.15))
    # a tuber has six to a dozen eyes, a small fingerling four or five
    n = int(rng.integers(4, 6)) if variant == "fingerling" else int(rng.integers(6, 9))
    for k in range(n):
        # eyes on the upper half, spread along the tuber
        u = -0.75 + 1.5 * (k + rng.uniform(0.2, 0.8)) / n
        a = rng.uniform(0.35, 1.1) * (1 if k % 2 else -1)
        dy, dz = np.sin(a), np.cos(a)
        s = np.sqrt(max(1e-6, 1 - u * u))
        p = np.array([u * rx, s * dy * ry, rz + s * dz * rz])
        eye = S.ellipsoid((0.003, 0.0025, 0.0012), center=p * 1.0 - np.array([0, 0, 0.0004]),
                          subdivisions=1)
        parts.append(make_part(f"eye_{k}", "eye", eye, eye_mat))
    # the scar where the tuber hung on its stolon, at the end opposite the eyes' crowd
    parts.append(make_part("stem_end", "stem_end", S.ellipsoid((0.0012, 0.004, 0.004), center=(-rx + 0.0008, 0, rz), subdivisions=1),
                           eye_mat))
    return parts
