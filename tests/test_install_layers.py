"""Install in layers: a plain ``pip install parse3d`` validates, draws, solves and exports glTF;
every command that needs an extra says which one, in one line, with exit code 2.

The optional packages are made unimportable in a subprocess (a finder at the head of
``sys.meta_path`` refuses them), which is what a venv without the extras looks like to parse3d.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
import tomllib

from parse3d._deps import EXTRAS, FORMAT_MODULES

ROOT = Path(__file__).resolve().parent.parent
TINY = ROOT / "tests" / "hostile" / "data" / "tiny.json"

#: Every optional module (and the big libraries they bring): none may be needed by the base.
BLOCKED = sorted(set(EXTRAS) | {"glcontext", "tokenizers", "huggingface_hub", "bpy"})

#: Distribution names of the optional packages, which the base dependencies must not name.
HEAVY_DISTS = ("torch", "ray", "diffusers", "transformers", "playwright", "sapien", "moderngl",
               "mujoco", "usd-core", "pyarrow", "coacd", "fastapi", "uvicorn", "peft")

_RUNNER = """
import contextlib, importlib.abc, io, json, sys

BLOCKED = set(json.loads(sys.argv[1]))
tried = set()

class Refuse(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        top = name.split(".")[0]
        if top in BLOCKED:
            tried.add(top)
            raise ModuleNotFoundError(f"No module named {name!r}", name=name)
        return None

sys.meta_path.insert(0, Refuse())
from parse3d.cli import main

results = []
for argv in json.loads(sys.argv[2]):
    out, err = io.StringIO(), io.StringIO()
    code = 0
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            main(argv)
        except SystemExit as e:
            code = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
        except BaseException as e:  # a traceback is what the user must never get
            code = "traceback: " + repr(e)
    results.append({"argv": argv, "code": code, "out": out.getvalue(), "err": err.getvalue()})
print(json.dumps(results))
"""


def _run_blocked(commands: list[list[str]], work: Path) -> list[dict]:
    env = {**os.environ, "PARSE3D_CACHE": str(work / "cache"), "COLUMNS": "200", "NO_COLOR": "1",
           "PYTHONPATH": os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")])}
    r = subprocess.run([sys.executable, "-c", _RUNNER, json.dumps(BLOCKED), json.dumps(commands)],
                       capture_output=True, text=True, env=env, cwd=str(work), timeout=600)
    assert r.returncode == 0, r.stderr[-3000:]
    return json.loads(r.stdout.strip().splitlines()[-1])


def test_base_dependencies_hold_no_optional_package():
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    base = " ".join(meta["dependencies"]).lower()
    for dist in HEAVY_DISTS:
        assert not re.search(rf"(^|[\s\[,]){re.escape(dist)}([\s<>=\[,;]|$)", base), dist
    extras = meta["optional-dependencies"]
    # every extra a message names exists; `all` includes each of them
    for extra in set(EXTRAS.values()):
        assert extra in extras, extra
        assert extra in extras["all"][0], extra
    # the demo extra holds what `parse3d demo` requires: settling and the preview
    assert set(extras["demo"][0].split("[")[1].rstrip("]").split(",")) == {"physics", "render"}


@pytest.fixture(scope="module")
def blocked_runs(tmp_path_factory):
    work = tmp_path_factory.mktemp("layers")
    light = [
        ["validate", str(TINY)],
        ["pag", "draw", str(TINY), "-o", "pag.png"],
        ["solve", str(TINY), "--seed", "0", "--out", "light", "--no-settle", "--no-preview",
         "--formats", "glb,obj"],
        ["export", "light", "--format", "obj", "-o", "light-obj"],
    ]
    heavy = {
        "solve": (["solve", str(TINY), "--out", "heavy-solve"], "physics", "heavy-solve"),
        "preview": (["solve", str(TINY), "--out", "heavy-prev", "--no-settle"], "render",
                    "heavy-prev"),
        "usd": (["solve", str(TINY), "--out", "heavy-usd", "--no-settle", "--no-preview",
                 "--formats", "glb,usd"], "export", "heavy-usd"),
        "generate": (["generate", "bedroom", "--out", "heavy-gen"], "physics", "heavy-gen"),
        "settle": (["settle", "light"], "physics", None),
        "render": (["render", "light"], "render", None),
        "export-usd": (["export", "light", "--format", "usd", "-o", "heavy-export"], "export",
                       "heavy-export"),
        "export-sim": (["export", "light", "--format", "mjcf,urdf", "-o", "heavy-sim"], "export",
                       "heavy-sim"),
        "demo": (["demo", "--out", "heavy-demo"], "physics", "heavy-demo"),
        "demo-no-settle": (["demo", "--out", "heavy-demo2", "--no-settle"], "render",
                           "heavy-demo2"),
        "assets-render": (["assets", "render", "desk", "-o", "desk.png"], "render", "desk.png"),
        "assets-gallery": (["assets", "gallery", "-o", "gallery.png", "--categories", "desk"],
                           "render", "gallery.png"),
        "dataset": (["dataset", "build", "--scenes", "1", "--out", "heavy-ds"], "dataset",
                    "heavy-ds"),
        "dataset-stats": (["dataset", "stats", "heavy-ds"], "dataset", "heavy-ds"),
        "layout": (["layout", "train", "heavy-ds", "--out", "heavy-run"], "ml", "heavy-run"),
        "vlm-finetune": (["vlm", "finetune", "--model", "m", "--data", "d", "--out", "heavy-lora"],
                         "ml", "heavy-lora"),
        "vlm-ask-local": (["vlm", "ask", "--local", "m", "--data", "d.jsonl", "--out",
                           "heavy-ask.jsonl"], "ml", "heavy-ask.jsonl"),
        "serve": (["serve", "--port", "0"], "web", None),
    }
    runs = _run_blocked(light + [argv for argv, _, _ in heavy.values()], work)
    return work, runs[:len(light)], dict(zip(heavy, zip(runs[len(light):], heavy.values(),
                                                         strict=True), strict=True))


def test_light_path_runs_without_any_extra(blocked_runs):
    work, light, _ = blocked_runs
    for r in light:
        assert r["code"] == 0, (r["argv"], r["err"][-2000:])
    assert (work / "pag.png").stat().st_size > 1000
    for f in ("scene.json", "scene.glb", "scene.obj"):
        assert (work / "light" / f).stat().st_size > 100, f
    assert (work / "light-obj" / "scene.obj").stat().st_size > 100
    scene = json.loads((work / "light" / "scene.json").read_text())
    assert [o["status"] for o in scene["objects"]] == ["placed", "placed"]


@pytest.mark.parametrize("case", ["solve", "preview", "usd", "generate", "settle", "render",
                                  "export-usd", "export-sim", "demo", "demo-no-settle", "assets-render",
                                  "assets-gallery", "dataset", "dataset-stats", "layout",
                                  "vlm-finetune", "vlm-ask-local", "serve"])
def test_missing_extra_is_one_line_naming_it(blocked_runs, case):
    work, _, heavy = blocked_runs
    r, (_, extra, output) = heavy[case]
    assert r["code"] == 2, (r["argv"], r["code"], r["err"][-2000:])
    lines = [ln for ln in r["err"].splitlines() if ln.strip()]
    assert len(lines) == 1, r["err"]
    assert f"pip install 'parse3d[{extra}]'" in lines[0], lines[0]
    assert "Traceback" not in r["err"] + r["out"]
    if output is not None:  # named before any work: nothing written
        assert not (work / output).exists(), output


def test_every_format_module_has_an_extra():
    for modules in FORMAT_MODULES.values():
        for m in modules:
            assert m in EXTRAS
