"""Settling (with its verify-and-repair rounds) of dataset template scenes, CPU per scene.

Usage::

    python benchmarks/bench_settle.py                          # 8 template scenes, 3 rounds
    python benchmarks/bench_settle.py --scenes 12 --rounds 5
    python benchmarks/bench_settle.py --baseline-rev fb2900d   # side by side with REV

Plans the scenes as ``parse3d dataset build`` does (templates, ``--seed``), solves each one
and times ``settle_and_repair`` on it (the dataset's settle stage), then ``extract_contacts``
(its contacts stage). The in-process collision cache is emptied before every scene, so each
pays what a dataset worker pays for a scene of fresh assets (reading their hulls from
``$PARSE3D_CACHE/collision``). With ``--baseline-rev REV`` a second worker runs the package of
REV and the two take turns, scene by scene, round by round: CPU ratios stay fair on a loaded
machine. The outcomes are then
compared: per object its status, physics flags, repairs and settled pose (largest difference
printed), and the contacts.
"""

from __future__ import annotations

import argparse
import contextlib
import statistics
import sys
import time

from _common import ROOT, Worker, revision_tree, serve

_SOLVED: dict[int, object] = {}


def _handle(req: dict) -> dict:
    import numpy as np

    from parse3d.datagen.build import BuildConfig
    from parse3d.datagen.planning import plan_scene
    from parse3d.datagen.sources import make_source
    from parse3d.physics import extract_contacts
    from parse3d.physics.collision import clear_cache
    from parse3d.pipeline import PipelineOptions, run_pipeline, settle_and_repair

    cfg = BuildConfig(scenes=int(req["scenes"]), seed=int(req["seed"]))
    source = make_source(cfg)
    plan = plan_scene(cfg, source, int(req["index"]))
    pag = source.make_pag(plan.template, plan.seed)
    scene = run_pipeline(pag, seed=plan.seed, out=None,
                         options=PipelineOptions(settle=False, preview=False))
    clear_cache()
    c0, w0 = time.process_time(), time.perf_counter()
    settle_and_repair(scene)
    cpu, wall = time.process_time() - c0, time.perf_counter() - w0
    c1 = time.process_time()
    contacts = extract_contacts(scene)  # the dataset's contacts stage, which follows
    cpu_contacts = time.process_time() - c1
    objects = {}
    for o in scene.objects.values():
        pose = None
        if o.settled_position is not None:
            pose = [float(x) for x in np.concatenate([np.ravel(o.settled_rotation),
                                                      np.ravel(o.settled_position)])]
        objects[o.id] = {"status": o.status, "flags": sorted(o.flags),
                         "repairs": [str(r) for r in o.repairs], "pose": pose}
    return {"cpu": cpu, "wall": wall, "cpu_contacts": cpu_contacts,
            "contacts": [c.to_dict() for c in contacts], "placed": len(scene.placed),
            "steps": scene.meta.get("settle", {}).get("steps"),
            "repair": scene.meta.get("repair"), "objects": objects}


def _compare(a: dict, b: dict) -> tuple[int, float]:
    """(objects whose status, flags or repairs differ, largest pose difference); the contacts
    differing count as one object more."""
    bad, worst = int(a["contacts"] != b["contacts"]), 0.0
    for oid, x in a["objects"].items():
        y = b["objects"].get(oid)
        if y is None or (x["status"], x["flags"], x["repairs"]) != \
                (y["status"], y["flags"], y["repairs"]):
            bad += 1
            continue
        if (x["pose"] is None) != (y["pose"] is None):
            bad += 1
        elif x["pose"] is not None:
            worst = max(worst, max(abs(p - q) for p, q in zip(x["pose"], y["pose"], strict=True)))
    return bad, worst


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", type=int, default=8)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--baseline-rev", metavar="REV", help="also time git revision REV")
    ap.add_argument("--_worker", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args._worker:
        serve(_handle)
        return
    with revision_tree(args.baseline_rev) if args.baseline_rev else contextlib.nullcontext() as wt:
        workers = {"now": Worker(__file__, src=ROOT / "src")}
        if wt is not None:
            workers[args.baseline_rev] = Worker(__file__, src=wt / "src")
        cpu: dict[str, list[list[float]]] = {k: [[] for _ in range(args.scenes)] for k in workers}
        ccpu: dict[str, list[list[float]]] = {k: [[] for _ in range(args.scenes)]
                                              for k in workers}
        last: dict[str, list[dict]] = {k: [{}] * args.scenes for k in workers}
        print(f"settling {args.scenes} template scenes, {args.rounds} rounds "
              f"({', '.join(workers)}) ...", flush=True)
        for _ in range(args.rounds):
            for i in range(args.scenes):
                for name, w in workers.items():
                    r = w.ask(index=i, scenes=args.scenes, seed=args.seed)
                    if "error" in r:
                        sys.exit(f"{name}: scene {i}: {r['error']}")
                    cpu[name][i].append(r["cpu"])
                    ccpu[name][i].append(r["cpu_contacts"])
                    last[name][i] = r
        for w in workers.values():
            w.close()
    names = list(workers)
    print(f"\n{'scene':>5} {'placed':>6} {'steps':>5} {'repaired':>8}  "
          + "  ".join(f"{n + ' CPU s':>14}" for n in names)
          + ("   ratio  outcomes" if len(names) > 1 else ""))
    med = {n: [statistics.median(c) for c in cpu[n]] for n in names}
    for i in range(args.scenes):
        r = last["now"][i]
        line = (f"{i:>5} {r['placed']:>6} {r['steps']!s:>5} "
                f"{(r['repair'] or {}).get('repaired', 0)!s:>8}  "
                + "  ".join(f"{med[n][i]:>14.3f}" for n in names))
        if len(names) > 1:
            bad, worst = _compare(r, last[names[1]][i])
            same = "same" if bad == 0 else f"{bad} objects differ"
            line += f"   {med[names[1]][i] / med['now'][i]:>5.2f}x  {same}, poses within {worst:.1e}"
        print(line)
    total = {n: sum(med[n]) / args.scenes for n in names}
    print("mean CPU s per scene: " + ", ".join(f"{n} {total[n]:.3f}" for n in names))
    cont = {n: sum(statistics.median(c) for c in ccpu[n]) / args.scenes for n in names}
    print("then contacts, mean CPU s per scene: "
          + ", ".join(f"{n} {cont[n]:.3f}" for n in names))
    if len(names) > 1:
        print(f"settle CPU per scene, {names[1]} / now: {total[names[1]] / total['now']:.2f}x")
        print(f"contacts CPU per scene, {names[1]} / now: {cont[names[1]] / cont['now']:.2f}x")
        both = {n: total[n] + cont[n] for n in names}
        print(f"settle + contacts, {names[1]} / now: {both[names[1]] / both['now']:.2f}x")


if __name__ == "__main__":
    main()
