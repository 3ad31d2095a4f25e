"""The user asset library: categories added from folders of real, part-split assets.

Layout (under :func:`parse3d.assets.library.user_library_dir`)::

    <library>/<category>/category.json     name, parts, vocabulary, size_range, density,
                                           placement, source, assets, extends
    <library>/<category>/<asset>.npz       cached assets (parse3d-asset/1)

A folder whose category is also procedural (``"extends": "procedural"``) adds assets to it: the
generator stays and the registry mixes the two (odd seeds draw loaded assets, even seeds the
generator; see ``registry.generate``). Otherwise the folder defines a new category whose
assets are all loaded.
"""

from __future__ import annotations

import json
import math
import os
import re
import warnings
from pathlib import Path

from ...errors import InputError, Problem
from .. import registry
from ..cache import load_asset, save_asset
from ..registry import PLACEMENTS, Category
from ._canon import SourceFrame, check_mapping_labels, finish_asset, read_mapping
from .glb import read_glb
from .partnet import is_partnet_folder, read_partnet_mobility

__all__ = ["CATEGORY_FORMAT", "register_library", "add_assets", "find_sources"]

CATEGORY_FORMAT = "parse3d-category/1"
_NAME = re.compile(r"^[a-z][a-z0-9_]*$")
_FILE = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.-]{0,120}\.npz$")

#: Node names that exporters invent; as part labels they say nothing about the part.
PLACEHOLDER_LABELS = frozenset({
    "gltf", "glb", "geometry", "mesh", "meshes", "node", "nodes", "object", "objects", "scene",
    "root", "group", "primitive", "default", "untitled", "model", "component", "shape", "obj",
    "polysurface", "cube", "plane", "cylinder", "sphere", "empty", "unnamed", "none", "null",
})
#: Sizes (largest extent, metres) an added asset or a ``--size-range`` may have.
MIN_ASSET_SIZE, MAX_ASSET_SIZE = 0.005, 30.0


def label_problems(raws, file_of) -> list[Problem]:
    """A problem for every part label that is not an identifier or is a placeholder name
    (``gltf``, ``geometry``, ``mesh``, ``node_0``, ...): map such parts with ``--mapping``."""
    probs = []
    for s, raw in raws:
        for lab in sorted(raw.labels):
            base = re.sub(r"(_?\d+)+$", "", lab)
            if not _NAME.match(lab):
                probs.append(Problem(f"/{lab}", f"part label {lab!r} is not an identifier "
                                     "(lower case letters, digits, '_'): name the part with "
                                     "--mapping", file_of(s), "vocabulary"))
            elif lab in PLACEHOLDER_LABELS or base in PLACEHOLDER_LABELS:
                probs.append(Problem(f"/{lab}", f"part label {lab!r} is an exporter's "
                                     "placeholder, not a part name: map the node to a real part "
                                     "label with --mapping (e.g. {\"" + lab + "\": \"seat\"})",
                                     file_of(s), "vocabulary"))
    return probs


def _read_category_json(path: Path) -> dict:
    data = json.loads(path.read_text(encoding="utf-8"))
    if not isinstance(data, dict) or data.get("format") != CATEGORY_FORMAT:
        raise ValueError(f"format is not {CATEGORY_FORMAT!r}")
    for key in ("name", "parts", "size_range", "assets"):
        if key not in data:
            raise ValueError(f"missing key {key!r}")
    return data


