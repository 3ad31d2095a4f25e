"""Tea ceremony things: whisks, scoops, sweets, braziers and incense burners.

A tea whisk stands on its bamboo ``handle`` with its ``tine``s curling up and out. A tea scoop
lies along X, its curved ``tip`` at +X. A wagashi sweet sits on a plate with its ``garnish``
on top and a ``pick`` stuck in it. A brazier's ``trivet`` on its rim holds the kettle
(``ON brazier:trivet``). An incense burner stands on three ``foot``s (tripod) under a domed ``lid``.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from ...geometry.frames import rot_z
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring, shell


def _bamboo(rng: np.random.Generator) -> Material:
    return Material(M.jitter(rng, (0.85, 0.75, 0.5), 0.04), 0.6, 0.0, "wood")


@register("tea_whisk", parts=("handle", "tine"), extra_parts=("binding", "core"), size_range=(0.08, 0.14),
          density=500, variants=("standard", "wide", "dark_bamboo"), placement="surface")
def tea_whisk(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = _bamboo(rng) if variant != "dark_bamboo" else Material(M.jitter(rng, (0.3, 0.22, 0.15), 0.03), 0.6,
                                                                   0.0, "wood")
    hh = rng.uniform(0.045, 0.055)
    r = 0.0075
    parts = [make_part("handle", "handle", S.cylinder(r, hh, center=(0, 0, hh / 2), sections=14), mat)]
    parts.append(make_part("binding", "binding", ring([(r - 0.0005, hh - 0.004), (r + 0.0012, hh - 0.004),
                                                       (r + 0.0012, hh), (r - 0.0005, hh)], sections=14),
                           Material((0.1, 0.1, 0.1, 1.0), 0.8, 0.0, "fabric")))
    L = rng.uniform(0.05, 0.06)
    spread = 0.026 if variant != "wide" else 0.032
    parts.append(make_part("core", "core", S.frustum(0.004, 0.006, L * 0.7, center=(0, 0, hh - 0.001), sections=10), mat))
    n = 16  # the outer ring of tines (a real whisk splits its bamboo into 16 to 120)
    for k in range(n):
        a = 2 * np.pi * k / n
        d = np.array([np.cos(a), np.sin(a), 0.0])
        path = [d * r * 0.8 + (0, 0, hh - 0.002), d * spread * 0.8 + (0, 0, hh + L * 0.6),
                d * spread + (0, 0, hh + L * 0.85), d * spread * 0.8 + (0, 0, hh + L)]
        parts.append(make_part(f"tine_{k}", "tine", S.tube(path, 0.0012, sections=5), mat))
    return parts


@register("tea_scoop", parts=("shaft", "tip"), extra_parts=("node",), size_range=(0.14, 0.21), density=600,
          variants=("natural", "lacquered"), placement="surface")
def tea_scoop(rng: np.random.Generator, variant: str) -> list[Part]:
    """A thin bamboo strip lying along X; the node near the middle, the tip curling up at +X."""
    mat = _bamboo(rng) if variant == "natural" else Material(M.jitter(rng, (0.15, 0.06, 0.05), 0.02), 0.2, 0.0, "wood")
    L = rng.uniform(0.15, 0.19)
    w, t = 0.009, 0.0025
    parts = [make_part("shaft", "shaft", S.box((L * 0.85, w, t), center=(-L * 0.075, 0, t / 2), bevel=0.0008), mat)]
    xn = -L * 0.05
    parts.append(make_part("node", "node", S.box((0.006, w + 0.001, t + 0.0015), center=(xn, 0, (t + 0.0015) / 2),
                                                 bevel=0.0006), mat))
    x0 = L * 0.35
    tip = S.hull(np.array([(x0 - 0.002, -w / 2, 0.0), (x0 - 0.002, w / 2, 0.0), (x0 - 0.002, -w / 2, t),
                           (x0 - 0.002, w / 2, t), (L / 2, -w * 0.7, 0.004), (L / 2, w * 0.7, 0.004),
                           (L / 2, -w * 0.7, 0.004 + t), (L / 2, w * 0.7, 0.004 + t)]))
    parts.append(make_part("tip", "tip", tip, mat))
    return parts


@register("wagashi", parts=("body",), extra_parts=("garnish", "pick"), size_range=(0.03, 0.12),
          density=1200, variants=("nerikiri", "daifuku", "yokan"), placement="surface")
def wagashi(rng: np.random.Generator, variant: str) -> list[Part]:
    """A sweet with its garnish on top and a wooden pick stuck in it, leaning out to the right,
    small enough for a plate's well."""
    colours = [(0.95, 0.7, 0.75), (0.7, 0.85, 0.55), (0.98, 0.95, 0.9), (0.55, 0.3, 0.45)]
    food = M.food(rng, colours[int(rng.integers(len(colours)))])
    r = rng.uniform(0.022, 0.028)
    if variant == "yokan":
        body = S.box((0.055, 0.022, 0.028), center=(0, 0, 0.014), bevel=0.001)
        food = M.food(rng, (0.3, 0.12, 0.1))
        top = 0.028
    elif variant == "daifuku":
        body = S.lathe([(r * 0.9, 0.0), (r, r * 0.3), (r * 0.8, r * 0.8), (r * 0.3, r)], sections=20)
        top = r
    else:
        body = S.lathe([(r * 0.85, 0.0), (r, r * 0.35), (r * 0.85, r * 0.75), (r * 0.4, r * 0.9)],
                       sections=10)  # a few facets read as the petals
        top = r * 0.9
    parts = [make_part("body", "body", body, food)]
    garnish = S.ellipsoid((0.006, 0.004, 0.0015), center=(0, 0, top + 0.0008), subdivisions=1)
    parts.append(make_part("garnish", "garnish", garnish, M.food(rng, (0.95, 0.85, 0.3))))
    lean = np.deg2rad(rng.uniform(30, 45))
    x0 = 0.012
    pick = S.tube([(x0, 0, top * 0.45), (x0 + 0.06 * np.sin(lean), 0, top * 0.45 + 0.06 * np.cos(lean))],
                  0.0015, sections=6)
    parts.append(make_part("pick", "pick", pick, _bamboo(rng)))
    return parts


