"""Vent grilles as the slots a person sees: a row of thin strips, each a part of its own, in
a face's plane (the first keeps the name the whole grille had, so earlier labels still name it)."""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from ..model import Material, Part, make_part


def slots(name: str, label: str, *, n: int, x0: float, x1: float, z0: float, z1: float, y: float, thick: float,
          mat: Material, vertical: bool = False, open_frac: float = 0.45) -> list[Part]:
    """``n`` slots in the plane ``y`` over ``[x0, x1] x [z0, z1]``: horizontal strips stacked in z
    (or ``vertical`` ones side by side in x), each ``open_frac`` of its pitch wide, ``thick``
    deep. Named ``name``, ``name_1``, ..., labelled ``label``."""
    out = []
    if vertical:
        pitch = (x1 - x0) / n
        for cx in x0 + pitch * (np.arange(n) + 0.5):
            out.append(S.box((pitch * open_frac, thick, z1 - z0), center=(float(cx), y, (z0 + z1) / 2)))
    else:
        pitch = (z1 - z0) / n
        for cz in z0 + pitch * (np.arange(n) + 0.5):
            out.append(S.box((x1 - x0, thick, pitch * open_frac), center=((x0 + x1) / 2, y, float(cz))))
    return [make_part(name if k == 0 else f"{name}_{k}", label, s, mat) for k, s in enumerate(out)]
