"""Solve jobs of the designer: validate, solve, settle, contacts, export, with progress events.

A :class:`Job` runs in a worker thread and appends events that the API streams to the
browser as server-sent events:

* ``{"type": "stage", "stage": "solve", "status": "start"}`` and ``status: "done"`` with
  ``seconds`` for each of :data:`STAGES` (``skipped`` for settle and contacts when not asked);
* ``{"type": "object", "id": ..., "status": "placed"|"failed", "reason": ...}`` per object;
* ``{"type": "done", ...}`` or ``{"type": "error", "message": ..., "problems": [...]}`` last.

The files go where ``parse3d solve`` puts them by default, ``out/<name>-<seed>/`` — inside the
server's working folder.
"""

from __future__ import annotations

import re
import threading
import time
import traceback
import uuid
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import InputError, Parse3dError, Problem
from ..pag.model import PAG
from ..pag.validate import validate_data
from ..scene.model import Scene

__all__ = ["STAGES", "SCENE_FILES", "Job", "run_job", "scene_payload", "out_folder"]

#: The stages a job reports, in order.
STAGES = ("validate", "solve", "settle", "contacts", "export")

#: The files of a solved scene the API serves.
SCENE_FILES = ("scene.json", "scene.glb", "contacts.json")


@dataclass
class Job:
    """One solve request and what it has produced so far.

    Attributes
    ----------
    id : str
    seed : int
    settle : bool
    events : list of dict
        Appended by the worker; read by any number of event streams.
    state : str
        ``queued``, ``running``, ``done`` (the scene exists, possibly with failed objects),
        ``failed`` (no scene: invalid PAG or an error) or ``cancelled``.
    out : Path or None
        The folder the scene files were written to.
    result : dict or None
        :func:`scene_payload` of the scene once done.
    """

    id: str
    seed: int
    settle: bool
    events: list[dict[str, Any]] = field(default_factory=list)
    state: str = "queued"
    out: Path | None = None
    result: dict[str, Any] | None = None
    created: float = field(default_factory=time.time)
    cancelled: threading.Event = field(default_factory=threading.Event, repr=False)
    _lock: threading.Lock = field(default_factory=threading.Lock, repr=False)

    def cancel(self) -> None:
        """Stop the job: a queued one never starts; a running one stops at the next object
        it places (or between stages) and writes nothing more."""
        if self.finished:
            return
        self.cancelled.set()
        if self.state == "queued":
            self.state = "cancelled"
            self.emit("error", stage="queue", message="cancelled", problems=[])

    def check_cancelled(self) -> None:
        if self.cancelled.is_set():
            raise _Cancelled()

    @classmethod
    def new(cls, seed: int, settle: bool) -> Job:
        return cls(uuid.uuid4().hex[:12], int(seed), bool(settle))

    def emit(self, type: str, **data: Any) -> None:
        with self._lock:
            self.events.append({"type": type, "t": round(time.time() - self.created, 4), **data})

    def events_since(self, n: int) -> list[dict[str, Any]]:
        with self._lock:
            return list(self.events[n:])

    @property
    def finished(self) -> bool:
        return self.state in ("done", "failed", "cancelled")


class _Cancelled(Exception):
    """Raised inside a running job once it was cancelled."""


def out_folder(workdir: Path, name: str, seed: int) -> Path:
    """``workdir/out/<name>-<seed>``, the name reduced to letters, digits, ``_`` and ``-``.

    Raises
    ------
    InputError
        ``out`` or the scene's folder is a symbolic link (or resolves) outside ``workdir``:
        the server writes nowhere else.
    """
    safe = re.sub(r"[^A-Za-z0-9_\-]+", "-", name or "").strip("-")[:60] or "scene"
    root = Path(workdir).resolve()
    out = root / "out" / f"{safe}-{int(seed)}"
    for p in (out.parent, out):
        if p.is_symlink() or (p.exists() and not p.resolve().is_relative_to(root)):
            raise InputError(Problem("", f"{p.relative_to(root)} is a link out of the working "
                                         "folder: the designer writes only inside it (remove "
                                         "the link)", str(p.relative_to(root)), "io"))
        if p.exists() and not p.is_dir():
            raise InputError(Problem("", f"{p.relative_to(root)} is a file, not a folder",
                                     str(p.relative_to(root)), "io"))
    return out


def _solve(pag: PAG, seed: int, library, on_object: Callable[[str, str, str | None], None],
           time_limit: float | None = None) -> Scene:
    """Run the solver, announcing each object as it is placed or fails.

    ``on_object(object_id, status, reason)`` is called from the solver's progress callback;
    the reasons of failed objects come with the job's ``done`` event.
    """
    from ..solver import solve

    return solve(pag, seed=seed, library=library, validate=False, deadline=time_limit,
                 progress=lambda p: on_object(p.object_id, p.status, None))


