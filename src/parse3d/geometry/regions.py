"""2D feasible regions in a support plane: Minkowski erosion, clipping and uniform sampling.

Regions are shapely geometries in a plane's (u, v) coordinates. A region may be polygonal
(2D), a set of segments (after a line constraint) or a set of points (after two).
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.errors import GEOSException
from shapely.geometry import LineString, MultiPoint, Point, Polygon
from shapely.geometry import box as shapely_box
from shapely.geometry.base import BaseGeometry

from .hulls import hull_indices_2d
from .memo import per_object

#: Precision grid (m) of region overlays: snapping makes GEOS's overlay robust to nearly
#: coincident vertices that different computations of the same edge produce.
GRID = 1e-9

__all__ = [
    "GRID",
    "clip",
    "one_dimension",
    "minkowski_convex",
    "erode",
    "eroded_area",
    "free_samples",
    "draw_outside",
    "half_plane",
    "strip",
    "line",
    "disk",
    "sample_uniform",
    "convex_footprint",
    "convex_outline",
    "inside_convex",
]


def inside_convex(poly: np.ndarray, p, tol: float = 0.0) -> bool:
    """Whether point ``p`` lies in the convex CCW polygon ``poly`` (K, 2), within ``tol``."""
    e = np.roll(poly, -1, axis=0) - poly
    d = p - poly
    cross = e[:, 0] * d[:, 1] - e[:, 1] * d[:, 0]
    return bool(np.all(cross >= -tol * np.linalg.norm(e, axis=1)))


def convex_footprint(points2d: np.ndarray) -> np.ndarray:
    """(K, 2) convex hull vertices of (N, 2) points, counter-clockwise."""
    pts = np.asarray(points2d, float)
    idx = hull_indices_2d(pts)
    if idx is not None:
        return pts[idx]
    # degenerate (collinear) point sets
    hull = MultiPoint(pts).convex_hull.buffer(1e-4)
    return np.asarray(hull.exterior.coords)[:-1]


def convex_outline(points2d: np.ndarray, idx: np.ndarray | None) -> np.ndarray:
    """(K, 2) counter-clockwise convex hull of (N, 2) points whose hull vertices are known to be
    ``points2d[idx]`` in hull order (either way round), as :func:`convex_footprint` gives it up
    to the starting vertex; with ``idx`` None, :func:`convex_footprint` of all the points."""
    if idx is None:
        return convex_footprint(points2d)
    p = np.asarray(points2d, float)[idx]
    x, y = p[:, 0], p[:, 1]
    twice_area = float(x[:-1] @ y[1:] - x[1:] @ y[:-1] + x[-1] * y[0] - x[0] * y[-1])
    return p if twice_area > 0 else p[::-1]


def minkowski_sum_convex(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """(K, 2) vertices of the Minkowski sum of two convex CCW polygons, by merging edges."""
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    a = np.roll(a, -int(np.lexsort((a[:, 0], a[:, 1]))[0]), axis=0)
    b = np.roll(b, -int(np.lexsort((b[:, 0], b[:, 1]))[0]), axis=0)
    ea = np.roll(a, -1, axis=0) - a
    eb = np.roll(b, -1, axis=0) - b
    e = np.vstack([ea, eb])
    ang = np.mod(np.arctan2(e[:, 1], e[:, 0]), 2 * np.pi)
    order = np.argsort(ang, kind="stable")
    pts = (a[0] + b[0]) + np.vstack([[0.0, 0.0], np.cumsum(e[order], axis=0)[:-1]])
    return pts


def minkowski_many(polys: list[np.ndarray], b: np.ndarray) -> list[np.ndarray]:
    """Minkowski sums of many convex CCW polygons with one convex CCW polygon ``b``.

    Vectorised edge merge: every sum's edges are its polygon's edges and ``b``'s, sorted by
    angle, walked from the sum of the two bottom-most vertices.
    """
    if not polys:
        return []
    pts, total = _minkowski_stack(polys, b)
    return np.split(pts, np.cumsum(total)[:-1])


def _minkowski_stack(polys: list[np.ndarray], b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The sums of :func:`minkowski_many` stacked: their vertices (V, 2), one sum after the
    other, and the vertex count of each."""
    b = np.asarray(b, float)
    ib = int(np.lexsort((b[:, 0], b[:, 1]))[0])
    b = np.concatenate([b[ib:], b[:ib]])
    eb = np.concatenate([b[1:], b[:1]]) - b
    ab = np.mod(np.arctan2(eb[:, 1], eb[:, 0]), 2 * np.pi)
    counts = np.array([len(p) for p in polys])
    A = np.vstack(polys).astype(float)
    gid = np.repeat(np.arange(len(polys)), counts)
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
    # next vertex within each polygon
    nxt = np.arange(len(A)) + 1
    nxt[starts + counts - 1] = starts
    ea = A[nxt] - A
    aa = np.mod(np.arctan2(ea[:, 1], ea[:, 0]), 2 * np.pi)
    # bottom-most vertex of each polygon (min y, then min x)
    order = np.lexsort((A[:, 0], A[:, 1], gid))
    first = order[np.searchsorted(gid[order], np.arange(len(polys)))]
    # angles measured from each polygon's start so the walk begins at its bottom vertex
    m = len(b)
    E = np.vstack([ea, np.tile(eb, (len(polys), 1))])
    ang = np.concatenate([aa, np.tile(ab, len(polys))])
    g = np.concatenate([gid, np.repeat(np.arange(len(polys)), m)])
    srt = np.lexsort((ang, g))
    E = E[srt]
    g = g[srt]
    csum = np.cumsum(E, axis=0)
    total = counts + m
    gstart = np.concatenate([[0], np.cumsum(total)[:-1]])
    base = np.where(gstart[:, None] > 0, csum[np.maximum(gstart - 1, 0)], 0.0)
    pts = csum - base[g] - E + (A[first] + b[0])[g]
    return pts, total


