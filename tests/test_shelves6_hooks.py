"""Wall hooks in a row, each with a hat or a bag to hang below it
(tests/data/rooms/hats_on_hooks_in_a_row.json): a hook written SIDE_OF the one before leaves
room beside it for what it holds, so every hat hangs (before, a hook could go a hand beside
the first one's hat and its own hat found "cap in the way")."""

from __future__ import annotations

from pathlib import Path

import pytest

from parse3d.measure import verify_settled
from parse3d.pag import load_pag
from parse3d.pipeline import PipelineOptions, run_pipeline

ROOMS = Path(__file__).parent / "data" / "rooms"
HUNG = ("cap", "sun_hat", "bag")


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 4, 5])
def test_each_hook_keeps_room_for_its_hat(seed):
    scene = run_pipeline(load_pag(ROOMS / "hats_on_hooks_in_a_row.json"), seed=seed, out=None,
                         options=PipelineOptions(settle=True, preview=False))
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for hid in HUNG:
        c = next(c for c in scene.relations if c.child == hid)
        assert c.relation == "HANGING_BELOW"
        assert c.holds_settled is True, (hid, c.detail, c.residual_settled)
    for c in scene.relations:
        if c.relation in ("SIDE_OF", "SECURED_TO"):
            assert c.holds_settled is True, (c.child, c.parent, c.detail)
    assert not [i for i in verify_settled(scene) if i.cause == "fell"]
    assert not [o.id for o in scene.objects.values() if {"fell", "tipped"} & set(o.flags)]
