"""Drawing PAGs to PNG and SVG."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from parse3d.errors import InputError
from parse3d.pag import load_pag
from parse3d.pag.draw import draw_pag, layout_pag

ROOT = Path(__file__).parent.parent


def test_draw_png_and_svg(tmp_path):
    small = load_pag(ROOT / "examples" / "bathroom.yaml")
    big = load_pag(ROOT / "examples" / "living_room.json")
    a = draw_pag(small, tmp_path / "small.png")
    b = draw_pag(big, tmp_path / "big.png")
    ia, ib = np.asarray(Image.open(a).convert("L")), np.asarray(Image.open(b).convert("L"))
    assert ib.shape[1] > ia.shape[1]  # the figure grows with the graph
    assert (ia < 100).mean() > 0.01 and (ia > 240).mean() > 0.5  # ink on a white page
    svg = draw_pag(small, tmp_path / "small.svg").read_text()
    assert svg.startswith("<?xml") and "<svg" in svg
    assert "HANGING_BELOW" in svg and "towel_bar" in svg


def test_layout_layers_follow_support_depth():
    pag = load_pag(ROOT / "examples" / "kitchen.json")
    pos = layout_pag(pag)
    assert pos["floor"][1] == 0.0
    assert pos["counter1"][1] < pos["fruit_bowl"][1] < pos["apple0"][1]
    assert len({tuple(p) for p in pos.values()}) == len(pos)  # no two nodes on one spot


def test_draw_rejects_other_formats(tmp_path):
    with pytest.raises(InputError, match="use .png or .svg"):
        draw_pag(load_pag(ROOT / "examples" / "bathroom.yaml"), tmp_path / "x.jpg")
