"""VLM benchmark build speed and yield: items per scene, seconds per scene, 200-scene estimate.

Usage::

    python benchmarks/bench_vlm.py DATASET_DIR                 # a dataset built with --views 4
    python benchmarks/bench_vlm.py DATASET_DIR --workers 2 --out out/vlm-bench
    python benchmarks/bench_vlm.py --build 12                   # build a 12-scene dataset first

Runs ``parse3d vlm build`` (exactly the library call) on a dataset that already has its
views (rendering is not part of the measurement), then prints the items per task, per scene
and per view, the seconds per scene (wall clock; the asset registry's import is timed apart),
the answer-letter and "no contact" shares, the share of relations by how they were derived
(``meta.source`` / ``meta.sources``), an independent audit, chance and the oracle, random,
prior and text-only (blind) scores on the test split, and a linear extrapolation to the issue's target: a 200-scene dataset with 4 views should
give at least 5,000 MCQ and 800 SGG items in at most 3 minutes on 2 cores.

The audit re-derives labels from the dataset's files without the builder's code: it reads
``scene.glb`` with trimesh, the settled quaternions with scipy, the cameras' ``K, R, t`` and
``contacts.json``, and checks, for ``--audit-mcq`` random relation / part-contact MCQ (the
answer) and ``--audit-sgg`` random SGG images (every triplet of ``meta.holds``), that
``near`` / ``far from`` match the horizontal distance of the oriented-box centres (< 0.9 m /
> 2.2 m), the camera-frame sides their margins (0.15 m / 0.30 m), ``on`` / ``in`` /
``against``-type relations and part contacts a contact in ``contacts.json`` and ``no
contact`` its absence, and that every distractor among them is false: of the part-contact
MCQ, the opposite of the answer about the marked objects (by ``contacts.json``) or another
category pair; of the relation MCQ, a relation false of the marked objects beyond doubt (the
other side beyond its margin, a distance outside the relation's band, contact or its
absence) or another category pair. Relations without a geometric test (``facing``, ``aligned with``) are
counted apart as not audited.
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from collections import Counter
from pathlib import Path

import numpy as np

from parse3d.datagen.build import BuildConfig, build_dataset
from parse3d.vlm.baselines import run_baseline
from parse3d.vlm.build import (
    BuildOptions,
    build_benchmark,
    candidate_objects,
    part_map,
    read_jsonl,
)
from parse3d.vlm.evaluate import evaluate


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dataset", nargs="?", type=Path, help="dataset folder with views")
    ap.add_argument("--out", type=Path, help="benchmark folder (default: temporary)")
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--build", type=int, default=0,
                    help="first build a template dataset of this many scenes with 4 views")
    ap.add_argument("--target-scenes", type=int, default=200)
    ap.add_argument("--audit-mcq", type=int, default=200)
    ap.add_argument("--audit-sgg", type=int, default=50)
    args = ap.parse_args()
    tmp = tempfile.TemporaryDirectory(prefix="bench-vlm-")
    ds = args.dataset
    if args.build:
        ds = ds or Path(tmp.name) / "ds"
        t = time.perf_counter()
        rep = build_dataset(BuildConfig(scenes=args.build, views=4), ds, workers=2)
        print(f"dataset: {rep.ok} scenes with 4 views in {time.perf_counter() - t:.0f} s "
              "(not part of the measurement)")
    if ds is None:
        ap.error("give a DATASET_DIR or --build N")
    out = args.out or Path(tmp.name) / "vlm"
    t = time.perf_counter()
    candidate_objects()
    part_map()  # the asset registry's import: paid once per run, not per scene
    fixed = time.perf_counter() - t
    t = time.perf_counter()
    res = build_benchmark(ds, out, BuildOptions(), workers=args.workers)
    wall = time.perf_counter() - t
    card = res.card
    c = card["counts"]["all"]
    scenes = sum(len(v) for v in card["scenes"].values())
    views = sum(1 for s in ("train", "val", "test") for r in read_jsonl(out / f"{s}.jsonl")
                if r["task"] == "sgg")
    mcq = c["tasks"].get("relation_mcq", 0) + c["tasks"].get("contact_mcq", 0)
    sgg = c["tasks"].get("sgg", 0)
    print(f"vlm build: {scenes} scenes, {c['items']} items in {wall:.1f} s "
          f"({wall / scenes:.2f} s per scene, {args.workers} worker(s)) after {fixed:.1f} s "
          "of start-up (importing the asset registry)")
    print(f"  relation MCQ {c['tasks'].get('relation_mcq', 0)}, contact MCQ "
          f"{c['tasks'].get('contact_mcq', 0)}, SGG {sgg} ({views} views with an SGG item)")
    print(f"  per scene: {mcq / scenes:.1f} MCQ, {sgg / scenes:.2f} SGG; SGG objects "
          f"{c['sgg_objects'] / max(sgg, 1):.1f} and triplets {c['sgg_triplets'] / max(sgg, 1):.1f}"
          " per image")
    for task in ("relation_mcq", "contact_mcq"):
        letters = c["answer_letters"][task]
        n = sum(letters.values()) or 1
        print(f"  {task} answer letters: " + ", ".join(f"{k} {v / n:.1%}"
                                                       for k, v in letters.items()))
    print(f"  'no contact' answers: {json.dumps(c['no_contact_share'])}")
    print(f"  relations asked: {json.dumps(c['relations'])}")
    rows = [r for s in ("train", "val", "test") for r in read_jsonl(out / f"{s}.jsonl")]
    for task in ("relation_mcq", "contact_mcq"):
        src = Counter(r["meta"].get("source", "?") for r in rows if r["task"] == task)
        n = sum(src.values()) or 1
        print(f"  {task} answers by derivation: " + ", ".join(
            f"{k} {v / n:.1%}" for k, v in src.most_common()))
    src = Counter(x for r in rows if r["task"] == "sgg" for x in r["meta"].get("sources", []))
    n = sum(src.values()) or 1
    holds = sum(len(r["meta"].get("holds", [])) for r in rows if r["task"] == "sgg")
    print("  SGG answer triplets by derivation: " + ", ".join(
        f"{k} {v / n:.1%}" for k, v in src.most_common())
          + f"; relations that hold per image (precision's reference) {holds / max(sgg, 1):.1f}")
    audit(ds, rows, args.audit_mcq, args.audit_sgg)
    test = out / "test.jsonl"
    gt = read_jsonl(test)
    print("  chance on test: relation 25.0, contact 25.0 (four options)")
    for name in ("oracle", "random", "prior", "blind"):
        rep = evaluate(gt, run_baseline(name, test), model=name)
        print(f"  {name} on test: relation {rep.relation.get('accuracy')}, contact "
              f"{rep.contact.get('accuracy')}, SGG F1 {rep.sgg.get('f1')}/"
              f"{rep.sgg.get('f1_nomatch')}")
    n = args.target_scenes
    print(f"extrapolated to {n} scenes x 4 views: {mcq / scenes * n:,.0f} MCQ (goal >= 5,000), "
          f"{sgg / scenes * n:,.0f} SGG (goal >= 800), {fixed + wall / scenes * n:,.0f} s "
          f"(goal <= 180 s on 2 cores)")
    tmp.cleanup()


_CONTACT_PHRASES = {"on", "in", "hanging below", "mounted on", "against", "leaning against",
                    "contact"}


def _scene_geometry(scene_dir: Path) -> tuple[dict, set, dict]:
    """Oriented-box centres (Z-up world), touching object pairs and cameras by view index,
    read from the files directly."""
    import trimesh
    from scipy.spatial.transform import Rotation

    sj = json.loads((scene_dir / "scene.json").read_text())
    ts = trimesh.load(str(scene_dir / "scene.glb"), force="scene")
    y_to_z = np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]], float)  # glTF is Y-up
    verts: dict[str, list] = {}
    for node in ts.graph.nodes_geometry:
        T, g = ts.graph[node]
        v = np.asarray(ts.geometry[g].vertices) @ T[:3, :3].T + T[:3, 3]
        verts.setdefault(str(node).split(":")[0], []).append(v @ y_to_z.T)
    centre = {}
    for od in sj["objects"]:
        if od.get("status") != "placed" or od["id"] not in verts:
            continue
        pose = od.get("settled_pose") or od["pose"]
        w, x, y, z = pose["quaternion"]
        R = Rotation.from_quat([x, y, z, w]).as_matrix()
        local = np.vstack(verts[od["id"]]) @ R
        centre[od["id"]] = R @ ((local.min(axis=0) + local.max(axis=0)) / 2)
    touching = set()
    for c in json.loads((scene_dir / "contacts.json").read_text()):
        a, b = c["a"].split(":")[0], c["b"].split(":")[0]
        touching |= {(a, b), (b, a)}
    cams = {}
    vf = json.loads((scene_dir / "views.json").read_text())["views"]
    for v in vf:
        cams[int(v["index"])] = (np.asarray(v["camera"]["R"], float),
                                 np.asarray(v["camera"]["t"], float))
    return centre, touching, cams


def _agrees(rel: str, a: str, b: str, geo) -> bool | None:
    centre, touching, (R, t) = geo
    ca, cb = centre[a], centre[b]
    d = float(np.hypot(*(ca[:2] - cb[:2])))
    pa, pb = R @ ca + t, R @ cb + t
    tests = {"near": d < 0.9, "far from": d > 2.2, "left of": pb[0] - pa[0] > 0.15,
             "right of": pa[0] - pb[0] > 0.15, "in front of": pb[2] - pa[2] > 0.30,
             "behind": pa[2] - pb[2] > 0.30, "no contact": (a, b) not in touching}
    if rel in tests:
        return tests[rel]
    if rel in _CONTACT_PHRASES:
        return (a, b) in touching
    return None


def _contact_distractors_false(r: dict, touching: set) -> tuple[int, int]:
    """A part-contact MCQ's distractors against ``contacts.json``: (false, checked).

    A distractor naming the marked objects' categories is the opposite of the answer (a
    contact when the two do not touch, "not in contact" when they do) and must be false by
    the contacts; one naming other categories must name a category pair other than the
    marked objects' (the answer's)."""
    opts, ans = r["meta"]["options"], "ABCD".index(r["meta"]["answer"])
    pair = (opts[ans]["subject"], opts[ans]["object"])
    touch = (r["meta"]["red"], r["meta"]["blue"]) in touching
    ok = n = 0
    for i, o in enumerate(opts):
        if i == ans:
            continue
        n += 1
        if (o["subject"], o["object"]) != pair:
            ok += 1
        elif o["kind"] == "no_contact":
            ok += touch
        else:
            ok += not touch
    return ok, n


def _false(rel: str, a: str, b: str, geo) -> bool:
    """Whether "a REL b" is false beyond doubt: the opposite side beyond its margin, a
    distance outside the relation's band (near > 1.1 m, far from < 1.8 m), a contact relation
    without contact, "no contact" with one."""
    centre, touching, (R, t) = geo
    ca, cb = centre[a], centre[b]
    d = float(np.hypot(*(ca[:2] - cb[:2])))
    pa, pb = R @ ca + t, R @ cb + t
    tests = {"near": d > 1.1, "far from": d < 1.8, "left of": pa[0] - pb[0] > 0.15,
             "right of": pb[0] - pa[0] > 0.15, "in front of": pa[2] - pb[2] > 0.30,
             "behind": pb[2] - pa[2] > 0.30, "no contact": (a, b) in touching}
    if rel in tests:
        return tests[rel]
    return rel in _CONTACT_PHRASES and (a, b) not in touching


def _relation_distractors_false(r: dict, geo) -> tuple[int, int]:
    """A relation MCQ's distractors: (false, checked). One naming the marked objects'
    categories must be false of the two by the geometry; one naming other categories must
    name a category pair other than the marked objects'."""
    from parse3d.vlm.vocab import RELATION_PHRASES

    opts, ans = r["meta"]["options"], "ABCD".index(r["meta"]["answer"])
    pair = (opts[ans]["subject"], opts[ans]["object"])
    ok = n = 0
    for i, o in enumerate(opts):
        if i == ans:
            continue
        n += 1
        if (o["subject"], o["object"]) != pair:
            ok += 1
        else:
            ok += _false(RELATION_PHRASES[o["relation"]], r["meta"]["red"], r["meta"]["blue"],
                         geo)
    return ok, n


