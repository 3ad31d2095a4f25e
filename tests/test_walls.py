"""Crowded walls: what stands along a wall (``solver.walls``), the conflict set the search
moves to make room for a wall object, and the explanation when a named wall is full."""

from __future__ import annotations

import re

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from parse3d.pag import PAG, Room
from parse3d.scene.shell import build_shell
from parse3d.solver import SolverConfig, solve
from parse3d.solver.search import wall_conflicts
from parse3d.solver.walls import Occupant, free_runs, occupants, wall_length, windows


def box(x0, x1, y0, y1, z0, z1) -> np.ndarray:
    """(8, 3) corners of an axis-aligned box (world metres)."""
    return np.array([[x, y, z] for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)], float)


@pytest.fixture
def wall_1():
    """wall_1 of a 3 x 2.5 m room: the plane x = 3, facing -x, 2.5 m long."""
    room = Room("bedroom", ((0, 0), (3, 0), (3, 2.5), (0, 2.5)), 2.6)
    return build_shell(room, wall_thickness=0.12).elements["wall_1"].surface


def test_occupants_are_what_stands_within_the_depth_and_height(wall_1):
    assert wall_length(wall_1)[1] == pytest.approx(2.5)
    hulls = {"cabinet": box(2.6, 3.0, 0.5, 1.0, 0.0, 0.8),     # against wall_1
             "table": box(1.0, 1.6, 0.5, 1.5, 0.0, 0.75),      # in the middle of the room
             "picture": box(2.97, 3.0, 1.2, 1.6, 1.5, 1.9),    # hung above the cabinet
             "chair": box(2.2, 2.7, 1.6, 2.1, 0.0, 0.9)}       # in front, its back 0.3 m off
    got = occupants(wall_1, hulls, 0.6, 0.0, 1.0)
    assert {o.id for o in got} == {"cabinet", "chair"}
    assert [o.a0 for o in got] == sorted(o.a0 for o in got)  # in wall order
    cab = next(o for o in got if o.id == "cabinet")
    assert cab.a1 - cab.a0 == pytest.approx(0.5)
    # the chair is 0.3 m from the wall: not in a 0.2 m deep slab
    assert [o.id for o in occupants(wall_1, hulls, 0.2, 0.0, 1.0)] == ["cabinet"]
    # up to 2 m high the picture takes its stretch too
    assert {o.id for o in occupants(wall_1, hulls, 0.2, 0.0, 2.0)} == {"cabinet", "picture"}
    runs = free_runs(2.5, occupants(wall_1, hulls, 0.2, 0.0, 1.0))
    assert sum(b - a for a, b in runs) == pytest.approx(2.0)


def test_windows_are_the_cheapest_stretches_to_clear():
    taken = [Occupant("bin", 0.2, 0.5), Occupant("bed", 0.9, 2.4), Occupant("lamp", 2.6, 2.9)]
    cost = {"bin": 1, "bed": 5, "lamp": 1}
    got = windows("wall_0", 3.0, taken, 0.8, lambda block: sum(cost[b] for b in block))
    assert got[0].blockers == ("bin",) and got[0].cost == 1
    assert got[0].a1 - got[0].a0 == pytest.approx(0.8)
    assert all(w.blockers for w in got)  # a free stretch needs no clearing
    assert [w.cost for w in got] == sorted(w.cost for w in got)
    # an occupant that may not move rules out every stretch it is in
    fixed = windows("wall_0", 3.0, taken, 0.8,
                    lambda block: None if "bin" in block else sum(cost[b] for b in block))
    assert fixed and all("bin" not in w.blockers for w in fixed)
    assert windows("wall_0", 3.0, taken, 3.5, lambda block: 1) == []


def boxes_on_wall_1() -> tuple[PAG, dict]:
    """Three boxes along wall_1 of a 3 x 2 m room (placed there by proposals), a chair and a
    basket away from it, then a dresser AGAINST wall_1 that finds no room."""
    pag = PAG("boxes-on-wall-1", Room("bedroom", ((0, 0), (3, 0), (3, 2), (0, 2)), 2.6))
    proposals = {}
    for k, y in enumerate((0.3, 1.0, 1.7)):
        pag.add(f"box_{k}", "storage_box")
        pag.relate(f"box_{k}", "ON", "floor")
        proposals[f"box_{k}"] = (np.eye(3), np.array([2.65, y, 5e-4]))
    pag.add("chair", "armchair")
    pag.relate("chair", "ON", "floor")
    proposals["chair"] = (np.eye(3), np.array([0.8, 1.0, 5e-4]))
    pag.add("basket", "laundry_basket")
    pag.relate("basket", "ON", "floor")
    proposals["basket"] = (np.eye(3), np.array([1.2, 0.3, 5e-4]))
    pag.add("dresser", "dresser")
    pag.relate("dresser", "ON", "floor")
    pag.relate("dresser@back", "AGAINST", "wall_1")
    return pag, proposals


