"""Intent over letter for support relations named by a part: what the writer meant (the chair
stands on the floor, the armchair rests on it) is placed, and what could not be met as written
is recorded with what to write instead.

Real solves of hand-written rooms (tests/data/rooms/: named_support_parts, in_on_a_board,
covered_top, marker_tray, heap_of_round_things, hung_by_a_named_part) on the pool's real
assets.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from parse3d.measure import check_edge
from parse3d.measure.checks import world_points
from parse3d.pag import load_pag
from parse3d.solver import solve
from parse3d.solver.intent import overhang, whole_object

ROOMS = Path(__file__).parent / "data" / "rooms"
NAMED = ROOMS / "named_support_parts.json"


@pytest.fixture(scope="module", params=[0, 1])
def scene(request):
    return solve(load_pag(NAMED), seed=request.param)


def _check(scene, child: str):
    return next(c for c in scene.relations if c.child == child)


def test_every_object_is_placed(scene):
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]


def test_legs_on_glides_stand_on_the_floor(scene):
    """A chair's legs end in glides a few millimetres tall: the legs hold through them."""
    for cid in ("chair_1:leg@bottom", "table:leg@bottom"):
        c = _check(scene, cid)
        assert c.holds, c.detail
        assert c.relaxed is None
    c = _check(scene, "chair_1:leg@bottom")
    assert "through foot_" in c.detail, c.detail
    assert abs(c.residual["distance"]) <= 2e-3


def test_a_frame_raised_on_legs_rests_by_its_legs_and_is_recorded_relaxed(scene):
    """No armchair in the pool has its frame on the floor: it stands on its legs, the ON by
    its frame is recorded (holds false, the frame's gap, what touches instead) and the cushion
    on its seat is placed."""
    c = _check(scene, "armchair:frame@bottom")
    assert c.holds is False and c.relaxed is not None
    assert "armchair:leg touches it" in c.relaxed["blocked"]
    assert c.relaxed["instead"] == "name armchair:leg@bottom or armchair@bottom"
    assert 0.03 < c.residual["distance"] < 0.3
    arm = scene.objects["armchair"]
    e = scene.pag.relations[c.index]
    assert check_edge(scene, whole_object(e), arm)[0]  # the whole armchair is on the floor
    # the least overhung instance of the pool was drawn
    from parse3d.solver.library import default_library

    lib = default_library()
    best = min(overhang(lib.load("armchair", k), e)[0] for k in range(lib.per_category))
    assert overhang(arm.asset, e)[0] == pytest.approx(best, rel=1e-6)
    assert _check(scene, "cushion").holds


def test_what_rests_on_a_relaxed_support_is_placed(scene):
    c = _check(scene, "nightstand:body@bottom")
    if c.holds is False:
        assert c.relaxed["instead"].startswith("name nightstand:")
    assert _check(scene, "lamp:base@bottom").holds


def test_a_felt_inlay_holds_what_stands_on_the_tabletop(scene):
    """A card table's tabletop is covered by a felt 3 mm thick: the chess board stands on it,
    and ON ...tabletop@top holds (the step onto a layer of the parent)."""
    assert _check(scene, "chess:board@bottom").holds


def test_a_stack_on_a_lid_draws_an_instance_with_a_lid(scene):
    """Most board games of the pool are card decks without a lid: every slot is looked at."""
    assert scene.objects["game_1"].asset.parts_by_label("lid")
    assert _check(scene, "game_2:box@bottom").holds


@pytest.mark.parametrize("seed", [0, 1])
def test_in_a_board_that_holds_nothing_inside_means_on_its_top(seed):
    """No wall shelf of the pool has an internal surface on its board: records IN it stand on
    its top, and IN holds (on top of the board, said so in the detail)."""
    scene = solve(load_pag(ROOMS / "in_on_a_board.json"), seed=seed)
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]
    shelf = scene.objects["shelf"]
    for rid in ("rec1", "rec2"):
        c = _check(scene, f"{rid}:sleeve@bottom")
        assert c.relation == "IN" and c.holds, c.detail
        assert "on top of the shelf" in c.detail
        rec = scene.objects[rid]
        assert rec.support_choice.owner == "shelf"
        assert shelf.asset.part(rec.support_choice.part).label == "shelf"