def audit(ds: Path, rows: list[dict], n_mcq: int, n_sgg: int) -> None:
    """Labels re-derived from the files agree with the benchmark's (printed)."""
    rng = np.random.default_rng(0)
    mcq = [r for r in rows if r["task"] != "sgg"]
    sgg = [r for r in rows if r["task"] == "sgg"]
    pick_m = [mcq[int(i)] for i in rng.choice(len(mcq), min(n_mcq, len(mcq)), replace=False)]
    pick_s = [sgg[int(i)] for i in rng.choice(len(sgg), min(n_sgg, len(sgg)), replace=False)]
    cache: dict[str, tuple] = {}

    def geo(r):
        if r["scene"] not in cache:
            cache[r["scene"]] = _scene_geometry(ds / "scenes" / r["scene"])
        centre, touching, cams = cache[r["scene"]]
        return centre, touching, cams[int(r["view"])]

    ok = n = 0
    for r in pick_m:
        if r["task"] == "contact_mcq":
            a, b = _contact_distractors_false(r, geo(r)[1])
            ok, n = ok + a, n + b
    print(f"  audit part-contact distractors: {ok}/{n} false ({100 * ok / max(n, 1):.2f}%, "
          "goal 100%)")
    ok = n = 0
    for r in pick_m:
        if r["task"] == "relation_mcq":
            a, b = _relation_distractors_false(r, geo(r))
            ok, n = ok + a, n + b
    print(f"  audit relation distractors: {ok}/{n} false ({100 * ok / max(n, 1):.2f}%, "
          "goal 100%)")
    for name, checks in (
            ("MCQ", [(r["id"], r["meta"]["red"],
                      r["meta"].get("phrase", r["meta"]["relation"]), r["meta"]["blue"], r)
                     for r in pick_m]),
            ("SGG triplets", [(r["id"], ids[s], rel, ids[o], r) for r in pick_s
                              for ids in [{x["name"]: x["object"] for x in r["meta"]["objects"]}]
                              for s, rel, o in r["meta"].get("holds", r["meta"]["triplets"])])):
        ok = bad = skipped = 0
        wrong = []
        for rid, a, rel, b, r in checks:
            v = _agrees(rel, a, b, geo(r))
            if v is None:
                skipped += 1
            elif v:
                ok += 1
            else:
                bad += 1
                wrong.append(f"{rid}: {a} {rel} {b}")
        n = ok + bad
        print(f"  audit {name}: {ok}/{n} agree ({100 * ok / max(n, 1):.2f}%, goal >= 99%); "
              f"{skipped} without a geometric test" + (f"; e.g. {wrong[:3]}" if wrong else ""))


if __name__ == "__main__":
    main()
