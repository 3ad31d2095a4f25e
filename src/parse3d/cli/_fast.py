"""``parse3d solve`` without typer, for plain command lines.

A line that names ``solve``, one PAG file and only ``solve``'s own options, each at most once
and with a well-formed value (``--seed 3``, not ``--seed=3``, ``--seed +3`` or ``--seed 3_0``),
runs here: the same function the typer command calls, with the same values typer would
convert (``int``, ``float``, ``pathlib.Path``). Anything else, ``--help`` and every mistake
included, returns False and goes through typer, which gives its usual messages.
"""

from __future__ import annotations

import errno
import re
import sys
from pathlib import Path

__all__ = ["solve_args", "run"]

_FLAGS = {"--no-settle": "no_settle", "--no-preview": "no_preview", "--json": "as_json",
          "--strict": "strict"}
_INT = re.compile(r"-?[0-9]+\Z")
_FLOAT = re.compile(r"-?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][-+]?[0-9]+)?\Z")
_TEXT = re.compile(r"[^-\s][^\s]*\Z")
_VALUES = {"--seed": ("seed", _INT, int), "--out": ("out", _TEXT, Path),
           "-o": ("out", _TEXT, Path), "--strategy": ("strategy", _TEXT, str),
           "--search": ("search", _TEXT, str), "--search-budget": ("search_budget", _INT, int),
           "--time-limit": ("time_limit", _FLOAT, float), "--formats": ("formats", _TEXT, str)}


def solve_args(args: list[str]) -> dict | None:
    """The keyword arguments of :func:`parse3d.cli.solve.solve_file` for a plain ``solve``
    line ``args`` (without the program name); None for any other line."""
    if len(args) < 2 or args[0] != "solve":
        return None
    kw: dict = {}
    files: list[str] = []
    k = 1
    while k < len(args):
        a = args[k]
        if a in _FLAGS:
            name, value = _FLAGS[a], True
        elif a in _VALUES:
            name, pattern, convert = _VALUES[a]
            if k + 1 >= len(args) or not pattern.match(args[k + 1]):
                return None
            k += 1
            value = convert(args[k])
        elif _TEXT.match(a):
            files.append(a)
            k += 1
            continue
        else:
            return None
        if name in kw:
            return None
        kw[name] = value
        k += 1
    if len(files) != 1:
        return None
    return {"pag_file": Path(files[0]), **kw}


def run(args: list[str]) -> bool:
    """Run ``args`` here when :func:`solve_args` takes it, exiting as the typer command would
    (0 when it returns); False when the line is left to typer."""
    kw = solve_args(args)
    if kw is None:
        return False
    from . import run_guarded
    from .solve import solve_file

    def command() -> None:
        # what click's standalone mode does around a command
        try:
            solve_file(**kw)
        except (EOFError, KeyboardInterrupt):
            print(file=sys.stderr)
            print("Aborted!", file=sys.stderr, flush=True)
            sys.exit(1)
        except OSError as e:
            if e.errno == errno.EPIPE:
                sys.exit(1)
            raise
        sys.exit(0)

    run_guarded(command)
    return True
