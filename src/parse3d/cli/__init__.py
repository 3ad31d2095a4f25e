"""The ``parse3d`` command line. Thin: parses arguments, calls the library, prints.

Each command group lives in its own module of this package and exposes ``register(app)``;
the typer application that holds them is :mod:`parse3d.cli._app` (``parse3d.cli.app``).
Input mistakes (:class:`parse3d.errors.InputError`) print one line per problem and exit 2, as
does a missing optional extra (:class:`parse3d.errors.DependencyError`, naming the extra);
infeasible scenes exit 3 (DESIGN §6). No traceback reaches the user for an input mistake.

Importing typer and building the application cost more than a small solve's own work, so a
plain ``parse3d solve`` line (known options with well-formed values, see ``_fast``) runs
without them; every other line, a mistake in that one included, goes through typer.
"""

from __future__ import annotations

import errno
import sys
from collections.abc import Callable

from ..errors import (
    EXIT_INFEASIBLE,
    EXIT_INPUT,
    DependencyError,
    InfeasibleError,
    InputError,
    Parse3dError,
)

__all__ = ["app", "main"]


def _echo_err(message: str) -> None:
    print(message, file=sys.stderr, flush=True)


def _os_message(e: OSError) -> str:
    where = e.filename if e.filename is not None else "<output>"
    what = e.strerror or str(e)
    hint = {errno.EACCES: "check the permissions or choose another folder",
            errno.EROFS: "the file system is read-only; choose another folder",
            errno.ENOSPC: "the disk is full; free space or choose another folder",
            errno.EISDIR: "a folder is in the way; give a file path",
            errno.ENOTDIR: "a file is in the way; give a folder path",
            errno.EEXIST: "something is in the way; choose another path"}.get(e.errno, "")
    return f"{where}:/: {what}" + (f" ({hint})" if hint else "")


def run_guarded(run: Callable[[], None]) -> None:
    """``run()`` with the library's errors turned into one line on stderr and an exit code."""
    try:
        run()
    except InputError as e:
        for p in e.problems:
            _echo_err(str(p))
        sys.exit(EXIT_INPUT)
    except OSError as e:
        # the disk or environment refused (read-only folder, a file where a folder is
        # expected, a full disk): one line naming the path, as for an input mistake
        _echo_err(_os_message(e))
        sys.exit(EXIT_INPUT)
    except KeyboardInterrupt:
        _echo_err("interrupted")
        sys.exit(130)
    except InfeasibleError as e:
        _echo_err(f"infeasible: {e}")
        sys.exit(EXIT_INFEASIBLE)
    except DependencyError as e:
        # a missing extra (or system library) is the user's set-up to fix, as an input
        # mistake is: one line naming what to install, exit 2
        _echo_err(f"error: {e}")
        sys.exit(EXIT_INPUT)
    except Parse3dError as e:
        _echo_err(f"error: {e}")
        sys.exit(1)


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``parse3d`` console script."""
    from ._fast import run

    args = sys.argv[1:] if argv is None else [str(a) for a in argv]
    if run(args):
        return
    from ._app import main as typer_main

    typer_main(argv)


#: What :mod:`parse3d.cli._app` defines that this package hands out (loaded on first use).
_FROM_APP = ("app", "_MODULES", "_LAZY", "_EAGER", "_LOADED", "_module_commands",
             "_lazy_module", "_LazyCommands", "_LazyGroup")


def __getattr__(name: str):
    if name not in _FROM_APP:  # submodules are found by the import system, not here
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    import importlib

    return getattr(importlib.import_module(f"{__name__}._app"), name)
