"""Mugs, cups and tea cups: revolved walls with a swept handle.

Mugs come round (revolved, optionally bellied) or square (bevelled box walls). Cups stand on a
heavy ``base`` and tea cups on a ``foot_ring``; both have a rolled ``rim``.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring


def _handle(rng, r_out: float, h: float, thick: float) -> S.Shape:
    span = h * rng.uniform(0.45, 0.65)
    z0 = h * 0.5 - span / 2
    reach = rng.uniform(0.022, 0.032)
    t = np.linspace(0, np.pi, 9)
    path = np.c_[r_out - 0.002 + reach * np.sin(t), np.zeros_like(t), z0 + span * (1 - np.cos(t)) / 2][::-1]
    # the handle sticks out to the asset's right (+X)
    return S.tube(path, thick, sections=10)


def _handle_joins(handle: S.Shape, r_out: float, thick: float, mat: Material) -> list[Part]:
    """The two pads where a pulled handle is luted onto the wall (upper and lower attachment),
    flattened discs on the wall at the handle's ends, facing +X."""
    b = handle.mesh.bounds
    z_lo, z_hi = float(b[0, 2]) + thick, float(b[1, 2]) - thick
    pad = thick * 1.5
    return [make_part(f"handle_join_{k}", "handle_join",
                      S.cylinder(pad, 0.004, center=(r_out - 0.001, 0.0, z), axis=(1, 0, 0), sections=10), mat)
            for k, z in enumerate((z_hi, z_lo))]


def _square_mug(rng, w: float, h: float, t: float) -> S.Shape:
    walls = [
        S.box((w, t, h), center=(0, w / 2 - t / 2, h / 2)),
        S.box((w, t, h), center=(0, -w / 2 + t / 2, h / 2)),
        S.box((t, w - 2 * t, h), center=(w / 2 - t / 2, 0, h / 2)),
        S.box((t, w - 2 * t, h), center=(-w / 2 + t / 2, 0, h / 2)),
        S.box((w - 2 * t, w - 2 * t, t), center=(0, 0, t / 2)),
    ]
    return S.union(walls)


@register("mug", parts=("body", "handle"), extra_parts=("rim", "foot_ring", "base", "handle_join"),
          size_range=(0.10, 0.14), density=900,
          variants=("round", "belly", "square"), placement="surface")
def mug(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.036, 0.045)
    h = rng.uniform(0.085, 0.11)
    t = rng.uniform(0.0035, 0.005)
    mat = M.ceramic(rng)
    fh = 0.003  # the unglazed foot it stands on
    if variant == "square":
        body = _square_mug(rng, 2 * r, h, t).moved((0, 0, fh))
        foot = S.box((2 * r - 0.006, 2 * r - 0.006, fh), center=(0, 0, fh / 2))
        prof = [(r, fh), (r, fh + h)]
    else:
        if variant == "belly":
            prof = [(r * 0.85, fh), (r * 1.05, fh + h * 0.35), (r * 1.0, fh + h * 0.75), (r * 0.92, fh + h)]
            body = S.vessel(prof, t)
        else:
            prof = [(r * 0.96, fh), (r, fh + h)]
            body = S.vessel(prof, t, piece_sections=16)
        rf = prof[0][0] * 0.9
        foot = ring([(rf - 0.005, 0.0), (rf, 0.0), (rf + 0.002, fh), (rf - 0.006, fh)], sections=16)
    th = rng.uniform(0.005, 0.007)
    handle = _handle(rng, r, h, th).moved((0, 0, fh))
    parts = [make_part("body", "body", body, mat), make_part("handle", "handle", handle, mat)]
    parts += _handle_joins(handle, r, th, mat)
    unglazed = Material(M.jitter(rng, (0.8, 0.74, 0.64), 0.03), 0.9, 0.0, "ceramic")
    if variant == "square":
        parts.append(make_part("base", "base", foot, unglazed))
        # the glazed lip round the four walls' top
        w, zl = 2 * r, fh + h
        lip = [S.box((w + 0.001, t + 0.001, 0.002), center=(0, sy * (w - t) / 2, zl - 0.0005)) for sy in (-1, 1)]
        lip += [S.box((t + 0.001, w - 2 * t, 0.002), center=(sx * (w - t) / 2, 0, zl - 0.0005)) for sx in (-1, 1)]
        parts.append(make_part("rim", "rim", lip, mat))
    else:
        parts.append(make_part("foot_ring", "foot_ring", foot, unglazed))
        parts.append(make_part("rim", "rim", _rim(prof[-1][0], fh + h, t, 0.0012), mat))
    return parts


