"""Structured glTF 2.0 (binary ``.glb``): one node per object, a child node per part.

Layout (DESIGN §5):

- a root node per object, named by its id (:func:`~parse3d.export.walk.node_name`: ``-`` made
  ``_``), carrying its world pose (a node ``matrix``: rotation, translation and uniform scale,
  converted to glTF's Y-up) and ``extras`` (object id, category, asset id, fixed, support, relation
  summary);
- under it one node per part named ``<object_id>__<part_name>`` (a name three.js, Blender
  and USD keep as it is: three.js drops colons) with ``extras.name`` holding the exact
  ``<object_id>:<part_name>``, plus the part label, relations naming it and its contacts
  (three.js puts ``extras`` in ``userData``); a part moved by a joint carries the joint's
  motion as its transform;
- meshes stay in the asset's frame and are written once per asset: objects that share an
  asset share its meshes (glTF instancing);
- the room shell as root nodes ``room__floor``, ``room__wall_i`` and ``room__ceiling`` (its own
  node, so viewers can hide it; left out with ``ExportOptions(ceiling=False)``).

No normals are written: glTF viewers then shade every triangle flat, which is what the
faceted procedural parts want.

The bytes come from trimesh's glTF exporter (a trimesh scene graph in this layout, extras on
its edges); it also stores identical vertex and index arrays once (many parts are the same
box). ``benchmarks/check_gltf_writer.py`` compares it with a hand-written writer.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import trimesh

from ..assets.model import Material
from ..scene.io import atomic_write_bytes
from ..scene.model import Scene
from . import MARKERS
from .walk import ExportOptions, SceneRecord, walk_scene

__all__ = ["NAME", "FILES", "MARKER", "Z_UP_TO_Y_UP", "write", "to_glb", "export_glb"]

NAME = "glb"
#: What :func:`write` creates in the output folder.
FILES = ("scene.glb",)
#: The file whose presence (and age) marks this export in a folder (written last).
MARKER = MARKERS["glb"]

#: The graph's root frame; the file has no node for it (objects and the shell are roots).
_BASE = "world"

#: Rotation taking parse3d's Z-up world to glTF's Y-up: (x, y, z) -> (x, z, -y).
Z_UP_TO_Y_UP = np.array([[1, 0, 0, 0], [0, 0, 1, 0], [0, -1, 0, 0], [0, 0, 0, 1]], dtype=float)


def _material(m: Material) -> trimesh.visual.material.PBRMaterial:
    color = [float(c) for c in m.color]
    return trimesh.visual.material.PBRMaterial(
        name=m.name, baseColorFactor=color, metallicFactor=float(m.metallic),
        roughnessFactor=float(m.roughness), alphaMode="BLEND" if color[3] < 1.0 else None)


def _mesh(vertices: np.ndarray, faces: np.ndarray, material: Material) -> trimesh.Trimesh:
    mesh = trimesh.Trimesh(vertices, faces, process=False)
    mesh.visual = trimesh.visual.TextureVisuals(material=_material(material))
    return mesh


def to_glb(rec: SceneRecord) -> bytes:
    """GLB bytes of a walked scene (see the module docstring for the layout).

    The file is written by trimesh's glTF exporter from a scene graph in this layout: one
    geometry per asset part, referenced by every object of that asset (instancing), and the
    extras on the graph's edges.
    """
    scene = trimesh.Scene(base_frame=_BASE)
    scene.metadata.update(rec.meta)
    for o in rec.objects:
        scene.graph.update(
            frame_from=_BASE, frame_to=o.node, matrix=Z_UP_TO_Y_UP @ o.transform,
            metadata={"name": o.id, "object_id": o.id, "category": o.category,
                      "asset_id": o.asset_id, "fixed": o.fixed, "support": o.support,
                      "relations": o.relations,
                      "joints": {j.name: round(j.value, 9) for j in o.joints}})
        link_motion = {lk.name: lk.motion for lk in o.links}
        for p in o.parts:
            key = f"{o.asset_id}:{p.name}"
            if key not in scene.geometry:
                scene.geometry[key] = _mesh(p.mesh.vertices, p.mesh.faces, p.material)
            scene.graph.update(
                frame_from=o.node, frame_to=p.node, matrix=link_motion[p.link], geometry=key,
                metadata={"name": p.key, "object_id": o.id, "part": p.name, "label": p.label,
                          "category": o.category, "asset_id": o.asset_id, "link": p.link,
                          "relations": p.relations, "contacts": p.contacts})
    for s in rec.shell:
        scene.geometry[s.key] = _mesh(s.mesh.vertices, s.mesh.faces, s.material)
        scene.graph.update(frame_from=_BASE, frame_to=s.node, matrix=Z_UP_TO_Y_UP,
                           geometry=s.key,
                           metadata={"name": s.key, "object_id": "room", "part": s.name,
                                     "label": s.name.split("_")[0]})
    return trimesh.exchange.gltf.export_glb(scene, include_normals=False)


def write(rec: SceneRecord, out: Path) -> list[Path]:
    """Write ``scene.glb`` into the folder ``out``; returns the paths written."""
    path = Path(out) / "scene.glb"
    atomic_write_bytes(path, to_glb(rec))
    return [path]


def export_glb(scene: Scene, options: ExportOptions = ExportOptions()) -> bytes:
    """The scene as structured GLB bytes."""
    return to_glb(walk_scene(scene, options))
