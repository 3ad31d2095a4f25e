"""The fixed vocabulary of the VLM benchmark: relations, object and part labels, synonyms.

One vocabulary is shared by the relation MCQ, the part-contact MCQ and scene-graph
generation (SGG). Its relations are

* the PAG relations (:mod:`parse3d.relations`) that hold after settling, named by their
  short phrase (``on``, ``against``, ``leaning against``, ``near``, ...);
* four camera-frame relations, measured on the objects' centroids in the view's camera
  frame: ``left of``, ``right of``, ``in front of`` (closer to the camera) and ``behind``;
* ``no contact``: the two objects share no part-level contact (``contacts.json``).

Examples
--------
>>> RELATION_PHRASES["ON"], RELATION_PHRASES["LEFT_OF"]
('on', 'left of')
>>> normalize_relation("to the left of")
'left of'
>>> normalize_object("couch")
'sofa'
"""

from __future__ import annotations

import functools
import re
from types import MappingProxyType

from ..relations import RELATIONS

__all__ = [
    "CAMERA_RELATIONS",
    "CONTACT_RELATIONS",
    "GEOMETRIC_RELATIONS",
    "NO_CONTACT",
    "RELATION_PHRASES",
    "PHRASE_TO_RELATION",
    "OBJECT_SYNONYMS",
    "RELATION_SYNONYMS",
    "INVERSE_RELATIONS",
    "object_label",
    "part_label",
    "normalize_object",
    "normalize_relation",
    "relation_sentence",
]

NO_CONTACT = "NO_CONTACT"

#: Measured in the camera frame of each view.
CAMERA_RELATIONS = ("LEFT_OF", "RIGHT_OF", "IN_FRONT_OF", "BEHIND")

#: PAG relations that need the two objects to touch: false whenever they share no contact.
CONTACT_RELATIONS = ("ON", "IN", "HANGING_BELOW", "SECURED_TO", "AGAINST", "LEANING_AGAINST")

#: PAG relations decided from the centroids when the PAG does not state them.
GEOMETRIC_RELATIONS = ("NEAR", "FAR_FROM")

_CAMERA_PHRASES = {"LEFT_OF": "left of", "RIGHT_OF": "right of", "IN_FRONT_OF": "in front of",
                   "BEHIND": "behind", NO_CONTACT: "no contact"}

#: Vocabulary key -> the phrase used in prompts, options and scene graphs.
RELATION_PHRASES: MappingProxyType[str, str] = MappingProxyType(
    {**{name: r.phrase for name, r in RELATIONS.items()}, **_CAMERA_PHRASES})

PHRASE_TO_RELATION: MappingProxyType[str, str] = MappingProxyType(
    {v: k for k, v in RELATION_PHRASES.items()})

#: "A left of B" is "B right of A": the scene-graph metrics compare the canonical form.
INVERSE_RELATIONS: MappingProxyType[str, str] = MappingProxyType(
    {"RIGHT_OF": "LEFT_OF", "BEHIND": "IN_FRONT_OF"})

#: Model outputs that mean a vocabulary relation (after lower-casing and trimming).
RELATION_SYNONYMS: MappingProxyType[str, str] = MappingProxyType({
    "on top of": "on", "on the top of": "on", "resting on": "on", "rests on": "on",
    "sitting on": "on", "standing on": "on", "placed on": "on", "lying on": "on",
    "supported by": "on", "above": "on",
    "inside": "in", "inside of": "in", "within": "in", "contained in": "in", "in the": "in",
    "hangs below": "hanging below", "hanging from": "hanging below", "below": "hanging below",
    "under": "hanging below", "suspended from": "hanging below",
    "fixed to": "mounted on", "attached to": "mounted on", "secured to": "mounted on",
    "mounted to": "mounted on", "hung on": "mounted on",
    "pushed against": "against", "touching": "against", "next to wall": "against",
    "leans against": "leaning against", "leaning on": "leaning against",
    "flush with": "aligned with", "aligned to": "aligned with",
    "back to back with": "opposite to", "opposite": "opposite to",
    "faces the same way as": "parallel to", "parallel with": "parallel to",
    "next to": "beside", "beside of": "beside", "by": "beside", "on one side of": "beside",
    "lined up along": "along",
    "close to": "near", "nearby": "near", "near to": "near",
    "far away from": "far from", "distant from": "far from",
    "faces": "facing", "facing towards": "facing", "facing toward": "facing",
    "toward": "facing", "towards": "facing",
    "to the left of": "left of", "on the left of": "left of", "left": "left of",
    "left side of": "left of", "on the left side of": "left of",
    "to the right of": "right of", "on the right of": "right of", "right": "right of",
    "right side of": "right of", "on the right side of": "right of",
    "in front": "in front of", "front of": "in front of", "before": "in front of",
    "closer than": "in front of",
    "behind of": "behind", "in back of": "behind", "back of": "behind",
    "farther than": "behind",
    "not touching": "no contact", "not in contact with": "no contact",
    "no contact with": "no contact", "not in contact": "no contact",
})

