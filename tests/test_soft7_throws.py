"""A throw written ``ON`` a narrow top of a seat hangs over it (``solver/over.py``): over a
sofa's back cushions when the sofa stands against a wall (not behind it, through the wall),
over what stands as high as the cushions in front of them (the pillows leaning there), folded
to clear the seat below; over one armrest of an armchair, though the two armrests written
without an index span a gap wide enough to lie on. Solved, settled and repaired as
``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import numpy as np
import pytest
from shapely.geometry import MultiPoint, Polygon

from test_rooms import solved

THROWS = {"couch_throw": ("couch", "back_cushion"), "arm_throw": ("reading_chair", "armrest")}


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_throws_hang_over_the_part_written(seed):
    from parse3d.measure.checks import world_points

    scene = solved("throws_over_seat_backs_and_arms", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    assert not [o.id for o in scene.objects.values() if "fell" in o.flags]
    floor = Polygon(np.asarray(scene.room.footprint, float)).buffer(1e-3)
    for oid, (owner, label) in THROWS.items():
        o = scene.objects[oid]
        assert o.fixed, oid
        assert o.support_choice.owner == owner
        part = next(p for p in scene.objects[owner].asset.parts if p.name == o.support_choice.part)
        assert part.label == label, (oid, part.name)
        pts = world_points(o, settled=True)
        assert floor.contains(MultiPoint(pts[:, :2].tolist())), oid  # not through a wall
        # its top level with the bar's top
        V = np.asarray(part.mesh.vertices, float)
        T = scene.objects[owner].transform(True)
        top = float((V @ T[:3, :3].T + T[:3, 3])[:, 2].max())
        np.testing.assert_allclose(pts[:, 2].max(), top, atol=0.02)
    for c in scene.relations:
        if c.child in THROWS:
            assert c.holds_settled or (c.relaxed is not None and "hangs over" in c.relaxed["blocked"]), c
