"""The designer's FastAPI application: JSON API plus the static front end.

Endpoints (all JSON unless said otherwise; errors are ``{"error": message, "problems": [...]}``
with a 4xx status, never a traceback):

==========================================  =====================================================
``GET  /api/vocabulary``                    categories (variants, parts), surfaces, relations
                                            (parameters with units, ranges, defaults), room types
``GET  /api/assets/{category}.glb``         preview GLB of a category (``?variant=``), one node per
                                            part with the label and surfaces in ``extras``
``POST /api/validate``                      body: a PAG; the problems with JSON pointers, as the CLI
``POST /api/solve``                         body: ``{"pag", "seed", "settle"}``; starts a job (202)
``GET  /api/jobs/{id}/events``              the job's progress as server-sent events
``GET  /api/jobs/{id}``                     state, events and, once done, the scene's results
``GET  /api/jobs/{id}/files/{file}``        ``scene.glb``, ``scene.json`` or ``contacts.json``
``GET  /api/templates``                     the bundled room templates
``POST /api/templates/{name}/expand``       body: ``{"seed"}``; the expanded PAG
``GET  /api/files``                         PAG files in the working folder
``GET  /api/files/{name}``                  one file's document and its problems
``PUT  /api/files/{name}``                  body: ``{"pag", "overwrite"}``; writes the file
``POST /api/convert?to=yaml|json``          body: a PAG; the text a saved file would hold
==========================================  =====================================================
"""

from __future__ import annotations

import asyncio
import json
import threading
import traceback
from collections import OrderedDict
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

from fastapi import FastAPI, HTTPException, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import FileResponse, JSONResponse, Response, StreamingResponse
from fastapi.staticfiles import StaticFiles
from starlette.concurrency import run_in_threadpool
from starlette.exceptions import HTTPException as StarletteHTTPException

from .._files import MAX_DEPTH, loads_json
from ..errors import InputError, Problem
from ..pag.io import dumps_pag
from ..pag.validate import ROOM_PARENTS, ROOM_SURFACES, validate_data
from ..relations import RELATIONS, SURFACES
from . import files as F
from .jobs import SCENE_FILES, STAGES, Job, run_job

__all__ = ["create_app", "MAX_BODY_BYTES", "MAX_QUEUE", "SOLVE_TIME_LIMIT", "STATIC_DIR"]

#: Largest request body accepted, bytes.
MAX_BODY_BYTES = 5 * 1024 * 1024

#: The built front end (index.html, modules, three.js under vendor/).
STATIC_DIR = Path(__file__).parent / "static"

#: Finished jobs kept for their results and files (the oldest finished ones are forgotten).
_MAX_JOBS = 32

#: Solves queued or running at once; one more is answered 429.
MAX_QUEUE = 4

#: Wall-clock seconds a solve may take; objects not placed by then fail with "time limit".
SOLVE_TIME_LIMIT = 120.0

#: Largest seed, as on the command line.
MAX_SEED = 2**32 - 1

#: Host names the server answers to, besides the one it was started on.
LOOPBACK_HOSTS = ("127.0.0.1", "localhost", "[::1]")

_STATE_CHANGING = frozenset({"POST", "PUT", "DELETE", "PATCH"})


def _host_name(host: str) -> str:
    """``host`` as it appears in a Host header (IPv6 addresses in brackets), lower case."""
    host = host.strip().lower()
    if ":" in host and not host.startswith("["):
        host = f"[{host}]"
    return host


