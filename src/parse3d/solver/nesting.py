"""Nesting and stacks of like round things: a plate on a plate, a bowl in a bowl, a cup in a cup.

A round child resting on (or in) a round parent of its own kind goes on the parent's axis first:
a small plate off-centre in a dinner plate's well rests with one side on the well's slope and
tips in settling (the kitchen example's side plate ended 10.8 degrees off), a dinner plate
off-centre on a side plate rests on one side of its rim. Concentric, each rests evenly all round.
"""

from __future__ import annotations

import numpy as np

from ..assets.model import Asset
from ..measure.checks import object_centroid, world_points
from ..measure.insides import no_room
from ..pag.model import Edge
from .config import Fail
from .geometry import asset_geometry
from .state import SolveState
from .support import Support, filled

__all__ = ["concentric_first", "floor_fit", "like_fit", "nest_instance", "nest_rise", "nest_samples",
           "in_on_top", "pieces_drop", "same_kind"]

def same_kind(st: SolveState, oid: str, sup: Support) -> bool:
    """Whether the child rests on or in a placed object of its own kind (their PAG nodes share
    a category)."""
    if sup.owner == "room" or sup.owner not in st.scene.objects:
        return False
    parent = st.scene.objects[sup.owner]
    return bool(parent.placed and parent.asset is not None
                and set(st.pag.objects[oid].candidates) & set(st.pag.objects[sup.owner].candidates))


def nest_rise(st: SolveState, oid: str, sup: Support) -> float:
    """Metres from an internal surface up to its owner's top, for a child IN an object of its
    own kind (a bowl in a bowl): it starts there and drops onto the parent's inside, resting on
    its wall when it is too wide for its floor. 0 otherwise."""
    if not same_kind(st, oid, sup):
        return 0.0
    parent = st.scene.objects[sup.owner]
    top = float(np.max(world_points(parent, hull_only=True, settled=False)[:, 2]))
    return max(0.0, top - float(sup.surface.origin[2]))


def concentric_first(st: SolveState, oid: str, sup: Support, asset: Asset, scale: float,
                     R: np.ndarray, samples: np.ndarray) -> np.ndarray:
    """``samples`` (origins in the support plane) with, first, the one that puts the child's
    centre of mass on the vertical through its parent's centre, when the child rests on or in
    an object of its own kind (their PAG nodes share a category): a loaf on a loaf, a book on
    a book, plates and bowls concentric."""
    if not same_kind(st, oid, sup):
        return samples
    parent = st.scene.objects[sup.owner]
    s = sup.surface
    com = (asset_geometry(asset).com * scale) @ R.T
    d = object_centroid(parent, False) - s.origin - com
    at = np.array([[float(d @ s.u), float(d @ s.v)]])
    if len(samples) and _flat_and_round(asset) and _flat_and_round(parent.asset):
        # a stack of plates or saucers is concentric: off the axis by more than a tenth of
        # the lower one's width it rests on one side of its rim and tilts when settled (a
        # dinner plate 4 cm off a side plate's axis tipped 2.4 degrees); another instance is
        # drawn when the axis itself is taken
        b = asset_geometry(parent.asset).bounds
        ext = (b[1] - b[0])[:2] * parent.scale
        lim = max(NEST_JITTER, STACK_OFF_AXIS * float(min(ext)))
        # as many candidates as before, all near the axis: a sunflower spiral about it
        i = np.arange(len(samples), dtype=float)
        a = 2.399963 * i  # the golden angle
        samples = at + lim * np.sqrt(i / len(samples))[:, None] * np.c_[np.cos(a), np.sin(a)]
        return samples
    return np.vstack([at, samples])[:max(len(samples), 1)] if len(samples) else at


#: Share of the lower object's width a round object stacked on one of its kind may sit off
#: its axis (:func:`concentric_first`).
STACK_OFF_AXIS = 0.1


