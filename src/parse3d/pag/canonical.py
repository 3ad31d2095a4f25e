"""A PAG document with its words resolved: categories and part labels as the asset library
names them (see :mod:`parse3d.words`). The solver solves the canonical document; scene.json
records it, so each object's category there is the member a hypernym drew.
"""

from __future__ import annotations

from typing import Any

from ..words import Resolver
from .refs import format_ref, parse_ref

__all__ = ["canonical_document"]


def canonical_document(data: dict[str, Any], resolver: Resolver) -> dict[str, Any]:
    """A valid ``pag/1`` document with every word resolved: categories are categories
    (a hypernym becomes the list of its members that have every part the relations name) and
    part words are labels. The input is not changed; unchanged documents come back as given.

    Parameters
    ----------
    data : dict
        A document that validates against ``resolver`` (see :func:`parse3d.pag.validate`).
    resolver : Resolver
    """
    objects = data.get("objects") or []
    rels = data.get("relations") or []
    parsed = []
    named: dict[str, set[str]] = {}
    for r in rels:
        refs = {}
        for side in ("child", "parent"):
            ref = parse_ref(r[side])
            refs[side] = ref
            if ref.part is not None:
                named.setdefault(ref.object, set()).add(ref.part)
        parsed.append(refs)
    cands: dict[str, tuple[str, ...]] = {}
    new_objects = []
    changed = False
    for o in objects:
        written = [o["category"]] if isinstance(o["category"], str) else list(o["category"])
        out: list[str] = []
        for c in written:
            got = resolver.categories_for(c) or (c,)
            if resolver.is_hypernym(c) and named.get(o["id"]):
                # a hypernym's members that have every part the relations name
                keep = tuple(m for m in got
                             if all(resolver.names_part(m, p) for p in named[o["id"]]))
                got = keep or got
            out += [m for m in got if m not in out]
        cat: Any = out[0] if len(out) == 1 and isinstance(o["category"], str) else out
        if cat != o["category"]:
            changed = True
            o = {**o, "category": cat}
        cands[o["id"]] = tuple(out)
        new_objects.append(o)
    new_rels = []
    for r, refs in zip(rels, parsed, strict=True):
        r2 = r
        for side, ref in refs.items():
            if ref.part is None or ref.object not in cands:
                continue
            labels = {resolver.part(c, ref.part, ref.surface).label for c in cands[ref.object]}
            labels.discard(None)
            if len(labels) == 1 and (label := labels.pop()) != ref.part:
                r2 = {**r2, side: format_ref(ref.object, label, ref.index, ref.surface)}
        if r2 is not r:
            changed = True
        new_rels.append(r2)
    if not changed:
        return data
    return {**data, "objects": new_objects, "relations": new_rels}
