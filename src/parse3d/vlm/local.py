"""Local Qwen2.5-VL / Qwen3-VL models: loading, encoding benchmark records, generation.

Records are encoded in Qwen's ChatML directly (the format both families were trained on)::

    <|im_start|>user
    <|vision_start|><|image_pad|>...<|image_pad|><|vision_end|>The image displays ...<|im_end|>
    <|im_start|>assistant
    C<|im_end|>

with one ``<|image_pad|>`` per merged image patch (``grid_t * grid_h * grid_w / merge²``),
``mm_token_type_ids`` marking those tokens (1) for the multimodal rotary positions, and labels
only on the assistant's answer and its ``<|im_end|>``. The tokenizer and the image processor
are read from the model folder; transformers' own processor class is not needed (it insists
on a video processor that needs torchvision).
"""

from __future__ import annotations

import contextlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .._files import inside
from ..errors import DependencyError, InputError, Problem

__all__ = ["VLProcessor", "load_processor", "load_model", "encode", "collate", "generate", "require_ml",
           "IGNORE"]

IGNORE = -100


def require_ml() -> None:
    """Raise :class:`DependencyError` naming the extra when torch / transformers / peft lack."""
    import importlib.util

    missing = [m for m in ("torch", "transformers", "peft", "accelerate")
               if importlib.util.find_spec(m) is None]
    if missing:
        raise DependencyError(f"local models need {', '.join(missing)}: pip install "
                              "'parse3d[ml]'")


@dataclass
class VLProcessor:
    """Tokenizer + image processor of a Qwen-VL model folder.

    Attributes
    ----------
    max_image_tokens : int
        Cap on merged image tokens per image (the paper: 1024); the image processor's pixel
        budget is set from it.
    """

    tokenizer: Any
    image_processor: Any
    image_token_id: int
    merge: int
    max_image_tokens: int = 1024


@contextlib.contextmanager
def reading_model(folder: str | Path, what: str = "model folder"):
    """Turn whatever a damaged model or adapter folder makes the loaders raise (a truncated
    safetensors file, half a config.json, a tokenizer of the wrong kind, shapes that do not
    fit) into one :class:`InputError` naming the folder."""
    try:
        yield
    except InputError:
        raise
    except Exception as e:  # noqa: BLE001 - transformers/peft/safetensors raise many types
        line = (str(e).strip().splitlines() or [type(e).__name__])[0][:200]
        raise InputError(Problem("", f"cannot read this {what} ({type(e).__name__}: {line}) — "
                                     "is it complete and a Qwen-VL checkpoint?", str(folder),
                                 "io")) from None


def check_safetensors(folder: Path, what: str) -> None:
    """Refuse a folder whose weights are only pickles (``*.bin``, ``*.pt``): loading those
    could run code from the file, so only ``*.safetensors`` weights are read."""
    if any(folder.glob("*.safetensors")):
        return
    if any(folder.glob("*.bin")) or any(folder.glob("*.pt")) or any(folder.glob("*.pth")):
        raise InputError(Problem("", f"this {what} holds only pickled weights (.bin/.pt): "
                                     "parse3d reads only .safetensors (a pickle can run code) "
                                     "— convert it with save_pretrained(safe_serialization=True)",
                                 str(folder), "io"))


def _check_model_dir(model_dir: Path) -> None:
    if not (model_dir / "config.json").exists():
        raise InputError(Problem("", "not a model folder (no config.json) — pass a local "
                                     "Qwen2.5-VL / Qwen3-VL checkpoint folder", str(model_dir),
                                 "io"))


def load_processor(model_dir: str | Path, *, max_image_tokens: int = 1024) -> VLProcessor:
    """Read the tokenizer and image processor of a model folder; cap the image tokens."""
    require_ml()
    from transformers import AutoTokenizer, Qwen2VLImageProcessorPil

    d = Path(model_dir)
    _check_model_dir(d)
    with reading_model(d):
        tok = AutoTokenizer.from_pretrained(d, trust_remote_code=False)
        ip = Qwen2VLImageProcessorPil.from_pretrained(d)
    merge = int(getattr(ip, "merge_size", 2))
    patch = int(getattr(ip, "patch_size", 14))
    budget = int(max_image_tokens) * (patch * merge) ** 2
    size = dict(getattr(ip, "size", None) or {})
    size["longest_edge"] = min(int(size.get("longest_edge", budget)), budget)
    size.setdefault("shortest_edge", (patch * merge) ** 2)
    size["shortest_edge"] = min(size["shortest_edge"], size["longest_edge"])
    ip.size = size
    image_id = tok.convert_tokens_to_ids("<|image_pad|>")
    if image_id is None or image_id == tok.unk_token_id:
        raise InputError(Problem("", "the tokenizer has no <|image_pad|> token: not a Qwen-VL "
                                     "model", str(d), "io"))
    return VLProcessor(tok, ip, int(image_id), merge, int(max_image_tokens))


def load_model(model_dir: str | Path, *, adapter: str | Path | None = None,
               device: str | None = None, max_image_tokens: int = 1024):
    """The model (with a LoRA adapter merged in when given) and its :class:`VLProcessor`."""
    d = Path(model_dir)
    _check_model_dir(d)  # before the heavy imports: a wrong path fails at once
    if adapter is not None and not (Path(adapter) / "adapter_config.json").exists():
        raise InputError(Problem("", "not a LoRA adapter folder (no adapter_config.json) — "
                                     "pass the --out of parse3d vlm finetune", str(adapter),
                                 "io"))
    require_ml()
    import torch
    from transformers import AutoModelForImageTextToText

    dev = device or ("cuda" if torch.cuda.is_available() else "cpu")
    dtype = torch.bfloat16 if dev.startswith("cuda") else torch.float32
    check_safetensors(d, "model folder")
    with reading_model(d):
        model = AutoModelForImageTextToText.from_pretrained(d, dtype=dtype, use_safetensors=True,
                                                            trust_remote_code=False)
    if adapter is not None:
        from peft import PeftModel

        a = Path(adapter)
        if not (a / "adapter_model.safetensors").is_file():
            raise InputError(Problem("", "no adapter_model.safetensors here: parse3d reads only "
                                         "safetensors adapters (a .bin pickle can run code)",
                                     str(a), "io"))
        with reading_model(a, "LoRA adapter folder"):
            model = PeftModel.from_pretrained(model, a).merge_and_unload()
    model.to(dev).eval()
    return model, load_processor(d, max_image_tokens=max_image_tokens)


