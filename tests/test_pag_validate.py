"""Validation of PAG documents: examples, vocabulary checks, one-pass reporting, errors."""

from __future__ import annotations

import copy
from pathlib import Path

import pytest

from pag_vocab import PLANNED_PARTS, FakeVocabulary
from parse3d.errors import (
    GeometryInputError,
    GraphError,
    InputError,
    ParameterError,
    Problem,
    ReferenceError,
    SchemaError,
    VocabularyError,
)
from parse3d.pag import PAG, Room, load_pag, pag_schema, read_document, validate_data
from parse3d.relations import RELATIONS

EXAMPLES = sorted(p for p in (Path(__file__).parent.parent / "examples").glob("*.*")
                  if p.suffix in (".json", ".yaml"))  # not the notebook

BASE = {
    "format": "pag/1",
    "name": "corner",
    "room": {"type": "study", "footprint": [[0, 0], [4, 0], [4, 3.5], [0, 3.5]], "height": 2.7},
    "objects": [{"id": "desk", "category": "desk"}, {"id": "mug", "category": "mug"},
                {"id": "shelf", "category": "bookcase"}],
    "relations": [
        {"relation": "ON", "child": "desk", "parent": "floor"},
        {"relation": "AGAINST", "child": "desk:tabletop@back", "parent": "wall_0"},
        {"relation": "ON", "child": "mug", "parent": "desk:tabletop@top"},
        {"relation": "ON", "child": "shelf", "parent": "floor"},
        {"relation": "SIDE_OF", "child": "shelf", "parent": "desk", "side": "left"},
    ],
}


def doc(**changes):
    d = copy.deepcopy(BASE)
    d.update(changes)
    return d


def test_base_is_valid():
    assert validate_data(BASE) == []
    assert validate_data(BASE, vocabulary=FakeVocabulary(PLANNED_PARTS)) == []


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_examples_are_structurally_valid(path):
    data = read_document(path)
    assert validate_data(data, file=str(path)) == []
    assert validate_data(data, vocabulary=FakeVocabulary(PLANNED_PARTS)) == []
    assert 15 <= len(data["objects"]) <= 50


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_examples_are_valid_against_the_asset_registry(path):
    from parse3d.assets.registry import vocabulary

    problems = validate_data(read_document(path), file=str(path), vocabulary=vocabulary())
    assert problems == [], "\n".join(str(p) for p in problems)


def test_examples_use_every_relation_and_room_element():
    relations, parents = set(), set()
    for path in EXAMPLES:
        pag = load_pag(path)
        relations |= {e.relation for e in pag.relations}
        parents |= {e.parent.object for e in pag.relations if e.parent.is_room_element}
        w, d = pag.room.footprint[2]
        assert 3 <= w <= 6 and 3 <= d <= 5 and 2.6 <= pag.room.height <= 3.0
    assert relations == set(RELATIONS)
    assert {"floor", "ceiling", "wall", "wall_0", "wall_1", "wall_2", "wall_3"} <= parents


def test_schema_matches_the_relation_dictionary():
    rel = pag_schema()["$defs"]["relation"]["properties"]
    assert rel["relation"]["enum"] == list(RELATIONS)
    params = {p.name for r in RELATIONS.values() for p in r.params}
    assert set(rel) - {"relation", "child", "parent"} == params


def test_three_mistakes_give_three_problems():
    d = doc()
    d["relations"][2]["parent"] = "dsk:tabletop"           # unknown object
    d["relations"][4]["side"] = "up"                       # bad enum value
    d["room"]["footprint"] = [[0, 0], [0, 3.5], [4, 3.5], [4, 0]]  # clockwise
    problems = validate_data(d)
    assert [p.pointer for p in problems] == ["/relations/4/side", "/room/footprint",
                                            "/relations/2/parent"]
    assert "did you mean 'desk'" in problems[2].message
    with pytest.raises(InputError) as e:
        validate_data(d, raise_errors=True, file="x.json")
    assert len(e.value.problems) == 3 and str(e.value).startswith("x.json:/relations/4/side: ")


@pytest.mark.parametrize(
    ("change", "cls"),
    [
        (lambda d: d.update(format="pag/0"), SchemaError),
        (lambda d: d["relations"][2].update(parent="dsk"), ReferenceError),
        (lambda d: d["relations"].append({"relation": "ON", "child": "mug", "parent": "floor"}),
         GraphError),
        (lambda d: d["relations"][1].update(gap=2.0), ParameterError),
        (lambda d: d["room"].update(height=0), GeometryInputError),
        (lambda d: d["objects"][0].update(category="dsk"), VocabularyError),
        (lambda d: (d["objects"][0].update(category="dsk"), d["room"].update(height=0)),
         InputError),
    ],
)
def test_the_most_specific_error_is_raised(change, cls):
    d = doc()
    change(d)
    with pytest.raises(cls) as e:
        validate_data(d, vocabulary=FakeVocabulary(PLANNED_PARTS), raise_errors=True)
    assert type(e.value) is cls


