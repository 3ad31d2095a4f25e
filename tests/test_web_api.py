"""The designer's JSON API (parse3d.web): every endpoint, and bad requests answered with 4xx."""

from __future__ import annotations

import json
import struct

import pytest
import yaml

pytest.importorskip("fastapi")
from fastapi.testclient import TestClient  # noqa: E402
from typer.testing import CliRunner  # noqa: E402

from parse3d.assets import registry  # noqa: E402
from parse3d.cli import app as cli_app  # noqa: E402
from parse3d.pag import validate_data  # noqa: E402
from parse3d.scene.io import SCENE_FORMAT  # noqa: E402
from parse3d.web import MAX_BODY_BYTES, create_app  # noqa: E402

ROOM = {"type": "study", "footprint": [[0, 0], [3, 0], [3, 2.5], [0, 2.5]], "height": 2.6}


def small_pag(name: str = "corner") -> dict:
    return {"format": "pag/1", "name": name, "room": ROOM,
            "objects": [{"id": "desk", "category": "desk"}, {"id": "lamp", "category": "table_lamp"}],
            "relations": [{"relation": "ON", "child": "desk", "parent": "floor"},
                          {"relation": "ON", "child": "lamp:base@bottom",
                           "parent": "desk:tabletop@top"}]}


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    return tmp_path_factory.mktemp("designer")


#: What the designer's own page sends: its address, and JSON bodies.
PAGE = {"base_url": "http://127.0.0.1:8765", "headers": {"Content-Type": "application/json"}}


@pytest.fixture(scope="module")
def client(workdir):
    with TestClient(create_app(workdir, port=8765), **PAGE) as c:
        yield c


def glb_json(data: bytes) -> dict:
    """The JSON chunk of a GLB file."""
    magic, version, _ = struct.unpack("<4sII", data[:12])
    assert magic == b"glTF" and version == 2
    n, kind = struct.unpack("<I4s", data[12:20])
    assert kind == b"JSON"
    return json.loads(data[20:20 + n])


def test_vocabulary_lists_categories_parts_and_relation_parameters(client):
    v = client.get("/api/vocabulary").json()
    cats = {c["name"]: c for c in v["categories"]}
    assert set(cats) == set(registry.categories())
    assert {"tabletop", "leg"} <= set(cats["desk"]["parts"])
    assert "top" in cats["desk"]["part_words"]  # the vocabulary file's words for its parts
    assert v["words"]["couch"] == ["sofa"] and "dining_chair" in v["words"]["chair"]
    assert cats["table_lamp"]["variants"] == list(registry.get("table_lamp").variants)
    rel = {r["name"]: r for r in v["relations"]}
    assert rel["ON"]["kind"] == "support" and rel["ON"]["child_surface"] == "bottom"
    near = {p["name"]: p for p in rel["NEAR"]["params"]}["distance"]
    assert (near["unit"], near["low"], near["high"], near["default"]) == ("m", 0.0, 50.0, 1.0)
    side = rel["SIDE_OF"]["params"][0]
    assert side["required"] and side["choices"] == ["left", "right", "front", "back"]
    assert rel["LEANING_AGAINST"]["params"][0]["default"] == [8.0, 16.0]
    assert rel["ON"]["room_parents"] == ["floor"] and rel["IN"]["room_parents"] == []
    assert rel["AGAINST"]["room_parents"] == ["wall", "wall_i"]
    assert v["surfaces"]["top"] == [0.0, 0.0, 1.0]
    assert "study" in v["room_types"]
    assert v["stages"] == ["validate", "solve", "settle", "contacts", "export"]


