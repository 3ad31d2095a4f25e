"""Loading templates and motifs from files, with every problem reported at once."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from typing import Any

from ..errors import InputError, Problem
from ..pag.io import read_document
from ..pag.schema import json_pointer, suggest
from ..pag.validate import error_for, validate_data
from .template_expand import _expand, _groups, _map_problem
from .template_model import (
    _OBJ_RE,
    _REL_KEYS,
    ROOM_TYPES,
    Motif,
    Template,
    motifs_dir,
    templates_dir,
)
from .template_schema import (
    _check_objects,
    _check_relations,
    _check_room,
    _count_hi,
    _dedupe,
    _motif_meaning,
    _schema_problems,
    _vocab,
)


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
    return _load_templates(templates_dir(), motifs_dir(), room_type)


def _load_templates(root: Path, motif_folder: Path, room_type: str | None) -> list[Template]:
    """Every template of ``root`` (``<room_type>/<name>.yaml``, only ``room_type``'s when
    given) with the motifs of ``motif_folder``: from the snapshot of the last full load when
    it is current (:mod:`parse3d.datagen.template_snapshot`), else loaded and validated (a
    full load without a problem then writes the snapshot)."""
    from .template_snapshot import (
        SNAPSHOT_NAME,
        cache_root,
        read_snapshot,
        snapshot_key,
        write_snapshot,
    )

    cache = cache_root()
    key = None
    if cache is not None:
        key = snapshot_key(root, motif_folder, cache)
        snap = read_snapshot(cache / SNAPSHOT_NAME, key)
        if snap is not None:
            return [t for t in snap if room_type is None or t.room_type == room_type]
    motifs = motif_library(motif_folder)
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
    if room_type is None and key is not None:
        write_snapshot(cache / SNAPSHOT_NAME, key, out)
    return out
