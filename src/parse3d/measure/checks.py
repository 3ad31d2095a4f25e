"""Geometric checks of every relation, measured on posed geometry.

One *check rule* per relation family, registered by relation name in :data:`CHECK_RULES`
(:func:`check_rule`). The solver validates candidate poses with :func:`check_edge`, and the same
rules re-check a scene after solving and after settling (``check_relations(scene,
settled=True)``). Each check returns a :class:`Check`: whether the relation holds, the measured
residuals and a short explanation.

Tolerances (documented in docs/solver.md): contact distance within 2 mm (1 mm below), normal
angles within 2 degrees, heights within 1 cm.
"""

from __future__ import annotations

import operator
from collections.abc import Callable
from dataclasses import dataclass
from types import MappingProxyType
from typing import NamedTuple

import numpy as np

from ..geometry.frames import angle_between
from ..geometry.memo import per_object
from ..geometry.surfaces import Surface, surface_from_bbox
from ..pag.model import Edge
from ..pag.refs import Ref
from ..relations import RELATIONS, SURFACES
from ..scene.model import PlacedObject, RelationCheck, Scene
from .geometry import (
    asset_geometry,
    asset_points,
    drop_distance,
    enclosure_directions,
    exact_drop,
    hull_extents,
    is_round,
    part_points,
    ray_caster,
    side_frame,
)
from .insides import no_room_inside
from .reach import (
    MOUNTED_DEPTH,
    WIDE_LEAN_DEG,
    face_slabs,
    lean_range,
    lean_up,
    mounted_parts,
    nearest_in_prism,
    piece_data,
    pieces_distance,
    standing_label,
    stands_to_lean,
)

__all__ = ["outer_part", "EPS", "DIST_TOL", "PENETRATION_TOL", "ANGLE_TOL_DEG", "COVER_THICK", "COVER_FLAT",
           "covering_thickness", "Check", "CheckContext",
           "CHECK_RULES", "check_rule", "check_edge", "check_relations", "object_centroid",
           "world_points", "select_parts", "end_pads", "END_DEPTH"]

#: Gap left between surfaces in contact when placing (m): FCL then sees no collision.
EPS = 5e-4
#: Largest gap (m) that still counts as contact.
DIST_TOL = 2e-3
#: Deepest penetration (m) that still counts as contact.
PENETRATION_TOL = 1e-3
#: Metres a low part of the parent (a burner on a cooktop; a gas burner's grate rises about
#: 3.5 cm) may raise an ``ON`` child above the named surface: the child rests on the parent's
#: geometry there, and the solver seats it on that part instead of fitting it between them.
STEP = 0.04
#: Largest angle (degrees) between normals that counts as parallel.
ANGLE_TOL_DEG = 2.0
_SIDE = {"front": (0.0, 1.0, 0.0), "back": (0.0, -1.0, 0.0), "right": (1.0, 0.0, 0.0),
         "left": (-1.0, 0.0, 0.0)}


class Check(NamedTuple):
    """The result of checking one relation.

    Attributes
    ----------
    holds : bool
    residual : dict of str to float
        What was measured (``distance`` in m, ``angle_deg``, ``offset``, ``enclosure``, ...).
    detail : str
        One line saying what was measured against what.
    """

    holds: bool
    residual: dict
    detail: str


@dataclass(frozen=True)
class CheckContext:
    """What a check rule sees.

    Attributes
    ----------
    scene : Scene
        The scene the child is checked in (its placed objects and room).
    edge : Edge
        The relation.
    child : PlacedObject
        The child, placed or a candidate pose.
    parent : PlacedObject or None
        The parent object (None for room elements).
    resolved : dict
        The support the solver chose for a support relation (``parent_part``,
        ``parent_element``, ``parent_surface``), empty when unknown.
    settled : bool or None
        Measure the settled poses (True), the solved ones (False) or whichever is newer (None).
    """

    scene: Scene
    edge: Edge
    child: PlacedObject
    parent: PlacedObject | None
    resolved: dict
    settled: bool | None

    def param(self, name: str):
        return self.edge.param(name)


CheckRule = Callable[[CheckContext], Check]
_RULES: dict[str, CheckRule] = {}
#: Relation name -> the rule that checks it (one rule per relation family).
CHECK_RULES: MappingProxyType[str, CheckRule] = MappingProxyType(_RULES)


#: A floor covering (a rug, a mat): a thin flat object lying on the floor, at most
#: ``COVER_THICK`` m thick and ``COVER_FLAT`` of its narrower side. What stands on one may
#: reach past its edge onto the floor, tilted by the covering's thickness across its base.
COVER_THICK, COVER_FLAT = 0.03, 0.05


def covering_thickness(lo: float, hi: float, narrow: float, floor_z: float) -> float:
    """The thickness of an object spanning heights ``lo`` to ``hi`` with narrower horizontal
    side ``narrow`` (m) if it is a floor covering on the floor at ``floor_z``, else 0."""
    thick = hi - lo
    covers = abs(lo - floor_z) <= 0.01 and thick <= min(COVER_THICK, COVER_FLAT * narrow)
    return float(thick) if covers else 0.0


def _base_over(child: PlacedObject, s: Surface, settled) -> bool:
    """Whether the child's base (its points within ``COVER_THICK`` of its lowest, as it
    stands partly on a floor covering and partly on the floor) reaches over the surface
    polygon of ``s``: a child wholly past a rug's edge is not ON it."""
    from shapely.geometry import MultiPoint

    pts = world_points(child, hull_only=True, settled=settled)
    h = pts @ s.normal
    low = pts[h <= h.min() + COVER_THICK] - s.origin
    base = MultiPoint(np.c_[low @ s.u, low @ s.v]).convex_hull
    return any(base.intersects(shell) for shell in _shells(s.polygon))


def _covering_tilt(scene: Scene, child: PlacedObject, pobj: PlacedObject, settled) -> float:
    """Degrees ``child`` may tilt ON ``pobj`` when ``pobj`` is a floor covering: its thickness
    across the child's feet, at least half its narrower base side apart (a chair's legs are set
    in from its seat's edge), one degree more; 0 elsewhere."""
    floor = scene.room.elements.get("floor")
    if floor is None:
        return 0.0
    pts = world_points(pobj, hull_only=True, settled=settled)
    thick = covering_thickness(float(pts[:, 2].min()), float(pts[:, 2].max()),
                               float(np.ptp(pts[:, :2], axis=0).min()),
                               float(floor.surface.origin[2]))
    base = float(np.min((child.asset.bounds[1] - child.asset.bounds[0])[:2])) * child.scale
    return float(np.degrees(np.arctan2(thick, 0.5 * base))) + 1.0 if thick > 0 else 0.0


def check_rule(*names: str) -> Callable[[CheckRule], CheckRule]:
    """Register a check rule for the relations ``names`` (a decorator).

    Raises
    ------
    ValueError
        A name is not in the relation dictionary, or already has a rule.
    """
    def deco(fn: CheckRule) -> CheckRule:
        for n in names:
            if n not in RELATIONS:
                raise ValueError(f"check rule {fn.__name__}: unknown relation {n!r}")
            if n in _RULES:
                raise ValueError(f"relation {n} already has a check rule ({_RULES[n].__name__})")
            _RULES[n] = fn
        return fn
    return deco


# ------------------------------------------------------------------------ geometry helpers
def world_points(obj: PlacedObject, *, hull_only: bool = False, settled: bool | None = None,
                 parts=None) -> np.ndarray:
    """(N, 3) world points of an object (its convex hull, or its parts' piece vertices)."""
    T = obj.transform(settled)
    if hull_only and parts is None:
        pts = asset_geometry(obj.asset).hull
    elif parts is None or (len(parts) == len(obj.asset.parts)
                           and all(map(operator.is_, parts, obj.asset.parts))):
        pts = asset_points(obj.asset)
    else:
        pts = part_points(parts)
    return pts @ T[:3, :3].T + T[:3, 3]


def object_centroid(obj: PlacedObject, settled: bool | None = None) -> np.ndarray:
    """World centre of the object's bounding box."""
    T = obj.transform(settled)
    return T[:3, :3] @ asset_geometry(obj.asset).center + T[:3, 3]


def select_parts(obj: PlacedObject, ref: Ref) -> list:
    """The parts a reference names: all parts without ``:part``, the label's parts in ``#k``
    order (:meth:`parse3d.assets.model.Asset.parts_by_label`), or just the k-th."""
    if ref.part is None:
        return list(obj.asset.parts)
    ps = obj.asset.parts_by_label(ref.part)
    if ref.index is not None:
        ps = ps[ref.index:ref.index + 1]
    return ps


