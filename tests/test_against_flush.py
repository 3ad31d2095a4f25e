"""A contact named on a part that another part overhangs goes flush by that part (the named
part's gap recorded relaxed), never drops the object and what it holds."""

from __future__ import annotations

import pytest

from test_rooms import solved

ROOM = "flush_by_what_sticks_out"


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_overhung_contact_goes_flush_and_keeps_what_it_holds(seed):
    scene = solved(ROOM, seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    by = {(c.relation, c.child): c for c in scene.relations}
    # the fridge's vent grille is a pad on its back: the back is against the wall through it
    fridge = by[("AGAINST", "fridge:body@back")]
    assert fridge.holds and fridge.holds_settled, fridge
    # the toaster's cord reaches behind its body: flush by the cord, or relaxed with the reason
    toaster = by[("AGAINST", "toaster:body@back")]
    if not toaster.holds_settled:
        # flush by the cord (the body's gap is the cord's reach), or, where the counter
        # keeps even the cord off the wall, relaxed with what blocked it
        assert toaster.relaxed and "toaster" in toaster.relaxed["blocked"], toaster
        if "further back than toaster:body" in toaster.relaxed["blocked"]:
            assert 0.0 < toaster.residual["distance"] < 0.1, toaster
    for key in (("IN", "bottle"), ("IN", "can")):
        assert by[key].holds_settled, by[key]
    assert not [o.id for o in scene.objects.values() if "fell" in o.flags]
