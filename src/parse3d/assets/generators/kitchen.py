"""Kitchen furniture and appliances: base cabinet runs, bar counters, refrigerators, stoves and
washing machines. Doors, drawer fronts, oven doors and portholes all face +Y.
"""

from __future__ import annotations

import numpy as np
import shapely
import trimesh

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._casework import black, door_parts, drawer_parts, glass_pane, knob, white
from ._dD_detail import back_screws
from ._kit import OPEN_DOOR, mount, revolute

H_COUNTER = 0.9
KICK_H, KICK_D = 0.1, 0.07


def _counter_top(w: float, d: float, z: float, thick: float, mat, *, hole=None) -> Part:
    """A countertop slab ``w x d`` with its top at ``z``; ``hole`` = (x0, x1, y0, y1) cuts a sink
    opening. The cut slab is one mesh (so its top is one connected surface) whose collision
    pieces are the four boxes around the opening."""
    zc = z - thick / 2
    if hole is None:
        return make_part("countertop", "countertop", S.box((w, d, thick), center=(0, 0, zc), bevel=0.004), mat)
    x0, x1, y0, y1 = hole
    boxes = [S.box((x0 + w / 2, d, thick), center=((x0 - w / 2) / 2, 0, zc)),
             S.box((w / 2 - x1, d, thick), center=((x1 + w / 2) / 2, 0, zc)),
             S.box((x1 - x0, y0 + d / 2, thick), center=((x0 + x1) / 2, (y0 - d / 2) / 2, zc)),
             S.box((x1 - x0, d / 2 - y1, thick), center=((x0 + x1) / 2, (y1 + d / 2) / 2, zc))]
    outline = shapely.box(-w / 2, -d / 2, w / 2, d / 2).difference(shapely.box(x0, y0, x1, y1))
    mesh = trimesh.creation.extrude_polygon(outline, thick)
    mesh.apply_translation((0, 0, z - thick))
    return make_part("countertop", "countertop", S.Shape(mesh, [p for b in boxes for p in b.pieces]), mat)


def _basin(x0: float, x1: float, y0: float, y1: float, z_top: float, depth: float, t: float) -> list[S.Shape]:
    """An open-topped rectangular sink bowl hanging below ``z_top``."""
    w, d = x1 - x0, y1 - y0
    cx, cy, zc = (x0 + x1) / 2, (y0 + y1) / 2, z_top - depth / 2
    return [S.box((w, d, t), center=(cx, cy, z_top - depth + t / 2)),
            S.box((w, t, depth - t), center=(cx, y0 + t / 2, zc + t / 2)),
            S.box((w, t, depth - t), center=(cx, y1 - t / 2, zc + t / 2)),
            S.box((t, d - 2 * t, depth - t), center=(x0 + t / 2, cy, zc + t / 2)),
            S.box((t, d - 2 * t, depth - t), center=(x1 - t / 2, cy, zc + t / 2))]


@register("kitchen_counter", parts=("countertop", "body", "door"),
          extra_parts=("drawer", "handle", "shelf", "toe_kick", "sink", "faucet", "hinge", "drawer_box", "shelf_pin", "strainer"),
          size_range=(0.85, 2.5),
          density=600, variants=("doors", "drawer_bank", "sink"))
