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

Prim names of objects, parts and shell elements are the glTF node names
(:func:`~parse3d.export.walk.node_name`: ``desk``, ``desk__tabletop``, ``room__floor``), unique
in the scene, so Blender's importer (which flattens nothing but keeps one namespace for all
objects) and three.js show the same names; USD prim names cannot hold colons, and the
``parse3d:*`` attributes keep the exact ones.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from ..errors import DependencyError
from ..geometry.frames import matrix_to_quat, rotation_between
from . import MARKERS
from .walk import ObjectRecord, SceneRecord

__all__ = ["NAME", "FILES", "MARKER", "write", "build_stage", "build_layer"]

NAME = "usd"
FILES = ("scene.usd",)
#: The file whose presence (and age) marks this export in a folder (written last).
MARKER = MARKERS["usd"]

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
    if a[0] < -1 + 1e-9:
        return np.array([0.0, 0.0, 0.0, 1.0])  # half turn about Z
    return matrix_to_quat(rotation_between((1.0, 0.0, 0.0), a))


class _Writer:
    """Authors the stage's root layer at the Sdf level (prim and property specs in one change
    block), which is many times faster than defining prims through the Usd API one by one."""

    def __init__(self, layer, rec: SceneRecord, lock_joints: bool) -> None:
        (self.Gf, self.Sdf, self.Usd, self.UsdGeom, self.UsdPhysics, self.UsdShade,
         self.Vt) = _pxr()
        self.layer = layer
        self.rec = rec
        self.lock = lock_joints
        self.T = self.Sdf.ValueTypeNames
        self.looks: dict[tuple, str] = {}
        self.physics_materials: dict[float, str] = {}
        self.proto_roots: dict[str, str] = {}
        self.protos: dict[tuple[str, str], str] = {}
        self.proto_names: set[str] = set()

    # -- specs ----------------------------------------------------------------------------
    def prim(self, path: str, type_name: str = "", *, api: tuple[str, ...] = (),
             specifier=None):
        """A ``def`` prim spec at ``path`` (its parent must exist)."""
        Sdf = self.Sdf
        parent_path, _, name = path.rpartition("/")
        parent = self.layer.GetPrimAtPath(parent_path or "/") if parent_path else \
            self.layer.pseudoRoot
        spec = Sdf.PrimSpec(parent, name, specifier or Sdf.SpecifierDef, type_name)
        if api:
            spec.SetInfo("apiSchemas", Sdf.TokenListOp.Create(prependedItems=list(api)))
        return spec

    def attr(self, spec, name: str, type_name, value, *, uniform: bool = False,
             custom: bool = False):
        Sdf = self.Sdf
        a = Sdf.AttributeSpec(spec, name, type_name,
                              Sdf.VariabilityUniform if uniform else Sdf.VariabilityVarying,
                              custom)
        if value is not None:
            a.default = value
        return a

    def rel(self, spec, name: str, *targets: str):
        r = self.Sdf.RelationshipSpec(spec, name, False)
        r.targetPathList.explicitItems = [self.Sdf.Path(t) for t in targets]
        return r

    def _vec3f(self, v) -> object:
        return self.Gf.Vec3f(*[float(c) for c in v])

    def _quatf(self, q) -> object:
        return self.Gf.Quatf(float(q[0]), float(q[1]), float(q[2]), float(q[3]))

    # -- geometry -------------------------------------------------------------------------
    def _mesh(self, path: str, vertices: np.ndarray, faces: np.ndarray, *, api=()):
        Vt, T = self.Vt, self.T
        m = self.prim(path, "Mesh", api=api)
        v = np.ascontiguousarray(vertices, np.float32)
        f = np.ascontiguousarray(faces, np.int32)
        self.attr(m, "points", T.Point3fArray, Vt.Vec3fArray.FromNumpy(v))
        self.attr(m, "faceVertexCounts", T.IntArray,
                  Vt.IntArray.FromNumpy(np.full(len(f), 3, np.int32)))
        self.attr(m, "faceVertexIndices", T.IntArray, Vt.IntArray.FromNumpy(f.ravel()))
        self.attr(m, "extent", T.Float3Array,
                  Vt.Vec3fArray.FromNumpy(np.stack([v.min(0), v.max(0)])))
        self.attr(m, "subdivisionScheme", T.Token, "none", uniform=True)
        return m

    def _look(self, mat) -> str:
        key = (tuple(round(float(c), 5) for c in mat.color), round(float(mat.roughness), 5),
               round(float(mat.metallic), 5), mat.name)
        if key not in self.looks:
            T = self.T
            if not self.looks:
                self.prim("/World/Looks")
            path = f"/World/Looks/{_ident(mat.name, set())}_{len(self.looks)}"
            material = self.prim(path, "Material")
            shader = self.prim(path + "/PreviewSurface", "Shader")
            self.attr(shader, "info:id", T.Token, "UsdPreviewSurface", uniform=True)
            self.attr(shader, "inputs:diffuseColor", T.Color3f, self._vec3f(key[0][:3]))
            self.attr(shader, "inputs:metallic", T.Float, key[2])
            self.attr(shader, "inputs:opacity", T.Float, key[0][3])
            self.attr(shader, "inputs:roughness", T.Float, key[1])
            self.attr(shader, "outputs:surface", T.Token, None)
            out = self.attr(material, "outputs:surface", T.Token, None)
            out.connectionPathList.explicitItems = [
                self.Sdf.Path(path + "/PreviewSurface.outputs:surface")]
            self.looks[key] = path
        return self.looks[key]

    def _visual(self, path: str, vertices, faces, mat) -> None:
        T, Vt = self.T, self.Vt
        m = self._mesh(path, vertices, faces, api=("MaterialBindingAPI",))
        self.attr(m, "primvars:displayColor", T.Color3fArray,
                  Vt.Vec3fArray([self._vec3f(mat.color[:3])]))
        if mat.color[3] < 1:
            self.attr(m, "primvars:displayOpacity", T.FloatArray,
                      Vt.FloatArray([float(mat.color[3])]))
        self.rel(m, "material:binding", self._look(mat))

    def _physics_material(self, friction: float) -> str:
        key = round(float(friction), 6)
        if key not in self.physics_materials:
            if not self.physics_materials:
                self.prim("/World/PhysicsMaterials")
            path = f"/World/PhysicsMaterials/friction_{len(self.physics_materials)}"
            mat = self.prim(path, "Material", api=("PhysicsMaterialAPI",))
            self.attr(mat, "physics:dynamicFriction", self.T.Float, key)
            self.attr(mat, "physics:staticFriction", self.T.Float, key)
            self.physics_materials[key] = path
        return self.physics_materials[key]

    def _colliders(self, scope: str, pieces, friction: float | None = None) -> None:
        T = self.T
        sc = self.prim(scope, "Scope",
                       api=("MaterialBindingAPI",) if friction is not None else ())
        if friction is not None:
            r = self.rel(sc, "material:binding:physics", self._physics_material(friction))
            r.SetInfo("bindMaterialAs", "weakerThanDescendants")
        for i, (v, f) in enumerate(pieces):
            m = self._mesh(f"{scope}/piece_{i}", v, f,
                           api=("PhysicsCollisionAPI", "PhysicsMeshCollisionAPI"))
            self.attr(m, "physics:approximation", T.Token, "convexHull", uniform=True)
            self.attr(m, "purpose", T.Token, "guide", uniform=True)

    def _attrs(self, spec, **values: str) -> None:
        for k, v in values.items():
            self.attr(spec, f"parse3d:{k}", self.T.String, v, custom=True)

    def _xform(self, path: str, T: np.ndarray | None = None, scale: float = 1.0, *, api=()):
        x = self.prim(path, "Xform", api=api)
        if T is not None:
            q = matrix_to_quat(T[:3, :3] / scale)
            order = ["xformOp:translate", "xformOp:orient"]
            self.attr(x, "xformOp:translate", self.T.Double3,
                      self.Gf.Vec3d(*[float(c) for c in T[:3, 3]]))
            self.attr(x, "xformOp:orient", self.T.Quatf, self._quatf(q))
            if abs(scale - 1.0) > 1e-12:
                self.attr(x, "xformOp:scale", self.T.Float3,
                          self.Gf.Vec3f(scale, scale, scale))
                order.append("xformOp:scale")
            self.attr(x, "xformOpOrder", self.T.TokenArray, self.Vt.TokenArray(order),
                      uniform=True)
        return x

    # -- prototypes -----------------------------------------------------------------------
    def _prototype(self, o: ObjectRecord, part) -> str:
        key = (o.asset_id, part.name)
        if key not in self.protos:
            root = self.proto_roots.get(o.asset_id)
            if root is None:
                if not self.proto_roots:
                    self.prim("/Prototypes")
                root = "/Prototypes/" + _ident(o.asset_id, self.proto_names)
                self.prim(root, specifier=self.Sdf.SpecifierClass)
                self.proto_roots[o.asset_id] = root
            path = f"{root}/{_ident(part.name, set())}"
            self._xform(path)
            self._visual(f"{path}/visual", part.mesh.vertices, part.mesh.faces, part.material)
            self._colliders(f"{path}/collision", part.pieces,
                            self.rec.friction(part.material.name))
            self.protos[key] = path
        return self.protos[key]

    # -- scene ----------------------------------------------------------------------------
    def world(self) -> None:
        T = self.T
        layer = self.layer
        layer.defaultPrim = "World"
        layer.pseudoRoot.SetInfo("upAxis", "Z")
        layer.pseudoRoot.SetInfo("metersPerUnit", 1.0)
        layer.pseudoRoot.SetInfo("kilogramsPerUnit", 1.0)
        world = self._xform("/World")
        world.customData = {"parse3d": dict(self.rec.meta)}
        scene = self.prim("/World/PhysicsScene", "PhysicsScene")
        self.attr(scene, "physics:gravityDirection", T.Vector3f, self.Gf.Vec3f(0, 0, -1))
        self.attr(scene, "physics:gravityMagnitude", T.Float, 9.81)

    def room(self) -> None:
        self._xform("/World/Room")
        taken: set[str] = set()
        for s in self.rec.shell:
            path = f"/World/Room/{_ident(s.node, taken)}"
            x = self._xform(path)
            self._attrs(x, objectId="room", partName=s.key, partLabel=s.name.split("_")[0])
            self._visual(f"{path}/visual", s.mesh.vertices, s.mesh.faces, s.material)
            # colliders and no body: static
            self._colliders(f"{path}/collision", s.pieces, self.rec.friction("room"))

    def obj(self, o: ObjectRecord, taken: set[str]) -> None:
        T = self.T
        path = f"/World/Objects/{_ident(o.node, taken)}"
        articulated = bool(o.joints)
        body_api = ("PhysicsRigidBodyAPI", "PhysicsMassAPI")
        x = self._xform(path, o.transform, o.scale,
                        api=("PhysicsArticulationRootAPI",) if articulated else body_api)
        self._attrs(x, objectId=o.id, category=o.category, assetId=o.asset_id,
                    support=o.support or "")
        self.attr(x, "parse3d:fixed", T.Bool, bool(o.fixed), custom=True)
        body_path = {}
        if articulated:
            self._xform(f"{path}/Links")
        for lk in o.links:
            if articulated:
                bp = f"{path}/Links/{_ident(lk.name, set())}"
                body = self._xform(bp, lk.motion, api=body_api)
            else:
                bp, body = path, x
            self.attr(body, "physics:mass", T.Float, float(lk.mass))
            body_path[lk.name] = bp
            for p in lk.parts:
                proto = self._prototype(o, p)
                prim = self.prim(f"{bp}/{_ident(p.node, taken)}", "Xform")
                prim.referenceList.Prepend(self.Sdf.Reference("", proto))
                self._attrs(prim, objectId=o.id, partName=p.key, partLabel=p.label,
                            category=o.category, assetId=o.asset_id)
        if o.joints or o.fixed:
            self.prim(f"{path}/Joints")
        for j in o.joints:
            revolute = j.joint.type == "revolute"
            kind = "angular" if revolute else "linear"
            jp = self.prim(f"{path}/Joints/{_ident(j.name, set())}",
                           "PhysicsRevoluteJoint" if revolute else "PhysicsPrismaticJoint",
                           api=(f"PhysicsDriveAPI:{kind}",) if self.lock else ())
            self.rel(jp, "physics:body0", body_path[j.parent_link])
            self.rel(jp, "physics:body1", body_path[j.child_link])
            self.attr(jp, "physics:axis", T.Token, "X", uniform=True)
            gq = self._quatf(_quat_to_x(np.asarray(j.joint.axis, float)))
            origin = self._vec3f(j.joint.origin)
            # both frames sit on the axis in their link's modelled (closed) frame; at the
            # exported value the child link is already turned or slid by that value
            self.attr(jp, "physics:localPos0", T.Point3f, origin)
            self.attr(jp, "physics:localRot0", T.Quatf, gq)
            self.attr(jp, "physics:localPos1", T.Point3f, origin)
            self.attr(jp, "physics:localRot1", T.Quatf, gq)
            lo, hi = sorted(float(v) for v in j.joint.limits)
            conv = np.degrees if revolute else (lambda v: v)
            self.attr(jp, "physics:lowerLimit", T.Float, float(conv(lo)))
            self.attr(jp, "physics:upperLimit", T.Float, float(conv(hi)))
            self.attr(jp, "parse3d:value", T.Float, float(j.value), custom=True)
            self.attr(jp, "parse3d:locked", T.Bool, bool(self.lock), custom=True)
            if self.lock:
                self.attr(jp, f"drive:{kind}:physics:stiffness", T.Float, LOCK_STIFFNESS)
                self.attr(jp, f"drive:{kind}:physics:damping", T.Float, LOCK_STIFFNESS / 100)
                self.attr(jp, f"drive:{kind}:physics:targetPosition", T.Float,
                          float(conv(j.value)))
        if o.fixed:
            w = self.prim(f"{path}/Joints/weld_to_world", "PhysicsFixedJoint")
            self.rel(w, "physics:body1", body_path[o.links[0].name])
            self.attr(w, "physics:localPos0", T.Point3f, self._vec3f(o.position))
            self.attr(w, "physics:localRot0", T.Quatf, self._quatf(matrix_to_quat(o.rotation)))
            self.attr(w, "physics:localPos1", T.Point3f, self.Gf.Vec3f(0, 0, 0))
            self.attr(w, "physics:localRot1", T.Quatf, self.Gf.Quatf(1, 0, 0, 0))


