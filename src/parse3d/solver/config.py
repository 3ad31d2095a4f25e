"""Solver options, per-stage random generators and the internal failure signal."""

from __future__ import annotations

import zlib
from dataclasses import dataclass

import numpy as np

__all__ = ["SolverConfig", "stage_rng", "STRATEGIES", "SEARCHES", "STRUCTURAL_FAILURES"]

#: Position sampling: Algorithm 1, or the rejection baseline the paper argues against.
STRATEGIES = ("constrained", "rejection")
#: Search over objects: one pass in assembly order, or with conflict-directed backjumping.
SEARCHES = ("greedy", "backtracking")

#: Consecutive validation failures of the same relation after which an asset is given up.
STRUCTURAL_FAILURES = 8


@dataclass(frozen=True)
class SolverConfig:
    """Solver options (saved into scene.json).

    Attributes
    ----------
    max_trials : int
        Pose samples per asset attempt before giving up.
    asset_attempts : int
        Assets (and scales) tried per object before it fails.
    strategy : str
        ``constrained`` (Algorithm 1) or ``rejection`` (the baseline).
    margin : float
        Metres kept between a footprint and the edge of its support polygon.
    wall_thickness : float
        Metres, for the room shell's slabs.
    search : str
        ``backtracking`` (re-place the objects a failure's constraint involves, within
        ``search_budget``) or ``greedy`` (one pass in assembly order).
    search_budget : int
        Re-placements of already placed objects the backtracking search may spend per scene.
    moves_per_failure : int
        Re-placements of other objects (backjumps, clearing a wall, moving a group or the
        support) one failing object may spend before it is relaxed or fails.
    relax : bool
        Relax a non-support relation that cannot be met (recorded ``holds: false`` with what
        blocked it) rather than fail the object; False keeps every relation hard (``--strict``).
    """

    max_trials: int = 30
    asset_attempts: int = 4
    strategy: str = "constrained"
    margin: float = 0.003
    wall_thickness: float = 0.12
    search: str = "backtracking"
    search_budget: int = 24
    moves_per_failure: int = 24
    relax: bool = True

    def __post_init__(self):
        if self.strategy not in STRATEGIES:
            raise ValueError(f"unknown strategy {self.strategy!r} (use {' or '.join(STRATEGIES)})")
        if self.search not in SEARCHES:
            raise ValueError(f"unknown search {self.search!r} (use {' or '.join(SEARCHES)})")
        if int(self.search_budget) < 0 or int(self.max_trials) < 1 or int(self.asset_attempts) < 1:
            raise ValueError("search_budget must be >= 0, max_trials and asset_attempts >= 1")

    def to_dict(self) -> dict:
        return {"max_trials": self.max_trials, "asset_attempts": self.asset_attempts,
                "strategy": self.strategy, "margin": self.margin,
                "wall_thickness": self.wall_thickness, "search": self.search,
                "search_budget": int(self.search_budget),
                "moves_per_failure": int(self.moves_per_failure), "relax": bool(self.relax)}


def stage_rng(seed: int, stage: str) -> np.random.Generator:
    """One generator per (scene seed, stage name)."""
    return np.random.default_rng([int(seed), zlib.crc32(stage.encode())])


class Fail(Exception):
    """An object could not be placed; the message names the constraint and what blocked it.

    ``intrinsic`` marks failures that no other object caused (the asset's own geometry, a
    support too small even when empty), which re-placing other objects cannot fix.
    """

    def __init__(self, message: str, *, intrinsic: bool = False):
        super().__init__(message)
        self.intrinsic = intrinsic
