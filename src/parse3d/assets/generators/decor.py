"""Wall decor and plants: picture frames, mirrors, wall clocks and potted plants.

Wall items are built with their flat back on the plane y = 0 and their face towards +Y, so the
back (−Y) can be pressed against a wall. Frames are four mitred bars with a chamfered front;
round rims are revolved rings (:func:`parse3d.assets.generators.lamps.shell`) turned to face +Y.
Pictures, mirror glass and clock dials fill most of their frame's depth, so no ledge inside a
frame is mistaken for an internal support surface.

Potted plants are one category with one placement, ``floor``: the ``bush`` and ``leafy``
variants (0.3–0.8 m) also suit a low table, the ``tree`` variant (1.1–1.6 m) only the floor.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from ...geometry.frames import make_transform, rot_x, rot_y, rot_z
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring
from .lamps import shell

#: Turns a shape built along +Z (from z = 0) so that it points along +Y (from y = 0).
_FACE_FRONT = rot_x(-np.pi / 2)


def _mitred_frame(w: float, h: float, bar: float, depth: float, chamfer: float,
                  backing: float = 0.0) -> list[S.Shape]:
    """Four mitred bars of a ``w`` x ``h`` frame in the XZ plane (centred at x = 0, z = h / 2),
    from y = ``backing`` to y = ``depth`` (front), each bar's front chamfered by ``chamfer``;
    with ``backing`` > 0 a full board closes the back from y = 0, so the whole back is one flat
    patch (what is pressed against the wall)."""
    def rect(hw, hh):
        return np.array([(-hw, -hh), (hw, -hh), (hw, hh), (-hw, hh)]) + (0, h / 2)

    outer, inner = rect(w / 2, h / 2), rect(w / 2 - bar, h / 2 - bar)
    outer_f = rect(w / 2 - chamfer, h / 2 - chamfer)
    inner_f = rect(w / 2 - bar + chamfer, h / 2 - bar + chamfer)
    bars = []
    for i in range(4):
        j = (i + 1) % 4
        back = np.array([outer[i], outer[j], inner[j], inner[i]])
        front = np.array([outer_f[i], outer_f[j], inner_f[j], inner_f[i]])
        pts = np.vstack([np.c_[back[:, 0], np.full(4, backing), back[:, 1]],
                         np.c_[front[:, 0], np.full(4, depth), front[:, 1]]])
        bars.append(S.hull(pts))
    if backing > 0:
        bars.append(S.box((w, backing, h), center=(0, backing / 2, h / 2)))
    return bars


#: The mitred frame's pieces, in :func:`_mitred_frame`'s order: (name, label).
_FRAME_PIECES = (("rail_bottom", "rail"), ("stile_right", "stile"), ("rail_top", "rail"),
                 ("stile_left", "stile"), ("backing", "backing"))


def _frame_parts(bars: list[S.Shape], mat: Material, rng) -> list[Part]:
    """The frame's four mitred bars and its backing board as parts (the ``frame`` group; a round
    or oval mirror's frame is one turned ring, a part labelled ``frame`` itself)."""
    board = M.solid(M.jitter(rng, (0.55, 0.45, 0.32), 0.03), "wood", 0.9)
    return [make_part(n, lab, b, board if lab == "backing" else mat)
            for (n, lab), b in zip(_FRAME_PIECES, bars, strict=True)]


def _hangers(w: float, h: float, bk: float, n: int) -> list[Part]:
    """``n`` D-ring hangers screwed to the backing board near its top, flush with the back."""
    metal = M.solid((0.7, 0.7, 0.68), "metal", 0.4, 0.9)
    xs = [0.0] if n == 1 else [-w * 0.3, w * 0.3]
    return [make_part(f"hanger_{k}", "hanger",
                      S.box((0.025, min(bk, 0.002), 0.018), center=(x, min(bk, 0.002) / 2, h * 0.82)),
                      metal) for k, x in enumerate(xs)]


