"""Dataset throughput: scenes per hour of the whole pipeline, per-stage times, where the rest goes.

Usage::

    python benchmarks/bench_dataset.py                      # 40 template scenes, 2 workers
    python benchmarks/bench_dataset.py --scenes 48 --workers 2 --views 2
    python benchmarks/bench_dataset.py --pags examples/     # the example PAGs instead
    python benchmarks/bench_dataset.py --baseline-rev 20249ea   # also the same build at REV
    python benchmarks/bench_dataset.py --scenes 200 --workers 1 # a worker's RSS after 200 scenes
    python benchmarks/bench_dataset.py --baseline-rev main --rounds 2  # interleaved: now, main, now, main

Builds ``--scenes`` scenes with the local executor (expand, solve, settle, contacts, render,
write; exactly what ``parse3d dataset build`` runs), then prints:

* the wall-clock throughput and the time 10,000 scenes would take at that rate;
* per-stage mean, median and max seconds from the manifest, and each stage's share of the
  workers' time (``workers x wall``);
* the share that is no pipeline stage: inside the task (planning, serialising the folder's
  files) and outside it (worker start-up and imports, handing scenes and files between the
  worker and the driver, the driver's writes, idle workers at the end); and the edges of the
  build in wall seconds: when the first scene began, how long workers idled at the end while
  the others finished their last scenes, and what came after the last scene;
* CPU seconds per scene: per stage (recorded by the workers), outside the tasks (start-up,
  IPC, cache upkeep), every worker process together (sampled from ``/proc``) and the driver;
  from the workers' CPU per scene the *idle-equivalent* rate, ``workers x 3600 / CPU per
  scene``: what the build makes when every worker has a core of its own. On a loaded machine
  compare that and the CPU figures, not the wall-clock ones;
* a fresh worker's start-up (imports, scene source, GL context) measured on its own;
* the resident memory of the largest worker after 1, 10, 25, 50, 100, 150, 200 ... scenes, and
  its peak (sampled from ``/proc``). ``--scenes 200 --workers 1`` has one worker build all 200
  (it is replaced after ``--max-tasks`` scenes, 200 by default).

The asset pool is the one under ``$PARSE3D_CACHE``: on an empty cache the first scenes also
generate their assets (run twice to see the cached rate). ``--baseline-rev REV`` builds the
same scenes with the package of git revision REV (a temporary worktree; its own asset cache
folder is the same) and prints both columns; ``--rounds N`` builds them alternately N times
each (now, REV, now, REV, ...) and sums the rounds per column, so that a change in the
machine's load falls on both columns alike.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

from _common import ROOT, revision_tree

STAGES = ("expand", "solve", "settle", "contacts", "render", "write")


def _hours(seconds: float) -> str:
    h = seconds / 3600.0
    return f"{h:,.1f} h" if h < 48 else f"{h / 24:,.1f} days"


def _descendants(pid: int) -> list[int]:
    """Every process below ``pid`` (Linux /proc)."""
    kids: dict[int, list[int]] = {}
    for d in os.listdir("/proc"):
        if not d.isdigit():
            continue
        try:
            with open(f"/proc/{d}/stat") as f:
                ppid = int(f.read().rsplit(")", 1)[1].split()[1])
        except (OSError, IndexError, ValueError):
            continue
        kids.setdefault(ppid, []).append(int(d))
    out, todo = [], [pid]
    while todo:
        for c in kids.get(todo.pop(), []):
            out.append(c)
            todo.append(c)
    return out


def _proc(pid: int) -> tuple[float, float, float]:
    """``(VmRSS MB, VmHWM MB, CPU seconds)`` of a process; zeros when it is gone."""
    rss = hwm = cpu = 0.0
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    rss = int(line.split()[1]) / 1024.0
                elif line.startswith("VmHWM:"):
                    hwm = int(line.split()[1]) / 1024.0
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        cpu = (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime + stime
    except (OSError, IndexError, ValueError):
        pass
    return rss, hwm, cpu


class _Watch:
    """Samples the processes below this one every ``period`` s: the peak resident memory
    (VmHWM) of the largest, the current VmRSS of the largest, and the CPU seconds of each
    (the last sample of a process that ends is kept, so at most ``period`` of it is lost)."""

    def __init__(self, period: float = 0.25):
        self.period, self.peak, self.rss = period, 0.0, 0.0
        self.cpu: dict[int, float] = {}
        self.seen: dict[int, tuple[float, float]] = {}  # pid -> (when sampled, VmRSS MB)
        self._stop = threading.Event()
        self._t = threading.Thread(target=self._run, daemon=True)

    def sample(self) -> None:
        now, t = 0.0, time.perf_counter()
        for p in _descendants(os.getpid()):
            rss, hwm, cpu = _proc(p)
            self.peak, now = max(self.peak, hwm), max(now, rss)
            self.cpu[p] = max(self.cpu.get(p, 0.0), cpu)
            if rss > 0:
                self.seen[p] = (t, rss)
        # a worker that ended since the last sample (replaced after --max-tasks scenes, just
        # after its last one) counts with its last sample
        self.rss = max([now] + [r for w, r in self.seen.values() if t - w <= 2 * self.period])

    def _run(self) -> None:
        while not self._stop.wait(self.period):
            self.sample()

    @property
    def cpu_seconds(self) -> float:
        return sum(self.cpu.values())

    def __enter__(self):
        self._t.start()
        return self

    def __exit__(self, *exc):
        self._stop.set()
        self._t.join()


_STARTUP = """
import json, sys, time
t0 = time.perf_counter()
from parse3d.datagen.build import BuildConfig
from parse3d.datagen import executors
t1 = time.perf_counter()
cfg = BuildConfig(scenes=1, source=tuple(json.loads(sys.argv[1])))
executors._process_state(cfg)
t2 = time.perf_counter()
print(json.dumps({"imports": t1 - t0, "state": t2 - t1}))
"""


def worker_startup(source: tuple[str, ...]) -> dict:
    """A fresh process's imports and per-process state (scene source, renderer), seconds."""
    t = time.perf_counter()
    r = subprocess.run([sys.executable, "-c", _STARTUP, json.dumps(list(source))],
                       capture_output=True, text=True, check=True)
    res = json.loads(r.stdout.strip().splitlines()[-1])
    res["process"] = time.perf_counter() - t
    return res


