"""The on-disk asset format: one compact, versioned ``.npz`` file per asset.

Loading a cached asset never recomputes geometry: part meshes, convex pieces, the six
directional surfaces of every part and the internal support surfaces are all stored.

File layout (``format: "parse3d-asset/1"``), every entry a plain numpy array (no pickles):

``header``
    UTF-8 JSON (uint8 array): ``{"format", "category", "asset_id", "size_range", "density",
    "meta", "parts": [{"name", "label", "material", "watertight", "pieces"}], "surfaces":
    [{"label", "source"}], "internal": [{"part", "surface", "clearance", "depth"}]}``.
    ``surfaces`` lists every part's six surfaces (part-major, in part order) followed by the
    internal surfaces; ``internal[i].surface`` indexes it.
``p{i}_v`` (V, 3) float32, ``p{i}_f`` (F, 3) int32
    Vertices (metres, asset frame) and faces of part ``i``'s visual mesh.
``p{i}_pv`` (sum V_k, 3) float32, ``p{i}_pf`` (sum F_k, 3) int32, ``p{i}_pn`` (K, 2) int64
    The part's K convex pieces concatenated; ``pn[k] = (V_k, F_k)``, faces index their own
    piece's vertices.
``surf_frame`` (S, 12) float64
    Each surface's ``origin``, ``normal``, ``u``, ``v``.
``surf_wkb`` (bytes,) uint8, ``surf_off`` (S + 1,) int64
    Each surface polygon as WKB (float64 coordinates, exact), concatenated with offsets.
``hull`` (H, 3) float64, optional
    The vertices of the convex hull of every piece's vertices (of the part meshes for an asset
    without pieces), as stored: what the solver and settling measure an asset by
    (:attr:`Asset.hull`). Kept so that solving never runs qhull; a file without it gets it
    computed when first needed.

Meshes load as arrays (:class:`~parse3d.geometry.meshes.MeshArrays`); a part's
``trimesh.Trimesh`` is made when first asked for, so reading an asset imports no mesh library.

Examples
--------
>>> from parse3d.assets import registry
>>> a = registry.generate("mug", seed=1)
>>> save_asset(a, "/tmp/mug-1.npz")                           # doctest: +SKIP
>>> load_asset("/tmp/mug-1.npz").asset_id                      # doctest: +SKIP
'mug-round-1'
"""

from __future__ import annotations

import hashlib
import io
import json
import math
import os
import re
import struct
import tempfile
import zipfile
import zlib
from pathlib import Path
from typing import Any

import numpy as np
import shapely

from .._files import user_mode
from ..errors import AssetError
from ..geometry.meshes import MeshArrays
from ..geometry.surfaces import Surface
from .model import Asset, InternalSurface, Joint, Material, Part, hull_points

__all__ = ["FORMAT", "save_asset", "load_asset", "asset_digest"]

#: Version tag written into every asset file; a file with another tag is refused.
FORMAT = "parse3d-asset/1"


