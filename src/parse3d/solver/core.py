"""The Part-Aware Spatial Configuration Solver (the paper's Algorithm 1).

For each object in assembly order:

1. **Asset selection and scale**: a candidate category, an asset from the library, a scale so
   the asset's largest extent falls in the category's size range (times the node's ``scale``).
2. **Support surface**: the parent part's surface named by the support relation (explicit
   ``@surface``, else the relation's default, else inferred: an upward surface large enough
   for the child; for ``IN`` an internal support surface with enough clearance).
3. **Rotation** from the part-level normal constraints: the child's contact surface
   anti-parallel to the support normal, the remaining angle about the support normal fixed by
   AGAINST / OPPOSITE_TO / ALIGNED_WITH / PARALLEL_TO (or kept upright on walls, or turned by
   TOWARD, or sampled), then the LEANING_AGAINST tilt.
4. **Coarse localisation** in the support plane: the support polygon minus the footprints
   already there, eroded by the child's footprint (exact Minkowski difference), clipped by the
   object-level regions (SIDE_OF half-plane, ALONG strip, NEAR disk, FAR_FROM complement).
5. **Part-level regions**: contact constraints become lines in the support plane (AGAINST, the
   line where the child's surface touches the parent's; ALIGNED_WITH / OPPOSITE_TO, where the
   planes coincide; LEANING_AGAINST, where the tilted child touches), intersected with the
   coarse region. An empty region fails the object with the constraint that emptied it.
6. **Sampling and validation**: positions drawn uniformly from the final region, each checked
   against every relation of the object and for mesh collisions (FCL) with everything placed.

``strategy="rejection"`` is the baseline the paper argues against: position and free angle
sampled uniformly over the whole support surface, then the same validation.
"""

from __future__ import annotations

import time
import zlib
from dataclasses import dataclass, field, replace

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry

from ..assets.model import Asset, Part
from ..geometry import regions as RG
from ..geometry.frames import axis_angle, rotation_between
from ..geometry.surfaces import Surface
from ..measure.checks import EPS, check_edge, object_centroid, world_points
from ..pag.algorithms import assembly_order
from ..pag.model import PAG, Edge
from ..pag.refs import Ref
from ..relations import SURFACES
from ..scene.model import PlacedObject, Scene
from ..scene.shell import build_shell
from .collision import Body, CollisionWorld, cached_body
from .geometry import asset_geometry, drop_distance, part_points

__all__ = ["SolverConfig", "solve_scene", "stage_rng"]

_SIDE_DIRS = {"front": (0.0, 1.0, 0.0), "back": (0.0, -1.0, 0.0),
              "right": (1.0, 0.0, 0.0), "left": (-1.0, 0.0, 0.0)}


@dataclass(frozen=True)
class SolverConfig:
    """Solver options (saved into scene.json).

    Attributes
    ----------
    max_trials : int
        Pose samples per asset attempt before giving up.
    asset_attempts : int
        Assets (and scales) tried per object before it fails.
    strategy : str
        ``constrained`` (Algorithm 1) or ``rejection`` (the baseline).
    margin : float
        Metres kept between a footprint and the edge of its support polygon.
    wall_thickness : float
    """

    max_trials: int = 30
    asset_attempts: int = 4
    strategy: str = "constrained"
    margin: float = 0.003
    wall_thickness: float = 0.12

    def to_dict(self) -> dict:
        return {"max_trials": self.max_trials, "asset_attempts": self.asset_attempts,
                "strategy": self.strategy, "margin": self.margin,
                "wall_thickness": self.wall_thickness}


def stage_rng(seed: int, stage: str) -> np.random.Generator:
    """One generator per (scene seed, stage name)."""
    return np.random.default_rng([int(seed), zlib.crc32(stage.encode())])


#: Consecutive validation failures of the same relation after which an asset is given up.
STRUCTURAL_FAILURES = 8


class _Fail(Exception):
    """An object could not be placed; the message names the constraint."""


@dataclass
class _Support:
    """A resolved support: a world surface and what it belongs to."""

    surface: Surface  # world frame; normal is the support normal
    owner: str  # object id or "room"
    part: str | None  # part name, or room element name
    label: str  # surface label used
    region: BaseGeometry  # polygon in (u, v) coordinates of ``surface``
    clearance: float = float("inf")


@dataclass
class _State:
    pag: PAG
    scene: Scene
    world: CollisionWorld
    hulls: dict[str, np.ndarray] = field(default_factory=dict)  # world hull points per object
    xy: dict[str, np.ndarray] = field(default_factory=dict)  # world xy convex footprint
    zr: dict[str, tuple[float, float]] = field(default_factory=dict)  # world z range
    pieces: dict[str, list] = field(default_factory=dict)  # world convex pieces, lazily
    accepted: list = field(default_factory=list)  # checks of the last accepted pose
    known: dict[int, tuple] = field(default_factory=dict)  # relation index -> check result
    resolved: dict[int, dict] = field(default_factory=dict)


