"""Crowding: a child finding no free space rests on one of its kind already there (a can on a
can, a plate on a plate), or is dropped into a small container onto what is in it (a pile)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import shapely
from shapely.geometry import Polygon

from ..assets.model import Asset
from ..geometry import regions as RG
from ..measure.checks import EPS, check_edge, world_points
from ..measure.geometry import exact_drop
from ..pag.model import Edge
from ..scene.model import PlacedObject
from .choice import lies_flat
from .collision import Body
from .config import Fail
from .geometry import asset_geometry, drop_distance
from .resting import held_at_rest, rest_points
from .rotation import solve_rotation
from .sampling import round_asset
from .state import SolveState, plane_coords
from .support import Support
from .validation import relations_and_collisions, resolution

__all__ = ["drop_into", "drop_onto", "hollow_like", "nest_edge", "nest_reason",
           "written_choice", "PILE_BASES", "PILE_AREA", "STACK_ON", "may_stack",
           "place_stacked", "rest_across", "ACROSS_DRAWS", "STACK_CENTRE", "STACK_OVER", "stack_centre"]


def drop_into(st: SolveState, oid: str, asset: Asset, scale: float, R: np.ndarray,
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
    Y = hull @ R.T
    r_child = max(float(np.ptp(Y @ s.u)), float(np.ptp(Y @ s.v))) / 2
    inner = own_fp.buffer(-r_child)
    found = []
    last = f"no room left in {sup.owner}"
    for _ in range(16):
        ab = cu + rng.uniform(-1, 1, 2) * 0.5 * radius - np.array([c3 @ s.u, c3 @ s.v])
        t = s.origin + ab[0] * s.u + ab[1] * s.v + (top - float(hN.min()) + 2 * EPS) * n
        cand = PlacedObject(oid, asset.category, asset, scale, R, t)
        d = drop_onto(cand, world_points(cand, hull_only=True), asset, onto, st, n)
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
        checks, why = relations_and_collisions(st, cand, others, body, R, t)
        if checks is None:
            last = why
            continue
        # what it rests on: the object whose drop distance is the contact
        pts = world_points(cand, hull_only=True)
        gaps = {o.id: drop_distance(pts, asset, cand.transform(), st.hulls[o.id], o.asset,
                                    o.transform(), -n) for o in onto}
        under = min(gaps, key=gaps.get)
        if under != owner.id and not _rolls(asset) and not _rests(
                cand, pts, asset, onto, st, n, c3 + t, s, min(np.ptp(Y @ s.u), np.ptp(Y @ s.v))):
            # on a knob, a lid's dome or the edge of another content: it would slide off (a
            # round thing rolls among the others into the container's hollow, where it rests)
            last = f"it would balance on {under} in {owner.id} and slide off"
            continue
        holds, res, detail = check_edge(st.scene, support_edge, cand,
                                        resolved=resolution(support_edge, sup.choice))
        if not holds and under != owner.id:
            holds, res, detail = bool(gaps[under] <= 2e-3), {"distance": round(gaps[under], 6)}, \
                f"piled on {under} in {owner.id}"
        return (R, t, sup, body), 1, [(holds, res, detail), *checks], \
            None if under == owner.id else under
    raise Fail(f"no free space on {sup.name} and no room in a pile: {last}")


def _rolls(asset: Asset) -> bool:
    """Round (:func:`parse3d.solver.sampling.round_asset`) with no large part lying flat: an
    apple, an orange; not a cup as tall as it is wide, which stands on its flat base."""
    size = float(np.ptp(asset_geometry(asset).hull, axis=0).max())
    return round_asset(asset) and not any(
        lies_flat(asset, p) for p in asset.parts if float(np.ptp(p.vertices, axis=0).max()) >= 0.5 * size)


def _rests(cand: PlacedObject, pts: np.ndarray, asset: Asset, onto: list[PlacedObject],
           st: SolveState, n: np.ndarray, com: np.ndarray, s, width: float) -> bool:
    """Whether ``cand``, dropped into a pile, is held by what it touches (its centre of mass
    over the points where it rests on ``onto``: :func:`parse3d.solver.resting.held_at_rest`)."""
    below = [(st.hulls[o.id], o.asset, o.transform()) for o in onto]
    touch = rest_points(pts, asset, cand.transform(), below, -n)
    return held_at_rest(com, touch, s.u, s.v, float(width))


def drop_onto(cand: PlacedObject, pts: np.ndarray, asset: Asset, onto: list[PlacedObject],
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


def may_stack(st: SolveState, edge: Edge) -> bool:
    """Piles and stacks are allowed IN a container or shelf, ON a plate, and ON an object of
    the child's own kind (resting across it and its like neighbours: :func:`rest_across`)."""
    if edge.parent.is_room_element:
        return False
    if edge.relation == "IN":
        return True
    parent = st.scene.objects.get(edge.parent.object)
    return edge.relation == "ON" and parent is not None and (
        parent.category in STACK_ON or _like(st, edge.child.object, parent.id))


