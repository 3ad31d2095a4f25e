"""How near a part comes to a face *within the face's extent* (not its infinite plane).

A book leaning on a box touches the box's side face only where the book is in front of that
face: 12 cm beside the box it touches nothing, and above the box's top its upper edge may pass
beyond the face's plane (it rests on the box's top edge). :func:`nearest_in_prism` measures the
smallest signed distance to a face's plane over the child's convex pieces clipped to the prism
the face sweeps along its normal; both the ``LEANING_AGAINST`` check and the solver's leaning
placement use it, so what the solver builds is what the check accepts.

The minimum of a linear function over a convex piece clipped by slabs is reached at a vertex of
the clipped piece: a vertex of the piece inside the slabs, an edge of the piece crossing a slab
plane, or (with two slab directions) a line where two slab planes meet, entering or leaving the
piece. All three are enumerated exactly.
"""

from __future__ import annotations

import numpy as np

__all__ = ["piece_data", "nearest_in_prism", "face_slabs", "lean_range", "WIDE_LEAN_DEG",
           "stands_to_lean", "STAND", "THIN_SHARE", "standing_label", "lean_up",
           "pieces_distance", "mounted_parts", "MOUNTED_DEPTH"]

#: Tilts (degrees) a child may lean at against an object's face when the PAG gives no
#: ``angle_deg``: the default range is tried first, then this one (a pillow slumped against a
#: headboard, a book against a short box). The check accepts the same range.
WIDE_LEAN_DEG = (4.0, 35.0)


def lean_range(edge, parent_is_object: bool) -> tuple[float, float]:
    """The tilt range (degrees) a leaning child may take: ``angle_deg`` as written, or, not
    written and leaning on an object, :data:`WIDE_LEAN_DEG` widened to include the default."""
    lo, hi = edge.param("angle_deg")
    if parent_is_object and "angle_deg" not in edge.params:
        return min(lo, WIDE_LEAN_DEG[0]), max(hi, WIDE_LEAN_DEG[1])
    return lo, hi

_DATA: dict[tuple, list] = {}


def piece_data(asset, parts) -> list[tuple]:
    """``[(vertices, faces, edges, planes, offsets)]`` of the parts' convex pieces in the asset
    frame (cached per asset and part names; ``planes @ x <= offsets`` inside); parts without
    pieces give their mesh vertices as one piece with no faces (vertices only)."""
    key = (asset.asset_id, tuple(p.name for p in parts))
    got = _DATA.get(key)
    if got is None:
        if len(_DATA) > 4096:
            _DATA.clear()
        got = []
        none = (np.zeros((0, 3), int), np.zeros((0, 2), int), np.zeros((0, 3)), np.zeros(0))
        for p in parts:
            pieces = p.piece_arrays
            if not pieces:
                got.append((np.asarray(p.vertices, float), *none))
                continue
            for pc in pieces:
                V = np.asarray(pc.vertices, float)
                F = np.asarray(pc.faces, int).reshape(-1, 3)
                if not len(F):
                    got.append((V, *none))
                    continue
                E = np.unique(np.sort(np.vstack([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]),
                                      axis=1), axis=0)
                A, d = _planes(V, F)
                got.append((V, F, E, A, d))
        _DATA[key] = got
    return got


