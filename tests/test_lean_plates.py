"""Plates displayed on a hutch (tests/data/rooms/plates_on_a_hutch): written ON their rim's
front and LEANING_AGAINST the back panel by their underside, they stand on edge behind the
shelf's plate rail, lean a few degrees from vertical and stay so after settling. The tilt is
measured from the side a plate stands on, not from its top."""

from __future__ import annotations

import numpy as np
import pytest

from parse3d.measure.reach import lean_up
from test_rooms import solved

PLATES = ("plate_a", "plate_b", "plate_c")


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_plates_stand_on_their_rims_leaning_on_the_back_panel(seed):
    scene = solved("plates_on_a_hutch", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for pid in PLATES:
        plate = scene.objects[pid]
        assert plate.placed and not plate.repairs, (pid, plate.repairs)
        mine = [c for c in scene.relations if c.child.startswith(f"{pid}:")]
        assert {c.relation for c in mine} == {"ON", "LEANING_AGAINST"}
        for c in mine:
            assert c.relaxed is None and c.holds_settled is True, (c.relation, c.residual_settled)
        lean = next(c for c in mine if c.relation == "LEANING_AGAINST")
        # a few degrees from vertical, its underside against the panel
        assert 2.0 <= lean.residual_settled["angle_deg"] <= 36.0, lean.residual_settled
        # it stands on edge: its own top (the face it would lie on) is nearly level
        top = np.asarray(plate.settled_rotation) @ np.array([0.0, 0.0, 1.0])
        assert abs(top[2]) < np.sin(np.radians(36.0)), top
        up = np.asarray(plate.settled_rotation) @ lean_up(plate.asset, scene.pag, pid)
        assert up[2] > np.cos(np.radians(36.0)), up


def test_the_tilt_of_a_plate_on_its_rim_is_read_from_the_side_it_stands_on():
    scene = solved("plates_on_a_hutch", 0)
    plate = scene.objects["plate_a"]
    # written ON rim@front: its front faces down when it stands untilted, so its back is up
    np.testing.assert_allclose(lean_up(plate.asset, scene.pag, "plate_a"), [0.0, -1.0, 0.0])
    bowl = scene.objects["bowl"]
    np.testing.assert_allclose(lean_up(bowl.asset, scene.pag, "bowl"), [0.0, 0.0, 1.0])
