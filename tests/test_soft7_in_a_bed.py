"""``IN`` a whole object with no inside that has room for the child: a blanket IN a child's
bed. The bed's only insides are the ledges of the tape sewn round its mattress, a few
millimetres wide with the mattress standing in them; the blanket lies on the bed's largest
free top, the mattress, and the ``IN`` check measures it there. A teddy IN a basket, which has
room inside, still goes in it. Solved, settled and repaired as ``parse3d solve`` does (real
SAPIEN physics)."""

from __future__ import annotations

import numpy as np
import pytest

from test_rooms import solved


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_blanket_in_a_bed_lies_on_its_mattress(seed):
    from parse3d.measure.checks import world_points

    scene = solved("blanket_in_a_small_bed", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    assert not [o.id for o in scene.objects.values() if "fell" in o.flags]
    blanket, bed = scene.objects["blanket"], scene.objects["small_bed"]
    assert blanket.support_choice.owner == "small_bed"
    (mattress,) = [p for p in bed.asset.parts if p.name == blanket.support_choice.part]
    assert mattress.label == "mattress"
    T = bed.transform(True)
    top = float((mattress.bounds[1, 2] * bed.scale) + T[2, 3])
    pts = world_points(blanket, settled=True)
    np.testing.assert_allclose(pts[:, 2].min(), top, atol=0.02)
    held = {(c.relation, c.child): c for c in scene.relations}
    assert held[("IN", "blanket")].holds_settled, held[("IN", "blanket")].residual_settled
    assert held[("IN", "teddy")].holds_settled
    assert scene.objects["teddy"].support_choice.owner == "toy_basket"


def test_an_inside_with_room_is_kept():
    """The reading asks for no inside with room: a basket's floor takes a teddy, a bed's tape
    ledges take nothing a blanket's width."""
    from parse3d.assets import registry
    from parse3d.measure.insides import child_extents, open_inside

    blanket = registry.generate("blanket", 0, variant="folded")
    w, _, h = child_extents(blanket, 1.0)
    bed = registry.generate("bed", 11, variant="storage")
    assert bed.internal and not open_inside(bed, 0.6, w / 2, h)
    basket = registry.generate("basket", 0)
    assert open_inside(basket, 1.0, 0.05, 0.05)
