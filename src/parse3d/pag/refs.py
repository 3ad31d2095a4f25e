"""References to objects, parts and surfaces: ``object[:part[#k]][@surface]``.

Examples
--------
>>> r = parse_ref("bookcase:shelf#2@top")
>>> (r.object, r.part, r.index, r.surface)
('bookcase', 'shelf', 2, 'top')
>>> parse_ref("wall_1").is_room_element
True
"""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["Ref", "parse_ref", "RefSyntaxError", "is_room_element", "ROOM_ELEMENTS", "wall_index"]

_IDENT = r"[A-Za-z_][A-Za-z0-9_\-]*"
_REF_RE = re.compile(
    rf"^(?P<object>{_IDENT})"
    rf"(?::(?P<part>{_IDENT})(?:#(?P<index>[0-9]+))?)?"
    rf"(?:@(?P<surface>[A-Za-z_]+))?$"
)
_WALL_RE = re.compile(r"^wall_(0|[1-9][0-9]*)$")

#: Names of room elements that are not numbered walls.
ROOM_ELEMENTS = ("floor", "ceiling", "wall")


class RefSyntaxError(ValueError):
    """A reference string does not follow ``object[:part[#k]][@surface]``."""


def is_room_element(name: str) -> bool:
    """Whether ``name`` names the floor, the ceiling, ``wall`` or a numbered wall ``wall_i``."""
    return name in ROOM_ELEMENTS or _WALL_RE.match(name) is not None


def wall_index(name: str) -> int | None:
    """The index ``i`` of ``wall_i``, else None."""
    m = _WALL_RE.match(name)
    return int(m.group(1)) if m else None


@dataclass(frozen=True)
class Ref:
    """A parsed reference.

    Attributes
    ----------
    object : str
        Object id or room element name.
    part : str or None
        Part label from the category's vocabulary (may match several parts).
    index : int or None
        ``#k``: the k-th matching part, 0-based, ordered bottom-to-top, then left-to-right,
        then back-to-front.
    surface : str or None
        One of ``top, bottom, front, back, left, right`` (checked by the validator, not here).
    text : str
        The reference as written, kept for exact round-trip.
    """

    object: str
    part: str | None = None
    index: int | None = None
    surface: str | None = None
    text: str = ""

    @property
    def is_room_element(self) -> bool:
        return is_room_element(self.object)

    def __str__(self) -> str:
        return self.text or format_ref(self.object, self.part, self.index, self.surface)


def format_ref(
    obj: str, part: str | None = None, index: int | None = None, surface: str | None = None
) -> str:
    """Write a reference string from its pieces."""
    s = obj
    if part is not None:
        s += f":{part}"
        if index is not None:
            s += f"#{index}"
    if surface is not None:
        s += f"@{surface}"
    return s


def parse_ref(text: str) -> Ref:
    """Parse ``object[:part[#k]][@surface]``.

    Raises
    ------
    RefSyntaxError
        With a message saying what is wrong and how to write it.
    """
    if not isinstance(text, str):
        raise RefSyntaxError(f"a reference must be a string, got {type(text).__name__}")
    m = _REF_RE.match(text)
    if m is None:
        hint = _syntax_hint(text)
        raise RefSyntaxError(
            f"bad reference {text!r}: expected 'object[:part[#k]][@surface]'{hint}"
        )
    idx = m.group("index")
    return Ref(m.group("object"), m.group("part"), int(idx) if idx is not None else None,
               m.group("surface"), text)


def _syntax_hint(text: str) -> str:
    if text == "":
        return " (the reference is empty)"
    if " " in text:
        return " (references contain no spaces)"
    if "." in text:
        return " (use ':' between object and part, e.g. 'desk:tabletop')"
    if text.count("@") > 1:
        return " (only one '@surface' is allowed)"
    if "#" in text and ":" not in text:
        return " ('#k' selects among parts: 'object:part#k')"
    if "#" in text:
        return " ('#k' takes a non-negative integer right after the part label)"
    if text.count(":") > 1:
        return " (only one ':part' is allowed)"
    if text[:1].isdigit():
        return " (ids start with a letter or '_')"
    return ""
