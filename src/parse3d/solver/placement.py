"""Stages 1 and 6 of Algorithm 1 for one object: choose an asset and scale, then sample
positions in the feasible region and validate each (relation checks, FCL collisions)."""

from __future__ import annotations

from copy import copy
from dataclasses import dataclass, field, replace

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry

from ..assets.model import Asset
from ..geometry import regions as RG
from ..geometry.meshes import MeshArrays, scaled_vertices
from ..measure.checks import EPS, STEP, world_points
from ..pag.model import Edge
from ..scene.model import PlacedObject, SupportChoice
from .bars import across_opening, held_across, opening
from .choice import (
    SURFACE_AXES,
    alternative_instance,
    draw_instance,
    edge_text,
    free_headroom,
    hung_edge_up,
    instance_scale,
    lacks,
    level_instance,
    no_stack_base,
    requirements,
)
from .collision import Body, cached_body
from .config import STRUCTURAL_FAILURES, Fail, SolverConfig
from .coverings import covers_floor, lay_covering
from .fit import instance_for
from .flush import flush_plan, least_overhung_key
from .geometry import asset_geometry, drop_distance, outline_indices
from .hanging import (
    attachment_region,
    draped_over,
    hang_over,
    hangs_beside,
    hung_by_part,
    hung_lengthwise,
    off_wall,
    off_wall_reason,
    other_hook,
    rail_fit,
    room_below,
)
from .intent import (
    beside,
    lies_flat,
    lies_in_stack,
    lies_on_cover,
    loose_reason,
    names_part,
    overhang,
    whole_object,
)
from .leaning import involves_object, lean_fit, lean_samples, lean_slide
from .ledge import may_lean, may_lean_on_wall, place_leaning, place_on_wall
from .mounting import mount_region, mounts
from .nesting import concentric_first, in_on_top, nest_rise, nest_samples, pieces_drop
from .over import OverEdge, over_after, over_edge, over_instance, place_over
from .regions import apply_region_rules, obstacles
from .resting import rests_on
from .rotation import solve_rotation
from .rows import in_a_row, packed, walled
from .rules import RULES
from .rules.alignment import level_plan, level_scale
from .rules.contact import overhung_plan
from .sampling import (
    HANGS_OFF,
    ROLL_EDGE,
    THIN_LOW,
    across_low_parts,
    base_centred,
    base_supported,
    covered_centres,
    covering_region,
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
    toward_relaxed,
    well_inside,
)
from .slots import may_slot, place_in_slots
from .stacking import (
    STACK_CENTRE,
    STACK_OVER,
    hollow_like,
    may_stack,
    nest_edge,
    nest_reason,
    place_stacked,
    stack_centre,
    written_choice,
)
from .standing import lies_down, may_stand_in, place_standing, standing_instance
from .state import SolveState, plane_coords, plane_key, support_chain
from .support import Support
from .upright import filed_instance, lies_in_cradle, stands_in_row, upright_axis
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
    #: contacts placed flush by another part than the one named (edge index -> why),
    #: recorded as relaxed (:mod:`parse3d.solver.flush`)
    flush: dict[int, str] = field(default_factory=dict)


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
    heap = None if hollow_like(st, support_edge) else beside(
        pag, st.scene, support_edge, no_stack_base)
    if heap is not None:
        others = [*others, heap[1]]
    nest = nest_edge(st, support_edge)  # ON a hollow one of its kind: nests in it (stacking.py)
    headroom = free_headroom(st, support_edge)
    axis = SURFACE_AXES[support_edge.child.surface or support_edge.spec.child_surface]
    for attempt in range(cfg.asset_attempts):
        got = draw_instance(library, node, reqs, tried, rng, reasons, attempt=attempt, keep=keep,
                            loosen=loosen, support_edge=support_edge, smallest=smallest,
                            own=frozenset(map(edge_text, edges)),
                            leans=any(e.relation == "LEANING_AGAINST" for e in edges))
        if got is None:
            break  # every suitable instance was tried
        category, asset, reqs = got
        if keep is None and (key := least_overhung_key(
                [e for i, e in enumerate(edges[1:], 1) if i not in skip and i not in loosen])) \
                and key(asset) > 0:
            # a contact named on a part another part overhangs: every slot ranked, the
            # instance whose named part comes nearest its parent first (flush.py)
            alt = alternative_instance(library, node.candidates, reqs, tried, rng, key=key,
                                       every=True)
            if alt is not None and key(alt[1]) < key(asset):
                category, asset = alt
                tried.add(asset.asset_id)
        if keep is None and attempt == 0:  # surfaces level with their parents' (alignment.py)
            category, asset = level_instance(st, library, oid, edges, skip, reqs, tried,
                                             category, asset)
        if keep is None and attempt == 0:  # nests, has room on its top (fit.py)
            category, asset = instance_for(st, library, oid, support_edge, category, asset,
                                           lambda a, r=reqs: lacks(a, r) is None, tried, rng)
            # a mouth that takes what stands in it (standing.py)
            category, asset = standing_instance(st, library, oid, support_edge, category,
                                                asset, lambda a, r=reqs: lacks(a, r) is None,
                                                tried, rng)
            tried.add(asset.asset_id)
        # a towel ON a tub's rim drawn rolled: a flat one, which hangs over it (over.py)
        category, asset = over_instance(st, library, support_edge, category, asset, reqs, tried)
        # a filed thing on a crowded shelf: a slab that stands in the row (upright.py)
        category, asset = filed_instance(st, library, support_edge, category, asset, reqs,
                                         tried, rng)
        category, asset, scale, short = instance_scale(
            st, oid, library, node, category, asset, reqs, tried, rng, attempt=attempt,
            keep=keep, support_edge=support_edge, headroom=headroom,
            axis=axis if (up := upright_axis(st, support_edge, asset)) is None else up)
        if short is not None:
            reasons.append(short)
            intrinsic.append(False)
            continue
        if keep is None or attempt > 0:  # a surface level with its parent's (alignment.py)
            scale = level_scale(st, node, asset, scale, edges, skip)
        # a soft thing ON a narrow top, or HANGING_BELOW a part that does not face down,
        # hangs over it, folded to fit (over.py); cloth ON a rod hangs below it (hanging.py)
        over = None if draped_over(st.scene, support_edge, asset) is not None \
            else over_edge(st, oid, support_edge, asset, scale)
        if over is not None:
            scale = over[1]
        hang = (over[0] if over is not None else None) \
            or hung_lengthwise(support_edge, asset) or hung_edge_up(support_edge, asset) \
            or lies_on_cover(support_edge, asset) or lies_flat(support_edge, asset, pag) \
            or lies_down(support_edge, asset, pag) \
            or _in_stack(st, support_edge, asset, category)
        # flat things filed on a shelf that holds them only standing: on edge in a row
        # a bottle in a rack's cradle lies on its side, neck out
        row = None if hang is not None else (stands_in_row(st, support_edge, asset, scale)
                                             or lies_in_cradle(st, support_edge, asset, scale))
        if row is not None:
            hang = row[0]
        # a notebook ON its cover, or ON a desk, lies on it; so do books stacked ON one another
        # cloth ON a rod hangs over it, the ON relaxed (hanging.py)
        drape = None if hang is not None else draped_over(st.scene, support_edge, asset)
        if drape is not None:
            hang = hung_edge_up(drape[0], asset) or drape[0]
        # several hung below one rail share its length (towels along a bar)
        scale = rail_fit(st, oid, support_edge, asset, scale,
                         SURFACE_AXES.get(hang.child.surface, 2) if hang is not None else 2)
        scale = lean_fit(st, oid, others, asset, scale)  # side by side along a face
        loose = None
        placed_edge = support_edge
        late = None
        if heap is not None:
            placed_edge, loose = heap[0], heap[2]
        elif nest is not None and attempt == cfg.asset_attempts - 1 and reasons:
            # the stack as written found no pose: nested in the one below instead
            placed_edge, loose = nest, nest_reason(support_edge, reasons)
        elif attempt == cfg.asset_attempts - 1 and reasons and (late := beside(
                pag, st.scene, support_edge, lambda a, ref: True)) is not None:
            # the stack on one of its kind as written found no pose (no room on it, nor
            # across it and its neighbours): beside it on what holds it, a heap
            placed_edge = late[0]
            loose = (f"{oid} found no pose ON {support_edge.parent} as written "
                     f"({reasons[-1].split('; ')[0]}), so it rests beside "
                     f"{support_edge.parent.object}, {late[0].relation} {late[0].parent} "
                     f"(write {late[0].relation} {oid} -> {late[0].parent}, or fewer on the stack)")
        elif drape is not None:
            loose = drape[1]
        elif over is not None:
            loose = over[2]
        elif hang is None and (on_top := in_on_top(st, support_edge, asset, scale)) is not None:
            placed_edge = on_top  # IN an object with no inside to take it: on its top (nesting.py)
        elif hang is None and names_part(support_edge) \
                and 0 < overhang(asset, support_edge)[0] < np.inf \
                and not hangs_beside(st, asset, scale, support_edge):
            # even the best instance is overhung: it rests by the part that reaches furthest
            loose = loose_reason(asset, support_edge, scale)
            placed_edge = whole_object(support_edge)
        # a contact named on a part another part overhangs: flush by that part (flush.py)
        flushed = flush_plan(asset, scale, edges, {*skip, *loosen}) if cfg.relax else {}
        if cfg.relax:  # a surface that does not come level with its parent's (alignment.py)
            flushed.update(level_plan(st, asset, scale, edges, {*skip, *flushed}))
            flushed.update(overhung_plan(st, asset, scale, edges, skip, flushed, loosen))
        placed = [flushed[i][0] if i in flushed else loosen.get(i, e)
                  for i, e in enumerate(edges[1:], 1) if i not in skip]
        try:
            pose, trials, checks, under = _place_asset(st, oid, asset, scale,
                                                       hang or placed_edge,
                                                       [*placed, *others[len(placed):],
                                                        *(row[1:] if row else ()),
                                                        *((late[1],) if late else ())], rng,
                                                       cfg, proposal if attempt == 0 else None)
        except Fail as f:
            reasons.append(str(f))
            intrinsic.append(f.intrinsic)
            total_trials += cfg.max_trials
            # no room below a handle as written, at the last instance: over it (over.py)
            got = None if attempt < cfg.asset_attempts - 1 else over_after(
                st, oid, asset, scale, hang or placed_edge, [*placed, *others[len(placed):]],
                cached_body(asset, scale, lambda a=asset, s=scale: scaled_mesh(a, s)), rng)
            if got is None:
                continue
            pose, trials, checks, under = got
        total_trials += trials
        R, t, sup, body = pose[:4]
        loose = other_hook(st, support_edge, sup, loose)  # the next free hook
        obj = PlacedObject(oid, category, asset, float(scale), R, t, "placed", None, total_trials,
                           support_choice=sup.choice)
        obj.rests_on = pose[4] if len(pose) > 4 else (hang.child.surface if hang is not None
                                                       else None)
        obj.fixed = RULES[(hang or support_edge).relation].fixed
        obj.stacked_on = under
        full = _full_checks(edges, skip, checks)
        if placed_edge is nest:  # measured on the edge as written afterwards
            obj.support_choice = written_choice(st, support_edge, sup.choice)
        for i in (*loosen, *flushed):
            full[i] = None
        if loose is not None:
            full[0] = None  # measured on the edge as written afterwards
        return Placement(obj, body, full, loose, {i: why for i, (_, why) in flushed.items()})
    raise Fail(_summarise(reasons, node), intrinsic=bool(intrinsic) and all(intrinsic))


