"""What collides in generated layouts, and which sampler setting changes it.

    python benchmarks/bench_layout_collide.py RUN_PAG RUN_NONE --max-scenes 10
    python benchmarks/bench_layout_collide.py RUN_PAG --max-scenes 4 \\
        --variants plain,steps=200,steps=1000,raw,noclip,truescale,upright,guide=5

Every variant samples each held-out scene (the first run's test split, objects of categories
some run never saw left out, as ``parse3d layout eval`` does) once per run with sampling
seed 0 and 50 denoising steps, places the scene's own assets at the generated poses (equal
volume scale) and measures the layout as ``eval --no-physics`` does. Per variant and run it
prints the collision rate, the colliding pairs per scene split by what they are to the PAG
(one carries the other, siblings on one support, both on the room, other), how deep they are
(quartiles and the share under 3 cm: cm-off contacts or objects inside each other), and the
support, relation and outside rates; then, per model variant, how far the scale taken from
the generated size is from the dataset's and how far the rotations tilt from upright (sampled
again, outside the CPU figures). Variants:

- ``plain``: the sampler as ``eval`` runs it;
- ``steps=N``: N denoising steps (the paper samples with all 1000);
- ``raw``: the trained weights instead of their EMA;
- ``noclip``: no clipping of the clean-sample estimate to [-1, 1];
- ``truescale``: each asset at the dataset's scale instead of the one from the generated size;
- ``upright``: rotations turned upright (yaw kept);
- ``guide=N``: physics guidance in the last N denoising steps (``--guide``);
- ``random`` / ``random+guide=N``: random poses (``eval``'s baseline), and after as many
  guidance passes as ``guide=N`` gives at most.

``solver`` measures the dataset's own solved poses. CPU seconds per variant are printed, so the
figures hold under load.
"""

from __future__ import annotations

import argparse
import time

