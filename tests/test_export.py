"""Exports to viewers and simulators, each checked by loading it in its consumer.

Two example rooms are solved and settled once, the other four example rooms solved only (the
load checks need no settling); every format of all six is written once and read back by the
library that users would open it with (trimesh, the Khronos glTF validator, pxr, MuJoCo,
yourdfpy, SAPIEN's URDF loader). A small cabinet with a hinged door and a drawer, built here,
checks that joints reach every format and put the door in the same place. A two-object scene
checks that settling and re-exporting keep a folder's exports in step with its scene.json.
"""

from __future__ import annotations

import importlib.util
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import trimesh

import parse3d
from parse3d.assets.model import Asset, Joint, Material, finalize_asset, make_part
from parse3d.cli import main
from parse3d.export import ExportOptions, export_scene, to_mujoco, to_sapien, walk_scene
from parse3d.export.gltf import Z_UP_TO_Y_UP
from parse3d.export.walk import _unique, node_name, split_node_name
from parse3d.geometry import shapes
from parse3d.geometry.frames import make_transform, quat_to_matrix, rot_z
from parse3d.pag import load_pag
from parse3d.pag.model import PAG, Room
from parse3d.physics.mujoco import settling_friction
from parse3d.pipeline import PipelineOptions, run_pipeline
from parse3d.scene.model import PlacedObject, Scene
from parse3d.scene.shell import build_shell

ROOT = Path(__file__).resolve().parents[1]
VALIDATOR = ROOT / "tests" / "gltf_validator"
FORMATS = ["glb", "usd", "mjcf", "urdf", "obj"]
ROOMS = ["bathroom.yaml", "study.json"]  # solved and settled
EXAMPLES = sorted(p.name for p in (ROOT / "examples").iterdir()
                  if p.suffix in (".json", ".yaml"))  # not the notebook
OTHER_ROOMS = [r for r in EXAMPLES if r not in ROOMS]  # solved only


def cabinet_asset() -> Asset:
    """A cabinet: a body, a door on a vertical hinge at its left edge and a sliding drawer."""
    wood = Material((0.6, 0.4, 0.25, 1.0), 0.6, 0.0, "wood")
    w, d, h, t = 0.6, 0.4, 0.8, 0.02
    body = make_part("body", "body", [
        shapes.box((w, d, t), (0, 0, t / 2)), shapes.box((w, d, t), (0, 0, h - t / 2)),
        shapes.box((t, d, h - 2 * t), (-w / 2 + t / 2, 0, h / 2)),
        shapes.box((t, d, h - 2 * t), (w / 2 - t / 2, 0, h / 2)),
        shapes.box((w - 2 * t, t, h - 2 * t), (0, -d / 2 + t / 2, h / 2))], wood)
    door = make_part("door", "door", shapes.box((w, t, h / 2), (0, d / 2 + t / 2, 3 * h / 4)),
                     Material((0.8, 0.2, 0.2, 1.0), 0.5, 0.0, "wood"))
    drawer = make_part("drawer", "drawer",
                       shapes.box((w - 2 * t, d - t, h / 2 - 2 * t), (0, t / 2, h / 4)),
                       Material((0.2, 0.2, 0.8, 1.0), 0.5, 0.0, "wood"))
    joints = [Joint("door_hinge", "revolute", "body", "door", (0, 0, 1), (-w / 2, d / 2 + t, 0),
                    (0.0, 1.6)),
              Joint("drawer_slide", "prismatic", "body", "drawer", (0, 1, 0), (0, 0, 0),
                    (0.0, 0.3))]
    asset = Asset("cabinet", "cabinet-test-0", [body, door, drawer], (0.5, 1.0), 500.0,
                  joints=joints)
    return finalize_asset(asset, internal=False)


