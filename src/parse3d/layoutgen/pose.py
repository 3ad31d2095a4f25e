"""The 12-D object pose of the layout model and its normalisation.

A pose row is ``[t (3), size (3), r6 (6)]`` in the world frame:

- ``t``: world position of the asset origin (centre of its bounding box's bottom face), metres;
- ``size``: the object's extents in its own frame, ``scale * asset.extents``, metres;
- ``r6``: the first two columns of the world rotation matrix (the continuous 6-D rotation
  representation), turned back into a rotation by Gram-Schmidt.

The network sees normalised poses: ``t`` mapped to ``[-1, 1]`` over the room's footprint
bounding box (x, y) and height (z), ``log(size)`` standardised by the training set's mean and
``size_spread`` (3) standard deviations (:class:`PoseStats`, saved with a run as ``stats.json``),
``r6`` unchanged. Every block therefore lies in ``[-1, 1]`` (sizes up to three standard
deviations from the mean), the range the DDPM sampler clips its clean-sample estimate to: with
plain standardisation that clipping squeezed every size into one standard deviation.

**Parent frame** (``parents`` given, the ``--frame parent`` option of a PAG-conditioned run):
an object with a support parent in the PAG (``parents[i] >= 0``: it is ``ON``/``IN``/...
another object) has its translation expressed in the parent's frame,
``t_rel = R_p^T (t_i - t_p)``, normalised like a world translation without the footprint's
offset (``2 t_rel / (hi - lo)`` in x, y; ``2 t_rel / height - 1`` in z, as a world height).
A mug on a desk is then "0.75 m up, somewhere over the desk top" wherever the desk is;
:func:`denormalise_poses` composes the translations along the support tree, parents first.
Sizes and rotations stay in the world frame.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

__all__ = ["POSE_DIM", "PoseStats", "rotation_to_6d", "rotation_from_6d", "room_box",
           "normalise_poses", "denormalise_poses", "support_order", "to_parent_frame",
           "from_parent_frame"]

#: Width of a pose row.
POSE_DIM = 12


def rotation_to_6d(R: np.ndarray) -> np.ndarray:
    """(..., 3, 3) rotations to (..., 6): first column then second column."""
    R = np.asarray(R, float)
    return np.concatenate([R[..., :, 0], R[..., :, 1]], axis=-1)


def rotation_from_6d(r6: np.ndarray) -> np.ndarray:
    """(..., 6) to (..., 3, 3) proper rotations by Gram-Schmidt (degenerate input: identity)."""
    r6 = np.asarray(r6, float)
    a, b = r6[..., :3], r6[..., 3:]
    na = np.linalg.norm(a, axis=-1, keepdims=True)
    a = np.where(na > 1e-8, a / np.maximum(na, 1e-8), np.array([1.0, 0.0, 0.0]))
    b = b - np.sum(a * b, axis=-1, keepdims=True) * a
    nb = np.linalg.norm(b, axis=-1, keepdims=True)
    fallback = np.cross(a, np.array([0.0, 0.0, 1.0]))
    fallback = np.where(np.linalg.norm(fallback, axis=-1, keepdims=True) > 1e-6, fallback,
                        np.cross(a, np.array([1.0, 0.0, 0.0])))
    b = np.where(nb > 1e-8, b / np.maximum(nb, 1e-8),
                 fallback / np.linalg.norm(fallback, axis=-1, keepdims=True))
    c = np.cross(a, b)
    return np.stack([a, b, c], axis=-1)


def room_box(footprint: np.ndarray, height: float) -> tuple[np.ndarray, np.ndarray]:
    """Lower and upper corners (3,) of the room's bounding box, metres."""
    fp = np.asarray(footprint, float)
    lo = np.r_[fp.min(axis=0), 0.0]
    hi = np.r_[fp.max(axis=0), float(height)]
    return lo, hi


