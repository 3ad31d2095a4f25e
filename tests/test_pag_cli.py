"""The ``parse3d validate`` and ``parse3d pag`` commands, over the broken-PAG corpus."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from parse3d.cli import app, main

ROOT = Path(__file__).parent.parent
BROKEN = Path(__file__).parent / "data" / "broken_pags"
EXPECTED = yaml.safe_load((BROKEN / "expected.yaml").read_text())
EXAMPLE = ROOT / "examples" / "kitchen.json"
PARSE3D = [str(Path(sys.executable).parent / "parse3d")]

runner = CliRunner()


def test_corpus_is_large_and_complete():
    files = {p.name for p in BROKEN.iterdir() if p.name != "expected.yaml"}
    assert len(files) >= 40
    assert files == set(EXPECTED)


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_broken_file_is_reported(name):
    exp = EXPECTED[name]
    res = runner.invoke(app, ["validate", str(BROKEN / name), "--json"])
    assert res.exit_code == exp["exit"], res.output
    (report,) = json.loads(res.stdout)
    assert report["valid"] is False and report["file"] == str(BROKEN / name)
    hits = [e for e in report["errors"]
            if e["pointer"] == exp["pointer"] and all(w in e["message"] for w in exp["words"])]
    assert hits, json.dumps(report["errors"], indent=1)


def test_console_script_prints_lines_and_exits_2_without_traceback():
    files = [BROKEN / "unknown_category.json", BROKEN / "cycle_of_two.json",
             BROKEN / "malformed_json.json", ROOT / "examples" / "nope.json"]
    proc = subprocess.run([*PARSE3D, "validate", *map(str, files)], capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert f"{files[0]}:/objects/0/category: unknown category 'dsk' — did you mean 'desk'?" in lines
    assert any(line.startswith(f"{files[1]}:/relations/10: the relations form a cycle: desk -> "
                               "low_table -> desk") for line in lines)
    assert any(line.startswith(f"{files[2]}:/: invalid JSON at line 7") for line in lines)
    assert f"{files[3]}:/: no such file" in lines


def test_main_maps_input_errors_to_exit_2(capsys):
    with pytest.raises(SystemExit) as e:
        main(["pag", "show", str(BROKEN / "cycle_of_two.json")])
    assert e.value.code == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and "/relations/10: the relations form a cycle" in err


def test_valid_files_print_ok():
    res = runner.invoke(app, ["validate", "--no-vocabulary", str(EXAMPLE),
                              str(ROOT / "examples" / "bathroom.yaml")])
    assert res.exit_code == 0, res.output
    assert res.stdout.splitlines() == [f"{EXAMPLE}: ok", f"{ROOT / 'examples' / 'bathroom.yaml'}: ok"]
    res = runner.invoke(app, ["validate", "--no-vocabulary", "--json", str(EXAMPLE),
                              str(BROKEN / "footprint_clockwise.json")])
    assert res.exit_code == 2
    out = json.loads(res.stdout)
    assert [r["valid"] for r in out] == [True, False] and out[0]["errors"] == []


def test_pag_show_text_and_json():
    res = runner.invoke(app, ["pag", "show", "--no-vocabulary", str(EXAMPLE)])
    assert res.exit_code == 0, res.output
    assert "assembly order:" in res.stdout and "support relations" in res.stdout
    assert "object-level relations" in res.stdout and "kitchen_counter" in res.stdout
    res = runner.invoke(app, ["pag", "show", "--no-vocabulary", "--json", str(EXAMPLE)])
    out = json.loads(res.stdout)
    order = out["assembly_order"]
    assert order.index("counter1") < order.index("fruit_bowl") < order.index("apple0")
    assert {o["id"] for o in out["objects"]} == set(order)
    assert set(out["relations"]) == {"support", "part", "object"}


def test_help_has_examples():
    for cmd in (["validate"], ["pag", "show"], ["pag", "draw"]):
        res = runner.invoke(app, [*cmd, "--help"])
        assert res.exit_code == 0 and "Example" in res.stdout and "parse3d" in res.stdout
