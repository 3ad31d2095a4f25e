"""The dataset builder: local and Ray executors, resume after SIGKILL, failures, statistics.

Every build here uses tiny PAGs (two or three objects) and ``--views 0`` so the whole file
stays fast; the reference dataset is built once per module.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from typer.testing import CliRunner

from parse3d.cli import app, main
from parse3d.datagen.build import BuildConfig, build_dataset, plan_scene, resolve_pag_paths
from parse3d.datagen.manifest import TIMING_COLUMNS, read_manifest

SCENES = 6


def _pag(name, room_type, objects, relations, size=(3.0, 3.0)):
    w, d = size
    return {"format": "pag/1", "name": name,
            "room": {"type": room_type, "footprint": [[0, 0], [w, 0], [w, d], [0, d]],
                     "height": 2.6},
            "objects": [{"id": i, "category": c} for i, c in objects], "relations": relations}


def _on(child, parent):
    return {"relation": "ON", "child": child, "parent": parent}


GOOD = [
    _pag("tiny-study", "study", [("desk", "desk"), ("mug", "mug"), ("book", "book")],
         [_on("desk", "floor"), _on("mug", "desk:tabletop"), _on("book", "desk:tabletop")]),
    _pag("tiny-kitchen", "kitchen", [("table", "dining_table"), ("plate", "plate"),
                                     ("cup", "cup")],
         [_on("table", "floor"), _on("plate", "table:tabletop"), _on("cup", "table:tabletop")]),
    _pag("tiny-bedroom", "bedroom", [("ns", "nightstand"), ("lamp", "table_lamp")],
         [_on("ns", "floor"), {"relation": "AGAINST", "child": "ns@back", "parent": "wall_0"},
          _on("lamp", "ns:top_panel")]),
]
BAD = [
    # validates only up to the category: raises InputError when the scene is built
    _pag("broken-storage", "storage", [("box", "flux_capacitor")], [_on("box", "floor")]),
    # a bed (1.9 m at least) cannot fit a 1.2 m room: nothing is placed
    _pag("cramped-bar", "bar", [("bed", "bed")], [_on("bed", "floor")], size=(1.2, 1.2)),
]


def _write_pags(folder: Path, pags) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    for p in pags:
        (folder / f"{p['name']}.json").write_text(json.dumps(p))
    return folder


@pytest.fixture(scope="module")
def pags(tmp_path_factory) -> Path:
    return _write_pags(tmp_path_factory.mktemp("pags"), GOOD)


@pytest.fixture(scope="module")
def reference(tmp_path_factory, pags) -> Path:
    """The uninterrupted 2-worker build every other build is compared with."""
    out = tmp_path_factory.mktemp("ref") / "ds"
    cfg = BuildConfig(scenes=SCENES, seed=7, source=resolve_pag_paths([pags]))
    report = build_dataset(cfg, out, workers=2)
    assert (report.ok, report.failed, report.built) == (SCENES, 0, SCENES)
    return out


def _strip(row: dict) -> dict:
    return {k: v for k, v in row.items() if k not in TIMING_COLUMNS}


def _scene_doc(folder: Path) -> dict:
    d = json.loads((folder / "scene.json").read_text())
    d.pop("timings")
    return d


def assert_same_scenes(a: Path, b: Path, indices) -> None:
    for i in indices:
        name = f"{i:05d}"
        assert _scene_doc(a / "scenes" / name) == _scene_doc(b / "scenes" / name), name
        assert ((a / "scenes" / name / "contacts.json").read_text()
                == (b / "scenes" / name / "contacts.json").read_text())


def test_build_covers_room_types_and_writes_every_file(reference, pags):
    rows = read_manifest(reference / "manifest.parquet")
    assert [r["index"] for r in rows] == list(range(SCENES))
    assert all(r["status"] == "ok" and r["reason"] is None for r in rows)
    # room types cycle in the source's order, so all are covered evenly
    assert [r["room_type"] for r in rows] == ["bedroom", "study", "kitchen"] * 2
    for r in rows:
        folder = reference / "scenes" / r["scene"]
        files = {p.name for p in folder.iterdir()}
        assert {"scene.json", "scene.glb", "contacts.json", "preview.png",
                "record.json"} <= files
        doc = json.loads((folder / "scene.json").read_text())
        assert doc["seed"] == r["seed"] and doc["room"]["type"] == r["room_type"]
        assert r["placed"] == doc["summary"]["placed"] == len(r["categories"]) == len(r["parts"])
        assert r["contacts"] == len(json.loads((folder / "contacts.json").read_text())) > 0
        assert r["density"] == pytest.approx(r["placed"] / r["area"], rel=1e-5)
        assert all(r[t] >= 0 for t in TIMING_COLUMNS) and r["t_solve"] > 0
        assert json.loads((folder / "record.json").read_text())["index"] == r["index"]
    assert not list(reference.glob(".tmp-*"))
    cfg = json.loads((reference / "dataset.json").read_text())
    assert cfg["format"] == "parse3d-dataset/1" and cfg["seed"] == 7
    assert cfg["rooms"] == ["bedroom", "study", "kitchen"]
    # the plan is a pure function of (seed, index)
    source_cfg = BuildConfig(scenes=SCENES, seed=7, source=resolve_pag_paths([pags]))
    from parse3d.datagen.build import make_source

    src = make_source(source_cfg)
    for r in rows:
        p = plan_scene(source_cfg, src, r["index"])
        assert (p.room_type, p.template, p.seed) == (r["room_type"], r["template"], r["seed"])


def test_resume_after_sigkill_gives_the_uninterrupted_result(reference, pags, tmp_path):
    out = tmp_path / "ds"
    cmd = [sys.executable, "-m", "parse3d", "dataset", "build", "--scenes", str(SCENES),
           "--out", str(out), "--pags", str(pags), "--seed", "7", "--views", "0"]
    proc = subprocess.Popen(cmd + ["--workers", "2"], start_new_session=True,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            done = list((out / "scenes").glob("[0-9]*")) if (out / "scenes").exists() else []
            if len(done) >= 2 or proc.poll() is not None:
                break
            time.sleep(0.05)
    finally:
        os.killpg(proc.pid, signal.SIGKILL)  # the driver and its workers, mid-run
        proc.wait()
    killed_with = len(list((out / "scenes").glob("[0-9]*")))
    assert 0 < killed_with < SCENES, "the kill should land mid-run"
    # the same command again (with another worker count): only the missing scenes run
    res = subprocess.run(cmd + ["--workers", "1", "--json"], capture_output=True, text=True,
                         timeout=120)
    assert res.returncode == 0, res.stderr
    summary = json.loads(res.stdout)
    assert summary["resumed"] >= killed_with and summary["built"] == SCENES - summary["resumed"]
    rows = [_strip(r) for r in read_manifest(out / "manifest.parquet")]
    ref = [_strip(r) for r in read_manifest(reference / "manifest.parquet")]
    assert rows == ref
    assert sorted(p.name for p in (out / "scenes").iterdir()) == [f"{i:05d}"
                                                                  for i in range(SCENES)]
    assert not list(out.glob(".tmp-*"))
    assert_same_scenes(reference, out, range(SCENES))


def test_failing_and_timed_out_scenes_are_recorded(tmp_path, pags):
    bad = _write_pags(tmp_path / "bad", [GOOD[0], *BAD])
    out = tmp_path / "ds"
    cfg = BuildConfig(scenes=3, seed=1, rooms=("storage", "bar", "study"),
                      source=resolve_pag_paths([bad]))
    report = build_dataset(cfg, out, workers=2)
    assert (report.ok, report.failed, report.timeout) == (1, 2, 0)
    rows = {r["room_type"]: r for r in read_manifest(out / "manifest.parquet")}
    assert rows["storage"]["status"] == "failed"
    assert "VocabularyError" in rows["storage"]["reason"]
    assert "flux_capacitor" in rows["storage"]["reason"]
    assert rows["bar"]["status"] == "failed" and rows["bar"]["placed"] == 0
    assert "no object could be placed" in rows["bar"]["reason"]
    assert rows["study"]["status"] == "ok"
    assert sorted(p.name for p in (out / "scenes").iterdir()) == ["00002"]
    fail = json.loads((out / "failures" / "00000.json").read_text())
    assert "Traceback" in fail["traceback"] and fail["record"]["status"] == "failed"
    # resuming keeps the failures; --retry-failed runs them again (and they fail again)
    again = build_dataset(cfg, out, workers=1)
    assert (again.built, again.resumed) == (0, 3)
    retried = build_dataset(cfg, out, workers=1, retry_failed=True)
    assert (retried.built, retried.failed, retried.ok) == (2, 2, 1)

    slow = BuildConfig(scenes=1, seed=1, rooms=("study",), source=resolve_pag_paths([bad]),
                       time_limit=0.05)
    report = build_dataset(slow, tmp_path / "slow", workers=1)
    (row,) = read_manifest(tmp_path / "slow" / "manifest.parquet")
    assert report.timeout == 1 and row["status"] == "timeout"
    # the soft limit ("ran past the 0.05 s time limit") or, on a loaded machine, the hard kill
    assert "time limit" in row["reason"] and "0.05 s" in row["reason"]


def test_ray_executor_matches_local(reference, pags, tmp_path):
    import ray

    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    try:
        cfg = BuildConfig(scenes=2, seed=7, source=resolve_pag_paths([pags]))
        report = build_dataset(cfg, tmp_path / "ray", executor="ray", workers=2)
    finally:
        ray.shutdown()
    assert (report.ok, report.built) == (2, 2)
    rows = [_strip(r) for r in read_manifest(tmp_path / "ray" / "manifest.parquet")]
    ref = [_strip(r) for r in read_manifest(reference / "manifest.parquet")][:2]
    assert rows == ref
    assert_same_scenes(reference, tmp_path / "ray", range(2))


def test_stats_writes_plots_and_tables(reference, tmp_path):
    out = tmp_path / "stats"
    res = CliRunner().invoke(app, ["dataset", "stats", str(reference), "--out", str(out)])
    assert res.exit_code == 0, res.output
    printed = res.stdout
    for name in ("categories", "parts_per_object", "room_types", "object_density",
                 "contacts_per_scene", "objects_per_scene"):
        img = np.asarray(Image.open(out / f"{name}.png").convert("L"))
        assert img.shape[0] > 300 and img.shape[1] > 600
        assert (img < 128).mean() > 0.005, f"{name}.png looks empty"
    table = json.loads((out / "stats.json").read_text())
    rows = read_manifest(reference / "manifest.parquet")
    s = table["summary"]
    assert s["scenes"] == SCENES and s["objects"] == sum(r["placed"] for r in rows)
    ok = sum(r["status"] == "ok" for r in rows)
    assert s["scenes_ok"] == ok
    assert f"| {ok} + {SCENES - ok} / {SCENES} |" in (out / "stats.md").read_text()
    assert s["distinct_assets"] == len({a for r in rows for a in r["assets"]})
    assert s["avg_objects"] == pytest.approx(np.mean([r["placed"] for r in rows]), abs=0.01)
    dens = np.array([r["density"] for r in rows])
    assert s["share_density_above_1.35"] == pytest.approx(np.mean(dens > 1.35))
    cons = np.array([r["contacts"] for r in rows])
    assert s["share_contacts_above_50"] == pytest.approx(np.mean(cons > 50))
    names = [r["dataset"] for r in table["table1"]]
    assert names[:5] == ["HSSD-200", "3D-FRONT", "FurniScene", "METASCENES",
                         "PARSE-10K (paper)"]
    ours = table["table1"][-1]
    assert ours["scenes"] == SCENES and ours["layout"] == "PAG files"
    assert ours["physics"] and ours["parts"] and ours["part_contacts"]
    md = (out / "stats.md").read_text()
    assert "| HSSD-200 | 211 | 18,656 | 329.70 |" in md and "PAG files" in md
    assert "Comparison with the paper's Table 1" in printed


def test_cli_input_mistakes(reference, pags, capsys):
    with pytest.raises(SystemExit) as e:
        main(["dataset", "build", "--scenes", "2", "--out", str(reference), "--pags", str(pags),
              "--rooms", "bedrom"])
    assert e.value.code == 2
    assert "did you mean 'bedroom'" in capsys.readouterr().err
    with pytest.raises(SystemExit) as e:  # same folder, another dataset seed
        main(["dataset", "build", "--scenes", "2", "--out", str(reference), "--pags", str(pags),
              "--seed", "8"])
    assert e.value.code == 2
    assert "other settings" in capsys.readouterr().err
    with pytest.raises(SystemExit) as e:
        main(["dataset", "stats", str(pags)])
    assert e.value.code == 2
    assert "no manifest.parquet" in capsys.readouterr().err


def test_template_build_with_local_workers(tmp_path):
    """The default source (room templates) reaches the local worker processes."""
    cfg = BuildConfig(scenes=2, seed=3, rooms=("bathroom", "laundry"), views=0, settle=False)
    report = build_dataset(cfg, tmp_path / "ds", workers=2)
    rows = read_manifest(tmp_path / "ds" / "manifest.parquet")
    assert sorted(r["room_type"] for r in rows) == ["bathroom", "laundry"]
    # what reached the workers is the template source: a scene that placed all but a few
    # objects (its record says which and why) is as much a proof of it as a complete one
    assert all(r["status"] in ("ok", "incomplete") for r in rows), [r["reason"] for r in rows]
    assert all(r["placed"] >= 0.8 * r["objects"] for r in rows), rows
    assert report is not None


def test_scenes_from_worker_processes_match_this_process(reference, pags):
    """A scene built by a worker forked from the preloaded fork server is byte for byte the
    one built here, in a process that never forked (timings aside)."""
    from parse3d.datagen.build import build_scene

    cfg = BuildConfig(scenes=SCENES, seed=7, source=resolve_pag_paths([pags]))
    for i in (0, 1):
        here = build_scene(cfg, i)
        assert here.record["status"] == "ok", here.record["reason"]
        folder = reference / "scenes" / f"{i:05d}"
        doc = json.loads(here.files["scene.json"])
        doc.pop("timings")
        assert doc == _scene_doc(folder)
        for name in ("scene.glb", "contacts.json"):
            assert here.files[name] == (folder / name).read_bytes(), name


PROBE = """
import json, sys
from parse3d.datagen.executors import WORKER_MODULES, start_context


