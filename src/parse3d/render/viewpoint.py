"""The preview's viewpoint, chosen by what it sees.

Candidates are the eye-height overviews of :func:`~parse3d.render.camera.overview_candidates`
(inside the room, from its corners) and *cut-away* views: from outside a corner and above
the room, looking down at its centre, where the renderer leaves out the walls and ceiling
that face away from the eye (a doll's-house view, as scene-synthesis papers show rooms). Each
candidate is rendered as a small instance mask, so occluders count (an island hiding the
kitchen's floor cabinets, a wardrobe in front of a picture). The preview is the candidate that

1. cuts nothing at the near plane (no object within :data:`MIN_CLEARANCE` of the eye),
2. lets no object cover more than :data:`~parse3d.render.camera.MAX_OBJECT_SHARE` of the frame,
3. sees the most wall-mounted objects (``SECURED_TO`` a wall), then
4. the most objects with at least :data:`MIN_PIXELS` visible pixels at the panel's size,
5. then the smallest largest share (ties: the candidates' order, eye-height views first).

Further panels (:func:`preview_views`) are the cut-away views that add the most to what the
panels before them see, by the same rules counted over all of them together.
``benchmarks/bench_preview_camera.py`` measures the result over the examples and templates.
"""

from __future__ import annotations

import math

import numpy as np

from ..scene.model import Scene
from .camera import (
    MAX_OBJECT_SHARE,
    Camera,
    _box_distance,
    _scene_far,
    intrinsics_from_fov,
    look_at,
    overview_candidates,
)
from .renderer import Renderer, scene_id_tables

__all__ = ["MIN_CLEARANCE", "MIN_PIXELS", "cutaway_candidates", "preview_views", "visibility_camera"]

#: Visible pixels (at the panel's size) for an object to count as seen.
MIN_PIXELS = 200
#: Least distance (m) from the eye to any object's box: nothing is cut by the near plane.
MIN_CLEARANCE = 0.3
#: Size of the masks the candidates are judged on.
PROBE = (240, 180)
#: Eye-height candidates judged (the best by projected boxes).
INTERIOR_PROBES = 4
#: Elevations (degrees above the horizontal) and field of view of the cut-away views.
CUTAWAY_ELEVATIONS = (35.0, 50.0, 65.0)
CUTAWAY_FOV = 35.0
#: Distance factor of the cut-away views over the one that just fits every object's box: a
#: little room at the edges, so no object is cut by the frame (a closer 0.92, with a fourth
#: near-vertical elevation, saw about one point more of the benchmark's objects in a trial,
#: cutting the outermost ones).
FIT = 1.02


def cutaway_candidates(scene: Scene, *, width: int = 640, height: int = 480,
                       settled: bool | None = None) -> list[Camera]:
    """Views from outside each footprint corner and each wall, above the room, looking at
    its centre.

    The eye stands on the line from the footprint's centre through the corner (or the wall's
    midpoint), :data:`CUTAWAY_ELEVATIONS` above the horizontal, :data:`FIT` times as far as
    it takes for every corner of every placed object's box to project inside the frame.
    Walls and the ceiling facing away from it are left out by the renderer.
    """
    fp = np.asarray(scene.room.footprint, float)
    boxes = np.array([o.world_bounds(settled) for o in scene.placed
                      if o.asset is not None]).reshape(-1, 2, 3)
    # frame the objects (the floor around them is context, not content)
    corners = np.array([[i >> 2 & 1, i >> 1 & 1, i & 1] for i in range(8)])
    pts = (boxes[:, corners, [0, 1, 2]].reshape(-1, 3) if len(boxes)
           else np.c_[fp, np.zeros(len(fp))])
    lo, hi = fp.min(axis=0), fp.max(axis=0)
    centre = (lo + hi) / 2
    target = np.array([centre[0], centre[1], 0.3 * scene.room.height])
    K = intrinsics_from_fov(width, height, CUTAWAY_FOV)
    half = math.radians(CUTAWAY_FOV) / 2
    vhalf = math.atan(math.tan(half) * height / width)
    far = _scene_far(scene) * 3
    out = []
    # from beyond each corner, then square to each wall (its midpoint's side)
    sides = [(f"corner {i}", c) for i, c in enumerate(fp)] + [
        (f"wall_{i}", (fp[i] + fp[(i + 1) % len(fp)]) / 2) for i in range(len(fp))]
    for where, point in sides:
        d = point - centre
        if np.linalg.norm(d) < 1e-9:
            continue
        d = d / np.linalg.norm(d)
        for el in CUTAWAY_ELEVATIONS:
            e = math.radians(el)
            back = np.array([d[0] * math.cos(e), d[1] * math.cos(e), math.sin(e)])
            # the distance s at which every point fits: an eye at target + s * back sees
            # p at camera coordinates rel + (0, 0, s), rel = R (p - target)
            R0, _ = look_at(target + back, target)
            rel = (pts - target) @ R0.T
            need = max(float(np.max(np.abs(rel[:, 0]) / math.tan(half) - rel[:, 2])),
                       float(np.max(np.abs(rel[:, 1]) / math.tan(vhalf) - rel[:, 2])))
            s = max(need * FIT, float(np.max(-rel[:, 2])) + 0.5, 1.0)
            eye = target + s * back
            R, t = look_at(eye, target)
            out.append(Camera(K, R, t, width, height, 0.05, far + s, "perspective",
                              {"preset": "cutaway", "from": where, "elevation_deg": el}))
    return out


