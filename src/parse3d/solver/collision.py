"""Mesh-level collision checking with FCL: persistent BVHs moved by ``set_transform``."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from typing import TYPE_CHECKING

import fcl
import numpy as np

if TYPE_CHECKING:
    import trimesh

    from ..geometry.meshes import MeshArrays

__all__ = ["CollisionWorld", "Body", "bvh_from_mesh", "cached_body", "static_body"]


def bvh_from_mesh(mesh: MeshArrays | trimesh.Trimesh) -> fcl.BVHModel:
    m = fcl.BVHModel()
    m.beginModel(len(mesh.vertices), len(mesh.faces))
    m.addSubModel(np.asarray(mesh.vertices, dtype=np.float64), np.asarray(mesh.faces, dtype=np.int32))
    m.endModel()
    return m


@dataclass
class Body:
    """An FCL collision object and the geometry it wraps (contacts name the geometry)."""

    obj: fcl.CollisionObject
    geom: fcl.BVHModel

    @classmethod
    def from_mesh(cls, mesh: MeshArrays | trimesh.Trimesh) -> Body:
        g = bvh_from_mesh(mesh)
        return cls(fcl.CollisionObject(g, fcl.Transform()), g)

    def move(self, R: np.ndarray, t: np.ndarray) -> None:
        self.obj.setTransform(fcl.Transform(np.asarray(R, float), np.asarray(t, float)))


_BVH_CACHE: dict[tuple[str, float], fcl.BVHModel] = {}


def cached_body(key: str, scale: float, mesh_fn) -> Body:
    """A Body for an asset at a scale, sharing one BVH per (asset, scale) in this process."""
    k = (key, round(float(scale), 9))
    g = _BVH_CACHE.get(k)
    if g is None:
        if len(_BVH_CACHE) > 2048:
            _BVH_CACHE.clear()
        g = bvh_from_mesh(mesh_fn())
        _BVH_CACHE[k] = g
    return Body(fcl.CollisionObject(g, fcl.Transform()), g)


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
    return Body(fcl.CollisionObject(g, fcl.Transform()), g)


class CollisionWorld:
    """Static world of placed objects in an FCL broadphase manager.

    Each placed object is registered once (its scaled mesh as a BVH, in its asset frame) with
    its pose; a candidate is tested by moving its own persistent body.
    """

    def __init__(self):
        self.manager = fcl.DynamicAABBTreeCollisionManager()
        self._names: dict[int, list[str]] = {}
        self._bodies: dict[str, Body] = {}
        self._dirty = False

    def add(self, name: str, body: Body) -> None:
        self._names.setdefault(id(body.geom), []).append(name)
        self._bodies[name] = body
        self.manager.registerObject(body.obj)
        self._dirty = True

    def remove(self, name: str) -> None:
        """Unregister the object added as ``name`` (a no-op when there is none)."""
        body = self._bodies.pop(name, None)
        if body is None:
            return
        self.manager.unregisterObject(body.obj)
        names = self._names.get(id(body.geom), [])
        if name in names:
            names.remove(name)
        self._dirty = True

    def collides(self, body: Body, ignore: frozenset[str] = frozenset()) -> str | None:
        """Name of a registered object that ``body`` collides with (None when free)."""
        if self._dirty:
            self.manager.setup()
            self._dirty = False
        req = fcl.CollisionRequest(num_max_contacts=16, enable_contact=True)
        data = fcl.CollisionData(request=req)
        self.manager.collide(body.obj, data, fcl.defaultCollisionCallback)
        shared = False
        for c in data.result.contacts:
            if c.o1 is body.geom and c.o2 is body.geom:
                shared = True  # a placed object built from the same BVH (same asset and scale)
            for g in (c.o1, c.o2):
                if g is body.geom:
                    continue
                for name in self._names.get(id(g), ()):
                    if name not in ignore:
                        return name
        if shared:
            for name in self._names.get(id(body.geom), ()):
                other = self._bodies.get(name)
                if name in ignore or other is None or other is body:
                    continue
                if fcl.collide(body.obj, other.obj, fcl.CollisionRequest(), fcl.CollisionResult()):
                    return name
        return None
