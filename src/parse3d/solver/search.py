"""The search over objects: Algorithm 1's loop in assembly order, failure propagation along
support only, conflict-directed backjumping, and re-placing a given set of objects with the
rest of the scene fixed (used by the repair after settling).

Every object draws from its own generator, ``stage_rng(seed, "object:<id>")``; a re-placement
draws from ``stage_rng(seed, "object:<id>:<round>")``, so a solve is deterministic per seed.
"""

from __future__ import annotations

import logging
import re
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import shapely

from ..measure.checks import check_edge, check_relations, object_centroid
from ..pag.algorithms import assembly_order
from ..pag.model import PAG
from ..relations import OBJECT
from ..scene.model import PlacedObject, Scene
from ..scene.shell import build_shell
from .choice import room_failure
from .collision import CollisionWorld, cached_body, static_body
from .config import Fail, SolverConfig, stage_rng
from .geometry import asset_geometry
from .intent import whole_object
from .placement import Placement, place_object, resolution, scaled_mesh
from .rules import RULES
from .rules.layout import nearest
from .state import SolveState, support_chain
from .walls import Window, free_runs, occupants, wall_length, windows

__all__ = ["SolveProgress", "solve_scene", "replace_objects", "support_descendants",
           "wall_conflicts", "mark_unmet", "relax_plan", "chase"]

log = logging.getLogger("parse3d.solver")


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

