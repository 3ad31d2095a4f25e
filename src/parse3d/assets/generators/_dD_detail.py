"""Small real fixings for the tabletop, kitchen, dining and seating generators: the rivets
through a knife's handle scales, and screws or bolts let flush into a face nothing rests on."""

from __future__ import annotations

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part

__all__ = ["steel", "rivets_through", "flush_screws", "back_screws"]


def steel() -> Material:
    """Bright steel for rivets, screws and bolts."""
    return M.solid((0.62, 0.62, 0.64), "metal", 0.3, 0.9)


def rivets_through(prefix: str, centres, *, length: float, axis=(0.0, 1.0, 0.0), radius: float = 0.0022,
                   mat: Material | None = None, start: int = 0) -> list[Part]:
    """One ``rivet`` per point of ``centres``, a pin ``length`` long along ``axis`` whose two heads
    lie flush with the faces of the handle it goes through. Named ``<prefix>_{start}``, ..."""
    mat = mat or steel()
    return [make_part(f"{prefix}_{start + k}", "rivet",
                      S.cylinder(radius, length, center=tuple(float(v) for v in c), axis=axis, sections=8), mat)
            for k, c in enumerate(centres)]


def flush_screws(prefix: str, centres, *, axis, radius: float = 0.004, depth: float = 0.0015,
                 label: str = "screw", mat: Material | None = None, start: int = 0) -> list[Part]:
    """One round screw head per point of ``centres`` (each the centre of the face it sits in),
    sunk ``depth`` into that face along ``-axis`` (``axis`` the face's outward normal) so it is
    flush with it. Named ``<prefix>_{start}``, ..."""
    mat = mat or steel()
    out = []
    for k, c in enumerate(centres):
        ctr = tuple(float(c[i]) - axis[i] * depth / 2 for i in range(3))
        out.append(make_part(f"{prefix}_{start + k}", label,
                             S.cylinder(radius, depth, center=ctr, axis=axis, sections=8), mat))
    return out


def back_screws(prefix: str, *, x0: float, x1: float, z0: float, z1: float, y: float, inset: float = 0.02,
                radius: float = 0.004, start: int = 0) -> list[Part]:
    """The four screws holding an appliance's cabinet at the corners of its back face (the plane
    y = ``y``, facing -Y, spanning ``[x0, x1] x [z0, z1]``), ``inset`` in from its edges and flush
    with it. Named ``<prefix>_{start}`` to ``<prefix>_{start + 3}``, labelled ``screw``."""
    pts = [(x, y, z) for z in (z0 + inset, z1 - inset) for x in (x0 + inset, x1 - inset)]
    return flush_screws(prefix, pts, axis=(0.0, -1.0, 0.0), radius=radius, start=start)
