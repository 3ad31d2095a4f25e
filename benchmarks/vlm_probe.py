"""Learnability check: a small CNN trained from scratch beside random, prior and blind.

Usage::

    python benchmarks/vlm_probe.py VLM_DIR                     # a benchmark (parse3d vlm build)
    python benchmarks/vlm_probe.py VLM_DIR --epochs 8 --out out/probe
    python benchmarks/vlm_probe.py VLM_DIR --text-only        # only the text-only twin

Trains :func:`parse3d.vlm.probe.train_probe` twice on the MCQ of ``train.jsonl`` — on the
images with the options' words, and the same network with blank images (text only) — and
prints the test-split accuracy of both per task beside chance (25%) and the ``random``,
``prior`` and ``blind`` baselines, scored by ``parse3d vlm eval``'s own code. ``--out`` keeps
the prediction files (``probe.jsonl``, ``probe-text.jsonl``) and ``probe.json`` (settings,
losses, figures) for ``parse3d vlm eval``. No pretrained weights, CPU only; about a minute per
thousand training questions and epoch on two cores at the default 128x96.
"""

from __future__ import annotations

import argparse
import json
import tempfile
from dataclasses import replace
from pathlib import Path

from parse3d.vlm.baselines import run_baseline
from parse3d.vlm.build import read_jsonl
from parse3d.vlm.evaluate import evaluate
from parse3d.vlm.probe import ProbeOptions, train_probe


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("bench", type=Path, help="benchmark folder (parse3d vlm build)")
    ap.add_argument("--epochs", type=int, default=ProbeOptions.epochs)
    ap.add_argument("--size", default="128x96", help="image size WxH the views are shrunk to")
    ap.add_argument("--max-items", type=int, default=0, help="training questions at most")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", type=Path, help="keep predictions and probe.json here")
    ap.add_argument("--text-only", action="store_true",
                    help="train only the text-only twin (a minute, not ten)")
    args = ap.parse_args()
    w, h = (int(v) for v in args.size.lower().split("x"))
    opts = ProbeOptions(size=(w, h), epochs=args.epochs, max_items=args.max_items,
                        seed=args.seed, threads=args.threads)
    tmp = tempfile.TemporaryDirectory(prefix="vlm-probe-")
    out = args.out or Path(tmp.name)
    out.mkdir(parents=True, exist_ok=True)
    test = args.bench / "test.jsonl"
    gt = read_jsonl(test)
    rows = [("chance", {"relation_mcq": 25.0, "contact_mcq": 25.0})]
    for name in ("random", "prior", "blind"):
        rep = evaluate(gt, run_baseline(name, test, seed=args.seed), model=name)
        rows.append((name, {"relation_mcq": rep.relation.get("accuracy"),
                            "contact_mcq": rep.contact.get("accuracy")}))
    runs = {}
    twins = [("probe-text", replace(opts, image=False)), ("probe", opts)]
    for name, o in twins[:1] if args.text_only else twins:
        res = train_probe(args.bench, o, progress=lambda e, n, loss, name=name: print(
            f"  {name} epoch {e}/{n}: loss {loss:.3f}", flush=True))
        (out / f"{name}.jsonl").write_text("".join(
            json.dumps({"id": k, "response": v}) + "\n" for k, v in res.responses.items()))
        rep = evaluate(gt, res.responses, model=name)
        rows.append((name, {"relation_mcq": rep.relation.get("accuracy"),
                            "contact_mcq": rep.contact.get("accuracy")}))
        runs[name] = res.to_json()
        print(f"  {name}: {res.items['train']} training questions, {res.wall:.0f} s; "
              f"train accuracy {res.train_accuracy}", flush=True)
    (out / "probe.json").write_text(json.dumps(runs, indent=1) + "\n")
    n = {t: sum(1 for r in gt if r["task"] == t) for t in ("relation_mcq", "contact_mcq")}
    print(f"\ntest split: {n['relation_mcq']} relation MCQ, {n['contact_mcq']} part-contact MCQ")
    print("| Model | Visual Relation | Part-level Contact |\n|---|---|---|")
    for name, acc in rows:
        print(f"| {name} | {acc['relation_mcq']} | {acc['contact_mcq']} |")
    tmp.cleanup()


if __name__ == "__main__":
    main()
