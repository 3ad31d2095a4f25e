"""Headless rendering of scenes and assets: RGB, depth, instance and part masks, normals.

See ``docs/render.md`` for the camera conventions, the outputs and the files written.

Examples
--------
>>> from parse3d.render import overview_camera, render_scene     # doctest: +SKIP
>>> res = render_scene(scene, overview_camera(scene))             # doctest: +SKIP
>>> res.instance.max() >= 1                                       # doctest: +SKIP
True
"""

from __future__ import annotations

from .camera import (
    Camera,
    ViewSampling,
    asset_camera,
    intrinsics_from_fov,
    look_at,
    overview_camera,
    plan_camera,
    sample_views,
)
from .io import (
    PREVIEW_PANELS,
    PREVIEW_SIZE,
    VIEWS_FORMAT,
    preview_camera,
    preview_cameras,
    save_preview,
    write_views,
)
from .renderer import (
    SYSTEM_PACKAGES,
    Lighting,
    Renderer,
    RoomStyle,
    create_context,
    default_renderer,
    render_asset,
    render_scene,
    scene_id_tables,
)
from .result import MaskRegion, RenderResult, mask_regions, view_record

__all__ = [
    "Camera",
    "ViewSampling",
    "asset_camera",
    "intrinsics_from_fov",
    "look_at",
    "overview_camera",
    "plan_camera",
    "sample_views",
    "VIEWS_FORMAT",
    "save_preview",
    "PREVIEW_SIZE",
    "PREVIEW_PANELS",
    "preview_camera",
    "preview_cameras",
    "write_views",
    "SYSTEM_PACKAGES",
    "Lighting",
    "Renderer",
    "RoomStyle",
    "create_context",
    "default_renderer",
    "render_asset",
    "render_scene",
    "scene_id_tables",
    "MaskRegion",
    "RenderResult",
    "mask_regions",
    "view_record",
]
