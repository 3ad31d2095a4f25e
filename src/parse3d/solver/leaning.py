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
import shapely.affinity
from shapely.geometry.base import BaseGeometry

from ..assets.model import Asset
from ..geometry import regions as RG
from ..geometry.frames import axis_angle
from ..measure.checks import EPS
from ..measure.reach import (
    lean_range,
    mounted_parts,
    nearest_in_prism,
    piece_data,
    pieces_distance,
    stands_to_lean,
)
from ..pag.model import Edge
from .config import Fail
from .geometry import asset_geometry, hull_extents, part_points
from .rotation import _pressing, parent_surface_world
from .state import SolveState, parts_for, plane_coords, plane_key
from .support import Support

__all__ = ["lean_tilt", "lean_line", "lean_fit", "lean_samples", "involves_object", "LEAN_GAP"]

#: Share of a face's width the objects leaning on it side by side may fill together (the rest:
#: the gaps between them and at its ends).
LEAN_GAP = 0.8

#: Metres within which another part counts as level with the named part toward the face.
LEVEL = 2e-3
_UP = np.array([0.0, 0.0, 1.0])


def _faces(st: SolveState, e: Edge) -> list:
    """The parent's world faces (one per part its reference names: a sofa's back cushions),
    each ``(surface, (z low, z high), width axis, outline along it)``; empty when the face is
    not upright (the plain plane test applies). Kept while the parent keeps its pose (every
    sample of a leaning child asks again)."""
    ref = e.parent
    if not ref.is_room_element and not st.scene.objects[ref.object].placed:
        return _faces_now(st, e)
    key = ("faces", ref.object, ref.part, ref.index, ref.surface, e.spec.parent_surface)
    return st.memo("room" if ref.is_room_element else ref.object, key,
                   lambda: _faces_now(st, e))


def _faces_now(st: SolveState, e: Edge) -> list:
    """:func:`_faces`, computed."""
    sB, _, label = parent_surface_world(st, e.parent, e.spec.parent_surface)
    if abs(float(sB.normal[2])) > 0.3:
        return []
    faces = [sB]
    if not e.parent.is_room_element and e.parent.part is not None and e.parent.index is None:
        parent = st.scene.objects[e.parent.object]
        more = parts_for(parent.asset, e.parent)
        if len(more) > 1:
            T = parent.transform()
            faces = [p.surfaces[label].transformed(T) for p in more if label in p.surfaces]
    out = []
    parent = None if e.parent.is_room_element else st.scene.objects[e.parent.object]
    own = [] if parent is None else parts_for(parent.asset, e.parent)
    for f in faces:
        o = f.outline_3d()
        t = np.cross(f.normal, _UP)
        t /= np.linalg.norm(t)
        # what is mounted on the face (an amplifier's knobs) is touched first
        front = 0.0 if parent is None or e.parent.part is None else \
            mounted_parts(parent, own, f, parent.transform())[1]
        out.append((f, (float(o[:, 2].min()), float(o[:, 2].max())), t, o @ t, front))
    return out


