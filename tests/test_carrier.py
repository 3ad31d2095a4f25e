"""Things that hang or are mounted by their own hardware: a part hung below a small part
(a mug by its handle on a cup hook, a saucepan by its handle on a pot rail's bar) touches it
by that part, what reaches higher standing beside it; solved, settled and repaired as
``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import pytest

from test_rooms import solved


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_hung_by_a_handle_beside_what_reaches_higher(seed):
    """Every object placed; each mug's and the saucepan's HANGING_BELOW holds after settling
    as written (not relaxed to the rim or the lid knob), their handle's top within a contact
    gap of the hook's or the rail's underside, and nothing fell."""
    scene = solved("hung_by_a_handle", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for oid in ("cup_a", "cup_b", "saucepan"):
        (c,) = [c for c in scene.relations if c.relation == "HANGING_BELOW"
                and c.child.startswith(oid)]
        assert c.relaxed is None, (oid, c.relaxed)
        assert c.holds_settled is True, (oid, c.residual_settled)
        assert scene.objects[oid].fixed, oid
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True and c.relaxed is None]
    assert not broken, broken
