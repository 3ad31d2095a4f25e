"""Stages 4 to 6 of Algorithm 1 for one support: the region the child's origin may take and the
order its positions are drawn in (free space, low parts stood on, round things in the middle,
room left for what comes beside), and the tests a drawn pose must pass (a base over a small
support, a turn to face a target)."""

from __future__ import annotations

import numpy as np
import shapely
from shapely.geometry import Polygon

from ..assets.model import Asset
from ..geometry import regions as RG
from ..geometry.frames import axis_angle
from ..measure.checks import EPS, covering_thickness, world_points
from ..pag.model import Edge
from ..scene.model import PlacedObject
from .choice import touching
from .config import Fail
from .geometry import asset_geometry, hull_extents, part_points, rect_sides
from .hanging import hung_size
from .regions import apply_region_rules, obstacles, steps_on
from .rules import RULES, RegionContext, parent_frame, side_vector
from .state import SolveState, angle_to, frame_key, plane_coords, plane_key
from .support import BAR_WIDTH, Support

__all__ = ["THIN_LOW", "HANGS_OFF", "region_context", "rules_region", "owner_pieces",
           "round_asset", "middle_first", "inset", "reach_box", "step_height", "step_under",
           "hung_siblings", "from_one_end", "leave_room", "base_supported", "never_upright",
           "resting_part", "low_parts", "covered_centres", "step_centres", "TIPPY",
           "free_positions", "inside_margin", "ROLLER_RATIO", "ROLL_EDGE", "is_roller",
           "footprint_widths", "well_inside", "face_target", "no_space", "floor_covering",
           "covering_region", "across_low_parts", "toward_relaxed", "layout_miss"]


#: Metres up to which low parts under a child's base (a box's tape, a label) need not hold
#: its centre of mass: resting across them it tilts by under a degree, not into a gap.
THIN_LOW = 3e-3


#: Why an overhanging child's pose fails when its base is not held.
HANGS_OFF = ("a foot or the base would hang off the support (centre of mass outside what rests "
             "on it)")


def region_context(st: SolveState, oid: str, asset: Asset, scale: float, R: np.ndarray,
                   h: float, sup: Support) -> RegionContext:
    """The posed child the region rules clip for (its bbox centre's offset from its origin)."""
    s = sup.surface
    c3 = (asset_geometry(asset).center * scale) @ R.T
    return RegionContext(st, oid, asset, scale, R, h, sup, np.array([c3 @ s.u, c3 @ s.v]),
                         c3 + h * s.normal)


def rules_region(st: SolveState, oid: str, asset: Asset, scale: float, R: np.ndarray,
                 h: float, sup: Support, support_edge: Edge, others: list[Edge], region0,
                 F: np.ndarray, holes: list[np.ndarray]):
    """The positions the child's relations allow on this support whatever stands on it; Fail
    when there are none.

    The region rules (and SECURED_TO's height band) are applied to the support eroded by the
    footprint alone, before the obstacles are gathered and the support is eroded by them (the
    costly part of a region). The rules clip, so a region they empty here stays empty with
    obstacles: a cabinet NEAR another and AGAINST a wall far from it fails that wall at once,
    with the rule's message about the free support. The region less the obstacles' grown
    footprints is the region ``_place_on`` builds, as a set (positions may be drawn from it
    without building it: :func:`RG.draw_outside`).

    None where this does not apply: no rule (nor height band), hanging children and supports
    too small for the footprint (overhanging children), whose regions are built otherwise
    (stacks are not asked). TOWARD, which keeps a region its cones miss, leaves the region as
    it finds it here; positions drawn from the result are still positions of the built region
    (when the obstacles leave its cones nothing, nothing is drawn and the region is built),
    but a rule emptying it is no proof."""
    rel = support_edge.relation
    rule = RULES[rel]
    if rule.hangs or (
            not rule.banded and all(RULES[e.relation].region_phase == "none" for e in others)):
        return None
    free = RG.erode(region0, holes, F)
    if free.is_empty or free.area < 1e-10:
        return None  # too small even when empty: _place_on says why (or overhangs)
    ctx = region_context(st, oid, asset, scale, R, h, sup)
    try:
        free = apply_region_rules(ctx, others, free, "object")
        free = rule.band(ctx, support_edge, free)
        return apply_region_rules(ctx, others, free, "part")
    except Fail:
        if any(e.relation == "TOWARD" for e in others):
            # TOWARD keeps a region its cones miss, so with obstacles a later rule may still
            # find room: only the region built with them can tell
            return None
        raise


