"""Whether an object has an inside with room for a child written ``IN`` it.

An asset's internal surfaces (``assets/internal.py``) are found geometrically, and some hold
nothing: the tape sewn round a mattress leaves a ledge a few millimetres wide that reads as an
inside, with the mattress standing in it. :func:`open_inside` asks whether some inside has
room for the child: one patch, or the narrow patches at one level together (a wine rack's
cradle bars), less what of the asset's own pieces stands in the slab the child would fill.
When none has, ``IN`` the whole object means on its largest free top (a folded blanket in a
crib lies on its mattress): :func:`child_extents` gives the child's side, the solver places it
there and the check measures it there.
"""

from __future__ import annotations

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon
from shapely.ops import unary_union

from ..geometry import regions as RG

__all__ = ["INSIDE_SHARE", "LEVEL_TOL", "ROOM", "child_extents", "no_room", "no_room_inside", "open_inside"]

#: Share of the child's narrower side an inside must be wide (a blanket may drape over a
#: drawer's sides, never over a 4 mm ledge).
INSIDE_SHARE = 0.5
#: Metres: an inside this wide holds anything written in it (a vase's floor, a drawer's).
ROOM = 0.03
#: Metres: outlines are snapped to this grid before they are subtracted.
GRID = 1e-6
#: Metres within which internal patches lie at one level (spanned together).
LEVEL_TOL = 0.005


def child_extents(asset, scale: float) -> tuple[float, float, float]:
    """``(w, d, h)``: the child's footprint sides as modelled (``w <= d``) and its height, m."""
    from .geometry import asset_geometry

    lo, hi = asset_geometry(asset).bounds * scale
    w, d = sorted(float(x) for x in (hi - lo)[:2])
    return w, d, float(hi[2] - lo[2])


def open_inside(asset, scale: float, need: float, height: float) -> bool:
    """Whether some inside of ``asset`` (drawn at ``scale``) has room for a disc ``need`` m
    across and ``height`` m high (see the module docstring)."""
    levels: dict[int, list] = {}
    for ins in asset.internal:
        s = ins.surface
        polys = list(s.polygon.geoms) if isinstance(s.polygon, MultiPolygon) else [s.polygon]
        levels.setdefault(round(float(s.origin[2]) / LEVEL_TOL), []).extend(
            (float(s.origin[2]), Polygon(s.to_3d(np.asarray(p.exterior.coords))[:, :2]).buffer(0))
            for p in polys if not p.is_empty)
    pieces = [pc.vertices for p in asset.parts for pc in p.piece_arrays]
    for group in levels.values():
        z = min(g[0] for g in group)
        hulls = [RG.convex_footprint(v[:, :2]) for v in pieces
                 if v[:, 2].max() > z + 2e-3 and v[:, 2].min() < z + height / scale]
        standing = unary_union([Polygon(h).buffer(0) for h in hulls if len(h) >= 3])
        regions = [p for _, p in group] + [unary_union([p for _, p in group]).convex_hull]
        for region in regions:
            try:
                left = shapely.set_precision(region, GRID).difference(
                    shapely.set_precision(standing, GRID))
            except shapely.errors.GEOSException:
                return True  # a degenerate outline: keep the inside as written
            if not left.buffer(-need / scale / 2).is_empty:
                return True
    return False


def no_room(parent_asset, parent_scale: float, child_asset, child_scale: float) -> bool:
    """Whether ``IN`` the whole parent means on its top for the child: the parent has insides
    (so it is drawn as one that holds things) and none takes a disc the smaller of
    :data:`INSIDE_SHARE` of the child's narrower side and :data:`ROOM` across, as high as the
    child (a strawberry in a wine glass's bowl keeps its inside)."""
    if parent_asset is None or child_asset is None or not parent_asset.internal:
        return False
    w, _, h = child_extents(child_asset, child_scale)
    return not open_inside(parent_asset, parent_scale, min(w * INSIDE_SHARE, ROOM), h)


def no_room_inside(parent, child) -> bool:
    """:func:`no_room` for a placed ``parent`` and ``child``."""
    return no_room(parent.asset, parent.scale, child.asset, child.scale)
