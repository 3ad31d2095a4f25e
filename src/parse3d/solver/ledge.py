"""A thin flat object standing on a narrow ledge, leaning back on the part behind it.

Sheet music ``ON stand:ledge``: a 0.22 x 0.30 m sheet cannot lie flat on a 5 cm ledge. A real
sheet stands on its lower edge on the ledge and leans back on the stand's desk. When a thin
child (its thinnest extent at most ``THIN`` times the next) does not fit lying flat on an
object's surface, :func:`place_leaning` stands it on the edge of its longer side, its flat face
against the nearest flat part of the support's owner that rises behind the ledge and leans
back by 3-35 degrees (the desk), and its lower edge on the ledge.

The pose records ``rests_on`` (the child's surface label on the ledge), which the ON check
reads: that surface faces the support within the lean angle, and the child's base (not its
centre of mass, which lies over the desk) rests on the support polygon.
"""

from __future__ import annotations

import numpy as np
import shapely

from ..assets.model import Asset
from ..measure.checks import EPS
from ..measure.reach import stands_to_lean
from ..pag.model import Edge
from ..scene.model import PlacedObject
from .collision import Body
from .config import Fail
from .geometry import asset_geometry, part_points
from .state import SolveState, parts_for, plane_coords
from .support import Support

__all__ = ["place_leaning", "may_lean", "THIN", "LEAN_RANGE_DEG", "may_lean_on_wall", "place_on_wall",
           "WALL_REACH", "WALL_LEAN_DEG"]

#: A child is thin when its smallest extent is at most this fraction of its middle one.
THIN = 0.2

#: Tilt from vertical (degrees) of a backing part a thin child may lean on.
LEAN_RANGE_DEG = (3.0, 35.0)

#: Metres around the ledge within which a backing part's foot must lie.
BACKING_REACH = 0.03

#: Positions along the ledge tried per asset.
LEAN_TRIALS = 8

_UP = np.array([0.0, 0.0, 1.0])

#: Asset axis -> surface label of its negative and positive side.
_LABELS = {0: ("left", "right"), 1: ("back", "front"), 2: ("bottom", "top")}


def may_lean(st: SolveState, asset: Asset, scale: float, sup: Support, edge: Edge) -> bool:
    """Whether ``place_leaning`` applies: ON a part of an object, a thin child, and a support
    narrower than the child lying flat."""
    if edge.relation != "ON" or sup.owner == "room":
        return False
    ext = np.sort(np.ptp(asset_geometry(asset).hull, axis=0) * scale)
    if ext[0] > THIN * ext[1]:
        return False
    if edge.child.part is not None and not _spans(asset, edge):
        return False
    x0, y0, x1, y1 = sup.region.bounds
    return min(x1 - x0, y1 - y0) < ext[1]


def _spans(asset: Asset, edge: Edge) -> bool:
    """Whether the child's part named by ``edge`` spans the child's two larger extents (a
    booklet's cover, not its staple): standing on its edge, the whole child stands on it."""
    parts = parts_for(asset, edge.child)
    if not parts:
        return False
    ext = np.ptp(asset_geometry(asset).hull, axis=0)
    own = np.ptp(part_points(parts), axis=0)
    big = np.argsort(ext)[1:]
    return bool(np.all(own[big] >= 0.8 * ext[big]))


def _backing(st: SolveState, sup: Support, height: float):
    """``(part name, front normal (3,), front offset)`` of the owner's flat part behind the
    ledge that leans back within ``LEAN_RANGE_DEG``: the plane the child's face rests on; None
    when there is none."""
    s = sup.surface
    n_up = s.normal
    ledge = sup.region.buffer(BACKING_REACH)
    centre = np.asarray(sup.region.centroid.coords[0])
    centre3 = s.origin + centre[0] * s.u + centre[1] * s.v
    best = None
    for name, pts in st.world_pieces(sup.owner):
        if name == sup.part:
            continue
        h = (pts - s.origin) @ n_up
        if float(h.max()) < 0.5 * height or float(h.min()) > 0.05:
            continue  # not rising from the ledge to hold the child up
        foot = pts[h <= float(h.min()) + 0.02]
        if not ledge.intersects(shapely.MultiPoint(plane_coords(s, foot)).convex_hull):
            continue
        c = pts.mean(axis=0)
        _, sv, vt = np.linalg.svd(pts - c, full_matrices=False)
        if sv[2] > 0.2 * sv[1]:
            continue  # not a flat board
        n = vt[2] / np.linalg.norm(vt[2])
        if (centre3 - c) @ n < 0:
            n = -n  # the face toward the ledge
        tilt = float(np.degrees(np.arccos(np.clip(abs(n @ n_up), -1, 1))))
        tilt = 90.0 - tilt  # the board's tilt from vertical
        if not (LEAN_RANGE_DEG[0] <= tilt <= LEAN_RANGE_DEG[1]) or n @ n_up < 0:
            continue
        off = float(np.max(pts @ n))
        rise = float(h.max())
        if best is None or rise > best[0]:
            best = (rise, name, n, off)
    return None if best is None else best[1:]


