"""Can the layout model memorise the scenes it is trained on?

    python benchmarks/bench_layout_overfit.py --dataset DIR --out RUN --steps 500
    python benchmarks/bench_layout_overfit.py --dataset DIR --out RUN --steps 1000   # resumes

``DIR`` holds one or two scene folders (all of them are training scenes then; with more, only the run's training scenes are generated back). The model is
trained PAG-conditioned without condition dropout (``--preset small``, learned relation
tokens; resumed when ``RUN`` holds a checkpoint), then every training scene is generated back
with sampling seeds 0 and 1 and compared with its own poses: the mean absolute error per pose
block in the network's normalised space (translation, size, 6-D rotation), the median
horizontal and vertical error of the object origins (m), and the metrics of
``parse3d layout eval`` without physics. ``--raw`` samples with the trained weights instead
of their EMA. Figures are CPU seconds, so they hold under load.
"""

from __future__ import annotations

import argparse
import time

import numpy as np


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dataset", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--steps", type=int, default=500)
    ap.add_argument("--preset", default="small")
    ap.add_argument("--lr", type=float, default=8e-4)
    ap.add_argument("--sample-steps", type=int, default=100)
    ap.add_argument("--frame", default="world", choices=("world", "parent"),
                    help="translations of supported objects in the world or the parent's frame")
    ap.add_argument("--raw", action="store_true", help="sample with the raw weights, not the EMA")
    args = ap.parse_args()

    import torch

    from parse3d.layoutgen.data import load_dataset
    from parse3d.layoutgen.evaluate import _scene_for, _sub_pag, layout_metrics
    from parse3d.layoutgen.pose import normalise_poses
    from parse3d.layoutgen.sample import SampleOptions, generate_poses
    from parse3d.layoutgen.train import TrainConfig, load_run, train

    torch.set_num_threads(1)
    t0 = time.process_time()
    rep = train(args.dataset, args.out, TrainConfig(
        steps=args.steps, preset=args.preset, relations="learned", cond_dropout=0.0,
        checkpoint_every=max(args.steps // 4, 1), lr=args.lr, frame=args.frame))
    losses = rep.losses
    print(f"trained to step {rep.steps} ({time.process_time() - t0:.0f} s CPU); loss, mean of "
          f"the first 20 steps {np.mean(losses[:20]):.4f}, of the last 50 {np.mean(losses[-50:]):.4f}")
    run = load_run(args.out)
    if args.raw:
        state = torch.load(f"{args.out}/checkpoint.pt", map_location="cpu", weights_only=False)
        run.model.load_state_dict(state["model"])
    weights = "raw" if args.raw else "EMA"
    print("| scene | seed | weights | t err | size err | r6 err | dxy (m) | dz (m) | support_rate "
          "| relations | relations_spatial | collision_rate | outside |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    import json
    from pathlib import Path

    # the scenes the run trained on (with more than two scenes, the split holds some out, and
    # their categories may be unknown to it)
    trained = set(json.loads((Path(args.out) / "split.json").read_text())["train"])
    for ls in load_dataset(args.dataset):
        if ls.scene_id not in trained:
            continue
        gt = normalise_poses(ls.poses, ls.footprint, ls.height, run.stats)
        for seed in (0, 1):
            p = generate_poses(run, ls.categories, ls.asset_info, ls.relations, ls.footprint,
                               ls.height, seed=seed, options=SampleOptions(steps=args.sample_steps))
            err = np.abs(normalise_poses(p, ls.footprint, ls.height, run.stats) - gt)
            dxy = np.median(np.linalg.norm(p[:, :2] - ls.poses[:, :2], axis=1))
            dz = np.median(np.abs(p[:, 2] - ls.poses[:, 2]))
            m = layout_metrics(_scene_for(ls, _sub_pag(ls), p, seed, given_scale=False,
                                          label="overfit"), physics=False)
            print(f"| {ls.scene_id} | {seed} | {weights} | {err[:, :3].mean():.4f} | "
                  f"{err[:, 3:6].mean():.4f} | {err[:, 6:].mean():.4f} | {dxy:.3f} | {dz:.3f} | "
                  f"{m.support_rate:.3f} | {m.relations:.3f} | {m.relations_spatial:.3f} | "
                  f"{m.collision_rate:.3f} | {m.outside:.3f} |")


if __name__ == "__main__":
    main()
