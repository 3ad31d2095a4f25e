"""Which room type, entry and seed scene ``index`` of a build is."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from .build_config import BuildConfig
from .sources import SceneSource, select_rooms


@dataclass(frozen=True)
class ScenePlan:
    """What scene ``index`` of a build is: a room type, an entry of it and a scene seed."""

    index: int
    room_type: str
    template: str
    seed: int


def plan_scene(config: BuildConfig, source: SceneSource, index: int,
               rooms: Sequence[str] | None = None) -> ScenePlan:
    """Scene ``index``: room types cycle in order (even coverage), then an entry and a scene
    seed are drawn from ``default_rng([config.seed, index])``.

    Depends only on ``(config.seed, index)``, the room list and the source's entries, never
    on which worker or executor runs it.
    """
    rooms = list(rooms) if rooms is not None else select_rooms(config, source)
    room = rooms[int(index) % len(rooms)]
    names = source.entries(room)
    rng = np.random.default_rng([int(config.seed), int(index)])
    name = names[int(rng.integers(len(names)))]
    seed = int(rng.integers(2**31 - 1))
    return ScenePlan(int(index), room, name, seed)


def scene_folder(index: int) -> str:
    """Folder name of scene ``index`` under ``DIR/scenes/``."""
    return f"{int(index):05d}"
