"""``parse3d template list|expand|check``: room templates that expand into PAGs."""

from __future__ import annotations

from pathlib import Path

import typer

from ..errors import EXIT_INFEASIBLE
from ._common import console, print_json

__all__ = ["register"]


def objects_by_seed(counts: list[int] | tuple[int, ...]) -> str:
    """The objects a template expanded into, per seed, said as such.

    Optional motifs and counts are drawn per seed, so one template expands into different
    numbers of objects (``63, 62`` is seed 0 then seed 1, not "63 of 62").

    Examples
    --------
    >>> objects_by_seed([63, 62])
    '62-63 objects (by seed: 63, 62)'
    >>> objects_by_seed([40, 40])
    '40 objects (each seed)'
    """
    lo, hi = min(counts), max(counts)
    if lo == hi:
        return f"{lo} objects" + (" (each seed)" if len(counts) > 1 else "")
    return f"{lo}-{hi} objects (by seed: {', '.join(map(str, counts))})"


def register(app: typer.Typer) -> None:
    group = typer.Typer(help="Room templates (pag-template/1): list, expand into PAGs, check.",
                        no_args_is_help=True)
    app.add_typer(group, name="template")

    @group.command("list")
    def list_cmd(
        room_type: str = typer.Option(None, "--room-type", help="Only this room type."),
        json_out: bool = typer.Option(False, "--json", help="Print JSON on stdout."),
    ) -> None:
        """List the bundled templates.

        Example:

            parse3d template list --room-type study
        """
        from ..datagen.templates import list_templates

        ts = list_templates(room_type)
        if json_out:
            print_json([{"name": t.name, "room_type": t.room_type, "description": t.description,
                         "motifs": sorted(t.motifs), "file": t.file} for t in ts])
            return
        for t in ts:
            console.print(f"{t.room_type:<13} {t.name:<32} {t.description}")
        console.print(f"{len(ts)} template{'s' if len(ts) != 1 else ''}")

    @group.command("expand")
    def expand_cmd(
        template: str = typer.Argument(..., help="A bundled template name or a template file."),
        seed: int = typer.Option(0, "--seed", min=0, max=2**32 - 1,
                                  help="Expansion seed, 0..4294967295."),
        out: Path = typer.Option(None, "-o", "--out", help="Write the PAG here (.json/.yaml)."),
        json_out: bool = typer.Option(False, "--json", help="Print the PAG as JSON on stdout."),
    ) -> None:
        """Expand a template into a PAG for one seed; print it or write it.

        Example:

            parse3d template expand study-reading-02 --seed 3 -o room.json
        """
        from ..datagen.templates import expand_template, load_template
        from ..pag.io import dumps_pag, save_pag

        pag = expand_template(load_template(template), seed)
        if out is not None:
            save_pag(pag, out)
            if json_out:
                print_json({"file": str(out), "name": pag.name, "objects": len(pag.objects),
                            "relations": len(pag.relations)})
            else:
                console.print(f"{out}: {pag.name}, {len(pag.objects)} objects, "
                              f"{len(pag.relations)} relations")
            return
        typer.echo(dumps_pag(pag.to_dict()), nl=False)

    @group.command("check")
    def check_cmd(
        templates: list[str] = typer.Argument(..., help="Template names or files."),
        seeds: int = typer.Option(2, "--seeds", min=1, max=100,
                                   help="Seeds 0..K-1 to expand and solve (K at most 100)."),
        json_out: bool = typer.Option(False, "--json", help="Print results as JSON on stdout."),
        threshold: float = typer.Option(0.9, "--threshold", min=0.0, max=1.0,
                                        help="Least mean placed fraction per template."),
    ) -> None:
        """Expand each template for K seeds, solve without settling, report what was placed.

        Exits 3 when a template places less than the threshold (default 90%) of its objects
        on average.

        Example:

            parse3d template check study-reading-02 bedroom-master-01 --seeds 2
        """
        from ..datagen.templates import check_template, load_template

        loaded = [load_template(t) for t in templates]
        results = []
        for t in loaded:
            r = check_template(t, range(seeds))
            results.append(r)
            if not json_out:
                mark = "ok " if r.placed_fraction >= threshold else "LOW"
                console.print(f"{mark} {t.name:<32} placed {r.placed_fraction:6.1%}  "
                              f"{objects_by_seed(r.n_objects)}  {sum(r.seconds):5.1f} s")
                for s, oid, reason in r.failures:
                    console.print(f"      seed {s} {oid}: {reason}")
        if json_out:
            print_json([r.to_dict() for r in results])
        if any(r.placed_fraction < threshold for r in results):
            raise typer.Exit(EXIT_INFEASIBLE)
