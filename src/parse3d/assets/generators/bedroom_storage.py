"""Bedroom case goods: nightstands, dressers and wardrobes.

All three are open-fronted carcasses (``body``) whose drawer fronts and doors face +Y. Drawers
(``drawer_k``, numbered bottom-up, left to right) carry a ``handle`` (bow handle or knob).
Wardrobes hold ``shelf`` boards and a hanging ``rod`` behind closed hinged or sliding doors, so
their shelves get internal support surfaces.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Material, Part, make_part
from ..registry import register
from ._bedbath_common import CARCASS_GROUP, bar_handle, bevel_box, carcass_panels, knob
from ._dB_case import cams, glides, wall_strap
from ._kit import DRAWER_TRAVEL, OPEN_DOOR, hinge_parts, mount, prismatic, revolute


def _pull(rng: np.random.Generator, center, width: float, style: str) -> S.Shape:
    if style == "knob":
        return knob(center, radius=rng.uniform(0.011, 0.016))
    return bar_handle(center, min(0.16, width * 0.45), radius=0.0055)


def _drawer_grid(rng: np.random.Generator, *, x0: float, x1: float, z0: float, z1: float,
                 rows: list[int], y_face: float, depth: float, mat: Material,
                 pull_mat: Material, style: str, start: int = 0, gap: float = 0.006,
                 weights: list[float] | None = None, panel_below: bool = False) -> list[Part | Joint]:
    """Drawers filling the front rectangle [x0, x1] x [z0, z1], row by row from the bottom.

    ``rows[i]`` is the number of drawers side by side in row ``i``; ``weights`` the relative
    row heights. Each drawer is its front (``drawer_k``, label ``drawer``) on an open box
    (``drawer_k_box``, label ``drawer_box``, open at the top) sliding out of the ``body`` on a prismatic joint,
    the front mounted on the box, the handle and its backplate (``backplate_k``) on the front.
    The case's web frame is modelled too: each drawer rides on a centre guide (``runner_k``,
    label ``runner``) under its box, a dust panel (``dust_panel_k``) separates each row from the
    one above (and the lowest row from the open space below it with ``panel_below``), and a
    divider (``divider_k``) stands between drawers side by side.
    """
    weights = weights or [1.0] * len(rows)
    hs = np.asarray(weights) / np.sum(weights) * (z1 - z0)
    parts: list[Part | Joint] = []
    k = start
    z = z0
    bd = max(depth - 0.018, 0.05)
    y_web = y_face - 0.018 - bd / 2
    n_div = n_dust = 0
    for i, (n, h) in enumerate(zip(rows, hs, strict=True)):
        w = (x1 - x0) / n
        if i > 0 or panel_below:  # the dust panel under this row, in the 13 mm clearance under the boxes
            parts.append(make_part(f"dust_panel_{n_dust}", "dust_panel",
                                   S.box((x1 - x0, bd, 0.006), center=((x0 + x1) / 2, y_web, z - 0.003)), mat))
            n_dust += 1
        top_gap = 0.006 if i < len(rows) - 1 else 0.0
        for j in range(1, n):
            parts.append(make_part(f"divider_{n_div}", "divider",
                                   S.box((0.008, bd, h - top_gap), center=(x0 + w * j, y_web, z + (h - top_gap) / 2)), mat))
            n_div += 1
        for j in range(n):
            x = x0 + w * (j + 0.5)
            zc = z + h / 2
            dw, dh, ft = w - gap, h - gap, 0.018
            front = bevel_box((dw, ft, dh), center=(x, y_face - ft / 2, zc), bevel=0.004)
            bd = max(depth - ft, 0.05)
            # an open-topped box (floor, sides, back) with slide clearance: its floor holds
            # what is put IN the drawer
            bw, bh, t = dw - 0.006, dh - 0.02, 0.012
            yc, bz0 = y_face - ft - bd / 2, zc - bh / 2
            box_ = [S.box((bw, bd, t), center=(x, yc, bz0 + t / 2)),
                    S.box((t, bd, bh - t), center=(x - bw / 2 + t / 2, yc, bz0 + t + (bh - t) / 2)),
                    S.box((t, bd, bh - t), center=(x + bw / 2 - t / 2, yc, bz0 + t + (bh - t) / 2)),
                    S.box((bw - 2 * t, t, bh - t), center=(x, yc - bd / 2 + t / 2, bz0 + t + (bh - t) / 2))]
            parts.append(make_part(f"drawer_{k}", "drawer", front, mat))
            parts.append(make_part(f"drawer_{k}_box", "drawer_box", box_, mat))
            pull_z = zc + (h * 0.2 if h > 0.22 else 0.0)
            parts.append(make_part(f"handle_{k}", "handle",
                                   _pull(rng, (x, y_face, pull_z), w, style), pull_mat))
            if style == "knob":
                plate = S.cylinder(0.02, 0.003, center=(x, y_face + 0.0015, pull_z), axis=(0, 1, 0), sections=12)
            else:
                plate = bevel_box((min(0.16, w * 0.45) + 0.03, 0.003, 0.03), center=(x, y_face + 0.0015, pull_z),
                                  bevel=0.001)
            parts.append(make_part(f"backplate_{k}", "backplate", plate, pull_mat))
            parts.append(make_part(f"runner_{k}", "runner",
                                   S.box((0.025, bd, 0.008), center=(x, yc, z + 0.004)), mat))
            # the plastic shoe under the box's back that straddles the runner
            parts.append(make_part(f"drawer_guide_{k}", "drawer_guide",
                                   S.box((0.045, 0.04, 0.004), center=(x, yc - bd / 2 + 0.03, bz0 - 0.002)),
                                   M.solid((0.9, 0.9, 0.88), "plastic", 0.5)))
            parts += [prismatic(f"drawer_{k}_slide", "body", f"drawer_{k}_box", travel=DRAWER_TRAVEL * bd),
                      mount(f"drawer_{k}_box", f"drawer_{k}"), mount(f"drawer_{k}", f"handle_{k}"),
                      mount(f"drawer_{k}", f"backplate_{k}"), mount(f"drawer_{k}_box", f"drawer_guide_{k}")]
            k += 1
        z += h
    return parts


def _legs(rng: np.random.Generator, w: float, d: float, h_leg: float, mat: Material,
          *, splay: bool) -> list[Part]:
    parts = []
    r = rng.uniform(0.015, 0.022)
    brass = Material(M.jitter(rng, (0.78, 0.62, 0.3), 0.03), 0.3, 0.9, "metal")
    for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1))):
        top = np.array([sx * (w / 2 - 0.05), sy * (d / 2 - 0.05), h_leg + 0.01])
        foot = top + [sx * 0.03, sy * 0.03, 0] if splay else top.copy()
        foot[2] = 0.0
        shape = S.frustum(r * 0.6, r, h_leg + 0.01, center=foot, axis=top - foot, sections=10)
        parts.append(make_part(f"leg_{i}", "leg", shape, mat))
        # the brass ferrule capping the leg's foot (the leg still reaches the floor)
        axis = (top - foot) / np.linalg.norm(top - foot)
        parts.append(make_part(f"ferrule_{i}", "ferrule", S.frustum(r * 0.62, r * 0.7, 0.03, center=foot, axis=axis, sections=10),
                               brass))
    return parts


def _case_top(w: float, d: float, z: float, t: float, mat: Material, *, side: float = 0.01,
              front: float = 0.015) -> Part:
    """The ``top_panel`` of a ``w`` x ``d`` case at height ``z``, ``t`` thick: it overhangs
    both sides by ``side`` and the front by ``front`` (metres) and is flush with the back, as
    on a chest made to stand against a wall by its back (``body@back``)."""
    return make_part("top_panel", "top_panel",
                     bevel_box((w + 2 * side, d + front, t), center=(0, front / 2, z + t / 2),
                               bevel=min(0.006, t / 3)),
                     mat)


@register("nightstand", parts=("body", "top_panel", "drawer"),
          extra_parts=("handle", "shelf", "leg", "plinth", "drawer_box", "ferrule", "backplate", "runner",
                       "dust_panel", "divider", "shelf_pin", "drawer_guide", "glide"), size_range=(0.4, 0.75),
          density=450, variants=("two_drawer", "drawer_shelf", "legged"), groups=CARCASS_GROUP)
def nightstand(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w = rng.uniform(0.42, 0.6)
    d = rng.uniform(0.35, 0.45)
    h = rng.uniform(0.5, 0.66)
    t = rng.uniform(0.016, 0.02)
    top_t = rng.uniform(0.02, 0.03)
    mat = M.wood(rng)
    pull_mat = M.metal(rng)
    style = "knob" if rng.random() < 0.4 else "bar"
    z0 = rng.uniform(0.18, 0.25) if variant == "legged" else 0.05
    body_h = h - top_t - z0
    parts: list[Part] = []
    parts += carcass_panels(w, d, body_h, t, mat, z0=z0, top=False)
    parts.append(_case_top(w, d, h - top_t, top_t, mat))
    if variant == "legged":
        parts += _legs(rng, w, d, z0, mat, splay=True)
    else:
        parts.append(make_part("plinth", "plinth",
                               S.box((w - 0.04, d - 0.04, z0), center=(0, -0.01, z0 / 2)), mat))
        parts += glides((-w / 2 + 0.035, w / 2 - 0.035), (-d / 2 + 0.025, d / 2 - 0.045))
    y_face = d / 2 + 0.018
    x0, x1 = -w / 2 + t, w / 2 - t
    inner_top = h - top_t
    depth = d - 0.03
    if variant == "drawer_shelf":
        dh = body_h * rng.uniform(0.32, 0.4)
        parts += _drawer_grid(rng, x0=x0, x1=x1, z0=inner_top - dh, z1=inner_top, rows=[1],
                              y_face=y_face, depth=depth, mat=mat, pull_mat=pull_mat, style=style,
                              panel_below=True)
        z_shelf = z0 + t + (inner_top - dh - z0 - t) * 0.5
        shelf = S.box((w - 2 * t, d - 0.02, t), center=(0, -0.005, z_shelf))
        parts.append(make_part("shelf", "shelf", shelf, mat))
        # the four pins in the side panels the shelf rests on, under its corners
        parts += [make_part(f"shelf_pin_{k}", "shelf_pin", S.cylinder(0.0025, 0.012, center=(sx * (w / 2 - t - 0.004), sy * d * 0.3, z_shelf - t / 2 - 0.003),
                                                                      axis=(1, 0, 0), sections=8), pull_mat)
                  for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)])]
    else:
        n = 2 if variant == "two_drawer" else int(rng.integers(1, 3))
        parts += _drawer_grid(rng, x0=x0, x1=x1, z0=z0 + t, z1=inner_top, rows=[1] * n,
                              y_face=y_face, depth=depth, mat=mat, pull_mat=pull_mat, style=style)
    return parts


@register("dresser", parts=("body", "top_panel", "drawer"),
          extra_parts=("handle", "leg", "plinth", "drawer_box", "ferrule", "backplate", "runner", "dust_panel",
                       "divider", "drawer_guide", "glide", "wall_strap"), size_range=(0.75, 1.8), density=450,
          variants=("wide", "tall", "mixed"), groups=CARCASS_GROUP)
def dresser(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    if variant == "tall":
        w, h = rng.uniform(0.7, 0.95), rng.uniform(1.1, 1.35)
        rows = [1] * int(rng.integers(5, 7))
    elif variant == "wide":
        w, h = rng.uniform(1.2, 1.6), rng.uniform(0.75, 0.9)
        rows = [2] * int(rng.integers(3, 5))
    else:
        w, h = rng.uniform(0.9, 1.3), rng.uniform(0.8, 1.05)
        rows = [1] * int(rng.integers(2, 4)) + [int(rng.integers(2, 4))]
    d = rng.uniform(0.45, 0.55)
    t = 0.018
    top_t = rng.uniform(0.022, 0.032)
    mat = M.wood(rng)
    pull_mat = M.metal(rng)
    style = "knob" if rng.random() < 0.35 else "bar"
    legged = rng.random() < 0.4
    z0 = rng.uniform(0.12, 0.18) if legged else rng.uniform(0.06, 0.09)
    body_h = h - top_t - z0
    parts = [*carcass_panels(w, d, body_h, t, mat, z0=z0, top=False),
             _case_top(w, d, h - top_t, top_t, mat)]
    if legged:
        parts += _legs(rng, w, d, z0, mat, splay=False)
    else:
        parts.append(make_part("plinth", "plinth",
                               S.box((w - 0.03, d - 0.03, z0), center=(0, -0.01, z0 / 2)), mat))
        parts += glides((-w / 2 + 0.03, w / 2 - 0.03), (-d / 2 + 0.02, d / 2 - 0.04))
    # the anti-tip strap on the back under the top, which ties the chest to the wall
    parts.append(wall_strap(z=h - top_t - 0.02, y=-d / 2))
    weights = [1.0] * len(rows)
    if variant == "mixed":
        weights[-1] = 0.7  # the row of small drawers at the top is shallower
    parts += _drawer_grid(rng, x0=-w / 2 + t, x1=w / 2 - t, z0=z0 + t, z1=h - top_t, rows=rows,
                          y_face=d / 2 + 0.018, depth=d - 0.03, mat=mat, pull_mat=pull_mat,
                          style=style, weights=weights)
    return parts


@register("wardrobe", parts=("body", "door", "shelf"), extra_parts=("handle", "rod", "plinth", "hinge", "track", "shelf_pin",
                                                                     "rod_socket", "glide", "cam_lock", "wall_strap"),
          size_range=(1.7, 2.3), density=300, variants=("two_door", "three_door", "sliding"), groups=CARCASS_GROUP)
def wardrobe(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    n_doors = {"two_door": 2, "three_door": 3, "sliding": 2}[variant]
    w = {"two_door": rng.uniform(0.9, 1.2), "three_door": rng.uniform(1.35, 1.75),
         "sliding": rng.uniform(1.5, 2.0)}[variant]
    d = rng.uniform(0.55, 0.62)
    h = rng.uniform(1.85, 2.2)
    t = rng.uniform(0.018, 0.022)
    plinth = rng.uniform(0.06, 0.1)
    mat = M.wood(rng)
    door_mat = mat if rng.random() < 0.7 else M.solid((0.93, 0.93, 0.91), "wood", roughness=0.4)
    pull_mat = M.metal(rng)
    # a partition splits shelves (left) from the hanging space (right)
    x_div = -w / 2 + (w / 3 if n_doors == 3 else w / 2)
    parts = [*carcass_panels(w, d, h - plinth, t, mat, z0=plinth, dividers=(x_div,)),
             make_part("plinth", "plinth",
                       S.box((w - 0.02, d - 0.03, plinth), center=(0, -0.015, plinth / 2)), mat)]
    # glides under the plinth, cam locks under the top board, the anti-tip strap on the back
    parts += glides((-w / 2 + 0.03, w / 2 - 0.03), (-d / 2 + 0.02, d / 2 - 0.05))
    parts += cams((h - t,), iw=w - 2 * t, ys=(-d / 2 + 0.05, d / 2 - 0.05))
    parts.append(wall_strap(z=h - t - 0.02, y=-d / 2))
    z_in0, z_in1 = plinth + t, h - t
    # shelves in the left section
    n_sh = int(rng.integers(3, 6))
    zs = np.linspace(z_in0, z_in1, n_sh + 2)[1:-1]
    sx0, sx1 = -w / 2 + t, x_div - t / 2
    depth = d - t * 0.6 - 0.02
    k = 0
    n_pin = 0
    for z in zs:
        shelf = S.box((sx1 - sx0, depth, t), center=((sx0 + sx1) / 2, -d / 2 + t * 0.6 + depth / 2, z))
        parts.append(make_part(f"shelf_{k}", "shelf", shelf, mat))
        k += 1
        # the four pins in the drilled rows of the side and the partition that carry the shelf
        for x, fy in [(sx0 + 0.006, -0.35), (sx0 + 0.006, 0.35), (sx1 - 0.006, -0.35), (sx1 - 0.006, 0.35)]:
            parts.append(make_part(f"shelf_pin_{n_pin}", "shelf_pin",
                                   S.cylinder(0.003, 0.012, center=(x, -d / 2 + t * 0.6 + depth * (0.5 + fy), z - t / 2 - 0.003),
                                              axis=(1, 0, 0), sections=8), pull_mat))
            n_pin += 1
    # hat shelf and rod in the right section
    hx0, hx1 = x_div + t / 2, w / 2 - t
    z_hat = z_in1 - rng.uniform(0.3, 0.4)
    parts.append(make_part(f"shelf_{k}", "shelf", S.box(
        (hx1 - hx0, depth, t), center=((hx0 + hx1) / 2, -d / 2 + t * 0.6 + depth / 2, z_hat)), mat))
    rod = S.cylinder(0.013, hx1 - hx0, center=((hx0 + hx1) / 2, 0.0, z_hat - 0.07), axis=(1, 0, 0),
                     sections=12)
    parts.append(make_part("rod", "rod", rod, pull_mat))
    # the sockets holding the rod's ends on the side and the partition
    for j, x in enumerate((hx0 + 0.003, hx1 - 0.003)):
        parts.append(make_part(f"rod_socket_{j}", "rod_socket", S.cylinder(0.022, 0.006, center=(x, 0.0, z_hat - 0.07), axis=(1, 0, 0),
                                                                          sections=12), pull_mat))
    # doors
    door_t = 0.02
    y_front = d / 2
    dz0, dz1 = plinth + 0.005, h - 0.005
    if variant == "sliding":
        overlap = 0.04
        dw = w / 2 + overlap / 2
        for i, (x, y) in enumerate(((-w / 2 + dw / 2, y_front + door_t / 2),
                                    (w / 2 - dw / 2, y_front + door_t * 1.5 + 0.004))):
            door = bevel_box((dw, door_t, dz1 - dz0), center=(x, y, (dz0 + dz1) / 2), bevel=0.004)
            parts.append(make_part(f"door_{i}", "door", door, door_mat))
            hx = x + (dw / 2 - 0.06) * (1 if i == 0 else -1)
            parts.append(make_part(f"handle_{i}", "handle", bar_handle(
                (hx, y + door_t / 2, (dz0 + dz1) / 2), 0.35, vertical=True, standoff=0.02),
                pull_mat))
            # the back door slides right, the front one left, each along its own track
            parts += [prismatic(f"door_{i}_slide", "track", f"door_{i}", travel=w / 2 - overlap,
                                axis=(1.0, 0.0, 0.0) if i == 0 else (-1.0, 0.0, 0.0)),
                      mount(f"door_{i}", f"handle_{i}")]
        parts.append(make_part("track", "track", S.box((w, 2 * door_t + 0.004, 0.004),
                                                       center=(0, y_front + door_t + 0.002, dz1 + 0.002)),
                               pull_mat))
    else:
        gap = 0.004
        dw = w / n_doors
        for i in range(n_doors):
            x = -w / 2 + dw * (i + 0.5)
            door = bevel_box((dw - gap, door_t, dz1 - dz0),
                             center=(x, y_front + door_t / 2, (dz0 + dz1) / 2), bevel=0.004)
            parts.append(make_part(f"door_{i}", "door", door, door_mat))
            # handles near the meeting edges; a lone door on the left of three pairs with none
            side = 1 if (i % 2 == 0 and i < n_doors - 1) else -1
            hx = x + side * (dw / 2 - 0.05)
            parts.append(make_part(f"handle_{i}", "handle", bar_handle(
                (hx, y_front + door_t, (dz0 + dz1) / 2 + 0.05), 0.3, vertical=True),
                pull_mat))
            # hinged on the edge away from the handle, opening outward
            xh = x - side * (dw - gap) / 2
            parts += hinge_parts(f"door_{i}_hinge", x=xh, y=y_front, z0=dz0, z1=dz1, mat=pull_mat, n=3,
                                 radius=0.006, length=0.06)
            parts += [revolute(f"door_{i}_hinge", "body", f"door_{i}", axis=(0, 0, 1), origin=(xh, y_front, dz0),
                               opens=OPEN_DOOR if side == 1 else -OPEN_DOOR),
                      mount(f"door_{i}", f"handle_{i}")]
    return parts
