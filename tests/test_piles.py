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


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_a_croissant_on_a_croissant_rests_on_the_pile_in_its_basket(seed):
    """A croissant ON a croissant, the one below and its neighbour IN a bread basket: placed
    (on the one below, or across both), every relation held after settling, and it ends over
    the basket's footprint, higher than the croissant it was written on."""
    scene = solved("croissants_across", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    basket = world_points(scene.objects["bread_basket"], hull_only=True, settled=True)
    c = object_centroid(scene.objects["croissant3"], True)
    assert np.all(c[:2] >= basket[:, :2].min(axis=0)), c
    assert np.all(c[:2] <= basket[:, :2].max(axis=0)), c
    assert c[2] > object_centroid(scene.objects["croissant1"], True)[2]


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_clothes_on_clothes_make_a_folded_pile(seed):
    """Clothes ON clothes on a chair's seat (``clothes`` names folded, loose and hanging
    clothes): the one below is drawn as an instance whose uppermost part is flat, not a dress
    on a hanger whose hook stands up, so the upper one is placed on it; both end over the
    seat and nothing falls; the upper one rests above the lower one."""
    from parse3d.solver.choice import top_lies_flat

    scene = solved("clothes_on_clothes", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    lower, upper = scene.objects["clothes1"], scene.objects["clothes2"]
    assert top_lies_flat(lower.asset), lower.asset.asset_id
    support = [c for c in scene.relations if c.relation == "ON" and c.child.startswith("clothes")]
    assert all(c.holds for c in support), [(c.child, c.residual) for c in support]
    seat = world_points(scene.objects["chair"], hull_only=True, settled=True)
    below = world_points(lower, hull_only=True, settled=True)
    c = object_centroid(upper, True)
    assert np.all(c[:2] >= below[:, :2].min(axis=0)), c
    assert np.all(c[:2] <= below[:, :2].max(axis=0)), c
    assert c[2] > object_centroid(lower, True)[2]
    assert below[:, 2].min() > seat[:, 2].min() + 0.2  # still on the seat, not on the floor
