"""A pen ON a notebook's front cover while the notebook lies on its back cover: the cover's
``top`` is the face that is up now; the spine, which runs along the cover's upper edge when
the notebook stands, does not cover it (solved, settled and repaired as ``parse3d solve``
does)."""

from __future__ import annotations

import numpy as np
import pytest

from parse3d.measure.checks import world_points
from test_rooms import solved


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_pens_rest_on_the_up_face_of_a_lying_pads_cover(seed):
    """Every object placed and none fell; each pen rests on its pad's front cover (the part
    chosen), its ON relation holds as solved, and it lies over the pad: its centre within the
    pad's footprint, above the pad's lowest point."""
    scene = solved("pens_on_lying_pads", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    held = {(c.relation, c.child): c.holds for c in scene.relations}
    for pen, pad in (("pen1", "pad1"), ("pen2", "pad2")):
        o = scene.objects[pen]
        assert o.support_choice.owner == pad, (pen, seed, o.support_choice)
        assert scene.objects[pad].asset.part(o.support_choice.part).label == "front_cover", \
            (pen, seed, o.support_choice)
        assert held[("ON", pen)] is True, (pen, seed)
        pts = world_points(o, hull_only=True, settled=False)
        box = world_points(scene.objects[pad], hull_only=True, settled=False)
        c = pts.mean(axis=0)
        assert np.all(c[:2] >= box[:, :2].min(axis=0)) and np.all(c[:2] <= box[:, :2].max(axis=0))
        assert pts[:, 2].min() >= box[:, 2].max() - 5e-3, (pen, seed)
