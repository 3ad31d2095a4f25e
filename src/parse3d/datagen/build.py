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
import os
import shutil
import signal
import tempfile
import threading
import time
import traceback
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError, Problem

__all__ = [
    "ROOM_TYPES",
    "DATASET_FORMAT",
    "BuildConfig",
    "SceneSource",
    "TemplateSource",
    "PagFileSource",
    "make_source",
    "ScenePlan",
    "plan_scene",
    "SceneOutcome",
    "build_scene",
    "BuildEvent",
    "BuildReport",
    "build_dataset",
    "scene_folder",
]

#: The 17 room types of PARSE-10K, in the paper's order.
ROOM_TYPES = ("bedroom", "living_room", "office", "study", "laundry", "storage", "dining_room",
              "bathroom", "tea_house", "game_room", "kitchen", "music_room", "bar", "dormitory",
              "meeting_room", "hotel", "grocery")

DATASET_FORMAT = "parse3d-dataset/1"

# Settings that change what a scene index produces: a folder built with other values of these
# cannot be resumed (workers, executor and the time limit may change between runs).
_IDENTITY = ("seed", "rooms", "views", "view_size", "settle", "source", "formats")


# --------------------------------------------------------------------------------------------
# configuration


@dataclass(frozen=True)
class BuildConfig:
    """What a dataset build produces (saved as ``DIR/dataset.json``).

    Attributes
    ----------
    scenes : int
        Number of scene indices, ``0 .. scenes-1``.
    seed : int
        Dataset seed; scene ``i`` depends on ``(seed, i)`` only.
    rooms : tuple of str
        Room types to cycle through, in order (empty: every room type the source has).
    views : int
        Sampled views per scene besides ``preview.png`` (0: the preview only).
    view_size : (int, int)
        Width and height of the preview and the views, pixels.
    settle : bool
        Settle in SAPIEN and extract the part-level contact graph.
    source : tuple of str
        ``()`` for the bundled PAG templates (:mod:`parse3d.datagen.templates`), or the PAG
        files to draw from (absolute paths; their room type is read from each file).
    time_limit : float or None
        Seconds one scene may take before it is recorded as ``timeout``.
    formats : tuple of str
        Export formats written into every scene folder (``parse3d.export.FORMATS`` names).
    """

    scenes: int
    seed: int = 0
    rooms: tuple[str, ...] = ()
    views: int = 0
    view_size: tuple[int, int] = (640, 480)
    settle: bool = True
    source: tuple[str, ...] = ()
    time_limit: float | None = 600.0
    formats: tuple[str, ...] = ("glb",)

    def __post_init__(self) -> None:
        from ..export import check_formats

        object.__setattr__(self, "formats", check_formats(self.formats, where="--formats"))
        if int(self.scenes) < 0:
            raise InputError(Problem("", f"--scenes must be >= 0, got {self.scenes}",
                                     "--scenes", "parameter"))
        if int(self.views) < 0:
            raise InputError(Problem("", f"--views must be >= 0, got {self.views}",
                                     "--views", "parameter"))
        if self.time_limit is not None and not float(self.time_limit) > 0:
            raise InputError(Problem("", f"--time-limit must be > 0 seconds, got "
                                         f"{self.time_limit}", "--time-limit", "parameter"))
        w, h = self.view_size
        if int(w) < 1 or int(h) < 1:
            raise InputError(Problem("", f"view size must be positive, got {w}x{h}",
                                     "--size", "parameter"))

    def to_dict(self) -> dict[str, Any]:
        return {"format": DATASET_FORMAT, "scenes": int(self.scenes), "seed": int(self.seed),
                "rooms": list(self.rooms), "views": int(self.views),
                "view_size": [int(v) for v in self.view_size], "settle": bool(self.settle),
                "source": ({"kind": "templates"} if not self.source
                           else {"kind": "pags", "paths": list(self.source)}),
                "time_limit": None if self.time_limit is None else float(self.time_limit),
                "formats": list(self.formats)}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> BuildConfig:
        src = d.get("source") or {"kind": "templates"}
        return cls(scenes=int(d["scenes"]), seed=int(d.get("seed", 0)),
                   rooms=tuple(d.get("rooms", ())), views=int(d.get("views", 0)),
                   view_size=tuple(d.get("view_size", (640, 480))),
                   settle=bool(d.get("settle", True)),
                   source=tuple(src.get("paths", ())) if src.get("kind") == "pags" else (),
                   time_limit=d.get("time_limit"), formats=tuple(d.get("formats", ("glb",))))


