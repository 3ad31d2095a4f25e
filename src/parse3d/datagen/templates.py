"""Room templates (``pag-template/1``) and motifs (``pag-motif/1``): PAGs drawn from a seed.

A *template* is a room type's recipe: a room whose width, depth and height are sampled, objects
that may repeat (``count``) or be optional (``p``), relations written as in ``pag/1``, and
*motifs* — reusable groups of objects (a desk set-up, a bed with nightstands) kept in
``motifs/<name>.yaml`` and shared by every template. :func:`expand_template` turns a template
and a seed into an ordinary :class:`~parse3d.pag.PAG`; the format is documented in
``docs/templates.md``.

Loading validates in two layers, like :mod:`parse3d.pag.validate`: the JSON Schema shipped
beside this module first, then meaning (unknown motif or parameter, bad ranges, duplicate ids
after expansion, a repeated parent without ``stack``, ...). Finally the template is expanded
with every optional object present and every count at its maximum, and that PAG is checked by
the ``pag/1`` validator against the asset vocabulary, with each problem mapped back to the line
of the template or motif it came from. Every mistake is an :class:`~parse3d.errors.InputError`
whose problems read ``FILE:/json/pointer: message``.

Examples
--------
>>> from parse3d.datagen.templates import list_templates, expand_template
>>> t = list_templates("study")[0]                                    # doctest: +SKIP
>>> pag = expand_template(t, seed=3)                                  # doctest: +SKIP
>>> pag.name                                                          # doctest: +SKIP
'study-reading-01-s3'
"""

from __future__ import annotations

import copy
import json
import re
import zlib
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError, Problem
from ..pag.io import read_document
from ..pag.model import PAG, PAG_FORMAT
from ..pag.refs import is_room_element
from ..pag.schema import _messages, json_pointer, suggest
from ..pag.validate import error_for, validate_data
from ..relations import RELATIONS

__all__ = [
    "ROOM_TYPES",
    "TEMPLATE_FORMAT",
    "MOTIF_FORMAT",
    "Motif",
    "Template",
    "TemplateStats",
    "TemplateCheck",
    "templates_dir",
    "motifs_dir",
    "load_motif",
    "motif_library",
    "load_template",
    "list_templates",
    "expand_template",
    "template_problems",
    "template_stats",
    "check_template",
]

TEMPLATE_FORMAT = "pag-template/1"
MOTIF_FORMAT = "pag-motif/1"

#: The room types of PARSE-10K (paper, section 4.2), exactly as templates name them.
ROOM_TYPES = (
    "bedroom", "living_room", "office", "study", "laundry", "storage", "dining_room",
    "bathroom", "tea_house", "game_room", "kitchen", "music_room", "bar", "dormitory",
    "meeting_room", "hotel", "grocery",
)

_PARAM_RE = re.compile(r"^\$([A-Za-z_][A-Za-z0-9_]*)(.*)$")
_OBJ_RE = re.compile(r"^([^:@]*)(.*)$")
_SUPPORTS = frozenset(n for n, r in RELATIONS.items() if r.is_support)
_REL_KEYS = ("relation", "child", "parent")


def templates_dir() -> Path:
    """The folder of bundled templates, ``templates/<room_type>/<name>.yaml``."""
    return Path(__file__).resolve().parent / "templates"


def motifs_dir() -> Path:
    """The folder of bundled motifs, ``motifs/<name>.yaml``."""
    return Path(__file__).resolve().parent / "motifs"


# --------------------------------------------------------------------------- data


@dataclass(frozen=True)
class Motif:
    """A reusable group of objects and relations (``pag-motif/1``).

    Attributes
    ----------
    name : str
    description : str
    params : dict of str to any
        Parameter defaults, referenced as ``$name`` inside the motif.
    data : dict
        The document as read (objects and relations as written).
    file : str or None
        Where it was read from.
    """

    name: str
    description: str
    params: dict[str, Any]
    data: dict[str, Any] = field(repr=False)
    file: str | None = None

    @property
    def object_ids(self) -> list[str]:
        return [o["id"] for o in self.data.get("objects", [])]


