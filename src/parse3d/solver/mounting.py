"""A thing mounted on an object's part by its back: a screen on a cart's VESA plate, a sign in
a stand's frame.

``SECURED_TO display:back_cover@back -> monitor_cart:mount@front`` fixes a 0.94 x 0.66 m
screen to a 0.39 x 0.29 m plate: the writer means the screen's back is fixed to the plate, the
screen far larger than it, not a footprint that must fit the plate. When the child's footprint
does not fit the part's face, the centre of its named part (else of its back, its points within
2 mm of the face) goes over the face instead (:func:`mount_region`); the rest of it may reach
past the face, clear of the owner's other parts at its depth and of other objects.

What is fixed on the face (the parts within :data:`~parse3d.measure.reach.MOUNTED_DEPTH` in
front of it and over it: a plate's VESA arms, the printed face set in a stand's frame) holds
the child: its back rests on the frontmost of them, and the ``SECURED_TO`` check accepts that
contact (:mod:`parse3d.measure.checks`).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry

from ..geometry import regions as RG
from ..measure.checks import EPS
from ..measure.reach import MOUNTED_DEPTH
from .config import Fail
from .regions import apply_region_rules, obstacles
from .rules import RULES
from .sampling import owner_pieces, reach_box, region_context

__all__ = ["mounts", "mount_region", "mounted_front", "BACK_BAND", "MOUNTED_SHARE"]

#: Metres from the child's rearmost point within which its points make up its back.
BACK_BAND = 2e-3

#: Metres off the face within which a part of the owner must begin to be mounted on it.
ON_FACE = 5e-3

#: Share of the face the parts mounted on it must cover together to hold the child (a VESA
#: plate's two arms cover a fifth of it; a whiteboard's frame round the board much less).
MOUNTED_SHARE = 0.15


def _mounted(d: Any) -> list[tuple[float, float, np.ndarray]]:
    """``(lowest, highest, footprint)`` of the owner's parts fixed on the face: beginning
    within :data:`ON_FACE` of it, ending within ``MOUNTED_DEPTH`` in front, over its region,
    together covering :data:`MOUNTED_SHARE` of it (none otherwise)."""
    out = []
    for lo_h, hi_h, fp in owner_pieces(d.st, d.sup, {d.sup.owner}, MOUNTED_DEPTH + 1e-3):
        if lo_h <= ON_FACE and hi_h <= MOUNTED_DEPTH and len(fp) >= 3 \
                and Polygon(fp).intersects(d.region0):
            out.append((lo_h, hi_h, fp))
    if not out:
        return out
    # together they cover a share of the face (a plate's two arms, a printed face), not a
    # strip along it or a frame round it (a whiteboard's: what is fixed there goes on the board)
    cover = shapely.union_all([Polygon(fp) for _, _, fp in out])
    if cover.intersection(d.region0).area < MOUNTED_SHARE * d.region0.area:
        return []
    return out


def mounted_front(d: Any) -> float:
    """Metres in front of the face at which what is mounted on it ends (0 with nothing)."""
    return max((hi for _, hi, _ in _mounted(d)), default=0.0)


def _named_back(d: Any, Y: np.ndarray, hN: np.ndarray) -> np.ndarray:
    """The points (turned, scaled) by which the child is fixed: its named part's (a screen's
    back cover), else (named by no part, or placed by the whole object when another part
    reaches further back: a screen's stand) its points within
    :data:`BACK_BAND` of its rearmost."""
    ref = d.edge.child
    parts = d.asset.parts_by_label(ref.part) if ref.part is not None else []
    if ref.index is not None:
        parts = parts[ref.index:ref.index + 1]
    pts = [pc.vertices for p in parts for pc in p.piece_arrays] or \
        [p.vertices for p in parts if len(p.vertices)]
    if not pts:
        return Y[hN <= hN.min() + BACK_BAND]
    return (np.vstack(pts) * d.scale) @ d.R.T


def mounts(d: Any) -> bool:
    """Whether the child of ``d`` (a :class:`~parse3d.solver.placement._OnSupport`) is
    mounted: ``SECURED_TO`` an object's part whose face its footprint does not fit, or does
    not fit clear of the other parts fixed on that face."""
    if d.edge.relation != "SECURED_TO" or d.sup.owner == "room" or d.edge.parent.part is None:
        return False
    if RG.erode(d.region0, [], d.F).is_empty:
        return True
    # parts on the face hold the child only where it does not fit between them: a note goes
    # on a corkboard's cork beside the notes and pins modelled there, not onto a pin's head
    fixed = _mounted(d)
    return bool(fixed) and RG.erode(d.region0, [fp for _, _, fp in fixed], d.F).is_empty


def mount_region(d: Any) -> BaseGeometry:
    """Positions of the child's origin in the face's plane: the whole footprint on the face
    where it fits, else the centre of its back over the face; clear of other objects and of
    the owner's parts at the depths the child reaches; within the height band and the
    relations' regions. Sets ``d.lift`` (the child rests on what is mounted on the face) and
    ``d.obst``. ``Fail`` when nothing is left."""
    st, sup, F, region0 = d.st, d.sup, d.F, d.region0
    s = sup.surface
    mounted = _mounted(d)
    d.lift = max((hi for _, hi, _ in mounted), default=0.0)
    Y = d.hull @ d.R.T
    hN = Y @ s.normal
    whole = RG.erode(region0, [], F)
    if whole.is_empty or whole.area < 1e-10:
        back = _named_back(d, Y, hN)
        c = np.array([float(np.mean(back @ s.u)), float(np.mean(back @ s.v))])
        Fc = RG.convex_footprint(np.vstack([c + o for o in ((0, 0), (1e-4, 0), (0, 1e-4),
                                                            (1e-4, 1e-4))]))
        whole = RG.erode(region0, [], Fc)
    if whole.is_empty or whole.area < 1e-10:
        raise Fail(f"no room to mount {d.oid} on {sup.name}: the centre of its back does not "
                   f"fit the face", intrinsic=True)
    area = RG.bounding_square(region0, pad=5.0)
    d.obst = obstacles(st, sup, d.exclude, d.height + EPS + d.lift,
                       reach_box(region0, F, 5.0), parts=False)
    region = RG.clip(whole, RG.erode(area, d.obst, F))
    depth = hN - hN.min() + d.lift + EPS
    fixed = {(lo, hi, fp.tobytes()) for lo, hi, fp in mounted}
    for lo_h, hi_h, fp in owner_pieces(st, sup, d.exclude, d.height + d.lift + EPS):
        if (lo_h, hi_h, fp.tobytes()) in fixed:
            continue  # behind its back: what it rests on
        at = Y[(depth >= lo_h - 1e-3) & (depth <= hi_h + 1e-3)]
        if len(at):
            Fs = RG.convex_footprint(np.vstack([np.c_[at @ s.u, at @ s.v],
                                                np.c_[at @ s.u, at @ s.v] + 1e-4]))
            region = RG.clip(region, RG.erode(area, [fp], Fs))
    if region.is_empty or region.area < 1e-10:
        raise Fail(f"no room to mount {d.oid} on {sup.name}: other objects or {sup.owner}'s "
                   f"other parts in the way")
    ctx = region_context(st, d.oid, d.asset, d.scale, d.R, d.h, sup)
    region = apply_region_rules(ctx, d.others, region, "object")
    region = RULES[d.edge.relation].band(ctx, d.edge, region)
    return apply_region_rules(ctx, d.others, region, "part")