# --------------------------------------------------------------------------------------------
# sources of PAGs


class SceneSource:
    """Where PAGs come from: named entries per room type, each expanded from a seed."""

    def room_types(self) -> list[str]:
        """Room types with at least one entry, in :data:`ROOM_TYPES` order (then sorted)."""
        raise NotImplementedError

    def entries(self, room_type: str) -> list[str]:
        """Sorted entry names (template names, PAG file stems) of ``room_type``."""
        raise NotImplementedError

    def make_pag(self, name: str, seed: int):
        """The PAG of entry ``name`` for ``seed`` (validated against the asset vocabulary)."""
        raise NotImplementedError


def _order_rooms(types) -> list[str]:
    known = [t for t in ROOM_TYPES if t in types]
    return known + sorted(t for t in types if t not in ROOM_TYPES)


class TemplateSource(SceneSource):
    """The PAG templates of :mod:`parse3d.datagen.templates` (17 room types)."""

    def __init__(self) -> None:
        from . import templates as _templates

        self._mod = _templates
        self._by_name = {t.name: t for t in _templates.list_templates()}

    def room_types(self) -> list[str]:
        return _order_rooms({t.room_type for t in self._by_name.values()})

    def entries(self, room_type: str) -> list[str]:
        return sorted(n for n, t in self._by_name.items() if t.room_type == room_type)

    def make_pag(self, name: str, seed: int):
        return self._mod.expand_template(self._by_name[name], int(seed))


class PagFileSource(SceneSource):
    """PAG files (JSON or YAML); each file is one entry of its room's type, named by its stem.

    The room type is read from each file without validating it; full validation happens when
    a scene is built, so a broken file fails its scenes (recorded in the manifest) rather than
    the whole build.
    """

    def __init__(self, paths: Sequence[str | Path]) -> None:
        from ..pag.io import read_document

        self.paths = [Path(p) for p in paths]
        self._types: dict[str, str] = {}
        self._files: dict[str, Path] = {}
        problems = []
        for p in self.paths:
            try:
                doc = read_document(p)
                rtype = str(doc["room"]["type"])
            except InputError as e:
                problems.extend(e.problems)
                continue
            except (KeyError, TypeError):
                problems.append(Problem("/room/type", "a PAG file needs room.type", str(p),
                                        "schema"))
                continue
            name = p.stem
            if name in self._files:
                problems.append(Problem("", f"two PAG files are named {name!r} "
                                            f"({self._files[name]} and {p}); rename one",
                                        str(p), "io"))
                continue
            self._types[name] = rtype
            self._files[name] = p
        if problems:
            raise InputError(*problems)

    def room_types(self) -> list[str]:
        return _order_rooms(set(self._types.values()))

    def entries(self, room_type: str) -> list[str]:
        return sorted(n for n, t in self._types.items() if t == room_type)

    def make_pag(self, name: str, seed: int):
        from ..assets.registry import vocabulary
        from ..pag.io import load_pag

        return load_pag(self._files[name], vocabulary=vocabulary())


def _templates_available() -> bool:
    """Whether the template package is installed and holds template files (cheap: no
    template is loaded)."""
    import importlib.util
    from importlib import resources

    if importlib.util.find_spec("parse3d.datagen.templates") is None:
        return False
    root = resources.files("parse3d.datagen") / "templates"
    return root.is_dir() and any(
        f.name.endswith(".yaml") for d in root.iterdir() if d.is_dir() for f in d.iterdir())


def _bundled_paths() -> list[str]:
    from ..scenes import bundled_paths

    return [str(p) for p in bundled_paths()]


def make_source(config: BuildConfig) -> SceneSource:
    """The source a configuration names: its PAG files, else the templates."""
    if config.source:
        return PagFileSource(config.source)
    return TemplateSource()


def default_source_paths() -> tuple[str, ...]:
    """``()`` (the templates) when templates are installed, else the bundled example PAGs."""
    return () if _templates_available() else tuple(_bundled_paths())


def resolve_pag_paths(paths: Sequence[str | Path]) -> tuple[str, ...]:
    """Absolute, sorted PAG files from files and folders (a folder: its .json/.yaml/.yml)."""
    out: list[Path] = []
    problems = []
    for p in paths:
        p = Path(p)
        if p.is_dir():
            found = sorted(f for f in p.iterdir() if f.suffix in (".json", ".yaml", ".yml"))
            if not found:
                problems.append(Problem("", "no .json, .yaml or .yml PAG file in this folder",
                                        str(p), "io"))
            out.extend(found)
        elif p.is_file():
            out.append(p)
        else:
            problems.append(Problem("", "no such file or folder", str(p), "io"))
    if problems:
        raise InputError(*problems)
    return tuple(sorted({str(p.resolve()) for p in out}))