def missing(conn):
    conn.send([m for m in WORKER_MODULES if m not in sys.modules])


if __name__ == "__main__":
    ctx = start_context()
    a, b = ctx.Pipe()
    p = ctx.Process(target=missing, args=(b,))
    p.start()
    print(json.dumps({"method": ctx.get_start_method(), "missing": a.recv()}))
    p.join()
"""


def test_workers_start_with_their_modules_imported(tmp_path):
    """Local workers fork from a server that imported the stages' modules (none of which
    the probe's own process imports), so a worker does not import them itself."""
    import multiprocessing as mp

    if "forkserver" not in mp.get_all_start_methods():
        pytest.skip("no fork server on this platform: workers are spawned")
    script = tmp_path / "probe.py"
    script.write_text(PROBE)
    res = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                         timeout=300)
    assert res.returncode == 0, res.stderr
    assert json.loads(res.stdout.splitlines()[-1]) == {"method": "forkserver", "missing": []}


def test_workers_replaced_after_every_scene_give_the_same_scenes(reference, pags, tmp_path):
    """``max_tasks=1``: every scene in a fresh worker (started while the driver commits the
    scene before); same scenes and rows as the reference."""
    cfg = BuildConfig(scenes=4, seed=7, source=resolve_pag_paths([pags]))
    report = build_dataset(cfg, tmp_path / "ds", workers=2, max_tasks=1)
    assert (report.ok, report.built) == (4, 4)
    assert_same_scenes(reference, tmp_path / "ds", range(4))
    rows = read_manifest(tmp_path / "ds" / "manifest.parquet")
    ref = read_manifest(reference / "manifest.parquet")[:4]
    assert [_strip(r) for r in rows] == [_strip(r) for r in ref]