def owner_pieces(st: SolveState, sup: Support, exclude: set[str], height: float):
    """``(lowest, highest, footprint)`` of the pieces of the supporting objects (``exclude``)
    other than the support part, in the slab of ``height`` beyond the support plane (heights
    along its normal, footprint in its plane coordinates)."""
    s = sup.surface
    for oid in sorted(exclude):
        if oid == "room":
            continue
        # kept per object pose and support plane: every child hung or mounted asks again
        kept = st.memo(oid, ("pieces in", frame_key(s)), lambda oid=oid: _pieces_in(st, oid, s))
        for k, (name, lo, hi, fp) in enumerate(kept):
            if oid == sup.owner and name == sup.part:
                continue
            if hi <= 1e-3 or lo >= height - 1e-3:
                continue
            if fp is None:
                fp = RG.convex_footprint(plane_coords(s, st.world_pieces(oid)[k][1]))
                fp.setflags(write=False)
                kept[k] = (name, lo, hi, fp)
            yield lo, hi, fp


def _pieces_in(st: SolveState, oid: str, s) -> list:
    """``[(part name, lowest, highest, None)]`` of ``oid``'s pieces along ``s``'s normal, in
    the order of :meth:`SolveState.world_pieces` (:func:`owner_pieces` fills in each one's
    footprint the first time it is asked for)."""
    out = []
    for name, pts in st.world_pieces(oid):
        hq = (pts - s.origin) @ s.normal
        out.append((name, float(hq.min()), float(hq.max()), None))
    return out


def round_asset(asset: Asset) -> bool:
    """About as wide as deep and tall (as :func:`parse3d.measure.is_round`): it rolls."""
    ext = hull_extents(asset)[0]
    return float(ext.max()) <= 1.3 * float(ext.min())


def middle_first(samples: np.ndarray, region0, F: np.ndarray, asset: Asset, scale: float,
                 R: np.ndarray, s) -> np.ndarray:
    """Samples for a round child IN a container, nearest the middle of its floor first, led
    by the middle itself (its centre of mass over it) when the footprint fits there: an apple
    dropped off-centre on a bowl's curved floor rolls to the middle in settling and can tip a
    footed bowl over."""
    c3 = (asset_geometry(asset).com * scale) @ R.T  # its centre of mass over the middle
    mid = np.asarray(region0.centroid.coords[0]) - np.array([c3 @ s.u, c3 @ s.v])
    order = np.argsort(np.linalg.norm(samples - mid, axis=1), kind="stable")
    out = samples[order]
    if region0.contains(Polygon(F + mid)):
        out = np.vstack([mid[None], out])[:len(samples)]
    return out


def inset(sup: Support, margin: float, walled: bool = False):
    """The support's region less a margin: objects keep ``margin`` from an object support's
    edge, and a hair's breadth (less than the contact gap EPS) from a room element's corners
    or a channel's walls (``walled``: bounded by walls in the collision world)."""
    edge = EPS / 2 if sup.owner == "room" or walled else margin
    region0 = sup.region.buffer(-edge, join_style="mitre")
    return sup.region if region0.is_empty else region0  # tiny supports (a burner): see overhang


def floor_covering(st: SolveState, sup: Support) -> bool:
    """Whether ``sup`` faces up on a floor covering (a rug, a mat: a thin flat object lying
    on the floor, :func:`parse3d.measure.checks.covering_thickness`)."""
    floor = st.scene.room.elements.get("floor")
    if sup.owner == "room" or sup.owner not in st.zr or floor is None \
            or float(sup.surface.normal[2]) < 0.99:
        return False
    lo, hi = st.zr[sup.owner]
    narrow = rect_sides(Polygon(st.xy[sup.owner]))[0]
    return covering_thickness(lo, hi, narrow, float(floor.surface.origin[2])) > 0


def covering_region(st: SolveState, sup: Support, region0, F: np.ndarray):
    """The region a child with footprint ``F`` (plane coordinates about its origin) may take
    ON a floor covering: ``region0`` grown by 0.8 of the footprint's narrower extent (a fifth
    of the child at least stays over the covering) and clipped to the floor, where the rest
    stands (chairs pulled up to a table on a rug, its ends past the rug's edge); None when
    ``sup`` is no floor covering or the child fits on it. Tried only when no pose is found on
    the covering itself, so what fits stands wholly on it."""
    if not floor_covering(st, sup):
        return None
    reach = 0.8 * float(np.min(np.ptp(F, axis=0)))
    room = st.scene.room.elements["floor"].surface
    floor = Polygon(plane_coords(sup.surface, room.to_3d(np.asarray(
        room.polygon.exterior.coords)))).buffer(-EPS / 2, join_style="mitre")
    grown = region0.buffer(reach, join_style="mitre").intersection(floor)
    return None if grown.is_empty or grown.area <= region0.area else grown


