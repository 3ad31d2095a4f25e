"""Stage 1 of Algorithm 1, instance choice: what an object's asset must have for its relations
(:func:`requirements`, :func:`lacks`), the instance drawn instead when one lacks it
(:func:`alternative_instance`) and the sizes it must fit (free height, spans, contents)."""

from __future__ import annotations

import operator
import zlib
from dataclasses import replace

import numpy as np
import shapely
import shapely.affinity
from shapely.geometry import Polygon

from ..assets.model import Asset
from ..geometry import regions as RG
from ..measure.checks import BOARD_LABELS, DIST_TOL, board_parts
from ..pag.model import Edge
from ..relations import SURFACES
from .bars import across_need
from .config import Fail
from .coverings import covering_scale
from .fit import CONTENTS_AREA, FIT_SHARE, contents_scale, roomy_scale, top_fit
from .fit import _sides as sup_sides
from .geometry import asset_geometry, hull_extents, part_points, rect_sides
from .hanging import below_room, edge_up, hang_room, rail_scale, thinness, typical_size
from .intent import names_part, overhang, soft
from .nesting import floor_fit
from .rules import RULES
from .rules.alignment import level_miss
from .standing import floor_takes
from .state import SolveState, plane_coords
from .support import _flat_cached, _flat_enough, cover_part, filled, support_candidates

__all__ = ["THIN_HANG", "hung_edge_up", "HEADROOM_FIT", "SURFACE_AXES", "extent_along",
           "extent_across", "SPAN_PART", "SPAN_BEARING", "span_need", "free_headroom",
           "CONTENTS_AREA", "contents_scale", "edge_text", "touching", "requirements", "lacks",
           "FREE_TOP", "FLAT_TOL", "lies_flat", "top_lies_flat", "TOP_BAND", "RIM_WIDTH", "RIM_OPENING", "rounded_rim",
           "free_top", "LAYER", "RANKED_SLOTS", "boards_hold", "too_tall_failure", "room_failure",
           "alternative_instance", "HANG_ROOM", "hang_reqs", "level_instance", "flush_edges", "part_overhang", "draw_instance",
           "instance_scale"]


#: A child whose height is at most this share of its next smaller extent is thin (a folded
#: towel, a flat bag): hung from an object's part it hangs edge-up, not flat.
THIN_HANG = 0.35


def hung_edge_up(edge: Edge, asset: Asset) -> Edge | None:
    """The support edge by which a thin child named by no surface, or by its top, hangs below
    an object's part (a towel on a bar, a flat bag on a hook): by its back, so it hangs
    edge-up, thin across the rail, and several hang along one rail (a towel hung flat by its
    top would stick out from the wall like a shelf); None for anything else (the edge as
    written)."""
    if not edge_up(edge):
        return None
    ext = np.ptp(asset_geometry(asset).bounds, axis=0)
    if ext[2] > THIN_HANG * float(np.sort(ext)[1]):
        return None
    from ..pag.refs import format_ref

    c = edge.child
    return replace(edge, child=replace(c, surface="back",
                                       text=format_ref(c.object, c.part, c.index, "back")))


#: Fraction of a shelf's free height an instance chosen or shrunk to fit under it may fill.
HEADROOM_FIT = 0.97


#: Asset-frame axis of each surface label's normal.
SURFACE_AXES = {"top": 2, "bottom": 2, "front": 1, "back": 1, "right": 0, "left": 0}


def extent_along(asset: Asset, axis: int) -> float:
    """The asset's extent (m, unit scale) along one of its own axes."""
    return float(hull_extents(asset)[0][axis])


def extent_across(asset: Asset, axis: int) -> float:
    """The asset's longest extent (m, unit scale) across ``axis`` (its support normal)."""
    ext = hull_extents(asset)[0]
    return float(max(ext[k] for k in range(3) if k != axis))


#: A part narrower than this (m) is too narrow to stand things on alone (a stand's arm).
SPAN_PART = 0.06


#: How far (m) beyond the middles of the two outer parts a spanning child must reach.
SPAN_BEARING = 0.03


def span_need(st: SolveState, edge: Edge) -> float:
    """The least length (m) an ``ON`` child needs to rest across the parts a spanning support
    joins (the two arms of a keyboard stand: their distance plus a bearing), when each of those
    parts alone is too narrow to stand on; 0 otherwise."""
    if edge.relation != "ON" or edge.parent.is_room_element or edge.parent.part is None \
            or edge.parent.index is not None:
        return 0.0
    parent = st.scene.objects.get(edge.parent.object)
    if parent is None or not parent.placed:
        return 0.0
    return st.memo(edge.parent.object, ("span-need", str(edge.parent)),
                   lambda: _span_length(st, edge))


def _span_length(st: SolveState, edge: Edge) -> float:
    try:
        sups = support_candidates(st, edge)
    except Fail:
        return 0.0
    if not any(s.spans for s in sups):
        return 0.0
    single = [s for s in sups if not s.spans]
    if any(rect_sides(s.region)[0] >= SPAN_PART for s in single):
        return 0.0
    mid = [np.asarray(s.surface.to_3d(np.asarray(s.region.centroid.coords)))[0] for s in single]
    gaps = [float(np.linalg.norm(a - b)) for i, a in enumerate(mid) for b in mid[i + 1:]]
    return min(gaps) + 2 * SPAN_BEARING if gaps else 0.0


