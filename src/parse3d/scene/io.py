"""Reading and writing solved scenes: ``scene.json`` and ``contacts.json``.

``scene.json`` (``format: "parse3d-scene/2"``, schema ``scene-2.schema.json`` in this package;
``parse3d-scene/1`` files, whose ``support`` is a ``parent:part@surface`` string, are still read)
holds the PAG as given, the seed, the room, every object's chosen category, asset, scale and
pose (solved and, once settled, settled), its status, and every relation's check results.
Assets are referenced by ``(category, variant, seed)`` for generated ones, or by the cached
file of a loaded one, so :func:`read_scene` rebuilds the exact scene.

Writes are atomic: files go to a temporary name in the folder and are renamed into place.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np

from .._files import atomic_write_bytes, atomic_write_text, read_input_text
from ..errors import InputError, Problem
from ..geometry.frames import matrix_to_quat, quat_to_matrix
from ..pag.model import PAG
from .model import Contact, PlacedObject, RelationCheck, Repair, Scene, SupportChoice
from .shell import build_shell
from .validate import SCENE_FORMATS

__all__ = ["SCENE_FORMAT", "READABLE_FORMATS", "scene_to_dict", "scene_json", "write_scene", "read_scene",
           "scene_schema", "atomic_write_text", "atomic_write_bytes", "clear_scene_outputs",
           "is_parse3d_scene",
           "OUTPUT_PATTERNS"]

SCENE_FORMAT = "parse3d-scene/2"
#: Formats :func:`read_scene` reads.
READABLE_FORMATS = SCENE_FORMATS


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
    """The ``parse3d-scene/2`` document of a scene."""
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
            d["support"] = o.support_choice.to_dict() if o.support_choice else None
            d["fixed"] = bool(o.fixed)
            d["trials"] = int(o.trials)
            if o.flags:
                d["flags"] = list(o.flags)
            if o.joints:
                d["joints"] = {k: float(v) for k, v in o.joints.items()}
            if o.stacked_on:
                d["stacked_on"] = o.stacked_on
            if o.rests_on:
                d["rests_on"] = o.rests_on
        else:
            d["reason"] = o.reason
        if o.repairs:
            d["repairs"] = [r.to_dict() for r in o.repairs]
        objects.append(d)
    rels = []
    for c in scene.relations:
        rels.append({"index": c.index, "relation": c.relation, "child": c.child,
                     "parent": c.parent, "holds": c.holds, "residual": c.residual,
                     "detail": c.detail, "holds_settled": c.holds_settled,
                     "residual_settled": c.residual_settled,
                     **({"relaxed": c.relaxed} if c.relaxed else {})})
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


def _finite(v: Any) -> Any:
    """``v`` with every non-finite float replaced by None: JSON has no NaN, and a bare ``NaN``
    would make the file unreadable (reading then reports the pointer of the null)."""
    if isinstance(v, float):
        return v if np.isfinite(v) else None
    if isinstance(v, dict):
        return {k: _finite(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_finite(x) for x in v]
    return v


def scene_json(scene: Scene) -> str:
    """The text of ``scene.json``: :func:`scene_to_dict` as indented JSON, non-finite floats
    as null."""
    doc = scene_to_dict(scene)
    try:  # almost always every float is finite: then nothing needs replacing
        text = json.dumps(doc, indent=1, allow_nan=False)
    except ValueError:
        text = json.dumps(_finite(doc), indent=1, allow_nan=False)
    return text + "\n"


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
    atomic_write_text(out / "scene.json", scene_json(scene))
    if scene.contacts is not None:
        atomic_write_text(out / "contacts.json",
                          json.dumps([c.to_dict() for c in scene.contacts], indent=1) + "\n")
    if scene.log:  # internal errors met while solving, with their tracebacks
        atomic_write_text(out / "solve.log", "\n".join(scene.log) + "\n")
    return out


#: Files a solve, settle or render writes into a scene folder (``*`` is a view index).
OUTPUT_PATTERNS = ("scene.json", "scene.glb", "contacts.json", "preview.png", "views.json",
                   "solve.log",
                   "rgb_*.png", "depth_*.png", "instance_*.png", "part_*.png")


def is_parse3d_scene(path: str | Path) -> bool:
    """Whether ``path`` is a ``scene.json`` written by parse3d (its ``format`` says so)."""
    try:
        fmt = json.loads(read_input_text(path, what="scene file")).get("format", "")
    except (InputError, ValueError, AttributeError, RecursionError):
        return False
    return isinstance(fmt, str) and fmt.startswith("parse3d-scene/")


def clear_scene_outputs(out_dir: str | Path) -> list[Path]:
    """Remove the outputs of an earlier solve from ``out_dir`` (and nothing else).

    A solve owns its folder's outputs: without this, a new ``scene.json`` would sit beside the
    previous seed's ``contacts.json``, preview and views. Only a folder holding a parse3d
    ``scene.json`` is cleared, and only regular files whose names match
    :data:`OUTPUT_PATTERNS` are removed; any other file is left alone.

    Returns
    -------
    list of Path
        The files removed.

    Raises
    ------
    InputError
        The folder holds a ``scene.json`` that parse3d did not write (nothing is removed).
    """
    import re

    out = Path(out_dir)
    sj = out / "scene.json"
    if not out.is_dir() or not sj.exists():
        return []
    if not is_parse3d_scene(sj):
        raise InputError(Problem("", "this folder holds a scene.json that is not a parse3d "
                                     "scene: choose another --out folder (nothing was changed)",
                                 str(sj), "io"))
    rx = re.compile("|".join(re.escape(p).replace(r"\*", r"\d+") for p in OUTPUT_PATTERNS))
    gone = []
    for f in sorted(out.iterdir()):
        if rx.fullmatch(f.name) and f.is_file() and not f.is_symlink():
            f.unlink()
            gone.append(f)
    return gone


def scene_schema() -> dict[str, Any]:
    """The JSON Schema of ``scene.json``."""
    return json.loads((Path(__file__).parent / "scene-2.schema.json").read_text())


def _load_asset(ref: dict[str, Any]):
    if ref.get("path"):
        from ..assets.cache import load_asset

        return load_asset(ref["path"])
    from ..assets.pool import default_pool

    # pool slot i holds generate(category, seed=i), read back from its file
    return default_pool().load(ref["category"], int(ref["seed"]))


def _support(v) -> SupportChoice | None:
    """The support of an object entry: a string in ``/1``, an object in ``/2``."""
    if not v:
        return None
    if isinstance(v, str):
        return SupportChoice.parse(v)
    return SupportChoice(str(v["owner"]), v.get("part"), str(v["surface"]))


def read_scene(path: str | Path) -> Scene:
    """Rebuild a Scene from a folder (or a ``scene.json`` path) written by :func:`write_scene`."""
    from ..assets.registry import categories
    from ..pag.io import loads_document
    from .validate import contacts_problems, scene_problems

    p = Path(path)
    f = p / "scene.json" if p.is_dir() else p
    if not f.exists():
        raise InputError(Problem("", f"no scene.json here — solve a PAG first "
                                     f"(parse3d solve PAG --out {p})", str(f), "io"))
    d = loads_document(read_input_text(f, what="scene file"), kind="json", file=str(f))
    problems = scene_problems(d, file=str(f), categories=set(categories()))
    if problems:
        raise InputError(problems)
    pag = PAG.from_dict(d["pag"])
    shell = build_shell(pag.room, wall_thickness=float(d["room"].get("wall_thickness", 0.12)))
    scene = Scene(pag, int(d["seed"]), shell, timings=dict(d.get("timings", {})),
                  settled=bool(d.get("settled")), meta=d.get("meta", {}))
    for od in d["objects"]:
        repairs = [Repair(int(r["round"]), str(r["cause"]), str(r["action"]))
                   for r in od.get("repairs", [])]
        if od["status"] != "placed":
            scene.objects[od["id"]] = PlacedObject(od["id"], od["category"], None,
                                                   status=od["status"], reason=od.get("reason"),
                                                   repairs=repairs)
            continue
        asset = _load_asset(od["asset"])
        pose = od["pose"]
        o = PlacedObject(od["id"], od["category"], asset, float(od["scale"]),
                         quat_to_matrix(pose["quaternion"]), np.array(pose["position"], float),
                         "placed", None, int(od.get("trials", 0)), None,
                         bool(od.get("fixed", False)), support_choice=_support(od.get("support")),
                         repairs=repairs, stacked_on=od.get("stacked_on"),
                         rests_on=od.get("rests_on"))
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
                                             r.get("detail", ""), r.get("relaxed")))
    cf = f.parent / "contacts.json"
    n_contacts = (d.get("summary") or {}).get("contacts")
    if cf.exists() and n_contacts is not None:  # None: the contacts.json is not this scene's
        cd = loads_document(read_input_text(cf, what="contacts file"), kind="json",
                            file=str(cf))
        problems = contacts_problems(cd, file=str(cf))
        if problems:
            raise InputError(problems)
        scene.contacts = [Contact(c["a"], c["b"], int(c["samples"]), float(c["min_distance"]))
                          for c in cd]
    return scene
