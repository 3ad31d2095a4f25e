"""SAPIEN 3 (PhysX, CPU) bodies for a scene.

Every placed object becomes one SAPIEN entity with a rigid body and one convex-mesh collision
shape per convex piece of its parts (the shapes are scaled by the object's uniform scale). Mass
and inertia come from PhysX integrating the collision volume at the category's density; friction
and restitution come from the part's material family (:data:`MATERIALS`). Objects marked
``fixed`` (wall-mounted and hanging items) are kinematic; the room shell (floor, walls, ceiling,
in convex pieces) is static.

Every shape is remembered with its owner: :attr:`PhysxWorld.shape_owner` maps ``id(shape)`` to
``(object id, part name)`` so the engine's contact reports can be read at part level.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..errors import DependencyError
from ..geometry.frames import matrix_to_quat
from ..scene.model import Scene
from .collision import ROOM, ConvexSet, asset_collision, shell_collision

__all__ = ["MaterialPhysics", "MATERIALS", "SHELL_MATERIAL", "PhysxWorld", "build_world",
           "import_sapien"]


@dataclass(frozen=True)
class MaterialPhysics:
    """Contact properties of a material family (PhysX averages them over a contact pair)."""

    static_friction: float
    dynamic_friction: float
    restitution: float


#: Friction and restitution per ``Material.name``; unknown families use ``plastic``.
MATERIALS: dict[str, MaterialPhysics] = {
    "wood": MaterialPhysics(0.55, 0.45, 0.10),
    "metal": MaterialPhysics(0.45, 0.35, 0.15),
    "fabric": MaterialPhysics(0.80, 0.70, 0.02),
    "ceramic": MaterialPhysics(0.50, 0.40, 0.10),
    "glass": MaterialPhysics(0.45, 0.35, 0.10),
    "plastic": MaterialPhysics(0.50, 0.40, 0.10),
    "paper": MaterialPhysics(0.55, 0.45, 0.02),
    "stone": MaterialPhysics(0.60, 0.50, 0.05),
    "plant": MaterialPhysics(0.60, 0.50, 0.02),
    "food": MaterialPhysics(0.60, 0.50, 0.02),
    "leather": MaterialPhysics(0.70, 0.60, 0.02),
}

#: Floor, walls and ceiling.
SHELL_MATERIAL = MaterialPhysics(0.60, 0.50, 0.05)


def material_physics(name: str) -> MaterialPhysics:
    """The contact properties of a material family (``plastic`` when unknown)."""
    return MATERIALS.get(name, MATERIALS["plastic"])


def import_sapien():
    """Import SAPIEN, or raise :class:`DependencyError` naming the package."""
    import warnings

    try:
        with warnings.catch_warnings():
            # SAPIEN warns when it falls back to its bundled Vulkan loader; physics needs none
            warnings.filterwarnings("ignore", message=".*libvulkan.*")
            import sapien
    except ImportError as e:  # pragma: no cover - sapien is a declared dependency
        raise DependencyError("settling needs SAPIEN 3: pip install 'parse3d[physics]'") from e
    return sapien


@dataclass
class PhysxWorld:
    """A SAPIEN scene built from a :class:`Scene`.

    Attributes
    ----------
    sapien_scene : sapien.Scene
    system : sapien.physx.PhysxCpuSystem
    entities : dict of str to sapien.Entity
        Per object id.
    bodies : dict of str to PhysxRigidDynamicComponent
        Per object id (kinematic for fixed objects).
    dynamic : list of str
        Ids of the simulated (non-kinematic) objects.
    shape_owner : dict of int to (str, str)
        ``id(shape)`` -> ``(object id or "room", part name)``.
    shapes : list
        Every collision shape (keeps the Python objects, and so their ids, alive).
    """

    sapien_scene: object
    system: object
    entities: dict[str, object] = field(default_factory=dict)
    bodies: dict[str, object] = field(default_factory=dict)
    dynamic: list[str] = field(default_factory=list)
    shape_owner: dict[int, tuple[str, str]] = field(default_factory=dict)
    shapes: list = field(default_factory=list)
    origin: np.ndarray = field(default_factory=lambda: np.zeros(3))
    #: Objects simulated as articulations (``free_joints``), by id: see
    #: :class:`parse3d.physics.articulation.ArticulatedObject`.
    articulations: dict[str, object] = field(default_factory=dict)

    def pose(self, object_id: str) -> tuple[np.ndarray, np.ndarray]:
        """World ``(R (3, 3), t (3,))`` of an object's asset frame now (the simulation runs in
        a local frame at ``origin``; this adds it back, in float64)."""
        from ..geometry.frames import quat_to_matrix

        p = self.entities[object_id].get_pose()
        return quat_to_matrix(np.asarray(p.q, float)), np.asarray(p.p, float) + self.origin

    def owner(self, shape) -> tuple[str, str] | None:
        """``(object id, part name)`` of a collision shape, None for an unknown shape."""
        return self.shape_owner.get(id(shape))


def _shapes(physx, pieces: ConvexSet, materials: list, scale: float, density: float | None,
            offset: np.ndarray | None = None):
    out = []
    for i in range(len(pieces)):
        v = np.asarray(pieces.piece_vertices(i), np.float64)
        if offset is not None:
            v = v - offset  # in float64, before PhysX's float32
        v = np.ascontiguousarray(v, np.float32)
        sh = physx.PhysxCollisionShapeConvexMesh(vertices=v, scale=[scale] * 3,
                                                 material=materials[i])
        if density is not None:
            sh.set_density(density)
        out.append(sh)
    return out


def build_world(scene: Scene, *, timestep: float, linear_damping: float, angular_damping: float,
                max_depenetration_velocity: float, sleep_threshold: float,
                solver_position_iterations: int, solver_velocity_iterations: int,
                settled: bool = False, origin: np.ndarray | None = None,
                free_joints: bool = False, contact_offset: float = 0.01,
                many_pieces: tuple[int, float] | None = None) -> PhysxWorld:
    """Build the PhysX (CPU) world of ``scene``.

    Parameters
    ----------
    scene : Scene
    timestep : float
        Seconds per step.
    linear_damping, angular_damping : float
        Per dynamic body (PhysX units: 1/s).
    max_depenetration_velocity : float
        m/s; bounds how fast PhysX pushes interpenetrating bodies apart.
    sleep_threshold : float
        Mass-normalised kinetic energy below which a body may sleep.
    solver_position_iterations, solver_velocity_iterations : int
    settled : bool
        Start from the settled poses (True) or the solved ones.
    origin : (3,) float, metres, world frame, optional
        Where the simulation's local frame sits: PhysX works in float32, so the room is moved
        near the origin (results then do not depend on where the room is); read poses back
        with :meth:`PhysxWorld.pose`. Default: the world origin.
    free_joints : bool
        Simulate objects whose assets have joints as articulations (doors swing, drawers
        slide; :mod:`parse3d.physics.articulation`) instead of one rigid body each; they are
        listed in :attr:`PhysxWorld.articulations`, not in ``bodies``.
    contact_offset : float
        Metres: shapes closer than this get contacts (PhysX's default 0.01; a pair of shapes
        gets contacts within the sum of their offsets).
    many_pieces : (int, float), optional
        ``(n, offset)``: the shapes of an object of at least ``n`` convex pieces get this
        contact offset instead. Nested dishes and stacked saucers (vessels of fifty to a
        hundred wall pieces) lie within 2 cm of each other over their whole area, and every
        pair of their pieces then makes contacts each step; settling passes a smaller offset
        for them (:class:`~parse3d.physics.settle.SettleConfig`).

    Returns
    -------
    PhysxWorld
    """
    sapien = import_sapien()
    physx = sapien.physx
    # SAPIEN reads its scene configuration when the system is created; cpu_workers=0 runs
    # PhysX on the calling thread, which keeps runs deterministic and one core per scene.
    physx.set_scene_config(gravity=np.array([0.0, 0.0, -9.81], np.float32), cpu_workers=0)
    physx.set_shape_config(contact_offset=float(contact_offset), rest_offset=0.0)
    system = physx.PhysxCpuSystem()
    world = PhysxWorld(sapien.Scene(systems=[system]), system)
    o = np.zeros(3) if origin is None else np.asarray(origin, np.float64).reshape(3)
    world.origin = o
    system.timestep = float(timestep)
    mats: dict[str, object] = {}

    def material(name: str):
        if name not in mats:
            m = material_physics(name)
            mats[name] = physx.PhysxMaterial(m.static_friction, m.dynamic_friction, m.restitution)
        return mats[name]

    shell = shell_collision(scene.room)
    sm = SHELL_MATERIAL
    shell_mat = physx.PhysxMaterial(sm.static_friction, sm.dynamic_friction, sm.restitution)
    ent = sapien.Entity()
    ent.set_name(ROOM)
    static = physx.PhysxRigidStaticComponent()
    for sh, part in zip(_shapes(physx, shell, [shell_mat] * len(shell), 1.0, None, o),
                        shell.parts, strict=True):
        static.attach(sh)
        world.shape_owner[id(sh)] = (ROOM, part)
        world.shapes.append(sh)
    ent.add_component(static)
    world.sapien_scene.add_entity(ent)
    world.entities[ROOM] = ent

    for obj in scene.placed:
        if obj.asset is None:
            continue
        if free_joints and obj.asset.joints and _add_articulated(
                world, obj, material, settled, o, linear_damping=linear_damping,
                angular_damping=angular_damping,
                max_depenetration_velocity=max_depenetration_velocity,
                sleep_threshold=sleep_threshold,
                solver_position_iterations=solver_position_iterations,
                solver_velocity_iterations=solver_velocity_iterations):
            continue
        data = asset_collision(obj.asset)
        shapes = _shapes(physx, data.pieces, [material(m) for m in data.materials], obj.scale,
                         data.density)
        if many_pieces is not None and len(shapes) >= many_pieces[0]:
            for sh in shapes:
                sh.set_contact_offset(float(many_pieces[1]))
        body = physx.PhysxRigidDynamicComponent()
        for sh, part in zip(shapes, data.pieces.parts, strict=True):
            body.attach(sh)
            world.shape_owner[id(sh)] = (obj.id, part)
            world.shapes.append(sh)
        body.set_linear_damping(float(linear_damping))
        body.set_angular_damping(float(angular_damping))
        body.set_max_depenetration_velocity(float(max_depenetration_velocity))
        body.set_sleep_threshold(float(sleep_threshold))
        body.set_solver_position_iterations(int(solver_position_iterations))
        body.set_solver_velocity_iterations(int(solver_velocity_iterations))
        if obj.fixed:
            body.set_kinematic(True)
        ent = sapien.Entity()
        ent.set_name(obj.id)
        ent.add_component(body)
        R, t = obj.rotation, obj.position
        if settled and obj.settled_position is not None:
            R, t = obj.settled_rotation, obj.settled_position
        ent.set_pose(sapien.Pose(np.asarray(np.asarray(t, np.float64) - o, np.float32),
                                 np.asarray(matrix_to_quat(R), np.float32)))
        world.sapien_scene.add_entity(ent)
        world.entities[obj.id] = ent
        world.bodies[obj.id] = body
        if not obj.fixed:
            world.dynamic.append(obj.id)
    return world


def _add_articulated(world: PhysxWorld, obj, material, settled: bool, origin: np.ndarray,
                     **params) -> bool:
    """Add ``obj`` as an articulation (see :func:`~parse3d.physics.articulation.add_articulated`);
    False when it stays a rigid body."""
    import sapien

    from .articulation import add_articulated

    R, t = obj.rotation, obj.position
    if settled and obj.settled_position is not None:
        R, t = obj.settled_rotation, obj.settled_position
    pose = sapien.Pose(np.asarray(np.asarray(t, np.float64) - origin, np.float32),
                       np.asarray(matrix_to_quat(R), np.float32))
    art = add_articulated(world, obj, material=material, pose=pose, **params)
    if art is None:
        return False
    world.articulations[obj.id] = art
    return True