def minkowski_convex(a: np.ndarray, b: np.ndarray) -> Polygon:
    """Minkowski sum of two convex point sets (N, 2) and (M, 2) as a polygon."""
    return Polygon(minkowski_sum_convex(convex_footprint(a), convex_footprint(b)))


def _cut(a: tuple, b: tuple, da: float, db: float) -> tuple:
    """The point where segment ``a``-``b`` crosses a line, from their signed distances."""
    f = da / (da - db)
    return (a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f)


def _erode_convex(poly: Polygon, neg: np.ndarray) -> BaseGeometry:
    """Erosion of a convex polygon by a footprint: each edge moves in by the footprint's
    support along the edge's outward normal."""
    rect, n, cn = _convex_edges(poly)
    if rect is not None:  # an axis-aligned rectangle (a floor, a tabletop, a shelf) shrinks per axis
        lo, hi = rect
        f = -neg  # the footprint
        lo2, hi2 = lo - f.min(axis=0), hi - f.max(axis=0)
        if (hi2 > lo2).all():
            return shapely_box(lo2[0], lo2[1], hi2[0], hi2[1])
        return Polygon()
    shift = np.max(-neg @ n.T, axis=0)  # support of the footprint (F = -neg) along n
    off = cn - shift
    # few edges: clipping on Python floats is cheaper than numpy's per-call overhead
    got = _half_planes(n, off) if len(n) > HALF_PLANES_FROM else None
    return got if got is not None else _clip_box(poly, n, off)


@per_object()
def _convex_edges(poly: Polygon) -> tuple:
    """``(rect, n, cn)`` of a convex polygon: ``rect`` its ``(lo, hi)`` corners when it is an
    axis-aligned rectangle (else None), otherwise the outward unit normals ``n`` (E, 2) of its
    counter-clockwise edges and each edge's offset ``cn`` (E,) along its normal. Kept per
    polygon object (a support's region is eroded again and again)."""
    c = np.asarray(poly.exterior.coords)[:-1]
    out = None
    if len(c) == 4:
        e = np.roll(c, -1, axis=0) - c
        if np.all(np.min(np.abs(e), axis=1) < 1e-12):
            out = ((c.min(axis=0), c.max(axis=0)), None, None)
    if out is None:
        if not Polygon(c).exterior.is_ccw:
            c = c[::-1]
        e = np.roll(c, -1, axis=0) - c
        n = np.c_[e[:, 1], -e[:, 0]]  # outward normal of a CCW ring
        n /= np.linalg.norm(n, axis=1, keepdims=True)
        out = (None, n, np.einsum("ij,ij->i", c, n))
    for a in (*(out[0] or ()), *out[1:]):
        if a is not None:
            a.flags.writeable = False  # shared by every erosion of the polygon
    return out


@per_object()
def _one_convex(region: BaseGeometry) -> bool:
    """Whether ``region`` is one convex polygon without holes, of at most 64 vertices (the
    case :func:`erode` moves edges for); kept per region object."""
    polys = list(region.geoms) if hasattr(region, "geoms") else [region]
    out = bool(len(polys) == 1 and isinstance(polys[0], Polygon) and not polys[0].interiors
               and len(polys[0].exterior.coords) <= 64
               and polys[0].convex_hull.area - polys[0].area < 1e-9 * max(polys[0].area, 1.0))
    return out


#: Edge count from which a convex erosion is vectorised (:func:`_half_planes`).
HALF_PLANES_FROM = 16