def measure(args) -> dict:
    """Build the dataset once with this package; the figures as a dict."""
    from parse3d.datagen.build import BuildConfig, build_dataset, resolve_pag_paths
    from parse3d.datagen.manifest import read_manifest

    source = resolve_pag_paths(args.pags) if args.pags else ()
    cfg = BuildConfig(scenes=args.scenes, seed=args.seed, views=args.views, source=source,
                      rooms=tuple(r for r in args.rooms.split(",") if r))
    start = worker_startup(source)
    with tempfile.TemporaryDirectory(prefix="parse3d-bench-") as tmp:
        out = Path(args.out) if args.out else Path(tmp) / "ds"
        if (out / "manifest.parquet").exists():
            raise SystemExit(f"{out} already holds a dataset: pass a fresh --out")
        trace: list[tuple[int, float]] = []  # (scenes done, largest worker's RSS now)
        done_at: list[tuple[float, float]] = []  # (s since the start, the scene's t_total)

        def progress(ev) -> None:
            done_at.append((time.perf_counter() - t0, ev.record.get("t_total") or 0.0))
            if ev.done in marks:
                watch.sample()
                trace.append((ev.done, watch.rss))

        marks = {n for n in (1, 10, 25, 50, 100, 150, 200, 300, 500) if n <= args.scenes}
        marks.add(args.scenes)
        with _Watch() as watch:
            t0, c0 = time.perf_counter(), time.process_time()
            build_dataset(cfg, out, workers=args.workers, max_tasks=args.max_tasks,
                          progress=progress)
            wall, driver = time.perf_counter() - t0, time.process_time() - c0
            watch.sample()
        rows = read_manifest(out / "manifest.parquet")
    keys = ("index", "status", "objects", "placed", "contacts",
            *(f"{p}_{s}" for p in ("t", "cpu") for s in (*STAGES, "total")))
    ends = sorted(t for t, _ in done_at)
    edges = {
        # when the first scene began: the driver's preparation and a worker's start-up
        "first_start": min((t - d for t, d in done_at), default=0.0),
        # worker-seconds idle at the end: each worker's last scene ends before the last one
        "tail_idle": sum(ends[-1] - t for t in ends[-args.workers:]) if ends else 0.0,
        # after the last scene: the last manifest write, stopping the workers
        "after_last": wall - ends[-1] if ends else 0.0,
    }
    return {"wall": wall, "workers": args.workers, "startup": start, "peak_rss_mb": watch.peak,
            "edges": edges,
            "worker_cpu": watch.cpu_seconds, "driver_cpu": driver, "rss_trace": trace,
            "rows": [{k: r.get(k) for k in keys} for r in rows]}


