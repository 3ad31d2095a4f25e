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
import shapely.affinity

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
from .support import Support, best_support

__all__ = ["end_width", "floor_takes", "may_stand_in", "place_standing", "stands_upright", "standing_instance",
           "STAND_TILT_DEG", "SHALLOW_TILT_DEG", "LONG", "lies_down", "TOPPLE_DEG", "STICK"]

#: A child is long when its longest extent is at least this multiple of its middle one.
LONG = 1.5

#: Largest tilt from vertical (degrees) of a child standing in a container.
STAND_TILT_DEG = 40.0

#: Largest tilt from vertical (degrees) of a child standing in a shallow container, tried when
#: at :data:`STAND_TILT_DEG` it would not yet lean on the rim anywhere: a spoon in a cereal
#: bowl, its bowl at the bottom, its handle on the rim.
SHALLOW_TILT_DEG = 70.0

#: Tilts tried from upright to :data:`STAND_TILT_DEG` before the steepest free one is bisected.
_TILT_GRID = 8

#: Degrees to which the steepest tilt that reaches the floor is bisected.
_TILT_STEP_DEG = 0.5

#: Poses tested per asset at most (a crowded container fails in bounded time).
STAND_BUDGET = 160

#: Sides of the floor (directions of lean) tried per asset.
STAND_SIDES = 6

#: Where the lower end is put: shares of the way from the floor's centre to its edge, away
#: from the lean and across it (beside what already stands there); last the middle, where a
#: child as wide as the floor stands upright (a cue's butt in a rack's cup, its shaft in a clip).
_FEET = ((0.6, 0.0), (0.5, 0.5), (0.5, -0.5), (0.2, 0.0), (-0.3, 0.0), (0.0, 0.0))
#: Positions drawn anywhere on the floor, leaning any way, when others stand there already.
_ANYWHERE = 10
#: The same, for a child leaning the way one already standing there leans (beside it).
_BESIDE = ((0.4, 0.7), (0.4, -0.7), (0.0, 0.75), (0.0, -0.75))

#: Metres of the lower end of a standing child that make its footprint (:func:`end_width`).
_END = 0.01

#: Metres above the floor at which the tilt is found (before sliding down onto it).
HOVER = 0.01

#: Metres the lower end may stay above the floor (its curve, collision pieces a little proud).
FLOOR_TOL = 0.012

#: Pool slots per candidate category looked at for a container whose mouth takes what stands
#: in it, and for a child that stands in the container drawn.
MOUTH_SLOTS = 8

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


def _lowest(Y: np.ndarray, up: np.ndarray) -> np.ndarray:
    """The middle of the points of ``Y`` (N, 3) within 1 mm of the lowest along ``up``: the
    centre of a flat end standing upright (a cue's butt in the middle of its cup), not one
    vertex of its rim."""
    h = Y @ up
    return Y[h <= h.min() + 1e-3].mean(axis=0)


def _unit_scale(asset: Asset) -> float:
    """The scale that brings ``asset`` into its category's size range (1 when it is in it)."""
    lo, hi = asset.size_range
    size = asset_geometry(asset).size
    return float(np.clip(1.0, lo / max(size, 1e-6), hi / max(size, 1e-6)))


def _long(asset: Asset) -> bool:
    ext = np.sort(np.ptp(asset_geometry(asset).hull, axis=0))
    return bool(ext[2] >= LONG * ext[1])


