"""A deterministic, disk-backed pool of assets per category.

Each category has ``K`` pool slots (default :data:`DEFAULT_PER_CATEGORY` = 20); slot ``i`` holds
the asset ``registry.generate(category, seed=i)``. :meth:`AssetPool.get` draws a slot index in
``[0, K)`` from the caller's ``rng`` and returns that slot's asset: loaded from the cache when it
was built before, generated (and cached) otherwise. Both paths return the asset as read back from
its file, so the result depends only on the rng state, ``K`` and the asset library — never on
whether :meth:`AssetPool.build` ran first.

Files live under ``<root>/<category>/<seed>-<fingerprint>.npz``; the fingerprint hashes the
source of the category's generator module, of the private helper modules it imports
(``generators/_kit.py``…) and of the shared geometry code, so editing a generator or a helper
quietly retires its old pool entries instead of serving stale assets.

Examples
--------
>>> pool = AssetPool()                                        # doctest: +SKIP
>>> pool.build(["mug"], per_category=4, workers=1, progress=False)  # doctest: +SKIP
>>> pool.get("mug", np.random.default_rng(0)).asset_id         # doctest: +SKIP
'mug-square-3'
"""

from __future__ import annotations

import ast
import hashlib
import inspect
import os
import re
import sys
import textwrap
import time
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np

from .._lru import LRU
from ..errors import AssetError
from . import registry
from .cache import FORMAT, load_asset, save_asset
from .model import Asset

__all__ = ["AssetPool", "BuildReport", "DEFAULT_PER_CATEGORY", "category_fingerprint", "default_pool"]

#: Pool slots per category: the asset variety a scene can draw from.
DEFAULT_PER_CATEGORY = 20

_SHARED_SOURCES = ("geometry.shapes", "geometry.surfaces", "assets.model", "assets.internal",
                   "assets.materials", "assets.registry", "assets.cache")


@cache
def _module_source(module_name: str) -> str:
    """The module's source text (the module's name when it cannot be read)."""
    mod = sys.modules.get(module_name)
    if mod is None:
        # read the source without importing the module (generators import trimesh): the same
        # text ``inspect.getsource`` gives, newlines translated and a last newline added
        import importlib.util
        import tokenize

        try:
            spec = importlib.util.find_spec(module_name)
            with tokenize.open(spec.origin) as fh:
                src = fh.read()
            if src and not src.endswith("\n"):
                src += "\n"
        except (OSError, TypeError, AttributeError, SyntaxError, ImportError, ValueError):
            src = module_name
        return src
    try:
        return inspect.getsource(mod)
    except (OSError, TypeError):
        return module_name


@cache
def _module_digest(module_name: str) -> bytes:
    return hashlib.sha256(_module_source(module_name).encode("utf-8")).digest()


#: The start of a relative import statement (``from . import x``, ``from ._kit import y``):
#: only these lines are parsed when looking for a module's private helpers.
_RELATIVE_IMPORT = re.compile(r"^[ \t]*from[ \t]+\.[\w.]*[ \t]+import\b", re.MULTILINE)


def _relative_imports(source: str) -> list[ast.ImportFrom]:
    """The relative ``from ... import`` statements of ``source``, as parsed nodes: each
    statement the pattern finds is parsed on its own (parenthesised and backslash-continued
    names included), which is ~50x cheaper than parsing the whole module; a match that does
    not parse alone (text in a string) is skipped."""
    out = []
    for m in _RELATIVE_IMPORT.finditer(source):
        end = m.end()
        while True:
            nl = source.find("\n", end)
            line = source[m.start():len(source) if nl < 0 else nl]
            if line.count("(") > line.count(")") or line.rstrip().endswith("\\"):
                if nl < 0:
                    break
                end = nl + 1
                continue
            break
        try:
            tree = ast.parse(textwrap.dedent(line))
        except SyntaxError:
            continue
        out += [n for n in tree.body if isinstance(n, ast.ImportFrom) and n.level == 1]
    return out


