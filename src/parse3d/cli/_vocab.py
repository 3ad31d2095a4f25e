"""The category vocabulary for light commands, without importing the asset library.

Checking a PAG's category names and part labels needs the asset registry's vocabulary, and
building it imports every procedural generator (and with them trimesh, scipy, shapely): most
of ``parse3d validate``'s time. The vocabulary only changes when the asset package's code or
the user library (``parse3d assets add``) changes, so a snapshot of it is kept beside the asset
cache, ``$PARSE3D_CACHE/vocabulary.json``, keyed by the version and the size and modification
time of every file it depends on. A missing or stale snapshot is rebuilt from the registry (the
slow path, once); a damaged one is ignored; a cache folder that cannot be written only costs
the slow path each time. A library folder that loads with warnings is not snapshotted, so its
warnings keep being shown.
"""

from __future__ import annotations

import contextlib
import hashlib
import importlib.util
import json
import os
import warnings
from pathlib import Path

from .._files import hash_library_stats, hash_tree_stats

__all__ = ["SnapshotVocabulary", "cli_vocabulary", "snapshot_key"]

#: The catalog (:func:`parse3d.assets.registry.catalog`) of the snapshot read last, for
#: :func:`solve_vocabulary`.
_CATALOG: dict = {}

SNAPSHOT_FORMAT = "parse3d-vocabulary/2"
SNAPSHOT_NAME = "vocabulary.json"


class SnapshotVocabulary:
    """A vocabulary read from a snapshot: what :mod:`parse3d.pag.validate` asks of one.

    Parameters
    ----------
    parts : dict of str to tuple of str
        Every category's part vocabulary, by category name (sorted as the registry sorts).
    """

    def __init__(self, parts: dict[str, tuple[str, ...]]):
        self._parts = parts

    def categories(self) -> list[str]:
        return list(self._parts)

    def has_category(self, name: str) -> bool:
        return name in self._parts

    def parts(self, category: str) -> tuple[str, ...]:
        return self._parts[category]


def _cache_root() -> Path | None:
    """The cache folder, or None where the registry must judge the setting (it raises the
    one-line error for a blank or unusable ``PARSE3D_CACHE``)."""
    env = os.environ.get("PARSE3D_CACHE")
    if env is None:
        return Path.home() / ".cache" / "parse3d"
    if not env.strip() or "\0" in env:
        return None
    return Path(env).expanduser()


def snapshot_key(root: Path) -> str:
    """A digest of everything the vocabulary depends on.

    Parameters
    ----------
    root : Path
        The cache folder (its ``library`` sub-folder holds the user's categories).

    Returns
    -------
    str
        Hex digest over the package version, every source file of ``parse3d.assets`` (path,
        size, modification time) and the user library's folders and ``category.json`` files.
    """
    import parse3d

    h = hashlib.sha256(f"{SNAPSHOT_FORMAT}\n{parse3d.__version__}\n".encode())
    spec = importlib.util.find_spec("parse3d.assets")
    for base in (spec.submodule_search_locations or []) if spec else []:
        hash_tree_stats(h, base)
    hash_library_stats(h, root)
    return h.hexdigest()


def _read(path: Path, key: str) -> SnapshotVocabulary | None:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(data, dict) or data.get("format") != SNAPSHOT_FORMAT or data.get("key") != key:
        return None
    cats = data.get("categories")
    if not isinstance(cats, dict) or not all(
            isinstance(v, list) and all(isinstance(x, str) for x in v) for v in cats.values()):
        return None
    catalog = data.get("catalog")
    if not isinstance(catalog, dict) or set(catalog) != set(cats):
        return None
    _CATALOG.clear()
    _CATALOG.update(catalog)
    return SnapshotVocabulary({k: tuple(v) for k, v in cats.items()})


def _write(path: Path, key: str, vocab) -> None:
    from ..assets.registry import catalog

    data = {"format": SNAPSHOT_FORMAT, "key": key,
            "categories": {c: list(vocab.parts(c)) for c in vocab.categories()},
            "catalog": catalog()}
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp.write_text(json.dumps(data, separators=(",", ":")), encoding="utf-8")
        os.replace(tmp, path)
    except OSError:  # a read-only or full cache: the slow path stays correct
        with contextlib.suppress(OSError):
            tmp.unlink()


def cli_vocabulary():
    """The vocabulary PAGs are checked against: from the snapshot when it is current, else
    from the asset registry (which then refreshes the snapshot).

    Returns
    -------
    SnapshotVocabulary or parse3d.assets.registry.Vocabulary
        Same categories and part vocabularies either way.
    """
    root = _cache_root()
    if root is not None and root.is_dir():
        key = snapshot_key(root)
        snap = _read(root / SNAPSHOT_NAME, key)
        if snap is not None:
            return snap
    from ..assets.registry import vocabulary

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        vocab = vocabulary()
    for w in caught:  # shown as the registry would have shown them
        warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    root = _cache_root()
    if root is not None and not caught:
        # the key is taken after loading: the registry may have created the cache folder
        _write(root / SNAPSHOT_NAME, snapshot_key(root), vocab)
    return vocab


def solve_vocabulary():
    """:func:`cli_vocabulary`, and with a current snapshot the asset registry told its
    categories from it (sizes, generator modules), so that solving with cached assets imports
    no generator (and no trimesh or scipy with them).

    Returns
    -------
    SnapshotVocabulary or parse3d.assets.registry.Vocabulary
    """
    vocab = cli_vocabulary()
    if isinstance(vocab, SnapshotVocabulary) and _CATALOG:
        from ..assets.registry import install_catalog

        # a damaged catalog installs nothing: the registry then decides as before
        with contextlib.suppress(KeyError, TypeError, ValueError):
            install_catalog(_CATALOG)
    return vocab
