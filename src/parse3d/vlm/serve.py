"""A minimal OpenAI-compatible chat server answering from a local model folder.

``make_app(model_dir)`` returns a FastAPI application with ``GET /v1/models`` and
``POST /v1/chat/completions`` (no streaming) that answers with the transformers model of
:mod:`parse3d.vlm.local` (greedy decoding; a LoRA adapter merged in when given). It speaks
the subset of the API that ``parse3d vlm ask --endpoint`` and vLLM share: user messages whose
content is a string or a list of ``text`` and ``image_url`` parts (base64 data URLs; the
image comes before its text), ``max_tokens``, ``usage`` in the reply. It is for serving a
fine-tuned adapter or a small model where vLLM is not installed, and for tests; it answers
one request at a time.

Run it with uvicorn::

    import uvicorn
    from parse3d.vlm.serve import make_app
    uvicorn.run(make_app("models/Qwen3-VL-8B-Instruct", adapter="out/lora"), port=8000)
"""

from __future__ import annotations

import base64
import binascii
import tempfile
import threading
import time
import uuid
from pathlib import Path
from typing import Any

from ..errors import InputError

__all__ = ["make_app", "record_of"]

_MIME = {"image/jpeg": ".jpg", "image/png": ".png"}


class RequestError(ValueError):
    """A request the server cannot answer (HTTP 400)."""


def record_of(messages: list[dict[str, Any]], folder: Path) -> dict[str, Any]:
    """A benchmark-style record of the last user message: its images written into
    ``folder`` (``<image>`` marks where each was), its text parts joined."""
    users = [m for m in messages if isinstance(m, dict) and m.get("role") == "user"]
    if not users:
        raise RequestError("no user message")
    content = users[-1].get("content")
    if isinstance(content, str):
        return {"id": "request", "messages": [{"role": "user", "content": content}],
                "images": []}
    if not isinstance(content, list):
        raise RequestError("a message's content must be a string or a list of parts")
    text, images = "", []
    for part in content:
        kind = part.get("type") if isinstance(part, dict) else None
        if kind == "text":
            text += str(part.get("text", ""))
        elif kind == "image_url":
            ref = part.get("image_url")
            url = str(ref.get("url", "") if isinstance(ref, dict) else ref or "")
            head, _, data = url.partition(",")
            mime = head.removeprefix("data:").removesuffix(";base64")
            if not head.startswith("data:") or mime not in _MIME:
                raise RequestError("images must be base64 data URLs (image/jpeg, image/png)")
            try:
                raw = base64.b64decode(data, validate=True)
            except (binascii.Error, ValueError):
                raise RequestError("an image is not valid base64") from None
            name = f"{len(images)}{_MIME[mime]}"
            (folder / name).write_bytes(raw)
            images.append(name)
            text += "<image>"
        else:
            raise RequestError(f"unsupported content part {kind!r}")
    return {"id": "request", "messages": [{"role": "user", "content": text}],
            "images": images}


def make_app(model_dir: str | Path, *, adapter: str | Path | None = None,
             name: str | None = None, device: str | None = None, max_tokens: int = 1024):
    """The FastAPI application serving ``model_dir`` under the model name ``name`` (default:
    the folder's name). Loads the model at once."""
    from fastapi import FastAPI, HTTPException
    from fastapi.responses import JSONResponse

    from .local import generate, load_model

    served = name or Path(model_dir).name
    model, proc = load_model(model_dir, adapter=adapter, device=device)
    lock = threading.Lock()
    app = FastAPI(title="parse3d vlm serve")

    @app.get("/v1/models")
    def models() -> dict[str, Any]:
        return {"object": "list", "data": [{"id": served, "object": "model",
                                            "owned_by": "parse3d"}]}

    @app.post("/v1/chat/completions")
    def chat(body: dict[str, Any]) -> Any:
        if body.get("model") != served:
            return JSONResponse({"error": {"message": f"the model {body.get('model')!r} does "
                                           f"not exist; this server has {served!r}",
                                           "type": "NotFoundError", "code": 404}}, 404)
        if body.get("stream"):
            raise HTTPException(400, "streaming is not supported")
        limit = body.get("max_tokens") or body.get("max_completion_tokens") or max_tokens
        if not isinstance(limit, int) or isinstance(limit, bool) or limit < 1:
            raise HTTPException(400, "max_tokens must be a positive integer")
        with tempfile.TemporaryDirectory(prefix="parse3d-serve-") as tmp:
            try:
                rec = record_of(body.get("messages") or [], Path(tmp))
            except RequestError as e:
                raise HTTPException(400, str(e)) from None
            try:
                with lock:
                    text, n_in, n_out = generate(model, proc, rec, Path(tmp),
                                                 max_new_tokens=min(int(limit), max_tokens))
            except InputError as e:  # an image that is no image
                raise HTTPException(400, str(e)) from None
        return {"id": f"chatcmpl-{uuid.uuid4().hex[:16]}", "object": "chat.completion",
                "created": int(time.time()), "model": served,
                "choices": [{"index": 0, "message": {"role": "assistant", "content": text},
                             "finish_reason": "stop"}],
                "usage": {"prompt_tokens": n_in, "completion_tokens": n_out,
                          "total_tokens": n_in + n_out}}

    return app