def _planes(V: np.ndarray, F: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Outward unit normals ``A`` and offsets ``d`` (``A x <= d`` inside) of a convex piece."""
    a, b, c = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    n = np.cross(b - a, c - a)
    ln = np.linalg.norm(n, axis=1)
    keep = ln > 1e-12
    n, a = n[keep] / ln[keep, None], a[keep]
    flip = ((V.mean(axis=0) - a) * n).sum(axis=1) > 0
    n[flip] *= -1
    return n, (n * a).sum(axis=1)


_PACKED: dict[int, tuple] = {}


def _packed(pieces) -> tuple[np.ndarray, np.ndarray, list[int]]:
    """All vertices of ``pieces`` stacked, ``(N, 3)``, where each piece starts, ``(P,)``, and
    the P + 1 bounds as ints: made once per pieces list (the lists of :func:`piece_data` are
    cached and reused)."""
    got = _PACKED.get(id(pieces))
    if got is not None and got[0] is pieces:
        return got[1]
    if len(_PACKED) > 4096:
        _PACKED.clear()
    V = np.vstack([pc[0] for pc in pieces]) if pieces else np.zeros((0, 3))
    cuts = np.cumsum([0] + [len(pc[0]) for pc in pieces]).astype(np.intp)
    out = (V, cuts[:-1], cuts.tolist())
    _PACKED[id(pieces)] = (pieces, out)  # holding the list keeps its id valid
    return out


def nearest_in_prism(pieces, T: np.ndarray, normal: np.ndarray, origin: np.ndarray,
                     slabs: list[tuple[np.ndarray, float, float]], band: float | None = None):
    """Smallest signed distance ``(x - origin) . normal`` over the pieces (asset frame, moved
    by the 4x4 ``T``) clipped to ``lo <= x . a <= hi`` for each ``(a, lo, hi)`` in ``slabs``
    (at most two directions, each perpendicular to ``normal``); ``(distance, point)``, or
    ``None`` when no piece reaches into the prism. With ``band``, ``(distance, point,
    points)``: also the (K, 3) candidate points within ``band`` of the smallest distance (the
    band of the child that touches)."""
    M, t0 = T[:3, :3], T[:3, 3]
    if not pieces:
        return None
    Vall, starts, cuts = _packed(pieces)
    W = Vall @ M.T + t0
    lower = np.minimum.reduceat((W - origin) @ normal, starts)
    lo_box, hi_box = np.minimum.reduceat(W, starts), np.maximum.reduceat(W, starts)
    # pieces whose box misses a slab reach nothing in the prism
    live = np.ones(len(starts), bool)
    half, mid = (hi_box - lo_box) / 2, (hi_box + lo_box) / 2
    for a, lo, hi in slabs:
        r, c = half @ np.abs(a), mid @ a
        live &= (c + r >= lo - 1e-7) & (c - r <= hi + 1e-7)
    order = np.argsort(lower, kind="stable")
    order = order[live[order]].tolist()
    if not order:
        return None
    low = lower.tolist()
    corners = _slab_corners(slabs, M, t0)
    keep_x, keep_d = [], []
    best = np.inf
    margin = 0.0 if band is None else band
    for i in order:
        if low[i] > best + margin:
            break  # no point of this piece (or the rest) comes nearer
        X = _clipped_candidates(W[cuts[i]:cuts[i + 1]], pieces[i], slabs, corners, M, t0)
        if X is None:
            continue
        dist = (X - origin) @ normal
        keep_x.append(X)
        keep_d.append(dist)
        best = min(best, float(dist.min()))
    if not keep_x:
        return None
    X, dist = np.vstack(keep_x), np.concatenate(keep_d)
    k = int(np.argmin(dist))
    if band is None:
        return float(dist[k]), X[k]
    return float(dist[k]), X[k], X[dist <= dist[k] + band]


def _slab_corners(slabs, M: np.ndarray, t0: np.ndarray) -> list:
    """With two slab directions, the four lines where their planes meet, in the asset frame:
    ``[(point, direction)]``."""
    if len(slabs) != 2:
        return []
    w, points = _slab_lines(slabs)
    if w is None:
        return []
    Mi = np.linalg.inv(M)
    wl = Mi @ w
    return [(Mi @ (P - t0), wl) for P in points]


_LINES: dict[tuple, tuple] = {}


def _slab_lines(slabs) -> tuple:
    """``(w, points)`` of two slabs: the direction ``w`` of the lines where their planes meet
    and a world point on each of the four (None, [] when the slabs are parallel); kept per
    slabs (a face is checked again and again at other poses of the child)."""
    (a1, l1, h1), (a2, l2, h2) = slabs
    key = (np.asarray(a1, float).tobytes(), np.asarray(a2, float).tobytes(), l1, h1, l2, h2)
    got = _LINES.get(key)
    if got is None:
        w = np.cross(a1, a2)
        if np.linalg.norm(w) > 1e-9:
            S = np.array([a1, a2, w])
            got = (w, [np.linalg.solve(S, [c1, c2, 0.0]) for c1 in (l1, h1) for c2 in (l2, h2)])
        else:
            got = (None, [])
        if len(_LINES) > 4096:
            _LINES.clear()
        _LINES[key] = got
    return got


def _clipped_candidates(V: np.ndarray, piece, slabs, corners, M: np.ndarray, t0: np.ndarray):
    """The candidate vertices (world, ``(K, 3)``) of one posed piece ``V`` clipped to the
    slabs (:func:`nearest_in_prism`), or None when none lies inside."""
    _, _, E, A, d = piece
    cands = [V]
    for a, lo, hi in slabs:  # edges crossing a slab plane
        if not len(E):
            continue
        p, q = V[E[:, 0]], V[E[:, 1]]
        sp, sq = p @ a, q @ a
        for c in (lo, hi):
            m = (sp - c) * (sq - c) < 0
            if m.any():
                tt = (c - sp[m]) / (sq[m] - sp[m])
                cands.append(p[m] + tt[:, None] * (q[m] - p[m]))
    if corners and len(A):
        for p0, wl in corners:
            aw, r = A @ wl, d - A @ p0
            if np.any((np.abs(aw) < 1e-12) & (r < -1e-9)):
                continue
            pos, neg = aw > 1e-12, aw < -1e-12
            t1 = np.min(r[pos] / aw[pos]) if pos.any() else np.inf
            tb = np.max(r[neg] / aw[neg]) if neg.any() else -np.inf
            if tb <= t1 and np.isfinite(tb) and np.isfinite(t1):
                ends = np.array([p0 + tb * wl, p0 + t1 * wl])
                cands.append(ends @ M.T + t0)
    X = np.vstack(cands)
    inside = np.ones(len(X), bool)
    for a, lo, hi in slabs:
        sa = X @ a
        inside &= (sa >= lo - 1e-7) & (sa <= hi + 1e-7)
    return X[inside] if inside.any() else None


def face_slabs(surface, grow: float = 1e-3) -> list[tuple[np.ndarray, float, float]]:
    """The two slabs ``(a, lo, hi)`` of a (world) surface's polygon bounds along its in-plane
    axes, grown by ``grow``: the prism of :func:`nearest_in_prism` for that face."""
    x0, y0, x1, y1 = surface.polygon.bounds
    o = surface.origin
    return [(surface.u, float(o @ surface.u + x0 - grow), float(o @ surface.u + x1 + grow)),
            (surface.v, float(o @ surface.v + y0 - grow), float(o @ surface.v + y1 + grow))]


#: A child is flat when its height is at most this share of its smaller horizontal extent.
THIN_SHARE = 0.5
#: The turn (asset frame) that stands a flat child on its front edge, its bottom facing back:
#: a rotation of -90 degrees about its x axis.
STAND = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])


def stands_to_lean(asset, pag, oid: str) -> bool:
    """Whether a leaning child is flat (a pillow, a cushion, a tray, a plate: its height at
    most :data:`THIN_SHARE` of its smaller horizontal extent) and so stands on its front edge
    to lean, its large face toward the parent: ``pillow@back`` then means its bottom face
    (``@front`` its top). The solver poses it so and the checks read it so."""
    if asset is None or not any(e.relation == "LEANING_AGAINST" and e.child.object == oid
                                and (e.child.surface or "back") in ("back", "front")
                                for e in pag.edges_of(oid)):
        return False
    from .geometry import asset_geometry

    ext = np.ptp(asset_geometry(asset).bounds, axis=0)
    return bool(ext[2] <= THIN_SHARE * min(ext[0], ext[1]))


def lean_up(asset, pag, oid: str) -> np.ndarray:
    """The asset-frame axis a leaning child's tilt is measured from (its up, standing
    untilted): its back for a flat child standing on its front edge (:func:`stands_to_lean`);
    the opposite of the side it is written ``ON`` or ``IN`` by (a plate ``ON`` its
    ``rim@front``, its underside leaning on a hutch's back panel, stands on its edge: the
    solver turns that side down before it tilts); else its top."""
    if stands_to_lean(asset, pag, oid):
        return np.array([0.0, -1.0, 0.0])
    sup = pag.supporter(oid)
    label = None if sup is None or sup.relation not in ("ON", "IN") else \
        sup.child.surface or sup.spec.child_surface
    if label in ("front", "back", "left", "right"):
        from ..relations import SURFACES

        return -np.array(SURFACES[label], float)
    return np.array([0.0, 0.0, 1.0])


def standing_label(label: str) -> str:
    """The asset surface a flat child standing on its front edge shows as ``label``."""
    return {"back": "bottom", "front": "top", "bottom": "front", "top": "back"}.get(label, label)


_FCL: dict[tuple, list] = {}


def _fcl_pieces(pieces, scale: float) -> tuple[list, np.ndarray]:
    """FCL convex shapes of ``pieces`` scaled by ``scale`` (FCL moves rigidly only) and the 8
    corners of each one's box, ``(P, 8, 3)``, made once per pieces list and scale."""
    import fcl

    key = (id(pieces), round(float(scale), 9))
    got = _FCL.get(key)
    if got is not None and got[0] is pieces:
        return got[1]
    if len(_FCL) > 4096:
        _FCL.clear()
    out = []
    for V0, F, *_ in pieces:
        if not len(F):
            continue
        V = np.asarray(V0, float) * scale
        lo, hi = V.min(axis=0), V.max(axis=0)
        corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                            for z in (lo[2], hi[2])])
        geom = fcl.Convex(V, len(F), np.c_[np.full(len(F), 3), F].ravel().astype(np.int32))
        out.append((geom, corners))
    out = ([g for g, _ in out], np.stack([c for _, c in out]) if out else np.zeros((0, 8, 3)))
    _FCL[key] = (pieces, out)  # holding the list keeps its id valid
    return out


