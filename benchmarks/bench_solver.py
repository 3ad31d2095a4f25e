"""Solver speed, its scaling with room size, and the constrained-vs-rejection ablation.

Usage::

    python benchmarks/bench_solver.py [--seeds 3] [--templates 6] [--baseline-rev REV]
                                      [--scaling 10,25,50,100,200,400] [--no-rooms]
                                      [--repeat 1]

Rooms: for each room (the bundled example rooms, a synthetic 50-object office, and some room
templates when they are installed) and seed, it solves with Algorithm 1 (``constrained``) and
with the rejection-sampling baseline on the same PAG and seed, after warm-up solves so that
assets come from the pool (collision data and asset generation are one-time costs, reported
separately). The summary gives placed objects per second over the rooms of >= 40 objects
(goal: >= 500 per core).

Scaling: the tables-and-tabletop room (``_common.tables_room``: dining tables on the floor,
mugs, plates, bowls, bottles and books on their tops, constant floor area per table) at each
size, warm (each seed solved once before it is timed), median over the seeds; then the exponent of a least-squares fit of time against
objects on log-log axes (goal: <= 1.2).

Every solve runs in a warm worker process; with ``--baseline-rev REV`` a second worker runs the
package of git revision REV (from a temporary worktree) on the same PAGs and seeds, in
interleaved rounds, and both columns are printed. Times are process CPU seconds on one core;
``--repeat K`` times each constrained room solve K times per side, alternating, and keeps the
least (a loaded machine adds time, never takes it away).
"""

from __future__ import annotations

import argparse
import statistics
import time

from _common import ROOT, Worker, fit_exponent, revision_tree, serve, tables_room

from parse3d.pag import PAG, Room, load_pag
from parse3d.scenes import bundled_paths


def office_50() -> PAG:
    """A 50-object open office: desks with their setups, chairs, a bookcase of vases."""
    pag = PAG("office-50", Room("office", ((0, 0), (8, 0), (8, 6), (0, 6)), 2.8))
    a, r = pag.add, pag.relate
    for i in range(6):
        a(f"desk{i}", "desk")
        r(f"desk{i}", "ON", "floor")
        a(f"chair{i}", "office_chair")
        r(f"chair{i}", "ON", "floor")
        r(f"chair{i}", "NEAR", f"desk{i}", distance=1.0)
        r(f"chair{i}", "TOWARD", f"desk{i}")
        for k, c in enumerate(["monitor", "keyboard", "mug", "book", "table_lamp"]):
            a(f"d{i}_{k}", c)
            r(f"d{i}_{k}", "ON", f"desk{i}:tabletop")
    a("bookcase", "bookcase")
    r("bookcase", "ON", "floor")
    r("bookcase@back", "AGAINST", "wall_0")
    for k in range(7):
        a(f"b{k}", "book")
        r(f"b{k}", "IN", "bookcase:shelf")
    a("lamp", "pendant_lamp")
    r("lamp", "HANGING_BELOW", "ceiling")
    return pag


