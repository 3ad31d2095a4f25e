"""Typed errors of parse3d.

Two families are kept apart on purpose:

* :class:`InputError` — the user's input is wrong (a PAG file, an asset folder, a command-line
  value). It carries every :class:`Problem` found, each naming the file, a JSON pointer into it
  and a message, so that the CLI prints one line per problem and exits with code 2.
* :class:`InfeasibleError` — the input is valid but no solution was found (no pose satisfies an
  object's constraints). It carries the solve report; the CLI exits with code 3.

Everything else (:class:`DependencyError` for a missing system library, :class:`AssetError` for a
broken generator) is a :class:`Parse3dError` too.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

__all__ = [
    "Parse3dError",
    "Problem",
    "InputError",
    "SchemaError",
    "ReferenceError",
    "GraphError",
    "ParameterError",
    "GeometryInputError",
    "VocabularyError",
    "InfeasibleError",
    "AssetError",
    "DependencyError",
    "EXIT_OK",
    "EXIT_INPUT",
    "EXIT_INFEASIBLE",
]

EXIT_OK = 0
EXIT_INPUT = 2
EXIT_INFEASIBLE = 3


class Parse3dError(Exception):
    """Base class of every error raised on purpose by parse3d."""


@dataclass(frozen=True)
class Problem:
    """One thing wrong with an input.

    Attributes
    ----------
    pointer : str
        RFC 6901 JSON pointer into the input document (``""`` for the whole document).
    message : str
        What is wrong, with a suggestion where one exists.
    file : str or None
        The file the input came from, if any.
    kind : str
        A short machine-readable category (``schema``, ``reference``, ``graph``, ``parameter``,
        ``geometry``, ``vocabulary``, ``syntax``, ``io``).
    """

    pointer: str
    message: str
    file: str | None = None
    kind: str = "schema"

    def __str__(self) -> str:
        return f"{self.file or '<input>'}:{self.pointer or '/'}: {self.message}"

    def to_dict(self) -> dict[str, str]:
        return {"pointer": self.pointer or "/", "message": self.message, "kind": self.kind}


class InputError(Parse3dError, ValueError):
    """The user's input is wrong. Carries every problem found in one pass.

    Parameters
    ----------
    problems : sequence of Problem or str
        The problems; a plain string becomes a problem with an empty pointer.
    file : str, optional
        Fills in the file of problems that do not name one.
    """

    def __init__(self, problems: Sequence[Problem] | Problem | str, file: str | None = None):
        if isinstance(problems, (Problem, str)):
            problems = [problems]
        fixed = []
        for p in problems:
            if isinstance(p, str):
                p = Problem("", p, file)
            elif p.file is None and file is not None:
                p = Problem(p.pointer, p.message, file, p.kind)
            fixed.append(p)
        self.problems: list[Problem] = fixed
        super().__init__("\n".join(str(p) for p in fixed))

    @classmethod
    def merge(cls, errors: Iterable[InputError]) -> InputError:
        problems: list[Problem] = []
        for e in errors:
            problems.extend(e.problems)
        return cls(problems)


class SchemaError(InputError):
    """The document does not follow the file format's JSON Schema."""


class ReferenceError(InputError):  # noqa: A001 - deliberately shadows the builtin inside parse3d
    """A reference names an object, part or surface that does not exist, or has bad syntax."""


class GraphError(InputError):
    """The relation graph is not a valid assembly: a cycle, a missing or a double supporter."""


class ParameterError(InputError):
    """A relation parameter has the wrong type, unit or range, or is not allowed."""


class GeometryInputError(InputError):
    """A room footprint or height that describes no real room."""


class VocabularyError(InputError):
    """An unknown category or a part label that the category does not have."""


class InfeasibleError(Parse3dError):
    """No pose satisfies some object's constraints within the trial budget.

    Attributes
    ----------
    report : Any
        The solve report (``parse3d.solver.SolveReport``) with every failed object and the
        constraint that emptied its feasible region. The partial scene is still usable.
    """

    def __init__(self, message: str, report: Any = None):
        super().__init__(message)
        self.report = report


class AssetError(Parse3dError):
    """An asset could not be generated or loaded."""


class DependencyError(Parse3dError):
    """A system library or optional package that a feature needs is missing.

    The message names the package to install.
    """
