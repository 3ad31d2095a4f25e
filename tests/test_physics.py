"""Settling in SAPIEN, part-level contacts, and an independent check in MuJoCo.

Scenes are built by hand: generated assets posed exactly on their supports (the collision
pieces' lowest point on the support's top surface).
"""

from __future__ import annotations

import json

import networkx as nx
import numpy as np
import pytest
from shapely.geometry import Polygon

from parse3d.assets import registry
from parse3d.geometry.frames import rot_x, rot_z
from parse3d.pag.model import PAG, Room
from parse3d.physics import (
    SettleConfig,
    contact_graph,
    contacts_from_json,
    contacts_to_json,
    extract_contacts,
    settle,
)
from parse3d.physics.bodies import build_world
from parse3d.physics.collision import asset_collision, shell_collision
from parse3d.physics.contacts import (
    clip_triangles_to_boxes,
    closest_point_on_triangles,
    signed_distance,
)
from parse3d.physics.mujoco import mujoco_motion
from parse3d.physics.settle import settle_world
from parse3d.scene.model import PlacedObject, Scene
from parse3d.scene.shell import build_shell

ROOM = Room("study", ((0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0)), 2.7)


def new_scene(room: Room = ROOM) -> Scene:
    return Scene(PAG("physics-test", room), 0, build_shell(room))


def put(scene: Scene, oid: str, category: str, seed: int, *, xy, z: float, R=None,
        support: str | None = None, fixed: bool = False, variant: str | None = None,
        lift: float = 0.0) -> PlacedObject:
    """Place an asset with its lowest collision point at height ``z + lift``."""
    asset = registry.generate(category, seed, variant)
    R = np.eye(3) if R is None else np.asarray(R, float)
    zmin = (asset_collision(asset).pieces.vertices @ R.T)[:, 2].min()
    pos = np.array([xy[0], xy[1], z + lift - zmin])
    obj = PlacedObject(oid, category, asset, 1.0, R, pos, support=support, fixed=fixed)
    scene.objects[oid] = obj
    return obj


def top_of(scene: Scene, oid: str, part: str) -> tuple[np.ndarray, float]:
    """World (x, y) centre and height of the top of a part's collision pieces."""
    obj = scene.objects[oid]
    data = asset_collision(obj.asset)
    ws = data.pieces.transformed(obj.rotation, obj.position, obj.scale)
    idx = [i for i, p in enumerate(ws.parts) if p == part]
    lo = ws.bounds[idx, 0].min(0)
    hi = ws.bounds[idx, 1].max(0)
    return (lo[:2] + hi[:2]) / 2, float(hi[2])


def touching(contacts, a_obj: str, b_obj: str) -> set[tuple[str, str]]:
    """Part pairs ``(a part, b part)`` in contact between two objects."""
    out = set()
    for c in contacts:
        (oa, pa), (ob, pb) = c.a.split(":", 1), c.b.split(":", 1)
        if (oa, ob) == (a_obj, b_obj):
            out.add((pa, pb))
        elif (oa, ob) == (b_obj, a_obj):
            out.add((pb, pa))
    return out


def desk_scene() -> Scene:
    sc = new_scene()
    put(sc, "desk", "desk", 1, xy=(2.0, 1.5), z=0.0, R=rot_z(0.3), support="floor")
    return sc


# ------------------------------------------------------------------------- kernels


def test_closest_point_on_triangles_matches_dense_sampling():
    rng = np.random.default_rng(0)
    tri = rng.normal(size=(200, 3, 3))
    p = rng.normal(size=(200, 3)) * 2
    q = closest_point_on_triangles(p, tri[:, 0], tri[:, 1], tri[:, 2])
    d = np.linalg.norm(p - q, axis=1)
    # dense barycentric sampling can only find points at least as far
    u, v = np.meshgrid(np.linspace(0, 1, 60), np.linspace(0, 1, 60))
    m = (u + v) <= 1
    u, v = u[m], v[m]
    pts = (tri[:, None, 0] * (1 - u - v)[None, :, None] + tri[:, None, 1] * u[None, :, None]
           + tri[:, None, 2] * v[None, :, None])
    dense = np.linalg.norm(pts - p[:, None], axis=2).min(1)
    assert np.all(d <= dense + 1e-9)
    assert np.all(dense - d < 0.05 * (1 + dense))


