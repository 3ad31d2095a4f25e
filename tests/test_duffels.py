"""A round duffel bag (gym, barrel) stands on the four studs under it, its curved bottom clear
of the floor, so it neither rolls nor fails the test for standing on its own base; a room of
them lying on the floor and on a suitcase lying on its back solves and settles
(tests/data/rooms/duffels_lying.json)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.measure import verify_settled
from parse3d.pag import load_pag
from parse3d.pipeline import PipelineOptions, run_pipeline
from parse3d.solver.choice import stands

ROOMS = Path(__file__).parent / "data" / "rooms"


@pytest.mark.parametrize("variant", ["gym", "barrel"])
@pytest.mark.parametrize("seed", [0, 1])
def test_a_round_bag_stands_on_its_studs(variant, seed):
    a = registry.generate("duffel_bag", seed, variant)
    body = np.vstack([p.mesh.vertices for p in a.parts_by_label("body")])
    feet = a.parts_by_label("foot")
    assert len(feet) == 4
    assert all(float(f.mesh.bounds[0, 2]) < 1e-4 for f in feet)
    assert float(body[:, 2].min()) > 2e-3  # the curved bottom is clear of the floor
    assert stands(a)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_duffels_lie_on_the_floor_and_on_a_suitcase(seed):
    scene = run_pipeline(load_pag(ROOMS / "duffels_lying.json"), seed=seed, out=None,
                         options=PipelineOptions(settle=True, preview=False))
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for oid in ("duffel_floor", "duffel_top"):
        c = next(c for c in scene.relations if c.relation == "ON" and c.child.split(":")[0] == oid)
        assert c.holds_settled is True, (oid, c.detail, c.residual_settled)
    assert not [i for i in verify_settled(scene) if i.cause in ("fell", "tipped")]
