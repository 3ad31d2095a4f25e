"""Storage furniture, kitchen and appliances, large leisure items and wall boards.

Every category x every variant is generated once (seed 1; the shared contract test covers
seeds 0 and 1 across variants) and checked for the asset contract, its orientation (a
geometric front probe) and the surfaces the relations need: shelves get internal support
surfaces for ``IN``, tops things are put ``ON`` get a large upward surface.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.assets.contract import check_asset
from parse3d.assets.model import Asset, Joint

CATEGORIES = ("bookcase", "storage_cabinet", "tv_stand", "kitchen_counter", "wall_cabinet", "refrigerator",
              "stove", "washing_machine", "storage_rack", "grocery_shelf", "bar_counter", "piano", "pool_table",
              "whiteboard", "wall_shelf", "coat_rack")
WALL = ("wall_cabinet", "whiteboard", "wall_shelf")
SEED = 1


@functools.cache
def _asset(category: str, variant: str, seed: int = SEED) -> Asset:
    return registry.generate(category, seed, variant)


def _cases():
    return [pytest.param(c, v, id=f"{c}-{v}") for c in CATEGORIES for v in registry.get(c).variants]


def _center(a: Asset, label: str) -> np.ndarray:
    b = np.array([p.bounds for p in a.parts if p.label == label])
    return (b[:, 0].min(axis=0) + b[:, 1].max(axis=0)) / 2


def _max_y(a: Asset, label: str) -> float:
    return max(float(p.bounds[1, 1]) for p in a.parts if p.label == label)


def _internal_parts(a: Asset) -> set[str]:
    return {s.part for s in a.internal}


def test_registered_with_variants_and_placement():
    cats = registry.categories()
    for c in CATEGORIES:
        assert c in cats, c
        assert len(cats[c].variants) >= 2, c
        assert cats[c].placement == ("wall" if c in WALL else "floor"), c


@pytest.mark.parametrize(("category", "variant"), _cases())
def test_contract(category: str, variant: str):
    a = _asset(category, variant)
    assert check_asset(a) == [], a.asset_id
    assert a.meta["variant"] == variant
    pieces = sum(len(p.pieces) for p in a.parts)
    assert pieces <= 120, f"{a.asset_id}: {pieces} collision pieces"


@pytest.mark.parametrize(("category", "variant"), _cases())
def test_front_probe(category: str, variant: str):
    """The object's front faces +Y (and wall items keep their flat back at -Y)."""
    a = _asset(category, variant)
    lo, hi = a.bounds
    labels = set(a.labels)
    if category == "bookcase":
        assert _center(a, "back_panel")[1] < _center(a, "shelf")[1]
        assert abs(a.part("back_panel").bounds[0, 1] - lo[1]) < 0.01
        if "door" in labels:
            assert _max_y(a, "door") > hi[1] - 0.05
    elif category in ("storage_cabinet", "wall_cabinet", "refrigerator", "kitchen_counter"):
        assert _center(a, "door")[1] > _center(a, "body")[1]
        assert _max_y(a, "door") > hi[1] - 0.06
        if category == "kitchen_counter":  # the countertop overhangs the doors at the front
            assert a.part("countertop").bounds[1, 1] > _max_y(a, "door")
    elif category == "tv_stand":
        front = [p for p in a.parts if p.label in ("handle", "shelf")]
        assert min(p.bounds.mean(axis=0)[1] for p in front) > a.part("body").bounds[0, 1] + 0.05
    elif category == "stove":
        assert _center(a, "door")[1] > _center(a, "body")[1]
        assert _center(a, "knob")[1] > a.part("body").bounds[1, 1] - 0.01
    elif category == "washing_machine":
        if variant == "front_loader":
            assert _center(a, "door")[1] > a.part("body").bounds[1, 1]
        else:
            assert _center(a, "control_panel")[1] < _center(a, "door")[1]
    elif category == "storage_rack":
        posts = np.array([p.bounds.mean(axis=0)[:2] for p in a.parts if p.label == "post"])
        assert len(posts) == 4 and np.allclose(posts.mean(axis=0), 0.0, atol=1e-6)
    elif category == "grocery_shelf":
        assert _center(a, "back_panel")[1] < a.parts_by_label("shelf")[-1].bounds[1, 1]
        assert _center(a, "price_rail")[1] >= _center(a, "back_panel")[1]
    elif category == "bar_counter":
        assert _max_y(a, "foot_rail") > a.part("body").bounds[1, 1] + 0.1  # customers' side
        assert a.part("countertop").bounds[1, 1] > a.part("body").bounds[1, 1] + 0.15
    elif category == "piano":
        assert _center(a, "keyboard")[1] > _center(a, "body")[1]
        assert _max_y(a, "keyboard") > hi[1] - 0.05
    elif category == "pool_table":
        ext = a.part("playing_surface").bounds
        assert ext[1, 0] - ext[0, 0] > 1.6 * (ext[1, 1] - ext[0, 1])  # 2:1 field, long along X
    elif category == "whiteboard":
        assert _center(a, "tray")[1] > _center(a, "board")[1]
        assert _center(a, "tray")[2] < _center(a, "board")[2]
        assert abs(min(p.bounds[0, 1] for p in a.parts if p.label in ("board", "frame", "standoff", "tray"))
                   - lo[1]) < 1e-6
    elif category == "wall_shelf":
        assert abs(min(p.bounds[0, 1] for p in a.parts if p.label == "bracket") - lo[1]) < 0.01
        assert _center(a, "shelf")[1] > lo[1] + 0.05
    elif category == "coat_rack":
        pole = a.part("pole").bounds.mean(axis=0)
        assert np.allclose(pole[:2], a.part("base").mesh.centroid[:2], atol=0.01)  # stands on its base
        hooks = a.parts_by_label("hook")
        assert len(hooks) >= 4 and min(h.bounds[0, 2] for h in hooks) > 0.6 * hi[2]


