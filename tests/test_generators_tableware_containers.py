"""Tableware, kitchenware, container and grocery generators: contract, front probes, internal
support surfaces and determinism."""

from __future__ import annotations

from functools import cache

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.assets.contract import check_asset
from parse3d.assets.internal import MIN_CLEARANCE, MIN_INTERNAL_AREA

CATEGORIES = (
    "bowl", "plate", "wine_glass", "vase", "candle",
    "cooking_pot", "frying_pan", "kettle", "teapot",
    "basket", "storage_box", "bucket", "trash_can", "laundry_basket",
    "bottle", "canned_food", "cereal_box", "detergent_bottle", "apple",
)
#: containers whose body must hold things IN it; the value says whether a lid covers it
CONTAINERS = {"bowl": False, "basket": None, "bucket": False, "cooking_pot": True,
              "storage_box": True, "trash_can": None, "laundry_basket": False}
FLOOR = {"trash_can", "laundry_basket"}
SEEDS = (0, 1)
CASES = [(c, v, s) for c in CATEGORIES for v in registry.get(c).variants for s in SEEDS]


@cache
def _asset(category: str, variant: str, seed: int):
    return registry.generate(category, seed, variant)


def _centre(part) -> np.ndarray:
    return part.mesh.bounds.mean(axis=0)


def _parts(asset, label: str):
    return asset.parts_by_label(label)


@pytest.mark.parametrize(("category", "variant", "seed"), CASES,
                         ids=[f"{c}-{v}-{s}" for c, v, s in CASES])
def test_contract(category, variant, seed):
    asset = _asset(category, variant, seed)
    assert check_asset(asset) == []
    cat = registry.get(category)
    assert cat.placement == ("floor" if category in FLOOR else "surface")
    # whatever stands on a support needs a flat-enough bottom: a real footprint at z = 0
    base = asset.mesh()
    down = (base.face_normals[:, 2] < -0.99) & (base.triangles[:, :, 2].max(axis=1) < 1e-3)
    assert base.area_faces[down].sum() > 4e-4


@pytest.mark.parametrize(("category", "variant", "seed"),
                         [c for c in CASES if c[0] in CONTAINERS],
                         ids=[f"{c}-{v}-{s}" for c, v, s in CASES if c in CONTAINERS])
def test_containers_have_an_internal_surface_on_the_body(category, variant, seed):
    asset = _asset(category, variant, seed)
    inner = [s for s in asset.internal if s.part == "body"]
    assert inner, f"{asset.asset_id} has no internal surface on its body"
    floor = max(inner, key=lambda s: s.surface.area)
    assert floor.surface.area >= MIN_INTERNAL_AREA
    assert floor.clearance >= MIN_CLEARANCE
    assert floor.depth > 0.02
    lidded = CONTAINERS[category]
    if lidded is None:  # lidded (or covered by a carrying handle) in some variants only
        lidded = any(p.label == "lid" for p in asset.parts)
        assert lidded <= np.isfinite(floor.clearance)
    else:
        assert np.isfinite(floor.clearance) == lidded
    # the floor lies inside the body's footprint, near its bottom
    b = asset.part("body").bounds
    assert b[0, 2] <= floor.surface.origin[2] < b[0, 2] + 0.3 * (b[1, 2] - b[0, 2])