def _ring(p: np.ndarray) -> BaseGeometry:
    """A polygon through the points ``p`` (in order), repeated vertices dropped."""
    keep = np.hypot(*(p - np.roll(p, 1, axis=0)).T) > 1e-12
    p = p[keep] if keep.any() else p[:1]
    if len(p) < 3:
        return Polygon()
    out = Polygon(p)
    return out if out.is_valid and out.area > 0 else Polygon()


def _half_planes(n: np.ndarray, off: np.ndarray, tol: float = 1e-9) -> BaseGeometry | None:
    """The polygon ``{x : n_i . x <= off_i for all i}`` for unit normals ``n`` (m, 2) in
    counter-clockwise order (a convex polygon's edges, moved); None when this cannot tell.

    Its vertices are the crossings of neighbouring lines; a line whose edge would have
    negative length is redundant (its edge vanished in the erosion) and is dropped, and the
    crossings are recomputed. The result is exact when every vertex lies in every half-plane
    (checked): then the polygon is the intersection. Vectorised: a few numpy calls per round
    rather than a clipping loop per edge.
    """
    keep = np.arange(len(n))
    for _ in range(len(n)):
        if len(keep) < 3:
            return Polygon()
        a, oa = n[keep], off[keep]
        b, ob = np.roll(a, -1, axis=0), np.roll(oa, -1)
        det = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
        if np.any(det <= 1e-12):  # a turn of half a circle or more between two lines
            return None
        p = np.c_[(oa * b[:, 1] - ob * a[:, 1]) / det, (a[:, 0] * ob - b[:, 0] * oa) / det]
        # length of each line's edge: from the previous crossing to the next, along the line
        d = p - np.roll(p, 1, axis=0)
        length = d[:, 1] * a[:, 0] - d[:, 0] * a[:, 1]
        if np.all(length >= -tol):
            inside = (p[:, None, 0] * n[None, :, 0] + p[:, None, 1] * n[None, :, 1]
                      - off[None, :]) <= tol
            return _ring(p) if inside.all() else None
        # drop the lines of negative length that are not next to a shorter one
        worst = (length < -tol) & (length <= np.roll(length, 1)) & (length <= np.roll(length, -1))
        keep = keep[~worst]
    return None


def _clip_box(poly: Polygon, n: np.ndarray, off: np.ndarray) -> BaseGeometry:
    """The half-planes of :func:`_half_planes` clipped from ``poly``'s bounding box one by one
    (the fallback where that cannot tell)."""
    # clip a big box by every half-plane {x : x . n <= off} (Sutherland-Hodgman on Python
    # floats: a few dozen vertices, where numpy's per-call overhead would dominate)
    x0, y0, x1, y1 = poly.bounds
    pts = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    for (nx, ny), oi in zip(n.tolist(), off.tolist(), strict=True):
        if not pts:
            break
        d = [px * nx + py * ny - oi for px, py in pts]
        nxt = []
        for k in range(len(pts)):
            j = k - 1
            dk, dj = d[k], d[j]
            if dk <= 1e-12:
                if dj > 1e-12:
                    nxt.append(_cut(pts[j], pts[k], dj, dk))
                nxt.append(pts[k])
            elif dj <= 1e-12:
                nxt.append(_cut(pts[j], pts[k], dj, dk))
        if nxt:  # drop repeated vertices
            kept = [q for q, r in zip(nxt, nxt[-1:] + nxt[:-1], strict=True)
                    if math.hypot(q[0] - r[0], q[1] - r[1]) > 1e-12]
            nxt = kept if kept else nxt[:1]
        pts = nxt
    if len(pts) < 3:
        return Polygon()
    out = Polygon(pts)
    return out if out.is_valid and out.area > 0 else Polygon()


def eroded_area(region: BaseGeometry, footprint: np.ndarray) -> float:
    """Area of ``erode(region, [], footprint)``: for an axis-aligned rectangle (a tabletop, a
    shelf) the product of its sides less the footprint's extents, without a polygon."""
    if _one_convex(region):
        poly = region.geoms[0] if hasattr(region, "geoms") else region
        rect = _convex_edges(poly)[0]
        if rect is not None:
            lo, hi = rect
            f = np.asarray(footprint, float)
            w = (hi - lo) - (f.max(axis=0) - f.min(axis=0))
            return float(w[0] * w[1]) if (w > 0).all() else 0.0
    return float(erode(region, [], footprint).area)