def _flat_and_round(asset: Asset) -> bool:
    """Whether an asset is a flat disc: round seen from above (x and y extents within 10%) and
    at most a quarter as tall as wide (a plate, a saucer, a coaster)."""
    b = asset_geometry(asset).bounds
    x, y, z = b[1] - b[0]
    return bool(abs(x - y) <= 0.1 * max(x, y) and z <= 0.25 * max(x, y))


#: Largest ratio of a nested child's width to its parent's (a bowl in a bowl).
NEST_WIDER = 1.05
#: Metres around the parent's axis within which a nested child's later draws fall.
NEST_JITTER = 0.004


def nest_samples(st: SolveState, oid: str, sup: Support, asset: Asset, scale: float,
                 R: np.ndarray, rng: np.random.Generator, n: int):
    """``(region, samples)`` for a child IN an object of its own kind (a bowl in a bowl, a cup
    in a cup): on the parent's axis, then within :data:`NEST_JITTER` of it. It need not fit
    the parent's floor: it starts at the rim (:func:`nest_rise`) and drops onto the inside,
    resting on the wall all round when it is wider than the floor. None otherwise."""
    import shapely

    if not same_kind(st, oid, sup):
        return None
    parent = st.scene.objects[sup.owner]
    mine = float(np.ptp(((asset_geometry(asset).hull * scale) @ R.T)[:, :2], axis=0).max())
    theirs = float(np.ptp(world_points(parent, hull_only=True, settled=False)[:, :2],
                          axis=0).max())
    if mine > NEST_WIDER * theirs:
        # a bowl wider than the one it sits in rests on its rim, top-heavy: the pair tipped
        raise Fail(f"no room in {sup.owner}: a {mine:.2f} m wide {asset.category} does not nest "
                   f"in a {theirs:.2f} m wide one (it would rest on its rim and tip it over)")
    at = concentric_first(st, oid, sup, asset, scale, R, np.zeros((0, 2)))
    if not len(at):
        return None
    c = at[0]
    r = NEST_JITTER * np.sqrt(rng.uniform(0, 1, max(n - 1, 0)))
    a = rng.uniform(0, 2 * np.pi, len(r))
    samples = np.vstack([c, c + np.c_[r * np.cos(a), r * np.sin(a)]])
    return shapely.Point(c).buffer(NEST_JITTER), samples


def pieces_drop(asset: Asset, T: np.ndarray, parent, down: np.ndarray, upper: float,
                tol: float = 2.5e-4) -> float:
    """How far the child (asset at the 4x4 ``T``) can move along ``down`` before its convex
    collision pieces touch the parent's (what settling simulates; a bowl's inside is a ring of
    pieces standing a little proud of its mesh): bisected to ``tol``; ``upper`` when they do
    not touch even there, 0 when they already do."""
    from ..measure.reach import piece_data, pieces_distance

    mine = piece_data(asset, asset.parts)
    theirs = piece_data(parent.asset, parent.asset.parts)
    Tp = parent.transform(False)
    d0 = np.asarray(down, float) / np.linalg.norm(down)

    def hits(shift: float) -> bool:
        Ts = np.array(T, float)
        Ts[:3, 3] += shift * d0
        return pieces_distance(mine, Ts, theirs, Tp, limit=1e-3) <= 0.0

    if not hits(upper):
        return float(upper)
    if hits(0.0):
        return 0.0
    lo, hi = 0.0, float(upper)
    while hi - lo > tol:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if hits(mid) else (mid, hi)
    return lo


#: Share of a container's floor a child shrunk to fit it may fill, along each side.
FLOOR_FIT = 0.95


