"""Loaders for real part-split assets, the user library and collision pieces.

Fixtures are written by the tests themselves: a part-split GLB made of boxes and a
PartNet-Mobility-style folder (URDF, OBJs, semantics.txt).
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import trimesh
from shapely.geometry import Polygon

from parse3d.assets import registry
from parse3d.assets.cache import load_asset
from parse3d.assets.collision import convex_pieces
from parse3d.assets.contract import check_asset
from parse3d.assets.loaders import (
    SourceFrame,
    add_assets,
    default_label,
    frame_rotation,
    load_glb,
    load_partnet_mobility,
    register_library,
)
from parse3d.errors import InputError

CHAIR = ("seat", "back", "leg")


def write_chair_glb(path, *, names=("seat", "back", "leg_0", "leg_1", "leg_2", "leg_3")):
    """A chair in glTF's frame (+Y up, front +Z): the back is at -Z."""
    sc = trimesh.Scene()
    seat = trimesh.creation.box((0.45, 0.05, 0.45))
    seat.apply_translation((0, 0.45, 0))
    back = trimesh.creation.box((0.45, 0.5, 0.05))
    back.apply_translation((0, 0.725, -0.2))
    meshes = [seat, back]
    for x, z in [(-0.2, -0.2), (0.2, -0.2), (-0.2, 0.2), (0.2, 0.2)]:
        leg = trimesh.creation.box((0.04, 0.425, 0.04))
        leg.apply_translation((x, 0.2125, z))
        meshes.append(leg)
    for name, m in zip(names, meshes, strict=False):
        m.visual.face_colors = (200, 120, 40, 255)
        sc.add_geometry(m, node_name=name, geom_name=name)
    sc.export(path)
    return path


def _obj(path, mesh):
    path.write_text(trimesh.exchange.obj.export_obj(mesh, include_normals=False, include_texture=False))


def write_partnet_cabinet(folder):
    """A cabinet in PartNet-Mobility's raw frame (+Y up, front -Z) with the usual root joint.

    ``link_0`` the frame (an L of two boards, so not convex), ``link_1`` a door
    hinged on the left, ``link_2`` its handle. The door is at raw -Z, the cabinet's front.
    """
    objs = folder / "textured_objs"
    objs.mkdir(parents=True)
    slab = trimesh.creation.box((0.6, 0.05, 0.4))
    slab.apply_translation((0, 0.025, 0))
    panel = trimesh.creation.box((0.6, 0.599, 0.05))
    panel.apply_translation((0, 0.3005, 0.175))  # two separate bodies, as modelled parts often are
    _obj(objs / "original-1.obj", trimesh.util.concatenate([slab, panel]))
    hinge = np.array([-0.3, 0.0, -0.21])
    door = trimesh.creation.box((0.6, 0.6, 0.02))
    door.apply_translation(np.array([0, 0.3, -0.21]) - hinge)  # stored in the link's frame
    _obj(objs / "original-2.obj", door)
    handle = trimesh.creation.box((0.02, 0.12, 0.03))
    handle.apply_translation(np.array([0.22, 0.3, -0.235]) - hinge)
    _obj(objs / "original-3.obj", handle)
    h = " ".join(str(x) for x in hinge)
    mh = " ".join(str(-x) for x in hinge)
    (folder / "mobility.urdf").write_text(f"""<?xml version="1.0"?>
<robot name="cabinet">
  <link name="base"/>
  <link name="link_0"><visual name="frame"><origin xyz="0 0 0"/>
    <geometry><mesh filename="textured_objs/original-1.obj"/></geometry></visual></link>
  <joint name="joint_0" type="fixed"><origin rpy="1.570796326794897 0 -1.570796326794897" xyz="0 0 0"/>
    <child link="link_0"/><parent link="base"/></joint>
  <link name="link_1"><visual name="door"><origin xyz="0 0 0"/>
    <geometry><mesh filename="textured_objs/original-2.obj"/></geometry></visual></link>
  <joint name="joint_1" type="revolute"><origin xyz="{h}"/><axis xyz="0 1 0"/>
    <child link="link_1"/><parent link="link_0"/><limit lower="0" upper="1.57"/></joint>
  <link name="link_2"><visual name="handle"><origin xyz="{mh}"/>
    <geometry><mesh filename="textured_objs/original-3.obj"/></geometry></visual></link>
  <joint name="joint_2" type="fixed"><origin xyz="{h}"/>
    <child link="link_2"/><parent link="link_1"/></joint>
</robot>
""")
    (folder / "semantics.txt").write_text("link_0 static cabinet_frame\nlink_1 hinge rotation_door\n"
                                          "link_2 static handle\n")
    return folder


