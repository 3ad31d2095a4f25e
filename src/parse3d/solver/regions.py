"""Stages 4 and 5 of Algorithm 1: the feasible region of the child's origin in the support
plane.

Obstacles (placed footprints in the slab above the support) are removed by an exact Minkowski
erosion; then one rule per relation family, registered by name in :data:`REGION_RULES`, clips
the region: object-level relations by half-planes, strips and discs (phase ``object``),
part-level contacts by lines (phase ``part``). A rule that empties the region fails the object
with a message naming the geometry that blocked it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry.base import BaseGeometry

from ..assets.model import Asset, Part
from ..geometry import regions as RG
from ..geometry.hulls import hull_indices_2d
from ..measure.checks import EPS, object_centroid
from ..pag.model import Edge
from ..relations import SURFACES
from .config import Fail
from .geometry import asset_geometry, outline_indices, part_points
from .rotation import parent_surface_world
from .state import SolveState, frame_key, parts_for, plane_coords, plane_key
from .support import Support

__all__ = ["REGION_RULES", "RegionContext", "obstacles", "apply_region_rules", "height_band",
           "parent_frame", "polygonal", "side_vector"]

_SIDE_DIRS = {"front": (0.0, 1.0, 0.0), "back": (0.0, -1.0, 0.0),
              "right": (1.0, 0.0, 0.0), "left": (-1.0, 0.0, 0.0)}


@dataclass
class RegionContext:
    """The posed child a region is built for.

    Attributes
    ----------
    st : SolveState
    oid : str
    asset : Asset
    scale : float
    R : (3, 3) float
        The child's rotation.
    h : float
        Height of the child's origin above the support plane (m).
    sup : Support
    off : (2,) float
        The child's bbox centre relative to its origin, in plane coordinates.
    off3 : (3,) float
        The same offset in the world, height above the plane included.
    """

    st: SolveState
    oid: str
    asset: Asset
    scale: float
    R: np.ndarray
    h: float
    sup: Support
    off: np.ndarray
    off3: np.ndarray


RegionRule = Callable[[RegionContext, Edge, BaseGeometry], BaseGeometry]
#: One rule per relation name: ``(phase, rule)`` with phase ``object``, ``part`` or ``none``.
REGION_RULES: dict[str, tuple[str, RegionRule]] = {}


def region_rule(phase: str, *names: str):
    def deco(fn: RegionRule) -> RegionRule:
        for n in names:
            REGION_RULES[n] = (phase, fn)
        return fn
    return deco


def apply_region_rules(ctx: RegionContext, edges: list[Edge], region: BaseGeometry,
                       phase: str) -> BaseGeometry:
    """Clip ``region`` by the rules of ``phase`` for each edge, in edge order."""
    for e in edges:
        ph, rule = REGION_RULES[e.relation]
        if ph == phase:
            region = rule(ctx, e, polygonal(region) if phase == "object" else region)
    return region


def polygonal(region: BaseGeometry) -> BaseGeometry:
    """The areal part of a region (erosion can leave slivers as lines in a collection)."""
    if region.geom_type != "GeometryCollection":
        return region
    polys = [g for g in region.geoms if g.geom_type in ("Polygon", "MultiPolygon")]
    return shapely.union_all(polys) if polys else shapely.Polygon()


@region_rule("none", "ON", "IN", "HANGING_BELOW", "SECURED_TO", "PARALLEL_TO")
def _no_region(ctx, e, region):
    """Support relations are the support itself (SECURED_TO's height band is applied with the
    support); PARALLEL_TO constrains the rotation only."""
    return region


#: Share of TOWARD's tolerance within which a child is squared to its target's side.
SQUARE_SHARE = 0.8
#: TOWARD tolerance (degrees) from which positions are restricted to where squaring is possible.
SQUARE_MIN_TOLERANCE = 25.0
_FIXING = ("AGAINST", "OPPOSITE_TO", "ALIGNED_WITH", "PARALLEL_TO", "LEANING_AGAINST")


@region_rule("object", "TOWARD")
def _toward(ctx, e, region):
    """With a ``tolerance_deg`` of at least ``SQUARE_MIN_TOLERANCE``, prefer positions from which
    the child, squared to the nearest side of its target, still faces the target's centroid
    within ``SQUARE_SHARE`` of the tolerance: four cones about the target's side normals. Where none is free, the whole region stays (the child then faces
    the centroid exactly). A child whose angle is fixed otherwise, or that asks for a free
    yaw, is not constrained."""
    st, s = ctx.st, ctx.sup.surface
    if st.pag.objects[ctx.oid].extra.get("yaw") == "free" or abs(float(s.normal[2])) < 0.9 \
            or any(x.relation in _FIXING for x in st.pag.edges_of(ctx.oid)):
        return region
    if e.param("tolerance_deg") < SQUARE_MIN_TOLERANCE:
        return region  # cones this narrow would crowd the chairs at the sides' centres
    xB, frame, hull = parent_frame(st, e.parent.object)
    if hull is None:
        return region
    cB = plane_coords(s, xB[None])[0] - ctx.off
    half = SQUARE_SHARE * np.deg2rad(e.param("tolerance_deg"))
    cones = []
    for ax in (frame[:, 0], -frame[:, 0], frame[:, 1], -frame[:, 1]):
        g = np.array([ax @ s.u, ax @ s.v])
        if np.linalg.norm(g) < 1e-6:
            continue
        a = float(np.arctan2(g[1], g[0]))
        far = 50.0
        cones.append(shapely.Polygon([tuple(cB), tuple(cB + far * np.array([np.cos(a - half), np.sin(a - half)])),
                                      tuple(cB + far * np.array([np.cos(a + half), np.sin(a + half)]))]))
    new = RG.clip(region, shapely.union_all(cones)) if cones else region
    return region if new.is_empty or new.area < 1e-10 else new


def parent_frame(st: SolveState, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """Centroid, rotation frame (columns: right, front, up) and hull points of a parent."""
    if name in st.scene.room.elements:
        s = st.scene.room.elements[name].surface
        front = s.normal
        up = np.array([0, 0, 1.0]) if abs(front[2]) < 0.9 else np.array([0, 1.0, 0])
        right = np.cross(front, up)
        return s.origin.copy(), np.c_[right, front, up], None
    o = st.scene.objects[name]
    if not o.placed:
        raise Fail(f"parent {name!r} was not placed")
    return object_centroid(o), o.rotation, st.hulls[name]


def _emptied(e: Edge, sup: Support, why: str = "") -> Fail:
    side = f" side {e.param('side')}" if e.relation in ("SIDE_OF", "ALONG") else ""
    return Fail(f"{e.relation} {e.child} -> {e.parent}{side} emptied the feasible region on "
                f"{sup.name}{': ' + why if why else ''}")


def _free_room_text(region: BaseGeometry) -> str:
    if region.is_empty:
        return "no free space was left there"
    b = region.bounds
    return f"the free positions span {b[2] - b[0]:.2f} x {b[3] - b[1]:.2f} m elsewhere"


@region_rule("object", "NEAR", "FAR_FROM")
def _distance(ctx, e, region):
    """A disc (NEAR) or its complement (FAR_FROM) of radius ``distance`` about the parent's
    centroid, horizontally; to a wall, a strip by the distance to its plane."""
    st, s, rel = ctx.st, ctx.sup.surface, e.relation
    xB, frame, hull = parent_frame(st, e.parent.object)
    cB = plane_coords(s, xB[None])[0] - ctx.off
    dist = e.param("distance")
    vertical = abs(float(s.normal[2])) < 0.5 and abs(float(s.v[2])) > 0.99
    if vertical:
        # on a wall the plane's v axis is vertical: the horizontal distance (or the distance
        # to a wall's plane) depends on the position a along the wall only
        c = s.origin + ctx.off3 - xB
        uh = s.u
        if hull is None:  # parent is a wall: distance to its plane, linear in a
            nB = frame[:, 1]
            k, c0 = float(uh @ nB), float(c @ nB)
            lo, hi = (-dist, dist) if rel == "NEAR" else (dist, 1e3)
            if abs(k) < 1e-9:
                ok = (abs(c0) <= dist) if rel == "NEAR" else (abs(c0) >= dist)
                clip = RG.bounding_square(region) if ok else shapely.Polygon()
            else:
                a1, a2 = sorted(((lo - c0) / k, (hi - c0) / k))
                clip = shapely.box(a1, -1e3, a2, 1e3)
                if rel == "FAR_FROM":
                    b1, b2 = sorted(((-hi - c0) / k, (-lo - c0) / k))
                    clip = clip.union(shapely.box(b1, -1e3, b2, 1e3))
        else:  # |c_xy + a u_xy| <= d: an interval of a
            cxy, uxy = c[:2], uh[:2]
            A = float(uxy @ uxy)
            B = 2 * float(cxy @ uxy)
            C = float(cxy @ cxy) - dist ** 2
            disc = B * B - 4 * A * C
            if A < 1e-9 or disc < 0:
                clip = shapely.Polygon() if rel == "NEAR" else RG.bounding_square(region)
            else:
                a1 = (-B - np.sqrt(disc)) / (2 * A)
                a2 = (-B + np.sqrt(disc)) / (2 * A)
                near = shapely.box(a1, -1e3, a2, 1e3)
                clip = near if rel == "NEAR" else RG.bounding_square(region).difference(near)
    elif hull is None:  # a wall: distance to its plane
        nw = frame[:, 1]
        g = np.array([nw @ s.u, nw @ s.v])
        g /= max(np.linalg.norm(g), 1e-9)
        clip = RG.strip(cB, g, -1e-3, dist) if rel == "NEAR" else RG.strip(cB, g, dist, 1e3)
    else:
        d = RG.disk(cB, dist, 48)
        clip = d if rel == "NEAR" else RG.bounding_square(region).difference(d)
    new = RG.clip(region, clip)
    if new.is_empty or new.area < 1e-10:
        raise _emptied(e, ctx.sup, f"nothing within {dist:g} m of {e.parent.object} is free "
                       f"({_free_room_text(region)})" if rel == "NEAR" else
                       f"nothing {dist:g} m or more from {e.parent.object} is free")
    return new


def side_vector(st: SolveState, e, R: np.ndarray) -> np.ndarray:
    """World direction of a ``SIDE_OF`` / ``ALONG`` edge's ``side``: in the parent's frame
    (rotation ``R``), or with ``frame: camera`` as the PAG's viewpoint sees it."""
    if e.param("frame") == "camera":  # the side as the photograph shows it
        return np.array(st.pag.viewpoint.side_direction(st.pag.room, e.param("side")))
    return R @ np.array(_SIDE_DIRS[e.param("side")])


