"""parse3d's solver side by side with NVIDIA's scene_synthesizer on the same placement workload.

Usage::

    python benchmarks/bench_peers.py --peer-python PYTHON [--sizes 10,25,50,100] [--rounds 5]
                                     [--no-commands] [--no-warm] [--cold-assets]

The workload (``_common.tables_layout``): dining tables on the floor of a square room of
constant floor area per table, and mugs, plates, bowls, bottles and books on the tables' tops,
dealt round-robin. parse3d solves it as a PAG (``_common.tables_room``, no settling); the peer
script builds a ``synth.Scene``, adds a floor slab, places the tables on the floor's labelled
support (``label_support`` / ``place_object``, which samples poses and rejects collisions),
then labels each table's top and places its items there (procedural ``TableAsset``,
``MugAsset``, ``PlateAsset``, ``BowlAsset``; a cylinder for a bottle and a box for a book).

Two measurements per room size N, in interleaved rounds (ours, peer, ours, ...):

warm
    one long-lived process per side (the peer in ``--peer-python``, through
    ``_common.Worker``), with warm assets: every scene of the rounds (each size and seed) is
    built once first, uncounted, so that each side has loaded or made every asset the rounds
    use (parse3d draws each object's asset from a pool of 20 per category, by seed; the peer
    makes its six procedural assets once); process CPU seconds of one solve / one scene,
    divided by the objects placed. ``--cold-assets`` warms up with one round of seed 0 only,
    so the counted rounds of other seeds include loading the pool assets they meet first.
command
    a whole command per scene, start-up included: ``parse3d solve FILE --no-settle
    --no-preview`` against ``PYTHON peer_script`` (this file with ``--_peer-command``); CPU
    seconds of the child process (user + system, from ``getrusage``), divided by the objects
    placed. Both run with Python's bytecode cache on (``PYTHONDONTWRITEBYTECODE`` is dropped
    from their environment), as installed packages are, and after one uncounted command each.

Printed per N: the median CPU per placed object of each side, objects placed, and the median
over rounds of the per-round ratio peer / ours (goals of the issue: >= 10 warm, >= 3 as whole
commands). scene_synthesizer is an optional dependency installed in its own interpreter
(``python3 -m venv VENV && VENV/bin/pip install scene-synthesizer``); without one the script
says so and exits.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _common import ROOT, Worker, serve, tables_layout

#: Sizes of the procedural peer assets (m), close to parse3d's generated ones.
TABLE = (1.6, 0.9, 0.75)
BOTTLE = (0.035, 0.25)  # radius, height
BOOK = (0.22, 0.15, 0.03)
#: Asset origins at the centre of the bottom face (placement puts the origin on the support).
BOTTOM = ("center", "center", "bottom")


# ---------------------------------------------------------------------------- the peer's side
_PEER_ASSETS: dict = {}


def peer_assets() -> dict:
    """One procedural asset per kind (built once per process, like parse3d's asset pool)."""
    if not _PEER_ASSETS:
        import scene_synthesizer as synth
        from scene_synthesizer import procedural_assets as pa

        _PEER_ASSETS.update({
            "dining_table": pa.TableAsset(*TABLE, origin=BOTTOM),
            "mug": pa.MugAsset(origin=BOTTOM),
            "plate": pa.PlateAsset(origin=BOTTOM),
            "bowl": pa.BowlAsset(origin=BOTTOM),
            "bottle": synth.CylinderAsset(radius=BOTTLE[0], height=BOTTLE[1], origin=BOTTOM),
            "book": synth.BoxAsset(extents=BOOK, origin=BOTTOM),
        })
    return _PEER_ASSETS


def peer_scene(n: int, seed: int) -> int:
    """Build the workload of ``n`` objects with scene_synthesizer; the objects placed."""
    import scene_synthesizer as synth

    lay = tables_layout(n)
    side = lay["side"]
    assets = peer_assets()
    scene = synth.Scene(seed=seed)
    scene.add_object(synth.BoxAsset(extents=(side, side, 0.02)), "floor",
                     translation=(side / 2, side / 2, -0.01))
    scene.label_support("floor", obj_ids="floor")
    placed = set()
    for t in lay["tables"]:
        if scene.place_object(t, assets["dining_table"], support_id="floor"):
            placed.add(t)
            scene.label_support(f"top_{t}", obj_ids=f"^{t}$")
    for oid, kind, table in lay["items"]:
        if table in placed and scene.place_object(oid, assets[kind], support_id=f"top_{table}"):
            placed.add(oid)
    return len(placed)


def handle_peer(req: dict) -> dict:
    t = time.process_time()
    placed = peer_scene(req["n"], req["seed"])
    return {"cpu": time.process_time() - t, "placed": placed}


# ---------------------------------------------------------------------------- parse3d's side
def handle_ours(req: dict) -> dict:
    from _common import tables_room

    from parse3d.solver import solve

    pag = tables_room(req["n"])
    t = time.process_time()
    scene = solve(pag, seed=req["seed"], validate=False)
    return {"cpu": time.process_time() - t,
            "placed": sum(1 for o in scene.objects.values() if o.placed)}


# ---------------------------------------------------------------------------- whole commands
def _child_cpu(cmd: list[str], **kw) -> tuple[float, subprocess.CompletedProcess]:
    # both sides run with their modules' bytecode cached, as installed packages have it (an
    # environment that turns bytecode writing off would make every parse3d command recompile
    # its sources, while the peer's site-packages were compiled at install)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    proc = subprocess.run(cmd, capture_output=True, text=True, env=env, **kw)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), proc


def command_ours(n: int, seed: int, tmp: Path) -> dict:
    from _common import tables_room

    pag_file = tmp / f"tables-{n}.json"
    if not pag_file.exists():
        pag_file.write_text(json.dumps(tables_room(n).to_dict()))
    out = tmp / f"out-{n}-{seed}"
    cpu, proc = _child_cpu([sys.executable, "-m", "parse3d", "solve", str(pag_file), "--seed",
                            str(seed), "--no-settle", "--no-preview", "--json", "--out", str(out)],
                           cwd=str(ROOT))
    if proc.returncode not in (0, 3):
        raise RuntimeError(f"parse3d solve failed ({proc.returncode}): {proc.stderr[-2000:]}")
    doc = json.loads((out / "scene.json").read_text())
    placed = sum(1 for o in doc["objects"] if o.get("status", "placed") == "placed")
    return {"cpu": cpu, "placed": placed}


def command_peer(python: str, n: int, seed: int) -> dict:
    cpu, proc = _child_cpu([python, __file__, "--_peer-command", str(n), str(seed)],
                           cwd=str(ROOT))
    if proc.returncode != 0:
        raise RuntimeError(f"peer script failed ({proc.returncode}): {proc.stderr[-2000:]}")
    return {"cpu": cpu, "placed": int(proc.stdout.strip().splitlines()[-1])}


# ---------------------------------------------------------------------------- driver
def peer_available(python: str | None) -> str | None:
    """Why the peer cannot run (None when it can)."""
    if not python:
        return "no --peer-python given"
    try:
        r = subprocess.run([python, "-c", "import scene_synthesizer"], capture_output=True,
                           text=True, timeout=300)
    except (OSError, subprocess.TimeoutExpired) as e:
        return f"{python} does not run ({e})"
    if r.returncode != 0:
        return f"{python} cannot import scene_synthesizer"
    return None


def compare(label: str, sizes: list[int], rounds: int, ours, peer, goal: float) -> None:
    print(f"\n{label}: CPU per placed object, median of {rounds} interleaved rounds")
    print(f"{'objects':>7s} | {'ours ms/obj':>11s} {'placed':>6s} | {'peer ms/obj':>11s} "
          f"{'placed':>6s} | {'peer/ours':>9s}")
    ratios = []
    for n in sizes:
        o_res, p_res = [], []
        for seed in range(rounds):
            o_res.append(ours(n, seed))
            p_res.append(peer(n, seed))
        per = [(p["cpu"] / max(p["placed"], 1)) / (o["cpu"] / max(o["placed"], 1))
               for o, p in zip(o_res, p_res, strict=True)]
        ratio = statistics.median(per)
        ratios.append(ratio)
        o_ms = statistics.median(1e3 * r["cpu"] / max(r["placed"], 1) for r in o_res)
        p_ms = statistics.median(1e3 * r["cpu"] / max(r["placed"], 1) for r in p_res)
        print(f"{n:7d} | {o_ms:11.2f} {statistics.median(r['placed'] for r in o_res):6.0f} | "
              f"{p_ms:11.2f} {statistics.median(r['placed'] for r in p_res):6.0f} | "
              f"{ratio:9.2f}", flush=True)
    print(f"median ratio over sizes: x{statistics.median(ratios):.2f} (goal of the issue: >= {goal:g})")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--peer-python", metavar="PYTHON",
                    help="interpreter that has scene-synthesizer installed")
    ap.add_argument("--sizes", default="10,25,50,100")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--no-commands", action="store_true", help="skip the whole-command runs")
    ap.add_argument("--no-warm", action="store_true", help="skip the warm runs")
    ap.add_argument("--cold-assets", action="store_true",
                    help="warm runs: warm up with seed 0 only (assets of other seeds load in "
                         "the counted rounds)")
    ap.add_argument("--_worker", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--_peer", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--_peer-command", dest="peer_command", nargs=2, type=int,
                    help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args._worker:
        serve(handle_peer if args._peer else handle_ours)
        return
    if args.peer_command:
        print(peer_scene(*args.peer_command))
        return
    why = peer_available(args.peer_python)
    if why is not None:
        print(f"bench_peers: skipped, scene_synthesizer is not available: {why}. Install it in "
              f"its own environment (python3 -m venv VENV && VENV/bin/pip install "
              f"scene-synthesizer) and pass --peer-python VENV/bin/python.")
        return
    sizes = [int(x) for x in args.sizes.split(",") if x.strip()]
    if not args.no_warm:
        with Worker(__file__, src=ROOT / "src") as ours, \
                Worker(__file__, python=args.peer_python, args=("--_peer",)) as peer:
            for n in sizes:  # warm-up, not counted
                for seed in (range(1) if args.cold_assets else range(args.rounds)):
                    ours.ask(n=n, seed=seed)
                    peer.ask(n=n, seed=seed)
            label = "warm process, assets first met in the rounds" if args.cold_assets \
                else "warm (one process per side, assets loaded)"
            compare(label, sizes, args.rounds,
                    lambda n, s: ours.ask(n=n, seed=s), lambda n, s: peer.ask(n=n, seed=s), 10)
    if not args.no_commands:
        with tempfile.TemporaryDirectory(prefix="parse3d-peers-") as tmp:
            command_ours(sizes[0], 0, Path(tmp))  # asset cache filled, not counted
            command_peer(args.peer_python, sizes[0], 0)
            compare("whole commands (start-up included)", sizes, args.rounds,
                    lambda n, s: command_ours(n, s, Path(tmp)),
                    lambda n, s: command_peer(args.peer_python, n, s), 3)


if __name__ == "__main__":
    main()
