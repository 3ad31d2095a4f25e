"""Template expansion: a template and a seed give one ``pag/1`` document.

Also maps the problems of an expanded PAG back to the template or motif line they came from.
"""

from __future__ import annotations

import copy
import zlib
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import InputError, Problem
from ..pag.model import PAG, PAG_FORMAT
from ..pag.validate import error_for, validate_data
from .template_model import _OBJ_RE, _PARAM_RE, _REL_KEYS, _SUPPORTS, Motif, Template
from .template_schema import _dedupe, _vocab


@dataclass
class _Group:
    """The template's own objects, or one use of a motif."""

    objects: list[dict[str, Any]]
    relations: list[dict[str, Any]]
    prefix: str | None = None
    params: dict[str, Any] = field(default_factory=dict)
    p: float | None = None
    file: str | None = None
    base: str = ""  # pointer prefix inside `file` ("" for the template and motif files)
    use_ptr: str | None = None  # for motifs: /motifs/k in the template
    motif: str | None = None

    @property
    def local_ids(self) -> set[str]:
        return {o["id"] for o in self.objects}

    def prefixed(self, oid: str) -> str:
        return f"{self.prefix}_{oid}" if self.prefix is not None else oid

    def pointer(self, ptr: str) -> str:
        return self.base + ptr

    def where(self, ptr: str) -> str:
        if self.motif is None:
            return ptr
        return f"motif {self.motif!r} {ptr} used at {self.use_ptr}"

    def ref(self, text: str) -> str:
        """A reference with $params substituted and local ids prefixed."""
        m = _PARAM_RE.match(text)
        if m and self.motif is not None:
            return f"{self.params[m.group(1)]}{m.group(2)}"
        if self.prefix is None:
            return text
        obj, rest = _OBJ_RE.match(text).groups()
        return f"{self.prefixed(obj)}{rest}" if obj in self.local_ids else text

    def value(self, v: Any) -> Any:
        if self.motif is not None and isinstance(v, str):
            m = _PARAM_RE.match(v)
            if m and not m.group(2):
                return copy.deepcopy(self.params[m.group(1)])
        return copy.deepcopy(v)


def _groups(data: dict[str, Any], motifs: dict[str, Motif]) -> list[_Group]:
    out = [_Group(data["objects"], data["relations"])]
    for k, use in enumerate(data.get("motifs") or []):
        m = motifs[use["motif"]]
        params = dict(m.params)
        params.update(use.get("params") or {})
        out.append(_Group(m.data["objects"], m.data["relations"], use.get("prefix", m.name),
                          params, use.get("p"), m.file, "", f"/motifs/{k}", m.name))
    return out


def _draw(v: Any, rng: np.random.Generator | None, *, low: bool) -> float:
    if not isinstance(v, list):
        return float(v)
    if rng is None:
        return float(v[0] if low else v[1])
    return round(float(rng.uniform(v[0], v[1])), 2)


@dataclass
class _Item:
    id: str
    node: dict[str, Any]
    n: int | None  # number of copies (None: not repeated)
    present: bool
    src: tuple[str | None, str, str | None]  # file, pointer, note