def _in_stack(st: SolveState, edge: Edge, asset: Asset, category: str) -> Edge | None:
    """``lies_in_stack`` for ``edge``: a book written ON a book, or under one, lies on its
    cover (intent.py)."""
    if edge.relation != "ON" or edge.child.part is not None:
        return None
    parent = st.scene.objects.get(edge.parent.object)
    above = [c for e in st.pag.relations if e.relation == "ON" and e.parent.object == edge.child.object
             for c in st.pag.objects[e.child.object].candidates]
    return lies_in_stack(edge, asset, parent.asset if parent is not None and parent.placed
                         else None, above, category)


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
    body = cached_body(asset, scale, lambda: scaled_mesh(asset, scale))
    if isinstance(support_edge, OverEdge):  # over a bar (over.py)
        return place_over(st, oid, asset, scale, support_edge, others, body, rng)
    geom = asset_geometry(asset)
    hull = geom.hull * scale
    rule = RULES[support_edge.relation]
    sups = rule.surfaces(st, support_edge)
    order = rule.order(sups, support_edge, asset, scale, rng)
    reasons = []
    inner: list[bool] = []
    constrained = cfg.strategy == "constrained"

    def holds(c, sp):
        return validate_pose(st, c, support_edge, others, sp)

    def slotted():
        return _fallback(lambda sp: may_slot(st, asset, scale, sp, support_edge),
                         lambda sp: place_in_slots(st, oid, asset, scale, sp, support_edge,
                                                   body, rng, holds),
                         sups, order, reasons, inner)

    if constrained and support_edge.relation == "IN":
        # flat, IN a rack of tines: on edge between two of them first, as a rack holds plates
        got = slotted()
        if got is not None:
            return got
    for variant in _wall_choices(st, others, rng):
        for si in order:
            sup = sups[int(si)]
            try:
                return _place_on(st, oid, asset, scale, hull, sup, support_edge, variant, body,
                                 rng, cfg, proposal)
            except Fail as f:
                reasons.append(str(f))
                inner.append(f.intrinsic)
    # no room beside what hangs there: a coat over the other coats (solver/hanging.py)
    got = hang_over(st, oid, support_edge, asset, [sups[int(si)] for si in order],
                    lambda sp: _place_on(st, oid, asset, scale, hull, sp, support_edge,
                                         variant, body, rng, cfg, proposal))
    if got is not None:
        return got
    if constrained:
        fallbacks = (
            # too big to lie flat on a ledge: stand it on its edge, leaning back (sheet music)
            (lambda sp: may_lean(st, asset, scale, sp, support_edge),
             lambda sp: place_leaning(st, oid, asset, scale, sp, support_edge, others, body,
                                      rng, holds)),
            # too long to lie in a narrow container: stand it up, leaning on the rim (a
            # toothbrush in a tumbler, flowers in a vase)
            (lambda sp: may_stand_in(st, asset, scale, sp, support_edge),
             lambda sp: place_standing(st, oid, asset, scale, sp, support_edge, others, body,
                                       rng, holds)),
            # flat, ON a rack of tines, and lying there failed: on edge between two of them
            (lambda sp: support_edge.relation != "IN"
             and may_slot(st, asset, scale, sp, support_edge),
             lambda sp: place_in_slots(st, oid, asset, scale, sp, support_edge, body, rng,
                                       holds)),
            # a thin thing that cannot stand on its edge (a picture frame with no easel on a
            # chest): stand it on the top leaning back on the wall behind (ledge.py)
            (lambda sp: may_lean_on_wall(st, asset, scale, sp, support_edge),
             lambda sp: place_on_wall(st, oid, asset, scale, sp, support_edge, others, body,
                                      rng, holds)),
            # crowding: rest on an object of the same category already on that support
            (lambda sp: may_stack(st, support_edge),
             lambda sp: place_stacked(st, oid, asset, scale, hull, sp, support_edge, others,
                                      body, rng)),
        )
        for may, place in fallbacks:
            got = _fallback(may, place, sups, order, reasons, inner)
            if got is not None:
                return got
    raise Fail(reasons[0] if len(reasons) == 1 else "; ".join(dict.fromkeys(reasons)),
               intrinsic=all(inner))


