"""Toy food in toy pots: a loaf written ``scale`` 0.4-0.5 ``IN`` a pot written 0.5-0.6 is
wider than the pot's floor even at the least scale the bread's size range allows. A writer who
scales a node below 1 means a small one (a toy), so the loaf is shrunk to lie in the floor
within the bread's size range taken down by that same factor (``nesting.floor_fit``). Solved,
settled and repaired as ``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import pytest

from test_rooms import solved

INSIDE = {"toy_loaf": "little_pot", "toy_loaf_2": "little_bowl"}


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_toy_loaves_lie_in_toy_containers(seed):
    from parse3d.solver.geometry import asset_geometry

    scene = solved("toy_food_in_toy_pots", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    assert not [o.id for o in scene.objects.values() if "fell" in o.flags]
    for c in scene.relations:
        if c.child in INSIDE:
            assert c.holds_settled, (c.child, c.residual_settled)
            o = scene.objects[c.child]
            assert o.support_choice.owner == INSIDE[c.child]
            g = asset_geometry(o.asset)
            lo = o.asset.size_range[0] / g.size * 0.4  # the range, taken down by the node's 0.4
            assert o.scale >= lo * 0.999, (c.child, o.scale, lo)
