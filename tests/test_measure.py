"""Relation checks (parse3d.measure) on hand-built poses: each relation holds where it should
and fails where it should not, measured on real generated assets in a real room shell."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.geometry.frames import axis_angle
from parse3d.measure import (
    CHECK_RULES,
    check_edge,
    check_rule,
    object_centroid,
    select_parts,
    verify_settled,
    world_points,
)
from parse3d.pag import PAG, Room
from parse3d.pag.refs import parse_ref
from parse3d.relations import RELATIONS
from parse3d.scene.model import PlacedObject, Scene
from parse3d.scene.shell import build_shell

#: A 4 x 3 m room: wall_0 runs along y = 0 (its inside faces +Y), wall_1 along x = 4.
ROOM = Room("study", ((0, 0), (4, 0), (4, 3), (0, 3)), 2.7)
GAP = 5e-4  # the contact gap the solver leaves


@pytest.fixture(scope="module")
def assets():
    cats = ["desk", "mug", "wall_cabinet", "grocery_shelf", "pendant_lamp", "picture_frame",
            "mirror", "guitar", "storage_box", "stove", "cup", "canned_food"]
    return {c: registry.generate(c, seed=0) for c in cats}


def rot_z(deg: float) -> np.ndarray:
    return axis_angle(np.array([0, 0, 1.0]), np.deg2rad(deg))


class Room1:
    """A scene under construction: objects placed by hand, relations checked one by one."""

    def __init__(self, assets):
        self.assets = assets
        self.pag = PAG("hand-built", ROOM)
        self.scene = Scene(self.pag, 0, build_shell(ROOM))

    def put(self, oid: str, category: str, t, R=None) -> PlacedObject:
        if oid not in self.pag.objects:
            self.pag.add(oid, category)
        o = PlacedObject(oid, category, self.assets[category], 1.0,
                         np.eye(3) if R is None else np.asarray(R, float), np.asarray(t, float))
        self.scene.objects[oid] = o
        return o

    def check(self, child: str, rel: str, parent: str, **params):
        self.pag.relations.clear()
        self.pag.relate(child, rel, parent, **params)
        e = self.pag.relations[0]
        return check_edge(self.scene, e, self.scene.objects[e.child.object])


def top_z(asset, part: str) -> float:
    return float(asset.part(part).surfaces["top"].origin[2])


@pytest.fixture()
def room(assets):
    r = Room1(assets)
    r.put("desk", "desk", (2.0, 1.5, GAP))
    return r


# ---------------------------------------------------------------------------- the registry
def test_every_relation_has_exactly_one_check_rule():
    assert set(CHECK_RULES) == set(RELATIONS)
    for name, rule in CHECK_RULES.items():
        assert rule.__doc__, f"the rule for {name} documents its test"


def test_measure_stands_below_the_solver():
    """Physics and evaluations import parse3d.measure without the solver; the old module is gone."""
    code = ("import sys, parse3d.measure, parse3d.physics; "
            "bad = sorted(m for m in sys.modules if m.startswith('parse3d.solver')); "
            "assert not bad, bad")
    subprocess.run([sys.executable, "-c", code], check=True, env={**os.environ})
    assert importlib.util.find_spec("parse3d.solver.checks") is None


def test_registering_an_unknown_or_second_rule_is_refused():
    with pytest.raises(ValueError, match="unknown relation"):
        check_rule("HOVERING")(lambda ctx: None)
    with pytest.raises(ValueError, match="already has a check rule"):
        check_rule("ON")(lambda ctx: None)


# ------------------------------------------------------------------------- support relations
def test_on(room, assets):
    z = top_z(assets["desk"], "tabletop") + 1.5 * GAP + GAP
    room.put("mug", "mug", (2.0, 1.5, z))
    assert room.check("mug", "ON", "floor").holds is False
    c = room.check("mug", "ON", "desk:tabletop")
    assert c.holds, c.detail
    assert abs(c.residual["distance"]) < 2e-3
    room.put("mug", "mug", (2.0, 1.5, z + 0.05))  # hovering 5 cm above
    c = room.check("mug", "ON", "desk:tabletop")
    assert not c.holds and c.residual["distance"] > 0.04
    room.put("mug", "mug", (2.0 + 0.75, 1.5, z))  # beyond the edge of the top
    c = room.check("mug", "ON", "desk:tabletop")
    assert not c.holds and "centre of mass" in c.detail
    assert room.check("desk", "ON", "floor").holds
    room.put("desk", "desk", (2.0, 1.5, GAP), R=axis_angle(np.array([1.0, 0, 0]), 0.3))
    assert not room.check("desk", "ON", "floor").holds  # tilted: normals not anti-parallel


def test_in_a_closed_cabinet(room, assets):
    cab = assets["wall_cabinet"]
    room.put("cab", "wall_cabinet", (1.0, 0.01, 1.5))
    shelf = next(s for s in cab.internal if s.part == "body")
    z = 1.5 + float(shelf.surface.origin[2]) + GAP
    xy = shelf.surface.origin[:2] + np.array([1.0, 0.01])
    room.put("cup", "cup", (xy[0], xy[1], z))
    c = room.check("cup", "IN", "cab:body")
    assert c.holds, c.detail
    assert c.residual["enclosure"] >= 0.5
    room.put("cup", "cup", (xy[0], xy[1], z + 0.03))
    assert not room.check("cup", "IN", "cab:body").holds


def test_hanging_below(room, assets):
    lamp = assets["pendant_lamp"]
    h = float(lamp.bounds[1, 2])
    room.put("lamp", "pendant_lamp", (2.0, 1.5, ROOM.height - h - GAP))
    c = room.check("lamp", "HANGING_BELOW", "ceiling")
    assert c.holds, c.detail
    room.put("lamp", "pendant_lamp", (2.0, 1.5, ROOM.height - h - 0.1))
    assert not room.check("lamp", "HANGING_BELOW", "ceiling").holds
    assert room.check("lamp", "HANGING_BELOW", "ceiling", drop=[0.05, 0.2]).holds


def test_secured_to_a_wall(room, assets):
    pic = assets["picture_frame"]
    y = -float(pic.bounds[0, 1]) + GAP
    zc = float(pic.bounds.mean(axis=0)[2])
    room.put("pic", "picture_frame", (2.0, y, 1.5 - zc))
    c = room.check("pic", "SECURED_TO", "wall_0", height=[1.4, 1.6])
    assert c.holds, c.detail
    assert abs(c.residual["height"] - 1.5) < 1e-6
    assert not room.check("pic", "SECURED_TO", "wall_0", height=[1.7, 1.9]).holds
    assert not room.check("pic", "SECURED_TO", "wall_1").holds  # not on that wall


def test_against_names_the_part(room, assets):
    desk = assets["desk"]
    back = float(desk.part("tabletop").mesh.bounds[0, 1])
    room.put("desk", "desk", (2.0, -back + GAP, GAP))
    c = room.check("desk:tabletop@back", "AGAINST", "wall_0")
    assert c.holds, c.detail
    assert not room.check("desk:tabletop@back", "AGAINST", "wall_0", gap=0.05).holds
    room.put("desk", "desk", (2.0, -back + 0.05, GAP))
    assert room.check("desk:tabletop@back", "AGAINST", "wall_0", gap=0.05).holds
    assert not room.check("desk:tabletop@back", "AGAINST", "wall_0").holds
    room.put("desk", "desk", (2.0, -back + GAP, GAP), R=rot_z(10))
    assert not room.check("desk:tabletop@back", "AGAINST", "wall_0").holds


# ---------------------------------------------------------------------------- planes
def test_aligned_opposite_parallel(room, assets):
    box = assets["storage_box"]
    room.put("a", "storage_box", (1.0, 1.0, GAP))
    room.put("b", "storage_box", (2.0, 1.0, GAP))
    assert room.check("b@front", "ALIGNED_WITH", "a@front").holds
    assert room.check("b@front", "PARALLEL_TO", "a@front").holds
    assert not room.check("b@front", "OPPOSITE_TO", "a@front").holds
    room.put("b", "storage_box", (2.0, 1.05, GAP))  # 5 cm forward: parallel, not flush
    assert not room.check("b@front", "ALIGNED_WITH", "a@front").holds
    assert room.check("b@front", "PARALLEL_TO", "a@front").holds
    room.put("b", "storage_box", (2.0, 1.0, GAP), R=rot_z(90))
    assert not room.check("b@front", "PARALLEL_TO", "a@front").holds
    # turned around with its front in the plane of a's front: back to back
    yf = float(box.bounds[1, 1])
    room.put("b", "storage_box", (1.0, 1.0 + 2 * yf, GAP), R=rot_z(180))
    c = room.check("b@front", "OPPOSITE_TO", "a@front")
    assert c.holds, c.detail


# --------------------------------------------------------------------------- object level
def test_side_of_near_far(room, assets):
    room.put("box", "storage_box", (3.2, 1.3, GAP))
    assert room.check("box", "SIDE_OF", "desk", side="right").holds
    assert not room.check("box", "SIDE_OF", "desk", side="left").holds
    assert not room.check("box", "SIDE_OF", "desk", side="front").holds
    c = room.check("box", "NEAR", "desk", distance=1.3)
    assert c.holds and abs(c.residual["distance"] - np.hypot(1.2, 0.2)) < 2e-2
    assert not room.check("box", "NEAR", "desk", distance=1.0).holds
    assert room.check("box", "FAR_FROM", "desk", distance=1.0).holds
    assert not room.check("box", "FAR_FROM", "desk", distance=1.3).holds
    # to a wall: the distance to its plane
    c = room.check("box", "NEAR", "wall_1", distance=1.0)
    assert c.holds and abs(c.residual["distance"] - 0.8) < 1e-6
    # the desk turned by 90 degrees: its right side now points along +Y
    room.put("desk", "desk", (2.0, 1.5, GAP), R=rot_z(90))
    assert not room.check("box", "SIDE_OF", "desk", side="right").holds
    assert room.check("box", "SIDE_OF", "desk", side="back").holds


def test_toward(room, assets):
    room.put("box", "storage_box", (2.0, 0.5, GAP))  # 1 m in front of the desk's back
    assert room.check("box", "TOWARD", "desk").holds  # its front (+Y) points at the desk
    room.put("box", "storage_box", (2.0, 0.5, GAP), R=rot_z(30))
    c = room.check("box", "TOWARD", "desk")
    assert not c.holds and abs(c.residual["angle_deg"] - 30) < 0.5
    assert room.check("box", "TOWARD", "desk", tolerance_deg=35).holds
    room.put("box", "storage_box", (2.0, 0.5, GAP), R=rot_z(180))
    assert room.check("box", "TOWARD", "desk", tolerance_deg=180).holds
    assert not room.check("box", "TOWARD", "desk", tolerance_deg=170).holds


def test_centroid_and_points_follow_the_pose(room, assets):
    o = room.scene.objects["desk"]
    c = object_centroid(o)
    assert np.allclose(c[:2], [2.0, 1.5], atol=0.05)
    pts = world_points(o, hull_only=True)
    assert pts[:, 2].min() == pytest.approx(GAP, abs=1e-6)


# ------------------------------------------------------------------ semantics (issue class 8)
def test_along_is_the_strip_beside_the_face(room, assets):
    """ALONG: 0 <= (x_A - x_B) . n_side - h_B <= width + h_A and |(x_A - x_B) . n_perp| <= e / 2,
    with h_B the distance from the parent's centroid to its side face, h_A the child's from its
    centroid to its near face (the gap between the faces at most ``width``), e the parent's
    extent along the face."""
    desk = assets["desk"]
    box = assets["storage_box"]
    front = float(desk.bounds[1, 1]) - float(desk.bounds.mean(axis=0)[1])  # h_B, side front
    half = 0.5 * float(desk.bounds[1, 0] - desk.bounds[0, 0])  # e / 2
    cy = 1.5 + float(desk.bounds.mean(axis=0)[1])  # the desk's centroid y
    by = float(box.bounds.mean(axis=0)[1])  # the box's centroid offset from its origin
    hA = by - float(box.bounds[0, 1])  # the box's near face, behind its centroid

    def at(out, lateral=0.0):
        room.put("box", "storage_box", (2.0 + lateral, cy + front + out - by, GAP))
        return room.check("box", "ALONG", "desk", side="front", width=0.5)

    c = at(0.25)
    assert c.holds, c.detail
    assert c.residual["offset"] == pytest.approx(0.25, abs=1e-4)
    assert at(0.49).holds and at(0.01).holds
    assert at(0.5 + hA - 0.01).holds  # its near face within the width of the desk's
    assert not at(0.5 + hA + 0.05).holds  # beyond: the gap wider than the width
    assert not at(-0.2).holds  # over the desk itself: not beside its face
    assert at(0.25, lateral=half - 0.02).holds
    c = at(0.25, lateral=half + 0.05)  # past the end of the face
    assert not c.holds and c.residual["lateral"] == pytest.approx(half + 0.05, abs=1e-3)
    assert not room.check("box", "ALONG", "desk", side="back", width=0.5).holds
    # along a wall: measured from its inner face
    room.put("box", "storage_box", (2.0, 0.3 - by, GAP))
    c = room.check("box", "ALONG", "wall_0", side="front", width=0.5)
    assert c.holds and c.residual["offset"] == pytest.approx(0.3, abs=1e-6)
    assert not room.check("box", "ALONG", "wall_0", side="front", width=0.25 - hA).holds
    assert room.check("box", "ALONG", "wall_0", side="front", width=0.35 - hA).holds


def test_in_an_open_shelf_needs_no_enclosure(room, assets):
    """IN on a shelf part: supported on its internal surface and inside the parent's bbox
    footprint; the enclosure threshold applies to other containers only."""
    gs = assets["grocery_shelf"]
    room.put("gs", "grocery_shelf", (1.0, 1.5, 0.0))
    shelf = gs.parts_by_label("shelf")[1]
    surf = next(s for s in gs.internal if s.part == shelf.name).surface
    z = float(surf.origin[2]) + GAP
    x0, y0 = 1.0 + float(surf.origin[0]), 1.5 + float(surf.origin[1])
    room.put("can", "canned_food", (x0, y0, z))
    c = room.check("can", "IN", "gs:shelf")
    assert c.holds, c.detail
    assert c.residual["inside_footprint"] == 1.0
    assert "open shelf" in c.detail
    assert room.check("can", "IN", "gs:shelf", min_enclosure=0.9).holds
    # at the shelf's height but beside the rack: not in it
    room.put("can", "canned_food", (x0 + 1.0, y0, z))
    c = room.check("can", "IN", "gs:shelf")
    assert not c.holds and c.residual["inside_footprint"] == 0.0
    # a second can resting on the first is in a pile on the shelf
    h = float(assets["canned_food"].bounds[1, 2])
    room.put("can", "canned_food", (x0, y0, z))
    room.put("can2", "canned_food", (x0 + 0.005, y0, z + h + GAP))
    room.pag.relations.clear()
    room.pag.relate("can", "IN", "gs:shelf")
    room.pag.relate("can2", "IN", "gs:shelf")
    c = check_edge(room.scene, room.pag.relations[1], room.scene.objects["can2"])
    assert c.holds, c.detail
    assert "resting on can" in c.detail
    room.put("can2", "canned_food", (x0 + 0.005, y0, z + h + 0.03))  # hovering above it
    assert not check_edge(room.scene, room.pag.relations[1], room.scene.objects["can2"]).holds


def test_part_index_follows_the_documented_order(assets):
    """#k: bottom-to-top, then left-to-right (+X), then back-to-front (+Y), 0-based."""
    stove = assets["stove"]
    burners = stove.parts_by_label("burner")
    centres = np.array([p.mesh.bounds.mean(axis=0) for p in burners])
    assert len(burners) == 4
    # two left burners (back, then front), then two right ones (back, then front)
    assert centres[0, 0] < 0 and centres[1, 0] < 0 and centres[2, 0] > 0 and centres[3, 0] > 0
    assert centres[0, 1] < centres[1, 1] and centres[2, 1] < centres[3, 1]
    o = PlacedObject("stove", "stove", stove)
    assert select_parts(o, parse_ref("stove:burner#2")) == [burners[2]]
    assert select_parts(o, parse_ref("stove:burner#9")) == []
    shelves = assets["grocery_shelf"].parts_by_label("shelf")
    bottoms = [p.mesh.bounds[0, 2] for p in shelves]
    assert bottoms == sorted(bottoms) and len(set(np.round(bottoms, 3))) == len(bottoms)


