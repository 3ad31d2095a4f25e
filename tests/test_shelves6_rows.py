"""Like things in a crowded row: three pairs of shoes ON one shelf of a small rack go heel to
the back, side by side, packed against the shelf's ends and one another
(tests/data/rooms/shoes_in_rows_on_a_rack.json), on the pool's real assets, solved, settled
and checked; and the turn rule's geometry on its own."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import shapely

from parse3d.measure import verify_settled
from parse3d.pag import load_pag
from parse3d.pipeline import PipelineOptions, run_pipeline
from parse3d.solver.rows import row_turns

ROOMS = Path(__file__).parent / "data" / "rooms"
SHELVES = {"shelf_0": ("boots", "sneakers", "loafers"),
           "shelf_1": ("heels", "sandals", "trainers")}


def _rect(w: float, d: float) -> np.ndarray:
    return np.array([[-w / 2, -d / 2], [w / 2, -d / 2], [w / 2, d / 2], [-w / 2, d / 2]])


def test_row_turns_keep_the_turn_that_takes_them_all():
    """A 0.70 x 0.27 m shelf: three 0.20 x 0.26 m pairs fit across it (heel to the back), not
    lengthwise (two only); one pair alone, or a shelf too shallow for either, tells nothing."""
    shelf = shapely.box(-0.35, -0.135, 0.35, 0.135)
    across, along = _rect(0.20, 0.26), _rect(0.26, 0.20)
    assert row_turns(shelf, [along, across], 3) == [False, True]
    assert row_turns(shelf, [along, across], 2) is None  # both take two
    assert row_turns(shelf, [along, across], 1) is None
    shallow = shapely.box(-0.35, -0.12, 0.35, 0.12)
    assert row_turns(shallow, [along, across], 3) is None  # neither takes three
    # the same shelf turned in its plane reads the same
    turned = shapely.affinity.rotate(shelf, 90, origin=(0, 0))
    assert row_turns(turned, [across, along], 3) == [False, True]


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 4, 5])
def test_three_pairs_of_shoes_fit_on_each_shelf_of_a_small_rack(seed):
    """Every pair is placed (before the turn and the packing, the third pair on a shelf found
    no room at five of these seeds), stands on its shelf after settling, the SIDE_OF chain
    holds, nothing fell. Pairs short enough to go three lengthwise may (the pool's shoes
    differ in size), so the turn itself is checked above."""
    scene = run_pipeline(load_pag(ROOMS / "shoes_in_rows_on_a_rack.json"), seed=seed, out=None,
                         options=PipelineOptions(settle=True, preview=False))
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for part, shoes in SHELVES.items():
        for sid in shoes:
            shoe = scene.objects[sid]
            assert shoe.support_choice.part == part, (sid, shoe.support)
            on = next(c for c in scene.relations if c.child == sid and c.relation == "ON")
            assert on.holds_settled is True, (sid, on.detail, on.residual_settled)
    for c in scene.relations:
        if c.relation == "SIDE_OF":
            assert c.holds_settled is True, (c.child, c.parent, c.detail)
    assert not [i for i in verify_settled(scene) if i.cause == "fell"]
    assert not [o.id for o in scene.objects.values() if {"fell", "tipped"} & set(o.flags)]
