"""Cheap value coercion for the command line's plain parameters (start-up time).

Typer coerces every parameter through a pydantic ``TypeAdapter``: importing pydantic and
building the adapters costs about a quarter of a second of every command's start-up, more
than the work of ``parse3d validate`` itself. The commands' parameters are almost all plain
``str``, ``int``, ``float``, ``bool`` and ``Path`` values (or lists of them), which need
nothing of that machinery. :func:`install` gives each such parameter a small coercer of its
own, before Typer builds an adapter for it; any other parameter (ranges, choices, custom
parsers, enums) keeps Typer's own coercion. If Typer's internals are not the ones this
module knows, :func:`install` does nothing and Typer coerces as before.
"""

from __future__ import annotations

import types
import typing
from dataclasses import dataclass
from pathlib import Path
from typing import Any

__all__ = ["install"]

_TRUE = frozenset({"1", "true", "t", "yes", "y", "on"})
_FALSE = frozenset({"0", "false", "f", "no", "n", "off", ""})
_PLAIN = (str, int, float, bool, Path)

try:  # Typer >= 0.20: coercion objects per parameter, built lazily on first use
    from typer._click.exceptions import BadParameter
    from typer._coercion import RuntimeParam
    from typer._param_types import coerce_cli_path
except ImportError:  # another Typer: leave its coercion alone
    RuntimeParam = None  # type: ignore[assignment,misc]


def _to(kind: type, value: Any) -> Any:
    """One command-line value as ``kind``; ``ValueError`` with a user-facing message."""
    if isinstance(value, kind) and not (kind is int and isinstance(value, bool)):
        return value
    if isinstance(value, bytes):
        value = value.decode("utf-8", "replace")
    if kind is str:
        return str(value)
    text = str(value).strip()
    if kind is bool:
        low = text.lower()
        if low in _TRUE:
            return True
        if low in _FALSE:
            return False
        raise ValueError(f"{value!r} is not a valid boolean (use true or false)")
    if kind is int:
        try:
            return int(text)
        except ValueError:
            raise ValueError(f"{value!r} is not a valid integer") from None
    try:  # float
        return float(text)
    except ValueError:
        raise ValueError(f"{value!r} is not a valid number") from None


def _plain(annotation: Any) -> tuple[type, bool] | None:
    """(leaf type, is a list) of a plain annotation; None for anything else."""
    origin = typing.get_origin(annotation)
    if origin in (typing.Union, types.UnionType):
        args = [a for a in typing.get_args(annotation) if a is not type(None)]
        return _plain(args[0]) if len(args) == 1 else None
    if origin is list:
        args = typing.get_args(annotation)
        inner = _plain(args[0]) if len(args) == 1 else None
        return (inner[0], True) if inner is not None and not inner[1] else None
    if origin is None and annotation in _PLAIN:
        return annotation, False
    return None


if RuntimeParam is not None:

    @dataclass(frozen=True)
    class _PlainParam(RuntimeParam):
        """Coerces ``str``/``int``/``float``/``bool``/``Path`` values (and lists of them)."""

        kind: type = str
        many: bool = False

        def _one(self, value: Any, param, ctx) -> Any:
            if self.kind is Path:
                v = value if isinstance(value, Path) else Path(
                    value.decode("utf-8", "replace") if isinstance(value, bytes) else value)
                path_type = self.parameter_info.path_type or Path
                if path_type is not Path:
                    v = path_type(v)
                return coerce_cli_path(v, self.parameter_info, path_type=path_type,
                                       param=param, ctx=ctx)
            try:
                return _to(self.kind, value)
            except ValueError as e:
                raise BadParameter(str(e), ctx=ctx, param=param) from None

        def _coerce_value(self, value: Any, param, ctx) -> Any:
            if self.many:
                items = value if isinstance(value, (list, tuple)) else [value]
                return [self._one(v, param, ctx) for v in items]
            return self._one(value, param, ctx)


def _fast(param) -> Any | None:
    """A :class:`_PlainParam` for one Typer parameter, or None to leave it to Typer."""
    desc = getattr(param, "type_descriptor", None)
    if desc is None or getattr(param, "_runtime_param", "missing") is not None:
        return None
    info = desc.parameter_info
    if desc.file_annotation is not None or info.parser is not None:
        return None
    if getattr(info, "min", None) is not None or getattr(info, "max", None) is not None:
        return None
    plain = _plain(desc.annotation)
    if plain is None:
        return None
    kind, many = plain
    if kind is not Path and getattr(info, "path_type", None) is not None:
        return None
    return _PlainParam(parameter_info=info, annotation=desc.annotation, kind=kind, many=many)


def _install_one(param) -> None:
    try:
        fast = _fast(param)
    except Exception:  # an unknown Typer detail: keep Typer's coercion
        fast = None
    if fast is not None:
        param._runtime_param = fast


def install(command) -> None:
    """Give every plain parameter of a click command (and its subcommands) a cheap coercer;
    ``--help``, made when a command line is parsed, included."""
    if RuntimeParam is None:
        return
    for param in getattr(command, "params", ()):
        _install_one(param)
    help_option = getattr(command, "get_help_option", None)
    if help_option is not None and not getattr(help_option, "_parse3d_plain", False):
        def get_help_option(ctx, _made=help_option):
            option = _made(ctx)
            if option is not None:
                _install_one(option)
            return option

        get_help_option._parse3d_plain = True
        command.get_help_option = get_help_option
    commands = getattr(command, "commands", None)
    if isinstance(commands, dict):  # not ``commands.values()``: the root's would import all
        for sub in dict.values(commands):
            install(sub)