def kitchen_counter(rng: np.random.Generator, variant: str) -> list[Part]:
    n_bays = int(rng.integers(2, 5)) if variant == "drawer_bank" else int(rng.integers(1, 5))
    bay = rng.uniform(0.5, 0.6)
    w, d, t = n_bays * bay, 0.58, 0.018
    top_t = rng.uniform(0.03, 0.04)
    oh = 0.024 + rng.uniform(0.015, 0.03)  # past the door fronts (18 mm door + 6 mm raised panel)
    z_top = H_COUNTER - top_t
    mat = M.wood(rng) if rng.random() < 0.6 else M.solid(M.jitter(rng, (0.9, 0.9, 0.88), 0.03)[:3], "wood")
    hmat = M.metal(rng)
    # the end panels are 1 cm thicker than the carcass's sides, flush with the countertop's
    # ends: units stand side by side (or against a wall) by their sides, the top a continuous run
    end_t = t + 0.01
    body = [S.box((end_t, d, z_top), center=(-w / 2 - 0.01 + end_t / 2, 0, z_top / 2)),
            S.box((end_t, d, z_top), center=(w / 2 + 0.01 - end_t / 2, 0, z_top / 2)),
            S.box((w - 2 * t, d - 0.01, t), center=(0, 0.005, KICK_H + t / 2)),
            S.box((w - 2 * t, 0.01, z_top - KICK_H - t), center=(0, -d / 2 + 0.005, (KICK_H + t + z_top) / 2)),
            S.box((w - 2 * t, 0.08, t), center=(0, d / 2 - 0.04, z_top - t / 2))]
    for i in range(1, n_bays):
        x = -w / 2 + i * bay
        body.append(S.box((t, d - 0.02, z_top - KICK_H - 2 * t), center=(x, 0.0, (KICK_H + z_top) / 2)))
    parts = [make_part("body", "body", body, mat),
             make_part("toe_kick", "toe_kick",
                       S.box((w - 2 * t, t, KICK_H), center=(0, d / 2 - KICK_D, KICK_H / 2)), black())]
    sink_bay = int(rng.integers(n_bays)) if variant == "sink" else -1
    hole = None
    y_face = d / 2
    for b in range(n_bays):
        x0, x1 = -w / 2 + b * bay + 0.002, -w / 2 + (b + 1) * bay - 0.002
        if variant == "drawer_bank" and b == n_bays - 1:
            zs = np.linspace(KICK_H, z_top, 4)
            for k in range(3):
                parts += drawer_parts(f"drawer_{b}_{k}", x0=x0, x1=x1, z0=zs[k] + 0.002, z1=zs[k + 1] - 0.002,
                                      y_front=y_face + 0.018, depth=d - 0.06, thick=0.018, mat=mat,
                                      handle_mat=hmat)
            continue
        z_door = z_top
        if b != sink_bay:
            z_door = z_top - 0.16
            parts += drawer_parts(f"drawer_{b}", x0=x0, x1=x1, z0=z_door + 0.002, z1=z_top - 0.002,
                                  y_front=y_face + 0.018, depth=d - 0.06, thick=0.018, mat=mat, handle_mat=hmat)
            zs = z_door - t
            parts.append(make_part(f"shelf_{b}", "shelf",
                                   S.box((bay - t - 0.004, d - 0.03, t),
                                         center=((x0 + x1) / 2, -0.01, (KICK_H + t + zs) / 2)), mat))
            # the four pins in the side panels' hole rows the shelf rests on
            zp = (KICK_H + t + zs) / 2 - t / 2 - 0.003
            half = (bay - t - 0.004) / 2
            xs_ = ((x0 + x1) / 2 - half + 0.005, (x0 + x1) / 2 + half - 0.005)
            parts += [make_part(f"shelf_pin_{4 * b + j}", "shelf_pin", S.cylinder(0.0025, 0.012, center=(x, y, zp), axis=(1, 0, 0), sections=8),
                                hmat) for j, (x, y) in enumerate((x, y) for x in xs_ for y in (-d * 0.35, d * 0.3))]
        else:
            cx = (x0 + x1) / 2
            hole = (cx - bay * 0.32, cx + bay * 0.32, -0.19, 0.19)
        parts += door_parts(f"door_{b}", x0=x0, x1=x1, z0=KICK_H + 0.002, z1=z_door - 0.002, y_back=y_face,
                            thick=0.018, mat=mat, handle_mat=hmat, hinge_left=b % 2 == 0,
                            style="shaker" if variant != "doors" else "flat")
        if hole is not None and b == sink_bay:
            hx0, hx1, hy0, hy1 = hole
            parts.append(make_part("sink", "sink", _basin(hx0, hx1, hy0 + oh / 2, hy1 + oh / 2, H_COUNTER - top_t,
                                                          0.18, 0.006), M.metal(rng)))
            # the basket strainer in the basin's floor, flush with it
            parts.append(make_part("strainer", "strainer", S.cylinder(0.045, 0.003, center=(cx, (hy0 + hy1) / 2 + oh / 2, H_COUNTER - top_t - 0.18 + 0.0045),
                                                                      sections=16), M.metal(rng)))
            path = [[cx, -d / 2 + 0.05, H_COUNTER], [cx, -d / 2 + 0.05, H_COUNTER + 0.3],
                    [cx, -d / 2 + 0.12, H_COUNTER + 0.36], [cx, -d / 2 + 0.2, H_COUNTER + 0.3],
                    [cx, -d / 2 + 0.21, H_COUNTER + 0.24]]
            parts.append(make_part("faucet", "faucet", [S.cylinder(0.025, 0.04, center=(cx, -d / 2 + 0.05, H_COUNTER + 0.02)),
                                                         S.tube(path, 0.012, sections=10)], M.metal(rng)))
            hole = (hx0, hx1, hy0 + oh / 2, hy1 + oh / 2)
    top_mat = M.stone(rng) if rng.random() < 0.7 else M.wood(rng)
    top = _counter_top(w + 0.02, d + oh, H_COUNTER, top_t, top_mat, hole=hole)
    for m in [top.mesh, *top.pieces]:
        m.apply_translation((0, oh / 2, 0))
    parts.insert(0, top)
    return parts


