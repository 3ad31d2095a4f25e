"""The dataset manifest: ``DIR/manifest.parquet``, one row per finished scene.

A *finished* scene is one the builder will not run again: it either committed its folder
``DIR/scenes/<index:05d>/`` (status ``ok``: every object placed and stable after settling and
repair; or ``incomplete``: some object failed or stayed unstable, the files are written and its
``scene.json`` says which and why) or was recorded as ``failed`` (the pipeline raised, or no
object could be placed) or ``timeout`` (it ran past the time limit). The manifest is an
index, rewritten atomically from the per-scene records: every committed scene folder holds its
own row as ``record.json``, every failed or timed-out scene has ``DIR/failures/<index:05d>.json``,
so an interrupted build loses nothing (see :func:`parse3d.datagen.build.build_dataset`).

Columns (:data:`COLUMNS`)
-------------------------
index : int32
    Scene index in ``[0, scenes)``.
scene : string or null
    Folder name under ``DIR/scenes/`` (``"00012"``); null for failed scenes.
room_type, template : string
    The room type and the template (or PAG file stem) the scene was drawn from.
seed : int64
    The scene seed given to the template expansion and the solver.
status : string
    ``ok``, ``incomplete``, ``failed`` or ``timeout``.
reason : string or null
    Why a scene failed or timed out (the exception, or the stage that ran out of time).
objects, placed, failed : int32
    Objects of the expanded PAG; placed and failed by the solver.
area : float64
    Floor area, m².
density : float64
    Placed objects per m² of floor.
contacts, object_contacts : int32 or null
    Edges of the part-level contact graph after settling; those between two objects (room
    shell contacts left out).
relations, relations_held : int32 or null
    PAG relations, and how many hold after settling (after solving when not settled).
repaired, unrepaired : int32 or null
    Objects re-placed after settling into a stable pose, and objects still unstable after the
    last repair round (they count as failed).
views : int32
    Rendered views besides ``preview.png``.
categories, assets : list of string
    Category and asset id of every placed object, in assembly order.
parts : list of int32
    Number of parts of every placed object, in the same order.
t_expand, t_solve, t_settle, t_contacts, t_render, t_write, t_total : float64
    Seconds per stage (``t_total``: the whole task, in the worker).
cpu_expand, cpu_solve, cpu_settle, cpu_contacts, cpu_render, cpu_write, cpu_total : float64
    CPU seconds of the worker process per stage (all its threads): unlike the wall-clock
    ``t_*`` they do not grow when other processes share the cores. Null in manifests written
    before they were recorded.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path
from typing import Any

from .._files import user_mode

__all__ = ["COLUMNS", "TIMING_COLUMNS", "STATUSES", "COMMITTED", "manifest_schema", "write_manifest",
           "read_manifest"]

STATUSES = ("ok", "incomplete", "failed", "timeout")
#: Statuses whose scene folder is written (``DIR/scenes/<index>/``).
COMMITTED = ("ok", "incomplete")
TIMING_COLUMNS = ("t_expand", "t_solve", "t_settle", "t_contacts", "t_render", "t_write",
                  "t_total", "cpu_expand", "cpu_solve", "cpu_settle", "cpu_contacts",
                  "cpu_render", "cpu_write", "cpu_total")


def _columns() -> list[tuple[str, str]]:
    base = [("index", "int32"), ("scene", "string"), ("room_type", "string"),
            ("template", "string"), ("seed", "int64"), ("status", "string"),
            ("reason", "string"), ("objects", "int32"), ("placed", "int32"),
            ("failed", "int32"), ("area", "float64"), ("density", "float64"),
            ("contacts", "int32"), ("object_contacts", "int32"), ("relations", "int32"),
            ("relations_held", "int32"), ("repaired", "int32"), ("unrepaired", "int32"),
            ("views", "int32"), ("categories", "list<string>"),
            ("assets", "list<string>"), ("parts", "list<int32>")]
    return base + [(t, "float64") for t in TIMING_COLUMNS]


#: (name, type) of every manifest column, in file order.
COLUMNS: tuple[tuple[str, str], ...] = tuple(_columns())


def manifest_schema():
    """The ``pyarrow.Schema`` of ``manifest.parquet``."""
    import pyarrow as pa

    types = {"int32": pa.int32(), "int64": pa.int64(), "float64": pa.float64(),
             "string": pa.string(), "list<string>": pa.list_(pa.string()),
             "list<int32>": pa.list_(pa.int32())}
    return pa.schema([pa.field(n, types[t]) for n, t in COLUMNS],
                     metadata={b"format": b"parse3d-manifest/1"})


def _row(record: dict[str, Any]) -> dict[str, Any]:
    row = {}
    for name, typ in COLUMNS:
        v = record.get(name)
        if v is None and typ.startswith("list"):
            v = []
        row[name] = v
    return row


def write_manifest(path: str | Path, records: list[dict[str, Any]]) -> Path:
    """Write ``records`` (sorted by index) to a Parquet file, atomically.

    The table goes to a temporary file in the same folder first and is renamed over ``path``,
    so a reader (or a build killed mid-write) never sees a half-written manifest.
    """
    import pyarrow as pa
    import pyarrow.parquet as pq

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    rows = [_row(r) for r in sorted(records, key=lambda r: int(r["index"]))]
    schema = manifest_schema()
    table = pa.Table.from_pylist(rows, schema=schema)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(fd)
    try:
        pq.write_table(table, tmp)
        os.chmod(tmp, user_mode())
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return path


def read_manifest(path: str | Path) -> list[dict[str, Any]]:
    """The rows of a manifest as dicts, sorted by index; ``[]`` when the file does not exist."""
    import pyarrow.parquet as pq

    path = Path(path)
    if not path.exists():
        return []
    rows = pq.read_table(path).to_pylist()
    return sorted(rows, key=lambda r: int(r["index"]))
