"""Room on a support's top for what goes ON it (``solver/fit.py``), solved, settled and
repaired as ``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import pytest

from parse3d.solver.fit import top_sides
from test_rooms import solved


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_a_small_fridge_is_drawn_with_room_for_its_tray(seed):
    """A fridge written small (scale 0.4-0.5) with a tray ON its top, a kettle and a cup IN
    the tray: most instances at that scale have a top smaller than any tray, so the fridge is
    drawn with one that takes it; everything placed and held after settling."""
    scene = solved("tray_on_small_fridge", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    fridge, tray = scene.objects["fridge"], scene.objects["tray"]
    edge = scene.pag.supporter("tray")
    short, long = (fridge.scale * s for s in top_sides(fridge.asset, edge))
    ext = sorted(tray.scale * (tray.asset.bounds[1] - tray.asset.bounds[0])[:2])
    assert ext[0] <= short and ext[1] <= long, (ext, short, long)


#: Why seed 1 of the dining room on a rug fails (not strict: a fix turns it green).
LONG_TABLE = ("a long trestle table on a round rug: the top has room for the table and the "
              "chairs' footprints together, but the chairs at the table's ends reach past the rug")


@pytest.mark.parametrize("seed", (0, pytest.param(1, marks=pytest.mark.xfail(
    reason=LONG_TABLE, strict=False)), 2))
def test_a_rug_is_drawn_with_room_for_a_table_and_its_chairs(seed):
    """A dining table and six chairs ALONG its sides, all ON one rug: the rug is drawn with
    room on its top for all their footprints together; every object placed, nothing fell, and
    every ON relation holds after settling."""
    scene = solved("dining_on_a_rug", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.relation == "ON" and c.holds_settled is not True]
    assert not broken, broken


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_microwave_overhangs_a_mini_fridge_on_its_feet(seed):
    """A microwave ON a mini fridge whose top is smaller than any microwave: it is placed,
    its ON relation holds after settling (its feet on the top, its centre of mass over it),
    and it stays upright."""
    import numpy as np

    scene = solved("microwave_on_mini_fridge", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    held = {(c.relation, c.child): c.holds_settled for c in scene.relations}
    assert held[("ON", "microwave")] is True, held
    up = scene.objects["microwave"].transform(True)[:3, 2] / scene.objects["microwave"].scale
    assert up[2] >= np.cos(np.radians(5.0)), up


@pytest.mark.parametrize("seed", (0, 1, 2, 3))
def test_a_television_leaves_room_for_the_speakers_beside_it(seed):
    """A television ON a small stand's top with a speaker SIDE_OF it left and right on the
    same top: the television is drawn no wider than the top leaves after the speakers (down to
    its category's least size); both speakers placed, every relation held after settling."""
    scene = solved("speakers_beside_a_tv", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