def select_rooms(config: BuildConfig, source: SceneSource) -> list[str]:
    """The room types a build cycles through, checked against the source."""
    have = source.room_types()
    if not config.rooms:
        if not have:
            raise InputError(Problem("", "the PAG source is empty: no template or PAG file",
                                     "--pags", "io"))
        return have
    import difflib

    problems = []
    for r in config.rooms:
        if r not in have:
            close = difflib.get_close_matches(r, list(have) + list(ROOM_TYPES), n=1)
            hint = f" — did you mean {close[0]!r}?" if close else ""
            problems.append(Problem("", f"no template or PAG of room type {r!r}{hint} "
                                        f"(available: {', '.join(have)})", "--rooms",
                                    "parameter"))
    if problems:
        raise InputError(*problems)
    return list(dict.fromkeys(config.rooms))


# --------------------------------------------------------------------------------------------
# one scene


@dataclass(frozen=True)
class ScenePlan:
    """What scene ``index`` of a build is: a room type, an entry of it and a scene seed."""

    index: int
    room_type: str
    template: str
    seed: int


def plan_scene(config: BuildConfig, source: SceneSource, index: int,
               rooms: Sequence[str] | None = None) -> ScenePlan:
    """Scene ``index``: room types cycle in order (even coverage), then an entry and a scene
    seed are drawn from ``default_rng([config.seed, index])``.

    Depends only on ``(config.seed, index)``, the room list and the source's entries, never
    on which worker or executor runs it.
    """
    rooms = list(rooms) if rooms is not None else select_rooms(config, source)
    room = rooms[int(index) % len(rooms)]
    names = source.entries(room)
    rng = np.random.default_rng([int(config.seed), int(index)])
    name = names[int(rng.integers(len(names)))]
    seed = int(rng.integers(2**31 - 1))
    return ScenePlan(int(index), room, name, seed)


@dataclass
class SceneOutcome:
    """A finished scene as a worker hands it back.

    Attributes
    ----------
    record : dict
        The manifest row (:mod:`parse3d.datagen.manifest`).
    files : dict of str to bytes
        The scene folder's files (empty unless the status is ``ok``).
    error : str or None
        The traceback of a scene that raised.
    """

    record: dict[str, Any]
    files: dict[str, bytes] = field(default_factory=dict)
    error: str | None = None


class SceneTimeout(BaseException):
    """A scene ran past the build's time limit.

    A ``BaseException`` so that no ``except Exception`` inside the pipeline swallows it.
    """


class _Stage:
    """The stage a scene is in, for timeout messages and per-stage timings."""

    def __init__(self) -> None:
        self.name = "plan"
        self.times: dict[str, float] = {}
        self._t = time.perf_counter()

    def enter(self, name: str) -> None:
        now = time.perf_counter()
        self.times[self.name] = self.times.get(self.name, 0.0) + now - self._t
        self.name, self._t = name, now


def _on_alarm(signum, frame):
    raise SceneTimeout()


def _base_record(plan: ScenePlan, config: BuildConfig) -> dict[str, Any]:
    return {"index": plan.index, "scene": None, "room_type": plan.room_type,
            "template": plan.template, "seed": plan.seed, "status": "failed", "reason": None,
            "views": int(config.views)}


def _scene_stats(scene) -> dict[str, Any]:
    placed = scene.placed
    area = float(scene.room.area)
    contacts = scene.contacts
    held = [(c.holds_settled if scene.settled else c.holds) for c in scene.relations]
    return {
        "objects": len(scene.objects), "placed": len(placed), "failed": len(scene.failed),
        "area": round(area, 6), "density": round(len(placed) / area, 6) if area > 0 else None,
        "contacts": None if contacts is None else len(contacts),
        "object_contacts": None if contacts is None else sum(
            1 for c in contacts if not (c.a.startswith("room:") or c.b.startswith("room:"))),
        "relations": len(scene.relations), "relations_held": sum(1 for h in held if h),
        "categories": [o.category for o in placed],
        "assets": [o.asset.asset_id for o in placed],
        "parts": [len(o.asset.parts) for o in placed],
    }