def lean_tilt(st: SolveState, sup: Support, asset: Asset, scale: float, R: np.ndarray,
              k: np.ndarray, d: np.ndarray, e: Edge, rng: np.random.Generator, fallback):
    """A tilt (radians about ``k``) at which the named part is the child's extreme toward the
    parent's face among the child's points at the face's height, and gravity presses it there.

    ``fallback()`` is the plain-plane choice, used for faces that are not upright, for
    supports that are not level and for walls (a wall spans every height)."""
    if _lying_roller(asset, R):
        raise Fail(f"LEANING_AGAINST {e.child} -> {e.parent}: {asset.asset_id} lies on its round "
                   f"side and would roll off what it leans on", intrinsic=True)
    _keeps_level(st, asset, R, k, e)
    if e.parent.is_room_element or abs(float(sup.surface.normal[2])) < 0.9:
        return fallback()
    faces = _faces(st, e)
    if not faces:
        return fallback()
    sB, (zlo, zhi), _, _, _ = faces[0]
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
    written = getattr(e, "_written_tilt", None)  # relaxed to lean further: as written first
    if written is not None:
        ranges = [written, (lo, hi)]
    stood = stands_to_lean(asset, st.pag, e.child.object)
    if stood:  # a pillow on its edge: the whole range, pressed firmly (it would roll upright)
        ranges = [wide]
    worst = (0.0, None)
    above = _parts_above(st, e, faces[0])
    blocked = upright = None
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
            hit = _hits_above(whole, T, sB, mine[0], above)
            if hit is not None:  # the neck would run into what sits on the face's top
                blocked = hit
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
        if ok and sup.owner != "room":  # resting on an object: where its base lands on it
            ok = _landing(st, sup, asset, scale, R, k, named, faces[0], ok) or ok
        if ok and stood:
            return _firm(asset, scale, R, k, d, ok, rng)
        if ok:
            try:
                return pressed(asset, scale, R, k, d, ok, rng, e)
            except Fail as f:  # it stands up by itself there: maybe leaning further holds
                upright = f
    if upright is not None:
        raise upright
    if blocked is not None and worst[1] is None:
        why = (f"leaning there it would run into {e.parent.object}:{blocked} above the face "
               f"(another instance of {e.parent.object} may have none)")
    elif worst[1] is None:
        why = (f"{e.child} never comes level with {e.parent} ({zhi - z0:.2f} m high above "
               f"{sup.name})")
    else:
        why = (f"at {e.parent}'s height another part of {e.child.object} reaches up to "
               f"{worst[0]:.2f} m further toward it than {e.child.part}")
    # the parent's instance may be the cause (an amplifier too tall for a guitar's body):
    # not intrinsic, so the search may re-place the parent
    raise Fail(f"LEANING_AGAINST {e.child} -> {e.parent}: at every tilt in {ranges[-1][0]:g}-"
               f"{ranges[-1][1]:g} deg {why}")


def _landing(st: SolveState, sup: Support, asset: Asset, scale: float, R: np.ndarray,
             k: np.ndarray, named, face, tilts: list[float]) -> list[float]:
    """The tilts among ``tilts`` at which the child, its named part touching ``face``, can
    rest its base on ``sup`` (an object's), clear of the owner's parts rising through the
    base (a padded bar across a guitar stand's cradle): resting on an object and leaning on
    another, the tilt fixes how far from the face the base stands (a guitar's neck on its
    stand's neck rest puts its body in the cradle only at some tilts)."""
    s = sup.surface
    sB, (zlo, zhi), _, _, front = face
    g = np.array([s.u @ sB.normal, s.v @ sB.normal])
    if np.linalg.norm(g) < 1e-6:
        return tilts
    region = _base_region(st, sup)
    if region.is_empty:
        return tilts
    hull = asset_geometry(asset).hull * scale
    z0 = float(s.origin[2])
    p0 = plane_coords(s, np.array([[0.0, 0.0, z0]]))[0]
    out = []
    for th in tilts:
        Rt = axis_angle(k, th) @ R
        Y = hull @ Rt.T
        T = np.eye(4)
        T[:3, :3] = Rt * scale
        T[2, 3] = z0 - float(Y[:, 2].min())
        got = nearest_in_prism(named, T, sB.normal, sB.origin, [(_UP, zlo, zhi)])
        if got is None:
            continue
        base = Y[Y[:, 2] <= Y[:, 2].min() + BASE_BAND]
        Fb = np.c_[base @ s.u, base @ s.v]
        Fb = RG.convex_footprint(np.vstack([Fb, Fb + 1e-4, Fb + [1e-4, 0.0]]))
        c = Fb.mean(axis=0)
        free = shapely.affinity.translate(RG.erode(region, [], Fb - c), -float(c[0]),
                                          -float(c[1]))
        if free.is_empty:
            continue
        gn = float(np.linalg.norm(g))
        ln = RG.line(p0, g / gn, (EPS + front - got[0]) / gn)
        if not RG.clip(free, ln).is_empty:
            out.append(th)
    return out


def _base_region(st: SolveState, sup: Support):
    """``sup``'s region, 3 mm in from its edge, less the footprints of its owner's parts that
    rise through the base of what rests on it (a padded bar across a guitar stand's cradle, a
    plate rail along a shelf), in the support plane's coordinates."""
    owner = st.scene.objects.get(sup.owner)
    if owner is None:
        return sup.region.buffer(-3e-3, join_style="mitre")
    return st.memo(sup.owner, ("lean_base", plane_key(sup.surface), sup.choice, sup.spans,
                               sup.reaches),
                   lambda: _clear_of_parts(sup, owner))


