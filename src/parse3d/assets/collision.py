"""Convex collision pieces for meshes loaded from files (procedural shapes carry their own).

:func:`convex_pieces` runs CoACD (approximate convex decomposition) on a part mesh and caches
the result on disk, keyed by a hash of the mesh's bytes and the options, so a library is only
decomposed once. A part that is already convex (its volume within 2% of its hull's) skips
CoACD and gets its hull. A part made of several separate bodies (a frame of boards) is split
into them first: convex bodies get their hulls and only the others go through CoACD, which is
both faster and tighter than decomposing the whole.
"""

from __future__ import annotations

import hashlib
import os
import tempfile
from pathlib import Path

import numpy as np
import trimesh

from .._files import user_mode
from ..errors import AssetError, DependencyError

__all__ = ["convex_pieces", "CONVEX_TOLERANCE"]

#: A watertight mesh whose volume is within this fraction of its hull's counts as convex.
CONVEX_TOLERANCE = 0.02
#: Parts made of more separate bodies than this are decomposed as a whole.
MAX_BODIES = 64
_CACHE_VERSION = "coacd-pieces/1"


def _mesh_key(mesh: trimesh.Trimesh, threshold: float) -> str:
    h = hashlib.sha256()
    h.update(_CACHE_VERSION.encode())
    h.update(np.ascontiguousarray(mesh.vertices, np.float64).tobytes())
    h.update(np.ascontiguousarray(mesh.faces, np.int64).tobytes())
    h.update(np.float64(threshold).tobytes())
    return h.hexdigest()[:32]


def _is_convex_enough(mesh: trimesh.Trimesh, hull: trimesh.Trimesh) -> bool:
    if not mesh.is_watertight or hull.volume <= 0:
        return False
    return abs(abs(mesh.volume) - hull.volume) <= CONVEX_TOLERANCE * hull.volume


def _read_cached(path: Path) -> list[trimesh.Trimesh] | None:
    try:
        with np.load(path, allow_pickle=False) as z:
            v, f, n = z["v"], z["f"], z["n"]
    except (OSError, ValueError, KeyError):
        return None  # a missing or damaged entry is simply recomputed
    out, v0, f0 = [], 0, 0
    for nv, nf in n:
        out.append(trimesh.Trimesh(v[v0:v0 + nv], f[f0:f0 + nf], process=False))
        v0 += int(nv)
        f0 += int(nf)
    return out


def _write_cached(path: Path, pieces: list[trimesh.Trimesh]) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    v = np.concatenate([p.vertices for p in pieces]).astype(np.float64)
    f = np.concatenate([p.faces for p in pieces]).astype(np.int64)
    n = np.array([[len(p.vertices), len(p.faces)] for p in pieces], np.int64)
    fd, tmp = tempfile.mkstemp(prefix=".coacd-", suffix=".npz", dir=path.parent)
    with os.fdopen(fd, "wb") as fh:
        np.savez(fh, v=v, f=f, n=n)
    os.chmod(tmp, user_mode())
    os.replace(tmp, path)


def _run_coacd(mesh: trimesh.Trimesh, threshold: float) -> list[trimesh.Trimesh]:
    try:
        import coacd
    except ImportError as e:  # pragma: no cover - coacd is a declared dependency
        raise DependencyError("convex decomposition needs CoACD: pip install coacd") from e
    coacd.set_log_level("error")
    cm = coacd.Mesh(np.asarray(mesh.vertices, np.float64), np.asarray(mesh.faces, np.int64))
    # a fixed seed keeps the decomposition (and so every scene built on it) reproducible
    parts = coacd.run_coacd(cm, threshold=float(threshold), seed=0)
    pieces = []
    for v, _faces in parts:
        pc = trimesh.convex.convex_hull(np.asarray(v, float))
        if pc.volume > 1e-12:
            pieces.append(pc)
    return pieces


def convex_pieces(mesh: trimesh.Trimesh, *, threshold: float = 0.05,
                  cache_dir: str | os.PathLike | None = None) -> list[trimesh.Trimesh]:
    """Convex pieces whose union approximates ``mesh``.

    Parameters
    ----------
    mesh : trimesh.Trimesh
        A part mesh, metres, any frame (pieces come back in the same frame).
    threshold : float
        CoACD's concavity threshold (smaller: more, tighter pieces).
    cache_dir : path, optional
        Where decompositions are cached; defaults to ``cache_dir()/coacd``.

    Returns
    -------
    list of trimesh.Trimesh
        Convex, watertight pieces. A mesh that is already convex gives its hull alone.

    Raises
    ------
    AssetError
        The mesh has no faces, or CoACD produced nothing.
    """
    if len(mesh.faces) == 0:
        raise AssetError("cannot decompose a mesh without faces")
    hull = mesh.convex_hull
    if _is_convex_enough(mesh, hull):
        return [hull]
    if cache_dir is None:
        from .library import cache_dir as _root

        cache_dir = _root() / "coacd"
    path = Path(cache_dir) / f"{_mesh_key(mesh, threshold)}.npz"
    cached = _read_cached(path) if path.exists() else None
    if cached:
        return cached
    pieces = []
    bodies = mesh.split(only_watertight=False) if mesh.body_count > 1 else [mesh]
    if len(bodies) > MAX_BODIES:
        bodies = [mesh]  # a cloud of fragments: one decomposition of the whole is tidier
    for body in bodies:
        if len(body.faces) == 0:
            continue
        h = body.convex_hull
        if _is_convex_enough(body, h):
            pieces.append(h)  # most bodies of a part (a box, a board) are convex already
        else:
            pieces.extend(_run_coacd(body, threshold))
    if not pieces:
        # degenerate input (a flat sheet): its hull is the best convex cover there is
        if hull.volume <= 1e-12:
            raise AssetError("convex decomposition found no volume in the mesh (is it flat?)")
        pieces = [hull]
    _write_cached(path, pieces)
    return pieces