@dataclass(frozen=True)
class Template:
    """A validated room template (``pag-template/1``).

    Attributes
    ----------
    name : str
        Unique over all templates; the file is ``<name>.yaml``.
    room_type : str
        One of :data:`ROOM_TYPES`.
    description : str
    data : dict
        The document as read.
    motifs : dict of str to Motif
        The motifs the template uses, by name (resolved at load time).
    file : str or None
    """

    name: str
    room_type: str
    description: str
    data: dict[str, Any] = field(repr=False)
    motifs: dict[str, Motif] = field(repr=False, default_factory=dict)
    file: str | None = None


@dataclass(frozen=True)
class TemplateStats:
    """Size statistics of a template over some seeds.

    Attributes
    ----------
    name : str
    seeds : tuple of int
    n_objects : tuple of int
        Objects per expanded PAG, one per seed.
    area : tuple of float
        Floor area per seed, m^2.
    n_relations : tuple of int
    """

    name: str
    seeds: tuple[int, ...]
    n_objects: tuple[int, ...]
    area: tuple[float, ...]
    n_relations: tuple[int, ...]

    @property
    def mean_objects(self) -> float:
        return float(np.mean(self.n_objects)) if self.n_objects else 0.0

    @property
    def mean_density(self) -> float:
        """Mean objects per square metre."""
        return float(np.mean(np.asarray(self.n_objects) / np.asarray(self.area)))


@dataclass(frozen=True)
class TemplateCheck:
    """The result of solving a template's expansions (see :func:`check_template`).

    Attributes
    ----------
    name : str
    seeds : tuple of int
    n_objects : tuple of int
        Objects per expanded PAG.
    n_placed : tuple of int
        Objects placed by the solver.
    failures : tuple of (seed, object id, reason)
    seconds : tuple of float
        Solve time per seed.
    """

    name: str
    seeds: tuple[int, ...]
    n_objects: tuple[int, ...]
    n_placed: tuple[int, ...]
    failures: tuple[tuple[int, str, str], ...]
    seconds: tuple[float, ...]

    @property
    def placed_fraction(self) -> float:
        """Mean over seeds of the fraction of objects placed."""
        fr = [p / n if n else 1.0 for p, n in zip(self.n_placed, self.n_objects, strict=True)]
        return float(np.mean(fr)) if fr else 1.0

    def to_dict(self) -> dict[str, Any]:
        return {
            "name": self.name, "seeds": list(self.seeds), "n_objects": list(self.n_objects),
            "n_placed": list(self.n_placed), "placed_fraction": round(self.placed_fraction, 4),
            "seconds": [round(s, 3) for s in self.seconds],
            "failures": [{"seed": s, "object": o, "reason": r} for s, o, r in self.failures],
        }


# ------------------------------------------------------------------------ schemas


@lru_cache(maxsize=2)
def _schema_validator(fmt: str):
    import jsonschema

    fname = {"template": "template-1.schema.json", "motif": "motif-1.schema.json"}[fmt]
    schema = json.loads((Path(__file__).resolve().parent / fname).read_text(encoding="utf-8"))
    cls = jsonschema.validators.validator_for(schema)
    cls.check_schema(schema)
    return cls(schema)


def _schema_problems(data: Any, fmt: str, file: str | None) -> list[Problem]:
    errors = sorted(_schema_validator(fmt).iter_errors(data),
                    key=lambda e: [str(p) for p in e.absolute_path])
    out: list[Problem] = []
    seen: set[tuple[str, str]] = set()
    for err in errors:
        for ptr, msg in _messages(err):
            if err.validator == "enum" and ptr == "/room_type":
                msg = msg.replace("unknown room_type", "unknown room type")
            if (ptr, msg) not in seen:
                seen.add((ptr, msg))
                out.append(Problem(ptr, msg, file, "schema"))
    return out


# ------------------------------------------------------------------------- motifs


