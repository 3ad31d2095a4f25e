"""Asset generation and pool-building speed.

Prints, per category, the median time to generate one asset (parts, convex pieces, the six
surfaces of every part, internal surfaces), the overall median, and the time to build a pool of
K assets per category with N worker processes.

Goals: median generation <= 40 ms per asset (issue 16, with >= 10 parts per asset on average); a
pool of 20 per category for every category on 2 workers in < 5 minutes.

    python benchmarks/bench_assets.py                       # full run
    python benchmarks/bench_assets.py --seeds 3 --per-category 2   # quick look
    python benchmarks/bench_assets.py --profile mug         # where the time goes
    python benchmarks/bench_assets.py --stats --seeds 3     # the `assets stats` figures
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import statistics
import tempfile
import time

from parse3d.assets import registry
from parse3d.assets.pool import AssetPool


def bench_generate(categories: list[str], seeds: int) -> dict[str, float]:
    out = {}
    for c in categories:
        ts = []
        for s in range(seeds):
            t = time.perf_counter()
            registry.generate(c, s)
            ts.append(time.perf_counter() - t)
        out[c] = statistics.median(ts)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seeds", type=int, default=5, help="assets per category for the timing")
    ap.add_argument("--per-category", type=int, default=20, help="pool size K (0 skips the pool)")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--categories", default="", help="comma-separated subset")
    ap.add_argument("--profile", default="", help="profile generating this category")
    ap.add_argument("--stats", action="store_true", help="print the library statistics (parts, joints) and stop")
    args = ap.parse_args()
    cats = [c for c in args.categories.split(",") if c] or list(registry.categories())
    if args.stats:
        from parse3d.assets.stats import library_stats

        st = library_stats(cats, seeds=args.seeds).to_dict()
        st.pop("per_category")
        for k, v in st.items():
            print(f"{k:<26}{v}")
        return
    if args.profile:
        pr = cProfile.Profile()
        pr.enable()
        for s in range(args.seeds):
            registry.generate(args.profile, s)
        pr.disable()
        pstats.Stats(pr).sort_stats("cumulative").print_stats(30)
        return
    gen = bench_generate(cats, args.seeds)
    print(f"{'category':<24}{'median ms':>10}")
    for c, t in sorted(gen.items(), key=lambda kv: -kv[1]):
        flag = "" if t <= 0.04 else "  (> 40 ms)"
        print(f"{c:<24}{t * 1e3:>10.1f}{flag}")
    overall = statistics.median(gen.values())
    print(f"{'overall median':<24}{overall * 1e3:>10.1f}   goal <= 40 ms")
    if args.per_category > 0:
        with tempfile.TemporaryDirectory() as tmp:
            pool = AssetPool(tmp, per_category=args.per_category)
            rep = pool.build(cats, workers=args.workers, progress=True)
        n = len(cats) * args.per_category
        est = rep.seconds * 20 / args.per_category
        print(f"pool: {n} assets ({args.per_category} x {len(cats)} categories) on {args.workers} "
              f"workers in {rep.seconds:.1f} s; K = 20 would take ~{est:.0f} s (goal < 300 s)")
        for k, v in rep.failures.items():
            print(f"  failed {k}: {v}")


if __name__ == "__main__":
    main()
