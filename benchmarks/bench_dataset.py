"""Dataset throughput: scenes per hour of the whole pipeline, per-stage times, 10k extrapolation.

Usage::

    python benchmarks/bench_dataset.py                      # 24 template scenes, 2 workers
    python benchmarks/bench_dataset.py --scenes 48 --workers 2 --views 2
    python benchmarks/bench_dataset.py --pags examples/     # the example PAGs instead
    python benchmarks/bench_dataset.py --out out/bench      # keep the dataset (default: temp)

Builds ``--scenes`` scenes with the local executor (expand, solve, settle, contacts, render,
write; exactly what ``parse3d dataset build`` runs), then prints the wall-clock throughput,
the per-stage mean and median seconds from the manifest, the share of each stage in the
workers' time, and the time 10,000 scenes would take at the measured rate, on this machine
and per worker core. The first scenes of each worker also pay for generating their assets
(the asset pool is per process), so small runs understate the steady-state rate a little; the
``warm`` line leaves out each worker's first scene.
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time
from pathlib import Path

from parse3d.datagen.build import BuildConfig, build_dataset, resolve_pag_paths
from parse3d.datagen.manifest import read_manifest

STAGES = ("expand", "solve", "settle", "contacts", "render", "write")


def _hours(seconds: float) -> str:
    h = seconds / 3600.0
    return f"{h:,.1f} h" if h < 48 else f"{h / 24:,.1f} days"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", type=int, default=24, help="scenes to build (a few dozen)")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--views", type=int, default=0, help="views per scene besides the preview")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--rooms", default="", help="comma-separated room types (default: all)")
    ap.add_argument("--pags", nargs="*", default=None,
                    help="PAG files or folders to build from instead of the templates")
    ap.add_argument("--out", default=None, help="dataset folder (default: a temporary one)")
    args = ap.parse_args()

    source = resolve_pag_paths(args.pags) if args.pags else ()
    cfg = BuildConfig(scenes=args.scenes, seed=args.seed, views=args.views, source=source,
                      rooms=tuple(r for r in args.rooms.split(",") if r))
    tmp = None
    if args.out is None:
        tmp = tempfile.TemporaryDirectory(prefix="parse3d-bench-")
        out = Path(tmp.name) / "ds"
    else:
        out = Path(args.out)
        if (out / "manifest.parquet").exists():
            raise SystemExit(f"{out} already holds a dataset: pass a fresh --out")
    print(f"building {args.scenes} scenes ({'templates' if not source else 'PAG files'}, "
          f"{args.workers} workers, {args.views} views, {os.cpu_count()} CPU cores) ...",
          flush=True)
    t0 = time.perf_counter()
    report = build_dataset(cfg, out, workers=args.workers)
    wall = time.perf_counter() - t0
    rows = read_manifest(out / "manifest.parquet")
    ok = [r for r in rows if r["status"] == "ok"]

    rate = 3600.0 * len(rows) / wall
    print(f"\n{len(rows)} scenes in {wall:.1f} s: {report.ok} ok, {report.failed} failed, "
          f"{report.timeout} timed out")
    print(f"throughput: {rate:,.0f} scenes/hour with {args.workers} workers "
          f"({rate / args.workers:,.0f} per worker)")
    if ok:
        objs = [r["placed"] for r in ok]
        print(f"scenes: {statistics.mean(objs):.1f} placed objects on average "
              f"(of {statistics.mean(r['objects'] for r in ok):.1f} requested), "
              f"{statistics.mean(r['contacts'] or 0 for r in ok):.1f} part-level contacts")
        print("\nper-stage seconds per scene (ok scenes, in the worker):")
        print(f"  {'stage':<10}{'mean':>9}{'median':>9}{'max':>9}{'share':>8}")
        busy = sum(r["t_total"] for r in ok)
        for st in STAGES:
            v = [r[f"t_{st}"] for r in ok]
            print(f"  {st:<10}{statistics.mean(v):9.3f}{statistics.median(v):9.3f}"
                  f"{max(v):9.3f}{100 * sum(v) / busy:7.1f}%")
        tot = [r["t_total"] for r in ok]
        print(f"  {'total':<10}{statistics.mean(tot):9.3f}{statistics.median(tot):9.3f}"
              f"{max(tot):9.3f}")
        # each worker's first scene also generates assets and loads the vocabulary
        warm = sorted(ok, key=lambda r: r["index"])[args.workers:]
        if warm:
            mean_warm = statistics.mean(r["t_total"] for r in warm)
            print(f"  warm mean (each worker's first scene left out): {mean_warm:.3f} s")
    per_scene = wall / max(1, len(rows))
    print("\nextrapolation to 10,000 scenes (linear in the measured wall time; assumes the "
          "same template mix and no failures beyond those seen):")
    print(f"  this machine, {args.workers} workers: {_hours(10000 * per_scene)}")
    core_s = per_scene * args.workers
    for cores in (16, 64, 256):
        print(f"  {cores} cores (Ray, same per-core speed): {_hours(10000 * core_s / cores)}")
    if tmp is not None:
        tmp.cleanup()
    else:
        print(f"\nkept the dataset in {out}; statistics: parse3d dataset stats {out}")


if __name__ == "__main__":
    main()
