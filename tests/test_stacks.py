"""Stacks of like things, solved, settled and repaired as ``parse3d solve`` does (real SAPIEN
physics): a can on a can, named by the lower can's body, its lid or no part at all."""

from __future__ import annotations

import numpy as np
import pytest

from parse3d.measure.checks import object_centroid, world_points
from test_rooms import solved


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_cans_stack_on_cans(seed):
    """Every can is placed, nothing fell, every ON holds after settling, and each upper can
    ends over the one below it, resting on its top (the lid's ring-pull lies in low relief, so
    the upper can stands level on it instead of running into it)."""
    scene = solved("stacked_cans", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    for upper, lower in (("can_2", "can_1"), ("can_3", "can_2"), ("can_5", "can_4")):
        low = world_points(scene.objects[lower], hull_only=True, settled=True)
        up = world_points(scene.objects[upper], hull_only=True, settled=True)
        c = object_centroid(scene.objects[upper], True)
        assert np.all(c[:2] >= low[:, :2].min(axis=0)), (upper, c)
        assert np.all(c[:2] <= low[:, :2].max(axis=0)), (upper, c)
        np.testing.assert_allclose(up[:, 2].min(), low[:, 2].max(), atol=3e-3)


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_plates_written_on_the_well_below_stack(seed):
    """``ON plate_2:foot_ring -> plate_1:well@top`` with a plate wider than the well: the writer
    means a stack, so the plate rests on the plate below as a whole; every plate placed, every
    relation held after settling, each upper plate over the one below it."""
    scene = solved("plates_on_wells", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    for upper, lower in (("plate_2", "plate_1"), ("plate_3", "plate_2")):
        off = object_centroid(scene.objects[upper], True) - object_centroid(
            scene.objects[lower], True)
        assert np.hypot(off[0], off[1]) < 0.03, (upper, off)
        assert scene.objects[upper].support_choice.owner == lower


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_baskets_nest_in_baskets(seed):
    """Three shopping baskets, each IN the one below (the second named IN the first's woven
    ``basket`` shell, which holds no floor of its own: it rests on the ``base`` the shell
    encloses): every basket placed and held after settling, each no wider than the one it
    nests in and over it."""
    scene = solved("baskets_nested", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    for upper, lower in (("basket2", "basket1"), ("basket3", "basket2")):
        up = world_points(scene.objects[upper], hull_only=True, settled=True)
        low = world_points(scene.objects[lower], hull_only=True, settled=True)
        assert np.ptp(up[:, :2], axis=0).max() <= 1.05 * np.ptp(low[:, :2], axis=0).max()
        c = object_centroid(scene.objects[upper], True)
        assert np.all(c[:2] >= low[:, :2].min(axis=0)), (upper, c)
        assert np.all(c[:2] <= low[:, :2].max(axis=0)), (upper, c)


@pytest.mark.parametrize("seed", (0, 1, 2, 3))
def test_baskets_written_on_rims_stack_on_the_one_named(seed):
    """Baskets written ``ON`` the rim of the one below: a hollow one of the child's kind is no
    round thing to heap beside (however near its outline comes to a ball's), so each rests on
    the basket written, or, finding no pose on its rim, nests in it, recorded relaxed with
    why; every basket placed and nothing fell in settling."""
    scene = solved("baskets_on_rims", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    assert not [o.id for o in scene.objects.values() if "fell" in o.flags]
    relaxed = scene.meta.get("relaxed", {})
    for upper, lower in (("middle", "stand"), ("upper", "middle")):
        assert scene.objects[upper].support_choice.owner == lower, upper
        c = next(c for c in scene.relations if c.child == upper and c.relation == "ON")
        assert c.holds_settled is True or "nests in" in relaxed.get(str(c.index), ""), \
            (upper, c.residual_settled, relaxed)
