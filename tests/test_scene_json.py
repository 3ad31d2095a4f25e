"""scene.json text: indented JSON of scene_to_dict, non-finite floats written as null."""

from __future__ import annotations

import json

import numpy as np

from parse3d.assets import registry
from parse3d.pag.model import PAG, Room
from parse3d.scene.io import _finite, read_scene, scene_json, scene_to_dict, write_scene
from parse3d.scene.model import PlacedObject, Scene
from parse3d.scene.shell import build_shell


def _scene() -> Scene:
    room = Room("study", ((0, 0), (3, 0), (3, 2.5), (0, 2.5)), 2.6)
    scene = Scene(PAG("json-test", room), 3, build_shell(room))
    scene.objects["mug"] = PlacedObject("mug", "mug", registry.generate("mug", 0), 1.0,
                                        np.eye(3), np.array([1.0, 1.0, 0.0]))
    return scene


def test_finite_scene_text_is_the_walked_text():
    scene = _scene()
    scene.timings["solve"] = 0.25
    want = json.dumps(_finite(scene_to_dict(scene)), indent=1, allow_nan=False) + "\n"
    assert scene_json(scene) == want


def test_non_finite_floats_become_null(tmp_path):
    scene = _scene()
    scene.meta["score"] = [1.0, float("inf"), {"x": float("-inf"), "y": float("nan")}]
    text = scene_json(scene)
    assert "NaN" not in text and "Infinity" not in text
    doc = json.loads(text)
    assert doc["meta"]["score"] == [1.0, None, {"x": None, "y": None}]
    write_scene(scene, tmp_path)
    assert (tmp_path / "scene.json").read_text() == text
    assert set(read_scene(tmp_path).objects) == {"mug"}
