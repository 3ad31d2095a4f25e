"""The bundled templates as a dataset sees them: a 200-scene expansion (as ``dataset build``
plans it, no solving) keeps every category under 8% of all objects and uses every category;
each room type draws on at least five motifs that no other room type uses; no sentence repeats
across template descriptions.
"""

from __future__ import annotations

import collections
import functools
import re

import numpy as np

from parse3d.assets import registry
from parse3d.datagen import templates as T

SCENES = 200
MAX_SHARE = 0.08


@functools.cache
def _expansion() -> tuple[collections.Counter, int]:
    """Category counts over a 200-scene plan: room types cycle, a template and a scene seed are
    drawn per index from ``default_rng([0, index])`` (the dataset builder's plan). An object
    with candidate categories counts a share for each candidate (the solver picks one)."""
    by_room = collections.defaultdict(list)
    for t in T.list_templates():
        by_room[t.room_type].append(t)
    rooms = sorted(by_room)
    counts: collections.Counter = collections.Counter()
    total = 0
    for i in range(SCENES):
        names = sorted(by_room[rooms[i % len(rooms)]], key=lambda t: t.name)
        rng = np.random.default_rng([0, i])
        t = names[int(rng.integers(len(names)))]
        pag = T.expand_template(t, int(rng.integers(2**31 - 1)))
        for o in pag.objects.values():
            cats = list(o.category) if isinstance(o.category, (list, tuple)) else [o.category]
            for c in cats:
                counts[c] += 1 / len(cats)
            total += 1
    return counts, total


def test_no_category_dominates_a_200_scene_expansion() -> None:
    counts, total = _expansion()
    assert total > 40 * SCENES  # rooms are dense (the paper: about 50 objects per scene)
    top, n = counts.most_common(1)[0]
    assert n / total <= MAX_SHARE, f"{top} is {n / total:.1%} of all objects"


def test_every_category_is_used() -> None:
    counts, _ = _expansion()
    unused = sorted(set(registry.categories()) - set(counts))
    assert not unused, unused


def test_each_room_type_has_five_motifs_of_its_own() -> None:
    users = collections.defaultdict(set)
    for t in T.list_templates():
        for m in t.data.get("motifs", []):
            users[m["motif"]].add(t.room_type)
    own = collections.Counter(next(iter(r)) for r in users.values() if len(r) == 1)
    rooms = {t.room_type for t in T.list_templates()}
    assert len(rooms) == 17
    short = {r: own[r] for r in rooms if own[r] < 5}
    assert not short, short


def test_no_sentence_repeats_across_template_descriptions() -> None:
    seen: dict[str, str] = {}
    for t in T.list_templates():
        for s in re.split(r"(?<=[.!?;:])\s+", t.data.get("description", "").strip()):
            key = re.sub(r"\s+", " ", s.strip().lower())
            if key:
                assert key not in seen, f"{t.name} repeats a sentence of {seen[key]}: {s!r}"
                seen[key] = t.name