def test_asset_preview_has_one_node_per_part_with_label_and_surfaces(client):
    r = client.get("/api/assets/table_lamp.glb", params={"variant": "column"})
    assert r.status_code == 200 and r.headers["content-type"] == "model/gltf-binary"
    tree = glb_json(r.content)
    asset = registry.generate("table_lamp", seed=0, variant="column")
    nodes = {n["name"]: n for n in tree["nodes"] if "mesh" in n}
    assert set(nodes) == {p.name for p in asset.parts}
    base = nodes["base"]["extras"]
    assert base["label"] == "base" and base["k"] == 0 and base["category"] == "table_lamp"
    assert set(base["surfaces"]) == {"top", "bottom", "front", "back", "left", "right"}
    # glTF is Y-up: the asset's -Z bottom normal is -Y, its +Y front is -Z
    assert base["surfaces"]["bottom"]["normal"] == pytest.approx([0, -1, 0], abs=1e-6)
    assert base["surfaces"]["front"]["normal"] == pytest.approx([0, 0, -1], abs=1e-6)
    # the base is the lowest part: its bottom surface is at the floor of the asset frame
    assert base["surfaces"]["bottom"]["origin"][1] == pytest.approx(0.0, abs=1e-3)


def test_asset_preview_numbers_parts_that_share_a_label(client):
    tree = glb_json(client.get("/api/assets/desk.glb", params={"variant": "four_leg"}).content)
    legs = sorted(n["extras"]["k"] for n in tree["nodes"] if n.get("extras", {}).get("label") == "leg")
    assert legs == list(range(len(legs))) and len(legs) == 4


@pytest.mark.parametrize("url, fragment", [
    ("/api/assets/nighstand.glb", "did you mean 'nightstand'"),
    ("/api/assets/desk.glb?variant=round", "has no variant 'round'"),
    ("/api/jobs/nope", "no job"),
    ("/api/jobs/nope/events", "no job"),
    ("/api/nothing/here", "no API endpoint"),
    ("/api/files/missing.json", "no file 'missing.json'"),
])
def test_unknown_things_are_404_with_a_message(client, url, fragment):
    r = client.get(url)
    assert r.status_code == 404
    assert fragment in r.json()["error"]


def test_validation_gives_the_cli_problems_and_pointers(client, workdir):
    bad = small_pag()
    bad["objects"].append({"id": "mug", "category": "mugg"})
    bad["relations"][1]["parent"] = "desk:tabletop@tpo"
    bad["room"] = {**ROOM, "height": -1}
    r = client.post("/api/validate", json=bad).json()
    assert not r["valid"]
    got = {(p["pointer"], p["message"]) for p in r["problems"]}
    path = workdir / "bad-for-cli.json"
    path.write_text(json.dumps(bad))
    out = CliRunner().invoke(cli_app, ["validate", str(path), "--json"])
    assert out.exit_code == 2
    cli = {(p["pointer"], p["message"]) for p in json.loads(out.stdout)[0]["errors"]}
    assert got == cli
    pointers = {p for p, _ in got}
    assert {"/objects/2/category", "/relations/1/parent", "/room/height", "/objects/2"} <= pointers
    assert client.post("/api/validate", json=small_pag()).json() == {"valid": True, "problems": []}


