"""A long object standing in a narrow container, leaning on its rim.

A toothbrush ``IN`` a tumbler, pens in a mug, flowers in a vase: lying flat, the child's
footprint does not fit the container's floor (a 0.17 m toothbrush on a 0.05 m floor), and a
pile puts it across the rim. What people mean is the object standing inside, its lower end on
the container's floor and its body leaning on the rim. :func:`place_standing` stands the child
with its long axis up (the end that holds the named part down: a toothbrush by its handle,
flowers by their stems), tilts it away from one side of the floor until it touches the rim
(tried from the steepest tilt down, each dropped onto the container's convex collision pieces,
what settling simulates), and keeps the first pose whose lower end reaches the floor.

The pose records ``rests_on`` (the child's surface label at its lower end), which the IN check
reads, with the tilt allowed up to :data:`STAND_TILT_DEG`.
"""

from __future__ import annotations

import numpy as np
import shapely

from ..assets.model import Asset
from ..measure.checks import EPS
from ..measure.reach import piece_data, pieces_distance
from ..pag.model import Edge
from ..scene.model import PlacedObject
from .collision import Body
from .config import Fail
from .geometry import asset_geometry
from .ledge import accept
from .nesting import pieces_drop
from .state import SolveState
from .support import Support

__all__ = ["may_stand_in", "place_standing", "STAND_TILT_DEG", "LONG"]

#: A child is long when its longest extent is at least this multiple of its middle one.
LONG = 1.5

#: Largest tilt from vertical (degrees) of a child standing in a container.
STAND_TILT_DEG = 40.0

#: Tilts tried from upright to :data:`STAND_TILT_DEG` before the steepest free one is bisected.
_TILT_GRID = 8

#: Degrees to which the steepest tilt that reaches the floor is bisected.
_TILT_STEP_DEG = 0.5

#: Poses tested per asset at most (a crowded container fails in bounded time).
STAND_BUDGET = 160

#: Sides of the floor (directions of lean) tried per asset.
STAND_SIDES = 6

#: Where the lower end is put: shares of the way from the floor's centre to its edge, away
#: from the lean and across it (beside what already stands there).
_FEET = ((0.6, 0.0), (0.5, 0.5), (0.5, -0.5), (0.2, 0.0), (-0.3, 0.0))
#: Positions drawn anywhere on the floor, leaning any way, when others stand there already.
_ANYWHERE = 10
#: The same, for a child leaning the way one already standing there leans (beside it).
_BESIDE = ((0.4, 0.7), (0.4, -0.7), (0.0, 0.75), (0.0, -0.75))

#: Metres above the floor at which the tilt is found (before sliding down onto it).
HOVER = 0.01

#: Metres the lower end may stay above the floor (its curve, collision pieces a little proud).
FLOOR_TOL = 0.012

#: Asset axis -> surface label of its negative and positive side.
_LABELS = {0: ("left", "right"), 1: ("back", "front"), 2: ("bottom", "top")}


def may_stand_in(st: SolveState, asset: Asset, scale: float, sup: Support, edge: Edge) -> bool:
    """Whether :func:`place_standing` applies: IN an object, a long child (longest extent at
    least :data:`LONG` times the middle one) longer than the container's floor is wide."""
    if edge.relation != "IN" or sup.owner == "room" or sup.owner not in st.scene.objects:
        return False
    ext = np.sort(np.ptp(asset_geometry(asset).hull, axis=0) * scale)
    if ext[2] < LONG * ext[1]:
        return False
    x0, y0, x1, y1 = sup.region.bounds
    return max(x1 - x0, y1 - y0) < ext[2]


def _down_end(asset: Asset, edge: Edge) -> tuple[int, int]:
    """``(axis, sign)`` of the asset's long axis and of its end that goes down: the end nearer
    the named part (a toothbrush's handle, a bouquet's stems); for an upright asset (long axis
    its z) its bottom; otherwise the narrower end."""
    hull = asset_geometry(asset).hull
    ext = np.ptp(hull, axis=0)
    a = int(np.argmax(ext))
    mid = 0.5 * (hull[:, a].min() + hull[:, a].max())
    if edge.child.part is not None:
        parts = [p for p in asset.parts if p.name == edge.child.part]
        if parts:
            c = float(np.mean(np.vstack([np.asarray(p.vertices, float) for p in parts])[:, a]))
            return a, (-1 if c <= mid else 1)
    if a == 2:
        return a, -1
    lo = hull[hull[:, a] <= hull[:, a].min() + 0.15 * ext[a]]
    hi = hull[hull[:, a] >= hull[:, a].max() - 0.15 * ext[a]]
    others = [k for k in range(3) if k != a]

    def width(p):
        return float(np.prod(np.ptp(p[:, others], axis=0))) if len(p) > 1 else 0.0

    return a, (-1 if width(lo) <= width(hi) else 1)


