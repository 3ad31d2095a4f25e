"""The dataset preview's render cost: ``preview.png`` of settled template scenes, CPU seconds.

Usage::

    python benchmarks/bench_preview.py                         # 4 scenes, 3 rounds
    python benchmarks/bench_preview.py --baseline-rev main     # also main's renderer, interleaved
    python benchmarks/bench_preview.py --scenes 6 --rounds 5

Solves and settles ``--scenes`` scenes of a dataset build (templates, dataset seed 0, the same
scene indices as ``parse3d dataset build``), then renders each scene's preview exactly as a
dataset worker does (``save_preview``: the viewpoint chosen among candidates on small
instance masks, then the 640x480 colour image, written as PNG) and prints CPU seconds per
preview:

* ``cold``: the scene's assets not yet uploaded (what a worker meets for most assets of a
  scene: the pool has thousands of slots), so the vertex buffers are built too;
* ``warm``: the same preview again, every mesh uploaded.

With ``--baseline-rev REV`` the package of git revision REV (a temporary worktree) renders
the same scenes in a second process, in alternating rounds; the ratios are printed. Mesa's
llvmpipe runs on one thread in both (``LP_NUM_THREADS=1``, as in dataset workers). The
pixels of both previews are compared too: the speed-ups here must not change the images.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

from _common import ROOT, Worker, revision_tree, serve

_STATE: dict = {}


def _setup(n: int) -> dict:
    from parse3d.datagen.build_config import BuildConfig
    from parse3d.datagen.planning import plan_scene
    from parse3d.datagen.sources import make_source
    from parse3d.pipeline import PipelineOptions, run_pipeline
    from parse3d.render import Renderer

    cfg = BuildConfig(scenes=n)
    source = make_source(cfg)
    scenes = []
    for i in range(n):
        plan = plan_scene(cfg, source, i)
        pag = source.make_pag(plan.template, plan.seed)
        scenes.append(run_pipeline(pag, seed=plan.seed, out=None,
                                   options=PipelineOptions(preview=False)))
    _STATE.update(scenes=scenes, renderer=Renderer(), tmp=Path(tempfile.mkdtemp()))
    return {"placed": [len(s.placed) for s in scenes]}


def _drop_meshes(r) -> None:
    """Forget every uploaded mesh (as if the scene's assets were new to this worker)."""
    with r.ctx:
        for _, gm in r._meshes.values():
            gm.release()
    r._meshes.clear()


def _round() -> dict:
    import numpy as np
    from PIL import Image

    from parse3d.render import save_preview

    r, out = _STATE["renderer"], _STATE["tmp"] / "preview.png"
    cold, warm, pixels = [], [], []
    for scene in _STATE["scenes"]:
        _drop_meshes(r)
        c = time.process_time()
        save_preview(scene, out, renderer=r)
        cold.append(time.process_time() - c)
        c = time.process_time()
        save_preview(scene, out, renderer=r)
        warm.append(time.process_time() - c)
        pixels.append(hashlib.sha256(np.asarray(Image.open(out)).tobytes()).hexdigest())
    return {"cold": cold, "warm": warm, "pixels": pixels}


def _handle(req: dict) -> dict:
    return _setup(int(req["scenes"])) if req["op"] == "setup" else _round()


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", type=int, default=4)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--baseline-rev", metavar="REV", help="also REV's renderer, interleaved")
    ap.add_argument("--_worker", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args._worker:
        serve(_handle)
        return
    os.environ["LP_NUM_THREADS"] = "1"
    print(f"solving and settling {args.scenes} template scenes per revision ...", flush=True)
    with Worker(__file__, src=ROOT / "src") as now:
        if args.baseline_rev:
            with revision_tree(args.baseline_rev) as wt, \
                    Worker(__file__, src=wt / "src", cwd=ROOT) as before:
                _run(args, now, before)
        else:
            _run(args, now, None)


def _run(args, now: Worker, before: Worker | None) -> None:
    workers = [("now", now)] + ([(args.baseline_rev[:10], before)] if before else [])
    placed = {name: w.ask(op="setup", scenes=args.scenes)["placed"] for name, w in workers}
    res: dict[str, dict[str, list[float]]] = {name: {"cold": [], "warm": []}
                                              for name, _ in workers}
    pixels: dict[str, list[str]] = {}
    for k in range(args.rounds):
        for name, w in (workers if k % 2 == 0 else workers[::-1]):
            r = w.ask(op="round")
            if "error" in r:
                sys.exit(f"{name}: {r['error']}")
            res[name]["cold"] += r["cold"]
            res[name]["warm"] += r["warm"]
            pixels[name] = r["pixels"]
    print(f"placed objects per scene: {placed['now']}")
    head = f"{'CPU s per preview (median)':30s}" + "".join(f"{n:>12s}" for n, _ in workers)
    print(head + ("     ratio" if before else ""))
    for kind in ("cold", "warm"):
        meds = [statistics.median(res[n][kind]) for n, _ in workers]
        line = f"  {kind:28s}" + "".join(f"{m:12.3f}" for m in meds)
        if before:
            line += f"{meds[1] / meds[0]:9.2f}x"
        print(line)
    if before:
        same = placed[workers[0][0]] == placed[workers[1][0]]
        if same:
            equal = sum(a == b for a, b in zip(*pixels.values(), strict=True))
            print(f"previews with the same pixels in both: {equal}/{len(pixels['now'])}")
        else:
            print("the revisions solve different scenes: pixels not compared")


if __name__ == "__main__":
    main()
