"""The category registry: every asset category, its part vocabulary, size range and generator.

Procedural generators register themselves with :func:`register`; modules under
``parse3d.assets.generators`` are imported on first use. Categories added from folders of real
assets (``parse3d assets add``) are registered through :func:`register_loaded`. The PAG
validator reads category names and part labels from here (:func:`vocabulary`).

Examples
--------
>>> from parse3d.assets import registry
>>> asset = registry.generate("mug", seed=3)
>>> sorted({p.label for p in asset.parts}) >= ["body", "handle"]
True
"""

from __future__ import annotations

import importlib
import pkgutil
import zlib
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ..errors import AssetError
from .model import Asset, Joint, Part, finalize_asset

__all__ = [
    "Category",
    "register",
    "register_loaded",
    "categories",
    "get",
    "generate",
    "vocabulary",
    "Vocabulary",
    "category_rng",
    "catalog",
    "install_catalog",
]

#: ``generator(rng, variant)`` returns the asset's parts, each optionally followed by the
#: :class:`~parse3d.assets.model.Joint` objects articulating them (doors, drawers, lids).
Generator = Callable[[np.random.Generator, str], list[Part | Joint]]

#: Typical supports of a category, used by templates and the demo (not a constraint).
PLACEMENTS = ("floor", "surface", "wall", "ceiling", "inside")


@dataclass(frozen=True)
class Category:
    """An asset category.

    Attributes
    ----------
    name : str
    parts : tuple of str
        Part labels every asset of the category has (what PAGs may refer to).
    vocabulary : tuple of str
        Every part label an asset of the category may have (a superset of ``parts``).
    size_range : (low, high), metres
        Real-world range of the asset's largest bbox extent.
    density : float
        kg / m^3 of the solid collision volume.
    variants : tuple of str
        Structural variants of the generator.
    placement : str
        Typical support: ``floor``, ``surface``, ``wall``, ``ceiling`` or ``inside``.
    generator : callable or None
        ``generator(rng, variant) -> list[Part]``; None for loaded categories.
    source : str
        ``procedural`` or the folder a loaded category came from.
    groups : dict of str to tuple of str
        Group labels: a label a PAG may name that covers the parts of several labels (a plate's
        ``body`` is its ``well`` and its ``rim``). Kept where a category's parts were split
        finer, so the labels PAGs used before still name the same geometry.
    """

    name: str
    parts: tuple[str, ...]
    vocabulary: tuple[str, ...]
    size_range: tuple[float, float]
    density: float
    variants: tuple[str, ...] = ("default",)
    placement: str = "floor"
    generator: Generator | None = field(default=None, compare=False, repr=False)
    source: str = "procedural"
    loaded_assets: tuple = field(default=(), compare=False, repr=False)
    groups: dict[str, tuple[str, ...]] = field(default_factory=dict, compare=False)


_REGISTRY: dict[str, Category] = {}
_DISCOVERED = False
#: Categories known from a catalog snapshot (:func:`install_catalog`), answered by :func:`get`
#: without importing any generator until one is needed.
_KNOWN: dict[str, Category] = {}


def register(
    name: str,
    *,
    parts: tuple[str, ...],
    size_range: tuple[float, float],
    density: float,
    variants: tuple[str, ...] = ("default",),
    placement: str = "floor",
    extra_parts: tuple[str, ...] = (),
    groups: dict[str, tuple[str, ...]] | None = None,
) -> Callable[[Generator], Generator]:
    """Decorator registering a procedural generator for a category.

    The generator takes ``(rng, variant)`` and returns the asset's parts in any placement, with
    the joints that articulate them mixed in (a door's revolute joint after the door); the
    registry recentres the asset (joints too), resolves surfaces and finds internal support
    surfaces.

    ``groups`` maps a group label to the part labels it covers (see :class:`Category`); a group
    label joins the vocabulary, and a required label may be a group label.
    """
    if placement not in PLACEMENTS:
        raise ValueError(f"placement must be one of {PLACEMENTS}")
    groups = {str(k): tuple(v) for k, v in (groups or {}).items()}

    def deco(fn: Generator) -> Generator:
        vocab = tuple(dict.fromkeys(parts + extra_parts + tuple(groups)
                                    + tuple(m for v in groups.values() for m in v)))
        _REGISTRY[name] = Category(name, tuple(parts), vocab, tuple(size_range), float(density),
                                   tuple(variants), placement, fn, groups=groups)
        return fn

    return deco


def register_loaded(category: Category) -> None:
    """Register (or replace) a category whose assets were loaded from files."""
    _REGISTRY[category.name] = category


def _discover() -> None:
    global _DISCOVERED
    if _DISCOVERED:
        return
    _DISCOVERED = True
    from . import generators

    for mod in pkgutil.iter_modules(generators.__path__):
        importlib.import_module(f"{generators.__name__}.{mod.name}")
    from .library import load_user_library

    load_user_library()


def categories() -> dict[str, Category]:
    """All registered categories by name, sorted."""
    _discover()
    return dict(sorted(_REGISTRY.items()))


