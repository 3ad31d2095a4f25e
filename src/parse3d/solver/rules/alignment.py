"""The alignment relations between part surfaces (``ALIGNED_WITH``, ``OPPOSITE_TO``,
``PARALLEL_TO``): they hold at any distance. All three fix the child's angle about the support
normal (its named surface parallel to the parent's, or anti-parallel for ``OPPOSITE_TO``);
``ALIGNED_WITH`` and ``OPPOSITE_TO`` also keep the line of origins where the two surfaces are
coplanar (phase ``part``)."""

from __future__ import annotations

import numpy as np
from shapely.geometry.base import BaseGeometry

from ...assets.model import Asset, Part
from ...pag.model import Edge
from ...relations import PART, SURFACES
from ..geometry import part_points
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

__all__ = ["AlignedWith", "OppositeTo", "ParallelTo"]


class AlignmentRule(RelationRule):
    family = "alignment"
    kind = PART
    fixes_yaw = True
    relax_order = 1
    #: +1: the two surfaces face the same way; -1: they face each other
    sign = 1.0

    def rotate(self, st: SolveState, asset: Asset, o: Orientation, e: Edge) -> None:
        turn_to_face(st, o, e, contact_normal(e.child, e.spec.child_surface), self.sign)


class Coplanar(AlignmentRule):
    """The child's named surface in the parent surface's plane."""

    region_phase = "part"

    def region(self, ctx: RegionContext, e: Edge, region: BaseGeometry) -> BaseGeometry:
        sB, g, parts, pts, base = touching_frame(ctx, e)
        nB = sB.normal
        label = e.child.surface or e.spec.child_surface
        pa = ctx.R @ child_surface_point(parts, label, ctx.scale)
        c = float(sB.origin @ nB) - float((base + pa) @ nB)
        return clip_to_line(ctx, e, region, g, c)


@register
class AlignedWith(Coplanar):
    """Flush with: coplanar surfaces, normals parallel."""

    names = ("ALIGNED_WITH",)


@register
class OppositeTo(Coplanar):
    """Back to back: coplanar surfaces, normals anti-parallel."""

    names = ("OPPOSITE_TO",)
    sign = -1.0


@register
class ParallelTo(AlignmentRule):
    """Faces the same way, at any distance: the rotation only."""

    names = ("PARALLEL_TO",)


def child_surface_point(parts: list[Part], label: str, scale: float) -> np.ndarray:
    """A point of the child's surface plane ``label`` (asset frame, scaled)."""
    if len(parts) == 1:
        return parts[0].surfaces[label].origin * scale
    n = np.array(SURFACES[label])
    pts = part_points(parts)
    k = int(np.argmax(pts @ n))
    c = pts.mean(axis=0)
    c = c + n * (pts[k] @ n - c @ n)
    return c * scale
