"""An eraser and two markers ON a whiteboard's tray (tests/data/rooms/eraser_in_a_tray.json): the
tray runs below the board and reaches 7 cm in front of its frame, so an eraser 5-6 cm deep lies on
its floor. Real assets, solved, settled and checked."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from parse3d.measure import verify_settled
from parse3d.pag import load_pag
from parse3d.pipeline import PipelineOptions, run_pipeline
from parse3d.solver.support import channel_floor

ROOMS = Path(__file__).parent / "data" / "rooms"
ON_TRAY = ("eraser", "pen_red", "pen_blue")


def _front(asset, labels) -> float:
    """The greatest y (toward the room) of the asset's parts with these labels."""
    return max(float(pc.vertices[:, 1].max()) for label in labels for p in asset.parts_by_label(label)
               for pc in p.piece_arrays)


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_an_eraser_lies_on_the_tray_floor_in_front_of_the_frame(seed):
    scene = run_pipeline(load_pag(ROOMS / "eraser_in_a_tray.json"), seed=seed, out=None,
                         options=PipelineOptions(settle=True, preview=False))
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    board = scene.objects["board"].asset
    tray = board.parts_by_label("tray")[0]
    floor = channel_floor(board, tray)
    assert floor is not None
    # the usable floor (between the back plate or the frame and the lip) is at least 6 cm deep
    ys = np.asarray(floor.polygon.exterior.coords)[:, 1] if hasattr(floor.polygon, "exterior") else None
    face = _front(board, ("board", "frame"))
    if ys is not None:
        assert float(ys.max()) - face >= 0.06 - 1e-3, (float(ys.max()), face)
    for cid in ON_TRAY:
        c = next(c for c in scene.relations if c.child == cid and c.relation == "ON")
        assert c.holds_settled is True, (cid, c.detail)
        assert scene.objects[cid].support is not None
    assert not [i for i in verify_settled(scene) if i.cause == "fell"]
    assert not [o.id for o in scene.objects.values() if {"fell", "tipped"} & set(o.flags)]
