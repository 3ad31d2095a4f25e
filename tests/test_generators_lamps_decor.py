"""Lamps, wall decor, plants, electronics, books, guitars and brooms: the asset contract, a
geometric front probe per category, the surfaces relations need, and determinism."""

from __future__ import annotations

from functools import cache

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.assets.contract import check_asset
from parse3d.assets.generators.lamps import shell

CATEGORIES = ("floor_lamp", "table_lamp", "pendant_lamp", "potted_plant", "picture_frame", "mirror",
              "wall_clock", "tv", "monitor", "laptop", "keyboard", "book", "guitar", "broom",
              "speaker", "remote_control")
SEEDS = (0, 1)
EPS = 1e-4


@cache
def _asset(category: str, seed: int, variant: str):
    return registry.generate(category, seed, variant)


def _cases():
    return [pytest.param(c, s, v, id=f"{c}-{v}-{s}")
            for c in CATEGORIES for v in registry.get(c).variants for s in SEEDS]


def _one(asset, label: str):
    parts = asset.parts_by_label(label)
    assert parts, f"{asset.asset_id} has no {label!r} part"
    return parts[0]


def _box(asset, label: str) -> np.ndarray:
    """(2, 3) bounds over all parts with ``label``."""
    b = np.array([p.bounds for p in asset.parts_by_label(label)])
    return np.array([b[:, 0].min(axis=0), b[:, 1].max(axis=0)])


def _centre(asset, label: str) -> np.ndarray:
    return _box(asset, label).mean(axis=0)


def _flat_back(asset, label: str) -> None:
    """A wall item's ``label`` part (for a group label, one of its parts: a frame's backing
    board) has a large flat patch on the asset's back plane (y min)."""
    b = asset.bounds
    _one(asset, label)
    back = max((p.surfaces["back"] for p in asset.parts_by_label(label)),
               key=lambda s: (abs(s.origin[1] - b[0, 1]) < 1e-3, s.area))
    assert back.source == "mesh"
    assert abs(back.origin[1] - b[0, 1]) < 1e-3
    ext = asset.extents
    assert back.area > 0.1 * ext[0] * ext[2]


def _stands_flat(asset, min_area: float) -> None:
    """Parts touching the floor offer at least ``min_area`` m^2 of downward surface at z = 0."""
    area = sum(p.surfaces["bottom"].area for p in asset.parts
               if abs(p.surfaces["bottom"].origin[2]) < 1e-3 and p.surfaces["bottom"].source == "mesh")
    assert area >= min_area, f"{asset.asset_id}: {area:.5f} m^2 on the floor"


