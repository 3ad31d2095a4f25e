"""The ``parse3d`` command line. Thin: parses arguments, calls the library, prints.

Each command group lives in its own module of this package and exposes ``register(app)``.
Input mistakes (:class:`parse3d.errors.InputError`) print one line per problem and exit 2;
infeasible scenes exit 3 (DESIGN §6). No traceback reaches the user for an input mistake.
"""

from __future__ import annotations

import importlib
import importlib.util
import sys

import typer

from ..errors import EXIT_INFEASIBLE, EXIT_INPUT, InfeasibleError, InputError, Parse3dError

__all__ = ["app", "main"]

app = typer.Typer(
    name="parse3d",
    help="Part-aware relational spatial modelling: PAG files to settled 3D scenes.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)

# Command modules, in the order their commands appear in --help.
_MODULES = ("validate", "pag", "solve", "settle", "render", "assets", "template", "dataset", "layout", "demo")

for _name in _MODULES:
    if importlib.util.find_spec(f"{__name__}.{_name}") is not None:
        importlib.import_module(f"{__name__}.{_name}").register(app)


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``parse3d`` console script."""
    try:
        app(args=argv, standalone_mode=True)
    except InputError as e:
        for p in e.problems:
            typer.echo(str(p), err=True)
        sys.exit(EXIT_INPUT)
    except InfeasibleError as e:
        typer.echo(f"infeasible: {e}", err=True)
        sys.exit(EXIT_INFEASIBLE)
    except Parse3dError as e:
        typer.echo(f"error: {e}", err=True)
        sys.exit(1)