def _fallback(may, place, sups: list, order, reasons: list, inner: list):
    """``place(support)`` on the first support, in ``order``, that ``may(support)`` admits and
    where the placement holds, or None; the reason of each that failed is added to
    ``reasons`` (and whether it was intrinsic to ``inner``)."""
    for si in order:
        sup = sups[int(si)]
        if not may(sup):
            continue
        try:
            return place(sup)
        except Fail as f:
            reasons.append(str(f))
            inner.append(f.intrinsic)
    return None


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


@dataclass
class _OnSupport:
    """The child turned for one support, before its position is drawn: what the steps of
    :func:`_place_on` share. Plane coordinates are the support surface's ``(u, v)``."""

    st: SolveState
    oid: str
    asset: Asset
    scale: float
    hull: np.ndarray
    sup: Support
    edge: Edge
    others: list[Edge]
    cfg: SolverConfig
    #: the rotation, the object it turns to face per position (TOWARD), its lean
    R: np.ndarray
    toward: str | None
    lean: list
    #: metres: a hung child's cord, the origin's height above the plane, the child's height
    drop: float
    h: float
    height: float
    #: the support's region less its margin, the objects holding it up, the footprint
    region0: BaseGeometry
    exclude: set[str]
    F: np.ndarray
    holes: list = field(default_factory=list)
    obst: list = field(default_factory=list)
    #: ON one of its own kind; raised onto the owner's low parts (burners) by ``lift`` m
    stack: bool = False
    lift: float = 0.0
    #: a support smaller than the child: its base must be held by ``base_solid``
    overhang: bool = False
    base_solid: BaseGeometry | None = None
    #: ``(region, samples)`` of a child leaning on an object or nested in one, else None
    leaned: tuple | None = None
    #: the support is a channel's floor, held in by its walls (rows.py)
    walled: bool = False
    #: ``(N, 3)`` points (turned) of the part a child hangs by when what reaches higher stands
    #: beside the parent (flush.py), else None: the whole child's top
    attach: np.ndarray | None = None


