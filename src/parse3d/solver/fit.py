"""Room on a support's top for what goes ON it: a microwave on a dorm fridge, a tray on a mini
fridge, a herb pot on a window sill.

A parent is drawn before its children, so an instance (or a scale within the node's range) whose
top cannot take even the smallest instance of a child written ON it fails that child later,
whatever is drawn for it ("a 0.40 x 0.61 m footprint does not fit its 0.35 x 0.25 m surface").
When a parent is placed, :func:`need` gives the smallest footprint each such child comes in (over
the pool slots looked at, at the least scale its node allows) and :func:`roomy_instance` /
:func:`roomy_scale` draw a parent whose named top takes it: the drawn instance when it does, else
an instance looked at that does (or comes closest), then a scale within the node's range (and
the category's size range) that makes room. A part smaller than the object's footprint (a
burner) is meant to be overhung (a pot on it) and draws as before. The child, failing for room, then draws its smallest
instance (``placement.place_object``), which now fits.
"""

from __future__ import annotations

import operator
import zlib
from functools import cache

import numpy as np

from ..assets.model import Asset
from ..pag.model import Edge
from .geometry import asset_geometry, hull_extents
from .state import SolveState
from .support import filled

__all__ = ["CONTENTS_AREA", "beside", "contents_scale", "instance_for", "need", "roomy_instance", "roomy_scale", "top_fit", "top_sides"]

#: Pool slots per candidate category looked at for a child's smallest footprint and for a
#: parent with room on its top.
FIT_SLOTS = 8
#: Share of a top's sides (its minimum rotated rectangle) a child's footprint may take: the
#: margin support regions keep and what stands at the top's edges (hinges, rims).
FIT_SHARE = 0.92
#: Axis of the child's own frame along its contact surface's normal.
_AXES = {"top": 2, "bottom": 2, "front": 1, "back": 1, "right": 0, "left": 0}


def _on_top_edges(st: SolveState, oid: str) -> list[Edge]:
    """ON edges (support edges) whose parent is ``oid`` on a top surface, child not placed and
    not of its kind."""
    out = []
    for e in st.pag.relations:
        if e.relation != "ON" or e.parent.object != oid or e.parent.is_room_element:
            continue
        if (e.parent.surface or "top") != "top" or st.pag.supporter(e.child.object) is not e:
            continue
        child = st.scene.objects.get(e.child.object)
        if child is not None and child.placed:
            continue
        if set(st.pag.objects[e.child.object].candidates) & set(st.pag.objects[oid].candidates):
            continue  # a stack of its kind: the upper one may overhang (a loaf on a loaf)
        out.append(e)
    return out


def _unit_scale(asset: Asset) -> float:
    """The scale that brings ``asset`` into its category's size range (1 when it is in it)."""
    lo, hi = asset.size_range
    size = asset_geometry(asset).size
    return float(np.clip(1.0, lo / max(size, 1e-6), hi / max(size, 1e-6)))


@cache
def _smallest_footprint(library, category: str, axis: int, n: int) -> tuple[float, float]:
    """``(short, long)`` sides (m, at the category's own scale) of the smallest footprint among
    the first ``n`` pool slots of ``category`` lying on the face normal to ``axis``."""
    best = None
    for slot in range(n):
        a = library.load(category, slot)
        ext = hull_extents(a)[0] * _unit_scale(a)
        sides = sorted(float(ext[k]) for k in range(3) if k != axis)
        if best is None or sides[0] * sides[1] < best[0] * best[1]:
            best = (sides[0], sides[1])
    return best


#: Footprint area a container needs per child IN it, in units of the child's typical size
#: squared (room to lie side by side, with the gaps round things leave).
CONTENTS_AREA = 2.5


def _contents(pag, oid: str) -> list[str]:
    """The children written IN ``oid`` as a whole (an index kept on the graph, rebuilt
    whenever its relations change)."""
    rel = pag.relations
    got = pag.__dict__.get("_contents_index")
    if got is None or len(got[0]) != len(rel) or not all(map(operator.is_, got[0], rel)):
        idx: dict[str, list[str]] = {}
        for e in rel:
            if e.relation == "IN" and e.parent.part is None and not e.parent.is_room_element:
                idx.setdefault(e.parent.object, []).append(e.child.object)
        got = (list(rel), idx)
        pag.__dict__["_contents_index"] = got
    return got[1].get(oid, [])