_POSED: dict[tuple, tuple] = {}


def _posed(pieces, T: np.ndarray) -> tuple:
    """``(shapes, box lows, box highs, R, t)`` of ``pieces`` moved by the similarity ``T``:
    FCL shapes at ``T``'s scale, their boxes in the world and ``T``'s rotation and translation
    (kept for the latest poses: a bisection moves one set against the same other set)."""
    key = (id(pieces), np.asarray(T, float).tobytes())
    got = _POSED.get(key)
    if got is not None and got[0] is pieces:
        return got[1]
    s = float(np.cbrt(abs(np.linalg.det(T[:3, :3]))))
    R, t = T[:3, :3] / s, np.array(T[:3, 3], float)
    shapes, corners = _fcl_pieces(pieces, s)
    if not shapes:
        out = [], np.zeros((0, 3)), np.zeros((0, 3)), R, t
    else:
        C = corners @ R.T + t
        out = shapes, C.min(axis=1), C.max(axis=1), R, t
    if len(_POSED) > 256:
        _POSED.clear()
    _POSED[key] = (pieces, out)  # holding the list keeps its id valid
    return out


def pieces_distance(pieces_a, T_a: np.ndarray, pieces_b, T_b: np.ndarray,
                    limit: float = 0.01) -> float:
    """Exact distance (GJK, FCL) between two sets of convex pieces (asset frames, moved by the
    4x4 similarity transforms), 0 where they overlap; ``inf`` beyond ``limit`` (boxes apart)."""
    import fcl

    ga, la, ha, Ra, ta = _posed(pieces_a, T_a)
    gb, lb, hb, Rb, tb = _posed(pieces_b, T_b)
    if not ga or not gb:
        return np.inf
    near = np.all((la[:, None, :] <= hb[None, :, :] + limit)
                  & (lb[None, :, :] <= ha[:, None, :] + limit), axis=2)
    if not near.any():
        return np.inf
    best = np.inf
    req = fcl.DistanceRequest()
    Ta, Tb = fcl.Transform(Ra, ta), fcl.Transform(Rb, tb)
    oa: dict[int, object] = {}
    ob: dict[int, object] = {}
    for i, j in zip(*np.nonzero(near), strict=True):
        a = oa.get(i) or oa.setdefault(i, fcl.CollisionObject(ga[i], Ta))
        b = ob.get(j) or ob.setdefault(j, fcl.CollisionObject(gb[j], Tb))
        d = fcl.distance(a, b, req, fcl.DistanceResult())
        best = min(best, max(float(d), 0.0))
        if best == 0.0:
            return 0.0
    return best


