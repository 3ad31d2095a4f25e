"""Reading and writing solved scenes: ``scene.json`` and ``contacts.json``.

``scene.json`` (``format: "parse3d-scene/1"``, schema ``scene-1.schema.json`` in this package)
holds the PAG as given, the seed, the room, every object's chosen category, asset, scale and
pose (solved and, once settled, settled), its status, and every relation's check results.
Assets are referenced by ``(category, variant, seed)`` for generated ones, or by the cached
file of a loaded one, so :func:`read_scene` rebuilds the exact scene.

Writes are atomic: files go to a temporary name in the folder and are renamed into place.
"""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError, Problem
from ..geometry.frames import matrix_to_quat, quat_to_matrix
from ..pag.model import PAG
from .model import Contact, PlacedObject, RelationCheck, Scene
from .shell import build_shell

__all__ = ["SCENE_FORMAT", "scene_to_dict", "write_scene", "read_scene", "scene_schema",
           "atomic_write_text", "atomic_write_bytes"]

SCENE_FORMAT = "parse3d-scene/1"


def _r(x, n: int = 6) -> list[float]:
    return [round(float(v), n) for v in np.asarray(x).ravel()]


def _pose(R, t) -> dict[str, list[float]]:
    return {"position": _r(t), "quaternion": _r(matrix_to_quat(R), 8)}


def _asset_ref(o: PlacedObject) -> dict[str, Any] | None:
    if o.asset is None:
        return None
    m = o.asset.meta
    ref = {"id": o.asset.asset_id, "category": o.asset.category,
           "source": m.get("generator", "procedural")}
    if "variant" in m:
        ref["variant"] = m["variant"]
    if "seed" in m:
        ref["seed"] = int(m["seed"])
    if "path" in m:
        ref["path"] = str(m["path"])
    return ref


def scene_to_dict(scene: Scene) -> dict[str, Any]:
    """The ``parse3d-scene/1`` document of a scene."""
    objects = []
    for o in scene.objects.values():
        d: dict[str, Any] = {"id": o.id, "category": o.category, "status": o.status}
        if o.placed:
            d["asset"] = _asset_ref(o)
            d["scale"] = round(float(o.scale), 8)
            d["pose"] = _pose(o.rotation, o.position)
            if o.settled_position is not None:
                d["settled_pose"] = _pose(o.settled_rotation, o.settled_position)
            d["parts"] = [{"name": p.name, "label": p.label} for p in o.asset.parts]
            d["support"] = o.support
            d["fixed"] = bool(o.fixed)
            d["trials"] = int(o.trials)
            if o.flags:
                d["flags"] = list(o.flags)
            if o.joints:
                d["joints"] = {k: float(v) for k, v in o.joints.items()}
        else:
            d["reason"] = o.reason
        objects.append(d)
    rels = []
    for c in scene.relations:
        rels.append({"index": c.index, "relation": c.relation, "child": c.child,
                     "parent": c.parent, "holds": c.holds, "residual": c.residual,
                     "detail": c.detail, "holds_settled": c.holds_settled,
                     "residual_settled": c.residual_settled})
    return {
        "format": SCENE_FORMAT,
        "seed": int(scene.seed),
        "pag": scene.pag.to_dict(),
        "room": {"type": scene.pag.room.type,
                 "footprint": [[float(x), float(y)] for x, y in scene.room.footprint],
                 "height": scene.room.height,
            "wall_thickness": scene.room.wall_thickness, "area": round(scene.room.area, 6)},
        "objects": objects,
        "relations": rels,
        "settled": bool(scene.settled),
        "timings": {k: round(float(v), 6) for k, v in scene.timings.items()},
        "meta": scene.meta,
        "summary": {"objects": len(scene.objects), "placed": len(scene.placed),
                    "failed": len(scene.failed),
                    "contacts": None if scene.contacts is None else len(scene.contacts)},
    }


