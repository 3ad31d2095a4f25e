"""``parse3d render SCENE_DIR``: render views of a solved scene (RGB, depth, masks, views.json)."""

from __future__ import annotations

import re
import time
from pathlib import Path

import typer

from .._deps import require
from ..errors import InputError, Problem
from ._common import check_seed, console, print_json

_SIZE = re.compile(r"^\s*(\d+)\s*[xX]\s*(\d+)\s*$")


def parse_size(text: str) -> tuple[int, int]:
    """``"640x480"`` to ``(640, 480)``; InputError for anything else."""
    m = _SIZE.match(text)
    if not m or int(m.group(1)) < 1 or int(m.group(2)) < 1 or max(map(int, m.groups())) > 8192:
        raise InputError(Problem("", f"--size must be WIDTHxHEIGHT with positive sizes up to "
                                     f"8192, e.g. 640x480; got {text!r}", "--size", "parameter"))
    return int(m.group(1)), int(m.group(2))


#: Most views one ``parse3d render`` call may ask for.
MAX_VIEWS = 1000


def register(app: typer.Typer) -> None:
    @app.command("render")
    def render_cmd(
        scene_dir: Path = typer.Argument(..., help="Folder holding scene.json (from parse3d solve)."),
        views: int = typer.Option(4, "--views", "-n", help="Number of sampled views, 0..1000."),
        size: str = typer.Option("640x480", "--size", help="Image size WIDTHxHEIGHT."),
        seed: int = typer.Option(0, "--seed", help="Seed of the view sampling."),
        overview: bool = typer.Option(False, "--overview",
                                      help="Also render the corner overview as the last view."),
        solved: bool = typer.Option(False, "--solved",
                                    help="Render the solved poses even when the scene is settled."),
        open_ratio: float = typer.Option(None, "--open", min=0.0, max=1.0,
                                         help="Open every door, drawer and lid to this "
                                              "fraction of its travel (0..1) instead of the "
                                              "stored joint values."),
        as_json: bool = typer.Option(False, "--json", help="Print a JSON summary."),
    ) -> None:
        """Render N views of SCENE_DIR: rgb_k.png, depth_k.png (16-bit mm), instance_k.png,
        part_k.png (16-bit ids) and views.json (cameras, id tables, visible objects and parts).

        Example: parse3d render out/study-0 --views 4 --size 640x480 --seed 0 --open 0.5
        """

        from ..render import Renderer, overview_camera, sample_views, write_views
        from ..render.camera import view_rng
        from ..scene.io import read_scene

        if not 0 <= views <= MAX_VIEWS:
            raise InputError(Problem("", f"--views must be in 0..{MAX_VIEWS}, got {views}",
                                     "--views", "parameter"))
        check_seed(seed)
        width, height = parse_size(size)
        require("moderngl", feature="rendering")
        scene = read_scene(scene_dir)
        for o in scene.objects.values():  # doors, drawers and lids as stored, or --open
            if o.asset is not None and o.asset.joints:
                o.asset = o.asset.posed(o.joints, ratio=open_ratio)
        settled = False if solved else None
        t0 = time.perf_counter()
        renderer = Renderer()
        rng = view_rng(seed)
        cams = sample_views(scene, views, rng, width=width, height=height, settled=settled,
                            renderer=renderer)
        if overview:
            cams.append(overview_camera(scene, width=width, height=height))
        t1 = time.perf_counter()
        doc = write_views(scene, cams, scene_dir, settled=settled, renderer=renderer,
                          meta={"seed": int(seed), "requested_views": int(views),
                                "size": [width, height]})
        t2 = time.perf_counter()
        relaxed = sum(1 for c in cams if c.meta.get("relaxed"))
        if as_json:
            print_json({
                "scene_dir": str(scene_dir),
                "views": len(doc["views"]),
                "relaxed": relaxed,
                "visible_objects": [sum(1 for o in v["objects"] if not o["room"])
                                    for v in doc["views"]],
                "timings": {"sample": round(t1 - t0, 4), "render": round(t2 - t1, 4)},
            })
            return
        console.print(f"rendered {len(doc['views'])} views of {scene.pag.name} at "
                      f"{width}x{height} (sampling {t1 - t0:.2f} s, rendering {t2 - t1:.2f} s)")
        for v in doc["views"]:
            n_obj = sum(1 for o in v["objects"] if not o["room"])
            console.print(f"  view {v['index']}: {n_obj} objects visible")
        if len(cams) < views + int(overview):
            console.print(f"  [yellow]only {len(cams)} views met the sampling rules[/]")
        if relaxed:
            console.print(f"  [yellow]{relaxed} views show fewer objects than asked[/]")
        console.print(f"  wrote {scene_dir}/rgb_k.png, depth_k.png, instance_k.png, part_k.png, "
                      "views.json")
