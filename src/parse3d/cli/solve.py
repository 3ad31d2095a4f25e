"""``parse3d solve`` and ``parse3d generate``."""

from __future__ import annotations

import contextlib
import sys
import time
from pathlib import Path
from typing import TYPE_CHECKING

from .._deps import require, require_formats
from ..errors import EXIT_INFEASIBLE, EXIT_INPUT, InputError, Problem
from ._common import check_range, check_seed, console, err_console, print_json, safe_name

if TYPE_CHECKING:
    import typer

#: Bounds of the solver options (docs/hardening.md).
MAX_SEARCH_BUDGET = 10_000
MAX_TIME_LIMIT = 86_400.0


def _summary(scene, out: Path | None) -> dict:
    from ..measure.stability import broken_after_settling

    s = {
        "name": scene.pag.name,
        "room": scene.pag.room.type,
        "seed": scene.seed,
        "objects": len(scene.objects),
        "placed": len(scene.placed),
        "failed": [{"id": o.id, "reason": o.reason} for o in scene.failed],
        "relations_holding": sum(1 for c in scene.relations if c.holds),
        "relations": len(scene.relations),
        "relations_holding_settled": (sum(1 for c in scene.relations if c.holds_settled)
                                      if scene.settled else None),
        "broken_after_settling": broken_after_settling(scene),
        "contacts": None if scene.contacts is None else len(scene.contacts),
        "repaired": scene.meta.get("repair", {}).get("repaired", 0),
        "unrepaired": scene.meta.get("repair", {}).get("unrepaired", 0),
        "relaxed": [{"index": c.index, "relation": c.relation, "child": c.child,
                     "parent": c.parent, "residual": c.residual, **c.relaxed}
                    for c in scene.relaxed],
        "timings": {k: round(v, 4) for k, v in scene.timings.items()},
        "out": str(out) if out else None,
    }
    return s


def _print_summary(s: dict) -> None:
    console.print(f"[bold]{s['name']}[/] ({s['room']}, seed {s['seed']}): "
                  f"{s['placed']}/{s['objects']} objects placed, "
                  f"{s['relations_holding']}/{s['relations']} relations hold after solving"
                  + (f", {s['relations_holding_settled']} after settling"
                     if s["relations_holding_settled"] is not None else "")
                  + (f", {s['contacts']} part-level contacts" if s["contacts"] is not None else ""))
    t = s["timings"]
    console.print("  time: " + ", ".join(f"{k} {v:.3f} s" for k, v in t.items()))
    if s["repaired"] or s["unrepaired"]:
        console.print(f"  repaired after settling: {s['repaired']}, still unstable: {s['unrepaired']}")
    for r in s["relaxed"]:
        console.print(f"  [yellow]relaxed[/] {r['relation']} {r['child']} -> {r['parent']}: "
                      f"{r['blocked']}; instead: {r['instead']}", highlight=False)
    for f in s["failed"]:
        console.print(f"  [red]failed[/] {f['id']}: {f['reason']}")
    for b in s.get("broken_after_settling", []):
        console.print(f"  [yellow]broken after settling[/] {b}")
    if s["out"]:
        console.print(f"  wrote {s['out']}/scene.json"
                      + (", scene.glb" if (Path(s['out']) / 'scene.glb').exists() else "")
                      + (", contacts.json" if s["contacts"] is not None else "")
                      + (", preview.png" if (Path(s['out']) / 'preview.png').exists() else ""))


def _run(pag, seed, out, strategy, no_settle, no_preview, as_json, formats="glb",
         search="backtracking", search_budget=24, time_limit=None, strict=False) -> None:
    from ..export import check_formats
    from ..pipeline import PipelineOptions, run_pipeline
    from ..solver import SEARCHES, STRATEGIES, SolverConfig

    if strategy not in STRATEGIES:
        raise InputError(Problem("", f"unknown strategy {strategy!r} (use constrained or rejection)",
                                 "--strategy", "parameter"))
    if search not in SEARCHES:
        raise InputError(Problem("", f"unknown search {search!r} (use backtracking or greedy)",
                                 "--search", "parameter"))
    search_budget = int(check_range("--search-budget", search_budget, 0, MAX_SEARCH_BUDGET))
    if time_limit is not None:
        check_range("--time-limit", time_limit, 0, MAX_TIME_LIMIT, unit="s", low_open=True)
    opts = PipelineOptions(settle=not no_settle, preview=not no_preview,
                           solver=SolverConfig(strategy=strategy, search=search,
                                               search_budget=search_budget, relax=not strict),
                           formats=check_formats(formats, where="--formats"),
                           time_limit=time_limit)
    require_formats(opts.formats)
    if not no_settle:
        require("sapien", feature="settling (or pass --no-settle)")
    if not no_preview:
        require("moderngl", feature="the preview (or pass --no-preview)")
    _prepare_out(out)
    with _solve_progress(len(pag.objects), quiet=as_json) as progress:
        scene = run_pipeline(pag, seed=seed, out=out, options=opts, progress=progress)
    s = _summary(scene, out)
    if as_json:
        print_json(s)
    else:
        _print_summary(s)
    if not scene.ok or (strict and scene.relaxed):
        sys.exit(EXIT_INFEASIBLE)


