"""Part-level contact extraction (paper, supplementary "Scene Simulation Procedure and Contact
Extraction").

For every pair of objects (the room shell counts as one more, static, body) and every pair of
their convex collision pieces, points are sampled uniformly on each piece's surface; a point
whose distance to the *other* piece is at most ``threshold`` (1 mm) — or that lies inside it —
is a contact sample. Every piece belongs to exactly one part, so each sample names a pair of
parts; aggregating the samples over the scene gives the undirected part-level contact graph.

Only the part of a piece's surface that can possibly be within ``threshold`` of the other piece
is sampled: its triangles are clipped to the other piece's bounding box grown by the threshold
and points are drawn uniformly (area-weighted) on the clipped polygons. That is the same
distribution as sampling the whole surface and discarding points that cannot qualify, at a
fraction of the cost. The hull vertices inside that box are added as samples too, so a contact
at a single corner is not missed by chance.

Distances are exact: for a point and a convex piece ``{x : n_k . x <= d_k}``, the largest
plane value ``m = max_k (n_k . x - d_k)`` is the signed distance when the point is inside
(``m <= 0``) or when its projection onto the maximising plane lies on the piece; otherwise the
distance is found against the piece's triangles (closest point on a triangle, vectorised).
``m`` is always a lower bound, so points with ``m > threshold`` are rejected without more work.

The result is deterministic: bodies in scene order, pieces in asset order, one generator from
``seed``.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

import numpy as np

from ..scene.model import Contact, Scene
from .collision import (
    ROOM,
    ConvexSet,
    WorldBody,
    _asset_key,
    asset_collision,
    concatenate,
    fcl_convex,
    fcl_piece,
    scene_bodies,
    shell_collision,
)

if TYPE_CHECKING:
    import networkx as nx

__all__ = [
    "extract_contacts",
    "contact_samples",
    "ContactSamples",
    "contacts_to_json",
    "contacts_from_json",
    "contact_graph",
    "signed_distance",
    "closest_point_on_triangles",
    "clip_triangles_to_boxes",
    "touching_parts",
]

DEFAULT_THRESHOLD = 0.001
DEFAULT_SAMPLES_PER_M2 = 10_000.0
DEFAULT_MIN_SAMPLES = 16
_PAD = 1e8  # plane offsets at or above this are padding


# --------------------------------------------------------------------------- geometry kernels


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.einsum("...i,...i->...", a, b)


def closest_point_on_triangles(p: np.ndarray, a: np.ndarray, b: np.ndarray,
                               c: np.ndarray) -> np.ndarray:
    """Closest point to ``p[i]`` on triangle ``(a[i], b[i], c[i])``.

    Parameters
    ----------
    p, a, b, c : (N, 3) float

    Returns
    -------
    (N, 3) float
        The closest points (Voronoi-region method; exact for degenerate triangles too).
    """
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = _dot(ab, ap), _dot(ac, ap)
    bp = p - b
    d3, d4 = _dot(ab, bp), _dot(ac, bp)
    cp = p - c
    d5, d6 = _dot(ab, cp), _dot(ac, cp)
    va = d3 * d6 - d5 * d4
    vb = d5 * d2 - d1 * d6
    vc = d1 * d4 - d3 * d2
    with np.errstate(divide="ignore", invalid="ignore"):
        den = va + vb + vc
        v_in = np.where(den != 0, vb / den, 0.0)
        w_in = np.where(den != 0, vc / den, 0.0)
        out = a + ab * v_in[:, None] + ac * w_in[:, None]
        # edge regions, then vertex regions; later assignments take precedence (Ericson's order)
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        m = (va <= 0) & (d4 - d3 >= 0) & (d5 - d6 >= 0)
        out = np.where(m[:, None], b + np.nan_to_num(w)[:, None] * (c - b), out)
        w = d2 / (d2 - d6)
        m = (vb <= 0) & (d2 >= 0) & (d6 <= 0)
        out = np.where(m[:, None], a + np.nan_to_num(w)[:, None] * ac, out)
        m = (d6 >= 0) & (d5 <= d6)
        out = np.where(m[:, None], c, out)
        v = d1 / (d1 - d3)
        m = (vc <= 0) & (d1 >= 0) & (d3 <= 0)
        out = np.where(m[:, None], a + np.nan_to_num(v)[:, None] * ab, out)
        m = (d3 >= 0) & (d4 <= d3)
        out = np.where(m[:, None], b, out)
        m = (d1 <= 0) & (d2 <= 0)
        out = np.where(m[:, None], a, out)
    return out


def signed_distance(points: np.ndarray, target: np.ndarray, pieces: ConvexSet, *,
                    cutoff: float = np.inf) -> np.ndarray:
    """Signed distance from each point to its convex piece (negative inside).

    Parameters
    ----------
    points : (N, 3) float
        World points.
    target : (N,) int
        Index of the piece of ``pieces`` each point is measured against.
    pieces : ConvexSet
    cutoff : float
        Points whose plane bound already exceeds ``cutoff`` get that lower bound instead of
        the exact distance (their only use is to be rejected).

    Returns
    -------
    (N,) float, metres
        Exact signed distance wherever it is ``<= cutoff``; a lower bound above it.
    """
    n = len(points)
    out = np.empty(n)
    if n == 0:
        return out
    order = np.argsort(target, kind="stable")
    tsorted = target[order]
    starts = np.flatnonzero(np.r_[True, tsorted[1:] != tsorted[:-1]])
    ends = np.r_[starts[1:], n]
    need_exact = []
    for s0, s1 in zip(starts, ends, strict=True):
        idx = order[s0:s1]
        pl = pieces.planes[tsorted[s0]]
        pl = pl[pl[:, 3] < _PAD]
        normals = pl[:, :3]
        vals = points[idx] @ normals.T - pl[:, 3]  # (m, F)
        k = vals.argmax(axis=1)
        m = vals[np.arange(len(idx)), k]
        out[idx] = m
        cand = (m > 0) & (m <= cutoff)
        if cand.any():
            # is the projection onto the maximising plane on the piece? then m is exact
            c = np.flatnonzero(cand)
            proj = vals[c] - m[c, None] * (normals[k[c]] @ normals.T)
            on_face = (proj <= 1e-12).all(axis=1)
            need_exact.append(idx[c[~on_face]])
    idx = np.concatenate(need_exact) if need_exact else np.zeros(0, int)
    if len(idx):
        out[idx] = _distance_to_surface(points[idx], target[idx], pieces)
    return out


def _distance_to_surface(points: np.ndarray, target: np.ndarray, pieces: ConvexSet) -> np.ndarray:
    """Unsigned distance from points to the triangles of their pieces (points outside)."""
    ti = pieces.tri_index
    counts = ti[target + 1] - ti[target]
    owner = np.repeat(np.arange(len(points)), counts)
    starts = np.repeat(ti[target] - np.concatenate([[0], np.cumsum(counts)[:-1]]), counts)
    tri = pieces.triangles[np.arange(len(owner)) + starts]
    p = points[owner]
    q = closest_point_on_triangles(p, tri[:, 0], tri[:, 1], tri[:, 2])
    d = np.linalg.norm(p - q, axis=1)
    best = np.full(len(points), np.inf)
    np.minimum.at(best, owner, d)
    return best


def clip_triangles_to_boxes(tris: np.ndarray, lo: np.ndarray,
                            hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Clip each triangle to its axis-aligned box (Sutherland–Hodgman, vectorised).

    Parameters
    ----------
    tris : (N, 3, 3) float
    lo, hi : (N, 3) float
        Box corners per triangle.

    Returns
    -------
    sub : (N, K, 3, 3) float
        Fan triangulation of each clipped polygon (``K`` = 7 for six clipping planes);
        unused slots are degenerate.
    areas : (N, K) float
        Area of each sub-triangle (0 for unused slots), in the units of ``tris`` squared.
    """
    full, tris_all = len(tris), tris
    inside = ((tris >= lo[:, None]) & (tris <= hi[:, None])).all(axis=(1, 2))
    cut = np.flatnonzero(~inside)  # only these need clipping: the rest stay as they are
    tris, lo, hi = tris[cut], lo[cut], hi[cut]
    N = len(tris)
    poly = tris.astype(float, copy=True)
    count = np.full(N, 3)
    for axis in range(3):
        for sign, bound in ((1.0, lo[:, axis]), (-1.0, hi[:, axis])):
            K = poly.shape[1]
            ar = np.arange(K)[None, :]
            valid = ar < count[:, None]
            nxt = np.where(ar + 1 < count[:, None], ar + 1, 0)
            s = sign * (poly[..., axis] - bound[:, None])
            sn = np.take_along_axis(s, nxt, axis=1)
            pn = np.take_along_axis(poly, nxt[..., None], axis=1)
            ins, insn = s >= 0, sn >= 0
            den = s - sn
            t = np.divide(s, den, out=np.zeros_like(s), where=den != 0)
            inter = poly + t[..., None] * (pn - poly)
            out = np.stack([poly, inter], axis=2).reshape(N, 2 * K, 3)
            keep = np.stack([valid & ins, valid & (ins != insn)], axis=2).reshape(N, 2 * K)
            count = keep.sum(axis=1)
            # the kept vertices, in order, moved to the front of each row (the slots past
            # ``count`` are never read)
            rows, cols = np.nonzero(keep)
            slot = np.cumsum(keep, axis=1)[rows, cols] - 1
            poly = np.zeros((N, max(3, int(count.max()) if N else 3), 3))
            poly[rows, slot] = out[rows, cols]
    K = poly.shape[1]
    clipped, poly = poly, np.zeros((full, K, 3))
    poly[cut] = clipped
    poly[inside, :3] = tris_all[inside]
    clipped_count, count = count, np.full(full, 3)
    count[cut] = clipped_count
    N = full
    j = np.arange(1, K - 1)
    sub = np.stack([np.broadcast_to(poly[:, :1], (N, K - 2, 3)), poly[:, j], poly[:, j + 1]],
                   axis=2)
    areas = 0.5 * np.linalg.norm(np.cross(sub[:, :, 1] - sub[:, :, 0], sub[:, :, 2] - sub[:, :, 0]),
                                 axis=-1)
    areas = np.where(j[None, :] + 1 < count[:, None], areas, 0.0)
    return sub, areas


