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
    MAX_FACES,
    MAX_SOURCE_BYTES,
    MAX_VERTICES,
    RawAsset,
    RawPart,
    SourceFrame,
    check_mapping_labels,
    check_part_mesh,
    check_raw_asset,
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
    _check_gltf_size(path)
    try:
        scene = trimesh.load(str(path), force="scene")
    except Exception as e:  # trimesh raises many types for a broken file
        raise InputError(Problem("", f"cannot read as glTF: {e}", file, "syntax")) from None
    R = frame.rotation()
    T_src = np.eye(4)
    T_src[:3, :3] = R * float(frame.unit_scale)
    parts, probs = [], []
    for node in sorted(scene.graph.nodes_geometry):
        T, geom_name = scene.graph[node]
        geom = scene.geometry.get(geom_name)
        if not isinstance(geom, trimesh.Trimesh) or len(geom.faces) == 0:
            continue
        label = label_for((node, geom_name) if node != geom_name else (node,), mapping)
        if label is None:
            continue
        mesh = geom.copy()
        bad = check_part_mesh(mesh, f"/nodes/{node}", file)
        if bad or not np.isfinite(T).all():
            probs += bad or [Problem(f"/nodes/{node}", "the node's transform is not finite",
                                     file, "geometry")]
            continue
        mesh.apply_transform(T_src @ T)
        material = material_of(geom)
        parts.append(RawPart(str(node), label, clean_mesh(mesh), material))
    if probs:
        raise InputError(probs)
    if len(parts) < 2:
        raise InputError(Problem("", f"found {len(parts)} mesh node(s); a part-split asset has one "
                                 "mesh node per part (at least two)", file, "geometry"))
    probs = part_label_problems(parts, vocabulary, file, "/nodes")
    if probs:
        raise InputError(probs)
    raw = RawAsset(file, parts, {"source_format": "gltf", "frame": frame.__dict__.copy()})
    check_raw_asset(raw, file)
    return raw


def _check_gltf_size(path: Path) -> None:
    """Refuse, before any mesh is built, a file larger than :data:`MAX_SOURCE_BYTES` or whose
    glTF JSON declares more than :data:`MAX_FACES` triangles or :data:`MAX_VERTICES` vertices
    (mesh instances counted once per node that uses them)."""
    import struct

    from ..._files import loads_json, read_input_bytes

    file = str(path)
    try:
        size = path.stat().st_size
    except OSError as e:
        raise InputError(Problem("", f"cannot read the file: {e.strerror}", file, "io")) from None
    if size > MAX_SOURCE_BYTES:
        raise InputError(Problem("", f"the file is {size / 2**20:.0f} MiB: an imported asset "
                                     f"may be at most {MAX_SOURCE_BYTES // 2**20} MiB", file,
                                 "io"))
    with open(path, "rb") as f:
        head = f.read(20)
    if path.suffix.lower() == ".glb" or head[:4] == b"glTF":
        if len(head) < 20 or head[:4] != b"glTF":
            raise InputError(Problem("", "not a GLB file (no glTF header)", file, "syntax"))
        n, kind = struct.unpack("<I4s", head[12:20])
        if kind != b"JSON" or n > size - 20:
            raise InputError(Problem("", "not a GLB file (no JSON chunk)", file, "syntax"))
        with open(path, "rb") as f:
            f.seek(20)
            raw = f.read(n)
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError:
            raise InputError(Problem("", "the GLB's JSON chunk is not UTF-8", file, "syntax")
                             ) from None
    else:
        text = read_input_bytes(path, limit=MAX_SOURCE_BYTES).decode("utf-8", "replace")
    try:
        doc = loads_json(text, file=file)
    except InputError as e:  # NaN in accessor bounds is how NaN vertices usually show
        msg = e.problems[0].message if e.problems else str(e)
        raise InputError(Problem("", f"the glTF JSON is damaged ({msg}): a NaN or infinite "
                                     "value means the mesh has non-finite vertices", file,
                                 "syntax")) from None
    if not isinstance(doc, dict):
        raise InputError(Problem("", "not a glTF document", file, "syntax"))
    faces, verts = _declared_counts(doc)
    if faces > MAX_FACES or verts > MAX_VERTICES:
        raise InputError(Problem("", f"the file declares {faces:,} triangles and {verts:,} "
                                     f"vertices: an imported asset may have at most "
                                     f"{MAX_FACES:,} faces and {MAX_VERTICES:,} vertices "
                                     "(simplify it first)", file, "geometry"))


def _declared_counts(doc: dict) -> tuple[int, int]:
    """(triangles, vertices) the glTF JSON declares, summed over the nodes that use meshes."""
    def count(i) -> int:
        acc = doc.get("accessors")
        if isinstance(i, int) and isinstance(acc, list) and 0 <= i < len(acc) \
                and isinstance(acc[i], dict) and isinstance(acc[i].get("count"), int):
            return max(0, acc[i]["count"])
        return 0

    per_mesh = []
    for m in doc.get("meshes") or []:
        f = v = 0
        for prim in (m.get("primitives") or []) if isinstance(m, dict) else []:
            if not isinstance(prim, dict):
                continue
            attrs = prim.get("attributes") if isinstance(prim.get("attributes"), dict) else {}
            n = count(attrs.get("POSITION"))
            v += n
            f += (count(prim["indices"]) if "indices" in prim else n) // 3
        per_mesh.append((f, v))
    faces = verts = 0
    uses = [n.get("mesh") for n in doc.get("nodes") or [] if isinstance(n, dict)]
    for i in uses or range(len(per_mesh)):
        if isinstance(i, int) and 0 <= i < len(per_mesh):
            faces += per_mesh[i][0]
            verts += per_mesh[i][1]
    return faces, verts


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
