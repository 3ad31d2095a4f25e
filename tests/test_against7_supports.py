"""A child ON an object's top AGAINST a face standing beside that top: another part of the
object (a pillow on a mattress against the headboard: the flat of the top ends short of its
rounded edge and the seam before the part) or the wall the object stands against (a
microwave on a countertop: the top's margin from its edge). The child bridges the gap to
rest against the face, held after settling."""

from __future__ import annotations

import pytest

from test_rooms import solved

ROOM = "pillows_against_a_headboard"


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_pillows_rest_against_the_headboard(seed):
    scene = solved(ROOM, seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    by = {(c.relation, c.child): c for c in scene.relations}
    for pid in ("pillow_l", "pillow_r"):
        pillow = scene.objects[pid]
        assert pillow.placed and pillow.support_choice.owner == "bed", pillow.support
        assert pillow.support_choice.part == "mattress", pillow.support
        on = by[("ON", pid)]
        assert on.holds_settled, on
        against = by[("AGAINST", f"{pid}:body@back")]
        if against.relaxed:
            # a tufted headboard's buttons stand proud of it: the pillow touches them first,
            # recorded with the part that stops it (never for want of room on the mattress)
            blocked = against.relaxed["blocked"]
            assert "reaches" in blocked and "emptied" not in blocked, blocked
            assert 0.0 < against.residual["distance"] < 0.02, against
        else:
            assert against.holds and against.holds_settled, against
    assert not [o.id for o in scene.objects.values() if "fell" in o.flags]


WALL_ROOM = "appliances_against_the_wall_on_a_counter"


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_appliances_on_a_counter_rest_against_its_wall(seed):
    # the countertop reaches the wall, but an object's top keeps a margin from its edge:
    # what is against the wall is carried up to it
    scene = solved(WALL_ROOM, seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    by = {(c.relation, c.child): c for c in scene.relations}
    for child, counter in (("microwave:body@back", "counter_a"),
                           ("knife_block:block@back", "counter_b"),
                           ("dish_soap:body@back", "counter_b")):
        oid = child.split(":")[0]
        assert scene.objects[oid].support_choice.owner == counter, scene.objects[oid].support
        assert by[("ON", oid)].holds_settled, by[("ON", oid)]
        against = by[("AGAINST", child)]
        assert not against.relaxed, against.relaxed
        assert against.holds and against.holds_settled, against
    assert not [o.id for o in scene.objects.values() if "fell" in o.flags]