@cache
def _private_helpers(module_name: str) -> tuple[str, ...]:
    """The private sibling modules (``_kit``, ``_casework``…) that ``module_name`` imports,
    directly or through one another, sorted: their code shapes the assets as much as the
    generator's own."""
    package = module_name.rpartition(".")[0]
    seen: set[str] = set()
    todo = [module_name]
    while todo:
        for node in _relative_imports(_module_source(todo.pop())):
            names = [node.module] if node.module else [a.name for a in node.names]
            for n in names:
                if n.startswith("_") and (dep := f"{package}.{n}") not in seen:
                    seen.add(dep)
                    todo.append(dep)
    return tuple(sorted(seen))


def category_fingerprint(category: str) -> str:
    """8 hex digits identifying the code that generates ``category``'s assets: the generator's
    module, the private helper modules it imports (``generators/_kit.py``…) and the shared
    geometry code.

    For a category with loaded assets the file list counts as well (adding assets changes
    which asset a seed draws).
    """
    cat = registry.get(category)
    h = hashlib.sha256(FORMAT.encode())
    for name in _SHARED_SOURCES:
        h.update(_module_digest(f"parse3d.{name}"))
    if cat.generator is not None:
        h.update(_module_digest(cat.generator.__module__))
        for helper in _private_helpers(cat.generator.__module__):
            h.update(_module_digest(helper))
    for p in cat.loaded_assets:
        h.update(str(p).encode())
    return h.hexdigest()[:8]


@dataclass
class BuildReport:
    """What :meth:`AssetPool.build` did.

    Attributes
    ----------
    generated, cached : int
        Assets generated now, and slots that were already in the pool.
    seconds : float
        Wall time.
    per_category : dict of str to float
        Median generation time per asset for each category, seconds (generated ones only).
    failures : dict of str to str
        ``"category/seed"`` to the error, for assets that could not be generated.
    """

    generated: int
    cached: int
    seconds: float
    per_category: dict[str, float]
    failures: dict[str, str]


def _build_one(root: str, category: str, seed: int, fingerprint: str) -> tuple[str, int, float, str]:
    """Generate and cache one slot (runs in a worker process)."""
    t = time.perf_counter()
    try:
        asset = registry.generate(category, seed)
        save_asset(asset, Path(root) / category / f"{seed}-{fingerprint}.npz")
    except Exception as e:  # reported per slot; one broken asset must not stop the build
        return category, seed, time.perf_counter() - t, f"{type(e).__name__}: {e}"
    return category, seed, time.perf_counter() - t, ""


