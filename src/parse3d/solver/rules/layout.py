"""The layout relations between objects (``SIDE_OF``, ``ALONG``, ``NEAR``, ``FAR_FROM``,
``TOWARD``): coarse constraints on the objects' centroids. They clip the region of the child's
origin first (phase ``object``: half-planes, strips, discs, cones) and are the first relaxed
when they cannot be met; only ``TOWARD`` turns the child (per sampled position, to face its
target)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import numpy as np
import shapely
from shapely.geometry.base import BaseGeometry

from ...assets.model import Asset
from ...geometry import regions as RG
from ...measure.geometry import side_frame
from ...pag.model import Edge
from ...relations import OBJECT
from ..config import Fail
from ..geometry import asset_geometry
from ..state import SolveState, plane_coords
from .base import (
    RULES,
    Orientation,
    RegionContext,
    RelationRule,
    emptied,
    free_room_text,
    parent_frame,
    register,
)

__all__ = ["Distance", "Side", "Toward", "side_vector", "nearest", "relaxed_to_nearest",
           "SQUARE_SHARE", "LAYOUT_MARGIN", "MARGIN_SHARE", "SIDE_MARGIN", "MARGIN_KEEP",
           "layout_margin", "with_margin", "near_depth",
           "SQUARE_MIN_TOLERANCE", "NEAREST_BAND"]

_SIDE_DIRS = {"front": (0.0, 1.0, 0.0), "back": (0.0, -1.0, 0.0),
              "right": (1.0, 0.0, 0.0), "left": (-1.0, 0.0, 0.0)}

#: Share of TOWARD's tolerance within which a child is squared to its target's side.
SQUARE_SHARE = 0.8
#: TOWARD tolerance (degrees) from which positions are restricted to where squaring is possible.
SQUARE_MIN_TOLERANCE = 25.0


class LayoutRule(RelationRule):
    family = "layout"
    kind = OBJECT
    region_phase = "object"
    relax_order = 0


@register
class Distance(LayoutRule):
    names = ("NEAR", "FAR_FROM")

    def region(self, ctx: RegionContext, e: Edge, region: BaseGeometry) -> BaseGeometry:
        """A disc (NEAR) or its complement (FAR_FROM) of radius ``distance`` about the parent's
        centroid, horizontally; to a wall, a strip by the distance to its plane."""
        st, s, rel = ctx.st, ctx.sup.surface, e.relation
        xB, frame, hull = parent_frame(st, e.parent.object)
        cB = plane_coords(s, xB[None])[0] - ctx.off
        dist = e.param("distance")
        clip = self._clip(ctx, e, region, dist, cB, frame, hull)
        new = RG.clip(region, clip)
        if new.is_empty or new.area < 1e-10:
            if relaxed_to_nearest(e):
                return closest(region, clip)
            raise emptied(e, ctx.sup, f"nothing within {dist:g} m of {e.parent.object} is free "
                           f"({free_room_text(region)})" if rel == "NEAR" else
                           f"nothing {dist:g} m or more from {e.parent.object} is free")
        # settling moves things by millimetres to centimetres: a child placed on the limit's
        # edge would not meet it afterwards, so the region keeps a margin inside the limit
        # where enough of it is free
        m = layout_margin(dist) * (1.0 if rel == "NEAR" else -1.0)
        return with_margin(new, lambda k: RG.clip(
            region, self._clip(ctx, e, region, dist - k * m, cB, frame, hull)))

    @staticmethod
    def _clip(ctx: RegionContext, e: Edge, region: BaseGeometry, dist: float, cB: np.ndarray,
              frame: np.ndarray, hull) -> BaseGeometry:
        """The positions of the child's origin (support plane coordinates) within ``dist`` of
        the parent (NEAR) or beyond it (FAR_FROM)."""
        st, s, rel = ctx.st, ctx.sup.surface, e.relation
        xB = parent_frame(st, e.parent.object)[0]
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
        return clip


@register
class Side(LayoutRule):
    names = ("SIDE_OF", "ALONG")

    def region(self, ctx: RegionContext, e: Edge, region: BaseGeometry) -> BaseGeometry:
        """SIDE_OF: the half-plane beyond the parent's centroid on ``side`` (parent frame, or the
        camera's with ``frame: camera``).
        ALONG: the strip beside the parent's ``side`` face, from the face outwards up to ``width``,
        within the parent's extent along that face (as :mod:`parse3d.measure` checks it); where
        it leaves nothing free, out to ``width`` plus the child's depth toward the face
        (:func:`near_depth`): its near face within ``width`` of the parent's, and where the
        child is the longer along the face, the face's middle within its length."""
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
            if (rel == "SIDE_OF" and d > 0) or relaxed_to_nearest(e):
                return region
            raise Fail(f"{rel} side {side!r} of {e.parent.object!r} is across {ctx.sup.name}"
                       + (f", which lies {-d:.2f} m on the other side of its centroid"
                          if rel == "SIDE_OF" else ": no strip beside that face lies on it"))
        g /= np.linalg.norm(g)
        if rel == "SIDE_OF":
            def within(m: float) -> BaseGeometry:
                return RG.half_plane(cB + m * g, g)
            # no limit but the parent's centroid: the margin scales with the child's own width
            # along the side (a record filed beside another keeps a millimetre, a chair 3 cm)
            ext = (ctx.asset.bounds[1] - ctx.asset.bounds[0]) * ctx.scale
            margin = min(SIDE_MARGIN, MARGIN_SHARE * float(np.abs(ctx.R.T @ nw) @ ext))
        else:
            hB = 0.0 if hull is None else float(np.max(plane_coords(s, hull) @ g - (cB + ctx.off) @ g))
            hB, w = max(hB, 0.0), e.param("width")
            gp = np.array([g[1], -g[0]])
            along = None if hull is None else plane_coords(s, hull) @ gp - (cB + ctx.off) @ gp
            reach, span = w, 0.0

            def within(m: float) -> BaseGeometry:
                # the strip's far edge and its ends come in by m (its near edge is the face:
                # settling does not push a child into its parent)
                strip = RG.strip(cB, g, hB, hB + reach - m)
                if along is None:
                    return strip
                lo, hi = float(along.min()), float(along.max())
                mid, half = 0.5 * (lo + hi), max(0.5 * (hi - lo), span)
                m = min(m, 0.5 * half)
                return RG.clip(strip, RG.strip(cB, gp, mid - half + m, mid + half - m))
            margin = layout_margin(w)
        clip = within(0.0)
        new = RG.clip(region, clip)
        if rel == "ALONG" and (new.is_empty or new.area < 1e-10):
            # a strip narrower than the child's own depth toward the face (a dryer 5 cm along
            # a washer): the width is the gap between the faces, the child's near face within
            # it; a child longer along the face than the parent (a bed beside a nightstand):
            # the face's middle within the child's length (as the check measures them)
            gp3 = np.array([-nw[1], nw[0], 0.0])
            reach, span = w + near_depth(ctx, nw), 0.5 * (near_depth(ctx, gp3)
                                                          + near_depth(ctx, -gp3))
            clip = within(0.0)
            new = RG.clip(region, clip)
        if new.is_empty or new.area < 1e-10:
            if relaxed_to_nearest(e):
                return closest(region, clip)
            raise emptied(e, ctx.sup, f"the {side} of {e.parent.object} is taken or outside "
                          f"{ctx.sup.name}", f" side {side}")
        return with_margin(new, lambda k: RG.clip(region, within(k * margin)))


