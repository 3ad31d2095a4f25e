"""Crowding: a child finding no free space rests on one of its kind already there (a can on a
can, a plate on a plate), or is dropped into a small container onto what is in it (a pile)."""

from __future__ import annotations

import numpy as np
import shapely
from shapely.geometry import Polygon

from ..assets.model import Asset
from ..geometry import regions as RG
from ..measure.checks import EPS, check_edge, world_points
from ..pag.model import Edge
from ..scene.model import PlacedObject
from .collision import Body
from .config import Fail
from .geometry import asset_geometry, drop_distance
from .rotation import solve_rotation
from .sampling import round_asset
from .state import SolveState, plane_coords
from .support import Support
from .validation import relations_and_collisions, resolution

__all__ = ["drop_into", "drop_onto", "PILE_BASES", "PILE_AREA", "STACK_ON", "may_stack",
           "place_stacked", "STACK_CENTRE", "STACK_OVER", "stack_centre"]


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
    r_child = max(float(np.ptp((hull @ R.T) @ s.u)), float(np.ptp((hull @ R.T) @ s.v))) / 2
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
        holds, res, detail = check_edge(st.scene, support_edge, cand,
                                        resolved=resolution(support_edge, sup.choice))
        if not holds and under != owner.id:
            holds, res, detail = bool(gaps[under] <= 2e-3), {"distance": round(gaps[under], 6)}, \
                f"piled on {under} in {owner.id}"
        return (R, t, sup, body), 1, [(holds, res, detail), *checks], \
            None if under == owner.id else under
    raise Fail(f"no free space on {sup.name} and no room in a pile: {last}")


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
    """Piles and stacks are allowed IN a container or shelf, and ON a plate."""
    if edge.parent.is_room_element:
        return False
    if edge.relation == "IN":
        return True
    parent = st.scene.objects.get(edge.parent.object)
    return edge.relation == "ON" and parent is not None and parent.category in STACK_ON


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

