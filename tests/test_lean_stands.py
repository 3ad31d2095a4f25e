"""Things leaning on an object's face (tests/data/rooms/guitars_in_stands,
cushions_against_chair_backs, ladder_against_a_bookcase): a guitar stands by its body in a
stand's cradle, leaning by its neck on the neck rest, at a tilt whose base lands in the
cradle; a cushion at the back of an armchair's seat overhangs it toward the back, held by
the seat and the back together; a ladder leans on a whole bookcase, its rails resting behind
the plane of the bookcase's foremost point. All stay so after settling."""

from __future__ import annotations

import copy
from dataclasses import replace

import pytest

from parse3d.geometry.surfaces import surface_from_bbox
from parse3d.measure import check_edge
from parse3d.measure.reach import face_slabs, nearest_in_prism, piece_data
from test_rooms import solved

GUITARS = {"guitar_a": "stand_a", "guitar_b": "stand_b"}


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_guitars_stand_in_their_stands_leaning_on_the_neck_rest(seed):
    scene = solved("guitars_in_stands", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for gid, sid in GUITARS.items():
        mine = [c for c in scene.relations if c.child.startswith(f"{gid}:")]
        assert {c.relation for c in mine} == {"ON", "LEANING_AGAINST"}
        for c in mine:
            assert c.relaxed is None and c.holds_settled is True, (c.relation, c.residual_settled)
        guitar = scene.objects[gid]
        assert not guitar.repairs, guitar.repairs
        # its body rests in the cradle, above the stand's base, below the neck rest
        z = guitar.world_bounds(settled=True)[0, 2]
        top = scene.objects[sid].world_bounds(settled=True)[1, 2]
        assert 0.05 < z < 0.5 * top, (z, top)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_cushions_stand_at_the_back_of_seats_leaning_on_the_backs(seed):
    scene = solved("cushions_against_chair_backs", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    for cid in ("cushion_a", "cushion_b"):
        mine = [c for c in scene.relations if c.child.split(":")[0].split("@")[0] == cid]
        assert {c.relation for c in mine} == {"ON", "LEANING_AGAINST"}
        for c in mine:
            assert c.relaxed is None and c.holds_settled is True, (c.relation, c.residual_settled)


def test_a_cushion_overhanging_the_seat_is_held_by_what_it_leans_on():
    """Its centre of mass behind the seat's back edge, over the gap between the seat and the
    chair's back: the seat and the back hold it together. Written to lean on the other chair's
    back, which it does not touch, the same pose no longer stands on the seat."""
    held = []
    for seed in (0, 1, 2):
        scene = solved("cushions_against_chair_backs", seed)
        leans = {e.child.object: e for e in scene.pag.relations
                 if e.relation == "LEANING_AGAINST"}
        for cid, other in (("cushion_a", "cushion_b"), ("cushion_b", "cushion_a")):
            on = next(e for e in scene.pag.relations if e.relation == "ON"
                      and e.child.object == cid)
            c = scene.objects[cid]
            got = check_edge(scene, on, c, settled=True)
            assert got.holds and got.residual["com_inside"] == 1.0, got.detail
            astray = copy.copy(scene)
            astray.pag = copy.copy(scene.pag)
            astray.pag.relations = [replace(e, parent=leans[other].parent) if e is leans[cid]
                                    else e for e in scene.pag.relations]
            bare = check_edge(astray, on, c, settled=True)
            if not bare.holds:
                assert "centre of mass outside" in bare.detail, bare.detail
                held.append((seed, cid))
    assert held, "no cushion overhangs its seat: the rule is not exercised"


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_ladder_leans_on_a_whole_bookcase(seed):
    scene = solved("ladder_against_a_bookcase", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    lean = next(c for c in scene.relations if c.relation == "LEANING_AGAINST")
    assert lean.relaxed is None and lean.holds_settled is True, lean.residual_settled
    assert 9.0 <= lean.residual_settled["angle_deg"] <= 21.0


def test_ladder_rests_behind_the_bookcase_fronts_plane():
    """The front of a whole bookcase is the plane of its foremost point (a door's handle): the
    ladder's rails pass behind it, resting on the doors or the top, and the check takes their
    exact distance to the bookcase there."""
    behind = []
    for seed in (0, 1, 2):
        scene = solved("ladder_against_a_bookcase", seed)
        case, ladder = scene.objects["bookcase"], scene.objects["ladder"]
        face = surface_from_bbox("front", case.asset.bounds).transformed(case.transform(True))
        got = nearest_in_prism(piece_data(ladder.asset, ladder.asset.parts_by_label("rail")),
                               ladder.transform(True), face.normal, face.origin,
                               face_slabs(face))
        behind.append(got[0])
    assert min(behind) < -1e-3, behind