def contents_scale(pag, oid: str, asset: Asset) -> float:
    """Scale at which ``asset``'s footprint has room for the children IN the object as a whole
    (not on a named part: shelves of a rack hold their own), at ``CONTENTS_AREA`` times their
    typical size squared each; 0 with fewer than two such children."""
    from .hanging import typical_size

    kids = _contents(pag, oid)
    if len(kids) < 2:
        return 0.0
    need = sum(CONTENTS_AREA * typical_size(pag, k) ** 2 for k in kids)
    ext = np.ptp(asset_geometry(asset).bounds, axis=0)
    area = float(ext[0] * ext[1])
    return float(np.sqrt(need / area)) if area > 0 else 0.0


def _grown_footprint(st: SolveState, library, oid: str, category: str, axis: int,
                     n: int) -> tuple[float, float] | None:
    """As :func:`_smallest_footprint`, each slot at the scale the child is drawn at to hold
    what is IN it or hangs below it (``choice.instance_scale``: a dish rack with plates and a
    glass in it, towels on a bar), for a child that holds such things; None for any other."""
    from .hanging import rail_scale

    best = None
    for slot in range(n):
        a = library.load(category, slot)
        grow = max(contents_scale(st.pag, oid, a), rail_scale(st.pag, oid, a))
        if grow <= 0 and best is None and slot == 0:
            return None  # holds nothing: the category's own sizes
        hi = a.size_range[1] / max(asset_geometry(a).size, 1e-6)
        ext = hull_extents(a)[0] * max(_unit_scale(a), min(grow, hi))
        sides = sorted(float(ext[k]) for k in range(3) if k != axis)
        if best is None or sides[0] * sides[1] < best[0] * best[1]:
            best = (sides[0], sides[1])
    return best


def need(st: SolveState, library, e: Edge, grown: bool = False) -> tuple[float, float] | None:
    """``(short, long)`` sides (m) of the smallest footprint the child of ``e`` comes in: over
    its candidate categories and the first :data:`FIT_SLOTS` pool slots, at the least scale its
    node allows; with ``grown``, at the size a child holding things IN it is drawn to hold
    them (:func:`_grown_footprint`). None when the library cannot be looked through."""
    if getattr(library, "load", None) is None:
        return None
    node = st.pag.objects[e.child.object]
    axis = _AXES.get(e.child.surface or "bottom", 2)
    n = min(FIT_SLOTS, int(getattr(library, "per_category", 20)))
    lo = node.scale[0] if node.scale is not None else 1.0
    best = None
    for cat in node.candidates:
        a, b = grown and _grown_footprint(st, library, e.child.object, cat, axis, n) \
            or _smallest_footprint(library, cat, axis, n)
        if best is None or a * b < best[0] * best[1]:
            best = (a * lo, b * lo)
    return best


def _sides(poly) -> tuple[float, float]:
    """The short and long sides (m) of a polygon's minimum rotated rectangle."""
    r = poly.minimum_rotated_rectangle
    if r.geom_type != "Polygon":
        return 0.0, 0.0
    xy = np.asarray(r.exterior.coords)[:3]
    a, b = float(np.linalg.norm(xy[1] - xy[0])), float(np.linalg.norm(xy[2] - xy[1]))
    return min(a, b), max(a, b)


def top_sides(asset: Asset, e: Edge) -> tuple[float, float]:
    """``(short, long)`` sides (m, unit scale) of the largest top the parts ``e`` names on
    ``asset`` offer (their minimum rotated rectangle); ``(0, 0)`` when there is none."""
    ps = asset.parts_by_label(e.parent.part) if e.parent.part is not None else list(asset.parts)
    if e.parent.index is not None:
        ps = ps[e.parent.index:e.parent.index + 1]
    best = (0.0, 0.0)
    for p in ps:
        top = p.surfaces.get("top")
        if top is None:
            continue
        a, b = _sides(filled(top.polygon))
        if a * b > best[0] * best[1]:
            best = (a, b)
    return best


def _room(asset: Asset, scale: float, e: Edge, want: tuple[float, float]) -> float:
    """How far the top ``e`` names, at ``scale``, is from taking ``want``: the largest ratio of
    a needed side to the side it goes on (<= 1: it fits)."""
    a, b = top_sides(asset, e)
    if a <= 0:
        return float("inf")
    return max(want[0] / (FIT_SHARE * a * scale), want[1] / (FIT_SHARE * b * scale))


