"""Flat things filed in a rack's slots: plates IN a dish rack stand on edge between its tines.

A person writes "three plates in the dish rack"; the rack holds them on edge, each between two
of a row of like upright parts (tines, dividers, pegs). When a flat child cannot be placed in
or on such an object as written (lying, it would rest on the tines or hang off the rack's wire
floor), it is stood on edge across the row, in the first free gap that is wide enough, and
lowered until it rests on the object's floor; it rests on the face that is then down
(``rests_on`` in scene.json, the way a toothbrush in a tumbler rests on its lower end) and
leans on a tine as it settles.
"""

from __future__ import annotations

import numpy as np

from ..assets.model import Asset
from ..measure.checks import EPS
from ..pag.model import Edge
from .collision import Body
from .config import Fail
from .geometry import asset_geometry
from .ledge import accept
from .nesting import pieces_drop
from .state import SolveState
from .support import Support

__all__ = ["may_slot", "place_in_slots", "slot_rows"]

#: Like upright parts a row needs.
ROW_MIN = 3
#: An upright part is at least this many times taller than it is wide.
UPRIGHT = 3.0
#: Metres the posts of a row may stray from its line (and their bottoms from one level).
ROW_TOL = 0.01
#: A flat child: its thickness at most this share of its middle extent.
FLAT = 0.3
#: Metres of play a gap must leave beside the child's thickness.
PLAY = 0.002
#: The share of the child's half depth (across the row) its middle may be off the row: the
#: posts hold it below its middle, not at its very edge; tried in DEPTHS steps.
HOLD = 0.8
DEPTHS = 4
#: Metres above the posts' foot the child is lowered from, and within which it must come to
#: rest (on the object's floor, not on a wire of its wall).
LOWER = 0.015
REACH = 0.012

_LABELS = {(0, 1): "right", (0, -1): "left", (1, 1): "front", (1, -1): "back",
           (2, 1): "top", (2, -1): "bottom"}


def slot_rows(asset: Asset, pieces: list[tuple[str, np.ndarray]]
              ) -> list[tuple[np.ndarray, np.ndarray, np.ndarray, float]]:
    """The rows of like upright parts of an object (``pieces``: its ``(part name, world
    vertices)`` per convex piece, :meth:`SolveState.world_pieces`), each as ``(post centres
    (k, 3) in order along the row, the row's unit direction (3,), the gaps between neighbouring
    posts less their thickness (k-1,), the height of the posts' foot)``: at least
    :data:`ROW_MIN` parts of one label, each :data:`UPRIGHT` times taller than wide, standing
    on one level along a line (a dish rack's tines)."""
    by_label: dict[str, list[np.ndarray]] = {}
    names = {p.name: p.label for p in asset.parts}
    for name, pts in pieces:
        by_label.setdefault(names.get(name, name), []).append(pts)
    rows = []
    for groups in by_label.values():
        if len(groups) < ROW_MIN:
            continue
        lo = np.array([g.min(axis=0) for g in groups])
        hi = np.array([g.max(axis=0) for g in groups])
        ext = hi - lo
        if not np.all(ext[:, 2] >= UPRIGHT * ext[:, :2].max(axis=1)):
            continue
        if np.ptp(lo[:, 2]) > ROW_TOL:
            continue
        c = 0.5 * (lo + hi)
        xy = c[:, :2] - c[:, :2].mean(axis=0)
        _, _, vt = np.linalg.svd(xy, full_matrices=False)
        d2 = vt[0]
        if np.abs(xy @ vt[1]).max() > ROW_TOL:
            continue
        order = np.argsort(xy @ d2)
        c = c[order]
        width = ext[order][:, :2].max(axis=1)
        d = np.array([d2[0], d2[1], 0.0])
        gaps = np.linalg.norm(np.diff(c[:, :2], axis=0), axis=1) - 0.5 * (width[:-1] + width[1:])
        rows.append((c, d, gaps, float(lo[:, 2].min())))
    return rows


def _flat(asset: Asset, scale: float) -> tuple[int, int, int] | None:
    """``(thin, vertical, across)`` axes of a flat child (its thickness at most :data:`FLAT`
    of its middle extent): the thin axis goes along the row, the shorter of the others up."""
    ext = np.ptp(asset_geometry(asset).hull, axis=0) * scale
    order = [int(i) for i in np.argsort(ext)]
    if ext[order[0]] > FLAT * ext[order[1]]:
        return None
    return order[0], order[1], order[2]


