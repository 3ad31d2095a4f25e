"""The support relations (``ON``, ``IN``, ``HANGING_BELOW``, ``SECURED_TO``): each object has
exactly one. They turn the child's contact surface against the support (``R0``, set by
:func:`parse3d.solver.rotation.solve_rotation`) and clip nothing themselves: the support
surface is the region. ``HANGING_BELOW`` hangs its child ``drop`` below the parent;
``SECURED_TO`` keeps its centre in a height band."""

from __future__ import annotations

import numpy as np
import shapely
from shapely.geometry.base import BaseGeometry

from ...assets.model import Asset
from ...geometry import regions as RG
from ...geometry.memo import per_object
from ...pag.model import PAG, Edge
from ...pag.refs import Ref
from ...relations import SUPPORT, SURFACES
from ..config import Fail
from ..geometry import asset_geometry, hull_extents, rect_sides
from ..state import SolveState
from ..support import Support, support_candidates
from .base import RegionContext, RelationRule, register

__all__ = ["SupportRule", "On", "In", "HangingBelow", "SecuredTo", "height_band", "may_fit"]


class SupportRule(RelationRule):
    """A support relation: its surfaces are the parent's (:func:`support_candidates`), tried
    in random order when the edge names no surface, else in theirs; a ``wall`` (any wall)
    in random order."""

    family = "support"
    kind = SUPPORT
    contact = True

    def surfaces(self, st: SolveState, edge: Edge) -> list[Support]:
        return support_candidates(st, edge)

    def order(self, sups: list[Support], edge: Edge, asset: Asset, scale: float,
              rng: np.random.Generator) -> np.ndarray:
        """Indices into ``sups`` in the order they are tried for the child ``asset`` at
        ``scale``."""
        order = rng.permutation(len(sups)) if len(sups) > 1 and edge.parent.surface is None \
            else np.arange(len(sups))
        if edge.parent.object == "wall":
            order = rng.permutation(len(sups))
        return order


@register
class On(SupportRule):
    """Rests on the parent part's upward surface (or the floor)."""

    names = ("ON",)

    def needs(self, pag: PAG, oid: str, e: Edge, text: str) -> list[tuple]:
        # the parent of a child of its own category is the base of a stack: it must not roll
        if e.parent.object == oid and e.child.object != oid and set(
                pag.objects[e.child.object].candidates) & set(pag.objects[oid].candidates):
            return [(e.parent.part, e.parent.index, text, "stack_base")]
        return []

    def part_needs(self, e: Edge, ref: Ref, role: str, text: str) -> list[tuple]:
        # a parent part's top is flat, with room on it
        if role == "parent" and ref.surface in (None, "top"):
            return [(ref.part, ref.index, text, "free_top")]
        return []

    def order(self, sups: list[Support], edge: Edge, asset: Asset, scale: float,
              rng: np.random.Generator) -> np.ndarray:
        """In their order (the highest first), but those the child's footprint cannot fit in
        any turn after the others: a bag on a bench's seat before its buttons, a cushion on
        a rug's field before its border strips (they stay, for a child that must overhang)."""
        order = np.arange(len(sups))
        if len(sups) > 1:
            label = edge.child.surface or edge.spec.child_surface
            axis = int(np.argmax(np.abs(SURFACES[label])))  # the asset axis it stands along
            ext = sorted(scale * float(x) for k, x in enumerate(hull_extents(asset)[0])
                         if k != axis)
            order = np.array(sorted(range(len(sups)), key=lambda i: not may_fit(sups[i], ext)))
        if edge.parent.object == "wall":
            order = rng.permutation(len(sups))
        return order


@register
class In(SupportRule):
    """Rests on one of the parent's internal support surfaces, within its free height."""

    names = ("IN",)
    internal = True

    def needs(self, pag: PAG, oid: str, e: Edge, text: str) -> list[tuple]:
        if e.parent.object == oid and e.parent.part is None:
            return [(None, None, text, "internal")]  # IN the whole object: any inside
        return []

    def part_needs(self, e: Edge, ref: Ref, role: str, text: str) -> list[tuple]:
        # a parent part holds an internal support surface
        return [(ref.part, ref.index, text, "internal")] if role == "parent" else []

    def order(self, sups: list[Support], edge: Edge, asset: Asset, scale: float,
              rng: np.random.Generator) -> np.ndarray:
        """In random order, across a cradle's bars (a spanning support) before on one."""
        order = super().order(sups, edge, asset, scale, rng)
        if edge.parent.object != "wall" and len(sups) > 1:
            order = rng.permutation(len(sups))
        if edge.parent.object == "wall" or len(sups) > 1:
            order = np.array(sorted(order, key=lambda i: not sups[int(i)].spans))
        return order


@register
class HangingBelow(SupportRule):
    """Hangs below the parent's downward surface (or the ceiling), ``drop`` below it."""

    names = ("HANGING_BELOW",)
    fixed = True
    hangs = True

    def offset(self, edge: Edge, rng: np.random.Generator) -> float:
        lo, hi = edge.param("drop")
        return rng.uniform(lo, hi)


@register
class SecuredTo(SupportRule):
    """Fixed to a wall or an object's surface, its centre within ``height`` of the floor."""

    names = ("SECURED_TO",)
    fixed = True
    banded = True

    def band(self, ctx: RegionContext, edge: Edge, region: BaseGeometry) -> BaseGeometry:
        return height_band(ctx, edge, region)


def may_fit(sup: Support, ext: list[float]) -> bool:
    """Whether a footprint of sides ``ext`` (short, long) may fit the support's region in
    some turn: not longer or wider than the sides of the region's oriented envelope."""
    short, long = _region_sides(sup.region)
    return ext[0] <= short + 1e-9 and ext[1] <= long + 1e-9


@per_object()
def _region_sides(region) -> tuple[float, float]:
    """:func:`rect_sides` of a support region, kept per region object."""
    return rect_sides(region)


def height_band(ctx: RegionContext, edge: Edge, region: BaseGeometry) -> BaseGeometry:
    """SECURED_TO: clip origin positions on a vertical support to the centre-height range."""
    lo, hi = edge.param("height")
    s = ctx.sup.surface
    vz = float(s.v[2])
    if abs(vz) < 0.5:
        return region
    c_off = float(((asset_geometry(ctx.asset).center * ctx.scale) @ ctx.R.T)[2])
    v_lo = (lo - c_off - s.origin[2]) / vz
    v_hi = (hi - c_off - s.origin[2]) / vz
    out = RG.clip(region, shapely.box(-1e3, min(v_lo, v_hi), 1e3, max(v_lo, v_hi)))
    if out.is_empty:
        half = float(np.ptp((asset_geometry(ctx.asset).hull * ctx.scale) @ ctx.R.T[:, 2])) / 2
        if hi < half - 1e-3:  # the geometry, not the room, rules it out
            raise Fail(f"SECURED_TO height {lo}-{hi} m: {ctx.oid} is {2 * half:.2f} m tall, so "
                       f"its centre is at least {half:.2f} m above the floor (height is the "
                       f"centre's, not the bottom's)", intrinsic=True)
        raise Fail(f"SECURED_TO height {lo}-{hi} m: no free space at that height on {ctx.sup.name}")
    return out
