"""ALONG with a width narrower than the child's own depth toward the parent's face (a dryer
8 cm along a washer, a stove 5 cm beside a fridge, a bed 20 cm beside a nightstand): the
width is the gap between the faces. The centroid strip alone would lie inside the parent's
and the child's footprints, so the relation could never hold; the child stands beside the
face instead, the gap within the width. A bed beside a nightstand, longer along the face
than it, has the face's middle within its length (its centroid a metre from the wall cannot
be within the nightstand's 40 cm). Solved, settled and repaired as ``parse3d solve`` does."""

from __future__ import annotations

import pytest

from test_rooms import solved


@pytest.mark.parametrize("seed", (0, 1, 2, 3))
def test_units_stand_side_by_side(seed):
    """Every object placed, nothing fell; each ALONG holds as placed and after settling, the
    child beyond the face by at least its own depth toward it and at most that plus the
    width."""
    scene = solved("units_abutting", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for o in scene.objects.values():
        assert "fell" not in o.flags, (o.id, seed, o.flags)
    pag = {(e.child.object, e.parent.object): e for e in scene.pag.relations
           if e.relation == "ALONG"}
    along = [c for c in scene.relations if c.relation == "ALONG"]
    assert len(along) == 3
    for c in along:
        assert c.relaxed is None, (c.child, seed, c.relaxed)
        assert c.holds is True and c.holds_settled is True, (c.child, seed, c.detail)
        w = pag[(c.child, c.parent)].param("width")
        # the centroid strip (0 to the width) is inside the units: the child stands beyond it
        assert c.residual_settled["offset"] > w, (c.child, seed, c.residual_settled)
    # the bed's centroid lies past the nightstand's end along the face (its half length)
    bed = next(c for c in along if c.child == "bed")
    assert abs(bed.residual_settled["lateral"]) > 0.3, (seed, bed.residual_settled)

