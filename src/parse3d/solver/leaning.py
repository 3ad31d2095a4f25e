"""LEANING_AGAINST a face of finite extent: a book against a box or a bookend, a pillow against a
headboard, a guitar against an amplifier.

The parent's face is a patch, not an infinite plane. The child's named part must touch it
*within its extent*: at the face's height (a guitar's body below an amplifier's top, while its
neck may pass over the top) and within its width (a book 12 cm beside a box touches nothing).
:func:`lean_tilt` picks the tilt at which the named part is the child's extreme toward the face
among the child's points at the face's height; :func:`lean_line` gives the positions where that
part touches the face, within the face's width. Both measure with
:func:`parse3d.measure.reach.nearest_in_prism`, as the ``LEANING_AGAINST`` check does.
"""

from __future__ import annotations

import numpy as np
import shapely
from shapely.geometry.base import BaseGeometry

from ..assets.model import Asset
from ..geometry import regions as RG
from ..geometry.frames import axis_angle
from ..measure.checks import EPS
from ..measure.reach import nearest_in_prism, piece_data
from ..pag.model import Edge
from .config import Fail
from .geometry import asset_geometry
from .rotation import parent_surface_world
from .state import SolveState, parts_for
from .support import Support

__all__ = ["lean_tilt", "lean_line", "lean_range", "WIDE_LEAN_DEG"]

#: Tilts (degrees) a child may lean at on an object's face when the PAG gives no ``angle_deg``:
#: the default range is tried first, then this one (a pillow slumped against a headboard, a
#: book against a short box). The check accepts the same range.
WIDE_LEAN_DEG = (4.0, 35.0)
#: Metres within which another part counts as level with the named part toward the face.
LEVEL = 2e-3
_UP = np.array([0.0, 0.0, 1.0])


def lean_range(edge: Edge, parent_is_object: bool) -> tuple[float, float]:
    """The tilt range (degrees) a leaning child may take: ``angle_deg`` as written, or, not
    written and leaning on an object, :data:`WIDE_LEAN_DEG` widened to include the default."""
    lo, hi = edge.param("angle_deg")
    if parent_is_object and "angle_deg" not in edge.params:
        return min(lo, WIDE_LEAN_DEG[0]), max(hi, WIDE_LEAN_DEG[1])
    return lo, hi


def _face(st: SolveState, e: Edge):
    """The parent's world face, its height slab and its width axis; None when the face is not
    upright (the plain plane test applies)."""
    sB, _, _ = parent_surface_world(st, e.parent, e.spec.parent_surface)
    if abs(float(sB.normal[2])) > 0.3:
        return None
    out = sB.outline_3d()
    t = np.cross(sB.normal, _UP)
    t /= np.linalg.norm(t)
    return sB, (float(out[:, 2].min()), float(out[:, 2].max())), t, out @ t


def lean_tilt(st: SolveState, sup: Support, asset: Asset, scale: float, R: np.ndarray,
              k: np.ndarray, d: np.ndarray, e: Edge, rng: np.random.Generator, fallback):
    """A tilt (radians about ``k``) at which the named part is the child's extreme toward the
    parent's face among the child's points at the face's height, and gravity presses it there.

    ``fallback()`` is the plain-plane choice, used for faces that are not upright, for
    supports that are not level and for walls (a wall spans every height)."""
    if e.parent.is_room_element or abs(float(sup.surface.normal[2])) < 0.9:
        return fallback()
    face = _face(st, e)
    if face is None:
        return fallback()
    sB, (zlo, zhi), _, _ = face
    from .rotation import _pressing

    parts = parts_for(asset, e.child) if e.child.part is not None else list(asset.parts)
    if not parts:
        raise Fail(f"LEANING_AGAINST {e.child} -> {e.parent}: {asset.asset_id} has no part "
                   f"{e.child.part!r}")
    named = piece_data(asset, parts)
    whole = piece_data(asset, asset.parts)
    hull = asset_geometry(asset).hull * scale
    z0 = float(sup.surface.origin[2])
    slab = [(_UP, zlo, zhi)]
    lo, hi = e.param("angle_deg")
    wide = lean_range(e, True)
    ranges = [(lo, hi)] + ([wide] if wide != (lo, hi) else [])
    worst = (0.0, None)
    for a, b in ranges:
        ok = []
        for th in np.deg2rad(np.linspace(a, b, 25)):
            Rt = axis_angle(k, th) @ R
            T = np.eye(4)
            T[:3, :3] = Rt * scale
            T[2, 3] = z0 - float((hull @ Rt.T)[:, 2].min())
            mine = nearest_in_prism(named, T, sB.normal, sB.origin, slab)
            if mine is None:
                continue
            if e.child.part is None:
                ok.append(th)
                continue
            every = nearest_in_prism(whole, T, sB.normal, sB.origin, slab)
            ahead = mine[0] - every[0]
            if ahead <= LEVEL:
                ok.append(th)
            elif ahead > worst[0]:
                worst = (ahead, th)
        if ok:
            return _pressing(asset, scale, R, k, d, ok, rng)
    if worst[1] is None:
        why = (f"{e.child} never comes level with {e.parent} ({zhi - z0:.2f} m high above "
               f"{sup.name})")
    else:
        why = (f"at {e.parent}'s height another part of {e.child.object} reaches up to "
               f"{worst[0]:.2f} m further toward it than {e.child.part}")
    # the parent's instance may be the cause (an amplifier too tall for a guitar's body):
    # not intrinsic, so the search may re-place the parent
    raise Fail(f"LEANING_AGAINST {e.child} -> {e.parent}: at every tilt in {ranges[-1][0]:g}-"
               f"{ranges[-1][1]:g} deg {why}")