class _Guard:
    """ASGI middleware protecting a server on a developer's laptop from web pages.

    * **DNS rebinding**: the ``Host`` header must name an allowed host (the loopback names and
      the address the server was started on) with the server's port; else 403.
    * **Cross-site requests**: every state-changing request (POST, PUT, DELETE, PATCH) must
      send ``Content-Type: application/json`` (a cross-origin page cannot without a CORS
      preflight, which this server never grants) and, when the browser sends one, an
      ``Origin`` of an allowed host with the same port and ``Sec-Fetch-Site`` ``same-origin``
      or ``none``; else 403 (415 for the content type).
    """

    def __init__(self, app, hosts: tuple[str, ...], port: int | None):
        self.app = app
        self.hosts = frozenset(_host_name(h) for h in hosts)
        self.port = port

    def _allowed(self, hostport: str) -> bool:
        hostport = hostport.strip().lower()
        if hostport.startswith("["):
            host, _, rest = hostport.partition("]")
            host += "]"
            port = rest[1:] if rest.startswith(":") else ""
        else:
            host, _, port = hostport.partition(":")
        if host not in self.hosts:
            return False
        if self.port is None:
            return port == "" or port.isdigit()
        return port == str(self.port) or (port == "" and self.port == 80)

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        headers = {}
        for k, v in scope.get("headers") or []:
            headers.setdefault(k.decode("latin-1").lower(), v.decode("latin-1"))
        if not self._allowed(headers.get("host", "")):
            return await _send_json(send, 403, {
                "error": f"the Host {headers.get('host', '')!r} is not this server's: open the "
                         "designer at http://127.0.0.1 (or the --host it was started on)"})
        if scope.get("method", "GET").upper() in _STATE_CHANGING:
            origin = headers.get("origin")
            if origin is not None:
                scheme, _, rest = origin.partition("://")
                if scheme not in ("http", "https") or not self._allowed(rest.rstrip("/")):
                    return await _send_json(send, 403, {
                        "error": f"requests from the page {origin!r} are refused: only the "
                                 "designer's own page may change files or start solves"})
            site = headers.get("sec-fetch-site")
            if site is not None and site not in ("same-origin", "none"):
                return await _send_json(send, 403, {
                    "error": f"a {site} request is refused: only the designer's own page may "
                             "change files or start solves"})
            ctype = headers.get("content-type", "").split(";")[0].strip().lower()
            if ctype != "application/json":
                return await _send_json(send, 415, {
                    "error": "state-changing requests must send Content-Type: application/json"})
        return await self.app(scope, receive, send)


class _BodyLimit:
    """ASGI middleware: 413 for bodies over ``max_bytes``, by header or by counting."""

    def __init__(self, app, max_bytes: int):
        self.app = app
        self.max_bytes = max_bytes

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        length = dict(scope.get("headers") or []).get(b"content-length")
        if length is not None:
            try:
                n = int(length)
            except ValueError:
                return await _send_json(send, 400, {"error": "bad Content-Length header"})
            if n > self.max_bytes:
                return await _send_json(send, 413, _too_large(self.max_bytes))
        seen = 0

        async def limited():
            nonlocal seen
            message = await receive()
            if message["type"] == "http.request":
                seen += len(message.get("body", b""))
                if seen > self.max_bytes:
                    raise HTTPException(413, _too_large(self.max_bytes)["error"])
            return message

        return await self.app(scope, limited, send)


def _too_large(limit: int) -> dict[str, str]:
    return {"error": f"request body too large: the limit is {limit // (1024 * 1024)} MB"}


async def _send_json(send, status: int, body: dict) -> None:
    data = json.dumps(body).encode()
    await send({"type": "http.response.start", "status": status,
                "headers": [(b"content-type", b"application/json"),
                            (b"content-length", str(len(data)).encode())]})
    await send({"type": "http.response.body", "body": data})


def _problem_response(e: InputError) -> JSONResponse:
    status = 409 if isinstance(e, F.FileExistsProblem) else 400
    if isinstance(e, F.MissingFileProblem) or (e.problems and all(
            p.kind == "vocabulary" and p.pointer in ("/category", "/variant") for p in e.problems)):
        status = 404
    first = e.problems[0].message if e.problems else str(e)
    return JSONResponse({"error": first, "problems": [p.to_dict() for p in e.problems]},
                        status_code=status)