@pytest.mark.parametrize("method, url, body, status, fragment", [
    ("post", "/api/validate", b'{"format": "pag/1",', 400, "invalid JSON at line 1"),
    ("post", "/api/validate", b"", 400, "needs a JSON body"),
    ("post", "/api/validate", b"\xff\xfe", 400, "not UTF-8"),
    ("post", "/api/validate", b'{"height": NaN}', 400, "NaN is not a number"),
    ("post", "/api/validate", b"[" * 100_000 + b"]" * 100_000, 400, "nested more than 64"),
    ("post", "/api/convert?to=yaml", b'{"meta": ' + b"[" * 500 + b"]" * 500 + b"}", 400,
     "nested more than 64"),
    ("post", "/api/solve", b"[1, 2]", 400, "must be a JSON object"),
    ("post", "/api/solve", b'{"seed": 1}', 400, "needs the key 'pag'"),
    ("post", "/api/solve", b'{"pag": {}, "seed": -3}', 400, "non-negative integer"),
    ("post", "/api/solve", b'{"pag": {}, "seed": 4294967296}', 400, "4,294,967,295"),
    ("post", "/api/validate", b'{"name": "\\ud800"}', 400, "surrogate"),
    ("put", "/api/files/lone.json", b'{"pag": {"name": "x\\udc00"}}', 400, "surrogate"),
    ("put", "/api/files/lone.yaml", b'{"pag": {"\\ud83d": 1}}', 400, "surrogate"),
    ("post", "/api/validate", b'{"a": 1, "a": 2}', 400, "repeated"),
    ("post", "/api/solve", b'{"pag": {}, "settle": "yes"}', 400, "true or false"),
    ("post", "/api/convert?to=xml", b"{}", 400, "use json or yaml"),
    ("put", "/api/files/room.json", b'{"pag": {}, "overwrite": 1}', 400, "true or false"),
    ("put", "/api/files/room.txt", b'{"pag": {}}', 400, "no PAG file extension"),
    ("put", "/api/files/.hidden.json", b'{"pag": {}}', 400, "not starting with a dot"),
    ("put", "/api/files/..%2Fescape.json", b'{"pag": {}}', 400, "not a plain file name"),
    ("put", "/api/files/a%5Cb.json", b'{"pag": {}}', 400, "not a plain file name"),
    ("put", "/api/files/room.json", b'{"pag": [1]}', 400, "must be a JSON object"),
    ("get", "/api/files/..%2F..%2Fetc%2Fpasswd", None, 400, "not a plain file name"),
    ("post", "/api/templates/study-reading-01/expand", b'{"seed": "x"}', 400, "non-negative"),
])
def test_bad_requests_are_4xx_with_a_json_message(client, workdir, method, url, body, status,
                                                  fragment):
    before = sorted(p.name for p in workdir.parent.iterdir())
    r = getattr(client, method)(url, content=body) if body is not None else client.get(url)
    assert r.status_code == status, r.text
    assert fragment in r.json()["error"]
    assert sorted(p.name for p in workdir.parent.iterdir()) == before  # nothing written outside


def test_path_traversal_through_the_url_never_leaves_the_folder(client, workdir):
    for url in ("/api/files/../escape.json", "/api/files/%2E%2E/escape.json",
                "/api/files/sub%2Fescape.json"):
        r = client.put(url, json={"pag": small_pag()})
        assert 400 <= r.status_code < 500 and r.json()["error"]
    assert not (workdir.parent / "escape.json").exists()
    assert not (workdir / "sub").exists()


def test_oversized_bodies_are_413(client):
    big = b'{"pad": "' + b"x" * (MAX_BODY_BYTES + 10) + b'"}'
    r = client.post("/api/validate", content=big)
    assert r.status_code == 413 and "too large" in r.json()["error"]

    def chunks():  # no Content-Length: the body is counted as it arrives
        for _ in range(6):
            yield b"x" * (1024 * 1024)

    r = client.post("/api/validate", content=chunks())
    assert r.status_code == 413 and "5 MB" in r.json()["error"]


def test_save_list_open_and_never_overwrite_by_accident(client, workdir):
    pag = small_pag("saved-room")
    r = client.put("/api/files/saved.json", json={"pag": pag})
    assert r.status_code == 200 and r.json()["valid"]
    assert validate_data(json.loads((workdir / "saved.json").read_text())) == []
    again = client.put("/api/files/saved.json", json={"pag": small_pag("other")})
    assert again.status_code == 409 and "exists already" in again.json()["error"]
    assert json.loads((workdir / "saved.json").read_text())["name"] == "saved-room"
    pag["name"] = "renamed"
    assert client.put("/api/files/saved.json", json={"pag": pag, "overwrite": True}).status_code == 200
    assert json.loads((workdir / "saved.json").read_text())["name"] == "renamed"
    r = client.put("/api/files/saved.yaml", json={"pag": pag})
    assert r.status_code == 200
    assert yaml.safe_load((workdir / "saved.yaml").read_text()) == pag
    names = [f["name"] for f in client.get("/api/files").json()["files"]]
    assert {"saved.json", "saved.yaml"} <= set(names)
    opened = client.get("/api/files/saved.yaml").json()
    assert opened["pag"] == pag and opened["problems"] == []
    # an invalid PAG is saved as work in progress, with its problems reported
    bad = {**pag, "relations": pag["relations"][:1]}
    r = client.put("/api/files/draft.json", json={"pag": bad}).json()
    assert not r["valid"] and r["problems"][0]["pointer"] == "/objects/1"
    assert not list(workdir.glob(".*"))  # no temporary files left


