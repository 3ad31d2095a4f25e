"""The dataset builder: many scenes from PAG templates, resumable, on processes or Ray.

For every scene index ``i`` of a build the builder picks a room type and a template
deterministically from ``(dataset seed, i)`` (:func:`plan_scene`), then runs the whole
per-scene pipeline in a worker (:func:`build_scene`): expand the template into a PAG, solve,
settle in SAPIEN, extract the part-level contact graph, render ``preview.png`` and ``views``
sampled views, and serialise the files. The driver commits each finished scene atomically
(a temporary folder in ``DIR`` renamed to ``DIR/scenes/<index:05d>/``) and keeps
``DIR/manifest.parquet`` (:mod:`parse3d.datagen.manifest`) up to date, so a build killed at any
moment resumes where it stopped when run again with the same settings.

Folder layout
-------------
``DIR/dataset.json``
    The build configuration (:class:`BuildConfig`), format ``parse3d-dataset/1``.
``DIR/manifest.parquet``
    One row per finished scene with its statistics.
``DIR/scenes/<index:05d>/``
    ``scene.json``, ``scene.glb``, ``contacts.json``, ``preview.png``, the views
    (``rgb_k.png``, ``depth_k.png``, ``instance_k.png``, ``part_k.png``, ``views.json``) and
    ``record.json`` (the scene's manifest row).
``DIR/failures/<index:05d>.json``
    The row and the traceback of every scene that failed or timed out.

Examples
--------
>>> from parse3d.datagen.build import BuildConfig, build_dataset    # doctest: +SKIP
>>> cfg = BuildConfig(scenes=20, seed=0, rooms=("bedroom", "kitchen"), views=2)
>>> report = build_dataset(cfg, "out/mini", workers=2)              # doctest: +SKIP
>>> report.ok, report.failed                                        # doctest: +SKIP
(20, 0)
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from .._deps import require
from .._files import FolderLock, check_output_dir
from ..errors import InputError, Problem
from .build_config import DATASET_FORMAT, DEFAULT_MAX_TASKS, BuildConfig
from .commit import (
    LOCK_NAME,
    _check_config,
    _clean_journal,
    _commit,
    _recover,
    _write_json,
    check_out_folder,
)
from .executors import make_executor, start_context
from .manifest import COMMITTED, write_manifest
from .planning import ScenePlan, plan_scene, scene_folder
from .sources import (
    PagFileSource,
    SceneSource,
    TemplateSource,
    default_source_paths,
    make_source,
    resolve_pag_paths,
    select_rooms,
)
from .task import SceneOutcome, build_scene
from .template_model import ROOM_TYPES

#: Most worker processes (or Ray tasks in flight) a build may ask for.
MAX_WORKERS = 512

__all__ = [
    "ROOM_TYPES",
    "DATASET_FORMAT",
    "DEFAULT_MAX_TASKS",
    "BuildConfig",
    "SceneSource",
    "TemplateSource",
    "PagFileSource",
    "make_source",
    "default_source_paths",
    "resolve_pag_paths",
    "select_rooms",
    "ScenePlan",
    "plan_scene",
    "SceneOutcome",
    "build_scene",
    "BuildEvent",
    "BuildReport",
    "build_dataset",
    "scene_folder",
]


@dataclass(frozen=True)
class BuildEvent:
    """One finished scene, as reported to a progress callback.

    ``done`` counts finished scenes of this build including those found on resume; ``total``
    is ``config.scenes``.
    """

    record: dict[str, Any]
    done: int
    total: int
    ok: int
    failed: int


@dataclass
class BuildReport:
    """The result of :func:`build_dataset`.

    Attributes
    ----------
    out : Path
    total, ok, failed, timeout, incomplete : int
        Scenes of the dataset by status (all of them, not only this run's).
    resumed : int
        Scenes found finished when the build started.
    built : int
        Scenes finished by this run.
    wall : float
        Seconds this run took.
    """

    out: Path
    total: int
    ok: int
    failed: int
    timeout: int
    resumed: int
    built: int
    wall: float
    incomplete: int = 0

    @property
    def scenes_per_hour(self) -> float:
        return 3600.0 * self.built / self.wall if self.wall > 0 else 0.0


def build_dataset(config: BuildConfig, out: str | Path, *, executor: str = "local",
                  workers: int = 2, ray_address: str | None = None,
                  retry_failed: bool = False, max_tasks: int = DEFAULT_MAX_TASKS, flush_every: float = 2.0,
                  progress: Callable[[BuildEvent], None] | None = None,
                  warn: Callable[[str], None] | None = None) -> BuildReport:
    """Build (or resume) a dataset of ``config.scenes`` scenes in ``out``.

    Parameters
    ----------
    config : BuildConfig
    out : path
        The dataset folder. When it already holds a build with the same settings, finished
        scenes are kept and only the missing ones run (no duplicates, no holes).
    executor : {"local", "ray"}
        A pool of worker processes on this machine, or tasks on a Ray cluster.
    workers : int
        Worker processes (local), or scenes in flight at once (Ray).
    ray_address : str or None
        Ray cluster address; None starts (or reuses) a local Ray instance.
    retry_failed : bool
        Run the scenes recorded as ``failed`` or ``timeout`` again.
    max_tasks : int
        Scenes a local worker process builds before it is replaced (bounds memory).
    flush_every : float
        Seconds between manifest rewrites, at least (finished scenes are durable at once
        through their own records; the manifest is always rewritten at the end). On a long
        build the interval grows to 20 times the CPU time of one rewrite.
    progress : callable or None
        Called with a :class:`BuildEvent` for every finished scene.
    warn : callable or None
        Called with a one-line message for every damaged file found on resume (the scene is
        built again; a damaged manifest is rebuilt from the per-scene records).

    Raises
    ------
    InputError
        Unknown room types or executor, an empty source, a folder built with other settings,
        a non-empty folder that is not a dataset (nothing is touched), or a folder another
        build is writing (its lock is held by a live process).
    DependencyError
        A package the build needs is not installed (checked before the disk is touched).
    """
    out = Path(out)
    # everything that can refuse the build does so before the disk is touched
    require("pyarrow", feature="a dataset build (manifest.parquet)")
    if config.settle:
        require("sapien", feature="settling (drop --no-settle to skip it)")
    require("moderngl", feature="rendering previews")
    if executor == "ray":
        require("ray", feature="the Ray executor")
    if executor not in ("local", "ray"):
        raise InputError(Problem("", f"unknown executor {executor!r} (use local or ray)",
                                 "--executor", "parameter"))
    if not 1 <= int(workers) <= MAX_WORKERS:
        raise InputError(Problem("", f"--workers must be in 1..{MAX_WORKERS}, got {workers}",
                                 "--workers", "parameter"))
    if not 1 <= int(max_tasks) <= 1_000_000:
        raise InputError(Problem("", f"--max-tasks must be in 1..1000000, got {max_tasks}",
                                 "--max-tasks", "parameter"))
    check_out_folder(out)
    if executor == "local":  # the workers' fork server imports their modules meanwhile
        start_context()
    source = make_source(config)
    rooms = select_rooms(config, source)
    config_run = replace(config, rooms=tuple(rooms))
    _check_config(out, config_run)
    check_output_dir(out)
    with FolderLock(out, name=LOCK_NAME, what="this dataset folder"):
        return _build_locked(config, config_run, out, source, executor=executor,
                             workers=workers, ray_address=ray_address,
                             retry_failed=retry_failed, max_tasks=max_tasks,
                             flush_every=flush_every, progress=progress, warn=warn)


def _build_locked(config: BuildConfig, config_run: BuildConfig, out: Path, source: SceneSource,
                  *, executor: str, workers: int, ray_address: str | None, retry_failed: bool,
                  max_tasks: int, flush_every: float,
                  progress: Callable[[BuildEvent], None] | None,
                  warn: Callable[[str], None] | None) -> BuildReport:
    """:func:`build_dataset` once the folder is checked and locked."""
    check_out_folder(out)  # again under the lock: nothing foreign slipped in meanwhile
    _check_config(out, config_run)
    cfg_file = out / "dataset.json"
    stored = json.loads(cfg_file.read_text()) if cfg_file.exists() else {}
    _write_json(cfg_file, {**config_run.to_dict(),
                           "scenes": max(int(stored.get("scenes", 0)), int(config.scenes)),
                           "rooms_requested": list(config.rooms)})

    rows = _recover(out, config.scenes, warn=warn)
    if retry_failed:
        rows = {i: r for i, r in rows.items() if r["status"] in COMMITTED}
    resumed = sum(1 for i in rows if i < config.scenes)
    todo = [i for i in range(config.scenes) if i not in rows]
    t0 = time.perf_counter()
    last_flush, flush_cost = t0, 0.0
    built = 0
    (out / "scenes").mkdir(exist_ok=True)

    def counts() -> tuple[int, int]:
        mine = [r for i, r in rows.items() if i < config.scenes]
        ok = sum(1 for r in mine if r["status"] == "ok")
        return ok, len(mine) - ok

    try:
        if todo:
            ex = make_executor(executor, workers=int(workers), address=ray_address,
                               max_tasks=max_tasks)
            for outcome in ex.run(config_run, todo, source=source):
                _commit(out, outcome)
                rows[int(outcome.record["index"])] = outcome.record
                built += 1
                if progress is not None:
                    ok, bad = counts()
                    progress(BuildEvent(outcome.record, ok + bad, config.scenes, ok, bad))
                if time.perf_counter() - last_flush >= max(flush_every, 20.0 * flush_cost):
                    # the whole table is rewritten: on a long build, less often (at most
                    # about 5% of the driver's time), so it does not take a worker's core
                    c = time.process_time()
                    write_manifest(out / "manifest.parquet", list(rows.values()))
                    flush_cost = time.process_time() - c
                    last_flush = time.perf_counter()
    finally:
        write_manifest(out / "manifest.parquet", list(rows.values()))
        _clean_journal(out)
    mine = [r for i, r in rows.items() if i < config.scenes]
    return BuildReport(out=out, total=len(mine),
                       ok=sum(1 for r in mine if r["status"] == "ok"),
                       failed=sum(1 for r in mine if r["status"] == "failed"),
                       incomplete=sum(1 for r in mine if r["status"] == "incomplete"),
                       timeout=sum(1 for r in mine if r["status"] == "timeout"),
                       resumed=resumed, built=built, wall=time.perf_counter() - t0)
