"""Whole-command start-up and the cold first solve, timed as a user runs them.

Usage::

    python benchmarks/bench_startup.py                         # this checkout, 3 rounds
    python benchmarks/bench_startup.py --baseline-rev 4607b75  # and REV, rounds interleaved
    python benchmarks/bench_startup.py --no-cold               # warm commands only (quick)

Prints medians of wall-clock seconds over ``--rounds`` rounds, one column per package:

* ``parse3d validate examples/study.json`` (goal <= 0.7 s);
* ``parse3d solve examples/kitchen.json --no-settle --no-preview`` (26 objects) with its assets
  cached (goal <= 1.2 s);
* the same solve on an empty asset cache (cold), next to the warm solve plus the time the
  assets it needs take to generate on their own: the cold run should cost at most 2x that sum;
* ``parse3d --help``.

Then the same figures in CPU seconds (user + system of each command's process, and of the
generation alone), which other processes' load inflates far less than wall-clock seconds. With
a baseline, a last column gives now / baseline.

Every command runs in a fresh process (``python -m parse3d``), so start-up, imports and the
asset cache are all in the figures. ``--baseline-rev REV`` checks REV out into a temporary git
worktree and alternates its commands with this checkout's in every round, so both columns see
the same machine load. Each package gets its own warm asset cache (a temporary folder).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
VALIDATE_PAG = ROOT / "examples" / "study.json"
SOLVE_PAG = ROOT / "examples" / "kitchen.json"

_GENERATE = """
import json, sys, time
from pathlib import Path
from parse3d.assets.pool import AssetPool
from parse3d.assets.registry import categories
categories()  # the registry's discovery is start-up, not generation
pool = AssetPool(root=sys.argv[1])
t, c = time.perf_counter(), time.process_time()
for cat, seed in json.loads(sys.argv[2]):
    pool.load(cat, seed)
print(json.dumps({"seconds": time.perf_counter() - t, "cpu": time.process_time() - c}))
"""


def _cpu() -> float:
    """CPU seconds (user + system) of the finished child processes so far."""
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    return ru.ru_utime + ru.ru_stime


def _run(src: Path, args: list[str], cache: Path, cwd: Path) -> tuple[float, float]:
    """Wall and CPU seconds of one ``parse3d`` command in a fresh process."""
    env = {**os.environ, "PYTHONPATH": str(src), "PARSE3D_CACHE": str(cache)}
    c = _cpu()
    t = time.perf_counter()
    r = subprocess.run([sys.executable, "-m", "parse3d", *args], env=env, cwd=str(cwd),
                       capture_output=True, text=True)
    dt = time.perf_counter() - t
    if r.returncode not in (0, 3):
        raise SystemExit(f"parse3d {' '.join(args)} failed ({r.returncode}):\n{r.stderr[-2000:]}")
    return dt, _cpu() - c


def _pool_slots(cache: Path) -> list[tuple[str, int]]:
    """(category, seed) of every asset in a cache's pool."""
    pool = cache / "pool"
    return sorted((p.parent.name, int(p.name.split("-", 1)[0])) for p in pool.glob("*/*.npz"))


def _generation(src: Path, slots: list[tuple[str, int]], tmp: Path) -> tuple[float, float]:
    root = tmp / "gen-pool"
    shutil.rmtree(root, ignore_errors=True)
    env = {**os.environ, "PYTHONPATH": str(src), "PARSE3D_CACHE": str(tmp / "gen-cache")}
    r = subprocess.run([sys.executable, "-c", _GENERATE, str(root), json.dumps(slots)],
                       env=env, capture_output=True, text=True, check=True)
    got = json.loads(r.stdout.strip().splitlines()[-1])
    return got["seconds"], got["cpu"]


