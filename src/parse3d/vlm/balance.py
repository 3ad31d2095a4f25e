"""Which part-contact questions to ask, chosen over a whole split so that text cannot answer.

A part-contact question names two objects (the red and the blue box) and offers four
statements. Asked naively, the text gives the answer away: which part pairs touch is nearly
fixed by the two categories (a table lamp's base on a nightstand's top panel), so the
plausible option is the answer. Here every question offers the same kind of four options

    the P of the A contacts the Q of the B      the A and the B are not in contact
    the P' of the C contacts the Q' of the D    the C and the D are not in contact

where (A, B) are the marked objects' categories and (C, D) another category pair drawn by how
often it is asked in the training split. Exactly one is true: for (A, B), the contact or its
absence (``contacts.json``); (C, D) names other objects. The part pairs are contacts seen
between objects of those categories in other scenes of the training split (when the marked
objects do not touch, the shown pair is such a contact: plausible, and false by the
geometry). So that "touching" and "not in contact" are equally likely for every category
pair, questions are chosen per split and category pair: as many about touching pairs as about
pairs that do not touch, drawn from all of the split's visible pairs.

The relation MCQ is chosen the same way, per category pair and *couple* of relations that
exclude each other by the geometry (:data:`RELATION_COUPLES`: a contact relation and "no
contact", ``left of`` and ``right of``, ``in front of`` and ``behind``, ``near`` and ``far
from``). A question about the couple (R, R') of marked objects with categories (A, B) offers

    A R B      A R' B      C S D      C S' D

where one of "A R B", "A R' B" holds and the other is false by the geometry, and (C, D, S, S')
is another category pair and couple drawn by how often the training split asks it. Per split,
category pair (ordered: red, blue) and couple, as many questions answer R as answer R', so
each option's text is the answer about a quarter of the times it is shown. Relations without
a test that can make them false (``facing``, ``aligned with``, ...) can never be a distractor
and are not asked (they stay in the scene graphs).

Everything here is data in, data out; the builder reads the scenes and writes the items.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from dataclasses import dataclass, field

import numpy as np

from .facts import SceneFacts, ViewFacts, VisibilityRule, pair_truth
from .vocab import CONTACT_RELATIONS, NO_CONTACT

__all__ = ["ContactCandidate", "ContactPrior", "RELATION_COUPLES", "RelationCandidate", "RelationKey",
           "RelationQuestion", "contact_candidates", "contact_counts", "plan_contact_questions",
           "contact_prior", "relation_candidates", "plan_relation_questions", "relation_asked",
           "visible_parts"]

LabelPair = tuple[str, str]


@dataclass(frozen=True)
class ContactCandidate:
    """A pair of visible objects in one view that a part-contact question may ask about.

    Attributes
    ----------
    scene : str
    view : int
    a, b : str
        Object ids (``a < b``).
    labels : (str, str)
        Their category labels, in the order ``a``, ``b``.
    touching : bool
        Whether the two touch through parts that are both visible (pairs that touch only
        through hidden parts are no candidates).
    """

    scene: str
    view: int
    a: str
    b: str
    labels: LabelPair
    touching: bool

    @property
    def key(self) -> LabelPair:
        """The unordered category pair (sorted labels)."""
        return (min(self.labels), max(self.labels))


@dataclass
class ContactPrior:
    """What the training split says about contacts, for one scene's questions.

    Attributes
    ----------
    part_pairs : dict
        ``(subject label, object label) -> {(subject part, object part): count}``: part
        pairs that touch between objects of these categories in other scenes (the training
        split first; other splits, then the scene itself, only for a pair never seen there).
    asked : dict
        ``(label, label) sorted -> questions``: how often each category pair is asked in the
        training split (the draw of the other pair of options).
    """

    part_pairs: dict[LabelPair, dict[LabelPair, int]] = field(default_factory=dict)
    asked: dict[LabelPair, int] = field(default_factory=dict)


def visible_parts(scene: SceneFacts, view: ViewFacts, oid: str) -> set[str]:
    """The names of an object's parts that are visible in a view."""
    return {n for n in scene.objects[oid].parts if f"{oid}:{n}" in view.parts}


