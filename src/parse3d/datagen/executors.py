"""Where scenes are built: a pool of local worker processes, or tasks on a Ray cluster.

Both executors run the same task, :func:`parse3d.datagen.build.build_scene`, and hand its
:class:`~parse3d.datagen.build.SceneOutcome` back to the driver, which alone writes to the
dataset folder. A scene therefore comes out the same whatever the executor or the number of
workers.

:class:`LocalExecutor`
    ``workers`` processes, each the one process of a ``concurrent.futures``
    ``ProcessPoolExecutor``, started through a fork server (so no thread lock of the driver
    is inherited) that has imported the stages' modules once (:data:`WORKER_MODULES`), so a
    worker starts without importing them again (``spawn`` where the platform has no fork
    server). Each creates its own OpenGL (EGL) context, builds at most ``max_tasks`` scenes
    and is then replaced by its pool, so memory stays bounded over long runs (caches of
    assets and collision shapes grow with every new asset).
    A worker that dies is replaced and its scene tried once more in the new worker (the death
    may have come from outside: the OOM killer, a signal); a scene whose worker dies twice (a
    crash in native code) is recorded as ``failed``, one that runs past the hard time limit is
    killed and recorded as ``timeout``, and the build goes on.
:class:`RayExecutor`
    Tasks of one CPU each on ``ray.init(address=...)``, or on a local Ray instance when no
    address is given. Files travel back to the driver through the object store, so the
    cluster's nodes need no shared file system.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
import time
from collections import deque
from collections.abc import Iterable, Iterator
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from typing import Any

from ..errors import InputError, Problem
from .build_config import DEFAULT_MAX_TASKS, BuildConfig
from .planning import plan_scene
from .sources import SceneSource, make_source
from .task import SceneOutcome, _base_record, build_scene

__all__ = ["LocalExecutor", "RayExecutor", "make_executor", "hard_limit", "WORKER_MODULES",
           "start_context"]

#: The modules a worker's stages import, preloaded by the fork server so that every worker
#: (and every replacement after ``max_tasks`` scenes) is forked with them already imported.
#: Importing creates no OpenGL context, SAPIEN scene or Python thread: those are made in the
#: worker, after the fork.
WORKER_MODULES = (
    "parse3d.datagen.task", "parse3d.datagen.memory", "parse3d.pipeline", "parse3d.physics",
    "parse3d.export", "parse3d.export.gltf", "parse3d.render", "parse3d.assets.generators",
    "parse3d.assets.loaders", "sapien", "moderngl",
)


def hard_limit(config: BuildConfig) -> float | None:
    """Seconds after which the driver kills a scene that its worker has not returned.

    The worker's own timer (``config.time_limit``) stops pure-Python stages; this backstop
    catches native code that does not return.
    """
    if config.time_limit is None:
        return None
    return float(config.time_limit) * 1.25 + 15.0


def _lost(config: BuildConfig, index: int, status: str, reason: str,
          source: SceneSource | None = None) -> SceneOutcome:
    """The outcome of a scene whose worker never answered."""
    plan = plan_scene(config, source if source is not None else make_source(config), index)
    rec = _base_record(plan, config)
    rec.update({"status": status, "reason": reason})
    return SceneOutcome(rec)


# --------------------------------------------------------------------------------------------
# per-process state of a worker (created on first use, after the fork)

_PROCESS: dict[str, Any] = {}


def _process_state(config: BuildConfig) -> tuple[Any, Any]:
    """This process's scene source and renderer (None when no GL context can be created: the
    scenes then fail with the renderer's DependencyError, recorded in the manifest)."""
    key = repr(config.source)
    if _PROCESS.get("key") != key:
        _PROCESS["key"] = key
        _PROCESS["source"] = make_source(config)
    if "renderer" not in _PROCESS:
        import os

        from ..errors import DependencyError
        from ..render import Renderer

        # one rasteriser thread (unless the user chose): the workers already keep every core
        # busy, and Mesa's llvmpipe threads then only add hand-overs between them
        os.environ.setdefault("LP_NUM_THREADS", "1")

        try:
            _PROCESS["renderer"] = Renderer()
        except DependencyError:
            _PROCESS["renderer"] = None
    return _PROCESS["source"], _PROCESS["renderer"]


def run_task(config: BuildConfig, index: int) -> SceneOutcome:
    """Build one scene with this process's source and renderer (the task of every executor),
    then trim the process's per-asset caches so that memory stays bounded over many scenes."""
    from .memory import bound_caches

    source, renderer = _process_state(config)
    try:
        return build_scene(config, index, source=source, renderer=renderer)
    finally:
        bound_caches(renderer)


# --------------------------------------------------------------------------------------------
# local processes