def _expand(data: dict[str, Any], motifs: dict[str, Motif], rng: np.random.Generator | None
            ) -> tuple[dict[str, Any], dict[str, list]]:
    """Expand a valid template; ``rng=None`` gives the maximal expansion used for checking.

    Returns the ``pag/1`` document and the provenance of its objects and relations
    (``(file, pointer, note)`` each).
    """
    room = data["room"]
    w = _draw(room["width"], rng, low=True)
    d = _draw(room["depth"], rng, low=True)
    h = _draw(room["height"], rng, low=True)
    if room.get("shape") == "L":
        nw = _draw(room["notch"]["width"], rng, low=False)
        nd = _draw(room["notch"]["depth"], rng, low=False)
        fp = [[0.0, 0.0], [w, 0.0], [w, round(d - nd, 2)], [round(w - nw, 2), round(d - nd, 2)],
              [round(w - nw, 2), d], [0.0, d]]
    else:
        fp = [[0.0, 0.0], [w, 0.0], [w, d], [0.0, d]]

    groups = _groups(data, motifs)
    tfile = None
    items: dict[str, _Item] = {}
    order: list[str] = []
    for g in groups:
        g_present = True
        if g.p is not None and rng is not None:
            g_present = bool(rng.random() < g.p)
        note = None if g.motif is None else f"motif {g.motif!r} used at {g.use_ptr}"
        for j, o in enumerate(g.objects):
            present = g_present
            if "p" in o and rng is not None:
                present = bool(rng.random() < o["p"]) and present
            n = None
            if "count" in o:
                c = o["count"]
                if not isinstance(c, list):
                    n = int(c)
                elif rng is None:
                    n = int(c[1])
                else:
                    n = int(rng.integers(c[0], c[1] + 1))
                if n == 0:
                    present = False
            node = {"id": g.prefixed(o["id"]),
                    "category": ([g.value(c) for c in o["category"]]
                                 if isinstance(o["category"], list) else g.value(o["category"]))}
            if "scale" in o:
                node["scale"] = list(g.value(o["scale"]))
            oid = node["id"]
            items[oid] = _Item(oid, node, n, present, (g.file or tfile, f"/objects/{j}", note))
            order.append(oid)

    # Paired repeats: a repeated child of a repeated parent with the same count spec takes the
    # parent's drawn count, so that copy k relates to copy k.
    rels: list[tuple[_Group, int, dict[str, Any], str, str]] = []
    for g in groups:
        for i, r in enumerate(g.relations):
            rels.append((g, i, r, g.ref(r["child"]), g.ref(r["parent"])))
    for _g, _i, r, c, p in rels:
        ci, pi = items.get(_obj(c)), items.get(_obj(p))
        if (not r.get("stack") and ci is not None and pi is not None and ci.n is not None
                and pi.n is not None and ci is not pi):
            ci.n = pi.n
            ci.present = ci.present and pi.present

    def copies(it: _Item) -> list[str]:
        return [it.id] if it.n is None else [f"{it.id}_{k}" for k in range(it.n)]

    objects, obj_src = [], []
    present_ids: set[str] = set()
    for oid in order:
        it = items[oid]
        if not it.present:
            continue
        for cid in copies(it):
            objects.append(dict(it.node, id=cid))
            obj_src.append(it.src)
            present_ids.add(cid)

    relations, rel_src = [], []
    for g, i, r, c, p in rels:
        note = None if g.motif is None else f"motif {g.motif!r} used at {g.use_ptr}"
        src = (g.file or tfile, f"/relations/{i}", note)
        extra = {k: g.value(v) for k, v in r.items() if k not in (*_REL_KEYS, "stack")}
        ci, pi = items.get(_obj(c)), items.get(_obj(p))
        c_copies = copies(ci) if ci is not None else [_obj(c)]
        if r.get("stack") and ci is not None and ci.n is not None:
            base_parent = _swap(p, copies(pi)[-1]) if pi is not None and pi.n else p
            for k, cid in enumerate(c_copies):
                if k == 0:
                    relations.append({"relation": r["relation"], "child": _swap(c, cid),
                                      "parent": base_parent, **extra})
                else:
                    relations.append({"relation": "ON", "child": _swap(c, cid),
                                      "parent": _stack_parent(c, c_copies[k - 1])})
                rel_src.append(src)
            continue
        if pi is not None and pi.n is not None and ci is not None and ci.n is not None \
                and ci is not pi:
            for cid, pid in zip(c_copies, copies(pi), strict=False):
                relations.append({"relation": r["relation"], "child": _swap(c, cid),
                                  "parent": _swap(p, pid), **extra})
                rel_src.append(src)
            continue
        for cid in c_copies:
            relations.append({"relation": r["relation"], "child": _swap(c, cid),
                              "parent": p, **extra})
            rel_src.append(src)

    # Remove what lost its support (recursively), then relations naming removed objects.
    all_ids = {cid for it in items.values() for cid in copies(it)}
    removed = all_ids - present_ids
    while True:
        newly = set()
        for rel in relations:
            if rel["relation"] in _SUPPORTS:
                ch, pa = _obj(rel["child"]), _obj(rel["parent"])
                if ch in present_ids and ch not in newly and pa in removed:
                    newly.add(ch)
        if not newly:
            break
        removed |= newly
        present_ids -= newly
    keep_o = [k for k, o in enumerate(objects) if o["id"] in present_ids]
    objects = [objects[k] for k in keep_o]
    obj_src = [obj_src[k] for k in keep_o]
    keep_r = [k for k, rel in enumerate(relations)
              if _obj(rel["child"]) not in removed and _obj(rel["parent"]) not in removed]
    relations = [relations[k] for k in keep_r]
    rel_src = [rel_src[k] for k in keep_r]

    doc = {
        "format": PAG_FORMAT,
        "name": data["name"],
        "room": {"type": data["room_type"], "footprint": fp, "height": h},
        "objects": objects,
        "relations": relations,
    }
    return doc, {"objects": obj_src, "relations": rel_src}


