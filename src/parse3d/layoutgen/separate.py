"""Separation guidance: push interpenetrating objects apart while sampling.

A diffusion model places objects to a few centimetres at best, and two pieces of furniture a
few centimetres into each other already collide. :func:`box_push` is a cheap, PAG-free
correction on the objects' oriented boxes, applied identically to every row that generates
poses (``SampleOptions.separate``; the random baseline gets :func:`separate_poses`):

- every pair whose world-axis boxes overlap is a candidate; a pair where one box lies mostly
  inside the other (80 % of the smaller one's volume) is left alone, since that is how an
  object sits *in* a shelf or a drawer;
- the pair is resolved along the axis of least penetration: vertically by lifting the upper
  object (so an object sunk into its support comes up onto it), horizontally by moving both
  apart, the larger one by less (weights inverse to volume);
- displacements of all pairs are summed, damped by half, and boxes kept inside the room's
  bounding box; the pass is repeated ``rounds`` times.

While sampling, the last ``separate`` denoising steps apply one pass to the network's estimate
of the clean poses (and the noise estimate is made consistent with it), and three more passes
follow the last step. A displacement is applied in the coordinates the model generates: for a
``--frame parent`` run a supported object moves relative to its parent and a parent carries
what it supports; for a world-frame run every object moves alone.

Boxes say nothing about an object sunk a few centimetres into the shelf board or the mattress
it lies on (its box is inside the parent's), so once the assets are placed,
:func:`separate_scene` resolves what still interpenetrates on the meshes themselves: per
pair, the deepest contact of their convex collision pieces (FCL, as the collision metric
finds them), and the smaller of the two objects moves out along the contact normal by the
depth plus 2 mm (sideways where the normal would push it into the floor), for a few rounds.
"""

from __future__ import annotations

import numpy as np

from .pose import room_box, rotation_from_6d

__all__ = ["box_push", "separate_poses", "separate_scene", "CONTAINED", "MESH_ROUNDS"]

#: Share of the smaller box inside the larger above which a pair is "in", not colliding.
CONTAINED = 0.8
_DAMP = 0.5


def _boxes(poses: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    R = rotation_from_6d(poses[:, 6:12])
    half = 0.5 * np.maximum(poses[:, 3:6], 1e-4)
    he = np.einsum("nij,nj->ni", np.abs(R), half)
    centre = poses[:, :3] + np.einsum("nij,nj->ni", R, np.c_[np.zeros((len(poses), 2)),
                                                             half[:, 2]])
    return centre, he


def box_push(poses: np.ndarray, footprint: np.ndarray, height: float) -> np.ndarray:
    """(N, 3) world displacements of one separation pass over (N, 12) world poses."""
    p = np.asarray(poses, float)
    n = len(p)
    d = np.zeros((n, 3))
    if n < 2:
        return d
    c, he = _boxes(p)
    lo, hi = c - he, c + he
    pen = np.minimum(hi[:, None], hi[None]) - np.maximum(lo[:, None], lo[None])  # (N, N, 3)
    vol = np.prod(2 * he, axis=1)
    iu, ju = np.triu_indices(n, 1)
    pp = pen[iu, ju]
    hit = np.all(pp > 0, axis=1)
    inter = np.prod(np.maximum(pp, 0), axis=1)
    small = np.minimum(vol[iu], vol[ju])
    hit &= inter < CONTAINED * small
    for i, j, pk in zip(iu[hit], ju[hit], pp[hit], strict=True):
        ax = int(np.argmin(pk))
        if ax == 2:
            up = i if c[i, 2] >= c[j, 2] else j
            d[up, 2] += pk[2]
            continue
        s = np.sign(c[i, ax] - c[j, ax]) or (1.0 if i < j else -1.0)
        wi = vol[j] / (vol[i] + vol[j])
        d[i, ax] += s * pk[ax] * wi
        d[j, ax] -= s * pk[ax] * (1.0 - wi)
    d *= _DAMP
    # keep every box inside the room's bounding box (where it fits)
    rlo, rhi = room_box(footprint, height)
    nlo, nhi = lo + d, hi + d
    fits = (hi - lo) <= (rhi - rlo)
    d += np.where(fits, np.maximum(rlo - nlo, 0) - np.maximum(nhi - rhi, 0), 0)
    return d


def separate_poses(poses: np.ndarray, footprint: np.ndarray, height: float, *,
                   rounds: int = 3) -> np.ndarray:
    """(N, 12) world poses after ``rounds`` passes of :func:`box_push` (objects move alone)."""
    out = np.array(poses, float, copy=True)
    for _ in range(rounds):
        out[:, :3] += box_push(out, footprint, height)
    return out


#: Rounds of :func:`separate_scene`.
MESH_ROUNDS = 8
_MARGIN = 0.002


def separate_scene(scene, *, rounds: int = MESH_ROUNDS, min_depth: float = _MARGIN) -> int:
    """Move interpenetrating objects of a Scene apart on their meshes (in place).

    Per round, every pair whose convex pieces penetrate deeper than ``min_depth`` (m) moves
    the smaller object (by bounding-box volume) along the deepest contact's normal, out by
    the depth plus 2 mm (sideways, away from the other object, where that would push it into
    the floor); an object pushed by several pairs moves by the sum. Fixed objects
    (held by the shell) move too: nothing is assumed about the PAG. Returns the number of
    moves made. The scene's relation checks are *not* updated.
    """
    from .evaluate import _deepest_contacts, _fcl_pieces

    moved = 0
    for _ in range(rounds):
        bodies = _fcl_pieces(scene)
        vol = [float(np.prod(np.ptp(b[1], axis=0))) for b in bodies]
        shift: dict[str, np.ndarray] = {}
        for i, j, best, normal in _deepest_contacts(bodies):
            if best <= min_depth:
                continue
            (ia, ba), (ib, bb) = bodies[i][:2], bodies[j][:2]
            # FCL's normal points from the first object to the second
            (mover, box, other), sign = (((ib, bb, ba), 1.0) if vol[j] <= vol[i]
                                         else ((ia, ba, bb), -1.0))
            d = sign * (best + _MARGIN) * normal
            if box[0, 2] + d[2] < 0.0:  # not into the floor: sideways, away from the other
                away = box.mean(0)[:2] - other.mean(0)[:2]
                n = float(np.linalg.norm(away))
                away = away / n if n > 1e-9 else np.array([1.0, 0.0])
                d = (best + _MARGIN) * np.r_[away, 0.0]
            shift[mover] = shift.get(mover, np.zeros(3)) + d
        if not shift:
            break
        for oid, d in shift.items():
            o = scene.objects[oid]
            o.position = np.asarray(o.position, float) + d
        moved += len(shift)
    return moved
