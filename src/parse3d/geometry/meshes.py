"""Triangle meshes as plain arrays, for the paths that need no mesh library.

Importing trimesh costs about half a second (it imports scipy.spatial, scipy.sparse and
scipy.special). A command that only reads cached assets, solves and writes a scene needs
vertices and faces, bounds, concatenation and scaling; :class:`MeshArrays` gives those with numpy
alone and turns into a ``trimesh.Trimesh`` (:meth:`MeshArrays.to_trimesh`) where one is truly
needed. The results equal trimesh's bit for bit (the same arithmetic in the same order).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np

__all__ = ["MeshArrays", "concatenate_arrays", "mesh_bounds", "scaled_vertices"]


@dataclass(frozen=True, eq=False)
class MeshArrays:
    """A triangle mesh as arrays.

    Attributes
    ----------
    vertices : (V, 3) float64
        Metres, in whatever frame the owner documents.
    faces : (F, 3) int64
        Vertex indices, counter-clockwise seen from outside.
    """

    vertices: np.ndarray
    faces: np.ndarray

    @cached_property
    def bounds(self) -> np.ndarray | None:
        """(2, 3) bounds of the vertices the faces use (None without any), as trimesh's."""
        return mesh_bounds(self.vertices, self.faces)

    def to_trimesh(self):
        """The same mesh as a ``trimesh.Trimesh`` (unprocessed, sharing nothing with this one).

        Made without trimesh's embree ray intersector: nothing casts rays through ``mesh.ray``
        (the ray queries build their own), and building one per mesh is a fifth of the cost of
        making it; ``mesh.ray`` still works, in Python.
        """
        import trimesh

        return trimesh.Trimesh(self.vertices.copy(), self.faces.copy(), process=False,
                               use_embree=False)


def mesh_bounds(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray | None:
    """(2, 3) min and max over the vertices ``faces`` reference; None when they reference none.

    Parameters
    ----------
    vertices : (V, 3) float
    faces : (F, 3) int
    """
    used = np.zeros(len(vertices), bool)
    used[np.asarray(faces).ravel()] = True
    pts = np.asarray(vertices)[used]
    if len(pts) == 0:
        return None
    return np.array([pts.min(axis=0), pts.max(axis=0)])


def concatenate_arrays(meshes: Sequence) -> MeshArrays:
    """One mesh of ``meshes`` (anything with ``vertices`` and ``faces``), faces re-indexed.

    Vertices and faces come in the order given, as ``trimesh.util.concatenate`` lays them out.
    """
    vs = [np.asarray(m.vertices, np.float64).view(np.ndarray) for m in meshes]
    fs = [np.asarray(m.faces, np.int64).view(np.ndarray) for m in meshes]
    offsets = np.cumsum([0] + [len(v) for v in vs[:-1]])
    vertices = np.vstack(vs) if vs else np.zeros((0, 3))
    faces = np.vstack([f + o for f, o in zip(fs, offsets, strict=True)]) if fs else np.zeros((0, 3), np.int64)
    return MeshArrays(vertices, faces)


def scaled_vertices(vertices: np.ndarray, scale: float) -> np.ndarray:
    """``vertices`` (V, 3) scaled about the origin by ``scale``, as ``Trimesh.apply_scale``
    computes it (a homogeneous matrix product; a scale within 1e-8 of 1 leaves them as they
    are), so collision models built from either agree exactly."""
    pts = np.asarray(vertices, np.float64)
    M = np.eye(4)
    M[:3, :3] *= float(scale)
    if len(pts) == 0 or np.abs(M - np.eye(4)).max() < 1e-8:
        return np.ascontiguousarray(pts.copy())
    stack = np.column_stack((pts, np.ones(len(pts))))
    return np.dot(M, stack.T).T[:, :3]
