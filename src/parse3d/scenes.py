"""The PAGs bundled with parse3d (the files of ``examples/``), by room type."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from .errors import InputError, Problem
from .pag.model import PAG

__all__ = ["bundled_paths", "bundled_room_types", "bundled_pag"]


def bundled_paths() -> list[Path]:
    """Paths of the bundled PAG files, sorted."""
    root = Path(str(resources.files("parse3d") / "data" / "pags"))
    return sorted(p for p in root.iterdir() if p.suffix in (".json", ".yaml", ".yml"))


def _load_all() -> list[PAG]:
    from .assets.registry import vocabulary
    from .pag.io import load_pag

    vocab = vocabulary()
    return [load_pag(p, vocabulary=vocab) for p in bundled_paths()]


def bundled_room_types() -> list[str]:
    return sorted({p.room.type for p in _load_all()})


def bundled_pag(room_type: str, seed: int = 0) -> PAG:
    """A PAG of ``room_type`` for ``seed``: one of the room templates of that type, expanded
    with the seed (or, for a room type with no templates, one of the bundled example PAGs)."""
    import zlib

    import numpy as np

    from .datagen.templates import ROOM_TYPES, expand_template, list_templates

    if room_type in ROOM_TYPES:
        templates = list_templates(room_type)
        if templates:
            rng = np.random.default_rng([int(seed), zlib.crc32(room_type.encode())])
            return expand_template(templates[int(rng.integers(len(templates)))], int(seed))
    pags = [p for p in _load_all() if p.room.type == room_type]
    if not pags:
        import difflib

        types = sorted(set(bundled_room_types()) | set(ROOM_TYPES))
        close = difflib.get_close_matches(room_type, types, n=1)
        hint = f" — did you mean {close[0]!r}?" if close else ""
        raise InputError(Problem("", f"no bundled PAG of room type {room_type!r}{hint} "
                                     f"(room types: {', '.join(types)})", "ROOM_TYPE", "reference"))
    return pags[int(seed) % len(pags)]
