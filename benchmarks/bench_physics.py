"""Settling and contact extraction on a furnished room of about 50 objects.

Usage::

    python benchmarks/bench_physics.py                 # hand-built room (~50 objects)
    python benchmarks/bench_physics.py --example examples/study.json   # a solved example

Prints the one-time collision preparation per asset, then (with collision data cached) the
PhysX world build, the stepping, the whole settle call and the contact extraction, each the
median of ``--repeat`` runs on one core.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from parse3d.assets import registry
from parse3d.geometry.frames import rot_z
from parse3d.pag.model import PAG, Room
from parse3d.physics import extract_contacts, settle
from parse3d.physics.collision import asset_collision, clear_cache
from parse3d.scene.model import PlacedObject, Scene
from parse3d.scene.shell import build_shell


def _put(scene: Scene, oid: str, category: str, seed: int, xy, z: float, yaw: float,
         support: str) -> PlacedObject:
    asset = registry.generate(category, seed)
    R = rot_z(yaw)
    zmin = (asset_collision(asset).pieces.vertices @ R.T)[:, 2].min()
    o = PlacedObject(oid, category, asset, 1.0, R, np.array([xy[0], xy[1], z - zmin]),
                     support=support)
    scene.objects[oid] = o
    return o


def _top(o: PlacedObject, part: str) -> tuple[np.ndarray, float]:
    ws = asset_collision(o.asset).pieces.transformed(o.rotation, o.position, o.scale)
    idx = [i for i, p in enumerate(ws.parts) if p == part]
    lo, hi = ws.bounds[idx, 0].min(0), ws.bounds[idx, 1].max(0)
    return (lo[:2] + hi[:2]) / 2, float(hi[2])


def hand_room() -> Scene:
    """A 9 m x 7 m dining hall: 6 tables with 4 items each, 18 chairs, 4 side tables with a
    tea cup: 56 objects."""
    room = Room("dining_room", ((0, 0), (9, 0), (9, 7), (0, 7)), 2.8)
    sc = Scene(PAG("bench-hall", room), 0, build_shell(room))
    small = ["mug", "cup", "plate", "tea_cup", "bowl", "book"]
    k = 0
    for i in range(3):
        for j in range(2):
            tid = f"table{i}{j}"
            t = _put(sc, tid, "dining_table", i * 2 + j, (1.8 + 2.8 * i, 1.8 + 3.4 * j), 0.0,
                     0.0, "floor")
            (cx, cy), z = _top(t, "tabletop")
            for n, (dx, dy) in enumerate([(-0.25, -0.15), (0.25, -0.15), (-0.25, 0.15),
                                          (0.25, 0.15)]):
                cat = small[(k + n) % len(small)]
                _put(sc, f"{cat}{k}_{n}", cat, k + n, (cx + dx, cy + dy), z, 0.5 * n,
                     f"{tid}:tabletop@top")
            for n, dx in enumerate((-0.6, 0.0, 0.6)):
                _put(sc, f"chair{i}{j}_{n}", "dining_chair", k + n, (1.8 + 2.8 * i + dx,
                     1.8 + 3.4 * j - 1.25), 0.0, 0.0, "floor")
            k += 4
    for n, (x, y) in enumerate([(3.2, 3.2), (6.0, 3.2), (0.4, 6.6), (8.6, 6.6)]):
        s = _put(sc, f"side{n}", "side_table", n, (x, y), 0.0, 0.0, "floor")
        (cx, cy), z = _top(s, "tabletop")
        _put(sc, f"tea{n}", "tea_cup", n, (cx, cy), z, 0.0, f"side{n}:tabletop@top")
    return sc


def solved_example(path: str) -> Scene:
    import parse3d

    return parse3d.solve(parse3d.load_pag(path), seed=0)


def _fresh(scene: Scene) -> None:
    for o in scene.objects.values():
        o.settled_rotation = o.settled_position = None


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--example", help="solve this PAG instead of the hand-built room")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    scene = solved_example(args.example) if args.example else hand_room()
    objs = [o for o in scene.placed if o.asset is not None]
    pieces = 0
    clear_cache()
    prep = []
    for o in objs:
        t = time.perf_counter()
        pieces += len(asset_collision(o.asset).pieces)
        prep.append(time.perf_counter() - t)
    print(f"scene: {len(objs)} objects, {pieces} convex pieces")
    print(f"collision preparation (once per asset): {1000 * statistics.median(prep):.1f} ms "
          f"median, {1000 * max(prep):.1f} ms max, {sum(prep):.3f} s for all")
    settle(scene)  # warm-up: imports, shell pieces
    build, step, total, contacts, steps, cpu_s, cpu_c = [], [], [], [], [], [], []
    for _ in range(args.repeat):
        _fresh(scene)
        c0 = time.process_time()
        rep = settle(scene)
        cpu_s.append(time.process_time() - c0)
        build.append(rep.build_seconds)
        step.append(rep.step_seconds)
        total.append(rep.seconds)
        steps.append(rep.steps)
        t, c0 = time.perf_counter(), time.process_time()
        cs = extract_contacts(scene)
        contacts.append(time.perf_counter() - t)
        cpu_c.append(time.process_time() - c0)
    med = statistics.median
    print(f"CPU time (one core): settle {med(cpu_s):.3f} s, contacts {med(cpu_c):.3f} s, "
          f"total {med(cpu_s) + med(cpu_c):.3f} s")
    print(f"settle: {med(total):.3f} s (world build {med(build):.3f} s, "
          f"{med(steps):.0f} steps {med(step):.3f} s, rest {med(total) - med(build) - med(step):.3f} s); "
          f"moved > 1 cm or 2 deg: {len(rep.moved())}")
    print(f"contacts: {med(contacts):.3f} s, {len(cs)} part pairs")
    print(f"settle + contacts (wall): {med(total) + med(contacts):.3f} s (goal < 1 s)")


if __name__ == "__main__":
    main()