def _place_on(st: SolveState, oid: str, asset: Asset, scale: float, hull: np.ndarray,
              sup: Support, support_edge: Edge, others: list[Edge], body: Body,
              rng: np.random.Generator, cfg: SolverConfig, proposal=None):
    """Place the child on one support: turn it (stage 3), draw positions of its origin from
    the feasible region (4 and 5), order them and try each (6); ``Fail`` with the reason."""
    d = _turned(st, oid, asset, scale, hull, sup, support_edge, others, rng, cfg)
    try:
        samples = _ordered(d, _positions(d, rng), rng)
        return _try_poses(d, samples, body, rng, proposal)
    except Fail:  # a rug or a mat: what finds no room on it may reach onto the floor
        grown = covering_region(st, sup, d.region0, d.F) \
            if support_edge.relation == "ON" and cfg.strategy == "constrained" else None
        if grown is None:
            raise
    d = _turned(st, oid, asset, scale, hull, sup, support_edge, others, rng, cfg)
    d.region0 = grown
    samples = _ordered(d, _positions(d, rng), rng)
    return _try_poses(d, samples, body, rng, proposal)


def _turned(st: SolveState, oid: str, asset: Asset, scale: float, hull: np.ndarray,
            sup: Support, support_edge: Edge, others: list[Edge], rng: np.random.Generator,
            cfg: SolverConfig) -> _OnSupport:
    """The child's rotation on ``sup``, its height above the plane and its footprint."""
    s = sup.surface
    rel = support_edge.relation
    R, toward, lean = solve_rotation(st, oid, asset, sup, support_edge, others, rng,
                                     cfg.strategy, scale)
    Y = hull @ R.T
    hN = Y @ s.normal
    height = float(hN.max() - hN.min())
    if rel == "IN" and height > sup.clearance:
        raise Fail(f"IN: {oid} is {height:.2f} m tall but {sup.name} has "
                   f"{sup.clearance:.2f} m of free height")
    drop = RULES[rel].offset(support_edge, rng)
    h = -float(hN.min()) + EPS + drop
    attach = hung_by_part(st, asset, scale, support_edge) if RULES[rel].hangs else None
    if attach is not None:  # by its named part, what reaches higher beside the parent (flush.py)
        attach = attach @ R.T
        h = -float((attach @ s.normal).min()) + EPS + drop
    # room elements are bounded by walls in the collision world; object supports keep a margin
    # (they only keep a hair's breadth from the corners, less than the contact gap EPS)
    walls = walled(st, sup)  # a channel's floor (rows.py)
    region0 = st.memo(sup.owner, ("region0", rel, sup.choice, sup.spans, sup.reaches,
                                  plane_key(s), cfg.margin, walls),
                      lambda: inset(sup, cfg.margin, walls))
    # the support's owner and everything holding it up (a cabinet around a stack of plates)
    exclude = support_chain(st.pag, sup.owner) if sup.owner != "room" else set()
    F = RG.convex_outline(np.column_stack([Y @ s.u, Y @ s.v]),
                          outline_indices(asset, R.T @ s.normal))
    return _OnSupport(st, oid, asset, scale, hull, sup, support_edge, others, cfg, R, toward,
                      lean, drop, h, height, region0, exclude, F, walled=walls,
                      attach=attach)