def lean_line(ctx, e: Edge, region: BaseGeometry) -> BaseGeometry | None:
    """The child's origins (support-plane coordinates) at which its named part touches the
    parent's upright face within the face's extent: on the contact line, and with the middle
    of the touching band inside the face's width. None for faces that are not upright or
    supports that are not level (the plain plane line applies)."""
    st, s, asset, scale, R = ctx.st, ctx.sup.surface, ctx.asset, ctx.scale, ctx.R
    if abs(float(s.normal[2])) < 0.9:
        return None
    face = _face(st, e)
    if face is None:
        return None
    sB, (zlo, zhi), t, along = face
    nB = sB.normal
    parts = parts_for(asset, e.child) if e.child.part is not None else list(asset.parts)
    if not parts:
        raise Fail(f"{e.child.object!r} has no part {e.child.part!r}")
    base = s.origin + ctx.h * s.normal
    T = np.eye(4)
    T[:3, :3] = R * scale
    T[:3, 3] = base
    got = nearest_in_prism(piece_data(asset, parts), T, nB, sB.origin, [(_UP, zlo, zhi)],
                           band=LEVEL)
    if got is None:
        raise Fail(f"LEANING_AGAINST {e.child} -> {e.parent}: {e.child} is never level with "
                   f"{e.parent} on {ctx.sup.name}")
    dist, _, band = got
    g = np.array([s.u @ nB, s.v @ nB])
    gt = np.array([s.u @ t, s.v @ t])
    if np.linalg.norm(g) < 1e-6 or np.linalg.norm(gt) < 1e-6:
        raise Fail(f"LEANING_AGAINST {e.child} -> {e.parent}: the parent surface is parallel "
                   f"to the support, no position satisfies it")
    # moving the origin by (x, y) moves the contact by g . (x, y) along the face normal
    ln = RG.line(np.zeros(2), g / np.linalg.norm(g), (EPS - dist) / np.linalg.norm(g))
    new = RG.clip(region, ln)
    # the middle of the touching band within the face's width (a margin of a quarter of the
    # narrower of the two, at most 2 cm)
    c = float(np.mean(band @ t))
    a0, a1 = float(along.min()), float(along.max())
    w = float(np.ptp(band @ t))
    m = min(0.02, 0.25 * max(min(w, a1 - a0), 0.0))
    if a1 - a0 > 2 * m:
        nt = np.linalg.norm(gt)
        new = RG.clip(new, RG.strip(np.zeros(2), gt / nt, (a0 + m - c) / nt, (a1 - m - c) / nt))
    if new.is_empty or shapely.get_num_geometries(new) == 0:
        b = region.bounds if not region.is_empty else None
        room = "no free space was left there" if b is None else \
            f"the free positions span {b[2] - b[0]:.2f} x {b[3] - b[1]:.2f} m elsewhere"
        raise Fail(f"LEANING_AGAINST {e.child} -> {e.parent} emptied the feasible region on "
                   f"{ctx.sup.name}: where {e.child} touches {e.parent} within its "
                   f"{a1 - a0:.2f} m wide face, {room}")
    return new


#: Metres above its lowest point within which a leaning child's points are its base.
BASE_BAND = 3e-3


def involves_object(sup: Support, lean: list) -> bool:
    """Whether a leaning child rests on an object or leans on one (a pillow on a mattress
    against the headboard, a frame on a shelf against the wall, a book on a desk against a
    box): then :func:`lean_samples` draws its positions."""
    return bool(lean) and (sup.owner != "room" or not lean[0][0].parent.is_room_element)


def lean_samples(st: SolveState, oid: str, asset: Asset, scale: float, R: np.ndarray, h: float,
                 sup: Support, others: list[Edge], region0, rng: np.random.Generator,
                 n: int):
    """``(region, samples)`` for a leaning child that involves an object: its *base* on the
    support (what leans overhangs toward the parent: a pillow's top over the mattress's end,
    toward the headboard), its relations' regions, and the contact line within the parent
    face's extent. The leaning part reaches over or toward its parent, so 2-D footprints of
    obstacles say nothing: the mesh collision test of each sample decides."""
    from .regions import RegionContext, apply_region_rules

    s = sup.surface
    Y = (asset_geometry(asset).hull * scale) @ R.T
    hN = Y @ s.normal
    base = Y[hN <= hN.min() + BASE_BAND]
    pts = np.c_[base @ s.u, base @ s.v]
    Fb = RG.convex_footprint(np.vstack([pts, pts + 1e-4, pts + [1e-4, 0.0]]))
    region = RG.erode(region0, [], Fb)
    if region.is_empty or region.area < 1e-10:
        raise Fail(f"no room on {sup.name} for the base of a leaning {asset.category}",
                   intrinsic=True)
    c3 = (asset_geometry(asset).center * scale) @ R.T
    ctx = RegionContext(st, oid, asset, scale, R, h, sup, np.array([c3 @ s.u, c3 @ s.v]),
                        c3 + h * s.normal)
    region = apply_region_rules(ctx, others, region, "object")
    region = apply_region_rules(ctx, others, region, "part")
    return region, RG.sample_uniform(region, rng, n)
