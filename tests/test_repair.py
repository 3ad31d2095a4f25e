"""Settle, verify, repair: objects that fall after settling are re-placed; what stays unstable
fails (with what rests on it), and the scene is then not ok."""

from __future__ import annotations

import json

import numpy as np
import pytest

from parse3d.pag import PAG, Room
from parse3d.pipeline import settle_and_repair, unstable_objects
from parse3d.scene.io import read_scene, scene_schema, write_scene
from parse3d.solver import solve


def table_setting() -> PAG:
    pag = PAG("table-setting", Room("dining_room", ((0, 0), (3.5, 0), (3.5, 3), (0, 3)), 2.7))
    pag.add("table", "coffee_table")
    pag.relate("table", "ON", "floor")
    pag.add("bowl", "bowl")
    pag.relate("bowl", "ON", "table:tabletop")
    pag.add("apple", "apple")
    pag.relate("apple", "IN", "bowl")
    pag.add("mug", "mug")
    pag.relate("mug", "ON", "table:tabletop")
    return pag


def _push_off(scene, oid: str) -> None:
    """Move an object (and what rests on it) past the table's edge, 2 cm up: it will fall to
    the floor."""
    from parse3d.solver.search import support_descendants

    table = scene.objects["table"].world_bounds()
    shift = np.array([table[1, 0] - scene.objects[oid].world_bounds()[0, 0] + 0.05, 0, 0.02])
    for o in [oid, *support_descendants(scene.pag, oid)]:
        scene.objects[o].position = scene.objects[o].position + shift


@pytest.fixture(scope="module")
def solved():
    scene = solve(table_setting(), seed=2)
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]
    return scene


def test_fallen_object_is_repaired(solved, tmp_path):
    import copy

    scene = copy.deepcopy(solved)
    _push_off(scene, "mug")
    stats = settle_and_repair(scene, rounds=3)
    mug = scene.objects["mug"]
    assert mug.placed and mug.repairs, mug
    assert mug.repairs[0].round == 1 and mug.repairs[0].cause == "fell"
    assert mug.repairs[0].action in ("pose", "asset")
    assert stats["repaired"] >= 1 and stats["unrepaired"] == 0
    assert "mug" not in unstable_objects(scene)
    # the repaired mug rests on the table again after settling
    assert abs(mug.settled_position[2] - mug.position[2]) < 0.01
    write_scene(scene, tmp_path, glb=False)
    doc = json.loads((tmp_path / "scene.json").read_text())
    import jsonschema

    jsonschema.validate(doc, scene_schema())
    entry = next(o for o in doc["objects"] if o["id"] == "mug")
    assert entry["repairs"][0]["cause"] == "fell"
    assert entry["support"]["owner"] == "table"
    back = read_scene(tmp_path)
    assert back.objects["mug"].repairs == mug.repairs
    assert back.objects["mug"].support_choice == mug.support_choice


def test_unrepaired_object_fails_with_what_it_supports(solved):
    import copy

    scene = copy.deepcopy(solved)
    _push_off(scene, "bowl")
    stats = settle_and_repair(scene, rounds=0)
    assert stats["unrepaired"] >= 1
    bowl, apple = scene.objects["bowl"], scene.objects["apple"]
    assert bowl.status == "failed" and bowl.reason.startswith("unstable after 0 repairs")
    assert apple.status == "failed" and "'bowl'" in apple.reason
    assert not scene.ok
    assert scene.objects["mug"].placed


def test_scene_1_files_are_still_read(solved, tmp_path):
    write_scene(solved, tmp_path, glb=False)
    doc = json.loads((tmp_path / "scene.json").read_text())
    doc["format"] = "parse3d-scene/1"
    for o in doc["objects"]:
        s = o.get("support")
        if s:
            o["support"] = s["part"] if s["owner"] == "room" else \
                f"{s['owner']}:{s['part']}@{s['surface']}"
    (tmp_path / "scene.json").write_text(json.dumps(doc))
    back = read_scene(tmp_path)
    for oid, o in solved.objects.items():
        assert back.objects[oid].support_choice == o.support_choice


def test_unmet_relations_stay_unmet_after_settling():
    from parse3d.pipeline import PipelineOptions, run_pipeline

    pag = PAG("unmet", Room("living_room", ((0, 0), (4, 0), (4, 3.5), (0, 3.5)), 2.7))
    pag.add("sofa", "sofa")
    pag.relate("sofa", "ON", "floor")
    pag.relate("sofa", "FAR_FROM", "wall_0", distance=9.0)
    pag.add("chair", "armchair")
    pag.relate("chair", "ON", "floor")
    pag.relate("chair", "NEAR", "sofa", distance=1.5)
    from parse3d.solver import SolverConfig

    # every relation hard, so the sofa fails
    scene = run_pipeline(pag, seed=0, out=None,
                         options=PipelineOptions(preview=False,
                                                 solver=SolverConfig(relax=False)))
    assert not scene.ok and scene.objects["chair"].placed and scene.settled
    near = next(c for c in scene.relations if c.relation == "NEAR")
    assert (near.holds, near.holds_settled) == (None, None)
    assert near.detail == "unmet: parent 'sofa' failed"
    # relaxed instead: the sofa is placed, its FAR_FROM recorded relaxed after settling too
    scene = run_pipeline(pag, seed=0, out=None, options=PipelineOptions(preview=False))
    assert scene.ok and scene.settled
    far = next(c for c in scene.relations if c.relation == "FAR_FROM")
    assert far.holds is False and far.holds_settled is False and far.relaxed
    on = next(c for c in scene.relations if c.relation == "ON" and c.child == "chair")
    assert on.holds and on.holds_settled


def test_settling_the_same_poses_again_gives_the_same_scene(solved):
    """What lets a repair round that could place nothing anew skip settling again."""
    import copy

    from parse3d.pipeline import _settle

    scene = copy.deepcopy(solved)
    _push_off(scene, "mug")  # something moves while settling
    _settle(scene)
    first = {k: (o.settled_rotation.tobytes(), o.settled_position.tobytes(), list(o.flags))
             for k, o in scene.objects.items() if o.placed}
    rel = [(c.index, c.holds_settled, c.residual_settled) for c in scene.relations]
    meta = copy.deepcopy(scene.meta["settle"])
    _settle(scene)
    assert {k: (o.settled_rotation.tobytes(), o.settled_position.tobytes(), list(o.flags))
            for k, o in scene.objects.items() if o.placed} == first
    assert [(c.index, c.holds_settled, c.residual_settled) for c in scene.relations] == rel
    assert scene.meta["settle"] == meta and "mug" in meta["fell"]


def test_repairs_stop_at_their_time_budget(solved):
    """With the budget spent (0 s) no repair round starts: the fallen mug is not re-placed, it
    fails as unstable, and the scene says the budget stopped the repairs."""
    import copy

    scene = copy.deepcopy(solved)
    _push_off(scene, "mug")
    stats = settle_and_repair(scene, rounds=3, budget=0.0)
    mug = scene.objects["mug"]
    assert not mug.placed and not mug.repairs and "unstable" in mug.reason, mug.reason
    assert stats == {"repaired": 0, "unrepaired": 1}
    assert scene.meta["repair"]["budget"] is True
