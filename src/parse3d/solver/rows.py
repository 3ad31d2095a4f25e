"""Small things side by side on a narrow support: markers and an eraser in a whiteboard's tray.

A channel (a whiteboard's marker tray, :func:`~parse3d.solver.support.channel_floor`) holds
what lies on its floor between its walls: the walls are part of the support, so a marker lying
on its round side needs no margin from the floor's edge to keep from rolling off (the lip
stops it), and the floor's edge is the wall itself (no extra margin either).

A strip narrower than the child is long (a tray, a sill, a ledge) takes its children in a row,
one beside the other along it. Drawn anywhere, the first two markers leave gaps shorter than
an eraser between them and the tray's ends; packed from one end (as things hung on a rail),
the rest of the strip stays in one piece for those still to come.

Like things written ON one part (three pairs of shoes on a shoe rack's shelf) are turned so
that they all fit in it side by side, as a person puts them away: a pair of shoes 0.20 m wide
and 0.26 m long goes heel to the back on a 0.70 x 0.27 m shelf, three in a row, not lengthwise
(two in a row), although one pair alone has more room lengthwise (:func:`row_turns`). In such
a crowded row (their widths together at least ``CROWDED`` of its length, no room for a second
row) each goes against an end of the row or against one already there, as a person pushes the
first pairs aside, and not where a random draw leaves gaps narrower than a pair between them
(:func:`packed`).
"""

from __future__ import annotations

import numpy as np

from ..pag.model import Edge
from .geometry import rect_sides
from .state import SolveState, plane_coords
from .support import Support, channel_floor

__all__ = ["walled", "in_a_row", "like_siblings", "row_turns", "packed", "STRIP", "ROW_GAP",
           "CROWDED"]

#: A support at least this many times longer than wide is a strip.
STRIP = 4.0

#: Like things side by side in a row are counted this much wider than they are (the gaps a
#: person leaves between them, and a post or a lip at the row's ends).
ROW_GAP = 0.03

#: Like things whose widths together take at least this share of their row's length are
#: packed against its ends and one another.
CROWDED = 0.6


def walled(st: SolveState, sup: Support) -> bool:
    """Whether ``sup`` is the floor of a channel-shaped part (between its walls)."""
    if sup.owner == "room" or sup.part is None:
        return False
    owner = st.scene.objects.get(sup.owner)
    if owner is None or owner.asset is None:
        return False
    try:
        part = owner.asset.part(sup.part)
    except KeyError:
        return False
    floor = channel_floor(owner.asset, part)
    if floor is None:
        return False
    at = (owner.transform(False) @ np.r_[floor.origin, 1.0])[:3]
    return abs(float((at - sup.surface.origin) @ sup.surface.normal)) < 1e-3


def in_a_row(st: SolveState, oid: str, edge: Edge, sup: Support, F: np.ndarray,
             region0) -> bool:
    """Whether the child goes in a row along a strip: ON an object's part whose region is at
    least ``STRIP`` times longer than wide and narrower than the child's footprint is long,
    with other children ON the same part still to be placed."""
    if edge.relation != "ON" or sup.owner == "room" or region0.is_empty:
        return False
    short, long_ = rect_sides(region0)
    if short <= 0 or long_ < STRIP * short:
        return False
    if short >= float(np.max(np.ptp(F, axis=0))):
        return False
    for e in st.pag.relations:
        if e.relation != "ON" or e.child.object == oid or e.parent.is_room_element \
                or e.parent.object != sup.owner or e.parent.part != edge.parent.part:
            continue
        kid = st.scene.objects.get(e.child.object)
        if kid is None or not kid.placed:
            return True
    return False


def _siblings(st: SolveState, oid: str, edge: Edge):
    """The other children written ``ON`` the same part (and ``#k``) as ``edge``."""
    for e in st.pag.relations:
        if e.relation == "ON" and e.child.object != oid and not e.parent.is_room_element \
                and e.parent.object == edge.parent.object and e.parent.part == edge.parent.part \
                and e.parent.index == edge.parent.index:
            yield e.child.object


def like_siblings(st: SolveState, oid: str, edge: Edge) -> int:
    """How many things of the child's kind (a shared category) are written ``ON`` the same
    part of the same object as ``edge`` (its support edge), the child included; 1 for a
    room element or a whole object."""
    if edge.relation != "ON" or edge.parent.is_room_element or edge.parent.part is None:
        return 1
    kinds = set(st.pag.objects[oid].candidates)
    return 1 + sum(bool(kinds & set(st.pag.objects[k].candidates))
                   for k in _siblings(st, oid, edge))