def _probe(asset, variant: str) -> None:
    c = asset.category
    b, ext = asset.bounds, asset.extents
    if c == "floor_lamp":
        assert _box(asset, "shade")[1, 2] > 0.85 * ext[2]
        assert _box(asset, "base")[0, 2] < EPS
        if variant == "arc":  # the arc carries the shade forward, over the room
            assert _centre(asset, "shade")[1] - _centre(asset, "base")[1] > 0.5
        else:
            assert np.abs(_centre(asset, "shade")[:2] - _centre(asset, "pole")[:2]).max() < 0.02
        _stands_flat(asset, 0.0005)
    elif c == "table_lamp":
        assert _box(asset, "shade")[0, 2] > _box(asset, "base")[0, 2]
        assert _box(asset, "stem")[1, 2] < _box(asset, "shade")[1, 2]
        _stands_flat(asset, 0.005)
    elif c == "pendant_lamp":
        canopy = _one(asset, "canopy")
        assert abs(canopy.bounds[1, 2] - b[1, 2]) < EPS
        top = canopy.surfaces["top"]
        assert top.source == "mesh" and top.area > 0.005
        cord = _box(asset, "cord")
        assert 0.3 - EPS <= cord[1, 2] - cord[0, 2] <= 1.0 + EPS
        assert _box(asset, "shade")[1, 2] <= cord[0, 2] + 0.03
    elif c == "potted_plant":
        assert _box(asset, "pot")[0, 2] < EPS
        assert abs(_box(asset, "plant")[1, 2] - b[1, 2]) < EPS
        assert _box(asset, "soil")[1, 2] < _box(asset, "pot")[1, 2]
        _stands_flat(asset, 0.01)
    elif c == "picture_frame":
        _flat_back(asset, "frame")
        assert _box(asset, "canvas")[1, 1] < _box(asset, "frame")[1, 1]
        if variant == "landscape":
            assert ext[0] > ext[2] * 1.2
        elif variant == "portrait":
            assert ext[2] > ext[0] * 1.2
        else:
            assert abs(ext[0] - ext[2]) < 1e-6
    elif c == "mirror":
        _flat_back(asset, "frame")
        assert _box(asset, "glass")[1, 1] < _box(asset, "frame")[1, 1]
        if variant == "round":
            assert abs(ext[0] - ext[2]) < 0.01 * ext[0]
        elif variant == "oval":
            assert ext[2] > 1.25 * ext[0]
    elif c == "wall_clock":
        _flat_back(asset, "body")
        face = _box(asset, "face")
        assert _box(asset, "hand")[0, 1] >= face[1, 1] - EPS
        assert _box(asset, "hand")[1, 1] <= b[1, 1] + EPS
    elif c in ("tv", "monitor"):
        screen = _box(asset, "screen")
        assert abs(screen[1, 1] - _box(asset, "body")[1, 1]) < 0.003  # the screen is the front
        assert _one(asset, "screen").surfaces["front"].area > 0.5 * ext[0] * (screen[1, 2] - screen[0, 2])
        if variant == "wall_mount":  # no stand: its VESA plate is its furthest back
            assert not asset.parts_by_label("stand") and not asset.parts_by_label("base")
            assert _box(asset, "vesa_plate")[0, 1] <= b[0, 1] + EPS
            return
        assert screen[0, 2] > _box(asset, "stand")[0, 2]
        if c == "monitor":
            assert _box(asset, "base")[0, 2] < EPS
            assert _box(asset, "base")[1, 1] > screen[1, 1]  # the foot reaches in front of it
        _stands_flat(asset, 0.003)
    elif c == "laptop":
        lid = _one(asset, "screen").mesh.vertices
        assert lid[:, 1].mean() < _centre(asset, "base")[1]  # hinged at the back
        lo, hi = lid[lid[:, 2] < lid[:, 2].min() + 0.01], lid[lid[:, 2] > lid[:, 2].max() - 0.01]
        lean = np.degrees(np.arctan2(lo[:, 1].mean() - hi[:, 1].mean(), hi[:, 2].mean() - lo[:, 2].mean()))
        assert 9 < lean < 26, lean  # opened 100-115 degrees
        assert _centre(asset, "display")[1] > lid[:, 1].mean()  # the display is the lid's front
        _stands_flat(asset, 0.03)
    elif c == "keyboard":
        assert ext[0] > ext[1] > ext[2]
        assert _box(asset, "keys")[1, 2] > _box(asset, "body")[1, 2] - 0.01
        _stands_flat(asset, 0.02)
    elif c == "book":
        y = {k: _centre(asset, k)[1] for k in ("front_cover", "pages", "back_cover")}
        assert y["front_cover"] > y["pages"] > y["back_cover"]
        assert _centre(asset, "spine")[0] < _centre(asset, "pages")[0]
        assert 0.01 - EPS <= ext[1] <= 0.06 + EPS
        assert _box(asset, "pages")[1, 2] <= _box(asset, "front_cover")[1, 2] + EPS
        _stands_flat(asset, 0.0002)
    elif c == "guitar":
        assert _box(asset, "body")[0, 2] < EPS
        assert abs(_box(asset, "head")[1, 2] - b[1, 2]) < 0.02
        front = "soundhole" if variant == "acoustic" else "pickguard"
        assert _box(asset, front)[1, 1] >= _box(asset, "body")[1, 1]  # strings face +Y
        assert _one(asset, "body").surfaces["back"].area > 0.05  # the flat back leans on walls
        _stands_flat(asset, 0.0005)
    elif c == "broom":
        assert _box(asset, "bristles")[0, 2] < EPS
        assert _centre(asset, "head")[2] < 0.4 < _centre(asset, "handle")[2]
        assert abs(_box(asset, "handle")[1, 2] - b[1, 2]) < EPS
        _stands_flat(asset, 0.005)
    elif c == "speaker":
        drivers = asset.parts_by_label("driver")
        assert len(drivers) >= 2
        assert all(p.name == f"driver_{k}" for k, p in enumerate(sorted(drivers, key=lambda p: p.name)))
        assert min(p.bounds[1, 1] for p in drivers) > _box(asset, "body")[1, 1]
        _stands_flat(asset, 0.02)
    elif c == "remote_control":
        assert ext[1] > 2 * ext[0] > 2 * ext[2]
        assert asset.part("power_button").bounds.mean(axis=0)[1] > _centre(asset, "body")[1]
        assert _box(asset, "button")[0, 2] > _box(asset, "body")[1, 2] - 0.002
        _stands_flat(asset, 0.002)
    else:  # pragma: no cover - every category above has a probe
        raise AssertionError(c)