def contact_candidates(scene: SceneFacts, view: ViewFacts) -> list[ContactCandidate]:
    """Every pair of visible objects of a view that touch through visible parts or do not
    touch at all."""
    vis = sorted(view.objects)
    out = []
    for i, a in enumerate(vis):
        for b in vis[i + 1:]:
            labels = (scene.objects[a].label, scene.objects[b].label)
            if (a, b) not in scene.contacts:
                out.append(ContactCandidate(scene.name, view.index, a, b, labels, False))
                continue
            va, vb = visible_parts(scene, view, a), visible_parts(scene, view, b)
            if any(pa in va and pb in vb for pa, pb in scene.contacts[(a, b)]):
                out.append(ContactCandidate(scene.name, view.index, a, b, labels, True))
    return out


def contact_counts(scene: SceneFacts) -> Counter:
    """Touching part pairs of a scene by label: ``(la, pa, lb, pb) -> count``, both ways."""
    c: Counter = Counter()
    for (a, b), pairs in scene.contacts.items():
        oa, ob = scene.objects[a], scene.objects[b]
        for pa, pb in pairs:
            c[(oa.label, oa.parts.get(pa, pa), ob.label, ob.parts.get(pb, pb))] += 1
    return c


def plan_contact_questions(candidates: list[ContactCandidate], *, per_view: int,
                           rng: np.random.Generator) -> list[ContactCandidate]:
    """The questions of one split: for every category pair, as many touching pairs as pairs
    that do not touch (the smaller of the two counts), at most ``per_view`` of each kind per
    view. Deterministic for the candidates' order and the generator."""
    by_key: dict[LabelPair, tuple[list, list]] = defaultdict(lambda: ([], []))
    for c in candidates:
        by_key[c.key][0 if c.touching else 1].append(c)
    used: Counter = Counter()
    out = []
    for key in sorted(by_key):
        touch, apart = by_key[key]
        if not touch or not apart:
            continue
        picked: list[list[ContactCandidate]] = [[], []]
        for kind, pool in enumerate((touch, apart)):
            for i in rng.permutation(len(pool)):
                c = pool[int(i)]
                if used[(c.scene, c.view, kind)] < per_view:
                    picked[kind].append(c)
                    used[(c.scene, c.view, kind)] += 1
        n = min(len(picked[0]), len(picked[1]))
        for kind in (0, 1):
            for c in picked[kind][n:]:  # give the view's slot back
                used[(c.scene, c.view, kind)] -= 1
            out += picked[kind][:n]
    return out


def contact_prior(scene: str, counts: dict[str, Counter], splits: dict[str, str],
                  asked: dict[LabelPair, int]) -> ContactPrior:
    """The prior one scene's questions draw their options from.

    Parameters
    ----------
    scene : str
        The scene whose questions these are (its own contacts are used only for a category
        pair seen nowhere else).
    counts : dict
        Scene name -> :func:`contact_counts`.
    splits : dict
        Scene name -> ``train`` / ``val`` / ``test``.
    asked : dict
        Sorted category pair -> questions in the training split.
    """
    layers: list[Counter] = [Counter(), Counter(), Counter()]
    for name, c in counts.items():
        layers[0 if name != scene and splits[name] == "train" else
               1 if name != scene else 2].update(c)
    part_pairs: dict[LabelPair, dict[LabelPair, int]] = {}
    for layer in layers:
        found: dict[LabelPair, dict[LabelPair, int]] = defaultdict(dict)
        for (la, pa, lb, pb), n in layer.items():
            if (la, lb) not in part_pairs:
                found[(la, lb)][(pa, pb)] = n
        part_pairs.update(found)
    return ContactPrior(part_pairs, dict(asked))


#: Couples of relations the relation MCQ asks about: where one holds, the other is false by
#: the same geometric test (a contact relation needs a contact, "no contact" its absence; the
#: camera-frame sides their margins; ``near`` < 0.9 m, ``far from`` > 2.2 m).
RELATION_COUPLES: tuple[tuple[str, str], ...] = (
    *((r, NO_CONTACT) for r in CONTACT_RELATIONS),
    ("LEFT_OF", "RIGHT_OF"), ("IN_FRONT_OF", "BEHIND"), ("NEAR", "FAR_FROM"))

_FAMILY = {**dict.fromkeys(CONTACT_RELATIONS, 0), "NEAR": 1, "LEFT_OF": 2, "IN_FRONT_OF": 2}

#: ``(red label, blue label, R, R')``: a category pair (ordered) and a couple.
RelationKey = tuple[str, str, str, str]


