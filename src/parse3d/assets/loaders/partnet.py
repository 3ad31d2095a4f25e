"""PartNet-Mobility-style folders: ``mobility.urdf`` + ``textured_objs/*.obj`` + ``semantics.txt``.

Every URDF link with ``<visual>`` meshes becomes one part, in the rest pose (each joint at 0,
clipped into its limits). ``semantics.txt`` has one line per link, ``link_name joint_type
semantic_label``; the semantic label, passed through an optional mapping (a mapping entry for
the link name wins over one for its semantic label), is the part label.

Frame: the URDF's joint and visual origins are applied, so coordinates are those of the URDF's
root link. In PartNet-Mobility the root joint rotates the raw Y-up, front -Z meshes upright
(rpy = 90 deg, 0, -90 deg), leaving objects +Z up and facing +X, in normalised units
(:data:`PARTNET_FRAME`); the category's size range sets the metric scale.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import trimesh

from ..._files import read_input_bytes, read_input_text
from ...errors import InputError, Problem
from ...geometry.frames import axis_angle, rot_x, rot_y, rot_z
from ..model import Asset, Joint
from ._canon import (
    MAX_FACES,
    MAX_SOURCE_BYTES,
    PARTNET_FRAME,
    RawAsset,
    RawPart,
    SourceFrame,
    check_mapping_labels,
    check_part_mesh,
    check_raw_asset,
    clean_mesh,
    default_label,
    finish_asset,
    material_of,
    part_label_problems,
    read_mapping,
)

__all__ = ["read_partnet_mobility", "load_partnet_mobility", "is_partnet_folder"]


def is_partnet_folder(path: str | os.PathLike) -> bool:
    """Whether ``path`` is a folder holding a ``mobility.urdf``."""
    return (Path(path) / "mobility.urdf").is_file()


def _floats(s: str | None, n: int) -> np.ndarray:
    if not s:
        return np.zeros(n)
    v = np.array([float(x) for x in s.split()[:n + 1]])
    if len(v) != n:
        raise ValueError(f"expected {n} numbers, got {s[:100]!r}")
    if not np.isfinite(v).all() or np.abs(v).max() > 1e6:
        raise ValueError(f"{s[:100]!r} holds a value that is not a finite number of at most 1e6")
    return v


def _origin(el) -> np.ndarray:
    """(4, 4) transform of an URDF ``<origin xyz rpy>`` (fixed-axis roll, pitch, yaw)."""
    T = np.eye(4)
    if el is None:
        return T
    r, p, y = _floats(el.get("rpy"), 3)
    T[:3, :3] = rot_z(y) @ rot_y(p) @ rot_x(r)
    T[:3, 3] = _floats(el.get("xyz"), 3)
    return T


def _joint_motion(joint) -> np.ndarray:
    """(4, 4) motion of a joint at its rest value: 0 clipped into its limits."""
    kind = joint.get("type", "fixed")
    T = np.eye(4)
    if kind in ("fixed", "floating", "planar"):
        return T
    lim = joint.find("limit")
    q = 0.0
    if lim is not None and kind != "continuous":
        lo = _floats(lim.get("lower", "0") or "0", 1)[0]
        hi = _floats(lim.get("upper", "0") or "0", 1)[0]
        if lo <= hi:
            q = float(np.clip(0.0, lo, hi))
    if q == 0.0:
        return T
    ax_el = joint.find("axis")
    axis = _floats(ax_el.get("xyz") if ax_el is not None else "1 0 0", 3)
    axis = axis / (np.linalg.norm(axis) or 1.0)
    if kind in ("revolute", "continuous"):
        T[:3, :3] = axis_angle(axis, q)
    elif kind == "prismatic":
        T[:3, 3] = axis * q
    return T


def _read_semantics(path: Path) -> dict[str, str]:
    out: dict[str, str] = {}
    if not path.exists():
        return out
    for line in read_input_text(path, what="semantics file").splitlines():
        f = line.split()
        if len(f) >= 3:
            out[f[0]] = f[2]
    return out


def read_partnet_mobility(folder: str | os.PathLike, *, mapping=None,
                          frame: SourceFrame = PARTNET_FRAME,
                          vocabulary: tuple[str, ...] | None = None) -> RawAsset:
    """Read a PartNet-Mobility-style folder into a :class:`RawAsset`.

    Raises
    ------
    InputError
        Missing folder or ``mobility.urdf``, malformed URDF, a missing mesh file, a link with
        geometry but no label, fewer than two parts, or a label outside ``vocabulary``.
    """
    folder = Path(folder)
    urdf = folder / "mobility.urdf"
    if not folder.is_dir():
        raise InputError(Problem("", "folder not found", str(folder), "io"))
    if not urdf.is_file():
        raise InputError(Problem("", "not a PartNet-Mobility folder (no mobility.urdf)", str(folder), "io"))
    mapping, mfile = read_mapping(mapping)
    check_mapping_labels(mapping, vocabulary, mfile)
    file = str(urdf)
    try:
        root = ET.fromstring(read_input_bytes(urdf, what="URDF file"))
    except ET.ParseError as e:
        raise InputError(Problem("", f"malformed URDF: {e}", file, "syntax")) from None
    links = {ln.get("name"): ln for ln in root.findall("link")}
    if None in links or "" in links:
        raise InputError(Problem("/link", "a link without a name", file, "schema"))
    children: dict[str, list] = {}
    child_of = set()
    for j in root.findall("joint"):
        p, c = j.find("parent"), j.find("child")
        if p is None or c is None or p.get("link") is None or c.get("link") is None:
            raise InputError(Problem(f"/joint/{j.get('name')}", "joint without parent or child", file, "schema"))
        children.setdefault(p.get("link"), []).append(j)
        child_of.add(c.get("link"))
    world = _link_frames(links, children, child_of, file)
    semantics = _read_semantics(folder / "semantics.txt")
    S = np.eye(4)
    S[:3, :3] = frame.rotation() * float(frame.unit_scale)
    parts, unlabelled, probs = [], [], []
    base = folder.resolve()
    budget = [MAX_FACES]  # faces still allowed; an OBJ is refused before it is loaded
    for name in sorted(links, key=_natural):
        link = links[name]
        meshes = []
        mat = None
        for vis in link.findall("visual"):
            m_el = vis.find("geometry/mesh")
            if m_el is None:
                continue
            where = f"/link/{name}/visual"
            mpath = folder / m_el.get("filename", "")
            try:
                inside = mpath.resolve().is_relative_to(base)
            except (OSError, RuntimeError):  # a symlink loop
                inside = False
            if not inside:
                probs.append(Problem(where, f"mesh file {m_el.get('filename')!r} lies outside "
                                     "the PartNet folder: only files inside it are read", file,
                                     "io"))
                continue
            if not mpath.is_file():
                probs.append(Problem(where, f"mesh file {m_el.get('filename')!r} not found",
                                     file, "io"))
                continue
            try:
                _check_obj_size(mpath, budget)
                mesh = trimesh.load(str(mpath), force="mesh")
            except InputError as e:
                probs += e.problems
                break
            except Exception as e:  # noqa: BLE001 - trimesh raises many types for a broken file
                probs.append(Problem(where, f"cannot read {mpath.name}: {str(e)[:200]}", file,
                                     "syntax"))
                continue
            if not isinstance(mesh, trimesh.Trimesh) or len(mesh.faces) == 0:
                continue
            budget[0] -= len(mesh.faces)
            try:
                scale = _floats(m_el.get("scale"), 3) if m_el.get("scale") else np.ones(3)
                T_vis = _origin(vis.find("origin"))
            except ValueError as e:
                probs.append(Problem(where, f"bad origin or scale: {e}", file, "syntax"))
                continue
            if not (np.abs(scale) >= 1e-6).all():
                probs.append(Problem(where, "a mesh scale of 0 (or below 1e-6) flattens the "
                                     "part", file, "geometry"))
                continue
            bad = check_part_mesh(mesh, where, file)
            if bad:
                probs += bad
                continue
            mat = mat or material_of(mesh)
            m = mesh.copy()
            if not np.allclose(scale, 1.0):
                m.apply_transform(np.diag([*scale, 1.0]))
            m.apply_transform(S @ world.get(name, np.eye(4)) @ T_vis)
            meshes.append(m)
        if not meshes:
            continue
        if name in mapping:
            label = mapping[name]
        elif name in semantics:
            sem = semantics[name]
            label = mapping.get(sem, mapping.get(default_label(sem), default_label(sem)))
        else:
            unlabelled.append(name)
            continue
        if label is None:
            continue
        mesh = clean_mesh(trimesh.util.concatenate(meshes))
        parts.append(RawPart(name, label, mesh, mat or material_of(mesh)))
    if unlabelled:
        probs.append(Problem("", f"links {unlabelled} have geometry but no line in semantics.txt and no "
                             "mapping entry", file, "vocabulary"))
    probs += part_label_problems(parts, vocabulary, file, "/link")
    if probs:
        raise InputError(probs)
    if len(parts) < 2:
        raise InputError(Problem("", f"found {len(parts)} labelled link(s) with geometry; a part-split "
                                 "asset needs at least two", file, "geometry"))
    try:
        joints = _read_joints(root, world, {p.source for p in parts}, S, file)
    except ValueError as e:
        raise InputError(Problem("", f"bad joint: {e}", file, "syntax")) from None
    raw = RawAsset(str(folder), parts, {"source_format": "partnet-mobility",
                                         "frame": frame.__dict__.copy()}, joints)
    check_raw_asset(raw, file)
    return raw


def _link_frames(links: dict, children: dict[str, list], child_of: set, file: str
                 ) -> dict[str, np.ndarray]:
    """World (4, 4) frame of every link reachable from a root, in the rest pose.

    Raises
    ------
    InputError
        A link reached twice (a joint cycle, or a link with two parent joints), or a joint
        origin, axis or limit that is not a finite number.
    """
    world: dict[str, np.ndarray] = {}
    stack = [(name, np.eye(4)) for name in links if name not in child_of]
    try:
        while stack:
            name, T = stack.pop()
            if name in world:
                raise InputError(Problem(f"/link/{name}", f"link {name!r} is reached by two "
                                         "joint paths (a joint cycle or two parents): a URDF "
                                         "is a tree", file, "schema"))
            world[name] = T
            for j in children.get(name, []):
                stack.append((j.find("child").get("link"),
                              T @ _origin(j.find("origin")) @ _joint_motion(j)))
    except ValueError as e:
        raise InputError(Problem("", f"bad joint origin: {e}", file, "syntax")) from None
    if len(child_of) and not any(n not in child_of for n in links):
        raise InputError(Problem("", "every link is the child of a joint (a joint cycle): a "
                                     "URDF needs a root link", file, "schema"))
    return world


def _check_obj_size(path: Path, budget: list[int]) -> None:
    """Refuse a mesh file over :data:`MAX_SOURCE_BYTES`, or an OBJ whose face lines exceed
    what is left of the asset's :data:`MAX_FACES` (counted without parsing it)."""
    data = read_input_bytes(path, limit=MAX_SOURCE_BYTES, what="mesh file")
    if path.suffix.lower() == ".obj":
        faces = data.count(b"\nf ") + data.startswith(b"f ")
        if faces > budget[0]:
            raise InputError(Problem("", f"the asset's meshes have more than {MAX_FACES:,} "
                                         "faces (simplify them first)", str(path), "geometry"))