def run_job(job: Job, data: Any, *, workdir: Path, vocabulary, library=None,
            time_limit: float | None = None) -> None:
    """Run every stage of ``job`` on the document ``data``; never raises.

    ``time_limit`` (seconds) bounds the solve: objects not placed by then fail with
    ``time limit``. A cancelled job stops at its next object or stage.
    """
    if job.finished:  # cancelled while queued
        return
    job.state = "running"
    stage = "validate"
    try:
        t = time.perf_counter()
        job.emit("stage", stage=stage, status="start")
        problems = validate_data(data, vocabulary=vocabulary)
        if problems:
            job.state = "failed"
            job.emit("error", stage=stage, message=f"the PAG has {len(problems)} problem"
                     f"{'s' if len(problems) != 1 else ''}: fix them before solving",
                     problems=[p.to_dict() for p in problems])
            return
        pag = PAG.from_dict(data)
        job.emit("stage", stage=stage, status="done", seconds=round(time.perf_counter() - t, 4))

        stage = "solve"
        job.emit("stage", stage=stage, status="start", objects=len(pag.objects))
        t = time.perf_counter()
        def on_object(oid, status, reason):
            job.check_cancelled()
            job.emit("object", id=oid, status=status, reason=reason)

        scene = _solve(pag, job.seed, library, on_object, time_limit)
        job.check_cancelled()
        job.emit("stage", stage=stage, status="done", seconds=round(time.perf_counter() - t, 4),
                 placed=len(scene.placed), failed=len(scene.failed))

        if job.settle and scene.placed:
            from ..physics import extract_contacts
            from ..pipeline import settle_and_repair

            stage = "settle"
            job.emit("stage", stage=stage, status="start")
            t = time.perf_counter()
            settle_and_repair(scene, library=library)
            scene.timings["settle"] = time.perf_counter() - t
            job.emit("stage", stage=stage, status="done", seconds=round(scene.timings["settle"], 4))
            job.check_cancelled()
            stage = "contacts"
            job.emit("stage", stage=stage, status="start")
            t = time.perf_counter()
            scene.contacts = extract_contacts(scene)
            scene.timings["contacts"] = time.perf_counter() - t
            job.emit("stage", stage=stage, status="done",
                     seconds=round(scene.timings["contacts"], 4), contacts=len(scene.contacts))
        else:
            job.emit("stage", stage="settle", status="skipped")
            job.emit("stage", stage="contacts", status="skipped")

        from ..pipeline import write_outputs

        job.check_cancelled()
        stage = "export"
        job.emit("stage", stage=stage, status="start")
        t = time.perf_counter()
        out = out_folder(workdir, pag.name, job.seed)
        from ..scene.io import clear_scene_outputs

        clear_scene_outputs(out)  # refuses a folder whose scene.json parse3d did not write
        write_outputs(scene, out)
        job.out = out
        job.emit("stage", stage=stage, status="done", seconds=round(time.perf_counter() - t, 4),
                 out=str(job.out.relative_to(workdir)))
        job.result = scene_payload(scene, out=str(job.out.relative_to(workdir)))
        job.state = "done"
        job.emit("done", ok=scene.ok, placed=len(scene.placed), objects=len(scene.objects),
                 failed=[{"id": o.id, "reason": o.reason} for o in scene.failed])
    except _Cancelled:
        job.state = "cancelled"
        job.emit("error", stage=stage, message="cancelled", problems=[])
    except InputError as e:
        job.state = "failed"
        job.emit("error", stage=stage, message=str(e.problems[0].message if e.problems else e),
                 problems=[p.to_dict() for p in e.problems])
    except Parse3dError as e:
        job.state = "failed"
        job.emit("error", stage=stage, message=str(e), problems=[])
    except Exception as e:  # a bug must reach the browser as a message, and the log in full
        traceback.print_exc()
        job.state = "failed"
        job.emit("error", stage=stage, message=f"internal error in {stage}: "
                 f"{type(e).__name__}: {e}", problems=[])


def scene_payload(scene: Scene, *, out: str | None = None) -> dict[str, Any]:
    """What the viewer needs of a solved scene: objects, relation checks, contacts, timings."""
    objects = []
    for o in scene.objects.values():
        d: dict[str, Any] = {"id": o.id, "category": o.category, "status": o.status,
                             "reason": o.reason}
        if o.placed:
            d["asset"] = o.asset.asset_id
            d["parts"] = [{"name": p.name, "label": p.label} for p in o.asset.parts]
            d["support"] = o.support
        objects.append(d)
    relations = [{"index": c.index, "relation": c.relation, "child": c.child, "parent": c.parent,
                  "holds": c.holds, "holds_settled": c.holds_settled, "residual": c.residual,
                  "residual_settled": c.residual_settled, "detail": c.detail}
                 for c in scene.relations]
    return {
        "name": scene.pag.name, "seed": int(scene.seed), "settled": bool(scene.settled),
        "room": {"footprint": [[float(x), float(y)] for x, y in scene.room.footprint],
                 "height": float(scene.room.height)},
        "ok": scene.ok, "objects": objects, "relations": relations,
        "contacts": None if scene.contacts is None else [c.to_dict() for c in scene.contacts],
        "timings": {k: round(float(v), 4) for k, v in scene.timings.items()},
        "out": out, "files": [f for f in SCENE_FILES
                              if f != "contacts.json" or scene.contacts is not None],
    }
