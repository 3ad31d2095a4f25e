"""Categories for the objects people write in kitchens, dining rooms, bathrooms, bars and shops:
cutlery, vegetables, kitchen tools, sideboards and display tables, bathroom items, irons and
mops, bar mats, beer taps and cash registers.

Beyond the shared contract: each lies or stands as the real thing does, offers the supports a
PAG names (a pot rail's hooks to hang from, a sideboard's shelves behind its doors, a stand
mixer's bowl, a bar mat's sheet) and moves where the real thing moves; and a few small rooms
using them solve.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.assets.contract import check_asset
from parse3d.assets.model import Asset
from parse3d.pag import PAG, Room
from parse3d.solver import solve

CATEGORIES = ("knife", "fork", "spoon", "tomato", "onion", "carrot", "potato", "knife_block",
              "cutting_board", "stand_mixer", "thermos", "pot_rail", "sideboard", "display_table",
              "table_runner", "flowers", "toothbrush", "toilet_brush", "mirror_cabinet", "iron", "mop",
              "bar_mat", "beer_tap", "cash_register", "hutch", "locker", "bar_table", "jukebox",
              "sign_stand", "high_chair", "shower", "tea_whisk", "tea_scoop", "wagashi", "brazier",
              "incense_burner", "toiletry_bag", "deodorant", "hanging_scale")
WALL = ("pot_rail", "mirror_cabinet")
CEILING = ("hanging_scale",)
FLOOR = ("sideboard", "display_table", "toilet_brush", "mop", "hutch", "locker", "bar_table", "jukebox",
         "sign_stand", "high_chair", "shower", "brazier")
ROOM = ((0, 0), (4, 0), (4, 3.5), (0, 3.5))


@functools.cache
def _asset(category: str, variant: str | None = None, seed: int = 1) -> Asset:
    return registry.generate(category, seed, variant)


def _bounds(a: Asset, label: str) -> np.ndarray:
    b = np.array([p.bounds for p in a.parts_by_label(label)])
    return np.array([b[:, 0].min(axis=0), b[:, 1].max(axis=0)])


def _cases():
    return [pytest.param(c, v, id=f"{c}-{v}") for c in CATEGORIES for v in registry.get(c).variants]


def test_registered_with_variants_and_placement():
    cats = registry.categories()
    for c in CATEGORIES:
        assert len(cats[c].variants) >= 2, c
        want = ("wall" if c in WALL else "ceiling" if c in CEILING else
                "floor" if c in FLOOR else "surface")
        assert cats[c].placement == want, c


@pytest.mark.parametrize(("category", "variant"), _cases())
def test_every_variant_honours_the_contract(category, variant):
    a = _asset(category, variant, seed=2)
    assert check_asset(a) == [], a.asset_id
    assert a.meta["variant"] == variant


@pytest.mark.parametrize("category", ["knife", "fork", "spoon", "toothbrush"])
def test_cutlery_lies_flat_with_the_working_end_at_plus_x(category):
    for v in registry.get(category).variants:
        a = _asset(category, v)
        ext = a.bounds[1] - a.bounds[0]
        assert ext[2] < 0.035 and ext[0] > 3 * ext[1], a.asset_id
        end = {"knife": "blade", "fork": "tine", "spoon": "bowl", "toothbrush": "bristles"}[category]
        assert _bounds(a, end).mean(axis=0)[0] > _bounds(a, "handle").mean(axis=0)[0], a.asset_id


def test_a_forks_tines_and_handle_end_touch_the_table():
    a = _asset("fork", "dinner")
    for p in [*a.parts_by_label("tine"), a.part("handle")]:
        assert p.bounds[0, 2] < 1e-3, p.name


def test_pot_rail_hooks_hang_below_the_rail_in_front_of_the_wall():
    for v in registry.get("pot_rail").variants:
        a = _asset("pot_rail", v)
        rail = _bounds(a, "rail")
        hooks = a.parts_by_label("hook")
        assert len(hooks) >= 3, a.asset_id
        for h in hooks:
            # the curl reaches over the rail and the open bottom hangs well below it
            assert h.bounds[1, 2] >= rail[1, 2] - 1e-3 and h.bounds[0, 2] < rail[0, 2] - 0.05, h.name
            assert h.surfaces["bottom"].normal[2] < -0.99
        # brackets reach the wall at the back (-Y)
        assert abs(_bounds(a, "bracket")[0, 1] - a.bounds[0, 1]) < 1e-3
        # "the bar" is the rail with its hooks, so a pan hangs below the bar from a hook
        assert {p.label for p in a.parts_by_label("bar")} == {"rail", "hook"}


def test_a_pan_hangs_below_the_pot_rails_bar_by_its_handle():
    """As rooms write it: the pan's handle 2-10 cm below the bar (the S-hook's length)."""
    pag = PAG("pot-rail", Room("kitchen", ROOM, 2.7))
    pag.add("rail", "pot_rail")
    pag.relate("rail:bracket@back", "SECURED_TO", "wall", height=[1.3, 1.45])
    pag.add("pan", "frying_pan")
    pag.relate("pan:handle@top", "HANGING_BELOW", "rail:bar@bottom", drop=[0.02, 0.1])
    scene = solve(pag, seed=1)
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]
    assert scene.objects["pan"].support_choice.part.startswith("hook")


@pytest.mark.parametrize(("category", "label"), [("sideboard", "shelf"), ("mirror_cabinet", "shelf"),
                                                 ("stand_mixer", "bowl"), ("hutch", "shelf"),
                                                 ("hanging_scale", "pan")])
def test_supports_inside(category, label):
    """Shelves behind doors or between side panels, a mixer's bowl and a scale's pan are
    internal supports."""
    for v in registry.get(category).variants:
        a = _asset(category, v)
        inside = {s.part for s in a.internal}
        for p in a.parts_by_label(label):
            assert p.name in inside, f"{a.asset_id}: {p.name} is not an internal surface"


def test_sideboard_doors_swing_out_and_drawers_slide_out():
    a = _asset("sideboard", "drawers_over_doors")
    kinds = {j.type for j in a.joints if j.limits != (0.0, 0.0)}
    assert kinds == {"revolute", "prismatic"}
    opened = a.posed(ratio=1.0)
    for p in a.parts_by_label("drawer"):
        assert opened.part(p.name).bounds[1, 1] > p.bounds[1, 1] + 0.2
    top = a.part("top_panel")
    assert top.bounds[1, 2] == pytest.approx(a.bounds[1, 2], rel=1e-6)
    # nothing reaches behind the body, so sideboard:body@back AGAINST a wall holds
    for v in registry.get("sideboard").variants:
        b = _asset("sideboard", v)
        # (body names the carcass's panels: what the solver puts against the wall)
        assert b.bounds[0, 1] == pytest.approx(min(p.bounds[0, 1] for p in b.parts_by_label("body")), abs=1e-6)
    for v in registry.get("hutch").variants:
        h = _asset("hutch", v)
        assert h.bounds[0, 1] == pytest.approx(h.part("back_panel").bounds[0, 1], abs=1e-6)
    assert top.surfaces["top"].area > 0.4


def test_mirror_cabinet_mirrors_go_with_their_doors():
    a = _asset("mirror_cabinet", "double")
    opened = a.posed(ratio=1.0)
    for door in a.parts_by_label("door"):
        mirror = a.part(f"{door.name}_mirror")
        moved = opened.part(mirror.name).bounds
        assert not np.allclose(moved, mirror.bounds)
        assert moved[1, 1] > mirror.bounds[1, 1] + 0.1


def test_stand_mixer_head_tilts_back_with_the_beater():
    a = _asset("stand_mixer", "tilt_head")
    opened = a.posed(ratio=1.0)
    for name in ("head", "beater"):
        assert opened.part(name).bounds[1, 2] > a.part(name).bounds[1, 2] + 0.05, name
    # the bowl stays put
    assert np.allclose(opened.part("bowl").bounds, a.part("bowl").bounds)


def test_cash_drawer_slides_towards_the_cashier():
    for v in registry.get("cash_register").variants:
        a = _asset("cash_register", v)
        opened = a.posed(ratio=1.0)
        assert opened.part("cash_drawer").bounds[1, 1] > a.part("cash_drawer").bounds[1, 1] + 0.15


def test_beer_tap_handles_pull_forward_over_the_drip_tray():
    a = _asset("beer_tap", "t_bar")
    opened = a.posed(ratio=1.0)
    tray = _bounds(a, "drip_tray")
    for h in a.parts_by_label("tap_handle"):
        assert opened.part(h.name).bounds[1, 1] > h.bounds[1, 1] + 0.03
    for f in a.parts_by_label("faucet"):
        x, y = (f.bounds[0, :2] + f.bounds[1, :2]) / 2
        assert tray[0, 0] < x < tray[1, 0] and f.bounds[1, 1] > tray[0, 1]


@pytest.mark.parametrize(("category", "variants"), [("locker", None), ("jukebox", None), ("hutch", None),
                                                    ("sideboard", ("drawers_over_doors", "three_door"))])
def test_the_body_stands_on_the_floor(category, variants):
    """Rooms write ``locker:body@bottom ON floor``: the body includes its base or plinth."""
    for v in variants or registry.get(category).variants:
        a = _asset(category, v)
        assert a.part("body").bounds[0, 2] == pytest.approx(0.0, abs=1e-6), a.asset_id


def test_a_table_runners_body_is_the_whole_runner():
    a = _asset("table_runner", "bordered")
    assert {p.label for p in a.parts_by_label("body")} == {"runner", "hem", "border"}


def test_bar_mat_rim_stands_above_the_sheet_glasses_rest_on():
    a = _asset("bar_mat", "service")
    mat, rim = a.part("mat"), _bounds(a, "rim")
    assert rim[1, 2] > mat.bounds[1, 2] + 0.002
    for c in a.parts_by_label("channel"):
        assert c.bounds[1, 2] < mat.bounds[1, 2]


def test_toilet_brush_stands_in_its_holder():
    for v in registry.get("toilet_brush").variants:
        a = _asset("toilet_brush", v)
        holder, head = _bounds(a, "holder"), a.part("brush_head").bounds
        assert (head[0, :2] >= holder[0, :2]).all() and (head[1, :2] <= holder[1, :2]).all()
        assert head[1, 2] < holder[1, 2]
        assert a.part("handle").bounds[1, 2] > holder[1, 2] + 0.1


def test_hutch_plates_lean_on_the_back_panel_behind_a_plate_rail():
    a = _asset("hutch", "open")
    back = a.part("back_panel")
    upper = [p for p in a.parts_by_label("shelf") if p.bounds[0, 2] > a.part("countertop").bounds[1, 2]]
    rails = a.parts_by_label("plate_rail")
    assert len(upper) >= 2 and len(rails) == len(upper)
    for shelf, rail in zip(upper, rails, strict=True):
        assert shelf.bounds[0, 1] == pytest.approx(back.bounds[1, 1], abs=1e-3)
        assert rail.bounds[0, 2] == pytest.approx(shelf.bounds[1, 2], abs=1e-3)
        assert 0.04 < rail.bounds[0, 1] - back.bounds[1, 1] < 0.1  # a plate's foot fits behind it


def test_high_chair_tray_is_at_table_height_in_front_of_the_seat():
    for v in registry.get("high_chair").variants:
        a = _asset("high_chair", v)
        tray, seat = a.part("tray"), a.part("seat")
        assert 0.7 < tray.bounds[1, 2] < 0.9 and tray.bounds[1, 1] > seat.bounds[1, 1] + 0.1
        assert tray.surfaces["top"].area > 0.08


def test_shower_door_moves_and_the_niche_holds_bottles():
    for v, kind in (("corner_slider", "prismatic"), ("hinged", "revolute")):
        a = _asset("shower", v)
        assert [j.type for j in a.joints if j.child_part == "door"] == [kind]
        opened = a.posed(ratio=1.0)
        assert not np.allclose(opened.part("door").bounds, a.part("door").bounds)
        niche = a.part("niche")
        assert 1.0 < niche.bounds[0, 2] < 1.4
    assert not _asset("shower", "walk_in").joints


def test_brazier_trivet_is_over_the_opening_and_the_scale_hook_is_on_top():
    for v in registry.get("brazier").variants:
        a = _asset("brazier", v)
        assert a.part("trivet").bounds[1, 2] == pytest.approx(a.bounds[1, 2], abs=0.03)
        assert a.part("trivet").surfaces["top"].area > 0.02
    for v in registry.get("hanging_scale").variants:
        a = _asset("hanging_scale", v)
        assert a.part("hook").bounds[1, 2] == pytest.approx(a.bounds[1, 2], abs=1e-6)
        assert a.part("pan").bounds[0, 2] == pytest.approx(0.0, abs=1e-6)


def _kitchen() -> PAG:
    pag = PAG("kitchen-tools", Room("kitchen", ROOM, 2.7))
    pag.add("counter", "kitchen_counter")
    pag.relate("counter", "ON", "floor")
    pag.relate("counter@back", "AGAINST", "wall")
    pag.add("board", "cutting_board")
    pag.relate("board", "ON", "counter:countertop")
    pag.add("knife", "knife")
    pag.relate("knife", "ON", "board:board")
    pag.add("tomato", "tomato")
    pag.relate("tomato", "ON", "board:board")
    pag.add("mixer", "stand_mixer")
    pag.relate("mixer", "ON", "counter:countertop")
    pag.add("rail", "pot_rail")
    pag.relate("rail:bracket@back", "SECURED_TO", "wall", height=[1.4, 1.6])
    pag.add("pan", "frying_pan")
    pag.relate("pan", "HANGING_BELOW", "rail:hook")
    return pag


def _dining() -> PAG:
    pag = PAG("dining-sideboard", Room("dining_room", ROOM, 2.7))
    pag.add("sb", "sideboard")
    pag.relate("sb", "ON", "floor")
    pag.relate("sb@back", "AGAINST", "wall")
    pag.add("runner", "table_runner")
    pag.relate("runner", "ON", "sb:top_panel")
    pag.add("thermos", "thermos")
    pag.relate("thermos", "ON", "runner:runner")
    pag.add("cup", "cup")
    pag.relate("cup", "IN", "sb:shelf")
    pag.add("mc", "mirror_cabinet")
    pag.relate("mc@back", "SECURED_TO", "wall", height=[1.5, 1.8])
    pag.add("brush", "toothbrush")
    pag.relate("brush", "IN", "mc:shelf")
    return pag


def _bar() -> PAG:
    pag = PAG("bar-top", Room("bar", ROOM, 2.7))
    pag.add("bar", "bar_counter")
    pag.relate("bar", "ON", "floor")
    pag.add("mat", "bar_mat")
    pag.relate("mat", "ON", "bar:countertop")
    pag.add("glass", "wine_glass")
    pag.relate("glass", "ON", "mat:mat")
    pag.add("tap", "beer_tap")
    pag.relate("tap", "ON", "bar:countertop")
    pag.add("till", "cash_register")
    pag.relate("till", "ON", "bar:countertop")
    pag.add("table", "display_table")
    pag.relate("table", "ON", "floor")
    pag.add("potato", "potato")
    pag.relate("potato", "ON", "table:tabletop")
    pag.add("iron", "iron")
    pag.relate("iron", "ON", "table:tabletop")
    return pag


def _nook() -> PAG:
    pag = PAG("breakfast-nook", Room("dining_room", ROOM, 2.7))
    pag.add("hutch", "hutch")
    pag.relate("hutch", "ON", "floor")
    pag.relate("hutch:back_panel@back", "AGAINST", "wall")
    pag.add("bowl", "bowl")
    pag.relate("bowl", "ON", "hutch:countertop")
    pag.add("chair", "high_chair")
    pag.relate("chair", "ON", "floor")
    pag.add("cup", "cup")
    pag.relate("cup", "ON", "chair:tray")
    pag.add("brazier", "brazier")
    pag.relate("brazier", "ON", "floor")
    pag.add("kettle", "kettle")
    pag.relate("kettle", "ON", "brazier:trivet")
    pag.add("scale", "hanging_scale")
    pag.relate("scale:hook", "HANGING_BELOW", "ceiling", drop=[0.6, 0.9])
    pag.add("apple", "apple")
    pag.relate("apple", "IN", "scale:pan")
    return pag


def _bathroom() -> PAG:
    pag = PAG("shower-corner", Room("bathroom", ROOM, 2.7))
    pag.add("shower", "shower")
    pag.relate("shower", "ON", "floor")
    pag.relate("shower@back", "AGAINST", "wall")
    pag.add("shampoo", "detergent_bottle")
    pag.relate("shampoo", "ON", "shower:niche")
    pag.add("locker", "locker")
    pag.relate("locker", "ON", "floor")
    pag.relate("locker@back", "AGAINST", "wall")
    pag.add("bag", "toiletry_bag")
    pag.relate("bag", "IN", "locker:shelf")
    pag.add("brush", "toilet_brush")
    pag.relate("brush", "ON", "floor")
    return pag


@pytest.mark.parametrize("room", [_kitchen, _dining, _bar, _nook, _bathroom],
                         ids=["kitchen", "dining", "bar", "nook", "bathroom"])
@pytest.mark.parametrize("seed", [0, 1])
def test_rooms_using_them_solve(room, seed):
    scene = solve(room(), seed=seed)
    assert scene.ok, [(o.id, o.reason) for o in scene.failed]
    support = {"ON", "IN", "HANGING_BELOW", "SECURED_TO"}
    held = [c for c in scene.relations if c.relation in support]
    assert held and all(c.holds for c in held), [c for c in held if not c.holds]


#: The motifs that put these categories in the bundled templates, each alone in a small room
#: (with the motif holding the counter it uses): room type, its params, a motif it builds on.
MOTIFS = {
    "kitchen_prep_corner": ("kitchen", "{wall: wall_0}", ""),
    "dining_room_dressed_sideboard": ("dining_room", "{wall: wall_0}", ""),
    "dining_room_hutch_nook": ("dining_room", "{wall: wall_0}", ""),
    "bathroom_shower_cabinet": ("bathroom", "{wall: wall_0}", ""),
    "bar_counter_taps": ("bar", "{counter: bc_counter, wall: wall_1}",
                         "{motif: bar_counter_set, prefix: bc, params: {away: wall_0, distance: 1.0}}"),
    "grocery_produce_display": ("grocery", "{counter: ck_counter, wall: wall_1}",
                                "{motif: grocery_checkout, prefix: ck, params: {wall: wall_0}}"),
    "laundry_iron_and_mop": ("laundry", "{wall: wall_0}", ""),
    "dormitory_lockers": ("dormitory", "{wall: wall_0}", ""),
    "tea_house_brazier": ("tea_house", "{wall: wall_0}", ""),
}


@pytest.mark.parametrize("motif", sorted(MOTIFS))
def test_motifs_using_them_solve(tmp_path, motif):
    from parse3d.datagen.templates import expand_template, load_template

    room_type, params, base = MOTIFS[motif]
    p = tmp_path / f"only-{motif.replace('_', '-')}.yaml"
    p.write_text("format: pag-template/1\n"
                 f"name: only-{motif.replace('_', '-')}\n"
                 f"room_type: {room_type}\n"
                 f'description: "A test room holding one {motif} motif."\n'
                 "room: {width: [4.6, 4.6], depth: [4.2, 4.2], height: [2.7, 2.7]}\n"
                 "objects: []\nrelations: []\nmotifs:\n"
                 + (f"  - {base}\n" if base else "")
                 + f"  - {{motif: {motif}, prefix: m, params: {params}}}\n")
    template = load_template(p)
    for seed in (0, 1):
        pag = expand_template(template, seed)
        scene = solve(pag, seed=seed)
        failed = {o.id: o.reason for o in scene.objects.values() if not o.placed}
        assert not failed, f"{motif} at seed {seed}: {failed}"