def reach_box(region, F: np.ndarray, pad: float) -> tuple[float, float, float, float]:
    """The box of obstacles that :func:`RG.erode` can meet, eroding ``region``'s bounding box
    padded by ``pad`` (as :func:`RG.bounding_square` does) by the footprint ``F``."""
    x0, y0, x1, y1 = region.bounds
    lo, hi = F.min(axis=0), F.max(axis=0)
    return (x0 - pad + lo[0], y0 - pad + lo[1], x1 + pad + hi[0], y1 + pad + hi[1])


def step_height(st: SolveState, sup: Support, step: float) -> float:
    """Height above ``sup`` of the highest piece of its owner rising at most ``step`` above it
    (0 when none)."""
    n = sup.surface.normal
    out = 0.0
    for _, pts in st.world_pieces(sup.owner):
        h = float(np.max((pts - sup.surface.origin) @ n))
        if 1e-3 < h <= step and steps_on(sup, plane_coords(sup.surface, pts)):
            out = max(out, h)
    return out


def step_under(st: SolveState, sup: Support, pts: np.ndarray, step: float) -> float:
    """How far to raise a child with world points ``pts`` so that its base (points within
    3 mm of its lowest) clears the owner's low parts (rising at most ``step``) under it."""
    n = sup.surface.normal
    h = (pts - sup.surface.origin) @ n
    base = pts[h <= h.min() + 3e-3]
    foot = Polygon(RG.convex_footprint(plane_coords(sup.surface, base))).buffer(1e-4)
    need = float(h.min())
    for top, piece in _low_pieces(st, sup, step):
        if foot.intersects(piece):
            need = max(need, top + EPS)
    return need - float(h.min())


def _low_pieces(st: SolveState, sup: Support, step: float) -> list[tuple[float, Polygon]]:
    """``(height of its top, footprint)`` (plane coordinates) of each piece of the owner that
    rises at most ``step`` above ``sup`` and is stood on (a burner of a cooktop); kept while
    the owner keeps its pose."""
    def make():
        n, out = sup.surface.normal, []
        for _, q in st.world_pieces(sup.owner):
            hq = (q - sup.surface.origin) @ n
            if 1e-3 < float(hq.max()) <= step and float(hq.min()) > -step:
                fp = plane_coords(sup.surface, q)
                if steps_on(sup, fp):
                    out.append((float(hq.max()), Polygon(RG.convex_footprint(fp))))
        return out
    return st.memo(sup.owner, ("low pieces", plane_key(sup.surface), step), make)


def hung_siblings(st: SolveState, oid: str, edge: Edge) -> bool:
    """Whether objects still to be placed hang below the same object as ``oid``."""
    if edge.parent.is_room_element:
        return False
    return any(e.relation == "HANGING_BELOW" and e.parent.object == edge.parent.object
               and e.child.object != oid and e.child.object not in st.xy
               for e in touching(st.pag, edge.parent.object))


def from_one_end(samples: np.ndarray, region0) -> np.ndarray:
    """Samples ordered along the support's longest direction, from one end: what hangs on a
    rail with more to come goes beside the last one, not in the middle."""
    pts = np.asarray(shapely.get_coordinates(region0), float)
    if len(pts) < 3:
        return samples
    d = pts - pts.mean(axis=0)
    axis = np.linalg.svd(d, full_matrices=False)[2][0]
    return samples[np.argsort(samples @ axis, kind="stable")]


