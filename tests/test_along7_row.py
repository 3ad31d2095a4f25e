"""A row of units ALONG one another against a wall (a wardrobe, two lockers and a bookcase,
each a few centimetres right of the last): the first unit is placed toward the wall's end
that leaves the most room for those still to come beside it, so the whole row fits and each
ALONG holds after settling (solved, settled and repaired as ``parse3d solve`` does)."""

from __future__ import annotations

import pytest

from test_rooms import solved


@pytest.mark.parametrize("seed", range(8))
def test_row_of_units_fits_along_the_wall(seed):
    """Every object placed, nothing fell, no ALONG relaxed; each holds after settling."""
    scene = solved("units_in_a_row", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for o in scene.objects.values():
        assert "fell" not in o.flags, (o.id, seed, o.flags)
    along = [c for c in scene.relations if c.relation == "ALONG"]
    assert len(along) == 3
    for c in along:
        assert c.relaxed is None, (c.child, seed, c.relaxed)
        assert c.holds_settled is True, (c.child, c.parent, seed, c.detail)
