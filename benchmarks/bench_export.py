"""Export speed: a 50-object scene to each format (glb, usd, mjcf, urdf, obj).

The scene is laid out directly (no solving): 50 generated assets of ten categories, five of
each, on a grid in a 12 m x 10 m room, so the figure is the exporter's alone. Each format is
written to a fresh folder ``--repeats`` times and the best time is reported, with the walk of
the scene (the shared part: records, convex hulls) included, as ``parse3d export`` runs it;
the CPU time of the process is printed beside the wall time (on a shared machine the wall
time also counts waiting for the disk and the other processes). ``import s`` is the one-off
cost of the first export in a process (importing pxr or mujoco), not in the best time;
``again s`` exports once more into the same folder, as ``parse3d settle`` refreshes an export
(mesh files already there are kept).

Goal (issue 15): each format in <= 1 s.

``--simulate SECONDS`` measures the MJCF model instead: a 64-object living room (template
``living-room-bright-11``, seed 0) is solved and settled, built by ``to_mujoco`` (collision
geoms only) and stepped for SECONDS of simulated time; it prints the real-time factor
(simulated / wall seconds, goal of issue 31: >= 0.5), the contacts and the largest distance an
object moved (the settled room should rest: < 1 cm). With ``--baseline-rev`` both revisions
simulate the same settled room, rounds interleaved.

    python benchmarks/bench_export.py --simulate 2 --baseline-rev HEAD~1

    python benchmarks/bench_export.py                 # every format
    python benchmarks/bench_export.py --formats usd --profile
    python benchmarks/bench_export.py --formats urdf --baseline-rev 20249ea

``--baseline-rev REV`` checks REV out into a temporary git worktree and exports the same scene
with both packages, each in its own long-lived process, the rounds interleaved (this checkout,
then REV, ``--repeats`` times), and prints each side's best wall and CPU time per format with
the ratio REV / this checkout: a before/after comparison that a busy machine slows alike.
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from parse3d.assets import registry
from parse3d.export import FORMATS, ExportOptions, export_scene
from parse3d.export.walk import clear_cache
from parse3d.geometry.frames import rot_z
from parse3d.pag.model import PAG, Room
from parse3d.physics.mujoco import settling_friction
from parse3d.scene.model import PlacedObject, Scene
from parse3d.scene.shell import build_shell

CATEGORIES = ("desk", "office_chair", "bookcase", "book", "mug", "table_lamp", "potted_plant",
              "sofa", "nightstand", "plate")


def big_scene(n: int = 50) -> Scene:
    """``n`` objects of :data:`CATEGORIES` on a grid (five seeds per category, reused)."""
    room = Room("office", ((0.0, 0.0), (12.0, 0.0), (12.0, 10.0), (0.0, 10.0)), 2.8)
    scene = Scene(PAG("bench-export", room), 0, build_shell(room))
    cols = 10
    for i in range(n):
        cat = CATEGORIES[i % len(CATEGORIES)]
        asset = registry.generate(cat, (i // len(CATEGORIES)) % 5)
        pos = np.array([0.6 + 1.2 * (i % cols), 0.8 + 1.9 * (i // cols), 0.0])
        scene.objects[f"{cat}_{i}"] = PlacedObject(f"{cat}_{i}", cat, asset, 1.0,
                                                   rot_z(0.3 * i), pos)
    return scene


def export_once(scene: Scene, fmt: str) -> dict:
    """One cold export of ``scene`` to ``fmt`` into a fresh folder: wall and CPU seconds,
    files and megabytes written."""
    opts = ExportOptions(friction=settling_friction())
    clear_cache()  # cold: the convex hulls of the pieces are part of the cost
    with tempfile.TemporaryDirectory() as d:
        t, c = time.perf_counter(), time.process_time()
        written = export_scene(scene, Path(d), [fmt], opts)
        wall, cpu = time.perf_counter() - t, time.process_time() - c
        return {"wall": wall, "cpu": cpu, "files": len(written),
                "mb": sum(p.stat().st_size for p in written) / 1e6}


ROOM_TEMPLATE, ROOM_SEED = "living-room-bright-11", 0  # 64 objects


def settled_room(folder: Path) -> Path:
    """Solve and settle the 64-object room into ``folder``; returns the scene folder."""
    from parse3d.assets.registry import vocabulary
    from parse3d.datagen.templates import expand_template, load_template
    from parse3d.pipeline import PipelineOptions, run_pipeline

    pag = expand_template(load_template(ROOM_TEMPLATE), ROOM_SEED, vocabulary=vocabulary())
    run_pipeline(pag, seed=ROOM_SEED, out=folder,
                 options=PipelineOptions(preview=False, formats=()))
    return folder


def simulate(folder: str, seconds: float) -> dict:
    """Step the MJCF model of the scene in ``folder`` for ``seconds`` of simulated time:
    real-time factor, wall seconds of stepping, contacts at the end, the largest distance a
    loose object moved (mm)."""
    import mujoco

    import parse3d
    from parse3d.export import to_mujoco

    scene = parse3d.load_scene(folder)
    model, data = to_mujoco(scene, ExportOptions(friction=settling_friction()), visual=False)
    free = [model.jnt_qposadr[j] for j in range(model.njnt)
            if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
    p0 = np.array([data.qpos[a:a + 3] for a in free])
    steps = int(round(seconds / model.opt.timestep))
    t = time.perf_counter()
    for _ in range(steps):
        mujoco.mj_step(model, data)
    wall = time.perf_counter() - t
    moved = np.linalg.norm(np.array([data.qpos[a:a + 3] for a in free]) - p0, axis=1)
    return {"rtf": steps * model.opt.timestep / wall, "wall": wall, "contacts": int(data.ncon),
            "geoms": int(model.ngeom), "moved_mm": float(moved.max() * 1000)}


def print_simulation(side: str, r: dict) -> None:
    print(f"{side[:10]:<10} {r['rtf']:8.3f} {r['wall']:8.2f} {r['geoms']:6d} {r['contacts']:8d} "
          f"{r['moved_mm']:9.2f}", flush=True)


def simulation(seconds: float, rev: str | None, repeats: int) -> None:
    """Real-time factor of the 64-object room, this checkout (and ``rev``)."""
    with tempfile.TemporaryDirectory() as d:
        t = time.perf_counter()
        folder = settled_room(Path(d) / "room")
        print(f"{ROOM_TEMPLATE} seed {ROOM_SEED}: solved and settled in "
              f"{time.perf_counter() - t:.1f} s; {seconds:g} s simulated, best of {repeats}")
        print(f"{'side':<10} {'RTF':>8} {'wall s':>8} {'geoms':>6} {'contacts':>8} "
              f"{'moved mm':>9}")
        if rev is None:
            print_simulation("this", max((simulate(str(folder), seconds)
                                          for _ in range(repeats)), key=lambda r: r["rtf"]))
            return
        from _common import ROOT, Worker, revision_tree

        with revision_tree(rev) as tree:
            sides = {"this": Worker(Path(__file__), src=ROOT / "src"),
                     rev: Worker(Path(__file__), src=tree / "src")}
            try:
                best: dict[str, dict] = {}
                for _ in range(repeats):
                    for k, w in sides.items():
                        r = w.ask(sim=seconds, scene=str(folder))
                        if "error" in r:
                            raise SystemExit(f"{k}: {r['error']}")
                        if k not in best or r["rtf"] > best[k]["rtf"]:
                            best[k] = r
            finally:
                for w in sides.values():
                    w.close()
        for k in sides:
            print_simulation(k, best[k])
        print(f"{'ratio':<10} {best['this']['rtf'] / best[rev]['rtf']:7.2f}x   "
              f"(this checkout / {rev})")


def worker(objects: int) -> None:
    """Answer ``{"fmt": F}`` requests with :func:`export_once` and ``{"sim": S, "scene": D}``
    with :func:`simulate` (for ``--baseline-rev``)."""
    from _common import serve

    scene = None

    def handle(req: dict) -> dict:
        nonlocal scene
        if "sim" in req:
            return simulate(req["scene"], req["sim"])
        if scene is None:
            scene = big_scene(objects)
            for fmt in FORMATS:  # imports (pxr, mujoco) and first-use caches, untimed
                export_once(scene, fmt)
        return export_once(scene, req["fmt"])

    serve(handle)


def compare(rev: str, formats: list[str], objects: int, repeats: int) -> None:
    """This checkout against ``rev``, rounds interleaved, best of ``repeats`` per side."""
    from _common import ROOT, Worker, revision_tree

    with revision_tree(rev) as tree:
        sides = {"this": Worker(Path(__file__), src=ROOT / "src", args=("--objects", str(objects))),
                 rev: Worker(Path(__file__), src=tree / "src", args=("--objects", str(objects)))}
        try:
            best = {(k, f): {"wall": float("inf"), "cpu": float("inf")}
                    for k in sides for f in formats}
            files = {}
            for _ in range(repeats):
                for f in formats:
                    for k, w in sides.items():
                        r = w.ask(fmt=f)
                        if "error" in r:
                            raise SystemExit(f"{k}: {r['error']}")
                        b = best[(k, f)]
                        b["wall"], b["cpu"] = min(b["wall"], r["wall"]), min(b["cpu"], r["cpu"])
                        files[(k, f)] = r["files"]
        finally:
            for w in sides.values():
                w.close()
    print(f"{'format':<6} {'side':<10} {'best s':>8} {'cpu s':>8} {'files':>6}")
    for f in formats:
        for k in sides:
            b = best[(k, f)]
            print(f"{f:<6} {k[:10]:<10} {b['wall']:8.3f} {b['cpu']:8.3f} {files[(k, f)]:6d}")
        this, base = best[("this", f)], best[(rev, f)]
        print(f"{f:<6} {'ratio':<10} {base['wall'] / this['wall']:7.2f}x "
              f"{base['cpu'] / this['cpu']:7.2f}x   ({rev} / this checkout)", flush=True)


def main() -> None:
    if "--_worker" in sys.argv:
        sys.argv.remove("--_worker")
        ap = argparse.ArgumentParser()
        ap.add_argument("--objects", type=int, default=50)
        worker(ap.parse_args().objects)
        return
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--objects", type=int, default=50)
    ap.add_argument("--formats", default=",".join(FORMATS))
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--profile", action="store_true", help="profile one export per format")
    ap.add_argument("--baseline-rev", metavar="REV",
                    help="compare with git revision REV, rounds interleaved")
    ap.add_argument("--simulate", type=float, metavar="SECONDS",
                    help="real-time factor of the 64-object room's MJCF model instead")
    args = ap.parse_args()
    if args.simulate:
        simulation(args.simulate, args.baseline_rev, args.repeats)
        return
    if args.baseline_rev:
        compare(args.baseline_rev, args.formats.split(","), args.objects, args.repeats)
        return
    t = time.perf_counter()
    scene = big_scene(args.objects)
    parts = sum(len(o.asset.parts) for o in scene.placed)
    print(f"scene: {len(scene.placed)} objects, {parts} parts, "
          f"{len({o.asset.asset_id for o in scene.placed})} distinct assets "
          f"(generated in {time.perf_counter() - t:.2f} s)")
    opts = ExportOptions(friction=settling_friction())
    print(f"{'format':<6} {'import s':>8} {'best s':>8} {'cpu s':>8} {'again s':>8} "
          f"{'files':>6} {'MB':>7}")
    for fmt in args.formats.split(","):
        t = time.perf_counter()
        with tempfile.TemporaryDirectory() as d:  # untimed: imports (pxr, mujoco) and caches
            export_scene(scene, Path(d), [fmt], opts)
        first = time.perf_counter() - t
        best, cpu, again, files, size = float("inf"), float("inf"), float("inf"), 0, 0.0
        for _ in range(args.repeats):
            clear_cache()  # cold: the convex hulls of the pieces are part of the cost
            with tempfile.TemporaryDirectory() as d:
                t, c = time.perf_counter(), time.process_time()
                written = export_scene(scene, Path(d), [fmt], opts)
                best = min(best, time.perf_counter() - t)
                cpu = min(cpu, time.process_time() - c)
                files = len(written)
                size = sum(p.stat().st_size for p in written) / 1e6
                # again into the same folder, as settling refreshes an export: mesh files
                # already there are kept
                clear_cache()
                t = time.perf_counter()
                export_scene(scene, Path(d), [fmt], opts)
                again = min(again, time.perf_counter() - t)
        print(f"{fmt:<6} {max(first - best, 0.0):8.3f} {best:8.3f} {cpu:8.3f} {again:8.3f} "
              f"{files:6d} {size:7.2f}", flush=True)
        if args.profile:
            with tempfile.TemporaryDirectory() as d:
                prof = cProfile.Profile()
                prof.enable()
                export_scene(scene, Path(d), [fmt], opts)
                prof.disable()
                pstats.Stats(prof).sort_stats("cumulative").print_stats(12)


if __name__ == "__main__":
    main()