def test_signed_distance_to_a_box_is_exact():
    import trimesh

    from parse3d.physics.collision import _hull, _pack

    cube = _pack(["cube"], [_hull(trimesh.creation.box((1.0, 1.0, 1.0)).vertices)])
    rng = np.random.default_rng(1)
    p = rng.uniform(-1.5, 1.5, size=(4000, 3))
    d = signed_distance(p, np.zeros(len(p), int), cube)
    q = np.abs(p) - 0.5
    exact = np.linalg.norm(np.maximum(q, 0), axis=1) + np.minimum(q.max(1), 0)
    assert np.allclose(d, exact, atol=1e-9)


def test_clipped_areas_match_shapely():
    rng = np.random.default_rng(2)
    tris = rng.uniform(0, 1, size=(300, 3, 3))
    tris[..., 2] = 0.0
    lo = np.tile([0.2, 0.3, -1.0], (300, 1))
    hi = np.tile([0.7, 0.8, 1.0], (300, 1))
    _, areas = clip_triangles_to_boxes(tris, lo, hi)
    box = Polygon([(0.2, 0.3), (0.7, 0.3), (0.7, 0.8), (0.2, 0.8)])
    ref = [Polygon(t[:, :2]).intersection(box).area for t in tris]
    assert np.allclose(areas.sum(1), ref, atol=1e-9)


def test_shell_over_a_non_convex_footprint_is_split_into_convex_prisms():
    room = Room("l_shape", ((0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)), 2.5)
    sh = shell_collision(build_shell(room))
    floor = [i for i, p in enumerate(sh.parts) if p == "floor"]
    assert len(floor) > 1
    outline = Polygon(room.footprint).buffer(0.12, join_style="mitre")
    # the prisms tile the slab: their volumes add up to the slab's
    assert np.isclose(sh.volumes[floor].sum(), outline.area * 0.1, rtol=1e-6)
    sc = new_scene(room)
    put(sc, "table", "side_table", 0, xy=(0.8, 3.2), z=0.0, support="floor")
    parts = {b for (_, b) in touching(extract_contacts(sc), "table", "room")}
    assert parts == {"floor"}


# --------------------------------------------------------------------- contacts


def test_book_lying_on_desk_touches_the_tabletop_only():
    sc = desk_scene()
    (cx, cy), ztop = top_of(sc, "desk", "tabletop")
    # lying on its back cover: the book's -Y (back) turned down
    put(sc, "book", "book", 0, xy=(cx + 0.1, cy), z=ztop, R=rot_z(0.3) @ rot_x(np.pi / 2),
        support="desk:tabletop@top")
    report = settle(sc)
    assert not report.flagged("fell") and not report.flagged("left_support")
    contacts = extract_contacts(sc)
    pairs = touching(contacts, "book", "desk")
    assert ("back_cover", "tabletop") in pairs
    assert {d for _, d in pairs} == {"tabletop"}
    assert not touching(contacts, "book", "room")
    # the desk stands on its legs
    assert {b for (_, b) in touching(contacts, "desk", "room")} == {"floor"}


def test_cup_in_a_wall_cabinet_touches_its_shelf_only():
    sc = new_scene()
    cab = registry.generate("wall_cabinet", 0)
    depth = cab.extents[1]
    obj = PlacedObject("cabinet", "wall_cabinet", cab, 1.0, np.eye(3),
                       np.array([2.0, depth / 2, 1.3]), support="wall_0@front", fixed=True)
    sc.objects["cabinet"] = obj
    shelf = cab.parts_by_label("shelf")[0].name
    (cx, cy), ztop = top_of(sc, "cabinet", shelf)
    put(sc, "cup", "cup", 1, xy=(cx, cy), z=ztop, support=f"cabinet:{shelf}@top")
    report = settle(sc)
    assert report.objects["cabinet"].displacement == 0.0
    assert not report.flagged("left_support")
    pairs = touching(extract_contacts(sc), "cup", "cabinet")
    assert {p for _, p in pairs} == {shelf}


