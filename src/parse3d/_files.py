"""File-system helpers shared by every layer: safe reads, atomic writes, umask, folder locks.

This module imports nothing from parse3d but :mod:`parse3d.errors`, so any layer may use it.

* :func:`read_input_bytes` refuses what is not a regular file (a FIFO, a device, a folder)
  *before* opening it, so a named pipe given as a PAG cannot hang a command, and caps the size.
* :func:`atomic_write_bytes` writes through a temporary file renamed into place, with the
  permission bits the user's umask gives (temporary files are private by default).
* :class:`FolderLock` is a pid file with stale-lock detection: a second writer of the same
  folder is refused with an :class:`~parse3d.errors.InputError`.
"""

from __future__ import annotations

import errno
import json
import math
import os
import re
import socket
import stat
import tempfile
from pathlib import Path
from typing import Any

from .errors import InputError, Problem, SchemaError

__all__ = [
    "MAX_INPUT_BYTES",
    "current_umask",
    "user_mode",
    "read_input_bytes",
    "read_input_text",
    "MAX_DEPTH",
    "loads_json",
    "read_json",
    "read_json_lines",
    "read_npz",
    "read_torch",
    "check_json_depth",
    "inside",
    "atomic_write_bytes",
    "atomic_write_text",
    "check_output_dir",
    "FolderLock",
]

#: Largest input document read (PAGs, templates, scene files), bytes. A PAG of the largest
#: allowed size is far below it.
MAX_INPUT_BYTES = 64 * 1024 * 1024
#: Deepest nesting of lists and objects a JSON or YAML input may have (a PAG needs 4).
MAX_DEPTH = 64
#: Largest binary model file read (a layout checkpoint, a shape encoder, a ``.npz`` cache).
MAX_MODEL_BYTES = 2 * 1024**3


def current_umask() -> int:
    """The process's umask, read without changing it (Linux ``/proc``; else set and restore)."""
    try:
        with open("/proc/self/status", encoding="ascii") as f:
            for line in f:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError):
        pass
    old = os.umask(0o022)
    os.umask(old)
    return old


def user_mode(*, directory: bool = False) -> int:
    """Permission bits a plain ``open``/``mkdir`` would give: 0o666/0o777 less the umask.

    ``mkstemp``/``mkdtemp`` create private files (0o600/0o700); what is renamed from them into
    place gets these bits, so outputs look as if written directly.
    """
    return (0o777 if directory else 0o666) & ~current_umask()


def read_input_bytes(path: str | Path, *, limit: int = MAX_INPUT_BYTES, what: str = "file"
                     ) -> bytes:
    """Read an input file, refusing anything that is not a regular file of at most ``limit``.

    Raises
    ------
    InputError
        Kind ``io``: missing, a folder, a FIFO/device/socket (never opened, so never a hang),
        larger than ``limit``, or unreadable.
    """
    path = Path(path)
    name = str(path)
    try:
        st = os.stat(path)
    except FileNotFoundError:
        raise InputError(Problem("", f"no such {what}", name, "io")) from None
    except OSError as e:
        raise InputError(Problem("", f"cannot read the {what}: {e.strerror}", name, "io")
                         ) from None
    if stat.S_ISDIR(st.st_mode):
        raise InputError(Problem("", f"this is a folder; give a {what}", name, "io"))
    if not stat.S_ISREG(st.st_mode):
        raise InputError(Problem("", f"not a regular file (a pipe, device or socket): give a "
                                     f"{what} on disk", name, "io"))
    if st.st_size > limit:
        raise InputError(Problem("", f"the {what} is {st.st_size / 2**20:.1f} MiB, more than "
                                     f"the {limit / 2**20:.0f} MiB an input may have", name,
                                 "io"))
    try:
        # O_NONBLOCK: if the path was swapped for a FIFO after the stat, open does not block
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as e:
        raise InputError(Problem("", f"cannot read the {what}: {e.strerror}", name, "io")
                         ) from None
    with os.fdopen(fd, "rb") as f:
        if not stat.S_ISREG(os.fstat(f.fileno()).st_mode):
            raise InputError(Problem("", "not a regular file", name, "io"))
        data = f.read(limit + 1)
    if len(data) > limit:
        raise InputError(Problem("", f"the {what} is larger than the {limit / 2**20:.0f} MiB "
                                     "an input may have", name, "io"))
    return data