def floor_fit(st: SolveState, edge, asset: Asset, scale: float, axis: int) -> float:
    """``scale``, or less when the child lying in its support orientation (``axis``, the asset
    axis of its support normal) is longer or wider than every internal floor of the object it
    goes IN but fits one shrunk within its category's size range (a rolled towel in a small
    wicker basket, a plant in a plant basket a little narrower than its pot), that range times
    the low end of the node's ``scale`` range when it is below 1 (a toy loaf in a toy pot,
    both written small); unchanged for
    anything else (a toothbrush far longer than a tumbler's floor stands in it instead). IN an
    object of its own kind that it cannot be shrunk to lie in (a basket in a basket) it rests on
    the parent's wall, so it is only shrunk (within its range) to be no wider than the
    parent."""
    if edge.relation == "ON":
        return like_fit(st, edge, asset, scale, axis)
    if edge.relation != "IN" or edge.parent.is_room_element \
            or edge.parent.object not in st.scene.objects:
        return scale
    fit = _floor_fit(st, edge, asset, scale, axis)
    parent = st.scene.objects[edge.parent.object]
    if fit == scale and parent.placed and set(st.pag.objects[edge.child.object].candidates) \
            & set(st.pag.objects[edge.parent.object].candidates):
        # nested in one of its kind and too big for its floor (a basket in a basket): it rests
        # on the parent's wall, so it need only be no wider than the parent (within its range)
        theirs = float(np.ptp(world_points(parent, hull_only=True, settled=False)[:, :2],
                              axis=0).max())
        mine = scale * float(np.ptp(asset_geometry(asset).hull[:, :2], axis=0).max())
        lo = asset.size_range[0] / max(asset_geometry(asset).size, 1e-6)
        return scale * theirs / mine if mine > theirs and scale * theirs / mine >= lo else scale
    return fit


#: Ratio of a stacked child's sides to those of the one of its kind below beyond which it is
#: drawn smaller, like the one below (:func:`like_fit`).
LIKE_WIDER = 1.25
#: Footprint area, in units of the lower one's, up to which a stacked child keeps its size.
LIKE_AREA = 3.0


def like_fit(st: SolveState, edge, asset: Asset, scale: float, axis: int) -> float:
    """``scale``, or less for a child ``ON`` a placed object of its own kind (their PAG nodes
    share a category) whose footprint, lying in its support orientation (``axis``), covers more
    than :data:`LIKE_AREA` times the lower one's and whose sides are more than
    :data:`LIKE_WIDER` times the lower one's: it is drawn the lower one's size,
    within its category's size range. A towel shrunk to lie in a small basket carries the
    towel written on it at its own size, not one twice as long that finds no rest there."""
    if edge.parent.is_room_element or edge.parent.object not in st.scene.objects:
        return scale
    parent = st.scene.objects[edge.parent.object]
    if not parent.placed or parent.asset is None or not (
            set(st.pag.objects[edge.child.object].candidates)
            & set(st.pag.objects[edge.parent.object].candidates)):
        return scale
    from dataclasses import replace

    from .geometry import hull_extents

    under = st.pag.supporter(parent.id)
    if under is not None and under.relation == "IN" and not under.parent.is_room_element \
            and under.parent.object in st.scene.objects:
        # one more on a pile in a container (towels in a basket): it lies in its floor too,
        # as the ones below were drawn to
        scale = _floor_fit(st, replace(under, child=edge.child), asset, scale, axis)
    ext = hull_extents(asset)[0]
    m1, m2 = sorted((scale * float(ext[k]) for k in range(3) if k != axis), reverse=True)
    below = world_points(parent, hull_only=True, settled=False)
    t1, t2 = sorted(np.ptp(below[:, :2], axis=0).tolist(), reverse=True)
    ratio = max(m1 / max(t1, 1e-9), m2 / max(t2, 1e-9))
    if ratio <= LIKE_WIDER or m1 * m2 <= LIKE_AREA * t1 * t2:
        return scale  # it may overhang the one below (a loaf on a smaller loaf)
    lo = asset.size_range[0] / max(asset_geometry(asset).size, 1e-6)
    return max(scale / ratio, lo) if scale > lo else scale


