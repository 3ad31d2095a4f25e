"""Mesh-level collision checking with FCL: persistent BVHs, built when first needed.

A candidate is tested against the placed objects whose boxes overlap its box (each body's
box in its own frame, carried to the world by its pose: a conservative bound of its mesh).
Only those pairs go to FCL, and a body's BVH is built the first time one of its pairs does:
an object whose box never meets another's (a mug alone on a table) never builds one. Boxes
that do not overlap hold meshes that cannot touch, so the answer is FCL's on every pair.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING

import fcl
import numpy as np

if TYPE_CHECKING:
    import trimesh

    from ..assets.model import Asset
    from ..geometry.meshes import MeshArrays

__all__ = ["CollisionWorld", "Body", "bvh_from_mesh", "cached_body", "static_body"]

#: Padding of every box (m): rounding in scaling and posing cannot hide a touching pair.
BOX_PAD = 1e-6


def bvh_from_mesh(mesh: MeshArrays | trimesh.Trimesh) -> fcl.BVHModel:
    m = fcl.BVHModel()
    m.beginModel(len(mesh.vertices), len(mesh.faces))
    m.addSubModel(np.asarray(mesh.vertices, dtype=np.float64), np.asarray(mesh.faces, dtype=np.int32))
    m.endModel()
    return m


def _box(vertices) -> np.ndarray:
    v = np.asarray(vertices, float).reshape(-1, 3)
    if not len(v):
        return np.zeros((2, 3))
    return np.array([v.min(axis=0), v.max(axis=0)])


class Body:
    """A collision body: a mesh's BVH (made by ``make`` on first need, see :attr:`geom`), its
    box in its own frame (``local``, (2, 3)) and its pose (set by :meth:`move`)."""

    __slots__ = ("_make", "_geom", "_obj", "_R", "_t", "local", "_mid", "_half")

    def __init__(self, make: Callable[[], fcl.BVHModel], local: np.ndarray,
                 geom: fcl.BVHModel | None = None):
        self._make = make
        self._geom = geom
        self._obj: fcl.CollisionObject | None = None
        self._R = np.eye(3)
        self._t = np.zeros(3)
        self.local = np.asarray(local, float)
        self._mid = (self.local[0] + self.local[1]) / 2
        self._half = (self.local[1] - self.local[0]) / 2

    @classmethod
    def from_mesh(cls, mesh: MeshArrays | trimesh.Trimesh) -> Body:
        g = bvh_from_mesh(mesh)
        return cls(lambda: g, _box(mesh.vertices), g)

    @property
    def geom(self) -> fcl.BVHModel:
        """The BVH (built now if it was not)."""
        if self._geom is None:
            self._geom = self._make()
        return self._geom

    @property
    def obj(self) -> fcl.CollisionObject:
        """The FCL collision object at the body's pose (made now if it was not)."""
        if self._obj is None:
            self._obj = fcl.CollisionObject(self.geom, fcl.Transform(self._R, self._t))
        return self._obj

    def move(self, R: np.ndarray, t: np.ndarray) -> None:
        self._R, self._t = np.asarray(R, float), np.asarray(t, float)
        if self._obj is not None:
            self._obj.setTransform(fcl.Transform(self._R, self._t))

    def world_box(self) -> np.ndarray:
        """(6,) lower and upper corner of a world box holding the body at its pose."""
        c = self._R @ self._mid + self._t
        e = np.abs(self._R) @ self._half + BOX_PAD
        return np.concatenate([c - e, c + e])


_BVH_CACHE: dict[tuple[str, float], fcl.BVHModel] = {}
_BOXES: dict[str, np.ndarray] = {}


def _local_box(asset: Asset) -> np.ndarray:
    b = _BOXES.get(asset.asset_id)
    if b is None:
        if len(_BOXES) > 4096:
            _BOXES.clear()
        b = _BOXES[asset.asset_id] = np.asarray(asset.bounds, float)
    return b


def cached_body(asset: Asset, scale: float, mesh_fn) -> Body:
    """A Body for an asset at a scale, sharing one BVH per (asset, scale) in this process;
    the BVH is built from ``mesh_fn()`` the first time a body of that pair needs one."""
    k = (asset.asset_id, round(float(scale), 9))

    def make() -> fcl.BVHModel:
        g = _BVH_CACHE.get(k)
        if g is None:
            if len(_BVH_CACHE) > 2048:
                _BVH_CACHE.clear()
            g = _BVH_CACHE[k] = bvh_from_mesh(mesh_fn())
        return g

    box = _local_box(asset) * float(scale)
    return Body(make, box if scale >= 0 else box[::-1], _BVH_CACHE.get(k))


_STATIC_BVH: dict[bytes, fcl.BVHModel] = {}


def static_body(mesh: MeshArrays) -> Body:
    """A Body for a world-frame mesh (a room slab), sharing one BVH per distinct mesh (by its
    arrays' bytes) in this process: every scene of a room builds the same slabs."""
    v = np.ascontiguousarray(mesh.vertices, dtype=np.float64)
    f = np.ascontiguousarray(mesh.faces, dtype=np.int32)
    h = hashlib.blake2b(digest_size=16)
    h.update(np.int64(v.shape + f.shape).tobytes())
    h.update(v.tobytes())
    h.update(f.tobytes())
    k = h.digest()
    g = _STATIC_BVH.get(k)
    if g is None:
        if len(_STATIC_BVH) > 2048:
            _STATIC_BVH.clear()
        g = _STATIC_BVH[k] = bvh_from_mesh(mesh)
    return Body(lambda: g, _box(v), g)


class CollisionWorld:
    """Static world of placed objects: each registered once with its pose (its box kept in
    one array), a candidate tested by moving its own persistent body."""

    def __init__(self):
        self._names: list[str] = []
        self._bodies: list[Body] = []
        self._rows: list[np.ndarray] = []
        self._table: np.ndarray | None = None

    def add(self, name: str, body: Body) -> None:
        self._names.append(name)
        self._bodies.append(body)
        self._rows.append(body.world_box())
        self._table = None

    def remove(self, name: str) -> None:
        """Unregister the object added as ``name`` (a no-op when there is none)."""
        if name in self._names:
            k = self._names.index(name)
            del self._names[k], self._bodies[k], self._rows[k]
            self._table = None

    @contextmanager
    def hidden(self, names: Iterable[str]) -> Iterator[None]:
        """The objects registered as ``names`` left out of every test inside the block, then
        registered again where they were."""
        saved = (list(self._names), list(self._bodies), list(self._rows))
        for n in set(names):
            self.remove(n)
        try:
            yield
        finally:
            self._names, self._bodies, self._rows = saved
            self._table = None

    def collides(self, body: Body, ignore: frozenset[str] = frozenset()) -> str | None:
        """Name of a registered object that ``body`` collides with (None when free): the
        first, in the order they were added, that FCL finds touching it."""
        if not self._names:
            return None
        if self._table is None:
            self._table = np.array(self._rows, float).reshape(-1, 6)
        T, b = self._table, body.world_box()
        near = np.flatnonzero(((T[:, :3] <= b[3:]) & (T[:, 3:] >= b[:3])).all(axis=1))
        for k in near.tolist():
            name, other = self._names[k], self._bodies[k]
            if other is body or name in ignore:
                continue
            if fcl.collide(body.obj, other.obj, fcl.CollisionRequest(), fcl.CollisionResult()):
                return name
        return None