# ---------------------------------------------------------------------------- extraction


class ContactSamples:
    """The recorded contact samples of a scene (what :func:`extract_contacts` aggregates).

    Attributes
    ----------
    points : (M, 3) float
        World positions of the samples, metres.
    distance : (M,) float
        Signed distance of each sample to the other piece (negative: inside it).
    source, target : (M,) int
        Global piece index the sample lies on / is measured against.
    keys : list of str
        ``body:part`` of every global piece.
    body : (G,) int
        Body index of every global piece.
    """

    def __init__(self, points, distance, source, target, keys, body):
        self.points = points
        self.distance = distance
        self.source = source
        self.target = target
        self.keys = keys
        self.body = body


def _candidate_body_pairs(bodies: list[WorldBody], thr: float,
                          pairs: set[frozenset[str]] | None) -> list[tuple[int, int]]:
    lo = np.array([b.bounds[0] for b in bodies]) - thr
    hi = np.array([b.bounds[1] for b in bodies]) + thr
    ov = ((lo[:, None] <= hi[None]) & (lo[None] <= hi[:, None])).all(-1)
    static = np.array([b.static for b in bodies])
    ov &= ~(static[:, None] & static[None])
    ii, jj = np.nonzero(np.triu(ov, 1))
    out = [(int(i), int(j)) for i, j in zip(ii, jj, strict=True)]
    if pairs is not None:
        out = [(i, j) for i, j in out if frozenset((bodies[i].id, bodies[j].id)) in pairs]
    return out


