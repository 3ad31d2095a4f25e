"""``parse3d vlm build|eval|baseline|ask|finetune``: the VLM spatial-reasoning benchmark."""

from __future__ import annotations

import sys
from pathlib import Path

import typer

from .._deps import require
from ..errors import InputError, Problem
from ._common import console, err_console, print_json


def _progress(label: str, enabled: bool):
    if not enabled:
        return None, (lambda done, total: None)
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    prog = Progress(TextColumn(f"[bold]{label}"), BarColumn(), MofNCompleteColumn(),
                    TimeElapsedColumn(), console=err_console.get(), transient=True)
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
        min_in_image: float = typer.Option(0.60, "--min-in-image",
                                           help="Least share of an object's projection "
                                                "inside the image (cut-off objects are "
                                                "not asked about)."),
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

        if views > 0:
            require("moderngl", feature="vlm build --views (rendering)")

        if min_pixels < 1 or not 0 <= min_in_image <= 1:
            raise InputError(Problem("", "--min-pixels must be >= 1 and --min-in-image in "
                                         "[0, 1]",
                                     "--min-pixels", "parameter"))
        opts = BuildOptions(seed=seed, views=views, boxes=boxes,
                            visibility=VisibilityRule(min_pixels=min_pixels,
                                                      min_in_image=min_in_image))
        prog, update = _progress("scene passes", not as_json and sys.stderr.isatty())
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
        more: list[Path] = typer.Argument(None, metavar="[PRED]...",
                                          help="More prediction files (--pred a b)."),
        allow_missing: bool = typer.Option(False, "--allow-missing",
                                           help="Score missing ids as wrong instead of "
                                                "refusing."),
        iou: float = typer.Option(0.5, "--iou", help="IoU threshold of SGG box matching."),
        as_json: bool = typer.Option(False, "--json", help="Print the metrics as JSON."),
    ) -> None:
        """Score predictions as the paper's Table 2 (Markdown), or --json.

        MCQ accuracy (per relation and room type); SGG recall, precision and F1 with and
        without box matching, and the average number of predicted relations.

        Example: parse3d vlm eval --gt out/mini-vlm/test.jsonl --pred out/qwen3vl.jsonl
        """
        from ..vlm.evaluate import evaluate_files, markdown_table

        if not 0 < iou <= 1:
            raise InputError(Problem("", "--iou must be in (0, 1]", "--iou", "parameter"))
        reports = []
        for p in [*pred, *(more or [])]:
            reports.append(evaluate_files(gt, p, allow_missing=allow_missing, iou=iou))
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

    @vlm.command("ask")
    def ask_cmd(
        data: Path = typer.Option(..., "--data", help="Benchmark split (VLM_DIR/test.jsonl)."),
        out: Path = typer.Option(..., "--out", "-o",
                                 help="Prediction JSONL (appended; answered ids are skipped)."),
        endpoint: str = typer.Option(None, "--endpoint",
                                     help="OpenAI-compatible base URL, e.g. "
                                          "http://127.0.0.1:8000/v1."),
        model: str = typer.Option(None, "--model", help="Model name at the endpoint."),
        local: Path = typer.Option(None, "--local", help="Local model folder instead."),
        adapter: Path = typer.Option(None, "--adapter",
                                     help="LoRA adapter folder (with --local)."),
        concurrency: int = typer.Option(4, "--concurrency", "-j", help="Requests in flight."),
        retries: int = typer.Option(4, "--retries", help="Retries per item (backoff doubles)."),
        backoff: float = typer.Option(1.0, "--backoff", help="Seconds before the first retry."),
        timeout: float = typer.Option(120.0, "--timeout", help="Seconds per request."),
        max_tokens: int = typer.Option(1024, "--max-tokens", help="Longest answer (tokens)."),
        api_key_env: str = typer.Option("OPENAI_API_KEY", "--api-key-env",
                                        help="Environment variable holding the API key."),
        price_in: float = typer.Option(0.0, "--price-in",
                                       help="USD per million prompt tokens (cost line)."),
        price_out: float = typer.Option(0.0, "--price-out",
                                        help="USD per million completion tokens."),
        limit: int = typer.Option(None, "--limit", help="Ask only the first N items."),
        as_json: bool = typer.Option(False, "--json", help="Print the summary as JSON."),
    ) -> None:
        """Run a model on benchmark items: an OpenAI-compatible endpoint or a local folder.

        Exactly one of --endpoint/--model or --local [--adapter]. Interrupted runs resume.

        Example: parse3d vlm ask --endpoint http://127.0.0.1:8000/v1 --model Qwen3-VL-8B-Instruct --data out/mini-vlm/test.jsonl --out qwen.jsonl
        """
        from ..vlm.build import read_jsonl
        from ..vlm.client import EndpointOptions, api_key_from_env, ask_endpoint, ask_local

        remote = endpoint is not None or model is not None
        if remote == (local is not None) or (remote and (endpoint is None or model is None)):
            raise InputError(Problem("", "give exactly one of --endpoint URL --model NAME, or "
                                         "--local MODEL_DIR [--adapter DIR]", "--endpoint",
                                     "parameter"))
        if adapter is not None and local is None:
            raise InputError(Problem("", "--adapter needs --local MODEL_DIR", "--adapter",
                                     "parameter"))
        if endpoint is not None and not endpoint.startswith(("http://", "https://")):
            raise InputError(Problem("", f"--endpoint must be an http(s) URL, got {endpoint!r}",
                                     "--endpoint", "parameter"))
        if local is not None:
            require("torch", "transformers", *(("peft",) if adapter is not None else ()),
                    feature="vlm ask --local")
        else:
            require("httpx", feature="vlm ask --endpoint")
        rows = read_jsonl(data)
        if limit is not None:
            rows = rows[:limit]
        try:
            if local is not None:
                s = ask_local(rows, data.parent, out, model_dir=local, adapter=adapter,
                              max_new_tokens=max_tokens)
            else:
                opts = EndpointOptions(concurrency=concurrency, retries=retries,
                                       backoff=backoff, timeout=timeout, max_tokens=max_tokens,
                                       api_key=api_key_from_env(api_key_env),
                                       price_in=price_in, price_out=price_out)
                s = ask_endpoint(rows, data.parent, out, endpoint=endpoint, model=model,
                                 options=opts)
        except KeyboardInterrupt:
            err_console.print(f"interrupted: the answers so far are in {out}; run the same "
                              "command again to ask only the rest")
            raise typer.Exit(130) from None
        d = s.to_dict()
        if as_json:
            print_json(d)
        else:
            console.print(f"{out}: {d['answered']} answered, {d['resumed']} already there, "
                          f"{d['failed']} failed in {d['wall_s']} s "
                          f"({d['items_per_s']} items/s; latency mean {d['latency_s']['mean']} "
                          f"s, p95 {d['latency_s']['p95']} s; {d['retries']} retries); tokens "
                          f"{d['prompt_tokens']} in / {d['completion_tokens']} out"
                          + (f"; cost ${d['cost_usd']:.4f}" if d["cost_usd"] else ""))
            for f in d["failed_ids"]:
                err_console.print(f"  failed: {f}")
        if s.failed:
            raise typer.Exit(1)

    @vlm.command("finetune")
    def finetune_cmd(
        model: Path = typer.Option(..., "--model", help="Local Qwen2.5-VL / Qwen3-VL folder."),
        data: Path = typer.Option(..., "--data", help="Benchmark folder (uses train.jsonl)."),
        out: Path = typer.Option(..., "--out", "-o", help="Adapter folder to write."),
        rank: int = typer.Option(8, "--rank", help="LoRA rank."),
        alpha: int = typer.Option(32, "--alpha", help="LoRA alpha."),
        lr: float = typer.Option(1e-4, "--lr", help="Peak learning rate (AdamW)."),
        min_lr: float = typer.Option(1e-5, "--min-lr", help="Final learning rate."),
        warmup: float = typer.Option(0.05, "--warmup", help="Share of updates warming up."),
        global_batch: int = typer.Option(16, "--global-batch", help="Items per update."),
        micro_batch: int = typer.Option(2, "--micro-batch", help="Items per device and pass."),
        epochs: float = typer.Option(1.0, "--epochs", help="Passes over the mixed set."),
        max_image_tokens: int = typer.Option(1024, "--max-image-tokens",
                                             help="Merged image tokens per image at most."),
        ratios: str = typer.Option("relation_mcq=1,contact_mcq=1,sgg=1", "--ratios",
                                   help="Task sampling ratios."),
        max_items: int = typer.Option(None, "--max-items", help="Train on the first N items."),
        seed: int = typer.Option(0, "--seed", help="Seed of mixing and initialisation."),
        checkpointing: bool = typer.Option(True, "--gradient-checkpointing/--no-gradient-"
                                                 "checkpointing",
                                           help="Recompute activations (less memory)."),
        group_by_length: bool = typer.Option(True, "--group-by-length/--no-group-by-length",
                                             help="Micro-batches of similar lengths."),
        device_map: str = typer.Option(None, "--device-map",
                                       help="transformers device_map, e.g. auto: spread a "
                                            "model too large for one GPU over the GPUs."),
        as_json: bool = typer.Option(False, "--json", help="Print the result as JSON."),
    ) -> None:
        """Fine-tune a LoRA adapter with the paper's recipe (rank 8, alpha 32, lr 1e-4, ...).

        Example: parse3d vlm finetune --model models/Qwen3-VL-8B-Instruct --data out/mini-vlm --out out/lora
        """
        from ..vlm.finetune import FinetuneOptions, finetune

        require("torch", "transformers", "peft", feature="vlm finetune")

        mix = {}
        for part in ratios.split(","):
            k, sep, v = part.partition("=")
            try:
                mix[k.strip()] = float(v)
            except ValueError:
                sep = ""
            if not sep:
                raise InputError(Problem("", f"--ratios wants task=ratio pairs, e.g. "
                                             f"relation_mcq=1,contact_mcq=1,sgg=0.5; got "
                                             f"{ratios!r}", "--ratios", "parameter"))
        opts = FinetuneOptions(rank=rank, alpha=alpha, lr=lr, min_lr=min_lr, warmup=warmup,
                               global_batch=global_batch, micro_batch=micro_batch,
                               epochs=epochs, max_image_tokens=max_image_tokens, ratios=mix,
                               max_items=max_items, seed=seed,
                               gradient_checkpointing=checkpointing,
                               group_by_length=group_by_length, device_map=device_map)

        def show(step: int, total: int, loss: float, rate: float) -> None:
            if not as_json:
                err_console.print(f"update {step}/{total}: loss {loss:.4f}, lr {rate:.2e}")

        res = finetune(model, data, out, opts, progress=show)
        d = {"out": str(res.out), "updates": res.steps, "first_loss": res.losses[0],
             "last_loss": res.losses[-1], "val_loss": res.val_loss, "devices": res.devices,
             "accumulation": res.accumulation, "wall_s": round(res.wall, 2)}
        if as_json:
            print_json(d)
            return
        console.print(f"{out}: {res.steps} updates on {res.devices} device(s) (accumulation "
                      f"{res.accumulation}), loss {res.losses[0]:.4f} -> {res.losses[-1]:.4f}"
                      + (f", val loss {res.val_loss:.4f}" if res.val_loss is not None else "")
                      + f" in {res.wall:.1f} s; use it with parse3d vlm ask --local {model} "
                        f"--adapter {out}")
