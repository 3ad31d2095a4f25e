"""Flat things filed on a shelf that does not hold them lying stand on an edge in a row
(records written ``IN`` one shelf side by side, scores ``IN`` another), and bottles ``IN`` a
wine rack's cradles lie on their side (solved, settled and repaired as ``parse3d solve``
does)."""

from __future__ import annotations

import numpy as np
import pytest

from parse3d.assets.registry import generate
from parse3d.measure.checks import world_points
from parse3d.solver.upright import filed_flat
from test_rooms import solved

ROOM = "records_filed_on_edge"


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_records_and_scores_stand_on_edge_in_a_row(seed):
    """Everything placed, nothing fell, every relation held after settling (the records'
    ``SIDE_OF`` read along the row); each filed slab on the crowded shelves stands (taller than
    it is thick, its edge recorded as ``rests_on``; a score standing likewise) and the records
    stand in one row: their thin axes parallel, each centre within 5 cm of the next along the
    row."""
    scene = solved(ROOM, seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    fallen = [(o.id, o.flags) for o in scene.objects.values() if {"fell", "tipped"} & set(o.flags)]
    assert not fallen, (seed, fallen)
    records = [scene.objects[f"record{i}"] for i in range(1, 10)]
    slabs = [o for o in records if filed_flat(o.asset)]
    assert len(slabs) >= 7, seed
    for o in slabs:
        ext = np.ptp(world_points(o, hull_only=True, settled=True), axis=0)
        assert o.rests_on in ("left", "back"), (o.id, seed, o.rests_on)
        assert ext[2] > 4 * min(ext[0], ext[1]), (o.id, seed, ext)
    for i in range(1, 5):  # a score stands on its shelf when four do not fit there lying
        o = scene.objects[f"score{i}"]
        ext = np.ptp(world_points(o, hull_only=True, settled=True), axis=0)
        assert not o.rests_on or ext[2] > 4 * min(ext[0], ext[1]), (o.id, seed, ext)
    thin = np.array([o.settled_rotation[:, 2] if o.settled_rotation is not None
                     else o.rotation[:, 2] for o in slabs])
    assert np.all(np.abs(thin @ thin[0]) > np.cos(np.deg2rad(10))), seed
    along = np.sort([float(world_points(o, hull_only=True, settled=True).mean(axis=0) @ thin[0])
                     for o in slabs])
    assert np.all(np.diff(along) < 0.05), (seed, np.diff(along))



@pytest.mark.parametrize(("category", "variant", "filed"), [
    ("vinyl_record", "single", True), ("vinyl_record", "lp", True),
    ("sheet_music", "booklet", True), ("sheet_music", "loose", True),
    ("vinyl_record", "bare", False), ("plate", None, False), ("book", None, False)])
def test_what_is_filed_on_edge(category, variant, filed):
    """A slab modelled lying with a rectangular outline (a record in its sleeve, a score) is
    filed on its edge when crowded; a bare disc and a plate (round: they pile) and a book
    (modelled standing already) are not."""
    assert filed_flat(generate(category, 1, variant)) is filed


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_bottles_lie_in_a_wine_rack_and_stand_on_a_table(seed):
    """Every bottle placed and every
    relation held after settling; those IN the rack's cradles (free height below a bottle's
    height) lie on their side (``rests_on`` recorded, their long axis level) along the rack's
    depth, neck to the front; the one ON the table stands."""
    scene = solved("bottles_in_a_wine_rack", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    rack = scene.objects["rack"]
    front = rack.rotation[:, 1]
    for oid in ("bottle1", "bottle2", "bottle3"):
        o = scene.objects[oid]
        R = o.settled_rotation if o.settled_rotation is not None else o.rotation
        axis = R[:, 2]  # the bottle's base-to-neck axis
        assert o.rests_on == "back", (oid, seed, o.rests_on)
        assert abs(float(axis[2])) < np.sin(np.deg2rad(10)), (oid, seed, axis)
        assert float(axis @ front) > np.cos(np.deg2rad(15)), (oid, seed, axis, front)
    o = scene.objects["bottle4"]
    R = o.settled_rotation if o.settled_rotation is not None else o.rotation
    assert o.rests_on is None and float(R[2, 2]) > np.cos(np.deg2rad(5)), seed
