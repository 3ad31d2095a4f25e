"""Chess: boards and pieces.

A chess board lies flat, its playing ``board`` the top (``chess_board:board@top`` is where the
pieces stand), the dark ``square``s inlaid in it; a folding board has a hinge across its middle.
A piece stands on its weighted ``base``; ``body`` is its turned stem and ``head`` what tells
the pieces apart (a king's cross, a queen's coronet, a rook's turret, a bishop's mitre, a
knight's horse head, a pawn's ball).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring
from ._kit import hinge_parts, rot


@register("chess_board", parts=("board", "square"), extra_parts=("frame", "hinge", "foot"),
          size_range=(0.25, 0.6), density=700, variants=("flat", "folding", "roll_up"), placement="surface")
def chess_board(rng: np.random.Generator, variant: str) -> list[Part]:
    sq = rng.uniform(0.04, 0.057) if variant != "roll_up" else rng.uniform(0.05, 0.057)
    b = rng.uniform(0.015, 0.03) if variant != "roll_up" else 0.01
    w = 8 * sq + 2 * b
    t = rng.uniform(0.012, 0.02) if variant != "roll_up" else 0.002
    light = Material(M.jitter(rng, (0.85, 0.72, 0.5), 0.03), 0.5, 0.0, "wood") if variant != "roll_up" else \
        M.solid((0.92, 0.92, 0.85), "plastic", 0.6)
    dark = Material(M.jitter(rng, (0.35, 0.2, 0.1), 0.03), 0.5, 0.0, "wood") if variant != "roll_up" else \
        M.solid((0.15, 0.4, 0.2), "plastic", 0.6)
    zf = 0.004 if variant == "flat" else 0.0
    parts = [make_part("board", "board", S.box((8 * sq, 8 * sq, t), center=(0, 0, zf + t / 2)), light)]
    if variant != "roll_up":
        frame = [S.box((w, b, t), center=(0, sy * (w / 2 - b / 2), zf + t / 2)) for sy in (-1, 1)]
        frame += [S.box((b, 8 * sq, t), center=(sx * (w / 2 - b / 2), 0, zf + t / 2)) for sx in (-1, 1)]
        parts.append(make_part("frame", "frame", frame, dark))
    else:
        frame = [S.box((w, b, t), center=(0, sy * (w / 2 - b / 2), t / 2)) for sy in (-1, 1)]
        frame += [S.box((b, 8 * sq, t), center=(sx * (w / 2 - b / 2), 0, t / 2)) for sx in (-1, 1)]
        parts.append(make_part("frame", "frame", frame, light))
    k = 0
    for i in range(8):
        for j in range(8):
            if (i + j) % 2 == 0:  # a1 (bottom left, white's side at -Y) is dark
                parts.append(make_part(f"square_{k}", "square", S.box((sq, sq, 0.0006), center=(-4 * sq + sq * (i + 0.5), -4 * sq + sq * (j + 0.5),
                                                                                               zf + t + 0.0003)), dark))
                k += 1
    if variant == "flat":
        for n, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"foot_{n}", "foot", S.cylinder(0.01, zf, center=(sx * (w / 2 - 0.02), sy * (w / 2 - 0.02), zf / 2),
                                                                   sections=10), M.solid((0.1, 0.1, 0.1), "fabric", 0.9)))
    if variant == "folding":
        parts += hinge_parts("hinge", x=-w / 2 - 0.004, y=0.0, z0=0.002, z1=t - 0.002, mat=M.solid((0.78, 0.62, 0.3), "metal", 0.3, 0.9),
                             n=2, radius=0.004, length=0.006)
    return parts


@register("chess_piece", parts=("base", "body", "head"), extra_parts=("collar", "felt", "cross", "finial", "merlon", "ear", "bead",
                                                                      "mane", "point"),
          size_range=(0.03, 0.12), density=900,
          variants=("royal", "minor", "rook", "pawn"), placement="surface")
def chess_piece(rng: np.random.Generator, variant: str) -> list[Part]:
    # royal: a king or a queen; minor: a bishop or a knight
    kind = {"royal": ("king", "queen"), "minor": ("bishop", "knight")}.get(variant, (variant,))
    variant = kind[int(rng.integers(len(kind)))]
    white = rng.random() < 0.5
    mat = Material(M.jitter(rng, (0.9, 0.82, 0.62) if white else (0.12, 0.08, 0.06), 0.02), 0.35, 0.0, "wood")
    H = {"king": 0.095, "queen": 0.085, "bishop": 0.07, "knight": 0.06, "rook": 0.055, "pawn": 0.048}[variant]
    H *= rng.uniform(0.9, 1.1)
    rb = H * (0.22 if variant != "pawn" else 0.27)
    parts = [make_part("felt", "felt", S.cylinder(rb * 0.95, 0.0015, center=(0, 0, 0.00075), sections=16),
                       M.solid((0.1, 0.3, 0.15), "fabric", 0.95))]
    z0 = 0.0015
    hb = H * 0.14
    parts.append(make_part("base", "base", S.lathe([(0.0005, z0), (rb, z0), (rb, z0 + hb * 0.5), (rb * 0.8, z0 + hb),
                                                    (0.0005, z0 + hb)], sections=16), mat))
    zb = z0 + hb
    # the turned bead round the top of the base
    parts.append(make_part("bead", "bead", ring([(rb * 0.78, zb - hb * 0.3), (rb * 0.86, zb - hb * 0.2), (rb * 0.86, zb - hb * 0.05),
                                                 (rb * 0.78, zb)], sections=16), mat))
    if variant == "knight":  # a short stem and a horse's head leaning forward (+Y)
        hs = H * 0.2
        parts.append(make_part("body", "body", S.frustum(rb * 0.75, rb * 0.55, hs, center=(0, 0, zb), sections=16), mat))
        zh = zb + hs
        head = S.hull(np.array([[sx * rb * 0.35, -rb * 0.5, zh] for sx in (-1, 1)] + [[sx * rb * 0.35, rb * 0.5, zh] for sx in (-1, 1)]
                               + [[sx * rb * 0.3, -rb * 0.3, zb + H * 0.85] for sx in (-1, 1)]
                               + [[sx * rb * 0.25, rb * 0.85, zb + H * 0.6] for sx in (-1, 1)]
                               + [[sx * rb * 0.2, rb * 0.2, z0 + H] for sx in (-1, 1)]))
        parts.append(make_part("head", "head", head, mat))
        # the two pricked ears behind the forelock
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"ear_{k}", "ear", S.frustum(rb * 0.1, rb * 0.02, H * 0.1,
                                                                center=(sx * rb * 0.15, -rb * 0.2, zb + H * 0.8), sections=6), mat))
        # the carved mane down the back of the neck
        parts.append(make_part("mane", "mane", S.hull(np.array([[sx * rb * 0.12, -rb * 0.42, z] for sx in (-1, 1)
                                                                for z in (zh + H * 0.05, zb + H * 0.75)]
                                                               + [[sx * rb * 0.12, -rb * 0.55, zh + H * 0.1] for sx in (-1, 1)])), mat))
        return parts
    stem_top = {"king": 0.62, "queen": 0.6, "bishop": 0.55, "rook": 0.55, "pawn": 0.42}[variant] * H
    rs0, rs1 = rb * 0.6, rb * (0.32 if variant != "rook" else 0.55)
    parts.append(make_part("body", "body", S.frustum(rs0, rs1, stem_top - hb, center=(0, 0, zb), sections=16), mat))
    zc = z0 + stem_top
    rc = rs1 * 1.45 if variant != "rook" else rs1 * 1.15
    # the thinner fillet turned just under the collar
    zf = zc - H * 0.04
    rf_ = float(np.interp(zf, [zb, zc], [rs0, rs1])) + H * 0.008
    parts.append(make_part("collar_1", "collar", S.cylinder(rf_, H * 0.02, center=(0, 0, zf), sections=16), mat))
    parts.append(make_part("collar", "collar", S.cylinder(rc, H * 0.04, center=(0, 0, zc + H * 0.02), sections=16), mat))
    zh = zc + H * 0.04
    top = z0 + H
    if variant == "pawn":
        rp = (top - zh) / 2
        head = S.ellipsoid((rp, rp, rp), center=(0, 0, zh + rp), subdivisions=2)
    elif variant == "rook":
        head = S.cylinder(rb * 0.62, top - zh, center=(0, 0, (zh + top) / 2), sections=8)
    elif variant == "bishop":
        head = S.ellipsoid((rs1 * 1.2, rs1 * 1.2, (top - zh) / 2), center=(0, 0, (zh + top) / 2), subdivisions=2)
    elif variant == "queen":
        head = S.lathe([(0.0005, zh), (rs1 * 1.0, zh), (rs1 * 1.6, top - H * 0.08), (rs1 * 0.6, top - H * 0.02), (0.0005, top)],
                       sections=16)
    else:  # king: a crown with a cross above
        zcr = top - H * 0.12
        head = S.lathe([(0.0005, zh), (rs1 * 1.0, zh), (rs1 * 1.5, zcr), (0.0005, zcr)], sections=16)
        parts.append(make_part("cross", "cross", [S.box((H * 0.03, H * 0.03, H * 0.12), center=(0, 0, zcr + H * 0.06)),
                                                  S.box((H * 0.09, H * 0.03, H * 0.03), center=(0, 0, zcr + H * 0.075))], mat))
    parts.append(make_part("head", "head", head, mat))
    if variant == "rook":  # the four merlons of the battlement
        rr = rb * 0.62
        for k, a in enumerate(np.linspace(0, 2 * np.pi, 4, endpoint=False) + np.pi / 4):
            parts.append(make_part(f"merlon_{k}", "merlon", S.box((rr * 0.55, rr * 0.35, H * 0.08),
                                                                  center=(np.cos(a) * rr * 0.78, np.sin(a) * rr * 0.78, top + H * 0.04),
                                                                  R=rot((0, 0, 1), a)), mat))
    elif variant in ("queen", "bishop"):  # the ball finial on top
        rf = H * 0.045
        parts.append(make_part("finial", "finial", S.ellipsoid((rf, rf, rf), center=(0, 0, top + rf * 0.6), subdivisions=1), mat))
    if variant == "queen":  # the eight carved points of the coronet round the crown's rim
        zc_ = top - H * 0.08
        for k, a in enumerate(np.linspace(0, 2 * np.pi, 8, endpoint=False)):
            c = np.array([np.cos(a), np.sin(a)]) * rs1 * 1.5
            parts.append(make_part(f"point_{k}", "point", S.frustum(H * 0.018, H * 0.004, H * 0.05, center=(c[0], c[1], zc_ - H * 0.01),
                                                                   sections=6), mat))
    return parts
