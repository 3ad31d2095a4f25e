"""CPU cost of one training step of the layout model, against another revision.

    python benchmarks/bench_layout_step.py --dataset DS --objects 60 --baseline-rev REV

Each measurement is a fresh process (one torch thread) that reads the first 40 scenes of
``DS``, takes the one whose object count is nearest ``--objects``, builds the network of
``--preset`` (learned relation tokens, the fixed shape descriptor) and times ``--steps``
optimiser steps of ``--draws`` noise draws after two warm-up steps; the figure is CPU seconds
per step, so it holds under load. Rounds interleave this checkout and ``REV``; medians and
their ratio are printed.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).resolve().parent))


def _once(dataset: str, objects: int, preset: str, draws: int, steps: int) -> dict:
    import time

    import torch

    from parse3d.layoutgen.data import find_scenes, graph_arrays, load_scene
    from parse3d.layoutgen.encoders import ShapeDescriptor, make_relation_encoder
    from parse3d.layoutgen.pose import PoseStats
    from parse3d.layoutgen.train import (
        TrainConfig,
        _batch_loss,
        _build_model,
        _step_generator,
        make_scheduler,
        scene_tensors,
    )

    torch.set_num_threads(1)
    scenes = [load_scene(f) for f in find_scenes(dataset)[:40]]
    s = min(scenes, key=lambda x: abs(len(x.categories) - objects))
    enc = ShapeDescriptor(sorted({c for x in scenes for c in x.categories}))
    rel = make_relation_encoder("learned")
    ga = graph_arrays(s.categories, s.asset_info, s.relations, s.footprint, s.height,
                      shape_encoder=enc, relation_encoder=rel,
                      stats=PoseStats.fit([x.poses for x in scenes]), poses=s.poses)
    g = scene_tensors(ga, "cpu")
    model, _ = _build_model(TrainConfig(preset=preset, relations="learned"), enc.dim, rel.dim, 0)
    opt = torch.optim.AdamW(model.parameters(), lr=8e-4)
    sched = make_scheduler()

    def step(i: int) -> None:
        loss = _batch_loss(model, sched, g, _step_generator(0, i, "cpu"), draws, 0.1, "pag", "cpu")
        opt.zero_grad()
        loss.backward()
        opt.step()

    for i in range(2):
        step(i)
    t0 = time.process_time()
    for i in range(steps):
        step(i)
    return {"objects": len(s.categories), "relations": len(s.relations),
            "step_cpu": (time.process_time() - t0) / steps}


def _measure(src: Path, args) -> dict:
    out = subprocess.run([sys.executable, __file__, "--_once", args.dataset, "--objects",
                          str(args.objects), "--preset", args.preset, "--draws", str(args.draws),
                          "--steps", str(args.steps)],
                         env={**__import__("os").environ, "PYTHONPATH": str(src)},
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dataset")
    ap.add_argument("--objects", type=int, default=60)
    ap.add_argument("--preset", default="cpu")
    ap.add_argument("--draws", type=int, default=16)
    ap.add_argument("--steps", type=int, default=5)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--baseline-rev", metavar="REV")
    ap.add_argument("--_once", metavar="DATASET", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args._once:
        print(json.dumps(_once(args._once, args.objects, args.preset, args.draws, args.steps)))
        return
    if not args.dataset:
        ap.error("--dataset is required")
    from _common import revision_tree

    sides: dict[str, list[dict]] = {"this": []}

    def rounds(base_src: Path | None) -> None:
        if base_src is not None:
            sides["baseline"] = []
        for r in range(args.rounds):
            if base_src is not None:
                sides["baseline"].append(_measure(base_src, args))
            sides["this"].append(_measure(ROOT / "src", args))
            print(f"round {r + 1}: " + ", ".join(f"{k} {v[-1]['step_cpu']:.3f} s"
                                                 for k, v in sides.items()), flush=True)

    if args.baseline_rev:
        with revision_tree(args.baseline_rev) as wt:
            rounds(wt / "src")
    else:
        rounds(None)
    m = sides["this"][0]
    print(f"\n{m['objects']} objects, {m['relations']} relations, preset {args.preset}, "
          f"{args.draws} draws: CPU seconds per step (median of {args.rounds})")
    med = {k: statistics.median(x["step_cpu"] for x in v) for k, v in sides.items()}
    for k, v in med.items():
        print(f"  {k:9s} {v:.3f}")
    if "baseline" in med:
        print(f"  speed-up over {args.baseline_rev}: {med['baseline'] / med['this']:.2f}x")


if __name__ == "__main__":
    main()