def load_motif(path: str | Path) -> Motif:
    """Read and validate a ``pag-motif/1`` file.

    Raises
    ------
    InputError
        Every problem of the file: schema, undeclared ``$params``, references to objects the
        motif does not have, duplicate ids, bad count or scale ranges, repeated parents.
    """
    path = Path(path)
    data = read_document(path)
    problems = _schema_problems(data, "motif", str(path))
    if not problems:
        problems = _motif_meaning(data, str(path))
    if problems:
        raise error_for(problems, file=str(path))
    return Motif(data["name"], data.get("description", ""), dict(data.get("params") or {}),
                 data, str(path))


def _motif_meaning(data: dict[str, Any], file: str) -> list[Problem]:
    problems: list[Problem] = []

    def add(ptr: str, msg: str, kind: str = "reference") -> None:
        problems.append(Problem(ptr, msg, file, kind))

    if Path(file).stem != data["name"]:
        add("/name", f"the motif is named {data['name']!r} but its file is "
            f"{Path(file).name!r}: name the file {data['name']}.yaml", "schema")
    params = data.get("params") or {}
    ids = _check_objects(data["objects"], add)
    for i, r in enumerate(data["relations"]):
        for key in _REL_KEYS[1:]:
            text = r[key]
            m = _PARAM_RE.match(text)
            if m:
                if m.group(1) not in params:
                    add(f"/relations/{i}/{key}", f"unknown parameter ${m.group(1)}"
                        f"{suggest(m.group(1), params)} (declare it under params)")
                continue
            obj = _OBJ_RE.match(text).group(1)
            if obj and not is_room_element(obj) and obj not in ids:
                add(f"/relations/{i}/{key}", f"unknown object {obj!r}{suggest(obj, ids)}; a "
                    "motif names its own objects, room elements, or $params")
        for key, v in r.items():
            if key in _REL_KEYS or not isinstance(v, str):
                continue
            m = _PARAM_RE.match(v)
            if m and m.group(1) not in params:
                add(f"/relations/{i}/{key}", f"unknown parameter ${m.group(1)}"
                    f"{suggest(m.group(1), params)} (declare it under params)", "parameter")
    for j, o in enumerate(data["objects"]):
        cats = [o["category"]] if isinstance(o["category"], str) else o["category"]
        for c in cats:
            m = _PARAM_RE.match(c)
            if m and m.group(1) not in params:
                add(f"/objects/{j}/category", f"unknown parameter ${m.group(1)}"
                    f"{suggest(m.group(1), params)} (declare it under params)")
    _check_relations(data, ids, add, local=lambda t: _OBJ_RE.match(t).group(1))
    return problems


@lru_cache(maxsize=4)
def _motif_folder(folder: str, stamp: tuple) -> dict[str, Motif]:
    out: dict[str, Motif] = {}
    errors: list[InputError] = []
    for p in sorted(Path(folder).glob("*.yaml")):
        try:
            m = load_motif(p)
        except InputError as e:
            errors.append(e)
            continue
        out[m.name] = m
    if errors:
        raise InputError.merge(errors)
    return out


def motif_library(folder: str | Path | None = None) -> dict[str, Motif]:
    """Every motif of a folder (default: the bundled motifs), by name.

    Read once per process and folder state (re-read when a file changes).
    """
    folder = Path(folder) if folder is not None else motifs_dir()
    stamp = tuple((p.name, p.stat().st_mtime_ns) for p in sorted(folder.glob("*.yaml")))
    return dict(_motif_folder(str(folder), stamp))


# ---------------------------------------------------------------------- templates


def _check_objects(objects: list[dict[str, Any]], add, base: str = "") -> dict[str, int]:
    """Range checks of object items; returns id -> index of the valid ids."""
    ids: dict[str, int] = {}
    for j, o in enumerate(objects):
        ptr = f"{base}/objects/{j}"
        if o["id"] in ids:
            add(f"{ptr}/id", f"duplicate object id {o['id']!r} (first declared at "
                f"{base}/objects/{ids[o['id']]})")
        else:
            ids[o["id"]] = j
        c = o.get("count")
        if isinstance(c, list) and c[0] > c[1]:
            add(f"{ptr}/count", f"count low {c[0]} is above high {c[1]}: write [low, high]",
                "parameter")
        sc = o.get("scale")
        if not isinstance(sc, list):
            continue
        if (sc[0] <= 0 or sc[1] <= 0):
            add(f"{ptr}/scale", f"scale factors must be positive, got {sc}", "parameter")
        elif sc[0] > sc[1]:
            add(f"{ptr}/scale", f"scale low {sc[0]:g} is above high {sc[1]:g}: write "
                "[low, high]", "parameter")
    return ids


