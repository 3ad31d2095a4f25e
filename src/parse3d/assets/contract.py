"""The contract every asset honours, whatever produced it (a generator or a loader).

:func:`check_asset` returns a list of human-readable problems (empty when the asset is sound):

* parts labelled from the category's vocabulary, the category's minimum labels present (a
  group label through any label it covers), unique names;
* six directional surfaces per part with unit normals matching their labels;
* every part inside the asset's bbox; base at z = 0 and centred in x and y;
* closed parts watertight;
* convex pieces convex, inside the part's bbox (with a small margin) and covering the part:
  total piece volume within 10% of the part's volume;
* size (largest extent) within the category's size range;
* joints (:func:`check_joints`): unique names, known types, existing and distinct parts, a tree
  (each part moved by at most one joint, no cycles), unit axes, ordered limits with 0 (the
  modelled, closed pose) at one end, the moved part attached to the rest of the asset at 0 and
  at both limits (no flying parts), and hinged parts opening out of the asset, not into it.
"""

from __future__ import annotations

import numpy as np

from ..relations import SURFACES
from .model import JOINT_TYPES, Asset

__all__ = ["check_asset", "check_joints", "VOLUME_TOLERANCE", "ATTACH_TOLERANCE"]

VOLUME_TOLERANCE = 0.10
#: Largest gap, metres, between a moved part and the part it hangs on: a drawer slide's side
#: clearance is 12.7 mm (half an inch); hinged parts touch their hinge line.
ATTACH_TOLERANCE = 0.015


