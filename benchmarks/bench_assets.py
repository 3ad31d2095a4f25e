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
    python benchmarks/bench_assets.py --seeds 2 --per-category 0 --baseline-rev c5b3064
    python benchmarks/bench_assets.py --release main --seeds 2   # the library beside a release

``--release REV`` prints the library's figures beside those of git revision REV, both measured
in this run (REV from a temporary worktree, in its own process): ScanNet200 object labels that
resolve to a category (a release without the vocabulary file understands a label only when it
is a category's name, spaces as underscores), categories, parts per asset (mean, median, p10),
articulated categories and the median generation time per asset.

``--baseline-rev REV`` times the same generation with the package of git revision REV beside
this one: each revision runs in its own long-lived process and the two take turns, a round
each, so a busy machine slows both alike; the table then gives both medians and their ratio
(categories REV lacks are left out of the comparison). ``--cpu`` times by the process's CPU
time instead of the wall clock: steadier when other work shares the machine.
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _common import Worker, revision_tree, serve  # noqa: E402

from parse3d.assets import registry  # noqa: E402
from parse3d.assets.pool import AssetPool  # noqa: E402


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


def _summary(req: dict) -> dict:
    """The worker's side of ``--release``: this revision's library figures."""
    from parse3d.assets.stats import library_stats

    st = library_stats(seeds=req["seeds"]).to_dict()
    cats = set(registry.categories())
    try:
        from parse3d.words import Resolver

        words = Resolver(registry.vocabulary())

        def understood(label: str) -> bool:
            return bool(words.categories_for(label))
    except ImportError:  # a release before the vocabulary file: category names only
        def understood(label: str) -> bool:
            return label.replace(" ", "_") in cats
    return {"labels_resolved": sum(map(understood, req["labels"])),
            "categories": st["categories"], "parts_mean": st["parts_per_asset_mean"],
            "parts_median": st["parts_per_asset_median"], "parts_p10": st["parts_per_asset_p10"],
            "articulated": len(st["articulated_categories"]),
            "generation_ms_median": st["generation_ms_median"]}


def compare_release(rev: str, seeds: int) -> None:
    """Print this library's figures beside revision ``rev``'s, both measured now."""
    from parse3d.words import reference_labels

    ref = reference_labels()
    labels = [x["label"] for x in ref["labels"] if x["label"] not in ref["excluded"]]
    here = Path(__file__).resolve()
    with revision_tree(rev) as wt, Worker(here) as now_w, \
            Worker(here, src=wt / "src", cwd=wt) as base_w:
        base = base_w.ask(summary=True, seeds=seeds, labels=labels)
        now = now_w.ask(summary=True, seeds=seeds, labels=labels)
    n = len(labels)
    rows = [("ScanNet200 object labels resolved", lambda d: f"{d['labels_resolved']}/{n} "
             f"({d['labels_resolved'] / n:.0%})", "goal >= 95%"),
            ("categories", lambda d: str(d["categories"]), "paper 132"),
            ("parts per asset, mean", lambda d: f"{d['parts_mean']:.1f}", "paper 17.4"),
            ("parts per asset, median", lambda d: f"{d['parts_median']:.0f}", ""),
            ("parts per asset, p10", lambda d: f"{d['parts_p10']:.0f}", "goal >= 6"),
            ("articulated categories", lambda d: str(d["articulated"]), ""),
            ("generation ms per asset, median", lambda d: f"{d['generation_ms_median']:.1f}",
             "goal <= 40")]
    print(f"{'measure':<36}{rev:>16}{'now':>16}   ({seeds} assets per category)")
    for name, fmt, goal in rows:
        print(f"{name:<36}{fmt(base):>16}{fmt(now):>16}   {goal}")


def _handle(req: dict) -> dict:
    """The worker's side of ``--baseline-rev`` (time one round over the categories asked) and
    of ``--release``."""
    if req.get("summary"):
        return _summary(req)
    if req.get("categories") is None:
        return {"categories": list(registry.categories())}
    out: dict[str, list[float]] = {}
    clock = time.process_time if req.get("cpu") else time.perf_counter
    for c in req["categories"]:
        try:
            ts = []
            for s in range(req["seeds"]):
                t = clock()
                registry.generate(c, s)
                ts.append(clock() - t)
            out[c] = ts
        except Exception:  # noqa: BLE001 - a category this revision cannot generate
            continue
    return {"times": out}


def compare_revisions(cats: list[str], seeds: int, rev: str, rounds: int, cpu: bool = False) -> None:
    """Time generation here and at ``rev`` in alternating rounds; print medians and ratios."""
    here = Path(__file__).resolve()
    with revision_tree(rev) as wt, Worker(here) as now_w, \
            Worker(here, src=wt / "src", cwd=wt) as base_w:
        base_cats = set(base_w.ask(categories=None)["categories"])
        common = [c for c in cats if c in base_cats]
        warm = {"categories": common, "seeds": 1}
        now_w.ask(**warm)
        base_w.ask(**warm)  # imports and first-use caches out of the timing
        times: dict[str, dict[str, list[float]]] = {"now": {}, "base": {}}
        for r in range(rounds):
            for side, w in (("base", base_w), ("now", now_w)) if r % 2 else (("now", now_w), ("base", base_w)):
                for c, ts in w.ask(categories=common, seeds=seeds, cpu=cpu)["times"].items():
                    times[side].setdefault(c, []).extend(ts)
    both = [c for c in common if c in times["now"] and c in times["base"]]
    med = {side: {c: statistics.median(times[side][c]) for c in both} for side in times}
    print(f"{'category':<24}{rev + ' ms':>12}{'now ms':>10}{'ratio':>8}")
    for c in sorted(both, key=lambda c: -med["now"][c]):
        b, n = med["base"][c], med["now"][c]
        print(f"{c:<24}{b * 1e3:>12.1f}{n * 1e3:>10.1f}{n / b:>8.2f}")
    b_all = statistics.median(med["base"].values())
    n_all = statistics.median(med["now"].values())
    print(f"{'overall median':<24}{b_all * 1e3:>12.1f}{n_all * 1e3:>10.1f}{n_all / b_all:>8.2f}"
          f"   ({len(both)} categories both revisions have; goal <= 40 ms)")
    left = sorted(set(cats) - set(both))
    if left:
        print(f"left out (not in {rev}): {', '.join(left)}")


def main() -> None:
    if "--_worker" in sys.argv:
        serve(_handle)
        return
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seeds", type=int, default=5, help="assets per category for the timing")
    ap.add_argument("--per-category", type=int, default=20, help="pool size K (0 skips the pool)")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--categories", default="", help="comma-separated subset")
    ap.add_argument("--profile", default="", help="profile generating this category")
    ap.add_argument("--stats", action="store_true", help="print the library statistics (parts, joints) and stop")
    ap.add_argument("--baseline-rev", metavar="REV",
                    help="also time git revision REV, alternating rounds with this one")
    ap.add_argument("--rounds", type=int, default=2, help="alternating rounds per revision (--baseline-rev)")
    ap.add_argument("--release", metavar="REV",
                    help="print the library's figures beside git revision REV's (e.g. main) and stop")
    ap.add_argument("--cpu", action="store_true",
                    help="time by process CPU time instead of wall-clock (steadier on a busy machine)")
    args = ap.parse_args()
    cats = [c for c in args.categories.split(",") if c] or list(registry.categories())
    if args.release:
        compare_release(args.release, args.seeds)
        return
    if args.baseline_rev:
        compare_revisions(cats, args.seeds, args.baseline_rev, args.rounds, args.cpu)
        if args.per_category <= 0:
            return
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
