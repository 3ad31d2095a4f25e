"""Property tests: random valid PAGs round-trip and order correctly; corruptions never crash."""

from __future__ import annotations

import copy
import json
import math

import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pag_strategies import pag_documents
from parse3d.errors import InputError, Problem
from parse3d.pag import PAG, assembly_order, support_tree, validate_data
from parse3d.pag.io import _Dumper, _Loader, dumps_pag, loads_document

SETTINGS = settings(max_examples=150, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow])


@SETTINGS
@given(pag_documents())
def test_valid_pags_round_trip_and_order(doc):
    assert validate_data(doc) == []
    pag = PAG.from_dict(doc)
    assert pag.to_dict() == doc
    assert loads_document(dumps_pag(doc), kind="json") == doc
    text = yaml.dump(pag.to_dict(), Dumper=_Dumper, sort_keys=False)
    assert PAG.from_dict(yaml.load(text, Loader=_Loader)) == pag
    order = assembly_order(pag)
    rank = {o: k for k, o in enumerate(order)}
    assert sorted(order) == sorted(pag.objects)
    for e in pag.relations:
        if not e.parent.is_room_element:
            assert rank[e.parent.object] < rank[e.child.object]
    assert set(support_tree(pag)) == set(pag.objects)


_JUNK = [None, True, -1, 0, 2.5, float("nan"), float("inf"), "", "x y", "wall_99", "desk:@",
         [], [1], [[0, 0]], {}, {"a": 1}]


def _paths(node, path=()):
    yield path
    if isinstance(node, dict):
        for k, v in node.items():
            yield from _paths(v, (*path, k))
    elif isinstance(node, list):
        for k, v in enumerate(node):
            yield from _paths(v, (*path, k))


def _get(doc, path):
    for p in path:
        doc = doc[p]
    return doc


@st.composite
def corrupted(draw):
    """(document, must_fail): a valid document with one random corruption."""
    doc = copy.deepcopy(draw(pag_documents(max_objects=6)))
    kind = draw(st.sampled_from(["delete", "retype", "mangle", "cycle", "double", "rename"]))
    paths = [p for p in _paths(doc) if p]
    must_fail = False
    if kind == "delete":
        path = draw(st.sampled_from(paths))
        parent = _get(doc, path[:-1])
        required = path[-1] in ("format", "name", "room", "objects", "relations", "id",
                                "category", "relation", "child", "parent", "type",
                                "footprint", "height") and not (
            path[-1] == "height" and path[0] == "relations")
        if isinstance(parent, dict):
            del parent[path[-1]]
            must_fail = required
        else:
            parent.pop(path[-1])
    elif kind == "retype":
        path = draw(st.sampled_from(paths))
        _get(doc, path[:-1])[path[-1]] = draw(st.sampled_from(_JUNK))
    elif kind == "mangle":
        k = draw(st.integers(0, len(doc["relations"]) - 1))
        side = draw(st.sampled_from(["child", "parent"]))
        text = doc["relations"][k][side]
        junk = draw(st.sampled_from([" ", ".", "@@", "#", ":", "::x", "@sideways", "zz"]))
        at = draw(st.integers(0, len(text)))
        doc["relations"][k][side] = text[:at] + junk + text[at:]
    elif kind == "cycle":
        # A relation from some supporter back to one of its dependants closes a cycle.
        tree = support_tree(PAG.from_dict(doc))
        chained = [c for c, p in tree.items() if p in tree]
        if chained:
            c = draw(st.sampled_from(chained))
            doc["relations"].append({"relation": "NEAR", "child": tree[c], "parent": c})
            must_fail = True
    elif kind == "double":
        o = draw(st.sampled_from(doc["objects"]))["id"]
        doc["relations"].append({"relation": "ON", "child": o, "parent": "floor"})
        must_fail = True
    else:
        o = draw(st.sampled_from(doc["objects"]))
        o["id"] = o["id"] + draw(st.sampled_from(["x", "_2", "-b"]))
        must_fail = True
    return doc, must_fail


@SETTINGS
@given(corrupted())
def test_corruptions_give_problems_never_crashes(case):
    doc, must_fail = case
    problems = validate_data(doc)
    assert all(isinstance(p, Problem) and isinstance(p.message, str) for p in problems)
    if must_fail:
        assert problems
    if problems:
        try:
            validate_data(doc, raise_errors=True)
        except InputError as e:
            assert len(e.problems) == len(problems)
        else:
            raise AssertionError("raise_errors did not raise")
    else:
        # A document that validates is usable: it builds, orders, and can be written.
        pag = PAG.from_dict(doc)
        assembly_order(pag)
        assert all(math.isfinite(v) for p in pag.room.footprint for v in p)
        json.loads(dumps_pag(doc))


@settings(max_examples=60, deadline=None)
@given(st.text(max_size=200))
def test_random_text_never_crashes_the_readers(text):
    for kind in ("json", "yaml"):
        try:
            data = loads_document(text, kind=kind)
        except InputError:
            continue
        validate_data(data)