def _back_fittings(w: float, h: float, bk: float, *, wire: bool, z_bottom: float) -> list[Part]:
    """The felt ``bumper`` pads at the back's two lower corners (a frame ``w`` wide; ``z_bottom``
    their height) and, with ``wire``, the picture ``wire`` strung between two hangers at
    ``h * 0.82`` (see :func:`_hangers`); all flush with the back, as the hangers are."""
    felt = M.solid((0.2, 0.2, 0.2), "fabric", 0.95)
    tb = min(bk, 0.0015)
    out = [make_part(f"bumper_{k}", "bumper", S.cylinder(0.006, tb, center=(sx, tb / 2, z_bottom), axis=(0, 1, 0), sections=10),
                     felt) for k, sx in enumerate((-w * 0.38, w * 0.38))]
    if wire:
        out.append(make_part("wire", "wire", S.cylinder(0.0008, w * 0.6, center=(0, tb / 2, h * 0.82 - 0.006), axis=(1, 0, 0),
                                                      sections=6), M.solid((0.7, 0.7, 0.68), "metal", 0.4, 0.9)))
    return out


def _ring(r_out: float, width: float, depth: float, *, cz: float = 0.0, stretch: float = 1.0,
          sections: int = 28) -> S.Shape:
    """A flat ring facing +Y, back on y = 0, centred at (0, cz) in XZ; ``stretch`` scales it
    along z (an oval)."""
    lin = np.diag([1.0, 1.0, stretch]) @ _FACE_FRONT
    return shell([(r_out, 0.0), (r_out, depth)], width, sections=sections, linear=lin,
                 offset=(0, 0, cz))


def _disc(r: float, y0: float, y1: float, *, cz: float = 0.0, stretch: float = 1.0,
          sections: int = 28) -> S.Shape:
    """A disc facing +Y between y0 and y1, centred at (0, cz) in XZ, scaled by ``stretch``
    along z."""
    a = np.linspace(0, 2 * np.pi, sections, endpoint=False)
    xz = np.c_[r * np.cos(a), cz + stretch * r * np.sin(a)]
    return S.hull(np.vstack([np.c_[xz[:, 0], np.full(sections, y), xz[:, 1]] for y in (y0, y1)]))


def _frame_material(rng) -> Material:
    r = rng.random()
    if r < 0.55:
        return M.wood(rng)
    if r < 0.8:
        return M.metal(rng)
    return M.solid((0.1, 0.1, 0.1) if rng.random() < 0.5 else (0.95, 0.95, 0.93), "plastic", 0.5)


@register("picture_frame", parts=("frame", "canvas"), extra_parts=("mat", "glazing", "hanger", "turn_button", "bumper", "wire",
                                                                    "screw"),
          size_range=(0.2, 1.2), density=500, variants=("landscape", "portrait", "square"),
          placement="wall", groups={"frame": ("rail", "stile", "backing")})
