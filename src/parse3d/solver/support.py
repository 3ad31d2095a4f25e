"""Stage 2 of Algorithm 1: the world surfaces a child may rest on, for its support relation."""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np
import shapely
import shapely.affinity
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry

from ..geometry.surfaces import Surface, hull_area_2d
from ..measure.checks import board_parts, on_board
from ..measure.geometry import part_points
from ..pag.model import Edge
from ..relations import SURFACES
from ..scene.model import SupportChoice
from .config import Fail, SolverConfig
from .geometry import ray_caster
from .state import SolveState, parts_for, plane_coords

__all__ = ["Support", "support_candidates"]


@dataclass
class Support:
    """A resolved support: a world surface and what it belongs to.

    Attributes
    ----------
    surface : Surface
        World frame; its normal is the support normal.
    choice : SupportChoice
        Owner (object id or ``room``), part (or room element) and surface label.
    region : shapely geometry
        Polygon in the ``(u, v)`` coordinates of ``surface``.
    clearance : float
        Free height above an internal surface (metres), ``inf`` elsewhere.
    holes : list of (K, 2) float
        Deep holes of the surface (a sink cut-out; not a plate's shallow well), in plane
        coordinates: filled in ``region``, obstacles for placement.
    spans : bool
        The surface spans several parts at one level (a luggage rack's straps): ``region`` is
        their convex hull, ``holes`` the gaps between them; what rests on it may straddle the
        gaps with its base on the parts.
    ring : bool
        The surface is a part's top that is a ring round an opening (a tub's rim; ``spans``,
        ``holes`` the opening): what is too big for the ring rests across the opening.
    reaches : tuple of str
        The parts of the owner ``region`` was carried up to (:func:`reach_to_parts`: a
        mattress's top to the headboard a pillow on it is against); empty when none.
    """

    surface: Surface
    choice: SupportChoice
    region: BaseGeometry
    clearance: float = float("inf")
    holes: list = field(default_factory=list)
    spans: bool = False
    ring: bool = False
    reaches: tuple = ()

    @property
    def owner(self) -> str:
        return self.choice.owner

    @property
    def part(self) -> str | None:
        return self.choice.part

    @property
    def label(self) -> str:
        return self.choice.surface

    @property
    def name(self) -> str:
        return self.choice.text


def filled(poly: BaseGeometry) -> BaseGeometry:
    """The polygon without its holes."""
    parts = list(poly.geoms) if hasattr(poly, "geoms") else [poly]
    out = [Polygon(p.exterior) for p in parts if isinstance(p, Polygon) and not p.is_empty]
    return shapely.union_all(out) if len(out) > 1 else (out[0] if out else poly)


_FLAT: dict[tuple[str, str, str], bool] = {}


def _flat_cached(asset_id: str, part, label: str) -> bool:
    key = (asset_id, part.name, label)
    got = _FLAT.get(key)
    if got is None:
        if len(_FLAT) > 8192:
            _FLAT.clear()
        got = _FLAT[key] = _flat_enough(part, label)
    return got


#: Metres: a part's top narrower than this over a lower, wider piece of it is the lip of a
#: channel (a whiteboard's marker tray), not where things lie.
LIP_WIDTH = 0.02
_CHANNEL: dict[tuple[str, str], Surface | None] = {}


def channel_floor(asset, part) -> Surface | None:
    """The floor of a channel-shaped part, in the asset frame: the top face of its widest
    convex piece lying lower than its top, when its top surface is a lip narrower than
    ``LIP_WIDTH`` and that face is at least twice as wide and 3 cm wide. None otherwise."""
    key = (asset.asset_id, part.name)
    if key not in _CHANNEL:
        got = None
        top = part.surfaces.get("top")
        if top is not None and len(part.piece_arrays) > 1 \
                and _sides(filled(top.polygon))[0] < LIP_WIDTH:
            best = None
            for pc in part.piece_arrays:
                z = float(pc.vertices[:, 2].max())
                if z >= float(top.origin[2]) - 5e-3:
                    continue
                near = pc.vertices[pc.vertices[:, 2] >= z - 2e-3]
                if len(near) < 3:
                    continue
                face = shapely.MultiPoint(near[:, :2]).convex_hull
                w = _sides(face)[0]
                if w >= max(2 * _sides(filled(top.polygon))[0], 0.03) \
                        and (best is None or face.area > best[1].area):
                    best = (z, face)
            if best is not None:
                z, face = best
                # between its walls: less the pieces rising above the floor (the lips)
                walls = [shapely.MultiPoint(pc.vertices[:, :2]).convex_hull
                         for pc in part.piece_arrays if float(pc.vertices[:, 2].max()) > z + 2e-3]
                inner = face.difference(shapely.union_all(walls)) if walls else face
                if inner.geom_type == "Polygon" and not inner.is_empty \
                        and _sides(inner)[0] >= 0.03:
                    face = inner
                c = np.array([face.centroid.x, face.centroid.y])
                poly = shapely.affinity.translate(face, -c[0], -c[1])
                got = Surface("top", np.array([c[0], c[1], z]), np.array([0.0, 0.0, 1.0]),
                              np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0]), poly)
        if len(_CHANNEL) > 8192:
            _CHANNEL.clear()
        _CHANNEL[key] = got
    return _CHANNEL[key]


