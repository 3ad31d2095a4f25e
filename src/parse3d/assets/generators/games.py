"""The game room: arcade cabinets, dart boards, foosball and card tables, board games and toys.

A dart board cabinet's doors are revolute joints hinged on its outer edges; a boxed board game's
lid is a separate part that lifts off.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._casework import black, felt
from ._kit import OPEN_DOOR, hinge_parts, legs4, revolute, rot


@register("arcade_cabinet", parts=("body", "screen", "control_panel"),
          extra_parts=("bezel", "marquee", "joystick", "button", "coin_door", "side_panel", "coin_slot", "coin_return", "lock",
                       "speaker", "t_molding"),
          size_range=(1.5, 2.0), density=300, variants=("upright", "cocktail_top", "twin"))
def arcade_cabinet(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.6, 0.7) if variant != "twin" else rng.uniform(0.8, 0.9)
    d, h = rng.uniform(0.7, 0.85), rng.uniform(1.65, 1.85)
    paint = M.solid(M.jitter(rng, [(0.1, 0.1, 0.12), (0.6, 0.1, 0.1), (0.1, 0.2, 0.55)][int(rng.integers(3))], 0.03),
                    "wood", 0.5)
    t = 0.018
    parts = [make_part(f"side_panel_{i}", "side_panel",
                       S.hull([[x - t / 2, -d / 2, 0], [x + t / 2, -d / 2, 0], [x - t / 2, d / 2, 0], [x + t / 2, d / 2, 0],
                               [x - t / 2, d / 2, 0.9], [x + t / 2, d / 2, 0.9], [x - t / 2, d / 2 - 0.25, 1.1],
                               [x + t / 2, d / 2 - 0.25, 1.1], [x - t / 2, -d / 2, h], [x + t / 2, -d / 2, h],
                               [x - t / 2, d / 2 - 0.15, h], [x + t / 2, d / 2 - 0.15, h]]), paint)
             for i, x in enumerate((-w / 2 + t / 2, w / 2 - t / 2))]
    iw = w - 2 * t
    body = [S.box((iw, d - 0.05, 0.85), center=(0, -0.025, 0.425)),
            S.box((iw, 0.3, h - 0.85), center=(0, -d / 2 + 0.15, 0.85 + (h - 0.85) / 2))]
    parts.append(make_part("body", "body", body, paint))
    R = rot((1, 0, 0), -np.deg2rad(25))
    sc = (0, d / 2 - 0.33, 1.28)
    parts.append(make_part("bezel", "bezel", S.box((iw, 0.02, 0.42), center=sc, R=R), black()))
    parts.append(make_part("screen", "screen", S.box((iw - 0.08, 0.006, 0.34), center=np.add(sc, R @ (0, 0.012, 0)), R=R),
                           M.solid((0.05, 0.08, 0.12), "glass", 0.1)))
    cp = S.box((iw, 0.3, 0.06), center=(0, d / 2 - 0.15, 0.93), R=rot((1, 0, 0), np.deg2rad(8)))
    parts.append(make_part("control_panel", "control_panel", cp, black()))
    players = 2 if variant == "twin" else 1
    bcol = [M.solid(c, "plastic", 0.4) for c in [(0.9, 0.1, 0.1), (0.1, 0.5, 0.9), (0.95, 0.8, 0.1), (0.1, 0.7, 0.2)]]
    k = 0
    for p in range(players):
        x0 = -iw / 4 if players == 2 and p == 0 else (iw / 4 if players == 2 else 0.0)
        x0 -= 0.08
        parts.append(make_part(f"joystick_{p}", "joystick",
                               S.union([S.cylinder(0.006, 0.07, center=(x0, d / 2 - 0.15, 1.0), sections=8),
                                        S.ellipsoid((0.018, 0.018, 0.018), center=(x0, d / 2 - 0.15, 1.04))]),
                               M.solid((0.8, 0.1, 0.1), "plastic", 0.3)))
        for b in range(3 if players == 2 else 6):
            bx = x0 + 0.09 + 0.045 * (b % 3)
            by = d / 2 - 0.13 - 0.05 * (b // 3)
            parts.append(make_part(f"button_{k}", "button",
                                   S.cylinder(0.014, 0.03, center=(bx, by, 0.97), sections=10), bcol[k % 4]))
            k += 1
    parts.append(make_part("marquee", "marquee", S.box((iw, 0.02, 0.18), center=(0, d / 2 - 0.17, h - 0.11)),
                           M.solid(M.jitter(rng, (0.95, 0.85, 0.3), 0.05), "plastic", 0.2)))
    parts.append(make_part("coin_door", "coin_door", S.box((0.2, 0.01, 0.22), center=(0, d / 2 + 0.004 - 0.025, 0.62)),
                           M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8)))
    # the one- and two-player start buttons, the coin door's two slots with their return
    # buttons and its lock, the speaker grilles under the marquee, and the T-moulding capping
    # each side panel's front edge
    for p in range(2):
        parts.append(make_part(f"button_{k + p}", "button", S.cylinder(0.01, 0.025, center=((p - 0.5) * 0.06, d / 2 - 0.25, 0.97), sections=10),
                               M.solid((0.95, 0.95, 0.95), "plastic", 0.3)))
    metal = M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8)
    yd = d / 2 + 0.009 - 0.025
    for j, sx in enumerate((-1, 1)):
        parts.append(make_part(f"coin_slot_{j}", "coin_slot", S.box((0.05, 0.006, 0.07), center=(sx * 0.05, yd + 0.003, 0.68)), metal))
        parts.append(make_part(f"coin_return_{j}", "coin_return", S.box((0.04, 0.006, 0.03), center=(sx * 0.05, yd + 0.003, 0.57)), black()))
    parts.append(make_part("lock", "lock", S.cylinder(0.01, 0.006, center=(0, yd + 0.003, 0.62), axis=(0, 1, 0), sections=10), metal))
    parts += [make_part(f"speaker_{j}", "speaker", S.box((0.12, 0.004, 0.08), center=(sx * iw * 0.3, d / 2 - 0.17, h - 0.26)), black())
              for j, sx in enumerate((-1, 1))]
    for j, x in enumerate((-w / 2 + t / 2, w / 2 - t / 2)):
        parts.append(make_part(f"t_molding_{j}", "t_molding", S.box((t + 0.004, 0.006, 0.9), center=(x, d / 2 + 0.003 - 0.006, 0.45)),
                               black()))
    if variant == "cocktail_top":
        parts.append(make_part("top_panel", "body", S.box((w, 0.35, 0.02), center=(0, -d / 2 + 0.175, h + 0.01)), paint))
    return parts


@register("dart_board", parts=("board",),
          extra_parts=("rim", "dart", "cabinet", "door", "hinge", "number_ring", "bullseye", "outer_bull",
                       "treble_ring", "double_ring", "spider", "number"),
          size_range=(0.4, 0.8), density=500, variants=("plain", "cabinet"), placement="wall")
def dart_board(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.218, 0.228)
    sisal = M.solid((0.12, 0.12, 0.1), "paper", 0.9)
    parts = []
    y0 = 0.0
    if variant == "cabinet":
        wood = M.wood(rng)
        cw, ch, cd = 2 * r + rng.uniform(0.08, 0.14), 2 * r + rng.uniform(0.12, 0.2), 0.08
        t = 0.015
        box = [S.box((cw, t, ch), center=(0, t / 2, ch / 2)),
               S.box((t, cd, ch), center=(-cw / 2 + t / 2, cd / 2, ch / 2)),
               S.box((t, cd, ch), center=(cw / 2 - t / 2, cd / 2, ch / 2)),
               S.box((cw - 2 * t, cd, t), center=(0, cd / 2, t / 2)),
               S.box((cw - 2 * t, cd, t), center=(0, cd / 2, ch - t / 2))]
        parts.append(make_part("cabinet", "cabinet", box, wood))
        y0, zc = t, ch / 2
        for i, s in enumerate((-1, 1)):
            x_out, x_in = s * cw / 2, 0.0
            door = S.box((cw / 2 - 0.002, 0.015, ch), center=((x_out + x_in) / 2, cd + 0.0075, ch / 2))
            parts.append(make_part(f"door_{i}", "door", door, wood))
            parts += hinge_parts(f"hinge_{i}", x=x_out, y=cd, z0=0.0, z1=ch, mat=M.metal(rng), radius=0.005, length=0.04)
            # the left door turns about its left edge outward (negative about +z), the right one positive
            parts.append(revolute(f"door_{i}_hinge", "cabinet", f"door_{i}", axis=(0, 0, 1), origin=(x_out, cd, 0),
                                  opens=-s * OPEN_DOOR))
    else:
        zc = r
    parts.append(make_part("board", "board", S.cylinder(r, 0.038, center=(0, y0 + 0.019, zc), axis=(0, 1, 0), sections=40),
                           sisal))
    parts.append(make_part("number_ring", "number_ring",
                           S.cylinder(r * 0.8, 0.004, center=(0, y0 + 0.04, zc), axis=(0, 1, 0), sections=40),
                           M.solid((0.8, 0.8, 0.8), "metal", 0.3, 0.8)))
    parts.append(make_part("rim", "rim", S.cylinder(r + 0.004, 0.03, center=(0, y0 + 0.015, zc), axis=(0, 1, 0),
                                                    sections=40), black()))
    # the scoring face: the red and green double and treble rings, the two bulls, and the wire
    # spider dividing the twenty segments (regulation radii, scaled to the board)
    k = r / 0.2255
    face_y = y0 + 0.042
    red, green = M.solid((0.75, 0.1, 0.1), "paper", 0.8), M.solid((0.1, 0.5, 0.2), "paper", 0.8)

    def flat_ring(r0: float, r1: float, y: float) -> S.Shape:
        a = np.linspace(0, 2 * np.pi, 20, endpoint=False)
        rm = (r0 + r1) / 2
        return S.tube(np.c_[rm * np.cos(a), np.full(20, y), zc + rm * np.sin(a)], (r1 - r0) / 2, sections=6, closed=True)

    parts.append(make_part("double_ring", "double_ring", flat_ring(0.162 * k, 0.170 * k, face_y + 0.004 * k), red))
    parts.append(make_part("treble_ring", "treble_ring", flat_ring(0.099 * k, 0.107 * k, face_y + 0.004 * k), green))
    parts.append(make_part("outer_bull", "outer_bull", flat_ring(0.00635 * k, 0.016 * k, face_y + 0.0048 * k), green))
    parts.append(make_part("bullseye", "bullseye", S.cylinder(0.00635 * k, 0.001, center=(0, face_y + 0.0005, zc), axis=(0, 1, 0),
                                                              sections=12), red))
    wires = []
    for j in range(20):
        a = np.pi / 2 + np.pi / 20 + 2 * np.pi * j / 20
        c = (0.016 * k + 0.170 * k) / 2
        wires.append(S.box(((0.170 - 0.016) * k, 0.0012, 0.001), center=(c * np.cos(a), face_y + 0.0014, zc + c * np.sin(a)),
                           R=rot((0, 1, 0), -a)))
    parts.append(make_part("spider", "spider", wires, M.solid((0.8, 0.8, 0.8), "metal", 0.3, 0.9)))
    # the twenty wire numerals round the number ring, 20 at the top, one over each segment
    rn = (0.170 * k + r * 0.8) / 2
    wire = M.solid((0.85, 0.85, 0.85), "metal", 0.3, 0.9)
    for j in range(20):
        a = np.pi / 2 - 2 * np.pi * j / 20
        parts.append(make_part(f"number_{j}", "number", S.box((0.006, 0.001, 0.008), center=(rn * np.cos(a), face_y + 0.0005, zc + rn * np.sin(a)),
                                                              R=rot((0, 1, 0), -(a - np.pi / 2))), wire))
    for k in range(int(rng.integers(0, 4))):
        a = rng.uniform(0, 2 * np.pi)
        rr = rng.uniform(0.0, r * 0.7)
        c = (rr * np.cos(a), y0 + 0.038 + 0.06, zc + rr * np.sin(a))
        parts.append(make_part(f"dart_{k}", "dart", S.cylinder(0.004, 0.13, center=c, axis=(0, 1, 0), sections=8),
                               M.solid((0.2, 0.5, 0.9), "plastic")))
    return parts


@register("foosball_table", parts=("body", "field", "rod"), extra_parts=("leg", "handle", "goal", "player"),
          size_range=(1.1, 1.6), density=400, variants=("standard", "compact"))
def foosball_table(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(1.3, 1.5) if variant == "standard" else rng.uniform(1.1, 1.25)
    W, H = rng.uniform(0.7, 0.78), rng.uniform(0.88, 0.94)
    wood = M.wood(rng)
    t, bh = 0.025, 0.2
    zb = H - bh
    body = [S.box((L, t, bh), center=(0, -W / 2 + t / 2, zb + bh / 2)), S.box((L, t, bh), center=(0, W / 2 - t / 2, zb + bh / 2)),
            S.box((t, W - 2 * t, bh), center=(-L / 2 + t / 2, 0, zb + bh / 2)),
            S.box((t, W - 2 * t, bh), center=(L / 2 - t / 2, 0, zb + bh / 2))]
    parts = [make_part("body", "body", body, wood),
             make_part("field", "field", S.box((L - 2 * t, W - 2 * t, 0.02), center=(0, 0, zb + 0.05)), felt(rng))]
    parts += legs4("leg", "leg", w=L - 0.05, d=W - 0.05, h=zb + 0.02, size=0.07, mat=wood)
    for i, s in enumerate((-1, 1)):
        parts.append(make_part(f"goal_{i}", "goal", S.box((0.02, 0.2, 0.07), center=(s * (L / 2 - t - 0.01), 0, zb + 0.095)),
                               black()))
    n = 8
    red, blue = M.solid((0.8, 0.1, 0.1), "plastic"), M.solid((0.1, 0.2, 0.7), "plastic")
    steel = M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9)
    zr = zb + 0.14
    for k in range(n):
        x = -L / 2 + t + (L - 2 * t) * (k + 0.5) / n
        side = 1 if k in (0, 1, 3, 5) else -1  # alternate teams along the table
        parts.append(make_part(f"rod_{k}", "rod", S.cylinder(0.008, W + 0.3, center=(x, side * 0.12, zr), axis=(0, 1, 0),
                                                             sections=8), steel))
        hy = side * (W / 2 + 0.12 + 0.12)
        parts.append(make_part(f"handle_{k}", "handle", S.cylinder(0.018, 0.09, center=(x, hy + side * 0.045, zr),
                                                                   axis=(0, 1, 0), sections=10), black()))
        m = [1, 2, 5, 3][k % 4]
        for j in range(m):
            y = side * 0.12 + (j - (m - 1) / 2) * (W - 0.1) / max(m, 2) * 0.8
            parts.append(make_part(f"player_{k}_{j}", "player", S.box((0.025, 0.02, 0.1), center=(x, y, zr - 0.03)),
                                   red if side > 0 else blue))
    return parts


@register("card_table", parts=("tabletop", "leg"), extra_parts=("apron", "felt", "cup_holder", "foot", "corner_block", "screw"),
          size_range=(0.7, 1.3),
          density=500, variants=("square", "octagon", "round"))
def card_table(rng: np.random.Generator, variant: str) -> list[Part]:
    s = rng.uniform(0.8, 1.2)
    h = rng.uniform(0.7, 0.76)
    wood = M.wood(rng)
    t = 0.03
    if variant == "square":
        top = S.box((s, s, t), center=(0, 0, h - t / 2), bevel=0.006)
        inlay = S.box((s - 0.1, s - 0.1, 0.003), center=(0, 0, h + 0.0015))
    else:
        n = 8 if variant == "octagon" else 32
        a = np.linspace(0, 2 * np.pi, n, endpoint=False) + (np.pi / n if n == 8 else 0)
        ring = np.c_[np.cos(a), np.sin(a)] * s / 2
        top = S.prism(ring, h - t, h)
        inlay = S.prism(ring * (1 - 0.12), h, h + 0.003)
    parts = [make_part("tabletop", "tabletop", top, wood), make_part("felt", "felt", inlay, felt(rng))]
    lw = s * 0.62 if variant != "square" else s - 0.08
    parts += legs4("leg", "leg", w=lw, d=lw, h=h - t, size=0.05, mat=wood)
    # a glide cap round each leg's foot (the legs still reach the floor)
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        parts.append(make_part(f"foot_{i}", "foot", S.box((0.056, 0.056, 0.012), center=(sx * (lw / 2 - 0.025), sy * (lw / 2 - 0.025), 0.006),
                                                         bevel=0.002), black("rubber")))
    ah = 0.08
    for i, (cx, cy, ax) in enumerate([(0, -lw / 2 + 0.01, 0), (0, lw / 2 - 0.01, 0), (-lw / 2 + 0.01, 0, 1),
                                      (lw / 2 - 0.01, 0, 1)]):
        size = (lw - 0.1, 0.02, ah) if ax == 0 else (0.02, lw - 0.1, ah)
        parts.append(make_part(f"apron_{i}", "apron", S.box(size, center=(cx, cy, h - t - ah / 2)), wood))
    # the glued blocks in the apron's inside corners
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        c = lw / 2 - 0.05 - 0.025
        parts.append(make_part(f"corner_block_{i}", "corner_block", S.box((0.05, 0.05, ah * 0.6), center=(sx * c, sy * c, h - t - ah * 0.3)),
                               wood))
        # the screw driven through the block's inner corner up into the top
        parts.append(make_part(f"screw_{i}", "screw", S.cylinder(0.0045, 0.003, center=(sx * (c - 0.012), sy * (c - 0.012), h - t - ah * 0.6 - 0.0015),
                                                                 sections=8), M.solid((0.6, 0.6, 0.62), "metal", 0.4)))
    if variant == "octagon":
        for i in range(4):
            a = np.pi / 4 + i * np.pi / 2
            c = (np.cos(a) * s * 0.36, np.sin(a) * s * 0.36, h + 0.0015)
            parts.append(make_part(f"cup_holder_{i}", "cup_holder", S.cylinder(0.045, 0.004, center=c, sections=16),
                                   M.solid((0.7, 0.6, 0.4), "metal", 0.3, 0.8)))
    return parts


@register("board_game", parts=("box",), extra_parts=("lid", "board", "piece", "card", "die", "rules", "seal", "timer"), size_range=(0.18, 0.55),
          density=400, variants=("boxed", "set_up", "card_deck"), placement="surface")
def board_game(rng: np.random.Generator, variant: str) -> list[Part]:
    art = M.paper(rng)
    if variant == "card_deck":
        w, d, h = rng.uniform(0.06, 0.07), rng.uniform(0.09, 0.1), rng.uniform(0.02, 0.03)
        parts = [make_part("box", "box", S.box((w, d, h), center=(0, 0, h / 2), bevel=0.001), art)]
        # spread cards beside the box make the asset larger than a palm
        for k in range(int(rng.integers(4, 9))):
            a = rng.uniform(-0.5, 0.5)
            c = (0.12 + k * 0.02, rng.uniform(-0.03, 0.03), 0.0004 + 0.0005 * k)
            parts.append(make_part(f"card_{k}", "card", S.box((w - 0.005, d - 0.005, 0.0004), center=c, R=rot((0, 0, 1), a)),
                                   M.solid((0.95, 0.95, 0.95), "paper")))
        # the deck box's tuck flap closing its top end, and the tax seal over it
        parts.append(make_part("lid", "lid", S.box((w - 0.002, 0.0006, h * 0.6), center=(0, d / 2 + 0.0003, h * 0.6)), art))
        parts.append(make_part("seal", "seal", S.box((0.012, 0.03, 0.0005), center=(0, d / 2 - 0.015, h + 0.00025)),
                               M.solid((0.9, 0.85, 0.6), "paper", 0.6)))
        return parts
    w, d = rng.uniform(0.25, 0.4), rng.uniform(0.25, 0.3)
    h = rng.uniform(0.05, 0.08)
    if variant == "boxed":
        parts = [make_part("box", "box", S.box((w - 0.004, d - 0.004, h - 0.01), center=(0, 0, (h - 0.01) / 2)),
                           M.solid((0.9, 0.9, 0.88), "paper")),
                 make_part("lid", "lid", [S.box((w, d, 0.003), center=(0, 0, h - 0.0015)),
                                          S.box((w, 0.003, 0.04), center=(0, -d / 2 + 0.0015, h - 0.02)),
                                          S.box((w, 0.003, 0.04), center=(0, d / 2 - 0.0015, h - 0.02)),
                                          S.box((0.003, d - 0.006, 0.04), center=(-w / 2 + 0.0015, 0, h - 0.02)),
                                          S.box((0.003, d - 0.006, 0.04), center=(w / 2 - 0.0015, 0, h - 0.02))], art)]
        # the round clear seals taping the lid shut at both ends
        parts += [make_part(f"seal_{k}", "seal", S.box((0.0005, 0.025, 0.025), center=(sx * (w / 2 + 0.00025), 0, h - 0.02)),
                            M.solid((0.9, 0.92, 0.95), "plastic", 0.2)) for k, sx in enumerate((-1, 1))]
        return parts
    b = rng.uniform(0.4, 0.5)
    parts = [make_part("board", "board", S.box((b, b, 0.004), center=(0, 0, 0.002)), art),
             make_part("box", "box", S.box((w * 0.8, d * 0.5, h * 0.7),
                                           center=(b / 2 - w * 0.4 - 0.01, -b / 2 + d * 0.25 + 0.01, 0.004 + h * 0.35)), art)]
    cols = [(0.85, 0.1, 0.1), (0.1, 0.3, 0.8), (0.1, 0.6, 0.2), (0.95, 0.8, 0.1)]
    for k in range(int(rng.integers(4, 10))):
        x, y = rng.uniform(-b / 2 + 0.03, b / 2 - 0.03, 2)
        parts.append(make_part(f"piece_{k}", "piece",
                               S.frustum(0.011, 0.005, 0.025, center=(x, y, 0.004), sections=10),
                               M.solid(cols[k % 4], "plastic", 0.3)))
    # two dice and the draw pile of cards on the board, the rules booklet beside the box
    for k in range(2):
        parts.append(make_part(f"die_{k}", "die", S.box((0.016, 0.016, 0.016), center=(b * 0.3 + k * 0.025, b * 0.3, 0.004 + 0.008),
                                                      bevel=0.002, R=rot((0, 0, 1), 0.3 * k)), M.solid((0.95, 0.95, 0.93), "plastic", 0.4)))
    parts.append(make_part("card", "card", S.box((0.06, 0.09, 0.012), center=(-b * 0.25, b * 0.25, 0.004 + 0.006)), art))
    # the discard pile beside the draw pile, and the sand timer lying on the board
    parts.append(make_part("card_1", "card", S.box((0.06, 0.09, 0.003), center=(-b * 0.25 + 0.075, b * 0.25, 0.004 + 0.0015),
                                                   R=rot((0, 0, 1), 0.15)), art))
    parts.append(make_part("timer", "timer", [S.cylinder(0.012, 0.004, center=(b * 0.05 + dx, -b * 0.3, 0.004 + 0.012), axis=(1, 0, 0),
                                                         sections=10) for dx in (-0.028, 0.028)]
                           + [S.cylinder(0.009, 0.052, center=(b * 0.05, -b * 0.3, 0.004 + 0.012), axis=(1, 0, 0), sections=10)],
                           M.glass(rng)))
    parts.append(make_part("rules", "rules", S.box((0.15, 0.21, 0.003), center=(b / 2 - w * 0.4 - 0.01, b * 0.12, 0.0055)),
                           M.solid((0.95, 0.95, 0.93), "paper", 0.8)))
    return parts


@register("toy_car", parts=("body", "wheel"), extra_parts=("cabin", "window", "bumper", "hubcap", "headlight", "tail_light", "grille",
                                                                    "mirror", "license_plate", "axle", "seat", "steering_wheel"),
          size_range=(0.08, 0.45),
          density=600, variants=("sedan", "truck", "ride_on"), placement="surface")
def toy_car(rng: np.random.Generator, variant: str) -> list[Part]:
    s = rng.uniform(0.1, 0.16) if variant != "ride_on" else rng.uniform(0.35, 0.42)
    paint = M.solid(M.jitter(rng, [(0.9, 0.15, 0.1), (0.1, 0.4, 0.85), (0.95, 0.8, 0.1), (0.2, 0.7, 0.3)][int(rng.integers(4))],
                             0.03), "plastic", 0.3)
    L, W = s, s * 0.45
    r = s * 0.12
    parts = [make_part("body", "body", S.box((L, W, s * 0.18), center=(0, 0, r + s * 0.06), bevel=s * 0.02), paint)]
    if variant == "truck":
        parts.append(make_part("cabin", "cabin", S.box((L * 0.3, W * 0.9, s * 0.2), center=(L * 0.3, 0, r + s * 0.24),
                                                       bevel=s * 0.02), paint))
        parts.append(make_part("bed", "body", S.box((L * 0.6, W, s * 0.08), center=(-L * 0.18, 0, r + s * 0.19)), paint))
    else:
        parts.append(make_part("cabin", "cabin", S.box((L * 0.5, W * 0.85, s * 0.16), center=(-L * 0.05, 0, r + s * 0.22),
                                                       bevel=s * 0.03), paint))
    parts.append(make_part("window", "window", S.box((L * 0.02, W * 0.7, s * 0.1), center=(L * 0.21 if variant != "truck" else L * 0.455,
                                                                                          0, r + s * 0.23)),
                           M.solid((0.2, 0.3, 0.4), "glass", 0.1)))
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        parts.append(make_part(f"wheel_{i}", "wheel", S.cylinder(r, W * 0.2, center=(sx * L * 0.32, sy * W * 0.5, r),
                                                                 axis=(0, 1, 0), sections=16), black()))
    for i, sx in enumerate((-1, 1)):
        parts.append(make_part(f"bumper_{i}", "bumper", S.box((s * 0.03, W * 0.9, s * 0.05), center=(sx * L / 2, 0, r + s * 0.02)),
                               M.solid((0.75, 0.75, 0.77), "metal", 0.3, 0.8)))
    # a hubcap on each wheel's outer face, the headlights at the front (+X) and the tail lights
    chrome = M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9)
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        parts.append(make_part(f"hubcap_{i}", "hubcap", S.cylinder(r * 0.5, W * 0.02, center=(sx * L * 0.32, sy * W * 0.6 + sy * W * 0.01, r),
                                                                   axis=(0, 1, 0), sections=12), chrome))
    zl = r + s * 0.1
    for i, sy in enumerate((-1, 1)):
        parts.append(make_part(f"headlight_{i}", "headlight", S.box((s * 0.01, W * 0.18, s * 0.04), center=(L / 2 + s * 0.005 - s * 0.01, sy * W * 0.3, zl)),
                               M.solid((1.0, 0.95, 0.7), "glass", 0.1)))
        parts.append(make_part(f"tail_light_{i}", "tail_light", S.box((s * 0.01, W * 0.18, s * 0.04), center=(-L / 2 - s * 0.005 + s * 0.01, sy * W * 0.3, zl)),
                               M.solid((0.9, 0.1, 0.1), "glass", 0.1)))
    # the radiator grille between the headlights, a wing mirror on each side of the cabin, the
    # number plates front and back, and the two axles the wheels turn on
    parts.append(make_part("grille", "grille", S.box((s * 0.008, W * 0.34, s * 0.035), center=(L / 2 - s * 0.002, 0, zl)), chrome))
    xm = L * 0.2 if variant != "truck" else L * 0.43
    for i, sy in enumerate((-1, 1)):
        parts.append(make_part(f"mirror_{i}", "mirror", S.box((s * 0.03, W * 0.06, s * 0.025), center=(xm, sy * (W * 0.45 + W * 0.03), r + s * 0.19)),
                               paint))
    for i, sx in enumerate((1, -1)):
        parts.append(make_part(f"license_plate_{i}", "license_plate", S.box((s * 0.006, W * 0.3, s * 0.03),
                                                                            center=(sx * (L / 2 + s * 0.015 + s * 0.003), 0, r + s * 0.02 - s * 0.045)),
                               M.solid((0.95, 0.95, 0.9), "metal", 0.4)))
    for i, sx in enumerate((-1, 1)):
        parts.append(make_part(f"axle_{i}", "axle", S.cylinder(r * 0.18, W * 1.0, center=(sx * L * 0.32, 0, r), axis=(0, 1, 0), sections=8),
                               chrome))
    if variant == "ride_on":  # the seat a child sits on and the steering wheel in front of it
        parts.append(make_part("seat", "seat", S.box((L * 0.2, W * 0.6, s * 0.02), center=(-L * 0.12, 0, r + s * 0.31), bevel=s * 0.005),
                               black()))
        parts.append(make_part("steering_wheel", "steering_wheel", S.cylinder(W * 0.15, s * 0.015, center=(L * 0.12, 0, r + s * 0.33),
                                                                            axis=(1, 0, 0.6), sections=12), black()))
    return parts


@register("teddy_bear", parts=("body", "head"), extra_parts=("ear", "arm", "leg", "snout", "eye", "nose", "paw_pad", "bow",
                                                                                       "ear_lining", "tail", "tag"),
          size_range=(0.15, 0.6), density=150, variants=("sitting", "small", "large"), placement="surface")
def teddy_bear(rng: np.random.Generator, variant: str) -> list[Part]:
    s = {"small": rng.uniform(0.16, 0.22), "sitting": rng.uniform(0.25, 0.35), "large": rng.uniform(0.45, 0.55)}[variant]
    fur = M.solid(M.jitter(rng, [(0.6, 0.42, 0.25), (0.85, 0.75, 0.6), (0.35, 0.22, 0.14), (0.9, 0.9, 0.88)][int(rng.integers(4))],
                           0.03), "fabric", 0.95)
    # the body sits on the ground with the legs (resting on the legs alone it would tip back)
    parts = [make_part("body", "body", S.ellipsoid((0.22 * s, 0.18 * s, 0.27 * s), center=(0, 0, 0.27 * s)), fur),
             make_part("head", "head", S.ellipsoid((0.19 * s, 0.17 * s, 0.17 * s), center=(0, 0.02 * s, 0.72 * s)), fur),
             make_part("snout", "snout", S.ellipsoid((0.07 * s, 0.06 * s, 0.05 * s), center=(0, 0.18 * s, 0.68 * s)),
                       M.solid((0.9, 0.85, 0.75), "fabric", 0.95))]
    for i, sx in enumerate((-1, 1)):
        parts.append(make_part(f"ear_{i}", "ear", S.ellipsoid((0.06 * s, 0.03 * s, 0.06 * s),
                                                              center=(sx * 0.13 * s, 0.0, 0.86 * s)), fur))
        parts.append(make_part(f"arm_{i}", "arm", S.ellipsoid((0.07 * s, 0.07 * s, 0.15 * s),
                                                              center=(sx * 0.24 * s, 0.05 * s, 0.38 * s)), fur))
        parts.append(make_part(f"leg_{i}", "leg", S.ellipsoid((0.08 * s, 0.15 * s, 0.08 * s),
                                                              center=(sx * 0.13 * s, 0.17 * s, 0.08 * s)), fur))
        parts.append(make_part(f"eye_{i}", "eye", S.ellipsoid((0.02 * s, 0.015 * s, 0.02 * s),
                                                              center=(sx * 0.07 * s, 0.165 * s, 0.76 * s)), black()))
        # the felt pad on the sole of each foot
        parts.append(make_part(f"paw_pad_{i}", "paw_pad", S.ellipsoid((0.05 * s, 0.012 * s, 0.05 * s),
                                                                      center=(sx * 0.13 * s, 0.315 * s, 0.08 * s), subdivisions=1),
                               M.solid((0.9, 0.85, 0.75), "fabric", 0.95)))
    # the stitched nose on the snout and the ribbon bow at the neck
    parts.append(make_part("nose", "nose", S.ellipsoid((0.025 * s, 0.015 * s, 0.018 * s), center=(0, 0.235 * s, 0.69 * s),
                                                       subdivisions=1), black()))
    bow = M.solid(M.jitter(rng, (0.75, 0.1, 0.15), 0.1), "fabric", 0.8)
    parts.append(make_part("bow", "bow", [S.ellipsoid((0.05 * s, 0.02 * s, 0.03 * s), center=(sx * 0.045 * s, 0.17 * s, 0.55 * s),
                                                      subdivisions=1) for sx in (-1, 1)], bow))
    # the pale linings inside the ears, a pad on each paw's inside, the stub of a tail and the
    # maker's cloth tag sewn into the side seam
    pale = parts[2].material
    for i, sx in enumerate((-1, 1)):
        parts.append(make_part(f"ear_lining_{i}", "ear_lining", S.ellipsoid((0.04 * s, 0.008 * s, 0.04 * s),
                                                                           center=(sx * 0.13 * s, 0.026 * s, 0.85 * s), subdivisions=1),
                               pale))
        parts.append(make_part(f"paw_pad_{i + 2}", "paw_pad", S.ellipsoid((0.035 * s, 0.01 * s, 0.045 * s),
                                                                          center=(sx * 0.24 * s, 0.115 * s, 0.3 * s), subdivisions=1),
                               pale))
    parts.append(make_part("tail", "tail", S.ellipsoid((0.035 * s, 0.03 * s, 0.035 * s), center=(0, -0.185 * s, 0.1 * s), subdivisions=1),
                           fur))
    parts.append(make_part("tag", "tag", S.box((0.002, 0.03 * s, 0.05 * s), center=(0.216 * s, -0.02 * s, 0.2 * s)),
                           M.solid((0.95, 0.95, 0.9), "fabric", 0.8)))
    return parts
