"""The room shell: floor, walls and ceiling built from a PAG's room."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from shapely.geometry import Polygon

from ..geometry.surfaces import Surface
from ..pag.model import Room
from .model import RoomShell, ShellElement

if TYPE_CHECKING:
    import trimesh

__all__ = ["build_shell", "DEFAULT_WALL_THICKNESS"]

DEFAULT_WALL_THICKNESS = 0.12
_SLAB = 0.1  # floor and ceiling slab thickness, m


def _extrude(poly2d: np.ndarray, z0: float, z1: float) -> trimesh.Trimesh:
    import trimesh

    return trimesh.creation.extrude_polygon(Polygon(poly2d), z1 - z0).apply_translation([0, 0, z0])


def _convex_corner(fp: np.ndarray, i: int) -> bool:
    """Whether vertex ``i`` of a counter-clockwise polygon is convex."""
    p, c, n = fp[i - 1], fp[i], fp[(i + 1) % len(fp)]
    d1, d2 = c - p, n - c
    return float(d1[0] * d2[1] - d1[1] * d2[0]) > 0


def build_shell(room: Room, *, wall_thickness: float = DEFAULT_WALL_THICKNESS) -> RoomShell:
    """Floor, walls and ceiling of ``room`` as static world-frame slabs with inward surfaces.

    Walls stand outside the footprint (their inner face lies exactly on the footprint edge) and
    run from the floor to the ceiling; wall ``i`` runs from vertex ``i`` to vertex ``i+1``.
    """
    fp = np.asarray(room.footprint, float)
    if Polygon(fp).exterior.is_ccw is False:
        fp = fp[::-1]
    h = float(room.height)
    poly = Polygon(fp)
    elements: dict[str, ShellElement] = {}
    c = np.asarray(poly.centroid.coords[0])
    outer = poly.buffer(wall_thickness, join_style="mitre")

    floor_mesh = _extrude(np.asarray(outer.exterior.coords)[:-1], -_SLAB, 0.0)
    floor_poly = Polygon(fp - c)
    elements["floor"] = ShellElement(
        "floor", floor_mesh,
        Surface("top", np.array([c[0], c[1], 0.0]), np.array([0, 0, 1.0]),
                np.array([1.0, 0, 0]), np.array([0, 1.0, 0]), floor_poly, "mesh"))
    for i in range(len(fp)):
        a, b = fp[i], fp[(i + 1) % len(fp)]
        d = b - a
        length = float(np.linalg.norm(d))
        t = d / length
        inward = np.array([-t[1], t[0]])  # left of a->b is inside for a CCW polygon
        # slabs overlap at convex corners; at a reflex corner (an L-shaped room's inner corner)
        # an extended slab would poke into the room, so it stops at the corner there
        ea = wall_thickness if _convex_corner(fp, i) else 0.0
        eb = wall_thickness if _convex_corner(fp, (i + 1) % len(fp)) else 0.0
        quad = np.array([a - t * ea, b + t * eb,
                         b + t * eb - inward * wall_thickness,
                         a - t * ea - inward * wall_thickness])
        mesh = _extrude(quad, -_SLAB, h + _SLAB)
        mid = (a + b) / 2
        n = np.array([inward[0], inward[1], 0.0])
        u = np.array([t[0], t[1], 0.0])
        v = np.array([0, 0, 1.0])
        if np.dot(np.cross(u, v), n) < 0:
            u = -u
        surf = Surface("front", np.array([mid[0], mid[1], h / 2]), n, u, v,
                       Polygon([(-length / 2, -h / 2), (length / 2, -h / 2),
                                (length / 2, h / 2), (-length / 2, h / 2)]), "mesh")
        elements[f"wall_{i}"] = ShellElement(f"wall_{i}", mesh, surf)
    ceil_mesh = _extrude(np.asarray(outer.exterior.coords)[:-1], h, h + _SLAB)
    elements["ceiling"] = ShellElement(
        "ceiling", ceil_mesh,
        Surface("bottom", np.array([c[0], c[1], h]), np.array([0, 0, -1.0]),
                np.array([1.0, 0, 0]), np.array([0, -1.0, 0]),
                Polygon(np.c_[fp[:, 0] - c[0], -(fp[:, 1] - c[1])]), "mesh"))
    return RoomShell(fp, h, wall_thickness, elements)
