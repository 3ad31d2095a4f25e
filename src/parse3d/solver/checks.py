"""Geometric checks of every relation, measured on posed geometry.

The solver validates candidate poses with these functions, and the same functions re-check a
scene after solving and after settling (``check_relations(scene, settled=True)``). Each check
returns whether the relation holds, the measured residuals and a short explanation.

Tolerances (documented in docs/solver.md): contact distance within 2 mm (1 mm below), normal
angles within 2 degrees, heights within 1 cm.
"""

from __future__ import annotations

import numpy as np

from ..geometry.frames import angle_between
from ..geometry.surfaces import Surface, surface_from_bbox
from ..pag.model import Edge
from ..pag.refs import Ref
from ..relations import SURFACES
from ..scene.model import PlacedObject, RelationCheck, Scene
from .geometry import (
    asset_geometry,
    drop_distance,
    enclosure_directions,
    part_points,
    ray_caster,
)

__all__ = ["EPS", "DIST_TOL", "ANGLE_TOL_DEG", "check_edge", "check_relations",
           "object_centroid", "world_points"]

#: Gap left between surfaces in contact when placing (m): FCL then sees no collision.
EPS = 5e-4
DIST_TOL = 2e-3
PENETRATION_TOL = 1e-3
ANGLE_TOL_DEG = 2.0
_SIDE = {"front": (0.0, 1.0, 0.0), "back": (0.0, -1.0, 0.0), "right": (1.0, 0.0, 0.0),
         "left": (-1.0, 0.0, 0.0)}


def world_points(obj: PlacedObject, *, hull_only: bool = False, settled: bool | None = None,
                 parts=None) -> np.ndarray:
    """(N, 3) world points of an object (its convex hull, or its parts' piece vertices)."""
    T = obj.transform(settled)
    if hull_only and parts is None:
        pts = asset_geometry(obj.asset).hull
    else:
        pts = part_points(parts if parts is not None else obj.asset.parts)
    return pts @ T[:3, :3].T + T[:3, 3]


def object_centroid(obj: PlacedObject, settled: bool | None = None) -> np.ndarray:
    """World centre of the object's bounding box."""
    T = obj.transform(settled)
    return T[:3, :3] @ asset_geometry(obj.asset).center + T[:3, 3]


def _parts(obj: PlacedObject, ref: Ref):
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
            return obj.asset.part(part_name).surfaces[label].transformed(T)
        except KeyError:
            return None
    parts = _parts(obj, ref)
    if not parts:
        return None
    if ref.part is None:
        return surface_from_bbox(label, asset_geometry(obj.asset).bounds).transformed(T)
    return parts[0].surfaces[label].transformed(T)


def _child_normal(obj: PlacedObject, ref: Ref, label: str, settled) -> np.ndarray:
    return obj.transform(settled)[:3, :3] @ np.array(SURFACES[label]) / obj.scale


def _nearest_wall(scene: Scene, p: np.ndarray) -> str:
    """The wall whose inner plane is closest to the point ``p`` (resolves ``wall``)."""
    return min((n for n in scene.room.elements if n.startswith("wall_")),
               key=lambda n: abs(float((p - scene.room.elements[n].surface.origin)
                                       @ scene.room.elements[n].surface.normal)))


def _frame(scene: Scene, name: str, settled, near: np.ndarray | None = None
           ) -> tuple[np.ndarray, np.ndarray]:
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
    from shapely.geometry import Point, Polygon

    d = p3 - s.origin
    poly = s.polygon
    parts = list(poly.geoms) if hasattr(poly, "geoms") else [poly]
    pt = Point(float(d @ s.u), float(d @ s.v))
    # holes do not count: an object on a rim spans the hole
    return any(Polygon(p.exterior).distance(pt) <= 1e-3 for p in parts if not p.is_empty)