def build_scene(config: BuildConfig, index: int, *, source: SceneSource | None = None,
                renderer=None) -> SceneOutcome:
    """Build scene ``index`` of a dataset, entirely in memory (the task every executor runs).

    Expands the planned entry, solves, settles, extracts contacts, renders ``preview.png``
    and ``config.views`` views with ``renderer`` (a :class:`parse3d.render.Renderer` created
    in this process; one is created when None), serialises the folder's files and returns
    them with the manifest row. Never raises for a scene that fails: the exception, or the
    stage in which ``config.time_limit`` ran out, goes into the row.
    """
    wall = time.perf_counter()
    stage = _Stage()
    source = source if source is not None else make_source(config)
    plan = plan_scene(config, source, index)
    record = _base_record(plan, config)
    use_alarm = (config.time_limit is not None
                 and threading.current_thread() is threading.main_thread())
    old = None
    if use_alarm:
        old = signal.signal(signal.SIGALRM, _on_alarm)
        signal.setitimer(signal.ITIMER_REAL, float(config.time_limit))
    tmp = None
    try:
        stage.enter("expand")
        pag = source.make_pag(plan.template, plan.seed)
        stage.enter("solve")
        scene = _run_stages(pag, plan.seed, config, stage)
        record.update(_scene_stats(scene))
        if not scene.placed:
            stage.enter("done")
            record["reason"] = "no object could be placed: " + "; ".join(
                f"{o.id}: {o.reason}" for o in scene.failed[:3])
            return SceneOutcome(_finish(record, stage, wall))
        stage.enter("render")
        tmp = Path(tempfile.mkdtemp(prefix="parse3d-scene-"))
        _render(scene, tmp, config, plan, renderer)
        stage.enter("write")
        from ..export import ExportOptions, export_scene
        from ..physics.mujoco import settling_friction
        from ..scene.io import write_scene

        scene.timings.update({k: round(stage.times.get(k, 0.0), 6)
                              for k in ("expand", "render")})
        write_scene(scene, tmp)
        export_scene(scene, tmp, config.formats, ExportOptions(friction=settling_friction()))
        files = {p.relative_to(tmp).as_posix(): p.read_bytes() for p in sorted(tmp.rglob("*"))
                 if p.is_file()}
        stage.enter("done")
        record["status"] = "ok"
        record["scene"] = scene_folder(plan.index)
        return SceneOutcome(_finish(record, stage, wall), files)
    except SceneTimeout:
        where = stage.name
        stage.enter("done")
        record["status"] = "timeout"
        record["reason"] = f"ran past the {config.time_limit:g} s time limit during {where}"
        return SceneOutcome(_finish(record, stage, wall))
    except Exception as e:
        stage.enter("done")
        record["status"] = "failed"
        record["reason"] = _reason(e)
        return SceneOutcome(_finish(record, stage, wall), error=traceback.format_exc())
    finally:
        if use_alarm:
            signal.setitimer(signal.ITIMER_REAL, 0.0)
            signal.signal(signal.SIGALRM, old)
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)


def _reason(e: BaseException) -> str:
    text = str(e).strip().splitlines()
    msg = text[0] if text else ""
    if isinstance(e, InputError) and len(e.problems) > 1:
        msg += f" (and {len(e.problems) - 1} more problems)"
    return f"{type(e).__name__}: {msg}"[:500]


def _run_stages(pag, seed: int, config: BuildConfig, stage: _Stage):
    """Solve, then settle and extract contacts (as :func:`parse3d.pipeline.run_pipeline`)."""
    from ..pipeline import PipelineOptions, run_pipeline

    scene = run_pipeline(pag, seed=seed, out=None,
                         options=PipelineOptions(settle=False, preview=False))
    if config.settle and scene.placed:
        from ..physics import extract_contacts, settle

        stage.enter("settle")
        settle(scene)
        scene.timings["settle"] = time.perf_counter() - stage._t
        stage.enter("contacts")
        scene.contacts = extract_contacts(scene)
        scene.timings["contacts"] = time.perf_counter() - stage._t
    return scene