def free_headroom(st: SolveState, edge: Edge) -> float:
    """The most free height (m) over the internal surfaces an ``IN`` child may rest on (the
    tallest shelf gap of a rack), or between an ``ON`` child's support surfaces on an object
    and the ceiling; inf for other supports, open containers or an unplaced parent."""
    if edge.relation not in ("IN", "ON") or edge.parent.is_room_element:
        return float("inf")
    parent = st.scene.objects.get(edge.parent.object)
    if parent is None or not parent.placed:
        return float("inf")
    return st.memo(edge.parent.object, ("headroom", edge.relation, str(edge.parent)),
                   lambda: _free_height(st, edge))


def _free_height(st: SolveState, edge: Edge) -> float:
    try:
        sups = support_candidates(st, edge)
    except Fail:
        return float("inf")
    if edge.relation == "ON":  # up to the ceiling (a wine rack on a tall cabinet)
        return max(st.scene.room.height - float(s.surface.origin[2]) for s in sups)
    return max(s.clearance for s in sups)


def edge_text(e: Edge) -> str:
    """An edge as failure reasons and requirements write it: ``AGAINST a:b@back -> wall_1``."""
    return f"{e.relation} {e.child} -> {e.parent}"


def touching(pag, oid: str) -> list[Edge]:
    """The edges of ``pag`` naming ``oid`` as child or parent, in file order (an index kept on
    the graph, rebuilt whenever its relations change)."""
    rel = pag.relations
    got = pag.__dict__.get("_touch_index")
    if got is None or len(got[0]) != len(rel) or not all(map(operator.is_, got[0], rel)):
        idx: dict[str, list[Edge]] = {}
        for e in pag.relations:
            idx.setdefault(e.child.object, []).append(e)
            if e.parent.object != e.child.object:
                idx.setdefault(e.parent.object, []).append(e)
        got = (list(rel), idx)  # the same edges, compared by identity
        pag.__dict__["_touch_index"] = got
    return got[1].get(oid, [])


def requirements(pag, oid: str) -> list[tuple[str, int | None, str, str]]:
    """What the object's asset must have, from every relation naming one of its parts:
    ``(part label, index or None, relation text, kind)`` with kind ``part`` (the part and
    ``#k`` exist), ``internal`` (an IN parent part holds an internal support surface),
    ``free_top`` (an ON parent part is flat with room on top), ``stack_base`` (an ON parent of
    the child's own category does not roll: the base of a stack) or ``extreme:<label>`` (an
    AGAINST child part reaches furthest along its surface normal)."""
    out = []
    for e in touching(pag, oid):
        text = edge_text(e)
        rule = RULES[e.relation]  # what each relation asks: rules/support.py, contact.py
        out += rule.needs(pag, oid, e, text)
        for ref, role in ((e.child, "child"), (e.parent, "parent")):
            if ref.object != oid or ref.part is None:
                continue
            out.append((ref.part, ref.index, text, "part"))
            out += rule.part_needs(e, ref, role, text)
        if e.relation == "HANGING_BELOW" and e.parent.object == oid \
                and e.child.object != oid and (depth := typical_size(pag, e.child.object)) > 0:
            # a part with room below it for the child to hang (a rack's rail, not its tines)
            out.append((e.parent.part, e.parent.index, text, f"{HANG_ROOM}:{depth:.3f}"))
    return out


#: Requirement kind: a part with room below it for a hung child (``hang_room:<metres>``).
HANG_ROOM = "hang_room"


def hang_reqs(reqs) -> list:
    """The requirements among ``reqs`` that ask room below a part for a hung child."""
    return [r for r in reqs if r[3].startswith(HANG_ROOM + ":")]