#: Share of a top's area the smallest footprints of all the children written ON it may take
#: together (a dining table and its chairs on a rug, two suitcases on a luggage cart).
AREA_SHARE = 0.7


def _gap(asset: Asset, scale: float, needs) -> float:
    """How far ``asset`` at ``scale`` is from having room for ``needs`` (``(edge, (short,
    long))`` per child): the largest of each child's side ratios (:func:`_room`) and, per top,
    the square root of the children's summed footprints over :data:`AREA_SHARE` of its area
    (<= 1: they fit)."""
    g = max(_room(asset, scale, e, want) for e, want in needs)
    tops: dict[tuple, float] = {}
    for e, want in needs:
        key = (e.parent.part, e.parent.index)
        tops[key] = tops.get(key, 0.0) + want[0] * want[1]
        a, b = top_sides(asset, e)
        if a > 0:
            g = max(g, float(np.sqrt(tops[key] / (AREA_SHARE * a * b))) / scale)
    return g


#: Share of an object's footprint its named top must cover to be drawn with room for what goes
#: ON it (a fridge's body, not a stove's burner).
MAIN_TOP = 0.5


def _main_top(asset: Asset, e: Edge) -> bool:
    """Whether the top ``e`` names covers :data:`MAIN_TOP` of the asset's footprint."""
    a, b = top_sides(asset, e)
    ext = hull_extents(asset)[0]
    return a * b >= MAIN_TOP * float(ext[0] * ext[1])


def _needs(st: SolveState, library, oid: str, asset: Asset, grown: bool = False
           ) -> list[tuple[Edge, tuple[float, float]]]:
    out = []
    for e in _on_top_edges(st, oid):
        if not _main_top(asset, e):
            continue
        want = need(st, library, e, grown)
        if want is not None:
            out.append((e, want))
    return out


def _max_scale(st: SolveState, oid: str, asset: Asset) -> float:
    """The largest scale the node and the category's size range allow ``asset``."""
    node = st.pag.objects[oid]
    hi = asset.size_range[1] / max(asset_geometry(asset).size, 1e-6)
    top = node.scale[1] if node.scale is not None else 1.0
    return min(top * _unit_scale(asset), max(hi, _unit_scale(asset)))


def roomy_instance(st: SolveState, library, oid: str, category: str, asset: Asset, usable,
                   tried: set[str], rng: np.random.Generator) -> tuple[str, Asset]:
    """``(category, asset)``: the drawn instance when, at the largest scale its node allows,
    its top takes the smallest footprint of every child written ON it; else the first untried
    instance that does (over the node's candidate categories, :data:`FIT_SLOTS` random pool
    slots each, ``usable(asset)`` true), or the one that comes closest. Only tops that are
    the object's own (at least :data:`MAIN_TOP` of its footprint) count: a pot is wider than
    any burner and overhangs it. The instances are first looked through (from a draw of their
    own) for room for the children at the size they are drawn to hold what is IN them
    (:func:`need` ``grown``), then, when none has it, at their smallest."""
    if getattr(library, "load", None) is None:
        return category, asset
    best = None
    # room for the children at the size they are drawn (a bowl grown for its apples), else
    # at their smallest (they shrink to fit the top)
    bare = _needs(st, library, oid, asset, False)
    if not bare:
        return category, asset
    grown = _needs(st, library, oid, asset, True)
    for needs in ([grown, bare] if grown != bare else [bare]):
        def gap(a: Asset, needs=needs) -> float:
            return _gap(a, _max_scale(st, oid, a), needs)

        here = gap(asset)
        if here <= 1.0:
            return category, asset
        best = (here, category, asset)
        k = int(getattr(library, "per_category", 20))
        cands = st.pag.objects[oid].candidates
        # the first pass draws from its own stream: when it finds nothing, the second draws
        # as if it had not run
        draw = rng if needs is bare else np.random.default_rng(
            zlib.crc32(f"{oid} {asset.asset_id}".encode()))
        for ci in draw.permutation(len(cands)):
            cat = cands[int(ci)]
            for slot in draw.permutation(k)[:FIT_SLOTS]:
                a = library.load(cat, int(slot))
                if a.asset_id in tried or not usable(a):
                    continue
                g = gap(a)
                if g < best[0]:
                    best = (g, cat, a)
                if g <= 1.0:
                    return cat, a
    return best[1], best[2]


