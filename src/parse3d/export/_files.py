"""Small file helpers shared by the writers."""

from __future__ import annotations

import hashlib
import re
from pathlib import Path

import numpy as np

__all__ = ["obj_text", "mtl_text", "mesh_digest", "safe_name", "MeshFiles"]


def obj_text(vertices: np.ndarray, faces: np.ndarray) -> str:
    """A Wavefront OBJ document of one triangle mesh (vertices in metres, no materials)."""
    v = np.asarray(vertices, float)
    f = np.asarray(faces, np.int64) + 1
    # one %-format over the whole array formats in C, far faster than a Python loop per line
    return (("v %.7g %.7g %.7g\n" * len(v)) % tuple(v.ravel().tolist())
            + ("f %d %d %d\n" * len(f)) % tuple(f.ravel().tolist()))


def mesh_digest(vertices, faces) -> str:
    """A content hash of a triangle mesh (equal meshes share one file or mesh asset)."""
    h = hashlib.blake2b(digest_size=12)
    h.update(np.ascontiguousarray(vertices, np.float64).tobytes())
    h.update(np.ascontiguousarray(faces, np.int64).tobytes())
    return h.hexdigest()


def safe_name(name: str) -> str:
    """``name`` with every character that is not safe in a file name replaced by ``_``."""
    return re.sub(r"[^A-Za-z0-9_.-]", "_", name)


def mtl_text(name: str, material) -> str:
    """A one-material Wavefront MTL document (diffuse colour, opacity) for ``material``."""
    r, g, b, a = (float(c) for c in material.color)
    return (f"newmtl {name}\nKd {r:.6g} {g:.6g} {b:.6g}\nKa 0 0 0\nKs 0 0 0\n"
            f"d {a:.6g}\nillum 1\n")


class MeshFiles:
    """OBJ files under one folder, each written once however often it is referenced."""

    def __init__(self, root: Path, folder: str = "meshes") -> None:
        self.root = Path(root)
        self.folder = folder
        self.written: dict[str, Path] = {}
        self._by_content: dict[tuple[str, object], str] = {}
        self._any: dict[str, str] = {}
        self._made = False

    def get(self, stem: str, vertices, faces, material=None) -> str:
        """The path of the mesh file relative to ``root`` (written on first request; a mesh
        equal to one already written, with the same material, reuses that file).

        With a ``material`` the OBJ references a ``.mtl`` file beside it carrying its colour.
        """
        digest = mesh_digest(vertices, faces)
        key = (digest, None if material is None else material.color)
        if key in self._by_content:
            return self._by_content[key]
        if material is None and digest in self._any:  # geometry only: any copy will do
            return self._any[digest]
        stem = safe_name(stem)
        rel = f"{self.folder}/{stem}.obj"
        if rel not in self.written:
            path = self.root / rel
            if not self._made:
                path.parent.mkdir(parents=True, exist_ok=True)
                self._made = True
            head = ""
            if material is not None:
                mtl = path.with_suffix(".mtl")
                mtl.write_text(mtl_text(stem, material))
                self.written[f"{self.folder}/{stem}.mtl"] = mtl
                head = f"mtllib {stem}.mtl\nusemtl {stem}\n"
            path.write_text(head + obj_text(vertices, faces))
            self.written[rel] = path
        self._by_content[key] = rel
        self._any.setdefault(digest, rel)
        return rel