def _clear_of_parts(sup: Support, owner):
    """:func:`_base_region` for the owner's current pose."""
    s = sup.surface
    region = sup.region.buffer(-3e-3, join_style="mitre")
    if region.is_empty:
        return region
    T = owner.transform()
    z0 = float(s.origin[2])
    cut = []
    for p in owner.asset.parts:
        P = part_points([p]) @ T[:3, :3].T + T[:3, 3]
        if float(P[:, 2].max()) <= z0 + BASE_BAND or float(P[:, 2].min()) >= z0 + BASE_BAND:
            continue
        cut.append(shapely.Polygon(RG.convex_footprint(plane_coords(s, P))).buffer(1e-4))
    return region.difference(shapely.union_all(cut)) if cut else region


#: Degrees from up within which a surface still holds what is ON it (the support test's).
LEVEL_DEG = 5.0


def _keeps_level(st: SolveState, asset: Asset, R: np.ndarray, k: np.ndarray, e: Edge) -> None:
    """Fail when leaning by the least tilt ``e`` allows would turn a surface of the child that
    something else is ON away from up (an ironing board leaning folded against the wall with an
    iron ON its iron rest): the support of what it carries is hard, its own lean is not, so the
    lean is relaxed and the child stands upright."""
    lo = float(e.param("angle_deg")[0])
    if lo <= LEVEL_DEG:
        return
    Rt = axis_angle(k, np.deg2rad(lo)) @ R
    for x in st.pag.relations:
        if x.relation != "ON" or x.parent.object != e.child.object:
            continue
        label = x.parent.surface or "top"
        parts = parts_for(asset, x.parent) if x.parent.part is not None else list(asset.parts)
        tops = [Rt @ np.asarray(p.surfaces[label].normal, float) for p in parts
                if label in p.surfaces]
        if tops and max(float(n[2]) for n in tops) < np.cos(np.deg2rad(LEVEL_DEG)):
            raise Fail(f"LEANING_AGAINST {e.child} -> {e.parent}: leaning by {lo:g} deg or more "
                       f"would tip {x.parent} off level, and {x.child.object} stands ON it "
                       f"(let {e.child.object} stand upright, or lean {x.child.object} too)",
                       intrinsic=True)


def _parts_above(st: SolveState, e: Edge, face) -> list[tuple[str, float, float, float]]:
    """The parent's parts standing on top of the face (an amplifier's head on its cabinet),
    over its width: ``(label, z low, z high, how far in front of the face's plane)``."""
    sB, (zlo, zhi), t, along, _ = face
    if e.parent.is_room_element:
        return []
    parent = st.scene.objects[e.parent.object]
    T = parent.transform()
    own = {p.name for p in parts_for(parent.asset, e.parent)}
    out = []
    for p in parent.asset.parts:
        if p.name in own:
            continue
        P = part_points([p]) @ T[:3, :3].T + T[:3, 3]
        if float(P[:, 2].min()) < zhi - 0.01:
            continue
        a = P @ t
        # over most of the face's width (else the child may lean beside it)
        cover = min(float(a.max()), float(along.max())) - max(float(a.min()), float(along.min()))
        if cover < 0.8 * float(np.ptp(along)):
            continue
        # from 1 cm above its foot: the child touches the face up to the face's top edge
        out.append((p.label, float(P[:, 2].min()) + 0.01, float(P[:, 2].max()),
                    float(np.max((P - sB.origin) @ sB.normal))))
    return out


def _hits_above(whole, T: np.ndarray, sB, touch: float, above) -> str | None:
    """The label of a part in ``above`` the child (posed by ``T``, then moved so that its named
    part, now ``touch`` from the face's plane, touches it) would reach into; None when none."""
    for label, z0, z1, front in above:
        got = nearest_in_prism(whole, T, sB.normal, sB.origin, [(_UP, z0, z1)])
        if got is not None and got[0] - touch + EPS < front - LEVEL:
            return label
    return None


