"""The bundled templates, validated once per change of what they depend on.

Loading every bundled template validates it in full (schema, meaning, the maximal expansion
against the asset vocabulary): about 3 s of CPU, at the start of every dataset build, and
it imports every asset generator for the vocabulary. The outcome only changes when a
template or motif file, the code that validates them or the asset vocabulary changes, so a
snapshot of the validated documents is kept beside the asset cache,
``$PARSE3D_CACHE/templates.json``, keyed by

- the content of every template and motif file (path and bytes),
- the package version and the size and modification time of every source file of
  ``parse3d`` (validation, the vocabulary's generators),
- the user library's folders and ``category.json`` files (``parse3d assets add``).

A missing, stale or damaged snapshot is ignored and the templates are validated as before;
only a load of every template without a problem writes one. Documents that JSON cannot give
back exactly (a YAML date, a non-string key) are not snapshotted. A cache folder that
cannot be written only costs the slow path each time.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
from pathlib import Path
from typing import Any

from .._files import hash_library_stats, hash_tree_stats
from .template_model import Motif, Template

__all__ = ["SNAPSHOT_FORMAT", "SNAPSHOT_NAME", "snapshot_key", "read_snapshot", "write_snapshot"]

SNAPSHOT_FORMAT = "parse3d-templates/1"
SNAPSHOT_NAME = "templates.json"


def cache_root() -> Path | None:
    """The cache folder, or None when ``$PARSE3D_CACHE`` is unusable (nothing is cached)."""
    from ..assets.library import cache_dir
    from ..errors import InputError

    try:
        return cache_dir()
    except InputError:
        return None


def snapshot_key(templates: Path, motifs: Path, root: Path) -> str:
    """A digest of everything loading the templates of ``templates`` (``<room>/<name>.yaml``)
    with the motifs of ``motifs`` depends on.

    Parameters
    ----------
    templates, motifs : Path
        The template and motif folders.
    root : Path
        The cache folder (its ``library`` sub-folder holds the user's categories).

    Returns
    -------
    str
        Hex digest (see the module's description).
    """
    package = Path(__file__).resolve().parents[1]  # its __init__ (the version) is among the sources
    h = hashlib.sha256(f"{SNAPSHOT_FORMAT}\n".encode())
    for folder, pattern in ((templates, "*/*.yaml"), (motifs, "*.yaml")):
        h.update(f"{folder}\n".encode())
        for p in sorted(folder.glob(pattern)):
            try:
                data = p.read_bytes()
            except OSError:
                data = b"-"
            h.update(f"{p.relative_to(folder)}:{len(data)}\n".encode())
            h.update(hashlib.sha256(data).digest())
    hash_tree_stats(h, package, skip=("__pycache__",))
    hash_library_stats(h, root)
    return h.hexdigest()


def _motif_doc(m: Motif) -> dict[str, Any]:
    return {"name": m.name, "description": m.description, "params": m.params, "data": m.data,
            "file": m.file}


def _motif(d: dict[str, Any]) -> Motif:
    return Motif(d["name"], d["description"], d["params"], d["data"], d["file"])


def read_snapshot(path: Path, key: str) -> list[Template] | None:
    """The templates of a current snapshot at ``path``; None when it is missing, stale or
    damaged."""
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(doc, dict) or doc.get("format") != SNAPSHOT_FORMAT or doc.get("key") != key:
        return None
    try:
        motifs = {name: _motif(d) for name, d in doc["motifs"].items()}
        return [Template(t["name"], t["room_type"], t["description"], t["data"],
                         {n: motifs[n] for n in t["motifs"]}, t["file"])
                for t in doc["templates"]]
    except (KeyError, TypeError, AttributeError):
        return None


def write_snapshot(path: Path, key: str, templates: list[Template]) -> bool:
    """Write the snapshot of ``templates`` (atomically); False when it was not written (the
    documents do not survive JSON unchanged, or the folder cannot be written)."""
    motifs: dict[str, Motif] = {}
    for t in templates:
        motifs.update(t.motifs)
    doc = {"format": SNAPSHOT_FORMAT, "key": key,
           "motifs": {n: _motif_doc(m) for n, m in sorted(motifs.items())},
           "templates": [{"name": t.name, "room_type": t.room_type,
                          "description": t.description, "data": t.data,
                          "motifs": list(t.motifs), "file": t.file} for t in templates]}
    try:
        text = json.dumps(doc, separators=(",", ":"), allow_nan=False)
    except (TypeError, ValueError):
        return False
    # repr tells 1 from 1.0, tuples from lists and int keys from str keys: what JSON would
    # change is not written
    if repr(json.loads(text)) != repr(doc):
        return False
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp.write_text(text, encoding="utf-8")
        os.replace(tmp, path)
    except OSError:
        with contextlib.suppress(OSError):
            tmp.unlink()
        return False
    return True