def leave_room(st: SolveState, oid: str, sup: Support, R: np.ndarray, F: np.ndarray,
               region0, samples: np.ndarray) -> np.ndarray:
    """Samples reordered so that those leaving room on the support for the objects still to be
    placed beside this one (``SIDE_OF`` / ``ALONG`` it, on the same support) come first: a
    stove with a counter to its right is not pushed into the corner. The room wanted on a side
    is the smallest size of the dependent's categories; for a unit against a wall with others
    ``ALONG`` it on the floor (a row), where no sample leaves it all, those leaving the most
    come first; the order is otherwise kept."""
    pag, s = st.pag, sup.surface
    owner = sup.owner if sup.owner != "room" else None

    def beside(o: str):
        """Edges of unplaced objects beside ``o`` on the same support."""
        for e in touching(pag, o):
            if e.relation not in ("SIDE_OF", "ALONG") or e.parent.object != o:
                continue
            kid = e.child.object
            if kid in st.scene.objects and st.scene.objects[kid].placed:
                continue
            ke = pag.supporter(kid)
            if ke is not None and (None if ke.parent.is_room_element else ke.parent.object) \
                    == owner:
                yield e

    def need(kid: str, seen: frozenset) -> float:
        """The dependent's smallest size, plus the room its own dependents want (a counter
        right of a stove right of a counter)."""
        from ..assets import registry

        sizes = []
        for c in pag.objects[kid].candidates:
            try:
                sizes.append(registry.get(c).size_range[0])
            except KeyError:
                continue
        more = [need(e.child.object, seen | {kid}) for e in beside(kid)
                if e.child.object not in seen]
        # a hook with a hat to hang: the hat's room (hanging.py)
        return max(min(sizes, default=0.0), hung_size(pag, kid)) + max(more, default=0.0)

    wants: list[tuple[np.ndarray, float]] = []
    strips = False  # an ALONG child: it needs the room right beside the face
    for e in beside(oid):
        d = side_vector(st, e, R)
        g = np.array([d @ s.u, d @ s.v])
        if np.linalg.norm(g) < 1e-6:
            continue
        wants.append((g / np.linalg.norm(g), need(e.child.object, frozenset({oid}))))
        strips |= e.relation == "ALONG"
    if not wants:
        return samples
    edge = np.asarray(region0.exterior.coords) if hasattr(region0, "exterior") else \
        np.vstack([np.asarray(p.exterior.coords) for p in region0.geoms])
    short = np.zeros(len(samples))
    for g, need in wants:
        room = float(np.max(edge @ g)) - (samples @ g + float(np.max(F @ g)))
        short += np.maximum(need - room, 0.0)
    # a unit against a wall with others ALONG it: a row along that wall
    row = strips and owner is None and any(
        x.relation == "AGAINST" and x.parent.is_room_element for x in pag.edges_of(oid))
    if not row:  # those leaving the room first
        ok = short <= 0
        return np.vstack([samples[ok], samples[~ok]])
    # units ALONG one another against a wall: those leaving all the room first; where none does
    # (the sizes are the categories' largest dimensions: a locker's height), those leaving the
    # most (a row of units along a wall starts at one end)
    return samples[np.argsort(short, kind="stable")]


def base_supported(asset: Asset, scale: float, R: np.ndarray, t: np.ndarray, s,
                   solid, upright: bool = False) -> bool:
    """Whether a child hanging over the edge of a small support still stands: the parts of its
    base (those reaching within 3 mm of its lowest point; the feet of a TV, a pot's bottom),
    each as its convex footprint intersected with the ``solid`` support polygon (plane
    coordinates), must together hold its centre of mass 5 mm inside their convex hull. A TV
    whose foot is off a narrow stand fails; a pot on a smaller burner passes. Across the bars
    of a cradle (a spanning support) the base rests on two bars with the centre of mass
    between them. What rests on one bar (narrower than ``BAR_WIDTH``) must lie along it, its
    base on the bar for at least half the child's length: a bottle across one bar, its neck
    over the gap, tips in settling. On a bar narrower than twice the margin the centre of
    mass need only be over it.

    ``upright`` (``ON``): what stands on its base over a small support needs the held part at
    least 30 % as wide as its base is narrow (a cup is not balanced on a tray's 1 cm rim, its
    base over the tray's floor; a kettle on a smaller burner is); no narrow-bar exception."""
    n = s.normal
    low = np.inf
    pieces = []
    for p in asset.parts:
        w = (part_points([p]) * scale) @ R.T + t
        h = (w - s.origin) @ n
        pieces.append((w, h))
        low = min(low, float(h.min()))
    held = []
    for w, h in pieces:
        if float(h.min()) > low + 3e-3:
            continue
        foot = shapely.MultiPoint(plane_coords(s, w[h <= low + 3e-3])).convex_hull
        foot = foot.buffer(1e-3).intersection(solid)
        if not foot.is_empty:
            held.append(foot)
    if not held:
        return False
    com = plane_coords(s, (R @ (asset_geometry(asset).com * scale) + t)[None])[0]
    hull = shapely.union_all(held).convex_hull
    touched = [g for g in getattr(solid, "geoms", [solid]) if g.intersects(hull)]
    if len(touched) == 1 and rect_sides(touched[0])[0] < BAR_WIDTH:
        # resting on one bar (a cradle's, a rail): the child lies along it, its base on it
        # over at least half its length; across it (a bottle's body on the bar, its neck over
        # the gap) it tips
        whole = shapely.MultiPoint(plane_coords(s, np.vstack([w for w, _ in pieces]))).convex_hull
        if rect_sides(hull)[1] < 0.5 * rect_sides(whole)[1]:
            return False
    if upright:
        base = shapely.MultiPoint(plane_coords(s, np.vstack(
            [w[h <= low + 3e-3] for w, h in pieces]))).convex_hull
        if rect_sides(hull)[0] < 0.3 * rect_sides(base)[0]:
            return False
    inner = hull.buffer(-5e-3)
    if inner.is_empty:
        if upright:
            return False
        inner = hull.buffer(1e-6)  # a support narrower than the margin: the centre of mass over it
    return inner.contains(shapely.Point(com))


