"""Towels stacked ``ON`` one another, where the towel drawn below may itself be a stack of
folded towels: about as tall as it is wide and deep (extents within 30%), but flat on top
across its footprint (``solver.choice.round_unlidded`` is false). The next
towel stacks on it as written; only a round thing (an apple) is heaped beside its like.
Solved, settled and repaired as ``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import pytest

from test_rooms import solved

STACKED = {"towel_b": "towel_a", "towel_c": "towel_b", "towel_e": "towel_d"}


@pytest.mark.parametrize("seed", (0, 1, 4, 7))
def test_towels_stack_on_a_stack_of_towels(seed):
    scene = solved("towel_stacks_on_a_dresser", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    assert not [o.id for o in scene.objects.values() if "fell" in o.flags]
    for c in scene.relations:
        if c.child in STACKED and c.relation == "ON":
            assert c.relaxed is None, c.relaxed
            assert c.holds_settled, (c.child, c.parent, c.residual_settled)
            assert scene.objects[c.child].support_choice.owner == STACKED[c.child]


def test_a_towel_stack_is_lidded_an_apple_is_not():
    from parse3d.assets import registry
    from parse3d.measure.geometry import hull_extents
    from parse3d.solver.choice import round_unlidded

    stacks = [a for a in (registry.generate("towel", s) for s in range(20))
              if a.asset_id.startswith("towel-stack")]
    assert stacks and not any(round_unlidded(a) for a in stacks)
    apple = registry.generate("apple", 0)
    ext = hull_extents(apple)[0]
    assert ext.max() <= 1.3 * ext.min() and round_unlidded(apple)
