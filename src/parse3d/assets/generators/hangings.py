"""Things that hang: lanterns and hanging scrolls.

A paper lantern hangs from its ``cord`` (``lantern:cord@top HANGING_BELOW ceiling``); a candle
lantern and a stone garden lantern stand on their ``base``. A hanging scroll's ``paper`` is its
back, flat against the wall, framed by the silk ``border`` in the same plane; the rods and the
hanging cord are in front of it.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring


@register("lantern", parts=("body", "base"), extra_parts=("cord", "cap", "rib", "frame", "pane", "handle", "roof", "post",
                                                          "candle", "finial", "light_box", "socket", "bulb", "wick", "window",
                                                          "collar"),
          size_range=(0.2, 1.3), density=200, variants=("paper", "candle", "stone"), placement="ceiling")
def lantern(rng: np.random.Generator, variant: str) -> list[Part]:
    parts = []
    if variant == "paper":
        r = rng.uniform(0.14, 0.22)
        hb = r * rng.uniform(1.1, 1.5)
        paper = Material(M.jitter(rng, [(0.95, 0.93, 0.88), (0.85, 0.15, 0.1), (0.95, 0.8, 0.3)][int(rng.integers(3))], 0.03),
                         0.9, 0.0, "paper")
        black = M.solid((0.08, 0.08, 0.08), "wood", 0.6)
        z0 = 0.02
        parts.append(make_part("base", "base", ring([(r * 0.45, 0.0), (r * 0.55, 0.0), (r * 0.55, z0), (r * 0.45, z0)], sections=20),
                               black))
        parts.append(make_part("body", "body", S.ellipsoid((r, r, hb / 2), center=(0, 0, z0 + hb / 2 - 0.01), subdivisions=2), paper))
        for k, f in enumerate((0.3, 0.5, 0.7)):
            zr = z0 - 0.01 + hb * f
            rr = r * np.sqrt(max(1 - ((f - 0.5) * 2) ** 2, 0.05)) + 0.002
            parts.append(make_part(f"rib_{k}", "rib", ring([(rr - 0.003, zr - 0.002), (rr, zr - 0.002), (rr, zr + 0.002),
                                                            (rr - 0.003, zr + 0.002)], sections=20), black))
        # the wire ribs nearer the ends that keep the paper's shoulders round
        for k, f in enumerate((0.15, 0.85), start=3):
            zr = z0 - 0.01 + hb * f
            rr = r * np.sqrt(max(1 - ((f - 0.5) * 2) ** 2, 0.05)) + 0.002
            parts.append(make_part(f"rib_{k}", "rib", ring([(rr - 0.003, zr - 0.002), (rr, zr - 0.002), (rr, zr + 0.002),
                                                            (rr - 0.003, zr + 0.002)], sections=20), black))
        zt = z0 + hb - 0.02
        parts.append(make_part("cap", "cap", S.cylinder(r * 0.5, 0.02, center=(0, 0, zt + 0.01), sections=20), black))
        # inside, the lamp socket hanging from the cap and its bulb
        parts.append(make_part("socket", "socket", S.cylinder(0.016, 0.05, center=(0, 0, zt - 0.025), sections=12),
                               M.solid((0.9, 0.9, 0.88), "plastic", 0.5)))
        parts.append(make_part("bulb", "bulb", S.ellipsoid((0.03, 0.03, 0.045), center=(0, 0, zt - 0.05 - 0.04), subdivisions=1),
                               Material((0.98, 0.97, 0.92, 1.0), 0.1, 0.0, "glass")))
        lc = rng.uniform(0.3, 0.6)
        parts.append(make_part("cord", "cord", S.cylinder(0.004, lc, center=(0, 0, zt + 0.02 + lc / 2), sections=8),
                               M.solid((0.1, 0.1, 0.1), "rubber", 0.8)))
        return parts
    if variant == "candle":  # a square metal lantern: base, four posts with glass panes, a pyramid roof, a ring handle
        w = rng.uniform(0.14, 0.2)
        h = rng.uniform(0.25, 0.35)
        metal = M.solid(M.jitter(rng, (0.12, 0.12, 0.13), 0.02)[:3], "metal", 0.4, 0.7)
        hb = 0.025
        parts.append(make_part("base", "base", S.box((w, w, hb), center=(0, 0, hb / 2), bevel=0.003), metal))
        hp = h - hb - 0.06
        for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"frame_{k}", "frame", S.box((0.012, 0.012, hp), center=(sx * (w / 2 - 0.01), sy * (w / 2 - 0.01),
                                                                                          hb + hp / 2)), metal))
        glass = M.glass(rng)
        panes = [S.box((w - 0.032, 0.003, hp), center=(0, sy * (w / 2 - 0.01), hb + hp / 2)) for sy in (-1, 1)]
        panes += [S.box((0.003, w - 0.032, hp), center=(sx * (w / 2 - 0.01), 0, hb + hp / 2)) for sx in (-1, 1)]
        parts.append(make_part("body", "body", panes, glass))
        zr = hb + hp
        parts.append(make_part("roof", "roof", S.hull(np.array([[sx * w / 2, sy * w / 2, zr] for sx in (-1, 1) for sy in (-1, 1)]
                                                               + [[sx * 0.02, sy * 0.02, zr + 0.045] for sx in (-1, 1) for sy in (-1, 1)])),
                               metal))
        Tr = np.eye(4)
        Tr[:3, :3] = np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]], float)
        Tr[:3, 3] = (0, 0, zr + 0.045 + 0.03)
        parts.append(make_part("handle", "handle", S.transformed(ring([(0.022, -0.003), (0.028, -0.003), (0.028, 0.003), (0.022, 0.003)],
                                                                      sections=12), Tr), metal))
        parts.append(make_part("candle", "candle", S.cylinder(0.025, 0.08, center=(0, 0, hb + 0.04), sections=16),
                               M.solid((0.95, 0.93, 0.85), "wax", 0.7)))
        # the candle's wick, and the four top rails of the frame holding the panes under the roof
        parts.append(make_part("wick", "wick", S.cylinder(0.0015, 0.012, center=(0, 0, hb + 0.08 + 0.006), sections=6),
                               M.solid((0.1, 0.1, 0.1), "fabric", 0.9)))
        rails = [S.box((w - 0.032, 0.008, 0.01), center=(0, sy * (w / 2 - 0.01), zr - 0.005)) for sy in (-1, 1)]
        rails += [S.box((0.008, w - 0.032, 0.01), center=(sx * (w / 2 - 0.01), 0, zr - 0.005)) for sx in (-1, 1)]
        parts += [make_part(f"frame_{4 + k}", "frame", sh, metal) for k, sh in enumerate(rails)]
        return parts
    # a stone garden lantern (toro): a base, a post, the light box with windows, a wide roof, a finial
    stone = M.stone(rng)
    h = rng.uniform(0.8, 1.2)
    wb = h * 0.35
    parts.append(make_part("base", "base", S.cylinder(wb / 2, h * 0.08, center=(0, 0, h * 0.04), sections=6), stone))
    parts.append(make_part("post", "post", S.cylinder(wb * 0.22, h * 0.35, center=(0, 0, h * 0.08 + h * 0.175), sections=12), stone))
    zp = h * 0.43
    parts.append(make_part("platform", "base", S.cylinder(wb * 0.45, h * 0.06, center=(0, 0, zp + h * 0.03), sections=6), stone))
    zb = zp + h * 0.06
    parts.append(make_part("light_box", "light_box", S.box((wb * 0.55, wb * 0.55, h * 0.2), center=(0, 0, zb + h * 0.1)), stone))
    parts.append(make_part("body", "body", S.box((wb * 0.3, 0.004, h * 0.1), center=(0, wb * 0.275 + 0.002, zb + h * 0.1)),
                           M.solid((0.15, 0.12, 0.1), "stone", 0.9)))
    # the light box's other three windows (the front one is ``body``): back, left and right
    dark = M.solid((0.15, 0.12, 0.1), "stone", 0.9)
    parts += [make_part(f"window_{k}", "window", shp, dark) for k, shp in enumerate([
        S.box((wb * 0.3, 0.004, h * 0.1), center=(0, -wb * 0.275 - 0.002, zb + h * 0.1)),
        S.box((0.004, wb * 0.3, h * 0.1), center=(-wb * 0.275 - 0.002, 0, zb + h * 0.1)),
        S.box((0.004, wb * 0.3, h * 0.1), center=(wb * 0.275 + 0.002, 0, zb + h * 0.1))])]
    zr = zb + h * 0.2
    # the lotus collar the finial sits in on the roof's top
    parts.append(make_part("collar", "collar", S.cylinder(wb * 0.1, h * 0.02, center=(0, 0, zr + h * 0.14 + h * 0.01), sections=12), stone))
    parts.append(make_part("roof", "roof", S.hull(np.array([[wb * 0.6 * np.cos(a), wb * 0.6 * np.sin(a), zr] for a in
                                                            np.linspace(0, 2 * np.pi, 6, endpoint=False)]
                                                           + [[wb * 0.1 * np.cos(a), wb * 0.1 * np.sin(a), zr + h * 0.14] for a in
                                                              np.linspace(0, 2 * np.pi, 6, endpoint=False)])), stone))
    parts.append(make_part("finial", "finial", S.ellipsoid((wb * 0.1, wb * 0.1, h * 0.05), center=(0, 0, zr + h * 0.14 + h * 0.04),
                                                           subdivisions=1), stone))
    return parts


@register("hanging_scroll", parts=("paper", "roller"), extra_parts=("border", "top_rod", "knob", "cord", "futai", "seal", "eye",
                                                                   "ichimonji", "tie"),
          size_range=(0.6, 2.2), density=300, variants=("vertical", "wide", "narrow"), placement="wall")
def hanging_scroll(rng: np.random.Generator, variant: str) -> list[Part]:
    w = {"vertical": rng.uniform(0.4, 0.6), "wide": rng.uniform(0.8, 1.3), "narrow": rng.uniform(0.25, 0.35)}[variant]
    h = {"vertical": rng.uniform(1.2, 1.9), "wide": rng.uniform(0.6, 0.9), "narrow": rng.uniform(1.0, 1.6)}[variant]
    t = 0.002
    silk = Material(M.jitter(rng, [(0.55, 0.45, 0.3), (0.3, 0.35, 0.3), (0.75, 0.7, 0.6)][int(rng.integers(3))], 0.03), 0.7, 0.0,
                    "fabric")
    art = M.solid(M.jitter(rng, (0.92, 0.88, 0.78), 0.02)[:3], "paper", 0.9)
    rr = 0.012
    z0 = rr * 2  # the roller at the bottom
    b = w * 0.12  # the border's side width
    bt, bb = h * 0.18, h * 0.1  # its top and bottom bands (heaven and earth)
    parts = [make_part("paper", "paper", S.box((w - 2 * b, t, h - bt - bb), center=(0, t / 2, z0 + bb + (h - bt - bb) / 2)), art)]
    border = [S.box((b, t, h), center=(sx * (w / 2 - b / 2), t / 2, z0 + h / 2)) for sx in (-1, 1)]
    border += [S.box((w - 2 * b, t, bt), center=(0, t / 2, z0 + h - bt / 2)), S.box((w - 2 * b, t, bb), center=(0, t / 2, z0 + bb / 2))]
    parts.append(make_part("border", "border", border, silk))
    wood = M.wood(rng)
    parts.append(make_part("roller", "roller", S.cylinder(rr, w + 0.02, center=(0, t + rr * 1.3, z0 - rr + 0.002), axis=(1, 0, 0), sections=12),
                           wood))
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"knob_{k}", "knob", S.cylinder(rr * 1.3, 0.025, center=(sx * (w / 2 + 0.01 + 0.0125), t + rr * 1.3,
                                                                                        z0 - rr + 0.002), axis=(1, 0, 0), sections=12),
                               wood))
    zt = z0 + h
    parts.append(make_part("top_rod", "top_rod", S.box((w, 0.008, 0.012), center=(0, t + 0.004, zt - 0.006)), wood))
    parts.append(make_part("cord", "cord", [S.tube([(-w * 0.3, t + 0.004, zt - 0.004), (0, t + 0.004, zt + 0.12)], 0.0015, sections=6),
                                            S.tube([(w * 0.3, t + 0.004, zt - 0.004), (0, t + 0.004, zt + 0.12)], 0.0015, sections=6)],
                           M.solid((0.6, 0.5, 0.3), "fabric", 0.9)))
    # the two hanging strips (futai) down from the top rod, the artist's red seal on the paper
    # and the metal eyes the cord is tied to
    fw = min(0.03, b * 0.5)
    parts += [make_part(f"futai_{k}", "futai", S.box((fw, 0.0008, bt * 0.9), center=(sx * (w / 2 - b - (w - 2 * b) / 4), t + 0.0004,
                                                                                    zt - bt * 0.45 - 0.012)), silk)
              for k, sx in enumerate((-1, 1))]
    parts.append(make_part("seal", "seal", S.box((0.025, 0.0006, 0.025), center=((w - 2 * b) * 0.3, t + 0.0003, z0 + bb + 0.06)),
                           M.solid((0.75, 0.1, 0.08), "paper", 0.8)))
    parts += [make_part(f"eye_{k}", "eye", S.cylinder(0.004, 0.006, center=(sx * w * 0.3, t + 0.004, zt + 0.001), sections=8),
                        M.solid((0.8, 0.65, 0.3), "metal", 0.3, 0.9)) for k, sx in enumerate((-1, 1))]
    # the narrow brocade strips (ichimonji) across the paper's top and bottom edges, and the flat
    # tie cord that wraps the rolled scroll, hanging from the top rod's middle
    pw, ph = w - 2 * b, h - bt - bb
    brocade = M.solid((0.8, 0.68, 0.35), "fabric", 0.7)
    parts += [make_part(f"ichimonji_{k}", "ichimonji", S.box((pw, 0.0006, min(0.02, ph * 0.04)),
                                                             center=(0, t + 0.0003, z0 + bb + zc)), brocade)
              for k, zc in enumerate((ph - min(0.01, ph * 0.02), min(0.01, ph * 0.02)))]
    parts.append(make_part("tie", "tie", S.box((0.008, 0.0008, bt * 0.6), center=(0, t + 0.0004, zt - 0.012 - bt * 0.3)),
                           M.solid((0.6, 0.5, 0.3), "fabric", 0.9)))
    return parts
