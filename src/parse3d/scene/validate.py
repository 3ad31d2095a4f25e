"""Validation of ``scene.json`` (``parse3d-scene/1`` and ``/2``) and ``contacts.json``.

A scene file may be hand-edited or damaged; :func:`scene_problems` reports every problem
found in one pass, each with a JSON pointer, as :func:`parse3d.pag.validate.validate_data`
does for PAGs, so that ``settle`` and ``render`` answer a broken file with one line per
problem (exit 2) instead of a traceback.

What is checked is what reading a scene relies on: the format, the seed, the embedded PAG
(a valid ``pag/1`` document), the room's wall thickness, every object (id, category, status;
for placed ones the asset reference, a positive finite scale and finite poses with a non-zero
quaternion), the relation records and the summary. Keys this module does not know are
allowed everywhere (newer writers add per-object keys such as ``repairs``, ``stacked_on`` or
``joints``), and an object's ``support`` may be a reference string, an object or null.

Examples
--------
>>> scene_problems({"format": "parse3d-scene/1"}, file="scene.json")[0].pointer
'/seed'
"""

from __future__ import annotations

import math
from typing import Any

from ..errors import Problem
from ..pag.validate import validate_data
from ..relations import SURFACES

__all__ = ["SCENE_FORMATS", "MAX_SCALE", "scene_problems", "contacts_problems"]

#: The scene formats this version reads.
SCENE_FORMATS = ("parse3d-scene/1", "parse3d-scene/2")
#: Largest object scale factor a scene may record.
MAX_SCALE = 1000.0
_STATUSES = ("placed", "failed")