def lean(asset, theta_deg: float, away: float = 0.0, part: str | None = None):
    """A pose tilting ``asset`` back toward wall_0 (y = 0) by ``theta_deg``, standing on the
    floor, with ``part`` (or the whole object) touching the wall, ``away`` metres off it."""
    R = axis_angle(np.array([1.0, 0, 0]), np.deg2rad(theta_deg))
    parts = asset.parts_by_label(part) if part else asset.parts
    pts = np.vstack([pc.vertices for p in parts for pc in p.pieces] or
                    [p.mesh.vertices for p in parts]) @ R.T
    allp = np.vstack([pc.vertices for p in asset.parts for pc in p.pieces]) @ R.T
    return R, np.array([2.0, -pts[:, 1].min() + GAP + away, -allp[:, 2].min() + GAP])


def test_leaning_against_means_the_named_part_touches(room, assets):
    R, t = lean(assets["mirror"], 12, part="frame")
    room.put("mirror", "mirror", t, R)
    c = room.check("mirror:frame@back", "LEANING_AGAINST", "wall_0")
    assert c.holds, c.detail
    assert c.residual["angle_deg"] == pytest.approx(12, abs=1e-6)
    room.pag.relate("mirror", "ON", "floor")  # stands on the floor, tilted by its lean
    assert check_edge(room.scene, room.pag.relations[1], room.scene.objects["mirror"]).holds
    assert not room.check("mirror:frame@back", "LEANING_AGAINST", "wall_0",
                          angle_deg=[20, 30]).holds
    assert not room.check("mirror:frame@back", "LEANING_AGAINST", "wall_1").holds
    R, t = lean(assets["mirror"], 12, away=0.05, part="frame")
    room.put("mirror", "mirror", t, R)
    assert not room.check("mirror:frame@back", "LEANING_AGAINST", "wall_0").holds
    # turned about the vertical: the named back no longer faces the wall
    R, t = lean(assets["mirror"], 12, part="frame")
    room.put("mirror", "mirror", t + [0, 0.2, 0], rot_z(40) @ R)
    assert not room.check("mirror@back", "LEANING_AGAINST", "wall_0").holds
    # a guitar leaning on its head: guitar:body@back does not hold, and says why
    R, t = lean(assets["guitar"], 12)
    room.put("guitar", "guitar", t, R)
    c = room.check("guitar:body@back", "LEANING_AGAINST", "wall_0")
    assert not c.holds and "another part touches it" in c.detail
    assert room.check("guitar@back", "LEANING_AGAINST", "wall_0").holds


