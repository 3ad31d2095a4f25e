"""The relation-aware step of the PAG-conditioned sampler: generated poses fitted to the PAG.

A diffusion model puts a mug on a desk to a centimetre or two at best; a mug 1.5 cm into the
desk top, or two books 2 cm into each other on one shelf, already counts as a collision. The
PAG says which objects touch and how (``ON``/``IN`` which surface of which part, ``AGAINST``
which wall), so a sampler that has the PAG can finish the job the network leaves half done.
:func:`fit_scene` does that on the placed assets, once the poses are generated; it is part of
the PAG-conditioned sampler only (``SampleOptions.fit``, ``sample --fit``, ``eval --fit``), which
is reported both with and without it. Nothing here is learned.

1. **Contacts, parents first** (the PAG's assembly order). For every object, its contact
   relations are resolved on the very surfaces the relation checks measure (the parent
   part's named surface, an internal shelf or container bottom, a wall plane):

   - the child's named surface is turned to face the parent surface (the smallest rotation
     that makes the normals anti-parallel) when they are within :data:`ALIGN_DEG`;
   - ``ON``/``IN`` an object: the child's centre is brought over the parent surface's polygon
     (inset by the child's half width where that leaves room), then the child is lowered or
     lifted along the surface normal to rest :data:`GAP` above it;
   - ``ON floor``, ``AGAINST``, ``SECURED_TO``: moved along the surface normal to the
     relation's gap (``AGAINST``'s ``gap`` parameter) plus :data:`GAP`;

   an object carries what it supports (its support subtree moves rigidly with it).
2. **Collisions, the PAG's way** (:data:`ROUNDS` rounds): every pair still interpenetrating
   by more than :data:`GAP` (FCL on the convex collision pieces, as the collision metric
   sees it) moves one object out, *within the freedom its relations leave*: tangentially to
   its support surface (a mug slides on the desk, a bed on the floor), and along the wall it
   is ``AGAINST`` or ``SECURED_TO``; the mover is the object carried by the other (a pillow
   in the headboard), else the one carried by an object rather than the room, else the
   smaller; what it carries moves with it, and an ``ON``/``IN`` child stays over its
   parent's surface.

``HANGING_BELOW`` (a drop range) and the arrangement relations (``NEAR``, ``SIDE_OF``, ...)
are left as generated.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..measure.checks import (
    CheckContext,
    _child_normal,
    _target_surface,
    select_parts,
    world_points,
)
from ..pag.algorithms import assembly_order
from ..relations import SUPPORT_RELATIONS
from ..scene.model import Scene

__all__ = ["FitReport", "fit_scene", "ALIGN_DEG", "GAP", "ROUNDS"]

#: Normals further apart than this (degrees) are not aligned (the model meant another face).
ALIGN_DEG = 30.0
#: Metres left between surfaces brought into contact (the checks allow -1...+2 mm).
GAP = 1e-3
#: Rounds of collision resolution.
ROUNDS = 12
_CONTACT = ("ON", "IN", "AGAINST", "SECURED_TO")
_SUPPORT = SUPPORT_RELATIONS


@dataclass
class FitReport:
    """What :func:`fit_scene` did.

    Attributes
    ----------
    aligned : int
        Objects turned so that a named surface faces its parent surface.
    contacts : int
        Contact relations brought to their gap.
    centred : int
        ``ON``/``IN`` children moved over their parent's surface.
    pushed : int
        Collision moves.
    """

    aligned: int = 0
    contacts: int = 0
    centred: int = 0
    pushed: int = 0

    def to_dict(self) -> dict:
        return {"aligned": self.aligned, "contacts": self.contacts, "centred": self.centred,
                "pushed": self.pushed}


def _rotation_between(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The smallest rotation taking unit vector ``a`` to unit vector ``b``."""
    v = np.cross(a, b)
    c = float(np.clip(a @ b, -1.0, 1.0))
    s = float(np.linalg.norm(v))
    if s < 1e-9:
        return np.eye(3)
    k = v / s
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + s * K + (1 - c) * (K @ K)


