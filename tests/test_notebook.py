"""``examples/quickstart.ipynb`` runs top to bottom.

Its code cells are executed in order in one fresh Python process (what a kernel does, without
a Jupyter install), in an empty folder, with ``$BROWSER`` set to a command that opens nothing
so that ``scene.show()`` writes its page and returns.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK = ROOT / "examples" / "quickstart.ipynb"


def code_cells() -> list[str]:
    nb = json.loads(NOTEBOOK.read_text())
    assert nb["nbformat"] == 4
    cells = [c for c in nb["cells"] if c["cell_type"] == "code"]
    # kept without outputs, so that diffs show the code
    assert all(not c["outputs"] and c["execution_count"] is None for c in cells)
    return ["".join(c["source"]) for c in cells]


def test_notebook_covers_the_first_hour():
    src = "\n".join(code_cells())
    for call in ("parse3d.load_pag(", ".validate()", "parse3d.solve(", "scene.show()",
                 "scene.save(", "parse3d.load_scene(", "scene.export(", "scene.render("):
        assert call in src, call


def test_notebook_runs_top_to_bottom(tmp_path):
    pytest.importorskip("moderngl")
    script = "\n\n".join(f"# --- cell {k}\n{c}" for k, c in enumerate(code_cells()))
    env = {**os.environ, "BROWSER": "true", "TMPDIR": str(tmp_path),
           "PYTHONPATH": os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")])}
    work = tmp_path / "work"
    work.mkdir()
    r = subprocess.run([sys.executable, "-c", script], cwd=work, env=env, capture_output=True,
                       text=True, timeout=600)
    assert r.returncode == 0, r.stderr[-3000:]
    assert "objects placed" in r.stdout and "exported" in r.stdout
    out = work / "out" / "quickstart"
    assert json.loads((out / "scene.json").read_text())["format"].startswith("parse3d-scene/")
    assert (out / "study.glb").read_bytes()[:4] == b"glTF"
    assert (out / "mjcf" / "study.xml").read_text().lstrip().startswith("<mujoco")
    image = np.asarray(Image.open(out / "render.png"))
    assert image.shape == (480, 640, 3) and image.std() > 5
    # scene.show() outside Jupyter wrote the viewer page
    pages = list(tmp_path.glob("parse3d-scene-*.html"))
    assert len(pages) == 1 and "three" in pages[0].read_text()[:200000].lower()
