"""The tea house: tea trays, floor cushions and tea caddies.

A tea tray is a shallow open container (its floor is an internal support for ``IN``); a tea
caddy's lid is a revolute joint hinged at the back for the hinged variant.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._household import ring
from ._kit import OPEN_DOOR, hinge_parts, mount, revolute


@register("tea_tray", parts=("base", "rim"), extra_parts=("handle", "foot", "slat", "spline"), size_range=(0.28, 0.65), density=600,
          variants=("rect", "round", "slatted"), placement="surface")
def tea_tray(rng: np.random.Generator, variant: str) -> list[Part]:
    wood = M.wood(rng) if variant != "round" else M.solid(M.jitter(rng, (0.15, 0.08, 0.05), 0.02), "wood", 0.3)
    fh = 0.012
    if variant == "round":
        r = rng.uniform(0.15, 0.22)
        parts = [make_part("base", "base", S.cylinder(r, 0.01, center=(0, 0, fh + 0.005), sections=32), wood),
                 make_part("rim", "rim", S.vessel([(r + 0.004, fh + 0.002), (r + 0.012, fh + 0.035)], thickness=0.006),
                           wood)]
        for k in range(3):
            a = 2 * np.pi * k / 3
            parts.append(make_part(f"foot_{k}", "foot", S.cylinder(0.018, fh, center=(r * 0.7 * np.cos(a), r * 0.7 * np.sin(a),
                                                                                     fh / 2), sections=10), wood))
        return parts
    w, d = rng.uniform(0.4, 0.6), rng.uniform(0.28, 0.36)
    rh, t = rng.uniform(0.03, 0.05), 0.01
    parts = feet4_bars(w, d, fh, wood)
    if variant == "slatted":
        n = int(rng.integers(7, 11))
        pitch = (w - 2 * t) / n
        for k in range(n):
            parts.append(make_part(f"slat_{k}", "slat", S.box((pitch * 0.8, d - 2 * t, 0.012),
                                                              center=(-w / 2 + t + pitch * (k + 0.5), 0, fh + 0.018)), wood))
        parts.append(make_part("base", "base", S.box((w - 2 * t, d - 2 * t, 0.006), center=(0, 0, fh + 0.003)), wood))
    else:
        parts.append(make_part("base", "base", S.box((w - 2 * t, d - 2 * t, 0.01), center=(0, 0, fh + 0.005)), wood))
    rim = [S.box((w, t, rh), center=(0, s * (d / 2 - t / 2), fh + rh / 2)) for s in (-1, 1)]
    rim += [S.box((t, d - 2 * t, rh), center=(s * (w / 2 - t / 2), 0, fh + rh / 2)) for s in (-1, 1)]
    # the four rails round the floor, each board its own (mitred at the corners)
    parts += [make_part("rim" if k == 0 else f"rim_{k}", "rim", b, wood) for k, b in enumerate(rim)]
    # two contrasting keys let across each mitred corner: thin triangles in saw kerfs, flush
    # with both rails' outer faces
    key = M.solid(M.jitter(rng, (0.25, 0.15, 0.1), 0.03), "wood", 0.5)
    k = 0
    for sx, sy in [(-1, -1), (1, -1), (-1, 1), (1, 1)]:
        cx, cy, e = sx * w / 2, sy * d / 2, 0.014
        tri = [(cx, cy), (cx - sx * e, cy), (cx, cy - sy * e)]
        if sx * sy < 0:
            tri = tri[::-1]
        for zk in (fh + rh / 3, fh + 2 * rh / 3):
            parts.append(make_part(f"spline_{k}", "spline", S.prism(tri, zk - 0.001, zk + 0.001), key))
            k += 1
    for i, s in enumerate((-1, 1)):
        parts.append(make_part(f"handle_{i}", "handle", S.box((0.012, 0.1, 0.02), center=(s * (w / 2 + 0.006), 0, fh + rh - 0.012)),
                               wood))
    return parts


def feet4_bars(w: float, d: float, fh: float, mat) -> list[Part]:
    """Two runner bars under a tray's short sides."""
    return [make_part(f"foot_{i}", "foot", S.box((0.03, d * 0.8, fh), center=(s * (w / 2 - 0.05), 0, fh / 2)), mat)
            for i, s in enumerate((-1, 1))]


@register("floor_cushion", parts=("cushion",), extra_parts=("button", "piping", "tassel"), size_range=(0.4, 0.85),
          density=120, variants=("square", "round", "zabuton"), placement="floor")