class Side:
    """One package (this checkout or a baseline worktree) and its caches."""

    def __init__(self, label: str, src: Path, tmp: Path, cold: bool = True):
        self.label, self.src, self.tmp, self.cold = label, src, tmp / label, cold
        self.tmp.mkdir(parents=True)
        self.warm = self.tmp / "cache-warm"
        self.times: dict[str, list[float]] = {}

    def add(self, key: str, value: float | tuple[float, float]) -> None:
        """Record a figure; a (wall, CPU) pair also records ``key_cpu``."""
        if isinstance(value, tuple):
            self.times.setdefault(f"{key}_cpu", []).append(value[1])
            value = value[0]
        self.times.setdefault(key, []).append(value)

    def prepare(self) -> None:
        """Fill the warm cache (assets, vocabulary) with one untimed run of each command."""
        _run(self.src, ["validate", str(VALIDATE_PAG)], self.warm, self.tmp)
        _run(self.src, ["solve", str(SOLVE_PAG), "--no-settle", "--no-preview", "--out",
                        str(self.tmp / "out")], self.warm, self.tmp)

    def round(self, k: int) -> None:
        out = str(self.tmp / "out")
        self.add("help", _run(self.src, ["--help"], self.warm, self.tmp))
        self.add("validate", _run(self.src, ["validate", str(VALIDATE_PAG)], self.warm, self.tmp))
        self.add("solve", _run(self.src, ["solve", str(SOLVE_PAG), "--no-settle", "--no-preview",
                                          "--out", out], self.warm, self.tmp))
        if not self.cold:
            return
        cold = self.tmp / f"cache-cold-{k}"
        self.add("cold", _run(self.src, ["solve", str(SOLVE_PAG), "--no-settle", "--no-preview",
                                         "--out", out], cold, self.tmp))
        self.add("generation", _generation(self.src, _pool_slots(cold), self.tmp))
        self.add("assets", float(len(_pool_slots(cold))))
        shutil.rmtree(cold, ignore_errors=True)

    def summary(self) -> dict[str, float]:
        s = {k: statistics.median(v) for k, v in self.times.items()}
        if self.cold:
            s["cold_ratio"] = s["cold"] / (s["solve"] + s["generation"])
            s["cold_ratio_cpu"] = s["cold_cpu"] / (s["solve_cpu"] + s["generation_cpu"])
        return s


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--baseline-rev", metavar="REV",
                    help="also time git revision REV (e.g. 4607b75), rounds interleaved")
    ap.add_argument("--no-cold", dest="cold", action="store_false",
                    help="skip the solves on an empty asset cache (the slow part)")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="parse3d-startup-") as d:
        tmp = Path(d)
        sides = [Side("now", ROOT / "src", tmp, args.cold)]
        wt = None
        if args.baseline_rev:
            wt = tmp / "tree"
            subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(wt),
                            args.baseline_rev], check=True, capture_output=True)
            sides.append(Side(args.baseline_rev[:10], wt / "src", tmp, args.cold))
        try:
            for s in sides:
                s.prepare()
            for k in range(args.rounds):
                for s in sides if k % 2 == 0 else sides[::-1]:
                    s.round(k)
                print(f"round {k + 1}/{args.rounds} done", file=sys.stderr, flush=True)
        finally:
            if wt is not None:
                subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(wt)],
                               check=False, capture_output=True)
        res = [(s.label, s.summary()) for s in sides]
    print(f"wall-clock seconds, median of {args.rounds} rounds ({os.cpu_count()} CPU cores)")
    print(f"{'':48s}" + "".join(f"{label:>12s}" for label, _ in res)
          + (f"{'ratio':>11s}" if len(res) > 1 else ""))
    rows = [("parse3d --help", "help", "{:.2f}"),
            ("parse3d validate study.json (goal <= 0.7)", "validate", "{:.2f}"),
            ("solve kitchen, 26 objects, cached (goal <= 1.2)", "solve", "{:.2f}"),
            ("solve kitchen on an empty asset cache", "cold", "{:.2f}"),
            ("  assets it generates", "assets", "{:.0f}"),
            ("  their generation alone", "generation", "{:.2f}"),
            ("  cold / (cached + generation) (goal <= 2)", "cold_ratio", "{:.2f}")]
    _table(res, rows)
    # CPU seconds do not grow with other processes' load the way wall-clock seconds do
    print(f"\nCPU seconds (user + system) of the same commands, median of {args.rounds} rounds")
    _table(res, [("parse3d --help", "help_cpu", "{:.2f}"),
                 ("parse3d validate study.json", "validate_cpu", "{:.2f}"),
                 ("solve kitchen, cached", "solve_cpu", "{:.2f}"),
                 ("solve kitchen on an empty asset cache", "cold_cpu", "{:.2f}"),
                 ("  their generation alone", "generation_cpu", "{:.2f}"),
                 ("  cold / (cached + generation)", "cold_ratio_cpu", "{:.2f}")])


def _table(res: list[tuple[str, dict[str, float]]], rows: list[tuple[str, str, str]]) -> None:
    for title, key, fmt in rows:
        if key not in res[0][1]:
            continue
        cells = "".join(f"{fmt.format(s[key]):>12s}" for _, s in res)
        ratio = f"{res[0][1][key] / res[1][1][key]:>10.2f}x" if len(res) > 1 and res[1][1][key] \
            and key not in ("assets",) and not key.startswith("cold_ratio") else ""
        print(f"{title:48s}{cells}{ratio}")


if __name__ == "__main__":
    main()