CABINET_MAP = {"cabinet_frame": "frame", "rotation_door": "door"}


@pytest.fixture
def restore_registry():
    registry.categories()
    saved = dict(registry._REGISTRY)
    yield
    registry._REGISTRY.clear()
    registry._REGISTRY.update(saved)


def test_default_label_and_frames():
    assert [default_label(n) for n in ("leg_0", "Leg.001", "leg 2", "back", "arm_rest12")] == \
        ["leg", "leg", "leg", "back", "arm_rest"]
    R = frame_rotation("+y", "+z")  # glTF
    np.testing.assert_allclose(R @ [0, 1, 0], [0, 0, 1])
    np.testing.assert_allclose(R @ [0, 0, 1], [0, 1, 0])
    assert np.isclose(np.linalg.det(R), 1.0)
    with pytest.raises(InputError, match="perpendicular"):
        frame_rotation("+y", "-y")
    with pytest.raises(InputError, match="one of"):
        frame_rotation("up", "+z")


def test_glb_chair_passes_the_contract(tmp_path):
    path = write_chair_glb(tmp_path / "chair.glb")
    a = load_glb(path, category="test_chair", size_range=(0.8, 1.2), cache_dir=tmp_path / "coacd")
    assert check_asset(a, vocabulary=CHAIR, required=CHAIR, size_range=(0.8, 1.2)) == []
    assert sorted(p.name for p in a.parts) == ["back", "leg_0", "leg_1", "leg_2", "leg_3", "seat"]
    # glTF front +Z became +Y: the back rest is behind the seat, at -Y, and up is +Z
    assert a.part("back").mesh.centroid[1] < a.part("seat").mesh.centroid[1] - 0.1
    assert a.part("back").bounds[1, 2] == pytest.approx(a.bounds[1, 2])
    np.testing.assert_allclose(a.extents, [0.45, 0.45, 0.975], atol=1e-5)
    # leg_k follow the #k order: same height, so left-to-right then back-to-front
    xs = [round(float(a.part(f"leg_{k}").mesh.centroid[0]), 3) for k in range(4)]
    assert xs == sorted(xs)
    assert a.parts[0].material.color[0] == pytest.approx(200 / 255, abs=0.01)
    assert a.meta["generator"] == "loaded" and a.meta["fit_scale"] == 1.0
    # a box part is convex: its hull is its one collision piece, no decomposition needed
    assert all(len(p.pieces) == 1 for p in a.parts)


def test_glb_front_axis_and_scale(tmp_path):
    path = write_chair_glb(tmp_path / "chair.glb")
    a = load_glb(path, category="test_chair", frame=SourceFrame("+y", "-z", 1.0),
                 size_range=(0.1, 5.0), cache_dir=tmp_path / "c")
    assert a.part("back").mesh.centroid[1] > a.part("seat").mesh.centroid[1] + 0.1
    # centimetre units scaled into the size range: 97.5 m is clamped to 2 m
    b = load_glb(path, category="test_chair", frame=SourceFrame("+y", "+z", 100.0),
                 size_range=(0.5, 2.0), cache_dir=tmp_path / "c")
    assert b.size == pytest.approx(2.0)
    assert b.meta["fit_scale"] == pytest.approx(2.0 / 97.5)


def test_glb_mapping_and_errors(tmp_path):
    path = write_chair_glb(tmp_path / "chair.glb", names=("Cushion", "Backrest", "l0", "l1", "l2", "l3"))
    mapping = {"Cushion": "seat", "Backrest": "back", "l": "leg"}
    a = load_glb(path, category="test_chair", mapping=mapping, size_range=(0.5, 1.5),
                 cache_dir=tmp_path / "c")
    assert a.labels == ["back", "leg", "seat"]
    mfile = tmp_path / "map.json"
    mfile.write_text(json.dumps({"Cushion": "seet", "Backrest": "back", "l": "leg"}))
    with pytest.raises(InputError) as e:
        add_assets(path, category="test_chair", mapping=mfile, parts=CHAIR, library=tmp_path / "lib")
    assert "map.json:/Cushion: unknown part label 'seet'" in str(e.value)
    assert "did you mean 'seat'" in str(e.value)
    single = tmp_path / "single.glb"
    trimesh.Scene([trimesh.creation.box()]).export(single)
    with pytest.raises(InputError, match="single.glb.*part-split"):
        load_glb(single, category="test_chair", size_range=(0.5, 1.5))
    with pytest.raises(InputError, match="nope.glb:/: file not found"):
        load_glb(tmp_path / "nope.glb", category="test_chair")


