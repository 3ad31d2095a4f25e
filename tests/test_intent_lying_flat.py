"""Notebooks and magazines written ``ON`` a desk with no part named lie on a cover, as a person
means; books in a row on a shelf stand as modelled (solved, settled and repaired as ``parse3d
solve`` does)."""

from __future__ import annotations

import numpy as np
import pytest

from parse3d.measure.checks import world_points
from test_rooms import solved


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_notebooks_on_a_desk_lie_and_books_in_a_row_stand(seed):
    """Everything placed, every relation held after settling; the notebook and the magazine
    lie (no taller than 4 cm, their cover's face recorded as ``rests_on``), the pen on the
    notebook above it, the books beside one another on the shelf stand (taller than wide)."""
    scene = solved("notebooks_lie_on_a_desk", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    for oid in ("notebook", "magazine"):
        o = scene.objects[oid]
        ext = np.ptp(world_points(o, hull_only=True, settled=True), axis=0)
        assert ext[2] <= 0.04 and o.rests_on in ("back", "left"), (oid, seed, ext, o.rests_on)
    pen = world_points(scene.objects["pen"], hull_only=True, settled=True)
    pad = world_points(scene.objects["notebook"], hull_only=True, settled=True)
    assert pen[:, 2].min() >= pad[:, 2].max() - 5e-3, seed
    for oid in ("book1", "book2"):
        ext = np.ptp(world_points(scene.objects[oid], hull_only=True, settled=True), axis=0)
        assert ext[2] > min(ext[0], ext[1]), (oid, seed, ext)
