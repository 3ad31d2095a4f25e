"""What falls after placing, and floors that are full: a cup that finds no room on a crowded
tray rests only where it is held; a rug lies under furniture standing on legs. Solved,
settled and repaired as ``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import pytest

from test_rooms import solved


def _fell(scene) -> list:
    return [(o.id, o.flags) for o in scene.objects.values()
            if {"fell", "tipped", "left_support"} & set(o.flags)]


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_cups_on_a_crowded_tray_are_not_balanced_on_the_kettle(seed):
    """A kettle and two cups IN a tea tray on a small fridge: every cup is placed and stays
    (a pile rest on the kettle's knob or lid slid off in settling), IN the tray after settling,
    and nothing fell."""
    scene = solved("cups_beside_a_kettle", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    assert not _fell(scene), _fell(scene)
    for c in scene.relations:
        if c.relation == "IN":
            assert c.holds_settled is True, (c.child, c.parent, c.residual_settled)


@pytest.mark.parametrize("seed", (0, 1, 2, 3))
def test_a_rug_written_after_the_furniture_lies_between_it(seed):
    """A rug ON the floor of a small furnished bedroom, written after the bed, wardrobe, desk,
    chair and nightstand: it is placed (under the bed's frame or between the chair's feet,
    drawn as large as fits), it rests flat on the floor, nothing fell, and each of its
    relations holds after settling or is recorded relaxed with what blocked it."""
    scene = solved("rug_in_a_furnished_room", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    assert not _fell(scene), _fell(scene)
    relaxed = scene.meta.get("relaxed", {})
    for c in scene.relations:
        if c.child == "rug":
            assert c.holds_settled is True or str(c.index) in relaxed, (c.relation, c.parent)
    rug = scene.objects["rug"]
    assert rug.settled_position is not None
    assert abs(rug.settled_position[2] - rug.position[2]) < 0.01


@pytest.mark.parametrize("seed", (0, 1, 2, 3))
def test_a_register_on_raised_parts_of_a_counter_stays(seed):
    """A cash register ON a checkout counter whose top carries a conveyor and other raised
    parts: it is placed, stays (its centre of mass over what it touches on the raised part,
    not half over the conveyor's end), its ON holds after settling, and nothing fell."""
    scene = solved("register_on_a_checkout", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    assert not _fell(scene), _fell(scene)
    for c in scene.relations:
        if c.child == "register" and c.relation == "ON":
            assert c.holds_settled is True, c.residual_settled