def test_a_stack_of_plates_gives_a_chain_of_contacts():
    sc = desk_scene()
    (cx, cy), ztop = top_of(sc, "desk", "tabletop")
    # each plate 3 mm above the one below's rim height: they drop and nest
    put(sc, "plate0", "plate", 4, xy=(cx, cy), z=ztop, support="desk:tabletop@top")
    for k in (1, 2):
        below = sc.objects[f"plate{k - 1}"]
        h = below.world_bounds()[1, 2]
        put(sc, f"plate{k}", "plate", 4, xy=(cx, cy), z=h + 0.003, support=f"plate{k - 1}:body@top")
    settle(sc)
    g = contact_graph(extract_contacts(sc))
    # a plate is several parts (well, rim, foot ring): contract each plate to one node
    plate = {n: n.split(":")[0] for n in g if n.startswith("plate")}
    g = nx.relabel_nodes(g, plate)
    assert g.has_edge("desk:tabletop", "plate0")
    assert g.has_edge("plate0", "plate1")
    assert g.has_edge("plate1", "plate2")
    assert not g.has_edge("desk:tabletop", "plate2")
    assert nx.shortest_path_length(g, "desk:tabletop", "plate2") == 3


def test_an_object_5mm_above_its_support_falls_onto_it():
    sc = desk_scene()
    (cx, cy), ztop = top_of(sc, "desk", "tabletop")
    put(sc, "mug", "mug", 2, xy=(cx - 0.2, cy), z=ztop, lift=0.005, support="desk:tabletop@top")
    assert not touching(extract_contacts(sc, settled=False), "mug", "desk")
    report = settle(sc)
    m = report.objects["mug"]
    assert 0.004 < m.drop < 0.006
    assert m.tilt_deg < 2.0 and not m.flags
    # the mug stands on its base: its body, or the foot ring under it
    assert {("body", "tabletop"), ("foot_ring", "tabletop")} & touching(extract_contacts(sc),
                                                                      "mug", "desk")


def test_an_unsupported_object_is_flagged():
    sc = desk_scene()
    # a mug floating well beside the desk falls to the floor
    put(sc, "mug", "mug", 0, xy=(0.5, 0.5), z=0.8, support="desk:tabletop@top")
    report = settle(sc)
    assert {"fell", "left_support"} <= set(report.objects["mug"].flags)
    assert "fell" in sc.objects["mug"].flags
    assert "floor" in {b for (_, b) in touching(extract_contacts(sc), "mug", "room")}


def test_a_fallen_object_is_frozen_once_it_has_landed():
    sc = desk_scene()
    (cx, cy), ztop = top_of(sc, "desk", "tabletop")
    put(sc, "mug", "mug", 2, xy=(cx, cy), z=ztop, lift=0.003, support="desk:tabletop@top")
    put(sc, "bowl", "bowl", 1, xy=(0.5, 0.5), z=0.8, support="desk:tabletop@top")
    report = settle(sc)
    assert sc.meta["settle"]["dropped_out"] == ["bowl"]
    assert {"fell", "left_support"} <= set(report.objects["bowl"].flags)
    # it left where it landed, on the floor, not in the air
    assert sc.objects["bowl"].settled_position[2] < 0.05
    assert "floor" in {b for (_, b) in touching(extract_contacts(sc), "bowl", "room")}
    # the rest settled as before and the run stopped once it slept
    assert report.early_exit and not report.objects["mug"].flags
    off = settle(sc, config=SettleConfig(drop_out=0.0))
    assert sc.meta["settle"]["dropped_out"] == [] and "fell" in off.objects["bowl"].flags