def _floor_fit(st: SolveState, edge, asset: Asset, scale: float, axis: int) -> float:
    """:func:`floor_fit` for a child fitted to the parent's floor."""
    from .geometry import hull_extents
    from .support import support_candidates

    try:
        sups = support_candidates(st, edge)
    except Fail:
        return scale
    ext = hull_extents(asset)[0]
    e1, e2 = sorted((scale * float(ext[k]) for k in range(3) if k != axis), reverse=True)
    best = 0.0
    for sup in sups:
        x0, y0, x1, y1 = sup.region.bounds
        w1, w2 = sorted((x1 - x0, y1 - y0), reverse=True)
        # lying along the floor's sides (a long thing across a square floor's diagonal is
        # no better: it stands), inside a round floor's own shape (a round basket's)
        fit = min(w1 / max(e1, 1e-9), w2 / max(e2, 1e-9))
        if fit < 1.0 and sup.region.area < ROUND_FLOOR \
                * sup.region.minimum_rotated_rectangle.area:  # shrunk: to lie inside it
            fit = min(fit, _rect_in(sup.region, e1, e2))
        best = max(best, fit)
    if best >= 1.0 or best <= 0.0:
        return scale
    fit = FLOOR_FIT * best
    # within its category's size range, taken down as far as the writer's own scale range goes
    # below 1 (a toy loaf, ``scale`` 0.4-0.5, in a toy pot)
    node = st.pag.objects[edge.child.object].scale
    lo = asset.size_range[0] / max(asset_geometry(asset).size, 1e-6) \
        * (min(1.0, float(node[0])) if node is not None else 1.0)
    return scale * fit if scale * fit >= lo else scale


#: Share of its envelope's area below which a floor is round (a circle fills 79%): what lies
#: on it must fit inside its shape, not its envelope.
ROUND_FLOOR = 0.9


def _rect_in(region, e1: float, e2: float) -> float:
    """The largest factor ``f`` (to 1%) such that an ``f e1`` by ``f e2`` rectangle centred on
    the region's centroid lies inside it, over a few turns (along its envelope's sides and at
    45 degrees): a round basket's floor holds a towel along its diameter's inscribed square,
    not its bounding box."""
    import shapely

    if region.is_empty or e1 <= 0 or e2 <= 0:
        return 0.0
    c = region.centroid
    r = region.minimum_rotated_rectangle
    xy = np.asarray(r.exterior.coords) if r.geom_type == "Polygon" else np.zeros((3, 2))
    a0 = float(np.arctan2(*(xy[1] - xy[0])[::-1]))
    x0, y0, x1, y1 = region.bounds
    hi = 2.0 * max(x1 - x0, y1 - y0) / min(e1, e2)
    best = 0.0
    for a in (a0, a0 + np.pi / 2, a0 + np.pi / 4, a0 - np.pi / 4):
        box = shapely.affinity.rotate(shapely.box(-e1 / 2, -e2 / 2, e1 / 2, e2 / 2), a,
                                      origin=(0, 0), use_radians=True)
        box = shapely.affinity.translate(box, c.x, c.y)
        lo, top = best, hi
        if not region.buffer(1e-9).contains(shapely.affinity.scale(box, lo, lo, origin=c)) \
                and lo > 0:
            continue
        while top - lo > 0.01:
            mid = 0.5 * (lo + top)
            inside = region.buffer(1e-9).contains(shapely.affinity.scale(box, mid, mid, origin=c))
            lo, top = (mid, top) if inside else (lo, mid)
        best = max(best, lo)
    return best


#: Pool slots per candidate category looked at for a child that nests in one of its kind.
NEST_SLOTS = 8


