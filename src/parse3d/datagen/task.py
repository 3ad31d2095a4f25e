"""The per-scene task every executor runs: expand, solve, settle, contacts, render, serialise."""

from __future__ import annotations

import shutil
import signal
import tempfile
import threading
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import InputError
from .build_config import BuildConfig
from .planning import ScenePlan, plan_scene, scene_folder
from .sources import SceneSource, make_source


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


#: The timed stages of a scene, in order (``t_<stage>`` and ``cpu_<stage>`` of its record).
STAGES = ("expand", "solve", "settle", "contacts", "render", "write")


class SceneTimeout(BaseException):
    """A scene ran past the build's time limit.

    A ``BaseException`` so that no ``except Exception`` inside the pipeline swallows it.
    """


class _Stage:
    """The stage a scene is in, for timeout messages and per-stage timings."""

    def __init__(self) -> None:
        self.name = "plan"
        self.times: dict[str, float] = {}
        self.cpu: dict[str, float] = {}  # CPU seconds of this process (all its threads)
        self._t = time.perf_counter()
        self._c = time.process_time()

    def enter(self, name: str) -> None:
        now, cpu = time.perf_counter(), time.process_time()
        self.times[self.name] = self.times.get(self.name, 0.0) + now - self._t
        self.cpu[self.name] = self.cpu.get(self.name, 0.0) + cpu - self._c
        self.name, self._t, self._c = name, now, cpu


#: Seconds between repeated alarms after the time limit: a SceneTimeout raised where Python
#: drops exceptions (a finaliser run by the garbage collector at that moment) is raised again.
ALARM_REPEAT = 0.05

_ALARM = {"armed": False}


def _on_alarm(signum, frame):
    if _ALARM["armed"]:
        raise SceneTimeout()


def _disarm() -> None:
    _ALARM["armed"] = False
    signal.setitimer(signal.ITIMER_REAL, 0.0)


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
        "repaired": (scene.meta.get("repair") or {}).get("repaired"),
        "unrepaired": (scene.meta.get("repair") or {}).get("unrepaired"),
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
    wall, cpu = time.perf_counter(), time.process_time()
    stage = _Stage()
    source = source if source is not None else make_source(config)
    plan = plan_scene(config, source, index)
    record = _base_record(plan, config)
    use_alarm = (config.time_limit is not None
                 and threading.current_thread() is threading.main_thread())
    old = None
    if use_alarm:
        old = signal.signal(signal.SIGALRM, _on_alarm)
        _ALARM["armed"] = True
        signal.setitimer(signal.ITIMER_REAL, float(config.time_limit), ALARM_REPEAT)
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
            return SceneOutcome(_finish(record, stage, wall, cpu))
        stage.enter("render")
        tmp = Path(tempfile.mkdtemp(prefix="parse3d-scene-"))
        _render(scene, tmp, config, plan, renderer)
        stage.enter("write")
        from ..pipeline import write_outputs

        scene.timings.update({k: round(stage.times.get(k, 0.0), 6)
                              for k in ("expand", "render")})
        write_outputs(scene, tmp, config.formats)
        files = {p.relative_to(tmp).as_posix(): p.read_bytes() for p in sorted(tmp.rglob("*"))
                 if p.is_file()}
        stage.enter("done")
        record["status"] = "ok" if scene.ok else "incomplete"
        if not scene.ok:
            record["reason"] = f"{len(scene.failed)} object(s) failed: " + "; ".join(
                f"{o.id}: {o.reason}" for o in scene.failed[:3])
        record["scene"] = scene_folder(plan.index)
        return SceneOutcome(_finish(record, stage, wall, cpu), files)
    except SceneTimeout:
        if use_alarm:
            _disarm()
        where = stage.name
        stage.enter("done")
        record["status"] = "timeout"
        record["reason"] = f"ran past the {config.time_limit:g} s time limit during {where}"
        return SceneOutcome(_finish(record, stage, wall, cpu))
    except Exception as e:
        stage.enter("done")
        record["status"] = "failed"
        record["reason"] = _reason(e)
        return SceneOutcome(_finish(record, stage, wall, cpu), error=traceback.format_exc())
    finally:
        if use_alarm:
            _disarm()
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
        from ..physics import extract_contacts
        from ..pipeline import settle_and_repair

        stage.enter("settle")
        settle_and_repair(scene)
        scene.timings["settle"] = time.perf_counter() - stage._t
        stage.enter("contacts")
        scene.contacts = extract_contacts(scene)
        scene.timings["contacts"] = time.perf_counter() - stage._t
    return scene


def _render(scene, out: Path, config: BuildConfig, plan: ScenePlan, renderer) -> None:
    from ..render import Renderer, sample_views, save_preview, write_views
    from ..render.camera import view_rng

    r = renderer if renderer is not None else Renderer()
    w, h = (int(v) for v in config.view_size)
    save_preview(scene, out / "preview.png", width=w, height=h, renderer=r)
    if config.views > 0:
        rng = view_rng(plan.seed)  # as parse3d render --seed
        cams = sample_views(scene, int(config.views), rng, width=w, height=h, renderer=r)
        write_views(scene, cams, out, renderer=r,
                    meta={"seed": int(plan.seed), "requested_views": int(config.views),
                          "size": [w, h]})


def _finish(record: dict[str, Any], stage: _Stage, wall: float, cpu: float) -> dict[str, Any]:
    for prefix, t in (("t", stage.times), ("cpu", stage.cpu)):
        record.update({f"{prefix}_{k}": round(t.get(k, 0.0), 6) for k in STAGES})
    record["t_total"] = round(time.perf_counter() - wall, 6)
    record["cpu_total"] = round(time.process_time() - cpu, 6)
    return record