def _positions(d: _OnSupport, rng: np.random.Generator) -> np.ndarray:
    """``(n, 2)`` positions of the child's origin: leaning on an object or nested (their own
    modules), drawn from the free space and the relations' region (``constrained``), or
    uniform over the support (``rejection``)."""
    st, sup, cfg = d.st, d.sup, d.cfg
    constrained = cfg.strategy == "constrained"
    d.leaned = lean_samples(st, d.oid, d.asset, d.scale, d.R, d.h, sup, d.others, d.region0,
                            rng, cfg.max_trials) \
        if constrained and involves_object(sup, d.lean) else None
    if d.leaned is None and constrained and d.edge.relation == "IN":
        d.leaned = nest_samples(st, d.oid, sup, d.asset, d.scale, d.R, rng, cfg.max_trials)
    if d.leaned is not None:  # leaning on or from an object, or nested (leaning.py, nesting.py)
        region, samples = d.leaned
    elif constrained:
        region, samples = _feasible(d, rng)
    else:
        region, samples = d.region0, None
    if samples is None:
        samples = RG.sample_uniform(region, rng, cfg.max_trials)  # one triangulation, all draws
    return samples


def _feasible(d: _OnSupport, rng: np.random.Generator):
    """``(region, None)``: the feasible region of the child's origin, built; or ``(None,
    samples)`` drawn from it without building it. ``Fail`` when it is empty."""
    st, sup, cfg, F = d.st, d.sup, d.cfg, d.F
    rel, s, region0 = d.edge.relation, sup.surface, d.region0
    if mounts(d):  # fixed by its back to a part smaller than it (mounting.py)
        return mount_region(d), None
    # a deep hole (a sink cut-out) is an obstacle; a shallow well is filled (spanned)
    d.holes = holes = [RG.convex_footprint(hole) for hole in sup.holes]
    # a stack: ON an object of the same kind (their PAG nodes share a category)
    d.stack = rel == "ON" and sup.owner != "room" and bool(
        set(st.pag.objects[d.oid].candidates) & set(st.pag.objects[sup.owner].candidates))
    if covers_floor(sup, rel, d.height, F):  # a rug: only what reaches into its slab (coverings.py)
        region, d.R, d.F, d.obst = lay_covering(st, sup, d.exclude, d.height + EPS, region0,
                                                holes, F, d.R)
        if region.is_empty or region.area < 1e-10:
            raise Fail(no_space(st, sup, F, region0, d.obst + holes),
                       intrinsic=RG.erode(region0, holes, F).is_empty)
        return _clip_by_relations(d, region), None
    ruled = None if d.stack else rules_region(st, d.oid, d.asset, d.scale, d.R, d.h, sup,
                                              d.edge, d.others, region0, F, holes)
    # low parts of the support's owner (burners on a cooktop) are stood on, not avoided
    step = STEP if rel == "ON" and sup.owner != "room" and not d.walled else 0.0
    if step:
        d.lift = st.memo(sup.owner, ("step", plane_key(s), step),
                         lambda: step_height(st, sup, step))
    samples = None
    if ruled is not None and d.lift == 0 and (
            sup.owner == "room" or rel == "IN" or inside_margin(F, d.height, d.walled) == 0):
        # drawn from the relations' region less the obstacles near it, without building
        # it (the obstacles whose grown footprint can reach the region are those listed)
        d.obst = obstacles(st, sup, d.exclude, d.height + EPS, reach_box(ruled, F, 0.0),
                           step=step)
        samples = RG.draw_outside(ruled, d.obst + holes, F, rng, cfg.max_trials)
    if samples is None:
        d.obst = obstacles(st, sup, d.exclude, d.height + EPS,
                           reach_box(region0, F, 5.0 if RULES[rel].hangs else 0.0),
                           step=step)
        if not d.stack:
            samples = free_positions(rel, sup, d.others, region0, d.obst + holes, F, d.height,
                                     d.lift, rng, cfg.max_trials, d.walled)
    if samples is not None:
        return None, samples  # drawn from the free space without building the region
    if RULES[rel].hangs:
        region = _hanging_region(d)
    else:
        region = RG.erode(region0, d.obst + holes, F)
        if (region.is_empty or region.area < 1e-10) and step and not d.stack and not d.walled \
                and (over := across_low_parts(d, step)) is not None:
            region, d.obst, d.lift = over  # across a plate's rim (sampling.py)
        if (region.is_empty or region.area < 1e-10) and rel in ("ON", "IN") \
                and sup.owner != "room" and RG.erode(region0, holes, F).is_empty \
                and Polygon(F).area <= (STACK_OVER if d.stack or sup.spans else 1.5) \
                * Polygon(st.xy[sup.owner]).area:
            region = _overhanging_region(d, step)
    if region.is_empty or region.area < 1e-10:
        raise Fail(no_space(st, sup, F, region0, d.obst + holes),
                   intrinsic=RG.erode(region0, holes, F).is_empty and not d.overhang)
    return _clip_by_relations(d, region), None


