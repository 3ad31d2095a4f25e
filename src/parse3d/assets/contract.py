"""The contract every asset honours, whatever produced it (a generator or a loader).

:func:`check_asset` returns a list of human-readable problems (empty when the asset is sound):

* parts labelled from the category's vocabulary, the category's minimum labels present, unique
  names;
* six directional surfaces per part with unit normals matching their labels;
* every part inside the asset's bbox; base at z = 0 and centred in x and y;
* closed parts watertight;
* convex pieces convex, inside the part's bbox (with a small margin) and covering the part:
  total piece volume within 10% of the part's volume;
* size (largest extent) within the category's size range.
"""

from __future__ import annotations

import numpy as np

from ..relations import SURFACES
from .model import Asset

__all__ = ["check_asset", "VOLUME_TOLERANCE"]

VOLUME_TOLERANCE = 0.10


def check_asset(asset: Asset, *, vocabulary: tuple[str, ...] | None = None,
                required: tuple[str, ...] | None = None,
                size_range: tuple[float, float] | None = None) -> list[str]:
    """Problems with ``asset`` (an empty list when it honours the contract).

    Parameters
    ----------
    asset : Asset
    vocabulary, required : tuple of str, optional
        Allowed and required part labels; default to the registered category's.
    size_range : (low, high), optional
        Defaults to ``asset.size_range``.
    """
    problems: list[str] = []
    if vocabulary is None or required is None:
        from . import registry

        try:
            cat = registry.get(asset.category)
            vocabulary = vocabulary or cat.vocabulary
            required = required or cat.parts
        except KeyError:
            problems.append(f"category {asset.category!r} is not registered")
            vocabulary, required = vocabulary or (), required or ()
    lo_sz, hi_sz = size_range or asset.size_range
    if not asset.parts:
        return ["asset has no parts"]
    names = [p.name for p in asset.parts]
    if len(set(names)) != len(names):
        problems.append(f"duplicate part names: {sorted(n for n in set(names) if names.count(n) > 1)}")
    labels = {p.label for p in asset.parts}
    for r in required:
        if r not in labels:
            problems.append(f"missing required part label {r!r} (has {sorted(labels)})")
    for p in asset.parts:
        if vocabulary and p.label not in vocabulary:
            problems.append(f"part {p.name!r} has label {p.label!r} outside the vocabulary {list(vocabulary)}")
    b = asset.bounds
    ext = b[1] - b[0]
    tol = 1e-4 + 1e-6 * max(ext.max(), 1.0)
    if abs(b[0, 2]) > tol:
        problems.append(f"base not at z = 0 (min z = {b[0, 2]:.5f})")
    c = (b[0, :2] + b[1, :2]) / 2
    if np.abs(c).max() > tol:
        problems.append(f"not centred in x, y (bbox centre {c.round(5).tolist()})")
    if not (lo_sz - 1e-6 <= asset.size <= hi_sz + 1e-6):
        problems.append(f"size {asset.size:.3f} m outside the size range [{lo_sz}, {hi_sz}]")
    for p in asset.parts:
        pb = p.bounds
        if (pb[0] < b[0] - tol).any() or (pb[1] > b[1] + tol).any():
            problems.append(f"part {p.name!r} sticks out of the asset bbox")
        if set(p.surfaces) != set(SURFACES):
            problems.append(f"part {p.name!r} has surfaces {sorted(p.surfaces)}, expected all six")
        for label, s in p.surfaces.items():
            n = np.asarray(s.normal)
            if abs(np.linalg.norm(n) - 1) > 1e-6 or np.dot(n, SURFACES.get(label, (0, 0, 0))) < 0.999:
                problems.append(f"part {p.name!r} surface {label!r} normal {n.round(4).tolist()} does not match")
            if s.area <= 0:
                problems.append(f"part {p.name!r} surface {label!r} has no area")
        if p.watertight and not p.mesh.is_watertight:
            problems.append(f"part {p.name!r} is not watertight")
        if not p.pieces:
            problems.append(f"part {p.name!r} has no collision pieces")
            continue
        margin = 0.003 + 0.02 * float(np.linalg.norm(pb[1] - pb[0]))
        vol = 0.0
        for i, pc in enumerate(p.pieces):
            if not pc.is_convex:
                problems.append(f"part {p.name!r} piece {i} is not convex")
            if (pc.bounds[0] < pb[0] - margin).any() or (pc.bounds[1] > pb[1] + margin).any():
                problems.append(f"part {p.name!r} piece {i} lies outside the part")
            vol += abs(pc.volume)
        if p.watertight and p.mesh.is_watertight:
            mv = abs(p.mesh.volume)
            if mv > 1e-9 and abs(vol - mv) > VOLUME_TOLERANCE * mv:
                problems.append(f"part {p.name!r} pieces cover {vol / mv:.0%} of its volume "
                                f"(must be within {VOLUME_TOLERANCE:.0%})")
    return problems