def _sides(poly) -> tuple[float, float]:
    """The short and long sides of a polygon's minimum rotated rectangle."""
    r = poly.minimum_rotated_rectangle
    if r.geom_type != "Polygon":
        return 0.0, float(r.length) if hasattr(r, "length") else 0.0
    xy = np.asarray(r.exterior.coords)[:3]
    a, b = float(np.linalg.norm(xy[1] - xy[0])), float(np.linalg.norm(xy[2] - xy[1]))
    return min(a, b), max(a, b)


#: Share of a part's top another part lying on it must cover to be the top instead (a
#: dryer's control panel over its body): what is ON the part stands on that part.
COVERS = 0.9
_COVER: dict[tuple[str, str], str | None] = {}


def outer_tops(asset, parts: list) -> list:
    """The members of a group label whose tops are the group's outside: ``ON dresser:body@top``
    means the carcass's top panel, not the bottom panel inside it under a shelf or the top.

    A member is dropped when another member of the same group lies above its top (bottom at or
    above that top, less 1 cm) over half or more of its footprint (bounding boxes, in the
    asset's frame). A group whose members all lie side by side keeps every member.
    """
    if len(parts) < 2:
        return parts
    b = np.array([p.bounds for p in parts])  # (n, 2, 3)
    area = np.prod(np.maximum(b[:, 1, :2] - b[:, 0, :2], 0.0), axis=1)
    keep = []
    for i, p in enumerate(parts):
        top = b[i, 1, 2]
        over = np.maximum(np.minimum(b[:, 1, :2], b[i, 1, :2])
                          - np.maximum(b[:, 0, :2], b[i, 0, :2]), 0.0).prod(axis=1)
        above = (b[:, 0, 2] >= top - 0.01) & (over >= 0.5 * area[i]) & (area[i] > 0)
        above[i] = False
        if not above.any():
            keep.append(p)
    return keep or parts


def cover_part(asset, part):
    """The part lying on ``part``'s top (its bottom within 1 cm above it) whose footprint
    covers ``COVERS`` of that top and whose own top is flat: ``ON dryer:body@top`` stands on
    the dryer's control panel when the panel covers the body. None when there is none."""
    key = (asset.asset_id, part.name)
    if key not in _COVER:
        got = None
        top = part.surfaces.get("top")
        if top is not None:
            area = filled(top.polygon).area
            for q in asset.parts:
                if q is part or "top" not in q.surfaces or not q.piece_arrays:
                    continue
                pts = np.vstack([pc.vertices for pc in q.piece_arrays])
                h = (pts - top.origin) @ top.normal
                if not -1e-3 <= float(h.min()) <= 0.01:
                    continue
                foot = shapely.union_all([  # per convex piece: a rail round a shelf is a frame
                    shapely.MultiPoint(np.c_[(pc.vertices - top.origin) @ top.u,
                                             (pc.vertices - top.origin) @ top.v]).convex_hull
                    for pc in q.piece_arrays])
                if area > 0 and foot.intersection(filled(top.polygon)).area >= COVERS * area \
                        and _flat_cached(asset.asset_id, q, "top"):
                    got = q.name
                    break
        if len(_COVER) > 8192:
            _COVER.clear()
        _COVER[key] = got
    name = _COVER[key]
    return None if name is None else asset.part(name)


