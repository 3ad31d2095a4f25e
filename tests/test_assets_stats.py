"""``parse3d assets stats``: library breadth and depth, measured by generating assets."""

from __future__ import annotations

import json

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.assets.stats import PAPER_CATEGORIES, library_stats
from parse3d.cli import main


def run(capsys, *args):
    with pytest.raises(SystemExit) as e:
        main(list(args))
    out = capsys.readouterr()
    return e.value.code or 0, out.out, out.err


def test_library_stats_measures_what_it_generates() -> None:
    names = ["filing_cabinet", "mug", "dart_board"]
    st = library_stats(names, seeds=2)
    assert st.categories == 3 and st.assets == 6
    assert st.variants == sum(len(registry.get(n).variants) for n in names)
    parts = [len(registry.generate(n, s).parts) for n in names for s in range(2)]
    assert st.parts_per_asset_mean == pytest.approx(np.mean(parts), abs=0.01)
    assert st.parts_per_asset_p10 == pytest.approx(np.percentile(parts, 10), abs=0.01)
    assert "filing_cabinet" in st.articulated_categories and "mug" not in st.articulated_categories
    assert st.per_category["mug"]["joints_mean"] == 0
    assert 0 < st.generation_ms_median <= st.generation_ms_p90


def test_cli_stats_json_and_errors(capsys) -> None:
    code, out, _ = run(capsys, "assets", "stats", "--json", "--seeds", "1", "--categories", "tea_caddy,mug")
    assert code == 0
    data = json.loads(out)
    for key in ("categories", "variants", "parts_per_asset_mean", "parts_per_asset_p10", "articulated_categories",
                "generation_ms_median", "per_category"):
        assert key in data
    assert data["categories"] == 2 and data["paper"]["categories"] == PAPER_CATEGORIES
    ref = data["scannet200"]
    assert ref["object_labels"] == 170 and ref["resolved"] == 170 - len(ref["unresolved"])
    code, out, _ = run(capsys, "assets", "stats", "--categories", "tea_caddy")
    assert code == 0 and "parts per asset" in out and "132" in out
    assert "ScanNet200 object labels resolved" in out
    code, out, err = run(capsys, "assets", "stats", "--categories", "tea_cady")
    assert code == 2 and "did you mean 'tea_caddy'" in out + err


def test_library_reaches_the_papers_breadth() -> None:
    cats = registry.categories()
    procedural = [c for c in cats.values() if c.generator is not None]
    assert len(procedural) >= PAPER_CATEGORIES
    assert all(2 <= len(c.variants) <= 4 for c in procedural if c.name not in ("default",))