def stands_upright(container: Asset, c_scale: float, child: Asset, scale: float,
                   edge: Edge) -> bool | None:
    """Whether ``child`` (scaled by ``scale``) stands upright, its lower end over the middle
    of one of the internal floors of ``container`` (scaled by ``c_scale``), touching nothing of
    it: the mouth takes it (a bouquet's fanning stems in a bud vase's neck do not). None when
    the child would not stand in it (not long, or the container's floor is as wide as it is
    long: it lies there)."""
    if not _long(child):
        return None
    hull = asset_geometry(child).hull * scale
    length = float(np.ptp(hull, axis=0).max())
    floors = [ins.surface for ins in container.internal if abs(float(ins.surface.normal[2])) >= 0.99]
    floors = [f for f in floors
              if max(np.ptp(np.asarray(f.polygon.envelope.exterior.coords), axis=0)) * c_scale < length]
    if not floors:
        return None
    axis, sign = _down_end(child, edge)
    R = _rotation(axis, sign, 0.0, 0.0, 0.0)
    Y = hull @ R.T
    low = _lowest(Y, np.array([0.0, 0.0, 1.0]))
    mine = piece_data(child, child.parts)
    theirs = piece_data(container, container.parts)
    Tc = np.eye(4)
    Tc[:3, :3] *= c_scale
    for f in floors:
        p = f.polygon.representative_point() if not f.polygon.contains(f.polygon.centroid) \
            else f.polygon.centroid
        foot3 = np.asarray(f.to_3d(np.array([[p.x, p.y]])), float).reshape(3) * c_scale
        T = np.eye(4)
        T[:3, :3] = R * scale
        T[:3, 3] = foot3 - low + np.array([0.0, 0.0, HOVER])
        if pieces_distance(mine, T, theirs, Tc, limit=1e-3) > 0:
            return True
    return False


def end_width(child: Asset, scale: float, edge: Edge) -> float:
    """Widest horizontal extent (metres) of the lower end of ``child`` (scaled by ``scale``)
    standing upright: the floor its handle or stems take."""
    hull = asset_geometry(child).hull * scale
    axis, sign = _down_end(child, edge)
    Y = hull @ _rotation(axis, sign, 0.0, 0.0, 0.0).T
    end = Y[Y[:, 2] <= Y[:, 2].min() + _END]
    return float(np.ptp(end[:, :2], axis=0).max()) if len(end) > 1 else 0.0