def nest_instance(st: SolveState, library, edge, category: str, asset: Asset, usable,
                  tried: set[str], rng: np.random.Generator) -> tuple[str, Asset]:
    """``(category, asset)`` for a child IN a placed object of its own kind (a basket in a
    basket, a bowl in a bowl): the drawn instance when, at its category's own size, it is no
    wider than the parent; else, over :data:`NEST_SLOTS` random pool slots per candidate
    category (untried, ``usable(asset)`` true), the widest that is (it nests deepest), or the
    narrowest looked at when none is. Unchanged for anything else."""
    if edge.relation != "IN" or edge.parent.is_room_element \
            or getattr(library, "load", None) is None:
        return category, asset
    oid, pid = edge.child.object, edge.parent.object
    parent = st.scene.objects.get(pid)
    if parent is None or not parent.placed or not (
            set(st.pag.objects[oid].candidates) & set(st.pag.objects[pid].candidates)):
        return category, asset
    theirs = float(np.ptp(world_points(parent, hull_only=True, settled=False)[:, :2],
                          axis=0).max())

    def width(a: Asset) -> float:
        lo, hi = a.size_range
        g = asset_geometry(a)
        unit = float(np.clip(1.0, lo / max(g.size, 1e-6), hi / max(g.size, 1e-6)))
        return unit * float(np.ptp(g.hull[:, :2], axis=0).max())

    if width(asset) <= theirs:
        return category, asset
    best, narrow = None, (width(asset), category, asset)
    k = int(getattr(library, "per_category", 20))
    cands = st.pag.objects[oid].candidates
    for ci in rng.permutation(len(cands)):
        cat = cands[int(ci)]
        for slot in rng.permutation(k)[:NEST_SLOTS]:
            a = library.load(cat, int(slot))
            if a.asset_id in tried or not usable(a):
                continue
            w = width(a)
            if w <= theirs and (best is None or w > best[0]):
                best = (w, cat, a)
            if w < narrow[0]:
                narrow = (w, cat, a)
    got = best or narrow
    return got[1], got[2]


#: Metres above a part's top within which another part of the asset covers it.
COVER_REACH = 0.2
_FREE_TOPS: dict[str, object] = {}


def _largest_free_top(asset: Asset):
    """The part of ``asset`` with the largest upward top of which the asset's other parts
    leave at least half free (within :data:`COVER_REACH` above it): a bed's mattress, not the
    deck under it; None when no part has one."""
    if asset.asset_id in _FREE_TOPS:
        return _FREE_TOPS[asset.asset_id]
    from shapely.geometry import Polygon

    from ..geometry import regions as RG

    best, area = None, 0.0
    for part in asset.parts:
        s = part.surfaces.get("top")
        if s is None or float(s.normal[2]) < 0.99:
            continue
        top = Polygon(s.to_3d(np.asarray(filled(s.polygon).convex_hull.exterior.coords))[:, :2])
        free = top
        for other in asset.parts:
            if other is part:
                continue
            for pc in other.piece_arrays:
                h = pc.vertices[:, 2] - float(s.origin[2])
                if h.max() > 1e-3 and h.min() < COVER_REACH:
                    free = free.difference(Polygon(RG.convex_footprint(pc.vertices[:, :2])))
        if free.area >= 0.5 * top.area and top.area > area:
            best, area = part, top.area
    if len(_FREE_TOPS) > 4096:
        _FREE_TOPS.clear()
    _FREE_TOPS[asset.asset_id] = best
    return best


def in_on_top(st: SolveState, edge, asset: Asset, scale: float):
    """For a child ``IN`` a whole placed object that has no inside with room for it (a folded
    blanket IN a bed, whose only insides are the slivers of the tape sewn round its
    mattress): the edge it is placed by instead, ``ON`` the object's largest free top (the
    mattress), where the ``IN`` check measures it too (``measure.insides``); None for anything
    else."""
    if edge.relation != "IN" or edge.parent.is_room_element or edge.parent.part is not None:
        return None
    parent = st.scene.objects.get(edge.parent.object)
    if parent is None or not parent.placed or parent.asset is None or not parent.asset.internal:
        return None
    if not no_room(parent.asset, parent.scale, asset, scale):
        return None
    from dataclasses import replace

    from ..pag.refs import format_ref

    best = _largest_free_top(parent.asset)
    if best is None:
        return None
    p, c = edge.parent, edge.child
    return Edge("ON", replace(c, surface=None, text=format_ref(c.object, c.part, c.index, None)),
                replace(p, part=best.label, index=None, surface="top",
                        text=format_ref(p.object, best.label, None, "top")), {})
