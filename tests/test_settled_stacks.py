"""A soft stack settled drooping a degree or two over the one below still stands on its own
bottom face: ``ON``'s "centre of mass over the child's own base" finds the base along the
child's own axis nearest the support normal, not as the points that hang lowest."""

from __future__ import annotations

import numpy as np
import pytest

from parse3d.assets.registry import generate
from parse3d.geometry.frames import rotation_about
from parse3d.measure.checks import _stands, asset_geometry
from parse3d.scene.model import PlacedObject
from test_rooms import solved

UP = np.array([0.0, 0.0, 1.0])


def _posed(category: str, variant: str, tilt_deg: float) -> tuple[PlacedObject, np.ndarray]:
    asset = generate(category, seed=3, variant=variant)
    R = rotation_about([1.0, 0.0, 0.0], np.radians(tilt_deg))
    obj = PlacedObject("thing", category, asset, 1.0, R, np.array([1.0, 1.0, 0.5]))
    com = obj.transform(False) @ np.r_[asset_geometry(asset).com, 1.0]
    return obj, com[:3]


@pytest.mark.parametrize("tilt", (0.0, 1.0, 2.5, -2.5))
def test_a_folded_stack_tilted_a_little_stands_on_its_bottom(tilt):
    """A stack of folded sweaters stands on its bottom face upright and tilted 1-2.5 deg (the
    lowest 3 mm of a tilted stack is one edge, beyond which its centre of mass lies)."""
    obj, com = _posed("folded_clothes", "sweaters", tilt)
    assert _stands(obj, com, UP, False)


@pytest.mark.parametrize("tilt", (0.0, 2.0))
def test_an_arc_lamp_still_tips_when_tilted(tilt):
    """A floor lamp whose arc carries its shade far past its base has its centre of mass
    beyond its own base, upright or tilted a little."""
    obj, com = _posed("floor_lamp", "arc", tilt)
    assert not _stands(obj, com, UP, False)


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_clothes_on_clothes_hold_after_settling(seed):
    """Clothes ON clothes on a chair's seat: both ON relations hold after settling, the upper
    one's centre of mass over its own base."""
    scene = solved("clothes_on_clothes", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for c in scene.relations:
        if c.relation == "ON" and c.child.startswith("clothes"):
            assert c.holds_settled is True, (c.child, seed, c.residual_settled)
            assert c.residual_settled["com_inside"] == 1.0