class _Fitter:
    def __init__(self, scene: Scene):
        from .sample import nearest_walls

        self.scene = scene
        self.pag = scene.pag
        self.resolved = {int(k): v for k, v in nearest_walls(scene).items()}
        self.index = {id(e): i for i, e in enumerate(self.pag.relations)}
        self.kids: dict[str, list[str]] = {}
        for oid in scene.objects:
            sup = self.pag.supporter(oid)
            if sup is not None and not sup.parent.is_room_element:
                self.kids.setdefault(str(sup.parent.object), []).append(oid)
        self.rep = FitReport()

    # ------------------------------------------------------------------ rigid moves
    def subtree(self, oid: str) -> list[str]:
        out, todo = [], [oid]
        while todo:
            x = todo.pop()
            if x in out:
                continue
            out.append(x)
            todo.extend(self.kids.get(x, ()))
        return out

    def move(self, oid: str, t: np.ndarray, R: np.ndarray | None = None,
             pivot: np.ndarray | None = None) -> None:
        """Move ``oid`` and what it carries: rotate by ``R`` about ``pivot``, then shift by ``t``."""
        for x in self.subtree(oid):
            o = self.scene.objects.get(x)
            if o is None or not o.placed:
                continue
            p = np.asarray(o.position, float)
            if R is not None:
                o.rotation = R @ np.asarray(o.rotation, float)
                p = R @ (p - pivot) + pivot
            o.position = p + t

    # ------------------------------------------------------------------ contacts
    def surface(self, e, o):
        pobj = None if e.parent.is_room_element else self.scene.objects.get(e.parent.object)
        if pobj is not None and not pobj.placed:
            return None
        ctx = CheckContext(self.scene, e, o, pobj, self.resolved.get(self.index[id(e)], {}),
                           False)
        try:
            s = _target_surface(ctx)
        except (KeyError, ValueError, IndexError):
            return None
        return None if isinstance(s, str) else s

    def label(self, e, o) -> str | None:
        if e.relation == "ON" and o.rests_on:
            return o.rests_on
        return e.child.surface or e.spec.child_surface

    def align(self, e, o, sB) -> None:
        label = self.label(e, o)
        if label is None:
            return
        nA = _child_normal(o, label, False)
        target = -np.asarray(sB.normal, float)
        ang = float(np.degrees(np.arccos(np.clip(nA @ target, -1.0, 1.0))))
        if ang <= 1e-3 or ang > ALIGN_DEG:
            return
        if abs(target[2]) < 0.3 and e.relation in ("AGAINST", "SECURED_TO"):
            # against a wall: turn about the vertical only, so the support contact stays
            h = nA - nA[2] * np.array([0, 0, 1.0])
            if np.linalg.norm(h) < 1e-6:
                return
            a = np.arctan2(target[1], target[0]) - np.arctan2(h[1], h[0])
            c, s = np.cos(a), np.sin(a)
            R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
        else:
            R = _rotation_between(nA, target)
        centre = world_points(o, hull_only=True, settled=False).mean(0)
        self.move(o.id, np.zeros(3), R, centre)
        self.rep.aligned += 1

    def centre_over(self, e, o, sB) -> None:
        """Bring the child's centre over the parent surface's polygon."""
        from shapely.geometry import Point

        pts = world_points(o, hull_only=True, settled=False)
        uv = sB.to_2d(pts)
        c = Point(*uv.mean(0))
        poly = sB.polygon
        half = 0.5 * float(np.min(np.ptp(uv, axis=0)))
        inner = poly.buffer(-min(half, 0.45 * np.sqrt(max(poly.area, 0.0))))
        if inner.is_empty:
            inner = poly.buffer(-1e-3)
        if inner.is_empty or inner.contains(c):
            return
        from shapely.ops import nearest_points

        q = nearest_points(inner, c)[0]
        d = sB.to_3d(np.array([[q.x, q.y]]))[0] - sB.to_3d(np.array([[c.x, c.y]]))[0]
        self.move(o.id, d)
        self.rep.centred += 1

    def contact(self, e, o, sB) -> None:
        """Move the child along the surface normal to the relation's gap."""
        parts = select_parts(o, e.child)
        if not parts:
            return
        pts = world_points(o, settled=False, parts=parts)
        n = np.asarray(sB.normal, float)
        gap = float(((pts - sB.origin) @ n).min())
        target = float(e.param("gap")) if e.relation == "AGAINST" else 0.0
        self.move(o.id, (target + GAP - gap) * n)
        self.rep.contacts += 1

    def fit_contacts(self) -> None:
        for oid in assembly_order(self.pag):
            o = self.scene.objects.get(oid)
            if o is None or not o.placed or o.asset is None:
                continue
            edges = [e for e in self.pag.edges_of(oid) if e.relation in _CONTACT]
            sup = self.pag.supporter(oid)
            # the support first (it fixes "up"), then walls; their moves are along
            # different normals and do not undo each other
            for e in sorted(edges, key=lambda e: e is not sup):
                sB = self.surface(e, o)
                if sB is None:
                    continue
                self.align(e, o, sB)
                sB = self.surface(e, o)  # an IN surface is chosen by the child's height
                if sB is None:
                    continue
                if e.relation in ("ON", "IN") and not e.parent.is_room_element:
                    self.centre_over(e, o, sB)
                self.contact(e, o, sB)

    # ------------------------------------------------------------------ collisions
    def freedom(self, oid: str) -> list[np.ndarray]:
        """Unit normals the object must not move along (its support and walls)."""
        o = self.scene.objects[oid]
        out = []
        for e in self.pag.edges_of(oid):
            if e.relation not in _CONTACT and e.relation not in _SUPPORT:
                continue
            if e.relation == "HANGING_BELOW":
                continue
            sB = self.surface(e, o)
            if sB is not None:
                out.append(np.asarray(sB.normal, float))
        return out

    def rank(self, a: str, b: str) -> tuple[str, str]:
        """(mover, other) of a colliding pair."""
        def parent(x):
            s = self.pag.supporter(x)
            return None if s is None or s.parent.is_room_element else str(s.parent.object)

        if b in self.subtree(a):  # b is carried by a
            return b, a
        if a in self.subtree(b):
            return a, b
        fixed = {x for x in (a, b) if self.scene.objects[x].fixed}
        if len(fixed) == 1:
            return (b, a) if a in fixed else (a, b)
        pa, pb = parent(a), parent(b)
        if (pa is None) != (pb is None):
            return (a, b) if pa is not None else (b, a)
        va = float(np.prod(np.ptp(self.scene.objects[a].world_bounds(settled=False), axis=0)))
        vb = float(np.prod(np.ptp(self.scene.objects[b].world_bounds(settled=False), axis=0)))
        return (a, b) if va <= vb else (b, a)

    def push_apart(self) -> None:
        from .evaluate import _deepest_contacts, _fcl_pieces

        for _ in range(ROUNDS):
            bodies = _fcl_pieces(self.scene)
            shift: dict[str, np.ndarray] = {}
            for i, j, depth, normal in _deepest_contacts(bodies):
                if depth <= GAP:
                    continue
                a, b = bodies[i][0], bodies[j][0]
                mover, other = self.rank(a, b)
                d = np.asarray(normal, float) * (1.0 if mover == b else -1.0)  # i -> j
                keep = self.freedom(mover)
                away = (self.scene.objects[mover].world_bounds(settled=False).mean(0)
                        - self.scene.objects[other].world_bounds(settled=False).mean(0))
                for n in keep:  # only along the surfaces it must stay on
                    d = d - (d @ n) * n
                    away = away - (away @ n) * n
                if np.linalg.norm(d) < 0.3:
                    d = away
                nd = float(np.linalg.norm(d))
                if nd < 1e-6:
                    continue
                d = d / nd
                cos = abs(float(d @ normal))
                step = min((depth + GAP) / max(cos, 0.3), 0.1 + depth)
                shift[mover] = shift.get(mover, np.zeros(3)) + step * d
            if not shift:
                break
            for oid, d in shift.items():
                self.move(oid, d)
                o = self.scene.objects[oid]
                sup = self.pag.supporter(oid)
                if sup is not None and sup.relation in ("ON", "IN") \
                        and not sup.parent.is_room_element:
                    sB = self.surface(sup, o)
                    if sB is not None:
                        self.centre_over(sup, o, sB)
            self.rep.pushed += len(shift)


def fit_scene(scene: Scene) -> FitReport:
    """Fit a generated scene's poses to its PAG's contacts, in place (see the module
    docstring). The scene's relation checks are *not* updated."""
    f = _Fitter(scene)
    f.fit_contacts()
    f.push_apart()
    return f.rep
