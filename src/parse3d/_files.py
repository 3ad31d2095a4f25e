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
import os
import socket
import stat
import tempfile
from pathlib import Path

from .errors import InputError, Problem

__all__ = [
    "MAX_INPUT_BYTES",
    "current_umask",
    "user_mode",
    "read_input_bytes",
    "read_input_text",
    "atomic_write_bytes",
    "atomic_write_text",
    "check_output_dir",
    "FolderLock",
]

#: Largest input document read (PAGs, templates, scene files), bytes. A PAG of the largest
#: allowed size is far below it.
MAX_INPUT_BYTES = 64 * 1024 * 1024


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