def test_partnet_mobility_cabinet(tmp_path):
    folder = write_partnet_cabinet(tmp_path / "cab")
    a = load_partnet_mobility(folder, category="test_cabinet", mapping=CABINET_MAP,
                              size_range=(0.5, 1.0), cache_dir=tmp_path / "coacd")
    labels = ("frame", "door", "handle")
    assert check_asset(a, vocabulary=labels, required=labels, size_range=(0.5, 1.0)) == []
    assert sorted(p.name for p in a.parts) == ["door", "frame", "handle"]
    np.testing.assert_allclose(a.extents, [0.6, 0.45, 0.6], atol=1e-4)
    # raw front -Z -> URDF +X -> canonical front +Y; the handle sits on the door's right half
    door, frame, handle = a.part("door"), a.part("frame"), a.part("handle")
    assert door.mesh.centroid[1] > frame.mesh.centroid[1] + 0.1
    assert handle.mesh.centroid[1] > door.mesh.centroid[1]
    assert handle.mesh.centroid[0] > 0.15
    # the L-shaped frame is not convex: it is split into its two convex bodies, which cover it
    assert len(frame.pieces) >= 2
    assert sum(p.volume for p in frame.pieces) == pytest.approx(frame.mesh.volume, rel=0.1)
    assert frame.surfaces["top"].source == "mesh"


def test_partnet_mobility_keeps_joints(tmp_path):
    folder = write_partnet_cabinet(tmp_path / "cab")
    a = load_partnet_mobility(folder, category="test_cabinet", mapping=CABINET_MAP,
                              size_range=(0.5, 1.0), cache_dir=tmp_path / "coacd")
    labels = ("frame", "door", "handle")
    assert check_asset(a, vocabulary=labels, required=labels, size_range=(0.5, 1.0)) == []
    (hinge,) = [j for j in a.joints if not j.is_mount]
    assert (hinge.name, hinge.type, hinge.parent_part, hinge.child_part) == ("joint_1", "revolute", "frame", "door")
    assert hinge.limits == pytest.approx((0.0, 1.57))
    # the hinge line is vertical, along the door's left back edge (door hinged on the left)
    assert abs(hinge.axis[2]) == pytest.approx(1.0)
    door, handle = a.part("door"), a.part("handle")
    assert hinge.origin[0] == pytest.approx(door.bounds[0, 0], abs=1e-6)
    assert hinge.origin[1] == pytest.approx(door.bounds[0, 1], abs=0.011)
    assert [(j.parent_part, j.child_part) for j in a.joints if j.is_mount] == [("door", "handle")]
    # opened, the door swings out to the front and takes its handle along
    opened = a.posed(ratio=1.0)
    assert opened.part("door").bounds[1, 1] > door.bounds[1, 1] + 0.4
    assert opened.part("handle").mesh.centroid[1] > handle.mesh.centroid[1] + 0.2
    assert opened.part("frame") is a.part("frame")


def test_partnet_errors(tmp_path):
    with pytest.raises(InputError, match="no mobility.urdf"):
        load_partnet_mobility(tmp_path, category="x")
    folder = write_partnet_cabinet(tmp_path / "cab")
    with pytest.raises(InputError, match="unknown part label 'rotation_door'"):
        add_assets(folder, category="test_cabinet", parts=("frame", "door", "handle"),
                   mapping={"cabinet_frame": "frame"}, library=tmp_path / "lib")
    (folder / "semantics.txt").write_text("link_0 static cabinet_frame\n")
    with pytest.raises(InputError, match=r"links \['link_1', 'link_2'\] have geometry but no"):
        load_partnet_mobility(folder, category="test_cabinet", mapping=CABINET_MAP)
    (folder / "textured_objs" / "original-3.obj").unlink()
    with pytest.raises(InputError, match="original-3.obj' not found"):
        load_partnet_mobility(folder, category="test_cabinet", mapping=CABINET_MAP)