def _count_hi(o: dict[str, Any]) -> int | None:
    c = o.get("count")
    if c is None:
        return None
    return int(c[1]) if isinstance(c, list) else int(c)


def _check_relations(data: dict[str, Any], ids: dict[str, int], add, *, local) -> None:
    """``stack`` and repeated-parent rules; ``local(ref)`` gives the referenced local id."""
    objs = data["objects"]
    for i, r in enumerate(data["relations"]):
        ptr = f"/relations/{i}"
        child, parent = local(r["child"]), local(r["parent"])
        co = objs[ids[child]] if child in ids else None
        po = objs[ids[parent]] if parent in ids else None
        c_rep = co is not None and "count" in co
        p_rep = po is not None and "count" in po
        if r.get("stack"):
            if r["relation"] not in _SUPPORTS:
                add(f"{ptr}/stack", f"stack applies to support relations only "
                    f"({', '.join(sorted(_SUPPORTS))}), not {r['relation']}", "parameter")
            elif co is not None and not c_rep:
                add(f"{ptr}/stack", f"stack needs a repeated child: give {child!r} a count",
                    "parameter")
            continue
        if p_rep:
            if c_rep and co.get("count") == po.get("count"):
                continue  # copy k relates to copy k
            add(f"{ptr}/parent", f"{parent!r} is repeated (count), so it cannot be the parent "
                "of a single object: make the child repeated with the same count (copy k "
                f"then relates to copy k), or use stack: true on {child!r}'s support relation "
                "for a pile", "graph")


def template_problems(
    data: Any, *, file: str | None = None, motifs: dict[str, Motif] | None = None,
    vocabulary=None,
) -> list[Problem]:
    """Every problem of a ``pag-template/1`` document: schema, meaning, expanded PAG.

    Parameters
    ----------
    data : any
        The parsed document.
    file : str, optional
        Recorded in each problem; the file's stem must equal the template's name.
    motifs : dict of str to Motif, optional
        Motifs it may use (default: the bundled library).
    vocabulary : optional
        Category vocabulary for the expanded PAG (default: the asset registry's).

    Returns
    -------
    list of Problem
        Empty when the template is valid.
    """
    problems = _schema_problems(data, "template", file)
    if problems:
        return problems
    if motifs is None:
        motifs = motif_library()

    def add(ptr: str, msg: str, kind: str = "reference", f: str | None = file) -> None:
        problems.append(Problem(ptr, msg, f, kind))

    if file is not None and Path(file).stem != data["name"]:
        add("/name", f"the template is named {data['name']!r} but its file is "
            f"{Path(file).name!r}: name the file {data['name']}.yaml", "schema")
    _check_room(data["room"], add)
    _check_objects(data["objects"], add)
    for i, r in enumerate(data["relations"]):
        for key in _REL_KEYS[1:]:
            if r[key].startswith("$"):
                add(f"/relations/{i}/{key}", "$parameters may only be used inside motifs")
    used: dict[str, Motif] = {}
    for k, use in enumerate(data.get("motifs") or []):
        m = motifs.get(use["motif"])
        if m is None:
            add(f"/motifs/{k}/motif", f"unknown motif {use['motif']!r}"
                f"{suggest(use['motif'], motifs)}")
            continue
        used[m.name] = m
        for pname in use.get("params") or {}:
            if pname not in m.params:
                known = ", ".join(m.params) or "none"
                add(f"/motifs/{k}/params/{json_pointer([pname])[1:]}",
                    f"unknown parameter {pname!r} of motif {m.name!r}"
                    f"{suggest(pname, m.params)} (its parameters: {known})", "parameter")
    if problems:
        return problems
    # Repeated-parent rules across the whole namespace (motif objects are visible by prefix).
    groups = _groups(data, used)
    flat_ids: dict[str, int] = {}
    flat_objs = []
    for g in groups:
        for o in g.objects:
            flat_ids.setdefault(g.prefixed(o["id"]), len(flat_objs))
            flat_objs.append(dict(o, id=g.prefixed(o["id"])))
    flat = {"objects": flat_objs, "relations": data["relations"]}
    _check_relations(flat, flat_ids, add, local=lambda t: _OBJ_RE.match(t).group(1))
    # Duplicate ids after expansion (all present, maximal counts).
    made: dict[str, str] = {}
    for g in groups:
        for j, o in enumerate(g.objects):
            hi = _count_hi(o)
            names = [g.prefixed(o["id"])] if hi is None else [
                f"{g.prefixed(o['id'])}_{k}" for k in range(hi)]
            where = g.where(f"/objects/{j}")
            for nm in names:
                if nm in made and made[nm] != where:
                    if g.motif is None:
                        add(f"/objects/{j}/id", f"after expansion the id {nm!r} is made twice "
                            f"(also by {made[nm]}); rename one")
                    else:
                        add(f"{g.use_ptr}/prefix", f"after expansion the id {nm!r} (motif "
                            f"{g.motif!r} /objects/{j}) is made twice (also by {made[nm]}); "
                            "give the motif another prefix")
                made.setdefault(nm, where)
    if problems:
        return problems
    doc, prov = _expand(data, used, None)
    for p in validate_data(doc, file=file, vocabulary=_vocab(vocabulary)):
        problems.append(_map_problem(p, prov, file))
    return _dedupe(problems)


