"""Solver robustness: PAGs the project has not seen must solve, and stay solved after physics.

Usage::

    python benchmarks/bench_robustness.py [--quick] [--baseline-rev REV] [--json FILE]
    python benchmarks/bench_robustness.py --every 4 --seeds 3 --workers 2   # a mid-size corpus

Prints one table with a row per corpus, each scene run through the project's per-scene path
(``parse3d.pipeline.run_pipeline``: solve, settle and whatever repair it does; nothing written):

``templates``
    every bundled room template expanded at 10 random seeds. Per template and k:
    ``rng = numpy.random.default_rng([crc32(template_name), k])`` draws, in this order, the
    expansion seed, the footprint scale per axis (uniform in x0.8-1.2), whether the room gets an
    L-cut (probability 0.3, rectangular rooms only), the corner, the cut's fraction of each of
    the two sides at that corner (uniform in 25-40%), and the solver seed. ``wall_i`` references
    are remapped after a cut (the shortened walls keep their role, the two new walls get new
    numbers). Rooms with a scale below x0.9 on either axis have their own row (some templates
    cannot fit there).
``examples``
    the bundled example rooms at seeds 0-19.
``rooms``
    the hand-written rooms of ``tests/data/rooms/`` at seeds 0-9.
``foreign``
    the rooms of ``tests/data/foreign/`` (written from photo descriptions by people who read
    only docs/pag.md and the category list) at seeds 0-4 (``--foreign`` runs this row alone;
    ``--foreign DIR`` runs the rooms of another folder instead, such as
    ``tests/data/foreign-later/``, rooms written later and never used to tune the solver).
    Words the vocabulary does not know yet are taken out in memory, never in the files: an
    object none of whose categories is known is left out with what rests on it and the
    relations naming it, and a part label its categories do not know is dropped from the
    reference (``ON table:surface`` becomes ``ON table``); how many were taken out is printed.
    The row adds tracebacks (scenes whose solve raised), relaxed relations per scene, the
    median and largest wall time of the pipeline (solve, settle, contacts) and its median and
    largest CPU time (``cpu med``, ``cpu max``: less noisy than wall time on a shared machine).
    Every row ends with the median and largest CPU seconds spent settling and repairing
    (``settle med``, ``settle max``: the first settling, every repair round and its settling;
    ``scene.timings["settle_cpu"]``, wall seconds in revisions without it).
``parse3d solve`` (with ``--cli``)
    every foreign case solved again by the command, in a fresh process (start-up, imports,
    asset cache reads, settle, contacts and preview in the figure), after the in-process pass
    has cached its assets: median and largest wall seconds, and CPU seconds.
``cost of failure``
    a scene (examples/study.json) and the same scene plus one wardrobe ON a mug: the ratio of
    their solve times (goal: at most 3).

Columns: scenes; objects; placed (% of objects); complete (% of scenes with every object
placed); support and all (% of relations holding after settling, a relation of an unplaced
object counts as broken); fallen (placed objects that fell, tipped or left their support in
settling, judged by ``parse3d.measure.verify_settled``, the definition the repair uses); obj/s
(placed objects per second of solve time). Goals from the issue: templates
>= 99.5% placed, >= 95% complete, >= 99% support, >= 95% all, 0 fallen; examples >= 95% complete;
rooms 100% complete and keeping their relations; cost of failure <= 3; obj/s not below the
baseline.

``--quick`` runs one seed (k = 0) of every 16th template, seeds 0-1 of the examples and of the
rooms (about 50 scenes); the full run is about 2,300 scenes (hours on one core).
``--every M --seeds K`` takes every M-th template at corpus seeds k = 0..K-1 (the examples and
rooms at seeds 0..K-1 too), a corpus between the two; ``--workers N`` measures the cases in N
processes (the figures are the same; the order of the cases is kept).
``--baseline-rev REV`` also runs the same corpus (built once, here) with the package of git
revision REV, checked out in a temporary worktree that is removed afterwards, and prints its
figures under each row. Times are wall seconds of the solve stage; on a shared machine they are
noisy.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import time
import zlib
from pathlib import Path

import numpy as np
from _common import ROOT, revision_tree

ROOMS = ROOT / "tests" / "data" / "rooms"
FOREIGN = ROOT / "tests" / "data" / "foreign"
EXAMPLES = ROOT / "examples"
FALLEN = ("fell", "tipped", "left_support")
SUPPORT = ("ON", "IN", "HANGING_BELOW", "SECURED_TO")
_WALL = re.compile(r"^wall_(\d+)(?=$|[:@])")


# ----------------------------------------------------------------------------- the corpus
def l_cut(footprint: list, corner: int, fa: float, fb: float) -> tuple[list, dict[int, int]]:
    """Cut a rectangle out of ``corner`` of a counter-clockwise quadrilateral.

    ``fa`` is the fraction of the incoming wall (``corner - 1`` -> ``corner``) and ``fb`` of the
    outgoing wall removed. Returns the new footprint and the map old wall index -> new index.
    """
    n = len(footprint)
    P = [np.asarray(p, float) for p in footprint]
    prev, nxt = P[(corner - 1) % n], P[(corner + 1) % n]
    c = P[corner]
    a = c + fa * (prev - c)  # on the incoming wall
    b = c + fb * (nxt - c)  # on the outgoing wall
    q = a + (b - c)  # the inner corner
    pts: list[np.ndarray] = []
    start: dict[int, int] = {}
    for i in range(n):
        if i == corner:
            pts += [a, q]
            start[i] = len(pts)
            pts.append(b)
        else:
            start[i] = len(pts)
            pts.append(P[i])
    return [[round(float(x), 4), round(float(y), 4)] for x, y in pts], start


def remap_walls(doc: dict, mapping: dict[int, int]) -> None:
    """Rewrite ``wall_i`` references of a PAG document in place."""
    def sub(ref: str) -> str:
        return _WALL.sub(lambda m: f"wall_{mapping[int(m.group(1))]}", ref)

    for r in doc["relations"]:
        r["child"], r["parent"] = sub(r["child"]), sub(r["parent"])


def template_cases(seeds: int, every: int = 1) -> list[dict]:
    """Cases of every ``every``-th bundled template at ``seeds`` corpus seeds each."""
    from parse3d.datagen.templates import expand_template, list_templates

    out = []
    for t in list_templates()[::every]:
        for k in range(seeds):
            rng = np.random.default_rng([zlib.crc32(t.name.encode()), k])
            doc = expand_template(t, int(rng.integers(2 ** 31))).to_dict()
            s = rng.uniform(0.8, 1.2, 2)
            fp = [[round(float(x * s[0]), 4), round(float(y * s[1]), 4)]
                  for x, y in doc["room"]["footprint"]]
            cut = bool(rng.random() < 0.3) and len(fp) == 4
            corner = int(rng.integers(4))
            fa, fb = rng.uniform(0.25, 0.40, 2)
            if cut:
                fp, mapping = l_cut(fp, corner, float(fa), float(fb))
                remap_walls(doc, mapping)
            doc["room"]["footprint"] = fp
            doc["name"] = f"{t.name}-k{k}"
            row = "templates" if s.min() >= 0.9 else "templates <x0.9"
            out.append({"row": row, "name": doc["name"], "pag": doc,
                        "seed": int(rng.integers(2 ** 31)), "lcut": cut})
    return out


def file_cases(row: str, paths: list[Path], seeds: range) -> list[dict]:
    from parse3d.pag import load_pag

    out = []
    for p in paths:
        doc = load_pag(p).to_dict()
        out += [{"row": row, "name": p.stem, "pag": doc, "seed": s} for s in seeds]
    return out


def known_words(doc: dict) -> tuple[dict, int, int]:
    """``doc`` (a PAG document) with the words the vocabulary does not know taken out (see the
    module's ``foreign``), and how many objects and part labels were taken out."""
    from parse3d.assets.registry import vocabulary
    from parse3d.pag.refs import format_ref, is_room_element, parse_ref

    vocab = vocabulary()
    doc = json.loads(json.dumps(doc))
    cats: dict[str, list[str]] = {}
    for o in doc["objects"]:
        c = o.get("category", o.get("categories"))
        cs = [c] if isinstance(c, str) else list(c or [])
        cats[o["id"]] = [x for x in cs if vocab.has_category(x)]
    gone = {oid for oid, cs in cats.items() if not cs}
    support = ("ON", "IN", "HANGING_BELOW", "SECURED_TO", "LEANING_AGAINST")
    grew = True
    while grew:  # what rests on a dropped object goes with it
        grew = False
        for r in doc["relations"]:
            c, p = parse_ref(r["child"]).object, parse_ref(r["parent"]).object
            if r["relation"] in support and p in gone and c not in gone:
                gone.add(c)
                grew = True
    doc["objects"] = [o for o in doc["objects"] if o["id"] not in gone]
    for o in doc["objects"]:
        if "category" in o and not isinstance(o["category"], str):
            o["category"] = cats[o["id"]]
    parts = 0

    def fix(text: str) -> str:
        nonlocal parts
        ref = parse_ref(text)
        if ref.part is None or is_room_element(ref.object):
            return text
        if any(ref.part in vocab.parts(c) for c in cats[ref.object]):
            return text
        parts += 1
        return format_ref(ref.object, None, None, ref.surface)

    rels = []
    for r in doc["relations"]:
        if parse_ref(r["child"]).object in gone or parse_ref(r["parent"]).object in gone:
            continue
        r["child"], r["parent"] = fix(r["child"]), fix(r["parent"])
        rels.append(r)
    doc["relations"] = rels
    return doc, len(gone), parts


def foreign_cases(seeds: range, folder: Path = FOREIGN) -> tuple[list[dict], str]:
    """The foreign rooms of ``folder`` at ``seeds``, with unknown words taken out
    (:func:`known_words`), and a line saying what was taken out and which rooms were skipped
    (still invalid)."""
    from parse3d.assets.registry import vocabulary
    from parse3d.pag import PAG

    out, dropped, parts, skipped, rooms = [], 0, 0, [], 0
    for p in sorted(Path(folder).glob("*.json")):
        written = json.loads(p.read_text())
        try:  # a room the vocabulary understands as written is measured as written
            PAG.from_dict(written).validate()
            doc, n_obj, n_part = written, 0, 0
        except Exception:  # noqa: BLE001 - a revision without those words: take them out
            doc, n_obj, n_part = known_words(written)
        try:
            pag = PAG.from_dict(doc).validate(vocabulary=vocabulary())
        except Exception as e:  # noqa: BLE001 - a room still invalid is skipped and named
            skipped.append(f"{p.stem} ({str(e).splitlines()[0][:80]})")
            continue
        rooms += 1
        dropped, parts = dropped + n_obj, parts + n_part
        out += [{"row": "foreign", "name": p.stem, "pag": pag.to_dict(), "seed": s}
                for s in seeds]
    note = (f"foreign: {rooms} rooms; words not in the vocabulary yet: {dropped} objects left "
            f"out (with what rests on them), {parts} part labels dropped"
            + (f"; skipped {', '.join(skipped)}" if skipped else ""))
    return out, note


def corpus(quick: bool, every: int | None = None, seeds: int | None = None) -> list[dict]:
    examples = sorted(EXAMPLES.glob("*.json")) + sorted(EXAMPLES.glob("*.yaml"))
    if every or seeds:
        k = seeds or 10
        return (template_cases(k, every=every or 1) + file_cases("examples", examples, range(k))
                + file_cases("rooms", sorted(ROOMS.glob("*.json")), range(k)))
    return ((template_cases(1, every=16) if quick else template_cases(10))
            + file_cases("examples", examples, range(2 if quick else 20))
            + file_cases("rooms", sorted(ROOMS.glob("*.json")), range(2 if quick else 10)))


# -------------------------------------------------------------------------- measuring
def measure(case: dict) -> dict:
    """Run one case through the pipeline and count what the table needs (works with any
    revision of the package: only the Scene model is read)."""
    from parse3d.pag import PAG
    from parse3d.pipeline import PipelineOptions, run_pipeline

    pag = PAG.from_dict(case["pag"])
    t0, w0 = time.process_time(), time.perf_counter()
    try:
        scene = run_pipeline(pag, seed=case["seed"], out=None,
                             options=PipelineOptions(settle=True, preview=False))
    except Exception as e:  # noqa: BLE001 - a crash is a result the table must show
        return {"row": case["row"], "name": case["name"], "seed": case["seed"],
                "objects": len(pag.objects), "placed": 0, "error": f"{type(e).__name__}: {e}",
                "wall_s": time.perf_counter() - w0}
    cpu, wall = time.process_time() - t0, time.perf_counter() - w0
    held = {c.index: c.holds_settled if scene.settled else c.holds for c in scene.relations}
    sup = [i for i, e in enumerate(pag.relations) if e.relation in SUPPORT]
    other = [i for i, e in enumerate(pag.relations) if e.relation not in SUPPORT]
    placed = [o for o in scene.objects.values() if o.placed]
    return {"row": case["row"], "name": case["name"], "seed": case["seed"],
            "objects": len(pag.objects), "placed": len(placed),
            "support": len(sup), "support_held": sum(held.get(i) is True for i in sup),
            "relations": len(sup) + len(other),
            "held": sum(held.get(i) is True for i in sup + other),
            "fallen": _fallen(scene, placed),
            "solve_s": float(scene.timings.get("solve", 0.0)), "cpu_s": cpu, "wall_s": wall,
            "settle_s": float(scene.timings.get("settle_cpu", scene.timings.get("settle", 0.0))),
            "relaxed": sum(bool(getattr(c, "relaxed", None)) for c in scene.relations),
            "failed": [f"{o.id}: {o.reason}" for o in scene.objects.values() if not o.placed]}


def _fallen(scene, placed) -> int:
    """Placed objects left fell / tipped / off their support: judged by
    ``parse3d.measure.verify_settled`` (the definition the repair uses), or by the physics flags
    in revisions without it."""
    try:
        from parse3d.measure import verify_settled
    except ImportError:
        return sum(any(f in o.flags for f in FALLEN) for o in placed)
    if not scene.settled:
        return 0
    ids = {o.id for o in placed}
    return len({i.object_id for i in verify_settled(scene)
                if i.cause in FALLEN and i.object_id in ids})


def cost_of_failure(seeds: range) -> dict:
    """Solve times of study.json with and without one wardrobe ON its mug."""
    from parse3d.pag import PAG
    from parse3d.solver import solve

    doc = json.loads((EXAMPLES / "study.json").read_text())
    mug = next(o["id"] for o in doc["objects"] if o["category"] == "mug")
    bad = json.loads(json.dumps(doc))
    bad["objects"].append({"id": "impossible_wardrobe", "category": "wardrobe"})
    bad["relations"].append({"relation": "ON", "child": "impossible_wardrobe", "parent": mug})
    times = {"base": [], "impossible": []}
    for name, d in (("base", doc), ("impossible", bad)):
        pag = PAG.from_dict(d)
        solve(pag, seed=seeds[0])  # warm-up: assets into memory
        for s in seeds:
            t = time.process_time()
            solve(pag, seed=s)
            times[name].append(time.process_time() - t)
    b, i = float(np.mean(times["base"])), float(np.mean(times["impossible"]))
    return {"base_s": b, "impossible_s": i, "ratio": i / b if b else float("nan")}


def cli_times(cases: list[dict]) -> list[dict]:
    """Wall and CPU seconds of ``parse3d solve`` (settle, contacts, preview; a fresh process
    per case, run with this interpreter and its ``PYTHONPATH``) on each foreign case, its
    PAG written to a temporary file. Run after the in-process pass, so the assets are cached."""
    import tempfile

    out = []
    with tempfile.TemporaryDirectory(prefix="parse3d-cli-") as tmp:
        for c in (c for c in cases if c["row"] == "foreign"):
            src = Path(tmp) / f"{c['name']}.json"
            src.write_text(json.dumps(c["pag"]))
            before = os.times()
            t = time.perf_counter()
            r = subprocess.run([sys.executable, "-m", "parse3d", "solve", str(src), "-o",
                                str(Path(tmp) / "out"), "--seed", str(c["seed"])],
                               capture_output=True, check=False)
            wall = time.perf_counter() - t
            after = os.times()
            cpu = (after.children_user - before.children_user
                   + after.children_system - before.children_system)
            out.append({"name": c["name"], "seed": c["seed"], "wall_s": wall, "cpu_s": cpu,
                        "rc": r.returncode})
    return out


def run_all(cases: list[dict], cof_seeds: range, progress: bool = True,
            workers: int = 1, cli: bool = False) -> dict:
    out = []
    if workers > 1:
        import multiprocessing as mp

        pool = mp.get_context("spawn").Pool(workers, maxtasksperchild=100)
        results = pool.imap(measure, cases)
    else:
        pool, results = None, map(measure, cases)
    for k, (c, m) in enumerate(zip(cases, results, strict=True)):
        out.append(m)
        if progress:  # one line per case, so that a long run can be followed
            print(f"{k + 1}/{len(cases)} {c['row']:16s} {c['name'][:36]:36s} seed {c['seed']}: "
                  f"{m['placed']}/{m['objects']} placed, {m.get('fallen', 0)} fallen, "
                  f"{m.get('cpu_s', 0):.1f} s (settle and repair {m.get('settle_s', 0):.1f} s)",
                  file=sys.stderr, flush=True)
    if pool is not None:
        pool.close()
        pool.join()
    return {"cases": out,
            "cost_of_failure": cost_of_failure(cof_seeds) if len(cof_seeds) else None,
            "cli": cli_times(cases) if cli else None}


# ----------------------------------------------------------------------------- reporting
ROWS = ("templates", "templates <x0.9", "examples", "rooms", "foreign")


def summarize(cases: list[dict]) -> dict[str, dict]:
    out = {}
    for row in ROWS:
        rs = [c for c in cases if c["row"] == row]
        if not rs:
            continue
        def g(key: str, rs=rs) -> float:
            return sum(c.get(key, 0) for c in rs)

        solve_s = g("solve_s")
        out[row] = {"scenes": len(rs), "objects": g("objects"),
                    "placed": 100.0 * g("placed") / max(g("objects"), 1),
                    "complete": 100.0 * sum(c["placed"] == c["objects"] for c in rs) / len(rs),
                    "support": 100.0 * g("support_held") / max(g("support"), 1),
                    "all": 100.0 * g("held") / max(g("relations"), 1),
                    "fallen": g("fallen"), "errors": sum("error" in c for c in rs),
                    "relaxed": g("relaxed") / len(rs),
                    "wall_median": float(np.median([c.get("wall_s", 0.0) for c in rs])),
                    "wall_max": max(c.get("wall_s", 0.0) for c in rs),
                    "cpu_median": float(np.median([c.get("cpu_s", 0.0) for c in rs])),
                    "cpu_max": max(c.get("cpu_s", 0.0) for c in rs),
                    "settle_median": float(np.median([c.get("settle_s", 0.0) for c in rs])),
                    "settle_max": max(c.get("settle_s", 0.0) for c in rs),
                    "obj_s": g("placed") / solve_s if solve_s else float("nan")}
    return out


def print_table(now: dict, before: dict | None, rev: str | None) -> None:
    head = (f"{'corpus':18s} {'run':>8s} {'scenes':>6s} {'objects':>7s} {'placed%':>8s} "
            f"{'complete%':>9s} {'support%':>8s} {'all%':>6s} {'fallen':>6s} {'obj/s':>7s} "
            f"{'tracebk':>7s} {'relaxed':>7s} {'wall med':>8s} {'wall max':>8s} {'cpu med':>7s} {'cpu max':>7s} "
            f"{'settle med':>10s} {'settle max':>10s}")
    print(head)
    print("-" * len(head))
    for row in ROWS:
        for label, res in (("now", now), (rev or "", before)):
            if res is None or row not in summarize(res["cases"]):
                continue
            s = summarize(res["cases"])[row]
            err = f"  ({s['errors']} crashed)" if s["errors"] else ""
            print(f"{row if label == 'now' else '':18s} {label[:8]:>8s} {s['scenes']:6d} "
                  f"{s['objects']:7d} {s['placed']:8.2f} {s['complete']:9.1f} {s['support']:8.2f} "
                  f"{s['all']:6.2f} {s['fallen']:6d} {s['obj_s']:7.1f} {s['errors']:7d} "
                  f"{s['relaxed']:7.2f} {s['wall_median']:8.2f} {s['wall_max']:8.2f} "
                  f"{s['cpu_median']:7.2f} {s['cpu_max']:7.2f} {s['settle_median']:10.2f} "
                  f"{s['settle_max']:10.2f}{err}")
    for label, res in (("now", now), (rev or "", before)):
        if res is None:
            continue
        c = res["cost_of_failure"]
        if c is None:
            continue
        print(f"{'cost of failure' if label == 'now' else '':18s} {label[:8]:>8s}  "
              f"study {c['base_s']:.2f} s, + wardrobe ON mug {c['impossible_s']:.2f} s: "
              f"x{c['ratio']:.2f} (goal <= 3)")
    for label, res in (("now", now), (rev or "", before)):
        runs = (res or {}).get("cli")
        if not runs:
            continue
        wall = [r["wall_s"] for r in runs]
        cpu = [r["cpu_s"] for r in runs]
        slow = max(runs, key=lambda r: r["wall_s"])
        print(f"{'parse3d solve' if label == 'now' else '':18s} {label[:8]:>8s}  "
              f"{len(runs)} foreign cases: wall median {np.median(wall):.2f} s, max "
              f"{max(wall):.2f} s ({slow['name']} seed {slow['seed']}), over 5 s: "
              f"{sum(w > 5 for w in wall)}; cpu median {np.median(cpu):.2f} s, max "
              f"{max(cpu):.2f} s (goal: wall median <= 2 s, none above 5 s)")


def baseline(rev: str, cases: list[dict], quick: bool, workers: int = 1,
             cof: int | None = None, cli: bool = False) -> dict:
    """Run the corpus with the package of ``rev`` (a temporary git worktree)."""
    with revision_tree(rev) as wt:
        spec = wt.parent / "corpus.json"
        spec.write_text(json.dumps({"cases": cases, "quick": quick, "workers": workers,
                                    "cli": cli,
                                    **({"cof": cof} if cof is not None else {})}))
        res = wt.parent / "result.json"
        env = {**os.environ, "PYTHONPATH": str(wt / "src")}
        subprocess.run([sys.executable, __file__, "--_run-corpus", str(spec), "--json",
                        str(res)], check=True, env=env, cwd=str(wt))
        return json.loads(res.read_text())


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="a small corpus (minutes, not hours)")
    ap.add_argument("--baseline-rev", metavar="REV",
                    help="also run the same corpus with git revision REV, e.g. main")
    ap.add_argument("--json", metavar="FILE", help="write every case's figures to FILE")
    ap.add_argument("--failures", action="store_true", help="list every failed object")
    ap.add_argument("--every", type=int, metavar="M", help="every M-th template only")
    ap.add_argument("--seeds", type=int, metavar="K",
                    help="corpus seeds per template (and seeds of examples and rooms)")
    ap.add_argument("--workers", type=int, default=1, metavar="N",
                    help="measure in N processes (default 1)")
    ap.add_argument("--foreign", nargs="?", const=str(FOREIGN), metavar="DIR",
                    help="the foreign rooms alone, at seeds 0-4 (--seeds K: 0..K-1); DIR: "
                         "the rooms of another folder (default tests/data/foreign)")
    ap.add_argument("--cli", action="store_true",
                    help="also time `parse3d solve` in a fresh process on each foreign case")
    ap.add_argument("--_run-corpus", dest="run_corpus", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.run_corpus:  # the baseline's side: measure the given corpus with this package
        spec = json.loads(Path(args.run_corpus).read_text())
        res = run_all(spec["cases"], range(spec.get("cof", 2 if spec["quick"] else 5)),
                      workers=spec.get("workers", 1), cli=spec.get("cli", False))
        Path(args.json).write_text(json.dumps(res))
        return
    if args.workers < 1 or (args.every is not None and args.every < 1) or (
            args.seeds is not None and args.seeds < 1):
        ap.error("--workers, --every and --seeds take a positive number")
    note = None
    if args.foreign:
        folder = Path(args.foreign)
        if not folder.is_dir() or not any(folder.glob("*.json")):
            ap.error(f"--foreign {args.foreign}: not a folder of PAG files (*.json)")
        cases, note = foreign_cases(range(args.seeds or 5), folder)
        cof = 0
    else:
        cases = corpus(args.quick, args.every, args.seeds)
        if args.every is None and args.seeds is None:
            more, note = foreign_cases(range(2 if args.quick else 5))
            cases += more
        cof = 2 if args.quick else 5
    now = run_all(cases, range(cof), workers=args.workers, cli=args.cli)
    before = (baseline(args.baseline_rev, cases, args.quick, args.workers, cof, args.cli)
              if args.baseline_rev else None)
    if note:
        print(note)
    print_table(now, before, args.baseline_rev)
    if args.failures:
        for c in now["cases"]:
            for f in c.get("failed", []) + ([c["error"]] if "error" in c else []):
                print(f"{c['row']:16s} {c['name']:32s} seed {c['seed']}: {f}")
    if args.json:
        Path(args.json).write_text(json.dumps({"now": now, "before": before}, indent=1))


if __name__ == "__main__":
    main()
