"""Solver speed and the constrained-vs-rejection ablation, measured side by side.

Usage::

    python benchmarks/bench_solver.py [--seeds 3] [--templates 6]

For each room (the bundled example rooms, a synthetic 50-object office, and some room templates
when they are installed) and seed, it solves with Algorithm 1 (``constrained``) and with the
rejection-sampling baseline on the same PAG and seed, after one warm-up solve so that assets come
from the pool (collision data and asset generation are one-time costs, reported separately).
Times are process CPU seconds on one core.
"""

from __future__ import annotations

import argparse
import statistics
import time

from parse3d.pag import PAG, Room, load_pag
from parse3d.scenes import bundled_paths
from parse3d.solver import SolverConfig, solve


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


def run(pag: PAG, seed: int, strategy: str) -> tuple[float, object]:
    t = time.process_time()
    scene = solve(pag, seed=seed, config=SolverConfig(strategy=strategy), validate=False)
    return time.process_time() - t, scene


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--templates", type=int, default=6)
    args = ap.parse_args()
    pags = rooms(args.templates)
    print(f"{'room':32s} {'objs':>4s} | {'ours s':>7s} {'obj/s':>6s} {'placed':>6s} {'trials':>6s} | "
          f"{'rej s':>7s} {'placed':>6s} {'trials':>6s} | {'time ratio':>10s}")
    rows = []
    for pag in pags:
        t0 = time.process_time()
        for seed in range(args.seeds):  # warm-up: assets into the pool and memory
            for strategy in ("constrained", "rejection"):
                run(pag, seed, strategy)
        warm = (time.process_time() - t0) / (2 * args.seeds)
        for seed in range(args.seeds):
            to, so = run(pag, seed, "constrained")
            tr, sr = run(pag, seed, "rejection")
            n = len(so.objects)
            po, pr = len(so.placed), len(sr.placed)
            tro = sum(o.trials for o in so.placed) / max(po, 1)
            trr = sum(o.trials for o in sr.placed) / max(pr, 1)
            rows.append((pag.name, n, to, po, tro, tr, pr, trr))
            print(f"{pag.name[:32]:32s} {n:4d} | {to:7.3f} {po / to:6.0f} {po / n:6.0%} {tro:6.2f} | "
                  f"{tr:7.3f} {pr / n:6.0%} {trr:6.2f} | {tr / to:10.2f}")
        print(f"{'':32s}      (cold solves, assets loaded or generated: {warm:.2f} s on average)")
    big = [r for r in rows if r[1] >= 40]
    print("\nsummary over", len(rows), "solves")
    print(f"  constrained: median {statistics.median(r[2] for r in rows):.3f} s/scene, "
          f"{sum(r[3] for r in rows) / sum(r[2] for r in rows):.0f} placed objects/s, "
          f"success {sum(r[3] for r in rows) / sum(r[1] for r in rows):.1%}, "
          f"{sum(r[4] * r[3] for r in rows) / max(sum(r[3] for r in rows), 1):.2f} trials/placed object")
    print(f"  rejection:   median {statistics.median(r[5] for r in rows):.3f} s/scene, "
          f"success {sum(r[6] for r in rows) / sum(r[1] for r in rows):.1%}, "
          f"{sum(r[7] * r[6] for r in rows) / max(sum(r[6] for r in rows), 1):.2f} trials/placed object")
    if big:
        print(f"  rooms with >= 40 objects: median {statistics.median(r[2] for r in big):.3f} s/scene, "
              f"{sum(r[3] for r in big) / sum(r[2] for r in big):.0f} objects/s")
    print(f"  time ratio rejection/constrained: {sum(r[5] for r in rows) / sum(r[2] for r in rows):.2f}")


if __name__ == "__main__":
    main()
