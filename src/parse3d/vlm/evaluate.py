"""``parse3d vlm eval``: score predictions as the paper's Table 2 does.

Predictions are JSONL lines ``{"id": ..., "response": "..."}``, one per benchmark item.

* **MCQ** (relation, part contact): accuracy of the chosen letter. :func:`parse_choice`
  reads ``C``, ``(C)``, ``C.``, ``The answer is C.``, ``Answer: (C) the mug ...`` or an
  option's text; anything else is *unparseable* and counts as wrong.
* **SGG**: objects ``name#k <|box_start|>x1, y1, x2, y2<|box_end|>`` (0-1000 grid) and
  triplets ``(subject#k, relation, object#k)``, or Qwen3-VL's native grounding JSON
  (``[{"bbox_2d": [x1, y1, x2, y2], "label": "mug"}, ...]`` on the same grid, with relations
  as ``{"subject", "relation" | "predicate", "object"}`` entries); names and relations pass
  :func:`parse3d.vlm.vocab.normalize_object` (case, articles, plurals of the benchmark's
  labels, synonyms) and the relation synonyms. A symmetric relation (``near``, ``far from``,
  ...) matches in either order. Objects are matched class by class with the Hungarian algorithm
  on IoU (threshold 0.5). A predicted triplet is correct *with box matching* when both its
  objects are matched to ground-truth objects that carry that relation, and *without box
  matching* (grounding-agnostic) when a ground-truth triplet has the same subject label,
  relation and object label. Recall counts the answer's triplets predicted; precision counts
  the predicted triplets that hold in the image (``meta.holds``: every relation true of the
  pair in the settled geometry, of which the answer lists the salient ones), so a true
  relation the answer leaves out is not a false positive. Both are micro-averaged over all
  items; ``Avg.`` is the mean number of predicted triplets per item.
"""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from scipy.optimize import linear_sum_assignment

from ..errors import InputError, Problem
from .build import read_jsonl
from .items import SYMMETRIC_RELATIONS, option_text
from .vocab import INVERSE_RELATIONS, PHRASE_TO_RELATION, normalize_object, normalize_relation

__all__ = ["parse_choice", "parse_scene_graph", "box_iou", "match_objects", "score_sgg",
           "EvalReport", "evaluate", "evaluate_files", "read_predictions", "markdown_table"]

#: Characters of a response that are scored; the rest is ignored (an SGG answer of 1000
#: objects with boxes and relations is far shorter). Parsing is linear in what is scored.
MAX_RESPONSE_CHARS = 200_000
#: Longest object name before a box token, and longest text between a box's two tokens.
_MAX_LABEL, _MAX_BOX = 200, 200
_BOX_START, _BOX_END = "<|box_start|>", "<|box_end|>"
_NUM = r"(-?\d{1,12}(?:\.\d{1,12})?)"
_COORDS = re.compile(rf"\s*\(?\s*{_NUM}\s*,\s*{_NUM}\s*\)?\s*,\s*\(?\s*{_NUM}\s*,\s*{_NUM}"
                     r"\s*\)?\s*")
_NAME = re.compile(r"^(.*?)\s*#\s*(\d+)$")