def _lean_rotation(asset: Asset, n: np.ndarray, up: np.ndarray, portrait: bool | None):
    """Rotation taking the asset's thinnest axis (its positive side) to ``n`` and its longer
    (``portrait``) or shorter in-plane axis to the board's up direction; also returns the
    label of the child's surface that then faces down. ``portrait`` None: a flat child
    standing on its front edge, its back up and its bottom on the board, as a flat leaner
    stands (:func:`parse3d.measure.reach.stands_to_lean`)."""
    ext = np.ptp(asset_geometry(asset).hull, axis=0)
    order = np.argsort(ext)
    thin, mid, long_ = (int(k) for k in order)
    if portrait is None:
        thin, a_up, a_along, sign = 2, 1, 0, -1.0
    else:
        a_up, a_along = (long_, mid) if portrait else (mid, long_)
        sign = 1.0
    d_up = up - (up @ n) * n
    d_up /= np.linalg.norm(d_up)
    R = np.zeros((3, 3))
    R[:, thin] = n
    R[:, a_up] = sign * d_up
    R[:, a_along] = np.cross(d_up, n)
    if np.linalg.det(R) < 0:
        R[:, a_along] *= -1
    return R, _LABELS[a_up][0 if sign > 0 else 1]


def place_leaning(st: SolveState, oid: str, asset: Asset, scale: float, sup: Support,
                  edge: Edge, others: list[Edge], body: Body, rng: np.random.Generator,
                  validate) -> tuple:
    """Stand the thin child on its lower edge on ``sup``, leaning back on the owner's board
    behind it. ``validate(cand, sup)`` returns ``(ok, why, checks)`` as the solver's relation
    checks do. Returns ``((R, t, sup, body, rests_on), trials, checks, None)`` like the
    solver's other placements; raises ``Fail`` when no pose holds."""
    s = sup.surface
    hull = asset_geometry(asset).hull * scale
    ext = np.sort(np.ptp(hull, axis=0))
    back = _backing(st, sup, 0.5 * ext[2])
    if back is None and (board := _board_itself(st, sup)) is not None:
        return _lean_on_board(st, oid, asset, scale, sup, others, body, rng, validate, board)
    if back is None:
        raise Fail(f"no free space on {sup.name}: {oid} does not fit lying flat, and "
                   f"{sup.owner} has no board behind the ledge to lean it on", intrinsic=True)
    part, n, off = back
    last = "no position along the ledge"
    trials = 0
    # a flat child the writer leans by its face stands on its front edge, as the checks read it
    stood = stands_to_lean(asset, st.pag, oid)
    for portrait in ((None,) if stood else (True, False)):
        R, rests = _lean_rotation(asset, n, s.normal, portrait)
        Y = hull @ R.T
        c = float(n @ s.normal)
        # two conditions fix the offsets along n and up: the face 1 mm (plus EPS) off the
        # board, the lower edge EPS above the ledge
        a_need = off + EPS + 1e-3 - float(np.min(Y @ n))
        b_need = float(s.origin @ s.normal) + EPS - float(np.min(Y @ s.normal))
        M = np.array([[1.0, c], [c, 1.0]])
        alpha, beta = np.linalg.solve(M, [a_need, b_need])
        along = np.cross(s.normal, n)
        along /= np.linalg.norm(along)
        base = alpha * n + beta * s.normal
        # the range along the ledge where the child stays on it
        uv = shapely.get_coordinates(sup.region)
        ledge3 = s.origin + uv[:, :1] * s.u + uv[:, 1:] * s.v
        lo, hi = float(np.min(ledge3 @ along)), float(np.max(ledge3 @ along))
        ylo, yhi = float(np.min(Y @ along)), float(np.max(Y @ along))
        room = (hi - lo) - (yhi - ylo)
        if room < 0:
            last = f"{oid} standing is wider than {sup.name}"
            continue
        mid = 0.5 * (lo + hi) - 0.5 * (ylo + yhi)
        cur = float(base @ along)
        for k in range(LEAN_TRIALS):
            trials += 1
            g = mid + (0.0 if k == 0 else rng.uniform(-0.4, 0.4) * room)
            t = base + (g - cur) * along
            foot = lower_edge(s, Y + t).mean(axis=0)
            if not sup.region.buffer(1e-4).contains(shapely.Point(foot)):
                last = f"its lower edge would miss {sup.name} in front of {sup.owner}:{part}"
                continue
            checks, last = accept(st, oid, asset, scale, R, t, rests, sup, body, validate)
            if checks is not None:
                return (R, t, sup, body, rests), trials, checks, None
    raise Fail(f"no valid pose standing on {sup.name} against {sup.owner}:{part} "
               f"({trials} trials, last: {last})")


