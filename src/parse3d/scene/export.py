"""Exporting scenes: a GLB with one node per part (Y-up, per the glTF spec)."""

from __future__ import annotations

import numpy as np
import trimesh
from trimesh.visual.material import PBRMaterial

from ..assets.model import Material
from .model import Scene

__all__ = ["export_glb", "scene_to_trimesh", "Z_UP_TO_Y_UP"]

#: Rotation taking parse3d's Z-up world to glTF's Y-up: (x, y, z) -> (x, z, -y).
Z_UP_TO_Y_UP = np.array([[1, 0, 0, 0], [0, 0, 1, 0], [0, -1, 0, 0], [0, 0, 0, 1]], dtype=float)

_SHELL = {"floor": Material((0.78, 0.74, 0.68, 1.0), 0.8, 0.0, "wood"),
          "wall": Material((0.93, 0.92, 0.89, 1.0), 0.9, 0.0, "stone"),
          "ceiling": Material((0.97, 0.97, 0.96, 1.0), 0.9, 0.0, "stone")}


def _visual(mesh: trimesh.Trimesh, mat: Material) -> trimesh.Trimesh:
    m = mesh.copy()
    m.visual = trimesh.visual.TextureVisuals(material=PBRMaterial(
        baseColorFactor=[int(round(c * 255)) for c in mat.color],
        metallicFactor=float(mat.metallic), roughnessFactor=float(mat.roughness),
        alphaMode="BLEND" if mat.color[3] < 1 else "OPAQUE", doubleSided=False))
    return m


def scene_to_trimesh(scene: Scene, *, settled: bool | None = None, shell: bool = True) -> trimesh.Scene:
    """A trimesh.Scene in parse3d's Z-up world frame, one geometry per part.

    Node names: ``<object_id>:<part_name>`` and ``room:floor``, ``room:wall_i``,
    ``room:ceiling``.
    """
    ts = trimesh.Scene()
    if shell:
        for name, el in scene.room.elements.items():
            kind = "wall" if name.startswith("wall_") else name
            ts.add_geometry(_visual(el.mesh, _SHELL[kind]), node_name=f"room:{name}",
                            geom_name=f"room:{name}")
    for o in scene.placed:
        T = o.transform(settled)
        for p in o.asset.parts:
            m = _visual(p.mesh, p.material)
            m.apply_transform(T)
            name = f"{o.id}:{p.name}"
            ts.add_geometry(m, node_name=name, geom_name=name)
    return ts


def export_glb(scene: Scene, *, settled: bool | None = None) -> bytes:
    """The scene as GLB bytes: world coordinates converted to glTF's Y-up."""
    ts = scene_to_trimesh(scene, settled=settled)
    for g in ts.geometry.values():
        g.apply_transform(Z_UP_TO_Y_UP)
    return ts.export(file_type="glb")
