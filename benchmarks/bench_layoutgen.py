"""The scene-generation experiment: PAG-conditioned vs unconditioned layout diffusion.

Usage::

    python benchmarks/bench_layoutgen.py --dataset out/mini --out out/layout-bench \\
        [--steps 2000] [--seeds 3] [--max-scenes 0] [--preset cpu] [--relations text] \\
        [--shape descriptor] [--guidance 1] [--device cpu] [--cpu-limit 30] [--fit] [--guide 5]
    python benchmarks/bench_layoutgen.py --build 1000 --rooms bedroom,study,bathroom ...

A small end-to-end check (a few minutes of CPU)::

    python benchmarks/bench_layoutgen.py --build 6 --rooms study --no-settle --out out/lb \\
        --steps 20 --preset tiny --relations learned --seeds 2 --max-scenes 1 --no-physics \\
        --sample-steps 10

The issue's full run on one GPU (the paper's sizes, ``--preset paper``: 512-d, 16 noisy
copies per scene; three training seeds per model; the table with and without guidance)::

    python benchmarks/bench_layoutgen.py --build 1000 --rooms bedroom,study,bathroom \\
        --workers 16 --out out/lb-gpu --steps 30000 --preset paper --device cuda --seeds 3 \\
        --train-seeds 3 --guide 5 --shape pointcloud

With ``--train-seeds K`` each model is trained K times (seeds 0..K-1, one train/test split)
under ``OUT/train-seed-k/``, and each row reports the mean ± spread over the K training seeds
(each seed's figure the mean over sampling seeds and held-out scenes). With ``--guide N`` the
table has every model row twice, ``[model only]`` and ``[model + guidance (N steps)]``, and the
claim is judged for each part.

With ``--build N`` it first builds (or resumes) an N-scene template dataset into
``OUT/dataset`` (``--workers`` processes). It then trains two runs on the same split,
``OUT/pag`` (``--cond pag``, condition dropout 0.1) and ``OUT/none`` (``--cond none``), with the
same steps and seed, and evaluates both on the PAG run's test scenes with ``--seeds`` sampling
seeds: solver, random poses, PAG-conditioned, the PAG run with its condition dropped, and the
unconditioned run. It writes ``OUT/eval/eval.md``, ``eval.json``, ``previews/*.png`` and
``OUT/eval/losses.png`` (both loss curves), and prints the table, the CPU seconds spent
training each model and whether the issue's claim holds (PAG beats unconditioned on relation
satisfaction and collision rate by more than the seed-to-seed spread, and both beat random).

The issue's full claim is >= 1,000 scenes of 2-3 room types and 30 CPU minutes per model:
``--steps 100000 --cpu-limit 30`` stops each training after 30 minutes of its CPU time (about
0.18 s of CPU per step for 60-object scenes with the ``cpu`` preset). ``--fit`` adds the
PAG-conditioned sampler's relation-aware step as a row of its own (and random poses with it);
the claim is then judged for the PAG-conditioned row with and without it. ``--guide N``
samples every model row with physics guidance (``parse3d layout eval --guide``); the claim is
judged against the plain random poses (the guided control row is not the baseline).
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dataset", type=Path, help="an existing dataset folder")
    ap.add_argument("--build", type=int, default=0, help="build this many scenes first")
    ap.add_argument("--rooms", default="bedroom,study,bathroom")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--out", type=Path, required=True)
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--preset", default="cpu")
    ap.add_argument("--relations", default="text")
    ap.add_argument("--shape", default="descriptor", help="descriptor or pointcloud")
    ap.add_argument("--noise-draws", type=int, default=16)
    ap.add_argument("--guidance", type=float, default=1.0)
    ap.add_argument("--frame", default="world", choices=("world", "parent"),
                    help="the PAG-conditioned run's translations of supported objects")
    ap.add_argument("--separate", type=int, default=0,
                    help="separation guidance in the last N denoising steps (every row)")
    ap.add_argument("--guide", type=int, default=0,
                    help="physics guidance in the last N denoising steps (every model row)")
    ap.add_argument("--device", default="cpu")
    ap.add_argument("--no-settle", action="store_true", help="build without settling (faster)")
    ap.add_argument("--seeds", type=int, default=3, help="sampling seeds per evaluation")
    ap.add_argument("--train-seeds", type=int, default=1,
                    help="train each model this many times (seeds 0..K-1); rows report the "
                    "mean and spread over training seeds")
    ap.add_argument("--max-scenes", type=int, default=0, help="evaluate at most this many test scenes")
    ap.add_argument("--sample-steps", type=int, default=100)
    ap.add_argument("--no-physics", action="store_true")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--cpu-limit", type=float, default=None,
                    help="stop each training after this many minutes of its CPU time")
    ap.add_argument("--fit", action="store_true",
                    help="also the PAG-conditioned rows with the relation-aware step")
    args = ap.parse_args()

    import torch

    from parse3d.layoutgen.evaluate import evaluate, held_out_scenes, write_result
    from parse3d.layoutgen.train import TrainConfig, load_run, train

    torch.set_num_threads(args.threads)
    args.out.mkdir(parents=True, exist_ok=True)
    dataset = args.dataset
    if args.build:
        from parse3d.datagen.build import BuildConfig, build_dataset

        dataset = args.out / "dataset"
        t = time.perf_counter()
        rep = build_dataset(BuildConfig(scenes=args.build, rooms=tuple(args.rooms.split(",")),
                                        settle=not args.no_settle), dataset, workers=args.workers)
        print(f"dataset: {rep.ok} scenes ok, {rep.failed} failed ({time.perf_counter() - t:.0f} s)")
    if dataset is None:
        ap.error("give --dataset or --build N")

    cpu: dict[str, list[float]] = {"pag": [0.0, 0.0], "none": [0.0, 0.0]}
    guides = (0, args.guide) if args.guide > 0 else (0,)
    # per training seed, per guidance setting: the evaluation of that seed's two runs
    results: list[list] = []
    for k in range(args.train_seeds):
        sub = args.out if args.train_seeds == 1 else args.out / f"train-seed-{k}"
        for cond in ("pag", "none"):
            cfg = TrainConfig(cond=cond, steps=args.steps, preset=args.preset,
                              relations=args.relations, shape=args.shape,
                              noise_draws=args.noise_draws, device=args.device, seed=k,
                              split_seed=0 if args.train_seeds > 1 else None,
                              checkpoint_every=max(args.steps // 8, 1),
                              frame=args.frame if cond == "pag" else "world",
                              cpu_limit=None if args.cpu_limit is None
                              else args.cpu_limit + time.process_time() / 60.0)
            c0, w0 = time.process_time(), time.perf_counter()
            rep = train(dataset, sub / cond, cfg, log=print)
            cpu[cond][0] += time.process_time() - c0
            cpu[cond][1] += time.perf_counter() - w0
            last = rep.losses[-50:]
            print(f"{cond} (training seed {k}): {rep.steps} steps; loss {rep.losses[0]:.3f} -> "
                  f"{sum(last) / len(last):.3f}; val {rep.val_losses[-1:]}")
        runs = [load_run(sub / "pag", device=args.device),
                load_run(sub / "none", device=args.device)]
        files = held_out_scenes(runs[0])
        if args.max_scenes:
            files = files[:args.max_scenes]
        per_guide = []
        for g in guides:
            dest = sub / ("eval" if g == 0 else f"eval-guided-{g}")
            c0 = time.process_time()
            res = evaluate(runs, files, seeds=args.seeds, physics=not args.no_physics,
                           sample_steps=args.sample_steps, previews=2, out=dest,
                           progress=lambda s: print("  " + s, flush=True),
                           guidance=args.guidance, separate=args.separate, fit=args.fit, guide=g)
            write_result(res, dest)
            print(f"evaluation (training seed {k}, guide {g}): {len(res.scenes)} scenes, "
                  f"{time.process_time() - c0:.0f} s CPU")
            per_guide.append(res)
        _loss_figure(sub, sub / "eval" / "losses.png")
        results.append(per_guide)

    res = _combine(results, guides)
    print()
    print(res.markdown())
    if args.train_seeds > 1:
        print(f"Rows: mean ± standard deviation over {args.train_seeds} training seeds (each "
              f"the mean over {args.seeds} sampling seeds and the held-out scenes).")
    print(json.dumps({"training_scenes": _training_scenes(args.out, args.train_seeds),
                      "train_cpu_minutes": {k: round(v[0] / 60, 1) for k, v in cpu.items()},
                      "train_wall_minutes": {k: round(v[1] / 60, 1) for k, v in cpu.items()}}))
    for g in guides:
        label = "model only" if g == 0 else f"model + guidance ({g} steps)"
        rows = [r for r in res.rows if r.name.endswith(f"[{label}]")
                or (r.kind in ("solver", "random") and r.name.endswith("[model only]"))]
        print(f"\n{label}:")
        _claim(type(res)(rows, res.scenes, res.seeds, res.physics))
    return 0


def _training_scenes(out: Path, train_seeds: int) -> int | None:
    """Scenes in the first run's training split."""
    sub = out if train_seeds == 1 else out / "train-seed-0"
    try:
        return len(json.loads((sub / "pag" / "split.json").read_text())["train"])
    except (OSError, KeyError, ValueError):
        return None


