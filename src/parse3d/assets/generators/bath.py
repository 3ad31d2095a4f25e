"""Bathroom fixtures: bathtubs, toilets, vanities and towel bars.

Bathtubs and basins are open vessels, so their inside bottoms are internal support surfaces
(``IN``). Toilets put the ``tank`` at -Y and the ``bowl`` at +Y; vanities stand with their back at
-Y and doors or drawers at +Y. A towel bar is a wall item: its ``bracket`` parts have flat backs
at -Y (pressed against the wall) and the ``bar`` runs along X.
"""

from __future__ import annotations

import numpy as np
import shapely
import trimesh

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._bedbath_common import CARCASS_GROUP, bar_handle, bevel_box, carcass_panels, knob, scaled
from ._dB_case import glides
from ._kit import DRAWER_TRAVEL, OPEN_DOOR, hinge_parts, mount, prismatic, revolute

_WHITE = (0.96, 0.96, 0.95)


def _enamel(rng: np.random.Generator) -> Material:
    return M.solid(M.jitter(rng, _WHITE, 0.01), "ceramic", roughness=0.2)


def _oval_vessel(profile, thickness: float, sx: float, sy: float, z0: float) -> S.Shape:
    """A revolved vessel stretched into an oval (x by ``sx``, y by ``sy``), bottom at ``z0``."""
    v = S.vessel(profile, thickness, sections=32, piece_sections=16)
    return scaled(v, sx, sy, 1.0, offset=(0, 0, z0))


def _faucet(x: float, y: float, z: float, reach: float, height: float, *, towards=(0, 1, 0),
            radius: float = 0.012) -> S.Shape:
    """A gooseneck spout rising from (x, y, z) and curving over ``towards`` by ``reach``."""
    d = np.asarray(towards, float)
    t = np.linspace(0, np.pi, 7)
    arc = [np.array([x, y, z + height]) + d * reach * (1 - np.cos(a)) / 2
           + [0, 0, reach * 0.5 * np.sin(a)] for a in t]
    path = [np.array([x, y, z - 0.003])] + arc + [arc[-1] - [0, 0, 0.03]]
    base = S.cylinder(radius * 2.2, 0.03, center=(x, y, z + 0.015), sections=14)
    return S.union([base, S.tube(np.array(path), radius, sections=8)])


@register("bathtub", parts=("tub",), extra_parts=("foot", "faucet", "base", "handle", "drain", "overflow", "screw", "plug",
                                                 "escutcheon"),
          size_range=(1.4, 1.9), density=400,
          variants=("clawfoot", "pedestal", "built_in"))
