"""The headless renderer: one OpenGL context (Mesa EGL, no display), meshes uploaded once.

A :class:`Renderer` owns an OpenGL 3.3 context created with
``moderngl.create_context(standalone=True, backend="egl")``. Each asset's parts are uploaded
once into one vertex buffer (position, normal, linear colour, roughness/metallic, local part
index) and drawn per placed object with its world transform; the room shell elements are
uploaded once per room. A view is drawn in two passes from the same geometry and matrices:

1. **colour**: multisampled (MSAA, 4 samples by default), hemisphere ambient plus a key
   directional light with a 3x3 PCF shadow map and an unshadowed fill light, ACES tone
   mapping and sRGB encoding. The shadow map depends only on the scene and is reused across
   views of the same scene.
2. **ids**: single-sampled float32 attachments holding the instance id, the part id, the
   camera-frame depth (metres) and the world normal of the surface at each pixel centre. Ids
   are small integers stored exactly in float32; nothing is blended or filtered.

Room shell visibility: a shell element (floor, wall, ceiling) is drawn only when the camera
centre is on the room side of its inner face, so cameras inside the room see every wall and
the ceiling, the top-down plan camera (above the ceiling) sees no ceiling, and a camera
standing outside a wall looks through it (a cut-away). The shell receives shadows but casts
none: the key light stands for the room's overall lighting, not for sun through a window.
"""

from __future__ import annotations

import hashlib
from collections import OrderedDict
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..assets.model import Asset, Material
from ..errors import DependencyError
from ..geometry.frames import cross_rows
from ..geometry.meshes import MeshArrays
from ..scene.model import RoomShell, Scene
from . import shaders
from .camera import Camera, asset_camera, look_at
from .result import RenderResult

__all__ = [
    "Lighting",
    "RoomStyle",
    "Renderer",
    "create_context",
    "default_renderer",
    "render_scene",
    "render_asset",
    "scene_id_tables",
    "SYSTEM_PACKAGES",
]

#: Debian packages that provide headless OpenGL through EGL (Mesa's llvmpipe works without GPU).
SYSTEM_PACKAGES = ("libegl1", "libegl-mesa0", "libgl1-mesa-dri")

#: A mesh as the renderer reads it: ``vertices`` (V, 3) and ``faces`` (F, 3).
if TYPE_CHECKING:  # a preview imports no mesh library: the arithmetic below is trimesh's
    import trimesh

    _Mesh = trimesh.Trimesh | MeshArrays

_SMOOTH_COS = float(np.cos(np.deg2rad(35.0)))
_FLOATS_PER_VERTEX = 12


def create_context():
    """A standalone OpenGL >= 3.3 context on EGL (headless).

    Raises
    ------
    DependencyError
        When moderngl is not installed or no EGL/OpenGL driver can be loaded; the message
        names the Debian packages to install.
    """
    try:
        import moderngl
    except ImportError as e:
        raise DependencyError(
            "rendering needs the Python package 'moderngl': pip install 'parse3d[render]'"
        ) from e
    hint = ("install Mesa's headless EGL/OpenGL drivers: sudo apt-get install "
            f"{' '.join(SYSTEM_PACKAGES)} (or run `make system`)")
    try:
        ctx = moderngl.create_context(standalone=True, backend="egl")
    except Exception as e:  # moderngl/glcontext raise plain Exceptions for missing libraries
        raise DependencyError(f"no headless OpenGL context could be created ({e}); {hint}") from e
    if ctx.version_code < 330:
        version = ctx.info.get("GL_VERSION", "?")
        ctx.release()
        raise DependencyError(f"OpenGL 3.3 is needed, the EGL driver offers {version}; {hint}")
    return ctx


@dataclass(frozen=True)
class Lighting:
    """Light rig (linear RGB intensities; directions point towards the light, world frame).

    Attributes
    ----------
    key_direction : (3,) float
        Direction towards the shadow-casting key light.
    key_color, fill_color : (3,) float
    fill_direction : (3,) float
        Direction towards the unshadowed fill light.
    sky, ground : (3,) float
        Hemisphere ambient colours for normals pointing up and down.
    exposure : float
    shadow_size : int
        Shadow map resolution in texels.
    background : (3,) float
        sRGB background colour where no surface is hit.
    """

    key_direction: tuple[float, float, float] = (0.45, -0.35, 1.0)
    key_color: tuple[float, float, float] = (1.75, 1.65, 1.5)
    fill_direction: tuple[float, float, float] = (-0.6, 0.7, 0.35)
    fill_color: tuple[float, float, float] = (0.22, 0.24, 0.28)
    sky: tuple[float, float, float] = (0.56, 0.58, 0.62)
    ground: tuple[float, float, float] = (0.3, 0.27, 0.24)
    exposure: float = 1.0
    shadow_size: int = 2048
    background: tuple[float, float, float] = (0.93, 0.93, 0.94)