@contextlib.contextmanager
def _solve_progress(total: int, *, quiet: bool):
    """A progress callback for the solver: a bar on a terminal; on other outputs one line per
    tenth of the objects for PAGs of 50 objects or more; nothing with ``--json``."""
    if quiet:
        yield None
        return
    if sys.stderr.isatty():
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TimeElapsedColumn

        with Progress("solving", BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
                      console=err_console.get(), transient=True) as bar:
            task = bar.add_task("solving", total=total)
            yield lambda p: bar.update(task, completed=p.done)
        return
    if total < 50:
        yield None
        return
    step = max(1, total // 10)
    t0 = time.perf_counter()

    def line(p) -> None:
        if p.done % step == 0 or p.done == p.total:
            print(f"solving: {p.done}/{p.total} objects decided, {time.perf_counter() - t0:.1f} s",
                  file=sys.stderr, flush=True)

    yield line


def _prepare_out(out: Path) -> None:
    """Check that ``out`` can hold a scene (exit 2 otherwise) and remove the outputs of an
    earlier solve there (a solve owns its folder's outputs; other files are kept)."""
    from .._files import check_output_dir
    from ..scene.io import clear_scene_outputs

    check_output_dir(out)
    clear_scene_outputs(out)


def solve_file(pag_file: Path, *, seed: int = 0, out: Path | None = None,
               strategy: str = "constrained", search: str = "backtracking",
               search_budget: int = 24, time_limit: float | None = None,
               no_settle: bool = False, no_preview: bool = False, formats: str = "glb",
               as_json: bool = False, strict: bool = False) -> None:
    """``parse3d solve``: the typer command and the plain command line (``_fast``) call this
    with the option values (the defaults are the options' defaults)."""
    from ..pag.io import load_pag
    from ._vocab import solve_vocabulary

    check_seed(seed)
    pag = load_pag(pag_file, vocabulary=solve_vocabulary())
    out = out or Path("out") / f"{safe_name(pag.name, pag_file.stem)}-{seed}"
    _run(pag, seed, out, strategy, no_settle, no_preview, as_json, formats, search,
         search_budget, time_limit, strict)


def register(app: typer.Typer) -> None:
    import typer

    @app.command("solve")
    def solve_cmd(
        pag_file: Path = typer.Argument(..., help="PAG file (.json or .yaml)."),
        seed: int = typer.Option(0, "--seed", help="Scene seed."),
        out: Path = typer.Option(None, "--out", "-o", help="Output folder (default: out/<name>-<seed>)."),
        strategy: str = typer.Option("constrained", help="constrained (Algorithm 1) or rejection (baseline)."),
        search: str = typer.Option("backtracking", help="backtracking (re-place conflicting objects) or greedy (one pass)."),
        search_budget: int = typer.Option(24, "--search-budget", help="Re-placements the backtracking search may spend."),
        time_limit: float = typer.Option(None, "--time-limit", help="Seconds; objects not placed by then fail (exit 3)."),
        no_settle: bool = typer.Option(False, "--no-settle", help="Skip physics settling and contacts."),
        no_preview: bool = typer.Option(False, "--no-preview", help="Skip preview.png."),
        formats: str = typer.Option("glb", "--formats",
                                    help="Export formats: glb, usd, mjcf, urdf, obj "
                                         "(comma-separated)."),
        as_json: bool = typer.Option(False, "--json", help="Print the summary as JSON."),
        strict: bool = typer.Option(False, "--strict",
                                    help="Every relation is hard: an object whose relations "
                                         "cannot be met fails (exit 3) instead of relaxing them."),
    ) -> None:
        """Solve a PAG into a settled scene: scene.json, scene.glb, contacts.json, preview.png.

        Exit codes: 0 all objects placed and stable (relations that could not be met are
        relaxed, printed and recorded holds: false in scene.json), 2 invalid PAG, 3 some
        objects could not be placed or stayed unstable after repair (the scene is still
        written, failed objects marked with their reason); with --strict also 3 when a
        relation could not be met.

        Example: parse3d solve examples/study.json --seed 3 --search greedy --time-limit 20 --out out/study
        """
        solve_file(pag_file, seed=seed, out=out, strategy=strategy, search=search,
                   search_budget=search_budget, time_limit=time_limit, no_settle=no_settle,
                   no_preview=no_preview, formats=formats, as_json=as_json, strict=strict)

    @app.command("generate")
    def generate_cmd(
        room_type: str = typer.Argument(..., help="Room type, e.g. bedroom, kitchen, study."),
        seed: int = typer.Option(0, "--seed", help="Scene seed: picks the template and seeds "
                                                    "its expansion and the solver."),
        out: Path = typer.Option(None, "--out", "-o",
                                 help="Output folder (default: out/<room_type>-<seed>)."),
        no_settle: bool = typer.Option(False, "--no-settle",
                                       help="Skip physics settling and contacts."),
        no_preview: bool = typer.Option(False, "--no-preview", help="Skip preview.png."),
        as_json: bool = typer.Option(False, "--json", help="Print the summary as JSON."),
    ) -> None:
        """Generate a scene of a room type: a room template of that type expanded with the seed.

        Room types: bedroom, living_room, office, study, laundry, storage, dining_room, bathroom,
        tea_house, game_room, kitchen, music_room, bar, dormitory, meeting_room, hotel, grocery.

        Example: parse3d generate bedroom --seed 7 --out out/bedroom-7
        """
        from ..scenes import bundled_pag

        check_seed(seed)
        pag = bundled_pag(room_type, seed)
        out = out or Path("out") / f"{safe_name(room_type, 'room')}-{seed}"
        _run(pag, seed, out, "constrained", no_settle, no_preview, as_json)


__all__ = ["register", "solve_file", "EXIT_INPUT"]
