"""Asset previews for the designer: one GLB per (category, variant), one node per part.

Each part is a node named by the part's unique name (``leg_0``) whose ``extras`` carry what
the front end needs to turn a click into a reference: the part label, its index ``k`` among
parts of that label (the order ``#k`` counts, see ``Asset.parts_by_label``) and its six
directional surfaces (origin and outward normal). Coordinates in the GLB, extras included,
are glTF's Y-up: ``(x, y, z)`` of the asset frame becomes ``(x, z, -y)``.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import trimesh
from trimesh.exchange.gltf import export_glb
from trimesh.visual.material import PBRMaterial

from ..assets import registry
from ..assets.model import Asset
from ..errors import InputError, Problem
from ..pag.schema import suggest

__all__ = ["preview_asset", "preview_glb", "part_extras", "to_y_up"]

#: The asset frame (Z up) to glTF's Y-up, as a 3x3 rotation: (x, y, z) -> (x, z, -y).
_Y_UP = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])

#: Seed of the preview asset of each (category, variant).
PREVIEW_SEED = 0


def to_y_up(v) -> list[float]:
    """A (3,) point or direction of the asset frame in glTF's Y-up frame, rounded to 0.1 mm."""
    return [round(float(x), 5) for x in _Y_UP @ np.asarray(v, float)]


def preview_asset(category: str, variant: str | None = None) -> Asset:
    """The preview asset of a category (and variant; default: the category's first).

    Raises
    ------
    InputError
        Unknown category or variant (kind ``vocabulary``), with the closest name suggested.
    """
    cats = registry.categories()
    if category not in cats:
        raise InputError(Problem("/category", f"unknown category {category!r}"
                                 f"{suggest(category, cats)}", None, "vocabulary"))
    cat = cats[category]
    if cat.generator is None:
        return registry.generate(category, seed=PREVIEW_SEED)
    variant = variant or cat.variants[0]
    if variant not in cat.variants:
        raise InputError(Problem("/variant", f"category {category!r} has no variant {variant!r}"
                                 f"{suggest(variant, cat.variants)} (variants: "
                                 f"{', '.join(cat.variants)})", None, "vocabulary"))
    return registry.generate(category, seed=PREVIEW_SEED, variant=variant)


def part_extras(asset: Asset) -> dict[str, dict]:
    """The ``extras`` of each part node, by part name (Y-up coordinates)."""
    index = {}
    for label in dict.fromkeys(p.label for p in asset.parts):
        for k, p in enumerate(asset.parts_by_label(label)):
            index[p.name] = k
    out = {}
    for p in asset.parts:
        surfaces = {lab: {"origin": to_y_up(s.origin), "normal": to_y_up(s.normal),
                          "area": round(float(s.area), 6)}
                    for lab, s in p.surfaces.items()}
        out[p.name] = {"part": p.name, "label": p.label, "k": index[p.name],
                       "count": sum(1 for q in asset.parts if q.label == p.label),
                       "category": asset.category, "asset_id": asset.asset_id,
                       "surfaces": surfaces}
    return out


@lru_cache(maxsize=256)
def preview_glb(category: str, variant: str | None = None) -> bytes:
    """GLB bytes of the preview asset: one node per part with its :func:`part_extras`."""
    asset = preview_asset(category, variant)
    extras = part_extras(asset)
    ts = trimesh.Scene()
    T = np.eye(4)
    T[:3, :3] = _Y_UP
    for p in asset.parts:
        m = p.mesh.copy()
        m.apply_transform(T)
        m.visual = trimesh.visual.TextureVisuals(material=PBRMaterial(
            baseColorFactor=[int(round(c * 255)) for c in p.material.color],
            metallicFactor=float(p.material.metallic),
            roughnessFactor=float(p.material.roughness), doubleSided=True))
        ts.add_geometry(m, node_name=p.name, geom_name=p.name)

    def add_extras(tree: dict) -> None:
        for node in tree.get("nodes", []):
            if node.get("name") in extras:
                node["extras"] = extras[node["name"]]
        tree.setdefault("asset", {})["extras"] = {
            "category": asset.category, "asset_id": asset.asset_id,
            "variant": asset.meta.get("variant")}

    return export_glb(ts, tree_postprocessor=add_extras)