def bathtub(rng: np.random.Generator, variant: str) -> list[Part]:
    length = rng.uniform(1.5, 1.8)
    width = rng.uniform(0.7, 0.82)
    mat = _enamel(rng)
    chrome = M.metal(rng)
    parts: list[Part] = []
    if variant == "built_in":
        h = rng.uniform(0.5, 0.58)
        t = rng.uniform(0.07, 0.1)
        bottom = rng.uniform(0.08, 0.12)
        walls = [bevel_box((length, t, h), center=(0, sy * (width - t) / 2, h / 2), bevel=0.01)
                 for sy in (-1, 1)]
        walls += [bevel_box((t, width - 2 * t, h), center=(sx * (length - t) / 2, 0, h / 2),
                            bevel=0.01) for sx in (-1, 1)]
        walls.append(S.box((length - 2 * t, width - 2 * t, bottom), center=(0, 0, bottom / 2)))
        parts.append(make_part("tub", "tub", walls, mat))
        top = h
        x_end = -length / 2 + t / 2
    else:
        h = rng.uniform(0.5, 0.58)
        z_feet = rng.uniform(0.08, 0.14) if variant == "clawfoot" else rng.uniform(0.1, 0.16)
        r = width / 2
        prof = [(r * 0.8, 0.0), (r * 0.94, h * 0.3), (r, h)]
        tub = _oval_vessel(prof, 0.035, length / width, 1.0, z_feet)
        rim_a = np.linspace(0, 2 * np.pi, 20, endpoint=False)
        rim = S.tube(np.c_[length / 2 * np.cos(rim_a) * 0.985, r * np.sin(rim_a) * 0.985,
                           np.full(20, z_feet + h)], 0.018, sections=8, closed=True)
        parts.append(make_part("tub", "tub", [tub, rim], mat))
        top = z_feet + h + 0.018
        x_end = -length / 2 + 0.07
        if variant == "clawfoot":
            foot_mat = chrome if rng.random() < 0.6 else mat
            for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1))):
                x, y = sx * length * 0.33, sy * r * 0.52
                leg = S.frustum(0.035, 0.05, z_feet + 0.03, center=(x, y, 0.0), sections=10)
                claw = S.ellipsoid((0.045, 0.04, 0.025), center=(x + sx * 0.01, y, 0.025),
                                   subdivisions=1)
                parts.append(make_part(f"foot_{i}", "foot", [leg, claw], foot_mat))
        else:
            base = scaled(S.frustum(1.0, 0.92, z_feet + 0.02, sections=28),
                          length * 0.3, r * 0.6, 1.0)
            parts.append(make_part("base", "base", base, mat))
    # a wall-mounted style spout over the -X end
    spout = _faucet(x_end, 0.0, top, 0.1, 0.06, towards=(1, 0, 0), radius=0.011)
    parts.append(make_part("faucet", "faucet", spout, chrome))
    # hot and cold cross-handles either side of the spout, on the deck or rim
    for i, sy in enumerate((-1, 1)):
        y = sy * 0.09
        # on the rim tube of a freestanding tub (an ellipse), on the end wall of a built-in one
        x = x_end if variant == "built_in" else -length / 2 * 0.985 * np.sqrt(1 - (y / (width / 2 * 0.985)) ** 2)
        stem = S.cylinder(0.012, 0.045, center=(x, y, top + 0.0225 - 0.004), sections=10)
        cross = [S.box((0.06, 0.012, 0.012), center=(x, y, top + 0.041)),
                 S.box((0.012, 0.06, 0.012), center=(x, y, top + 0.041))]
        parts.append(make_part(f"handle_{i}", "handle", [stem, *cross], chrome))
    # the drain in the floor at the tap end, and the overflow plate on the end wall above it
    if variant == "built_in":
        z_floor = bottom
        zo = (z_floor + top) / 2 + 0.05
        xd, xo = -length / 2 + t + 0.1, -length / 2 + t + 0.004
    else:  # the oval's end wall leans out: its inner face at a height, along -X
        tx = 0.035 * length / width

        def inner_x(z: float) -> float:
            f = float(np.interp(z - z_feet, [q[1] for q in prof], [q[0] / r for q in prof]))
            return -length / 2 * f + tx

        z_floor = z_feet + 0.035
        zo = (z_floor + top) / 2 + 0.05
        xd, xo = inner_x(z_floor) + 0.1, inner_x(zo) + 0.004
    parts.append(make_part("drain", "drain", S.cylinder(0.035, 0.004, center=(xd, 0, z_floor + 0.002), sections=14), chrome))
    parts.append(make_part("overflow", "overflow", S.cylinder(0.035, 0.008, center=(xo, 0, zo), axis=(1, 0, 0), sections=14),
                           chrome))
    # the overflow plate's two screws, the rubber plug lying by the drain, and the flanges
    # under the two handles
    for i, sz in enumerate((-1, 1)):
        parts.append(make_part(f"screw_{i}", "screw", S.cylinder(0.005, 0.003, center=(xo + 0.0055, 0, zo + sz * 0.02), axis=(1, 0, 0),
                                                                sections=8), chrome))
    parts.append(make_part("plug", "plug", S.frustum(0.026, 0.03, 0.012, center=(xd + 0.08, 0.05, z_floor), sections=12),
                           M.solid((0.1, 0.1, 0.1), "rubber", 0.8)))
    for i, sy in enumerate((-1, 1)):
        y = sy * 0.09
        x = x_end if variant == "built_in" else -length / 2 * 0.985 * np.sqrt(1 - (y / (width / 2 * 0.985)) ** 2)
        parts.append(make_part(f"escutcheon_{i}", "escutcheon", S.cylinder(0.024, 0.006, center=(x, y, top + 0.003), sections=12), chrome))
    return parts


@register("toilet", parts=("bowl", "tank", "seat"), extra_parts=("lid", "handle", "base", "hinge", "bolt_cap", "valve"),
          size_range=(0.6, 0.9), density=900, variants=("two_piece", "one_piece", "skirted"),
          groups={"tank": ("tank", "tank_lid")})