# --------------------------------------------------------------------------- helpers
def _parts_for(asset: Asset, ref: Ref) -> list[Part]:
    if ref.part is None:
        return list(asset.parts)
    ps = asset.parts_by_label(ref.part)
    if ref.index is not None:
        ps = ps[ref.index:ref.index + 1]
    return ps


def _room_surface(scene: Scene, name: str) -> Surface:
    return scene.room.elements[name].surface


def _plane_coords(surf: Surface, pts: np.ndarray) -> np.ndarray:
    d = np.asarray(pts, float) - surf.origin
    return np.c_[d @ surf.u, d @ surf.v]


def _filled(poly: BaseGeometry) -> BaseGeometry:
    """The polygon without its holes."""
    parts = list(poly.geoms) if hasattr(poly, "geoms") else [poly]
    filled = [Polygon(p.exterior) for p in parts if isinstance(p, Polygon) and not p.is_empty]
    return shapely.union_all(filled) if len(filled) > 1 else (filled[0] if filled else poly)


def _shrink(region: BaseGeometry, margin: float) -> BaseGeometry:
    return region.buffer(-margin, join_style="mitre") if margin > 0 else region


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


def _angle_to(vec: np.ndarray, target: np.ndarray, n: np.ndarray) -> float | None:
    """Angle about ``n`` taking ``vec`` onto ``target`` (both projected); None if degenerate."""
    pv = vec - np.dot(vec, n) * n
    pt = target - np.dot(target, n) * n
    if np.linalg.norm(pv) < 1e-3 or np.linalg.norm(pt) < 1e-3:
        return None
    pv /= np.linalg.norm(pv)
    pt /= np.linalg.norm(pt)
    return float(np.arctan2(np.dot(np.cross(pv, pt), n), np.dot(pv, pt)))


def _wrap(a: float) -> float:
    return float((a + np.pi) % (2 * np.pi) - np.pi)


# ----------------------------------------------------------------- support resolution
def _support_candidates(st: _State, edge: Edge, child_h: float) -> list[_Support]:
    """World support surfaces the child may be placed on, for its support edge."""
    scene = st.scene
    ref = edge.parent
    rel = edge.relation
    label = ref.surface or edge.spec.parent_surface
    if ref.is_room_element:
        if ref.object == "wall":
            names = [n for n in scene.room.elements if n.startswith("wall_")]
        else:
            names = [ref.object]
        out = []
        for nm in names:
            s = _room_surface(scene, nm)
            out.append(_Support(s, "room", nm, s.label, s.polygon))
        return out
    parent = scene.objects[ref.object]
    if not parent.placed:
        raise _Fail(f"parent {ref.object!r} was not placed")
    T = parent.transform()
    parts = _parts_for(parent.asset, ref)
    if not parts:
        raise _Fail(f"{ref.object!r} ({parent.asset.asset_id}) has no part {ref.part!r}"
                    + (f" #{ref.index}" if ref.index is not None else ""))
    out = []
    if rel == "IN":
        names = {p.name for p in parts}
        for ins in parent.asset.internal:
            if ins.part in names:
                s = ins.surface.transformed(T)
                out.append(_Support(s, parent.id, ins.part, "top", s.polygon,
                                    ins.clearance * parent.scale))
        if not out:
            raise _Fail(f"IN: {ref} has no internal support surface"
                        f" (parts: {', '.join(sorted({p.label for p in parts}))})")
        return out
    want = {"ON": np.array([0, 0, 1.0]), "HANGING_BELOW": np.array([0, 0, -1.0])}.get(rel)
    for p in parts:
        labels = [label] if (ref.surface or rel != "ON") else ["top"]
        for lb in labels:
            s = p.surfaces[lb].transformed(T)
            if want is not None and np.dot(s.normal, want) < np.cos(np.deg2rad(5)):
                continue
            # an object ON a rim spans its hole (a plate on a plate): fill the holes
            region = _filled(s.polygon) if rel == "ON" else s.polygon
            out.append(_Support(s, parent.id, p.name, lb, region))
    if not out:
        raise _Fail(f"{rel}: no surface of {ref} faces the right way for {rel}")
    if rel == "ON" and ref.surface is None and len(out) > 1:
        out.sort(key=lambda s: -s.surface.origin[2])
    return out


# --------------------------------------------------------------------- rotations
def _contact_normal(asset: Asset, ref: Ref, default_label: str) -> np.ndarray:
    return np.array(SURFACES[ref.surface or default_label], float)


