"""Stage 3 of Algorithm 1: the child's rotation from the part-level normal constraints.

The child's contact surface is turned anti-parallel to the support normal; the angle about the
support normal is then set by each relation's rule (``rotate`` of its
:class:`~parse3d.solver.rules.RelationRule`). A free angle is squared to the room's walls (floor
furniture) unless the object asks for ``"yaw": "free"``.
"""

from __future__ import annotations

import zlib

import numpy as np
import shapely

from ..assets.model import Asset
from ..geometry import regions as RG
from ..geometry.frames import axis_angle, rotation_between
from ..measure.reach import STAND, stands_to_lean
from ..pag.model import Edge
from ..relations import SURFACES
from .bars import opening
from .config import Fail
from .geometry import asset_geometry, outline_indices, part_points
from .rows import like_siblings, row_turns
from .rules import RULES, Orientation, parent_surface_world
from .state import SolveState, angle_to, parts_for, wrap
from .support import Support

__all__ = ["Orientation", "solve_rotation", "parent_surface_world", "HOOK_REACH"]

#: Metres: the furthest out from its support a hung thing's attachment may be drawn when its
#: body, hung right below, would reach into the wall behind (a pot on an S-hook of a rail
#: a few centimetres off the wall; ``hanging.off_wall``). A turn of a hung child that reaches
#: further into a wall than this is not drawn (a coat on a wall hook hangs along the wall).
HOOK_REACH = 0.15


def wall_angles(st: SolveState, R0: np.ndarray, n_s: np.ndarray) -> list[float]:
    """Angles about ``n_s`` that square the child's front to each wall direction (distinct
    modulo 90 degrees), wall_0's first."""
    out: list[float] = []
    for w in st.scene.room.walls:
        a = angle_to(R0 @ np.array([0, 1.0, 0]), w.surface.normal, n_s)
        if a is None:
            continue
        if all(abs(wrap(4 * (a - b))) > np.deg2rad(2.0) for b in out):
            out.append(a)
    return out or [0.0]


def solve_rotation(st: SolveState, oid: str, asset: Asset, sup: Support, support_edge: Edge,
                   edges: list[Edge], rng: np.random.Generator, strategy: str,
                   scale: float = 1.0) -> tuple[np.ndarray, str | None, list]:
    """Rotation of the child; returns ``(R, toward_target, lean)``.

    ``lean`` is ``[(edge, theta, direction)]`` when the child leans (tilt ``theta`` radians
    toward ``direction``), else empty.
    """
    n_s = sup.surface.normal
    R0 = _base_rotation(support_edge.child.surface or support_edge.spec.child_surface, n_s)
    if support_edge.relation == "ON" and stands_to_lean(asset, st.pag, oid):
        R0 = R0 @ STAND  # a flat leaner (a pillow) stands on its front edge
    o = Orientation(R0, n_s)
    if abs(n_s[2]) <= 0.9:  # on a wall: stay upright
        o.phi, o.source = _upright_angle(R0, n_s), "upright"
    if strategy == "constrained":
        for e in edges:
            RULES[e.relation].rotate(st, asset, o, e)
        if o.phi is not None:
            o.toward = None  # fixed by part-level constraints; TOWARD is only checked
    phi = o.phi
    if phi is None and o.toward is None:
        free = st.pag.objects[oid].extra.get("yaw") == "free"
        if strategy == "constrained" and not free and sup.owner == "room":
            # floor furniture stands square to the room's walls
            angles = wall_angles(st, R0, n_s)
            phi = angles[int(rng.integers(len(angles)))] + rng.integers(4) * np.pi / 2
        elif strategy == "constrained" and not free:
            phi = _fitting_angle(st, asset, scale, sup, R0, n_s, rng,
                                 row=like_siblings(st, oid, support_edge), oid=oid)
        else:
            phi = rng.uniform(0, 2 * np.pi)
    R = axis_angle(n_s, phi) @ R0 if phi is not None else R0
    lean = []
    if o.lean is not None:
        e, d = o.lean
        k = np.cross(n_s, d)
        if np.linalg.norm(k) > 1e-6:
            from .leaning import lean_tilt  # a face of finite extent (an object's)
            theta = lean_tilt(st, sup, asset, scale, R, k, d, e, rng,
                              lambda: _lean_angle(asset, scale, R, k, d, e, rng))
            R = axis_angle(k, theta) @ R
            lean = [(e, theta, d)]
    return R, o.toward, lean