def cabinet_scene(door: float = 0.5, drawer: float = 0.1) -> Scene:
    """Two cabinets sharing one asset: a scaled, turned, loose one with its door and drawer
    ajar, and a fixed one with everything closed."""
    room = Room("study", ((0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (0.0, 3.0)), 2.5)
    scene = Scene(PAG("cabinets", room), 0, build_shell(room))
    asset = cabinet_asset()
    scene.objects["cab"] = PlacedObject("cab", "cabinet", asset, 1.2, rot_z(0.4),
                                        np.array([1.5, 1.5, 0.0]),
                                        joints={"door_hinge": door, "drawer_slide": drawer})
    scene.objects["cab2"] = PlacedObject("cab2", "cabinet", asset, 1.0, np.eye(3),
                                         np.array([0.6, 0.6, 0.0]), fixed=True)
    return scene


def door_centre(scene: Scene, oid: str = "cab") -> np.ndarray:
    """World centre of the door's bounding box at the scene's joint values."""
    o = scene.objects[oid]
    j = {j.name: j for j in o.asset.joints}["door_hinge"]
    m = o.asset.part("door").mesh.copy()
    m.apply_transform(o.transform() @ j.transform(o.joints.get("door_hinge", 0.0)))
    return m.bounds.mean(axis=0)


@pytest.fixture(scope="session")
def cabinets(tmp_path_factory):
    scene = cabinet_scene()
    out = tmp_path_factory.mktemp("cabinets")
    export_scene(scene, out, FORMATS, ExportOptions(friction=settling_friction()))
    return scene, out


@pytest.fixture(scope="session")
def rooms(tmp_path_factory):
    """Two example rooms, solved and settled, written as solve writes them."""
    from parse3d.assets.registry import vocabulary

    out = {}
    for name in ROOMS:
        d = tmp_path_factory.mktemp(Path(name).stem)
        pag = load_pag(ROOT / "examples" / name, vocabulary=vocabulary())
        scene = run_pipeline(pag, seed=0, out=d, options=PipelineOptions(preview=False))
        assert scene.settled and scene.placed
        out[Path(name).stem] = (scene, d)
    return out


@pytest.fixture(scope="session")
def exported(rooms, tmp_path_factory):
    """Every format of both rooms, read back from disk as a user would."""
    out = {}
    for name, (_, d) in rooms.items():
        scene = parse3d.load_scene(d)
        target = tmp_path_factory.mktemp(f"{name}-export")
        files = export_scene(scene, target, FORMATS, ExportOptions(friction=settling_friction()))
        out[name] = (scene, target, files)
    return out


@pytest.fixture(scope="session")
def every_room(exported, tmp_path_factory):
    """All six example rooms exported in every format into their own scene folders: the two
    settled ones of :func:`exported`, the others solved (not settled) at seed 0."""
    from parse3d.assets.registry import vocabulary

    out = {name: (scene, target) for name, (scene, target, _) in exported.items()}
    for name in OTHER_ROOMS:
        d = tmp_path_factory.mktemp(Path(name).stem)
        pag = load_pag(ROOT / "examples" / name, vocabulary=vocabulary())
        run_pipeline(pag, seed=0, out=d, options=PipelineOptions(settle=False, preview=False,
                                                                 formats=()))
        scene = parse3d.load_scene(d)
        assert scene.placed
        export_scene(scene, d, FORMATS, ExportOptions(friction=settling_friction()))
        out[Path(name).stem] = (scene, d)
    return out


def _world_part_meshes(scene: Scene) -> dict[str, trimesh.Trimesh]:
    meshes = {}
    for o in scene.placed:
        for p in o.asset.parts:
            meshes[f"{o.id}:{p.name}"] = o.part_mesh(p)
    return meshes


# -- the exporter contract ----------------------------------------------------------------

@pytest.mark.parametrize("fmt", FORMATS)
def test_every_format_module_keeps_the_exporter_contract(fmt, tmp_path):
    """A format is one module: NAME, FILES, MARKER and write(record, out) writing only its
    FILES, the MARKER among them, byte for byte the same on every run."""
    from parse3d.export import FORMATS as REGISTERED
    from parse3d.export import format_module

    assert set(REGISTERED) == set(FORMATS)
    mod = format_module(fmt)
    assert fmt == mod.NAME and mod.MARKER and isinstance(mod.FILES, tuple)
    rec = walk_scene(cabinet_scene(), ExportOptions(friction=settling_friction()))
    runs = []
    for run in ("a", "b"):
        out = tmp_path / run
        out.mkdir()
        written = mod.write(rec, out)
        rel = {str(p.relative_to(out)) for p in written}
        on_disk = {str(p.relative_to(out)) for p in out.rglob("*") if p.is_file()}
        assert rel == on_disk  # every file written is reported, nothing else is left
        assert mod.MARKER in rel
        assert all(any(r == f or (f.endswith("/") and r.startswith(f)) for f in mod.FILES)
                   for r in rel), sorted(rel)
        runs.append({r: (out / r).read_bytes() for r in rel})
    assert runs[0] == runs[1]


# -- glTF ---------------------------------------------------------------------------------

def _glb_json(path: Path) -> dict:
    data = path.read_bytes()
    n = int.from_bytes(data[12:16], "little")
    return json.loads(data[20:20 + n])


@pytest.mark.parametrize("room", [Path(r).stem for r in ROOMS])
def test_glb_has_object_and_part_nodes_with_extras(exported, room):
    scene, out, _ = exported[room]
    sc = trimesh.load(out / "scene.glb", force="scene")
    back = np.linalg.inv(Z_UP_TO_Y_UP)
    expected = _world_part_meshes(scene)
    for o in scene.placed:
        assert o.id in sc.graph.nodes
        for p in o.asset.parts:
            key = f"{o.id}:{p.name}"
            T, geom = sc.graph[node_name(key)]
            m = sc.geometry[geom].copy()
            m.apply_transform(back @ T)
            assert np.allclose(m.bounds, expected[key].bounds, atol=1e-4), key
            meta = sc.graph.transforms.edge_data[(o.id, node_name(key))]["metadata"]
            assert meta["name"] == key and meta["object_id"] == o.id
            assert meta["category"] == o.category and meta["asset_id"] == o.asset.asset_id
            assert meta["label"] == p.label
    for el in ("floor", "wall_0", "ceiling"):
        assert f"room__{el}" in sc.graph.nodes
    doc = _glb_json(out / "scene.glb")
    roots = {doc["nodes"][i]["name"] for i in doc["scenes"][0]["nodes"]}
    assert "room__ceiling" in roots and {o.id for o in scene.placed} <= roots
    # a mesh per distinct (asset, part), not per object: shared assets are instanced
    distinct = {(o.asset.asset_id, p.name) for o in scene.placed for p in o.asset.parts}
    assert len(doc["meshes"]) == len(distinct) + len(scene.room.elements)
    # relation summary: the desk's tabletop names the relations that use it
    objs = {doc["nodes"][i]["name"]: doc["nodes"][i] for i in doc["scenes"][0]["nodes"]}
    o = scene.placed[-1]
    assert any(r["child"].split(":")[0].split("@")[0] == o.id
               for r in objs[o.id]["extras"]["relations"])


def test_solve_writes_the_structured_glb(rooms):
    _, d = rooms["study"]
    doc = _glb_json(d / "scene.glb")
    names = {n["name"] for n in doc["nodes"]}
    assert "desk" in names and "desk__tabletop" in names and "room__ceiling" in names


def test_no_ceiling_leaves_the_ceiling_out(rooms, tmp_path):
    scene, _ = rooms["bathroom"]
    export_scene(scene, tmp_path, ["glb", "obj"], ExportOptions(ceiling=False))
    names = {n["name"] for n in _glb_json(tmp_path / "scene.glb")["nodes"]}
    assert "room__floor" in names and "room__ceiling" not in names
    assert "o room:ceiling" not in (tmp_path / "scene.obj").read_text()


def _validate(paths: list[Path]) -> list[dict]:
    proc = subprocess.run(["node", str(VALIDATOR / "validate.mjs"), *map(str, paths)],
                          capture_output=True, text=True, timeout=120, check=True)
    return json.loads(proc.stdout)


@pytest.mark.skipif(shutil.which("node") is None
                    or not (VALIDATOR / "node_modules" / "gltf-validator").is_dir(),
                    reason="needs node and `npm ci` in tests/gltf_validator")
def test_gltf_validator_reports_no_errors(every_room, cabinets):
    paths = [out / "scene.glb" for _, out in every_room.values()] + [cabinets[1] / "scene.glb"]
    assert len(paths) == len(EXAMPLES) + 1
    reports = _validate(paths)
    assert len(reports) == len(paths)
    for r in reports:
        assert r["issues"]["numErrors"] == 0, r["issues"]["messages"][:5]
        assert r["issues"]["numWarnings"] == 0, r["issues"]["messages"][:5]


# -- USD ----------------------------------------------------------------------------------

@pytest.mark.parametrize("room", [Path(r).stem for r in ROOMS])
def test_usd_stage_has_bodies_colliders_and_metadata(exported, room):
    from pxr import Usd, UsdGeom, UsdPhysics, UsdShade

    scene, out, _ = exported[room]
    stage = Usd.Stage.Open(str(out / "scene.usd"))
    assert UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    prims = list(stage.Traverse())
    objects = [p for p in prims if p.GetParent().GetPath() == "/World/Objects"]
    assert sorted(p.GetAttribute("parse3d:objectId").Get() for p in objects) == \
        sorted(o.id for o in scene.placed)
    bodies = [p for p in prims if p.HasAPI(UsdPhysics.RigidBodyAPI)]
    # one body per object, and one more per moving part (doors, drawers; mounts ride along)
    assert len(bodies) == sum(1 + sum(not j.is_mount for j in o.asset.joints)
                              for o in scene.placed)
    rec = walk_scene(scene)
    want = {o.id: o.mass for o in rec.objects}
    got: dict[str, float] = {}
    for b in bodies:  # /World/Objects/<id>[/<moving part link>]: an object's links share its mass
        oid = b.GetPath().pathString.split("/")[3]
        got[oid] = got.get(oid, 0.0) + UsdPhysics.MassAPI(b).GetMassAttr().Get()
    assert got == pytest.approx(want, rel=1e-5)
    colliders = [p for p in prims if p.HasAPI(UsdPhysics.CollisionAPI)]
    pieces = sum(len(p.pieces) for o in rec.objects for p in o.parts)
    assert len(colliders) == pieces + sum(len(s.pieces) for s in rec.shell)
    assert all(UsdPhysics.MeshCollisionAPI(c).GetApproximationAttr().Get() == "convexHull"
               for c in colliders)
    welds = [p for p in prims if p.IsA(UsdPhysics.FixedJoint)]
    assert len(welds) == sum(o.fixed for o in scene.placed)
    parts = [p for p in prims if p.GetAttribute("parse3d:partName").IsValid()]
    keys = {p.GetAttribute("parse3d:partName").Get() for p in parts}
    assert {f"{o.id}:{p.name}" for o in scene.placed for p in o.asset.parts} <= keys
    assert "room:ceiling" in keys
    visual = stage.GetPrimAtPath(str(parts[-1].GetPath()) + "/visual")
    assert UsdShade.MaterialBindingAPI(visual).ComputeBoundMaterial()[0]
    floor = stage.GetPrimAtPath("/World/Room/room__floor/collision/piece_0")
    bound = UsdShade.MaterialBindingAPI(floor).ComputeBoundMaterial("physics")[0]
    assert UsdPhysics.MaterialAPI(bound.GetPrim()).GetStaticFrictionAttr().Get() == \
        pytest.approx(settling_friction()["room"])


def test_usd_passes_the_usd_validators(every_room, cabinets):
    from pxr import Usd, UsdValidation

    validators = UsdValidation.ValidationRegistry().GetOrLoadAllValidators()
    assert len(validators) > 10
    context = UsdValidation.ValidationContext(validators)
    for path in [out / "scene.usd" for _, out in every_room.values()] + \
            [cabinets[1] / "scene.usd"]:
        errors = context.Validate(Usd.Stage.Open(str(path)))
        assert [e.GetMessage() for e in errors] == []


# -- names in consumers ---------------------------------------------------------------------

def node_tree(rec) -> dict[str, tuple[str, str | None]]:
    """What every viewer should show: node name -> (exact name, the node name of the object
    it belongs to, or None for an object or a shell element)."""
    out = {}
    for o in rec.objects:
        out[o.node] = (o.id, None)
        for p in o.parts:
            out[p.node] = (p.key, o.node)
    for s in rec.shell:
        out[s.node] = (s.key, None)
    return out


def test_node_names_survive_viewers_and_map_back(exported, cabinets):
    # three.js's PropertyBinding.sanitizeNodeName: white space to "_", then [ ] . : / dropped
    three = lambda n: re.sub(r"[\[\]./:]", "", re.sub(r"\s", "_", n))  # noqa: E731
    for scene in [exported[r][0] for r in exported] + [cabinets[0]]:
        tree = node_tree(walk_scene(scene))
        assert len(tree) == sum(1 + len(o.asset.parts) for o in scene.placed) + \
            len(scene.room.elements)  # unique in the scene: no viewer renames one
        for name, (exact, owner) in tree.items():
            assert re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name), name  # a USD prim name
            assert three(name) == name
            obj, part = split_node_name(name)
            if owner is not None:
                assert (obj, part) == (owner, exact.split(":", 1)[1])
    assert node_name("reading-lamp:shade_0") == "reading_lamp__shade_0"
    # ids that differ only in "-" against "_" still get names of their own
    taken: set[str] = set()
    assert [_unique(node_name(i), taken) for i in ("a-b", "a_b", "a-b")] == ["a_b", "a_b_2", "a_b_3"]


