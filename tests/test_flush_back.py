"""Furniture made to stand against a wall is flush there by the part a person sees as its back:
no top panel, lid, countertop, plinth, end cap, post sleeve or headboard overhangs it, so
``AGAINST dresser:body@back -> wall`` (or ``bed:frame@right -> wall``) holds as written."""

from __future__ import annotations

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.measure.checks import end_pads
from parse3d.relations import SURFACES
from parse3d.solver.geometry import part_points
from test_rooms import solved

#: (category, named part, side, variants made to stand against a wall by it)
FLUSH = [
    ("nightstand", "body", "back", None),
    ("dresser", "body", "back", None),
    ("piano", "body", "back", ("upright",)),
    ("bathroom_vanity", "body", "back", None),
    ("fireplace", "surround", "back", None),
    ("grocery_shelf", "back_panel", "back", ("single_sided",)),
    ("storage_rack", "shelf", "back", None),
    ("kitchen_counter", "body", "back", None),
    ("kitchen_counter", "body", "left", None),
    ("kitchen_counter", "body", "right", None),
    # a four-poster's posts stand outside its rails by design
    ("bed", "frame", "left", ("platform", "storage")),
    ("bed", "frame", "right", ("platform", "storage")),
]


def _cases():
    return [pytest.param(cat, v, part, side, id=f"{cat}-{v}-{part}@{side}")
            for cat, part, side, variants in FLUSH for v in variants or registry.get(cat).variants]


@pytest.mark.parametrize(("category", "variant", "part", "side"), _cases())
@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_the_named_part_reaches_the_objects_extreme(category, variant, part, side, seed):
    a = registry.generate(category, seed, variant)
    n = np.asarray(SURFACES[side], float)
    pts = {p.name: part_points([p]) for p in a.parts}
    named = {p.name for p in a.parts_by_label(part)}
    assert named, f"{a.asset_id} has no {part}"
    pads = end_pads([pts[k] for k in named], [(k, q) for k, q in pts.items() if k not in named], n)
    mine = max(float(np.max(pts[k] @ n)) for k in (*named, *pads))
    whole = max(float(np.max(q @ n)) for q in pts.values())
    over = {k: float(np.max(q @ n)) - mine for k, q in pts.items() if float(np.max(q @ n)) > mine + 1e-4}
    assert whole - mine < 1e-4, f"{a.asset_id}: parts reach further {side} than {part}: {over}"


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("room", ["backs_to_the_walls", "shop_backs_to_the_walls"])
def test_furniture_against_walls_by_named_backs_holds_after_settling(room, seed):
    scene = solved(room, seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    contacts = [c for c in scene.relations if c.relation == "AGAINST"]
    assert len(contacts) >= 5
    for c in contacts:
        assert c.holds and c.holds_settled, (c.child, c.parent, c.relaxed, c.residual_settled)
    # what stands on the tops stays there
    for c in scene.relations:
        if c.relation == "ON":
            assert c.holds_settled, (c.child, c.parent, c.residual_settled)
    assert not [o.id for o in scene.objects.values() if "fell" in o.flags]
