"""Reading and writing ``pag/1`` files (JSON canonical, YAML accepted).

:func:`load_pag` reads, validates (schema and meaning, every problem at once) and builds a
:class:`~parse3d.pag.model.PAG`; :func:`save_pag` writes one back so that
``load_pag(save_pag(p, path)) == p``. The file type follows the extension: ``.json``, or
``.yaml`` / ``.yml``.

YAML is read with the YAML 1.2 core rules for scalars: only ``true``/``false`` are booleans
(so ``relation: ON`` stays the string ``"ON"``) and dates stay strings.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from typing import Any

import yaml

from ..errors import InputError, Problem, SchemaError
from .model import PAG
from .validate import Vocabulary, validate_data

__all__ = ["load_pag", "save_pag", "read_document", "dumps_pag", "loads_document"]

_JSON_EXT = (".json",)
_YAML_EXT = (".yaml", ".yml")


_SafeLoader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
_SafeDumper = getattr(yaml, "CSafeDumper", yaml.SafeDumper)


class _Loader(_SafeLoader):
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


class _Dumper(_SafeDumper):
    """Safe YAML dumper that keeps key order."""


def _kind(path: Path) -> str:
    ext = path.suffix.lower()
    if ext in _JSON_EXT:
        return "json"
    if ext in _YAML_EXT:
        return "yaml"
    raise InputError(Problem("", f"unknown file type {path.suffix or '(none)'!r}: use .json, "
                             ".yaml or .yml", str(path), "io"))


def loads_document(text: str, *, kind: str, file: str | None = None) -> Any:
    """Parse JSON or YAML text; malformed text raises :class:`SchemaError` with line/column.

    Parameters
    ----------
    text : str
    kind : {"json", "yaml"}
    file : str, optional
        Named in the error.
    """
    if kind == "json":
        try:
            return json.loads(text, parse_constant=_reject_constant)
        except json.JSONDecodeError as e:
            raise SchemaError(Problem("", f"invalid JSON at line {e.lineno}, column {e.colno}: "
                                      f"{e.msg}", file, "syntax")) from None
        except ValueError as e:
            raise SchemaError(Problem("", f"invalid JSON: {e}", file, "syntax")) from None
    try:
        return yaml.load(text, Loader=_Loader)  # noqa: S506 - a SafeLoader subclass
    except yaml.YAMLError as e:
        mark = getattr(e, "problem_mark", None)
        where = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        what = getattr(e, "problem", None) or str(e)
        raise SchemaError(Problem("", f"invalid YAML{where}: {what}", file, "syntax")) from None


def _reject_constant(name: str) -> Any:
    raise ValueError(f"{name} is not a number a PAG may contain")


def read_document(path: str | Path) -> dict[str, Any]:
    """Read a JSON or YAML file into a dict, without validating it.

    Raises
    ------
    InputError
        The file is missing or unreadable (kind ``io``), or is not well-formed JSON/YAML
        (:class:`SchemaError`, kind ``syntax``, with the line and column).
    """
    path = Path(path)
    kind = _kind(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(Problem("", "no such file", str(path), "io")) from None
    except (OSError, UnicodeDecodeError) as e:
        raise InputError(Problem("", f"cannot read the file: {e}", str(path), "io")) from None
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
