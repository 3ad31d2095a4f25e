"""One least-recently-used mapping for the process caches of every layer.

Python's ``functools.lru_cache`` fits a pure function of hashable arguments; the caches here
are keyed by a content digest computed from an unhashable argument (an asset, a part's
arrays, a room shell), fill several entries in one pass, and are trimmed from outside
(``parse3d.datagen.memory`` bounds a dataset worker's caches after every scene). ``LRU`` is an
``OrderedDict``, oldest entry first, that a read through :meth:`LRU.get` refreshes and a write
beyond ``maxsize`` trims.
"""

from __future__ import annotations

from collections import OrderedDict
from typing import TypeVar

__all__ = ["LRU"]

K = TypeVar("K")
V = TypeVar("V")


class LRU(OrderedDict[K, V]):
    """A mapping that keeps at most ``maxsize`` entries (None: no bound), dropping the least
    recently read or written first.

    ``get`` counts as a use; ``cache[key]`` and ``key in cache`` do not (they are for the
    owner's own bookkeeping). Storing a key, new or not, makes it the newest.

    Examples
    --------
    >>> c = LRU(2)
    >>> c["a"], c["b"] = 1, 2
    >>> c.get("a")
    1
    >>> c["c"] = 3
    >>> list(c)
    ['a', 'c']
    """

    def __init__(self, maxsize: int | None = None) -> None:
        super().__init__()
        if maxsize is not None and maxsize < 0:
            raise ValueError("maxsize must be non-negative")
        self.maxsize = maxsize

    def get(self, key: K, default: V | None = None) -> V | None:  # type: ignore[override]
        try:
            value = super().__getitem__(key)
        except KeyError:
            return default
        self.move_to_end(key)
        return value

    def __setitem__(self, key: K, value: V) -> None:
        super().__setitem__(key, value)
        self.move_to_end(key)
        if self.maxsize is not None:
            while len(self) > self.maxsize:
                self.popitem(last=False)
