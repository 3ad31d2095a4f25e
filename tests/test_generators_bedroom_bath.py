"""Generators for bedroom furniture, seating, soft goods and bathroom fixtures.

Every category x every variant x two seeds honours the asset contract; per category a geometric
probe checks the canonical frame (front at +Y, backs and headboards at -Y, wall items flat at
-Y) and the surfaces the relations need (tops to put things on, internal surfaces for IN).
"""

from __future__ import annotations

from functools import cache

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.assets.contract import check_asset
from parse3d.assets.model import Asset, Part

CATEGORIES = ("bed", "bunk_bed", "nightstand", "wardrobe", "dresser", "office_chair",
              "dining_chair", "armchair", "sofa", "bar_stool", "pillow", "towel", "rug",
              "bathtub", "toilet", "bathroom_vanity", "towel_bar")
SEEDS = (0, 1)


@cache
def _asset(category: str, variant: str, seed: int) -> Asset:
    return registry.generate(category, seed, variant)


def _cases():
    return [pytest.param(c, v, s, id=f"{c}-{v}-{s}")
            for c in CATEGORIES for v in registry.get(c).variants for s in SEEDS]


def _center(parts: list[Part] | Part) -> np.ndarray:
    ps = parts if isinstance(parts, list) else [parts]
    b = np.array([p.bounds for p in ps])
    return (b[:, 0].min(axis=0) + b[:, 1].max(axis=0)) / 2


def _top_area(p: Part) -> float:
    s = p.surfaces["top"]
    assert s.source == "mesh"
    return s.area


def _probe_bed(a: Asset) -> None:
    head, mat = a.part("headboard"), a.part("mattress")
    assert _center(head)[1] < _center(mat)[1]
    assert head.bounds[1, 1] <= mat.bounds[0, 1] + 0.02
    assert _top_area(mat) > 0.7 * mat.mesh.extents[0] * mat.mesh.extents[1]


def _probe_bunk_bed(a: Asset) -> None:
    low, up = a.part("mattress_0"), a.part("mattress_1")
    assert low.bounds[1, 2] + 0.5 < up.bounds[0, 2]
    ladder = a.part("ladder")
    front = ladder.bounds[1, 1] > a.bounds[1, 1] - 0.05
    end = ladder.bounds[0, 0] > up.bounds[1, 0]
    assert front or end
    assert _top_area(low) > 1.0 and _top_area(up) > 1.0


def _probe_case(a: Asset) -> None:
    body = a.parts_by_label("body")[0]
    for d in a.parts_by_label("drawer"):
        assert d.bounds[1, 1] > body.bounds[1, 1] - 0.005  # drawer fronts at the front
    for h in a.parts_by_label("handle"):
        assert h.bounds[1, 1] > body.bounds[1, 1] + 0.01
    top = a.part("top_panel")
    assert _top_area(top) > 0.8 * top.mesh.extents[0] * top.mesh.extents[1]
    assert abs(top.bounds[1, 2] - a.bounds[1, 2]) < 1e-6


def _probe_wardrobe(a: Asset) -> None:
    body = a.part("body")
    for d in a.parts_by_label("door"):
        assert d.bounds[1, 1] > a.bounds[1, 1] - 0.06
        assert _center(d)[1] > _center(body)[1]
    shelves = {p.name for p in a.parts_by_label("shelf")}
    on_shelves = [s for s in a.internal if s.part in shelves]
    assert len(on_shelves) >= 2
    assert all(s.clearance > 0.15 for s in on_shelves)


def _probe_back_seat(a: Asset, back: str = "back", seat: str = "seat") -> None:
    assert _center(a.parts_by_label(back))[1] < _center(a.parts_by_label(seat))[1] - 0.05
    seat_top = max(p.bounds[1, 2] for p in a.parts_by_label(seat))
    assert max(p.bounds[1, 2] for p in a.parts_by_label(back)) > seat_top + 0.2
    assert all(_top_area(p) > 0.05 for p in a.parts_by_label(seat))


def _probe_office_chair(a: Asset) -> None:
    _probe_back_seat(a)
    casters = a.parts_by_label("caster")
    assert len(casters) == 5
    assert min(c.bounds[0, 2] for c in casters) < 1e-6


def _probe_armchair(a: Asset) -> None:
    _probe_back_seat(a)
    assert _center(a.part("armrest_0"))[0] < 0 < _center(a.part("armrest_1"))[0]


def _probe_sofa(a: Asset) -> None:
    _probe_back_seat(a, "back_cushion", "seat_cushion")
    assert _center(a.part("armrest_0"))[0] < 0 < _center(a.part("armrest_1"))[0]
    assert len(a.parts_by_label("seat_cushion")) in (2, 3)