def test_glb_and_usd_give_parts_the_same_names_and_owners(exported):
    from pxr import Usd

    scene, out, _ = exported["study"]
    want = node_tree(walk_scene(scene, ExportOptions()))
    # glTF: part nodes are children of their object's node; extras keep the exact name
    doc = _glb_json(out / "scene.glb")
    got = {}
    for n in doc["nodes"]:
        got.setdefault(n["name"], [n["extras"]["name"], None])
        for c in n.get("children", []):
            got[doc["nodes"][c]["name"]] = [doc["nodes"][c]["extras"]["name"], n["name"]]
    assert {k: tuple(v) for k, v in got.items()} == want
    # USD: prim names are the node names; the owner is the nearest prim with an object id
    stage = Usd.Stage.Open(str(out / "scene.usd"))
    got = {}
    for prim in stage.Traverse():
        exact = prim.GetAttribute("parse3d:partName")
        if not exact.IsValid():
            if prim.GetParent().GetPath() == "/World/Objects":
                got[prim.GetName()] = (prim.GetAttribute("parse3d:objectId").Get(), None)
            continue
        if exact.Get().startswith("room:"):
            got[prim.GetName()] = (exact.Get(), None)
            continue
        owner = prim.GetParent()
        while not owner.GetAttribute("parse3d:objectId").IsValid():
            owner = owner.GetParent()
        got[prim.GetName()] = (exact.Get(), owner.GetName())
    assert got == want


BLENDER_SCRIPT = """
import json, sys
import bpy

out = {}
for fmt, path in (("glb", sys.argv[1]), ("usd", sys.argv[2])):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if fmt == "glb":
        bpy.ops.import_scene.gltf(filepath=path)
    else:
        bpy.ops.wm.usd_import(filepath=path)
    tree = {}
    for o in bpy.data.objects:
        chain, p = [], o.parent
        while p is not None:
            chain.append(p.name)
            p = p.parent
        tree[o.name] = {"ancestors": chain, "name": o.get("name")}
    out[fmt] = tree
print("BLENDER" + json.dumps(out))
"""


def blender_python() -> str | None:
    """A Python that imports bpy: this one, or ``$PARSE3D_BLENDER_PYTHON`` (bpy needs numpy<2,
    so it usually lives in an environment of its own: ``pip install 'parse3d[blender]'``)."""
    if importlib.util.find_spec("bpy") is not None:
        return sys.executable
    return os.environ.get("PARSE3D_BLENDER_PYTHON") or None


@pytest.mark.skipif(blender_python() is None,
                    reason="needs Blender as a module: a Python with bpy (pip install "
                           "'parse3d[blender]') here or named by PARSE3D_BLENDER_PYTHON")
def test_blender_imports_glb_and_usd_with_the_names_and_owners(exported):
    scene, out, _ = exported["study"]
    want = node_tree(walk_scene(scene))
    # Blender's own process: bpy carries its own USD libraries, which must not meet pxr's
    proc = subprocess.run([blender_python(), "-c", BLENDER_SCRIPT, str(out / "scene.glb"),
                           str(out / "scene.usd")], capture_output=True, text=True,
                          timeout=600, check=True)
    line = next(ln for ln in proc.stdout.splitlines() if ln.startswith("BLENDER"))
    got = json.loads(line[len("BLENDER"):])
    for fmt in ("glb", "usd"):
        tree = got[fmt]
        for name, (_, owner) in want.items():
            assert name in tree, (fmt, name)  # as written: no prefix dropped, no ".001"
            if owner is not None:
                assert owner in tree[name]["ancestors"], (fmt, name, tree[name]["ancestors"])
        if fmt == "glb":  # glTF extras become custom properties
            assert {n: tree[n]["name"] for n in want} == {n: e for n, (e, _) in want.items()}


# -- masses -------------------------------------------------------------------------------

