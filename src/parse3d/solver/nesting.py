"""Nesting and stacks of like round things: a plate on a plate, a bowl in a bowl, a cup in a cup.

A round child resting on (or in) a round parent of its own kind goes on the parent's axis first:
a small plate off-centre in a dinner plate's well rests with one side on the well's slope and
tips in settling (the kitchen example's side plate ended 10.8 degrees off), a dinner plate
off-centre on a side plate rests on one side of its rim. Concentric, each rests evenly all round.
"""

from __future__ import annotations

import numpy as np

from ..assets.model import Asset
from ..measure.checks import object_centroid
from .geometry import asset_geometry
from .state import SolveState
from .support import Support

__all__ = ["concentric_first", "ROUND_FOOTPRINT"]

#: Largest ratio of the two horizontal extents of a round footprint (a plate, a bowl, a cup).
ROUND_FOOTPRINT = 1.15


def _round_footprint(asset: Asset, R: np.ndarray | None = None) -> bool:
    ext = np.ptp(asset_geometry(asset).hull @ (np.eye(3) if R is None else R).T, axis=0)
    a, b = sorted(ext[:2])
    return b <= ROUND_FOOTPRINT * a


def concentric_first(st: SolveState, oid: str, sup: Support, asset: Asset, scale: float,
                     R: np.ndarray, samples: np.ndarray) -> np.ndarray:
    """``samples`` (origins in the support plane) with, first, the one that puts the child's
    centre of mass on the vertical through its parent's centre, when the child rests on or in
    an object of its own kind (their PAG nodes share a category) and both are round in plan."""
    if sup.owner == "room" or sup.owner not in st.scene.objects:
        return samples
    parent = st.scene.objects[sup.owner]
    if not parent.placed or parent.asset is None or not (
            set(st.pag.objects[oid].candidates) & set(st.pag.objects[sup.owner].candidates)):
        return samples
    if not (_round_footprint(asset, R) and _round_footprint(parent.asset, parent.rotation)):
        return samples
    s = sup.surface
    com = (asset_geometry(asset).com * scale) @ R.T
    d = object_centroid(parent, False) - s.origin - com
    at = np.array([[float(d @ s.u), float(d @ s.v)]])
    return np.vstack([at, samples])[:max(len(samples), 1)]
