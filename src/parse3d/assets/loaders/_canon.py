"""Shared steps of every loader: source frames, part labels, and canonicalisation.

A loader reads a file into a :class:`RawAsset` (part meshes already in the canonical
orientation and in metres, labels resolved), then :func:`finish_asset` fits the size range,
recentres, computes convex pieces and resolves surfaces.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import trimesh

from ..._files import MAX_DEPTH, loads_json, read_input_text
from ...errors import AssetError, InputError, Problem
from ..collision import convex_pieces
from ..model import Asset, Joint, Material, Part, finalize_asset

__all__ = ["SourceFrame", "RawPart", "RawAsset", "frame_rotation", "default_label", "read_mapping",
           "label_for", "finish_asset", "material_of", "GLTF_FRAME", "PARTNET_FRAME",
           "MAX_FACES", "MAX_VERTICES", "MAX_PARTS", "MAX_SOURCE_BYTES", "check_part_mesh"]

#: Most triangles an imported asset may have (all parts together, instances counted).
MAX_FACES = 1_000_000
#: Most vertices an imported asset may have (all parts together).
MAX_VERTICES = 1_000_000
#: Most parts (mesh nodes or URDF links with geometry) an imported asset may have.
MAX_PARTS = 256
#: Largest mapping file read.
MAX_MAPPING_BYTES = 1024 * 1024
#: Largest source file read (a GLB, a glTF and its buffers, one OBJ of a PartNet folder).
MAX_SOURCE_BYTES = 512 * 1024 * 1024

_AXES = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}


@dataclass(frozen=True)
class SourceFrame:
    """How a source file's coordinates relate to parse3d's canonical asset frame.

    Attributes
    ----------
    up : str
        The source axis that points up: ``"+z"``, ``"+y"``, ``"-x"``... (a bare ``"z"`` means
        ``"+z"``).
    front : str
        The source axis the object's front faces; must be perpendicular to ``up``.
    unit_scale : float
        Metres per source unit (``0.01`` for centimetres).
    """

    up: str = "+z"
    front: str = "+y"
    unit_scale: float = 1.0

    def rotation(self) -> np.ndarray:
        """(3, 3) rotation taking source coordinates to the canonical frame."""
        return frame_rotation(self.up, self.front)


#: glTF 2.0: +Y up, the front of an asset faces +Z, metres (the glTF specification).
GLTF_FRAME = SourceFrame(up="+y", front="+z", unit_scale=1.0)
#: PartNet-Mobility after applying the URDF's joints: the root joint of every mobility.urdf
#: rotates the raw Y-up, front -Z meshes (rpy = 90 deg, 0, -90 deg) so objects stand on +Z and
#: face +X. Units are normalised, not metres: the category size range sets the scale.
PARTNET_FRAME = SourceFrame(up="+z", front="+x", unit_scale=1.0)


def _axis(spec: str, what: str) -> np.ndarray:
    s = spec.strip().lower()
    sign = -1.0 if s.startswith("-") else 1.0
    s = s.lstrip("+-")
    if s not in _AXES:
        raise InputError(Problem("", f"{what} axis {spec!r} is not one of +x, -x, +y, -y, +z, -z",
                                 None, "parameter"))
    return sign * np.array(_AXES[s])


def frame_rotation(up: str, front: str) -> np.ndarray:
    """(3, 3) rotation mapping the source ``up`` axis to +Z and ``front`` to +Y.

    The source's right-hand side (``front x up``) goes to +X, so the rotation is proper.
    """
    u = _axis(up, "up")
    f = _axis(front, "front")
    if abs(float(u @ f)) > 1e-9:
        raise InputError(Problem("", f"front axis {front!r} must be perpendicular to up axis {up!r}",
                                 None, "parameter"))
    r = np.cross(f, u)
    return np.stack([r, f, u])


_TRAILING = re.compile(r"(?:[._\-\s]*\d+)+$")


def default_label(name: str) -> str:
    """A part label from a node or link name: lower case, trailing indices stripped.

    ``"leg_0"``, ``"Leg.001"`` and ``"leg 2"`` all give ``"leg"``; spaces become ``_``.
    """
    s = _TRAILING.sub("", name.strip())
    s = re.sub(r"[\s\-]+", "_", s).lower().strip("_")
    return s or name.strip().lower()


def read_mapping(mapping: Mapping[str, str | None] | str | Path | None) -> tuple[dict, str | None]:
    """A name-to-label mapping from a dict or a JSON/YAML file.

    Values are part labels, or ``null`` to drop the node or link.

    Returns
    -------
    (dict, str or None)
        The mapping and the file it came from.
    """
    if mapping is None:
        return {}, None
    if isinstance(mapping, Mapping):
        return dict(mapping), None
    path = Path(mapping)
    if not path.exists():
        raise InputError(Problem("", "mapping file not found", str(path), "io"))
    text = read_input_text(path, limit=MAX_MAPPING_BYTES, what="mapping file")
    if path.suffix.lower() in (".yaml", ".yml"):
        data = _mapping_yaml(text, str(path))
    else:
        data = loads_json(text, file=str(path))
    if not isinstance(data, dict):
        raise InputError(Problem("", "a mapping must be an object {name: part label}", str(path), "schema"))
    bad = [k for k, v in data.items() if v is not None and not isinstance(v, str)]
    if bad:
        raise InputError([Problem(f"/{k}", "must be a part label (string) or null", str(path), "schema")
                          for k in bad])
    return data, str(path)


def _mapping_yaml(text: str, file: str):
    """A YAML mapping file, parsed safely: aliases (which can expand without bound) and
    nesting deeper than :data:`~parse3d._files.MAX_DEPTH` are refused before it is built."""
    import yaml

    depth = 0
    try:
        for ev in yaml.parse(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader)):
            if isinstance(ev, yaml.AliasEvent):
                raise InputError(Problem("", "a mapping file may not use YAML aliases (*name)",
                                         file, "syntax"))
            if isinstance(ev, yaml.CollectionStartEvent):
                depth += 1
                if depth > MAX_DEPTH:
                    raise InputError(Problem("", f"nested more than {MAX_DEPTH} levels deep",
                                             file, "syntax"))
            elif isinstance(ev, yaml.CollectionEndEvent):
                depth -= 1
        return yaml.safe_load(text)
    except yaml.YAMLError as e:
        raise InputError(Problem("", f"cannot parse the mapping: {str(e)[:200]}", file,
                                 "syntax")) from None


def check_mapping_labels(mapping: dict, vocabulary: tuple[str, ...] | None, file: str | None) -> None:
    """InputError for mapping values outside ``vocabulary`` (when one is known)."""
    if not vocabulary:
        return
    import difflib

    probs = []
    for k, v in mapping.items():
        if v is not None and v not in vocabulary:
            close = difflib.get_close_matches(v, vocabulary, n=1)
            hint = f" — did you mean {close[0]!r}?" if close else f" (labels: {', '.join(vocabulary)})"
            probs.append(Problem(f"/{k}", f"unknown part label {v!r}{hint}", file or "<mapping>",
                                 "vocabulary"))
    if probs:
        raise InputError(probs)


def part_label_problems(parts, vocabulary: tuple[str, ...] | None, file: str | None,
                        pointer: str) -> list[Problem]:
    """A problem for every part whose label is outside ``vocabulary`` (pointer
    ``<pointer>/<source name>``), with the closest label as a suggestion."""
    if not vocabulary:
        return []
    import difflib

    probs = []
    for p in parts:
        if p.label not in vocabulary:
            close = difflib.get_close_matches(p.label, vocabulary, n=1)
            hint = f" — did you mean {close[0]!r}? (add it to the mapping)" if close else \
                f" (labels: {', '.join(vocabulary)}; map it with --mapping)"
            probs.append(Problem(f"{pointer}/{p.source}", f"unknown part label {p.label!r}{hint}",
                                 file, "vocabulary"))
    return probs


def label_for(names: tuple[str, ...], mapping: dict) -> str | None:
    """The label of a node: the first of ``names`` found in ``mapping`` decides (``None`` drops
    it); otherwise the default label of the last name."""
    for n in names:
        if n in mapping:
            return mapping[n]
    for n in names:
        d = default_label(n)
        if d in mapping:
            return mapping[d]
    return default_label(names[-1])


def material_of(mesh: trimesh.Trimesh) -> Material:
    """The base colour of a loaded mesh's visual (grey when it has none)."""
    color = None
    vis = mesh.visual
    mat = getattr(vis, "material", None)
    try:
        if mat is not None:
            color = np.asarray(mat.main_color, float)
        elif vis is not None and vis.kind in ("vertex", "face"):
            color = np.asarray(vis.main_color, float)
    except (AttributeError, ValueError, IndexError):
        color = None
    if color is None or color.size < 3:
        return Material()
    c = color / 255.0 if color.max() > 1.0 else color
    rgba = (float(c[0]), float(c[1]), float(c[2]), float(c[3]) if c.size > 3 else 1.0)
    return Material(rgba, 0.6, 0.0, "plastic")