def _kill_workers(count: int, stop) -> list[int]:
    """Kill the first ``count`` scene workers (the children of this process's fork server)
    one by one as soon as they are seen, from outside (as the OOM killer would): each dies
    while starting or building its first scene."""
    from multiprocessing import forkserver

    import psutil

    killed: list[int] = []
    while len(killed) < count and not stop.is_set():
        server = getattr(forkserver._forkserver, "_forkserver_pid", None)
        try:
            workers = psutil.Process(server).children() if server else []
        except psutil.NoSuchProcess:
            workers = []
        for p in workers:
            try:
                if (p.pid not in killed and p.status() != psutil.STATUS_ZOMBIE
                        and time.time() - p.create_time() > 0.02):
                    p.kill()
                    killed.append(p.pid)
                    break
            except psutil.NoSuchProcess:
                continue
        time.sleep(0.05)
    return killed


@pytest.mark.parametrize("deaths", [1, 2])
def test_a_killed_worker_is_replaced_and_its_scene_retried_once(reference, pags, tmp_path,
                                                                  deaths):
    """The first worker killed: a fresh one builds its scene again, the same scene
    as the reference. Killed twice on the same scene: the scene is recorded as failed and
    the build goes on to the next."""
    import threading

    cfg = BuildConfig(scenes=2, seed=7, source=resolve_pag_paths([pags]))
    stop, killed = threading.Event(), []
    killer = threading.Thread(target=lambda: killed.extend(_kill_workers(deaths, stop)))
    killer.start()
    try:
        report = build_dataset(cfg, tmp_path / "ds", workers=1)
    finally:
        stop.set()
        killer.join()
    assert len(killed) == deaths
    rows = {r["index"]: r for r in read_manifest(tmp_path / "ds" / "manifest.parquet")}
    assert sorted(rows) == [0, 1] and rows[1]["status"] == "ok"
    if deaths == 1:
        assert (report.ok, report.failed) == (2, 0)
        assert_same_scenes(reference, tmp_path / "ds", range(2))
    else:
        assert (report.ok, report.failed) == (1, 1)
        assert rows[0]["status"] == "failed" and "died twice" in rows[0]["reason"]
        assert_same_scenes(reference, tmp_path / "ds", [1])
