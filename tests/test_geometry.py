"""Geometry kernels against brute-force references (property-based)."""

from __future__ import annotations

import numpy as np
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon

from parse3d.geometry import regions as RG
from parse3d.geometry.shapes import _convex, box, lathe, tube, vessel

seeds = st.integers(0, 2**31 - 1)


def _polys(seed):
    rng = np.random.default_rng(seed)
    region = RG.convex_footprint(rng.normal(size=(int(rng.integers(3, 10)), 2)) * 2)
    foot = RG.convex_footprint(rng.normal(size=(int(rng.integers(3, 10)), 2)) * 0.3)
    return rng, region, foot - foot.mean(axis=0)


@settings(max_examples=120, deadline=None)
@given(seeds, st.booleans())
def test_erosion_of_convex_region_matches_boundary_sweep(seed, clockwise):
    _, region, foot = _polys(seed)
    reg = Polygon(region[::-1] if clockwise else region)
    fast = RG.erode(reg, [], foot)
    c = np.asarray(reg.exterior.coords)
    seg = np.stack([c[:-1], c[1:]], axis=1)
    pts = (seg[:, :, None, :] - foot[None, None]).reshape(len(seg), -1, 2)
    ref = shapely.difference(reg, shapely.union_all(shapely.convex_hull(shapely.multipoints(pts))))
    assert abs(fast.area - ref.area) < 1e-9
    assert shapely.symmetric_difference(fast, ref, grid_size=RG.GRID).area < 1e-7


@settings(max_examples=80, deadline=None)
@given(seeds)
def test_minkowski_many_matches_hull_of_sums(seed):
    rng, _, foot = _polys(seed)
    obs = [RG.convex_footprint(rng.normal(size=(int(rng.integers(3, 12)), 2)) + rng.normal(size=2) * 3)
           for _ in range(int(rng.integers(1, 6)))]
    for ob, m in zip(obs, RG.minkowski_many(obs, foot), strict=True):
        ref = shapely.MultiPoint((ob[:, None] + foot[None]).reshape(-1, 2)).convex_hull
        assert shapely.symmetric_difference(Polygon(m), ref, grid_size=RG.GRID).area < 1e-7


@settings(max_examples=60, deadline=None)
@given(seeds)
def test_samples_lie_in_the_region_and_fill_it(seed):
    rng, region, _ = _polys(seed)
    reg = Polygon(region).difference(Polygon(region).centroid.buffer(0.2))
    pts = RG.sample_uniform(reg, rng, 400)
    assert all(reg.buffer(1e-9).contains(shapely.Point(p)) for p in pts)
    # uniform: the share of samples in the left half matches its share of the area
    x = reg.centroid.x
    left = reg.intersection(shapely.box(-1e3, -1e3, x, 1e3)).area / reg.area
    assert abs((pts[:, 0] < x).mean() - left) < 0.12


def test_samples_on_lines_and_points():
    rng = np.random.default_rng(0)
    ln = shapely.LineString([(0, 0), (2, 0)])
    pts = RG.sample_uniform(ln, rng, 50)
    assert np.allclose(pts[:, 1], 0) and (pts[:, 0] >= 0).all() and (pts[:, 0] <= 2).all()
    assert np.allclose(RG.sample_uniform(shapely.Point(1, 2), rng, 3), [[1, 2]] * 3)


@settings(max_examples=50, deadline=None)
@given(seeds)
def test_convex_hull_mesh_is_closed_and_outward(seed):
    pts = np.random.default_rng(seed).normal(size=(20, 3))
    m = _convex(pts)
    assert m.is_watertight and m.is_convex and m.volume > 0


def test_shapes_pieces_cover_their_meshes():
    for s in (box((0.4, 0.3, 0.2), bevel=0.01), lathe([(0.1, 0), (0.1, 0.02), (0.02, 0.05), (0.02, 0.4)]),
              tube([[0, 0, 0], [0.1, 0, 0.05], [0.1, 0, 0.2]], 0.01),
              vessel([(0.05, 0), (0.06, 0.1)], 0.004, piece_sections=32)):
        assert s.mesh.is_watertight
        assert all(p.is_convex for p in s.pieces)
        assert abs(sum(p.volume for p in s.pieces) - s.mesh.volume) <= 0.1 * s.mesh.volume
