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