def read_input_text(path: str | Path, *, limit: int = MAX_INPUT_BYTES, what: str = "file"
                    ) -> str:
    """:func:`read_input_bytes` decoded as UTF-8 (a decoding error is an ``InputError``)."""
    data = read_input_bytes(path, limit=limit, what=what)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise InputError(Problem("", f"not UTF-8 text (byte {e.start}): save the {what} as "
                                     "UTF-8", str(path), "syntax")) from None


# ------------------------------------------------------------------------ reading user files
#
# Every file a user hands to parse3d is read through one of the functions below: the path must
# be a regular file within a size bound (never opened for a blocking read), text must be UTF-8,
# JSON nesting is bounded before a recursive parser runs, and binary formats never unpickle.


class _DupDict(dict):
    """A JSON object that had repeated keys (``dups`` lists them, in order)."""

    dups: list[str]


def _pairs(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    d: dict[str, Any] = {}
    dups = []
    for k, v in pairs:
        if k in d:
            dups.append(k)
        d[k] = v
    if dups:
        d = _DupDict(d)
        d.dups = dups
    return d


def _duplicates(v: Any, ptr: str) -> list[tuple[str, str]]:
    out: list[tuple[str, str]] = []
    stack = [(v, ptr)]
    while stack:
        v, ptr = stack.pop()
        if isinstance(v, dict):
            if isinstance(v, _DupDict):
                out += [(f"{ptr}/{_esc(k)}", k) for k in v.dups]
            stack += [(x, f"{ptr}/{_esc(k)}") for k, x in v.items()]
        elif isinstance(v, list):
            stack += [(x, f"{ptr}/{i}") for i, x in enumerate(v)]
    return sorted(out)



def _esc(key: str) -> str:
    return str(key).replace("~", "~0").replace("/", "~1")


# a string as one run of plain characters between escapes (the "unrolled loop"): the regex
# engine keeps no backtracking point per character, so a 10 MB string costs no memory
_JSON_TOKENS = re.compile(r'"[^"\\]*(?:\\.[^"\\]*)*"|[\[\]{}]')


def check_json_depth(text: str, file: str | None, *, limit: int | None = None) -> None:
    """Refuse nesting deeper than ``limit`` (:data:`MAX_DEPTH`) before the recursive JSON
    decoder sees it (a linear scan of the text)."""
    limit = MAX_DEPTH if limit is None else limit
    depth = 0
    for m in _JSON_TOKENS.finditer(text):
        c = m.group()
        if c in "[{":
            depth += 1
            if depth > limit:
                line = text.count("\n", 0, m.start()) + 1
                raise SchemaError(Problem("", f"nested more than {limit} levels deep (at "
                                              f"line {line}): the formats parse3d reads need only a few",
                                          file, "syntax"))
        elif c in "]}":
            depth -= 1



def _reject_constant(name: str) -> Any:
    raise ValueError(f"{name} is not a number (JSON has no NaN or Infinity)")


def _finite_float(text: str) -> float:
    v = float(text)
    if not math.isfinite(v):
        raise ValueError(f"{text} is too large to be a finite number")
    return v




def loads_json(text: str, *, file: str | None = None, depth: int | None = None) -> Any:
    """Parse JSON text, bounded: nesting, repeated keys and non-finite numbers are errors.

    Raises
    ------
    SchemaError
        Syntax errors (with line and column), nesting deeper than ``depth``
        (:data:`MAX_DEPTH`), a repeated key (at its pointer), ``NaN``/``Infinity``/``1e400``.
    """
    check_json_depth(text, file, limit=depth)
    try:
        data = json.loads(text, parse_constant=_reject_constant, parse_float=_finite_float,
                          object_pairs_hook=_pairs)
    except json.JSONDecodeError as e:
        raise SchemaError(Problem("", f"invalid JSON at line {e.lineno}, column {e.colno}: "
                                  f"{e.msg}", file, "syntax")) from None
    except (ValueError, RecursionError) as e:
        raise SchemaError(Problem("", f"invalid JSON: {e}", file, "syntax")) from None
    dups = _duplicates(data, "")
    if dups:
        raise SchemaError([Problem(ptr, f"the key {key!r} is repeated in this object "
                                        "(JSON keeps only one): remove or rename it",
                                   file, "syntax") for ptr, key in dups])
    return data


def read_json(path: str | Path, *, limit: int = MAX_INPUT_BYTES, what: str = "file",
              depth: int | None = None) -> Any:
    """Read a user's JSON file: :func:`read_input_text` then :func:`loads_json`."""
    return loads_json(read_input_text(path, limit=limit, what=what), file=str(path),
                      depth=depth)


def read_json_lines(path: str | Path, *, limit: int = MAX_INPUT_BYTES, what: str = "file",
                    depth: int | None = None) -> list[tuple[int, Any]]:
    """Read a JSON Lines file: ``[(line number, value)]`` for every non-blank line.

    A bad line is an :class:`InputError` naming the file and the line (pointer ``line N``).
    """
    text = read_input_text(path, limit=limit, what=what)
    out = []
    for n, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        try:
            out.append((n, loads_json(line, file=str(path), depth=depth)))
        except SchemaError as e:
            msg = e.problems[0].message if e.problems else str(e)
            raise SchemaError(Problem(f"line {n}", f"not valid JSON ({msg}); one JSON value per "
                                                   "line", str(path), "syntax")) from None
    return out


def inside(base: str | Path, rel: Any, *, what: str = "file", file: str | None = None
           ) -> Path:
    """``base / rel`` when ``rel`` is a relative path that stays inside ``base`` once symbolic
    links are resolved; an :class:`InputError` otherwise (``../../etc/passwd``, ``/home/x``).

    A record naming its images, or a URDF naming its meshes, must never reach a file outside
    the folder it came with (an image is uploaded to a model endpoint as it is)."""
    root = Path(base).resolve()
    if not isinstance(rel, str) or not rel or "\0" in rel or Path(rel).is_absolute():
        raise InputError(Problem("", f"the {what} {rel!r} is not a relative path in "
                                     f"{root.name or root}", file, "io"))
    p = (root / rel).resolve()
    if not p.is_relative_to(root):
        raise InputError(Problem("", f"the {what} {rel!r} lies outside {root.name or root}: "
                                     "only files inside it are read", file, "io"))
    return p


def read_npz(path: str | Path, *, limit: int = MAX_MODEL_BYTES, what: str = "file"
             ) -> dict[str, Any]:
    """Read a ``.npz`` archive into ``{name: array}`` without pickles.

    A damaged archive, an object array (a pickle) or a file that is not a zip is an
    :class:`InputError` naming the file.
    """
    import io
    import zipfile

    import numpy as np

    data = read_input_bytes(path, limit=limit, what=what)
    try:
        with np.load(io.BytesIO(data), allow_pickle=False) as z:
            return {k: z[k] for k in z.files}
    except (ValueError, OSError, EOFError, KeyError, zipfile.BadZipFile) as e:
        raise InputError(Problem("", f"not a readable .npz archive ({_first_line(e)}): "
                                     "it is damaged or was not written by parse3d", str(path),
                                 "io")) from None


def read_torch(path: str | Path, *, limit: int = MAX_MODEL_BYTES, what: str = "checkpoint"
               ) -> Any:
    """Read a PyTorch file with ``weights_only=True``: tensors, numbers, strings, lists and
    dicts only. No code in the file ever runs (a pickle that would call a function is refused).

    Raises
    ------
    InputError
        The file is missing, damaged, truncated, or holds anything but plain weights.
    """
    import io

    import torch

    data = read_input_bytes(path, limit=limit, what=what)
    try:
        return torch.load(io.BytesIO(data), map_location="cpu", weights_only=True)
    except Exception as e:  # noqa: BLE001 - the unpickler raises many types for damaged files
        raise InputError(Problem("", f"not a readable {what} ({_first_line(e)}): it is "
                                     "damaged, truncated or holds more than plain weights",
                                 str(path), "io")) from None


def _first_line(e: BaseException) -> str:
    text = str(e).strip().splitlines()
    line = text[0] if text else type(e).__name__
    return line[:200]


def check_output_dir(path: str | Path, *, option: str = "--out") -> Path:
    """Make sure ``path`` is (or can become) a writable folder; create it.

    Raises
    ------
    InputError
        ``path`` or one of its parents is a file, or the folder cannot be created or written.
    """
    path = Path(path)
    if path.exists() and not path.is_dir():
        raise InputError(Problem("", f"{option} names a file, not a folder: give a folder "
                                     "path", str(path), "io"))
    try:
        path.mkdir(parents=True, exist_ok=True)
    except (FileExistsError, NotADirectoryError):
        raise InputError(Problem("", f"a part of the {option} path is a file, not a folder",
                                 str(path), "io")) from None
    except OSError as e:
        raise InputError(Problem("", f"cannot create the {option} folder: {e.strerror}",
                                 str(path), "io")) from None
    if not os.access(path, os.W_OK | os.X_OK):
        raise InputError(Problem("", f"the {option} folder is not writable: choose another "
                                     "folder or fix its permissions", str(path), "io"))
    return path


def atomic_write_bytes(path: str | Path, data: bytes) -> None:
    """Write ``data`` to ``path`` through a temporary file renamed over it (mode per umask)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.chmod(tmp, user_mode())
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def atomic_write_text(path: str | Path, text: str) -> None:
    """:func:`atomic_write_bytes` of UTF-8 text."""
    atomic_write_bytes(path, text.encode("utf-8"))


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    except OSError:
        return False
    return True


class FolderLock:
    """An exclusive pid-file lock on a folder (``<folder>/<name>``), stale-lock aware.

    The file holds ``{"pid": ..., "host": ...}``. A lock whose process no longer runs on this
    host is stale and is taken over. Use as a context manager; the file is removed on exit.

    Raises
    ------
    InputError
        Another live process holds the lock (the message names its pid).
    """

    def __init__(self, folder: str | Path, *, name: str = ".parse3d.lock",
                 what: str = "this folder") -> None:
        self.path = Path(folder) / name
        self.what = what
        self._held = False

    def _holder(self) -> dict | None:
        try:
            return json.loads(self.path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None

    def acquire(self) -> None:
        me = {"pid": os.getpid(), "host": socket.gethostname()}
        for _ in range(3):
            try:
                fd = os.open(self.path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
            except FileExistsError:
                h = self._holder()
                if (isinstance(h, dict) and isinstance(h.get("pid"), int)
                        and (h.get("host") != me["host"] or _alive(h["pid"]))):
                    where = "" if h.get("host") == me["host"] else f" on {h.get('host')}"
                    raise InputError(Problem(
                        "", f"another process (pid {h['pid']}{where}) is writing {self.what}; "
                            f"wait for it to finish (remove {self.path.name} if it is gone)",
                        str(self.path.parent), "io")) from None
                # stale (dead process, or unreadable half-written file): take it over
                self.path.unlink(missing_ok=True)
                continue
            except OSError as e:
                if e.errno in (errno.EACCES, errno.EROFS, errno.EPERM):
                    raise InputError(Problem("", f"cannot write {self.what}: {e.strerror}",
                                             str(self.path.parent), "io")) from None
                raise
            with os.fdopen(fd, "w", encoding="utf-8") as f:
                json.dump(me, f)
            self._held = True
            return
        raise InputError(Problem("", f"could not take the lock of {self.what}",
                                 str(self.path.parent), "io"))

    def release(self) -> None:
        if self._held:
            h = self._holder()
            if isinstance(h, dict) and h.get("pid") == os.getpid():
                self.path.unlink(missing_ok=True)
            self._held = False

    def __enter__(self) -> FolderLock:
        self.acquire()
        return self

    def __exit__(self, *exc) -> None:
        self.release()


def hash_stat(h, path: str | Path) -> None:
    """Feed ``path``'s modification time and size (or its absence) into the hash ``h``: the key
    of a cache that must be rebuilt when a file changes."""
    try:
        st = os.stat(path)
    except OSError:
        h.update(f"{path}:-\n".encode())
        return
    h.update(f"{path}:{st.st_mtime_ns}:{st.st_size}\n".encode())


def hash_tree_stats(h, base: str | Path, skip: tuple[str, ...] = ()) -> None:
    """:func:`hash_stat` of every ``.py`` and ``.json`` file under ``base`` in a fixed order,
    leaving out folders named in ``skip``."""
    for d, dirs, files in sorted(os.walk(base)):
        dirs[:] = sorted(x for x in dirs if x not in skip)
        for f in sorted(files):
            if f.endswith((".py", ".json")):
                hash_stat(h, os.path.join(d, f))


def hash_library_stats(h, root: Path) -> None:
    """:func:`hash_stat` of the user asset library under ``root`` (its folders and their
    ``category.json`` files)."""
    lib = root / "library"
    hash_stat(h, lib)
    if lib.is_dir():
        for sub in sorted(lib.iterdir()):
            if sub.is_dir():
                hash_stat(h, sub)
                hash_stat(h, sub / "category.json")