def roomy_scale(st: SolveState, library, oid: str, asset: Asset, scale: float) -> float:
    """``scale``, or larger so that the top of ``asset`` takes the smallest footprint of every
    child written ON it (and all of them together, :func:`_gap`), when what the node and the
    category's size range allow does."""
    needs = _needs(st, library, oid, asset)
    if not needs:
        return scale
    g = _gap(asset, scale, needs)
    if g <= 1.0 or not np.isfinite(g) or scale * g > _max_scale(st, oid, asset):
        return scale  # fits, or no scale allowed makes room (the child may overhang)
    return scale * g


#: Sides of a child that the objects written SIDE_OF it stand along (beside it on its top).
_BESIDE = ("left", "right")


def beside(st: SolveState, library, edge: Edge) -> float:
    """Metres the unplaced objects written ``SIDE_OF`` the child of ``edge`` (left or right of
    it) on the same support take along the top: the short side of the smallest footprint each
    comes in (speakers either side of a television on a console)."""
    if library is None:
        return 0.0
    kid, total = edge.child.object, 0.0
    for e in st.pag.relations:
        if e.relation != "SIDE_OF" or e.parent.object != kid or e.param("side") not in _BESIDE:
            continue
        other = st.scene.objects.get(e.child.object)
        if other is not None and other.placed:
            continue
        sup = st.pag.supporter(e.child.object)
        if sup is None or sup.relation != "ON" or sup.parent.object != edge.parent.object \
                or sup.parent.part != edge.parent.part:
            continue
        want = need(st, library, sup)
        if want is not None:
            total += want[0]
    return total


def top_fit(st: SolveState, edge: Edge, asset: Asset, scale: float, axis: int,
            library=None) -> float:
    """``scale``, or less so that the child ``ON`` an object's top fits the largest of its
    supports (a herb pot on a 12 cm window sill): down to the least scale the node's own
    ``scale`` range allows, which the writer said is meant (when even that does not fit, the
    smaller child overhangs under the stability rule); without a node range, only when
    shrinking within the category's size range makes it fit (a television wider than its
    stand keeps its size). Unchanged for a stack of one category (a child may overhang one
    of its kind) and anything not ON an object. With ``library``, the objects written beside
    the child on the same top (:func:`beside`) take their share of its long side first."""
    from .config import Fail
    from .support import support_candidates

    if edge.relation != "ON" or edge.parent.is_room_element \
            or edge.parent.object not in st.scene.objects:
        return scale
    node = st.pag.objects[edge.child.object]
    if set(node.candidates) & set(st.pag.objects[edge.parent.object].candidates):
        return scale
    try:
        sups = support_candidates(st, edge)
    except Fail:
        return scale
    ext = hull_extents(asset)[0]
    c0, c1 = sorted(scale * float(ext[k]) for k in range(3) if k != axis)
    best = float("inf")
    side = beside(st, library, edge)
    for sup in sups:
        s0, s1 = _sides(sup.region)
        if s0 > 0 and FIT_SHARE * s1 > side:
            best = min(best, max(c0 / (FIT_SHARE * s0), c1 / (FIT_SHARE * s1 - side)))
    if best <= 1.0 or not np.isfinite(best):
        return scale
    target = scale / best
    if node.scale is not None:
        return max(target, min(scale, node.scale[0] * _unit_scale(asset)))
    lo = asset.size_range[0] / max(asset_geometry(asset).size, 1e-6)
    if side > 0:  # room beside it: as small as its category allows, if not small enough
        return max(target, min(scale, lo))
    return target if target >= lo else scale


def instance_for(st: SolveState, library, oid: str, edge: Edge, category: str, asset: Asset,
                 usable, tried: set[str], rng: np.random.Generator) -> tuple[str, Asset]:
    """``(category, asset)`` for the first attempt at ``oid`` (its support edge ``edge``): one
    that nests in the object of its kind it goes IN (:func:`.nesting.nest_instance`), then one
    with room on its top for what goes ON it (:func:`roomy_instance`)."""
    from .nesting import nest_instance

    category, asset = nest_instance(st, library, edge, category, asset, usable, tried, rng)
    return roomy_instance(st, library, oid, category, asset, usable, tried, rng)
