"""The project's glTF writer beside trimesh's exporter, on the same walked scene.

``parse3d.export.gltf`` writes ``scene.glb`` itself (about 190 lines). trimesh, already a
dependency, has a glTF exporter: this script builds the same file with it, from the same
:class:`~parse3d.export.walk.SceneRecord` (one node per object with its world pose, a child
node per part, meshes in the asset's frame shared between objects of one asset, per-node
``extras``, the room shell), and compares what a user of ``scene.glb`` relies on:

- time to build the bytes (best of ``--repeats``) and file size;
- meshes and accessors written (instancing: one mesh per asset part, not per object);
- the node names a viewer shows (``<object>__<part>``), read back by trimesh;
- ``extras`` on object and part nodes (three.js ``userData``), read back from the JSON chunk;
- the part transforms: every part's world matrix, read back, against the project's file;
- what trimesh adds that the layout leaves out (normals, ``matrix`` instead of TRS).

It prints the figures side by side (docs/export.md quotes them). Run:

    python benchmarks/check_gltf_writer.py                 # the 50-object export benchmark scene
    python benchmarks/check_gltf_writer.py --repeats 5
"""

from __future__ import annotations

import argparse
import io
import json
import struct
import sys
import time
from pathlib import Path

import numpy as np
import trimesh

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_export import big_scene  # noqa: E402

from parse3d.export.gltf import Z_UP_TO_Y_UP, to_glb  # noqa: E402
from parse3d.export.walk import ExportOptions, SceneRecord, walk_scene  # noqa: E402


def trimesh_glb(rec: SceneRecord) -> bytes:
    """The same layout through trimesh's exporter (its scene graph and ``export_glb``)."""
    scene = trimesh.Scene(base_frame="world")
    scene.metadata.update(rec.meta)
    added: set[tuple[str, str]] = set()
    for o in rec.objects:
        scene.graph.update(frame_from="world", frame_to=o.node,
                           matrix=Z_UP_TO_Y_UP @ o.transform,
                           metadata={"name": o.id, "object_id": o.id, "category": o.category,
                                     "asset_id": o.asset_id, "fixed": o.fixed,
                                     "support": o.support, "relations": o.relations})
        motion = {lk.name: lk.motion for lk in o.links}
        for p in o.parts:
            key = f"{o.asset_id}:{p.name}"
            if (o.asset_id, p.name) not in added:  # one geometry per asset part: instancing
                m = trimesh.Trimesh(p.mesh.vertices, p.mesh.faces, process=False)
                m.visual = trimesh.visual.TextureVisuals(material=trimesh.visual.material.
                                                         PBRMaterial(
                    name=p.material.name, baseColorFactor=list(p.material.color),
                    metallicFactor=p.material.metallic, roughnessFactor=p.material.roughness))
                scene.geometry[key] = m
                added.add((o.asset_id, p.name))
            scene.graph.update(frame_from=o.node, frame_to=p.node, matrix=motion[p.link],
                               geometry=key,
                               metadata={"name": p.key, "object_id": o.id, "part": p.name,
                                         "label": p.label, "category": o.category,
                                         "asset_id": o.asset_id, "link": p.link,
                                         "relations": p.relations, "contacts": p.contacts})
    for s in rec.shell:
        scene.geometry[s.key] = trimesh.Trimesh(s.mesh.vertices, s.mesh.faces, process=False)
        scene.graph.update(frame_from="world", frame_to=s.node, matrix=Z_UP_TO_Y_UP,
                           geometry=s.key,
                           metadata={"name": s.key, "object_id": "room", "part": s.name})
    return trimesh.exchange.gltf.export_glb(scene, include_normals=False)


def json_chunk(glb: bytes) -> dict:
    n = struct.unpack_from("<I", glb, 12)[0]
    return json.loads(glb[20:20 + n])


def read_back(glb: bytes) -> tuple[dict[str, np.ndarray], dict]:
    """World matrices of the part nodes as trimesh loads them, and the raw glTF JSON."""
    s = trimesh.load(io.BytesIO(glb), file_type="glb", force="scene")
    world = {}
    for node in s.graph.nodes_geometry:
        world[node] = s.graph.get(node)[0]
    return world, json_chunk(glb)


def best(fn, repeats: int) -> tuple[float, bytes]:
    times, out = [], b""
    for _ in range(repeats):
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return min(times), out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--objects", type=int, default=50)
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args(argv)
    rec = walk_scene(big_scene(a.objects), ExportOptions())
    t_own, own = best(lambda: to_glb(rec), a.repeats)
    t_tm, tm = best(lambda: trimesh_glb(rec), a.repeats)
    w_own, j_own = read_back(own)
    w_tm, j_tm = read_back(tm)

    def extras_kept(j: dict) -> int:
        return sum(1 for n in j["nodes"] if n.get("extras", {}).get("name"))

    shared = sorted(set(w_own) & set(w_tm))
    dev = max((float(np.abs(w_own[k] - w_tm[k]).max()) for k in shared), default=float("nan"))
    rows = [
        ("build ms (best)", f"{1000 * t_own:.1f}", f"{1000 * t_tm:.1f}"),
        ("file KB", f"{len(own) / 1024:.0f}", f"{len(tm) / 1024:.0f}"),
        ("nodes", len(j_own["nodes"]), len(j_tm["nodes"])),
        ("meshes", len(j_own.get("meshes", [])), len(j_tm.get("meshes", []))),
        ("accessors", len(j_own.get("accessors", [])), len(j_tm.get("accessors", []))),
        ("materials", len(j_own.get("materials", [])), len(j_tm.get("materials", []))),
        ("nodes with extras.name", extras_kept(j_own), extras_kept(j_tm)),
        ("part nodes read back", len(w_own), len(w_tm)),
        ("nodes using TRS / matrix",
         f"{sum('matrix' not in n for n in j_own['nodes'])} / "
         f"{sum('matrix' in n for n in j_own['nodes'])}",
         f"{sum('matrix' not in n for n in j_tm['nodes'])} / "
         f"{sum('matrix' in n for n in j_tm['nodes'])}"),
    ]
    print(f"{a.objects} objects, {len(rec.shell)} shell pieces; parse3d writer vs trimesh "
          f"{trimesh.__version__} export_glb")
    print(f"{'':26s} {'parse3d':>12s} {'trimesh':>12s}")
    for name, x, y in rows:
        print(f"{name:26s} {x!s:>12s} {y!s:>12s}")
    print(f"part world matrices: {len(shared)} in both, largest difference {dev:.2e}; "
          f"names only in one file: {len(set(w_own) ^ set(w_tm))}")
    ratio = t_tm / t_own if t_own else float("nan")
    print(f"time ratio trimesh / parse3d: {ratio:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