@region_rule("object", "SIDE_OF", "ALONG")
def _side(ctx, e, region):
    """SIDE_OF: the half-plane beyond the parent's centroid on ``side`` (parent frame, or the
    camera's with ``frame: camera``).
    ALONG: the strip beside the parent's ``side`` face, from the face outwards up to ``width``,
    within the parent's extent along that face (as :mod:`parse3d.measure` checks it)."""
    st, s, rel = ctx.st, ctx.sup.surface, e.relation
    xB, frame, hull = parent_frame(st, e.parent.object)
    cB = plane_coords(s, xB[None])[0] - ctx.off
    side = e.param("side")
    nw = side_vector(st, e, frame)
    g = np.array([nw @ s.u, nw @ s.v])
    if np.linalg.norm(g) < 1e-6:
        # the side is across the support (a mirror on the wall behind a vanity, SIDE_OF its
        # back): measured in 3-D, as the check does, every position on the support is on the
        # same side of the parent's centroid
        d = float((np.asarray(s.origin, float) - xB) @ nw)
        if rel == "SIDE_OF" and d > 0:
            return region
        raise Fail(f"{rel} side {side!r} of {e.parent.object!r} is across {ctx.sup.name}"
                   + (f", which lies {-d:.2f} m on the other side of its centroid"
                      if rel == "SIDE_OF" else ": no strip beside that face lies on it"))
    g /= np.linalg.norm(g)
    if rel == "SIDE_OF":
        clip = RG.half_plane(cB, g)
    else:
        hB = 0.0 if hull is None else float(np.max(plane_coords(s, hull) @ g - (cB + ctx.off) @ g))
        clip = RG.strip(cB, g, max(hB, 0.0), max(hB, 0.0) + e.param("width"))
        if hull is not None:  # within the parent's extent along the face
            gp = np.array([g[1], -g[0]])
            along = plane_coords(s, hull) @ gp - (cB + ctx.off) @ gp
            clip = RG.clip(clip, RG.strip(cB, gp, float(along.min()), float(along.max())))
    new = RG.clip(region, clip)
    if new.is_empty or new.area < 1e-10:
        raise _emptied(e, ctx.sup, f"the {side} of {e.parent.object} is taken or outside "
                       f"{ctx.sup.name}")
    return new


