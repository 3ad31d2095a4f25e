"""Hanging: what is hung by a named part below its top (a jacket named by its collar) hangs
from the hook by its highest part (the hanger above the collar); solved, settled and repaired
as ``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import pytest

from test_rooms import solved


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_a_jacket_named_by_its_collar_hangs_by_its_hanger(seed):
    """Every object placed and every relation held after settling; the jacket's relation is
    measured at its hanger, which lies above its collar (the named part's own gap is recorded
    as ``named_gap``, larger than the contact distance)."""
    scene = solved("hung_by_collar", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    (jacket,) = [c for c in scene.relations if c.child.startswith("jacket")]
    res = jacket.residual_settled
    assert res["named_gap"] > res["distance"] + 0.01, res
    assert -0.001 <= res["distance"] <= 0.002, res


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_three_towels_share_one_bar_along_its_length(seed):
    """Three towels named by their top below one towel bar: all placed, each hung edge-up
    (by its back), side by side along the bar (their footprints do not overlap), every
    relation held after settling."""
    import shapely

    from parse3d.measure.checks import world_points

    scene = solved("towels_on_one_bar", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    towels = [scene.objects[f"towel{k}"] for k in (1, 2, 3)]
    assert all(t.rests_on == "back" for t in towels), [t.rests_on for t in towels]
    fps = [shapely.MultiPoint(world_points(t, hull_only=True, settled=True)[:, :2]).convex_hull
           for t in towels]
    for i in range(3):
        for j in range(i + 1, 3):
            overlap = fps[i].intersection(fps[j]).area
            assert overlap <= 0.05 * min(fps[i].area, fps[j].area), (i, j, overlap)