def near_depth(ctx: RegionContext, n: np.ndarray) -> float:
    """How far the posed child reaches from its centroid (bounding-box centre) against the
    horizontal direction ``n``: toward a parent it stands beside on that side (m)."""
    n = np.array([n[0], n[1], 0.0])
    n /= max(float(np.linalg.norm(n)), 1e-9)
    geo = asset_geometry(ctx.asset)
    pts = (geo.hull * ctx.scale) @ ctx.R.T
    c = (geo.center * ctx.scale) @ ctx.R.T
    return max(float(np.max((c - pts) @ n)), 0.0)


@register
class Toward(LayoutRule):
    names = ("TOWARD",)

    def rotate(self, st: SolveState, asset: Asset, o: Orientation, e: Edge) -> None:
        """Turned per sampled position to face the parent (unless a part-level rule fixed
        it)."""
        o.toward = e.parent.object

    def region(self, ctx: RegionContext, e: Edge, region: BaseGeometry) -> BaseGeometry:
        """With a ``tolerance_deg`` of at least ``SQUARE_MIN_TOLERANCE``, prefer positions from which
        the child, squared to the nearest side of its target, still faces the target's centroid
        within ``SQUARE_SHARE`` of the tolerance: four cones about the target's side normals. Where none is free, the whole region stays (the child then faces
        the centroid exactly). A child whose angle is fixed otherwise, or that asks for a free
        yaw, is not constrained."""
        st, s = ctx.st, ctx.sup.surface
        if st.pag.objects[ctx.oid].extra.get("yaw") == "free" or abs(float(s.normal[2])) < 0.9 \
                or any(RULES[x.relation].fixes_yaw for x in st.pag.edges_of(ctx.oid)):
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


