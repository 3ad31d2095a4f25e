"""Instrument cases: a violin (or viola) case lying closed, its lid hinged along the back.

The case lies flat, neck end at +X, the handle and latches on the front (+Y) side; ``shell``
is the lower half the instrument lies in, ``lid`` the upper half.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, make_part
from ..registry import register
from ._kit import OPEN_DOOR, hinge_parts, mount, revolute


def _outline(variant: str, L: float, W: float) -> np.ndarray:
    """The case's footprint (N, 2), convex: a rounded oblong, or a shaped case narrowing to the neck."""
    a = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    if variant == "oblong":
        return np.c_[L / 2 * np.sign(np.cos(a)) * np.abs(np.cos(a)) ** 0.4, W / 2 * np.sign(np.sin(a)) * np.abs(np.sin(a)) ** 0.4]
    # shaped: wide at the body end (-X), narrow at the scroll end (+X)
    x = L / 2 * np.cos(a)
    y = W / 2 * np.sin(a) * (0.75 - 0.35 * (x / (L / 2)))
    return np.c_[x, y]


@register("violin_case", parts=("shell", "lid"),
          extra_parts=("handle", "latch", "hinge", "foot", "strap_ring", "lock", "name_tag", "trim", "handle_mount"),
          size_range=(0.6, 0.9), density=350, variants=("oblong", "shaped", "viola"), placement="floor")
def violin_case(rng: np.random.Generator, variant: str) -> list:
    L = rng.uniform(0.76, 0.8) if variant != "viola" else rng.uniform(0.8, 0.86)
    W = rng.uniform(0.22, 0.26)
    h = rng.uniform(0.11, 0.14)
    shellm = Material(M.jitter(rng, [(0.08, 0.08, 0.09), (0.15, 0.2, 0.35), (0.45, 0.1, 0.1), (0.9, 0.9, 0.88)][int(rng.integers(4))],
                              0.03), 0.5, 0.0, "plastic")
    metal = M.solid((0.75, 0.75, 0.77), "metal", 0.3, 0.9)
    black = M.solid((0.05, 0.05, 0.05), "rubber", 0.8)
    poly = _outline("oblong" if variant == "viola" else variant, L, W)
    zf = 0.006
    zs = zf + h * 0.62
    parts = [make_part("shell", "shell", S.prism(poly, zf, zs), shellm),
             make_part("lid", "lid", S.prism(poly * 0.995, zs, zf + h), shellm)]
    ymax = float(poly[:, 1].max())
    ymin = float(poly[:, 1].min())
    for k, x in enumerate((-L * 0.3, L * 0.25)):
        parts.append(make_part(f"foot_{k}", "foot", S.box((0.05, W * 0.3, zf), center=(x, 0, zf / 2)), black))
    # the handle on the front side at the balance point, latches either side of it
    yf = ymax * 0.92
    parts.append(make_part("handle", "handle", S.tube([(-0.06, yf, zs), (-0.05, yf + 0.03, zs), (0.05, yf + 0.03, zs), (0.06, yf, zs)],
                                                      0.008, sections=8), black))
    # the two metal mounts the handle's ends are held in on the side of the shell
    parts += [make_part(f"handle_mount_{k}", "handle_mount", S.box((0.016, 0.012, 0.022), center=(sx * 0.06, yf + 0.002, zs)), metal)
              for k, sx in enumerate((-1, 1))]
    for k, x in enumerate((-0.16, 0.16)):
        parts.append(make_part(f"latch_{k}", "latch", S.box((0.03, 0.008, 0.03), center=(x, yf + 0.004, zs)), metal))
    parts.append(make_part("strap_ring", "strap_ring", S.box((0.02, 0.01, 0.012), center=(-L * 0.42, 0, zf + h + 0.006)), metal))
    parts.append(make_part("strap_ring_1", "strap_ring", S.box((0.02, 0.01, 0.012), center=(L * 0.42, 0, zf + h + 0.006)), metal))
    # the key lock in each latch, the name tag plate on the lid, the trim band along the seam
    for k, x in enumerate((-0.16, 0.16)):
        parts.append(make_part(f"lock_{k}", "lock", S.cylinder(0.004, 0.002, center=(x, yf + 0.009, zs + 0.006), axis=(0, 1, 0),
                                                               sections=8), black))
    parts.append(make_part("name_tag", "name_tag", S.box((0.06, 0.035, 0.002), center=(L * 0.15, 0, zf + h + 0.001)), metal))
    parts.append(make_part("trim", "trim", S.prism(poly * 1.004, zs - 0.003, zs + 0.003), black))
    yb = ymin * 0.92
    parts += hinge_parts("hinge", x=zs, y=yb - 0.005, z0=-0.2, z1=0.2, mat=metal, axis="x", radius=0.005, length=0.05)
    parts += [revolute("lid_hinge", "shell", "lid", axis=(1, 0, 0), origin=(0, yb, zs), opens=OPEN_DOOR * 0.6),
              mount("lid", "strap_ring"), mount("lid", "strap_ring_1"), mount("lid", "name_tag")]
    return parts