@dataclass(frozen=True)
class RoomStyle:
    """Materials of the room shell."""

    floor: Material = Material((0.62, 0.47, 0.33, 1.0), 0.55, 0.0, "wood")
    wall: Material = Material((0.88, 0.86, 0.82, 1.0), 0.9, 0.0, "stone")
    ceiling: Material = Material((0.94, 0.94, 0.93, 1.0), 0.95, 0.0, "stone")

    def material(self, element: str) -> Material:
        if element == "floor":
            return self.floor
        if element == "ceiling":
            return self.ceiling
        return self.wall


#: Norms at or below this are zero (trimesh's ``util.TOL_ZERO``), and angles below this are
#: a degenerate triangle's (``tol.merge``).
_TOL_ZERO = np.finfo(np.float64).resolution * 100
_TOL_MERGE = 1e-8


def _unitize(rows: np.ndarray, *, zero: bool = False) -> np.ndarray:
    """(n, d) rows scaled to unit length: ``trimesh.util.unitize``, the same operations in the
    same order (so the same bits); rows of norm <= ``_TOL_ZERO`` are left as they are, or with
    ``zero`` set to zero (as :func:`parse3d.geometry.surfaces.unit_normals` does)."""
    norm = np.sqrt(np.dot(rows * rows, [1.0] * rows.shape[1]))
    valid = norm > _TOL_ZERO
    norm[valid] **= -1
    out = rows * norm.reshape((-1, 1))
    if zero and not valid.all():
        out[~valid] = 0.0
    return out


def _corner_angles(tri: np.ndarray) -> np.ndarray:
    """(n, 3) angles (radians) at the corners of (n, 3, 3) triangles, all zero for a
    degenerate triangle: ``trimesh.triangles.angles``, operation for operation."""
    u = _unitize(tri[:, 1] - tri[:, 0])
    v = _unitize(tri[:, 2] - tri[:, 0])
    w = _unitize(tri[:, 2] - tri[:, 1])
    out = np.zeros((len(tri), 3), dtype=np.float64)
    out[:, 0] = np.arccos(np.clip(np.dot(u * v, [1.0] * 3), -1, 1))
    out[:, 1] = np.arccos(np.clip(np.dot(-u * w, [1.0] * 3), -1, 1))
    out[:, 2] = np.pi - out[:, 0] - out[:, 1]
    out[(out < _TOL_MERGE).any(axis=1), :] = 0.0
    return out


