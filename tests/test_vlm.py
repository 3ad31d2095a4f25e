"""The VLM benchmark: building items from a dataset, scoring, baselines, clients, fine-tuning.

One tiny dataset (4 scenes of two small rooms, 2 views each at 320x240) is built per
session and turned into a benchmark once; every test reads those files.
"""

from __future__ import annotations

import base64
import io
import json
import math
import shutil
import socket
import threading
from collections import Counter
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path

import jsonschema
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PIL import Image
from typer.testing import CliRunner

from parse3d.cli import app, main
from parse3d.datagen.build import BuildConfig, build_dataset, resolve_pag_paths
from parse3d.errors import InputError
from parse3d.vlm.balance import RELATION_COUPLES, RelationCandidate, plan_relation_questions
from parse3d.vlm.build import read_jsonl, record_schema
from parse3d.vlm.evaluate import evaluate, parse_choice, parse_scene_graph, score_sgg
from parse3d.vlm.facts import (
    VisibilityRule,
    in_image_share,
    load_scene_facts,
    relation_sources,
    view_facts,
)
from parse3d.vlm.items import option_holds
from parse3d.vlm.vocab import OBJECT_SYNONYMS, normalize_object, normalize_relation

runner = CliRunner()
MIN_PIXELS = 150


def _pag(name, room_type, objects, relations, size):
    w, d = size
    return {"format": "pag/1", "name": name,
            "room": {"type": room_type, "footprint": [[0, 0], [w, 0], [w, d], [0, d]],
                     "height": 2.6},
            "objects": [{"id": i, "category": c} for i, c in objects], "relations": relations}


def _on(child, parent):
    return {"relation": "ON", "child": child, "parent": parent}


PAGS = [
    _pag("tiny-study", "study",
         [("desk", "desk"), ("mug", "mug"), ("book", "book"), ("chair", "office_chair"),
          ("book2", "book"), ("book3", "book")],
         [_on("desk", "floor"), {"relation": "AGAINST", "child": "desk:tabletop@back",
                                 "parent": "wall_0"},
          _on("mug", "desk:tabletop"), _on("book", "desk:tabletop"), _on("chair", "floor"),
          _on("book2", "chair:seat"), _on("book3", "desk:tabletop"),
          {"relation": "NEAR", "child": "chair", "parent": "desk", "distance": 1.0}],
         (3.0, 3.0)),
    _pag("tiny-bedroom", "bedroom", [("ns", "nightstand"), ("lamp", "table_lamp"), ("bed", "bed"),
                                     ("ns2", "nightstand")],
         [_on("bed", "floor"), _on("ns", "floor"), _on("ns2", "floor"),
          {"relation": "AGAINST", "child": "ns@back", "parent": "wall_0"},
          {"relation": "AGAINST", "child": "ns2@back", "parent": "wall_0"},
          _on("lamp", "ns:top_panel"), {"relation": "AGAINST", "child": "bed@back",
                                        "parent": "wall_0"}],
         (3.5, 3.5)),
]


@pytest.fixture(scope="session")
def dataset(tmp_path_factory) -> Path:
    pags = tmp_path_factory.mktemp("vlm-pags")
    for p in PAGS:
        (pags / f"{p['name']}.json").write_text(json.dumps(p))
    out = tmp_path_factory.mktemp("vlm-ds") / "ds"
    cfg = BuildConfig(scenes=4, seed=0, views=2, view_size=(320, 240),
                      source=resolve_pag_paths([pags]))
    report = build_dataset(cfg, out, workers=1)
    assert report.ok == 4
    return out


