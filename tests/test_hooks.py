"""Pots on a pot rail whose bar runs a few centimetres off the wall: a lidded pot wider than
that gap hangs out from the wall on its hook instead of failing with "collides with the
wall"; solved, settled and repaired as ``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import pytest

from test_rooms import solved


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_pots_wider_than_the_gap_to_the_wall_hang_out_from_it(seed):
    """Every object placed and held (fixed, nothing fell). Each pot's body is clear of the
    wall behind the rail and hangs within a hook's reach in front of it, its top below the
    rail's top; every relation holds after settling or is recorded relaxed, a pot's saying how far
    out from the rail it hangs."""
    from parse3d.measure.checks import world_points
    from parse3d.solver.hanging import HOOK_REACH

    scene = solved("pots_on_a_rail", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True and c.relaxed is None]
    assert not broken, broken
    rail = world_points(scene.objects["rail"], hull_only=True, settled=True)
    for oid in ("dutch_oven", "casserole"):
        pot = scene.objects[oid]
        assert pot.fixed, oid
        pts = world_points(pot, hull_only=True, settled=True)
        assert pts[:, 1].min() >= -1e-3, (oid, pts[:, 1].min())  # clear of wall_0 (y = 0)
        assert pts[:, 1].min() <= rail[:, 1].max() + HOOK_REACH, oid
        # hung from a hook or the bar: its top within the rail's height or a hook's drop below
        assert rail[:, 2].min() - 0.1 <= pts[:, 2].max() <= rail[:, 2].max() + 1e-3, oid
        if pts[:, 1].min() > rail[:, 1].max() + 0.01:  # out from the rail: said so
            (c,) = [c for c in scene.relations if c.child.startswith(oid)]
            assert c.holds_settled is True or "out from it, on its hook" in c.relaxed["blocked"]