#: Real masses, kg, of the objects of MASS_PAG: low and high ends of what such things weigh.
#: Sources: retailers' specification sheets and manufacturers' data (typical figures).
REAL_MASS = {
    "kettle": (0.5, 2.0),     # electric 1.7 l kettles 0.7-1.4 kg; stainless stovetop 1-2 kg
    "mug": (0.2, 0.5),        # stoneware and porcelain mugs 250-450 g
    "book": (0.15, 2.5),      # paperbacks 0.2-0.4 kg, hardcovers 0.5-1 kg, art books to 2.5 kg
    "toaster": (0.8, 3.0),    # two-slot 1-1.5 kg, four-slot 1.8-2.8 kg
    "pot": (1.0, 6.0),        # stainless stock pots 1.5-3 kg, enamelled cast iron 4-6 kg
    "microwave": (4.0, 20.0),  # countertop microwaves 10-16 kg, compact ones from 5 kg
    "lamp": (0.5, 4.0),       # pendant lights 1-3 kg on manufacturers' data sheets
    "suitcase": (2.0, 12.0),  # empty: carry-on 2-3.5 kg, check-in 3.5-6 kg, trunks to 12 kg
    "bin": (0.5, 12.0),       # kitchen bins: plastic 1-2 kg, stainless pedal bins 4-8 kg
    "case": (1.0, 6.0),       # gig bags 1-2 kg, hard guitar cases 3-5.5 kg
}

MASS_PAG = {"format": "pag/1", "name": "masses",
            "room": {"type": "kitchen", "footprint": [[0, 0], [5, 0], [5, 4], [0, 4]],
                     "height": 2.7},
            "objects": [{"id": "table", "category": "dining_table"},
                        {"id": "kettle", "category": "kettle"}, {"id": "mug", "category": "mug"},
                        {"id": "book", "category": "book"},
                        {"id": "toaster", "category": "toaster"},
                        {"id": "pot", "category": "cooking_pot"},
                        {"id": "microwave", "category": "microwave"},
                        {"id": "lamp", "category": "pendant_lamp"},
                        {"id": "suitcase", "category": "suitcase"},
                        {"id": "bin", "category": "trash_can"},
                        {"id": "case", "category": "guitar_case"}],
            "relations": [{"relation": "ON", "child": "table", "parent": "floor"},
                          *({"relation": "ON", "child": c, "parent": "table:tabletop"}
                            for c in ("kettle", "mug", "book", "toaster", "pot", "microwave")),
                          {"relation": "HANGING_BELOW", "child": "lamp", "parent": "ceiling"},
                          *({"relation": "ON", "child": c, "parent": "floor"}
                            for c in ("suitcase", "bin", "case"))]}


def test_masses_of_ten_objects_are_real_in_mujoco_and_usd(tmp_path):
    import mujoco
    from pxr import Usd, UsdPhysics

    from parse3d.assets.registry import vocabulary

    (tmp_path / "masses.json").write_text(json.dumps(MASS_PAG))
    pag = load_pag(tmp_path / "masses.json", vocabulary=vocabulary())
    scene = run_pipeline(pag, seed=0, out=tmp_path / "s",
                         options=PipelineOptions(settle=False, preview=False, formats=()))
    assert len(scene.placed) == len(MASS_PAG["objects"])
    export_scene(scene, tmp_path / "s", ["mjcf", "usd"])
    model = mujoco.MjModel.from_xml_path(str(tmp_path / "s" / "scene.xml"))
    stage = Usd.Stage.Open(str(tmp_path / "s" / "scene.usd"))
    for oid, (lo, hi) in REAL_MASS.items():
        body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, oid)
        in_mujoco = float(model.body_subtreemass[body])  # the object and its moving parts
        in_usd = sum(UsdPhysics.MassAPI(p).GetMassAttr().Get()
                     for p in Usd.PrimRange(stage.GetPrimAtPath(f"/World/Objects/{oid}"))
                     if p.HasAPI(UsdPhysics.MassAPI))
        assert in_usd == pytest.approx(in_mujoco, rel=1e-4), oid
        assert lo <= in_mujoco <= hi, f"{oid}: {in_mujoco:.2f} kg, real {lo}-{hi} kg"


def test_shell_categories_weigh_their_walls_and_solid_ones_their_volume():
    from parse3d.export.mass import MATERIAL_DENSITY, WALL, part_mass

    # a closed 1-litre plastic body of 0.06 m2: a 2 mm shell, not a litre of solid
    shell = part_mass(1e-3, 0.06, scale=1.0, density=1500.0, material="plastic", shell=True)
    assert shell == pytest.approx(0.06 * WALL["plastic"] * MATERIAL_DENSITY["plastic"])
    # a part already thinner than the wall keeps its volume; a solid category its density
    assert part_mass(1e-5, 0.06, scale=1.0, density=1500.0, material="plastic",
                     shell=True) == pytest.approx(1e-5 * MATERIAL_DENSITY["plastic"])
    assert part_mass(1e-3, 0.06, scale=2.0, density=1500.0, material="plastic",
                     shell=False) == pytest.approx(8e-3 * 1500.0)
    # twice the size: four times the wall area
    assert part_mass(1e-3, 0.06, scale=2.0, density=1500.0, material="plastic",
                     shell=True) == pytest.approx(4 * shell)


# -- MJCF ---------------------------------------------------------------------------------

@pytest.mark.parametrize("room", [Path(r).stem for r in ROOMS])
def test_mjcf_loads_and_a_settled_room_rests_for_one_second(exported, room):
    import mujoco

    scene, out, _ = exported[room]
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    assert model.opt.cone == mujoco.mjtCone.mjCONE_ELLIPTIC and model.opt.noslip_iterations == 0
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    ids = [o.id for o in scene.placed]
    body = {i: mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, i) for i in ids}
    assert min(body.values()) > 0
    free = sum(1 for o in scene.placed if not o.fixed)
    assert sum(model.jnt_type == mujoco.mjtJoint.mjJNT_FREE) == free
    p0 = data.xpos.copy()
    for _ in range(int(round(1.0 / model.opt.timestep))):
        mujoco.mj_step(model, data)
    moved = {i: float(np.linalg.norm(data.xpos[b] - p0[b])) for i, b in body.items()}
    assert max(moved.values()) < 0.01, sorted(moved.items(), key=lambda kv: -kv[1])[:3]


def test_mjcf_of_the_other_room_loads_with_colours(exported):
    import mujoco

    scene, out, _ = exported["bathroom"]
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    o = scene.placed[0]
    g = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, f"{o.id}:{o.asset.parts[0].name}")
    assert np.allclose(model.geom_rgba[g], o.asset.parts[0].material.color, atol=1e-6)
    assert model.geom_contype[g] == 0  # visual only
    assert (out / "meshes").is_dir()


# -- URDF ---------------------------------------------------------------------------------

