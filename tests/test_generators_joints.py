"""Articulation: which categories carry joints, what the joint contract catches, and how joint
values pose parts (mounted handles follow their doors; drawers slide out, doors swing out).

The validity of every generated joint is checked by the asset contract
(``tests/test_asset_contract.py`` runs ``check_asset``, which includes ``check_joints``).
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.assets.cache import load_asset, save_asset
from parse3d.assets.contract import check_joints
from parse3d.assets.model import Joint, joint_order

#: (category, variant) pairs whose assets must articulate, as the issue lists them.
ARTICULATED = [("storage_cabinet", "two_door"), ("wardrobe", "hinged"), ("dresser", "wide"),
               ("nightstand", "two_drawer"), ("desk", "four_leg"), ("kitchen_counter", "drawer_bank"),
               ("wall_cabinet", "solid"), ("refrigerator", "top_freezer"), ("stove", "gas"),
               ("washing_machine", "front_loader"), ("tv_stand", "drawers"), ("storage_box", "wooden"),
               ("filing_cabinet", "vertical"), ("freezer_chest", "small"), ("bathroom_vanity", "drawers")]


@functools.cache
def _asset(category: str, variant: str, seed: int = 0):
    return registry.generate(category, seed, variant)


def _movable(asset):
    return [j for j in asset.joints if not j.is_mount]


@pytest.mark.parametrize(("category", "variant"), ARTICULATED)
def test_listed_categories_articulate(category: str, variant: str) -> None:
    if variant not in registry.get(category).variants:
        variant = registry.get(category).variants[0]
    # a desk draws its drawer by chance: look over a few seeds
    assets = [_asset(category, variant, s) for s in range(4 if category == "desk" else 1)]
    found = [a for a in assets if _movable(a)]
    assert found, f"{category} ({variant}) has no movable joint"
    a = found[0]
    assert check_joints(a) == []
    kinds = {j.type for j in _movable(a)}
    labels = {a.part(j.child_part).label for j in _movable(a)}
    assert labels & {"door", "drawer_box", "lid", "freezer_door"}, labels
    if "drawer_box" in labels:
        assert "prismatic" in kinds
    if "door" in labels:
        assert "revolute" in kinds


def test_door_swings_out_and_its_handle_follows() -> None:
    a = _asset("storage_cabinet", "two_door")
    door = next(j for j in a.joints if j.child_part == "door_0")
    assert door.type == "revolute" and np.isclose(abs(door.axis[2]), 1.0)
    body_front = a.part("body").bounds[1, 1]
    T = a.part_transforms(ratio=1.0)
    moved = a.part("door_0").mesh.copy()
    moved.apply_transform(T["door_0"])
    assert moved.bounds.mean(axis=0)[1] > body_front + 0.1  # swung out in front of the cabinet
    np.testing.assert_allclose(T["door_0_handle"], T["door_0"])  # the handle is mounted on it
    # the hinge line lies on the door's back edge, where the hinge barrels are
    hinge = a.part("door_0_hinge_0").mesh.bounds.mean(axis=0)
    assert np.linalg.norm((hinge - np.asarray(door.origin))[:2]) < 0.01
    # closed is the modelled pose
    np.testing.assert_allclose(a.part_transforms({})["door_0"], np.eye(4))


def test_drawer_slides_out_by_its_travel_with_front_and_handle() -> None:
    a = _asset("filing_cabinet", "vertical")
    slide = next(j for j in a.joints if j.name == "drawer_0_slide")
    assert slide.type == "prismatic" and slide.child_part == "drawer_0_box"
    T = a.part_transforms({"drawer_0_slide": 10.0})  # clipped to the upper limit
    np.testing.assert_allclose(T["drawer_0_box"][:3, 3], np.asarray(slide.axis) * slide.limits[1])
    for mounted in ("drawer_0", "drawer_0_handle", "drawer_0_label"):
        np.testing.assert_allclose(T[mounted], T["drawer_0_box"])
    # the drawer keeps the label 'drawer' on its front: PAGs written before still find the face
    assert [p.name for p in a.parts_by_label("drawer")][:1] == ["drawer_0"]
    assert any(s.part.endswith("_box") for s in a.internal)  # the open box is an IN target


def test_joints_survive_the_cache(tmp_path) -> None:
    a = _asset("freezer_chest", "small")
    path = tmp_path / "a.npz"
    save_asset(a, path)
    b = load_asset(path)
    assert [j.to_dict() for j in b.joints] == [j.to_dict() for j in a.joints]


def _broken(asset, **changes):
    j = _movable(asset)[0]
    bad = dataclasses.replace(j, **changes)
    return dataclasses.replace(asset, joints=[bad if x is j else x for x in asset.joints])


@pytest.mark.parametrize(("changes", "message"), [
    ({"child_part": "nope"}, "does not have"),
    ({"axis": (0.0, 0.0, 2.0)}, "unit vector"),
    ({"limits": (1.0, -1.0)}, "not ordered"),
    ({"limits": (0.5, 1.0)}, "closed pose 0"),
    ({"type": "ball"}, "type"),
])
def test_contract_catches_bad_joint_fields(changes, message) -> None:
    problems = check_joints(_broken(_asset("storage_cabinet", "two_door"), **changes))
    assert any(message in p for p in problems), problems


def test_contract_catches_a_door_swinging_into_the_cabinet() -> None:
    a = _asset("storage_cabinet", "two_door")
    j = next(j for j in a.joints if j.child_part == "door_0")
    inward = (-j.limits[1], 0.0) if j.limits[1] > 0 else (0.0, -j.limits[0])
    problems = check_joints(dataclasses.replace(a, joints=[dataclasses.replace(x, limits=inward) if x is j else x
                                                           for x in a.joints]))
    assert any("into" in p for p in problems), problems


def test_contract_catches_a_drawer_pulled_off_its_runners() -> None:
    a = _asset("filing_cabinet", "vertical")
    j = next(j for j in a.joints if j.name == "drawer_0_slide")
    far = dataclasses.replace(a, joints=[dataclasses.replace(x, limits=(0.0, 3.0)) if x is j else x for x in a.joints])
    problems = check_joints(far)
    assert any("away from the rest of the asset" in p for p in problems), problems


def test_contract_catches_a_joint_cycle() -> None:
    a = _asset("filing_cabinet", "vertical")
    loop = [Joint("a", "prismatic", "drawer_0_box", "drawer_1_box", (0, 1.0, 0), (0, 0, 0), (0.0, 0.1)),
            Joint("b", "prismatic", "drawer_1_box", "drawer_0_box", (0, 1.0, 0), (0, 0, 0), (0.0, 0.1))]
    problems = check_joints(dataclasses.replace(a, joints=loop))
    assert any("cycle" in p for p in problems), problems


def test_joint_order_puts_parents_first() -> None:
    a = _asset("filing_cabinet", "vertical")
    order = [j.child_part for j in joint_order(list(reversed(a.joints)))]
    for j in a.joints:
        if j.parent_part in order:
            assert order.index(j.parent_part) < order.index(j.child_part)
