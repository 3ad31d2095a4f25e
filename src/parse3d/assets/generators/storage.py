"""Storage furniture: bookcases, cabinets, media consoles, wall cabinets, racks and gondolas.

Shelves are separate parts (``shelf_0`` at the bottom, upward), sized to the carcass interior
so that :mod:`parse3d.assets.internal` finds an internal support surface on each one: covered
by the next shelf or the top, walled by the sides and the back. Open racks get a lip (its own
``beam`` part) around every shelf so the same holds without side panels. Adjustable shelves rest
on four ``shelf_pin`` s each; a wire rack's shelves are held on its posts by a ``sleeve`` at every
corner, an industrial rack's by a ``bracket``; gondola posts end in ``end_cap`` s.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Part, make_part
from ..registry import register
from ._casework import black, door_parts, drawer_parts, glass_pane, shelf_heights
from ._dB_case import cams as _cams
from ._dB_case import glides as _glides
from ._dB_case import wall_strap as _wall_strap
from ._kit import mount
from ._rods import leg_caps


def _carcass(w: float, d: float, h: float, t: float, *, z0: float = 0.0, back: float = 0.008,
             bottom: bool = True, top: bool = True) -> list[S.Shape]:
    """Sides, optional top/bottom and a back panel of a box carcass spanning ``[z0, h]``."""
    hs = h - z0
    out = [S.box((t, d, hs), center=(-w / 2 + t / 2, 0, z0 + hs / 2), bevel=0.002),
           S.box((t, d, hs), center=(w / 2 - t / 2, 0, z0 + hs / 2), bevel=0.002)]
    iw = w - 2 * t
    z_in0, z_in1 = z0 + (t if bottom else 0.0), h - (t if top else 0.0)
    if bottom:
        out.append(S.box((iw, d, t), center=(0, 0, z0 + t / 2)))
    if top:
        out.append(S.box((iw, d, t), center=(0, 0, h - t / 2)))
    out.append(S.box((iw, back, z_in1 - z_in0), center=(0, -d / 2 + back / 2, (z_in0 + z_in1) / 2)))
    return out


def _shelves(levels, *, iw: float, y0: float, y1: float, t: float, mat, start: int = 0) -> list[Part]:
    """Shelf boards of inner width ``iw`` from ``y0`` (back) to ``y1`` (front), tops at ``levels``."""
    sd = y1 - y0
    return [make_part(f"shelf_{start + i}", "shelf",
                      S.box((iw, sd, t), center=(0, (y0 + y1) / 2, z - t / 2), bevel=0.002), mat)
            for i, z in enumerate(levels)]


def _pins(levels, *, iw: float, y0: float, y1: float, t: float, start: int = 0, cx: float = 0.0) -> list[Part]:
    """Four shelf pins under each shelf (tops at ``levels``): short metal pegs standing out of
    the side panels' inner faces (at x = ``cx`` +- ``iw`` / 2) 3 cm in from the shelf's back and
    front."""
    pin = M.solid((0.72, 0.7, 0.66), "metal", 0.3, 0.9)
    out = []
    k = start
    for z in levels:
        for y in (y0 + 0.03, y1 - 0.03):
            for sx in (-1, 1):
                out.append(make_part(f"shelf_pin_{k}", "shelf_pin",
                                     S.cylinder(0.0025, 0.01, center=(cx + sx * (iw / 2 - 0.005), y, z - t - 0.0025), axis=(1, 0, 0),
                                                sections=8), pin))
                k += 1
    return out


def _door_row(prefix: str, *, w: float, z0: float, z1: float, y_back: float, n: int, mat, hmat,
              style: str, glass=None, start: int = 0, gap: float = 0.003,
              parents: tuple[str, str] = ("body", "body")) -> list[Part | Joint]:
    """``n`` doors side by side; ``parents`` names the part a left- and a right-hinged door hangs
    on."""
    parts = []
    dw = w / n
    for i in range(n):
        x0, x1 = -w / 2 + i * dw + gap, -w / 2 + (i + 1) * dw - gap
        hinge_left = i < n / 2 if n > 1 else True
        parts += door_parts(f"{prefix}_{start + i}", x0=x0, x1=x1, z0=z0 + gap, z1=z1 - gap,
                            y_back=y_back, thick=0.018, mat=mat, handle_mat=hmat,
                            hinge_left=hinge_left, style=style, glass=glass,
                            parent=parents[0] if hinge_left else parents[1])
    return parts


@register("bookcase", parts=("shelf", "side_panel", "back_panel"),
          extra_parts=("top_panel", "base", "door", "handle", "glass", "hinge", "shelf_pin", "glide", "cam_lock", "wall_strap"),
          size_range=(0.9, 2.3),
          density=550, variants=("open", "doored", "glass_doored"))
def bookcase(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d, h = rng.uniform(0.6, 1.2), rng.uniform(0.28, 0.4), rng.uniform(1.0, 2.2)
    t, bt, plinth = rng.uniform(0.018, 0.025), 0.008, rng.uniform(0.05, 0.09)
    mat = M.wood(rng)
    hmat = M.metal(rng)
    oh = rng.uniform(0.0, 0.015)
    h_side = h - t
    parts = [
        make_part("side_panel_0", "side_panel",
                  S.box((t, d, h_side), center=(-w / 2 + t / 2, 0, h_side / 2), bevel=0.002), mat),
        make_part("side_panel_1", "side_panel",
                  S.box((t, d, h_side), center=(w / 2 - t / 2, 0, h_side / 2), bevel=0.002), mat),
        make_part("top_panel", "top_panel",
                  S.box((w + 2 * oh, d + oh, t), center=(0, oh / 2, h - t / 2), bevel=0.003), mat),
        make_part("back_panel", "back_panel",
                  S.box((w - 2 * t, bt, h_side - plinth), center=(0, -d / 2 + bt / 2, (plinth + h_side) / 2)),
                  mat),
        make_part("base", "base", S.box((w - 2 * t, t, plinth), center=(0, d / 2 - t / 2 - 0.01, plinth / 2)),
                  mat),
    ]
    inner = h_side - plinth
    n = int(np.clip(np.floor(inner / 0.3), 3, 6))
    levels = plinth + t + shelf_heights(0.0, inner, n)
    parts += _shelves(levels, iw=w - 2 * t, y0=-d / 2 + bt, y1=d / 2 - 0.002, t=t, mat=mat)
    parts += _pins(levels[1:], iw=w - 2 * t, y0=-d / 2 + bt, y1=d / 2 - 0.002, t=t)
    # glides under the side panels; cam locks under the fixed bottom shelf and the top; the
    # wall strap on the back's top edge (the back ends under the top panel)
    parts += _glides((-w / 2 + t / 2, w / 2 - t / 2), (-d / 2 + 0.03, d / 2 - 0.03))
    parts += _cams((levels[0] - t, h - t), iw=w - 2 * t, ys=(-d / 2 + bt + 0.04, d / 2 - 0.04))
    parts.append(_wall_strap(z=h_side - 0.02, y=-d / 2 + bt))
    if variant == "doored":
        k = max(1, n // 2)
        z_top = plinth + k * inner / n + t
        parts += _door_row("door", w=w, z0=plinth, z1=z_top, y_back=d / 2, n=2, mat=mat, hmat=hmat,
                           style="shaker" if rng.random() < 0.6 else "flat",
                           parents=("side_panel_0", "side_panel_1"))
    elif variant == "glass_doored":
        parts += _door_row("door", w=w, z0=plinth, z1=h_side, y_back=d / 2, n=2, mat=mat, hmat=hmat,
                           style="glass", glass=glass_pane(rng), parents=("side_panel_0", "side_panel_1"))
    return parts


@register("storage_cabinet", parts=("body", "door", "shelf"),
          extra_parts=("handle", "drawer", "glass", "hinge", "drawer_box", "shelf_pin", "glide", "cam_lock", "wall_strap", "catch",
                       "strike_plate"),
          size_range=(0.7, 2.1), density=550, variants=("two_door", "single_door", "drawer_top"))
def storage_cabinet(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w = rng.uniform(0.45, 0.6) if variant == "single_door" else rng.uniform(0.7, 1.2)
    d, h = rng.uniform(0.4, 0.6), rng.uniform(0.8, 2.0)
    t, plinth = 0.018, rng.uniform(0.06, 0.1)
    mat = M.wood(rng) if rng.random() < 0.7 else M.metal(rng)
    hmat = M.metal(rng)
    body = _carcass(w, d, h, t, z0=plinth)
    body.append(S.box((w - 2 * t, d - 0.03, plinth), center=(0, -0.015, plinth / 2)))
    z_door_top = h
    drawers = []
    if variant == "drawer_top":
        z_door_top = h - rng.uniform(0.14, 0.2)
        body.append(S.box((w - 2 * t, d - 0.008, t), center=(0, 0.004, z_door_top - t / 2)))
        for i in range(2):
            x0, x1 = -w / 2 + i * w / 2 + 0.003, -w / 2 + (i + 1) * w / 2 - 0.003
            drawers += drawer_parts(f"drawer_{i}", x0=x0, x1=x1, z0=z_door_top + 0.003, z1=h - 0.003,
                                    y_front=d / 2 + 0.018, depth=d - 0.06, thick=0.018, mat=mat,
                                    handle_mat=hmat)
    parts = [make_part("body", "body", body, mat), *drawers]
    n_door = 1 if variant == "single_door" else 2
    parts += _door_row("door", w=w, z0=plinth, z1=z_door_top, y_back=d / 2, n=n_door, mat=mat, hmat=hmat,
                       style="shaker" if rng.random() < 0.5 else "flat")
    # a magnetic catch under the top at each door's free edge, and the steel strike plate on the
    # door's back that it holds shut
    z_in = z_door_top - t
    for i in range(n_door):
        x0, x1 = -w / 2 + i * w / n_door + 0.003, -w / 2 + (i + 1) * w / n_door - 0.003
        xf = x1 - 0.04 if (i < n_door / 2 if n_door > 1 else True) else x0 + 0.04
        parts.append(make_part(f"catch_{i}", "catch", S.box((0.03, 0.02, 0.012), center=(xf, d / 2 - 0.012, z_in - 0.006)), black()))
        parts.append(make_part(f"door_{i}_strike_plate", "strike_plate", S.box((0.02, 0.002, 0.01), center=(xf, d / 2 - 0.001, z_in - 0.006)),
                               M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)))
        parts.append(mount(f"door_{i}", f"door_{i}_strike_plate"))
    inner = z_door_top - t - (plinth + t)
    n = int(np.clip(np.floor(inner / 0.32), 1, 5))
    levels = plinth + t + shelf_heights(0.0, inner, n + 1)[1:] + t
    parts += _shelves(levels, iw=w - 2 * t, y0=-d / 2 + 0.008, y1=d / 2 - 0.01, t=t, mat=mat)
    parts += _pins(levels, iw=w - 2 * t, y0=-d / 2 + 0.008, y1=d / 2 - 0.01, t=t)
    # glides under the plinth's corners, cam locks under the top, the wall strap at the back
    parts += _glides((-w / 2 + t + 0.02, w / 2 - t - 0.02), (-d / 2 + 0.03, d / 2 - 0.06))
    parts += _cams((h - t,), iw=w - 2 * t, ys=(-d / 2 + 0.05, d / 2 - 0.05))
    parts.append(_wall_strap(z=h - t - 0.02, y=-d / 2 + 0.008))
    return parts


@register("tv_stand", parts=("top_panel", "body"),
          extra_parts=("drawer", "handle", "shelf", "leg", "door", "hinge", "drawer_box", "grommet", "shelf_pin", "ferrule",
                       "glide"),
          size_range=(0.9, 2.1), density=550, variants=("drawers", "cubbies", "legged"))
def tv_stand(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d, h = rng.uniform(1.0, 2.0), rng.uniform(0.35, 0.5), rng.uniform(0.4, 0.6)
    t = rng.uniform(0.018, 0.025)
    mat = M.wood(rng)
    hmat = M.metal(rng)
    z0 = rng.uniform(0.12, 0.2) if variant == "legged" else rng.uniform(0.03, 0.06)
    h_body = h - t
    parts = []
    n_bays = 3 if w > 1.4 else 2
    bay = (w - 2 * t) / n_bays
    body = _carcass(w, d, h_body, t, z0=z0, top=False)
    for i in range(1, n_bays):
        x = -w / 2 + t + i * bay
        body.append(S.box((t, d - 0.008, h_body - z0 - t), center=(x, 0.004, (z0 + t + h_body) / 2)))
    if variant != "legged":
        body.append(S.box((w - 0.04, d - 0.04, z0), center=(0, -0.01, z0 / 2)))
    parts.append(make_part("body", "body", body, mat))
    parts.append(make_part("top_panel", "top_panel",
                           S.box((w, d + 0.01, t), center=(0, 0.005, h - t / 2), bevel=0.004), mat))
    mid = (z0 + t + h_body) / 2
    if variant == "legged":
        leg = rng.uniform(0.03, 0.045)
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            x, y = sx * (w / 2 - 0.06), sy * (d / 2 - 0.05)
            parts.append(make_part(f"leg_{i}", "leg", S.frustum(leg / 2 * 0.6, leg / 2, z0, center=(x, y, 0),
                                                                 sections=12), mat))
    for b in range(n_bays):
        # the bay's opening between the dividers (dividers are centred on the bay boundaries)
        sx0 = -w / 2 + t + b * bay + (t / 2 if b > 0 else 0)
        sx1 = -w / 2 + t + (b + 1) * bay - (t / 2 if b < n_bays - 1 else 0)
        x0, x1 = sx0 + 0.002, sx1 - 0.002
        if (variant == "drawers" and b != n_bays // 2) or (variant == "legged" and b == 0):
            parts += drawer_parts(f"drawer_{b}", x0=x0, x1=x1, z0=z0 + t + 0.003, z1=h_body - 0.003,
                                  y_front=d / 2, depth=d - 0.05, thick=0.018, mat=mat, handle_mat=hmat,
                                  knob_style=variant == "legged")
        elif variant == "legged":
            parts += door_parts(f"door_{b}", x0=x0, x1=x1, z0=z0 + t + 0.003, z1=h_body - 0.003,
                                y_back=d / 2 - 0.018, thick=0.018, mat=mat, handle_mat=hmat,
                                hinge_left=b % 2 == 1, style="flat", handle_len=0.08)
        else:
            parts.append(make_part(f"shelf_{b}", "shelf",
                                   S.box((sx1 - sx0, d - 0.03, t), center=((sx0 + sx1) / 2, -0.011, mid)),
                                   mat))
            # the shelf rests on four pins out of the bay's side panels
            parts += _pins([mid + t / 2], iw=sx1 - sx0, y0=-0.011 - (d - 0.03) / 2, y1=-0.011 + (d - 0.03) / 2, t=t,
                           start=4 * b, cx=(sx0 + sx1) / 2)
        # a cable grommet through the back panel of every bay, near its top
        parts.append(make_part(f"grommet_{b}", "grommet", S.cylinder(0.03, 0.012, center=((sx0 + sx1) / 2, -d / 2 + 0.006, h_body - 0.07),
                                                                     axis=(0, 1, 0), sections=12), black()))
    if variant == "legged":  # brass ferrules on the tapered legs' feet
        parts += leg_caps(parts, label="ferrule", mat=M.solid((0.78, 0.62, 0.3), "metal", 0.3, 0.9))
    else:  # glides under the plinth's corners
        parts += _glides((-w / 2 + 0.045, w / 2 - 0.045), (-d / 2 + 0.03, d / 2 - 0.05))
    return parts


@register("wall_cabinet", parts=("body", "door", "shelf"), extra_parts=("handle", "glass", "hinge", "shelf_pin", "hanger", "screw"),
          size_range=(0.45, 1.1), density=550, variants=("solid", "glass", "lift_up"), placement="wall")
def wall_cabinet(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d, h = rng.uniform(0.4, 1.0), rng.uniform(0.28, 0.36), rng.uniform(0.5, 0.9)
    if variant == "lift_up":
        w, h = rng.uniform(0.6, 1.0), rng.uniform(0.35, 0.45)
    t = 0.018
    mat = M.wood(rng) if rng.random() < 0.6 else M.solid(M.jitter(rng, (0.92, 0.92, 0.9), 0.02)[:3], "wood")
    hmat = M.metal(rng)
    db = d - 0.02  # carcass depth; the doors bring the front flush with the asset's +Y face
    body = _carcass(w, db, h, t, back=0.01)
    parts = [make_part("body", "body", [s.moved((0, -0.01, 0)) for s in body], mat)]
    yf = d / 2 - 0.02
    n = max(1, int(np.floor((h - 2 * t) / 0.22)) - 1)
    levels = t + shelf_heights(0.0, h - 2 * t, n + 1)[1:] + t
    parts += _shelves(levels, iw=w - 2 * t, y0=-d / 2 + 0.01, y1=yf - 0.01, t=t, mat=mat)
    parts += _pins(levels, iw=w - 2 * t, y0=-d / 2 + 0.01, y1=yf - 0.01, t=t)
    # the two hanger brackets in the top back corners that hook it on its wall rail, and the
    # screws through the back's bottom corners (heads flush with the back's inner face)
    steel = M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)
    parts += [make_part(f"hanger_{k}", "hanger", S.box((0.03, 0.02, 0.05), center=(sx * (w / 2 - t - 0.015), -d / 2 + 0.02, h - t - 0.025)),
                        steel) for k, sx in enumerate((-1, 1))]
    parts += [make_part(f"screw_{k}", "screw", S.cylinder(0.005, 0.002, center=(sx * (w / 2 - t - 0.03), -d / 2 + 0.009, t + 0.03),
                                                          axis=(0, 1, 0), sections=8), steel) for k, sx in enumerate((-1, 1))]
    if variant == "lift_up":
        return parts + door_parts("door", x0=-w / 2, x1=w / 2, z0=0.0, z1=h, y_back=yf, thick=0.018,
                                  mat=mat, handle_mat=hmat, hinge_left=True, style="flat",
                                  handle_len=0.3, handle_at="bottom")
    n_door = 1 if w < 0.55 else 2
    style = "glass" if variant == "glass" else ("shaker" if rng.random() < 0.5 else "flat")
    parts += _door_row("door", w=w, z0=0.0, z1=h, y_back=yf, n=n_door, mat=mat, hmat=hmat, style=style,
                       glass=glass_pane(rng))
    return parts


def _lip(w: float, d: float, z: float, hgt: float, t: float, *, y_back: float | None = None) -> list[S.Shape]:
    """Four bars of height ``hgt`` standing on level ``z`` just outside a ``w x d`` deck; with
    ``y_back`` the deck reaches back to ``y_back`` and the back bar stands on its back edge."""
    zc = z + hgt / 2 - 0.015
    hh = hgt + 0.015
    y0 = -d / 2 if y_back is None else y_back + t  # where the side bars meet the back bar
    return [S.box((w + 2 * t, t, hh), center=(0, d / 2 + t / 2, zc)),
            S.box((w + 2 * t, t, hh), center=(0, y0 - t / 2, zc)),
            S.box((t, d / 2 - y0, hh), center=(w / 2 + t / 2, (d / 2 + y0) / 2, zc)),
            S.box((t, d / 2 - y0, hh), center=(-w / 2 - t / 2, (d / 2 + y0) / 2, zc))]


def _sleeve(x: float, y: float, z: float) -> S.Shape:
    """The tapered plastic sleeve clamped round a wire rack's post at ``(x, y)`` under a shelf
    whose underside is at ``z``."""
    return S.frustum(0.017, 0.0145, 0.035, center=(x, y, z - 0.035), sections=10)


@register("storage_rack", parts=("shelf", "post"), extra_parts=("beam", "foot", "sleeve", "bracket"), size_range=(1.0, 2.1),
          density=900, variants=("wire", "industrial"))
def storage_rack(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.9, 1.5), rng.uniform(0.35, 0.6), rng.uniform(1.2, 2.0)
    n = int(rng.integers(3, 6))
    steel = M.metal(rng)
    deck = steel if variant == "wire" else M.wood(rng)
    lip_h = 0.03 if variant == "wire" else 0.04
    z_first = rng.uniform(0.12, 0.2)
    levels = np.linspace(z_first, h - 0.06, n)
    corners = [(sx * (w / 2 + 0.01), sy * (d / 2 + 0.01), sx, sy) for sx, sy in [(-1, -1), (1, -1), (-1, 1), (1, 1)]]
    parts = []
    for i, (x, y, sx, sy) in enumerate(corners):
        if variant == "wire":
            post = S.cylinder(0.0125, h - 0.02, center=(x, y, 0.01 + (h - 0.02) / 2), sections=12)
            parts.append(make_part(f"foot_{i}", "foot", S.frustum(0.016, 0.013, 0.02, center=(x, y, 0),
                                                                    sections=12), black()))
        else:
            a, th = 0.04, 0.004
            post = S.union([S.box((a, th, h), center=(x - sx * (a / 2 - 0.01), y + sy * (0.01 - th / 2), h / 2)),
                            S.box((th, a, h), center=(x + sx * (0.01 - th / 2), y - sy * (a / 2 - 0.01), h / 2))])
        parts.append(make_part(f"post_{i}", "post", post, steel))
    # each shelf reaches back to the backs of the posts (a wire rack's to its sleeves'), its back
    # beam standing on its back edge, so the rack stands flush against a wall by its shelves
    # (``shelf@back``); the deck ends at the beam (a wall round what the shelf holds) and a
    # strip of the shelf runs on under the beam
    x0, y0 = corners[0][:2]
    y_back = min([float(p.bounds[0, 1]) for p in parts]
                 + ([float(_sleeve(x0, y0, 0.0).mesh.bounds[0, 1])] if variant == "wire" else []))
    for i, z in enumerate(levels):
        tk = 0.008 if variant == "wire" else 0.016
        top = z + (0.0 if variant == "wire" else -0.02)
        t = 0.01 if variant == "wire" else 0.02
        y_in = y_back + t
        parts.append(make_part(f"shelf_{i}", "shelf",
                               [S.box((w, d / 2 - y_in, tk), center=(0, (d / 2 + y_in) / 2, top - tk / 2)),
                                S.box((w, t, tk), center=(0, y_back + t / 2, top - tk / 2))], deck))
        parts.append(make_part(f"beam_{i}", "beam", _lip(w, d, top, lip_h, t, y_back=y_back), steel))
        # where the shelf meets each post: a tapered plastic sleeve clamped round a wire rack's
        # post, a gusset bracket bolted inside an angle post's corner
        for j, (x, y, sx, sy) in enumerate(corners):
            if variant == "wire":
                parts.append(make_part(f"sleeve_{4 * i + j}", "sleeve", _sleeve(x, y, top - tk), black()))
            else:
                parts.append(make_part(f"bracket_{4 * i + j}", "bracket",
                                       S.prism([(x, y), (x - sx * 0.06, y), (x, y - sy * 0.06)], top - tk - 0.006, top - tk), steel))
    return parts


@register("grocery_shelf", parts=("shelf", "back_panel"), extra_parts=("post", "base", "price_rail", "end_cap", "price_tag",
                                                                    "glide"),
          size_range=(1.3, 2.3), density=800, variants=("single_sided", "double_sided"))
def grocery_shelf(rng: np.random.Generator, variant: str) -> list[Part]:
    w, h = rng.uniform(0.9, 1.33), rng.uniform(1.4, 2.2)
    sd = rng.uniform(0.3, 0.45)
    n = int(rng.integers(4, 7))
    steel = M.metal(rng) if rng.random() < 0.3 else M.solid(M.jitter(rng, (0.9, 0.9, 0.88), 0.02)[:3], "metal",
                                                             0.4, 0.3)
    sides = (1, -1) if variant == "double_sided" else (1,)
    pt = 0.05  # upright / back-panel assembly depth
    # a wall gondola's back panel is flush with the backs of its uprights (it stands against
    # the wall by it); an island gondola's stands between the uprights, shelved both ways
    y_bp = 0.0 if variant == "double_sided" else -pt / 2 + 0.006
    parts = [make_part("back_panel", "back_panel", S.box((w - 0.08, 0.012, h - 0.15), center=(0, y_bp, 0.15 + (h - 0.15) / 2)),
                       steel)]
    for i, x in enumerate((-w / 2 + 0.02, w / 2 - 0.02)):
        parts.append(make_part(f"post_{i}", "post", S.box((0.04, pt, h - 0.01), center=(x, 0, (h - 0.01) / 2), bevel=0.003), steel))
        # the cap closing the upright's top, 1 mm proud of its sides
        parts.append(make_part(f"end_cap_{i}", "end_cap", S.box((0.042, pt, 0.01), center=(x, 0, h - 0.005)),
                               black()))
    base_h = rng.uniform(0.1, 0.15)
    bd = sd + 0.1
    z_top = h - rng.uniform(0.1, 0.2)
    levels = np.linspace(base_h, z_top, n)
    k = 0
    for si, s in enumerate(sides):
        y_in = s * 0.006
        # the decks reach back to the back panel's face (their fronts where an island's are)
        y_back = y_bp + s * 0.006
        kick = S.box((w - 0.08, 0.02, base_h - 0.02), center=(0, s * (bd - 0.004), (base_h - 0.02) / 2))
        parts.append(make_part(f"base_{si}", "base", kick, steel))
        for j, z in enumerate(levels):
            dd = bd if j == 0 else sd
            y0, y1 = sorted((y_back, y_in + s * dd))
            deck = S.box((w - 0.08, y1 - y0, 0.02), center=(0, (y0 + y1) / 2, z - 0.01))
            shapes = [deck]
            if j > 0:
                for x in (-w / 2 + 0.06, w / 2 - 0.06):
                    yb = y_back + s * 0.002
                    shapes.append(S.hull([[x - 0.005, yb, z - 0.02], [x + 0.005, yb, z - 0.02],
                                          [x - 0.005, y_in + s * dd * 0.8, z - 0.02],
                                          [x + 0.005, y_in + s * dd * 0.8, z - 0.02],
                                          [x - 0.005, yb, z - 0.14], [x + 0.005, yb, z - 0.14]]))
            parts.append(make_part(f"shelf_{k}", "shelf", shapes, steel))
            y_rail = y_in + s * (dd + 0.006)
            rail_mat = M.solid((0.85, 0.2, 0.15) if s > 0 else (0.2, 0.35, 0.7), "plastic")
            parts.append(make_part(f"price_rail_{k}", "price_rail",
                                   S.box((w - 0.08, 0.012, 0.045), center=(0, y_rail, z + 0.045 / 2 - 0.025)),
                                   rail_mat))
            # the paper price tickets slid into the rail's channel, flush with its face
            parts += [make_part(f"price_tag_{2 * k + i}", "price_tag", S.box((0.07, 0.001, 0.03),
                                                                            center=(x, y_rail + s * 0.0055, z + 0.045 / 2 - 0.025)),
                                M.solid((0.97, 0.96, 0.9), "paper", 0.8))
                      for i, x in enumerate((-(w - 0.08) * 0.25, (w - 0.08) * 0.25))]
            k += 1
    # a levelling foot under each upright
    parts += _glides((-w / 2 + 0.02, w / 2 - 0.02), (0.0,))
    return parts
