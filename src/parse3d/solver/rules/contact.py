"""The contact relations between part surfaces (``AGAINST``, ``LEANING_AGAINST``): they hold
only with the two touching. Both turn the child's named surface to face the parent surface
(fixing its angle about the support normal) and keep the line of origins where the named
part touches it (phase ``part``, after the object-level relations)."""

from __future__ import annotations

import numpy as np
from shapely.geometry.base import BaseGeometry

from ...assets.model import Asset
from ...measure.checks import EPS
from ...measure.reach import STAND, stands_to_lean
from ...pag.model import Edge
from ...relations import PART, SURFACES
from ..config import Fail
from ..flush import excess, flush_reason, over_tolerance, touching_parts
from ..geometry import asset_geometry, part_points
from ..state import SolveState
from .base import (
    Orientation,
    RegionContext,
    RelationRule,
    clip_to_line,
    contact_normal,
    register,
    touching_frame,
    turn_to_face,
)

__all__ = ["Against", "LeaningAgainst"]


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
        c = float(sB.origin @ nB) + gap - float((base + pa) @ nB)
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