def picture_frame(rng: np.random.Generator, variant: str) -> list[Part]:
    long = rng.uniform(0.25, 1.1)
    ratio = 1.0 if variant == "square" else rng.uniform(1.25, 1.6)
    w, h = (long, long / ratio) if variant == "landscape" else (long / ratio, long)
    bar = min(w, h) * rng.uniform(0.06, 0.12)
    depth = rng.uniform(0.018, 0.035)
    bk = rng.uniform(0.003, 0.005)
    parts = _frame_parts(_mitred_frame(w, h, bar, depth, bar * 0.25, bk), _frame_material(rng), rng)
    iw, ih = w - 2 * bar, h - 2 * bar
    # the glass in front of the picture, held in the frame's rebate
    parts.append(make_part("glazing", "glazing", S.box((iw, 0.002, ih), center=(0, depth - 0.0035, h / 2)),
                           M.glass(rng)))
    parts += _hangers(w, h, bk, 1 if w < 0.5 else 2)
    parts += _back_fittings(w, h, bk, wire=w >= 0.5, z_bottom=bar * 0.5)
    # the canvas (and the mat in front of it) fill most of the frame depth in front of the
    # backing board, so no ledge is left inside the frame
    t = (depth - bk) * rng.uniform(0.65, 0.8)
    if rng.random() < 0.5:  # a passe-partout board around a smaller picture
        m = min(iw, ih) * rng.uniform(0.1, 0.18)
        mat_c = M.solid(M.jitter(rng, (0.95, 0.94, 0.9), 0.01), "paper", 0.9)
        yc = bk + t / 2
        board = [S.box((iw, t, m), center=(0, yc, bar + m / 2)),
                 S.box((iw, t, m), center=(0, yc, h - bar - m / 2)),
                 S.box((m, t, ih - 2 * m), center=(-iw / 2 + m / 2, yc, h / 2)),
                 S.box((m, t, ih - 2 * m), center=(iw / 2 - m / 2, yc, h / 2))]
        parts.append(make_part("mat", "mat", board, mat_c))
        iw, ih = iw - 2 * m, ih - 2 * m
    canvas = S.box((iw, t * 0.9, ih), center=(0, bk + t * 0.45, h / 2))
    parts.append(make_part("canvas", "canvas", canvas, M.paper(rng)))
    # the turn buttons on the back holding the backing board in, one mid-way along each side,
    # flush with the back like the hangers
    steel = M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8)
    ib = min(bk, 0.0015)
    for k, (x, z) in enumerate([(0, bar * 0.6), (0, h - bar * 0.6), (-w / 2 + bar * 0.6, h / 2), (w / 2 - bar * 0.6, h / 2)]):
        parts.append(make_part(f"turn_button_{k}", "turn_button", S.box((0.012, ib, 0.012), center=(x, ib / 2, z)), steel))
    parts += _more_turn_buttons(w, h, bar, ib, steel, start=4)
    parts += _hanger_screws(w, h, bk, 1 if w < 0.5 else 2)
    return parts


def _more_turn_buttons(w: float, h: float, bar: float, ib: float, mat: Material, *, start: int) -> list[Part]:
    """The second pair of turn buttons on each side of a frame's back: a frame is held shut
    every quarter of its length, not only mid-way (``ib`` thick, flush with the back)."""
    spots = [(sx * w / 4, z) for z in (bar * 0.6, h - bar * 0.6) for sx in (-1, 1)]
    spots += [(sx * (w / 2 - bar * 0.6), z) for sx in (-1, 1) for z in (h / 4, 3 * h / 4)]
    return [make_part(f"turn_button_{start + k}", "turn_button", S.box((0.012, ib, 0.012), center=(x, ib / 2, z)), mat)
            for k, (x, z) in enumerate(spots)]


def _hanger_screws(w: float, h: float, bk: float, n: int, *, start: int = 0) -> list[Part]:
    """The screw through the strap of each of the ``n`` D-ring hangers of :func:`_hangers`,
    just below the ring, its head flush with the back."""
    metal = M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8)
    xs = [0.0] if n == 1 else [-w * 0.3, w * 0.3]
    tb = min(bk, 0.002)
    return [make_part(f"screw_{start + k}", "screw", S.cylinder(0.003, tb, center=(x, tb / 2, h * 0.82 - 0.005), axis=(0, 1, 0),
                                                                sections=8), metal) for k, x in enumerate(xs)]


def _mirror_glass() -> Material:
    return Material((0.86, 0.89, 0.91, 1.0), 0.02, 1.0, "glass")


@register("mirror", parts=("frame", "glass"), extra_parts=("hanger", "bevel", "screw", "bumper", "wire", "turn_button"),
          size_range=(0.3, 1.8),
          density=1200, variants=("rectangular", "round", "oval"), placement="wall",
          groups={"frame": ("frame", "rail", "stile", "backing")})