@dataclass
class RawPart:
    """A loaded part before canonicalisation: mesh in the canonical orientation, metres."""

    source: str
    label: str
    mesh: trimesh.Trimesh
    material: Material = field(default_factory=Material)


@dataclass
class RawAsset:
    """A loaded file's parts plus provenance, not yet recentred, fitted or decomposed."""

    source: str
    parts: list[RawPart]
    meta: dict = field(default_factory=dict)
    #: joints in the canonical orientation, naming parts by their ``RawPart.source``
    joints: list = field(default_factory=list)

    @property
    def size(self) -> float:
        b = np.array([p.mesh.bounds for p in self.parts])
        return float((b[:, 1].max(axis=0) - b[:, 0].min(axis=0)).max())

    @property
    def labels(self) -> set[str]:
        return {p.label for p in self.parts}


def check_part_mesh(mesh: trimesh.Trimesh, where: str, file: str | None) -> list[Problem]:
    """Problems of one part's mesh as read: non-finite or absurdly large coordinates."""
    v = np.asarray(mesh.vertices, float)
    if v.size and not np.isfinite(v).all():
        return [Problem(where, "the mesh has NaN or infinite vertex coordinates", file,
                        "geometry")]
    if v.size and np.abs(v).max() > 1e6:
        return [Problem(where, f"vertex coordinates reach {np.abs(v).max():.3g}: more than "
                        "1e6 source units from the origin (check the units or --scale)", file,
                        "geometry")]
    return []