def pressed(asset: Asset, scale: float, R: np.ndarray, k: np.ndarray, d: np.ndarray,
            tilts: list[float], rng: np.random.Generator, e: Edge) -> float:
    """One of ``tilts`` (those at which the named part touches) at which gravity presses the
    child toward its parent (:func:`parse3d.solver.rotation._pressing`); Fail when at every one
    of them its centre of mass lies behind the edge it pivots on: it would stand up off the
    parent in settling (a guitar leaning by its body, which touches only below about 4
    degrees; even a flat-bottomed one 8 mm behind may stay, a round-bottomed one 17 mm
    behind rolled upright)."""
    g = asset_geometry(asset)
    hull, com = g.hull * scale, g.com * scale
    best = -np.inf
    for th in tilts:
        Rt = axis_angle(k, th) @ R
        Y = hull @ Rt.T
        base = Y[Y[:, 2] <= Y[:, 2].min() + 2e-3]
        best = max(best, float((Rt @ com) @ d - np.max(base @ d)))
    if best < 0.0:
        lo, hi = np.rad2deg(min(tilts)), np.rad2deg(max(tilts))
        raise Fail(f"LEANING_AGAINST {e.child} -> {e.parent}: {e.child.part or 'it'} touches "
                   f"only at tilts of {lo:.0f}-{hi:.0f} deg, where {asset.asset_id} stands up "
                   f"by itself (its centre of mass {-best * 1000:.0f} mm short of its base's "
                   f"edge), so settling would undo the lean (name {e.child.object}@"
                   f"{e.child.surface or 'back'} to lean on any part)", intrinsic=True)
    return _pressing(asset, scale, R, k, d, tilts, rng)


def _lying_roller(asset: Asset, R: np.ndarray) -> bool:
    """An elongated child with a round-ish cross-section (its two smaller extents within 30%,
    the longest beyond 1.5 times them: a bolster) whose long axis lies level in ``R``."""
    ext = np.ptp(asset_geometry(asset).bounds, axis=0)
    k = np.argsort(ext)
    if ext[k[1]] > 1.3 * ext[k[0]] or ext[k[2]] < 1.5 * ext[k[1]]:
        return False
    return abs(float(R[2, k[2]])) < 0.5


#: Share of its thickness by which a flat child standing on its edge keeps its centre of mass
#: beyond the edge it pivots on, toward the parent: its rounded edge rolls, a thin margin lets
#: it stand up off the parent in settling.
FIRM_SHARE = 0.3


def _firm(asset: Asset, scale: float, R: np.ndarray, k: np.ndarray, d: np.ndarray,
          tilts: list[float], rng: np.random.Generator) -> float:
    """One of ``tilts`` at which the centre of mass lies :data:`FIRM_SHARE` of the child's
    thickness beyond its base toward the parent (random among them); else the firmest."""
    need = FIRM_SHARE * float(np.ptp(asset_geometry(asset).hull[:, 2])) * scale
    return _pressing(asset, scale, R, k, d, tilts, rng, margin=need)


def lean_line(ctx, e: Edge, region: BaseGeometry) -> BaseGeometry | None:
    """The child's origins (support-plane coordinates) at which its named part touches the
    parent's upright face within the face's extent: on the contact line, and with the middle
    of the touching band inside the face's width. None for faces that are not upright or
    supports that are not level (the plain plane line applies)."""
    st, s, asset, scale, R = ctx.st, ctx.sup.surface, ctx.asset, ctx.scale, ctx.R
    if abs(float(s.normal[2])) < 0.9:
        return None
    faces = _faces(st, e)
    if not faces:
        return None
    parts = parts_for(asset, e.child) if e.child.part is not None else list(asset.parts)
    if not parts:
        raise Fail(f"{e.child.object!r} has no part {e.child.part!r}")
    base = s.origin + ctx.h * s.normal
    T = np.eye(4)
    T[:3, :3] = R * scale
    T[:3, 3] = base
    got, widths = [], []
    for sB, (zlo, zhi), t, along, front in faces:
        new = _on_face(e, s, sB, zlo, zhi, t, along, piece_data(asset, parts), T, region,
                       front)
        widths.append(float(np.ptp(along)))
        if new is not None and not new.is_empty:
            got.append(new)
    if not got:
        b = region.bounds if not region.is_empty else None
        room = "no free space was left there" if b is None else \
            f"the free positions span {b[2] - b[0]:.2f} x {b[3] - b[1]:.2f} m elsewhere"
        raise Fail(f"LEANING_AGAINST {e.child} -> {e.parent} emptied the feasible region on "
                   f"{ctx.sup.name}: where {e.child} touches {e.parent} within its "
                   f"{max(widths):.2f} m wide face, {room}")
    return got[0] if len(got) == 1 else shapely.union_all(got)