def test_urdf_loads_in_yourdfpy_and_sapien(exported):
    import sapien
    import yourdfpy

    from parse3d.export.sapien import load_urdf_scene

    scene, out, _ = exported["bathroom"]
    rows = json.loads((out / "urdf" / "scene.json").read_text())
    assert [r["id"] for r in rows] == [o.id for o in scene.placed] + ["room"]
    for r in rows[:4]:
        u = yourdfpy.URDF.load(str(out / "urdf" / r["urdf"]), load_collision_meshes=True)
        o = scene.objects.get(r["id"])
        assert {lk for lk in u.link_map} == {p.name for p in o.asset.parts}
        assert u.scene is not None and len(u.scene.geometry) == len(o.asset.parts)
    sim = load_urdf_scene(out / "urdf", render=False)
    rec = walk_scene(scene)
    mass = {o.id: o.mass for o in rec.objects}
    pieces = {o.id: {p.name: len(p.pieces) for p in o.parts} for o in rec.objects}
    for o in scene.placed:
        if len(o.asset.parts) == 1:
            entity = sim.actors[o.id]
            assert np.allclose(entity.pose.p, o.settled_position, atol=1e-5)
            body = entity.find_component_by_type(sapien.physx.PhysxRigidBaseComponent)
            assert len(body.collision_shapes) == sum(pieces[o.id].values()), o.id
            continue
        art = sim.articulations[o.id]
        assert {lk.name for lk in art.links} == {p.name for p in o.asset.parts}
        # every convex piece of a part is a collision shape of its own in SAPIEN
        assert {lk.name: len(lk.collision_shapes) for lk in art.links} == pieces[o.id]
        assert np.allclose(art.root_pose.p, o.settled_position, atol=1e-5)
        assert sum(lk.mass for lk in art.links) == pytest.approx(mass[o.id], rel=1e-3, abs=0.01)
    assert "room" in sim.articulations


# -- OBJ ----------------------------------------------------------------------------------

def test_obj_has_a_group_per_part(exported):
    scene, out, _ = exported["study"]
    sc = trimesh.load(out / "scene.obj", force="scene", group_material=False, split_groups=True)
    expected = _world_part_meshes(scene)
    assert set(expected) | {f"room:{n}" for n in scene.room.elements} == set(sc.geometry)
    back = np.linalg.inv(Z_UP_TO_Y_UP[:3, :3])
    for key, mesh in expected.items():
        world = np.asarray(sc.geometry[key].vertices) @ back.T
        assert np.allclose([world.min(0), world.max(0)], mesh.bounds, atol=1e-5), key
    assert "newmtl" in (out / "scene.mtl").read_text()


# -- every example room -------------------------------------------------------------------

@pytest.mark.parametrize("room", [Path(r).stem for r in EXAMPLES])
def test_every_format_of_every_example_room_loads_in_its_consumer(every_room, room):
    import mujoco
    from pxr import Usd, UsdPhysics

    from parse3d.export.sapien import load_urdf_scene

    scene, out = every_room[room]
    ids = {o.id for o in scene.placed}
    keys = set(_world_part_meshes(scene))
    shell = {f"room:{n}" for n in scene.room.elements}
    moving = sum(not j.is_mount for o in scene.placed for j in o.asset.joints)
    # glTF and OBJ in trimesh: a node per object and per part; a group per part
    sc = trimesh.load(out / "scene.glb", force="scene")
    assert {node_name(n) for n in ids | keys | shell} <= set(sc.graph.nodes)
    obj = trimesh.load(out / "scene.obj", force="scene", group_material=False,
                       split_groups=True)
    assert set(obj.geometry) == keys | shell
    # USD in pxr: every object, a rigid body per link
    stage = Usd.Stage.Open(str(out / "scene.usd"))
    objects = stage.GetPrimAtPath("/World/Objects").GetChildren()
    assert {p.GetAttribute("parse3d:objectId").Get() for p in objects} == ids
    bodies = [p for p in stage.Traverse() if p.HasAPI(UsdPhysics.RigidBodyAPI)]
    assert len(bodies) == len(ids) + moving
    # MJCF in MuJoCo: a body per object and moving part, a free joint per loose object
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    assert model.nbody == 1 + len(ids) + moving
    assert sum(model.jnt_type == mujoco.mjtJoint.mjJNT_FREE) == \
        sum(not o.fixed for o in scene.placed)
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data)
    assert np.isfinite(data.qpos).all()
    # URDF in SAPIEN's loader: every object and the room
    sim = load_urdf_scene(out / "urdf", render=False)
    assert set(sim.actors) | set(sim.articulations) == ids | {"room"}


# -- joints -------------------------------------------------------------------------------

def test_joints_put_the_door_in_the_same_place_in_every_format(cabinets):
    import mujoco
    import yourdfpy
    from pxr import Usd, UsdGeom, UsdPhysics

    scene, out = cabinets
    want = door_centre(scene)
    # glTF
    sc = trimesh.load(out / "scene.glb", force="scene")
    T, geom = sc.graph["cab__door"]
    m = sc.geometry[geom].copy()
    m.apply_transform(np.linalg.inv(Z_UP_TO_Y_UP) @ T)
    assert np.allclose(m.bounds.mean(0), want, atol=1e-5)
    # MJCF
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    g = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "cab:door")
    mid = model.geom_dataid[g]
    v = model.mesh_vert[model.mesh_vertadr[mid]:model.mesh_vertadr[mid] + model.mesh_vertnum[mid]]
    v = v @ data.geom_xmat[g].reshape(3, 3).T + data.geom_xpos[g]
    assert np.allclose((v.min(0) + v.max(0)) / 2, want, atol=1e-5)
    hinge = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, "cab:door_hinge")
    assert model.jnt_type[hinge] == mujoco.mjtJoint.mjJNT_HINGE
    assert np.allclose(model.jnt_range[hinge], [0.0, 1.6])
    # URDF in yourdfpy, at the joint values of urdf/scene.json
    rows = {r["id"]: r for r in json.loads((out / "urdf" / "scene.json").read_text())}
    r = rows["cab"]
    assert r["joints"] == {"door_hinge": 0.5, "drawer_slide": pytest.approx(0.12)}
    u = yourdfpy.URDF.load(str(out / "urdf" / r["urdf"]))
    assert u.joint_map["door_hinge"].type == "revolute"
    assert u.joint_map["drawer_slide"].type == "prismatic"
    assert u.joint_map["drawer_slide"].limit.upper == pytest.approx(0.36)
    u.update_cfg(r["joints"])
    vis = u.link_map["door"].visuals[0]
    mesh = trimesh.load(out / "urdf" / vis.geometry.mesh.filename, force="mesh")
    mesh.apply_scale(vis.geometry.mesh.scale[0])
    world = make_transform(quat_to_matrix(r["quaternion"]), r["position"])
    mesh.apply_transform(world @ u.get_transform("door", u.base_link) @ vis.origin)
    assert np.allclose(mesh.bounds.mean(0), want, atol=1e-5)
    # SAPIEN, through to_sapien
    sim = to_sapien(scene, render=False)
    art = sim.articulations["cab"]
    assert np.allclose(art.get_qpos(), [0.5, 0.12], atol=1e-6)
    link = next(lk for lk in art.links if lk.name == "door")
    mesh = trimesh.load(out / "urdf" / vis.geometry.mesh.filename, force="mesh")
    mesh.apply_scale(1.2)
    pose = link.entity.pose
    mesh.apply_transform(make_transform(quat_to_matrix(pose.q), pose.p) @ vis.origin)
    assert np.allclose(mesh.bounds.mean(0), want, atol=1e-5)
    # USD
    stage = Usd.Stage.Open(str(out / "scene.usd"))
    p = stage.GetPrimAtPath("/World/Objects/cab/Links/door/cab__door/visual")
    M = np.array(UsdGeom.XformCache().GetLocalToWorldTransform(p)).T
    pts = np.array(UsdGeom.Mesh(p).GetPointsAttr().Get()) @ M[:3, :3].T + M[:3, 3]
    assert np.allclose((pts.min(0) + pts.max(0)) / 2, want, atol=1e-5)
    rev = UsdPhysics.RevoluteJoint(stage.GetPrimAtPath("/World/Objects/cab/Joints/door_hinge"))
    assert rev.GetUpperLimitAttr().Get() == pytest.approx(np.degrees(1.6), rel=1e-6)
    assert rev.GetBody1Rel().GetTargets()[0] == "/World/Objects/cab/Links/door"
    assert stage.GetPrimAtPath("/World/Objects/cab").HasAPI(UsdPhysics.ArticulationRootAPI)
    assert stage.GetPrimAtPath("/World/Objects/cab2/Joints/weld_to_world").IsA(
        UsdPhysics.FixedJoint)


