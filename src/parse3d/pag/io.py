"""Reading and writing ``pag/1`` files (JSON canonical, YAML accepted).

:func:`load_pag` reads, validates (schema and meaning, every problem at once) and builds a
:class:`~parse3d.pag.model.PAG`; :func:`save_pag` writes one back so that
``load_pag(save_pag(p, path)) == p``. The file type follows the extension: ``.json``, or
``.yaml`` / ``.yml``.

YAML is read with the YAML 1.2 core rules for scalars: only ``true``/``false`` are booleans
(so ``relation: ON`` stays the string ``"ON"``) and dates stay strings.

Parsing is bounded before any object is built (hostile files cannot crash or hang a command):

* the input must be a regular file of at most :data:`~parse3d._files.MAX_INPUT_BYTES`
  (a FIFO or device is refused without being opened for a blocking read);
* nesting is at most :data:`MAX_DEPTH` levels (checked on the token or event stream, so deep
  nesting never reaches a recursive parser);
* YAML aliases may expand the document to at most :data:`MAX_NODES` nodes in all;
* YAML tags are limited to the plain JSON types (``!!str``, ``!!int``, ``!!float``,
  ``!!bool``, ``!!null``, ``!!map``, ``!!seq``): a timestamp, set, binary or any other tag is
  an error with the pointer of the tagged node;
* a repeated key in a JSON object or YAML mapping is an error with the pointer of the repeat;
* numbers must be finite (``NaN``, ``Infinity``, ``1e400``, ``.inf`` are errors).
"""

from __future__ import annotations

import functools
import json
import math
import re
from pathlib import Path
from typing import Any

from .._files import MAX_DEPTH, _esc, loads_json, read_input_text
from ..errors import InputError, Problem, SchemaError
from .model import PAG
from .validate import Vocabulary, validate_data

__all__ = ["load_pag", "save_pag", "read_document", "dumps_pag", "loads_document", "MAX_DEPTH",
           "MAX_NODES"]

#: Most nodes (scalars, lists, objects) a document may expand to, YAML aliases included.
MAX_NODES = 2_000_000

_JSON_EXT = (".json",)
_YAML_EXT = (".yaml", ".yml")


@functools.cache
def _yaml():
    """``(yaml, Loader, Dumper)``, made on first use (PyYAML costs start-up time that JSON
    documents do not need). Loader: safe, YAML 1.2 booleans, no timestamp conversion;
    Dumper: safe, keeps key order."""
    import yaml

    safe_loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    safe_dumper = getattr(yaml, "CSafeDumper", yaml.SafeDumper)

    class _Loader(safe_loader):
        """Safe YAML loader with YAML 1.2 booleans and no timestamp conversion."""

    _Loader.yaml_implicit_resolvers = {
        ch: [(tag, rx) for tag, rx in rs
             if tag not in ("tag:yaml.org,2002:bool", "tag:yaml.org,2002:timestamp")]
        for ch, rs in yaml.SafeLoader.yaml_implicit_resolvers.items()
    }
    _Loader.add_implicit_resolver(
        "tag:yaml.org,2002:bool", re.compile(r"^(?:true|True|TRUE|false|False|FALSE)$"),
        list("tTfF"),
    )

    class _Dumper(safe_dumper):
        """Safe YAML dumper that keeps key order."""

    return yaml, _Loader, _Dumper


def __getattr__(name: str):
    # ``_Loader`` and ``_Dumper`` as module attributes, for code that imports them
    if name in ("_Loader", "_Dumper"):
        return _yaml()[1 if name == "_Loader" else 2]
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def _kind(path: Path) -> str:
    ext = path.suffix.lower()
    if ext in _JSON_EXT:
        return "json"
    if ext in _YAML_EXT:
        return "yaml"
    raise InputError(Problem("", f"unknown file type {path.suffix or '(none)'!r}: use .json, "
                             ".yaml or .yml", str(path), "io"))


