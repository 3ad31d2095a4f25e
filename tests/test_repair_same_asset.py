"""A stable object re-posed only because its support relation broke in settling gets only the
attempts that keep its asset, and when it finds no new pose, what rests on it keeps its pose: a
repair does not spend a full search, nor move a spoon, for a bowl that stays where it was."""

from __future__ import annotations

from pathlib import Path

import pytest

from parse3d import pipeline
from parse3d.pag.io import load_pag
from parse3d.solver import solve
from parse3d.solver.search import replace_objects

ROOM = Path(__file__).parent / "data" / "foreign-third" / "breakfast-table.json"


@pytest.fixture(scope="module")
def settled():
    scene = solve(load_pag(ROOM), seed=1)
    pipeline.settle_and_repair(scene, rounds=0)
    return scene


def _standing(scene) -> tuple[str, str]:
    """The object unstable only by its support relation (standing, tilted in a plate's well)
    and the one resting on it (its spoon)."""
    bad = pipeline.unstable_objects(scene)
    oid = next(k for k, why in sorted(bad.items()) if why == "support relation")
    on = next(o.id for o in scene.objects.values()
              if o.placed and o.support_choice is not None and o.support_choice.owner == oid)
    return oid, on


def test_a_bowl_that_stands_keeps_its_pose_and_its_spoon(settled):
    import copy

    bowl, spoon_id = _standing(settled)  # a bowl tilted in a plate's well, standing
    scene = copy.deepcopy(settled)
    spoon = scene.objects[spoon_id]
    done = replace_objects(scene, [bowl], seed=scene.seed, round=1, same_asset={bowl})
    assert done == {}
    assert scene.objects[spoon_id] is spoon  # not placed anew on a bowl that did not move
    # without the hook the spoon is placed anew (another asset) in the bowl that stayed
    scene = copy.deepcopy(settled)
    assert spoon_id in replace_objects(scene, [bowl], seed=scene.seed, round=1)


def test_repair_of_the_bowl_leaves_the_scene_as_settled(settled):
    bowl, spoon_id = _standing(settled)
    scene = solve(load_pag(ROOM), seed=1)
    pipeline.settle_and_repair(scene)
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]
    assert not pipeline.unstable_objects(scene, relations=False)
    assert [r.action for r in scene.objects[bowl].repairs] == ["pose"]
    # what rests on it is still held there after the repair's settling
    assert scene.objects[spoon_id].support_choice.owner == bowl
    assert not {"fell", "left_support"} & set(scene.objects[spoon_id].flags)
