"""Free joints in physics: ``settle(..., free_joints=True)`` / ``parse3d settle --free-joints``.

A dresser with a drawer pulled half out and a wardrobe with a door ajar (the library's own
generated assets) are settled in a small room. With free joints each becomes a PhysX
articulation: the joint values stay within their limits and are written back, nothing
explodes, the door really swings, contacts still name parts; by default (joints locked)
the stored joint values are left untouched.
"""

from __future__ import annotations

import copy
import json

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.cli import main
from parse3d.geometry.frames import rot_z
from parse3d.pag.model import PAG, Room
from parse3d.physics import SettleConfig, extract_contacts, settle
from parse3d.physics.bodies import build_world
from parse3d.scene.model import PlacedObject, Scene
from parse3d.scene.shell import build_shell


def _moving(asset, kind: str):
    return next(j for j in asset.joints if j.type == kind and not j.is_mount)


@pytest.fixture(scope="session")
def furniture() -> Scene:
    """A dresser (a drawer at half its travel) and a wardrobe (a door 60 % open, lifted 2 cm
    so it drops onto the floor), both loose."""
    room = Room("bedroom", ((0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)), 2.6)
    scene = Scene(PAG("joints", room), 0, build_shell(room))
    dresser, wardrobe = registry.generate("dresser", 0), registry.generate("wardrobe", 0)
    drawer, door = _moving(dresser, "prismatic"), _moving(wardrobe, "revolute")
    scene.objects["dresser"] = PlacedObject("dresser", "dresser", dresser, 1.0, np.eye(3),
                                            np.array([1.0, 1.0, 0.0]),
                                            joints={drawer.name: drawer.at_ratio(0.5)})
    scene.objects["wardrobe"] = PlacedObject("wardrobe", "wardrobe", wardrobe, 1.0, rot_z(0.3),
                                             np.array([2.7, 2.6, 0.02]),
                                             joints={door.name: door.at_ratio(0.6)})
    return scene


@pytest.fixture(scope="session")
def settled_free(furniture):
    scene = copy.deepcopy(furniture)
    report = settle(scene, config=SettleConfig(steps=200, free_joints=True))
    return scene, report


def _world(scene: Scene):
    return build_world(scene, timestep=0.01, linear_damping=0.05, angular_damping=0.5,
                       max_depenetration_velocity=0.5, sleep_threshold=0.005,
                       solver_position_iterations=10, solver_velocity_iterations=1,
                       free_joints=True)


def test_free_settle_keeps_the_drawer_within_its_limits(furniture, settled_free):
    scene, report = settled_free
    d = scene.objects["dresser"]
    drawer = _moving(d.asset, "prismatic")
    lo, hi = sorted(drawer.limits)
    v = d.joints[drawer.name]
    assert lo <= v <= hi
    # nothing pulls a level drawer: it stays about where it was opened
    assert v == pytest.approx(drawer.at_ratio(0.5), abs=0.02)
    door = _moving(scene.objects["wardrobe"].asset, "revolute")
    lo, hi = sorted(door.limits)
    assert lo <= scene.objects["wardrobe"].joints[door.name] <= hi
    for o in scene.objects.values():  # every other stored value stays within its limits too
        limits = {j.name: sorted(j.limits) for j in o.asset.joints}
        assert all(limits[n][0] - 1e-9 <= x <= limits[n][1] + 1e-9 for n, x in o.joints.items())
    w = report.objects["wardrobe"]
    assert 0.015 < w.drop < 0.03 and not w.flags  # it dropped onto the floor and stood
    assert scene.meta["settle"]["config"]["free_joints"] is True
    assert furniture.objects["dresser"].joints == {drawer.name: drawer.at_ratio(0.5)}


def test_a_free_door_swings_and_nothing_explodes(furniture):
    scene = copy.deepcopy(furniture)
    world = _world(scene)
    assert set(world.articulations) == {"dresser", "wardrobe"}
    art = world.articulations["wardrobe"]
    door = _moving(scene.objects["wardrobe"].asset, "revolute")
    i, _ = art.joints[door.name]
    start = art.values()[door.name]
    qvel = np.zeros(art.articulation.dof, np.float32)
    qvel[i] = -np.sign(start) * 1.0  # push it back towards closed
    art.articulation.set_qvel(qvel)
    fastest = 0.0
    for _ in range(60):
        world.sapien_scene.step()
        for a in world.articulations.values():
            fastest = max(fastest, *(float(np.linalg.norm(lk.linear_velocity))
                                     for lk in a.links))
    now = art.values()[door.name]
    assert abs(now - start) > 0.05  # the door turned on its hinge
    lo, hi = sorted(door.limits)
    assert lo <= now <= hi
    assert fastest < 2.0
    for oid in ("dresser", "wardrobe"):
        R, t = world.pose(oid)
        assert np.isfinite(R).all() and np.isfinite(t).all()
        assert np.allclose(R.T @ R, np.eye(3), atol=1e-4) and -0.01 < t[2] < 0.05


def test_contacts_still_name_parts(settled_free):
    scene, _ = settled_free
    world = _world(scene)
    parts = {(oid, p.name) for oid, o in scene.objects.items() for p in o.asset.parts}
    owners = {world.owner(sh) for a in world.articulations.values() for lk in a.links
              for sh in lk.collision_shapes}
    assert owners and owners <= parts
    contacts = extract_contacts(scene)
    floor = {c.a if c.b == "room:floor" else c.b for c in contacts
             if "room:floor" in (c.a, c.b)}
    assert any(k.startswith("dresser:") for k in floor)
    assert all(tuple(k.split(":", 1)) in parts for k in floor if not k.startswith("room:"))


def test_default_settle_leaves_joint_values_untouched(furniture):
    scene = copy.deepcopy(furniture)
    before = {k: dict(o.joints) for k, o in scene.objects.items()}
    settle(scene, config=SettleConfig(steps=50))
    assert {k: o.joints for k, o in scene.objects.items()} == before
    assert scene.meta["settle"]["config"]["free_joints"] is False


def test_cli_free_joints_writes_the_joint_values(furniture, tmp_path, capsys):
    from parse3d.scene.io import read_scene, write_scene

    d = tmp_path / "room"
    write_scene(copy.deepcopy(furniture), d)
    with pytest.raises(SystemExit) as e:
        main(["settle", str(d), "--steps", "60", "--free-joints", "--no-glb", "--json"])
    assert not e.value.code
    report = json.loads(capsys.readouterr().out)
    assert report["config"]["free_joints"] is True
    assert all(k.split(":", 1)[0] in furniture.objects for k in report["joints_moved"])
    doc = json.loads((d / "scene.json").read_text())
    rows = {o["id"]: o for o in doc["objects"]}
    drawer = _moving(furniture.objects["dresser"].asset, "prismatic")
    assert rows["dresser"]["joints"][drawer.name] == pytest.approx(drawer.at_ratio(0.5),
                                                                   abs=0.02)
    assert read_scene(d).settled