def toilet(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = _enamel(rng)
    seat_mat = mat if rng.random() < 0.7 else M.plastic(rng)
    z_rim = rng.uniform(0.38, 0.42)
    r = rng.uniform(0.17, 0.19)  # half width of the bowl rim
    sy = rng.uniform(1.25, 1.4)  # the bowl is longer than wide
    tank_w = rng.uniform(0.36, 0.44)
    tank_d = rng.uniform(0.15, 0.2)
    y_tank = -0.32
    y_bowl = y_tank + tank_d / 2 + r * sy - 0.02
    parts: list[Part] = []
    # the foot the bowl stands on
    if variant == "skirted":
        foot = bevel_box((r * 1.7, r * sy * 2 + 0.05, z_rim - 0.16),
                         center=(0, y_bowl - 0.05, (z_rim - 0.16) / 2), bevel=0.03)
    else:
        foot = scaled(S.lathe([(0.12, 0.0), (0.1, 0.05), (0.085, 0.15), (0.09, z_rim - 0.2)],
                              sections=24), 1.0, 1.25, 1.0, offset=(0, y_bowl - 0.03, 0))
    parts.append(make_part("base", "base", foot, mat))
    prof = [(r * 0.45, 0.0), (r * 0.85, 0.11), (r, 0.2)]
    bowl = _oval_vessel(prof, 0.025, 1.0, sy, z_rim - 0.2).moved((0, y_bowl, 0))
    parts.append(make_part("bowl", "bowl", bowl, mat))
    # the seat: a flattened ring resting on the rim
    a = np.linspace(0, 2 * np.pi, 12, endpoint=False)  # 12 convex pieces (the collision budget)
    ring = np.c_[r * 0.86 * np.cos(a), r * 0.86 * sy * np.sin(a) + y_bowl, np.full(12, 0.0)]
    seat = scaled(S.tube(ring, 0.03, sections=8, closed=True), 1.0, 1.0, 0.45,
                  offset=(0, 0, z_rim + 0.0135))
    parts.append(make_part("seat", "seat", seat, seat_mat))
    if variant == "one_piece":
        tank_h, z_tank = rng.uniform(0.2, 0.26), z_rim - 0.02
    else:
        tank_h, z_tank = rng.uniform(0.32, 0.4), z_rim + 0.02
    tank = bevel_box((tank_w, tank_d, tank_h), center=(0, y_tank, z_tank + tank_h / 2),
                     bevel=0.015)
    tank_lid = bevel_box((tank_w + 0.02, tank_d + 0.02, 0.025),
                         center=(0, y_tank, z_tank + tank_h + 0.0125), bevel=0.008)
    if variant != "one_piece":  # the cistern stands on a neck behind the bowl
        neck = S.box((tank_w * 0.5, tank_d * 0.8, z_tank - z_rim + 0.2),
                     center=(0, y_tank + 0.02, z_rim - 0.2 + (z_tank - z_rim + 0.2) / 2))
        parts.append(make_part("tank", "tank", [tank, neck], mat))
    else:
        parts.append(make_part("tank", "tank", tank, mat))
    # the cistern's loose lid, lifted off to reach the flush valve (``tank`` still covers it)
    parts.append(make_part("tank_lid", "tank_lid", tank_lid, mat))
    z_tank_top = z_tank + tank_h + 0.025
    if rng.random() < 0.5:
        button = S.cylinder(0.018, 0.01, center=(0, y_tank, z_tank_top + 0.004), sections=14)
        parts.append(make_part("handle", "handle", button, M.metal(rng)))
    else:
        lever = bar_handle((-tank_w / 2 + 0.06, y_tank + tank_d / 2, z_tank + tank_h - 0.05),
                           0.06, standoff=0.015, radius=0.006)
        parts.append(make_part("handle", "handle", lever, M.metal(rng)))
    if rng.random() < 0.8:
        lid_t = 0.02
        if rng.random() < 0.6:  # lid down, on the seat
            lid = scaled(S.cylinder(1.0, lid_t, sections=24), r * 0.98, r * 0.98 * sy, 1.0,
                         offset=(0, y_bowl + 0.005, z_rim + 0.027 + lid_t / 2))
        else:  # lid up, leaning on the tank
            lid = scaled(S.cylinder(1.0, 1.0, axis=(0, 1, 0), sections=24), r * 0.98, lid_t,
                         r * 0.98 * sy, offset=(0, y_tank + tank_d / 2 + 0.03 + lid_t / 2,
                                                z_rim + 0.03 + r * sy))
        parts.append(make_part("lid", "lid", lid, seat_mat))
    # the seat's two hinges behind the bowl, and the caps over the floor bolts either side of the foot
    y_h = y_bowl - r * 0.86 * sy - 0.015
    for i, sx in enumerate((-1, 1)):
        parts.append(make_part(f"hinge_{i}", "hinge", S.box((0.03, 0.04, 0.02), center=(sx * 0.07, y_h, z_rim + 0.01), bevel=0.004),
                               seat_mat))
    y_b = y_bowl - 0.03 if variant != "skirted" else y_bowl - 0.05
    x_b = 0.15 * 1.0 if variant != "skirted" else r * 0.85 + 0.015
    for i, sx in enumerate((-1, 1)):
        parts.append(make_part(f"bolt_cap_{i}", "bolt_cap", S.frustum(0.014, 0.006, 0.028, center=(sx * x_b, y_b, 0), sections=10), mat))
    # the shut-off valve on the supply behind the bowl (the collision budget, 60 pieces, allows
    # one more piece)
    parts.append(make_part("valve", "valve", S.cylinder(0.012, 0.04, center=(-tank_w / 2 + 0.05, y_tank - tank_d / 2 + 0.03, 0.14),
                                                        sections=10), M.solid((0.75, 0.75, 0.77), "metal", 0.3, 0.9)))
    return parts


def _holed_top(w: float, d: float, t: float, z: float, hole_w: float, hole_d: float,
               hole_y: float) -> S.Shape:
    """A countertop slab with a rectangular cut-out (for an undermount basin)."""
    poly = shapely.box(-w / 2, -d / 2, w / 2, d / 2).difference(
        shapely.box(-hole_w / 2, hole_y - hole_d / 2, hole_w / 2, hole_y + hole_d / 2))
    mesh = trimesh.creation.extrude_polygon(poly, t)
    mesh.apply_translation((0, 0, z))
    yb, yf = hole_y - hole_d / 2, hole_y + hole_d / 2
    pieces = [S.box((w, yb + d / 2, t), center=(0, (yb - d / 2) / 2, z + t / 2)),
              S.box((w, d / 2 - yf, t), center=(0, (yf + d / 2) / 2, z + t / 2)),
              S.box(((w - hole_w) / 2, hole_d, t), center=(-(w + hole_w) / 4, hole_y, z + t / 2)),
              S.box(((w - hole_w) / 2, hole_d, t), center=((w + hole_w) / 4, hole_y, z + t / 2))]
    return S.Shape(mesh, [p.mesh for p in pieces])


@register("bathroom_vanity", parts=("countertop", "basin", "faucet"),
          extra_parts=("body", "door", "drawer", "handle", "plinth", "backsplash", "drawer_box", "hinge", "runner",
                       "trap", "valve", "glide"),
          size_range=(0.7, 1.4), density=500, variants=("vessel", "undermount", "drawers"), groups=CARCASS_GROUP)
def bathroom_vanity(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.6, 1.2)
    d = rng.uniform(0.45, 0.55)
    h = rng.uniform(0.8, 0.86)  # countertop top
    t = 0.018
    top_t = rng.uniform(0.02, 0.035)
    plinth = rng.uniform(0.06, 0.1)
    wood = M.wood(rng) if rng.random() < 0.7 else M.solid((0.94, 0.94, 0.92), "wood", 0.45)
    stone = M.stone(rng)
    chrome = M.metal(rng)
    basin_mat = _enamel(rng)
    body_h = h - top_t - plinth
    parts: list[Part] = [
        *carcass_panels(w, d, body_h, t, wood, z0=plinth, top=False),
        make_part("plinth", "plinth", S.box((w - 0.04, d - 0.05, plinth),
                                            center=(0, -0.02, plinth / 2)), wood),
        # levelling glides under the plinth's corners
        *glides((-w / 2 + 0.045, w / 2 - 0.045), (-d / 2 + 0.03, d / 2 - 0.07))]
    y_face = d / 2 + 0.018
    if variant == "drawers":
        rows = int(rng.integers(2, 4))
        z = plinth + t
        hs = (h - top_t - z) / rows
        for k in range(rows):
            zc = z + hs * (k + 0.5)
            dw_, dh_, ft, bd = w - 2 * t - 0.006, hs - 0.006, 0.018, d - 0.06 - 0.018
            parts.append(make_part(f"drawer_{k}", "drawer",
                                   bevel_box((dw_, ft, dh_), center=(0, y_face - ft / 2, zc), bevel=0.004), wood))
            parts.append(make_part(f"drawer_{k}_box", "drawer_box", S.box((dw_ - 0.014, bd, dh_ - 0.02),
                                                                          center=(0, y_face - ft - bd / 2, zc)), wood))
            parts.append(make_part(f"handle_{k}", "handle", bar_handle(
                (0, y_face, zc + hs * 0.15), min(0.3, w * 0.35)), chrome))
            parts += [prismatic(f"drawer_{k}_slide", "body", f"drawer_{k}_box", travel=DRAWER_TRAVEL * bd),
                      mount(f"drawer_{k}_box", f"drawer_{k}"), mount(f"drawer_{k}", f"handle_{k}")]
    else:
        n = 1 if w < 0.75 else 2
        dw = (w - 2 * t) / n
        dz0, dz1 = plinth + t * 0.5, h - top_t - 0.005
        for i in range(n):
            x = -w / 2 + t + dw * (i + 0.5)
            door = bevel_box((dw - 0.005, 0.018, dz1 - dz0),
                             center=(x, y_face - 0.009, (dz0 + dz1) / 2), bevel=0.004)
            parts.append(make_part(f"door_{i}", "door", door, wood))
            side = 1 if (n == 2 and i == 0) else -1
            hx = x + (dw / 2 - 0.05) * side
            parts.append(make_part(f"handle_{i}", "handle",
                                   knob((hx, y_face, dz1 - 0.08)) if rng.random() < 0.3 else
                                   bar_handle((hx, y_face, dz1 - 0.12), 0.12, vertical=True),
                                   chrome))
            xh = x - side * (dw - 0.005) / 2  # hinged on the edge away from the handle
            parts += hinge_parts(f"door_{i}_hinge", x=xh, y=y_face - 0.018, z0=dz0, z1=dz1, mat=chrome)
            parts += [revolute(f"door_{i}_hinge", "body", f"door_{i}", axis=(0, 0, 1), origin=(xh, y_face - 0.018, dz0),
                               opens=OPEN_DOOR if side == 1 else -OPEN_DOOR),
                      mount(f"door_{i}", f"handle_{i}")]
    # the countertop overhangs the front and the sides; its back is flush with the carcass's
    # (and its backsplash stands on it), as the vanity stands against the wall by its back
    ct_w, ct_d = w + 0.02, d + 0.02
    ct_y = (ct_d - d) / 2
    basin_y = 0.03
    rb = min(0.2, w * 0.3, d * 0.38)
    if variant == "undermount":
        hole_w, hole_d = rb * 2 * 1.15, rb * 2 * 0.9
        top = _holed_top(ct_w, ct_d, top_t, h - top_t, hole_w, hole_d, basin_y - ct_y).moved((0, ct_y, 0))
        depth = rng.uniform(0.14, 0.18)
        prof = [(rb * 0.55, 0.0), (rb * 0.85, depth * 0.5), (rb * 1.1, depth)]
        basin = _oval_vessel(prof, 0.015, 1.15, 0.92, h - top_t - depth).moved((0, basin_y, 0))
        spout_z = h
    else:
        top = bevel_box((ct_w, ct_d, top_t), center=(0, ct_y, h - top_t / 2), bevel=0.005)
        depth = rng.uniform(0.12, 0.16)
        rv = min(rb, 0.2)
        if rng.random() < 0.5:
            prof = [(rv * 0.45, 0.0), (rv * 0.8, depth * 0.35), (rv, depth)]
        else:
            prof = [(rv * 0.9, 0.0), (rv, depth)]
        basin = S.vessel(prof, 0.012, sections=32, piece_sections=16).moved((0, basin_y, h))
        spout_z = h
    parts.append(make_part("countertop", "countertop", top, stone))
    parts.append(make_part("basin", "basin", basin, basin_mat))
    if rng.random() < 0.6:
        parts.append(make_part("backsplash", "backsplash", bevel_box(
            (ct_w, 0.02, 0.1), center=(0, ct_y - ct_d / 2 + 0.01, h + 0.05), bevel=0.004), stone))
    y_tap = basin_y - (rb + 0.05 if variant == "undermount" else rb + 0.04)
    tall = 0.12 if variant == "undermount" else 0.12 + depth
    reach = basin_y - y_tap - 0.03
    parts.append(make_part("faucet", "faucet",
                           _faucet(0.0, y_tap, spout_z, reach, tall, towards=(0, 1, 0)), chrome))
    if variant == "drawers":  # each drawer runs on a centre runner under its box
        for k in range(rows):
            zr = plinth + t + hs * k
            parts.append(make_part(f"runner_{k}", "runner", S.box((0.025, d - 0.1, 0.006), center=(0, -0.02, zr + 0.003)), wood))
    else:  # the waste trap under the basin and the two shut-off valves on the back panel
        yb = -d / 2 + 0.03
        zt = plinth + t + body_h * 0.45
        z_under = (h - top_t - depth if variant == "undermount" else h - top_t) - 0.005
        zt = min(zt, z_under - 0.1)
        parts.append(make_part("trap", "trap", S.tube([(0, basin_y, z_under), (0, basin_y, zt), (0, yb, zt)], 0.02,
                                                      sections=10), M.solid((0.8, 0.8, 0.82), "plastic", 0.4)))
        for i, sx in enumerate((-1, 1)):
            parts.append(make_part(f"valve_{i}", "valve", S.cylinder(0.012, 0.04, center=(sx * min(0.15, w / 2 - 0.06), yb, zt + 0.1),
                                                                     axis=(0, 1, 0), sections=10), chrome))
    return parts


@register("towel_bar", parts=("bar",), extra_parts=("bracket", "set_screw", "end_cap"), size_range=(0.4, 0.9),
          density=2000, variants=("single", "double", "square"), placement="wall")
def towel_bar(rng: np.random.Generator, variant: str) -> list[Part]:
    length = rng.uniform(0.42, 0.82)
    standoff = rng.uniform(0.06, 0.08)
    z = 0.05
    mat = M.metal(rng)
    r_bar = rng.uniform(0.008, 0.012)
    span = length - rng.uniform(0.04, 0.08)  # bracket centres
    ys = (standoff,) if variant != "double" else (standoff - 0.035, standoff)
    parts: list[Part] = []
    for i, sx in enumerate((-1, 1)):
        x = sx * span / 2
        rosette = S.cylinder(0.028, 0.012, center=(x, 0.006, z), axis=(0, 1, 0), sections=16)
        arm = S.cylinder(0.011, ys[-1] + 0.01 - 0.012, center=(x, 0.012 + (ys[-1] - 0.002) / 2, z),
                         axis=(0, 1, 0), sections=10)
        cup = S.cylinder(r_bar + 0.006, 0.03, center=(x - sx * 0.005, ys[-1], z), axis=(1, 0, 0),
                         sections=12)
        parts.append(make_part(f"bracket_{i}", "bracket", [rosette, arm, cup], mat))
        # the set screw under the post that locks it on its wall plate
        parts.append(make_part(f"set_screw_{i}", "set_screw", S.cylinder(0.003, 0.004, center=(x, 0.02, z - 0.011 - 0.0015),
                                                                        sections=8), mat))
    for k, y in enumerate(ys):
        if variant == "square":
            bar = bevel_box((length, r_bar * 1.8, r_bar * 1.8), center=(0, y, z), bevel=0.002)
        else:
            bar = S.cylinder(r_bar, length, center=(0, y, z), axis=(1, 0, 0), sections=14)
        parts.append(make_part("bar" if len(ys) == 1 else f"bar_{k}", "bar", bar, mat))
        # the caps closing the bar's hollow ends
        for j, sx in enumerate((-1, 1)):
            xc = sx * (length / 2 - 0.003)
            cap = (bevel_box((0.006, r_bar * 1.8, r_bar * 1.8), center=(xc, y, z), bevel=0.001) if variant == "square"
                   else S.cylinder(r_bar, 0.006, center=(xc, y, z), axis=(1, 0, 0), sections=14))
            parts.append(make_part(f"end_cap_{2 * k + j}", "end_cap", cap, mat))
    return parts
