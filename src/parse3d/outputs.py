"""The Python surface of a :class:`~parse3d.scene.model.Scene`: save, export by suffix, view.

The :class:`Scene` methods call these functions, which import the exporters, the renderer
and the physics tables only when used (the scene model stays cheap to import).
"""

from __future__ import annotations

import base64
import json
import struct
from pathlib import Path

from .errors import InputError, Problem
from .scene.model import Scene

__all__ = ["SUFFIXES", "save_scene", "export_file", "viewer_page_of", "show_scene",
           "in_notebook"]

#: File suffix -> export format (:data:`parse3d.export.FORMATS`).
SUFFIXES: dict[str, str] = {".glb": "glb", ".gltf": "glb", ".usd": "usd", ".usda": "usd",
                            ".usdc": "usd", ".xml": "mjcf", ".urdf": "urdf", ".obj": "obj"}


def _options(settled: bool | None = None):
    from .export import ExportOptions
    from .physics.mujoco import settling_friction

    # the friction table settling used, as parse3d solve writes it
    return ExportOptions(settled=settled, friction=settling_friction())


def save_scene(scene: Scene, out: str | Path, *, formats: tuple[str, ...] = ("glb",),
               preview: bool = False) -> Path:
    """Write ``scene`` into the folder ``out`` as ``parse3d solve`` does.

    ``scene.json`` (and ``contacts.json`` when contacts were extracted), the export
    ``formats`` (``scene.glb`` by default) and, with ``preview``, ``preview.png``. Outputs of
    an earlier solve in ``out`` are replaced; a ``scene.json`` that parse3d did not write is
    refused. Returns the folder.
    """
    from .export import check_formats
    from .pipeline import write_outputs
    from .scene.io import clear_scene_outputs

    formats = check_formats(formats, where="formats") if formats else ()
    out = Path(out)
    clear_scene_outputs(out)
    write_outputs(scene, out, formats, preview=preview)
    return out


def _gltf_from_glb(glb: bytes) -> str:
    """A ``.gltf`` document (JSON, its buffer embedded as a data URI) holding ``glb``."""
    n_json = struct.unpack_from("<I", glb, 12)[0]
    doc = json.loads(glb[20:20 + n_json])
    rest = 20 + n_json
    if rest < len(glb):
        n_bin = struct.unpack_from("<I", glb, rest)[0]
        data = glb[rest + 8:rest + 8 + n_bin]
        doc["buffers"][0]["uri"] = ("data:application/octet-stream;base64,"
                                    + base64.b64encode(data).decode("ascii"))
    return json.dumps(doc, separators=(",", ":"))


