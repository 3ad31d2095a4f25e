"""Exports to viewers and simulators: structured glTF, USD, MJCF, URDF, OBJ.

Every format is one module of this package with the same small surface — ``NAME`` (the
format's name on the command line), ``FILES`` (what it creates in the output folder) and
``write(record, out) -> list[Path]`` — over one walk of the scene
(:func:`~parse3d.export.walk.walk_scene`). Adding a format is adding a module and its name
to :data:`FORMATS`.

- :func:`export_scene` — write one or more formats of a scene into a folder (and refresh the
  stale exports of a scene folder);
- :func:`present_formats`, :func:`stale_formats` — the exports a folder holds, and those
  older than its ``scene.json``;
- :func:`to_sapien`, :func:`to_mujoco` — live simulator objects for a scene;
- :data:`FORMATS` — format name to module name;
- :func:`~parse3d.export.record.read_options` — the options each export in a folder was made
  with (``exports.json``), reused when a refresh rewrites it.

Formats that need optional packages (usd-core, mujoco) import them only when used.
"""

from __future__ import annotations

import errno
import importlib
import json
from collections.abc import Iterable
from pathlib import Path
from types import ModuleType

from ..errors import InputError, Problem
from ..scene.model import Scene
from .record import OPTIONS_FILE, options_to_dict, read_options, write_options
from .walk import ExportOptions, SceneRecord, walk_scene

__all__ = ["FORMATS", "MARKERS", "OWN_FILES", "foreign_files", "ExportOptions", "SceneRecord", "walk_scene", "export_scene",
           "format_module", "check_formats", "present_formats", "stale_formats", "to_sapien",
           "to_mujoco"]

#: Format name -> module of this package.
FORMATS: dict[str, str] = {"glb": "gltf", "usd": "usd", "mjcf": "mjcf", "urdf": "urdf",
                           "obj": "obj"}
#: Format name -> the file (relative to a scene folder) whose presence marks the format as
#: exported there; each writer module's ``MARKER``. Kept here so that finding the formats of a
#: folder imports no writer.
MARKERS: dict[str, str] = {"glb": "scene.glb", "usd": "scene.usd", "mjcf": "scene.xml",
                           "urdf": "urdf/scene.json", "obj": "scene.obj"}
#: Format name -> the fixed file names it writes (besides content-named mesh files): an
#: export refuses to replace these in a folder parse3d did not write them in.
OWN_FILES: dict[str, tuple[str, ...]] = {"glb": ("scene.glb",), "usd": ("scene.usd",),
                                         "mjcf": ("scene.xml",),
                                         "urdf": ("urdf/scene.json",),
                                         "obj": ("scene.obj", "scene.mtl")}


def foreign_files(out: str | Path, formats: Iterable[str]) -> list[Path]:
    """The files of ``formats`` in ``out`` that parse3d did not write there.

    A file counts as parse3d's when ``exports.json`` records its format, or when the folder
    is a scene folder (its ``scene.json`` is a parse3d scene: ``solve`` owns its outputs).
    Anything else in the way, a user's own ``scene.xml`` or ``scene.obj``, is foreign.
    """
    from ..scene.io import is_parse3d_scene

    out = Path(out)
    if not out.is_dir() or is_parse3d_scene(out / "scene.json"):
        return []
    try:
        recorded = set(read_options(out))
    except InputError:
        recorded = set()
    return [out / f for n in formats if n not in recorded for f in OWN_FILES[n]
            if (out / f).is_file() or (out / f).is_symlink()]


def format_module(name: str) -> ModuleType:
    """The writer module of format ``name``."""
    return importlib.import_module(f"{__name__}.{FORMATS[name]}")


def check_formats(formats: str | Iterable[str], *, where: str = "--formats") -> tuple[str, ...]:
    """Parse and check a format list (``"glb,usd"`` or a sequence), keeping the given order.

    Raises
    ------
    InputError
        For an unknown or repeated format, naming ``where`` and the known formats.
    """
    items = [f.strip() for f in formats.split(",")] if isinstance(formats, str) else list(formats)
    out: list[str] = []
    for f in items:
        if f not in FORMATS:
            raise InputError(Problem("", f"unknown format {f!r}: use one or more of "
                                         f"{', '.join(FORMATS)}", where, "parameter"))
        if f not in out:
            out.append(f)
    if not out:
        raise InputError(Problem("", f"no format given: use one or more of {', '.join(FORMATS)}",
                                 where, "parameter"))
    return tuple(out)


def present_formats(folder: str | Path) -> tuple[str, ...]:
    """The formats exported into ``folder``: those whose marker file (``scene.glb``,
    ``scene.usd``, ``scene.xml``, ``urdf/scene.json``, ``scene.obj``) is there."""
    folder = Path(folder)
    return tuple(f for f in FORMATS if (folder / MARKERS[f]).is_file())


def stale_formats(folder: str | Path) -> tuple[str, ...]:
    """The formats exported into the scene folder ``folder`` that are not newer than its
    ``scene.json`` (written before the scene last changed); none when there is no
    ``scene.json``."""
    folder = Path(folder)
    try:
        scene_time = (folder / "scene.json").stat().st_mtime_ns
    except OSError:
        return ()
    return tuple(f for f in present_formats(folder)
                 if (folder / MARKERS[f]).stat().st_mtime_ns <= scene_time)


