"""Resting across an opening: a tray written ON a bathtub's rim, a ring round the tub's
opening, lies across the opening with its ends on the two long sides of the rim, and what
stands on the tray stays there; solved, settled and repaired as ``parse3d solve`` does (real
SAPIEN physics)."""

from __future__ import annotations

import numpy as np
import pytest

from test_rooms import solved


@pytest.mark.parametrize("seed", (0, 1, 2, 3))
def test_a_tray_rests_across_a_bathtub(seed):
    """The tray is placed and held by the rim after settling: its centre over the tub's
    opening (not balanced on one side of the rim), its ends reaching past the opening on both
    sides; what stands on it is placed and every relation holds after settling."""
    from parse3d.measure.checks import world_points

    scene = solved("tray_across_a_tub", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    tub, tray = scene.objects["tub"], scene.objects["caddy"]
    T = tub.transform(True)
    rim = float(tub.asset.part("tub").surfaces["top"].transformed(T).origin[2])
    pts = world_points(tray, settled=True)
    # level at the rim, neither sunk into the tub nor tipped (as flat as it was placed)
    lo = pts[:, 2].min()
    np.testing.assert_allclose(np.ptp(pts[:, 2]), np.ptp(world_points(tray)[:, 2]), rtol=0.05,
                               atol=3e-3)
    # what bears on the rim: the tray's points at the rim's height (its feet hang lower, into
    # the opening, or stand on the rim), in the tub's frame (its width along y)
    local = (np.c_[pts, np.ones(len(pts))] @ np.linalg.inv(T).T)[:, :3]
    half = 0.5 * float(np.ptp(tub.asset.part("tub").vertices[:, 1]))
    bear = local[np.abs(pts[:, 2] - rim) <= 4e-3]
    assert lo <= rim + 4e-3 and len(bear), (lo, rim)
    # on the two long sides of the rim, across the opening: both sides of the tub's axis, out
    # past its middle half
    assert bear[:, 1].min() < -0.5 * half and bear[:, 1].max() > 0.5 * half, \
        (bear[:, 1].min(), bear[:, 1].max(), half)
    # and its middle over the opening, between the two sides
    assert abs(float(local[:, 1].mean())) < 0.25 * half