def loads_document(text: str, *, kind: str, file: str | None = None) -> Any:
    """Parse JSON or YAML text, bounded; malformed text raises :class:`SchemaError`.

    Parameters
    ----------
    text : str
    kind : {"json", "yaml"}
    file : str, optional
        Named in the error.

    Raises
    ------
    SchemaError
        Syntax errors (with line and column), nesting deeper than :data:`MAX_DEPTH`, YAML
        aliases expanding past :data:`MAX_NODES`, tags that are not plain JSON types, repeated
        keys and non-finite numbers (each with the JSON pointer of the offending node).
    """
    if kind == "json":
        return loads_json(text, file=file)
    _yaml_precheck(text, file)
    yaml, _Loader, _ = _yaml()
    try:
        data = yaml.load(text, Loader=_Loader)  # noqa: S506 - a SafeLoader subclass
    except yaml.YAMLError as e:
        mark = getattr(e, "problem_mark", None)
        where = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        what = getattr(e, "problem", None) or str(e)
        raise SchemaError(Problem("", f"invalid YAML{where}: {what}", file, "syntax")) from None
    except RecursionError:
        raise SchemaError(Problem("", "invalid YAML: nested too deeply", file, "syntax")
                          ) from None
    bad = _non_finite(data, "")
    if bad:
        raise SchemaError(Problem(bad, "not a finite number (.nan and .inf are not allowed)",
                                  file, "syntax"))
    return data


def _non_finite(v: Any, ptr: str) -> str | None:
    stack = [(v, ptr)]
    while stack:
        v, ptr = stack.pop()
        if isinstance(v, float) and not math.isfinite(v):
            return ptr or "/"
        if isinstance(v, dict):
            stack += [(x, f"{ptr}/{_esc(str(k))}") for k, x in v.items()]
        elif isinstance(v, list):
            stack += [(x, f"{ptr}/{i}") for i, x in enumerate(v)]
    return None


_PLAIN_TAGS = frozenset("tag:yaml.org,2002:" + t
                        for t in ("str", "int", "float", "bool", "null", "map", "seq"))


def _yaml_precheck(text: str, file: str | None) -> None:
    """Walk the YAML event stream (iterative, no object built): depth, expanded size, tags and
    repeated keys, each reported with the JSON pointer of the node."""
    yaml, _Loader, _ = _yaml()
    loader = _Loader(text)
    # stack of [kind, pointer, key-expected flag or index, current key, keys seen, size]
    stack: list[list[Any]] = []
    anchors: dict[str, int] = {}
    open_anchors: list[tuple[str, int, int]] = []  # (anchor, stack depth, nodes at start)
    nodes = 0
    problems: list[Problem] = []

    def fail(ptr: str, msg: str) -> None:
        problems.append(Problem(ptr or "/", msg, file, "syntax"))

    try:
        while True:
            ev = loader.get_event()
            if ev is None:
                break
            if isinstance(ev, (yaml.MappingEndEvent, yaml.SequenceEndEvent)):
                stack.pop()
                while open_anchors and open_anchors[-1][1] == len(stack) + 1:
                    name, _d, start = open_anchors.pop()
                    anchors[name] = nodes - start
                _after_value(stack)
                continue
            if not isinstance(ev, (yaml.ScalarEvent, yaml.MappingStartEvent,
                                   yaml.SequenceStartEvent, yaml.AliasEvent)):
                continue
            # where this node sits
            ptr, is_key = "", False
            if stack:
                top = stack[-1]
                if top[0] == "map":
                    if top[2]:
                        is_key = True
                        ptr = top[1]
                    else:
                        ptr = f"{top[1]}/{_esc(str(top[3]))}"
                else:
                    top[2] += 1
                    ptr = f"{top[1]}/{top[2]}"
            if isinstance(ev, yaml.AliasEvent):
                nodes += anchors.get(ev.anchor, 1)
                if nodes > MAX_NODES:
                    raise _Stop(Problem(ptr or "/", f"YAML aliases expand the document past "
                                        f"{MAX_NODES:,} nodes: write the values out instead",
                                        file, "syntax"))
                if is_key:
                    top[2], top[3] = False, "?"
                else:
                    _after_value(stack)
                continue
            nodes += 1
            if nodes > MAX_NODES:
                raise _Stop(Problem("/", f"the document has more than {MAX_NODES:,} nodes",
                                    file, "syntax"))
            tag = getattr(ev, "tag", None)
            if tag and tag != "!" and tag not in _PLAIN_TAGS:
                fail(ptr, f"the YAML tag {tag.replace('tag:yaml.org,2002:', '!!')} is not a "
                          "plain JSON type (string, number, boolean, null, list, mapping): "
                          "remove it, or quote the value")
            if isinstance(ev, yaml.ScalarEvent):
                if is_key:
                    top[2], top[3] = False, ev.value
                    if ev.value in top[4]:
                        fail(f"{top[1]}/{_esc(ev.value)}", f"the key {ev.value!r} is repeated "
                                 "in this mapping (only one would be kept): remove or rename it")
                    top[4].add(ev.value)
                else:
                    if ev.anchor:
                        anchors[ev.anchor] = 1
                    _after_value(stack)
                continue
            # a collection starts
            if is_key:
                fail(ptr, "a list or mapping used as a mapping key: keys must be strings")
                top[2], top[3] = False, "?"
                child_ptr = ptr + "/?"
            else:
                child_ptr = ptr
            if len(stack) >= MAX_DEPTH:
                raise _Stop(Problem(ptr[:60] + "..." if len(ptr) > 60 else ptr or "/",
                                    f"nested more than {MAX_DEPTH} levels deep: "
                                    "a PAG needs only a few", file, "syntax"))
            if ev.anchor:
                open_anchors.append((ev.anchor, len(stack) + 1, nodes))
            if isinstance(ev, yaml.MappingStartEvent):
                stack.append(["map", child_ptr, True, None, set()])
            else:
                stack.append(["seq", child_ptr, -1, None, None])
            if len(problems) > 50:
                break
    except _Stop as e:
        problems.append(e.problem)
    except yaml.YAMLError:
        return  # the real loader reports syntax errors with their position
    finally:
        loader.dispose()
    if problems:
        raise SchemaError(problems)