def merge(runs: list[dict]) -> dict:
    """Several runs of the same build as one: walls, CPU and rows summed, the peak the
    largest, start-up and the RSS trace of the first run."""
    if len(runs) == 1:
        return runs[0]
    out = dict(runs[0])
    for k in ("wall", "worker_cpu", "driver_cpu"):
        out[k] = sum(r[k] for r in runs)
    out["peak_rss_mb"] = max(r["peak_rss_mb"] for r in runs)
    out["edges"] = {k: sum(r["edges"][k] for r in runs) for k in runs[0]["edges"]}
    out["rows"] = [row for r in runs for row in r["rows"]]
    out["round_walls"] = [r["wall"] for r in runs]
    out["rounds"] = len(runs)
    return out


def _mean(v: list) -> float | None:
    v = [x for x in v if x is not None]
    return statistics.mean(v) if v else None


def summarize(res: dict) -> dict:
    rows, wall, workers = res["rows"], res["wall"], res["workers"]
    ok = [r for r in rows if r["status"] in ("ok", "incomplete")]
    n = max(1, len(rows))
    budget = wall * workers  # worker-seconds available
    s = {"scenes": len(rows), "ok": sum(r["status"] == "ok" for r in rows),
         "incomplete": sum(r["status"] == "incomplete" for r in rows),
         "failed": sum(r["status"] in ("failed", "timeout") for r in rows),
         "rate": 3600.0 * len(rows) / wall, "wall": wall,
         "placed": statistics.mean(r["placed"] or 0 for r in ok) if ok else 0.0,
         "peak_rss_mb": res["peak_rss_mb"], "startup": res["startup"],
         "rss_trace": dict(res.get("rss_trace") or []), "edges": res.get("edges") or {},
         "round_walls": res.get("round_walls") or [wall]}
    for st in STAGES:
        v = [r[f"t_{st}"] or 0.0 for r in ok] or [0.0]
        s[st] = (statistics.mean(v), statistics.median(v), max(v))
        s[f"share_{st}"] = 100.0 * sum(r[f"t_{st}"] or 0.0 for r in rows) / budget
    tot = [r["t_total"] or 0.0 for r in ok] or [0.0]
    s["total"] = (statistics.mean(tot), statistics.median(tot), max(tot))
    in_task = sum((r["t_total"] or 0.0) - sum(r[f"t_{st}"] or 0.0 for st in STAGES) for r in rows)
    s["share_in_task"] = 100.0 * in_task / budget
    s["share_outside"] = 100.0 * (budget - sum(r["t_total"] or 0.0 for r in rows)) / budget
    # CPU seconds: per stage from the manifest (recorded by the worker), all of it from /proc
    for st in (*STAGES, "total"):
        s[f"cpu_{st}"] = _mean([r.get(f"cpu_{st}") for r in ok])
    cpu = res.get("worker_cpu") or 0.0
    s["cpu_scene"] = cpu / n  # every worker process's CPU, start-up and IPC included
    tasks = sum(r.get("cpu_total") or 0.0 for r in rows)
    s["cpu_outside"] = (cpu - tasks) / n if any(r.get("cpu_total") for r in rows) else None
    s["cpu_driver"] = (res.get("driver_cpu") or 0.0) / n
    # on an idle machine every worker has a core of its own: workers x 3600 / CPU per scene
    s["idle_rate"] = 3600.0 * workers / s["cpu_scene"] if cpu > 0 else 0.0
    return s