def standing_instance(st: SolveState, library, oid: str, edge: Edge, category: str,
                      asset: Asset, usable, tried: set[str],
                      rng: np.random.Generator) -> tuple[str, Asset]:
    """``(category, asset)`` for the first attempt at ``oid`` (support edge ``edge``), so that
    what stands in a narrow container fits through its mouth (:func:`stands_upright`):

    - a long child ``IN`` a placed object: the drawn instance when it stands upright there,
      else the first of :data:`MOUTH_SLOTS` random pool slots per candidate category that does
      (flowers slim enough for the vase drawn);
    - a container with long children written ``IN`` it, not placed yet: the drawn instance
      when its mouth takes the most of the first :data:`MOUTH_SLOTS` pool slots of each
      child's categories, else the instance looked at that takes the most (a vase whose neck
      takes a bouquet, not a bud vase).

    A container with children written ``IN`` it that would not stand there (a potted plant in
    a basket) is drawn likewise with a floor whose free height takes the median height of each
    child's first :data:`MOUTH_SLOTS` pool slots, at the least scale its node allows (a
    basket whose handle leaves the leaves no room is passed over), and with flat children
    (picture books) with a floor that takes them standing (:func:`floor_takes`); so is one
    that goes ``IN`` a placed object itself (a basket of books on a shelf). Unchanged for
    anything else, and when no instance looked at does better."""
    if getattr(library, "load", None) is None:
        return category, asset
    k = int(getattr(library, "per_category", 20))
    cands = st.pag.objects[oid].candidates
    parent = st.scene.objects.get(edge.parent.object)
    if edge.relation == "IN" and not edge.parent.is_room_element and parent is not None \
            and parent.placed and parent.asset is not None:
        # what is written to stand there shares its floor: each long child not placed yet
        # gets as wide a share of it (two toothbrushes in a tumbler: neither takes over half)
        coming = 1 + sum(1 for e in st.pag.relations
                         if e.relation == "IN" and e.parent.object == parent.id
                         and e.child.object != oid and st.pag.supporter(e.child.object) is e
                         and not getattr(st.scene.objects.get(e.child.object), "placed", False))
        floors = [ins.surface.polygon for ins in parent.asset.internal
                  if abs(float(ins.surface.normal[2])) >= 0.99]
        wide = max((min(np.ptp(np.asarray(f.envelope.exterior.coords), axis=0)) for f in floors),
                   default=0.0) * parent.scale

        def fits(a: Asset) -> bool | None:
            up = stands_upright(parent.asset, parent.scale, a, _unit_scale(a), edge)
            if up is None:
                return up
            if up and coming > 1 and end_width(a, _unit_scale(a), edge) * coming > wide:
                return False
            return up

        up = fits(asset)
        if up is True:
            return category, asset
        if up is False:
            for ci in rng.permutation(len(cands)):
                cat = cands[int(ci)]
                for slot in rng.permutation(k)[:MOUTH_SLOTS]:
                    a = library.load(cat, int(slot))
                    if a.asset_id not in tried and usable(a) and fits(a):
                        return cat, a
            return category, asset
        # not a thing that stands there (a basket on a shelf): drawn for what goes in it
    inside = [e for e in st.pag.relations
              if e.relation == "IN" and e.parent.object == oid
              and st.pag.supporter(e.child.object) is e
              and not (set(st.pag.objects[e.child.object].candidates) & set(cands))]
    if not inside:
        return category, asset
    kids = [(e, library.load(c, slot)) for e in inside
            for c in st.pag.objects[e.child.object].candidates for slot in range(MOUTH_SLOTS)]

    def least(oid_: str, a: Asset) -> float:
        """The least scale the node of ``oid_`` allows ``a`` (its category's size, times the
        low end of the node's ``scale`` range)."""
        node = st.pag.objects[oid_]
        return _unit_scale(a) * (float(node.scale[0]) if node.scale is not None else 1.0)

    # what does not stand in it lies or sits on its floor: the median height of each child's
    # instances looked at needs that much free height (a plant's leaves under a handle; not
    # the lowest, a herb pot among floor plants)
    heights: dict[str, list[float]] = {}
    for e, ka in kids:
        if not _long(ka):
            h = float(np.ptp(asset_geometry(ka).hull[:, 2])) * least(e.child.object, ka)
            heights.setdefault(e.child.object, []).append(h)
    low = {k: float(np.median(v)) for k, v in heights.items()}
    # ... and flat ones a floor that takes them standing (picture books in a basket)
    floor_ok = floor_takes(st, library, oid, edge)

    def takes(a: Asset) -> tuple[int, int]:
        """Verdicts ``(yes, no)``: of each child slot that would stand in ``a`` whether it
        goes through its mouth, and of each child that would not whether the lowest of its
        slots has the free height on one of its floors; and for flat children whether a
        floor takes them standing (:func:`floor_takes`)."""
        s_ = least(oid, a)
        got = [stands_upright(a, s_, ka, _unit_scale(ka), e) for e, ka in kids]
        room = max((ins.clearance for ins in a.internal), default=0.0) * s_
        got += [room >= h for h in low.values()]
        if floor_ok is not None:
            got.append(floor_ok(a))
        return sum(g is True for g in got), sum(g is False for g in got)

    yes, no = takes(asset)
    if no == 0:
        return category, asset
    best = (yes, category, asset)
    for ci in rng.permutation(len(cands)):
        cat = cands[int(ci)]
        for slot in rng.permutation(k)[:MOUTH_SLOTS]:
            a = library.load(cat, int(slot))
            if a.asset_id in tried or not usable(a):
                continue
            y, n = takes(a)
            if y > best[0]:
                best = (y, cat, a)
            if y > 0 and n == 0:
                return cat, a
    return best[1], best[2]


#: A child is flat (a book, a board) when its thinnest extent is at most this share of its
#: middle one: such a thing needs a floor that takes its footprint, not only the height.
FLAT_THIN = 0.25


