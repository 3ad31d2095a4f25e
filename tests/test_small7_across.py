"""A keyboard across the two arms of an X-stand: the arms are narrower than its underside and
its rubber feet hang past them, its ends over the upper ends of the stand's legs. It comes to
rest on the arms' tops (probing the stand from the keyboard's hull corners misses the arms and
meets the legs' ends 3 cm lower), and its ``ON`` holds with the feet below the arms' level."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from parse3d.measure import summarize_settled
from parse3d.solver.bars import across_drop
from parse3d.solver.library import AssetLibrary
from parse3d.solver.state import plane_coords
from test_rooms import solved

SEEDS = (0, 1, 2, 3)


def _arms_top(stand):
    """The first arm's top surface and the arms' tops in its plane coordinates (as modelled)."""
    arms = stand.parts_by_label("arm")
    s = arms[0].surfaces["top"]
    polys = []
    for p in arms:
        t = p.surfaces["top"]
        xy = np.asarray(t.polygon.exterior.coords)
        w = t.origin + xy[:, :1] * t.u + xy[:, 1:2] * t.v
        polys.append(shapely.Polygon(plane_coords(s, w)))
    return s, shapely.union_all(polys)


@pytest.mark.parametrize("offset", (-0.06, 0.0, 0.05))
def test_the_drop_across_narrow_arms_meets_their_tops(offset):
    """A 61-key controller held 5 mm over an X-stand's arms (centred between them, moved
    ``offset`` m along them) may drop 5 mm: its body's underside meets the arms' tops, not
    the legs' ends below them."""
    lib = AssetLibrary()
    stand, keys = lib.load("keyboard_stand", 15), lib.load("midi_keyboard", 1)
    assert "x_frame" in stand.asset_id and "controller61" in keys.asset_id
    s, solid = _arms_top(stand)
    pts = np.vstack([pc.vertices for p in keys.parts for pc in p.piece_arrays])
    body = min(float(pc.vertices[:, 2].min()) for p in keys.parts_by_label("body")
               for pc in p.piece_arrays)
    mid = 0.5 * (pts.min(axis=0) + pts.max(axis=0))
    # the keyboard's long axis across the arms (both along the asset's x)
    t = np.array([-mid[0], -mid[1] + offset + s.origin[1], s.origin[2] + 0.005 - body])
    # it reaches past both arms, over the legs' upper ends
    assert pts[:, 0].min() + t[0] < solid.bounds[0] + s.origin[0] - 0.1
    assert pts[:, 0].max() + t[0] > solid.bounds[2] + s.origin[0] + 0.1
    np.testing.assert_allclose(across_drop(keys, 1.0, np.eye(3), t, s, solid), 0.005,
                               rtol=1e-3, atol=1e-5)
    # beside the arms it meets nothing: no drop onto them
    far = t + np.array([0.0, 1.0, 0.0])
    assert across_drop(keys, 1.0, np.eye(3), far, s, solid) == np.inf


@pytest.mark.parametrize("seed", SEEDS)
def test_keyboards_rest_across_x_stand_arms(seed):
    """Three keyboards ON their stands' ``arm`` (X, Z and table stands, as drawn): all placed,
    every relation held after settling, nothing fallen, each keyboard level where it was put
    and its underside at its arms' top."""
    scene = solved("keyboards_across_narrow_arms", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    s = summarize_settled(scene)
    assert s.complete and s.keeps_relations()
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    assert not [o.id for o in scene.objects.values() if o.flags], \
        {o.id: o.flags for o in scene.objects.values() if o.flags}
    for k in "abc":
        keys = scene.objects[f"keys_{k}"]
        np.testing.assert_allclose(keys.settled_position, keys.position, atol=5e-3)
        up = keys.transform(True)[:3, 2] / keys.scale
        assert up[2] >= np.cos(np.radians(2.0)), (k, up)
        c = next(c for c in scene.relations if c.child == f"keys_{k}" and c.relation == "ON")
        assert abs(c.residual_settled["distance"]) <= 5e-3, c.residual_settled
