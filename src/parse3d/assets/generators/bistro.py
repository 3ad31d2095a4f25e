"""Pub and café furniture: bar tables (high tables), jukeboxes and A-frame sign stands.

A bar table's ``tabletop`` stands at 1.0-1.1 m on a pedestal or four legs with a ``footrest``
ring. A jukebox stands on the floor, back to the wall: its arched ``body``, the ``glass``
window over the record mechanism, the ``speaker`` grille below and the ``button`` row. An
sign stand holds a sign in its ``frame`` over a ``base``.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._casework import black
from ._household import ring
from ._kit import rot


@register("bar_table", parts=("tabletop", "leg"), extra_parts=("base", "footrest", "stretcher", "foot", "apron", "top_plate", "collar", "screw",
                                                               "corner_block"),
          size_range=(0.95, 1.5), density=600, variants=("pedestal", "four_leg", "square_pedestal"),
          placement="floor")
def bar_table(rng: np.random.Generator, variant: str) -> list[Part]:
    top_mat = M.wood(rng)
    metal = Material((0.12, 0.12, 0.13, 1.0), 0.45, 0.7, "metal") if rng.random() < 0.6 else M.metal(rng)
    h = rng.uniform(1.0, 1.1)
    t = 0.03
    parts: list[Part] = []
    if variant == "four_leg":
        w = rng.uniform(0.6, 0.8)
        parts.append(make_part("tabletop", "tabletop", S.box((w, w, t), center=(0, 0, h - t / 2), bevel=0.004),
                               top_mat))
        leg = 0.04
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            x, y = sx * (w / 2 - 0.05), sy * (w / 2 - 0.05)
            parts.append(make_part(f"leg_{i}", "leg", S.box((leg, leg, h - t), center=(x, y, (h - t) / 2), bevel=0.003),
                                   top_mat))
        zf = rng.uniform(0.28, 0.35)
        span = w - 0.1 - leg
        for k, (size, c) in enumerate([((span, 0.025, 0.025), (0, -(w / 2 - 0.05), zf)),
                                       ((span, 0.025, 0.025), (0, w / 2 - 0.05, zf)),
                                       ((0.025, span, 0.025), (-(w / 2 - 0.05), 0, zf)),
                                       ((0.025, span, 0.025), (w / 2 - 0.05, 0, zf))]):
            parts.append(make_part(f"footrest_{k}", "footrest", S.box(size, center=c), metal))
        # the aprons under the top, between the legs, and a cap round each leg's foot
        ha = 0.07
        for k, (size, c) in enumerate([((span, 0.02, ha), (0, -(w / 2 - 0.05), h - t - ha / 2)),
                                       ((span, 0.02, ha), (0, w / 2 - 0.05, h - t - ha / 2)),
                                       ((0.02, span, ha), (-(w / 2 - 0.05), 0, h - t - ha / 2)),
                                       ((0.02, span, ha), (w / 2 - 0.05, 0, h - t - ha / 2))]):
            parts.append(make_part(f"apron_{k}", "apron", S.box(size, center=c), top_mat))
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"foot_{i}", "foot", S.box((leg + 0.006, leg + 0.006, 0.012),
                                                             center=(sx * (w / 2 - 0.05), sy * (w / 2 - 0.05), 0.006)),
                                   black("rubber")))
            # the corner block glued across the inside corner of the aprons behind the leg, under
            # the top (not touching it)
            q = w / 2 - 0.05 - 0.01 - 0.03
            parts.append(make_part(f"corner_block_{i}", "corner_block",
                                   S.box((0.08, 0.02, ha * 0.7), center=(sx * q, sy * q, h - t - 0.002 - ha * 0.35),
                                         R=rot((0, 0, 1), float(np.arctan2(sx, -sy)))), top_mat))
        return parts
    if variant == "square_pedestal":
        w = rng.uniform(0.6, 0.75)
        parts.append(make_part("tabletop", "tabletop", S.box((w, w, t), center=(0, 0, h - t / 2), bevel=0.004),
                               top_mat))
        base = S.box((0.5, 0.5, 0.02), center=(0, 0, 0.01), bevel=0.004)
    else:
        r = rng.uniform(0.3, 0.4)
        parts.append(make_part("tabletop", "tabletop", S.cylinder(r, t, center=(0, 0, h - t / 2), sections=40),
                               top_mat))
        base = S.frustum(0.26, 0.2, 0.03, center=(0, 0, 0.006), sections=32)  # on four glides
    parts.append(make_part("base", "base", base, metal))
    parts.append(make_part("leg", "leg", S.cylinder(0.035, h - t - 0.02, center=(0, 0, (h - t + 0.02) / 2 - 0.001),
                                                   sections=16), metal))
    zf = rng.uniform(0.25, 0.32)
    rf = rng.uniform(0.17, 0.21)
    parts.append(make_part("footrest", "footrest", ring([(rf - 0.01, zf - 0.01), (rf + 0.01, zf - 0.01),
                                                          (rf + 0.01, zf + 0.01), (rf - 0.01, zf + 0.01)],
                                                         sections=32), metal))
    for k in range(4):
        a = np.pi / 4 + k * np.pi / 2
        d = np.array([np.cos(a), np.sin(a), 0.0])
        spoke = S.tube([d * 0.03 + (0, 0, zf), d * (rf - 0.005) + (0, 0, zf)], 0.006, sections=8)
        parts.append(make_part(f"stretcher_{k}", "stretcher", spoke, metal))
    if variant == "pedestal":
        for k, a in enumerate(np.pi / 4 + np.arange(4) * np.pi / 2):
            glide = S.cylinder(0.015, 0.0065, center=(0.2 * np.cos(a), 0.2 * np.sin(a), 0.00325), sections=10)
            parts.append(make_part(f"foot_{k}", "foot", glide, black("rubber")))
    # the cross plate screwed under the top that the column fixes into, and the collar where the
    # column meets the base
    parts.append(make_part("top_plate", "top_plate", [S.box((0.4, 0.05, 0.012), center=(0, 0, h - t - 0.006)),
                                                      S.box((0.05, 0.4, 0.012), center=(0, 0, h - t - 0.006))], metal))
    # the four screws through the cross plate's arm ends into the top, heads under the plate
    steel = M.solid((0.55, 0.55, 0.57), "metal", 0.35, 0.9)
    parts += [make_part(f"screw_{k}", "screw", S.cylinder(0.006, 0.003, center=(x, y, h - t - 0.012 - 0.0015), sections=8), steel)
              for k, (x, y) in enumerate([(0.175, 0), (-0.175, 0), (0, 0.175), (0, -0.175)])]
    z_base = 0.036 if variant == "pedestal" else 0.02
    parts.append(make_part("collar", "collar", S.cylinder(0.05, 0.03, center=(0, 0, z_base + 0.015), sections=16), metal))
    return parts


@register("jukebox", parts=("body",), extra_parts=("glass", "speaker", "button", "crest", "light", "record", "tonearm",
                                                   "coin_slot", "title_strip", "grille_bar", "coin_return", "lock"),
          size_range=(1.0, 1.7), density=400, variants=("bubbler", "wallbox_cabinet", "retro"),
          placement="floor")
def jukebox(rng: np.random.Generator, variant: str) -> list[Part]:
    """Standing with its back (-Y) to the wall; the domed top for ``bubbler``."""
    wood = M.wood(rng)
    chrome = Material((0.88, 0.88, 0.9, 1.0), 0.1, 1.0, "metal")
    w, d = rng.uniform(0.7, 0.85), rng.uniform(0.55, 0.7)
    hb = rng.uniform(1.05, 1.2) if variant != "retro" else rng.uniform(1.3, 1.45)
    zb = 0.06
    plinth = S.box((w - 0.04, d - 0.04, zb), center=(0, 0, zb / 2))  # part of the body: it stands on it
    parts: list[Part] = []
    if variant == "bubbler":
        body = S.box((w, d, hb - zb - w / 2 + 0.001), center=(0, 0, zb + (hb - zb - w / 2) / 2))
        dome = S.cylinder(w / 2, d, center=(0, 0, hb - w / 2), axis=(0, 1, 0), sections=24)
        # keep only the upper half of the dome: a hull of its upper vertices
        v = dome.mesh.vertices
        dome = S.hull(np.asarray(v[v[:, 2] >= hb - w / 2 - 1e-9]))
        parts.append(make_part("body", "body", [plinth, body, dome], wood))
        light = S.tube([(x, d / 2 + 0.004, z) for x, z in
                        zip(w / 2 * 0.9 * np.cos(np.linspace(0, np.pi, 9)),
                            hb - w / 2 + w / 2 * 0.9 * np.sin(np.linspace(0, np.pi, 9)), strict=True)],
                       0.015, sections=8)
        parts.append(make_part("light", "light", light, Material((1.0, 0.6, 0.2, 1.0), 0.2, 0.0, "plastic")))
    else:
        body = S.box((w, d, hb - zb), center=(0, 0, (zb + hb) / 2), bevel=0.02)
        parts.append(make_part("body", "body", [plinth, body], wood if variant == "wallbox_cabinet" else black()))
        if variant == "retro":
            parts.append(make_part("light", "light", S.box((0.04, 0.02, hb - zb - 0.1),
                                                           center=(-w / 2 + 0.05, d / 2 + 0.009, (zb + hb) / 2)),
                                   Material((0.3, 0.6, 1.0, 1.0), 0.2, 0.0, "plastic")))
        parts.append(make_part("crest", "crest", S.box((w * 0.7, d * 0.5, 0.08), center=(0, -d * 0.1, hb + 0.04 - 0.001),
                                                       bevel=0.01), chrome))
    zg0, zg1 = zb + (hb - zb) * 0.48, zb + (hb - zb) * 0.82
    parts.append(make_part("glass", "glass", S.box((w * 0.6, 0.01, zg1 - zg0), center=(0, d / 2 + 0.004, (zg0 + zg1) / 2)),
                           M.glass(rng)))
    zs0, zs1 = zb + 0.06, zb + (hb - zb) * 0.33
    parts.append(make_part("speaker", "speaker", S.box((w * 0.55, 0.01, zs1 - zs0),
                                                       center=(0, d / 2 + 0.004, (zs0 + zs1) / 2)),
                           Material((0.25, 0.2, 0.15, 1.0), 0.9, 0.0, "fabric")))
    zbtn = zb + (hb - zb) * 0.4
    for k in range(6):
        x = (k - 2.5) * w * 0.08
        parts.append(make_part(f"button_{k}", "button", S.box((0.03, 0.02, 0.02), center=(x, d / 2 + 0.009, zbtn),
                                                              bevel=0.003), chrome))
    # under the glass, the record on its turntable and the tone arm; the title strips of the
    # selection above the buttons; the coin slot beside them; chrome bars across the speaker
    zr = (zg0 + zg1) / 2
    rr = min(0.15, (zg1 - zg0) * 0.4)
    parts.append(make_part("record", "record", S.cylinder(rr, 0.002, center=(0, d / 2 + 0.001, zr), axis=(0, 1, 0), sections=24),
                           black("plastic")))
    parts.append(make_part("tonearm", "tonearm", S.box((0.012, 0.002, rr * 1.1), center=(rr * 0.9, d / 2 + 0.003, zr + rr * 0.3),
                                                       R=rot((0, 1, 0), -0.4)), chrome))
    zt = zbtn + 0.03
    parts.append(make_part("title_strip", "title_strip", S.box((w * 0.5, 0.003, 0.025), center=(0, d / 2 + 0.0015, zt)),
                           M.paper(rng)))
    parts.append(make_part("coin_slot", "coin_slot", S.box((0.03, 0.012, 0.05), center=(w * 0.3, d / 2 + 0.006, zbtn), bevel=0.003),
                           chrome))
    for k in range(3):
        z = zs0 + (zs1 - zs0) * (k + 1) / 4
        parts.append(make_part(f"grille_bar_{k}", "grille_bar", S.box((w * 0.57, 0.008, 0.01), center=(0, d / 2 + 0.013, z)), chrome))
    # the coin-return cup under the coin slot, and the key lock of the front door beside the
    # speaker
    parts.append(make_part("coin_return", "coin_return", S.box((0.03, 0.01, 0.025), center=(w * 0.3, d / 2 + 0.005, zbtn - 0.05),
                                                               bevel=0.002), chrome))
    parts.append(make_part("lock", "lock", S.cylinder(0.01, 0.008, center=(w * 0.36, d / 2 + 0.004, (zs0 + zs1) / 2), axis=(0, 1, 0),
                                                      sections=10), chrome))
    return parts


@register("sign_stand", parts=("base", "frame"),
          extra_parts=("post", "sign_face", "board", "hinge", "foot", "handle", "bracket", "cap", "screw", "collar"),
          size_range=(0.7, 1.9), density=600, variants=("poster", "twin_post", "a_frame"), placement="floor")
def sign_stand(rng: np.random.Generator, variant: str) -> list[Part]:
    """A free-standing sign holder facing +Y: a weighted ``base``, a ``post`` (two for
    ``twin_post``) and the ``frame`` whose front face takes a sign (``SECURED_TO
    sign_stand:frame``); an ``a_frame`` pavement sign stands open on its two boards."""
    metal = Material((0.15, 0.15, 0.16, 1.0), 0.45, 0.7, "metal") if rng.random() < 0.6 else M.metal(rng)
    face = M.paper(rng) if variant != "a_frame" else Material((0.1, 0.12, 0.1, 1.0), 0.9, 0.0, "stone")
    parts: list[Part] = []
    if variant == "a_frame":
        wood = M.wood(rng)
        w, L = rng.uniform(0.5, 0.65), rng.uniform(0.8, 1.1)
        spread = np.deg2rad(rng.uniform(12, 16))
        t = 0.02
        H = L * np.cos(spread)
        for k, sgn in enumerate((1, -1)):
            T = np.eye(4)
            T[:3, :3] = rot((1, 0, 0), sgn * spread)
            T[:3, 3] = (0, 0, H)
            board = S.box((w, t, L), center=(0, sgn * t / 2, -L / 2)).apply(T)
            parts.append(make_part("frame" if k == 0 else "board", "frame" if k == 0 else "board", board, wood))
            if k == 0:
                inset = S.box((w - 0.08, 0.003, L - 0.12), center=(0, t + 0.0015, -L / 2 - 0.02)).apply(T)
                parts.append(make_part("sign_face", "sign_face", inset, face))
        parts.append(make_part("hinge", "hinge", S.cylinder(0.012, w * 0.9, center=(0, 0, H - 0.004), axis=(1, 0, 0),
                                                           sections=12), M.metal(rng)))
        # the base: a chain-like spreader bar low between the boards keeps them from sliding apart
        yb = np.tan(spread) * H * 0.85  # the boards' inner faces at that height
        parts.append(make_part("base", "base", S.tube([(0, yb - 0.001, H * 0.15), (0, -yb + 0.001, H * 0.15)], 0.004,
                                                      sections=6), M.metal(rng)))
        # the carrying handle through the boards' top, under the hinge
        parts.append(make_part("handle", "handle", S.box((0.12, 0.05, 0.025), center=(0, 0, H - 0.05)), M.metal(rng)))
        # the rubber shoes on each board's two bottom corners
        rubber = Material((0.08, 0.08, 0.08, 1.0), 0.9, 0.0, "rubber")
        yf = np.tan(spread) * H + t / np.cos(spread) / 2
        for k, (sx, sy) in enumerate([(-1, 1), (1, 1), (-1, -1), (1, -1)]):
            parts.append(make_part(f"foot_{k}", "foot", S.box((0.05, 0.03, 0.015), center=(sx * (w / 2 - 0.025), sy * (yf - 0.012), 0.0075)),
                                   rubber))
        return parts
    fw, fh = rng.uniform(0.5, 0.65), rng.uniform(0.7, 0.95)
    top = rng.uniform(1.5, 1.75)
    t = 0.025
    z0 = top - fh
    frame = [S.box((fw, t, fh), center=(0, 0, z0 + fh / 2), bevel=0.003)]
    parts.append(make_part("frame", "frame", frame, metal))
    parts.append(make_part("sign_face", "sign_face", S.box((fw - 0.05, 0.003, fh - 0.05),
                                                           center=(0, t / 2 + 0.0015, z0 + fh / 2)), face))
    if variant == "poster":
        parts.append(make_part("base", "base", S.frustum(0.2, 0.17, 0.02, center=(0, 0, 0), sections=32), metal))
        parts.append(make_part("post", "post", S.cylinder(0.015, z0 + 0.05 - 0.019, center=(0, -t / 2 - 0.015, (z0 + 0.05 + 0.019) / 2),
                                                         sections=12), metal))
        # the clamp holding the frame on the post, and the post's cap
        parts.append(make_part("bracket", "bracket", S.box((0.06, 0.03, 0.05), center=(0, -t / 2 - 0.015, z0 + 0.02)), metal))
        parts.append(make_part("cap", "cap", S.cylinder(0.017, 0.008, center=(0, -t / 2 - 0.015, z0 + 0.05 + 0.004), sections=12),
                               M.solid((0.1, 0.1, 0.1), "plastic", 0.5)))
        # the clamp's thumb screw at the back, the collar where the post meets the base, and the
        # rubber ring under the base's rim
        parts.append(make_part("screw", "screw", S.cylinder(0.008, 0.02, center=(0, -t / 2 - 0.04, z0 + 0.02), axis=(0, 1, 0), sections=10),
                               metal))
        parts.append(make_part("collar", "collar", S.cylinder(0.03, 0.02, center=(0, -t / 2 - 0.015, 0.03), sections=12), metal))
        parts.append(make_part("foot", "foot", ring([(0.17, 0.0), (0.19, 0.0), (0.19, 0.003), (0.17, 0.003)], sections=32),
                               Material((0.08, 0.08, 0.08, 1.0), 0.9, 0.0, "rubber")))
    else:
        parts.append(make_part("base", "base", S.box((fw + 0.1, 0.06, 0.02), center=(0, 0, 0.03), bevel=0.004), metal))
        for k, sx in enumerate((-1, 1)):
            x = sx * (fw / 2 + 0.012)
            parts.append(make_part(f"post_{k}", "post", S.box((0.025, 0.025, top - 0.04), center=(x, 0, 0.04 + (top - 0.04) / 2 - 0.001),
                                                              bevel=0.002), metal))
            parts.append(make_part(f"foot_{k}", "foot", S.box((0.05, 0.4, 0.02), center=(x, 0, 0.01), bevel=0.004), metal))
            parts.append(make_part(f"cap_{k}", "cap", S.box((0.027, 0.027, 0.008), center=(x, 0, top + 0.003)),
                                   M.solid((0.1, 0.1, 0.1), "plastic", 0.5)))
    return parts