def lacks(asset: Asset, reqs) -> str | None:
    """Why ``asset`` cannot meet ``reqs`` (see :func:`requirements`), or None."""
    for label, idx, text, kind in reqs:
        if kind.startswith(HANG_ROOM + ":"):
            depth = float(kind.split(":")[1])
            if hang_room(asset, label, idx, depth) is None \
                    and (label is None or not below_room(asset, label, idx, depth)):
                # (a part right below the named one with room holds it: hanging.hang_over)
                where = "any part" if label is None else f"its {label}"
                return (f"{asset.asset_id} has no room below {where} for a {depth:.2f} m "
                        f"thing to hang ({text})")
            continue
        if kind == "internal" and label is None:
            if not asset.internal and not any(free_top(asset, p) for p in board_parts(asset)):
                return f"{asset.asset_id} holds nothing inside ({text})"
            continue  # an inside, or boards that hold what is IN it on their tops
        if kind == "stack_base" and label is None:
            if not any(lies_flat(asset, p) for p in asset.parts):
                return (f"{asset.asset_id} would roll: neither its top nor its bottom is flat "
                        f"to stack on ({text})")
            if not top_lies_flat(asset):
                return (f"{asset.asset_id}'s uppermost part is not flat: the next one of its "
                        f"kind would balance on it (a hanger's hook) ({text})")
            continue
        ps = asset.parts_by_label(label)
        if not ps:
            return f"{asset.asset_id} has no part {label!r} ({text})"
        if idx is not None and idx >= len(ps):
            return f"{asset.asset_id} has {len(ps)} {label} part(s), no #{idx} ({text})"
        ps = ps[idx:idx + 1] if idx is not None else ps
        if kind in ("internal", "internal_or_board"):
            names = {p.name for p in ps}
            if kind == "internal_or_board" and label in BOARD_LABELS \
                    and not any(i.part in names for i in asset.internal) \
                    and any(free_top(asset, p) for p in ps):
                continue  # a board holds what is IN it on its top
            if not any(i.part in names for i in asset.internal):
                return f"{asset.asset_id}'s {label} holds nothing inside ({text})"
        elif kind == "free_top":
            if all(rounded_rim(asset, p) for p in ps):
                return (f"{asset.asset_id}'s {label} top is a rounded rim, no flat band "
                        f"{RIM_WIDTH * 100:.0f} cm wide: what stands on it tips over ({text})")
            if not any(free_top(asset, p) or (q := cover_part(asset, p)) is not None
                       and free_top(asset, q) for p in ps):
                if not any(_flat_cached(asset.asset_id, p, "top") for p in ps):
                    return (f"{asset.asset_id}'s {label} is slanted: its top is no surface to "
                            f"stand on ({text})")
                return (f"{asset.asset_id}'s {label} top is mostly covered by its other parts, "
                        f"no room for a {FREE_TOP * 100:.0f} cm wide item ({text})")
        elif kind == "stack_base":
            if not any(lies_flat(asset, p) for p in ps):
                return (f"{asset.asset_id}'s {label} would roll: neither its top nor its bottom "
                        f"is flat to stack on ({text})")
            if not any(clear_middle(asset, p) for p in ps):
                return (f"{asset.asset_id}'s {label} has a part standing on the middle of its "
                        f"top (a knob): the next one of its kind would balance on it ({text})")
        elif kind.startswith("extreme:"):
            n = np.asarray(SURFACES[kind.split(":")[1]], float)
            side = kind.split(":")[1]
            mine = float(np.max(part_points(ps) @ n))
            who = max(asset.parts, key=lambda p: float(np.max(part_points([p]) @ n)))
            d = float(np.max(part_points([who]) @ n)) - mine
            if d > 2e-3:
                oid = text.split(" ")[1].split(":")[0]
                return (f"{text}: {oid}:{who.label} reaches {d:.2f} m further {side} than "
                        f"{oid}:{label} (asset {asset.asset_id}): name {oid}:{who.label}@{side} "
                        f"or {oid}@{side}")
    return None


#: Width (m) of the smallest item a part's top must have room for (stage 1's reachability).
FREE_TOP = 0.08
_FREE_TOP: dict[tuple[str, str], bool] = {}


#: Metres within which a stack base's top or bottom face must lie over half its area.
FLAT_TOL = 3e-3


_LIES_FLAT: dict[tuple[str, str], bool] = {}


def lies_flat(asset: Asset, part) -> bool:
    """Whether the part's top or bottom is flat (within ``FLAT_TOL`` over half its bounding
    box face): a folded towel or a box can be the base of a stack of its kind; a rolled towel,
    round above and below, would roll away under the next one."""
    key = (asset.asset_id, part.name)
    got = _LIES_FLAT.get(key)
    if got is None:
        if len(_LIES_FLAT) > 8192:
            _LIES_FLAT.clear()
        got = _LIES_FLAT[key] = any(_flat_enough(part, lb, tol=FLAT_TOL, frac=0.5)
                                    for lb in ("top", "bottom"))
    return got


#: Metres below an asset's highest point within which its parts make its top (what the next
#: one of its kind rests on).
TOP_BAND = 0.01


def top_lies_flat(asset: Asset, span: float | None = None) -> bool:
    """Whether a part making the asset's top (within ``TOP_BAND`` of its highest point) lies
    flat and spans at least ``span`` (default ``TOP_SPAN``) of the asset's footprint: a folded
    shirt's top fold, not a hanger's hook above a dress nor the tape loop above a coat's
    collar."""
    span = TOP_SPAN if span is None else span
    key = (asset.asset_id, f"<top {span:g}>")
    got = _LIES_FLAT.get(key)
    if got is None:
        pts = [part_points([p]) for p in asset.parts]
        zs = [float(q[:, 2].max()) for q in pts]
        foot = float(np.prod(np.ptp(np.vstack(pts)[:, :2], axis=0)))
        got = _LIES_FLAT[key] = any(
            lies_flat(asset, p) and float(np.prod(np.ptp(q[:, :2], axis=0))) >= span * foot
            for p, q, z in zip(asset.parts, pts, zs, strict=True) if z > max(zs) - TOP_BAND)
    return got


#: Share of its footprint (bounding box) the flat top of a thing round in outline must span to
#: carry the next one of its kind: a paint can's lid, a cube box's top; not a cherry tomato's
#: calyx.
LID_SPAN = 0.5


