"""Part-labelled 3D assets: the model, the category registry, generators, loaders and caches.

* :mod:`.model` — :class:`Asset`, :class:`Part`, :class:`Material`, :class:`InternalSurface`.
* :mod:`.registry` — categories, ``generate(category, seed)``, the vocabulary PAGs are checked
  against.
* :mod:`.generators` — procedural generators, one module per family.
* :mod:`.loaders` — part-split GLB/glTF files, PartNet-Mobility folders, the user library.
* :mod:`.cache` — the on-disk asset format; :mod:`.pool` — the pre-built, deterministic pool.
* :mod:`.collision` — convex pieces (CoACD) for loaded meshes; :mod:`.contract` — the checks
  every asset passes; :mod:`.preview` — quick pictures.

See ``docs/assets.md``.
"""

from .cache import asset_digest, load_asset, save_asset
from .model import Asset, InternalSurface, Material, Part, finalize_asset, make_part
from .pool import AssetPool
from .registry import categories, generate, vocabulary

__all__ = [
    "Asset",
    "Part",
    "Material",
    "InternalSurface",
    "make_part",
    "finalize_asset",
    "categories",
    "generate",
    "vocabulary",
    "save_asset",
    "load_asset",
    "asset_digest",
    "AssetPool",
]