import numpy as np


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--max-scenes", type=int, default=10)
    ap.add_argument("--sample-steps", type=int, default=50)
    ap.add_argument("--variants", default="solver,random,plain")
    args = ap.parse_args()

    import torch

    from parse3d.layoutgen import sample as S
    from parse3d.layoutgen.data import load_scene
    from parse3d.layoutgen.evaluate import (
        _known_only,
        _sub_pag,
        collisions,
        held_out_scenes,
        layout_metrics,
        pair_kind,
        random_poses,
    )
    from parse3d.layoutgen.guide import PASSES, guide_poses, piece_boxes
    from parse3d.layoutgen.pose import rotation_from_6d
    from parse3d.layoutgen.train import load_run

    torch.set_num_threads(1)
    runs = [load_run(r) for r in args.runs]
    known = set.intersection(*(set(r.categories) for r in runs))
    files = held_out_scenes(runs[0])[:args.max_scenes]
    scenes = [_known_only(load_scene(f), known) for f in files]
    kinds = ("child_parent", "siblings", "floor", "other")

    def equal_volume(ls, poses):
        return [float(np.clip(np.cbrt(np.prod(np.maximum(p[3:6], 1e-3))
                                      / np.prod(np.maximum(a.extents, 1e-4))), *S.SCALE_RANGE))
                for p, a in zip(poses, ls.assets, strict=True)]

    def poses_for(variant, run, ls):
        name, _, val = variant.partition("=")
        if variant == "solver":
            return (ls.poses if ls.solved_poses is None else ls.solved_poses), list(ls.scales)
        if name.startswith("random"):
            p = random_poses(ls, np.random.default_rng([0, 0, 17]))
            if name == "random+guide":
                p = guide_poses(p, piece_boxes(ls.assets), ls.footprint, ls.height,
                                passes=int(val) * PASSES, scales=ls.scales)
            return p, list(ls.scales)
        opts = S.SampleOptions(steps=int(val) if name == "steps" else args.sample_steps,
                               guide=int(val) if name == "guide" else 0)
        restore = None
        if name == "raw":
            restore = {k: v.clone() for k, v in run.model.state_dict().items()}
            state = torch.load(run.path / "checkpoint.pt", map_location="cpu", weights_only=False)
            run.model.load_state_dict(state["model"])
        make = S.make_scheduler
        if name == "noclip":
            def unclipped():
                sched = make()
                sched.register_to_config(clip_sample=False)
                return sched
            S.make_scheduler = unclipped
        try:
            p = S.generate_poses(run, ls.categories, ls.assets, ls.relations, ls.footprint,
                                 ls.height, seed=0, options=opts)
        finally:
            S.make_scheduler = make
            if restore is not None:
                run.model.load_state_dict(restore)
        scales = list(ls.scales) if name == "truescale" else equal_volume(ls, p)
        if name == "upright":
            R = rotation_from_6d(p[:, 6:12])
            yaw = np.arctan2(R[:, 1, 0], R[:, 0, 0])
            c, s = np.cos(yaw), np.sin(yaw)
            p = p.copy()
            p[:, 6:12] = np.stack([c, s, 0 * c, -s, c, 0 * c], 1)
        return p, scales

    print("| variant | run | collision_rate | pairs/scene | child-parent | siblings | room | other "
          "| depth quartiles (cm) | < 3 cm | support_rate | relations | relations_spatial "
          "| outside | CPU s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    extra: list[str] = []
    for variant in args.variants.split(","):
        model = not (variant == "solver" or variant.startswith("random"))
        for run in (runs if model else [None]):
            t0 = time.process_time()
            rates, pairs, by, depths, sup, rel, sp, out = [], [], dict.fromkeys(kinds, 0), [], [], [], [], []
            for ls in scenes:
                pag = _sub_pag(ls)
                p, scales = poses_for(variant, run, ls)
                scene = S.layout_scene(pag, ls.object_ids, ls.categories, p, seed=0,
                                       assets=ls.assets, scales=scales)
                hits = collisions(scene)
                m = layout_metrics(scene, physics=False)
                rates.append(m.collision_rate)
                pairs.append(len(hits))
                for a, b, d in hits:
                    by[pair_kind(pag, a, b)] += 1
                    depths.append(d)
                sup.append(m.support_rate)
                rel.append(m.relations)
                sp.append(m.relations_spatial)
                out.append(m.outside)
            cpu = time.process_time() - t0
            if model:  # how far the generated scale and rotation are from the dataset's
                errs, tilts = [], []
                for ls in scenes:
                    p, scales = poses_for(variant, run, ls)
                    errs += list(np.abs(np.log(np.asarray(equal_volume(ls, p)) / ls.scales)))
                    up = np.clip(rotation_from_6d(p[:, 6:12])[:, 2, 2], -1.0, 1.0)
                    tilts += list(np.degrees(np.arccos(up)))
                extra.append(f"{variant} {run.name}: |log(scale / dataset scale)| median "
                             f"{np.median(errs):.3f}, 90th percentile {np.percentile(errs, 90):.3f}; "
                             f"tilt from upright median {np.median(tilts):.2f} deg")
            n = max(len(scenes), 1)
            d = np.array(depths)
            q = " / ".join(f"{x * 100:.1f}" for x in np.percentile(d, [25, 50, 75])) if len(d) else "-"
            print(f"| {variant} | {run.name if run else '-'} | {np.mean(rates):.3f} "
                  f"| {np.mean(pairs):.1f} | " + " | ".join(f"{by[k] / n:.1f}" for k in kinds)
                  + f" | {q} | {np.mean(d < 0.03) if len(d) else 0:.2f} | {np.nanmean(sup):.3f} "
                  f"| {np.nanmean(rel):.3f} | {np.nanmean(sp):.3f} | {np.mean(out):.3f} "
                  f"| {cpu:.0f} |", flush=True)
    print()
    print("\n".join(extra))


if __name__ == "__main__":
    main()