def start_context():
    """The multiprocessing context of local workers, its fork server started now.

    ``forkserver`` where the platform has it (Linux, macOS): a fresh single-threaded server
    that imports :data:`WORKER_MODULES` (and the main module, as multiprocessing does by
    default) while the driver goes on preparing the build; each worker is then forked from
    it with those modules loaded. ``spawn`` elsewhere (Windows): every worker imports them
    itself. A fork server already running in this process (started by an earlier build or by
    other code) is reused as it is; its workers then import what it lacks.
    """
    import multiprocessing as mp

    if "forkserver" not in mp.get_all_start_methods():
        return mp.get_context("spawn")
    from multiprocessing import forkserver

    ctx = mp.get_context("forkserver")
    server = forkserver._forkserver
    if getattr(server, "_forkserver_pid", None) is None:  # not started yet: preload
        ctx.set_forkserver_preload(["__main__", *WORKER_MODULES])
    forkserver.ensure_running()
    return ctx


def _watch_driver(driver: int) -> None:
    """Exit this worker once the driver process is gone (killed with SIGKILL, say): a pool
    worker blocked on its task queue would never notice, since it holds both ends of that
    queue, and the fork server it was forked from outlives the driver too."""
    while True:
        time.sleep(1.0)
        try:
            os.kill(driver, 0)
        except ProcessLookupError:
            os._exit(1)
        except PermissionError:  # a process of another user took the id: gone as well
            os._exit(1)


def _init_worker(config: BuildConfig, source, driver: int) -> None:
    """A pool process's start: its scene source and GL context, made once for the scenes it
    builds (``max_tasks`` of them before the pool replaces it)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the driver handles Ctrl-C and stops us
    _PROCESS.clear()  # nothing of the driver's (a GL context above all) is reused
    _PROCESS["config"] = config
    if source is not None:  # handed over by the driver: templates are not loaded again
        _PROCESS.update(key=repr(config.source), source=source)
    from .. import export, physics, pipeline  # noqa: F401 - the stages' modules, once
    from .memory import freeze_startup

    _process_state(config)  # the scene source and the GL context
    freeze_startup()  # full collections then skip all of that
    threading.Thread(target=_watch_driver, args=(driver,), daemon=True).start()


def _run_index(index: int) -> SceneOutcome:
    """The pool's task: scene ``index`` of the configuration the process started with."""
    return run_task(_PROCESS["config"], index)


def _kill(pool: ProcessPoolExecutor) -> None:
    """Kill ``pool``'s process now (a scene past its hard limit, or the build stopped) and
    wait for it. ``kill_workers`` is public from Python 3.14; before, the pool's own table
    of processes is the only handle on them."""
    if hasattr(pool, "kill_workers"):
        pool.kill_workers()
    else:
        for proc in list((getattr(pool, "_processes", None) or {}).values()):
            with contextlib.suppress(OSError, ValueError):
                proc.kill()
    pool.shutdown(wait=True, cancel_futures=True)


@dataclass
class _Slot:
    """One worker: a ``ProcessPoolExecutor`` of one process, and the scene it builds."""

    pool: ProcessPoolExecutor
    future: Future | None = None
    index: int | None = None
    started: float = 0.0


class LocalExecutor:
    """Worker processes on this machine, one ``concurrent.futures.ProcessPoolExecutor`` of a
    single process per worker, so that a death or a hang is charged to its own scene.

    Parameters
    ----------
    workers : int
        Processes building scenes at once.
    max_tasks : int
        Scenes per worker process before it is replaced (bounds memory).
    """

    def __init__(self, *, workers: int = 2, max_tasks: int = DEFAULT_MAX_TASKS) -> None:
        self.workers = max(1, int(workers))
        self.max_tasks = max(1, int(max_tasks))

    def run(self, config: BuildConfig, indices: Iterable[int], *,
            source: SceneSource | None = None) -> Iterator[SceneOutcome]:
        """Build ``indices``; yields each outcome as it finishes (not in index order).

        ``source``: the driver's :class:`SceneSource` of ``config``, handed to the workers
        (None: each worker makes its own).
        """
        import pickle

        # forkserver: workers fork from a fresh single-threaded server, never from a driver that
        # may hold thread locks (a test runner's I/O thread, native thread pools) at fork time
        ctx = start_context()
        if source is not None:  # handed over by pickling; a source that cannot be is rebuilt
            try:
                pickle.dumps(source)
            except (TypeError, AttributeError, pickle.PicklingError):
                source = None
        pending = deque(int(i) for i in indices)
        limit = hard_limit(config)
        died: dict[int, int] = {}

        def new_slot() -> _Slot:
            return _Slot(ProcessPoolExecutor(
                max_workers=1, mp_context=ctx, initializer=_init_worker,
                initargs=(config, source, os.getpid()), max_tasks_per_child=self.max_tasks))

        def hand_out(s: _Slot) -> None:
            """Give worker ``s`` the next scene, or let it go when none is left. Called before
            an outcome goes back to the driver, so the worker builds on while it commits."""
            if pending:
                s.index, s.started = pending.popleft(), time.perf_counter()
                s.future = s.pool.submit(_run_index, s.index)
            else:
                s.index, s.future = None, None
                s.pool.shutdown(wait=False)
                slots.remove(s)

        slots: list[_Slot] = []
        try:
            while pending and len(slots) < self.workers:
                slots.append(new_slot())
                hand_out(slots[-1])
            while slots:
                futures = {s.future: s for s in slots}
                finished, _ = wait(futures, timeout=0.5, return_when=FIRST_COMPLETED)
                for s in list(slots):
                    if s.future in finished:
                        index = s.index
                        try:
                            outcome = s.future.result()
                        except BrokenProcessPool:
                            s.pool.shutdown(wait=True, cancel_futures=True)
                            slots.remove(s)
                            died[index] = died.get(index, 0) + 1
                            if died[index] < 2:
                                # once more in a fresh worker: the process may have been
                                # killed from outside (OOM killer, a signal to the group)
                                pending.appendleft(index)
                                slots.append(new_slot())
                                hand_out(slots[-1])
                                continue
                            outcome = _lost(config, index, "failed",
                                            "worker process died twice while building this "
                                            "scene", source)
                            if pending:
                                slots.append(new_slot())
                                hand_out(slots[-1])
                        else:
                            hand_out(s)
                        yield outcome
                    elif limit is not None and time.perf_counter() - s.started > limit:
                        msg = (f"killed after {limit:g} s: the worker did not return "
                               f"(time limit {config.time_limit:g} s)")
                        outcome = _lost(config, s.index, "timeout", msg, source)
                        _kill(s.pool)
                        slots.remove(s)
                        if pending:
                            slots.append(new_slot())
                            hand_out(slots[-1])
                        yield outcome
        finally:
            for s in slots:
                if s.future is not None and not s.future.done():
                    _kill(s.pool)
                else:
                    s.pool.shutdown(wait=True, cancel_futures=True)


