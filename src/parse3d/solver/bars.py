"""What rests across several like parts at one level (a suitcase on a luggage rack's straps, a
keyboard on both arms of an X-stand): held by the parts its underside meets, not by its
lowest points, which may hang in a gap between them or past them (a suitcase's wheels, a
keyboard's rubber feet)."""

from __future__ import annotations

import numpy as np
import shapely

from ..assets.model import Asset
from .geometry import asset_geometry
from .state import plane_coords

__all__ = ["held_across"]

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
