"""Physics guidance while denoising: the objects' collision pieces pushed out of each other.

What the layout models get wrong is not a centimetre here and there: on held-out scenes the
pairs that interpenetrate by more than 1 cm do so by 10 cm (median), a book sunk into its shelf
board, a pillow into the mattress, a nightstand into the bed. The network's clean-pose estimate
is that far off, and no sampler setting changes it (more denoising steps, raw weights instead
of EMA, no clipping, the assets' real scales, upright rotations: all within a few points of
the collision rate). PhyScene's answer is guidance: during the last denoising steps, the
estimate of the clean layout is moved down the gradient of a physical penalty, and the noise
estimate is made consistent with the moved estimate, so the sampler continues from a layout
that does not interpenetrate.

The penalty here is on the objects' own collision geometry, which the sampler knows (each
object's asset): every convex collision piece of every asset as a box in the asset's frame,
scaled, turned and moved with the object to an axis-aligned world box. For every pair of
objects whose piece boxes overlap, each of the six directions (up, down, sideways) has the
move that clears every overlapping pair of their pieces; the pair's objects move apart along
the shortest one, the larger object by less (inverse to volume), and a direction that would
push either of them out of the room costs four times what it would leave; one that would lift
an object standing on the floor is taken only when no other is left (a chair in a desk goes
sideways, not onto it). Boxes of pieces, not of whole objects: a book between a bookcase's
boards overlaps none of them, one sunk into a board is lifted out of it onto the board. The
room penalty moves an object back inside the room's bounding box and its footprint (an
L-shaped room's inner corner included). The pairs are resolved one after the other, each
seeing the moves of those before it (summing the moves of all pairs at once lets two
neighbours pushing one object from both sides cancel out, and leaves it stuck in both), and
the pass is repeated per guided step until nothing moves (at most
:data:`PASSES` times); each pair's move is the
gradient step of its squared depth along that direction, with the step size that separates
the pair in one move.

The PAG-conditioned sampler guides with its condition, as classifier guidance steers with
the class (``supports``, the ``ON``/``IN`` parent of every object, :func:`pag_supports`):

- a child overlapping the object that carries it moves alone (:func:`_into_slot`): out of
  each parent piece its own way, up onto a piece under its middle (a shelf board, a desk
  top), down from one over it (the board above a shelf), up or sideways from one across it
  (a side panel), never down through its parent or off its plan;
- siblings on one support move apart within the support surface (sideways only), each kept
  over the parent;
- a supported object is not lifted or lowered off its support by any other pair (as one
  standing on the floor);
- an object carries what it supports: a nightstand pushed out of the bed takes its lamp.

The unconditioned rows (and a ``pag`` run sampled with its condition dropped) never see the
PAG: they get the PAG-free push above (``supports`` None). It runs inside the sampler; the
random baseline, which has no denoising steps, does not get it, but ``eval --guide`` also
reports the random poses after the same number of PAG-free passes as a control.
"""

from __future__ import annotations

import numpy as np

from ..assets.model import Asset
from ..relations import SUPPORT_RELATIONS
from .pose import room_box, rotation_from_6d

__all__ = ["PieceBoxes", "piece_boxes", "grounded", "guide_push", "guide_poses", "PASSES",
           "still", "pag_supports"]

#: Passes of :func:`guide_push` per guided denoising step, at most (they stop once nothing
#: moves by more than :data:`_STILL`).
PASSES = 48
_STILL = 1e-4
#: Overlaps shallower than this (m) are left alone (the collision metric counts 1 cm).
_SLACK = 0.001
#: Cost per metre that a move would take an object out of the room's box.
_BLOCKED = 4.0
#: Cost per metre of lifting an object that stands on the floor: only when nothing else is left.
_GROUNDED = 1e3
#: An object whose lowest point is this close to the floor (m) stands on it.
_ON_FLOOR = 0.02


