"""Small building blocks shared by the newer families: rotations, legs, feet, slats and the
joints that articulate doors, drawers and lids.

Everything is in the asset's canonical frame (+Z up, front +Y, metres). Joint helpers return
:class:`~parse3d.assets.model.Joint` objects that a generator appends after the parts they move;
the registry collects them into ``Asset.joints`` and recentres them with the parts.
"""

from __future__ import annotations

import numpy as np
import trimesh

from ...geometry import shapes as S
from ..model import Joint, Material, Part, make_part

__all__ = ["rot", "legs4", "feet4", "hinge_parts", "revolute", "prismatic", "mount", "slats",
           "OPEN_DOOR", "DRAWER_TRAVEL"]

#: How far a door or lid opens, radians (about 100 degrees).
OPEN_DOOR = 1.75
#: Fraction of its depth a drawer slides out at its upper limit.
DRAWER_TRAVEL = 0.75


def rot(axis, angle: float) -> np.ndarray:
    """(3, 3) rotation by ``angle`` radians about ``axis`` (3,)."""
    return trimesh.transformations.rotation_matrix(angle, np.asarray(axis, float))[:3, :3]


def legs4(prefix: str, label: str, *, w: float, d: float, h: float, size: float, mat: Material,
          inset: float = 0.0, round_: bool = False, z0: float = 0.0) -> list[Part]:
    """Four legs at the corners of a ``w x d`` footprint, ``h`` tall from ``z0``; ``size`` is the
    leg's width (square) or diameter (round). Named ``<prefix>_0..3`` left-back, right-back,
    left-front, right-front."""
    out = []
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        x, y = sx * (w / 2 - inset - size / 2), sy * (d / 2 - inset - size / 2)
        if round_:
            shp = S.cylinder(size / 2, h, center=(x, y, z0 + h / 2), sections=12)
        else:
            shp = S.box((size, size, h), center=(x, y, z0 + h / 2), bevel=min(0.003, size / 6))
        out.append(make_part(f"{prefix}_{i}", label, shp, mat))
    return out


def feet4(prefix: str, *, w: float, d: float, r: float, h: float, mat: Material,
          inset: float = 0.0) -> list[Part]:
    """Four round feet (glides, pads) of radius ``r`` and height ``h`` standing on z = 0."""
    out = []
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        x, y = sx * (w / 2 - inset - r), sy * (d / 2 - inset - r)
        out.append(make_part(f"{prefix}_{i}", "foot", S.cylinder(r, h, center=(x, y, h / 2), sections=12),
                             mat))
    return out


def hinge_parts(prefix: str, *, x: float, y: float, z0: float, z1: float, mat: Material,
                n: int = 2, radius: float = 0.006, length: float = 0.05, axis: str = "z") -> list[Part]:
    """``n`` hinge barrels on the line through ``(x, y)`` along ``axis`` (``z`` for side-hinged
    doors, ``x`` for lids and flaps, where ``x`` then means the line's z and ``y`` its y), spread
    between ``z0`` and ``z1``. Named ``<prefix>_0..n-1`` with label ``hinge``."""
    out = []
    span = z1 - z0
    for k in range(n):
        t = (k + 0.5) / n if n > 2 else (0.12 if k == 0 else 0.88)
        c = z0 + span * t
        if axis == "z":
            shp = S.cylinder(radius, length, center=(x, y, c), sections=10)
        else:
            shp = S.cylinder(radius, length, center=(c, y, x), axis=(1, 0, 0), sections=10)
        out.append(make_part(f"{prefix}_{k}", "hinge", shp, mat))
    return out


def revolute(name: str, parent: str, child: str, *, axis, origin, opens: float = OPEN_DOOR) -> Joint:
    """A hinge: ``child`` turns about ``axis`` through ``origin`` from 0 (closed) to ``opens``
    radians (negative ``opens`` turns the other way; limits are ordered either way)."""
    a = np.asarray(axis, float)
    a = a / np.linalg.norm(a)
    lim = (0.0, float(opens)) if opens >= 0 else (float(opens), 0.0)
    return Joint(name, "revolute", parent, child, tuple(float(x) for x in a),
                 tuple(float(x) for x in origin), lim)


def prismatic(name: str, parent: str, child: str, *, travel: float, axis=(0.0, 1.0, 0.0),
              origin=(0.0, 0.0, 0.0)) -> Joint:
    """A slide: ``child`` moves along ``axis`` from 0 (closed) to ``travel`` metres."""
    a = np.asarray(axis, float)
    a = a / np.linalg.norm(a)
    return Joint(name, "prismatic", parent, child, tuple(float(x) for x in a),
                 tuple(float(x) for x in origin), (0.0, float(travel)))


def mount(parent: str, child: str) -> Joint:
    """Rigidly mount ``child`` (a handle, a pane, a knob) on a moving ``parent`` part."""
    return Joint(f"{child}_mount", "prismatic", parent, child, (0.0, 0.0, 1.0), (0.0, 0.0, 0.0),
                 (0.0, 0.0))


def slats(prefix: str, label: str, *, n: int, x0: float, x1: float, z0: float, z1: float, y: float,
          thick: float, mat: Material, vertical: bool = False, gap_frac: float = 0.35,
          start: int = 0) -> list[Part]:
    """``n`` slats in the plane y = ``y`` across ``[x0, x1] x [z0, z1]``: horizontal boards
    stacked in z (or vertical ones side by side in x), a ``gap_frac`` share of the span open."""
    out = []
    if vertical:
        pitch = (x1 - x0) / n
        sw = pitch * (1 - gap_frac)
        for k in range(n):
            cx = x0 + pitch * (k + 0.5)
            out.append(make_part(f"{prefix}_{start + k}", label,
                                 S.box((sw, thick, z1 - z0), center=(cx, y, (z0 + z1) / 2)), mat))
    else:
        pitch = (z1 - z0) / n
        sh = pitch * (1 - gap_frac)
        for k in range(n):
            cz = z0 + pitch * k + sh / 2
            out.append(make_part(f"{prefix}_{start + k}", label,
                                 S.box((x1 - x0, thick, sh), center=((x0 + x1) / 2, y, cz)), mat))
    return out
