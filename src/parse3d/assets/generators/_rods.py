"""Straight rods between two points, and bent rods as chains of them.

A rod is a cylinder (its mesh and pieces built from the cached cylinder arrays), about ten
times quicker to make than a two-point ``shapes.tube``, which builds its convex hull anew.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S


def rod(a, b, r: float, sections: int = 8) -> S.Shape:
    """A round rod of radius ``r`` from point ``a`` to point ``b`` (3,), capped flat."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    v = b - a
    length = float(np.linalg.norm(v))
    c = (a + b) / 2
    return S.cylinder(float(r), length, center=(float(c[0]), float(c[1]), float(c[2])),
                      axis=tuple(float(x) for x in v / length), sections=int(sections))


def segments(path, r: float, sections: int = 8) -> list[S.Shape]:
    """A bent rod along ``path`` (N, 3) as straight rods, one per segment (sharp bends keep the
    volume exact: the rods overlap only at the joints)."""
    return [rod(a, b, r, sections) for a, b in zip(path[:-1], path[1:], strict=True)]