class PieceBoxes:
    """The collision pieces of a scene's assets as boxes in each asset's frame.

    Attributes
    ----------
    lo, hi : (M, 3) float
        Bounds of every piece, asset frame, unscaled.
    owner : (M,) int
        The object each piece belongs to.
    extents : (N, 3) float
        Each asset's extents (for the equal-volume scale of a generated size).
    """

    def __init__(self, assets: list[Asset]):
        from ..physics.collision import asset_collision

        lo, hi, owner = [], [], []
        for k, a in enumerate(assets):
            b = np.asarray(asset_collision(a).pieces.bounds, float).reshape(-1, 2, 3)
            lo.append(b[:, 0])
            hi.append(b[:, 1])
            owner.append(np.full(len(b), k))
        self.lo = np.concatenate(lo) if lo else np.zeros((0, 3))
        self.hi = np.concatenate(hi) if hi else np.zeros((0, 3))
        self.owner = np.concatenate(owner).astype(int) if owner else np.zeros(0, int)
        self.extents = np.array([np.maximum(a.extents, 1e-4) for a in assets], float).reshape(-1, 3)

    def scales(self, poses: np.ndarray) -> np.ndarray:
        """(N,) the uniform scale of equal volume of every asset and its generated size (as the
        assets are placed), clipped to the sampler's range."""
        from .sample import SCALE_RANGE

        size = np.maximum(np.asarray(poses, float)[:, 3:6], 1e-3)
        return np.clip(np.cbrt(np.prod(size, 1) / np.prod(self.extents, 1)), *SCALE_RANGE)

    def world(self, poses: np.ndarray, scales: np.ndarray | None = None
              ) -> tuple[np.ndarray, np.ndarray]:
        """(M, 3) world centres and half extents of the pieces' axis-aligned boxes."""
        p = np.asarray(poses, float)
        s = self.scales(p) if scales is None else np.asarray(scales, float)
        R = rotation_from_6d(p[:, 6:12])[self.owner]
        sc = s[self.owner][:, None]
        c_loc = 0.5 * (self.lo + self.hi) * sc
        h_loc = 0.5 * (self.hi - self.lo) * sc
        centre = np.einsum("mij,mj->mi", R, c_loc) + p[self.owner, :3]
        half = np.einsum("mij,mj->mi", np.abs(R), h_loc)
        return centre, half


def piece_boxes(assets: list[Asset]) -> PieceBoxes:
    """:class:`PieceBoxes` of ``assets`` (one per object, in order)."""
    return PieceBoxes(assets)


def _room_push(lo: np.ndarray, hi: np.ndarray, footprint: np.ndarray, height: float
               ) -> np.ndarray:
    """(N, 3) moves that bring every object's box back into the room (where it fits)."""
    import shapely
    from shapely.geometry import Polygon

    rlo, rhi = room_box(footprint, height)
    fits = (hi - lo) <= (rhi - rlo)
    d = np.where(fits, np.maximum(rlo - lo, 0) - np.maximum(hi - rhi, 0), 0.0)
    poly = Polygon(footprint)
    if abs(poly.area - float(np.prod((rhi - rlo)[:2]))) < 1e-9:
        return d  # a rectangular room: its box is the room
    # plan corners outside a non-rectangular footprint: towards the nearest boundary point
    nlo, nhi = lo + d, hi + d
    corners = np.stack([np.c_[nlo[:, 0], nlo[:, 1]], np.c_[nhi[:, 0], nlo[:, 1]],
                        np.c_[nhi[:, 0], nhi[:, 1]], np.c_[nlo[:, 0], nhi[:, 1]]], 1)
    flat = corners.reshape(-1, 2)
    inside = shapely.contains_xy(poly, flat[:, 0], flat[:, 1]).reshape(-1, 4)
    ring = poly.exterior
    for i in np.flatnonzero(~inside.all(1)):
        if not fits[i, :2].all():
            continue
        mv = np.zeros(2)
        for c in corners[i][~inside[i]]:
            q = ring.interpolate(ring.project(shapely.Point(c)))
            v = np.array([q.x, q.y]) - c
            mv = np.where(np.abs(v) > np.abs(mv), v, mv)
        d[i, :2] += mv
    return d


def grounded(poses: np.ndarray, boxes: PieceBoxes, scales: np.ndarray | None = None
             ) -> np.ndarray:
    """(N,) bool: the objects whose lowest piece is within 2 cm of the floor."""
    c, h = boxes.world(poses, scales)
    low = np.full(len(poses), np.inf)
    np.minimum.at(low, boxes.owner, c[:, 2] - h[:, 2])
    return low < _ON_FLOOR


def pag_supports(relations, n: int) -> np.ndarray:
    """(n,) the object each object stands ``ON`` or is ``IN`` (-1: none, the room, or carried
    another way), from the PAG's relations (:class:`.data.RelationSpec`): the object's first
    support relation, as :func:`.data.support_parents` reads it."""
    from .data import support_parents

    parents = support_parents(relations, n)
    first: dict[int, str] = {}
    for r in relations:
        if r.relation in SUPPORT_RELATIONS:
            first.setdefault(r.child, r.relation)
    for k in range(n):
        if first.get(k) not in ("ON", "IN"):
            parents[k] = -1
    return parents


