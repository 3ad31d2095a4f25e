"""Template and motif checks on the document alone: the JSON Schemas, then meaning.

Meaning covers ranges (count, scale, room sizes, the L-shaped room's notch), duplicate ids,
undeclared ``$params`` of motifs and the repeated-parent and ``stack`` rules. Checks that need
the expanded PAG live in :mod:`parse3d.datagen.template_load`.
"""

from __future__ import annotations

import json
import re
from functools import lru_cache
from pathlib import Path
from typing import Any

from ..errors import Problem
from ..pag.refs import is_room_element
from ..pag.schema import _messages, suggest
from .template_model import _OBJ_RE, _PARAM_RE, _REL_KEYS, _SUPPORTS


@lru_cache(maxsize=2)
def _schema_validator(fmt: str):
    import jsonschema

    fname = {"template": "template-1.schema.json", "motif": "motif-1.schema.json"}[fmt]
    schema = json.loads((Path(__file__).resolve().parent / fname).read_text(encoding="utf-8"))
    cls = jsonschema.validators.validator_for(schema)
    cls.check_schema(schema)
    return cls(schema)


#: Most copies a ``count`` may make (the schemas' maximum).
MAX_COUNT = 100


def _too_many(v: Any) -> bool:
    vals = v if isinstance(v, list) else [v]
    return any(isinstance(x, int) and not isinstance(x, bool) and x > MAX_COUNT for x in vals)


def _schema_problems(data: Any, fmt: str, file: str | None) -> list[Problem]:
    errors = sorted(_schema_validator(fmt).iter_errors(data),
                    key=lambda e: [str(p) for p in e.absolute_path])
    out: list[Problem] = []
    seen: set[tuple[str, str]] = set()
    for err in errors:
        for ptr, msg in _messages(err):
            if err.validator == "enum" and ptr == "/room_type":
                msg = msg.replace("unknown room_type", "unknown room type")
            if re.search(r"/count(/[01])?$", ptr) and _too_many(err.instance):
                msg = (f"count {err.instance} is too large: a count is at most {MAX_COUNT} "
                       "copies (an integer or [low, high])")
            if (ptr, msg) not in seen:
                seen.add((ptr, msg))
                out.append(Problem(ptr, msg, file, "schema"))
    return out


def _motif_meaning(data: dict[str, Any], file: str) -> list[Problem]:
    problems: list[Problem] = []

    def add(ptr: str, msg: str, kind: str = "reference") -> None:
        problems.append(Problem(ptr, msg, file, kind))

    if Path(file).stem != data["name"]:
        add("/name", f"the motif is named {data['name']!r} but its file is "
            f"{Path(file).name!r}: name the file {data['name']}.yaml", "schema")
    params = data.get("params") or {}
    ids = _check_objects(data["objects"], add)
    for i, r in enumerate(data["relations"]):
        for key in _REL_KEYS[1:]:
            text = r[key]
            m = _PARAM_RE.match(text)
            if m:
                if m.group(1) not in params:
                    add(f"/relations/{i}/{key}", f"unknown parameter ${m.group(1)}"
                        f"{suggest(m.group(1), params)} (declare it under params)")
                continue
            obj = _OBJ_RE.match(text).group(1)
            if obj and not is_room_element(obj) and obj not in ids:
                add(f"/relations/{i}/{key}", f"unknown object {obj!r}{suggest(obj, ids)}; a "
                    "motif names its own objects, room elements, or $params")
        for key, v in r.items():
            if key in _REL_KEYS or not isinstance(v, str):
                continue
            m = _PARAM_RE.match(v)
            if m and m.group(1) not in params:
                add(f"/relations/{i}/{key}", f"unknown parameter ${m.group(1)}"
                    f"{suggest(m.group(1), params)} (declare it under params)", "parameter")
    for j, o in enumerate(data["objects"]):
        cats = [o["category"]] if isinstance(o["category"], str) else o["category"]
        for c in cats:
            m = _PARAM_RE.match(c)
            if m and m.group(1) not in params:
                add(f"/objects/{j}/category", f"unknown parameter ${m.group(1)}"
                    f"{suggest(m.group(1), params)} (declare it under params)")
    _check_relations(data, ids, add, local=lambda t: _OBJ_RE.match(t).group(1))
    return problems