def test_files_that_are_not_pags_open_with_a_message(client, workdir):
    (workdir / "broken.json").write_text('{"format": "pag/1",\n  "name": }')
    r = client.get("/api/files/broken.json")
    assert r.status_code == 400 and r.json()["error"].startswith("invalid JSON at line 2")
    (workdir / "deep.yaml").write_text("a: " + "[" * 3000 + "]" * 3000 + "\n")
    r = client.get("/api/files/deep.yaml")
    assert r.status_code == 400 and "nested" in r.json()["error"]


def test_convert_gives_the_text_of_a_saved_file(client):
    pag = small_pag()
    assert yaml.safe_load(client.post("/api/convert?to=yaml", json=pag).text) == pag
    assert json.loads(client.post("/api/convert?to=json", json=pag).text) == pag


def test_templates_list_and_expand(client):
    ts = client.get("/api/templates").json()
    assert len(ts) > 100 and {"name", "room_type", "description"} <= set(ts[0])
    name = next(t["name"] for t in ts if t["room_type"] == "study")
    a = client.post(f"/api/templates/{name}/expand", json={"seed": 1}).json()
    assert a["name"] == f"{name}-s1" and validate_data(a, vocabulary=registry.vocabulary()) == []
    b = client.post(f"/api/templates/{name}/expand", json={"seed": 1}).json()
    assert a == b
    r = client.post("/api/templates/study-nope/expand", json={})
    assert r.status_code == 404 and "no template" in r.json()["error"]


def sse(text: str) -> list[dict]:
    return [json.loads(line[5:]) for line in text.splitlines() if line.startswith("data:")]


def test_solve_streams_stage_progress_and_serves_the_scene(client, workdir):
    r = client.post("/api/solve", json={"pag": small_pag(), "seed": 2, "settle": True})
    assert r.status_code == 202
    job = r.json()["job"]
    events = sse(client.get(f"/api/jobs/{job}/events").text)
    stages = [(e["stage"], e["status"]) for e in events if e["type"] == "stage"]
    assert stages == [(s, x) for s in ("validate", "solve", "settle", "contacts", "export")
                      for x in ("start", "done")]
    assert [e["id"] for e in events if e["type"] == "object"] == ["desk", "lamp"]
    assert events[-1]["type"] == "done" and events[-1]["ok"]
    status = client.get(f"/api/jobs/{job}").json()
    assert status["state"] == "done"
    res = status["result"]
    assert res["settled"] and res["out"] == "out/corner-2"
    assert [r["holds_settled"] for r in res["relations"]] == [True, True]
    pairs = {(c["a"], c["b"]) for c in res["contacts"]}
    assert ("desk:tabletop", "lamp:base") in pairs
    glb = client.get(f"/api/jobs/{job}/files/scene.glb")
    assert glb.status_code == 200
    names = {n["name"] for n in glb_json(glb.content)["nodes"]}
    assert {"lamp__base", "desk__tabletop", "room__ceiling", "room__floor"} <= names
    scene = client.get(f"/api/jobs/{job}/files/scene.json").json()
    assert scene["format"] == SCENE_FORMAT and scene["seed"] == 2
    assert (workdir / "out" / "corner-2" / "contacts.json").is_file()
    assert client.get(f"/api/jobs/{job}/files/preview.png").status_code == 404
    # the stream of a finished job replays everything
    assert sse(client.get(f"/api/jobs/{job}/events").text) == events


def test_solving_an_invalid_pag_reports_its_problems(client):
    bad = small_pag()
    bad["relations"].pop()
    job = client.post("/api/solve", json={"pag": bad}).json()["job"]
    events = sse(client.get(f"/api/jobs/{job}/events").text)
    assert events[-1]["type"] == "error" and events[-1]["stage"] == "validate"
    assert events[-1]["problems"][0]["pointer"] == "/objects/1"
    assert client.get(f"/api/jobs/{job}").json()["state"] == "failed"
    assert client.get(f"/api/jobs/{job}/files/scene.json").status_code == 404