CABINET_PAG = {"format": "pag/1", "name": "cabinet",
               "room": {"type": "study", "footprint": [[0, 0], [3, 0], [3, 3], [0, 3]],
                        "height": 2.6},
               "objects": [{"id": "cab", "category": "storage_cabinet"}],
               "relations": [{"relation": "ON", "child": "cab", "parent": "floor"}]}


def test_joint_values_in_scene_json_reach_every_format(tmp_path, capsys):
    """Door angles written into scene.json come out of every format at those angles."""
    import mujoco
    from pxr import Usd

    from parse3d.assets.registry import vocabulary

    (tmp_path / "cab.json").write_text(json.dumps(CABINET_PAG))
    d = tmp_path / "scene"
    run_pipeline(load_pag(tmp_path / "cab.json", vocabulary=vocabulary()), seed=0, out=d,
                 options=PipelineOptions(settle=False, preview=False, formats=()))
    doc = json.loads((d / "scene.json").read_text())
    hinges = [j for j in parse3d.load_scene(d).objects["cab"].asset.joints
              if j.type == "revolute"]
    assert len(hinges) >= 2
    want = {j.name: round(0.6 * max(j.limits, key=abs), 6) for j in hinges}  # 60 % open
    doc["objects"][0]["joints"] = want
    (d / "scene.json").write_text(json.dumps(doc))
    assert _cli(["export", str(d), "--format", ",".join(FORMATS)]) == 0
    capsys.readouterr()
    scene = parse3d.load_scene(d)
    cab = scene.objects["cab"]
    assert cab.joints == want
    # glTF: the object's extras
    node = next(n for n in _glb_json(d / "scene.glb")["nodes"] if n["name"] == "cab")
    assert node["extras"]["joints"] == pytest.approx(want)
    # USD: each joint's value and the drive target holding it (degrees)
    stage = Usd.Stage.Open(str(d / "scene.usd"))
    for name, v in want.items():
        jp = stage.GetPrimAtPath(f"/World/Objects/cab/Joints/{name}")
        assert jp.GetAttribute("parse3d:value").Get() == pytest.approx(v, abs=1e-6)
        target = jp.GetAttribute("drive:angular:physics:targetPosition").Get()
        assert target == pytest.approx(np.degrees(v), abs=1e-4)
    # MJCF: the model's initial configuration
    model = mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
    for name, v in want.items():
        j = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, f"cab:{name}")
        assert model.qpos0[model.jnt_qposadr[j]] == pytest.approx(v, abs=1e-6)
    # URDF: the values to set after loading
    rows = {r["id"]: r for r in json.loads((d / "urdf" / "scene.json").read_text())}
    assert rows["cab"]["joints"] == pytest.approx(want)
    # OBJ: the doors baked where the joints put them
    obj = trimesh.load(d / "scene.obj", force="scene", group_material=False, split_groups=True)
    posed = cab.asset.part_transforms(want)
    for j in hinges:
        m = cab.asset.part(j.child_part).mesh.copy()
        m.apply_transform(cab.transform() @ posed[j.child_part])
        got = np.asarray(obj.geometry[f"cab:{j.child_part}"].vertices)
        got = got @ np.linalg.inv(Z_UP_TO_Y_UP[:3, :3]).T
        assert np.allclose([got.min(0), got.max(0)], m.bounds, atol=1e-5), j.child_part


def test_mujoco_locks_joints_by_default(cabinets):
    import mujoco

    scene, _ = cabinets
    model, data = to_mujoco(scene, visual=False)
    q0 = data.qpos.copy()
    for _ in range(250):
        mujoco.mj_step(model, data)
    assert np.abs(data.qpos - q0).max() < 2e-3
    hinge = model.jnt_qposadr[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT,
                                                "cab:door_hinge")]
    assert q0[hinge] == pytest.approx(0.5)


def test_mjcf_file_is_the_model_mjspec_builds(cabinets):
    """scene.xml with its mesh files compiles to the model ``build_spec`` makes in memory
    (every mesh inline), which ``to_mujoco`` uses."""
    import mujoco

    from parse3d.export.mjcf import build_spec

    scene, out = cabinets
    a = build_spec(walk_scene(scene, ExportOptions(friction=settling_friction()))).compile()
    b = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    for n in ("nbody", "ngeom", "njnt", "neq", "nmesh"):
        assert getattr(a, n) == getattr(b, n), n
    for f in ("body_pos", "body_quat", "body_mass", "body_inertia", "geom_pos", "geom_quat",
              "geom_rgba", "geom_friction", "geom_contype", "geom_group", "geom_size",
              "jnt_type", "jnt_range", "jnt_axis", "jnt_pos", "qpos0", "eq_data", "eq_type"):
        assert np.allclose(getattr(a, f), getattr(b, f), atol=1e-9), f
    for f in ("timestep", "impratio", "noslip_iterations", "cone"):
        assert getattr(a.opt, f) == getattr(b.opt, f), f


def test_to_sapien_holds_joints_unless_free(cabinets):
    scene, _ = cabinets
    moved = {}
    for free in (True, False):
        sim = to_sapien(scene, render=False, free_joints=free)
        art = sim.articulations["cab"]
        art.set_qvel(np.array([-2.0, -0.5], np.float32))  # swing the door shut, push the drawer
        for _ in range(30):
            sim.scene.step()
        q = np.asarray(art.get_qpos(), float)
        assert np.isfinite(q).all() and 0.0 <= q[0] <= 1.6 and 0.0 <= q[1] <= 0.36
        moved[free] = np.abs(q - [0.5, 0.12]).max()
    assert moved[True] > 0.1 and moved[False] < 0.02, moved


def test_open_ratio_opens_every_joint_to_its_far_limit():
    scene = cabinet_scene(door=0.0, drawer=0.0)
    rec = walk_scene(scene, ExportOptions(open_ratio=1.0))
    cab = next(o for o in rec.objects if o.id == "cab")
    assert {j.name: j.value for j in cab.joints} == {"door_hinge": 1.6,
                                                     "drawer_slide": pytest.approx(0.3)}
    closed = walk_scene(scene)
    assert {j.name: j.value for j in closed.objects[0].joints} == {"door_hinge": 0.0,
                                                                   "drawer_slide": 0.0}


