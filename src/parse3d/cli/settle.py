"""``parse3d settle SCENE_DIR``: settle a solved scene and extract its contact graph."""

from __future__ import annotations

import time
from pathlib import Path

import typer

from .._deps import require
from ..errors import InputError, Problem
from ._common import check_range, console, print_json

#: Bounds of the settle options (documented in docs/physics.md).
MAX_STEPS = 100_000
MAX_DT = 0.1
MAX_DAMPING = 100.0
MAX_THRESHOLD = 0.05


def register(app: typer.Typer) -> None:
    @app.command("settle")
    def settle_cmd(
        scene_dir: Path = typer.Argument(..., help="Folder holding scene.json (from parse3d solve)."),
        steps: int = typer.Option(1000, "--steps",
                                  help="Simulation steps, 1..100000 (paper: 1000)."),
        dt: float = typer.Option(0.01, "--dt",
                                 help="Time step in seconds, (0, 0.1] (paper: 0.01)."),
        linear_damping: float = typer.Option(0.05, "--linear-damping",
                                             help="0..100 (paper: 0.05)."),
        angular_damping: float = typer.Option(0.5, "--angular-damping",
                                              help="0..100 (paper: 0.5)."),
        full: bool = typer.Option(False, "--full", help="Run every step (no early exit once all bodies sleep)."),
        threshold: float = typer.Option(0.001, "--threshold",
                                        help="Contact distance in metres, (0, 0.05]."),
        no_glb: bool = typer.Option(False, "--no-glb", help="Do not rewrite scene.glb (the "
                                                            "folder's other exports are still "
                                                            "refreshed)."),
        free_joints: bool = typer.Option(False, "--free-joints",
                                         help="Let doors, drawers and lids move (objects with "
                                              "joints become articulations; the final joint "
                                              "values go to scene.json). Default: locked."),
        as_json: bool = typer.Option(False, "--json", help="Print the report as JSON."),
    ) -> None:
        """Settle SCENE_DIR in SAPIEN and write the settled poses and contacts.json back.

        scene.glb and every other export already in SCENE_DIR (scene.usd, scene.xml, urdf/,
        scene.obj) are rewritten in the settled pose, each with the options it was exported
        with (recorded in exports.json: --no-ceiling, --open, --solved).

        Example: parse3d settle out/study-0 (or, letting an ajar door swing:
        parse3d settle out/bedroom-0 --free-joints)
        """
        from ..physics import SettleConfig, extract_contacts, settle
        from ..scene.io import read_scene, write_scene

        if not 1 <= steps <= MAX_STEPS:
            raise InputError(Problem("", f"--steps must be an integer in 1..{MAX_STEPS}, got "
                                         f"{steps}", "--steps", "parameter"))
        check_range("--dt", dt, 0.0, MAX_DT, unit="s", low_open=True)
        check_range("--linear-damping", linear_damping, 0.0, MAX_DAMPING)
        check_range("--angular-damping", angular_damping, 0.0, MAX_DAMPING)
        check_range("--threshold", threshold, 0.0, MAX_THRESHOLD, unit="m", low_open=True)
        require("sapien", feature="settling")
        scene = read_scene(scene_dir)
        from ..export.record import read_options

        read_options(scene_dir)  # a damaged export record stops us before anything is written
        joints_before = {o.id: dict(o.joints) for o in scene.placed}
        report = settle(scene, config=SettleConfig(
            dt=dt, steps=steps, linear_damping=linear_damping, angular_damping=angular_damping,
            early_exit=not full, contact_threshold=threshold, free_joints=free_joints))
        t = time.perf_counter()
        scene.contacts = extract_contacts(scene, threshold=threshold)
        scene.timings["contacts"] = round(time.perf_counter() - t, 4)
        out = write_scene(scene, scene_dir)
        from ..export import ExportOptions, export_scene
        from ..physics.mujoco import settling_friction

        # scene.glb, and every other export already in the folder, now in the settled pose,
        # each with the options it was last exported with (exports.json)
        exported = export_scene(scene, scene_dir, [] if no_glb else ["glb"],
                                ExportOptions(friction=settling_friction()),
                                skip=["glb"] if no_glb else [], keep_options=True)
        # joints that free settling moved, as "object:joint" -> [before, after]
        swung = {f"{o.id}:{n}": [joints_before[o.id].get(n, 0.0), v] for o in scene.placed
                 for n, v in o.joints.items()
                 if abs(v - joints_before.get(o.id, {}).get(n, 0.0)) > 1e-3}
        if as_json:
            d = report.to_dict()
            d["joints_moved"] = swung
            d["contacts"] = len(scene.contacts)
            d["timings"] = {"settle": scene.timings["settle"],
                            "contacts": scene.timings["contacts"]}
            print_json(d)
            return
        moved = report.moved()
        console.print(f"settled {len(report.objects)} objects in {report.steps} steps "
                      f"({scene.timings['settle']:.3f} s"
                      + (", all asleep early" if report.early_exit else "") + f"); "
                      f"{len(moved)} moved more than 1 cm or 2 deg; "
                      f"{len(scene.contacts)} part-level contacts ({scene.timings['contacts']:.3f} s)")
        for flag in ("fell", "tipped", "left_support", "sank"):
            ids = report.flagged(flag)
            if ids:
                console.print(f"  [yellow]{flag}[/]: {', '.join(ids)}")
        if free_joints:
            console.print(f"  {len(swung)} joints moved more than 0.001"
                          + "".join(f"; {k} {a:.3f} -> {b:.3f}" for k, (a, b) in
                                    sorted(swung.items())[:5]))
        if scene.relations:
            held = sum(1 for c in scene.relations if c.holds_settled)
            console.print(f"  {held}/{len(scene.relations)} relations hold after settling")
        tops = sorted({p.relative_to(scene_dir).parts[0] for p in exported}, key=str)
        console.print(f"  wrote {out}/scene.json, contacts.json"
                      + "".join(f", {t}" for t in tops))