def _part_surface_world(st: _State, ref: Ref, default_label: str) -> tuple[Surface, str, str]:
    """World surface of a parent reference (object part or room element)."""
    scene = st.scene
    label = ref.surface or default_label
    if ref.is_room_element:
        if ref.object == "wall":
            raise _Fail("'wall' (any wall) can only be a support parent")
        return _room_surface(scene, ref.object), ref.object, scene.room.elements[ref.object].surface.label
    parent = scene.objects[ref.object]
    if not parent.placed:
        raise _Fail(f"parent {ref.object!r} was not placed")
    parts = _parts_for(parent.asset, ref)
    if not parts:
        raise _Fail(f"{ref.object!r} has no part {ref.part!r}")
    if ref.part is None:
        # the whole object's face: the bbox face of the asset
        from ..geometry.surfaces import surface_from_bbox

        s = surface_from_bbox(label, asset_geometry(parent.asset).bounds)
        return s.transformed(parent.transform()), "", label
    p = parts[0]
    return p.surfaces[label].transformed(parent.transform()), p.name, label


def _solve_rotation(st: _State, oid: str, asset: Asset, sup: _Support, support_edge: Edge,
                    edges: list[Edge], rng: np.random.Generator, strategy: str) -> tuple[np.ndarray, str | None, list]:
    """Rotation of the child; returns (R, toward_target, lean) with lean = (edge, theta, d)."""
    n_s = sup.surface.normal
    n_c = _contact_normal(asset, support_edge.child, support_edge.spec.child_surface)
    R0 = rotation_between(n_c, -n_s)
    horizontal = abs(n_s[2]) > 0.9
    phi: float | None = None
    source = None
    toward = None
    lean = None
    if not horizontal:
        phi = _upright_angle(R0, n_s)
        source = "upright"
    if strategy == "constrained":
        for e in edges:
            rel = e.relation
            if rel in ("AGAINST", "OPPOSITE_TO", "ALIGNED_WITH", "PARALLEL_TO", "LEANING_AGAINST"):
                sB, _, _ = _part_surface_world(st, e.parent, e.spec.parent_surface)
                nA = _contact_normal(asset, e.child, e.spec.child_surface)
                sign = 1.0 if rel in ("ALIGNED_WITH", "PARALLEL_TO") else -1.0
                ang = _angle_to(R0 @ nA, sign * sB.normal, n_s)
                if ang is None:
                    if abs(np.dot(R0 @ nA, sign * sB.normal) - 1) < 1e-3:
                        continue  # already satisfied whatever the angle
                    raise _Fail(f"{rel} {e.child} -> {e.parent}: the surfaces cannot be turned "
                                f"to face each other on this support")
                if phi is not None and abs(_wrap(ang - phi)) > np.deg2rad(1.0):
                    raise _Fail(f"{rel} {e.child} -> {e.parent} needs a different orientation "
                                f"than {source}")
                phi, source = ang, f"{rel} {e.child} -> {e.parent}"
                if rel == "LEANING_AGAINST":
                    lo, hi = e.param("angle_deg")
                    lean = (e, np.deg2rad(rng.uniform(lo, hi)), -sB.normal)
            elif rel == "TOWARD":
                toward = e.parent.object
        if phi is not None:
            toward = None  # the orientation is fixed by part-level constraints; TOWARD is checked
    if phi is None and toward is None:
        if strategy == "constrained" and rng.random() < 0.75:
            base = _room_axis_angle(st, R0, n_s)
            phi = base + rng.integers(4) * np.pi / 2 + rng.normal(0, np.deg2rad(2.0))
        else:
            phi = rng.uniform(0, 2 * np.pi)
    R = axis_angle(n_s, phi) @ R0 if phi is not None else R0
    if lean is not None:
        e, theta, d = lean
        k = np.cross(n_s, d)
        if np.linalg.norm(k) > 1e-6:
            R = axis_angle(k, theta) @ R
    return R, toward, [lean] if lean else []


def _room_axis_angle(st: _State, R0: np.ndarray, n_s: np.ndarray) -> float:
    """Angle about the support normal that aligns the child's front with wall_0's normal."""
    w0 = st.scene.room.elements.get("wall_0")
    if w0 is None:
        return 0.0
    a = _angle_to(R0 @ np.array([0, 1.0, 0]), w0.surface.normal, n_s)
    return a or 0.0