def floor_cushion(rng: np.random.Generator, variant: str) -> list[Part]:
    cloth = M.fabric(rng)
    trim = M.solid(M.jitter(rng, (0.75, 0.6, 0.3), 0.05), "fabric", 0.9)
    if variant == "round":
        r, h = rng.uniform(0.2, 0.3), rng.uniform(0.08, 0.15)
        parts = [make_part("cushion", "cushion", S.union([S.cylinder(r - h / 2, h, center=(0, 0, h / 2), sections=32),
                                                          S.ellipsoid((r, r, h / 2), center=(0, 0, h / 2))]), cloth)]
        top = h
        pts = [(0.0, 0.0)] + [(r * 0.5 * np.cos(a), r * 0.5 * np.sin(a)) for a in np.linspace(0, 2 * np.pi, 6, endpoint=False)]
    else:
        s = rng.uniform(0.5, 0.7) if variant == "zabuton" else rng.uniform(0.42, 0.55)
        h = rng.uniform(0.05, 0.08) if variant == "zabuton" else rng.uniform(0.1, 0.16)
        parts = [make_part("cushion", "cushion", S.box((s, s * (1.1 if variant == "zabuton" else 1.0), h), center=(0, 0, h / 2),
                                                       bevel=h / 3.2), cloth),
                 make_part("piping", "piping", S.box((s + 0.008, s * (1.1 if variant == "zabuton" else 1.0) + 0.008, 0.01),
                                                     center=(0, 0, h / 2)), trim)]
        top = h
        pts = [(0.0, 0.0), (-s / 4, -s / 4), (s / 4, -s / 4), (-s / 4, s / 4), (s / 4, s / 4)]
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            if variant == "zabuton":
                parts.append(make_part(f"tassel_{i}", "tassel", S.ellipsoid((0.015, 0.015, 0.012),
                                                                             center=(sx * (s / 2 - 0.01), sy * (s * 0.55 - 0.01),
                                                                                     h / 2)), trim))
    for k, (x, y) in enumerate(pts):
        parts.append(make_part(f"button_{k}", "button", S.cylinder(0.012, 0.01, center=(x, y, top - 0.003), sections=10), trim))
    # the tufting thread runs through to a twin button on the underside, sunk into the
    # cushion flush with its bottom
    for k, (x, y) in enumerate(pts):
        parts.append(make_part(f"button_{len(pts) + k}", "button", S.cylinder(0.012, 0.006, center=(x, y, 0.003), sections=10), trim))
    if variant == "round":  # the piped seam round the middle of the side
        parts.append(make_part("piping", "piping", ring([(r - 0.003, h / 2 - 0.004), (r + 0.004, h / 2 - 0.004), (r + 0.004, h / 2 + 0.004),
                                                         (r - 0.003, h / 2 + 0.004)], sections=32), trim))
    return parts


@register("tea_caddy", parts=("body", "lid"), extra_parts=("knob", "hinge", "label", "bead", "inner_lid", "clasp"), size_range=(0.07, 0.2), density=500,
          variants=("round", "square_hinged"), placement="surface")
def tea_caddy(rng: np.random.Generator, variant: str) -> list[Part]:
    tin = M.solid(M.jitter(rng, [(0.1, 0.3, 0.2), (0.6, 0.1, 0.1), (0.1, 0.1, 0.1), (0.8, 0.65, 0.3)][int(rng.integers(4))],
                           0.03), "metal", 0.35, 0.7)
    if variant == "round":
        r, h = rng.uniform(0.035, 0.05), rng.uniform(0.08, 0.14)
        return [make_part("body", "body", S.cylinder(r, h, center=(0, 0, h / 2), sections=24), tin),
                make_part("lid", "lid", S.cylinder(r + 0.002, 0.02, center=(0, 0, h + 0.008), sections=24), tin),
                make_part("knob", "knob", S.ellipsoid((0.01, 0.01, 0.008), center=(0, 0, h + 0.02)), tin),
                make_part("label", "label", S.cylinder(r + 0.0008, h * 0.4, center=(0, 0, h * 0.45), sections=24),
                          M.paper(rng)),
                # the rolled beads stiffening the tin near its foot and under the lid, and the one
                # rolled round the lid's own lower edge
                *[make_part(f"bead_{k}", "bead", ring([(r - 0.001, z - 0.002), (r + 0.0015, z), (r - 0.001, z + 0.002)], sections=24), tin)
                  for k, z in enumerate((0.006, h - 0.03))],
                make_part("bead_2", "bead", ring([(r + 0.001, h - 0.0015), (r + 0.0035, h - 0.0005), (r + 0.001, h + 0.0015)], sections=24), tin),
                # the tight-fitting inner lid's pull ring, seen when the outer lid is off
                make_part("inner_lid", "inner_lid", ring([(r * 0.3, h - 0.001), (r * 0.4, h - 0.001), (r * 0.4, h), (r * 0.3, h)], sections=16),
                          tin)]
    w, h = rng.uniform(0.07, 0.1), rng.uniform(0.09, 0.15)
    parts = [make_part("body", "body", S.box((w, w, h), center=(0, 0, h / 2), bevel=0.003), tin),
             make_part("lid", "lid", S.box((w + 0.002, w + 0.002, 0.015), center=(0, 0, h + 0.0075), bevel=0.003), tin),
             make_part("knob", "knob", S.cylinder(0.008, 0.01, center=(0, 0.01, h + 0.02), sections=10), tin),
             make_part("label", "label", S.box((w * 0.7, 0.001, h * 0.4), center=(0, w / 2 + 0.0004, h * 0.45)), M.paper(rng))]
    parts += hinge_parts("hinge", x=h, y=-w / 2 - 0.003, z0=-w / 2, z1=w / 2, mat=tin, radius=0.003, length=0.015, axis="x")
    # the spring clasp on the front that holds the lid shut, on the body under the lid's edge
    parts.append(make_part("clasp", "clasp", S.box((0.018, 0.003, 0.012), center=(0, w / 2 + 0.0015, h - 0.007)), tin))
    parts.append(revolute("lid_hinge", "body", "lid", axis=(1, 0, 0), origin=(0, -w / 2 - 0.001, h), opens=OPEN_DOOR))
    parts.append(mount("lid", "knob"))
    return parts