def _probe(asset) -> None:
    """The geometric check that the category's parts are where its canonical frame says."""
    c = asset.category
    top = asset.bounds[1, 2]
    body = asset.part("body") if any(p.name == "body" for p in asset.parts) else None
    if c == "plate":
        # stackable: low, flat bottom and a flat well on top; ``body`` names the whole plate
        assert asset.extents[2] < 0.05
        assert {p.label for p in asset.parts_by_label("body")} == {"well", "rim", "foot_ring"}
        well = asset.part("well").mesh
        up = well.face_normals[:, 2] > 0.99
        assert well.area_faces[up].sum() > 0.25 * asset.extents[0] ** 2
        # the foot ring is under the well (its ridge reaches half a millimetre into it)
        assert asset.part("foot_ring").bounds[1, 2] <= well.bounds[0, 2] + 0.001
    elif c == "wine_glass":
        foot, stem, bowl = (asset.part(n) for n in ("foot", "stem", "bowl"))
        assert foot.bounds[1, 2] <= stem.bounds[0, 2] + 1e-6
        assert stem.bounds[1, 2] <= bowl.bounds[0, 2] + 1e-6
        assert bowl.bounds[1, 2] == pytest.approx(top)
    elif c == "vase":
        # ``body`` names the whole vase: its body, neck, lip and foot ring
        assert {p.label for p in asset.parts_by_label("body")} >= {"body", "lip", "foot_ring"}
        assert asset.part("lip").bounds[1, 2] == pytest.approx(top)
        if asset.meta["variant"] != "cylinder":
            nb = asset.part("neck").bounds
            assert nb[1, 0] - nb[0, 0] < 0.8 * asset.extents[0]
    elif c in ("cooking_pot", "storage_box"):
        lid = asset.part("lid")
        # the lid rests on the body: its underside at (or just below, for a lip/skirt) the rim
        covers = [p.bounds[1, 2] for p in asset.parts if p.label in ("lid", "lid_knob")]
        assert max(covers) == pytest.approx(top)
        assert lid.bounds[1, 2] > body.bounds[1, 2]
        assert lid.bounds[0, 2] < body.bounds[1, 2] + 1e-6
        if c == "cooking_pot":
            xs = sorted(_centre(p)[0] for p in _parts(asset, "handle"))
            assert len(xs) == 2 and xs[0] < body.bounds[0, 0] + 0.02 and xs[1] > body.bounds[1, 0] - 0.02
    elif c == "frying_pan":
        handle = max(_parts(asset, "handle"), key=lambda p: p.bounds[1, 0])
        assert _centre(handle)[0] > body.bounds[1, 0] - 0.01  # along +X
        assert asset.part("grip").bounds[1, 0] == pytest.approx(asset.bounds[1, 0])
    elif c in ("kettle", "teapot"):
        spout = asset.part("spout")
        assert _centre(spout)[1] > _centre(body)[1] + 0.03  # spout at the front (+Y)
        assert spout.bounds[1, 1] == pytest.approx(asset.bounds[1, 1])
        handle = asset.part("handle")
        if c == "teapot" or asset.meta["variant"] == "electric":
            assert _centre(handle)[1] < _centre(body)[1] - 0.03  # handle at the back (-Y)
        else:
            assert handle.bounds[1, 2] == pytest.approx(top)  # arches over the top
    elif c == "bucket":
        assert asset.part("handle").bounds[1, 2] > body.bounds[1, 2] - 0.05
    elif c == "trash_can" and asset.meta["variant"] == "pedal":
        assert _centre(asset.part("pedal"))[1] > body.bounds[1, 1] - 0.01  # pedal at the front
    elif c == "cereal_box":
        e = asset.extents
        assert e[2] > e[0] > 2 * e[1]  # tall, thin in y: the large face looks along +Y
        assert asset.part("label").bounds[1, 1] == pytest.approx(asset.bounds[1, 1])
    elif c == "detergent_bottle":
        assert asset.part("cap").bounds[1, 2] == pytest.approx(top)
        if asset.meta["variant"] == "jug":
            assert _centre(asset.part("handle"))[1] < _centre(asset.part("cap"))[1] - 0.03
    elif c == "bottle":
        assert asset.part("cap").bounds[1, 2] == pytest.approx(top)
    elif c == "apple":
        assert asset.part("stem").bounds[1, 2] == pytest.approx(top)
        assert 0.06 <= max(asset.extents[:2]) <= 0.09
    elif c == "candle":
        assert asset.part("wick").bounds[1, 2] > body.bounds[1, 2]
        if asset.meta["variant"] == "taper":
            assert asset.part("holder").bounds[0, 2] < body.bounds[0, 2]
    elif c == "canned_food":
        label = asset.part("label")
        assert label.bounds[0, 2] > 0 and label.bounds[1, 2] < top
        assert label.bounds[1, 0] <= body.bounds[1, 0] + 1e-6


@pytest.mark.parametrize("category", CATEGORIES)
def test_front_probe_and_variants_differ(category):
    cat = registry.get(category)
    assert len(cat.variants) >= 2
    for v in cat.variants:
        for s in SEEDS:
            _probe(_asset(category, v, s))
    shapes = {(tuple(p.name for p in a.parts), sum(len(p.mesh.vertices) for p in a.parts),
               tuple(a.extents.round(4)))
              for a in (_asset(category, v, 0) for v in cat.variants)}
    assert len(shapes) == len(cat.variants)  # structurally different variants


@pytest.mark.parametrize("category", CATEGORIES)
def test_same_seed_same_asset(category):
    v = registry.get(category).variants[-1]
    a, b = _asset(category, v, 0), registry.generate(category, 0, v)
    assert [p.name for p in a.parts] == [p.name for p in b.parts]
    for pa, pb in zip(a.parts, b.parts, strict=True):
        np.testing.assert_array_equal(pa.mesh.vertices, pb.mesh.vertices)
    assert not np.allclose(a.extents, _asset(category, v, 1).extents)