def _is_convex(mesh) -> bool:
    """Whether a piece is a closed, consistently wound convex solid: every edge is used once in
    each direction, and no vertex lies in front of any face's plane (beyond 1e-6 of the piece's
    size). The same verdict as ``trimesh.Trimesh.is_convex`` for a collision piece, without
    its graph work."""
    v = np.asarray(mesh.vertices, float)
    f = np.asarray(mesh.faces, np.int64)
    if len(f) < 4:
        return False
    e = f[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
    key = e[:, 0] * len(v) + e[:, 1]
    rev = e[:, 1] * len(v) + e[:, 0]
    if len(np.unique(key)) != len(key) or not np.isin(rev, key).all():
        return False
    tri = v[f]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    ln = np.linalg.norm(n, axis=1)
    ok = ln > 1e-15
    n = n[ok] / ln[ok, None]
    d = np.einsum("ij,ij->i", n, tri[ok, 0])
    scale = max(float(np.ptp(v, axis=0).max()), 1e-9)
    return bool((v @ n.T - d <= 1e-6 * max(scale, 1.0) + 1e-9).all())


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
    for g, members in asset.label_groups.items():
        if labels & set(members):
            labels.add(g)  # a group label is present where any label it covers is
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
            if not _is_convex(pc):
                problems.append(f"part {p.name!r} piece {i} is not convex")
            if (pc.bounds[0] < pb[0] - margin).any() or (pc.bounds[1] > pb[1] + margin).any():
                problems.append(f"part {p.name!r} piece {i} lies outside the part")
            vol += abs(pc.volume)
        if p.watertight and p.mesh.is_watertight:
            mv = abs(p.mesh.volume)
            if mv > 1e-9 and abs(vol - mv) > VOLUME_TOLERANCE * mv:
                problems.append(f"part {p.name!r} pieces cover {vol / mv:.0%} of its volume "
                                f"(must be within {VOLUME_TOLERANCE:.0%})")
    problems += check_joints(asset)
    return problems


def check_joints(asset: Asset) -> list[str]:
    """Problems with ``asset.joints`` (an empty list for a sound or a rigid asset)."""
    if not asset.joints:
        return []
    import trimesh

    problems: list[str] = []
    names = {p.name for p in asset.parts}
    jn = [j.name for j in asset.joints]
    if len(set(jn)) != len(jn):
        problems.append(f"duplicate joint names: {sorted(n for n in set(jn) if jn.count(n) > 1)}")
    seen_child: dict[str, str] = {}
    for j in asset.joints:
        where = f"joint {j.name!r}"
        if j.type not in JOINT_TYPES:
            problems.append(f"{where} has type {j.type!r}, expected one of {list(JOINT_TYPES)}")
        for role, part in (("parent", j.parent_part), ("child", j.child_part)):
            if part not in names:
                problems.append(f"{where} names {role} part {part!r}, which the asset does not have")
        if j.parent_part == j.child_part:
            problems.append(f"{where} moves part {j.child_part!r} relative to itself")
        if j.child_part in seen_child:
            problems.append(f"part {j.child_part!r} is moved by two joints ({seen_child[j.child_part]!r}, {j.name!r})")
        seen_child[j.child_part] = j.name
        if abs(float(np.linalg.norm(j.axis)) - 1.0) > 1e-6:
            problems.append(f"{where} axis {list(j.axis)} is not a unit vector")
        lo, hi = j.limits
        if lo > hi:
            problems.append(f"{where} limits {list(j.limits)} are not ordered")
        elif not (lo == 0.0 or hi == 0.0):
            problems.append(f"{where} limits {list(j.limits)} do not have the closed pose 0 at one end")
    if problems:
        return problems
    by_child = {j.child_part: j for j in asset.joints}
    for j in asset.joints:  # a tree: walking up from any joint ends at a part no joint moves
        up, steps = j.parent_part, 0
        while up in by_child and steps <= len(asset.joints):
            up, steps = by_child[up].parent_part, steps + 1
        if steps > len(asset.joints):
            problems.append(f"joint {j.name!r} is part of a cycle of joints")
            return problems
    meshes = {p.name: p.mesh for p in asset.parts}
    children: dict[str, list[str]] = {}
    for j in asset.joints:
        children.setdefault(j.parent_part, []).append(j.child_part)

    def subtree(part: str) -> set[str]:
        out, todo = set(), [part]
        while todo:
            p = todo.pop()
            if p not in out:
                out.add(p)
                todo += children.get(p, [])
        return out

    # with every other joint closed, the parts a joint does not move stay where they are modelled:
    # one collision manager over all parts serves every joint (its moving parts taken out)
    everything = trimesh.collision.CollisionManager()
    for name, m in meshes.items():
        everything.add_object(name, m)
    part_bounds = {name: np.asarray(m.bounds) for name, m in meshes.items()}
    for j in asset.joints:
        moving = subtree(j.child_part)
        static = [n for n in meshes if n not in moving]
        if not static:
            continue
        values = [0.0] if j.is_mount else [0.0, *(v for v in j.limits if v != 0.0)]
        if j.type == "revolute" and not j.is_mount:  # the first tenth shows which way it swings
            values.insert(1, 0.1 * j.at_ratio(1.0))
        rb = np.array([part_bounds[n] for n in static])
        rest_centre = (rb[:, 0].min(axis=0) + rb[:, 1].max(axis=0)) / 2
        for n in moving:
            everything.remove_object(n)
        closed_reach = None
        for v in values:
            T = asset.part_transforms({j.name: v}).get(j.child_part, np.eye(4))
            # attached: the moved part touches the rest of the asset (its parent, or the runners
            # and neighbours it rides on), within the tolerance
            gap = everything.min_distance_single(meshes[j.child_part], transform=T)
            if gap > ATTACH_TOLERANCE:
                problems.append(f"joint {j.name!r} at {v:.3f}: part {j.child_part!r} is {gap * 1000:.1f} mm away from "
                                f"the rest of the asset (must stay attached, within {ATTACH_TOLERANCE * 1000:.0f} mm)")
            # a hinged part opens out of the asset, never into it: its centre gets no closer to the
            # centre of the rest of the asset than it is when closed (slides run along a face or
            # out of it; the attachment check above keeps them on their runners)
            if j.type != "revolute":
                continue
            c = T[:3, :3] @ part_bounds[j.child_part].mean(axis=0) + T[:3, 3]
            reach = float(np.linalg.norm(c - rest_centre))
            if closed_reach is None:
                closed_reach = reach
            elif reach < closed_reach - 1e-3:
                problems.append(f"joint {j.name!r} at {v:.3f} moves {j.child_part!r} into the asset, not out of it")
        for n in moving:
            everything.add_object(n, meshes[n])
    return problems