def _surface(scene: Scene, obj: PlacedObject | None, ref: Ref, label: str,
             settled: bool | None, part_name: str | None = None) -> Surface | None:
    """World surface for a reference; None when it cannot be resolved."""
    if ref.is_room_element:
        el = scene.room.elements.get(part_name or ref.object)
        return None if el is None else el.surface
    if obj is None or obj.asset is None:
        return None
    T = obj.transform(settled)
    if part_name is not None:
        try:
            return _world_surface(obj.asset.part(part_name).surfaces[label], T)
        except KeyError:
            return None
    parts = select_parts(obj, ref)
    if not parts:
        return None
    if ref.part is None:
        return surface_from_bbox(label, asset_geometry(obj.asset).bounds).transformed(T)
    return _world_surface(outer_part(parts, label).surfaces[label], T)


def outer_part(parts: list, label: str):
    """The part among ``parts`` (one label's, in ``#k`` order) whose surface ``label`` lies
    furthest out along that surface's normal (asset frame; the first within 1 mm): a
    bookcase's ``side_panel@right`` is the right panel's outer face, not the left panel's
    inner one."""
    if len(parts) == 1:
        return parts[0]
    n = np.array(SURFACES[label], float)
    far = [float(p.surfaces[label].origin @ n) for p in parts]
    top = max(far)
    return next(p for p, f in zip(parts, far, strict=True) if f >= top - 1e-3)


_WORLD: dict[tuple, tuple] = {}


def _world_surface(surf: Surface, T: np.ndarray) -> Surface:
    """``surf.transformed(T)``, made once per (surface object, transform): a parent's surface
    is checked against every candidate placed on it."""
    key = (id(surf), np.asarray(T, float).tobytes())
    got = _WORLD.get(key)
    if got is not None and got[0] is surf:
        return got[1]
    if len(_WORLD) > 8192:
        _WORLD.clear()
    world = surf.transformed(T)
    _WORLD[key] = (surf, world)  # holding the surface keeps its id valid
    return world


def _child_normal(obj: PlacedObject, label: str, settled) -> np.ndarray:
    return obj.transform(settled)[:3, :3] @ np.array(SURFACES[label]) / obj.scale


def _nearest_wall(scene: Scene, p: np.ndarray) -> str:
    """The wall whose inner plane is closest to the point ``p`` (resolves ``wall``)."""
    return min((n for n in scene.room.elements if n.startswith("wall_")),
               key=lambda n: abs(float((p - scene.room.elements[n].surface.origin)
                                       @ scene.room.elements[n].surface.normal)))


def _frame(scene: Scene, name: str, settled, near: np.ndarray | None = None
           ) -> tuple[np.ndarray, np.ndarray]:
    """Centroid and frame (columns: right, front, up) of an object or room element."""
    if name == "wall" and near is not None:
        name = _nearest_wall(scene, near)
    if name in scene.room.elements:
        s = scene.room.elements[name].surface
        up = np.array([0, 0, 1.0]) if abs(s.normal[2]) < 0.9 else np.array([0, 1.0, 0])
        return s.origin, np.c_[np.cross(s.normal, up), s.normal, up]
    o = scene.objects[name]
    R = o.settled_rotation if (settled is not False and o.settled_rotation is not None) else o.rotation
    return object_centroid(o, settled), R


def _plane_dist(pts: np.ndarray, s: Surface) -> np.ndarray:
    return (pts - s.origin) @ s.normal


def _in_polygon(s: Surface, p3: np.ndarray) -> bool:
    from shapely.geometry import Point

    d = p3 - s.origin
    pt = Point(float(d @ s.u), float(d @ s.v))
    return any(shell.distance(pt) <= 1e-3 for shell in _shells(s.polygon))


@per_object(8192)
def _shells(poly) -> list:
    """The pieces of ``poly`` without their holes (an object on a rim spans the hole), made
    once per polygon object."""
    from shapely.geometry import Polygon

    parts = list(poly.geoms) if hasattr(poly, "geoms") else [poly]
    shells = [Polygon(p.exterior) for p in parts if not p.is_empty]
    return shells


def _stands(child: PlacedObject, com: np.ndarray, n: np.ndarray, settled) -> bool:
    """Whether the centre of mass projects inside the convex hull of the child's lowest
    points (its base), along the support normal ``n`` (along the child's own axis nearest
    it, :func:`_own_up`)."""
    from ..geometry.regions import convex_footprint, inside_convex

    # the answer depends only on the normal and the centre of mass in the asset's frame (the
    # base and the point are then fixed up to a rigid motion of the plane): posed by a turn
    # about the normal, every candidate of an asset shares one answer
    T = child.transform(settled)
    M = T[:3, :3]
    n = _own_up(M, n)
    key = (child.asset.asset_id, *(M.T @ n).round(9).tolist(),
           *np.linalg.solve(M, com - T[:3, 3]).round(9).tolist())
    got = _STANDS.get(key)
    if got is not None:
        return got
    pts = asset_points(child.asset) @ M.T + T[:3, 3]
    h = pts @ n
    base = pts[h <= h.min() + 3e-3]
    u = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    hull = convex_footprint(np.c_[base @ u, base @ v])
    # a round child rests on a point (within 2 mm of it); anything else keeps its centre of
    # mass over its base, not beyond its edge (a gooseneck faucet 1 mm past its base tips)
    got = inside_convex(hull, np.array([com @ u, com @ v]),
                        tol=2e-3 if is_round(child) or _lying_axis(child, n, settled) is not None
                        else 0.0)
    if len(_STANDS) > 65536:
        _STANDS.clear()
    _STANDS[key] = got
    return got


_STANDS: dict[tuple, bool] = {}

#: Degrees within which a child's own axis is taken for its support's normal when its base is
#: found: a soft stack settled drooping a degree or two over its support's edge still stands on
#: its bottom face, not on the edge that hangs lowest.
OWN_AXIS_DEG = 10.0


def _own_up(M: np.ndarray, n: np.ndarray) -> np.ndarray:
    """The world direction of the child's own axis (pose rotation and scale ``M``) nearest the
    support normal ``n``, where it lies within ``OWN_AXIS_DEG`` of it; else ``n``."""
    a = M.T @ n
    k = int(np.argmax(np.abs(a)))
    axis = np.zeros(3)
    axis[k] = np.sign(a[k])
    w = M @ axis
    w /= np.linalg.norm(w)
    return w if float(np.degrees(angle_between(w, n))) <= OWN_AXIS_DEG else n


def _enclosure(child: PlacedObject, parent: PlacedObject, settled, floor: Surface | None = None) -> float:
    """Fraction of rays from the child's centroid that hit the parent.

    With the container's ``floor`` (the internal surface the child rests on), the rays start at
    the centroid's x-y but no higher than halfway from that floor up to the parent's top: a cup
    standing on a tray inside its low rim is in the tray although its centre of mass is above
    the rim."""
    T = parent.transform(settled)
    Tinv = np.linalg.inv(T)
    c = object_centroid(child, settled)
    o = Tinv[:3, :3] @ c + Tinv[:3, 3]
    if floor is not None:
        f = Tinv[:3, :3] @ floor.origin + Tinv[:3, 3]
        top = float(asset_geometry(parent.asset).bounds[1, 2])
        o[2] = min(o[2], max(f[2], (f[2] + top) / 2))
    dirs = enclosure_directions() @ Tinv[:3, :3].T
    dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
    hit = ray_caster(parent.asset).any_hits(np.tile(o, (len(dirs), 1)), dirs)
    return float(np.mean(hit))


# ------------------------------------------------------------------- object-level rules
@check_rule("NEAR", "FAR_FROM")
def _check_distance(ctx: CheckContext) -> Check:
    """Horizontal centroid distance (to a wall: distance to its plane) vs ``distance``."""
    e = ctx.edge
    xA = object_centroid(ctx.child, ctx.settled)
    xB, RB = _frame(ctx.scene, e.parent.object, ctx.settled, near=xA)
    if e.parent.is_room_element:
        d = abs(float((xA - xB) @ RB[:, 1]))
    else:
        d = float(np.linalg.norm((xA - xB)[:2]))
    lim = ctx.param("distance")
    ok = d <= lim + 1e-6 if e.relation == "NEAR" else d >= lim - 1e-6
    return Check(ok, {"distance": round(d, 5)}, f"centroid distance {d:.3f} m vs {lim} m")


