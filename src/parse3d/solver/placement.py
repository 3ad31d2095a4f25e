"""Stages 1 and 6 of Algorithm 1 for one object: choose an asset and scale, then sample
positions in the feasible region and validate each (relation checks, FCL collisions)."""

from __future__ import annotations

import operator
from dataclasses import dataclass, replace

import numpy as np
import shapely
from shapely.geometry import Polygon

from ..assets.model import Asset
from ..geometry import regions as RG
from ..geometry.frames import axis_angle
from ..geometry.memo import per_object
from ..geometry.meshes import MeshArrays, scaled_vertices
from ..measure.checks import BOARD_LABELS, EPS, STEP, check_edge, world_points
from ..pag.model import Edge
from ..relations import SURFACES
from ..scene.model import PlacedObject, SupportChoice
from .collision import Body, cached_body
from .config import STRUCTURAL_FAILURES, Fail, SolverConfig
from .fit import instance_for, roomy_scale, top_fit
from .geometry import asset_geometry, drop_distance, hull_extents, outline_indices, part_points
from .hanging import edge_up, rail_fit, rail_scale, thinness
from .intent import beside, loose_reason, names_part, overhang, soft, whole_object
from .leaning import involves_object, lean_samples, lean_slide
from .ledge import may_lean, place_leaning
from .nesting import concentric_first, floor_fit, nest_rise, nest_samples, pieces_drop
from .regions import (
    REGION_RULES,
    RegionContext,
    apply_region_rules,
    height_band,
    obstacles,
    parent_frame,
    side_vector,
    steps_on,
)
from .rotation import solve_rotation
from .standing import may_stand_in, place_standing
from .state import SolveState, angle_to, plane_coords, plane_key, support_chain
from .support import (
    BAR_WIDTH,
    Support,
    _flat_cached,
    _flat_enough,
    cover_part,
    filled,
    support_candidates,
)

__all__ = ["Placement", "place_object", "requirements", "lacks", "scaled_mesh", "resolution"]


@dataclass
class Placement:
    """An accepted pose: the object, its collision body and the checks measured on it (one per
    edge of the object, in ``pag.edges_of`` order)."""

    obj: PlacedObject
    body: Body
    checks: list[tuple]
    #: why the support edge was placed otherwise than written (by the whole object when its
    #: named part cannot touch, beside a round parent), recorded as relaxed; None when not
    loose_support: str | None = None


def place_object(st: SolveState, oid: str, rng: np.random.Generator, cfg: SolverConfig,
                 library, *, skip: frozenset[int] = frozenset(),
                 proposal: tuple[np.ndarray, np.ndarray] | None = None,
                 keep: PlacedObject | None = None, smallest: bool = False,
                 loosen: dict[int, Edge] | None = None) -> Placement:
    """Place one object (its parents are placed); raise Fail with the reason otherwise.

    ``skip`` holds indices (into ``pag.edges_of(oid)``) of non-support relations left out
    because their parent failed. ``proposal`` is a world pose ``(R, t)`` tried first. ``keep``
    is an earlier placement of the object whose asset and scale the first attempt reuses (a
    repair by another pose). ``smallest`` starts with the suitable instance of least
    footprint among those looked at (a table that must leave room for its chairs).
    ``loosen`` maps indices of relaxed part-level edges to the edge placed instead (the same
    relation by the whole object: the part that reaches furthest touches); their checks are
    left None (measured on the edge as written afterwards).
    """
    pag = st.pag
    node = pag.objects[oid]
    edges = pag.edges_of(oid)
    support_edge = edges[0]
    loosen = loosen or {}
    others = [loosen.get(i, e) for i, e in enumerate(edges[1:], 1) if i not in skip]
    reasons: list[str] = []
    intrinsic: list[bool] = []
    total_trials = 0
    dropped = {_edge_text(edges[i]) for i in (*skip, *loosen)}
    reqs = [r for r in requirements(pag, oid) if r[2] not in dropped]
    tried: set[str] = set()
    # ON a round thing of its kind (an apple on an apple): beside it, a heap
    heap = beside(pag, st.scene, support_edge,
                  lambda a, ref: lacks(a, [(ref.part, ref.index, "", "stack_base")]) is not None)
    if heap is not None:
        others = [*others, heap[1]]
    headroom = _headroom(st, support_edge)
    axis = _AXES[support_edge.child.surface or support_edge.spec.child_surface]
    for attempt in range(cfg.asset_attempts):
        category = node.candidates[int(rng.integers(len(node.candidates)))]
        asset = library.get(category, rng)
        picked = True  # by a rule below, else drawn
        if keep is not None and attempt == 0:
            category, asset = keep.category, keep.asset
        elif attempt == 0 and (flush := _flush_edges(loosen)):
            # a contact relaxed to the whole object: the instance whose named part is least
            # overhung (a shelf's back panel 2 cm in front of its posts, not 45 cm)
            alt = _alternative(library, node.candidates, reqs, tried, rng,
                               key=lambda a: max(_overhang(a, e) for e in flush))
            if alt is not None:
                category, asset = alt
        elif attempt == 0 and keep is None and edge_up(support_edge) and thinness(asset) < 1:
            # a flat thing hung edge-up (a folded towel, not a coat): its thickness stands out
            # from the rail toward the wall behind it, so the thinnest instance looked at first
            alt = _alternative(library, node.candidates, reqs, tried, rng, key=thinness)
            if alt is not None:
                category, asset = alt
        elif smallest and attempt == 0:
            alt = _alternative(library, node.candidates, reqs, tried, rng, smallest=True)
            if alt is not None:
                category, asset = alt
        elif reasons and _space(reasons[-1]):
            # the last instance did not fit where it must go: the smallest suitable one next
            alt = _alternative(library, node.candidates, reqs, tried | {asset.asset_id}, rng,
                               smallest=True)
            if alt is not None:
                category, asset = alt
        elif reasons and _too_tall(reasons[-1]):
            # too tall for its height band on a wall (curtains hung at 0.8-1 m): the lowest
            # untried instance next (its up axis)
            alt = _alternative(library, node.candidates, reqs, tried | {asset.asset_id}, rng,
                               key=lambda a: _extent(a, 2))
            if alt is not None:
                category, asset = alt
        else:
            picked = False
        if not (keep is not None and attempt == 0) and (
                not picked and asset.asset_id in tried or lacks(asset, reqs)):
            # constraint-aware selection (also when a rule above found nothing and kept the
            # draw): another instance that has what the relations need, among a sample of
            # slots, then among every slot (a board game with a lid: most are card decks)
            alt = _alternative(library, node.candidates, reqs, tried, rng) or _alternative(
                library, node.candidates, reqs, tried, rng, every=True)
            if alt is None and (loose_reqs := soft(reqs)) != reqs:
                # no instance is the flat base a stack of its kind needs (apples): any one,
                # and what would stack on it rests beside it
                alt = _alternative(library, node.candidates, loose_reqs, tried, rng)
                if alt is not None:
                    reqs = loose_reqs
            if alt is None and (boards := _boards(reqs)) != reqs:
                # no instance holds anything inside the named shelf: one whose shelf is a
                # board, and what is IN it stands on its top (a wall shelf)
                alt = _alternative(library, node.candidates, boards, tried, rng, every=True)
                if alt is not None:
                    reqs = boards
            if alt is None:
                if asset.asset_id in tried:
                    break  # every suitable instance was tried
                why = lacks(asset, reqs)
                n = int(getattr(library, "per_category", 20))
                raise Fail(f"no {'/'.join(node.candidates)} asset looked at in the pool (up to "
                           f"{n} per category) fits the relations: {why}",
                           intrinsic=True)
            category, asset = alt
        if keep is None and names_part(support_edge) and overhang(asset, support_edge)[0] > 0:
            # the named part is not where the support needs it (a frame raised on legs): the
            # instance whose named part reaches furthest toward the support, of every slot
            alt = _alternative(library, node.candidates, reqs, tried | {asset.asset_id}, rng,
                               key=lambda a: overhang(a, support_edge)[0], every=True)
            if alt is not None and overhang(alt[1], support_edge)[0] < overhang(
                    asset, support_edge)[0]:
                category, asset = alt
        if keep is None and attempt == 0:  # nests, has room on its top (fit.py)
            category, asset = instance_for(st, library, oid, support_edge, category, asset,
                                           lambda a, r=reqs: lacks(a, r) is None, tried, rng)
        tried.add(asset.asset_id)
        # generators already make real-world sizes: keep them (times the node's scale range),
        # clamped so the size stays in the category's range (this normalises loaded assets)
        lo, hi = asset.size_range
        s_node = rng.uniform(*node.scale) if node.scale is not None else 1.0
        size = asset_geometry(asset).size
        scale = s_node * float(np.clip(1.0, lo / max(size, 1e-6), hi / max(size, 1e-6)))
        # a container with several things IN it (apples in a bowl) is drawn big enough to hold
        # them, within its category's size range
        scale = max(scale, min(_contents_scale(pag, oid, asset), hi / max(size, 1e-6)))
        # and a rail with several things hung below it long enough for them (towels on a bar)
        scale = max(scale, min(rail_scale(pag, oid, asset), hi / max(size, 1e-6)))
        scale *= 0.92 ** max(0, attempt - 2)  # other instances first, then smaller ones
        scale = roomy_scale(st, library, oid, asset, scale)  # room on its top (fit.py)
        if keep is not None and attempt == 0:
            scale = keep.scale
        elif scale * _extent(asset, axis) > HEADROOM_FIT * headroom:
            # taller than every shelf it may go IN (a cereal box on a grocery shelf): the lowest
            # untried instance, then shrunk to the free height within its category's range
            alt = _alternative(library, node.candidates, reqs, tried, rng,
                               key=lambda a: _extent(a, axis))
            if alt is not None and _extent(alt[1], axis) < _extent(asset, axis):
                category, asset = alt
                tried.add(asset.asset_id)
                lo, hi = asset.size_range
                size = asset_geometry(asset).size
                scale = s_node * float(np.clip(1.0, lo / max(size, 1e-6), hi / max(size, 1e-6)))
            fit = HEADROOM_FIT * headroom / max(_extent(asset, axis), 1e-6)
            if fit >= asset.size_range[0] / max(asset_geometry(asset).size, 1e-6):
                scale = min(scale, fit)
        if keep is None or attempt > 0:
            # longer than a container's floor: shrunk to lie in it, within its size range
            scale = floor_fit(st, support_edge, asset, scale, axis)
            scale = top_fit(st, support_edge, asset, scale, axis)  # a small top (fit.py)
        reach = _span_need(st, support_edge)
        if reach > 0 and keep is None and scale * _across(asset, axis) < reach:
            # too short to rest across the parts it must span (a keyboard on a stand's two
            # arms): the widest untried instance, then as large as the node's scale allows
            alt = _alternative(library, node.candidates, reqs, tried, rng,
                               key=lambda a: -_across(a, axis))
            if alt is not None and _across(alt[1], axis) > _across(asset, axis):
                category, asset = alt
                tried.add(asset.asset_id)
            lo, hi = asset.size_range
            size = asset_geometry(asset).size
            top = (node.scale[1] if node.scale is not None else 1.0) * float(
                np.clip(1.0, lo / max(size, 1e-6), hi / max(size, 1e-6)))
            scale = max(scale, min(top, reach / max(_across(asset, axis), 1e-6)))
            if scale * _across(asset, axis) < reach - 1e-6:
                # a reason about room: the search may re-place the support as another instance
                ref = support_edge.parent
                reasons.append(f"a {scale * _across(asset, axis):.2f} m {category} does not fit "
                               f"across {ref.object}'s {ref.part} parts ({reach:.2f} m needed)")
                intrinsic.append(False)
                continue
        hang = _hung_edge_up(support_edge, asset)
        # several hung below one rail share its length (towels along a bar)
        scale = rail_fit(st, oid, support_edge, asset, scale, 1 if hang is not None else 2)
        loose = None
        placed_edge = support_edge
        if heap is not None:
            placed_edge, loose = heap[0], heap[2]
        elif hang is None and names_part(support_edge) \
                and 0 < overhang(asset, support_edge)[0] < np.inf:
            # even the best instance is overhung: it rests by the part that reaches furthest
            loose = loose_reason(asset, support_edge, scale)
            placed_edge = whole_object(support_edge)
        try:
            pose, trials, checks, under = _place_asset(st, oid, asset, scale,
                                                       hang or placed_edge, others, rng, cfg,
                                                       proposal if attempt == 0 else None)
        except Fail as f:
            reasons.append(str(f))
            intrinsic.append(f.intrinsic)
            total_trials += cfg.max_trials
            continue
        total_trials += trials
        R, t, sup, body = pose[:4]
        obj = PlacedObject(oid, category, asset, float(scale), R, t, "placed", None, total_trials,
                           support_choice=sup.choice)
        obj.rests_on = pose[4] if len(pose) > 4 else ("back" if hang is not None else None)
        obj.fixed = support_edge.relation in ("SECURED_TO", "HANGING_BELOW")
        obj.stacked_on = under
        full = _full_checks(edges, skip, checks)
        for i in loosen:
            full[i] = None
        if loose is not None:
            full[0] = None  # measured on the edge as written afterwards
        return Placement(obj, body, full, loose)
    raise Fail(_summarise(reasons, node), intrinsic=bool(intrinsic) and all(intrinsic))


