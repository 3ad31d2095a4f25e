"""What the solver knows while it places objects: the scene so far, its collision world and
the world-frame geometry of every placed object (indexed once, when the object is placed)."""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field

import numpy as np

from ..assets.model import Asset, Part
from ..geometry import regions as RG
from ..geometry.memo import per_object
from ..geometry.surfaces import Surface
from ..measure.checks import world_points
from ..pag.model import PAG
from ..pag.refs import Ref
from ..scene.model import PlacedObject, Scene
from .collision import Body, CollisionWorld
from .geometry import outline_indices

__all__ = ["SolveState"]


@dataclass
class SolveState:
    """The partial scene and the geometry index of its placed objects.

    Attributes
    ----------
    pag, scene : the graph and the scene being filled
    world : CollisionWorld
        The room shell and every placed object.
    hulls : dict of str to (N, 3) float
        World convex-hull points per placed object.
    xy : dict of str to (M, 2) float
        World convex footprint per placed object.
    zr : dict of str to (float, float)
        World z range per placed object.
    pieces : dict
        World convex pieces per placed object, built on first use.

    The placed objects are also indexed as arrays (in the order of ``hulls``) for queries
    that would otherwise loop over every placed object: see :meth:`near`.
    """

    pag: PAG
    scene: Scene
    world: CollisionWorld
    hulls: dict[str, np.ndarray] = field(default_factory=dict)
    xy: dict[str, np.ndarray] = field(default_factory=dict)
    zr: dict[str, tuple[float, float]] = field(default_factory=dict)
    pieces: dict[str, list] = field(default_factory=dict)
    _ids: list[str] = field(default_factory=list, repr=False)
    _rows: list[tuple[float, ...]] = field(default_factory=list, repr=False)
    _table: np.ndarray | None = field(default=None, repr=False)
    _memo: dict[str, dict] = field(default_factory=dict, repr=False)

    def add(self, obj: PlacedObject, body: Body) -> None:
        """Register a placed object (its pose is final until :meth:`remove`)."""
        self.scene.objects[obj.id] = obj
        self._memo.pop(obj.id, None)
        self.hulls[obj.id] = world_points(obj, hull_only=True)
        self.xy[obj.id] = RG.convex_outline(self.hulls[obj.id][:, :2],
                                            outline_indices(obj.asset, obj.rotation[2]))
        self.zr[obj.id] = (float(self.hulls[obj.id][:, 2].min()),
                           float(self.hulls[obj.id][:, 2].max()))
        lo, hi = self.xy[obj.id].min(axis=0), self.xy[obj.id].max(axis=0)
        c, r = (lo + hi) / 2, float(np.linalg.norm(hi - lo)) / 2
        row = (float(c[0]), float(c[1]), r, *self.zr[obj.id])
        if obj.id in self._ids:  # re-registered: it keeps its place, as in the dicts
            self._rows[self._ids.index(obj.id)] = row
        else:
            self._ids.append(obj.id)
            self._rows.append(row)
        self._table = None
        body.move(obj.rotation, obj.position)
        self.world.add(obj.id, body)

    def remove(self, oid: str) -> None:
        """Take a placed object out of the collision world and the geometry index."""
        for d in (self.hulls, self.xy, self.zr, self.pieces, self._memo):
            d.pop(oid, None)
        if oid in self._ids:
            k = self._ids.index(oid)
            del self._ids[k], self._rows[k]
            self._table = None
        self.world.remove(oid)

    @contextmanager
    def hidden(self, ids: Iterable[str]) -> Iterator[None]:
        """Placed objects ``ids`` left out of the collision world and the geometry index
        inside the block (they stay in the scene), then back as they were: what a child may
        overlap (a coat hung over another on one coat tree, see :func:`.hanging.hung_over`)."""
        ids = [i for i in ids if i in self.hulls]
        if not ids:
            yield
            return
        saved = [dict(d) for d in (self.hulls, self.xy, self.zr, self.pieces)]
        rows = (list(self._ids), list(self._rows))
        for d in (self.hulls, self.xy, self.zr, self.pieces):
            for i in ids:
                d.pop(i, None)
        keep = [k for k, i in enumerate(self._ids) if i not in ids]
        self._ids = [self._ids[k] for k in keep]
        self._rows = [self._rows[k] for k in keep]
        self._table = None
        try:
            with self.world.hidden(ids):
                yield
        finally:
            self.hulls, self.xy, self.zr, self.pieces = saved
            self._ids, self._rows = rows
            self._table = None

    def near(self, center: np.ndarray, radius: float, z0: float, z1: float) -> list[str]:
        """Placed objects, in the order of ``hulls``, whose world footprint may come within
        ``radius`` of the world xy point ``center`` and whose z range overlaps ``(z0, z1)``.

        Conservative: every object that does is listed (some that do not may be). Each
        footprint is bounded by the disc around its bounding box's centre; the disc is
        widened by sqrt(2) so that the box of the footprint in any rotated frame is covered.
        """
        if not self._ids:
            return []
        if self._table is None:
            self._table = np.array(self._rows, float).reshape(-1, 5)
        T = self._table
        d = np.hypot(T[:, 0] - center[0], T[:, 1] - center[1])
        ok = (d <= radius + np.sqrt(2.0) * T[:, 2] + 1e-6) & (T[:, 4] >= z0) & (T[:, 3] <= z1)
        return [self._ids[i] for i in np.flatnonzero(ok)]

    def memo(self, oid: str, key, fn):
        """``fn()``, computed once per ``key`` while ``oid`` (a placed object, or ``room``)
        keeps its pose: for geometry derived from a fixed parent (its support region with a
        margin, its low parts' height, its pieces' footprints in a support plane)."""
        got = self._memo.setdefault(oid, {})
        if key not in got:
            got[key] = fn()
        return got[key]

    def world_pieces(self, oid: str) -> list[tuple[str, np.ndarray]]:
        """(part name, world vertices) of every convex piece of a placed object (cached)."""
        got = self.pieces.get(oid)
        if got is None:
            o = self.scene.objects[oid]
            T = o.transform()
            got = [(p.name, pc.vertices @ T[:3, :3].T + T[:3, 3]) for p in o.asset.parts
                   for pc in p.piece_arrays]
            self.pieces[oid] = got
        return got