async def _json_body(request: Request) -> Any:
    raw = await request.body()
    if not raw:
        raise InputError(Problem("", "the request needs a JSON body", None, "syntax"))
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        raise InputError(Problem("", "the request body is not UTF-8 text", None, "syntax")) from None
    data = loads_json(text)
    bad = _lone_surrogate(data)
    if bad is not None:
        raise InputError(Problem(bad, "a string holds a lone UTF-16 surrogate (\\ud800-\\udfff "
                                      "without its pair): it is not text", None, "syntax"))
    return data


def _lone_surrogate(value: Any) -> str | None:
    """The JSON pointer of the first string (or key) that is not encodable text, or None."""
    stack = [(value, "")]
    while stack:
        v, ptr = stack.pop()
        if isinstance(v, str):
            if not _encodable(v):
                return ptr or "/"
        elif isinstance(v, dict):
            for k, x in v.items():
                if not _encodable(k):
                    return ptr or "/"
                stack.append((x, f"{ptr}/{k}"))
        elif isinstance(v, list):
            stack += [(x, f"{ptr}/{i}") for i, x in enumerate(v)]
    return None


def _encodable(text: str) -> bool:
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


def _depth(value: Any) -> int:
    """Nesting depth of lists and dicts, without recursion."""
    deepest, stack = 0, [(value, 1)]
    while stack:
        v, d = stack.pop()
        if isinstance(v, dict):
            v = list(v.values())
        if isinstance(v, list):
            deepest = max(deepest, d)
            if d <= MAX_DEPTH:
                stack.extend((x, d + 1) for x in v)
    return deepest


def _object_body(body: Any, key: str | None = None) -> dict[str, Any]:
    if not isinstance(body, dict):
        raise InputError(Problem("", "the request body must be a JSON object", None, "schema"))
    if key is not None and key not in body:
        raise InputError(Problem(f"/{key}", f"the request body needs the key {key!r}", None,
                                 "schema"))
    return body


def _int_field(body: dict[str, Any], key: str, default: int, high: int = MAX_SEED) -> int:
    v = body.get(key, default)
    if isinstance(v, bool) or not isinstance(v, int) or not 0 <= v <= high:
        raise InputError(Problem(f"/{key}", f"{key} must be a non-negative integer of at most "
                                 f"{high:,} (as on the command line), got {json.dumps(v)}",
                                 None, "parameter"))
    return v


def vocabulary_payload() -> dict[str, Any]:
    """Everything the editor offers: categories (with the part words each understands),
    the words naming categories (synonyms and hypernyms, from the vocabulary file), surfaces,
    relations, room elements."""
    from ..assets.registry import categories, vocabulary
    from ..datagen.templates import ROOM_TYPES
    from ..words import Resolver

    words = Resolver(vocabulary())
    cats = [{"name": c.name, "variants": list(c.variants), "parts": list(c.parts),
             "vocabulary": list(c.vocabulary), "placement": c.placement,
             "size_range": list(c.size_range), "source": c.source,
             "part_words": words.part_words(c.name)}
            for c in categories().values()]
    names = {w: list(words.categories_for(w) or ())
             for w in words.words(synonyms=True)
             if w not in words.category_names() or words.is_hypernym(w)}
    relations = []
    for r in RELATIONS.values():
        parents = sorted(x for e in ROOM_PARENTS[r.name]
                         for x in (("wall", "wall_i") if e == "walls" else (e,)))
        relations.append({
            "name": r.name, "kind": r.kind, "child_surface": r.child_surface,
            "parent_surface": r.parent_surface, "meaning": r.meaning,
            "constraints": r.constraints, "phrase": r.phrase, "room_parents": parents,
            "params": [{"name": p.name, "type": p.type, "unit": p.unit, "low": p.low,
                        "high": p.high, "default": list(p.default) if isinstance(p.default, tuple)
                        else p.default, "choices": list(p.choices), "doc": p.doc,
                        "required": p.required} for p in r.params],
        })
    return {"categories": cats, "words": names,
            "surfaces": {k: list(v) for k, v in SURFACES.items()},
            "relations": relations, "room_types": list(ROOM_TYPES),
            "room_surfaces": ROOM_SURFACES, "stages": list(STAGES)}


