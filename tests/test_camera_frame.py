"""``"frame": "camera"``: SIDE_OF and ALONG read as the photograph shows them, from the PAG's
``viewpoint``; without it a side is in the parent's own frame (a desk facing the camera has
its own left on the viewer's right)."""

from __future__ import annotations

import copy
import json
import math

import numpy as np
import pytest

from parse3d.errors import InputError
from parse3d.measure import object_centroid
from parse3d.pag import PAG, Viewpoint
from parse3d.pag.validate import validate_data
from parse3d.solver import solve

# a 4 x 3 m study: wall_0 is y = 0, wall_2 is y = 3; the camera stands at wall_0 looking +y
# at a desk against wall_2, which faces the camera (its own left is the viewer's right, +x)
DOC = {
    "format": "pag/1", "name": "desk-photo",
    "room": {"type": "study", "footprint": [[0, 0], [4, 0], [4, 3], [0, 3]], "height": 2.7},
    "viewpoint": {"wall": "wall_0"},
    "objects": [{"id": "desk", "category": "desk"}, {"id": "laptop", "category": "laptop"},
                {"id": "mug", "category": "mug"}],
    "relations": [
        {"relation": "ON", "child": "desk", "parent": "floor"},
        {"relation": "AGAINST", "child": "desk:tabletop@back", "parent": "wall_2"},
        {"relation": "ON", "child": "laptop", "parent": "desk:tabletop@top"},
        {"relation": "ON", "child": "mug", "parent": "desk:tabletop@top"},
        {"relation": "SIDE_OF", "child": "mug", "parent": "laptop", "side": "left",
         "frame": "camera"},
    ],
}


def _problems(doc: dict) -> list[str]:
    return [f"{p.pointer}: {p.message}" for p in validate_data(doc)]


def test_a_wall_viewpoint_looks_into_the_room_and_sides_are_the_viewers():
    pag = PAG.from_dict(DOC)
    vp = pag.viewpoint
    assert vp == Viewpoint(wall="wall_0")
    np.testing.assert_allclose(vp.view_direction(pag.room), (0.0, 1.0), atol=1e-12)
    np.testing.assert_allclose(vp.side_direction(pag.room, "right"), (1, 0, 0), atol=1e-12)
    np.testing.assert_allclose(vp.side_direction(pag.room, "left"), (-1, 0, 0), atol=1e-12)
    np.testing.assert_allclose(vp.side_direction(pag.room, "front"), (0, -1, 0), atol=1e-12)
    # looking from (4, 3) toward the origin: the right is a quarter turn clockwise of the view
    p = Viewpoint(position=(4.0, 3.0), look_at=(0.0, 0.0))
    d = np.array(p.view_direction(pag.room))
    r = np.array(p.side_direction(pag.room, "right"))
    np.testing.assert_allclose(d, (-0.8, -0.6), rtol=1e-12)
    assert np.cross(np.r_[d, 0], r)[2] < 0 and math.isclose(float(r @ np.r_[d, 0]), 0.0,
                                                             abs_tol=1e-12)
    assert PAG.from_dict(pag.to_dict()) == pag and pag.to_dict()["viewpoint"] == {"wall": "wall_0"}


@pytest.mark.parametrize("seed", [0, 1])
def test_left_in_the_camera_frame_is_the_viewers_left(seed):
    scene = solve(PAG.from_dict(DOC), seed=seed)
    mug, laptop = scene.objects["mug"], scene.objects["laptop"]
    assert mug.placed and laptop.placed
    xm, xl = object_centroid(mug, False), object_centroid(laptop, False)
    assert xm[0] < xl[0]  # the viewer's left is -x
    side = [c for c in scene.relations if c.relation == "SIDE_OF"]
    assert side and all(c.holds for c in side)


def test_without_the_camera_frame_left_is_the_desks_own_left():
    doc = copy.deepcopy(DOC)
    del doc["relations"][-1]["frame"]
    scene = solve(PAG.from_dict(doc), seed=0)
    xm = object_centroid(scene.objects["mug"], False)
    xl = object_centroid(scene.objects["laptop"], False)
    assert xm[0] > xl[0]  # the desk faces the camera: its left is the viewer's right


def test_viewpoint_problems_name_the_place_and_the_fix():
    doc = copy.deepcopy(DOC)
    del doc["viewpoint"]
    (msg,) = _problems(doc)
    assert msg.startswith("/relations/4/frame:") and '"viewpoint": {"wall": "wall_i"}' in msg
    doc["viewpoint"] = {"wall": "wall_7"}
    assert _problems(doc) == ["/viewpoint/wall: 'wall_7' does not exist: this room has walls "
                              "wall_0 to wall_3"]
    doc["viewpoint"] = {"wall": "wall_0", "position": [1, 1], "look_at": [2, 2]}
    assert any(m.startswith("/viewpoint:") and "not both" in m for m in _problems(doc))
    doc["viewpoint"] = {"position": [1, 1]}
    assert any("both" in m and "look_at" in m for m in _problems(doc))
    doc["viewpoint"] = {"position": [1, 1], "look_at": [1, 1]}
    assert any(m.startswith("/viewpoint/look_at:") for m in _problems(doc))
    doc["viewpoint"] = {"wall": "wall_0", "tilt": 3}
    assert any("tilt" in m for m in _problems(doc))
    # NEAR has no sides: a frame there is refused as any foreign parameter is
    bad = copy.deepcopy(DOC)
    bad["relations"].append({"relation": "NEAR", "child": "mug", "parent": "laptop",
                             "frame": "camera"})
    assert any(m.startswith("/relations/5/frame:") for m in _problems(bad))


def test_the_cli_refuses_a_camera_frame_without_a_viewpoint(tmp_path):
    doc = copy.deepcopy(DOC)
    del doc["viewpoint"]
    f = tmp_path / "room.json"
    f.write_text(json.dumps(doc))
    with pytest.raises(InputError) as e:
        PAG.from_dict(doc).validate()
    assert "viewpoint" in str(e.value)
