"""Writing rendered views to disk: PNG images and ``views.json``.

Files written by :func:`write_views` into a scene directory, for view ``k``:

* ``rgb_k.png`` — 8-bit sRGB colour;
* ``depth_k.png`` — 16-bit grey, camera-frame depth in **millimetres** (0 = no hit, values
  clipped to 65535);
* ``instance_k.png`` / ``part_k.png`` — 16-bit grey ids (0 = background), named in
  ``views.json``;
* ``views.json`` (``format: "parse3d-views/1"``, JSON Schema ``views-1.schema.json`` in this
  package) — the id tables and, per view, the full camera and the visible objects and parts
  with pixel counts and inclusive boxes.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
from PIL import Image

from ..errors import InputError
from ..scene.model import Scene
from .camera import Camera
from .renderer import Renderer, default_renderer, scene_id_tables
from .result import RenderResult, view_record

__all__ = ["VIEWS_FORMAT", "PREVIEW_SIZE", "PREVIEW_PANELS", "write_views", "save_preview",
           "preview_camera", "preview_cameras", "save_png16", "load_views_schema"]

VIEWS_FORMAT = "parse3d-views/1"


def save_png16(path: str | Path, image: np.ndarray) -> None:
    """Write an (H, W) array of integers in [0, 65535] as a 16-bit grey PNG."""
    a = np.asarray(image)
    if a.min(initial=0) < 0 or a.max(initial=0) > 65535:
        raise ValueError(f"values outside [0, 65535] cannot go into a 16-bit PNG: {path}")
    Image.fromarray(a.astype(np.uint16)).save(path)


def depth_to_mm(depth: np.ndarray) -> np.ndarray:
    """(H, W) float metres to uint16 millimetres (0 = no hit, clipped to 65535)."""
    mm = np.rint(np.asarray(depth, np.float64) * 1000.0)
    return np.clip(mm, 0, 65535).astype(np.uint16)


def _write_result(out: Path, k: int, res: RenderResult) -> dict[str, str]:
    files = {"rgb": f"rgb_{k}.png", "depth": f"depth_{k}.png",
             "instance": f"instance_{k}.png", "part": f"part_{k}.png"}
    Image.fromarray(res.rgb).save(out / files["rgb"])
    save_png16(out / files["depth"], depth_to_mm(res.depth))
    save_png16(out / files["instance"], res.instance)
    save_png16(out / files["part"], res.part)
    return files


def write_views(scene: Scene, cameras: list[Camera], out_dir: str | Path, *,
                settled: bool | None = None, renderer: Renderer | None = None,
                meta: dict[str, Any] | None = None) -> dict[str, Any]:
    """Render ``cameras`` and write images plus ``views.json`` into ``out_dir``.

    Parameters
    ----------
    scene : Scene
    cameras : list of Camera
    out_dir : path
        Created if missing; existing view files of the same names are overwritten.
    settled : bool or None
        Which object poses to render (see :meth:`Renderer.render`).
    renderer : Renderer or None
    meta : dict or None
        Stored under ``meta`` in ``views.json`` (e.g. the sampling seed).

    Returns
    -------
    dict
        The ``views.json`` document.
    """
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    r = renderer if renderer is not None else default_renderer()
    views = []
    instances, parts = scene_id_tables(scene)
    for k, cam in enumerate(cameras):
        res = r.render(scene, cam, settled=settled)
        files = _write_result(out, k, res)
        rec = view_record(res)
        views.append({"index": k, "files": files, **rec})
    doc = {
        "format": VIEWS_FORMAT,
        "scene": scene.pag.name,
        "seed": int(scene.seed),
        "settled": bool(scene.settled if settled is None else settled),
        "depth": {"unit": "mm", "kind": "camera_z", "no_hit": 0},
        "camera_convention": "opencv: x right, y down, z forward; x_cam = R @ x_world + t",
        "instances": {str(k): v for k, v in instances.items()},
        "parts": {str(k): v for k, v in parts.items()},
        "meta": dict(meta or {}),
        "views": views,
    }
    (out / "views.json").write_text(json.dumps(doc, indent=1) + "\n")
    return doc


#: Default size of each panel of ``preview.png``, pixels (width, height). At 1280x960 a cup
#: or a book on a desk across a 5 m room covers a few hundred pixels; at 640x480 a quarter of
#: that, too few to tell what it is (docs/render.md, "Preview").
PREVIEW_SIZE = (1280, 960)
#: Panels of ``preview.png``, side by side: the view that sees the room best and the one
#: that adds the most to it (nearly always from the opposite side).
PREVIEW_PANELS = 2


def preview_camera(scene: Scene, *, width: int = 640, height: int = 480,
                   settled: bool | None = None, renderer: Renderer | None = None) -> Camera:
    """The preview's main viewpoint, chosen by what it sees (occluders considered): the
    first of :func:`preview_cameras`."""
    from .viewpoint import visibility_camera

    r = renderer if renderer is not None else default_renderer()
    return visibility_camera(scene, width=width, height=height, settled=settled, renderer=r)


def preview_cameras(scene: Scene, *, width: int = PREVIEW_SIZE[0],
                    height: int = PREVIEW_SIZE[1], panels: int = PREVIEW_PANELS,
                    settled: bool | None = None,
                    renderer: Renderer | None = None) -> list[Camera]:
    """The cameras of the preview's panels, left to right: see
    :func:`parse3d.render.viewpoint.preview_views`."""
    from .viewpoint import preview_views

    r = renderer if renderer is not None else default_renderer()
    return preview_views(scene, panels, width=width, height=height, settled=settled,
                         renderer=r)


#: zlib level of the preview PNG: level 1 encodes a 640x480 preview in about two thirds of
#: the default level's (6) time for a file about a sixth larger; the pixels are the same.
PREVIEW_PNG_LEVEL = 1


def save_preview(scene: Scene, path: str | Path, *, width: int = PREVIEW_SIZE[0],
                 height: int = PREVIEW_SIZE[1], panels: int = PREVIEW_PANELS,
                 settled: bool | None = None, renderer: Renderer | None = None) -> Path:
    """Render the preview of ``scene`` to a PNG at ``path``: ``panels`` views
    (:func:`preview_cameras`) of ``width`` x ``height`` pixels each, side by side, so the
    image is ``panels * width`` x ``height``."""
    if width < 1 or height < 1:
        raise InputError(f"preview size must be positive, got {width}x{height}")
    if panels < 1:
        raise InputError(f"preview panels must be at least 1, got {panels}")
    r = renderer if renderer is not None else default_renderer()
    cams = preview_cameras(scene, width=width, height=height, panels=panels, settled=settled,
                           renderer=r)
    rgb = np.hstack([r.render_rgb(scene, cam, settled=settled) for cam in cams])
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    Image.fromarray(rgb).save(path, compress_level=PREVIEW_PNG_LEVEL)
    return path


def load_views_schema() -> dict[str, Any]:
    """The JSON Schema of ``views.json``."""
    return json.loads((Path(__file__).with_name("views-1.schema.json")).read_text())
