"""The settle-and-repair stage of given rooms: CPU, outcome, and whether the repair budget
changed the outcome.

Usage::

    python benchmarks/bench_repairs.py tests/data/foreign-third/breakfast-table.json --seeds 2
    python benchmarks/bench_repairs.py ROOM.json ... --seeds 2 --baseline-rev c73f174

Each room is solved once per seed, then ``settle_and_repair`` runs on a copy with the default
budget (``REPAIR_BUDGET`` CPU seconds) and on a copy with none. Printed per solve: CPU seconds
of each run (with the budget, without), the objects failed after repairs (with the budget), and whether the two runs ended alike (same
status, flags and repairs per object): "budget" marks a solve whose result depended on the
machine's speed. With ``--baseline-rev REV`` the package of REV runs the same solves in a second
worker, taking turns with this one, and its figures are printed beside these.
"""

from __future__ import annotations

import argparse
import contextlib
import sys
from pathlib import Path

from _common import ROOT, Worker, revision_tree, serve


def _handle(req: dict) -> dict:
    import copy
    import time

    from parse3d.pag.io import load_pag
    from parse3d.pipeline import REPAIR_BUDGET, settle_and_repair
    from parse3d.solver import solve

    scene = solve(load_pag(req["room"]), seed=int(req["seed"]))
    out = {}
    for name, budget in (("budget", REPAIR_BUDGET), ("free", None)):
        s = copy.deepcopy(scene)
        c0 = time.process_time()
        settle_and_repair(s, budget=budget)
        cpu = time.process_time() - c0
        out[name] = {"cpu": cpu,
                     "failed": sorted(o.id for o in s.objects.values() if not o.placed
                                      and (o.reason or "").startswith("unstable")),
                     "objects": {o.id: [o.status, sorted(o.flags), [str(r) for r in o.repairs]]
                                 for o in s.objects.values()}}
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rooms", nargs="*", help="PAG files")
    ap.add_argument("--seeds", type=int, default=2, help="seeds 0..N-1 (default 2)")
    ap.add_argument("--baseline-rev", metavar="REV", help="also run git revision REV")
    ap.add_argument("--_worker", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args._worker:
        serve(_handle)
        return
    if not args.rooms:
        ap.error("give at least one PAG file")
    with revision_tree(args.baseline_rev) if args.baseline_rev else contextlib.nullcontext() as wt:
        workers = {"now": Worker(__file__, src=ROOT / "src")}
        if wt is not None:
            workers[args.baseline_rev] = Worker(__file__, src=wt / "src")
        names = list(workers)
        print(f"{'room':<34} {'seed':>4}  " + "  ".join(
            f"{n[:7] + ' CPU s':>15} {'failed after repairs':<24}" for n in names))
        print(f"{'':<34} {'':>4}  " + "  ".join(f"{'budget':>7} {'none':>7} {'':<24}"
                                                 for n in names))
        total = dict.fromkeys(names, 0.0)
        for room in args.rooms:
            for seed in range(args.seeds):
                cells = []
                for n, w in workers.items():
                    r = w.ask(room=str(Path(room).resolve()), seed=seed)
                    if "error" in r:
                        sys.exit(f"{n}: {room} seed {seed}: {r['error']}")
                    b, f = r["budget"], r["free"]
                    total[n] += b["cpu"]
                    mark = "" if b["objects"] == f["objects"] else " (budget)"
                    cells.append(f"{b['cpu']:>7.2f} {f['cpu']:>7.2f} "
                                 f"{(', '.join(b['failed']) or '-') + mark:<24}")
                print(f"{Path(room).stem:<34} {seed:>4}  " + "  ".join(cells), flush=True)
        for w in workers.values():
            w.close()
    print("total CPU s: " + ", ".join(f"{n} {total[n]:.2f}" for n in names))


if __name__ == "__main__":
    main()
