"""What stands along a wall: the occupants of a stretch of wall (objects against it, hung on
it, or standing on the floor in front of it) and the cheapest window of a given width to clear
for a wall object that found no room.

Positions along a wall are metres along its surface's horizontal axis ``u`` from the end where
``u`` is least; depths are metres in front of its surface, along its normal.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import shapely

from ..geometry.surfaces import Surface

__all__ = ["Occupant", "Window", "wall_length", "occupants", "free_runs", "windows"]


@dataclass(frozen=True)
class Occupant:
    """A placed object taking a stretch of wall.

    Attributes
    ----------
    id : str
    a0, a1 : float
        The stretch it takes (m along the wall), where it comes within the depth.
    """

    id: str
    a0: float
    a1: float


@dataclass(frozen=True)
class Window:
    """A stretch of wall and what would have to move to free it.

    Attributes
    ----------
    wall : str
    a0, a1 : float
        The stretch (m along the wall).
    blockers : tuple of str
        Occupants overlapping it, in wall order.
    cost : int
        Objects moved to free it (the blockers with what depends on them).
    """

    wall: str
    a0: float
    a1: float
    blockers: tuple[str, ...]
    cost: int


def wall_length(surface: Surface) -> tuple[float, float]:
    """(start, length) of a wall surface along its horizontal axis ``u`` (plane coordinates)."""
    x0, _, x1, _ = surface.polygon.bounds
    return float(x0), float(x1 - x0)


def occupants(surface: Surface, hulls: dict[str, np.ndarray], depth: float, z0: float,
              z1: float) -> list[Occupant]:
    """Placed objects (world hull points ``hulls``, (N, 3) each) that come within ``depth``
    metres in front of the wall with their z range overlapping ``(z0, z1)``, and the stretch
    of wall each takes there; sorted along the wall."""
    start, length = wall_length(surface)
    slab = shapely.box(-1e3, -1.0, 1e3, depth)
    out = []
    for oid, H in hulls.items():
        if float(H[:, 2].max()) <= z0 + 1e-3 or float(H[:, 2].min()) >= z1 - 1e-3:
            continue
        d = H - surface.origin
        dn = d @ surface.normal
        if float(dn.min()) >= depth:
            continue
        a = d @ surface.u - start
        if float(a.max()) <= 0.0 or float(a.min()) >= length:
            continue
        near = shapely.MultiPoint(np.column_stack([a, dn])).convex_hull.intersection(slab)
        if near.is_empty:
            continue
        b = near.bounds
        lo, hi = max(b[0], 0.0), min(b[2], length)
        if hi > lo:
            out.append(Occupant(oid, lo, hi))
    return sorted(out, key=lambda o: (o.a0, o.a1, o.id))


def free_runs(length: float, taken: list[Occupant]) -> list[tuple[float, float]]:
    """The stretches (a0, a1) of a wall of ``length`` metres that no occupant takes."""
    out, at = [], 0.0
    for o in sorted(taken, key=lambda o: o.a0):
        if o.a0 > at:
            out.append((at, o.a0))
        at = max(at, o.a1)
    if at < length:
        out.append((at, length))
    return out


def windows(wall: str, length: float, taken: list[Occupant], width: float,
            cost: Callable[[tuple[str, ...]], int | None]) -> list[Window]:
    """Stretches of ``width`` metres on a wall of ``length`` metres, each with the occupants
    that would have to move to free it, cheapest first by ``cost`` of those occupants (None:
    they cannot move). Windows nobody blocks are left out; so are windows with the same
    blockers as another."""
    if width > length:
        return []
    starts = {0.0, length - width}
    for o in taken:
        starts.update((o.a1, o.a0 - width))
    found: dict[tuple[str, ...], Window] = {}
    for a in sorted(starts):
        if a < 0.0 or a + width > length + 1e-9:
            continue
        block = tuple(o.id for o in taken if o.a1 > a + 1e-3 and o.a0 < a + width - 1e-3)
        if not block or block in found:
            continue
        c = cost(block)
        if c is not None:
            found[block] = Window(wall, a, a + width, block, int(c))
    return sorted(found.values(), key=lambda w: (w.cost, len(w.blockers), w.a0))
