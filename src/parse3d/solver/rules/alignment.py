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
the pose, and recorded relaxed with the height difference (:func:`level_plan`). Likewise a
surface parallel to the wall the child is ``AGAINST`` (a counter's front in line with a
stove's, both backs against the wall): a depth, met by the instance."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from shapely.geometry.base import BaseGeometry

from ...assets.model import Asset, Part
from ...geometry import regions as RG
from ...measure.checks import DIST_TOL
from ...pag.model import Edge, ObjectNode
from ...relations import PART, SURFACES
from ..config import Fail, SolverConfig
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
           "Level", "level_edges", "child_height", "level_miss", "level_scale", "level_plan"]


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
        if _along(region, g):
            return region  # a depth from the wall another contact holds it on (level_plan)
        nB = sB.normal
        label = e.child.surface or e.spec.child_surface
        pa = ctx.R @ child_surface_point(parts, label, ctx.scale)
        c = float(sB.origin @ nB) - float((base + pa) @ nB)
        if e.parent.object == ctx.sup.owner:
            region = _to_edge(region, g, c)
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


#: How far past the free positions a surface flush with its own support's side may take the
#: child: the margin objects keep from an object support's edge (``SolverConfig.margin``).
EDGE_SLACK = SolverConfig.margin + 1e-4


def _to_edge(region: BaseGeometry, g: np.ndarray, c: float) -> BaseGeometry:
    """``region`` grown to reach the line ``g . x = c`` when it misses it by no more than
    :data:`EDGE_SLACK`: a child flush with the side of the top it stands on (a keyboard's front
    with the desk's) stands at the edge, not the margin kept from it."""
    nrm = float(np.linalg.norm(g))
    ln = RG.line(np.zeros(2), g / nrm, c / nrm)
    if region.is_empty or not RG.clip(region, ln).is_empty:
        return region
    d = float(region.distance(ln))
    return region.buffer(d + 1e-6, join_style="mitre") if d <= EDGE_SLACK else region


def _along(region: BaseGeometry, g: np.ndarray) -> bool:
    """Whether ``region`` is already a line (another contact clipped it) parallel to the line
    of normal ``g`` (plane coordinates): the two would meet nowhere or everywhere."""
    if region.geom_type not in ("LineString", "MultiLineString"):
        return False
    line = region if region.geom_type == "LineString" else region.geoms[0]
    xy = np.asarray(line.coords, float)
    d = xy[-1] - xy[0]
    nd = float(np.linalg.norm(d))
    return nd > 1e-9 and abs(float(d @ g)) < 1e-3 * nd * float(np.linalg.norm(g))


def _parallel(n_s: np.ndarray, nB: np.ndarray) -> bool:
    """Whether a parent surface normal ``nB`` is parallel to the support normal ``n_s``
    (within 0.06 deg): no position on the support moves the child's surface toward it."""
    n_s = np.asarray(n_s, float)
    nB = np.asarray(nB, float)
    return float(np.linalg.norm(nB - (nB @ n_s) * n_s)) < 1e-3


@dataclass(frozen=True)
class Level:
    """A level relation of one object: its named surface must come to ``target`` metres from
    ``plane`` along the plane's normal, measured from the child's contact with that plane (its
    extreme point along ``contact``, asset frame); ``on_support``: the plane is the child's
    support (a height, which the scale may meet), else the parent of an ``AGAINST`` of the
    child (a depth from a wall: fronts in line, backs against it)."""

    index: int
    edge: Edge
    target: float
    contact: np.ndarray
    on_support: bool
    plane: str
    vertical: bool


def level_edges(st: SolveState, edges: list[Edge], leave=frozenset()) -> list[Level]:
    """The level relations among one object's ``edges`` (``pag.edges_of``: the support
    first) but the indices in ``leave``: each :data:`LEVEL_RELATIONS` edge whose parent
    surface is parallel to the child's support, or to the parent surface of one of its
    ``AGAINST`` edges (the two lines would be parallel: ``counter:body@front`` in line with a
    stove's front while both backs are against the wall)."""
    planes = []  # (surface, child contact normal, gap, on support, name)
    sup = support_plane(st, edges[0])
    if sup is not None:
        planes.append((sup, edges[0].child.surface or edges[0].spec.child_surface, 0.0, True,
                       edges[0].parent.object))
    for j, f in enumerate(edges[1:], 1):
        if j in leave or f.relation != "AGAINST":
            continue
        try:
            P = parent_surface_world(st, f.parent, f.spec.parent_surface)[0]
        except Fail:
            continue
        planes.append((P, f.child.surface or f.spec.child_surface, float(f.param("gap")), False,
                       f.parent.object))
    out = []
    for i, e in enumerate(edges[1:], 1):
        if i in leave or e.relation not in LEVEL_RELATIONS:
            continue
        try:
            sB = parent_surface_world(st, e.parent, e.spec.parent_surface)[0]
        except Fail:
            continue
        for P, label, gap, on_sup, name in planes:
            if _parallel(P.normal, sB.normal):
                out.append(Level(i, e, float((sB.origin - P.origin) @ P.normal) - gap,
                                 np.array(SURFACES[label], float), on_sup, name,
                                 abs(float(P.normal[2])) > 0.9))
                break
    return out