SEED = 0


def test_the_conflict_set_of_a_wall_object_is_what_stands_along_its_wall():
    pag, proposals = boxes_on_wall_1()
    greedy = solve(pag, seed=SEED, config=SolverConfig(search="greedy", relax=False),
                   proposals=proposals)
    for k in range(3):  # the boxes stand where they were proposed
        assert np.allclose(greedy.objects[f"box_{k}"].position, proposals[f"box_{k}"][1])
    dresser = greedy.objects["dresser"]
    assert not dresser.placed
    # the explanation names what takes the wall and the room left on it
    assert re.search(r"wall_1 \(2\.00 m\) is taken by box_\d, box_\d, box_\d: its longest free "
                     r"stretch is 0\.\d\d m, dresser needs about \d\.\d\d m", dresser.reason)
    got = wall_conflicts(greedy, "dresser", seed=SEED)
    assert got and all(w.wall == "wall_1" for w in got)
    assert all(set(w.blockers) <= {"box_0", "box_1", "box_2"} for w in got)
    assert [w.cost for w in got] == sorted(w.cost for w in got)
    # backtracking moves what stands in the way and places the dresser against wall_1
    back = solve(pag, seed=SEED, proposals=proposals)
    assert back.ok, [(o.id, o.reason) for o in back.failed]
    against = next(c for c in back.relations if c.relation == "AGAINST")
    assert against.holds
    moved = [k for k in range(3)
             if not np.allclose(back.objects[f"box_{k}"].position, proposals[f"box_{k}"][1])]
    assert moved
    assert np.allclose(back.objects["chair"].position, proposals["chair"][1])


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(0.0, 4.0), st.floats(0.01, 1.5)), max_size=6),
       st.floats(0.1, 2.0))
def test_free_runs_and_windows_partition_the_wall(spans, width):
    length = 4.0
    taken = [Occupant(f"o{k}", a, min(a + w, length)) for k, (a, w) in enumerate(spans)
             if a < length]
    runs = free_runs(length, taken)
    covered = shapely.union_all([shapely.box(o.a0, 0, o.a1, 1) for o in taken]).area \
        if taken else 0.0
    assert sum(b - a for a, b in runs) + covered == pytest.approx(length, abs=1e-9)
    for a, b in runs:  # nothing takes a free run
        assert all(o.a1 <= a + 1e-9 or o.a0 >= b - 1e-9 for o in taken)
    for w in windows("wall_0", length, taken, width, lambda block: len(block)):
        assert w.a0 >= 0.0 and w.a1 <= length + 1e-9 and w.a1 - w.a0 == pytest.approx(width)
        assert set(w.blockers) == {o.id for o in taken
                                   if o.a1 > w.a0 + 1e-3 and o.a0 < w.a1 - 1e-3}


def test_any_wall_relation_is_rechecked_on_the_wall_it_was_met_on():
    # a lamp AGAINST "wall" 10 cm off it, in a corner 5 cm from the side wall: the re-check
    # after settling took the nearer side wall (90 degrees off) although physics moved nothing
    from pathlib import Path

    from parse3d.pag import load_pag
    from parse3d.pipeline import PipelineOptions, run_pipeline

    pag = load_pag(Path(__file__).parent / "data" / "rooms" / "crowded_walls.json")
    scene = run_pipeline(pag, seed=5, out=None, options=PipelineOptions(settle=True, preview=False))
    walls = [i for i, e in enumerate(pag.relations) if e.parent.object == "wall"]
    assert walls
    for i in walls:
        assert scene.meta["resolved"][str(i)]["parent_element"].startswith("wall_")
        c = next(c for c in scene.relations if c.index == i)
        assert c.holds and c.holds_settled, (pag.relations[i], c)
