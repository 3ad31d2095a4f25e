"""Room templates and motifs: validation errors, expansion rules, bundled templates, solving."""

from __future__ import annotations

import json
import textwrap
from pathlib import Path

import pytest

from parse3d.datagen.templates import (
    ROOM_TYPES,
    check_template,
    expand_template,
    list_templates,
    load_motif,
    load_template,
    motif_library,
    template_problems,
    template_stats,
)
from parse3d.errors import InputError

MINE = ("bedroom", "living_room", "office", "study", "dormitory", "hotel")


def write(folder: Path, name: str, text: str) -> Path:
    p = folder / name
    p.write_text(textwrap.dedent(text), encoding="utf-8")
    return p


@pytest.fixture()
def motifs(tmp_path):
    """A small motif library of our own: a table with a stack of plates and a picture."""
    d = tmp_path / "motifs"
    d.mkdir()
    write(d, "table_set.yaml", """\
        format: pag-motif/1
        name: table_set
        description: A table with plates stacked on it and a picture on a wall.
        params: {wall: wall_0, height: [1.4, 1.6]}
        objects:
          - {id: table, category: dining_table}
          - {id: plate, category: plate, count: [2, 3]}
          - {id: pic, category: picture_frame, p: 0.0}
        relations:
          - {relation: ON, child: table, parent: floor}
          - {relation: ON, child: plate, parent: "table:tabletop", stack: true}
          - {relation: SECURED_TO, child: "pic:frame@back", parent: $wall, height: $height}
        """)
    return motif_library(d)


BASE = """\
    format: pag-template/1
    name: {name}
    room_type: study
    description: test
    room: {{width: [3.5, 4.0], depth: 3.5, height: 2.7}}
    objects:
      - {{id: desk, category: desk}}
      - {{id: book, category: book, count: [2, 4]}}
      - {{id: lamp, category: table_lamp, p: 0.5}}
      - {{id: mug, category: mug}}
    relations:
      - {{relation: ON, child: desk, parent: floor}}
      - {{relation: AGAINST, child: "desk:tabletop@back", parent: wall_0}}
      - {{relation: ON, child: "book:back_cover@back", parent: "desk:tabletop", stack: true}}
      - {{relation: ON, child: lamp, parent: "desk:tabletop"}}
      - {{relation: ON, child: mug, parent: "lamp:base"}}
      - {{relation: NEAR, child: desk, parent: wall_1, distance: 2.0}}
    motifs:
      - {{motif: table_set, prefix: ts, params: {{wall: wall_2}}}}
    """


def test_valid_small_template_expands_with_rules(tmp_path, motifs):
    t = load_template(write(tmp_path, "small-01.yaml", BASE.format(name="small-01")),
                      motifs=motifs)
    seen_lamp = set()
    for seed in range(12):
        pag = expand_template(t, seed)
        d = pag.to_dict()
        assert d["name"] == f"small-01-s{seed}"
        assert d["meta"] == {"template": "small-01", "seed": seed}
        ids = [o["id"] for o in d["objects"]]
        books = [i for i in ids if i.startswith("book_")]
        assert 2 <= len(books) <= 4 and books == [f"book_{k}" for k in range(len(books))]
        rel = {(r["child"], r["parent"]) for r in d["relations"]}
        # stack: copy 0 on the desk, copy k on copy k-1 (the face opposite the child's)
        assert ("book_0:back_cover@back", "desk:tabletop") in rel
        for k in range(1, len(books)):
            assert (f"book_{k}:back_cover@back", f"book_{k - 1}@front") in rel
        # motif: prefixed ids and references, parameters substituted, p=0 object absent
        assert "ts_table" in ids and "ts_pic" not in ids
        plates = [i for i in ids if i.startswith("ts_plate_")]
        assert ("ts_plate_0", "ts_table:tabletop") in rel
        assert all((f"ts_plate_{k}", f"ts_plate_{k - 1}") in rel for k in range(1, len(plates)))
        # optional lamp: when absent, the mug it supports goes too
        seen_lamp.add("lamp" in ids)
        assert ("mug" in ids) == ("lamp" in ids)
        assert all(r["child"].split(":")[0].split("@")[0] in ids for r in d["relations"])
        w = d["room"]["footprint"][1][0]
        assert 3.5 <= w <= 4.0 and d["room"]["footprint"][2][1] == 3.5
    assert seen_lamp == {True, False}
    # deterministic
    assert expand_template(t, 5).to_dict() == expand_template(t, 5).to_dict()
    assert expand_template(t, 5).to_dict() != expand_template(t, 6).to_dict()


