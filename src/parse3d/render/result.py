"""Render results and the per-view statistics computed from their masks."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .camera import Camera

__all__ = ["RenderResult", "MaskRegion", "mask_regions", "view_record"]


@dataclass
class RenderResult:
    """One rendered view.

    Attributes
    ----------
    rgb : (H, W, 3) uint8 or None
        sRGB colour (anti-aliased); None when only masks were rendered.
    depth : (H, W) float32
        Camera-frame depth (OpenCV +z, along the optical axis), metres; 0 where nothing is hit.
    instance : (H, W) int32
        Instance id per pixel (exact, no anti-aliasing); 0 = background.
    part : (H, W) int32
        Part id per pixel (exact); 0 = background.
    normals : (H, W, 3) float32
        Unit world-frame normal of the visible surface, turned towards the camera; 0 where
        nothing is hit.
    camera : Camera
    instances : dict of int to str
        Instance id to object id (``floor``, ``wall_i``, ``ceiling`` for the room shell).
    parts : dict of int to str
        Part id to ``object_id:part_name`` (``room:floor`` ... for the shell).
    """

    rgb: np.ndarray | None
    depth: np.ndarray
    instance: np.ndarray
    part: np.ndarray
    normals: np.ndarray
    camera: Camera
    instances: dict[int, str] = field(default_factory=dict)
    parts: dict[int, str] = field(default_factory=dict)

    @property
    def hit(self) -> np.ndarray:
        """(H, W) bool: pixels where a surface was hit."""
        return self.instance > 0


@dataclass(frozen=True)
class MaskRegion:
    """Where one id appears in a mask.

    Attributes
    ----------
    id : int
    pixels : int
        Number of pixels with this id.
    bbox : (xmin, ymin, xmax, ymax)
        Inclusive pixel coordinates (x = column, y = row).
    """

    id: int
    pixels: int
    bbox: tuple[int, int, int, int]


def mask_regions(mask: np.ndarray) -> list[MaskRegion]:
    """Pixel counts and inclusive 2D boxes of every non-zero id of an (H, W) integer mask,
    sorted by id.

    Linear in the pixels: ids are counted with ``bincount``, compacted through a lookup table,
    and the rows and columns each id occupies are marked in (ids, H) and (ids, W) tables whose
    first and last marks are the box.
    """
    m = np.asarray(mask)
    if m.ndim != 2:
        raise ValueError(f"mask must be (H, W), got shape {m.shape}")
    H, W = m.shape
    if m.size == 0 or m.max(initial=0) <= 0:
        return []
    if m.min() < 0:
        raise ValueError("mask ids must be >= 0")
    counts = np.bincount(m.ravel())
    ids = np.flatnonzero(counts)
    ids = ids[ids > 0]
    lut = np.zeros(len(counts), np.intp)
    lut[ids] = np.arange(1, len(ids) + 1)
    k = lut[m]  # (H, W) compact index, 0 = background
    rows = np.zeros((len(ids) + 1, H), bool)
    cols = np.zeros((len(ids) + 1, W), bool)
    rows[k, np.arange(H)[:, None]] = True
    cols[k, np.arange(W)[None, :]] = True
    rows, cols = rows[1:], cols[1:]
    ymin = rows.argmax(axis=1)
    ymax = H - 1 - rows[:, ::-1].argmax(axis=1)
    xmin = cols.argmax(axis=1)
    xmax = W - 1 - cols[:, ::-1].argmax(axis=1)
    return [MaskRegion(int(i), int(counts[i]), (int(a), int(b), int(c), int(d)))
            for i, a, b, c, d in zip(ids, xmin, ymin, xmax, ymax, strict=True)]


def view_record(result: RenderResult) -> dict[str, Any]:
    """The per-view metadata of ``views.json``: the camera and what is visible.

    ``objects`` lists every visible instance (room elements included, flagged ``room``) with
    its pixel count and inclusive box; ``parts`` the same per part.
    """
    objects = []
    for r in mask_regions(result.instance):
        name = result.instances.get(r.id, "")
        objects.append({"id": r.id, "object": name, "room": _is_room(name),
                        "pixels": r.pixels, "bbox": list(r.bbox)})
    parts = []
    for r in mask_regions(result.part):
        name = result.parts.get(r.id, "")
        parts.append({"id": r.id, "part": name, "room": name.startswith("room:"),
                      "pixels": r.pixels, "bbox": list(r.bbox)})
    return {"camera": result.camera.to_dict(), "objects": objects, "parts": parts}


def _is_room(name: str) -> bool:
    return name in ("floor", "ceiling") or (name.startswith("wall_") and name[5:].isdigit())
