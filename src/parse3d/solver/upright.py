"""Things filed upright in a row: flat things written on a shelf that do not fit there lying.

A person who writes six records ``IN`` one shelf of a record shelf means them standing on their
edge side by side, spine out, as books stand; so do scores, sleeves, folders and boards filed
on a shelf. An object modelled lying (its thin axis vertical: a record, a sheet of music) that
is a slab with a rectangular outline (not a bare disc or a plate, which pile up) stands on an
edge face when the objects written on the same part do not all fit there lying side by side
(:func:`stands_in_row`). It stands on the lower of its edges that fit under the shelf above
and across the shelf, its thin axis along the shelf's longer side (a
``PARALLEL_TO`` of its large face to the part's side face, so the row runs along the shelf),
and its sides are read as a book's in a row, its thin axis its right
(:func:`parse3d.measure.geometry.side_frame`): ``SIDE_OF record2 -> record1 right`` is to the
right along the shelf. The pose records ``rests_on``, which the support check measures.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import shapely

from ..assets.model import Asset
from ..measure.geometry import ON_EDGE_THIN
from ..pag.model import Edge
from ..pag.refs import format_ref
from .geometry import asset_geometry
from .state import SolveState
from .support import best_support

__all__ = ["FILED_THIN", "SLAB_FILL", "filed_flat", "stands_in_row", "upright_axis", "filed_instance",
           "lies_in_cradle"]

#: A filed flat thing's thickness is at most this share of its smaller other extent (as the
#: checks read a flat thing standing on an edge: :func:`parse3d.measure.geometry.side_frame`).
FILED_THIN = ON_EDGE_THIN
#: ... and its outline fills at least this share of its bounding rectangle (a sleeve, a
#: folder, a sheet; not a bare disc, a plate or a bowl, which would roll on an edge and whose
#: like pile up).
SLAB_FILL = 0.85


def _thin_lying(asset: Asset) -> bool:
    """Whether ``asset`` is modelled lying and thin (:data:`FILED_THIN`)."""
    ext = np.ptp(asset_geometry(asset).bounds, axis=0)
    return 0 < ext[2] <= FILED_THIN * min(float(ext[0]), float(ext[1]))


def filed_flat(asset: Asset) -> bool:
    """Whether ``asset`` is a slab modelled lying (thin axis vertical, :data:`FILED_THIN`) with
    a rectangular outline (:data:`SLAB_FILL`): a record in its sleeve, a score, a folder."""
    if not _thin_lying(asset):
        return False
    g = asset_geometry(asset)
    ext = np.ptp(g.bounds, axis=0)
    outline = shapely.MultiPoint(np.asarray(g.hull, float)[:, :2]).convex_hull
    return float(outline.area) >= SLAB_FILL * float(ext[0] * ext[1])


def _siblings(pag, edge: Edge) -> list[str]:
    """Objects written ``ON``/``IN`` the same part (or surface) of the same parent as ``edge``."""
    p = edge.parent
    return [e.child.object for e in pag.relations
            if e.relation in ("ON", "IN") and e.parent.object == p.object
            and e.parent.part == p.part and e.parent.index == p.index]


#: Share by which a footprint is widened when counting how many fit side by side: positions
#: are drawn, not packed, so things lying on a shelf keep some room between them.
PACKING_ROOM = 1.15


def _lying_capacity(w: float, d: float, a: float, b: float) -> int:
    """How many ``a`` x ``b`` footprints fit side by side on a ``w`` x ``d`` rectangle, each
    with :data:`PACKING_ROOM`."""
    if min(a, b) <= 0:
        return 10 ** 6
    a, b = a * PACKING_ROOM, b * PACKING_ROOM
    return max(int(w // a) * int(d // b), int(w // b) * int(d // a))


def _crowded(st: SolveState, edge: Edge, asset: Asset, scale: float, shape: bool = True):
    """``(support, row axis of the owner, width, depth)`` when ``edge`` puts a filed flat
    thing (with ``shape`` False: any thing) on a part of a placed object that does not hold
    all the (at least two) things written on it lying side by side, and nothing is written
    on it (a chess board with its pieces lies); None otherwise."""
    c, p = edge.child, edge.parent
    if edge.relation not in ("ON", "IN") or c.part is not None \
            or c.surface not in (None, "bottom") or p.is_room_element or p.part is None:
        return None
    parent = st.scene.objects.get(p.object)
    if parent is None or not parent.placed or (shape and not filed_flat(asset)):
        return None
    sup = best_support(st, edge, key=lambda s: s.region.area)
    if sup is None:
        return None
    # the support's extent along the owner's right and front (the shelf's width and depth)
    R, s = parent.rotation, sup.surface
    x0, y0, x1, y1 = sup.region.bounds
    corners = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    world = corners[:, :1] * s.u + corners[:, 1:] * s.v
    along = [float(np.ptp(world @ R[:, k])) for k in (0, 1)]
    row = 0 if along[0] >= along[1] else 1
    width, depth = along[row], along[1 - row]
    ext = np.ptp(asset_geometry(asset).bounds, axis=0) * scale
    n = len(set(_siblings(st.pag, edge)))
    if n < 2 or n <= _lying_capacity(width, depth, float(ext[0]), float(ext[1])) \
            or any(e.relation in ("ON", "IN") and e.parent.object == c.object
                   for e in st.pag.relations):
        return None  # they fit lying, or it is alone, or holds something: as written
    return sup, row, width, depth


def _edges(ext: np.ndarray, depth: float) -> list[int]:
    """The asset axes (0: standing on its left edge, 1: on its back edge) a slab of extents
    ``ext`` may stand along, best first: those whose other extent lies across a shelf
    ``depth`` deep, the lower first; then the others, the shallower first."""
    return sorted((0, 1), key=lambda k: (ext[1 - k] > depth, ext[k] if ext[1 - k] <= depth
                                         else ext[1 - k]))


def filed_instance(st: SolveState, library, edge: Edge, category: str, asset: Asset,
                   reqs: list, tried: set[str], rng: np.random.Generator) -> tuple[str, Asset]:
    """``(category, asset)``: for a thing of a kind that is filed (a record: its pool holds
    sleeved ones) drawn as an instance that is not a slab (a bare disc) where the things
    written on its shelf do not fit lying, an untried slab of its candidates, which stands in
    the row (:func:`stands_in_row`); the instance drawn otherwise."""
    if not _thin_lying(asset) or filed_flat(asset) \
            or _crowded(st, edge, asset, 1.0, shape=False) is None:
        return category, asset
    from .choice import alternative_instance

    alt = alternative_instance(library, st.pag.objects[edge.child.object].candidates, reqs,
                               tried, rng, key=lambda a: 0.0 if filed_flat(a) else 1.0)
    if alt is None or not filed_flat(alt[1]):
        return category, asset
    tried.add(alt[1].asset_id)
    return alt


def upright_axis(st: SolveState, edge: Edge, asset: Asset) -> int | None:
    """The asset axis that is vertical as the object is placed: for a filed flat thing crowded
    on its shelf (:func:`stands_in_row`) the edge it stands on (:func:`_edges`), for a bottle
    in a cradle (:func:`lies_in_cradle`) its diameter; for choosing an instance and a scale
    that fit under the part above. None when it is placed as modelled."""
    if _cradled(st, edge, asset, 1.0) is not None:
        return 1
    got = _crowded(st, edge, asset, 1.0)
    if got is None:
        return None
    return _edges(np.ptp(asset_geometry(asset).bounds, axis=0), got[3])[0]


#: A long round thing: its length at least this many times its larger other extent, ...
LONG_ROUND = 1.8
#: ... and its other two extents within this ratio of each other (a bottle, a rolled poster).
ROUND_RATIO = 1.3


def _cradled(st: SolveState, edge: Edge, asset: Asset, scale: float):
    """The support when ``edge`` puts a long round thing modelled upright (a bottle) ``ON`` or
    ``IN`` a part of a placed object whose free height is below its height: it lies there
    (:func:`lies_in_cradle`); None otherwise."""
    c, p = edge.child, edge.parent
    if edge.relation not in ("ON", "IN") or c.part is not None \
            or c.surface not in (None, "bottom") or p.is_room_element or p.part is None:
        return None
    ext = np.ptp(asset_geometry(asset).bounds, axis=0)
    lo, hi = sorted((float(ext[0]), float(ext[1])))
    if ext[2] < LONG_ROUND * hi or hi > ROUND_RATIO * lo:
        return None
    parent = st.scene.objects.get(p.object)
    if parent is None or not parent.placed:
        return None
    sup = best_support(st, edge, key=lambda s: s.clearance)
    return sup if sup is not None and sup.clearance < ext[2] * scale else None


def _depth(st: SolveState, owner: str) -> float:
    """Metres the placed ``owner`` (a wine rack) spans along its front."""
    o = st.scene.objects[owner]
    return float(np.ptp(st.hulls[owner] @ o.rotation[:, 1]))


def lies_in_cradle(st: SolveState, edge: Edge, asset: Asset, scale: float
                   ) -> tuple[Edge, ...] | None:
    """For a long round thing modelled upright (a wine bottle) written ``ON``/``IN`` a part of a
    placed object whose free height is below its height but takes its diameter (a wine
    rack's cradle): the support edge by which it lies on its side there, and a
    ``PARALLEL_TO`` of its top to the part's front, so it lies along the part's depth, neck
    out, as such racks hold bottles (when it is longer than the owner is deep: at the turn that
    fits, along a shelf). None for anything else, and when even its diameter does
    not fit (it is placed as written, and fails with the free height)."""
    sup = _cradled(st, edge, asset, scale)
    if sup is None:
        return None
    ext = np.ptp(asset_geometry(asset).bounds, axis=0) * scale
    if ext[1] > sup.clearance:
        return None
    c, p = edge.child, edge.parent
    lying = replace(edge, child=replace(c, surface="back",
                                        text=format_ref(c.object, None, None, "back")))
    if ext[2] > _depth(st, p.object):
        return (lying,)  # longer than its owner is deep: the turn that fits (along a shelf)
    out = Edge("PARALLEL_TO", replace(c, part=None, index=None, surface="top",
                                      text=format_ref(c.object, None, None, "top")),
               replace(p, surface="front", text=format_ref(p.object, p.part, p.index, "front")),
               {})
    return lying, out


def stands_in_row(st: SolveState, edge: Edge, asset: Asset, scale: float
                  ) -> tuple[Edge, ...] | None:
    """For ``ON``/``IN`` a part of a placed object, written with no part of the child's own,
    of a flat slab modelled lying (:func:`filed_flat`) when the objects written on that part
    do not all fit there lying side by side: the support edge by which it stands on an edge
    face, a ``PARALLEL_TO`` of its large top face to the part's side face along which the
    row runs (its thin axis along the shelf) and a ``NEAR`` to its neighbour in the row
    (:func:`_neighbour`; not for the first). None for anything else, or when no edge face
    fits under the shelf above and across the shelf."""
    got = _crowded(st, edge, asset, scale)
    if got is None:
        return None
    sup, row, width, depth = got
    ext = np.ptp(asset_geometry(asset).bounds, axis=0) * scale
    fits = [k for k in _edges(ext, depth) if ext[k] <= sup.clearance and ext[1 - k] <= depth]
    if not fits:
        return None
    face = ("left", "back")[fits[0]]  # the lower of the edges it fits on: the steadier
    c, p = edge.child, edge.parent
    standing = replace(edge, child=replace(c, surface=face,
                                           text=format_ref(c.object, None, None, face)))
    side = ("right", "front")[row]
    parallel = Edge("PARALLEL_TO", replace(c, part=None, index=None, surface="top",
                                           text=format_ref(c.object, None, None, "top")),
                    replace(p, surface=side, text=format_ref(p.object, p.part, p.index, side)),
                    {})
    near = _neighbour(st, edge, float(ext[2]))
    return (standing, parallel) if near is None else (standing, parallel, near)


#: Metres beyond three thicknesses by which a filed thing's centre may be from its neighbour's
#: in the row (they touch or nearly: a row, not things strewn along the shelf).
ROW_GAP = 0.01


def _neighbour(st: SolveState, edge: Edge, thick: float) -> Edge | None:
    """A ``NEAR`` to the thing this one stands beside in the row: the one it is written
    ``SIDE_OF`` when that is on the same shelf, else the last placed one standing there; None
    for the first of the row."""
    oid = edge.child.object
    mates = set(_siblings(st.pag, edge)) - {oid}
    placed = [m for m in mates if (o := st.scene.objects.get(m)) is not None and o.placed]
    if not placed:
        return None
    written = [e.parent.object for e in st.pag.relations
               if e.relation == "SIDE_OF" and e.child.object == oid and e.parent.object in placed]
    standing = [m for m in _siblings(st.pag, edge) if m in placed
                and st.scene.objects[m].rests_on in ("left", "right", "front", "back")]
    mate = written[0] if written else (standing[-1] if standing else None)
    if mate is None:
        return None
    ref = edge.child
    return Edge("NEAR", replace(ref, part=None, index=None, surface=None, text=oid),
                replace(ref, object=mate, part=None, index=None, surface=None, text=mate),
                {"distance": round(3 * thick + ROW_GAP, 4)})