def register_library(root: str | os.PathLike) -> list[str]:
    """Register every category found under ``root`` (one sub-folder per category).

    A folder with a broken ``category.json`` or missing asset files is skipped with a warning
    naming the file, so one bad folder does not stop every command.

    Returns
    -------
    list of str
        The categories registered.
    """
    root = Path(root)
    if not root.is_dir():
        return []
    done = []
    procedural = {n: c for n, c in registry._REGISTRY.items() if c.generator is not None}
    for sub in sorted(p for p in root.iterdir() if p.is_dir()):
        cj = sub / "category.json"
        if not cj.is_file():
            continue
        try:
            cat = _category_of(sub, cj, procedural)
        except (ValueError, TypeError, KeyError, OSError, InputError) as e:
            msg = str(e).splitlines()[0] if str(e) else type(e).__name__
            warnings.warn(f"{cj}: skipped ({msg})", stacklevel=2)
            continue
        if cat is None:
            continue
        registry.register_loaded(cat)
        done.append(cat.name)
    return done


def _category_of(sub: Path, cj: Path, procedural: dict) -> Category | None:
    """The category a library folder declares (None: nothing to register); raises on any
    damage so that :func:`register_library` can skip the folder with a warning."""
    data = _read_category_json(cj)
    name = data["name"]
    if not isinstance(name, str) or not _NAME.match(name):
        raise ValueError(f"name {name!r} is not a lower-case identifier")
    if not isinstance(data["assets"], list):
        raise ValueError("assets must be a list of file names")
    paths = []
    for a in data["assets"]:
        if not (isinstance(a, str) and _FILE.match(a)):
            raise ValueError(f"asset {a!r} is not a .npz file name in the folder")
        p = sub / a
        if p.is_file():
            paths.append(str(p))
        else:
            warnings.warn(f"{cj}: asset file {a!r} is missing; skipped", stacklevel=3)
    base = procedural.get(name)
    if base is not None:
        return Category(base.name, base.parts, base.vocabulary, base.size_range, base.density,
                        base.variants, base.placement, base.generator, "procedural+" + str(sub),
                        tuple(paths), groups=base.groups)
    if not paths:
        return None
    parts = tuple(data["parts"])
    vocab = tuple(data.get("vocabulary", parts))
    if not all(isinstance(x, str) and _NAME.match(x) for x in parts + vocab):
        raise ValueError("parts and vocabulary must be lists of lower-case identifiers")
    lo, hi = (float(x) for x in data["size_range"])
    if not (MIN_ASSET_SIZE <= lo <= hi <= MAX_ASSET_SIZE):
        raise ValueError(f"size_range {[lo, hi]} is outside [{MIN_ASSET_SIZE}, "
                         f"{MAX_ASSET_SIZE}] m")
    density = float(data.get("density", 500.0))
    if not 1.0 <= density <= 30000.0:
        raise ValueError(f"density {density} is outside 1..30000 kg/m^3")
    placement = data.get("placement", "floor")
    if placement not in PLACEMENTS:
        raise ValueError(f"placement {placement!r} is not one of {', '.join(PLACEMENTS)}")
    return Category(name, parts, vocab, (lo, hi), density, ("loaded",), placement, None,
                    str(sub), tuple(paths))


def find_sources(src: Path) -> list[Path]:
    """GLB/glTF files and PartNet-Mobility folders in ``src`` (or ``src`` itself), sorted."""
    if src.is_file():
        return [src] if src.suffix.lower() in (".glb", ".gltf") else []
    if is_partnet_folder(src):
        return [src]
    out = []
    for p in sorted(src.iterdir()):
        if p.is_file() and p.suffix.lower() in (".glb", ".gltf") or p.is_dir() and is_partnet_folder(p):
            out.append(p)
    return out


def _asset_problem(asset) -> str | None:
    """What makes a built asset unusable (non-finite geometry, a size outside the bounds),
    or None."""
    import numpy as np

    for part in asset.parts:
        arrays = [part.mesh.vertices] + [c.vertices for c in part.pieces]
        if not all(np.isfinite(np.asarray(a, float)).all() for a in arrays):
            return f"part {part.name!r} has non-finite coordinates after fitting"
    size = float(asset.size)
    if not (math.isfinite(size) and MIN_ASSET_SIZE * 0.5 <= size <= MAX_ASSET_SIZE * 2):
        return f"the fitted asset is {size:g} m across"
    return None


