"""``parse3d vlm build|eval|baseline|ask|finetune``: the VLM spatial-reasoning benchmark."""

from __future__ import annotations

import sys
from pathlib import Path

import typer

from ..errors import InputError, Problem
from ._common import console, err_console, print_json


def _progress(label: str, enabled: bool):
    if not enabled:
        return None, (lambda done, total: None)
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    prog = Progress(TextColumn(f"[bold]{label}"), BarColumn(), MofNCompleteColumn(),
                    TimeElapsedColumn(), console=err_console, transient=True)
    task = prog.add_task(label, total=None)
    prog.start()

    def update(done: int, total: int) -> None:
        prog.update(task, completed=done, total=total)

    return prog, update


def register(app: typer.Typer) -> None:
    vlm = typer.Typer(name="vlm", no_args_is_help=True,
                      help="VLM spatial-reasoning benchmark: build, evaluate, baselines, "
                           "ask a model, fine-tune.")
    app.add_typer(vlm, name="vlm")

    @vlm.command("build")
    def build_cmd(
        dataset: Path = typer.Argument(..., help="Dataset folder (parse3d dataset build)."),
        out: Path = typer.Option(..., "--out", "-o", help="Benchmark folder to write."),
        views: int = typer.Option(0, "--views",
                                  help="Render this many views (into OUT/renders) for scenes "
                                       "that have fewer; 0 uses the dataset's views."),
        seed: int = typer.Option(0, "--seed", help="Seed of splits, pairs and distractors."),
        boxes: str = typer.Option("projected", "--boxes",
                                  help="SGG boxes: projected (3-D boxes) or mask (tight)."),
        min_pixels: int = typer.Option(400, "--min-pixels",
                                       help="Least mask pixels of a visible object or part."),
        min_share: float = typer.Option(0.30, "--min-share",
                                        help="Least share of the projected hull visible."),
        workers: int = typer.Option(1, "--workers", "-w",
                                    help="Worker processes (the output does not change)."),
        as_json: bool = typer.Option(False, "--json", help="Print the card as JSON."),
    ) -> None:
        """Make relation MCQ, part-contact MCQ and SGG items from a dataset's views.

        Writes OUT/train.jsonl, val.jsonl, test.jsonl (messages + images), OUT/images/ and the
        card OUT/vlm.json. The dataset folder is only read.

        Example: parse3d vlm build out/mini --out out/mini-vlm
        """
        from ..vlm.build import BuildOptions, build_benchmark
        from ..vlm.facts import VisibilityRule

        if min_pixels < 1 or not 0 <= min_share <= 1:
            raise InputError(Problem("", "--min-pixels must be >= 1 and --min-share in [0, 1]",
                                     "--min-pixels", "parameter"))
        opts = BuildOptions(seed=seed, views=views, boxes=boxes,
                            visibility=VisibilityRule(min_pixels=min_pixels,
                                                      min_share=min_share))
        prog, update = _progress("scenes", not as_json and sys.stderr.isatty())
        try:
            res = build_benchmark(dataset, out, opts, workers=workers, progress=update)
        finally:
            if prog is not None:
                prog.stop()
        if as_json:
            print_json(res.card)
            return
        c = res.card["counts"]
        console.print(f"[bold]{out}[/]: {c['all']['items']} items in {res.wall:.1f} s "
                      f"({len(res.card['scenes']['train'])}/{len(res.card['scenes']['val'])}/"
                      f"{len(res.card['scenes']['test'])} scenes train/val/test)")
        for split in ("train", "val", "test"):
            t = c[split]["tasks"]
            console.print(f"  {split:5s}: relation MCQ {t.get('relation_mcq', 0)}, "
                          f"contact MCQ {t.get('contact_mcq', 0)}, SGG {t.get('sgg', 0)}")
        nc = c["all"]["no_contact_share"]
        console.print(f"  'no contact' answers: relation MCQ {nc['relation_mcq']:.0%}, "
                      f"contact MCQ {nc['contact_mcq']:.0%}; answer letters "
                      f"{c['all']['answer_letters']}")
        if res.rendered:
            console.print(f"  rendered views for {res.rendered} scenes into {out}/renders/")
        console.print(f"  card: {out}/vlm.json")

    @vlm.command("eval")
    def eval_cmd(
        gt: Path = typer.Option(..., "--gt", help="Benchmark split (VLM_DIR/test.jsonl)."),
        pred: list[Path] = typer.Option(..., "--pred",
                                        help="Prediction JSONL ({id, response} per line); "
                                             "repeat to compare several."),
        allow_missing: bool = typer.Option(False, "--allow-missing",
                                           help="Score missing ids as wrong instead of "
                                                "refusing."),
        iou: float = typer.Option(0.5, "--iou", help="IoU threshold of SGG box matching."),
        as_json: bool = typer.Option(False, "--json", help="Print the metrics as JSON."),
    ) -> None:
        """Score predictions: MCQ accuracy, SGG recall/precision/F1 with and without box
        matching, as the paper's Table 2 (Markdown), or --json.

        Example: parse3d vlm eval --gt out/mini-vlm/test.jsonl --pred out/qwen3vl.jsonl
        """
        from ..vlm.build import read_jsonl
        from ..vlm.evaluate import evaluate, evaluate_files, markdown_table, read_predictions

        if not 0 < iou <= 1:
            raise InputError(Problem("", "--iou must be in (0, 1]", "--iou", "parameter"))
        reports = []
        for p in pred:
            if iou == 0.5:
                reports.append(evaluate_files(gt, p, allow_missing=allow_missing))
            else:
                rep = evaluate(read_jsonl(gt), read_predictions(p), model=p.stem, iou=iou)
                reports.append(rep)
        if as_json:
            print_json([r.to_dict() for r in reports] if len(reports) > 1
                       else reports[0].to_dict())
            return
        typer.echo(markdown_table(reports))

    @vlm.command("baseline")
    def baseline_cmd(
        name: str = typer.Argument(..., help="random, prior, blind, oracle or perturbed."),
        data: Path = typer.Option(..., "--data", help="Benchmark split (VLM_DIR/test.jsonl)."),
        out: Path = typer.Option(..., "--out", "-o", help="Prediction JSONL to write."),
        seed: int = typer.Option(0, "--seed", help="Seed (random, perturbed)."),
        dataset: Path = typer.Option(None, "--dataset",
                                     help="The dataset folder if it moved (oracle)."),
    ) -> None:
        """Write a baseline's predictions for a split; score them with parse3d vlm eval.

        Example: parse3d vlm baseline oracle --data out/mini-vlm/test.jsonl --out oracle.jsonl
        """
        import json

        from ..vlm.baselines import run_baseline

        answers = run_baseline(name, data, seed=seed, dataset=dataset)
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_text("".join(json.dumps({"id": k, "response": v}) + "\n"
                               for k, v in answers.items()))
        console.print(f"{name}: {len(answers)} predictions -> {out}")
