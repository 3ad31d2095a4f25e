"""Flat things IN a rack of tines (plates and a saucer IN a dish rack) stand on edge between
two tines, resting on the rack's floor grid, and stay there through settling. Solved, settled
and repaired as ``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import numpy as np
import pytest

from test_rooms import solved

FLAT = ("plate1", "plate2", "plate3", "saucer")


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_plates_stand_on_edge_between_the_tines(seed):
    """Every object placed, none fell. Each plate rests on an edge face (``rests_on``), its
    face upright after settling (its thin axis within 30 degrees of level), its middle in the
    rack's footprint and between two neighbouring tines along the row, and its IN holds after
    settling."""
    from parse3d.measure.checks import world_points

    scene = solved("plates_in_a_dish_rack", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    assert not [o.id for o in scene.objects.values() if "fell" in o.flags]
    rack = scene.objects["rack"]
    T = rack.transform(True)
    tines = np.array([(np.asarray(p.bounds, float).mean(axis=0) * rack.scale) @ T[:3, :3].T
                      + T[:3, 3] for p in rack.asset.parts if p.label == "tine"])
    row = tines[-1, :2] - tines[0, :2]
    row /= np.linalg.norm(row)
    along = np.sort(tines[:, :2] @ row)
    box = world_points(rack, settled=True)
    for oid in FLAT:
        o = scene.objects[oid]
        assert o.rests_on in ("left", "right", "front", "back"), (oid, o.rests_on)
        R = o.transform(True)[:3, :3] / o.scale
        thin = int(np.argmin(np.ptp(o.asset.mesh_arrays().vertices, axis=0)))
        tilt = np.degrees(np.arcsin(min(1.0, abs(float(R[2, thin])))))
        assert tilt < 30.0, (oid, tilt)
        c = world_points(o, settled=True).mean(axis=0)
        assert (box.min(axis=0)[:2] <= c[:2]).all() and (c[:2] <= box.max(axis=0)[:2]).all()
        x = float(c[:2] @ row)
        assert along[0] < x < along[-1], (oid, x, along)
    for c in scene.relations:
        assert c.holds_settled, (c.relation, c.child, c.parent, c.residual_settled)


def test_the_rule_asks_for_a_row_of_upright_parts_and_a_flat_child():
    """A dish rack's tines make one row, its gaps wider than a plate is thick; a counter has
    no such row, and a mug is no flat child."""
    from parse3d.assets import registry
    from parse3d.solver.slots import _flat, slot_rows

    def pieces(o):
        T = o.transform(False)
        return [(p.name, pc.vertices @ T[:3, :3].T + T[:3, 3]) for p in o.asset.parts
                for pc in p.piece_arrays]

    scene = solved("plates_in_a_dish_rack", 0)
    rack, counter = scene.objects["rack"], scene.objects["counter"]
    (row,) = slot_rows(rack.asset, pieces(rack))
    centres, d, gaps, _ = row
    assert len(centres) == 8 and abs(float(d[2])) < 1e-9
    assert (gaps > 0.02).all()
    assert slot_rows(counter.asset, pieces(counter)) == []
    plate = scene.objects["plate1"]
    assert _flat(plate.asset, plate.scale) is not None
    assert _flat(registry.generate("mug", 0), 1.0) is None
