"""Fixings shared by the table, chair and dining-room generators: the screws that hold glued
blocks and plates to the top or seat above them."""

from __future__ import annotations

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part


def screws_under(parts: list[Part], label: str, *, start: int = 0, radius: float = 0.005) -> list[Part]:
    """One ``screw`` per part labelled ``label`` (a corner block, a cleat), driven up through its
    middle into what is above: a round head ``radius`` metres wide, 2 mm tall, just under the
    part's bottom face, where nothing rests. Named ``screw_{start}``, ``screw_{start + 1}``, ..."""
    steel = M.solid((0.55, 0.55, 0.57), "metal", 0.35, 0.9)
    out = []
    for p in parts:
        if not isinstance(p, Part) or p.label != label:
            continue
        (x0, y0, z0), (x1, y1, _) = p.bounds
        out.append(make_part(f"screw_{start + len(out)}", "screw",
                             S.cylinder(radius, 0.002, center=((x0 + x1) / 2, (y0 + y1) / 2, z0 - 0.001), sections=8), steel))
    return out
