"""The template data model: formats, room types and the ``Template``/``Motif`` records.

See :mod:`parse3d.datagen.templates` for the whole template API and ``docs/templates.md`` for
the ``pag-template/1`` and ``pag-motif/1`` formats.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..relations import RELATIONS

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