# -- command line -------------------------------------------------------------------------

def _cli(args: list[str]) -> int:
    with pytest.raises(SystemExit) as e:
        main(args)
    return int(e.value.code or 0)


def test_cli_exports_a_scene_folder(rooms, tmp_path, capsys):
    _, d = rooms["bathroom"]
    assert _cli(["export", str(d), "--format", "obj,urdf", "--out", str(tmp_path),
                 "--no-ceiling", "--solved", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["formats"] == ["obj", "urdf"]
    assert (tmp_path / "scene.obj").is_file() and (tmp_path / "urdf" / "scene.json").is_file()
    assert "room:ceiling" not in (tmp_path / "scene.obj").read_text()


def test_cli_bad_input_exits_2(rooms, tmp_path, capsys):
    _, d = rooms["bathroom"]
    assert _cli(["export", str(tmp_path), "--format", "glb"]) == 2
    assert "not a scene folder" in capsys.readouterr().err
    assert _cli(["export", str(d), "--format", "fbx"]) == 2
    assert "unknown format 'fbx'" in capsys.readouterr().err
    blocker = tmp_path / "file"
    blocker.write_text("not a folder")
    assert _cli(["export", str(d), "--format", "glb", "--out", str(blocker / "x")]) == 2
    assert "cannot create the output folder" in capsys.readouterr().err
    assert blocker.read_text() == "not a folder"
    # something in the way of a file the export writes: named, and no temporary file left
    busy = tmp_path / "busy"
    (busy / "scene.usd").mkdir(parents=True)
    (busy / "urdf").write_text("mine")
    for fmt, name, what in (("usd", "scene.usd", "a folder"), ("urdf", "urdf", "a file")):
        assert _cli(["export", str(d), "--format", fmt, "--out", str(busy)]) == 2
        err = capsys.readouterr().err
        assert err.startswith(f"{busy / name}:") and f"{what} is in the way" in err, err
    assert sorted(p.name for p in busy.iterdir()) == ["scene.usd", "urdf"]
    assert (busy / "urdf").read_text() == "mine"
    unsettled = tmp_path / "unsettled"
    unsettled.mkdir()
    doc = json.loads((d / "scene.json").read_text())
    doc["settled"] = False
    (unsettled / "scene.json").write_text(json.dumps(doc))
    assert _cli(["export", str(unsettled), "--format", "glb", "--settled"]) == 2
    assert "was not settled" in capsys.readouterr().err


def test_solve_formats_writes_each_format(tmp_path, capsys):
    from parse3d.export import present_formats

    pag = tmp_path / "tiny.json"
    pag.write_text(json.dumps(TINY_PAG))
    bad = tmp_path / "bad"
    assert _cli(["solve", str(pag), "--formats", "glb,fbx", "--out", str(bad)]) == 2
    assert "unknown format 'fbx'" in capsys.readouterr().err and not bad.exists()
    d = tmp_path / "s"
    assert _cli(["solve", str(pag), "--formats", "usd,urdf", "--no-settle", "--no-preview",
                 "--out", str(d), "--json"]) == 0
    capsys.readouterr()
    assert (d / "scene.usd").is_file() and (d / "urdf" / "scene.json").is_file()
    assert set(json.loads((d / "exports.json").read_text())["formats"]) == {"usd", "urdf"}
    assert present_formats(d) == ("usd", "urdf")


def test_load_scene_reads_what_solve_wrote(rooms):
    scene, d = rooms["study"]
    back = parse3d.load_scene(d)
    assert [o.id for o in back.placed] == [o.id for o in scene.placed]
    assert back.settled


# -- keeping a folder's exports in step with its scene.json ---------------------------------

TINY_PAG = {"format": "pag/1", "name": "tiny",
            "room": {"type": "study", "footprint": [[0, 0], [3, 0], [3, 3], [0, 3]],
                     "height": 2.6},
            "objects": [{"id": "desk", "category": "desk"}, {"id": "mug", "category": "mug"}],
            "relations": [{"relation": "ON", "child": "desk", "parent": "floor"},
                          {"relation": "ON", "child": "mug", "parent": "desk:tabletop"}]}


@pytest.fixture(scope="session")
def tiny_scene(tmp_path_factory):
    """A desk with a mug, solved (not settled), the mug lifted 3 cm so settling drops it."""
    from parse3d.assets.registry import vocabulary

    path = tmp_path_factory.mktemp("tiny-pag") / "tiny.json"
    path.write_text(json.dumps(TINY_PAG))
    pag = load_pag(path, vocabulary=vocabulary())
    scene = run_pipeline(pag, seed=0, out=None,
                         options=PipelineOptions(settle=False, preview=False, formats=()))
    scene.objects["mug"].position = scene.objects["mug"].position + [0.0, 0.0, 0.03]
    return scene


def _folder_with_every_format(scene: Scene, d: Path) -> Path:
    from parse3d.pipeline import write_outputs

    write_outputs(scene, d, tuple(FORMATS))
    return d


def _exported_mug_positions(d: Path) -> dict[str, np.ndarray]:
    """The mug's position in each export of folder ``d`` (world frame, Z-up)."""
    import mujoco
    from pxr import Usd

    out = {}
    doc = _glb_json(d / "scene.glb")
    node = next(n for n in doc["nodes"] if n["name"] == "mug")
    out["glb"] = np.linalg.inv(Z_UP_TO_Y_UP[:3, :3]) @ np.array(node["translation"])
    stage = Usd.Stage.Open(str(d / "scene.usd"))
    out["usd"] = np.array(stage.GetPrimAtPath("/World/Objects/mug")
                          .GetAttribute("xformOp:translate").Get())
    model = mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
    out["mjcf"] = model.body_pos[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, "mug")]
    rows = {r["id"]: r for r in json.loads((d / "urdf" / "scene.json").read_text())}
    out["urdf"] = np.array(rows["mug"]["position"])
    return out


def _referenced_meshes(d: Path) -> set[str]:
    import re

    refs = set(re.findall(r'file="([^"]+)"', (d / "scene.xml").read_text()))
    for u in (d / "urdf").glob("*.urdf"):
        refs |= {f"urdf/{m}" for m in re.findall(r'filename="([^"]+)"', u.read_text())}
    return refs


def test_settle_refreshes_every_export_in_the_folder(tiny_scene, tmp_path, capsys):
    from parse3d.export import stale_formats

    d = _folder_with_every_format(tiny_scene, tmp_path / "tiny")
    lifted = tiny_scene.objects["mug"].position.copy()
    # not settled yet: every format's default pose is the solved one
    for fmt, pos in _exported_mug_positions(d).items():
        assert np.allclose(pos, lifted, atol=1e-5), fmt
    meshes = {p: p.stat().st_mtime_ns for p in (d / "meshes").iterdir()}
    assert _cli(["settle", str(d), "--steps", "150", "--json"]) == 0
    capsys.readouterr()
    scene = parse3d.load_scene(d)
    settled = scene.objects["mug"].settled_position
    assert scene.settled and lifted[2] - settled[2] > 0.01  # the mug fell onto the desk
    assert stale_formats(d) == ()
    for fmt, pos in _exported_mug_positions(d).items():
        assert np.allclose(pos, settled, atol=1e-5), fmt
    obj = trimesh.load(d / "scene.obj", force="scene", group_material=False, split_groups=True)
    mug = scene.objects["mug"]
    want = mug.part_mesh(mug.asset.parts[0], settled=True).bounds
    got = np.asarray(obj.geometry[f"mug:{mug.asset.parts[0].name}"].vertices)
    got = got @ np.linalg.inv(Z_UP_TO_Y_UP[:3, :3]).T
    assert np.allclose([got.min(0), got.max(0)], want, atol=1e-5)
    # the meshes are in the asset frame: settling rewrote none of them
    assert {p: p.stat().st_mtime_ns for p in (d / "meshes").iterdir()} == meshes


def test_export_rerun_refreshes_stale_exports_and_drops_unused_files(tiny_scene, tmp_path,
                                                                   capsys):
    from parse3d.export import stale_formats

    d = _folder_with_every_format(tiny_scene, tmp_path / "tiny")
    (d / "meshes" / "notes.txt").write_text("mine")
    # scene.json changed after the exports were written (as by an older parse3d settle)
    earlier = (d / "scene.json").stat().st_mtime_ns - 10**9
    for marker in ("scene.glb", "scene.usd", "scene.xml", "urdf/scene.json", "scene.obj"):
        os.utime(d / marker, ns=(earlier, earlier))
    assert stale_formats(d) == tuple(FORMATS)
    assert _cli(["export", str(d), "--format", "obj", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["formats"] == ["obj"] and report["refreshed"] == ["glb", "usd", "mjcf", "urdf"]
    assert stale_formats(d) == ()
    # an export to another folder refreshes nothing there but what it was asked for
    assert _cli(["export", str(d), "--format", "glb", "--out", str(tmp_path / "o"),
                 "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["refreshed"] == []
    assert sorted(p.name for p in (tmp_path / "o").iterdir()) == ["exports.json", "scene.glb"]
    # without the mug, its URDF and the meshes only it used leave the folder
    files = {str(p.relative_to(d)) for p in d.rglob("*") if p.is_file()}
    scene = parse3d.load_scene(d)
    del scene.objects["mug"]
    export_scene(scene, d, ["mjcf", "urdf"], refresh=False)
    left = {str(p.relative_to(d)) for p in d.rglob("*") if p.is_file()}
    assert not (d / "urdf" / "mug.urdf").exists() and (d / "urdf" / "desk.urdf").is_file()
    gone = files - left
    assert gone and all("mug" in f for f in gone), sorted(gone)
    assert (d / "meshes" / "notes.txt").read_text() == "mine"
    mesh_files = {f for f in left if f.startswith(("meshes/", "urdf/meshes/"))
                  and not f.endswith((".txt", ".mtl"))}
    assert mesh_files == _referenced_meshes(d)


def test_refreshes_keep_the_options_each_export_was_made_with(tiny_scene, tmp_path, capsys):
    from parse3d.export.record import read_options

    d = _folder_with_every_format(tiny_scene, tmp_path / "tiny")
    lifted = tiny_scene.objects["mug"].position.copy()
    assert _cli(["export", str(d), "--format", "glb,mjcf", "--no-ceiling", "--open", "1"]) == 0
    assert _cli(["export", str(d), "--format", "urdf", "--solved"]) == 0
    capsys.readouterr()
    rec = read_options(d)
    assert not rec["glb"].ceiling and rec["mjcf"].open_ratio == 1.0
    assert rec["urdf"].settled is False and rec["usd"].ceiling and rec["usd"].settled is None
    assert _cli(["settle", str(d), "--steps", "150"]) == 0
    capsys.readouterr()
    scene = parse3d.load_scene(d)
    settled = scene.objects["mug"].settled_position
    assert scene.settled and lifted[2] - settled[2] > 0.01

    def ceilings() -> dict[str, bool]:
        import mujoco
        from pxr import Usd

        glb = {n.get("name") for n in _glb_json(d / "scene.glb")["nodes"]}
        model = mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
        stage = Usd.Stage.Open(str(d / "scene.usd"))  # held: its prims die with it
        return {"glb": "room__ceiling" in glb,
                "mjcf": mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "room:ceiling") >= 0,
                "usd": stage.GetPrimAtPath("/World/Room/room__ceiling").IsValid()}

    # settling rewrote every export in the settled pose, but with the options it was made with
    assert ceilings() == {"glb": False, "mjcf": False, "usd": True}
    pos = _exported_mug_positions(d)
    assert np.allclose(pos["urdf"], lifted, atol=1e-6)  # exported --solved: stays solved
    for fmt in ("glb", "usd", "mjcf"):
        assert np.allclose(pos[fmt], settled, atol=1e-5), fmt
    # a refresh by export_scene keeps them too; a format asked for anew takes the new options
    earlier = (d / "scene.json").stat().st_mtime_ns - 10**9
    os.utime(d / "scene.glb", ns=(earlier, earlier))
    export_scene(scene, d, ["mjcf"], ExportOptions())
    assert ceilings() == {"glb": False, "mjcf": True, "usd": True}
    assert read_options(d)["mjcf"].ceiling and not read_options(d)["glb"].ceiling
    # a damaged record is a clear error before anything is written
    (d / "exports.json").write_text("{not json")
    before = (d / "scene.json").read_bytes()
    assert _cli(["settle", str(d), "--steps", "5"]) == 2
    err = capsys.readouterr().err
    assert "exports.json" in err and "not valid JSON" in err
    assert (d / "scene.json").read_bytes() == before


# -- datasets -----------------------------------------------------------------------------

def test_dataset_formats_are_written_and_part_of_its_identity(tmp_path, capsys):
    from parse3d.datagen.build import BuildConfig, build_dataset, resolve_pag_paths
    from parse3d.errors import InputError

    (tmp_path / "pags").mkdir()
    (tmp_path / "pags" / "tiny.json").write_text(json.dumps(TINY_PAG))
    source = resolve_pag_paths([tmp_path / "pags"])
    cfg = BuildConfig(scenes=1, seed=0, source=source, settle=False, formats=("glb", "mjcf"))
    out = tmp_path / "ds"
    report = build_dataset(cfg, out, workers=1)
    assert report.ok == 1
    scene = out / "scenes" / "00000"
    assert (scene / "scene.glb").is_file() and (scene / "scene.xml").is_file()
    assert any((scene / "meshes").glob("*.stl"))
    assert json.loads((out / "dataset.json").read_text())["formats"] == ["glb", "mjcf"]
    # the formats are a set: naming them in another order resumes the same dataset
    again = BuildConfig(scenes=1, seed=0, source=source, settle=False, formats=("mjcf", "glb"))
    assert build_dataset(again, out, workers=1).ok == 1
    other = BuildConfig(scenes=1, seed=0, source=source, settle=False, formats=("glb",))
    with pytest.raises(InputError, match="formats"):
        build_dataset(other, out, workers=1)
    with pytest.raises(InputError, match="unknown format 'fbx'"):
        BuildConfig(scenes=1, formats=("fbx",))
    # a finished dataset gets more formats through parse3d export
    assert _cli(["export", str(out), "--format", "obj"]) == 0
    capsys.readouterr()
    assert (scene / "scene.obj").is_file()
