"""The headless renderer: depth, masks and boxes against ray casting; shadows; files; CLI."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import jsonschema
import numpy as np
import pytest
import trimesh
from PIL import Image
from shapely.geometry import Point, Polygon

from parse3d.assets import registry
from parse3d.assets.model import Material
from parse3d.errors import InputError
from parse3d.geometry.frames import rot_z
from parse3d.pag.model import PAG, Room
from parse3d.render import (
    Camera,
    Renderer,
    asset_camera,
    look_at,
    mask_regions,
    overview_camera,
    plan_camera,
    preview_cameras,
    render_asset,
    sample_views,
    save_preview,
    view_record,
    write_views,
)
from parse3d.render.camera import intrinsics_from_fov
from parse3d.render.io import load_views_schema
from parse3d.scene.model import PlacedObject, Scene
from parse3d.scene.shell import build_shell

# ---------------------------------------------------------------------------------------------
# fixtures: a small hand-built study (the solver is not needed to test the renderer)


def _study() -> Scene:
    room = Room("study", ((0, 0), (4, 0), (4, 3.5), (0, 3.5)), 2.7)
    scene = Scene(PAG("render-test", room), 0, build_shell(room))

    def add(oid, category, seed, xy, yaw=0.0, z=0.0):
        asset = registry.generate(category, seed)
        scene.objects[oid] = PlacedObject(oid, category, asset, 1.0, rot_z(yaw),
                                          np.array([xy[0], xy[1], z]))
        return scene.objects[oid]

    desk = add("desk", "desk", 0, (2.0, 2.6))
    z_desk = desk.world_surface(desk.asset.part("tabletop"), "top").origin[2]
    add("mug", "mug", 0, (1.7, 2.5), 0.5, z_desk)
    add("cup", "cup", 1, (2.3, 2.7), 0.0, z_desk)
    table = add("coffee_table", "coffee_table", 0, (1.5, 1.0), 0.3)
    z_table = table.world_surface(table.asset.part("tabletop"), "top").origin[2]
    add("tea_cup", "tea_cup", 2, (1.5, 1.0), 0.0, z_table)
    add("side_table", "side_table", 0, (3.4, 0.8))
    return scene


@pytest.fixture(scope="module")
def scene() -> Scene:
    return _study()


@pytest.fixture(scope="module")
def renderer() -> Renderer:
    r = Renderer()
    yield r
    r.release()


@pytest.fixture(scope="module")
def sampled(scene, renderer) -> list[Camera]:
    return sample_views(scene, 2, np.random.default_rng(7), width=240, height=180,
                        renderer=renderer)


def _cameras(scene, sampled) -> dict[str, Camera]:
    return {"overview": overview_camera(scene, width=200, height=150),
            "plan": plan_camera(scene, width=200, height=160),
            "sampled": sampled[0]}


# ---------------------------------------------------------------------------------------------
# ray-casting reference


def _visible_shell(scene: Scene, cam: Camera) -> list[str]:
    """Shell elements the renderer draws: those whose inner face the camera is in front of."""
    out = []
    for name, el in scene.room.elements.items():
        if np.dot(cam.position - el.surface.origin, el.surface.normal) > -1e-6:
            out.append(name)
    return out


def _reference(scene: Scene, res):
    """World mesh of everything drawn, with per-face instance and part ids from the tables."""
    inst_of = {v: k for k, v in res.instances.items()}
    part_of = {v: k for k, v in res.parts.items()}
    meshes, inst, part = [], [], []
    for o in scene.placed:
        for p in o.asset.parts:
            m = o.part_mesh(p)
            meshes.append(m)
            inst.append(np.full(len(m.faces), inst_of[o.id]))
            part.append(np.full(len(m.faces), part_of[f"{o.id}:{p.name}"]))
    for name in _visible_shell(scene, res.camera):
        m = scene.room.elements[name].mesh
        meshes.append(m)
        inst.append(np.full(len(m.faces), inst_of[name]))
        part.append(np.full(len(m.faces), part_of[f"room:{name}"]))
    mesh = trimesh.util.concatenate(meshes)
    return mesh, np.concatenate(inst), np.concatenate(part)


def _cast(mesh: trimesh.Trimesh, cam: Camera, uv: np.ndarray, face_ids: np.ndarray):
    """First hits of the rays through pixel centres ``uv``.

    Returns (ray index, triangle index, camera z, ambiguous) per hit ray; ``ambiguous`` marks
    rays whose first hit is matched, at the same distance, by a face of another id: coplanar
    overlapping faces (wall tops meeting at a room corner) have no defined winner. Each id's
    faces are cast separately for that, since one cast reports only one of coplanar hits.
    """
    from trimesh.ray.ray_pyembree import RayMeshIntersector

    origins, dirs = cam.rays(uv)
    unit = dirs / np.linalg.norm(dirs, axis=1, keepdims=True)
    tri, ray, loc = RayMeshIntersector(mesh).intersects_id(
        origins, unit, multiple_hits=False, return_locations=True)
    dist = np.einsum("ij,ij->i", loc - origins[ray], unit[ray])
    hit_id = face_ids[tri]
    ambiguous = np.zeros(len(ray), bool)
    for i in np.unique(face_ids):
        sub = mesh.submesh([np.flatnonzero(face_ids == i)], append=True)
        t2, r2, l2 = RayMeshIntersector(sub).intersects_id(
            origins[ray], unit[ray], multiple_hits=False, return_locations=True)
        d2 = np.einsum("ij,ij->i", l2 - origins[ray][r2], unit[ray][r2])
        ambiguous[r2[(np.abs(d2 - dist[r2]) < 1e-5) & (hit_id[r2] != i)]] = True
    z = (loc @ cam.R.T + cam.t)[:, 2]
    return ray, tri, z, ambiguous


def _interior(mask: np.ndarray) -> np.ndarray:
    """(H, W) bool: pixels whose whole 3x3 neighbourhood has one id (not on a silhouette)."""
    H, W = mask.shape
    p = np.pad(mask, 1, mode="edge")
    same = np.ones((H, W), bool)
    for dy in (0, 1, 2):
        for dx in (0, 1, 2):
            same &= p[dy:dy + H, dx:dx + W] == mask
    return same


# ---------------------------------------------------------------------------------------------
# cameras


def test_gl_projection_reproduces_opencv_pixels():
    rng = np.random.default_rng(0)
    K = np.array([[300.0, 0, 151.3], [0, 280.0, 97.8], [0, 0, 1]])
    R, t = look_at([0.3, -2.0, 1.4], [0.1, 0.5, 0.6])
    for projection in ("perspective", "orthographic"):
        cam = Camera(K if projection == "perspective" else K * [[0.2], [0.2], [1]], R, t,
                     320, 200, 0.1, 20.0, projection)
        pts = np.array([0.1, 0.5, 0.6]) + rng.normal(0, 0.4, (50, 3))
        uv, z = cam.project(pts)
        clip = (np.c_[pts, np.ones(len(pts))] @ cam.gl_view().T) @ cam.gl_projection().T
        ndc = clip[:, :3] / clip[:, 3:]
        x_win = (ndc[:, 0] + 1) / 2 * cam.width
        y_win = (ndc[:, 1] + 1) / 2 * cam.height
        # OpenGL pixel centres are at half-integers; rows count from the bottom
        np.testing.assert_allclose(x_win - 0.5, uv[:, 0], atol=1e-9)
        np.testing.assert_allclose(cam.height - y_win - 0.5, uv[:, 1], atol=1e-9)
        # rays through the projections pass through the points
        o, d = cam.rays(uv)
        np.testing.assert_allclose(o + d * z[:, None], pts, atol=1e-9)


def test_camera_dict_round_trip_and_conventions(scene):
    cam = overview_camera(scene, width=64, height=48)
    back = Camera.from_dict(json.loads(json.dumps(cam.to_dict())))
    for a in ("K", "R", "t"):
        np.testing.assert_allclose(getattr(back, a), getattr(cam, a))
    # OpenCV: +y of the camera points down in the world for an upright camera
    assert cam.R[1] @ [0, 0, 1] < 0
    np.testing.assert_allclose(cam.world_to_camera @ cam.camera_to_world, np.eye(4), atol=1e-12)
    assert 1.2 < cam.position[2] < 1.8


# ---------------------------------------------------------------------------------------------
# depth and masks against ray casting


@pytest.mark.parametrize("which", ["overview", "plan", "sampled"])
def test_depth_and_masks_match_ray_casting(scene, renderer, sampled, which):
    cam = _cameras(scene, sampled)[which]
    res = renderer.render(scene, cam, color=False)
    mesh, inst_of_face, part_of_face = _reference(scene, res)
    H, W = res.instance.shape
    vv, uu = np.mgrid[0:H, 0:W]
    uv = np.c_[uu.ravel(), vv.ravel()].astype(float)
    ray, tri, z, ambiguous = _cast(mesh, cam, uv, part_of_face)
    inst_ref = np.zeros(H * W, np.int32)
    part_ref = np.zeros(H * W, np.int32)
    depth_ref = np.zeros(H * W)
    inst_ref[ray], part_ref[ray], depth_ref[ray] = inst_of_face[tri], part_of_face[tri], z
    interior = (_interior(res.instance) & _interior(res.part)).ravel()
    interior[ray[ambiguous]] = False
    assert interior.mean() > 0.8
    # every mask pixel away from silhouettes names what the ray through its centre hits
    np.testing.assert_array_equal(res.instance.ravel()[interior], inst_ref[interior])
    np.testing.assert_array_equal(res.part.ravel()[interior], part_ref[interior])
    # depth in metres from the same geometry
    hit = interior & (inst_ref > 0)
    assert hit.sum() > 0.5 * H * W
    err = np.abs(res.depth.ravel()[hit] - depth_ref[hit])
    assert np.percentile(err, 99) < 0.002, np.percentile(err, 99)
    assert np.all(res.depth.ravel()[res.instance.ravel() == 0] == 0)
    # normals are unit and face the camera where something is hit
    n = res.normals.reshape(-1, 3)[hit]
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0, atol=1e-3)
    if not cam.orthographic:
        _, d = cam.rays(uv[hit])
        assert np.mean(np.einsum("ij,ij->i", n, d) <= 1e-6) > 0.99


def test_objects_seen_from_inside_and_shell_ids(scene, renderer):
    cam = overview_camera(scene, width=160, height=120)
    res = renderer.render(scene, cam, color=False)
    names = {res.instances[i] for i in np.unique(res.instance) if i}
    assert {"desk", "coffee_table", "side_table", "floor"} <= names
    assert any(n.startswith("wall_") for n in names)
    assert set(res.instances.values()) >= {"floor", "ceiling", "wall_0", "wall_3"}
    assert res.parts[max(res.parts)] == "room:ceiling"
    # the plan camera looks down through the (hidden) ceiling onto the floor
    top = renderer.render(scene, plan_camera(scene, width=160, height=120), color=False)
    top_names = {top.instances[i] for i in np.unique(top.instance) if i}
    assert "ceiling" not in top_names and "floor" in top_names


def test_boxes_equal_mask_extents(scene, renderer, sampled):
    res = renderer.render(scene, sampled[0], color=False)
    rec = view_record(res)
    for key, mask, table in (("objects", res.instance, res.instances),
                             ("parts", res.part, res.parts)):
        ids = [i for i in np.unique(mask) if i]
        assert [r["id"] for r in rec[key]] == ids
        for r in rec[key]:
            ys, xs = np.nonzero(mask == r["id"])
            assert r["pixels"] == len(xs)
            assert r["bbox"] == [xs.min(), ys.min(), xs.max(), ys.max()]
            assert r["object" if key == "objects" else "part"] == table[r["id"]]
    assert mask_regions(np.zeros((4, 5), np.int32)) == []


def test_rendering_is_deterministic(scene, renderer, sampled):
    a = renderer.render(scene, sampled[1])
    b = renderer.render(scene, sampled[1])
    fresh = Renderer(samples=renderer.samples)
    try:
        c = fresh.render(scene, sampled[1])
    finally:
        fresh.release()
    for other in (b, c):
        np.testing.assert_array_equal(a.instance, other.instance)
        np.testing.assert_array_equal(a.part, other.part)
        np.testing.assert_array_equal(a.depth, other.depth)
        np.testing.assert_array_equal(a.rgb, other.rgb)


def test_rgb_only_and_masks_only_equal_the_full_render(scene, renderer, sampled):
    cams = sampled[:3]
    masks = renderer.instance_masks(scene, [c.resized(96, 72) for c in cams])
    for cam, mask in zip(cams, masks, strict=True):
        full = renderer.render(scene, cam)
        np.testing.assert_array_equal(renderer.render_rgb(scene, cam), full.rgb)
        small = renderer.render(scene, cam.resized(96, 72), color=False, shadows=False)
        assert mask.dtype == np.int32
        np.testing.assert_array_equal(mask, small.instance)


def test_view_culling_changes_no_pixel(scene, renderer, sampled, monkeypatch):
    from parse3d.render import renderer as module

    cams = [*sampled[:3], overview_camera(scene)]
    culled = []
    keep = module._in_view

    def counted(items, camera):
        out = keep(items, camera)
        culled.append(sum(it.mesh.vbo is not None for it in items) - len(out))
        return out

    monkeypatch.setattr(module, "_in_view", counted)
    with_cull = [renderer.render(scene, cam) for cam in cams]
    assert sum(culled) > 0  # some views leave objects out
    monkeypatch.setattr(module, "_in_view",
                        lambda items, camera: [it for it in items if it.mesh.vbo is not None])
    for cam, a in zip(cams, with_cull, strict=True):
        b = renderer.render(scene, cam)
        for name in ("rgb", "depth", "instance", "part", "normals"):
            np.testing.assert_array_equal(getattr(a, name), getattr(b, name))


def test_vertex_data_matches_trimesh_per_mesh():
    from parse3d.render.renderer import _closed, _vertex_data

    box = trimesh.creation.box((0.4, 0.3, 0.2))
    sphere = trimesh.creation.icosphere(2)
    sphere.apply_translation([1.0, 0.0, 0.0])
    card = trimesh.Trimesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.2]],
                           [[0, 1, 2], [2, 1, 3]], process=False)
    empty = trimesh.Trimesh(np.zeros((0, 3)), np.zeros((0, 3), int), process=False)
    mat = Material((0.5, 0.2, 0.9, 1.0), 0.3, 0.1, "m")
    meshes = [card, box, empty, sphere]
    data, n_closed = _vertex_data([(m, mat) for m in meshes])
    want = {}
    for k, m in enumerate(meshes):
        if len(m.faces) == 0:
            continue
        m = m.copy()
        fn = np.repeat(m.face_normals, 3, axis=0)
        vn = m.vertex_normals[m.faces].reshape(-1, 3)
        smooth = np.einsum("ij,ij->i", fn, vn) > np.cos(np.deg2rad(35.0))
        want[k] = (m.vertices[m.faces].reshape(-1, 3), np.where(smooth[:, None], vn, fn))
    order = [k for k in want if _closed(meshes[k])] + [k for k in want if not _closed(meshes[k])]
    assert order == [1, 3, 0]  # closed meshes first, each in its own order
    assert n_closed == sum(len(want[k][0]) for k in (1, 3))
    np.testing.assert_array_equal(data[:, 11], np.concatenate(
        [np.full(len(want[k][0]), k) for k in order]))
    for col, which in ((slice(0, 3), 0), (slice(3, 6), 1)):
        np.testing.assert_array_equal(
            data[:, col], np.concatenate([want[k][which] for k in order]).astype(np.float32))
    np.testing.assert_allclose(data[:, 6:9], np.tile(np.array(mat.color[:3]) ** 2.2,
                                                     (len(data), 1)), rtol=1e-6)


# ---------------------------------------------------------------------------------------------
# colour and shadows


def test_rgb_is_shaded_and_shadows_darken_the_floor(scene, renderer):
    cam = overview_camera(scene, width=320, height=240)
    res = renderer.render(scene, cam)
    rgb = res.rgb.astype(float)
    assert res.rgb.dtype == np.uint8 and rgb.std() > 15
    assert len(np.unique(res.rgb.reshape(-1, 3), axis=0)) > 500
    floor_id = next(k for k, v in res.instances.items() if v == "floor")
    interior = _interior(res.instance)
    ys, xs = np.nonzero((res.instance == floor_id) & interior)
    o, d = cam.rays(np.c_[xs, ys].astype(float))
    pts = o + d * res.depth[ys, xs][:, None]
    # which floor points see the key light: cast rays towards it through the objects
    L = np.asarray(renderer.lighting.key_direction, float)
    L /= np.linalg.norm(L)
    objs = trimesh.util.concatenate([o.mesh() for o in scene.placed])
    from trimesh.ray.ray_pyembree import RayMeshIntersector

    blocked = RayMeshIntersector(objs).intersects_any(pts + 1e-3 * L, np.tile(L, (len(pts), 1)))
    assert 50 < blocked.sum() < 0.8 * len(pts)
    lum = rgb[ys, xs].mean(axis=1)
    shadowed, lit = lum[blocked], lum[~blocked]
    assert shadowed.mean() < 0.75 * lit.mean()
    assert np.mean(shadowed < np.median(lit)) > 0.95
    # without shadow mapping the same pixels are as bright as open floor
    flat = renderer.render(scene, cam, shadows=False).rgb.astype(float)[ys, xs].mean(axis=1)
    assert flat[blocked].mean() > 0.9 * flat[~blocked].mean()


def test_render_asset_thumbnail():
    asset = registry.generate("desk", 3)
    res = render_asset(asset, size=(128, 96))
    assert res.rgb.shape == (96, 128, 3)
    fg = res.instance == 1
    assert 0.1 < fg.mean() < 0.9
    (r,) = mask_regions(res.instance)
    assert r.bbox[0] > 0 and r.bbox[1] > 0 and r.bbox[2] < 127 and r.bbox[3] < 95
    assert set(np.unique(res.part)) - {0} <= set(res.parts)
    assert len(set(np.unique(res.part)) - {0}) >= 2
    bg = res.rgb[~fg].astype(float).mean(axis=0)
    assert np.abs(res.rgb[fg].astype(float).mean(axis=0) - bg).max() > 10
    # a 3/4 view from the front-right: the camera sits at +X, +Y, above
    cam = asset_camera(asset.bounds, width=64, height=64)
    assert cam.position[0] > 0 and cam.position[1] > 0 and cam.position[2] > asset.bounds[1, 2] / 2


# ---------------------------------------------------------------------------------------------
# view sampling


def test_sampled_views_follow_the_rules(scene, renderer, sampled):
    poly = Polygon(scene.room.footprint)
    for cam in sampled:
        p = cam.position
        assert poly.contains(Point(p[0], p[1])) and 1.2 <= p[2] <= 1.8
        for o in scene.placed:
            lo, hi = o.world_bounds()
            assert not np.all((p > lo) & (p < hi)), f"camera inside {o.id}"
        res = renderer.render(scene, cam, color=False)
        h3, w3 = cam.height // 3, cam.width // 3
        centre = res.depth[h3:cam.height - h3, w3:cam.width - w3]
        assert centre[centre > 0].min() >= 1.0
        counts = [(res.instance == i).sum() for i, n in res.instances.items()
                  if n in scene.objects]
        assert sum(c >= 200 for c in counts) >= 3
        assert not cam.meta.get("relaxed")


def test_failed_objects_get_no_id_and_tiny_rooms_give_no_views(scene, renderer):
    room = Room("closet", ((0, 0), (1.2, 0), (1.2, 1.0), (0, 1.0)), 2.4)
    tiny = Scene(PAG("tiny", room), 0, build_shell(room))
    tiny.objects["mug"] = scene.objects["mug"]
    tiny.objects["ghost"] = PlacedObject("ghost", "desk", None, status="failed", reason="test")
    assert sample_views(tiny, 2, np.random.default_rng(0), width=64, height=48,
                        renderer=renderer) == []
    res = renderer.render(tiny, plan_camera(tiny, width=64, height=48), color=False)
    assert "ghost" not in res.instances.values() and res.instances[1] == "mug"
    assert list(res.parts.values())[:2] == ["mug:body", "mug:handle"]


def test_sample_views_is_reproducible(scene, renderer):
    a = sample_views(scene, 2, np.random.default_rng(3), width=96, height=72, renderer=renderer)
    b = sample_views(scene, 2, np.random.default_rng(3), width=96, height=72, renderer=renderer)
    assert len(a) == 2
    for x, y in zip(a, b, strict=True):
        np.testing.assert_array_equal(x.R, y.R)
        np.testing.assert_array_equal(x.t, y.t)


# ---------------------------------------------------------------------------------------------
# files


def test_write_views_files_and_schema(scene, renderer, sampled, tmp_path):
    doc = write_views(scene, sampled, tmp_path, renderer=renderer, meta={"seed": 7})
    jsonschema.validate(json.loads((tmp_path / "views.json").read_text()), load_views_schema())
    assert len(doc["views"]) == len(sampled)
    for k, cam in enumerate(sampled):
        res = renderer.render(scene, cam)
        depth = np.asarray(Image.open(tmp_path / f"depth_{k}.png"))
        inst = np.asarray(Image.open(tmp_path / f"instance_{k}.png"))
        part = np.asarray(Image.open(tmp_path / f"part_{k}.png"))
        rgb = np.asarray(Image.open(tmp_path / f"rgb_{k}.png"))
        np.testing.assert_array_equal(inst, res.instance)
        np.testing.assert_array_equal(part, res.part)
        np.testing.assert_array_equal(depth, np.rint(res.depth.astype(float) * 1000))
        np.testing.assert_array_equal(rgb, res.rgb)
        assert doc["views"][k]["camera"]["K"] == cam.K.tolist()
    assert doc["instances"]["1"] == "desk"
    assert "room:floor" in doc["parts"].values()


def test_save_preview(scene, tmp_path):
    # two panels of 160x120 side by side; each the colour render of its camera
    path = save_preview(scene, tmp_path / "preview.png", width=160, height=120)
    img = np.asarray(Image.open(path))
    assert img.shape == (120, 320, 3) and img[:, :160].std() > 10 and img[:, 160:].std() > 10
    r = Renderer()
    cams = preview_cameras(scene, width=160, height=120, renderer=r)
    np.testing.assert_array_equal(img[:, 160:], r.render_rgb(scene, cams[1]))
    one = np.asarray(Image.open(save_preview(scene, tmp_path / "one.png", width=160, height=120,
                                             panels=1)))
    np.testing.assert_array_equal(one, img[:, :160])
    with pytest.raises(InputError, match="panels"):
        save_preview(scene, tmp_path / "none.png", panels=0)


def test_missing_egl_raises_dependency_error():
    # A real failure, not a mock: point libglvnd at no EGL vendor at all.
    code = ("from parse3d.render import Renderer\n"
            "from parse3d.errors import DependencyError\n"
            "try:\n    Renderer()\nexcept DependencyError as e:\n    print('DEPENDENCY', e)\n")
    env = dict(os.environ, __EGL_VENDOR_LIBRARY_FILENAMES="/nonexistent/egl_vendor.json",
               __EGL_VENDOR_LIBRARY_DIRS="/nonexistent")
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                         text=True, timeout=120)
    assert "DEPENDENCY" in out.stdout, out.stdout + out.stderr
    for pkg in ("libegl1", "libegl-mesa0", "libgl1-mesa-dri"):
        assert pkg in out.stdout


# ---------------------------------------------------------------------------------------------
# command line


def test_cli_render_writes_views(scene, tmp_path):
    from typer.testing import CliRunner

    from parse3d.cli import app
    from parse3d.scene.io import write_scene

    write_scene(scene, tmp_path, glb=False)
    result = CliRunner().invoke(app, ["render", str(tmp_path), "--views", "2", "--size",
                                      "160x120", "--seed", "1", "--json"])
    assert result.exit_code == 0, result.output
    summary = json.loads(result.output)
    assert summary["views"] == 2
    doc = json.loads((tmp_path / "views.json").read_text())
    jsonschema.validate(doc, load_views_schema())
    for k in range(2):
        for kind in ("rgb", "depth", "instance", "part"):
            img = Image.open(tmp_path / f"{kind}_{k}.png")
            assert img.size == (160, 120)
        assert np.asarray(Image.open(tmp_path / f"instance_{k}.png")).dtype == np.uint16
    assert doc["views"][0]["camera"]["width"] == 160
    assert sorted(doc["instances"].values())[:3] == ["ceiling", "coffee_table", "cup"]


def test_cli_render_rejects_bad_size(scene, tmp_path, capsys):
    from parse3d.cli import main
    from parse3d.scene.io import write_scene

    write_scene(scene, tmp_path, glb=False)
    with pytest.raises(SystemExit) as exc:
        main(["render", str(tmp_path), "--size", "640by480"])
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert "--size" in err and "640x480" in err and "Traceback" not in err


def test_intrinsics_from_fov():
    K = intrinsics_from_fov(640, 480, 90.0)
    assert K[0, 0] == pytest.approx(320.0) and K[0, 2] == pytest.approx(319.5)


def test_colour_without_msaa_is_depth_tested(scene, renderer, sampled):
    """``samples=0`` draws into the resolve target: nearer surfaces still hide farther ones,
    so the image differs from the multisampled one only along edges."""
    plain = Renderer(samples=0)
    try:
        a = plain.render_rgb(scene, sampled[1]).astype(int)
    finally:
        plain.release()
    b = renderer.render_rgb(scene, sampled[1]).astype(int)
    assert np.abs(a - b).max(axis=-1).mean() < 3.0


def test_vertex_normals_arithmetic_is_trimeshs_bit_for_bit():
    """The renderer's face normals, corner angles and unit vertex normals are trimesh's
    (``util.unitize``, ``triangles.angles``) to the last bit, on real asset meshes and on
    degenerate triangles, so a preview looks the same without importing trimesh."""
    from parse3d.geometry.surfaces import unit_normals
    from parse3d.render.renderer import _corner_angles, _unitize

    tris = []
    for cat, seed in (("mug", 0), ("armchair", 1), ("wall_shelf", 2)):
        for p in registry.generate(cat, seed).parts:
            m = p.mesh_arrays if hasattr(p, "mesh_arrays") else p.mesh
            tris.append(np.asarray(m.vertices, float)[np.asarray(m.faces)])
    flat = np.array([[[0, 0, 0], [1, 0, 0], [2, 0, 0]],   # collinear
                     [[0, 0, 0], [0, 0, 0], [0, 1, 0]],   # two corners at one point
                     [[0, 0, 0], [1e-15, 0, 0], [0, 1e-15, 0]]], float)
    tri = np.concatenate([*tris, flat])
    e = tri[:, 1:, :] - tri[:, :2, :]
    cross = np.cross(e[:, 0], e[:, 1])
    assert np.array_equal(_unitize(cross, zero=True), unit_normals(cross))
    assert np.array_equal(_corner_angles(tri), trimesh.triangles.angles(tri))
    rows = np.random.default_rng(0).normal(size=(500, 3))
    rows[::50] = 0.0
    assert np.array_equal(_unitize(rows), trimesh.util.unitize(rows))


def test_solve_with_preview_imports_no_mesh_library(tmp_path):
    """``parse3d solve`` (settle, contacts, preview) never needs trimesh for a rectangular
    room: its import is a fifth of the command's time."""
    code = ("import sys\nfrom parse3d.cli import main\n"
            f"sys.argv = ['parse3d', 'solve', 'examples/study.json', '-o', {str(tmp_path)!r}]\n"
            "try:\n    main()\nexcept SystemExit as e:\n    assert not e.code, e.code\n"
            "print('trimesh' in sys.modules)\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       timeout=600, cwd=os.path.dirname(os.path.dirname(__file__)))
    assert r.returncode == 0, r.stderr[-2000:]
    assert r.stdout.strip().splitlines()[-1] == "False"
    assert (tmp_path / "preview.png").is_file()
