"""``parse3d dataset build`` and ``parse3d dataset stats``."""

from __future__ import annotations

import sys
from pathlib import Path

import typer

from .._deps import require
from ..errors import InputError, Problem
from ._common import console, err_console, print_json


def _rooms(text: str | None) -> tuple[str, ...]:
    if not text:
        return ()
    rooms = tuple(r.strip() for r in text.split(",") if r.strip())
    if not rooms:
        raise InputError(Problem("", "--rooms needs comma-separated room types, e.g. "
                                     "bedroom,kitchen", "--rooms", "parameter"))
    return rooms


def _progress_columns():
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        ProgressColumn,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )
    from rich.text import Text

    class Rate(ProgressColumn):
        """Scenes per hour over this run (counted from its first finished scene)."""

        def render(self, task) -> Text:
            el = task.elapsed or 0.0
            done = task.fields.get("built", 0)
            rate = 3600.0 * done / el if el > 0 and done else 0.0
            return Text(f"{rate:,.0f} scenes/h" if rate else "-- scenes/h", style="cyan")

    return (TextColumn("[bold]{task.description}"), BarColumn(), MofNCompleteColumn(),
            TextColumn("ok {task.fields[ok]} · failed {task.fields[bad]}"), Rate(),
            TimeElapsedColumn(), TextColumn("ETA"), TimeRemainingColumn())


class _LineRate:
    """Rate and ETA for plain progress lines (no TTY), counted from this run's first scene."""

    def __init__(self) -> None:
        self.t0: float | None = None
        self.done0 = 0

    def tick(self, done: int, total: int) -> str:
        import time

        now = time.monotonic()
        if self.t0 is None:
            self.t0, self.done0 = now, done
            return "-- scenes/h, ETA --"
        n, el = done - self.done0, now - self.t0
        if n <= 0 or el <= 0:
            return "-- scenes/h, ETA --"
        per = el / n
        eta = max(0.0, (total - done) * per)
        h, rem = divmod(int(round(eta)), 3600)
        return f"{3600.0 / per:,.0f} scenes/h, ETA {h}:{rem // 60:02d}:{rem % 60:02d}"