def mirror(rng: np.random.Generator, variant: str) -> list[Part]:
    depth = rng.uniform(0.02, 0.04)
    # the glass part is the mirror glass on its backing board, nearly flush with the frame
    t_glass = depth * rng.uniform(0.65, 0.8)
    mat = _frame_material(rng)
    if variant == "rectangular":
        w = rng.uniform(0.4, 0.8)
        h = w * rng.uniform(1.2, 2.2) if rng.random() < 0.8 else w * rng.uniform(0.6, 0.8)
        bar = rng.uniform(0.03, 0.07)
        bk = 0.004
        frame = _mitred_frame(w, h, bar, depth, bar * 0.3, bk)
        glass = S.box((w - 2 * bar, t_glass - bk, h - 2 * bar), center=(0, (t_glass + bk) / 2, h / 2))
        # the ground bevel round the glass's edge, flush with its face inside the frame
        iw, ih, bw = w - 2 * bar, h - 2 * bar, min(0.02, (w - 2 * bar) * 0.05)
        yb = t_glass - 0.0005
        bevel = [S.box((iw, 0.001, bw), center=(0, yb, bar + bw / 2)), S.box((iw, 0.001, bw), center=(0, yb, h - bar - bw / 2)),
                 S.box((bw, 0.001, ih - 2 * bw), center=(-iw / 2 + bw / 2, yb, h / 2)),
                 S.box((bw, 0.001, ih - 2 * bw), center=(iw / 2 - bw / 2, yb, h / 2))]
        return [*_frame_parts(frame, mat, rng), make_part("glass", "glass", glass, _mirror_glass()),
                make_part("bevel", "bevel", bevel, _mirror_glass()),
                *_hangers(w, h, bk, 2), *_back_fittings(w, h, bk, wire=True, z_bottom=bar * 0.5),
                # the turn buttons holding the glass and its backing in the frame, and the
                # screw through each hanger's strap
                *_more_turn_buttons(w, h, bar, 0.0015, M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8), start=0),
                *_hanger_screws(w, h, bk, 2)]
    r = rng.uniform(0.2, 0.45)
    width = r * rng.uniform(0.08, 0.18)
    k = rng.uniform(1.3, 1.7) if variant == "oval" else 1.0
    frame = _ring(r, width, depth, stretch=k)
    glass = _disc(r - width, 0.0, t_glass, stretch=k)
    # a keyhole hanger plate on the back of the frame's top
    zh = r * k - width / 2
    hanger = S.box((0.03, 0.002, 0.02), center=(0, 0.001, zh))
    metal = M.solid((0.7, 0.7, 0.68), "metal", 0.4, 0.9)
    # the glass's ground bevel round its edge, and the two screws holding the hanger plate
    bevel = _ring(r - width, min(0.02, r * 0.08), 0.0015, stretch=k).moved((0, t_glass - 0.001, 0))
    return [make_part("frame", "frame", frame, mat),
            make_part("glass", "glass", glass, _mirror_glass()),
            make_part("bevel", "bevel", bevel, _mirror_glass()),
            make_part("hanger", "hanger", hanger, metal),
            *[make_part(f"screw_{j}", "screw", S.cylinder(0.0025, 0.0015, center=(sx * 0.01, 0.00275, zh), axis=(0, 1, 0),
                                                          sections=8), metal) for j, sx in enumerate((-1, 1))],
            *_back_fittings(r * 1.2, 2 * r * k, 0.0015, wire=False, z_bottom=-r * k * 0.7),
            # the four turn buttons on the frame's back holding the glass in, on its diagonals
            *[make_part(f"turn_button_{j}", "turn_button",
                        S.box((0.012, 0.0015, 0.012), center=(sx * (r - width / 2) * 0.7071, 0.00075, sz * (r - width / 2) * 0.7071 * k)),
                        metal) for j, (sx, sz) in enumerate(((-1, 1), (1, 1), (-1, -1), (1, -1)))]]