def _rim(r_out: float, z: float, t: float, bead: float) -> S.Shape:
    """A rolled rim round a wall's top edge (outer radius ``r_out`` at height ``z``): a
    triangular section with faces sloping 27 degrees (no flat annulus, no ledge), rising little
    above the lip (a cup's height decides whether a tray's rim encloses it)."""
    k = 0.5 * (t + bead)
    return ring([(r_out - t, z - 1.5 * k), (r_out + bead, z - 0.5 * k), (r_out - t, z + 0.5 * k)],
                sections=16)


@register("cup", parts=("body",), extra_parts=("base", "rim", "handle", "handle_join", "stacking_ring"), size_range=(0.08, 0.14),
          density=900, variants=("tumbler", "tapered", "handled"), placement="surface")
def cup(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.03, 0.04)
    h = rng.uniform(0.08, 0.12)
    t = rng.uniform(0.0025, 0.004)
    mat = M.glass(rng) if rng.random() < 0.5 else M.plastic(rng)
    if variant == "handled":
        mat = M.ceramic(rng)
    zb = rng.uniform(0.004, 0.007)  # the heavy base it stands on
    r0 = r * 0.8 if variant == "tapered" else r
    prof = [(r0, zb), (r, zb + h)]
    r_base = r0 * 0.96
    base = S.lathe([(r_base, 0.0), (r_base, zb - 0.001), (r0 * 0.9, zb)], sections=24)
    parts = [make_part("body", "body", S.vessel(prof, t, bottom=t * 2), mat),
             make_part("base", "base", base, mat),
             make_part("rim", "rim", _rim(r, zb + h, t, rng.uniform(0.0008, 0.0015)), mat)]
    if variant == "handled":
        th = rng.uniform(0.004, 0.006)
        handle = _handle(rng, r, h, th).moved((0, 0, zb))
        parts.append(make_part("handle", "handle", handle, mat))
        parts += _handle_joins(handle, r, th, mat)
    else:  # the moulded ring round the wall a stacked cup rests on when nested
        zs = zb + h * 0.72
        rs = r0 + (r - r0) * 0.72
        parts.append(make_part("stacking_ring", "stacking_ring", ring([(rs - 0.0005, zs - 0.003), (rs + 0.0012, zs - 0.0015),
                                                                       (rs + 0.0012, zs + 0.0015), (rs - 0.0005, zs + 0.003)],
                                                                      sections=16), mat))
    return parts


@register("tea_cup", parts=("body",), extra_parts=("handle", "foot_ring", "rim", "trim", "handle_join"),
          size_range=(0.06, 0.11), density=900, variants=("bowl", "handled"), placement="surface")
def tea_cup(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.03, 0.042)
    h = rng.uniform(0.045, 0.065)
    t = 0.003
    mat = M.ceramic(rng)
    fh = rng.uniform(0.002, 0.0035)  # the low foot ring it stands on
    body = S.vessel([(r * 0.5, fh), (r * 0.55, fh + 0.006), (r * 0.9, fh + h * 0.5), (r, fh + h)], t)
    rf = r * 0.48
    foot = ring([(rf - 0.004, 0.0), (rf, 0.0), (rf - 0.002, fh + 0.0005)], sections=16)
    parts = [make_part("body", "body", body, mat), make_part("foot_ring", "foot_ring", foot, mat),
             make_part("rim", "rim", _rim(r, fh + h, t, 0.001), mat)]
    if variant == "handled":
        handle = _handle(rng, r * 0.9, h, 0.004).moved((0, 0, fh))
        parts.append(make_part("handle", "handle", handle, mat))
        parts += _handle_joins(handle, r * 0.9, 0.004, mat)
    # the gilded band under the rim and a painted spray of flowers on the front
    zt = fh + h * 0.88
    rt = r * 0.9 + (r - r * 0.9) * (zt - fh - h * 0.5) / (h * 0.5)
    gold = Material(M.jitter(rng, (0.83, 0.68, 0.3), 0.03), 0.3, 0.9, "metal")
    parts.append(make_part("trim", "trim", ring([(rt - 0.0004, zt - 0.002), (rt + 0.0005, zt - 0.002),
                                                 (rt + 0.0005, zt + 0.002), (rt - 0.0004, zt + 0.002)],
                                                sections=16), gold))
    return parts
