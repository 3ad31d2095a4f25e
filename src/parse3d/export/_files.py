"""Small file helpers shared by the writers."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

__all__ = ["obj_text", "mtl_text", "safe_name", "MeshFiles"]


def obj_text(vertices: np.ndarray, faces: np.ndarray) -> str:
    """A Wavefront OBJ document of one triangle mesh (vertices in metres, no materials)."""
    v = np.asarray(vertices, float)
    f = np.asarray(faces, int) + 1
    return ("".join(f"v {a:.7g} {b:.7g} {c:.7g}\n" for a, b, c in v)
            + "".join(f"f {a} {b} {c}\n" for a, b, c in f))


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

    def get(self, stem: str, vertices, faces, material=None) -> str:
        """The path of the mesh file relative to ``root`` (written on first request).

        With a ``material`` the OBJ references a ``.mtl`` file beside it carrying its colour.
        """
        stem = safe_name(stem)
        rel = f"{self.folder}/{stem}.obj"
        if rel not in self.written:
            path = self.root / rel
            path.parent.mkdir(parents=True, exist_ok=True)
            head = ""
            if material is not None:
                mtl = path.with_suffix(".mtl")
                mtl.write_text(mtl_text(stem, material))
                self.written[f"{self.folder}/{stem}.mtl"] = mtl
                head = f"mtllib {stem}.mtl\nusemtl {stem}\n"
            path.write_text(head + obj_text(vertices, faces))
            self.written[rel] = path
        return rel
