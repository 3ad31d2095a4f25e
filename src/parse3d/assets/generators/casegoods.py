"""Case goods: china hutches and lockers.

A hutch is a lower cabinet (doors, drawers, a shelf behind the doors) under a ``countertop``,
with an open shelved top over it: its upper ``shelf`` boards (``shelf_1`` upward: the lower
cabinet's shelf is ``shelf_0``) are internal supports walled by the ``side_panel``s and the
``back_panel``, and each carries a ``plate_rail`` groove strip so plates stand on their rims
leaning against the back. A locker is a tall steel cabinet: hinged ``door``s with ``vent``
louvres, a ``shelf`` and a ``hook`` inside each compartment.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Material, Part, make_part
from ..registry import register
from ._casework import door_parts, drawer_parts
from ._dB_case import cams, glides, wall_strap
from ._kit import mount


@register("hutch", parts=("countertop", "body", "shelf", "back_panel"),
          extra_parts=("side_panel", "top_panel", "door", "drawer", "drawer_box", "handle", "hinge",
                       "plate_rail", "glass", "shelf_pin", "glide", "cam_lock"),
          size_range=(1.5, 2.3), density=550, variants=("open", "glass_doors", "drawers"),
          placement="floor",
          groups={"body": ("cabinet_side", "bottom_panel", "cabinet_top", "cabinet_back", "drawer_rail", "plinth")})
def hutch(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d = rng.uniform(1.0, 1.6), rng.uniform(0.42, 0.52)
    hl = rng.uniform(0.82, 0.9)  # countertop height
    H = rng.uniform(1.8, 2.1)
    du = rng.uniform(0.28, 0.34)  # the upper part's depth
    t = 0.02
    mat = M.wood(rng) if rng.random() < 0.7 else Material(M.jitter(rng, (0.92, 0.91, 0.86), 0.02),
                                                          0.5, 0.0, "wood")
    hmat = M.metal(rng)
    z0 = 0.08
    hb = hl - t
    zd = hb - t - 0.15 if variant == "drawers" else hb - t
    # the lower cabinet's carcass, panel by panel (``body`` covers them all; the plinth, named
    # body, stands on the floor and carries the doors and drawers)
    parts: list[Part | Joint] = [
        make_part(f"cabinet_side_{k}", "cabinet_side", S.box((t, d, hb - z0), center=(sx * (w / 2 - t / 2), 0, (z0 + hb) / 2)), mat)
        for k, sx in enumerate((-1, 1))]
    parts += [make_part("bottom_panel", "bottom_panel", S.box((w - 2 * t, d, t), center=(0, 0, z0 + t / 2)), mat),
              make_part("cabinet_top", "cabinet_top", S.box((w - 2 * t, d, t), center=(0, 0, hb - t / 2)), mat),
              make_part("cabinet_back", "cabinet_back", S.box((w - 2 * t, 0.008, hb - z0 - 2 * t),
                                                              center=(0, -d / 2 + 0.004, (z0 + hb) / 2)), mat)]
    if zd < hb - t - 1e-6:  # the rail between the drawers and the doors
        parts.append(make_part("drawer_rail", "drawer_rail", S.box((w - 2 * t, d - 0.008, t), center=(0, 0.004, zd + t / 2)), mat))
    parts.append(make_part("body", "plinth", S.box((w - 0.04, d - 0.04, z0), center=(0, -0.01, z0 / 2)), mat))
    # glides under the plinth and cam locks under the bottom panel
    parts += glides((-w / 2 + 0.045, w / 2 - 0.045), (-d / 2 + 0.03, d / 2 - 0.05))
    parts += cams((z0,), iw=w - 2 * t, ys=(-d / 2 + 0.05, d / 2 - 0.05))
    parts.append(make_part("countertop", "countertop",
                           S.box((w + 0.03, d + 0.02, t), center=(0, 0.01, hl - t / 2), bevel=0.004), mat))
    dw = (w - 2 * t) / 2
    for i in range(2):
        x0, x1 = -w / 2 + t + i * dw + 0.002, -w / 2 + t + (i + 1) * dw - 0.002
        if zd < hb - t - 1e-6:
            parts += drawer_parts(f"drawer_{i}", x0=x0, x1=x1, z0=zd + t + 0.003, z1=hb - t - 0.003,
                                  y_front=d / 2, depth=d - 0.06, thick=0.018, mat=mat, handle_mat=hmat,
                                  knob_style=True)
        parts += door_parts(f"door_{i}", x0=x0, x1=x1, z0=z0 + t + 0.003, z1=zd - 0.003,
                            y_back=d / 2 - 0.018, thick=0.018, mat=mat, handle_mat=hmat,
                            hinge_left=i == 0, style="shaker", handle_len=0.1)
    zs0 = (z0 + t + zd) / 2
    parts.append(make_part("shelf_0", "shelf", S.box((w - 2 * t, d - 0.04, t), center=(0, -0.012, zs0)), mat))
    # the open top: sides, back, crown, shelves with a plate groove near the back
    yb = -d / 2
    hu = H - hl
    parts.append(make_part("back_panel", "back_panel",
                           S.box((w - 2 * t, 0.012, hu - t), center=(0, yb + 0.006, hl + (hu - t) / 2)), mat))
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"side_panel_{k}", "side_panel",
                               S.box((t, du, hu), center=(sx * (w / 2 - t / 2), yb + du / 2, hl + hu / 2)), mat))
    parts.append(make_part("top_panel", "top_panel",
                           S.box((w + 0.03, du + 0.02, 0.04), center=(0, yb + du / 2 + 0.01, H - 0.02), bevel=0.004),
                           mat))
    ns = int(rng.integers(2, 4))
    for k in range(ns):
        zk = hl + (hu - 0.04) * (k + 1) / (ns + 1)
        parts.append(make_part(f"shelf_{k + 1}", "shelf",
                               S.box((w - 2 * t, du - 0.012, t), center=(0, yb + 0.012 + (du - 0.012) / 2, zk - t / 2)),
                               mat))
        parts.append(make_part(f"plate_rail_{k}", "plate_rail",
                               S.box((w - 2 * t, 0.012, 0.006), center=(0, yb + 0.012 + 0.07, zk + 0.003)), mat))
        # the four pins in the side panels' drilled rows that carry the shelf
        for j, (sx, fy) in enumerate([(-1, 0.25), (-1, 0.75), (1, 0.25), (1, 0.75)]):
            parts.append(make_part(f"shelf_pin_{4 * k + j}", "shelf_pin",
                                   S.cylinder(0.003, 0.012, center=(sx * (w / 2 - t - 0.006), yb + 0.012 + (du - 0.012) * fy, zk - t - 0.003),
                                              axis=(1, 0, 0), sections=8), hmat))
    if variant == "glass_doors":
        zt = H - 0.04
        for i in range(2):
            x0, x1 = -w / 2 + t + i * dw + 0.002, -w / 2 + t + (i + 1) * dw - 0.002
            parts += door_parts(f"upper_door_{i}", x0=x0, x1=x1, z0=hl + 0.003, z1=zt - 0.003,
                                y_back=yb + du, thick=0.018, mat=mat, handle_mat=hmat,
                                hinge_left=i == 0, style="glass", glass=M.glass(rng), handle_len=0.08,
                                parent=f"side_panel_{i}")
    return parts


@register("locker", parts=("body", "door"), extra_parts=("handle", "hinge", "shelf", "hook", "vent",
                                                          "nameplate", "hasp", "glide", "wall_strap", "rivet"),
          size_range=(1.2, 2.0), density=400, variants=("single", "two_tier", "bank"), placement="floor",
          groups={"body": ("top_panel", "bottom_panel", "back_panel", "side_panel", "partition", "tier_panel",
                           "plinth")})
def locker(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    """A steel locker (a ``bank`` is three side by side): a door per compartment with vent
    louvres and a handle, a shelf near the top and a coat hook under it."""
    steel = Material(M.jitter(rng, [(0.45, 0.55, 0.65), (0.6, 0.62, 0.64), (0.2, 0.35, 0.55),
                                    (0.75, 0.3, 0.25)][int(rng.integers(4))], 0.02), 0.45, 0.6, "metal")
    cols = 3 if variant == "bank" else 1
    wc = rng.uniform(0.3, 0.4)
    w, d, H = wc * cols, rng.uniform(0.42, 0.5), rng.uniform(1.6, 1.85)
    zb = 0.1
    t = 0.01
    dc = d - 0.02
    yc = -0.01
    # the carcass panel by panel, all covered by ``body``; the recessed base, named body, stands
    # on the floor (locker:body@bottom) and carries the doors
    parts: list[Part | Joint] = [
        make_part("top_panel", "top_panel", S.box((w, dc, t), center=(0, yc, H - t / 2)), steel),
        make_part("bottom_panel", "bottom_panel", S.box((w, dc, t), center=(0, yc, zb + t / 2)), steel),
        make_part("back_panel", "back_panel", S.box((w - 0.004, 0.006, H - zb), center=(0, -d / 2 + 0.003, (H + zb) / 2)), steel)]
    for i in range(cols + 1):
        x = -w / 2 + t / 2 + i * (w - t) / cols
        outer = i in (0, cols)
        parts.append(make_part(f"side_panel_{i // cols}" if outer else f"partition_{i - 1}", "side_panel" if outer else "partition",
                               S.box((t, dc, H - zb), center=(x, yc, (H + zb) / 2)), steel))
    tiers = 2 if variant == "two_tier" else 1
    zt = [zb + (H - zb) * k / tiers for k in range(tiers + 1)]
    for k in range(1, tiers):
        parts.append(make_part(f"tier_panel_{k - 1}", "tier_panel", S.box((w - 2 * t, dc, t), center=(0, yc, zt[k])), steel))
    parts.append(make_part("body", "plinth", S.box((w - 0.02, dc - 0.03, zb), center=(0, yc - 0.015, zb / 2)), steel))
    # levelling glides under the base; the anchor bracket that ties the top to the wall
    parts += glides((-w / 2 + 0.035, w / 2 - 0.035), (yc - dc / 2 + 0.03, yc + dc / 2 - 0.06))
    parts.append(wall_strap(z=H - t - 0.02, y=-d / 2 + 0.006))
    yf = yc + dc / 2
    hmat = Material((0.7, 0.7, 0.72, 1.0), 0.3, 0.9, "metal")
    k_shelf = 0
    for c in range(cols):
        x0 = -w / 2 + t + c * (w - t) / cols
        x1 = -w / 2 + (c + 1) * (w - t) / cols
        for r in range(tiers):
            name = f"door_{c}_{r}" if (cols > 1 or tiers > 1) else "door"
            z0, z1 = zt[r] + (t if r == 0 else t / 2), zt[r + 1] - (t if r == tiers - 1 else t / 2)
            parts += door_parts(name, x0=x0 + 0.002, x1=x1 - 0.002, z0=z0 + 0.002, z1=z1 - 0.002,
                                y_back=yf, thick=0.012, mat=steel, handle_mat=hmat, hinge_left=c < cols / 2,
                                style="flat", handle_len=0.08)
            # vent louvres pressed into the top and the bottom of the door, mounted on it
            for j in range(6):
                zv = z1 - 0.06 - j * 0.025 if j < 3 else z0 + 0.06 + (j - 3) * 0.025
                vent = S.box(((x1 - x0) * 0.6, 0.004, 0.008), center=((x0 + x1) / 2, yf + 0.013, zv))
                parts.append(make_part(f"{name}_vent_{j}", "vent", vent, Material((0.1, 0.1, 0.1, 1.0), 0.6, 0.3,
                                                                                  "metal")))
                parts.append(mount(name, f"{name}_vent_{j}"))
            plate = S.box((0.06, 0.003, 0.025), center=((x0 + x1) / 2, yf + 0.0135, z1 - 0.16))
            parts.append(make_part(f"{name}_nameplate", "nameplate", plate, hmat))
            parts.append(mount(name, f"{name}_nameplate"))
            # the two rivets through the number plate's ends
            for j, sx in enumerate((-1, 1)):
                parts.append(make_part(f"{name}_rivet_{j}", "rivet", S.cylinder(0.0025, 0.001, center=((x0 + x1) / 2 + sx * 0.024, yf + 0.0155, z1 - 0.16),
                                                                               axis=(0, 1, 0), sections=8), hmat))
                parts.append(mount(f"{name}_nameplate", f"{name}_rivet_{j}"))
            # the padlock hasp beside the handle: a staple on the frame through a slot in the door
            xh = (x1 - 0.045) if c < cols / 2 else (x0 + 0.045)
            xh += 0.03 if c < cols / 2 else -0.03
            parts.append(make_part(f"{name}_hasp", "hasp", S.box((0.012, 0.012, 0.03), center=(xh, yf + 0.018, (z0 + z1) / 2 - 0.07)), hmat))
            parts.append(mount(name, f"{name}_hasp"))
            if z1 - z0 > 0.6:  # a hat shelf and a coat hook under it
                zs = z1 - 0.3
                parts.append(make_part(f"shelf_{k_shelf}", "shelf",
                                       S.box((x1 - x0, dc - 0.02, 0.008), center=((x0 + x1) / 2, yc - 0.008, zs)),
                                       steel))
                hook = S.tube([((x0 + x1) / 2, -d / 2 + 0.006, zs - 0.05), ((x0 + x1) / 2, -d / 2 + 0.05, zs - 0.05),
                               ((x0 + x1) / 2, -d / 2 + 0.06, zs - 0.035)], 0.004, sections=6)
                parts.append(make_part(f"hook_{k_shelf}", "hook", hook, hmat))
                # a single-prong hook on each side wall under the shelf
                for j, sx in enumerate((-1, 1)):
                    xs_ = (x0 + 0.004) if sx < 0 else (x1 - 0.004)
                    side = S.tube([(xs_, yc - 0.05, zs - 0.04), (xs_ - sx * 0.04, yc - 0.05, zs - 0.04), (xs_ - sx * 0.05, yc - 0.05, zs - 0.025)],
                                  0.0035, sections=6)
                    parts.append(make_part(f"hook_{k_shelf}_{j}", "hook", side, hmat))
                k_shelf += 1
    return parts
