"""Training data of the layout model, read from a built dataset's ``scene.json`` files.

One :class:`LayoutScene` per scene: the placed objects' categories, assets and 12-D poses
(:mod:`.pose`, from the *settled* poses where the scene was settled), the PAG relations between
them as :class:`~.encoders.RelationSpec` items, and the room (footprint and height).
:func:`graph_arrays` turns a scene into the arrays the network consumes.

A dataset folder is anything :func:`find_scenes` understands: a ``parse3d dataset build``
folder (``DIR/scenes/<index>/scene.json``), a folder of scene folders, or one scene folder.

Reading a scene does not read its assets' meshes: what the layout model needs of an asset
(its extents and part labels, :class:`~.encoders.AssetInfo`) is kept in an index under the
cache folder (``layoutgen/asset-info.json``), keyed by the asset file and checked against its
size and modification time; :attr:`LayoutScene.assets` loads the assets themselves when asked.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..assets.model import Asset
from ..errors import InputError, Problem
from ..geometry.frames import quat_to_matrix
from ..pag.model import PAG
from ..pag.refs import wall_index
from ..relations import SUPPORT_RELATIONS
from ..scene.io import READABLE_FORMATS
from .encoders import AssetInfo, RelationEncoder, RelationSpec, ShapeEncoder
from .pose import PoseStats, normalise_poses, rotation_to_6d, support_order

__all__ = ["LayoutScene", "GraphArrays", "find_scenes", "load_scene", "load_dataset",
           "load_asset_ref", "asset_info", "save_asset_index", "pag_relations", "split_scenes", "graph_arrays", "support_parents", "ROOM_GEO_DIM",
           "ROOM_CTX_DIM"]

ROOM_GEO_DIM = 8
ROOM_CTX_DIM = 4


@dataclass
class LayoutScene:
    """One scene as training (or evaluation) data.

    Attributes
    ----------
    scene_id : str
        The scene folder's name.
    path : Path
        The scene folder.
    pag : PAG
        The graph the scene was solved from (all objects, placed or not).
    object_ids, categories : list of str
        Placed objects, in the scene's order.
    asset_info : list of AssetInfo
        Their assets' extents and part labels (the assets themselves: :attr:`assets`).
    poses : (N, 12) float
        World poses (translation, size, 6-D rotation), see :mod:`.pose`.
    scales : (N,) float
    relations : list of RelationSpec
        PAG relations whose child (and parent object, if any) were placed.
    footprint : (F, 2) float
    height : float
    solved_poses : (N, 12) float or None
        The solver's own poses before settling (what its relation checks passed on); None
        when they equal ``poses``.
    """

    scene_id: str
    path: Path
    pag: PAG
    object_ids: list[str]
    categories: list[str]
    asset_info: list[AssetInfo]
    poses: np.ndarray
    scales: np.ndarray
    relations: list[RelationSpec] = field(default_factory=list)
    footprint: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    height: float = 0.0
    solved_poses: np.ndarray | None = None

    @property
    def room_type(self) -> str:
        return self.pag.room.type

    @property
    def assets(self) -> list[Asset]:
        """The placed objects' assets, loaded (memoised) from their references."""
        return [load_asset_ref(dict(i.ref)) for i in self.asset_info]


def find_scenes(dataset: str | Path) -> list[Path]:
    """The ``scene.json`` files of a dataset folder, sorted; InputError when there are none."""
    root = Path(dataset)
    if not root.exists():
        raise InputError(Problem("", "no such folder — give a dataset built with "
                                     "'parse3d dataset build'", str(root), "io"))
    if (root / "scene.json").is_file():
        return [root / "scene.json"]
    files = sorted((root / "scenes").glob("*/scene.json")) if (root / "scenes").is_dir() else []
    files = files or sorted(root.glob("*/scene.json"))
    if not files:
        raise InputError(Problem("", "no scenes here (expected scenes/<index>/scene.json) — "
                                     "build one with 'parse3d dataset build --out "
                                     f"{root}'", str(root), "io"))
    return files


_ASSETS: dict[tuple, Asset] = {}


