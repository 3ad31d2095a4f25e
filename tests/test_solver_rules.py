"""Focused tests of three placement rules of the solver, each on real generated assets:

* ``base_supported``: a child hanging over a small support stands only when the parts of its
  base resting on the support hold its centre of mass (a desk half off a platform does not; a
  bottle lying across a wine rack's bar does when the bar is under its centre of mass);
* ``_pressing``: a leaning object is tilted far enough that gravity presses it toward what it
  leans on (its centre of mass beyond the base edge it pivots on);
* ``leave_room``: samples that leave room beside an object for what is still to be placed
  beside it on the same support come first (a stove with a counter to its right is not pushed
  into the corner).
"""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from shapely.geometry import box

from parse3d.assets import registry
from parse3d.geometry.frames import axis_angle
from parse3d.geometry.surfaces import Surface
from parse3d.measure.geometry import asset_geometry
from parse3d.pag import PAG, Room
from parse3d.scene.model import Scene
from parse3d.scene.shell import build_shell
from parse3d.solver.collision import CollisionWorld
from parse3d.solver.rotation import LEAN_MARGIN, _pressing
from parse3d.solver.sampling import base_supported, leave_room
from parse3d.solver.state import SolveState
from parse3d.solver.support import support_candidates

EX, EY, EZ = np.eye(3)


def floor_plane(z: float = 0.0) -> Surface:
    """An upward plane at height ``z`` whose plane coordinates are world x and y."""
    return Surface("top", np.array([0.0, 0.0, z]), EZ, EX, EY, box(-5, -5, 5, 5))


# ------------------------------------------------------------------------ base_supported
def test_base_supported_needs_the_resting_base_to_hold_the_centre_of_mass():
    desk = registry.generate("desk", seed=0)
    s = floor_plane()
    R, t = np.eye(3), np.zeros(3)  # the asset's origin is the centre of its base: on the plane
    half = float(asset_geometry(desk).bounds[1, 0])
    assert base_supported(desk, 1.0, R, t, s, box(-2, -2, 2, 2))
    # only the right-hand legs on the platform: the centre of mass (near x = 0) hangs off
    assert not base_supported(desk, 1.0, R, t, s, box(0.6 * half, -2, 2, 2))
    # nothing of the base on it at all
    assert not base_supported(desk, 1.0, R, t, s, box(3, 3, 4, 4))


@pytest.fixture(scope="module")
def lying_bottle():
    """A bottle lying on its back (its axis along world -Y), its lowest point on z = 0, and the
    (x, y) of its centre of mass."""
    bottle = registry.generate("bottle", seed=0)
    R = axis_angle(EX, np.pi / 2)  # its back (-Y) faces down
    hull = asset_geometry(bottle).hull @ R.T
    t = np.array([0.0, 0.0, -float(hull[:, 2].min())])
    com = R @ asset_geometry(bottle).com + t
    return bottle, R, t, com[:2]


@pytest.mark.parametrize("width", [0.015, 0.003])
def test_base_supported_on_a_bar_under_the_centre_of_mass(lying_bottle, width):
    """A wine rack's cradle bar (0.015 m), or one narrower than the 5 mm margin: the bottle
    lies along it with its centre of mass over it; 6 cm off its centre of mass (the bar still
    under the bottle), it would not."""
    bottle, R, t, (cx, cy) = lying_bottle
    s = floor_plane()
    along = box(cx - width / 2, cy - 0.2, cx + width / 2, cy + 0.2)
    assert base_supported(bottle, 1.0, R, t, s, along)
    off = shapely.affinity.translate(along, 0.06, 0.0)
    assert not base_supported(bottle, 1.0, R, t, s, off)


@pytest.mark.parametrize("width", [0.015, 0.003])
def test_base_supported_across_bars_needs_two(lying_bottle, width):
    """Across one bar, even right under its centre of mass, a lying bottle balances (its neck
    over the gap tips it in settling); across two bars under its body, it lies."""
    bottle, R, t, (cx, cy) = lying_bottle
    s = floor_plane()
    across = box(cx - 0.2, cy - width / 2, cx + 0.2, cy + width / 2)
    assert not base_supported(bottle, 1.0, R, t, s, across)
    # the bottle runs from its base (y = 0) to its cap (y = -height); 60% of the way is body
    near, far = -0.02, -(float(asset_geometry(bottle).bounds[1, 2]) * 0.6)
    assert far < cy < near
    two = shapely.union_all([box(cx - 0.2, y - width / 2, cx + 0.2, y + width / 2) for y in (near, far)])
    assert base_supported(bottle, 1.0, R, t, s, two)


