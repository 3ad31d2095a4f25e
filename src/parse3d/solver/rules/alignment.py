"""The alignment relations between part surfaces (``ALIGNED_WITH``, ``OPPOSITE_TO``,
``PARALLEL_TO``): they hold at any distance. All three fix the child's angle about the support
normal (its named surface parallel to the parent's, or anti-parallel for ``OPPOSITE_TO``);
``ALIGNED_WITH`` and ``OPPOSITE_TO`` also keep the line of origins where the two surfaces are
coplanar (phase ``part``).

Two surfaces parallel to the child's support (two countertops flush, ``ALIGNED_WITH
counter_b:countertop@top -> counter_a:countertop@top``) are coplanar at one height, not along
a line: no position on the support changes it. The region is left alone and the height is met
by the instance and its scale (:func:`level_miss`, :func:`level_scale`, used when the instance
is drawn); when none comes level, the relation is placed as written but not checked against
the pose, and recorded relaxed with the height difference (:func:`level_plan`)."""

from __future__ import annotations

import numpy as np
from shapely.geometry.base import BaseGeometry

from ...assets.model import Asset, Part
from ...measure.checks import DIST_TOL
from ...pag.model import Edge, ObjectNode
from ...relations import PART, SURFACES
from ..config import Fail
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

__all__ = ["AlignedWith", "OppositeTo", "ParallelTo", "LEVEL_RELATIONS", "LEVEL_SCALE",
           "level_edges", "level_miss", "level_scale", "level_plan"]


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
        sB, _, _ = parent_surface_world(ctx.st, e.parent, e.spec.parent_surface)
        if _parallel(ctx.sup.surface.normal, sB.normal):
            return region  # a height, met by the instance and its scale (level_plan)
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


#: Relations whose two surfaces, both parallel to the child's support, meet at one height.
LEVEL_RELATIONS = ("ALIGNED_WITH", "OPPOSITE_TO")
#: The most the scale of an instance may change (either way) to bring its named surface level
#: with the parent's, within its category's size range (and the node's ``scale`` when written).
LEVEL_SCALE = 0.1


def _parallel(n_s: np.ndarray, nB: np.ndarray) -> bool:
    """Whether a parent surface normal ``nB`` is parallel to the support normal ``n_s``
    (within 0.06 deg): no position on the support moves the child's surface toward it."""
    n_s = np.asarray(n_s, float)
    nB = np.asarray(nB, float)
    return float(np.linalg.norm(nB - (nB @ n_s) * n_s)) < 1e-3


def level_edges(st: SolveState, edges: list[Edge], leave=frozenset()
                ) -> list[tuple[int, Edge, float]]:
    """The level relations among one object's ``edges`` (``pag.edges_of``: the support
    first) but the indices in ``leave``: ``(index, edge, height)`` for each
    :data:`LEVEL_RELATIONS` edge whose parent surface is parallel to the child's support,
    ``height`` the parent surface's height above the support plane (m, along its normal)."""
    sup = support_plane(st, edges[0])
    if sup is None:
        return []
    out = []
    for i, e in enumerate(edges[1:], 1):
        if i in leave or e.relation not in LEVEL_RELATIONS:
            continue
        try:
            sB = parent_surface_world(st, e.parent, e.spec.parent_surface)[0]
        except Fail:
            continue
        if _parallel(sup.normal, sB.normal):
            out.append((i, e, float((sB.origin - sup.origin) @ sup.normal)))
    return out


def child_height(asset: Asset, e: Edge, support_edge: Edge) -> float | None:
    """Height (m, unscaled) of the surface ``e`` names on the child above the child's support
    contact (its extreme point along the support edge's child surface normal, asset frame);
    None when the named part is missing or its surface is not parallel to that contact."""
    n_c = np.array(SURFACES[support_edge.child.surface or support_edge.spec.child_surface], float)
    label = e.child.surface or e.spec.child_surface
    if abs(abs(float(np.array(SURFACES[label], float) @ n_c)) - 1.0) > 1e-6:
        return None
    parts = parts_for(asset, e.child)
    if not parts:
        return None
    pa = child_surface_point(parts, label, 1.0)
    return float(np.max(part_points(asset.parts) @ n_c)) - float(pa @ n_c)


def _scale_bounds(node: ObjectNode, asset: Asset, scale: float) -> tuple[float, float]:
    """The scales a level change may give ``asset`` drawn at ``scale``: within
    :data:`LEVEL_SCALE` of it, its category's size range and the node's ``scale`` range."""
    lo, hi = asset.size_range
    size = max(asset_geometry(asset).size, 1e-6)
    a, b = scale * (1 - LEVEL_SCALE), scale * (1 + LEVEL_SCALE)
    a, b = max(a, lo / size), min(b, hi / size)
    if node.scale is not None:
        base = float(np.clip(1.0, lo / size, hi / size))
        a, b = max(a, node.scale[0] * base), min(b, node.scale[1] * base)
    return (a, b) if a <= b else (scale, scale)


def level_scale(st: SolveState, node: ObjectNode, asset: Asset, scale: float,
                edges: list[Edge], leave=frozenset()) -> float:
    """``scale`` changed so that the first level relation's named child surface comes to its
    parent's height, or as near as the scales :func:`_scale_bounds` allows; ``scale`` when
    the object has no level relation."""
    for _, e, target in level_edges(st, edges, leave):
        h = child_height(asset, e, edges[0])
        if h is not None and h > 1e-6:
            a, b = _scale_bounds(node, asset, scale)
            return float(np.clip(target / h, a, b))
    return scale


def level_miss(st: SolveState, node: ObjectNode, edges: list[Edge], leave=frozenset()):
    """A key ranking instances by how far (m) their named surfaces stay from their parents'
    heights at the best scale :func:`level_scale` gives them (inf: the part is missing), or
    None when the object has no level relation."""
    lv = level_edges(st, edges, leave)
    if not lv:
        return None

    def key(asset: Asset) -> float:
        lo, hi = asset.size_range
        size = max(asset_geometry(asset).size, 1e-6)
        s = level_scale(st, node, asset, float(np.clip(1.0, lo / size, hi / size)), edges, leave)
        miss = 0.0
        for _, e, target in lv:
            h = child_height(asset, e, edges[0])
            miss = max(miss, float("inf") if h is None else abs(target - s * h))
        return miss

    return key


def level_plan(st: SolveState, asset: Asset, scale: float, edges: list[Edge],
               leave=frozenset()) -> dict[int, tuple[Edge, str]]:
    """For one object's ``edges`` but ``leave``, the level relations that ``asset`` at
    ``scale`` does not bring within half the checks' distance tolerance of their parents'
    heights: index -> (the edge placed instead: the same, not rejecting a pose; why, recorded
    as the relation's relaxation, naming the height difference)."""
    out = {}
    for i, e, target in level_edges(st, edges, leave):
        h = child_height(asset, e, edges[0])
        if h is None:
            continue
        d = target - scale * h
        if abs(d) <= DIST_TOL / 2:
            continue
        label = e.child.surface or e.spec.child_surface
        out[i] = (measured_after(e), (
            f"{e.relation} {e.child} -> {e.parent}: the {label} of {e.child.object} stands "
            f"{abs(d) * 1000:.0f} mm {'below' if d > 0 else 'above'} that of {e.parent.object} "
            f"(asset {asset.asset_id} at scale {scale:.3f}; no instance looked at comes level "
            f"within {LEVEL_SCALE:.0%} of its size) (write a scale range on {e.child.object} "
            f"that reaches it, or PARALLEL_TO)"))
    return out