def _flat_enough(part, label: str, tol: float = 0.02, frac: float = 0.2) -> bool:
    """Whether the part's geometry really reaches its bbox face ``label`` over an area.

    A slanted part (an open piano lid) touches its bbox top only along an edge: the convex hull
    of its points within ``tol`` (m) of the face covers less than ``frac`` of the face.
    """
    n = np.asarray(SURFACES[label], float)
    axes = [i for i in range(3) if abs(n[i]) < 0.5]
    pieces = part.piece_arrays
    pts = np.vstack([pc.vertices for pc in pieces]) if pieces else part.vertices
    h = pts @ n
    face = np.ptp(pts[:, axes], axis=0)
    near = pts[h >= h.max() - tol][:, axes]
    if len(near) < 3 or face.prod() <= 0:
        return len(near) >= 3
    area = hull_area_2d(near)
    return area > 0 and area >= frac * float(face.prod())


def _holes(poly: BaseGeometry) -> list[np.ndarray]:
    parts = list(poly.geoms) if hasattr(poly, "geoms") else [poly]
    return [np.asarray(r.coords)[:-1] for p in parts if isinstance(p, Polygon)
            for r in p.interiors]


#: Metres below an ON surface within which a hole has a floor (a plate's well); a deeper hole
#: (a sink cut in a countertop) is no support.
HOLE_DEPTH = 0.03


def _deep_holes(s: Surface, holes: list[np.ndarray], parent, which: tuple[str, str],
                ) -> list[np.ndarray]:
    """The holes of a world surface with nothing of the parent within ``HOLE_DEPTH`` below
    (rays cast down from points inside the hole, in the parent's asset frame; cached per
    asset and surface)."""
    if not holes:
        return []
    key = (parent.asset.asset_id, *which, len(holes))
    deep = _DEEP.get(key)
    if deep is None:
        deep = _DEEP[key] = _hole_depths(s, holes, parent)
        if len(_DEEP) > 8192:
            _DEEP.clear()
    return [h for h, d in zip(holes, deep, strict=True) if d]


_DEEP: dict[tuple, list[bool]] = {}


def _hole_depths(s: Surface, holes: list[np.ndarray], parent) -> list[bool]:
    """Per hole, whether it is deeper than ``HOLE_DEPTH``."""
    T = parent.transform()
    Ti = np.linalg.inv(T)
    out = []
    for h in holes:
        poly = Polygon(h)
        inner = poly.buffer(-0.1 * np.sqrt(max(poly.area, 1e-12)))
        pts2 = [np.array(inner.representative_point().coords[0])] if not inner.is_empty else []
        pts2.append(np.array(poly.representative_point().coords[0]))
        start = np.array([s.to_3d(np.asarray(p)[None])[0] + 1e-3 * s.normal for p in pts2])
        o = start @ Ti[:3, :3].T + Ti[:3, 3]
        v = Ti[:3, :3] @ (-s.normal)
        k = float(np.linalg.norm(v))
        locs, idx, _ = ray_caster(parent.asset).first_hits(o, np.tile(v / k, (len(o), 1)))
        depth = np.full(len(o), np.inf)
        for loc, i in zip(locs, idx, strict=True):
            depth[i] = min(depth[i], float(np.linalg.norm(loc - o[i])) / k)
        out.append(bool(float(depth.min()) > HOLE_DEPTH))
    return out


#: Metres: the pieces of a part whose tops lie this close to the level of its top surface
#: make its rim together (a built-in tub's four walls).
RIM_LEVEL = 5e-3

#: Metres: gaps between the pieces' flat tops up to twice this wide are closed (the chamfers
#: where a built-in tub's bevelled walls meet at the corners).
RIM_GAP = 0.015

#: Metres below a piece's top within which its points make its flat top.
RIM_TOL = 3e-3


def ring_top(part, T: np.ndarray, s):
    """The top of ``part`` posed by ``T`` at the level of its top surface ``s`` when it is a
    ring around an opening, as a polygon with holes in the plane coordinates of ``s``; else
    None. The surface itself, when it has a hole (a freestanding tub's rolled rim); else the
    union of the flat tops of the part's convex pieces at that level (each piece's points
    within ``RIM_TOL`` of its top: a built-in tub's four walls), the gaps between them up to
    ``2 * RIM_GAP`` wide closed (their chamfers where they meet at the corners)."""
    if any(g.interiors for g in getattr(s.polygon, "geoms", [s.polygon])):
        return s.polygon
    n = s.normal
    tops = []
    for v in [pc.vertices for pc in part.piece_arrays] or [part.vertices]:
        w = np.asarray(v, float) @ T[:3, :3].T + T[:3, 3]
        h = (w - s.origin) @ n
        hi = float(h.max())
        if abs(hi) > RIM_LEVEL:
            continue
        tops.append(shapely.MultiPoint(plane_coords(s, w[h >= hi - RIM_TOL])).convex_hull)
    if len(tops) < 2:
        return None
    ring = shapely.union_all([g.buffer(RIM_GAP, join_style="mitre") for g in tops])
    ring = ring.buffer(-RIM_GAP, join_style="mitre")
    return ring if any(g.interiors for g in getattr(ring, "geoms", [ring])) else None