@pytest.mark.parametrize(("category", "seed", "variant"), _cases())
def test_contract_and_front_probe(category: str, seed: int, variant: str) -> None:
    asset = _asset(category, seed, variant)
    assert check_asset(asset) == [], asset.asset_id
    assert asset.meta["variant"] == variant
    _probe(asset, variant)
    # nothing of these is a container: no spurious IN targets (a pot's soil is allowed)
    assert all(s.part == "soil" for s in asset.internal), [s.part for s in asset.internal]
    pieces = sum(len(p.pieces) for p in asset.parts)
    assert pieces <= 70, pieces


@pytest.mark.parametrize("category", CATEGORIES)
def test_same_seed_same_asset_and_variants_differ(category: str) -> None:
    variants = registry.get(category).variants
    assert len(variants) >= 2
    a = _asset(category, 0, variants[0])
    again = registry.generate(category, 0, variants[0])
    assert [p.name for p in a.parts] == [p.name for p in again.parts]
    for p, q in zip(a.parts, again.parts, strict=True):
        assert np.array_equal(p.mesh.vertices, q.mesh.vertices)
        assert p.material == q.material
    other = _asset(category, 1, variants[0])  # continuous parameters vary with the seed
    assert not np.allclose(a.extents, other.extents)


def test_shell_pieces_tile_the_wall_exactly() -> None:
    s = shell([(0.2, 0.0), (0.17, 0.1), (0.1, 0.25)], 0.004, sections=18)
    assert s.mesh.is_watertight and s.mesh.is_winding_consistent
    assert len(s.pieces) == 2 * 18
    assert all(p.is_convex and p.volume > 0 for p in s.pieces)
    assert np.isclose(sum(p.volume for p in s.pieces), s.mesh.volume, rtol=1e-9)
    # a mapped shell (turned to face +Y, stretched) keeps its pieces and volume consistent
    lin = np.diag([1.0, 1.0, 1.5]) @ np.array([[1, 0, 0], [0, 0, 1], [0, -1, 0]], float)
    m = shell([(0.3, 0.0), (0.3, 0.03)], 0.04, sections=12, linear=lin, offset=(0, 0, 1))
    assert m.mesh.is_watertight and m.mesh.volume > 0
    assert np.isclose(sum(p.volume for p in m.pieces), m.mesh.volume, rtol=1e-9)
    assert np.allclose(m.mesh.bounds[:, 1], [0.0, 0.03])
