"""Check that asset generation gives the same assets as before a change (a speed-up's proof).

Generates every procedural category for a few seeds and writes, per asset, the arrays that
define it: every part's name, label, mesh vertices and faces, convex pieces, the six
directional surfaces (origin, normal, axes, polygon rings), internal surfaces and joints.
``--save FILE`` stores them; ``--compare FILE`` generates again and reports every difference
larger than ``--atol`` (exit status 1 if any).

    python benchmarks/check_asset_equivalence.py --save before.npz     # on the old revision
    python benchmarks/check_asset_equivalence.py --compare before.npz  # after the change
"""

from __future__ import annotations

import argparse
import sys

import numpy as np
from shapely.geometry import MultiPolygon

from parse3d.assets import registry


def _rings(poly) -> list[np.ndarray]:
    geoms = poly.geoms if isinstance(poly, MultiPolygon) else [poly]
    out = []
    for g in geoms:
        if g.is_empty:
            continue
        out.append(np.asarray(g.exterior.coords, float))
        out.extend(np.asarray(r.coords, float) for r in g.interiors)
    return out


def _surface(prefix: str, s, rec: dict) -> None:
    rec[f"{prefix}/source"] = np.array(s.source)
    for k in ("origin", "normal", "u", "v"):
        rec[f"{prefix}/{k}"] = np.asarray(getattr(s, k), float)
    for i, r in enumerate(_rings(s.polygon)):
        rec[f"{prefix}/ring{i}"] = r


def asset_arrays(category: str, seed: int) -> dict[str, np.ndarray]:
    """Every array defining asset (category, seed), keyed by a readable path."""
    a = registry.generate(category, seed)
    key = f"{category}/{seed}"
    rec: dict[str, np.ndarray] = {}
    rec[f"{key}/parts"] = np.array([f"{p.name}:{p.label}" for p in a.parts])
    for p in a.parts:
        pk = f"{key}/{p.name}"
        rec[f"{pk}/vertices"] = np.asarray(p.mesh.vertices, float)
        rec[f"{pk}/faces"] = np.asarray(p.mesh.faces)
        rec[f"{pk}/color"] = np.asarray(p.material.color, float)
        rec[f"{pk}/npieces"] = np.array(len(p.pieces))
        for i, pc in enumerate(p.pieces):
            rec[f"{pk}/piece{i}/vertices"] = np.asarray(pc.vertices, float)
            rec[f"{pk}/piece{i}/faces"] = np.asarray(pc.faces)
        for lab, s in sorted(p.surfaces.items()):
            _surface(f"{pk}/surface/{lab}", s, rec)
    for i, s in enumerate(a.internal):
        ik = f"{key}/internal{i}"
        rec[f"{ik}/part"] = np.array(s.part)
        rec[f"{ik}/clearance_depth"] = np.array([s.clearance, s.depth], float)
        _surface(f"{ik}/surface", s.surface, rec)
    for i, j in enumerate(a.joints):
        d = j.to_dict()
        rec[f"{key}/joint{i}"] = np.array(repr(sorted(d.items())))
    return rec


def collect(seeds: int, categories: list[str]) -> dict[str, np.ndarray]:
    rec: dict[str, np.ndarray] = {}
    for c in categories:
        for s in range(seeds):
            rec.update(asset_arrays(c, s))
    return rec


def compare(before: dict, now: dict, atol: float) -> list[str]:
    problems = []
    for k in sorted(set(before) | set(now)):
        if k not in now:
            problems.append(f"{k}: missing now")
            continue
        if k not in before:
            problems.append(f"{k}: new")
            continue
        a, b = before[k], now[k]
        if a.dtype.kind in "fc" or b.dtype.kind in "fc":
            if a.shape != b.shape:
                problems.append(f"{k}: shape {a.shape} -> {b.shape}")
            elif not np.allclose(a, b, rtol=0.0, atol=atol, equal_nan=True):
                problems.append(f"{k}: max difference {np.nanmax(np.abs(a - b)):.3g}")
        elif a.shape != b.shape or not np.array_equal(a, b):
            problems.append(f"{k}: {a!r} -> {b!r}"[:200])
    return problems


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=2)
    ap.add_argument("--categories", default="", help="comma-separated subset (default: all)")
    ap.add_argument("--atol", type=float, default=1e-9)
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--save", metavar="FILE")
    g.add_argument("--compare", metavar="FILE")
    args = ap.parse_args()
    cats = [c for c in args.categories.split(",") if c] or [
        n for n, c in registry.categories().items() if c.generator is not None]
    if args.save:
        rec = collect(args.seeds, cats)
        np.savez_compressed(args.save, **rec)
        print(f"saved {len(rec)} arrays of {len(cats)} categories x {args.seeds} seeds")
        return
    with np.load(args.compare) as f:
        before = {k: f[k] for k in f.files}
    saved = {k.split("/")[0] for k in before}
    cats = [c for c in cats if c in saved]
    before = {k: a for k, a in before.items() if k.split("/")[0] in cats}
    cats_before = cats
    now = collect(args.seeds, cats)
    problems = compare(before, now, args.atol)
    for p in problems[:50]:
        print(p)
    print(f"{len(before)} arrays compared over {len(cats_before)} categories x {args.seeds} seeds: "
          f"{len(problems)} differ (atol {args.atol:g})")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
