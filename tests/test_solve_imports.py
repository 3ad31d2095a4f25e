"""A whole ``parse3d solve --no-settle --no-preview`` with its assets cached imports neither
scipy nor jsonschema (nor trimesh), and writes the scene it always wrote."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

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

PAG = {"format": "pag/1", "name": "two",
       "room": {"type": "dining", "footprint": [[0, 0], [3, 0], [3, 3], [0, 3]], "height": 2.7},
       "objects": [{"id": "t", "category": "dining_table"}, {"id": "m", "category": "mug"}],
       "relations": [{"relation": "ON", "child": "t", "parent": "floor"},
                     {"relation": "ON", "child": "m", "parent": "t:tabletop"}]}


def _solve(pag: Path, out: Path, cache: Path) -> dict:
    env = {**os.environ, "PARSE3D_CACHE": str(cache), "PYTHONPATH": str(ROOT / "src")}
    r = subprocess.run([sys.executable, "-c", _PROBE, "solve", str(pag), "--seed", "3",
                        "--no-settle", "--no-preview", "--json", "--out", str(out)],
                       capture_output=True, text=True, env=env, cwd=str(ROOT), timeout=600)
    return json.loads(r.stdout.strip().splitlines()[-1])


def test_cached_solve_imports_no_scipy_or_jsonschema(tmp_path):
    pag = tmp_path / "two.json"
    pag.write_text(json.dumps(PAG))
    cold = _solve(pag, tmp_path / "a", tmp_path / "cache")  # snapshot and assets made here
    assert cold["code"] == 0
    warm = _solve(pag, tmp_path / "b", tmp_path / "cache")
    assert warm["code"] == 0
    assert "fcl" in warm["modules"] and "shapely" in warm["modules"]
    assert not {"scipy", "jsonschema", "trimesh"} & set(warm["modules"]), warm["modules"]
    a, b = (json.loads((tmp_path / d / "scene.json").read_text()) for d in ("a", "b"))
    assert [o["pose"] for o in a["objects"]] == [o["pose"] for o in b["objects"]]
    assert (tmp_path / "b" / "scene.glb").read_bytes() == (tmp_path / "a" / "scene.glb").read_bytes()