_OPPOSITE = {"top": "bottom", "bottom": "top", "front": "back", "back": "front",
             "left": "right", "right": "left"}


def _stack_parent(child_ref: str, below: str) -> str:
    """The support of a stacked copy: the face of the copy below opposite the child's face.

    A book written ``book:back_cover@back`` rests on its back, so the next one rests on the
    previous book's whole-object ``@front`` face, which then points up; without a surface the
    previous copy's default (top) is used.
    """
    surface = child_ref.rpartition("@")[2] if "@" in child_ref else None
    return f"{below}@{_OPPOSITE[surface]}" if surface in _OPPOSITE else below


def _obj(ref: str) -> str:
    return _OBJ_RE.match(ref).group(1)


def _swap(ref: str, new_obj: str) -> str:
    return new_obj + _OBJ_RE.match(ref).group(2)


def _map_problem(p: Problem, prov: dict[str, list], file: str | None) -> Problem:
    """Point a problem of the expanded PAG at the template or motif line it came from."""
    parts = p.pointer.split("/")
    if len(parts) >= 3 and parts[1] in ("objects", "relations") and parts[2].isdigit():
        k = int(parts[2])
        src = prov[parts[1]]
        if k < len(src):
            f, ptr, note = src[k]
            rest = "/".join(parts[3:])
            ptr = ptr + ("/" + rest if rest else "")
            msg = p.message + (f" (in {note})" if note else "")
            return Problem(ptr, msg, f or file, p.kind)
    if p.pointer.startswith("/room"):
        return Problem("/room", p.message, file, p.kind)
    return Problem(p.pointer, p.message, file, p.kind)


def _rng(template: Template, seed: int) -> np.random.Generator:
    return np.random.default_rng([int(seed), zlib.crc32(template.name.encode("utf-8"))])


def expand_template(template: Template, seed: int, *, vocabulary=None) -> PAG:
    """Draw one PAG from a template.

    Deterministic for (template, seed): the generator is
    ``numpy.random.default_rng([seed, zlib.crc32(name)])`` and draws happen in file order
    (room width, depth, height, notch width and depth; then the template's objects — ``p``
    before ``count`` — then each motif use: its ``p``, then its objects).

    Parameters
    ----------
    template : Template
    seed : int
        A non-negative integer.
    vocabulary : optional
        Checks the result (default: the asset registry's vocabulary).

    Returns
    -------
    PAG
        Named ``<name>-s<seed>``, with ``meta = {"template": name, "seed": seed}``.

    Raises
    ------
    InputError
        A negative seed, or an expansion that does not validate (mapped to template lines).
    """
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise InputError(Problem("", f"the seed must be a non-negative integer, got {seed!r}",
                                 "--seed", "parameter"))
    doc, prov = _expand(template.data, template.motifs, _rng(template, seed))
    doc["name"] = f"{template.name}-s{int(seed)}"
    doc["meta"] = {"template": template.name, "seed": int(seed)}
    problems = validate_data(doc, file=template.file, vocabulary=_vocab(vocabulary))
    if problems:
        raise error_for(_dedupe([_map_problem(p, prov, template.file) for p in problems]),
                        file=template.file)
    return PAG.from_dict(doc)
