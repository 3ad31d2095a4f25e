"""The JSON Schema of ``pag/1`` files and the first validation layer.

The schema ships as ``pag-1.schema.json`` inside the package. :func:`schema_problems` runs it
over a document and turns every violation into a :class:`~parse3d.errors.Problem` with a JSON
pointer and a message a person can act on (unknown keys get the closest allowed key as a
suggestion).

Examples
--------
>>> [p.message for p in schema_problems({"format": "pag/1", "name": "x",
...     "room": {"type": "study", "footprint": [[0, 0], [3, 0], [3, 3]], "height": 2.7},
...     "objects": [], "relations": [{"relaton": "ON", "child": "a", "parent": "floor"}]})]
["missing key 'relation'", "unknown key 'relaton' — did you mean 'relation'?"]
"""

from __future__ import annotations

import difflib
import json
import re
from functools import lru_cache
from importlib import resources
from typing import Any

from ..errors import Problem

__all__ = ["SCHEMA_FILE", "pag_schema", "schema_problems", "json_pointer", "suggest"]

SCHEMA_FILE = "pag-1.schema.json"

_TYPE_NAMES = {
    "object": "an object",
    "array": "a list",
    "string": "a string",
    "number": "a number",
    "integer": "an integer",
    "boolean": "true or false",
    "null": "null",
}


@lru_cache(maxsize=1)
def pag_schema() -> dict[str, Any]:
    """The ``pag/1`` JSON Schema (draft 2020-12) as a dict."""
    text = resources.files(__package__).joinpath(SCHEMA_FILE).read_text(encoding="utf-8")
    return json.loads(text)


@lru_cache(maxsize=1)
def _validator():
    import jsonschema

    schema = pag_schema()
    cls = jsonschema.validators.validator_for(schema)
    cls.check_schema(schema)
    return cls(schema)


def json_pointer(path) -> str:
    """RFC 6901 pointer of a path of keys and indices (``""`` is the whole document)."""
    out = []
    for part in path:
        s = str(part).replace("~", "~0").replace("/", "~1")
        out.append("/" + s)
    return "".join(out)


def suggest(word: str, candidates, *, cutoff: float = 0.6) -> str:
    """`` — did you mean 'x'?`` for the closest candidate, or ``""``."""
    if not isinstance(word, str):
        return ""
    close = difflib.get_close_matches(word, list(candidates), n=1, cutoff=cutoff)
    return f" — did you mean {close[0]!r}?" if close else ""


def _json_type(value: Any) -> str:
    if isinstance(value, bool):
        return "a boolean"
    if value is None:
        return "null"
    if isinstance(value, (int, float)):
        return "a number"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "an object"
    return type(value).__name__


def _short(value: Any) -> str:
    try:
        text = json.dumps(value)
    except (TypeError, ValueError):
        text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def _messages(err) -> list[tuple[str, str]]:
    """(pointer, message) pairs for one jsonschema error."""
    ptr = json_pointer(err.absolute_path)
    v = err.validator
    inst = err.instance
    if v == "additionalProperties":
        allowed = list(err.schema.get("properties", {}))
        extra = [k for k in inst if k not in allowed] if isinstance(inst, dict) else []
        return [
            (f"{ptr}/{json_pointer([k])[1:]}", f"unknown key {k!r}{suggest(k, allowed)}"
             + ("" if suggest(k, allowed) else f" (allowed keys: {', '.join(allowed)})"))
            for k in extra
        ]
    if v == "required":
        missing = [k for k in err.validator_value if not (isinstance(inst, dict) and k in inst)]
        return [(ptr, f"missing key {k!r}") for k in missing]
    if v == "type":
        want = err.validator_value
        wants = [want] if isinstance(want, str) else list(want)
        names = " or ".join(_TYPE_NAMES.get(w, w) for w in wants)
        return [(ptr, f"expected {names}, got {_json_type(inst)} {_short(inst)}")]
    if v == "const":
        return [(ptr, f"must be {err.validator_value!r}, got {_short(inst)}")]
    if v == "enum":
        choices = [str(c) for c in err.validator_value]
        what = err.absolute_path[-1] if err.absolute_path else "value"
        hint = suggest(inst, choices) if isinstance(inst, str) else ""
        if not hint and isinstance(inst, str):
            hint = suggest(inst.upper(), choices)
        shown = repr(inst) if isinstance(inst, str) else _short(inst)
        return [(ptr, f"unknown {what} {shown}{hint} (one of: {', '.join(choices)})")]
    if v == "pattern":
        return [(ptr, f"{_short(inst)} is not a valid identifier: use letters, digits, '_' and "
                      "'-', starting with a letter or '_'")]
    if v == "minItems":
        n = err.validator_value
        return [(ptr, f"needs at least {n} item{'s' if n != 1 else ''}, got {len(inst)}")]
    if v == "maxItems":
        return [(ptr, f"needs at most {err.validator_value} items, got {len(inst)}")]
    if v == "minLength":
        return [(ptr, "must not be empty")]
    if v in ("oneOf", "anyOf"):
        # Report the errors of the alternative whose type matches the value, if one does.
        alts = err.validator_value
        have = _json_type(inst)
        for k, alt in enumerate(alts):
            t = alt.get("type")
            if t and _TYPE_NAMES.get(t) == have:
                subs = [e for e in err.context if e.relative_schema_path[0] == k]
                out = [m for e in subs for m in _messages(e)]
                if out:
                    return out
        kinds = [_TYPE_NAMES.get(a.get("type"), "another value") for a in alts]
        want = " or ".join(dict.fromkeys(kinds))
        return [(ptr, f"expected {want}, got {have} {_short(inst)}")]
    return [(ptr, err.message)]


