"""The options each export in a folder was made with (``exports.json``).

When a scene changes (``parse3d settle``, a re-solve) the exports in its folder are rewritten
by :func:`parse3d.export.export_scene`; this small sidecar lets that refresh reuse the options
the user chose (``--no-ceiling``, ``--open RATIO``, ``--solved``) instead of the defaults.
It lives beside the exports rather than in ``scene.json`` because writing it must not make
the scene newer than its exports (staleness is judged by modification times), and because an
export folder given with ``--out`` holds no ``scene.json``.

Format (JSON)::

    {"version": 1,
     "formats": {"glb": {"settled": null, "ceiling": false, "open_ratio": null,
                         "friction": {"wood": 0.5, ...}},
                 "mjcf": {...}}}

``settled`` null means "the scene's own state" (settled once the scene is settled); a
``friction`` of null leaves the simulators' defaults.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

from ..errors import InputError, Problem
from ..scene.io import atomic_write_text
from .walk import ExportOptions

__all__ = ["OPTIONS_FILE", "options_to_dict", "options_from_dict", "read_options",
           "write_options"]

#: File name of the record in an export folder.
OPTIONS_FILE = "exports.json"
_VERSION = 1


def options_to_dict(options: ExportOptions) -> dict[str, Any]:
    """The JSON form of ``options``."""
    return {"settled": options.settled, "ceiling": bool(options.ceiling),
            "open_ratio": None if options.open_ratio is None else float(options.open_ratio),
            "friction": None if options.friction is None
            else {str(k): float(v) for k, v in sorted(options.friction.items())}}


def _bad(path: Path, where: str, what: str) -> InputError:
    return InputError(Problem("", f"{what} — fix it, or delete {OPTIONS_FILE} to refresh "
                                  "with the default export options", str(path), where))


def options_from_dict(d: Any, path: Path, where: str) -> ExportOptions:
    """Read one format's entry; ``path`` and ``where`` name it in errors.

    Raises
    ------
    InputError
        For a value of the wrong type or out of range.
    """
    if not isinstance(d, dict):
        raise _bad(path, where, "expected an object of export options")
    settled = d.get("settled")
    if settled is not None and not isinstance(settled, bool):
        raise _bad(path, f"{where}.settled", "expected true, false or null")
    ceiling = d.get("ceiling", True)
    if not isinstance(ceiling, bool):
        raise _bad(path, f"{where}.ceiling", "expected true or false")
    ratio = d.get("open_ratio")
    if ratio is not None and (isinstance(ratio, bool) or not isinstance(ratio, (int, float))
                              or not 0.0 <= ratio <= 1.0):
        raise _bad(path, f"{where}.open_ratio", "expected null or a number in 0..1")
    friction = d.get("friction")
    if friction is not None:
        if not isinstance(friction, dict) or not all(
                isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
                and v >= 0 for v in friction.values()):
            raise _bad(path, f"{where}.friction",
                       "expected null or an object of non-negative numbers")
        friction = {str(k): float(v) for k, v in friction.items()}
    return ExportOptions(settled=settled, ceiling=ceiling,
                         open_ratio=None if ratio is None else float(ratio), friction=friction)


def read_options(folder: str | Path) -> dict[str, ExportOptions]:
    """The recorded options per format in ``folder`` (empty when there is no record).

    Raises
    ------
    InputError
        For a record that is not valid JSON or holds bad values (naming the place).
    """
    path = Path(folder) / OPTIONS_FILE
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        return {}
    except OSError as e:
        raise _bad(path, "file", f"cannot read it: {e.strerror}") from None
    try:
        data = json.loads(text)
    except json.JSONDecodeError as e:
        raise _bad(path, f"line {e.lineno}", f"not valid JSON ({e.msg})") from None
    if not isinstance(data, dict) or not isinstance(data.get("formats", {}), dict):
        raise _bad(path, "formats", "expected {\"version\": 1, \"formats\": {...}}")
    return {str(k): options_from_dict(v, path, f"formats.{k}")
            for k, v in data.get("formats", {}).items()}


def write_options(folder: str | Path, options: dict[str, ExportOptions]) -> Path:
    """Record ``options`` (format -> options) in ``folder``, keeping the entries of other
    formats already recorded there; returns the record's path."""
    path = Path(folder) / OPTIONS_FILE
    try:
        merged = read_options(folder)
    except InputError:
        merged = {}  # a damaged record is replaced by what was just written
    merged.update(options)
    doc = {"version": _VERSION,
           "formats": {k: options_to_dict(v) for k, v in sorted(merged.items())}}
    atomic_write_text(path, json.dumps(doc, indent=1) + "\n")
    return path
