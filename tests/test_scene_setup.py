"""What a solve sets up per scene and keeps for the next one in the same process: the room
shell (copies, never shared arrays) and the room slabs' BVHs (shared, by content)."""

from __future__ import annotations

import numpy as np

from parse3d.geometry.meshes import MeshArrays
from parse3d.pag.model import Room
from parse3d.scene import shell
from parse3d.solver.collision import static_body


def test_a_shell_built_again_is_equal_and_shares_no_array(tmp_path, monkeypatch):
    monkeypatch.setenv("PARSE3D_CACHE", str(tmp_path))
    monkeypatch.setattr(shell, "_BUILT", {})
    room = Room("study", ((0, 0), (3, 0), (3, 2.5), (0, 2.5)), 2.7)
    first = shell.build_shell(room)
    want = {n: (e.mesh_arrays.vertices.copy(), e.surface.origin.copy())
            for n, e in first.elements.items()}
    for el in first.elements.values():  # a caller may change what it was given
        el.mesh_arrays.vertices[:] += 5.0
        el.surface.origin[:] = 0.0
    first.footprint[:] = 9.0
    second = shell.build_shell(room)
    assert list(second.elements) == list(want)
    for n, el in second.elements.items():
        assert np.array_equal(el.mesh_arrays.vertices, want[n][0])
        assert np.array_equal(el.surface.origin, want[n][1])
    assert np.array_equal(second.footprint, np.asarray(room.footprint, float))
    other = shell.build_shell(Room("study", room.footprint, 3.0))
    assert other.elements["ceiling"].surface.origin[2] == 3.0


def test_static_bodies_share_a_bvh_per_distinct_mesh():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
    f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    a, b = static_body(MeshArrays(v, f)), static_body(MeshArrays(v.copy(), f.copy()))
    c = static_body(MeshArrays(v * 2, f))
    assert a.geom is b.geom and a.obj is not b.obj
    assert c.geom is not a.geom