def _carrier(asset, ins) -> str:
    """The part whose geometry carries an internal surface: a drawer's floor is listed under
    its front (the part a PAG names) and under its box, and the box is what a child IN the
    drawer touches (so the support recorded and the contacts agree)."""
    if asset.part(ins.part).label != "drawer":
        return ins.part
    for other in asset.internal:
        if other.part != ins.part and asset.part(other.part).label == "drawer_box" \
                and np.allclose(other.surface.origin, ins.surface.origin, atol=1e-6) \
                and np.allclose(other.surface.normal, ins.surface.normal, atol=1e-6):
            return other.part
    return ins.part


def support_candidates(st: SolveState, edge: Edge) -> list[Support]:
    """World support surfaces the child may be placed on, for its support edge.

    Kept on the solve state per parent (:meth:`SolveState.memo`) while the parent keeps its
    pose: every child placed on a table asks for the same surfaces."""
    ref = edge.parent
    owner = "room" if ref.is_room_element else ref.object
    if owner != "room" and not st.scene.objects[ref.object].placed:
        raise Fail(f"parent {ref.object!r} was not placed")
    key = ("supports", edge.relation, ref.object, ref.part, ref.index, ref.surface,
           edge.spec.parent_surface)
    sups = list(st.memo(owner, key, lambda: _support_candidates(st, edge)))
    if edge.relation != "ON" or owner == "room":
        return sups
    # per child, after the kept surfaces: carried up to the faces this child is against
    return [reach_to_parts(st, edge, st.scene.objects[owner], sup) for sup in sups]



def best_support(st: SolveState, edge: Edge, key) -> Support | None:
    """The candidate support of ``edge`` (:func:`support_candidates`) with the largest
    ``key(support)``, or None when it has none yet (an unplaced parent, none that fits)."""
    try:
        sups = support_candidates(st, edge)
    except Fail:
        return None
    return max(sups, key=key) if sups else None