def may_slot(st: SolveState, asset: Asset, scale: float, sup: Support, edge: Edge) -> bool:
    """Whether :func:`place_in_slots` applies: a flat child ``IN`` or ``ON`` an object with a
    row of upright parts whose gaps are wider than the child is thick."""
    if edge.relation not in ("IN", "ON") or sup.owner not in st.scene.objects:
        return False
    axes = _flat(asset, scale)
    if axes is None:
        return False
    thick = float(np.ptp(asset_geometry(asset).hull[:, axes[0]]) * scale)
    rows = slot_rows(st.scene.objects[sup.owner].asset, st.world_pieces(sup.owner))
    return any((gaps > thick + PLAY).any() for _, _, gaps, _ in rows)


def _rotation(axes: tuple[int, int, int], d: np.ndarray) -> tuple[np.ndarray, str]:
    """The rotation standing the child on edge across the row ``d`` and the face then down."""
    thin, up, across = axes
    z = np.array([0.0, 0.0, 1.0])
    R = np.zeros((3, 3))
    R[:, thin] = d
    R[:, up] = z
    R[:, across] = np.cross(z, d)
    if np.linalg.det(R) < 0:
        R[:, across] *= -1
    return R, _LABELS[(up, -1)]


def place_in_slots(st: SolveState, oid: str, asset: Asset, scale: float, sup: Support,
                   edge: Edge, body: Body, rng: np.random.Generator, validate) -> tuple:
    """Stand the flat child on edge in the first free gap of a row of upright parts of the
    object ``sup`` belongs to, lowered onto the object; ``validate(cand, sup)`` returns
    ``(ok, why, checks)`` as the solver's relation checks do. Returns ``((R, t, sup, body,
    rests_on), trials, checks, None)`` like the solver's other placements; raises ``Fail``."""
    axes = _flat(asset, scale)
    parent = st.scene.objects[sup.owner]
    hull = asset_geometry(asset).hull * scale
    thick = float(np.ptp(hull[:, axes[0]]))
    P = np.vstack([pts for _, pts in st.world_pieces(sup.owner)])
    trials = 0
    last = f"no gap between its parts is wider than {oid} is thick"
    for centres, d, gaps, bottom in slot_rows(parent.asset, st.world_pieces(sup.owner)):
        R, rests = _rotation(axes, d)
        n = np.cross([0.0, 0.0, 1.0], d)
        Y = hull @ R.T
        half = 0.5 * float(np.ptp(Y @ n))
        mid_n = 0.5 * float((Y @ n).min() + (Y @ n).max())
        row_n = float(centres[0] @ n)
        # across the row: the child's middle on the row, or moved toward the middle of the
        # object (clear of its walls), the row still passing through the child within HOLD
        inward = 1.0 if float(P.mean(axis=0) @ n) >= row_n else -1.0
        depths = [row_n + inward * k * HOLD * half / DEPTHS for k in range(DEPTHS + 1)]
        mids = 0.5 * (centres[:-1] + centres[1:])
        free = [i for i in range(len(gaps)) if gaps[i] > thick + PLAY]
        # from one end of the row or the other, as a person fills a rack
        if rng.random() < 0.5:
            free.reverse()
        for i in free:
            along = float(mids[i] @ d) - 0.5 * float((Y @ d).min() + (Y @ d).max())
            for c_n in depths:
                trials += 1
                t = along * d + (c_n - mid_n) * n
                t[2] = bottom + LOWER - float(Y[:, 2].min())
                T = np.eye(4)
                T[:3, :3] = R * scale
                T[:3, 3] = t
                drop = pieces_drop(asset, T, parent, np.array([0.0, 0.0, -1.0]), 2 * LOWER)
                if drop <= 0.0:
                    last = f"it would run into {sup.owner} there"
                    continue
                t = t - np.array([0.0, 0.0, drop - EPS])
                if float((Y[:, 2] + t[2]).min()) > bottom + REACH:
                    last = f"it would stay above the floor of {sup.owner}'s slots"
                    continue
                checks, why = accept(st, oid, asset, scale, R, t, rests, sup, body, validate)
                if checks is not None:
                    return (R, t, sup, body, rests), trials, checks, None
                last = why
    raise Fail(f"no room to stand {oid} on edge in {sup.owner}'s slots ({trials} tried, "
               f"last: {last})")
