"""The whole per-scene pipeline: solve, settle, verify and repair, extract contacts, write,
preview.

Used by ``parse3d solve``, ``parse3d generate``, ``parse3d demo`` and the dataset builder, so
they all produce the same files (DESIGN §5).

After settling, objects that fell, tipped or left their support, or whose support relation no
longer holds, are re-placed with the rest of the scene fixed (round 1: another pose; later
rounds: another asset) and the scene is settled again, up to ``repair_rounds`` rounds. An
object still fallen, tipped or off its support after the last round becomes ``failed``
("unstable after N repairs"), with everything resting on it. Objects that rest as meant but
turned (:func:`parse3d.measure.stability.settled_rest`) with their support relation failing are
re-placed too, and go back to where they rested if that leaves them unstable: a repair never
makes a stable object fail. A flat object that fell over onto what held it up and that another
pose does not make stand keeps the rest it fell into (:func:`keep_rest`), the relations it
broke recorded relaxed; what that rest then unsettles, or what was placed against the pose it
left (a book leaning on it), is placed once more against the rest before it can fail.
"""

from __future__ import annotations

import copy
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .measure.checks import check_relations
from .measure.stability import lies_flat, verify_settled
from .pag.model import PAG
from .scene.model import Repair, Scene
from .solver import SolverConfig, solve
from .solver.search import mark_unmet, replace_objects, support_descendants

__all__ = ["PipelineOptions", "run_pipeline", "settle_and_repair", "write_outputs", "unstable_objects",
           "UNSTABLE_FLAGS", "REPAIR_BUDGET", "keep_rest"]

#: Physics flags that may make an object unstable (set by settling; whether it is, is decided by
#: :func:`parse3d.measure.verify_settled`).
UNSTABLE_FLAGS = ("fell", "tipped", "left_support")


#: CPU seconds of this process after which no further repair round is started (the first
#: settling and a round under way always finish): a scene whose repairs keep failing costs at
#: most about this much more than one that needs none. CPU time, not wall time, so that a busy
#: machine does not cut the repairs short and change the scene (settling is single-threaded:
#: on an idle machine the two agree).
REPAIR_BUDGET = 4.0


@dataclass(frozen=True)
class PipelineOptions:
    """What to run after solving.

    Attributes
    ----------
    settle : bool
        Settle in SAPIEN and extract the part-level contact graph.
    preview : bool
        Render ``preview.png``.
    solver : SolverConfig
    formats : tuple of str
        Export formats written next to ``scene.json`` (names of ``parse3d.export.FORMATS``).
    repair_rounds : int
        Settle-verify-repair rounds after the first settling (0: no repair).
    time_limit : float or None
        Seconds the solver may spend before unplaced objects fail with ``time limit``.
    repair_budget : float or None
        CPU seconds after which no further repair round starts (:func:`settle_and_repair`).
    """

    settle: bool = True
    preview: bool = True
    solver: SolverConfig = SolverConfig()
    formats: tuple[str, ...] = ("glb",)
    repair_rounds: int = 3
    time_limit: float | None = None
    repair_budget: float | None = REPAIR_BUDGET


def unstable_objects(scene: Scene, *, relations: bool = True) -> dict[str, str]:
    """``{id: cause}`` of settled, placed, dynamic objects that are unstable, by the one
    definition of :func:`parse3d.measure.verify_settled` (fell, tipped, left_support), and (with
    ``relations``) of those whose support relation no longer holds (cause ``support
    relation``, the name ``scene.json`` records for ``broke_support``).

    Per object the first cause found in the order fell, left_support, tipped, support relation.
    """
    rank = {c: k for k, c in enumerate(("fell", "left_support", "tipped", "broke_support"))}
    out: dict[str, str] = {}
    for i in sorted(verify_settled(scene), key=lambda i: rank[i.cause]):
        if i.object_id in out or (i.cause == "broke_support" and not relations):
            continue
        out[i.object_id] = "support relation" if i.cause == "broke_support" else i.cause
    if relations:
        out.update(dict.fromkeys(_turned_at_rest(scene, out), "support relation"))
    return out