def _closed(mesh: trimesh.Trimesh) -> bool:
    """Whether back faces of ``mesh`` can never be seen: watertight (every edge shared by
    exactly two faces), consistently wound (the two run it in opposite directions, so no
    directed edge repeats) and outward (positive signed volume).

    The same answer as trimesh's ``is_watertight``, ``is_winding_consistent`` and
    ``volume > 0``, computed in one pass without filling the mesh's cache (every asset a
    dataset worker meets for the first time comes through here).
    """
    faces = np.asarray(mesh.faces, np.int64)
    if faces.ndim != 2 or faces.shape[1] != 3 or len(faces) == 0:
        return False
    edges = faces[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
    n = int(edges.max()) + 1
    lo, hi = np.minimum(edges[:, 0], edges[:, 1]), np.maximum(edges[:, 0], edges[:, 1])
    _, counts = np.unique(lo * n + hi, return_counts=True)
    if not (counts == 2).all():
        return False
    if len(np.unique(edges[:, 0] * n + edges[:, 1])) != len(edges):
        return False
    v = np.asarray(mesh.vertices, np.float64)
    if int(faces.max()) >= len(v) or int(faces.min()) < 0:
        return False
    t = v[faces]
    return bool(np.einsum("ij,ij->", t[:, 0], np.cross(t[:, 1], t[:, 2])) > 0.0)


def _closed_parts(F: np.ndarray, tri: np.ndarray, face_part: np.ndarray, n_parts: int,
                  n_vertices: int) -> np.ndarray:
    """(P,) bool: :func:`_closed` of every part at once.

    ``F`` (N, 3) are the faces of all parts with their vertex indices offset into one array of
    ``n_vertices`` vertices (so no two parts share an edge), ``tri`` (N, 3, 3) their corners
    and ``face_part`` (N,) the part of each face.
    """
    edges = F[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
    edge_part = np.repeat(face_part, 3)
    lo, hi = np.minimum(edges[:, 0], edges[:, 1]), np.maximum(edges[:, 0], edges[:, 1])
    _, inv, counts = np.unique(lo * n_vertices + hi, return_inverse=True, return_counts=True)
    bad = counts[inv] != 2  # an edge not shared by exactly two faces: open or non-manifold
    _, inv, counts = np.unique(edges[:, 0] * n_vertices + edges[:, 1], return_inverse=True,
                               return_counts=True)
    bad |= counts[inv] > 1  # a directed edge twice: inconsistent winding
    closed = np.bincount(edge_part[bad], minlength=n_parts) == 0
    for k in np.flatnonzero(closed):  # outward: positive signed volume, per part as _closed
        t = tri[face_part == k]
        closed[k] = bool(np.einsum("ij,ij->", t[:, 0], cross_rows(t[:, 1], t[:, 2])) > 0.0)
    return closed


def _vertex_data(items: list[tuple[_Mesh, Material]]) -> tuple[np.ndarray, int]:
    """Interleaved vertices, one per triangle corner, closed meshes first.

    ``items`` are meshes (``trimesh.Trimesh`` or the ``MeshArrays`` a loaded asset's parts
    hold) with their materials.

    Corners keep the smooth vertex normal where it is within 35 degrees of the face normal,
    else take the face normal, so boxes have hard edges and lathed shapes look round. Face
    normals, angle-weighted vertex normals and closedness are what trimesh's
    ``face_normals``, ``vertex_normals`` and :func:`_closed` give per mesh, computed for all
    meshes in one pass (an asset's parts are a few dozen small meshes: per-mesh calls cost
    more than the arithmetic) and without filling the meshes' caches.

    Returns
    -------
    data : (V, 12) float32
        Position, normal, linear RGB, roughness, metallic, local part index.
    n_closed : int
        The first ``n_closed`` vertices belong to closed meshes (drawn with back-face culling).
    """
    keep, faces, verts, given = [], [], [], []
    offset = 0
    for k, (mesh, mat) in enumerate(items):
        f = np.asarray(mesh.faces, np.int64)
        if len(f) == 0:
            continue
        v = np.asarray(mesh.vertices, np.float64)
        if int(f.min()) < 0 or int(f.max()) >= len(v):
            raise ValueError(f"mesh {k} has face indices outside its {len(v)} vertices")
        keep.append((k, mat))
        faces.append(f + offset)
        verts.append(v)
        # normals given to a trimesh (or carried through a transform) win, as in trimesh
        cache = getattr(mesh, "_cache", None)
        given.append(np.asarray(mesh.face_normals, np.float64)
                     if cache is not None and "face_normals" in cache else None)
        offset += len(v)
    if not keep:
        return np.zeros((0, _FLOATS_PER_VERTEX), np.float32), 0
    F = np.concatenate(faces)
    V = np.concatenate(verts)
    sizes = np.array([len(f) for f in faces])
    face_part = np.repeat(np.arange(len(keep)), sizes)
    tri = V[F]
    e = tri[:, 1:, :] - tri[:, :2, :]  # the edges trimesh crosses, so the normals match it
    fn = _unitize(cross_rows(e[:, 0], e[:, 1]), zero=True)
    if any(g is not None for g in given):
        starts = np.r_[0, np.cumsum(sizes)]
        for j, g in enumerate(given):
            if g is not None and g.shape == (sizes[j], 3):
                fn[starts[j]:starts[j + 1]] = g
    # angle-weighted vertex normals over the faces with a valid normal (trimesh's
    # weighted_vertex_normals: the same products, summed per vertex in face order)
    ok = (fn**2).sum(axis=1) > 0.5
    ang = _corner_angles(tri)[ok]
    idx = F[ok].ravel()
    contrib = ang.reshape(-1, 1) * np.repeat(fn[ok], 3, axis=0)
    vn = np.stack([np.bincount(idx, weights=contrib[:, c], minlength=len(V))
                   for c in range(3)], axis=1)
    vn = _unitize(vn)
    corner_fn = np.repeat(fn, 3, axis=0)
    corner_vn = vn[F].reshape(-1, 3)
    smooth = np.einsum("ij,ij->i", corner_fn, corner_vn) > _SMOOTH_COS
    table = np.array([[*(np.clip(np.asarray(m.color[:3], float), 0.0, 1.0) ** 2.2),
                       m.roughness, m.metallic, k] for k, m in keep], np.float64)
    corner_part = np.repeat(face_part, 3)
    data = np.empty((len(corner_part), _FLOATS_PER_VERTEX), np.float32)
    data[:, 0:3] = tri.reshape(-1, 3)
    data[:, 3:6] = np.where(smooth[:, None], corner_vn, corner_fn)
    data[:, 6:12] = table[corner_part]
    closed = _closed_parts(F, tri, face_part, len(keep), len(V))[corner_part]
    n_closed = int(closed.sum())
    if 0 < n_closed < len(data):
        data = np.concatenate([data[closed], data[~closed]])  # parts keep their order
    return data, n_closed


class _GpuMesh:
    """One vertex buffer (all parts of an asset, or one shell element) and its three VAOs."""

    def __init__(self, ctx, programs: dict, items: list[tuple[_Mesh, Material]]):
        data, self.n_closed = _vertex_data(items)
        self.n_parts = len(items)
        self.n_vertices = len(data)
        # (8, 4) homogeneous corners of the vertices' box, for culling whole meshes per view
        box = (np.array([data[:, :3].min(axis=0), data[:, :3].max(axis=0)], np.float64)
               if len(data) else np.zeros((2, 3)))
        self.corners = np.array([[x, y, z, 1.0] for x in box[:, 0] for y in box[:, 1]
                                 for z in box[:, 2]])
        self.vbo = ctx.buffer(data.tobytes()) if len(data) else None
        if self.vbo is None:
            self.vaos = {}
            return
        self.vaos = {
            "color": ctx.vertex_array(programs["color"], [
                (self.vbo, "3f 3f 3f 2f 4x", "in_pos", "in_normal", "in_color", "in_mat")]),
            "ids": ctx.vertex_array(programs["ids"], [
                (self.vbo, "3f 3f 20x 1f", "in_pos", "in_normal", "in_part")]),
            "shadow": ctx.vertex_array(programs["shadow"], [(self.vbo, "3f 36x", "in_pos")]),
            "mask": ctx.vertex_array(programs["mask"], [(self.vbo, "3f 36x", "in_pos")]),
        }

    def draw(self, ctx, kind: str) -> None:
        """Draw closed meshes with back-face culling (no overdraw from their far sides),
        open ones (cloth, cards) double-sided."""
        vao = self.vaos[kind]
        if self.n_closed:
            ctx.enable(ctx.CULL_FACE)
            vao.render(vertices=self.n_closed)
            ctx.disable(ctx.CULL_FACE)
        if self.n_vertices > self.n_closed:
            vao.render(first=self.n_closed, vertices=self.n_vertices - self.n_closed)

    def release(self) -> None:
        for vao in self.vaos.values():
            vao.release()
        if self.vbo is not None:
            self.vbo.release()


@dataclass
class _Item:
    mesh: _GpuMesh
    model: np.ndarray
    instance: int
    part_base: int
    casts_shadow: bool
    element: str | None = None

    def __post_init__(self) -> None:
        # uniform bytes and the world box corners, made once per draw list however many
        # views draw it
        self.model_bytes = _mat_bytes(self.model)
        self.normal_bytes = _mat_bytes(_normal_matrix(self.model))
        self.corners = self.mesh.corners @ np.asarray(self.model, np.float64).T


#: Relative margin of the view-volume test: a mesh is skipped only when its box lies this
#: far beyond one clip plane, so float32 rounding on the GPU can never make it touch a pixel.
_CULL_MARGIN = 1e-3


def _in_view(items: list[_Item], camera: Camera) -> list[_Item]:
    """The items with geometry that may show in ``camera``'s view, in their order.

    An item is left out when all eight corners of its world box lie beyond the same plane of
    the clip volume (in homogeneous clip coordinates, so also behind the camera): then no
    part of it can reach a pixel or the depth buffer, and the image is the same without it.
    Drawing is per vertex on a CPU rasteriser, so what a corner camera has behind it costs
    as much as what it sees.
    """
    live = [it for it in items if it.mesh.vbo is not None]
    if not live:
        return live
    clip = np.stack([it.corners for it in live]) @ (camera.gl_projection()
                                                    @ camera.gl_view()).T
    w = clip[..., 3:4]
    pad = _CULL_MARGIN * (np.abs(w) + 1e-3)
    xyz = clip[..., :3]
    out = ((xyz < -w - pad).all(axis=1) | (xyz > w + pad).all(axis=1)).any(axis=1)
    return [it for it, o in zip(live, out, strict=True) if not o]


class _Targets:
    """Framebuffers of one image size."""

    def __init__(self, ctx, width: int, height: int, samples: int):
        size = (width, height)
        self.msaa = ctx.framebuffer(
            color_attachments=[ctx.renderbuffer(size, 4, samples=samples)],
            depth_attachment=ctx.depth_renderbuffer(size, samples=samples))
        # without MSAA the colour pass draws straight into ``resolve``: it needs its own depth
        self.resolve = ctx.framebuffer(
            color_attachments=[ctx.renderbuffer(size, 4)],
            depth_attachment=None if samples else ctx.depth_renderbuffer(size))
        self.ids = ctx.framebuffer(
            color_attachments=[ctx.texture(size, 4, dtype="f4"), ctx.texture(size, 4, dtype="f4")],
            depth_attachment=ctx.depth_renderbuffer(size))
        self._all = [self.msaa, self.resolve, self.ids]

    def release(self) -> None:
        for fbo in self._all:
            for a in list(fbo.color_attachments) + [fbo.depth_attachment]:
                if a is not None:
                    a.release()
            fbo.release()


def _mat_bytes(M: np.ndarray) -> bytes:
    """Column-major float32 bytes of a matrix (what GLSL uniforms expect)."""
    return np.ascontiguousarray(np.asarray(M, np.float32).T).tobytes()


def _normal_matrix(model: np.ndarray) -> np.ndarray:
    return np.linalg.inv(model[:3, :3]).T


def _gl_ortho(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """(4, 4) OpenGL orthographic projection of the eye-space box [lo, hi] (z negative ahead)."""
    P = np.eye(4)
    P[0, 0] = 2.0 / (hi[0] - lo[0])
    P[1, 1] = 2.0 / (hi[1] - lo[1])
    P[2, 2] = -2.0 / (hi[2] - lo[2])
    P[0, 3] = -(hi[0] + lo[0]) / (hi[0] - lo[0])
    P[1, 3] = -(hi[1] + lo[1]) / (hi[1] - lo[1])
    P[2, 3] = (hi[2] + lo[2]) / (hi[2] - lo[2])  # eye z = hi (nearest) -> -1, lo -> +1
    return P


def _shell_names(scene: Scene) -> list[str]:
    walls = sorted((n for n in scene.room.elements if n.startswith("wall_")),
                   key=lambda n: int(n.split("_")[1]))
    return [n for n in ["floor", *walls, "ceiling"] if n in scene.room.elements]


def _shell_index(scene: Scene, name: str) -> int:
    return _shell_names(scene).index(name)


def scene_id_tables(scene: Scene) -> tuple[dict[int, str], dict[int, str]]:
    """The instance and part id tables of a scene (what the masks' values mean).

    Returns
    -------
    instances : dict of int to str
        Placed objects (with an asset) ``1..N`` in scene order, then ``floor``, ``wall_0`` ...
        ``wall_{n-1}`` and ``ceiling``.
    parts : dict of int to str
        ``object_id:part_name`` for every part of those objects in order, then
        ``room:floor``, ``room:wall_0`` ... ``room:ceiling``.
    """
    instances: dict[int, str] = {}
    parts: dict[int, str] = {}
    iid = pid = 0
    for o in scene.objects.values():
        if not o.placed or o.asset is None:
            continue
        iid += 1
        instances[iid] = o.id
        for p in o.asset.parts:
            pid += 1
            parts[pid] = f"{o.id}:{p.name}"
    for name in _shell_names(scene):
        iid += 1
        pid += 1
        instances[iid] = name
        parts[pid] = f"room:{name}"
    return instances, parts


class Renderer:
    """Renders scenes and assets; keeps the context and uploaded meshes alive across views.

    Parameters
    ----------
    samples : int
        MSAA samples of the colour pass (clamped to what the driver offers; 0 or 1 = none).
    lighting : Lighting
    room_style : RoomStyle
    cache_size : int
        How many uploaded assets to keep (least recently used ones are released).

    Examples
    --------
    >>> r = Renderer()                                    # doctest: +SKIP
    >>> res = r.render(scene, overview_camera(scene))     # doctest: +SKIP
    >>> res.rgb.shape, res.depth.dtype                    # doctest: +SKIP
    ((480, 640, 3), dtype('float32'))

    Notes
    -----
    An OpenGL context belongs to the process that created it: create renderers after
    forking worker processes, not before.
    """

    def __init__(self, *, samples: int = 4, lighting: Lighting = Lighting(),
                 room_style: RoomStyle = RoomStyle(), cache_size: int = 512):
        self.ctx = create_context()
        self.samples = int(min(max(samples, 0), self.ctx.max_samples))
        if self.samples == 1:
            self.samples = 0
        self.lighting = lighting
        self.room_style = room_style
        self.cache_size = int(cache_size)
        self.programs = {
            "shadow": self.ctx.program(vertex_shader=shaders.SHADOW_VS,
                                       fragment_shader=shaders.SHADOW_FS),
            "color": self.ctx.program(vertex_shader=shaders.COLOR_VS,
                                      fragment_shader=shaders.COLOR_FS),
            "ids": self.ctx.program(vertex_shader=shaders.IDS_VS, fragment_shader=shaders.IDS_FS),
            "mask": self.ctx.program(vertex_shader=shaders.MASK_VS,
                                     fragment_shader=shaders.MASK_FS),
        }
        # owner object (kept alive so its id() stays unique) and its uploaded mesh
        self._meshes: OrderedDict[tuple, tuple[object, _GpuMesh]] = OrderedDict()
        self._targets: dict[tuple[int, int], _Targets] = {}
        size = int(lighting.shadow_size)
        self._shadow_tex = self.ctx.depth_texture((size, size))
        self._shadow_tex.compare_func = "<="
        self._shadow_tex.repeat_x = False
        self._shadow_tex.repeat_y = False
        self._shadow_fbo = self.ctx.framebuffer(depth_attachment=self._shadow_tex)
        self._shadow_key: bytes | None = None
        self._light_vp = np.eye(4)
        self._shadow_offset = 0.0
        self._shadow_texel = 1.0 / size
        self._set_static_uniforms()

    # -- set-up ---------------------------------------------------------------------------
    def _set_static_uniforms(self) -> None:
        L = self.lighting
        p = self.programs["color"]
        p["u_light_dir"].value = tuple(np.asarray(L.key_direction) / np.linalg.norm(L.key_direction))
        p["u_light_color"].value = tuple(L.key_color)
        p["u_fill_dir"].value = tuple(np.asarray(L.fill_direction) / np.linalg.norm(L.fill_direction))
        p["u_fill_color"].value = tuple(L.fill_color)
        p["u_sky"].value = tuple(L.sky)
        p["u_ground"].value = tuple(L.ground)
        p["u_exposure"].value = float(L.exposure)
        p["u_shadow_texel"].value = self._shadow_texel
        p["u_shadow"].value = 0

    def _mesh(self, key: tuple, owner: object,
              items: list[tuple[_Mesh, Material]]) -> _GpuMesh:
        hit = self._meshes.get(key)
        if hit is not None and hit[0] is owner:
            self._meshes.move_to_end(key)
            return hit[1]
        if hit is not None:
            hit[1].release()
        gm = _GpuMesh(self.ctx, self.programs, items)
        self._meshes[key] = (owner, gm)
        while len(self._meshes) > self.cache_size:
            _, (_, old) = self._meshes.popitem(last=False)
            old.release()
        return gm

    def _asset_mesh(self, asset: Asset) -> _GpuMesh:
        # the arrays a loaded part holds: no trimesh.Trimesh is made for drawing it
        return self._mesh(("asset", id(asset)), asset,
                          [(p.mesh_arrays, p.material) for p in asset.parts])

    def _shell_mesh(self, room: RoomShell, name: str) -> _GpuMesh:
        el = room.elements[name]
        return self._mesh(("shell", id(room), name), room,
                          [(el.mesh_arrays, self.room_style.material(name))])

    def _target(self, width: int, height: int) -> _Targets:
        t = self._targets.get((width, height))
        if t is None:
            if len(self._targets) >= 4:
                for old in self._targets.values():
                    old.release()
                self._targets.clear()
            t = _Targets(self.ctx, width, height, self.samples)
            self._targets[(width, height)] = t
        return t

    # -- draw lists -----------------------------------------------------------------------
    def _scene_items(self, scene: Scene, settled: bool | None
                     ) -> tuple[list[_Item], dict[int, str], dict[int, str]]:
        instances, parts = scene_id_tables(scene)
        # every mesh of this frame must stay uploaded while it is drawn
        self.cache_size = max(self.cache_size, len(instances) + 1)
        first_part = {}
        for pid, name in parts.items():
            first_part.setdefault(name.split(":", 1)[0], pid)
        items: list[_Item] = []
        for iid, oid in instances.items():
            if oid in scene.objects and scene.objects[oid].asset is not None:
                o = scene.objects[oid]
                items.append(_Item(self._asset_mesh(o.asset), o.transform(settled), iid,
                                   first_part[oid], True))
            else:
                items.append(_Item(self._shell_mesh(scene.room, oid), np.eye(4), iid,
                                   first_part["room"] + _shell_index(scene, oid), False, oid))
        return items, instances, parts

    @staticmethod
    def _shell_visible(room: RoomShell, name: str, camera: Camera) -> bool:
        s = room.elements[name].surface
        return float(np.dot(camera.position - s.origin, s.normal)) > -1e-6

    # -- shadows --------------------------------------------------------------------------
    def _update_shadow(self, items: list[_Item], bounds: np.ndarray) -> None:
        casters = [it for it in items if it.casts_shadow and it.mesh.vbo is not None]
        h = hashlib.blake2b(digest_size=16)
        h.update(np.asarray(bounds, np.float64).tobytes())
        for it in casters:
            h.update(np.array([id(it.mesh), it.mesh.n_vertices], np.uint64).tobytes())
            h.update(np.asarray(it.model, np.float64).tobytes())
        key = h.digest()
        if key == self._shadow_key:
            return
        L = np.asarray(self.lighting.key_direction, float)
        L /= np.linalg.norm(L)
        centre = bounds.mean(axis=0)
        radius = float(np.linalg.norm(bounds[1] - bounds[0])) / 2 + 1e-3
        R, t = look_at(centre + L * 2 * radius, centre)
        view = np.eye(4)
        view[:3, :3] = np.diag([1.0, -1.0, -1.0]) @ R
        view[:3, 3] = np.diag([1.0, -1.0, -1.0]) @ t
        corners = np.array([[x, y, z] for x in bounds[:, 0] for y in bounds[:, 1]
                            for z in bounds[:, 2]])
        e = corners @ view[:3, :3].T + view[:3, 3]
        lo, hi = e.min(axis=0) - 0.05, e.max(axis=0) + 0.05
        proj = _gl_ortho(lo, hi)
        self._light_vp = proj @ view
        texel_world = max(hi[0] - lo[0], hi[1] - lo[1]) / self.lighting.shadow_size
        self._shadow_offset = 1.5 * texel_world
        self._shadow_fbo.use()
        self._shadow_fbo.clear(depth=1.0)
        self.ctx.enable(self.ctx.DEPTH_TEST)
        prog = self.programs["shadow"]
        prog["u_light_vp"].write(_mat_bytes(self._light_vp))
        for it in casters:
            prog["u_model"].write(it.model_bytes)
            it.mesh.vaos["shadow"].render()  # both sides: thin parts must still cast
        self._shadow_key = key

    # -- drawing --------------------------------------------------------------------------
    def _begin(self) -> None:
        self.ctx.enable(self.ctx.DEPTH_TEST)
        self.ctx.disable(self.ctx.CULL_FACE)

    def _draw_color(self, items: list[_Item], camera: Camera, *, shadows: bool) -> np.ndarray:
        """The colour pass: (H, W, 3) uint8 sRGB."""
        W, H = camera.width, camera.height
        tg = self._target(W, H)
        ctx = self.ctx
        self._begin()
        items = _in_view(items, camera)
        p = self.programs["color"]
        bg = self.lighting.background
        fbo = tg.msaa if self.samples else tg.resolve
        fbo.use()
        fbo.clear(bg[0], bg[1], bg[2], 1.0, depth=1.0)
        p["u_view_proj"].write(_mat_bytes(camera.gl_projection() @ camera.gl_view()))
        p["u_eye"].value = tuple(float(x) for x in camera.position)
        p["u_ortho"].value = camera.orthographic
        p["u_view_dir"].value = tuple(float(x) for x in camera.forward)
        p["u_light_vp"].write(_mat_bytes(self._light_vp))
        p["u_shadow_offset"].value = float(self._shadow_offset)
        p["u_shadows"].value = bool(shadows)
        self._shadow_tex.use(location=0)
        for it in items:
            if it.mesh.vbo is None:
                continue
            p["u_model"].write(it.model_bytes)
            p["u_normal_mat"].write(it.normal_bytes)
            it.mesh.draw(ctx, "color")
        if self.samples:
            ctx.copy_framebuffer(tg.resolve, tg.msaa)
        raw = tg.resolve.read(components=3, alignment=1)
        return np.frombuffer(raw, np.uint8).reshape(H, W, 3)[::-1].copy()

    def _draw_ids(self, items: list[_Item], camera: Camera, *,
                  full: bool = True) -> tuple[np.ndarray, np.ndarray | None]:
        """The id pass: (H, W, 4) float32 instance, part, depth and the (H, W, 4) normal
        attachment, rows from the top; without ``full`` the instance channel alone is drawn
        (the others zero) and no normals are read."""
        W, H = camera.width, camera.height
        tg = self._target(W, H)
        ctx = self.ctx
        self._begin()
        items = _in_view(items, camera)
        kind = "ids" if full else "mask"
        p = self.programs[kind]
        tg.ids.use()
        tg.ids.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        p["u_view"].write(_mat_bytes(camera.gl_view()))
        p["u_proj"].write(_mat_bytes(camera.gl_projection()))
        for it in items:
            if it.mesh.vbo is None:
                continue
            p["u_model"].write(it.model_bytes)
            p["u_instance"].value = float(it.instance)
            if full:
                p["u_normal_mat"].write(it.normal_bytes)
                p["u_part_base"].value = float(it.part_base)
            it.mesh.draw(ctx, kind)
        ids = np.frombuffer(tg.ids.read(components=4, attachment=0, dtype="f4", alignment=1),
                            np.float32).reshape(H, W, 4)[::-1]
        if not full:
            return ids, None
        nrm = np.frombuffer(tg.ids.read(components=4, attachment=1, dtype="f4", alignment=1),
                            np.float32).reshape(H, W, 4)[::-1]
        return ids, nrm

    def _draw(self, items: list[_Item], camera: Camera, *, color: bool,
              shadows: bool) -> tuple[np.ndarray | None, np.ndarray, np.ndarray]:
        rgb = self._draw_color(items, camera, shadows=shadows) if color else None
        ids, nrm = self._draw_ids(items, camera)
        return rgb, ids, nrm

    @staticmethod
    def _result(rgb, ids, nrm, camera, instances, parts) -> RenderResult:
        return RenderResult(
            rgb=rgb,
            depth=np.ascontiguousarray(ids[..., 2], dtype=np.float32),
            instance=np.rint(ids[..., 0]).astype(np.int32),
            part=np.rint(ids[..., 1]).astype(np.int32),
            normals=np.ascontiguousarray(nrm[..., :3], dtype=np.float32),
            camera=camera,
            instances=instances,
            parts=parts,
        )

    # -- public ---------------------------------------------------------------------------
    def render(self, scene: Scene, camera: Camera, *, settled: bool | None = None,
               color: bool = True, shadows: bool = True) -> RenderResult:
        """Render one view of a scene.

        Parameters
        ----------
        scene : Scene
        camera : Camera
        settled : bool or None
            Object poses to use: ``None`` the settled pose where there is one, ``True``
            settled only, ``False`` the solved pose.
        color : bool
            Run the colour pass (``rgb`` is None otherwise; masks, depth and normals are
            always rendered).
        shadows : bool
            Shadow mapping of the key light.

        Returns
        -------
        RenderResult
            Instance ids: placed objects ``1..N`` in scene order, then ``floor``, ``wall_0``
            ... and ``ceiling``; part ids number every object's parts in order, then one per
            shell element (``room:floor`` ...). 0 is background in both.
        """
        with self.ctx:  # several renderers may live in one process: make ours current
            return self._render_scene(scene, camera, settled=settled, color=color,
                                      shadows=shadows)

    def _render_scene(self, scene: Scene, camera: Camera, *, settled: bool | None, color: bool,
                      shadows: bool) -> RenderResult:
        items, instances, parts = self._scene_items(scene, settled)
        if color and shadows:
            self._scene_shadow(scene, items, settled)
        rgb, ids, nrm = self._draw(self._visible(scene, items, camera), camera, color=color,
                                   shadows=shadows)
        return self._result(rgb, ids, nrm, camera, instances, parts)

    def _visible(self, scene: Scene, items: list[_Item], camera: Camera) -> list[_Item]:
        return [it for it in items
                if it.element is None or self._shell_visible(scene.room, it.element, camera)]

    def _scene_shadow(self, scene: Scene, items: list[_Item], settled: bool | None) -> None:
        """The key light's shadow map over the room and every placed object."""
        fp = scene.room.footprint
        lo = np.r_[fp.min(axis=0), 0.0]
        hi = np.r_[fp.max(axis=0), scene.room.height]
        obj_b = [o.world_bounds(settled) for o in scene.placed if o.asset is not None]
        if obj_b:
            ob = np.array(obj_b)
            lo = np.minimum(lo, ob[:, 0].min(axis=0))
            hi = np.maximum(hi, ob[:, 1].max(axis=0))
        self._update_shadow(items, np.array([lo, hi]))

    def render_rgb(self, scene: Scene, camera: Camera, *, settled: bool | None = None,
                   shadows: bool = True) -> np.ndarray:
        """The colour image of one view, nothing else: (H, W, 3) uint8 sRGB, the same pixels
        as ``render(scene, camera).rgb`` without the id, depth and normal pass (previews)."""
        with self.ctx:
            items, _, _ = self._scene_items(scene, settled)
            if shadows:
                self._scene_shadow(scene, items, settled)
            return self._draw_color(self._visible(scene, items, camera), camera,
                                    shadows=shadows)

    def instance_masks(self, scene: Scene, cameras: list[Camera], *,
                       settled: bool | None = None) -> list[np.ndarray]:
        """The instance masks of several views of one scene, nothing else: (H, W) int32 each,
        the same as ``render(scene, camera, color=False).instance``; the draw list is made
        once for all of them (choosing a viewpoint among candidates)."""
        with self.ctx:
            items, _, _ = self._scene_items(scene, settled)
            out = []
            for cam in cameras:
                ids, _ = self._draw_ids(self._visible(scene, items, cam), cam, full=False)
                out.append(np.rint(ids[..., 0]).astype(np.int32))
        return out

    def render_asset(self, asset: Asset, camera: Camera, *, color: bool = True,
                     shadows: bool = True) -> RenderResult:
        """Render one asset in its canonical frame (instance id 1, part ids ``1..P`` in the
        order of ``asset.parts``)."""
        with self.ctx:
            return self._render_asset(asset, camera, color=color, shadows=shadows)

    def _render_asset(self, asset: Asset, camera: Camera, *, color: bool,
                      shadows: bool) -> RenderResult:
        item = _Item(self._asset_mesh(asset), np.eye(4), 1, 1, True)
        instances = {1: asset.asset_id}
        parts = {k + 1: f"{asset.asset_id}:{p.name}" for k, p in enumerate(asset.parts)}
        if color and shadows:
            b = asset.bounds
            pad = 0.05 * max(float(np.max(b[1] - b[0])), 1e-3)
            self._update_shadow([item], np.array([b[0] - pad, b[1] + pad]))
        rgb, ids, nrm = self._draw([item], camera, color=color, shadows=shadows)
        return self._result(rgb, ids, nrm, camera, instances, parts)

    def release(self) -> None:
        """Free every GPU object and the context."""
        with self.ctx:
            for _, gm in self._meshes.values():
                gm.release()
            self._meshes.clear()
            for t in self._targets.values():
                t.release()
            self._targets.clear()
        self.ctx.release()


_DEFAULT: Renderer | None = None


def default_renderer() -> Renderer:
    """The process's shared renderer, created on first use."""
    global _DEFAULT
    if _DEFAULT is None:
        _DEFAULT = Renderer()
    return _DEFAULT


def render_scene(scene: Scene, camera: Camera, *, settled: bool | None = None,
                 renderer: Renderer | None = None) -> RenderResult:
    """Render one view of ``scene`` (see :meth:`Renderer.render`) with the shared renderer."""
    r = renderer if renderer is not None else default_renderer()
    return r.render(scene, camera, settled=settled)


def render_asset(asset: Asset, *, size: tuple[int, int] = (256, 256), camera: Camera | None = None,
                 renderer: Renderer | None = None) -> RenderResult:
    """Render an asset, by default in a 3/4 view from its front-right (thumbnails).

    Parameters
    ----------
    asset : Asset
    size : (width, height)
        Image size in pixels (ignored when ``camera`` is given).
    camera : Camera or None
        Defaults to :func:`parse3d.render.camera.asset_camera` framing the asset's bounds.
    """
    if camera is None:
        camera = asset_camera(asset.bounds, width=int(size[0]), height=int(size[1]))
    r = renderer if renderer is not None else default_renderer()
    return r.render_asset(asset, camera)