def test_objects_of_many_pieces_make_contacts_only_when_near():
    """A vessel of many wall pieces (a saucer) gets the settling's small contact offset; a
    book of four pieces keeps PhysX's default."""
    sc = desk_scene()
    (cx, cy), ztop = top_of(sc, "desk", "tabletop")
    put(sc, "saucer", "saucer", 0, xy=(cx, cy), z=ztop, support="desk:tabletop@top")
    put(sc, "book", "book", 0, xy=(cx - 0.3, cy), z=ztop, R=rot_x(np.pi / 2),
        support="desk:tabletop@top")
    cfg = SettleConfig()
    assert len(asset_collision(sc.objects["saucer"].asset).pieces) >= cfg.many_pieces
    assert len(asset_collision(sc.objects["book"].asset).pieces) < cfg.many_pieces
    world = settle_world(sc, cfg)
    offsets = {}
    for sh in world.shapes:
        offsets.setdefault(world.owner(sh)[0], set()).add(round(sh.get_contact_offset(), 4))
    assert offsets["saucer"] == {0.004}
    assert offsets["book"] == {0.01}
    report = settle(sc)
    assert not report.objects["saucer"].flags and not report.objects["book"].flags


# ------------------------------------------------------------ a furnished corner


def corner_scene() -> Scene:
    """Desk with a book, a mug and a plate; side table with a tea cup; a wall cabinet with a
    cup; a bookcase with a book on a shelf."""
    sc = desk_scene()
    (cx, cy), ztop = top_of(sc, "desk", "tabletop")
    R = rot_z(0.3)
    put(sc, "book", "book", 0, xy=(cx + 0.15, cy), z=ztop, R=R @ rot_x(np.pi / 2),
        support="desk:tabletop@top")
    off = R @ np.array([-0.3, 0.1, 0])
    put(sc, "mug", "mug", 2, xy=(cx + off[0], cy + off[1]), z=ztop, R=rot_z(1.0),
        support="desk:tabletop@top")
    off = R @ np.array([-0.3, -0.15, 0])
    put(sc, "plate", "plate", 1, xy=(cx + off[0], cy + off[1]), z=ztop,
        support="desk:tabletop@top")
    put(sc, "side", "side_table", 0, xy=(0.6, 2.3), z=0.0, support="floor")
    (sx, sy), stop = top_of(sc, "side", "tabletop")
    put(sc, "tea", "tea_cup", 0, xy=(sx, sy), z=stop, support="side:tabletop@top")
    cab = registry.generate("wall_cabinet", 0)
    sc.objects["cabinet"] = PlacedObject("cabinet", "wall_cabinet", cab, 1.0, np.eye(3),
                                         np.array([3.0, cab.extents[1] / 2, 1.3]),
                                         support="wall_0@front", fixed=True)
    shelf = cab.parts_by_label("shelf")[0].name
    (kx, ky), ktop = top_of(sc, "cabinet", shelf)
    put(sc, "cup", "cup", 1, xy=(kx, ky), z=ktop, support=f"cabinet:{shelf}@top")
    bc = put(sc, "bookcase", "bookcase", 0, xy=(0.0, 0.0), z=0.0, R=rot_z(-np.pi / 2),
             support="floor")
    # against wall_3 (x = 0), facing +X
    bc.position[:2] = [bc.asset.extents[1] / 2 + 0.002, 1.2]
    sh = bc.asset.parts_by_label("shelf")[1].name
    (bx, by), btop = top_of(sc, "bookcase", sh)
    put(sc, "book2", "book", 3, xy=(bx, by), z=btop, R=rot_z(-np.pi / 2),
        support=f"bookcase:{sh}@top")
    return sc


@pytest.fixture(scope="module")
def corner():
    sc = corner_scene()
    report = settle(sc)
    return sc, report