def _hanging_region(d: _OnSupport):
    """Where a child hanging below an object's part may be: what hangs needs its attachment
    (the points touching the parent) on the parent's surface, not its whole footprint (a
    towel is wider than the bar it hangs from; a hook as thick as a thin rail needs only its
    centre over it); the owner's other parts (a towel bar's brackets) block only what hangs
    at their depth: the hook, not the shoulders below."""
    st, sup, F, region0 = d.st, d.sup, d.F, d.region0
    region0 = attachment_region(region0, sup.region)  # a ring, a tine: hung from its bottom
    s = sup.surface
    Y = d.hull @ d.R.T
    hN = Y @ s.normal
    top = Y[hN <= hN.min() + 2e-3]
    if d.attach is not None:
        aN = d.attach @ s.normal
        top = d.attach[aN <= aN.min() + 2e-3]
    c = np.array([float(np.mean(top @ s.u)), float(np.mean(top @ s.v))])
    Fc = RG.convex_footprint(np.vstack([c + o for o in ((0, 0), (1e-4, 0), (0, 1e-4),
                                                        (1e-4, 1e-4))]))
    d.obst = obst = obstacles(st, sup, d.exclude, d.height + EPS, reach_box(region0, F, 5.0),
                              parts=False)
    square = RG.bounding_square(region0, pad=5.0)
    free = RG.erode(square, obst, F)
    # a pot too wide for the gap to the wall behind: out from it on its hook (hanging.py)
    got = off_wall(st, sup, region0, Fc, free, F)
    region = got[0] if got is not None else RG.clip(RG.erode(region0, [], Fc), free)
    if got is not None and got[1] > 0:
        d.sup = copy(sup)
        d.sup.out = off_wall_reason(d.edge, sup, got[1])
    depth = hN + d.h
    for lo_h, hi_h, fp in owner_pieces(st, sup, d.exclude, d.height + EPS):
        if region.is_empty:
            break  # nothing left for the owner's other pieces to block
        at = Y[(depth >= lo_h - 1e-3) & (depth <= hi_h + 1e-3)]
        if len(at):
            Fs = RG.convex_footprint(np.vstack([np.c_[at @ s.u, at @ s.v],
                                                np.c_[at @ s.u, at @ s.v] + 1e-4]))
            region = RG.clip(region, RG.erode(square, [fp], Fs))
    if region.is_empty or region.area < 1e-10:
        if RG.erode(region0, [], Fc).is_empty:
            raise Fail(f"no room to hang below {sup.name}: its attachment does not "
                       f"fit the surface", intrinsic=True)
        near = Polygon(st.xy[sup.owner]) if sup.owner in st.xy else None
        below = [o for o in st.scene.objects.values() if o.placed and o.id not in d.exclude
                 and o.id in st.zr and st.zr[o.id][1] > float(s.origin[2]) - d.height
                 and st.zr[o.id][0] < float(s.origin[2])
                 and near is not None and Polygon(st.xy[o.id]).distance(near) < 0.5]
        names = ", ".join(o.id for o in below[:4]) or "the room's walls or other objects"
        raise Fail(f"no room to hang a {np.ptp(F[:, 0]):.2f} x {np.ptp(F[:, 1]):.2f} m, "
                   f"{d.height:.2f} m tall {d.asset.category} below {sup.name}: "
                   f"{names} in the way")
    return region


def _overhanging_region(d: _OnSupport, step: float):
    """A support smaller than the child (a pot on a burner, an apple in a bowl, a bottle on
    a bathtub's rim): the paper's stability rule, centre of mass over the solid support
    polygon, decides; only for children no bigger than the parent object (no wardrobe on a
    mug), up to ``STACK_OVER`` times its area in a stack of one category (a picture book on
    a paperback). The positions whose centre of mass is over the support, clear of
    obstacles, on the floor's footprint; marks ``d`` as overhanging."""
    st, sup, F, region0 = d.st, d.sup, d.F, d.region0
    s = sup.surface
    com = (asset_geometry(d.asset).com * d.scale) @ d.R.T
    solid = region0.difference(shapely.union_all([Polygon(h) for h in d.holes])) \
        if d.holes else region0
    # across several parts (a suitcase on a luggage rack's straps): the centre of
    # mass anywhere over their hull, the base on the parts (checked per sample)
    over = region0 if sup.spans else solid
    region = shapely.affinity.translate(over, -float(com @ s.u), -float(com @ s.v))
    # only obstacles that can reach the positions kept matter
    d.obst = obstacles(st, sup, d.exclude, d.height + EPS, reach_box(region, F, 0.0),
                       step=step)
    region = RG.clip(region, RG.erode(RG.bounding_square(region0, pad=5.0), d.obst, F))
    room = st.scene.room.elements["floor"].surface
    fp = Polygon(plane_coords(s, room.to_3d(np.asarray(room.polygon.exterior.coords))))
    region = RG.clip(region, RG.erode(fp, [], F))
    d.overhang, d.base_solid = True, solid
    return region


def _clip_by_relations(d: _OnSupport, region):
    """``region`` clipped by the relations' region rules (object-level, SECURED_TO's height
    band, then part-level contacts), kept well inside an object's top for a tippy child or a
    roller, and over the middle of the one below for a stack."""
    st, sup, F, rel = d.st, d.sup, d.F, d.edge.relation
    ctx = region_context(st, d.oid, d.asset, d.scale, d.R, d.h, sup)
    region = apply_region_rules(ctx, d.others, region, "object")
    region = RULES[rel].band(ctx, d.edge, region)
    region = apply_region_rules(ctx, d.others, region, "part")
    if rel == "ON" and sup.owner != "room":
        if not d.overhang:
            region = well_inside(region, F, d.height, d.walled)
        elif is_roller(F, d.height) and not d.stack:  # a loaf on a loaf: centred below
            # a roller overhanging the support (a baguette longer than the side table)
            # keeps its centre of mass ROLL_EDGE widths from the edge
            w = footprint_widths(F)[0]
            region = region.buffer(-ROLL_EDGE * w) if region.area > 1e-10 else region
            if region.is_empty or region.area < 1e-10:
                raise Fail(no_space(st, sup, F, d.region0, d.obst + d.holes)
                           + f" (a {d.asset.category} lying on its round side keeps its "
                           f"centre of mass {ROLL_EDGE * w:.2f} m inside the edge, "
                           f"or it rolls off)")
    if d.stack:
        region = stack_centre(region, d.region0, d.asset, d.scale, d.R, sup.surface)
        if region.is_empty or region.area < 1e-10:
            raise Fail(f"no room on {sup.name}: a {d.asset.category} stacked on another "
                       f"keeps its centre of mass over the middle "
                       f"{STACK_CENTRE * 100:.0f}% of it, and its footprint on it")
    return region