def test_collision_cache_and_fast_path(tmp_path):
    box = trimesh.creation.box((0.2, 0.3, 0.4))
    (piece,) = convex_pieces(box, cache_dir=tmp_path)
    assert piece.volume == pytest.approx(box.volume)
    assert not any(tmp_path.iterdir())  # the convex fast path caches nothing
    ell = trimesh.creation.extrude_polygon(Polygon([(0, 0), (0.4, 0), (0.4, 0.1), (0.1, 0.1), (0.1, 0.4),
                                                    (0, 0.4)]), 0.1)
    first = convex_pieces(ell, cache_dir=tmp_path)
    assert len(first) >= 2 and all(p.is_convex for p in first)
    assert sum(p.volume for p in first) == pytest.approx(ell.volume, rel=0.05)
    assert len(list(tmp_path.glob("*.npz"))) == 1
    again = convex_pieces(ell, cache_dir=tmp_path)
    assert [p.vertices.tobytes() for p in again] == [p.vertices.tobytes() for p in first]


def test_library_new_category(tmp_path, restore_registry):
    src = tmp_path / "src"
    src.mkdir()
    write_chair_glb(src / "a.glb")
    write_partnet_cabinet(src / "b")  # a second source of another kind, mapped to chair labels
    mapping = {"cabinet_frame": "seat", "rotation_door": "back", "handle": "leg"}
    lib = tmp_path / "lib"
    cat = add_assets(src, category="test_chair", mapping=mapping, library=lib,
                     cache_dir=tmp_path / "coacd")
    assert cat.generator is None and len(cat.loaded_assets) == 2
    assert set(cat.parts) == set(CHAIR)
    meta = json.loads((lib / "test_chair" / "category.json").read_text())
    assert meta["format"] == "parse3d-category/1" and meta["assets"] == ["a.npz", "b.npz"]
    assert register_library(lib) == ["test_chair"]
    for seed in (0, 1):
        a = registry.generate("test_chair", seed)
        assert check_asset(a) == []
    assert registry.generate("test_chair", 2).asset_id == registry.generate("test_chair", 0).asset_id
    assert "test_chair" in registry.vocabulary().categories()


def test_library_extends_procedural_category(tmp_path, restore_registry):
    src = tmp_path / "src"
    src.mkdir()
    write_chair_glb(src / "t.glb", names=("tabletop", "leg_9", "leg_0", "leg_1", "leg_2", "leg_3"))
    lib = tmp_path / "lib"
    cat = add_assets(src, category="side_table", library=lib, cache_dir=tmp_path / "coacd")
    assert cat.generator is not None and len(cat.loaded_assets) == 1
    register_library(lib)
    # even seeds stay procedural, odd seeds draw the loaded assets
    assert registry.generate("side_table", 0).meta["generator"] == "procedural"
    loaded = registry.generate("side_table", 1)
    assert loaded.meta["generator"] == "loaded"
    assert check_asset(loaded) == []
    lo, hi = registry.get("side_table").size_range
    assert lo <= loaded.size <= hi
    with pytest.raises(InputError, match="lacks the part labels \\['tabletop'\\]"):
        bad = tmp_path / "bad"
        bad.mkdir()
        write_chair_glb(bad / "x.glb", names=("leg_5", "leg_4", "leg_0", "leg_1", "leg_2", "leg_3"))
        add_assets(bad, category="side_table", library=lib)


def test_add_rejects_bad_input(tmp_path):
    with pytest.raises(InputError, match="folder not found"):
        add_assets(tmp_path / "missing", category="x", library=tmp_path)
    (tmp_path / "empty").mkdir()
    with pytest.raises(InputError, match="empty:/: no .glb"):
        add_assets(tmp_path / "empty", category="x", library=tmp_path)
    with pytest.raises(InputError, match="category name"):
        add_assets(tmp_path / "empty", category="Bad Name", library=tmp_path)


def test_loaded_file_round_trip(tmp_path, restore_registry):
    src = tmp_path / "src"
    src.mkdir()
    write_chair_glb(src / "c.glb")
    cat = add_assets(src, category="test_chair", library=tmp_path / "lib", cache_dir=tmp_path / "k")
    a = load_asset(cat.loaded_assets[0])
    assert a.asset_id == "test_chair-c" and a.meta["source"].endswith("c.glb")