def get(name: str) -> Category:
    """A category by name; KeyError with suggestions when unknown."""
    if not _DISCOVERED and name in _KNOWN:
        return _KNOWN[name]
    _discover()
    try:
        return _REGISTRY[name]
    except KeyError:
        import difflib

        close = difflib.get_close_matches(name, list(_REGISTRY), n=1)
        hint = f" — did you mean {close[0]!r}?" if close else ""
        raise KeyError(f"unknown category {name!r}{hint}") from None


def category_rng(category: str, seed: int, stage: str = "asset") -> np.random.Generator:
    """The generator for (category, seed, stage): stable across runs and platforms."""
    return np.random.default_rng([int(seed), zlib.crc32(category.encode()), zlib.crc32(stage.encode())])


def generate(category: str, seed: int = 0, variant: str | None = None) -> Asset:
    """Generate one asset of ``category`` from ``seed`` (and optionally a fixed variant).

    The same (category, seed, variant) always gives the same asset.
    """
    cat = get(category)
    # a procedural category with added real assets mixes them: odd seeds draw a loaded asset
    if cat.generator is None or (cat.loaded_assets and int(seed) % 2 == 1):
        if not cat.loaded_assets:
            raise AssetError(f"category {category!r} has no generator and no loaded assets")
        from .cache import load_asset

        k = int(seed) if cat.generator is None else int(seed) // 2
        return load_asset(cat.loaded_assets[k % len(cat.loaded_assets)])
    rng = category_rng(category, seed)
    # the variant is always drawn, so naming the drawn variant gives the same asset (scene.json)
    drawn = str(cat.variants[int(rng.integers(len(cat.variants)))])
    if variant is None:
        variant = drawn
    elif variant not in cat.variants:
        raise AssetError(f"category {category!r} has no variant {variant!r} "
                         f"(variants: {', '.join(cat.variants)})")
    try:
        built = cat.generator(rng, variant)
    except Exception as e:  # a generator bug must say which asset broke
        raise AssetError(f"generating {category} (variant {variant}, seed {seed}) failed: {e}") from e
    parts = [x for x in built if isinstance(x, Part)]
    joints = [x for x in built if isinstance(x, Joint)]
    names = [p.name for p in parts]
    if len(set(names)) != len(names):
        raise AssetError(f"{category}: duplicate part names {names}")
    meta = {"generator": "procedural", "variant": variant, "seed": int(seed)}
    if cat.groups:
        meta["label_groups"] = {k: list(v) for k, v in cat.groups.items()}
    asset = Asset(category, f"{category}-{variant}-{seed}", parts, cat.size_range, cat.density,
                  meta=meta, joints=joints)
    return finalize_asset(asset)


class _Deferred:
    """The generator of a category known from a catalog: the first call imports the generators
    and runs the real one. ``__module__`` names the real one's module (for the pool's
    fingerprint)."""

    def __init__(self, name: str, module: str):
        self.name = name
        self.__module__ = module

    def __call__(self, rng: np.random.Generator, variant: str) -> list[Part | Joint]:
        _discover()
        return _REGISTRY[self.name].generator(rng, variant)


def catalog() -> dict[str, dict]:
    """Every category as plain JSON data, for :func:`install_catalog` in a later process."""
    out = {}
    for name, c in categories().items():
        out[name] = {"parts": list(c.parts), "vocabulary": list(c.vocabulary),
                     "size_range": [float(x) for x in c.size_range], "density": float(c.density),
                     "variants": list(c.variants), "placement": c.placement, "source": c.source,
                     "module": None if c.generator is None else c.generator.__module__,
                     "loaded": [str(p) for p in c.loaded_assets]}
    return out


def install_catalog(data: dict[str, dict]) -> None:
    """Know the categories of ``data`` (from :func:`catalog`) without importing generators.

    :func:`get` answers from it until something needs every category (:func:`categories`) or
    a generator runs; then the generators are imported as usual and the registry's own
    categories take over. The caller vouches that ``data`` is current (the CLI keys its
    snapshot by the source files it depends on).
    """
    from pathlib import Path

    known = {}
    for name, d in data.items():
        known[name] = Category(
            name, tuple(d["parts"]), tuple(d["vocabulary"]), tuple(d["size_range"]),
            float(d["density"]), tuple(d["variants"]), d["placement"],
            None if d["module"] is None else _Deferred(name, d["module"]), d["source"],
            tuple(Path(p) for p in d["loaded"]))
    _KNOWN.update(known)


class Vocabulary:
    """What the PAG validator checks category names and part labels against."""

    def __init__(self, cats: dict[str, Category]):
        self._cats = cats

    def categories(self) -> list[str]:
        return list(self._cats)

    def has_category(self, name: str) -> bool:
        return name in self._cats

    def parts(self, category: str) -> tuple[str, ...]:
        return self._cats[category].vocabulary


def vocabulary() -> Vocabulary:
    """The current vocabulary (procedural and loaded categories); from the installed catalog
    (:func:`install_catalog`) while no generator has been imported."""
    if not _DISCOVERED and _KNOWN:
        return Vocabulary(dict(sorted(_KNOWN.items())))
    return Vocabulary(categories())
