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

The relation MCQ borrows half of this: its options are the answer and a relation false of
the marked pair, and two statements about another category pair, all drawn by how often the
training split answers them (:class:`RelationPrior`). Its questions are not yet chosen per
category pair and relation, so the answer and the false relation can still differ in how
plausible they are.

Everything here is data in, data out; the builder reads the scenes and writes the items.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from dataclasses import dataclass, field

import numpy as np

from .facts import SceneFacts, ViewFacts

__all__ = ["ContactCandidate", "ContactPrior", "RelationPrior", "relation_prior", "contact_candidates", "contact_counts",
           "plan_contact_questions", "contact_prior", "visible_parts"]

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


@dataclass
class RelationPrior:
    """What the training split answers in its relation MCQ, for one scene's options.

    Attributes
    ----------
    statements : dict
        ``(subject label, RELATION, object label) -> answers`` in other scenes of the
        training split (other splits only when it has none).
    pairs : dict
        ``(subject label, object label) -> answers``.
    relations : dict
        ``RELATION -> answers``.
    """

    statements: dict[tuple[str, str, str], int] = field(default_factory=dict)
    pairs: dict[LabelPair, int] = field(default_factory=dict)
    relations: dict[str, int] = field(default_factory=dict)


def relation_prior(scene: str, answers: dict[str, Counter], splits: dict[str, str]
                   ) -> RelationPrior:
    """The prior one scene's relation options draw from: the answers (``(la, REL, lb) ->
    count`` per scene name) of the other training scenes, or of every other scene when the
    training split has none besides this one."""
    total: Counter = Counter()
    for name, c in answers.items():
        if name != scene and splits[name] == "train":
            total.update(c)
    if not total:
        for name, c in answers.items():
            if name != scene:
                total.update(c)
    pairs: Counter = Counter()
    relations: Counter = Counter()
    for (la, r, lb), n in total.items():
        pairs[(la, lb)] += n
        relations[r] += n
    return RelationPrior(dict(total), dict(pairs), dict(relations))
