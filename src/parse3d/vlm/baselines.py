"""Baselines and sanity checks: random, answer prior, text-only, oracle, perturbed oracle.

Each baseline maps benchmark records to responses (``{id: response}``), written as the same
prediction JSONL a model produces, so ``parse3d vlm eval`` scores them like any model.

* ``random`` — a uniform letter; for SGG five random names with random boxes and random
  triplets among them.
* ``prior`` — the most frequent answer letter of each task in ``train.jsonl``; for SGG the
  eight most frequent ground-truth triplets (by label) of the training split, without boxes.
* ``blind`` — text only: every option is scored by how often its text (objects, relation,
  parts) was the correct answer in the training split versus a distractor (smoothed log
  odds), backing off to its relation (relation MCQ) or its part pair / "not in contact"
  (contact MCQ) when the training split never shows that text; SGG as ``prior``.
* ``oracle`` — answers from the 3-D ground truth of the dataset (``scene.json``,
  ``contacts.json``, ``scene.glb``, ``views.json``): the option that holds, the scene graph
  with boxes projected from the 3-D boxes. Scores 100% on every task when every question
  has exactly one true option.
* ``perturbed`` — the oracle with 20% of MCQ answers changed to a wrong letter, 20% of
  SGG boxes shifted right by 60% of their width (IoU < 0.5) and 20% of triplets dropped
  (exactly ``ceil(0.2 n)`` of each, drawn over the whole file).
"""

from __future__ import annotations

import math
from collections import Counter
from pathlib import Path
from typing import Any

import numpy as np

from .._files import read_json
from ..errors import InputError, Problem
from .build import read_jsonl
from .evaluate import parse_scene_graph
from .facts import SceneFacts, VisibilityRule, load_scene_facts, view_facts
from .items import LETTERS, format_box, option_holds, option_text, sgg_item

__all__ = ["BASELINES", "run_baseline"]

BASELINES = ("random", "prior", "blind", "oracle", "perturbed")


def _train_rows(data: Path) -> list[dict[str, Any]]:
    train = data.parent / "train.jsonl"
    if not train.exists():
        raise InputError(Problem("", "this baseline learns from train.jsonl beside the data "
                                     "file, which is missing", str(train), "io"))
    return read_jsonl(train)


def _sgg_text(objects, triplets) -> str:
    out = "Objects:\n" + "\n".join(f"{o['name']} {format_box(o['box'])}" for o in objects)
    return out + "\nRelations:\n" + "\n".join(f"({s}, {r}, {o})" for s, r, o in triplets)


def _random(rows, rng: np.random.Generator) -> dict[str, str]:
    out = {}
    names = sorted({o["label"] for r in rows if r["task"] == "sgg" for o in r["meta"]["objects"]})
    rels = sorted({t[1] for r in rows if r["task"] == "sgg" for t in r["meta"]["triplets"]})
    for r in rows:
        if r["task"] != "sgg":
            out[r["id"]] = LETTERS[int(rng.integers(4))]
            continue
        objs = []
        for k in range(5 if names else 0):
            x1, y1 = rng.integers(0, 800, 2)
            w, h = rng.integers(50, 200, 2)
            objs.append({"name": f"{names[int(rng.integers(len(names)))]}#{k + 1}",
                         "box": [int(x1), int(y1), int(x1 + w), int(y1 + h)]})
        trip = []
        for _ in range(5 if len(objs) > 1 and rels else 0):
            i, j = rng.choice(len(objs), 2, replace=False)
            trip.append((objs[i]["name"], rels[int(rng.integers(len(rels)))], objs[j]["name"]))
        out[r["id"]] = _sgg_text(objs, trip)
    return out


def _sgg_prior(train) -> str:
    c = Counter((t[0].split("#")[0], t[1], t[2].split("#")[0])
                for r in train if r["task"] == "sgg" for t in r["meta"]["triplets"])
    return _sgg_text([], [(f"{s}#1", rel, f"{o}#1") for (s, rel, o), _ in c.most_common(8)])


def _prior(rows, train) -> dict[str, str]:
    best = {}
    for task in ("relation_mcq", "contact_mcq"):
        c = Counter(r["meta"]["answer"] for r in train if r["task"] == task)
        best[task] = c.most_common(1)[0][0] if c else "A"
    sg = _sgg_prior(train)
    return {r["id"]: best[r["task"]] if r["task"] != "sgg" else sg for r in rows}


def _option_key(o: dict[str, Any]) -> str:
    if o["kind"] == "relation":
        return f"rel:{o['relation']}"
    if o["kind"] == "no_contact":
        return "no_contact"
    return f"parts:{o['subject_part']}|{o['object_part']}"


def _blind(rows, train) -> dict[str, str]:
    good: Counter[str] = Counter()
    bad: Counter[str] = Counter()
    for r in train:
        if r["task"] == "sgg":
            continue
        ans = LETTERS.index(r["meta"]["answer"])
        for i, o in enumerate(r["meta"]["options"]):
            for key in (_option_key(o), option_text(o)):
                (good if i == ans else bad)[key] += 1

    def score(o: dict[str, Any]) -> float:
        # the option's whole text when the training split shows it, else its relation or
        # part pair
        key = option_text(o)
        if good[key] + bad[key] == 0:
            key = _option_key(o)
        return math.log((good[key] + 1) / (bad[key] + 1))

    sg = _sgg_prior(train)
    out = {}
    for r in rows:
        if r["task"] == "sgg":
            out[r["id"]] = sg
            continue
        scores = [score(o) for o in r["meta"]["options"]]
        out[r["id"]] = LETTERS[int(np.argmax(scores))]
    return out