def _hands(rng, r_face: float, y: float, cz: float) -> list[Part]:
    """Hour (``hands``, as the three once were one part), minute and (sometimes) second hands,
    all labelled ``hand``, on a face of radius ``r_face`` whose front is at ``y``, centred at
    (0, cz), and the ``hub`` nut holding them; angles run clockwise as seen from the front."""
    dark = M.solid((0.08, 0.08, 0.08), "metal", 0.4, 0.6)
    specs = [(0.5, 0.06, 0.002), (0.78, 0.04, 0.002)]
    if rng.random() < 0.6:
        specs.append((0.88, 0.012, 0.0015))
    hands = []
    for k, (length, width, thick) in enumerate(specs):
        theta = rng.uniform(0, 2 * np.pi)
        L = r_face * length
        tail = L * 0.15
        d = np.array([-np.sin(theta), np.cos(theta)])  # viewer's clockwise is towards -X
        c = (L / 2 - tail) * d
        yk = y + thick / 2 + k * 0.0025
        hands.append(S.box((max(width * r_face, 0.002), thick, L), center=(c[0], yk, cz + c[1]),
                           R=rot_y(-theta)))
    names = ("hands", "minute_hand", "second_hand")
    out = [make_part(names[k], "hand", h, dark) for k, h in enumerate(hands)]
    out.append(make_part("hub", "hub", _disc(0.008, y, y + 0.003 * len(specs) + 0.002, cz=cz, sections=12), dark))
    return out


def _ticks(r: float, y: float, cz: float) -> list[Part]:
    marks = []
    for k in range(12):
        a = 2 * np.pi * k / 12
        L = r * (0.12 if k % 3 == 0 else 0.07)
        c = (r * 0.9 - L / 2) * np.array([-np.sin(a), np.cos(a)])
        marks.append(S.box((0.006 if k % 3 == 0 else 0.004, 0.0015, L),
                           center=(c[0], y + 0.00075, cz + c[1]), R=rot_y(-a)))
    return [make_part(f"marker_{k}", "marker", m, M.solid((0.1, 0.1, 0.1), "plastic")) for k, m in enumerate(marks)]


@register("wall_clock", parts=("body", "face"), extra_parts=("hand", "marker", "hub", "crystal"),
          size_range=(0.2, 0.6), density=600, variants=("round", "square"), placement="wall")
def wall_clock(rng: np.random.Generator, variant: str) -> list[Part]:
    depth = rng.uniform(0.035, 0.06)
    back = rng.uniform(0.005, 0.01)
    rim = rng.uniform(0.01, 0.03)
    face_mat = M.solid(M.jitter(rng, (0.96, 0.95, 0.92), 0.02), "paper", 0.7)
    body_mat = _frame_material(rng)
    # the dial plate fills most of the body's depth (no ledge inside the rim), hands in front
    face_y = depth * rng.uniform(0.6, 0.7)
    if variant == "round":
        r = rng.uniform(0.12, 0.25)
        ring = shell([(r, back), (r, depth)], rim, sections=28,
                     linear=_FACE_FRONT, offset=(0, 0, r))
        body = [ring, _disc(r, 0.0, back, cz=r)]
        face = _disc(r - rim, back, face_y, cz=r)
        r_face, cz = r - rim, r
    else:
        a = rng.uniform(0.22, 0.45)
        body = _mitred_frame(a, a, rim, depth, rim * 0.2, back)
        face = S.box((a - 2 * rim, face_y - back, a - 2 * rim), center=(0, (face_y + back) / 2, a / 2))
        r_face, cz = a / 2 - rim, a / 2
    parts = [make_part("body", "body", body, body_mat), make_part("face", "face", face, face_mat),
             *_ticks(r_face, face_y, cz), *_hands(rng, r_face, face_y, cz)]
    # the glass crystal over the dial, set just inside the rim's front edge
    glass = M.glass(rng)
    # (clear of the hub's nut: on a shallow case the crystal domes a little proud of the rim)
    yc0 = max(depth - 0.004, float(parts[-1].mesh.bounds[1, 1]) + 0.0005)
    yc1 = yc0 + 0.002
    if variant == "round":
        crystal = _disc(r - rim, yc0, yc1, cz=r)
    else:
        crystal = S.box((a - 2 * rim, yc1 - yc0, a - 2 * rim), center=(0, (yc0 + yc1) / 2, a / 2))
    parts.append(make_part("crystal", "crystal", crystal, glass))
    return parts