def check_edge(scene: Scene, edge: Edge, child: PlacedObject, *, resolved: dict | None = None,
               settled: bool | None = None) -> tuple[bool, dict, str]:
    """Check one relation of ``child`` (a placed or candidate object).

    Returns
    -------
    holds : bool
    residual : dict of str to float
    detail : str
    """
    rel = edge.relation
    spec = edge.spec
    pobj = None if edge.parent.is_room_element else scene.objects.get(edge.parent.object)
    if pobj is not None and not pobj.placed:
        return False, {}, "parent not placed"
    res: dict[str, float] = {}
    if spec.kind == "object":
        xA = object_centroid(child, settled)
        xB, RB = _frame(scene, edge.parent.object, settled, near=xA)
        if rel in ("NEAR", "FAR_FROM"):
            if edge.parent.is_room_element:  # a wall: distance to its plane
                d = abs(float((xA - xB) @ RB[:, 1]))
            else:
                d = float(np.linalg.norm((xA - xB)[:2]))
            res["distance"] = round(d, 5)
            lim = edge.param("distance")
            ok = d <= lim + 1e-6 if rel == "NEAR" else d >= lim - 1e-6
            return ok, res, f"centroid distance {d:.3f} m vs {lim} m"
        if rel == "TOWARD":
            R = child.transform(settled)[:3, :3] / child.scale
            f = (R @ np.array([0, 1.0, 0]))[:2]
            to = (xB - xA)[:2]
            ang = float(np.degrees(angle_between(np.r_[f, 0], np.r_[to, 0]))) if np.linalg.norm(to) > 1e-6 else 0.0
            res["angle_deg"] = round(ang, 3)
            return ang <= edge.param("tolerance_deg") + 1e-6, res, f"facing off by {ang:.1f} deg"
        side = edge.param("side")
        n = RB @ np.array(_SIDE[side])
        n[2] = 0
        n /= max(np.linalg.norm(n), 1e-9)
        proj = float((xA - xB) @ n)
        res["offset"] = round(proj, 5)
        if rel == "SIDE_OF":
            return proj > 0, res, f"offset {proj:.3f} m toward {side}"
        hB = 0.0
        if pobj is not None:
            hB = float(np.max((world_points(pobj, hull_only=True, settled=settled) - xB) @ n))
        w = edge.param("width")
        ok = hB - 1e-3 <= proj <= hB + w + 1e-3
        return ok, res, f"offset {proj:.3f} m, strip [{hB:.3f}, {hB + w:.3f}]"

    # part-level and support relations
    c_label = edge.child.surface or spec.child_surface
    p_label = edge.parent.surface or spec.parent_surface
    r = resolved or {}
    if rel == "IN" and r.get("parent_part") and pobj is not None:
        ins = [s for s in pobj.asset.internal if s.part == r["parent_part"]]
        if not ins:
            return False, res, "internal surface missing"
        T = pobj.transform(settled)
        cands = [s.surface.transformed(T) for s in ins]
        pts = world_points(child, settled=settled, parts=_parts(child, edge.child))
        low = pts[np.argmin(pts[:, 2])]
        sB = min(cands, key=lambda s: abs(float((low - s.origin) @ s.normal)))
    elif rel == "IN" and pobj is not None:
        T = pobj.transform(settled)
        names = {p.name for p in _parts(pobj, edge.parent)}
        cands = [s.surface.transformed(T) for s in pobj.asset.internal if s.part in names]
        if not cands:
            return False, res, "no internal surface"
        pts = world_points(child, settled=settled, parts=_parts(child, edge.child))
        low = pts[np.argmin(pts[:, 2])]
        sB = min(cands, key=lambda s: abs(float((low - s.origin) @ s.normal)))
    else:
        part_name = r.get("parent_part") or r.get("parent_element")
        label = r.get("parent_surface") or p_label
        if edge.parent.is_room_element:
            part_name = r.get("parent_element") or (None if edge.parent.object == "wall" else edge.parent.object)
            if part_name is None:  # "wall": the wall the child is closest to
                pts = world_points(child, hull_only=True, settled=settled)
                part_name = min((n for n in scene.room.elements if n.startswith("wall_")),
                                key=lambda n: float(np.min(_plane_dist(pts, scene.room.elements[n].surface))))
        sB = _surface(scene, pobj, edge.parent, label, settled, part_name)
        if sB is None:
            return False, res, f"cannot resolve {edge.parent}"
    parts = _parts(child, edge.child)
    if not parts:
        return False, res, f"child has no part {edge.child.part!r}"
    pts = world_points(child, settled=settled, parts=parts)
    dist = _plane_dist(pts, sB)
    nA = _child_normal(child, edge.child, c_label, settled)

    if rel in ("ON", "IN", "HANGING_BELOW", "SECURED_TO", "AGAINST"):
        gap = float(dist.min())
        if rel == "ON" and pobj is not None and gap < -PENETRATION_TOL:
            # resting below the surface plane, inside the parent's hollow (a plate in a
            # plate): the contact is the free drop onto the parent's geometry
            d = drop_distance(world_points(child, hull_only=True, settled=settled), child.asset,
                              child.transform(settled),
                              world_points(pobj, hull_only=True, settled=settled), pobj.asset,
                              pobj.transform(settled), -sB.normal)
            if np.isfinite(d):
                gap = d
        target = 0.0
        lo_t, hi_t = -PENETRATION_TOL, DIST_TOL
        if rel == "AGAINST":
            target = edge.param("gap")
        elif rel == "HANGING_BELOW":
            lo_d, hi_d = edge.param("drop")
            lo_t, hi_t = lo_d - PENETRATION_TOL, hi_d + DIST_TOL
        ang = float(np.degrees(angle_between(nA, -sB.normal)))
        ang_tol = ANGLE_TOL_DEG
        if rel == "ON":  # a leaning object stands on its support tilted by its lean angle
            for le in scene.pag.edges_of(edge.child.object):
                if le.relation == "LEANING_AGAINST":
                    ang_tol = max(ang_tol, le.param("angle_deg")[1] + 1.0)
        res["distance"] = round(gap - target, 6)
        res["angle_deg"] = round(ang, 4)
        ok = (lo_t <= gap - target <= hi_t) if rel != "HANGING_BELOW" else (lo_t <= gap <= hi_t)
        ok = ok and ang <= ang_tol
        detail = f"gap {gap * 1000:.2f} mm, normals off by {ang:.2f} deg"
        if ok and rel == "ON":
            com = child.transform(settled) @ np.r_[asset_geometry(child.asset).com, 1.0]
            inside = _in_polygon(sB, com[:3])
            res["com_inside"] = float(inside)
            ok = inside
            if not inside:
                detail = "centre of mass outside the support polygon"
            elif ang_tol == ANGLE_TOL_DEG and not _stands(child, com[:3], sB.normal, settled):
                # and over the child's own footprint on it, or it would tip (an arc lamp)
                ok = False
                res["com_inside"] = 0.0
                detail = "centre of mass outside the object's own base: it would tip over"
        if ok and rel == "IN" and pobj is not None:
            enc = _enclosure(child, pobj, settled)
            res["enclosure"] = round(enc, 4)
            ok = enc >= edge.param("min_enclosure") - 1e-9
            detail = f"enclosure {enc:.2f}"
        if ok and rel == "SECURED_TO":
            zc = float(object_centroid(child, settled)[2])
            lo, hi = edge.param("height")
            res["height"] = round(zc, 4)
            ok = lo - 0.01 <= zc <= hi + 0.01
            detail = f"centre at {zc:.2f} m"
        return ok, res, detail
    if rel == "LEANING_AGAINST":
        # contact by the whole object (see the solver docs); the tilt is of its up axis
        gap = float(_plane_dist(world_points(child, settled=settled), sB).min())
        T = child.transform(settled)
        up = T[:3, :3] @ np.array([0, 0, 1.0]) / child.scale
        tilt = float(np.degrees(angle_between(up, [0, 0, 1.0])))
        lo, hi = edge.param("angle_deg")
        res["distance"] = round(gap, 6)
        res["angle_deg"] = round(tilt, 4)
        ok = -PENETRATION_TOL <= gap <= DIST_TOL and lo - 1.0 <= tilt <= hi + 1.0
        return ok, res, f"gap {gap * 1000:.2f} mm, tilt {tilt:.1f} deg"
    if rel in ("ALIGNED_WITH", "OPPOSITE_TO", "PARALLEL_TO"):
        sign = 1.0 if rel in ("ALIGNED_WITH", "PARALLEL_TO") else -1.0
        ang = float(np.degrees(angle_between(nA, sign * sB.normal)))
        res["angle_deg"] = round(ang, 4)
        if rel == "PARALLEL_TO":
            return ang <= ANGLE_TOL_DEG, res, f"normals off by {ang:.2f} deg"
        # coplanar: the child's surface plane passes through the parent's plane
        sA = _surface(scene, child, edge.child, c_label, settled)
        off = float((sA.origin - sB.origin) @ sB.normal) if sA is not None else float("inf")
        res["distance"] = round(off, 6)
        ok = ang <= ANGLE_TOL_DEG and abs(off) <= DIST_TOL
        return ok, res, f"planes {off * 1000:.2f} mm apart, normals off by {ang:.2f} deg"
    return False, res, f"unknown relation {rel}"


def _stands(child: PlacedObject, com: np.ndarray, n: np.ndarray, settled) -> bool:
    """Whether the centre of mass projects inside the convex hull of the child's lowest
    points (its base), along the support normal ``n``."""
    from ..geometry.regions import convex_footprint, inside_convex

    pts = world_points(child, settled=settled)
    h = pts @ n
    base = pts[h <= h.min() + 3e-3]
    u = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    hull = convex_footprint(np.c_[base @ u, base @ v])
    return inside_convex(hull, np.array([com @ u, com @ v]), tol=2e-3)


def _enclosure(child: PlacedObject, parent: PlacedObject, settled) -> float:
    """Fraction of rays from the child's centroid that hit the parent."""
    T = parent.transform(settled)
    Tinv = np.linalg.inv(T)
    c = object_centroid(child, settled)
    o = Tinv[:3, :3] @ c + Tinv[:3, 3]
    dirs = enclosure_directions() @ Tinv[:3, :3].T
    dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
    hit = ray_caster(parent.asset).intersects_any(np.tile(o, (len(dirs), 1)), dirs)
    return float(np.mean(hit))


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
