"""Small file helpers shared by the writers."""

from __future__ import annotations

import contextlib
import hashlib
import os
import re
from pathlib import Path

import numpy as np

from .._files import user_mode
from ..geometry.meshes import MeshArrays, concatenate_arrays

__all__ = ["obj_text", "pieces_obj_text", "join_pieces", "stl_bytes", "mtl_text", "mesh_digest", "safe_name", "material_name",
           "MeshFiles", "MATERIAL_LIBRARY", "remove_stale", "write_file"]

#: File name of the shared material library of a mesh folder (visual OBJ files use it).
MATERIAL_LIBRARY = "materials.mtl"


def obj_text(vertices: np.ndarray, faces: np.ndarray) -> str:
    """A Wavefront OBJ document of one triangle mesh (vertices in metres, no materials)."""
    v = np.asarray(vertices, float)
    f = np.asarray(faces, np.int64) + 1
    # one %-format over the whole array formats in C, far faster than a Python loop per line
    return (("v %.7g %.7g %.7g\n" * len(v)) % tuple(v.ravel().tolist())
            + ("f %d %d %d\n" * len(f)) % tuple(f.ravel().tolist()))


def join_pieces(pieces) -> tuple[np.ndarray, np.ndarray]:
    """The pieces ``[(vertices (V_i, 3), faces (F_i, 3)), ...]`` as one mesh: stacked
    vertices and the faces renumbered into them."""
    m = concatenate_arrays([MeshArrays(np.asarray(v), np.asarray(f)) for v, f in pieces])
    return m.vertices, m.faces


def pieces_obj_text(pieces) -> str:
    """A Wavefront OBJ document with one object (``o piece_<i>``) per piece
    ``(vertices (V_i, 3), faces (F_i, 3))``, in metres, no materials.

    Each piece's vertices follow its ``o`` line and its faces use the file-wide numbering:
    loaders that take an OBJ object as one convex shape (PyBullet; SAPIEN with
    ``load_multiple_collisions_from_file``) get every piece as its own shape.
    """
    template: list[str] = []
    values: list[float | int] = []
    first = 1
    for i, (v, f) in enumerate(pieces):
        v = np.asarray(v, float)
        f = np.asarray(f, np.int64)
        template.append(f"o piece_{i}\n" + "v %.7g %.7g %.7g\n" * len(v)
                        + "f %d %d %d\n" * len(f))
        values += v.ravel().tolist()
        values += (f + first).ravel().tolist()
        first += len(v)
    # one %-format over everything formats in C, far faster than a Python loop per line
    return "".join(template) % tuple(values)


_STL_TRIANGLE = np.dtype([("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])


def stl_bytes(vertices: np.ndarray, faces: np.ndarray) -> bytes:
    """A binary STL document of one triangle mesh (float32, metres, outward normals)."""
    tri = np.asarray(vertices, float)[np.asarray(faces, np.int64)]
    a, b = tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]
    n = np.empty_like(a)  # the cross product, without np.cross's overhead on small arrays
    n[:, 0] = a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1]
    n[:, 1] = a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2]
    n[:, 2] = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    norm = np.sqrt((n * n).sum(axis=1))[:, None]
    rows = np.zeros(len(tri), _STL_TRIANGLE)
    rows["normal"] = n / np.where(norm > 0, norm, 1.0)
    rows["v"] = tri
    head = b"parse3d mesh".ljust(80, b" ")
    return head + np.uint32(len(tri)).tobytes() + rows.tobytes()


def mesh_digest(vertices, faces) -> str:
    """A content hash of a triangle mesh (equal meshes share one file or mesh asset)."""
    h = hashlib.blake2b(digest_size=12)
    h.update(np.ascontiguousarray(vertices, np.float64).tobytes())
    h.update(np.ascontiguousarray(faces, np.int64).tobytes())
    return h.hexdigest()


def safe_name(name: str) -> str:
    """``name`` with every character that is not safe in a file name replaced by ``_``."""
    return re.sub(r"[^A-Za-z0-9_.-]", "_", name)


def material_name(material) -> str:
    """A name for ``material`` that depends only on its family and colour (``wood_996640ff``),
    so files written by earlier exports keep naming the right entry of a material library."""
    rgba = "".join(f"{min(max(int(round(float(c) * 255)), 0), 255):02x}"
                   for c in material.color)
    return safe_name(f"{material.name}_{rgba}")


def mtl_text(name: str, material) -> str:
    """One Wavefront MTL entry (diffuse colour, opacity) for ``material``."""
    r, g, b, a = (float(c) for c in material.color)
    return (f"newmtl {name}\nKd {r:.6g} {g:.6g} {b:.6g}\nKa 0 0 0\nKs 0 0 0\n"
            f"d {a:.6g}\nillum 1\n")


def write_file(path: str | Path, data: bytes, mode: int | None = None) -> None:
    """Write ``data`` to ``path`` in place (one open, one write: for the many small files of
    an export, which are regenerated rather than edited; ``mode`` defaults to the umask's)."""
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC,
                 user_mode() if mode is None else mode)
    try:
        os.write(fd, data)
    finally:
        os.close(fd)