def _stem(p: Path) -> str:
    s = re.sub(r"[^A-Za-z0-9_.-]+", "_", p.stem if p.is_file() else p.name)
    return s.strip("._") or "asset"


def add_assets(src: str | os.PathLike, *, category: str, mapping=None,
               parts: tuple[str, ...] | None = None,
               size_range: tuple[float, float] | None = None,
               frame: SourceFrame | None = None, density: float | None = None,
               placement: str | None = None, library: str | os.PathLike | None = None,
               cache_dir: str | os.PathLike | None = None) -> Category:
    """Load every GLB/glTF file and PartNet-Mobility folder in ``src`` into the user library.

    Parameters
    ----------
    src : path
        A folder of ``.glb``/``.gltf`` files and/or PartNet-Mobility folders, or one of them.
    category : str
        Lower-case name. An existing procedural category gets the assets added; an existing
        loaded category grows; otherwise a new category is created.
    mapping : dict or path, optional
        Node/link/semantic name to part label (``null`` drops it).
    parts : tuple of str, optional
        The part vocabulary of a new category (default: the labels found).
    size_range : (low, high), metres, optional
        Largest-extent range; assets outside are scaled into it. A new category without one
        gets the loaded sizes widened by 10%.
    frame : SourceFrame, optional
        Source convention; default per format (glTF: +Y up, front +Z; PartNet-Mobility: the
        URDF frame, +Z up, front +X).
    library : path, optional
        Library root (default :func:`parse3d.assets.library.user_library_dir`).

    Returns
    -------
    Category
        What the library now holds for ``category`` (it is registered on the next start-up, or
        now through :func:`register_library`).

    Raises
    ------
    InputError
        A missing folder, nothing loadable in it, a file that is not a part-split asset, an
        unknown part label, a bad size range or placement.
    """
    from ..library import user_library_dir

    src = Path(src)
    if not src.exists():
        raise InputError(Problem("", "folder not found", str(src), "io"))
    if not _NAME.match(category):
        raise InputError(Problem("", f"category name {category!r} must be lower case letters, digits "
                                 "and '_', starting with a letter", None, "parameter"))
    if size_range is not None and not (
            MIN_ASSET_SIZE <= size_range[0] <= size_range[1] <= MAX_ASSET_SIZE):
        raise InputError(Problem("", f"size range {list(size_range)} must satisfy "
                                 f"{MIN_ASSET_SIZE} <= low <= high <= {MAX_ASSET_SIZE} (metres)",
                                 "--size-range", "parameter"))
    if density is not None and not (math.isfinite(density) and 1.0 <= density <= 30000.0):
        raise InputError(Problem("", f"density {density} must be in 1..30000 kg/m^3",
                                 "--density", "parameter"))
    if placement is not None and placement not in PLACEMENTS:
        raise InputError(Problem("", f"placement {placement!r} is not one of {', '.join(PLACEMENTS)}",
                                 None, "parameter"))
    sources = find_sources(src)
    if not sources:
        raise InputError(Problem("", "no .glb/.gltf files or PartNet-Mobility folders (with "
                                 "mobility.urdf) found", str(src), "io"))
    lib = Path(library) if library is not None else user_library_dir()
    folder = lib / category
    cj = folder / "category.json"
    old = None
    if cj.is_file():
        try:
            old = _read_category_json(cj)
        except (ValueError, OSError) as e:
            raise InputError(Problem("", f"broken library entry: {e}", str(cj), "schema")) from None
    existing = registry.categories().get(category)
    procedural = existing is not None and existing.generator is not None
    if procedural:
        vocab: tuple[str, ...] | None = existing.vocabulary
        size_range = size_range or existing.size_range
    elif parts:
        vocab = tuple(dict.fromkeys(tuple(parts) + tuple(old["vocabulary"] if old else ())))
    else:
        vocab = None  # grows with what is found
    mapping_d, mfile = read_mapping(mapping)
    check_mapping_labels(mapping_d, vocab, mfile)
    raws = []
    for s in sources:
        if s.is_dir():
            raws.append((s, read_partnet_mobility(s, mapping=mapping_d, vocabulary=vocab,
                                                  **({"frame": frame} if frame else {}))))
        else:
            raws.append((s, read_glb(s, mapping=mapping_d, vocabulary=vocab,
                                     **({"frame": frame} if frame else {}))))
    probs = label_problems(raws, str)
    if size_range is None and old is None:
        probs += [Problem("", f"the asset is {r.size:g} m across: give --size-range (metres) "
                          f"to scale it, or fix its units (sizes {MIN_ASSET_SIZE}..{MAX_ASSET_SIZE}"
                          " m)", str(s), "parameter")
                  for s, r in raws if not (MIN_ASSET_SIZE <= r.size <= MAX_ASSET_SIZE)]
    if probs:
        raise InputError(probs)
    if procedural:
        missing = [(s, sorted(set(existing.parts) - r.labels)) for s, r in raws
                   if set(existing.parts) - r.labels]
        if missing:
            raise InputError([Problem("", f"lacks the part labels {m} that every {category!r} has "
                                      "(map them with --mapping)", str(s), "vocabulary")
                              for s, m in missing])
    if size_range is None:
        if old is not None:
            size_range = tuple(old["size_range"])
        else:
            sizes = [r.size for _, r in raws]
            size_range = (round(min(sizes) * 0.9, 4), round(max(sizes) * 1.1, 4))
    if density is None:
        density = existing.density if existing is not None else float((old or {}).get("density", 500.0))
    names = list(old["assets"]) if old else []
    # every asset is built and checked before anything is created in the library: a file
    # that fails leaves no folder, no half category behind
    built = [(_stem(s), finish_asset(raw, category=category, asset_id=f"{category}-{_stem(s)}",
                                     size_range=size_range, density=density,
                                     cache_dir=cache_dir)) for s, raw in raws]
    for stem, asset in built:
        bad = _asset_problem(asset)
        if bad:
            raise InputError(Problem("", bad, next(str(s) for s in sources if _stem(s) == stem),
                                     "geometry"))
    folder.mkdir(parents=True, exist_ok=True)
    for stem, asset in built:
        save_asset(asset, folder / f"{stem}.npz")
        if f"{stem}.npz" not in names:
            names.append(f"{stem}.npz")
    names.sort()
    labels_all = [set(load_asset(folder / n).labels) for n in names]
    found = sorted(set().union(*labels_all))
    if procedural:
        req, voc = existing.parts, existing.vocabulary
    else:
        common = set.intersection(*labels_all)
        voc = vocab or tuple(found)
        voc = tuple(dict.fromkeys(tuple(voc) + tuple(found)))
        req = tuple(x for x in voc if x in common)
    data = {
        "format": CATEGORY_FORMAT,
        "name": category,
        "parts": list(req),
        "vocabulary": list(voc),
        "size_range": [float(size_range[0]), float(size_range[1])],
        "density": float(density),
        "placement": placement or (existing.placement if existing is not None
                                   else (old or {}).get("placement", "floor")),
        "source": str(src.resolve()),
        "extends": "procedural" if procedural else None,
        "assets": names,
    }
    tmp = cj.with_suffix(".json.tmp")
    tmp.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    os.replace(tmp, cj)
    paths = tuple(str(folder / n) for n in names)
    if procedural:
        return Category(existing.name, existing.parts, existing.vocabulary, existing.size_range,
                        existing.density, existing.variants, existing.placement, existing.generator,
                        "procedural+" + str(folder), paths, groups=existing.groups)
    return Category(category, tuple(req), tuple(voc), tuple(data["size_range"]), float(density),
                    ("loaded",), data["placement"], None, str(folder), paths)