def register(app: typer.Typer) -> None:
    ds = typer.Typer(name="dataset", help="Build PARSE-10K-like datasets and their statistics.",
                     no_args_is_help=True)
    app.add_typer(ds, name="dataset")

    @ds.command("build")
    def build_cmd(
        scenes: int = typer.Option(..., "--scenes", "-n", help="Number of scenes."),
        out: Path = typer.Option(..., "--out", "-o", help="Dataset folder (resumed if it exists)."),
        rooms: str = typer.Option(None, "--rooms",
                                  help="Comma-separated room types (default: all)."),
        workers: int = typer.Option(2, "--workers", "-w", help="Worker processes / tasks in flight."),
        views: int = typer.Option(0, "--views",
                                  help="Sampled views per scene besides preview.png."),
        size: str = typer.Option("640x480", "--size", help="Image size WIDTHxHEIGHT."),
        executor: str = typer.Option("local", "--executor", help="local or ray."),
        ray_address: str = typer.Option(None, "--ray-address",
                                        help="Ray cluster address (default: a local instance)."),
        seed: int = typer.Option(0, "--seed", help="Dataset seed."),
        time_limit: float = typer.Option(600.0, "--time-limit",
                                         help="Seconds per scene before it is recorded as timeout."),
        pags: list[Path] = typer.Option(None, "--pags",
                                        help="Build from these PAG files or folders instead of "
                                             "the templates (repeatable)."),
        no_settle: bool = typer.Option(False, "--no-settle",
                                       help="Skip settling and contact extraction."),
        formats: str = typer.Option("glb", "--formats",
                                    help="Export formats per scene: glb, usd, mjcf, urdf, obj "
                                         "(comma-separated; part of the dataset's identity)."),
        retry_failed: bool = typer.Option(False, "--retry-failed",
                                          help="Run failed and timed-out scenes again."),
        max_tasks: int = typer.Option(None, "--max-tasks",
                                      help="Scenes per local worker before it is replaced "
                                           "(default 200)."),
        as_json: bool = typer.Option(False, "--json", help="Print a JSON summary."),
    ) -> None:
        """Build (or resume) a dataset: DIR/scenes/<index>/, DIR/manifest.parquet, DIR/dataset.json.

        Scene i is the same whatever the executor and worker count; run the same command again
        after an interruption and only the missing scenes are built.

        Example: parse3d dataset build --scenes 100 --out out/mini --rooms bedroom,kitchen --workers 2
        """
        from ..datagen.build import (
            DEFAULT_MAX_TASKS,
            BuildConfig,
            build_dataset,
            default_source_paths,
            resolve_pag_paths,
        )
        from .render import parse_size

        source = resolve_pag_paths(pags) if pags else default_source_paths()
        cfg = BuildConfig(scenes=scenes, seed=seed, rooms=_rooms(rooms), views=views,
                          view_size=parse_size(size), settle=not no_settle, source=source,
                          time_limit=time_limit, formats=tuple(formats.split(",")))
        interactive = not as_json and sys.stderr.isatty()
        if interactive:
            from rich.progress import Progress

            prog = Progress(*_progress_columns(), console=err_console.get(), transient=False)
            prog.start()
            task = prog.add_task("building", total=scenes, ok=0, bad=0, built=0)
            built = [0]

            def on_event(ev) -> None:
                if built[0] == 0:
                    # restart the clock at the first scene of this run, so that the rate and
                    # the ETA ignore scenes found finished (resume) and the start-up
                    prog.reset(task, completed=ev.done, ok=ev.ok, bad=ev.failed, built=0)
                else:
                    prog.update(task, completed=ev.done, ok=ev.ok, bad=ev.failed,
                                built=built[0])
                built[0] += 1
        else:
            prog = None
            rate = _LineRate()

            def on_event(ev) -> None:
                r = ev.record
                extra = f" — {r['reason']}" if r.get("reason") else ""
                err_console.print(f"[{ev.done}/{ev.total}] scene {r['index']:05d} "
                                  f"{r['room_type']}/{r['template']}: {r['status']}{extra}"
                                  f" · {rate.tick(ev.done, ev.total)}", markup=False)
        try:
            report = build_dataset(cfg, out, executor=executor, workers=workers,
                                   ray_address=ray_address, retry_failed=retry_failed,
                                   max_tasks=DEFAULT_MAX_TASKS if max_tasks is None else max_tasks,
                                   progress=on_event,
                                   warn=lambda msg: err_console.print(f"warning: {msg}",
                                                                      markup=False))
        except KeyboardInterrupt:
            if prog is not None:
                prog.stop()
            err_console.print(f"interrupted: the finished scenes are kept in {out}; run the "
                              "same command again to resume")
            raise typer.Exit(130) from None
        finally:
            if prog is not None:
                prog.stop()
        summary = {"out": str(out), "scenes": report.total, "ok": report.ok,
                   "incomplete": report.incomplete,
                   "failed": report.failed, "timeout": report.timeout,
                   "resumed": report.resumed, "built": report.built,
                   "wall_s": round(report.wall, 2),
                   "scenes_per_hour": round(report.scenes_per_hour, 1)}
        if as_json:
            print_json(summary)
            return
        console.print(f"[bold]{out}[/]: {report.ok} scenes ok, {report.incomplete} incomplete, "
                      f"{report.failed} failed, "
                      f"{report.timeout} timed out ({report.resumed} found finished, "
                      f"{report.built} built in {report.wall:.1f} s, "
                      f"{report.scenes_per_hour:,.0f} scenes/h)")
        if report.failed or report.timeout:
            console.print(f"  reasons: {out}/failures/*.json and the manifest's reason column")
        console.print(f"  wrote {out}/scenes/, {out}/manifest.parquet, {out}/dataset.json; "
                      f"statistics: parse3d dataset stats {out}")

    @ds.command("stats")
    def stats_cmd(
        dataset_dir: Path = typer.Argument(..., help="Dataset folder (from parse3d dataset build)."),
        out: Path = typer.Option(None, "--out", "-o", help="Output folder (default: DIR/stats)."),
        as_json: bool = typer.Option(False, "--json", help="Print the table as JSON."),
    ) -> None:
        """Statistics of a dataset as in the paper: plots (PNG) and a table (Markdown, JSON).

        Example: parse3d dataset stats out/mini
        """
        from ..datagen.stats import dataset_stats, write_stats

        require("pyarrow", feature="dataset stats (manifest.parquet)")
        stats = dataset_stats(dataset_dir)
        files = write_stats(stats, out if out is not None else dataset_dir / "stats")
        if as_json:
            print_json(stats.table())
            return
        typer.echo(stats.markdown())
        typer.echo("wrote " + ", ".join(str(f) for f in files))