def export_file(scene: Scene, path: str | Path, *, settled: bool | None = None) -> list[Path]:
    """Write ``scene`` to ``path`` in the format its suffix names; returns the files written.

    ``.glb``, ``.gltf`` (one JSON file, buffer embedded), ``.usd``/``.usda``/``.usdc``,
    ``.xml`` (MJCF, its meshes in ``meshes/`` beside it) and ``.obj`` (with its ``.mtl``
    beside it) are written at ``path``. URDF describes one object, not a scene: ``.urdf``
    writes ``urdf/`` beside ``path`` (one ``<object>.urdf`` per object, ``room.urdf`` and
    ``urdf/scene.json`` placing them), as ``parse3d export --format urdf`` does.
    """
    from ._files import atomic_write_bytes, atomic_write_text

    path = Path(path)
    fmt = SUFFIXES.get(path.suffix.lower())
    if fmt is None:
        known = ", ".join(SUFFIXES)
        raise InputError(Problem("", f"no export format for the suffix {path.suffix or '(none)'!r}"
                                     f": name the file with one of {known}", str(path), "io"))
    if path.is_dir():
        raise InputError(Problem("", "this is a folder: export to a file path in it, such as "
                                     f"{path / ('scene' + path.suffix)}", str(path), "io"))
    from .export import walk_scene

    rec = walk_scene(scene, _options(settled))
    path.parent.mkdir(parents=True, exist_ok=True)
    if fmt == "glb":
        from .export.gltf import to_glb

        glb = to_glb(rec)
        if path.suffix.lower() == ".gltf":
            atomic_write_text(path, _gltf_from_glb(glb))
        else:
            atomic_write_bytes(path, glb)
        return [path]
    if fmt == "usd":
        from .export.usd import build_layer

        tmp = path.with_name(f".{path.stem}.tmp{path.suffix}")
        try:
            layer = build_layer(rec, path=str(tmp))
            layer.Save()
            del layer
            tmp.replace(path)
        except BaseException:
            tmp.unlink(missing_ok=True)
            raise
        return [path]
    if fmt == "mjcf":
        from .export.mjcf import build_xml

        xml, files = build_xml(rec, path.parent)
        atomic_write_text(path, xml)
        return [path, *files.close()]
    if fmt == "obj":
        from .export.obj import to_obj

        mtl_path = path.with_suffix(".mtl")
        obj, mtl = to_obj(rec, mtl_path.name)
        atomic_write_text(mtl_path, mtl)
        atomic_write_text(path, obj)
        return [path, mtl_path]
    from .export.urdf import write

    return write(rec, path.parent)


def viewer_page_of(scene: Scene, *, settled: bool | None = None) -> str:
    """The scene in a self-contained three.js page (:mod:`parse3d.scene.viewer`), without its
    ceiling so the room is seen from above."""
    from .export import walk_scene
    from .export.gltf import to_glb
    from .scene.viewer import viewer_page

    opts = _options(settled)
    opts = type(opts)(settled=opts.settled, ceiling=False, friction=opts.friction)
    return viewer_page(to_glb(walk_scene(scene, opts)),
                       title=f"{scene.pag.name or 'scene'} (seed {scene.seed})")


def in_notebook() -> bool:
    """Whether this runs in a Jupyter kernel (IPython already imported and serving one)."""
    import sys

    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    return shell is not None and "IPKernelApp" in getattr(shell, "config", {})


def show_scene(scene: Scene, *, path: str | Path | None = None,
               open_browser: bool = True) -> Path | None:
    """Show ``scene`` in the three.js viewer.

    In a Jupyter kernel (and no ``path``) the viewer is displayed in the cell's output and
    None is returned. Elsewhere the page is written to ``path`` (a new temporary file when
    None), opened in the web browser unless ``open_browser`` is False, and its path returned.
    """
    if path is None and in_notebook():
        from IPython.display import HTML, display

        from .scene.viewer import viewer_iframe

        display(HTML(viewer_iframe(viewer_page_of(scene))))
        return None
    import os
    import tempfile
    import webbrowser

    from ._files import atomic_write_text

    page = viewer_page_of(scene)
    if path is None:
        fd, name = tempfile.mkstemp(prefix="parse3d-scene-", suffix=".html")
        os.close(fd)
        path = name
    path = Path(path)
    atomic_write_text(path, page)
    if open_browser:
        webbrowser.open(path.resolve().as_uri())
    return path


def render_scene_rgb(scene: Scene, width: int = 640, height: int = 480, *, camera=None,
                     settled: bool | None = None):
    """What :meth:`Scene.render` returns: an (H, W, 3) uint8 image from the preview's
    viewpoint or ``camera``."""
    from .render import default_renderer, preview_camera

    r = default_renderer()
    if camera is None:
        camera = preview_camera(scene, width=width, height=height, settled=settled, renderer=r)
    return r.render_rgb(scene, camera, settled=settled)


def repr_html(scene: Scene) -> str:
    """What :meth:`Scene._repr_html_` returns: the viewer page in an ``<iframe srcdoc>``."""
    from .scene.viewer import viewer_iframe

    return viewer_iframe(viewer_page_of(scene))