def _turned_at_rest(scene: Scene, skip) -> list[str]:
    """Placed dynamic objects not in ``skip`` that rest as meant after turning in settling
    (:func:`parse3d.measure.stability.settled_rest`: a content on a pile in its container, a
    slumped leaner) while their support relation, met when solved, fails on the settled poses:
    worth another pose, not a failure."""
    from .measure.stability import settled_rest

    checks = {c.index: c for c in scene.relations}
    index = {id(e): i for i, e in enumerate(scene.pag.relations)}
    out = []
    for oid, o in scene.objects.items():
        e = scene.pag.supporter(oid)
        if oid in skip or e is None or not o.placed or o.fixed or o.settled_position is None:
            continue
        c = checks.get(index[id(e)])
        if c is not None and c.holds is True and c.holds_settled is False \
                and settled_rest(scene, o) is not None:
            out.append(oid)
    return out


def _support_key(scene: Scene, oid: str) -> str:
    """The key of ``oid``'s support relation in ``scene.meta["resolved"]`` (its PAG index)."""
    e = scene.pag.supporter(oid)
    return str(next(i for i, r in enumerate(scene.pag.relations) if r is e))


def _pose_of(obj) -> tuple:
    """``(asset id, position, rotation)`` of a placed object (None for a failed one)."""
    if not obj.placed or obj.asset is None:
        return (None, None, None)
    return (obj.asset.asset_id, np.array(obj.position, float), np.array(obj.rotation, float))


def _same_pose(a: tuple, b: tuple) -> bool:
    """Whether two :func:`_pose_of` are one pose: the same asset within 0.1 mm and 0.01."""
    if a[0] is None or a[0] != b[0]:
        return False
    return bool(np.abs(a[1] - b[1]).max() <= 1e-4 and np.abs(a[2] - b[2]).max() <= 1e-2)


def _settle(scene: Scene) -> None:
    from .physics import settle

    for o in scene.objects.values():
        o.settled_rotation = o.settled_position = None
    scene.settled = False
    settle(scene)


def _replace(scene: Scene, ids: list[str], *, unstable: set[str], **kw) -> dict[str, str]:
    """:func:`parse3d.solver.search.replace_objects` for ``ids``, and for those of ``unstable``
    (fallen, tipped, off their support) it finds no new pose for, again against the solved poses
    of the rest alone (one that stands, re-posed for its relation only, keeps its pose).

    The first try sees the rest of the scene partly where it came to rest (a support's top and
    outline from its settled pose) and partly as solved (its collision body): a stack re-placed on
    where its base settled rests better. But a base that slid in settling (a coaster 2 cm under a
    heavy glass) then overlaps its own collision body wherever the child is tried, and the child
    would fail "unstable after N repairs" without another pose ever being tried. Settling starts
    again from the solved poses, so a pose that fits those is a real one. The settled poses are
    put back on the objects that kept their pose (or were placed again exactly where they were);
    one placed anew has none until settled.
    """
    done = replace_objects(scene, ids, **kw)
    left = [oid for oid in ids if oid not in done and oid in unstable
            and scene.objects[oid].placed]
    if not left:
        return done
    held = {oid: (o, o.settled_rotation, o.settled_position) for oid, o in scene.objects.items()
            if o.settled_position is not None}
    for o, _, _ in held.values():
        o.settled_rotation = o.settled_position = None
    try:
        done.update(replace_objects(scene, left, **kw))
    finally:
        for oid, (o, R, t) in held.items():
            now = scene.objects.get(oid)
            if now is o or (now is not None and _same_pose(_pose_of(o), _pose_of(now))):
                now.settled_rotation, now.settled_position = R, t
    return done


