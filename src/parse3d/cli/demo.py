"""``parse3d demo``: solve the bundled rooms into out/demo/ and say where the files are."""

from __future__ import annotations

from pathlib import Path

import typer
from rich.console import Console
from rich.table import Table

from .._deps import require
from ._common import check_seed, console, safe_name


def register(app: typer.Typer) -> None:
    @app.command("demo")
    def demo_cmd(
        out: Path = typer.Option(Path("out/demo"), "--out", "-o", help="Output folder."),
        seed: int = typer.Option(0, "--seed", help="Scene seed of every room."),
        no_settle: bool = typer.Option(False, "--no-settle",
                                       help="Skip physics settling and contacts."),
    ) -> None:
        """Solve, settle and render every bundled example room into OUT/<name>/.

        Example: parse3d demo --out out/demo
        """
        from ..assets.registry import vocabulary
        from ..measure.stability import broken_after_settling
        from ..pag.io import load_pag
        from ..pipeline import PipelineOptions, run_pipeline
        from ..scenes import bundled_paths
        from .solve import _prepare_out

        check_seed(seed)
        # name the extras before any folder is written (make demo installs both)
        if not no_settle:
            require("sapien", feature="the demo's settling (or pass --no-settle)")
        require("moderngl", feature="the demo's previews")
        vocab = vocabulary()
        table = Table(title="parse3d demo")
        for col in ("room", "objects", "placed", "relations hold", "contacts", "solve s", "settle s", "folder"):
            table.add_column(col)
        broken: list[str] = []
        for path in bundled_paths():
            pag = load_pag(path, vocabulary=vocab)
            folder = out / safe_name(pag.name, path.stem)
            console.print(f"solving {path.name} ...")
            _prepare_out(folder)
            scene = run_pipeline(pag, seed=seed, out=folder,
                                 options=PipelineOptions(settle=not no_settle))
            hold = sum(1 for c in scene.relations if (c.holds_settled if scene.settled else c.holds))
            table.add_row(pag.room.type, str(len(scene.objects)), str(len(scene.placed)),
                          f"{hold}/{len(scene.relations)}",
                          "-" if scene.contacts is None else str(len(scene.contacts)),
                          f"{scene.timings.get('solve', 0):.2f}",
                          f"{scene.timings.get('settle', 0):.2f}", str(folder))
            broken += [f"{pag.name}: {b}" for b in broken_after_settling(scene)]
        # a wide console even when the output is not a terminal (make demo, CI logs)
        Console(highlight=False, width=max(console.width, 140)).print(table)
        for b in broken:
            console.print(f"broken after settling: {b}")
        console.print(f"Open the .glb files in Blender or any glTF viewer; preview.png shows each room. "
                      f"Files are in {out}/")
