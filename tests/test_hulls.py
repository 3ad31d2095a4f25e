"""The 2-D hull kernel against qhull: the same vertices, counter-clockwise, None where qhull
gives up."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial import ConvexHull, QhullError

from parse3d.geometry.hulls import hull_indices_2d
from parse3d.geometry.regions import convex_footprint


def _qhull_set(pts: np.ndarray) -> set | None:
    try:
        return {tuple(p) for p in pts[ConvexHull(pts).vertices].tolist()}
    except (QhullError, ValueError):
        return None


def _ccw(poly: np.ndarray) -> bool:
    e = np.roll(poly, -1, axis=0) - poly
    turn = e[:, 0] * np.roll(e[:, 1], -1) - e[:, 1] * np.roll(e[:, 0], -1)
    return bool((turn > 0).all())


def _rotated_box_projection(rng, n_sub: int) -> np.ndarray:
    """A box's subdivided vertices turned in 3-D and projected along z: edge points that
    rounding leaves a hair off a straight line, as the solver's outlines have them."""
    g = np.linspace(-0.5, 0.5, n_sub)
    pts = np.array([(x, y, z) for x in g for y in g for z in (-0.2, 0.2)
                    if abs(x) == 0.5 or abs(y) == 0.5]) * rng.uniform(0.05, 2.0, 3)
    a = rng.uniform(0, 2 * np.pi)
    R = np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1.0]])
    return (pts @ R.T)[:, :2] + rng.uniform(-3, 3, 2)


@pytest.mark.parametrize("seed", range(40))
def test_same_vertices_as_qhull_on_solver_like_sets(seed):
    rng = np.random.default_rng(seed)
    if seed % 2:
        pts = _rotated_box_projection(rng, int(rng.integers(2, 7)))
    else:  # a cylinder's rings: near-duplicate points on a circle
        t = np.linspace(0, 2 * np.pi, int(rng.integers(8, 40)), endpoint=False) + rng.uniform(0, 1)
        ring = np.c_[np.cos(t), np.sin(t)] * rng.uniform(0.02, 0.6)
        pts = np.vstack([ring, ring * (1 - 1e-17), ring * 0.5])
    idx = hull_indices_2d(pts)
    assert idx is not None and _ccw(pts[idx])
    want = _qhull_set(pts)
    got = {tuple(p) for p in pts[idx].tolist()}
    if seed % 2:
        assert got == want
    else:  # near-duplicates: qhull and the chain may keep either twin
        assert len(got) == len(want)
        assert np.allclose(np.sort(pts[idx], axis=0),
                           np.sort(np.array(sorted(want)), axis=0), atol=1e-15)


@settings(max_examples=150, deadline=None)
@given(st.lists(st.tuples(st.integers(-50, 50), st.integers(-50, 50)), min_size=1, max_size=40))
def test_integer_points_match_qhull(raw):
    pts = np.array(raw, float) / 10.0
    idx = hull_indices_2d(pts)
    want = _qhull_set(pts)
    if want is None:
        assert idx is None
    else:
        assert idx is not None and _ccw(pts[idx])
        assert {tuple(p) for p in pts[idx].tolist()} == want


@pytest.mark.parametrize("pts", [
    [[0, 0], [1, 1]],
    [[0, 0], [1, 1], [2, 2], [3, 3]],
    [[0, 0], [0, 0], [0, 0]],
    [[0, 0], [1, 0], [np.nan, 1]],
])
def test_degenerate_sets_have_no_hull(pts):
    assert hull_indices_2d(np.array(pts, float)) is None


def test_convex_footprint_of_a_segment_is_a_thin_polygon():
    fp = convex_footprint(np.array([[0, 0], [1, 0], [2, 0.0]]))
    assert len(fp) >= 3 and np.ptp(fp[:, 1]) <= 2.1e-4


@pytest.mark.parametrize("seed", range(6))
def test_large_sets_match_qhull(seed):
    rng = np.random.default_rng(100 + seed)
    n = int(rng.integers(64, 3000))
    pts = rng.normal(size=(n, 2)) * rng.uniform(0.1, 3.0, 2) + rng.uniform(-5, 5, 2)
    if seed % 2:  # a disc's rim and inside: most points on or near the hull
        a = rng.uniform(0, 2 * np.pi, n)
        pts = np.c_[np.cos(a), np.sin(a)] * np.where(rng.random(n) < 0.5, 1.0, rng.random(n))[:, None]
    idx = hull_indices_2d(pts)
    assert idx is not None and _ccw(pts[idx])
    assert {tuple(p) for p in pts[idx].tolist()} == _qhull_set(pts)
