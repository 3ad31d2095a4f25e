"""Drawing a PAG as a layered node-link diagram (the paper's Fig. 2 style).

Object nodes are large labelled circles coloured by support depth; the parts that relations
name are small dark circles attached to their object; room elements are squares in the bottom
row. Support edges (``ON``, ``IN``, ``HANGING_BELOW``, ``SECURED_TO``) are bold solid lines,
other part-level edges dashed, object-level edges dotted; each edge is labelled with its
relation. Layers follow support depth, so the picture reads bottom-up as the assembly.
"""

from __future__ import annotations

import math
from collections import defaultdict
from pathlib import Path

from ..errors import InputError, Problem
from ..relations import RELATIONS
from .algorithms import support_depth, support_tree
from .model import PAG

__all__ = ["draw_pag", "layout_pag"]

_ROOM_ORDER = ("floor", "wall", "ceiling")


def _room_key(name: str) -> tuple[int, int]:
    if name.startswith("wall_"):
        return (1, int(name[5:]))
    return (_ROOM_ORDER.index(name) if name in _ROOM_ORDER else 3, -1)


def layout_pag(pag: PAG, *, max_row: int = 14) -> dict[str, tuple[float, float]]:
    """Positions of object nodes and of the room elements that relations name.

    Layers follow support depth (room elements at the bottom); within a layer objects sit in
    the order of their supporters' positions (so subtrees stay together), then declaration.
    A layer wider than ``max_row`` nodes wraps onto further rows.

    Returns
    -------
    dict of str to (x, y)
        Drawing units: one unit between neighbours in a layer, one per layer.
    """
    depth = support_depth(pag)
    tree = support_tree(pag)
    rooms = sorted({e.parent.object for e in pag.relations if e.parent.is_room_element},
                   key=_room_key)
    layers: dict[int, list[str]] = defaultdict(list)
    for oid in pag.objects:
        layers[depth[oid]].append(oid)
    # A wide layer wraps onto several rows so that large graphs stay readable.
    width = min(max_row, max([len(rooms)] + [len(v) for v in layers.values()] + [1]))
    pos: dict[str, tuple[float, float]] = {}

    def place(names: list[str], y: float) -> float:
        rows = [names[k:k + width] for k in range(0, len(names), width)] or [[]]
        for r, row in enumerate(rows):
            step = width / len(row) if row else 1.0
            offset = 0.5 * step + (0.25 * step if r % 2 else 0.0) * (len(row) < width)
            for k, name in enumerate(row):
                pos[name] = (offset + k * step, y + 0.75 * r)
        return y + 0.75 * (len(rows) - 1)

    y = place(rooms, 0.0)
    rank = {oid: k for k, oid in enumerate(pag.objects)}
    for d in sorted(layers):
        names = sorted(layers[d], key=lambda o: (pos.get(tree.get(o, ""), (width, 0))[0], rank[o]))
        y = place(names, y + 1.0)
    return pos


#: Largest PAG :func:`draw_pag` draws: objects, and support layers (depth of the support tree).
MAX_DRAW_OBJECTS = 300
MAX_DRAW_DEPTH = 40
#: Largest image :func:`draw_pag` writes, pixels.
MAX_DRAW_PIXELS = 40_000_000