def erode(region: BaseGeometry, obstacles: list[np.ndarray], footprint: np.ndarray) -> BaseGeometry:
    """Positions ``p`` where ``p + footprint`` lies inside ``region`` and misses every obstacle.

    Parameters
    ----------
    region : shapely Polygon or MultiPolygon
        Where the footprint must stay.
    obstacles : list of (K, 2) arrays
        Convex obstacles (occupied footprints).
    footprint : (F, 2) array
        Convex footprint of the object relative to its reference point (which should lie
        inside the footprint, so that the boundary sweep below is exact).

    Returns
    -------
    shapely geometry
        The feasible set of reference points (possibly empty).
    """
    neg = -np.asarray(footprint, float)
    cut = []
    polys = list(region.geoms) if hasattr(region, "geoms") else [region]
    if _one_convex(region):
        inner = _erode_convex(polys[0], neg)
        polys = []
    else:
        inner = None
    for poly in polys:
        if poly.is_empty or not isinstance(poly, Polygon):
            continue
        for ring in [poly.exterior, *poly.interiors]:
            c = np.asarray(ring.coords)
            seg = np.stack([c[:-1], c[1:]], axis=1)  # (E, 2, 2)
            pts = (seg[:, :, None, :] + neg[None, None, :, :]).reshape(len(seg), -1, 2)
            cut.extend(shapely.convex_hull(shapely.multipoints(pts)))
    if obstacles:
        negf = neg if _strictly_convex_ccw(neg) else convex_footprint(neg)
        # only obstacles whose sum can reach the region matter (others on a far-away table):
        # every obstacle's box at once
        x0, y0, x1, y1 = region.bounds
        lo, hi = negf.min(axis=0), negf.max(axis=0)
        A = np.concatenate(obstacles)
        at = np.concatenate([[0], np.cumsum([len(ob) for ob in obstacles])[:-1]])
        olo, ohi = np.minimum.reduceat(A, at), np.maximum.reduceat(A, at)
        hit = ((olo[:, 0] + lo[0] <= x1) & (ohi[:, 0] + hi[0] >= x0)
               & (olo[:, 1] + lo[1] <= y1) & (ohi[:, 1] + hi[1] >= y0))
        obstacles = [obstacles[k] for k in np.flatnonzero(hit)]
    if obstacles:
        # the sums as closed rings, one after the other: each one's first vertex repeated
        pts, total = _minkowski_stack(obstacles, negf)
        ends = np.cumsum(total)
        ring = np.insert(np.arange(len(pts)), ends, ends - total)
        idx = np.repeat(np.arange(len(total)), total + 1)
        cut.extend(shapely.polygons(shapely.linearrings(pts[ring], indices=idx)))
    base = inner if inner is not None else region
    if not cut or base.is_empty:
        return base
    try:
        blocked = shapely.union_all(cut)
    except GEOSException:
        # a sum ring that crosses itself (an obstacle outline folded back on itself): its
        # valid form, snapped to the grid, covers the same ground
        blocked = shapely.union_all(shapely.make_valid(np.asarray(cut, dtype=object)),
                                    grid_size=GRID)
    return shapely.difference(base, blocked, grid_size=GRID)


#: Batches of draws :func:`free_samples` tries before leaving the region to be built.
FREE_SAMPLE_ROUNDS = 6
#: Draws after which :func:`free_samples` and :func:`draw_outside` give up when none was free.
EMPTY_AFTER = 600


@per_object()
def _convex_half_planes(poly: Polygon) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """``(N, c, bounds)`` of a convex polygon: outward unit edge normals (E, 2) and offsets
    (E,) with the polygon ``{x : N x <= c}``, and its bounds (4,); None when ``poly`` is not
    one convex polygon. Cached per polygon object (a support's region is asked for again and
    again)."""
    hp = None
    if (isinstance(poly, Polygon) and not poly.is_empty and not poly.interiors
            and len(poly.exterior.coords) <= 64
            and poly.convex_hull.area - poly.area <= 1e-9 * max(poly.area, 1.0)):
        v = shapely.get_coordinates(poly.exterior)[:-1]
        if not poly.exterior.is_ccw:
            v = v[::-1]
        e = np.concatenate([v[1:], v[:1]]) - v
        keep = np.hypot(e[:, 0], e[:, 1]) > 1e-12
        v, e = v[keep], e[keep]
        nrm = np.column_stack([e[:, 1], -e[:, 0]]) / np.hypot(e[:, 0], e[:, 1])[:, None]
        hp = (nrm, np.einsum("ij,ij->i", nrm, v), np.array(poly.bounds))
    return hp


