"""``parse3d pag show|draw``: look at a PAG file."""

from __future__ import annotations

from pathlib import Path

import typer

from ..relations import RELATIONS
from ._common import print_json

__all__ = ["register"]

_KIND_TITLES = {"support": "support", "part": "part-level", "object": "object-level"}


def _load(file: Path, check_vocabulary: bool):
    from ..pag.io import load_pag

    vocab = None
    if check_vocabulary:
        from ._vocab import cli_vocabulary

        vocab = cli_vocabulary()
    return load_pag(file, vocabulary=vocab)


def register(app: typer.Typer) -> None:
    group = typer.Typer(help="Inspect and draw PAG files.", no_args_is_help=True)
    app.add_typer(group, name="pag")

    @group.command("show")
    def show(
        file: Path = typer.Argument(..., help="A PAG file (.json, .yaml or .yml)."),
        json_out: bool = typer.Option(False, "--json", help="Print as JSON on stdout."),
        no_vocabulary: bool = typer.Option(False, "--no-vocabulary",
                                           help="Do not check categories and part labels."),
    ) -> None:
        """Show a PAG: its room, objects with categories, relations by kind, assembly order.

        Example:

            parse3d pag show examples/bedroom.json
        """
        from ..pag.algorithms import assembly_order, support_depth

        pag = _load(file, not no_vocabulary)
        order = assembly_order(pag)
        depth = support_depth(pag)
        groups: dict[str, list] = {k: [] for k in _KIND_TITLES}
        for e in pag.relations:
            groups[RELATIONS[e.relation].kind].append(e)
        if json_out:
            print_json({
                "file": str(file),
                "name": pag.name,
                "room": pag.room.to_dict(),
                "objects": [{"id": o.id, "category": list(o.candidates), "depth": depth[o.id]}
                            for o in pag.objects.values()],
                "relations": {k: [e.to_dict() for e in es] for k, es in groups.items()},
                "assembly_order": order,
            })
            return
        r = pag.room
        typer.echo(f"{pag.name}: {r.type}, {r.n_walls} walls, height {r.height:g} m, "
                   f"{len(pag.objects)} objects, {len(pag.relations)} relations")
        typer.echo("\nobjects:")
        for o in pag.objects.values():
            scale = f"  scale {o.scale[0]:g}-{o.scale[1]:g}" if o.scale else ""
            typer.echo(f"  {o.id:<20} {' | '.join(o.candidates)}{scale}")
        for kind, es in groups.items():
            if not es:
                continue
            typer.echo(f"\n{_KIND_TITLES[kind]} relations ({len(es)}):")
            for e in es:
                params = "".join(f"  {k}={v}" for k, v in e.params.items())
                typer.echo(f"  {str(e.child):<28} {e.relation:<16} {e.parent}{params}")
        typer.echo("\nassembly order:")
        typer.echo("  " + " -> ".join(order))

    @group.command("draw")
    def draw(
        file: Path = typer.Argument(..., help="A PAG file (.json, .yaml or .yml)."),
        out: Path = typer.Option(..., "--out", "-o", help="Image to write (.png or .svg)."),
        no_vocabulary: bool = typer.Option(False, "--no-vocabulary",
                                           help="Do not check categories and part labels."),
    ) -> None:
        """Draw a PAG: objects layered by support depth, part nodes, labelled relations.

        Example:

            parse3d pag draw examples/kitchen.json -o kitchen_pag.png
        """
        from ..errors import InputError
        from ..pag.draw import draw_pag

        pag = _load(file, not no_vocabulary)
        try:
            path = draw_pag(pag, out)
        except InputError as e:
            raise InputError(e.problems, file=str(file)) from None
        typer.echo(f"wrote {path}")