def child_height(asset: Asset, lv: Level) -> float | None:
    """Distance (m, unscaled) of the surface ``lv`` names on the child from the child's
    contact with the level's plane (its extreme point along ``lv.contact``, asset frame);
    None when the named part is missing or its surface is not parallel to that contact."""
    e = lv.edge
    label = e.child.surface or e.spec.child_surface
    if abs(abs(float(np.array(SURFACES[label], float) @ lv.contact)) - 1.0) > 1e-6:
        return None
    parts = parts_for(asset, e.child)
    if not parts:
        return None
    pa = child_surface_point(parts, label, 1.0)
    return float(np.max(part_points(asset.parts) @ lv.contact)) - float(pa @ lv.contact)


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
    """``scale`` changed so that the first level relation on the child's support (a height),
    else the first one from a wall (a depth), brings its named child surface to its parent's,
    or as near as the scales :func:`_scale_bounds` allows; ``scale`` when the object has
    none."""
    for lv in sorted(level_edges(st, edges, leave), key=lambda x: not x.on_support):
        h = child_height(asset, lv)
        if h is not None and h > 1e-6:
            a, b = _scale_bounds(node, asset, scale)
            return float(np.clip(lv.target / h, a, b))
    return scale


def level_miss(st: SolveState, node: ObjectNode, edges: list[Edge], leave=frozenset()):
    """A key ranking instances by how far (m) their named surfaces stay from their parents'
    heights (or depths) at the scale :func:`level_scale` gives them (inf: the part is
    missing), or None when the object has no level relation."""
    lv = level_edges(st, edges, leave)
    if not lv:
        return None

    def key(asset: Asset) -> float:
        lo, hi = asset.size_range
        size = max(asset_geometry(asset).size, 1e-6)
        s = level_scale(st, node, asset, float(np.clip(1.0, lo / size, hi / size)), edges, leave)
        miss = 0.0
        for x in lv:
            h = child_height(asset, x)
            miss = max(miss, float("inf") if h is None else abs(x.target - s * h))
        return miss

    return key


def level_plan(st: SolveState, asset: Asset, scale: float, edges: list[Edge],
               leave=frozenset()) -> dict[int, tuple[Edge, str]]:
    """For one object's ``edges`` but ``leave``, the level relations that ``asset`` at
    ``scale`` does not bring within half the checks' distance tolerance of their parents'
    heights (or depths): index -> (the edge placed instead: the same, not rejecting a pose;
    why, recorded as the relation's relaxation, naming the difference)."""
    out = {}
    for lv in level_edges(st, edges, leave):
        h = child_height(asset, lv)
        if h is None:
            continue
        d = lv.target - scale * h
        if abs(d) <= DIST_TOL / 2:
            continue
        e = lv.edge
        label = e.child.surface or e.spec.child_surface
        if lv.vertical:
            where = f"stands {abs(d) * 1000:.0f} mm {'below' if d > 0 else 'above'} that of"
        else:
            where = (f"lies {abs(d) * 1000:.0f} mm {'nearer' if d > 0 else 'further from'} "
                     f"{lv.plane} than that of")
        node = st.pag.objects[e.child.object]
        written = "" if node.scale is None else \
            f", its scale {node.scale[0]:g}-{node.scale[1]:g} as written"
        out[lv.index] = (measured_after(e), (
            f"{e.relation} {e.child} -> {e.parent}: the {label} of {e.child.object} {where} "
            f"{e.parent.object} (asset {asset.asset_id} at scale {scale:.3f}{written}; no "
            f"instance looked at comes in line within {LEVEL_SCALE:.0%} of its size) (write "
            f"a scale range on {e.child.object} that reaches it, or PARALLEL_TO)"))
    return out
