"""Books, guitars and brooms.

Books stand upright, with the ``front_cover`` at +Y, the ``back_cover`` at −Y, the ``spine`` on
the −X side and the ``pages`` block between the covers; the ``title`` printed on the spine and a
``barcode`` on the back cover, and a bound book's ``headband`` s at both ends of the block and its
``ribbon`` marker. Boxes all, since books are the commonest small object in a scene. Guitars stand on the bottom of their body, neck up, strings facing
+Y; their flat back (−Y) is what leans against a wall. Brooms stand on their bristles.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from ...geometry.frames import rot_x
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring


def _page_colour(rng) -> Material:
    return M.solid(M.jitter(rng, (0.94, 0.92, 0.85), 0.02), "paper", 0.9)


@register("book", parts=("front_cover", "back_cover", "spine", "pages"), extra_parts=("headband", "ribbon"),
          size_range=(0.15, 0.42),
          density=650, variants=("paperback", "hardcover", "large"), placement="surface")
def book(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "paperback":
        h, w, t = rng.uniform(0.17, 0.21), rng.uniform(0.105, 0.135), rng.uniform(0.01, 0.035)
        c, inset = rng.uniform(0.0008, 0.0015), 0.0
    elif variant == "hardcover":
        h, w, t = rng.uniform(0.21, 0.26), rng.uniform(0.14, 0.18), rng.uniform(0.02, 0.05)
        c, inset = rng.uniform(0.0025, 0.0035), rng.uniform(0.002, 0.004)
    else:
        h, w, t = rng.uniform(0.28, 0.38), rng.uniform(0.22, 0.3), rng.uniform(0.015, 0.06)
        c, inset = rng.uniform(0.003, 0.004), rng.uniform(0.003, 0.005)
    cover = M.paper(rng)
    spine = S.box((c, t, h), center=(-w / 2 + c / 2, 0, h / 2))
    front = S.box((w - c, c, h), center=(c / 2, t / 2 - c / 2, h / 2))
    back = S.box((w - c, c, h), center=(c / 2, -t / 2 + c / 2, h / 2))
    pw = w - c - inset
    pages = S.box((pw, t - 2 * c, h - 2 * inset), center=(-w / 2 + c + pw / 2, 0, h / 2))
    out = [make_part("front_cover", "front_cover", front, cover),
           make_part("back_cover", "back_cover", back, cover),
           make_part("spine", "spine", spine, cover),
           make_part("pages", "pages", pages, _page_colour(rng))]
    if variant != "paperback":  # a sewn block: headbands at both ends and a ribbon marker
        band = M.solid((0.7, 0.15, 0.15), "fabric", 0.8)
        out += [make_part(f"headband_{k}", "headband", S.box((0.003, t - 2 * c, inset * 0.8), center=(-w / 2 + c + 0.0015, 0, z)),
                          band) for k, z in enumerate((inset * 0.4, h - inset * 0.4))]
        # the ribbon's tail lies along the foot of the block, between the covers
        out.append(make_part("ribbon", "ribbon", S.box((0.006, t * 0.5, inset * 0.5), center=(-w * 0.1, 0, inset * 0.25)), band))
    return out


def _bout(cx: float, cz: float, rx: float, rz: float, y0: float, y1: float, *,
          z_cut: float | None = None, n: int = 20) -> S.Shape:
    """An elliptic slab in the XZ plane between y0 and y1, optionally cut flat below ``z_cut``."""
    a = np.linspace(0, 2 * np.pi, n, endpoint=False)
    xz = np.c_[cx + rx * np.cos(a), cz + rz * np.sin(a)]
    if z_cut is not None:
        xz[:, 1] = np.maximum(xz[:, 1], z_cut)
    pts = np.vstack([np.c_[xz[:, 0], np.full(n, y0), xz[:, 1]], np.c_[xz[:, 0], np.full(n, y1), xz[:, 1]]])
    return S.hull(pts)


@register("guitar", parts=("body", "neck", "head"),
          extra_parts=("bridge", "soundhole", "pickguard", "pickup", "tuning_peg", "string", "nut", "knob", "jack",
                       "strap_button", "switch", "rosette"),
          size_range=(0.85, 1.15), density=450, variants=("acoustic", "electric"))
def guitar(rng: np.random.Generator, variant: str) -> list[Part]:
    acoustic = variant == "acoustic"
    if acoustic:
        length, lower, upper = rng.uniform(0.47, 0.52), rng.uniform(0.37, 0.41), rng.uniform(0.27, 0.3)
        depth = rng.uniform(0.09, 0.12)
        mat = M.wood(rng)
    else:
        length, lower, upper = rng.uniform(0.4, 0.45), rng.uniform(0.31, 0.34), rng.uniform(0.24, 0.28)
        depth = rng.uniform(0.04, 0.05)
        mat = M.solid(M.jitter(rng, [(0.7, 0.1, 0.1), (0.1, 0.1, 0.1), (0.9, 0.9, 0.88),
                                     (0.15, 0.3, 0.6)][int(rng.integers(4))], 0.02), "wood", 0.3)
    y0, y1 = -depth / 2, depth / 2
    rz_low = length * 0.32
    low = _bout(0, rz_low, lower / 2, rz_low, y0, y1, z_cut=0.006)
    rz_up = length * 0.24
    up = _bout(0, length - rz_up, upper / 2, rz_up, y0, y1)
    waist = _bout(0, length * 0.55, upper * 0.4, length * 0.2, y0, y1)
    body = [low, up, waist]
    dark = M.solid((0.12, 0.08, 0.05), "wood", 0.6)
    neck_w, neck_t = rng.uniform(0.046, 0.054), rng.uniform(0.02, 0.025)
    neck_len = rng.uniform(0.37, 0.41) if acoustic else rng.uniform(0.38, 0.42)
    z_neck = length - 0.03
    neck = S.box((neck_w, neck_t, neck_len + 0.03), center=(0, y1 - neck_t / 2 - 0.004,
                                                             z_neck + (neck_len + 0.03) / 2))
    board = S.box((neck_w * 0.96, 0.005, neck_len), center=(0, y1 - 0.0015, length + neck_len / 2))
    # the head is tilted back (towards -Y) by 12 degrees at the top of the neck
    R = rot_x(np.deg2rad(12))
    head_len, head_w = rng.uniform(0.17, 0.2), rng.uniform(0.07, 0.085)
    top = np.array([0.0, y1 - neck_t / 2 - 0.004, length + neck_len])
    head_c = top + R @ np.array([0, 0, head_len / 2])
    head = S.box((head_w, 0.016, head_len), center=head_c, R=R, bevel=0.003)
    pegs = []
    for k in range(6):
        side = -1 if k < 3 else 1
        p = top + R @ np.array([side * (head_w / 2 + 0.008), 0.0, head_len * (0.3 + 0.22 * (k % 3))])
        pegs.append(S.cylinder(0.006, 0.018, center=p, axis=(1, 0, 0), sections=8))
    # neck and fretboard are one part; each tuning peg is a part of its own
    metal = M.metal(rng)
    parts = [make_part("body", "body", body, mat), make_part("neck", "neck", [neck, board], dark),
             make_part("head", "head", head, dark)]
    parts += [make_part(f"tuning_peg_{k}", "tuning_peg", pg, metal) for k, pg in enumerate(pegs)]
    # the nut at the top of the fretboard, and six strings from it down to the bridge
    y_board = y1 + 0.001
    nut_h = 0.003
    parts.append(make_part("nut", "nut", S.box((neck_w * 0.96, nut_h, 0.004),
                                                center=(0, y_board + nut_h / 2, length + neck_len - 0.002)),
                           M.solid((0.92, 0.9, 0.84), "plastic")))
    z_b, y_b = (length * 0.3, y1 + 0.0095) if acoustic else (length * 0.25, y1 + 0.013)
    z_n, y_n = length + neck_len - 0.004, y_board + nut_h + 0.0008
    for k in range(6):
        f = (k - 2.5) / 2.5
        a = np.array([f * 0.026, y_b, z_b])
        b = np.array([f * neck_w * 0.36, y_n, z_n])
        parts.append(make_part(f"string_{k}", "string",
                               S.cylinder(0.0007, float(np.linalg.norm(b - a)), center=(a + b) / 2,
                                          axis=b - a, sections=6), metal))
    if acoustic:
        hole = S.cylinder(length * 0.085, 0.002, center=(0, y1 + 0.001, length * 0.62), axis=(0, 1, 0),
                          sections=20)
        parts.append(make_part("soundhole", "soundhole", hole, M.solid((0.05, 0.04, 0.03), "wood")))
        parts.append(make_part("rosette", "rosette", S.transformed(
            ring([(length * 0.085, -0.0008), (length * 0.1, -0.0008), (length * 0.1, 0.0008), (length * 0.085, 0.0008)], sections=20),
            np.array([[1, 0, 0, 0], [0, 0, -1, y1 + 0.0005], [0, 1, 0, length * 0.62], [0, 0, 0, 1.0]])), dark))
        bridge = S.box((0.15, 0.008, 0.03), center=(0, y1 + 0.004, length * 0.3), bevel=0.002)
        parts.append(make_part("bridge", "bridge", bridge, dark))
    else:
        guard = S.hull(np.array([(x, y, z) for x in (-lower * 0.32, lower * 0.3)
                                 for y in (y1, y1 + 0.002) for z in (length * 0.28, length * 0.7)]))
        knobs = [S.cylinder(0.01, 0.012, center=(lower * 0.3, y1 + 0.006, z), axis=(0, 1, 0),
                            sections=10) for z in (length * 0.2, length * 0.28)]
        parts.append(make_part("pickguard", "pickguard", guard, M.solid((0.95, 0.95, 0.93), "plastic")))
        # the volume and tone knobs, the pickups (each its own), the pickup selector switch and
        # the output jack on the body's edge
        parts += [make_part(f"knob_{k}", "knob", kn, M.solid((0.95, 0.95, 0.93), "plastic")) for k, kn in enumerate(knobs)]
        pickups = [S.box((0.075, 0.008, 0.02), center=(0, y1 + 0.006, z), bevel=0.002)
                   for z in (length * 0.38, length * 0.55)]
        parts += [make_part("pickups" if k == 0 else f"pickups_{k}", "pickup", pu, M.solid((0.1, 0.1, 0.1), "plastic"))
                  for k, pu in enumerate(pickups)]
        parts.append(make_part("switch", "switch", S.cylinder(0.003, 0.02, center=(-lower * 0.25, y1 + 0.012, length * 0.62),
                                                              axis=(0, 1, 0), sections=8), metal))
        parts.append(make_part("jack", "jack", S.cylinder(0.009, 0.008, center=(lower * 0.4635 + 0.002, 0, length * 0.2),
                                                          axis=(1, 0, 0), sections=10), metal))
        parts.append(make_part("bridge", "bridge", S.box((0.08, 0.01, 0.02),
                                                         center=(0, y1 + 0.005, length * 0.25)),
                               M.metal(rng)))
    # the strap button on the upper bout, by the neck heel
    parts.append(make_part("strap_button", "strap_button", S.cylinder(0.006, 0.01, center=(upper * 0.4635 + 0.002, 0, length * 0.85),
                                                                      axis=(1, 0, 0), sections=8), metal))
    return parts


@register("broom", parts=("handle", "head"), extra_parts=("bristles", "ferrule", "hang_cap", "brace", "stitching"),
          size_range=(1.0, 1.6),
          density=300, variants=("push", "angle", "corn"))
def broom(rng: np.random.Generator, variant: str) -> list[Part]:
    bristle = M.solid(M.jitter(rng, [(0.85, 0.72, 0.45), (0.15, 0.15, 0.15), (0.2, 0.35, 0.7),
                                     (0.8, 0.2, 0.2)][int(rng.integers(4))], 0.02), "fabric", 0.9)
    stock = M.wood(rng) if rng.random() < 0.5 else M.plastic(rng)
    r_h = rng.uniform(0.011, 0.014)
    if variant == "push":
        w, d = rng.uniform(0.4, 0.6), rng.uniform(0.06, 0.08)
        hb, hs = rng.uniform(0.06, 0.09), rng.uniform(0.03, 0.045)
        bristles = S.box((w - 0.01, d * 0.8, hb), center=(0, 0, hb / 2), bevel=0.004)
        head = S.box((w, d, hs), center=(0, 0, hb + hs / 2), bevel=0.006)
        z_head = hb + hs
    elif variant == "angle":
        w, d = rng.uniform(0.25, 0.32), rng.uniform(0.035, 0.05)
        hb_lo, hb_hi = rng.uniform(0.1, 0.13), rng.uniform(0.16, 0.2)
        # bristles: flat bottom, top slanting up from the right to the left
        pts = [(x, y, z) for y in (-d * 0.4, d * 0.4)
               for x, z in ((-w / 2, 0.0), (w / 2, 0.0), (w / 2, hb_lo), (-w / 2, hb_hi))]
        bristles = S.hull(np.array(pts))
        slope = (hb_hi - hb_lo) / w
        head_pts = [(x, y, z + dz) for y in (-d / 2, d / 2)
                    for x, z in ((-w / 2, hb_hi), (w / 2, hb_lo)) for dz in (-0.005, 0.035)]
        head_pts += [(0.0, y, hb_lo + slope * w / 2 + 0.07) for y in (-d / 2 * 0.8, d / 2 * 0.8)]
        head = S.hull(np.array(head_pts))
        z_head = hb_lo + slope * w / 2 + 0.07
    else:  # corn broom: a flat fan of straw bound to the handle
        w, d, hb = rng.uniform(0.28, 0.36), rng.uniform(0.04, 0.06), rng.uniform(0.3, 0.4)
        pts = [(x, y, z) for y in (-d / 2, d / 2)
               for x, z in ((-w / 2, 0.0), (w / 2, 0.0), (w * 0.2, hb), (-w * 0.2, hb))]
        bristles = S.hull(np.array(pts))
        head = S.box((w * 0.42, d + 0.006, 0.04), center=(0, 0, hb - 0.03), bevel=0.006)
        z_head = hb + 0.01
    length = rng.uniform(0.95, 1.18) if variant == "corn" else rng.uniform(1.05, 1.35)
    handle = S.cylinder(r_h, length, center=(0, 0, z_head - 0.02 + length / 2), sections=12)
    out = [make_part("bristles", "bristles", bristles, bristle),
           make_part("head", "head", head, stock),
           make_part("handle", "handle", handle, M.wood(rng) if rng.random() < 0.5 else M.metal(rng))]
    # the threaded collar the handle screws into and the cap with a hanging hole over its end
    top = z_head - 0.02 + length
    out.append(make_part("ferrule", "ferrule", S.cylinder(r_h * 1.35, 0.05, center=(0, 0, z_head + 0.025), sections=12), stock))
    out.append(make_part("hang_cap", "hang_cap", S.cylinder(r_h * 1.15, 0.03, center=(0, 0, top - 0.015), sections=12), stock))
    if variant == "push":  # the brace from the head to the handle that keeps it from working loose
        out.append(make_part("brace", "brace", S.tube([(-w * 0.3, 0, z_head), (-r_h * 1.2, 0, z_head + 0.2)], 0.005, sections=8),
                             M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8)))
    elif variant == "corn":  # the rows of stitching that flatten the straw into a fan
        out += [make_part(f"stitching_{k}", "stitching", S.box((w * (0.5 - 0.08 * k), d + 0.004, 0.006), center=(0, 0, z)),
                          M.solid((0.7, 0.15, 0.15), "fabric", 0.8)) for k, z in enumerate((hb * 0.45, hb * 0.6, hb * 0.75))]
    return out