# ------------------------------------------------------------------- regions
def _obstacles(st: _State, sup: _Support, exclude: set[str], height: float) -> list[np.ndarray]:
    """Footprints (in the support plane) of placed objects in the slab above the support."""
    out = []
    n = sup.surface.normal
    horizontal = abs(n[2]) > 0.999
    if horizontal:  # footprints precomputed in world xy; the slab test is a z-range test
        sz = float(sup.surface.origin[2])
        keep = []
        for oid in st.hulls:
            if oid in exclude:
                continue
            z0, z1 = st.zr[oid]
            lo_h, hi_h = sorted(((z0 - sz) * n[2], (z1 - sz) * n[2]))
            if hi_h > 1e-3 and lo_h < height - 1e-3:
                keep.append(st.xy[oid])
        if keep:
            allxy = np.vstack(keep)
            uv = _plane_coords(sup.surface, np.c_[allxy, np.full(len(allxy), sz)])
            out.extend(np.split(uv, np.cumsum([len(k) for k in keep])[:-1]))
    for oid, pts in ([] if horizontal else st.hulls.items()):
        if oid in exclude:
            continue
        h = (pts - sup.surface.origin) @ n
        if h.max() <= 1e-3 or h.min() >= height - 1e-3:
            continue
        out.append(RG.convex_footprint(_plane_coords(sup.surface, pts)))
    # the supporting objects themselves are not whole obstacles, but their other parts are:
    # a cabinet's sides and back around its shelf, the other burners of a stove
    for oid in exclude:
        for _, pts in _world_pieces(st, oid):
            # the supporting piece itself lies below the plane and drops out of the slab test;
            # the rest of the support part (a cabinet body's sides) stays an obstacle
            h = (pts - sup.surface.origin) @ n
            if h.max() <= 1e-3 or h.min() >= height - 1e-3:
                continue
            out.append(RG.convex_footprint(_plane_coords(sup.surface, pts)))
    return out


def _world_pieces(st: _State, oid: str) -> list[tuple[str, np.ndarray]]:
    """(part name, world vertices) of every convex piece of a placed object (cached)."""
    got = st.pieces.get(oid)
    if got is None:
        o = st.scene.objects[oid]
        T = o.transform()
        got = [(p.name, pc.vertices @ T[:3, :3].T + T[:3, 3]) for p in o.asset.parts
               for pc in p.pieces]
        st.pieces[oid] = got
    return got


def _object_regions(st: _State, edges: list[Edge], sup: _Support, off: np.ndarray,
                    region: BaseGeometry, off3: np.ndarray) -> BaseGeometry:
    """Clip ``region`` (positions of the child origin) by the object-level relations.

    ``off`` is the child's centroid relative to its origin in plane coordinates, ``off3`` the
    same offset in the world (including the height above the plane).
    """
    s = sup.surface
    vertical = abs(float(s.normal[2])) < 0.5 and abs(float(s.v[2])) > 0.99
    for e in edges:
        rel = e.relation
        if rel not in ("SIDE_OF", "ALONG", "NEAR", "FAR_FROM"):
            continue
        xB, frame, hull = _parent_frame(st, e.parent.object)
        cB = _plane_coords(s, xB[None])[0] - off
        if rel in ("NEAR", "FAR_FROM") and vertical:
            # on a wall the plane's v axis is vertical: the horizontal distance (or the distance
            # to a wall's plane) depends on the position a along the wall only
            dist = e.param("distance")
            c = s.origin + off3 - xB
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
        elif rel in ("NEAR", "FAR_FROM") and hull is None:
            # a wall: distance to its plane
            nw = frame[:, 1]
            g = np.array([nw @ s.u, nw @ s.v])
            g /= max(np.linalg.norm(g), 1e-9)
            dist = e.param("distance")
            clip = RG.strip(cB, g, -1e-3, dist) if rel == "NEAR" else RG.strip(cB, g, dist, 1e3)
        elif rel in ("NEAR", "FAR_FROM"):
            d = RG.disk(cB, e.param("distance"), 48)
            clip = d if rel == "NEAR" else RG.bounding_square(region).difference(d)
        else:
            side = e.param("side")
            nw = frame @ np.array(_SIDE_DIRS[side])
            g = np.array([nw @ s.u, nw @ s.v])
            if np.linalg.norm(g) < 1e-6:
                raise _Fail(f"{rel} side {side!r} of {e.parent.object!r} is not in the support plane")
            g /= np.linalg.norm(g)
            if rel == "SIDE_OF":
                clip = RG.half_plane(cB, g)
            else:
                hB = 0.0 if hull is None else float(np.max(_plane_coords(s, hull) @ g - (cB + off) @ g))
                clip = RG.strip(cB, g, max(hB, 0.0), max(hB, 0.0) + e.param("width"))
        new = RG.clip(region, clip)
        if new.is_empty or new.area < 1e-10:
            raise _Fail(f"{rel} {e.child} -> {e.parent}"
                        f"{' side ' + e.param('side') if rel in ('SIDE_OF', 'ALONG') else ''}"
                        f" emptied the feasible region on {_sup_name(sup)}")
        region = new
    return region


