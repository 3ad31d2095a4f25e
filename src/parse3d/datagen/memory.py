"""Keeping a dataset worker's memory bounded over hundreds of scenes.

A worker builds scene after scene in one process, and every stage keeps what it derived from
an asset in a process cache: the asset itself (the pool's LRU), its convex collision pieces
(settling, contacts), its hull and centre of mass (solver, checks), its ray caster (checks), its
vertex buffer (rendering) and its FCL BVH per scale (solver). Each cache is bounded on its own,
but by counts sized for one interactive session, not for a worker that meets a few dozen new
assets in every scene: together they grew by about 50 MB per scene.

:func:`bound_caches` trims them all, oldest entries first, after every scene: the small
entries to :data:`LIGHT_CACHE_FACTOR` times a common number of assets, FCL BVHs and vertex
buffers to that number and two thirds of it. Caches only save work: what a scene comes out as never depends on them, so
trimming changes no output.
"""

from __future__ import annotations

import gc
import itertools
from collections import OrderedDict
from typing import Any

__all__ = ["DEFAULT_CACHED_ASSETS", "BVH_PER_ASSET", "LIGHT_CACHE_FACTOR", "bound_caches", "cache_sizes", "freeze_startup", "peak_rss_mb",
           "rss_mb"]

#: Assets whose derived data a worker keeps between scenes. Each costs about 0.6 MB over all
#: caches (the asset 0.2, its vertex buffer 0.25, collision pieces 0.1, the rest little) and
#: a miss costs 1-4 ms per cache; scenes draw from some 2,700 pool slots, and a scene meets
#: 40-60 assets it did not use in the scene before. Measured in one worker under load: with
#: 384 assets RSS levelled at about 670 MB, with 768 at about 950 MB (peak 1.2 GB), and CPU
#: per scene was the same; 512 keeps a margin below 1.5 GB over hundreds of scenes.
DEFAULT_CACHED_ASSETS = 512

#: The caches of small entries (the assets themselves, collision pieces, hulls, ray casters)
#: keep this many times ``assets``: together about 0.3 MB per asset, and a miss in all of
#: them costs about 2 ms. FCL BVHs (0.3 MB each) and vertex buffers (0.25 MB) keep to
#: ``assets`` and two thirds of it.
LIGHT_CACHE_FACTOR = 2.0

#: FCL BVHs are built per (asset, scale), about 0.3 MB each: objects whose node draws no
#: scale get the same scale in every scene, so they are reused across scenes too.
BVH_PER_ASSET = 1.0


def _trim(cache: dict, keep: int, on_drop=None) -> int:
    """Drop the oldest entries of ``cache`` (an LRU ``OrderedDict`` or an insertion-ordered
    ``dict``) until at most ``keep`` remain; returns how many were dropped."""
    excess = len(cache) - max(0, int(keep))
    if excess <= 0:
        return 0
    if isinstance(cache, OrderedDict):
        gone = [cache.popitem(last=False)[1] for _ in range(excess)]
    else:
        keys = list(itertools.islice(iter(cache), excess))
        gone = [cache.pop(k) for k in keys]
    if on_drop is not None:
        for v in gone:
            on_drop(v)
    return excess


def _caches(renderer) -> list[tuple[str, dict, float, Any]]:
    """``(name, cache, entries per asset, on_drop)`` of every per-asset cache in this process."""
    from ..assets.pool import default_pool
    from ..export import walk
    from ..measure import geometry
    from ..physics import collision
    from ..solver import collision as solver_collision

    k = LIGHT_CACHE_FACTOR
    out = [("assets", default_pool()._lru, k, None),
           ("collision", collision._CACHE, k, None),
           ("geometry", geometry._GEOM, 4.0 * k, None),
           ("ray casters", geometry._CASTERS, k, None),
           ("export hulls", walk._HULLS, 8.0 * k, None),
           ("bvh", solver_collision._BVH_CACHE, BVH_PER_ASSET, None)]
    if renderer is not None:  # vertex buffers are the largest entries: the newest two thirds
        out.append(("render meshes", renderer._meshes, 2.0 / 3.0, lambda v: v[1].release()))
    return out


def cache_sizes(renderer=None) -> dict[str, int]:
    """Entries of every per-asset cache of this process, by name."""
    return {name: len(c) for name, c, _, _ in _caches(renderer)}


#: Calls of :func:`bound_caches` between two full garbage collections: one costs about
#: 0.2 s CPU in a worker holding a few hundred assets' data, a tenth of a scene.
COLLECT_EVERY = 25
_calls = 0


def bound_caches(renderer=None, *, assets: int = DEFAULT_CACHED_ASSETS,
                 collect_every: int = COLLECT_EVERY) -> int:
    """Trim this process's per-asset caches to about ``assets`` assets each (oldest first).

    ``renderer``: the worker's :class:`parse3d.render.Renderer`, whose uploaded meshes are
    trimmed too (their GPU buffers released). Every ``collect_every`` calls (0: never) a full
    garbage collection runs; freed heap pages then go back to the system (glibc), so the
    resident size reflects what was dropped. Returns the number of entries dropped.
    """
    global _calls
    dropped = 0
    for _name, cache, per_asset, on_drop in _caches(renderer):
        dropped += _trim(cache, int(per_asset * assets), on_drop)
    if renderer is not None:
        renderer.cache_size = min(renderer.cache_size, max(int(2 * assets / 3), 1))
    _calls += 1
    if collect_every > 0 and _calls % int(collect_every) == 0:
        gc.collect()
    _malloc_trim()
    return dropped


def freeze_startup() -> None:
    """Move every object alive now (modules, the GL context, the scene source) out of the
    garbage collector's sight: a worker's full collections then only walk what its scenes
    made. Call once, after start-up."""
    gc.collect()
    gc.freeze()


def _malloc_trim() -> None:
    try:
        import ctypes

        ctypes.CDLL("libc.so.6").malloc_trim(0)
    except (OSError, AttributeError):  # not glibc: the memory is reused, not returned
        pass


def _status_mb(field: str) -> float | None:
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith(field + ":"):
                    return int(line.split()[1]) / 1024.0
    except (OSError, ValueError, IndexError):
        pass
    return None


def rss_mb() -> float | None:
    """This process's resident memory now, MB (None where ``/proc`` is missing)."""
    return _status_mb("VmRSS")


def peak_rss_mb() -> float | None:
    """This process's peak resident memory so far, MB (None where ``/proc`` is missing)."""
    return _status_mb("VmHWM")