def _resettle(scene: Scene) -> None:
    """Check the relations on the poses as they are now, mark the unmet, and settle again."""
    scene.relations = []
    scene.relations = check_relations(scene)
    mark_unmet(scene)
    _settle(scene)


def _restore(scene: Scene, oid: str, old, res) -> None:
    """Put back ``old``, the record of ``oid`` before a repair (keeping the repairs and flags it
    gathered since), and the support it was resolved on (``res``, None for none)."""
    now = scene.objects[oid]
    old.repairs, old.flags = list(now.repairs), list(now.flags)
    scene.objects[oid] = old
    key = _support_key(scene, oid)
    if res is not None:  # the support it was solved on, as it was
        scene.meta.setdefault("resolved", {})[key] = res
    else:
        scene.meta.get("resolved", {}).pop(key, None)


def settle_and_repair(scene: Scene, *, rounds: int = 3, library=None,
                      config: SolverConfig | None = None,
                      budget: float | None = REPAIR_BUDGET) -> dict[str, int]:
    """Settle ``scene``, then re-place what is unstable and settle again, up to ``rounds``,
    starting no round once ``budget`` CPU seconds of this process have passed since the start
    (None: no bound).

    Returns ``{"repaired": n, "unrepaired": m}``: objects repaired into a stable pose, and
    objects that became ``failed`` because they were still unstable, plus ``"kept": k`` when k
    objects re-placed only for their support relation went back to their earlier pose
    (``scene.meta["repair"]`` also says ``"budget": true`` when the budget stopped the rounds).
    """
    cfg = config or SolverConfig()
    t0 = time.process_time()
    over = False
    _settle(scene)
    touched: set[str] = set()
    # objects re-posed while stable (and what rests on them): PlacedObject and resolved support
    # before that round
    before: dict[str, tuple] = {}
    before_of: dict[str, None] = {}  # those objects themselves (not what rests on them)
    still: dict[str, str] | None = None  # unstable_objects(relations=False) as settled now
    # objects that fell over flat onto what held them up: cause and, per object (with what
    # rests on it), PlacedObject and resolved support as they lay then
    rests: dict[str, tuple[str, dict[str, tuple]]] = {}
    for rnd in range(1, rounds + 1):
        # a broken support relation on a stable object gets one new pose (round 1), no more;
        # one resting as meant, turned (a content, a slumped leaner), is tried every round
        bad = unstable_objects(scene, relations=rnd == 1)
        real = {k: v for k, v in bad.items() if v != "support relation"}
        if rnd > 1:
            bad.update(dict.fromkeys(_turned_at_rest(scene, bad), "support relation"))
        still = real
        for oid in real:  # the first flat rest seen, to keep should the repairs not do better
            if oid not in rests and lies_flat(scene, scene.objects[oid]):
                rests[oid] = (real[oid], {d: (copy.deepcopy(scene.objects[d]),
                                              copy.deepcopy(scene.meta.get("resolved", {}).get(
                                                  _support_key(scene, d))))
                                          for d in [oid, *support_descendants(scene.pag, oid)]
                                          if scene.objects[d].placed})
        if rnd > 1:  # another pose did not stand either: the flat rest is kept, not another asset
            bad = {k: v for k, v in bad.items() if k not in rests}
        if not bad:
            break
        if budget is not None and time.process_time() - t0 > budget:
            over = True
            break
        action = "pose" if rnd == 1 else "asset"
        # stable, re-posed only for their relation: their pose before, to go back to
        for oid in set(bad) - set(real):
            before_of.setdefault(oid, None)
            for d in [oid, *support_descendants(scene.pag, oid)]:
                if d not in before:
                    key = _support_key(scene, d)
                    before[d] = (copy.deepcopy(scene.objects[d]),
                                 copy.deepcopy(scene.meta.get("resolved", {}).get(key)))
        was = {oid: _pose_of(scene.objects[oid]) for oid in bad}
        done = _replace(scene, list(bad), unstable=set(real), seed=scene.seed, round=rnd,
                        library=library, config=cfg, new_asset=set(bad) if action == "asset" else None,
                        same_asset=set(bad) - set(real) if action == "pose" else None,
                        stop=None if budget is None else lambda: time.process_time() - t0 > budget)
        over = over or (budget is not None and time.process_time() - t0 > budget)
        # placed again exactly where it was (the only pose its relations leave): not a change
        done = {k: v for k, v in done.items()
                if k not in was or not _same_pose(was[k], _pose_of(scene.objects[k]))}
        for oid, cause in bad.items():
            o = scene.objects[oid]
            o.repairs.append(Repair(rnd, cause, done.get(oid, action)))
            touched.add(oid)
        if not done:
            # nothing could be placed anew: every pose is what was settled, and settling the
            # same poses again (deterministic) would give the same scene
            continue
        _resettle(scene)
        still = None
    if still is None:
        still = unstable_objects(scene, relations=False)
    # a repair never makes a stable object fail: one re-posed for its relation alone that is
    # unstable now goes back to where it was (with what rests on it) and the scene settles again
    back = [oid for oid in before_of if oid in still and scene.objects[oid].placed]
    if back:
        for oid in back:
            for d in [oid, *support_descendants(scene.pag, oid)]:
                if d in before and scene.objects[d].placed:
                    _restore(scene, d, *before[d])
        _resettle(scene)
        still = unstable_objects(scene, relations=False)
        touched.update(back)
    # a flat object that fell over onto what held it up (a plate stood on its rim, a frame with
    # no stand) keeps the rest it came to rather than failing: the relations it broke are
    # recorded relaxed, saying so
    flat = [oid for oid in scene.objects if oid in still and oid in rests]
    if flat:
        for oid in flat:
            for d, (old, res) in rests[oid][1].items():
                _restore(scene, d, old, res)
        keep_rest(scene, {oid: rests[oid][0] for oid in flat})
        _settle(scene)
        was, still = still, unstable_objects(scene, relations=False)
        touched.update(flat)
        # what the rests unsettled or left placed against a pose that is gone (a book leaning on
        # the one that now lies where it fell) is placed once more against them, not failed
        kept = {d for oid in flat for d in rests[oid][1]}
        near = {e.child.object for e in scene.pag.relations if e.parent.object in kept}
        moved = [oid for oid in still if oid not in kept and scene.objects[oid].placed
                 and (oid not in was or oid in near)]
        if moved:
            done = _replace(scene, moved, unstable=set(moved), seed=scene.seed,
                            round=rounds + 1, library=library, config=cfg)
            for oid in moved:
                scene.objects[oid].repairs.append(
                    Repair(len(scene.objects[oid].repairs) + 1, still[oid], done.get(oid, "pose")))
            if done:
                _resettle(scene)
                still = unstable_objects(scene, relations=False)
            touched.update(moved)
    for oid in [o for o in scene.objects if o in still]:  # assembly order: supports first
        o = scene.objects[oid]
        if not o.placed:
            continue  # failed with its support already
        o.status, o.reason = "failed", f"unstable after {len(o.repairs)} repairs ({still[oid]})"
        for d in support_descendants(scene.pag, oid):
            if scene.objects[d].placed:
                scene.objects[d].status = "failed"
                scene.objects[d].reason = f"its support {oid!r} failed (unstable after " \
                                          f"{len(o.repairs)} repairs)"
    if still:
        scene.relations = []
        scene.relations = check_relations(scene)
        check_relations(scene, settled=True)
    mark_unmet(scene)  # settling re-checked them as failing
    stats = {"repaired": len(touched - set(still)), "unrepaired": len(still)}
    if back:
        stats["kept"] = len(back)
    if flat:
        stats["rested"] = len([oid for oid in flat if oid not in still])
    scene.meta["repair"] = dict(stats, budget=True) if over else stats
    return stats


