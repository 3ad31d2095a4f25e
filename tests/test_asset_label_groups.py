"""Group labels: where a category's one part was split into finer parts, its old label still
names the same geometry (the parts it covers), in the vocabulary, in ``#k`` order, through the
asset cache and in a PAG's references."""

from __future__ import annotations

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.assets.cache import load_asset, save_asset
from parse3d.pag.validate import validate_data

SPLIT = {  # category: the labels its ``body`` covers now
    "plate": {"well", "rim", "foot_ring"},
    "pillow": {"cover", "piping", "tag", "zipper", "zip_pull"},
    "rug": {"field", "border", "medallion", "motif"},
}


@pytest.mark.parametrize("category", sorted(SPLIT))
def test_old_label_names_every_sub_part(category: str) -> None:
    cat = registry.get(category)
    assert "body" in cat.vocabulary and SPLIT[category] <= set(cat.vocabulary)
    a = registry.generate(category, 0)
    covered = a.parts_by_label("body")
    assert {p.label for p in covered} == SPLIT[category]
    # the group covers the whole asset but the decorations a PAG never meant by ``body``
    names = {p.name for p in covered}
    assert names == {p.name for p in a.parts if p.label != "fringe"}
    # its bbox is the old part's: the asset's extent in x and y
    lo = np.min([p.bounds[0] for p in covered], axis=0)
    hi = np.max([p.bounds[1] for p in covered], axis=0)
    if category != "rug":
        np.testing.assert_allclose([lo, hi], a.bounds, atol=1e-9)
    assert hi[2] == pytest.approx(a.bounds[1, 2])


def test_group_labels_survive_the_asset_cache(tmp_path) -> None:
    a = registry.generate("plate", 1)
    save_asset(a, tmp_path / "plate.npz")
    b = load_asset(tmp_path / "plate.npz")
    assert [p.name for p in b.parts_by_label("body")] == [p.name for p in a.parts_by_label("body")]


def test_a_pag_may_name_old_and_new_labels() -> None:
    data = {
        "format": "pag/1", "name": "table-for-one",
        "room": {"type": "dining_room", "footprint": [[0, 0], [3, 0], [3, 3], [0, 3]], "height": 2.6},
        "objects": [{"id": "table", "category": "dining_table"}, {"id": "plate", "category": "plate"},
                    {"id": "cup", "category": "cup"}],
        "relations": [
            {"relation": "ON", "child": "table", "parent": "floor"},
            {"relation": "ON", "child": "plate:body", "parent": "table:tabletop"},
            {"relation": "ON", "child": "cup:base", "parent": "table:tabletop"},
            {"relation": "PARALLEL_TO", "child": "cup:rim", "parent": "plate:rim"},
        ],
    }
    assert validate_data(data, vocabulary=registry.vocabulary()) == []
    bad = dict(data, relations=data["relations"] + [
        {"relation": "PARALLEL_TO", "child": "cup:saucer", "parent": "plate:well"}])
    assert any("saucer" in str(p) for p in validate_data(bad, vocabulary=registry.vocabulary()))


CARCASSES = ("nightstand", "dresser", "wardrobe", "bathroom_vanity", "hutch", "locker", "sideboard")


@pytest.mark.parametrize("category", CARCASSES)
def test_a_carcass_body_is_its_panels(category: str) -> None:
    """A case good's one-piece ``body`` became its panels: ``body`` names them all (two sides or
    partitions at least, a bottom or plinth), the part named body that doors and drawers hang on
    is one of them, and the group spans the carcass: the asset's width, from its back."""
    for variant in registry.get(category).variants:
        a = registry.generate(category, 0, variant)
        covered = a.parts_by_label("body")
        labels = {p.label for p in covered}
        assert len(covered) >= 4 and len(labels) >= 3, (a.asset_id, labels)
        assert a.part("body") in covered
        lo = np.min([p.bounds[0] for p in covered], axis=0)
        hi = np.max([p.bounds[1] for p in covered], axis=0)
        # the panels span the carcass: across the asset's width, from its back
        assert hi[0] - lo[0] >= 0.9 * (a.bounds[1, 0] - a.bounds[0, 0]), a.asset_id
        assert lo[1] == pytest.approx(a.bounds[0, 1], abs=0.02), a.asset_id


def test_a_bed_frame_is_its_rails() -> None:
    a = registry.generate("bed", 0, "four_poster")
    assert {p.label for p in a.parts_by_label("frame")} >= {"side_rail", "foot_rail"}
    b = registry.generate("bed", 0, "platform")
    assert {p.label for p in b.parts_by_label("frame")} == {"plinth", "deck"}
    # the platform's frame is still what stands on the floor, under the mattress
    assert min(p.bounds[0, 2] for p in b.parts_by_label("frame")) == pytest.approx(b.bounds[0, 2], abs=0.006)


@pytest.mark.parametrize("seed", [0, 1])
def test_on_a_carcass_body_top_is_on_its_outside(seed: int) -> None:
    """``ON dresser:body@top`` with ``body`` a group of panels: the child stands on the
    carcass's top, not on the bottom panel inside it (which is also a member's top)."""
    from pathlib import Path

    import parse3d

    pag = parse3d.load_pag(Path(__file__).parent / "data" / "rooms" / "carcass_tops.json")
    scene = parse3d.solve(pag, seed=seed)
    for child, parent in (("lamp", "ns"), ("book", "dr"), ("vase", "sb"), ("mug", "hu")):
        c, p = scene.objects[child], scene.objects[parent]
        assert c.placed, child
        T = p.transform()
        tops = [float((np.asarray(q.bounds) @ T[:3, :3].T + T[:3, 3])[:, 2].max())
                for q in p.asset.parts_by_label("body")]
        bottom = float(c.world_bounds()[0, 2])
        # resting on (or above) the group's highest top, not 1 cm lower inside the carcass
        assert bottom >= max(tops) - 0.01, (child, bottom, max(tops))