def _json_safe(obj: Any) -> Any:
    """``obj`` with numpy scalars and arrays turned into plain JSON values."""
    if isinstance(obj, dict):
        return {str(k): _json_safe(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_json_safe(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, Path):
        return str(obj)
    if isinstance(obj, float) and not np.isfinite(obj):
        return None if np.isnan(obj) else ("inf" if obj > 0 else "-inf")
    return obj


def _surface_rows(s: Surface) -> np.ndarray:
    return np.concatenate([np.asarray(s.origin, float), np.asarray(s.normal, float),
                           np.asarray(s.u, float), np.asarray(s.v, float)])


def _asset_arrays(asset: Asset) -> dict[str, np.ndarray]:
    """Every array of the file format, header included."""
    arrays: dict[str, np.ndarray] = {}
    surfaces: list[Surface] = []
    parts_h = []
    for i, p in enumerate(asset.parts):
        arrays[f"p{i}_v"] = np.asarray(p.mesh.vertices, np.float32)
        arrays[f"p{i}_f"] = np.asarray(p.mesh.faces, np.int32)
        if p.pieces:
            arrays[f"p{i}_pv"] = np.concatenate([np.asarray(pc.vertices, np.float32) for pc in p.pieces])
            arrays[f"p{i}_pf"] = np.concatenate([np.asarray(pc.faces, np.int32) for pc in p.pieces])
        else:
            arrays[f"p{i}_pv"] = np.zeros((0, 3), np.float32)
            arrays[f"p{i}_pf"] = np.zeros((0, 3), np.int32)
        arrays[f"p{i}_pn"] = np.array([[len(pc.vertices), len(pc.faces)] for pc in p.pieces],
                                      np.int64).reshape(-1, 2)
        labels = list(p.surfaces)
        surfaces.extend(p.surfaces[k] for k in labels)
        parts_h.append({"name": p.name, "label": p.label, "material": p.material.to_dict(),
                        "watertight": bool(p.watertight), "surfaces": labels})
    internal_h = []
    for s in asset.internal:
        internal_h.append({"part": s.part, "surface": len(surfaces),
                           "clearance": None if np.isinf(s.clearance) else float(s.clearance),
                           "depth": float(s.depth)})
        surfaces.append(s.surface)
    wkb = [shapely.to_wkb(s.polygon, output_dimension=2) for s in surfaces]
    off = np.zeros(len(wkb) + 1, np.int64)
    off[1:] = np.cumsum([len(w) for w in wkb])
    arrays["surf_wkb"] = np.frombuffer(b"".join(wkb), np.uint8)
    arrays["surf_off"] = off
    arrays["surf_frame"] = (np.array([_surface_rows(s) for s in surfaces], float)
                            if surfaces else np.zeros((0, 12)))
    # the hull of the vertices as the file stores them, so it is the loaded asset's own
    arrays["hull"] = hull_points(np.vstack(
        [np.asarray(a, np.float32).astype(np.float64) for a in _hull_sources(arrays, asset)]))
    header = {
        "format": FORMAT,
        "category": asset.category,
        "asset_id": asset.asset_id,
        "size_range": [float(x) for x in asset.size_range],
        "density": float(asset.density),
        "meta": _json_safe(asset.meta),
        "parts": parts_h,
        "surfaces": [{"label": s.label, "source": s.source} for s in surfaces],
        "internal": internal_h,
    }
    if asset.joints:  # rigid assets keep the header (and digest) they always had
        header["joints"] = [j.to_dict() for j in asset.joints]
    arrays["header"] = np.frombuffer(json.dumps(header).encode("utf-8"), np.uint8)
    return arrays


def _hull_sources(arrays: dict[str, np.ndarray], asset: Asset) -> list[np.ndarray]:
    """The stored vertex arrays the hull is taken over: every part's pieces, or every part's
    mesh when no part has pieces (as :attr:`Asset.hull` chooses)."""
    n = len(asset.parts)
    pieces = [arrays[f"p{i}_pv"] for i in range(n) if len(arrays[f"p{i}_pv"])]
    return pieces or [arrays[f"p{i}_v"] for i in range(n)] or [np.zeros((0, 3))]


def save_asset(asset: Asset, path: str | os.PathLike) -> Path:
    """Write ``asset`` to ``path`` (``.npz``), atomically.

    The file is written next to its destination and renamed into place, so parallel writers
    and readers never see a half-written file.

    Returns
    -------
    Path
        The path written.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    arrays = _asset_arrays(asset)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.stem}-", suffix=".npz", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            np.savez_compressed(fh, **arrays)
        os.chmod(tmp, user_mode())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def _pieces(pv: np.ndarray, pf: np.ndarray, pn: np.ndarray) -> list[MeshArrays]:
    out = []
    v0 = f0 = 0
    for nv, nf in pn:
        v = pv[v0:v0 + nv].astype(np.float64)
        f = pf[f0:f0 + nf].astype(np.int64)
        out.append(MeshArrays(v, f))
        v0 += int(nv)
        f0 += int(nf)
    return out


#: The header numpy writes for a plain little- or big-endian numeric array in C order; other
#: headers go through numpy's general reader.
_NPY_HEADER = re.compile(rb"\{'descr': '([<>|][biufc]\d+)', 'fortran_order': False, "
                         rb"'shape': \(((?:\d+, ?)*\d*)\), \} *\n?$")


def _read_npy(raw: bytes) -> np.ndarray:
    """One ``.npy`` member's array (a writable copy). Plain numeric headers are read with a
    regular expression: numpy parses every header with ``ast.literal_eval``, which is most of
    the time of loading an asset's ~50 small arrays."""
    if raw[:6] == b"\x93NUMPY" and len(raw) >= 12:
        start = 10 if raw[6] == 1 else 12
        hlen = int.from_bytes(raw[8:start], "little")
        m = _NPY_HEADER.match(raw[start:start + hlen])
        if m is not None:
            shape = tuple(int(x) for x in m.group(2).split(b",") if x.strip())
            arr = np.frombuffer(raw, np.dtype(m.group(1).decode("ascii")),
                                count=math.prod(shape), offset=start + hlen)
            return arr.reshape(shape).copy()
    return np.load(io.BytesIO(raw), allow_pickle=False)


def _read_npz(path: Path) -> dict[str, np.ndarray]:
    """Every array of an ``.npz`` file, by name (as ``numpy.load`` gives them).

    The file is read in one go and each member is inflated straight from that buffer (offsets
    from the zip's central directory, CRC checked): ``zipfile``'s per-member file objects cost
    more than the ~50 small arrays of an asset themselves. Members that are not plain stored or
    deflated ones go through ``zipfile``.
    """
    with open(path, "rb") as fh:
        buf = fh.read()
    out = {}
    view = memoryview(buf)
    with zipfile.ZipFile(io.BytesIO(buf)) as zf:
        for info in zf.infolist():
            if not info.filename.endswith(".npy"):
                raise ValueError(f"unexpected member {info.filename!r}")
            raw = _member(buf, view, info)
            out[info.filename[:-4]] = _read_npy(raw if raw is not None else zf.read(info))
    return out


def _member(buf: bytes, view: memoryview, info: zipfile.ZipInfo) -> bytes | None:
    """One member's bytes read from the whole file's buffer; None to leave it to zipfile."""
    if info.flag_bits & 0x1 or info.compress_type not in (zipfile.ZIP_STORED,
                                                          zipfile.ZIP_DEFLATED):
        return None
    off = info.header_offset
    if buf[off:off + 4] != b"PK\x03\x04" or off + 30 > len(buf):
        raise zipfile.BadZipFile(f"bad local header of {info.filename!r}")
    name_len, extra_len = struct.unpack_from("<HH", buf, off + 26)
    start = off + 30 + name_len + extra_len
    data = view[start:start + info.compress_size]
    if len(data) != info.compress_size:
        raise zipfile.BadZipFile(f"{info.filename!r} is truncated")
    try:
        raw = zlib.decompress(data, -15) if info.compress_type == zipfile.ZIP_DEFLATED \
            else bytes(data)
    except zlib.error as e:
        raise zipfile.BadZipFile(f"{info.filename!r}: {e}") from None
    if len(raw) != info.file_size or zlib.crc32(raw) != info.CRC:
        raise zipfile.BadZipFile(f"bad CRC or size of {info.filename!r}")
    return raw


def load_asset(path: str | os.PathLike) -> Asset:
    """Read an asset written by :func:`save_asset`.

    Raises
    ------
    AssetError
        The file is missing, unreadable, or has another format version (the message names the
        file and what to do).
    """
    path = Path(path)
    try:
        data = _read_npz(path)
    except FileNotFoundError:
        raise AssetError(f"{path}: asset file not found") from None
    except (OSError, ValueError, zipfile.BadZipFile, EOFError) as e:
        raise AssetError(f"{path}: not a parse3d asset file ({e})") from None
    if "header" not in data:
        raise AssetError(f"{path}: not a parse3d asset file (no header)")
    try:
        header = json.loads(data["header"].tobytes().decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as e:
        raise AssetError(f"{path}: corrupt asset header ({e})") from None
    fmt = header.get("format") if isinstance(header, dict) else None
    if fmt != FORMAT:
        raise AssetError(f"{path}: asset format {fmt!r} is not {FORMAT!r}; rebuild it "
                         "(delete the file, or run `parse3d assets build` / `parse3d assets add`)")
    try:
        return _asset_from(header, data)
    except (KeyError, IndexError, TypeError, ValueError, shapely.errors.ShapelyError) as e:
        raise AssetError(f"{path}: corrupt asset file ({type(e).__name__}: {e})") from None


def _asset_from(header: dict, data: dict[str, np.ndarray]) -> Asset:
    frames = data["surf_frame"]
    off = data["surf_off"]
    raw = data["surf_wkb"].tobytes()
    polys = shapely.from_wkb([raw[off[i]:off[i + 1]] for i in range(len(off) - 1)])
    surfaces = [
        Surface(h["label"], frames[i, 0:3].copy(), frames[i, 3:6].copy(), frames[i, 6:9].copy(),
                frames[i, 9:12].copy(), polys[i], h["source"])
        for i, h in enumerate(header["surfaces"])
    ]
    parts = []
    k = 0
    for i, ph in enumerate(header["parts"]):
        mesh = MeshArrays(data[f"p{i}_v"].astype(np.float64), data[f"p{i}_f"].astype(np.int64))
        pieces = _pieces(data[f"p{i}_pv"], data[f"p{i}_pf"], data[f"p{i}_pn"])
        surf = {}
        for label in ph["surfaces"]:
            surf[label] = surfaces[k]
            k += 1
        parts.append(Part(ph["name"], ph["label"], mesh, Material.from_dict(ph["material"]),
                          pieces, surf, bool(ph["watertight"])))
    internal = [
        InternalSurface(h["part"], surfaces[h["surface"]],
                        float("inf") if h["clearance"] is None else float(h["clearance"]),
                        float(h["depth"]))
        for h in header["internal"]
    ]
    hull = data.get("hull")
    if hull is not None and (hull.ndim != 2 or hull.shape[1] != 3):
        raise ValueError(f"hull has shape {hull.shape}, not (H, 3)")
    return Asset(header["category"], header["asset_id"], parts, tuple(header["size_range"]),
                 float(header["density"]), internal, header["meta"],
                 [Joint.from_dict(j) for j in header.get("joints", [])],
                 hull=None if hull is None else hull.astype(np.float64))


def asset_digest(asset: Asset) -> str:
    """A stable hex digest of everything an asset file stores (to compare assets exactly).

    Vertices are taken at the file's float32 precision, so an asset and its cached copy have
    the same digest.
    """
    h = hashlib.sha256()
    arrays = _asset_arrays(asset)
    for k in sorted(arrays):
        h.update(k.encode())
        h.update(np.ascontiguousarray(arrays[k]).tobytes())
    return h.hexdigest()