def contact_samples(bodies: list[WorldBody], *, threshold: float = DEFAULT_THRESHOLD,
                    samples_per_m2: float = DEFAULT_SAMPLES_PER_M2,
                    min_samples: int = DEFAULT_MIN_SAMPLES, seed: int = 0,
                    pairs: Iterable[tuple[str, str]] | None = None) -> ContactSamples:
    """Sample the surfaces of every candidate piece pair and keep points within ``threshold``.

    Parameters
    ----------
    bodies : list of WorldBody
        World-frame bodies (see :func:`parse3d.physics.collision.scene_bodies`).
    threshold : float
        Contact distance, metres.
    samples_per_m2 : float
        Sampling density on the surface region that can be in contact.
    min_samples : int
        Fewest points drawn on a non-empty region (small pieces still get tested).
    seed : int
        Seed of the sampling generator.
    pairs : iterable of (str, str), optional
        Restrict to these body pairs (ids; ``room`` for the shell).

    Returns
    -------
    ContactSamples
    """
    thr = float(threshold)
    rng = np.random.default_rng(seed)
    allp = concatenate([b.pieces for b in bodies])
    body_of = np.repeat(np.arange(len(bodies)), [len(b.pieces) for b in bodies])
    keys = [f"{b.id}:{p}" for b in bodies for p in b.pieces.parts]  # in allp's order
    first = np.concatenate([[0], np.cumsum([len(b.pieces) for b in bodies])])
    want = None if pairs is None else {frozenset(p) for p in pairs}

    # piece pairs whose boxes come within the threshold
    src, tgt = [], []
    for i, j in _candidate_body_pairs(bodies, thr, want):
        bi = allp.bounds[first[i]:first[i + 1]]
        bj = allp.bounds[first[j]:first[j + 1]]
        ov = ((bi[:, None, 0] - thr <= bj[None, :, 1]) & (bj[None, :, 0] - thr <= bi[:, None, 1])
              ).all(-1)
        a, b = np.nonzero(ov)
        src.append(a + first[i])
        tgt.append(b + first[j])
    empty = ContactSamples(np.zeros((0, 3)), np.zeros(0), np.zeros(0, int), np.zeros(0, int),
                           keys, body_of)
    if not src:
        return empty
    pa, pb = np.concatenate(src), np.concatenate(tgt)
    if len(pa) == 0:
        return empty
    # one sampling group per (surface of one piece, box of the other), both directions
    g_src = np.concatenate([pa, pb])
    g_tgt = np.concatenate([pb, pa])
    g_lo = allp.bounds[g_tgt, 0] - thr
    g_hi = allp.bounds[g_tgt, 1] + thr

    # the source triangles that reach into the box
    ti = allp.tri_index
    counts = ti[g_src + 1] - ti[g_src]
    grp = np.repeat(np.arange(len(g_src)), counts)
    tri_id = np.arange(counts.sum()) + np.repeat(ti[g_src] - np.concatenate([[0], np.cumsum(counts)[:-1]]), counts)
    tris = allp.triangles[tri_id]
    tlo, thi = tris.min(axis=1), tris.max(axis=1)
    reach = ((tlo <= g_hi[grp]) & (g_lo[grp] <= thi)).all(-1)
    grp, tris = grp[reach], tris[reach]
    sub, areas = clip_triangles_to_boxes(tris, g_lo[grp], g_hi[grp])
    sub_grp = np.repeat(grp, sub.shape[1])
    sub = sub.reshape(-1, 3, 3)
    areas = areas.reshape(-1)
    nz = areas > 0
    sub, areas, sub_grp = sub[nz], areas[nz], sub_grp[nz]
    g_area = np.bincount(sub_grp, weights=areas, minlength=len(g_src))
    n = np.where(g_area > 0, np.maximum(min_samples, np.ceil(g_area * samples_per_m2)), 0)
    n = n.astype(int)

    # area-weighted choice of sub-triangle within each group, then uniform barycentrics
    csum = np.cumsum(areas)
    g_start = np.zeros(len(g_src))
    has = np.bincount(sub_grp, minlength=len(g_src)) > 0
    first_sub = np.searchsorted(sub_grp, np.arange(len(g_src)))
    g_start[has] = (csum - areas)[first_sub[has]]
    s_grp = np.repeat(np.arange(len(g_src)), n)
    u = rng.random(len(s_grp))
    t = g_start[s_grp] + u * g_area[s_grp]
    k = np.searchsorted(csum, t, side="right")
    k = np.clip(k, 0, len(csum) - 1)
    # guard against round-off sending a sample into the next group
    lo_k = first_sub[s_grp]
    hi_k = lo_k + np.bincount(sub_grp, minlength=len(g_src))[s_grp] - 1
    k = np.clip(k, lo_k, hi_k)
    r1, r2 = rng.random(len(k)), rng.random(len(k))
    sq = np.sqrt(r1)
    w0, w1, w2 = 1 - sq, sq * (1 - r2), sq * r2
    tri = sub[k]
    pts = tri[:, 0] * w0[:, None] + tri[:, 1] * w1[:, None] + tri[:, 2] * w2[:, None]

    # hull vertices inside the box
    vi = allp.vert_index
    vcount = vi[g_src + 1] - vi[g_src]
    v_grp = np.repeat(np.arange(len(g_src)), vcount)
    v_id = np.arange(vcount.sum()) + np.repeat(vi[g_src] - np.concatenate([[0], np.cumsum(vcount)[:-1]]), vcount)
    vp = allp.vertices[v_id]
    inb = ((vp >= g_lo[v_grp]) & (vp <= g_hi[v_grp])).all(-1)
    pts = np.concatenate([pts, vp[inb]])
    s_grp = np.concatenate([s_grp, v_grp[inb]])

    d = signed_distance(pts, g_tgt[s_grp], allp, cutoff=thr)
    keep = d <= thr
    return ContactSamples(pts[keep], d[keep], g_src[s_grp[keep]], g_tgt[s_grp[keep]], keys,
                          body_of)


