"""Toiletries: toiletry bags and deodorants.

A toiletry bag lies on its base, zipped, with a carry ``handle`` on top; a deodorant stands on
its ``base`` under its ``cap``.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring, shell


@register("toiletry_bag", parts=("body",), extra_parts=("zipper", "handle", "pull", "hook", "tab", "logo"),
          size_range=(0.18, 0.35), density=250, variants=("zipped", "hanging", "barrel"), placement="surface")
def toiletry_bag(rng: np.random.Generator, variant: str) -> list[Part]:
    cloth = M.fabric(rng) if rng.random() < 0.6 else M.leather(rng)
    metal = M.metal(rng)
    if variant == "barrel":
        r, L = rng.uniform(0.06, 0.075), rng.uniform(0.2, 0.26)
        body = S.cylinder(r, L, center=(0, 0, r), axis=(1, 0, 0), sections=20)
        top = 2 * r
    else:
        w, d, h = rng.uniform(0.22, 0.28), rng.uniform(0.1, 0.13), rng.uniform(0.12, 0.16)
        body = S.box((w, d, h), center=(0, 0, h / 2), bevel=0.02)
        top, L = h, w
    parts = [make_part("body", "body", body, cloth)]
    parts.append(make_part("zipper", "zipper", S.box((L * 0.85, 0.008, 0.004), center=(0, 0, top + 0.001)),
                           Material((0.1, 0.1, 0.1, 1.0), 0.6, 0.0, "plastic")))
    parts.append(make_part("pull", "pull", S.box((0.012, 0.006, 0.025), center=(L * 0.42, 0.006, top - 0.008)), metal))
    # the second slider of the two-way zip, the fabric tabs finishing the zip's ends and the
    # maker's patch on the front
    parts.append(make_part("pull_1", "pull", S.box((0.012, 0.006, 0.025), center=(-L * 0.42, 0.006, top - 0.008)), metal))
    parts += [make_part(f"tab_{k}", "tab", S.box((0.02, 0.012, 0.008), center=(sx * (L * 0.425 + 0.01), 0, top)), cloth)
              for k, sx in enumerate((-1, 1))]
    y_front = r if variant == "barrel" else d / 2
    z_logo = r if variant == "barrel" else h * 0.45
    parts.append(make_part("logo", "logo", S.box((0.05, 0.002, 0.02), center=(0, y_front + 0.001, z_logo)), metal))
    handle = S.tube([(-L * 0.2, 0, top - 0.002), (-L * 0.15, 0, top + 0.025), (L * 0.15, 0, top + 0.025),
                     (L * 0.2, 0, top - 0.002)], 0.005, sections=6)
    parts.append(make_part("handle", "handle", handle, cloth))
    if variant == "hanging":
        parts.append(make_part("hook", "hook", S.tube([(0, 0, top + 0.025), (0, 0, top + 0.06), (0.02, 0, top + 0.075),
                                                       (0.035, 0, top + 0.06)], 0.003, sections=6), metal))
    return parts


def _cap(outer, t: float, z_top: float, *, bottom: float | None = None, scale=(1.0, 1.0)) -> S.Shape:
    """A hollow cap of revolution, open downwards: ``outer`` is its (r, depth below the top)
    profile, ``t`` its wall, ``z_top`` the height of its top; ``scale`` stretches it in x and y
    (an oval stick's cap)."""
    turn = np.array([[scale[0], 0, 0, 0], [0, -scale[1], 0, 0], [0, 0, -1, z_top], [0, 0, 0, 1]])
    return shell(outer, t, bottom=bottom, sections=14).apply(turn)


@register("deodorant", parts=("base", "cap"), extra_parts=("label", "dial", "stick", "valve_cup", "actuator", "ball", "collar"), size_range=(0.1, 0.2),
          density=900, variants=("stick", "spray", "roll_on"), placement="surface")
def deodorant(rng: np.random.Generator, variant: str) -> list[Part]:
    body = M.plastic(rng) if variant != "spray" else M.metal(rng)
    parts: list[Part] = []
    if variant == "stick":
        w, d, h = rng.uniform(0.055, 0.065), rng.uniform(0.03, 0.038), rng.uniform(0.085, 0.1)
        s = np.diag([w / 2, d / 2, 1.0, 1.0])
        base = S.lathe([(0.9, 0.0), (1.0, 0.004), (1.0, h)], sections=20).apply(s)
        cap = _cap([(0.9, 0.0), (1.02, 0.008), (1.02, 0.048)], 0.06, h + 0.028, bottom=0.003, scale=(w / 2, d / 2))
        # the twist dial under the stick that raises it
        parts.append(make_part("dial", "dial", S.cylinder(0.012, 0.006, center=(0, 0, 0.003), sections=14), body))
        base = base.moved((0, 0, 0.005))
        cap = cap.moved((0, 0, 0.005))
        r_label, zl = None, None
        # the printed label wrapped round the oval case
        parts.append(make_part("label", "label", ring([(0.97, 0.005 + h * 0.2), (1.0, 0.005 + h * 0.2), (1.0, 0.005 + h * 0.7),
                                                       (0.97, 0.005 + h * 0.7)], sections=20).apply(s), M.paper(rng)))
    else:
        r = rng.uniform(0.022, 0.027)
        h = rng.uniform(0.11, 0.15) if variant == "spray" else rng.uniform(0.07, 0.09)
        base = S.lathe([(r * 0.9, 0.0), (r, 0.004), (r, h * 0.85), (r * 0.75, h)], sections=20)
        cap = _cap([(r * 0.6, 0.0), (r * 0.85, 0.01), (r * 0.8, 0.045)], 0.0015, h + 0.04)
        r_label, zl = r, (h * 0.2, h * 0.7)
    parts.append(make_part("base", "base", base, body))
    parts.append(make_part("cap", "cap", cap, M.plastic(rng)))
    if r_label is not None:
        parts.append(make_part("label", "label", ring([(r_label - 0.0005, zl[0]), (r_label + 0.0006, zl[0]),
                                                       (r_label + 0.0006, zl[1]), (r_label - 0.0005, zl[1])], sections=20),
                               M.paper(rng)))
    # under the cap: the domed stick wound up out of its case; a spray can's crimped valve cup
    # and the actuator pressed to spray; a roll-on's ball held in its snap-on collar
    if variant == "stick":
        top = h + 0.005
        stick = S.lathe([(0.86, top - 0.004), (0.86, top + 0.006), (0.5, top + 0.014)], sections=16).apply(s)
        parts.append(make_part("stick", "stick", stick, M.solid((0.96, 0.96, 0.94), "plastic", 0.6)))
    elif variant == "spray":
        tin = M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9)
        parts.append(make_part("valve_cup", "valve_cup", S.lathe([(r * 0.5, h - 0.002), (r * 0.5, h + 0.004), (r * 0.4, h + 0.006)],
                                                                 sections=16), tin))
        parts.append(make_part("actuator", "actuator", S.cylinder(r * 0.3, 0.012, center=(0, 0, h + 0.012), sections=12),
                               M.plastic(rng)))
    else:
        parts.append(make_part("collar", "collar", ring([(r * 0.62, h - 0.002), (r * 0.78, h - 0.002), (r * 0.62, h + 0.008)], sections=16), M.plastic(rng)))
        parts.append(make_part("ball", "ball", S.ellipsoid((r * 0.64, r * 0.64, r * 0.64), center=(0, 0, h + 0.006),
                                                           subdivisions=1), Material((0.9, 0.92, 0.95, 0.6), 0.1, 0.0, "glass")))
    return parts