# --------------------------------------------------------------------------- helpers
def parts_for(asset: Asset, ref: Ref) -> list[Part]:
    """The parts of ``asset`` a reference names (all parts when it names none)."""
    if ref.part is None:
        return list(asset.parts)
    ps = asset.parts_by_label(ref.part)
    if ref.index is not None:
        ps = ps[ref.index:ref.index + 1]
    return ps


def plane_coords(surf: Surface, pts: np.ndarray) -> np.ndarray:
    """(N, 2) coordinates of world points in the plane frame ``(u, v)`` of ``surf``."""
    d = np.asarray(pts, float) - surf.origin
    return np.column_stack([d @ surf.u, d @ surf.v])


@per_object()
def plane_key(s: Surface) -> tuple:
    """A hashable key of a support plane (its origin and normal rounded to 1e-9), made once
    per surface object (a parent's supports are kept on the solve state and asked for by
    every child)."""
    key = (*np.asarray(s.origin).round(9).tolist(), *np.asarray(s.normal).round(9).tolist())
    return key


@per_object()
def frame_key(s: Surface) -> bytes:
    """A hashable key of a surface's plane frame, exact (origin, normal and in-plane axes, as
    bytes): geometry in its plane coordinates may be kept under it. Made once per surface
    object."""
    key = b"".join(np.asarray(x, float).tobytes() for x in (s.origin, s.normal, s.u, s.v))
    return key



def angle_to(vec: np.ndarray, target: np.ndarray, n: np.ndarray) -> float | None:
    """Angle about ``n`` taking ``vec`` onto ``target`` (both projected); None if degenerate."""
    pv = vec - np.dot(vec, n) * n
    pt = target - np.dot(target, n) * n
    npv, npt = math.sqrt(pv.dot(pv)), math.sqrt(pt.dot(pt))  # np.linalg.norm's value
    if npv < 1e-3 or npt < 1e-3:
        return None
    pv /= npv
    pt /= npt
    (a, b, c), (x, y, z) = pv.tolist(), pt.tolist()
    cross = np.array([b * z - c * y, c * x - a * z, a * y - b * x])  # np.cross is slow here
    return float(np.arctan2(np.dot(cross, n), np.dot(pv, pt)))


def wrap(a: float) -> float:
    """An angle in radians wrapped to [-pi, pi)."""
    return float((a + np.pi) % (2 * np.pi) - np.pi)


def support_chain(pag: PAG, oid: str) -> set[str]:
    """``oid`` and the objects below it in the support tree."""
    out = set()
    while oid is not None and oid not in out and oid in pag.objects:
        out.add(oid)
        e = pag.supporter(oid)
        oid = e.parent.object if e is not None else None
    return out
