"""Committing finished scenes durably and recovering them after an interruption."""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import time
from pathlib import Path
from typing import Any

from .._files import read_json
from ..errors import InputError, Problem
from ..scene.io import atomic_write_text
from .build_config import _IDENTITY, BuildConfig
from .manifest import COMMITTED, STATUSES, read_manifest
from .planning import scene_folder
from .task import SceneOutcome

#: The build's pid-file lock and its journal of temporary folders, in the dataset folder.
LOCK_NAME = ".parse3d-build.lock"
JOURNAL_NAME = ".parse3d-journal"
_TMP_RE = re.compile(r"\.tmp-\d{5,}-\d+-\d+")
_SCENE_RE = re.compile(r"\d{5,}")
_SAFE_NAME = re.compile(r"[A-Za-z0-9_.-]{1,100}")


def _check_config(out: Path, config: BuildConfig) -> None:
    f = out / "dataset.json"
    if not f.exists():
        return
    try:
        old = BuildConfig.from_dict(read_json(f, what="build configuration"))
    except (KeyError, TypeError, ValueError, AttributeError) as e:
        raise InputError(Problem("", f"cannot read the build configuration ({e}); use another "
                                     "--out folder", str(f), "io")) from None
    diffs = [k for k in _IDENTITY if getattr(old, k) != getattr(config, k)]
    if diffs:
        what = ", ".join(f"{k} {getattr(old, k)!r} (now {getattr(config, k)!r})" for k in diffs)
        raise InputError(Problem("", f"this folder holds a dataset built with other settings: "
                                     f"{what}; resume with the same settings or use another "
                                     f"--out folder", str(f), "parameter"))


def _write_json(path: Path, data: Any) -> None:
    atomic_write_text(path, json.dumps(data, indent=1) + "\n")


#: Files of a dataset folder the builder itself writes at the top level.
OWN_NAMES = ("dataset.json", "manifest.parquet", "scenes", "failures", LOCK_NAME, JOURNAL_NAME)


def check_out_folder(out: Path) -> None:
    """Refuse an ``--out`` that is a file, or a non-empty folder that is not a dataset.

    Nothing is created or changed; a folder holding ``dataset.json`` is one of ours (its
    settings are checked later by :func:`_check_config`).

    Raises
    ------
    InputError
    """
    if out.exists() and not out.is_dir():
        raise InputError(Problem("", "--out names a file, not a folder: give a new or empty "
                                     "folder (or an existing dataset to resume)", str(out), "io"))
    if not out.is_dir() or (out / "dataset.json").is_file():
        return
    if (out / LOCK_NAME).exists():
        return  # a build is just starting here: the lock decides
    try:
        entries = sorted(p.name for p in out.iterdir())
    except OSError as e:
        raise InputError(Problem("", f"cannot read the --out folder: {e.strerror}", str(out),
                                 "io")) from None
    if entries:
        shown = ", ".join(entries[:3]) + (", ..." if len(entries) > 3 else "")
        raise InputError(Problem("", f"this folder is not empty ({shown}) and holds no parse3d "
                                     "dataset (no dataset.json): give a new or empty folder; "
                                     "nothing was changed", str(out), "io"))


def _journal(out: Path, name: str) -> None:
    """Record a temporary folder name before anything is written into it."""
    with open(out / JOURNAL_NAME, "a", encoding="utf-8") as f:
        f.write(name + "\n")
        f.flush()
        os.fsync(f.fileno())


def _clean_journal(out: Path) -> None:
    """Remove the temporary folders an interrupted run recorded (and nothing else)."""
    j = out / JOURNAL_NAME
    if not j.is_file():
        return
    for line in j.read_text(encoding="utf-8", errors="replace").splitlines():
        name = line.strip()
        if _TMP_RE.fullmatch(name):
            shutil.rmtree(out / name, ignore_errors=True)
    j.unlink()


def file_digest(data: bytes) -> list:
    """``[size, sha256 hex]`` of a file's bytes, as recorded in ``record.json``."""
    return [len(data), hashlib.sha256(data).hexdigest()]


def _scene_intact(d: Path, rec: dict[str, Any]) -> bool:
    """Whether every file recorded at commit still has its size and hash."""
    files = rec.get("files")
    if not isinstance(files, dict):
        return True  # a record written before files were recorded: nothing to compare
    for name, want in files.items():
        f = d / name
        if not _SAFE_NAME.fullmatch(str(name)) or not f.is_file():
            return False
        if not (isinstance(want, list) and len(want) == 2):
            return False
        if f.stat().st_size != want[0] or file_digest(f.read_bytes()) != want:
            return False
    return True