def _num(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _int(v: Any) -> bool:
    return isinstance(v, int) and not isinstance(v, bool)


def _type(v: Any) -> str:
    if v is None:
        return "null"
    if isinstance(v, bool):
        return "a boolean"
    if isinstance(v, (int, float)):
        return f"the number {v}"
    if isinstance(v, str):
        return "a string"
    if isinstance(v, list):
        return "a list"
    if isinstance(v, dict):
        return "an object"
    return type(v).__name__


class _Checker:
    def __init__(self, file: str | None) -> None:
        self.file = file
        self.problems: list[Problem] = []

    def add(self, ptr: str, msg: str, kind: str = "schema") -> None:
        self.problems.append(Problem(ptr or "/", msg, self.file, kind))

    def need(self, d: dict, key: str, base: str, test, what: str) -> Any:
        """``d[key]`` when present and ``test(value)``; else a problem and None."""
        if key not in d:
            self.add(f"{base}/{key}", f"missing key {key!r} ({what})")
            return None
        v = d[key]
        if not test(v):
            self.add(f"{base}/{key}", f"expected {what}, got {_type(v)}")
            return None
        return v

    def opt(self, d: dict, key: str, base: str, test, what: str) -> None:
        if key in d and d[key] is not None and not test(d[key]):
            self.add(f"{base}/{key}", f"expected {what}, got {_type(d[key])}")

    def vec(self, v: Any, n: int) -> bool:
        return isinstance(v, list) and len(v) == n and all(_num(x) for x in v)

    def pose(self, d: dict, key: str, base: str, *, required: bool) -> None:
        if key not in d or (d[key] is None and not required):
            if required:
                self.add(f"{base}/{key}", f"missing key {key!r} (the object's pose)")
            return
        p = d[key]
        ptr = f"{base}/{key}"
        if not isinstance(p, dict):
            self.add(ptr, f"expected an object with position and quaternion, got {_type(p)}")
            return
        self.need(p, "position", ptr, lambda v: self.vec(v, 3), "[x, y, z] of finite numbers")
        q = self.need(p, "quaternion", ptr, lambda v: self.vec(v, 4),
                      "[w, x, y, z] of finite numbers")
        if q is not None and math.sqrt(sum(x * x for x in q)) < 1e-6:
            self.add(f"{ptr}/quaternion", "the quaternion is zero: it describes no rotation")


def scene_problems(data: Any, *, file: str | None = None,
                   categories: set[str] | None = None) -> list[Problem]:
    """Every problem of a ``scene.json`` document; empty when it can be read.

    Parameters
    ----------
    data : any
        The parsed document.
    file : str, optional
        Recorded in each problem.
    categories : set of str, optional
        Known asset categories; a generated asset of another category is a problem.

    Returns
    -------
    list of Problem
    """
    c = _Checker(file)
    if not isinstance(data, dict):
        c.add("", f"a scene file holds a JSON object, got {_type(data)}")
        return c.problems
    fmt = data.get("format")
    if fmt not in SCENE_FORMATS:
        c.add("/format", f"expected format {' or '.join(map(repr, SCENE_FORMATS))}, got "
                         f"{fmt!r}: is this a scene.json written by parse3d solve?")
        return c.problems
    c.need(data, "seed", "", lambda v: _int(v) and v >= 0, "a non-negative integer")
    pag = c.need(data, "pag", "", lambda v: isinstance(v, dict), "the PAG as an object")
    if pag is not None:
        for p in validate_data(pag, file=file):
            c.add("/pag" + (p.pointer if p.pointer != "/" else ""), p.message, p.kind)
    room = data.get("room")
    if room is not None:
        if not isinstance(room, dict):
            c.add("/room", f"expected an object, got {_type(room)}")
        else:
            c.opt(room, "wall_thickness", "/room",
                  lambda v: _num(v) and 0 <= v <= 1.0, "a wall thickness in [0, 1] m")
    objs = c.need(data, "objects", "", lambda v: isinstance(v, list), "a list of objects")
    seen: dict[str, int] = {}
    for j, o in enumerate(objs or []):
        base = f"/objects/{j}"
        if not isinstance(o, dict):
            c.add(base, f"expected an object, got {_type(o)}")
            continue
        oid = c.need(o, "id", base, lambda v: isinstance(v, str) and v, "a non-empty string")
        if oid is not None:
            if oid in seen:
                c.add(f"{base}/id", f"duplicate object id {oid!r} (also /objects/{seen[oid]})")
            seen[oid] = j
        c.need(o, "category", base, lambda v: isinstance(v, str) and v, "a category name")
        status = c.need(o, "status", base, lambda v: v in _STATUSES,
                        f"one of {', '.join(_STATUSES)}")
        c.opt(o, "flags", base, lambda v: isinstance(v, list)
              and all(isinstance(x, str) for x in v), "a list of strings")
        c.opt(o, "joints", base, lambda v: isinstance(v, dict)
              and all(_num(x) for x in v.values()), "an object of finite numbers")
        c.opt(o, "support", base, lambda v: isinstance(v, str) or (
            isinstance(v, dict) and isinstance(v.get("owner"), str)
            and isinstance(v.get("surface"), str) and isinstance(v.get("part"), (str, type(None)))),
              "a reference string, an object {owner, part, surface} or null")
        c.opt(o, "stacked_on", base, lambda v: isinstance(v, str), "an object id")
        c.opt(o, "rests_on", base, lambda v: v in SURFACES, f"one of {', '.join(SURFACES)}")
        c.opt(o, "repairs", base, lambda v: isinstance(v, list) and all(
            isinstance(r, dict) and _int(r.get("round")) and isinstance(r.get("cause"), str)
            and isinstance(r.get("action"), str) for r in v),
              "a list of {round, cause, action}")
        if status != "placed":
            continue
        asset = c.need(o, "asset", base, lambda v: isinstance(v, dict), "the asset reference")
        if asset is not None:
            ab = f"{base}/asset"
            if asset.get("path") is not None:
                c.need(asset, "path", ab, lambda v: isinstance(v, str) and v, "a file path")
            else:
                cat = c.need(asset, "category", ab, lambda v: isinstance(v, str) and v,
                             "a category name")
                c.need(asset, "seed", ab, lambda v: _int(v) and v >= 0,
                       "a non-negative integer (the asset's pool slot)")
                if cat is not None and categories is not None and cat not in categories:
                    c.add(f"{ab}/category", f"unknown asset category {cat!r}: this parse3d "
                                            "cannot rebuild the asset", "vocabulary")
        c.need(o, "scale", base, lambda v: _num(v) and 0 < v <= MAX_SCALE,
               f"a finite scale in (0, {MAX_SCALE:g}]")
        c.pose(o, "pose", base, required=True)
        c.pose(o, "settled_pose", base, required=False)
        c.opt(o, "fixed", base, lambda v: isinstance(v, bool), "true or false")
        c.opt(o, "trials", base, lambda v: _int(v) and v >= 0, "a non-negative integer")
    rels = data.get("relations", [])
    if not isinstance(rels, list):
        c.add("/relations", f"expected a list, got {_type(rels)}")
        rels = []
    for i, r in enumerate(rels):
        base = f"/relations/{i}"
        if not isinstance(r, dict):
            c.add(base, f"expected an object, got {_type(r)}")
            continue
        c.need(r, "index", base, lambda v: _int(v) and v >= 0, "a non-negative integer")
        for key in ("relation", "child", "parent"):
            c.need(r, key, base, lambda v: isinstance(v, str), "a string")
        for key in ("holds", "holds_settled"):
            c.opt(r, key, base, lambda v: isinstance(v, bool), "true, false or null")
        for key in ("residual", "residual_settled"):
            c.opt(r, key, base, lambda v: isinstance(v, dict), "an object or null")
    c.opt(data, "settled", "", lambda v: isinstance(v, bool), "true or false")
    c.opt(data, "timings", "", lambda v: isinstance(v, dict)
          and all(_num(x) for x in v.values()), "an object of finite numbers")
    c.opt(data, "meta", "", lambda v: isinstance(v, dict), "an object")
    summ = data.get("summary")
    if summ is not None:
        if not isinstance(summ, dict):
            c.add("/summary", f"expected an object, got {_type(summ)}")
        else:
            c.opt(summ, "contacts", "/summary", lambda v: _int(v) and v >= 0,
                  "a non-negative integer or null")
    return c.problems


def contacts_problems(data: Any, *, file: str | None = None) -> list[Problem]:
    """Every problem of a ``contacts.json`` document (a list of part pairs)."""
    c = _Checker(file)
    if not isinstance(data, list):
        c.add("", f"a contacts file holds a list of contacts, got {_type(data)}")
        return c.problems
    for k, x in enumerate(data):
        base = f"/{k}"
        if not isinstance(x, dict):
            c.add(base, f"expected an object, got {_type(x)}")
            continue
        c.need(x, "a", base, lambda v: isinstance(v, str), "a part name 'object:part'")
        c.need(x, "b", base, lambda v: isinstance(v, str), "a part name 'object:part'")
        c.need(x, "samples", base, lambda v: _int(v) and v >= 0, "a non-negative integer")
        c.need(x, "min_distance", base, _num, "a finite number (metres)")
        if len(c.problems) > 50:
            break
    return c.problems