def free_samples(region: BaseGeometry, obstacles: list[np.ndarray], footprint: np.ndarray,
                 rng: np.random.Generator, n: int, *, margin: float = 0.0) -> np.ndarray | None:
    """(n, 2) positions uniform over ``erode(region, obstacles, footprint)`` shrunk by
    ``margin``, drawn without building that region; None when this cannot tell cheaply.

    For a convex ``region`` the eroded region is a convex polygon (the region's edges moved in
    by the footprint's extent along their normals) less the obstacles grown by the footprint
    (convex too): positions are drawn uniformly in a box holding the polygon and kept when
    inside it and outside every grown obstacle, in one vectorised test per batch. ``margin`` >
    0 keeps positions that far from the region's edge and the obstacles (the footprint grown
    by a 32-gon of that radius, as a buffer would approximate it).

    None when ``region`` is not one convex polygon, or when :data:`FREE_SAMPLE_ROUNDS` batches
    did not find ``n`` positions (the free space is empty or a small share of the box: build
    the region with :func:`erode`, which tells which, and sample it instead).
    """
    hp = _convex_half_planes(region)
    if hp is None:
        return None
    N0, c0, (x0, y0, x1, y1) = hp
    neg = -np.asarray(footprint, float)
    neg = neg if _strictly_convex_ccw(neg) else convex_footprint(neg)
    if margin > 0:
        neg = minkowski_sum_convex(neg, margin * _UNIT_32GON)
    # p + F inside the region: each edge moved in by the footprint's support along its normal
    c0 = c0 - (-neg @ N0.T).max(axis=0)
    lo, hi = neg.min(axis=0), neg.max(axis=0)
    x0, y0, x1, y1 = x0 + hi[0], y0 + hi[1], x1 + lo[0], y1 + lo[1]
    if x1 <= x0 or y1 <= y0:
        return None
    N, c = N0, c0
    if obstacles:
        # only obstacles whose grown box meets the box matter
        counts = [len(ob) for ob in obstacles]
        A = np.concatenate(obstacles)
        at = np.concatenate([[0], np.cumsum(counts)[:-1]])
        olo = np.minimum.reduceat(A, at) + lo
        ohi = np.maximum.reduceat(A, at) + hi
        hit = (olo[:, 0] < x1) & (ohi[:, 0] > x0) & (olo[:, 1] < y1) & (ohi[:, 1] > y0)
        grown = [obstacles[k] for k in np.flatnonzero(hit)]
    else:
        grown = []
    # every grown obstacle as half-planes too: inside it when inside all of its edges
    test = _GrownTest(grown, neg) if grown else None

    def batch(m: int) -> tuple[np.ndarray, np.ndarray]:
        P = np.empty((m, 2))
        P[:, 0] = x0 + rng.random(m) * (x1 - x0)
        P[:, 1] = y0 + rng.random(m) * (y1 - y0)
        ok = ((P @ N.T - c) <= 0).all(axis=1)
        if test is not None:
            ok &= ~test.inside(P)
        return P, ok

    return _kept_draws(batch, n, FREE_SAMPLE_ROUNDS)


def _kept_draws(batch, n: int, rounds: int) -> np.ndarray | None:
    """The first ``n`` positions kept from batches of draws, ``batch(m) -> (P, ok)``, each
    batch sized by the share kept so far; None when ``rounds`` batches did not keep ``n``, or
    :data:`EMPTY_AFTER` draws kept none (the built region then tells why)."""
    out, have, drawn = [], 0, 0
    for _ in range(rounds):
        rate = max(have / drawn, 0.05) if drawn else 0.5
        m = int(math.ceil((n - have) / rate * 1.25)) + 4
        P, ok = batch(m)
        drawn += m
        if ok.any():
            out.append(P[ok])
            have += int(ok.sum())
        if have >= n:
            return np.concatenate(out)[:n]
        if not have and drawn >= EMPTY_AFTER:
            return None  # (nearly) nothing free
    return None


