"""``parse3d assets``: list, show, render, add, build — and their exit codes."""

from __future__ import annotations

import json

import pytest
import trimesh
from PIL import Image

from parse3d.assets import registry
from parse3d.cli import main


def run(capsys, *args):
    with pytest.raises(SystemExit) as e:
        main(list(args))
    out = capsys.readouterr()
    return e.value.code or 0, out.out, out.err


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("PARSE3D_CACHE", str(tmp_path / "cache"))
    registry.categories()
    saved = dict(registry._REGISTRY)
    yield tmp_path / "cache"
    registry._REGISTRY.clear()
    registry._REGISTRY.update(saved)


def test_list_json(capsys):
    code, out, _ = run(capsys, "assets", "list", "--json")
    assert code == 0
    rows = json.loads(out)
    by = {r["category"]: r for r in rows}
    assert set(by) == set(registry.categories())
    assert {"body", "handle"} <= set(by["mug"]["parts"])
    lo, hi = by["desk"]["size_range"]
    assert 0 < lo < hi


def test_show_json_and_text(capsys):
    code, out, _ = run(capsys, "assets", "show", "mug", "--seed", "2", "--json")
    assert code == 0
    data = json.loads(out)
    assert data["asset_id"] == registry.generate("mug", 2).asset_id
    body = next(p for p in data["parts"] if p["label"] == "body")
    assert set(body["surfaces"]) == {"top", "bottom", "front", "back", "left", "right"}
    assert body["surfaces"]["top"]["normal"] == [0.0, 0.0, 1.0]
    assert data["internal"] and data["internal"][0]["part"] == "body"
    code, out, _ = run(capsys, "assets", "show", "desk", "--seed", "0")
    assert code == 0 and "tabletop" in out


def test_unknown_category_exits_2_with_a_suggestion(capsys):
    code, _, err = run(capsys, "assets", "show", "mugg")
    assert code == 2
    assert "unknown category 'mugg'" in err and "did you mean 'mug'" in err
    assert "Traceback" not in err


def test_render_writes_a_picture(tmp_path, capsys):
    out = tmp_path / "mug.png"
    code, _, _ = run(capsys, "assets", "render", "mug", "--seed", "1", "-o", str(out))
    assert code == 0
    img = Image.open(out).convert("RGB")
    assert img.size[0] >= 300
    colours = img.resize((64, 64)).getcolors(64 * 64)
    assert len(colours) > 10  # something was drawn, not a blank canvas


def test_add_bad_folder_exits_2(tmp_path, capsys, cache):
    code, _, err = run(capsys, "assets", "add", str(tmp_path / "nope"), "--category", "thing")
    assert code == 2 and "folder not found" in err
    (tmp_path / "empty").mkdir()
    code, _, err = run(capsys, "assets", "add", str(tmp_path / "empty"), "--category", "thing")
    assert code == 2 and "no .glb/.gltf files" in err
    code, _, err = run(capsys, "assets", "add", str(tmp_path / "empty"), "--category", "thing",
                       "--size-range", "big")
    assert code == 2 and "--size-range" in err


def test_add_then_list(tmp_path, capsys, cache):
    src = tmp_path / "src"
    src.mkdir()
    sc = trimesh.Scene()
    for name, (w, h, z) in {"shade": (0.3, 0.2, 0.5), "base": (0.15, 0.4, 0.2)}.items():
        m = trimesh.creation.box((w, h, w))
        m.apply_translation((0, z, 0))  # glTF: +Y up
        sc.add_geometry(m, node_name=name, geom_name=name)
    sc.export(src / "lamp.glb")
    code, out, err = run(capsys, "assets", "add", str(src), "--category", "test_lamp",
                         "--size-range", "0.3,0.8", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["parts"] == ["base", "shade"] and data["size_range"] == [0.3, 0.8]
    assert (cache / "library" / "test_lamp" / "category.json").is_file()
    from parse3d.assets.loaders import register_library

    register_library(cache / "library")  # what the next start-up does
    code, out, _ = run(capsys, "assets", "list", "--json")
    lamp = next(r for r in json.loads(out) if r["category"] == "test_lamp")
    assert lamp["parts"] == ["base", "shade"] and lamp["source"].endswith("test_lamp")


def test_gallery_writes_a_contact_sheet(capsys, tmp_path):
    """The documented ``parse3d assets gallery`` (``make gallery``): its progress bar runs on
    the CLI's lazily made console and a PNG of the asked categories comes out."""
    out = tmp_path / "gallery.png"
    code, stdout, err = run(capsys, "assets", "gallery", "--categories", "mug,plate", "--seeds", "2",
                            "--out", str(out))
    assert code == 0, err
    assert "2 categories x 2 seeds" in stdout
    img = Image.open(out)
    assert img.width > 100 and img.height > 100
    assert len(set(img.convert("RGB").getdata())) > 10  # something was drawn


def test_words_lists_synonyms_and_hypernyms(capsys):
    code, out, _ = run(capsys, "assets", "words", "--json")
    assert code == 0
    rows = {r["word"]: r for r in json.loads(out)}
    assert rows["couch"] == {"word": "couch", "kind": "synonym", "categories": ["sofa"]}
    assert rows["chair"]["kind"] == "hypernym"
    assert {"chair", "armchair", "office_chair"} <= set(rows["chair"]["categories"])
    cats = set(registry.categories())
    assert all(set(r["categories"]) <= cats for r in rows.values())


def test_words_looks_up_words_and_part_references(capsys):
    code, out, _ = run(capsys, "assets", "words", "Couches", "desks", "table:top@top",
                       "book:cover@front", "--json")
    assert code == 0
    couch, desk, top, cover = json.loads(out)
    assert couch["kind"] == "synonym" and couch["categories"] == ["sofa"]
    assert "seat_cushion" in couch["part_words"]["sofa"]
    assert desk["kind"] == "category" and desk["categories"] == ["desk"]
    assert top["kind"] == "hypernym" and top["part"]["desk"] == "tabletop"
    assert set(top["part"]) == set(top["categories"])
    assert cover["part"] == {"book": "front_cover"}
    code, out, _ = run(capsys, "assets", "words", "throw")
    assert code == 0 and "throw: a synonym of blanket" in out


def test_words_that_name_nothing_exit_2_with_what_to_write(capsys):
    code, out, err = run(capsys, "assets", "words", "book:cover", "mugg")
    assert code == 2
    assert "write cover@front or cover@back" in out
    assert "no category 'mugg'" in out and "did you mean 'mug'" in out
    assert "Traceback" not in out + err


def test_show_tells_which_parts_differ_between_variants(capsys):
    """A writer picking `shelf#k` or `door` sees how many each draw of the category may have
    (seeds of every variant), not only the one asset shown."""
    code, out, _ = run(capsys, "assets", "show", "bookcase", "--json")
    assert code == 0
    spread = json.loads(out)["variant_parts"]
    counts = {v: [sum(p.label == "door" for p in registry.generate("bookcase", s, v).parts)
                  for s in range(3)] for v in registry.get("bookcase").variants}
    assert spread["door"]["min"] == min(min(c) for c in counts.values())
    assert spread["door"]["max"] == max(max(c) for c in counts.values())
    assert spread["door"]["variants"] == [v for v, c in counts.items() if any(c)]
    assert "open" not in spread["door"]["variants"]
    code, out, _ = run(capsys, "assets", "show", "bookcase")
    assert code == 0 and "parts that differ between assets" in out
