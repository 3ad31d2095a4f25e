"""Shared building blocks for casework (cabinets, shelving, appliances): panels, doors, drawers,
handles and knobs.

Every helper returns :class:`~parse3d.geometry.shapes.Shape` objects or lists of
:class:`~parse3d.assets.model.Part` in the asset's canonical frame (+Z up, front +Y, metres),
so generators only decide proportions and layout.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from ..model import Joint, Material, Part, make_part
from ._kit import DRAWER_TRAVEL, OPEN_DOOR, hinge_parts, mount, prismatic, revolute

__all__ = ["bar_pull", "knob", "door_parts", "drawer_parts", "shelf_heights", "felt", "white",
           "black", "glass_pane"]


def felt(rng: np.random.Generator) -> Material:
    """Billiard cloth: green, blue or red."""
    from .. import materials as M

    base = [(0.10, 0.42, 0.20), (0.12, 0.28, 0.55), (0.50, 0.12, 0.12)][int(rng.integers(3))]
    return Material(M.jitter(rng, base, 0.02), 0.95, 0.0, "fabric")


def white(rng: np.random.Generator, name: str = "metal") -> Material:
    """Enamel white / off-white (appliances, boards)."""
    from .. import materials as M

    return Material(M.jitter(rng, (0.93, 0.93, 0.92), 0.015), 0.3, 0.1, name)


def black(name: str = "plastic") -> Material:
    """Matte black (burners, keys, pockets, seals)."""
    return Material((0.06, 0.06, 0.07, 1.0), 0.6, 0.0, name)


def glass_pane(rng: np.random.Generator) -> Material:
    from .. import materials as M

    return M.glass(rng)


def bar_pull(center, length: float, *, vertical: bool, reach: float = 0.028,
             radius: float = 0.006) -> S.Shape:
    """A bar pull standing off a front face at ``center`` (the face point), toward +Y.

    Parameters
    ----------
    center : (3,) float
        Point on the front face (y = the face) where the pull is centred, metres.
    length : float
        Length of the grip, metres.
    vertical : bool
        Grip along Z (doors) or along X (drawers).
    """
    c = np.asarray(center, float)
    a = np.array([0.0, 0.0, 1.0]) if vertical else np.array([1.0, 0.0, 0.0])
    y0 = np.array([0.0, -0.004, 0.0])
    yr = np.array([0.0, reach, 0.0])
    path = [c - a * length / 2 + y0, c - a * length / 2 + yr, c + a * length / 2 + yr,
            c + a * length / 2 + y0]
    return S.tube(path, radius, sections=8)


def knob(center, radius: float, depth: float, *, axis=(0.0, 1.0, 0.0)) -> S.Shape:
    """A round knob whose base sits at ``center`` and sticks out ``depth`` along ``axis``."""
    ax = np.asarray(axis, float)
    c = np.asarray(center, float) + ax * depth / 2 - ax * 0.002
    return S.cylinder(radius, depth + 0.002, center=c, axis=ax, sections=16)


def door_parts(name: str, *, x0: float, x1: float, z0: float, z1: float, y_back: float,
               thick: float, mat: Material, handle_mat: Material, hinge_left: bool,
               style: str = "shaker", glass: Material | None = None,
               handle_len: float = 0.12, handle_at: str = "side", label: str = "door",
               parent: str | None = "body", hinge_mat: Material | None = None) -> list[Part | Joint]:
    """A hinged door filling ``[x0, x1] x [z0, z1]`` whose back face is at ``y_back``.

    ``style``: ``flat`` (slab), ``shaker`` (slab with a raised centre panel) or ``glass``
    (a frame around a glass pane; the pane is its own part ``<name>_glass`` labelled ``glass``).
    The handle (``<name>_handle``, label ``handle``) sits on the side away from the hinge
    (``handle_at="side"``) or runs along the bottom or top edge (``"bottom"``: lift-up flaps
    hinged at the top; ``"top"``: oven doors hinged at the bottom, dropping open).

    With a ``parent`` part name the door is articulated: two hinge barrels (``<name>_hinge_k``,
    label ``hinge``) on the hinge line at the door's back edge, a revolute joint
    ``<name>_hinge`` (0 closed, opening outward by about 100 degrees; drop-down and lift-up
    doors 90 degrees) and mounts carrying the handle and pane with the door.
    Returns the door part(s), the handle part, then the hinges and joints.
    """
    w, h = x1 - x0, z1 - z0
    cx, cz = (x0 + x1) / 2, (z0 + z1) / 2
    yc = y_back + thick / 2
    parts = []
    if style == "glass" and glass is not None:
        f = min(0.06, w * 0.18, h * 0.18)
        frame = [
            S.box((f, thick, h), center=(x0 + f / 2, yc, cz), bevel=0.003),
            S.box((f, thick, h), center=(x1 - f / 2, yc, cz), bevel=0.003),
            S.box((w - 2 * f, thick, f), center=(cx, yc, z0 + f / 2)),
            S.box((w - 2 * f, thick, f), center=(cx, yc, z1 - f / 2)),
        ]
        parts.append(make_part(name, label, frame, mat))
        pane = S.box((w - 2 * f, 0.005, h - 2 * f), center=(cx, yc, cz))
        parts.append(make_part(f"{name}_glass", "glass", pane, glass))
    else:
        slab = [S.box((w, thick, h), center=(cx, yc, cz), bevel=min(0.004, thick / 4))]
        if style == "shaker" and w > 0.15 and h > 0.15:
            m = min(0.07, w * 0.15, h * 0.15)
            slab.append(S.box((w - 2 * m, 0.006, h - 2 * m), center=(cx, y_back + thick + 0.002, cz),
                              bevel=0.002))
        parts.append(make_part(name, label, slab, mat))
    y_front = y_back + thick + (0.006 if style == "shaker" else 0.0)
    if handle_at in ("bottom", "top"):
        zh = z0 + 0.04 if handle_at == "bottom" else z1 - 0.04
        pull = bar_pull((cx, y_front, zh), min(handle_len, w * 0.8), vertical=False)
    else:
        hx = (x1 - 0.045) if hinge_left else (x0 + 0.045)
        pull = bar_pull((hx, y_front, cz), min(handle_len, h * 0.6), vertical=True)
    parts.append(make_part(f"{name}_handle", "handle", pull, handle_mat))
    if parent is None:
        return parts
    hm = hinge_mat or handle_mat
    out: list[Part | Joint] = list(parts)
    r = min(0.006, thick / 3)
    if handle_at == "side":
        xh = x0 if hinge_left else x1
        out += hinge_parts(f"{name}_hinge", x=xh, y=y_back, z0=z0, z1=z1, mat=hm, radius=r,
                           length=min(0.06, h * 0.15))
        out.append(revolute(f"{name}_hinge", parent, name, axis=(0, 0, 1), origin=(xh, y_back, z0),
                            opens=OPEN_DOOR if hinge_left else -OPEN_DOOR))
    else:
        zh = z0 if handle_at == "top" else z1
        out += hinge_parts(f"{name}_hinge", x=zh, y=y_back, z0=x0, z1=x1, mat=hm, radius=r,
                           length=min(0.06, w * 0.15), axis="x")
        out.append(revolute(f"{name}_hinge", parent, name, axis=(1, 0, 0), origin=(x0, y_back, zh),
                            opens=-np.pi / 2 if handle_at == "top" else np.pi / 2))
    out += [mount(name, p.name) for p in parts[1:]]
    return out


def drawer_parts(name: str, *, x0: float, x1: float, z0: float, z1: float, y_front: float,
                 depth: float, thick: float, mat: Material, handle_mat: Material,
                 knob_style: bool = False, parent: str | None = "body") -> list[Part | Joint]:
    """A drawer: its front panel (``<name>``, label ``drawer``: it carries the drawer's front
    face, as the whole drawer did before the box was a part of its own) in
    ``[x0, x1] x [z0, z1]`` whose front face is at ``y_front``, the open-topped box behind it
    ``depth`` deep (``<name>_box``, label ``drawer_box``: its floor is the internal support for
    ``IN``), and a pull (``<name>_handle``).

    With a ``parent`` part name the box slides out along +Y on a prismatic joint
    ``<name>_slide`` (0 closed, ``DRAWER_TRAVEL`` of its depth open) with the front mounted on
    the box and the pull on the front.
    """
    w, h = x1 - x0, z1 - z0
    cx, cz = (x0 + x1) / 2, (z0 + z1) / 2
    yb = y_front - thick
    t = 0.012
    bw, bh = w - 0.02, h - 0.03
    bz0 = z0 + 0.01
    y_end = yb - depth
    walls = [
        S.box((bw, depth, t), center=(cx, yb - depth / 2, bz0 + t / 2)),
        S.box((t, depth, bh - t), center=(cx - bw / 2 + t / 2, yb - depth / 2, bz0 + t + (bh - t) / 2)),
        S.box((t, depth, bh - t), center=(cx + bw / 2 - t / 2, yb - depth / 2, bz0 + t + (bh - t) / 2)),
        S.box((bw - 2 * t, t, bh - t), center=(cx, y_end + t / 2, bz0 + t + (bh - t) / 2)),
    ]
    front = S.box((w, thick, h), center=(cx, y_front - thick / 2, cz), bevel=min(0.004, thick / 4))
    parts: list[Part | Joint] = [make_part(name, "drawer", front, mat),
                                 make_part(f"{name}_box", "drawer_box", walls, mat)]
    if knob_style:
        pull = knob((cx, y_front, cz), 0.014, 0.025)
    else:
        pull = bar_pull((cx, y_front, cz), min(0.16, w * 0.5), vertical=False)
    parts.append(make_part(f"{name}_handle", "handle", pull, handle_mat))
    if parent is not None:
        parts += [prismatic(f"{name}_slide", parent, f"{name}_box", travel=DRAWER_TRAVEL * depth),
                  mount(f"{name}_box", name), mount(name, f"{name}_handle")]
    return parts


def shelf_heights(z0: float, z1: float, n: int) -> np.ndarray:
    """``n`` evenly spaced shelf levels from ``z0`` (inclusive) below ``z1`` (exclusive)."""
    return z0 + (z1 - z0) * np.arange(n) / n