@register("brazier", parts=("body", "trivet"), extra_parts=("ash", "foot", "ear", "liner", "prong", "bar", "charcoal"),
          size_range=(0.25, 0.65), density=1500, variants=("hibachi", "furo", "box"), placement="floor")
def brazier(rng: np.random.Generator, variant: str) -> list[Part]:
    """A charcoal brazier: a bed of ``ash`` inside the ``body`` and a ``trivet`` plate over the
    opening that a kettle stands on."""
    dark = Material((0.12, 0.11, 0.1, 1.0), 0.6, 0.6, "metal")
    ash = Material((0.75, 0.74, 0.72, 1.0), 0.95, 0.0, "stone")
    parts: list[Part] = []
    if variant == "box":
        wood = M.wood(rng)
        w, h = rng.uniform(0.4, 0.55), rng.uniform(0.28, 0.34)
        t = 0.025
        walls = [S.box((w, t, h), center=(0, w / 2 - t / 2, h / 2)), S.box((w, t, h), center=(0, -w / 2 + t / 2, h / 2)),
                 S.box((t, w - 2 * t, h), center=(w / 2 - t / 2, 0, h / 2)),
                 S.box((t, w - 2 * t, h), center=(-w / 2 + t / 2, 0, h / 2)),
                 S.box((w - 2 * t, w - 2 * t, t), center=(0, 0, t / 2))]
        parts.append(make_part("body", "body", walls, wood))
        ri = w / 2 - t - 0.03
        liner = shell([(ri, h * 0.3), (ri, h - 0.01)], 0.004, sections=24)
        parts.append(make_part("liner", "liner", liner, Material((0.72, 0.45, 0.25, 1.0), 0.3, 0.9, "metal")))
        parts.append(make_part("ash", "ash", S.cylinder(ri - 0.004, h * 0.35, center=(0, 0, t + h * 0.175 - 0.001),
                                                        sections=24), ash))
        top = h
        r_open = ri
        z_ash = t + h * 0.35 - 0.001
    else:
        r = rng.uniform(0.16, 0.22)
        h = rng.uniform(0.2, 0.26)
        zf = 0.03 if variant == "furo" else 0.0
        prof = [(r * 0.7, zf), (r * 0.95, zf + h * 0.35), (r, zf + h * 0.7), (r * 0.85, zf + h)]
        mat = M.ceramic(rng) if variant == "hibachi" else dark
        parts.append(make_part("body", "body", shell(prof, 0.012, sections=28), mat))
        parts.append(make_part("ash", "ash", S.cylinder(r * 0.7, h * 0.45, center=(0, 0, zf + 0.012 + h * 0.225 - 0.001),
                                                        sections=24), ash))
        top = zf + h
        r_open = r * 0.85 - 0.012
        z_ash = zf + 0.012 + h * 0.45 - 0.001
        if variant == "furo":
            for k in range(3):
                a = 2 * np.pi * k / 3 + np.pi / 2
                parts.append(make_part(f"foot_{k}", "foot", S.box((0.04, 0.04, zf + 0.01),
                                                                  center=(r * 0.6 * np.cos(a), r * 0.6 * np.sin(a),
                                                                          (zf + 0.01) / 2)), dark))
            for k, sx in enumerate((-1, 1)):
                parts.append(make_part(f"ear_{k}", "ear", S.ellipsoid((0.02, 0.012, 0.025),
                                                                      center=(sx * r * 0.99, 0, zf + h * 0.7),
                                                                      subdivisions=1), dark))
    # the sticks of charcoal laid on the ash under the trivet, side by side
    coal = Material((0.06, 0.06, 0.06, 1.0), 0.95, 0.0, "stone")
    rc = 0.012
    for k, y in enumerate((-2.2 * rc, 0.0, 2.2 * rc)):
        parts.append(make_part(f"charcoal_{k}", "charcoal", S.cylinder(rc, min(0.07, r_open), center=(0, y, z_ash + rc - 0.002),
                                                                       axis=(1, 0, 0), sections=8), coal))
    # the trivet: a plate over the opening with three prongs down into the ash
    rt = r_open * 0.85
    parts.append(make_part("trivet", "trivet", S.cylinder(rt, 0.006, center=(0, 0, top + 0.003), sections=24), dark))
    for k in range(3):
        a = 2 * np.pi * k / 3
        prong = S.box((0.012, 0.006, 0.06), center=(rt * 0.8 * np.cos(a), rt * 0.8 * np.sin(a), top - 0.03 + 0.001))
        parts.append(make_part(f"prong_{k}", "prong", prong, dark))
    # the bar across the opening that the trivet rests on, its ends on the rim
    bar = S.box((2 * r_open + 0.02, 0.02, 0.006), center=(0, 0, top - 0.003 + 0.0005))
    parts.append(make_part("bar", "bar", bar, dark))
    return parts


