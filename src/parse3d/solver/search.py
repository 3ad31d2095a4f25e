"""The search over objects: Algorithm 1's loop in assembly order, failure propagation along
support only, conflict-directed backjumping, and re-placing a given set of objects with the
rest of the scene fixed (used by the repair after settling).

Every object draws from its own generator, ``stage_rng(seed, "object:<id>")``; a re-placement
draws from ``stage_rng(seed, "object:<id>:<round>")``, so a solve is deterministic per seed.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Polygon

from ..measure.checks import check_relations, object_centroid
from ..pag.algorithms import assembly_order
from ..pag.model import PAG
from ..scene.model import PlacedObject, Scene
from ..scene.shell import build_shell
from .collision import Body, CollisionWorld, cached_body
from .config import Fail, SolverConfig, stage_rng
from .placement import Placement, place_object, resolution, scaled_mesh
from .state import SolveState

__all__ = ["SolveProgress", "solve_scene", "replace_objects", "support_descendants"]


@dataclass(frozen=True)
class SolveProgress:
    """One progress event: an object was placed or failed.

    Attributes
    ----------
    object_id : str
    status : str
        ``placed`` or ``failed``.
    done, total : int
        Objects decided so far, and in the scene.
    """

    object_id: str
    status: str
    done: int
    total: int


def support_descendants(pag: PAG, oid: str) -> list[str]:
    """Objects resting (directly or not) on ``oid``, in assembly order."""
    kids: dict[str, list[str]] = {}
    for c in pag.objects:
        e = pag.supporter(c)
        if e is not None and not e.parent.is_room_element:
            kids.setdefault(e.parent.object, []).append(c)
    out, todo = set(), [oid]
    while todo:
        for c in kids.get(todo.pop(), []):
            if c not in out:
                out.add(c)
                todo.append(c)
    return [o for o in assembly_order(pag) if o in out]


#: Conflicting objects tried per failure, and rounds over them (each with fresh draws): at
#: least ``JUMP_ROUNDS``, more while a round is short, up to ``JUMP_TRIES`` re-placements (one
#: culprit, the bed a nightstand must stand beside, gets several draws).
MAX_CULPRITS = 6

#: Metres below a parent, and around its footprint, where placed objects are in the way of what
#: hangs from it (a hanger's length, a robe's sway).
HANG_SPACE = 1.0
HANG_REACH = 0.3
JUMP_ROUNDS = 2
JUMP_TRIES = 6


def _size_estimate(pag: PAG, oid: str) -> float:
    """Typical size (m) of an object's candidate categories (largest of their size ranges'
    middles); 0 for categories the registry does not know."""
    from ..assets import registry

    out = 0.0
    for c in pag.objects[oid].candidates:
        try:
            lo, hi = registry.get(c).size_range
        except KeyError:
            continue
        out = max(out, (lo + hi) / 2)
    return out


def placement_order(pag: PAG) -> list[str]:
    """The PAG's assembly order, with siblings on one object support (children of a table, a
    shelf) reordered more constrained and larger first, unless that would place an object
    before one of its parents or after one of its dependents."""
    order = assembly_order(pag)
    groups: dict[str, list[str]] = {}
    for oid in order:
        e = pag.supporter(oid)
        if e is not None and not e.parent.is_room_element:
            groups.setdefault(e.parent.object, []).append(oid)
    pos = {o: i for i, o in enumerate(order)}
    for kids in groups.values():
        if len(kids) < 2:
            continue
        slots = sorted(pos[k] for k in kids)
        ranked = sorted(kids, key=lambda k: (-len(pag.edges_of(k)), -_size_estimate(pag, k),
                                             pos[k]))
        new = dict(zip(ranked, slots, strict=True))
        # keep the group as it is when moving would put an object before one of its parents
        # or after one of its dependents
        at = {**pos, **new}
        if all(at[e.parent.object] < at[e.child.object] for e in pag.relations
               if e.parent.object in at and e.child.object in at
               and (e.child.object in new or e.parent.object in new)):
            for k, slot in new.items():
                order[slot] = k
            pos.update(new)
    return order


class _Search:
    """The solve in progress: placements, failures and the check results kept per edge."""

    def __init__(self, pag: PAG, seed: int, cfg: SolverConfig, library, st: SolveState):
        self.pag, self.seed, self.cfg, self.library, self.st = pag, int(seed), cfg, library, st
        self.placements: dict[str, Placement] = {}
        self.failed: dict[str, str] = {}
        self.edge_index = {id(e): i for i, e in enumerate(pag.relations)}
        self.budget = int(cfg.search_budget) if cfg.search == "backtracking" else 0
        self.backjumps = 0

    # ------------------------------------------------------------ bookkeeping
    def skipped(self, oid: str) -> frozenset[int]:
        """Indices of ``oid``'s non-support edges whose parent object failed."""
        return frozenset(i for i, e in enumerate(self.pag.edges_of(oid))
                         if i > 0 and e.parent.object in self.failed)

    def try_place(self, oid: str, stage: str, proposal=None, keep=None) -> Placement:
        rng = stage_rng(self.seed, stage)
        return place_object(self.st, oid, rng, self.cfg, self.library, skip=self.skipped(oid),
                            proposal=proposal, keep=keep)

    def commit(self, p: Placement) -> None:
        self.placements[p.obj.id] = p
        self.failed.pop(p.obj.id, None)
        self.st.add(p.obj, p.body)

    def uncommit(self, oid: str) -> Placement | None:
        p = self.placements.pop(oid, None)
        if p is not None:
            self.st.remove(oid)
        return p

    def fail(self, oid: str, reason: str, trials: int = 0) -> None:
        node = self.pag.objects[oid]
        self.failed[oid] = reason
        self.st.scene.objects[oid] = PlacedObject(oid, node.candidates[0], None, status="failed",
                                                  reason=reason, trials=trials)

    # ------------------------------------------------------------ backjumping
    def conflict_set(self, oid: str) -> list[str]:
        """Placed objects the failed object's constraints involve: the parents of its layout
        relations and the other occupants of its support (of the same wall for wall items),
        nearest in the PAG first."""
        pag = self.pag
        edges = pag.edges_of(oid)
        sup = edges[0].parent.object
        out: list[str] = []
        for e in edges[1:]:
            p = e.parent.object
            if p in self.placements and p not in out:
                out.append(p)
        walls = {e.parent.object for e in edges if e.parent.is_room_element
                 and e.parent.object.startswith("wall")}
        layout = list(out)
        occupants = list(reversed(list(self.placements)))
        if layout:  # nearest to the layout parents first
            anchors = np.array([object_centroid(self.st.scene.objects[p]) for p in layout])
            occupants.sort(key=lambda o: float(np.min(np.linalg.norm(
                anchors - object_centroid(self.st.scene.objects[o]), axis=1))))
        for other in occupants:
            if other in out:
                continue
            oe = pag.edges_of(other)
            same_support = oe[0].parent.object == sup and oe[0].relation == edges[0].relation
            same_wall = bool(walls) and any(e.parent.object in walls or e.parent.object == "wall"
                                            for e in oe)
            if same_support or same_wall:
                out.append(other)
        if edges[0].relation == "HANGING_BELOW" and sup in self.placements:
            # what stands or hangs in the space below the parent (a shelf under a robe hook)
            st = self.st
            z0 = st.zr[sup][0]
            foot = Polygon(st.xy[sup])
            for other in occupants:
                if other in out or other == sup or other not in st.zr:
                    continue
                if z0 - HANG_SPACE < st.zr[other][1] and st.zr[other][0] < z0 and \
                        foot.distance(Polygon(st.xy[other])) < HANG_REACH:
                    out.append(other)
        # never move what the failed object rests on or anything holding it up
        below = set()
        e = pag.supporter(oid)
        while e is not None and not e.parent.is_room_element and e.parent.object not in below:
            below.add(e.parent.object)
            e = pag.supporter(e.parent.object)
        return [o for o in out if o not in below]

    def backjump(self, oid: str) -> Placement | None:
        """Re-place conflicting objects (with what rests on them) to make room for ``oid``;
        the scene is restored when no choice works within the budget."""
        culprits = self.conflict_set(oid)[:MAX_CULPRITS]
        rounds = max(JUMP_ROUNDS, JUMP_TRIES // max(len(culprits), 1))
        tries = [(r, c) for r in range(rounds) for c in culprits]
        for k, (_, culprit) in enumerate(tries):
            moved = [culprit, *[d for d in support_descendants(self.pag, culprit)
                                if d in self.placements]]
            if self.budget < len(moved):
                continue
            self.budget -= len(moved)
            self.backjumps += 1
            old = {m: self.uncommit(m) for m in moved}
            for m in moved:  # out of the scene while the conflict is re-solved
                self.st.scene.objects[m] = PlacedObject(m, old[m].obj.category, None,
                                                        status="failed", reason="re-placing")
            # a moved object the failed one relates to goes first (a parent of its layout
            # relation); occupants of its support go after it (it takes its room first)
            parents = {e.parent.object for e in self.pag.edges_of(oid)}
            seq = [*moved, oid] if parents & set(moved) else [oid, *moved]
            new: list[str] = []
            mine = None
            try:
                for m in seq:
                    p = self.try_place(m, f"object:{m}:jump{k}")
                    self.commit(p)
                    new.append(m)
                    if m == oid:
                        mine = p
                return mine
            except Fail:
                for m in new:
                    self.uncommit(m)
                for m in moved:
                    self.st.scene.objects[m] = old[m].obj
                    self.commit(old[m])
                self.st.scene.objects.pop(oid, None)
        return None


def solve_scene(pag: PAG, *, seed: int = 0, library=None, config: SolverConfig | None = None,
                progress: Callable[[SolveProgress], None] | None = None,
                deadline: float | None = None,
                proposals: dict[str, tuple] | None = None) -> Scene:
    """Solve a validated PAG into a Scene (failed objects are marked, never raised).

    Parameters
    ----------
    pag : PAG
    seed : int
    library : asset library, optional
    config : SolverConfig, optional
    progress : callable, optional
        Called with a :class:`SolveProgress` after each object is decided.
    deadline : float, optional
        Seconds of wall time; objects not placed by then fail with ``time limit``.
    proposals : dict of str to (R (3, 3), t (3,)), optional
        World poses tried first for these objects (then the usual sampling).
    """
    from .library import default_library

    cfg = config or SolverConfig()
    library = library or default_library()
    t0 = time.perf_counter()
    shell = build_shell(pag.room, wall_thickness=cfg.wall_thickness)
    scene = Scene(pag, int(seed), shell, meta={"solver": cfg.to_dict()})
    world = CollisionWorld()
    for name, el in shell.elements.items():
        world.add(f"room:{name}", Body.from_mesh(el.mesh_arrays))
    st = SolveState(pag, scene, world)
    srch = _Search(pag, seed, cfg, library, st)
    order = placement_order(pag)
    proposals = proposals or {}
    for n, oid in enumerate(order):
        sup = pag.supporter(oid)
        if deadline is not None and time.perf_counter() - t0 > deadline:
            srch.fail(oid, f"time limit: {deadline:g} s reached before it was placed")
        elif sup is not None and sup.parent.object in srch.failed:
            srch.fail(oid, f"its support {sup.parent.object!r} failed")
        else:
            try:
                srch.commit(srch.try_place(oid, f"object:{oid}", proposals.get(oid)))
            except Fail as f:
                # re-placing others cannot fix what the object's own geometry rules out
                got = srch.backjump(oid) if srch.budget > 0 and not f.intrinsic else None
                if got is None:
                    srch.fail(oid, str(f), cfg.max_trials * cfg.asset_attempts)
        if progress is not None:
            progress(SolveProgress(oid, scene.objects[oid].status, n + 1, len(order)))
    # keep the PAG's assembly order in scene.objects
    scene.objects = {oid: scene.objects[oid] for oid in assembly_order(pag)}
    scene.meta["search"] = {"backjumps": srch.backjumps,
                            "budget_left": srch.budget if cfg.search == "backtracking" else None}
    scene.timings["solve"] = time.perf_counter() - t0
    _finish(scene, srch)
    return scene


def _finish(scene: Scene, srch: _Search) -> None:
    """Relation checks (reusing those measured when each pose was accepted), resolutions and
    unmet relations."""
    pag = scene.pag
    known: dict[int, tuple] = {}
    resolved: dict[str, dict] = {}
    for oid, p in srch.placements.items():
        edges = pag.edges_of(oid)
        for e, r in zip(edges, p.checks, strict=False):
            if r is not None:
                known[srch.edge_index[id(e)]] = r
        resolved[str(srch.edge_index[id(edges[0])])] = resolution(
            edges[0], p.obj.support_choice, final=True)
    scene.meta["resolved"] = resolved
    t1 = time.perf_counter()
    scene.relations = check_relations(scene, known=known)
    mark_unmet(scene)
    scene.timings["check"] = time.perf_counter() - t1
    scene.meta["trials"] = {o.id: o.trials for o in scene.objects.values()}


def mark_unmet(scene: Scene) -> None:
    """Relations of a placed child whose (non-support) parent failed: ``holds`` None and
    ``detail`` ``unmet: parent 'x' failed`` (after settling too)."""
    for c in scene.relations:
        e = scene.pag.relations[c.index]
        child = scene.objects.get(e.child.object)
        parent = scene.objects.get(e.parent.object)
        if child is None or not child.placed or parent is None or parent.placed:
            continue
        c.holds, c.residual, c.detail = None, {}, f"unmet: parent {e.parent.object!r} failed"
        if scene.settled:
            c.holds_settled, c.residual_settled = None, None


def replace_objects(scene: Scene, ids: list[str], *, seed: int, round: int, library=None,
                    config: SolverConfig | None = None, new_asset: set[str] | None = None,
                    ) -> dict[str, str]:
    """Re-place ``ids`` (and what rests on them) in ``scene``, keeping every other object fixed.

    Each object draws from ``stage_rng(seed, "object:<id>:repair<round>")``; objects in
    ``new_asset`` skip the asset they had (another pool draw). Objects that cannot be placed
    again keep their old pose. Returns ``{id: "pose" | "asset"}`` for those re-placed.
    """
    from .library import default_library

    cfg = config or SolverConfig()
    library = library or default_library()
    pag = scene.pag
    world = CollisionWorld()
    for name, el in scene.room.elements.items():
        world.add(f"room:{name}", Body.from_mesh(el.mesh_arrays))
    st = SolveState(pag, scene, world)
    todo: list[str] = []
    for oid in ids:
        for o in [oid, *support_descendants(pag, oid)]:
            if o not in todo and scene.objects[o].placed:
                todo.append(o)
    todo = [o for o in assembly_order(pag) if o in todo]
    for o in scene.objects.values():
        if o.placed and o.id not in todo:
            st.add(o, cached_body(o.asset.asset_id, o.scale, lambda o=o: scaled_mesh(o.asset, o.scale)))
    srch = _Search(pag, seed, cfg, library, st)
    srch.failed = {o.id: o.reason or "" for o in scene.objects.values() if not o.placed}
    done: dict[str, str] = {}
    new_asset = new_asset or set()
    for oid in todo:
        old = scene.objects[oid]
        for attempt in range(4):
            keep = old if oid not in new_asset and attempt < 2 else None
            try:
                p = srch.try_place(oid, f"object:{oid}:repair{round}:{attempt}", keep=keep)
            except Fail:
                continue
            if oid in new_asset and p.obj.asset.asset_id == old.asset.asset_id and attempt < 3:
                continue
            p.obj.repairs = list(old.repairs)
            p.obj.flags = [f for f in old.flags if f not in ("fell", "tipped", "left_support")]
            p.obj.joints = dict(old.joints)
            srch.commit(p)
            done[oid] = "asset" if p.obj.asset.asset_id != old.asset.asset_id else "pose"
            break
        else:
            st.add(old, cached_body(old.asset.asset_id, old.scale,
                                    lambda o=old: scaled_mesh(o.asset, o.scale)))
    # fresh checks for what moved
    known: dict[int, tuple] = {}
    for oid, p in srch.placements.items():
        for e, r in zip(pag.edges_of(oid), p.checks, strict=False):
            if r is not None:
                known[srch.edge_index[id(e)]] = r
        scene.meta.setdefault("resolved", {})[str(srch.edge_index[id(pag.edges_of(oid)[0])])] = \
            resolution(pag.edges_of(oid)[0], p.obj.support_choice, final=True)
    return done
