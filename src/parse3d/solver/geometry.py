"""The solver's per-asset geometry: the same cached kernels the relation checks use.

They live in :mod:`parse3d.measure.geometry` (physics and evaluations measure with them
without importing the solver); the solver's stages import them from here.
"""

from __future__ import annotations

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
           "drop_distance", "outline_indices", "hull_extents"]