class AssetPool:
    """Pre-generated assets per category, with an in-memory LRU on top of the disk cache.

    Parameters
    ----------
    root : path, optional
        Pool folder; defaults to ``cache_dir()/pool``.
    per_category : int
        ``K``: the number of slots :meth:`get` draws from.
    memory : int
        How many assets the in-memory LRU keeps.

    Notes
    -----
    Assets returned by :meth:`get` are shared with the LRU: treat them as read-only (move
    copies, or pose them with transforms).
    """

    def __init__(self, root: str | os.PathLike | None = None, *,
                 per_category: int = DEFAULT_PER_CATEGORY, memory: int = 1024):
        if root is None:
            from .library import cache_dir

            root = cache_dir() / "pool"
        if per_category < 1:
            raise ValueError("per_category must be at least 1")
        self.root = Path(root)
        self.per_category = int(per_category)
        self.memory = int(memory)
        self._lru: LRU[tuple[str, int], Asset] = LRU(self.memory)
        self._fp: dict[str, str] = {}

    def _fingerprint(self, category: str) -> str:
        fp = self._fp.get(category)
        if fp is None:
            fp = self._fp[category] = category_fingerprint(category)
        return fp

    def path(self, category: str, seed: int) -> Path:
        """Cache file of slot ``seed`` of ``category``."""
        return self.root / category / f"{int(seed)}-{self._fingerprint(category)}.npz"

    def load(self, category: str, seed: int) -> Asset:
        """The asset of slot ``seed`` (any non-negative int): cached, or generated and cached."""
        key = (category, int(seed))
        hit = self._lru.get(key)
        if hit is not None:
            return hit
        path = self.path(category, seed)
        asset = None
        if path.is_file():
            try:
                asset = load_asset(path)
            except AssetError:
                asset = None  # damaged or outdated entry: regenerate it below
        if asset is None:
            save_asset(registry.generate(category, int(seed)), path)
            # read the file back so an on-demand asset equals a pre-built one bit for bit
            asset = load_asset(path)
        self._lru[key] = asset
        return asset

    def get(self, category: str, rng: np.random.Generator) -> Asset:
        """Draw an asset of ``category``: slot ``rng.integers(K)``.

        Consumes exactly one integer draw from ``rng``.
        """
        registry.get(category)  # unknown category: KeyError with a suggestion
        seed = int(rng.integers(self.per_category))
        return self.load(category, seed)

    def missing(self, categories: list[str] | None = None,
                per_category: int | None = None) -> list[tuple[str, int]]:
        """Slots not yet in the pool."""
        cats = list(categories) if categories is not None else list(registry.categories())
        k = self.per_category if per_category is None else int(per_category)
        return [(c, s) for c in cats for s in range(k) if not self.path(c, s).is_file()]

    def build(self, categories: list[str] | None = None, *, per_category: int | None = None,
              workers: int = 2, progress: bool = True) -> BuildReport:
        """Pre-generate ``per_category`` slots of each category in parallel.

        Parameters
        ----------
        categories : list of str, optional
            Default: every registered category.
        per_category : int, optional
            Default: the pool's ``K``.
        workers : int
            Worker processes (1 runs in this process).
        progress : bool
            Show a rich progress bar.
        """
        cats = list(categories) if categories is not None else list(registry.categories())
        for c in cats:
            registry.get(c)
        k = self.per_category if per_category is None else int(per_category)
        todo = self.missing(cats, k)
        cached = len(cats) * k - len(todo)
        t0 = time.perf_counter()
        times: dict[str, list[float]] = {}
        failures: dict[str, str] = {}

        def record(cat: str, seed: int, dt: float, err: str) -> None:
            if err:
                failures[f"{cat}/{seed}"] = err
            else:
                times.setdefault(cat, []).append(dt)

        bar = None
        task = None
        if progress and todo:
            from rich.progress import (
                BarColumn,
                MofNCompleteColumn,
                Progress,
                TextColumn,
                TimeRemainingColumn,
            )

            bar = Progress(TextColumn("assets"), BarColumn(), MofNCompleteColumn(),
                           TimeRemainingColumn(), TextColumn("{task.description}"), transient=False)
            bar.start()
            task = bar.add_task("", total=len(todo))
        try:
            args = [(str(self.root), c, s, self._fingerprint(c)) for c, s in todo]
            if workers <= 1 or len(todo) <= 1:
                for a in args:
                    record(*_build_one(*a))
                    if bar is not None:
                        bar.update(task, advance=1, description=a[1])
            else:
                import multiprocessing as mp
                from concurrent.futures import ProcessPoolExecutor, as_completed

                # fork server: never fork a process whose threads may hold locks
                with ProcessPoolExecutor(max_workers=int(workers),
                                         mp_context=mp.get_context("forkserver")) as ex:
                    futs = [ex.submit(_build_one, *a) for a in args]
                    for f in as_completed(futs):
                        r = f.result()
                        record(*r)
                        if bar is not None:
                            bar.update(task, advance=1, description=r[0])
        finally:
            if bar is not None:
                bar.stop()
        med = {c: float(np.median(v)) for c, v in sorted(times.items())}
        return BuildReport(sum(len(v) for v in times.values()), cached, time.perf_counter() - t0,
                           med, failures)


_DEFAULT_POOL: AssetPool | None = None


def default_pool() -> AssetPool:
    """The process-wide pool under ``cache_dir()/pool`` (what the solver uses by default)."""
    global _DEFAULT_POOL
    if _DEFAULT_POOL is None:
        _DEFAULT_POOL = AssetPool()
    return _DEFAULT_POOL
