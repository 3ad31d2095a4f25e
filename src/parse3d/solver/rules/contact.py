"""The contact relations between part surfaces (``AGAINST``, ``LEANING_AGAINST``): they hold
only with the two touching. Both turn the child's named surface to face the parent surface
(fixing its angle about the support normal) and keep the line of origins where the named
part touches it (phase ``part``, after the object-level relations)."""

from __future__ import annotations

import numpy as np
from shapely.geometry.base import BaseGeometry

from ...assets.model import Asset
from ...geometry.surfaces import Surface
from ...measure.checks import DIST_TOL, EPS
from ...measure.reach import STAND, stands_to_lean
from ...pag.model import Edge
from ...relations import PART, SURFACES
from ..config import Fail
from ..flush import excess, flush_reason, over_tolerance, touching_parts
from ..geometry import asset_geometry, part_points
from ..state import SolveState, parts_for
from .base import (
    Orientation,
    RegionContext,
    RelationRule,
    clip_to_line,
    contact_normal,
    measured_after,
    parent_surface_world,
    register,
    support_plane,
    touching_frame,
    turn_to_face,
)

__all__ = ["Against", "LeaningAgainst", "parent_overhang", "overhung_plan"]


class ContactRule(RelationRule):
    family = "contact"
    kind = PART
    contact = True
    region_phase = "part"
    fixes_yaw = True
    relax_order = 1


@register
class Against(ContactRule):
    """The named child surface faces the parent surface, its part's extreme point ``gap``
    from it; no other part may reach further than that gap (an instance whose other part
    does is placed flush by that part, the relation relaxed: :mod:`parse3d.solver.flush`)."""

    names = ("AGAINST",)

    def rotate(self, st: SolveState, asset: Asset, o: Orientation, e: Edge) -> None:
        turn_to_face(st, o, e, contact_normal(e.child, e.spec.child_surface), -1.0)

    def region(self, ctx: RegionContext, e: Edge, region: BaseGeometry) -> BaseGeometry:
        sB, g, parts, pts, base = touching_frame(ctx, e)
        nB = sB.normal
        label = e.child.surface or e.spec.child_surface
        # contact: the extreme point along its (rotated) surface normal of the named part
        # with the pads ending it (a fridge's vent grille on its back touches for the back)
        nA_w = ctx.R @ np.array(SURFACES[label])
        if e.child.part is not None:
            pts = (part_points(touching_parts(ctx.asset, e)) * ctx.scale) @ ctx.R.T
        pa = pts[int(np.argmax(pts @ nA_w))]
        gap = e.param("gap") + EPS
        check_extreme(ctx, e)
        # another part of the parent reaching past the named one at the child's heights (a
        # countertop over its cabinet's side): the child stops at that part
        n = ctx.sup.surface.normal
        hts = (base + (asset_geometry(ctx.asset).hull * ctx.scale) @ ctx.R.T) @ n
        over = parent_overhang(ctx.st, e, sB, float(hts.min()), float(hts.max()), n)[0]
        c = float(sB.origin @ nB) + max(gap, over + EPS) - float((base + pa) @ nB)
        return clip_to_line(ctx, e, region, g, c)


@register
class LeaningAgainst(ContactRule):
    """The named child surface faces the parent (a flat leaner's bottom: it stands on its
    edge), tilted by ``angle_deg`` so that the named part touches it (the tilt is drawn in
    :func:`parse3d.solver.rotation.solve_rotation`, on an object's face in
    :mod:`parse3d.solver.leaning`)."""

    names = ("LEANING_AGAINST",)

    def rotate(self, st: SolveState, asset: Asset, o: Orientation, e: Edge) -> None:
        nA = contact_normal(e.child, e.spec.child_surface)
        if stands_to_lean(asset, st.pag, e.child.object):
            nA = STAND.T @ nA  # a flat child on its edge: its bottom faces the parent
        sB = turn_to_face(st, o, e, nA, -1.0)
        if sB is not None:
            o.lean = (e, -sB.normal)

    def region(self, ctx: RegionContext, e: Edge, region: BaseGeometry) -> BaseGeometry:
        from ..leaning import lean_line  # within the parent face's extent

        got = lean_line(ctx, e, region)
        if got is not None:
            return got
        sB, g, parts, pts, base = touching_frame(ctx, e)
        nB = sB.normal
        src = pts if e.child.part is not None else \
            (asset_geometry(ctx.asset).hull * ctx.scale) @ ctx.R.T
        reach = float(np.max(src @ (-nB)))
        target = float(sB.origin @ (-nB)) - EPS
        c = target - float(base @ (-nB)) - reach
        return clip_to_line(ctx, e, region, -g, c)