def _render(scene, out: Path, config: BuildConfig, plan: ScenePlan, renderer) -> None:
    from ..render import Renderer, sample_views, save_preview, write_views

    r = renderer if renderer is not None else Renderer()
    w, h = (int(v) for v in config.view_size)
    save_preview(scene, out / "preview.png", width=w, height=h, renderer=r)
    if config.views > 0:
        rng = np.random.default_rng([int(plan.seed), 0x52454E44])  # "REND", as parse3d render
        cams = sample_views(scene, int(config.views), rng, width=w, height=h, renderer=r)
        write_views(scene, cams, out, renderer=r,
                    meta={"seed": int(plan.seed), "requested_views": int(config.views),
                          "size": [w, h]})


def _finish(record: dict[str, Any], stage: _Stage, wall: float) -> dict[str, Any]:
    t = stage.times
    record.update({
        "t_expand": round(t.get("expand", 0.0), 6),
        "t_solve": round(t.get("solve", 0.0), 6),
        "t_settle": round(t.get("settle", 0.0), 6),
        "t_contacts": round(t.get("contacts", 0.0), 6),
        "t_render": round(t.get("render", 0.0), 6),
        "t_write": round(t.get("write", 0.0), 6),
        "t_total": round(time.perf_counter() - wall, 6),
    })
    return record


# --------------------------------------------------------------------------------------------
# the build


def scene_folder(index: int) -> str:
    """Folder name of scene ``index`` under ``DIR/scenes/``."""
    return f"{int(index):05d}"


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
    total, ok, failed, timeout : int
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

    @property
    def scenes_per_hour(self) -> float:
        return 3600.0 * self.built / self.wall if self.wall > 0 else 0.0


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
    from ..scene.io import atomic_write_text

    atomic_write_text(path, json.dumps(data, indent=1) + "\n")
    path.chmod(0o644)


def _recover(out: Path, scenes: int) -> dict[int, dict[str, Any]]:
    """Finished scenes of a previous run: the manifest plus every durable per-scene record.

    Removes what an interrupted run left half-done (temporary folders, scene folders without
    a record).
    """
    from .manifest import read_manifest

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
            (tmp / fname).parent.mkdir(parents=True, exist_ok=True)  # meshes/, urdf/
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


def build_dataset(config: BuildConfig, out: str | Path, *, executor: str = "local",
                  workers: int = 2, ray_address: str | None = None,
                  retry_failed: bool = False, max_tasks: int = 200, flush_every: float = 2.0,
                  progress: Callable[[BuildEvent], None] | None = None) -> BuildReport:
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
        Seconds between manifest rewrites (finished scenes are durable at once through their
        own records; the manifest is always rewritten at the end).
    progress : callable or None
        Called with a :class:`BuildEvent` for every finished scene.

    Raises
    ------
    InputError
        Unknown room types or executor, an empty source, or a folder built with other
        settings.
    """
    from .executors import make_executor
    from .manifest import write_manifest

    out = Path(out)
    source = make_source(config)
    rooms = select_rooms(config, source)
    if executor not in ("local", "ray"):
        raise InputError(Problem("", f"unknown executor {executor!r} (use local or ray)",
                                 "--executor", "parameter"))
    if int(workers) < 1:
        raise InputError(Problem("", f"--workers must be >= 1, got {workers}", "--workers",
                                 "parameter"))
    out.mkdir(parents=True, exist_ok=True)
    config_run = replace(config, rooms=tuple(rooms))
    _check_config(out, config_run)
    cfg_file = out / "dataset.json"
    stored = json.loads(cfg_file.read_text()) if cfg_file.exists() else {}
    _write_json(cfg_file, {**config_run.to_dict(),
                           "scenes": max(int(stored.get("scenes", 0)), int(config.scenes)),
                           "rooms_requested": list(config.rooms)})

    rows = _recover(out, config.scenes)
    if retry_failed:
        rows = {i: r for i, r in rows.items() if r["status"] == "ok"}
    resumed = sum(1 for i in rows if i < config.scenes)
    todo = [i for i in range(config.scenes) if i not in rows]
    t0 = time.perf_counter()
    last_flush = t0
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
                if time.perf_counter() - last_flush >= flush_every:
                    write_manifest(out / "manifest.parquet", list(rows.values()))
                    last_flush = time.perf_counter()
    finally:
        write_manifest(out / "manifest.parquet", list(rows.values()))
    mine = [r for i, r in rows.items() if i < config.scenes]
    return BuildReport(out=out, total=len(mine),
                       ok=sum(1 for r in mine if r["status"] == "ok"),
                       failed=sum(1 for r in mine if r["status"] == "failed"),
                       timeout=sum(1 for r in mine if r["status"] == "timeout"),
                       resumed=resumed, built=built, wall=time.perf_counter() - t0)
