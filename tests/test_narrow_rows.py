"""Small things on narrow supports: markers in a whiteboard's tray lie in a row on the tray's
floor between its walls (tests/data/rooms/markers_in_a_row.json), on the pool's real assets,
solved, settled and checked."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from parse3d.measure import verify_settled
from parse3d.measure.checks import world_points
from parse3d.pag import load_pag
from parse3d.pipeline import PipelineOptions, run_pipeline
from parse3d.solver.support import channel_floor

ROOMS = Path(__file__).parent / "data" / "rooms"
MARKERS = ("red_marker", "blue_marker", "black_marker")


def solved(name: str, seed: int):
    return run_pipeline(load_pag(ROOMS / f"{name}.json"), seed=seed, out=None,
                        options=PipelineOptions(settle=True, preview=False))


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_markers_lie_in_a_row_on_the_floor_of_a_tray(seed):
    """Three markers ON a whiteboard's tray: each lies on the tray's floor (not on the tray's
    own eraser or markers, not on its lip), ON holds after settling, nothing fell."""
    scene = solved("markers_in_a_row", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    board = scene.objects["board"]
    tray = board.asset.parts_by_label("tray")[0]
    floor = channel_floor(board.asset, tray)
    assert floor is not None
    z = float((board.transform(True) @ np.r_[floor.origin, 1.0])[2])
    for mid in MARKERS:
        low = float(world_points(scene.objects[mid], settled=True)[:, 2].min())
        np.testing.assert_allclose(low, z, atol=4e-3, err_msg=mid)
        c = next(c for c in scene.relations if c.child == mid)
        assert c.holds_settled is True, (mid, c.detail, c.residual_settled)
    assert not [i for i in verify_settled(scene) if i.cause == "fell"]
    assert not [o.id for o in scene.objects.values() if {"fell", "tipped"} & set(o.flags)]


@pytest.mark.parametrize("seed", [1, 3])
def test_a_far_from_in_one_tray_is_relaxed_as_far_as_the_tray_allows(seed):
    """Two markers FAR_FROM each other by more than the tray is long: the marker is placed,
    the relation recorded relaxed (what blocked it, what to write instead), and the marker
    lies as far from the other as the free tray allows, not beside it."""
    from parse3d.pag import PAG
    from parse3d.solver import solve

    pag = load_pag(ROOMS / "markers_in_a_row.json")
    data = pag.to_dict()
    data["relations"].append({"relation": "FAR_FROM", "child": "black_marker",
                              "parent": "red_marker", "distance": 0.9})
    scene = solve(PAG.from_dict(data), seed=seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    c = next(c for c in scene.relations if c.relation == "FAR_FROM")
    assert c.holds is False and c.relaxed is not None
    # named in what blocked it, or (when a crosswise footprint's reason ranks first) in what to write instead
    assert "FAR_FROM black_marker -> red_marker" in c.relaxed["blocked"] + c.relaxed["instead"]
    black, red = scene.objects["black_marker"], scene.objects["red_marker"]
    gap = float(np.linalg.norm(black.position[:2] - red.position[:2]))
    assert gap > 0.2  # farther than a marker's length: not packed beside it
