"""Things that hang or are mounted by their own hardware: a part hung below a small part
(a mug by its handle on a cup hook, a saucepan by its handle on a pot rail's bar) touches it
by that part, what reaches higher standing beside it; solved, settled and repaired as
``parse3d solve`` does (real SAPIEN physics)."""

from __future__ import annotations

import pytest

from test_rooms import solved


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_hung_by_a_handle_beside_what_reaches_higher(seed):
    """Every object placed; each mug's and the saucepan's HANGING_BELOW holds after settling
    as written (not relaxed to the rim or the lid knob), their handle's top within a contact
    gap of the hook's or the rail's underside, and nothing fell."""
    scene = solved("hung_by_a_handle", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for oid in ("cup_a", "cup_b", "saucepan"):
        (c,) = [c for c in scene.relations if c.relation == "HANGING_BELOW"
                and c.child.startswith(oid)]
        assert c.relaxed is None, (oid, c.relaxed)
        assert c.holds_settled is True, (oid, c.residual_settled)
        assert scene.objects[oid].fixed, oid
    broken = [(c.relation, c.child, c.parent, c.residual_settled) for c in scene.relations
              if c.holds_settled is not True and c.relaxed is None]
    assert not broken, broken


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_hung_and_mounted_by_their_own_hardware(seed):
    """A jacket named by its collar on a wall hook and a coat named by its garment on a coat
    tree hang by the loop in the collar (an instance without a hanger); a TV named by its back
    cover on a wall and a monitor on a cart's mount are instances without a stand, their back
    cover (with the VESA plate on it) touching; each such support holds as written after
    settling. A TV ON a console stands on its feet. Nothing fell."""
    from parse3d.measure import verify_settled
    from parse3d.solver.choice import stands

    scene = solved("hung_and_mounted_by_their_hardware", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for oid in ("anorak", "parka", "screen", "panel"):
        (c,) = [c for c in scene.relations if c.relation in ("HANGING_BELOW", "SECURED_TO")
                and c.child.startswith(oid + ":")]
        assert c.relaxed is None, (oid, c.relaxed)
        assert c.holds_settled is True, (oid, c.residual_settled)
    for oid in ("anorak", "parka"):
        asset = scene.objects[oid].asset
        assert asset.parts_by_label("loop") and not asset.parts_by_label("hook"), asset.asset_id
    for oid in ("screen", "panel"):
        asset = scene.objects[oid].asset
        assert asset.parts_by_label("vesa_plate") and not asset.parts_by_label("stand"), \
            asset.asset_id
    tv = scene.objects["set"].asset
    assert tv.parts_by_label("stand") and stands(tv), tv.asset_id
    assert not [i for i in verify_settled(scene) if i.cause == "fell"]
