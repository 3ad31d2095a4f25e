"""The fast structural check of a PAG document's top level never lets through what the JSON
Schema rejects, and a valid file is checked without importing jsonschema."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from parse3d.pag.schema import _fast_skeleton, _validator

ROOT = Path(__file__).resolve().parent.parent

_SCALARS = st.one_of(st.none(), st.booleans(), st.integers(-3, 3), st.floats(allow_nan=True),
                     st.text(max_size=6), st.just("pag/1"))
_JSON = st.recursive(_SCALARS, lambda inner: st.one_of(
    st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=4), inner, max_size=3)),
    max_leaves=8)
@st.composite
def skeletons(draw) -> dict:
    """Top-level documents (objects and relations emptied), each part valid most of the time."""

    def pick(valid, rate=8):
        return draw(_JSON) if draw(st.integers(0, rate)) == 0 else draw(valid)

    num = st.one_of(st.integers(-5, 5), st.floats(allow_nan=True))
    point = st.lists(num, min_size=2, max_size=2)
    room = {"type": pick(st.just("study")),
            "footprint": pick(st.lists(st.integers(0, 15).flatmap(
                lambda k: _JSON if k == 0 else point), min_size=2, max_size=5), 12),
            "height": pick(num)}
    for k in list(room):
        if draw(st.integers(0, 20)) == 0:
            del room[k]
    if draw(st.integers(0, 20)) == 0:
        room[draw(st.text(max_size=5))] = draw(_JSON)
    doc = {"format": pick(st.just("pag/1")), "name": pick(st.text(max_size=3)),
           "room": room if draw(st.integers(0, 20)) else draw(_JSON),
           "objects": pick(st.just([])), "relations": pick(st.just([]))}
    if draw(st.booleans()):
        doc["meta"] = pick(st.dictionaries(st.text(max_size=3), _SCALARS, max_size=2))
    for k in list(doc):
        if draw(st.integers(0, 25)) == 0:
            del doc[k]
    if draw(st.integers(0, 25)) == 0:
        doc[draw(st.text(max_size=5))] = draw(_JSON)
    return doc


@settings(max_examples=400, deadline=None)
@given(skeletons())
def test_fast_skeleton_passes_only_what_the_schema_accepts(doc):
    if _fast_skeleton(doc):
        assert list(_validator().iter_errors(doc)) == []


def test_a_valid_skeleton_takes_the_fast_path():
    doc = {"format": "pag/1", "name": "x", "objects": [], "relations": [], "meta": {"a": 1},
           "room": {"type": "study", "footprint": [[0, 0], [3, 0.5], [3, 3]], "height": 2.7}}
    assert _fast_skeleton(doc)
    assert not _fast_skeleton({**doc, "room": {**doc["room"], "height": True}})
    assert not _fast_skeleton({**doc, "format": "pag/2"})


def test_validating_an_example_imports_no_jsonschema(tmp_path):
    code = ("import json, sys\nfrom parse3d.pag.io import load_pag\n"
            f"load_pag({str(ROOT / 'examples' / 'kitchen.json')!r})\n"
            "print(json.dumps('jsonschema' in sys.modules))")
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "PARSE3D_CACHE": str(tmp_path)}
    r = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                       check=True)
    assert json.loads(r.stdout.strip().splitlines()[-1]) is False