def _carried(supports: np.ndarray) -> list[list[int]]:
    """Per object, itself and every object it carries (its support subtree)."""
    n = len(supports)
    kids: list[list[int]] = [[] for _ in range(n)]
    for k, p in enumerate(supports):
        if p >= 0:
            kids[int(p)].append(k)
    out = []
    for k in range(n):
        seen, todo = [], [k]
        while todo:
            x = todo.pop()
            if x not in seen:
                seen.append(x)
                todo.extend(kids[x])
        out.append(seen)
    return out


def _into_slot(clo: np.ndarray, chi: np.ndarray, plo: np.ndarray, phi: np.ndarray
               ) -> np.ndarray:
    """(3,) the move of a child (box ``clo``-``chi``) out of the pieces of its parent that it
    overlaps (boxes ``plo``-``phi``), each piece its own way: a piece under the child's middle
    (a shelf board, a desk top) lifts it onto the piece, one over it (the board above a
    shelf) lowers it, one across it (a side panel, a mattress the child sank into) lifts it
    or pushes it sideways, whichever is shorter; a book sunk into the corner of its
    compartment comes out into the compartment. Per axis the largest move counts, a lift
    before a lowering."""
    mid = 0.5 * (clo[2] + chi[2])
    up = phi[:, 2] - clo[2]
    below = phi[:, 2] <= mid
    above = plo[:, 2] >= mid
    m = np.zeros(3)
    lift = 0.0
    for j in np.flatnonzero(~below & ~above):
        opts = np.array([phi[j, 0] - clo[0], -(chi[0] - plo[j, 0]),
                         phi[j, 1] - clo[1], -(chi[1] - plo[j, 1]), up[j]])
        k = int(np.argmin(np.abs(opts)))
        if k == 4:
            lift = max(lift, up[j])
        elif abs(opts[k]) > abs(m[k // 2]):
            m[k // 2] = opts[k]
    if below.any() or lift > 0:
        m[2] = max(up[below].max(initial=0.0), lift)
    elif above.any():
        m[2] = -(chi[2] - plo[above, 2]).max()
    return np.where(np.abs(m) > _SLACK, m, 0.0)


def guide_push(poses: np.ndarray, boxes: PieceBoxes, footprint: np.ndarray, height: float,
               scales: np.ndarray | None = None, ground: np.ndarray | None = None,
               supports: np.ndarray | None = None) -> np.ndarray:
    """(N, 3) world displacements of one guidance pass over (N, 12) world poses.

    Every pair of objects whose piece boxes overlap (more than 1 mm), in turn, moves apart
    along the cheapest direction that clears all their overlapping pieces, shared inversely
    to the objects' volumes; a pair sees the moves of the pairs before it. Then every object
    is brought back inside the room (see the module docstring). ``ground``: the objects that stand on the floor
    and are not to be lifted (default: :func:`grounded` of ``poses``; a series of passes fixes
    it at its start, so that a lifted object does not stop counting as grounded).
    ``supports``: the PAG's ``ON``/``IN`` parent of every object (:func:`pag_supports`), for
    the PAG-conditioned sampler only: child and parent, siblings and what an object carries
    are then moved the PAG's way (see the module docstring); None: PAG-free.
    """
    p = np.asarray(poses, float)
    n = len(p)
    c, h = boxes.world(p, scales)
    lo, hi = c - h, c + h
    own = boxes.owner
    olo = np.full((n, 3), np.inf)
    ohi = np.full((n, 3), -np.inf)
    np.minimum.at(olo, own, lo)
    np.maximum.at(ohi, own, hi)
    empty = ~np.isfinite(olo).all(1)
    olo[empty], ohi[empty] = p[empty, :3], p[empty, :3]
    if ground is None:
        ground = grounded(p, boxes, scales)
    ground = np.asarray(ground, float)
    sup = None if supports is None else np.asarray(supports, int)
    # what moves with an object: itself, and under the PAG what it carries
    group = [[k] for k in range(n)] if sup is None else _carried(sup)
    # lifting or lowering an object off what carries it: as costly as lifting off the floor
    held = np.zeros(n) if sup is None else (sup >= 0).astype(float)
    d = np.zeros((n, 3))
    rlo, rhi = room_box(footprint, height)
    vol = np.prod(np.maximum(ohi - olo, 1e-3), 1)
    u = np.concatenate([np.eye(3), -np.eye(3)])  # (6, 3) directions of a
    flat = np.array([1.0, 1.0, 0.0, 1.0, 1.0, 0.0])  # the sideways directions

    def off(o: int, m: np.ndarray) -> np.ndarray:
        """How far (per direction) object ``o`` moved by ``m`` (6, 3) leaves the plan of what
        carries it (0 without a carrier)."""
        if sup is None or sup[o] < 0:
            return np.zeros(len(m))
        q = int(sup[o])
        cen = 0.5 * (olo[o] + ohi[o])[:2] + m[:, :2]
        return (np.maximum(olo[q, :2] - cen, 0) + np.maximum(cen - ohi[q, :2], 0)).sum(1)

    # objects whose boxes overlap, then their pieces
    ov = np.all((olo[:, None] < ohi[None]) & (olo[None] < ohi[:, None]), axis=2)
    ia, ib = np.nonzero(np.triu(ov, 1))
    if len(ia):
        idx = [np.flatnonzero(own == k) for k in range(n)]
        for a, b in zip(ia, ib, strict=True):
            pa, pb = idx[a], idx[b]
            la, ha, lb, hb = lo[pa][:, None], hi[pa][:, None], lo[pb][None], hi[pb][None]
            # moves of a that clear b: + along an axis (hb - la) or - (ha - lb)
            plus, minus = hb - la, ha - lb
            hit = np.all((plus > _SLACK) & (minus > _SLACK), axis=2)
            if not hit.any():
                continue
            # per direction, the move that clears every overlapping pair of pieces
            need = np.concatenate([plus, minus], axis=2)[hit].max(0)  # (6,)
            wa = vol[b] / (vol[a] + vol[b])
            if sup is not None and (sup[a] == b or sup[b] == a):
                wa = 1.0 if sup[a] == b else 0.0  # the child moves, its parent stays
            ma, mb = u * (need * wa)[:, None], -u * (need * (1.0 - wa))[:, None]
            # a direction that would push either object out of the room costs what it leaves
            out = (np.maximum(rlo - (olo[a] + ma), 0) + np.maximum(ohi[a] + ma - rhi, 0)
                   + np.maximum(rlo - (olo[b] + mb), 0) + np.maximum(ohi[b] + mb - rhi, 0))
            # lifting what stands on the floor leaves it hanging in the air: as costly
            lift = np.maximum(ma[:, 2], 0) * ground[a] + np.maximum(mb[:, 2], 0) * ground[b]
            cost = need + _BLOCKED * out.sum(1) + _GROUNDED * lift
            if sup is not None:
                if sup[a] == b or sup[b] == a:
                    # the child up onto its parent's surface, or sideways over it: never
                    # down through it, never off it
                    mc = ma if sup[a] == b else mb
                    cost = need + _BLOCKED * out.sum(1) + _GROUNDED * (
                        np.maximum(-mc[:, 2], 0) + off(a if sup[a] == b else b, mc))
                else:
                    lift = np.abs(ma[:, 2]) * held[a] + np.abs(mb[:, 2]) * held[b]
                    cost = cost + _GROUNDED * (lift + off(a, ma) + off(b, mb))
                    if sup[a] == sup[b] and sup[a] >= 0:  # siblings: within their surface
                        cost = cost + _GROUNDED * (1.0 - flat) * need
            k = int(np.argmin(cost))
            moves = ((a, ma[k]), (b, mb[k]))
            if sup is not None and (sup[a] == b or sup[b] == a):
                ch = a if sup[a] == b else b
                pieces = (pb if ch == a else pa)[(hit.any(0) if ch == a else hit.any(1))]
                m = _into_slot(olo[ch], ohi[ch], lo[pieces], hi[pieces])
                if m.any():
                    moves = ((ch, m),)
            for o, m in moves:  # resolved now: later pairs see it moved
                if not m.any():
                    continue
                for x in group[o]:
                    lo[idx[x]] += m
                    hi[idx[x]] += m
                    olo[x] += m
                    ohi[x] += m
                    d[x] += m
        olo, ohi = olo - d, ohi - d
    return d + _room_push(olo + d, ohi + d, footprint, height)


def still(d: np.ndarray) -> bool:
    """Whether a pass's displacements ``d`` are all negligible (the passes may stop)."""
    return bool(np.abs(d).max(initial=0.0) < _STILL)


def guide_poses(poses: np.ndarray, boxes: PieceBoxes, footprint: np.ndarray, height: float, *,
                passes: int = PASSES, scales: np.ndarray | None = None,
                supports: np.ndarray | None = None) -> np.ndarray:
    """(N, 12) world poses after ``passes`` passes of :func:`guide_push` (PAG-free unless
    ``supports`` is given): the control the random baseline gets in ``eval --guide``."""
    out = np.array(poses, float, copy=True)
    ground = grounded(out, boxes, scales)
    for _ in range(passes):
        d = guide_push(out, boxes, footprint, height, scales, ground, supports)
        out[:, :3] += d
        if still(d):
            break
    return out
