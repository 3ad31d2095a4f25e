"""``parse3d vlm finetune``: the paper's LoRA recipe (Appendix A.4) with transformers + peft.

Defaults are the paper's: LoRA rank 8, alpha 32 on every linear layer of the language model
(attention and MLP projections; the vision tower and the LM head stay frozen) and, in a
mixture-of-experts model (Qwen3-VL-30B-A3B, -235B-A22B), on its experts, which are 3-D
parameters rather than linear layers (peft's ``target_parameters``), AdamW at
1e-4 with a linear warm-up over 5% of the updates then a cosine decay to 1e-5, a global
batch of 16 (micro-batch 2 per device, gradient accumulation making up the rest), one
epoch, images capped at 1024 merged tokens, the three tasks mixed by fixed ratios. GPUs are
used when present (bfloat16); under ``accelerate launch`` every process takes its share of
the global batch; ``device_map="auto"`` spreads a model too large for one GPU over the GPUs
of one process. Gradient checkpointing is on by default, and micro-batches hold items of
similar length (length-grouped, so little of a batch is padding). The adapter, the recipe and the loss log are saved into ``out``;
``parse3d vlm ask --local MODEL --adapter OUT`` uses them.
"""

from __future__ import annotations

import json
import math
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError, Problem
from .build import TASKS, read_jsonl

__all__ = ["FinetuneOptions", "FinetuneResult", "mix_tasks", "lr_at", "lora_targets",
           "expert_parameters", "length_grouped", "finetune"]


@dataclass(frozen=True)
class FinetuneOptions:
    """The recipe (saved as ``finetune.json`` beside the adapter).

    Attributes
    ----------
    rank, alpha, dropout : int, int, float
        LoRA rank, scaling numerator and dropout.
    lr, min_lr : float
        Peak and final learning rates (AdamW).
    warmup : float
        Share of the updates with a linear warm-up.
    weight_decay : float
    global_batch, micro_batch : int
        Items per update, and per device and forward pass.
    epochs : float
        Passes over the mixed training set.
    max_image_tokens : int
        Merged image tokens per image at most.
    ratios : dict of str to float
        Sampling ratio per task: 1 takes every item once, 0.5 half of them, 2 each twice.
    max_items : int or None
        Use only the first ``max_items`` of the mixed set (smoke runs).
    val_items : int
        Validation items whose loss is reported at the end.
    seed : int
    gradient_checkpointing : bool
        Recompute activations in the backward pass (memory for time).
    group_by_length : bool
        Micro-batches of items of similar length (within windows of 64 micro-batches, the
        batches' order shuffled).
    device_map : str or None
        transformers' ``device_map`` (``auto``: layers spread over this process's GPUs, for
        a model that does not fit one); None puts the whole model on this process's device.
    """

    rank: int = 8
    alpha: int = 32
    dropout: float = 0.05
    lr: float = 1e-4
    min_lr: float = 1e-5
    warmup: float = 0.05
    weight_decay: float = 0.0
    global_batch: int = 16
    micro_batch: int = 2
    epochs: float = 1.0
    max_image_tokens: int = 1024
    ratios: dict[str, float] = field(default_factory=lambda: dict.fromkeys(TASKS, 1.0))
    max_items: int | None = None
    val_items: int = 64
    seed: int = 0
    gradient_checkpointing: bool = True
    group_by_length: bool = True
    device_map: str | None = None


@dataclass
class FinetuneResult:
    """What a run did: updates, losses per update, validation loss, seconds."""

    out: Path
    steps: int
    losses: list[float]
    val_loss: float | None
    wall: float
    accumulation: int
    devices: int


def mix_tasks(rows: list[dict[str, Any]], ratios: dict[str, float],
              rng: np.random.Generator) -> list[dict[str, Any]]:
    """Sample every task by its ratio and shuffle them together."""
    out: list[dict[str, Any]] = []
    for task in TASKS:
        items = [r for r in rows if r["task"] == task]
        ratio = float(ratios.get(task, 0.0))
        if not items or ratio <= 0:
            continue
        whole, frac = int(ratio), ratio - int(ratio)
        out += items * whole
        k = int(round(frac * len(items)))
        out += [items[int(i)] for i in rng.choice(len(items), k, replace=False)]
    order = rng.permutation(len(out))
    return [out[int(i)] for i in order]


def lr_at(step: int, total: int, opts: FinetuneOptions) -> float:
    """Learning rate of update ``step`` (0-based) of ``total``: warm-up, then cosine to min."""
    warm = max(1, int(math.ceil(opts.warmup * total)))
    if step < warm:
        return opts.lr * (step + 1) / warm
    span = max(1, total - warm)
    t = min(1.0, (step - warm) / span)
    return opts.min_lr + 0.5 * (opts.lr - opts.min_lr) * (1 + math.cos(math.pi * t))