def _read_joints(root, world: dict[str, np.ndarray], with_parts: set[str], S: np.ndarray,
                 file: str) -> list[Joint]:
    """The URDF's movable joints as asset joints (canonical orientation, source link names).

    A joint's parent is its parent link, or the nearest ancestor link that became a part; a
    fixed joint under a moving part mounts its child on it (a handle on a door). Limits are
    taken relative to the rest pose the meshes were read in, so 0 is that pose; when the rest
    value lies inside the range, the longer side is kept so 0 stays at one end.
    """
    parent_of = {j.find("child").get("link"): j for j in root.findall("joint")}

    def part_above(link: str | None) -> str | None:
        seen = set()
        while link is not None and link not in seen:
            if link in with_parts:
                return link
            seen.add(link)
            j = parent_of.get(link)
            link = j.find("parent").get("link") if j is not None else None
        return None

    R = S[:3, :3] / np.cbrt(np.linalg.det(S[:3, :3]))
    out: list[Joint] = []
    moving: set[str] = set()
    for j in root.findall("joint"):  # URDF lists parents before children in practice
        kind = j.get("type", "fixed")
        child = j.find("child").get("link")
        parent = part_above(j.find("parent").get("link"))
        if child not in with_parts or parent is None:
            continue
        name = j.get("name") or f"{child}_joint"
        if kind == "fixed":
            if parent in moving:
                out.append(Joint(f"{child}_mount", "prismatic", parent, child, (0.0, 0.0, 1.0),
                                 (0.0, 0.0, 0.0), (0.0, 0.0)))
                moving.add(child)
            continue
        if kind not in ("revolute", "continuous", "prismatic"):
            continue
        ax_el = j.find("axis")
        axis = _floats(ax_el.get("xyz") if ax_el is not None else "1 0 0", 3)
        if np.linalg.norm(axis) == 0:
            raise InputError(Problem(f"/joint/{name}/axis", "zero joint axis", file, "geometry"))
        # the joint frame before its motion: the parent link's world frame times the origin
        Tj = S @ world.get(j.find("parent").get("link"), np.eye(4)) @ _origin(j.find("origin"))
        a = R @ (world.get(j.find("parent").get("link"), np.eye(4))[:3, :3]
                 @ _origin(j.find("origin"))[:3, :3] @ (axis / np.linalg.norm(axis)))
        lim = j.find("limit")
        if kind == "continuous" or lim is None:
            lo, hi = (0.0, 2 * np.pi) if kind != "prismatic" else (0.0, 0.0)
        else:
            lo = _floats(lim.get("lower", "0") or "0", 1)[0]
            hi = _floats(lim.get("upper", "0") or "0", 1)[0]
        rest = float(np.clip(0.0, min(lo, hi), max(lo, hi)))
        lo, hi = min(lo, hi) - rest, max(lo, hi) - rest
        if lo < 0 < hi:
            lo, hi = (0.0, hi) if hi >= -lo else (lo, 0.0)
        scale = float(np.cbrt(np.linalg.det(S[:3, :3])))
        if kind == "prismatic":
            lo, hi = lo * scale, hi * scale
        out.append(Joint(name, "prismatic" if kind == "prismatic" else "revolute", parent, child,
                         tuple(float(x) for x in a / np.linalg.norm(a)),
                         tuple(float(x) for x in Tj[:3, 3]), (float(lo), float(hi))))
        moving.add(child)
    return out


def _natural(name: str):
    import re

    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", name)]


def load_partnet_mobility(folder: str | os.PathLike, *, category: str, mapping=None,
                          frame: SourceFrame = PARTNET_FRAME,
                          size_range: tuple[float, float] | None = None,
                          density: float | None = None, asset_id: str | None = None,
                          cache_dir: str | os.PathLike | None = None) -> Asset:
    """Load a PartNet-Mobility folder as an asset of ``category`` (see :func:`load_glb` for the
    parameters; ``frame`` defaults to :data:`PARTNET_FRAME`)."""
    from .glb import _category_defaults

    vocab, sr, dens = _category_defaults(category)
    raw = read_partnet_mobility(folder, mapping=mapping, frame=frame, vocabulary=vocab)
    return finish_asset(raw, category=category,
                        asset_id=asset_id or f"{category}-{Path(folder).name}",
                        size_range=size_range or sr, density=density or dens or 500.0,
                        cache_dir=cache_dir)
