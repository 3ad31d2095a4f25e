"""Committing finished scenes durably and recovering them after an interruption."""

from __future__ import annotations

import json
import os
import shutil
import tempfile
import time
from pathlib import Path
from typing import Any

from ..errors import InputError, Problem
from ..scene.io import atomic_write_text
from .build_config import _IDENTITY, BuildConfig
from .manifest import read_manifest
from .planning import scene_folder
from .task import SceneOutcome


def _check_config(out: Path, config: BuildConfig) -> None:
    f = out / "dataset.json"
    if not f.exists():
        return
    try:
        old = BuildConfig.from_dict(json.loads(f.read_text()))
    except (json.JSONDecodeError, KeyError, TypeError, ValueError) as e:
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
    path.chmod(0o644)


def _recover(out: Path, scenes: int) -> dict[int, dict[str, Any]]:
    """Finished scenes of a previous run: the manifest plus every durable per-scene record.

    Removes what an interrupted run left half-done (temporary folders, scene folders without
    a record).
    """
    for p in out.glob(".tmp-*"):
        shutil.rmtree(p, ignore_errors=True)
    rows: dict[int, dict[str, Any]] = {int(r["index"]): r for r in read_manifest(
        out / "manifest.parquet")}
    scenes_dir = out / "scenes"
    if scenes_dir.is_dir():
        for d in sorted(scenes_dir.iterdir()):
            rec = d / "record.json"
            if not rec.exists():
                shutil.rmtree(d, ignore_errors=True)
                continue
            r = json.loads(rec.read_text())
            rows.setdefault(int(r["index"]), r)
    fail_dir = out / "failures"
    if fail_dir.is_dir():
        for f in sorted(fail_dir.glob("*.json")):
            r = json.loads(f.read_text())["record"]
            rows.setdefault(int(r["index"]), r)
    # rows of ok scenes whose folder is gone are not finished any more
    return {i: r for i, r in rows.items()
            if r["status"] != "ok" or (scenes_dir / scene_folder(i) / "record.json").exists()}


def _commit(out: Path, outcome: SceneOutcome) -> None:
    """Write a finished scene durably: its folder by rename, or its failure record."""
    rec = outcome.record
    name = scene_folder(rec["index"])
    if rec["status"] == "ok":
        t = time.perf_counter()
        tmp = Path(tempfile.mkdtemp(prefix=f".tmp-{name}-", dir=out))
        for fname, data in outcome.files.items():
            (tmp / fname).write_bytes(data)
        final = out / "scenes" / name
        if final.exists():  # a stale folder of a scene being rebuilt (--retry-failed)
            shutil.rmtree(final)
        rec["t_write"] = round(rec["t_write"] + time.perf_counter() - t, 6)
        (tmp / "record.json").write_text(json.dumps(rec, indent=1) + "\n")
        os.chmod(tmp, 0o755)
        os.rename(tmp, final)
        stale = out / "failures" / f"{name}.json"
        if stale.exists():
            stale.unlink()
    else:
        _write_json(out / "failures" / f"{name}.json",
                    {"record": rec, "traceback": outcome.error})