def _soil() -> Material:
    return Material((0.24, 0.17, 0.11, 1.0), 0.95, 0.0, "plant")


def _pot(rng, r_top: float, h: float) -> tuple[list[Part], float, float]:
    """A plant pot with soil; returns its parts, the soil's top z and its radius."""
    t = rng.uniform(0.008, 0.014)
    mat = M.ceramic(rng) if rng.random() < 0.6 else M.solid(M.jitter(rng, (0.72, 0.38, 0.24)),
                                                            "ceramic", 0.8)
    z_soil = h - rng.uniform(0.025, 0.045)
    if rng.random() < 0.7:
        r_bot = r_top * rng.uniform(0.7, 0.85)
        h_rim = h * rng.uniform(0.1, 0.18)
        r_rim = r_top - h_rim * (r_top - r_bot) / h
        wall = shell([(r_bot, 0.0), (r_rim, h - h_rim)], t, sections=16)
        lip = shell([(r_top, h - h_rim), (r_top, h)], r_top - r_rim + t, sections=16)
        floor = S.cylinder(r_bot - t * 0.5, t, center=(0, 0, t / 2), sections=16)
        pot = [wall, lip, floor]
        r_in = r_bot + (r_rim - r_bot) * min(z_soil / (h - h_rim), 1.0) - t - 0.002
        soil = S.lathe([(r_bot - t - 0.002, t), (r_in, z_soil)], sections=16)
        # the drip tray the pot stands in: its floor is under the pot's (on the same ground), its
        # sloping edge shows round the foot
        saucer = ring([(r_bot - 0.002, 0.0), (r_bot + 0.025, 0.0), (r_bot + 0.02, 0.012), (r_bot - 0.002, 0.012)],
                      sections=16)
    else:  # square planter
        a = r_top * 2
        pot = [S.box((a, t, h), center=(0, a / 2 - t / 2, h / 2), bevel=0.002),
               S.box((a, t, h), center=(0, -a / 2 + t / 2, h / 2), bevel=0.002),
               S.box((t, a - 2 * t, h), center=(a / 2 - t / 2, 0, h / 2)),
               S.box((t, a - 2 * t, h), center=(-a / 2 + t / 2, 0, h / 2)),
               S.box((a - 2 * t, a - 2 * t, t), center=(0, 0, t / 2))]
        r_in = a / 2 - t
        soil = S.box((a - 2 * t, a - 2 * t, z_soil - t), center=(0, 0, (z_soil + t) / 2))
        saucer = None  # a square planter stands on its own floor
    parts = [make_part("pot", "pot", pot, mat), make_part("soil", "soil", soil, _soil())]
    if saucer is not None:
        parts.append(make_part("saucer", "saucer", saucer, mat))
    return parts, z_soil, r_in


def _blobs(rng, n: int, center, spread, size) -> list[S.Shape]:
    """``n`` overlapping ellipsoids scattered around ``center`` (3,) within ``spread`` (3,)."""
    out = []
    for _ in range(n):
        c = np.asarray(center) + rng.uniform(-1, 1, 3) * spread
        r = size * rng.uniform(0.7, 1.2, 3) * (1, 1, 0.8)
        out.append(S.ellipsoid(r, center=c, subdivisions=1))
    return out


@register("potted_plant", parts=("pot", "plant"), extra_parts=("soil", "trunk", "saucer", "stake", "tie"), size_range=(0.15, 1.8),
          density=400, variants=("bush", "tree", "leafy", "herb"))