def never_upright(asset: Asset, scale: float, R: np.ndarray, s, solid) -> bool:
    """Whether :func:`base_supported` with ``upright`` fails wherever the child stands on
    ``solid``: what it holds lies in ``solid``, so its short side is at most the square root
    of the area of any rectangle about ``solid`` (its oriented envelope), which is narrower
    than 30 % of the short side of the child's base (a handbag on a bench's button)."""
    n = s.normal
    pieces = [(w := (part_points([p]) * scale) @ R.T, w @ n) for p in asset.parts]
    low = min(float(h.min()) for _, h in pieces)
    base = shapely.MultiPoint(plane_coords(s, np.vstack(
        [w[h <= low + 3e-3] for w, h in pieces]))).convex_hull
    held = float(np.sqrt(max(solid.minimum_rotated_rectangle.area, 0.0)))
    return held < 0.3 * rect_sides(base)[0] * (1.0 - 1e-6)


def base_centred(asset: Asset, scale: float, R: np.ndarray, s, solid) -> np.ndarray:
    """The position (plane coordinates of the child's origin) that puts the middle of the
    child's base (its points within 3 mm of its lowest, turned by ``R``) over the middle of
    ``solid``: where an overhanging child's feet have the most room."""
    n = s.normal
    w = np.vstack([part_points([p]) for p in asset.parts]) * scale @ R.T
    h = w @ n
    low = w[h <= h.min() + 3e-3]
    base = shapely.MultiPoint(np.c_[low @ s.u, low @ s.v]).convex_hull.centroid
    mid = solid.centroid
    return np.array([mid.x - base.x, mid.y - base.y])


def resting_part(st: SolveState, sup: Support, cand: PlacedObject) -> str | None:
    """The part of ``sup``'s owner that the child rests on: among the owner's pieces under the
    child's base (its points within 3 mm of its lowest), the one whose top is within 3 mm of
    the base; None when none is, or that part has no top surface."""
    s, n = sup.surface, sup.surface.normal
    pts = world_points(cand, hull_only=True)
    h = (pts - s.origin) @ n
    low = float(h.min())
    foot = shapely.MultiPoint(plane_coords(s, pts[h <= low + 3e-3])).convex_hull.buffer(1e-3)
    best, gap = None, 3e-3
    for name, q in st.world_pieces(sup.owner):
        top = float(np.max((q - s.origin) @ n))
        if abs(top - low) <= gap and foot.intersects(
                shapely.MultiPoint(plane_coords(s, q)).convex_hull):
            best, gap = name, abs(top - low)
    owner = st.scene.objects[sup.owner]
    if best is None or "top" not in owner.asset.part(best).surfaces:
        return None
    return best


def low_parts(st: SolveState, sup: Support, step: float, at: float | None = None):
    """The footprints of :func:`_low_pieces` as one geometry (the burners a pot may rest on);
    with ``at`` (metres above ``sup``: the child's base), only those whose top lies within 3 mm
    of it, what the base rests on (a knob on a lid, not the lid around it)."""
    pieces = [p for top, p in _low_pieces(st, sup, step) if at is None or abs(top - at) <= 3e-3]
    return shapely.union_all(pieces) if pieces else Polygon()


def covered_centres(F: np.ndarray, at: np.ndarray, centres: list[np.ndarray]) -> int:
    """How many of ``centres`` (plane coordinates) the footprint ``F`` placed at ``at`` covers
    or comes within 3 cm of."""
    foot = Polygon(F + at).buffer(0.03)
    return sum(foot.contains(shapely.Point(c)) for c in centres)


