"""Several things hanging below one rail: towels along a towel bar, cloths on a heated rail.

What hangs below an object's part shares that part's length with the other objects hanging
below the same parent: each is drawn, within its category's size range, no wider along the rail
than an equal share of the rail's length (:func:`rail_fit`), so the last of three towels finds
room beside the other two instead of failing with "towel_1 in the way". A thin thing hung
edge-up (a folded towel) is drawn thinnest-first among the instances looked at
(:func:`thinness`): its thickness stands out from the rail toward the wall behind it. A rail
with several things to hang below it is drawn long enough for them, within its category's
size range (:func:`rail_scale`).

Cloth written ``ON`` a rod (a towel on a drying rack's rod, a sock on a rail) cannot lie on a
bar a centimetre thick: it hangs over it, held by the rod like a towel on a towel bar, and the
``ON`` is recorded relaxed with what to write instead (:func:`draped_over`).

Cloth hung on one rack drapes over what already hangs there (:func:`hung_over`): a second coat
on a coat tree whose hooks sit a hand apart goes on its hook over the first coat's shoulder,
as real coats do, instead of failing with "jacket1 in the way".

What hangs below a part keeps clear of the walls (:func:`off_wall`): a lidded pot wider than
the gap between a pot rail and the wall behind it hangs out from the wall on its hook.

A wall hook with something to hang below it keeps that room free (:func:`room_below`): a
second hook is put up where its hat will hang clear of the first hook's hat, not a hand beside
it, where the hat finds "hat1 in the way".
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import Any

import numpy as np

from ..assets.model import Asset
from ..pag.model import Edge
from .config import Fail
from .flush import clears_beside
from .geometry import asset_geometry, hull_extents, part_points, rect_sides
from .intent import overhang
from .rotation import HOOK_REACH
from .state import SolveState, plane_coords
from .support import support_candidates

__all__ = ["attachment_region", "below_room", "below_with_room", "hang_room", "HANG_CLEAR", "hangs_beside", "hung_by_part", "drapes", "draped_over", "edge_up", "hang_over", "hung_lengthwise", "hung_over", "off_wall", "off_wall_reason", "other_hook", "room_below", "hung_size",
           "rail_fit", "rail_scale", "rod_thickness", "thinness", "typical_size", "RAIL_GAP",
           "DRAPING", "ROD_THICK", "ROD_LONG"]

#: Share of a rail's length the objects hung on it may fill together (the rest: its brackets
#: and the gaps between them).
RAIL_GAP = 0.85


def _along(asset: Asset, up: int) -> float:
    """The asset's extent (unit scale) along a rail it hangs on: the longer of its two extents
    across its vertical axis ``up`` (a towel's width, not its thickness)."""
    ext = hull_extents(asset)[0]
    return float(max(ext[k] for k in range(3) if k != up))


def _rail_length(st: SolveState, edge: Edge) -> float:
    """Metres of rail below which the edge's child may hang: the longest extent of the
    longest support surface the parent reference resolves to (a double towel bar's back bar
    lies close to the wall: what hangs there may not fit, so they share one)."""
    try:
        sups = support_candidates(st, edge)
    except Fail:
        return 0.0
    out = 0.0
    for sup in sups:
        x0, y0, x1, y1 = sup.region.bounds
        out = max(out, x1 - x0, y1 - y0)
    return out


def typical_size(pag, oid: str) -> float:
    """The least middle of the size ranges of ``oid``'s candidate categories (metres; 0 when
    none is known): how big the writer's object is before an instance is drawn."""
    from ..assets import registry

    sizes = []
    for c in pag.objects[oid].candidates:
        try:
            lo, hi = registry.get(c).size_range
        except KeyError:
            continue
        sizes.append(0.5 * (lo + hi))
    return min(sizes, default=0.0)


def rail_scale(pag, oid: str, asset: Asset) -> float:
    """Scale at which ``asset`` (a towel bar, a coat rail) is long enough for the objects
    hung below one of its parts side by side, each at its category's typical size, in
    :data:`RAIL_GAP` of its length; 0 with fewer than two such objects."""
    groups: dict[tuple, list[str]] = {}
    for e in pag.relations:
        if e.relation == "HANGING_BELOW" and e.parent.object == oid \
                and e.parent.part is not None:
            groups.setdefault((e.parent.part, e.parent.index), []).append(e.child.object)
    need = 0.0
    for kids in groups.values():
        if len(kids) < 2:
            continue
        total = sum(typical_size(pag, k) for k in kids)
        need = max(need, total / RAIL_GAP)
    length = float(np.max(hull_extents(asset)[0][:2]))
    return need / max(length, 1e-6)


def rail_fit(st: SolveState, oid: str, edge: Edge, asset: Asset, scale: float,
             up: int) -> float:
    """``scale``, or less when the child (hanging with its asset axis ``up`` vertical) is
    wider than its share of the rail: :data:`RAIL_GAP` of the rail's length split equally
    among everything hung below the same parent reference. Never below the category's size
    range; unchanged for anything but HANGING_BELOW an object's part shared with other hung
    objects."""
    if edge.relation != "HANGING_BELOW" or edge.parent.is_room_element \
            or edge.parent.part is None:
        return scale
    sibs = [e for e in st.pag.relations if e.relation == "HANGING_BELOW"
            and e.child.object != oid and e.parent.object == edge.parent.object
            and e.parent.part == edge.parent.part and e.parent.index == edge.parent.index]
    if not sibs:
        return scale
    length = st.memo(edge.parent.object, ("rail-length", str(edge.parent)),
                     lambda: _rail_length(st, edge))
    share = RAIL_GAP * length / (1 + len(sibs))
    width = scale * _along(asset, up)
    if share <= 0 or width <= share:
        return scale
    lo = asset.size_range[0] / max(asset_geometry(asset).size, 1e-6)
    return max(scale * share / width, min(lo, scale))


def edge_up(edge: Edge) -> bool:
    """Whether a thin child of ``edge`` hangs edge-up: HANGING_BELOW an object's part, named
    by no surface or by its top (a towel hung flat by its top would stick out from the wall
    like a shelf)."""
    return edge.relation == "HANGING_BELOW" and edge.child.surface in (None, "top") \
        and not edge.parent.is_room_element


def thinness(asset: Asset) -> float:
    """An asset's height relative to its larger other extent (a folded towel lying: small):
    the thinnest hangs edge-up with the least standing out from the rail."""
    ext = hull_extents(asset)[0]
    return float(ext[2] / max(ext[0], ext[1], 1e-9))


#: A child is long when its longest extent is at least this multiple of its middle one.
LONG_HUNG = 1.5

#: Share of a long child's length from either end within which the centre of the part it is
#: hung by must lie for it to hang lengthwise from that end (a hammer's head, a screwdriver's
#: handle).
END_SHARE = 0.3

_END_LABELS = {0: ("left", "right"), 1: ("back", "front")}

#: Share of the length within which a part's bounds must reach an end of the child for the
#: part to count as that end though its centre lies further in (a stubby screwdriver's handle
#: is half its length).
END_REACH = 0.05


def _end_at(centre: float, lo: float, hi: float) -> float:
    """Where along the child's length (0 to 1) a part hung by sits for :func:`hung_lengthwise`:
    its centre, or the end it reaches when it spans from that end to short of the middle."""
    if lo <= END_REACH and centre < 0.5 - END_REACH:
        return 0.0
    if hi >= 1 - END_REACH and centre > 0.5 + END_REACH:
        return 1.0
    return centre


def hung_lengthwise(edge: Edge, asset: Asset) -> Edge | None:
    """The support edge by which a long child lying along its x or y axis (a hammer, a
    screwdriver) hangs lengthwise, the end holding the named part up: HANGING_BELOW an
    object's part by a named part near one end of its length, named by no surface or by its
    top (a hammer hung by its head from a pegboard hook hangs head up, handle down, not flat
    across the hook into the wall); None for anything else (the edge as written)."""
    c = edge.child
    if edge.relation != "HANGING_BELOW" or edge.parent.is_room_element or c.part is None \
            or c.surface not in (None, "top"):
        return None
    hull = np.asarray(asset.hull_vertices(), float)
    ext = np.ptp(hull, axis=0)
    a = int(np.argmax(ext))
    if a == 2 or ext[a] < LONG_HUNG * float(np.sort(ext)[1]):
        return None
    parts = asset.parts_by_label(c.part)
    if c.index is not None:
        parts = parts[c.index:c.index + 1]
    if not parts:
        return None
    # the named parts together, else the first of them at an end (a combination wrench's
    # heads at both ends: it hangs by one)
    groups = [np.vstack([np.asarray(p.bounds, float) for p in parts])] + \
        [np.asarray(p.bounds, float) for p in parts]
    lo, length = float(hull[:, a].min()), max(float(ext[a]), 1e-9)
    ats = [_end_at((float(np.mean(b[:, a])) - lo) / length,
                   (float(b[:, a].min()) - lo) / length, (float(b[:, a].max()) - lo) / length)
           for b in groups]
    at = next((x for x in ats if not END_SHARE < x < 1 - END_SHARE), None)
    if at is None:
        return None
    from ..pag.refs import format_ref

    label = _END_LABELS[a][0 if at <= END_SHARE else 1]
    return replace(edge, child=replace(c, surface=label,
                                       text=format_ref(c.object, c.part, c.index, label)))


#: Material families of things that drape: hung side by side they may lie over one another.
DRAPING = frozenset({"fabric", "leather", "paper"})


def drapes(asset: Asset) -> bool:
    """Whether ``asset`` is cloth-like: its largest part (by bounding box) is made of a
    :data:`DRAPING` material (a coat, a towel, a paper bag; not its hanger)."""
    best, vol = None, -1.0
    for p in asset.parts:
        v = float(np.prod(np.ptp(np.asarray(p.bounds, float), axis=0)))
        if v > vol:
            best, vol = p, v
    return best is not None and best.material is not None and best.material.name in DRAPING


def hung_over(st: SolveState, oid: str, edge: Edge, asset: Asset) -> frozenset[str]:
    """The placed objects that ``oid`` (``asset``, hung by ``edge``) may overlap: for a
    draping child HANGING_BELOW a part of an object, the draping objects already hanging below
    any part of that same object that no other relation ties to it (a towel the writer put
    SIDE_OF another hangs beside it); empty for anything else."""
    if edge.relation != "HANGING_BELOW" or edge.parent.is_room_element \
            or not drapes(asset):
        return frozenset()
    tied = {e.parent.object if e.child.object == oid else e.child.object
            for e in st.pag.relations if e is not edge and oid in (e.child.object, e.parent.object)}
    out = set()
    for e in st.pag.relations:
        if e.relation != "HANGING_BELOW" or e.parent.object != edge.parent.object:
            continue
        o = st.scene.objects.get(e.child.object)
        if o is None or not o.placed or o.id == oid or o.id in tied or o.asset is None:
            continue
        if drapes(o.asset):
            out.add(o.id)
    return frozenset(out)


#: Turns about its hook a draping thing is tried at over the others (each place call draws
#: one): a coat on the corner side of a coat tree swings clear of the walls.
SWINGS = 4


def hang_over(st: SolveState, oid: str, edge: Edge, asset: Asset, sups: list,
              place: Callable[[Any], Any]) -> Any | None:
    """``place(sup)`` for the first of ``sups`` where it succeeds with the draping things
    :func:`hung_over` allows ``oid`` to overlap left out of the way, at up to :data:`SWINGS`
    turns; then, where other things hang on the parent already, on its other parts with the
    named part's label, nearest the named one first (the next free hook of a coat tree: see
    :func:`other_hook`; alone on it, other instances are tried on the named hook). None when
    none holds it. Tried after the supports fail with the others in the way: a coat hangs
    beside the others where there is room, over them where there is not."""
    over = hung_over(st, oid, edge, asset)
    named = {sp.choice.part for sp in sups}
    crowded = any(e.relation == "HANGING_BELOW" and e.parent.object == edge.parent.object
                  and e.child.object != oid and e.child.object in st.hulls
                  for e in st.pag.relations)
    rest = [sp for sp in _same_label(st, edge) if sp.choice.part not in named] \
        if crowded else []
    if sups and rest:
        c = _centre(sups[0])
        rest.sort(key=lambda sp: float(np.linalg.norm(_centre(sp) - c)))
    with st.hidden(over):
        for group, turns in ((sups, SWINGS if over else 0), (rest, SWINGS)):
            for _ in range(turns):
                for sup in group:
                    try:
                        return place(sup)
                    except Fail:
                        continue
    for sup in below_with_room(st, edge):
        # no room below the named part (the arch of a luggage cart's rail, its hanger bar
        # right under it): on the part below it that has room, as a garment bag hangs there
        try:
            return place(sup)
        except Fail:
            continue
    return None


def below_with_room(st: SolveState, edge: Edge) -> list:
    """For ``edge`` HANGING_BELOW a part of an object that has no room below it for the child
    (:func:`hang_room` at the child's typical size), the supports of the parent's other parts
    right below it (under its outline, lower than its bottom) that have: a luggage cart's
    hanger bar under the arch of its rail. Nearest the named part first; empty for anything
    else."""
    ref = edge.parent
    if edge.relation != "HANGING_BELOW" or ref.is_room_element or ref.part is None:
        return []
    pobj = st.scene.objects.get(ref.object)
    depth = typical_size(st.pag, edge.child.object)
    if pobj is None or not pobj.placed or pobj.asset is None or depth <= 0:
        return []
    asset = pobj.asset
    d = depth / max(float(pobj.scale), 1e-6)  # the asset's own frame
    if hang_room(asset, ref.part, ref.index, d) is not None:
        return []
    labels = below_room(asset, ref.part, ref.index, d)
    from ..pag.refs import format_ref

    out = []
    for label in labels:
        text = format_ref(ref.object, label, None, ref.surface)
        try:
            out += support_candidates(st, replace(edge, parent=replace(
                ref, part=label, index=None, text=text)))
        except Fail:
            continue
    return out


def _centre(sup) -> np.ndarray:
    """World centre of a support's region."""
    s = sup.surface
    c = sup.region.centroid
    return s.origin + c.x * s.u + c.y * s.v


def _same_label(st: SolveState, edge: Edge) -> list:
    """Supports of every part of the parent with the named part's label (every hook of a coat
    tree, not only ``hook#1``): none for anything but HANGING_BELOW a part of an object."""
    if edge.relation != "HANGING_BELOW" or edge.parent.is_room_element \
            or edge.parent.part is None:
        return []
    try:
        return support_candidates(st, replace(edge, parent=replace(edge.parent, index=None)))
    except Fail:
        return []


def other_hook(st: SolveState, edge: Edge, sup, loose: str | None = None) -> str | None:
    """``loose`` (why the support edge is already relaxed, or None), and why ``edge``
    (HANGING_BELOW a part) is recorded relaxed when its child hangs on ``sup``, another part of
    the same label (the named hook taken, or facing a wall), or hung out from a part too close
    to the wall (:func:`off_wall`)."""
    out = getattr(sup, "out", None)
    if out is not None:
        loose = (f"{loose}; " if loose else "") + out
    if edge.relation != "HANGING_BELOW" or edge.parent.is_room_element \
            or edge.parent.part is None or sup.choice is None or getattr(sup, "over", False):
        # hung over a bar: its own reason (over.py)
        why = getattr(sup, "why", None)
        return loose if why is None else (f"{loose}; " if loose else "") + why
    try:
        named = {sp.choice.part for sp in support_candidates(st, edge)}
    except Fail:
        named = set()
    if sup.choice.part in named:
        return loose
    from ..pag.refs import format_ref

    ref = edge.parent
    return (f"{loose}; " if loose else "") + (f"no room to hang {edge.child.object} below "
            f"{format_ref(ref.object, ref.part, ref.index, ref.surface)} (others hang there, "
            f"it faces a wall, or its own parts are in the way below it): it hangs on {ref.object}:{sup.choice.part} instead")


#: Metres: a part no thicker than this across its length is a rod or a rail (a drying rack's
#: rod, a towel rail), too thin for cloth to lie on.
ROD_THICK = 0.04
#: A rod is at least this many times longer than it is thick.
ROD_LONG = 6.0


def rod_thickness(scene, edge: Edge) -> float | None:
    """The thickness in metres of the parent parts ``edge`` names (on ``scene``'s placed
    parent) when every one of them is a rod (long and thin in its two other axes: :data:`ROD_THICK`, :data:`ROD_LONG`), at the
    placed parent's scale; None for anything else (a shelf, a whole object, the floor)."""
    ref = edge.parent
    if ref.is_room_element or ref.part is None:
        return None
    pobj = scene.objects.get(ref.object)
    if pobj is None or not pobj.placed or pobj.asset is None:
        return None
    parts = pobj.asset.parts_by_label(ref.part)
    if ref.index is not None:
        parts = parts[ref.index:ref.index + 1]
    if not parts:
        return None
    thick = 0.0
    for p in parts:
        ext = np.sort(np.ptp(np.asarray(p.bounds, float), axis=0)) * pobj.scale
        if ext[1] > ROD_THICK or ext[2] < ROD_LONG * ext[1]:
            return None
        thick = max(thick, float(ext[1]))
    return thick


def draped_over(scene, edge: Edge, asset: Asset) -> tuple[Edge, str] | None:
    """For cloth (:func:`drapes`) written ``ON`` a rod (:func:`rod_thickness`): the edge it is
    placed by instead, ``HANGING_BELOW`` the same rod parts (edge-up when it is thin, as a
    towel on a towel bar), and why the ``ON`` as written is relaxed; None for anything else."""
    if edge.relation != "ON" or not drapes(asset):
        return None
    thick = rod_thickness(scene, edge)
    if thick is None:
        return None
    from ..pag.refs import format_ref

    c, p = edge.child, edge.parent
    parent = replace(p, surface="bottom", text=format_ref(p.object, p.part, p.index, "bottom"))
    child = replace(c, surface=None, text=format_ref(c.object, c.part, c.index, None))
    hung = Edge("HANGING_BELOW", child, parent, {})
    rod = format_ref(p.object, p.part, p.index, None)
    why = (f"{rod} is a rod {thick * 1000:.0f} mm thick: {c.object} cannot lie on it, so it "
           f"hangs over it (write HANGING_BELOW {c.object} -> {rod})")
    return hung, why


def attachment_region(region0, region):
    """Where on a support's underside a hung child's attachment may be: the support's region
    less its margin (``region0``), or the whole region when the margin leaves nothing (the
    bottom of a curtain ring or of a rack's tine, a few millimetres wide: the hook hangs from
    it all the same)."""
    return region if region0.is_empty or region0.area < 1e-10 else region0




def off_wall(st: SolveState, sup, region0, Fc: np.ndarray, free, F: np.ndarray):
    """``(region, reach)``: the positions of a hung child's origin whose attachment (``Fc``,
    a point) is within ``region0``, in ``free`` (clear of obstacles), with its footprint ``F``
    inside the room's floor; and the metres its attachment lies out from ``region0`` (0 when
    some positions are right below it). A pot wider than the gap between a rail and the wall
    behind hangs out from the wall on its hook, by the least reach that clears it (up to
    :data:`HOOK_REACH`); None when nothing within that reach clears the walls."""
    from shapely.geometry import Polygon

    from ..geometry import regions as RG
    from .state import plane_coords

    floor = st.scene.room.elements["floor"].surface
    fp = Polygon(plane_coords(sup.surface, floor.to_3d(
        np.asarray(floor.polygon.exterior.coords))))
    room = RG.clip(free, RG.erode(fp, [], F))
    reaches = (0.0, *np.arange(0.01, HOOK_REACH + 1e-9, 0.01))
    got = {}

    def clears(k: int) -> bool:
        grown = region0.buffer(float(reaches[k])) if reaches[k] else region0
        got[k] = RG.clip(RG.erode(grown, [], Fc), room)
        return not got[k].is_empty and got[k].area > 1e-10

    if clears(0):
        return got[0], 0.0
    # the positions only grow with the reach: none at the longest, none at all; otherwise
    # the least reach that clears, halving the interval (not every centimetre in turn)
    lo, hi = 0, len(reaches) - 1
    if not clears(hi):
        return None
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (lo, mid) if clears(mid) else (mid, hi)
    return got[hi], float(reaches[hi])


def off_wall_reason(edge: Edge, sup, reach: float) -> str:
    """Why ``edge`` is recorded relaxed when its child hangs ``reach`` metres out from
    ``sup`` (:func:`off_wall`): what it hangs from is too close to the wall behind it."""
    c = edge.child.object
    return (f"{sup.name} is too close to the wall behind it for {c} to hang right below it: "
            f"{c} hangs {reach * 100:.0f} cm out from it, on its hook (write HANGING_BELOW "
            f"{c} -> a part further from the wall, or a smaller {c})")


def hung_size(pag, oid: str) -> float:
    """The largest :func:`typical_size` of what is written ``HANGING_BELOW`` ``oid`` (0 when
    nothing is): the room a hook takes on its wall with its hat."""
    return max((typical_size(pag, e.child.object) for e in pag.relations
                if e.relation == "HANGING_BELOW" and e.parent.object == oid), default=0.0)


def room_below(st: SolveState, oid: str, sup, F: np.ndarray, samples: np.ndarray) -> np.ndarray:
    """Samples of an object put up on an upright surface (a hook on a wall) with things still
    to hang below it, those whose room below is clear of what is placed first (a stable
    order; unchanged otherwise).

    ``samples`` (N, 2) are positions of the object's origin and ``F`` its outline about it,
    in the plane coordinates of ``sup``'s surface. The room below is as wide as the outline
    or the largest of its hung children's :func:`typical_size` (whichever is wider), centred
    on the outline, and that size tall below its lowest point; what is placed within that
    size in front of the surface and overlaps it (seen on the surface) is in the way. Samples
    whose room is taken come last, the least taken (by the area overlapped) first.
    """
    s = sup.surface
    n = np.asarray(s.normal, float)
    if abs(float(n[2])) > 0.5 or not len(samples):
        return samples
    kids = [e.child.object for e in st.pag.relations
            if e.relation == "HANGING_BELOW" and e.parent.object == oid]
    kids = [k for k in kids if not (k in st.scene.objects and st.scene.objects[k].placed)]
    size = max((typical_size(st.pag, k) for k in kids), default=0.0)
    if size <= 0:
        return samples
    up = np.array([float(s.u[2]), float(s.v[2])])
    if np.linalg.norm(up) < 1e-6:
        return samples
    up /= np.linalg.norm(up)
    along = np.array([-up[1], up[0]])
    fa, fz = F @ along, F @ up
    half = 0.5 * max(float(np.ptp(fa)), size)
    mid = samples @ along + 0.5 * float(fa.min() + fa.max())
    top = samples @ up + float(fz.min())
    taken = np.zeros(len(samples))
    for o in st.scene.objects.values():
        if not o.placed or o.id in (oid, sup.owner) or o.id not in st.hulls:
            continue
        H = st.hulls[o.id]
        depth = (H - s.origin) @ n
        if float(depth.min()) > size or float(depth.max()) < 0.0:
            continue
        P = plane_coords(s, H)
        pa, pz = P @ along, P @ up
        wide = np.minimum(mid + half, pa.max()) - np.maximum(mid - half, pa.min())
        tall = np.minimum(top, pz.max()) - np.maximum(top - size, pz.min())
        taken += np.clip(wide, 0.0, None) * np.clip(tall, 0.0, None)
    # the free ones first, in their order; then the least taken (a gap between two beds a
    # little narrower than the room asked: a jacket narrower than that still hangs there)
    return samples[np.argsort(taken, kind="stable")]


def _hung_part(st: SolveState, asset: Asset, scale: float, e: Edge):
    if e.parent.is_room_element or e.relation != "HANGING_BELOW" or e.child.part is None \
            or not 0 < overhang(asset, e)[0] < np.inf:
        return None  # the named part (with its end pads: a collar's loop) is the top already
    try:
        sups = support_candidates(st, e)
    except Fail:
        return None
    got = [clears_beside(asset, e, scale, rect_sides(s.region)) for s in sups]
    return got[0] if got and all(p is not None for p in got) else None


def hangs_beside(st: SolveState, asset: Asset, scale: float, e: Edge) -> bool:
    """Whether :func:`.flush.clears_beside` finds a part of ``asset`` at ``scale`` to hang by
    below each surface the parent part of ``e`` resolves to (a room element is an unbounded
    plane: False): a mug by its handle on a cup hook, its rim beside the hook."""
    return _hung_part(st, asset, scale, e) is not None


def hung_by_part(st: SolveState, asset: Asset, scale: float, e: Edge) -> np.ndarray | None:
    """``(N, 3)`` points (asset frame, at ``scale``) of the named child part of ``e`` the
    child hangs by when the parts reaching higher stand beside the parent
    (:func:`hangs_beside`): its top then touches the parent, not the object's; else None."""
    p = _hung_part(st, asset, scale, e)
    return None if p is None else part_points([p]) * scale


#: Metres of clearance a hung thing needs on either side of the part it hangs from, across
#: its width: half the depth of a garment on a hanger (a rod 6 cm from a drying rack's ridge
#: is in its way).
HANG_CLEAR = 0.06

_HANG_ROOM: dict[tuple, str | None] = {}


def hang_room(asset: Asset, label: str | None, index: int | None, depth: float) -> str | None:
    """The name of a part of ``asset`` (of ``label``, ``#index``, when named) with room for a
    thing ``depth`` metres long to hang below it: no other part of the asset reaches into the
    column of that depth below it (its outline, less :data:`HANG_CLEAR` around every part
    below it), and, for an asset that stands on something (not put up on a wall or a
    ceiling), its bottom at least ``depth`` above the asset's lowest point (what it stands on
    is there). None when no part has that room: a dish rack's tines, a shoe rack's shelves,
    a drying rack's rods with the next rod below them, a clothes horse lower than a shirt."""
    key = (asset.asset_id, label, index, round(float(depth), 3))
    if key in _HANG_ROOM:
        return _HANG_ROOM[key]
    import shapely
    from shapely.geometry import MultiPoint

    from ..assets import registry

    try:
        stands = registry.get(asset.category).placement not in ("wall", "ceiling")
    except KeyError:
        stands = True
    parts = asset.parts if label is None else asset.parts_by_label(label)
    if label is not None and index is not None:
        parts = parts[index:index + 1]
    low = float(part_points(asset.parts)[:, 2].min())
    pieces = [(p, pc.vertices) for p in asset.parts for pc in p.piece_arrays]
    got = None
    for p in parts:
        pts = part_points([p])
        bottom = float(pts[:, 2].min())
        if stands and bottom - low < depth:
            continue
        free = MultiPoint(pts[:, :2]).convex_hull
        blocks = [MultiPoint(v[:, :2]).convex_hull.buffer(HANG_CLEAR) for q, v in pieces
                  if q is not p and float(v[:, 2].min()) < bottom - 1e-3
                  and float(v[:, 2].max()) > bottom - depth]
        if blocks:
            free = free.difference(shapely.union_all(blocks))
        if not free.is_empty and free.area > 1e-6:
            got = p.name
            break
    if len(_HANG_ROOM) > 8192:
        _HANG_ROOM.clear()
    _HANG_ROOM[key] = got
    return got


def below_room(asset: Asset, label: str, index: int | None, depth: float) -> list[str]:
    """The labels of the parts of ``asset`` right below its parts ``label`` (``#index``):
    under their outline, lower than their bottom, with room below them for a thing ``depth``
    metres long (:func:`hang_room`), nearest first (a luggage cart's hanger bar under the arch
    of its rail)."""
    from shapely.geometry import MultiPoint

    named = asset.parts_by_label(label)
    named = named[index:index + 1] if index is not None else named
    if not named:
        return []
    pts = part_points(named)
    under = MultiPoint(pts[:, :2]).convex_hull
    bottom = float(pts[:, 2].min())
    labels: dict[str, float] = {}
    for p in asset.parts:
        if p.label == label or p.label in labels:
            continue
        q = part_points([p])
        top = float(q[:, 2].max())
        if top >= bottom + 1e-3 or not MultiPoint(q[:, :2]).convex_hull.intersects(under):
            continue
        if hang_room(asset, p.label, None, depth) is not None:
            labels[p.label] = bottom - top
    return sorted(labels, key=labels.get)
