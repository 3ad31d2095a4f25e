"""What a solve with cached assets reads without a mesh library: assets as arrays, the stored
hull, the shell cache and the registry's catalog."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from parse3d.assets import registry
from parse3d.assets.cache import load_asset, save_asset
from parse3d.assets.model import hull_points
from parse3d.assets.pool import category_fingerprint
from parse3d.geometry.meshes import MeshArrays, concatenate_arrays, scaled_vertices
from parse3d.pag.model import Room
from parse3d.scene import shell

SRC = str(Path(__file__).resolve().parent.parent / "src")


def _run(code: str, cache: Path) -> dict:
    env = {**os.environ, "PYTHONPATH": SRC, "PARSE3D_CACHE": str(cache)}
    r = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                       check=True)
    return json.loads(r.stdout.strip().splitlines()[-1])


@pytest.fixture(scope="module")
def cabinet(tmp_path_factory):
    """A generated asset with pieces and joints, and its cached file."""
    a = registry.generate("dresser", seed=2)
    path = save_asset(a, tmp_path_factory.mktemp("assets") / "cab.npz")
    return a, path


def test_loaded_asset_reads_arrays_equal_to_its_meshes(cabinet):
    _, path = cabinet
    a = load_asset(path)
    assert all(isinstance(p.piece_arrays[0], MeshArrays) for p in a.parts if p.piece_arrays)
    for p in a.parts:
        v, f, b = np.array(p.vertices), np.array(p.faces), p.bounds
        m = p.mesh  # made now
        assert np.array_equal(m.vertices, v) and np.array_equal(m.faces, f)
        assert np.array_equal(m.bounds, b)
        assert [np.array_equal(pc.vertices, q.vertices) for pc, q in zip(
            p.pieces, p.piece_arrays, strict=True)] == [True] * len(p.pieces)
    whole = a.mesh()
    arr = a.mesh_arrays()
    assert np.array_equal(whole.vertices, arr.vertices) and np.array_equal(whole.faces, arr.faces)


def test_stored_hull_is_the_hull_of_the_loaded_pieces(cabinet):
    _, path = cabinet
    a = load_asset(path)
    assert a.hull is not None
    pts = np.vstack([pc.vertices for p in a.parts for pc in p.pieces])
    assert np.array_equal(a.hull, hull_points(pts))


def test_scaled_vertices_match_trimesh_apply_scale(cabinet):
    a, _ = cabinet
    for s in (1.0, 1.0 + 1e-10, 0.83, 1.27):
        m = a.mesh()
        m.apply_scale(s)
        assert np.array_equal(scaled_vertices(a.mesh_arrays().vertices, s), m.vertices)
    assert concatenate_arrays([]).vertices.shape == (0, 3)


def test_loading_and_measuring_an_asset_imports_no_trimesh(cabinet, tmp_path):
    _, path = cabinet
    got = _run(f"""
import json, sys
from parse3d.assets.cache import load_asset
from parse3d.measure.geometry import asset_geometry, part_points
a = load_asset({str(path)!r})
g = asset_geometry(a)
part_points(a.parts)
b = a.bounds
print(json.dumps({{"trimesh": "trimesh" in sys.modules, "scipy": "scipy" in sys.modules}}))
""", tmp_path)
    assert got == {"trimesh": False, "scipy": False}


def test_shell_cache_gives_the_extruded_slabs(tmp_path, monkeypatch):
    monkeypatch.setenv("PARSE3D_CACHE", str(tmp_path))
    monkeypatch.setattr(shell, "_BUILT", {})  # nothing built in this process yet
    room = Room("kitchen", ((0, 0), (4, 0), (4, 2), (2, 2), (2, 3.5), (0, 3.5)), 2.6)
    fresh = shell.build_shell(room)
    files = list((tmp_path / "shell").glob("*.npz"))
    assert len(files) == 1
    remembered = shell.build_shell(room)  # from this process's memory: a copy
    assert remembered.elements["floor"].mesh_arrays.vertices is not \
        fresh.elements["floor"].mesh_arrays.vertices
    shell._BUILT.clear()
    again = shell.build_shell(room)  # from the cache
    for n, el in fresh.elements.items():
        m = again.elements[n].mesh_arrays
        assert np.array_equal(el.mesh_arrays.vertices, m.vertices)
        assert np.array_equal(el.mesh_arrays.faces, m.faces)
        assert np.array_equal(el.mesh.vertices, again.elements[n].mesh.vertices)
    files[0].write_bytes(b"not a zip")  # damaged: extruded again and rewritten
    shell._BUILT.clear()
    third = shell.build_shell(room)
    assert np.array_equal(third.elements["floor"].mesh_arrays.faces,
                          fresh.elements["floor"].mesh_arrays.faces)
    assert np.load(files[0])["v0"].shape[1] == 3


def test_catalog_answers_like_the_registry_without_importing_generators(tmp_path):
    cats = ["dresser", "mug", "bookcase"]
    want = {c: [list(registry.get(c).size_range), category_fingerprint(c)] for c in cats}
    data = json.dumps(registry.catalog())
    got = _run(f"""
import json, sys
from parse3d.assets import registry
from parse3d.assets.pool import category_fingerprint
registry.install_catalog(json.loads({data!r}))
out = {{c: [list(registry.get(c).size_range), category_fingerprint(c)] for c in {cats!r}}}
out["vocabulary"] = len(registry.vocabulary().categories())
out["trimesh"] = "trimesh" in sys.modules
print(json.dumps(out))
""", tmp_path)
    assert got.pop("trimesh") is False
    assert got.pop("vocabulary") == len(registry.categories())
    assert got == want


def test_ray_caster_matches_trimesh_bit_for_bit(cabinet):
    from trimesh.ray.ray_pyembree import RayMeshIntersector

    from parse3d.geometry.rays import RayCaster

    # an asset as the solver gets it, read from the pool (a generated one may carry the face
    # normals of the primitives it was built from, rounded differently)
    a = load_asset(cabinet[1])
    ref = RayMeshIntersector(a.mesh())
    m = a.mesh_arrays()
    mine = RayCaster(m.vertices, m.faces)
    rng = np.random.default_rng(3)
    b = a.bounds
    o = rng.uniform(b[0] - 0.1, b[1] + 0.1, (600, 3))
    d = rng.normal(size=(600, 3))
    d[:200] = [0.0, 0.0, -1.0]  # straight down, as drops are cast
    d[200:300] *= 4.0  # not unit length
    want = ref.intersects_location(o, d, multiple_hits=False)
    got = mine.first_hits(o, d)
    assert len(want[1]) > 100
    for w, g in zip(want, got, strict=True):
        assert w.dtype == g.dtype and np.array_equal(w, g)
    assert np.array_equal(ref.intersects_any(o, d), mine.any_hits(o, d))


def test_joint_rotation_matches_trimesh():
    import trimesh

    from parse3d.geometry.frames import rotation_about

    rng = np.random.default_rng(5)
    for _ in range(200):
        axis, theta = rng.normal(size=3) * rng.uniform(0.1, 5), rng.uniform(-7, 7)
        assert np.array_equal(rotation_about(axis, theta),
                              trimesh.transformations.rotation_matrix(theta, axis)[:3, :3])
