"""Stages 4 and 5 of Algorithm 1: the feasible region of the child's origin in the support
plane.

Obstacles (placed footprints in the slab above the support) are removed by an exact Minkowski
erosion; then each relation's rule (:mod:`parse3d.solver.rules`) clips the region:
object-level relations by half-planes, strips and discs (phase ``object``), part-level
contacts by lines (phase ``part``). A rule that empties the region fails the object with a
message naming the geometry that blocked it.
"""

from __future__ import annotations

import numpy as np
import shapely
from shapely.geometry.base import BaseGeometry

from ..assets.model import Asset
from ..geometry import regions as RG
from ..geometry.hulls import hull_indices_2d
from ..pag.model import Edge
from .geometry import outline_indices
from .rules import RULES, RegionContext
from .rules.layout import relaxed_to_nearest
from .state import SolveState, frame_key, plane_coords, plane_key
from .support import Support

__all__ = ["RegionContext", "obstacles", "apply_region_rules", "polygonal", "steps_on"]


def apply_region_rules(ctx: RegionContext, edges: list[Edge], region: BaseGeometry,
                       phase: str) -> BaseGeometry:
    """Clip ``region`` by the rules of ``phase`` for each edge, in edge order; a layout edge
    relaxed to its nearest positions (:func:`~.rules.layout.relaxed_to_nearest`) clips last,
    after the part-level contacts, so that it takes the positions nearest its region among
    those the contacts leave."""
    late = [e for e in edges if relaxed_to_nearest(e)]
    for e in edges:
        rule = RULES[e.relation]
        if rule.region_phase == phase and not any(e is x for x in late):
            region = rule.region(ctx, e, polygonal(region) if phase == "object" else region)
    for e in late if phase == "part" else ():
        region = RULES[e.relation].region(ctx, e, region)
    return region


def polygonal(region: BaseGeometry) -> BaseGeometry:
    """The areal part of a region (erosion can leave slivers as lines in a collection)."""
    if region.geom_type != "GeometryCollection":
        return region
    polys = [g for g in region.geoms if g.geom_type in ("Polygon", "MultiPolygon")]
    return shapely.union_all(polys) if polys else shapely.Polygon()


def obstacles(st: SolveState, sup: Support, exclude: set[str], height: float,
              within: tuple[float, float, float, float] | None = None,
              step: float = 0.0, parts: bool = True, across: bool = False) -> list[np.ndarray]:
    """Footprints (in the support plane) of placed objects in the slab above the support, and
    (with ``parts``) the other parts of the supporting objects (``exclude``) in that slab,
    except pieces of theirs rising at most ``step`` above the support that the child stands on
    (burners on a cooktop, :func:`steps_on`), or with ``across`` all those low pieces (a
    folded napkin longer than a plate's well lies across its rim).

    ``within`` is a box ``(a0, b0, a1, b1)`` in plane coordinates: footprints that cannot meet
    it are left out (on horizontal supports, found through the state's spatial index; a
    footprint whose bounding box meets the box is always kept, so :func:`~parse3d.geometry.
    regions.erode` given the region inside that box sees the same obstacles as without it).
    """
    out = []
    n = sup.surface.normal
    horizontal = abs(n[2]) > 0.999
    if horizontal:  # footprints precomputed in world xy; the slab test is a z-range test
        sz = float(sup.surface.origin[2])
        if within is None:
            ids = list(st.hulls)
        else:  # a conservative prefilter by the index; the exact tests follow
            s = sup.surface
            a0, b0, a1, b1 = within
            c = s.origin + (a0 + a1) / 2 * s.u + (b0 + b1) / 2 * s.v
            r = 1.01 * float(np.hypot(a1 - a0, b1 - b0)) / 2 + 0.01
            pad = 1.01 * height + 0.01
            ids = st.near(c[:2], r, sz - pad, sz + pad)
        keep = [st.xy[oid] for oid in ids if oid not in exclude
                and _in_slab(st.zr[oid], sz, float(n[2]), height)]
        if keep:
            allxy = np.vstack(keep)
            uv = plane_coords(sup.surface, np.column_stack([allxy, np.full(len(allxy), sz)]))
            out.extend(np.split(uv, np.cumsum([len(k) for k in keep])[:-1]))
    if not horizontal:  # a wall: each object's heights and footprint kept per plane frame
        fkey = ("hull", frame_key(sup.surface))
        for oid, pts in st.hulls.items():
            if oid in exclude:
                continue
            got = st.memo(oid, fkey, lambda pts=pts: _hull_heights(pts, sup.surface))
            if got[1] <= 1e-3 or got[0] >= height - 1e-3:
                continue
            if got[2] is None:  # the object's outline seen along the normal (kept per asset)
                o = st.scene.objects[oid]
                got[2] = RG.convex_outline(plane_coords(sup.surface, pts),
                                           outline_indices(o.asset, o.rotation.T @ n))
            out.append(got[2])
    # the supporting objects themselves are not whole obstacles, but their other parts are:
    # a cabinet's sides and back around its shelf, the other burners of a stove
    key = ("pieces", *plane_key(sup.surface))
    for oid in (exclude if parts else ()):
        for piece in st.memo(oid, key, lambda oid=oid: _piece_heights(st, oid, sup)):
            lo_h, hi_h, pts, fp = piece[:4]
            if hi_h <= 1e-3 or lo_h >= height - 1e-3:
                continue
            if fp is None:  # footprints are made when first needed, then kept
                fp = piece[3] = RG.convex_outline(plane_coords(sup.surface, pts), piece[4])
            if hi_h <= step and (across or steps_on(sup, fp)):
                continue  # stood on; with ``across`` all of them (a napkin across a rim)
            out.append(fp)
    return out