@region_rule("part", "AGAINST", "ALIGNED_WITH", "OPPOSITE_TO", "LEANING_AGAINST")
def _contact_line(ctx, e, region):
    """The line of origins where the named child part touches the parent surface: AGAINST at
    ``gap``, ALIGNED_WITH / OPPOSITE_TO with coplanar surfaces, LEANING_AGAINST where the tilted
    child's named part (or, naming none, its extreme point) touches."""
    st, s, rel = ctx.st, ctx.sup.surface, e.relation
    if rel == "LEANING_AGAINST":  # within the parent face's extent (solver/leaning.py)
        from .leaning import lean_line
        got = lean_line(ctx, e, region)
        if got is not None:
            return got
    asset, scale, R, sup = ctx.asset, ctx.scale, ctx.R, ctx.sup
    sB, _, _ = parent_surface_world(st, e.parent, e.spec.parent_surface)
    nB = sB.normal
    g = np.array([s.u @ nB, s.v @ nB])
    if np.linalg.norm(g) < 1e-6:
        raise Fail(f"{rel} {e.child} -> {e.parent}: the parent surface is parallel to the "
                   f"support, no position satisfies it")
    parts = parts_for(asset, e.child)
    if not parts:
        raise Fail(f"{e.child.object!r} has no part {e.child.part!r}")
    pts = (part_points(parts) * scale) @ R.T
    base = s.origin + ctx.h * s.normal
    if rel == "LEANING_AGAINST":
        src = pts if e.child.part is not None else (asset_geometry(asset).hull * scale) @ R.T
        reach = float(np.max(src @ (-nB)))
        target = float(sB.origin @ (-nB)) - EPS
        c = target - float(base @ (-nB)) - reach
        gg = -g
    else:
        label = e.child.surface or e.spec.child_surface
        if rel == "AGAINST":
            # contact: the named part's extreme point along its (rotated) surface normal
            nA_w = R @ np.array(SURFACES[label])
            pa = pts[int(np.argmax(pts @ nA_w))]
            gap = e.param("gap") + EPS
            _check_extreme(ctx, e, parts, nA_w, label)
        else:
            pa = R @ _child_surface_point(parts, label, scale)
            gap = 0.0
        c = float(sB.origin @ nB) + gap - float((base + pa) @ nB)
        gg = g
    nrm = np.linalg.norm(gg)
    ln = RG.line(np.zeros(2), gg / nrm, c / nrm)
    new = RG.clip(region, ln)
    if new.is_empty:
        raise _emptied(e, sup, f"where {e.child} touches {e.parent}, {_free_room_text(region)}")
    return new


def _check_extreme(ctx: RegionContext, e: Edge, parts: list[Part], n: np.ndarray,
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


def _child_surface_point(parts: list[Part], label: str, scale: float) -> np.ndarray:
    """A point of the child's surface plane ``label`` (asset frame, scaled)."""
    if len(parts) == 1:
        return parts[0].surfaces[label].origin * scale
    n = np.array(SURFACES[label])
    pts = part_points(parts)
    k = int(np.argmax(pts @ n))
    c = pts.mean(axis=0)
    c = c + n * (pts[k] @ n - c @ n)
    return c * scale


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


def obstacles(st: SolveState, sup: Support, exclude: set[str], height: float,
              within: tuple[float, float, float, float] | None = None,
              step: float = 0.0, parts: bool = True) -> list[np.ndarray]:
    """Footprints (in the support plane) of placed objects in the slab above the support, and
    (with ``parts``) the other parts of the supporting objects (``exclude``) in that slab,
    except pieces of theirs rising at most ``step`` above the support (burners on a cooktop:
    the child stands on them).

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
            if hi_h <= step and steps_on(sup, fp):
                continue
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
