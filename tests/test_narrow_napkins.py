"""A folded napkin longer than a small plate's well, written ON the well, lies across it onto
the plate's raised edge (tests/data/rooms/napkins_across_rims.json): real assets, solved,
settled and checked."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from parse3d.measure import verify_settled
from parse3d.measure.checks import world_points
from parse3d.pag import load_pag
from parse3d.pipeline import PipelineOptions, run_pipeline

ROOMS = Path(__file__).parent / "data" / "rooms"


@pytest.mark.parametrize("seed", [0, 2, 3])
def test_a_napkin_longer_than_the_well_lies_across_it(seed):
    scene = run_pipeline(load_pag(ROOMS / "napkins_across_rims.json"), seed=seed, out=None,
                         options=PipelineOptions(settle=True, preview=False))
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    longer = 0
    for k in "ab":
        plate, napkin = scene.objects[f"plate_{k}"], scene.objects[f"napkin_{k}"]
        c = next(c for c in scene.relations if c.child == f"napkin_{k}")
        assert c.holds_settled is True, (c.detail, c.residual_settled)
        well = world_points(plate, parts=plate.asset.parts_by_label("well"), settled=True)
        nap = world_points(napkin, settled=True)
        longer += float(np.ptp(nap[:, :2], axis=0).max()) > float(np.ptp(well[:, 0]))
    assert longer  # the napkins did not fit inside the well
    assert not [i for i in verify_settled(scene) if i.cause in ("fell", "tipped")]
    assert not [o.id for o in scene.objects.values() if {"fell", "tipped"} & set(o.flags)]
