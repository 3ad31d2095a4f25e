"""The process caches' LRU mapping, and the caches built on it evicting at their sizes."""

from __future__ import annotations

import pickle

import pytest

from parse3d._lru import LRU
from parse3d.assets.pool import AssetPool
from parse3d.datagen.memory import _trim
from parse3d.physics import collision


def test_reads_refresh_and_writes_beyond_the_size_drop_the_oldest():
    c = LRU(3)
    for k in "abc":
        c[k] = k.upper()
    assert c.get("a") == "A"  # a is now the newest
    c["d"] = "D"
    assert list(c) == ["c", "a", "d"]  # b, the least recently used, went
    c["c"] = "C2"  # a write refreshes too
    c["e"] = "E"
    assert list(c) == ["d", "c", "e"] and c["c"] == "C2"
    assert c.get("b") is None and c.get("b", 0) == 0 and "b" not in c
    assert len(c) == 3


def test_unbounded_zero_and_invalid_sizes():
    free = LRU()
    for i in range(10_000):
        free[i] = i
    assert len(free) == 10_000
    none = LRU(0)
    none["x"] = 1
    assert len(none) == 0 and none.get("x") is None
    with pytest.raises(ValueError, match="maxsize"):
        LRU(-1)


def test_pickles_with_its_size_and_order():
    c = LRU(4)
    for i in range(6):
        c[i] = i * i
    back = pickle.loads(pickle.dumps(c))
    assert back.maxsize == 4 and list(back.items()) == [(2, 4), (3, 9), (4, 16), (5, 25)]


def test_a_worker_trims_it_oldest_first():
    c = LRU(10)
    for i in range(6):
        c[i] = i
    c.get(0)
    dropped = []
    assert _trim(c, 2, dropped.append) == 4
    assert dropped == [1, 2, 3, 4] and list(c) == [5, 0]


def test_asset_pool_keeps_its_memory_size(tmp_path):
    pool = AssetPool(tmp_path, per_category=3, memory=2)
    a0, a1 = pool.load("cup", 0), pool.load("cup", 1)
    assert pool.load("cup", 0) is a0  # served from memory, and now the newest
    pool.load("cup", 2)
    assert len(pool._lru) == 2
    assert pool.load("cup", 0) is a0
    b1 = pool.load("cup", 1)  # evicted: read back from disk, a new object of equal content
    assert b1 is not a1 and b1.asset_id == a1.asset_id


def test_collision_cache_evicts_at_its_size(tmp_path, monkeypatch):
    monkeypatch.setenv("PARSE3D_CACHE", str(tmp_path / "cache"))
    monkeypatch.setattr(collision, "_CACHE", LRU(2))
    pool = AssetPool(tmp_path / "pool", per_category=3)
    assets = [pool.load("cup", i) for i in range(3)]
    first = [collision.asset_collision(a) for a in assets[:2]]
    assert collision.asset_collision(assets[0]) is first[0]
    collision.asset_collision(assets[2])
    assert len(collision._CACHE) == 2
    assert collision.asset_collision(assets[0]) is first[0]  # kept: used more recently
    again = collision.asset_collision(assets[1])  # dropped: read back from the disk cache
    assert again is not first[1] and again.asset_id == first[1].asset_id