def lora_targets(model) -> list[str]:
    """Names of every linear layer of the language model (not the vision tower, not the head)."""
    import torch

    names = []
    for name, mod in model.named_modules():
        if isinstance(mod, torch.nn.Linear) and "language_model" in name \
                and "visual" not in name and not name.endswith("lm_head"):
            names.append(name)
    return names


def expert_parameters(model) -> list[str]:
    """Names of the language model's expert weights stored as 3-D parameters
    (``(experts, out, in)``: a mixture-of-experts block), which LoRA reaches through peft's
    ``target_parameters``; empty for a dense model."""
    return [name for name, p in model.named_parameters()
            if p.ndim == 3 and "language_model" in name and "visual" not in name
            and ".experts." in name]


def length_grouped(items: list[dict[str, Any]], micro_batch: int, rng: np.random.Generator,
                   *, window: int = 64) -> list[dict[str, Any]]:
    """``items`` reordered so that each run of ``micro_batch`` has similar lengths.

    Within windows of ``window`` micro-batches the items are sorted by the length of their
    text (images have one size per benchmark), cut into micro-batches, and the micro-batches
    of the whole run shuffled. Every item stays exactly once.
    """
    def length(r: dict[str, Any]) -> int:
        return sum(len(str(m.get("content", ""))) for m in r.get("messages", []))

    span = max(1, micro_batch * window)
    batches = []
    for w in range(0, len(items), span):
        chunk = sorted(items[w:w + span], key=length)
        batches += [chunk[i:i + micro_batch] for i in range(0, len(chunk), micro_batch)]
    return [r for k in rng.permutation(len(batches)) for r in batches[int(k)]]


def _check(opts: FinetuneOptions) -> None:
    bad = []
    if opts.rank < 1 or opts.alpha < 1:
        bad.append("--rank and --alpha must be >= 1")
    if not 0 < opts.min_lr <= opts.lr:
        bad.append("need 0 < --min-lr <= --lr")
    if opts.global_batch < 1 or opts.micro_batch < 1:
        bad.append("--global-batch and --micro-batch must be >= 1")
    if opts.epochs <= 0:
        bad.append("--epochs must be > 0")
    if set(opts.ratios) - set(TASKS):
        bad.append(f"task ratios must name {', '.join(TASKS)}")
    if bad:
        raise InputError([Problem("", b, "options", "parameter") for b in bad])


