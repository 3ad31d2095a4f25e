"""``parse3d layout train|sample|eval``: PAG-conditioned layout diffusion."""

from __future__ import annotations

import sys
from pathlib import Path

import typer

from .._deps import require
from ..errors import InputError, Problem
from ._common import console, err_console, print_json


def _threads(n: int) -> None:
    if n < 1:
        raise InputError(Problem("", f"--threads must be at least 1, got {n}", "--threads",
                                 "parameter"))
    # every layout command runs the diffusion model: name the extra before any work
    require("torch", "diffusers", feature="layout diffusion")
    import torch

    torch.set_num_threads(n)


def _positive(name: str, value: int) -> None:
    if value < 1:
        raise InputError(Problem("", f"{name} must be at least 1, got {value}", name, "parameter"))


def register(app: typer.Typer) -> None:
    lay = typer.Typer(name="layout", no_args_is_help=True,
                      help="Layout diffusion conditioned on PAGs: train, sample, evaluate.")
    app.add_typer(lay, name="layout")

    threads_opt = typer.Option(1, "--threads", help="torch CPU threads (1 is fastest on a "
                                                    "small or shared machine).")

    @lay.command("train")
    def train_cmd(
        dataset: Path = typer.Argument(..., help="Dataset folder (parse3d dataset build)."),
        out: Path = typer.Option(..., "--out", "-o", help="Run folder (resumed if it holds a checkpoint)."),
        cond: str = typer.Option("pag", "--cond", help="pag (PAG-conditioned) or none."),
        steps: int = typer.Option(2000, "--steps", help="Optimiser steps in total."),
        preset: str = typer.Option("cpu", "--preset",
                                   help="cpu (d=128, 4 layers), small (d=64, 3 layers), paper "
                                        "(512-d) or tiny."),
        relations: str = typer.Option("text", "--relations",
                                      help="Relation embedding: text (MiniLM phrases) or learned."),
        shape: str = typer.Option("descriptor", "--shape",
                                  help="Shape encoder: descriptor (fixed) or pointcloud (learned "
                                       "on the pool's surface points)."),
        noise_draws: int = typer.Option(16, "--noise-draws", help="Noise draws per scene and step."),
        cond_dropout: float = typer.Option(0.1, "--cond-dropout",
                                           help="Condition dropout for guidance (pag runs)."),
        seed: int = typer.Option(0, "--seed", help="Seed of the split, initialisation and noise."),
        checkpoint_every: int = typer.Option(250, "--checkpoint-every", help="Steps between checkpoints."),
        device: str = typer.Option("cpu", "--device", help="cpu or cuda."),
        frame: str = typer.Option("world", "--frame",
                                  help="pag runs: translation of a supported object in the "
                                       "world (world) or in its support parent's frame (parent)."),
        time_limit: float = typer.Option(None, "--time-limit",
                                         help="Minutes of wall time; stops (with a checkpoint) "
                                              "before --steps when reached."),
        cpu_limit: float = typer.Option(None, "--cpu-limit",
                                        help="Minutes of CPU time of this process (loading "
                                             "included); stops (with a checkpoint) before "
                                             "--steps when reached."),
        threads: int = threads_opt,
        as_json: bool = typer.Option(False, "--json", help="Print a JSON summary."),
    ) -> None:
        """Train a layout model on DATASET's settled scenes (or resume one).

        Writes config.json, split.json, stats.json, checkpoint.pt (with EMA weights),
        loss.png and losses.csv to --out.

        Example: parse3d layout train out/mini --out runs/pag --cond pag --steps 3000
        """
        from ..layoutgen.train import TrainConfig, train

        _threads(threads)
        cfg = TrainConfig(cond=cond, steps=steps, preset=preset, relations=relations,
                          shape=shape, noise_draws=noise_draws, cond_dropout=cond_dropout, seed=seed,
                          checkpoint_every=checkpoint_every, device=device, frame=frame,
                          time_limit=time_limit, cpu_limit=cpu_limit)
        cfg.check()
        from rich.progress import (
            BarColumn,
            MofNCompleteColumn,
            Progress,
            TextColumn,
            TimeRemainingColumn,
        )

        prog = Progress(TextColumn("[bold]train"), BarColumn(), MofNCompleteColumn(),
                        TextColumn("loss {task.fields[loss]:.4f}"), TimeRemainingColumn(),
                        console=err_console.get(), disable=as_json or not sys.stderr.isatty())
        with prog:
            task = prog.add_task("train", total=steps, loss=float("nan"))

            def on_step(step: int, total: int, loss: float) -> None:
                prog.update(task, completed=step, loss=loss)

            rep = train(dataset, out, cfg, progress=on_step,
                        log=None if as_json else (lambda s: err_console.print(s)))
        last = rep.losses[-50:]
        summary = {"run": str(rep.run), "start_step": rep.start_step, "steps": rep.steps,
                   "seconds": round(rep.seconds, 2),
                   "loss_first": rep.losses[0] if rep.losses else None,
                   "loss_last50": sum(last) / len(last) if last else None,
                   "val_losses": rep.val_losses}
        if as_json:
            print_json(summary)
            return
        console.print(f"trained {out} to step {rep.steps} ({rep.steps - rep.start_step} steps "
                      f"in {rep.seconds:.1f} s); loss {summary['loss_first']:.4f} -> "
                      f"{summary['loss_last50']:.4f} (mean of the last {len(last)})")
        console.print(f"  wrote {out}/checkpoint.pt, config.json, split.json, stats.json, loss.png")

    @lay.command("sample")
    def sample_cmd(
        run: Path = typer.Argument(..., help="Run folder (parse3d layout train)."),
        pag_file: Path = typer.Option(..., "--pag", help="PAG file (JSON or YAML)."),
        out: Path = typer.Option(..., "--out", "-o", help="Scene folder to write."),
        seed: int = typer.Option(0, "--seed", help="Sampling seed."),
        sample_steps: int = typer.Option(100, "--sample-steps", help="Denoising steps."),
        guidance: float = typer.Option(1.0, "--guidance",
                                       help="Classifier-free guidance weight (1: plain conditional)."),
        uncond: bool = typer.Option(False, "--uncond", help="Drop the PAG condition."),
        separate: int = typer.Option(0, "--separate", min=0,
                                     help="Separation guidance: push interpenetrating objects "
                                          "apart during the last N denoising steps (0: off)."),
        guide: int = typer.Option(0, "--guide", min=0,
                                  help="Physics guidance: keep the objects' collision pieces "
                                       "apart and in the room during the last N denoising "
                                       "steps, with the PAG's supports when conditioned on "
                                       "it (0: off)."),
        fit: bool = typer.Option(False, "--fit",
                                 help="Relation-aware step: bring the PAG's contacts (ON, IN, "
                                      "AGAINST, SECURED_TO) to their surfaces and move what "
                                      "still collides within the freedom its relations leave."),
        refine: bool = typer.Option(False, "--refine",
                                    help="Hand the generated poses to the solver as its first "
                                         "proposals; report how many it kept."),
        device: str = typer.Option("cpu", "--device", help="cpu or cuda."),
        threads: int = threads_opt,
        as_json: bool = typer.Option(False, "--json", help="Print a JSON summary."),
    ) -> None:
        """Generate a layout for a PAG: OUT/scene.json and OUT/scene.glb with pool assets.

        The folder is a normal scene: 'parse3d settle OUT' and 'parse3d render OUT' accept it.
        With --refine the solver lays the PAG out starting from the generated poses (snapped
        upright and onto their supports); scene.json's meta.refine says which it kept.

        Example: parse3d layout sample runs/pag --pag examples/study.json --out out/gen-study
        """
        from ..layoutgen.sample import SampleOptions, sample_layout
        from ..layoutgen.train import load_run
        from ..pag.io import load_pag
        from ..pipeline import write_outputs

        _threads(threads)
        _positive("--sample-steps", sample_steps)
        r = load_run(run, device=device)
        pag = load_pag(pag_file)
        scene = sample_layout(r, pag, seed=seed, file=str(pag_file),
                              options=SampleOptions(steps=sample_steps, guidance=guidance,
                                                    cond=not uncond, separate=separate,
                                                    fit=fit, guide=guide))
        gen_held = sum(1 for c in scene.relations if c.holds)
        rep = None
        if refine:
            from ..layoutgen.sample import refine_layout

            with err_console.status("refining with the solver"):
                scene, rep = refine_layout(scene, seed=seed)
        write_outputs(scene, out)
        held = sum(1 for c in scene.relations if c.holds)
        if as_json:
            print_json({"out": str(out), "objects": len(scene.objects),
                        "relations": len(scene.relations), "relations_held": held,
                        "relations_held_generated": gen_held,
                        "refine": rep.to_dict() if rep is not None else None,
                        "timings": scene.timings})
            return
        console.print(f"generated {len(scene.objects)} objects with {r.name} (step {r.step}, "
                      f"{scene.meta['cond']}) in {scene.timings['generate']:.1f} s; "
                      f"{gen_held}/{len(scene.relations)} relations hold as generated")
        if rep is not None:
            console.print(f"refined: the solver kept {len(rep.kept)} of {rep.proposed} generated "
                          f"poses, placed {rep.placed} objects ({rep.failed} failed); "
                          f"{held}/{len(scene.relations)} relations hold")
        console.print(f"  wrote {out}/scene.json, scene.glb — next: parse3d settle {out}")

    @lay.command("eval")
    def eval_cmd(
        runs: list[Path] = typer.Argument(..., help="Run folders; each is a row."),
        dataset: Path = typer.Option(None, "--dataset",
                                     help="Held-out scenes (default: the first run's test split)."),
        out: Path = typer.Option(None, "--out", "-o", help="Output folder (default: RUN/eval)."),
        seeds: int = typer.Option(3, "--seeds", help="Sampling seeds per model."),
        max_scenes: int = typer.Option(0, "--max-scenes", help="Use at most this many scenes (0: all)."),
        no_physics: bool = typer.Option(False, "--no-physics",
                                        help="Skip settling and contacts (fast)."),
        sample_steps: int = typer.Option(100, "--sample-steps", help="Denoising steps."),
        guidance: float = typer.Option(1.0, "--guidance",
                                       help="Classifier-free guidance of the PAG rows (1: plain)."),
        separate: int = typer.Option(0, "--separate", min=0,
                                     help="Separation guidance in every generated row (the "
                                          "random one too): the last N denoising steps (0: off)."),
        guide: int = typer.Option(0, "--guide", min=0,
                                  help="Physics guidance in every model row: the last N "
                                       "denoising steps (0: off), with the PAG's supports in "
                                       "the PAG-conditioned rows; adds random poses after as "
                                       "many guidance passes as a control row."),
        fit: bool = typer.Option(False, "--fit",
                                 help="Add each PAG-conditioned row's samples after the "
                                      "relation-aware step, and random poses with it."),
        previews: int = typer.Option(2, "--previews", help="Scenes to render side by side."),
        device: str = typer.Option("cpu", "--device", help="cpu or cuda."),
        threads: int = threads_opt,
        as_json: bool = typer.Option(False, "--json", help="Print the JSON result."),
    ) -> None:
        """Measure runs against the solver and random poses on held-out PAGs.

        Writes eval.md, eval.json and previews/<scene>.png (one column per row).

        Example: parse3d layout eval runs/pag runs/none --seeds 3 --out runs/eval
        """
        from ..layoutgen.evaluate import evaluate, held_out_scenes, write_result
        from ..layoutgen.train import load_run

        _threads(threads)
        _positive("--seeds", seeds)
        _positive("--sample-steps", sample_steps)
        loaded = [load_run(r, device=device) for r in runs]
        files = held_out_scenes(loaded[0], dataset)
        if not files:
            raise InputError(Problem("", "the run has no test scenes — give --dataset",
                                     str(runs[0] / "split.json"), "io"))
        if max_scenes > 0:
            files = files[:max_scenes]
        dest = out if out is not None else runs[0] / "eval"
        with err_console.status("evaluating") as st:
            res = evaluate(loaded, files, seeds=seeds, physics=not no_physics,
                           sample_steps=sample_steps, previews=previews, out=dest,
                           progress=None if as_json else (lambda s: st.update(s)),
                           guidance=guidance, separate=separate, fit=fit, guide=guide)
        if not res.scenes:
            raise InputError(Problem("", "no held-out scene has only categories the runs know",
                                     str(dataset or runs[0]), "vocabulary"))
        j, md = write_result(res, dest)
        if as_json:
            print_json(res.to_dict())
            return
        console.print(res.markdown())
        console.print(f"wrote {j}, {md}" + (f", {len(res.previews)} previews" if res.previews else ""))