@dataclass(frozen=True)
class PoseStats:
    """Normalisation of the size block: mean and standard deviation of ``log(size)`` (3 each).

    ``size_spread``: how many standard deviations map to 1 (3 for new runs; runs written
    before it existed read as 1).
    """

    log_size_mean: tuple[float, float, float]
    log_size_std: tuple[float, float, float]
    size_spread: float = 3.0

    @classmethod
    def fit(cls, poses: list[np.ndarray]) -> PoseStats:
        """Statistics over the (N, 12) pose arrays of the training scenes."""
        ls = np.log(np.maximum(np.concatenate([p[:, 3:6] for p in poses]), 1e-4))
        return cls(tuple(float(x) for x in ls.mean(0)),
                   tuple(float(max(x, 1e-3)) for x in ls.std(0)))

    def to_dict(self) -> dict:
        return asdict(self)

    @classmethod
    def from_dict(cls, d: dict) -> PoseStats:
        return cls(tuple(d["log_size_mean"]), tuple(d["log_size_std"]),
                   float(d.get("size_spread", 1.0)))

    @property
    def _scale(self) -> np.ndarray:
        return self.size_spread * np.array(self.log_size_std)


def support_order(parents: np.ndarray) -> list[int]:
    """Object indices with every parent before its children (``parents[i]`` -1: a root).

    Raises ValueError on a cycle.
    """
    parents = np.asarray(parents, int)
    n = len(parents)
    state = np.zeros(n, int)  # 0 new, 1 on the path, 2 done
    order: list[int] = []
    for i in range(n):
        path = []
        k = i
        while k >= 0 and state[k] == 0:
            state[k] = 1
            path.append(k)
            k = int(parents[k])
        if k >= 0 and state[k] == 1:
            raise ValueError(f"the support parents form a cycle through object {k}")
        for k in reversed(path):
            state[k] = 2
            order.append(k)
    return order


def to_parent_frame(t: np.ndarray, R: np.ndarray, parents: np.ndarray) -> np.ndarray:
    """(N, 3) world translations to parent-frame ones where ``parents[i] >= 0``."""
    t = np.array(t, float)
    out = t.copy()
    for i, p in enumerate(np.asarray(parents, int)):
        if p >= 0:
            out[i] = R[p].T @ (t[i] - t[p])
    return out


def from_parent_frame(t: np.ndarray, R: np.ndarray, parents: np.ndarray) -> np.ndarray:
    """Inverse of :func:`to_parent_frame`: compose along the support tree, parents first."""
    parents = np.asarray(parents, int)
    out = np.array(t, float)
    for i in support_order(parents):
        p = parents[i]
        if p >= 0:
            out[i] = out[p] + R[p] @ out[i]
    return out


def _has_parent(parents, n: int) -> np.ndarray:
    if parents is None:
        return np.zeros(n, bool)
    return np.asarray(parents, int) >= 0


def normalise_poses(poses: np.ndarray, footprint: np.ndarray, height: float,
                    stats: PoseStats, parents: np.ndarray | None = None) -> np.ndarray:
    """(N, 12) world poses to the network's space (see the module docstring); ``parents``
    (N,) selects the parent frame for objects with a support parent (-1: none)."""
    lo, hi = room_box(footprint, height)
    p = np.asarray(poses, float)
    rel = _has_parent(parents, len(p))
    t = 2.0 * (p[:, :3] - lo) / np.maximum(hi - lo, 1e-6) - 1.0
    if rel.any():
        tr = to_parent_frame(p[:, :3], rotation_from_6d(p[:, 6:12]), parents)
        t[rel] = 2.0 * tr[rel] / np.maximum(hi - lo, 1e-6)
        t[rel, 2] -= 1.0
    s = (np.log(np.maximum(p[:, 3:6], 1e-4)) - np.array(stats.log_size_mean)) / stats._scale
    return np.concatenate([t, s, p[:, 6:12]], axis=1).astype(np.float32)


def denormalise_poses(x: np.ndarray, footprint: np.ndarray, height: float,
                      stats: PoseStats, parents: np.ndarray | None = None) -> np.ndarray:
    """Inverse of :func:`normalise_poses`; ``r6`` is re-orthonormalised."""
    lo, hi = room_box(footprint, height)
    x = np.asarray(x, float)
    rel = _has_parent(parents, len(x))
    t = (x[:, :3] + 1.0) * 0.5 * (hi - lo) + lo
    s = np.exp(x[:, 3:6] * stats._scale + np.array(stats.log_size_mean))
    R = rotation_from_6d(x[:, 6:12])
    r6 = rotation_to_6d(R)
    if rel.any():
        tr = (x[:, :3] + np.array([0.0, 0.0, 1.0])) * 0.5 * (hi - lo)
        t = from_parent_frame(np.where(rel[:, None], tr, t), R, parents)
    return np.concatenate([t, s, r6], axis=1)