#: A child whose height is at most this share of its next smaller extent is thin (a folded
#: towel, a flat bag): hung from an object's part it hangs edge-up, not flat.
THIN_HANG = 0.35


def _hung_edge_up(edge: Edge, asset: Asset) -> Edge | None:
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
_AXES = {"top": 2, "bottom": 2, "front": 1, "back": 1, "right": 0, "left": 0}


def _extent(asset: Asset, axis: int) -> float:
    """The asset's extent (m, unit scale) along one of its own axes."""
    return float(hull_extents(asset)[0][axis])


def _across(asset: Asset, axis: int) -> float:
    """The asset's longest extent (m, unit scale) across ``axis`` (its support normal)."""
    ext = hull_extents(asset)[0]
    return float(max(ext[k] for k in range(3) if k != axis))


#: A part narrower than this (m) is too narrow to stand things on alone (a stand's arm).
SPAN_PART = 0.06

#: How far (m) beyond the middles of the two outer parts a spanning child must reach.
SPAN_BEARING = 0.03


def _span_need(st: SolveState, edge: Edge) -> float:
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
    if any(_sides(s.region)[0] >= SPAN_PART for s in single):
        return 0.0
    mid = [np.asarray(s.surface.to_3d(np.asarray(s.region.centroid.coords)))[0] for s in single]
    gaps = [float(np.linalg.norm(a - b)) for i, a in enumerate(mid) for b in mid[i + 1:]]
    return min(gaps) + 2 * SPAN_BEARING if gaps else 0.0


def _headroom(st: SolveState, edge: Edge) -> float:
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


#: Footprint area a container needs per child IN it, in units of the child's typical size
#: squared (room to lie side by side, with the gaps round things leave).
CONTENTS_AREA = 2.5


def _contents_scale(pag, oid: str, asset: Asset) -> float:
    """Scale at which ``asset``'s footprint has room for the children IN the object as a whole
    (not on a named part: shelves of a rack hold their own), at ``CONTENTS_AREA`` times their
    typical size squared each; 0 with fewer than two such children."""
    from ..assets import registry

    kids = [e.child.object for e in touching(pag, oid)
            if e.relation == "IN" and e.parent.object == oid and e.parent.part is None]
    if len(kids) < 2:
        return 0.0
    need = 0.0
    for k in kids:
        sizes = []
        for c in pag.objects[k].candidates:
            try:
                lo, hi = registry.get(c).size_range
            except KeyError:
                continue
            sizes.append(0.5 * (lo + hi))
        need += CONTENTS_AREA * min(sizes, default=0.0) ** 2
    ext = np.ptp(asset_geometry(asset).bounds, axis=0)
    area = float(ext[0] * ext[1])
    return float(np.sqrt(need / area)) if area > 0 else 0.0


def _edge_text(e: Edge) -> str:
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
        text = _edge_text(e)
        if e.parent.object == oid and e.relation == "ON" and e.child.object != oid and set(
                pag.objects[e.child.object].candidates) & set(pag.objects[oid].candidates):
            out.append((e.parent.part, e.parent.index, text, "stack_base"))
        if e.parent.object == oid and e.relation == "IN" and e.parent.part is None:
            out.append((None, None, text, "internal"))  # IN the whole object: any inside
        for ref, role in ((e.child, "child"), (e.parent, "parent")):
            if ref.object != oid or ref.part is None:
                continue
            out.append((ref.part, ref.index, text, "part"))
            if role == "parent" and e.relation == "IN":
                out.append((ref.part, ref.index, text, "internal"))
            if role == "parent" and e.relation == "ON" and ref.surface in (None, "top"):
                out.append((ref.part, ref.index, text, "free_top"))
            if role == "child" and e.relation == "AGAINST":
                out.append((ref.part, ref.index, text,
                            f"extreme:{ref.surface or e.spec.child_surface}"))
    return out


def lacks(asset: Asset, reqs) -> str | None:
    """Why ``asset`` cannot meet ``reqs`` (see :func:`requirements`), or None."""
    for label, idx, text, kind in reqs:
        if kind == "internal" and label is None:
            if not asset.internal:
                return f"{asset.asset_id} holds nothing inside ({text})"
            continue
        if kind == "stack_base" and label is None:
            if not any(_lies_flat(asset, p) for p in asset.parts):
                return (f"{asset.asset_id} would roll: neither its top nor its bottom is flat "
                        f"to stack on ({text})")
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
                    and any(_free_top(asset, p) for p in ps):
                continue  # a board holds what is IN it on its top
            if not any(i.part in names for i in asset.internal):
                return f"{asset.asset_id}'s {label} holds nothing inside ({text})"
        elif kind == "free_top":
            if all(_rounded_rim(asset, p) for p in ps):
                return (f"{asset.asset_id}'s {label} top is a rounded rim, no flat band "
                        f"{RIM_WIDTH * 100:.0f} cm wide: what stands on it tips over ({text})")
            if not any(_free_top(asset, p) or (q := cover_part(asset, p)) is not None
                       and _free_top(asset, q) for p in ps):
                if not any(_flat_cached(asset.asset_id, p, "top") for p in ps):
                    return (f"{asset.asset_id}'s {label} is slanted: its top is no surface to "
                            f"stand on ({text})")
                return (f"{asset.asset_id}'s {label} top is mostly covered by its other parts, "
                        f"no room for a {FREE_TOP * 100:.0f} cm wide item ({text})")
        elif kind == "stack_base":
            if not any(_lies_flat(asset, p) for p in ps):
                return (f"{asset.asset_id}'s {label} would roll: neither its top nor its bottom "
                        f"is flat to stack on ({text})")
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


def _lies_flat(asset: Asset, part) -> bool:
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


#: Width (m) of the flat band a rim (a top around an opening) needs for things to stand on it.
RIM_WIDTH = 0.03
#: Width (m) of an opening no small child spans (a tub, not a burner ring a pot sits across).
RIM_OPENING = 0.3

_ROUNDED: dict[tuple[str, str], bool] = {}


def _rounded_rim(asset: Asset, part) -> bool:
    """Whether the part's top is a rim around an opening at least ``RIM_OPENING`` wide (its
    top surface has such a hole: no small child spans it) that is rounded: no convex piece of
    it is flat (within ``FLAT_TOL`` of its highest point) over a band ``RIM_WIDTH`` wide. A clawfoot tub's rolled rim is a tube: a bottle stood on its crest
    tips into the tub; a built-in tub's flat deck holds it."""
    key = (asset.asset_id, part.name)
    got = _ROUNDED.get(key)
    if got is None:
        poly = part.surfaces["top"].polygon if "top" in part.surfaces else None
        rims = [g for g in getattr(poly, "geoms", [poly]) if isinstance(g, Polygon)
                and any(_sides(Polygon(r))[0] >= RIM_OPENING for r in g.interiors)]
        got = False
        if rims:
            top = max(float(pc.vertices[:, 2].max()) for pc in part.piece_arrays)
            widths = [0.0]
            for pc in part.piece_arrays:
                v = pc.vertices[pc.vertices[:, 2] >= top - FLAT_TOL]
                if len(v) >= 3:
                    widths.append(_sides(shapely.MultiPoint(v[:, :2]).convex_hull)[0])
            got = max(widths) < RIM_WIDTH
        if len(_ROUNDED) > 8192:
            _ROUNDED.clear()
        _ROUNDED[key] = got
    return got


