"""``parse3d vlm eval``: score predictions as the paper's Table 2 does.

Predictions are JSONL lines ``{"id": ..., "response": "..."}``, one per benchmark item.

* **MCQ** (relation, part contact): accuracy of the chosen letter. :func:`parse_choice`
  reads ``C``, ``(C)``, ``C.``, ``The answer is C.``, ``Answer: (C) the mug ...`` or an
  option's text; anything else is *unparseable* and counts as wrong.
* **SGG**: objects ``name#k <|box_start|>x1, y1, x2, y2<|box_end|>`` (0-1000 grid) and
  triplets ``(subject#k, relation, object#k)``; names and relations pass the synonym tables of
  :mod:`parse3d.vlm.vocab`. Objects are matched class by class with the Hungarian algorithm
  on IoU (threshold 0.5). A predicted triplet is correct *with box matching* when both its
  objects are matched to ground-truth objects that carry that relation, and *without box
  matching* (grounding-agnostic) when a ground-truth triplet has the same subject label,
  relation and object label. Precision, recall and F1 are micro-averaged over all items
  (total correct / total predicted, total correct / total ground truth); ``Avg.`` is the mean
  number of predicted triplets per item.
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
from .items import option_text
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

    >>> [parse_choice(t) for t in ("C", "(C)", "The answer is C.", "Answer: (b)", "maybe")]
    ['C', 'C', 'C', 'B', None]
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
    found = set(re.findall(r"\b([A-D])\b", t))
    if len(found) == 1:
        return found.pop()
    return None


def _split_name(name: str) -> tuple[str, int | None]:
    n = name.strip().strip("-*•").strip()
    n = re.sub(r"^\d+[.)]\s*", "", n)
    m = _NAME.match(n)
    if m:
        return normalize_object(m.group(1)), int(m.group(2))
    return normalize_object(n), None


def parse_scene_graph(text: str) -> tuple[list[dict[str, Any]], list[tuple[str, str, str]]]:
    """Objects and canonical triplets of an SGG response.

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
    for label_text, box in boxes:
        label, k = _split_name(label_text)
        if not label:
            continue
        count[label] += 1
        name = f"{label}#{k if k is not None else count[label]}"
        objects.append({"name": name, "label": label, "box": box})
        by_label.setdefault(label, []).append(name)
    names = {o["name"] for o in objects}
    triplets = []
    for s, r, o in _triplets(kept):
        rel = normalize_relation(r) or "?"

        def resolve(x: str) -> str:
            label, k = _split_name(x)
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
    """Counts of one or more SGG items (sums)."""

    items: int = 0
    pred: int = 0
    gt: int = 0
    correct_matched: int = 0
    correct_unmatched: int = 0
    pred_objects: int = 0
    gt_objects: int = 0
    matched_objects: int = 0

    def add(self, other: SggScore) -> None:
        for k in self.__dataclass_fields__:
            setattr(self, k, getattr(self, k) + getattr(other, k))

    def metrics(self) -> dict[str, float]:
        def prf(c: int) -> tuple[float, float, float]:
            p = c / self.pred if self.pred else 0.0
            r = c / self.gt if self.gt else 0.0
            f = 2 * p * r / (p + r) if p + r else 0.0
            return 100 * p, 100 * r, 100 * f

        pm, rm, fm = prf(self.correct_matched)
        pu, ru, fu = prf(self.correct_unmatched)
        return {"recall": rm, "precision": pm, "f1": fm, "recall_nomatch": ru,
                "precision_nomatch": pu, "f1_nomatch": fu,
                "avg_relations": self.pred / self.items if self.items else 0.0,
                "object_recall": 100 * self.matched_objects / self.gt_objects
                if self.gt_objects else 0.0,
                "object_precision": 100 * self.matched_objects / self.pred_objects
                if self.pred_objects else 0.0}


def score_sgg(gt_meta: dict[str, Any], response: str, threshold: float = 0.5) -> SggScore:
    """Score one SGG response against an item's ``meta`` (objects and triplets)."""
    gt_objs = gt_meta["objects"]
    gt_trip = [tuple(t) for t in gt_meta["triplets"]]
    pred_objs, pred_trip = parse_scene_graph(response)
    m = match_objects(pred_objs, gt_objs, threshold)
    gt_set = Counter(gt_trip)
    ok_m = 0
    for s, r, o in pred_trip:
        key = (m.get(s), r, m.get(o))
        if key[0] is not None and key[2] is not None and gt_set[key] > 0:
            gt_set[key] -= 1
            ok_m += 1
    glabel = {o["name"]: o["label"] for o in gt_objs}
    plabel = {o["name"]: o["label"] for o in pred_objs}
    gl = Counter((glabel.get(s, s), r, glabel.get(o, o)) for s, r, o in gt_trip)
    ok_u = 0
    for s, r, o in pred_trip:
        key = (plabel.get(s, s.split("#")[0]), r, plabel.get(o, o.split("#")[0]))
        if gl[key] > 0:
            gl[key] -= 1
            ok_u += 1
    return SggScore(1, len(pred_trip), len(gt_trip), ok_m, ok_u, len(pred_objs), len(gt_objs),
                    len(m))


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
            sgg.add(score_sgg(r["meta"], resp, iou))
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
        for k, t in enumerate(trips):
            if not (isinstance(t, list) and len(t) == 3 and all(isinstance(x, str) for x in t)):
                return f"meta.triplets[{k}] must be three strings"
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
