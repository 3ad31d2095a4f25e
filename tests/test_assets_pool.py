"""The asset pool: the same rng state gives the same asset whether or not it was pre-built."""

from __future__ import annotations

import numpy as np

from parse3d.assets.cache import asset_digest
from parse3d.assets.pool import AssetPool


def _draws(pool, seed, n=3):
    rng = np.random.default_rng(seed)
    return [asset_digest(pool.get("cup", rng)) for _ in range(n)]


def test_prebuilt_and_on_demand_agree(tmp_path):
    built = AssetPool(tmp_path / "built", per_category=3)
    rep = built.build(["cup"], workers=1, progress=False)
    assert rep.generated == 3 and rep.cached == 0 and not rep.failures
    assert built.missing(["cup"]) == []
    lazy = AssetPool(tmp_path / "lazy", per_category=3)
    assert lazy.missing(["cup"]) == [("cup", 0), ("cup", 1), ("cup", 2)]
    assert _draws(built, 7) == _draws(lazy, 7)
    # a fresh pool object reads the same files back
    assert _draws(AssetPool(tmp_path / "lazy", per_category=3), 7) == _draws(built, 7)
    again = built.build(["cup"], workers=1, progress=False)
    assert again.generated == 0 and again.cached == 3


def test_get_consumes_one_draw_and_uses_the_lru(tmp_path):
    pool = AssetPool(tmp_path, per_category=2)
    rng = np.random.default_rng(1)
    a = pool.get("cup", rng)
    ref = np.random.default_rng(1)
    ref.integers(2)
    assert rng.integers(1 << 30) == ref.integers(1 << 30)
    assert pool.load("cup", int(a.meta["seed"])) is a  # second load: served from memory


def test_parallel_build(tmp_path):
    pool = AssetPool(tmp_path, per_category=2)
    rep = pool.build(["cup", "mug"], workers=2, progress=False)
    assert rep.generated == 4 and not rep.failures
    assert set(rep.per_category) == {"cup", "mug"}
    assert pool.missing(["cup", "mug"]) == []


def test_damaged_entry_is_regenerated(tmp_path):
    pool = AssetPool(tmp_path, per_category=1)
    good = asset_digest(pool.load("cup", 0))
    pool.path("cup", 0).write_bytes(b"broken")
    assert asset_digest(AssetPool(tmp_path, per_category=1).load("cup", 0)) == good


def test_fingerprint_covers_the_private_helper_modules(monkeypatch):
    """Editing a shared helper (``generators/_kit.py``) retires the cached assets of every
    category built with it, through the modules that import it, and of no other."""
    from parse3d.assets import pool

    kit = "parse3d.assets.generators._kit"
    # appliances imports _kit directly and through _casework; clothing imports no helper
    assert {kit, "parse3d.assets.generators._casework"} <= set(
        pool._private_helpers("parse3d.assets.generators.appliances"))
    assert kit in pool._private_helpers("parse3d.assets.generators.casegoods")  # via _casework
    assert pool._private_helpers("parse3d.assets.generators.clothing") == ()
    before = {c: pool.category_fingerprint(c) for c in ("microwave", "clothes")}

    real = pool._module_source.__wrapped__
    monkeypatch.setattr(pool, "_module_source",
                        lambda m: real(m) + ("\n# edited\n" if m == kit else ""))
    pool._module_digest.cache_clear()
    try:
        after = {c: pool.category_fingerprint(c) for c in ("microwave", "clothes")}
    finally:
        monkeypatch.undo()
        pool._module_digest.cache_clear()
    assert after["microwave"] != before["microwave"]
    assert after["clothes"] == before["clothes"]


def _imports_by_full_parse(source: str) -> list[tuple[str | None, tuple[str, ...]]]:
    import ast

    return [(n.module, tuple(a.name for a in n.names)) for n in ast.walk(ast.parse(source))
            if isinstance(n, ast.ImportFrom) and n.level == 1]


def test_relative_import_scan_matches_a_whole_module_parse():
    """The fingerprint's cheap scan of relative imports finds exactly what parsing the whole
    module finds: on every generator module, and on the forms a module may use (parenthesised
    over several lines, backslash-continued, inside a function, an import-like line in a
    docstring)."""
    import pkgutil

    from parse3d.assets import generators, pool

    def scan(src):
        return [(n.module, tuple(a.name for a in n.names)) for n in pool._relative_imports(src)]

    names = [f"parse3d.assets.generators.{m.name}"
             for m in pkgutil.iter_modules(generators.__path__)]
    assert len(names) > 30
    for name in names:
        src = pool._module_source(name)
        assert sorted(scan(src), key=repr) == sorted(_imports_by_full_parse(src), key=repr), name
    src = ('"""Docs.\n\nfrom ._fake import (\n"""\n'
           "from ._kit import (rot,\n    legs4)\n"
           "from . import _rods, \\\n    _casework\n"
           "def f():\n    from ._household import ring  # late\n    return ring\n"
           "from .. import materials as M\n")
    assert sorted(scan(src), key=repr) == sorted(_imports_by_full_parse(src), key=repr)
    assert {m for m, _ in scan(src)} == {"_kit", None, "_household"}
