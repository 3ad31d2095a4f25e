"""Collision data shared by settling, contact extraction and the MuJoCo check.

Every part of an asset carries convex pieces (procedural shapes build them; loaded meshes get
them from CoACD in :mod:`parse3d.assets.collision`). This module turns them into packed,
engine-neutral arrays once per asset — hull vertices, triangles and face planes in the asset
frame — and places them in the world for a scene:

- :func:`asset_collision` — the per-asset data, cached within the process by asset id;
- :func:`shell_collision` — the room shell (floor, walls, ceiling) as static convex pieces;
  a slab over a non-convex footprint is split into convex prisms (one per triangle of the
  footprint's triangulation);
- :func:`scene_bodies` — one :class:`WorldBody` per placed object (plus ``room``) with its
  pieces moved to the world by the object's pose and uniform scale.

A piece is a convex polytope ``{x : n_k . x <= d_k for every face k}``.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import weakref
import zipfile
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Polygon

from .._lru import LRU
from ..assets.model import Asset
from ..scene.model import RoomShell, Scene

__all__ = [
    "ROOM",
    "ConvexSet",
    "AssetCollision",
    "WorldBody",
    "asset_collision",
    "shell_collision",
    "scene_bodies",
    "concatenate",
    "clear_cache",
    "fcl_convex",
    "fcl_piece",
]

#: Body id of the room shell in contact keys (``room:floor``, ``room:wall_0``).
ROOM = "room"

_PAD_OFFSET = 1e9  # padding plane n=0, d=1e9: its value n.x - d never wins a max


@dataclass(frozen=True)
class ConvexSet:
    """Packed convex pieces in one frame.

    Attributes
    ----------
    parts : tuple of str
        Part name of every piece (``leg_0``; ``floor``, ``wall_2`` for the shell).
    vertices : (V, 3) float
        Hull vertices of all pieces, concatenated, metres.
    vert_index : (P + 1,) int
        Piece ``i`` owns ``vertices[vert_index[i]:vert_index[i + 1]]``.
    triangles : (T, 3, 3) float
        Hull triangles of all pieces, concatenated.
    tri_index : (P + 1,) int
        Piece ``i`` owns ``triangles[tri_index[i]:tri_index[i + 1]]``.
    planes : (P, F, 4) float
        Face planes ``(n, d)`` per piece with ``n . x <= d`` inside (unit outward normals);
        padded with ``(0, 0, 0, 1e9)``.
    areas : (P,) float
        Surface area per piece, m^2.
    volumes : (P,) float
        Volume per piece, m^3.
    bounds : (P, 2, 3) float
        Axis-aligned bounds per piece.
    """

    parts: tuple[str, ...]
    vertices: np.ndarray
    vert_index: np.ndarray
    triangles: np.ndarray
    tri_index: np.ndarray
    planes: np.ndarray
    areas: np.ndarray
    volumes: np.ndarray
    bounds: np.ndarray

    def __len__(self) -> int:
        return len(self.parts)

    def piece_vertices(self, i: int) -> np.ndarray:
        """(V_i, 3) hull vertices of piece ``i``."""
        return self.vertices[self.vert_index[i]:self.vert_index[i + 1]]

    def transformed(self, R: np.ndarray, t: np.ndarray, scale: float = 1.0) -> ConvexSet:
        """The same pieces under ``x -> R @ (scale * x) + t`` (R a rotation, scale > 0)."""
        R = np.asarray(R, float)
        t = np.asarray(t, float)
        A = R * float(scale)
        verts = self.vertices @ A.T + t
        tris = self.triangles @ A.T + t
        n = self.planes[..., :3] @ R.T
        d = self.planes[..., 3] * scale + n @ t
        d = np.where(self.planes[..., 3] >= _PAD_OFFSET, _PAD_OFFSET, d)
        planes = np.concatenate([n, d[..., None]], axis=-1)
        lo = np.minimum.reduceat(verts, self.vert_index[:-1], axis=0)
        hi = np.maximum.reduceat(verts, self.vert_index[:-1], axis=0)
        return ConvexSet(self.parts, verts, self.vert_index, tris, self.tri_index, planes,
                         self.areas * scale**2, self.volumes * scale**3, np.stack([lo, hi], 1))


@dataclass(frozen=True)
class AssetCollision:
    """Collision data of one asset, in its canonical frame (unscaled).

    Attributes
    ----------
    asset_id : str
    pieces : ConvexSet
    density : float
        kg / m^3.
    materials : tuple of str
        Material family of every piece (its part's ``Material.name``).
    """

    asset_id: str
    pieces: ConvexSet
    density: float
    materials: tuple[str, ...]

    @property
    def volume(self) -> float:
        return float(self.pieces.volumes.sum())

    @property
    def mass(self) -> float:
        return self.volume * self.density


@dataclass(frozen=True)
class WorldBody:
    """One body of a scene in the world frame.

    Attributes
    ----------
    id : str
        Object id, or ``room`` for the shell.
    pieces : ConvexSet
        World-frame pieces.
    bounds : (2, 3) float
        World AABB of all pieces.
    static : bool
        True for the room shell.
    """

    id: str
    pieces: ConvexSet
    bounds: np.ndarray
    static: bool = False


@dataclass(frozen=True)
class _Hull:
    vertices: np.ndarray  # (V, 3)
    triangles: np.ndarray  # (T, 3, 3), outward winding
    planes: np.ndarray  # (F, 4) unique face planes
    area: float
    volume: float


def _pack(parts: list[str], hulls: list[_Hull]) -> ConvexSet:
    fmax = max(len(h.planes) for h in hulls)
    planes = np.zeros((len(hulls), fmax, 4))
    planes[..., 3] = _PAD_OFFSET
    for i, h in enumerate(hulls):
        planes[i, : len(h.planes)] = h.planes
    verts = [h.vertices for h in hulls]
    index = np.concatenate([[0], np.cumsum([len(v) for v in verts])]).astype(int)
    tri_index = np.concatenate([[0], np.cumsum([len(h.triangles) for h in hulls])]).astype(int)
    bounds = np.stack([np.array([v.min(0) for v in verts]), np.array([v.max(0) for v in verts])], 1)
    return ConvexSet(tuple(parts), np.concatenate(verts), index,
                     np.concatenate([h.triangles for h in hulls]), tri_index, planes,
                     np.array([h.area for h in hulls]), np.array([h.volume for h in hulls]),
                     bounds)


def concatenate(sets: list[ConvexSet]) -> ConvexSet:
    """All pieces of several sets as one set (same frame assumed), in order."""
    fmax = max(cs.planes.shape[1] for cs in sets)
    # one padded array filled in place: one piece with many faces pads every other piece to
    # its count, and padding each set then concatenating copied all of that twice
    planes = np.zeros((sum(len(cs) for cs in sets), fmax, 4))
    planes[..., 3] = _PAD_OFFSET
    k = 0
    for cs in sets:
        n, f = cs.planes.shape[:2]
        planes[k:k + n, :f] = cs.planes
        k += n

    def offsets(idx: list[np.ndarray]) -> np.ndarray:
        sizes = np.concatenate([np.diff(i) for i in idx])
        return np.concatenate([[0], np.cumsum(sizes)]).astype(int)

    return ConvexSet(
        tuple(p for cs in sets for p in cs.parts),
        np.concatenate([cs.vertices for cs in sets]),
        offsets([cs.vert_index for cs in sets]),
        np.concatenate([cs.triangles for cs in sets]),
        offsets([cs.tri_index for cs in sets]),
        planes,
        np.concatenate([cs.areas for cs in sets]),
        np.concatenate([cs.volumes for cs in sets]),
        np.concatenate([cs.bounds for cs in sets]),
    )


def _hull(points: np.ndarray) -> _Hull | None:
    """Convex hull of a piece's vertices; None for a degenerate (flat or empty) piece."""
    from scipy.spatial import ConvexHull, QhullError

    pts = np.asarray(points, float)
    if len(pts) < 4:
        return None
    try:
        h = ConvexHull(pts)
    except QhullError:  # flat point sets have no volume to collide
        return None
    if h.volume <= 1e-12:
        return None
    used = np.unique(h.simplices)
    tris = pts[h.simplices]
    n = h.equations[:, :3]
    # qhull's simplices are not consistently wound: orient every triangle outward
    flip = np.einsum("ij,ij->i", np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0]), n) < 0
    tris[flip] = tris[flip][:, ::-1]
    planes = np.c_[n, -h.equations[:, 3]]
    # coplanar triangles share a plane; keeping one keeps the plane arrays short
    _, keep = np.unique(np.round(planes, 9), axis=0, return_index=True)
    return _Hull(pts[used], tris, planes[np.sort(keep)], float(h.area), float(h.volume))