def finetune(model_dir: str | Path, data: str | Path, out: str | Path,
             options: FinetuneOptions = FinetuneOptions(), *, progress=None) -> FinetuneResult:
    """Train a LoRA adapter on ``data/train.jsonl`` (a benchmark folder) and save it to ``out``.

    Parameters
    ----------
    model_dir : path
        A local Qwen2.5-VL or Qwen3-VL folder (weights, tokenizer, preprocessor config).
    data : path
        A benchmark folder from ``parse3d vlm build`` (or a training JSONL in it).
    out : path
        The adapter folder.
    progress : callable, optional
        Called with ``(step, total, loss, lr)`` after every update.
    """
    from .local import require_ml

    require_ml()
    import torch
    from accelerate import Accelerator, PartialState
    from peft import LoraConfig, get_peft_model
    from transformers import AutoModelForImageTextToText

    from .local import check_safetensors, collate, encode, load_processor, reading_model

    _check(options)
    t0 = time.perf_counter()
    data = Path(data)
    train_file = data if data.suffix == ".jsonl" else data / "train.jsonl"
    base = train_file.parent
    rows = read_jsonl(train_file)
    if not rows:
        raise InputError(Problem("", "no training items", str(train_file), "io"))
    rng = np.random.default_rng(options.seed)
    mixed = mix_tasks(rows, options.ratios, rng)
    if options.max_items is not None:
        mixed = mixed[: options.max_items]
    torch.manual_seed(options.seed)

    # processes only (PartialState fixes no precision), so the Accelerator below is the first
    world = PartialState().num_processes
    per_update = options.micro_batch * world
    accumulation = max(1, options.global_batch // per_update)
    accelerator = Accelerator(gradient_accumulation_steps=accumulation,
                              mixed_precision="bf16" if torch.cuda.is_available() else "no")
    proc = load_processor(model_dir, max_image_tokens=options.max_image_tokens)
    check_safetensors(Path(model_dir), "model folder")
    with reading_model(model_dir):
        model = AutoModelForImageTextToText.from_pretrained(
            model_dir, dtype=torch.bfloat16 if torch.cuda.is_available() else torch.float32,
            use_safetensors=True, trust_remote_code=False, device_map=options.device_map)
    targets = lora_targets(model)
    experts = expert_parameters(model)
    if not targets:
        raise InputError(Problem("", "found no linear layers of a language model to adapt — "
                                     "is this a Qwen2.5-VL / Qwen3-VL folder?", str(model_dir),
                                 "io"))
    # peft's parameter targeting cannot apply dropout (x is not factored out of the expert
    # product), so a mixture-of-experts model trains its adapters without it
    dropout = 0.0 if experts else options.dropout
    cfg = LoraConfig(r=options.rank, lora_alpha=options.alpha, lora_dropout=dropout,
                     target_modules=targets, target_parameters=experts or None, bias="none")
    model = get_peft_model(model, cfg)
    model.config.use_cache = False
    if options.gradient_checkpointing:
        kw = {"use_reentrant": False}
        if hasattr(model, "activation_checkpointing_enable"):  # the newer name
            model.activation_checkpointing_enable(activation_checkpointing_kwargs=kw)
        else:
            model.gradient_checkpointing_enable(gradient_checkpointing_kwargs=kw)
        model.enable_input_require_grads()  # the frozen embeddings' output needs a grad
    opt = torch.optim.AdamW([p for p in model.parameters() if p.requires_grad], lr=options.lr,
                            weight_decay=options.weight_decay)
    n_epochs = options.epochs
    total_micro = int(math.ceil(len(mixed) * n_epochs / per_update))
    total = max(1, int(math.ceil(total_micro / accumulation)))
    sched = torch.optim.lr_scheduler.LambdaLR(
        # accelerate steps a prepared scheduler once per process and update
        opt, lambda s: lr_at(min(s // world, total - 1), total, options) / options.lr)
    model, opt, sched = accelerator.prepare(model, opt, sched)
    pad = proc.tokenizer.pad_token_id
    if pad is None:
        pad = proc.tokenizer.convert_tokens_to_ids("<|endoftext|>")
    # the epoch's item order: whole passes, then a part of one
    order = []
    full = int(n_epochs)
    for e in range(full):
        order += mixed if e == 0 else [mixed[int(i)] for i in rng.permutation(len(mixed))]
    order += mixed[: int(round((n_epochs - full) * len(mixed)))]
    if options.group_by_length:
        order = length_grouped(order, per_update, rng)
    mine = order[accelerator.process_index::world]
    losses: list[float] = []
    model.train()
    step_loss, n_micro = 0.0, 0
    for i in range(0, len(mine), options.micro_batch):
        batch = collate([encode(proc, r, base, with_answer=True)
                         for r in mine[i:i + options.micro_batch]], pad)
        batch = {k: v.to(accelerator.device) for k, v in batch.items()}
        with accelerator.accumulate(model):
            loss = model(**batch).loss
            accelerator.backward(loss)
            opt.step()
            sched.step()
            opt.zero_grad()
        step_loss += float(loss.detach())
        n_micro += 1
        if accelerator.sync_gradients:
            losses.append(step_loss / n_micro)
            if progress is not None:
                progress(len(losses), total, losses[-1], sched.get_last_lr()[0])
            step_loss, n_micro = 0.0, 0
    if n_micro:
        losses.append(step_loss / n_micro)
    val_loss = None
    val_file = base / "val.jsonl"
    if options.val_items > 0 and val_file.exists():
        val = read_jsonl(val_file)[: options.val_items]
        model.eval()
        vals = []
        with torch.no_grad():
            for r in val:
                b = {k: v.to(accelerator.device)
                     for k, v in encode(proc, r, base, with_answer=True).items()}
                vals.append(float(model(**b).loss))
        val_loss = float(np.mean(vals)) if vals else None
    out = Path(out)
    if accelerator.is_main_process:
        out.mkdir(parents=True, exist_ok=True)
        accelerator.unwrap_model(model).save_pretrained(out)
        rec = {"format": "parse3d-vlm-finetune/1", "model": str(model_dir),
               "data": str(train_file), "recipe": asdict(options), "items": len(mixed),
               "devices": world, "accumulation": accumulation, "updates": len(losses),
               "losses": [round(x, 5) for x in losses], "val_loss": val_loss,
               "lora_targets": len(targets), "lora_expert_parameters": len(experts),
               "lora_dropout_used": dropout,
               "wall_s": round(time.perf_counter() - t0, 2)}
        (out / "finetune.json").write_text(json.dumps(rec, indent=1) + "\n")
    return FinetuneResult(out, len(losses), losses, val_loss, time.perf_counter() - t0,
                          accumulation, world)
