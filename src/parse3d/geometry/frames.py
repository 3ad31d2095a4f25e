"""Rigid frames: rotations, quaternions (w, x, y, z) and 4x4 transforms.

Conventions: world +Z up; quaternions are scalar-first ``[w, x, y, z]`` as in scene.json.
The conversions are written out rather than taken from scipy's ``Rotation``: importing
scipy costs 0.2-0.4 s, and a cached ``parse3d solve`` imports no scipy (tests/test_solve_imports.py);
tests/test_frames.py checks every one against ``Rotation`` to 1e-12.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "rot_z",
    "rot_x",
    "rot_y",
    "axis_angle",
    "rotation_about",
    "matrix_to_quat",
    "quat_to_matrix",
    "make_transform",
    "transform_points",
    "transform_vectors",
    "yaw_of",
    "rotation_between",
    "angle_between",
    "cross_rows",
]


def rot_z(theta: float) -> np.ndarray:
    """(3, 3) rotation by ``theta`` radians about +Z."""
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rot_x(theta: float) -> np.ndarray:
    """(3, 3) rotation by ``theta`` radians about +X."""
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rot_y(theta: float) -> np.ndarray:
    """(3, 3) rotation by ``theta`` radians about +Y."""
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def axis_angle(axis, theta: float) -> np.ndarray:
    """(3, 3) rotation by ``theta`` radians about the unit vector ``axis`` (Rodrigues)."""
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(theta) * k + (1 - np.cos(theta)) * (k @ k)


def rotation_about(axis, theta: float) -> np.ndarray:
    """(3, 3) rotation by ``theta`` radians about ``axis`` (any length), summed as
    ``cos(theta) I + (1 - cos(theta)) a a^T + sin(theta) [a]x`` in that order (the rounding
    articulated assets were always posed with)."""
    a = np.array(axis[:3], dtype=np.float64)
    a /= np.sqrt(np.dot(a, a))
    s, c = np.sin(theta), np.cos(theta)
    R = np.diag([c, c, c])
    R += np.outer(a, a) * (1.0 - c)
    a = a * s
    R += np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])
    return R


def rotation_between(a, b) -> np.ndarray:
    """(3, 3) smallest rotation taking unit vector ``a`` onto unit vector ``b``."""
    a = np.asarray(a, float)
    a = a / math.sqrt(a.dot(a))
    b = np.asarray(b, float)
    b = b / math.sqrt(b.dot(b))
    # numpy's cross (and norm) cost more than the arithmetic on single 3-vectors; the same
    # products and differences, so the same bits
    (a0, a1, a2), (b0, b1, b2) = a.tolist(), b.tolist()
    v = np.array([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0])
    c = float(np.dot(a, b))
    nv = math.sqrt(v.dot(v))
    if nv < 1e-12:
        if c > 0:
            return np.eye(3)
        # 180 degrees about any axis orthogonal to a
        perp = np.array([1.0, 0, 0]) if abs(a[0]) < 0.9 else np.array([0, 1.0, 0])
        axis = np.cross(a, perp)
        return axis_angle(axis, np.pi)
    return axis_angle(v, np.arctan2(nv, c))


def angle_between(a, b) -> float:
    """Angle in radians between two vectors."""
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    c = np.dot(a, b) / (np.linalg.norm(a) * np.linalg.norm(b))
    return float(np.arccos(np.clip(c, -1.0, 1.0)))


def matrix_to_quat(R: np.ndarray) -> np.ndarray:
    """(4,) unit quaternion ``[w, x, y, z]`` with w >= 0 from a (3, 3) rotation matrix."""
    R = np.asarray(R, dtype=float)
    t = np.trace(R)
    if t > 0:
        s = np.sqrt(t + 1.0) * 2
        q = [0.25 * s, (R[2, 1] - R[1, 2]) / s, (R[0, 2] - R[2, 0]) / s, (R[1, 0] - R[0, 1]) / s]
    elif R[0, 0] > R[1, 1] and R[0, 0] > R[2, 2]:
        s = np.sqrt(1.0 + R[0, 0] - R[1, 1] - R[2, 2]) * 2
        q = [(R[2, 1] - R[1, 2]) / s, 0.25 * s, (R[0, 1] + R[1, 0]) / s, (R[0, 2] + R[2, 0]) / s]
    elif R[1, 1] > R[2, 2]:
        s = np.sqrt(1.0 + R[1, 1] - R[0, 0] - R[2, 2]) * 2
        q = [(R[0, 2] - R[2, 0]) / s, (R[0, 1] + R[1, 0]) / s, 0.25 * s, (R[1, 2] + R[2, 1]) / s]
    else:
        s = np.sqrt(1.0 + R[2, 2] - R[0, 0] - R[1, 1]) * 2
        q = [(R[1, 0] - R[0, 1]) / s, (R[0, 2] + R[2, 0]) / s, (R[1, 2] + R[2, 1]) / s, 0.25 * s]
    q = np.asarray(q)
    q /= np.linalg.norm(q)
    return q if q[0] >= 0 else -q


def quat_to_matrix(q) -> np.ndarray:
    """(3, 3) rotation matrix from a quaternion ``[w, x, y, z]``."""
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def make_transform(R=None, t=None, scale: float = 1.0) -> np.ndarray:
    """(4, 4) homogeneous transform ``x -> R @ (scale * x) + t``."""
    T = np.zeros((4, 4))
    T[3, 3] = 1.0
    if R is not None:
        np.multiply(np.asarray(R, float), scale, out=T[:3, :3])
    else:
        T[0, 0] = T[1, 1] = T[2, 2] = scale
    if t is not None:
        T[:3, 3] = t
    return T


def transform_points(T: np.ndarray, pts) -> np.ndarray:
    """Apply a (4, 4) transform to (N, 3) points."""
    pts = np.asarray(pts, dtype=float)
    return pts @ T[:3, :3].T + T[:3, 3]


def transform_vectors(T: np.ndarray, vecs) -> np.ndarray:
    """Rotate (N, 3) direction vectors by a (4, 4) transform and renormalise."""
    v = np.asarray(vecs, dtype=float) @ T[:3, :3].T
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(n > 0, n, 1.0)


def yaw_of(R: np.ndarray) -> float:
    """Yaw (radians about +Z) of the rotated +Y (front) axis, measured from +Y."""
    f = np.asarray(R)[:, 1]
    return float(np.arctan2(-f[0], f[1]))


def cross_rows(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """(N, 3) row-wise cross products of (N, 3) arrays ``a`` and ``b``.

    The same products and differences as ``np.cross`` (so the same bits), without its axis
    handling, which dominates for the few dozen rows of a part's faces.
    """
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    out = np.empty(np.broadcast_shapes(a.shape, b.shape))
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    out[..., 0] = a1 * b2 - a2 * b1
    out[..., 1] = a2 * b0 - a0 * b2
    out[..., 2] = a0 * b1 - a1 * b0
    return out