def check_extreme(ctx: RegionContext, e: Edge) -> None:
    """Fail when another part of the child reaches further along the contact normal than the
    named part by more than the gap written: it would enter the parent while the named part
    keeps its gap (the placement goes flush by that part first: :mod:`parse3d.solver.flush`)."""
    if e.child.part is None or not over_tolerance(excess(ctx.asset, e, ctx.scale)):
        return
    raise Fail(flush_reason(ctx.asset, e, ctx.scale), intrinsic=True)


def parent_overhang(st: SolveState, e: Edge, sB: Surface, lo: float, hi: float,
                    n: np.ndarray) -> tuple[float, str]:
    """How far (m) another part of ``e``'s parent object reaches past the named parent surface
    ``sB`` (world) toward the child, among the parts reaching into the child's heights ``lo``
    to ``hi`` along the support normal ``n`` (world), and that part's label: a countertop 1 cm
    over its cabinet's side, where a unit beside it touches the countertop, not the cabinet.
    ``(0, "")`` for a room element, a parent named without a part, or none reaching past."""
    ref = e.parent
    if ref.is_room_element or ref.part is None:
        return 0.0, ""
    pobj = st.scene.objects.get(ref.object)
    if pobj is None or not pobj.placed:
        return 0.0, ""
    named = {p.name for p in parts_for(pobj.asset, ref)}
    T = pobj.transform()
    d0 = float(sB.origin @ sB.normal)
    best, who = 0.0, ""
    for p in pobj.asset.parts:
        if p.name in named:
            continue
        P = part_points([p]) @ T[:3, :3].T + T[:3, 3]
        h = P @ n
        if h.max() <= lo + EPS or h.min() >= hi - EPS:
            continue  # above or below the child: it passes under or over it
        reach = float(np.max(P @ sB.normal)) - d0
        if reach > best:
            best, who = reach, p.label
    return best, who


def overhung_plan(st: SolveState, asset: Asset, scale: float, edges: list[Edge], leave,
                  placed: dict[int, tuple[Edge, str]], loosen: dict[int, Edge]
                  ) -> dict[int, tuple[Edge, str]]:
    """For one object's ``edges`` (the support first) but ``leave``, the ``AGAINST`` contacts
    whose named parent part another part of the parent overhangs toward the child by more
    than the ``gap`` written, at the heights of ``asset`` at ``scale`` on its support (units
    side by side whose countertops reach past their cabinets): index -> (the edge placed
    instead: as placed so far, ``placed`` or ``loosen``, not rejecting a pose, the child
    flush with the overhanging part by :meth:`Against.region`; why, recorded as the
    relation's relaxation, after the reason already in ``placed``)."""
    sup = support_plane(st, edges[0])
    if sup is None:
        return {}
    n = sup.normal
    n_c = np.array(SURFACES[edges[0].child.surface or edges[0].spec.child_surface], float)
    hp = asset_geometry(asset).hull @ n_c
    lo = float(sup.origin @ n)
    hi = lo + scale * float(hp.max() - hp.min())
    out = {}
    for i, e in enumerate(edges[1:], 1):
        if i in leave or e.relation != "AGAINST" or e.parent.part is None \
                or e.parent.is_room_element:
            continue
        try:
            sB = parent_surface_world(st, e.parent, e.spec.parent_surface)[0]
        except Fail:
            continue
        over, who = parent_overhang(st, e, sB, lo, hi, n)
        if over <= float(e.param("gap")) + DIST_TOL:
            continue
        side = e.parent.surface or e.spec.parent_surface
        po = e.parent.object
        why = (f"{e.relation} {e.child} -> {e.parent}: {po}:{who} reaches {over:.3f} m further "
               f"{side} than {po}:{e.parent.part}, so {e.child.object} touches {po}:{who}: "
               f"name {po}:{who}@{side} or {po}@{side}")
        before = placed.get(i)
        edge = before[0] if before is not None else loosen.get(i, e)
        out[i] = (measured_after(edge), why if before is None else f"{before[1]}; {why}")
    return out
