"""Cameras: pinhole (and orthographic) cameras with OpenCV conventions, and view presets.

Conventions
-----------
* **Intrinsics** ``K = [[fx, 0, cx], [0, fy, cy], [0, 0, 1]]`` in pixels. The centre of the
  top-left pixel is ``(u, v) = (0, 0)``; ``u`` grows to the right, ``v`` grows downwards
  (OpenCV). Pixel ``(u, v)`` covers ``[u - 0.5, u + 0.5] x [v - 0.5, v + 0.5]``.
* **Extrinsics** are world-to-camera: ``x_cam = R @ x_world + t``. The camera frame is
  OpenCV's: +x right, +y down, +z forward (the optical axis). The camera centre in the world
  is ``-R.T @ t``.
* **Perspective** projection: ``u = fx * x / z + cx``, ``v = fy * y / z + cy``.
* **Orthographic** projection (``projection="orthographic"``, used by :func:`plan_camera`):
  ``u = fx * x + cx``, ``v = fy * y + cy``; ``fx`` and ``fy`` are then pixels per metre and
  the rays through all pixels are parallel to the camera's +z axis, starting on the camera's
  image plane (``z = 0`` in the camera frame).
* **Depth** everywhere in :mod:`parse3d.render` is the camera-frame ``z`` of the surface
  (distance along the optical axis, not along the ray), metres.
* ``near`` and ``far`` (metres, along +z) clip what is rendered.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from shapely import contains_xy
from shapely.geometry import Polygon

from ..errors import InputError
from ..scene.model import Scene

__all__ = [
    "Camera",
    "look_at",
    "intrinsics_from_fov",
    "overview_camera",
    "view_rng",
    "VIEW_STAGE",
    "overview_candidates",
    "plan_camera",
    "asset_camera",
    "sample_views",
    "ViewSampling",
]

#: OpenCV camera axes expressed in OpenGL eye axes (x right, y up, z backwards).
_CV_TO_GL = np.diag([1.0, -1.0, -1.0])

PROJECTIONS = ("perspective", "orthographic")


@dataclass(eq=False)
class Camera:
    """A camera: intrinsics, world-to-camera extrinsics, image size and clip range.

    Attributes
    ----------
    K : (3, 3) float
        Intrinsics in pixels (``fx, fy, cx, cy``; see the module docstring).
    R : (3, 3) float
        World-to-camera rotation (rows are the camera's x, y, z axes in world coordinates).
    t : (3,) float
        World-to-camera translation, metres.
    width, height : int
        Image size in pixels.
    near, far : float
        Clip distances along the optical axis, metres.
    projection : str
        ``perspective`` or ``orthographic``.
    """

    K: np.ndarray
    R: np.ndarray
    t: np.ndarray
    width: int
    height: int
    near: float = 0.05
    far: float = 100.0
    projection: str = "perspective"
    meta: dict[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        self.K = np.asarray(self.K, float).reshape(3, 3)
        self.R = np.asarray(self.R, float).reshape(3, 3)
        self.t = np.asarray(self.t, float).reshape(3)
        self.width, self.height = int(self.width), int(self.height)
        if self.width < 1 or self.height < 1:
            raise InputError(f"camera size must be positive, got {self.width}x{self.height}")
        if self.projection not in PROJECTIONS:
            raise InputError(f"camera projection must be one of {PROJECTIONS}, "
                             f"got {self.projection!r}")
        if not 0 < self.near < self.far:
            raise InputError(f"camera clip range needs 0 < near < far, got {self.near}, {self.far}")

    # -- intrinsics -----------------------------------------------------------------------
    @property
    def fx(self) -> float:
        return float(self.K[0, 0])

    @property
    def fy(self) -> float:
        return float(self.K[1, 1])

    @property
    def cx(self) -> float:
        return float(self.K[0, 2])

    @property
    def cy(self) -> float:
        return float(self.K[1, 2])

    @property
    def orthographic(self) -> bool:
        return self.projection == "orthographic"

    # -- extrinsics -----------------------------------------------------------------------
    @property
    def position(self) -> np.ndarray:
        """(3,) camera centre in the world, metres."""
        return -self.R.T @ self.t

    @property
    def forward(self) -> np.ndarray:
        """(3,) unit optical axis (+z of the camera) in the world frame."""
        return self.R[2].copy()

    @property
    def world_to_camera(self) -> np.ndarray:
        """(4, 4) world-to-camera transform (OpenCV camera frame)."""
        T = np.eye(4)
        T[:3, :3] = self.R
        T[:3, 3] = self.t
        return T

    @property
    def camera_to_world(self) -> np.ndarray:
        """(4, 4) camera-to-world transform (the camera's pose)."""
        T = np.eye(4)
        T[:3, :3] = self.R.T
        T[:3, 3] = self.position
        return T

    # -- OpenGL ---------------------------------------------------------------------------
    def gl_view(self) -> np.ndarray:
        """(4, 4) world-to-eye matrix in OpenGL's eye convention (x right, y up, z back)."""
        T = np.eye(4)
        T[:3, :3] = _CV_TO_GL @ self.R
        T[:3, 3] = _CV_TO_GL @ self.t
        return T

    def gl_projection(self) -> np.ndarray:
        """(4, 4) OpenGL projection matrix reproducing ``K`` exactly.

        Maps eye coordinates to clip space so that, after the viewport transform and a
        vertical flip of the read-back image, the point at camera-frame ``(x, y, z)`` lands on
        pixel coordinates ``(u, v)`` of the module docstring (OpenGL pixel centres sit at
        half-integers, hence the ``+ 0.5``).
        """
        W, H = self.width, self.height
        n, f = self.near, self.far
        ax = 2.0 * self.fx / W
        ay = 2.0 * self.fy / H
        bx = 2.0 * (self.cx + 0.5) / W - 1.0
        by = 1.0 - 2.0 * (self.cy + 0.5) / H
        P = np.zeros((4, 4))
        if self.orthographic:
            P[0, 0], P[0, 3] = ax, bx
            P[1, 1], P[1, 3] = ay, by
            P[2, 2], P[2, 3] = -2.0 / (f - n), -(f + n) / (f - n)
            P[3, 3] = 1.0
        else:
            P[0, 0], P[0, 2] = ax, -bx
            P[1, 1], P[1, 2] = ay, -by
            P[2, 2], P[2, 3] = -(f + n) / (f - n), -2.0 * f * n / (f - n)
            P[3, 2] = -1.0
        return P

    # -- geometry -------------------------------------------------------------------------
    def project(self, points) -> tuple[np.ndarray, np.ndarray]:
        """Project world points.

        Parameters
        ----------
        points : (N, 3) float
            World points, metres.

        Returns
        -------
        uv : (N, 2) float
            Pixel coordinates (OpenCV).
        z : (N,) float
            Camera-frame depth, metres (negative behind the camera).
        """
        p = np.asarray(points, float).reshape(-1, 3) @ self.R.T + self.t
        z = p[:, 2]
        if self.orthographic:
            uv = p[:, :2] * [self.fx, self.fy] + [self.cx, self.cy]
        else:
            with np.errstate(divide="ignore", invalid="ignore"):
                uv = p[:, :2] / z[:, None] * [self.fx, self.fy] + [self.cx, self.cy]
        return uv, z

    def rays(self, uv) -> tuple[np.ndarray, np.ndarray]:
        """World rays through pixel coordinates.

        Parameters
        ----------
        uv : (N, 2) float
            Pixel coordinates (OpenCV; integers are pixel centres).

        Returns
        -------
        origins : (N, 3) float
            Ray origins: the camera centre, or points on the image plane for orthographic
            cameras.
        directions : (N, 3) float
            Directions, scaled so that moving ``d`` units along one changes the camera-frame
            depth by ``d`` (i.e. camera-frame ``z`` component 1). Normalise for unit rays.
        """
        uv = np.asarray(uv, float).reshape(-1, 2)
        x = (uv[:, 0] - self.cx) / self.fx
        y = (uv[:, 1] - self.cy) / self.fy
        Rt = self.R.T
        if self.orthographic:
            pc = np.c_[x, y, np.zeros_like(x)]
            origins = pc @ Rt.T + self.position
            directions = np.tile(self.R[2], (len(uv), 1))
        else:
            dc = np.c_[x, y, np.ones_like(x)]
            origins = np.tile(self.position, (len(uv), 1))
            directions = dc @ Rt.T
        return origins, directions

    def resized(self, width: int, height: int) -> Camera:
        """The same camera at another image size (intrinsics scaled with the image)."""
        sx, sy = width / self.width, height / self.height
        K = self.K.copy()
        K[0, 0] *= sx
        K[1, 1] *= sy
        K[0, 2] = (K[0, 2] + 0.5) * sx - 0.5
        K[1, 2] = (K[1, 2] + 0.5) * sy - 0.5
        return Camera(K, self.R, self.t, width, height, self.near, self.far, self.projection,
                      dict(self.meta))

    # -- files ----------------------------------------------------------------------------
    def to_dict(self) -> dict[str, Any]:
        """JSON form (``views.json``): intrinsics, extrinsics and both 4x4 transforms."""
        return {
            "projection": self.projection,
            "width": self.width,
            "height": self.height,
            "K": [[float(x) for x in row] for row in self.K],
            "fx": self.fx, "fy": self.fy, "cx": self.cx, "cy": self.cy,
            "R": [[float(x) for x in row] for row in self.R],
            "t": [float(x) for x in self.t],
            "world_to_camera": [[float(x) for x in row] for row in self.world_to_camera],
            "camera_to_world": [[float(x) for x in row] for row in self.camera_to_world],
            "position": [float(x) for x in self.position],
            "near": float(self.near),
            "far": float(self.far),
            "convention": "opencv",
            "meta": dict(self.meta),
        }

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Camera:
        return cls(np.asarray(d["K"], float), np.asarray(d["R"], float),
                   np.asarray(d["t"], float), int(d["width"]), int(d["height"]),
                   float(d.get("near", 0.05)), float(d.get("far", 100.0)),
                   d.get("projection", "perspective"), dict(d.get("meta", {})))


def intrinsics_from_fov(width: int, height: int, fov_deg: float) -> np.ndarray:
    """(3, 3) intrinsics with square pixels, ``fov_deg`` horizontal field of view and the
    principal point at the image centre."""
    f = 0.5 * width / np.tan(np.deg2rad(fov_deg) / 2.0)
    return np.array([[f, 0.0, (width - 1) / 2.0], [0.0, f, (height - 1) / 2.0], [0, 0, 1.0]])


def look_at(eye, target, up=(0.0, 0.0, 1.0)) -> tuple[np.ndarray, np.ndarray]:
    """World-to-camera ``(R, t)`` of an OpenCV camera at ``eye`` looking at ``target``.

    Image "up" (−y of the camera) is as close to ``up`` as possible; when the view direction
    is parallel to ``up``, world +Y is used as image up instead.
    """
    eye = np.asarray(eye, float)
    z = np.asarray(target, float) - eye
    z /= np.linalg.norm(z)
    up = np.asarray(up, float)
    x = np.cross(z, up)
    if np.linalg.norm(x) < 1e-6:
        x = np.cross(z, [0.0, 1.0, 0.0])
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    R = np.vstack([x, y, z])
    return R, -R @ eye


def _scene_far(scene: Scene) -> float:
    fp = scene.room.footprint
    diag = float(np.linalg.norm(fp.max(axis=0) - fp.min(axis=0)))
    return max(20.0, 2.0 * np.hypot(diag, scene.room.height) + 5.0)


def _box_distance(p: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """(N,) distances from point ``p`` to (N, 2, 3) axis-aligned boxes (0 inside)."""
    d = np.maximum(np.maximum(boxes[:, 0] - p, p - boxes[:, 1]), 0.0)
    return np.linalg.norm(d, axis=1)


#: Largest share of the frame one object may cover in the overview (its projected box).
MAX_OBJECT_SHARE = 0.30
#: Where overview candidates stand: metres from a corner towards the centroid.
_INSETS = (0.35, 0.9, 1.5)


def _frame_shares(cam: Camera, boxes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per box: the share of the frame its projected bounding box covers (1 when the box
    reaches behind the camera), and whether its centre projects inside the frame."""
    n = len(boxes)
    if n == 0:
        return np.zeros(0), np.zeros(0, bool)
    idx = np.array([[i >> 2 & 1, i >> 1 & 1, i & 1] for i in range(8)])
    corners = boxes[:, idx, [0, 1, 2]]                       # (N, 8, 3)
    uv, z = cam.project(corners.reshape(-1, 3))
    uv, z = uv.reshape(n, 8, 2), z.reshape(n, 8)
    behind = (z <= cam.near).any(axis=1)
    lo = np.clip(np.nan_to_num(uv.min(axis=1)), 0, [cam.width, cam.height])
    hi = np.clip(np.nan_to_num(uv.max(axis=1)), 0, [cam.width, cam.height])
    share = np.prod(np.maximum(hi - lo, 0), axis=1) / float(cam.width * cam.height)
    share = np.where(behind, 1.0, share)
    cuv, cz = cam.project(boxes.mean(axis=1))
    inside = (cz > cam.near) & (cuv[:, 0] >= 0) & (cuv[:, 0] < cam.width) \
        & (cuv[:, 1] >= 0) & (cuv[:, 1] < cam.height)
    return share, inside


#: Stage tag of the view-sampling generator (``"REND"``): ``default_rng([seed, VIEW_STAGE])``.
VIEW_STAGE = 0x52454E44


def view_rng(seed: int) -> np.random.Generator:
    """The generator ``parse3d render --seed S`` and dataset builds sample views with."""
    return np.random.default_rng([int(seed), VIEW_STAGE])


def overview_candidates(scene: Scene, *, width: int = 640, height: int = 480,
                        fov_deg: float = 75.0, eye_height: float = 1.6,
                        settled: bool | None = None) -> list[Camera]:
    """Overview viewpoints, best first by what their frames are expected to show.

    Candidates stand 0.35, 0.9 or 1.5 m from each footprint corner towards the centroid, at
    ``eye_height`` (capped 0.15 m below the ceiling), and look at the centroid at 0.5 m
    height. They are ordered by projecting every object's bounding box: first those where no
    object covers more than :data:`MAX_OBJECT_SHARE` of the frame (a near object hides the
    room), then by the objects whose centre falls in the frame, then by the clearance to the
    nearest object (beyond 1.5 m all equal), then by the distance to the centroid (ties:
    corner order, then the nearest inset). ``meta["share"]`` and ``meta["in_frame"]`` hold
    the estimates.
    """
    fp = scene.room.footprint
    poly = Polygon(fp)
    c = np.asarray(poly.centroid.coords[0])
    boxes = np.array([o.world_bounds(settled) for o in scene.placed
                      if o.asset is not None]).reshape(-1, 2, 3)
    K = intrinsics_from_fov(width, height, fov_deg)
    far = _scene_far(scene)
    target = [c[0], c[1], 0.5]
    z = min(eye_height, scene.room.height - 0.15)
    scored = []
    for i, corner in enumerate(fp):
        inward = c - corner
        dist = float(np.linalg.norm(inward))
        if dist < 1e-9:
            continue
        for j, inset in enumerate(_INSETS):
            if j and inset >= 0.8 * dist:
                continue
            xy = corner + inset * inward / dist
            if not poly.contains(_point(xy)):
                continue
            eye = np.array([xy[0], xy[1], z])
            R, t = look_at(eye, target)
            share, inside = _frame_shares(Camera(K, R, t, width, height, 0.05, far), boxes)
            top = float(share.max()) if len(share) else 0.0
            clear = float(_box_distance(eye, boxes).min()) if len(boxes) else np.inf
            ok = top <= MAX_OBJECT_SHARE
            key = (ok, int(inside.sum()) if ok else -round(top, 3),
                   round(min(clear, 1.5), 3), round(float(np.linalg.norm(c - xy)), 6),
                   -i, -j)
            cam = Camera(K, R, t, width, height, 0.05, far, "perspective",
                         {"preset": "overview", "share": round(top, 4),
                          "in_frame": int(inside.sum())})
            scored.append((key, cam))
    if not scored:
        eye = np.array([c[0], c[1], z]) + [0.01, 0.01, 0.0]
        R, t = look_at(eye, target)
        return [Camera(K, R, t, width, height, 0.05, far, "perspective",
                       {"preset": "overview"})]
    scored.sort(key=lambda kc: kc[0], reverse=True)
    return [cam for _, cam in scored]


def overview_camera(scene: Scene, *, width: int = 640, height: int = 480,
                    fov_deg: float = 75.0, eye_height: float = 1.6,
                    settled: bool | None = None) -> Camera:
    """The best of :func:`overview_candidates` (chosen without rendering).

    :func:`parse3d.render.preview_camera` refines the choice by rendering the candidates.
    """
    return overview_candidates(scene, width=width, height=height, fov_deg=fov_deg,
                               eye_height=eye_height, settled=settled)[0]


def plan_camera(scene: Scene, *, width: int = 640, height: int = 480,
                margin: float = 0.3) -> Camera:
    """A top-down orthographic camera framing the room footprint.

    The camera looks straight down (−Z) from 1 m above the ceiling; image right is world +X
    and image up is world +Y. ``fx = fy`` are pixels per metre, chosen so the footprint plus
    ``margin`` metres fits the image.
    """
    fp = scene.room.footprint
    lo, hi = fp.min(axis=0) - margin, fp.max(axis=0) + margin
    size = hi - lo
    s = min(width / size[0], height / size[1])
    centre = (lo + hi) / 2
    h = scene.room.height + 1.0
    R = np.array([[1.0, 0, 0], [0, -1.0, 0], [0, 0, -1.0]])
    eye = np.array([centre[0], centre[1], h])
    t = -R @ eye
    K = np.array([[s, 0, (width - 1) / 2.0], [0, s, (height - 1) / 2.0], [0, 0, 1.0]])
    return Camera(K, R, t, width, height, 0.05, h + 1.0, "orthographic", {"preset": "plan"})


def asset_camera(bounds, *, width: int, height: int, fov_deg: float = 35.0,
                 azimuth_deg: float = 35.0, elevation_deg: float = 25.0) -> Camera:
    """A 3/4 view of a box from the front-right (the asset frame's +Y front, +X right).

    Parameters
    ----------
    bounds : (2, 3) float
        The box to frame, metres.
    azimuth_deg : float
        Rotation of the view direction from the front (+Y) towards the right (+X).
    elevation_deg : float
        Angle above the horizontal.
    """
    b = np.asarray(bounds, float)
    centre = b.mean(axis=0)
    radius = max(float(np.linalg.norm(b[1] - b[0])) / 2.0, 1e-3)
    K = intrinsics_from_fov(width, height, fov_deg)
    half = min(np.arctan(width / (2 * K[0, 0])), np.arctan(height / (2 * K[1, 1])))
    dist = radius / np.sin(half) * 1.05
    az, el = np.deg2rad(azimuth_deg), np.deg2rad(elevation_deg)
    direction = np.array([np.sin(az) * np.cos(el), np.cos(az) * np.cos(el), np.sin(el)])
    eye = centre + dist * direction
    R, t = look_at(eye, centre)
    return Camera(K, R, t, width, height, max(1e-3, dist - 2 * radius), dist + 2 * radius,
                  "perspective", {"preset": "asset"})


def _point(xy):
    from shapely.geometry import Point

    return Point(float(xy[0]), float(xy[1]))


@dataclass(frozen=True)
class ViewSampling:
    """Acceptance rules of :func:`sample_views`.

    Attributes
    ----------
    height_range : (2,) float
        Camera height above the floor, metres.
    wall_margin : float
        Minimum horizontal distance from the camera to the footprint boundary, metres.
    object_margin : float
        The camera stays this far outside every object's world bounding box, metres.
    min_clearance : float
        No surface closer than this (camera-frame depth) in the central third of the image.
    max_near_fraction : float
        At most this fraction of the image may be closer than ``min_clearance / 2``.
    min_objects : int
        Objects (not room elements) that must be visible ...
    min_pixels : int
        ... with at least this many pixels each in the instance mask.
    fov_deg : float
        Horizontal field of view.
    max_pitch_deg : float
        The optical axis points at most this far below the horizontal.
    attempts_per_view : int
        Candidate budget per requested view before the best rejected candidates are used.
    """

    height_range: tuple[float, float] = (1.2, 1.8)
    wall_margin: float = 0.25
    object_margin: float = 0.05
    min_clearance: float = 1.0
    max_near_fraction: float = 0.05
    min_objects: int = 3
    min_pixels: int = 200
    fov_deg: float = 70.0
    max_pitch_deg: float = 50.0
    attempts_per_view: int = 40


def sample_views(scene: Scene, n: int, rng: np.random.Generator, *, width: int = 640,
                 height: int = 480, rules: ViewSampling = ViewSampling(),
                 settled: bool | None = None, renderer=None) -> list[Camera]:
    """``n`` cameras inside the room looking at clusters of objects.

    Each candidate stands inside the footprint (``rules.wall_margin`` from the walls), at a
    height in ``rules.height_range`` and outside every object's bounding box; it looks at the
    centroid of a random object and its nearest neighbours, at most ``rules.max_pitch_deg``
    below the horizontal. A candidate is accepted when a
    depth and instance render at the final size shows no surface closer than
    ``rules.min_clearance`` in the central third of the image (so it never faces a wall or an
    object from up close) and at least ``rules.min_objects`` objects with
    ``rules.min_pixels`` pixels each. Scenes with fewer objects than ``rules.min_objects``
    require every object instead. When the candidate budget runs out, the best rejected
    candidates that still pass the position and clearance rules fill the remaining views
    (``camera.meta["relaxed"] = True``). Fewer than ``n`` cameras come back only when too few
    candidates pass the position and clearance rules at all (rooms too small to stand 1 m
    from every wall).

    Parameters
    ----------
    scene : Scene
    n : int
        Number of views.
    rng : numpy.random.Generator
    width, height : int
        Image size of the returned cameras.
    rules : ViewSampling
    settled : bool or None
        Which pose of the objects to use (see :meth:`PlacedObject.transform`).
    renderer : Renderer or None
        Reused when given (else a shared default renderer is used).

    Returns
    -------
    list of Camera
        ``meta`` holds ``preset="sampled"``, the target object ids and the visible object count.
    """
    from .renderer import default_renderer

    if n < 0:
        raise InputError(f"number of views must be >= 0, got {n}")
    if n == 0:
        return []
    r = renderer if renderer is not None else default_renderer()
    objs = [o for o in scene.placed if o.asset is not None]
    poly = Polygon(scene.room.footprint)
    inner = poly.buffer(-rules.wall_margin)
    if inner.is_empty:
        inner = poly.buffer(-0.05)
    bounds = np.array([o.world_bounds(settled) for o in objs]).reshape(-1, 2, 3)
    centres = bounds.mean(axis=1) if len(objs) else np.zeros((0, 3))
    need = min(rules.min_objects, len(objs))
    K = intrinsics_from_fov(width, height, rules.fov_deg)
    far = _scene_far(scene)
    z_top = scene.room.height - 0.1
    lo_xy, hi_xy = np.asarray(inner.bounds[:2]), np.asarray(inner.bounds[2:])

    accepted: list[Camera] = []
    spare: list[tuple[int, int, int, Camera]] = []
    budget = rules.attempts_per_view * n
    attempt = 0
    while len(accepted) < n and attempt < budget:
        attempt += 1
        # -- position: inside the footprint, outside every object box ---------------------
        xy = rng.uniform(lo_xy, hi_xy)
        if not contains_xy(inner, xy[0], xy[1]):
            continue
        z = min(float(rng.uniform(*rules.height_range)), z_top)
        eye = np.array([xy[0], xy[1], z])
        if len(objs):
            m = rules.object_margin
            inside = np.all((eye > bounds[:, 0] - m) & (eye < bounds[:, 1] + m), axis=1)
            if inside.any():
                continue
        # -- target: a cluster of objects ---------------------------------------------------
        if len(objs):
            k = int(rng.integers(len(objs)))
            d = np.linalg.norm(centres - centres[k], axis=1)
            near_ids = np.argsort(d)[: max(need, 1)]
            target = centres[near_ids].mean(axis=0) + rng.normal(0, 0.1, 3)
            targets = [objs[i].id for i in near_ids]
        else:
            c = np.asarray(poly.centroid.coords[0])
            target = np.array([c[0], c[1], 0.5])
            targets = []
        drop = eye[2] - target[2]
        if drop > np.tan(np.deg2rad(rules.max_pitch_deg)) * np.linalg.norm(target[:2] - eye[:2]):
            continue
        R, t = look_at(eye, target)
        cam = Camera(K, R, t, width, height, 0.05, far, "perspective",
                     {"preset": "sampled", "targets": targets})
        res = r.render(scene, cam, settled=settled, color=False)
        # -- clearance along the view --------------------------------------------------------
        dep = res.depth
        h3, w3 = height // 3, width // 3
        centre = dep[h3: height - h3, w3: width - w3]
        hit = centre[centre > 0]
        if hit.size and hit.min() < rules.min_clearance:
            continue
        close = (dep > 0) & (dep < rules.min_clearance / 2)
        if close.mean() > rules.max_near_fraction:
            continue
        # -- enough objects -------------------------------------------------------------------
        counts = np.bincount(res.instance.ravel(), minlength=len(objs) + 1)[1: len(objs) + 1]
        n_good = int((counts >= rules.min_pixels).sum())
        cam.meta["visible_objects"] = n_good
        if n_good >= need:
            accepted.append(cam)
        else:
            spare.append((n_good, int(counts.sum()), attempt, cam))
    if len(accepted) < n:
        spare.sort(key=lambda s: (-s[0], -s[1], s[2]))
        for *_, cam in spare[: n - len(accepted)]:
            cam.meta["relaxed"] = True
            accepted.append(cam)
    return accepted