def parse_choice(response: str, options: list[str] | None = None) -> str | None:
    """The letter A-D a response chooses, or None when it cannot be read.

    A capital ``A`` before a word is the article, not a choice:

    >>> [parse_choice(t) for t in ("C", "(C)", "The answer is C.", "Answer: (b)", "maybe",
    ...                            "A mug is on the desk.", "A is correct")]
    ['C', 'C', 'C', 'B', None, None, 'A']
    """
    if not isinstance(response, str):
        return None
    t = response[:MAX_RESPONSE_CHARS].strip()
    m = re.fullmatch(r"[\s(\[*'\"]*([A-Da-d])[\s)\].:*'\"]*", t)
    if m:
        return m.group(1).upper()
    m = re.search(r"answer\s*(?:(?:is|:)\s*)?(?:option\s*)?[(\[]?\s*([A-Da-d])\b", t, re.I)
    if m:
        return m.group(1).upper()
    m = re.match(r"[(\[]?([A-D])[)\].:]", t)
    if m:
        return m.group(1)
    found = set(re.findall(r"\(([A-D])\)", t))
    if len(found) == 1:
        return found.pop()
    if options:
        low = t.lower().strip(" .")
        hits = [i for i, o in enumerate(options) if o.lower().strip(" .") == low]
        if len(hits) == 1:
            return "ABCD"[hits[0]]
    found = {m.group(1) for m in re.finditer(r"\b([A-D])\b", t)
             if not (m.group(1) == "A" and _ARTICLE.match(t, m.end()))}
    if len(found) == 1:
        return found.pop()
    return None


#: After a capital "A": a following word that makes it the article ("A mug is ..."), not a
#: letter ("A is correct").
_ARTICLE = re.compile(r"\s+(?!(?:is|was|seems|fits|matches|describes|and|or)\b)[A-Za-z]")


def _split_name(name: str, known: frozenset[str] = frozenset()) -> tuple[str, int | None]:
    n = name.strip().strip("-*•").strip()
    n = re.sub(r"^\d+[.)]\s*", "", n)
    m = _NAME.match(n)
    if m:
        return normalize_object(m.group(1), known), int(m.group(2))
    return normalize_object(n, known), None


def parse_scene_graph(text: str, known: frozenset[str] = frozenset()
                      ) -> tuple[list[dict[str, Any]], list[tuple[str, str, str]]]:
    """Objects and canonical triplets of an SGG response.

    ``known`` are the benchmark's object labels (plurals of them are read as the label).

    Returns
    -------
    objects : list of dict
        ``{"name": "mug#1", "label": "mug", "box": [x1, y1, x2, y2]}`` (0-1000 grid); names
        without ``#k`` are numbered in order of appearance.
    triplets : list of (str, str, str)
        ``(subject name, relation phrase, object name)`` with synonyms normalised and
        ``right of`` / ``behind`` turned into ``left of`` / ``in front of``; triplets whose
        relation is not in the vocabulary are kept with the relation ``?`` (never correct).
    """
    text = text[:MAX_RESPONSE_CHARS] if isinstance(text, str) else ""
    objects: list[dict[str, Any]] = []
    count: Counter[str] = Counter()
    by_label: dict[str, list[str]] = {}
    boxes, kept = _boxes(text)
    trips = _triplets(kept)
    native = _native_json(kept)
    if native is not None:
        boxes += native[0]
        trips += native[1]
    for label_text, box in boxes:
        label, k = _split_name(label_text, known)
        if not label:
            continue
        count[label] += 1
        name = f"{label}#{k if k is not None else count[label]}"
        objects.append({"name": name, "label": label, "box": box})
        by_label.setdefault(label, []).append(name)
    names = {o["name"] for o in objects}
    triplets = []
    for s, r, o in trips:
        rel = normalize_relation(r) or "?"

        def resolve(x: str) -> str:
            label, k = _split_name(x, known)
            name = f"{label}#{k if k is not None else 1}"
            if name not in names and by_label.get(label):
                name = by_label[label][0]
            return name

        s, o = resolve(s), resolve(o)
        key = PHRASE_TO_RELATION.get(rel)
        if key in INVERSE_RELATIONS:
            s, o = o, s
            rel = {"LEFT_OF": "left of", "IN_FRONT_OF": "in front of"}[INVERSE_RELATIONS[key]]
        triplets.append((s, rel, o))
    return objects, triplets