def _rotation(axis: int, sign: int, spin: float, tilt: float, side: float) -> np.ndarray:
    """Rotation taking the asset's ``sign * axis`` end to straight down, spun by ``spin``
    about the vertical, then tilted by ``tilt`` (radians) so the upper end leans toward the
    horizontal direction at angle ``side``."""
    up = np.zeros(3)
    up[axis] = -sign  # the upper end's direction in the asset frame
    z = np.array([0.0, 0.0, 1.0])
    # R0 takes ``up`` to z (the smallest rotation; a half turn about x when opposite)
    v = np.cross(up, z)
    c = float(up @ z)
    if np.linalg.norm(v) < 1e-9:
        R0 = np.eye(3) if c > 0 else np.diag([1.0, -1.0, -1.0])
    else:
        K = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
        R0 = np.eye(3) + K + K @ K / (1 + c)
    cs, ss = np.cos(spin), np.sin(spin)
    Rz = np.array([[cs, -ss, 0], [ss, cs, 0], [0, 0, 1.0]])
    # tilt about the horizontal axis perpendicular to the lean direction
    k = np.array([-np.sin(side), np.cos(side), 0.0])
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    Rt = np.eye(3) + np.sin(tilt) * K + (1 - np.cos(tilt)) * K @ K
    return Rt @ Rz @ R0


def _lean_sides(standing: list[PlacedObject]) -> list[float]:
    """Angles (about the vertical) toward which the long objects in ``standing`` lean."""
    out = []
    for o in standing:
        if not o.rests_on:
            continue
        a = int(np.argmax(np.ptp(asset_geometry(o.asset).hull, axis=0)))
        up = o.rotation[:, a] * (1.0 if o.rotation[2, a] >= 0 else -1.0)
        if np.hypot(up[0], up[1]) > 1e-3:
            out.append(float(np.arctan2(up[1], up[0])))
    return out


def _edge_distance(region, c: np.ndarray, d: np.ndarray) -> float:
    """Distance from ``c`` (plane coordinates, inside ``region``) to the region's edge along
    the unit direction ``d``."""
    far = shapely.LineString([c, c + 10.0 * d])
    cut = far.intersection(region)
    return float(cut.length) if not cut.is_empty else 0.0