def test_front_end_is_served_with_three_js_from_the_package(client):
    page = client.get("/")
    assert page.status_code == 200 and "text/html" in page.headers["content-type"]
    assert "http://" not in page.text and "https://" not in page.text  # no CDN
    assert '"three": "./vendor/three.module.min.js"' in page.text
    for f in ("main.js", "picker.js", "vendor/three.module.min.js",
              "vendor/addons/loaders/GLTFLoader.js", "vendor/addons/controls/OrbitControls.js"):
        assert client.get(f"/{f}").status_code == 200, f
    assert client.get("/nothing.js").status_code == 404


def test_serve_command_help_and_bad_workdir(tmp_path):
    runner = CliRunner()
    out = runner.invoke(cli_app, ["serve", "--help"])
    assert out.exit_code == 0 and "Example" in out.stdout and "--workdir" in out.stdout
    from parse3d.cli import main

    with pytest.raises(SystemExit) as e:
        main(["serve", "--workdir", str(tmp_path / "missing")])
    assert e.value.code == 2


def test_committed_front_end_is_the_build_of_its_sources():
    """static/ holds web/src/ as built by web/build.mjs, with three.js at the pinned version."""
    from pathlib import Path

    from parse3d.web.app import STATIC_DIR

    src = Path(__file__).resolve().parents[1] / "web"
    if not (src / "src").is_dir():
        pytest.skip("the front-end sources are not in this installation (an sdist or wheel)")
    for f in (src / "src").iterdir():
        assert (STATIC_DIR / f.name).read_bytes() == f.read_bytes(), \
            f"static/{f.name} differs from web/src/{f.name}: run `node web/build.mjs`"
    pinned = json.loads((src / "package.json").read_text())["dependencies"]["three"]
    three = (STATIC_DIR / "vendor" / "three.module.min.js").read_text()
    assert f'const t="{pinned.split(".")[1]}"' in three[:1000], "vendored three.js is not the pinned one"


# ------------------------------------------------------------------- a laptop's server


def test_foreign_hosts_and_cross_site_requests_are_refused(client, workdir):
    """DNS rebinding (a foreign Host) and CSRF (a foreign Origin, a form's text/plain body)
    never reach the API; nothing is read or written."""
    (workdir / "mine.json").write_text(json.dumps(small_pag("mine")))
    before = (workdir / "mine.json").read_text()
    body = json.dumps({"pag": small_pag("evil"), "overwrite": True})
    for host in ("evil.example:8765", "127.0.0.1:9999", "localhost.evil.example", ""):
        r = client.get("/api/files/mine.json", headers={"Host": host})
        assert r.status_code == 403 and "Host" in r.json()["error"], host
        r = client.put("/api/files/mine.json", content=body, headers={"Host": host})
        assert r.status_code == 403
    for host in ("localhost:8765", "[::1]:8765", "127.0.0.1:8765"):
        assert client.get("/api/files", headers={"Host": host}).status_code == 200
    for origin in ("http://evil.example", "http://127.0.0.1:9999", "null"):
        r = client.put("/api/files/mine.json", content=body, headers={"Origin": origin})
        assert r.status_code == 403 and "refused" in r.json()["error"], origin
        r = client.post("/api/solve", content=body, headers={"Origin": origin})
        assert r.status_code == 403
    r = client.post("/api/validate", content=body, headers={"Sec-Fetch-Site": "cross-site"})
    assert r.status_code == 403
    for ctype in ("text/plain", "application/x-www-form-urlencoded", "multipart/form-data", ""):
        for method, url in (("put", "/api/files/mine.json"), ("post", "/api/solve"),
                            ("post", "/api/validate"), ("post", "/api/convert"),
                            ("delete", "/api/jobs/x")):
            r = client.request(method, url, content=body, headers={"Content-Type": ctype})
            assert r.status_code == 415 and "application/json" in r.json()["error"]
    assert (workdir / "mine.json").read_text() == before
    assert not (workdir / "out" / "evil-0").exists()
    # the page itself (same origin, JSON) works
    r = client.post("/api/validate", content=body, headers={
        "Origin": "http://127.0.0.1:8765", "Sec-Fetch-Site": "same-origin"})
    assert r.status_code == 200


