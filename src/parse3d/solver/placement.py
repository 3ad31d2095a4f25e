"""Stages 1 and 6 of Algorithm 1 for one object: choose an asset and scale, then sample
positions in the feasible region and validate each (relation checks, FCL collisions)."""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import shapely
from shapely.geometry import Polygon

from ..assets.model import Asset
from ..geometry import regions as RG
from ..geometry.meshes import MeshArrays, scaled_vertices
from ..measure.checks import EPS, STEP, world_points
from ..pag.model import Edge
from ..scene.model import PlacedObject, SupportChoice
from .choice import (
    HEADROOM_FIT,
    SURFACE_AXES,
    alternative_instance,
    boards_hold,
    contents_scale,
    edge_text,
    extent_across,
    extent_along,
    flush_edges,
    free_headroom,
    hung_edge_up,
    lacks,
    part_overhang,
    requirements,
    room_failure,
    span_need,
    too_tall_failure,
)
from .collision import Body, cached_body
from .config import STRUCTURAL_FAILURES, Fail, SolverConfig
from .geometry import asset_geometry, drop_distance, hull_extents, outline_indices
from .hanging import edge_up, rail_fit, rail_scale, thinness
from .intent import beside, loose_reason, names_part, overhang, soft, whole_object
from .leaning import involves_object, lean_samples, lean_slide
from .ledge import may_lean, place_leaning
from .nesting import concentric_first, floor_fit, nest_rise, nest_samples, pieces_drop
from .regions import apply_region_rules, height_band, obstacles
from .rotation import solve_rotation
from .sampling import (
    HANGS_OFF,
    ROLL_EDGE,
    THIN_LOW,
    base_supported,
    covered_centres,
    face_target,
    footprint_widths,
    free_positions,
    from_one_end,
    hung_siblings,
    inset,
    inside_margin,
    is_roller,
    leave_room,
    low_parts,
    may_fit,
    middle_first,
    never_upright,
    no_space,
    owner_pieces,
    reach_box,
    region_context,
    resting_part,
    round_asset,
    rules_region,
    step_centres,
    step_height,
    step_under,
    well_inside,
)
from .stacking import STACK_CENTRE, STACK_OVER, may_stack, place_stacked, stack_centre
from .standing import may_stand_in, place_standing
from .state import SolveState, plane_coords, plane_key, support_chain
from .support import Support, support_candidates
from .validation import resolution, validate_pose

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
    dropped = {edge_text(edges[i]) for i in (*skip, *loosen)}
    reqs = [r for r in requirements(pag, oid) if r[2] not in dropped]
    tried: set[str] = set()
    # ON a round thing of its kind (an apple on an apple): beside it, a heap
    heap = beside(pag, st.scene, support_edge,
                  lambda a, ref: lacks(a, [(ref.part, ref.index, "", "stack_base")]) is not None)
    if heap is not None:
        others = [*others, heap[1]]
    headroom = free_headroom(st, support_edge)
    axis = SURFACE_AXES[support_edge.child.surface or support_edge.spec.child_surface]
    for attempt in range(cfg.asset_attempts):
        category = node.candidates[int(rng.integers(len(node.candidates)))]
        asset = library.get(category, rng)
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
            alt = alternative_instance(library, node.candidates, reqs, tried | {asset.asset_id}, rng,
                                       smallest=True)
            if alt is not None:
                category, asset = alt
        elif reasons and too_tall_failure(reasons[-1]):
            # too tall for its height band on a wall (curtains hung at 0.8-1 m): the lowest
            # untried instance next (its up axis)
            alt = alternative_instance(library, node.candidates, reqs, tried | {asset.asset_id}, rng,
                                       key=lambda a: extent_along(a, 2))
            if alt is not None:
                category, asset = alt
        else:
            picked = False
        if not (keep is not None and attempt == 0) and (
                not picked and asset.asset_id in tried or lacks(asset, reqs)):
            # constraint-aware selection (also when a rule above found nothing and kept the
            # draw): another instance that has what the relations need, among a sample of
            # slots, then among every slot (a board game with a lid: most are card decks)
            alt = alternative_instance(library, node.candidates, reqs, tried, rng) or alternative_instance(
                library, node.candidates, reqs, tried, rng, every=True)
            if alt is None and (loose_reqs := soft(reqs)) != reqs:
                # no instance is the flat base a stack of its kind needs (apples): any one,
                # and what would stack on it rests beside it
                alt = alternative_instance(library, node.candidates, loose_reqs, tried, rng)
                if alt is not None:
                    reqs = loose_reqs
            if alt is None and (boards := boards_hold(reqs)) != reqs:
                # no instance holds anything inside the named shelf: one whose shelf is a
                # board, and what is IN it stands on its top (a wall shelf)
                alt = alternative_instance(library, node.candidates, boards, tried, rng, every=True)
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
            alt = alternative_instance(library, node.candidates, reqs, tried | {asset.asset_id}, rng,
                                       key=lambda a: overhang(a, support_edge)[0], every=True)
            if alt is not None and overhang(alt[1], support_edge)[0] < overhang(
                    asset, support_edge)[0]:
                category, asset = alt
        tried.add(asset.asset_id)
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
        if keep is not None and attempt == 0:
            scale = keep.scale
        elif scale * extent_along(asset, axis) > HEADROOM_FIT * headroom:
            # taller than every shelf it may go IN (a cereal box on a grocery shelf): the lowest
            # untried instance, then shrunk to the free height within its category's range
            alt = alternative_instance(library, node.candidates, reqs, tried, rng,
                                       key=lambda a: extent_along(a, axis))
            if alt is not None and extent_along(alt[1], axis) < extent_along(asset, axis):
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
        reach = span_need(st, support_edge)
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
                reasons.append(f"a {scale * extent_across(asset, axis):.2f} m {category} does not fit "
                               f"across {ref.object}'s {ref.part} parts ({reach:.2f} m needed)")
                intrinsic.append(False)
                continue
        hang = hung_edge_up(support_edge, asset)
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
        axis = SURFACE_AXES[support_edge.child.surface or support_edge.spec.child_surface]
        ext = sorted(scale * float(x) for k, x in enumerate(hull_extents(asset)[0]) if k != axis)
        order = np.array(sorted(range(len(sups)), key=lambda i: not may_fit(sups[i], ext)))
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
                                     body, rng, lambda c, sp: validate_pose(st, c, support_edge,
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
                                      lambda c, sp: validate_pose(st, c, support_edge, others, sp))
            except Fail as f:
                reasons.append(str(f))
                inner.append(f.intrinsic)
    if cfg.strategy == "constrained" and may_stack(st, support_edge):
        # crowding: rest on an object of the same category already on that support
        for si in order:
            try:
                return place_stacked(st, oid, asset, scale, hull, sups[int(si)], support_edge,
                                     others, body, rng)
            except Fail as f:
                reasons.append(str(f))
                inner.append(f.intrinsic)
    raise Fail(reasons[0] if len(reasons) == 1 else "; ".join(dict.fromkeys(reasons)),
               intrinsic=all(inner))


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
                      lambda: inset(sup, cfg.margin))
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
        ruled = None if stack else rules_region(st, oid, asset, scale, R, h, sup, support_edge,
                                                others, region0, F, holes)
        # low parts of the support's owner (burners on a cooktop) are stood on, not avoided
        step = STEP if rel == "ON" and sup.owner != "room" else 0.0
        if step:
            lift = st.memo(sup.owner, ("step", plane_key(s), step),
                           lambda: step_height(st, sup, step))
        samples = None
        if ruled is not None and lift == 0 and (
                sup.owner == "room" or rel == "IN" or inside_margin(F, height) == 0):
            # drawn from the relations' region less the obstacles near it, without building
            # it (the obstacles whose grown footprint can reach the region are those listed)
            obst = obstacles(st, sup, exclude, height + EPS, reach_box(ruled, F, 0.0), step=step)
            samples = RG.draw_outside(ruled, obst + holes, F, rng, cfg.max_trials)
        if samples is None:
            obst = obstacles(st, sup, exclude, height + EPS,
                             reach_box(region0, F, 5.0 if rel == "HANGING_BELOW" else 0.0),
                             step=step)
            if not stack:
                samples = free_positions(rel, sup, others, region0, obst + holes, F, height,
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
            obst = obstacles(st, sup, exclude, height + EPS, reach_box(region0, F, 5.0),
                             parts=False)
            region = RG.clip(RG.erode(region0, [], Fc),
                             RG.erode(RG.bounding_square(region0, pad=5.0), obst, F))
            depth = hN + h
            for lo_h, hi_h, fp in owner_pieces(st, sup, exclude, height + EPS):
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
                obst = obstacles(st, sup, exclude, height + EPS, reach_box(region, F, 0.0),
                                 step=step)
                region = RG.clip(region, RG.erode(RG.bounding_square(region0, pad=5.0), obst, F))
                room = st.scene.room.elements["floor"].surface
                fp = Polygon(plane_coords(s, room.to_3d(np.asarray(room.polygon.exterior.coords))))
                region = RG.clip(region, RG.erode(fp, [], F))
                overhang, base_solid = True, solid
        if samples is None and (region.is_empty or region.area < 1e-10):
            raise Fail(no_space(st, sup, F, region0, obst + holes),
                       intrinsic=RG.erode(region0, holes, F).is_empty and not overhang)
        if samples is None:
            ctx = region_context(st, oid, asset, scale, R, h, sup)
            region = apply_region_rules(ctx, others, region, "object")
            if rel == "SECURED_TO":
                region = height_band(ctx, support_edge, region)
            region = apply_region_rules(ctx, others, region, "part")
            if rel == "ON" and sup.owner != "room":
                if not overhang:
                    region = well_inside(region, F, height)
                elif is_roller(F, height) and not stack:  # a loaf on a loaf: centred below
                    # a roller overhanging the support (a baguette longer than the side table)
                    # keeps its centre of mass ROLL_EDGE widths from the edge
                    w = footprint_widths(F)[0]
                    region = region.buffer(-ROLL_EDGE * w) if region.area > 1e-10 else region
                    if region.is_empty or region.area < 1e-10:
                        raise Fail(no_space(st, sup, F, region0, obst + holes)
                                   + f" (a {asset.category} lying on its round side keeps its "
                                   f"centre of mass {ROLL_EDGE * w:.2f} m inside the edge, "
                                   f"or it rolls off)")
            if stack:
                region = stack_centre(region, region0, asset, scale, R, s)
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
        samples = leave_room(st, oid, sup, R, F, region0, samples)
        if rel == "HANGING_BELOW" and hung_siblings(st, oid, support_edge):
            samples = from_one_end(samples, region0)
    if strategy == "constrained" and rel == "IN" and sup.owner != "room" and len(samples) \
            and round_asset(asset):
        samples = middle_first(samples, region0, F, asset, scale, R, s)
    if lift > 0 and strategy == "constrained" and len(samples):
        # centred on a low part first (a pan on a burner), so it does not straddle its edge
        com = (asset_geometry(asset).com * scale) @ R.T
        centres = step_centres(st, sup, STEP)
        seats = [c - np.array([com @ s.u, com @ s.v]) for c in centres]
        # a handle may reach past the cooktop's edge: the seat needs its footprint clear of
        # obstacles and its centre of mass on the support (the checks below measure both)
        free = RG.erode(RG.bounding_square(region0, pad=1.0), obst, F)
        seats = [seats[int(k)] for k in rng.permutation(len(seats))
                 if free.contains(shapely.Point(seats[int(k)]))]
        # seats that cover the fewest other burners first, so a second pan or pot still finds
        # one (random among equals; the sort is stable)
        seats.sort(key=lambda a: covered_centres(F, a, centres))
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
            and never_upright(asset, scale, R, s, base_solid):
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
                Rt, h = face_target(st, toward, R, hull, s, ab, h, drop, others)
            # above the owner's low parts; the drop below brings it onto them or the surface
            t = s.origin + ab[0] * s.u + ab[1] * s.v + (h + lift + rise) * s.normal
        cand = PlacedObject(oid, asset.category, asset, scale, Rt, t)
        if overhang and not base_supported(asset, scale, Rt, t, s, base_solid,
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
                up = step_under(st, sup, pts, STEP)
                if up > 0:
                    t = t + up * s.normal
                    cand = PlacedObject(oid, asset.category, asset, scale, Rt, t)
                if float(np.min((pts - s.origin) @ s.normal)) + up > THIN_LOW + EPS and \
                        not base_supported(asset, scale, Rt, t, s, low_parts(st, sup, STEP),
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
        ok, why, checks = validate_pose(st, cand, support_edge, others, sup)
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
            part = resting_part(st, sup, cand)
            if part is not None and part != sup.part:
                return (Rt, t, replace(sup, choice=SupportChoice(sup.owner, part, "top")),
                        body), trials, checks, None
        return (Rt, t, sup, body), trials, checks, None
    raise Fail(f"no valid pose on {sup.name} in {trials} trials (last: {last})")