def _wall_mounted(scene: Scene) -> set[str]:
    return {r.child.object for r in scene.pag.relations
            if r.relation == "SECURED_TO" and r.parent.object.startswith("wall")}


def preview_views(scene: Scene, n: int = 2, *, width: int = 640, height: int = 480,
                  settled: bool | None = None, renderer: Renderer) -> list[Camera]:
    """The preview's panels: the candidate that sees the room best (module docstring), then
    the ones that add the most to what the panels before them see.

    A second panel is nearly always the view from the other side of the room: furniture
    stands against the walls facing inwards, so the shelves, cabinets and wall-mounted
    objects a cut-away view sees from behind face the opposite view.

    Parameters
    ----------
    scene : Scene
    n : int
        Panels (cameras) to choose, at least 1 (fewer when there are fewer candidates).
    width, height : int
        Size of each panel, pixels.
    settled : bool, optional
        Use the settled poses (default: when the scene was settled).
    renderer : Renderer
        Renders the candidates' instance masks at :data:`PROBE` size.

    Returns
    -------
    list of Camera
        ``meta`` holds ``preset`` (``overview`` or ``cutaway``), ``seen`` (objects with at
        least :data:`MIN_PIXELS` visible pixels in this panel, estimated from the probe),
        ``walls_seen``, and ``seen_so_far`` (in this panel or one before it).
    """
    interior = overview_candidates(scene, width=width, height=height,
                                   settled=settled)[:INTERIOR_PROBES]
    cands = interior + cutaway_candidates(scene, width=width, height=height, settled=settled)
    placed = [o for o in scene.placed if o.asset is not None]
    ids = {o.id for o in placed}
    walls = _wall_mounted(scene) & ids
    boxes = np.array([o.world_bounds(settled) for o in placed]).reshape(-1, 2, 3)
    instances, _ = scene_id_tables(scene)
    probes = [cam.resized(*PROBE) for cam in cands]
    masks = renderer.instance_masks(scene, probes, settled=settled)
    # the pixel threshold, MIN_PIXELS of a panel, scaled to the probe
    need = MIN_PIXELS * (PROBE[0] * PROBE[1]) / (width * height)
    judged = []  # per candidate: (usable, smaller largest share, objects seen)
    for cam, mask in zip(cands, masks, strict=True):
        vals, counts = np.unique(mask, return_counts=True)
        px = {instances.get(int(v)): int(c) for v, c in zip(vals, counts, strict=True) if v > 0}
        top = max((px.get(i, 0) for i in ids), default=0) / mask.size
        clear = float(_box_distance(cam.position, boxes).min()) if len(boxes) else np.inf
        usable = (clear >= MIN_CLEARANCE, top <= MAX_OBJECT_SHARE)
        judged.append((usable, -round(top, 3), {i for i in ids if px.get(i, 0) >= need}))
    out: list[Camera] = []
    chosen: list[int] = []
    so_far: set[str] = set()
    for _ in range(min(max(1, n), len(cands))):
        def key(k: int, so_far=so_far) -> tuple:
            usable, top, seen = judged[k]
            both = seen | so_far
            return (*usable, len(both & walls), len(both), top, -k)

        # after the first panel, cut-away views only: panels seen side by side read as one
        # room from several sides, not a doll's house next to a photograph from inside
        rest = [k for k in range(len(cands)) if k not in chosen
                and (not chosen or cands[k].meta.get("preset") == "cutaway")]
        if not rest:
            break
        k = max(rest, key=key)
        chosen.append(k)
        seen = judged[k][2]
        so_far = so_far | seen
        best = cands[k]
        out.append(Camera(best.K, best.R, best.t, best.width, best.height, best.near, best.far,
                          best.projection, {**best.meta, "seen": len(seen),
                                            "walls_seen": len(seen & walls),
                                            "seen_so_far": len(so_far)}))
    return out


def visibility_camera(scene: Scene, *, width: int = 640, height: int = 480,
                      settled: bool | None = None, renderer: Renderer) -> Camera:
    """The preview's main camera: the first of :func:`preview_views`."""
    return preview_views(scene, 1, width=width, height=height, settled=settled,
                         renderer=renderer)[0]
