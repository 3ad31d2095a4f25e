"""The room shell: floor, walls and ceiling built from a PAG's room.

The slabs are extruded with trimesh. Their vertices and faces are kept on disk, in
``$PARSE3D_CACHE/shell/<key>.npz`` keyed by the slabs' outlines and heights, so solving a room
seen before imports no mesh library. A damaged entry is extruded again, and a cache that
cannot be written only costs the extrusion.
"""

from __future__ import annotations

import contextlib
import functools
import hashlib
import os
import tempfile

import numpy as np
from shapely.geometry import Polygon

from ..geometry.meshes import MeshArrays
from ..geometry.surfaces import Surface
from ..pag.model import Room
from .model import RoomShell, ShellElement

__all__ = ["build_shell", "DEFAULT_WALL_THICKNESS"]

DEFAULT_WALL_THICKNESS = 0.12
_SLAB = 0.1  # floor and ceiling slab thickness, m
#: Version of the shell cache's entries: change it when the extrusion changes.
_CACHE_FORMAT = b"parse3d-shell/1"


def _extrude(poly2d: np.ndarray, z0: float, z1: float) -> MeshArrays:
    import trimesh

    m = trimesh.creation.extrude_polygon(Polygon(poly2d), z1 - z0).apply_translation([0, 0, z0])
    return MeshArrays(np.asarray(m.vertices, np.float64).copy(), np.asarray(m.faces, np.int64).copy())


def _slab_meshes(slabs: list[tuple[np.ndarray, float, float]]) -> list[MeshArrays]:
    """The extrusion of every ``(outline (K, 2), z0, z1)``: from the shell cache, or
    extruded (and cached)."""
    h = hashlib.sha256(_CACHE_FORMAT)
    h.update(_extruder_stamp())
    for poly, z0, z1 in slabs:
        h.update(np.ascontiguousarray(poly, np.float64).tobytes())
        h.update(np.float64([len(poly), z0, z1]).tobytes())
    root = _cache_root()
    path = None if root is None else root / "shell" / f"{h.hexdigest()[:32]}.npz"
    if path is not None and path.is_file():
        try:
            with np.load(path, allow_pickle=False) as data:
                out = [MeshArrays(data[f"v{i}"].astype(np.float64), data[f"f{i}"].astype(np.int64))
                       for i in range(len(slabs))]
            if all(m.vertices.ndim == 2 and m.vertices.shape[1] == 3 and m.faces.ndim == 2
                   and m.faces.shape[1] == 3 and (m.faces.size == 0 or
                                                  m.faces.min() >= 0 and
                                                  m.faces.max() < len(m.vertices))
                   for m in out):
                return out
        except (OSError, ValueError, KeyError, EOFError):
            pass  # damaged: extrude again below
    out = [_extrude(poly, z0, z1) for poly, z0, z1 in slabs]
    if path is not None:
        _write(path, out)
    return out


@functools.lru_cache(maxsize=1)
def _extruder_stamp() -> bytes:
    """Size and modification time of trimesh's extrusion code, found without importing
    trimesh: another trimesh may triangulate differently (looked up once per process)."""
    import importlib.util

    spec = importlib.util.find_spec("trimesh")
    for base in (spec.submodule_search_locations or []) if spec else []:
        with contextlib.suppress(OSError):
            st = os.stat(os.path.join(base, "creation.py"))
            return f"{st.st_size}:{st.st_mtime_ns}".encode()
    return b"-"


def _cache_root():
    """The cache folder, or None when ``$PARSE3D_CACHE`` is unusable (nothing is cached)."""
    from ..assets.library import cache_dir
    from ..errors import InputError

    try:
        return cache_dir()
    except InputError:
        return None


def _write(path, meshes: list[MeshArrays]) -> None:
    arrays = {}
    for i, m in enumerate(meshes):
        arrays[f"v{i}"], arrays[f"f{i}"] = m.vertices, m.faces
    tmp = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.stem}-", suffix=".npz", dir=path.parent)
        with os.fdopen(fd, "wb") as fh:
            np.savez(fh, **arrays)
        os.replace(tmp, path)
    except OSError:  # a read-only or full cache: the next solve extrudes again
        if tmp is not None:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
def _convex_corner(fp: np.ndarray, i: int) -> bool:
    """Whether vertex ``i`` of a counter-clockwise polygon is convex."""
    p, c, n = fp[i - 1], fp[i], fp[(i + 1) % len(fp)]
    d1, d2 = c - p, n - c
    return float(d1[0] * d2[1] - d1[1] * d2[0]) > 0


#: Shells built in this process, by footprint, height and wall thickness (a dataset worker or
#: a long-lived solver builds the same few rooms again and again); handed out as copies.
_BUILT: dict[tuple, RoomShell] = {}
_BUILT_MAX = 256


