"""Objects IN a drawer, assets posed open, and the contract's convexity check."""

from __future__ import annotations

import numpy as np
import trimesh

from parse3d.assets import registry
from parse3d.assets.contract import _is_convex
from parse3d.pag import PAG, Room
from parse3d.solver import solve
from parse3d.solver.library import AssetLibrary


def test_drawer_floor_is_an_internal_surface_of_its_box_and_front() -> None:
    a = registry.generate("dresser", 0)
    fronts = [p.name for p in a.parts_by_label("drawer")]
    by_part = {s.part: s for s in a.internal}
    for f in fronts:
        box = a.part(f"{f}_box")
        s = by_part[f]
        assert s.surface is by_part[box.name].surface
        # the floor lies inside the box, below its walls' tops, with room above it
        lo, hi = box.bounds
        assert lo[2] < s.surface.origin[2] < hi[2] - 0.04
        assert s.clearance >= 0.04


def test_remote_in_a_closed_drawer() -> None:
    pag = PAG("drawer", Room("bedroom", ((0, 0), (3, 0), (3, 3), (0, 3)), 2.6))
    pag.add("dresser", "dresser")
    pag.relate("dresser", "ON", "floor")
    pag.add("remote", "remote_control")
    pag.relate("remote", "IN", "dresser:drawer#1")
    scene = solve(pag, seed=0, library=AssetLibrary(per_category=2))
    assert scene.ok, scene.objects["remote"].reason
    remote, dresser = scene.objects["remote"], scene.objects["dresser"]
    front = dresser.asset.parts_by_label("drawer")[1]
    # the support recorded is the part that carries the drawer's floor, its box (what the
    # remote touches), not the front the PAG names
    assert remote.support == f"dresser:{front.name}_box@top"
    assert remote.support_choice.part == f"{front.name}_box"
    assert scene.relations[1].holds, scene.relations[1].detail
    # it lies inside the drawer's box (closed), within its walls and above its floor
    box = dresser.part_mesh(dresser.asset.part(f"{front.name}_box"), settled=False)
    rb = remote.world_bounds(settled=False)
    lo, hi = box.bounds
    assert (rb[0, :2] >= lo[:2] - 1e-3).all() and (rb[1, :2] <= hi[:2] + 1e-3).all()
    assert lo[2] < rb[0, 2] < hi[2]
    # and physics agrees: settled, it stays on the support recorded
    from parse3d.physics import settle

    settle(scene)
    assert "left_support" not in remote.flags and "fell" not in remote.flags, remote.flags


def test_posed_asset_opens_doors_and_drawers() -> None:
    a = registry.generate("dresser", 0)
    opened = a.posed(ratio=1.0)
    assert a.posed() is a and a.posed(ratio=0.0) is a
    slide = next(j for j in a.joints if j.type == "prismatic" and not j.is_mount)
    box = slide.child_part
    moved = opened.part(box).bounds - a.part(box).bounds
    assert np.allclose(moved, [slide.limits[1] * np.asarray(slide.axis)] * 2, atol=1e-9)
    # the front and the pull mounted on the box come along; the body stays
    front = next(j.child_part for j in a.joints if j.is_mount and j.parent_part == box)
    assert np.allclose(opened.part(front).bounds - a.part(front).bounds, moved)
    assert opened.part("body") is a.part("body")
    assert a.part(box).bounds[1, 1] < opened.part(box).bounds[1, 1]  # the source is untouched


def test_convexity_check_matches_trimesh() -> None:
    box = trimesh.creation.box((0.3, 0.2, 0.1))
    ring = trimesh.creation.annulus(0.05, 0.1, 0.02)
    assert _is_convex(box) and box.is_convex
    assert not _is_convex(ring) and not ring.is_convex
    flipped = box.copy()
    flipped.faces = flipped.faces[:, ::-1]
    assert not _is_convex(flipped)
    open_box = trimesh.Trimesh(box.vertices, box.faces[:-1], process=False)
    assert not _is_convex(open_box)


def test_dataset_stats_report_the_largest_category_share() -> None:
    from parse3d.datagen.stats import DatasetStats

    row = {"placed": 3, "objects": 3, "density": 0.5, "contacts": 10, "room_type": "bedroom"}
    rows = [dict(row, categories=["book", "book", "mug"], assets=["book-a-0", "book-a-1", "mug-b-0"],
                 parts=[4, 4, 2]),
            dict(row, categories=["book", "bed", "lamp"], assets=["book-a-0", "bed-c-0", "lamp-d-0"],
                 parts=[4, 12, 5])]
    st = DatasetStats("tiny", {"settle": True}, {"ok": 2}, rows)
    s = st.table()["summary"]
    assert (s["largest_category"], s["largest_category_share"], s["categories"]) == ("book", 0.5, 4)
    assert s["avg_parts_per_asset"] == 5.4  # (4 + 4 + 2 + 12 + 5) / 5 distinct assets
    md = st.markdown()
    assert "| largest category (share of objects) | book (50.0%) |" in md
    # the distribution, largest first
    assert md.index("| book | 3 | 50.0% |") < md.index("| mug | 1 | 16.7% |")


def test_render_open_poses_drawers(tmp_path) -> None:
    import json

    from PIL import Image
    from typer.testing import CliRunner

    from parse3d.cli import app
    from parse3d.scene.io import write_scene

    pag = PAG("open", Room("bedroom", ((0, 0), (2.5, 0), (2.5, 2.5), (0, 2.5)), 2.5))
    pag.add("dresser", "dresser")
    pag.relate("dresser", "ON", "floor")
    scene = solve(pag, seed=0, library=AssetLibrary(per_category=1))
    assert scene.ok
    depth, cams = {}, {}
    for name, extra in (("closed", []), ("open", ["--open", "1"])):
        d = tmp_path / name
        write_scene(scene, d, glb=False)
        # the corner overview: one camera, whatever the pose of the drawers
        res = CliRunner().invoke(app, ["render", str(d), "--views", "0", "--overview", "--size",
                                       "96x72", "--json", *extra])
        assert res.exit_code == 0, res.output
        assert json.loads(res.output)["views"] == 1
        depth[name] = np.asarray(Image.open(d / "depth_0.png"), float)
        cam = json.loads((d / "views.json").read_text())["views"][0]["camera"]
        cams[name] = {k: v for k, v in cam.items() if k != "meta"}
    # the same camera sees the drawers pulled out: nearer surfaces where they stand out
    assert cams["open"] == cams["closed"]
    changed = np.abs(depth["open"] - depth["closed"]) > 20  # millimetres
    assert changed.mean() > 0.01
    assert (depth["open"][changed] < depth["closed"][changed]).mean() > 0.5