def keep_rest(scene: Scene, causes: dict[str, str]) -> None:
    """Make where the settled objects ``causes`` (``{id: cause}``) came to rest their pose, with
    what rests on them: each gets a repair ``rest``, and every relation of theirs (as child or
    parent) that held when solved and fails on the new pose is recorded relaxed (what blocked
    it: the fall). The caller settles the scene again."""
    held = {c.index for c in scene.relations if c.holds is True}
    moved: dict[str, str] = {}
    for oid, cause in causes.items():
        for d in [oid, *support_descendants(scene.pag, oid)]:
            o = scene.objects[d]
            if d in moved or not o.placed or o.settled_position is None:
                continue
            o.position = np.array(o.settled_position, float)
            o.rotation = np.array(o.settled_rotation, float)
            moved[d] = oid
        o = scene.objects[oid]
        o.repairs.append(Repair(len(o.repairs) + 1, cause, "rest"))
    scene.relations = []
    scene.relations = check_relations(scene)
    relaxed = scene.meta.setdefault("relaxed", {})
    for c in scene.relations:
        e = scene.pag.relations[c.index]
        who = moved.get(e.child.object) or moved.get(e.parent.object)
        if who is None or c.holds is not False or c.index not in held or str(c.index) in relaxed:
            continue
        o = scene.objects[who]
        relaxed[str(c.index)] = (
            f"{who} {causes[who]} in settling as placed, again after {len(o.repairs) - 1} "
            f"repair(s), and {lies_flat(scene, o) or 'rests where it fell'} (write a LEANING_AGAINST "
            f"that holds {who} up, or let it lie flat)")
    mark_unmet(scene)