# ------------------------------------------------------------------------------ _pressing
def lean_margin(asset, R, k, d, th) -> float:
    """How far (m) the centre of mass lies beyond the lowest points along ``d`` at tilt ``th``."""
    g = asset_geometry(asset)
    Rt = axis_angle(k, th) @ R
    Y = g.hull @ Rt.T
    base = Y[Y[:, 2] <= Y[:, 2].min() + 2e-3]
    return float((Rt @ g.com) @ d - np.max(base @ d))


def test_pressing_tilts_far_enough_for_gravity_to_hold_the_lean():
    guitar = registry.generate("guitar", seed=0)
    R = np.eye(3)
    d = -EY  # the wall is behind it
    k = EX  # tilting about +X turns its top toward -Y
    tilts = list(np.deg2rad([0.0, 1.0, 2.0, 12.0, 16.0, 20.0]))
    margins = [lean_margin(guitar, R, k, d, th) for th in tilts]
    pressed = {th for th, m in zip(tilts, margins, strict=True) if m >= LEAN_MARGIN}
    assert pressed and tilts[0] not in pressed  # upright it would not lean on the wall
    picks = {_pressing(guitar, 1.0, R, k, d, tilts, np.random.default_rng(i)) for i in range(40)}
    assert picks <= pressed and len(picks) > 1  # a random one of the tilts that press
    # none presses: the one that comes closest
    small = tilts[:3]
    assert _pressing(guitar, 1.0, R, k, d, small, np.random.default_rng(0)) == \
        small[int(np.argmax(margins[:3]))]


# ---------------------------------------------------------------------------- leave_room
def kitchen_wall(counter_beside: bool) -> tuple[SolveState, object]:
    pag = PAG("stove-and-counter", Room("kitchen", ((0, 0), (4, 0), (4, 3), (0, 3)), 2.7))
    pag.add("stove", "stove")
    pag.relate("stove", "ON", "floor")
    pag.add("counter", "kitchen_counter")
    pag.relate("counter", "ON", "floor")
    if counter_beside:
        pag.relate("counter", "SIDE_OF", "stove", side="right")
    st = SolveState(pag, Scene(pag, 0, build_shell(pag.room)), CollisionWorld())
    sup = support_candidates(st, pag.supporter("stove"))[0]
    return st, sup


def test_leave_room_puts_samples_with_room_for_the_counter_first():
    st, sup = kitchen_wall(counter_beside=True)
    s = sup.surface
    F = np.array([[-0.3, -0.3], [0.3, -0.3], [0.3, 0.3], [-0.3, 0.3]])  # the stove, unturned
    # stove centres at world x = 3.6 (0.1 m left on its right: no counter fits), then 1.0
    cramped, roomy = s.to_2d(np.array([[3.6, 1.5, 0.0], [1.0, 1.5, 0.0]]))
    samples = np.array([cramped, roomy, cramped + [0, 0.1]])
    out = leave_room(st, "stove", sup, np.eye(3), F, sup.region, samples)
    assert np.allclose(out, [roomy, cramped, cramped + [0, 0.1]])  # otherwise in order
    # turned half round, the stove's right is world -x: at x = 1.0 only 0.7 m are left there,
    # less than the smallest counter (0.85 m)
    turned = leave_room(st, "stove", sup, axis_angle(EZ, np.pi), F, sup.region,
                         np.array([roomy, cramped]))
    assert np.allclose(turned, [cramped, roomy])
    # nothing to leave room for: the order is kept
    st2, sup2 = kitchen_wall(counter_beside=False)
    assert np.allclose(leave_room(st2, "stove", sup2, np.eye(3), F, sup2.region, samples),
                       samples)