def _check_room(room: dict[str, Any], add) -> None:
    for key in ("width", "depth", "height"):
        v = room[key]
        if isinstance(v, list) and v[0] > v[1]:
            add(f"/room/{key}", f"{key} low {v[0]:g} is above high {v[1]:g}: write [low, high]",
                "parameter")
    shape = room.get("shape", "rectangle")
    if shape == "L" and "notch" not in room:
        add("/room", "an L-shaped room needs notch: {width: [lo, hi], depth: [lo, hi]}, the "
            "part cut from the +x+y corner", "geometry")
    if shape != "L" and "notch" in room:
        add("/room/notch", "notch applies to L-shaped rooms only: add shape: L", "geometry")
    if shape == "L" and "notch" in room:
        for key in ("width", "depth"):
            nv, rv = room["notch"][key], room[key]
            n_hi = nv[1] if isinstance(nv, list) else nv
            r_lo = rv[0] if isinstance(rv, list) else rv
            if isinstance(nv, list) and nv[0] > nv[1]:
                add(f"/room/notch/{key}", f"notch {key} low {nv[0]:g} is above high {nv[1]:g}",
                    "parameter")
            elif n_hi >= r_lo:
                add(f"/room/notch/{key}", f"the notch {key} (up to {n_hi:g} m) must be smaller "
                    f"than the room {key} (from {r_lo:g} m)", "geometry")


def _vocab(vocabulary):
    if vocabulary is not None:
        return vocabulary
    from ..assets.registry import vocabulary as registry_vocabulary

    return registry_vocabulary()


def _dedupe(problems: list[Problem]) -> list[Problem]:
    seen, out = set(), []
    for p in problems:
        key = (p.file, p.pointer, p.message)
        if key not in seen:
            seen.add(key)
            out.append(p)
    return out


def load_template(
    path_or_name: str | Path, *, motifs: dict[str, Motif] | None = None, vocabulary=None,
) -> Template:
    """Read and validate a template file, or a bundled template by name.

    Parameters
    ----------
    path_or_name : str or Path
        A ``.yaml``/``.yml``/``.json`` file, or the name of a bundled template.
    motifs : dict of str to Motif, optional
        Default: the bundled motif library.
    vocabulary : optional
        Default: the asset registry's vocabulary.

    Raises
    ------
    InputError
        With every problem found (``FILE:/json/pointer: message``).
    """
    path = Path(path_or_name)
    if not path.exists() and path.suffix.lower() not in (".yaml", ".yml", ".json") \
            and "/" not in str(path_or_name):
        path = _bundled_path(str(path_or_name))
    data = read_document(path)
    if motifs is None:
        motifs = motif_library()
    problems = template_problems(data, file=str(path), motifs=motifs, vocabulary=vocabulary)
    if problems:
        raise error_for(problems, file=str(path))
    used = {m["motif"]: motifs[m["motif"]] for m in data.get("motifs") or []}
    return Template(data["name"], data["room_type"], data.get("description", ""), data, used,
                    str(path))