def _check_objects(objects: list[dict[str, Any]], add, base: str = "") -> dict[str, int]:
    """Range checks of object items; returns id -> index of the valid ids."""
    ids: dict[str, int] = {}
    for j, o in enumerate(objects):
        ptr = f"{base}/objects/{j}"
        if o["id"] in ids:
            add(f"{ptr}/id", f"duplicate object id {o['id']!r} (first declared at "
                f"{base}/objects/{ids[o['id']]})")
        else:
            ids[o["id"]] = j
        c = o.get("count")
        if isinstance(c, list) and c[0] > c[1]:
            add(f"{ptr}/count", f"count low {c[0]} is above high {c[1]}: write [low, high]",
                "parameter")
        sc = o.get("scale")
        if not isinstance(sc, list):
            continue
        if (sc[0] <= 0 or sc[1] <= 0):
            add(f"{ptr}/scale", f"scale factors must be positive, got {sc}", "parameter")
        elif sc[0] > sc[1]:
            add(f"{ptr}/scale", f"scale low {sc[0]:g} is above high {sc[1]:g}: write "
                "[low, high]", "parameter")
    return ids


def _count_hi(o: dict[str, Any]) -> int | None:
    c = o.get("count")
    if c is None:
        return None
    return int(c[1]) if isinstance(c, list) else int(c)


def _check_relations(data: dict[str, Any], ids: dict[str, int], add, *, local) -> None:
    """``stack`` and repeated-parent rules; ``local(ref)`` gives the referenced local id."""
    objs = data["objects"]
    for i, r in enumerate(data["relations"]):
        ptr = f"/relations/{i}"
        child, parent = local(r["child"]), local(r["parent"])
        co = objs[ids[child]] if child in ids else None
        po = objs[ids[parent]] if parent in ids else None
        c_rep = co is not None and "count" in co
        p_rep = po is not None and "count" in po
        if r.get("stack"):
            if r["relation"] not in _SUPPORTS:
                add(f"{ptr}/stack", f"stack applies to support relations only "
                    f"({', '.join(sorted(_SUPPORTS))}), not {r['relation']}", "parameter")
            elif co is not None and not c_rep:
                add(f"{ptr}/stack", f"stack needs a repeated child: give {child!r} a count",
                    "parameter")
            continue
        if p_rep:
            if c_rep and co.get("count") == po.get("count"):
                continue  # copy k relates to copy k
            add(f"{ptr}/parent", f"{parent!r} is repeated (count), so it cannot be the parent "
                "of a single object: make the child repeated with the same count (copy k "
                f"then relates to copy k), or use stack: true on {child!r}'s support relation "
                "for a pile", "graph")


def _check_room(room: dict[str, Any], add) -> None:
    for key in ("width", "depth", "height"):
        v = room[key]
        if isinstance(v, list) and v[0] > v[1]:
            add(f"/room/{key}", f"{key} low {v[0]:g} is above high {v[1]:g}: write [low, high]",
                "parameter")
    shape = room.get("shape", "rectangle")
    if shape == "L" and "notch" not in room:
        add("/room", "an L-shaped room needs notch: {width: [lo, hi], depth: [lo, hi]}, the "
            "part cut from the +x+y corner", "geometry")
    if shape != "L" and "notch" in room:
        add("/room/notch", "notch applies to L-shaped rooms only: add shape: L", "geometry")
    if shape == "L" and "notch" in room:
        for key in ("width", "depth"):
            nv, rv = room["notch"][key], room[key]
            n_hi = nv[1] if isinstance(nv, list) else nv
            r_lo = rv[0] if isinstance(rv, list) else rv
            if isinstance(nv, list) and nv[0] > nv[1]:
                add(f"/room/notch/{key}", f"notch {key} low {nv[0]:g} is above high {nv[1]:g}",
                    "parameter")
            elif n_hi >= r_lo:
                add(f"/room/notch/{key}", f"the notch {key} (up to {n_hi:g} m) must be smaller "
                    f"than the room {key} (from {r_lo:g} m)", "geometry")


def _vocab(vocabulary):
    if vocabulary is not None:
        return vocabulary
    from ..assets.registry import vocabulary as registry_vocabulary

    return registry_vocabulary()


def _dedupe(problems: list[Problem]) -> list[Problem]:
    seen, out = set(), []
    for p in problems:
        key = (p.file, p.pointer, p.message)
        if key not in seen:
            seen.add(key)
            out.append(p)
    return out