def _user_parts(record: dict[str, Any]) -> tuple[str, list[str], str | None]:
    msgs = record["messages"]
    user = next((m["content"] for m in msgs if m["role"] == "user"), None)
    if user is None:
        raise InputError(Problem("", f"item {record.get('id')} has no user message", "", "schema"))
    answer = msgs[-1]["content"] if msgs[-1]["role"] == "assistant" else None
    return user, list(record.get("images", [])), answer


def encode(proc: VLProcessor, record: dict[str, Any], base: Path, *, with_answer: bool
           ) -> dict[str, Any]:
    """Token ids, labels and image tensors of one record (batch of one, tensors).

    Parameters
    ----------
    base : path
        The folder image paths are relative to (the JSONL's folder).
    with_answer : bool
        Append the assistant's answer (training) or stop at ``<|im_start|>assistant\\n``
        (generation).
    """
    import torch
    from PIL import Image

    user, images, answer = _user_parts(record)
    pics = []
    for p in images:
        path = inside(base, p, what="image", file=str(record.get("id")))
        try:
            pics.append(Image.open(path).convert("RGB"))
        except (OSError, ValueError) as e:
            raise InputError(Problem("", f"not a readable image ({e})", str(path), "io")
                             ) from None
    feats = proc.image_processor(images=pics, return_tensors="pt") if pics else {}
    grids = feats["image_grid_thw"].tolist() if pics else []
    chunks = user.split("<image>")
    if len(chunks) - 1 != len(pics):
        raise InputError(Problem("", f"item {record.get('id')}: {len(chunks) - 1} <image> "
                                     f"markers for {len(pics)} images", "", "schema"))
    text = "<|im_start|>user\n" + chunks[0]
    for grid, chunk in zip(grids, chunks[1:], strict=True):
        n = int(grid[0] * grid[1] * grid[2]) // proc.merge ** 2
        text += "<|vision_start|>" + "<|image_pad|>" * n + "<|vision_end|>" + chunk
    text += "<|im_end|>\n<|im_start|>assistant\n"
    tok = proc.tokenizer
    prompt_ids = tok(text, add_special_tokens=False)["input_ids"]
    ids = list(prompt_ids)
    labels = [IGNORE] * len(ids)
    if with_answer:
        if answer is None:
            raise InputError(Problem("", f"item {record.get('id')} has no assistant answer to "
                                         "train on", "", "schema"))
        ans = tok(answer + "<|im_end|>", add_special_tokens=False)["input_ids"]
        ids += ans
        labels += ans
    out: dict[str, Any] = {
        "input_ids": torch.tensor([ids]),
        "attention_mask": torch.ones(1, len(ids), dtype=torch.long),
        "labels": torch.tensor([labels]),
        "mm_token_type_ids": (torch.tensor([ids]) == proc.image_token_id).to(torch.int32),
    }
    if pics:
        out["pixel_values"] = feats["pixel_values"]
        out["image_grid_thw"] = feats["image_grid_thw"]
    return out


def collate(batch: list[dict[str, Any]], pad_id: int) -> dict[str, Any]:
    """Right-pad a list of :func:`encode` outputs into one batch."""
    import torch

    n = max(b["input_ids"].shape[1] for b in batch)

    def pad(key: str, value: int):
        return torch.cat([torch.nn.functional.pad(b[key], (0, n - b[key].shape[1]), value=value)
                          for b in batch])

    out = {"input_ids": pad("input_ids", pad_id), "attention_mask": pad("attention_mask", 0),
           "labels": pad("labels", IGNORE), "mm_token_type_ids": pad("mm_token_type_ids", 0)}
    with_img = [b for b in batch if "pixel_values" in b]
    if with_img:
        out["pixel_values"] = torch.cat([b["pixel_values"] for b in with_img])
        out["image_grid_thw"] = torch.cat([b["image_grid_thw"] for b in with_img])
    return out


def generate(model, proc: VLProcessor, record: dict[str, Any], base: Path, *,
             max_new_tokens: int = 512) -> tuple[str, int, int]:
    """Greedy answer to one record: ``(text, prompt tokens, new tokens)``.

    Special tokens of the answer (``<|box_start|>`` ...) are kept; the end-of-turn and
    padding tokens are removed.
    """
    import torch

    enc = encode(proc, record, base, with_answer=False)
    enc.pop("labels")
    dev = next(model.parameters()).device
    enc = {k: v.to(dev) for k, v in enc.items()}
    tok = proc.tokenizer
    end = tok.convert_tokens_to_ids("<|im_end|>")
    with torch.no_grad():
        out = model.generate(**enc, max_new_tokens=max_new_tokens, do_sample=False,
                             eos_token_id=end, pad_token_id=tok.pad_token_id or end)
    new = out[0, enc["input_ids"].shape[1]:].tolist()
    text = tok.decode(new, skip_special_tokens=False)
    for t in ("<|im_end|>", "<|endoftext|>"):
        text = text.replace(t, "")
    return text.strip(), int(enc["input_ids"].shape[1]), len(new)
