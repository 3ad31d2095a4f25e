"""A dataset worker: its per-asset caches stay bounded and trimming them changes no output;
what it derives per new asset agrees with the reference computation."""

from __future__ import annotations

import json
from collections import OrderedDict

import numpy as np
import pytest
import trimesh

from parse3d.datagen.build import BuildConfig, build_scene, resolve_pag_paths
from parse3d.datagen.memory import LIGHT_CACHE_FACTOR, _trim, bound_caches, cache_sizes
from parse3d.render import Renderer

PAG = {"format": "pag/1", "name": "tiny-study",
       "room": {"type": "study", "footprint": [[0, 0], [3, 0], [3, 3], [0, 3]], "height": 2.6},
       "objects": [{"id": "desk", "category": "desk"}, {"id": "mug", "category": "mug"},
                   {"id": "book", "category": "book"}],
       "relations": [{"relation": "ON", "child": "desk", "parent": "floor"},
                     {"relation": "ON", "child": "mug", "parent": "desk:tabletop"},
                     {"relation": "ON", "child": "book", "parent": "desk:tabletop"}]}


def test_trim_drops_the_oldest_entries_first():
    lru = OrderedDict((k, k) for k in "abcde")
    lru.move_to_end("a")  # used last: kept
    dropped = []
    assert _trim(lru, 2, dropped.append) == 3
    assert list(lru) == ["e", "a"] and dropped == ["b", "c", "d"]
    plain = {k: k for k in range(6)}
    assert _trim(plain, 4) == 2 and list(plain) == [2, 3, 4, 5]
    assert _trim(plain, 10) == 0 and len(plain) == 4


def _files(outcome) -> dict[str, bytes]:
    files = dict(outcome.files)
    doc = json.loads(files.pop("scene.json"))
    doc.pop("timings")
    files["scene.json"] = json.dumps(doc, sort_keys=True).encode()
    return files


@pytest.fixture(scope="module")
def renderer():
    r = Renderer()
    yield r
    r.release()


def test_a_scene_built_on_emptied_caches_is_the_same(tmp_path, renderer):
    path = tmp_path / "tiny-study.json"
    path.write_text(json.dumps(PAG))
    cfg = BuildConfig(scenes=2, seed=3, source=resolve_pag_paths([path]))
    warm = build_scene(cfg, 1, renderer=renderer)
    assert warm.record["status"] == "ok", warm.record["reason"]
    sizes = cache_sizes(renderer)
    assert sizes["assets"] >= 3 and sizes["render meshes"] >= 3 and sizes["collision"] >= 3
    # per-stage CPU seconds are recorded next to the wall-clock ones
    assert warm.record["cpu_solve"] > 0 and warm.record["cpu_total"] > 0

    assert bound_caches(renderer, assets=2) > 0
    sizes = cache_sizes(renderer)
    light = 2 * LIGHT_CACHE_FACTOR  # the small entries keep more assets
    assert sizes["assets"] <= light and sizes["collision"] <= light
    assert sizes["render meshes"] <= 2
    assert sizes["bvh"] <= 2 and renderer.cache_size <= 2
    bound_caches(renderer, assets=0)
    assert set(cache_sizes(renderer).values()) == {0}

    cold = build_scene(cfg, 1, renderer=renderer)
    assert cold.record["status"] == "ok"
    assert sorted(cold.files) == sorted(warm.files)
    assert _files(cold) == _files(warm)  # scene.json, contacts.json, scene.glb, preview.png


def _meshes() -> dict[str, trimesh.Trimesh]:
    box = trimesh.creation.box((1.0, 2.0, 0.5))
    cyl = trimesh.creation.cylinder(0.3, 1.0, sections=24)
    f = np.asarray(box.faces)
    flipped = f.copy()
    flipped[3] = flipped[3, ::-1]  # one face wound the other way: watertight, inconsistent
    return {
        "box": box, "cylinder": cyl, "sphere": trimesh.creation.icosphere(2),
        "inside-out": trimesh.Trimesh(box.vertices, f[:, ::-1], process=False),
        "open": trimesh.Trimesh(box.vertices, f[:-1], process=False),
        "flipped face": trimesh.Trimesh(box.vertices, flipped, process=False),
        "doubled face": trimesh.Trimesh(box.vertices, np.vstack([f, f[:1]]), process=False),
        "plane": trimesh.Trimesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]], process=False),
        "empty": trimesh.Trimesh(np.zeros((0, 3)), np.zeros((0, 3), int), process=False),
    }


@pytest.mark.parametrize("name", sorted(_meshes()))
def test_closed_agrees_with_trimesh(name):
    from parse3d.render.renderer import _closed

    mesh = _meshes()[name]
    copy = mesh.copy()
    try:
        want = bool(copy.is_watertight and copy.is_winding_consistent and copy.volume > 0)
    except (ValueError, IndexError):
        want = False
    assert _closed(mesh) == want
    assert want == (name in ("box", "cylinder", "sphere"))