@check_rule("TOWARD")
def _check_toward(ctx: CheckContext) -> Check:
    """Horizontal angle between the child's front and the direction to the parent."""
    xA = object_centroid(ctx.child, ctx.settled)
    xB, _ = _frame(ctx.scene, ctx.edge.parent.object, ctx.settled, near=xA)
    R = ctx.child.transform(ctx.settled)[:3, :3] / ctx.child.scale
    f = (R @ np.array([0, 1.0, 0]))[:2]
    to = (xB - xA)[:2]
    ang = float(np.degrees(angle_between(np.r_[f, 0], np.r_[to, 0]))) \
        if np.linalg.norm(to) > 1e-6 else 0.0
    return Check(ang <= ctx.param("tolerance_deg") + 1e-6, {"angle_deg": round(ang, 3)},
                 f"facing off by {ang:.1f} deg")


def _side_offset(ctx: CheckContext) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """Child centroid, parent centroid, horizontal unit n_side (the parent's frame, or the
    camera's) and the offset along it."""
    xA = object_centroid(ctx.child, ctx.settled)
    xB, RB = _frame(ctx.scene, ctx.edge.parent.object, ctx.settled, near=xA)
    if ctx.param("frame") == "camera":  # as seen from the PAG's viewpoint
        pag = ctx.scene.pag
        n = np.array(pag.viewpoint.side_direction(pag.room, ctx.param("side")))
    else:
        parent = ctx.scene.objects.get(ctx.edge.parent.object)
        RB = RB if parent is None else side_frame(parent, RB)  # a record on edge: along its row
        n = RB @ np.array(_SIDE[ctx.param("side")])
    n[2] = 0
    n /= max(np.linalg.norm(n), 1e-9)
    return xA, xB, n, float((xA - xB) @ n)


@check_rule("SIDE_OF")
def _check_side_of(ctx: CheckContext) -> Check:
    """(x_A - x_B) . n_side > 0."""
    _, _, _, proj = _side_offset(ctx)
    side = ctx.param("side")
    return Check(proj > 0, {"offset": round(proj, 5)}, f"offset {proj:.3f} m toward {side}")


@check_rule("ALONG")
def _check_along(ctx: CheckContext) -> Check:
    """The child's centroid lies beside the parent's ``side`` face, at most ``width`` out from
    it or with the gap between that face and the child's near face at most ``width`` (a dryer
    5 cm along a washer), and within the parent's extent along the face,
    ``|(x_A - x_B) . n_side^perp| <= e / 2`` (both horizontal; e the parent's extent along
    n_side^perp), or with the face's middle within the child's own extent along it (a bed
    beside a nightstand)."""
    xA, xB, n, proj = _side_offset(ctx)
    pts = _parent_outline(ctx, xA)
    hB = float(np.max((pts - xB) @ n))  # the face: the parent's extreme along n_side
    perp = np.array([n[1], -n[0], 0.0])  # n_side x up
    along = (pts - xB) @ perp
    mid = 0.5 * float(along.max() + along.min())
    half = 0.5 * float(along.max() - along.min())
    lat = float((xA - xB) @ perp) - mid
    w = ctx.param("width")
    out = proj - hB
    # the child's depth from its centroid toward the face: its near face within ``width``;
    # a child longer along the face than the parent: the face's middle within its length
    rel = xA - world_points(ctx.child, hull_only=True, settled=ctx.settled)
    hA = max(float(np.max(rel @ n)), 0.0)
    span = 0.5 * float(np.max(rel @ perp) - np.min(rel @ perp))
    ok = -1e-3 <= out <= w + hA + 1e-3 and abs(lat) <= max(half, span) + 1e-3
    return Check(ok, {"offset": round(out, 5), "lateral": round(lat, 5)},
                 f"{out:.3f} m out from the {ctx.param('side')} face (strip 0-{w:.3f} m, "
                 f"gap {out - hA:.3f} m), {abs(lat):.3f} m along it (half extent {half:.3f} m)")


def _parent_outline(ctx: CheckContext, near: np.ndarray) -> np.ndarray:
    """(N, 3) world points spanning the parent: its hull, or a wall's corners."""
    if ctx.parent is not None:
        return world_points(ctx.parent, hull_only=True, settled=ctx.settled)
    name = ctx.edge.parent.object
    if name == "wall":
        name = _nearest_wall(ctx.scene, near)
    s = ctx.scene.room.elements[name].surface
    poly = s.polygon
    geoms = list(poly.geoms) if hasattr(poly, "geoms") else [poly]
    return s.to_3d(np.vstack([np.asarray(g.exterior.coords) for g in geoms]))


# ------------------------------------------------------------ part-level and support rules
def _lowest(ctx: CheckContext) -> np.ndarray:
    pts = world_points(ctx.child, settled=ctx.settled, parts=select_parts(ctx.child, ctx.edge.child))
    return pts[np.argmin(pts[:, 2])]


def _internal_surface(ctx: CheckContext) -> tuple[Surface, str] | str:
    """The parent's internal support surface nearest the child's lowest point (IN) and the
    part it belongs to, or why there is none."""
    pobj, r = ctx.parent, ctx.resolved
    T = pobj.transform(ctx.settled)
    if r.get("parent_part"):
        cands = [(s.surface.transformed(T), s.part) for s in pobj.asset.internal
                 if s.part == r["parent_part"]]
        if not cands:
            return "internal surface missing"
    else:
        names = {p.name for p in select_parts(pobj, ctx.edge.parent)}
        cands = [(s.surface.transformed(T), s.part) for s in pobj.asset.internal if s.part in names]
        if not cands:
            return "no internal surface"
    low = _lowest(ctx)
    return min(cands, key=lambda c: abs(float((low - c[0].origin) @ c[0].normal)))


def _parent_surface(ctx: CheckContext) -> Surface | str:
    """The parent surface a part-level or support relation (other than IN) refers to."""
    e, r, scene = ctx.edge, ctx.resolved, ctx.scene
    label = r.get("parent_surface") or e.parent.surface or e.spec.parent_surface
    part_name = r.get("parent_part") or r.get("parent_element")
    if e.parent.is_room_element:
        part_name = r.get("parent_element") or (None if e.parent.object == "wall" else e.parent.object)
        if part_name is None:  # "wall": the wall the child is closest to
            pts = world_points(ctx.child, hull_only=True, settled=ctx.settled)
            part_name = min((n for n in scene.room.elements if n.startswith("wall_")),
                            key=lambda n: float(np.min(_plane_dist(pts, scene.room.elements[n].surface))))
    sB = _surface(scene, ctx.parent, e.parent, label, ctx.settled, part_name)
    return f"cannot resolve {e.parent}" if sB is None else sB


def _target_surface(ctx: CheckContext) -> Surface | str:
    if ctx.edge.relation == "IN" and ctx.parent is not None:
        got = _internal_surface(ctx)
        return got if isinstance(got, str) else got[0]
    return _parent_surface(ctx)


def _child_label(ctx: CheckContext) -> str:
    if ctx.edge.relation in ("ON", "IN", "HANGING_BELOW") and ctx.child.rests_on:
        # standing on another face (sheet music on a ledge, a toothbrush in a tumbler), hung
        # by it (a towel edge-up)
        return ctx.child.rests_on
    label = ctx.edge.child.surface or ctx.edge.spec.child_surface
    if ctx.edge.relation in ("ON", "LEANING_AGAINST") \
            and stands_to_lean(ctx.child.asset, ctx.scene.pag, ctx.child.id):
        return standing_label(label)  # a pillow on its edge, its bottom against the headboard
    return label


#: Degrees a child resting on a pile of its siblings (apples, towels in a basket) or on its
#: container's wall (a bowl nested in a bowl) may tilt.
PILE_TILT_DEG = 15.0
#: Degrees a child standing on a ledge on another face (``rests_on``) may lean back.
LEDGE_LEAN_DEG = 35.0
#: Degrees a long child standing in a container on its lower end (``rests_on``: a toothbrush
#: in a tumbler, pens in a mug) may lean on the rim: up to 70 degrees, a spoon in a shallow
#: cereal bowl (``solver.standing.SHALLOW_TILT_DEG``), and a degree of settling.
STAND_LEAN_DEG = 71.0


def _placed_lying(child: PlacedObject) -> bool:
    """Whether ``child`` was placed lying: its height no more than its longest horizontal
    extent in the solved pose (as :func:`.stability.settled_rest` reads "lying")."""
    ext = np.ptp(world_points(child, hull_only=True, settled=False), axis=0)
    return bool(ext[2] <= max(ext[0], ext[1]))