def place_standing(st: SolveState, oid: str, asset: Asset, scale: float, sup: Support,
                   edge: Edge, others: list[Edge], body: Body, rng: np.random.Generator,
                   validate) -> tuple:
    """Stand the long child in the container ``sup`` belongs to, its lower end on the floor
    and its body leaning on the rim. ``validate(cand, sup)`` returns ``(ok, why, checks)`` as
    the solver's relation checks do. Returns ``((R, t, sup, body, rests_on), trials, checks,
    None)`` like the solver's other placements; raises ``Fail`` when no pose holds."""
    s = sup.surface
    if abs(float(s.normal[2])) < 0.99:
        raise Fail(f"no room to stand {oid} in {sup.name}: its floor is not level",
                   intrinsic=True)
    parent = st.scene.objects[sup.owner]
    # what it may touch going in: the container and what already stands in it
    inside = [parent] + [o for o in st.scene.objects.values()
                         if o.placed and o.id != oid and o.support_choice == sup.choice]
    hull = asset_geometry(asset).hull * scale
    axis, sign = _down_end(asset, edge)
    rests = _LABELS[axis][0 if sign < 0 else 1]
    region = sup.region
    centre = np.asarray(region.centroid.coords[0])
    floor = float(s.origin @ s.normal)
    trials = 0
    last = "no pose reaches the floor"
    mine = piece_data(asset, asset.parts)
    theirs = [(piece_data(o.asset, o.asset.parts), o.transform(False)) for o in inside]

    def pose(R: np.ndarray, foot3: np.ndarray, hover: float):
        """``(T, t)``: the child turned by ``R``, its lowest point ``hover`` over ``foot3``."""
        Y = hull @ R.T
        low = Y[int(np.argmin(Y @ s.normal))]
        t = foot3 - low + (floor + hover - float(foot3 @ s.normal)) * s.normal
        T = np.eye(4)
        T[:3, :3] = R * scale
        T[:3, 3] = t
        return T, t

    def free(R: np.ndarray, foot3: np.ndarray) -> str | None:
        """None when the child turned by ``R`` stands over ``foot3`` touching nothing, else
        the id of what it runs into."""
        T, _ = pose(R, foot3, HOVER)
        return next((o.id for o, (P, Tp) in zip(inside, theirs, strict=True)
                     if pieces_distance(mine, T, P, Tp, limit=1e-3) <= 0), None)

    # beside what already stands there, leaning the same way (toothbrushes side by side),
    # then in other directions
    sides = [(a, _BESIDE) for a in _lean_sides(inside[1:])] + [
        (a, _FEET) for a in rng.uniform(0, 2 * np.pi)
        + np.arange(STAND_SIDES) * 2 * np.pi / STAND_SIDES]
    if len(inside) > 1:  # and anywhere on the floor, in any direction
        sides += [(a, ((None, None),)) for a in rng.uniform(0, 2 * np.pi, _ANYWHERE)]
    for side, feet in sides:
        spin = rng.uniform(0, 2 * np.pi)
        # the lean's direction in the support plane: the lower end goes on the other side
        d3 = np.array([np.cos(side), np.sin(side), 0.0])
        d2 = np.array([float(d3 @ s.u), float(d3 @ s.v)])
        d2 /= max(np.linalg.norm(d2), 1e-9)
        across = np.array([-d2[1], d2[0]])
        r = _edge_distance(region, centre, -d2)
        w = _edge_distance(region, centre, across)
        for share, aside in feet:
            if trials >= STAND_BUDGET:
                break
            if share is None:
                x0, y0, x1, y1 = region.bounds
                foot = rng.uniform((x0, y0), (x1, y1))
            else:
                foot = centre - share * r * d2 + aside * w * across
            if not region.contains(shapely.Point(foot)):
                continue
            foot3 = s.origin + foot[0] * s.u + foot[1] * s.v

            def at(tilt: float, spin=spin, side=side):
                return _rotation(axis, sign, spin, tilt, side)

            # the steepest tilt at which it stands there free, before one where it does not:
            # it leans on the rim (or on what stands in the container already)
            grid = np.radians(np.linspace(0.0, STAND_TILT_DEG, _TILT_GRID))
            hits = []
            for g in grid:
                trials += 1
                hits.append(free(at(float(g)), foot3))
            k = next((i for i in range(len(grid) - 1, 0, -1)
                      if hits[i - 1] is None and hits[i] is not None), None)
            if k is None:
                last = f"at {STAND_TILT_DEG:.0f} degrees it would not yet lean on the rim of " \
                       f"{sup.owner}" if hits[-1] is None else \
                       f"standing there it would run into {hits[0]}"
                continue
            lo, hi = float(grid[k - 1]), float(grid[k])
            while hi - lo > np.radians(_TILT_STEP_DEG):
                mid = 0.5 * (lo + hi)
                trials += 1
                lo, hi = (mid, hi) if free(at(mid), foot3) is None else (lo, mid)
            R = at(lo)
            T, t = pose(R, foot3, HOVER)
            # then down along its own axis until its lower end touches the floor
            slide = R[:, axis] * sign
            d = min(pieces_drop(asset, T, o, slide, 2 * HOVER + FLOOR_TOL) for o in inside)
            t = t + (d - EPS) * slide
            h_low = float(np.min((hull @ R.T + t) @ s.normal)) - floor
            if h_low > FLOOR_TOL:
                last = f"its lower end would stay {h_low * 1000:.0f} mm above the floor of " \
                       f"{sup.owner}"
                continue
            checks, last = accept(st, oid, asset, scale, R, t, rests, sup, body, validate)
            if checks is not None:
                return (R, t, sup, body, rests), trials, checks, None
    raise Fail(f"no room to stand {oid} in {sup.name} ({trials} trials, last: {last})")
