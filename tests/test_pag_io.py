"""Loading and saving PAG files: exact round-trip, YAML rules, read errors."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from parse3d.errors import InputError, SchemaError
from parse3d.pag import PAG, Room, load_pag, read_document, save_pag

EXAMPLES = sorted(p for p in (Path(__file__).parent.parent / "examples").glob("*.*")
                  if p.suffix in (".json", ".yaml"))  # not the notebook


def test_there_are_at_least_six_examples():
    assert len([p for p in EXAMPLES if p.suffix in (".json", ".yaml", ".yml")]) >= 6


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
@pytest.mark.parametrize("ext", [".json", ".yaml"])
def test_examples_round_trip_exactly(path, ext, tmp_path):
    data = read_document(path)
    assert PAG.from_dict(data).to_dict() == data
    pag = load_pag(path)
    out = save_pag(pag, tmp_path / f"copy{ext}")
    again = load_pag(out)
    assert again == pag
    assert read_document(out) == data


def test_builder_gives_the_dict_a_file_would(tmp_path):
    pag = PAG("corner", Room("study", ((0, 0), (4, 0), (4, 3.5), (0, 3.5)), 2.7))
    pag.add("desk", "desk")
    pag.add("lamp", ["table_lamp", "floor_lamp"], scale=(0.9, 1.1))
    pag.relate("desk", "ON", "floor")
    pag.relate("desk:tabletop@back", "AGAINST", "wall_0")
    pag.relate("lamp", "ON", "desk:tabletop")
    pag.relate("lamp", "SIDE_OF", "desk", side="right")
    pag.relate("desk", "NEAR", "wall_1", distance=1.5)
    text = """{
      "format": "pag/1", "name": "corner",
      "room": {"type": "study", "footprint": [[0, 0], [4, 0], [4, 3.5], [0, 3.5]], "height": 2.7},
      "objects": [{"id": "desk", "category": "desk"},
                  {"id": "lamp", "category": ["table_lamp", "floor_lamp"], "scale": [0.9, 1.1]}],
      "relations": [
        {"relation": "ON", "child": "desk", "parent": "floor"},
        {"relation": "AGAINST", "child": "desk:tabletop@back", "parent": "wall_0"},
        {"relation": "ON", "child": "lamp", "parent": "desk:tabletop"},
        {"relation": "SIDE_OF", "child": "lamp", "parent": "desk", "side": "right"},
        {"relation": "NEAR", "child": "desk", "parent": "wall_1", "distance": 1.5}]}"""
    (tmp_path / "corner.json").write_text(text)
    assert pag.validate() is pag
    assert pag.to_dict() == json.loads(text)
    assert load_pag(tmp_path / "corner.json") == pag


def test_yaml_keeps_on_as_a_string(tmp_path):
    p = tmp_path / "a.yaml"
    p.write_text("format: pag/1\nname: 2024-01-02\nroom: {type: study, footprint: [[0,0],[3,0],"
                 "[3,3]], height: 2.5}\nobjects: [{id: a, category: mug}]\n"
                 "relations:\n- {relation: ON, child: a, parent: floor}\n")
    pag = load_pag(p)
    assert pag.relations[0].relation == "ON"
    assert pag.name == "2024-01-02"
    save_pag(pag, tmp_path / "b.yml")
    assert load_pag(tmp_path / "b.yml") == pag


def test_read_errors_are_input_errors(tmp_path):
    with pytest.raises(InputError, match="no such file"):
        load_pag(tmp_path / "missing.json")
    (tmp_path / "a.txt").write_text("{}")
    with pytest.raises(InputError, match="unknown file type '.txt'"):
        load_pag(tmp_path / "a.txt")
    (tmp_path / "bad.json").write_text('{"format": "pag/1",\n  "name": }')
    with pytest.raises(SchemaError) as e:
        load_pag(tmp_path / "bad.json")
    (p,) = e.value.problems
    assert p.pointer == "" and "line 2, column 11" in p.message and p.file.endswith("bad.json")
    (tmp_path / "bad.yaml").write_text("format: pag/1\nname: [x\n")
    with pytest.raises(SchemaError, match="invalid YAML at line"):
        load_pag(tmp_path / "bad.yaml")


def test_load_reports_every_problem(tmp_path):
    doc = read_document(EXAMPLES[0])
    doc["relations"][0]["relation"] = "ONN"
    doc["objects"][0]["scale"] = [2, 1]
    doc["room"]["height"] = 0
    save_pag(doc, tmp_path / "bad.json")
    with pytest.raises(InputError) as e:
        load_pag(tmp_path / "bad.json")
    pointers = {p.pointer for p in e.value.problems}
    assert {"/relations/0/relation", "/objects/0/scale", "/room/height"} <= pointers
    assert all(p.file == str(tmp_path / "bad.json") for p in e.value.problems)