def potted_plant(rng: np.random.Generator, variant: str) -> list[Part]:
    """A plant in a pot: a bush, a tree, a leafy plant on a stake, or a herb in a small pot (9-13 cm
    across, the kind on a kitchen window sill) whose leaves reach a little past its rim."""
    green = M.plant(rng)
    if variant == "herb":
        r_top, h_pot = rng.uniform(0.045, 0.065), rng.uniform(0.08, 0.12)
        parts, z0, r_in = _pot(rng, r_top, h_pot)
        size = rng.uniform(0.05, 0.08)
        leaves = _blobs(rng, int(rng.integers(6, 10)), (0, 0, z0 + size * 1.1),
                        (r_top * 0.7, r_top * 0.7, size * 0.7), size * 0.55)
    elif variant == "tree":
        r_top, h_pot = rng.uniform(0.16, 0.24), rng.uniform(0.28, 0.42)
        parts, z0, r_in = _pot(rng, r_top, h_pot)
        top = rng.uniform(1.1, 1.6)
        crown = rng.uniform(0.3, 0.45)
        bend = rng.uniform(-0.04, 0.04, 2)
        zs = np.linspace(z0 - 0.02, top - crown * 1.1, 5)
        path = np.c_[bend[0] * np.sin(np.linspace(0, np.pi, 5)), bend[1] * np.sin(np.linspace(0, np.pi, 5)), zs]
        trunk = S.tube(path, rng.uniform(0.015, 0.025), sections=8)
        leaves = _blobs(rng, int(rng.integers(7, 11)), path[-1] + (0, 0, crown * 0.45),
                        (crown * 0.55, crown * 0.55, crown * 0.35), crown * 0.5)
        parts.append(make_part("trunk", "trunk", trunk, M.solid(M.jitter(rng, (0.38, 0.27, 0.18)),
                                                                "wood", 0.8)))
    elif variant == "bush":
        r_top, h_pot = rng.uniform(0.1, 0.2), rng.uniform(0.14, 0.3)
        parts, z0, r_in = _pot(rng, r_top, h_pot)
        size = r_top * rng.uniform(0.7, 1.0)
        leaves = _blobs(rng, int(rng.integers(6, 10)), (0, 0, z0 + size * 0.9),
                        (r_top * 0.8, r_top * 0.8, size * 0.5), size * 0.6)
    else:
        r_top, h_pot = rng.uniform(0.09, 0.17), rng.uniform(0.15, 0.3)
        parts, z0, r_in = _pot(rng, r_top, h_pot)
        n = int(rng.integers(7, 12))
        leaves = []
        for k in range(n):
            L = rng.uniform(0.25, 0.7)
            tilt = rng.uniform(0.05, 0.45)
            yaw = 2 * np.pi * k / n + rng.uniform(-0.3, 0.3)
            leaf = S.ellipsoid((rng.uniform(0.025, 0.045), 0.006, L / 2), center=(0, 0, L / 2),
                               subdivisions=1)
            base = np.array([np.cos(yaw), np.sin(yaw)]) * r_in * 0.4
            T = make_transform(rot_z(yaw) @ rot_y(tilt), (base[0], base[1], z0 - 0.03))
            leaves.append(leaf.apply(T))
        # the bamboo stake the leaves are tied to, and its tie
        hs = rng.uniform(0.3, 0.45)
        parts.append(make_part("stake", "stake", S.cylinder(0.004, hs, center=(r_in * 0.3, 0, z0 - 0.05 + hs / 2), sections=6),
                               M.solid(M.jitter(rng, (0.75, 0.65, 0.4), 0.03), "wood", 0.8)))
        parts.append(make_part("tie", "tie", S.cylinder(0.008, 0.006, center=(r_in * 0.3, 0, z0 - 0.05 + hs * 0.7), sections=8),
                               M.solid((0.3, 0.5, 0.2), "fabric", 0.9)))
    # every leaf or foliage clump is a part of its own, all labelled ``plant``
    parts += [make_part(f"plant_{k}", "plant", leaf, green) for k, leaf in enumerate(leaves)]
    return parts