@pytest.mark.parametrize("seed", [0, 1])
def test_a_round_thing_on_one_of_its_kind_rests_beside_it(seed):
    """Nothing stacks on an apple or a tomato: the one below is placed all the same (no
    instance is a flat base), the one written ON it rests on the same support touching it (a
    heap), and the ON is recorded relaxed saying so and what to write instead."""
    from parse3d.measure import summarize_settled
    from parse3d.pipeline import settle_and_repair

    scene = solve(load_pag(ROOMS / "heap_of_round_things.json"), seed=seed)
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]
    for child, below, under in (("apple3", "apple1", "crate"), ("tomato2", "tomato1", "table")):
        c = _check(scene, child)
        assert c.relaxed is not None, c.detail
        assert f"{below} (" in c.relaxed["blocked"] and "is round" in c.relaxed["blocked"]
        assert c.relaxed["instead"].startswith(f"write {'IN' if under == 'crate' else 'ON'} "
                                               f"{child} -> {under}")
        o = scene.objects[child]
        assert o.support_choice.owner == under
        gap = np.linalg.norm(o.position[:2] - scene.objects[below].position[:2])
        assert gap < 0.2  # beside it, within the NEAR the heap adds
    settle_and_repair(scene)
    s = summarize_settled(scene)
    assert s.complete and s.unstable == 0


@pytest.mark.parametrize("seed", [0, 1])
def test_on_a_part_under_a_covering_part_stands_on_the_cover(seed):
    """Every dryer of the pool has its control panel over the whole top of its body: a basket
    ON dryer:body@top stands on the panel, recorded as the part it touches, and holds."""
    scene = solve(load_pag(ROOMS / "covered_top.json"), seed=seed)
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]
    basket, dryer = scene.objects["basket"], scene.objects["dryer"]
    assert basket.support_choice.owner == "dryer"
    assert dryer.asset.part(basket.support_choice.part).label == "control_panel"
    c = _check(scene, "basket:body@bottom")
    assert c.holds, c.detail
    assert abs(c.residual["distance"]) <= 2e-3


@pytest.mark.parametrize("seed", [0, 1])
def test_on_a_channel_lies_on_its_floor_between_its_lips(seed):
    """A whiteboard's tray is a channel whose top surface is its 6 mm front lip: markers ON
    it lie on the channel's floor, below the lip, and ON holds there."""
    scene = solve(load_pag(ROOMS / "marker_tray.json"), seed=seed)
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]
    board = scene.objects["whiteboard"]
    lip = float(world_points(board, parts=board.asset.parts_by_label("tray"))[:, 2].max())
    for mid in ("marker_1", "marker_2"):
        c = _check(scene, mid)
        assert c.holds, c.detail
        assert float(world_points(scene.objects[mid])[:, 2].min()) < lip - 5e-3


def test_a_centre_of_mass_past_the_base_edge_is_no_stand():
    """A gooseneck faucet whose spout puts its centre of mass 1 mm beyond its base's edge
    tips in settling: ON by its base does not hold (the 2 mm tolerance is for round things,
    which rest on a point)."""
    from parse3d.assets import registry
    from parse3d.measure.geometry import asset_geometry
    from parse3d.pag import PAG, Room
    from parse3d.scene.model import PlacedObject, Scene
    from parse3d.scene.shell import build_shell

    room = Room("bathroom", ((0, 0), (3, 0), (3, 3), (0, 3)), 2.6)
    pag = PAG("faucet", room)
    pag.add("faucet", "faucet")
    pag.relate("faucet:base@bottom", "ON", "floor")
    scene = Scene(pag, 0, build_shell(room))
    asset = registry.generate("faucet", seed=16)
    assert asset.asset_id == "faucet-gooseneck-16"
    base = world_points(PlacedObject("x", "faucet", asset, 1.0, np.eye(3), np.zeros(3)),
                        parts=asset.parts_by_label("base"))
    assert asset_geometry(asset).com[1] > base[:, 1].max()  # past the base's back edge
    o = PlacedObject("faucet", "faucet", asset, 1.0, np.eye(3), np.array([1.5, 1.5, 5e-4]))
    scene.objects["faucet"] = o
    holds, _, detail = check_edge(scene, pag.relations[0], o)
    assert not holds and "tip over" in detail


