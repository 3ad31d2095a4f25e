"""What rests across several like parts at one level (a suitcase on a luggage rack's straps, a
keyboard on both arms of an X-stand): held by the parts its underside meets, not by its
lowest points, which may hang in a gap between them or past them (a suitcase's wheels, a
keyboard's rubber feet).

A part whose top is a ring around an opening (a bathtub's rim, whether one moulded rim or
four walls meeting at one level) is such a support too: what is too big for the ring alone
rests across the opening on two opposite sides of it (a bath caddy from rim to rim): the
ring is found with the support (``support.ring_top``), the child turned and drawn across it
here."""

from __future__ import annotations

import numpy as np
import shapely

from ..assets.model import Asset
from .geometry import asset_geometry, rect_sides
from .state import plane_coords

__all__ = ["across_need", "across_opening", "held_across", "opening"]

#: Metres: the pieces of the child whose undersides lie this close to the lowest one over the
#: support rest on it together.
BASE_TOL = 3e-3

#: Metres the centre of mass keeps inside the hull of what holds the child.
COM_MARGIN = 5e-3


def held_across(asset: Asset, scale: float, R: np.ndarray, t: np.ndarray, s, solid,
                rests: bool = False) -> bool:
    """Whether the child posed by ``(R, t)`` rests on the parts of a spanning support.

    ``solid`` is the parts' tops (plane coordinates of ``s``, the gaps between them cut out).
    Each convex piece of the child has an underside: the hull of its points within
    ``BASE_TOL`` of its lowest. The pieces whose underside meets ``solid`` are the ones the
    parts can catch; the lowest of those sets the level the child comes to rest at, and the
    undersides at that level, clipped to ``solid``, hold it: its centre of mass must lie
    ``COM_MARGIN`` inside their convex hull. Pieces lower than that level over a gap or past
    the parts hang there (a suitcase's wheels between straps)."""
    n = s.normal
    held, level = [], np.inf
    faces = []
    for p in asset.parts:
        pieces = [pc.vertices for pc in p.piece_arrays] or [p.vertices]
        for v in pieces:
            w = (np.asarray(v, float) * scale) @ R.T + t
            h = (w - s.origin) @ n
            lo = float(h.min())
            under = shapely.MultiPoint(plane_coords(s, w[h <= lo + BASE_TOL])).convex_hull
            on = under.buffer(1e-3).intersection(solid)
            if on.is_empty or on.area <= 0:
                continue
            faces.append((lo, on))
            level = min(level, lo)
    held = [on for lo, on in faces if lo <= level + BASE_TOL]
    if not held or (rests and level > BASE_TOL):
        return False
    com = plane_coords(s, (R @ (asset_geometry(asset).com * scale) + t)[None])[0]
    inner = shapely.union_all(held).convex_hull.buffer(-COM_MARGIN)
    return not inner.is_empty and inner.contains(shapely.Point(com))


def opening(sup):
    """The opening a ring support (``sup.ring``: a tub's rim) closes round, the largest of its
    holes lying wholly inside its region; None for any other support."""
    if not sup.ring or not sup.holes:
        return None
    inner = sup.region.buffer(-1e-3)
    inside = [h for h in (shapely.Polygon(x) for x in sup.holes) if inner.contains(h)]
    return max(inside, key=lambda h: h.area) if inside else None


def across_opening(hole, samples: np.ndarray, mid: np.ndarray, F: np.ndarray) -> np.ndarray:
    """``samples`` (positions of the child's origin) moved onto the line through ``mid`` (the
    position that centres the child's base on the opening ``hole``) along the opening's long
    axis, no further along it than keeps the child's footprint ``F`` (plane coordinates about
    its origin) within the opening's length, ``mid`` first: across the opening, the child's
    ends rest on the two long sides of the ring, not on an end of it. Draws no numbers."""
    box = np.asarray(hole.minimum_rotated_rectangle.exterior.coords)[:3]
    e1, e2 = box[1] - box[0], box[2] - box[1]
    axis = e1 if np.linalg.norm(e1) >= np.linalg.norm(e2) else e2
    axis = axis / max(float(np.linalg.norm(axis)), 1e-12)
    mid = np.asarray(mid, float)
    ends = np.asarray(hole.exterior.coords) @ axis
    reach = np.asarray(F, float) @ axis
    lo = float(ends.min() - reach.min() - mid @ axis)
    hi = float(ends.max() - reach.max() - mid @ axis)
    along = (np.asarray(samples, float) - mid) @ axis
    along = np.clip(along, min(lo, 0.0), max(hi, 0.0))
    return np.vstack([mid, mid + along[:, None] * axis[None]])


#: Metres a child resting across an opening reaches onto the ring past each side of it.
BEARING = 0.03


def across_need(sups, length: float, width: float) -> float:
    """The least length (m) an ``ON`` child with a ``length`` x ``width`` footprint needs to
    rest across the opening of a ring support among ``sups`` (a tray across a tub: the
    opening's narrow width and ``BEARING`` onto the ring on each side), when it is at least
    half that width (a tray, not a bottle on the rim), falls short of it and fits none of the
    other supports (a bag on a bench's seat, not across the frame round it); 0 otherwise."""
    for sup in sups:
        if not sup.ring:
            short, long = rect_sides(sup.region)
            if width <= short and length <= long:
                return 0.0
    need = 0.0
    for sup in sups:
        hole = opening(sup)
        if hole is None:
            continue
        box = np.asarray(hole.minimum_rotated_rectangle.exterior.coords)[:3]
        width = float(min(np.linalg.norm(box[1] - box[0]), np.linalg.norm(box[2] - box[1])))
        if 0.5 * width <= length < width + 2 * BEARING:
            need = max(need, width + 2 * BEARING)
    return need