_BASE: dict[tuple, np.ndarray] = {}


def _base_rotation(label: str, n_s: np.ndarray) -> np.ndarray:
    """The smallest rotation turning the child's ``label`` surface normal against the support
    normal ``n_s`` (a fresh copy), made once per (label, normal)."""
    n_s = np.asarray(n_s, float)
    key = (label, n_s.tobytes())
    got = _BASE.get(key)
    if got is None:
        if len(_BASE) > 4096:
            _BASE.clear()
        got = _BASE[key] = rotation_between(np.array(SURFACES[label], float), -n_s)
    return got.copy()


def _fitting_angle(st: SolveState, asset: Asset, scale: float, sup: Support, R0: np.ndarray,
                   n_s: np.ndarray, rng: np.random.Generator, row: int = 1,
                   oid: str = "") -> float:
    """A free angle on an object's surface: three times in four square to the support's owner
    (else uniform), preferring the quarter turns whose footprint sits well inside the support
    (a TV along its stand, not across it); a uniform angle is kept only if it fits as well.
    ``row`` like things sharing the part: only the turns that take them all side by side
    (rows.row_turns), when some do and some do not. Something hung below a smaller part drawn
    turned into a wall or the furniture takes the nearest quarter turn that keeps it clear
    (:func:`_in_room`) three times in four, when some do. ``oid`` is the child."""
    s = sup.surface
    owner = st.scene.objects.get(sup.owner)
    ref = owner.rotation[:, 1] if owner is not None and owner.placed else None
    base = angle_to(R0 @ np.array([0, 1.0, 0]), ref, n_s) if ref is not None else None
    if base is None:
        base = wall_angles(st, R0, n_s)[0]
    hull = asset_geometry(asset).hull * scale

    def fit(phi: float) -> float:
        R = axis_angle(n_s, phi) @ R0
        Y = hull @ R.T
        F = RG.convex_outline(np.column_stack([Y @ s.u, Y @ s.v]),
                              outline_indices(asset, R.T @ s.normal))
        return RG.eroded_area(sup.region, F)

    quarter = [base + k * np.pi / 2 for k in range(4)]
    Y0 = hull @ R0.T
    fp_area = float(np.ptp(Y0 @ s.u) * np.ptp(Y0 @ s.v))
    if fp_area < 0.05 * sup.region.area:  # small on a large top: every turn fits
        areas = np.ones(4)
    else:  # a half turn fits (nearly) as well as its opposite: two erosions, not four
        a0, a1 = fit(quarter[0]), fit(quarter[1])
        areas = np.array([a0, a1, a0, a1])
    if sup.spans and (areas.max() <= 0.0 or opening(sup) is not None):
        # no turn fits inside a support joining several parts (a keyboard on a stand's two
        # arms), or it spans a ring round an opening (a tray on a tub's rim, bars.py): the
        # turns whose footprint, centred on it, lies most over the parts (across)
        solid = sup.region.difference(shapely.union_all([shapely.Polygon(h) for h in sup.holes])) \
            if sup.holes else sup.region

        def overlap(phi: float) -> float:
            R = axis_angle(n_s, phi) @ R0
            Y = hull @ R.T
            F = RG.convex_outline(np.column_stack([Y @ s.u, Y @ s.v]),
                                  outline_indices(asset, R.T @ s.normal))
            c = np.asarray(sup.region.centroid.coords)[0] - F.mean(axis=0)
            return float(shapely.Polygon(F + c).intersection(solid).area)

        fit = overlap
        a0, a1 = fit(quarter[0]), fit(quarter[1])
        areas = np.array([a0, a1, a0, a1])
    rows = row_turns(sup.region, [_outline(asset, hull, R0, n_s, s, q) for q in quarter[:2]],
                     row) if row > 1 else None
    keep = rows + rows if rows is not None else [True] * 4
    if rows is not None:  # like things in a row: the turns that take them all (rows.py)
        areas = np.where(keep, areas, -1.0)
    turn = lambda phi: float(phi)  # noqa: E731
    if areas.max() <= 0.0 and float(n_s[2]) < -0.9:  # hung below it
        # wider than its support every way (a coat on a wall hook): when some quarter turns
        # are clear and some not (_in_room), a turn drawn into a wall or the furniture is,
        # three times in four, the nearest clear quarter turn instead (else kept: another
        # ring or hook may take it); decided by a generator of the child's own, so the
        # solve's draws stay as they were
        inside = _in_room(st, oid, asset, scale, sup, R0, n_s)
        clear = [p for p in quarter if inside(p)]
        if 0 < len(clear) < 4:
            own = np.random.default_rng([zlib.crc32(f"{oid} {asset.asset_id}".encode()),
                                         zlib.crc32(sup.name.encode())])

            def turn(phi: float) -> float:
                if inside(phi) or own.random() >= 0.75:
                    return float(phi)
                return float(min(clear, key=lambda p: abs(wrap(p - phi))))
    good = [p for p, a, k in zip(quarter, areas, keep, strict=True)
            if k and a >= 0.7 * areas.max()]
    if rng.random() >= 0.75:
        phi = rng.uniform(0, 2 * np.pi)
        if rows is None and (areas.min() == areas.max() == 1.0 or fit(phi) >= 0.7 * areas.max()):
            return turn(phi)
    return turn(good[int(rng.integers(len(good)))] + rng.normal(0, np.deg2rad(2.0)))


