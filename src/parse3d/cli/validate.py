"""``parse3d validate FILE...``: check PAG files before solving."""

from __future__ import annotations

from pathlib import Path

import typer

from ..errors import EXIT_INPUT, InputError, Problem
from ._common import print_json

__all__ = ["register", "validate_files"]


def _vocabulary():
    from ._vocab import cli_vocabulary

    return cli_vocabulary()


def validate_files(files: list[Path], *, vocabulary=None) -> list[tuple[str, list[Problem]]]:
    """Validate each file; (file, problems) pairs in the order given."""
    from ..pag.io import read_document
    from ..pag.validate import validate_data

    results = []
    for f in files:
        try:
            data = read_document(f)
        except InputError as e:
            results.append((str(f), e.problems))
            continue
        results.append((str(f), validate_data(data, file=str(f), vocabulary=vocabulary)))
    return results


def register(app: typer.Typer) -> None:
    @app.command("validate")
    def validate(
        files: list[Path] = typer.Argument(..., help="PAG files (.json, .yaml or .yml)."),
        json_out: bool = typer.Option(False, "--json", help="Print results as JSON on stdout."),
        no_vocabulary: bool = typer.Option(
            False, "--no-vocabulary",
            help="Skip the checks of category names and part labels against the asset registry."),
    ) -> None:
        """Check PAG files: schema, references, parameters, graph, room and vocabulary.

        Every problem of every file is reported in one pass, one line each:
        FILE:/json/pointer: message. Exits 0 when all files are valid, 2 otherwise.

        Example:

            parse3d validate examples/study.json examples/bathroom.yaml

            parse3d validate my_room.json --json
        """
        vocab = None if no_vocabulary else _vocabulary()
        results = validate_files(files, vocabulary=vocab)
        if json_out:
            print_json([
                {"file": f, "valid": not probs,
                 "errors": [{"pointer": p.pointer or "/", "message": p.message, "kind": p.kind}
                            for p in probs]}
                for f, probs in results
            ])
        else:
            for f, probs in results:
                if probs:
                    for p in probs:
                        typer.echo(str(p), err=True)
                else:
                    typer.echo(f"{f}: ok")
        if any(probs for _, probs in results):
            raise typer.Exit(EXIT_INPUT)