def schema_problems(data: Any, *, file: str | None = None) -> list[Problem]:
    """Every violation of the ``pag/1`` schema, in document order.

    Object and relation items, and the rest of the document, that pass a fast structural
    check equivalent to (or stricter than) their schema are not handed to jsonschema, which
    keeps large documents fast and a valid file's check free of importing it; the others are
    validated (item by item) for precise messages.

    Parameters
    ----------
    data : any
        The parsed document.
    file : str, optional
        Recorded in each problem.

    Returns
    -------
    list of Problem
        Kind ``"schema"``; an empty list for a document that follows the schema.
    """
    errors: list[tuple[tuple, Any]] = []
    if isinstance(data, dict):
        skeleton = dict(data)
        for key, fast in (("objects", _fast_object), ("relations", _fast_relation)):
            items = data.get(key)
            if not isinstance(items, list):
                continue
            skeleton[key] = []
            for i, item in enumerate(items):
                if not fast(item):
                    errors += [((key, i, *e.absolute_path), e)
                               for e in _item_validator(key).iter_errors(item)]
        if not _fast_skeleton(skeleton):
            errors += [(tuple(e.absolute_path), e) for e in _validator().iter_errors(skeleton)]
    else:
        errors += [(tuple(e.absolute_path), e) for e in _validator().iter_errors(data)]
    out: list[Problem] = []
    seen: set[tuple[str, str]] = set()
    for prefix, err in sorted(errors, key=lambda pe: _path_key(pe[0])):
        base = json_pointer(prefix[: len(prefix) - len(err.absolute_path)])
        for ptr, msg in _messages(err):
            ptr = base + ptr
            if (ptr, msg) not in seen:
                seen.add((ptr, msg))
                out.append(Problem(ptr, msg, file, "schema"))
    return out


@lru_cache(maxsize=2)
def _item_validator(key: str):
    import jsonschema

    schema = pag_schema()
    name = {"objects": "object", "relations": "relation"}[key]
    sub = {"$schema": schema["$schema"], "$ref": f"#/$defs/{name}", "$defs": schema["$defs"]}
    return jsonschema.validators.validator_for(schema)(sub)


_ID_RE = re.compile(r"[A-Za-z_][A-Za-z0-9_\-]*")


def _num(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _num_or_pair(v: Any) -> bool:
    return _num(v) or (isinstance(v, list) and len(v) == 2 and _num(v[0]) and _num(v[1]))


def _point(v: Any) -> bool:
    return isinstance(v, list) and len(v) == 2 and _num(v[0]) and _num(v[1])


def _fast_skeleton(d: dict) -> bool:
    """Whether a document whose ``objects`` and ``relations`` lists were emptied surely follows
    the schema (False: ask jsonschema)."""
    if not (d.keys() <= {"format", "name", "room", "objects", "relations", "meta"}
            and d.keys() >= {"format", "name", "room", "objects", "relations"}):
        return False
    room = d["room"]
    if not (isinstance(d["format"], str) and d["format"] == "pag/1" and isinstance(d["name"], str)
            and d["objects"] == [] and d["relations"] == []
            and isinstance(d.get("meta", {}), dict) and isinstance(room, dict)
            and room.keys() == {"type", "footprint", "height"}):
        return False
    fp = room["footprint"]
    return (isinstance(room["type"], str) and _num(room["height"]) and isinstance(fp, list)
            and len(fp) >= 3 and all(_point(p) for p in fp))


def _fast_object(o: Any) -> bool:
    if not isinstance(o, dict) or not o.keys() <= {"id", "category", "scale"}:
        return False
    oid, cat = o.get("id"), o.get("category")
    if not (isinstance(oid, str) and _ID_RE.fullmatch(oid)):
        return False
    if isinstance(cat, str):
        if not cat:
            return False
    elif not (isinstance(cat, list) and cat and all(isinstance(c, str) and c for c in cat)):
        return False
    sc = o.get("scale", None)
    return "scale" not in o or (isinstance(sc, list) and len(sc) == 2 and all(map(_num, sc)))


@lru_cache(maxsize=1)
def _relation_rules() -> tuple[frozenset, frozenset, dict]:
    props = pag_schema()["$defs"]["relation"]["properties"]
    rules = {}
    for key, sub in props.items():
        if key in ("relation", "child", "parent"):
            continue
        if "enum" in sub:
            rules[key] = _enum_rule(frozenset(sub["enum"]))
        elif sub.get("type") == "number":
            rules[key] = _num
        else:
            rules[key] = _num_or_pair
    return frozenset(props), frozenset(props["relation"]["enum"]), rules


def _enum_rule(allowed: frozenset):
    """A check that a value is one of ``allowed`` (any unhashable value is not)."""
    return lambda v: isinstance(v, str) and v in allowed


def _fast_relation(r: Any) -> bool:
    keys, names, rules = _relation_rules()
    if not isinstance(r, dict) or not r.keys() <= keys:
        return False
    if r.get("relation") not in names if isinstance(r.get("relation"), str) else True:
        return False
    if not (isinstance(r.get("child"), str) and isinstance(r.get("parent"), str)):
        return False
    for k, v in r.items():
        rule = rules.get(k)
        if rule is not None and not (isinstance(v, (str, int, float, list)) and rule(v)):
            return False
    return True


def _path_key(path) -> tuple:
    return tuple((0, p, "") if isinstance(p, int) else (1, 0, str(p)) for p in path)
