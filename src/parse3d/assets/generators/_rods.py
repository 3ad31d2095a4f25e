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


def leg_caps(parts, *, label: str, mat, height: float = 0.03, grow: float = 0.002,
             legs: tuple[str, ...] = ("leg",)) -> list:
    """A cap (rubber shoe, brass ferrule) sleeving the foot of each leg that stands on the floor.

    Each cap wraps the leg's bottom ``height`` metres, ``grow`` thicker than the leg all round,
    standing on z = 0 like the leg, so nothing is lifted; a round foot gets a 10-sided sleeve,
    any other a box. Caps never reach past the bounds of ``parts`` (the asset keeps its size).

    Parameters
    ----------
    parts : list
        The asset's parts so far (joints mixed in are ignored).
    label : str
        The caps' label; they are named ``label_k`` in the order of their legs.
    legs : tuple of str
        Labels of the parts that are legs.
    """
    from ..model import Part, make_part

    solids = [p for p in parts if isinstance(p, Part)]
    lo = np.min([p.bounds[0] for p in solids], axis=0)
    hi = np.max([p.bounds[1] for p in solids], axis=0)
    out = []
    for p in solids:
        if p.label not in legs or p.bounds[0, 2] > 1e-4:
            continue
        v = np.asarray(p.mesh.vertices, float)
        foot = v[v[:, 2] < p.bounds[0, 2] + 1e-4][:, :2]
        if len(foot) < 3:
            continue
        c = (foot.min(axis=0) + foot.max(axis=0)) / 2
        ext = foot.max(axis=0) - foot.min(axis=0)
        h = min(height, 0.25 * float(p.bounds[1, 2] - p.bounds[0, 2]))
        if len(foot) >= 8 and abs(ext[0] - ext[1]) < 0.1 * ext.max():  # round
            r = min(float(np.linalg.norm(foot - c, axis=1).max()) + grow,
                    *(c - lo[:2]), *(hi[:2] - c))
            shape = S.cylinder(r, h, center=(float(c[0]), float(c[1]), h / 2), sections=10)
        else:
            a = np.maximum(foot.min(axis=0) - grow, lo[:2])
            b = np.minimum(foot.max(axis=0) + grow, hi[:2])
            shape = S.box((float(b[0] - a[0]), float(b[1] - a[1]), h),
                          center=(float(a[0] + b[0]) / 2, float(a[1] + b[1]) / 2, h / 2))
        out.append(make_part(f"{label}_{len(out)}", label, shape, mat))
    return out
