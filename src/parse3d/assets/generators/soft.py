"""Soft goods: pillows, towels and rugs.

Pillows are a soft convex ``cover`` with a flattened bottom (they stand on a bed or a sofa) and a
``piping`` cord along the seam; folded towels are stacks of rounded layers, rolled towels
flattened rolls along X; rugs are a thin ``field`` framed by a ``border`` on the floor, optionally
with ``fringe`` strips at their short ends. A pillow's or a rug's ``body`` (its one part before)
is a group label over its cover, piping, care ``tag`` and ``zipper``, or its field, border and the
woven ``medallion`` and corner ``motif`` s. Towels show their woven ``border`` band, a hanging
``loop`` and a ``tag``.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from ...geometry.frames import make_transform, rot_y
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._bedbath_common import bevel_box, cushion, loft, soft_hull
from ._household import ring


def _roll(length: float, radius: float, *, squash: float = 0.85, flat: float = 0.3,
          n_u: int = 16) -> S.Shape:
    """A soft roll along X (bolster, rolled towel) with rounded ends and a flat bottom.

    Centred on x = y = 0, bottom at z = 0. One convex piece.
    """
    u = np.linspace(0, 2 * np.pi, n_u, endpoint=False)
    # built along +Z, then turned so the axis runs along X; ring x becomes -z after turning,
    # so clipping x from above flattens the final bottom
    ring = np.c_[radius * np.cos(u), radius * squash * np.sin(u)]
    ring[:, 0] = np.minimum(ring[:, 0], radius * (1 - flat))
    end = min(radius * 0.6, length * 0.2)
    zs, scales = [], []
    for k, a in enumerate(np.linspace(0, np.pi / 2, 4)):
        zs.append(end * (1 - np.cos(a)))
        scales.append(0.55 + 0.45 * np.sin(a))
        if k == 3:
            break
    prof = list(zip(zs, scales, strict=True))
    prof += [(length - z, s) for z, s in prof[::-1]]
    rings = [np.c_[ring * s, np.full(n_u, z - length / 2)] for z, s in prof]
    mesh = loft(rings)
    shape = S.Shape(mesh, [mesh]).apply(make_transform(rot_y(np.pi / 2)))
    return shape.moved((0, 0, -shape.mesh.bounds[0, 2]))


def _piping_loop(rx: float, ry: float, power: float, z: float, n: int = 20) -> np.ndarray:
    """(n, 3) points on the superellipse seam of a :func:`soft_hull` pillow at height ``z``."""
    u = np.linspace(0, 2 * np.pi, n, endpoint=False)
    cu, su = np.cos(u), np.sin(u)
    ex = 2.0 / power
    return np.c_[rx * np.sign(cu) * np.abs(cu) ** ex, ry * np.sign(su) * np.abs(su) ** ex,
                 np.full(n, z)]


@register("pillow", parts=("body",), extra_parts=("cover", "piping", "tag", "zipper", "zip_pull"), size_range=(0.3, 0.95),
          density=60, variants=("bed", "square", "bolster"), placement="surface",
          groups={"body": ("cover", "piping", "tag", "zipper", "zip_pull")})
def pillow(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.fabric(rng) if rng.random() < 0.6 else M.solid((0.95, 0.94, 0.92), "fabric", 0.95)
    trim = mat if rng.random() < 0.5 else M.fabric(rng)
    pr = rng.uniform(0.004, 0.006)  # the piping cord's radius
    if variant == "bolster":
        length, radius = rng.uniform(0.45, 0.9), rng.uniform(0.08, 0.12)
        body = _roll(length, radius, squash=1.0, flat=0.25)
        # a cord round each end, where the end cap is sewn to the body
        z_axis = radius * 0.75
        end = min(radius * 0.6, length * 0.2)
        u = np.linspace(0, 2 * np.pi, 16, endpoint=False)
        yz = np.c_[radius * np.cos(u), np.maximum(z_axis + radius * np.sin(u), pr)]
        cords = [S.tube(np.c_[np.full(len(u), sx * (length / 2 - end)), yz], pr, sections=8,
                        closed=True) for sx in (-1, 1)]
        piping = cords
    else:
        if variant == "bed":
            w, d = rng.uniform(0.5, 0.75), rng.uniform(0.35, 0.5)
        else:
            w = d = rng.uniform(0.38, 0.55)
        t = rng.uniform(0.1, 0.18)
        power = rng.uniform(3.0, 5.0)
        body = soft_hull((w / 2, d / 2, t / 2), power=power, flat=0.3)
        # the cord round the seam where the two faces of the cover meet
        piping = [S.tube(_piping_loop(w / 2, d / 2, power, 0.0), pr, sections=8, closed=True)]
    out = [make_part("cover", "cover", body, mat), make_part("piping", "piping", piping, trim)]
    # the care tag sewn into the seam, and the zip that closes the cover
    tag = M.solid((0.97, 0.97, 0.95), "fabric", 0.9)
    if variant == "bolster":
        out.append(make_part("tag", "tag", S.box((0.004, 0.03, 0.05), center=(length / 2 - end + 0.004, radius * 0.2, radius * 0.9)), tag))
        out.append(make_part("zipper", "zipper", S.box((length * 0.6, 0.004, 0.006), center=(0, -radius + 0.004, radius * 0.75)),
                             M.solid((0.3, 0.3, 0.32), "metal", 0.4, 0.6)))
        # the slider's pull tab hanging at the zip's closed end
        out.append(make_part("zip_pull", "zip_pull", S.box((0.008, 0.003, 0.022), center=(length * 0.3 - 0.006, -radius + 0.0035,
                                                                                          radius * 0.75 - 0.013)),
                             M.solid((0.3, 0.3, 0.32), "metal", 0.4, 0.6)))
    else:
        out.append(make_part("tag", "tag", S.box((0.03, 0.05, 0.002), center=(w / 2 - 0.04, -d / 2 - 0.02, 0.001 + pr)), tag))
        out.append(make_part("zipper", "zipper", S.box((w * 0.6, 0.006, 0.004), center=(0, -d / 2 + 0.004, pr + 0.004)),
                             M.solid((0.3, 0.3, 0.32), "metal", 0.4, 0.6)))
        # the slider's pull tab lying flat at the zip's closed end
        out.append(make_part("zip_pull", "zip_pull", S.box((0.022, 0.008, 0.003), center=(w * 0.3 - 0.011, -d / 2 + 0.004,
                                                                                          pr + 0.0075)),
                             M.solid((0.3, 0.3, 0.32), "metal", 0.4, 0.6)))
    return out


def _folded(rng, w: float, d: float, t: float, z0: float, n: int) -> list[S.Shape]:
    """``n`` rounded layers of a folded towel, bottom at ``z0``."""
    lt = t / n
    layers = []
    for k in range(n):
        dx, dy = rng.uniform(-0.004, 0.004, 2)
        layers.append(cushion(w - 0.004 * k, d, lt, (dx, dy, z0 + lt * (k + 0.5)),
                              round_xy=0.02, round_z=lt * 0.45, n=2))
    return layers


@register("towel", parts=("body",), extra_parts=("border", "loop", "tag"), size_range=(0.15, 0.5), density=200,
          variants=("folded", "rolled", "stack"), placement="surface")
def towel(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.fabric(rng)
    band = M.solid(tuple(min(1.0, c * 0.8) for c in mat.color[:3]), "fabric", 0.9)
    tag = M.solid((0.97, 0.97, 0.95), "fabric", 0.9)
    if variant == "rolled":
        length, rad = rng.uniform(0.25, 0.4), rng.uniform(0.045, 0.07)
        body = _roll(length, rad, squash=0.9, flat=0.2)
        # the woven borders showing as bands round the roll near its ends
        zb = float(body.mesh.bounds[1, 2]) / 2
        bands = [make_part(f"border_{k}", "border", S.cylinder(rad * 0.93, 0.02, center=(sx * length * 0.3, 0, zb), axis=(1, 0, 0),
                                                               sections=16), band) for k, sx in enumerate((-1, 1))]
        return [make_part("body", "body", body, mat), *bands]
    w, d = rng.uniform(0.25, 0.38), rng.uniform(0.18, 0.28)
    n = int(rng.integers(3, 5))
    t = rng.uniform(0.012, 0.018) * n
    def details(top: float, k: int) -> list[Part]:
        """The border band across the top layer, the hanging loop folded onto the top and the tag
        at its edge (both inside the towel's footprint, so a towel hung edge-up takes no more
        rail than its cloth)."""
        sfx = "" if k == 0 else f"_{k}"
        return [make_part(f"border{sfx}", "border", S.box((w * 0.9, 0.03, 0.0015), center=(0, d * 0.3, top + 0.0002)), band),
                make_part(f"loop{sfx}", "loop", S.box((0.01, 0.04, 0.003), center=(w / 2 - 0.03, -d / 2 + 0.022, top + 0.0015)), band),
                make_part(f"tag{sfx}", "tag", S.box((0.025, 0.035, 0.0015), center=(-w / 2 + 0.03, -d / 2 + 0.0185, top + 0.00075)), tag)]

    if variant == "folded":
        return [make_part("body", "body", _folded(rng, w, d, t, 0.0, n), mat), *details(t, 0)]
    parts = []
    z = 0.0
    for i in range(int(rng.integers(2, 4))):
        parts.append(make_part("body" if i == 0 else f"body_{i}", "body",
                               _folded(rng, w, d, t, z, n), mat if i % 2 == 0 else M.fabric(rng)))
        z += t
        parts += details(z, i)
    return parts


@register("rug", parts=("body",), extra_parts=("field", "border", "fringe", "medallion", "motif"), size_range=(1.2, 3.5),
          density=300, variants=("rectangular", "round", "runner"), placement="floor",
          groups={"body": ("field", "border", "medallion", "motif")})
def rug(rng: np.random.Generator, variant: str) -> list[Part]:
    t = rng.uniform(0.008, 0.02)
    mat = M.fabric(rng)
    edge = M.fabric(rng)  # the border is woven in another colour
    if variant == "round":
        r = rng.uniform(0.6, 1.2)
        b = r * rng.uniform(0.08, 0.14)
        field = S.cylinder(r - b, t, center=(0, 0, t / 2), sections=48)
        border = ring([(r - b, 0.0), (r - 0.006, 0.0), (r, t * 0.5), (r - 0.006, t), (r - b, t)],
                      sections=48)
        return [make_part("field", "field", field, mat), make_part("border", "border", border, edge),
                make_part("medallion", "medallion", S.cylinder((r - b) * 0.35, 0.0012, center=(0, 0, t - 0.0004), sections=24), edge),
                *[make_part(f"motif_{k}", "motif", S.cylinder((r - b) * 0.08, 0.0012, center=(np.cos(a) * (r - b) * 0.65,
                                                                                           np.sin(a) * (r - b) * 0.65, t - 0.0004),
                                                      sections=8), edge) for k, a in enumerate(np.linspace(0, 2 * np.pi, 8, endpoint=False))]]
    if variant == "runner":
        w, d = rng.uniform(2.0, 3.2), rng.uniform(0.6, 0.9)
    else:
        w = rng.uniform(1.4, 3.2)
        d = w * rng.uniform(0.6, 0.8)
    b = min(w, d) * rng.uniform(0.06, 0.1)
    field = S.box((w - 2 * b, d - 2 * b, t), center=(0, 0, t / 2))
    # four bands framing the field: the long ones run the full width, the short ones fit between
    bands = [bevel_box((w, b, t), center=(0, sy * (d - b) / 2, t / 2), bevel=t / 3) for sy in (-1, 1)]
    bands += [bevel_box((b, d - 2 * b, t), center=(sx * (w - b) / 2, 0, t / 2), bevel=t / 3)
              for sx in (-1, 1)]
    parts = [make_part("field", "field", field, mat), make_part("border", "border", bands, edge)]
    # the woven medallions (three along a runner, one in a rug's centre) and the four corner
    # motifs of the field
    fw, fd = w - 2 * b, d - 2 * b
    rm = min(fw, fd) * 0.22
    xs = (-fw * 0.3, 0.0, fw * 0.3) if variant == "runner" else (0.0,)
    diamond = [(rm, 0), (0, rm * 0.7), (-rm, 0), (0, -rm * 0.7)]
    parts += [make_part("medallion" if k == 0 else f"medallion_{k}", "medallion", S.prism([(x + px, py) for px, py in diamond],
                                                                                         t - 0.001, t + 0.0002), edge)
              for k, x in enumerate(xs)]
    cm = min(fw, fd) * 0.12
    parts += [make_part(f"motif_{k}", "motif", S.prism([(sx * (fw / 2 - cm * 0.2), sy * (fd / 2 - cm * 0.2)),
                                                        (sx * (fw / 2 - cm * 1.2), sy * (fd / 2 - cm * 0.2)),
                                                        (sx * (fw / 2 - cm * 0.2), sy * (fd / 2 - cm * 1.2))], t - 0.001, t + 0.0002), edge)
              for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)])]
    if rng.random() < 0.6:
        fl = rng.uniform(0.04, 0.08)
        fringe_mat = M.solid((0.92, 0.9, 0.84), "fabric", 0.95)
        w_total = w + 2 * fl
        if w_total > 3.5:  # keep the largest extent within the category's range
            fl = (3.5 - w) / 2 - 1e-3
        for i, sx in enumerate((-1, 1)):
            strip = S.box((fl + 0.01, d * 0.96, 0.003), center=(sx * (w / 2 + fl / 2 - 0.005), 0,
                                                               0.0015))
            parts.append(make_part(f"fringe_{i}", "fringe", strip, fringe_mat))
    return parts
