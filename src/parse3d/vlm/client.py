"""``parse3d vlm ask``: run a model on benchmark items and write predictions.

Two back ends, one output (``{"id", "response", ...}`` per line, appended as answers arrive):

* an **OpenAI-compatible chat endpoint** (vLLM or SGLang serving Qwen3-VL, or a hosted API):
  ``POST {endpoint}/chat/completions`` with the images as base64 data URLs, several requests
  in flight, retries with exponential backoff on connection errors, 408/409/429 and 5xx;
* a **local model folder** (transformers, optionally with a LoRA adapter from
  ``parse3d vlm finetune``), greedy decoding.

Interrupted runs resume: ids already in the output file are skipped. A summary gives the
wall time, latency percentiles, token counts and, with prices, the cost.
"""

from __future__ import annotations

import base64
import json
import os
import threading
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .._files import inside, read_input_bytes, read_input_text
from ..errors import DependencyError, InputError, Parse3dError, Problem

__all__ = ["EndpointOptions", "AskSummary", "openai_messages", "ask_endpoint", "ask_local",
           "done_ids", "prompt_messages"]

_RETRY_STATUS = {408, 409, 429, 500, 502, 503, 504}


@dataclass(frozen=True)
class EndpointOptions:
    """How to talk to an endpoint.

    Attributes
    ----------
    concurrency : int
        Requests in flight.
    retries : int
        Extra attempts per item after a retryable failure.
    backoff : float
        Seconds before the first retry; doubled each time (capped at 60 s).
    timeout : float
        Seconds per request.
    max_tokens : int
    temperature : float
    api_key : str or None
        Sent as ``Authorization: Bearer``; the CLI reads it from an environment variable.
    price_in, price_out : float
        USD per million prompt / completion tokens, for the cost line of the summary.
    """

    concurrency: int = 4
    retries: int = 4
    backoff: float = 1.0
    timeout: float = 120.0
    max_tokens: int = 1024
    temperature: float = 0.0
    api_key: str | None = None
    price_in: float = 0.0
    price_out: float = 0.0


@dataclass
class AskSummary:
    """What a run did (seconds, tokens, USD)."""

    requested: int = 0
    answered: int = 0
    resumed: int = 0
    failed: list[str] = field(default_factory=list)
    wall: float = 0.0
    latencies: list[float] = field(default_factory=list)
    prompt_tokens: int = 0
    completion_tokens: int = 0
    retries: int = 0
    cost: float = 0.0

    def to_dict(self) -> dict[str, Any]:
        lat = np.array(self.latencies) if self.latencies else np.zeros(1)
        return {"requested": self.requested, "answered": self.answered,
                "resumed": self.resumed, "failed": len(self.failed),
                "failed_ids": self.failed[:20], "retries": self.retries,
                "wall_s": round(self.wall, 2),
                "latency_s": {"mean": round(float(lat.mean()), 3),
                              "p50": round(float(np.percentile(lat, 50)), 3),
                              "p95": round(float(np.percentile(lat, 95)), 3)},
                "items_per_s": round(self.answered / self.wall, 3) if self.wall else 0.0,
                "prompt_tokens": self.prompt_tokens,
                "completion_tokens": self.completion_tokens,
                "cost_usd": round(self.cost, 4)}


def done_ids(out: Path) -> set[str]:
    """Ids already answered in an output file (a torn last line is ignored)."""
    if not out.exists():
        return set()
    ids = set()
    for line in read_input_text(out, what="prediction file").splitlines():
        try:
            ids.add(str(json.loads(line)["id"]))
        except (json.JSONDecodeError, KeyError, TypeError):
            continue
    return ids


def prompt_messages(record: dict[str, Any]) -> list[dict[str, Any]]:
    """The record's messages before its last assistant turn (the answer is never sent)."""
    msgs = list(record["messages"])
    if msgs and msgs[-1]["role"] == "assistant":
        msgs = msgs[:-1]
    return msgs


#: Largest image sent to an endpoint, bytes.
MAX_IMAGE_BYTES = 32 * 1024 * 1024


def _data_url(path: Path) -> str:
    mime = "image/png" if path.suffix.lower() == ".png" else "image/jpeg"
    data = read_input_bytes(path, limit=MAX_IMAGE_BYTES, what="image")
    return f"data:{mime};base64," + base64.b64encode(data).decode("ascii")


def openai_messages(record: dict[str, Any], base: Path) -> list[dict[str, Any]]:
    """OpenAI chat messages of a record: ``<image>`` markers become base64 image parts.

    Image paths must stay inside ``base`` (the split's folder): a record cannot make parse3d
    upload another file of this machine."""
    images = [inside(base, p, what="image", file=str(record.get("id")))
              for p in record.get("images", [])]
    for p in images:
        if not p.exists():
            raise InputError(Problem("", f"image {p} of item {record['id']} is missing",
                                     str(base), "io"))
    k = 0
    out = []
    for m in prompt_messages(record):
        text = m["content"]
        if "<image>" not in text:
            out.append({"role": m["role"], "content": text})
            continue
        parts: list[dict[str, Any]] = []
        for i, chunk in enumerate(text.split("<image>")):
            if i > 0:
                parts.append({"type": "image_url", "image_url": {"url": _data_url(images[k])}})
                k += 1
            if chunk:
                parts.append({"type": "text", "text": chunk})
        out.append({"role": m["role"], "content": parts})
    return out


class _Fatal(Parse3dError):
    pass


def _url(endpoint: str) -> str:
    e = endpoint.rstrip("/")
    return e if e.endswith("/chat/completions") else e + "/chat/completions"


def _writer(out: Path):
    out.parent.mkdir(parents=True, exist_ok=True)
    lock = threading.Lock()
    f = out.open("a")

    def write(row: dict[str, Any]) -> None:
        with lock:
            f.write(json.dumps(row) + "\n")
            f.flush()

    return f, write


