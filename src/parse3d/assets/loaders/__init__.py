"""Loaders for real part-split assets and the user asset library.

* :func:`load_glb` — part-split GLB/glTF files (one mesh node per part).
* :func:`load_partnet_mobility` — PartNet-Mobility-style folders (URDF + OBJs + semantics).
* :func:`add_assets` / :func:`register_library` — the user library behind
  ``parse3d assets add`` and the registry's start-up.

Every loader canonicalises units, up axis and front direction (:class:`SourceFrame`),
recentres, decomposes parts into convex pieces (CoACD, cached) and resolves surfaces.
"""

from ._canon import (
    GLTF_FRAME,
    PARTNET_FRAME,
    RawAsset,
    RawPart,
    SourceFrame,
    default_label,
    frame_rotation,
)
from .glb import load_glb, read_glb
from .library import CATEGORY_FORMAT, add_assets, find_sources, register_library
from .partnet import is_partnet_folder, load_partnet_mobility, read_partnet_mobility

__all__ = [
    "SourceFrame",
    "GLTF_FRAME",
    "PARTNET_FRAME",
    "RawAsset",
    "RawPart",
    "default_label",
    "frame_rotation",
    "load_glb",
    "read_glb",
    "load_partnet_mobility",
    "read_partnet_mobility",
    "is_partnet_folder",
    "add_assets",
    "find_sources",
    "register_library",
    "CATEGORY_FORMAT",
]