def lower_edge(s, Y: np.ndarray) -> np.ndarray:
    """The points of ``Y`` (world) within 3 mm of its lowest along the normal of surface ``s``,
    in ``s``'s plane coordinates: the edge a leaning child stands on."""
    h = (Y - s.origin) @ s.normal
    return plane_coords(s, Y[h <= h.min() + 3e-3])


def accept(st: SolveState, oid: str, asset: Asset, scale: float, R: np.ndarray, t: np.ndarray,
           rests: str, sup: Support, body: Body, validate) -> tuple[list | None, str]:
    """Check a standing pose (the object resting on ``rests``): ``(checks, "")`` when its
    relations hold (``validate(cand, sup)``) and it collides with nothing (``body`` is moved
    there), else ``(None, why)``."""
    cand = PlacedObject(oid, asset.category, asset, scale, R, t)
    cand.rests_on = rests
    ok, why, checks = validate(cand, sup)
    if not ok:
        return None, why
    body.move(R, t)
    hit = st.world.collides(body)
    if hit is not None:
        return None, f"collides with {hit}"
    return checks, ""


#: Tilt (degrees from vertical) of a thin child leaning on an upright board it is ON, when
#: no ``LEANING_AGAINST`` says it.
BOARD_LEAN_DEG = (8.0, 20.0)


def _board_itself(st: SolveState, sup: Support):
    """``(front normal (3,), top front edge point (3,), width axis (3,), width)`` when the
    support part is itself an upright flat board whose top is narrower than a thin child (a
    piano's music rest): the child leans on its front face, standing on what lies below; None
    otherwise. The front is the face away from the rest of the owner."""
    mine = [pts for name, pts in st.world_pieces(sup.owner) if name == sup.part]
    rest = [pts for name, pts in st.world_pieces(sup.owner) if name != sup.part]
    if not mine or not rest:
        return None
    P = np.vstack(mine)
    c = P.mean(axis=0)
    _, sv, vt = np.linalg.svd(P - c, full_matrices=False)
    if sv[2] > 0.2 * sv[1]:
        return None
    n = vt[2] / np.linalg.norm(vt[2])
    if abs(float(n[2])) > np.sin(np.deg2rad(LEAN_RANGE_DEG[1])):
        return None  # lying, not upright
    Q = np.vstack(rest)
    if (c - 0.5 * (Q.min(axis=0) + Q.max(axis=0))) @ n < 0:
        n = -n  # away from the middle of the rest of the owner
    t = np.cross(_UP, n)
    t /= np.linalg.norm(t)
    h = P[:, 2]
    edge = P[h >= h.max() - 2e-3]
    e = edge[int(np.argmax(edge @ n))]
    a = P @ t
    e = e + (0.5 * float(a.min() + a.max()) - float(e @ t)) * t  # at the middle of its width
    return n, e, t, float(np.ptp(a))