def test_l_room_and_paired_repeats(tmp_path, motifs):
    text = """\
        format: pag-template/1
        name: paired-01
        room_type: dining_room
        room: {width: 5, depth: 4.5, height: 2.7, shape: L, notch: {width: 1.2, depth: 1.0}}
        objects:
          - {id: table, category: dining_table}
          - {id: chair, category: dining_chair, count: [2, 4]}
          - {id: plate, category: plate, count: [2, 4]}
        relations:
          - {relation: ON, child: table, parent: floor}
          - {relation: ON, child: chair, parent: floor}
          - {relation: TOWARD, child: chair, parent: table}
          - {relation: ON, child: plate, parent: "table:tabletop"}
          - {relation: NEAR, child: plate, parent: chair, distance: 0.9}
          - {relation: SIDE_OF, child: table, parent: wall_5, side: front}
        """
    t = load_template(write(tmp_path, "paired-01.yaml", text), motifs=motifs)
    d = expand_template(t, 1).to_dict()
    assert d["room"]["footprint"] == [[0, 0], [5, 0], [5, 3.5], [3.8, 3.5], [3.8, 4.5], [0, 4.5]]
    chairs = [o["id"] for o in d["objects"] if o["id"].startswith("chair_")]
    plates = [o["id"] for o in d["objects"] if o["id"].startswith("plate_")]
    assert len(chairs) == len(plates)
    near = {(r["child"], r["parent"]) for r in d["relations"] if r["relation"] == "NEAR"}
    assert near == {(f"plate_{k}", f"chair_{k}") for k in range(len(chairs))}


BROKEN = {
    # name: (text edit, expected pointer, fragment of the message)
    "schema-key": (("{id: mug, category: mug}", "{id: mug, categroy: mug}"),
                   "/objects/3/categroy", "did you mean 'category'"),
    "room-type": (("room_type: study", "room_type: studdy"), "/room_type",
                  "did you mean 'study'"),
    "unknown-motif": (("motif: table_set", "motif: table_sett"), "/motifs/0/motif",
                      "did you mean 'table_set'"),
    "unknown-param": (("params: {wall: wall_2}", "params: {wal: wall_2}"),
                      "/motifs/0/params/wal", "did you mean 'wall'"),
    "count-range": (("count: [2, 4]", "count: [4, 2]"), "/objects/1/count", "above high"),
    "count-negative": (("count: [2, 4]", "count: [-1, 2]"), "/objects/1/count/0", ""),
    "p-range": (("p: 0.5", "p: 1.5"), "/objects/2/p", ""),
    "repeated-parent": (('child: mug, parent: "lamp:base"', "child: mug, parent: book"),
                        "/relations/4/parent", "is repeated"),
    "duplicate-after-expansion": (("{id: mug, category: mug}", "{id: ts_table, category: mug}"),
                                  "/motifs/0/prefix", "made twice"),
    "unknown-category": (("category: desk}", "category: dessk}"), "/objects/0/category",
                         "did you mean 'desk'"),
    "unknown-part": (("parent: \"desk:tabletop\", stack", "parent: \"desk:tabeltop\", stack"),
                     "/relations/2/parent", "tabletop"),
    "bad-wall": (("parent: wall_1, distance", "parent: wall_7, distance"),
                 "/relations/5/parent", "wall_7"),
    "param-outside-motif": (("parent: wall_1, distance", "parent: $wall, distance"),
                            "/relations/5/parent", "only be used inside motifs"),
    "name-mismatch": (("name: name-mismatch", "name: other-name"), "/name", "name the file"),
}


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_broken_templates_give_pointed_input_errors(tmp_path, motifs, case):
    (old, new), pointer, fragment = BROKEN[case]
    text = BASE.format(name=case)
    assert old in text
    text = text.replace(old, new)
    path = write(tmp_path, f"{case}.yaml", text)
    with pytest.raises(InputError) as e:
        load_template(path, motifs=motifs)
    ptrs = {p.pointer for p in e.value.problems}
    assert pointer in ptrs, str(e.value)
    p = next(p for p in e.value.problems if p.pointer == pointer)
    assert fragment in p.message
    assert str(p).startswith(f"{path}:{pointer}: ")