def hollow_like(st: SolveState, edge: Edge) -> bool:
    """Whether ``ON child -> parent`` puts the child on a placed object of its own kind that
    holds things inside (an internal support surface: a shopping basket, a bowl, a crate): it
    nests in or rests on it, and however round its outline it does not roll, so it is never
    a heap beside it (:func:`parse3d.solver.intent.beside`, for apples and oranges)."""
    if edge.relation != "ON" or edge.parent.is_room_element:
        return False
    parent = st.scene.objects.get(edge.parent.object)
    return bool(parent is not None and parent.placed and parent.asset is not None
                and parent.asset.internal and _like(st, edge.child.object, parent.id))


def nest_edge(st: SolveState, edge: Edge) -> Edge | None:
    """``IN child -> parent`` (whole objects) for ``ON child -> parent[:part]`` where the parent
    is a hollow one of the child's kind (:func:`hollow_like`): a shopping basket written ON the
    rim of the one below nests in it, as a stack of baskets (or of paper cups, of crates)
    does, resting on its inside or, when as wide, on its rim (:mod:`parse3d.solver.nesting`).
    The relation as written is measured afterwards: resting inside the parent's hollow, the
    ``ON`` contact is the free drop onto it. None for anything else."""
    if not hollow_like(st, edge):
        return None
    c, p = edge.child, edge.parent
    return Edge("IN", replace(c, part=None, index=None, surface=None, text=c.object),
                replace(p, part=None, index=None, surface=None, text=p.object))


def nest_reason(edge: Edge, reasons: list[str]) -> str:
    """Why a child written ``ON`` a hollow one of its kind was nested in it instead
    (:func:`nest_edge`), recorded as relaxed."""
    why = reasons[-1].split("; ")[0]
    return (f"{edge.child.object} found no pose ON {edge.parent} as written ({why}), so it "
            f"nests in {edge.parent.object}, a hollow one of its kind, as stacked baskets do "
            f"(write IN {edge.child.object} -> {edge.parent.object} for a nested stack)")


def written_choice(st: SolveState, edge: Edge, choice):
    """The support choice recorded for a child nested by :func:`nest_edge`: the parent's part
    as written (its rim's top), so the ``ON`` as written is measured on it; ``choice`` when
    no part is named or the asset has no such part."""
    from ..scene.model import SupportChoice

    ref = edge.parent
    parent = st.scene.objects.get(ref.object)
    if ref.part is None or choice is None or parent is None or parent.asset is None:
        return choice
    ps = parent.asset.parts_by_label(ref.part)
    ps = ps[ref.index:ref.index + 1] if ref.index is not None else ps
    if len(ps) != 1:
        return choice
    return SupportChoice(choice.owner, ps[0].name, ref.surface or "top")


def _like(st: SolveState, a: str, b: str) -> bool:
    """Whether the PAG nodes ``a`` and ``b`` share a category (things of one kind)."""
    return bool(set(st.pag.objects[a].candidates) & set(st.pag.objects[b].candidates))