def test_vocabulary_checks_categories_and_parts():
    vocab = FakeVocabulary({"desk": ("tabletop", "leg"), "mug": ("body", "handle"),
                            "nightstand": ("body", "top_panel", "drawer"),
                            "bookcase": ("shelf",)})
    d = doc()
    d["objects"].append({"id": "stand", "category": ["nighstand", "desk"]})
    d["relations"].append({"relation": "ON", "child": "stand", "parent": "floor"})
    d["relations"].append({"relation": "AGAINST", "child": "mug:handel",
                           "parent": "stand:top_panel"})
    msgs = {p.pointer: p.message for p in validate_data(d, vocabulary=vocab)}
    assert msgs["/objects/3/category/0"] == ("unknown category 'nighstand' — did you mean "
                                             "'nightstand'?")
    assert msgs["/relations/6/child"].startswith("category 'mug' has no part 'handel' — did you "
                                                 "mean 'handle'?")
    # a word that is no misspelling gets the parts closest in meaning (the top of a desk)
    assert msgs["/relations/6/parent"].startswith("category 'desk' has no part 'top_panel' "
                                                  "— did you mean 'tabletop'")
    assert msgs["/relations/6/parent"].endswith("(parts: tabletop, leg)")
    assert len(msgs) == 3


def test_real_registry_vocabulary_for_existing_categories():
    from parse3d.assets.registry import vocabulary

    d = doc()
    d["objects"][2]["category"] = "side_table"
    d["objects"][1]["category"] = ["mug", "tea_cup"]
    d["relations"][2]["child"] = "mug:handle"
    assert validate_data(d, vocabulary=vocabulary()) == []
    d["objects"][1]["category"] = "mgu"
    d["relations"][1]["child"] = "desk:shelf@back"
    msgs = {p.pointer: p.message for p in validate_data(d, vocabulary=vocabulary())}
    assert "did you mean 'mug'" in msgs["/objects/1/category"]
    assert msgs["/relations/1/child"].startswith("category 'desk' has no part 'shelf'")
    assert "tabletop" in msgs["/relations/1/child"]


def test_builder_validate_goes_through_the_validator():
    pag = PAG("x", Room("study", ((0, 0), (3, 0), (3, 3), (0, 3)), 2.6))
    pag.add("desk", "desk")
    pag.add("mug", "mug")
    pag.relate("desk", "ON", "floor")
    pag.relate("mug", "ON", "desk:tabletop")
    pag.relate("mug", "NEAR", "wall_9")
    with pytest.raises(ReferenceError, match="there is no 'wall_9'"):
        pag.validate()
    with pytest.raises(InputError, match="bad reference"):
        pag.relate("mug", "NEAR", "desk..x")


def test_every_problem_is_a_problem_with_a_pointer():
    d = doc(relations=[{"relation": "SIDE_OF", "child": "mug:body", "parent": "ceiling",
                        "side": "left", "gap": "x"}], objects=[{"id": "mug", "category": "mug"},
                                                               {"id": "mug", "category": 5}])
    problems = validate_data(d)
    assert problems and all(isinstance(p, Problem) for p in problems)
    assert all(p.pointer.startswith("/") for p in problems)
    assert len({(p.pointer, p.message) for p in problems}) == len(problems)


@pytest.mark.parametrize("data", [None, 3, "pag", [], [1, 2], {"format": 1}, {"room": []},
                                  {"objects": [1, None, {"id": []}], "relations": [[], {}]}])
def test_garbage_gives_problems_not_crashes(data):
    problems = validate_data(data)
    assert problems
    with pytest.raises(InputError):
        validate_data(data, raise_errors=True)


def test_unhashable_enum_value_is_a_problem_not_a_crash():
    from parse3d.pag.validate import validate_data

    doc = {"format": "pag/1", "name": "x",
           "room": {"type": "study", "footprint": [[0, 0], [4, 0], [4, 3], [0, 3]], "height": 2.7},
           "objects": [{"id": "desk", "category": "desk"}, {"id": "mug", "category": "mug"}],
           "relations": [{"relation": "ON", "child": "desk", "parent": "floor"},
                         {"relation": "ON", "child": "mug", "parent": "desk"},
                         {"relation": "SIDE_OF", "child": "mug", "parent": "desk", "side": []}]}
    problems = validate_data(doc)
    assert [p.pointer for p in problems] == ["/relations/2/side"]
    assert "unknown side" in problems[0].message


def test_a_number_json_cannot_hold_is_a_problem_where_it_is():
    """NaN or infinity anywhere (``meta`` too) makes a PAG that could not be written back:
    a problem at its place, not an error when the PAG is saved."""
    doc = {"format": "pag/1", "name": "a",
           "room": {"type": "study", "footprint": [[0, 0], [2.0, 0], [2.0, 2.0], [0, 2.0]],
                    "height": 3.0},
           "objects": [{"id": "o0", "category": "book"}],
           "relations": [{"relation": "ON", "child": "o0", "parent": "floor"}],
           "meta": {"source": float("nan"), "seed": 0, "w": [1.0, float("inf")]}}
    problems = validate_data(doc)
    assert {p.pointer for p in problems} == {"/meta/source", "/meta/w/1"}
    assert all("finite" in p.message for p in problems)