def test_settled_scene_barely_moves(corner):
    sc, report = corner
    moved = report.moved(distance=0.01, angle_deg=2.0)
    assert len(moved) <= 0.05 * len(report.objects), moved
    for flag in ("fell", "tipped", "left_support"):
        assert not report.flagged(flag), (flag, report.to_dict())
    assert sc.settled and sc.meta["settle"]["config"] == SettleConfig().to_dict()
    # settling again from the settled poses changes nothing
    again = Scene(sc.pag, sc.seed, sc.room)
    for o in sc.placed:
        again.objects[o.id] = PlacedObject(o.id, o.category, o.asset, o.scale,
                                           o.settled_rotation, o.settled_position,
                                           support=o.support, fixed=o.fixed)
    second = settle(again)
    assert all(m.displacement < 0.002 and m.rotation_deg < 0.5 for m in second.objects.values())


def test_settled_scene_rests_in_mujoco(corner):
    sc, _ = corner
    motion = mujoco_motion(sc, seconds=1.0)
    assert set(motion) == set(sc.objects)
    worst = max(motion.values(), key=lambda m: m.displacement)
    assert worst.displacement < 0.01, worst
    assert motion["cabinet"].displacement == 0.0


def test_early_exit_matches_the_full_run():
    sc = desk_scene()
    (cx, cy), ztop = top_of(sc, "desk", "tabletop")
    put(sc, "mug", "mug", 2, xy=(cx, cy), z=ztop, lift=0.003, support="desk:tabletop@top")
    early = settle(sc)
    pose_early = sc.objects["mug"].settled_position.copy()
    full = settle(sc, config=SettleConfig(early_exit=False))
    assert early.early_exit and early.steps < full.steps == 1000
    assert np.allclose(pose_early, sc.objects["mug"].settled_position, atol=1e-4)
    # sleep is checked after every step, not only at the fallen-body checks: the run stops at
    # the step where the mug fell asleep, whatever check_every is, at the same pose
    every = settle(sc, config=SettleConfig(check_every=1))
    assert every.steps == early.steps
    assert np.allclose(pose_early, sc.objects["mug"].settled_position, atol=1e-4)


def test_contacts_agree_with_the_engine(corner):
    sc, _ = corner
    ours = extract_contacts(sc)
    world = build_world(sc, timestep=0.01, linear_damping=0.05, angular_damping=0.5,
                        max_depenetration_velocity=0.5, sleep_threshold=0.005,
                        solver_position_iterations=10, solver_velocity_iterations=1,
                        settled=True)
    world.sapien_scene.step()  # one step generates the contact pairs
    engine: dict[frozenset, float] = {}
    for c in world.system.get_contacts():
        a, b = (world.owner(s) for s in c.shapes)
        if a[0] == b[0] or not c.points:
            continue
        key = frozenset((f"{a[0]}:{a[1]}", f"{b[0]}:{b[1]}"))
        sep = min(p.separation for p in c.points)
        engine[key] = min(engine.get(key, np.inf), sep)
    mine = {frozenset((c.a, c.b)): c.min_distance for c in ours}
    dynamic = set(world.dynamic)
    # every part pair the engine sees within 1 mm, the extraction has
    close = {k for k, s in engine.items() if s <= 0.001}
    assert close, "the engine reports no resting contact"
    assert close <= set(mine), close - set(mine)
    # and every pair the extraction finds touching (with a simulated body) the engine sees
    # within its contact offset, at a matching distance
    for k, d in mine.items():
        if not any(x.split(":")[0] in dynamic for x in k) or d > 0.0005:
            continue
        assert k in engine, k
        assert engine[k] <= 0.002


def test_contacts_are_deterministic_and_round_trip(corner):
    sc, _ = corner
    a = extract_contacts(sc)
    b = extract_contacts(sc)
    assert a == b
    assert all(c.a < c.b and c.samples > 0 and c.min_distance <= 0.001 for c in a)
    rows = json.loads(json.dumps(contacts_to_json(a)))
    assert set(rows[0]) == {"a", "b", "samples", "min_distance"}
    back = contacts_from_json(rows)
    assert [(c.a, c.b, c.samples) for c in back] == [(c.a, c.b, c.samples) for c in a]
    g = contact_graph(a)
    assert g.number_of_edges() == len(a)
    assert g.nodes["room:floor"]["room"] and g.nodes["desk:tabletop"]["object"] == "desk"


