"""How long the layout model takes to read a dataset before training starts.

    python benchmarks/bench_layout_load.py --dataset DS                      # this checkout
    python benchmarks/bench_layout_load.py --dataset DS --baseline-rev REV   # and REV, interleaved

Each measurement is a fresh process that reads every scene of ``DS`` (``load_dataset``) and
turns it into the network's input (``graph_arrays`` with the fixed shape descriptor and the
learned relation tokens), as ``parse3d layout train`` does; the figure is the process's CPU
time for that (imports excluded), so it holds under load. This checkout is measured twice per
round: with its asset index (``$PARSE3D_CACHE/layoutgen/asset-info.json``) removed first
(``cold``: every asset is read once and indexed) and with the index from the run before
(``warm``). Rounds interleave the sides; the medians and their ratios are printed.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

from _common import ROOT, revision_tree


def _once(dataset: str) -> dict:
    from parse3d.layoutgen.data import graph_arrays, load_dataset
    from parse3d.layoutgen.encoders import ShapeDescriptor, make_relation_encoder
    from parse3d.layoutgen.pose import PoseStats

    t0 = time.process_time()
    scenes = load_dataset(dataset)
    t1 = time.process_time()
    shape = ShapeDescriptor({c for s in scenes for c in s.categories})
    rel = make_relation_encoder("learned")
    stats = PoseStats.fit([s.poses for s in scenes])
    # revisions before the asset index have no asset_info: their scenes carry the assets
    infos = [getattr(s, "asset_info", None) or s.assets for s in scenes]
    for s, a in zip(scenes, infos, strict=True):
        graph_arrays(s.categories, a, s.relations, s.footprint, s.height,
                     shape_encoder=shape, relation_encoder=rel, stats=stats, poses=s.poses)
    t2 = time.process_time()
    return {"scenes": len(scenes), "load": t1 - t0, "total": t2 - t0}


def _measure(src: Path, dataset: str) -> dict:
    env = dict(os.environ, PYTHONPATH=str(src))
    out = subprocess.run([sys.executable, __file__, "--_once", dataset], env=env,
                         capture_output=True, text=True, check=True, cwd=str(ROOT))
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dataset", required=False)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--baseline-rev", metavar="REV")
    ap.add_argument("--_once", metavar="DATASET", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args._once:
        print(json.dumps(_once(args._once)))
        return
    if not args.dataset:
        ap.error("--dataset is required")
    from parse3d.assets.library import cache_dir

    index = cache_dir() / "layoutgen" / "asset-info.json"
    sides: dict[str, list[dict]] = {"cold": [], "warm": []}

    def run_rounds(base_src: Path | None) -> None:
        if base_src is not None:
            sides["baseline"] = []
        for r in range(args.rounds):
            if base_src is not None:
                sides["baseline"].append(_measure(base_src, args.dataset))
            index.unlink(missing_ok=True)
            sides["cold"].append(_measure(ROOT / "src", args.dataset))
            sides["warm"].append(_measure(ROOT / "src", args.dataset))
            print(f"round {r + 1}: " + ", ".join(f"{k} {v[-1]['total']:.2f} s"
                                                 for k, v in sides.items()), flush=True)

    if args.baseline_rev:
        with revision_tree(args.baseline_rev) as wt:
            run_rounds(wt / "src")
    else:
        run_rounds(None)
    n = sides["warm"][0]["scenes"]
    print(f"\n{n} scenes, CPU seconds (median of {args.rounds}; load_dataset / load + arrays):")
    med = {k: (statistics.median(m["load"] for m in v), statistics.median(m["total"] for m in v))
           for k, v in sides.items()}
    for k, (ld, tot) in med.items():
        print(f"  {k:9s} {ld:7.2f} / {tot:7.2f}   ({1000 * tot / n:.1f} ms per scene)")
    if "baseline" in med:
        b = med["baseline"][1]
        print(f"  speed-up over {args.baseline_rev}: cold {b / med['cold'][1]:.1f}x, "
              f"warm {b / med['warm'][1]:.1f}x")


if __name__ == "__main__":
    main()
