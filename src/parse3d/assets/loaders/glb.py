"""Part-split GLB / glTF files: one mesh node per part.

Each mesh node becomes a part. Its label comes from the node name through an optional mapping
(``{"SeatCushion": "seat", "Armrest_L": "armrest", "Light": null}``); without a mapping entry the
node name with trailing indices stripped is the label (``leg_2`` and ``leg.001`` give ``leg``).
Node transforms are applied. glTF is +Y up with the front facing +Z (glTF 2.0 specification);
another convention is given with a :class:`SourceFrame`.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import trimesh

from ...errors import InputError, Problem
from ..model import Asset
from ._canon import (
    GLTF_FRAME,
    RawAsset,
    RawPart,
    SourceFrame,
    check_mapping_labels,
    clean_mesh,
    finish_asset,
    label_for,
    material_of,
    part_label_problems,
    read_mapping,
)

__all__ = ["read_glb", "load_glb"]


def read_glb(path: str | os.PathLike, *, mapping=None, frame: SourceFrame = GLTF_FRAME,
             vocabulary: tuple[str, ...] | None = None) -> RawAsset:
    """Read a part-split GLB/glTF into a :class:`RawAsset` (canonical orientation, metres).

    Raises
    ------
    InputError
        The file is missing or unreadable, has fewer than two mesh nodes (not part-split), or
        a label falls outside ``vocabulary``.
    """
    path = Path(path)
    file = str(path)
    if not path.is_file():
        raise InputError(Problem("", "file not found", file, "io"))
    mapping, mfile = read_mapping(mapping)
    check_mapping_labels(mapping, vocabulary, mfile)
    try:
        scene = trimesh.load(str(path), force="scene")
    except Exception as e:  # trimesh raises many types for a broken file
        raise InputError(Problem("", f"cannot read as glTF: {e}", file, "syntax")) from None
    R = frame.rotation()
    T_src = np.eye(4)
    T_src[:3, :3] = R * float(frame.unit_scale)
    parts = []
    for node in sorted(scene.graph.nodes_geometry):
        T, geom_name = scene.graph[node]
        geom = scene.geometry.get(geom_name)
        if not isinstance(geom, trimesh.Trimesh) or len(geom.faces) == 0:
            continue
        label = label_for((node, geom_name) if node != geom_name else (node,), mapping)
        if label is None:
            continue
        mesh = geom.copy()
        mesh.apply_transform(T_src @ T)
        material = material_of(geom)
        parts.append(RawPart(str(node), label, clean_mesh(mesh), material))
    if len(parts) < 2:
        raise InputError(Problem("", f"found {len(parts)} mesh node(s); a part-split asset has one "
                                 "mesh node per part (at least two)", file, "geometry"))
    probs = part_label_problems(parts, vocabulary, file, "/nodes")
    if probs:
        raise InputError(probs)
    return RawAsset(file, parts, {"source_format": "gltf", "frame": frame.__dict__.copy()})


def load_glb(path: str | os.PathLike, *, category: str, mapping=None,
             frame: SourceFrame = GLTF_FRAME, size_range: tuple[float, float] | None = None,
             density: float | None = None, asset_id: str | None = None,
             cache_dir: str | os.PathLike | None = None) -> Asset:
    """Load a part-split GLB/glTF as an asset of ``category``.

    Parameters
    ----------
    path : path
        The ``.glb`` / ``.gltf`` file.
    category : str
        The category; when it is registered its vocabulary, size range and density apply.
    mapping : dict or path, optional
        Node name (or stripped node name) to part label; ``null`` drops the node.
    frame : SourceFrame
        The file's up axis, front axis and units (default: glTF, +Y up, front +Z, metres).
    size_range : (low, high), optional
        Overrides the category's; the asset is scaled into it when outside.
    density : float, optional
    asset_id : str, optional
        Defaults to ``<category>-<file stem>``.
    cache_dir : path, optional
        Where convex decompositions are cached.
    """
    vocab, sr, dens = _category_defaults(category)
    raw = read_glb(path, mapping=mapping, frame=frame, vocabulary=vocab)
    return finish_asset(raw, category=category,
                        asset_id=asset_id or f"{category}-{Path(path).stem}",
                        size_range=size_range or sr, density=density or dens or 500.0,
                        cache_dir=cache_dir)


def _category_defaults(category: str):
    from .. import registry

    try:
        cat = registry.get(category)
    except KeyError:
        return None, None, None
    return cat.vocabulary, cat.size_range, cat.density
