"""A free-standing garment rack (`garment_rack`, `clothes_rail`, a `rack`): shirts and a dress
hung below its rail stay hung after settling (tests/data/rooms/shirts_on_a_garment_rack.json)."""

from __future__ import annotations

from pathlib import Path

import pytest

from parse3d.measure import verify_settled
from parse3d.pag import load_pag
from parse3d.pipeline import PipelineOptions, run_pipeline

ROOMS = Path(__file__).parent / "data" / "rooms"


@pytest.mark.parametrize("seed", [0, 1])
def test_garments_hang_on_a_garment_rack(seed):
    scene = run_pipeline(load_pag(ROOMS / "shirts_on_a_garment_rack.json"), seed=seed, out=None,
                         options=PipelineOptions(settle=True, preview=False))
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    assert scene.objects["rack"].asset.category == "clothes_rack"
    broken = [(c.relation, c.child, c.parent, c.detail) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken
    for oid in ("shirt1", "shirt2", "shirt3", "dress"):
        assert scene.objects[oid].support_choice.owner == "rack"
    assert not [i for i in verify_settled(scene) if i.cause in ("fell", "tipped")]