def _free_top(asset: Asset, part) -> bool:
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


#: Metres of a layer lying on a part's top (a card table's felt, a glass top) that does not
#: cover it: what stands on the part stands on the layer (the ``ON`` check's step).
LAYER = 0.01
#: Pool slots examined per candidate category when looking for a suitable instance.
RANKED_SLOTS = 6


def _boards(reqs):
    """``reqs`` with each internal surface required of a board part (:data:`BOARD_LABELS`)
    met by its free top as well."""
    return [(label, idx, text, "internal_or_board")
            if kind == "internal" and label in BOARD_LABELS else (label, idx, text, kind)
            for label, idx, text, kind in reqs]


def _too_tall(reason: str) -> bool:
    """Whether a failure was a height band the instance is too tall for (SECURED_TO)."""
    return "height is the centre's" in reason


def _space(reason: str) -> bool:
    """Whether a failure was about room (a region emptied, no free space, collisions)."""
    return any(k in reason for k in ("emptied", "no free space", "collides", "does not fit"))


def _alternative(library, categories, reqs, tried: set[str], rng: np.random.Generator, *,
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


def _flush_edges(loosen: dict[int, Edge]) -> list[Edge]:
    """The edges, as written, of relaxed AGAINST contacts named by a child part."""
    return [e for e in loosen.values() if e.relation == "AGAINST"
            and getattr(e, "_named_part", None) is not None]


def _overhang(asset: Asset, e: Edge) -> float:
    """Metres by which another part of ``asset`` reaches further along the named child
    surface's normal than the part ``e`` names (infinite when the asset lacks it)."""
    label, idx = e._named_part
    ps = asset.parts_by_label(label)
    if not ps or (idx is not None and idx >= len(ps)):
        return float("inf")
    ps = ps[idx:idx + 1] if idx is not None else ps
    n = np.asarray(SURFACES[e.child.surface or e.spec.child_surface], float)
    return float(np.max(part_points(asset.parts) @ n) - np.max(part_points(ps) @ n))


def _full_checks(edges: list[Edge], skip: frozenset[int], checks: list[tuple]) -> list[tuple]:
    it = iter(checks)
    return [None if i in skip else next(it) for i in range(len(edges))]


def _summarise(reasons: list[str], node) -> str:
    """One message for all attempts: the most frequent distinct reasons (at most two), and how
    many assets were tried when there were several."""
    if not reasons:
        return "no attempt"
    counts: dict[str, int] = {}
    for r in reasons:
        for frag in r.split("; "):
            counts[frag] = counts.get(frag, 0) + 1
    uniq = sorted(counts, key=lambda r: -counts[r])
    msg = "; ".join(uniq[:2])
    if len(reasons) > 1 and all("in this " in r for r in reasons):
        msg = msg.replace("in this ", "in every ")
    more = f"; {len(uniq) - 2} other reasons" if len(uniq) > 2 else ""
    return msg + more + (f" ({len(reasons)} assets tried)" if len(reasons) > 1 else "")


def _place_asset(st: SolveState, oid: str, asset: Asset, scale: float, support_edge: Edge,
                 others: list[Edge], rng: np.random.Generator, cfg: SolverConfig, proposal):
    geom = asset_geometry(asset)
    hull = geom.hull * scale
    sups = support_candidates(st, support_edge)
    order = rng.permutation(len(sups)) if len(sups) > 1 and support_edge.parent.surface is None \
        and support_edge.relation != "ON" else np.arange(len(sups))
    if support_edge.relation == "ON" and len(sups) > 1:
        # in their order (the highest first), but those the child's footprint cannot fit in
        # any turn after the others: a bag on a bench's seat before its buttons, a cushion on
        # a rug's field before its border strips (they stay, for a child that must overhang)
        axis = _AXES[support_edge.child.surface or support_edge.spec.child_surface]
        ext = sorted(scale * float(x) for k, x in enumerate(hull_extents(asset)[0]) if k != axis)
        order = np.array(sorted(range(len(sups)), key=lambda i: not _may_fit(sups[i], ext)))
    if support_edge.parent.object == "wall" or (support_edge.relation == "IN" and len(sups) > 1):
        order = rng.permutation(len(sups))
        if support_edge.relation == "IN":  # across a cradle's bars before on one of them
            order = np.array(sorted(order, key=lambda i: not sups[int(i)].spans))
    body = cached_body(asset, scale, lambda: scaled_mesh(asset, scale))
    reasons = []
    inner: list[bool] = []
    for variant in _wall_choices(st, others, rng):
        for si in order:
            sup = sups[int(si)]
            try:
                return _place_on(st, oid, asset, scale, hull, sup, support_edge, variant, body,
                                 rng, cfg, proposal)
            except Fail as f:
                reasons.append(str(f))
                inner.append(f.intrinsic)
    if cfg.strategy == "constrained" and any(
            may_lean(st, asset, scale, sups[int(si)], support_edge) for si in order):
        # too big to lie flat on a ledge: stand it on its edge, leaning back (sheet music)
        for si in order:
            if not may_lean(st, asset, scale, sups[int(si)], support_edge):
                continue
            try:
                return place_leaning(st, oid, asset, scale, sups[int(si)], support_edge, others,
                                     body, rng, lambda c, sp: _validate(st, c, support_edge,
                                                                        others, sp))
            except Fail as f:
                reasons.append(str(f))
                inner.append(f.intrinsic)
    if cfg.strategy == "constrained" and any(
            may_stand_in(st, asset, scale, sups[int(si)], support_edge) for si in order):
        # too long to lie in a narrow container: stand it up, leaning on the rim (a toothbrush
        # in a tumbler, flowers in a vase)
        for si in order:
            if not may_stand_in(st, asset, scale, sups[int(si)], support_edge):
                continue
            try:
                return place_standing(st, oid, asset, scale, sups[int(si)], support_edge,
                                      others, body, rng,
                                      lambda c, sp: _validate(st, c, support_edge, others, sp))
            except Fail as f:
                reasons.append(str(f))
                inner.append(f.intrinsic)
    if cfg.strategy == "constrained" and _may_stack(st, support_edge):
        # crowding: rest on an object of the same category already on that support
        for si in order:
            try:
                return _place_stacked(st, oid, asset, scale, hull, sups[int(si)], support_edge,
                                      others, body, rng)
            except Fail as f:
                reasons.append(str(f))
                inner.append(f.intrinsic)
    raise Fail(reasons[0] if len(reasons) == 1 else "; ".join(dict.fromkeys(reasons)),
               intrinsic=all(inner))


def _drop_into(st: SolveState, oid: str, asset: Asset, scale: float, R: np.ndarray,
               sup: Support, support_edge: Edge, others: list[Edge], body: Body,
               rng: np.random.Generator, onto: list[PlacedObject], own_fp: Polygon):
    """A pile in a small container: drop the child from above the container at sampled
    positions onto the container and what is in it, and keep the lowest valid rest (an apple
    nestles between the others and the bowl's wall rather than on top of them)."""
    s, n = sup.surface, sup.surface.normal
    owner = onto[0]
    hull = asset_geometry(asset).hull * scale
    hN = (hull @ R.T) @ n
    c3 = (asset_geometry(asset).com * scale) @ R.T
    top = max(float(np.max((st.hulls[o.id] - s.origin) @ n)) for o in onto)
    cu = np.array(own_fp.centroid.coords[0])
    radius = max(np.sqrt(own_fp.area / np.pi), 1e-3)
    r_child = max(float(np.ptp((hull @ R.T) @ s.u)), float(np.ptp((hull @ R.T) @ s.v))) / 2
    inner = own_fp.buffer(-r_child)
    found = []
    last = f"no room left in {sup.owner}"
    for _ in range(16):
        ab = cu + rng.uniform(-1, 1, 2) * 0.5 * radius - np.array([c3 @ s.u, c3 @ s.v])
        t = s.origin + ab[0] * s.u + ab[1] * s.v + (top - float(hN.min()) + 2 * EPS) * n
        cand = PlacedObject(oid, asset.category, asset, scale, R, t)
        d = _drop(cand, world_points(cand, hull_only=True), asset, onto, st, n)
        if not np.isfinite(d):
            continue
        t = t - (d - EPS) * n
        cand = PlacedObject(oid, asset.category, asset, scale, R, t)
        pts = world_points(cand, hull_only=True)
        height = float(np.max((pts - s.origin) @ n))
        com = cand.transform()[:3, :3] @ asset_geometry(asset).com + t
        if height > sup.clearance:
            last = f"the pile would reach {height:.2f} m, above the {sup.clearance:.2f} m free"
            continue
        if inner.is_empty or not inner.contains(shapely.Point(plane_coords(s, com[None])[0])):
            last = f"it would rest on the rim of {sup.owner}"
            continue
        found.append((float(com @ n), t, cand))
    for _, t, cand in sorted(found, key=lambda f: f[0]):
        checks, why = _relations_and_collisions(st, cand, others, body, R, t)
        if checks is None:
            last = why
            continue
        # what it rests on: the object whose drop distance is the contact
        pts = world_points(cand, hull_only=True)
        gaps = {o.id: drop_distance(pts, asset, cand.transform(), st.hulls[o.id], o.asset,
                                    o.transform(), -n) for o in onto}
        under = min(gaps, key=gaps.get)
        holds, res, detail = check_edge(st.scene, support_edge, cand,
                                        resolved=resolution(support_edge, sup.choice))
        if not holds and under != owner.id:
            holds, res, detail = bool(gaps[under] <= 2e-3), {"distance": round(gaps[under], 6)}, \
                f"piled on {under} in {owner.id}"
        return (R, t, sup, body), 1, [(holds, res, detail), *checks], \
            None if under == owner.id else under
    raise Fail(f"no free space on {sup.name} and no room in a pile: {last}")


def _drop(cand: PlacedObject, pts: np.ndarray, asset: Asset, onto: list[PlacedObject],
          st: SolveState, n: np.ndarray) -> float:
    """How far ``cand`` can move down (along ``-n``) before touching any of ``onto``."""
    return min(drop_distance(pts, asset, cand.transform(), st.hulls[o.id], o.asset,
                             o.transform(), -n) for o in onto)


#: Objects of a pile tried as the base of a stack (at random), per support and asset.
PILE_BASES = 6

#: Footprint of a container, in units of the child's, up to which a child finding no free
#: space and none of its kind there is piled on the other things in it (a fruit bowl).
PILE_AREA = 40.0

#: Parent categories that take a plate-like stack for ON (every IN support takes piles).
STACK_ON = ("plate",)


def _may_stack(st: SolveState, edge: Edge) -> bool:
    """Piles and stacks are allowed IN a container or shelf, and ON a plate."""
    if edge.parent.is_room_element:
        return False
    if edge.relation == "IN":
        return True
    parent = st.scene.objects.get(edge.parent.object)
    return edge.relation == "ON" and parent is not None and parent.category in STACK_ON


def _place_stacked(st: SolveState, oid: str, asset: Asset, scale: float, hull: np.ndarray,
                   sup: Support, support_edge: Edge, others: list[Edge], body: Body,
                   rng: np.random.Generator):
    """Place the child on top of a same-category object already on ``sup`` (a can on a can
    on a shelf, a plate on a stack of plates), or, in a small container (a bowl, a basket),
    dropped into it onto its wall or the pile; ``Fail`` when none can take it.

    Returns like ``_place_on`` plus the id of the object it rests on (None: the container).
    """
    s = sup.surface
    n = s.normal
    R, _, _ = solve_rotation(st, oid, asset, sup, support_edge, others, rng, "constrained", scale)
    Y = hull @ R.T
    hN = Y @ n
    c3 = (asset_geometry(asset).com * scale) @ R.T
    owner = st.scene.objects[sup.owner]
    own_fp = Polygon(RG.convex_footprint(plane_coords(s, st.hulls[sup.owner])))
    child_area = Polygon(RG.convex_footprint(np.c_[Y @ s.u, Y @ s.v])).area
    # a small container (a bowl, a basket) holds a pile: it may rest on its wall too
    container = support_edge.relation == "IN" and own_fp.area <= 12 * child_area
    contents = [o for o in st.scene.objects.values()
                if o.placed and o.support_choice == sup.choice and o.id in st.hulls]
    pile = [o for o in contents if o.category == asset.category]
    if container:  # onto whatever is in it (an apple on the bananas in a fruit bowl)
        return _drop_into(st, oid, asset, scale, R, sup, support_edge, others, body, rng,
                          [owner, *contents], own_fp)
    if support_edge.relation == "ON" and _round_asset(asset):
        # dropped on another, a round thing touches it at one point and rolls off a flat
        # plate in settling: as many as fit, then a failure that says how many there are
        there = [o.id for o in st.scene.objects.values() if o.placed
                 and o.support_choice is not None and o.support_choice.owner == sup.owner]
        raise Fail(f"no free space on {sup.name}: it holds {len(there)} object(s) already "
                   f"({', '.join(there[:6])}{', ...' if len(there) > 6 else ''}), and a round "
                   f"{asset.category} piled on a flat {owner.category} rolls off (put them IN a "
                   f"bowl or basket to pile them)")
    bases = [pile[int(k)] for k in rng.permutation(len(pile))[:PILE_BASES]]
    if not bases and support_edge.relation == "IN" and contents \
            and own_fp.area <= PILE_AREA * child_area:
        # none of its kind there, other things are (an apple IN a fruit bowl that holds
        # bananas and an orange): a pile on them
        return _drop_into(st, oid, asset, scale, R, sup, support_edge, others, body, rng,
                          [owner, *contents], own_fp)
    if not bases:
        raise Fail(f"no free space on {sup.name}, and no {asset.category} there to stack on")
    last = f"no {asset.category} on {sup.name} can take another on top"
    for under in bases:
        H = st.hulls[under.id]
        is_owner = under is owner
        top = float(np.max((H - s.origin) @ n))
        fp = own_fp if is_owner else Polygon(RG.convex_footprint(plane_coords(s, H)))
        cu = np.array((sup.region.centroid if is_owner else fp.centroid).coords[0])
        radius = max(np.sqrt(fp.area / np.pi), 1e-3)
        allowed = fp.union(own_fp) if container else fp
        for _ in range(6):
            ab = cu + rng.normal(0.0, (0.4 if container else 0.2) * radius, 2) \
                - np.array([c3 @ s.u, c3 @ s.v])
            h = top - float(hN.min()) + 2 * EPS
            t = s.origin + ab[0] * s.u + ab[1] * s.v + h * n
            cand = PlacedObject(oid, asset.category, asset, scale, R, t)
            pts = world_points(cand, hull_only=True)
            d = _drop(cand, pts, asset, [under] + ([owner] if container else []), st, n)
            if not np.isfinite(d):
                last = f"nothing under it on {under.id}"
                continue
            t = t - (d - EPS) * n
            cand = PlacedObject(oid, asset.category, asset, scale, R, t)
            pts = world_points(cand, hull_only=True)
            height = float(np.max((pts - s.origin) @ n))
            if height > sup.clearance:
                last = f"a pile on {under.id} would reach {height:.2f} m, above the " \
                       f"{sup.clearance:.2f} m of free height"
                continue
            com = plane_coords(s, (cand.transform()[:3, :3] @ asset_geometry(asset).com
                                   + t)[None])[0]
            if not allowed.contains(shapely.Point(com)):
                last = f"its centre of mass would overhang {under.id}"
                continue
            checks, why = _relations_and_collisions(st, cand, others, body, R, t)
            if checks is None:
                last = why
                continue
            if is_owner:  # resting in the container: the usual check of the support relation
                holds, res, detail = check_edge(st.scene, support_edge, cand,
                                                resolved=resolution(support_edge, sup.choice))
                sup_check = (holds, res, detail + " (resting on the container's wall)")
            else:  # the support is the object below (or the container): measure the gap
                gap = _drop(cand, pts, asset, [under] + ([owner] if container else []), st, n)
                sup_check = (bool(gap <= 2e-3), {"distance": round(float(gap), 6)},
                             f"stacked on {under.id}")
            return (R, t, sup, body), 1, [sup_check, *checks], None if is_owner else under.id
    raise Fail(f"no free space on {sup.name} and no stack fits: {last}")


def _wall_choices(st: SolveState, edges: list[Edge], rng: np.random.Generator) -> list[list[Edge]]:
    """Edge lists with ``wall`` (any wall) replaced by each concrete wall, in random order."""
    if not any(e.parent.object == "wall" for e in edges):
        return [edges]
    walls = [n for n in st.scene.room.elements if n.startswith("wall_")]
    out = []
    for k in rng.permutation(len(walls)):
        w = walls[int(k)]
        out.append([replace(e, parent=replace(e.parent, object=w, text=""))
                    if e.parent.object == "wall" else e for e in edges])
    return out


def scaled_mesh(asset: Asset, scale: float) -> MeshArrays:
    """A copy of the asset's mesh at ``scale`` (for its collision body)."""
    m = asset.mesh_arrays()
    return MeshArrays(scaled_vertices(m.vertices, scale), m.faces)


def _place_on(st: SolveState, oid: str, asset: Asset, scale: float, hull: np.ndarray,
              sup: Support, support_edge: Edge, others: list[Edge], body: Body,
              rng: np.random.Generator, cfg: SolverConfig, proposal=None):
    s = sup.surface
    rel = support_edge.relation
    strategy = cfg.strategy
    R, toward, lean = solve_rotation(st, oid, asset, sup, support_edge, others, rng, strategy,
                                     scale)
    Y = hull @ R.T
    hN = Y @ s.normal
    height = float(hN.max() - hN.min())
    if rel == "IN" and height > sup.clearance:
        raise Fail(f"IN: {oid} is {height:.2f} m tall but {sup.name} has "
                   f"{sup.clearance:.2f} m of free height")
    drop = 0.0
    if rel == "HANGING_BELOW":
        lo, hi = support_edge.param("drop")
        drop = rng.uniform(lo, hi)
    h = -float(hN.min()) + EPS + drop
    # room elements are bounded by walls in the collision world; object supports keep a margin
    # (they only keep a hair's breadth from the corners, less than the contact gap EPS)
    region0 = st.memo(sup.owner, ("region0", rel, sup.choice, sup.spans, plane_key(s), cfg.margin),
                      lambda: _inset(sup, cfg.margin))
    # the support's owner and everything holding it up (a cabinet around a stack of plates)
    exclude = support_chain(st.pag, sup.owner) if sup.owner != "room" else set()
    F = RG.convex_outline(np.column_stack([Y @ s.u, Y @ s.v]),
                          outline_indices(asset, R.T @ s.normal))
    overhang = False
    base_solid = None
    lift = 0.0
    leaned = lean_samples(st, oid, asset, scale, R, h, sup, others, region0, rng,
                          cfg.max_trials) \
        if strategy == "constrained" and involves_object(sup, lean) else None
    if leaned is None and strategy == "constrained" and rel == "IN":
        leaned = nest_samples(st, oid, sup, asset, scale, R, rng, cfg.max_trials)
    if leaned is not None:  # leaning on or from an object, or nested (leaning.py, nesting.py)
        region, samples = leaned
    elif strategy == "constrained":
        # a deep hole (a sink cut-out) is an obstacle; a shallow well is filled (spanned)
        holes = [RG.convex_footprint(hole) for hole in sup.holes]
        # a stack: ON an object of the same kind (their PAG nodes share a category)
        stack = rel == "ON" and sup.owner != "room" and bool(
            set(st.pag.objects[oid].candidates) & set(st.pag.objects[sup.owner].candidates))
        ruled = None if stack else _rules_region(st, oid, asset, scale, R, h, sup, support_edge,
                                                 others, region0, F, holes)
        # low parts of the support's owner (burners on a cooktop) are stood on, not avoided
        step = STEP if rel == "ON" and sup.owner != "room" else 0.0
        if step:
            lift = st.memo(sup.owner, ("step", plane_key(s), step),
                           lambda: _step_height(st, sup, step))
        samples = None
        if ruled is not None and lift == 0 and (
                sup.owner == "room" or rel == "IN" or _inside_margin(F, height) == 0):
            # drawn from the relations' region less the obstacles near it, without building
            # it (the obstacles whose grown footprint can reach the region are those listed)
            obst = obstacles(st, sup, exclude, height + EPS, _reach(ruled, F, 0.0), step=step)
            samples = RG.draw_outside(ruled, obst + holes, F, rng, cfg.max_trials)
        if samples is None:
            obst = obstacles(st, sup, exclude, height + EPS,
                             _reach(region0, F, 5.0 if rel == "HANGING_BELOW" else 0.0),
                             step=step)
            if not stack:
                samples = _free_positions(rel, sup, others, region0, obst + holes, F, height,
                                          lift, rng, cfg.max_trials)
        if samples is not None:
            pass  # drawn from the free space without building the region
        elif rel == "HANGING_BELOW":
            # what hangs needs its attachment (the points touching the parent) on the parent's
            # surface, not its whole footprint: a towel is wider than the bar it hangs from; a
            # hook as thick as a thin rail needs only its centre over it
            top = Y[hN <= hN.min() + 2e-3]
            c = np.array([float(np.mean(top @ s.u)), float(np.mean(top @ s.v))])
            Fc = RG.convex_footprint(np.vstack([c + d for d in ((0, 0), (1e-4, 0), (0, 1e-4),
                                                                  (1e-4, 1e-4))]))
            # the owner's other parts (a towel bar's brackets) block only what hangs at their
            # depth: the hook, not the shoulders below
            obst = obstacles(st, sup, exclude, height + EPS, _reach(region0, F, 5.0),
                             parts=False)
            region = RG.clip(RG.erode(region0, [], Fc),
                             RG.erode(RG.bounding_square(region0, pad=5.0), obst, F))
            depth = hN + h
            for lo_h, hi_h, fp in _owner_pieces(st, sup, exclude, height + EPS):
                at = Y[(depth >= lo_h - 1e-3) & (depth <= hi_h + 1e-3)]
                if len(at):
                    Fs = RG.convex_footprint(np.vstack([np.c_[at @ s.u, at @ s.v],
                                                        np.c_[at @ s.u, at @ s.v] + 1e-4]))
                    region = RG.clip(region, RG.erode(RG.bounding_square(region0, pad=5.0),
                                                      [fp], Fs))
            if region.is_empty or region.area < 1e-10:
                if RG.erode(region0, [], Fc).is_empty:
                    raise Fail(f"no room to hang below {sup.name}: its attachment does not "
                               f"fit the surface", intrinsic=True)
                near = Polygon(st.xy[sup.owner]) if sup.owner in st.xy else None
                below = [o for o in st.scene.objects.values() if o.placed and o.id not in exclude
                         and o.id in st.zr and st.zr[o.id][1] > float(s.origin[2]) - height
                         and st.zr[o.id][0] < float(s.origin[2])
                         and near is not None and Polygon(st.xy[o.id]).distance(near) < 0.5]
                names = ", ".join(o.id for o in below[:4]) or "the room's walls or other objects"
                raise Fail(f"no room to hang a {np.ptp(F[:, 0]):.2f} x {np.ptp(F[:, 1]):.2f} m, "
                           f"{height:.2f} m tall {asset.category} below {sup.name}: "
                           f"{names} in the way")
        else:
            region = RG.erode(region0, obst + holes, F)
            if (region.is_empty or region.area < 1e-10) and rel in ("ON", "IN") \
                    and sup.owner != "room" and RG.erode(region0, holes, F).is_empty \
                    and Polygon(F).area <= (STACK_OVER if stack else 1.5) * Polygon(st.xy[sup.owner]).area:
                # a support smaller than the child (a pot on a burner, an apple in a bowl, a
                # bottle on a bathtub's rim): the paper's stability rule, centre of mass over
                # the solid support polygon, decides; only for children no bigger than the
                # parent object (no wardrobe on a mug), up to STACK_OVER times its area in a
                # stack of one category (a picture book on a paperback)
                com = (asset_geometry(asset).com * scale) @ R.T
                solid = region0.difference(shapely.union_all([Polygon(h) for h in holes])) \
                    if holes else region0
                # across several parts (a suitcase on a luggage rack's straps): the centre of
                # mass anywhere over their hull, the base on the parts (checked per sample)
                over = region0 if sup.spans else solid
                region = shapely.affinity.translate(over, -float(com @ s.u), -float(com @ s.v))
                # only obstacles that can reach the positions kept matter
                obst = obstacles(st, sup, exclude, height + EPS, _reach(region, F, 0.0),
                                 step=step)
                region = RG.clip(region, RG.erode(RG.bounding_square(region0, pad=5.0), obst, F))
                room = st.scene.room.elements["floor"].surface
                fp = Polygon(plane_coords(s, room.to_3d(np.asarray(room.polygon.exterior.coords))))
                region = RG.clip(region, RG.erode(fp, [], F))
                overhang, base_solid = True, solid
        if samples is None and (region.is_empty or region.area < 1e-10):
            raise Fail(_no_space(st, sup, F, region0, obst + holes),
                       intrinsic=RG.erode(region0, holes, F).is_empty and not overhang)
        if samples is None:
            ctx = _region_context(st, oid, asset, scale, R, h, sup)
            region = apply_region_rules(ctx, others, region, "object")
            if rel == "SECURED_TO":
                region = height_band(ctx, support_edge, region)
            region = apply_region_rules(ctx, others, region, "part")
            if rel == "ON" and sup.owner != "room":
                if not overhang:
                    region = _well_inside(region, F, height)
                elif _roller(F, height) and not stack:  # a loaf on a loaf: centred below
                    # a roller overhanging the support (a baguette longer than the side table)
                    # keeps its centre of mass ROLL_EDGE widths from the edge
                    w = _widths(F)[0]
                    region = region.buffer(-ROLL_EDGE * w) if region.area > 1e-10 else region
                    if region.is_empty or region.area < 1e-10:
                        raise Fail(_no_space(st, sup, F, region0, obst + holes)
                                   + f" (a {asset.category} lying on its round side keeps its "
                                   f"centre of mass {ROLL_EDGE * w:.2f} m inside the edge, "
                                   f"or it rolls off)")
            if stack:
                region = _stack_centre(region, region0, asset, scale, R, s)
                if region.is_empty or region.area < 1e-10:
                    raise Fail(f"no room on {sup.name}: a {asset.category} stacked on another "
                               f"keeps its centre of mass over the middle "
                               f"{STACK_CENTRE * 100:.0f}% of it, and its footprint on it")
    else:
        region = region0
        samples = None
    trials = 0
    last = "no sample"
    if samples is None:
        samples = RG.sample_uniform(region, rng, cfg.max_trials)  # one triangulation, all draws
    if strategy == "constrained" and len(samples):
        samples = _leave_room(st, oid, sup, R, F, region0, samples)
        if rel == "HANGING_BELOW" and _hung_siblings(st, oid, support_edge):
            samples = _from_one_end(samples, region0)
    if strategy == "constrained" and rel == "IN" and sup.owner != "room" and len(samples) \
            and _round_asset(asset):
        samples = _middle_first(samples, region0, F, asset, scale, R, s)
    if lift > 0 and strategy == "constrained" and len(samples):
        # centred on a low part first (a pan on a burner), so it does not straddle its edge
        com = (asset_geometry(asset).com * scale) @ R.T
        centres = _step_centres(st, sup, STEP)
        seats = [c - np.array([com @ s.u, com @ s.v]) for c in centres]
        # a handle may reach past the cooktop's edge: the seat needs its footprint clear of
        # obstacles and its centre of mass on the support (the checks below measure both)
        free = RG.erode(RG.bounding_square(region0, pad=1.0), obst, F)
        seats = [seats[int(k)] for k in rng.permutation(len(seats))
                 if free.contains(shapely.Point(seats[int(k)]))]
        # seats that cover the fewest other burners first, so a second pan or pot still finds
        # one (random among equals; the sort is stable)
        seats.sort(key=lambda a: _covered(F, a, centres))
        if seats:
            samples = np.vstack([np.array(seats), samples])[:len(samples)]
    if strategy == "constrained" and len(samples):
        # a plate on a plate, a bowl in a bowl: on the parent's axis first (solver/nesting.py)
        samples = concentric_first(st, oid, sup, asset, scale, R, samples)
    same = hung = 0
    # a bowl in a bowl, a cup in a cup: from the parent's rim down onto its inside
    rise = nest_rise(st, oid, sup) if strategy == "constrained" and rel == "IN" else 0.0
    if overhang and rel == "ON" and not sup.spans and proposal is None and toward is None \
            and strategy == "constrained" and len(samples) \
            and _never_upright(asset, scale, R, s, base_solid):
        # the loop below would find the base hanging off at every sample and give up after
        # STRUCTURAL_FAILURES of them: say so at once, the draws made all the same
        raise Fail(f"no valid pose on {sup.name} in "
                   f"{min(len(samples), cfg.max_trials, STRUCTURAL_FAILURES)} trials "
                   f"(last: {HANGS_OFF})")
    for k in range(cfg.max_trials + (proposal is not None)):
        trials += 1
        if proposal is not None and k == 0:
            Rt, t = np.asarray(proposal[0], float), np.asarray(proposal[1], float)
        else:
            if strategy == "rejection":
                R, toward, lean = solve_rotation(st, oid, asset, sup, support_edge, others, rng,
                                                 strategy, scale)
                hN = (hull @ R.T) @ s.normal
                h = -float(hN.min()) + EPS + drop
            ab = samples[k - (proposal is not None)]
            Rt = R
            if toward is not None and strategy == "constrained":
                Rt, h = _face(st, toward, R, hull, s, ab, h, drop, others)
            # above the owner's low parts; the drop below brings it onto them or the surface
            t = s.origin + ab[0] * s.u + ab[1] * s.v + (h + lift + rise) * s.normal
        cand = PlacedObject(oid, asset.category, asset, scale, Rt, t)
        if overhang and not _base_supported(asset, scale, Rt, t, s, base_solid,
                                            upright=rel == "ON"):
            # tested before the drop, which moves the child along the normal only (the test
            # reads positions in the plane and heights relative to the lowest point)
            hung = hung + 1 if last == HANGS_OFF else 1
            last = HANGS_OFF
            if rel == "ON" and not sup.spans and not stack and hung >= STRUCTURAL_FAILURES:
                # the base misses the support wherever it is drawn: structural (across the
                # parts of a spanning support, feet on two straps, fewer draws hold)
                break
            continue
        dropped = False
        if (rel == "ON" or rise) and sup.owner != "room":
            # settle onto the parent's actual geometry: a plate on a plate sits in its well
            parent = st.scene.objects[sup.owner]
            d = drop_distance(world_points(cand, hull_only=True), asset, cand.transform(),
                              st.hulls[sup.owner], parent.asset, parent.transform(), -s.normal)
            if rise and np.isfinite(d):  # nested: rays miss curved walls touching between vertices
                d = pieces_drop(asset, cand.transform(), parent, -s.normal, d + 5e-3)
            dropped = bool(np.isfinite(d) and d > 2 * EPS)
            if dropped:
                t = t - (d - EPS) * s.normal
                cand = PlacedObject(oid, asset.category, asset, scale, Rt, t)
            if lift > 0:  # rest on the low parts under its base (rays may miss a burner)
                pts = world_points(cand, hull_only=True)
                up = _step_under(st, sup, pts, STEP)
                if up > 0:
                    t = t + up * s.normal
                    cand = PlacedObject(oid, asset.category, asset, scale, Rt, t)
                if float(np.min((pts - s.origin) @ s.normal)) + up > THIN_LOW + EPS and \
                        not _base_supported(asset, scale, Rt, t, s, _low_parts(st, sup, STEP),
                                            upright=True):
                    # raised onto low parts, its centre of mass must be over what holds it:
                    # a pot half on a burner's edge tips into the gap in settling
                    last = "its base would rest on the edge of a low part (centre of mass " \
                           "outside what holds it)"
                    continue
        if leaned is not None and lean and not lean[0][0].parent.is_room_element:
            # onto the parent's pieces, not its face's plane (a reclined back cushion)
            t = lean_slide(st, oid, asset, scale, Rt, t, lean[0])
            cand = PlacedObject(oid, asset.category, asset, scale, Rt, t)
        # footprint inside the support polygon: the region guarantees it, except after a TOWARD
        # turn, for rejection samples and proposals
        if not overhang and (Rt is not R or strategy == "rejection"):
            Fw = plane_coords(s, world_points(cand, hull_only=True))
            if not region0.contains(Polygon(RG.convex_footprint(Fw))):
                last = f"footprint leaves {sup.name}"
                continue
        ok, why, checks = _validate(st, cand, support_edge, others, sup)
        if not ok:
            # the region makes relations hold by construction; the same relation failing
            # again and again is structural (a pan that would tip, a part that is not the
            # lowest one): stop wasting samples on this asset
            rel_of = why.split(":")[0]
            same = same + 1 if rel_of == last.split(":")[0] else 1
            last = why
            if same >= STRUCTURAL_FAILURES:
                break
            continue
        body.move(Rt, t)
        hit = st.world.collides(body)
        if hit is not None:
            last = f"collides with {hit}"
            continue
        if rel == "ON" and sup.owner != "room" and dropped and lift == 0:
            # sunk below the named surface onto another part (a teapot inside a tray's rim
            # rests on its base): record the part it touches, as settling will see it
            part = _resting_part(st, sup, cand)
            if part is not None and part != sup.part:
                return (Rt, t, replace(sup, choice=SupportChoice(sup.owner, part, "top")),
                        body), trials, checks, None
        return (Rt, t, sup, body), trials, checks, None
    raise Fail(f"no valid pose on {sup.name} in {trials} trials (last: {last})")


#: Metres up to which low parts under a child's base (a box's tape, a label) need not hold
#: its centre of mass: resting across them it tilts by under a degree, not into a gap.
THIN_LOW = 3e-3

#: Why an overhanging child's pose fails when its base is not held.
HANGS_OFF = ("a foot or the base would hang off the support (centre of mass outside what rests "
             "on it)")


def _region_context(st: SolveState, oid: str, asset: Asset, scale: float, R: np.ndarray,
                    h: float, sup: Support) -> RegionContext:
    """The posed child the region rules clip for (its bbox centre's offset from its origin)."""
    s = sup.surface
    c3 = (asset_geometry(asset).center * scale) @ R.T
    return RegionContext(st, oid, asset, scale, R, h, sup, np.array([c3 @ s.u, c3 @ s.v]),
                         c3 + h * s.normal)


def _rules_region(st: SolveState, oid: str, asset: Asset, scale: float, R: np.ndarray,
                  h: float, sup: Support, support_edge: Edge, others: list[Edge], region0,
                  F: np.ndarray, holes: list[np.ndarray]):
    """The positions the child's relations allow on this support whatever stands on it; Fail
    when there are none.

    The region rules (and SECURED_TO's height band) are applied to the support eroded by the
    footprint alone, before the obstacles are gathered and the support is eroded by them (the
    costly part of a region). The rules clip, so a region they empty here stays empty with
    obstacles: a cabinet NEAR another and AGAINST a wall far from it fails that wall at once,
    with the rule's message about the free support. The region less the obstacles' grown
    footprints is the region ``_place_on`` builds, as a set (positions may be drawn from it
    without building it: :func:`RG.draw_outside`).

    None where this does not apply: no rule (nor height band), hanging children and supports
    too small for the footprint (overhanging children), whose regions are built otherwise
    (stacks are not asked). TOWARD, which keeps a region its cones miss, leaves the region as
    it finds it here; positions drawn from the result are still positions of the built region
    (when the obstacles leave its cones nothing, nothing is drawn and the region is built),
    but a rule emptying it is no proof."""
    rel = support_edge.relation
    if rel == "HANGING_BELOW" or (
            rel != "SECURED_TO" and all(REGION_RULES[e.relation][0] == "none" for e in others)):
        return None
    free = RG.erode(region0, holes, F)
    if free.is_empty or free.area < 1e-10:
        return None  # too small even when empty: _place_on says why (or overhangs)
    ctx = _region_context(st, oid, asset, scale, R, h, sup)
    try:
        free = apply_region_rules(ctx, others, free, "object")
        if rel == "SECURED_TO":
            free = height_band(ctx, support_edge, free)
        return apply_region_rules(ctx, others, free, "part")
    except Fail:
        if any(e.relation == "TOWARD" for e in others):
            # TOWARD keeps a region its cones miss, so with obstacles a later rule may still
            # find room: only the region built with them can tell
            return None
        raise


def _owner_pieces(st: SolveState, sup: Support, exclude: set[str], height: float):
    """``(lowest, highest, footprint)`` of the pieces of the supporting objects (``exclude``)
    other than the support part, in the slab of ``height`` beyond the support plane (heights
    along its normal, footprint in its plane coordinates)."""
    s = sup.surface
    for oid in sorted(exclude):
        if oid == "room":
            continue
        for name, pts in st.world_pieces(oid):
            if oid == sup.owner and name == sup.part:
                continue
            hq = (pts - s.origin) @ s.normal
            if float(hq.max()) <= 1e-3 or float(hq.min()) >= height - 1e-3:
                continue
            yield float(hq.min()), float(hq.max()), RG.convex_footprint(plane_coords(s, pts))


def _round_asset(asset: Asset) -> bool:
    """About as wide as deep and tall (as :func:`parse3d.measure.is_round`): it rolls."""
    ext = hull_extents(asset)[0]
    return float(ext.max()) <= 1.3 * float(ext.min())


def _middle_first(samples: np.ndarray, region0, F: np.ndarray, asset: Asset, scale: float,
                  R: np.ndarray, s) -> np.ndarray:
    """Samples for a round child IN a container, nearest the middle of its floor first, led
    by the middle itself (its centre of mass over it) when the footprint fits there: an apple
    dropped off-centre on a bowl's curved floor rolls to the middle in settling and can tip a
    footed bowl over."""
    c3 = (asset_geometry(asset).com * scale) @ R.T  # its centre of mass over the middle
    mid = np.asarray(region0.centroid.coords[0]) - np.array([c3 @ s.u, c3 @ s.v])
    order = np.argsort(np.linalg.norm(samples - mid, axis=1), kind="stable")
    out = samples[order]
    if region0.contains(Polygon(F + mid)):
        out = np.vstack([mid[None], out])[:len(samples)]
    return out


def _inset(sup: Support, margin: float):
    """The support's region less a margin: objects keep ``margin`` from an object support's
    edge, and a hair's breadth (less than the contact gap EPS) from a room element's corners
    (they are bounded by walls in the collision world)."""
    region0 = sup.region.buffer(-(EPS / 2 if sup.owner == "room" else margin), join_style="mitre")
    return sup.region if region0.is_empty else region0  # tiny supports (a burner): see overhang


def _reach(region, F: np.ndarray, pad: float) -> tuple[float, float, float, float]:
    """The box of obstacles that :func:`RG.erode` can meet, eroding ``region``'s bounding box
    padded by ``pad`` (as :func:`RG.bounding_square` does) by the footprint ``F``."""
    x0, y0, x1, y1 = region.bounds
    lo, hi = F.min(axis=0), F.max(axis=0)
    return (x0 - pad + lo[0], y0 - pad + lo[1], x1 + pad + hi[0], y1 + pad + hi[1])


def _step_height(st: SolveState, sup: Support, step: float) -> float:
    """Height above ``sup`` of the highest piece of its owner rising at most ``step`` above it
    (0 when none)."""
    n = sup.surface.normal
    out = 0.0
    for _, pts in st.world_pieces(sup.owner):
        h = float(np.max((pts - sup.surface.origin) @ n))
        if 1e-3 < h <= step and steps_on(sup, plane_coords(sup.surface, pts)):
            out = max(out, h)
    return out


def _step_under(st: SolveState, sup: Support, pts: np.ndarray, step: float) -> float:
    """How far to raise a child with world points ``pts`` so that its base (points within
    3 mm of its lowest) clears the owner's low parts (rising at most ``step``) under it."""
    n = sup.surface.normal
    h = (pts - sup.surface.origin) @ n
    base = pts[h <= h.min() + 3e-3]
    foot = Polygon(RG.convex_footprint(plane_coords(sup.surface, base))).buffer(1e-4)
    need = float(h.min())
    for top, piece in _low_pieces(st, sup, step):
        if foot.intersects(piece):
            need = max(need, top + EPS)
    return need - float(h.min())


def _low_pieces(st: SolveState, sup: Support, step: float) -> list[tuple[float, Polygon]]:
    """``(height of its top, footprint)`` (plane coordinates) of each piece of the owner that
    rises at most ``step`` above ``sup`` and is stood on (a burner of a cooktop); kept while
    the owner keeps its pose."""
    def make():
        n, out = sup.surface.normal, []
        for _, q in st.world_pieces(sup.owner):
            hq = (q - sup.surface.origin) @ n
            if 1e-3 < float(hq.max()) <= step and float(hq.min()) > -step:
                fp = plane_coords(sup.surface, q)
                if steps_on(sup, fp):
                    out.append((float(hq.max()), Polygon(RG.convex_footprint(fp))))
        return out
    return st.memo(sup.owner, ("low pieces", plane_key(sup.surface), step), make)


def _hung_siblings(st: SolveState, oid: str, edge: Edge) -> bool:
    """Whether objects still to be placed hang below the same object as ``oid``."""
    if edge.parent.is_room_element:
        return False
    return any(e.relation == "HANGING_BELOW" and e.parent.object == edge.parent.object
               and e.child.object != oid and e.child.object not in st.xy
               for e in touching(st.pag, edge.parent.object))


def _from_one_end(samples: np.ndarray, region0) -> np.ndarray:
    """Samples ordered along the support's longest direction, from one end: what hangs on a
    rail with more to come goes beside the last one, not in the middle."""
    pts = np.asarray(shapely.get_coordinates(region0), float)
    if len(pts) < 3:
        return samples
    d = pts - pts.mean(axis=0)
    axis = np.linalg.svd(d, full_matrices=False)[2][0]
    return samples[np.argsort(samples @ axis, kind="stable")]


def _leave_room(st: SolveState, oid: str, sup: Support, R: np.ndarray, F: np.ndarray,
                region0, samples: np.ndarray) -> np.ndarray:
    """Samples reordered so that those leaving room on the support for the objects still to be
    placed beside this one (``SIDE_OF`` / ``ALONG`` it, on the same support) come first: a
    stove with a counter to its right is not pushed into the corner. The room wanted on a side
    is the smallest size of the dependent's categories; the order is otherwise kept."""
    pag, s = st.pag, sup.surface
    owner = sup.owner if sup.owner != "room" else None

    def beside(o: str):
        """Edges of unplaced objects beside ``o`` on the same support."""
        for e in touching(pag, o):
            if e.relation not in ("SIDE_OF", "ALONG") or e.parent.object != o:
                continue
            kid = e.child.object
            if kid in st.scene.objects and st.scene.objects[kid].placed:
                continue
            ke = pag.supporter(kid)
            if ke is not None and (None if ke.parent.is_room_element else ke.parent.object) \
                    == owner:
                yield e

    def need(kid: str, seen: frozenset) -> float:
        """The dependent's smallest size, plus the room its own dependents want (a counter
        right of a stove right of a counter)."""
        from ..assets import registry

        sizes = []
        for c in pag.objects[kid].candidates:
            try:
                sizes.append(registry.get(c).size_range[0])
            except KeyError:
                continue
        more = [need(e.child.object, seen | {kid}) for e in beside(kid)
                if e.child.object not in seen]
        return min(sizes, default=0.0) + max(more, default=0.0)

    wants: list[tuple[np.ndarray, float]] = []
    for e in beside(oid):
        d = side_vector(st, e, R)
        g = np.array([d @ s.u, d @ s.v])
        if np.linalg.norm(g) < 1e-6:
            continue
        wants.append((g / np.linalg.norm(g), need(e.child.object, frozenset({oid}))))
    if not wants:
        return samples
    edge = np.asarray(region0.exterior.coords) if hasattr(region0, "exterior") else \
        np.vstack([np.asarray(p.exterior.coords) for p in region0.geoms])
    ok = np.ones(len(samples), bool)
    for g, need in wants:
        room = float(np.max(edge @ g)) - (samples @ g + float(np.max(F @ g)))
        ok &= room >= need
    return np.vstack([samples[ok], samples[~ok]])


def _base_supported(asset: Asset, scale: float, R: np.ndarray, t: np.ndarray, s,
                    solid, upright: bool = False) -> bool:
    """Whether a child hanging over the edge of a small support still stands: the parts of its
    base (those reaching within 3 mm of its lowest point; the feet of a TV, a pot's bottom),
    each as its convex footprint intersected with the ``solid`` support polygon (plane
    coordinates), must together hold its centre of mass 5 mm inside their convex hull. A TV
    whose foot is off a narrow stand fails; a pot on a smaller burner passes. Across the bars
    of a cradle (a spanning support) the base rests on two bars with the centre of mass
    between them. What rests on one bar (narrower than ``BAR_WIDTH``) must lie along it, its
    base on the bar for at least half the child's length: a bottle across one bar, its neck
    over the gap, tips in settling. On a bar narrower than twice the margin the centre of
    mass need only be over it.

    ``upright`` (``ON``): what stands on its base over a small support needs the held part at
    least 30 % as wide as its base is narrow (a cup is not balanced on a tray's 1 cm rim, its
    base over the tray's floor; a kettle on a smaller burner is); no narrow-bar exception."""
    n = s.normal
    low = np.inf
    pieces = []
    for p in asset.parts:
        w = (part_points([p]) * scale) @ R.T + t
        h = (w - s.origin) @ n
        pieces.append((w, h))
        low = min(low, float(h.min()))
    held = []
    for w, h in pieces:
        if float(h.min()) > low + 3e-3:
            continue
        foot = shapely.MultiPoint(plane_coords(s, w[h <= low + 3e-3])).convex_hull
        foot = foot.buffer(1e-3).intersection(solid)
        if not foot.is_empty:
            held.append(foot)
    if not held:
        return False
    com = plane_coords(s, (R @ (asset_geometry(asset).com * scale) + t)[None])[0]
    hull = shapely.union_all(held).convex_hull
    touched = [g for g in getattr(solid, "geoms", [solid]) if g.intersects(hull)]
    if len(touched) == 1 and _sides(touched[0])[0] < BAR_WIDTH:
        # resting on one bar (a cradle's, a rail): the child lies along it, its base on it
        # over at least half its length; across it (a bottle's body on the bar, its neck over
        # the gap) it tips
        whole = shapely.MultiPoint(plane_coords(s, np.vstack([w for w, _ in pieces]))).convex_hull
        if _sides(hull)[1] < 0.5 * _sides(whole)[1]:
            return False
    if upright:
        base = shapely.MultiPoint(plane_coords(s, np.vstack(
            [w[h <= low + 3e-3] for w, h in pieces]))).convex_hull
        if _sides(hull)[0] < 0.3 * _sides(base)[0]:
            return False
    inner = hull.buffer(-5e-3)
    if inner.is_empty:
        if upright:
            return False
        inner = hull.buffer(1e-6)  # a support narrower than the margin: the centre of mass over it
    return inner.contains(shapely.Point(com))


def _may_fit(sup: Support, ext: list[float]) -> bool:
    """Whether a footprint of sides ``ext`` (short, long) may fit the support's region in
    some turn: not longer or wider than the sides of the region's oriented envelope."""
    short, long = _region_sides(sup.region)
    return ext[0] <= short + 1e-9 and ext[1] <= long + 1e-9


@per_object()
def _region_sides(region) -> tuple[float, float]:
    """:func:`_sides` of a support region, kept per region object."""
    return _sides(region)


def _never_upright(asset: Asset, scale: float, R: np.ndarray, s, solid) -> bool:
    """Whether :func:`_base_supported` with ``upright`` fails wherever the child stands on
    ``solid``: what it holds lies in ``solid``, so its short side is at most the square root
    of the area of any rectangle about ``solid`` (its oriented envelope), which is narrower
    than 30 % of the short side of the child's base (a handbag on a bench's button)."""
    n = s.normal
    pieces = [(w := (part_points([p]) * scale) @ R.T, w @ n) for p in asset.parts]
    low = min(float(h.min()) for _, h in pieces)
    base = shapely.MultiPoint(plane_coords(s, np.vstack(
        [w[h <= low + 3e-3] for w, h in pieces]))).convex_hull
    held = float(np.sqrt(max(solid.minimum_rotated_rectangle.area, 0.0)))
    return held < 0.3 * _sides(base)[0] * (1.0 - 1e-6)


def _sides(poly) -> tuple[float, float]:
    """(short, long) sides of a shape's minimum rotated rectangle (a segment: (0, length))."""
    r = poly.minimum_rotated_rectangle
    if not isinstance(r, Polygon):
        return 0.0, float(r.length)
    xy = np.asarray(r.exterior.coords)[:3]
    a, b = float(np.linalg.norm(xy[1] - xy[0])), float(np.linalg.norm(xy[2] - xy[1]))
    return min(a, b), max(a, b)


def _resting_part(st: SolveState, sup: Support, cand: PlacedObject) -> str | None:
    """The part of ``sup``'s owner that the child rests on: among the owner's pieces under the
    child's base (its points within 3 mm of its lowest), the one whose top is within 3 mm of
    the base; None when none is, or that part has no top surface."""
    s, n = sup.surface, sup.surface.normal
    pts = world_points(cand, hull_only=True)
    h = (pts - s.origin) @ n
    low = float(h.min())
    foot = shapely.MultiPoint(plane_coords(s, pts[h <= low + 3e-3])).convex_hull.buffer(1e-3)
    best, gap = None, 3e-3
    for name, q in st.world_pieces(sup.owner):
        top = float(np.max((q - s.origin) @ n))
        if abs(top - low) <= gap and foot.intersects(
                shapely.MultiPoint(plane_coords(s, q)).convex_hull):
            best, gap = name, abs(top - low)
    owner = st.scene.objects[sup.owner]
    if best is None or "top" not in owner.asset.part(best).surfaces:
        return None
    return best


def _low_parts(st: SolveState, sup: Support, step: float):
    """The footprints of :func:`_low_pieces` as one geometry (the burners a pot may rest on)."""
    pieces = _low_pieces(st, sup, step)
    return shapely.union_all([p for _, p in pieces]) if pieces else Polygon()


def _covered(F: np.ndarray, at: np.ndarray, centres: list[np.ndarray]) -> int:
    """How many of ``centres`` (plane coordinates) the footprint ``F`` placed at ``at`` covers
    or comes within 3 cm of."""
    foot = Polygon(F + at).buffer(0.03)
    return sum(foot.contains(shapely.Point(c)) for c in centres)


def _step_centres(st: SolveState, sup: Support, step: float) -> list[np.ndarray]:
    """Plane coordinates (2,) of the centres of the owner's parts that rise at most ``step``
    above ``sup`` (the burners of a cooktop)."""
    n = sup.surface.normal
    parts: dict[str, list[np.ndarray]] = {}
    for name, pts in st.world_pieces(sup.owner):
        h = (pts - sup.surface.origin) @ n
        if 1e-3 < float(h.max()) <= step and float(h.min()) > -step:
            parts.setdefault(name, []).append(pts)
    out = []
    for pts in parts.values():
        uv = plane_coords(sup.surface, np.vstack(pts))
        out.append(0.5 * (uv.min(axis=0) + uv.max(axis=0)))
    return out


#: A child taller than this many times its narrowest footprint width is tippy.
TIPPY = 1.5


def _free_positions(rel: str, sup: Support, others: list[Edge], region0, obst: list[np.ndarray],
                    F: np.ndarray, height: float, lift: float, rng: np.random.Generator,
                    n: int) -> np.ndarray | None:
    """(n, 2) positions drawn from the free space of a plain support (ON or IN, no relation
    clipping the region, no low parts to stand on) without building the region: the region
    ``_place_on`` would build, with a tippy child kept well inside (see :func:`_well_inside`);
    None when that region must be built (elsewhere, or when it is empty or small: then its
    construction says why, or finds the few positions left)."""
    if rel not in ("ON", "IN") or lift > 0 \
            or any(REGION_RULES[e.relation][0] != "none" for e in others):
        return None
    margin = _inside_margin(F, height) if rel == "ON" and sup.owner != "room" else 0.0
    return RG.free_samples(region0, obst, F, rng, n, margin=margin)


#: Fraction (about its centre) of the support polygon of an object that the centre of mass of
#: one of its own category stacked on it must lie over: a book on a book on a book.
STACK_CENTRE = 0.4

#: Footprint area, in units of the area of the object below, up to which an object of the same
#: category may be stacked on it overhanging its edges (its centre of mass over the middle).
STACK_OVER = 3.0


def _stack_centre(region, region0, asset: Asset, scale: float, R: np.ndarray, s):
    """``region`` (positions of the child's origin) restricted to those that put its centre
    of mass over the middle ``STACK_CENTRE`` of ``region0``: offsets add up along a stack, and
    a book resting near the edge of the one below tips the stack over in settling."""
    com = (asset_geometry(asset).com * scale) @ R.T
    mid = shapely.affinity.scale(region0, STACK_CENTRE, STACK_CENTRE, origin="centroid")
    return RG.clip(region, shapely.affinity.translate(mid, -float(com @ s.u), -float(com @ s.v)))


def _inside_margin(F: np.ndarray, height: float) -> float:
    """Metres a child's footprint ``F`` keeps inside an object's support: a quarter of its
    narrowest width for a tippy child (a TV on its stand, taller than ``TIPPY`` times that
    width), half of it for a roller (:func:`_roller`), else 0."""
    w = float(min(np.ptp(F[:, 0]), np.ptp(F[:, 1])))
    if height > TIPPY * w:
        return 0.25 * w
    return 0.5 * _widths(F)[0] if _roller(F, height) else 0.0


#: A child lying with its width and height within this ratio, and its length beyond it, may
#: roll (looser than the checks' ``ROLL_RATIO``: an oval baguette 8 x 6 cm rolls too).
ROLLER_RATIO = 1.5
#: Widths a roller longer than its support keeps its centre of mass from the support's edge
#: (as a shorter one, its footprint half its width inside).
ROLL_EDGE = 1.0


def _roller(F: np.ndarray, height: float) -> bool:
    """Whether a child with footprint ``F`` and ``height`` lies elongated on a round-ish
    cross-section: nudged near a support's edge (a baguette by an orange) it rolls off."""
    w, L = _widths(F)
    thin, thick = sorted((w, height))
    return thick <= ROLLER_RATIO * thin and ROLLER_RATIO * thick < L


def _widths(F: np.ndarray) -> tuple[float, float]:
    """The narrowest width of footprint ``F`` over directions 2 degrees apart, and its extent
    across that direction (a baguette lying askew is as thin as one lying square)."""
    a = np.deg2rad(np.arange(0.0, 180.0, 2.0))
    d = np.column_stack([np.cos(a), np.sin(a)])
    ext = np.ptp(np.asarray(F, float) @ d.T, axis=0)
    k = int(np.argmin(ext))
    return float(ext[k]), float(ext[(k + 45) % 90])


def _shrunk(region, margin: float):
    """``region`` shrunk by ``margin`` metres, when anything is left."""
    if margin <= 0 or region.area < 1e-10:
        return region
    inner = region.buffer(-margin)
    return inner if not inner.is_empty and inner.area > 1e-10 else region


def _well_inside(region, F: np.ndarray, height: float):
    """Keep a tippy child's or a roller's base well inside the support: the region shrunk by
    :func:`_inside_margin`, when anything is left."""
    return _shrunk(region, _inside_margin(F, height))


def _face(st, toward, R, hull, s, ab, h, drop, others):
    """Turn the child about the support normal to face ``toward`` from position ``ab``: square
    to the nearest side of the target when that keeps TOWARD's tolerance, else at its
    centroid."""
    t0 = s.origin + ab[0] * s.u + ab[1] * s.v + h * s.normal
    target, frame, thull = parent_frame(st, toward)
    front = R @ np.array([0, 1.0, 0])
    want = target - t0
    ang = angle_to(front, want, s.normal)
    if ang is None:
        return R, h
    tol = next((np.deg2rad(e.param("tolerance_deg")) for e in others
                if e.relation == "TOWARD" and e.parent.object == toward), np.deg2rad(10.0))
    if thull is not None:
        # the side of the target facing the child: the target frame axis most aligned with
        # the direction from the target to the child, weighed by the target's half extents
        d = t0 - target
        best = None
        for ax in (frame[:, 0], frame[:, 1]):
            half = max(float(np.ptp(thull @ ax)) / 2, 1e-3)
            score = abs(float(d @ ax)) / half
            if best is None or score > best[0]:
                best = (score, -np.sign(float(d @ ax)) * ax)
        sq = angle_to(front, best[1], s.normal)
        if sq is not None:
            a, b = best[1][:2], want[:2]
            dev = abs(float(np.arctan2(a[0] * b[1] - a[1] * b[0], float(a @ b))))
            if dev <= 0.8 * tol:
                ang = sq
    Rt = axis_angle(s.normal, ang) @ R
    hN2 = (hull @ Rt.T) @ s.normal
    return Rt, -float(hN2.min()) + EPS + drop


def _no_space(st: SolveState, sup: Support, F: np.ndarray, region0, obst) -> str:
    """Why the support has no room: too small, or taken (by whom)."""
    fx, fy = np.ptp(F[:, 0]), np.ptp(F[:, 1])
    if RG.erode(region0, [], F).is_empty:
        b = region0.bounds
        return (f"no free space on {sup.name}: a {fx:.2f} x {fy:.2f} m footprint does not fit "
                f"its {b[2] - b[0]:.2f} x {b[3] - b[1]:.2f} m surface")
    there = [o.id for o in st.scene.objects.values()
             if o.placed and o.support_choice is not None and o.support_choice == sup.choice]
    if not there:
        return f"no free space on {sup.name} for a {fx:.2f} x {fy:.2f} m footprint"
    names = ", ".join(there[:4]) + (", ..." if len(there) > 4 else "")
    return (f"no free space on {sup.name} for a {fx:.2f} x {fy:.2f} m footprint: it holds "
            f"{len(there)} objects already ({names})")


def _validate(st: SolveState, cand: PlacedObject, support_edge: Edge, others: list[Edge],
              sup: Support) -> tuple[bool, str, list]:
    results = []
    for e in [support_edge, *others]:
        holds, res, detail = check_edge(st.scene, e, cand, resolved=resolution(e, sup.choice))
        if not holds:
            return False, f"{e.relation} {e.child} -> {e.parent}: {detail}", []
        results.append((holds, res, detail))
    return True, "", results


def resolution(edge: Edge, choice, *, final: bool = False) -> dict | None:
    """What the checks need to know of a support edge's resolution (part, element, surface);
    ``final`` is the form kept in ``scene.meta["resolved"]`` (no surface for room elements)."""
    if not edge.is_support:
        return None
    room = choice.owner == "room"
    return {"parent_part": None if room else choice.part,
            "parent_element": choice.part if room else None,
            "parent_surface": None if room and final else choice.surface,
            "internal": edge.relation == "IN" and not (room and final)}


def _relations_and_collisions(st, cand, others, body, R, t) -> tuple[list | None, str]:
    """Check a piled candidate pose against the object's other relations, then for collisions
    (``body`` is moved to the pose). Returns ``(checks, "")``, or ``(None, why it failed)``."""
    checks = []
    for e in others:
        holds, res, detail = check_edge(st.scene, e, cand)
        if not holds:
            return None, f"{e.relation} {e.child} -> {e.parent}: {detail}"
        checks.append((holds, res, detail))
    body.move(R, t)
    hit = st.world.collides(body)
    if hit is not None:
        return None, f"collides with {hit}"
    return checks, ""
