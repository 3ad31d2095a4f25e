"""Ray casting against a triangle mesh with Embree (embreex), from arrays.

The solver asks where rays first hit an asset (how far a child drops onto its parent, how
deep a hole in a support is, whether a container encloses a point). trimesh's Embree wrapper
answers that too, but importing trimesh costs more than a whole small solve. This caster
takes vertices and faces and gives the same answers bit for bit: Embree runs in float32 on
the mesh moved to its lowest corner and scaled so its bounding-box diagonal is 100 (the
precision trimesh's wrapper also works at), and each hit point is recomputed in float64 as
the crossing of the ray with the hit triangle's plane. (A ``trimesh.Trimesh`` that carries
face normals given at its creation, as trimesh's primitives do, may put hit points a rounding
error away; meshes read from the asset cache carry none.)
"""

from __future__ import annotations

import numpy as np

from .meshes import mesh_bounds

__all__ = ["RayCaster"]

#: Vectors shorter than this have no direction (a degenerate triangle has no normal).
_ZERO = float(np.finfo(np.float64).resolution * 100)
#: A ray this close to parallel to the hit triangle's plane has no crossing point.
_PARALLEL = 1e-5


def _unit_rows(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Rows of (N, 3) ``v`` scaled to unit length, and which rows had a length at all (the
    others are left as they are)."""
    norm = np.sqrt(np.dot(v * v, [1.0, 1.0, 1.0]))
    valid = norm > _ZERO
    norm[valid] **= -1
    return v * norm.reshape((-1, 1)), valid


def _row_dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.dot(a * b, [1.0, 1.0, 1.0])


class RayCaster:
    """First hits of rays on one triangle mesh.

    Parameters
    ----------
    vertices : (V, 3) float
        Metres, in the frame rays will be given in.
    faces : (F, 3) int

    Examples
    --------
    >>> v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]]); f = np.array([[0, 1, 2]])
    >>> locs, ray, tri = RayCaster(v, f).first_hits(np.array([[0.2, 0.2, 1.0]]),
    ...                                              np.array([[0, 0, -2.0]]))
    >>> locs.round(6).tolist(), ray.tolist(), tri.tolist()
    ([[0.2, 0.2, 0.0]], [0], [0])
    """

    def __init__(self, vertices: np.ndarray, faces: np.ndarray):
        from embreex import rtcore_scene
        from embreex.mesh_construction import TriangleMesh

        v = np.array(vertices, dtype=np.float64)
        f = np.asarray(faces, dtype=np.int64).view(np.ndarray)
        tri = v[f]
        self._plane_origins = tri[:, 0, :]
        edges = tri[:, 1:, :] - tri[:, :2, :]
        normals, valid = _unit_rows(np.cross(edges[:, 0], edges[:, 1]))
        self._plane_normals = np.where(valid[:, None], normals, 0.0)
        b = mesh_bounds(v, f)
        diagonal = 1.0 if b is None else float((np.ptp(b, axis=0) ** 2).sum() ** 0.5)
        self._scale = 100.0 / diagonal
        self._origin = v.min(axis=0) if len(v) else np.zeros(3)
        self._scene = rtcore_scene.EmbreeScene()
        TriangleMesh(scene=self._scene,
                     vertices=((v - self._origin) * self._scale).astype(np.float32),
                     indices=f.astype(np.int32))

    def _first_triangle(self, origins: np.ndarray, directions: np.ndarray) -> np.ndarray:
        scaled = (np.array(origins, dtype=np.float64) - self._origin) * self._scale
        return self._scene.run(scaled.astype(np.float32), directions.astype(np.float32))

    def first_hits(self, origins: np.ndarray, directions: np.ndarray
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Where each ray first hits the mesh.

        Parameters
        ----------
        origins, directions : (N, 3) float
            Directions need not be unit length.

        Returns
        -------
        locations : (M, 3) float
            Hit points, in the rays' order.
        index_ray : (M,) int
            The ray of each hit (rays that miss, or run along the hit triangle's plane, have
            none).
        index_tri : (M,) int
            The face each ray hit.
        """
        origins = np.array(origins, dtype=np.float64)
        directions = np.array(directions, dtype=np.float64)
        if origins.shape != directions.shape:
            raise ValueError(f"origins {origins.shape} and directions {directions.shape} differ")
        directions, _ = _unit_rows(directions)
        query = self._first_triangle(origins, directions)
        rays = np.nonzero(query != -1)[0]
        tris = query[rays].astype(np.int64)
        to_plane = self._plane_origins[tris] - origins[rays]
        normals = self._plane_normals[tris]
        along = _row_dot(directions[rays], normals)
        ok = np.abs(along) > _PARALLEL
        dist = np.divide(_row_dot(to_plane, normals)[ok], along[ok])
        locations = directions[rays][ok] * dist.reshape((-1, 1))
        locations += origins[rays][ok]
        return locations, rays[ok], tris[ok]

    def any_hits(self, origins: np.ndarray, directions: np.ndarray) -> np.ndarray:
        """(N,) bool: whether each ray hits the mesh at all."""
        directions, _ = _unit_rows(np.asarray(directions, dtype=np.float64))
        return self._first_triangle(np.asarray(origins, dtype=np.float64), directions) != -1