def _in_slab(zr: tuple[float, float], sz: float, nz: float, height: float) -> bool:
    """Whether an object spanning heights ``zr`` reaches into the slab of ``height`` above a
    horizontal plane at height ``sz`` with normal z component ``nz``."""
    a, b = (zr[0] - sz) * nz, (zr[1] - sz) * nz
    lo_h, hi_h = (a, b) if a <= b else (b, a)
    return hi_h > 1e-3 and lo_h < height - 1e-3


def steps_on(sup: Support, fp: np.ndarray) -> bool:
    """Whether a low piece of the support's owner with footprint ``fp`` (plane coordinates)
    is stood on: its middle is over the support (a burner on a cooktop); a low piece at or
    beyond the support's edge (a tray's rim around its floor, a shelf's lip) bounds it."""
    c = fp.mean(axis=0)
    return bool(sup.region.covers(shapely.Point(float(c[0]), float(c[1]))))


def _hull_heights(pts: np.ndarray, s) -> list:
    """``[lowest, highest, None]``: heights of a placed object's hull points above the plane
    of ``s``; the last slot holds their footprint in its plane once made (see
    :func:`obstacles`)."""
    h = (pts - s.origin) @ s.normal
    return [h.min(), h.max(), None]


def _piece_heights(st: SolveState, oid: str, sup: Support) -> list[list]:
    """``[lowest, highest, points, None, outline]`` for each convex piece of a placed object:
    heights above the support plane, world points, a slot for the piece's footprint in the
    plane once made (see :func:`obstacles`) and the indices of its vertices there."""
    s = sup.surface
    o = st.scene.objects[oid]
    d = o.rotation.T @ s.normal  # the normal in the asset's frame
    out = []
    for k, (_, pts) in enumerate(st.world_pieces(oid)):
        h = (pts - s.origin) @ s.normal
        out.append([float(h.min()), float(h.max()), pts, None, _piece_outline(o.asset, k, d)])
    return out


#: Hull indices of a convex piece's vertices seen along a direction (asset frame), per
#: ``(asset id, piece, direction rounded to 1e-9)``.
_PIECE_OUTLINES: dict[tuple, np.ndarray | None] = {}


def _piece_outline(asset: Asset, k: int, d: np.ndarray) -> np.ndarray | None:
    """Indices into the ``k``-th convex piece's vertices (in :meth:`SolveState.world_pieces`
    order) of its outline seen along ``d`` (asset frame): any pose's footprint of the piece in
    a plane of that normal has its vertices there (as :func:`outline_indices` for a whole
    asset), so a footprint costs a gather instead of a hull. None when degenerate."""
    key = (asset.asset_id, k, *np.asarray(d, float).round(9).tolist())
    if key not in _PIECE_OUTLINES:
        if len(_PIECE_OUTLINES) > 65536:
            _PIECE_OUTLINES.clear()
        v = [pc.vertices for p in asset.parts for pc in p.piece_arrays][k]
        d = np.asarray(d, float) / np.linalg.norm(d)
        a = np.cross(d, [1.0, 0, 0] if abs(d[0]) < 0.9 else [0, 1.0, 0])
        a /= np.linalg.norm(a)
        _PIECE_OUTLINES[key] = hull_indices_2d(np.c_[v @ a, v @ np.cross(d, a)])
    return _PIECE_OUTLINES[key]