def test_motif_errors_point_into_the_motif_file(tmp_path):
    d = tmp_path / "m"
    d.mkdir()
    p = write(d, "bad.yaml", """\
        format: pag-motif/1
        name: bad
        params: {wall: wall}
        objects:
          - {id: desk, category: desk}
        relations:
          - {relation: ON, child: desk, parent: floor}
          - {relation: AGAINST, child: "desk@back", parent: $wal}
          - {relation: NEAR, child: desk, parent: deks, distance: 1.0}
        """)
    with pytest.raises(InputError) as e:
        load_motif(p)
    msgs = {(q.pointer, q.message) for q in e.value.problems}
    assert any(ptr == "/relations/1/parent" and "did you mean 'wall'" in m for ptr, m in msgs)
    assert any(ptr == "/relations/2/parent" and "did you mean 'desk'" in m for ptr, m in msgs)


def test_motif_category_error_maps_to_motif_line(tmp_path, motifs):
    d = tmp_path / "m2"
    d.mkdir()
    write(d, "odd.yaml", """\
        format: pag-motif/1
        name: odd
        objects:
          - {id: thing, category: tabel}
        relations:
          - {relation: ON, child: thing, parent: floor}
        """)
    lib = motif_library(d)
    text = BASE.replace("motif: table_set, prefix: ts, params: {{wall: wall_2}}",
                        "motif: odd, prefix: o").format(name="uses-odd")
    path = write(tmp_path, "uses-odd.yaml", text)
    problems = template_problems(_read(path), file=str(path), motifs=lib)
    assert any(p.file.endswith("odd.yaml") and p.pointer == "/objects/0/category"
               and "used at /motifs/0" in p.message for p in problems)


def _read(path: Path):
    from parse3d.pag.io import read_document

    return read_document(path)


def test_unknown_names_and_room_types():
    with pytest.raises(InputError, match="did you mean"):
        list_templates("bedrom")
    with pytest.raises(InputError, match="no template file or bundled template"):
        load_template("no-such-template-anywhere")
    with pytest.raises(InputError, match="non-negative"):
        expand_template(list_templates("study")[0], -1)


@pytest.mark.parametrize("room_type", MINE)
def test_bundled_templates_expand_to_valid_dense_pags(room_type):
    ts = list_templates(room_type)
    assert len(ts) >= 12
    assert len({t.name for t in ts}) == len(ts)
    n_objects = []
    for t in ts:
        assert Path(t.file).stem == t.name and t.room_type == room_type
        for seed in (0, 1):
            pag = expand_template(t, seed)  # validated against the asset vocabulary
            assert pag.room.type == room_type
            n_objects.append(len(pag.objects))
        st = template_stats(t, (0, 1))
        assert all(12 <= a <= 35 for a in st.area), (t.name, st.area)
    assert sum(n_objects) / len(n_objects) >= 50


def test_every_room_type_is_known_and_motifs_load():
    assert len(ROOM_TYPES) == 17
    lib = motif_library()
    for name in ("desk_setup", "bookcase_with_books", "counter_run", "bed_with_nightstands",
                 "sofa_corner", "dining_set", "wall_art", "pendant_lights", "reading_nook",
                 "tv_wall", "bathroom_vanity_set", "meeting_table_set"):
        assert name in lib


def test_cli_list_expand_check(tmp_path):
    from typer.testing import CliRunner

    from parse3d.cli import app

    runner = CliRunner()
    r = runner.invoke(app, ["template", "list", "--room-type", "hotel", "--json"])
    assert r.exit_code == 0, r.output
    names = [x["name"] for x in json.loads(r.stdout)]
    assert len(names) >= 12
    out = tmp_path / "room.json"
    r = runner.invoke(app, ["template", "expand", names[0], "--seed", "2", "-o", str(out)])
    assert r.exit_code == 0, r.output
    assert json.loads(out.read_text())["name"] == f"{names[0]}-s2"
    r = runner.invoke(app, ["template", "expand", names[0], "--seed", "2"])
    assert json.loads(r.stdout) == json.loads(out.read_text())


@pytest.mark.slow
@pytest.mark.parametrize("name", ["study-compact-06", "hotel-deluxe-02"])
def test_bundled_templates_solve(name):
    t = load_template(name)
    r = check_template(t, (0,))
    assert r.placed_fraction >= 0.9, r.failures
