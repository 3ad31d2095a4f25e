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

__all__ = ["draw_pag", "layout_pag", "pag_figure"]

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
    import matplotlib.pyplot as plt

    fig = pag_figure(pag, title=title, dpi=dpi, where=str(path))
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi, bbox_inches="tight")
    plt.close(fig)
    return path


def pag_figure(pag: PAG, *, title: str | None = None, dpi: int = 110,
               where: str = "<drawing>"):
    """The matplotlib figure :func:`draw_pag` saves (close it with ``plt.close(fig)``).

    Every label is a text artist with a ``gid`` saying what it names: ``object:<id>`` (the
    id inside its circle, shrunk or wrapped to fit), ``category:<id>``, ``room:<name>``,
    ``part:<id>:<part>`` and ``relation:<k>`` (the k-th relation's label, placed along its
    edge where it overlaps no other label, circle or square).
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    import numpy as np
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
                                 "a smaller PAG", where, "parameter"))
    fig, ax = plt.subplots(figsize=(fig_w, fig_h), dpi=dpi)
    ax.set_xlim(-0.2, width + 0.2)
    ax.set_ylim(-0.6, top + 0.7)
    ax.set_aspect("auto")
    ax.axis("off")
    cmap = plt.get_cmap("viridis")
    renderer = fig.canvas.get_renderer()
    labels = _Labels(ax, renderer)

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
    for oid, plabels in parts.items():
        x0, y0 = pos[oid]
        n = len(plabels)
        for k, label in enumerate(plabels):
            ang = math.pi * (0.15 + 0.7 * (k + 0.5) / n) if n > 1 else math.pi / 2
            dx = 1.9 * r_obj * math.cos(ang) * x_per_in / y_per_in * 0.55
            dy = 1.9 * r_obj * math.sin(ang)
            part_pos[(oid, label)] = (x0 + dx, y0 + dy)

    def anchor(ref) -> tuple[float, float]:
        if ref.part is not None and ref.object in pag.objects:
            label = ref.part + (f"#{ref.index}" if ref.index is not None else "")
            return part_pos[(ref.object, label)]
        return pos.get(ref.object, (0.0, 0.0))

    # Nodes first (they are the obstacles every label avoids); edges are drawn underneath.
    sq = 0.16
    for name, (x, y) in pos.items():
        if name in pag.objects:
            continue
        ax.add_patch(Rectangle((x - sq * x_per_in / y_per_in, y - sq),
                               2 * sq * x_per_in / y_per_in, 2 * sq, fc="#d9d9d9", ec="#444444",
                               lw=1.5, zorder=3))
        labels.block_data(x - sq * x_per_in / y_per_in, y - sq, x + sq * x_per_in / y_per_in,
                          y + sq)
        labels.fixed(ax.text(x, y, name, fontsize=8, ha="center", va="center", zorder=4,
                             weight="bold", gid=f"room:{name}"))
    rx = r_obj * x_per_in / y_per_in
    for oid, node in pag.objects.items():
        x, y = pos[oid]
        col = cmap(0.15 + 0.75 * (depth[oid] - 1) / max(1, max_depth - 1))
        ax.add_patch(_ellipse(x, y, rx, r_obj, col)).set_gid(f"node:{oid}")
        labels.block_data(x - rx, y - r_obj, x + rx, y + r_obj)
        inside = labels.data_to_px(x + 0.8 * rx, y)[0] - labels.data_to_px(x - 0.8 * rx, y)[0]
        text, size = _fit_name(oid, inside, dpi=dpi)
        ax.text(x, y, text, fontsize=size, ha="center", va="center", zorder=7, weight="bold",
                color="white" if depth[oid] <= max_depth / 2 else "black",
                gid=f"object:{oid}", linespacing=0.95)
        cat = node.category if isinstance(node.category, str) else "|".join(node.category)
        labels.fixed(ax.text(x, y - r_obj - 0.04, cat, fontsize=6, ha="center", va="top",
                             zorder=7, color="#444444", gid=f"category:{oid}"))
    for oid, plabels in parts.items():
        x, y = pos[oid]
        for label in plabels:
            px, py = part_pos[(oid, label)]
            ax.plot([x, px], [y, py], color="#555555", lw=0.8, zorder=3)
            ax.add_patch(Circle((px, py), 0.035, fc="#303030", ec="none", zorder=5,
                                transform=ax.transData))
            t = ax.text(px, py, label, fontsize=6, ha="center", va="center", zorder=6,
                        color="#303030", gid=f"part:{oid}:{label}")
            # above the dot first, then beside it, then below
            labels.place(t, [labels.data_to_px(px, py) + np.asarray(off) * dpi / 110
                             for off in _PART_OFFSETS])

    seen_pairs: dict[tuple, int] = defaultdict(int)
    for k, e in enumerate(pag.relations):
        if e.child.object not in pos or e.parent.object not in pos:
            continue
        spec = RELATIONS.get(e.relation)
        kind = spec.kind if spec else "object"
        a, b = anchor(e.child), anchor(e.parent)
        key = (e.child.object, e.parent.object)
        rad = 0.12 + 0.15 * seen_pairs[key]
        seen_pairs[key] += 1
        style = {"support": ("-", 2.6, "#222222"), "part": ("--", 1.3, "#1f5fa8"),
                 "object": (":", 1.4, "#b5541b")}[kind]
        ax.add_patch(FancyArrowPatch(a, b, arrowstyle="-|>", mutation_scale=10,
                                     linestyle=style[0], linewidth=style[1], color=style[2],
                                     alpha=0.85, connectionstyle=f"arc3,rad={rad}", zorder=1,
                                     shrinkA=4, shrinkB=4))
        t = ax.text(0, 0, e.relation, fontsize=6, color=style[2], ha="center", va="center",
                    zorder=2, gid=f"relation:{k}",
                    bbox={"boxstyle": "round,pad=0.1", "fc": "white", "ec": "none",
                          "alpha": 0.75})
        labels.place(t, _along_arc(labels.data_to_px(*a), labels.data_to_px(*b), rad,
                                   nudge=8 * dpi / 110))

    handles = [
        Line2D([], [], color="#222222", lw=2.6, label="support (ON, IN, HANGING_BELOW, SECURED_TO)"),
        Line2D([], [], color="#1f5fa8", lw=1.3, ls="--", label="part-level constraint"),
        Line2D([], [], color="#b5541b", lw=1.4, ls=":", label="object-level constraint"),
    ]
    ax.legend(handles=handles, loc="upper left", fontsize=7, frameon=False)
    ax.set_title(title if title is not None else f"{pag.name} ({pag.room.type}, "
                 f"{len(pag.objects)} objects, {len(pag.relations)} relations)", fontsize=10)
    return fig


#: Where a part's label may go, pixels from its dot at 110 dpi: above, beside, below.
_PART_OFFSETS = [(0, 9), (-14, 9), (14, 9), (-22, 0), (22, 0), (0, -9), (-14, -9), (14, -9),
                 (0, 17), (-26, 12), (26, 12)]


def _along_arc(a, b, rad: float, *, nudge: float, n: int = 9):
    """Candidate label centres along matplotlib's ``arc3`` curve from ``a`` to ``b`` (pixels),
    the middle first, then outwards; then the same points nudged off the curve."""
    import numpy as np

    a, b = np.asarray(a, float), np.asarray(b, float)
    d = b - a
    c = (a + b) / 2 + rad * np.array([d[1], -d[0]])  # arc3's control point
    ts = [0.5] + [t for k in range(1, n // 2 + 1) for t in (0.5 - 0.4 * k / (n // 2),
                                                          0.5 + 0.4 * k / (n // 2))]
    pts = [(1 - t) ** 2 * a + 2 * (1 - t) * t * c + t ** 2 * b for t in ts]
    return pts + [p + (0, k * nudge) for k in (1, -1, 2, -2) for p in pts]


def _fit_name(name: str, width_px: float, *, dpi: int) -> tuple[str, float]:
    """An object id and the font size (points) that fit it into a circle ``width_px`` pixels
    across inside (at ``dpi``): one line at up to 7.5 pt if it fits at 5.5 pt or more, else
    two, then three lines (cut at underscores where one is near, else anywhere)."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextPath

    bold = FontProperties(weight="bold")

    def fit(text: str) -> float:  # the largest size (pt) at which ``text`` fits
        wide = max(TextPath((0, 0), line, size=1, prop=bold).get_extents().width
                   for line in text.split("\n")) * dpi / 72
        tall = (text.count("\n") + 1) * 1.2 * dpi / 72
        return min(7.5, width_px / wide, 0.9 * width_px / tall)

    text, size = name, fit(name)
    for lines in (2, 3):
        if size >= 5.5:
            break
        text = _split(name, lines)
        size = fit(text)
    return text, size


