"""A result kept per argument object (by identity), for data derived from long-lived geometry."""

from __future__ import annotations

from collections.abc import Callable
from functools import wraps
from typing import Any, TypeVar

__all__ = ["per_object"]

F = TypeVar("F", bound=Callable[[Any], Any])


def per_object(limit: int = 4096) -> Callable[[F], F]:
    """Decorate a one-argument function so that its result is kept per argument *object*:
    a support's region is eroded again and again, a surface's plane key is asked for by every
    child. The argument is held with its result (which keeps its ``id`` valid); the cache is
    emptied when it grows past ``limit`` entries."""

    def deco(fn: F) -> F:
        cache: dict[int, tuple] = {}

        @wraps(fn)
        def kept(obj):
            got = cache.get(id(obj))
            if got is not None and got[0] is obj:
                return got[1]
            if len(cache) > limit:
                cache.clear()
            out = fn(obj)
            cache[id(obj)] = (obj, out)
            return out

        return kept  # type: ignore[return-value]

    return deco