def round_unlidded(asset: Asset) -> bool:
    """Round in outline, as wide as deep and tall (extents within 30 %), with no flat top
    spanning ``LID_SPAN`` of its footprint: an apple, a cherry tomato under its calyx; not a
    paint can or a cube box."""
    ext = hull_extents(asset)[0]
    return float(ext.max()) <= 1.3 * float(ext.min()) and not top_lies_flat(asset, LID_SPAN)


def no_stack_base(asset: Asset, ref) -> bool:
    """Whether the next one of its kind cannot stand on ``asset`` (the part ``ref`` names, if
    any), so it rests beside it in a heap (:func:`parse3d.solver.intent.beside`): it lacks
    the ``stack_base`` :func:`lacks` asks for (a flat base or top, nothing standing on its
    middle), or it is round with no lid (:func:`round_unlidded`)."""
    return lacks(asset, [(ref.part, ref.index, "", "stack_base")]) is not None \
        or round_unlidded(asset)


#: Share of an asset's footprint (bounding box) a flat top part must span to carry the next
#: one of its kind (a hanging loop's 0.3 % does not).
TOP_SPAN = 0.01


#: Width (m) of the flat band a rim (a top around an opening) needs for things to stand on it.
RIM_WIDTH = 0.03
#: Width (m) of an opening no small child spans (a tub, not a burner ring a pot sits across).
RIM_OPENING = 0.3


_ROUNDED: dict[tuple[str, str], bool] = {}


def rounded_rim(asset: Asset, part) -> bool:
    """Whether the part's top is a rim around an opening at least ``RIM_OPENING`` wide (its
    top surface has such a hole: no small child spans it) that is rounded: no convex piece of
    it is flat (within ``FLAT_TOL`` of its highest point) over a band ``RIM_WIDTH`` wide. A clawfoot tub's rolled rim is a tube: a bottle stood on its crest
    tips into the tub; a built-in tub's flat deck holds it."""
    key = (asset.asset_id, part.name)
    got = _ROUNDED.get(key)
    if got is None:
        poly = part.surfaces["top"].polygon if "top" in part.surfaces else None
        rims = [g for g in getattr(poly, "geoms", [poly]) if isinstance(g, Polygon)
                and any(rect_sides(Polygon(r))[0] >= RIM_OPENING for r in g.interiors)]
        got = False
        if rims:
            top = max(float(pc.vertices[:, 2].max()) for pc in part.piece_arrays)
            widths = [0.0]
            for pc in part.piece_arrays:
                v = pc.vertices[pc.vertices[:, 2] >= top - FLAT_TOL]
                if len(v) >= 3:
                    widths.append(rect_sides(shapely.MultiPoint(v[:, :2]).convex_hull)[0])
            got = max(widths) < RIM_WIDTH
        if len(_ROUNDED) > 8192:
            _ROUNDED.clear()
        _ROUNDED[key] = got
    return got


def free_top(asset: Asset, part) -> bool:
    """Whether the part's top face is flat (not a slanted part touching its bounding box's top
    along an edge only) and has a ``FREE_TOP``-wide patch, or half its area, that the asset's
    other parts do not cover within 20 cm above it (a top-loading washer's lid covers most of
    its top)."""
    key = (asset.asset_id, part.name)
    got = _FREE_TOP.get(key)
    if got is None and not _flat_cached(asset.asset_id, part, "top"):
        got = _FREE_TOP[key] = False  # slanted (an open grand piano's lid): nothing stands on it
    if got is None:
        s = part.surfaces["top"]
        free = filled(s.polygon)
        for p in asset.parts:
            if p is part:
                continue
            for pc in p.piece_arrays:  # per convex piece: a part's pieces may frame the top
                h = (pc.vertices - s.origin) @ s.normal
                if h.max() <= 1e-3 or h.min() >= 0.2 or (h.min() >= -1e-3 and h.max() <= LAYER):
                    continue  # below, high above, or a layer lying on it that holds as well
                free = free.difference(Polygon(RG.convex_footprint(plane_coords(s, pc.vertices))))
        # room for an item, or at least mostly uncovered (a bathtub's thin rim holds bottles
        # by their centre of mass)
        got = not free.buffer(-FREE_TOP / 2).is_empty or free.area >= 0.5 * filled(s.polygon).area
        if len(_FREE_TOP) > 8192:
            _FREE_TOP.clear()
        _FREE_TOP[key] = got
    return got


_CLEAR: dict[tuple[str, str], bool] = {}


def clear_middle(asset: Asset, part) -> bool:
    """Whether no other part of the asset rises more than 3 mm above the middle of the part's
    top (its outline scaled by half about its centroid; within 20 cm above it), short of a layer
    covering 90% of it (a hinge at its edge leaves it clear): a lid's knob would carry
    a jar of the same kind stacked on it, balanced on 2 cm, and it falls in settling."""
    key = (asset.asset_id, part.name)
    got = _CLEAR.get(key)
    if got is None:
        got = True
        s = part.surfaces.get("top")
        if s is not None:
            top = filled(s.polygon)
            mid = shapely.affinity.scale(top, 0.5, 0.5, origin=top.centroid)
            for p in asset.parts:
                if p is part:
                    continue
                for pc in p.piece_arrays:
                    h = (pc.vertices - s.origin) @ s.normal
                    if h.max() <= 3e-3 or h.min() >= 0.2:
                        continue
                    fp = Polygon(RG.convex_footprint(plane_coords(s, pc.vertices)))
                    if fp.intersects(mid) and fp.area < 0.9 * top.area:
                        got = False
        if len(_CLEAR) > 8192:
            _CLEAR.clear()
        _CLEAR[key] = got
    return got


