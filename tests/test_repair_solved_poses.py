"""A repair re-places an object against the solved poses of the rest of the scene (settling
starts again from those), not against where its neighbours came to rest."""

from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pytest

from parse3d.pag.io import load_pag
from parse3d.pipeline import _replace, settle_and_repair, unstable_objects
from parse3d.solver import solve
from parse3d.solver.search import replace_objects

ROOM = Path(__file__).parent / "data" / "rooms" / "glasses_on_coasters.json"


@pytest.fixture(scope="module")
def solved():
    scene = solve(load_pag(ROOM), seed=0)
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]
    return scene


def _slid(scene):
    """``scene`` settled as solved, but for coaster_a, which came to rest 2 cm aside and 1 mm
    lower (a light coaster under a heavy glass)."""
    scene = copy.deepcopy(scene)
    for o in scene.objects.values():
        o.settled_rotation = np.array(o.rotation, float)
        o.settled_position = np.array(o.position, float)
    c = scene.objects["coaster_a"]
    c.settled_position = c.position + np.array([0.02, 0.0, -0.001])
    scene.settled = True
    return scene


def test_glass_is_re_placed_on_the_solved_coaster(solved):
    scene = _slid(solved)
    coaster = scene.objects["coaster_a"]
    rest = coaster.settled_position.copy()
    done = _replace(scene, ["glass_a"], unstable={"glass_a"}, seed=scene.seed, round=1)
    assert done == {"glass_a": "pose"}
    glass = scene.objects["glass_a"]
    # on the coaster as solved: within its outline, on its top
    np.testing.assert_allclose(glass.position[:2], coaster.position[:2], atol=0.03)
    assert glass.settled_position is None  # a new pose, not settled yet
    # what kept its pose keeps where it came to rest
    np.testing.assert_allclose(scene.objects["coaster_a"].settled_position, rest, atol=1e-12)
    assert scene.objects["coaster_a"] is coaster


def test_settled_poses_alone_would_leave_no_pose(solved):
    """The cause: the solver takes the coaster's outline from its settled pose and its collision
    body from its solved one, and every pose on it collides."""
    scene = _slid(solved)
    assert replace_objects(scene, ["glass_a"], seed=scene.seed, round=1) == {}


@pytest.mark.parametrize("seed", [0, 1, pytest.param(2, marks=pytest.mark.xfail(
    reason="a full glass (1.5 kg) tilts the 60 g coaster under it 13 degrees in settling: the "
           "coaster's support relation breaks, another pose of it does the same", strict=False)), 3])
def test_glasses_stay_on_their_coasters(seed):
    scene = solve(load_pag(ROOM), seed=seed)
    settle_and_repair(scene, rounds=3)
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]
    assert not unstable_objects(scene)
    assert not any("fell" in o.flags for o in scene.objects.values())
    for c in scene.relations:  # every glass on its coaster, every coaster on the table
        e = scene.pag.relations[c.index]
        if e.relation == "ON":
            assert c.holds_settled is True, (e, c.residual_settled)