def _support_candidates(st: SolveState, edge: Edge) -> list[Support]:
    scene = st.scene
    ref = edge.parent
    rel = edge.relation
    label = ref.surface or edge.spec.parent_surface
    if ref.is_room_element:
        names = ([n for n in scene.room.elements if n.startswith("wall_")]
                 if ref.object == "wall" else [ref.object])
        out = []
        for nm in names:
            s = scene.room.elements[nm].surface
            out.append(Support(s, SupportChoice("room", nm, s.label), s.polygon))
        return out
    parent = scene.objects[ref.object]
    if not parent.placed:
        raise Fail(f"parent {ref.object!r} was not placed")
    T = parent.transform()
    parts = parts_for(parent.asset, ref)
    if not parts:
        raise Fail(f"{ref.object!r} ({parent.asset.asset_id}) has no part {ref.part!r}"
                   + (f" #{ref.index}" if ref.index is not None else ""))
    if rel == "ON" and label == "top" and ref.index is None \
            and ref.part in parent.asset.label_groups:
        parts = outer_tops(parent.asset, parts)  # a carcass's top panel, not its floor
    out, rings, like = [], [], rel == "ON" and _like(st, edge)
    if rel == "IN":
        names = {p.name for p in parts}
        seen: set[tuple] = set()
        for ins in parent.asset.internal:
            if ins.part in names:
                carrier = _carrier(parent.asset, ins)
                # one support per patch: a drawer's floor listed twice (under its front and
                # its box) once, a cradle's front and back bars each
                key = (carrier, *np.round(ins.surface.origin, 6).tolist())
                if key in seen:
                    continue
                seen.add(key)
                s = ins.surface.transformed(T)
                out.append(Support(s, SupportChoice(parent.id, carrier, "top"), s.polygon,
                                   ins.clearance * parent.scale))
        if not out and not on_board(parent, ref):
            out = _inside_of(parent, parts, T)
        if out:
            return _span_bars(out)
        if not on_board(parent, ref):
            raise Fail(f"IN: {ref} has no internal support surface"
                       f" (parts: {', '.join(sorted({p.label for p in parts}))})")
        rel, label = "ON", "top"  # a board holds what is IN it on its top (a wall shelf)
        if ref.part is None:
            parts = board_parts(parent.asset)  # IN the whole shelf: on its boards
    want = {"ON": np.array([0, 0, 1.0]), "HANGING_BELOW": np.array([0, 0, -1.0])}.get(rel)
    slanted = []
    if rel == "ON" and ref.part is not None and label == "top":
        # a part whose top another part covers (a dryer's body under its control panel):
        # what is ON it stands on that part; not when the parent lies on another face (a
        # notebook on its cover: its spine along the cover's upper edge covers no top)
        parts = [(cover_part(parent.asset, p) if _world_top(p, T) == "top" else None) or p
                 for p in parts]
    for p in parts:
        labels = [label] if (ref.surface or rel != "ON") else ["top"]
        for lb in labels:
            s = p.surfaces[lb].transformed(T)
            if rel == "ON" and lb == "top" and np.dot(s.normal, want) < np.cos(np.deg2rad(5)):
                # the parent lies on another face (a notebook on its cover): its part's top
                # is the face that is up now (its front cover's outer face)
                lb = _world_top(p, T) or lb
                s = p.surfaces[lb].transformed(T)
            if want is not None and np.dot(s.normal, want) < np.cos(np.deg2rad(5)):
                continue
            if rel == "ON" and not _flat_cached(parent.asset.asset_id, p, lb):
                slanted.append(p.name)
                continue
            # an object ON a rim spans its hole (a plate on a plate); placement keeps a child
            # smaller than a hole (a bottle by a sink cut-out) off it
            region = filled(s.polygon) if rel == "ON" else s.polygon
            holes = _deep_holes(s, _holes(s.polygon), parent, (p.name, lb)) if rel == "ON" else []
            if rel == "ON" and lb == "top" and ref.part is not None \
                    and (floor := channel_floor(parent.asset, p)) is not None:
                # a channel (a whiteboard's tray): what is ON it lies on its floor, between
                # its lips; the lip's top after
                f = floor.transformed(T)
                out.append(Support(f, SupportChoice(parent.id, p.name, lb), f.polygon))
            out.append(Support(s, SupportChoice(parent.id, p.name, lb), region, holes=holes))
            if rel == "ON" and lb == "top" and not like and (ring := ring_top(p, T, s)) is not None \
                    and (deep := _deep_holes(s, _holes(ring), parent, (p.name, "ring"))):
                # a ring round an opening (a tub's rim): across it, after the rest (bars.py);
                # not for one of the parent's kind (a basket on a basket nests or stacks)
                whole = filled(ring)
                rings.append(Support(replace(s, polygon=whole), SupportChoice(parent.id, p.name, lb),
                                     whole, holes=deep, spans=True, ring=True))
    if not out:
        if slanted:
            raise Fail(f"{rel}: {ref} has no flat upward surface ({', '.join(slanted)} only "
                       f"touches its bounding box's top along an edge: it is slanted)")
        raise Fail(f"{rel}: no surface of {ref} faces the right way for {rel}")
    if rel == "ON" and ref.surface is None and len(out) > 1:
        out.sort(key=lambda s: -s.surface.origin[2])
    if rel == "ON" and ref.part is not None and ref.index is None and len(out) > 1:
        span = _span(out)
        if span is not None:  # tried after each part alone
            out.append(span)
    if rel == "ON" and ref.part is not None and label == "top" and _like(st, edge):
        # a stack of like things named by a part of the lower one (a plate ON plate:well, a
        # jar ON jar:lid): the writer means the stack, so when the child does not fit that
        # part it rests on the lower one as a whole (the drop brings it into the well, or
        # onto the rim when it is too wide); tried after the part as written
        whole = replace(edge, parent=replace(ref, part=None, index=None, surface=None))
        named = {(o.choice.part, o.surface.label) for o in out}
        out += [o for o in _support_candidates(st, whole)
                if (o.choice.part, o.surface.label) not in named]
    return out + rings


#: How far (m) a top may end short of the face a child on it is against and still be carried
#: up to it: a mattress's rounded edge and the seam between it and its headboard, a
#: countertop's margin at the wall it stands against.
REACH = 0.08


