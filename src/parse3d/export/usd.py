"""USD (``scene.usd``, via usd-core): a stage for Isaac Sim, Omniverse and usdview.

Stage: Z-up, ``metersPerUnit = 1``, default prim ``/World``.

- ``/World/Room/<element>``: the shell meshes, static colliders (no rigid body); the ceiling
  is its own prim.
- ``/World/Objects/<object>``: an Xform with the object's pose (translate, orient, uniform
  scale). A rigid object is one rigid body (``PhysicsRigidBodyAPI`` + ``PhysicsMassAPI``
  with its mass); an articulated one has a rigid body per link (``Links/base``,
  ``Links/<child part>``) joined by ``PhysicsRevoluteJoint`` / ``PhysicsPrismaticJoint``
  with limits, locked by a stiff drive at the stored value unless ``lock_joints=False``.
  SECURED_TO and HANGING_BELOW objects are welded to the world by a ``PhysicsFixedJoint``.
- One Xform per part under its body, holding a ``visual`` mesh (display colour and a
  ``UsdPreviewSurface`` material) and a ``collision`` scope with one guide-purpose mesh per
  convex piece (``PhysicsCollisionAPI``, approximation ``convexHull``), bound to a physics
  material with the part material's friction when the export has a friction table
  (``/World/PhysicsMaterials``; static and dynamic friction alike). Part geometry is
  written once per asset under the abstract ``/Prototypes`` class and referenced by every
  object using it.
- Custom attributes ``parse3d:objectId``, ``parse3d:category``, ``parse3d:assetId``,
  ``parse3d:partName`` (``object:part``), ``parse3d:partLabel``.

USD prim names cannot hold colons or start with a digit; ``parse3d:*`` attributes keep the
real names.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from ..errors import DependencyError
from ..geometry.frames import matrix_to_quat
from .walk import ObjectRecord, SceneRecord

__all__ = ["NAME", "FILES", "write", "build_stage"]

NAME = "usd"
FILES = ("scene.usd",)

#: Stiffness of the drive that holds a locked joint at its stored value (N m / deg, N / m).
LOCK_STIFFNESS = 1e6


def _pxr():
    try:
        from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics, UsdShade, Vt
    except ImportError as e:  # pragma: no cover - usd-core is a declared dependency
        raise DependencyError("USD export needs usd-core: pip install 'parse3d[export]'") from e
    return Gf, Sdf, Usd, UsdGeom, UsdPhysics, UsdShade, Vt


def _ident(name: str, taken: set[str]) -> str:
    """A valid, unique USD prim name for ``name``."""
    s = re.sub(r"[^A-Za-z0-9_]", "_", name) or "_"
    if s[0].isdigit():
        s = "_" + s
    base, k = s, 1
    while s in taken:
        s, k = f"{base}_{k}", k + 1
    taken.add(s)
    return s


def _quat_to_x(axis: np.ndarray) -> np.ndarray:
    """``[w, x, y, z]`` rotating +X onto ``axis`` (UsdPhysics joints move along their X)."""
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    x = np.array([1.0, 0.0, 0.0])
    c = float(np.dot(x, a))
    if c < -1 + 1e-9:
        return np.array([0.0, 0.0, 0.0, 1.0])  # half turn about Z
    v = np.cross(x, a)
    q = np.array([1.0 + c, *v])
    return q / np.linalg.norm(q)


class _Writer:
    def __init__(self, stage, rec: SceneRecord, lock_joints: bool) -> None:
        (self.Gf, self.Sdf, self.Usd, self.UsdGeom, self.UsdPhysics, self.UsdShade,
         self.Vt) = _pxr()
        self.stage = stage
        self.rec = rec
        self.lock = lock_joints
        self.looks: dict[tuple, object] = {}
        self.physics_materials: dict[float, object] = {}
        self.protos: dict[tuple[str, str], str] = {}
        self.proto_names: set[str] = set()

    # -- geometry -------------------------------------------------------------------------
    def _mesh(self, path: str, vertices: np.ndarray, faces: np.ndarray):
        UsdGeom, Vt = self.UsdGeom, self.Vt
        m = UsdGeom.Mesh.Define(self.stage, path)
        v = np.ascontiguousarray(vertices, np.float32)
        m.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(v))
        f = np.ascontiguousarray(faces, np.int32)
        m.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(f), 3, np.int32)))
        m.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(f.ravel()))
        m.CreateExtentAttr(Vt.Vec3fArray.FromNumpy(np.stack([v.min(0), v.max(0)])))
        m.CreateSubdivisionSchemeAttr("none")
        return m

    def _look(self, mat):
        key = (tuple(round(float(c), 5) for c in mat.color), round(float(mat.roughness), 5),
               round(float(mat.metallic), 5), mat.name)
        if key not in self.looks:
            Sdf, UsdShade, Gf = self.Sdf, self.UsdShade, self.Gf
            path = f"/World/Looks/{mat.name}_{len(self.looks)}"
            material = UsdShade.Material.Define(self.stage, path)
            shader = UsdShade.Shader.Define(self.stage, path + "/PreviewSurface")
            shader.CreateIdAttr("UsdPreviewSurface")
            shader.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).Set(Gf.Vec3f(*key[0][:3]))
            shader.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(key[1])
            shader.CreateInput("metallic", Sdf.ValueTypeNames.Float).Set(key[2])
            shader.CreateInput("opacity", Sdf.ValueTypeNames.Float).Set(key[0][3])
            material.CreateSurfaceOutput().ConnectToSource(shader.ConnectableAPI(), "surface")
            self.looks[key] = material
        return self.looks[key]

    def _visual(self, path: str, vertices, faces, mat) -> None:
        m = self._mesh(path, vertices, faces)
        m.CreateDisplayColorAttr([self.Gf.Vec3f(*[float(c) for c in mat.color[:3]])])
        if mat.color[3] < 1:
            m.CreateDisplayOpacityAttr([float(mat.color[3])])
        self.UsdShade.MaterialBindingAPI.Apply(m.GetPrim()).Bind(self._look(mat))

    def _physics_material(self, friction: float):
        key = round(float(friction), 6)
        if key not in self.physics_materials:
            path = f"/World/PhysicsMaterials/friction_{len(self.physics_materials)}"
            mat = self.UsdShade.Material.Define(self.stage, path)
            api = self.UsdPhysics.MaterialAPI.Apply(mat.GetPrim())
            api.CreateStaticFrictionAttr(key)
            api.CreateDynamicFrictionAttr(key)
            self.physics_materials[key] = mat
        return self.physics_materials[key]

    def _colliders(self, scope: str, pieces, friction: float | None = None) -> None:
        UsdGeom, UsdPhysics = self.UsdGeom, self.UsdPhysics
        sc = UsdGeom.Scope.Define(self.stage, scope)
        if friction is not None:
            self.UsdShade.MaterialBindingAPI.Apply(sc.GetPrim()).Bind(
                self._physics_material(friction), self.UsdShade.Tokens.weakerThanDescendants,
                "physics")
        for i, (v, f) in enumerate(pieces):
            m = self._mesh(f"{scope}/piece_{i}", v, f)
            m.CreatePurposeAttr(UsdGeom.Tokens.guide)
            UsdPhysics.CollisionAPI.Apply(m.GetPrim())
            UsdPhysics.MeshCollisionAPI.Apply(m.GetPrim()).CreateApproximationAttr("convexHull")

    def _attrs(self, prim, **values: str) -> None:
        for k, v in values.items():
            prim.CreateAttribute(f"parse3d:{k}", self.Sdf.ValueTypeNames.String, custom=True).Set(v)

    def _xform(self, path: str, T: np.ndarray | None = None, scale: float = 1.0):
        x = self.UsdGeom.Xform.Define(self.stage, path)
        if T is not None:
            q = matrix_to_quat(T[:3, :3] / scale)
            x.AddTranslateOp().Set(self.Gf.Vec3d(*[float(c) for c in T[:3, 3]]))
            x.AddOrientOp().Set(self.Gf.Quatf(float(q[0]), float(q[1]), float(q[2]), float(q[3])))
            if abs(scale - 1.0) > 1e-12:
                x.AddScaleOp().Set(self.Gf.Vec3f(scale, scale, scale))
        return x

    # -- prototypes -----------------------------------------------------------------------
    def _prototype(self, o: ObjectRecord, part) -> str:
        key = (o.asset_id, part.name)
        if key not in self.protos:
            root = "/Prototypes/" + _ident(o.asset_id, self.proto_names)
            if not self.stage.GetPrimAtPath(root):
                self.stage.CreateClassPrim(root)
            path = f"{root}/{_ident(part.name, set())}"
            self._xform(path)
            self._visual(f"{path}/visual", part.mesh.vertices, part.mesh.faces, part.material)
            self._colliders(f"{path}/collision", part.pieces,
                            self.rec.friction(part.material.name))
            self.protos[key] = path
        return self.protos[key]

    # -- scene ----------------------------------------------------------------------------
    def room(self) -> None:
        self._xform("/World/Room")
        taken: set[str] = set()
        for s in self.rec.shell:
            path = f"/World/Room/{_ident(s.name, taken)}"
            x = self._xform(path)
            self._attrs(x.GetPrim(), objectId="room", partName=s.key,
                        partLabel=s.name.split("_")[0])
            self._visual(f"{path}/visual", s.mesh.vertices, s.mesh.faces, s.material)
            # colliders and no body: static
            self._colliders(f"{path}/collision", s.pieces, self.rec.friction("room"))

    def obj(self, o: ObjectRecord, taken: set[str]) -> None:
        UsdPhysics, Gf = self.UsdPhysics, self.Gf
        path = f"/World/Objects/{_ident(o.id, taken)}"
        x = self._xform(path, o.transform, o.scale)
        self._attrs(x.GetPrim(), objectId=o.id, category=o.category, assetId=o.asset_id,
                    support=o.support or "")
        x.GetPrim().CreateAttribute("parse3d:fixed", self.Sdf.ValueTypeNames.Bool,
                                    custom=True).Set(bool(o.fixed))
        articulated = bool(o.joints)
        if articulated:
            UsdPhysics.ArticulationRootAPI.Apply(x.GetPrim())
        body_path = {}
        for lk in o.links:
            bp = f"{path}/Links/{_ident(lk.name, set())}" if articulated else path
            if articulated:
                if not self.stage.GetPrimAtPath(f"{path}/Links"):
                    self._xform(f"{path}/Links")
                self._xform(bp, lk.motion)
            body = self.stage.GetPrimAtPath(bp)
            UsdPhysics.RigidBodyAPI.Apply(body)
            UsdPhysics.MassAPI.Apply(body).CreateMassAttr(float(lk.mass))
            body_path[lk.name] = bp
            names: set[str] = set()
            for p in lk.parts:
                pp = f"{bp}/{_ident(p.name, names)}"
                prim = self.stage.DefinePrim(pp, "Xform")
                prim.GetReferences().AddInternalReference(self._prototype(o, p))
                self._attrs(prim, objectId=o.id, partName=p.key, partLabel=p.label,
                            category=o.category, assetId=o.asset_id)
        for j in o.joints:
            typ = UsdPhysics.RevoluteJoint if j.joint.type == "revolute" else UsdPhysics.PrismaticJoint
            jp = typ.Define(self.stage, f"{path}/Joints/{_ident(j.name, set())}")
            jp.CreateBody0Rel().SetTargets([body_path[j.parent_link]])
            jp.CreateBody1Rel().SetTargets([body_path[j.child_link]])
            jp.CreateAxisAttr("X")
            q = _quat_to_x(np.asarray(j.joint.axis, float))
            gq = Gf.Quatf(float(q[0]), float(q[1]), float(q[2]), float(q[3]))
            origin = Gf.Vec3f(*[float(c) for c in j.joint.origin])
            # both frames sit on the axis in their link's modelled (closed) frame; at the
            # exported value the child link is already turned or slid by that value
            jp.CreateLocalPos0Attr(origin)
            jp.CreateLocalRot0Attr(gq)
            jp.CreateLocalPos1Attr(origin)
            jp.CreateLocalRot1Attr(gq)
            lo, hi = sorted(float(v) for v in j.joint.limits)
            revolute = j.joint.type == "revolute"
            conv = np.degrees if revolute else (lambda v: v)
            jp.CreateLowerLimitAttr(float(conv(lo)))
            jp.CreateUpperLimitAttr(float(conv(hi)))
            prim = jp.GetPrim()
            prim.CreateAttribute("parse3d:value", self.Sdf.ValueTypeNames.Float,
                                 custom=True).Set(float(j.value))
            prim.CreateAttribute("parse3d:locked", self.Sdf.ValueTypeNames.Bool,
                                 custom=True).Set(bool(self.lock))
            if self.lock:
                drive = UsdPhysics.DriveAPI.Apply(prim, "angular" if revolute else "linear")
                drive.CreateStiffnessAttr(LOCK_STIFFNESS)
                drive.CreateDampingAttr(LOCK_STIFFNESS / 100)
                drive.CreateTargetPositionAttr(float(conv(j.value)))
        if o.fixed:
            w = UsdPhysics.FixedJoint.Define(self.stage, f"{path}/Joints/weld_to_world")
            w.CreateBody1Rel().SetTargets([body_path[o.links[0].name]])
            qw = matrix_to_quat(o.rotation)
            w.CreateLocalPos0Attr(Gf.Vec3f(*[float(c) for c in o.position]))
            w.CreateLocalRot0Attr(Gf.Quatf(float(qw[0]), float(qw[1]), float(qw[2]), float(qw[3])))
            w.CreateLocalPos1Attr(Gf.Vec3f(0, 0, 0))
            w.CreateLocalRot1Attr(Gf.Quatf(1, 0, 0, 0))


def build_stage(rec: SceneRecord, *, lock_joints: bool = True, path: str | None = None):
    """A ``Usd.Stage`` of a walked scene (in memory, or created at ``path``)."""
    Gf, Sdf, Usd, UsdGeom, UsdPhysics, UsdShade, Vt = _pxr()
    stage = Usd.Stage.CreateNew(path) if path else Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdPhysics.SetStageKilogramsPerUnit(stage, 1.0)
    world = UsdGeom.Xform.Define(stage, "/World")
    stage.SetDefaultPrim(world.GetPrim())
    world.GetPrim().SetCustomDataByKey("parse3d", dict(rec.meta))
    scene = UsdPhysics.Scene.Define(stage, "/World/PhysicsScene")
    scene.CreateGravityDirectionAttr(Gf.Vec3f(0, 0, -1))
    scene.CreateGravityMagnitudeAttr(9.81)
    w = _Writer(stage, rec, lock_joints)
    w.room()
    w._xform("/World/Objects")
    taken: set[str] = set()
    for o in rec.objects:
        w.obj(o, taken)
    return stage


def write(rec: SceneRecord, out: Path, *, lock_joints: bool = True) -> list[Path]:
    """Write ``scene.usd`` (binary crate) into the folder ``out``; returns the paths written."""
    path = Path(out) / "scene.usd"
    tmp = path.with_name(".scene.tmp.usd")
    stage = build_stage(rec, lock_joints=lock_joints, path=str(tmp))
    stage.GetRootLayer().Save()
    del stage
    tmp.replace(path)
    return [path]
