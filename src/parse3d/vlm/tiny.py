"""A tiny, randomly initialised Qwen3-VL built offline, for tests and smoke runs.

Nothing is downloaded: a small byte-level BPE tokenizer is trained with ``tokenizers`` on
the benchmark's own text, with Qwen's special tokens (``<|im_start|>``, ``<|vision_start|>``,
``<|image_pad|>``, ``<|box_start|>``, ...) and a Qwen-style chat template; the image
processor is configured locally (16-pixel patches, 2x2 merge, a pixel budget); the model is
built from a config (two layers, hidden size 64, ``mrope_section`` summing to
``head_dim / 2``). Model, tokenizer and processor are saved into one folder that
``parse3d vlm finetune --model`` and ``parse3d vlm ask --local`` read like a real checkpoint.
It learns the format, not the task: use it to test the pipeline, not to measure anything.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

__all__ = ["QWEN_SPECIAL_TOKENS", "CHAT_TEMPLATE", "make_tiny_qwen3vl"]

QWEN_SPECIAL_TOKENS = (
    "<|endoftext|>", "<|im_start|>", "<|im_end|>", "<|object_ref_start|>",
    "<|object_ref_end|>", "<|box_start|>", "<|box_end|>", "<|quad_start|>", "<|quad_end|>",
    "<|vision_start|>", "<|vision_end|>", "<|vision_pad|>", "<|image_pad|>", "<|video_pad|>",
)

#: Qwen's ChatML with images as <|vision_start|><|image_pad|><|vision_end|>.
CHAT_TEMPLATE = (
    "{% for message in messages %}"
    "<|im_start|>{{ message['role'] }}\n"
    "{% if message['content'] is string %}{{ message['content'] }}"
    "{% else %}{% for part in message['content'] %}"
    "{% if part['type'] == 'image' or 'image' in part %}"
    "<|vision_start|><|image_pad|><|vision_end|>"
    "{% elif part['type'] == 'text' %}{{ part['text'] }}{% endif %}"
    "{% endfor %}{% endif %}<|im_end|>\n"
    "{% endfor %}"
    "{% if add_generation_prompt %}<|im_start|>assistant\n{% endif %}"
)


def _tokenizer(texts: Iterable[str], vocab_size: int):
    from tokenizers import Tokenizer, decoders, models, pre_tokenizers, trainers
    from transformers import PreTrainedTokenizerFast

    tok = Tokenizer(models.BPE())
    tok.pre_tokenizer = pre_tokenizers.ByteLevel(add_prefix_space=False)
    tok.decoder = decoders.ByteLevel()
    trainer = trainers.BpeTrainer(vocab_size=vocab_size, special_tokens=list(QWEN_SPECIAL_TOKENS),
                                  initial_alphabet=pre_tokenizers.ByteLevel.alphabet(),
                                  show_progress=False)
    tok.train_from_iterator(texts, trainer)
    fast = PreTrainedTokenizerFast(tokenizer_object=tok, eos_token="<|im_end|>",
                                   pad_token="<|endoftext|>", unk_token=None)
    fast.add_special_tokens({"additional_special_tokens": list(QWEN_SPECIAL_TOKENS[1:])})
    fast.chat_template = CHAT_TEMPLATE
    return fast


def make_tiny_qwen3vl(out: str | Path, texts: Iterable[str], *, vocab_size: int = 600,
                      hidden: int = 64, layers: int = 2, max_pixels: int = 64 * 64,
                      experts: int = 0, seed: int = 0) -> Path:
    """Build and save a tiny random Qwen3-VL (model, tokenizer, processor) into ``out``.

    Parameters
    ----------
    texts : iterable of str
        Text to train the tokenizer on (e.g. the benchmark's prompts and answers).
    vocab_size : int
        BPE vocabulary size, special tokens included.
    hidden : int
        Hidden size of the language model (4 heads of ``hidden / 4``).
    max_pixels : int
        The image processor's pixel budget (an image of 64x64 pixels gives 4 tokens).
    experts : int
        0: a dense Qwen3-VL; otherwise a Qwen3-VL-MoE with this many experts per layer (two
        routed per token), the architecture of Qwen3-VL-30B-A3B and -235B-A22B.
    """
    import torch
    from transformers import (
        Qwen2VLImageProcessorPil,
        Qwen3VLConfig,
        Qwen3VLForConditionalGeneration,
        Qwen3VLMoeConfig,
        Qwen3VLMoeForConditionalGeneration,
    )

    out = Path(out)
    tok = _tokenizer(texts, vocab_size)
    ids = {t: tok.convert_tokens_to_ids(t) for t in QWEN_SPECIAL_TOKENS}
    heads = 4
    head_dim = hidden // heads
    half = head_dim // 2
    mrope = [half - 2 * (half // 3), half // 3, half // 3]  # temporal, height, width
    moe = {"num_experts": experts, "num_experts_per_tok": min(2, experts),
           "moe_intermediate_size": hidden, "decoder_sparse_step": 1} if experts else {}
    config_cls, model_cls = ((Qwen3VLMoeConfig, Qwen3VLMoeForConditionalGeneration) if experts
                             else (Qwen3VLConfig, Qwen3VLForConditionalGeneration))
    cfg = config_cls(
        text_config={**moe, "hidden_size": hidden, "intermediate_size": 2 * hidden,
                     "num_hidden_layers": layers, "num_attention_heads": heads,
                     "num_key_value_heads": 2, "head_dim": head_dim, "vocab_size": len(tok),
                     "max_position_embeddings": 4096,
                     "rope_parameters": {"rope_type": "default", "rope_theta": 10000.0,
                                         "mrope_section": mrope, "mrope_interleaved": True},
                     "pad_token_id": ids["<|endoftext|>"], "eos_token_id": ids["<|im_end|>"],
                     "bos_token_id": ids["<|endoftext|>"]},
        vision_config={"depth": 2, "hidden_size": 32, "intermediate_size": 64, "num_heads": 2,
                       "out_hidden_size": hidden, "patch_size": 16, "spatial_merge_size": 2,
                       "temporal_patch_size": 2, "num_position_embeddings": 64,
                       "deepstack_visual_indexes": [1]},
        image_token_id=ids["<|image_pad|>"], video_token_id=ids["<|video_pad|>"],
        vision_start_token_id=ids["<|vision_start|>"], vision_end_token_id=ids["<|vision_end|>"],
        tie_word_embeddings=False)
    torch.manual_seed(seed)
    model = model_cls(cfg)
    model.generation_config.eos_token_id = ids["<|im_end|>"]
    model.generation_config.pad_token_id = ids["<|endoftext|>"]
    budget = {"shortest_edge": 32 * 32, "longest_edge": int(max_pixels)}
    image_processor = Qwen2VLImageProcessorPil(patch_size=16, merge_size=2, temporal_patch_size=2,
                                               size=budget)
    # tokenizer and image processor are saved separately (as a checkpoint's files are):
    # transformers' Qwen3VLProcessor insists on a video processor, which needs torchvision
    out.mkdir(parents=True, exist_ok=True)
    model.save_pretrained(out)
    tok.save_pretrained(out)
    image_processor.save_pretrained(out)
    return out