def ask_endpoint(records: list[dict[str, Any]], base: Path, out: Path, *, endpoint: str,
                 model: str, options: EndpointOptions = EndpointOptions()) -> AskSummary:
    """Ask an OpenAI-compatible endpoint every record not yet answered in ``out``.

    Raises
    ------
    InputError
        The endpoint cannot be reached after the retries, or it refuses the request for a
        reason retrying cannot fix (401/403/404: key, model or URL). Answers written so far
        are kept; running again resumes.
    """
    try:
        import httpx
    except ImportError:
        raise DependencyError("parse3d vlm ask --endpoint needs httpx: pip install httpx "
                              "(or parse3d[web])") from None

    summary = AskSummary(requested=len(records))
    have = done_ids(out)
    todo = [r for r in records if str(r["id"]) not in have]
    summary.resumed = len(records) - len(todo)
    url = _url(endpoint)
    headers = {"Content-Type": "application/json"}
    if options.api_key:
        headers["Authorization"] = f"Bearer {options.api_key}"
    stop = threading.Event()
    t0 = time.perf_counter()
    f, write = _writer(out)
    lock = threading.Lock()

    def one(rec: dict[str, Any], client: httpx.Client) -> None:
        body = {"model": model, "messages": openai_messages(rec, base),
                "max_tokens": options.max_tokens, "temperature": options.temperature}
        delay = options.backoff
        last = ""
        for attempt in range(options.retries + 1):
            if stop.is_set():
                return
            if attempt:
                with lock:
                    summary.retries += 1
                time.sleep(min(delay, 60.0))
                delay *= 2
            t = time.perf_counter()
            try:
                resp = client.post(url, json=body, headers=headers, timeout=options.timeout)
            except (httpx.ConnectError, httpx.ConnectTimeout) as e:
                last = f"cannot connect ({e.__class__.__name__}: {e})"
                continue
            except httpx.TransportError as e:
                last = f"{e.__class__.__name__}: {e}"
                continue
            if resp.status_code in (401, 403, 404):
                raise _Fatal(f"{url} answered {resp.status_code}: {resp.text[:200]}")
            if resp.status_code in _RETRY_STATUS:
                last = f"HTTP {resp.status_code}"
                continue
            if resp.status_code != 200:
                last = f"HTTP {resp.status_code}: {resp.text[:200]}"
                break
            try:
                d = resp.json()
                text = d["choices"][0]["message"]["content"] or ""
            except (ValueError, KeyError, IndexError, TypeError):
                last = "the answer is not an OpenAI chat completion"
                break
            if isinstance(text, list):  # content parts
                text = "".join(p.get("text", "") for p in text if isinstance(p, dict))
            usage = d.get("usage") or {}
            lat = time.perf_counter() - t
            write({"id": rec["id"], "response": text, "latency_s": round(lat, 3),
                   "usage": usage})
            with lock:
                summary.answered += 1
                summary.latencies.append(lat)
                summary.prompt_tokens += int(usage.get("prompt_tokens", 0) or 0)
                summary.completion_tokens += int(usage.get("completion_tokens", 0) or 0)
            return
        if last.startswith("cannot connect") and summary.answered == 0:
            raise _Fatal(last)
        with lock:
            summary.failed.append(f"{rec['id']}: {last}")

    try:
        with httpx.Client() as client, \
                ThreadPoolExecutor(max(1, options.concurrency)) as pool:
            futures = [pool.submit(one, r, client) for r in todo]
            try:
                for fut in as_completed(futures):
                    fut.result()
            except (_Fatal, KeyboardInterrupt) as e:
                # stop queued items and retries; requests in flight finish and are kept
                stop.set()
                for other in futures:
                    other.cancel()
                if isinstance(e, _Fatal):
                    raise InputError(Problem(
                        "", f"{e} — is the server running, and are --endpoint (e.g. "
                            "http://127.0.0.1:8000/v1), --model and the API key right? "
                            f"{summary.answered} answers were kept in {out}; run again to "
                            "resume", endpoint, "io")) from None
                raise
    finally:
        f.close()
        summary.wall = time.perf_counter() - t0
        summary.cost = (summary.prompt_tokens * options.price_in
                        + summary.completion_tokens * options.price_out) / 1e6
    return summary


def ask_local(records: list[dict[str, Any]], base: Path, out: Path, *, model_dir: str | Path,
              adapter: str | Path | None = None, max_new_tokens: int = 512,
              device: str | None = None) -> AskSummary:
    """Answer records with a local model folder (plus an optional LoRA adapter), greedily."""
    from .local import generate, load_model

    summary = AskSummary(requested=len(records))
    have = done_ids(out)
    todo = [r for r in records if str(r["id"]) not in have]
    summary.resumed = len(records) - len(todo)
    t0 = time.perf_counter()
    model, processor = load_model(model_dir, adapter=adapter, device=device)
    f, write = _writer(out)
    try:
        for rec in todo:
            t = time.perf_counter()
            text, n_in, n_out = generate(model, processor, rec, base,
                                         max_new_tokens=max_new_tokens)
            lat = time.perf_counter() - t
            write({"id": rec["id"], "response": text, "latency_s": round(lat, 3),
                   "usage": {"prompt_tokens": n_in, "completion_tokens": n_out}})
            summary.answered += 1
            summary.latencies.append(lat)
            summary.prompt_tokens += n_in
            summary.completion_tokens += n_out
    finally:
        f.close()
        summary.wall = time.perf_counter() - t0
    return summary


def api_key_from_env(name: str | None) -> str | None:
    """The API key in environment variable ``name`` (None when unset or not asked for)."""
    return os.environ.get(name) if name else None
