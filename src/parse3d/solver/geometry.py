"""The solver's per-asset geometry: the same cached kernels the relation checks use.

They live in :mod:`parse3d.measure.geometry` (physics and evaluations measure with them
without importing the solver); the solver's stages import them from here.
"""

from __future__ import annotations

import numpy as np
from shapely.geometry import Polygon

from ..measure.geometry import (
    AssetGeometry,
    asset_geometry,
    drop_distance,
    enclosure_directions,
    hull_extents,
    outline_indices,
    part_points,
    ray_caster,
)

__all__ = ["AssetGeometry", "asset_geometry", "part_points", "ray_caster", "enclosure_directions",
           "drop_distance", "outline_indices", "hull_extents", "rect_sides"]

def rect_sides(poly) -> tuple[float, float]:
    """(short, long) sides of a shape's minimum rotated rectangle (a segment: (0, length))."""
    r = poly.minimum_rotated_rectangle
    if not isinstance(r, Polygon):
        return 0.0, float(r.length)
    xy = np.asarray(r.exterior.coords)[:3]
    a, b = float(np.linalg.norm(xy[1] - xy[0])), float(np.linalg.norm(xy[2] - xy[1]))
    return min(a, b), max(a, b)
