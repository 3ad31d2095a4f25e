"""Preview viewpoint: what ``preview.png`` shows of each room.

For every bundled example and 20 room templates (spread over the room types, seed 0, solved
without settling), the preview's cameras of this version are chosen and their instance masks
rendered at the preview's panel size. Printed per room and in total:

- the share of placed objects with at least ``--min-pixels`` (200) visible pixels in one
  panel (goal: 80%);
- the wall-mounted objects (``SECURED_TO`` a wall) seen with that many pixels;
- the largest share of a panel one object covers, and whether an object is cut by the near
  plane (part of it closer than the near plane, inside the view);
- the objects seen by size (largest side of the box) and by support (floor, on furniture,
  inside furniture, wall or ceiling), and why the others are missed (out of the frame, too
  small even if nothing hid them, hidden);
- the median time to choose the cameras and to render the panels' colour.

Solved scenes are kept in ``--cache`` so that two versions compare on the same scenes;
``--size 640x480 --panels 1`` measures the preview as it was before it had two panels.

Run: ``python benchmarks/bench_preview_camera.py [--size WxH] [--panels N] [--cache DIR]
[--templates 20] [--rooms NAME,...]``
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from parse3d.datagen.templates import expand_template, list_templates
from parse3d.pag.io import load_pag
from parse3d.render import PREVIEW_PANELS, PREVIEW_SIZE, Renderer, preview_cameras
from parse3d.render.renderer import scene_id_tables
from parse3d.scene.io import read_scene, write_scene
from parse3d.solver import solve

ROOT = Path(__file__).resolve().parent.parent


def rooms(n_templates: int) -> list[tuple[str, object]]:
    """(name, PAG or loader) of the bundled examples and ``n_templates`` templates spread over
    the room types (every k-th of the sorted list)."""
    out = [(p.stem, lambda p=p: load_pag(p)) for p in sorted((ROOT / "examples").glob("*.*"))
           if p.suffix in (".json", ".yaml")]
    ts = sorted(list_templates(), key=lambda t: t.name)
    step = max(1, len(ts) // max(1, n_templates))
    for t in ts[::step][:n_templates]:
        out.append((t.name, lambda t=t: expand_template(t, 0)))
    return out


def wall_mounted(scene) -> set[str]:
    return {r.child.object for r in scene.pag.relations
            if r.relation == "SECURED_TO" and r.parent.object.startswith("wall")}


#: Size classes by the largest side of an object's box, metres (upper bounds).
SIZES = (("<15cm", 0.15), ("15-40cm", 0.40), ("40cm-1m", 1.0), (">1m", float("inf")))
SUPPORTS = ("floor", "on furniture", "inside", "wall/ceiling")
REASONS = ("out of frame", "too small", "hidden")


def support_class(scene, object_id: str) -> str:
    """Where an object stands: on the floor, on furniture, inside furniture, or on a wall
    or ceiling (``SECURED_TO`` or ``HANGING_BELOW``)."""
    e = scene.pag.supporter(object_id)
    if e is None or e.relation == "ON" and e.parent.object == "floor":
        return "floor"
    if e.relation in ("SECURED_TO", "HANGING_BELOW"):
        return "wall/ceiling"
    return "inside" if e.relation == "IN" else "on furniture"


def size_class(box: np.ndarray) -> str:
    side = float(np.max(box[1] - box[0]))
    return next(name for name, top in SIZES if side < top)


def miss_reason(cam, box: np.ndarray, min_pixels: int) -> str:
    """Why an object has fewer than ``min_pixels`` visible pixels: its box's centre is out of
    the frame; its projected box covers fewer than twice ``min_pixels`` (too small at this
    resolution even if nothing hid it); otherwise something hides it (furniture in front, a
    closed cabinet around it)."""
    uv, z = cam.project(box.mean(axis=0)[None])
    if z[0] <= cam.near or not (0 <= uv[0, 0] < cam.width and 0 <= uv[0, 1] < cam.height):
        return "out of frame"
    corners = np.array([[x, y, zz] for x in box[:, 0] for y in box[:, 1] for zz in box[:, 2]])
    uv, _ = cam.project(corners)
    uv = np.clip(uv, 0, [cam.width, cam.height])
    area = float(np.prod(uv.max(axis=0) - uv.min(axis=0)))
    return "too small" if area < 2 * min_pixels else "hidden"


def table(title: str, keys, counts: dict) -> str:
    """One line: ``title  key seen/total (share) ...``."""
    cells = [f"{k} {counts[k][0]}/{counts[k][1]} ({counts[k][0] / max(1, counts[k][1]):.0%})"
             for k in keys if counts[k][1]]
    return f"{title:14}" + "   ".join(cells)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--size", default=None,
                    help="Size of each panel, WIDTHxHEIGHT (default: the preview's).")
    ap.add_argument("--panels", type=int, default=PREVIEW_PANELS,
                    help="Panels side by side (default: the preview's).")
    ap.add_argument("--cache", default="out/bench-preview-camera",
                    help="Folder of solved scenes (reused when present).")
    ap.add_argument("--templates", type=int, default=20, help="Room templates besides the examples.")
    ap.add_argument("--rooms", default="", help="Only these rooms (comma-separated names).")
    ap.add_argument("--min-pixels", type=int, default=200, help="Visible pixels that count as seen.")
    args = ap.parse_args()
    w, h = (int(v) for v in args.size.split("x")) if args.size else PREVIEW_SIZE
    only = {n for n in args.rooms.split(",") if n}
    r = Renderer()
    total = seen_total = wall_total = wall_seen = cut_rooms = 0
    by_size = {k: [0, 0] for k, _ in SIZES}
    by_support = {k: [0, 0] for k in SUPPORTS}
    misses = {(s, why): 0 for s in SUPPORTS for why in REASONS}
    t_choose, t_render = [], []
    for name, make in rooms(args.templates):
        if only and name not in only:
            continue
        folder = Path(args.cache) / name
        if (folder / "scene.json").is_file():
            scene = read_scene(folder)
        else:
            scene = solve(make(), seed=0)
            write_scene(scene, folder)
        t = time.perf_counter()
        cams = preview_cameras(scene, width=w, height=h, panels=args.panels, renderer=r)
        t_choose.append(time.perf_counter() - t)
        t = time.perf_counter()
        for cam in cams:
            r.render_rgb(scene, cam)
        t_render.append(time.perf_counter() - t)
        instances, _ = scene_id_tables(scene)
        # an object counts with its pixels in the one panel that shows it best
        pixels: dict[str, int] = {}
        masks = r.instance_masks(scene, cams)
        for mask in masks:
            vals, counts = np.unique(mask, return_counts=True)
            for v, n in zip(vals, counts, strict=True):
                if v > 0:
                    key = instances.get(int(v))
                    pixels[key] = max(pixels.get(key, 0), int(n))
        placed = [o for o in scene.placed if o.asset is not None]
        ids = [o.id for o in placed]
        seen = [i for i in ids if pixels.get(i, 0) >= args.min_pixels]
        for o in placed:
            box = np.asarray(o.world_bounds(None), float)
            ok = pixels.get(o.id, 0) >= args.min_pixels
            sup = support_class(scene, o.id)
            for acc, key in ((by_size, size_class(box)), (by_support, sup)):
                acc[key][0] += ok
                acc[key][1] += 1
            if not ok:  # why, in the panel where it is largest
                why = max((miss_reason(cam, box, args.min_pixels) for cam in cams),
                          key=REASONS.index)
                misses[sup, why] += 1
        walls = wall_mounted(scene) & set(ids)
        top = max((pixels.get(i, 0) for i in ids), default=0) / (w * h)
        # cut at the near plane: a box corner closer than the near plane, in front of the eye
        cut = sorted({i for cam in cams for i in _near_cut(scene, cam)})
        total += len(ids)
        seen_total += len(seen)
        wall_total += len(walls)
        wall_seen += len(walls & set(seen))
        cut_rooms += bool(cut)
        print(f"{name:32} {len(seen):3d}/{len(ids):3d} objects seen  walls "
              f"{len(walls & set(seen))}/{len(walls)}  largest {top:5.1%}"
              f"  {' + '.join(_label(cam) for cam in cams)}"
              f"{'  cut: ' + ', '.join(cut) if cut else ''}",
              flush=True)
    print(f"\nseen (>= {args.min_pixels} px in one of {args.panels} panel(s) of {w}x{h}), "
          "by size and by support:")
    print(table("size", [k for k, _ in SIZES], by_size))
    print(table("support", SUPPORTS, by_support))
    print("missed, by support and reason (out of frame / too small: projected box under "
          f"{2 * args.min_pixels} px / hidden: behind or inside something):")
    for s in SUPPORTS:
        print(f"  {s:14}" + "   ".join(f"{why} {misses[s, why]:3d}" for why in REASONS))
    print(f"TOTAL objects with >= {args.min_pixels} px: {seen_total}/{total} "
          f"({seen_total / max(1, total):.1%}); wall-mounted seen {wall_seen}/{wall_total}; "
          f"rooms with an object cut at the near plane: {cut_rooms}; camera choice "
          f"{np.median(t_choose) * 1000:.0f} ms median; colour render of {args.panels} x {w}x{h} "
          f"{np.median(t_render) * 1000:.0f} ms median")


def _label(cam) -> str:
    m = cam.meta
    return f"{m.get('preset', '')} {m.get('from', '')} {m.get('elevation_deg', '')}".strip()


def _near_cut(scene, cam) -> list[str]:
    out = []
    for o in scene.placed:
        lo, hi = np.asarray(o.world_bounds(None), float)
        corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                            for z in (lo[2], hi[2])])
        uv, z = cam.project(corners)
        if (z < cam.near).any() and (z > cam.near).any():
            inside = (uv[:, 0] >= 0) & (uv[:, 0] < cam.width) & (uv[:, 1] >= 0) & (uv[:, 1] < cam.height)
            if inside[z > cam.near].any():
                out.append(o.id)
    return out


if __name__ == "__main__":
    main()