class MeshFiles:
    """Mesh files under one folder, each written once however often it is referenced.

    Geometry-only meshes are binary STL (:meth:`get`) or, for a set of convex pieces, an OBJ
    with one object per piece (:meth:`get_pieces`); meshes with a material are OBJ naming an
    entry of the folder's shared material library (:data:`MATERIAL_LIBRARY`, written by
    :meth:`close`). A geometry-only request is answered by any file of the same geometry, one
    with a material included, so a part whose visual mesh is its collision pieces needs one
    file. File names carry a hash of the content (``<stem>.<hash>.stl``), so a file already in
    the folder from an earlier export of the same assets is kept as it is: re-exporting a
    scene after settling rewrites no mesh.
    """

    def __init__(self, root: Path, folder: str = "meshes") -> None:
        self.root = Path(root)
        self.folder = folder
        self.written: dict[str, Path] = {}
        self._dir = os.path.join(str(self.root), folder)
        self._by_content: dict[tuple[str, object], str] = {}
        self._any: dict[str, str] = {}
        self._materials: dict[str, str] = {}
        self._made = False
        self._mode = user_mode()

    def get(self, stem: str, vertices, faces, material=None) -> str:
        """The path of the mesh file relative to ``root`` (written on first request; a mesh
        equal to one already written, with the same material, reuses that file).

        With a ``material`` the file is an OBJ whose colour is in the material library.
        """
        return self._get(stem, mesh_digest(vertices, faces), material,
                         lambda: obj_text(vertices, faces),
                         lambda: stl_bytes(vertices, faces))

    def get_pieces(self, stem: str, pieces, material=None) -> str:
        """As :meth:`get` for a set of pieces ``[(vertices, faces), ...]``, written as one
        OBJ with an object (``o piece_<i>``) per piece, whether or not it has a material."""
        h = hashlib.blake2b(digest_size=12)
        for v, f in pieces:
            h.update(mesh_digest(v, f).encode())
        text = lambda: pieces_obj_text(pieces)  # noqa: E731
        return self._get(stem, "pieces:" + h.hexdigest(), material, text,
                         lambda: text().encode())

    def _get(self, stem: str, digest: str, material, obj, geometry) -> str:
        mname = None if material is None else material_name(material)
        key = (digest, mname)
        if key in self._by_content:
            return self._by_content[key]
        if material is None and digest in self._any:  # geometry only: any copy will do
            return self._any[digest]
        tag = hashlib.blake2b(f"{digest}:{mname}".encode(), digest_size=4).hexdigest()
        if material is None:
            pieces = digest.startswith("pieces:")
            name = f"{safe_name(stem)}.{tag}.{'obj' if pieces else 'stl'}"
            data = geometry()
        else:
            self._materials.setdefault(mname, mtl_text(mname, material))
            name = f"{safe_name(stem)}.{tag}.obj"
            data = f"mtllib {MATERIAL_LIBRARY}\nusemtl {mname}\n{obj()}".encode()
        rel = f"{self.folder}/{name}"
        if rel not in self.written:
            if not self._made:
                os.makedirs(self._dir, exist_ok=True)
                self._made = True
            path = os.path.join(self._dir, name)
            try:
                same = os.stat(path).st_size == len(data)  # written by an earlier export
            except FileNotFoundError:
                same = False
            if not same:
                write_file(path, data, self._mode)
            self.written[rel] = self.root / rel
        self._by_content[key] = rel
        self._any.setdefault(digest, rel)
        return rel

    def close(self) -> list[Path]:
        """Write the material library (when a mesh has a material); returns every file of
        this export in the folder."""
        if self._materials:
            rel = f"{self.folder}/{MATERIAL_LIBRARY}"
            write_file(os.path.join(self._dir, MATERIAL_LIBRARY),
                       "".join(self._materials.values()).encode(), self._mode)
            self.written[rel] = self.root / rel
        return list(self.written.values())


def remove_stale(root: Path, before: set[str], now: set[str]) -> None:
    """Delete the files (relative to ``root``) an earlier export wrote and this one did not.

    Only files named by the earlier export's own files are candidates, so nothing else a
    user keeps in the folder is touched; a name that leaves ``root`` is ignored.
    """
    base = Path(root).resolve()
    for rel in before - now:
        path = (base / rel).resolve()
        if base not in path.parents or not path.is_file():
            continue
        if path.suffix == ".obj":  # an OBJ's own material file (older exports wrote one each)
            mtl = _own_material_file(path)
            if mtl is not None and str(mtl.relative_to(base)) not in now:
                with contextlib.suppress(OSError):
                    mtl.unlink()
        with contextlib.suppress(OSError):
            path.unlink()


def _own_material_file(obj: Path) -> Path | None:
    """The ``<stem>.mtl`` beside ``obj`` when the OBJ names it as its material library."""
    try:
        with open(obj, encoding="utf-8", errors="replace") as f:
            head = f.readline()
    except OSError:
        return None
    mtl = obj.with_suffix(".mtl")
    return mtl if head.strip() == f"mtllib {mtl.name}" and mtl.is_file() else None