@register("incense_burner", parts=("body", "lid"), extra_parts=("foot", "ear", "knob", "vent", "foot_ring"),
          size_range=(0.06, 0.25), density=2500, variants=("tripod", "bowl", "tower"), placement="surface")
def incense_burner(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.ceramic(rng) if variant == "bowl" else Material(M.jitter(rng, (0.45, 0.35, 0.2), 0.05), 0.4, 0.8, "metal")
    r = rng.uniform(0.04, 0.06)
    h = r * (0.9 if variant != "tower" else 1.6)
    zf = 0.015 if variant == "tripod" else 0.0
    prof = [(r * 0.6, zf), (r * 0.95, zf + h * 0.4), (r, zf + h * 0.75), (r * 0.9, zf + h)]
    parts = [make_part("body", "body", S.lathe(prof, sections=24), mat)]
    if variant == "tripod":
        for k in range(3):
            a = 2 * np.pi * k / 3 + np.pi / 2
            parts.append(make_part(f"foot_{k}", "foot", S.frustum(0.006, 0.008, zf + 0.004,
                                                                  center=(r * 0.6 * np.cos(a), r * 0.6 * np.sin(a), 0),
                                                                  sections=10), mat))
        for k, sx in enumerate((-1, 1)):
            ear = S.tube([(sx * r * 0.95, 0, zf + h * 0.75), (sx * r * 1.25, 0, zf + h * 0.85),
                          (sx * r * 1.2, 0, zf + h * 1.05)], 0.004, sections=6)
            parts.append(make_part(f"ear_{k}", "ear", ear, mat))
    zt = zf + h
    lid_h = r * (0.5 if variant != "tower" else 0.9)
    lid = S.lathe([(r * 0.92, zt), (r * 0.8, zt + lid_h * 0.5), (r * 0.35, zt + lid_h)], sections=20)
    parts.append(make_part("lid", "lid", lid, mat))
    parts.append(make_part("knob", "knob", S.ellipsoid((r * 0.18, r * 0.18, r * 0.2), center=(0, 0, zt + lid_h + r * 0.12),
                                                       subdivisions=1), mat))
    # the openings in the lid the smoke rises through, round its shoulder
    dark = Material((0.05, 0.05, 0.05, 1.0), 0.9, 0.0, "metal")
    zv = zt + lid_h * 0.5
    rv = r * 0.8
    for k, a in enumerate(np.linspace(0, 2 * np.pi, 4, endpoint=False) + np.pi / 4):
        T = np.eye(4)
        T[:3, :3] = rot_z(a)
        T[:3, 3] = (np.cos(a) * rv, np.sin(a) * rv, zv)
        parts.append(make_part(f"vent_{k}", "vent", S.box((0.003, r * 0.3, lid_h * 0.25)).apply(T), dark))
    if variant != "tripod":  # it stands on a low foot ring
        parts.append(make_part("foot_ring", "foot_ring", ring([(r * 0.45, 0.0), (r * 0.62, 0.0), (r * 0.54, 0.004)],
                                                              sections=20), mat))
    return parts