def _combine(results: list[list], guides: tuple[int, ...]):
    """One table: every row of every guidance setting, labelled ``[model only]`` or
    ``[model + guidance (N steps)]``; with several training seeds each row's per-seed entries
    are the training seeds' means (over sampling seeds), so its ± is the spread over training."""
    from parse3d.layoutgen.evaluate import METRICS, EvalResult, EvalRow

    first = results[0][0]
    rows = []
    plain = {r.name for r in first.rows}
    for gi, g in enumerate(guides):
        label = "model only" if g == 0 else f"model + guidance ({g} steps)"
        for ri, row in enumerate(results[0][gi].rows):
            if gi > 0 and row.name in plain:
                continue  # the solver and the plain random poses: once, in the first part
            if len(results) == 1:
                per_seed = row.per_seed
            else:
                per_seed = [{m: r[gi].rows[ri].mean_std(m)[0] for m, _, _ in METRICS}
                            for r in results]
            rows.append(EvalRow(f"{row.name} [{label}]", row.kind, per_seed, []))
    return EvalResult(rows, first.scenes, len(results) if len(results) > 1 else first.seeds,
                      first.physics)


def _loss_figure(out: Path, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    fig, ax = plt.subplots(figsize=(6, 3.6), dpi=110)
    for cond, color in (("pag", "#d62728"), ("none", "#1f77b4")):
        ck = __import__("torch").load(out / cond / "checkpoint.pt", weights_only=False)
        y = np.asarray(ck["losses"], float)
        k = max(5, len(y) // 40)
        if len(y) > k:
            ax.plot(np.arange(k, len(y) + 1), np.convolve(y, np.ones(k) / k, "valid"), color=color,
                    label=f"{cond}: train ({k}-step mean)")
        if ck["val_losses"]:
            s, v = zip(*ck["val_losses"], strict=True)
            ax.plot(s, v, "o--", color=color, ms=3, label=f"{cond}: validation")
    ax.set_yscale("log")
    ax.set_xlabel("step")
    ax.set_ylabel("epsilon MSE")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def _claim(res) -> None:
    # the first row of each kind: the plain random poses, the unconditioned run (not the
    # dropped condition); every PAG-conditioned row (with and without the relation-aware step)
    none = next((r for r in res.rows if r.kind == "none" and "dropped" not in r.name), None)
    rnd = next((r for r in res.rows if r.kind == "random"), None)
    if none is None or rnd is None:
        return
    for pag in (r for r in res.rows if r.kind == "pag"):
        print(pag.name)
        _claim_row(pag, none, rnd)


def _claim_row(pag, none, rnd) -> None:
    for metric, better in (("relations", 1), ("relations_spatial", 1), ("relations_settled", 1),
                           ("support_rate", 1), ("collision_rate", -1)):
        (mp, sp), (mn, sn), (mr, _) = pag.mean_std(metric), none.mean_std(metric), rnd.mean_std(metric)
        if mp != mp:  # NaN: not measured (no physics)
            continue
        margin = better * (mp - mn)
        print(f"{metric}: PAG {mp:.3f}±{sp:.3f} vs unconditioned {mn:.3f}±{sn:.3f} "
              f"(margin {margin:+.3f}, spread {max(sp, sn):.3f}: "
              f"{'holds' if margin > max(sp, sn) else 'does not hold'}); random {mr:.3f}; "
              f"both beat random: {better * (mp - mr) > 0 and better * (mn - mr) > 0}")


if __name__ == "__main__":
    raise SystemExit(main())
