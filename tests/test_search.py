"""The solver's search: failure propagation along support only, backjumping, rule registries,
the solve API (progress, deadline, proposals, strict) and explanations."""

from __future__ import annotations

import numpy as np
import pytest

from parse3d.errors import InfeasibleError
from parse3d.pag import PAG, Room
from parse3d.relations import relation_names
from parse3d.solver import SolverConfig, solve
from parse3d.solver.regions import REGION_RULES
from parse3d.solver.rotation import ROTATION_RULES


def impossible_sofa_room() -> PAG:
    """A living room whose sofa cannot be placed (FAR_FROM a wall by more than the room)."""
    pag = PAG("impossible-sofa", Room("living_room", ((0, 0), (4.5, 0), (4.5, 4), (0, 4)), 2.7))
    a, r = pag.add, pag.relate
    a("sofa", "sofa")
    r("sofa", "ON", "floor")
    r("sofa", "FAR_FROM", "wall_0", distance=9.0)
    a("pillow", "pillow")  # rests on the sofa: fails with it
    r("pillow", "ON", "sofa:seat_cushion")
    a("chair", "armchair")  # only NEAR the sofa: placed, NEAR unmet
    r("chair", "ON", "floor")
    r("chair", "NEAR", "sofa", distance=1.5)
    a("rug", "rug")
    r("rug", "ON", "floor")
    r("rug", "SIDE_OF", "sofa", side="front")
    a("table", "coffee_table")  # a chain resting on the rug, not on the sofa
    r("table", "ON", "rug")
    r("table", "NEAR", "sofa", distance=1.2)
    a("vase", "vase")
    r("vase", "ON", "table:tabletop")
    return pag


@pytest.mark.parametrize("seed", [0, 1])
def test_failure_propagates_only_along_support(seed):
    scene = solve(impossible_sofa_room(), seed=seed, config=SolverConfig(search="greedy"))
    status = {o.id: o.status for o in scene.objects.values()}
    assert status == {"sofa": "failed", "pillow": "failed", "chair": "placed", "rug": "placed",
                      "table": "placed", "vase": "placed"}
    assert "FAR_FROM" in scene.objects["sofa"].reason
    assert scene.objects["pillow"].reason == "its support 'sofa' failed"
    by = {(c.relation, c.child.split(":")[0]): c for c in scene.relations}
    for key in [("NEAR", "chair"), ("SIDE_OF", "rug"), ("NEAR", "table")]:
        assert by[key].holds is None
        assert by[key].detail == "unmet: parent 'sofa' failed"
    # the relations that do not involve the sofa were met
    assert by[("ON", "vase")].holds and by[("ON", "table")].holds


def test_every_relation_has_a_rule():
    names = set(relation_names())
    assert set(ROTATION_RULES) == names
    assert set(REGION_RULES) == names
    assert {ph for ph, _ in REGION_RULES.values()} <= {"object", "part", "none"}


def crowded_shelf(n: int) -> PAG:
    pag = PAG("crowded", Room("study", ((0, 0), (3, 0), (3, 3), (0, 3)), 2.7))
    pag.add("bookcase", "bookcase")
    pag.relate("bookcase", "ON", "floor")
    pag.relate("bookcase@back", "AGAINST", "wall_0")
    for i in range(n):
        pag.add(f"book{i}", "book")
        pag.relate(f"book{i}", "IN", "bookcase:shelf#0")
    return pag


def test_backtracking_places_at_least_as_much_and_is_deterministic():
    pag = crowded_shelf(40)
    greedy = solve(pag, seed=0, config=SolverConfig(search="greedy"))
    back = solve(pag, seed=0, config=SolverConfig(search="backtracking", search_budget=12))
    again = solve(pag, seed=0, config=SolverConfig(search="backtracking", search_budget=12))
    assert len(back.placed) >= len(greedy.placed)
    assert back.meta["search"]["budget_left"] >= 0
    assert [(o.id, o.status, tuple(np.round(o.position, 9))) for o in back.objects.values()] == \
           [(o.id, o.status, tuple(np.round(o.position, 9))) for o in again.objects.values()]
    for o in back.failed:  # a full shelf says how many it already holds
        assert "holds" in o.reason and "objects already" in o.reason


def test_config_rejects_unknown_search():
    with pytest.raises(ValueError, match="unknown search"):
        SolverConfig(search="dfs")
    with pytest.raises(ValueError, match="unknown strategy"):
        SolverConfig(strategy="random")


def small_room() -> PAG:
    pag = PAG("small", Room("study", ((0, 0), (3, 0), (3, 3), (0, 3)), 2.7))
    pag.add("desk", "desk")
    pag.relate("desk", "ON", "floor")
    pag.add("mug", "mug")
    pag.relate("mug", "ON", "desk:tabletop")
    pag.add("wardrobe", "wardrobe")
    pag.relate("wardrobe", "ON", "mug")
    return pag


def test_progress_deadline_proposals_and_strict():
    events = []
    scene = solve(small_room(), seed=0, progress=events.append)
    assert [(e.object_id, e.done, e.total) for e in events] == \
           [("desk", 1, 3), ("mug", 2, 3), ("wardrobe", 3, 3)]
    assert [e.status for e in events] == ["placed", "placed", "failed"]
    # a proposal that is valid is taken as is
    desk = scene.objects["desk"]
    again = solve(small_room(), seed=5, proposals={"desk": (desk.rotation, desk.position)})
    assert np.allclose(again.objects["desk"].position, desk.position)
    # a deadline already passed fails everything with "time limit"
    late = solve(small_room(), seed=0, deadline=0.0)
    assert all(o.reason.startswith("time limit") for o in late.objects.values())
    with pytest.raises(InfeasibleError) as ei:
        solve(small_room(), seed=0, strict=True)
    assert ei.value.report.objects["wardrobe"].status == "failed"


def test_floor_furniture_is_square_to_the_walls_unless_free():
    pag = PAG("square", Room("dining_room", ((0, 0), (5, 0), (5, 4), (0, 4)), 2.7))
    pag.add("table", "dining_table")
    pag.relate("table", "ON", "floor")
    pag.add("rug", "rug", yaw="free")
    pag.relate("rug", "ON", "floor")
    assert pag.to_dict()["objects"][1]["yaw"] == "free"
    free = []
    for seed in range(4):
        scene = solve(pag, seed=seed)
        for oid in ("table", "rug"):
            R = scene.objects[oid].rotation
            yaw = np.degrees(np.arctan2(R[1, 0], R[0, 0]))
            off = min(abs(yaw - k) for k in (-180, -90, 0, 90, 180))
            if oid == "table":
                assert off < 1e-6
            else:
                free.append(off)
    assert max(free) > 1.0  # the free rug is not squared
