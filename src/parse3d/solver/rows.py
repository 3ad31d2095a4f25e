"""Small things side by side on a narrow support: markers and an eraser in a whiteboard's tray.

A channel (a whiteboard's marker tray, :func:`~parse3d.solver.support.channel_floor`) holds
what lies on its floor between its walls: the walls are part of the support, so a marker lying
on its round side needs no margin from the floor's edge to keep from rolling off (the lip
stops it), and the floor's edge is the wall itself (no extra margin either).

A strip narrower than the child is long (a tray, a sill, a ledge) takes its children in a row,
one beside the other along it. Drawn anywhere, the first two markers leave gaps shorter than
an eraser between them and the tray's ends; packed from one end (as things hung on a rail),
the rest of the strip stays in one piece for those still to come.
"""

from __future__ import annotations

import numpy as np

from ..pag.model import Edge
from .geometry import rect_sides
from .state import SolveState
from .support import Support, channel_floor

__all__ = ["walled", "in_a_row", "STRIP"]

#: A support at least this many times longer than wide is a strip.
STRIP = 4.0


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
