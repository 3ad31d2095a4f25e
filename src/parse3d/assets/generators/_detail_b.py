"""Small real details shared by the household, wall, workshop and tableware families: screw
heads, rubber feet, rings of nozzles or studs, rivets.

Each helper returns :class:`~parse3d.assets.model.Part` objects, one per physical piece (a
screw is a part of its own, as a person points at it), in the asset's canonical frame (+Z up,
front +Y, metres). They draw no random numbers, so adding them leaves the rest of an asset as
it was for the same seed.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from ..model import Material, Part, make_part

__all__ = ["studs", "ring_points", "tufts", "stack", "each"]


def studs(prefix: str, label: str, centers, *, r: float, h: float, mat: Material,
          axis=(0.0, 0.0, 1.0), sections: int = 10, start: int = 0) -> list[Part]:
    """Short cylinders (screw heads, rivets, rubber feet, nozzles, buttons) of radius ``r`` and
    height ``h`` centred at each of ``centers`` (N, 3), along ``axis``; named
    ``<prefix>_<k>`` from ``start``."""
    return [make_part(f"{prefix}_{start + k}", label,
                      S.cylinder(r, h, center=tuple(float(x) for x in c), axis=axis, sections=sections), mat)
            for k, c in enumerate(np.asarray(centers, float).reshape(-1, 3))]


def ring_points(n: int, radius: float, *, center=(0.0, 0.0, 0.0), plane: str = "xy",
                phase: float = 0.0) -> np.ndarray:
    """(n, 3) points evenly spaced on a circle of ``radius`` about ``center`` in the ``xy``
    (horizontal), ``xz`` (facing +Y) or ``yz`` (facing +X) plane."""
    a = phase + np.linspace(0, 2 * np.pi, n, endpoint=False)
    c, s = radius * np.cos(a), radius * np.sin(a)
    z = np.zeros(n)
    uv = {"xy": (c, s, z), "xz": (c, z, s), "yz": (z, c, s)}[plane]
    return np.asarray(center, float) + np.c_[uv]


def tufts(prefix: str, label: str, *, nx: int, ny: int, x0: float, x1: float, y0: float, y1: float,
          z: float, length: float, r: float, mat: Material, down: bool = False) -> list[Part]:
    """A grid of ``nx * ny`` bristle tufts (thin upright cylinders, ``length`` long, radius
    ``r``) rooted at height ``z`` over ``[x0, x1] x [y0, y1]``, growing up (or down)."""
    xs = np.linspace(x0, x1, nx) if nx > 1 else np.array([(x0 + x1) / 2])
    ys = np.linspace(y0, y1, ny) if ny > 1 else np.array([(y0 + y1) / 2])
    zc = z - length / 2 if down else z + length / 2
    pts = [(x, y, zc) for y in ys for x in xs]
    return studs(prefix, label, pts, r=r, h=length, mat=mat, sections=6)


def stack(prefix: str, label: str, *, n: int, size, z0: float, mat: Material,
          center=(0.0, 0.0), start: int = 0) -> list[Part]:
    """``n`` sheets or layers of ``size`` (w, d, t) stacked from ``z0`` (pages of a pad, sheets
    of a ream)."""
    w, d, t = size
    return [make_part(f"{prefix}_{start + k}", label,
                      S.box((w, d, t), center=(center[0], center[1], z0 + t * (k + 0.5))), mat)
            for k in range(n)]


def each(name: str, label: str, shapes, mat: Material) -> list[Part]:
    """One part per shape of ``shapes`` (the wheels, latches or handles of one object, each a
    piece a person points at): the first keeps ``name``, the others are ``<name>_1...``."""
    return [make_part(name if k == 0 else f"{name}_{k}", label, s, mat) for k, s in enumerate(shapes)]