def _on_face(e: Edge, s, sB, zlo: float, zhi: float, t: np.ndarray, along: np.ndarray, pieces,
             T: np.ndarray, region: BaseGeometry, front: float = 0.0) -> BaseGeometry | None:
    """The part of ``region`` where the child (posed by ``T`` at the plane's origin) touches
    the face ``sB`` within its extent; None when its named part never comes level with it."""
    nB = sB.normal
    got = nearest_in_prism(pieces, T, nB, sB.origin, [(_UP, zlo, zhi)], band=LEVEL)
    if got is None:
        return None
    dist, _, band = got
    g = np.array([s.u @ nB, s.v @ nB])
    gt = np.array([s.u @ t, s.v @ t])
    if np.linalg.norm(g) < 1e-6 or np.linalg.norm(gt) < 1e-6:
        return None
    # moving the origin by (x, y) moves the contact by g . (x, y) along the face normal
    ln = RG.line(np.zeros(2), g / np.linalg.norm(g), (EPS + front - dist) / np.linalg.norm(g))
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
    # the erosion wants the reference point inside the footprint: erode about the base's
    # centre, then move back to the origin
    c = Fb.mean(axis=0)
    region = shapely.affinity.translate(RG.erode(region0, [], Fb - c), -float(c[0]),
                                        -float(c[1]))
    if region.is_empty or region.area < 1e-10:
        raise Fail(f"no room on {sup.name} for the base of a leaning {asset.category}",
                   intrinsic=True)
    c3 = (asset_geometry(asset).center * scale) @ R.T
    ctx = RegionContext(st, oid, asset, scale, R, h, sup, np.array([c3 @ s.u, c3 @ s.v]),
                        c3 + h * s.normal)
    region = apply_region_rules(ctx, others, region, "object")
    region = apply_region_rules(ctx, others, region, "part")
    return region, _packed(st, oid, R, s, others, RG.sample_uniform(region, rng, n))


def _leaning_beside(st: SolveState, oid: str, edges: list[Edge]) -> list[str]:
    """The other objects leaning on the same face of the same object as ``oid`` (an edge of
    ``edges``) and resting on the same object: cushions along one bench's back."""
    sup = st.pag.supporter(oid)
    out = []
    for e in edges:
        if e.relation != "LEANING_AGAINST" or e.parent.is_room_element or sup is None:
            continue
        key = (e.parent.object, e.parent.part, e.parent.index, e.parent.surface)
        for x in st.pag.relations:
            if x.relation != "LEANING_AGAINST" or x.child.object == oid or (
                    x.parent.object, x.parent.part, x.parent.index, x.parent.surface) != key:
                continue
            under = st.pag.supporter(x.child.object)
            if under is not None and under.parent.object == sup.parent.object \
                    and x.child.object not in out:
                out.append(x.child.object)
    return out


def _packed(st: SolveState, oid: str, R: np.ndarray, s, edges: list[Edge],
            samples: np.ndarray) -> np.ndarray:
    """Samples of a child leaning on a face that others lean on side by side, reordered so
    that they pack along it: nearest the placed ones first; the first of them from the end
    away from those the writer put beside it (cushion1 first at the left end when cushion2 is
    SIDE_OF its right), else from one end. Unchanged for a child leaning alone."""
    from .rules import side_vector

    beside = _leaning_beside(st, oid, edges)
    if not beside or len(samples) < 2:
        return samples
    placed = [b for b in beside if b in st.hulls]
    if placed:
        cs = np.array([plane_coords(s, st.hulls[b]).mean(axis=0) for b in placed])
        d = np.min(np.linalg.norm(samples[:, None, :] - cs[None], axis=2), axis=1)
        return samples[np.argsort(d, kind="stable")]
    g = np.zeros(3)
    for x in st.pag.relations:
        if x.relation == "SIDE_OF" and x.child.object in beside and x.parent.object == oid:
            g -= side_vector(st, x, R)  # it goes to that side: this one the other way
    g2 = np.array([g @ s.u, g @ s.v])
    if np.linalg.norm(g2) < 1e-6:
        d = samples - samples.mean(axis=0)
        g2 = np.linalg.svd(d, full_matrices=False)[2][0]
    return samples[np.argsort(-(samples @ g2), kind="stable")]


#: Metres a leaning child is backed off its contact line before it slides onto its parent.
SLIDE_BACK = 0.08


