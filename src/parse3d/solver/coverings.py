"""A floor covering under furniture: a rug or a runner lies where the floor is free at its
own height.

A rug in a real room runs under the bed and between the legs of the table and chairs; only
what stands on the floor within the rug's thickness (a leg, a foot, a solid plinth) is in its
way. The furniture's whole footprints, the obstacles of anything taller, would leave a rug
written after the furniture no room in a furnished room. :func:`covers_floor` says when a
child is such a covering, :func:`low_obstacles` gives the footprints in its slab: those of the
convex pieces of the placed objects that reach into it.
"""

from __future__ import annotations

import numpy as np

from ..assets.model import Asset
from ..geometry import regions as RG
from ..geometry.surfaces import Surface
from ..measure.checks import COVER_FLAT, COVER_THICK, EPS
from ..measure.geometry import asset_geometry
from ..pag.model import Edge
from .state import SolveState, plane_coords, plane_key
from .support import Support

__all__ = ["covers_floor", "low_obstacles", "lay_covering", "covering_scale", "COVER_STEPS"]


def covers_floor(sup: Support, relation: str, height: float, F: np.ndarray) -> bool:
    """Whether a child ``height`` m thick with footprint ``F`` ((K, 2) plane coordinates),
    placed by ``relation`` on ``sup``, is a floor covering: ``ON`` the room's floor, at most
    ``COVER_THICK`` thick and ``COVER_FLAT`` of its narrower side (the measure's reading of
    a covering, :func:`parse3d.measure.checks.covering_thickness`)."""
    if relation != "ON" or sup.owner != "room" or sup.surface.normal[2] < 0.999:
        return False
    narrow = float(min(np.ptp(F[:, 0]), np.ptp(F[:, 1])))
    return height <= min(COVER_THICK, COVER_FLAT * narrow)


def low_obstacles(st: SolveState, s: Surface, exclude: set[str],
                  height: float) -> list[np.ndarray]:
    """Footprints ((K, 2) plane coordinates of the horizontal surface ``s``) of the convex
    pieces of the placed objects (not in ``exclude``) that reach into the slab of ``height`` m
    above it (a bed's legs, a cabinet's plinth; not the bed's frame above them)."""
    sz = float(s.origin[2])
    out = []
    for oid, (lo, hi) in st.zr.items():
        if oid in exclude or oid not in st.hulls or lo - sz >= height - 1e-3 or hi - sz <= 1e-3:
            continue
        out.extend(st.memo(oid, ("low", *plane_key(s), round(height, 4)),
                           lambda oid=oid: _low_pieces(st, oid, s, height)))
    return out


def lay_covering(st: SolveState, sup: Support, exclude: set[str], height: float, region0,
                 holes: list[np.ndarray], F: np.ndarray, R: np.ndarray):
    """Where a floor covering of footprint ``F`` ((K, 2) plane coordinates) turned by ``R``
    (3, 3) may lie on ``sup``: ``region0`` less :func:`low_obstacles` and ``holes``, grown by
    the footprint. When nothing is free at that turn, the quarter turn about the normal is
    tried (a runner along a galley kitchen, not across it). Returns ``(region, R, F,
    obstacles)``; the region may be empty (nowhere at either turn)."""
    s = sup.surface
    obst = low_obstacles(st, s, exclude, height)
    n = s.normal
    K = np.array([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    quarter = np.eye(3) + K + K @ K  # a quarter turn about the normal (Rodrigues)
    region = None
    for Rk, Fk in ((R, F), (quarter @ R, np.c_[-F[:, 1], F[:, 0]])):
        region = RG.erode(region0, obst + holes, Fk)
        if not region.is_empty and region.area >= 1e-10:
            return region, Rk, Fk, obst
    return region, R, F, obst


def _low_pieces(st: SolveState, oid: str, s, height: float) -> list[np.ndarray]:
    """The footprints of ``oid``'s convex pieces reaching below ``height`` above ``s``."""
    out = []
    for _, pts in st.world_pieces(oid):
        h = (pts - s.origin) @ s.normal
        if float(h.min()) < height - 1e-3 and float(h.max()) > 1e-3:
            out.append(RG.convex_footprint(plane_coords(s, pts)))
    return out


#: Scales (fractions of the drawn one) a floor covering is tried at, largest first, down to
#: its category's smallest size.
COVER_STEPS = (1.0, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4)


def covering_scale(st: SolveState, edge: Edge, asset: Asset, scale: float,
                   least: float) -> float:
    """The scale of a floor covering (``ON`` the floor, flat as :func:`covers_floor` reads it)
    drawn at ``scale``: the largest of ``COVER_STEPS`` times it, not below ``least``, at which
    its footprint (along the room's axes or turned a quarter) fits somewhere on the floor
    clear of what stands in its slab (:func:`low_obstacles`): a rug for a furnished room is
    one that fits between its furniture, not one that finds no room. ``scale`` for anything
    else, or when none fits (the placement then says why)."""
    floor = st.scene.room.elements.get("floor")
    if edge.relation != "ON" or edge.parent.object != "floor" or floor is None:
        return scale
    s = floor.surface
    hull = asset_geometry(asset).hull * scale
    ext = np.ptp(hull, axis=0)
    if ext[2] > min(COVER_THICK, COVER_FLAT * float(min(ext[0], ext[1]))):
        return scale
    obst = low_obstacles(st, s, set(), float(ext[2]) + EPS)
    room = s.polygon
    flat = [np.c_[hull @ s.u, hull @ s.v], np.c_[hull @ s.v, -(hull @ s.u)]]
    for k in COVER_STEPS:
        if k < 1.0 and scale * k < least:
            break
        for F in flat:
            free = RG.erode(room, obst, RG.convex_footprint(F * k * 1.02))
            if not free.is_empty and free.area > 1e-10:
                return scale * k
    return scale
