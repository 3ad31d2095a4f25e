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


def _label_boxes(fig):
    """gid -> (x0, y0, x1, y1) pixels of every labelled text of a PAG drawing."""
    r = fig.canvas.get_renderer()
    out = {}
    for t in fig.axes[0].texts:
        if t.get_gid():
            e = t.get_window_extent(r)
            out[t.get_gid()] = (e.x0, e.y0, e.x1, e.y1)
    return out


def _overlap(a, b, pad=0.5):
    return min(a[2], b[2]) - max(a[0], b[0]) > pad and min(a[3], b[3]) - max(a[1], b[1]) > pad


LONG_IDS = {"format": "pag/1", "name": "long-ids",
            "room": {"type": "study", "footprint": [[0, 0], [4, 0], [4, 3], [0, 3]], "height": 2.5},
            "objects": [{"id": "writing_desk_by_the_window", "category": "desk"},
                        {"id": "reading_lamp_of_grandmother", "category": "table_lamp"},
                        {"id": "verylongidentifierwithoutbreaks", "category": "book"}],
            "relations": [
                {"relation": "ON", "child": "writing_desk_by_the_window", "parent": "floor"},
                {"relation": "ON", "child": "reading_lamp_of_grandmother",
                 "parent": "writing_desk_by_the_window:tabletop"},
                {"relation": "ON", "child": "verylongidentifierwithoutbreaks",
                 "parent": "writing_desk_by_the_window:tabletop"},
                {"relation": "NEAR", "child": "verylongidentifierwithoutbreaks",
                 "parent": "reading_lamp_of_grandmother"}]}


@pytest.mark.parametrize("name", ["study.json", "living_room.json", "kitchen.json", "long"])
def test_labels_do_not_overlap_and_names_fit_their_circles(name, tmp_path):
    import json

    import matplotlib.pyplot as plt

    from parse3d.pag.draw import pag_figure

    if name == "long":  # ids too long for one line at the smallest size
        (tmp_path / "long.json").write_text(json.dumps(LONG_IDS))
        pag = load_pag(tmp_path / "long.json")
    else:
        pag = load_pag(ROOT / "examples" / name)
    fig = pag_figure(pag)
    try:
        boxes = _label_boxes(fig)
        movable = [g for g in boxes if g.startswith(("relation:", "part:"))]
        assert len([g for g in movable if g.startswith("relation:")]) == len(pag.relations)
        others = [g for g in boxes if not g.startswith("object:")]
        clashes = [(a, b) for a in movable for b in others
                   if a != b and _overlap(boxes[a], boxes[b])]
        assert not clashes, clashes[:5]
        # every object's id lies inside its circle, whole (wrapped at '_' when long)
        nodes = {p.get_gid(): p for p in fig.axes[0].patches if p.get_gid()}
        r = fig.canvas.get_renderer()
        for oid in pag.objects:
            e = nodes[f"node:{oid}"].get_window_extent(r)
            x0, y0, x1, y1 = boxes[f"object:{oid}"]
            assert e.x0 <= x0 and x1 <= e.x1 and e.y0 <= y0 and y1 <= e.y1, oid
            text = next(t.get_text() for t in fig.axes[0].texts if t.get_gid() == f"object:{oid}")
            assert text.replace("\n", "") == oid
    finally:
        plt.close(fig)