@pytest.mark.parametrize("seed", [0, 1])
def test_a_coat_hung_by_its_collar_hangs_by_its_loop(seed):
    """A coat hung by its collar from a wall hook is drawn without a hanger (the coats on one
    have its hook above the collar): it hangs by the loop in its collar, the HANGING_BELOW
    held as written."""
    scene = solve(load_pag(ROOMS / "hung_by_a_named_part.json"), seed=seed)
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]
    c = _check(scene, "coat:collar@top")
    assert c.holds is True and c.relaxed is None, (c.residual, c.relaxed)
    asset = scene.objects["coat"].asset
    assert asset.parts_by_label("loop") and not asset.parts_by_label("hook"), asset.asset_id


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_notebooks_written_on_their_cover_lie_on_it(seed):
    """Notebooks and magazines are modelled standing; written ``ON pad:back_cover@bottom``
    they lie on the back cover (recorded as resting on its outer face), and a pen ON the
    front cover's top rests on the cover's face that is up, not on its 1 cm edge. Every
    relation holds after settling."""
    from test_rooms import solved

    scene = solved("notebooks_lie_on_covers", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    for oid in ("pad1", "pad2", "mag1", "mag2"):
        o = scene.objects[oid]
        assert o.rests_on == "back", (oid, o.rests_on)
        # lying: the asset's thin y axis is vertical
        T = o.transform(True)
        assert abs(T[2, 1]) > 0.95, (oid, T[:3, 1])
    for pen, pad in (("pen1", "pad1"), ("pen2", "pad2")):
        assert scene.objects[pen].position[2] > scene.objects[pad].position[2]


@pytest.mark.parametrize("seed", (0, 1, 2))
def test_books_written_on_one_another_lie_in_a_stack(seed):
    """Books written ON one another with no part named lie on their back covers, each on the
    one below, and glasses ON the top one rest on it; books ON a bookcase's shelf with no
    stack stand as modelled. Every relation holds after settling."""
    from test_rooms import solved

    scene = solved("books_stacked_on_a_table", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    broken = [(c.relation, c.child, c.parent) for c in scene.relations
              if c.holds_settled is not True]
    assert not broken, broken
    z = []
    for oid in ("book1", "book2", "book3"):
        o = scene.objects[oid]
        assert o.rests_on == "back", (oid, o.rests_on)
        T = o.transform(True)
        assert abs(T[2, 1]) > 0.95, (oid, T[:3, 1])  # lying: its thin axis vertical
        z.append(float(o.world_bounds()[1, 2]))
    assert z == sorted(z)
    assert scene.objects["glasses"].position[2] > z[-1] - 0.01
    for oid in ("book4", "book5"):
        o = scene.objects[oid]
        assert o.rests_on is None and abs(o.transform(True)[2, 2]) > 0.95, oid  # standing


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_flat_lidded_thing_round_in_outline_carries_one_of_its_kind(seed):
    """A paint can is about as wide as it is tall, but its lid is flat (its bail handle folded
    down): the can written ON it stands on the lid, as written, and stays there after
    settling; boxes likewise (tests/data/rooms/paint_cans_stacked.json)."""
    from parse3d.pipeline import PipelineOptions, run_pipeline

    scene = run_pipeline(load_pag(ROOMS / "paint_cans_stacked.json"), seed=seed, out=None,
                         options=PipelineOptions(settle=True, preview=False))
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for child, below in (("can_b", "can_a"), ("can_d", "can_c"), ("box_b", "box_a")):
        c = next(c for c in scene.relations if c.child.split(":")[0] == child)
        assert c.relaxed is None, c.relaxed
        assert c.holds_settled is True, (c.detail, c.residual_settled)
        assert scene.objects[child].support_choice.owner == below


def test_a_like_thing_that_finds_no_room_on_the_one_below_rests_beside_it():
    """Folded clothes written ON the folded clothes below, in a basket on a washer, where the
    upper one is larger than the lower one's top (a room written by outsiders,
    tests/data/foreign-later/laundry-nook.json, seed 1): it is not left out but rests beside
    the one below in the basket, the ON recorded relaxed saying why."""
    from parse3d.pag import PAG
    from parse3d.pipeline import PipelineOptions, run_pipeline

    path = ROOMS.parent / "foreign-later" / "laundry-nook.json"
    scene = run_pipeline(PAG.from_dict(json.loads(path.read_text())), seed=1,
                         out=None, options=PipelineOptions(settle=False, preview=False))
    assert scene.objects["folded3"].placed, scene.objects["folded3"].reason
    c = next(c for c in scene.relations if c.child.split(":")[0] == "folded3")
    if c.holds is not True:
        assert c.relaxed is not None and "rests beside folded2" in c.relaxed["blocked"]
        assert scene.objects["folded3"].support_choice.owner == "basket"
