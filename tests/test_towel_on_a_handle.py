"""A towel written below a stove's `handle` with no `#k`, where the stove has several handles
(the oven door's, a drawer's near the floor), hangs over the highest of them, which leaves room
to hang, not over the lowest (tests/data/rooms/towel_on_an_oven_handle.json)."""

from __future__ import annotations

from pathlib import Path

import pytest

from parse3d.measure import verify_settled
from parse3d.measure.checks import world_points
from parse3d.pag import load_pag
from parse3d.pipeline import PipelineOptions, run_pipeline

ROOMS = Path(__file__).parent / "data" / "rooms"


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_towel_hangs_over_the_highest_handle(seed):
    scene = run_pipeline(load_pag(ROOMS / "towel_on_an_oven_handle.json"), seed=seed, out=None,
                         options=PipelineOptions(settle=True, preview=False))
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    rng = scene.objects["range"]
    handles = rng.asset.parts_by_label("handle")
    part = scene.objects["towel"].support_choice.part
    assert scene.objects["towel"].support_choice.owner == "range"
    tops = {p.name: float(world_points(rng, parts=[p])[:, 2].max()) for p in handles}
    assert tops[part] >= max(tops.values()) - 1e-6, (part, tops)
    c = next(c for c in scene.relations if c.child == "towel")
    assert c.relaxed is not None and "hangs over range:handle" in c.relaxed["blocked"], c.relaxed
    assert not [i for i in verify_settled(scene) if i.cause == "fell"]