def reach_to_parts(st: SolveState, edge: Edge, parent, sup: Support) -> Support:
    """``sup`` (the top of one part of ``parent``) with its region carried up to a face the
    child is ``AGAINST`` that stands up beside the top, when the region ends at most
    :data:`REACH` short of it: another part of ``parent`` (a pillow ON a mattress AGAINST the
    bed's headboard: the flat of a soft top stops short of its rounded edge and the seam
    before the headboard) or a room wall (a microwave ON a countertop AGAINST the wall the
    counter stands against: an object's top keeps a margin from its edge that would keep the
    child off the wall). The child bridges the gap, held by the top under its centre of mass
    and stopped by the face. Past the face by the support's default margin, which the region
    is inset by: then up to the face, not into it (the ``AGAINST`` line stops the child at
    it). Asked per child (the kept surfaces are the parent's). ``sup`` unchanged when no such
    contact is written or the region is not one convex polygon."""
    s, region = sup.surface, sup.region
    part = next((p for p in parent.asset.parts if p.name == sup.part), None)
    if part is None or sup.spans or not isinstance(region, Polygon) or region.is_empty \
            or region.area < 0.98 * region.convex_hull.area:
        return sup
    out, reached = region, []
    for name, sB in _faces_against(st, edge, parent, part, s):
        g = np.array([s.u @ sB.normal, s.v @ sB.normal])
        k = float(np.linalg.norm(g))
        if k < 0.5 or abs(float(sB.normal @ s.normal)) > 0.5:
            continue  # not a face standing up from the top
        g, c0 = g / k, float((sB.origin - s.origin) @ sB.normal) / k
        xy = np.asarray(region.exterior.coords)
        short = float((xy @ g).min()) - c0  # from the region to the face, along -g
        if not 0.0 < short <= REACH:
            continue
        shift = -(short + SolverConfig.margin) * g
        out = shapely.union(out, shapely.convex_hull(shapely.union(
            out, shapely.affinity.translate(out, *shift))))
        reached.append(name)
    if not reached:
        return sup
    return replace(sup, region=out, reaches=tuple(sorted(set(reached))))


def _faces_against(st: SolveState, edge: Edge, parent, part, s: Surface):
    """``(name, world surface)`` of the faces the child of ``edge`` is ``AGAINST`` that rise
    above the top ``s`` of ``part`` of ``parent``: the named parts of ``parent`` but ``part``,
    and room walls."""
    T = parent.transform()
    for e in st.pag.edges_of(edge.child.object):
        if e.relation != "AGAINST":
            continue
        ref = e.parent
        if ref.is_room_element:
            el = st.scene.room.elements.get(ref.object)
            if el is not None and ref.object.startswith("wall_"):
                yield ref.object, el.surface
            continue
        if ref.object != parent.id or ref.part is None:
            continue
        label = ref.surface or e.spec.parent_surface
        for q in parts_for(parent.asset, ref):
            if q.name == part.name or label not in q.surfaces:
                continue
            P = part_points([q]) @ T[:3, :3].T + T[:3, 3]
            if float((P @ s.normal).max() - s.origin @ s.normal) <= 1e-3:
                continue  # not rising above the top
            yield q.name, q.surfaces[label].transformed(T)


def _inside_of(parent, parts, T) -> list[Support]:
    """The parent's internal surfaces of other parts that lie within the bounding box of
    ``parts`` (asset frame, 1 cm of slack): IN a shopping basket's woven ``basket`` shell, the
    child rests on its ``base``, the floor the shell encloses."""
    pts = np.vstack([pc.vertices for p in parts for pc in p.piece_arrays]) \
        if any(p.piece_arrays for p in parts) else np.vstack([p.vertices for p in parts])
    lo, hi = pts.min(axis=0) - 0.01, pts.max(axis=0) + 0.01
    out, seen = [], set()
    for ins in parent.asset.internal:
        o = np.asarray(ins.surface.origin, float)
        key = (ins.part, *np.round(o, 6).tolist())
        if key in seen or not np.all((o >= lo) & (o <= hi)):
            continue
        seen.add(key)
        s = ins.surface.transformed(T)
        out.append(Support(s, SupportChoice(parent.id, _carrier(parent.asset, ins), "top"),
                           s.polygon, ins.clearance * parent.scale))
    return out


