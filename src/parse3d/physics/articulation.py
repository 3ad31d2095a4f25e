"""Articulated objects in SAPIEN 3 (PhysX, CPU): doors that swing, drawers that slide.

By default settling keeps joints locked: every object is one rigid body in its closed
collision shape (:mod:`parse3d.physics.bodies`). With ``free_joints`` (``parse3d settle
--free-joints``) an object whose asset has joints becomes a PhysX articulation instead:

- links: one per moving part (a joint's child part) plus ``base`` holding every other part;
  a mount (a joint with no travel: a handle on a door) rides rigidly on its parent's link;
- link frames: the asset frame, moved by the joints above the link (so every convex piece
  stays in the asset frame, scaled by the object's scale, as for rigid bodies);
- joints: PhysX ``revolute`` or ``prismatic`` joints whose frame sits at the joint origin
  with its x axis along the joint axis, limits from the asset (prismatic ones scaled), a
  little damping (:data:`JOINT_DAMPING`) and friction (:data:`JOINT_FRICTION`) so an ajar door
  comes to rest; starting values from ``PlacedObject.joints`` (clipped to the limits);
- the root link floats freely for a loose object and is fixed for a ``fixed`` one (a wall
  cabinet's door can still swing);
- the links of one object do not collide with each other (its parts are modelled touching,
  a door flush with its neighbour; PhysX would push them apart), only with everything else.

Every collision shape is registered in :attr:`PhysxWorld.shape_owner` with its part, so
contacts still name parts. An asset whose moving link has no collision piece stays rigid.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..assets.model import BASE_LINK, link_groups
from ..geometry.frames import matrix_to_quat
from ..scene.model import PlacedObject
from .collision import asset_collision

__all__ = ["BASE_LINK", "JOINT_DAMPING", "JOINT_FRICTION", "ArticulatedObject",
           "link_groups", "add_articulated"]

#: Name of the link holding every part that no joint moves.
#: Joint damping (N·m·s/rad for hinges, N·s/m for slides).
JOINT_DAMPING = 0.5
#: Joint friction coefficient (PhysX's unitless articulation joint friction).
JOINT_FRICTION = 0.05


@dataclass
class ArticulatedObject:
    """An object simulated as an articulation.

    Attributes
    ----------
    articulation : sapien.physx.PhysxArticulation
    links : list of PhysxArticulationLinkComponent
        Root (``base``) first.
    joints : dict of str to (int, float)
        Asset joint name -> (index into the articulation's qpos, factor from the asset's
        units to the simulation's: 1 for a hinge, the object's scale for a slide).
    limits : dict of str to (float, float)
        Asset joint name -> limits in the asset's units.
    """

    articulation: object
    links: list
    joints: dict[str, tuple[int, float]]
    limits: dict[str, tuple[float, float]]

    @property
    def sleeping(self) -> bool:
        return all(lk.sleeping for lk in self.links)

    def values(self) -> dict[str, float]:
        """Joint values now (radians or metres in the asset's units), within the limits."""
        q = np.asarray(self.articulation.get_qpos(), float)
        out = {}
        for name, (i, k) in self.joints.items():
            lo, hi = self.limits[name]
            out[name] = float(np.clip(q[i] / k, lo, hi)) + 0.0  # no -0.0
        return out


def _axis_frame(axis) -> np.ndarray:
    """A rotation whose x column is ``axis`` (unit)."""
    x = np.asarray(axis, float)
    x = x / np.linalg.norm(x)
    helper = np.array([0.0, 0.0, 1.0]) if abs(x[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    y = np.cross(helper, x)
    y /= np.linalg.norm(y)
    return np.column_stack([x, y, np.cross(x, y)])


def add_articulated(world, obj: PlacedObject, *, material, pose, linear_damping: float,
                    angular_damping: float, max_depenetration_velocity: float,
                    sleep_threshold: float, solver_position_iterations: int,
                    solver_velocity_iterations: int) -> ArticulatedObject | None:
    """Add ``obj`` to ``world`` as an articulation; None (nothing added) when its asset has no
    moving joint or a moving link has no collision piece.

    Parameters
    ----------
    world : PhysxWorld
        Receives the root link's entity in ``entities`` and every shape in ``shape_owner``.
    obj : PlacedObject
    material : callable
        Material family name -> ``PhysxMaterial``.
    pose : sapien.Pose
        The root link's (asset frame's) pose in the simulation frame.
    linear_damping, angular_damping, max_depenetration_velocity : float
        Per link.
    sleep_threshold : float
    solver_position_iterations, solver_velocity_iterations : int
    """
    import sapien

    physx = sapien.physx
    asset = obj.asset
    part_link, order, joints = link_groups(asset)
    if not joints:
        return None
    data = asset_collision(asset)
    by_link: dict[str, list[int]] = {n: [] for n in order}
    for i, part in enumerate(data.pieces.parts):
        by_link[part_link.get(part, BASE_LINK)].append(i)
    if any(not v for v in by_link.values()):
        return None
    s = float(obj.scale)
    group = len(world.articulations) + 1
    parent_of = {j.child_part: (j, parent) for j, parent in joints}
    comps: dict[str, object] = {}
    entities = []
    for name in order:
        parent = None if name == BASE_LINK else comps[parent_of[name][1]]
        link = physx.PhysxArticulationLinkComponent(parent)
        for i in by_link[name]:
            v = np.ascontiguousarray(data.pieces.piece_vertices(i), np.float32)
            sh = physx.PhysxCollisionShapeConvexMesh(vertices=v, scale=[s] * 3,
                                                     material=material(data.materials[i]))
            sh.set_density(data.density)
            # SAPIEN skips a pair whose group-2 masks share a bit and whose group-3 values are
            # equal: no collisions inside this object (its parts are modelled touching)
            sh.set_collision_groups([1, 1, 1, group])
            link.attach(sh)
            world.shape_owner[id(sh)] = (obj.id, data.pieces.parts[i])
            world.shapes.append(sh)
        link.set_linear_damping(float(linear_damping))
        link.set_angular_damping(float(angular_damping))
        link.set_max_depenetration_velocity(float(max_depenetration_velocity))
        link.name = f"{obj.id}:{name}" if name != BASE_LINK else obj.id
        ent = sapien.Entity()
        ent.set_name(link.name)
        ent.add_component(link)
        comps[name] = link
        entities.append(ent)
    for name in order[1:]:
        j, _ = parent_of[name]
        jt = comps[name].joint
        jt.name = j.name
        jt.type = "revolute" if j.type == "revolute" else "prismatic"
        frame = sapien.Pose(np.asarray(np.asarray(j.origin, float) * s, np.float32),
                            np.asarray(matrix_to_quat(_axis_frame(j.axis)), np.float32))
        jt.pose_in_parent = frame
        jt.pose_in_child = frame  # link frames coincide when the joint is at 0
        k = 1.0 if j.type == "revolute" else s
        lo, hi = sorted(float(v) for v in j.limits)
        jt.limit = np.array([[lo * k, hi * k]], np.float32)
        jt.set_drive_property(0.0, JOINT_DAMPING)
        jt.friction = JOINT_FRICTION
    comps[BASE_LINK].joint.type = "fixed" if obj.fixed else "undefined"
    entities[0].pose = pose
    for ent in entities:
        world.sapien_scene.add_entity(ent)
    art = comps[BASE_LINK].articulation
    art.set_sleep_threshold(float(sleep_threshold))
    art.set_solver_position_iterations(int(solver_position_iterations))
    art.set_solver_velocity_iterations(int(solver_velocity_iterations))
    index = {jt.name: i for i, jt in enumerate(art.get_active_joints())}
    spec, limits = {}, {}
    q = np.zeros(art.dof)
    for j, _ in joints:
        k = 1.0 if j.type == "revolute" else s
        lo, hi = sorted(float(v) for v in j.limits)
        spec[j.name] = (index[j.name], k)
        limits[j.name] = (lo, hi)
        q[index[j.name]] = float(np.clip(obj.joints.get(j.name, 0.0), lo, hi)) * k
    art.set_qpos(q.astype(np.float32))
    art.set_qvel(np.zeros(art.dof, np.float32))
    art.set_root_pose(pose)
    world.entities[obj.id] = entities[0]
    return ArticulatedObject(art, [comps[n] for n in order], spec, limits)