class _Stop(Exception):
    def __init__(self, problem: Problem) -> None:
        super().__init__(str(problem))
        self.problem = problem


def _after_value(stack: list[list[Any]]) -> None:
    """A value (scalar, alias or whole collection) ended: a mapping expects its next key."""
    if stack and stack[-1][0] == "map":
        stack[-1][2] = True


def read_document(path: str | Path) -> dict[str, Any]:
    """Read a JSON or YAML file into a dict, without validating it.

    Raises
    ------
    InputError
        The file is missing, not a regular file (a folder, FIFO or device: never read), too
        large or unreadable (kind ``io``), or is not well-formed JSON/YAML within the bounds of
        :func:`loads_document` (:class:`SchemaError`, kind ``syntax``).
    """
    path = Path(path)
    kind = _kind(path)
    text = read_input_text(path)
    return loads_document(text, kind=kind, file=str(path))


def load_pag(path: str | Path, *, vocabulary: Vocabulary | None = None) -> PAG:
    """Read, validate and build a PAG.

    Parameters
    ----------
    path : str or Path
        A ``.json``, ``.yaml`` or ``.yml`` file.
    vocabulary : Vocabulary, optional
        Checks category names and part labels (``parse3d.assets.registry.vocabulary()``).

    Raises
    ------
    InputError
        With every problem of the file (the most specific subclass they share).
    """
    data = read_document(path)
    validate_data(data, file=str(path), vocabulary=vocabulary, raise_errors=True)
    return PAG.from_dict(data)


def save_pag(pag: PAG | dict[str, Any], path: str | Path) -> Path:
    """Write a PAG (or a ``pag/1`` dict) as JSON or YAML, by the extension of ``path``.

    JSON is written with one object or relation per line. Returns the path.
    """
    path = Path(path)
    kind = _kind(path)
    data = pag.to_dict() if isinstance(pag, PAG) else pag
    if kind == "json":
        text = dumps_pag(data)
    else:
        yaml, _, _Dumper = _yaml()
        text = yaml.dump(data, Dumper=_Dumper, sort_keys=False, allow_unicode=True,
                         default_flow_style=None, width=100)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def dumps_pag(data: dict[str, Any]) -> str:
    """JSON text of a ``pag/1`` document: readable, one object or relation per line."""
    _check_finite(data)

    def one(v: Any) -> str:
        return json.dumps(v, ensure_ascii=False, separators=(", ", ": "))

    lines = ["{"]
    keys = list(data)
    for n, key in enumerate(keys):
        value = data[key]
        end = "," if n < len(keys) - 1 else ""
        if key in ("objects", "relations") and isinstance(value, list) and value:
            lines.append(f"  {one(key)}: [")
            lines += [f"    {one(v)}{',' if k < len(value) - 1 else ''}"
                      for k, v in enumerate(value)]
            lines.append(f"  ]{end}")
        elif key == "meta" and isinstance(value, dict):
            body = json.dumps(value, ensure_ascii=False, indent=2).replace("\n", "\n  ")
            lines.append(f"  {one(key)}: {body}{end}")
        else:
            lines.append(f"  {one(key)}: {one(value)}{end}")
    lines.append("}")
    return "\n".join(lines) + "\n"


def _check_finite(v: Any) -> None:
    if isinstance(v, float) and not math.isfinite(v):
        raise InputError(Problem("", f"cannot write the non-finite number {v} to JSON",
                                 None, "parameter"))
    if isinstance(v, dict):
        for x in v.values():
            _check_finite(x)
    elif isinstance(v, list):
        for x in v:
            _check_finite(x)