def step_centres(st: SolveState, sup: Support, step: float) -> list[np.ndarray]:
    """Plane coordinates (2,) of the centres of the owner's parts that rise at most ``step``
    above ``sup`` (the burners of a cooktop)."""
    n = sup.surface.normal
    parts: dict[str, list[np.ndarray]] = {}
    for name, pts in st.world_pieces(sup.owner):
        h = (pts - sup.surface.origin) @ n
        if 1e-3 < float(h.max()) <= step and float(h.min()) > -step:
            parts.setdefault(name, []).append(pts)
    out = []
    for pts in parts.values():
        uv = plane_coords(sup.surface, np.vstack(pts))
        out.append(0.5 * (uv.min(axis=0) + uv.max(axis=0)))
    return out


#: A child taller than this many times its narrowest footprint width is tippy.
TIPPY = 1.5


def free_positions(rel: str, sup: Support, others: list[Edge], region0, obst: list[np.ndarray],
                   F: np.ndarray, height: float, lift: float, rng: np.random.Generator,
                   n: int, walled: bool = False) -> np.ndarray | None:
    """(n, 2) positions drawn from the free space of a plain support (ON or IN, no relation
    clipping the region, no low parts to stand on) without building the region: the region
    ``_place_on`` would build, with a tippy child kept well inside (see :func:`well_inside`);
    None when that region must be built (elsewhere, or when it is empty or small: then its
    construction says why, or finds the few positions left)."""
    if rel not in ("ON", "IN") or lift > 0 \
            or any(RULES[e.relation].region_phase != "none" for e in others):
        return None
    margin = inside_margin(F, height, walled) if rel == "ON" and sup.owner != "room" else 0.0
    return RG.free_samples(region0, obst, F, rng, n, margin=margin)


def inside_margin(F: np.ndarray, height: float, walled: bool = False) -> float:
    """Metres a child's footprint ``F`` keeps inside an object's support: a quarter of its
    narrowest width for a tippy child (a TV on its stand, taller than ``TIPPY`` times that
    width), half of it for a roller (:func:`is_roller`), else 0; 0 between a channel's walls
    (``walled``: the lip holds a marker lying on its round side)."""
    if walled:
        return 0.0
    w = float(min(np.ptp(F[:, 0]), np.ptp(F[:, 1])))
    if height > TIPPY * w:
        return 0.25 * w
    return 0.5 * footprint_widths(F)[0] if is_roller(F, height) else 0.0


#: A child lying with its width and height within this ratio, and its length beyond it, may
#: roll (looser than the checks' ``ROLL_RATIO``: an oval baguette 8 x 6 cm rolls too).
ROLLER_RATIO = 1.5
#: Widths a roller longer than its support keeps its centre of mass from the support's edge
#: (as a shorter one, its footprint half its width inside).
ROLL_EDGE = 1.0


def is_roller(F: np.ndarray, height: float) -> bool:
    """Whether a child with footprint ``F`` and ``height`` lies elongated on a round-ish
    cross-section: nudged near a support's edge (a baguette by an orange) it rolls off."""
    w, L = footprint_widths(F)
    thin, thick = sorted((w, height))
    return thick <= ROLLER_RATIO * thin and ROLLER_RATIO * thick < L


def footprint_widths(F: np.ndarray) -> tuple[float, float]:
    """The narrowest width of footprint ``F`` over directions 2 degrees apart, and its extent
    across that direction (a baguette lying askew is as thin as one lying square)."""
    a = np.deg2rad(np.arange(0.0, 180.0, 2.0))
    d = np.column_stack([np.cos(a), np.sin(a)])
    ext = np.ptp(np.asarray(F, float) @ d.T, axis=0)
    k = int(np.argmin(ext))
    return float(ext[k]), float(ext[(k + 45) % 90])


def _shrunk(region, margin: float):
    """``region`` shrunk by ``margin`` metres, when anything is left."""
    if margin <= 0 or region.area < 1e-10:
        return region
    inner = region.buffer(-margin)
    return inner if not inner.is_empty and inner.area > 1e-10 else region


def well_inside(region, F: np.ndarray, height: float, walled: bool = False):
    """Keep a tippy child's or a roller's base well inside the support: the region shrunk by
    :func:`inside_margin`, when anything is left."""
    return _shrunk(region, inside_margin(F, height, walled))