def _ordered(d: _OnSupport, samples: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """The samples in the order they are tried: leaving room for what comes beside, from one
    end of a rail with more to hang, round things in the middle of a container, pans on a
    burner, a plate on a plate's axis (each first)."""
    if d.cfg.strategy != "constrained" or not len(samples):
        return samples
    st, oid, sup, asset, scale, R, F = d.st, d.oid, d.sup, d.asset, d.scale, d.R, d.F
    s, rel, region0 = sup.surface, d.edge.relation, d.region0
    if in_a_row(st, oid, d.edge, sup, F, region0):  # side by side along a strip (rows.py)
        samples = from_one_end(samples, region0)
    else:  # a crowded row of like things: against its ends and one another (rows.py)
        samples = packed(st, oid, d.edge, sup, F, region0, samples)
    # a relaxed FAR_FROM or NEAR: as far (near) as the support allows (sampling.py)
    samples = toward_relaxed(st, oid, asset, scale, R, sup, d.others, samples)
    samples = leave_room(st, oid, sup, R, F, region0, samples)
    samples = room_below(st, oid, sup, F, samples)  # a hook's hat clear of others (hanging.py)
    if RULES[rel].hangs and hung_siblings(st, oid, d.edge):
        samples = from_one_end(samples, region0)
    if rel == "IN" and sup.owner != "room" and round_asset(asset):
        samples = middle_first(samples, region0, F, asset, scale, R, s)
    if d.lift > 0:
        # centred on a low part first (a pan on a burner), so it does not straddle its edge
        com = (asset_geometry(asset).com * scale) @ R.T
        centres = step_centres(st, sup, STEP)
        seats = [c - np.array([com @ s.u, com @ s.v]) for c in centres]
        # a handle may reach past the cooktop's edge: the seat needs its footprint clear of
        # obstacles and its centre of mass on the support (the checks below measure both)
        free = RG.erode(RG.bounding_square(region0, pad=1.0), d.obst, F)
        seats = [seats[int(k)] for k in rng.permutation(len(seats))
                 if free.contains(shapely.Point(seats[int(k)]))]
        # seats that cover the fewest other burners first, so a second pan or pot still finds
        # one (random among equals; the sort is stable)
        seats.sort(key=lambda a: covered_centres(F, a, centres))
        if seats:
            samples = np.vstack([np.array(seats), samples])[:len(samples)]
    if d.overhang and rel == "ON" and not sup.spans and not d.stack:
        # wider than its support (a microwave on a small fridge): its base centred over the
        # support first, where its feet have the most room (sampling.py)
        samples = np.vstack([base_centred(asset, scale, R, s, d.base_solid), samples])
    if d.overhang and rel == "ON" and (hole := opening(sup)) is not None:
        # across a ring round an opening (a tray on a tub's rim): centred on its long axis
        samples = across_opening(hole, samples, base_centred(asset, scale, R, s, hole), F)
    # a plate on a plate, a bowl in a bowl: on the parent's axis first (solver/nesting.py)
    return concentric_first(st, oid, sup, asset, scale, R, samples)


def _try_poses(d: _OnSupport, samples: np.ndarray, body: Body, rng: np.random.Generator,
               proposal):
    """Try the poses in turn (``proposal`` first): dropped onto the parent's geometry, then
    checked (relations, collisions); the first valid one, or ``Fail`` with the last reason
    (early when the same relation keeps failing: structural)."""
    st, oid, asset, scale, sup, cfg = d.st, d.oid, d.asset, d.scale, d.sup, d.cfg
    s, rel, strategy = sup.surface, d.edge.relation, cfg.strategy
    R, toward, lean, h = d.R, d.toward, d.lean, d.h
    trials = 0
    last = "no sample"
    same = hung = 0
    # a bowl in a bowl, a cup in a cup: from the parent's rim down onto its inside
    rise = nest_rise(st, oid, sup) if strategy == "constrained" and rel == "IN" else 0.0
    if d.overhang and rel == "ON" and not sup.spans and proposal is None and toward is None \
            and strategy == "constrained" and len(samples) \
            and never_upright(asset, scale, R, s, d.base_solid):
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
                R, toward, lean = solve_rotation(st, oid, asset, sup, d.edge, d.others, rng,
                                                 strategy, scale)
                hN = (d.hull @ R.T) @ s.normal
                h = -float(hN.min()) + EPS + d.drop
            ab = samples[k - (proposal is not None)]
            Rt = R
            if toward is not None and strategy == "constrained":
                Rt, h = face_target(st, toward, R, d.hull, s, ab, h, d.drop, d.others)
            # above the owner's low parts; the drop below brings it onto them or the surface
            t = s.origin + ab[0] * s.u + ab[1] * s.v + (h + d.lift + rise) * s.normal
        cand = PlacedObject(oid, asset.category, asset, scale, Rt, t)
        if d.overhang and not (
                held_across(asset, scale, Rt, t, s, d.base_solid) if sup.spans and rel == "ON"
                else base_supported(asset, scale, Rt, t, s, d.base_solid, upright=rel == "ON")):
            # tested before the drop, which moves the child along the normal only (the test
            # reads positions in the plane and heights relative to the lowest point)
            hung = hung + 1 if last == HANGS_OFF else 1
            last = HANGS_OFF
            if rel == "ON" and not sup.spans and not d.stack and hung >= STRUCTURAL_FAILURES:
                # the base misses the support wherever it is drawn: structural (across the
                # parts of a spanning support, feet on two straps, fewer draws hold)
                break
            continue
        dropped = False
        if (rel == "ON" or rise) and sup.owner != "room":
            cand, dropped, why = _onto_parent(d, cand, rise)
            t = cand.position
            if not why and d.overhang and sup.spans and rel == "ON" \
                    and not held_across(asset, scale, Rt, t, s, d.base_solid, rests=True):
                why = HANGS_OFF  # caught by something below the parts (a wheel on a rail)
            if not why and (d.overhang or d.lift > 0) and not sup.spans and rel == "ON" \
                    and not rests_on(cand, st.scene.objects[sup.owner],
                                     np.vstack([p for _, p in st.world_pieces(sup.owner)]),
                                     s.origin, s.normal, s.u, s.v):
                why = HANGS_OFF  # over the edge of a raised part it came to rest on (resting.py)
            if why:
                last = why
                continue
        if d.leaned is not None and lean and not lean[0][0].parent.is_room_element:
            # onto the parent's pieces, not its face's plane (a reclined back cushion)
            t = lean_slide(st, oid, asset, scale, Rt, t, lean[0])
            cand = PlacedObject(oid, asset.category, asset, scale, Rt, t)
        # footprint inside the support polygon: the region guarantees it, except after a TOWARD
        # turn, for rejection samples and proposals
        if not d.overhang and (Rt is not R or strategy == "rejection"):
            Fw = plane_coords(s, world_points(cand, hull_only=True))
            if not d.region0.contains(Polygon(RG.convex_footprint(Fw))):
                last = f"footprint leaves {sup.name}"
                continue
        ok, why, checks = validate_pose(st, cand, d.edge, d.others, sup)
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
        if rel == "ON" and sup.owner != "room" and dropped and d.lift == 0:
            # sunk below the named surface onto another part (a teapot inside a tray's rim
            # rests on its base): record the part it touches, as settling will see it
            part = resting_part(st, sup, cand)
            if part is not None and part != sup.part:
                return (Rt, t, replace(sup, choice=SupportChoice(sup.owner, part, "top")),
                        body), trials, checks, None
        return (Rt, t, sup, body), trials, checks, None
    raise Fail(f"no valid pose on {sup.name} in {trials} trials (last: {last})")


#: Metres below a named surface that a child dropped onto its owner's geometry may sink
#: (into a tray inside its rim, into a plate's well); further, it fell through.
FALL_THROUGH = 0.1


def _onto_parent(d: _OnSupport, cand: PlacedObject, rise: float
                 ) -> tuple[PlacedObject, bool, str]:
    """``cand`` settled onto the parent's actual geometry (a plate on a plate sits in its
    well; nested, onto its inside) and onto the owner's low parts under its base: ``(cand,
    dropped, why)`` with ``why`` saying why the pose fails ("" when it does not)."""
    st, sup, asset, scale = d.st, d.sup, d.asset, d.scale
    s, Rt, t = sup.surface, cand.rotation, cand.position
    parent = st.scene.objects[sup.owner]
    dist = drop_distance(world_points(cand, hull_only=True), asset, cand.transform(),
                         st.hulls[sup.owner], parent.asset, parent.transform(), -s.normal)
    if rise and np.isfinite(dist):  # nested: rays miss curved walls touching between vertices
        dist = pieces_drop(asset, cand.transform(), parent, -s.normal, dist + 5e-3)
    dropped = bool(np.isfinite(dist) and dist > 2 * EPS)
    if dropped and sup.owner != "room" and dist - (d.drop + d.lift + rise) > FALL_THROUGH:
        # through the named surface, far down onto another part of the owner (a keyboard
        # between a stand's arms down onto its floor rails): not resting on what was named
        return cand, False, (f"it would fall {dist:.2f} m through {sup.name} onto a lower "
                             f"part of {sup.owner}")
    if dropped:
        t = t - (dist - EPS) * s.normal
        cand = PlacedObject(d.oid, asset.category, asset, scale, Rt, t)
    if d.lift > 0:  # rest on the low parts under its base (rays may miss a burner)
        pts = world_points(cand, hull_only=True)
        up = step_under(st, sup, pts, STEP)
        if up > 0:
            t = t + up * s.normal
            cand = PlacedObject(d.oid, asset.category, asset, scale, Rt, t)
        at = float(np.min((pts - s.origin) @ s.normal)) + up
        if at > THIN_LOW + EPS and \
                not base_supported(asset, scale, Rt, t, s, low_parts(st, sup, STEP, at),
                                   upright=True):
            # raised onto low parts, its centre of mass must be over what holds it:
            # a pot half on a burner's edge tips into the gap in settling
            return cand, dropped, ("its base would rest on the edge of a low part (centre of "
                                   "mass outside what holds it)")
    return cand, dropped, ""