def check_raw_asset(raw: RawAsset, file: str | None) -> None:
    """Bounds every imported asset must meet before it is canonicalised.

    Raises
    ------
    InputError
        More than :data:`MAX_PARTS` parts, :data:`MAX_FACES` faces or :data:`MAX_VERTICES`
        vertices; a part left without any face of positive area after degenerate faces are
        dropped; NaN or infinite coordinates.
    """
    probs = []
    if len(raw.parts) > MAX_PARTS:
        probs.append(Problem("", f"{len(raw.parts)} parts: an asset may have at most "
                                 f"{MAX_PARTS}", file, "geometry"))
    faces = sum(len(p.mesh.faces) for p in raw.parts)
    verts = sum(len(p.mesh.vertices) for p in raw.parts)
    if faces > MAX_FACES or verts > MAX_VERTICES:
        probs.append(Problem("", f"{faces:,} faces and {verts:,} vertices: an imported asset may "
                                 f"have at most {MAX_FACES:,} faces and {MAX_VERTICES:,} vertices "
                                 "(simplify it first)", file, "geometry"))
    for p in raw.parts:
        probs += check_part_mesh(p.mesh, f"/{p.source}", file)
        if len(p.mesh.faces) == 0 or not float(p.mesh.area) > 0.0:
            probs.append(Problem(f"/{p.source}", f"part {p.source!r} ({p.label}) has no face of "
                                 "positive area (only degenerate triangles): remove it or map "
                                 "it to null", file, "geometry"))
    if probs:
        raise InputError(probs)
    b = np.array([p.mesh.bounds for p in raw.parts])
    ext = b[:, 1].max(axis=0) - b[:, 0].min(axis=0)
    if not (ext > 0).all():
        raise InputError(Problem("", f"the asset is flat (extents {ext.round(6).tolist()}): a "
                                     "part-split asset needs some thickness on every axis",
                                 file, "geometry"))