#: Object names a model may use -> the benchmark's label (the category with spaces). Checked
#: first (it settles what a hypernym such as "chair" counts as in the benchmark); then the
#: synonyms of the package's vocabulary file (``parse3d/data/vocabulary.json``).
OBJECT_SYNONYMS: MappingProxyType[str, str] = MappingProxyType({
    "couch": "sofa", "settee": "sofa", "television": "tv", "tv set": "tv",
    "bedside table": "nightstand", "night stand": "nightstand", "bedside cabinet": "nightstand",
    "cupboard": "storage cabinet", "cabinet": "storage cabinet", "closet": "wardrobe",
    "armoire": "wardrobe", "bookshelf": "bookcase", "book shelf": "bookcase",
    "shelf": "wall shelf", "computer monitor": "monitor", "screen": "monitor",
    "display": "monitor", "coffee cup": "mug", "teacup": "tea cup", "plate dish": "plate",
    "dish": "plate", "lamp": "table lamp", "desk lamp": "table lamp",
    "standing lamp": "floor lamp", "ceiling lamp": "pendant lamp", "hanging lamp": "pendant lamp",
    "desk chair": "office chair", "swivel chair": "office chair", "chair": "dining chair",
    "easy chair": "armchair", "stool": "bar stool", "carpet": "rug", "mat": "rug",
    "painting": "picture frame", "picture": "picture frame", "photo frame": "picture frame",
    "poster": "picture frame", "plant": "potted plant", "houseplant": "potted plant",
    "bin": "trash can", "garbage can": "trash can", "waste bin": "trash can",
    "dustbin": "trash can", "fridge": "refrigerator", "laptop computer": "laptop",
    "notebook computer": "laptop", "tub": "bathtub", "bath": "bathtub",
    "kitchen table": "dining table", "table": "dining table", "work desk": "desk",
    "writing desk": "desk", "novel": "book", "cushion": "pillow", "pan": "frying pan",
    "pot": "cooking pot", "saucepan": "cooking pot", "clock": "wall clock",
    "washer": "washing machine", "glass": "wine glass", "remote": "remote control",
    "end table": "side table", "box": "storage box", "drawers": "dresser",
    "chest of drawers": "dresser", "counter": "kitchen counter", "cooker": "stove",
    "oven": "stove", "loudspeaker": "speaker", "hamper": "laundry basket",
})

_SPACES = re.compile(r"[\s_]+")


def object_label(category: str) -> str:
    """The label of a category in prompts: ``office_chair`` -> ``office chair``."""
    return _SPACES.sub(" ", category).strip()


def part_label(label: str) -> str:
    """The label of a part in prompts: ``front_cover`` -> ``front cover``."""
    return _SPACES.sub(" ", label).strip()


def _clean(text: str) -> str:
    t = _SPACES.sub(" ", str(text).lower()).strip(" .,:;!?\"'`*()[]")
    return re.sub(r"^(the|a|an) ", "", t)


def _shared_resolver(known: frozenset[str]):
    """The project's shared vocabulary resolver over ``known`` labels, or None where the
    shared vocabulary module is not part of this installation."""
    try:
        from ..words import Resolver
    except ImportError:
        return None
    return Resolver({k.replace(" ", "_"): () for k in known})


def normalize_object(name: str, known: frozenset[str] | set[str] = frozenset()) -> str:
    """A model's object name -> the benchmark label: case, articles, plurals, synonyms.

    ``known`` are the benchmark's labels (an SGG split's object labels): a plural of one of
    them (``books``, ``shelves``, ``glasses``) is its singular. The synonym table
    :data:`OBJECT_SYNONYMS` applies to a name and its singular, then the shared vocabulary's
    synonyms where that module is installed. Unknown names come back cleaned (lower case,
    single spaces, no article), so they simply never match.

    >>> normalize_object("Books", {"book"}), normalize_object("the couches")
    ('book', 'sofa')
    """
    t = _clean(name)
    if t in known:
        return t
    from ..words import lexicon, normalize, singulars

    # the shared vocabulary's plural rule, on the label's words (``coffee tables``)
    for c in (t, *(x.replace("_", " ") for x in singulars(t.replace(" ", "_")))):
        if c in known:
            return c
        if c in OBJECT_SYNONYMS:
            return OBJECT_SYNONYMS[c]
    if known:
        r = _resolver(frozenset(known))
        if r is not None:
            hits = {c.replace("_", " ") for c in r.categories_for(t) or ()} & set(known)
            if len(hits) == 1:
                return hits.pop()
    # the package's vocabulary file: a synonym naming one category (``bookshelf``, ``fridge``)
    lex = lexicon()
    w = normalize(t)
    for form in (w, *singulars(w)):
        target = lex.synonyms.get(form)
        members = lex.hypernyms.get(target, (target,))
        if target is not None and len(members) == 1:  # one category, not a kind of several
            return object_label(members[0])
    return t


_resolver = functools.lru_cache(maxsize=8)(_shared_resolver)


def normalize_relation(phrase: str) -> str | None:
    """A model's relation phrase -> the vocabulary phrase, or None when it is not one."""
    t = _clean(phrase)
    t = re.sub(r"^is ", "", t)
    if t in PHRASE_TO_RELATION:
        return t
    if t in RELATION_SYNONYMS:
        return RELATION_SYNONYMS[t]
    return None


def relation_sentence(subject: str, relation: str, obj: str) -> str:
    """An MCQ option: ``the mug is on the desk``; ``the mug has no contact with the desk``."""
    if relation == NO_CONTACT:
        return f"the {subject} has no contact with the {obj}"
    return f"the {subject} is {RELATION_PHRASES[relation]} the {obj}"
