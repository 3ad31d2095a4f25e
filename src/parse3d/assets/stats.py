"""Library statistics: how broad (categories, variants) and how fine (parts per asset) the asset
library is, which categories articulate, and how fast assets generate.

The pool's slot *i* of a category is ``registry.generate(category, seed=i)``, so measuring seeds
``0 .. n-1`` measures the first ``n`` slots of every pool.

Examples
--------
>>> s = library_stats(["mug", "filing_cabinet"], seeds=1)
>>> s.categories, "filing_cabinet" in s.articulated_categories
(2, True)
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable
from dataclasses import asdict, dataclass, field

import numpy as np

from . import registry

__all__ = ["LibraryStats", "library_stats", "reference_coverage", "PAPER_CATEGORIES",
           "PAPER_PARTS_PER_ASSET"]

#: PARSE-10K draws from 132 categories averaging 17.4 parts per object (the paper, Sec. 4).
PAPER_CATEGORIES = 132
PAPER_PARTS_PER_ASSET = 17.4


@dataclass
class LibraryStats:
    """What :func:`library_stats` measured.

    Attributes
    ----------
    categories, variants, assets : int
        Categories measured, their structural variants in total, assets generated.
    parts_per_asset_mean, parts_per_asset_p10, parts_per_asset_median : float
        Over every generated asset.
    joints_per_asset_mean : float
        Movable joints (mounts excluded) per asset.
    articulated_categories : list of str
        Categories where some generated asset has a movable joint.
    generation_ms_median, generation_ms_p90 : float
        Wall time of ``registry.generate`` per asset, milliseconds.
    per_category : dict
        ``{category: {"variants", "parts_mean", "joints_mean", "generation_ms_median"}}``.
    scannet200 : dict
        :func:`reference_coverage`: ScanNet200's object labels and how many resolve.
    """

    categories: int
    variants: int
    assets: int
    parts_per_asset_mean: float
    parts_per_asset_p10: float
    parts_per_asset_median: float
    joints_per_asset_mean: float
    articulated_categories: list[str]
    generation_ms_median: float
    generation_ms_p90: float
    per_category: dict[str, dict[str, float]] = field(default_factory=dict)
    scannet200: dict = field(default_factory=dict)
    paper: dict[str, float] = field(default_factory=lambda: {"categories": PAPER_CATEGORIES,
                                                              "parts_per_asset_mean": PAPER_PARTS_PER_ASSET})

    def to_dict(self) -> dict:
        return asdict(self)


def reference_coverage() -> dict:
    """How many of ScanNet200's object labels (its 200 indoor labels less those naming no
    movable or mountable object, ``parse3d/data/scannet200.json``) resolve to a category of
    the library, directly, through a synonym or a hypernym of the vocabulary file.

    Returns
    -------
    dict
        ``object_labels``, ``resolved`` (counts), ``fraction``, ``unresolved`` (labels),
        ``excluded`` (count) and ``source``.
    """
    from ..words import Resolver, reference_labels

    ref = reference_labels()
    words = Resolver(registry.vocabulary())
    objects = [x["label"] for x in ref["labels"] if x["label"] not in ref["excluded"]]
    missing = [x for x in objects if not words.categories_for(x)]
    return {"object_labels": len(objects), "resolved": len(objects) - len(missing),
            "fraction": round((len(objects) - len(missing)) / max(len(objects), 1), 4),
            "unresolved": missing, "excluded": len(ref["excluded"]), "source": ref["source"]}


def library_stats(categories: Iterable[str] | None = None, *, seeds: int = 3,
                  progress: Callable[[str], None] | None = None) -> LibraryStats:
    """Generate ``seeds`` assets of every category (seeds ``0 .. seeds-1``) and measure them.

    Parameters
    ----------
    categories : iterable of str, optional
        Default: every registered category.
    seeds : int
        Assets per category (the first pool slots).
    progress : callable, optional
        Called with each category name before it is measured.
    """
    cats = registry.categories()
    names = list(categories) if categories is not None else list(cats)
    parts: list[int] = []
    times: list[float] = []
    joints: list[int] = []
    articulated: list[str] = []
    per: dict[str, dict[str, float]] = {}
    for name in names:
        if progress is not None:
            progress(name)
        cp, cj, ct = [], [], []
        for s in range(seeds):
            t0 = time.perf_counter()
            a = registry.generate(name, s)
            ct.append(time.perf_counter() - t0)
            cp.append(len(a.parts))
            cj.append(sum(not j.is_mount for j in a.joints))
        if any(cj):
            articulated.append(name)
        per[name] = {"variants": len(cats[name].variants), "parts_mean": round(float(np.mean(cp)), 2),
                     "joints_mean": round(float(np.mean(cj)), 2),
                     "generation_ms_median": round(float(np.median(ct)) * 1000, 1)}
        parts += cp
        joints += cj
        times += ct
    p = np.asarray(parts, float) if parts else np.zeros(1)
    t = np.asarray(times, float) * 1000 if times else np.zeros(1)
    return LibraryStats(
        categories=len(names), variants=int(sum(len(cats[n].variants) for n in names)), assets=len(parts),
        parts_per_asset_mean=round(float(p.mean()), 2), parts_per_asset_p10=round(float(np.percentile(p, 10)), 2),
        parts_per_asset_median=round(float(np.median(p)), 2),
        joints_per_asset_mean=round(float(np.mean(joints)) if joints else 0.0, 2),
        articulated_categories=articulated, generation_ms_median=round(float(np.median(t)), 1),
        generation_ms_p90=round(float(np.percentile(t, 90)), 1), per_category=per,
        scannet200=reference_coverage())