def _bundled_paths() -> dict[str, Path]:
    return {p.stem: p for p in sorted(templates_dir().glob("*/*.yaml"))}


def _bundled_path(name: str) -> Path:
    paths = _bundled_paths()
    if name not in paths:
        raise InputError(Problem("", f"no template file or bundled template named {name!r}"
                                 f"{suggest(name, paths)} (see `parse3d template list`)",
                                 name, "io"))
    return paths[name]


def list_templates(room_type: str | None = None) -> list[Template]:
    """The bundled templates, sorted by room type then name.

    Parameters
    ----------
    room_type : str, optional
        Only this room type (one of :data:`ROOM_TYPES`).

    Raises
    ------
    InputError
        An unknown room type, or a bundled template that does not validate.
    """
    if room_type is not None and room_type not in ROOM_TYPES:
        raise InputError(Problem("", f"unknown room type {room_type!r}"
                                 f"{suggest(room_type, ROOM_TYPES)} (one of: "
                                 f"{', '.join(ROOM_TYPES)})", "--room-type", "parameter"))
    root = templates_dir()
    motifs = motif_library()
    vocab = _vocab(None)
    out, errors = [], []
    types = [room_type] if room_type else ROOM_TYPES
    for rt in types:
        for p in sorted((root / rt).glob("*.yaml")):
            try:
                t = load_template(p, motifs=motifs, vocabulary=vocab)
            except InputError as e:
                errors.append(e)
                continue
            if t.room_type != rt:
                errors.append(InputError(Problem(
                    "/room_type", f"a {t.room_type} template in the {rt}/ folder: move it to "
                    f"{t.room_type}/", str(p), "schema")))
                continue
            out.append(t)
    if errors:
        raise InputError.merge(errors)
    return out


# ---------------------------------------------------------------------- expansion


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


def template_stats(template: Template, seeds: range | list[int] | tuple[int, ...] = range(8)
                   ) -> TemplateStats:
    """Objects, relations and floor area of a template's expansions over some seeds."""
    from shapely.geometry import Polygon

    n_obj, area, n_rel = [], [], []
    for s in seeds:
        doc, _ = _expand(template.data, template.motifs, _rng(template, s))
        n_obj.append(len(doc["objects"]))
        n_rel.append(len(doc["relations"]))
        area.append(float(Polygon(doc["room"]["footprint"]).area))
    return TemplateStats(template.name, tuple(int(s) for s in seeds), tuple(n_obj), tuple(area),
                         tuple(n_rel))


def check_template(template: Template, seeds: range | list[int] | tuple[int, ...] = range(2),
                   *, library=None) -> TemplateCheck:
    """Expand a template for some seeds and solve each (no settling).

    Parameters
    ----------
    template : Template
    seeds : iterable of int
        Each seed expands the template and seeds the solver.
    library : parse3d.solver.AssetLibrary, optional
        Shared asset library (default: the process-wide pool).

    Returns
    -------
    TemplateCheck
    """
    import time

    from ..solver import solve

    n_obj, n_placed, fails, secs = [], [], [], []
    for s in seeds:
        pag = expand_template(template, s)
        t0 = time.perf_counter()
        scene = solve(pag, seed=int(s), library=library, validate=False)
        secs.append(time.perf_counter() - t0)
        n_obj.append(len(pag.objects))
        n_placed.append(len(scene.placed))
        fails += [(int(s), o.id, o.reason or "") for o in scene.failed]
    return TemplateCheck(template.name, tuple(int(s) for s in seeds), tuple(n_obj),
                         tuple(n_placed), tuple(fails), tuple(secs))
