"""Housework tools: clothes irons and mops.

An iron rests on its ``soleplate`` with the point towards +Y and the ``handle`` arching over the
``body``; it can stand ON an ironing board. A mop stands upright on its ``head`` (strands, a flat
pad or a sponge) with the ``handle`` pole rising to a hanging loop; lean it with
``LEANING_AGAINST``.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._casework import black, white


def _sole_outline(L: float, W: float, n: int = 9) -> np.ndarray:
    """An iron's footprint: square heel at -Y, curved sides meeting in a point at +Y."""
    t = np.linspace(0, 1, n)
    right = np.c_[W / 2 * np.sqrt(1 - t ** 2.2), -L / 2 + L * (0.45 + 0.55 * t)]
    left = right[::-1] * (-1, 1)
    return np.vstack([[(-W / 2, -L / 2), (W / 2, -L / 2)], right, left[1:]])


@register("iron", parts=("soleplate", "body", "handle"),
          extra_parts=("water_tank", "dial", "cord", "heel", "button", "dock", "fill_cap", "nozzle", "light", "cord_guard"),
          size_range=(0.18, 0.37), density=900, variants=("steam", "travel", "cordless"),
          placement="surface")
def iron(rng: np.random.Generator, variant: str) -> list[Part]:
    shell_mat = white(rng, "plastic") if rng.random() < 0.5 else M.plastic(rng)
    steel = Material(M.jitter(rng, (0.8, 0.8, 0.82), 0.01), 0.2, 0.95, "metal")
    L = rng.uniform(0.24, 0.28) if variant != "travel" else rng.uniform(0.17, 0.19)
    W = L * rng.uniform(0.42, 0.47)
    z0 = 0.0
    parts: list[Part] = []
    if variant == "cordless":
        # the charging dock the iron rests on
        dh = 0.02
        dock = S.prism(_sole_outline(L + 0.02, W + 0.02) + (0, -0.005), 0.0, dh)
        parts.append(make_part("dock", "dock", dock, black()))
        z0 = dh
    out = _sole_outline(L, W)
    ts = 0.006
    parts.append(make_part("soleplate", "soleplate", S.prism(out, z0, z0 + ts), steel))
    hb = L * rng.uniform(0.28, 0.34)
    inner = out * 0.92 + (0, -L * 0.02)
    top = out * np.array([0.55, 0.7]) + (0, -L * 0.08)
    body = S.hull(np.vstack([np.c_[inner, np.full(len(inner), z0 + ts - 0.001)],
                             np.c_[top, np.full(len(top), z0 + ts + hb * 0.55)]]))
    parts.append(make_part("body", "body", body, shell_mat))
    tank = S.hull(np.vstack([np.c_[out[len(out) // 2 - 3:len(out) // 2 + 4] * (0.7, 0.85),
                                   np.full(7, z0 + ts + hb * 0.3)],
                             np.c_[out[len(out) // 2 - 3:len(out) // 2 + 4] * (0.45, 0.75) + (0, -0.01),
                                   np.full(7, z0 + ts + hb * 0.62)]]))
    parts.append(make_part("water_tank", "water_tank", tank,
                           Material((0.55, 0.75, 0.9, 0.6), 0.1, 0.0, "plastic")))
    # the handle: a bar from the heel up and forward over the body, joined at the front
    zt = z0 + ts + hb
    path = [(0, -L * 0.38, z0 + ts + hb * 0.45), (0, -L * 0.32, zt), (0, L * 0.12, zt),
            (0, L * 0.22, z0 + ts + hb * 0.5)]
    parts.append(make_part("handle", "handle", S.tube(path, 0.013, sections=10), shell_mat))
    parts.append(make_part("dial", "dial", S.cylinder(0.018, 0.008, center=(0, -L * 0.05, z0 + ts + hb * 0.55 + 0.003),
                                                      sections=16), black()))
    parts.append(make_part("button", "button", S.cylinder(0.006, 0.006, center=(0, L * 0.1, zt + 0.011),
                                                          sections=10), M.plastic(rng)))
    # the steam-burst button behind the spray button
    parts.append(make_part("button_1", "button", S.cylinder(0.006, 0.006, center=(0, L * 0.04, zt + 0.011), sections=10),
                           parts[-1].material))
    heel = S.box((W * 0.8, 0.012, hb * 0.45), center=(0, -L / 2 + 0.004, z0 + ts + hb * 0.22), bevel=0.003)
    parts.append(make_part("heel", "heel", heel, shell_mat))
    # the tank's fill cap under the handle's front, the spray nozzle at the nose and the
    # heating light beside the dial
    parts.append(make_part("fill_cap", "fill_cap", S.cylinder(0.009, 0.006, center=(0, L * 0.2, z0 + ts + hb * 0.5), axis=(0, 1, 0),
                                                              sections=10), shell_mat))
    parts.append(make_part("nozzle", "nozzle", S.cylinder(0.004, 0.01, center=(0, L * 0.27, z0 + ts + hb * 0.32), axis=(0, 1, 0),
                                                          sections=8), black()))
    parts.append(make_part("light", "light", S.cylinder(0.003, 0.003, center=(0.025, -L * 0.05, z0 + ts + hb * 0.55), sections=8),
                           Material((0.9, 0.3, 0.1, 1.0), 0.2, 0.0, "plastic")))
    if variant != "cordless":
        cord = S.tube([(0, -L / 2 - 0.002, z0 + ts + hb * 0.35), (0, -L / 2 - 0.03, z0 + ts + hb * 0.3),
                       (0.01, -L / 2 - 0.06, 0.005)], 0.004, sections=8)
        parts.append(make_part("cord", "cord", cord, black()))
        # the swivelling strain relief where the cord leaves the heel
        parts.append(make_part("cord_guard", "cord_guard", S.cylinder(0.008, 0.025, center=(0, -L / 2 - 0.008, z0 + ts + hb * 0.35),
                                                                      axis=(0, 1, 0), sections=10), black("rubber")))
    return parts


@register("mop", parts=("handle", "head"), extra_parts=("strand", "pad", "grip", "hanger", "socket", "collar", "pin",
                                                                 "lever_grip"),
          size_range=(1.0, 1.6), density=500, variants=("string", "flat", "sponge"), placement="floor")
def mop(rng: np.random.Generator, variant: str) -> list[Part]:
    """Upright on its head; the pole along +Z."""
    pole = M.metal(rng) if rng.random() < 0.6 else M.wood(rng)
    plastic = M.plastic(rng)
    H = rng.uniform(1.15, 1.4)
    parts: list[Part] = []
    if variant == "string":
        cotton = Material(M.jitter(rng, (0.9, 0.88, 0.82), 0.03), 0.95, 0.0, "fabric")
        zh = 0.2
        head = S.cylinder(0.035, 0.05, center=(0, 0, zh + 0.025), sections=16)
        parts.append(make_part("head", "head", head, plastic))
        n = 10
        for k in range(n):
            a = 2 * np.pi * k / n
            d = np.array([np.cos(a), np.sin(a), 0.0])
            spread = rng.uniform(0.1, 0.16)
            path = [d * 0.025 + (0, 0, zh + 0.01), d * 0.06 + (0, 0, zh * 0.5),
                    d * spread + (0, 0, 0.008)]
            parts.append(make_part(f"strand_{k}", "strand", S.tube(path, 0.008, sections=6), cotton))
        z_top = zh + 0.05
    elif variant == "flat":
        pw, pd = rng.uniform(0.35, 0.45), rng.uniform(0.1, 0.13)
        pad = S.box((pw, pd, 0.015), center=(0, 0, 0.0075), bevel=0.003)
        parts.append(make_part("pad", "pad", pad, Material(M.jitter(rng, (0.3, 0.5, 0.8), 0.1), 0.95, 0.0,
                                                               "fabric")))
        frame = S.box((pw - 0.01, pd - 0.01, 0.02), center=(0, 0, 0.025), bevel=0.004)
        parts.append(make_part("head", "head", frame, plastic))
        joint = S.box((0.03, 0.03, 0.05), center=(0, 0, 0.06), bevel=0.005)
        parts.append(make_part("socket", "socket", joint, plastic))
        # the pin the flat head swivels on, through the socket
        parts.append(make_part("pin", "pin", S.cylinder(0.005, 0.04, center=(0, 0, 0.05), axis=(1, 0, 0), sections=8),
                               M.solid((0.75, 0.75, 0.77), "metal", 0.3, 0.9)))
        z_top = 0.085
    else:
        sponge = Material(M.jitter(rng, (0.9, 0.8, 0.2), 0.05), 0.95, 0.0, "fabric")
        sw = rng.uniform(0.25, 0.3)
        parts.append(make_part("pad", "pad", S.box((sw, 0.06, 0.05), center=(0, 0, 0.025), bevel=0.005), sponge))
        parts.append(make_part("head", "head", S.box((sw + 0.01, 0.07, 0.025), center=(0, 0, 0.0625),
                                                     bevel=0.004), plastic))
        # the wringer lever folded along the pole
        lever = S.tube([(0.02, 0.04, 0.07), (0.02, 0.04, 0.45)], 0.006, sections=8)
        parts.append(make_part("socket", "socket", [S.box((0.04, 0.04, 0.04), center=(0, 0, 0.09), bevel=0.004),
                                                   lever], plastic))
        # the grip moulded on the lever's end, where the hand pulls it down
        parts.append(make_part("lever_grip", "lever_grip", S.cylinder(0.01, 0.05, center=(0.02, 0.04, 0.43), sections=10),
                               plastic))
        z_top = 0.1
    parts.append(make_part("handle", "handle", S.cylinder(0.012, H - z_top, center=(0, 0, (H + z_top) / 2 - 0.002),
                                                          sections=12), pole))
    parts.append(make_part("grip", "grip", S.cylinder(0.015, 0.16, center=(0, 0, H - 0.1), sections=12), plastic))
    # the threaded collar where the pole screws into the head
    parts.append(make_part("collar", "collar", S.cylinder(0.016, 0.025, center=(0, 0, z_top + 0.0125), sections=12), plastic))
    parts.append(make_part("hanger", "hanger", S.tube([(0, 0, H - 0.01), (0, 0, H + 0.02), (0, 0.015, H + 0.035),
                                                       (0, 0.03, H + 0.02), (0, 0.03, H + 0.005)], 0.003,
                                                      sections=6), plastic))
    return parts