#: Metres of a layer lying on a part's top (a card table's felt, a glass top) that does not
#: cover it: what stands on the part stands on the layer (the ``ON`` check's step).
LAYER = 0.01
#: Pool slots examined per candidate category when looking for a suitable instance.
RANKED_SLOTS = 6


def boards_hold(reqs):
    """``reqs`` with each internal surface required of a board part (:data:`BOARD_LABELS`)
    met by its free top as well."""
    return [(label, idx, text, "internal_or_board")
            if kind == "internal" and label in BOARD_LABELS else (label, idx, text, kind)
            for label, idx, text, kind in reqs]


def too_tall_failure(reason: str) -> bool:
    """Whether a failure was a height band the instance is too tall for (SECURED_TO)."""
    return "height is the centre's" in reason


def room_failure(reason: str) -> bool:
    """Whether a failure was about room (a region emptied, no free space, collisions, a base
    with only the edge of a low part under it: a knob on a lid)."""
    return any(k in reason for k in ("emptied", "no free space", "collides", "does not fit",
                                     "edge of a low part"))


def alternative_instance(library, categories, reqs, tried: set[str], rng: np.random.Generator, *,
                         smallest: bool = False, key=None, every: bool = False):
    """An untried instance, over the candidate categories and a random sample of their pool
    slots (``every``: all of them), that meets ``reqs``: the first found, or with
    ``smallest`` the one with the smallest footprint, or with ``key`` (a function of the
    asset) the one of least key; None when there is none."""
    load = getattr(library, "load", None)
    if load is None:
        return None
    k = int(getattr(library, "per_category", 20))
    # a part that must reach furthest (AGAINST by a part) is rare among instances: every slot
    slots = k if every or any(r[3].startswith("extreme:") for r in reqs) else RANKED_SLOTS
    best = None
    for ci in rng.permutation(len(categories)):
        cat = categories[int(ci)]
        for slot in rng.permutation(k)[:slots]:
            asset = load(cat, int(slot))
            if asset.asset_id in tried or lacks(asset, reqs) is not None:
                continue
            if key is not None:
                area = float(key(asset))
            elif not smallest:
                return cat, asset
            else:
                ext = np.ptp(asset_geometry(asset).bounds, axis=0)
                area = float(ext[0] * ext[1])
            if best is None or area < best[0]:
                best = (area, cat, asset)
    return None if best is None else (best[1], best[2])


def flush_edges(loosen: dict[int, Edge]) -> list[Edge]:
    """The edges, as written, of relaxed AGAINST contacts named by a child part."""
    return [e for e in loosen.values() if e.relation == "AGAINST"
            and getattr(e, "_named_part", None) is not None]


def part_overhang(asset: Asset, e: Edge) -> float:
    """Metres by which another part of ``asset`` reaches further along the named child
    surface's normal than the part ``e`` names (infinite when the asset lacks it)."""
    label, idx = e._named_part
    ps = asset.parts_by_label(label)
    if not ps or (idx is not None and idx >= len(ps)):
        return float("inf")
    ps = ps[idx:idx + 1] if idx is not None else ps
    n = np.asarray(SURFACES[e.child.surface or e.spec.child_surface], float)
    return float(np.max(part_points(asset.parts) @ n) - np.max(part_points(ps) @ n))



def level_instance(st: SolveState, library, oid: str, edges: list[Edge], leave, reqs: list,
                   tried: set[str], category: str, asset: Asset) -> tuple[str, Asset]:
    """For an object with surfaces to bring level with its parents' (two countertops flush:
    :mod:`.rules.alignment`), the instance of every pool slot whose named surfaces come nearest
    their parents' heights at a scale it allows, when ``asset`` does not come within half the
    checks' tolerance; ``(category, asset)`` unchanged otherwise. The lookup draws from a
    generator of its own (seeded from the object id), not the solve's."""
    node = st.pag.objects[oid]
    key = level_miss(st, node, edges, leave)
    if key is None or key(asset) <= DIST_TOL / 2:
        return category, asset
    rng = np.random.default_rng(zlib.crc32(f"level:{oid}".encode()))
    alt = alternative_instance(library, node.candidates, reqs, tried, rng, key=key, every=True)
    if alt is None or key(alt[1]) >= key(asset):
        return category, asset
    tried.add(alt[1].asset_id)
    return alt