def place_stacked(st: SolveState, oid: str, asset: Asset, scale: float, hull: np.ndarray,
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
    if support_edge.relation == "ON" and sup.owner in st.scene.objects \
            and _like(st, oid, sup.owner):
        # ON one of its kind that has no room on its top: across it and its like neighbours
        return rest_across(st, oid, asset, scale, R, sup, support_edge, others, body, rng)
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
        return drop_into(st, oid, asset, scale, R, sup, support_edge, others, body, rng,
                         [owner, *contents], own_fp)
    if support_edge.relation == "ON" and round_asset(asset):
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
        return drop_into(st, oid, asset, scale, R, sup, support_edge, others, body, rng,
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
            d = drop_onto(cand, pts, asset, [under] + ([owner] if container else []), st, n)
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
            checks, why = relations_and_collisions(st, cand, others, body, R, t)
            if checks is None:
                last = why
                continue
            if is_owner:  # resting in the container: the usual check of the support relation
                holds, res, detail = check_edge(st.scene, support_edge, cand,
                                                resolved=resolution(support_edge, sup.choice))
                sup_check = (holds, res, detail + " (resting on the container's wall)")
            else:  # the support is the object below (or the container): measure the gap
                gap = drop_onto(cand, pts, asset, [under] + ([owner] if container else []), st, n)
                sup_check = (bool(gap <= 2e-3), {"distance": round(float(gap), 6)},
                             f"stacked on {under.id}")
            return (R, t, sup, body), 1, [sup_check, *checks], None if is_owner else under.id
    raise Fail(f"no free space on {sup.name} and no stack fits: {last}")


#: Fraction (about its centre) of the support polygon of an object that the centre of mass of
#: one of its own category stacked on it must lie over: a book on a book on a book.
STACK_CENTRE = 0.4


#: Footprint area, in units of the area of the object below, up to which an object of the same
#: category may be stacked on it overhanging its edges (its centre of mass over the middle).
STACK_OVER = 3.0


def stack_centre(region, region0, asset: Asset, scale: float, R: np.ndarray, s):
    """``region`` (positions of the child's origin) restricted to those that put its centre
    of mass over the middle ``STACK_CENTRE`` of ``region0``: offsets add up along a stack, and
    a book resting near the edge of the one below tips the stack over in settling."""
    com = (asset_geometry(asset).com * scale) @ R.T
    mid = shapely.affinity.scale(region0, STACK_CENTRE, STACK_CENTRE, origin="centroid")
    return RG.clip(region, shapely.affinity.translate(mid, -float(com @ s.u), -float(com @ s.v)))



#: Positions (each at every turn tried) at which a child is dropped onto one of its kind and
#: its like neighbours (:func:`rest_across`).
ACROSS_DRAWS = 12


def _yaw(R: np.ndarray, n: np.ndarray, angle: float) -> np.ndarray:
    """``R`` turned by ``angle`` radians about the unit normal ``n``."""
    c, sn = np.cos(angle), np.sin(angle)
    K = np.array([[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]])
    return (np.eye(3) + sn * K + (1.0 - c) * K @ K) @ R


def _long_axis(pts: np.ndarray, s) -> float:
    """Angle (radians, in the plane ``(u, v)`` of ``s``) of the longer side of the points'
    minimum rotated rectangle seen along the normal."""
    uv = plane_coords(s, pts)
    r = shapely.MultiPoint(uv).minimum_rotated_rectangle
    if not isinstance(r, Polygon):
        return 0.0
    xy = np.asarray(r.exterior.coords)[:3]
    a, b = xy[1] - xy[0], xy[2] - xy[1]
    d = a if np.hypot(*a) >= np.hypot(*b) else b
    return float(np.arctan2(d[1], d[0]))


def rest_across(st: SolveState, oid: str, asset: Asset, scale: float, R: np.ndarray,
                sup: Support, support_edge: Edge, others: list[Edge], body: Body,
                rng: np.random.Generator):
    """A child ``ON`` an object of its own kind that has no room on its top (a rolled towel
    on a rolled towel, a croissant on a croissant in a bread basket): dropped from above onto
    that object, the objects of its kind beside it on the same support and what holds them
    (the basket), lying as the one below lies, and kept where it touches the one below with
    its centre of mass over what it rests on: in the groove between two rolls, across two
    croissants, or on one's top when it balances there. The lowest such rest is kept.

    Returns like ``_place_on`` plus None (its support is the object below)."""
    s, n = sup.surface, sup.surface.normal
    parent = st.scene.objects[sup.owner]
    holder = parent.support_choice.owner if parent.support_choice is not None else "room"
    hull = asset_geometry(asset).hull * scale
    com0 = asset_geometry(asset).com * scale
    # the poses the collision world holds (solved, not settled: a repair after settling)
    H = {o.id: world_points(o, hull_only=True, settled=False) for o in st.scene.objects.values()
         if o.placed and o.id in st.hulls and o.id != oid}
    P = H[parent.id]
    pc = plane_coords(s, P).mean(axis=0)
    reach = float(np.ptp(hull, axis=0).max())
    like = []
    for o in st.scene.objects.values():
        if o.id in (oid, parent.id) or not o.placed or o.id not in st.hulls \
                or o.support_choice is None or not _like(st, oid, o.id):
            continue
        if o.support_choice.owner not in (holder, parent.id):
            continue
        if Polygon(RG.convex_footprint(plane_coords(s, H[o.id]))).distance(
                Polygon(RG.convex_footprint(plane_coords(s, P)))) <= 0.5 * reach:
            like.append(o)
    # a top (or bottom) flat enough to balance on alone: not a bolster's or a roll's, unless
    # the pile is in a container, whose wall and contents catch it (croissants in a basket)
    under = st.pag.supporter(parent.id)
    flat = (under is not None and under.relation == "IN") or any(
        lies_flat(parent.asset, p) for p in parent.asset.parts
        if sup.choice is None or p.name == sup.choice.part)
    # what holds them (a basket) is left to the collision test: its handle arches over them
    onto = [parent, *like]
    # lying as the one below lies (rolls side by side), and turned a quarter
    want = _long_axis(P, s)
    have = _long_axis(hull @ R.T, s)
    turns = [_yaw(R, n, want - have), _yaw(R, n, want - have + np.pi / 2), R]
    centres = [pc] + [0.5 * (pc + plane_coords(s, H[o.id]).mean(axis=0)) for o in like]
    radius = max(float(np.sqrt(Polygon(RG.convex_footprint(plane_coords(s, P))).area / np.pi)),
                 1e-3)
    while len(centres) < ACROSS_DRAWS:
        centres.append(pc + rng.normal(0.0, 0.3 * radius, 2))
    top = max(float(np.max((H[o.id] - s.origin) @ n)) for o in onto)
    found = []
    last = f"nothing of {parent.id} under it"
    for Rk in turns:
        Y = hull @ Rk.T
        c3 = com0 @ Rk.T
        hN = Y @ n
        for cu in centres:
            ab = cu - np.array([c3 @ s.u, c3 @ s.v])
            t = s.origin + ab[0] * s.u + ab[1] * s.v + (top - float(hN.min()) + 2 * EPS) * n
            cand = PlacedObject(oid, asset.category, asset, scale, Rk, t)
            pts = world_points(cand, hull_only=True)
            # rays from the vertices miss curved bodies touching between them (a croissant
            # on a croissant): each drop is bisected on the meshes
            T = cand.transform()
            drops = {o.id: exact_drop(asset, T, o.asset, o.transform(False), -n,
                                      drop_distance(pts, asset, T, H[o.id], o.asset,
                                                    o.transform(False), -n)) for o in onto}
            d = min(drops.values())
            if not np.isfinite(d):
                continue
            t = t - (d - EPS) * n
            cand = PlacedObject(oid, asset.category, asset, scale, Rk, t)
            pts = world_points(cand, hull_only=True)
            gaps = {k: v - d + EPS for k, v in drops.items()}
            if gaps[parent.id] > 2e-3 and not any(
                    gaps[o.id] <= 2e-3 and o.stacked_on == parent.id for o in like):
                # on the one below, or on one of its kind piled on it (a basket too small
                # for two towels side by side holds the second on the first)
                last = f"it would rest on {min(gaps, key=gaps.get)}, not on {parent.id}"
                continue
            if float(np.max((pts - s.origin) @ n)) > sup.clearance + float(np.max((P - s.origin)
                                                                                   @ n)):
                last = "no free height above it"
                continue
            held = [o for o in onto if gaps[o.id] <= 2e-3]
            base = shapely.MultiPoint(np.vstack([plane_coords(s, H[o.id])
                                                 for o in held])).convex_hull
            c_w = Rk @ com0 + t
            com = plane_coords(s, c_w[None])[0]
            if len(held) == 1:  # balanced on the one below: over its middle, and flat
                if not flat:
                    last = f"it would balance on the round top of {held[0].id}"
                    continue
                base = shapely.affinity.scale(base, STACK_CENTRE, STACK_CENTRE,
                                              origin="centroid")
            if not base.buffer(-2e-3).contains(shapely.Point(com)):
                last = f"its centre of mass would not be over {', '.join(o.id for o in held)}"
                continue
            found.append((float(c_w @ n), Rk, t, cand, held))
    for _, Rk, t, cand, held in sorted(found, key=lambda f: f[0]):
        checks, why = relations_and_collisions(st, cand, others, body, Rk, t)
        if checks is None:
            last = why
            continue
        holds, res, detail = check_edge(st.scene, support_edge, cand,
                                        resolved=resolution(support_edge, sup.choice))
        if not holds:
            last = f"{support_edge.relation} {support_edge.child} -> {support_edge.parent}: " \
                   f"{detail}"
            continue
        if len(held) > 1:
            detail += f", across {', '.join(o.id for o in held)}"
        return (Rk, t, sup, body), 1, [(holds, res, detail), *checks], None
    raise Fail(f"no room on {sup.name} and none across it and its like neighbours: {last}")
