"""Quick matplotlib pictures of assets: one asset, or a contact sheet of many.

A stand-in for the real renderer (``parse3d.render``): flat-shaded triangles coloured by each
part's material, seen in a 3/4 view from the front-right (+X, +Y, above). Enough to check that a
generator builds what it should and that parts are labelled sensibly.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from .model import Asset

__all__ = ["draw_asset", "render_asset", "contact_sheet"]

_LIGHT = np.array([0.4, 0.8, 1.0]) / np.linalg.norm([0.4, 0.8, 1.0])
_ELEV, _AZIM = 22.0, 45.0
_CAMERA = np.array([np.cos(np.radians(_ELEV)) * np.cos(np.radians(_AZIM)),
                    np.cos(np.radians(_ELEV)) * np.sin(np.radians(_AZIM)), np.sin(np.radians(_ELEV))])
_MAX_TRIANGLES = 60000


def draw_asset(ax, asset: Asset, *, title: str | None = None, labels: bool = False) -> None:
    """Draw ``asset`` into a matplotlib 3D axes (front-right 3/4 view, parts by material)."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    tris, cols = [], []
    total = sum(len(p.mesh.faces) for p in asset.parts)
    step = max(1, int(np.ceil(total / _MAX_TRIANGLES)))
    for p in asset.parts:
        t = np.asarray(p.mesh.triangles)[::step]
        n = np.asarray(p.mesh.face_normals)[::step]
        # back faces would paint over front ones (matplotlib sorts by depth, not per pixel)
        front = n @ _CAMERA > 0
        t, n = t[front], n[front]
        shade = 0.45 + 0.55 * np.clip(n @ _LIGHT, 0.0, 1.0)
        rgb = np.asarray(p.material.color[:3], float)
        c = np.clip(rgb[None, :] * shade[:, None], 0, 1)
        cols.append(np.c_[c, np.full(len(c), max(0.35, float(p.material.color[3])))])
        tris.append(t)
    coll = Poly3DCollection(np.concatenate(tris), facecolors=np.concatenate(cols), linewidths=0)
    ax.add_collection3d(coll)
    b = asset.bounds
    c = b.mean(axis=0)
    r = float((b[1] - b[0]).max()) / 2 or 0.5
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[1] - r, c[1] + r)
    ax.set_zlim(c[2] - r, c[2] + r)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=_ELEV, azim=_AZIM)
    ax.set_axis_off()
    if labels:
        for p in asset.parts:
            q = p.mesh.bounds.mean(axis=0)
            ax.text(q[0], q[1], q[2], p.name, fontsize=6, color="black")
    if title:
        ax.set_title(title, fontsize=8)


def render_asset(asset: Asset, out: str | os.PathLike, *, size: int = 640, labels: bool = True) -> Path:
    """Write a PNG picture of ``asset`` to ``out``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(size / 100, size / 100), dpi=100)
    ax = fig.add_subplot(111, projection="3d")
    draw_asset(ax, asset, title=f"{asset.asset_id}  ({asset.size:.2f} m)", labels=labels)
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=100)
    plt.close(fig)
    return out


def contact_sheet(rows: Sequence[tuple[str, Sequence[Asset]]], out: str | os.PathLike, *,
                  cell: int = 160) -> Path:
    """A grid picture: one row per (name, assets), one cell per asset; writes a PNG."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ncols = max(len(a) for _, a in rows) if rows else 1
    # several categories per sheet row keeps the picture from becoming a thin strip
    per_line = max(1, 12 // max(ncols, 1))
    lines = [rows[i:i + per_line] for i in range(0, len(rows), per_line)]
    fig = plt.figure(figsize=(cell * ncols * per_line / 100, cell * len(lines) / 100), dpi=100)
    for li, line in enumerate(lines):
        for ri, (name, assets) in enumerate(line):
            for ci, a in enumerate(assets):
                idx = li * ncols * per_line + ri * ncols + ci + 1
                ax = fig.add_subplot(len(lines), ncols * per_line, idx, projection="3d")
                draw_asset(ax, a, title=name if ci == 0 else None)
    fig.subplots_adjust(left=0, right=1, top=0.97, bottom=0, wspace=0, hspace=0.1)
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=100)
    plt.close(fig)
    return out