def draw_instance(library, node, reqs: list, tried: set[str], rng: np.random.Generator,
                  reasons: list[str], *, attempt: int, keep, loosen: dict[int, Edge],
                  support_edge: Edge, smallest: bool, own: frozenset[str] = frozenset(),
                  leans: bool = False):
    """The instance of one placement attempt: drawn from the library, or picked by a rule
    (the last one kept for a repair, the least overhung for a relaxed contact, the thinnest
    for a flat thing hung edge-up, the smallest after a failure for room, the lowest after
    a height band), replaced by one that meets ``reqs`` when it lacks something; added to
    ``tried``. Returns ``(category, asset, reqs)`` (``reqs`` loosened when no instance meets
    them as written: what the object's children ask of it, from relations other than the
    texts ``own``, is dropped last), or None when every suitable instance was tried; ``Fail``
    when none in the pool is suitable. Set ``leans`` when the object leans on something: an
    instance that cannot stand on its own base is then kept."""
    category = node.candidates[int(rng.integers(len(node.candidates)))]
    asset = library.get(category, rng)
    if (hung := hang_reqs(reqs)) and not (keep is not None and attempt == 0) \
            and lacks(asset, hung) is not None:
        # something is to hang below it and the draw has no room for it (a dish rack drawn
        # for "rack", with shirts to hang): an instance that has, looked up with a generator
        # of its own (the solve's draws are unchanged where nothing is filtered)
        own_rng = np.random.default_rng(zlib.crc32(f"hang:{node.id}:{attempt}".encode()))
        alt = alternative_instance(library, node.candidates, reqs, tried, own_rng, every=True) \
            or alternative_instance(library, node.candidates, hung, tried, own_rng, every=True)
        if alt is not None:
            category, asset = alt
        else:  # none has: the draw stands, and what hangs below it relaxes or fails alone
            reqs = [r for r in reqs if r not in hung]
    picked = True  # by a rule below, else drawn
    if keep is not None and attempt == 0:
        category, asset = keep.category, keep.asset
    elif attempt == 0 and (flush := flush_edges(loosen)):
        # a contact relaxed to the whole object: the instance whose named part is least
        # overhung (a shelf's back panel 2 cm in front of its posts, not 45 cm)
        alt = alternative_instance(library, node.candidates, reqs, tried, rng,
                                   key=lambda a: max(part_overhang(a, e) for e in flush))
        if alt is not None:
            category, asset = alt
    elif attempt == 0 and keep is None and edge_up(support_edge) and thinness(asset) < 1:
        # a flat thing hung edge-up (a folded towel, not a coat): its thickness stands out
        # from the rail toward the wall behind it, so the thinnest instance looked at first
        alt = alternative_instance(library, node.candidates, reqs, tried, rng, key=thinness)
        if alt is not None:
            category, asset = alt
    elif smallest and attempt == 0:
        alt = alternative_instance(library, node.candidates, reqs, tried, rng, smallest=True)
        if alt is not None:
            category, asset = alt
    elif reasons and room_failure(reasons[-1]):
        # the last instance did not fit where it must go: the smallest suitable one next
        alt = alternative_instance(library, node.candidates, reqs, tried | {asset.asset_id},
                                   rng, smallest=True)
        if alt is not None:
            category, asset = alt
    elif reasons and too_tall_failure(reasons[-1]):
        # too tall for its height band on a wall (curtains hung at 0.8-1 m): the lowest
        # untried instance next (its up axis)
        alt = alternative_instance(library, node.candidates, reqs, tried | {asset.asset_id},
                                   rng, key=lambda a: extent_along(a, 2))
        if alt is not None:
            category, asset = alt
    else:
        picked = False
    if not (keep is not None and attempt == 0) and (
            not picked and asset.asset_id in tried or lacks(asset, reqs)):
        # constraint-aware selection (also when a rule above found nothing and kept the
        # draw): another instance that has what the relations need, among a sample of
        # slots, then among every slot (a board game with a lid: most are card decks)
        alt = alternative_instance(library, node.candidates, reqs, tried, rng) \
            or alternative_instance(library, node.candidates, reqs, tried, rng, every=True)
        if alt is None and (loose_reqs := soft(reqs)) != reqs:
            # no instance is the flat base a stack of its kind needs (apples): any one,
            # and what would stack on it rests beside it
            alt = alternative_instance(library, node.candidates, loose_reqs, tried, rng)
            if alt is not None:
                reqs = loose_reqs
        if alt is None and (boards := boards_hold(reqs)) != reqs:
            # no instance holds anything inside the named shelf: one whose shelf is a
            # board, and what is IN it stands on its top (a wall shelf)
            alt = alternative_instance(library, node.candidates, boards, tried, rng,
                                       every=True)
            if alt is not None:
                reqs = boards
        if alt is None and own and (mine := [r for r in reqs if r[2] in own]) != reqs:
            # no instance has what a child names on it (a second shelf no fridge of the pool
            # has): the object is placed all the same, and that child fails or relaxes alone
            alt = alternative_instance(library, node.candidates, mine, tried, rng)
            if alt is not None:
                reqs = mine
        if alt is None:
            if asset.asset_id in tried:
                return None  # every suitable instance was tried
            why = lacks(asset, reqs)
            n = int(getattr(library, "per_category", 20))
            raise Fail(f"no {'/'.join(node.candidates)} asset looked at in the pool (up to "
                       f"{n} per category) fits the relations: {why}",
                       intrinsic=True)
        category, asset = alt
    if keep is None and names_part(support_edge) and overhang(asset, support_edge)[0] > 0:
        # the named part is not where the support needs it (a frame raised on legs): the
        # instance whose named part reaches furthest toward the support, of every slot
        alt = alternative_instance(library, node.candidates, reqs, tried | {asset.asset_id},
                                   rng, key=lambda a: overhang(a, support_edge)[0],
                                   every=True)
        if alt is not None and overhang(alt[1], support_edge)[0] < overhang(
                asset, support_edge)[0]:
            category, asset = alt
    if keep is None and not leans and stood_on_base(support_edge, node.id) \
            and not stands(asset):
        # ON by the whole object, an instance that cannot stand on its base (a TV made for the
        # wall, without feet): one that stands, of every slot, looked up without the solve's
        # generator (what leans on something needs no base of its own)
        alt = alternative_instance(library, node.candidates, reqs, tried | {asset.asset_id},
                                   np.random.default_rng(zlib.crc32(node.id.encode())),
                                   key=lambda a: not stands(a), every=True)
        if alt is not None and stands(alt[1]):
            category, asset = alt
    tried.add(asset.asset_id)
    return category, asset, reqs