def draw_outside(region: BaseGeometry, obstacles: list[np.ndarray], footprint: np.ndarray,
                 rng: np.random.Generator, n: int, rounds: int = FREE_SAMPLE_ROUNDS
                 ) -> np.ndarray | None:
    """(n, 2) positions uniform over ``region`` less the obstacles grown by the footprint,
    drawn without building that set; None when ``rounds`` batches did not find ``n``.

    ``region`` holds positions already (a support eroded by the footprint and clipped by
    relations): polygons (drawn by area, from their bounding box), segments (by length) or
    points. A draw is kept when it lies in no obstacle's Minkowski sum with the footprint (one
    vectorised half-plane test per batch), so the positions are those of :func:`erode` of the
    support by the obstacles, clipped the same way, as a set.
    """
    if region.is_empty:
        return None
    neg = -np.asarray(footprint, float)
    neg = neg if _strictly_convex_ccw(neg) else convex_footprint(neg)
    x0, y0, x1, y1 = region.bounds
    parts = list(region.geoms) if hasattr(region, "geoms") else [region]
    areal = [g for g in parts if g.area > 1e-12]
    segs = None
    if not areal:
        linear = [g for g in parts if g.length > 1e-12]
        if linear:
            c = [shapely.get_coordinates(ls) for g in linear
                 for ls in (g.geoms if hasattr(g, "geoms") else [g])]
            segs = np.concatenate([np.stack([p[:-1], p[1:]], axis=1) for p in c])
            ln = np.hypot(*(segs[:, 1] - segs[:, 0]).T)
            cum = np.cumsum(ln) / ln.sum()
        else:
            pts = np.array([shapely.get_coordinates(g)[0] for g in parts if not g.is_empty])
    else:
        geom = areal[0] if len(areal) == 1 else shapely.MultiPolygon(
            [p for g in areal for p in (g.geoms if hasattr(g, "geoms") else [g])])
        shapely.prepare(geom)
    # only obstacles whose grown box meets the region's box matter
    lo, hi = neg.min(axis=0), neg.max(axis=0)
    grown = []
    if obstacles:
        A = np.concatenate(obstacles)
        at = np.concatenate([[0], np.cumsum([len(ob) for ob in obstacles])[:-1]])
        olo = np.minimum.reduceat(A, at) + lo
        ohi = np.maximum.reduceat(A, at) + hi
        hit = (olo[:, 0] <= x1) & (ohi[:, 0] >= x0) & (olo[:, 1] <= y1) & (ohi[:, 1] >= y0)
        grown = [obstacles[k] for k in np.flatnonzero(hit)]
    test = None
    if grown:
        test = _GrownTest(grown, neg)
        if segs is not None:  # the free pieces of the segments, exactly
            segs = _segments_outside(segs, test.N, test.c)
            test = None
            if not len(segs):
                return None
            ln = np.hypot(*(segs[:, 1] - segs[:, 0]).T)
            cum = np.cumsum(ln) / ln.sum()
            grown = []

    def batch(m: int) -> tuple[np.ndarray, np.ndarray]:
        if areal:
            P = np.empty((m, 2))
            P[:, 0] = x0 + rng.random(m) * (x1 - x0)
            P[:, 1] = y0 + rng.random(m) * (y1 - y0)
            ok = shapely.contains_xy(geom, P[:, 0], P[:, 1])
        elif segs is not None:
            k = np.minimum(np.searchsorted(cum, rng.random(m)), len(segs) - 1)
            t = rng.random(m)[:, None]
            P = segs[k, 0] + t * (segs[k, 1] - segs[k, 0])
            ok = np.ones(m, bool)
        else:
            P = pts[rng.integers(len(pts), size=m)]
            ok = np.ones(m, bool)
        if test is not None:
            ok &= ~test.inside(P)
        return P, ok

    return _kept_draws(batch, n, rounds)


class _GrownTest:
    """Which points lie strictly inside some obstacle grown by a footprint.

    The Minkowski sum of a convex obstacle ``O`` and the convex ``-F`` is the intersection of
    the half-planes ``n . x < h_O(n) + h_-F(n)`` over the edge normals ``n`` of both (``h`` a
    support function): no sum is built. Each obstacle's rows are padded to one width (rows
    that hold everywhere), and a point is tested only against the obstacles whose box (the
    obstacle's box grown by the footprint's) holds it.
    """

    def __init__(self, grown: list[np.ndarray], neg: np.ndarray):
        counts = np.array([len(o) for o in grown])
        A = np.concatenate(grown).astype(float, copy=False)
        starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
        nxt = np.arange(1, len(A) + 1)
        nxt[starts + counts - 1] = starts
        E = A[nxt] - A
        No = np.column_stack([E[:, 1], -E[:, 0]])  # outward normals of counter-clockwise rings
        co = (No * A).sum(axis=1) + (No @ neg.T).max(axis=1)
        flat = np.abs(E).max(axis=1) < 1e-12  # repeated vertices: no constraint
        No[flat], co[flat] = 0.0, 1.0
        Ef = np.roll(neg, -1, axis=0) - neg
        Nf = np.column_stack([Ef[:, 1], -Ef[:, 0]])
        keep = np.abs(Ef).max(axis=1) >= 1e-12
        Nf = Nf[keep]
        cf = np.maximum.reduceat(A @ Nf.T, starts, axis=0) + (Nf * neg[keep]).sum(axis=1)
        K, W = len(counts), int(counts.max())
        self.N = np.zeros((K, W + len(Nf), 2))
        self.c = np.ones((K, W + len(Nf)))
        g = np.repeat(np.arange(K), counts)
        j = np.arange(len(A)) - np.repeat(starts, counts)
        self.N[g, j], self.c[g, j] = No, co
        self.N[:, W:], self.c[:, W:] = Nf, cf
        self.lo = np.minimum.reduceat(A, starts) + neg.min(axis=0)
        self.hi = np.maximum.reduceat(A, starts) + neg.max(axis=0)

    def inside(self, P: np.ndarray) -> np.ndarray:
        lo, hi = self.lo, self.hi
        x, y = P[:, 0:1], P[:, 1:2]
        box = (x >= lo[:, 0]) & (x <= hi[:, 0]) & (y >= lo[:, 1]) & (y <= hi[:, 1])
        pi, ki = np.nonzero(box)
        out = np.zeros(len(P), bool)
        if len(pi):
            Nk = self.N[ki]
            S = P[pi, 0:1] * Nk[:, :, 0] + P[pi, 1:2] * Nk[:, :, 1] - self.c[ki]
            out[pi[(S < 0).all(axis=1)]] = True
        return out