def rooms(n_templates: int) -> list[PAG]:
    out = [load_pag(p) for p in bundled_paths()] + [office_50()]
    try:
        from parse3d.datagen.templates import expand_template, list_templates
    except ImportError:
        return out
    templates = list_templates()
    step = max(1, len(templates) // max(n_templates, 1))
    out += [expand_template(t, 0) for t in templates[::step][:n_templates]]
    return out


# ------------------------------------------------------------------ the worker's side
_SEEN: dict[str, float] = {}


def handle(req: dict) -> dict:
    """Solve a PAG (sent as its document) at a seed and strategy; the first request for a
    PAG name first runs ``warm`` solves (seeds 0..warm-1, both strategies) and reports them."""
    from parse3d.solver import SolverConfig, solve

    pag = PAG.from_dict(req["pag"])
    warm = None
    if pag.name not in _SEEN:
        t = time.process_time()
        for seed in range(req.get("warm", 1)):
            for strategy in req.get("strategies", ["constrained"]):
                solve(pag, seed=seed, config=SolverConfig(strategy=strategy), validate=False)
        warm = time.process_time() - t
        _SEEN[pag.name] = warm
    t = time.process_time()
    scene = solve(pag, seed=req["seed"], config=SolverConfig(strategy=req["strategy"]),
                  validate=False)
    cpu = time.process_time() - t
    placed = [o for o in scene.objects.values() if o.placed]
    return {"cpu": cpu, "n": len(scene.objects), "placed": len(placed),
            "trials": sum(o.trials for o in placed) / max(len(placed), 1), "warm": warm}


# ------------------------------------------------------------------ the driver's side
def run_rooms(pags: list[PAG], seeds: int, now: Worker, before: Worker | None,
              repeat: int = 1) -> None:
    strategies = ["constrained", "rejection"]
    cols = f"{'before s':>8s} {'obj/s':>6s} {'placed':>6s} {'speedup':>7s}" if before else ""
    print(f"{'room':28s} {'objs':>4s} | {'ours s':>7s} {'obj/s':>6s} {'placed':>6s} "
          f"{'trials':>6s} | {'rej s':>7s} {'placed':>6s} | {'rej/ours':>8s} | {cols}")
    rows = []
    for pag in pags:
        doc = pag.to_dict()
        warm = {}
        for seed in range(seeds):
            base = dict(pag=doc, seed=seed, warm=seeds, strategies=strategies)
            o = now.ask(**base, strategy="constrained")
            r = now.ask(**base, strategy="rejection")
            b = before.ask(**base, strategy="constrained") if before else None
            for _ in range(repeat - 1):  # the least CPU of the repeats, alternating sides
                o = min(o, {**now.ask(**base, strategy="constrained"), "warm": o["warm"]},
                        key=lambda x: x["cpu"])
                if b is not None and "error" not in b:
                    b = min(b, {**before.ask(**base, strategy="constrained"), "warm": b["warm"]},
                            key=lambda x: x["cpu"])
            if b is not None and "error" in b:  # the other revision cannot solve this room
                print(f"  (before: {pag.name}: {b['error']})")
                b = None
            warm.setdefault("now", o["warm"])
            if b is not None:
                warm.setdefault("before", b["warm"])
            n = o["n"]
            rows.append((pag.name, n, o, r, b))
            line = (f"{pag.name[:28]:28s} {n:4d} | {o['cpu']:7.3f} {o['placed'] / o['cpu']:6.0f} "
                    f"{o['placed'] / n:6.0%} {o['trials']:6.2f} | {r['cpu']:7.3f} "
                    f"{r['placed'] / n:6.0%} | {r['cpu'] / o['cpu']:8.2f} |")
            if b is not None:
                line += (f" {b['cpu']:8.3f} {b['placed'] / b['cpu']:6.0f} {b['placed'] / n:6.0%} "
                         f"{b['cpu'] / o['cpu']:7.2f}")
            print(line, flush=True)
        print(f"{'':28s}      (warm-up: {seeds} seeds x 2 strategies, {warm['now']:.2f} s"
              + (f"; before {warm['before']:.2f} s)" if "before" in warm else ")"))
    print(f"\nsummary over {len(rows)} solves")
    for label, pick in (("all rooms", rows), ("rooms >= 40 objects", [x for x in rows if x[1] >= 40])):
        if not pick:
            continue
        placed = sum(x[2]["placed"] for x in pick)
        cpu = sum(x[2]["cpu"] for x in pick)
        line = (f"  {label:20s} ours: median {statistics.median(x[2]['cpu'] for x in pick):.3f} "
                f"s/scene, {placed / cpu:.0f} placed objects/s, placed "
                f"{placed / sum(x[1] for x in pick):.1%}")
        both = [x for x in pick if x[4] is not None]
        if before and both:
            placed = sum(x[2]["placed"] for x in both)
            cpu = sum(x[2]["cpu"] for x in both)
            pick = both
            bp = sum(x[4]["placed"] for x in pick)
            bc = sum(x[4]["cpu"] for x in pick)
            line += (f" | on the {len(both)} solves both revisions ran: before {bp / bc:.0f} "
                     f"objects/s, placed {bp / sum(x[1] for x in pick):.1%}"
                     f" | speedup x{(placed / cpu) / (bp / bc):.2f}")
        print(line)
    print(f"  rejection: placed {sum(x[3]['placed'] for x in rows) / sum(x[1] for x in rows):.1%}, "
          f"time ratio rejection/constrained "
          f"{sum(x[3]['cpu'] for x in rows) / sum(x[2]['cpu'] for x in rows):.2f}")


def run_scaling(sizes: list[int], seeds: int, now: Worker, before: Worker | None) -> None:
    print(f"\nscaling: tables-and-tabletop room, warm, median of {seeds} seeds (CPU s)")
    print(f"{'objects':>7s} | {'ours s':>8s} {'obj/s':>6s} {'placed':>6s}"
          + (f" | {'before s':>8s} {'obj/s':>6s} {'placed':>6s} {'speedup':>7s}" if before else ""))
    t_now, t_before = [], []
    for n in sizes:
        doc = tables_room(n).to_dict()
        res = {"now": [], "before": []}
        for seed in range(seeds):  # interleaved rounds
            # warm: every seed's solve runs once first (its assets drawn from the pool, their
            # collision data built), as in the rooms above
            res["now"].append(now.ask(pag=doc, seed=seed, strategy="constrained", warm=seeds))
            if before:
                res["before"].append(before.ask(pag=doc, seed=seed, strategy="constrained",
                                                warm=seeds))
        med = {k: (statistics.median(r["cpu"] for r in v),
                   statistics.median(r["placed"] for r in v)) for k, v in res.items() if v}
        t_now.append(med["now"][0])
        line = f"{n:7d} | {med['now'][0]:8.3f} {med['now'][1] / med['now'][0]:6.0f} " \
               f"{med['now'][1] / n:6.0%}"
        if before:
            t_before.append(med["before"][0])
            line += (f" | {med['before'][0]:8.3f} {med['before'][1] / med['before'][0]:6.0f} "
                     f"{med['before'][1] / n:6.0%} {med['before'][0] / med['now'][0]:7.2f}")
        print(line, flush=True)
    if len(sizes) >= 2:
        line = f"fitted exponent (time ~ objects^k): ours k = {fit_exponent(sizes, t_now):.2f}"
        if before:
            line += f", before k = {fit_exponent(sizes, t_before):.2f}"
        print(line + " (goal: <= 1.2)")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--templates", type=int, default=6)
    ap.add_argument("--baseline-rev", metavar="REV",
                    help="also run git revision REV (e.g. 4607b75) side by side")
    ap.add_argument("--scaling", default="10,25,50,100,200,400",
                    help="room sizes of the scaling run (comma-separated; empty: none)")
    ap.add_argument("--no-rooms", action="store_true", help="only the scaling run")
    ap.add_argument("--repeat", type=int, default=1,
                    help="time each constrained room solve this many times per side, "
                         "alternating, and keep the least CPU (less noise under load)")
    ap.add_argument("--_worker", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args._worker:
        serve(handle)
        return
    sizes = [int(x) for x in args.scaling.split(",") if x.strip()]
    with Worker(__file__, src=ROOT / "src") as now:
        if args.baseline_rev:
            with revision_tree(args.baseline_rev) as wt, \
                    Worker(__file__, src=wt / "src", cwd=wt) as before:
                print(f"before: {args.baseline_rev}, now: this tree")
                _run(args, sizes, now, before)
        else:
            _run(args, sizes, now, None)


def _run(args, sizes: list[int], now: Worker, before: Worker | None) -> None:
    if not args.no_rooms:
        run_rooms(rooms(args.templates), args.seeds, now, before, args.repeat)
    if sizes:
        run_scaling(sizes, args.seeds, now, before)


if __name__ == "__main__":
    main()