def _contact(ctx: CheckContext, sB: Surface) -> tuple[Check, bool]:
    """Contact of the child's named parts with ``sB``: the family ON, IN, HANGING_BELOW,
    SECURED_TO and AGAINST (distance band and anti-parallel normals). Also returns whether
    the normal tolerance was widened for a leaning object."""
    e, child, pobj, settled = ctx.edge, ctx.child, ctx.parent, ctx.settled
    rel = e.relation
    parts = select_parts(child, e.child)
    if not parts:
        return Check(False, {}, f"child has no part {e.child.part!r}"), False
    pts = world_points(child, settled=settled, parts=parts)
    gap = float(_plane_dist(pts, sB).min())
    ends: list[str] = []
    if rel in END_RELATIONS and e.child.part is not None and gap > DIST_TOL:
        # the named parts stand on pads at their ends (a chair's legs on glides): those
        # touch for them
        ends, gap = _ends(child, parts, sB, settled, gap)
    if rel == "ON" and pobj is not None and (gap < -PENETRATION_TOL
                                             or DIST_TOL < gap <= STEP + DIST_TOL):
        # resting below the surface plane, inside the parent's hollow (a plate in a plate),
        # or up to STEP above it on a low part of the parent (a pan on a burner of the
        # cooktop): the contact is the free drop onto the parent's geometry
        d = drop_distance(world_points(child, hull_only=True, settled=settled), child.asset,
                          child.transform(settled),
                          world_points(pobj, hull_only=True, settled=settled), pobj.asset,
                          pobj.transform(settled), -sB.normal)
        # curved bodies touching between vertices (a croissant on croissants, a pillow on a
        # pillow) read millimetres apart on the rays
        d = _refined_drop(d, child, pobj, settled, -sB.normal)
        if gap > 0 and not (np.isfinite(d) and d <= DIST_TOL):
            d = _gap_to_low_parts(pts, pobj, sB, settled)  # the rays may miss a low burner
        if np.isfinite(d) and (gap < 0 or d <= DIST_TOL):
            gap = d
    pile = None
    on_wall = False
    if rel == "IN" and pobj is not None and gap < -PENETRATION_TOL:
        # below the internal surface's plane, resting on the container's curved inside (a
        # bowl nested in a bowl, its foot ring below the plane of the inner floor's flat)
        d = drop_distance(world_points(child, hull_only=True, settled=settled), child.asset,
                          child.transform(settled),
                          world_points(pobj, hull_only=True, settled=settled), pobj.asset,
                          pobj.transform(settled), -sB.normal)
        d = _refined_drop(d, child, pobj, settled, -sB.normal)
        if np.isfinite(d) and -PENETRATION_TOL <= d <= DIST_TOL:
            gap, on_wall = float(d), True
    if rel in ("ON", "IN") and pobj is not None and gap > DIST_TOL:
        pile = _resting_on_sibling(ctx, -sB.normal)
        if pile is not None:
            pile, gap = pile
        elif rel == "IN":
            # in a container on its curved wall above the bottom (an apple in a bowl, rolled
            # against the others): the contact is the free drop onto the container
            d = drop_distance(world_points(child, hull_only=True, settled=settled), child.asset,
                              child.transform(settled),
                              world_points(pobj, hull_only=True, settled=settled), pobj.asset,
                              pobj.transform(settled), -sB.normal)
            d = _refined_drop(d, child, pobj, settled, -sB.normal)
            if np.isfinite(d) and -PENETRATION_TOL <= d <= DIST_TOL:
                gap, on_wall = float(d), True
    target = 0.0
    lo_t, hi_t = -PENETRATION_TOL, DIST_TOL
    if rel == "AGAINST":
        target = ctx.param("gap")
    elif rel == "HANGING_BELOW":
        lo_d, hi_d = ctx.param("drop")
        lo_t, hi_t = lo_d - PENETRATION_TOL, hi_d + DIST_TOL
    nA = _child_normal(child, _child_label(ctx), settled)
    ang = float(np.degrees(angle_between(nA, -sB.normal)))
    ang_tol = ANGLE_TOL_DEG
    long_axis = _lying_axis(child, sB.normal, settled) if rel in ("ON", "IN") else None
    if rel in ("ON", "IN") and is_round(child):
        ang_tol = 180.0  # an apple rests in any orientation
    elif rel == "IN" and settled and pobj is not None and _placed_lying(child):
        # a content placed lying in its container (a banana bunch, a croissant) tumbles there
        # when settled: IN asks containment (the enclosure or footprint below), not a pose
        ang_tol = 180.0
    elif rel == "ON" and settled and pobj is not None and _placed_lying(child) \
            and _content_of_kind(ctx):
        # one on a pile of its kind in a container (a croissant on croissants in a bread
        # basket, a towel on towels): a content too, it tumbles as the others do
        ang_tol = 180.0
    elif long_axis is not None:
        # lying along its long axis (a baguette, a bottle on its side): it may roll about
        # that axis; the axis itself lies level
        ang = abs(90.0 - float(np.degrees(angle_between(long_axis, sB.normal))))
    elif rel == "ON" and child.rests_on:  # on its lower edge, leaning back on the ledge
        ang_tol = LEDGE_LEAN_DEG + 1.0
    elif rel == "IN" and child.rests_on:  # on its lower end, leaning on the container's rim
        ang_tol = STAND_LEAN_DEG
    elif rel in ("ON", "IN"):  # a leaning object stands on its support tilted by its lean angle
        for le in ctx.scene.pag.edges_of(e.child.object):
            if le.relation == "LEANING_AGAINST":
                on_obj = not le.parent.is_room_element
                # on an object, up to the widest lean: one leaning further than written (its
                # lean relaxed) still stands on its support
                hi = max(lean_range(le, on_obj)[1], WIDE_LEAN_DEG[1] if on_obj else 0.0)
                ang_tol = max(ang_tol, hi + 1.0)
    if rel == "ON" and settled and pobj is not None:  # partly on a rug, partly on the floor
        ang_tol = max(ang_tol, _covering_tilt(ctx.scene, child, pobj, settled))
    if pile is not None or on_wall:  # on a pile (a rolled towel on towels) or on the
        ang_tol = max(ang_tol, PILE_TILT_DEG)  # container's wall (a bowl in a bowl), as it lands
    res = {"distance": round(gap - target, 6), "angle_deg": round(ang, 4)}
    if pile is not None:
        res["piled"] = 1.0
    if on_wall:
        res["on_wall"] = 1.0
    ok = (lo_t <= gap - target <= hi_t) if rel != "HANGING_BELOW" else (lo_t <= gap <= hi_t)
    ok = ok and ang <= ang_tol
    detail = f"gap {gap * 1000:.2f} mm, normals off by {ang:.2f} deg"
    if ends:
        detail += f", through {', '.join(ends)}"
    if pile is not None:
        detail += f", resting on {pile}"
    elif on_wall:
        detail += f", resting on {e.parent.object}'s wall"
    leans = rel in ("ON", "IN") and any(le.relation == "LEANING_AGAINST"
                                for le in ctx.scene.pag.edges_of(e.child.object))
    return Check(ok, res, detail), ang_tol != ANGLE_TOL_DEG or leans


#: Relations whose named child part may touch through pads at its end (:func:`_ends`): a
#: chair leg's glide, a screen's VESA plate on its back cover, the hanging loop rising from a
#: coat's collar (as the solver reads them: ``solver.intent.overhang``).
END_RELATIONS = ("ON", "AGAINST", "SECURED_TO", "HANGING_BELOW")
#: Metres a pad at the end of a named part (a chair leg's glide, a table foot, a bumper on a
#: cabinet's back) may reach beyond it; a part reaching further (an armchair's legs under its
#: frame) is a part of its own, not the named part's end.
END_DEPTH = 0.02