def _segments_outside(segs: np.ndarray, N: np.ndarray, c: np.ndarray) -> np.ndarray:
    """The pieces (M, 2, 2) of segments ``segs`` (S, 2, 2) outside every convex polygon given
    as padded half-planes ``N . x < c`` (K, W, 2) and (K, W), as :class:`_GrownTest` holds
    them (pieces shorter than 1e-9 m dropped)."""
    a0, d = segs[:, 0], segs[:, 1] - segs[:, 0]
    # row (k, w) holds inside where a + t * b < 0, t in [0, 1] along the segment
    a = np.einsum("sx,kwx->skw", a0, N) - c[None]
    b = np.einsum("sx,kwx->skw", d, N)
    with np.errstate(divide="ignore", invalid="ignore"):
        r = -a / b
    inf = np.inf
    flat_in = a < 0  # a row parallel to the segment holds everywhere or nowhere
    lo = np.where(b < 0, r, np.where(b > 0, -inf, np.where(flat_in, -inf, inf)))
    hi = np.where(b > 0, r, np.where(b < 0, inf, np.where(flat_in, inf, -inf)))
    LO, HI = lo.max(axis=2), hi.min(axis=2)
    out = []
    for k in range(len(segs)):
        cut = sorted((max(x, 0.0), min(y, 1.0)) for x, y in zip(LO[k], HI[k], strict=True)
                     if y > 0.0 and x < 1.0 and y > x)
        t0, L = 0.0, float(np.hypot(*d[k]))
        for x, y in [*cut, (1.0, 1.0)]:
            if (x - t0) * L > 1e-9:
                out.append((a0[k] + t0 * d[k], a0[k] + x * d[k]))
            t0 = max(t0, y)
    return np.array(out, float).reshape(-1, 2, 2)


_UNIT_32GON = np.column_stack([np.cos(np.arange(32) * np.pi / 16), np.sin(np.arange(32) * np.pi / 16)])


def _strictly_convex_ccw(p: np.ndarray) -> bool:
    """Whether the ring ``p`` (K, 2) turns left at every vertex and winds once: a convex
    polygon in counter-clockwise order with no repeated or collinear vertices (as
    :func:`convex_footprint` gives, up to the starting vertex)."""
    if len(p) < 3:
        return False
    e = np.concatenate([p[1:], p[:1]]) - p
    f = np.concatenate([e[1:], e[:1]])
    if not (e[:, 0] * f[:, 1] - e[:, 1] * f[:, 0] > 0).all():
        return False
    # left turns all round may still wind twice (a pentagram): then more than one edge points
    # down-left of its predecessor in angle order, i.e. the edge angle falls more than once
    ang = np.arctan2(e[:, 1], e[:, 0])
    return int((np.concatenate([ang[1:], ang[:1]]) < ang).sum()) <= 1


def clip(a: BaseGeometry, b: BaseGeometry) -> BaseGeometry:
    """``a`` intersected with ``b`` on the precision grid, as one dimension (see
    :func:`one_dimension`): GEOS's overlay refuses a collection mixing dimensions, which an
    area whose pieces touch along an edge or at a corner leaves behind."""
    return one_dimension(shapely.intersection(one_dimension(a), one_dimension(b),
                                              grid_size=GRID))


def one_dimension(g: BaseGeometry) -> BaseGeometry:
    """``g`` with only its pieces of the highest dimension when it is a collection mixing
    dimensions (an area with a line or a point where two pieces touched: those have no area
    to place anything in; a line with points where it touched an obstacle's corner)."""
    if g.geom_type != "GeometryCollection" or g.is_empty:
        return g
    parts = list(shapely.get_parts(g))
    dims = [int(shapely.get_dimensions(p)) for p in parts]
    top = max(dims)
    if min(dims) == top:
        return g
    keep = [p for p, d in zip(parts, dims, strict=True) if d == top]
    return shapely.union_all(keep) if len(keep) > 1 else keep[0]


def half_plane(point, normal, extent: float = 1e3) -> Polygon:
    """{x : (x - point) . normal > 0} clipped to a large square."""
    p = np.asarray(point, float)
    n = np.asarray(normal, float)
    n = n / np.linalg.norm(n)
    t = np.array([-n[1], n[0]])
    q = [p + t * extent, p - t * extent, p - t * extent + n * extent, p + t * extent + n * extent]
    return Polygon(q)