def _parent_frame(st: _State, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """Centroid, rotation frame (columns: right, front, up) and hull points of a parent."""
    if name in st.scene.room.elements:
        s = st.scene.room.elements[name].surface
        front = s.normal
        up = np.array([0, 0, 1.0]) if abs(front[2]) < 0.9 else np.array([0, 1.0, 0])
        right = np.cross(front, up)
        return s.origin.copy(), np.c_[right, front, up], None
    o = st.scene.objects[name]
    if not o.placed:
        raise _Fail(f"parent {name!r} was not placed")
    return object_centroid(o), o.rotation, st.hulls[name]


def _support_chain(pag: PAG, oid: str) -> set[str]:
    """``oid`` and the objects below it in the support tree."""
    out = set()
    while oid is not None and oid not in out and oid in pag.objects:
        out.add(oid)
        e = pag.supporter(oid)
        oid = e.parent.object if e is not None else None
    return out


def _sup_name(sup: _Support) -> str:
    if sup.owner == "room":
        return sup.part
    return f"{sup.owner}:{sup.part}@{sup.label}"


def _part_lines(st: _State, oid: str, asset: Asset, scale: float, R: np.ndarray, h: float,
                edges: list[Edge], sup: _Support, region: BaseGeometry) -> BaseGeometry:
    """Intersect the region with the lines of part-level contact constraints."""
    s = sup.surface
    for e in edges:
        rel = e.relation
        if rel not in ("AGAINST", "ALIGNED_WITH", "OPPOSITE_TO", "LEANING_AGAINST"):
            continue
        sB, _, _ = _part_surface_world(st, e.parent, e.spec.parent_surface)
        nB = sB.normal
        g = np.array([s.u @ nB, s.v @ nB])
        if np.linalg.norm(g) < 1e-6:
            raise _Fail(f"{rel} {e.child} -> {e.parent}: the parent surface is parallel to the "
                        f"support, no position satisfies it")
        parts = _parts_for(asset, e.child)
        if not parts:
            raise _Fail(f"{e.child.object!r} has no part {e.child.part!r}")
        pts = (part_points(parts) * scale) @ R.T
        base = s.origin + h * s.normal
        if rel == "LEANING_AGAINST":
            # the named surface sets which side faces the parent; the object leans until its
            # extreme point toward the parent touches it (a guitar leans on its head)
            reach = float(np.max((asset_geometry(asset).hull * scale) @ R.T @ (-nB)))
            target = float(sB.origin @ (-nB)) - EPS
            # (a u + b v) . (-nB) = target - base . (-nB) - reach
            c = target - float(base @ (-nB)) - reach
            gg = -g
        else:
            label = e.child.surface or e.spec.child_surface
            if rel == "AGAINST":
                # contact: the named part's extreme point along its (rotated) surface normal
                nA_w = R @ np.array(SURFACES[label])
                pa = pts[int(np.argmax(pts @ nA_w))]
                gap = e.param("gap") + EPS
            else:
                pa = R @ _child_surface_point(parts, label, scale)
                gap = 0.0
            c = float(sB.origin @ nB) + gap - float((base + pa) @ nB)
            gg = g
        nrm = np.linalg.norm(gg)
        ln = RG.line(np.zeros(2), gg / nrm, c / nrm)
        new = RG.clip(region, ln)
        if new.is_empty:
            raise _Fail(f"{rel} {e.child} -> {e.parent} emptied the feasible region on {_sup_name(sup)}")
        region = new
    return region


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


# ---------------------------------------------------------------------- placing
def _place_object(st: _State, oid: str, rng: np.random.Generator, cfg: SolverConfig,
                  library) -> PlacedObject:
    pag = st.pag
    node = pag.objects[oid]
    edges = pag.edges_of(oid)
    support_edge = edges[0]
    others = edges[1:]
    last_fail = "no attempt"
    total_trials = 0
    for attempt in range(cfg.asset_attempts):
        category = node.candidates[int(rng.integers(len(node.candidates)))]
        asset = library.get(category, rng)
        # generators already make real-world sizes: keep them (times the node's scale range),
        # clamped so the size stays in the category's range (this normalises loaded assets)
        lo, hi = asset.size_range
        s_node = rng.uniform(*node.scale) if node.scale is not None else 1.0
        size = asset_geometry(asset).size
        scale = s_node * float(np.clip(1.0, lo / max(size, 1e-6), hi / max(size, 1e-6)))
        scale *= 0.92 ** attempt  # retries try a smaller instance
        try:
            pose, trials = _place_asset(st, oid, asset, scale, support_edge, others, rng, cfg)
        except _Fail as f:
            last_fail = str(f)
            total_trials += cfg.max_trials
            continue
        total_trials += trials
        R, t, sup, body = pose
        obj = PlacedObject(oid, category, asset, float(scale), R, t, "placed", None, total_trials,
                           _sup_name(sup))
        obj.fixed = support_edge.relation in ("SECURED_TO", "HANGING_BELOW")
        return obj, body
    raise _Fail(last_fail)


def _place_asset(st: _State, oid: str, asset: Asset, scale: float, support_edge: Edge,
                 others: list[Edge], rng: np.random.Generator, cfg: SolverConfig):
    geom = asset_geometry(asset)
    hull = geom.hull * scale
    b = asset_geometry(asset).bounds
    sups = _support_candidates(st, support_edge, child_h=float((b[1, 2] - b[0, 2]) * scale))
    order = rng.permutation(len(sups)) if len(sups) > 1 and support_edge.parent.surface is None \
        and support_edge.relation != "ON" else np.arange(len(sups))
    if support_edge.relation == "ON" and len(sups) > 1:
        order = np.arange(len(sups))
    if support_edge.parent.object == "wall" or (support_edge.relation == "IN" and len(sups) > 1):
        order = rng.permutation(len(sups))
    body = cached_body(asset.asset_id, scale, lambda: _scaled_mesh(asset, scale))
    reasons = []
    for variant in _wall_choices(st, others, rng):
        for si in order:
            sup = sups[int(si)]
            try:
                return _place_on(st, oid, asset, scale, hull, sup, support_edge, variant, body,
                                 rng, cfg)
            except _Fail as f:
                reasons.append(str(f))
    raise _Fail(reasons[0] if len(reasons) == 1 else "; ".join(dict.fromkeys(reasons)))


def _wall_choices(st: _State, edges: list[Edge], rng: np.random.Generator) -> list[list[Edge]]:
    """Edge lists with ``wall`` (any wall) replaced by each concrete wall, in random order."""
    if not any(e.parent.object == "wall" for e in edges):
        return [edges]
    walls = [n for n in st.scene.room.elements if n.startswith("wall_")]
    out = []
    for k in rng.permutation(len(walls)):
        w = walls[int(k)]
        out.append([replace(e, parent=replace(e.parent, object=w, text=""))
                    if e.parent.object == "wall" else e for e in edges])
    return out


def _scaled_mesh(asset: Asset, scale: float):
    m = asset.mesh()
    m.apply_scale(scale)
    return m


def _place_on(st: _State, oid: str, asset: Asset, scale: float, hull: np.ndarray, sup: _Support,
              support_edge: Edge, others: list[Edge], body: Body, rng: np.random.Generator,
              cfg: SolverConfig):
    s = sup.surface
    rel = support_edge.relation
    strategy = cfg.strategy
    R, toward, lean = _solve_rotation(st, oid, asset, sup, support_edge, others, rng, strategy)
    Y = hull @ R.T
    hN = Y @ s.normal
    height = float(hN.max() - hN.min())
    if rel == "IN" and height > sup.clearance:
        raise _Fail(f"IN: {oid} is {height:.2f} m tall but {_sup_name(sup)} has "
                    f"{sup.clearance:.2f} m of free height")
    drop = 0.0
    if rel == "HANGING_BELOW":
        lo, hi = support_edge.param("drop")
        drop = rng.uniform(lo, hi)
    h = -float(hN.min()) + EPS + drop
    # room elements are bounded by walls in the collision world; object supports keep a margin
    # (they only keep a hair's breadth from the corners, less than the contact gap EPS)
    region0 = _shrink(sup.region, EPS / 2) if sup.owner == "room" else _shrink(sup.region, cfg.margin)
    if region0.is_empty:
        region0 = sup.region  # tiny supports (a burner) keep their polygon; see overhang below
    # the support's owner and everything holding it up (a cabinet around a stack of plates)
    exclude = _support_chain(st.pag, sup.owner) if sup.owner != "room" else set()
    F = RG.convex_footprint(np.c_[Y @ s.u, Y @ s.v])
    overhang = False
    if strategy == "constrained":
        obst = _obstacles(st, sup, exclude, height + EPS)
        if rel == "HANGING_BELOW":
            # what hangs needs its attachment (the points touching the parent) on the parent's
            # surface, not its whole footprint: a towel is wider than the bar it hangs from
            top = Y[hN <= hN.min() + 2e-3]
            Fc = RG.convex_footprint(np.vstack([np.c_[top @ s.u, top @ s.v],
                                                np.c_[top @ s.u, top @ s.v] + 1e-4]))
            region = RG.clip(RG.erode(region0, [], Fc),
                             RG.erode(RG.bounding_square(region0, pad=5.0), obst, F))
        else:
            region = RG.erode(region0, obst, F)
            if (region.is_empty or region.area < 1e-10) and rel in ("ON", "IN") \
                    and sup.owner != "room" and RG.erode(region0, [], F).is_empty \
                    and Polygon(F).area <= 1.5 * Polygon(st.xy[sup.owner]).area:
                # a support smaller than the child (a pot on a burner, an apple in a bowl):
                # the paper's stability rule, centre of mass over the support polygon, decides;
                # only for children no bigger than the parent object (no wardrobe on a mug)
                com = (asset_geometry(asset).com * scale) @ R.T
                region = shapely.affinity.translate(region0, -float(com @ s.u), -float(com @ s.v))
                region = RG.clip(region, RG.erode(RG.bounding_square(region0, pad=5.0), obst, F))
                # and stay inside the room
                room = st.scene.room.elements["floor"].surface
                fp = Polygon(_plane_coords(s, room.to_3d(np.asarray(room.polygon.exterior.coords))))
                region = RG.clip(region, RG.erode(fp, [], F))
                overhang = True
        if region.is_empty or region.area < 1e-10:
            raise _Fail(f"no free space on {_sup_name(sup)} for a "
                        f"{np.ptp(F[:, 0]):.2f} x {np.ptp(F[:, 1]):.2f} m footprint")
        c_off = np.array([(geom_center(asset) * scale) @ R.T @ s.u,
                          (geom_center(asset) * scale) @ R.T @ s.v])
        off3 = (geom_center(asset) * scale) @ R.T + h * s.normal
        region = _object_regions(st, others, sup, c_off, region, off3)
        if rel == "SECURED_TO":
            region = _height_band(asset, scale, R, s, support_edge, region, sup)
        region = _part_lines(st, oid, asset, scale, R, h, others, sup, region)
    else:
        region = region0
    trials = 0
    last = "no sample"
    samples = RG.sample_uniform(region, rng, cfg.max_trials)  # one triangulation, all draws
    same = 0
    for k in range(cfg.max_trials):
        trials += 1
        if strategy == "rejection":
            R, toward, lean = _solve_rotation(st, oid, asset, sup, support_edge, others, rng, strategy)
            hN = (hull @ R.T) @ s.normal
            h = -float(hN.min()) + EPS + drop
        ab = samples[k]
        Rt = R
        if toward is not None and strategy == "constrained":
            t0 = s.origin + ab[0] * s.u + ab[1] * s.v + h * s.normal
            target = _parent_frame(st, toward)[0]
            front = R @ np.array([0, 1.0, 0])
            ang = _angle_to(front, target - t0, s.normal)
            if ang is not None:
                Rt = axis_angle(s.normal, ang) @ R
                hN2 = (hull @ Rt.T) @ s.normal
                h = -float(hN2.min()) + EPS + drop
        t = s.origin + ab[0] * s.u + ab[1] * s.v + h * s.normal
        cand = PlacedObject(oid, asset.category, asset, scale, Rt, t)
        if rel == "ON" and sup.owner != "room":
            # settle onto the parent's actual geometry: a plate on a plate sits in its well
            parent = st.scene.objects[sup.owner]
            d = drop_distance(world_points(cand, hull_only=True), asset, cand.transform(),
                              st.hulls[sup.owner], parent.asset, parent.transform(), -s.normal)
            if np.isfinite(d) and d > 2 * EPS:
                t = t - (d - EPS) * s.normal
                cand = PlacedObject(oid, asset.category, asset, scale, Rt, t)
        # footprint inside the support polygon: the region guarantees it, except after a TOWARD
        # turn and for rejection samples
        if not overhang and (Rt is not R or strategy == "rejection"):
            Fw = _plane_coords(s, world_points(cand, hull_only=True))
            if not region0.contains(Polygon(RG.convex_footprint(Fw))):
                last = f"footprint leaves {_sup_name(sup)}"
                continue
        ok, why = _validate(st, cand, support_edge, others, sup)
        if not ok:
            # the region makes relations hold by construction; the same relation failing
            # again and again is structural (a pan that would tip, a part that is not the
            # lowest one): stop wasting samples on this asset
            rel_of = why.split(":")[0]
            same = same + 1 if rel_of == last.split(":")[0] else 1
            last = why
            if same >= STRUCTURAL_FAILURES:
                break
            continue
        body.move(Rt, t)
        hit = st.world.collides(body)
        if hit is not None:
            last = f"collides with {hit}"
            continue
        return (Rt, t, sup, body), trials
    raise _Fail(f"no valid pose on {_sup_name(sup)} in {trials} trials (last: {last})")


def _height_band(asset: Asset, scale: float, R: np.ndarray, s: Surface, edge: Edge,
                 region: BaseGeometry, sup: _Support) -> BaseGeometry:
    """Clip origin positions on a vertical support to the centre-height range ``height``."""
    lo, hi = edge.param("height")
    vz = float(s.v[2])
    if abs(vz) < 0.5:
        return region
    c_off = float(((geom_center(asset) * scale) @ R.T)[2])
    v_lo = (lo - c_off - s.origin[2]) / vz
    v_hi = (hi - c_off - s.origin[2]) / vz
    out = RG.clip(region, shapely.box(-1e3, min(v_lo, v_hi), 1e3, max(v_lo, v_hi)))
    if out.is_empty:
        raise _Fail(f"SECURED_TO height {lo}-{hi} m: no free space at that height on {_sup_name(sup)}")
    return out


def geom_center(asset: Asset) -> np.ndarray:
    return asset_geometry(asset).center


def _validate(st: _State, cand: PlacedObject, support_edge: Edge, others: list[Edge],
              sup: _Support) -> tuple[bool, str]:
    results = []
    for e in [support_edge, *others]:
        holds, res, detail = check_edge(st.scene, e, cand, resolved=_resolution(e, sup))
        if not holds:
            return False, f"{e.relation} {e.child} -> {e.parent}: {detail}"
        results.append((holds, res, detail))
    st.accepted = results  # the checks of the pose that will be kept, in edge order
    return True, ""


def _resolution(edge: Edge, sup: _Support) -> dict | None:
    if not edge.is_support:
        return None
    return {"parent_part": sup.part if sup.owner != "room" else None,
            "parent_element": sup.part if sup.owner == "room" else None,
            "parent_surface": sup.label, "internal": edge.relation == "IN"}


# ------------------------------------------------------------------------ driver
def solve_scene(pag: PAG, *, seed: int = 0, library=None, config: SolverConfig | None = None) -> Scene:
    """Solve a validated PAG into a Scene (failed objects are marked, never raised)."""
    from ..measure.checks import check_relations
    from .library import default_library

    cfg = config or SolverConfig()
    library = library or default_library()
    t0 = time.perf_counter()
    shell = build_shell(pag.room, wall_thickness=cfg.wall_thickness)
    scene = Scene(pag, int(seed), shell, meta={"solver": cfg.to_dict()})
    world = CollisionWorld()
    for name, el in shell.elements.items():
        world.add(f"room:{name}", Body.from_mesh(el.mesh))
    st = _State(pag, scene, world)
    order = assembly_order(pag)
    edge_index = {id(e): i for i, e in enumerate(pag.relations)}
    failed: dict[str, str] = {}
    for oid in order:
        node = pag.objects[oid]
        rng = stage_rng(seed, f"object:{oid}")
        blocked = next((e.parent.object for e in pag.edges_of(oid)
                        if e.parent.object in failed), None)
        if blocked is not None:
            failed[oid] = f"depends on {blocked!r}, which failed"
            scene.objects[oid] = PlacedObject(oid, node.candidates[0], None, status="failed",
                                              reason=failed[oid])
            continue
        try:
            obj, body = _place_object(st, oid, rng, cfg, library)
        except _Fail as f:
            failed[oid] = str(f)
            scene.objects[oid] = PlacedObject(oid, node.candidates[0], None, status="failed",
                                              reason=str(f), trials=cfg.max_trials * cfg.asset_attempts)
            continue
        scene.objects[oid] = obj
        # the checks computed when the pose was accepted are final: parents never move later
        for e, r in zip(pag.edges_of(oid), st.accepted, strict=False):
            st.known[edge_index[id(e)]] = r
        st.hulls[oid] = world_points(obj, hull_only=True)
        st.xy[oid] = RG.convex_footprint(st.hulls[oid][:, :2])
        st.zr[oid] = (float(st.hulls[oid][:, 2].min()), float(st.hulls[oid][:, 2].max()))
        body.move(obj.rotation, obj.position)
        world.add(oid, body)
        sup_edge = pag.edges_of(oid)[0]
        st.resolved[pag.relations.index(sup_edge)] = _resolution_from_obj(obj, sup_edge)
    scene.meta["resolved"] = {str(k): v for k, v in st.resolved.items()}
    scene.timings["solve"] = time.perf_counter() - t0
    t1 = time.perf_counter()
    scene.relations = check_relations(scene, known=st.known)
    scene.timings["check"] = time.perf_counter() - t1
    scene.meta["trials"] = {o.id: o.trials for o in scene.objects.values()}
    return scene


def _resolution_from_obj(obj: PlacedObject, edge: Edge) -> dict:
    sup = obj.support or ""
    if edge.parent.is_room_element:
        return {"parent_part": None, "parent_element": sup, "parent_surface": None,
                "internal": False}
    owner, rest = sup.split(":", 1)
    part, label = rest.split("@", 1)
    return {"parent_part": part, "parent_element": None, "parent_surface": label,
            "internal": edge.relation == "IN"}