def load_asset_ref(ref: dict) -> Asset:
    """The asset a ``scene.json`` object references (pool slot or cached file), memoised."""
    key = (ref.get("path"), ref.get("category"), ref.get("seed"))
    a = _ASSETS.get(key)
    if a is None:
        if ref.get("path"):
            from ..assets.cache import load_asset

            a = load_asset(ref["path"])
        else:
            from ..assets.pool import default_pool

            a = default_pool().load(ref["category"], int(ref["seed"]))
        if len(_ASSETS) > 4096:
            _ASSETS.clear()
        _ASSETS[key] = a
    return a


_INDEX_FORMAT = "parse3d-layout-asset-info/1"


class _AssetIndex:
    """The on-disk index of :class:`AssetInfo` by asset file (see the module docstring)."""

    def __init__(self):
        self.path: Path | None = None
        self.env: str | None = None
        self.entries: dict[str, dict] = {}
        self.files: dict[tuple, str] = {}  # (category, seed) or path -> asset file
        self.infos: dict[str, tuple[list, AssetInfo]] = {}  # asset file -> (stamp, info)
        self.dirty = False

    def _file(self, ref: dict) -> str:
        if ref.get("path"):
            return str(ref["path"])
        key = (ref["category"], int(ref["seed"]))
        f = self.files.get(key)
        if f is None:
            from ..assets.pool import default_pool

            f = self.files[key] = str(default_pool().path(*key))
        return f

    def _open(self) -> None:
        env = os.environ.get("PARSE3D_CACHE")
        if self.path is not None and env == self.env:
            return
        from ..assets.library import cache_dir

        self.save()  # what was added under another cache folder goes there
        self.env = env
        self.path = cache_dir() / "layoutgen" / "asset-info.json"
        self.entries, self.files, self.infos, self.dirty = {}, {}, {}, False
        try:
            doc = json.loads(self.path.read_text())
        except (OSError, ValueError):
            return  # none yet, or unreadable: rebuilt as assets are read
        if isinstance(doc, dict) and doc.get("format") == _INDEX_FORMAT:
            self.entries = dict(doc.get("entries", {}))

    def info(self, ref: dict) -> AssetInfo:
        self._open()
        key = self._file(ref)
        try:
            st = os.stat(key)
        except OSError:
            st = None  # not built yet: loading it below builds it
        stamp = None if st is None else [st.st_size, st.st_mtime_ns]
        hit = self.infos.get(key)
        if hit is not None and hit[0] == stamp:
            return hit[1]
        e = self.entries.get(key)
        if stamp is not None and e is not None and e["stamp"] == stamp:
            info = AssetInfo(e["asset_id"], tuple(e["extents"]), tuple(e["labels"]),
                             tuple(sorted(ref.items())))
        else:
            info = AssetInfo.of(load_asset_ref(ref), ref)
            st = os.stat(key)
            stamp = [st.st_size, st.st_mtime_ns]
            self.entries[key] = {"stamp": stamp, "asset_id": info.asset_id,
                                 "extents": list(info.extents),
                                 "labels": list(info.part_labels)}
            self.dirty = True
        self.infos[key] = (stamp, info)
        return info

    def save(self) -> None:
        if not self.dirty or self.path is None:
            return
        from ..scene.io import atomic_write_text

        self.path.parent.mkdir(parents=True, exist_ok=True)
        atomic_write_text(self.path, json.dumps({"format": _INDEX_FORMAT,
                                                 "entries": self.entries}) + "\n")
        self.dirty = False


_INDEX = _AssetIndex()


def asset_info(ref: dict) -> AssetInfo:
    """The :class:`AssetInfo` of a ``scene.json`` asset reference, from the on-disk index
    when the asset file is unchanged, otherwise by loading the asset (and indexing it)."""
    return _INDEX.info(ref)


def save_asset_index() -> None:
    """Write the asset index if :func:`asset_info` added to it (atomically)."""
    _INDEX.save()


def _room_category(name: str) -> str:
    return "wall" if name.startswith("wall") else name


