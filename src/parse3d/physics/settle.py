"""Settling a solved scene under gravity in SAPIEN 3 (PhysX, CPU).

The paper (supplementary, "Scene Simulation Procedure") simulates every scene for 1000 steps
of 0.01 s with a linear damping of 0.05 and an angular damping of 0.5 on every object, using
convex collision pieces; those are the defaults of :class:`SettleConfig`.

Choices of this implementation (see ``docs/physics.md``):

- objects with ``fixed`` set (the solver sets it for ``SECURED_TO`` a wall and
  ``HANGING_BELOW`` something) are kinematic: they hold their pose and push, but are not
  pushed; real wall anchors and cords are not simulated;
- the run stops early once every dynamic body sleeps (checked after every step):
  PhysX does not move sleeping bodies and nothing can wake them (no kinematic body moves and
  no force is applied), so the remaining steps would not change any pose;
- PhysX runs on the calling thread (``cpu_workers=0``): one core per scene, deterministic.

After the run every object gets its settled pose and, in ``PlacedObject.flags``, what the
settled scene shows, with the definitions of :func:`parse3d.measure.verify_settled`: ``fell``
(dropped more than 5 cm and off what held it), ``tipped`` (its up axis tilted more than 15
degrees, its centre of mass 2 cm lower, not round), ``left_support`` (no part of it within the
contact threshold of any part of its supporter, the contacts' exact geometry, and its support
relation failing on the settled poses) and ``sank`` (a collision vertex ends more than the
contact tolerance below the floor).

The simulation runs in a local frame centred on the room (:func:`local_origin`): PhysX is
single precision, and a room 1 km from the origin must settle as it does at the origin.
Every PAG relation is re-checked on the settled poses.
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass, field
from typing import Any

import numpy as np

from ..scene.model import Scene
from .bodies import build_world
from .collision import ROOM

__all__ = ["SettleConfig", "ObjectMotion", "SettleReport", "settle", "local_origin",
           "PHYSICS_FLAGS"]

#: Flags that settling owns in ``PlacedObject.flags`` (replaced on every run).
PHYSICS_FLAGS = ("fell", "tipped", "left_support", "sank")
#: Depth (m) below the floor beyond which a settled object is flagged ``sank``.
SINK_TOLERANCE = 0.001


@dataclass(frozen=True)
class SettleConfig:
    """Parameters of a settling run (saved into ``scene.meta["settle"]``).

    Attributes
    ----------
    dt : float
        Time step, seconds (paper: 0.01).
    steps : int
        Steps to simulate at most (paper: 1000).
    linear_damping, angular_damping : float
        Per dynamic body (paper: 0.05 and 0.5).
    early_exit : bool
        Stop once every dynamic body sleeps.
    check_every : int
        Steps between checks for fallen bodies (``drop_out``); whether everything sleeps is
        checked after every step.
    sleep_threshold : float
        PhysX's mass-normalised kinetic energy below which a body may sleep.
    max_depenetration_velocity : float
        m/s; how fast PhysX may push interpenetrating bodies apart.
    solver_position_iterations, solver_velocity_iterations : int
    fall_distance : float
        A drop larger than this (m) flags ``fell``.
    tip_angle_deg : float
        A tilt of the up axis larger than this flags ``tipped``.
    contact_threshold : float
        Distance (m) within which an object still touches its supporter.
    free_joints : bool
        Let doors, drawers and lids move (objects with joints become articulations; their
        final joint values are written to ``PlacedObject.joints``). Default: joints locked,
        one rigid body per object.
    many_pieces, many_pieces_offset : int, float
        The contact offset (m) of the shapes of an object of at least ``many_pieces`` convex
        pieces (a vessel's wall segments: a saucer, a bowl, a jar); other shapes keep PhysX's
        default of 1 cm. Two shapes get contacts within the sum of their offsets, so a stack
        of four saucers made 12,000 contacts a step at the default and settled several times
        slower; at 4 mm only the pieces that nearly touch make contacts (at 3 mm glass jars
        standing on a shelf never came to sleep).
    drop_out : float
        An awake body whose origin has dropped more than this (m) at a sleep check, and that
        has landed (vertical speed under 5 cm/s), or that has dropped more than
        ``fall_distance`` and no longer goes down, has fallen for certain: it is frozen where it
        is (kinematic, so what rests on it stays held), and that pose is its settled one, so a bowl rolling about the floor does not keep the
        rest of the room simulating to the last step. 0 keeps every body to the end.
    """

    dt: float = 0.01
    steps: int = 1000
    linear_damping: float = 0.05
    angular_damping: float = 0.5
    early_exit: bool = True
    check_every: int = 10
    sleep_threshold: float = 0.005
    max_depenetration_velocity: float = 0.5
    solver_position_iterations: int = 10
    solver_velocity_iterations: int = 1
    fall_distance: float = 0.05
    tip_angle_deg: float = 15.0
    contact_threshold: float = 0.001
    free_joints: bool = False
    many_pieces: int = 40
    many_pieces_offset: float = 0.004
    drop_out: float = 0.25

    def __post_init__(self):
        import math

        if not (math.isfinite(self.dt) and 0 < self.dt <= 1.0) or self.steps < 0 \
                or self.check_every < 1:
            raise ValueError("dt must be in (0, 1] s, steps >= 0 and check_every >= 1")
        for name in ("linear_damping", "angular_damping", "contact_threshold", "fall_distance",
                     "tip_angle_deg", "sleep_threshold", "max_depenetration_velocity",
                     "drop_out", "many_pieces_offset"):
            v = float(getattr(self, name))
            if not (math.isfinite(v) and v >= 0):
                raise ValueError(f"{name} must be a finite number >= 0, got {v}")

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


@dataclass
class ObjectMotion:
    """How one object moved while settling.

    Attributes
    ----------
    id : str
    displacement : float
        Distance between the solved and settled asset origins, metres.
    drop : float
        Fall of the origin (positive = lower), metres.
    rotation_deg : float
        Angle of the rotation between the solved and settled orientations.
    tilt_deg : float
        Angle between the solved and settled up (+Z) axes.
    fixed : bool
        Held kinematic.
    flags : list of str
        Subset of :data:`PHYSICS_FLAGS`.
    """

    id: str
    displacement: float
    drop: float
    rotation_deg: float
    tilt_deg: float
    fixed: bool = False
    flags: list[str] = field(default_factory=list)

    def to_dict(self) -> dict[str, Any]:
        return {"id": self.id, "displacement": round(self.displacement, 6),
                "drop": round(self.drop, 6), "rotation_deg": round(self.rotation_deg, 4),
                "tilt_deg": round(self.tilt_deg, 4), "fixed": self.fixed, "flags": self.flags}


@dataclass
class SettleReport:
    """The outcome of :func:`settle`.

    Attributes
    ----------
    config : SettleConfig
    steps : int
        Steps actually simulated.
    early_exit : bool
        Whether the run stopped because everything slept.
    seconds : float
        Wall time of the whole call (building the world, stepping, measuring).
    build_seconds, step_seconds : float
        Building the PhysX world; stepping it.
    objects : dict of str to ObjectMotion
    relations_checked : bool
        Whether the PAG relations were re-checked on the settled poses.
    """

    config: SettleConfig
    steps: int
    early_exit: bool
    seconds: float
    build_seconds: float
    step_seconds: float
    objects: dict[str, ObjectMotion]
    relations_checked: bool = False

    def moved(self, *, distance: float = 0.01, angle_deg: float = 2.0) -> list[str]:
        """Ids of objects that moved more than ``distance`` (m) or rotated more than
        ``angle_deg``."""
        return [m.id for m in self.objects.values()
                if m.displacement > distance or m.rotation_deg > angle_deg]

    def flagged(self, flag: str) -> list[str]:
        return [m.id for m in self.objects.values() if flag in m.flags]

    def to_dict(self) -> dict[str, Any]:
        return {"config": self.config.to_dict(), "steps": self.steps,
                "early_exit": self.early_exit, "seconds": round(self.seconds, 4),
                "build_seconds": round(self.build_seconds, 4),
                "step_seconds": round(self.step_seconds, 4),
                "relations_checked": self.relations_checked,
                "objects": {k: v.to_dict() for k, v in self.objects.items()}}


def _angle_deg(R: np.ndarray) -> float:
    c = (np.trace(R) - 1.0) / 2.0
    return float(np.degrees(np.arccos(np.clip(c, -1.0, 1.0))))


def _support_key(support: str | None) -> tuple[str, str | None] | None:
    """``parent:part@surface`` -> ``(parent, part)``; ``floor``, ``room:floor`` ->
    ``("room", "floor")``; ``wall`` (any wall) -> ``("room", None)``."""
    if not support:
        return None
    ref = support.split("@", 1)[0]
    obj, _, part = ref.partition(":")
    part = part.split("#", 1)[0] or None
    if obj in ("floor", "ceiling") or obj.startswith("wall_"):
        return ROOM, obj
    if obj == "wall":
        return ROOM, None
    return obj, part


def _left_support(scene: Scene, ids: list[str], threshold: float) -> set[str]:
    """Objects among ``ids`` no longer within ``threshold`` of the part that supported them
    (exact convex distances between collision pieces)."""
    from .contacts import touching_parts

    wanted: dict[str, tuple[str, str | None]] = {}
    for oid in ids:
        key = _support_key(scene.objects[oid].support)
        if key is None:
            continue
        parent = key[0]
        if parent != ROOM and (parent not in scene.objects or not scene.objects[parent].placed):
            continue
        wanted[oid] = key
    if not wanted:
        return set()
    # any part of the supporting object (the contacts' pairs), the named element of the room
    key = {c: (p, part if p == ROOM else None) for c, (p, part) in wanted.items()}
    near = touching_parts(scene, [(c, p, part) for c, (p, part) in key.items()],
                          threshold=threshold, settled=True)
    return {c for c, (p, part) in key.items() if (c, p, part) not in near}


def _final_flags(scene: Scene, motions: dict, lost: set[str], cfg) -> None:
    """Make ``fell`` / ``tipped`` / ``left_support`` say what the settled scene shows, with the
    definitions of :func:`parse3d.measure.verify_settled`: an object turned in place is not
    ``tipped`` (its centre of mass no lower), nor is a round one (an apple rolls); one that
    dropped onto a lower part of what held it did not ``fall``; and ``left_support`` needs it
    touching no part of its supporter (the contacts' geometry) while its support relation
    fails on the settled poses (a pile, or a child resting on the next part of its support,
    still holds)."""
    from ..measure.stability import verify_settled

    holds = {c.index: c.holds_settled for c in scene.relations}
    index = {id(e): i for i, e in enumerate(scene.pag.relations)}
    for oid in lost:
        e = scene.pag.supporter(oid)
        if e is not None and holds.get(index[id(e)]) is True:
            motions[oid].flags.remove("left_support")
            scene.objects[oid].flags.remove("left_support")
    causes: dict[str, set[str]] = {}
    for bad in verify_settled(scene, fall_distance=cfg.fall_distance,
                              tip_angle_deg=cfg.tip_angle_deg):
        causes.setdefault(bad.object_id, set()).add(bad.cause)
    for oid, m in motions.items():
        got = causes.get(oid, set())
        m.flags = [f for f in ("fell", "tipped") if f in got] + \
            [f for f in m.flags if f not in ("fell", "tipped")]
        o = scene.objects[oid]
        o.flags = [f for f in o.flags if f not in PHYSICS_FLAGS] + m.flags


def _recheck_relations(scene: Scene) -> bool:
    """Re-check every PAG relation on the settled poses (``holds_settled``/``residual_settled``)."""
    if not scene.pag.relations:
        return False
    from ..measure.checks import check_relations

    checks = check_relations(scene, settled=True)
    have = {c.index for c in scene.relations}
    for c in checks:
        if c.index not in have:
            scene.relations.append(c)
    scene.relations.sort(key=lambda c: c.index)
    return True


def _floor_sink(obj) -> float:
    """How far (m) the lowest collision vertex of a settled object lies below the floor."""
    from .collision import asset_collision

    if obj.asset is None or obj.settled_position is None:
        return 0.0
    data = asset_collision(obj.asset)
    if not len(data.pieces):
        return 0.0
    v = np.asarray(data.pieces.vertices, float) * float(obj.scale)
    z = v @ np.asarray(obj.settled_rotation, float)[2] + float(obj.settled_position[2])
    return float(max(0.0, -z.min()))


def local_origin(scene: Scene) -> np.ndarray:
    """Origin of the local frame a scene is simulated in: the centre of the footprint's
    bounding box, on the floor ((3,) float, metres, world frame).

    PhysX stores poses and collision vertices in float32 (about 0.1 mm of resolution 1 km
    from the origin); simulating near the origin makes a room settle the same wherever it is.
    """
    fp = np.asarray(scene.room.footprint, np.float64)
    c = 0.5 * (fp.min(axis=0) + fp.max(axis=0))
    return np.array([c[0], c[1], 0.0])


def _drop_out(world, dyn: dict, start_z: dict[str, float], heights: dict[str, list[float]],
              cfg: SettleConfig, gone: dict[str, tuple[np.ndarray, np.ndarray]]) -> None:
    """Freeze where it is (kinematic: what rests on it stays held) every awake body of ``dyn``
    that has fallen for certain: dropped more than ``cfg.drop_out`` and landed (vertical speed
    under 5 cm/s), or dropped more than ``cfg.fall_distance`` and no longer going down (its
    height within 1 mm over the last :data:`STILL_CHECKS` checks: a can rolling about the shelf
    it fell to). Its pose goes into ``gone`` and it leaves ``dyn``."""
    oz = float(world.origin[2])
    for oid in [i for i, b in dyn.items() if not b.is_sleeping]:
        z = float(world.entities[oid].get_pose().p[2]) + oz  # the height alone, as pose() has it
        h = heights.setdefault(oid, [])
        h.append(z)
        del h[:-STILL_CHECKS]
        drop = start_z[oid] - z
        landed = drop > cfg.drop_out and abs(float(dyn[oid].get_linear_velocity()[2])) < 0.05
        rolling = drop > cfg.fall_distance and len(h) == STILL_CHECKS and max(h) - min(h) < 1e-3
        if landed or rolling:
            gone[oid] = world.pose(oid)
            body = dyn.pop(oid)
            body.set_linear_velocity(np.zeros(3, np.float32))
            body.set_angular_velocity(np.zeros(3, np.float32))
            body.set_kinematic(True)


#: Sleep checks over which a fallen body's height must stay within 1 mm to be frozen.
STILL_CHECKS = 6


def settle_world(scene: Scene, cfg: SettleConfig):
    """The PhysX world :func:`settle` simulates ``scene`` in with ``cfg``'s parameters (in the
    room's local frame, :func:`local_origin`)."""
    return build_world(scene, timestep=cfg.dt, linear_damping=cfg.linear_damping,
                       angular_damping=cfg.angular_damping,
                       max_depenetration_velocity=cfg.max_depenetration_velocity,
                       sleep_threshold=cfg.sleep_threshold,
                       solver_position_iterations=cfg.solver_position_iterations,
                       solver_velocity_iterations=cfg.solver_velocity_iterations,
                       origin=local_origin(scene), free_joints=cfg.free_joints,
                       many_pieces=(cfg.many_pieces, cfg.many_pieces_offset))


def settle(scene: Scene, *, config: SettleConfig | None = None, dt: float | None = None,
           steps: int | None = None, linear_damping: float | None = None,
           angular_damping: float | None = None) -> SettleReport:
    """Simulate ``scene`` under gravity and write the settled poses into it.

    Parameters
    ----------
    scene : Scene
        Modified in place: ``settled_rotation``/``settled_position`` and physics flags of every
        placed object, ``joints`` of articulated ones with ``free_joints``, ``holds_settled``/``residual_settled`` of every relation,
        ``settled = True``, ``timings["settle"]`` and ``meta["settle"]`` (config and summary).
    config : SettleConfig, optional
        All parameters (defaults: the paper's).
    dt, steps, linear_damping, angular_damping : optional
        Override the paper's four parameters of ``config``.

    Returns
    -------
    SettleReport
    """
    from dataclasses import replace

    cfg = config or SettleConfig()
    over = {k: v for k, v in (("dt", dt), ("steps", steps), ("linear_damping", linear_damping),
                              ("angular_damping", angular_damping)) if v is not None}
    if over:
        cfg = replace(cfg, **over)
    t0 = time.perf_counter()
    world = settle_world(scene, cfg)
    t1 = time.perf_counter()
    dyn = {i: world.bodies[i] for i in world.dynamic}
    start_z = {i: float(scene.objects[i].position[2]) for i in dyn}
    gone: dict[str, tuple[np.ndarray, np.ndarray]] = {}  # dropped out: pose when frozen
    heights: dict[str, list[float]] = {}
    n = 0
    early = False
    step = world.sapien_scene.step
    awake = None  # the body found awake at the last sleep check (checked first: one call)
    while n < cfg.steps:
        step()
        n += 1
        if cfg.drop_out > 0 and (n % cfg.check_every == 0 or n == cfg.steps):
            _drop_out(world, dyn, start_z, heights, cfg, gone)
        if cfg.early_exit and n < cfg.steps and (n % cfg.check_every == 0
                                                 or awake is None or awake.is_sleeping):
            awake = next((b for b in dyn.values() if not b.is_sleeping), None)
            if awake is None and all(a.sleeping for a in world.articulations.values()):
                early = True
                break
    t2 = time.perf_counter()

    for oid, art in world.articulations.items():  # free joints: where they came to rest
        stored = scene.objects[oid].joints
        for name, v in art.values().items():  # joints at rest where they started: unlisted
            if name in stored or abs(v) > 1e-4:
                stored[name] = round(v, 6)
    motions: dict[str, ObjectMotion] = {}
    for oid in world.entities:
        if oid == ROOM:
            continue
        obj = scene.objects[oid]
        R, t = gone[oid] if oid in gone else world.pose(oid)
        if obj.fixed:  # kinematic: exactly where the solver put it
            R, t = np.array(obj.rotation, float), np.array(obj.position, float)
        obj.settled_rotation, obj.settled_position = R, t
        dR = R @ np.asarray(obj.rotation).T
        tilt = float(np.degrees(np.arccos(np.clip(R[:, 2] @ np.asarray(obj.rotation)[:, 2], -1, 1))))
        m = ObjectMotion(oid, float(np.linalg.norm(t - obj.position)),
                         float(obj.position[2] - t[2]), _angle_deg(dR), tilt, obj.fixed)
        if m.drop > cfg.fall_distance:
            m.flags.append("fell")
        if m.tilt_deg > cfg.tip_angle_deg:
            m.flags.append("tipped")
        if not obj.fixed and _floor_sink(obj) > max(cfg.contact_threshold, SINK_TOLERANCE):
            m.flags.append("sank")
        motions[oid] = m
    lost = _left_support(scene, [k for k, m in motions.items() if not m.fixed],
                         cfg.contact_threshold)
    for oid in lost:
        motions[oid].flags.append("left_support")
    for oid, m in motions.items():
        o = scene.objects[oid]
        o.flags = [f for f in o.flags if f not in PHYSICS_FLAGS] + m.flags
    scene.settled = True
    checked = _recheck_relations(scene)
    _final_flags(scene, motions, lost, cfg)
    t3 = time.perf_counter()
    report = SettleReport(cfg, n, early, t3 - t0, t1 - t0, t2 - t1, motions, checked)
    scene.timings["settle"] = round(t3 - t0, 4)
    scene.meta["settle"] = {"config": cfg.to_dict(), "steps": n, "early_exit": early,
                            "moved": report.moved(), "fell": report.flagged("fell"),
                            "tipped": report.flagged("tipped"),
                            "left_support": report.flagged("left_support"),
                            "dropped_out": sorted(gone)}
    return report