def _boxes(text: str) -> tuple[list[tuple[str, list[float]]], str]:
    """``[(name before the box, [x1, y1, x2, y2])]`` and the text without them.

    Anchored on the box tokens (found with ``str.find``): the name is the text since the last
    line break, ``<`` or ``>`` (at most :data:`_MAX_LABEL` characters back) and the numbers lie
    between the two tokens (at most :data:`_MAX_BOX` characters), so every character is looked
    at a bounded number of times whatever the response holds.
    """
    out: list[tuple[str, list[float]]] = []
    rest: list[str] = []
    done = 0  # text before this is consumed (kept in rest or matched)
    pos = text.find(_BOX_START)
    while pos >= 0:
        inner = pos + len(_BOX_START)
        end = text.find(_BOX_END, inner, inner + _MAX_BOX + len(_BOX_END))
        m = _COORDS.fullmatch(text, inner, end) if end >= 0 else None
        if m is not None:
            lo = max(done, pos - _MAX_LABEL)
            start = max(lo, *(text.rfind(c, lo, pos) + 1 for c in "\n<>"))
            out.append((text[start:pos].strip(), [float(g) for g in m.groups()]))
            rest.append(text[done:start])
            done = end + len(_BOX_END)
            pos = text.find(_BOX_START, done)
        else:
            pos = text.find(_BOX_START, inner)
    rest.append(text[done:])
    return out, "".join(rest)


_FENCE = re.compile(r"```(?:json)?", re.I)


def _native_json(text: str) -> tuple[list[tuple[str, list[float]]],
                                     list[tuple[str, str, str]]] | None:
    """Boxes and triplets of Qwen3-VL's grounding JSON in a response, or None when it holds
    none: a list of ``{"bbox_2d": [x1, y1, x2, y2], "label": ...}`` (0-1000 grid), or an
    object with such a list under ``objects`` and relation entries under ``relations``
    (``{"subject", "relation" | "predicate", "object"}`` or ``[s, r, o]``). One ``json``
    parse of the text from its first ``[`` or ``{`` to its last ``]`` or ``}``."""
    import json

    t = _FENCE.sub("", text)
    starts = [i for i in (t.find("["), t.find("{")) if i >= 0]
    end = max(t.rfind("]"), t.rfind("}"))
    if not starts or end < min(starts):
        return None
    try:
        doc = json.loads(t[min(starts):end + 1])
    except (ValueError, RecursionError):
        return None
    if isinstance(doc, dict):
        entries = [*(doc.get("objects") or []), *(doc.get("relations") or [])]
    elif isinstance(doc, list):
        entries = doc
    else:
        return None
    boxes: list[tuple[str, list[float]]] = []
    trips: list[tuple[str, str, str]] = []
    for e in entries if isinstance(entries, list) else []:
        if isinstance(e, dict):
            box = e.get("bbox_2d", e.get("bbox"))
            label = e.get("label", e.get("name"))
            if (isinstance(label, str) and isinstance(box, list) and len(box) == 4
                    and all(isinstance(v, int | float) and not isinstance(v, bool)
                            for v in box)):
                boxes.append((label, [float(v) for v in box]))
                continue
            rel = e.get("relation", e.get("predicate"))
            trip = (e.get("subject"), rel, e.get("object"))
        elif isinstance(e, list) and len(e) == 3:
            trip = tuple(e)
        else:
            continue
        if all(isinstance(x, str) and x.strip() for x in trip):
            trips.append(tuple(x.strip() for x in trip))
    return (boxes, trips) if boxes or trips else None


def _triplets(text: str) -> list[tuple[str, str, str]]:
    """``(a, b, c)`` groups of three non-empty fields without ``(``, ``)``, ``,`` or a line
    break, stripped; one left-to-right pass."""
    out = []
    pos = text.find("(")
    while pos >= 0:
        close = pos + 1
        n = len(text)
        while close < n and text[close] not in "()\n":
            close += 1
        if close < n and text[close] == ")":
            parts = [x.strip() for x in text[pos + 1:close].split(",")]
            if len(parts) == 3 and all(parts):
                out.append((parts[0], parts[1], parts[2]))
                pos = text.find("(", close + 1)
                continue
        pos = text.find("(", pos + 1) if close >= n or text[close] != "(" else close
    return out