# --------------------------------------------------------------------------------------------
# Ray


class RayExecutor:
    """Scene tasks on a Ray cluster (one CPU each).

    Parameters
    ----------
    address : str or None
        Passed to ``ray.init``; None connects to the running Ray instance of this process, or
        starts a local one with ``workers`` CPUs.
    workers : int
        Scenes in flight at once.
    """

    def __init__(self, *, address: str | None = None, workers: int = 2) -> None:
        self.address = address
        self.workers = max(1, int(workers))

    def run(self, config: BuildConfig, indices: Iterable[int], *,
            source: SceneSource | None = None) -> Iterator[SceneOutcome]:
        """Build ``indices``; yields each outcome as it finishes (not in index order).

        ``source`` is unused: every Ray worker process makes its own, once.
        """
        try:
            import ray
        except ImportError:
            from ..errors import DependencyError

            raise DependencyError("the Ray executor needs the Python package 'ray': "
                                  "pip install 'parse3d[cluster]'") from None
        started = False
        if not ray.is_initialized():
            if self.address:
                ray.init(address=self.address, log_to_driver=False)
            else:
                ray.init(num_cpus=self.workers, include_dashboard=False, log_to_driver=False)
            started = True
        task = ray.remote(num_cpus=1, max_retries=0)(run_task)
        pending = deque(int(i) for i in indices)
        limit = hard_limit(config)
        cfg_ref = ray.put(config)
        flight: dict[Any, tuple[int, float]] = {}
        try:
            while pending or flight:
                while pending and len(flight) < self.workers:
                    i = pending.popleft()
                    flight[task.remote(cfg_ref, i)] = (i, time.perf_counter())
                done, _ = ray.wait(list(flight), num_returns=1, timeout=0.5)
                for ref in done:
                    i, _t = flight.pop(ref)
                    try:
                        yield ray.get(ref)
                    except ray.exceptions.RayError as e:
                        msg = str(e).strip().splitlines()
                        yield _lost(config, i, "failed", f"{type(e).__name__}: "
                                                         f"{msg[0] if msg else ''}"[:500])
                if limit is not None:
                    now = time.perf_counter()
                    for ref, (i, t) in list(flight.items()):
                        if now - t > limit:
                            ray.cancel(ref, force=True)
                            flight.pop(ref)
                            yield _lost(config, i, "timeout",
                                        f"cancelled after {limit:g} s: the task did not return "
                                        f"(time limit {config.time_limit:g} s)")
        finally:
            for ref in flight:
                ray.cancel(ref, force=True)
            if started:
                ray.shutdown()


def make_executor(kind: str, *, workers: int = 2, address: str | None = None,
                  max_tasks: int = DEFAULT_MAX_TASKS):
    """``LocalExecutor`` or ``RayExecutor`` by name (``max_tasks``: local only)."""
    if kind == "local":
        if address:
            raise InputError(Problem("", "--ray-address needs --executor ray", "--ray-address",
                                     "parameter"))
        return LocalExecutor(workers=workers, max_tasks=max_tasks)
    if kind == "ray":
        return RayExecutor(address=address, workers=workers)
    raise InputError(Problem("", f"unknown executor {kind!r} (use local or ray)", "--executor",
                             "parameter"))