def floor_takes(st: SolveState, library, oid: str, edge: Edge, share: float = 1.0):
    """For a container ``oid`` (its support edge ``edge``) with flat things written ``IN`` it
    (:data:`FLAT_THIN`: picture books in a basket), a predicate on its instances: whether one
    of its floors takes the smallest footprint of each such child's first
    :data:`MOUTH_SLOTS` pool slots standing as modelled, at the scale the instance gets where
    it goes (its category's size, capped by the depth, width and free height of the shelf it
    goes in, as :func:`parse3d.solver.choice.instance_scale` shrinks it, to ``share`` of the
    free height). None when it has no flat children."""
    if getattr(library, "load", None) is None:
        return None
    foot = {}
    for e in st.pag.relations:
        if e.relation != "IN" or e.parent.object != oid or st.pag.supporter(e.child.object) is not e:
            continue
        node = st.pag.objects[e.child.object]
        for c in node.candidates:
            for slot in range(MOUTH_SLOTS):
                ka = library.load(c, slot)
                ext = np.ptp(asset_geometry(ka).hull, axis=0)
                if _long(ka) or min(ext) > FLAT_THIN * float(np.median(ext)):
                    continue
                s_ = _unit_scale(ka) * (float(node.scale[0]) if node.scale is not None else 1.0)
                foot.setdefault(e.child.object, []).append(tuple(sorted(ext[:2] * s_)))
    if not foot:
        return None
    # the smallest of each child's footprints (by its longer side): the drawn one is shrunk
    # to the floor within its category's size range (nesting.floor_fit)
    foot = {k: min(v, key=lambda f: f[1]) for k, v in foot.items()}
    room = _room_at(st, edge)
    node = st.pag.objects[oid]

    def takes(a: Asset) -> bool:
        s_ = _unit_scale(a) * (float(node.scale[0]) if node.scale is not None else 1.0)
        if room is not None:
            ext = np.ptp(asset_geometry(a).hull, axis=0)
            w, d, hgt = room
            lo, hi = sorted(ext[:2])
            s_ = min(s_, d / max(lo, 1e-6), w / max(hi, 1e-6),
                     share * hgt / max(float(ext[2]), 1e-6))
        return all(takes_footprint(a, s_, f) for f in foot.values())

    return takes


def _room_at(st: SolveState, edge: Edge) -> tuple[float, float, float] | None:
    """``(width, depth, free height)`` of the largest surface ``edge`` puts its child on
    (its width the longer side), or None when that is not known yet (an unplaced parent, the
    room)."""
    if edge.relation not in ("ON", "IN") or edge.parent.is_room_element:
        return None
    sup = best_support(st, edge, key=lambda s_: s_.region.area)
    if sup is None:
        return None
    x0, y0, x1, y1 = sup.region.bounds
    d, w = sorted((x1 - x0, y1 - y0))
    return float(w), float(d), float(sup.clearance)


def takes_footprint(container: Asset, scale: float, foot: tuple[float, float]) -> bool:
    """Whether a floor of ``container`` (at ``scale``) holds an ``a`` x ``b`` footprint
    ``foot`` round its centre, along its own axes either way round (a book standing in a round
    basket whose floor is narrower than the book is wide: no)."""
    a, b = foot
    for ins in container.internal:
        if abs(float(ins.surface.normal[2])) < 0.99:
            continue
        poly = shapely.affinity.scale(ins.surface.polygon, scale, scale, origin=(0, 0))
        c = poly.representative_point() if not poly.contains(poly.centroid) else poly.centroid
        for w, d in ((a, b), (b, a)):
            if poly.contains(shapely.box(c.x - w / 2, c.y - d / 2, c.x + w / 2, c.y + d / 2)):
                return True
    return False


def place_standing(st: SolveState, oid: str, asset: Asset, scale: float, sup: Support,
                   edge: Edge, others: list[Edge], body: Body, rng: np.random.Generator,
                   validate) -> tuple:
    """Stand the long child in the container ``sup`` belongs to, its lower end on the floor
    and its body leaning on the rim, tilted up to :data:`STAND_TILT_DEG`, or up to
    :data:`SHALLOW_TILT_DEG` where at that tilt it would nowhere lean on the rim yet (a spoon
    in a shallow bowl). ``validate(cand, sup)`` returns ``(ok, why, checks)`` as the solver's
    relation checks do. Returns ``((R, t, sup, body, rests_on), trials, checks, None)`` like
    the solver's other placements; raises ``Fail`` when no pose holds."""
    try:
        return _stand(st, oid, asset, scale, sup, edge, body, rng, validate, STAND_TILT_DEG)
    except _Shallow:
        return _stand(st, oid, asset, scale, sup, edge, body, rng, validate, SHALLOW_TILT_DEG)


class _Shallow(Fail):
    """No pose held, and at every place tried the child would not yet lean on the rim."""