def box_iou(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """IoU of boxes ``(N, 4)`` and ``(M, 4)`` (``x1, y1, x2, y2``) -> ``(N, M)``."""
    a = np.asarray(a, float).reshape(-1, 4)
    b = np.asarray(b, float).reshape(-1, 4)
    lt = np.maximum(a[:, None, :2], b[None, :, :2])
    rb = np.minimum(a[:, None, 2:], b[None, :, 2:])
    inter = np.prod(np.clip(rb - lt, 0, None), axis=2)
    area_a = np.prod(np.clip(a[:, 2:] - a[:, :2], 0, None), axis=1)
    area_b = np.prod(np.clip(b[:, 2:] - b[:, :2], 0, None), axis=1)
    union = area_a[:, None] + area_b[None, :] - inter
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(union > 0, inter / union, 0.0)


def match_objects(pred: list[dict[str, Any]], gt: list[dict[str, Any]],
                  threshold: float = 0.5) -> dict[str, str]:
    """Class-wise Hungarian matching on IoU: predicted name -> ground-truth name."""
    out: dict[str, str] = {}
    for label in {o["label"] for o in pred} & {o["label"] for o in gt}:
        p = [o for o in pred if o["label"] == label]
        g = [o for o in gt if o["label"] == label]
        iou = box_iou([o["box"] for o in p], [o["box"] for o in g])
        rows, cols = linear_sum_assignment(-iou)
        for i, j in zip(rows, cols, strict=True):
            if iou[i, j] >= threshold:
                out[p[i]["name"]] = g[j]["name"]
    return out


@dataclass
class SggScore:
    """Counts of one or more SGG items (sums): ``correct_*`` answer triplets predicted
    (recall), ``true_*`` predicted triplets that hold (precision), with and without box
    matching."""

    items: int = 0
    pred: int = 0
    gt: int = 0
    correct_matched: int = 0
    correct_unmatched: int = 0
    pred_objects: int = 0
    gt_objects: int = 0
    matched_objects: int = 0
    true_matched: int = 0
    true_unmatched: int = 0

    def add(self, other: SggScore) -> None:
        for k in self.__dataclass_fields__:
            setattr(self, k, getattr(self, k) + getattr(other, k))

    def metrics(self) -> dict[str, float]:
        def prf(c: int, t: int) -> tuple[float, float, float]:
            p = t / self.pred if self.pred else 0.0
            r = c / self.gt if self.gt else 0.0
            f = 2 * p * r / (p + r) if p + r else 0.0
            return 100 * p, 100 * r, 100 * f

        pm, rm, fm = prf(self.correct_matched, self.true_matched)
        pu, ru, fu = prf(self.correct_unmatched, self.true_unmatched)
        return {"recall": rm, "precision": pm, "f1": fm, "recall_nomatch": ru,
                "precision_nomatch": pu, "f1_nomatch": fu,
                "avg_relations": self.pred / self.items if self.items else 0.0,
                "object_recall": 100 * self.matched_objects / self.gt_objects
                if self.gt_objects else 0.0,
                "object_precision": 100 * self.matched_objects / self.pred_objects
                if self.pred_objects else 0.0}


def _canonical(s: str, r: str, o: str) -> tuple[str, str, str]:
    """A symmetric relation's triplet with its two ends in sorted order."""
    if PHRASE_TO_RELATION.get(r) in SYMMETRIC_RELATIONS and o < s:
        return o, r, s
    return s, r, o


def score_sgg(gt_meta: dict[str, Any], response: str, threshold: float = 0.5,
              known: frozenset[str] = frozenset()) -> SggScore:
    """Score one SGG response against an item's ``meta`` (objects and triplets).

    ``known``: the benchmark's object labels (default: this item's), whose plurals are read
    as them.
    """
    gt_objs = gt_meta["objects"]
    gt_trip = [tuple(t) for t in gt_meta["triplets"]]
    known = known or frozenset(o["label"] for o in gt_objs)
    pred_objs, pred_trip = parse_scene_graph(response, known)
    m = match_objects(pred_objs, gt_objs, threshold)
    holds = [tuple(t) for t in gt_meta.get("holds", gt_trip)]
    ok_m = _hits(pred_trip, gt_trip, holds, lambda x: m.get(x))
    glabel = {o["name"]: o["label"] for o in gt_objs}
    plabel = {o["name"]: o["label"] for o in pred_objs}
    ok_u = _hits([(plabel.get(s, s.split("#")[0]), r, plabel.get(o, o.split("#")[0]))
                  for s, r, o in pred_trip],
                 [(glabel.get(s, s), r, glabel.get(o, o)) for s, r, o in gt_trip],
                 [(glabel.get(s, s), r, glabel.get(o, o)) for s, r, o in holds], lambda x: x)
    return SggScore(1, len(pred_trip), len(gt_trip), ok_m[0], ok_u[0], len(pred_objs),
                    len(gt_objs), len(m), ok_m[1], ok_u[1])


def _hits(pred, answer, holds, name) -> tuple[int, int]:
    """(answer triplets predicted, predicted triplets that hold): each ground-truth triplet
    counts once; ``name`` maps a predicted name to the ground truth's (None: unmatched)."""
    mapped = []
    for s, r, o in pred:
        a, b = name(s), name(o)
        if a is not None and b is not None:
            mapped.append(_canonical(a, r, b))
    want = Counter(_canonical(*t) for t in answer)
    recalled = 0
    for t in mapped:
        if want[t] > 0:
            want[t] -= 1
            recalled += 1
    true = Counter(_canonical(*t) for t in holds)
    for t in answer:  # an answer triplet holds, whatever an older record's holds list says
        true[_canonical(*t)] = max(true[_canonical(*t)], 1)
    right = 0
    for t in mapped:
        if true[t] > 0:
            true[t] -= 1
            right += 1
    return recalled, right


@dataclass
class EvalReport:
    """Scores of one prediction file against a benchmark split."""

    model: str
    relation: dict[str, Any] = field(default_factory=dict)
    contact: dict[str, Any] = field(default_factory=dict)
    sgg: dict[str, float] = field(default_factory=dict)
    items: dict[str, int] = field(default_factory=dict)
    missing: list[str] = field(default_factory=list)
    unknown: list[str] = field(default_factory=list)
    unparseable: list[str] = field(default_factory=list)

    def to_dict(self) -> dict[str, Any]:
        return {"model": self.model, "items": self.items,
                "relation_mcq": self.relation, "contact_mcq": self.contact, "sgg": self.sgg,
                "missing": {"count": len(self.missing), "ids": self.missing[:20]},
                "unknown": {"count": len(self.unknown), "ids": self.unknown[:20]},
                "unparseable": {"count": len(self.unparseable), "ids": self.unparseable[:20]}}


def _acc(rows: list[tuple[dict[str, Any], bool]], key) -> dict[str, Any]:
    by: dict[str, list[bool]] = {}
    for r, ok in rows:
        by.setdefault(key(r), []).append(ok)
    return {k: {"n": len(v), "accuracy": round(100 * sum(v) / len(v), 2)}
            for k, v in sorted(by.items())}


def _mcq(rows: list[tuple[dict[str, Any], bool]]) -> dict[str, Any]:
    if not rows:
        return {"n": 0, "accuracy": None}
    return {"n": len(rows), "accuracy": round(100 * sum(ok for _, ok in rows) / len(rows), 2),
            "per_relation": _acc(rows, lambda r: str(r["meta"].get("phrase",
                                                                   r["meta"].get("relation")))),
            "per_room_type": _acc(rows, lambda r: r["meta"].get("room_type", "?"))}


def read_predictions(path: str | Path) -> dict[str, str]:
    """``{id: response}`` of a prediction JSONL file (the last line wins for an id)."""
    out: dict[str, str] = {}
    for n, row in enumerate(read_jsonl(path), 1):
        if "id" not in row or "response" not in row:
            raise InputError(Problem(f"line {n}", "a prediction needs 'id' and 'response' "
                                                  "(one {\"id\": ..., \"response\": ...} per "
                                                  "line)", str(path), "schema"))
        out[str(row["id"])] = row["response"] if isinstance(row["response"], str) else ""
    return out


def evaluate(gt: list[dict[str, Any]], pred: dict[str, str], *, model: str = "model",
             iou: float = 0.5) -> EvalReport:
    """Score predictions (``{id: response}``) against benchmark records."""
    rep = EvalReport(model)
    ids = {r["id"] for r in gt}
    rep.unknown = sorted(set(pred) - ids)
    rel, con = [], []
    sgg = SggScore()
    known = frozenset(o.get("label") for r in gt if r["task"] == "sgg"
                      for o in r["meta"].get("objects", []))
    for r in gt:
        resp = pred.get(r["id"])
        if resp is None:
            rep.missing.append(r["id"])
            resp = ""
        if r["task"] in ("relation_mcq", "contact_mcq"):
            opts = [option_text(o) for o in r["meta"].get("options", [])]
            choice = parse_choice(resp, opts)
            if choice is None and r["id"] in pred:
                rep.unparseable.append(r["id"])
            (rel if r["task"] == "relation_mcq" else con).append(
                (r, choice == r["meta"]["answer"]))
        elif r["task"] == "sgg":
            sgg.add(score_sgg(r["meta"], resp, iou, known))
    rep.items = dict(sorted(Counter(r["task"] for r in gt).items()))
    rep.relation, rep.contact = _mcq(rel), _mcq(con)
    rep.sgg = {k: round(v, 2) for k, v in sgg.metrics().items()} if sgg.items else {}
    return rep


def evaluate_files(gt_path: str | Path, pred_path: str | Path, *, allow_missing: bool = False,
                   model: str | None = None, iou: float = 0.5) -> EvalReport:
    """Score a prediction file; missing or unknown ids are an error unless allowed."""
    gt = read_jsonl(gt_path)
    if not gt:
        raise InputError(Problem("", "no benchmark items in this file", str(gt_path), "io"))
    for n, r in enumerate(gt, 1):
        if not {"id", "task", "meta"} <= set(r):
            raise InputError(Problem(f"line {n}", "not a benchmark record (id, task, meta) — "
                                                  "pass a split written by parse3d vlm build",
                                     str(gt_path), "schema"))
        why = _record_problem(r)
        if why:
            raise InputError(Problem(f"line {n}", f"a damaged benchmark record: {why} — pass a "
                                                  "split written by parse3d vlm build",
                                     str(gt_path), "schema"))
    pred = read_predictions(pred_path)
    rep = evaluate(gt, pred, model=model or Path(pred_path).stem, iou=iou)
    if (rep.missing or rep.unknown) and not allow_missing:
        parts = []
        if rep.missing:
            parts.append(f"{len(rep.missing)} benchmark ids have no prediction (e.g. "
                         f"{', '.join(rep.missing[:3])})")
        if rep.unknown:
            parts.append(f"{len(rep.unknown)} predicted ids are not in {Path(gt_path).name} "
                         f"(e.g. {', '.join(rep.unknown[:3])})")
        raise InputError(Problem("", "; ".join(parts) + " — predict every item of this split "
                                     "(parse3d vlm ask resumes), or pass --allow-missing to "
                                     "score missing ones as wrong", str(pred_path), "io"))
    return rep


def _record_problem(r: dict[str, Any]) -> str | None:
    """What is wrong with the shape of a benchmark record, or None."""
    import math

    def number(v: Any) -> bool:
        return isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v)

    if not isinstance(r["id"], str | int) or isinstance(r["id"], bool):
        return "'id' must be a string"
    meta = r["meta"]
    if not isinstance(meta, dict):
        return "'meta' must be an object"
    if r["task"] in ("relation_mcq", "contact_mcq"):
        if not isinstance(meta.get("answer"), str):
            return "meta.answer must be a letter"
        opts = meta.get("options", [])
        if not isinstance(opts, list):
            return "meta.options must be a list"
        for k, o in enumerate(opts):
            try:
                if not isinstance(option_text(o), str):
                    raise TypeError
            except (KeyError, TypeError, AttributeError):
                return f"meta.options[{k}] is not an option"
    elif r["task"] == "sgg":
        objs, trips = meta.get("objects"), meta.get("triplets")
        if not isinstance(objs, list) or not isinstance(trips, list):
            return "meta.objects and meta.triplets must be lists"
        for k, o in enumerate(objs):
            if not (isinstance(o, dict) and isinstance(o.get("name"), str)
                    and isinstance(o.get("label"), str) and isinstance(o.get("box"), list)
                    and len(o["box"]) == 4 and all(number(v) for v in o["box"])):
                return f"meta.objects[{k}] needs a name, a label and a box of four numbers"
        holds = meta.get("holds", [])
        if not isinstance(holds, list):
            return "meta.holds must be a list"
        for key, rows in (("triplets", trips), ("holds", holds)):
            for k, t in enumerate(rows):
                if not (isinstance(t, list) and len(t) == 3
                        and all(isinstance(x, str) for x in t)):
                    return f"meta.{key}[{k}] must be three strings"
    return None


