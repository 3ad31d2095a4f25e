"""The one-GPU run: zero-shot Qwen3-VL served by vLLM, then LoRA fine-tuning and its score.

Usage (one H100 / H200, a benchmark from ``parse3d vlm build``)::

    # zero-shot: start vLLM on the model, ask the test split, stop the server, score
    python benchmarks/vlm_gpu_run.py zero-shot --bench out/mini-vlm --serve \\
        --model Qwen/Qwen3-VL-8B-Instruct --out out/gpu
    # or against a server that is already running (vLLM, SGLang, parse3d.vlm.serve)
    python benchmarks/vlm_gpu_run.py zero-shot --bench out/mini-vlm \\
        --endpoint http://127.0.0.1:8000/v1 --model Qwen/Qwen3-VL-8B-Instruct --out out/gpu
    # LoRA on a local 8B folder (bf16, gradient checkpointing, length-grouped batches),
    # then the adapter answers the test split
    python benchmarks/vlm_gpu_run.py lora --bench out/mini-vlm \\
        --model models/Qwen3-VL-8B-Instruct --out out/gpu
    # a model that does not fit the GPU: its layers spread over GPU and CPU memory
    python benchmarks/vlm_gpu_run.py lora --bench out/mini-vlm \\
        --model models/Qwen3-VL-30B-A3B-Instruct --device-map auto --out out/gpu-moe
    # several GPUs: an accelerate FSDP config, then accelerate launch ... lora ...
    python benchmarks/vlm_gpu_run.py fsdp-config --processes 8 --out out/fsdp.yaml

Every step writes under ``--out``: ``zero-shot.jsonl`` / ``lora.jsonl`` (predictions,
resumable), ``lora/`` (the adapter and ``finetune.json``) and ``report.json`` (the scores of
``parse3d vlm eval``, the ask summary and the settings), and prints the Table 2 row. The same
code runs on a CPU: with a tiny model (``parse3d.vlm.tiny``) and a small benchmark it is what
the tests run; on a GPU, bfloat16 and CUDA are taken when present.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

from parse3d.vlm.build import read_jsonl
from parse3d.vlm.client import EndpointOptions, api_key_from_env, ask_endpoint, ask_local
from parse3d.vlm.evaluate import evaluate, markdown_table
from parse3d.vlm.finetune import FinetuneOptions, finetune


def _test_rows(bench: Path, limit: int) -> list[dict]:
    rows = read_jsonl(bench / "test.jsonl")
    if limit:  # the first items of every task, so a short run still covers the three
        by_task: dict[str, list[dict]] = {}
        for r in rows:
            by_task.setdefault(r["task"], []).append(r)
        rows = [r for rs in by_task.values() for r in rs[:limit]]
    return rows


def _score(name: str, rows: list[dict], pred: Path, out: Path, extra: dict) -> dict:
    answers = {r["id"]: r["response"] for r in read_jsonl(pred)}
    rep = evaluate(rows, {k: v for k, v in answers.items() if k in {r["id"] for r in rows}},
                   model=name)
    print(markdown_table([rep]), flush=True)
    path = out / "report.json"
    doc = json.loads(path.read_text()) if path.exists() else {}
    doc[name] = {"scores": rep.to_dict(), **extra}
    path.write_text(json.dumps(doc, indent=1) + "\n")
    return doc[name]


def wait_ready(endpoint: str, timeout: float, server: subprocess.Popen | None = None) -> None:
    """Block until ``endpoint``/models answers 200 (the server has loaded its model)."""
    import httpx

    t0 = time.perf_counter()
    while time.perf_counter() - t0 < timeout:
        if server is not None and server.poll() is not None:
            sys.exit(f"the server stopped (exit {server.returncode}) before it was ready")
        try:
            if httpx.get(endpoint.rstrip("/") + "/models", timeout=5).status_code == 200:
                return
        except httpx.HTTPError:
            pass
        time.sleep(2)
    sys.exit(f"no server answered at {endpoint} within {timeout:.0f} s")


def vllm_command(model: str, port: int, max_model_len: int) -> list[str]:
    """``vllm serve`` for one GPU: one image per prompt, bf16, the model's own name."""
    return ["vllm", "serve", model, "--port", str(port), "--dtype", "bfloat16",
            "--max-model-len", str(max_model_len), "--limit-mm-per-prompt", '{"image": 1}',
            "--gpu-memory-utilization", "0.90"]


def zero_shot(args) -> dict:
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    rows = _test_rows(args.bench, args.limit)
    endpoint, server = args.endpoint, None
    if args.serve:
        endpoint = f"http://127.0.0.1:{args.port}/v1"
        cmd = vllm_command(args.model, args.port, args.max_model_len)
        print("starting:", " ".join(cmd), flush=True)
        server = subprocess.Popen(cmd)
    try:
        wait_ready(endpoint, args.ready_timeout, server)
        opts = EndpointOptions(concurrency=args.concurrency, max_tokens=args.max_tokens,
                               api_key=api_key_from_env(args.api_key_env))
        pred = out / "zero-shot.jsonl"
        summary = ask_endpoint(rows, args.bench, pred, endpoint=endpoint, model=args.model,
                               options=opts)
    finally:
        if server is not None:
            server.terminate()
            server.wait(timeout=120)
    return _score("zero-shot", rows, pred, out,
                  {"model": args.model, "endpoint": endpoint, "ask": summary.to_dict()})


