"""The contract every registered category honours (procedural or loaded).

One parametrized test over every category x two seeds, cycling through the category's
variants so each variant is generated at least once.
"""

from __future__ import annotations

import pytest

from parse3d.assets import registry
from parse3d.assets.cache import asset_digest
from parse3d.assets.contract import check_asset


def _cases():
    cases = []
    for name, cat in registry.categories().items():
        variants = cat.variants if cat.generator is not None else (None,)
        for i in range(max(2, len(variants))):
            cases.append(pytest.param(name, i, variants[i % len(variants)], id=f"{name}-{i}"))
    return cases


@pytest.mark.parametrize(("category", "seed", "variant"), _cases())
def test_asset_contract(category: str, seed: int, variant: str | None) -> None:
    cat = registry.get(category)
    asset = registry.generate(category, seed, variant)
    problems = check_asset(asset)
    assert not problems, f"{asset.asset_id}:\n" + "\n".join(problems)
    lo, hi = cat.size_range
    assert lo - 1e-6 <= asset.size <= hi + 1e-6
    # every required label names parts, directly or as a group label over finer parts
    assert all(asset.parts_by_label(r) for r in cat.parts)
    assert asset.category == category
    if variant is not None:
        assert asset.meta["variant"] == variant
    if seed == 0:  # once per category: the same seed gives the same asset, byte for byte
        assert asset_digest(registry.generate(category, seed, variant)) == asset_digest(asset)
