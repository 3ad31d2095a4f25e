"""A stable object re-posed only because its support relation broke in settling gets only the
attempts that keep its asset, and when it finds no new pose, what rests on it keeps its pose: a
repair does not spend a full search, nor move a spoon, for a bowl that stays where it was."""

from __future__ import annotations

from pathlib import Path

import numpy as np
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


def test_a_bowl_that_stands_keeps_its_pose_and_its_spoon(settled):
    import copy

    bad = pipeline.unstable_objects(settled)
    assert bad == {"bowl3": "support relation"}  # tilted in the plate's well, standing
    scene = copy.deepcopy(settled)
    spoon = scene.objects["spoon3"]
    done = replace_objects(scene, ["bowl3"], seed=scene.seed, round=1, same_asset={"bowl3"})
    assert done == {}
    assert scene.objects["spoon3"] is spoon  # not placed anew on a bowl that did not move
    # without the hook the spoon is placed anew (another asset) in the bowl that stayed
    scene = copy.deepcopy(settled)
    assert "spoon3" in replace_objects(scene, ["bowl3"], seed=scene.seed, round=1)


def test_repair_of_the_bowl_leaves_the_scene_as_settled():
    scene = solve(load_pag(ROOM), seed=1)
    pipeline.settle_and_repair(scene)
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]
    assert not pipeline.unstable_objects(scene, relations=False)
    bowl = scene.objects["bowl3"]
    assert [r.action for r in bowl.repairs] == ["pose"]
    np.testing.assert_allclose(scene.objects["spoon3"].settled_position,
                               scene.objects["spoon3"].position, atol=0.02)
