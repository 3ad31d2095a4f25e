"""A stick modelled standing that would topple from its base (a pool cue) written ON a table
lies on its side and stays lying when settled (tests/data/rooms/cues_on_a_table.json): real
assets, solved, settled and checked."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.measure import verify_settled
from parse3d.pag import load_pag
from parse3d.pipeline import PipelineOptions, run_pipeline
from parse3d.solver.standing import lies_down

ROOMS = Path(__file__).parent / "data" / "rooms"


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_cues_on_a_pool_table_lie_on_their_side(seed):
    scene = run_pipeline(load_pag(ROOMS / "cues_on_a_table.json"), seed=seed, out=None,
                         options=PipelineOptions(settle=True, preview=False))
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for cid in ("long_cue", "spare_cue"):
        cue = scene.objects[cid]
        assert cue.rests_on in ("left", "back"), cue.rests_on
        axis = np.asarray(cue.settled_rotation)[:, 2]  # the cue's length, modelled upright
        np.testing.assert_allclose(axis[2], 0.0, atol=np.sin(np.deg2rad(5.0)), err_msg=cid)
        c = next(c for c in scene.relations if c.child == cid)
        assert c.holds_settled is True, (cid, c.detail, c.residual_settled)
    assert not [i for i in verify_settled(scene) if i.cause in ("fell", "tipped")]
    assert not [o.id for o in scene.objects.values() if {"fell", "tipped"} & set(o.flags)]


def test_what_stands_on_a_wide_base_is_not_laid_down():
    """A floor lamp is as tall and thin, but stands on a base that holds it: as written."""
    from parse3d.pag import PAG, Room

    pag = PAG("lamp", Room("living_room", ((0, 0), (3, 0), (3, 3), (0, 3)), 2.6))
    pag.add("lamp", "floor_lamp")
    pag.add("cue", "pool_cue")
    pag.relate("lamp", "ON", "floor")
    pag.relate("cue", "ON", "floor")
    lamp, cue = pag.relations
    for seed in range(4):
        assert lies_down(lamp, registry.generate("floor_lamp", seed=seed), pag) is None
        assert lies_down(cue, registry.generate("pool_cue", seed=seed), pag) is not None