# ------------------------------------------------------------------- after settling
def test_verify_settled_reports_each_cause(room, assets):
    ztop = top_z(assets["desk"], "tabletop") + GAP
    pag = room.pag
    for oid, cat in (("mug", "mug"), ("cup", "cup"), ("box", "storage_box"), ("pic", "picture_frame")):
        room.put(oid, cat, (2.0 + 0.2 * len(pag.objects), 1.5, ztop))
    room.put("box", "storage_box", (0.8, 2.0, GAP))
    room.put("pic", "picture_frame", (2.0, 0.02, 1.0))
    room.scene.objects["pic"].fixed = True
    pag.relations.clear()
    pag.relate("desk", "ON", "floor")
    pag.relate("mug", "ON", "desk:tabletop")
    pag.relate("cup", "ON", "desk:tabletop")
    pag.relate("box", "ON", "floor")
    pag.relate("pic", "SECURED_TO", "wall_0")
    with pytest.raises(ValueError, match="settled scene"):
        verify_settled(room.scene)
    for o in room.scene.objects.values():
        o.settled_rotation, o.settled_position = o.rotation.copy(), o.position.copy()
    room.scene.settled = True
    assert verify_settled(room.scene) == []
    mug, cup, box, desk = (room.scene.objects[k] for k in ("mug", "cup", "box", "desk"))
    mug.settled_position = np.array([3.3, 1.5, GAP])  # fell off the desk onto the floor
    mug.flags = ["left_support"]
    cup.settled_position = cup.position + [0, 0, 0.02]  # lifted 2 cm: still close, relation broken
    box.settled_rotation = axis_angle(np.array([1.0, 0, 0]), np.deg2rad(30))
    assert ("box", "tipped") not in {(i.object_id, i.cause) for i in verify_settled(room.scene)}, \
        "turned in place, its centre of mass no lower: not tipped over"
    box.settled_position = box.position - [0, 0, 0.03]  # turned and fallen over onto an edge
    room.scene.objects["pic"].settled_position = np.array([2.0, 0.5, 0.0])  # fixed: ignored
    got = {(i.object_id, i.cause) for i in verify_settled(room.scene)}
    assert got == {("mug", "fell"), ("mug", "left_support"), ("cup", "broke_support"),
                   ("box", "tipped"), ("box", "broke_support")}
    by = {(i.object_id, i.cause): i for i in verify_settled(room.scene)}
    assert by[("mug", "fell")].value == pytest.approx(ztop - GAP)
    assert by[("box", "tipped")].value == pytest.approx(30.0)
    assert "gap 20" in by[("cup", "broke_support")].detail
    assert by[("cup", "broke_support")].relation == 2
    assert verify_settled(room.scene, tip_angle_deg=45) and \
        ("box", "tipped") not in {(i.object_id, i.cause) for i in verify_settled(room.scene, tip_angle_deg=45)}
    # what the desk carries moves with it
    desk.settled_position = desk.position - [0, 0, 0.1]
    d = next(i for i in verify_settled(room.scene) if i.object_id == "desk")
    assert d.cause == "fell" and set(d.carries) == {"mug", "cup"}


