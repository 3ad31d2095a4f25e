"""The categories written for rooms described by people who never saw the asset list: music
gear, the games room, hand tools, stationery, blankets and bicycles.

Beyond the contract (``tests/test_asset_contract.py``): the supports people put things on or
in (a toolbox's tray, a piano bench's compartment, a cue rack's cups), the joints the real
things have, the part names the outsiders' rooms use, and two small rooms solved with them.
"""

from __future__ import annotations

from functools import cache

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.pag import PAG, Room
from parse3d.solver import solve

NEW = ["record_player", "vinyl_record", "metronome", "piano_bench", "midi_keyboard", "guitar_stand", "pool_ball",
       "pool_cue", "cue_rack", "game_console", "game_controller", "beanbag", "neon_sign", "vise", "pliers", "paint_can",
       "toolbox", "coat_hook", "pen", "notebook", "chalk", "globe", "blanket", "bicycle", "binder", "magazine", "marker",
       "sticky_note", "whiteboard_eraser", "jar", "lantern", "hanging_scroll", "violin_case", "service_bell", "chess_board",
       "chess_piece", "faucet", "vessel_sink", "pedestal_sink", "utility_sink", "coaster", "croissant", "jewelry_box",
       "folding_screen", "dog_bed", "laptop_stand", "console_table", "dais", "paper_towel_holder", "clothes", "luggage_cart"]


@cache
def _asset(category: str, variant: str, seed: int = 0):
    return registry.generate(category, seed, variant)


def _box(asset, label: str) -> np.ndarray:
    """(2, 3) bounds of every part labelled (or grouped as) ``label``."""
    b = np.array([p.bounds for p in asset.parts_by_label(label)])
    return np.array([b[:, 0].min(axis=0), b[:, 1].max(axis=0)])


def test_every_new_category_is_registered_with_its_variants():
    cats = registry.categories()
    for name in NEW:
        assert name in cats, name
        assert len(cats[name].variants) >= 2


@pytest.mark.parametrize(("category", "variant", "label"), [
    ("toolbox", "metal", "tray"), ("toolbox", "plastic", "tray"),
    ("piano_bench", "storage", "compartment"), ("cue_rack", "wall", "cup"), ("cue_rack", "floor", "cup"),
    ("jar", "mason", "body"), ("jar", "water", "body"), ("jewelry_box", "hinged", "tray"), ("vessel_sink", "oval", "basin"),
    ("pedestal_sink", "round", "basin"), ("utility_sink", "double", "basin"),
])
def test_supports_inside(category, variant, label):
    """A toolbox's lift-out tray, a storage bench's compartment floor and a cue rack's cups are
    internal supports (what ``IN object:part`` lands on)."""
    a = _asset(category, variant)
    parts = {p.name for p in a.parts_by_label(label)}
    inside = [s for s in a.internal if s.part in parts]
    assert inside, f"{a.asset_id}: no internal surface on {label}"
    if category == "toolbox":  # the tray hangs inside the body, below the closed lid
        lid = _box(a, "lid")
        assert all(s.surface.origin[2] < lid[0, 2] for s in inside)


def test_cue_rack_holder_names_its_cups_and_clip():
    """``cue_rack:holder`` (the outsiders' word) is a group: the cups the butts stand in and the
    slotted clip higher up; a cue IN the holder stands on a cup's floor."""
    a = _asset("cue_rack", "wall")
    held = {p.label for p in a.parts_by_label("holder")}
    assert held == {"cup", "clip"}
    cups, clip = _box(a, "cup"), _box(a, "clip")
    assert clip[0, 2] > cups[1, 2] + 0.5


@pytest.mark.parametrize(("category", "variant", "moving", "kind"), [
    ("toolbox", "metal", "lid", "revolute"), ("record_player", "hifi", "dust_cover", "revolute"),
    ("piano_bench", "storage", "seat", "revolute"), ("vise", "bench", "jaw_1", "prismatic"),
    ("notebook", "spiral", "front_cover", "revolute"), ("notebook", "legal_pad", "front_cover", "revolute"),
    ("violin_case", "shaped", "lid", "revolute"), ("jewelry_box", "drawers", "lid", "revolute"),
])
def test_joints_where_the_real_thing_has_them(category, variant, moving, kind):
    a = _asset(category, variant)
    j = next(j for j in a.joints if j.child_part == moving)
    assert j.type == kind
    lo, hi = j.limits
    opened = a.posed({j.name: hi if abs(hi) > abs(lo) else lo})
    before = a.part(moving).bounds
    after = opened.part(moving).bounds
    if kind == "revolute":  # lids and covers swing out of the closed asset's box
        box = a.bounds
        assert max((after[1] - box[1]).max(), (box[0] - after[0]).max()) > 0.02
        if category not in ("notebook", "binder"):  # lids lift
            assert after[1, 2] > before[1, 2] + 0.02
        else:  # a notebook stands like a book: its front cover swings forward (+Y)
            assert after[1, 1] > box[1, 1] + 0.02
    else:  # the vise's front jaw slides out towards the user, carrying its screw and handle
        assert after[1, 1] > before[1, 1] + 0.03
        assert opened.part("handle").bounds[1, 1] > a.part("handle").bounds[1, 1] + 0.03


@pytest.mark.parametrize(("variant", "keys"), [("mini", 25), ("controller49", 49), ("controller61", 61)])
def test_midi_keyboard_has_a_real_key_count(variant, keys):
    a = _asset("midi_keyboard", variant)
    assert len(a.parts_by_label("key")) == keys


