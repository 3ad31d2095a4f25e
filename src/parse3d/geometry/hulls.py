"""Convex hulls of 2-D point sets without qhull.

The solver takes a hull of a few dozen projected points many times per object, and a whole
``parse3d solve`` command would otherwise import ``scipy.spatial`` (about a third of a second
of start-up) for it. Andrew's monotone chain is as fast as setting up qhull for such sets and
needs numpy only.

Like qhull, the result drops points that lie on an edge within rounding: after the exact
chain, vertices whose turn is below ``rel_tol`` times the points' magnitude are removed, so
the mesh seams and subdivided edges that a rotation leaves a hair off a straight line do not
become vertices of zero angle (whose edge normals would be noise).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["hull_indices_2d"]

#: Turns (as a distance relative to the points' magnitude, at least 1 m) below which a hull
#: vertex counts as lying on the line through its neighbours.
REL_TOL = 1e-12


#: Point counts from which points well inside the extreme points' quadrilateral are dropped
#: before the chain (a vectorised test; the chain itself runs in Python).
_PREFILTER = 64


def _outside_extremes(pts: np.ndarray, margin: float) -> np.ndarray:
    """Indices of the points not inside the quadrilateral of the leftmost, lowest, rightmost
    and highest points by more than ``margin`` (those cannot be hull vertices)."""
    ext = [int(np.argmin(pts[:, 0])), int(np.argmin(pts[:, 1])), int(np.argmax(pts[:, 0])),
           int(np.argmax(pts[:, 1]))]
    quad = pts[[i for k, i in enumerate(ext) if i != ext[k - 1]]]
    if len(quad) < 3:
        return np.arange(len(pts))
    inside = np.ones(len(pts), bool)
    for a, b in zip(quad, np.roll(quad, -1, axis=0), strict=True):
        e = b - a
        cross = e[0] * (pts[:, 1] - a[1]) - e[1] * (pts[:, 0] - a[0])
        inside &= cross > margin * math.hypot(e[0], e[1])
    return np.flatnonzero(~inside)


def hull_indices_2d(points2d: np.ndarray, *, rel_tol: float = REL_TOL) -> np.ndarray | None:
    """Indices of the convex hull vertices of (N, 2) points, counter-clockwise.

    Parameters
    ----------
    points2d : (N, 2) float
    rel_tol : float
        A vertex whose distance from the line through its two neighbours is at most
        ``rel_tol * max(1, max |coordinate|)`` is dropped (collinear within rounding).

    Returns
    -------
    (K,) int array, K >= 3, or None
        None when the points span no area (fewer than three distinct points, all on one line,
        or not finite), where qhull would raise.

    >>> hull_indices_2d(np.array([[0, 0], [1, 0], [0.5, 0], [1, 1], [0, 1], [0.5, 0.5]])).tolist()
    [0, 1, 3, 4]
    """
    pts = np.asarray(points2d, float)
    if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 3 or not np.isfinite(pts).all():
        return None
    tol = rel_tol * max(float(np.abs(pts).max()), 1.0)
    cand = _outside_extremes(pts, 1e3 * tol) if len(pts) >= _PREFILTER else np.arange(len(pts))
    order = cand[np.lexsort((pts[cand, 1], pts[cand, 0]))]
    p = pts[order]
    keep = np.ones(len(p), bool)
    keep[1:] = np.any(p[1:] != p[:-1], axis=1)
    idx = order[keep].tolist()
    if len(idx) < 3:
        return None
    P = pts.tolist()

    def chain(seq: list[int]) -> list[int]:
        out: list[int] = []
        for i in seq:
            qx, qy = P[i]
            while len(out) >= 2:
                ax, ay = P[out[-2]]
                bx, by = P[out[-1]]
                if (bx - ax) * (qy - ay) - (by - ay) * (qx - ax) > 0:
                    break
                out.pop()
            out.append(i)
        return out

    hull = chain(idx)[:-1] + chain(idx[::-1])[:-1]
    changed = True
    while changed and len(hull) >= 3:
        changed = False
        k = 0
        while len(hull) >= 3 and k < len(hull):
            ax, ay = P[hull[k - 1]]
            bx, by = P[hull[k]]
            cx, cy = P[hull[(k + 1) % len(hull)]]
            ex, ey = cx - ax, cy - ay
            if (bx - ax) * ey - (by - ay) * ex <= tol * math.hypot(ex, ey):
                del hull[k]
                changed = True
            else:
                k += 1
    if len(hull) < 3:
        return None
    return np.array(hull, dtype=np.intp)