def _in_room(st: SolveState, oid: str, asset: Asset, scale: float, sup: Support,
             R0: np.ndarray, n_s: np.ndarray):
    """Whether (1.0) or not (0.0) the child hung right below ``sup`` by its top (the middle of
    its highest points below the middle of ``sup``), turned by an angle about ``n_s`` from
    ``R0``, keeps its footprint inside the room's floor grown by :data:`HOOK_REACH` and clear of the
    placed objects at its heights (but what holds the support up, and what else hangs from
    its owner: a coat goes over another coat) and of the owner's other parts there (a coat
    tree's pole), as a function of that angle."""
    from .state import support_chain

    floor = st.scene.room.elements["floor"].surface
    room = shapely.Polygon(floor.to_3d(np.asarray(floor.polygon.exterior.coords))[:, :2])
    room = room.buffer(HOOK_REACH, join_style="mitre")
    hull = asset_geometry(asset).hull * scale
    s = sup.surface
    at = s.to_3d(np.asarray(sup.region.centroid.coords))[0]
    height = float(np.ptp(hull @ R0.T @ n_s))
    lo, hi = float(at[2]) - height, float(at[2])
    skip = support_chain(st.pag, sup.owner) | {oid} | {
        o for o in st.pag.objects if (e := st.pag.supporter(o)) is not None
        and e.parent.object == sup.owner}
    near = [shapely.Polygon(xy) for o, xy in st.xy.items()
            if o not in skip and o in st.zr and st.zr[o][0] < hi and st.zr[o][1] > lo]
    # the owner's other parts below the support (a coat tree's pole, its other hooks): what
    # hangs at their depth keeps clear of them
    own = [] if sup.owner not in st.xy else [
        (float(d.min()), float(d.max()), shapely.MultiPoint(pts[:, :2]).convex_hull)
        for name, pts in st.world_pieces(sup.owner) if name != sup.part
        and float((d := (pts - s.origin) @ s.normal).max()) > 1e-3 and float(d.min()) < height]

    def inside(phi: float) -> float:
        Y = hull @ (axis_angle(n_s, phi) @ R0).T
        hN = Y @ s.normal
        top = Y[hN <= hN.min() + 2e-3, :2].mean(axis=0)  # hung by its top, as it is placed
        xy, depth = Y[:, :2] - top + at[:2], hN - hN.min()
        F = shapely.MultiPoint(xy).convex_hull
        if not room.contains(F) or any(F.intersects(p) for p in near):
            return 0.0
        for d0, d1, fp in own:
            m = (depth >= d0 - 1e-3) & (depth <= d1 + 1e-3)
            if m.sum() >= 3 and shapely.MultiPoint(xy[m]).convex_hull.intersects(fp):
                return 0.0
        return 1.0

    return inside


def _outline(asset: Asset, hull: np.ndarray, R0: np.ndarray, n_s: np.ndarray, s,
             phi: float) -> np.ndarray:
    """The child's footprint in the plane coordinates of ``s``, turned ``phi`` about ``n_s``."""
    R = axis_angle(n_s, phi) @ R0
    Y = hull @ R.T
    return RG.convex_outline(np.column_stack([Y @ s.u, Y @ s.v]),
                             outline_indices(asset, R.T @ s.normal))