def clean_mesh(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """Merge duplicate vertices and drop degenerate faces (files often carry both)."""
    m = trimesh.Trimesh(np.asarray(mesh.vertices, float), np.asarray(mesh.faces, np.int64),
                        process=True)
    m.update_faces(m.nondegenerate_faces())
    m.update_faces(m.unique_faces())
    m.remove_unreferenced_vertices()
    if m.is_watertight and m.volume < 0:
        m.invert()
    return m


#: Thickness given to the collision piece of a flat part (a picture's canvas, a mirror), m.
FLAT_THICKNESS = 0.001


def _flat_pieces(mesh: trimesh.Trimesh) -> list[trimesh.Trimesh]:
    """One thin convex piece for a part whose vertices lie in a plane (no convex hull of its
    own); an empty list for a part with volume."""
    v = np.asarray(mesh.vertices, float)
    c = v - v.mean(axis=0)
    _, sv, vh = np.linalg.svd(c, full_matrices=False)
    if len(sv) < 3 or sv[2] > 1e-9 * max(sv[0], 1e-12):
        return []
    n = vh[2] * (FLAT_THICKNESS / 2)
    return [trimesh.convex.convex_hull(np.vstack([v + n, v - n]))]


def finish_asset(raw: RawAsset, *, category: str, asset_id: str,
                 size_range: tuple[float, float] | None, density: float,
                 coacd_threshold: float = 0.05, cache_dir: str | Path | None = None) -> Asset:
    """Canonicalise a raw asset into an :class:`Asset`.

    Scales it uniformly into ``size_range`` when its largest extent falls outside (the factor
    goes into ``meta["fit_scale"]``), recentres it (bbox bottom centre at the origin), names
    parts (``label`` when unique, else ``label_k`` in the ``#k`` order: bottom-to-top,
    left-to-right, back-to-front), decomposes every part into convex pieces and resolves
    surfaces and internal surfaces.

    Raises
    ------
    InputError
        The asset breaks a bound of :func:`check_raw_asset`, or its parts cannot be
        decomposed into convex pieces (named with the source file).
    """
    check_raw_asset(raw, raw.source)
    try:
        return _finish(raw, category=category, asset_id=asset_id, size_range=size_range,
                       density=density, coacd_threshold=coacd_threshold, cache_dir=cache_dir)
    except (ValueError, ArithmeticError, IndexError, RuntimeError, AssetError) as e:
        raise InputError(Problem("", f"cannot make an asset of it ({type(e).__name__}: "
                                     f"{str(e)[:200]})", raw.source, "geometry")) from None


def _finish(raw: RawAsset, *, category: str, asset_id: str,
            size_range: tuple[float, float] | None, density: float, coacd_threshold: float,
            cache_dir: str | Path | None) -> Asset:
    meshes = [p.mesh.copy() for p in raw.parts]
    b = np.array([m.bounds for m in meshes])
    lo, hi = b[:, 0].min(axis=0), b[:, 1].max(axis=0)
    size = float((hi - lo).max())
    fit = 1.0
    if size_range is not None and size > 0:
        target = float(np.clip(size, size_range[0], size_range[1]))
        fit = target / size
    shift = -np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]])
    for m in meshes:
        m.apply_translation(shift)
        if fit != 1.0:
            m.apply_scale(fit)
    counts: dict[str, int] = {}
    for p in raw.parts:
        counts[p.label] = counts.get(p.label, 0) + 1

    def order_key(i: int):
        m = meshes[i]
        c = m.bounds.mean(axis=0)
        return (round(float(m.bounds[0, 2]), 3), round(float(c[0]), 3), round(float(c[1]), 3), i)

    names = [""] * len(meshes)
    seen: dict[str, int] = {}
    for i in sorted(range(len(meshes)), key=order_key):
        label = raw.parts[i].label
        if counts[label] == 1:
            names[i] = label
        else:
            k = seen.get(label, 0)
            seen[label] = k + 1
            names[i] = f"{label}_{k}"
    parts = []
    for i, (rp, m) in enumerate(zip(raw.parts, meshes, strict=True)):
        pieces = _flat_pieces(m) or convex_pieces(m, threshold=coacd_threshold,
                                                  cache_dir=cache_dir)
        parts.append(Part(names[i], rp.label, m, rp.material, pieces, watertight=bool(m.is_watertight)))
    meta = dict(raw.meta)
    meta.update({"generator": "loaded", "source": raw.source, "fit_scale": fit})
    # joints follow their parts: renamed, origins recentred and scaled, slides scaled
    by_source = {rp.source: names[i] for i, rp in enumerate(raw.parts)}
    joints = []
    for j in raw.joints:
        if j.parent_part not in by_source or j.child_part not in by_source:
            continue
        lim = j.limits if j.type == "revolute" else (j.limits[0] * fit, j.limits[1] * fit)
        joints.append(Joint(j.name, j.type, by_source[j.parent_part], by_source[j.child_part], j.axis,
                            tuple(float(x) for x in (np.asarray(j.origin) + shift) * fit),
                            tuple(float(x) for x in lim)))
    asset = Asset(category, asset_id, parts,
                  tuple(size_range) if size_range else (size * fit, size * fit), float(density),
                  meta=meta, joints=joints)
    return finalize_asset(asset)
