"""PAG files in the designer's working folder: the only folder the server writes.

File names are checked, never repaired silently: a name is one path component of letters,
digits, ``.``, ``_`` and ``-``, not starting with a dot, ending in ``.json``, ``.yaml`` or
``.yml``. Anything else (``../x.json``, ``a/b.json``, ``/etc/passwd``) is an
:class:`~parse3d.errors.InputError` naming the fix. Existing files are only replaced when
the caller says so, so a save never loses a file by accident.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from ..errors import InputError, Problem
from ..pag.io import dumps_pag, loads_document, read_document, save_pag

__all__ = ["PAG_SUFFIXES", "check_name", "list_pag_files", "read_pag_file", "write_pag_file",
           "FileExistsProblem", "MissingFileProblem", "yaml_text", "parse_text"]

PAG_SUFFIXES = (".json", ".yaml", ".yml")
_NAME = re.compile(r"^[A-Za-z0-9_\-][A-Za-z0-9_.\-]{0,99}$")


class FileExistsProblem(InputError):
    """The file exists and the caller did not ask to replace it."""


class MissingFileProblem(InputError):
    """No such file in the working folder."""


def check_name(name: str) -> str:
    """``name`` if it is a safe PAG file name, else an InputError saying how to fix it."""
    if not isinstance(name, str) or not name:
        raise InputError(Problem("/name", "give a file name such as 'my-room.json'", None, "io"))
    if "/" in name or "\\" in name or name in (".", ".."):
        raise InputError(Problem("/name", f"{name!r} is not a plain file name: the designer only "
                                 "reads and writes files directly in its working folder (use "
                                 "e.g. 'my-room.json')", None, "io"))
    if not _NAME.match(name):
        raise InputError(Problem("/name", f"{name!r} is not an allowed file name: use letters, "
                                 "digits, '.', '_' and '-' (at most 100), not starting with a "
                                 "dot", None, "io"))
    if not name.lower().endswith(PAG_SUFFIXES):
        raise InputError(Problem("/name", f"{name!r} has no PAG file extension: end it in "
                                 ".json, .yaml or .yml", None, "io"))
    return name


def _path(workdir: Path, name: str) -> Path:
    root = Path(workdir).resolve()
    p = (root / check_name(name)).resolve()
    if p.parent != root:  # a symlink pointing elsewhere
        raise InputError(Problem("/name", f"{name!r} resolves outside the working folder",
                                 None, "io"))
    return p


def list_pag_files(workdir: Path) -> list[dict[str, Any]]:
    """PAG files directly in ``workdir``: name, size in bytes, modification time (s)."""
    out = []
    for p in sorted(Path(workdir).iterdir()):
        if p.is_file() and p.suffix.lower() in PAG_SUFFIXES and _NAME.match(p.name):
            st = p.stat()
            out.append({"name": p.name, "bytes": st.st_size, "modified": st.st_mtime})
    return out


def read_pag_file(workdir: Path, name: str) -> Any:
    """The parsed document of a PAG file of the working folder (not validated)."""
    p = _path(workdir, name)
    if not p.is_file():
        raise MissingFileProblem(Problem("/name", f"no file {name!r} in the working folder",
                                         None, "io"))
    try:
        return read_document(p)
    except InputError as e:  # name the file as the user knows it, not its absolute path
        raise InputError([Problem(q.pointer, q.message, name, q.kind) for q in e.problems]) from None
    except RecursionError:
        raise InputError(Problem("", "the file is nested too deeply to be a PAG", name,
                                 "syntax")) from None


def write_pag_file(workdir: Path, name: str, data: dict[str, Any], *,
                   overwrite: bool = False) -> Path:
    """Write a ``pag/1`` document as JSON or YAML (by the extension) into ``workdir``.

    The document is written as given, valid or not, so work in progress can be kept; the
    text is produced before the file is opened, so a document that cannot be written
    leaves an existing file untouched.
    """
    p = _path(workdir, name)
    if p.is_dir() or (p.exists() and not p.is_file()):
        raise InputError(Problem("/name", f"{name!r} is a folder (or not a regular file) in the "
                                 "working folder: choose another name", None, "io"))
    if p.exists() and not overwrite:
        raise FileExistsProblem(Problem("/name", f"{name!r} exists already: save with "
                                        "overwrite to replace it, or choose another name",
                                        None, "io"))
    if not isinstance(data, dict):
        raise InputError(Problem("/pag", "the PAG must be a JSON object", None, "schema"))
    if p.suffix.lower() == ".json":
        dumps_pag(data)  # raises on values JSON cannot hold before anything is written
    tmp = p.with_name(f".{p.stem}.saving{p.suffix}")
    try:
        save_pag(data, tmp)
        tmp.replace(p)  # atomic: a reader never sees half a file
    except (ValueError, TypeError, UnicodeError) as e:
        raise InputError(Problem("/pag", f"the PAG cannot be written as {p.suffix[1:]}: {e}",
                                 None, "schema")) from None
    finally:
        tmp.unlink(missing_ok=True)  # never leave a half-written temporary file behind
    return p


def yaml_text(data: dict[str, Any]) -> str:
    """YAML text of a document, as ``save_pag`` writes it to a ``.yaml`` file."""
    import yaml

    from ..pag.io import _Dumper

    return yaml.dump(data, Dumper=_Dumper, sort_keys=False, allow_unicode=True,
                     default_flow_style=None, width=100)


def parse_text(text: str, kind: str) -> Any:
    """Parse uploaded JSON or YAML text (InputError with line and column when malformed)."""
    return loads_document(text, kind=kind)