def run_pipeline(pag: PAG, *, seed: int, out: str | Path | None,
                 options: PipelineOptions = PipelineOptions(), library=None,
                 progress: Callable | None = None) -> Scene:
    """Solve ``pag`` and, per ``options``, settle and repair, extract contacts, write and
    preview.

    Returns the scene; ``scene.ok`` tells whether every object was placed (and, when settled,
    stayed stable).
    """
    scene = solve(pag, seed=seed, config=options.solver, library=library, progress=progress,
                  deadline=options.time_limit)
    if options.settle and scene.placed:
        from .physics import extract_contacts

        t, c = time.perf_counter(), time.process_time()
        settle_and_repair(scene, rounds=options.repair_rounds, library=library,
                          config=options.solver, budget=options.repair_budget)
        scene.timings["settle"] = time.perf_counter() - t
        # CPU seconds too: settling is single-threaded, and on a busy machine wall time is not
        # what the repairs cost
        scene.timings["settle_cpu"] = time.process_time() - c
        t = time.perf_counter()
        scene.contacts = extract_contacts(scene)
        scene.timings["contacts"] = time.perf_counter() - t
    if out is not None:
        write_outputs(scene, out, options.formats, preview=options.preview)
    return scene


def write_outputs(scene: Scene, out: str | Path, formats: tuple[str, ...] = ("glb",), *,
                  preview: bool = False) -> Path:
    """Write ``scene.json`` (and ``contacts.json``), the export ``formats`` and, with
    ``preview``, ``preview.png`` into ``out`` (:meth:`Scene.save` is the public door).

    The exports carry the friction table settling used, so simulators see the same contacts.
    Returns the path of ``scene.json``.
    """
    from .export import ExportOptions, export_scene
    from .physics.mujoco import settling_friction
    from .scene.io import write_scene

    path = write_scene(scene, out)
    export_scene(scene, out, formats, ExportOptions(friction=settling_friction()))
    if preview:
        from .render import save_preview

        t = time.perf_counter()
        save_preview(scene, Path(out) / "preview.png")
        scene.timings["preview"] = time.perf_counter() - t
        write_scene(scene, out)  # with the preview's time
    return path