def build_layer(rec: SceneRecord, *, lock_joints: bool = True, path: str | None = None):
    """The root ``Sdf.Layer`` of a walked scene's stage (anonymous, or new at ``path``)."""
    Gf, Sdf, Usd, UsdGeom, UsdPhysics, UsdShade, Vt = _pxr()
    layer = Sdf.Layer.CreateNew(path) if path else Sdf.Layer.CreateAnonymous(".usda")
    w = _Writer(layer, rec, lock_joints)
    with Sdf.ChangeBlock():
        w.world()
        w.room()
        w._xform("/World/Objects")
        taken: set[str] = set()
        for o in rec.objects:
            w.obj(o, taken)
    return layer


def build_stage(rec: SceneRecord, *, lock_joints: bool = True, path: str | None = None):
    """A ``Usd.Stage`` of a walked scene (in memory, or created at ``path``)."""
    Usd = _pxr()[2]
    return Usd.Stage.Open(build_layer(rec, lock_joints=lock_joints, path=path))


def write(rec: SceneRecord, out: Path, *, lock_joints: bool = True) -> list[Path]:
    """Write ``scene.usd`` (binary crate) into the folder ``out``; returns the paths written."""
    path = Path(out) / "scene.usd"
    tmp = path.with_name(".scene.tmp.usd")
    try:
        layer = build_layer(rec, lock_joints=lock_joints, path=str(tmp))
        layer.Save()
        del layer
        tmp.replace(path)
    except BaseException:
        tmp.unlink(missing_ok=True)  # no half-written file left behind
        raise
    return [path]
