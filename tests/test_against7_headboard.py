"""A child ON a part of an object AGAINST another part of it (a pillow on a mattress against
the headboard): the flat of the top ends short of its rounded edge and the seam before the
part, and the child bridges them to rest against the part, held after settling."""

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