def template_index() -> dict[str, dict[str, Any]]:
    """The bundled room templates by name: room type, description and file (not validated;
    expanding one validates it)."""
    from ..datagen.templates import templates_dir
    from ..pag.io import read_document

    out = {}
    for p in sorted(templates_dir().glob("*/*.yaml")):
        d = read_document(p)
        out[p.stem] = {"name": p.stem, "room_type": d.get("room_type", p.parent.name),
                       "description": d.get("description", ""), "path": p}
    return dict(sorted(out.items(), key=lambda kv: (kv[1]["room_type"], kv[0])))


def create_app(workdir: str | Path = ".", *, library=None, max_body: int = MAX_BODY_BYTES,
               host: str | None = None, port: int | None = None,
               other_hosts: tuple[str, ...] = (), max_queue: int = MAX_QUEUE,
               solve_time_limit: float = SOLVE_TIME_LIMIT) -> FastAPI:
    """The designer application serving ``workdir``, the only folder it writes.

    Parameters
    ----------
    workdir : str or Path
        PAG files are listed, read and saved here; solved scenes go to ``workdir/out/``.
    library : AssetLibrary, optional
        Where the solver takes assets from (default: the on-disk pool).
    max_body : int
        Largest request body, bytes (default 5 MB).
    host, port : str and int, optional
        The address the server listens on: requests must name it (or a loopback name) in
        their ``Host`` header, with this port (any port when None).
    other_hosts : tuple of str
        More names the server answers to (this machine's name and addresses when it listens
        on every interface).
    max_queue : int
        Solves queued or running at once; more are answered 429.
    solve_time_limit : float
        Seconds a solve may run; objects not placed by then fail with "time limit".
    """
    root = Path(workdir).resolve()
    if not root.is_dir():
        raise InputError(Problem("", "the working folder does not exist: create it or pass "
                                 "another --workdir", str(workdir), "io"))
    # no Swagger page: it would load its scripts from a CDN; the schema is at /api/openapi.json
    app = FastAPI(title="parse3d PAG designer", docs_url=None, redoc_url=None,
                  openapi_url="/api/openapi.json")
    app.add_middleware(_BodyLimit, max_bytes=max_body)
    hosts = LOOPBACK_HOSTS + ((host,) if host and host not in ("0.0.0.0", "::") else ()) \
        + tuple(other_hosts)
    app.add_middleware(_Guard, hosts=hosts, port=port)  # added last: runs first
    jobs: OrderedDict[str, Job] = OrderedDict()
    # one solve at a time: the physics engine and the machine are shared
    executor = ThreadPoolExecutor(max_workers=1, thread_name_prefix="parse3d-solve")
    state: dict[str, Any] = {}
    lock = threading.Lock()
    app.state.workdir = root
    app.state.jobs = jobs

    def vocab():
        from ..assets.registry import vocabulary

        return vocabulary()

    def cached(key: str, fn):
        with lock:
            if key not in state:
                state[key] = fn()
            return state[key]

    @app.exception_handler(InputError)
    async def _input_error(request: Request, e: InputError):
        return _problem_response(e)

    @app.exception_handler(StarletteHTTPException)
    async def _http_error(request: Request, e: StarletteHTTPException):
        return JSONResponse({"error": str(e.detail)}, status_code=e.status_code)

    @app.exception_handler(RequestValidationError)
    async def _request_error(request: Request, e: RequestValidationError):
        errs = e.errors()
        where = "/".join(str(x) for x in errs[0].get("loc", ())) if errs else ""
        msg = errs[0].get("msg", "bad request") if errs else "bad request"
        return JSONResponse({"error": f"{where}: {msg}"}, status_code=422)

    @app.exception_handler(Exception)
    async def _internal(request: Request, e: Exception):
        traceback.print_exception(e)
        return JSONResponse({"error": f"internal error: {type(e).__name__}: {e}"},
                            status_code=500)

    # ------------------------------------------------------------------ vocabulary
    @app.get("/api/vocabulary")
    async def get_vocabulary():
        return await run_in_threadpool(cached, "vocabulary", vocabulary_payload)

    @app.get("/api/assets/{category}.glb")
    async def get_asset(category: str, variant: str | None = None):
        from .preview import preview_glb

        data = await run_in_threadpool(preview_glb, category, variant)
        return Response(data, media_type="model/gltf-binary",
                        headers={"Cache-Control": "max-age=3600"})

    # ------------------------------------------------------------------ validation
    @app.post("/api/validate")
    async def post_validate(request: Request):
        data = await _json_body(request)
        problems = await run_in_threadpool(
            lambda: validate_data(data, vocabulary=cached("vocab", vocab)))
        return {"valid": not problems, "problems": [p.to_dict() for p in problems]}

    @app.post("/api/convert")
    async def post_convert(request: Request, to: str = "json"):
        data = _object_body(await _json_body(request))
        if to == "json":
            return Response(dumps_pag(data), media_type="application/json")
        if to == "yaml":
            return Response(F.yaml_text(data), media_type="application/yaml")
        raise InputError(Problem("/to", f"unknown format {to!r}: use json or yaml", None,
                                 "parameter"))

    # ------------------------------------------------------------------ solving
    @app.post("/api/solve", status_code=202)
    async def post_solve(request: Request):
        body = _object_body(await _json_body(request), "pag")
        seed = _int_field(body, "seed", 0)
        settle = body.get("settle", True)
        if not isinstance(settle, bool):
            raise InputError(Problem("/settle", "settle must be true or false", None,
                                     "parameter"))
        busy = sum(not j.finished for j in jobs.values())
        if busy >= max_queue:
            return JSONResponse({"error": f"{busy} solves are queued or running, the most this "
                                          "server takes: wait for one to finish or cancel one "
                                          "(DELETE /api/jobs/{id})"}, status_code=429,
                                headers={"Retry-After": "5"})
        job = Job.new(seed, settle)
        jobs[job.id] = job
        finished = [k for k, j in jobs.items() if j.finished]
        for k in finished[:max(0, len(finished) - _MAX_JOBS)]:
            del jobs[k]  # only finished jobs are forgotten: a running one stays listed
        voc = await run_in_threadpool(cached, "vocab", vocab)
        executor.submit(run_job, job, body["pag"], workdir=root, vocabulary=voc, library=library,
                        time_limit=solve_time_limit)
        return {"job": job.id, "events": f"/api/jobs/{job.id}/events",
                "status": f"/api/jobs/{job.id}"}

    def get_job(job_id: str) -> Job:
        if job_id not in jobs:
            raise HTTPException(404, f"no job {job_id!r} (jobs are kept while the server runs)")
        return jobs[job_id]

    @app.get("/api/jobs/{job_id}")
    async def job_status(job_id: str):
        job = get_job(job_id)
        return {"job": job.id, "state": job.state, "seed": job.seed,
                "events": job.events_since(0), "result": job.result}

    @app.delete("/api/jobs/{job_id}")
    async def cancel_job(job_id: str):
        job = get_job(job_id)
        job.cancel()
        return {"job": job.id, "state": job.state}

    @app.get("/api/jobs/{job_id}/events")
    async def job_events(job_id: str, request: Request):
        job = get_job(job_id)

        async def stream():
            n = 0
            while True:
                new = job.events_since(n)
                for ev in new:
                    yield f"event: {ev['type']}\ndata: {json.dumps(ev)}\n\n"
                n += len(new)
                if job.finished and not job.events_since(n):
                    break
                if await request.is_disconnected():
                    break
                await asyncio.sleep(0.05)

        return StreamingResponse(stream(), media_type="text/event-stream",
                                 headers={"Cache-Control": "no-cache"})

    @app.get("/api/jobs/{job_id}/files/{name}")
    async def job_file(job_id: str, name: str):
        job = get_job(job_id)
        if name not in SCENE_FILES:
            raise HTTPException(404, f"no scene file {name!r} (files: {', '.join(SCENE_FILES)})")
        if job.out is None or not (job.out / name).is_file():
            raise HTTPException(404, f"{name} is not written yet (job state: {job.state})")
        media = "model/gltf-binary" if name.endswith(".glb") else "application/json"
        return FileResponse(job.out / name, media_type=media, filename=name)

    # ------------------------------------------------------------------ templates
    @app.get("/api/templates")
    async def get_templates():
        index = await run_in_threadpool(cached, "templates", template_index)
        return [{k: v for k, v in t.items() if k != "path"} for t in index.values()]

    @app.post("/api/templates/{name}/expand")
    async def expand(name: str, request: Request):
        from ..datagen.templates import expand_template, load_template

        raw = await request.body()
        body = _object_body(await _json_body(request)) if raw.strip() else {}
        seed = _int_field(body, "seed", 0)
        index = await run_in_threadpool(cached, "templates", template_index)
        if name not in index:
            from ..pag.schema import suggest

            raise HTTPException(404, f"no template {name!r}{suggest(name, index)}")

        def run():
            t = load_template(index[name]["path"], vocabulary=cached("vocab", vocab))
            return expand_template(t, seed, vocabulary=cached("vocab", vocab)).to_dict()

        return await run_in_threadpool(run)

    # ------------------------------------------------------------------ files
    @app.get("/api/files")
    async def get_files():
        return {"workdir": root.name, "files": F.list_pag_files(root)}

    @app.get("/api/files/{name}")
    async def get_file(name: str):
        data = await run_in_threadpool(F.read_pag_file, root, name)
        if _depth(data) > MAX_DEPTH:
            raise InputError(Problem("", f"the file is nested more than {MAX_DEPTH} levels "
                                     "deep: a PAG never is", name, "syntax"))
        problems = await run_in_threadpool(
            lambda: validate_data(data, file=name, vocabulary=cached("vocab", vocab)))
        return {"name": name, "pag": data, "problems": [p.to_dict() for p in problems]}

    @app.put("/api/files/{name}")
    async def put_file(name: str, request: Request):
        body = _object_body(await _json_body(request), "pag")
        overwrite = body.get("overwrite", False)
        if not isinstance(overwrite, bool):
            raise InputError(Problem("/overwrite", "overwrite must be true or false", None,
                                     "parameter"))
        p = await run_in_threadpool(F.write_pag_file, root, name, body["pag"],
                                    overwrite=overwrite)
        problems = await run_in_threadpool(
            lambda: validate_data(body["pag"], file=name, vocabulary=cached("vocab", vocab)))
        return {"name": p.name, "bytes": p.stat().st_size, "valid": not problems,
                "problems": [q.to_dict() for q in problems]}

    # ------------------------------------------------------------------ front end
    @app.api_route("/api/{rest:path}", methods=["GET", "POST", "PUT", "DELETE", "PATCH"])
    async def unknown_api(rest: str):
        if rest.startswith("files/"):  # a name with a slash, once the URL was decoded
            F.check_name(rest[len("files/"):])
        raise HTTPException(404, f"no API endpoint /api/{rest}")

    @app.get("/")
    async def index():
        return FileResponse(STATIC_DIR / "index.html", media_type="text/html")

    app.mount("/", StaticFiles(directory=STATIC_DIR), name="static")
    def warm_up() -> None:  # the first page load should not wait for the asset registry
        cached("vocabulary", vocabulary_payload)
        cached("vocab", vocab)

    app.router.on_startup.append(
        lambda: threading.Thread(target=warm_up, name="parse3d-warm-up", daemon=True).start())
    app.router.on_shutdown.append(lambda: executor.shutdown(wait=False, cancel_futures=True))
    return app
