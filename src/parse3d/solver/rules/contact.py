"""The contact relations between part surfaces (``AGAINST``, ``LEANING_AGAINST``): they hold
only with the two touching. Both turn the child's named surface to face the parent surface
(fixing its angle about the support normal) and keep the line of origins where the named
part touches it (phase ``part``, after the object-level relations)."""

from __future__ import annotations

import numpy as np
from shapely.geometry.base import BaseGeometry

from ...assets.model import Asset, Part
from ...measure.checks import EPS
from ...measure.reach import STAND, stands_to_lean
from ...pag.model import Edge
from ...pag.refs import Ref
from ...relations import PART, SURFACES
from ..config import Fail
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
    from it; the named part must be the child's extreme along that normal."""

    names = ("AGAINST",)

    def part_needs(self, e: Edge, ref: Ref, role: str, text: str) -> list[tuple]:
        # a child part reaches furthest along its surface normal (else another part touches)
        if role == "child":
            return [(ref.part, ref.index, text, f"extreme:{ref.surface or e.spec.child_surface}")]
        return []

    def rotate(self, st: SolveState, asset: Asset, o: Orientation, e: Edge) -> None:
        turn_to_face(st, o, e, contact_normal(e.child, e.spec.child_surface), -1.0)

    def region(self, ctx: RegionContext, e: Edge, region: BaseGeometry) -> BaseGeometry:
        sB, g, parts, pts, base = touching_frame(ctx, e)
        nB = sB.normal
        label = e.child.surface or e.spec.child_surface
        # contact: the named part's extreme point along its (rotated) surface normal
        nA_w = ctx.R @ np.array(SURFACES[label])
        pa = pts[int(np.argmax(pts @ nA_w))]
        gap = e.param("gap") + EPS
        check_extreme(ctx, e, parts, nA_w, label)
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


def check_extreme(ctx: RegionContext, e: Edge, parts: list[Part], n: np.ndarray,
                  label: str) -> None:
    """Fail when another part of the child reaches further along the contact normal than the
    named part: the named part could never touch (a sofa's frame behind its back cushion)."""
    if e.child.part is None:
        return
    R, scale = ctx.R, ctx.scale
    mine = float(np.max((part_points(parts) * scale) @ R.T @ n))
    worst, who = 0.0, None
    for p in ctx.asset.parts:
        if p in parts:
            continue
        r = float(np.max((part_points([p]) * scale) @ R.T @ n)) - mine
        if r > worst:
            worst, who = r, p
    if who is not None and worst > 2e-3:
        raise Fail(f"{e.relation} {e.child} -> {e.parent}: {e.child.object}:{who.label} reaches "
                   f"{worst:.2f} m further {label} than {e.child.part} in this "
                   f"{ctx.asset.category} asset: name {e.child.object}:{who.label}@{label} or "
                   f"{e.child.object}@{label}", intrinsic=True)