@register("bar_counter", parts=("countertop", "body"), extra_parts=("foot_rail", "shelf", "panel", "bracket", "corbel", "speed_rail",
                                                                                          "end_cap", "kick_plate", "flange", "shelf_pin"),
          size_range=(1.4, 3.3), density=600, variants=("straight", "l_shaped"))
def bar_counter(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(1.4, 2.6), rng.uniform(0.45, 0.6), rng.uniform(1.02, 1.1)
    t, top_t = 0.025, rng.uniform(0.04, 0.06)
    oh = rng.uniform(0.2, 0.3)
    mat, top_mat, steel = M.wood(rng), (M.stone(rng) if rng.random() < 0.5 else M.wood(rng)), M.metal(rng)
    zb = h - top_t
    # body: the customer wall at +Y, two ends, a plinth floor; open to the bartender at -Y
    body = [S.box((w, t, zb), center=(0, d / 2 - t / 2, zb / 2), bevel=0.003),
            S.box((t, d - t, zb), center=(-w / 2 + t / 2, -t / 2, zb / 2)),
            S.box((t, d - t, zb), center=(w / 2 - t / 2, -t / 2, zb / 2)),
            S.box((w - 2 * t, d - t, t), center=(0, -t / 2, 0.08 + t / 2))]
    parts = [make_part("body", "body", body, mat),
             make_part("shelf", "shelf", S.box((w - 2 * t, d - t - 0.02, t), center=(0, -t / 2 - 0.01, zb * 0.55)),
                       mat)]
    x_right = w / 2 + 0.02
    ry, rz = d / 2 + 0.2, 0.22
    rail_path = [[-w / 2 + 0.06, ry, rz], [w / 2 - 0.06, ry, rz]]
    supports = [((x, ry, rz), (0.0, -0.2)) for x in np.linspace(-w / 2 + 0.15, w / 2 - 0.15, 3)]
    if variant == "l_shaped":
        lw = rng.uniform(0.8, 1.3)  # the return runs back toward -Y at the +X end
        xc, y_end = w / 2 - d / 2, -d / 2 - lw
        ret = [S.box((t, lw, zb), center=(w / 2 - t / 2, -d / 2 - lw / 2, zb / 2), bevel=0.003),
               S.box((d - t, t, zb), center=(xc - t / 2, y_end + t / 2, zb / 2)),
               S.box((d - t, lw - t, t), center=(xc - t / 2, -d / 2 - (lw - t) / 2, 0.08 + t / 2))]
        parts.append(make_part("panel", "panel", ret, mat))
        x_right = w / 2 + oh
        rx = w / 2 + 0.2
        rail_path = [[-w / 2 + 0.06, ry, rz], [rx, ry, rz], [rx, y_end + 0.06, rz]]
        supports.append(((rx, y_end + lw / 2, rz), (-0.2, 0.0)))
    main_top = S.box((x_right + w / 2 + 0.02, d + oh, top_t), center=((x_right - w / 2 - 0.02) / 2, oh / 2, h - top_t / 2),
                     bevel=0.006 if variant != "l_shaped" else 0.0)
    if variant == "l_shaped":  # one slab (one connected top surface), covered by two boxes
        xa, xb, xr = -w / 2 - 0.02, x_right, w / 2 - d
        y0, ym, y1 = y_end, -d / 2, d / 2 + oh
        outline = shapely.Polygon([(xa, ym), (xr, ym), (xr, y0), (xb, y0), (xb, y1), (xa, y1)])
        mesh = trimesh.creation.extrude_polygon(outline, top_t)
        mesh.apply_translation((0, 0, h - top_t))
        top_ret = S.box((xb - xr, ym - y0, top_t), center=((xr + xb) / 2, (y0 + ym) / 2, h - top_t / 2))
        main_top = S.Shape(mesh, main_top.pieces + top_ret.pieces)
    parts.insert(0, make_part("countertop", "countertop", main_top, top_mat))
    parts.append(make_part("foot_rail", "foot_rail", S.tube(rail_path, 0.025, sections=12), steel))
    # the brackets holding the foot rail off the customer wall, each its own
    parts += [make_part(f"bracket_{k}", "bracket", S.tube([p, (p[0] + dx, p[1] + dy, rz + 0.04)], 0.012, sections=8), steel)
              for k, (p, (dx, dy)) in enumerate(supports)]
    # corbels under the top's overhang on the customer side, and the bartender's speed rail of
    # bottles hung on the inside of the customer wall
    parts += [make_part(f"corbel_{k}", "corbel", S.prism([(0, 0), (oh - 0.03, 0), (0, -0.2)], 0, 0.03).apply(
        np.array([[0, 0, 1, x - 0.015], [1, 0, 0, d / 2], [0, 1, 0, zb], [0, 0, 0, 1.0]])), mat)
              for k, x in enumerate(np.linspace(-w / 2 + 0.2, w / 2 - 0.2, 3))]
    parts.append(make_part("speed_rail", "speed_rail", [S.box((w * 0.5, 0.1, 0.006), center=(-w * 0.2, d / 2 - t - 0.05, zb * 0.6)),
                                                        S.box((w * 0.5, 0.006, 0.06), center=(-w * 0.2, d / 2 - t - 0.1, zb * 0.6 + 0.027))],
                           steel))
    # the foot rail's two domed end caps, the steel kick plate along the customer wall's foot
    # and the bartender's lower shelf just above the plinth floor
    ends = [np.asarray(rail_path[0], float), np.asarray(rail_path[-1], float)]
    dirs = [ends[0] - np.asarray(rail_path[1], float), ends[1] - np.asarray(rail_path[-2], float)]
    for k, (e, u) in enumerate(zip(ends, dirs, strict=True)):
        u = u / np.linalg.norm(u)
        parts.append(make_part(f"end_cap_{k}", "end_cap", S.cylinder(0.027, 0.02, center=tuple(e + u * 0.008), axis=tuple(u), sections=12), steel))
    parts.append(make_part("kick_plate", "kick_plate", S.box((w - 0.01, 0.003, 0.15), center=(0, d / 2 + 0.0015, 0.075)), steel))
    parts.append(make_part("shelf_1", "shelf", S.box((w - 2 * t, d - t - 0.02, t), center=(0, -t / 2 - 0.01, zb * 0.25)), mat))
    # the round flange screwing each foot-rail bracket to the customer wall (or the return's end)
    for k, (p, (dx, dy)) in enumerate(supports):
        u = np.array([dx, dy, 0.0]) / np.hypot(dx, dy)
        c = np.array([p[0] + dx, p[1] + dy, rz + 0.04]) - u * 0.003
        parts.append(make_part(f"flange_{k}", "flange", S.cylinder(0.03, 0.006, center=tuple(c), axis=tuple(u), sections=12), steel))
    # the four pins in the end panels each shelf rests on, under its corners
    ys = (-t / 2 - 0.01 - (d - t - 0.02) / 2 + 0.04, -t / 2 - 0.01 + (d - t - 0.02) / 2 - 0.04)
    for i, zs in enumerate((zb * 0.55, zb * 0.25)):
        parts += [make_part(f"shelf_pin_{4 * i + j}", "shelf_pin",
                            S.cylinder(0.0025, 0.012, center=(sx * (w / 2 - t - 0.006), y, zs - t / 2 - 0.0025), axis=(1, 0, 0), sections=8),
                            steel) for j, (sx, y) in enumerate((sx, y) for sx in (-1, 1) for y in ys)]
    return parts


@register("refrigerator", parts=("body", "door", "shelf"), extra_parts=("handle", "freezer_door", "drawer", "hinge", "light",
                                                                     "thermostat", "gasket", "toe_grille", "hinge_cover",
                                                                     "dispenser", "trim", "shelf_support"),
          size_range=(1.4, 2.0), density=300, variants=("single", "top_freezer", "side_by_side"))
def refrigerator(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.8, 0.92) if variant == "side_by_side" else rng.uniform(0.55, 0.75)
    d, h = rng.uniform(0.6, 0.72), rng.uniform(1.45, 1.9)
    t, dt, gap = 0.04, 0.06, 0.004
    shell = white(rng) if rng.random() < 0.6 else M.metal(rng)
    liner = M.solid((0.94, 0.95, 0.96), "plastic", 0.4)
    hmat = M.metal(rng)
    db = d - dt  # cabinet depth behind the doors
    yb, yf = -d / 2, d / 2 - dt
    body = [S.box((t, db, h), center=(-w / 2 + t / 2, (yb + yf) / 2, h / 2), bevel=0.006),
            S.box((t, db, h), center=(w / 2 - t / 2, (yb + yf) / 2, h / 2), bevel=0.006),
            S.box((w - 2 * t, db, t), center=(0, (yb + yf) / 2, h - t / 2)),
            S.box((w - 2 * t, db, 0.08), center=(0, (yb + yf) / 2, 0.04)),
            S.box((w - 2 * t, t, h - t - 0.08), center=(0, yb + t / 2, (h - t + 0.08) / 2))]
    iw, y0, y1 = w - 2 * t, yb + t, yf - 0.01
    z_lo, z_hi = 0.08, h - t
    parts = []
    x_mid = 0.0
    if variant == "top_freezer":
        z_split = h - rng.uniform(0.38, 0.48)
        body.append(S.box((iw, db, t), center=(0, (yb + yf) / 2, z_split - t / 2)))
        parts += door_parts("freezer_door", x0=-w / 2, x1=w / 2, z0=z_split + gap, z1=h, y_back=yf, thick=dt,
                            mat=shell, handle_mat=hmat, hinge_left=True, style="flat", handle_len=0.25,
                            label="freezer_door")
        parts += door_parts("door", x0=-w / 2, x1=w / 2, z0=0.0, z1=z_split - gap, y_back=yf, thick=dt,
                            mat=shell, handle_mat=hmat, hinge_left=True, style="flat", handle_len=0.45)
        z_hi = z_split - t
    elif variant == "side_by_side":
        fw = w * rng.uniform(0.38, 0.45)
        xs = -w / 2 + fw
        body.append(S.box((t, db, h - t - 0.08), center=(xs, (yb + yf) / 2, (h - t + 0.08) / 2)))
        parts += door_parts("freezer_door", x0=-w / 2, x1=xs - gap, z0=0.0, z1=h, y_back=yf, thick=dt,
                            mat=shell, handle_mat=hmat, hinge_left=False, style="flat", handle_len=0.7,
                            label="freezer_door")
        parts += door_parts("door", x0=xs + gap, x1=w / 2, z0=0.0, z1=h, y_back=yf, thick=dt,
                            mat=shell, handle_mat=hmat, hinge_left=True, style="flat", handle_len=0.7)
        iw = w / 2 - t - xs - t / 2
        x_mid = (xs + t / 2 + w / 2 - t) / 2
    else:
        parts += door_parts("door", x0=-w / 2, x1=w / 2, z0=0.0, z1=h, y_back=yf, thick=dt,
                            mat=shell, handle_mat=hmat, hinge_left=True, style="flat", handle_len=0.6)
    parts.insert(0, make_part("body", "body", body, shell))
    n = int(np.clip(np.floor((z_hi - z_lo) / 0.3), 2, 5))
    levels = z_lo + (z_hi - z_lo) * np.arange(1, n) / n
    glass = glass_pane(rng)
    for i, z in enumerate(levels):
        parts.append(make_part(f"shelf_{i}", "shelf",
                               S.box((iw - 0.004, y1 - y0, 0.008), center=(x_mid, (y0 + y1) / 2, z - 0.004)), glass))
        # the plastic trim along the glass's front edge (flush with its top) and the two rails
        # moulded in the liner's side walls it rests on
        parts.append(make_part(f"shelf_{i}_trim", "trim",
                               S.box((iw - 0.004, 0.008, 0.014), center=(x_mid, y1 + 0.004, z - 0.007)), liner))
        parts += [make_part(f"shelf_{i}_support_{j}", "shelf_support",
                            S.box((0.012, y1 - y0 - 0.04, 0.01), center=(x_mid + sx * (iw / 2 - 0.006), (y0 + y1) / 2 - 0.01, z - 0.013)),
                            liner) for j, sx in enumerate((-1, 1))]
    crisper = S.union([S.box((iw - 0.02, y1 - y0 - 0.02, 0.006), center=(x_mid, (y0 + y1) / 2, z_lo + 0.003)),
                       S.box((iw - 0.02, 0.01, 0.16), center=(x_mid, y1 - 0.015, z_lo + 0.08))])
    parts.append(make_part("drawer", "drawer", crisper, liner))
    # the lamp and the thermostat dial in the top of the fresh-food compartment
    parts.append(make_part("light", "light", S.box((0.08, 0.04, 0.012), center=(x_mid, y0 + 0.08, z_hi - 0.006)),
                           M.solid((1.0, 0.98, 0.9), "glass", 0.1)))
    parts.append(make_part("thermostat", "thermostat", S.cylinder(0.018, 0.012, center=(x_mid + iw * 0.25, y0 + 0.1, z_hi - 0.006),
                                                                  sections=12), liner))
    # the toe grille over the compressor's air inlet at the front foot, the cover over each
    # door's top hinge on the cabinet's top, and on a side-by-side the water and ice
    # dispenser let into the freezer door
    parts.append(make_part("toe_grille", "toe_grille", S.box((w - 2 * t, 0.006, 0.07), center=(0, yf - 0.003, 0.04)), black()))
    hinge_x = {"single": [-w / 2 + 0.04], "top_freezer": [-w / 2 + 0.04], "side_by_side": [-w / 2 + 0.04, w / 2 - 0.04]}[variant]
    parts += [make_part(f"hinge_cover_{k}", "hinge_cover", S.box((0.06, 0.08, 0.012), center=(x, yf - 0.035, h - 0.006 + 0.0), bevel=0.003),
                        shell) for k, x in enumerate(hinge_x)]
    if variant == "side_by_side":
        fw_c = (-w / 2 + xs - gap) / 2
        parts.append(make_part("dispenser", "dispenser", S.box((fw * 0.6, 0.012, 0.3), center=(fw_c, yf + dt + 0.006 - 0.012, h * 0.55)),
                               black()))
        parts.append(mount("freezer_door", "dispenser"))
    return parts + _door_gaskets(parts)


def _door_gaskets(parts: list) -> list:
    """The magnetic rubber gasket round the back of each refrigerator door, pressed against the
    cabinet's front edge when the door is shut (mounted on the door, so it swings with it)."""
    rubber = M.solid((0.85, 0.86, 0.86), "rubber", 0.8)
    out: list = []
    for door in [p for p in parts if isinstance(p, Part) and p.label in ("door", "freezer_door")]:
        (x0, y0, z0), (x1, _, z1) = door.bounds
        b, t, m = 0.02, 0.006, 0.012  # band width, thickness, inset from the door's edge
        y = y0 - t / 2
        frame = [S.box((x1 - x0 - 2 * m, t, b), center=((x0 + x1) / 2, y, z0 + m + b / 2)),
                 S.box((x1 - x0 - 2 * m, t, b), center=((x0 + x1) / 2, y, z1 - m - b / 2)),
                 S.box((b, t, z1 - z0 - 2 * m - 2 * b), center=(x0 + m + b / 2, y, (z0 + z1) / 2)),
                 S.box((b, t, z1 - z0 - 2 * m - 2 * b), center=(x1 - m - b / 2, y, (z0 + z1) / 2))]
        name = f"{door.name}_gasket"
        out += [make_part(name, "gasket", frame, rubber), mount(door.name, name)]
    return out


def _ring_path(center, radius: float, n: int, *, plane: str = "xy") -> np.ndarray:
    a = np.linspace(0, 2 * np.pi, n, endpoint=False)
    c = np.asarray(center, float)
    if plane == "xy":
        return c + np.c_[radius * np.cos(a), radius * np.sin(a), np.zeros(n)]
    return c + np.c_[radius * np.cos(a), np.zeros(n), radius * np.sin(a)]


@register("stove", parts=("body", "cooktop", "burner"),
          extra_parts=("door", "handle", "knob", "window", "drawer", "backguard", "hinge", "drawer_box", "display", "indicator",
                       "vent", "screw"), size_range=(0.85, 1.15),
          density=400, variants=("gas", "electric", "double_oven"))
def stove(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.5, 0.76), rng.uniform(0.6, 0.66)
    h_body, top_t = 0.88, 0.02
    enamel = white(rng) if rng.random() < 0.4 else M.metal(rng)
    hmat = M.metal(rng)
    cook_mat = M.metal(rng) if variant == "gas" else black("glass")
    parts = [make_part("body", "body", S.box((w, d, h_body), center=(0, 0, h_body / 2), bevel=0.004), enamel),
             make_part("cooktop", "cooktop", S.box((w, d, top_t), center=(0, 0, h_body + top_t / 2), bevel=0.003),
                       cook_mat)]
    z = h_body + top_t
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        c = (sx * w / 4, sy * d / 4 - 0.02, z)
        r = rng.uniform(0.07, 0.1) if (i % 3 == 0) else rng.uniform(0.055, 0.075)
        if variant == "gas":
            shapes = [S.cylinder(0.035, 0.025, center=(c[0], c[1], z + 0.0125), sections=16),
                      S.tube(_ring_path((c[0], c[1], z + 0.03), r, 8), 0.005, sections=6, closed=True)]
            mat = black("metal")
        else:
            shapes = [S.cylinder(r, 0.003, center=(c[0], c[1], z + 0.0015), sections=24),
                      S.tube(_ring_path((c[0], c[1], z + 0.004), r * 0.7, 8), 0.003, sections=6, closed=True)]
            mat = M.solid((0.25, 0.25, 0.27), "metal", 0.5, 0.5)
        parts.append(make_part(f"burner_{i}", "burner", shapes, mat))
    if rng.random() < 0.5:
        bg = S.box((w, 0.04, rng.uniform(0.08, 0.15)), center=(0, -d / 2 + 0.02, 0), bevel=0.004)
        bz = bg.mesh.bounds
        bg = bg.moved((0, 0, z - bz[0, 2]))
        parts.append(make_part("backguard", "backguard", bg, enamel))
    yf = d / 2
    for i, x in enumerate(np.linspace(-w / 2 + 0.08, w / 2 - 0.08, 4)):
        parts.append(make_part(f"knob_{i}", "knob", knob((x, yf, h_body - 0.05), 0.018, 0.025), black()))
    ovens = [(0.12, 0.45), (0.47, 0.79)] if variant == "double_oven" else [(0.12, 0.79)]
    for k, (z0, z1) in enumerate(ovens):
        name = "door" if len(ovens) == 1 else f"door_{k}"
        parts += door_parts(name, x0=-w / 2 + 0.01, x1=w / 2 - 0.01, z0=z0, z1=z1, y_back=yf, thick=0.03,
                            mat=enamel, handle_mat=hmat, hinge_left=True, style="flat",
                            handle_len=w * 0.75, handle_at="top")
        wh = (z1 - z0) * 0.45
        parts.append(make_part(f"window_{k}", "window",
                               S.box((w * 0.6, 0.004, wh), center=(0, yf + 0.031, (z0 + z1) / 2 - 0.02)), black("glass")))
    if variant != "double_oven":
        parts += drawer_parts("drawer", x0=-w / 2 + 0.01, x1=w / 2 - 0.01, z0=0.02, z1=0.11, y_front=yf + 0.02,
                              depth=d - 0.12, thick=0.02, mat=enamel, handle_mat=hmat)
    # the oven clock between the middle knobs, the hot-surface and oven-on lights above it, and the oven's vent slot along the cooktop's back edge (flush with it)
    zk = h_body - 0.05
    parts.append(make_part("display", "display", S.box((0.07, 0.003, 0.025), center=(0, yf + 0.0015, zk)), black("glass")))
    parts += [make_part(f"indicator_{k}", "indicator", S.cylinder(0.004, 0.003, center=(sx * 0.025, yf + 0.0015, zk + 0.027), axis=(0, 1, 0),
                                                                  sections=8), M.solid((0.95, 0.4, 0.1), "glass", 0.2))
              for k, sx in enumerate((-1, 1))]
    parts.append(make_part("vent", "vent", S.box((w * 0.5, 0.03, 0.002), center=(0, -d / 2 + 0.06, z - 0.0009)), black()))
    # the four screws holding the back panel at its corners
    parts += back_screws("screw", x0=-w / 2, x1=w / 2, z0=0.0, z1=h_body, y=-d / 2, inset=0.03)
    return parts


@register("washing_machine", parts=("body", "door"), extra_parts=("control_panel", "knob", "window", "drawer",
                                                                   "display", "foot", "hinge", "button", "gasket", "filter_cover",
                                                                   "handle", "lid_lock", "dispenser", "screw"),
          size_range=(0.8, 1.0), density=250, variants=("front_loader", "top_loader"))
def washing_machine(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.58, 0.62), rng.uniform(0.52, 0.64), rng.uniform(0.82, 0.88)
    enamel = white(rng) if rng.random() < 0.8 else M.solid((0.3, 0.31, 0.33), "metal", 0.4, 0.4)
    trim = M.solid((0.75, 0.76, 0.78), "plastic", 0.35) if rng.random() < 0.5 else black()
    fz = 0.015
    parts = [make_part("body", "body", S.box((w, d, h - fz), center=(0, 0, fz + (h - fz) / 2), bevel=0.012), enamel)]
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        parts.append(make_part(f"foot_{i}", "foot",
                               S.cylinder(0.02, fz + 0.002, center=(sx * (w / 2 - 0.05), sy * (d / 2 - 0.05), (fz + 0.002) / 2),
                                          sections=12), black()))
    yf = d / 2
    if variant == "front_loader":
        panel = S.box((w - 0.02, 0.012, 0.11), center=(0, yf + 0.004, h - 0.07), bevel=0.003)
        parts.append(make_part("control_panel", "control_panel", panel, trim))
        parts.append(make_part("drawer", "drawer", S.box((0.16, 0.014, 0.07), center=(-w / 2 + 0.1, yf + 0.011, h - 0.07),
                                                          bevel=0.003), enamel))
        parts.append(make_part("knob", "knob", knob((w / 2 - 0.1, yf + 0.01, h - 0.07), 0.026, 0.025), trim))
        parts.append(make_part("display", "display", S.box((0.1, 0.006, 0.04), center=(0.02, yf + 0.012, h - 0.07)),
                               black("glass")))
        r, zc = rng.uniform(0.15, 0.19), rng.uniform(0.4, 0.46)
        ring = S.tube(_ring_path((0, yf + 0.025, zc), r, 12, plane="xz"), 0.025, sections=8, closed=True)
        parts.append(make_part("door", "door", ring, trim))
        parts.append(make_part("window", "window", S.cylinder(r - 0.01, 0.02, center=(0, yf + 0.015, zc), axis=(0, 1, 0),
                                                               sections=24), glass_pane(rng)))
        xh = -r - 0.025  # the porthole swings open on its left edge
        parts += [make_part("hinge", "hinge", S.box((0.03, 0.03, 0.08), center=(xh, yf + 0.012, zc)), trim),
                  revolute("door_hinge", "body", "door", axis=(0, 0, 1), origin=(xh, yf, zc), opens=OPEN_DOOR),
                  mount("door", "window")]
        # the rubber boot sealing the drum's mouth round the porthole, the door's pull, the pump
        # filter's flap low on the front, and the programme buttons beside the display
        parts.append(make_part("gasket", "gasket", S.cylinder(r - 0.005, 0.004, center=(0, yf + 0.002, zc), axis=(0, 1, 0), sections=24),
                               M.solid((0.25, 0.25, 0.27), "rubber", 0.8)))
        parts.append(make_part("handle", "handle", S.box((0.03, 0.025, 0.09), center=(r + 0.02, yf + 0.035, zc), bevel=0.005), trim))
        parts.append(mount("door", "handle"))
        parts.append(make_part("filter_cover", "filter_cover", S.box((0.12, 0.006, 0.1), center=(w / 2 - 0.1, yf + 0.003, 0.09),
                                                                      bevel=0.003), enamel))
        parts += [make_part(f"button_{k}", "button", S.box((0.018, 0.008, 0.012), center=(0.1 + 0.025 * k, yf + 0.012, h - 0.07)),
                            black()) for k in range(3)]
    else:
        console = S.box((w, 0.11, 0.12), center=(0, -d / 2 + 0.055, h + 0.06 - 0.01), bevel=0.01)
        parts.append(make_part("control_panel", "control_panel", console, enamel))
        parts.append(make_part("knob", "knob", knob((w / 2 - 0.1, -d / 2 + 0.11, h + 0.06), 0.026, 0.025), trim))
        parts.append(make_part("display", "display", S.box((0.12, 0.006, 0.04), center=(0, -d / 2 + 0.112, h + 0.06)),
                               black("glass")))
        lid = S.box((w - 0.06, d - 0.16, 0.02), center=(0, 0.04, h + 0.01), bevel=0.006)
        parts.append(make_part("door", "door", lid, trim))
        parts.append(make_part("window", "window", S.box((w * 0.5, (d - 0.16) * 0.5, 0.004), center=(0, 0.04, h + 0.021)),
                               glass_pane(rng)))
        yh = 0.04 - (d - 0.16) / 2  # the lid lifts on its back edge, against the console
        parts += [revolute("door_hinge", "body", "door", axis=(1, 0, 0), origin=(0, yh, h), opens=np.pi / 2),
                  mount("door", "window")]
        # the lid's finger pull at its front edge and the programme buttons on the console
        parts.append(make_part("handle", "handle", S.box((0.12, 0.015, 0.012), center=(0, 0.04 + (d - 0.16) / 2 + 0.0075, h + 0.014)),
                               trim))
        parts.append(mount("door", "handle"))
        parts += [make_part(f"button_{k}", "button", S.box((0.018, 0.008, 0.012), center=(-w / 2 + 0.08 + 0.025 * k, -d / 2 + 0.114, h + 0.06)),
                            black()) for k in range(3)]
        # the lid lock's catch in the body's top beside the lid's front edge, and the bleach and
        # softener dispensers in the top's front corners, under the lid
        parts.append(make_part("lid_lock", "lid_lock", S.box((0.03, 0.012, 0.004), center=(0.09, 0.04 + (d - 0.16) / 2 + 0.012, h - 0.0019)),
                               black()))
        parts += [make_part(f"dispenser_{k}", "dispenser", S.cylinder(0.025, 0.004, center=(sx * (w / 2 - 0.07), 0.04 + (d - 0.16) / 2 - 0.04,
                                                                                             h - 0.0019), sections=12), trim)
                  for k, sx in enumerate((-1, 1))]
    # the four screws holding the back panel at its corners
    parts += back_screws("screw", x0=-w / 2, x1=w / 2, z0=fz, z1=h, y=-d / 2, inset=0.04)
    return parts