# ------------------------------------------------------------------- headroom of a shelf
def test_in_a_rack_lower_than_the_drawn_instance_takes_a_lower_or_smaller_one():
    """Three cereal boxes IN a grocery shelf whose gaps (0.22 m) are lower than most boxes
    (0.22-0.29 m): the lowest instance is drawn, then shrunk within the category's range to
    the free height, instead of failing with "no free space" after four tall draws."""
    from parse3d.solver import solve
    from parse3d.solver.choice import extent_along

    pag = PAG("cereal-aisle", Room("store", ((0, 0), (4, 0), (4, 3), (0, 3)), 2.7))
    pag.add("rack", "grocery_shelf")
    pag.relate("rack", "ON", "floor")
    pag.relate("rack@back", "AGAINST", "wall_2")
    for i in range(3):
        pag.add(f"cereal_{i}", "cereal_box")
        pag.relate(f"cereal_{i}", "IN", "rack:shelf")
    scene = solve(pag, seed=8)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    rack = scene.objects["rack"]
    for i in range(3):
        o = scene.objects[f"cereal_{i}"]
        gap = max(s.clearance for s in rack.asset.internal if s.part == o.support_choice.part)
        assert o.scale * extent_along(o.asset, 2) <= gap * rack.scale
        lo, hi = o.asset.size_range
        assert lo - 1e-9 <= o.scale * asset_geometry(o.asset).size <= hi + 1e-9


# ------------------------------------------------------------------------ a slanted part
def test_on_a_slanted_part_draws_an_instance_where_it_is_flat():
    """An open grand piano's lid touches its bounding box's top along an edge only: it is no
    support, so an object ON ``piano:lid`` makes the solver draw a piano whose lid is flat (an
    upright), and says why a grand one does not do."""
    from parse3d.solver import solve
    from parse3d.solver.placement import lacks

    need = [("lid", None, "ON score -> piano:lid", "free_top")]
    assert "lid is slanted" in lacks(registry.generate("piano", seed=0), need)  # a grand
    assert lacks(registry.generate("piano", seed=1), need) is None  # an upright
    pag = PAG("piano-score", Room("music_room", ((0, 0), (5, 0), (5, 4.5), (0, 4.5)), 2.7))
    pag.add("piano", "piano")
    pag.relate("piano", "ON", "floor")
    pag.add("score", "sheet_music")
    pag.relate("score", "ON", "piano:lid")
    scene = solve(pag, seed=0)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    assert lacks(scene.objects["piano"].asset, need) is None


# ------------------------------------------------------------ a support of several parts
@pytest.mark.parametrize("seed", [0, 1])
def test_a_suitcase_rests_across_a_luggage_racks_straps(seed):
    """``ON rack:strap`` names three straps at one level: a suitcase's feet stand on the outer
    straps with its centre of mass over the gap between them (no strap alone holds it)."""
    from parse3d.measure import check_edge
    from parse3d.solver import solve

    pag = PAG("luggage", Room("storage", ((0, 0), (4, 0), (4, 3), (0, 3)), 2.7))
    pag.add("rack", "luggage_rack")
    pag.relate("rack", "ON", "floor")
    pag.relate("rack@back", "AGAINST", "wall_0")
    pag.add("case", "suitcase")
    pag.relate("case", "ON", "rack:strap")
    scene = solve(pag, seed=seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    case = scene.objects["case"]
    holds, res, _ = check_edge(scene, pag.supporter("case"), case)
    assert holds and res["com_inside"] == 1.0


# -------------------------------------------------------------------------- a stack base
def test_the_base_of_a_stack_is_an_instance_that_does_not_roll():
    """``towel_1 ON towel_0``: the lower towel is the base of a stack of its kind, so a rolled
    towel (round above and below) is no instance for it; a folded one is."""
    from parse3d.solver.placement import lacks, requirements

    pag = PAG("towels", Room("bathroom", ((0, 0), (3, 0), (3, 2.5), (0, 2.5)), 2.6))
    pag.add("shelf", "bookcase")
    pag.relate("shelf", "ON", "floor")
    pag.add("towel_0", "towel")
    pag.relate("towel_0", "IN", "shelf:shelf")
    pag.add("towel_1", "towel")
    pag.relate("towel_1", "ON", "towel_0")
    need = [r for r in requirements(pag, "towel_0") if r[3] == "stack_base"]
    assert need and not [r for r in requirements(pag, "towel_1") if r[3] == "stack_base"]
    rolled = registry.generate("towel", seed=1)
    folded = registry.generate("towel", seed=2)
    assert "rolled" in rolled.asset_id and "folded" in folded.asset_id
    assert "would roll" in lacks(rolled, need)
    assert lacks(folded, need) is None