def row_turns(region, footprints: list[np.ndarray], n: int) -> list[bool] | None:
    """Which turns of the child take ``n`` like things side by side on ``region``.

    Parameters
    ----------
    region : shapely geometry
        The support's region, plane coordinates (metres).
    footprints : list of (K, 2) float
        The child's footprint at each turn considered, same coordinates.
    n : int
        How many like things share the region (the child included).

    Returns
    -------
    list of bool or None
        Per footprint, whether ``n`` of it fit in a grid square to the region's minimum
        rotated rectangle, ``ROW_GAP`` between neighbours; ``None`` when that does not tell the turns apart
        (all take them, or none does: the turn is then chosen as for one child).
    """
    if n < 2 or region.is_empty:
        return None
    r = region.minimum_rotated_rectangle
    if not hasattr(r, "exterior"):
        return None
    xy = np.asarray(r.exterior.coords)[:3]
    a, b = xy[1] - xy[0], xy[2] - xy[1]
    la, lb = float(np.linalg.norm(a)), float(np.linalg.norm(b))
    if min(la, lb) <= 0:
        return None
    a, b = a / la, b / lb
    out = []
    for F in footprints:
        # a grid of them, a gap between neighbours (none beyond the last one)
        wa, wb = float(np.ptp(F @ a)) + ROW_GAP, float(np.ptp(F @ b)) + ROW_GAP
        out.append(int((la + ROW_GAP) // wa) * int((lb + ROW_GAP) // wb) >= n)
    if all(out) or not any(out):
        return None
    return out


def packed(st: SolveState, oid: str, edge: Edge, sup: Support, F: np.ndarray, region0,
           samples: np.ndarray) -> np.ndarray:
    """The samples of a child in a crowded row of like things, tightest first.

    ``samples`` (N, 2) are positions of the child's origin and ``F`` its footprint about it,
    in the plane coordinates of ``sup``. Along the long side of ``region0``'s minimum rotated
    rectangle, a sample's key is the smaller of its gaps to the row's ends or to a sibling
    already placed on the part beside it (overlapping it across the row); the order is
    otherwise kept (the sort is stable). Unchanged unless :func:`like_siblings` of the child,
    at its width along the row, take ``CROWDED`` of the row's length, and the child is deeper
    than half the row is (one row only: six chairs on a rug are no row).
    """
    if edge.relation != "ON" or sup.owner == "room" or region0.is_empty or not len(samples):
        return samples
    n = like_siblings(st, oid, edge)
    r = region0.minimum_rotated_rectangle
    if n < 2 or not hasattr(r, "exterior"):
        return samples
    xy = np.asarray(r.exterior.coords)[:3]
    sides = [xy[1] - xy[0], xy[2] - xy[1]]
    k = int(np.argmax([np.linalg.norm(d) for d in sides]))
    axis = sides[k] / np.linalg.norm(sides[k])
    across = sides[1 - k] / max(float(np.linalg.norm(sides[1 - k])), 1e-12)
    ends = np.asarray(r.exterior.coords) @ axis
    lo, hi = float(ends.min()), float(ends.max())
    fa, fb = F @ axis, F @ across
    wide = float(np.ptp(np.asarray(r.exterior.coords) @ across))
    if n * float(np.ptp(fa)) < CROWDED * (hi - lo) or 2 * float(np.ptp(fb)) <= wide:
        return samples  # room to spare along it, or for a second row (chairs on a rug)
    s = sup.surface
    others = []
    for kid in _siblings(st, oid, edge):
        o = st.scene.objects.get(kid)
        if o is not None and o.placed and kid in st.hulls:
            P = plane_coords(s, st.hulls[kid])
            others.append((float((P @ axis).min()), float((P @ axis).max()),
                           float((P @ across).min()), float((P @ across).max())))
    a0 = samples @ axis + float(fa.min())
    a1 = samples @ axis + float(fa.max())
    b0 = samples @ across + float(fb.min())
    b1 = samples @ across + float(fb.max())
    gap = np.minimum(a0 - lo, hi - a1)
    for o0, o1, p0, p1 in others:
        beside = (b0 < p1) & (b1 > p0)
        gap = np.where(beside & (a0 >= o1 - 1e-3), np.minimum(gap, a0 - o1), gap)
        gap = np.where(beside & (a1 <= o0 + 1e-3), np.minimum(gap, o0 - a1), gap)
    return samples[np.argsort(np.maximum(gap, 0.0), kind="stable")]
