"""Placement rate of the solver on the bundled example rooms over many seeds.

Usage::

    python benchmarks/bench_placement.py [--seeds 10] [--search backtracking] [--settle]

Prints, per example room, the objects placed over all seeds, the solves that placed every object,
and (with ``--settle``) the placed objects still carrying a physics flag (fell, tipped,
left_support) after settling and repair, then the totals and the placed objects per CPU second
(of solving, or with ``--settle`` of the whole pipeline).
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from parse3d.pag import load_pag
from parse3d.solver import SolverConfig, solve

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=10)
    ap.add_argument("--search", default=None, help="greedy or backtracking (default: the solver's)")
    ap.add_argument("--settle", action="store_true", help="settle and repair (the full pipeline)")
    args = ap.parse_args()
    cfg = SolverConfig() if args.search is None else SolverConfig(search=args.search)
    print(f"{'room':<16} {'placed':>10} {'complete':>9} {'flagged':>9} {'cpu s':>7}")
    tot_p = tot_n = tot_c = tot_s = tot_u = 0
    cpu_total = 0.0
    for path in sorted(EXAMPLES.glob("*.json")) + sorted(EXAMPLES.glob("*.yaml")):
        pag = load_pag(path)
        placed = n = complete = unstable = 0
        cpu = 0.0
        for seed in range(args.seeds):
            t = time.process_time()
            if args.settle:
                from parse3d.pipeline import PipelineOptions, run_pipeline

                scene = run_pipeline(pag, seed=seed, out=None,
                                     options=PipelineOptions(preview=False, solver=cfg))
                unstable += sum(1 for o in scene.placed
                                if {"fell", "tipped", "left_support"} & set(o.flags))
            else:
                scene = solve(pag, seed=seed, config=cfg)
            cpu += time.process_time() - t
            placed += len(scene.placed)
            n += len(scene.objects)
            complete += int(len(scene.placed) == len(scene.objects))
        print(f"{pag.name:<16} {placed:>4}/{n:<5} {complete:>4}/{args.seeds:<4} "
              f"{unstable if args.settle else '-':>9} {cpu:7.1f}")
        tot_p, tot_n, tot_c, tot_s, tot_u = (tot_p + placed, tot_n + n, tot_c + complete,
                                             tot_s + args.seeds, tot_u + unstable)
        cpu_total += cpu
    print(f"{'total':<16} {tot_p:>4}/{tot_n:<5} {tot_c:>4}/{tot_s:<4} "
          f"{tot_u if args.settle else '-':>9} {cpu_total:7.1f}")
    print(f"objects placed: {100 * tot_p / max(tot_n, 1):.1f}%, complete solves: "
          f"{100 * tot_c / max(tot_s, 1):.1f}%, placed objects per CPU second: "
          f"{tot_p / max(cpu_total, 1e-9):.2f}")


if __name__ == "__main__":
    main()