@dataclass(frozen=True)
class RelationCandidate:
    """An ordered pair of visible objects of one view and the couples it can be asked about.

    Attributes
    ----------
    scene : str
    view : int
    a, b : str
        Object ids: ``a`` is marked red (the subject), ``b`` blue.
    labels : (str, str)
        Their category labels.
    answers : tuple of (int, str)
        ``(couple index, relation)`` for every couple of :data:`RELATION_COUPLES` one of
        whose relations holds of "a REL b" while the other is false.
    """

    scene: str
    view: int
    a: str
    b: str
    labels: LabelPair
    answers: tuple[tuple[int, str], ...]


@dataclass(frozen=True)
class RelationQuestion:
    """A relation MCQ before its options: "``a`` ``relation`` ``b``" holds, "``a`` ``other``
    ``b``" is false (the two form a couple of :data:`RELATION_COUPLES`)."""

    scene: str
    view: int
    a: str
    b: str
    relation: str
    other: str
    key: RelationKey


def relation_candidates(scene: SceneFacts, view: ViewFacts, rule: VisibilityRule
                        ) -> list[RelationCandidate]:
    """Every ordered pair of visible objects of a view with a couple it can be asked about."""
    vis = sorted(view.objects)
    out = []
    for a in vis:
        for b in vis:
            if a == b:
                continue
            true, undecided = pair_truth(scene, view.camera, a, b, rule)
            answers = []
            for i, (r, r2) in enumerate(RELATION_COUPLES):
                for yes, no in ((r, r2), (r2, r)):
                    if yes in true and no not in true and no not in undecided:
                        answers.append((i, yes))
            if answers:
                out.append(RelationCandidate(scene.name, view.index, a, b,
                                             (scene.objects[a].label, scene.objects[b].label),
                                             tuple(answers)))
    return out


def plan_relation_questions(candidates: list[RelationCandidate], *, per_view: int,
                            rng: np.random.Generator) -> list[RelationQuestion]:
    """The relation questions of one split: for every category pair (red, blue) and couple
    (R, R'), as many questions answering R as answering R' (the smaller of the two counts),
    at most ``per_view`` questions per view and one per pair of objects. The couples choose
    in the order of :data:`RELATION_COUPLES` by family (contact relations, then near / far,
    then the camera-frame sides, which nearly every pair can answer and would otherwise take
    every view's slots), scarce keys first within a family. Deterministic for the
    candidates' order and the generator."""
    by_key: dict[RelationKey, tuple[list, list]] = defaultdict(lambda: ([], []))
    for c in candidates:
        for i, rel in c.answers:
            r, r2 = RELATION_COUPLES[i]
            by_key[(*c.labels, r, r2)][0 if rel == r else 1].append(c)
    keys = sorted((_FAMILY[key[2]], min(len(s0), len(s1)), key)
                  for key, (s0, s1) in by_key.items())
    used: Counter = Counter()
    pairs: set[tuple[str, int, frozenset[str]]] = set()
    out = []
    for _, n_min, key in keys:
        if n_min == 0:
            continue
        sides = by_key[key]
        order = [iter(rng.permutation(len(pool))) for pool in sides]

        def take(side: int, sides=sides, order=order) -> RelationCandidate | None:
            for i in order[side]:
                c = sides[side][int(i)]
                pair = (c.scene, c.view, frozenset((c.a, c.b)))
                if used[(c.scene, c.view)] < per_view and pair not in pairs:
                    used[(c.scene, c.view)] += 1
                    pairs.add(pair)
                    return c
            return None

        # one of each side at a time (the two orders of a pair of objects of one category,
        # "chair 1 left of chair 2" and "chair 2 right of chair 1", compete for the pair)
        while (c0 := take(0)) is not None:
            c1 = take(1)
            if c1 is None:  # give the view's slot and the pair back
                used[(c0.scene, c0.view)] -= 1
                pairs.discard((c0.scene, c0.view, frozenset((c0.a, c0.b))))
                break
            out += [RelationQuestion(c0.scene, c0.view, c0.a, c0.b, key[2], key[3], key),
                    RelationQuestion(c1.scene, c1.view, c1.a, c1.b, key[3], key[2], key)]
    return out


def relation_asked(questions: list[RelationQuestion]) -> dict[RelationKey, int]:
    """How often each category pair and couple is asked (the draw of the other pair of
    options)."""
    return dict(Counter(q.key for q in questions))