def test_contacts_of_some_pairs_are_those_sampled_among_all_bodies(corner):
    from parse3d.physics.collision import scene_bodies
    from parse3d.physics.contacts import _aggregate, contact_samples

    sc, _ = corner
    pairs = [("book", "desk"), ("mug", "desk"), ("cup", "cabinet"), ("tea", "side"),
             ("bookcase", "room")]
    kw = {"threshold": 0.001, "samples_per_m2": 2000.0}
    among_all = _aggregate(contact_samples(scene_bodies(sc), pairs=pairs, **kw))
    assert extract_contacts(sc, pairs=pairs, **kw) == among_all
    assert {c.a.split(":")[0] for c in among_all} | {c.b.split(":")[0] for c in among_all} \
        == {"book", "desk", "mug", "cup", "cabinet", "tea", "side", "bookcase", "room"}
    assert extract_contacts(sc, pairs=[("nothing", "here")]) == []


def test_touching_parts_agrees_with_the_sampled_contacts(corner):
    from parse3d.physics.contacts import touching_parts

    sc, _ = corner
    contacts = extract_contacts(sc)
    part_pairs = {(c.a, c.b) for c in contacts} | {(c.b, c.a) for c in contacts}
    asked = [(a.split(":")[0], b.split(":")[0], b.split(":", 1)[1]) for a, b in part_pairs]
    # every part pair sampled within 1 mm is within 1 mm exactly
    assert touching_parts(sc, asked) == set(asked)
    # pairs far apart, and a part the body touches nowhere, are not
    far = [("mug", "side", None), ("tea", "desk", None), ("book", "desk", "leg_0"),
           ("book2", "room", "floor")]
    assert not touching_parts(sc, far)
    assert touching_parts(sc, [("desk", "room", None), ("mug", "nothing", None)]) == \
        {("desk", "room", None)}


def test_touching_parts_measures_the_gap_exactly():
    from parse3d.physics.contacts import touching_parts

    for lift, near in ((0.0005, True), (0.0015, False)):
        sc = desk_scene()
        (cx, cy), ztop = top_of(sc, "desk", "tabletop")
        put(sc, "box", "book", 0, xy=(cx, cy), z=ztop, lift=lift, support="desk:tabletop@top")
        got = touching_parts(sc, [("box", "desk", "tabletop")], threshold=0.001, settled=False)
        assert bool(got) is near, lift


def test_settle_command_writes_settled_scene_and_contacts(tmp_path):
    from typer.testing import CliRunner

    from parse3d.cli import app
    from parse3d.scene.io import read_scene, write_scene

    sc = desk_scene()
    (cx, cy), ztop = top_of(sc, "desk", "tabletop")
    put(sc, "mug", "mug", 2, xy=(cx, cy), z=ztop, lift=0.004, support="desk:tabletop@top")
    write_scene(sc, tmp_path, glb=False)
    res = CliRunner().invoke(app, ["settle", str(tmp_path), "--no-glb", "--json"])
    assert res.exit_code == 0, res.output
    out = json.loads(res.output)
    assert out["objects"]["mug"]["drop"] > 0.003
    rows = json.loads((tmp_path / "contacts.json").read_text())
    # the mug stands on its base (its body, or the foot ring under it)
    assert any(r["a"] == "desk:tabletop" and r["b"] in ("mug:body", "mug:foot_ring")
               for r in rows), rows
    back = read_scene(tmp_path)
    assert back.settled and back.objects["mug"].settled_position is not None
    bad = CliRunner().invoke(app, ["settle", str(tmp_path), "--dt", "0"])
    assert bad.exit_code != 0