def _card(data: Path) -> dict[str, Any]:
    card = data.parent / "vlm.json"
    if not card.exists():
        raise InputError(Problem("", "the oracle needs the benchmark card vlm.json beside the "
                                     "data file", str(card), "io"))
    card_doc = read_json(card, what="benchmark card")
    if not isinstance(card_doc, dict):
        raise InputError(Problem("", "the benchmark card is not a JSON object", str(card),
                                 "schema"))
    return card_doc


def _oracle(rows, data: Path, dataset: Path | None) -> dict[str, str]:
    card = _card(data)
    ds = Path(dataset) if dataset is not None else Path(card["dataset"])
    if not (ds / "scenes").is_dir():
        raise InputError(Problem("", "the dataset this benchmark was built from is not here; "
                                     "pass --dataset DIR", str(ds), "io"))
    opts = card["options"]
    rule = VisibilityRule(**opts["visibility"])
    from .build import candidate_objects

    candidates = candidate_objects()
    scenes: dict[str, SceneFacts] = {}
    out = {}
    for r in rows:
        name = r["scene"]
        if name not in scenes:
            vf = data.parent / "renders" / name
            scenes.clear()
            scenes[name] = load_scene_facts(ds / "scenes" / name,
                                            views_folder=vf if vf.is_dir() else None)
        scene = scenes[name]
        v = next((v for v in scene.views if int(v["index"]) == int(r["view"])), None)
        if v is None:
            raise InputError(Problem("", f"scene {name} has no view {r['view']}", str(ds), "io"))
        view = view_facts(scene, v, rule)
        if r["task"] == "sgg":
            item = sgg_item(scene, view, candidates, rule, boxes=r["meta"].get("boxes",
                                                                               opts["boxes"]))
            out[r["id"]] = item.answer if item is not None else ""
            continue
        red, blue = r["meta"]["red"], r["meta"]["blue"]
        true = [i for i, o in enumerate(r["meta"]["options"])
                if option_holds(scene, view, red, blue, o, rule)]
        out[r["id"]] = LETTERS[true[0]] if len(true) == 1 else "?"
    return out


def _pick(n: int, share: float, rng: np.random.Generator) -> set[int]:
    """Exactly ``ceil(share * n)`` of ``range(n)``."""
    k = int(math.ceil(share * n)) if n else 0
    return {int(i) for i in rng.choice(n, k, replace=False)} if k else set()


def _perturb(rows, answers: dict[str, str], rng: np.random.Generator,
             share: float = 0.2) -> dict[str, str]:
    mcq = [r["id"] for r in rows if r["task"] != "sgg" and answers[r["id"]] in LETTERS]
    flip = {mcq[i] for i in _pick(len(mcq), share, rng)}
    graphs = {r["id"]: parse_scene_graph(answers[r["id"]]) for r in rows if r["task"] == "sgg"}
    boxes = [(k, i) for k, (objs, _) in graphs.items() for i in range(len(objs))]
    trips = [(k, i) for k, (_, t) in graphs.items() for i in range(len(t))]
    jitter = {boxes[i] for i in _pick(len(boxes), share, rng)}
    drop = {trips[i] for i in _pick(len(trips), share, rng)}
    out = {}
    for r in rows:
        a = answers[r["id"]]
        if r["task"] != "sgg":
            if r["id"] in flip:
                a = LETTERS[(LETTERS.index(a) + int(rng.integers(1, 4))) % 4]
            out[r["id"]] = a
            continue
        objs, trip = graphs[r["id"]]
        for i, o in enumerate(objs):
            if (r["id"], i) in jitter:
                x1, y1, x2, y2 = o["box"]
                dx = 0.6 * (x2 - x1) + 1
                o["box"] = [x1 + dx, y1, x2 + dx, y2]
            o["box"] = [int(round(v)) for v in o["box"]]
        trip = [t for i, t in enumerate(trip) if (r["id"], i) not in drop]
        out[r["id"]] = _sgg_text(objs, trip)
    return out


def run_baseline(name: str, data: str | Path, *, seed: int = 0,
                 dataset: str | Path | None = None) -> dict[str, str]:
    """Responses of a baseline for every record of a benchmark split.

    Parameters
    ----------
    name : str
        One of :data:`BASELINES`.
    data : path
        A split (``VLM_DIR/test.jsonl``); ``prior`` and ``blind`` read ``train.jsonl`` beside
        it, ``oracle`` and ``perturbed`` the card ``vlm.json`` and the dataset it names.
    seed : int
    dataset : path, optional
        The dataset folder, when it moved since the benchmark was built.
    """
    data = Path(data)
    if name not in BASELINES:
        raise InputError(Problem("", f"unknown baseline {name!r}; choose one of "
                                     f"{', '.join(BASELINES)}", "NAME", "parameter"))
    rows = read_jsonl(data)
    rng = np.random.default_rng([int(seed), BASELINES.index(name)])
    if name == "random":
        return _random(rows, rng)
    if name == "prior":
        return _prior(rows, _train_rows(data))
    if name == "blind":
        return _blind(rows, _train_rows(data))
    answers = _oracle(rows, data, Path(dataset) if dataset is not None else None)
    return answers if name == "oracle" else _perturb(rows, answers, rng)