def _stand(st: SolveState, oid: str, asset: Asset, scale: float, sup: Support, edge: Edge,
           body: Body, rng: np.random.Generator, validate, limit: float) -> tuple:
    """:func:`place_standing` with tilts up to ``limit`` degrees."""
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
    shallow = True  # so far, nowhere does it lean on the rim at the largest tilt
    mine = piece_data(asset, asset.parts)
    theirs = [(piece_data(o.asset, o.asset.parts), o.transform(False)) for o in inside]
    Tp = parent.transform(False)
    P = asset_geometry(parent.asset).hull @ Tp[:3, :3].T + Tp[:3, 3]
    # what the container stands on: its points within a centimetre of its lowest
    base = shapely.MultiPoint(P[P[:, 2] <= P[:, 2].min() + 0.01][:, :2]).convex_hull

    def pose(R: np.ndarray, foot3: np.ndarray, hover: float):
        """``(T, t)``: the child turned by ``R``, its lowest point ``hover`` over ``foot3``."""
        Y = hull @ R.T
        low = _lowest(Y, s.normal)
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
            grid = np.radians(np.linspace(0.0, limit, round(_TILT_GRID * limit / STAND_TILT_DEG)))
            hits = []
            for g in grid:
                trials += 1
                hits.append(free(at(float(g)), foot3))
            k = next((i for i in range(len(grid) - 1, 0, -1)
                      if hits[i - 1] is None and hits[i] is not None), None)
            if k is None:
                shallow = shallow and hits[-1] is None
                last = f"at {limit:.0f} degrees it would not yet lean on the rim of " \
                       f"{sup.owner}" if hits[-1] is None else \
                       f"standing there it would run into {hits[0]}"
                continue
            shallow = False
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
            if limit > STAND_TILT_DEG and not base.contains(shapely.Point(
                    (hull @ R.T + t).mean(axis=0)[:2])):
                # leaning that far, its weight outside what the container stands on would tip
                # the container over
                last = f"leaning {np.degrees(lo):.0f} degrees its weight would be outside the " \
                       f"base of {sup.owner} and tip it"
                continue
            checks, last = accept(st, oid, asset, scale, R, t, rests, sup, body, validate)
            if checks is not None:
                return (R, t, sup, body, rests), trials, checks, None
    if shallow and trials and limit < SHALLOW_TILT_DEG:
        raise _Shallow(last)
    raise Fail(f"no room to stand {oid} in {sup.name} ({trials} trials, last: {last})")


#: Degrees a child standing on its base may lean before its centre of mass leaves the base:
#: below this it topples at a touch (a pool cue on its butt, a pen on its end).
TOPPLE_DEG = 3.0

#: A stick: modelled standing, its height at least this multiple of its horizontal extents.
STICK = 4.0

#: A stick's cross-section is round-ish: its two horizontal extents within this ratio.
ROUND_SECTION = 1.5


def lies_down(edge: Edge, asset: Asset, pag) -> Edge | None:
    """``ON`` with no child part named, for a stick modelled standing (its height at least
    ``STICK`` times its width, its section round-ish: ``ROUND_SECTION``) that would topple from its base (its centre of mass within
    ``TOPPLE_DEG`` of the base's edge, seen from the base: a pool cue on its butt): the edge
    by which it lies on its side (its thinner horizontal axis down), as a person means a cue
    ON a pool table; None for anything else (the edge as written), and for a child that also
    leans (``LEANING_AGAINST``: it stands leaning)."""
    c = edge.child
    if edge.relation != "ON" or c.part is not None or c.surface not in (None, "bottom"):
        return None
    if any(e.relation == "LEANING_AGAINST" and e.child.object == c.object
           for e in pag.relations):
        return None
    g = asset_geometry(asset)
    ext = np.ptp(g.hull, axis=0)
    w, d = sorted((float(ext[0]), float(ext[1])))
    if ext[2] < STICK * d or d > ROUND_SECTION * w:
        return None  # not a stick, or a flat one (a ladder: it leans, it does not roll)
    low = float(g.hull[:, 2].min())
    base = g.hull[g.hull[:, 2] <= low + 3e-3][:, :2]
    foot = shapely.MultiPoint(base).convex_hull
    at = shapely.Point(float(g.com[0]), float(g.com[1]))
    r = float(foot.exterior.distance(at)) if foot.geom_type == "Polygon" \
        and foot.contains(at) else 0.0
    if np.degrees(np.arctan2(r, max(float(g.com[2]) - low, 1e-6))) >= TOPPLE_DEG:
        return None
    from dataclasses import replace

    from ..pag.refs import format_ref

    side = "left" if ext[0] <= ext[1] else "back"  # the thinner way down
    return replace(edge, child=replace(c, surface=side,
                                       text=format_ref(c.object, None, None, side)))