def lora(args) -> dict:
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    opts = FinetuneOptions(rank=args.rank, alpha=args.alpha, lr=args.lr, epochs=args.epochs,
                           global_batch=args.global_batch, micro_batch=args.micro_batch,
                           max_items=args.max_items or None,
                           max_image_tokens=args.max_image_tokens,
                           gradient_checkpointing=not args.no_gradient_checkpointing,
                           group_by_length=True, device_map=args.device_map,
                           val_items=args.val_items)
    t = time.perf_counter()
    res = finetune(args.model, args.bench, out / "lora", opts, progress=lambda s, n, loss, lr:
                   print(f"  update {s}/{n}: loss {loss:.4f}, lr {lr:.2e}", flush=True))
    train_s = time.perf_counter() - t
    rows = _test_rows(args.bench, args.limit)
    pred = out / "lora.jsonl"
    summary = ask_local(rows, args.bench, pred, model_dir=args.model, adapter=out / "lora",
                        max_new_tokens=args.max_tokens)
    return _score("lora", rows, pred, out,
                  {"model": str(args.model), "train_s": round(train_s, 1),
                   "updates": res.steps, "val_loss": res.val_loss,
                   "ask": summary.to_dict()})


def fsdp_config(args) -> None:
    """An accelerate FSDP config: every parameter, gradient and optimiser state sharded over
    the processes (and kept in CPU memory with ``--offload``), transformer-block wrapping."""
    lines = ["compute_environment: LOCAL_MACHINE", "distributed_type: FSDP",
             "mixed_precision: bf16", f"num_processes: {args.processes}", "num_machines: 1",
             "machine_rank: 0", "fsdp_config:",
             "  fsdp_version: 2",
             "  fsdp_auto_wrap_policy: TRANSFORMER_BASED_WRAP",
             "  fsdp_reshard_after_forward: true",
             f"  fsdp_offload_params: {'true' if args.offload else 'false'}",
             "  fsdp_cpu_ram_efficient_loading: true",
             "  fsdp_state_dict_type: SHARDED_STATE_DICT"]
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text("\n".join(lines) + "\n")
    print(f"wrote {args.out}; run: accelerate launch --config_file {args.out} "
          "benchmarks/vlm_gpu_run.py lora --bench BENCH --model MODEL --out OUT")


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("step", choices=("zero-shot", "lora", "fsdp-config"),
                    help="zero-shot: ask a served model the test split and score it; lora: "
                         "fine-tune a LoRA adapter, answer the test split, score; fsdp-config: "
                         "write an accelerate FSDP config to --out")
    ap.add_argument("--bench", type=Path, help="benchmark folder (parse3d vlm build)")
    ap.add_argument("--model", help="served model name (zero-shot) or model folder (lora)")
    ap.add_argument("--out", type=Path, required=True,
                    help="results folder (the config file for fsdp-config)")
    ap.add_argument("--limit", type=int, default=0, help="test items per task at most")
    ap.add_argument("--max-tokens", type=int, default=1024, help="answer tokens at most")
    z = ap.add_argument_group("zero-shot")
    z.add_argument("--endpoint", default="http://127.0.0.1:8000/v1")
    z.add_argument("--serve", action="store_true", help="start vllm serve on --model first")
    z.add_argument("--port", type=int, default=8000)
    z.add_argument("--max-model-len", type=int, default=16384)
    z.add_argument("--ready-timeout", type=float, default=1800.0)
    z.add_argument("-j", "--concurrency", type=int, default=32)
    z.add_argument("--api-key-env", default="OPENAI_API_KEY")
    lo = ap.add_argument_group("lora")
    lo.add_argument("--rank", type=int, default=8)
    lo.add_argument("--alpha", type=int, default=32)
    lo.add_argument("--lr", type=float, default=1e-4)
    lo.add_argument("--epochs", type=float, default=1.0)
    lo.add_argument("--global-batch", type=int, default=16)
    lo.add_argument("--micro-batch", type=int, default=4)
    lo.add_argument("--max-items", type=int, default=0, help="training items at most")
    lo.add_argument("--max-image-tokens", type=int, default=1024)
    lo.add_argument("--val-items", type=int, default=64)
    lo.add_argument("--device-map", default=None,
                    help="auto: spread a model too large for the GPU over GPU and CPU memory")
    lo.add_argument("--no-gradient-checkpointing", action="store_true")
    f = ap.add_argument_group("fsdp-config")
    f.add_argument("--processes", type=int, default=1)
    f.add_argument("--offload", action="store_true", help="keep parameters in CPU memory")
    args = ap.parse_args(argv)
    if args.step != "fsdp-config" and (args.bench is None or args.model is None):
        ap.error(f"{args.step} needs --bench and --model")
    if args.step == "zero-shot":
        zero_shot(args)
    elif args.step == "lora":
        lora(args)
    else:
        fsdp_config(args)


if __name__ == "__main__":
    main()
