"""The rotation conversions of ``geometry.frames`` against scipy's ``Rotation``.

They stay written out (a cached solve imports no scipy, whose import costs 0.2-0.4 s); scipy
is the reference: the same matrices and the same ``[w, x, y, z]`` quaternions (w >= 0, the
sign scene.json and every export carry) to 1e-12, on random rotations and half turns.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from parse3d.export.usd import _quat_to_x
from parse3d.geometry.frames import (
    axis_angle,
    matrix_to_quat,
    quat_to_matrix,
    rot_x,
    rot_y,
    rot_z,
    rotation_about,
    rotation_between,
)


def _rotvec(axis, theta):
    a = np.asarray(axis, float)
    return Rotation.from_rotvec(a * (theta / np.linalg.norm(a))).as_matrix()


def _scipy_quat(R):
    q = Rotation.from_matrix(R).as_quat(scalar_first=True)
    return q if q[0] >= 0 else -q


def _quat_matrix(q):
    return Rotation.from_quat(np.asarray(q, float), scalar_first=True).as_matrix()


def _half_turns():
    """Rotations by pi (w = 0: the quaternion's sign is decided by its largest component)
    and the axis-aligned ones a scene is full of."""
    axes = [*np.eye(3), (1, -1, 0), (1, 1, 1), (0, 1, -1), (-1, 0, 1)]
    out = [_rotvec(a, np.pi) for a in axes]
    out += [np.diag([-1.0, -1, 1]), np.diag([1.0, -1, -1]), np.diag([-1.0, 1, -1]), np.eye(3)]
    out += [rot_z(k * np.pi / 2) for k in range(4)] + [rot_x(np.pi / 2) @ rot_y(np.pi)]
    return out


def test_quaternions_match_scipy_on_random_and_half_turn_rotations():
    rng = np.random.default_rng(7)
    for R in [*Rotation.random(500, rng=rng).as_matrix(), *_half_turns()]:
        q = matrix_to_quat(R)
        np.testing.assert_allclose(q, _scipy_quat(R), rtol=0, atol=1e-12)
        assert q[0] >= 0
        np.testing.assert_allclose(quat_to_matrix(q), _quat_matrix(q), rtol=0, atol=1e-12)
        np.testing.assert_allclose(quat_to_matrix(q), R, rtol=0, atol=1e-12)
    # not unit length: both normalise
    q = np.array([2.0, -0.4, 1.0, 0.3])
    np.testing.assert_allclose(quat_to_matrix(q), _quat_matrix(q), rtol=0, atol=1e-12)


def test_axis_angle_and_rotation_between_match_scipy():
    rng = np.random.default_rng(8)
    for _ in range(500):
        axis, theta = rng.normal(size=3) * rng.uniform(0.1, 10), rng.uniform(-7, 7)
        np.testing.assert_allclose(axis_angle(axis, theta), _rotvec(axis, theta),
                                   rtol=0, atol=1e-12)
        np.testing.assert_allclose(rotation_about(axis, theta), _rotvec(axis, theta),
                                   rtol=0, atol=1e-12)
        a, b = rng.normal(size=3), rng.normal(size=3)
        R = rotation_between(a, b)
        np.testing.assert_allclose(R @ (a / np.linalg.norm(a)), b / np.linalg.norm(b),
                                   rtol=0, atol=1e-12)
        v = np.cross(a, b)
        ref = _rotvec(v, np.arctan2(np.linalg.norm(v), np.dot(a, b)))
        np.testing.assert_allclose(R, ref, rtol=0, atol=1e-12)


@pytest.mark.parametrize("axis", [*np.eye(3), *-np.eye(3), (0.3, -2.0, 0.5), (-1, 1e-12, 0)])
def test_usd_joint_frame_quaternion_turns_x_onto_the_axis(axis):
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    q = _quat_to_x(a)
    np.testing.assert_allclose(_quat_matrix(q) @ [1.0, 0, 0], a, rtol=0, atol=1e-9)
    if a[0] > -1 + 1e-9:  # the half-angle form it was written as
        ref = np.array([1.0 + a[0], *np.cross([1.0, 0, 0], a)])
        np.testing.assert_allclose(q, ref / np.linalg.norm(ref), rtol=0, atol=1e-12)
    else:
        np.testing.assert_allclose(q, [0, 0, 0, 1.0])
