"""Where the solver gets assets: a deterministic pool of generated assets per category."""

from __future__ import annotations

import numpy as np

from ..assets.model import Asset

__all__ = ["AssetLibrary", "DEFAULT_PER_CATEGORY"]

DEFAULT_PER_CATEGORY = 20


class AssetLibrary:
    """A pool of ``per_category`` assets per category, generated on demand and kept in memory.

    ``get(category, rng)`` draws an index in ``[0, per_category)`` from ``rng`` and returns the
    asset generated with that seed, so results do not depend on what was generated before.
    The on-disk :class:`parse3d.assets.pool.AssetPool` offers the same ``get``.
    """

    def __init__(self, per_category: int = DEFAULT_PER_CATEGORY):
        self.per_category = int(per_category)
        self._cache: dict[tuple[str, int], Asset] = {}

    def get(self, category: str, rng: np.random.Generator) -> Asset:
        """Slot ``rng.integers(per_category)`` of ``category`` (one integer draw)."""
        return self.load(category, int(rng.integers(self.per_category)))

    def load(self, category: str, seed: int) -> Asset:
        """The asset of slot ``seed``."""
        from ..assets import registry

        key = (category, int(seed))
        if key not in self._cache:
            self._cache[key] = registry.generate(category, seed=int(seed))
        return self._cache[key]


def default_library():
    """The library used when ``solve`` is given none: the on-disk asset pool
    (:func:`parse3d.assets.pool.default_pool`), so each asset is generated once per machine."""
    from ..assets.pool import default_pool

    return default_pool()
