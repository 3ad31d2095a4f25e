"""Layout relations placed inside their limits keep holding after settling: a plate NEAR a
chair, a glass NEAR a plate, a knife SIDE_OF a plate, chairs ALONG a table and a bean bag NEAR
one thing and FAR_FROM another are placed with a margin inside the limit where the free room
allows, so the millimetres to centimetres that settling moves things do not undo them (solved,
settled and repaired as ``parse3d solve`` does)."""

from __future__ import annotations

import numpy as np
import pytest

from parse3d.solver.rules.layout import layout_margin
from test_rooms import solved

LAYOUT = ("NEAR", "FAR_FROM", "SIDE_OF", "ALONG")


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_layout_relations_hold_after_settling(seed):
    """Every object placed and resting where it was put (no fall); each layout relation is
    placed at least half its margin inside its limit (the room leaves space for the whole
    margin) and holds on the settled poses."""
    scene = solved("settled_layout_margins", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for o in scene.objects.values():
        moved = o.settled_position[2] - o.position[2] if o.settled_position is not None else 0.0
        assert moved > -0.05, (o.id, seed, moved)
    layout = [c for c in scene.relations if c.relation in LAYOUT]
    assert len(layout) == 8
    pag = {(e.relation, e.child.object, e.parent.object): e for e in scene.pag.relations}
    for c in layout:
        e = pag[(c.relation, c.child, c.parent)]
        if c.relation == "NEAR":
            inside = e.param("distance") - c.residual["distance"]
        elif c.relation == "FAR_FROM":
            inside = c.residual["distance"] - e.param("distance")
        elif c.relation == "ALONG":
            inside = e.param("width") - c.residual["offset"]
        else:
            inside = c.residual["offset"]
        # SIDE_OF's margin is a share of the child's width: a knife's is a few millimetres
        margin = 2e-3 if c.relation == "SIDE_OF" else layout_margin(
            e.param("width" if c.relation == "ALONG" else "distance"))
        assert c.holds and inside >= 0.5 * margin - 1e-4, (c.relation, c.child, seed, c.residual)
        assert c.holds_settled is True, (c.relation, c.child, c.parent, seed,
                                                    c.residual, c.residual_settled)


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_bean_bag_rests_on_its_flat_bottom(seed):
    """A bean bag stands on its sack's flat bottom panel: settling neither tilts nor rolls it,
    and its ON floor holds after settling."""
    scene = solved("settled_layout_margins", seed)
    o = scene.objects["bean_bag"]
    on = next(c for c in scene.relations if c.relation == "ON" and c.child == "bean_bag")
    assert on.holds_settled is True, (seed, on.residual_settled)
    assert on.residual_settled["angle_deg"] < 1.0, (seed, on.residual_settled)
    np.testing.assert_allclose(o.settled_position[:2], o.position[:2], atol=5e-3)