#: Share of a face a mounted part must cover for what leans on the face to rest on it.
COVERING = 0.3
#: Metres in front of a face within which a parent's other parts count as mounted on it (an
#: amplifier's grille and knobs on its cabinet's front).
MOUNTED_DEPTH = 0.03


def mounted_parts(parent, face_parts, surface, T: np.ndarray) -> tuple[list, float]:
    """The parent's parts mounted on a face (other parts within :data:`MOUNTED_DEPTH` in front
    of its plane and over its extent: an amplifier's grille and knobs on its cabinet's front),
    and how far the frontmost of those covering at least :data:`COVERING` of the face reaches
    in front of its plane (the grille, not a knob; 0 with none). ``T``: the parent's pose."""
    T = np.asarray(T, float)
    key = (id(parent.asset), tuple(p.name for p in face_parts), T.tobytes(),
           np.asarray(surface.origin, float).tobytes(), np.asarray(surface.normal, float).tobytes(),
           np.asarray(surface.u, float).tobytes(), np.asarray(surface.v, float).tobytes(),
           surface.polygon.bounds, float(surface.area))
    got = _MOUNTED.get(key)
    if got is not None and got[0] is parent.asset:
        return list(got[1]), got[2]
    own = {p.name for p in face_parts}
    slabs = face_slabs(surface)
    out, front = [], 0.0
    for p in parent.asset.parts:
        if p.name in own:
            continue
        V = np.vstack([pc.vertices for pc in p.piece_arrays] or [p.vertices])
        P = V @ T[:3, :3].T + T[:3, 3]
        h = (P - surface.origin) @ surface.normal
        if float(h.min()) < -0.005 or float(h.max()) > MOUNTED_DEPTH or float(h.max()) <= 1e-4:
            continue
        if any(float((P @ a).max()) < lo or float((P @ a).min()) > hi for a, lo, hi in slabs):
            continue
        out.append(p)
        (u0, u1), (v0, v1) = ((float((P @ a).min()), float((P @ a).max())) for a, _, _ in
                              slabs[:2])
        if (u1 - u0) * (v1 - v0) >= COVERING * surface.area:
            front = max(front, float(h.max()))
    if len(_MOUNTED) > 1024:
        _MOUNTED.clear()
    _MOUNTED[key] = (parent.asset, tuple(out), front)  # the asset held keeps its id valid
    return out, front


#: :func:`mounted_parts` per parent asset, face parts, pose and face (a face is checked again
#: for every pose of what leans on it).
_MOUNTED: dict[tuple, tuple] = {}