@pytest.fixture(scope="session")
def bench(dataset, tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("vlm-bench") / "vlm"
    r = runner.invoke(app, ["vlm", "build", str(dataset), "--out", str(out),
                            "--min-pixels", str(MIN_PIXELS)])
    assert r.exit_code == 0, r.output
    return out


def _main(capsys, *args) -> tuple[int, str]:
    """Run the real entry point (input errors -> exit 2); returns the code and all output."""
    with pytest.raises(SystemExit) as e:
        main([str(a) for a in args])
    out = capsys.readouterr()
    return e.value.code, out.out + out.err


def _all(bench: Path) -> list[dict]:
    return [r for s in ("train", "val", "test") for r in read_jsonl(bench / f"{s}.jsonl")]


def test_build_records_splits_and_card(bench, dataset):
    rows = _all(bench)
    tasks = Counter(r["task"] for r in rows)
    assert tasks["relation_mcq"] >= 8 and tasks["contact_mcq"] >= 2 and tasks["sgg"] >= 6
    ids = [r["id"] for r in rows]
    assert len(ids) == len(set(ids))
    for r in rows:
        assert {"id", "task", "scene", "view", "messages", "images"} <= set(r)
        user, assistant = r["messages"]
        assert user["role"] == "user" and user["content"].startswith("<image>")
        assert assistant["role"] == "assistant" and assistant["content"]
        assert len(r["images"]) == 1
        img = bench / r["images"][0]  # relative to the JSONL folder
        assert img.exists() and Image.open(img).size == (320, 240)
        if r["task"] != "sgg":
            assert assistant["content"] in "ABCD" and assistant["content"] == r["meta"]["answer"]
            assert len(r["meta"]["options"]) == 4
            assert "(A) " in user["content"] and "(D) " in user["content"]
    # whole scenes per split
    scenes = {s: {r["scene"] for r in read_jsonl(bench / f"{s}.jsonl")}
              for s in ("train", "val", "test")}
    assert not (scenes["train"] & scenes["test"]) and not (scenes["train"] & scenes["val"])
    assert not (scenes["val"] & scenes["test"])
    assert all(scenes.values())
    validator = jsonschema.Draft202012Validator(record_schema())
    for r in rows:
        validator.validate(r)
    card = json.loads((bench / "vlm.json").read_text())
    assert card["format"] == "parse3d-vlm/1"
    assert card["counts"]["all"]["tasks"] == dict(sorted(tasks.items()))
    letters = card["counts"]["all"]["answer_letters"]["relation_mcq"]
    assert sum(letters.values()) == tasks["relation_mcq"]
    assert max(letters.values()) - min(letters.values()) <= 4  # balanced per scene
    assert set(card["counts"]["all"]["room_types"]) == {"study", "bedroom"}
    assert 0 <= card["counts"]["all"]["no_contact_share"]["contact_mcq"] <= 1
    # nothing was written into the dataset
    assert not any(p.suffix == ".jpg" for p in dataset.rglob("*"))
    # LLaMA-Factory's declaration: its files exist and their images resolve from the folder
    info = json.loads((bench / "dataset_info.json").read_text())
    assert set(info) == {"parse3d_vlm_train", "parse3d_vlm_val", "parse3d_vlm_test"}
    for d in info.values():
        recs = read_jsonl(bench / d["file_name"])
        assert d["formatting"] == "sharegpt" and set(d["columns"].values()) <= set(recs[0])
        assert all((bench / im).is_file() for r in recs for im in r["images"])


def test_questions_ask_about_visible_things_and_have_one_true_option(bench, dataset):
    rule = VisibilityRule(min_pixels=MIN_PIXELS)
    facts = {}
    for r in _all(bench):
        if r["task"] == "sgg":
            continue
        scene = facts.setdefault(r["scene"], load_scene_facts(dataset / "scenes" / r["scene"]))
        view = view_facts(scene, next(v for v in scene.views if v["index"] == r["view"]), rule)
        red, blue = r["meta"]["red"], r["meta"]["blue"]
        assert view.objects[red]["pixels"] >= MIN_PIXELS
        assert view.objects[blue]["share"] >= rule.min_in_image
        holds = [option_holds(scene, view, red, blue, o, rule) for o in r["meta"]["options"]]
        assert holds.count(True) == 1
        assert "ABCD"[holds.index(True)] == r["meta"]["answer"]
        if r["task"] == "contact_mcq":
            assert any(o["kind"] == "no_contact" for o in r["meta"]["options"])


def test_visibility_is_what_is_seen_not_a_hull_share(dataset):
    rule = VisibilityRule(min_pixels=MIN_PIXELS)
    scene = load_scene_facts(dataset / "scenes" / "00000")
    view = max(scene.views, key=lambda v: len(v.get("objects", [])))
    seen = view_facts(scene, view, rule).objects
    assert seen
    # a thin object shows few pixels of a large hull (a floor lamp's pole): still visible
    thin = json.loads(json.dumps(view))
    for rec in thin["objects"]:
        rec["pixels"] = max(rec["pixels"] // 50, MIN_PIXELS) if rec["object"] in seen \
            else rec["pixels"]
    assert set(view_facts(scene, thin, rule).objects) == set(seen)
    # below the pixel floor: not visible
    floor = VisibilityRule(min_pixels=10**7)
    assert not view_facts(scene, view, floor).objects
    # the camera turned so that every object is mostly out of frame: none is asked about
    cut = json.loads(json.dumps(view))
    cut["camera"]["K"][0][2] += 2.0 * cut["camera"]["width"]
    assert not view_facts(scene, cut, rule).objects
    assert round(in_image_share(np.array([[-20.5, 0], [19.5, 0], [19.5, 10], [-20.5, 10]]),
                                640, 480), 6) == 0.5


def test_datasets_naming_parts_object_colon_part_still_read(dataset, tmp_path):
    """A dataset written when scene.glb named part nodes "desk:tabletop" (now "desk__tabletop")
    gives the same objects and boxes."""
    import trimesh

    src = dataset / "scenes" / "00000"
    old = tmp_path / "00000"
    shutil.copytree(src, old)
    ts = trimesh.load(str(src / "scene.glb"), force="scene")
    renamed = trimesh.Scene()
    for node in ts.graph.nodes_geometry:
        T, g = ts.graph[node]
        renamed.add_geometry(ts.geometry[g], node_name=str(node).replace("__", ":", 1),
                             geom_name=str(node).replace("__", ":", 1), transform=T)
    renamed.export(str(old / "scene.glb"))
    assert any(":" in str(n) for n in trimesh.load(str(old / "scene.glb"),
                                                   force="scene").graph.nodes_geometry)
    new, was = load_scene_facts(src), load_scene_facts(old)
    assert set(was.objects) == set(new.objects) and new.objects
    for oid, o in new.objects.items():
        np.testing.assert_allclose(was.objects[oid].corners, o.corners, rtol=1e-5, atol=1e-5)


def test_truth_follows_the_settled_geometry(bench, dataset):
    """Near / far and the camera-frame sides of every question and scene graph, recomputed
    from the settled boxes here, agree with the labels; each carries its derivation."""
    rule = VisibilityRule(min_pixels=MIN_PIXELS)
    facts: dict[str, object] = {}
    checked = 0
    for r in _all(bench):
        scene = facts.setdefault(r["scene"], load_scene_facts(dataset / "scenes" / r["scene"]))
        view = next(v for v in scene.views if v["index"] == r["view"])
        cam = view_facts(scene, view, rule).camera
        if r["task"] == "sgg":
            assert len(r["meta"]["sources"]) == len(r["meta"]["triplets"])
            ids = {o["name"]: o["object"] for o in r["meta"]["objects"]}
            assert {tuple(t) for t in r["meta"]["triplets"]} <= \
                {tuple(t) for t in r["meta"]["holds"]}
            pairs = [(ids[a], rel, ids[b]) for a, rel, b in r["meta"]["holds"]]
        else:
            assert r["meta"]["source"]
            pairs = [(r["meta"]["red"], r["meta"].get("phrase", r["meta"]["relation"]),
                      r["meta"]["blue"])]
        for a, rel, b in pairs:
            ca, cb = scene.objects[a].centroid, scene.objects[b].centroid
            d = float(np.hypot(*(ca[:2] - cb[:2])))
            pa, pb = cam.R @ ca + cam.t, cam.R @ cb + cam.t
            expect = {"near": d < 0.9, "far from": d > 2.2,
                      "left of": pb[0] - pa[0] > 0.15, "right of": pa[0] - pb[0] > 0.15,
                      "in front of": pb[2] - pa[2] > 0.30, "behind": pa[2] - pb[2] > 0.30,
                      "on": (a, b) in scene.contacts, "no contact": (a, b) not in scene.contacts}
            if rel in expect:
                assert expect[rel], (r["id"], a, rel, b, d)
                checked += 1
    assert checked > 20
    # a PAG-stated "near" between the two objects furthest apart is not true
    scene = next(iter(facts.values()))
    ids = sorted(scene.objects)
    a, b = max(((x, y) for x in ids for y in ids), key=lambda p: float(np.hypot(
        *(scene.objects[p[0]].centroid[:2] - scene.objects[p[1]].centroid[:2]))))
    assert np.hypot(*(scene.objects[a].centroid[:2] - scene.objects[b].centroid[:2])) > 1.1
    scene.pag.add((a, "NEAR", b))
    cam = view_facts(scene, scene.views[0], rule).camera
    assert "NEAR" not in relation_sources(scene, cam, a, b, rule)[0]


def test_sgg_boxes_and_relations(bench):
    sgg = [r for r in _all(bench) if r["task"] == "sgg"]
    assert any(r["meta"]["triplets"] for r in sgg)
    for r in sgg:
        text = r["messages"][1]["content"]
        assert "<|box_start|>" in text
        objs, trip = parse_scene_graph(text)
        assert [o["name"] for o in objs] == [o["name"] for o in r["meta"]["objects"]]
        for o in objs:
            x1, y1, x2, y2 = o["box"]
            assert 0 <= x1 < x2 <= 1000 and 0 <= y1 < y2 <= 1000
        assert [list(t) for t in trip] == r["meta"]["triplets"]
        assert "on" in r["messages"][0]["content"] and "left of" in r["messages"][0]["content"]


def test_build_is_deterministic_and_mask_boxes(bench, dataset, tmp_path):
    again = tmp_path / "again"
    r = runner.invoke(app, ["vlm", "build", str(dataset), "--out", str(again),
                            "--min-pixels", str(MIN_PIXELS), "--boxes", "mask"])
    assert r.exit_code == 0, r.output
    a, b = read_jsonl(bench / "test.jsonl"), read_jsonl(again / "test.jsonl")
    assert [x["id"] for x in a] == [x["id"] for x in b]
    assert [x["messages"] for x in a if x["task"] != "sgg"] == \
        [x["messages"] for x in b if x["task"] != "sgg"]
    # mask boxes are the tight boxes of the visible masks: inside the projected ones' image
    sa = [x for x in a if x["task"] == "sgg"]
    sb = [x for x in b if x["task"] == "sgg"]
    assert sa and [x["meta"]["boxes"] for x in sb] == ["mask"] * len(sb)
    assert [x["meta"]["objects"] for x in sa] != [x["meta"]["objects"] for x in sb]


def test_build_bad_input(dataset, tmp_path, capsys):
    # a dataset whose scenes have no views
    bare = tmp_path / "bare"
    (bare / "scenes").mkdir(parents=True)
    src = dataset / "scenes" / "00000"
    dst = bare / "scenes" / "00000"
    dst.mkdir()
    for f in ("scene.json", "contacts.json", "scene.glb"):
        shutil.copy(src / f, dst / f)
    code, out = _main(capsys, "vlm", "build", bare, "--out", tmp_path / "o")
    assert code == 2 and "Traceback" not in out
    assert "no rendered views" in out and "--views" in out
    code, out = _main(capsys, "vlm", "build", dataset, "--out", dataset / "vlm")
    assert code == 2 and "outside the dataset" in out
    code, out = _main(capsys, "vlm", "build", src, "--out", tmp_path / "o2")
    assert code == 2 and "not a dataset folder" in out
    # nothing visible: refused, and a benchmark already in the folder is kept
    kept = tmp_path / "kept"
    assert _main(capsys, "vlm", "build", dataset, "--out", kept)[0] == 0
    before = (kept / "train.jsonl").read_bytes()
    code, out = _main(capsys, "vlm", "build", dataset, "--out", kept, "--min-pixels", 10**8)
    assert code == 2 and "no object is visible" in out and "--min-pixels" in out
    assert (kept / "train.jsonl").read_bytes() == before
    # a corrupt views.json, and a mask box from an instance mask of another size
    for name, change in (("corrupt", lambda d: d[:len(d) // 2]),
                         ("listed", lambda d: "[]"),
                         ("big-mask", lambda d: json.dumps(_widen_boxes(json.loads(d))))):
        copy = tmp_path / name
        shutil.copytree(dataset, copy, ignore=shutil.ignore_patterns("vlm"))
        views = copy / "scenes" / "00000" / "views.json"
        views.write_text(change(views.read_text()))
        code, out = _main(capsys, "vlm", "build", copy, "--out", tmp_path / f"o-{name}")
        assert code == 2 and str(views) in out and "Traceback" not in out, out


def _widen_boxes(doc: dict) -> dict:
    """views.json as if its masks were rendered at twice the camera's size."""
    for v in doc["views"]:
        for rec in v.get("objects", []):
            rec["bbox"] = [2 * x + 1 for x in rec["bbox"]]
            rec["pixels"] *= 4
    return doc


def test_build_renders_missing_views_outside_the_dataset(dataset, tmp_path):
    bare = tmp_path / "bare"
    (bare / "scenes").mkdir(parents=True)
    src, dst = dataset / "scenes" / "00001", bare / "scenes" / "00001"
    dst.mkdir()
    for f in ("scene.json", "contacts.json", "scene.glb"):
        shutil.copy(src / f, dst / f)
    before = sorted(p.name for p in dst.iterdir())
    out = tmp_path / "vlm"
    r = runner.invoke(app, ["vlm", "build", str(bare), "--out", str(out), "--views", "1",
                            "--min-pixels", str(MIN_PIXELS), "--json"])
    assert r.exit_code == 0, r.output
    assert sorted(p.name for p in dst.iterdir()) == before
    assert (out / "renders" / "00001" / "views.json").exists()
    assert json.loads(r.stdout)["rendered_scenes"] == 1
    rows = read_jsonl(out / "test.jsonl") + read_jsonl(out / "train.jsonl")
    assert rows and all(x["view"] == 0 for x in rows)


@pytest.mark.parametrize("text, letter", [
    ("C", "C"), ("(C)", "C"), ("The answer is C.", "C"), ("answer: (b)", "B"), ("D.", "D"),
    ("(A) the mug is on the desk", "A"), ("**B**", "B"), ("I think it is C", "C"),
    ("none of them", None), ("A or B", None), ("", None),
    ("A mug is on the desk.", None), ("A is correct", "A"), ("a", "A"),
    ("A mug is on the desk, so B.", "B"),
])
def test_parse_choice(text, letter):
    assert parse_choice(text) == letter


_PIECES = ["<|box_start|>", "<|box_end|>", "mug#1", "mug", "#2", "(", ")", ", ", " on ",
           "12", "-3", "1000", "Objects:\n", "\nRelations:\n", "right of", "couch", "C", "."]


@settings(max_examples=150, deadline=None)
@given(st.one_of(st.lists(st.sampled_from(_PIECES), max_size=30).map("".join), st.text()))
def test_parsers_take_any_text(text):
    assert parse_choice(text) in (None, "A", "B", "C", "D")
    objs, trip = parse_scene_graph(text)
    gt = {"objects": [{"name": "mug#1", "label": "mug", "box": [0, 0, 10, 10]}],
          "triplets": [["mug#1", "on", "mug#1"]]}
    s = score_sgg(gt, text)
    assert s.correct_matched <= min(s.pred, s.gt) and s.correct_unmatched <= min(s.pred, s.gt)
    assert all(len(o["box"]) == 4 for o in objs) and all(len(t) == 3 for t in trip)


@pytest.mark.parametrize("name, known, label", [
    ("books", {"book"}, "book"), ("The Books", {"book"}, "book"),
    ("shelves", {"shelf"}, "shelf"), ("coffee tables", {"coffee table"}, "coffee table"),
    ("bodies", {"body"}, "body"), ("glass", {"glass"}, "glass"),
    ("couches", set(), "sofa"), ("a couch", {"sofa"}, "sofa"),
    ("glasses", {"wine glass"}, "wine glass"), ("boxes", {"storage box"}, "storage box"),
    ("fridge", set(), "refrigerator"), ("Bedside Table", set(), "nightstand"),
    ("unicorns", {"book"}, "unicorns"),
])
def test_object_names_normalised(name, known, label):
    assert normalize_object(name, frozenset(known)) == label


@pytest.mark.parametrize("name, label", [
    # the shared vocabulary file's synonyms naming one category (not in OBJECT_SYNONYMS)
    ("accent table", "side table"), ("Lounge chairs", "armchair"),
    ("file cabinet", "filing cabinet"), ("an accent table", "side table"),
])
def test_object_names_normalised_by_the_shared_vocabulary(name, label):
    assert name.lower() not in OBJECT_SYNONYMS
    assert normalize_object(name) == label


@pytest.mark.parametrize("phrase, relation", [
    ("on", "on"), ("On top of", "on"), ("is on", "on"), ("to the left of", "left of"),
    ("on the right side of", "right of"), ("next to", "beside"), ("in front", "in front of"),
    ("not in contact with", "no contact"), ("  far   from. ", "far from"),
    ("hanging from", "hanging below"), ("dancing with", None), ("", None),
])
def test_relation_phrases_normalised(phrase, relation):
    assert normalize_relation(phrase) == relation


_MUG_DESK = {"objects": [{"name": "book#1", "label": "book", "box": [100, 100, 200, 200]},
                         {"name": "desk#1", "label": "desk", "box": [50, 150, 900, 900]}],
             "triplets": [["book#1", "on", "desk#1"], ["book#1", "near", "desk#1"]],
             "holds": [["book#1", "on", "desk#1"], ["book#1", "near", "desk#1"],
                       ["book#1", "left of", "desk#1"]]}


@pytest.mark.parametrize("response, recalled, right", [
    # plurals of the benchmark's own labels, a symmetric relation the other way round
    ("books#1 <|box_start|>100, 100, 200, 200<|box_end|>\n"
     "desk#1 <|box_start|>50, 150, 900, 900<|box_end|>\n"
     "(books#1, on, desk#1)\n(desk#1, near, books#1)", 2, 2),
    # Qwen3-VL's grounding JSON, relations as entries
    ('```json\n[{"bbox_2d": [100, 100, 200, 200], "label": "book"},\n'
     ' {"bbox_2d": [50, 150, 900, 900], "label": "desks"},\n'
     ' {"subject": "book", "predicate": "on top of", "object": "desk"}]\n```', 1, 1),
    ('{"objects": [{"bbox_2d": [100, 100, 200, 200], "label": "Book"},'
     ' {"bbox_2d": [50, 150, 900, 900], "label": "desk"}],'
     ' "relations": [["book", "near", "desk"], ["desk", "right of", "book"]]}', 1, 2),
    # a true relation the answer does not list is no false positive; a false one is
    ("book#1 <|box_start|>100, 100, 200, 200<|box_end|> desk#1 <|box_start|>50, 150, 900, 900"
     "<|box_end|> (book#1, left of, desk#1) (book#1, in front of, desk#1)", 0, 1),
    ('[{"bbox_2d": "x", "label": "book"}] {broken', 0, 0),
])
def test_sgg_scoring_reads_plurals_json_and_judges_precision_by_what_holds(
        response, recalled, right):
    s = score_sgg(_MUG_DESK, response)
    assert (s.correct_matched, s.true_matched) == (recalled, right)
    assert (s.correct_unmatched, s.true_unmatched) == (recalled, right)


def test_sgg_scoring_matches_boxes_per_class():
    gt = {"objects": [{"name": "mug#1", "label": "mug", "box": [100, 100, 200, 200]},
                      {"name": "mug#2", "label": "mug", "box": [400, 100, 500, 200]},
                      {"name": "desk#1", "label": "desk", "box": [50, 150, 900, 900]}],
          "triplets": [["mug#1", "on", "desk#1"], ["mug#2", "on", "desk#1"],
                       ["mug#1", "left of", "mug#2"]]}
    # mugs predicted in the other order, a synonym, an inverse relation, one box off
    pred = ("Objects:\nmug#1 <|box_start|>405, 100, 500, 205<|box_end|>\n"
            "mug#2 <|box_start|>100, 95, 200, 200<|box_end|>\n"
            "table#1 <|box_start|>50, 150, 900, 900<|box_end|>\n"
            "Relations:\n(mug#2, on top of, table#1)\n(mug#1, right of, mug#2)\n"
            "(mug#1, under, mug#2)")
    s = score_sgg(gt, pred)
    # "table" is not "desk": no box match for the desk, so only the left-of triplet counts
    assert (s.pred, s.gt, s.correct_matched) == (3, 3, 1)
    assert s.correct_unmatched == 1
    pred_ok = pred.replace("table#1", "desk#1")
    s = score_sgg(gt, pred_ok)
    assert (s.correct_matched, s.correct_unmatched, s.matched_objects) == (2, 2, 3)
    m = s.metrics()
    assert m["precision"] == pytest.approx(200 / 3) and m["recall"] == pytest.approx(200 / 3)


def test_baselines_and_eval(bench, tmp_path):
    test = bench / "test.jsonl"
    scores = {}
    for name in ("random", "prior", "blind", "oracle", "perturbed"):
        pred = tmp_path / f"{name}.jsonl"
        r = runner.invoke(app, ["vlm", "baseline", name, "--data", str(test),
                                "--out", str(pred)])
        assert r.exit_code == 0, r.output
        r = runner.invoke(app, ["vlm", "eval", "--gt", str(test), "--pred", str(pred),
                                "--json"])
        assert r.exit_code == 0, r.output
        scores[name] = json.loads(r.stdout)
    o = scores["oracle"]
    assert o["relation_mcq"]["accuracy"] == 100.0
    if o["contact_mcq"]["n"]:
        assert o["contact_mcq"]["accuracy"] == 100.0
    assert o["sgg"]["f1"] == 100.0 and o["sgg"]["f1_nomatch"] == 100.0
    assert o["unparseable"]["count"] == 0
    p = scores["perturbed"]
    assert p["sgg"]["recall_nomatch"] < 100.0 or p["sgg"]["recall"] < 100.0
    assert p["sgg"]["precision_nomatch"] == 100.0
    assert p["sgg"]["recall"] <= p["sgg"]["recall_nomatch"]
    assert scores["random"]["sgg"]["f1"] < 50
    # the oracle also answers every training question
    pred = tmp_path / "oracle-train.jsonl"
    assert runner.invoke(app, ["vlm", "baseline", "oracle", "--data",
                               str(bench / "train.jsonl"), "--out", str(pred)]).exit_code == 0
    rep = evaluate(read_jsonl(bench / "train.jsonl"),
                   {x["id"]: x["response"] for x in read_jsonl(pred)})
    assert rep.relation["accuracy"] == 100.0 and rep.sgg["f1"] == 100.0
    r = runner.invoke(app, ["vlm", "eval", "--gt", str(test), "--pred",
                            str(tmp_path / "oracle.jsonl"), "--pred",
                            str(tmp_path / "random.jsonl")])
    assert r.exit_code == 0 and "| oracle | 100.0 |" in r.output and "Visual Relation" in r.output
    # --pred a b, as its help shows
    r2 = runner.invoke(app, ["vlm", "eval", "--gt", str(test), "--pred",
                             str(tmp_path / "oracle.jsonl"), str(tmp_path / "random.jsonl")])
    assert r2.exit_code == 0 and r2.output == r.output


def test_eval_bad_predictions(bench, tmp_path, capsys):
    test = bench / "test.jsonl"
    rows = read_jsonl(test)
    pred = tmp_path / "p.jsonl"
    lines = [{"id": r["id"], "response": "no idea"} for r in rows[1:]] + [
        {"id": "nope", "response": "A"}]
    pred.write_text("".join(json.dumps(x) + "\n" for x in lines))
    code, out = _main(capsys, "vlm", "eval", "--gt", test, "--pred", pred)
    assert code == 2 and "Traceback" not in out
    assert "1 benchmark ids have no prediction" in out and rows[0]["id"] in out
    assert "not in test.jsonl" in out
    r = runner.invoke(app, ["vlm", "eval", "--gt", str(test), "--pred", str(pred),
                            "--allow-missing", "--json"])
    assert r.exit_code == 0, r.output
    d = json.loads(r.stdout)
    assert d["missing"]["count"] == 1 and d["unknown"]["count"] == 1
    n_mcq = sum(r["task"] != "sgg" for r in rows[1:])
    assert d["unparseable"]["count"] == n_mcq
    assert d["relation_mcq"]["accuracy"] == 0.0
    pred.write_text('{"id": "x"}\n')
    code, out = _main(capsys, "vlm", "eval", "--gt", test, "--pred", pred)
    assert code == 2 and "line 1" in out and "response" in out
    pred.write_text("{not json\n")
    code, out = _main(capsys, "vlm", "eval", "--gt", test, "--pred", pred)
    assert code == 2 and "not valid JSON" in out


# -- model client ------------------------------------------------------------------------


class _Chat(BaseHTTPRequestHandler):
    """An OpenAI-compatible chat endpoint: checks the request, fails the first calls (503)."""

    state: dict = {}

    def log_message(self, *args):  # keep the test output clean
        pass

    def do_POST(self):  # noqa: N802 - http.server's name
        st = self.state
        body = json.loads(self.rfile.read(int(self.headers["Content-Length"])))
        with st["lock"]:
            st["calls"] += 1
            fail = st["fail"] > 0
            st["fail"] -= 1 if fail else 0
        if self.path != "/v1/chat/completions" or body.get("model") != "tiny-vl":
            return self._send(404, {"error": {"message": "no such model"}})
        if fail:
            return self._send(503, {"error": {"message": "overloaded"}})
        (msg,) = body["messages"]
        kinds = [p["type"] for p in msg["content"]]
        assert msg["role"] == "user" and kinds == ["image_url", "text"]
        url = msg["content"][0]["image_url"]["url"]
        head, data = url.split(",", 1)
        assert head == "data:image/jpeg;base64"
        Image.open(io.BytesIO(base64.b64decode(data))).verify()
        text = msg["content"][1]["text"]
        with st["lock"]:
            st["answered"].append(text)
        reply = ("Objects:\ndesk#1 <|box_start|>0, 0, 500, 500<|box_end|>\nRelations:\n"
                 if text.startswith("Detect") else "The answer is (B).")
        self._send(200, {"id": "x", "object": "chat.completion", "model": body["model"],
                         "choices": [{"index": 0, "finish_reason": "stop",
                                      "message": {"role": "assistant", "content": reply}}],
                         "usage": {"prompt_tokens": 100, "completion_tokens": 5,
                                   "total_tokens": 105}})

    def _send(self, code, doc):
        data = json.dumps(doc).encode()
        self.send_response(code)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)


@pytest.fixture
def server():
    _Chat.state = {"calls": 0, "fail": 2, "answered": [], "lock": threading.Lock()}
    httpd = ThreadingHTTPServer(("127.0.0.1", 0), _Chat)
    t = threading.Thread(target=httpd.serve_forever, daemon=True)
    t.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}/v1", _Chat.state
    httpd.shutdown()
    httpd.server_close()


def test_ask_endpoint_retries_resumes_and_scores(bench, server, tmp_path, capsys):
    url, state = server
    test = bench / "test.jsonl"
    rows = read_jsonl(test)
    out = tmp_path / "pred.jsonl"
    code, text = _main(capsys, "vlm", "ask", "--endpoint", url, "--model", "tiny-vl", "--data",
                       test, "--out", out, "--limit", 3, "--backoff", 0.01, "-j", 2, "--json")
    assert code == 0, text
    first = json.loads(text[text.index("{"):])
    assert first["answered"] == 3 and first["retries"] >= 2
    assert first["prompt_tokens"] == 300 and first["latency_s"]["p95"] > 0
    # an interrupted run (here: --limit) resumes: only the rest is asked
    code, text = _main(capsys, "vlm", "ask", "--endpoint", url, "--model", "tiny-vl", "--data",
                       test, "--out", out, "--backoff", 0.01, "--price-in", 1.0)
    assert code == 0, text
    assert f"{len(rows) - 3} answered, 3 already there" in text and "cost $" in text
    preds = read_jsonl(out)
    assert sorted(p["id"] for p in preds) == sorted(r["id"] for r in rows)
    assert len(state["answered"]) == len(rows)
    # the prompt went without the answer, and the predictions score
    assert all("Your answer should only be" in t or t.startswith("Detect")
               for t in state["answered"])
    code, text = _main(capsys, "vlm", "eval", "--gt", test, "--pred", out, "--json")
    assert code == 0
    d = json.loads(text)
    assert d["unparseable"]["count"] == 0 and d["relation_mcq"]["n"] > 0


def test_ask_bad_endpoint_and_arguments(bench, server, tmp_path, capsys):
    url, _ = server
    test = bench / "test.jsonl"
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        closed = s.getsockname()[1]
    code, text = _main(capsys, "vlm", "ask", "--endpoint", f"http://127.0.0.1:{closed}/v1",
                       "--model", "m", "--data", test, "--out", tmp_path / "p.jsonl",
                       "--retries", 1, "--backoff", 0.01)
    assert code == 2 and "Traceback" not in text
    assert "cannot connect" in text and "--endpoint" in text
    code, text = _main(capsys, "vlm", "ask", "--endpoint", url, "--model", "wrong", "--data",
                       test, "--out", tmp_path / "p.jsonl")
    assert code == 2 and "404" in text
    code, text = _main(capsys, "vlm", "ask", "--endpoint", url, "--model", "tiny-vl",
                       "--local", tmp_path, "--data", test, "--out", tmp_path / "p.jsonl")
    assert code == 2 and "exactly one of" in text
    code, text = _main(capsys, "vlm", "ask", "--local", tmp_path, "--data", test,
                       "--out", tmp_path / "p.jsonl")
    assert code == 2 and "not a model folder" in text
    # a record naming an image outside its split's folder is never read, nor sent
    secret = tmp_path / "secret.png"
    secret.write_bytes(b"private")
    rec = dict(read_jsonl(test)[0], id="evil", images=[f"../{'../' * 12}{secret}"])
    (tmp_path / "split").mkdir()
    evil = tmp_path / "split" / "test.jsonl"
    evil.write_text(json.dumps(rec) + "\n")
    code, text = _main(capsys, "vlm", "ask", "--endpoint", url, "--model", "tiny-vl", "--data",
                       evil, "--out", tmp_path / "evil.jsonl", "--retries", 1)
    assert code == 2 and "outside" in text and "Traceback" not in text, text
    assert not any("private" in t for t in server[1]["answered"])


# -- fine-tuning a tiny offline Qwen3-VL ---------------------------------------------------------


def test_finetune_tiny_qwen3vl_then_ask_local_and_eval(bench, tmp_path, capsys):
    from parse3d.vlm.finetune import FinetuneOptions, lr_at
    from parse3d.vlm.tiny import make_tiny_qwen3vl

    texts = [m["content"] for r in read_jsonl(bench / "train.jsonl") for m in r["messages"]]
    model = make_tiny_qwen3vl(tmp_path / "tiny", texts, vocab_size=400)
    adapter = tmp_path / "lora"
    code, text = _main(capsys, "vlm", "finetune", "--model", model, "--data", bench, "--out",
                       adapter, "--max-items", 8, "--epochs", 3, "--global-batch", 4,
                       "--micro-batch", 2, "--lr", 3e-3, "--min-lr", 3e-4,
                       "--ratios", "relation_mcq=1,contact_mcq=1,sgg=0", "--json")
    assert code == 0, text
    rec = json.loads((adapter / "finetune.json").read_text())
    losses = rec["losses"]
    assert rec["accumulation"] == 2 and rec["items"] <= 8
    micro = math.ceil(rec["items"] * 3 / 2)
    assert rec["updates"] == math.ceil(micro / 2)
    assert rec["recipe"]["rank"] == 8 and rec["recipe"]["alpha"] == 32
    assert np.mean(losses[-2:]) < losses[0] - 0.3  # the loss falls
    assert (adapter / "adapter_config.json").exists()
    cfg = json.loads((adapter / "adapter_config.json").read_text())
    assert cfg["r"] == 8 and cfg["lora_alpha"] == 32
    assert all("language_model" in t for t in cfg["target_modules"])
    assert any(t.endswith("down_proj") for t in cfg["target_modules"])
    # the recipe's schedule: linear warm-up, then down to the minimum
    o = FinetuneOptions()
    assert lr_at(0, 100, o) == pytest.approx(2e-5) and lr_at(4, 100, o) == pytest.approx(1e-4)
    assert lr_at(99, 100, o) == pytest.approx(1e-5, rel=0.05)
    # reload the adapter, answer the test split, score it
    pred = tmp_path / "pred.jsonl"
    code, text = _main(capsys, "vlm", "ask", "--local", model, "--adapter", adapter, "--data",
                       bench / "test.jsonl", "--out", pred, "--max-tokens", 4)
    assert code == 0, text
    assert len(read_jsonl(pred)) == len(read_jsonl(bench / "test.jsonl"))
    code, text = _main(capsys, "vlm", "eval", "--gt", bench / "test.jsonl", "--pred", pred,
                       "--json")
    assert code == 0, text
    d = json.loads(text)
    assert d["missing"]["count"] == 0 and d["relation_mcq"]["accuracy"] is not None
    # damaged or pickled models and adapters: exit 2 naming the folder, nothing answered
    import shutil

    def ask(model_dir, adapter_dir=None) -> tuple[int, str]:
        args = ["vlm", "ask", "--local", model_dir, "--data", bench / "test.jsonl", "--out",
                tmp_path / "bad.jsonl", "--max-tokens", 1]
        return _main(capsys, *args, *(["--adapter", adapter_dir] if adapter_dir else []))

    broken = tmp_path / "broken"
    shutil.copytree(model, broken)
    w = next(broken.glob("*.safetensors"))
    w.write_bytes(w.read_bytes()[:len(w.read_bytes()) // 2])
    code, text = ask(broken)
    assert code == 2 and str(broken) in text and "Traceback" not in text, text
    half = tmp_path / "half"
    shutil.copytree(model, half)
    (half / "config.json").write_text((half / "config.json").read_text()[:50])
    code, text = ask(half)
    assert code == 2 and str(half) in text, text
    pickled = tmp_path / "pickled"
    shutil.copytree(adapter, pickled)
    (pickled / "adapter_model.safetensors").rename(pickled / "adapter_model.bin")
    code, text = ask(model, pickled)
    assert code == 2 and "safetensors" in text, text
    assert not (tmp_path / "bad.jsonl").exists() or read_jsonl(tmp_path / "bad.jsonl") == []


def test_finetune_tiny_qwen3vl_moe_adapts_its_experts(bench, tmp_path):
    """LoRA reaches a mixture-of-experts model's experts (3-D parameters, not linear layers)
    through peft's parameter targeting; with gradient checkpointing and length-grouped
    batches the adapter trains, saves and reloads."""
    import torch
    from peft import PeftModel
    from transformers import AutoModelForImageTextToText

    from parse3d.vlm.finetune import FinetuneOptions, expert_parameters, finetune
    from parse3d.vlm.tiny import make_tiny_qwen3vl

    texts = [m["content"] for r in read_jsonl(bench / "train.jsonl") for m in r["messages"]]
    model_dir = make_tiny_qwen3vl(tmp_path / "moe", texts, vocab_size=400, experts=4)
    base = AutoModelForImageTextToText.from_pretrained(model_dir)
    experts = expert_parameters(base)
    assert experts and all(p.endswith(("gate_up_proj", "down_proj")) for p in experts)
    before = {n: p.detach().clone() for n, p in base.named_parameters() if n in experts}
    opts = FinetuneOptions(max_items=6, global_batch=2, micro_batch=2, lr=3e-3, min_lr=3e-4,
                           ratios={"relation_mcq": 1, "contact_mcq": 0, "sgg": 0},
                           val_items=0)
    assert opts.gradient_checkpointing and opts.group_by_length
    res = finetune(model_dir, bench, tmp_path / "lora", opts)
    assert res.steps >= 2 and all(np.isfinite(res.losses))
    cfg = json.loads((tmp_path / "lora" / "adapter_config.json").read_text())
    assert sorted(cfg["target_parameters"]) == sorted(experts)
    rec = json.loads((tmp_path / "lora" / "finetune.json").read_text())
    assert rec["lora_expert_parameters"] == len(experts)
    tuned = PeftModel.from_pretrained(base, tmp_path / "lora").merge_and_unload()
    changed = [n for n, p in tuned.named_parameters()
               if n in before and not torch.allclose(p, before[n])]
    assert sorted(changed) == sorted(experts)  # every expert tensor moved


def test_length_grouped_batches_keep_every_item():
    from parse3d.vlm.finetune import length_grouped

    rng = np.random.default_rng(0)
    items = [{"id": i, "messages": [{"content": "x" * int(n)}]}
             for i, n in enumerate(rng.integers(1, 500, 200))]
    out = length_grouped(items, 4, np.random.default_rng(1), window=50)
    assert sorted(r["id"] for r in out) == list(range(200))
    spread = [np.ptp([len(r["messages"][0]["content"]) for r in out[i:i + 4]])
              for i in range(0, 200, 4)]
    raw = [np.ptp([len(r["messages"][0]["content"]) for r in items[i:i + 4]])
           for i in range(0, 200, 4)]
    assert np.mean(spread) < 0.2 * np.mean(raw)


def test_contact_questions_are_balanced_so_text_cannot_answer(bench):
    """Every part-contact question offers a contact and "not in contact" for the marked
    objects' categories and for another category pair; per split and category pair, as many
    answers are a contact as are "not in contact"."""
    for split in ("train", "val", "test"):
        answers: dict[tuple, Counter] = {}
        for r in read_jsonl(bench / f"{split}.jsonl"):
            if r["task"] != "contact_mcq":
                continue
            opts = r["meta"]["options"]
            pairs = Counter((o["subject"], o["object"]) for o in opts)
            assert sorted(pairs.values()) == [2, 2]
            for pair in pairs:
                kinds = sorted(o["kind"] for o in opts if (o["subject"], o["object"]) == pair)
                assert kinds == ["contact", "no_contact"]
            right = opts["ABCD".index(r["meta"]["answer"])]
            key = tuple(sorted((right["subject"], right["object"])))
            answers.setdefault(key, Counter())[right["kind"]] += 1
        for key, c in answers.items():
            assert c["contact"] == c["no_contact"], (split, key, c)
    n = sum(1 for r in _all(bench) if r["task"] == "contact_mcq")
    assert n >= 2


def test_probe_trains_from_scratch_and_answers_the_test_split(bench, tmp_path):
    """The learnability probe's CPU path: a small CNN and its text-only twin train on the
    training MCQ and answer every test MCQ; with the images it can memorise eight questions
    (the text alone cannot: questions with the same options have other answers)."""
    from parse3d.vlm.probe import ProbeOptions, train_probe

    test_ids = {r["id"] for r in read_jsonl(bench / "test.jsonl") if r["task"] != "sgg"}
    for image in (True, False):
        # lr 1e-3 for 300 epochs: at 3e-3 the loss oscillates and what is memorised depends
        # on the rendered images' last bits
        opts = ProbeOptions(size=(64, 48), epochs=300, batch=4, width=8, max_items=8,
                            lr=1e-3, image=image, threads=1)
        res = train_probe(bench, opts)
        assert set(res.responses) == test_ids
        assert set(res.responses.values()) <= set("ABCD")
        assert res.items["train"] == 8 and len(res.losses) == 300
        assert all(math.isfinite(x) for x in res.losses)
        if image:  # the images tell eight questions apart: memorised
            assert res.losses[-1] < 0.5 * res.losses[0]
            assert min(res.train_accuracy.values()) >= 75.0, res.train_accuracy
        report = evaluate(read_jsonl(bench / "test.jsonl"), res.responses)
        assert report.relation["n"] + report.contact["n"] == len(test_ids)
        assert json.loads(json.dumps(res.to_json()))["options"]["image"] is image
    with pytest.raises(InputError, match="benchmark folder"):
        train_probe(tmp_path)


@pytest.fixture
def tiny_server(bench, tmp_path):
    """The tiny random Qwen3-VL served by parse3d.vlm.serve (uvicorn, a free local port)."""
    import uvicorn

    from parse3d.vlm.serve import make_app
    from parse3d.vlm.tiny import make_tiny_qwen3vl

    texts = [m["content"] for r in read_jsonl(bench / "train.jsonl") for m in r["messages"]]
    model = make_tiny_qwen3vl(tmp_path / "tiny", texts, vocab_size=400)
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    srv = uvicorn.Server(uvicorn.Config(make_app(model, name="tiny-qwen3vl", max_tokens=16),
                                        host="127.0.0.1", port=port, log_level="warning"))
    t = threading.Thread(target=srv.run, daemon=True)
    t.start()
    for _ in range(400):
        if srv.started:
            break
        threading.Event().wait(0.05)
    assert srv.started
    yield f"http://127.0.0.1:{port}/v1", model
    srv.should_exit = True
    t.join(timeout=10)


def _gpu_run():
    import importlib.util

    path = Path(__file__).resolve().parents[1] / "benchmarks" / "vlm_gpu_run.py"
    spec = importlib.util.spec_from_file_location("vlm_gpu_run", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_one_gpu_run_on_cpu_with_a_served_tiny_model(bench, tiny_server, tmp_path):
    """The one-GPU script's CPU path: zero-shot through the OpenAI-compatible client against
    a served tiny Qwen3-VL, then LoRA (gradient checkpointing, length-grouped batches) and
    the adapter's answers, each scored into report.json."""
    import httpx

    url, model = tiny_server
    # the server speaks the API: a wrong model name is a 404, a file URL a 400
    r = httpx.post(url + "/chat/completions", json={"model": "other", "messages": []})
    assert r.status_code == 404
    r = httpx.post(url + "/chat/completions", json={
        "model": "tiny-qwen3vl", "messages": [{"role": "user", "content": [
            {"type": "image_url", "image_url": {"url": "file:///etc/hostname"}},
            {"type": "text", "text": "hi"}]}]})
    assert r.status_code == 400 and "data URL" in r.text
    assert httpx.get(url + "/models").json()["data"][0]["id"] == "tiny-qwen3vl"
    run, out = _gpu_run(), tmp_path / "gpu"
    run.main(["zero-shot", "--bench", str(bench), "--endpoint", url, "--model", "tiny-qwen3vl",
              "--out", str(out), "--limit", "2", "--max-tokens", "8", "-j", "2"])
    rows = run._test_rows(bench, 2)
    n = Counter(r["task"] for r in rows)
    assert n["relation_mcq"] == 2 and n["sgg"] == 2  # the first two of every task
    pred = read_jsonl(out / "zero-shot.jsonl")
    assert {p["id"] for p in pred} == {r["id"] for r in rows}
    assert all(p["usage"]["prompt_tokens"] > 100 for p in pred)  # the image's tokens too
    run.main(["lora", "--bench", str(bench), "--model", str(model), "--out", str(out),
              "--max-items", "8", "--epochs", "2", "--global-batch", "4", "--micro-batch", "2",
              "--lr", "3e-3", "--val-items", "2", "--limit", "2", "--max-tokens", "8"])
    rec = json.loads((out / "lora" / "finetune.json").read_text())
    assert rec["recipe"]["gradient_checkpointing"] and rec["recipe"]["group_by_length"]
    assert rec["updates"] == 4 and rec["val_loss"] is not None
    assert len(read_jsonl(out / "lora.jsonl")) == len(rows)
    report = json.loads((out / "report.json").read_text())
    for name in ("zero-shot", "lora"):
        s = report[name]["scores"]
        assert s["relation_mcq"]["n"] == 2 and s["contact_mcq"]["n"] == n["contact_mcq"]
        assert report[name]["ask"]["answered"] == len(rows)
    run.main(["fsdp-config", "--processes", "2", "--offload", "--out", str(out / "fsdp.yaml")])
    assert "distributed_type: FSDP" in (out / "fsdp.yaml").read_text()


def test_relation_questions_are_balanced_so_text_cannot_answer(bench):
    """A relation MCQ offers a couple of relations that exclude each other (on / no contact,
    left of / right of, in front of / behind, near / far from) about the marked objects'
    categories and a couple about another category pair (with none asked, an object replaced
    by a category absent from the scene); per split, category pair and couple, as many
    answers are the one relation as the other."""
    couples = {frozenset(c) for c in RELATION_COUPLES}
    for split in ("train", "val", "test"):
        answers: dict[tuple, Counter] = {}
        for r in read_jsonl(bench / f"{split}.jsonl"):
            if r["task"] != "relation_mcq":
                continue
            opts = r["meta"]["options"]
            right = opts["ABCD".index(r["meta"]["answer"])]
            pairs = Counter((o["subject"], o["object"]) for o in opts)
            assert sorted(pairs.values()) == [2, 2], opts
            assert pairs[(right["subject"], right["object"])] == 2, opts
            for pair in pairs:
                assert frozenset(o["relation"] for o in opts
                                 if (o["subject"], o["object"]) == pair) in couples, opts
            assert right["relation"] == r["meta"]["relation"]
            key = (right["subject"], right["object"], frozenset(
                o["relation"] for o in opts if (o["subject"], o["object"])
                == (right["subject"], right["object"])))
            answers.setdefault(key, Counter())[right["relation"]] += 1
        for key, c in answers.items():
            assert len(c) == 2 and len(set(c.values())) == 1, (split, key, c)
    assert sum(1 for r in _all(bench) if r["task"] == "relation_mcq") >= 4


def _candidate(scene, view, a, b, labels, *answers):
    return RelationCandidate(scene, view, a, b, labels, tuple(
        (next(i for i, c in enumerate(RELATION_COUPLES) if r in c), r) for r in answers))


def test_plan_relation_questions_balances_each_category_pair_and_couple():
    """Per category pair (red, blue) and couple, as many questions answer one relation as the
    other; a pair of objects is asked once per view and a view at most ``per_view`` times;
    contact couples choose before the camera-frame sides."""
    cands = []
    for v in range(6):  # six views: the lamp on one nightstand, beside the other
        cands += [_candidate("s", v, "lamp", "ns1", ("table lamp", "nightstand"), "ON", "LEFT_OF"),
                  _candidate("s", v, "lamp", "ns2", ("table lamp", "nightstand"), "NO_CONTACT",
                             "RIGHT_OF"),
                  _candidate("s", v, "ns1", "lamp", ("nightstand", "table lamp"), "NO_CONTACT",
                             "RIGHT_OF")]
    cands += [_candidate("t", 0, "lamp", "ns", ("table lamp", "nightstand"), "ON")]
    plan = plan_relation_questions(cands, per_view=2, rng=np.random.default_rng(0))
    by = Counter((q.key, q.relation) for q in plan)
    on_key = ("table lamp", "nightstand", "ON", "NO_CONTACT")
    assert by[(on_key, "ON")] == by[(on_key, "NO_CONTACT")] == 6
    for q in plan:
        assert {q.relation, q.other} == set(q.key[2:])
    assert len({(q.scene, q.view, frozenset((q.a, q.b))) for q in plan}) == len(plan)
    assert max(Counter((q.scene, q.view) for q in plan).values()) <= 2
    # a category pair with one side only ("the nightstand on the lamp" never holds) is not asked
    assert not any(q.key[:2] == ("nightstand", "table lamp") and q.key[2] == "ON" for q in plan)
    assert plan == plan_relation_questions(cands, per_view=2, rng=np.random.default_rng(0))
