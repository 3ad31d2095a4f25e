"""Asset thumbnails and the category contact sheet, drawn by the renderer."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw

from ..assets.model import Asset
from .renderer import render_asset

__all__ = ["save_thumbnail", "contact_sheet"]


def save_thumbnail(asset: Asset, out: str | os.PathLike, *, size: int = 512) -> Path:
    """Render ``asset`` from its front-right (3/4 view, soft shadows) into a PNG."""
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    Image.fromarray(render_asset(asset, size=(size, size)).rgb).save(out)
    return out


def contact_sheet(rows: Sequence[tuple[str, Sequence[Asset]]], out: str | os.PathLike, *,
                  cell: int = 192, per_line: int = 4) -> Path:
    """A grid PNG: each category's assets side by side, ``per_line`` categories per row,
    the category name over its first cell."""
    rows = list(rows)
    ncols = max((len(a) for _, a in rows), default=1)
    lines = [rows[i:i + per_line] for i in range(0, len(rows), per_line)]
    label = 18
    W = cell * ncols * per_line
    H = (cell + label) * max(len(lines), 1)
    sheet = Image.new("RGB", (W, H), (255, 255, 255))
    draw = ImageDraw.Draw(sheet)
    for li, line in enumerate(lines):
        y0 = li * (cell + label)
        for ri, (name, assets) in enumerate(line):
            x0 = ri * ncols * cell
            draw.text((x0 + 6, y0 + 3), name, fill=(20, 20, 20))
            for ci, a in enumerate(assets):
                img = render_asset(a, size=(cell, cell)).rgb
                sheet.paste(Image.fromarray(np.ascontiguousarray(img)), (x0 + ci * cell, y0 + label))
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    sheet.save(out)
    return out
