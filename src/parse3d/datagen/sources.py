"""Where a build's PAGs come from: the room templates, or PAG files."""

from __future__ import annotations

import difflib
from collections.abc import Sequence
from pathlib import Path

from ..assets.registry import vocabulary
from ..errors import InputError, Problem
from ..pag.io import load_pag, read_document
from .build_config import BuildConfig
from .template_expand import expand_template
from .template_load import list_templates
from .template_model import ROOM_TYPES, templates_dir


class SceneSource:
    """Where PAGs come from: named entries per room type, each expanded from a seed."""

    def room_types(self) -> list[str]:
        """Room types with at least one entry, in :data:`ROOM_TYPES` order (then sorted)."""
        raise NotImplementedError

    def entries(self, room_type: str) -> list[str]:
        """Sorted entry names (template names, PAG file stems) of ``room_type``."""
        raise NotImplementedError

    def make_pag(self, name: str, seed: int):
        """The PAG of entry ``name`` for ``seed`` (validated against the asset vocabulary)."""
        raise NotImplementedError


def _order_rooms(types) -> list[str]:
    known = [t for t in ROOM_TYPES if t in types]
    return known + sorted(t for t in types if t not in ROOM_TYPES)


class TemplateSource(SceneSource):
    """The PAG templates of :mod:`parse3d.datagen.templates` (17 room types)."""

    def __init__(self) -> None:
        self._by_name = {t.name: t for t in list_templates()}

    def room_types(self) -> list[str]:
        return _order_rooms({t.room_type for t in self._by_name.values()})

    def entries(self, room_type: str) -> list[str]:
        return sorted(n for n, t in self._by_name.items() if t.room_type == room_type)

    def make_pag(self, name: str, seed: int):
        return expand_template(self._by_name[name], int(seed))


class PagFileSource(SceneSource):
    """PAG files (JSON or YAML); each file is one entry of its room's type, named by its stem.

    The room type is read from each file without validating it; full validation happens when
    a scene is built, so a broken file fails its scenes (recorded in the manifest) rather than
    the whole build.
    """

    def __init__(self, paths: Sequence[str | Path]) -> None:
        self.paths = [Path(p) for p in paths]
        self._types: dict[str, str] = {}
        self._files: dict[str, Path] = {}
        problems = []
        for p in self.paths:
            try:
                doc = read_document(p)
                rtype = str(doc["room"]["type"])
            except InputError as e:
                problems.extend(e.problems)
                continue
            except (KeyError, TypeError):
                problems.append(Problem("/room/type", "a PAG file needs room.type", str(p),
                                        "schema"))
                continue
            name = p.stem
            if name in self._files:
                problems.append(Problem("", f"two PAG files are named {name!r} "
                                            f"({self._files[name]} and {p}); rename one",
                                        str(p), "io"))
                continue
            self._types[name] = rtype
            self._files[name] = p
        if problems:
            raise InputError(*problems)

    def room_types(self) -> list[str]:
        return _order_rooms(set(self._types.values()))

    def entries(self, room_type: str) -> list[str]:
        return sorted(n for n, t in self._types.items() if t == room_type)

    def make_pag(self, name: str, seed: int):
        return load_pag(self._files[name], vocabulary=vocabulary())


def _templates_available() -> bool:
    """Whether the template package is installed and holds template files (cheap: no
    template is loaded)."""
    root = templates_dir()
    return root.is_dir() and any(root.glob("*/*.yaml"))


def _bundled_paths() -> list[str]:
    from ..scenes import bundled_paths

    return [str(p) for p in bundled_paths()]


def make_source(config: BuildConfig) -> SceneSource:
    """The source a configuration names: its PAG files, else the templates."""
    if config.source:
        return PagFileSource(config.source)
    return TemplateSource()


def default_source_paths() -> tuple[str, ...]:
    """``()`` (the templates) when templates are installed, else the bundled example PAGs."""
    return () if _templates_available() else tuple(_bundled_paths())


def resolve_pag_paths(paths: Sequence[str | Path]) -> tuple[str, ...]:
    """Absolute, sorted PAG files from files and folders (a folder: its .json/.yaml/.yml)."""
    out: list[Path] = []
    problems = []
    for p in paths:
        p = Path(p)
        if p.is_dir():
            found = sorted(f for f in p.iterdir() if f.suffix in (".json", ".yaml", ".yml"))
            if not found:
                problems.append(Problem("", "no .json, .yaml or .yml PAG file in this folder",
                                        str(p), "io"))
            out.extend(found)
        elif p.is_file():
            out.append(p)
        else:
            problems.append(Problem("", "no such file or folder", str(p), "io"))
    if problems:
        raise InputError(*problems)
    return tuple(sorted({str(p.resolve()) for p in out}))


def select_rooms(config: BuildConfig, source: SceneSource) -> list[str]:
    """The room types a build cycles through, checked against the source."""
    have = source.room_types()
    if not config.rooms:
        if not have:
            raise InputError(Problem("", "the PAG source is empty: no template or PAG file",
                                     "--pags", "io"))
        return have
    problems = []
    for r in config.rooms:
        if r not in have:
            close = difflib.get_close_matches(r, list(have) + list(ROOM_TYPES), n=1)
            hint = f" — did you mean {close[0]!r}?" if close else ""
            problems.append(Problem("", f"no template or PAG of room type {r!r}{hint} "
                                        f"(available: {', '.join(have)})", "--rooms",
                                    "parameter"))
    if problems:
        raise InputError(*problems)
    return list(dict.fromkeys(config.rooms))