def end_pads(named: list[np.ndarray], others: list[tuple[str, np.ndarray]], d: np.ndarray,
             depth: float = END_DEPTH) -> list[str]:
    """The names among ``others`` (name, points) of the pads ending the named parts (points
    ``named``, one array per part) toward direction ``d``: each lies within ``depth`` of the
    named parts' furthest point along ``d``, reaching beyond it, its near end within 1 mm of
    it, and its footprint across ``d`` meets one of theirs (a chair leg's glide, a table's
    foot; not a shelf's post running along its set-in back panel)."""
    from shapely.geometry import Polygon

    from ..geometry.regions import convex_footprint

    d = np.asarray(d, float) / np.linalg.norm(d)
    u = np.cross(d, [1.0, 0.0, 0.0] if abs(d[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(d, u)
    reach = max(float(np.max(q @ d)) for q in named)

    def foot(q):
        return Polygon(convex_footprint(np.c_[q @ u, q @ v])).buffer(2e-3)

    base = None
    out = []
    for name, q in others:
        h = q @ d
        if not (reach < float(h.max()) <= reach + depth
                and reach - depth <= float(h.min()) <= reach + 1e-3):
            continue
        if base is None:
            base = [foot(n) for n in named]
        f = foot(q)
        if any(f.intersects(b) for b in base):
            out.append(name)
    return out


def _ends(child: PlacedObject, parts: list, sB: Surface, settled, gap: float
          ) -> tuple[list[str], float]:
    """The child's other parts ending the named ``parts`` toward ``sB`` (:func:`end_pads`),
    and the gap of the named parts with them (``gap`` when there are none)."""
    T = child.transform(settled)
    named = {id(p) for p in parts}

    def world(p):
        return part_points([p]) @ T[:3, :3].T + T[:3, 3]

    others = [(p.name, world(p)) for p in child.asset.parts if id(p) not in named]
    pads = end_pads([world(p) for p in parts], others, -sB.normal,
                    END_DEPTH * child.scale)
    if not pads:
        return [], gap
    low = min(float(_plane_dist(q, sB).min()) for name, q in others if name in pads)
    return pads, min(gap, low)


#: Two extents within this ratio count as one round cross-section; the third must exceed
#: them by as much to be a long axis.
ROLL_RATIO = 1.3


def _lying_axis(child: PlacedObject, n: np.ndarray, settled) -> np.ndarray | None:
    """The world direction of the long axis of an elongated child with a round-ish cross
    section (its two smaller extents within ``ROLL_RATIO``) lying on its side (that axis within
    20 degrees of level), which it may roll about; None otherwise."""
    ext, k = hull_extents(child.asset)
    if ext[k[1]] > ROLL_RATIO * ext[k[0]] or ext[k[2]] <= ROLL_RATIO * ext[k[1]]:
        return None
    axis = child.transform(settled)[:3, :3][:, k[2]] / child.scale
    if abs(float(axis @ n)) > np.sin(np.deg2rad(20.0)):
        return None
    return axis


def _gap_to_low_parts(pts: np.ndarray, pobj: PlacedObject, sB: Surface, settled) -> float:
    """Gap (m) between the base of a child with world points ``pts`` (those within 3 mm of
    its lowest) and the highest part of the parent rising at most ``STEP`` above ``sB`` that
    lies under that base; inf when none does."""
    from shapely.geometry import Polygon

    from ..geometry.regions import convex_footprint

    def uv(p):
        d = p - sB.origin
        return np.c_[d @ sB.u, d @ sB.v]

    h = _plane_dist(pts, sB)
    foot = Polygon(convex_footprint(uv(pts[h <= h.min() + 3e-3]))).buffer(1e-4)
    T = pobj.transform(settled)
    top = -np.inf
    for p in pobj.asset.parts:
        for pc in p.piece_arrays:
            q = pc.vertices @ T[:3, :3].T + T[:3, 3]
            hq = _plane_dist(q, sB)
            if 1e-3 < hq.max() <= STEP and hq.min() > -STEP \
                    and foot.intersects(Polygon(convex_footprint(uv(q)))):
                top = max(top, float(hq.max()))
    return float(h.min()) - top if np.isfinite(top) else np.inf


def _resting_on_sibling(ctx: CheckContext, down: np.ndarray) -> tuple[str, float] | None:
    """A pile: the placed object with the same support parent that the child rests on (the
    free drop along ``down`` onto it is within contact distance), and that drop."""
    child, settled, scene = ctx.child, ctx.settled, ctx.scene
    pts = world_points(child, hull_only=True, settled=settled)
    lo, hi = pts[:, :2].min(axis=0), pts[:, :2].max(axis=0)
    for oid, o in scene.objects.items():
        if oid == child.id or not o.placed or o.asset is None:
            continue
        sup = scene.pag.supporter(oid)
        if sup is None or (sup.parent.object != ctx.edge.parent.object
                           and o.stacked_on != ctx.edge.parent.object):
            continue  # on the parent, or piled on it (a towel on the towel on a towel)
        q = world_points(o, hull_only=True, settled=settled)
        if np.any(q[:, :2].min(axis=0) > hi) or np.any(q[:, :2].max(axis=0) < lo):
            continue
        d = drop_distance(pts, child.asset, child.transform(settled), q, o.asset,
                          o.transform(settled), down)
        d = _refined_drop(d, child, o, settled, down)
        if -PENETRATION_TOL <= d <= DIST_TOL:
            return oid, float(d)
    return None


#: Metres up to which a vertex-sampled drop is measured again on the meshes (round bodies
#: touching between vertices read a few millimetres apart).
REFINE_DROP = 0.01


def _refined_drop(d: float, child: PlacedObject, other: PlacedObject, settled,
                  down: np.ndarray) -> float:
    """``d`` (a drop measured by :func:`drop_distance`), or, when it is just beyond contact,
    the exact drop of the child's mesh onto ``other``'s."""
    if not DIST_TOL < d <= REFINE_DROP:
        return d
    return exact_drop(child.asset, child.transform(settled), other.asset,
                      other.transform(settled), down, d)


def _leans_on_board(ctx: CheckContext, sB: Surface, base: np.ndarray) -> bool:
    """A thin child standing on a ledge (``rests_on``) that is ON an upright board (a piano's
    music rest, whose top is a 1 cm edge): it leans on the board, its base below the board's
    top standing on the board's owner there. Holds when its base is below the top and it
    touches the board (within contact distance)."""
    if not ctx.child.rests_on or ctx.parent is None or ctx.edge.parent.part is None \
            or float(_plane_dist(base[None], sB)[0]) > -DIST_TOL:
        return False
    pp = select_parts(ctx.parent, ctx.edge.parent)
    d = pieces_distance(piece_data(ctx.child.asset, ctx.child.asset.parts),
                        ctx.child.transform(ctx.settled), piece_data(ctx.parent.asset, pp),
                        ctx.parent.transform(ctx.settled))
    return d <= DIST_TOL


#: Metres from the face it leans on within which a leaning child's points are its lean contact.
LEAN_CONTACT = 3e-3


def _held_by_lean(ctx: CheckContext, sB: Surface, p3: np.ndarray) -> bool:
    """A child that leans on a face and touches it (its ``LEANING_AGAINST`` holds) is held by
    its base and by that face: whether ``p3`` (its centre of mass) projects inside the convex
    hull of the support polygon (with every part the parent reference names at its level, as
    :func:`_in_span`) and the child's points touching the face (a guitar in a stand, its weight
    between the cradle's arms and the neck rest; a cushion at the back of a seat, its top on
    the chair's back)."""
    from ..geometry.regions import convex_footprint, inside_convex

    pag, child = ctx.scene.pag, ctx.child
    leans = [le for le in pag.edges_of(child.id) if le.relation == "LEANING_AGAINST"]
    if not leans:
        return False
    base = [np.asarray(shell.exterior.coords)[:, :2] for shell in _shells(sB.polygon)]
    base += [_span_points(ctx, sB)]
    T = child.transform(ctx.settled)
    for le in leans:
        pobj = None if le.parent.is_room_element else ctx.scene.objects.get(le.parent.object)
        if pobj is not None and not pobj.placed:
            continue
        lctx = CheckContext(ctx.scene, le, child, pobj, {}, ctx.settled)
        face = _parent_surface(lctx)
        if isinstance(face, str) or not _check_leaning(lctx).holds:
            continue
        parts = select_parts(child, le.child) if le.child.part is not None else \
            child.asset.parts
        touch = []
        for f in _lean_faces(lctx, face):  # a fork's two prongs: the one it touches
            got = nearest_in_prism(piece_data(child.asset, parts), T, f.normal, f.origin,
                                   face_slabs(f), band=LEAN_CONTACT)
            if got is not None and got[0] <= DIST_TOL:
                q = got[2] - sB.origin
                touch.append(np.c_[q @ sB.u, q @ sB.v])
        if not touch:
            continue
        pts = np.vstack(base + touch)
        d = p3 - sB.origin
        if inside_convex(convex_footprint(pts), np.array([d @ sB.u, d @ sB.v]), 1e-3):
            return True
    return False


def _resolve_or_fail(ctx: CheckContext) -> Surface | Check:
    sB = _target_surface(ctx)
    return Check(False, {}, sB) if isinstance(sB, str) else sB


@check_rule("ON")
def _check_on(ctx: CheckContext) -> Check:
    """Contact, anti-parallel normals, centre of mass over the support polygon and over the
    child's own base."""
    sB = _resolve_or_fail(ctx)
    if isinstance(sB, Check):
        return sB
    c, leaning = _contact(ctx, sB)
    if not c.holds:
        return c
    res = dict(c.residual)
    com = ctx.child.transform(ctx.settled) @ np.r_[asset_geometry(ctx.child.asset).com, 1.0]
    if ctx.child.rests_on:
        # standing on a ledge leaning back: its base rests on the support, its centre of
        # mass lies over what it leans on
        pts = world_points(ctx.child, hull_only=True, settled=ctx.settled)
        h = _plane_dist(pts, sB)
        com = np.r_[pts[h <= h.min() + 3e-3].mean(axis=0), 1.0]
    inside = _in_polygon(sB, com[:3]) or _in_span(ctx, sB, com[:3]) \
        or _in_hollow(ctx, sB, com[:3]) or _leans_on_board(ctx, sB, com[:3]) \
        or _across_like(ctx, sB, com[:3]) or _held_by_lean(ctx, sB, com[:3]) or (  # partly on a rug, the floor holds the rest
            ctx.parent is not None and _covering_tilt(ctx.scene, ctx.child, ctx.parent,
                                                      ctx.settled) > 0
            and _base_over(ctx.child, sB, ctx.settled))
    res["com_inside"] = float(inside)
    if not inside:
        return Check(False, res, "centre of mass outside the support polygon")
    if not leaning and not _stands(ctx.child, com[:3], sB.normal, ctx.settled):
        # and over the child's own footprint on it, or it would tip (an arc lamp)
        res["com_inside"] = 0.0
        return Check(False, res, "centre of mass outside the object's own base: it would tip over")
    return Check(True, res, c.detail)


def _content_of_kind(ctx: CheckContext) -> bool:
    """Whether the parent shares a category with the child (PAG nodes) and is itself ``IN``
    a container: the child is one more content of a pile there."""
    pag, pid = ctx.scene.pag, ctx.edge.parent.object
    if ctx.edge.parent.is_room_element or pid not in pag.objects:
        return False
    under = pag.supporter(pid)
    return under is not None and under.relation == "IN" and bool(
        set(pag.objects[ctx.child.id].candidates) & set(pag.objects[pid].candidates))


def _across_like(ctx: CheckContext, sB: Surface, p3: np.ndarray) -> bool:
    """Whether the child rests across the parent and objects of its kind beside it (a rolled
    towel in the groove between two, a croissant across two): ``p3`` over the convex hull of
    the footprints of the parent and of each object sharing a category with the child (PAG
    nodes) and the parent's supporter that the child touches (free drop within contact)."""
    pobj, child, scene, settled = ctx.parent, ctx.child, ctx.scene, ctx.settled
    pag = scene.pag
    if pobj is None or ctx.edge.parent.is_room_element:
        return False
    kind = set(pag.objects[child.id].candidates)
    if not kind & set(pag.objects[pobj.id].candidates):
        return False
    under = pag.supporter(pobj.id)
    box = scene.objects.get(under.parent.object) if under is not None else None
    if settled and box is not None and box.placed and _content_of_kind(ctx):
        # settled on a pile of its kind in a container, touching the one below: held by the
        # pile and the container's wall, its centre of mass over the container
        from shapely.geometry import MultiPoint, Point

        d = world_points(box, hull_only=True, settled=True) - sB.origin
        q = p3 - sB.origin
        if MultiPoint(np.c_[d @ sB.u, d @ sB.v]).convex_hull.contains(
                Point(float(q @ sB.u), float(q @ sB.v))):
            return True
    pts = world_points(child, hull_only=True, settled=settled)
    lo, hi = pts[:, :2].min(axis=0), pts[:, :2].max(axis=0)
    held = []
    for oid, o in scene.objects.items():
        if oid in (child.id, pobj.id) or not o.placed or o.asset is None \
                or not kind & set(pag.objects[oid].candidates):
            continue
        sup = pag.supporter(oid)
        if sup is None or under is None or sup.parent.object != under.parent.object:
            continue
        q = world_points(o, hull_only=True, settled=settled)
        if np.any(q[:, :2].min(axis=0) > hi) or np.any(q[:, :2].max(axis=0) < lo):
            continue
        d = _refined_drop(drop_distance(pts, child.asset, child.transform(settled), q, o.asset,
                                        o.transform(settled), -sB.normal),
                          child, o, settled, -sB.normal)
        if d <= DIST_TOL:
            held.append(q)
    if not held:
        return False
    from shapely.geometry import MultiPoint, Point

    d = np.vstack([world_points(pobj, hull_only=True, settled=settled), *held]) - sB.origin
    hull = MultiPoint(np.c_[d @ sB.u, d @ sB.v]).convex_hull
    q = p3 - sB.origin
    return bool(hull.contains(Point(float(q @ sB.u), float(q @ sB.v))))


#: Metres within which the tops of parts count as one level (a luggage rack's straps).
LEVEL_TOL = 5e-3


def _in_hollow(ctx: CheckContext, sB: Surface, p3: np.ndarray) -> bool:
    """Whether the child rests below the named parent part's top, in its hollow (a marker in
    a whiteboard's tray, between its lips), with ``p3`` over that part's outline."""
    pobj, ref = ctx.parent, ctx.edge.parent
    if pobj is None or ref.part is None:
        return False
    low = float(_plane_dist(world_points(ctx.child, hull_only=True, settled=ctx.settled),
                            sB).min())
    if low >= -PENETRATION_TOL:
        return False
    from shapely.geometry import MultiPoint, Point

    name = ctx.resolved.get("parent_part")
    parts = [p for p in pobj.asset.parts if p.name == name] if name else select_parts(pobj, ref)
    if not parts:
        return False
    d = world_points(pobj, settled=ctx.settled, parts=parts) - sB.origin
    hull = MultiPoint(np.c_[d @ sB.u, d @ sB.v]).convex_hull
    q = p3 - sB.origin
    return bool(hull.distance(Point(float(q @ sB.u), float(q @ sB.v))) <= 1e-3)


def _in_span(ctx: CheckContext, sB: Surface, p3: np.ndarray) -> bool:
    """Whether ``p3`` projects inside the convex hull of the tops of every part the parent
    reference names (a label without ``#k``) at the level of ``sB``: what rests across a
    luggage rack's straps has them all as its support polygon."""
    from shapely.geometry import MultiPoint, Point

    pts = _span_points(ctx, sB)
    if not len(pts):
        return False
    hull = MultiPoint(pts).convex_hull
    return bool(hull.distance(Point(float((p3 - sB.origin) @ sB.u),
                                     float((p3 - sB.origin) @ sB.v))) <= 1e-3)


def _span_points(ctx: CheckContext, sB: Surface) -> np.ndarray:
    """(N, 2) outline points, in ``sB``'s plane, of the tops of every part the parent reference
    names (a label without ``#k``) at the level of ``sB``; empty unless there are two or more."""
    ref, pobj = ctx.edge.parent, ctx.parent
    if pobj is None or ref.part is None or ref.index is not None:
        return np.zeros((0, 2))
    T = pobj.transform(ctx.settled)
    pts = []
    for p in select_parts(pobj, ref):
        s = p.surfaces["top"].transformed(T)
        if abs(float((s.origin - sB.origin) @ sB.normal)) <= LEVEL_TOL \
                and float(s.normal @ sB.normal) > 0.999:
            pts.append(s.outline_3d())
    if len(pts) < 2:
        return np.zeros((0, 2))
    d = np.vstack(pts) - sB.origin
    return np.c_[d @ sB.u, d @ sB.v]


#: Part labels whose internal surfaces are open shelves or racks: IN on them needs no enclosure.
OPEN_SUPPORT_LABELS = frozenset({"shelf", "rack"})
#: Part labels of boards: ``IN`` one that holds nothing inside (a wall shelf's board) means ON
#: its top.
BOARD_LABELS = frozenset({"shelf", "tier", "board", "plank", "ledge"})


def board_parts(asset) -> list:
    """The boards (:data:`BOARD_LABELS`) of an asset that holds nothing inside (a wall shelf):
    ``IN`` the whole object means ON one of them; empty for anything with an inside."""
    if asset.internal:
        return []
    return [p for p in asset.parts if p.label in BOARD_LABELS]


def on_board(pobj: PlacedObject, ref: Ref, part_name: str | None = None) -> bool:
    """Whether ``IN`` the parent part ``ref`` (or the resolved ``part_name``) means ON its top:
    a board (:data:`BOARD_LABELS`) of which no named part holds an internal surface; ``IN``
    the whole object when it holds nothing inside and has boards (plates in a wall shelf)."""
    if part_name is not None:
        parts = [p for p in pobj.asset.parts if p.name == part_name]
    elif ref.part is None:
        parts = board_parts(pobj.asset)
    else:
        parts = select_parts(pobj, ref)
    names = {p.name for p in parts}
    return bool(parts) and all(p.label in BOARD_LABELS for p in parts) \
        and not any(i.part in names for i in pobj.asset.internal)


@check_rule("IN")
def _check_in(ctx: CheckContext) -> Check:
    """Contact with an internal support surface of the parent (or a pile on it); then, on a
    shelf part, the child's centroid inside the parent's bounding-box footprint, and in any
    other container a ray-cast enclosure >= ``min_enclosure`` (the rays start at the centroid,
    lowered to at most halfway from the internal surface up to the parent's top)."""
    pobj = ctx.parent
    if pobj is None:
        return Check(False, {}, "IN needs an object parent")
    got = _internal_surface(ctx)
    if ctx.edge.parent.part is None and no_room_inside(pobj, ctx.child):
        from dataclasses import replace  # no inside with room for it: on its top (insides.py)

        c = _check_on(replace(ctx, edge=replace(ctx.edge, relation="ON"),
                              resolved={**ctx.resolved, "parent_surface": "top"}))
        return Check(c.holds, c.residual, f"{c.detail}; on its top (no inside has room for it)")
    if isinstance(got, str):
        if on_board(pobj, ctx.edge.parent, ctx.resolved.get("parent_part")):
            # a board holds what is IN it on its top (records on a wall shelf)
            from dataclasses import replace

            c = _check_on(replace(ctx, edge=replace(ctx.edge, relation="ON"),
                                  resolved={**ctx.resolved, "parent_surface": "top"}))
            return Check(c.holds, c.residual, f"{c.detail}; on top of the "
                         f"{ctx.edge.parent.part} (it holds nothing inside)")
        return Check(False, {}, got)
    sB, part = got
    c, _ = _contact(ctx, sB)
    if not c.holds:
        return c
    label = next((p.label for p in pobj.asset.parts if p.name == part), part)
    if label in OPEN_SUPPORT_LABELS or c.residual.get("piled") or c.residual.get("on_wall"):
        # on an open shelf, or on a pile in the container or its wall (an apple on apples may
        # rise above a shallow bowl's rim): the centroid over the parent's footprint
        Ti = np.linalg.inv(pobj.transform(ctx.settled))
        x = Ti[:3, :3] @ object_centroid(ctx.child, ctx.settled) + Ti[:3, 3]
        b = asset_geometry(pobj.asset).bounds
        tol = 1e-3 / pobj.scale
        inside = bool(np.all(x[:2] >= b[0, :2] - tol) and np.all(x[:2] <= b[1, :2] + tol))
        res = dict(c.residual, inside_footprint=float(inside))
        where = "on a pile" if c.residual.get("piled") else "on its wall" \
            if c.residual.get("on_wall") else f"on the open {label} {part}"
        return Check(inside, res, f"{c.detail}; {where}, centroid "
                     f"{'inside' if inside else 'outside'} {ctx.edge.parent.object}'s footprint")
    enc = _enclosure(ctx.child, pobj, ctx.settled, sB)
    res = dict(c.residual, enclosure=round(enc, 4))
    return Check(enc >= ctx.param("min_enclosure") - 1e-9, res, f"{c.detail}; enclosure {enc:.2f}")


@check_rule("HANGING_BELOW", "AGAINST")
def _check_contact(ctx: CheckContext) -> Check:
    """The named part at ``drop`` (HANGING_BELOW) or ``gap`` (AGAINST) from the parent
    surface, normals anti-parallel."""
    sB = _resolve_or_fail(ctx)
    if isinstance(sB, Check):
        return sB
    return _contact(ctx, sB)[0]


@check_rule("SECURED_TO")
def _check_secured(ctx: CheckContext) -> Check:
    """Contact, anti-parallel normals and the centre's height within ``height``."""
    sB = _resolve_or_fail(ctx)
    if isinstance(sB, Check):
        return sB
    c, _ = _contact(ctx, sB)
    if not c.holds:
        c = _on_mounted(ctx, sB, c)
    if not c.holds:
        return c
    zc = float(object_centroid(ctx.child, ctx.settled)[2])
    lo, hi = ctx.param("height")
    return Check(lo - 0.01 <= zc <= hi + 0.01, dict(c.residual, height=round(zc, 4)),
                 f"centre at {zc:.2f} m")


def _on_mounted(ctx: CheckContext, sB: Surface, c: Check) -> Check:
    """``c``, or a holding check when the child (normals within tolerance) touches what is
    mounted on the parent part's face instead of the face itself: a screen on the VESA arms
    fixed to a cart's mount plate, a sign on the face fixed in a stand's frame."""
    pobj, ref = ctx.parent, ctx.edge.parent
    if pobj is None or ref.part is None or c.residual.get("angle_deg", 90.0) > ANGLE_TOL_DEG \
            or not 0 < c.residual.get("distance", -1.0) <= MOUNTED_DEPTH + DIST_TOL:
        return c
    pp = select_parts(pobj, ref)
    Tp = pobj.transform(ctx.settled)
    on, _ = mounted_parts(pobj, pp, sB, Tp)
    if not on:
        return c
    parts = select_parts(ctx.child, ctx.edge.child)
    pads, _ = _ends(ctx.child, parts, sB, ctx.settled, np.inf)  # through standoffs
    parts = parts + [p for p in ctx.child.asset.parts if p.name in pads]
    d = pieces_distance(piece_data(ctx.child.asset, parts), ctx.child.transform(ctx.settled),
                        piece_data(pobj.asset, pp + on), Tp)
    if not -PENETRATION_TOL <= d <= DIST_TOL:
        return c
    return Check(True, dict(c.residual, distance=round(d, 6), mounted=1.0),
                 f"{c.detail}, touching what is mounted on {ref.object}:{ref.part} "
                 f"({d * 1000:.2f} mm)")


@check_rule("LEANING_AGAINST")
def _check_leaning(ctx: CheckContext) -> Check:
    """The named part touches the parent face *within its extent* (-1...+2 mm; a book beside a
    box touches nothing), its named surface faces the parent (normals anti-parallel within the
    tilt + 2 deg), and the up axis is tilted from vertical by ``angle_deg`` (+-1 deg; see
    :func:`parse3d.measure.reach.lean_range`). A parent label naming several parts (a sofa's
    back cushions) holds when the child leans on any of them."""
    sB = _resolve_or_fail(ctx)
    if isinstance(sB, Check):
        return sB
    if not select_parts(ctx.child, ctx.edge.child):
        return Check(False, {}, f"child has no part {ctx.edge.child.part!r}")
    faces = _lean_faces(ctx, sB)
    best = None
    if len(faces) > 1:  # faces the child's box comes nowhere near cannot hold it: skip them
        H = world_points(ctx.child, hull_only=True, settled=ctx.settled)
        lo, hi = H.min(axis=0) - 0.02, H.max(axis=0) + 0.02
        near = [f for f in faces if np.all(f.outline_3d().min(axis=0) <= hi)
                and np.all(f.outline_3d().max(axis=0) >= lo)]
        faces = near or faces[:1]
    for f in faces:
        c = _lean_on(ctx, f)
        if c.holds:
            return c
        d = abs(c.residual.get("distance", np.inf))
        if best is None or d < best[0]:
            best = (d, c)
    return best[1]


def _lean_faces(ctx: CheckContext, sB: Surface) -> list[Surface]:
    """The faces a ``LEANING_AGAINST`` may lean on: ``sB``, or one per part a parent label
    without ``#k`` names (a sofa's back cushions, a guitar stand's neck-rest prongs)."""
    ref, pobj = ctx.edge.parent, ctx.parent
    if pobj is None or ref.part is None or ref.index is not None \
            or ctx.resolved.get("parent_part"):
        return [sB]
    label = ref.surface or ctx.edge.spec.parent_surface
    T = pobj.transform(ctx.settled)
    more = [_world_surface(p.surfaces[label], T) for p in select_parts(pobj, ref)
            if label in p.surfaces]
    return more or [sB]


def _lean_on(ctx: CheckContext, sB: Surface) -> Check:
    """:func:`_check_leaning` against one face."""
    child, settled = ctx.child, ctx.settled
    parts = select_parts(child, ctx.edge.child)
    T, slabs = child.transform(settled), face_slabs(sB)
    near = nearest_in_prism(piece_data(child.asset, parts), T, sB.normal, sB.origin, slabs)
    if near is None:
        off = float(_plane_dist(world_points(child, settled=settled, parts=parts), sB).min())
        return Check(False, {"distance": round(off, 6), "outside_face": 1.0},
                     f"{ctx.edge.child} is not in front of {ctx.edge.parent} (beside or past "
                     f"the face's extent)")
    gap = near[0]
    if not -PENETRATION_TOL <= gap <= DIST_TOL and ctx.parent is not None:
        # past the face's plane, resting on the parent's real surface behind it (a sofa's back
        # cushion slanted back from the front of its box; a whole bookcase's front, open
        # between its shelves, a ladder's rail resting on a shelf's edge behind it), or in
        # front of it on what is mounted on it (an amplifier's grille and knobs): the exact
        # distance decides
        pp = select_parts(ctx.parent, ctx.edge.parent)
        Tp = ctx.parent.transform(settled)
        on, _ = mounted_parts(ctx.parent, pp, sB, Tp)
        d = pieces_distance(piece_data(child.asset, parts), T,
                            piece_data(ctx.parent.asset, pp + on), Tp)
        if d <= DIST_TOL:
            gap = d
    # a flat child standing on its front edge to lean (a pillow) has its back as its up axis, a
    # plate written ON its rim's front the opposite of that face
    up_local = lean_up(child.asset, ctx.scene.pag, child.id)
    up = T[:3, :3] @ up_local / child.scale
    tilt = float(np.degrees(angle_between(up, [0, 0, 1.0])))
    face = float(np.degrees(angle_between(_child_normal(child, _child_label(ctx), settled),
                                          -sB.normal)))
    lo, hi = lean_range(ctx.edge, ctx.parent is not None)
    res = {"distance": round(gap, 6), "angle_deg": round(tilt, 4), "facing_deg": round(face, 4)}
    touches = -PENETRATION_TOL <= gap <= DIST_TOL
    ok = touches and lo - 1.0 <= tilt <= hi + 1.0 and face <= hi + ANGLE_TOL_DEG
    detail = f"{ctx.edge.child} {gap * 1000:.2f} mm from the parent, tilt {tilt:.1f} deg"
    whole = gap
    if not touches and gap > DIST_TOL:  # does another part touch instead?
        whole_near = nearest_in_prism(piece_data(child.asset, child.asset.parts), T, sB.normal,
                                      sB.origin, slabs)
        whole = gap if whole_near is None else whole_near[0]
    if not touches and gap > DIST_TOL and whole < gap - DIST_TOL:
        detail += f" (another part touches it; the named part is {1000 * (gap - whole):.0f} mm off)"
    return Check(ok, res, detail)


def _support_tilt(ctx: CheckContext) -> float:
    """Degrees the settled child may tilt because it stands ON a floor covering, partly past
    its edge (:func:`_covering_tilt`); 0 before settling and on anything else."""
    sup = ctx.scene.pag.supporter(ctx.child.id)
    if not ctx.settled or sup is None or sup.relation != "ON" or sup.parent.is_room_element:
        return 0.0
    pobj = ctx.scene.objects.get(sup.parent.object)
    if pobj is None or not pobj.placed:
        return 0.0
    return _covering_tilt(ctx.scene, ctx.child, pobj, ctx.settled)


@check_rule("ALIGNED_WITH", "OPPOSITE_TO", "PARALLEL_TO")
def _check_planes(ctx: CheckContext) -> Check:
    """Normals parallel (anti-parallel for OPPOSITE_TO); coplanar except PARALLEL_TO."""
    sB = _resolve_or_fail(ctx)
    if isinstance(sB, Check):
        return sB
    rel = ctx.edge.relation
    label = _child_label(ctx)
    nA = _child_normal(ctx.child, label, ctx.settled)
    sign = 1.0 if rel in ("ALIGNED_WITH", "PARALLEL_TO") else -1.0
    ang = float(np.degrees(angle_between(nA, sign * sB.normal)))
    res = {"angle_deg": round(ang, 4)}
    if rel == "PARALLEL_TO":
        tilt = _support_tilt(ctx)
        if tilt > 0 and abs(float(nA[2])) < 0.5 and abs(float(sB.normal[2])) < 0.5:
            # side faces of a child standing partly on a rug: the rug's thickness tilts it
            # (as ON allows), so its face turns as written (about the vertical, as the
            # parent's face) and tilts no more than the rug makes it
            yaw = float(np.degrees(angle_between(np.r_[nA[:2], 0.0], np.r_[sB.normal[:2], 0.0])))
            res["yaw_deg"] = round(yaw, 4)
            return Check(yaw <= ANGLE_TOL_DEG and ang <= tilt + ANGLE_TOL_DEG, res,
                         f"normals off by {ang:.2f} deg, {yaw:.2f} deg about the vertical "
                         f"(standing partly on a floor covering: tilted up to {tilt:.1f} deg)")
        return Check(ang <= ANGLE_TOL_DEG, res, f"normals off by {ang:.2f} deg")
    # coplanar: the child's surface plane passes through the parent's plane
    sA = _surface(ctx.scene, ctx.child, ctx.edge.child, label, ctx.settled)
    off = float((sA.origin - sB.origin) @ sB.normal) if sA is not None else float("inf")
    res["distance"] = round(off, 6)
    ok = ang <= ANGLE_TOL_DEG and abs(off) <= DIST_TOL
    return Check(ok, res, f"planes {off * 1000:.2f} mm apart, normals off by {ang:.2f} deg")


# ------------------------------------------------------------------------------ entry points
def check_edge(scene: Scene, edge: Edge, child: PlacedObject, *, resolved: dict | None = None,
               settled: bool | None = None) -> Check:
    """Check one relation of ``child`` (a placed or candidate object).

    Parameters
    ----------
    scene : Scene
    edge : Edge
    child : PlacedObject
        Placed, or a candidate pose the solver is validating.
    resolved : dict, optional
        The support chosen for a support relation (keys ``parent_part``, ``parent_element``,
        ``parent_surface``).
    settled : bool, optional
        True: the settled poses; False: the solved ones; None: whichever is newer.

    Returns
    -------
    Check
        ``(holds, residual, detail)``.
    """
    pobj = None if edge.parent.is_room_element else scene.objects.get(edge.parent.object)
    if pobj is not None and not pobj.placed:
        return Check(False, {}, "parent not placed")
    rule = _RULES.get(edge.relation)
    if rule is None:
        return Check(False, {}, f"unknown relation {edge.relation}")
    return rule(CheckContext(scene, edge, child, pobj, resolved or {}, settled))


def check_relations(scene: Scene, *, settled: bool = False,
                    known: dict[int, tuple] | None = None) -> list[RelationCheck]:
    """Check every PAG relation on the solved (or settled) poses.

    When ``settled`` is True the results go into ``holds_settled`` / ``residual_settled`` of
    the scene's existing checks (created if missing) and the list is returned. ``known`` maps
    relation indices to results already measured on the same poses (the solver's own).
    """
    resolved = {int(k): v for k, v in scene.meta.get("resolved", {}).items()}
    existing = {c.index: c for c in scene.relations}
    out = []
    for i, e in enumerate(scene.pag.relations):
        child = scene.objects.get(e.child.object)
        c = existing.get(i) or RelationCheck(i, e.relation, str(e.child), str(e.parent), None)
        if child is None or not child.placed:
            holds, res, detail = None, {}, "child not placed"
        elif known is not None and i in known:  # measured already, on the same pose
            holds, res, detail = known[i]
        else:
            holds, res, detail = check_edge(scene, e, child, resolved=resolved.get(i),
                                            settled=settled)
        if settled:
            c.holds_settled, c.residual_settled = holds, res
        else:
            c.holds, c.residual, c.detail = holds, res, detail
        out.append(c)
    return out
