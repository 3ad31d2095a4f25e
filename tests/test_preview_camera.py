"""The preview's viewpoint shows the room: chosen by rendered visibility, occluders considered."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("moderngl")

from parse3d.datagen.templates import expand_template, list_templates  # noqa: E402
from parse3d.pag.io import load_pag  # noqa: E402
from parse3d.render import (  # noqa: E402
    PREVIEW_PANELS,
    PREVIEW_SIZE,
    Renderer,
    overview_camera,
    preview_camera,
    preview_cameras,
)
from parse3d.render.camera import MAX_OBJECT_SHARE  # noqa: E402
from parse3d.render.renderer import scene_id_tables  # noqa: E402
from parse3d.render.viewpoint import MIN_CLEARANCE, MIN_PIXELS  # noqa: E402
from parse3d.solver import solve  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent


def _pixels(r, scene, cam) -> dict[str, int]:
    mask = r.instance_masks(scene, [cam])[0]
    inst, _ = scene_id_tables(scene)
    vals, counts = np.unique(mask, return_counts=True)
    return {inst.get(int(v)): int(n) for v, n in zip(vals, counts, strict=True) if v > 0}


@pytest.fixture(scope="module")
def kitchen():
    # the kitchen whose eye-height preview hid its floor cabinets behind the island
    return solve(load_pag(ROOT / "examples" / "kitchen.json"), seed=0)


def test_kitchen_preview_sees_the_room(kitchen):
    scene, r = kitchen, Renderer()
    cam = preview_camera(scene, renderer=r)
    assert (cam.width, cam.height) == (640, 480)
    px = _pixels(r, scene, cam)
    ids = [o.id for o in scene.placed]
    seen = {i for i in ids if px.get(i, 0) >= MIN_PIXELS}
    walls = {e.child.object for e in scene.pag.relations
             if e.relation == "SECURED_TO" and e.parent.object.startswith("wall")}
    assert walls and walls <= seen, walls - seen  # every wall-mounted object in view
    assert len(seen) >= 0.6 * len(ids), (len(seen), len(ids))
    # more of the room than the eye-height overview ranked by projected boxes alone
    old = _pixels(r, scene, overview_camera(scene))
    assert len(seen) > sum(1 for i in ids if old.get(i, 0) >= MIN_PIXELS)
    assert max(px.get(i, 0) for i in ids) / (640 * 480) <= MAX_OBJECT_SHARE


@pytest.mark.parametrize("panel", [0, 1])
def test_kitchen_preview_cuts_nothing_at_the_near_plane(kitchen, panel):
    scene, r = kitchen, Renderer()
    cam = preview_cameras(scene, renderer=r)[panel]
    if panel == 0:  # the main panel is preview_camera's view
        main = preview_camera(scene, width=cam.width, height=cam.height, renderer=r)
        np.testing.assert_allclose(main.position, cam.position, rtol=0, atol=1e-9)
    for o in scene.placed:
        lo, hi = o.world_bounds(None)
        # the eye is clear of every object's box, so no box reaches the near plane
        assert np.linalg.norm(np.maximum(np.maximum(lo - cam.position, cam.position - hi), 0)) \
            >= MIN_CLEARANCE, o.id
        corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                            for z in (lo[2], hi[2])])
        uv, depth = cam.project(corners)
        assert (depth > cam.near).all() or (depth < 0).all(), o.id  # never straddling
        if cam.meta["preset"] == "cutaway":  # framed whole: nothing cut at the frame's edges
            assert ((uv >= 0) & (uv <= [cam.width, cam.height])).all(), o.id


def _wall_mounted(scene) -> set[str]:
    return {e.child.object for e in scene.pag.relations
            if e.relation == "SECURED_TO" and e.parent.object.startswith("wall")}


def _seen_in_preview(r, scene) -> tuple[set[str], list]:
    """Objects (not the room's shell) with at least MIN_PIXELS visible pixels in one panel of
    the default preview, and the panels' cameras."""
    cams = preview_cameras(scene, renderer=r)
    ids = {o.id for o in scene.placed if o.asset is not None}
    best: dict[str, int] = {}
    for cam in cams:
        for i, n in _pixels(r, scene, cam).items():
            best[i] = max(best.get(i, 0), n)
    return {i for i, n in best.items() if n >= MIN_PIXELS and i in ids}, cams


@pytest.fixture(scope="module")
def family_bedroom():
    # 48 objects, 14 of them under 15 cm: books, a clock, lamps on nightstands, toys in a box
    t = next(t for t in list_templates() if t.name == "bedroom-family-06")
    return solve(expand_template(t, 0), seed=0)


@pytest.mark.parametrize("room", ["kitchen", "family_bedroom"])
def test_preview_panels_show_most_of_the_room(room, request):
    scene, r = request.getfixturevalue(room), Renderer()
    seen, cams = _seen_in_preview(r, scene)
    ids = [o.id for o in scene.placed if o.asset is not None]
    assert len(cams) == PREVIEW_PANELS == 2
    assert all((c.width, c.height) == PREVIEW_SIZE for c in cams)
    # panels from different sides of the room, both cut-away views (nothing cut at the near
    # plane: the eye is outside the room)
    assert not np.allclose(cams[0].position, cams[1].position)
    assert cams[1].meta["preset"] == "cutaway"
    walls = _wall_mounted(scene)
    assert walls and walls <= seen, walls - seen
    # kitchen 20/26, the bedroom 42/48 (at 640x480 in one view: 18/26 and 34/48)
    floor = {"kitchen": 0.72, "family_bedroom": 0.8}[room]
    assert len(seen) >= floor * len(ids), (len(seen), len(ids))
