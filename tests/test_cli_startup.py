"""Start-up of the command line: lazy command modules, light ``validate``, the vocabulary snapshot."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
import typer
from typer.testing import CliRunner

from parse3d.cli import _LAZY, _MODULES, _vocab, app

ROOT = Path(__file__).resolve().parent.parent
STUDY = ROOT / "examples" / "study.json"

#: What a light command must not load (seconds of start-up each).
HEAVY = ("sapien", "torch", "moderngl", "fcl")
#: Also absent once the vocabulary snapshot exists: the asset library's geometry stack.
GEOMETRY = ("trimesh", "shapely", "scipy", "networkx", "numpy")

_PROBE = """
import json, sys
from parse3d.cli import main
code = 0
try:
    main(sys.argv[1:])
except SystemExit as e:
    code = e.code
print(json.dumps({"code": code, "modules": sorted({m.split('.')[0] for m in sys.modules})}))
"""


def _run_cli(args: list[str], cache: Path) -> dict:
    env = {**os.environ, "PARSE3D_CACHE": str(cache),
           "PYTHONPATH": os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")])}
    r = subprocess.run([sys.executable, "-c", _PROBE, *args], capture_output=True, text=True,
                       env=env, cwd=str(ROOT), timeout=300)
    return json.loads(r.stdout.strip().splitlines()[-1])


def test_lazy_table_matches_what_modules_register():
    for module, names in _LAZY.items():
        assert module in _MODULES
        sub = typer.Typer()
        __import__(f"parse3d.cli.{module}", fromlist=["register"]).register(sub)
        got = [c.name for c in sub.registered_commands] + [g.name for g in sub.registered_groups]
        assert sorted(got) == sorted(names), module


def test_validate_does_not_import_heavy_libraries(tmp_path):
    # the first run builds the vocabulary snapshot from the asset registry: trimesh (which
    # loads fcl when installed), never the simulator, the renderer or torch
    cold = _run_cli(["validate", str(STUDY)], tmp_path)
    assert cold["code"] == 0
    assert not {"sapien", "torch", "moderngl"} & set(cold["modules"])
    assert (tmp_path / "vocabulary.json").is_file()
    warm = _run_cli(["validate", str(STUDY)], tmp_path)
    assert warm["code"] == 0
    assert not set(HEAVY + GEOMETRY) & set(warm["modules"]), warm["modules"]
    # a valid file passes the schema's fast structural checks: jsonschema is not needed
    assert "parse3d" in warm["modules"] and "jsonschema" not in warm["modules"]
    # plain parameters are coerced without pydantic; rich and PyYAML load on first use
    assert not {"pydantic", "rich", "yaml"} & set(warm["modules"]), warm["modules"]


def test_plain_parameters_coerce_like_typer(tmp_path):
    from parse3d.cli import _params

    assert _params._to(int, " 42 ") == 42 and _params._to(float, "0.5") == 0.5
    assert _params._to(bool, "Yes") is True and _params._to(bool, "off") is False
    with pytest.raises(ValueError, match="not a valid integer"):
        _params._to(int, "4x")
    runner = CliRunner()
    bad = runner.invoke(app, ["solve", str(STUDY), "--seed", "abc", "--out", str(tmp_path)])
    assert bad.exit_code == 2 and "--seed" in bad.output and "abc" in bad.output
    assert not any(tmp_path.iterdir())
    other = tmp_path / "other.json"
    other.write_text(STUDY.read_text())
    ok = runner.invoke(app, ["validate", "--json", "--no-vocabulary", str(STUDY), str(other)])
    assert ok.exit_code == 0, ok.output
    assert [r["file"] for r in json.loads(ok.output)] == [str(STUDY), str(other)]


def test_snapshot_vocabulary_equals_the_registry(tmp_path, monkeypatch):
    from parse3d.assets.registry import vocabulary

    monkeypatch.setenv("PARSE3D_CACHE", str(tmp_path))
    first = _vocab.cli_vocabulary()
    snap = _vocab.cli_vocabulary()
    assert isinstance(snap, _vocab.SnapshotVocabulary)
    reg = vocabulary()
    assert snap.categories() == reg.categories() == first.categories()
    assert len(snap.categories()) > 50
    for c in reg.categories():
        assert snap.parts(c) == reg.parts(c)
    assert not snap.has_category("no_such_thing")


def test_snapshot_is_stale_when_the_library_changes(tmp_path, monkeypatch):
    monkeypatch.setenv("PARSE3D_CACHE", str(tmp_path))
    _vocab.cli_vocabulary()
    path = tmp_path / _vocab.SNAPSHOT_NAME
    assert _vocab._read(path, _vocab.snapshot_key(tmp_path)) is not None
    folder = tmp_path / "library" / "lamp_post"
    folder.mkdir(parents=True)
    (folder / "category.json").write_text("{}")
    assert _vocab._read(path, _vocab.snapshot_key(tmp_path)) is None
    # a damaged snapshot is ignored, never trusted
    path.write_text("{not json")
    assert _vocab._read(path, _vocab.snapshot_key(tmp_path)) is None


def test_validate_reports_the_same_with_the_snapshot(tmp_path, monkeypatch):
    bad = json.loads(STUDY.read_text())
    bad["objects"][0]["category"] = "dessk"
    f = tmp_path / "bad.json"
    f.write_text(json.dumps(bad))
    cache = tmp_path / "cache"
    cache.mkdir()
    monkeypatch.setenv("PARSE3D_CACHE", str(cache))
    runner = CliRunner()
    first = runner.invoke(app, ["validate", str(f)])
    assert (cache / _vocab.SNAPSHOT_NAME).is_file()
    second = runner.invoke(app, ["validate", str(f)])
    assert first.exit_code == second.exit_code == 2
    assert "did you mean 'desk'" in first.output
    assert first.output == second.output


def _all_commands(group, prefix=()):
    ctx = typer.Context(group)
    for name in group.list_commands(ctx):
        cmd = group.get_command(ctx, name)
        yield (*prefix, name)
        if hasattr(cmd, "list_commands"):
            yield from _all_commands(cmd, (*prefix, name))


def test_every_command_help_completes():
    root = typer.main.get_command(app)
    commands = list(_all_commands(root))
    assert ("validate",) in commands and ("assets", "list") in commands
    assert ("solve",) in commands and ("generate",) in commands
    runner = CliRunner()
    top = runner.invoke(app, ["--help"])
    assert top.exit_code == 0
    for module in _MODULES:
        for name in _LAZY.get(module, ()):
            assert f" {name} " in top.output, name
    for cmd in commands:
        r = runner.invoke(app, [*cmd, "--help"])
        assert r.exit_code == 0, (cmd, r.output)
        assert "Usage:" in r.output, cmd


@pytest.mark.parametrize("args", [["nosuch"], ["validate"]])
def test_unknown_command_and_missing_argument_exit_2(args):
    r = CliRunner().invoke(app, args)
    assert r.exit_code == 2


def _solve_probe(args: list[str]) -> dict:
    """Run ``parse3d`` with ``args`` in a fresh process (the test's own asset cache): exit
    code and the top-level modules it imported."""
    env = {**os.environ,
           "PYTHONPATH": os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")])}
    r = subprocess.run([sys.executable, "-c", _PROBE, *args], capture_output=True, text=True,
                       env=env, cwd=str(ROOT), timeout=600)
    return json.loads(r.stdout.strip().splitlines()[-1])


def test_plain_solve_line_skips_typer_and_solves_the_same(tmp_path):
    from parse3d.pag import PAG, Room

    pag = PAG("tabletop", Room("dining", ((0, 0), (3, 0), (3, 3), (0, 3)), 2.6))
    pag.add("table", "dining_table")
    pag.relate("table", "ON", "floor")
    pag.add("mug", "mug")
    pag.relate("mug", "ON", "table:tabletop")
    src = tmp_path / "tabletop.json"
    src.write_text(json.dumps(pag.to_dict()))
    common = ["--no-settle", "--no-preview", "--json"]
    plain = _solve_probe(["solve", str(src), "--seed", "4", *common, "--out", str(tmp_path / "a")])
    assert plain["code"] == 0
    assert "typer" not in plain["modules"] and "click" not in plain["modules"]
    # ``--seed=4`` is a form only typer reads: the same scene through the full parser
    full = _solve_probe(["solve", str(src), "--seed=4", *common, "-o", str(tmp_path / "b")])
    assert full["code"] == 0 and "typer" in full["modules"]

    def objects(d: Path) -> list:
        return json.loads((d / "scene.json").read_text())["objects"]

    assert objects(tmp_path / "a") == objects(tmp_path / "b")
    assert (tmp_path / "a" / "scene.glb").read_bytes() == (tmp_path / "b" / "scene.glb").read_bytes()


@pytest.mark.parametrize("args, plain", [
    (["solve", "x.json"], True),
    (["solve", "x.json", "--seed", "3", "-o", "out/x", "--no-settle", "--json"], True),
    (["solve", "--time-limit", "2.5", "x.json", "--formats", "glb,obj"], True),
    (["solve", "x.json", "--seed=3"], False),           # typer's own forms
    (["solve", "x.json", "--seed", "+3"], False),
    (["solve", "x.json", "--seed", "3", "--seed", "4"], False),
    (["solve", "x.json", "--help"], False),
    (["solve", "x.json", "--out"], False),              # mistakes: typer says what is wrong
    (["solve", "x.json", "y.json"], False),
    (["solve", "--seed", "3"], False),
    (["solve", "x.json", "--unknown"], False),
    (["generate", "bedroom"], False),
])
def test_which_solve_lines_skip_typer(args, plain):
    from parse3d.cli import _fast

    got = _fast.solve_args(args)
    assert (got is not None) == plain
    if plain:
        assert got["pag_file"] == Path("x.json")
