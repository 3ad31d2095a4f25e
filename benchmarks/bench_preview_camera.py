"""Preview viewpoint: the largest share of the frame one object covers, and how many objects
are visible, for every bundled example, with the preview camera of this version (what ``preview.png`` shows).

Run: ``python benchmarks/bench_preview_camera.py [WIDTHxHEIGHT]`` (default 160x120).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from parse3d.pag.io import load_pag
from parse3d.render import Renderer, preview_camera
from parse3d.solver import solve


def main() -> None:
    w, h = (int(v) for v in (sys.argv[1] if len(sys.argv) > 1 else "160x120").split("x"))
    r = Renderer()
    examples = sorted((Path(__file__).resolve().parent.parent / "examples").glob("*.*"))
    for ex in examples:
        scene = solve(load_pag(ex), seed=0)
        res = r.render(scene, preview_camera(scene, width=w, height=h, renderer=r))
        ids, counts = np.unique(res.instance, return_counts=True)
        objs = {res.instances.get(int(i)): n / res.instance.size
                for i, n in zip(ids, counts, strict=True)
                if i > 0 and res.instances.get(int(i)) in scene.objects}
        print(f"{ex.name:18} largest object share {max(objs.values()):.3f}, "
              f"{len(objs)}/{len(scene.placed)} objects visible")


if __name__ == "__main__":
    main()
