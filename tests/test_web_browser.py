"""The PAG designer in a real browser: Debian's Chromium driven by Playwright against a live server.

Builds a small room by clicking (a desk, a table lamp whose base's bottom goes ON the desk's
tabletop top), watches validation problems appear and disappear next to their fields, solves,
checks that the scene canvas shows a rendered room, and saves a PAG that the CLI validates.
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest
import uvicorn
from PIL import Image
from playwright.sync_api import sync_playwright

from parse3d.web import create_app

CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--no-sandbox", "--disable-background-networking", "--disable-component-update",
                 "--disable-sync", "--disable-quic", "--no-first-run", "--headless",
                 "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"]

pytestmark = pytest.mark.skipif(
    not os.path.exists(CHROMIUM),
    reason=f"the browser tests need Debian's Chromium at {CHROMIUM} "
           "(make system-test installs it: apt-get install chromium)")


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    workdir = tmp_path_factory.mktemp("designer-browser")
    port = free_port()
    srv = uvicorn.Server(uvicorn.Config(create_app(workdir), host="127.0.0.1", port=port,
                                        log_level="warning"))
    thread = threading.Thread(target=srv.run, daemon=True)
    thread.start()
    deadline = time.time() + 30
    while not srv.started:
        if time.time() > deadline or not thread.is_alive():
            pytest.fail("the designer server did not start")
        time.sleep(0.05)
    yield f"http://127.0.0.1:{port}", workdir
    srv.should_exit = True
    thread.join(10)


@pytest.fixture(scope="module")
def page(server):
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        pg = browser.new_page(viewport={"width": 1500, "height": 1000}, accept_downloads=True)
        errors: list[str] = []
        pg.on("pageerror", lambda e: errors.append(str(e)))
        pg.goto(server[0] + "/")
        pg.wait_for_selector("body[data-ready='1']", timeout=30_000)
        pg.errors = errors
        yield pg
        browser.close()


def click_at(page, point: dict) -> None:
    assert point is not None
    page.mouse.click(point["x"], point["y"])


def wait_preview(page, side: str, category: str) -> None:
    page.wait_for_function(
        f"(window.designer.pickers.{side}.loaded || '').startsWith('{category}/')", timeout=30_000)


def canvas_pixels(page, selector: str) -> np.ndarray:
    """(H, W, 3) uint8 pixels of an element, without a 4 px rim (borders, antialiasing)."""
    png = page.locator(selector).screenshot()
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))[4:-4, 4:-4]


def test_build_validate_solve_and_save_by_clicking(page, server):
    url, workdir = server
    # add a desk: it has no supporter yet, said next to its row
    page.fill("#add-category", "desk")
    page.click("#add-object")
    problem = page.locator(".problem[data-for='/objects/0']")
    problem.wait_for()
    assert "object 'desk' has no supporter" in problem.inner_text()
    page.fill("#add-category", "table_lamp")
    page.click("#add-object")
    page.locator(".problem[data-for='/objects/1']").wait_for()

    # desk ON floor: the desk's problem disappears
    page.select_option("#child-object", "desk")
    page.select_option("#relation", "ON")
    assert page.locator("#parent-object option[value='ceiling']").is_disabled()  # not for ON
    page.select_option("#parent-object", "floor")
    page.click("#add-relation")
    page.locator(".problem[data-for='/objects/0']").wait_for(state="detached")

    # the lamp's base, then the arrow of its bottom surface, in the child preview
    page.select_option("#child-object", "table_lamp")
    wait_preview(page, "child", "table_lamp")
    click_at(page, page.evaluate("window.designer.pickers.child.screenPoint('base')"))
    # clicking a part picks the part, not the face clicked: the default surface applies
    assert page.inner_text("#child-ref") == "table_lamp:base"
    assert "on" in page.locator("#child-surfaces button[data-surface='']").get_attribute("class")
    assert page.locator("#child-preview").get_attribute("class") == "preview"
    click_at(page, page.evaluate("window.designer.pickers.child.screenPoint('base', 'bottom')"))
    assert page.inner_text("#child-ref") == "table_lamp:base@bottom"
    assert "on" in page.locator("#child-surfaces button[data-surface='bottom']").get_attribute("class")

    # the desk's tabletop, clicked: the part, with ON's default surface (its top)
    page.select_option("#parent-object", "desk")
    wait_preview(page, "parent", "desk")
    click_at(page, page.evaluate("window.designer.pickers.parent.screenPoint('tabletop')"))
    assert page.inner_text("#parent-ref") == "desk:tabletop"
    page.select_option("#relation", "ON")
    page.click("#add-relation")
    page.locator(".problem").first.wait_for(state="detached")
    page.wait_for_function("document.querySelector('#validity').textContent === 'valid'")
    rel = page.locator("#relations .row").nth(1)
    assert rel.locator(".rel-child").input_value() == "table_lamp:base@bottom"
    assert rel.locator(".rel-parent").input_value() == "desk:tabletop"

    # a bad room height: the problem shows next to the field, and goes when fixed
    page.fill("#room-height", "-2")
    height_problem = page.locator(".problem[data-for='/room/height']")
    height_problem.wait_for()
    assert "positive number of metres" in height_problem.inner_text()
    assert "has-problem" in page.locator("#room-height").get_attribute("class")
    page.fill("#room-height", "2.6")
    height_problem.wait_for(state="detached")

    # the graph: two objects, the floor, two part nodes, two support edges
    assert page.locator("#graph .node.object").count() == 2
    assert page.locator("#graph .node.room").count() == 1
    assert sorted(page.locator("#graph .node.part").evaluate_all(
        "ns => ns.map(n => n.dataset.id)")) == ["desk:tabletop", "table_lamp:base"]
    assert page.locator("#graph .edge-support").count() == 2

    # solve: stage progress, then the scene on the canvas
    blank = canvas_pixels(page, "#viewer canvas")
    page.click("#solve")
    page.wait_for_selector("#solve-status[data-done='1']", timeout=120_000)
    assert page.inner_text("#solve-status").startswith("2/2 objects placed")
    states = page.locator("#stages li").evaluate_all("ls => ls.map(l => l.className)")
    assert states == ["done"] * 5
    page.wait_for_function("window.designer.viewer.rendered > 0")
    page.wait_for_timeout(200)
    shot = canvas_pixels(page, "#viewer canvas")
    assert len(np.unique(blank.reshape(-1, 3), axis=0)) <= 2  # the empty viewer: background only
    colours = np.unique(shot.reshape(-1, 3), axis=0)
    assert len(colours) > 30, "the scene canvas is blank"
    background = np.all(shot == blank[blank.shape[0] // 2, blank.shape[1] // 2], axis=-1).mean()
    assert background < 0.6, f"{background:.0%} of the canvas is background"

    # click the lamp in the scene: its relation held after settling
    click_at(page, page.evaluate("window.designer.viewer.screenPoint('table_lamp')"))
    info = page.locator("#scene-info")
    info.locator("h4").wait_for()
    assert info.locator("h4").inner_text().startswith("table_lamp")
    row = info.locator("tr", has_text="table_lamp:base@bottom ON desk:tabletop")
    assert row.locator("td").nth(2).inner_text() == "✓"
    page.check("#contacts")
    assert page.evaluate("window.designer.viewer.overlay.visible")

    # the scene files can be downloaded
    links = page.locator("#downloads a").evaluate_all("as => as.map(a => a.getAttribute('href'))")
    assert [link.rsplit("/", 1)[1] for link in links] == ["scene.json", "scene.glb", "contacts.json"]
    assert all(page.request.get(url + link).ok for link in links)

    # save into the working folder; the CLI validates the file
    page.fill("#file-name", "corner.json")
    page.click("#save")
    page.wait_for_function("document.querySelector('#message').textContent.startsWith('saved')")
    saved = workdir / "corner.json"
    data = json.loads(saved.read_text())
    assert data["relations"][1] == {"relation": "ON", "child": "table_lamp:base@bottom",
                                    "parent": "desk:tabletop"}
    env = {**os.environ, "PYTHONPATH": str(Path(__file__).parents[1] / "src")}
    cli = subprocess.run([sys.executable, "-m", "parse3d", "validate", str(saved)],
                         capture_output=True, text=True, env=env, timeout=120)
    assert cli.returncode == 0, cli.stderr

    # and downloads the same PAG as YAML
    with page.expect_download() as dl:
        page.click("#download-yaml")
    import yaml

    assert yaml.safe_load(Path(dl.value.path()).read_text()) == data
    assert page.errors == []


def test_footprint_drawn_clockwise_is_turned_counter_clockwise(page):
    page.click("#draw")
    # clicks in the pad's viewBox, clockwise seen from above (y up): go round the square
    corners = page.evaluate("""() => {
        const svg = document.querySelector('#pad');
        const m = svg.getScreenCTM();
        const vb = svg.viewBox.baseVal;
        const flip = (x, y) => [x, 2 * vb.y + vb.height - y];
        return [[1, 1], [1, 4], [4, 4], [4, 1]].map(([x, y]) => {
            const [sx, sy] = flip(x, y);
            const p = svg.createSVGPoint(); p.x = sx; p.y = sy;
            const q = p.matrixTransform(m);
            return {x: q.x, y: q.y};
        });
    }""")
    for c in corners:
        click_at(page, c)
    click_at(page, corners[0])  # close the outline
    fp = page.evaluate("window.designer.state.doc.room.footprint")
    assert len(fp) == 4
    area = sum(x1 * y2 - x2 * y1 for (x1, y1), (x2, y2) in zip(fp, fp[1:] + fp[:1], strict=True)) / 2
    assert area == pytest.approx(9.0)
    assert page.input_value("#footprint").splitlines() == ["1, 1", "4, 1", "4, 4", "1, 4"]
    # typed clockwise: the validator's message shows next to the footprint
    page.fill("#footprint", "0, 0\n0, 3\n3, 3\n3, 0")
    page.locator("#footprint").blur()
    problem = page.locator(".problem[data-for='/room/footprint']")
    problem.wait_for()
    assert "clockwise" in problem.inner_text()
    page.click("#reverse")
    problem.wait_for(state="detached")
    assert page.evaluate("window.designer.state.doc.room.footprint") == [[0, 0], [3, 0], [3, 3], [0, 3]]
    # unsaved edits are not dropped without asking: dismissing keeps them, accepting drops them
    with answering(page, accept=False) as messages:
        page.click("#new")
    assert len(messages) == 1 and "unsaved changes" in messages[0]
    assert page.evaluate("window.designer.state.doc.room.footprint") == [[0, 0], [3, 0], [3, 3], [0, 3]]
    with answering(page, accept=True):
        page.click("#new")
    assert page.evaluate("window.designer.state.doc.room.footprint") == [[0, 0], [4, 0], [4, 3.5], [0, 3.5]]


def test_threejs_keeps_the_exported_names_and_owners(page, tmp_path):
    """scene.glb loaded by three.js's GLTFLoader in the page: every node keeps the name the
    exporter gave it (three.js drops colons, which the names avoid), under its object, with
    the exact ``object:part`` in ``userData``."""
    import base64

    from parse3d.assets.registry import vocabulary
    from parse3d.export import walk_scene
    from parse3d.pag import load_pag
    from parse3d.pipeline import PipelineOptions, run_pipeline

    pag = load_pag(Path(__file__).parents[1] / "examples" / "study.json", vocabulary=vocabulary())
    scene = run_pipeline(pag, seed=0, out=tmp_path,
                         options=PipelineOptions(settle=False, preview=False))
    want = {}
    for o in walk_scene(scene).objects:
        want[o.node] = [o.id, None]
        want.update({p.node: [p.key, o.node] for p in o.parts})
    want.update({f"room__{n}": [f"room:{n}", None] for n in scene.room.elements})
    got = page.evaluate("""async (b64) => {
        const { GLTFLoader } = await import("three/addons/loaders/GLTFLoader.js");
        const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
        const gltf = await new GLTFLoader().parseAsync(bytes.buffer, "");
        const out = {};
        gltf.scene.traverse((n) => {
          if (n === gltf.scene) return;
          out[n.name] = [n.userData.name ?? null, n.parent === gltf.scene ? null : n.parent.name];
        });
        return out;
    }""", base64.b64encode((tmp_path / "scene.glb").read_bytes()).decode())
    assert got == want


@contextlib.contextmanager
def answering(page, accept: bool):
    """Answer every dialog raised inside the block, and only those: yields their messages.

    A listener left behind (``page.once`` for a dialog that never came) would answer the next
    test's dialog first, so the listener is removed on leaving the block.
    """
    messages: list[str] = []

    def answer(dialog) -> None:
        messages.append(dialog.message)
        dialog.accept() if accept else dialog.dismiss()

    page.on("dialog", answer)
    try:
        yield messages
    finally:
        page.remove_listener("dialog", answer)


def fresh(page) -> None:
    """A new, empty PAG (accepting the discard question if there are unsaved edits)."""
    with answering(page, accept=True):
        page.click("#new")
        page.wait_for_function("window.designer.state.doc.objects.length === 0")
    page.evaluate("window.scrollTo(0, 0)")


def objects(page) -> list[str]:
    return page.evaluate("window.designer.state.doc.objects.map(o => o.id)")


def test_undo_and_redo_step_through_edits(page):
    fresh(page)
    assert page.locator("#undo").is_disabled() and page.locator("#redo").is_disabled()
    for cat in ("desk", "mug"):
        page.fill("#add-category", cat)
        page.click("#add-object")
    page.select_option("#child-object", "desk")
    page.select_option("#relation", "ON")
    page.select_option("#parent-object", "floor")
    page.click("#add-relation")
    assert objects(page) == ["desk", "mug"]
    page.click("#undo")  # the relation
    assert page.evaluate("window.designer.state.doc.relations.length") == 0
    page.click("#undo")  # the mug
    assert objects(page) == ["desk"]
    assert page.locator("#objects .row").count() == 1
    page.click("#redo")
    assert objects(page) == ["desk", "mug"]
    # the keyboard too (outside text fields, where the browser undoes typing)
    page.locator("#graph").click()
    page.keyboard.press("Control+z")
    assert objects(page) == ["desk"]
    page.keyboard.press("Control+Shift+z")
    page.keyboard.press("Control+y")
    assert objects(page) == ["desk", "mug"]
    assert page.evaluate("window.designer.state.doc.relations.length") == 1
    # a new edit drops what could be redone
    page.click("#undo")
    page.fill("#add-category", "book")
    page.click("#add-object")
    assert page.locator("#redo").is_disabled()
    assert objects(page) == ["desk", "mug", "book"]
    # typing a name is one step, not one per key
    page.fill("#pag-name", "")
    page.type("#pag-name", "reading-nook", delay=20)
    page.click("#undo")
    assert page.evaluate("window.designer.state.doc.name") in ("", "my-room")
    assert page.input_value("#pag-name") == page.evaluate("window.designer.state.doc.name")


def test_save_over_an_existing_file_asks_first(page, server):
    _, workdir = server
    fresh(page)
    page.fill("#add-category", "desk")
    page.click("#add-object")
    page.fill("#file-name", "overwrite-me.json")
    page.click("#save")
    page.wait_for_function("document.querySelector('#message').textContent.startsWith('saved')")
    saved = workdir / "overwrite-me.json"
    assert [o["id"] for o in json.loads(saved.read_text())["objects"]] == ["desk"]
    page.fill("#add-category", "mug")
    page.click("#add-object")
    # dismissed: the file stays as it was
    with answering(page, accept=False) as asked:
        page.click("#save")
        page.wait_for_function("document.querySelector('#message').textContent.startsWith('save:')")
    assert len(asked) == 1 and "overwrite-me.json exists. Replace it?" in asked[0]
    assert [o["id"] for o in json.loads(saved.read_text())["objects"]] == ["desk"]
    # accepted: replaced
    with answering(page, accept=True) as asked:
        page.click("#save")
        page.wait_for_function("document.querySelector('#message').textContent.startsWith('saved')")
    assert len(asked) == 1
    assert [o["id"] for o in json.loads(saved.read_text())["objects"]] == ["desk", "mug"]


def quadrants() -> bytes:
    """A 320 x 240 PNG: red, green, blue and yellow quadrants."""
    img = Image.new("RGB", (320, 240))
    for (x, y), c in {(0, 0): (220, 30, 30), (160, 0): (30, 200, 60),
                      (0, 120): (40, 60, 220), (160, 120): (240, 220, 40)}.items():
        img.paste(c, (x, y, x + 160, y + 120))
    buf = io.BytesIO()
    img.save(buf, "PNG")
    return buf.getvalue()


def test_reference_image_stays_beside_the_viewer(page):
    fresh(page)
    page.set_input_files("#reference-file", files=[
        {"name": "room-photo.png", "mimeType": "image/png", "buffer": quadrants()}])
    page.wait_for_function("window.designer.referenceLoaded === 'room-photo.png'")
    shot = np.asarray(Image.open(io.BytesIO(page.locator("#reference-img").screenshot())).convert("RGB"))
    h, w = shot.shape[:2]
    assert w > 200  # shown large enough to read
    for (fy, fx), colour in {(0.25, 0.25): (220, 30, 30), (0.25, 0.75): (30, 200, 60),
                             (0.75, 0.25): (40, 60, 220), (0.75, 0.75): (240, 220, 40)}.items():
        np.testing.assert_allclose(shot[int(fy * h), int(fx * w)], colour, atol=12)
    # adding objects and relations scrolls the page: the viewer and the photo stay in view
    for _ in range(14):
        page.fill("#add-category", "book")
        page.click("#add-object")
    page.locator("#relations").scroll_into_view_if_needed()
    page.evaluate("window.scrollTo(0, document.body.scrollHeight)")
    assert page.evaluate("window.scrollY") > 100
    vh = page.viewport_size["height"]
    for sel in ("#viewer", "#reference-img"):
        box = page.locator(sel).bounding_box()
        assert box["y"] >= 0 and box["y"] + box["height"] <= vh, (sel, box)
    # it stays for the session, and goes with ✕
    page.reload()
    page.wait_for_selector("body[data-ready='1']")
    page.wait_for_function("window.designer.referenceLoaded === 'room-photo.png'")
    page.click("#reference-clear")
    assert page.locator("#reference-img").count() == 0


def test_viewer_is_in_view_on_a_laptop_screen(page, server):
    pg = page.context.browser.new_page(viewport={"width": 1366, "height": 768})
    try:
        pg.goto(server[0] + "/")
        pg.wait_for_selector("body[data-ready='1']", timeout=30_000)
        box = pg.locator("#viewer").bounding_box()
        assert box["height"] >= 300 and box["y"] + box["height"] <= 768, box
    finally:
        pg.close()


def test_graph_of_sixty_objects_is_readable(page):
    """A 64-object living room: its graph fits the panel (no scrolling), nodes and labels
    keep their size and do not overlap, supporters come before what they hold."""
    fresh(page)
    page.click("#load-templates")
    page.select_option("#templates", "living-room-bright-11")
    page.fill("#template-seed", "0")
    page.click("#expand")
    page.wait_for_function("window.designer.state.doc.objects.length >= 60")
    n = page.evaluate("window.designer.state.doc.objects.length")
    assert n == 64
    assert page.locator("#graph .node.object").count() == n
    sizes = page.evaluate("""() => { const b = document.querySelector('.graph-box');
        return [b.scrollHeight, b.clientHeight, b.scrollWidth, b.clientWidth]; }""")
    assert sizes[0] <= sizes[1] + 1 and sizes[2] <= sizes[3] + 1, f"the graph scrolls: {sizes}"
    panel = page.locator(".graph-box").bounding_box()
    boxes = page.evaluate("""() => [...document.querySelectorAll('#graph .node.object')].map(g => {
        const c = g.querySelector('circle').getBoundingClientRect();
        const t = g.querySelector('text').getBoundingClientRect();
        return {c: [c.left, c.top, c.right, c.bottom], t: [t.left, t.top, t.right, t.bottom],
                font: parseFloat(getComputedStyle(g.querySelector('text')).fontSize)
                      * g.querySelector('text').getScreenCTM().a};
    })""")
    overlap = lambda a, b: min(a[2], b[2]) - max(a[0], b[0]) > 0.5 and min(a[3], b[3]) - max(a[1], b[1]) > 0.5  # noqa: E731
    for i, a in enumerate(boxes):
        for box in (a["c"], a["t"]):  # inside the panel
            assert panel["x"] - 1 <= box[0] and box[2] <= panel["x"] + panel["width"] + 1, box
            assert panel["y"] - 1 <= box[1] and box[3] <= panel["y"] + panel["height"] + 1, box
        assert a["font"] >= 9.5, "labels shrink with the graph"
        assert a["c"][2] - a["c"][0] >= 24, "nodes shrink with the graph"
        for b in boxes[i + 1:]:
            assert not overlap(a["c"], b["c"]), "object nodes overlap"
            assert not overlap(a["t"], b["t"]), "object labels overlap"
    # every object in its supporter's outline: a supporter above what it holds, in the same
    # column or an earlier one (the outline flows into columns left to right)
    centre = page.evaluate("""() => Object.fromEntries([...document.querySelectorAll('#graph .node.object')]
        .map(g => { const c = g.querySelector('circle').getBoundingClientRect();
                    return [g.dataset.id, [c.left, c.top]]; }))""")
    doc = page.evaluate("window.designer.state.doc")
    supports = {"ON", "IN", "HANGING_BELOW", "SECURED_TO"}
    for r in doc["relations"]:
        parent = r["parent"].split(":")[0].split("@")[0]
        if r["relation"] in supports and parent in centre:
            p, c = centre[parent], centre[r["child"].split(":")[0].split("@")[0]]
            assert p[1] < c[1] or p[0] < c[0] - 60, (r["parent"], r["child"])
    # and the drawing is drawn: the graph panel's pixels are not blank
    shot = np.asarray(Image.open(io.BytesIO(page.locator(".graph-box").screenshot())).convert("RGB"))
    assert len(np.unique(shot.reshape(-1, 3), axis=0)) > 20
    assert (shot.sum(axis=-1) < 600).mean() > 0.02  # ink: nodes, labels, edges