def _aggregate(cs: ContactSamples) -> list[Contact]:
    if len(cs.distance) == 0:
        return []
    names, rank = np.unique(np.asarray(cs.keys), return_inverse=True)  # rank order = str order
    ra, rb = rank[cs.source], rank[cs.target]
    lo, hi = np.minimum(ra, rb), np.maximum(ra, rb)
    code = lo.astype(np.int64) * len(names) + hi
    uniq, inv, count = np.unique(code, return_inverse=True, return_counts=True)
    mind = np.full(len(uniq), np.inf)
    np.minimum.at(mind, inv, cs.distance)
    return [Contact(str(names[u // len(names)]), str(names[u % len(names)]), int(c), float(m))
            for u, c, m in zip(uniq, count, mind, strict=True)]


def extract_contacts(scene: Scene, *, threshold: float = DEFAULT_THRESHOLD,
                     samples_per_m2: float = DEFAULT_SAMPLES_PER_M2,
                     min_samples: int = DEFAULT_MIN_SAMPLES, seed: int = 0,
                     settled: bool | None = None,
                     pairs: Iterable[tuple[str, str]] | None = None) -> list[Contact]:
    """The scene's part-level contact graph as a sorted list of edges.

    Parameters
    ----------
    scene : Scene
        Objects are taken at their settled pose where they have one (see ``settled``).
    threshold : float
        Contact distance, metres (the paper's 1 mm).
    samples_per_m2 : float
        Surface sampling density, points per m^2.
    min_samples : int
        Fewest samples on any piece's surface region that may touch the other piece.
    seed : int
        Seed of the sampling generator (the result is deterministic for a seed).
    settled : bool or None
        Which pose to use: None takes the settled pose where present.
    pairs : iterable of (str, str), optional
        Only these object pairs (``room`` is the shell).

    Returns
    -------
    list of Contact
        One per touching part pair, ``a < b``, sorted; ``samples`` counts the samples of both
        surfaces, ``min_distance`` is the smallest signed distance (negative: interpenetration
        depth, metres).
    """
    only = None
    if pairs is not None:
        # bodies in no wanted pair only cost time: the samples of a pair do not depend on
        # which other bodies are present (same pieces, groups and random draws, in order)
        pairs = [tuple(p) for p in pairs]
        only = {x for p in pairs for x in p}
    bodies = scene_bodies(scene, settled=settled, only=only)
    if not bodies:
        return []
    cs = contact_samples(bodies, threshold=threshold, samples_per_m2=samples_per_m2,
                         min_samples=min_samples, seed=seed, pairs=pairs)
    return _aggregate(cs)


# ------------------------------------------------------------------- exact proximity (GJK)

class _Placed:
    """One body for :func:`touching_parts`: world piece boxes and FCL objects made on demand."""

    def __init__(self, key, pieces: ConvexSet, R: np.ndarray, t: np.ndarray, scale: float):
        import fcl

        self.key, self.pieces, self.scale = key, pieces, float(scale)
        verts = pieces.vertices @ (R * self.scale).T + t
        lo = np.minimum.reduceat(verts, pieces.vert_index[:-1], axis=0)
        hi = np.maximum.reduceat(verts, pieces.vert_index[:-1], axis=0)
        self.bounds = np.stack([lo, hi], 1)
        self._tf = fcl.Transform(np.asarray(R, float), np.asarray(t, float))
        self._objs: dict[int, Any] = {}

    def obj(self, i: int):
        import fcl

        o = self._objs.get(i)
        if o is None:
            if self.key is None:  # the room shell: world frame, no cache by asset
                g = fcl_convex(np.asarray(self.pieces.piece_vertices(i), float))
            else:
                g = fcl_piece(self.key, self.scale, i, self.pieces)
            o = self._objs[i] = fcl.CollisionObject(g, self._tf)
        return o


def touching_parts(scene: Scene, pairs: Iterable[tuple[str, str, str | None]], *,
                   threshold: float = DEFAULT_THRESHOLD,
                   settled: bool | None = None) -> set[tuple[str, str, str | None]]:
    """Which objects come within ``threshold`` of a part of another body: exact convex
    distances (GJK, FCL) between collision pieces, no sampling.

    A contact edge of :func:`extract_contacts` implies the same pair here (a sample within
    the threshold is a point of one piece that close to the other); the converse can miss
    only where sampling misses a region smaller than its spacing.

    Parameters
    ----------
    scene : Scene
    pairs : iterable of (str, str, str or None)
        ``(object id, other body id, part name)``: the other body is an object id or
        ``room``; part None means any part of it.
    threshold : float
        Metres.
    settled : bool or None
        Which pose to use (None: the settled one where present).

    Returns
    -------
    set of (str, str, str or None)
        The given triples whose bodies touch (overlap counts as touching).
    """
    import fcl

    pairs = list(pairs)
    want = {x for a, b, _ in pairs for x in (a, b)}
    bodies: dict[str, _Placed] = {}
    for oid in want:
        if oid == ROOM:
            sh = shell_collision(scene.room)
            bodies[oid] = _Placed(None, sh, np.eye(3), np.zeros(3), 1.0)
            continue
        obj = scene.objects.get(oid)
        if obj is None or not obj.placed or obj.asset is None:
            continue
        data = asset_collision(obj.asset)
        T = obj.transform(settled)
        bodies[oid] = _Placed(_asset_key(obj.asset), data.pieces, T[:3, :3] / obj.scale,
                              T[:3, 3], obj.scale)
    thr = float(threshold)
    request = fcl.DistanceRequest()
    out = set()
    for a, b, part in pairs:
        A, B = bodies.get(a), bodies.get(b)
        if A is None or B is None:
            continue
        jb = np.arange(len(B.pieces))
        if part is not None:
            jb = jb[np.asarray(B.pieces.parts) == part]
        ba, bb = A.bounds, B.bounds[jb]
        near = ((ba[:, None, 0] - thr <= bb[None, :, 1]) & (bb[None, :, 0] - thr <= ba[:, None, 1])
                ).all(-1)
        for i, j in zip(*np.nonzero(near), strict=True):
            d = fcl.distance(A.obj(int(i)), B.obj(int(jb[j])), request, fcl.DistanceResult())
            if d <= thr:
                out.add((a, b, part))
                break
    return out


# ------------------------------------------------------------------------------- outputs


def contacts_to_json(contacts: Iterable[Contact]) -> list[dict[str, Any]]:
    """``contacts.json`` content (DESIGN §5): ``[{"a", "b", "samples", "min_distance"}, ...]``."""
    return [c.to_dict() for c in contacts]


def contacts_from_json(data: Iterable[dict[str, Any]]) -> list[Contact]:
    """Inverse of :func:`contacts_to_json`."""
    return [Contact(str(d["a"]), str(d["b"]), int(d["samples"]), float(d["min_distance"]))
            for d in data]


def contact_graph(contacts: Iterable[Contact]) -> nx.Graph:
    """The contact graph: nodes ``object:part`` (attributes ``object``, ``part``, ``room``),
    edges carrying ``samples`` and ``min_distance``."""
    import networkx as nx

    g = nx.Graph()
    for c in contacts:
        for key in (c.a, c.b):
            if key not in g:
                obj, part = key.split(":", 1)
                g.add_node(key, object=obj, part=part, room=obj == ROOM)
        g.add_edge(c.a, c.b, samples=c.samples, min_distance=c.min_distance)
    return g