def _lean_angle(asset: Asset, scale: float, R: np.ndarray, k: np.ndarray, d: np.ndarray, e: Edge,
                rng: np.random.Generator) -> float:
    """A tilt in ``angle_deg`` at which the named child part is the object's extreme toward
    the parent (so the named part, not another, touches it); Fail when none is."""
    lo, hi = e.param("angle_deg")
    if e.child.part is None:
        return _pressing(asset, scale, R, k, d, list(np.deg2rad(np.linspace(lo, hi, 25))), rng)
    parts = parts_for(asset, e.child)
    if not parts:
        raise Fail(f"LEANING_AGAINST {e.child} -> {e.parent}: {asset.asset_id} has no part "
                   f"{e.child.part!r}")
    hull = asset_geometry(asset).hull
    mine = part_points(parts)
    others = [p for p in asset.parts if p not in parts]
    grid = np.deg2rad(np.linspace(lo, hi, 25))
    ok, worst = [], (0.0, None)
    scale_free = max(float(np.ptp(hull, axis=0).max()), 1e-6)
    for th in grid:
        Rt = axis_angle(k, th) @ R
        reach_part = float(np.max(mine @ Rt.T @ d))
        reach_all = float(np.max(hull @ Rt.T @ d))
        if reach_all - reach_part <= 1e-3 * scale_free:
            ok.append(th)
        elif reach_all - reach_part > worst[0]:
            best = max(others, key=lambda p: float(np.max(part_points([p]) @ Rt.T @ d)),
                       default=None)
            worst = (reach_all - reach_part, best)
    if ok:  # Fail when gravity would stand it up off the parent (solver/leaning.py)
        from .leaning import pressed
        return pressed(asset, scale, R, k, d, ok, rng, e)
    # the largest tilt at which it would work, for the message
    fit = [t for t in np.deg2rad(np.linspace(0.0, 45.0, 91))
           if float(np.max(hull @ (axis_angle(k, t) @ R).T @ d))
           - float(np.max(mine @ (axis_angle(k, t) @ R).T @ d)) <= 1e-3 * scale_free]
    other = worst[1].name if worst[1] is not None else "another part"
    lean_any = f"name {e.child.object}@{e.child.surface or 'back'} to lean on any part"
    hint = (f"{e.child.part} could touch only at tilts up to {np.rad2deg(max(fit)):.0f} deg, "
            f"or {lean_any}" if fit else lean_any)
    raise Fail(f"LEANING_AGAINST {e.child} -> {e.parent}: at every tilt in {lo:g}-{hi:g} deg "
               f"{e.child.object}:{other} reaches up to {worst[0] * scale:.2f} m further "
               f"toward {e.parent} than {e.child.part} ({hint})", intrinsic=True)


#: Metres the centre of mass of a leaning object must lie beyond the edge of its base it pivots
#: on, toward what it leans on, so that gravity keeps it pressed there.
LEAN_MARGIN = 0.004


def _pressing(asset: Asset, scale: float, R: np.ndarray, k: np.ndarray, d: np.ndarray,
              tilts: list[float], rng: np.random.Generator, *,
              margin: float = LEAN_MARGIN) -> float:
    """One of ``tilts`` (radians about ``k``) at which gravity presses the object toward ``d``
    (its parent): its centre of mass lies at least ``margin`` (metres) beyond its lowest points
    (the base edge it pivots on) along ``d``. A random one of those; when none, the tilt that
    comes closest (a flat-bottomed guitar with a low centre of mass at a small tilt would stand
    up off the wall in settling)."""
    g = asset_geometry(asset)
    hull, com = g.hull * scale, g.com * scale
    margins = []
    for th in tilts:
        Rt = axis_angle(k, th) @ R
        Y = hull @ Rt.T
        base = Y[Y[:, 2] <= Y[:, 2].min() + 2e-3]
        margins.append(float((Rt @ com) @ d - np.max(base @ d)))
    good = [t for t, m in zip(tilts, margins, strict=True) if m >= margin]
    if good:
        return float(good[int(rng.integers(len(good)))])
    return float(tilts[int(np.argmax(margins))])


def _upright_angle(R0: np.ndarray, n: np.ndarray) -> float:
    """Angle about ``n`` that turns ``R0 @ ez`` as close as possible to world +Z."""
    v = R0[:, 2]
    z = np.array([0.0, 0.0, 1.0])
    pv = v - np.dot(v, n) * n
    pz = z - np.dot(z, n) * n
    if np.linalg.norm(pv) < 1e-6 or np.linalg.norm(pz) < 1e-6:
        return 0.0
    pv /= np.linalg.norm(pv)
    pz /= np.linalg.norm(pz)
    return float(np.arctan2(np.dot(np.cross(pv, pz), n), np.dot(pv, pz)))