def atomic_write_bytes(path: Path, data: bytes) -> None:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def atomic_write_text(path: Path, text: str) -> None:
    atomic_write_bytes(path, text.encode("utf-8"))


def write_scene(scene: Scene, out_dir: str | Path, *, glb: bool = False) -> Path:
    """Write ``scene.json`` and (when extracted) ``contacts.json``.

    ``scene.glb`` and the other formats come from :func:`parse3d.export.export_scene` (the
    layer above); ``glb`` is accepted for older callers and must stay False.
    """
    if glb:
        raise ValueError("write_scene no longer writes scene.glb: call "
                         "parse3d.export.export_scene(scene, out, ['glb'])")
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    atomic_write_text(out / "scene.json", json.dumps(scene_to_dict(scene), indent=1) + "\n")
    if scene.contacts is not None:
        atomic_write_text(out / "contacts.json",
                          json.dumps([c.to_dict() for c in scene.contacts], indent=1) + "\n")
    return out


def scene_schema() -> dict[str, Any]:
    """The JSON Schema of ``scene.json``."""
    return json.loads((Path(__file__).parent / "scene-1.schema.json").read_text())


def _load_asset(ref: dict[str, Any]):
    if ref.get("path"):
        from ..assets.cache import load_asset

        return load_asset(ref["path"])
    from ..assets.pool import default_pool

    # pool slot i holds generate(category, seed=i), read back from its file
    return default_pool().load(ref["category"], int(ref["seed"]))


def read_scene(path: str | Path) -> Scene:
    """Rebuild a Scene from a folder (or a ``scene.json`` path) written by :func:`write_scene`."""
    p = Path(path)
    f = p / "scene.json" if p.is_dir() else p
    if not f.exists():
        raise InputError(Problem("", f"no scene.json here — solve a PAG first "
                                     f"(parse3d solve PAG --out {p})", str(f), "io"))
    try:
        d = json.loads(f.read_text())
    except json.JSONDecodeError as e:
        raise InputError(Problem("", f"not valid JSON: {e}", str(f), "syntax")) from None
    if d.get("format") != SCENE_FORMAT:
        raise InputError(Problem("/format", f"expected format {SCENE_FORMAT!r}, got "
                                            f"{d.get('format')!r}", str(f), "schema"))
    pag = PAG.from_dict(d["pag"])
    shell = build_shell(pag.room, wall_thickness=float(d["room"].get("wall_thickness", 0.12)))
    scene = Scene(pag, int(d["seed"]), shell, timings=dict(d.get("timings", {})),
                  settled=bool(d.get("settled")), meta=d.get("meta", {}))
    for od in d["objects"]:
        if od["status"] != "placed":
            scene.objects[od["id"]] = PlacedObject(od["id"], od["category"], None,
                                                   status=od["status"], reason=od.get("reason"))
            continue
        asset = _load_asset(od["asset"])
        pose = od["pose"]
        o = PlacedObject(od["id"], od["category"], asset, float(od["scale"]),
                         quat_to_matrix(pose["quaternion"]), np.array(pose["position"], float),
                         "placed", None, int(od.get("trials", 0)), od.get("support"),
                         bool(od.get("fixed", False)))
        if "settled_pose" in od:
            o.settled_rotation = quat_to_matrix(od["settled_pose"]["quaternion"])
            o.settled_position = np.array(od["settled_pose"]["position"], float)
        o.flags = list(od.get("flags", []))
        o.joints = {str(k): float(v) for k, v in od.get("joints", {}).items()}
        scene.objects[o.id] = o
    for r in d.get("relations", []):
        scene.relations.append(RelationCheck(r["index"], r["relation"], r["child"], r["parent"],
                                             r["holds"], r.get("residual") or {},
                                             r.get("holds_settled"), r.get("residual_settled"),
                                             r.get("detail", "")))
    cf = f.parent / "contacts.json"
    if cf.exists():
        scene.contacts = [Contact(c["a"], c["b"], int(c["samples"]), float(c["min_distance"]))
                          for c in json.loads(cf.read_text())]
    return scene