def face_target(st, toward, R, hull, s, ab, h, drop, others):
    """Turn the child about the support normal to face ``toward`` from position ``ab``: square
    to the nearest side of the target when that keeps TOWARD's tolerance, else at its
    centroid."""
    t0 = s.origin + ab[0] * s.u + ab[1] * s.v + h * s.normal
    target, frame, thull = parent_frame(st, toward)
    front = R @ np.array([0, 1.0, 0])
    want = target - t0
    ang = angle_to(front, want, s.normal)
    if ang is None:
        return R, h
    tol = next((np.deg2rad(e.param("tolerance_deg")) for e in others
                if e.relation == "TOWARD" and e.parent.object == toward), np.deg2rad(10.0))
    if thull is not None:
        # the side of the target facing the child: the target frame axis most aligned with
        # the direction from the target to the child, weighed by the target's half extents
        d = t0 - target
        best = None
        for ax in (frame[:, 0], frame[:, 1]):
            half = max(float(np.ptp(thull @ ax)) / 2, 1e-3)
            score = abs(float(d @ ax)) / half
            if best is None or score > best[0]:
                best = (score, -np.sign(float(d @ ax)) * ax)
        sq = angle_to(front, best[1], s.normal)
        if sq is not None:
            a, b = best[1][:2], want[:2]
            dev = abs(float(np.arctan2(a[0] * b[1] - a[1] * b[0], float(a @ b))))
            if dev <= 0.8 * tol:
                ang = sq
    Rt = axis_angle(s.normal, ang) @ R
    hN2 = (hull @ Rt.T) @ s.normal
    return Rt, -float(hN2.min()) + EPS + drop


def no_space(st: SolveState, sup: Support, F: np.ndarray, region0, obst) -> str:
    """Why the support has no room: too small, or taken (by whom)."""
    fx, fy = np.ptp(F[:, 0]), np.ptp(F[:, 1])
    if RG.erode(region0, [], F).is_empty:
        b = region0.bounds
        return (f"no free space on {sup.name}: a {fx:.2f} x {fy:.2f} m footprint does not fit "
                f"its {b[2] - b[0]:.2f} x {b[3] - b[1]:.2f} m surface")
    there = [o.id for o in st.scene.objects.values()
             if o.placed and o.support_choice is not None and o.support_choice == sup.choice]
    if not there:
        return f"no free space on {sup.name} for a {fx:.2f} x {fy:.2f} m footprint"
    names = ", ".join(there[:4]) + (", ..." if len(there) > 4 else "")
    return (f"no free space on {sup.name} for a {fx:.2f} x {fy:.2f} m footprint: it holds "
            f"{len(there)} objects already ({names})")



def across_low_parts(d, step: float):
    """``(region, obstacles, lift)`` for a child ``d`` (placement's ``_OnSupport``) that finds
    no room between the owner's low parts around its support (a folded napkin longer than a
    plate's well, inside the rim): it lies across them, so they are no obstacles, and ``lift``
    is the height of the highest of them within its reach, above which it is drawn and then
    dropped onto them; only on a support at least as wide as the child (along its length it
    may be longer). Anywhere on the support when it fits there between the other
    obstacles; else, longer than the support, centred on it (within ``ACROSS_CENTRE``), so
    that the low parts on both sides hold it level. None when no such part rises there or no
    position is left."""
    st, sup, region0, F = d.st, d.sup, d.region0, d.F
    s = sup.surface
    if region0.is_empty or rect_sides(region0)[0] < footprint_widths(F)[0]:
        return None  # narrower than the child's width (a tray's lip): nothing to lie across
    reach = float(np.max(np.ptp(F, axis=0)))
    near = region0.buffer(reach)
    lift = 0.0
    for _, pts in st.world_pieces(sup.owner):
        h = (pts - s.origin) @ s.normal
        if not 1e-3 < float(h.max()) <= step:
            continue
        if near.intersects(shapely.MultiPoint(plane_coords(s, pts)).convex_hull):
            lift = max(lift, float(h.max()))
    if lift <= 0:
        return None
    obst = obstacles(st, sup, d.exclude, d.height + EPS, reach_box(region0, F, reach), step=step,
                     across=True)
    holes = list(d.holes)
    region = RG.erode(region0, obst + holes, F)
    if region.is_empty or region.area < 1e-10:
        com = (asset_geometry(d.asset).com * d.scale) @ d.R.T
        c = np.asarray(region0.centroid.coords[0]) - np.array([com @ s.u, com @ s.v])
        region = RG.clip(shapely.Point(float(c[0]), float(c[1])).buffer(ACROSS_CENTRE),
                         RG.erode(RG.bounding_square(region0, pad=reach), obst + holes, F))
    if region.is_empty or region.area < 1e-10:
        return None
    return region, obst, lift


