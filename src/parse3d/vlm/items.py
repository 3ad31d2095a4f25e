"""The three tasks of one view: relation MCQ, part-contact MCQ and scene-graph generation.

Each function takes the scene's ground truth, one view's visibility and an explicit random
generator, and returns :class:`Item` objects (question, answer, structured metadata and
how to draw the image). Nothing here writes files; :mod:`parse3d.vlm.build` does.

Every MCQ option is structured data (``meta["options"]``) as well as text, and
:func:`option_holds` decides it from the 3-D ground truth: the builder keeps a question only
when exactly one of its four options holds, and the oracle baseline answers with the same
function from the files alone.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .balance import (
    ContactCandidate,
    ContactPrior,
    RelationKey,
    RelationQuestion,
    visible_parts,
)
from .facts import (
    SceneFacts,
    ViewFacts,
    VisibilityRule,
    pair_truth,
    projected_box,
    relation_sources,
    to_grid,
)
from .vocab import (
    CAMERA_RELATIONS,
    INVERSE_RELATIONS,
    NO_CONTACT,
    RELATION_PHRASES,
    relation_sentence,
)

__all__ = [
    "LETTERS",
    "RELATION_PROMPT",
    "CONTACT_PROMPT",
    "SGG_PROMPT",
    "Item",
    "TaskLimits",
    "relation_items",
    "contact_items",
    "sgg_item",
    "option_holds",
    "option_text",
    "format_box",
    "SUPPORT_RELATIONS",
]

LETTERS = "ABCD"
SUPPORT_RELATIONS = ("ON", "IN", "HANGING_BELOW", "SECURED_TO")
#: "A REL B" and "B REL A" say the same: never offered as a swapped-order distractor.
SYMMETRIC_RELATIONS = ("NO_CONTACT", "NEAR", "FAR_FROM", "AGAINST", "ALIGNED_WITH",
                       "OPPOSITE_TO", "PARALLEL_TO", "SIDE_OF")

RELATION_PROMPT = (
    "The image displays two objects highlighted with a red and a blue bounding box. Your task "
    "is to identify the object within the red box, the object within the blue box, and the "
    "spatial relationship between them. From the options below, choose the one that correctly "
    "describes this scene (each option names the object in the red box first). {options}. "
    "Your answer should only be the letter of the correct option.")

CONTACT_PROMPT = (
    "The image displays two objects highlighted with a red and a blue bounding box. Your task "
    "is to identify the object within the red box, the object within the blue box, and "
    "whether they are in contact with each other. From the options below, choose the one that "
    "correctly describes this scene (each option names the object in the red box first). "
    "{options}. Your answer should only be the letter of the correct option.")

SGG_PROMPT = (
    "Detect and localize all objects in the image, then identify the spatial relationships "
    "between the detected objects. Candidate object names: {objects}. Candidate relations: "
    "{relations}. Answer with a line 'Objects:' followed by one line per object, "
    "'name#k <|box_start|>x1, y1, x2, y2<|box_end|>' (k numbers objects of the same name "
    "from 1; coordinates on a 0-1000 grid of the image width and height), then a line "
    "'Relations:' followed by one line per relation, '(subject#k, relation, object#k)'.")


@dataclass(frozen=True)
class TaskLimits:
    """How many questions one view may give.

    Attributes
    ----------
    relation : int
        Relation MCQs per view (the split's questions are chosen by
        :func:`parse3d.vlm.balance.plan_relation_questions`).
    contact : int
        Part-contact MCQs per view about touching object pairs, and as many at most about
        pairs that do not touch (the split's questions are chosen by
        :func:`parse3d.vlm.balance.plan_contact_questions`).
    """

    relation: int = 8
    contact: int = 6


@dataclass
class Item:
    """One question before it is written.

    Attributes
    ----------
    task : str
        ``relation_mcq``, ``contact_mcq`` or ``sgg``.
    prompt, answer : str
        The user text (without the image token) and the assistant's target.
    meta : dict
        Structured ground truth (options, answer letter, relation, objects, triplets, ...).
    marks : list of (str, list of int)
        Boxes to draw on the image: ``("red" | "blue", [x1, y1, x2, y2])`` in pixels.
    """

    task: str
    prompt: str
    answer: str
    meta: dict[str, Any]
    marks: list[tuple[str, list[int]]] = field(default_factory=list)


def _pick_letter(counts: dict[str, int], rng: np.random.Generator) -> int:
    low = min(counts[c] for c in LETTERS)
    choices = [i for i, c in enumerate(LETTERS) if counts[c] == low]
    return int(choices[int(rng.integers(len(choices)))])


def option_text(opt: dict[str, Any]) -> str:
    """The text of a structured option."""
    if opt["kind"] == "relation":
        return relation_sentence(opt["subject"], opt["relation"], opt["object"])
    if opt["kind"] == "no_contact":
        return f"the {opt['subject']} and the {opt['object']} are not in contact"
    return (f"the {opt['subject_part']} of the {opt['subject']} contacts the "
            f"{opt['object_part']} of the {opt['object']}")


def _label_contacts(scene: SceneFacts, a: str, b: str) -> set[tuple[str, str]]:
    oa, ob = scene.objects[a], scene.objects[b]
    return {(oa.parts.get(pa, pa), ob.parts.get(pb, pb))
            for pa, pb in scene.contacts.get((a, b), set())}


def option_holds(scene: SceneFacts, view: ViewFacts, red: str, blue: str,
                 opt: dict[str, Any], rule: VisibilityRule) -> bool:
    """Whether an option is true of the red and blue objects, from the 3-D ground truth."""
    oa, ob = scene.objects[red], scene.objects[blue]
    if opt["subject"] != oa.label or opt["object"] != ob.label:
        return False
    if opt["kind"] == "relation":
        true, _ = pair_truth(scene, view.camera, red, blue, rule)
        return opt["relation"] in true
    if opt["kind"] == "no_contact":
        return (red, blue) not in scene.contacts
    return (opt["subject_part"], opt["object_part"]) in _label_contacts(scene, red, blue)


def _finish_mcq(template: str, correct: dict[str, Any],
                distractors: list[dict[str, Any]], counts: dict[str, int],
                rng: np.random.Generator, meta: dict[str, Any]) -> tuple[str, str, dict]:
    k = _pick_letter(counts, rng)
    opts = list(distractors)
    rng.shuffle(opts)
    opts.insert(k, correct)
    counts[LETTERS[k]] += 1
    text = ", ".join(f"({LETTERS[i]}) {option_text(o)}" for i, o in enumerate(opts))
    meta = {**meta, "options": opts, "answer": LETTERS[k]}
    return template.format(options=text), LETTERS[k], meta


def _statement(subject: str, relation: str, obj: str) -> dict[str, Any]:
    return {"kind": "relation", "subject": subject, "relation": relation, "object": obj}


def _relation_options(la: str, lb: str, q: RelationQuestion,
                      asked: list[dict[RelationKey, int]], labels: list[str],
                      rng: np.random.Generator) -> list[dict[str, Any]]:
    """The three false options of a relation question (:mod:`parse3d.vlm.balance`): "A R' B"
    (the couple's other relation, false of the marked objects) and both relations of a couple
    asked about another category pair, drawn by how often the first table of ``asked`` with
    another category pair asks it (the question's split, then every split)."""
    out = [_statement(la, q.other, lb)]
    for table in asked:
        key = _weighted(table, rng, exclude={k for k in table if k[:2] in ((la, lb), (lb, la))})
        if key is not None:
            lc, ld, r3, r4 = key
            return out + [_statement(lc, r3, ld), _statement(lc, r4, ld)]
    # no other category pair asked: a category absent from the scene replaces one of the
    # two objects (false of the whole scene)
    if not labels:
        return []
    o = labels[int(rng.integers(len(labels)))]
    if rng.random() < 0.5:
        return out + [_statement(o, q.relation, lb), _statement(o, q.other, lb)]
    return out + [_statement(la, q.relation, o), _statement(la, q.other, o)]


def relation_items(scene: SceneFacts, view: ViewFacts, questions: list[RelationQuestion],
                   asked: list[dict[RelationKey, int]], labels: list[str], rule: VisibilityRule,
                   counts: dict[str, int], rng: np.random.Generator) -> list[Item]:
    """Relation MCQs of one view, about the ``questions`` the split's plan chose
    (:func:`parse3d.vlm.balance.plan_relation_questions`).

    Four options: the answer "A R B", "A R' B" with the other relation of its couple (false
    of the two: contact relations between objects that do not touch and "no contact" between
    objects that do, camera-frame sides beyond the opposite margin, near / far beyond their
    bands), and the two relations of a couple asked about another category pair, drawn from
    ``asked`` (how often the question's split asks each category pair and couple; then every
    split). Drawn from the same split, the other pair is as familiar to a model trained on
    the training split as the marked one. ``labels`` are object labels absent from the scene,
    used only when no other category pair is asked.
    """
    items = []
    for q in questions:
        a, b = q.a, q.b
        sources, _ = relation_sources(scene, view.camera, a, b, rule)
        if q.relation not in sources:
            continue
        la, lb = scene.objects[a].label, scene.objects[b].label
        dis = _relation_options(la, lb, q, asked, labels, rng)
        correct = _statement(la, q.relation, lb)
        if len(dis) != 3 or len({option_text(o) for o in [correct, *dis]}) != 4:
            continue
        prompt, letter, meta = _finish_mcq(
            RELATION_PROMPT, correct, dis, counts, rng,
            {"red": a, "blue": b, "relation": q.relation,
             "phrase": RELATION_PHRASES[q.relation], "source": sources[q.relation]})
        if sum(option_holds(scene, view, a, b, o, rule) for o in meta["options"]) != 1:
            counts[letter] -= 1
            continue
        items.append(Item("relation_mcq", prompt, letter, meta,
                          [("red", view.objects[a]["bbox"]), ("blue", view.objects[b]["bbox"])]))
    return items


def _weighted(table: dict, rng: np.random.Generator, exclude=()):
    """A key of ``table`` drawn with probability proportional to its count (None if none)."""
    keys = sorted(k for k in table if k not in exclude and table[k] > 0)
    if not keys:
        return None
    w = np.array([table[k] for k in keys], dtype=float)
    return keys[int(rng.choice(len(keys), p=w / w.sum()))]


def _contact(subject: str, sp: str, obj: str, op: str) -> dict[str, Any]:
    return {"kind": "contact", "subject": subject, "subject_part": sp, "object": obj,
            "object_part": op}


def _other_pair(la: str, lb: str, prior: ContactPrior, part_map: dict[str, list[str]],
                present: set[str], rng: np.random.Generator) -> list[dict[str, Any]]:
    """The second pair of options: another category pair (drawn by how often it is asked in
    the training split), touching through a part pair seen touching, and not in contact."""
    key = _weighted(prior.asked, rng, exclude={(min(la, lb), max(la, lb))})
    if key is not None:
        lc, ld = key if rng.random() < 0.5 else key[::-1]
        parts = _weighted(prior.part_pairs.get((lc, ld), {}), rng)
        if parts is not None:
            return [_contact(lc, parts[0], ld, parts[1]),
                    {"kind": "no_contact", "subject": lc, "object": ld}]
    # a dataset with a single category pair that touches: an absent category replaces one
    # of the two objects (false of the whole scene)
    absent = sorted(lab for lab, ps in part_map.items() if lab not in present and ps)
    if not absent:
        return []
    lab = absent[int(rng.integers(len(absent)))]
    part = part_map[lab][int(rng.integers(len(part_map[lab])))]
    pairs = prior.part_pairs.get((la, lb), {})
    sp, op = next(iter(sorted(pairs))) if pairs else (part, part)
    if rng.random() < 0.5:
        return [_contact(lab, part, lb, op), {"kind": "no_contact", "subject": lab,
                                                "object": lb}]
    return [_contact(la, sp, lab, part), {"kind": "no_contact", "subject": la, "object": lab}]


def contact_items(scene: SceneFacts, view: ViewFacts, plan: list[ContactCandidate],
                  prior: ContactPrior, part_map: dict[str, list[str]], rule: VisibilityRule,
                  counts: dict[str, int], rng: np.random.Generator) -> list[Item]:
    """Part-contact MCQs of one view, about the pairs ``plan`` chose
    (:func:`parse3d.vlm.balance.plan_contact_questions`).

    Four options (:mod:`parse3d.vlm.balance`): for the marked objects' categories (A, B), a
    part contact and "not in contact" — one of them true: the touching part pair when they
    touch (a pair of visible parts from ``contacts.json``), else "not in contact" beside a
    part pair that touches between such objects elsewhere (``prior.part_pairs``) — and the
    same two for another category pair (C, D) drawn from ``prior.asked``, false of the
    marked objects.
    """
    present = {o.label for o in scene.objects.values()}
    items = []
    for cand in plan:
        a, b = cand.a, cand.b
        if rng.random() < 0.5:
            a, b = b, a
        oa, ob = scene.objects[a], scene.objects[b]
        la, lb = oa.label, ob.label
        no_contact = {"kind": "no_contact", "subject": la, "object": lb}
        if cand.touching:
            va, vb = visible_parts(scene, view, a), visible_parts(scene, view, b)
            pairs = sorted((pa, pb) for pa, pb in scene.contacts[(a, b)] if pa in va and pb in vb)
            pa, pb = pairs[int(rng.integers(len(pairs)))]
            correct = _contact(la, oa.parts[pa], lb, ob.parts[pb])
            dis = [no_contact]
        else:
            seen = _weighted(prior.part_pairs.get((la, lb), {}), rng)
            if seen is None:
                continue
            correct = no_contact
            dis = [_contact(la, seen[0], lb, seen[1])]
        dis += _other_pair(la, lb, prior, part_map, present, rng)
        texts = {option_text(o) for o in [correct, *dis]}
        if len(dis) != 3 or len(texts) != 4:
            continue
        prompt, letter, meta = _finish_mcq(
            CONTACT_PROMPT, correct, dis, counts, rng,
            {"red": a, "blue": b, "relation": "contact" if cand.touching else "no contact",
             "source": "contacts"})
        if sum(option_holds(scene, view, a, b, o, rule) for o in meta["options"]) != 1:
            counts[letter] -= 1
            continue
        items.append(Item("contact_mcq", prompt, letter, meta,
                          [("red", view.objects[a]["bbox"]), ("blue", view.objects[b]["bbox"])]))
    return items


def format_box(box: list[int]) -> str:
    """``<|box_start|>x1, y1, x2, y2<|box_end|>`` (0-1000 grid)."""
    return "<|box_start|>" + ", ".join(str(int(v)) for v in box) + "<|box_end|>"


def sgg_triplets(scene: SceneFacts, view: ViewFacts, rule: VisibilityRule
                 ) -> list[tuple[str, str, str, str]]:
    """The scene graph of a view: every true relation between two visible objects.

    For every ordered pair of visible objects, the relations :func:`relation_sources` finds
    true, each with its derivation; ``no contact`` is left out (it is the absence of an
    edge), camera-frame relations are given in their canonical direction (``left of``,
    ``in front of``; the inverse is the same triplet turned around) and a symmetric relation
    once per pair (subject first by id).

    Returns
    -------
    list of (subject id, RELATION, object id, derivation), sorted.
    """
    out: set[tuple[str, str, str, str]] = set()
    vis = sorted(view.objects)
    for a in vis:
        for b in vis:
            if a == b:
                continue
            true, _ = relation_sources(scene, view.camera, a, b, rule)
            for r, how in true.items():
                if r == NO_CONTACT or r in INVERSE_RELATIONS:
                    continue
                if r in SYMMETRIC_RELATIONS and a > b:
                    continue
                out.add((a, r, b, how))
    return sorted(out)


#: An SGG box is the projected 3-D box unless less than this share of it lies in the image;
#: then the visible mask's tight box (a projected box mostly outside the image, clipped,
#: covers whatever neighbour is at the border).
MIN_BOX_IN_IMAGE = 0.5


def _answer_graph(scene: SceneFacts, holds: list[tuple[str, str, str, str]]
                  ) -> list[tuple[str, str, str, str]]:
    """The scene graph an SGG answer lists: of the relations that hold, every contact and PAG
    relation, and the camera-frame and distance relations between each object and its
    nearest visible neighbour (horizontal centroid distance). Every relation that holds is
    kept in ``meta.holds``, against which predictions are judged true or false."""
    objs = sorted({t[0] for t in holds} | {t[2] for t in holds})
    nearest: set[frozenset[str]] = set()
    for a in objs:
        others = [b for b in objs if b != a]
        if others:
            ca = scene.objects[a].centroid[:2]
            b = min(others, key=lambda b: (float(np.linalg.norm(scene.objects[b].centroid[:2]
                                                                 - ca)), b))
            nearest.add(frozenset((a, b)))
    return [t for t in holds
            if t[3] not in ("camera", "distance") or frozenset((t[0], t[2])) in nearest]


def _in_image(px: list[float], width: int, height: int) -> float:
    """Share of a pixel box's area inside the image."""
    x1, y1, x2, y2 = px
    area = max(x2 - x1, 0.0) * max(y2 - y1, 0.0)
    if area <= 0:
        return 0.0
    ix = max(min(x2, width) - max(x1, 0.0), 0.0)
    iy = max(min(y2, height) - max(y1, 0.0), 0.0)
    return ix * iy / area


def sgg_item(scene: SceneFacts, view: ViewFacts, candidates: list[str], rule: VisibilityRule,
             *, boxes: str = "projected") -> Item | None:
    """The scene-graph item of a view (None when no object is visible).

    Parameters
    ----------
    boxes : str
        ``projected`` (the paper: the 3-D oriented box projected into the image, except where
        less than :data:`MIN_BOX_IN_IMAGE` of it lies in the image: then the mask's box) or
        ``mask`` (the tight box of the visible mask). Each object records ``box_from``.
    """
    if not view.objects:
        return None
    cam = view.camera
    rows = []
    for oid, rec in view.objects.items():
        x1, y1, x2, y2 = rec["bbox"]
        px, how = [x1, y1, x2 + 1, y2 + 1], "mask"
        if boxes != "mask":
            full = projected_box(cam, scene.objects[oid].corners, clip=False)
            if full is not None and _in_image(full, cam.width, cam.height) >= MIN_BOX_IN_IMAGE:
                px, how = projected_box(cam, scene.objects[oid].corners), "projected"
        rows.append((oid, to_grid(px, cam.width, cam.height), how))
    if not rows:
        return None
    rows.sort(key=lambda r: (scene.objects[r[0]].label, r[1][0], r[1][1], r[0]))
    names: dict[str, str] = {}
    seen: dict[str, int] = {}
    objects = []
    for oid, g, how in rows:
        lab = scene.objects[oid].label
        seen[lab] = seen.get(lab, 0) + 1
        names[oid] = f"{lab}#{seen[lab]}"
        objects.append({"name": names[oid], "label": lab, "object": oid, "box": g,
                        "box_from": how})
    holds = [t for t in sgg_triplets(scene, view, rule) if t[0] in names and t[2] in names]
    graph = _answer_graph(scene, holds)
    triplets = [[names[s], RELATION_PHRASES[r], names[o]] for s, r, o, _ in graph]
    answer = "Objects:\n" + "\n".join(f"{o['name']} {format_box(o['box'])}" for o in objects)
    answer += "\nRelations:\n" + "\n".join(f"({s}, {r}, {o})" for s, r, o in triplets)
    rels = [RELATION_PHRASES[r] for r in RELATION_PHRASES
            if r not in CAMERA_RELATIONS[1::2] and r != NO_CONTACT]
    prompt = SGG_PROMPT.format(objects=", ".join(candidates), relations=", ".join(rels))
    return Item("sgg", prompt, answer.rstrip(), {"objects": objects, "triplets": triplets,
                                                  "sources": [t[3] for t in graph],
                                                  "holds": [[names[s], RELATION_PHRASES[r],
                                                             names[o]]
                                                            for s, r, o, _ in holds],
                                                  "boxes": boxes})
