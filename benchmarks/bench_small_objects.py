"""Template dataset scenes whose small objects failed or fell: re-solved and settled, how many
are complete.

Usage::

    python benchmarks/bench_small_objects.py                         # the default scenes
    python benchmarks/bench_small_objects.py --baseline-rev main     # side by side with REV
    python benchmarks/bench_small_objects.py --index 45,96 --scenes 200 --seed 0

Plans each scene as ``parse3d dataset build --scenes N --seed S`` (templates) does, solves it
at its seed and runs the settle-verify-repair rounds (the dataset's solve and settle stages).
The default indices are those of a 200-scene build at seed 0 that were incomplete for a small
object: sheet music on a music stand's ledge, books stacked on books, bread on a board, bottles
on a bathtub, an apple in a footed bowl, robes on a hook rail, a wine rack on a cabinet and
bottles in its cradle, magazines on magazines, a tissue box on a crowded shelf. With
``--baseline-rev REV`` a second worker runs REV's package on the same scenes, in turn.
"""

from __future__ import annotations

import argparse
import contextlib
import sys
import time

from _common import ROOT, Worker, revision_tree, serve

DEFAULT = (45, 96, 181, 198, 19, 47, 151, 91, 126, 177, 118, 58, 109, 74, 142, 120, 75)


def _handle(req: dict) -> dict:
    from parse3d.datagen.build import BuildConfig
    from parse3d.datagen.planning import plan_scene
    from parse3d.datagen.sources import make_source
    from parse3d.pipeline import PipelineOptions, run_pipeline

    cfg = BuildConfig(scenes=int(req["scenes"]), seed=int(req["seed"]))
    source = make_source(cfg)
    plan = plan_scene(cfg, source, int(req["index"]))
    pag = source.make_pag(plan.template, plan.seed)
    c0 = time.process_time()
    scene = run_pipeline(pag, seed=plan.seed, out=None,
                         options=PipelineOptions(settle=True, preview=False))
    failed = [f"{o.id}: {o.reason}" for o in scene.failed]
    return {"cpu": time.process_time() - c0, "template": plan.template,
            "objects": len(scene.objects), "failed": failed,
            "repaired": (scene.meta.get("repair") or {}).get("repaired", 0)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--index", default=",".join(map(str, DEFAULT)),
                    help="comma-separated scene indices of the build")
    ap.add_argument("--scenes", type=int, default=200, help="scenes of the planned build")
    ap.add_argument("--seed", type=int, default=0, help="seed of the planned build")
    ap.add_argument("--baseline-rev", metavar="REV", help="also run git revision REV")
    ap.add_argument("--_worker", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args._worker:
        serve(_handle)
        return
    indices = [int(x) for x in args.index.split(",") if x.strip()]
    with revision_tree(args.baseline_rev) if args.baseline_rev else contextlib.nullcontext() as wt:
        workers = {"now": Worker(__file__, src=ROOT / "src")}
        if wt is not None:
            workers[args.baseline_rev] = Worker(__file__, src=wt / "src")
        names = list(workers)
        print(f"{'scene':>5}  {'template':<28} " + "  ".join(f"{n:>12}" for n in names)
              + "  first failure (now)", flush=True)
        done = {n: 0 for n in names}
        cpu = {n: 0.0 for n in names}
        for i in indices:
            res = {}
            for name, w in workers.items():
                r = w.ask(index=i, scenes=args.scenes, seed=args.seed)
                if "error" in r:
                    sys.exit(f"{name}: scene {i}: {r['error']}")
                res[name] = r
                done[name] += not r["failed"]
                cpu[name] += r["cpu"]
            cells = "  ".join(f"{'complete' if not res[n]['failed'] else str(len(res[n]['failed'])) + ' failed':>12}"
                              for n in names)
            first = res["now"]["failed"][0][:90] if res["now"]["failed"] else ""
            print(f"{i:>5}  {res['now']['template']:<28} {cells}  {first}", flush=True)
        for w in workers.values():
            w.close()
    print("complete: " + ", ".join(f"{n} {done[n]}/{len(indices)}" for n in names))
    print("CPU s: " + ", ".join(f"{n} {cpu[n]:.1f}" for n in names))


if __name__ == "__main__":
    main()