#: Metres from the middle of a support within which a child longer than it, lying across the
#: owner's low parts on both sides (a napkin across a plate's rim), keeps its centre of mass.
ACROSS_CENTRE = 0.01


def toward_relaxed(st: SolveState, oid: str, asset: Asset, scale: float, R: np.ndarray,
                   sup: Support, others: list[Edge], samples: np.ndarray) -> np.ndarray:
    """Samples ordered to come as close as the support allows to what a relaxed layout
    relation of the child asked (left out of ``others``: it could not be met, a marker 0.9 m
    from another in a 0.7 m tray), the order otherwise kept: a ``FAR_FROM`` or ``NEAR`` an
    object farthest from its parent first, or nearest (the distance of the child's centre of
    mass to the parent's origin, in the support's plane); to a wall, by how far the distance
    to its plane misses; a ``SIDE_OF`` or ``ALONG`` by how far (horizontally, m) the centre of
    mass misses the half-plane or the strip the relation asks (:func:`layout_miss`)."""
    if not len(samples):
        return samples
    kept = {id(e) for e in others}
    relaxed = [e for e in st.pag.edges_of(oid)[1:]
               if e.relation in ("FAR_FROM", "NEAR", "SIDE_OF", "ALONG")
               and id(e) not in kept and (e.parent.object in st.scene.room.elements or (
                   e.parent.object in st.scene.objects
                   and st.scene.objects[e.parent.object].placed))]
    if not relaxed:
        return samples
    s = sup.surface
    com = (asset_geometry(asset).com * scale) @ R.T
    at = samples + np.array([com @ s.u, com @ s.v])
    X = s.origin + com @ s.normal * s.normal + at[:, :1] * s.u + at[:, 1:2] * s.v
    key = np.zeros(len(samples))
    for e in relaxed:
        if e.relation in ("FAR_FROM", "NEAR") and not e.parent.is_room_element:
            p = plane_coords(s, st.scene.objects[e.parent.object].position[None])[0]
            dist = np.linalg.norm(at - p, axis=1)
            key += -dist if e.relation == "FAR_FROM" else dist
        else:
            key += layout_miss(st, e, X)
    return samples[np.argsort(key, kind="stable")]


def layout_miss(st: SolveState, e: Edge, X: np.ndarray) -> np.ndarray:
    """(N,) metres by which child centroids ``X`` (N, 3) miss what the layout edge ``e``
    asks, measured as :mod:`parse3d.measure` checks it: ``NEAR`` / ``FAR_FROM`` a wall, the
    distance to its plane beyond (within) ``distance``; ``SIDE_OF``, how far behind the
    parent's centroid along the side's horizontal direction; ``ALONG``, how far outside the
    strip beside the parent's ``side`` face (out from the face up to ``width``, within the
    parent's extent along it). 0 where it is met; 0 everywhere for a parent it cannot read
    (the room itself)."""
    name = e.parent.object
    if e.relation in ("NEAR", "FAR_FROM"):
        if name not in st.scene.room.elements or name == "wall":
            return np.zeros(len(X))
        w = st.scene.room.elements[name].surface
        d = np.abs((X - w.origin) @ w.normal)
        gap = d - e.param("distance")
        return np.maximum(gap, 0.0) if e.relation == "NEAR" else np.maximum(-gap, 0.0)
    if name not in st.scene.objects or name not in st.hulls:
        return np.zeros(len(X))
    xB, frame, hull = parent_frame(st, name)
    n = np.array(side_vector(st, e, frame), float)
    n[2] = 0.0
    if np.linalg.norm(n) < 1e-9:
        return np.zeros(len(X))
    n /= np.linalg.norm(n)
    proj = (X - xB) @ n
    if e.relation == "SIDE_OF":
        return np.maximum(-proj, 0.0)
    hB = float(np.max((hull - xB) @ n))
    perp = np.array([n[1], -n[0], 0.0])
    along = (hull - xB) @ perp
    mid, half = 0.5 * float(along.max() + along.min()), 0.5 * float(np.ptp(along))
    out = proj - hB
    lat = np.abs((X - xB) @ perp - mid)
    return np.maximum(-out, 0.0) + np.maximum(out - e.param("width"), 0.0) \
        + np.maximum(lat - half, 0.0)
