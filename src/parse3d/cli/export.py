"""``parse3d export SCENE_DIR --format ...``: a solved scene to viewers and simulators."""

from __future__ import annotations

import time
from pathlib import Path

import typer

from .._deps import require_formats
from ..errors import InputError, Problem
from ._common import console, print_json


def _scene_dirs(path: Path) -> list[Path]:
    """The scene folder itself, or every scene folder of a dataset (``DIR/scenes/*``)."""
    if (path / "scene.json").is_file() or path.suffix == ".json":
        return [path]
    scenes = path / "scenes"
    if scenes.is_dir():
        found = sorted(p for p in scenes.iterdir() if (p / "scene.json").is_file())
        if found:
            return found
    if not path.exists():
        raise InputError(Problem("", "no such folder — give a folder written by parse3d solve "
                                     "(or a dataset folder)", str(path), "io"))
    raise InputError(Problem("", "not a scene folder: no scene.json here (nor a dataset's "
                                 "scenes/*/scene.json) — solve a PAG first "
                                 f"(parse3d solve PAG --out {path})", str(path), "io"))


def register(app: typer.Typer) -> None:
    @app.command("export")
    def export_cmd(
        scene_dir: Path = typer.Argument(..., help="Scene folder (holds scene.json), or a "
                                                   "dataset folder to export all its scenes."),
        fmt: str = typer.Option("glb", "--format", "-f",
                                help="glb, usd, mjcf, urdf or obj; several as glb,usd."),
        out: Path = typer.Option(None, "--out", "-o",
                                 help="Output folder (default: the scene folder itself)."),
        no_ceiling: bool = typer.Option(False, "--no-ceiling", help="Leave the ceiling out."),
        settled: bool = typer.Option(None, "--settled/--solved",
                                     help="Pose to export (default: settled when the scene "
                                          "was settled)."),
        open_ratio: float = typer.Option(None, "--open", min=0.0, max=1.0,
                                         help="Open every door, drawer and lid to this "
                                              "fraction of its travel (0..1) instead of the "
                                              "stored joint values."),
        force: bool = typer.Option(False, "--force",
                                   help="Replace scene.xml, scene.obj... in --out even when "
                                        "parse3d did not write them."),
        as_json: bool = typer.Option(False, "--json", help="Print what was written as JSON."),
    ) -> None:
        """Export a solved scene as structured glTF, USD, MJCF, URDF or OBJ.

        Files: scene.glb; scene.usd; scene.xml + meshes/; urdf/<object_id>.urdf +
        urdf/scene.json; scene.obj + scene.mtl. Exports already in the scene folder that are
        older than its scene.json are rewritten too. Files of these names in --out that
        parse3d did not write are never replaced (exit 2) unless --force is given. Exit code 2
        for a folder that is not a scene, an unknown format or an output that cannot be
        written.

        Example: parse3d export out/study-0 --format usd,mjcf --no-ceiling
        """
        from ..export import ExportOptions, check_formats, export_scene, stale_formats
        from ..physics.mujoco import settling_friction
        from ..scene.io import read_scene

        formats = check_formats(fmt, where="--format")
        require_formats(formats)
        dirs = _scene_dirs(scene_dir)
        opts = ExportOptions(settled=settled, ceiling=not no_ceiling, open_ratio=open_ratio,
                             friction=settling_friction())
        rows = []
        for d in dirs:
            scene = read_scene(d)
            if settled and not scene.settled:
                raise InputError(Problem("", "--settled: this scene was not settled — run "
                                             f"parse3d settle {d} first, or export --solved",
                                         str(d), "parameter"))
            target = out if out is not None else (d if d.is_dir() else d.parent)
            if out is not None and len(dirs) > 1:
                target = out / d.name
            # in the scene's own folder, other exports older than scene.json are refreshed
            own = out is None or target.resolve() == (d if d.is_dir() else d.parent).resolve()
            stale = [f for f in stale_formats(target) if f not in formats] if own else []
            t = time.perf_counter()
            files = export_scene(scene, target, formats, opts, refresh=own, force=force)
            rows.append({"scene": str(d), "out": str(target), "formats": list(formats),
                         "refreshed": stale, "files": [str(f) for f in files],
                         "seconds": round(time.perf_counter() - t, 4)})
        if as_json:
            print_json(rows if len(rows) > 1 else rows[0])
            return
        for r in rows:
            extra = f"; refreshed {', '.join(r['refreshed'])}" if r["refreshed"] else ""
            console.print(f"{r['scene']}: wrote {len(r['files'])} files "
                          f"({', '.join(r['formats'])}{extra}) to {r['out']} in "
                          f"{r['seconds']:.2f} s")