def build_shell(room: Room, *, wall_thickness: float = DEFAULT_WALL_THICKNESS) -> RoomShell:
    """Floor, walls and ceiling of ``room`` as static world-frame slabs with inward surfaces.

    Walls stand outside the footprint (their inner face lies exactly on the footprint edge) and
    run from the floor to the ceiling; wall ``i`` runs from vertex ``i`` to vertex ``i+1``.
    Each call returns a shell of its own (arrays copied from the one built for the same room
    earlier in this process, when there is one).
    """
    fp = np.asarray(room.footprint, float)
    key = (fp.shape, fp.tobytes(), float(room.height), float(wall_thickness))
    shell = _BUILT.get(key)
    if shell is None:
        shell = _build_shell(fp, float(room.height), float(wall_thickness))
        if len(_BUILT) >= _BUILT_MAX:
            _BUILT.clear()
        _BUILT[key] = shell
    return _copy_shell(shell)


def _copy_shell(shell: RoomShell) -> RoomShell:
    """A shell sharing no array with ``shell`` (polygons are immutable and shared)."""
    elements = {}
    for name, el in shell.elements.items():
        m, s = el.mesh_arrays, el.surface
        elements[name] = ShellElement(
            name, MeshArrays(m.vertices.copy(), m.faces.copy()),
            Surface(s.label, s.origin.copy(), s.normal.copy(), s.u.copy(), s.v.copy(), s.polygon,
                    s.source))
    return RoomShell(shell.footprint.copy(), shell.height, shell.wall_thickness, elements)


def _build_shell(fp: np.ndarray, height: float, wall_thickness: float) -> RoomShell:
    """:func:`build_shell` of a footprint (K, 2) and a height, built now."""
    if Polygon(fp).exterior.is_ccw is False:
        fp = fp[::-1]
    h = height
    poly = Polygon(fp)
    elements: dict[str, ShellElement] = {}
    c = np.asarray(poly.centroid.coords[0])
    outer = poly.buffer(wall_thickness, join_style="mitre")

    ring = np.asarray(outer.exterior.coords)[:-1]
    quads = []
    for i in range(len(fp)):
        a, b = fp[i], fp[(i + 1) % len(fp)]
        t = (b - a) / float(np.linalg.norm(b - a))
        inward = np.array([-t[1], t[0]])  # left of a->b is inside for a CCW polygon
        # slabs overlap at convex corners; at a reflex corner (an L-shaped room's inner corner)
        # an extended slab would poke into the room, so it stops at the corner there
        ea = wall_thickness if _convex_corner(fp, i) else 0.0
        eb = wall_thickness if _convex_corner(fp, (i + 1) % len(fp)) else 0.0
        quads.append(np.array([a - t * ea, b + t * eb,
                               b + t * eb - inward * wall_thickness,
                               a - t * ea - inward * wall_thickness]))
    floor_mesh, *wall_meshes, ceil_mesh = _slab_meshes(
        [(ring, -_SLAB, 0.0)] + [(q, -_SLAB, h + _SLAB) for q in quads] + [(ring, h, h + _SLAB)])
    floor_poly = Polygon(fp - c)
    elements["floor"] = ShellElement(
        "floor", floor_mesh,
        Surface("top", np.array([c[0], c[1], 0.0]), np.array([0, 0, 1.0]),
                np.array([1.0, 0, 0]), np.array([0, 1.0, 0]), floor_poly, "mesh"))
    for i in range(len(fp)):
        a, b = fp[i], fp[(i + 1) % len(fp)]
        d = b - a
        length = float(np.linalg.norm(d))
        t = d / length
        inward = np.array([-t[1], t[0]])
        mesh = wall_meshes[i]
        mid = (a + b) / 2
        n = np.array([inward[0], inward[1], 0.0])
        u = np.array([t[0], t[1], 0.0])
        v = np.array([0, 0, 1.0])
        if np.dot(np.cross(u, v), n) < 0:
            u = -u
        surf = Surface("front", np.array([mid[0], mid[1], h / 2]), n, u, v,
                       Polygon([(-length / 2, -h / 2), (length / 2, -h / 2),
                                (length / 2, h / 2), (-length / 2, h / 2)]), "mesh")
        elements[f"wall_{i}"] = ShellElement(f"wall_{i}", mesh, surf)
    elements["ceiling"] = ShellElement(
        "ceiling", ceil_mesh,
        Surface("bottom", np.array([c[0], c[1], h]), np.array([0, 0, -1.0]),
                np.array([1.0, 0, 0]), np.array([0, -1.0, 0]),
                Polygon(np.c_[fp[:, 0] - c[0], -(fp[:, 1] - c[1])]), "mesh"))
    return RoomShell(fp, h, wall_thickness, elements)