def _probe_bar_stool(a: Asset) -> None:
    seat = a.part("seat")
    assert abs(seat.bounds[1, 2] - a.bounds[1, 2]) < 1e-6 and seat.bounds[0, 2] > 0.5
    assert _top_area(seat) > 0.05


def _probe_soft(a: Asset) -> None:
    body = a.parts_by_label("body")[0]
    bottom = body.surfaces["bottom"]
    assert bottom.source == "mesh" and abs(bottom.origin[2]) < 0.003
    assert bottom.area > 0.2 * body.mesh.extents[0] * body.mesh.extents[1]


def _probe_rug(a: Asset) -> None:
    _probe_soft(a)
    assert a.extents[2] <= 0.021


def _probe_bathtub(a: Asset) -> None:
    inside = [s for s in a.internal if s.part == "tub"]
    assert inside and max(s.depth for s in inside) > 0.3
    assert max(s.surface.area for s in inside) > 0.3


def _probe_toilet(a: Asset) -> None:
    assert _center(a.part("tank"))[1] < _center(a.part("bowl"))[1] - 0.1
    assert a.part("seat").bounds[0, 2] > 0.3


def _probe_vanity(a: Asset) -> None:
    top = a.part("countertop")
    assert _top_area(top) > 0.2
    assert a.part("faucet").bounds[1, 2] > top.bounds[1, 2] + 0.08
    assert any(s.part == "basin" for s in a.internal)
    fronts = a.parts_by_label("door") + a.parts_by_label("drawer")
    assert fronts and all(p.bounds[1, 1] > a.part("body").bounds[1, 1] for p in fronts)
    assert _center(a.part("faucet"))[1] < _center(a.part("basin"))[1]


def _probe_towel_bar(a: Asset) -> None:
    brackets = a.parts_by_label("bracket")
    assert len(brackets) == 2
    for b in brackets:
        back = b.surfaces["back"]
        assert abs(back.origin[1] - a.bounds[0, 1]) < 1e-6 and back.area > 1e-3
    for bar in a.parts_by_label("bar"):
        assert bar.mesh.extents[0] > 0.9 * a.extents[0]
        assert _center(bar)[1] > a.bounds[0, 1] + 0.02
    assert a.extents[0] == a.size


PROBES = {
    "bed": _probe_bed, "bunk_bed": _probe_bunk_bed, "nightstand": _probe_case,
    "dresser": _probe_case, "wardrobe": _probe_wardrobe, "office_chair": _probe_office_chair,
    "dining_chair": _probe_back_seat, "armchair": _probe_armchair, "sofa": _probe_sofa,
    "bar_stool": _probe_bar_stool, "pillow": _probe_soft, "towel": _probe_soft, "rug": _probe_rug,
    "bathtub": _probe_bathtub, "toilet": _probe_toilet, "bathroom_vanity": _probe_vanity,
    "towel_bar": _probe_towel_bar,
}


@pytest.mark.parametrize(("category", "variant", "seed"), _cases())
def test_contract_and_front_probe(category: str, variant: str, seed: int) -> None:
    asset = _asset(category, variant, seed)
    problems = check_asset(asset)
    assert not problems, f"{asset.asset_id}:\n" + "\n".join(problems)
    PROBES[category](asset)


@pytest.mark.parametrize("category", CATEGORIES)
def test_same_seed_same_asset(category: str) -> None:
    variant = registry.get(category).variants[-1]
    a = _asset(category, variant, 0)
    b = registry.generate(category, 0, variant)
    assert [p.name for p in a.parts] == [p.name for p in b.parts]
    for pa, pb in zip(a.parts, b.parts, strict=True):
        np.testing.assert_array_equal(pa.mesh.vertices, pb.mesh.vertices)
    c = _asset(category, variant, 1)
    assert not all(np.array_equal(pa.mesh.vertices, pc.mesh.vertices)
                   for pa, pc in zip(a.parts, c.parts, strict=False))


def test_wardrobe_doors_close_the_shelves() -> None:
    """The shelves are covered from above and walled (internal surfaces, not open tops)."""
    a = _asset("wardrobe", "sliding", 0)
    shelf_names = {p.name for p in a.parts_by_label("shelf")}
    internal = [s for s in a.internal if s.part in shelf_names]
    assert internal and all(np.isfinite(s.clearance) for s in internal)


def test_bunk_bed_orders_mattresses_bottom_up() -> None:
    a = _asset("bunk_bed", "front_ladder", 0)
    assert [p.name for p in a.parts_by_label("mattress")] == ["mattress_0", "mattress_1"]


def test_piece_counts_stay_modest() -> None:
    for category in ("office_chair", "dining_chair", "bar_stool", "toilet"):
        for variant in registry.get(category).variants:
            a = _asset(category, variant, 0)
            assert sum(len(p.pieces) for p in a.parts) <= 60, a.asset_id
