"""Plants on a window's sill: the pool has windows with sills from 8 to 22 cm deep in front of
the frame and herb pots 9-13 cm across, so a plant written ON a sill stands on it (its pot on
the sill, its leaves free to reach past the edge into the room), solved, settled and repaired
as ``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import numpy as np
import pytest

from parse3d.assets import registry
from test_rooms import solved


def _extent(asset, label: str) -> np.ndarray:
    """``(3,)`` extents (m, unit scale) of the parts labelled ``label``."""
    v = np.vstack([np.asarray(p.mesh.vertices) for p in asset.parts_by_label(label)])
    return np.ptp(v, axis=0)


def test_window_sills_come_narrow_and_deep():
    """Over a handful of windows the sill's depth in front of the frame spans narrow (about
    10 cm) to deep (above 18 cm) sills."""
    depths = []
    for seed in range(12):
        a = registry.generate("window", seed)
        depths.append(float(_extent(a, "sill")[1] - _extent(a, "frame")[1]))
    assert min(depths) >= 0.08 - 1e-6 and max(depths) <= 0.22 + 1e-6, depths
    assert min(depths) < 0.12 and max(depths) > 0.18, depths


def test_a_herb_pot_is_small_and_its_leaves_reach_past_the_rim():
    """The herb variant: a pot 9-13 cm across, the leaves over it wider than the pot's foot."""
    for seed in range(4):
        a = registry.generate("potted_plant", seed, variant="herb")
        pot, leaves = _extent(a, "pot"), _extent(a, "plant")
        assert 0.09 - 1e-3 <= max(pot[0], pot[1]) <= 0.13 + 1e-3, pot
        assert max(leaves[0], leaves[1]) > 0.75 * max(pot[0], pot[1]), (pot, leaves)


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_plants_stand_on_a_window_sill_and_a_narrow_shelf(seed):
    """A herb named by its pot and a plant with no scale ON a window's sill, a small plant ON
    a narrow wall shelf: every object placed, each plant resting on what it was written ON,
    every relation held after settling, nothing fell."""
    scene = solved("plants_on_a_sill", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for oid, owner in (("basil", "window"), ("fern", "window"), ("cactus", "ledge")):
        assert scene.objects[oid].support_choice.owner == owner, oid
    broken = [(c.relation, c.child, c.parent, c.residual_settled, c.relaxed)
              for c in scene.relations if c.holds_settled is not True]
    assert not broken, broken
    assert not [o.id for o in scene.objects.values() if "fell" in o.flags]