def _lean_on_board(st: SolveState, oid: str, asset: Asset, scale: float, sup: Support,
                   others: list[Edge], body: Body, rng: np.random.Generator, validate,
                   board) -> tuple:
    """Lean the thin child on the support board (on its top front edge or, lower, its face),
    tilted back by the ``LEANING_AGAINST`` range written on that board (else
    :data:`BOARD_LEAN_DEG`), standing on what of the owner lies below in front of it (a
    piano's key bed under its music rest). Returns as :func:`place_leaning`."""
    from .nesting import pieces_drop

    n, edge, t, width = board
    lo, hi = BOARD_LEAN_DEG
    for e in others:
        if e.relation == "LEANING_AGAINST" and e.parent.object == sup.owner:
            lo, hi = (float(x) for x in e.param("angle_deg"))
    parent = st.scene.objects[sup.owner]
    floor = min(float(pts[:, 2].min()) for _, pts in st.world_pieces(sup.owner))
    hull = asset_geometry(asset).hull * scale
    stood = stands_to_lean(asset, st.pag, oid)
    trials, last = 0, "no tilt tried"
    for th in rng.permutation(np.deg2rad(np.linspace(lo, hi, 5))):
        nt = np.cos(th) * n + np.sin(th) * _UP
        for portrait in ((None,) if stood else (True, False)):
            R, rests = _lean_rotation(asset, nt, _UP, portrait)
            Y = hull @ R.T
            span = float(np.ptp(Y @ t))
            room = width - span
            g = 0.0 if room <= 0 else rng.uniform(-0.4, 0.4) * room
            # its lowest point at the edge's height, far enough in front of the board that
            # nothing of it reaches the owner; then dropped onto what is below and slid back
            # onto the board, in turns (its foot settles where it can lean)
            t0 = edge - Y.mean(axis=0) + g * t
            t0 = t0 + (float(edge @ n) + 0.01 - float(np.min((Y + t0) @ n))) * n
            t0[2] += float(edge[2]) + 0.01 - float(np.min((Y + t0)[:, 2]))
            T = np.eye(4)
            T[:3, :3] = R * scale
            reach = float(edge[2]) + 0.01 - floor
            trials += 1
            tt, fell = t0, False
            for _ in range(4):
                T[:3, 3] = tt
                got = _stepped_drop(pieces_drop, asset, T, parent, reach)
                if got >= reach:
                    fell = True
                    break
                tt = tt - max(got - EPS, 0.0) * _UP
                T[:3, 3] = tt
                got = _stepped_drop(pieces_drop, asset, T, parent, 0.3, -n)
                tt = tt - max(got - EPS, 0.0) * n
            if fell:
                last = f"nothing of {sup.owner} below {sup.name} to stand on"
                continue
            T[:3, 3] = tt
            if pieces_drop(asset, T, parent, -_UP, 2e-3, tol=5e-4) >= 2e-3:
                last = f"{oid} does not come to rest leaning on {sup.owner}:{sup.part}"
                continue
            if float(np.max((Y + tt)[:, 2])) < float(edge[2]):
                # its top edge on the board's face would slip in settling: over its top edge
                last = f"{oid} standing there is lower than the top of {sup.owner}:{sup.part}"
                continue
            checks, last = accept(st, oid, asset, scale, R, tt, rests, sup, body, validate)
            if checks is not None:
                return (R, tt, sup, body, rests), trials, checks, None
    raise Fail(f"no valid pose leaning on {sup.owner}:{sup.part} ({trials} trials, last: "
               f"{last})")


def _stepped_drop(pieces_drop, asset: Asset, T: np.ndarray, parent, reach: float,
                  d: np.ndarray = -_UP, step: float = 0.02) -> float:
    """How far the child can move along ``d`` before touching ``parent``, in steps of
    ``step`` metres so that it does not pass through a thin part; ``reach`` when nothing is
    met."""
    done = 0.0
    while done < reach:
        Ts = np.array(T, float)
        Ts[:3, 3] += done * d
        got = pieces_drop(asset, Ts, parent, d, min(step, reach - done), tol=5e-4)
        if got < min(step, reach - done):
            return done + got
        done += step
    return reach


#: Metres between an object's top and a room wall behind it within which a thin child ON the
#: top that cannot stand on its edge leans on the wall (a chest against the wall).
WALL_REACH = 0.15

#: Tilt (degrees from vertical) of a thin child leaning on a room wall from an object's top.
WALL_LEAN_DEG = (10.0, 20.0)


def may_lean_on_wall(st: SolveState, asset: Asset, scale: float, sup: Support,
                     edge: Edge) -> bool:
    """Whether :func:`place_on_wall` applies: ON an object's upward top (no child part or
    other face named), a thin child (its thinnest extent at most ``THIN`` times the next) with
    nothing ON or IN it, a room wall within ``WALL_REACH`` of the top's edge."""
    if edge.relation != "ON" or sup.owner == "room" or edge.child.part is not None \
            or edge.child.surface not in (None, "bottom") or float(sup.surface.normal[2]) < 0.99:
        return False
    if any(e.relation in ("ON", "IN") and e.parent.object == edge.child.object
           for e in st.pag.relations):
        return False  # what rests on it needs it as modelled (a pen on a notebook)
    ext = np.sort(np.ptp(asset_geometry(asset).hull, axis=0) * scale)
    return ext[0] <= THIN * ext[1] and _wall_behind(st, sup) is not None


