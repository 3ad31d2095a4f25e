"""A picture frame with no easel ON a chest of drawers against the wall stands on its lower
edge on the top, leaning back on the wall (tests/data/rooms/frame_on_a_chest.json): real
assets, solved, settled and checked."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from parse3d.measure import verify_settled
from parse3d.measure.checks import world_points
from parse3d.pag import load_pag
from parse3d.pipeline import PipelineOptions, run_pipeline
from parse3d.solver.ledge import WALL_LEAN_DEG

ROOMS = Path(__file__).parent / "data" / "rooms"


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_a_frame_on_a_chest_leans_on_the_wall_behind(seed):
    scene = run_pipeline(load_pag(ROOMS / "frame_on_a_chest.json"), seed=seed, out=None,
                         options=PipelineOptions(settle=True, preview=False))
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    photo = scene.objects["wedding_photo"]
    assert photo.rests_on  # standing on an edge, not lying on its back
    c = next(c for c in scene.relations if c.child == "wedding_photo")
    assert c.holds_settled is True, (c.detail, c.residual_settled)
    assert WALL_LEAN_DEG[0] - 1.0 <= c.residual_settled["angle_deg"] <= WALL_LEAN_DEG[1] + 1.0
    # its back touches the wall the chest stands against, after settling
    wall = scene.room.elements["wall_1"].surface
    gap = float(((world_points(photo, settled=True) - wall.origin) @ wall.normal).min())
    np.testing.assert_allclose(gap, 0.0, atol=5e-3)
    assert not [i for i in verify_settled(scene) if i.cause == "fell"]
    assert not [o.id for o in scene.objects.values() if {"fell", "tipped"} & set(o.flags)]