def stood_on_base(e: Edge, oid: str) -> bool:
    """Whether the support ``e`` stands its child ``oid`` on its own base: ``ON`` by the whole
    object's bottom."""
    return e.relation == "ON" and e.child.object == oid and e.child.part is None \
        and (e.child.surface or "bottom") == "bottom"


_STANDS: dict[str, bool] = {}


def stands(asset: Asset) -> bool:
    """Whether ``asset`` stands on its base as modelled: its centre of mass lies over the
    convex hull (grown by 1 mm) of its points within 3 mm of its lowest (a TV's feet, a book's
    bottom edge; not a wall TV's buttons under its bottom edge, nor a picture frame's edge
    with the frame's back bulging behind it)."""
    got = _STANDS.get(asset.asset_id)
    if got is None:
        pts = part_points(asset.parts)
        low = pts[pts[:, 2] <= pts[:, 2].min() + 3e-3][:, :2]
        com = asset_geometry(asset).com
        base = shapely.MultiPoint(low).convex_hull.buffer(1e-3)
        got = bool(base.contains(shapely.Point(com[0], com[1])))
        if len(_STANDS) > 8192:
            _STANDS.clear()
        _STANDS[asset.asset_id] = got
    return got


def top_short(st: SolveState, edge: Edge, asset: Asset, scale: float, axis: int) -> float:
    """How much wider ``asset`` at ``scale`` is than the largest top it may stand ON (the
    larger of its two side ratios; <= 1: it fits); 0 for anything not ON an object's top and
    for a stack of one category (a loaf on a loaf may overhang it)."""
    if edge.relation != "ON" or edge.parent.is_room_element \
            or edge.parent.object not in st.scene.objects:
        return 0.0
    if set(st.pag.objects[edge.child.object].candidates) \
            & set(st.pag.objects[edge.parent.object].candidates):
        return 0.0
    try:
        sups = support_candidates(st, edge)
    except Fail:
        return 0.0
    ext = hull_extents(asset)[0]
    c0, c1 = sorted(scale * float(ext[k]) for k in range(3) if k != axis)
    best = float("inf")
    for sup in sups:
        s0, s1 = sup_sides(sup.region)
        if s0 < LEDGE_SHARE * c0:
            return 0.0  # a ledge it leans on (a score on a music rest), not a top to stand on
        best = min(best, max(c0 / s0, c1 / s1))
    return best if np.isfinite(best) else 0.0


#: A top narrower than this share of the child's short side is a ledge the child leans on.
LEDGE_SHARE = 0.3


def cramped_scale(st: SolveState, library, oid: str, asset: Asset, scale: float) -> float:
    """The largest scale the node allows ``asset`` when what is written ON its top (only ON,
    not IN a tray) is wider than that top both ways even then (:func:`.fit.roomy_scale` keeps
    ``scale``): a microwave's feet on a mini fridge need all of it. Else ``scale``."""
    from .fit import _max_scale, _needs, top_sides

    needs = _needs(st, library, oid, asset)
    if not needs or any(e.relation != "ON" for e, _ in needs):
        return scale
    top = _max_scale(st, oid, asset)
    # wider than the top both ways even at that scale: the feet need all of it
    for e, (w0, w1) in needs:
        a, b = top_sides(asset, e)
        if a > 0 and w0 > a * top and w1 > b * top:
            return top
    return scale