#: Wall relations whose object needs a free stretch of its wall (see :meth:`_Search.clear`).
WALL_NEEDS = ("AGAINST", "SECURED_TO", "LEANING_AGAINST")
#: Metres added to a wall object's width and depth when looking for a stretch to clear.
CLEAR_PAD = 0.05
#: Stretches of wall tried per failure, cheapest first.
CLEAR_WINDOWS = 3
#: Extra cost of moving an object that names the very wall being cleared (it must find room on
#: it again).
CLEAR_SAME_WALL = 2
#: Objects bulkier (bounding-box volume) than this many times the object a wall is cleared
#: for are not moved to clear it.
CLEAR_BULK = 3.0
#: Draws per layout parent re-placed with its whole group.
GROUP_DRAWS = 2
#: Metres around a layout parent within which what stands on its support moves with it in a
#: group's last draw.
AROUND = 0.6
#: Most objects moved when a child's object support is re-placed with its group (a wall shelf
#: with what is on it), and draws of that move.
SUPPORT_GROUP = 10
SUPPORT_DRAWS = 2


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
        #: re-placements for clearing crowded walls, apart from the budget of backjumps
        self.reserve = self.budget
        self.backjumps = 0
        #: nesting of clearing moves (a displaced wall object clears a stretch of its own):
        #: allowed in the last move only, and how deep the search is in it
        self.nest = False
        self.depth = 0
        self.nest_reserve = self.budget
        self.order = placement_order(pag)
        #: relaxed edges (global index as text) and what blocked them, kept in the scene
        self.relaxed: dict[str, str] = st.scene.meta.setdefault("relaxed", {})
        #: relaxed part-level edges placed by the whole object instead (kept in the scene, so a
        #: re-placement, by a backjump or a repair, places them so again)
        self.whole: list[str] = st.scene.meta.setdefault("relaxed_whole", [])
        #: re-placements spent on the moves for the object now failing
        self.spent = 0

    def late(self) -> bool:
        """Whether the moves for the object now failing have spent their share
        (``cfg.moves_per_failure`` re-placements; counted, so a solve stays deterministic)."""
        return self.spent >= self.cfg.moves_per_failure

    # ------------------------------------------------------------ bookkeeping
    def skipped(self, oid: str) -> frozenset[int]:
        """Indices of ``oid``'s non-support edges whose parent object failed or that were
        relaxed (``scene.meta["relaxed"]``)."""
        return frozenset(i for i, e in enumerate(self.pag.edges_of(oid))
                         if i > 0 and (e.parent.object in self.failed
                                       or str(self.edge_index[id(e)]) in self.relaxed))

    def relax(self, oid: str, reason: str) -> Placement | None:
        """Place ``oid`` with its unmet relations relaxed, step by step as
        :func:`relax_plan` orders them (the relations the failure names, then the culprit
        among the others, then object-level relations, part-level contacts by the whole
        object, layout relations only at their nearest positions, then every one left out);
        after a failed step, that step with what its own failure names relaxed as well
        (:func:`chase`) comes next. Each step is one placement with half the draws and two
        assets, at most ``MAX_RELAX_STEPS`` (the last, every relation left out, always, with
        all the draws);
        the relaxed edges are recorded in ``relaxed`` (global index as text: what blocked
        them, the last failure that names them, else ``reason``). None when even with every non-support relation relaxed the support cannot
        hold the object."""
        cfg = self.cfg
        cheap = SolverConfig(**{**cfg.to_dict(), "max_trials": max(1, cfg.max_trials // 2),
                                "asset_attempts": min(2, cfg.asset_attempts)})
        edges = self.pag.edges_of(oid)
        done = self.skipped(oid)
        plan = relax_plan(self.pag, oid, reason, done)
        last = plan.pop() if plan else None
        tried: list[dict[int, str]] = []
        # what blocked each edge: the last failure that names it, else the object's
        why = dict.fromkeys(_named_edges(self.pag, oid, reason), reason)
        k = 0
        while last is not None:
            if plan and len(tried) < MAX_RELAX_STEPS - 1:
                step = plan.pop(0)
                if step in tried:
                    continue
            else:
                step, last = last, None
            tried.append(step)
            keys = {i: str(self.edge_index[id(edges[i])]) for i in step}
            for i, key in keys.items():
                self.relaxed[key] = why.get(i, reason)
            loose = {i: loosened(edges[i]) for i, how in step.items() if how == "loose"}
            self.whole.extend(keys[i] for i in loose)
            try:
                # the last step, every relation left out, is the object's last chance: all
                # the draws
                p = self.place(oid, stage_rng(self.seed, f"object:{oid}:relax{k}"),
                               cheap if last is not None else cfg, loosen=loose)
            except Fail as f:
                for key in keys.values():
                    self.relaxed.pop(key, None)
                self.whole[:] = [w for w in self.whole if w not in keys.values()]
                if str(f).startswith(INTERNAL):
                    return None
                why.update(dict.fromkeys(_named_edges(self.pag, oid, str(f)), str(f)))
                nxt = chase(self.pag, oid, step, str(f), done)
                if nxt is not None and nxt not in tried and nxt != last:
                    # first among the steps relaxing as many relations
                    plan = [x for x in plan if x != nxt]
                    at = next((j for j, x in enumerate(plan) if len(x) >= len(nxt)), len(plan))
                    plan.insert(at, nxt)
                continue
            finally:
                k += 1
            self.commit(p)
            return p
        return None

    def try_place(self, oid: str, stage: str, proposal=None, keep=None,
                  smallest: bool = False) -> Placement:
        rng = stage_rng(self.seed, stage)
        loose = {i: loosened(e) for i, e in enumerate(self.pag.edges_of(oid))
                 if i > 0 and str(self.edge_index[id(e)]) in self.whole}
        return self.place(oid, rng, self.cfg, proposal=proposal, keep=keep, smallest=smallest,
                          loosen=loose)

    def place(self, oid: str, rng, cfg: SolverConfig, **kw) -> Placement:
        """:func:`place_object` for ``oid``; an exception other than :class:`Fail` becomes a
        Fail ``internal error: ...`` (intrinsic: no move of others is tried for it) with its
        traceback in the log and ``scene.log``, so one object's fault never stops a solve."""
        loose = kw.get("loosen") or {}
        try:
            return place_object(self.st, oid, rng, cfg, self.library,
                                skip=self.skipped(oid) - set(loose), **kw)
        except Fail:
            raise
        except Exception as e:  # noqa: BLE001 - one object's fault is its failure
            raise _internal(self.st.scene, oid, e) from e

    def commit(self, p: Placement) -> None:
        edges = self.pag.edges_of(p.obj.id)
        key = str(self.edge_index[id(edges[0])])
        if p.loose_support is not None:
            self.relaxed[key] = p.loose_support
        else:
            self.relaxed.pop(key, None)
        for i, why in p.flush.items():  # flush by another part than the one named
            k = str(self.edge_index[id(edges[i])])
            self.relaxed[k] = why
            if k not in self.whole:  # a re-placement places it so again, not without it
                self.whole.append(k)
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
            foot = shapely.Polygon(st.xy[sup])
            for other in occupants:
                if other in out or other == sup or other not in st.zr:
                    continue
                if z0 - HANG_SPACE < st.zr[other][1] and st.zr[other][0] < z0 and \
                        foot.distance(shapely.Polygon(st.xy[other])) < HANG_REACH:
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
            if self.late():
                break
            moved = [culprit, *[d for d in support_descendants(self.pag, culprit)
                                if d in self.placements]]
            if self.budget < len(moved):
                continue
            self.budget -= len(moved)
            self.spent += len(moved)
            self.backjumps += 1
            # a moved object the failed one relates to goes first (a parent of its layout
            # relation); occupants of its support go after it (it takes its room first)
            parents = {e.parent.object for e in self.pag.edges_of(oid)}
            seq = [*moved, oid] if parents & set(moved) else [oid, *moved]
            got = self.relocate(oid, moved, seq, f"jump{k}")
            if got is not None:
                return got
        return None

    def relocate(self, oid: str, moved: list[str], seq: list[str], stage: str,
                 small: frozenset[str] = frozenset()) -> Placement | None:
        """Take ``moved`` out of the scene and place ``seq`` (``oid`` and ``moved``) in that
        order, each drawing from ``stage_rng(seed, "object:<id>:<stage>")`` (those in
        ``small`` starting with their smallest suitable instance); ``oid``'s placement, or
        None with the scene restored exactly when one of them fails."""
        snap, objs = dict(self.placements), dict(self.st.scene.objects)
        old = {m: self.uncommit(m) for m in moved}
        for m in moved:  # out of the scene while the conflict is re-solved
            self.st.scene.objects[m] = PlacedObject(m, old[m].obj.category, None,
                                                    status="failed", reason="re-placing")
        new: list[str] = []
        mine = None
        nested = False
        try:
            for m in seq:
                try:
                    p = self.try_place(m, f"object:{m}:{stage}", smallest=m in small)
                except Fail as f:
                    # a moved wall object that finds no room again may clear a stretch of
                    # its own (one level deep: the bench a wardrobe displaced)
                    if m == oid or not self.nest or self.depth or f.intrinsic \
                            or not room_failure(str(f)):
                        raise
                    self.depth += 1
                    try:
                        got = self.clear(m)
                    finally:
                        self.depth -= 1
                    if got is None:
                        raise
                    nested = True
                    new.append(m)
                    continue
                self.commit(p)
                new.append(m)
                if m == oid:
                    mine = p
            self.recheck({m for m, p in self.placements.items() if p is not snap.get(m)})
            return mine
        except Fail:
            if nested:  # back to the snapshot, what the nested move shifted too
                for m in [m for m, p in self.placements.items() if p is not snap.get(m)]:
                    self.uncommit(m)
                for m, p in snap.items():
                    if m not in self.placements:
                        self.commit(p)
                self.st.scene.objects.clear()
                self.st.scene.objects.update(objs)
                return None
            for m in new:
                self.uncommit(m)
            for m in moved:
                self.st.scene.objects[m] = old[m].obj
                self.commit(old[m])
            self.st.scene.objects.pop(oid, None)
        return None

    def recheck(self, moved: set[str]) -> None:
        """Check again the layout relations of placed objects that stayed towards objects that
        moved (a chair NEAR a dining table a backjump re-placed), keeping the fresh results;
        raise Fail when one no longer holds (the move is then undone)."""
        for oid, p in self.placements.items():
            if oid in moved:
                continue
            for i, e in enumerate(self.pag.edges_of(oid)):
                if i == 0 or e.parent.object not in moved or p.checks[i] is None:
                    continue
                r = check_edge(self.st.scene, e, p.obj)
                if not r[0]:
                    raise Fail(f"moving {e.parent.object} breaks {e.relation} {e.child} -> "
                               f"{e.parent}: {r[2]}")
                p.checks[i] = r

    # ------------------------------------------------------------ crowded walls
    def wall_need(self, oid: str) -> tuple[list[str], float, float, float, float] | None:
        """The walls a floor or wall object must stand against or hang on (every wall for
        ``wall``) and the room it needs there: ``(walls, width along the wall, depth in front
        of it, z0, z1)`` in metres, from its first asset draw at its usual scale; None for
        objects that name no wall or rest on another object."""
        pag = self.pag
        edges = pag.edges_of(oid)
        sup = edges[0]
        if not sup.parent.is_room_element:
            return None
        e = next((x for x in edges if x.relation in WALL_NEEDS and x.parent.is_room_element
                  and x.parent.object.startswith("wall")), None)
        if e is None or (e is not sup and sup.parent.object != "floor"):
            return None
        walls = [n for n in self.st.scene.room.elements if n.startswith("wall_")] \
            if e.parent.object == "wall" else [e.parent.object]
        ext = self.extents(oid)
        label = e.child.surface or e.spec.child_surface
        width, depth = (ext[1], ext[0]) if label in ("left", "right") else (ext[0], ext[1])
        if e.relation == "AGAINST":
            depth += e.param("gap")
        if e is sup:  # hung on the wall: anywhere its centre may be in the height band
            lo, hi = e.param("height")
            z0, z1 = lo - ext[2] / 2, hi + ext[2] / 2
        else:
            z0, z1 = 0.0, float(ext[2])
        return walls, float(width), float(depth), float(z0), float(z1)

    def extents(self, oid: str) -> np.ndarray:
        """(3,) extents (m) of the asset ``oid``'s first placement attempt draws, at the scale
        it gets there (the node's largest scale, within its category's size range)."""
        node = self.pag.objects[oid]
        rng = stage_rng(self.seed, f"object:{oid}")
        category = node.candidates[int(rng.integers(len(node.candidates)))]
        asset = self.library.get(category, rng)
        g = asset_geometry(asset)
        lo, hi = asset.size_range
        size = max(g.size, 1e-6)
        scale = (node.scale[1] if node.scale is not None else 1.0) \
            * float(np.clip(1.0, lo / size, hi / size))
        return np.ptp(g.bounds, axis=0) * scale

    def movers(self, oid: str) -> list[str]:
        """``oid`` and the placed objects that must move with it: what rests on any of them,
        and what relates to any of them (a chair NEAR a moved table), in placement order."""
        out, todo = {oid}, [oid]
        while todo:
            cur = todo.pop()
            for e in self.pag.relations:
                c = e.child.object
                if e.parent.object == cur and c not in out and c in self.placements:
                    out.add(c)
                    todo.append(c)
        return [o for o in self.order if o in out]

    def make_room(self, oid: str, reason: str = "") -> Placement | None:
        """Larger moves than a backjump's, from the clearing reserve: free a stretch of the
        wall the object needs (:meth:`clear`), re-place each placed parent of its layout
        relations together with everything that depends on it (a dining table with its
        chairs and what is on it), the failed object in its place in that group, or re-place
        the object support it found no room on (:meth:`resupport`). None with the scene
        restored when no move works."""
        got = self.clear(oid)
        if got is not None:
            return got
        got = self.regroup(oid)
        if got is None and room_failure(reason):
            got = self.resupport(oid)
        if got is None:
            # last, clearing again where the objects it displaces may clear for themselves
            # (from a reserve of its own, so that what the moves above spent does not bar it)
            self.nest, self.reserve, kept = True, self.nest_reserve, self.reserve
            try:
                got = self.clear(oid, "nest")
            finally:
                self.nest, self.nest_reserve, self.reserve = False, self.reserve, kept
        return got

    def resupport(self, oid: str) -> Placement | None:
        """Re-place the object ``oid`` rests on, with everything resting on or relating to it
        (at most ``SUPPORT_GROUP`` objects), the failed object in its place in that group:
        for a child that found no room on a support placed where other objects crowd it (a
        wall shelf hung just under another one leaves its tea caddies no headroom). Up to
        ``SUPPORT_DRAWS`` draws from the clearing reserve; None with the scene restored."""
        sup = self.pag.supporter(oid)
        if sup is None or sup.parent.is_room_element or sup.parent.object not in self.placements:
            return None
        parent = sup.parent.object
        group = set(self.movers(parent))
        if group & (support_chain(self.pag, parent) - {parent}) or len(group) > SUPPORT_GROUP:
            return None
        moved = [o for o in self.order if o in group]
        seq = [o for o in self.order if o in group or o == oid]
        for r in range(SUPPORT_DRAWS):
            if self.late():
                break
            if self.reserve < len(moved):
                break
            self.reserve -= len(moved)
            self.spent += len(moved)
            self.backjumps += 1
            got = self.relocate(oid, moved, seq, f"support{r}")
            if got is not None:
                return got
        return None

    def regroup(self, oid: str) -> Placement | None:
        """Re-place each placed parent of ``oid``'s layout relations with its group (see
        :meth:`make_room`); None with the scene restored when no draw works."""
        protected = support_chain(self.pag, oid)
        parents = [e.parent.object for e in self.pag.edges_of(oid)[1:]
                   if e.parent.object in self.placements]
        for k, parent in enumerate(dict.fromkeys(parents)):
            group = set(self.movers(parent))
            if group & protected:
                continue
            # the group alone, then with what stands around the parent on its support
            around: set[str] = set()
            room = self.reserve - GROUP_DRAWS * len(group)
            for n in self.around(parent, group | protected):
                more = set(self.movers(n)) - group
                if not more & protected and len(group | around | more) <= room:
                    around |= more
            for r, extra in enumerate([set()] * GROUP_DRAWS + ([around] if around else [])):
                if self.late():
                    break
                moved = [o for o in self.order if o in group or o in extra]
                if self.reserve < len(moved):
                    break
                self.reserve -= len(moved)
                self.spent += len(moved)
                self.backjumps += 1
                seq = [o for o in self.order if o in group or o == oid] + \
                    [o for o in self.order if o in extra]
                # the parent as small as its instances come, leaving room for its group
                got = self.relocate(oid, moved, seq, f"group{k}:{r}", frozenset({parent}))
                if got is not None:
                    return got
        return None

    def around(self, parent: str, skip: set[str]) -> list[str]:
        """Placed objects on ``parent``'s support (room elements: the same one) whose
        footprints come within ``AROUND`` metres of its footprint, nearest first."""
        sup = self.pag.supporter(parent)
        if sup is None or parent not in self.st.xy:
            return []
        me = shapely.Polygon(self.st.xy[parent])
        out = []
        for o in self.placements:
            e = self.pag.supporter(o)
            if o in skip or e is None or e.parent.object != sup.parent.object:
                continue
            d = me.distance(shapely.Polygon(self.st.xy[o]))
            if d <= AROUND:
                out.append((d, o))
        return [o for _, o in sorted(out)]

    def wall_windows(self, oid: str) -> list[Window]:
        """The conflict set of a wall object, by stretch of wall: for each stretch of the
        walls it needs (:meth:`wall_need`) where it would fit once cleared, the placed objects
        standing there (along the wall, or on the floor in front of it), cheapest to move
        first. The cost of a stretch is the number of objects moved (with what rests on or
        relates to them), plus ``CLEAR_SAME_WALL`` for each of them that names this very wall
        and for a wall that an object still to be placed names. Stretches holding something
        the object rests on or relates to, or bulkier than ``CLEAR_BULK`` times the object,
        are left out."""
        need = self.wall_need(oid)
        if need is None:
            return []
        walls, width, depth, z0, z1 = need
        protected = support_chain(self.pag, oid) | {e.parent.object
                                                    for e in self.pag.edges_of(oid)}
        # what is much bulkier than the object stays: moved, it would take the room of the
        # objects still to come (a bed moved for an armchair)
        bulk = CLEAR_BULK * float(np.prod(self.extents(oid)))
        protected |= {o for o, H in self.st.hulls.items()
                      if float(np.prod(np.ptp(H, axis=0))) > bulk}
        groups: dict[str, set[str] | None] = {}
        # walls that objects still to come name (a wardrobe AGAINST wall_3) are left to them
        later = {e.parent.object for e in self.pag.relations if e.relation in WALL_NEEDS
                 and e.child.object not in self.placements and e.child.object != oid}
        found = []
        for wall in walls:
            def cost(block: tuple[str, ...], wall=wall) -> int | None:
                moved: set[str] = set()
                for b in block:
                    if b not in groups:
                        g = set(self.movers(b)) if b in self.placements else None
                        groups[b] = None if g is None or g & protected else g
                    if groups[b] is None:
                        return None
                    moved |= groups[b]
                again = sum(any(e.parent.object == wall for e in self.pag.edges_of(m))
                            for m in moved) + (wall in later)
                return len(moved) + CLEAR_SAME_WALL * again

            s = self.st.scene.room.elements[wall].surface
            taken = occupants(s, self.st.hulls, depth + CLEAR_PAD, z0, z1)
            found += windows(wall, wall_length(s)[1], taken, width + CLEAR_PAD, cost)
        return sorted(found, key=lambda w: (w.cost, len(w.blockers), w.wall, w.a0))

    def clear(self, oid: str, tag: str = "clear") -> Placement | None:
        """Make room on a crowded wall: take out everything standing in the cheapest stretch
        of wall where ``oid`` would fit (:meth:`wall_windows`, with what depends on them),
        place ``oid`` first (it takes that stretch), then the others anywhere they go; up to
        ``CLEAR_WINDOWS`` stretches, from the clearing reserve. None with the scene restored
        when none works."""
        for k, win in enumerate(self.wall_windows(oid)[:CLEAR_WINDOWS]):
            if self.late():
                break
            group = {m for b in win.blockers for m in self.movers(b)}
            moved = [o for o in self.order if o in group]
            if self.reserve < len(moved):
                continue
            self.reserve -= len(moved)
            self.spent += len(moved)
            self.backjumps += 1
            got = self.relocate(oid, moved, [oid, *moved], f"{tag}{k}")
            if got is not None:
                return got
        return None

    def explain(self, oid: str, reason: str) -> str:
        """The failure reason, with what takes the wall the object names (``wall_k``) and the
        longest free stretch left when it found no room there."""
        need = self.wall_need(oid)
        if need is None or len(need[0]) != 1 or not room_failure(reason):
            return reason
        (w,), width, depth, z0, z1 = need
        s = self.st.scene.room.elements[w].surface
        length = wall_length(s)[1]
        taken = occupants(s, self.st.hulls, depth, z0, z1)
        if not taken:
            return reason
        names = list(dict.fromkeys(t.id for t in taken))
        run = max((b - a for a, b in free_runs(length, taken)), default=0.0)
        return (f"{reason}; {w} ({length:.2f} m) is taken by {', '.join(names[:6])}"
                f"{', ...' if len(names) > 6 else ''}: its longest free stretch is {run:.2f} m, "
                f"{oid} needs about {width:.2f} m")


#: Edge text in failure reasons: ``AGAINST sofa:back_cushion@back -> wall_2``.
_EDGE_RE = re.compile(r"\b([A-Z_]{2,}) (\S+) -> (\S+?)[:;,)]?(?:\s|$)")


def _named_edges(pag: PAG, oid: str, reason: str) -> list[int]:
    """Indices (into ``pag.edges_of(oid)``) of the edges a failure reason names."""
    texts = {f"{r} {c} -> {p}" for r, c, p in _EDGE_RE.findall(reason)}
    return [i for i, e in enumerate(pag.edges_of(oid))
            if i > 0 and f"{e.relation} {e.child} -> {e.parent}" in texts]


def relax_plan(pag: PAG, oid: str, reason: str, done: frozenset[int] = frozenset()
               ) -> list[dict[int, str]]:
    """The steps by which ``oid``'s non-support relations are relaxed, each ``{edge index:
    "skip" | "loose"}`` (``loose``: a part-level contact named by a part, placed by the whole
    object instead; a layout relation, placed at the free positions nearest its region):

    1. each edge the failure ``reason`` names alone (the last named first), loose first;
    2. the culprit among the others: each other edge alone relaxed (a layout relation loose,
       a contact left out), object-level ones first; then each with the named ones left out;
    3. every object-level relation loose;
    4. part-level contacts as well by the whole object;
    5. every layout relation loose and every contact left out;
    6. last, every one left out.

    Steps relaxing fewer relations come first (stable: in the order above), the last always
    last. Support relations are never relaxed; ``done`` (edges already left out) is left
    out. The search (:meth:`_Search.relax`) tries at most ``MAX_RELAX_STEPS`` of them (the
    last always), adding after a failed step that step with the edge its failure names
    relaxed as well (:func:`chase`), among the steps relaxing as many."""
    edges = pag.edges_of(oid)
    order = [RULES[e.relation].relax_order for e in edges]  # None: never relaxed (support)
    free = [i for i in range(1, len(edges)) if i not in done and order[i] is not None]
    obj = [i for i in free if order[i] == 0]
    part = [i for i in free if order[i] > 0]

    def soft(i: int) -> str:
        return "loose" if (edges[i].child.part is not None and order[i] > 0) \
            or _layout(edges[i]) else "skip"

    def out_(i: int) -> str:  # left out: a layout relation still at its nearest positions
        return "loose" if _layout(edges[i]) else "skip"

    steps: list[dict[int, str]] = []
    named = [i for i in _named_edges(pag, oid, reason) if i in free]
    # the edges the failure names, each alone (the last named first: "AGAINST a needs a
    # different orientation than AGAINST b" may be met without b), by the whole object first
    for i in reversed(named):
        steps.append({i: soft(i)})
        if soft(i) == "loose":
            steps.append({i: "skip"})
    # the culprit is another edge, or the named one with another: each other one alone
    # relaxed, then each beside the named ones left out, cheapest (object-level) first
    others = sorted((i for i in free if i not in named), key=lambda i: (order[i], i))
    base = {i: "skip" for i in named}
    steps += [{i: out_(i)} for i in others]
    if base:
        steps += [{**base, i: out_(i)} for i in others]
    if obj:
        steps.append({**base, **{i: soft(i) for i in obj}})
    if any(soft(i) == "loose" for i in part):
        steps.append({**{i: soft(i) for i in obj}, **{i: soft(i) for i in part}})
    if any(_layout(edges[i]) for i in free):
        steps.append({i: out_(i) for i in free})
    out: list[dict[int, str]] = []
    for st in steps:
        if st and st not in out:
            out.append(st)
    last = dict.fromkeys(free, "skip")  # every one left out: always tried, last
    # fewest relations relaxed first: every edge that can still be met is kept
    out = sorted((st for st in out if st != last), key=len)
    return out + ([last] if last else [])


def chase(pag: PAG, oid: str, step: dict[int, str], reason: str,
          done: frozenset[int] = frozenset()) -> dict[int, str] | None:
    """The step after ``step`` failed with ``reason``: ``step`` with the edges that reason
    names relaxed as well (a layout relation at its nearest positions, a contact left out,
    also one that was placed by the whole object), or None when it names no edge it could
    still relax."""
    edges = pag.edges_of(oid)
    new = dict(step)
    for i in _named_edges(pag, oid, reason):
        if i in done or RULES[edges[i].relation].relax_order is None:
            continue
        if i not in new:  # a layout relation at its nearest positions, a contact left out
            new[i] = "loose" if _layout(edges[i]) else "skip"
        elif new[i] == "loose" and not _layout(edges[i]):
            new[i] = "skip"
    return None if new == step else new


def _layout(e) -> bool:
    return RULES[e.relation].family == "layout"


def loosened(e):
    """What a relaxed edge is placed by instead: a layout relation by the free positions
    nearest its region (:func:`~.rules.layout.nearest`), a part-level contact by the whole
    object (:func:`~.intent.whole_object`)."""
    return nearest(e) if RULES[e.relation].family == "layout" else whole_object(e)


#: Placements tried when relaxing one object's relations (each with half the draws and two
#: assets, a quarter of a full placement; the last one leaves every non-support relation out).
MAX_RELAX_STEPS = 8


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
    proposals : dict of str to (R (3, 3), t (3,)) or (R, t, asset, scale), optional
        World poses tried first for these objects (then the usual sampling); with an asset and
        its scale, the first attempt places that asset at that scale.
    """
    from .library import default_library

    cfg = config or SolverConfig()
    library = library or default_library()
    t0 = time.perf_counter()
    shell = build_shell(pag.room, wall_thickness=cfg.wall_thickness)
    scene = Scene(pag, int(seed), shell, meta={"solver": cfg.to_dict()})
    world = CollisionWorld()
    for name, el in shell.elements.items():
        world.add(f"room:{name}", static_body(el.mesh_arrays))
    st = SolveState(pag, scene, world)
    srch = _Search(pag, seed, cfg, library, st)
    order = srch.order
    proposals = proposals or {}
    for n, oid in enumerate(order):
        sup = pag.supporter(oid)
        if deadline is not None and time.perf_counter() - t0 > deadline:
            srch.fail(oid, f"time limit: {deadline:g} s reached before it was placed")
        elif sup is not None and sup.parent.object in srch.failed:
            srch.fail(oid, f"its support {sup.parent.object!r} failed")
        else:
            try:
                prop = proposals.get(oid)
                keep = None
                if prop is not None and len(prop) == 4:
                    # a proposed asset and scale too: tried first with the proposed pose
                    R, t, asset, scale = prop
                    prop = (R, t)
                    keep = PlacedObject(oid, asset.category, asset, float(scale),
                                        np.asarray(R, float), np.asarray(t, float))
                srch.commit(srch.try_place(oid, f"object:{oid}", prop, keep))
            except Fail as f:
                srch.spent = 0
                try:
                    got = None if str(f).startswith(INTERNAL) else _recover(srch, oid, f)
                    reason = None if got is not None else srch.explain(oid, str(f))
                except Exception as e:  # noqa: BLE001 - one object's fault is its failure
                    reason = str(_internal(scene, oid, e))
                if reason is not None:
                    if oid in srch.placements:
                        srch.uncommit(oid)
                    srch.fail(oid, reason, cfg.max_trials * cfg.asset_attempts)
            except Exception as e:  # noqa: BLE001 - one object's fault is its failure
                if oid in srch.placements:
                    srch.uncommit(oid)
                srch.fail(oid, str(_internal(scene, oid, e)))
        if progress is not None:
            progress(SolveProgress(oid, scene.objects[oid].status, n + 1, len(order)))
    # keep the PAG's assembly order in scene.objects
    scene.objects = {oid: scene.objects[oid] for oid in assembly_order(pag)}
    scene.meta["search"] = {"backjumps": srch.backjumps,
                            "budget_left": srch.budget if cfg.search == "backtracking" else None}
    scene.timings["solve"] = time.perf_counter() - t0
    _finish(scene, srch)
    return scene


def _recover(srch: _Search, oid: str, f: Fail) -> Placement | None:
    """After ``oid`` failed with ``f``: re-place what conflicts (backjumping, larger moves),
    then relax its relations (``relax`` in the config); the placement or None."""
    # re-placing others cannot fix what the object's own geometry rules out
    got = srch.backjump(oid) if srch.budget > 0 and not f.intrinsic else None  # committed
    if got is None and srch.reserve > 0 and not f.intrinsic:
        got = srch.make_room(oid, str(f))
    if got is None and srch.cfg.relax:
        got = srch.relax(oid, srch.explain(oid, str(f)))
    return got


def _internal(scene: Scene, oid: str, e: Exception) -> Fail:
    """An exception while placing ``oid`` as its failure (``internal error: ...``); the
    traceback goes to the log (``parse3d.solver``) and ``scene.log``, the scene goes on."""
    tb = traceback.format_exc()
    log.error("internal error while placing %s\n%s", oid, tb)
    scene.log.append(f"internal error while placing {oid}\n{tb}")
    return Fail(f"{INTERNAL}{type(e).__name__}: {e}", intrinsic=True)


#: How the failure of an object whose placement raised an exception begins.
INTERNAL = "internal error: "


def _resolve_any_wall(scene: Scene, resolved: dict[str, dict]) -> None:
    """Record which wall a relation to ``wall`` (any wall) was met on: the first wall on which
    it holds for the solved pose. Without it a re-check (after settling) takes the wall nearest
    the child, which in a corner can be the other one (a lamp AGAINST a wall 10 cm off it,
    5 cm from the side wall)."""
    walls = [n for n in scene.room.elements if n.startswith("wall_")]
    for i, e in enumerate(scene.pag.relations):
        if e.parent.object != "wall" or str(i) in resolved:
            continue
        o = scene.objects.get(e.child.object)
        if o is None or not o.placed:
            continue
        for n in walls:
            r = {"parent_part": None, "parent_element": n, "parent_surface": None,
                 "internal": False}
            if check_edge(scene, e, o, resolved=r, settled=False)[0]:
                resolved[str(i)] = r
                break


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
        if p.obj.support_choice.owner in (edges[0].parent.object, "room"):
            # (not when it rests on another object than written: an apple beside a round one)
            resolved[str(srch.edge_index[id(edges[0])])] = resolution(
                edges[0], p.obj.support_choice, final=True)
    _resolve_any_wall(scene, resolved)
    scene.meta["resolved"] = resolved
    t1 = time.perf_counter()
    scene.relations = check_relations(scene, known=known)
    mark_unmet(scene)
    scene.timings["check"] = time.perf_counter() - t1
    scene.meta["trials"] = {o.id: o.trials for o in scene.objects.values()}


def mark_unmet(scene: Scene) -> None:
    """Relations of a placed child whose (non-support) parent failed: ``holds`` None and
    ``detail`` ``unmet: parent 'x' failed`` (after settling too); relaxed relations
    (``scene.meta["relaxed"]``) that do not hold when solved get ``relaxed`` (what blocked
    them and what to write instead), unless they hold after settling (the record states the
    final state)."""
    relaxed = scene.meta.get("relaxed") or {}
    for c in scene.relations:
        why = relaxed.get(str(c.index))
        if why is not None and c.holds is False:
            c.relaxed = {"blocked": why, "instead": _instead(scene.pag.relations[c.index], why)}
        if scene.settled and c.holds_settled is True:
            c.relaxed = None  # relaxed, and it holds after all: the record says what is
    for c in scene.relations:
        e = scene.pag.relations[c.index]
        child = scene.objects.get(e.child.object)
        parent = scene.objects.get(e.parent.object)
        if child is None or not child.placed or parent is None or parent.placed:
            continue
        c.holds, c.residual, c.detail = None, {}, f"unmet: parent {e.parent.object!r} failed"
        if scene.settled:
            c.holds_settled, c.residual_settled = None, None


_INSTEAD_RE = re.compile(r"\((write [^)]+)\)")
_SAY_RE = re.compile(r"\bname (\S+ or \S+?)(?:[;,)]|\s|$)")


def _instead(e, why: str) -> str:
    """What the writer could say instead of a relaxed relation: the reason's own advice
    (``name sofa:frame@back or sofa@back``), else a general one per relation family."""
    m = _SAY_RE.search(why)
    if m:
        return f"name {m.group(1)}"
    m = _INSTEAD_RE.search(why)
    if m:
        return m.group(1)
    if e.spec.kind == OBJECT:
        return (f"loosen or drop {e.relation} {e.child} -> {e.parent} (another side, a larger "
                f"distance or width), or give {e.child.object} more room")
    if e.child.part is not None:
        return (f"name {e.child.object}@{e.child.surface or e.spec.child_surface} (the whole "
                f"object) or drop the contact")
    return f"drop {e.relation} {e.child} -> {e.parent} or free room for it"


def wall_conflicts(scene: Scene, oid: str, *, seed: int, library=None,
                   config: SolverConfig | None = None) -> list[Window]:
    """The conflict set the search would use to make room for ``oid`` (an object of
    ``scene`` AGAINST, SECURED_TO or LEANING_AGAINST a wall) among the placed objects of
    ``scene``: the stretches of wall where it would fit once cleared, each with the objects
    standing there, cheapest to move first (see ``_Search.wall_windows``); empty for other
    objects."""
    from .library import default_library

    cfg = config or SolverConfig()
    srch = _Search(scene.pag, seed, cfg, library or default_library(), _state_of(scene, {oid}))
    srch.placements = {o.id: None for o in scene.objects.values() if o.placed and o.id != oid}
    return srch.wall_windows(oid)


def _state_of(scene: Scene, leave_out: set[str]) -> SolveState:
    """A solve state holding the room and the placed objects of ``scene`` but ``leave_out``."""
    world = CollisionWorld()
    for name, el in scene.room.elements.items():
        world.add(f"room:{name}", static_body(el.mesh_arrays))
    st = SolveState(scene.pag, scene, world)
    for o in scene.objects.values():
        if o.placed and o.id not in leave_out:
            st.add(o, cached_body(o.asset, o.scale,
                                  lambda o=o: scaled_mesh(o.asset, o.scale)))
    return st


def replace_objects(scene: Scene, ids: list[str], *, seed: int, round: int, library=None,
                    config: SolverConfig | None = None, new_asset: set[str] | None = None,
                    stop: Callable[[], bool] | None = None,
                    same_asset: set[str] | None = None) -> dict[str, str]:
    """Re-place ``ids`` (and what rests on them) in ``scene``, keeping every other object fixed.

    Each object draws from ``stage_rng(seed, "object:<id>:repair<round>")``; objects in
    ``new_asset`` skip the asset they had (another pool draw). Objects that cannot be placed
    again keep their old pose; so does every object whose attempts begin once ``stop()`` is
    true (the repair's time budget is spent). Objects in ``same_asset`` get only the attempts
    that keep their asset, and where they find no new pose, what rests on them keeps its pose
    too. Returns ``{id: "pose" | "asset"}`` for those re-placed.
    """
    from .library import default_library

    cfg = config or SolverConfig()
    library = library or default_library()
    pag = scene.pag
    todo: list[str] = []
    for oid in ids:
        for o in [oid, *support_descendants(pag, oid)]:
            if o not in todo and scene.objects[o].placed:
                todo.append(o)
    todo = [o for o in assembly_order(pag) if o in todo]
    st = _state_of(scene, set(todo))
    srch = _Search(pag, seed, cfg, library, st)
    srch.failed = {o.id: o.reason or "" for o in scene.objects.values() if not o.placed}
    done: dict[str, str] = {}
    new_asset = new_asset or set()
    kept: set[str] = set()  # of same_asset, those that keep their pose
    for oid in todo:
        old = scene.objects[oid]
        sup = pag.supporter(oid)
        # what rests on one of same_asset that keeps its pose keeps its own
        stays = oid not in ids and sup is not None and sup.parent.object in kept
        for attempt in range(4):
            if stays or (stop is not None and stop()):
                continue  # it keeps its pose (below)
            if attempt >= 2 and oid in (same_asset or ()):
                continue
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
            st.add(old, cached_body(old.asset, old.scale,
                                    lambda o=old: scaled_mesh(o.asset, o.scale)))
            if oid in (same_asset or ()) or stays:
                kept.add(oid)
    # fresh checks for what moved
    known: dict[int, tuple] = {}
    for oid, p in srch.placements.items():
        for e, r in zip(pag.edges_of(oid), p.checks, strict=False):
            if r is not None:
                known[srch.edge_index[id(e)]] = r
        sup = pag.edges_of(oid)[0]
        key = str(srch.edge_index[id(sup)])
        if p.obj.support_choice.owner in (sup.parent.object, "room"):
            scene.meta.setdefault("resolved", {})[key] = resolution(
                sup, p.obj.support_choice, final=True)
        else:  # resting on another object than written (an apple beside a round one)
            scene.meta.setdefault("resolved", {}).pop(key, None)
    return done
