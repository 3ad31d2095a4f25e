"""The solver's geometry indexes: the PAG's per-child edge index and the spatial index of
placed footprints must answer as the full scans they replace."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from parse3d.pag import PAG, Room


def _scan_edges_of(pag: PAG, oid: str):
    es = [e for e in pag.relations if e.child.object == oid]
    return sorted(es, key=lambda e: 0 if e.is_support else 1)


def _scan_supporter(pag: PAG, oid: str):
    return next((e for e in pag.relations if e.is_support and e.child.object == oid), None)


def test_edge_index_follows_changes_to_relations():
    pag = PAG("t", Room("study", ((0, 0), (4, 0), (4, 3), (0, 3)), 2.7))
    pag.add("desk", "desk")
    pag.add("lamp", "table_lamp")
    pag.relate("lamp", "NEAR", "desk", distance=1.0)
    assert pag.supporter("lamp") is None and pag.edges_of("lamp") == _scan_edges_of(pag, "lamp")
    pag.relate("desk", "ON", "floor")
    pag.relate("lamp", "ON", "desk:tabletop")  # added after: the index is rebuilt
    for oid in ("desk", "lamp", "nobody"):
        assert pag.edges_of(oid) == _scan_edges_of(pag, oid)
        assert pag.supporter(oid) is _scan_supporter(pag, oid)
    assert pag.edges_of("lamp")[0].relation == "ON"
    # an edge replaced in place, and the returned list is the caller's own
    pag.relations[0] = replace(pag.relations[0], params={"distance": 2.0})
    assert pag.edges_of("lamp")[1].params == {"distance": 2.0}
    pag.edges_of("lamp").clear()
    assert len(pag.edges_of("lamp")) == 2
    pag.relations.remove(pag.relations[-1])
    assert pag.supporter("lamp") is None


def test_spatial_index_is_a_superset_of_the_full_scan():
    from parse3d.solver.collision import CollisionWorld
    from parse3d.solver.state import SolveState

    rng = np.random.default_rng(7)
    st = SolveState(None, None, CollisionWorld())
    boxes = {}
    for i in range(60):  # footprints registered as SolveState.add does, then some removed
        c = rng.uniform(0, 10, 2)
        half = rng.uniform(0.05, 0.8, 2)
        a = rng.uniform(0, np.pi)
        rot = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
        fp = (np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]]) * half) @ rot.T + c
        z = tuple(sorted(rng.uniform(0, 2, 2)))
        oid = f"o{i}"
        st.xy[oid], st.zr[oid], st.hulls[oid] = fp, z, np.c_[fp, np.full(4, z[0])]
        lo, hi = fp.min(axis=0), fp.max(axis=0)
        st._ids.append(oid)
        st._rows.append((*((lo + hi) / 2), float(np.linalg.norm(hi - lo)) / 2, *z))
        boxes[oid] = fp
    for oid in ("o3", "o17", "o40"):
        st.remove(oid)
        boxes.pop(oid)
    for _ in range(200):
        center, radius = rng.uniform(-1, 11, 2), rng.uniform(0, 3)
        z0, z1 = sorted(rng.uniform(0, 2, 2))
        got = st.near(center, radius, z0, z1)
        assert got == [o for o in st.hulls if o in got]  # in registration order
        for oid, fp in boxes.items():
            close = np.min(np.linalg.norm(fp - center, axis=1)) <= radius
            if close and st.zr[oid][1] >= z0 and st.zr[oid][0] <= z1:
                assert oid in got


def test_vectorised_convex_erosion_equals_the_clip():
    """Many-sided convex supports are eroded by crossing the moved edge lines at once; the
    result must be the polygon the half-plane clip gives (empty when that is empty)."""
    from shapely.geometry import Polygon

    from parse3d.geometry import regions as RG

    rng = np.random.default_rng(3)
    decided = 0
    for k in range(150):
        m = int(rng.choice([20, 48, 64]))
        a = np.linspace(0, 2 * np.pi, m, endpoint=False) + rng.uniform(0, 1)
        r = rng.uniform(0.2, 1.2)
        poly = Polygon(np.c_[r * np.cos(a) * rng.uniform(0.4, 1.6), r * np.sin(a)])
        F = RG.convex_footprint(rng.normal(size=(int(rng.integers(3, 30)), 2))
                                * rng.uniform(0.01, 0.5))
        F = F - F.mean(axis=0)
        c = np.asarray(poly.exterior.coords)[:-1]
        e = np.roll(c, -1, axis=0) - c
        n = np.c_[e[:, 1], -e[:, 0]] / np.linalg.norm(e, axis=1)[:, None]
        off = np.einsum("ij,ij->i", c, n) - np.max(F @ n.T, axis=0)
        want = RG._clip_box(poly, n, off)
        got = RG._half_planes(n, off)
        if got is None:  # it could not tell: the clip decides
            continue
        decided += 1
        assert got.is_empty == want.is_empty, k
        if not want.is_empty:
            assert got.symmetric_difference(want).area < 1e-10, k
        assert RG._erode_convex(poly, -F).equals(got)
    assert decided >= 75  # the vectorised path answers most of the time


def test_rejection_sampling_is_uniform_over_the_region():
    """Regions that fill their box are sampled by rejection: every point inside, and the
    share of points in each half of an L-shaped region follows its area."""
    import shapely
    from shapely.geometry import Polygon

    from parse3d.geometry import regions as RG

    L = Polygon([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)])  # area 3, fills 3/4 of its box
    pts = RG.sample_uniform(L, np.random.default_rng(0), 6000)
    assert pts.shape == (6000, 2)
    assert shapely.contains_xy(L.buffer(1e-9), pts[:, 0], pts[:, 1]).all()
    low = float(np.mean(pts[:, 1] < 1.0))  # the lower bar holds 2/3 of the area
    assert abs(low - 2 / 3) < 0.03
    again = RG.sample_uniform(L, np.random.default_rng(0), 6000)
    assert np.array_equal(pts, again)  # deterministic for a seed


def _convex(rng: np.random.Generator, k: int, r: float, at=(0.0, 0.0)) -> np.ndarray:
    from parse3d.geometry import regions as RG

    return RG.convex_footprint(rng.normal(size=(k, 2)) * r + np.asarray(at))


def test_free_samples_are_uniform_over_the_eroded_region():
    """Positions drawn from a convex support's free space without building it lie in the
    region :func:`erode` builds, spread over it by area; where that region is empty, or the
    support is not convex, the sampler leaves it to be built (None)."""
    import shapely
    from shapely.geometry import Polygon

    from parse3d.geometry import regions as RG

    rng = np.random.default_rng(5)
    drawn = 0
    for k in range(40):
        region = Polygon(_convex(rng, 12, rng.uniform(0.5, 1.5)))
        obst = [_convex(rng, 8, rng.uniform(0.05, 0.3), rng.uniform(-1, 1, 2))
                for _ in range(int(rng.integers(0, 6)))]
        F = _convex(rng, 10, rng.uniform(0.02, 0.2))
        F = F - F.mean(axis=0)
        margin = float(rng.choice([0.0, 0.03]))
        want = RG.erode(region, obst, F)
        if margin:
            want = want.buffer(-margin * np.cos(np.pi / 32))
        got = RG.free_samples(region, obst, F, np.random.default_rng(k), 3000, margin=margin)
        if want.is_empty or want.area < 1e-10:
            assert got is None, k
            continue
        if got is None:  # a small share of its box: built instead
            continue
        drawn += 1
        assert got.shape == (3000, 2)
        assert shapely.contains_xy(want.buffer(1e-7), got[:, 0], got[:, 1]).all(), k
        # the left half of the region's box holds its share of the area
        x0, y0, x1, y1 = want.bounds
        left = want.intersection(shapely.box(x0, y0, (x0 + x1) / 2, y1)).area / want.area
        assert abs(float(np.mean(got[:, 0] < (x0 + x1) / 2)) - left) < 0.04, k
        again = RG.free_samples(region, obst, F, np.random.default_rng(k), 3000, margin=margin)
        assert np.array_equal(got, again)  # deterministic for a seed
    assert drawn >= 15
    L = Polygon([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)])
    assert RG.free_samples(L, [], np.array([[-0.1, -0.1], [0.1, -0.1], [0, 0.1]]),
                           rng, 10) is None


def test_outline_of_a_posed_asset_is_its_footprint():
    """A posed asset's footprint gathered from its cached outline is the convex hull of all
    its projected hull points, for turns about the plane normal and tilted views alike."""
    from shapely.geometry import Polygon

    from parse3d.assets import registry
    from parse3d.geometry import regions as RG
    from parse3d.geometry.frames import axis_angle
    from parse3d.measure.geometry import asset_geometry, outline_indices

    asset = registry.generate("mug", seed=0)
    hull = asset_geometry(asset).hull * 1.3
    rng = np.random.default_rng(2)
    for k in range(30):
        R = axis_angle(np.array([0, 0, 1.0]), rng.uniform(0, 2 * np.pi))
        if k % 3 == 0:  # tilted
            R = axis_angle(np.array([1.0, 0, 0]), rng.uniform(0, np.pi)) @ R
        Y = hull @ R.T + rng.normal(size=3)
        n = np.array([0, 0, 1.0])
        uv = Y[:, :2]
        got = RG.convex_outline(uv, outline_indices(asset, R.T @ n))
        want = RG.convex_footprint(uv)
        assert Polygon(got).exterior.is_ccw and Polygon(got).is_valid
        assert Polygon(got).symmetric_difference(Polygon(want)).area < 1e-12, k
