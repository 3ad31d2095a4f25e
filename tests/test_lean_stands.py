"""Things resting on one part of an object and leaning on another (tests/data/rooms/
guitars_in_stands): a guitar stands by its body in a stand's two cradle arms and leans by its
neck on the stand's neck rest. Its centre of mass lies behind the cradle, between the cradle
and the neck rest: the base and the lean hold it together, so its support holds while the
lean touches, and not once it stops touching."""

from __future__ import annotations

import copy
from dataclasses import replace

import pytest

from parse3d.measure import check_edge
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