def _has_top(a: Asset, part, min_area: float) -> bool:
    s = part.surfaces["top"]
    return s.normal[2] > 0.99 and s.area >= min_area


@pytest.mark.parametrize(("category", "variant"), _cases())
def test_support_surfaces(category: str, variant: str):
    a = _asset(category, variant)
    inside = _internal_parts(a)
    shelves = a.parts_by_label("shelf")
    if category in ("bookcase", "storage_cabinet", "wall_cabinet", "refrigerator", "storage_rack"):
        assert shelves and all(s.name in inside for s in shelves), (inside, [s.name for s in shelves])
    if category == "bookcase":
        assert 3 <= len(shelves) <= 6
        for s in shelves:
            surf = [x for x in a.internal if x.part == s.name]
            assert max(x.clearance for x in surf) >= 0.2
            assert max(x.surface.area for x in surf) > 0.1
    if category == "grocery_shelf":  # every shelf but the top one of each side is covered
        sides = 2 if variant == "double_sided" else 1
        assert 4 * sides <= len(shelves) <= 6 * sides
        assert sum(s.name in inside for s in shelves) >= len(shelves) - sides
        top = max(shelves, key=lambda p: p.bounds[1, 2])
        assert top.name in inside or _has_top(a, top, 0.2)
    if category in ("kitchen_counter", "bar_counter"):
        assert inside & {p.name for p in a.parts if p.label in ("shelf", "body")}
    if category == "wall_shelf":
        for s in shelves:
            w, d = (s.bounds[1] - s.bounds[0])[:2]
            assert _has_top(a, s, 0.8 * w * d)
    for p in a.parts:  # what things are put ON: most of the part's footprint faces up
        if p.label in ("countertop", "top_panel", "cooktop", "playing_surface"):
            w, d = (p.bounds[1] - p.bounds[0])[:2]
            assert _has_top(a, p, 0.45 * w * d), (p.name, p.surfaces["top"].area, w * d)
    if category == "stove":
        burners = a.parts_by_label("burner")
        assert len(burners) == 4
        top = a.part("cooktop").bounds[1, 2]
        assert all(b.bounds[1, 2] > top + 0.002 for b in burners)  # raised above the cooktop


@pytest.mark.parametrize("category", CATEGORIES)
def test_same_seed_same_geometry(category: str):
    cat = registry.get(category)
    variant = cat.variants[-1]
    def parts(seed):  # generators return their parts with the joints that articulate them
        return [x for x in cat.generator(registry.category_rng(category, seed), variant) if not isinstance(x, Joint)]

    runs = [parts(5) for _ in range(2)]
    assert [p.name for p in runs[0]] == [p.name for p in runs[1]]
    for p, q in zip(*runs, strict=True):
        assert np.array_equal(p.mesh.vertices, q.mesh.vertices)
        assert p.material == q.material
    other = parts(6)
    assert any(p.mesh.vertices.shape != q.mesh.vertices.shape or not np.allclose(p.mesh.vertices, q.mesh.vertices)
               for p, q in zip(runs[0], other, strict=False)) or len(other) != len(runs[0])