def strip(point, normal, lo: float, hi: float, extent: float = 1e3) -> Polygon:
    """{x : lo < (x - point) . normal < hi}."""
    p = np.asarray(point, float)
    n = np.asarray(normal, float)
    n = n / np.linalg.norm(n)
    t = np.array([-n[1], n[0]])
    a, b = p + n * lo, p + n * hi
    return Polygon([a + t * extent, a - t * extent, b - t * extent, b + t * extent])


def line(point, normal, offset: float, extent: float = 1e3) -> LineString:
    """{x : (x - point) . normal = offset} as a long segment."""
    p = np.asarray(point, float)
    n = np.asarray(normal, float)
    n = n / np.linalg.norm(n)
    t = np.array([-n[1], n[0]])
    c = p + n * offset
    return LineString([c - t * extent, c + t * extent])


def disk(center, radius: float, resolution: int = 32) -> Polygon:
    return Point(center).buffer(radius, resolution // 4)


def sample_uniform(region: BaseGeometry, rng: np.random.Generator, n: int = 1) -> np.ndarray:
    """(n, 2) points uniformly distributed over ``region`` (by area, length or count)."""
    if region.is_empty:
        return np.zeros((0, 2))
    parts = list(region.geoms) if hasattr(region, "geoms") else [region]
    areal = [g for g in parts if g.area > 1e-12]
    if areal:
        got = _sample_by_rejection(areal, rng, n)
        if got is not None:
            return got
        # every triangle's ring is 4 coordinates (closed): read them all at once
        coords = np.concatenate([
            shapely.get_coordinates(shapely.constrained_delaunay_triangles(g)).reshape(-1, 4, 2)
            for g in areal])[:, :3]
        e1, e2 = coords[:, 1] - coords[:, 0], coords[:, 2] - coords[:, 0]
        a = np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]) / 2
        k = rng.choice(len(coords), size=n, p=a / a.sum())
        r1, r2 = rng.random(n), rng.random(n)
        flip = r1 + r2 > 1
        r1[flip], r2[flip] = 1 - r1[flip], 1 - r2[flip]
        c = coords[k]
        return c[:, 0] + r1[:, None] * (c[:, 1] - c[:, 0]) + r2[:, None] * (c[:, 2] - c[:, 0])
    linear = [g for g in parts if g.length > 1e-12]
    if linear:
        segs = []
        for g in linear:
            ls = list(g.geoms) if hasattr(g, "geoms") else [g]
            for s in ls:
                c = np.asarray(s.coords)
                segs.extend(zip(c[:-1], c[1:], strict=True))
        segs = np.array(segs)
        ln = np.linalg.norm(segs[:, 1] - segs[:, 0], axis=1)
        k = rng.choice(len(segs), size=n, p=ln / ln.sum())
        t = rng.random(n)[:, None]
        return segs[k, 0] + t * (segs[k, 1] - segs[k, 0])
    pts = np.array([np.asarray(g.coords)[0] for g in parts if not g.is_empty])
    return pts[rng.integers(len(pts), size=n)]


#: Least share of its bounding box a region must fill to be sampled by rejection from the box
#: (thinner regions are triangulated).
REJECTION_FILL = 0.2


def _sample_by_rejection(areal: list[BaseGeometry], rng: np.random.Generator,
                         n: int) -> np.ndarray | None:
    """(n, 2) points uniform over the polygons ``areal``, drawn uniformly in their bounding box
    and kept when inside (one vectorised point-in-polygon test per batch, no triangulation);
    None when the polygons fill too little of the box for that to be cheap."""
    geom = areal[0] if len(areal) == 1 else shapely.MultiPolygon(
        [p for g in areal for p in (g.geoms if hasattr(g, "geoms") else [g])])
    x0, y0, x1, y1 = geom.bounds
    box_area = (x1 - x0) * (y1 - y0)
    fill = geom.area / box_area if box_area > 0 else 0.0
    if fill < REJECTION_FILL:
        return None
    shapely.prepare(geom)
    out, have = [], 0
    for _ in range(16):
        m = int(math.ceil((n - have) / fill * 1.25)) + 4
        x = x0 + rng.random(m) * (x1 - x0)
        y = y0 + rng.random(m) * (y1 - y0)
        ok = shapely.contains_xy(geom, x, y)
        if ok.any():
            out.append(np.c_[x[ok], y[ok]])
            have += int(ok.sum())
        if have >= n:
            return np.concatenate(out)[:n]
    return None


def bounding_square(region: BaseGeometry, pad: float = 1.0) -> Polygon:
    x0, y0, x1, y1 = region.bounds
    return shapely_box(x0 - pad, y0 - pad, x1 + pad, y1 + pad)