#: Margin (m) that a layout relation's region keeps inside its limit where the region allows
#: (settling moves things by millimetres to centimetres), at most ``MARGIN_SHARE`` of the limit.
LAYOUT_MARGIN = 0.05
MARGIN_SHARE = 0.2
#: Margin (m) beyond the parent's centroid that a ``SIDE_OF`` region keeps where it allows, at
#: most ``MARGIN_SHARE`` of the child's width along the side.
SIDE_MARGIN = 0.03
#: Least share of a layout relation's exact region that its region with the margin keeps to be
#: used instead (a sliver would crowd the sampled positions).
MARGIN_KEEP = 0.1


def layout_margin(limit: float) -> float:
    """The margin (m) kept inside a distance or width ``limit`` (m)."""
    return min(LAYOUT_MARGIN, MARGIN_SHARE * float(limit))


def with_margin(exact: BaseGeometry, inner: Callable[[float], BaseGeometry]) -> BaseGeometry:
    """The region ``inner(k)`` with the full margin (k = 1) or half of it, whichever first keeps
    at least ``MARGIN_KEEP`` of the ``exact`` region's area; else the exact region (the child
    then goes on the limit's edge, as the free room allows)."""
    for k in (1.0, 0.5):
        got = inner(k)
        if not got.is_empty and got.area >= max(MARGIN_KEEP * exact.area, 1e-10):
            return got
    return exact


#: Width (m) of the band of free positions nearest an emptied layout region that a relaxed
#: layout relation keeps (beyond the distance from the free positions to that region).
NEAREST_BAND = 0.1


def nearest(e: Edge) -> Edge:
    """The layout edge ``e`` relaxed to its nearest feasible pose: where its region would empty
    the free positions, the child goes to the free positions nearest that region instead of
    failing (a soap dispenser right of a sink at the counter's end stands as close to that
    side as the counter allows). The relation is still checked, and recorded relaxed when it
    does not hold."""
    out = replace(e)
    object.__setattr__(out, "_nearest", True)
    return out


def relaxed_to_nearest(e: Edge) -> bool:
    """Whether ``e`` is a layout edge relaxed by :func:`nearest` (its check then does not reject
    a pose: the region already holds the nearest positions)."""
    return bool(getattr(e, "_nearest", False))


def closest(region: BaseGeometry, clip: BaseGeometry) -> BaseGeometry:
    """The part of ``region`` within ``NEAREST_BAND`` of its positions nearest ``clip`` (the
    whole region when ``clip`` is empty or the band leaves no area; of a region without area,
    the lines or points a part-level contact left, the part within that band)."""
    if clip.is_empty or region.is_empty:
        return region
    d = float(region.distance(clip))
    near = RG.clip(region, clip.buffer(d + NEAREST_BAND, 16))
    if region.area < 1e-10:  # the lines or points part-level contacts leave
        return region if near.is_empty else near
    return region if near.is_empty or near.area < 1e-10 else near


def side_vector(st: SolveState, e, R: np.ndarray) -> np.ndarray:
    """World direction of a ``SIDE_OF`` / ``ALONG`` edge's ``side``: in the parent's frame
    (rotation ``R``), or with ``frame: camera`` as the PAG's viewpoint sees it."""
    if e.param("frame") == "camera":  # the side as the photograph shows it
        return np.array(st.pag.viewpoint.side_direction(st.pag.room, e.param("side")))
    parent = st.scene.objects.get(e.parent.object)
    if parent is not None and parent.placed:  # a record on edge: along its row
        R = side_frame(parent, R)
    return R @ np.array(_SIDE_DIRS[e.param("side")])