#: Version of the on-disk collision data; part of every key (bump when ``_hull`` changes).
DISK_FORMAT = "parse3d-collision/1"


def _fingerprint(asset: Asset) -> str:
    h = hashlib.blake2b(digest_size=12)
    h.update(DISK_FORMAT.encode())
    h.update(asset.asset_id.encode())
    h.update(np.float64(asset.density).tobytes())
    for p in asset.parts:
        h.update(p.name.encode())
        h.update(p.material.name.encode())
        for pc in p.piece_arrays:  # the arrays as held: no trimesh object is made
            h.update(np.ascontiguousarray(pc.vertices, np.float64).tobytes())
    return h.hexdigest()


#: ``id(asset)`` -> (weak reference to it, its fingerprint), for assets alive in this process.
_KEYS: dict[int, tuple[weakref.ref, str]] = {}


def _asset_key(asset: Asset) -> str:
    """The fingerprint of ``asset``, hashed once per asset object.

    Settling, contact extraction and every repair round ask for the same assets again and
    again; hashing every piece's vertices each time cost as much as the rest of the lookup.
    An asset's parts and pieces do not change once it is made (scaling is the object's, not
    the asset's), so the object's first fingerprint stays its fingerprint.
    """
    i = id(asset)
    hit = _KEYS.get(i)
    if hit is not None and hit[0]() is asset:
        return hit[1]

    def forget(ref, i=i):
        if _KEYS.get(i, (None,))[0] is ref:
            del _KEYS[i]

    key = _fingerprint(asset)
    _KEYS[i] = (weakref.ref(asset, forget), key)
    return key


