"""What rests across several like parts named by their label (a suitcase ON a luggage rack's
``strap``, a keyboard ON an X-stand's ``arm``): it is held by all the parts at that level, its
wheels or feet free to hang between or past them, and it stays there through settling."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from shapely.geometry import MultiPoint

from parse3d.measure.checks import world_points
from parse3d.solver.geometry import asset_geometry
from test_rooms import solved


def _tops(obj, label: str) -> list:
    """The settled footprints of ``obj``'s parts with ``label`` and the heights of their tops."""
    T = obj.transform(True)
    out = []
    for p in obj.asset.parts_by_label(label):
        w = np.vstack([pc.vertices for pc in p.piece_arrays]) @ T[:3, :3].T \
            + T[:3, 3]
        out.append((MultiPoint(w[:, :2]).convex_hull, float(w[:, 2].max())))
    return out


@pytest.mark.parametrize("seed", (0, 1, 2, 3))
@pytest.mark.parametrize("child,owner,label", [("case", "rack", "strap"),
                                               ("keys", "stand", "arm")])
def test_a_thing_rests_across_the_like_parts(seed, child, owner, label):
    scene = solved("across_like_parts", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    held = {(c.relation, c.child): c.holds_settled for c in scene.relations}
    assert held[("ON", child)] is True, held
    o = scene.objects[child]
    w = world_points(o, settled=True)
    tops = _tops(scene.objects[owner], label)
    level = max(z for _, z in tops)
    # after settling it lies across two parts or more at their level, not on one
    foot = MultiPoint(w[:, :2]).convex_hull
    under = [g for g, z in tops if abs(z - level) < 5e-3 and g.intersects(foot)]
    assert len(under) >= 2, (child, len(under))
    # held where it was put: settling neither drops nor tilts it
    np.testing.assert_allclose(o.settled_position, o.position, atol=5e-3)
    up = o.transform(True)[:3, 2] / o.scale
    assert up[2] >= np.cos(np.radians(2.0)), up
    over = shapely.union_all(under)
    # its centre of mass over the hull of the parts' tops
    T = o.transform(True)
    com = T[:3, :3] @ asset_geometry(o.asset).com + T[:3, 3]
    assert over.convex_hull.contains(shapely.Point(com[:2])), (child, com)