def instance_scale(st: SolveState, oid: str, library, node, category: str, asset: Asset,
                   reqs: list, tried: set[str], rng: np.random.Generator, *, attempt: int,
                   keep, support_edge: Edge, axis: int, headroom: float):
    """The scale of one attempt's instance: its real-world size (times the node's scale
    range) clamped to its category's range, big enough for what is IN it or hangs below it,
    8% smaller from the fourth attempt, the earlier one's for a repair; another instance when
    it is too tall for every shelf it may go in or too short to span the parts it must rest
    across. Returns ``(category, asset, scale, reason)``: ``reason`` (about room) when even
    the widest instance cannot span those parts, else None."""
    pag = st.pag
    # generators already make real-world sizes: keep them (times the node's scale range),
    # clamped so the size stays in the category's range (this normalises loaded assets)
    lo, hi = asset.size_range
    s_node = rng.uniform(*node.scale) if node.scale is not None else 1.0
    size = asset_geometry(asset).size
    scale = s_node * float(np.clip(1.0, lo / max(size, 1e-6), hi / max(size, 1e-6)))
    # a container with several things IN it (apples in a bowl) is drawn big enough to hold
    # them, within its category's size range
    scale = max(scale, min(contents_scale(pag, oid, asset), hi / max(size, 1e-6)))
    # and a rail with several things hung below it long enough for them (towels on a bar)
    scale = max(scale, min(rail_scale(pag, oid, asset), hi / max(size, 1e-6)))
    scale *= 0.92 ** max(0, attempt - 2)  # other instances first, then smaller ones
    roomy = roomy_scale(st, library, oid, asset, scale)  # room on its top (fit.py)
    if roomy == scale and keep is None:
        # no scale allowed gives what goes ON its top room (a microwave on a small fridge):
        # the largest allowed, so the rest overhangs as little as it can
        roomy = max(scale, cramped_scale(st, library, oid, asset, scale))
    scale = roomy
    # a rug for a furnished room: one that fits between what stands on the floor (coverings.py)
    scale = covering_scale(st, support_edge, asset, scale, lo / max(size, 1e-6))
    if keep is not None and attempt == 0:
        scale = keep.scale
    elif scale * extent_along(asset, axis) > HEADROOM_FIT * headroom:
        # taller than every shelf it may go IN (a cereal box on a grocery shelf): the lowest
        # untried instance, then shrunk to the free height within its category's range
        # (one whose floor takes the flat things written IN it first: standing.py)
        holds = floor_takes(st, library, oid, support_edge, HEADROOM_FIT) or (lambda a: True)
        alt = alternative_instance(library, node.candidates, reqs, tried, rng,
                                   key=lambda a: extent_along(a, axis) + (0.0 if holds(a) else 1e3))
        if alt is not None and extent_along(alt[1], axis) < extent_along(asset, axis) \
                and (holds(alt[1]) or not holds(asset)):
            category, asset = alt
            tried.add(asset.asset_id)
            lo, hi = asset.size_range
            size = asset_geometry(asset).size
            scale = s_node * float(np.clip(1.0, lo / max(size, 1e-6), hi / max(size, 1e-6)))
        fit = HEADROOM_FIT * headroom / max(extent_along(asset, axis), 1e-6)
        if fit >= asset.size_range[0] / max(asset_geometry(asset).size, 1e-6):
            scale = min(scale, fit)
    if keep is None or attempt > 0:
        # longer than a container's floor: shrunk to lie in it, within its size range
        scale = floor_fit(st, support_edge, asset, scale, axis)
        if span_need(st, support_edge) <= 0:  # not resting across several parts
            scale = top_fit(st, support_edge, asset, scale, axis, library)  # a small top (fit.py)
            if keep is None and top_short(st, support_edge, asset, scale, axis) > 1.0:
                # wider than the top even so: the smallest untried instance, at the least
                # size its category allows (it overhangs, its feet on the top)
                alt = alternative_instance(library, node.candidates, reqs, tried, rng,
                                           smallest=True)
                if alt is not None and top_short(st, support_edge, alt[1], 1.0, axis) \
                        < top_short(st, support_edge, asset, 1.0, axis):
                    category, asset = alt
                    tried.add(asset.asset_id)
                lo = asset.size_range[0] / max(asset_geometry(asset).size, 1e-6)
                r = top_short(st, support_edge, asset, 1.0, axis)
                scale = max(lo, min(scale, FIT_SHARE / r)) if r > 0 else scale
    reach = span_need(st, support_edge)
    if not reach and support_edge.relation == "ON" and not support_edge.parent.is_room_element:
        # across a ring round an opening (a tray across a tub, bars.py)
        try:
            ext = sorted(float(e) for k, e in enumerate(hull_extents(asset)[0]) if k != axis)
            reach = across_need(support_candidates(st, support_edge), scale * ext[1],
                                scale * ext[0])
        except Fail:
            reach = 0.0
    if reach > 0 and keep is None and scale * extent_across(asset, axis) < reach:
        # too short to rest across the parts it must span (a keyboard on a stand's two
        # arms): the widest untried instance, then as large as the node's scale allows
        alt = alternative_instance(library, node.candidates, reqs, tried, rng,
                                   key=lambda a: -extent_across(a, axis))
        if alt is not None and extent_across(alt[1], axis) > extent_across(asset, axis):
            category, asset = alt
            tried.add(asset.asset_id)
        lo, hi = asset.size_range
        size = asset_geometry(asset).size
        top = (node.scale[1] if node.scale is not None else 1.0) * float(
            np.clip(1.0, lo / max(size, 1e-6), hi / max(size, 1e-6)))
        scale = max(scale, min(top, reach / max(extent_across(asset, axis), 1e-6)))
        if scale * extent_across(asset, axis) < reach - 1e-6:
            # a reason about room: the search may re-place the support as another instance
            ref = support_edge.parent
            return category, asset, scale, (
                f"a {scale * extent_across(asset, axis):.2f} m {category} does not fit "
                f"across {ref.object}'s {ref.part} parts ({reach:.2f} m needed)")
    return category, asset, scale, None
