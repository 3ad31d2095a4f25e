"""Whether a child dropped onto other objects is held where it comes to rest.

A drop brings a child down until it first touches something; that is where it would rest
only if its centre of mass lies over what it touches. A cup dropped onto a kettle's knob
touches it at one point and slides off in settling, a can dropped onto the rounded shoulder
of a jar rolls away; an apple dropped among other apples and a bowl's wall rests on several
points around it. :func:`rest_points` finds the points of contact of a dropped pose,
:func:`held_at_rest` tests the centre of mass against their hull.
"""

from __future__ import annotations

import numpy as np
import shapely

from ..assets.model import Asset
from ..measure.checks import world_points
from ..measure.geometry import asset_geometry, ray_caster
from ..scene.model import PlacedObject

__all__ = ["REST_TOL", "REST_MARGIN", "LINE_TOL", "RAISED", "rest_points", "held_at_rest",
           "rests_on"]


#: Metres above the first contact within which a point of a dropped child counts as touching
#: (a rest on a flat top touches along the whole base, within the drop's tolerance).
REST_TOL = 3e-3


#: Fraction of the child's narrowest width its centre of mass keeps inside the hull of its
#: contacts (an unstable balance on an edge tips at the first push of settling).
REST_MARGIN = 0.05


#: Metres from a line (or point) of contact within which a centre of mass is over it: a pen
#: lying on its side rests along a line, as the ``ON`` check reads it (2 mm).
LINE_TOL = 2e-3


def _hits(pts: np.ndarray, asset: Asset, T: np.ndarray, d: np.ndarray) -> np.ndarray:
    """Distance along ``d`` from each world point ``pts`` (N, 3) to the asset's mesh placed
    by ``T`` (inf where the ray misses)."""
    Ti = np.linalg.inv(T)
    o = pts @ Ti[:3, :3].T + Ti[:3, 3]
    v = Ti[:3, :3] @ d
    scale = float(np.linalg.norm(v))
    out = np.full(len(pts), np.inf)
    if not len(pts):
        return out
    locs, idx, _ = ray_caster(asset).first_hits(o, np.tile(v / scale, (len(o), 1)))
    if len(idx):
        dist = np.linalg.norm(locs - o[idx], axis=1) / scale
        np.minimum.at(out, idx, dist)
    return out


def rest_points(child_pts: np.ndarray, child_asset: Asset, T_child: np.ndarray,
                below: list[tuple[np.ndarray, Asset, np.ndarray]], down: np.ndarray,
                *, tol: float = REST_TOL) -> np.ndarray:
    """(M, 3) world points where a child resting on the objects ``below`` touches them.

    Parameters
    ----------
    child_pts : (N, 3) float
        The child's points (its hull vertices), world frame, at rest.
    child_asset, T_child
        The child's asset and its asset-to-world similarity transform.
    below : list of (points (K, 3), asset, transform)
        What it may rest on, each with its points (world frame), asset and transform.
    down : (3,) float
        The direction of the drop (unit or not).

    The child's points within ``tol`` of a mesh below along ``down``, and the points below
    within ``tol`` of the child's mesh along ``-down``.
    """
    d = np.asarray(down, float) / np.linalg.norm(down)
    found = []
    for pts, asset, T in below:
        gap = _hits(child_pts, asset, T, d)
        found.append(child_pts[gap <= tol])
        up = _hits(pts, child_asset, T_child, -d)
        found.append(pts[up <= tol])
    return np.vstack(found) if found else np.zeros((0, 3))


def held_at_rest(com: np.ndarray, points: np.ndarray, u: np.ndarray, v: np.ndarray,
                 width: float, *, margin: float = REST_MARGIN) -> bool:
    """Whether the centre of mass ``com`` (3,) lies over the contact ``points`` (M, 3): inside
    their convex hull seen along the support normal (in-plane axes ``u``, ``v``), at least
    ``margin`` times ``width`` (metres, the child's narrowest width) from its edge."""
    if not len(points):
        return False
    hull = shapely.MultiPoint(np.c_[points @ u, points @ v]).convex_hull
    p = shapely.Point(float(com @ u), float(com @ v))
    if hull.geom_type != "Polygon":  # on a line or a point (a pen lying on a pad): over it
        return bool(hull.distance(p) <= LINE_TOL)
    return bool(hull.contains(p) and hull.exterior.distance(p) >= margin * width)


#: Metres above the named surface from which a child rests on something raised on it (as
#: the low parts a child is raised onto are read, ``docs/solver.md``).
RAISED = 3e-3


def rests_on(child: PlacedObject, parent: PlacedObject, parent_pts: np.ndarray,
             origin: np.ndarray, normal: np.ndarray, u: np.ndarray, v: np.ndarray) -> bool:
    """Whether ``child``, dropped onto ``parent`` along ``-normal``, is held where it came to
    rest: its centre of mass over the points where it touches the parent's mesh, by
    ``REST_MARGIN`` of its narrowest width (:func:`held_at_rest`). A register dropped
    half over a counter's edge onto a conveyor raised on the counter rests on the conveyor,
    whose edge is inside the counter's: its centre of mass over the counter is not over the
    conveyor, and it tips off in settling. ``parent_pts`` (K, 3) are the vertices of the
    parent's convex pieces, world frame; ``origin``, ``normal``, ``u``, ``v`` the named
    support plane's point, normal and axes. A child resting on the named surface itself (its
    lowest point within ``RAISED`` of it) is left to the support polygon's test (True)."""
    T = child.transform()
    pts = world_points(child, hull_only=True)
    if float(np.min((pts - origin) @ normal)) <= RAISED:
        return True
    # the parent's points under the child's footprint (the tops of a keyboard's keys)
    a, b = pts @ u, pts @ v
    pa, pb = parent_pts @ u, parent_pts @ v
    under = parent_pts[(pa >= a.min()) & (pa <= a.max()) & (pb >= b.min()) & (pb <= b.max())]
    touch = rest_points(pts, child.asset, T, [(under, parent.asset, parent.transform())],
                        -np.asarray(normal, float))
    com = T[:3, :3] @ asset_geometry(child.asset).com + T[:3, 3]
    width = float(min(np.ptp(pts @ u), np.ptp(pts @ v)))
    return held_at_rest(com, touch, u, v, width)
