"""Crowding and piles: fruit of different kinds piled in one bowl, a box stacked on a taped box,
towels in a basket shorter than they are;
solved, settled and repaired as ``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import numpy as np
import pytest

from parse3d.measure.checks import object_centroid, world_points
from test_rooms import solved


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_fruit_of_several_kinds_piles_in_one_bowl(seed):
    """A tomato and three apples IN one bowl, a box ON a box: every object placed and every
    relation held after settling; each fruit ends over the bowl's footprint, the upper box
    over the lower one, resting on its top (or inside it on its floor, an open box)."""
    scene = solved("mixed_fruit_pile", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    bowl = world_points(scene.objects["fruit_bowl"], hull_only=True, settled=True)
    for oid in ("tomato", "apple1", "apple2", "apple3"):
        c = object_centroid(scene.objects[oid], True)
        assert np.all(c[:2] >= bowl[:, :2].min(axis=0)), (oid, c)
        assert np.all(c[:2] <= bowl[:, :2].max(axis=0)), (oid, c)
    lower = world_points(scene.objects["box1"], hull_only=True, settled=True)
    upper = world_points(scene.objects["box2"], hull_only=True, settled=True)
    c = object_centroid(scene.objects["box2"], True)
    assert np.all(c[:2] >= lower[:, :2].min(axis=0)), c
    assert np.all(c[:2] <= lower[:, :2].max(axis=0)), c
    # on the closed box's top, or inside an open one on its floor
    assert lower[:, 2].min() < upper[:, 2].min() <= lower[:, 2].max() + 0.01


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_towels_longer_than_a_small_basket_lie_in_it(seed):
    """Two towels IN a basket whose floor (about 0.15 m) is shorter than a towel at its drawn
    size: each is drawn smaller within the towel's size range, lies inside the basket's
    footprint, and its relation holds after settling."""
    scene = solved("towels_in_basket", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    basket = world_points(scene.objects["basket"], hull_only=True, settled=True)
    for oid in ("towel1", "towel2"):
        c = object_centroid(scene.objects[oid], True)
        assert np.all(c[:2] >= basket[:, :2].min(axis=0)), (oid, c)
        assert np.all(c[:2] <= basket[:, :2].max(axis=0)), (oid, c)