def export_scene(scene: Scene, out: str | Path, formats: str | Iterable[str] = ("glb",),
                 options: ExportOptions = ExportOptions(), *, refresh: bool = True,
                 skip: Iterable[str] = (), keep_options: bool = False,
                 force: bool = False) -> list[Path]:
    """Write ``scene`` in each of ``formats`` into the folder ``out``.

    Parameters
    ----------
    scene : Scene
    out : path
        Output folder (created when missing). Each format writes its own fixed file names in
        it (``scene.glb``, ``scene.usd``, ``scene.xml`` + ``meshes/``, ``urdf/``,
        ``scene.obj`` + ``scene.mtl``); nothing is written outside it.
    formats : str or sequence of str
        Names from :data:`FORMATS`; may be empty when ``refresh`` is on.
    options : ExportOptions
    refresh : bool
        When ``out`` is the scene's folder (it holds ``scene.json``), also rewrite every
        other format already exported there that is not newer than ``scene.json``
        (:func:`stale_formats`), so the folder never holds an export that disagrees with its
        scene. A refreshed format is written with the options it was last exported with
        (recorded in ``exports.json``, :mod:`parse3d.export.record`), else with ``options``.
    skip : sequence of str
        Formats never refreshed.
    keep_options : bool
        Write the requested ``formats`` too with their recorded options where a record
        exists (``options`` only for formats never exported here): a refresh of named
        formats, as ``parse3d settle`` rewrites ``scene.glb``.
    force : bool
        Replace files in the way that parse3d did not write (:func:`foreign_files`);
        without it they are refused and nothing is written.

    Returns
    -------
    list of Path
        Every file written, ``exports.json`` (the options of each format) last.

    Raises
    ------
    InputError
        For an unknown format, an output folder that cannot be written, a damaged
        ``exports.json``, or files in the way that parse3d did not write (without ``force``).
    """
    names = check_formats(formats, where="formats") if (formats or not refresh) else ()
    out = Path(out)
    refreshed: tuple[str, ...] = ()
    if refresh:
        refreshed = tuple(f for f in stale_formats(out) if f not in names and f not in skip)
        names += refreshed
    if not names:
        return []
    foreign = [] if force else foreign_files(out, names)
    if foreign:
        raise InputError([Problem("", "exists and was not written by parse3d: it is not "
                                      "replaced (nothing was written) — choose another --out, "
                                      "remove it, or pass --force", str(f), "io")
                          for f in foreign])
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise InputError(Problem("", f"cannot create the output folder: {e.strerror} — choose "
                                     "a writable folder with --out", str(out), "io")) from None
    recorded = read_options(out) if refreshed or keep_options else {}
    requested = set(names[:len(names) - len(refreshed)])
    plan = {n: recorded[n] if n in recorded and (n not in requested or keep_options)
            else options for n in names}
    groups: dict[str, list[str]] = {}  # one walk per distinct set of options
    for n in names:
        groups.setdefault(json.dumps(options_to_dict(plan[n]), sort_keys=True), []).append(n)
    written: list[Path] = []
    for group in groups.values():
        rec = walk_scene(scene, plan[group[0]])
        for name in group:
            try:
                written += format_module(name).write(rec, out)
            except OSError as e:
                raise InputError(_write_problem(f"the {name} export", e, out)) from None
    try:
        written.append(write_options(out, plan))
    except OSError as e:
        raise InputError(_write_problem(OPTIONS_FILE, e, out)) from None
    return written


_IN_THE_WAY = {errno.EISDIR: "a folder is in the way", errno.ENOTDIR: "a file is in the way",
               errno.EEXIST: "a file is in the way"}


def _write_problem(what: str, e: OSError, out: Path) -> Problem:
    """The one-line problem of a write that the file system refused, naming the file that
    could not be written (a rename's target, not its temporary source)."""
    path = e.filename2 if e.filename2 is not None else e.filename
    if path is not None and Path(path).name.startswith("."):  # a temporary beside the target
        path = Path(path).parent
    reason = _IN_THE_WAY.get(e.errno, e.strerror or str(e))
    return Problem("", f"cannot write {what}: {reason} — remove it or choose another folder "
                       "with --out", str(path if path is not None else out), "io")


def to_sapien(scene: Scene, options: ExportOptions = ExportOptions(), *,
              timestep: float = 0.01, render: bool | None = None, free_joints: bool = True):
    """A live SAPIEN scene of ``scene``: see :func:`parse3d.export.sapien.to_sapien`."""
    from .sapien import to_sapien as _to_sapien

    return _to_sapien(scene, options, timestep=timestep, render=render,
                      free_joints=free_joints)


def to_mujoco(scene: Scene, options: ExportOptions = ExportOptions(), *,
              timestep: float = 0.002, visual: bool = True, lock_joints: bool = True):
    """A compiled ``(MjModel, MjData)`` of ``scene``: see :func:`parse3d.export.mjcf.to_mujoco`."""
    from .mjcf import to_mujoco as _to_mujoco

    return _to_mujoco(scene, options, timestep=timestep, visual=visual,
                      lock_joints=lock_joints)
