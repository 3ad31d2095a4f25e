"""Positions drawn without building regions, and the solver choices that keep attempts cheap:
the relations' region less the grown obstacles (areas by rejection, contact lines exactly),
the erosion area of a rectangle, supports a child fits tried first."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, Polygon

from parse3d.geometry import regions as RG
from parse3d.pag import PAG, Room
from parse3d.solver import solve


def _exact(region, obstacles, footprint):
    """The set the draws come from, built with GEOS: ``region`` less the grown obstacles."""
    if not obstacles:
        return region
    grown = [Polygon(p) for p in RG.minkowski_many(obstacles, -np.asarray(footprint))]
    return shapely.difference(region, shapely.union_all(grown))


def _case(rng):
    obstacles = [RG.convex_footprint(rng.uniform(-0.3, 0.3, (8, 2)) + rng.uniform(-1.5, 1.5, 2))
                 for _ in range(int(rng.integers(1, 7)))]
    footprint = RG.convex_footprint(rng.uniform(-0.2, 0.2, (6, 2)))
    return obstacles, footprint


def test_draws_from_an_area_lie_in_the_built_region_and_cover_it_evenly():
    rng = np.random.default_rng(1)
    region = shapely.box(-2, -1, 2, 1).intersection(shapely.Point(0.3, 0).buffer(1.6))
    drawn = 0
    for _ in range(40):
        obstacles, footprint = _case(rng)
        exact = _exact(region, obstacles, footprint)
        got = RG.draw_outside(region, obstacles, footprint, rng, 400)
        if got is None:  # only where (nearly) nothing is free
            assert exact.area < 0.05 * region.area
            continue
        drawn += 1
        assert len(got) == 400
        assert shapely.distance(exact, shapely.points(got)).max() < 1e-9
        # even: the share of draws left of the middle follows the free area there
        left = exact.intersection(shapely.box(-9, -9, 0.3, 9)).area / exact.area
        assert abs(float(np.mean(got[:, 0] < 0.3)) - left) < 0.1
    assert drawn >= 30


def test_a_contact_line_loses_the_grown_obstacles_exactly():
    rng = np.random.default_rng(2)
    for _ in range(200):
        line = LineString([(-2, rng.uniform(-1, 1)), (2, rng.uniform(-1, 1))])
        obstacles, footprint = _case(rng)
        exact = _exact(line, obstacles, footprint)
        got = RG.draw_outside(line, obstacles, footprint, rng, 50)
        if exact.length < 1e-9:
            assert got is None
            continue
        assert got is not None and len(got) == 50
        assert shapely.distance(exact, shapely.points(got)).max() < 1e-9


def test_the_eroded_area_of_a_rectangle_is_that_of_its_erosion():
    rng = np.random.default_rng(3)
    rect = shapely.box(0, 0, 1.2, 0.6)
    slanted = Polygon([(0, 0), (1.2, 0.1), (1.1, 0.7), (-0.1, 0.6)])
    for _ in range(20):
        footprint = RG.convex_footprint(rng.uniform(-0.3, 0.3, (6, 2)))
        for region in (rect, slanted):
            assert RG.eroded_area(region, footprint) == pytest.approx(
                RG.erode(region, [], footprint).area, abs=1e-12)
    assert RG.eroded_area(rect, np.array([[-1, -1], [1, -1], [1, 1], [-1, 1.0]])) == 0.0


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_an_on_child_is_tried_first_on_the_parts_it_fits(seed, monkeypatch):
    """A bag ON a tufted bench rests on its cushion, not balanced on a button (the highest
    parts); a floor cushion ON a rug's body lies on its field, not across the border. The
    parts it cannot fit are not even tried when one it fits takes it."""
    from parse3d.solver import placement

    tried: dict[str, list[str]] = {}
    place_on = placement._place_on

    def spy(st, oid, asset, scale, hull, sup, *args, **kw):
        tried.setdefault(oid, []).append(sup.choice.part)
        return place_on(st, oid, asset, scale, hull, sup, *args, **kw)

    monkeypatch.setattr(placement, "_place_on", spy)
    pag = PAG("bench", Room("bedroom", ((0, 0), (4, 0), (4, 3), (0, 3)), 2.7))
    pag.add("bench", "bed_bench")
    pag.relate("bench", "ON", "floor")
    pag.add("bag", "handbag")
    pag.relate("bag", "ON", "bench")
    pag.add("rug", "rug")
    pag.relate("rug", "ON", "floor")
    pag.add("cushion", "floor_cushion")
    pag.relate("cushion", "ON", "rug:body")
    scene = solve(pag, seed=seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    assert not scene.objects["bag"].support_choice.part.startswith("button")
    assert scene.objects["cushion"].support_choice.part == "field"
    assert not any(p.startswith("button") for p in tried["bag"]), tried["bag"]
    assert tried["cushion"] == ["field"], tried["cushion"]


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_a_cabinet_near_another_finds_its_wall(seed):
    """``b NEAR a`` and ``b@back AGAINST wall`` (any wall): the walls far from ``a`` are ruled
    out by the relations alone, and ``b`` stands against a wall within reach of ``a``."""
    from parse3d.measure import check_edge

    pag = PAG("filing", Room("office", ((0, 0), (5, 0), (5, 4), (0, 4)), 2.7))
    pag.add("a", "filing_cabinet")
    pag.relate("a", "ON", "floor")
    pag.relate("a@back", "AGAINST", "wall_0")
    pag.add("b", "filing_cabinet")
    pag.relate("b", "ON", "floor")
    pag.relate("b", "NEAR", "a", distance=1.2)
    pag.relate("b@back", "AGAINST", "wall")
    scene = solve(pag, seed=seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for e in pag.edges_of("b"):
        if e.parent.object == "wall":
            continue
        assert check_edge(scene, e, scene.objects["b"])[0], e


def test_a_curtain_hangs_with_its_centre_in_its_height_band():
    """``SECURED_TO wall height [0.8, 1.0]`` is the centre's height: floor-length curtains too
    tall for it are followed by the lowest untried instance, and one hangs in the band."""
    for seed in range(6):
        pag = PAG("curtain", Room("bedroom", ((0, 0), (4, 0), (4, 3), (0, 3)), 2.7))
        pag.add("dressing", "curtain")
        pag.relate("dressing", "SECURED_TO", "wall", height=(0.8, 1.0))
        scene = solve(pag, seed=seed)
        assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
        centre = float(np.mean(scene.objects["dressing"].world_bounds(settled=False)[:, 2]))
        assert 0.8 - 1e-6 <= centre <= 1.0 + 1e-6