def pag_relations(pag: PAG, index: dict[str, int], categories: dict[str, str]) -> list[RelationSpec]:
    """The PAG's relations among the objects in ``index`` (object id to graph index).

    Relations whose child or parent object is not in ``index`` are left out.
    """
    out = []
    for e in pag.relations:
        c = e.child.object
        if c not in index:
            continue
        if e.parent.is_room_element:
            p, pcat = -1, _room_category(e.parent.object)
        elif e.parent.object in index:
            p, pcat = index[e.parent.object], categories[e.parent.object]
        else:
            continue
        side = e.params.get("side")
        out.append(RelationSpec(index[c], p, e.relation, categories[c], pcat,
                                e.child.part, e.parent.part, e.child.surface, e.parent.surface,
                                side if isinstance(side, str) else None,
                                wall_index(e.parent.object) if e.parent.is_room_element else None))
    return out


def load_scene(scene_json: str | Path) -> LayoutScene:
    """Read one scene; poses of placed objects (settled where settled)."""
    from .._files import read_json

    f = Path(scene_json)
    d = read_json(f, what="scene file")
    fmt = d.get("format") if isinstance(d, dict) else None
    if fmt not in READABLE_FORMATS:
        raise InputError(Problem("/format", f"expected one of {', '.join(READABLE_FORMATS)}, "
                                            f"got {fmt!r}", str(f), "schema"))
    try:
        return _layout_scene(f, d)
    except (KeyError, TypeError, ValueError, AttributeError, IndexError) as e:
        what = f"missing {e}" if isinstance(e, KeyError) else str(e).splitlines()[0][:200]
        raise InputError(Problem("", f"damaged scene file ({what}): build the scene again",
                                 str(f), "schema")) from None


def _layout_scene(f: Path, d: dict) -> LayoutScene:
    pag = PAG.from_dict(d["pag"])
    ids, cats, infos, poses, solved, scales = [], [], [], [], [], []
    for od in d["objects"]:
        if od.get("status") != "placed":
            continue
        info = asset_info(od["asset"])
        s = float(od["scale"])
        ids.append(od["id"])
        cats.append(od["category"])
        infos.append(info)
        scales.append(s)
        size = s * np.asarray(info.extents, float)
        for dest, pose in ((poses, od.get("settled_pose") or od["pose"]), (solved, od["pose"])):
            dest.append(np.concatenate([np.asarray(pose["position"], float), size,
                                        rotation_to_6d(quat_to_matrix(pose["quaternion"]))]))
    index = {o: i for i, o in enumerate(ids)}
    rels = pag_relations(pag, index, dict(zip(ids, cats, strict=True)))
    poses_a = np.array(poses, float).reshape(-1, 12)
    solved_a = np.array(solved, float).reshape(-1, 12)
    return LayoutScene(f.parent.name, f.parent, pag, ids, cats, infos, poses_a,
                       np.array(scales, float), rels, np.array(d["room"]["footprint"], float),
                       float(d["room"]["height"]),
                       None if np.array_equal(poses_a, solved_a) else solved_a)


def load_dataset(dataset: str | Path, *, progress=None) -> list[LayoutScene]:
    """Every scene of a dataset folder with at least one placed object."""
    out = []
    for f in find_scenes(dataset):
        s = load_scene(f)
        if s.object_ids:
            out.append(s)
        if progress is not None:
            progress()
    save_asset_index()
    if not out:
        raise InputError(Problem("", "no scene of this dataset has a placed object",
                                 str(dataset), "io"))
    return out


def split_scenes(scene_ids: list[str], rng: np.random.Generator, *,
                 fractions: tuple[float, float, float] = (0.8, 0.1, 0.1)) -> dict[str, list[str]]:
    """Split scene ids into ``train``/``val``/``test`` (at least one train scene; val and test
    get at least one scene each when there are three or more)."""
    ids = sorted(scene_ids)
    perm = [ids[i] for i in rng.permutation(len(ids))]
    n = len(ids)
    n_test = max(1, round(fractions[2] * n)) if n >= 3 else 0
    n_val = max(1, round(fractions[1] * n)) if n >= 3 else 0
    test, val, train = perm[:n_test], perm[n_test:n_test + n_val], perm[n_test + n_val:]
    return {"train": sorted(train), "val": sorted(val), "test": sorted(test)}