def _wall_behind(st: SolveState, sup: Support):
    """``(wall name, its normal into the room (3,), its offset along it)`` of the room wall
    nearest the support's edge, within ``WALL_REACH``; None when there is none."""
    s = sup.surface
    uv = shapely.get_coordinates(sup.region)
    pts = s.origin + uv[:, :1] * s.u + uv[:, 1:] * s.v
    best = None
    for name, el in st.scene.room.elements.items():
        if not name.startswith("wall_"):
            continue
        n = np.asarray(el.surface.normal, float)
        if abs(float(n[2])) > 0.1:
            continue
        off = float(el.surface.origin @ n)
        d = float(np.min(pts @ n)) - off
        if not -1e-3 <= d <= WALL_REACH:
            continue
        # the top lies in front of the wall's face, not past its end
        a = (pts - el.surface.origin) @ el.surface.u
        lo, hi = (float(x) for x in el.surface.polygon.bounds[::2])
        if float(a.max()) < lo or float(a.min()) > hi:
            continue
        if best is None or d < best[0]:
            best = (d, name, n, off)
    return None if best is None else best[1:]


def place_on_wall(st: SolveState, oid: str, asset: Asset, scale: float, sup: Support,
                  edge: Edge, others: list[Edge], body: Body, rng: np.random.Generator,
                  validate) -> tuple:
    """Stand a thin child that cannot stand on its edge (a wall picture frame with no easel
    ON a chest of drawers) on its lower edge on the top, its back leaning on the room wall
    behind by ``WALL_LEAN_DEG``. Returns as :func:`place_leaning`; ``Fail`` when no pose
    holds."""
    got = _wall_behind(st, sup)
    if got is None:
        raise Fail(f"no wall behind {sup.name} to lean {oid} on", intrinsic=True)
    wall, nw, off = got
    s = sup.surface
    hull = asset_geometry(asset).hull * scale
    along = np.cross(s.normal, nw)
    along /= np.linalg.norm(along)
    uv = shapely.get_coordinates(sup.region)
    top3 = s.origin + uv[:, :1] * s.u + uv[:, 1:] * s.v
    lo, hi = float(np.min(top3 @ along)), float(np.max(top3 @ along))
    stood = stands_to_lean(asset, st.pag, oid)
    # upright as modelled first (a landscape frame stays landscape)
    turns = (None,) if stood else \
        ((True, False) if int(np.argmax(np.ptp(hull, axis=0))) == 2 else (False, True))
    trials, last = 0, "no tilt tried"
    for th in rng.permutation(np.deg2rad(np.linspace(*WALL_LEAN_DEG, 3))):
        # the child's face plane leans back: its normal tilted up from the wall's
        nt = np.cos(th) * nw + np.sin(th) * s.normal
        for portrait in turns:
            R, rests = _lean_rotation(asset, nt, s.normal, portrait)
            Y = hull @ R.T
            # its back 1 mm (plus EPS) off the wall, its lower edge EPS above the top
            t = (off + EPS + 1e-3 - float(np.min(Y @ nw))) * nw
            t = t + (float(s.origin @ s.normal) + EPS - float(np.min((Y + t) @ s.normal))) \
                * s.normal
            ylo, yhi = float(np.min(Y @ along)), float(np.max(Y @ along))
            room = (hi - lo) - (yhi - ylo)
            if room < 0:
                last = f"{oid} standing is wider than {sup.name}"
                continue
            cur = float(t @ along)
            for k in range(LEAN_TRIALS):
                trials += 1
                g = lo - ylo + (rng.uniform(0.0, 1.0) * room if k else 0.5 * room)
                tt = t + (g - cur) * along
                foot = lower_edge(s, Y + tt)
                if not sup.region.buffer(1e-4).contains(shapely.MultiPoint(foot).convex_hull):
                    last = f"its lower edge would miss {sup.name} in front of {wall}"
                    continue
                checks, last = accept(st, oid, asset, scale, R, tt, rests, sup, body, validate)
                if checks is not None:
                    return (R, tt, sup, body, rests), trials, checks, None
    raise Fail(f"no valid pose standing on {sup.name} leaning on {wall} ({trials} trials, "
               f"last: {last})")
