"""Helpers shared by the command modules."""

from __future__ import annotations

import json
import math
import re
import sys
from typing import Any

from ..errors import InputError, Problem


class _Console:
    """A ``rich`` console made on first use: importing rich costs start-up time that a
    command printing plain lines (``validate``) does not need to pay."""

    def __init__(self, **options) -> None:
        self._options = options
        self._console = None

    def get(self):
        """The ``rich.console.Console`` itself (for rich APIs that take one: progress bars)."""
        if self._console is None:
            from rich.console import Console

            self._console = Console(**self._options)
        return self._console

    def __getattr__(self, name: str):
        if name.startswith("__"):
            raise AttributeError(name)
        return getattr(self.get(), name)

    def __enter__(self):
        return self.get().__enter__()

    def __exit__(self, *exc) -> None:
        self.get().__exit__(*exc)


console = _Console(stderr=False, highlight=False, soft_wrap=True)
err_console = _Console(stderr=True, highlight=False, soft_wrap=True)


def print_json(data: Any) -> None:
    """Machine-readable output on stdout (one JSON document)."""
    sys.stdout.write(json.dumps(data, indent=2, sort_keys=False) + "\n")
    sys.stdout.flush()


#: Seeds accepted by every command: non-negative and at most 2**32 - 1.
SEED_MAX = 2**32 - 1
#: Longest folder name derived from data (a PAG's name), characters.
MAX_NAME = 100

_UNSAFE = re.compile(r"[^A-Za-z0-9._+-]+")


def check_seed(seed: int, option: str = "--seed") -> int:
    """A seed in ``0 .. SEED_MAX``, else an :class:`InputError` naming the option."""
    if not 0 <= int(seed) <= SEED_MAX:
        raise InputError(Problem("", f"{option} must be an integer in 0..{SEED_MAX}, got {seed}",
                                 option, "parameter"))
    return int(seed)


def check_range(option: str, value: float, low: float, high: float, *, unit: str = "",
                low_open: bool = False) -> float:
    """A finite number in ``[low, high]`` (``(low, high]`` with ``low_open``), else an
    :class:`InputError` naming the option and the range; NaN and infinities are refused."""
    v = float(value)
    ok = math.isfinite(v) and (v > low if low_open else v >= low) and v <= high
    if not ok:
        lb = "(" if low_open else "["
        u = f" {unit}" if unit else ""
        raise InputError(Problem("", f"{option} must be a finite number in {lb}{low:g}, "
                                     f"{high:g}]{u}, got {value}", option, "parameter"))
    return v


def safe_name(text: str | None, fallback: str) -> str:
    """A folder name made from data (a PAG's ``name``): no separators, ``..``, NUL or control
    characters, at most :data:`MAX_NAME` characters; ``fallback`` when nothing is left."""
    name = re.sub(r"\.{2,}", ".", _UNSAFE.sub("_", str(text or ""))).strip("._-")
    name = name[:MAX_NAME].strip("._-")
    if not name or set(name) <= {"."}:
        name = _UNSAFE.sub("_", fallback).strip("._-")[:MAX_NAME] or "scene"
    return name
