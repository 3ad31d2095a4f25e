"""Dataset throughput: scenes per hour of the whole pipeline, per-stage times, where the rest goes.

Usage::

    python benchmarks/bench_dataset.py                      # 40 template scenes, 2 workers
    python benchmarks/bench_dataset.py --scenes 48 --workers 2 --views 2
    python benchmarks/bench_dataset.py --pags examples/     # the example PAGs instead
    python benchmarks/bench_dataset.py --baseline-rev 4607b75   # also the same build at REV
    python benchmarks/bench_dataset.py --scenes 200 --workers 1 # a worker's RSS after 200 scenes

Builds ``--scenes`` scenes with the local executor (expand, solve, settle, contacts, render,
write; exactly what ``parse3d dataset build`` runs), then prints:

* the wall-clock throughput and the time 10,000 scenes would take at that rate;
* per-stage mean, median and max seconds from the manifest, and each stage's share of the
  workers' time (``workers x wall``);
* the share that is no pipeline stage: inside the task (planning, serialising the folder's
  files) and outside it (worker start-up and imports, handing scenes and files between the
  worker and the driver, the driver's writes, idle workers at the end);
* a fresh worker's start-up (imports, scene source, GL context) measured on its own;
* the peak resident memory of the largest worker process (sampled from ``/proc``).

The asset pool is the one under ``$PARSE3D_CACHE``: on an empty cache the first scenes also
generate their assets (run twice to see the cached rate). ``--baseline-rev REV`` builds the
same scenes with the package of git revision REV (a temporary worktree; its own asset cache
folder is the same) and prints both columns.
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


def _hwm_mb(pid: int) -> float:
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024.0
    except OSError:
        pass
    return 0.0


class _RssWatch:
    """Samples the peak RSS (VmHWM) of this process's descendants every ``period`` s."""

    def __init__(self, period: float = 0.5):
        self.period, self.peak = period, 0.0
        self._stop = threading.Event()
        self._t = threading.Thread(target=self._run, daemon=True)

    def _run(self) -> None:
        while not self._stop.wait(self.period):
            for p in _descendants(os.getpid()):
                self.peak = max(self.peak, _hwm_mb(p))

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
        with _RssWatch() as rss:
            t0 = time.perf_counter()
            build_dataset(cfg, out, workers=args.workers)
            wall = time.perf_counter() - t0
        rows = read_manifest(out / "manifest.parquet")
    return {"wall": wall, "workers": args.workers, "startup": start, "peak_rss_mb": rss.peak,
            "rows": [{k: r[k] for k in ("index", "status", "objects", "placed", "contacts",
                                        *(f"t_{s}" for s in STAGES), "t_total")} for r in rows]}


def summarize(res: dict) -> dict:
    rows, wall, workers = res["rows"], res["wall"], res["workers"]
    ok = [r for r in rows if r["status"] in ("ok", "incomplete")]
    budget = wall * workers  # worker-seconds available
    s = {"scenes": len(rows), "ok": sum(r["status"] == "ok" for r in rows),
         "incomplete": sum(r["status"] == "incomplete" for r in rows),
         "failed": sum(r["status"] in ("failed", "timeout") for r in rows),
         "rate": 3600.0 * len(rows) / wall, "wall": wall,
         "placed": statistics.mean(r["placed"] or 0 for r in ok) if ok else 0.0,
         "peak_rss_mb": res["peak_rss_mb"], "startup": res["startup"]}
    for st in STAGES:
        v = [r[f"t_{st}"] or 0.0 for r in ok] or [0.0]
        s[st] = (statistics.mean(v), statistics.median(v), max(v))
        s[f"share_{st}"] = 100.0 * sum(r[f"t_{st}"] or 0.0 for r in rows) / budget
    tot = [r["t_total"] or 0.0 for r in ok] or [0.0]
    s["total"] = (statistics.mean(tot), statistics.median(tot), max(tot))
    in_task = sum((r["t_total"] or 0.0) - sum(r[f"t_{st}"] or 0.0 for st in STAGES) for r in rows)
    s["share_in_task"] = 100.0 * in_task / budget
    s["share_outside"] = 100.0 * (budget - sum(r["t_total"] or 0.0 for r in rows)) / budget
    return s


def print_table(now: dict, before: dict | None, rev: str | None) -> None:
    cols = [("now", summarize(now))] + ([(rev[:10], summarize(before))] if before else [])
    head = f"{'':34s}" + "".join(f"{name:>14s}" for name, _ in cols)
    print(head)

    def line(label: str, fmt, key=None) -> None:
        print(f"{label:34s}" + "".join(f"{fmt(s if key is None else s[key]):>14s}"
                                        for _, s in cols))

    line("scenes (ok/incomplete/failed)", lambda s: f"{s['ok']}/{s['incomplete']}/{s['failed']}")
    line("placed objects per scene", lambda v: f"{v:.1f}", "placed")
    line("wall, s", lambda v: f"{v:.1f}", "wall")
    line("scenes/hour (goal >= 5,000)", lambda v: f"{v:,.0f}", "rate")
    line("10,000 scenes take", lambda s: _hours(10000 * s["wall"] / max(1, s["scenes"])))
    print("per scene, s (mean / median)")
    for st in (*STAGES, "total"):
        line(f"  {st}", lambda v: f"{v[0]:.3f}/{v[1]:.3f}", st)
    print("share of the workers' time (workers x wall), %")
    for st in STAGES:
        line(f"  {st}", lambda v: f"{v:.1f}", f"share_{st}")
    line("  not a stage, in the task", lambda v: f"{v:.1f}", "share_in_task")
    line("  not a stage, outside tasks", lambda v: f"{v:.1f}", "share_outside")
    print("a fresh worker, s")
    line("  imports", lambda v: f"{v['imports']:.2f}", "startup")
    line("  scene source + GL context", lambda v: f"{v['state']:.2f}", "startup")
    line("  whole process", lambda v: f"{v['process']:.2f}", "startup")
    line("peak worker RSS, MB (goal <= 1536)", lambda v: f"{v:,.0f}", "peak_rss_mb")


def baseline(rev: str, argv: list[str]) -> dict:
    """This benchmark run with the package of ``rev`` (a temporary git worktree)."""
    with revision_tree(rev) as wt:
        res = wt.parent / "result.json"
        env = {**os.environ, "PYTHONPATH": str(wt / "src")}
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
    ap.add_argument("--out", default=None, help="dataset folder (default: a temporary one)")
    ap.add_argument("--baseline-rev", metavar="REV",
                    help="also build the same scenes with git revision REV, e.g. 4607b75")
    ap.add_argument("--_json", dest="json_out", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.pags:
        args.pags = [str(Path(p).resolve()) for p in args.pags]
    print(f"building {args.scenes} scenes ({'PAG files' if args.pags else 'templates'}, "
          f"{args.workers} workers, {args.views} views, {os.cpu_count()} CPU cores) ...",
          flush=True)
    now = measure(args)
    if args.json_out:  # the baseline's side
        Path(args.json_out).write_text(json.dumps(now))
        return
    before = None
    if args.baseline_rev:
        argv = ["--scenes", str(args.scenes), "--workers", str(args.workers), "--views",
                str(args.views), "--seed", str(args.seed), "--rooms", args.rooms]
        if args.pags:
            argv += ["--pags", *args.pags]
        before = baseline(args.baseline_rev, argv)
    print()
    print_table(now, before, args.baseline_rev)


if __name__ == "__main__":
    main()
