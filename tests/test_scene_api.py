"""The Python API of a scene: save, load_scene, export by suffix, the notebook viewer."""

from __future__ import annotations

import json

import numpy as np
import pytest
import trimesh

import parse3d
from parse3d.errors import InputError
from parse3d.pag import load_pag
from parse3d.pipeline import PipelineOptions, run_pipeline

PAG_DOC = {"format": "pag/1", "name": "tiny",
           "room": {"type": "study", "footprint": [[0, 0], [3, 0], [3, 3], [0, 3]],
                    "height": 2.6},
           "objects": [{"id": "desk", "category": "desk"}, {"id": "mug", "category": "mug"}],
           "relations": [{"relation": "ON", "child": "desk", "parent": "floor"},
                         {"relation": "ON", "child": "mug", "parent": "desk:tabletop"}]}


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    """A desk with a mug, solved, settled, contacts extracted."""
    from parse3d.assets.registry import vocabulary

    path = tmp_path_factory.mktemp("pag") / "tiny.json"
    path.write_text(json.dumps(PAG_DOC))
    pag = load_pag(path, vocabulary=vocabulary())
    return run_pipeline(pag, seed=0, out=None, options=PipelineOptions(preview=False, formats=()))


def test_save_writes_what_solve_writes_and_load_scene_reads_it_back(scene, tmp_path):
    assert scene.contacts is not None
    out = scene.save(tmp_path / "s")
    assert {p.name for p in out.iterdir()} >= {"scene.json", "scene.glb", "contacts.json"}
    assert not (out / "preview.png").exists()
    back = parse3d.load_scene(out)
    assert back.objects.keys() == scene.objects.keys()
    np.testing.assert_allclose(back.objects["mug"].transform(), scene.objects["mug"].transform(),
                               rtol=1e-5, atol=1e-6)
    assert parse3d.load_scene(out / "scene.json").seed == scene.seed
    # a reloaded scene exports again, and an unknown format is refused by name
    files = back.export(tmp_path / "again.glb")
    assert trimesh.load(files[0]).geometry
    with pytest.raises(InputError, match="unknown format 'fbx'"):
        scene.save(tmp_path / "t", formats=("fbx",))


def test_export_by_suffix_writes_files_their_readers_parse(scene, tmp_path):
    import mujoco
    import yourdfpy
    from pxr import Usd

    glb = trimesh.load(scene.export(tmp_path / "a" / "room.glb")[0])
    names = set(glb.graph.nodes)
    assert "mug" in names and "desk" in names
    gltf = scene.export(tmp_path / "room.gltf")[0]
    assert json.loads(gltf.read_text())["buffers"][0]["uri"].startswith("data:")
    assert len(trimesh.load(gltf).geometry) == len(glb.geometry)
    for suffix in (".usd", ".usda", ".usdc"):
        stage = Usd.Stage.Open(str(scene.export(tmp_path / f"room{suffix}")[0]))
        assert stage.GetPrimAtPath("/World/Objects/mug").IsValid()
    assert (tmp_path / "room.usda").read_text().startswith("#usda")
    xml = scene.export(tmp_path / "m" / "room.xml")[0]
    model = mujoco.MjModel.from_xml_path(str(xml))
    assert model.nbody > 2
    files = scene.export(tmp_path / "u" / "room.urdf")
    placed = json.loads((tmp_path / "u" / "urdf" / "scene.json").read_text())
    assert {r["id"] for r in placed} == {"desk", "mug", "room"}
    mug = next(f for f in files if f.name == "mug.urdf")
    assert yourdfpy.URDF.load(str(mug)).link_map
    obj = scene.export(tmp_path / "o" / "room.obj")
    assert [p.name for p in obj] == ["room.obj", "room.mtl"]
    assert "mtllib room.mtl" in obj[0].read_text()
    assert trimesh.load(obj[0], force="scene").geometry


def test_export_refuses_an_unknown_suffix_with_the_known_ones(scene, tmp_path):
    with pytest.raises(InputError, match=r"'\.fbx'.*\.glb"):
        scene.export(tmp_path / "room.fbx")
    with pytest.raises(InputError, match="no export format"):
        scene.export(tmp_path / "room")


def test_save_with_preview_writes_the_png_and_records_its_time(scene, tmp_path):
    from PIL import Image

    out = scene.save(tmp_path / "p", formats=(), preview=True)
    # two panels of 1280x960 side by side (docs/render.md, "Preview")
    assert Image.open(out / "preview.png").size == (2560, 960)
    assert not (out / "scene.glb").exists()
    assert "preview" in json.loads((out / "scene.json").read_text())["timings"]


def test_notebook_html_embeds_the_glb_and_the_viewer_scripts(scene):
    import base64
    import html
    import re

    snippet = scene._repr_html_()
    assert snippet.startswith("<iframe srcdoc=")
    page = html.unescape(re.search(r'srcdoc="([^"]*)"', snippet).group(1))
    glb = base64.b64decode(re.search(r'id="p3d-glb"[^>]*>([^<]*)<', page).group(1))
    assert glb[:4] == b"glTF"
    assert {"mug", "desk"} <= set(trimesh.load(trimesh.util.wrap_as_stream(glb),
                                               file_type="glb").graph.nodes)
    # three.js and its loaders are inside (works offline): no script fetched from anywhere
    assert all(f'id="{i}"' in page for i in ("p3d-three", "p3d-gltf", "p3d-orbit", "p3d-bgu"))
    assert "<script>" in page and "src=" not in page and "://" not in page


def test_show_writes_a_page_that_chromium_draws_with_the_part_names(scene, tmp_path):
    import os

    if not os.path.exists("/usr/bin/chromium"):
        pytest.skip("needs Debian's Chromium (apt-get install chromium)")
    from playwright.sync_api import sync_playwright

    from parse3d.outputs import in_notebook

    assert not in_notebook()  # so show() writes the page rather than displaying it
    path = scene.show(tmp_path / "view.html", open_browser=False)
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path="/usr/bin/chromium", args=[
            "--no-sandbox", "--headless", "--use-gl=angle", "--use-angle=swiftshader",
            "--enable-unsafe-swiftshader"])
        page = browser.new_page(viewport={"width": 640, "height": 480})
        errors: list[str] = []
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto(path.as_uri())
        page.wait_for_selector("body[data-ready]", timeout=60_000)
        ready = page.evaluate("document.body.dataset.ready")
        viewer = page.evaluate("window.parse3dViewer")
        label = page.text_content("#p3d-label")
        page.mouse.move(320, 240)  # the view's centre: the room or an object, named on hover
        hovered = page.text_content("#p3d-label")
        browser.close()
    assert ready == "1", label
    assert not errors
    assert hovered in viewer["names"]
    assert viewer["meshes"] > 2
    names = viewer["names"]
    assert any(n.startswith("mug : ") for n in names) and any(n.startswith("desk : ") for n in names), names


def test_render_returns_the_preview_image_and_takes_a_camera(scene, tmp_path):
    from PIL import Image

    from parse3d.render import overview_camera, save_preview

    rgb = scene.render(160, 120)
    assert rgb.shape == (120, 160, 3) and rgb.dtype == np.uint8
    assert rgb.std() > 5  # a room, not a blank frame
    # the same pixels as the main (left) panel of the preview parse3d solve writes
    ref = np.asarray(Image.open(save_preview(scene, tmp_path / "p.png", width=160, height=120,
                                             panels=1)))
    np.testing.assert_array_equal(rgb, ref)
    cam = overview_camera(scene, width=96, height=64)
    assert scene.render(camera=cam).shape == (64, 96, 3)
