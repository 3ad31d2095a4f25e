"""The dataset build configuration (``DIR/dataset.json``, format ``parse3d-dataset/1``)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..errors import InputError, Problem

#: Bounds of a build's settings (``--scenes``, ``--views``, ``--seed``, ``--time-limit`` s).
MAX_SCENES = 10_000_000
MAX_VIEWS = 100
MAX_SEED = 2**32 - 1
MAX_TIME_LIMIT = 86_400.0

#: Scenes a local worker process builds before it is replaced (bounds its memory).
DEFAULT_MAX_TASKS = 200

DATASET_FORMAT = "parse3d-dataset/1"


_IDENTITY = ("seed", "rooms", "views", "view_size", "settle", "source", "formats")


@dataclass(frozen=True)
class BuildConfig:
    """What a dataset build produces (saved as ``DIR/dataset.json``).

    Attributes
    ----------
    scenes : int
        Number of scene indices, ``0 .. scenes-1``.
    seed : int
        Dataset seed; scene ``i`` depends on ``(seed, i)`` only.
    rooms : tuple of str
        Room types to cycle through, in order (empty: every room type the source has).
    views : int
        Sampled views per scene besides ``preview.png`` (0: the preview only).
    view_size : (int, int)
        Width and height of the preview and the views, pixels.
    settle : bool
        Settle in SAPIEN and extract the part-level contact graph.
    source : tuple of str
        ``()`` for the bundled PAG templates (:mod:`parse3d.datagen.templates`), or the PAG
        files to draw from (absolute paths; their room type is read from each file).
    time_limit : float or None
        Seconds one scene may take before it is recorded as ``timeout``.
    formats : tuple of str
        Export formats written into every scene folder (``parse3d.export.FORMATS`` names;
        kept in the order of ``FORMATS``, as they are a set).
    """

    scenes: int
    seed: int = 0
    rooms: tuple[str, ...] = ()
    views: int = 0
    view_size: tuple[int, int] = (640, 480)
    settle: bool = True
    source: tuple[str, ...] = ()
    time_limit: float | None = 600.0
    formats: tuple[str, ...] = ("glb",)

    def __post_init__(self) -> None:
        from ..export import FORMATS, check_formats

        # a set of formats, in one order, so that glb,mjcf and mjcf,glb are the same dataset
        asked = check_formats(self.formats, where="--formats")
        object.__setattr__(self, "formats", tuple(f for f in FORMATS if f in asked))
        for option, value, hi in (("--scenes", self.scenes, MAX_SCENES),
                                  ("--views", self.views, MAX_VIEWS),
                                  ("--seed", self.seed, MAX_SEED)):
            if not 0 <= int(value) <= hi:
                raise InputError(Problem("", f"{option} must be an integer in 0..{hi}, got "
                                             f"{value}", option, "parameter"))
        if self.time_limit is not None and not (
                math.isfinite(float(self.time_limit))
                and 0 < float(self.time_limit) <= MAX_TIME_LIMIT):
            raise InputError(Problem("", f"--time-limit must be a number of seconds in (0, "
                                         f"{MAX_TIME_LIMIT:g}], got {self.time_limit}",
                                     "--time-limit", "parameter"))
        w, h = self.view_size
        if int(w) < 1 or int(h) < 1:
            raise InputError(Problem("", f"view size must be positive, got {w}x{h}",
                                     "--size", "parameter"))

    def to_dict(self) -> dict[str, Any]:
        return {"format": DATASET_FORMAT, "scenes": int(self.scenes), "seed": int(self.seed),
                "rooms": list(self.rooms), "views": int(self.views),
                "view_size": [int(v) for v in self.view_size], "settle": bool(self.settle),
                "source": ({"kind": "templates"} if not self.source
                           else {"kind": "pags", "paths": list(self.source)}),
                "time_limit": None if self.time_limit is None else float(self.time_limit),
                "formats": list(self.formats)}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> BuildConfig:
        src = d.get("source") or {"kind": "templates"}
        return cls(scenes=int(d["scenes"]), seed=int(d.get("seed", 0)),
                   rooms=tuple(d.get("rooms", ())), views=int(d.get("views", 0)),
                   view_size=tuple(d.get("view_size", (640, 480))),
                   settle=bool(d.get("settle", True)),
                   source=tuple(src.get("paths", ())) if src.get("kind") == "pags" else (),
                   time_limit=d.get("time_limit"), formats=tuple(d.get("formats", ("glb",))))
