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