_CACHE_SIZE = 4096
_CACHE: LRU[str, AssetCollision] = LRU(_CACHE_SIZE)


def clear_cache() -> None:
    """Forget the collision data cached for assets in this process (the disk copy stays)."""
    _CACHE.clear()
    _SHELL_CACHE.clear()
    _KEYS.clear()
    _FCL_PIECES.clear()


def _disk_dir():
    """``$PARSE3D_CACHE/collision``, or None when the cache setting is unusable."""
    from ..assets.library import cache_dir
    from ..errors import InputError

    try:
        return cache_dir() / "collision"
    except InputError:
        return None


def _disk_read(key: str, asset_id: str) -> AssetCollision | None:
    d = _disk_dir()
    if d is None:
        return None
    from ..assets.cache import _read_npz  # the asset files' reader: one read, CRC-checked

    path = d / f"{key}.npz"
    try:
        z = _read_npz(path)
        meta = json.loads(bytes(z["meta"]).decode())
        if meta.get("format") != DISK_FORMAT or meta.get("asset_id") != asset_id:
            return None
        cs = ConvexSet(tuple(meta["parts"]), z["vertices"], z["vert_index"], z["triangles"],
                       z["tri_index"], z["planes"], z["areas"], z["volumes"], z["bounds"])
        return AssetCollision(asset_id, cs, float(meta["density"]), tuple(meta["materials"]))
    except (OSError, ValueError, KeyError, TypeError, EOFError, zipfile.BadZipFile):
        return None  # absent or damaged: computed again


def _disk_write(key: str, data: AssetCollision) -> None:
    d = _disk_dir()
    if d is None:
        return
    cs = data.pieces
    meta = {"format": DISK_FORMAT, "asset_id": data.asset_id, "density": data.density,
            "parts": list(cs.parts), "materials": list(data.materials)}
    tmp = d / f".{key}.{os.getpid()}.tmp.npz"
    try:
        d.mkdir(parents=True, exist_ok=True)
        np.savez(tmp, meta=np.frombuffer(json.dumps(meta).encode(), np.uint8),
                 vertices=cs.vertices, vert_index=cs.vert_index, triangles=cs.triangles,
                 tri_index=cs.tri_index, planes=cs.planes, areas=cs.areas, volumes=cs.volumes,
                 bounds=cs.bounds)
        os.replace(tmp, d / f"{key}.npz")
    except OSError:  # a read-only or full cache only costs the hulls again
        with contextlib.suppress(OSError):
            tmp.unlink()


def asset_collision(asset: Asset) -> AssetCollision:
    """The collision data of ``asset`` (computed once per asset content).

    Parts without pieces contribute nothing; degenerate (zero-volume) pieces are dropped.
    The result is kept in this process and on disk (``$PARSE3D_CACHE/collision``, keyed by
    the asset's content), so fresh dataset workers do not compute the hulls again.

    Raises
    ------
    ValueError
        When the asset has no usable convex piece at all.
    """
    key = _asset_key(asset)
    hit = _CACHE.get(key)
    if hit is not None:
        return hit
    data = _disk_read(key, asset.asset_id)
    if data is None:
        parts, hulls, mats = [], [], []
        for p in asset.parts:
            for pc in p.piece_arrays:
                h = _hull(np.asarray(pc.vertices))
                if h is not None:
                    parts.append(p.name)
                    hulls.append(h)
                    mats.append(p.material.name)
        if not hulls:
            raise ValueError(f"asset {asset.asset_id} has no convex collision pieces")
        data = AssetCollision(asset.asset_id, _pack(parts, hulls), float(asset.density),
                              tuple(mats))
        _disk_write(key, data)
    _CACHE[key] = data
    return data


