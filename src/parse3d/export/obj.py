"""Wavefront OBJ (``scene.obj`` + ``scene.mtl``): the whole scene baked into one file.

One object and group (``o``/``g``) per part named ``<object_id>:<part_name>`` and one per shell
element (``room:floor``, ``room:wall_i``, ``room:ceiling``), each with its material in
``scene.mtl`` (diffuse colour, opacity). Vertices are in world coordinates converted to Y-up
(the convention of OBJ viewers and Blender's importer, as for glTF): parse3d's
``(x, y, z)`` is written as ``(x, z, -y)``. OBJ has no hierarchy, instancing or metadata:
use the GLB or USD export for those.
"""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from ..scene.io import atomic_write_text
from . import MARKERS
from ._files import safe_name
from .walk import SceneRecord

__all__ = ["NAME", "FILES", "MARKER", "write", "to_obj"]

NAME = "obj"
FILES = ("scene.obj", "scene.mtl")
#: The file whose presence (and age) marks this export in a folder (written last).
MARKER = MARKERS["obj"]

_Z_TO_Y = np.array([[1.0, 0, 0], [0, 0, 1.0], [0, -1.0, 0]])


def to_obj(rec: SceneRecord, mtl_name: str = "scene.mtl") -> tuple[str, str]:
    """``(obj text, mtl text)`` of a walked scene."""
    obj = io.StringIO()
    obj.write(f"# parse3d scene {rec.name}, {rec.meta['pose']} pose, Y-up, metres\n")
    obj.write(f"mtllib {mtl_name}\n")
    mtl = io.StringIO()
    materials: dict[tuple, str] = {}
    offset = 1

    def material(m) -> str:
        key = (tuple(round(float(c), 4) for c in m.color), m.name)
        if key not in materials:
            name = safe_name(f"{m.name}_{len(materials)}")
            r, g, b, a = key[0]
            mtl.write(f"newmtl {name}\nKd {r:.4g} {g:.4g} {b:.4g}\nKa 0 0 0\nKs 0.1 0.1 0.1\n"
                      f"Ns 20\nd {a:.4g}\nillum 2\n\n")
            materials[key] = name
        return materials[key]

    def emit(name: str, vertices: np.ndarray, faces: np.ndarray, mat) -> None:
        nonlocal offset
        obj.write(f"o {name}\ng {name}\nusemtl {material(mat)}\n")
        v = np.asarray(vertices, float) @ _Z_TO_Y.T
        np.savetxt(obj, v, fmt="v %.6f %.6f %.6f")
        np.savetxt(obj, np.asarray(faces, np.int64) + offset, fmt="f %d %d %d")
        offset += len(v)

    for o in rec.objects:
        T = o.transform
        motion = {lk.name: lk.motion for lk in o.links}
        for p in o.parts:
            A = T @ motion[p.link]
            v = np.asarray(p.mesh.vertices, float) @ A[:3, :3].T + A[:3, 3]
            emit(p.key, v, p.mesh.faces, p.material)
    for s in rec.shell:
        emit(s.key, s.mesh.vertices, s.mesh.faces, s.material)
    return obj.getvalue(), mtl.getvalue()


def write(rec: SceneRecord, out: Path) -> list[Path]:
    """Write ``scene.obj`` and ``scene.mtl`` into the folder ``out``; returns the paths."""
    out = Path(out)
    obj, mtl = to_obj(rec)
    atomic_write_text(out / "scene.mtl", mtl)
    atomic_write_text(out / "scene.obj", obj)
    return [out / "scene.obj", out / "scene.mtl"]