def lean_slide(st: SolveState, oid: str, asset: Asset, scale: float, R: np.ndarray,
               t: np.ndarray, lean: tuple):
    """The child's position after sliding it, from ``SLIDE_BACK`` behind ``t``, horizontally
    toward the object it leans on until its collision pieces touch the parent's: the face's
    plane is a patch of the part, which may slant back above it (a sofa's reclined back
    cushion) or carry parts in front of it; the pieces are what settling simulates. ``t``
    unchanged when nothing is met within reach."""
    from ..measure.geometry import drop_distance
    from .nesting import pieces_drop

    e, _, d = lean
    parent = st.scene.objects[e.parent.object]
    d = np.asarray(d, float) / np.linalg.norm(d)
    start = np.asarray(t, float) - SLIDE_BACK * d
    T = np.eye(4)
    T[:3, :3] = R * scale
    T[:3, 3] = start
    reach = SLIDE_BACK + 0.05
    if e.parent.part is not None:
        return _slide_onto_part(st, e, asset, T, parent, d, reach, t)
    # the rays of the mesh vertices first (fast), then the pieces near where they meet
    ray = drop_distance((asset_geometry(asset).hull * scale) @ R.T + start, asset, T,
                        st.hulls[parent.id], parent.asset, parent.transform(), d)
    lo = 0.0
    if np.isfinite(ray) and ray < reach:
        lo = max(0.0, float(ray) - 0.01)
        reach = min(reach, float(ray) + 0.005)
    T[:3, 3] = start + lo * d
    got = lo + pieces_drop(asset, T, parent, d, reach - lo, tol=5e-4)
    if got >= SLIDE_BACK + 0.05:
        return t
    return start + max(got - EPS, 0.0) * d


def _slide_onto_part(st: SolveState, e: Edge, asset: Asset, T: np.ndarray, parent, d: np.ndarray,
                     reach: float, t: np.ndarray) -> np.ndarray:
    """:func:`lean_slide` onto the parent's named part (and what is mounted on its face) alone:
    its other parts in the way (a plate rail along a hutch's shelf, in front of the back panel
    the plate leans on) are the collision test's to judge, not a stop short of the face."""
    Tp = parent.transform()
    own = parts_for(parent.asset, e.parent)
    faces = _faces(st, e)
    on = mounted_parts(parent, own, faces[0][0], Tp)[0] if faces else []
    mine = piece_data(asset, asset.parts)
    theirs = piece_data(parent.asset, own + [p for p in on if p not in own])
    # conservative advancement: moving by the pieces' distance cannot make them overlap
    shift = 0.0
    Ts = np.array(T, float)
    for _ in range(40):
        Ts[:3, 3] = T[:3, 3] + shift * d
        gap = pieces_distance(mine, Ts, theirs, Tp, limit=reach - shift + 1e-3)
        if gap > reach - shift:
            return t
        if gap <= 5e-4:
            break
        shift += gap
    return T[:3, 3] + max(shift - EPS, 0.0) * d


def lean_fit(st: SolveState, oid: str, edges: list[Edge], asset: Asset, scale: float) -> float:
    """``scale``, or less when the child is wider than its share of an object's upright face
    it leans on together with others resting on the same object (three cushions along a bench's
    back): :data:`LEAN_GAP` of the face's width split equally among them, each measured across
    its leaning side (its x extent leaning by its back or front, as a flat leaner standing on
    its edge also does; its y extent by a side). Never below the category's size range, and
    unchanged where even that share is below it (books against a narrow bookend lean on one
    another, not side by side)."""
    for e in edges:
        if e.relation != "LEANING_AGAINST" or e.parent.is_room_element \
                or e.parent.object not in st.scene.objects:
            continue
        beside = _leaning_beside(st, oid, [e])
        if not beside:
            continue
        try:
            faces = _faces(st, e)
        except Fail:
            continue
        if not faces:
            continue
        along = np.concatenate([f[3] for f in faces])
        share = LEAN_GAP * float(np.ptp(along)) / (1 + len(beside))
        axis = 1 if e.child.surface in ("left", "right") else 0
        width = scale * float(hull_extents(asset)[0][axis])
        lo = asset.size_range[0] / max(asset_geometry(asset).size, 1e-6)
        if width <= share or share < width * lo / max(scale, 1e-9):
            continue
        return max(scale * share / width, min(lo, scale))
    return scale
