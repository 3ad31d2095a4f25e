"""The on-disk collision cache: the same hulls as computing them, damage tolerated."""

from __future__ import annotations

import numpy as np

from parse3d.assets.registry import generate
from parse3d.physics import collision as C


def _same(a: C.AssetCollision, b: C.AssetCollision) -> None:
    assert a.asset_id == b.asset_id and a.density == b.density and a.materials == b.materials
    assert a.pieces.parts == b.pieces.parts
    for f in ("vertices", "vert_index", "triangles", "tri_index", "planes", "areas", "volumes",
              "bounds"):
        x, y = getattr(a.pieces, f), getattr(b.pieces, f)
        assert x.dtype == y.dtype and np.array_equal(x, y), f


def test_collision_data_comes_back_from_disk_bit_for_bit(tmp_path, monkeypatch):
    monkeypatch.setenv("PARSE3D_CACHE", str(tmp_path))
    asset = generate("side_table", seed=1)
    C.clear_cache()
    computed = C.asset_collision(asset)
    files = list((tmp_path / "collision").glob("*.npz"))
    assert len(files) == 1
    C.clear_cache()
    loaded = C.asset_collision(asset)
    assert loaded is not computed
    _same(computed, loaded)
    # a damaged file is computed again (and rewritten), never trusted
    files[0].write_bytes(b"not a zip")
    C.clear_cache()
    _same(computed, C.asset_collision(asset))
    assert files[0].stat().st_size > 100


def test_unwritable_cache_still_computes(tmp_path, monkeypatch):
    monkeypatch.setenv("PARSE3D_CACHE", str(tmp_path / "cache"))
    (tmp_path / "cache").mkdir()
    (tmp_path / "cache" / "collision").write_text("a file where the folder would go")
    C.clear_cache()
    data = C.asset_collision(generate("mug", seed=0))
    assert len(data.pieces) > 0


def test_an_asset_is_fingerprinted_once_per_object(tmp_path, monkeypatch):
    monkeypatch.setenv("PARSE3D_CACHE", str(tmp_path))
    C.clear_cache()
    calls = []
    real = C._fingerprint
    monkeypatch.setattr(C, "_fingerprint", lambda a: calls.append(a.asset_id) or real(a))
    asset = generate("mug", seed=0)
    first = C.asset_collision(asset)
    for _ in range(3):
        assert C.asset_collision(asset) is first
    assert calls == [asset.asset_id]
    # the memo holds the content's fingerprint, and forgets the object once it is gone
    assert C._asset_key(asset) == real(asset)
    other = generate("mug", seed=0)
    assert C.asset_collision(other) is first  # same content, same data
    assert len(calls) == 2
    n = len(C._KEYS)
    del other
    import gc

    gc.collect()
    assert len(C._KEYS) == n - 1