def _f(v: Any) -> str:
    return "–" if v is None else f"{v:.1f}"


def markdown_table(reports: list[EvalReport]) -> str:
    """Table 2 of the paper for these reports, plus per-relation and per-room accuracy."""
    lines = ["| Model | Visual Relation ↑ | Part-level Contact ↑ | Recall ↑ | Precision ↑ "
             "| F1 Score ↑ | Avg. |", "|---|---|---|---|---|---|---|"]
    for r in reports:
        s = r.sgg
        if s:
            rec = f"{s['recall']:.1f}/{s['recall_nomatch']:.1f}"
            pre = f"{s['precision']:.1f}/{s['precision_nomatch']:.1f}"
            f1 = f"{s['f1']:.1f}/{s['f1_nomatch']:.1f}"
            avg = f"{s['avg_relations']:.1f}"
        else:
            rec = pre = f1 = avg = "–"
        lines.append(f"| {r.model} | {_f(r.relation.get('accuracy'))} | "
                     f"{_f(r.contact.get('accuracy'))} | {rec} | {pre} | {f1} | {avg} |")
    lines.append("")
    lines.append("SGG: with box matching / without (grounding-agnostic).")
    for r in reports:
        for title, d in (("relation MCQ", r.relation), ("contact MCQ", r.contact)):
            if not d.get("n"):
                continue
            per = ", ".join(f"{k} {v['accuracy']:.1f} ({v['n']})"
                            for k, v in d["per_relation"].items())
            room = ", ".join(f"{k} {v['accuracy']:.1f} ({v['n']})"
                             for k, v in d["per_room_type"].items())
            lines.append(f"\n{r.model} — {title} per answer: {per}")
            lines.append(f"{r.model} — {title} per room type: {room}")
        if r.missing or r.unknown or r.unparseable:
            lines.append(f"\n{r.model}: {len(r.missing)} missing, {len(r.unknown)} unknown, "
                         f"{len(r.unparseable)} unparseable (counted as wrong)")
    return "\n".join(lines)