def _like(st: SolveState, edge: Edge) -> bool:
    """Whether the child and the parent of ``edge`` are of one kind (their PAG nodes share a
    category): a stack."""
    kids, parents = st.pag.objects.get(edge.child.object), st.pag.objects.get(edge.parent.object)
    return kids is not None and parents is not None \
        and bool(set(kids.candidates) & set(parents.candidates))


#: Metres within which parts' upward surfaces count as one level (a rack's straps or bars).
LEVEL_TOL = 5e-3

#: An internal patch narrower than this (metres) is a bar (a wine rack's cradle bar).
BAR_WIDTH = 0.03


def _bar_width(sup: Support) -> float:
    r = sup.region.minimum_rotated_rectangle
    xy = np.asarray(r.exterior.coords)[:3] if isinstance(r, Polygon) else None
    if xy is None:
        return 0.0
    return float(min(np.linalg.norm(xy[1] - xy[0]), np.linalg.norm(xy[2] - xy[1])))


def _span_bars(sups: list[Support]) -> list[Support]:
    """IN supports with, first, one support spanning the bars of one part at one level (a wine
    rack's cradle: a front and a back bar), so that what lies in the cradle rests across two
    bars instead of balancing on one; the bars alone follow (for a child too short to reach
    across)."""
    out, spans, done = [], [], set()
    for i, x in enumerate(sups):
        if i in done:
            continue
        if _bar_width(x) >= BAR_WIDTH:
            out.append(x)
            continue
        group = [k for k, y in enumerate(sups) if k not in done and y.choice == x.choice
                 and _bar_width(y) < BAR_WIDTH]
        span = _span([sups[k] for k in group]) if len(group) > 1 else None
        if span is None:
            out.append(x)
            continue
        level = [k for k in group
                 if abs(float((sups[k].surface.origin - x.surface.origin) @ x.surface.normal))
                 <= LEVEL_TOL]
        done.update(level)
        spans.append(replace(span, clearance=min(sups[k].clearance for k in level)))
        out += [sups[k] for k in level]
    return spans + out


def _exteriors(poly) -> list:
    """The exterior rings of a polygon or of each polygon of a collection."""
    return [g.exterior for g in getattr(poly, "geoms", [poly]) if isinstance(g, Polygon)]


def _span(sups: list[Support]) -> Support | None:
    """One support over the parts at the level of the first of ``sups`` (a luggage rack's
    three straps, a cradle's bars): their convex hull, with the gaps between them as holes;
    None when fewer than two parts share that level."""
    s0 = sups[0].surface
    level = [x for x in sups if abs(float((x.surface.origin - s0.origin) @ s0.normal)) <= LEVEL_TOL
             and np.allclose(x.surface.normal, s0.normal, atol=1e-6)]
    if len(level) < 2:
        return None
    pieces = []
    for x in level:
        # into the first one's plane frame (parts' frames may be turned: a round rug's border
        # and its field)
        xs = x.surface
        poly = filled(x.region)
        if poly.is_empty:
            continue
        rings = [np.asarray(r.coords) for r in _exteriors(poly)]
        for xy in rings:
            w = xs.origin + xy[:, :1] * xs.u + xy[:, 1:2] * xs.v - s0.origin
            pieces.append(Polygon(np.c_[w @ s0.u, w @ s0.v]).buffer(0))
    union = shapely.union_all(pieces)
    hull = union.convex_hull
    # opened by a micrometre: the difference leaves zero-width spikes along the hull's edge,
    # which would turn a gap's convex footprint over a part (a strap's corner cut off)
    gaps = hull.difference(union).buffer(-1e-6, join_style="mitre").buffer(1e-6,
                                                                          join_style="mitre")
    holes = [np.asarray(g.exterior.coords)[:-1] for g in getattr(gaps, "geoms", [gaps])
             if isinstance(g, Polygon) and not g.is_empty and g.area > 1e-8]
    return Support(replace(s0, polygon=hull), sups[0].choice, hull, holes=holes, spans=True)


def _world_top(part, T: np.ndarray) -> str | None:
    """The label of ``part``'s surface whose normal points up under the pose ``T`` (within
    5 degrees), or None."""
    for lb, n in SURFACES.items():
        d = T[:3, :3] @ np.asarray(n, float)  # T scales the object: its direction only
        if lb in part.surfaces and float(d[2]) >= np.cos(np.deg2rad(5)) * np.linalg.norm(d):
            return lb
    return None