@dataclass
class GraphArrays:
    """A scene graph as the network's input (N objects, R relations).

    Attributes
    ----------
    x0 : (N, 12) float32
        Normalised poses (zeros when generating).
    shape : (N, T, D) float32
        Shape feature tokens.
    rel_vec : (R, Dr) float32
        Relation vectors.
    rel_child, rel_parent : (R,) int64
        Object indices; ``rel_parent`` is -1 for room elements.
    room_geo : (N, 8) float32
        Per object, its relations to the room shell: floor, ceiling, any wall, number of
        numbered walls, mean wall midpoint (x, y normalised to the room box) and mean inward
        wall normal (x, y).
    room_ctx : (4,) float32
        Room width, depth, height (metres / 5) and floor area (m² / 25).
    """

    x0: np.ndarray
    shape: np.ndarray
    rel_vec: np.ndarray
    rel_child: np.ndarray
    rel_parent: np.ndarray
    room_geo: np.ndarray
    room_ctx: np.ndarray


def _room_features(footprint: np.ndarray, height: float, relations: list[RelationSpec],
                   n: int) -> tuple[np.ndarray, np.ndarray]:
    fp = np.asarray(footprint, float)
    lo, hi = fp.min(0), fp.max(0)
    geo = np.zeros((n, ROOM_GEO_DIM), np.float32)
    walls: dict[int, list[tuple[np.ndarray, np.ndarray]]] = {}
    for r in relations:
        if r.parent >= 0:
            continue
        if r.parent_category == "floor":
            geo[r.child, 0] = 1.0
        elif r.parent_category == "ceiling":
            geo[r.child, 1] = 1.0
        else:
            geo[r.child, 2] = 1.0
            if r.wall is not None and r.wall < len(fp):
                a, b = fp[r.wall], fp[(r.wall + 1) % len(fp)]
                d = (b - a) / max(np.linalg.norm(b - a), 1e-9)
                mid = 2.0 * ((a + b) / 2 - lo) / np.maximum(hi - lo, 1e-6) - 1.0
                walls.setdefault(r.child, []).append((mid, np.array([-d[1], d[0]])))
    for i, ws in walls.items():
        geo[i, 3] = len(ws)
        geo[i, 4:6] = np.mean([w[0] for w in ws], axis=0)
        geo[i, 6:8] = np.mean([w[1] for w in ws], axis=0)
    x, y = fp[:, 0], fp[:, 1]
    area = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
    ctx = np.array([(hi - lo)[0] / 5, (hi - lo)[1] / 5, height / 5, area / 25], np.float32)
    return geo, ctx


_SUPPORT = SUPPORT_RELATIONS


def support_parents(relations: list[RelationSpec], n: int) -> np.ndarray:
    """(n,) the support parent object of every object (-1: none, or a room element).

    An object's first support relation (``ON``/``IN``/``HANGING_BELOW``/``SECURED_TO``) counts,
    as :meth:`~parse3d.pag.model.PAG.supporter` does; a relation to a room element makes
    it a root. A relation that would close a cycle is ignored.
    """
    parents = np.full(n, -1, np.int64)
    seen = np.zeros(n, bool)
    for r in relations:
        if r.relation not in _SUPPORT or seen[r.child]:
            continue
        seen[r.child] = True
        if r.parent < 0:
            continue
        parents[r.child] = r.parent
        try:
            support_order(parents)
        except ValueError:
            parents[r.child] = -1
    return parents


def graph_arrays(categories: list[str], assets: list[Asset | AssetInfo],
                 relations: list[RelationSpec],
                 footprint: np.ndarray, height: float, *, shape_encoder: ShapeEncoder,
                 relation_encoder: RelationEncoder, stats: PoseStats,
                 poses: np.ndarray | None = None, frame: str = "world") -> GraphArrays:
    """The network input of one scene (``poses`` None: an empty ``x0`` for generation);
    ``frame="parent"``: translations in the support parent's frame (:mod:`.pose`)."""
    n = len(categories)
    shape = np.stack([shape_encoder.encode(a, c) for a, c in zip(assets, categories, strict=True)])
    parents = support_parents(relations, n) if frame == "parent" else None
    x0 = (normalise_poses(poses, footprint, height, stats, parents) if poses is not None
          else np.zeros((n, 12), np.float32))
    geo, ctx = _room_features(footprint, height, relations, n)
    rv = relation_encoder.encode(relations)
    return GraphArrays(x0.astype(np.float32), shape.astype(np.float32), rv.astype(np.float32),
                       np.array([r.child for r in relations], np.int64),
                       np.array([r.parent for r in relations], np.int64), geo, ctx)