def draw_pag(pag: PAG, path: str | Path, *, title: str | None = None, dpi: int = 110) -> Path:
    """Draw ``pag`` to a PNG or SVG file (chosen by the extension of ``path``).

    Parameters
    ----------
    pag : PAG
    path : str or Path
        Ends in ``.png`` or ``.svg``.
    title : str, optional
        Defaults to the PAG's name and room type.
    dpi : int
        Resolution of PNG output.

    Returns
    -------
    Path
        The file written. The figure grows with the widest layer and the number of layers,
        so that 50 objects stay readable.

    Raises
    ------
    InputError
        A PAG too large to draw legibly: more than :data:`MAX_DRAW_OBJECTS` objects, a support
        chain deeper than :data:`MAX_DRAW_DEPTH`, or an image above :data:`MAX_DRAW_PIXELS`.
    """
    path = Path(path)
    if path.suffix.lower() not in (".png", ".svg"):
        raise InputError(Problem("", f"cannot draw to {path.suffix or 'a file without extension'!r}:"
                                 " use .png or .svg", str(path), "io"))
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, FancyArrowPatch, Rectangle

    if len(pag.objects) > MAX_DRAW_OBJECTS:
        raise InputError(Problem("/objects", f"{len(pag.objects)} objects are too many to draw "
                                 f"legibly (at most {MAX_DRAW_OBJECTS}); use parse3d pag show",
                                 None, "parameter"))
    depth = support_depth(pag)
    max_depth = max(list(depth.values()) + [1])
    if max_depth > MAX_DRAW_DEPTH:
        raise InputError(Problem("/relations", f"a support chain {max_depth} objects deep is too "
                                 f"deep to draw (at most {MAX_DRAW_DEPTH}); use parse3d pag show",
                                 None, "parameter"))
    pos = layout_pag(pag)
    width = max([x for x, _ in pos.values()] + [1.0]) + 0.5
    top = max([y for _, y in pos.values()] + [1.0])
    fig_w = max(8.0, 1.7 * width + 1.5)
    fig_h = max(5.0, 2.3 * (top + 1) + 1.5)
    if fig_w * fig_h * dpi * dpi > MAX_DRAW_PIXELS:
        raise InputError(Problem("", f"the drawing would be {fig_w * dpi:.0f}x{fig_h * dpi:.0f} "
                                 f"pixels (at most {MAX_DRAW_PIXELS:,}); lower the dpi or draw "
                                 "a smaller PAG", str(path), "parameter"))
    fig, ax = plt.subplots(figsize=(fig_w, fig_h))
    ax.set_xlim(-0.2, width + 0.2)
    ax.set_ylim(-0.6, top + 0.7)
    ax.set_aspect("auto")
    ax.axis("off")
    cmap = plt.get_cmap("viridis")

    # Parts named by relations, fanned out around their object.
    r_obj = 0.17
    x_per_in = (width + 0.4) / fig_w
    y_per_in = (top + 1.3) / fig_h
    parts: dict[str, list[str]] = defaultdict(list)
    for e in pag.relations:
        for ref in (e.child, e.parent):
            if ref.part is not None and ref.object in pag.objects:
                label = ref.part + (f"#{ref.index}" if ref.index is not None else "")
                if label not in parts[ref.object]:
                    parts[ref.object].append(label)
    part_pos: dict[tuple[str, str], tuple[float, float]] = {}
    for oid, labels in parts.items():
        x0, y0 = pos[oid]
        n = len(labels)
        for k, label in enumerate(labels):
            ang = math.pi * (0.15 + 0.7 * (k + 0.5) / n) if n > 1 else math.pi / 2
            dx = 1.9 * r_obj * math.cos(ang) * x_per_in / y_per_in * 0.55
            dy = 1.9 * r_obj * math.sin(ang)
            part_pos[(oid, label)] = (x0 + dx, y0 + dy)

    def anchor(ref) -> tuple[float, float]:
        if ref.part is not None and ref.object in pag.objects:
            label = ref.part + (f"#{ref.index}" if ref.index is not None else "")
            return part_pos[(ref.object, label)]
        return pos.get(ref.object, (0.0, 0.0))

    # Edges first, underneath the nodes.
    seen_pairs: dict[tuple, int] = defaultdict(int)
    for e in pag.relations:
        if e.child.object not in pos or e.parent.object not in pos:
            continue
        spec = RELATIONS.get(e.relation)
        kind = spec.kind if spec else "object"
        a, b = anchor(e.child), anchor(e.parent)
        key = (e.child.object, e.parent.object)
        bend = 0.15 * seen_pairs[key]
        seen_pairs[key] += 1
        style = {"support": ("-", 2.6, "#222222"), "part": ("--", 1.3, "#1f5fa8"),
                 "object": (":", 1.4, "#b5541b")}[kind]
        arrow = FancyArrowPatch(a, b, arrowstyle="-|>", mutation_scale=10, linestyle=style[0],
                                linewidth=style[1], color=style[2], alpha=0.85,
                                connectionstyle=f"arc3,rad={0.12 + bend}", zorder=1,
                                shrinkA=4, shrinkB=4)
        ax.add_patch(arrow)
        mx, my = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
        ax.text(mx, my, e.relation, fontsize=6, color=style[2], ha="center", va="center",
                zorder=2, bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none",
                                "alpha": 0.75})

    # Room elements as squares.
    sq = 0.16
    for name, (x, y) in pos.items():
        if name in pag.objects:
            continue
        ax.add_patch(Rectangle((x - sq * x_per_in / y_per_in, y - sq),
                               2 * sq * x_per_in / y_per_in, 2 * sq, fc="#d9d9d9", ec="#444444",
                               lw=1.5, zorder=3))
        ax.text(x, y, name, fontsize=8, ha="center", va="center", zorder=4, weight="bold")

    # Object nodes and their parts.
    for oid, node in pag.objects.items():
        x, y = pos[oid]
        col = cmap(0.15 + 0.75 * (depth[oid] - 1) / max(1, max_depth - 1))
        for label in parts.get(oid, ()):
            px, py = part_pos[(oid, label)]
            ax.plot([x, px], [y, py], color="#555555", lw=0.8, zorder=3)
            ax.add_patch(Circle((px, py), 0.035, fc="#303030", ec="none", zorder=5,
                                transform=ax.transData))
            ax.text(px, py + 0.06, label, fontsize=6, ha="center", va="bottom", zorder=6,
                    color="#303030")
        ax.add_patch(_ellipse(x, y, r_obj * x_per_in / y_per_in, r_obj, col))
        cat = node.category if isinstance(node.category, str) else "|".join(node.category)
        ax.text(x, y + 0.02, oid, fontsize=7.5, ha="center", va="center", zorder=7,
                weight="bold", color="white" if depth[oid] <= max_depth / 2 else "black")
        ax.text(x, y - r_obj - 0.04, cat, fontsize=6, ha="center", va="top", zorder=7,
                color="#444444")

    handles = [
        Line2D([], [], color="#222222", lw=2.6, label="support (ON, IN, HANGING_BELOW, SECURED_TO)"),
        Line2D([], [], color="#1f5fa8", lw=1.3, ls="--", label="part-level constraint"),
        Line2D([], [], color="#b5541b", lw=1.4, ls=":", label="object-level constraint"),
    ]
    ax.legend(handles=handles, loc="upper left", fontsize=7, frameon=False)
    ax.set_title(title if title is not None else f"{pag.name} ({pag.room.type}, "
                 f"{len(pag.objects)} objects, {len(pag.relations)} relations)", fontsize=10)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi, bbox_inches="tight")
    plt.close(fig)
    return path


def _ellipse(x: float, y: float, rx: float, ry: float, colour):
    from matplotlib.patches import Ellipse

    return Ellipse((x, y), 2 * rx, 2 * ry, fc=colour, ec="#222222", lw=1.0, zorder=4)
