"""Shared detail for keyboard instruments: a row of white keys, each its own part."""

from __future__ import annotations

from ...geometry import shapes as S
from ..model import Material, Part, make_part


def white_keys(x0: float, x1: float, *, y_front: float, depth: float, z0: float, z1: float, mat: Material,
               n: int = 52, label: str = "key", prefix: str = "white_key") -> list[Part]:
    """``n`` white keys side by side between ``x0`` and ``x1`` (a 1 mm gap between keys), their
    fronts at ``y_front`` (+Y), reaching ``depth`` back, from ``z0`` up to their tops at ``z1``."""
    kw = (x1 - x0) / n
    return [make_part(f"{prefix}_{k}", label,
                      S.box((kw - 0.001, depth, z1 - z0), center=(x0 + (k + 0.5) * kw, y_front - depth / 2, (z0 + z1) / 2)),
                      mat) for k in range(n)]
