"""Preview viewpoint: what ``preview.png`` shows of each room.

For every bundled example and 20 room templates (spread over the room types, seed 0, solved
without settling), the preview camera of this version is chosen and its instance mask rendered
at the preview's size. Printed per room and in total:

- the share of placed objects with at least ``--min-pixels`` (200) visible pixels (goal: 80%);
- the wall-mounted objects (``SECURED_TO`` a wall) seen with that many pixels;
- the largest share of the frame one object covers, and whether an object is cut by the near
  plane (part of it closer than the near plane, inside the view).

Solved scenes are kept in ``--cache`` so that two versions compare on the same scenes.

Run: ``python benchmarks/bench_preview_camera.py [--size 640x480] [--cache DIR] [--templates 20]``
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from parse3d.datagen.templates import expand_template, list_templates
from parse3d.pag.io import load_pag
from parse3d.render import Renderer, preview_camera
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


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--size", default="640x480", help="Preview size WIDTHxHEIGHT.")
    ap.add_argument("--cache", default="out/bench-preview-camera",
                    help="Folder of solved scenes (reused when present).")
    ap.add_argument("--templates", type=int, default=20, help="Room templates besides the examples.")
    ap.add_argument("--min-pixels", type=int, default=200, help="Visible pixels that count as seen.")
    args = ap.parse_args()
    w, h = (int(v) for v in args.size.split("x"))
    r = Renderer()
    total = seen_total = wall_total = wall_seen = cut_rooms = 0
    t_choose = []
    for name, make in rooms(args.templates):
        folder = Path(args.cache) / name
        if (folder / "scene.json").is_file():
            scene = read_scene(folder)
        else:
            scene = solve(make(), seed=0)
            write_scene(scene, folder)
        t = time.perf_counter()
        cam = preview_camera(scene, width=w, height=h, renderer=r)
        t_choose.append(time.perf_counter() - t)
        mask = r.instance_masks(scene, [cam])[0]
        instances, _ = scene_id_tables(scene)
        vals, counts = np.unique(mask, return_counts=True)
        pixels = {instances.get(int(v)): int(n) for v, n in zip(vals, counts, strict=True) if v > 0}
        ids = [o.id for o in scene.placed]
        seen = [i for i in ids if pixels.get(i, 0) >= args.min_pixels]
        walls = wall_mounted(scene) & set(ids)
        top = max((pixels.get(i, 0) for i in ids), default=0) / mask.size
        # cut at the near plane: a box corner closer than the near plane, in front of the eye
        cut = _near_cut(scene, cam)
        total += len(ids)
        seen_total += len(seen)
        wall_total += len(walls)
        wall_seen += len(walls & set(seen))
        cut_rooms += bool(cut)
        print(f"{name:32} {len(seen):3d}/{len(ids):3d} objects seen  walls "
              f"{len(walls & set(seen))}/{len(walls)}  largest {top:5.1%}"
              f"  {cam.meta.get('preset', '')} {cam.meta.get('from', '')} "
              f"{cam.meta.get('elevation_deg', '')}{'  cut: ' + ', '.join(cut) if cut else ''}")
    print(f"TOTAL objects with >= {args.min_pixels} px: {seen_total}/{total} "
          f"({seen_total / max(1, total):.1%}); wall-mounted seen {wall_seen}/{wall_total}; "
          f"rooms with an object cut at the near plane: {cut_rooms}; camera choice "
          f"{np.median(t_choose) * 1000:.0f} ms median")


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