def _read_record(f: Path, *, key: str | None = None) -> dict[str, Any] | None:
    """A per-scene record, or None when the file is damaged."""
    try:
        r = json.loads(f.read_text(encoding="utf-8"))
        if key is not None:
            r = r[key]
        int(r["index"])
        if r.get("status") not in STATUSES:
            return None
        return r
    except (OSError, ValueError, KeyError, TypeError):
        return None


def _recover(out: Path, scenes: int, *, warn=None) -> dict[int, dict[str, Any]]:
    """Finished scenes of a previous run, from the per-scene records (the manifest is an index).

    Removes only what this builder wrote and an interrupted run left half-done: the temporary
    folders named in its journal, and scene folders whose record or files are damaged (they
    are built again). A damaged ``manifest.parquet`` or ``failures/*.json`` is rebuilt from
    the records (those scenes run again). Folders the builder did not write are refused, never
    removed.

    Raises
    ------
    InputError
        A folder under ``scenes/`` that is not a committed scene (no ``record.json``).
    """
    warn = warn or (lambda msg: None)
    _clean_journal(out)
    rows: dict[int, dict[str, Any]] = {}
    try:
        manifest = read_manifest(out / "manifest.parquet")
    except Exception as e:  # noqa: BLE001 - any damage to the index: rebuild it from records
        warn(f"{out / 'manifest.parquet'}: damaged ({type(e).__name__}); rebuilt from the "
             "per-scene records")
        manifest = []
    manifest_rows = {int(r["index"]): r for r in manifest if r.get("status") not in COMMITTED}
    scenes_dir = out / "scenes"
    foreign = []
    if scenes_dir.is_dir():
        for d in sorted(scenes_dir.iterdir()):
            rec = d / "record.json"
            if not (d.is_dir() and _SCENE_RE.fullmatch(d.name) and rec.exists()):
                foreign.append(d)
                continue
            r = _read_record(rec)
            if r is None or scene_folder(r["index"]) != d.name or not _scene_intact(d, r):
                warn(f"{d}: damaged (record or files changed since it was written); "
                     "building it again")
                shutil.rmtree(d)
                continue
            rows[int(r["index"])] = r
    if foreign:
        raise InputError(Problem("", f"{foreign[0].name!r} under scenes/ was not written by "
                                     "the dataset builder (no record.json): move it out of the "
                                     "dataset folder; nothing was changed", str(foreign[0]),
                                 "io"))
    fail_dir = out / "failures"
    if fail_dir.is_dir():
        for f in sorted(fail_dir.glob("*.json")):
            r = _read_record(f, key="record")
            if r is None:
                warn(f"{f}: damaged; that scene runs again")
                continue
            if r["status"] not in COMMITTED:
                rows.setdefault(int(r["index"]), r)
    # failed rows only known from the manifest (their failures/ file is gone) stay finished
    for i, r in manifest_rows.items():
        rows.setdefault(i, r)
    return rows


def _commit(out: Path, outcome: SceneOutcome) -> None:
    """Write a finished scene durably: its folder by rename, or its failure record."""
    rec = outcome.record
    name = scene_folder(rec["index"])
    if rec["status"] in COMMITTED:
        t = time.perf_counter()
        tmp_name = f".tmp-{name}-{os.getpid()}-{time.monotonic_ns()}"
        _journal(out, tmp_name)
        tmp = out / tmp_name
        tmp.mkdir()
        rec["files"] = {}
        for fname, data in outcome.files.items():
            (tmp / fname).parent.mkdir(parents=True, exist_ok=True)  # meshes/, urdf/
            (tmp / fname).write_bytes(data)
            rec["files"][fname] = file_digest(data)
        final = out / "scenes" / name
        if (final / "record.json").exists():  # our stale folder of a rebuilt scene
            shutil.rmtree(final)
        rec["t_write"] = round(rec["t_write"] + time.perf_counter() - t, 6)
        (tmp / "record.json").write_text(json.dumps(rec, indent=1) + "\n")
        os.rename(tmp, final)
        stale = out / "failures" / f"{name}.json"
        if stale.exists():
            stale.unlink()
    else:
        _write_json(out / "failures" / f"{name}.json",
                    {"record": rec, "traceback": outcome.error})