def _split(name: str, lines: int) -> str:
    """``name`` in ``lines`` pieces of about equal length, cut after an underscore when one
    is within three characters of the even cut."""
    cuts, start = [], 0
    for k in range(1, lines):
        even = round(k * len(name) / lines)
        near = [i + 1 for i, ch in enumerate(name) if ch == "_" and abs(i + 1 - even) <= 3
                and i + 1 > start]
        cut = min(near, key=lambda i: abs(i - even)) if near else even
        cuts.append(cut)
        start = cut
    bounds = [0, *cuts, len(name)]
    return "\n".join(name[a:b] for a, b in zip(bounds, bounds[1:], strict=False) if b > a)


class _Labels:
    """Greedy label placement: each label takes the first candidate spot (pixels) where its
    box overlaps nothing placed or blocked so far, else the spot of least overlap."""

    def __init__(self, ax, renderer):
        import numpy as np

        self.ax, self.renderer = ax, renderer
        self.boxes = np.zeros((0, 4))  # x0, y0, x1, y1 in pixels

    def data_to_px(self, x: float, y: float):
        return self.ax.transData.transform((x, y))

    def block_data(self, x0: float, y0: float, x1: float, y1: float) -> None:
        (a, b), (c, d) = self.data_to_px(x0, y0), self.data_to_px(x1, y1)
        self._add((min(a, c), min(b, d), max(a, c), max(b, d)))

    def fixed(self, text) -> None:
        e = text.get_window_extent(self.renderer)
        self._add((e.x0, e.y0, e.x1, e.y1))

    def _add(self, box) -> None:
        import numpy as np

        self.boxes = np.vstack([self.boxes, np.asarray(box, float)[None]])

    def place(self, text, candidates) -> None:
        import numpy as np

        e = text.get_window_extent(self.renderer)
        w, h = e.width + 2, e.height + 2
        best, best_cost = None, np.inf
        for c in candidates:
            box = np.array([c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2])
            ox = np.clip(np.minimum(box[2], self.boxes[:, 2]) - np.maximum(box[0], self.boxes[:, 0]), 0, None)
            oy = np.clip(np.minimum(box[3], self.boxes[:, 3]) - np.maximum(box[1], self.boxes[:, 1]), 0, None)
            cost = float((ox * oy).sum())
            if cost < best_cost:
                best, best_cost = (c, box), cost
            if cost == 0.0:
                break
        (cx, cy), box = best
        text.set_position(self.ax.transData.inverted().transform((cx, cy)))
        self._add(box)


def _ellipse(x: float, y: float, rx: float, ry: float, colour):
    from matplotlib.patches import Ellipse

    return Ellipse((x, y), 2 * rx, 2 * ry, fc=colour, ec="#222222", lw=1.0, zorder=4)