def test_guitar_stand_cradle_below_neck_rest():
    for variant in ("tripod", "wooden"):
        a = _asset("guitar_stand", variant)
        cradle, rest = _box(a, "cradle"), _box(a, "neck_rest")
        assert rest[0, 2] > cradle[1, 2] + 0.4, variant


def test_notebook_cover_group_and_coat_hook_reach():
    nb = _asset("notebook", "bound")
    covers = nb.parts_by_label("cover")
    assert {p.label for p in covers} == {"front_cover", "back_cover"}
    assert nb.part("front_cover").bounds[0, 1] > nb.part("back_cover").bounds[1, 1]  # the book frame: front at +Y
    for variant in ("single", "rail"):
        hook = _asset("coat_hook", variant)
        plate, hooks = _box(hook, "plate"), _box(hook, "hook")
        assert hooks[1, 1] > plate[1, 1] + 0.04  # the hooks reach out from the wall plate
        assert plate[0, 1] <= hooks[0, 1] + 1e-9  # the plate is the back, against the wall


def _garage() -> PAG:
    pag = PAG("garage-corner", Room("storage", ((0, 0), (4, 0), (4, 3.5), (0, 3.5)), 2.5))
    pag.add("toolbox", "toolbox")
    pag.relate("toolbox", "ON", "floor")
    pag.add("pliers", "pliers")
    pag.relate("pliers", "IN", "toolbox:tray")
    pag.add("can", "paint_can")
    pag.relate("can", "ON", "floor")
    pag.add("bike", "bicycle")
    pag.relate("bike", "ON", "floor")
    pag.relate("bike@back", "AGAINST", "wall_0")
    pag.add("hook", "coat_hook")
    pag.relate("hook", "SECURED_TO", "wall_1", height=[1.5, 1.7])
    pag.add("desk", "desk")
    pag.relate("desk", "ON", "floor")
    pag.add("vise", "vise")
    pag.relate("vise", "ON", "desk:tabletop@top")
    return pag


def _music_corner() -> PAG:
    pag = PAG("music-corner", Room("music_room", ((0, 0), (4, 0), (4, 3.5), (0, 3.5)), 2.6))
    pag.add("bench", "piano_bench")
    pag.relate("bench", "ON", "floor")
    pag.add("metronome", "metronome")
    pag.relate("metronome", "ON", "bench:seat@top")
    pag.add("stand", "guitar_stand")
    pag.relate("stand", "ON", "floor")
    pag.add("player", "record_player")
    pag.relate("player", "ON", "floor")
    pag.add("notebook", "notebook")
    pag.relate("notebook:back_cover@back", "ON", "bench:seat@top")  # lying, as the outsiders wrote it
    pag.add("pen", "pen")
    pag.relate("pen", "ON", "notebook:front_cover@front")
    return pag


def _lobby_corner() -> PAG:
    pag = PAG("lobby-corner", Room("hotel_lobby", ((0, 0), (5, 0), (5, 4), (0, 4)), 2.8))
    pag.add("cart", "luggage_cart")
    pag.relate("cart", "ON", "floor")
    pag.add("case", "suitcase")
    pag.relate("case", "ON", "cart:deck@top")
    pag.add("console", "console_table")
    pag.relate("console", "ON", "floor")
    pag.relate("console:tabletop@back", "AGAINST", "wall_1")
    pag.add("player", "record_player")
    pag.relate("player:base", "ON", "console:tabletop@top")
    pag.add("jar", "jar")
    pag.relate("jar", "ON", "console:tabletop@top")
    pag.add("bell", "service_bell")
    pag.relate("bell", "ON", "console:tabletop@top")
    pag.add("scroll", "hanging_scroll")
    pag.relate("scroll:paper@back", "SECURED_TO", "wall_2", height=[1.1, 1.4])
    pag.add("sink", "utility_sink")
    pag.relate("sink", "ON", "floor")
    pag.relate("sink@back", "AGAINST", "wall_3")
    return pag


@pytest.mark.parametrize("room", [_garage, _music_corner, _lobby_corner])
def test_small_rooms_solve(room):
    scene = solve(room(), seed=0)
    failed = {o.id: o.reason for o in scene.objects.values() if not o.placed}
    assert not failed
    assert all(c.holds for c in scene.relations), [(c.child, c.relation, c.parent, c.detail) for c in scene.relations
                                                   if not c.holds]


def test_book_frame_and_part_words():
    """Binders and magazines stand like books (covers facing ±Y, spine at -X), as the outsiders'
    ``binder:cover@front`` and ``magazine:back_cover@back ON table`` take them; ``cover`` names
    both covers."""
    for cat, variant in (("binder", "lever_arch"), ("magazine", "glossy")):
        a = _asset(cat, variant)
        assert {p.label for p in a.parts_by_label("cover")} == {"front_cover", "back_cover"}
        assert a.part("front_cover").bounds[0, 1] > a.part("back_cover").bounds[1, 1]
        assert a.extents[2] > 3 * a.extents[1]  # upright and thin
    scroll = _asset("hanging_scroll", "vertical")
    assert scroll.part("paper").bounds[0, 1] <= scroll.bounds[0, 1] + 1e-9  # the paper lies flat on the wall
    lamp = _asset("lantern", "paper")
    assert _box(lamp, "cord")[1, 2] >= lamp.bounds[1, 2] - 1e-9  # it hangs from its cord
    assert len(_asset("chess_board", "flat").parts_by_label("square")) == 32


def test_chess_pieces_differ_by_their_heads():
    """Kings and queens stand tallest, then bishops and knights, rooks and pawns lowest."""
    def tallest(variant):
        return max(registry.generate("chess_piece", s, variant).extents[2] for s in range(4))
    assert tallest("royal") > tallest("minor") > tallest("pawn")
    assert tallest("royal") > tallest("rook")
