"""What hangs below an object needs room below one of its parts: the instance drawn for a
group word (``rack``: a dish rack, a wine rack, a coat tree...) or for a part several
variants name (a radiator's ``section``) is one with such a part; solved, settled and
repaired as ``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import pytest

from parse3d.solver.choice import lacks, requirements
from parse3d.solver.hanging import hang_room
from parse3d.solver.library import AssetLibrary
from test_rooms import solved


def test_room_below_tells_a_coat_tree_from_a_dish_rack():
    """A coat tree's hooks have room below for a coat; a dish rack's tines and a shoe rack's
    shelves have not (the next shelf, the counter under it)."""
    lib = AssetLibrary()
    assert all(hang_room(lib.load("coat_rack", s), None, None, 0.9) for s in range(4))
    for cat in ("dish_rack", "storage_rack", "wine_rack"):
        assert not any(hang_room(lib.load(cat, s), None, None, 0.9) for s in range(4)), cat


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_the_rack_drawn_holds_what_hangs_below_it(seed):
    """Every object placed, none fell; the rack and the radiator drawn have room below a
    part for what hangs there, and every relation holds after settling or is recorded
    relaxed with its reason."""
    from parse3d.measure import summarize_settled

    scene = solved("hung_below_a_group_word", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for oid in ("rack", "heater"):
        reqs = requirements(scene.pag, oid)
        assert any(r[3].startswith("hang_room:") for r in reqs), reqs
        assert lacks(scene.objects[oid].asset, reqs) is None, scene.objects[oid].asset.asset_id
    for oid in ("coat1", "coat2", "towel1", "towel2"):
        assert scene.objects[oid].support_choice.owner in ("rack", "heater"), oid
    s = summarize_settled(scene)
    assert s.complete and s.keeps_relations()
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True and c.relaxed is None]
    assert not broken, broken


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_a_garment_bag_hangs_on_the_bar_under_a_rail_with_no_room_below(seed):
    """A garment bag written below a luggage cart's arched rail, whose hanger bar is right
    under it: it hangs on the part below with room for it (the hanger bar), recorded relaxed
    naming that part; every object placed, none fell, every relation holds after settling
    or is recorded relaxed."""
    from parse3d.measure import summarize_settled

    scene = solved("garment_bag_on_a_luggage_cart", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    bag = scene.objects["garment_bag"]
    assert bag.support_choice.owner == "cart" and bag.fixed
    assert bag.support_choice.part.startswith("hanger_bar"), bag.support_choice.part
    s = summarize_settled(scene)
    assert s.complete and s.keeps_relations()
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True and c.relaxed is None]
    assert not broken, broken
    relaxed = scene.meta.get("relaxed") or {}
    hung = [c for c in scene.relations if c.relation == "HANGING_BELOW"]
    assert hung and (hung[0].holds_settled or "it hangs on cart:hanger_bar" in
                     relaxed.get(str(hung[0].index), "")), relaxed


@pytest.mark.parametrize("seed", (0, 1, 2, 3))
def test_a_hook_between_two_headboards_keeps_room_for_its_jacket(seed):
    """A coat hook on the wall two beds stand against, a jacket to hang below it: the hook
    goes where the least of the jacket's room is taken, the jacket hangs from it clear of
    both beds; every object placed, every relation holds after settling or is recorded
    relaxed."""
    from parse3d.measure import summarize_settled

    scene = solved("hook_between_two_beds", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    jacket = scene.objects["jacket"]
    assert jacket.support_choice.owner == "coat_hook" and jacket.fixed
    s = summarize_settled(scene)
    assert s.complete and s.keeps_relations()
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True and c.relaxed is None]
    assert not broken, broken