def test_exact_drop_sees_round_bodies_touching_between_vertices():
    """An apple leaning on another at 78 deg from the vertical, 50 um apart: the rays from
    hull vertices read a drop of millimetres (more than the contact distance, so a settled pile
    read as broken), the mesh-on-mesh drop finds the contact."""
    from parse3d.measure.checks import DIST_TOL
    from parse3d.measure.geometry import drop_distance, exact_drop

    apple = registry.generate("apple", seed=0)
    below = PlacedObject("a", "apple", apple, 1.0, np.eye(3), np.zeros(3))
    th = np.deg2rad(78)
    d = np.array([np.sin(th), 0.0, np.cos(th)])
    R = axis_angle(np.array([1.0, 0, 0]), np.deg2rad(30))
    far = PlacedObject("b", "apple", apple, 1.0, R, 0.2 * d)
    # slide in along the contact direction until 50 um short of touching
    s = exact_drop(apple, far.transform(), apple, below.transform(), -d, 0.16, tol=1e-5)
    assert 0.1 < s < 0.16
    on = PlacedObject("b", "apple", apple, 1.0, R, 0.2 * d - (s - 5e-5) * d)
    down = np.array([0, 0, -1.0])
    rays = drop_distance(world_points(on, hull_only=True), apple, on.transform(),
                         world_points(below, hull_only=True), apple, below.transform(), down)
    exact = exact_drop(apple, on.transform(), apple, below.transform(), down, rays)
    assert rays > DIST_TOL
    assert exact <= min(1e-3, rays)
    # along the contact direction: the 50 um gap, to the bisection's 0.25 mm; not touching
    # within the bound: the bound
    assert exact_drop(apple, on.transform(), apple, below.transform(), -d, 1e-3) <= 2.5e-4
    assert exact_drop(apple, far.transform(), apple, below.transform(), down, 0.01) == 0.01