def fcl_convex(points: np.ndarray):
    """An ``fcl.Convex`` of a convex point set ((N, 3) float): its hull's vertices and
    triangles, the vertices shared (FCL walks the hull's edge graph to find support points)."""
    import fcl
    from scipy.spatial import ConvexHull

    h = ConvexHull(points)
    used = np.unique(h.simplices)
    remap = np.full(len(points), -1)
    remap[used] = np.arange(len(used))
    tri = remap[h.simplices]
    return fcl.Convex(np.ascontiguousarray(points[used], np.float64), len(tri),
                      np.c_[np.full(len(tri), 3), tri].ravel())


#: ``fcl.Convex`` per (asset content key, uniform scale, piece index), asset frame, scaled.
_FCL_CACHE_SIZE = 8192
_FCL_PIECES: LRU[tuple[str, float, int], object] = LRU(_FCL_CACHE_SIZE)


def fcl_piece(key: str, scale: float, index: int, pieces: ConvexSet):
    """The ``fcl.Convex`` of piece ``index`` of an asset's ``pieces`` scaled by ``scale``,
    made once per (asset content ``key``, scale, piece) in this process (FCL moves shapes
    rigidly only, so the scale is baked in)."""
    k = (key, float(scale), int(index))
    g = _FCL_PIECES.get(k)
    if g is None:
        g = _FCL_PIECES[k] = fcl_convex(np.asarray(pieces.piece_vertices(index), float) * scale)
    return g


def _convex_prisms(poly: np.ndarray, z0: float, z1: float) -> list[np.ndarray]:
    """Vertex sets of convex prisms covering the extrusion of a simple polygon."""
    shp = Polygon(poly)
    if shp.convex_hull.area - shp.area <= 1e-9 * max(shp.area, 1.0):
        rings = [np.asarray(shp.exterior.coords)[:-1]]
    else:
        import trimesh

        v, f = trimesh.creation.triangulate_polygon(shp, engine="earcut")
        rings = [v[tri] for tri in f]
    out = []
    for r in rings:
        out.append(np.vstack([np.c_[r, np.full(len(r), z0)], np.c_[r, np.full(len(r), z1)]]))
    return out


_SHELL_CACHE: LRU[bytes, ConvexSet] = LRU(64)


def shell_collision(room: RoomShell) -> ConvexSet:
    """The room shell as static convex pieces, world frame (cached per shell geometry).

    Walls are convex slabs already; the floor and ceiling slabs are split into convex prisms
    when the footprint is not convex.
    """
    key = b"".join([np.ascontiguousarray(room.footprint, np.float64).tobytes(),
                    np.float64([room.height, room.wall_thickness]).tobytes()]
                   + [n.encode() + np.ascontiguousarray(e.mesh_arrays.bounds, np.float64).tobytes()
                      for n, e in room.elements.items()])
    hit = _SHELL_CACHE.get(key)
    if hit is None:
        hit = _SHELL_CACHE[key] = _shell_pieces(room)
    return hit


def _shell_pieces(room: RoomShell) -> ConvexSet:
    parts, hulls = [], []
    for name, el in room.elements.items():
        m = el.mesh_arrays
        if name in ("floor", "ceiling"):
            z0, z1 = float(m.bounds[0, 2]), float(m.bounds[1, 2])
            # the slab's outline: the footprint grown by the wall thickness
            outline = Polygon(room.footprint).buffer(room.wall_thickness, join_style="mitre")
            pieces = _convex_prisms(np.asarray(outline.exterior.coords)[:-1], z0, z1)
        else:
            pieces = [np.asarray(m.vertices)]
        for pts in pieces:
            h = _hull(pts)
            if h is not None:
                parts.append(name)
                hulls.append(h)
    return _pack(parts, hulls)


def scene_bodies(scene: Scene, *, settled: bool | None = None,
                 include_room: bool = True,
                 only: set[str] | frozenset[str] | None = None) -> list[WorldBody]:
    """World-frame collision bodies of every placed object (and the room shell).

    Parameters
    ----------
    scene : Scene
    settled : bool or None
        Pose to use: None takes the settled pose where there is one.
    include_room : bool
        Append the shell as the static body ``room``.
    only : set of str, optional
        Only these object ids (``room`` for the shell, still subject to ``include_room``);
        the scene's order is kept.

    Returns
    -------
    list of WorldBody
        Objects in the scene's order, then ``room``.
    """
    out = []
    for obj in scene.placed:
        if obj.asset is None or (only is not None and obj.id not in only):
            continue
        data = asset_collision(obj.asset)
        T = obj.transform(settled)
        R = T[:3, :3] / obj.scale
        ws = data.pieces.transformed(R, T[:3, 3], obj.scale)
        out.append(WorldBody(obj.id, ws, np.array([ws.bounds[:, 0].min(0), ws.bounds[:, 1].max(0)])))
    if include_room and (only is None or ROOM in only):
        sh = shell_collision(scene.room)
        out.append(WorldBody(ROOM, sh, np.array([sh.bounds[:, 0].min(0), sh.bounds[:, 1].max(0)]),
                             static=True))
    return out