def _opt(fmt: str):
    return lambda v: "n/a" if v is None else format(v, fmt)


def print_table(now: dict, before: dict | None, rev: str | None) -> None:
    cols = [("now", summarize(now))] + ([(rev[:10], summarize(before))] if before else [])
    head = f"{'':38s}" + "".join(f"{name:>14s}" for name, _ in cols)
    print(head)

    def line(label: str, fmt, key=None) -> None:
        print(f"{label:38s}" + "".join(f"{fmt(s if key is None else s[key]):>14s}"
                                        for _, s in cols))

    rounds = now.get("rounds", 1)
    if rounds > 1:
        print(f"({rounds} rounds per column, built alternately; scene counts and times are "
              "their sums)")
    line("scenes (ok/incomplete/failed)", lambda s: f"{s['ok']}/{s['incomplete']}/{s['failed']}")
    line("placed objects per scene", lambda v: f"{v:.1f}", "placed")
    line("wall, s", lambda v: f"{v:.1f}", "wall")
    if rounds > 1:
        line("  of each round", lambda v: " ".join(f"{w:.0f}" for w in v), "round_walls")
    line("scenes/hour, wall (goal >= 5,000)", lambda v: f"{v:,.0f}", "rate")
    line("10,000 scenes take, wall", lambda s: _hours(10000 * s["wall"] / max(1, s["scenes"])))
    print("CPU seconds per scene (do not grow with the machine's load)")
    for st in (*STAGES, "total"):
        line(f"  {st}", _opt(".3f"), f"cpu_{st}")
    line("  not a stage: worker outside tasks", _opt(".3f"), "cpu_outside")
    line("  every worker process, all of it", _opt(".3f"), "cpu_scene")
    line("  the driver (commits, manifest)", _opt(".3f"), "cpu_driver")
    line("idle-equivalent scenes/hour", lambda v: f"{v:,.0f}", "idle_rate")
    print("  (workers x 3600 / worker CPU per scene: the rate with a free core per worker)")
    print("wall seconds per scene (mean / median)")
    for st in (*STAGES, "total"):
        line(f"  {st}", lambda v: f"{v[0]:.3f}/{v[1]:.3f}", st)
    print("share of the workers' wall time (workers x wall), %")
    for st in STAGES:
        line(f"  {st}", lambda v: f"{v:.1f}", f"share_{st}")
    line("  not a stage, in the task", lambda v: f"{v:.1f}", "share_in_task")
    line("  not a stage, outside tasks", lambda v: f"{v:.1f}", "share_outside")
    print("start and end of the build, wall seconds")
    line("  first scene began after", lambda e: _opt(".2f")(e.get("first_start")), "edges")
    line("  workers idle at the end, worker-s", lambda e: _opt(".2f")(e.get("tail_idle")),
         "edges")
    line("  after the last scene", lambda e: _opt(".2f")(e.get("after_last")), "edges")
    print("a fresh worker, s")
    line("  imports", lambda v: f"{v['imports']:.2f}", "startup")
    line("  scene source + GL context", lambda v: f"{v['state']:.2f}", "startup")
    line("  whole process", lambda v: f"{v['process']:.2f}", "startup")
    marks = sorted(set().union(*(s["rss_trace"] for _, s in cols)))
    if marks:
        print("largest worker's RSS after n scenes, MB")
        for m in marks:
            line(f"  {m}", lambda s, m=m: _opt(",.0f")(s["rss_trace"].get(m)))
    line("peak worker RSS, MB (goal <= 1536)", lambda v: f"{v:,.0f}", "peak_rss_mb")
    if before:
        a, b = cols[0][1], cols[1][1]
        if a["cpu_scene"] > 0 and b["cpu_scene"] > 0:
            print(f"worker CPU per scene, {rev[:10]} / now: {b['cpu_scene'] / a['cpu_scene']:.2f}x")
        if a["rate"] > 0 and b["rate"] > 0:
            print(f"wall-clock rate, now / {rev[:10]}: {a['rate'] / b['rate']:.2f}x")


