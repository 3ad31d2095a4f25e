"""Hardware of flat-pack case goods shared by storage and bedroom furniture: levelling glides
under a case, the cam locks that draw its fixed panels to the sides, and the anti-tip wall strap
on its back."""

from __future__ import annotations

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part

__all__ = ["glides", "cams", "wall_strap"]


def glides(xs, ys, *, start: int = 0) -> list[Part]:
    """A levelling glide under each corner (at every x of ``xs`` and y of ``ys``): a plastic foot
    pressed into the bottom edge, flush with it (the cabinet stands on its glides)."""
    grey = M.solid((0.25, 0.25, 0.26), "plastic", 0.6)
    return [make_part(f"glide_{start + k}", "glide", S.cylinder(0.007, 0.003, center=(x, y, 0.0015), sections=10), grey)
            for k, (x, y) in enumerate((x, y) for x in xs for y in ys)]


def cams(zs, *, iw: float, ys, start: int = 0) -> list[Part]:
    """The cam locks that draw a fixed panel to the sides: a metal disc let flush into the panel's
    underside (at height ``zs``) near each side, at every y of ``ys``."""
    zinc = M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)
    out = []
    for z in zs:
        for y in ys:
            for sx in (-1, 1):
                out.append(make_part(f"cam_lock_{start + len(out)}", "cam_lock",
                                     S.cylinder(0.0075, 0.001, center=(sx * (iw / 2 - 0.012), y, z + 0.0005), sections=10), zinc))
    return out


def wall_strap(*, z: float, y: float) -> Part:
    """The anti-tip bracket screwed to the top of the back, which ties a tall case to the wall."""
    return make_part("wall_strap", "wall_strap", S.box((0.04, 0.002, 0.03), center=(0, y + 0.001, z)),
                     M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9))