def test_the_solve_queue_is_bounded_cancellable_and_never_forgets_a_running_job(
        tmp_path, monkeypatch):
    import threading

    from parse3d.web import app as web_app

    # the first job waits until the second is cancelled, so the second is surely still queued
    # then (a fast machine, or a slow one, must not decide which state it is in)
    go, real_run = threading.Event(), web_app.run_job

    def first_waits(job, *args, **kwargs):
        if job.seed == 0:
            go.wait(60)
        return real_run(job, *args, **kwargs)

    monkeypatch.setattr(web_app, "run_job", first_waits)
    with TestClient(create_app(tmp_path, max_queue=2), **PAGE) as c:
        ids = []
        for seed in range(2):
            r = c.post("/api/solve", json={"pag": small_pag(), "seed": seed, "settle": True})
            assert r.status_code == 202
            ids.append(r.json()["job"])
        r = c.post("/api/solve", json={"pag": small_pag(), "seed": 9})
        assert r.status_code == 429 and "cancel" in r.json()["error"]
        assert c.delete(f"/api/jobs/{ids[1]}").json()["state"] in ("cancelled", "running")
        go.set()
        events = sse(c.get(f"/api/jobs/{ids[1]}/events").text)
        assert events[-1] == {**events[-1], "type": "error", "message": "cancelled"}
        assert sse(c.get(f"/api/jobs/{ids[0]}/events").text)[-1]["type"] == "done"
        assert c.get(f"/api/jobs/{ids[1]}").json()["state"] == "cancelled"
        assert not (tmp_path / "out" / "corner-1").exists()
        assert c.delete("/api/jobs/nope").status_code == 404
        # a queue with room again takes a solve
        assert c.post("/api/solve", json={"pag": small_pag(), "seed": 3}).status_code == 202


def test_solves_never_write_through_a_link_out_of_the_folder(tmp_path):
    work, elsewhere = tmp_path / "work", tmp_path / "elsewhere"
    work.mkdir()
    elsewhere.mkdir()
    (work / "out").symlink_to(elsewhere)
    (work / "dir.json").mkdir()
    with TestClient(create_app(work), **PAGE) as c:
        job = c.post("/api/solve", json={"pag": small_pag(), "settle": False}).json()["job"]
        events = sse(c.get(f"/api/jobs/{job}/events").text)
        assert events[-1]["type"] == "error" and "link out of the working folder" in \
            events[-1]["message"]
        r = c.put("/api/files/dir.json", json={"pag": small_pag(), "overwrite": True})
        assert r.status_code == 400 and "folder" in r.json()["error"]
    assert list(elsewhere.iterdir()) == []
    assert sorted(p.name for p in work.iterdir()) == ["dir.json", "out"]  # no temporary files


def test_serve_refuses_a_busy_port_and_warns_about_a_public_address(tmp_path):
    import socket
    import subprocess
    import sys

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()
        port = s.getsockname()[1]
        r = subprocess.run([sys.executable, "-m", "parse3d", "serve", "--workdir", str(tmp_path),
                            "--port", str(port)], capture_output=True, text=True, timeout=60)
    assert r.returncode == 2
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and f"port {port}" in lines[0] and "in use" in lines[0], r.stderr
    r = subprocess.run([sys.executable, "-m", "parse3d", "serve", "--workdir", str(tmp_path),
                        "--host", "no-such-host.invalid"], capture_output=True, text=True,
                       timeout=60)
    assert r.returncode == 2 and "--host" in r.stderr and "Traceback" not in r.stderr
    from parse3d.cli.serve import _check_address

    assert _check_address("127.0.0.1")[1] and _check_address("localhost")[1]
    assert not _check_address("0.0.0.0")[1]