def run_json(argv: list[str], src: Path) -> dict:
    """This benchmark run once, in a fresh process, with the package under ``src``."""
    with tempfile.TemporaryDirectory(prefix="parse3d-bench-") as tmp:
        res = Path(tmp) / "result.json"
        env = {**os.environ, "PYTHONPATH": str(src)}
        subprocess.run([sys.executable, __file__, *argv, "--_json", str(res)], check=True,
                       env=env, cwd=str(ROOT))
        return json.loads(res.read_text())


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", type=int, default=40, help="scenes to build (at least 40)")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--views", type=int, default=0, help="views per scene besides the preview")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--rooms", default="", help="comma-separated room types (default: all)")
    ap.add_argument("--pags", nargs="*", default=None,
                    help="PAG files or folders to build from instead of the templates")
    ap.add_argument("--max-tasks", type=int, default=200,
                    help="scenes a worker builds before it is replaced (as parse3d dataset "
                         "build --max-tasks); with --workers 1 and --scenes N <= this, one "
                         "worker builds them all and its RSS is traced")
    ap.add_argument("--out", default=None,
                    help="dataset folder (default: a temporary one); one build only")
    ap.add_argument("--baseline-rev", metavar="REV",
                    help="also build the same scenes with git revision REV, e.g. 4607b75")
    ap.add_argument("--rounds", type=int, default=1,
                    help="with --baseline-rev: build both columns this many times, alternately")
    ap.add_argument("--_json", dest="json_out", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.pags:
        args.pags = [str(Path(p).resolve()) for p in args.pags]
    if args.out and (args.baseline_rev or args.rounds > 1):
        ap.error("--out builds one dataset: leave it out with --baseline-rev or --rounds")
    print(f"building {args.scenes} scenes ({'PAG files' if args.pags else 'templates'}, "
          f"{args.workers} workers, {args.views} views, {os.cpu_count()} CPU cores) ...",
          flush=True)
    if args.scenes < 40 and not args.json_out:
        print("note: the wall-clock rate of fewer than 40 scenes is mostly start-up and tail")
    if args.json_out:  # one column's run, in its own process
        Path(args.json_out).write_text(json.dumps(measure(args)))
        return
    before = None
    if not args.baseline_rev:
        now = merge([measure(args) for _ in range(max(1, args.rounds))])
    else:
        argv = ["--scenes", str(args.scenes), "--workers", str(args.workers),
                "--max-tasks", str(args.max_tasks), "--views",
                str(args.views), "--seed", str(args.seed), "--rooms", args.rooms]
        if args.pags:
            argv += ["--pags", *args.pags]
        runs: dict[str, list[dict]] = {"now": [], "before": []}
        with revision_tree(args.baseline_rev) as wt:
            for r in range(max(1, args.rounds)):
                print(f"round {r + 1}: this build, then {args.baseline_rev}", flush=True)
                runs["now"].append(run_json(argv, ROOT / "src"))
                runs["before"].append(run_json(argv, wt / "src"))
        now, before = merge(runs["now"]), merge(runs["before"])
    print()
    print_table(now, before, args.baseline_rev)


if __name__ == "__main__":
    main()
