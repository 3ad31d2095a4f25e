"""Check that the solver gives the same scenes as before a change (a speed-up's proof).

Solves a fixed set of rooms (the bundled example rooms, the 50-object office of
``bench_solver.py``, some room templates and, with ``--foreign N``, foreign rooms) at a few seeds, without settling, and stores each
scene's ``scene.json`` text with its timings left out. ``--save FILE`` writes them;
``--compare FILE`` solves again and reports every scene whose text differs, with the first
differing object (exit status 1 if any).

    python benchmarks/check_solver_equivalence.py --save before.json     # on the old revision
    python benchmarks/check_solver_equivalence.py --compare before.json  # after the change
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

from bench_solver import office_50

from parse3d.pag import load_pag
from parse3d.scene.io import scene_to_dict
from parse3d.scenes import bundled_paths
from parse3d.solver import solve

FOREIGN = Path(__file__).resolve().parent.parent / "tests" / "data" / "foreign"


def cases(n_templates: int, seeds: int, n_foreign: int = 0) -> list[tuple[str, object, int]]:
    """``(key, pag, seed)`` of every scene checked."""
    out = []
    for p in sorted(FOREIGN.glob("*.json"))[:n_foreign]:
        pag = load_pag(p)
        out += [(f"foreign/{p.stem}/{s}", pag, s) for s in range(2)]
    for p in bundled_paths():
        pag = load_pag(p)
        out += [(f"{pag.name}/{s}", pag, s) for s in range(2)]
    pag = office_50()
    out += [(f"{pag.name}/{s}", pag, s) for s in range(seeds)]
    from parse3d.datagen.templates import expand_template, list_templates

    templates = list_templates()
    step = max(1, len(templates) // max(n_templates, 1))
    for t in templates[::step][:n_templates]:
        pag = expand_template(t, 0)
        out += [(f"{t.name}/{s}", pag, s) for s in range(seeds)]
    return out


def scene_doc(pag, seed: int) -> dict:
    scene = solve(pag, seed=seed, validate=False)
    doc = scene_to_dict(scene)
    doc.pop("timings", None)
    doc.get("meta", {}).pop("timings", None)
    # the poses at full precision too (scene.json rounds them)
    doc["exact"] = {o.id: [repr(float(x)) for x in (*o.rotation.ravel(), *o.position, o.scale)]
                    for o in scene.objects.values() if o.placed}
    return doc


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    what = ap.add_mutually_exclusive_group(required=True)
    what.add_argument("--save", metavar="FILE")
    what.add_argument("--compare", metavar="FILE")
    ap.add_argument("--templates", type=int, default=12)
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--foreign", type=int, default=0, metavar="N",
                    help="also the first N rooms of tests/data/foreign at seeds 0-1")
    args = ap.parse_args()
    t0 = time.process_time()
    docs = {}
    for key, pag, seed in cases(args.templates, args.seeds, args.foreign):
        docs[key] = json.loads(json.dumps(scene_doc(pag, seed)))
        print(f"{key}: {sum(o.get('status') == 'placed' for o in docs[key]['objects'])} of "
              f"{len(docs[key]['objects'])} placed", flush=True)
    print(f"{len(docs)} scenes, {time.process_time() - t0:.1f} s CPU")
    if args.save:
        with open(args.save, "w") as f:
            json.dump(docs, f)
        return
    with open(args.compare) as f:
        before = json.load(f)
    bad = 0
    for key, doc in docs.items():
        old = before.get(key)
        if old == doc:
            continue
        bad += 1
        if old is None:
            print(f"DIFF {key}: not in {args.compare}")
            continue
        objs = {o["id"]: o for o in old.get("objects", [])}
        first = next((o["id"] for o in doc.get("objects", []) if objs.get(o["id"]) != o), None)
        print(f"DIFF {key}: first differing object {first}"
              + ("" if first else f" (differs in {[k for k in doc if doc[k] != old.get(k)]})"))
    print(f"{len(docs) - bad} of {len(docs)} scenes identical")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
