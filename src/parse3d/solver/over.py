"""Soft things over a bar: a throw over an armchair's back, a towel over an oven's handle or a
tub's rim, a backpack by its straps over a chair's back.

People write a soft thing ``ON`` the narrow top of a part (``ON throw -> armchair:back@top``)
or ``HANGING_BELOW`` it (``HANGING_BELOW backpack -> chair:back@top``, ``HANGING_BELOW towel ->
stove@front``, ``HANGING_BELOW towel -> vanity:handle_0@bottom``) and mean the same thing: it
hangs *over* that part, its middle on the part's top, the rest falling down one side within the
part's length. Neither relation can be met as written (the top is too narrow to lie on, and no
surface of it faces down), so the child is placed the way the writer meant, the written
relation recorded relaxed with that reading:

- **the child is soft** (:func:`soft`): cloth (its largest part is of a draping material and
  thin, :data:`THIN_CLOTH`: a throw, a towel, a shirt; not a cushion) or a bag with straps
  (:data:`STRAPS`: a backpack, a tote);
- **the part is a bar** (:func:`bar_of`): its top, the part's points within :data:`TOP_BAND`
  of its highest, is narrower than the child lying flat and than :data:`BAR_WIDE` (``ON``), or
  any part named for ``HANGING_BELOW`` by a surface that does not face down, or a handle or a
  knob on a door or a drawer (``@bottom``, :func:`_on_a_door`; any rod or knob once hanging below
  it as written found no room, :func:`over_after`); an object named by a side
  (``stove@front``) hangs it on the rod-like part (a handle) furthest along that side;
- **the pose** (:func:`place_over`): the child hangs edge-up, its thin side against the bar's
  outer face, its top level with the bar's top, down the side away from the parent's centre
  (or the side the writer named; the other side when that one is blocked), out over what of
  the parent or on it stands about as high as the bar on that side (:func:`_high_pieces`: a
  sofa's back frame, the pillows leaning on its back cushions), never through a wall; a strap
  bag hangs upright, its straps toward the bar. A child longer than the bar, or taller than
  the bar is high above what it may reach down to (:func:`_hang_floor`: the floor, a sofa's
  seat), is shown folded: scaled down to fit (never below its category's size range), the size
  recorded in the reason. It is fixed where it hangs, like everything hung, so settling keeps
  it held.

A roll (:func:`_core`: a toilet roll) ``HANGING_BELOW`` a rod hangs threaded on it, its core
around the rod (:func:`threaded_edge`), not below it where the toilet beside it is in the way.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..assets.model import Asset
from ..measure.checks import EPS, world_points
from ..pag.model import Edge
from ..pag.refs import format_ref
from ..relations import SURFACES
from ..scene.model import PlacedObject, SupportChoice
from .config import Fail
from .geometry import asset_geometry
from .hanging import ROD_LONG, ROD_THICK, drapes
from .rules.layout import relaxed_to_nearest
from .state import SolveState, parts_for
from .support import Support, filled, support_candidates
from .validation import relations_and_collisions

__all__ = ["OverEdge", "over_after", "over_edge", "place_over", "soft", "bar_of",
           "threaded_edge", "BAR_WIDE", "CLOTH", "CORES", "KNOB", "STRAPS",
           "THIN_CLOTH", "TOP_BAND"]

#: Metres: cloth is thin: the thinnest extent of its largest part (a folded throw's layer, a
#: towel) is at most this (a cushion or a pillow is thicker).
THIN_CLOTH = 0.08
#: Materials of cloth that hangs over a bar (not paper: a book, a paper bag).
CLOTH = frozenset({"fabric", "leather"})
#: Part labels of a roll's core: a roll hangs threaded on a rod through it.
CORES = ("core", "tube")
#: Part labels of a bag's straps or handles: a bag that has one hangs by it.
STRAPS = ("strap", "straps", "shoulder_strap", "handle", "handles")
#: Metres below a part's highest point within which its points make its top (a chair back's
#: top rail, an armrest's upper face).
TOP_BAND = 0.02
#: Metres: a part no larger than this in any direction is a knob: a towel hangs over it.
KNOB = 0.06
#: Metres: a top at most this wide is a bar or a ledge (a chair back's rail, an armrest, a tub's
#: rim), not a table's top.
BAR_WIDE = 0.25
#: Metres from a part's side, as a share of the object's extent, within which a rod-like part
#: lies on that side (an oven's handle on its front).
SIDE_SHARE = 0.25
#: A top shorter than this multiple of its width, or than the part is tall, is a post's or an
#: upright handle's end: the child hangs along the parent's face it stands out from.
SQUARE = 2.0
#: Metres below a bar's top within which the parent's pieces on the side the child hangs
#: down stand as high as the bar: the child hangs over them too (a sofa's back frame a few
#: centimetres below its back cushions' tops), not into them.
HIGH = 0.1
#: Metres out from the face a child hangs down within which what lies below it is in its way.
NEAR_FACE = 0.15
#: Metres: what hangs over a bar keeps this far above the floor.
FLOOR_CLEAR = 0.03
#: Metres the child is moved out from the bar's face, in turn, when something of the parent
#: below the top (a reclined back, a rocking chair's runners) is in the way.
STEPS = (0.0, 0.01, 0.025, 0.045, 0.07, 0.1)


class OverEdge(Edge):
    """A ``HANGING_BELOW`` edge meaning "hangs over the bar": placed by :func:`place_over`,
    never by the support surfaces of its parent reference."""


def soft(asset: Asset, scale: float) -> str | None:
    """``"strap"`` for a draping bag of :data:`CLOTH` with a strap or handle part (a
    backpack), ``"cloth"`` for thin cloth (:data:`THIN_CLOTH` at ``scale``), else None."""
    if not drapes(asset):
        return None
    if asset.parts and _largest(asset).material.name not in CLOTH:
        return None  # a book's paper does not hang over a bar
    if any(p.label in STRAPS for p in asset.parts):
        return "strap"
    best = _largest(asset)
    thin = float(np.min(np.ptp(np.asarray(best.bounds, float), axis=0))) * scale
    return "cloth" if thin <= THIN_CLOTH else None


def _largest(asset: Asset):
    """The asset's largest part by bounding box (what :func:`drapes` reads)."""
    return max(asset.parts, key=lambda p: float(np.prod(np.ptp(np.asarray(p.bounds, float),
                                                             axis=0))))


def _world_vertices(parent, part) -> np.ndarray:
    T = parent.transform()
    v = np.asarray(part.mesh.vertices, float)
    return v @ T[:3, :3].T + T[:3, 3]


def _is_rod(parent, part, knob: bool = True) -> bool:
    """Whether a part is a rod (no thicker than :data:`ROD_THICK` across, at least half
    :data:`ROD_LONG` times longer: a handle, a bar) or, with ``knob``, a knob (no extent over
    :data:`KNOB`)."""
    ext = np.sort(np.ptp(np.asarray(part.bounds, float), axis=0)) * parent.scale
    return bool(ext[1] <= ROD_THICK and ext[2] >= ROD_LONG * max(ext[1], 1e-6) * 0.5
                or knob and ext[2] <= KNOB)


def _on_a_door(asset: Asset, part) -> bool:
    """Whether ``part`` moves with a door, a drawer or a lid (a joint moves it: a vanity's
    handle or knob), not a hook made to hang things below it (a coat rack's, a pegboard's)."""
    return any(j.child_part == part.name for j in asset.joints)


def _side_rod(parent, side: str):
    """``(part, index)`` of the rod-like part furthest along the parent's ``side`` (an oven's
    handle on its front; the highest of those as far), within :data:`SIDE_SHARE` of its extent
    from that side; None when there is none."""
    n = np.asarray(SURFACES[side], float)
    lo, hi = np.asarray(parent.asset.bounds, float)
    far = float(np.max(np.array([lo, hi]) @ n))
    span = float(abs((hi - lo) @ n))
    best, at = None, (-np.inf, -np.inf)
    for p in parent.asset.parts:
        if not _is_rod(parent, p, knob=False):
            continue
        b = np.mean(np.asarray(p.bounds, float), axis=0)
        c = float(b @ n)
        key = (round(c, 2), float(b[2]))  # the highest of those as far out (an oven's top door)
        if c >= far - SIDE_SHARE * span and key > at:
            best, at = p, key
    if best is None:
        return None
    same = parent.asset.parts_by_label(best.label)
    return best, next(i for i, q in enumerate(same) if q is best)


def bar_of(st: SolveState, edge: Edge, asset: Asset, scale: float, *, after: bool = False):
    """The bar ``edge``'s soft child hangs over: ``(ref, parts, side)`` with the reference of
    the bar's part (surface ``top``), its parts and the world direction the writer named (or
    None); None when ``edge`` does not read as "over a bar" (module docstring). ``after``:
    hanging below a rod as written failed (:func:`over_after`), any rod reads so."""
    if edge.relation not in ("ON", "HANGING_BELOW") or edge.parent.is_room_element:
        return None
    parent = st.scene.objects.get(edge.parent.object)
    if parent is None or not parent.placed or parent.asset is None:
        return None
    if soft(parent.asset, parent.scale) is not None:
        return None  # soft on soft (a towel ON a folded towel): a stack, lying as written
    ref = edge.parent
    surface = ref.surface or edge.spec.parent_surface
    side = None
    if ref.part is None:
        if edge.relation != "HANGING_BELOW" or surface not in ("front", "back", "left", "right"):
            return None
        got = _side_rod(parent, surface)
        if got is None:
            return None
        part, index = got
        ref = replace(ref, part=part.label, index=index, surface="top",
                      text=format_ref(ref.object, part.label, index, "top"))
        side = parent.rotation @ np.asarray(SURFACES[surface], float)
        return ref, [part], side, _top(parent, part)
    parts = parts_for(parent.asset, ref)
    if not parts:
        return None
    if edge.relation == "HANGING_BELOW" and ref.index is None and len(parts) > 1:
        # a label several parts share (a range's handles: the oven door's and the drawer's
        # below it): over the highest, which leaves the most room to hang
        parts = sorted(parts, key=lambda p: -_top(parent, p)[0])
    top = _top(parent, parts[0])
    if edge.relation == "HANGING_BELOW":
        if surface == "bottom" and not (
                all(_is_rod(parent, p) and (after or _on_a_door(parent.asset, p))
                    for p in parts)):
            return None  # a shelf's underside, a towel bar: hung below it as written
    else:
        if surface != "top":
            return None
        top = _region_top(st, edge) or top
        if top[2] >= min(hull_lying(asset, scale), BAR_WIDE):
            return None  # a table's top, or it fits lying flat: ON as written
    if surface in ("front", "back", "left", "right"):
        side = parent.rotation @ np.asarray(SURFACES[surface], float)
    ref = replace(ref, surface="top", text=format_ref(ref.object, ref.part, ref.index, "top"))
    return ref, parts, side, top


def hull_lying(asset: Asset, scale: float) -> float:
    """The shorter side (m) of ``asset``'s footprint lying on its largest face."""
    ext = np.sort(np.ptp(asset_geometry(asset).hull, axis=0)) * scale
    return float(ext[1])


def _region_top(st: SolveState, edge: Edge):
    """``(z, centre, width, length, axis, part)`` of the widest upward support surface
    ``edge`` (``ON`` a part's top) resolves to (a tub's rim beside the wall: a strip, not the
    ring its points make), as :func:`_top`, with the name of its part; None when it resolves
    to none."""
    from shapely.geometry import Point

    try:
        sups = support_candidates(st, edge)
    except Fail:
        return None
    best = None
    for sp in sups:
        s = sp.surface
        if sp.region.is_empty or float(s.normal[2]) < 0.9 or sp.ring or sp.spans:
            # a ring round an opening spans it (bars.py), and the hull of like parts at one
            # level (an armchair's two armrests) spans the gap between them: no top to lie on
            continue
        rect = sp.region.minimum_rotated_rectangle
        if rect.geom_type != "Polygon":
            continue
        q = np.asarray(rect.exterior.coords)[:4]
        e0, e1 = q[1] - q[0], q[2] - q[1]
        l0, l1 = float(np.linalg.norm(e0)), float(np.linalg.norm(e1))
        e = e0 if l0 >= l1 else e1
        a = (e[0] * s.u + e[1] * s.v)[:2]
        a = a / max(float(np.linalg.norm(a)), 1e-9)
        m = rect.centroid if isinstance(rect.centroid, Point) else None
        c = (s.origin + m.x * s.u + m.y * s.v) if m is not None else s.origin
        got = (float(c[2]), np.asarray(c[:2], float), min(l0, l1), max(l0, l1), a,
               sp.choice.part)
        if best is None or got[2] > best[2]:
            best = got
    return best


def _top(parent, part):
    """``(z, centre, width, length, axis, part)`` of a part's top: its points within
    :data:`TOP_BAND` of its highest, their footprint's narrower side ``width`` across the
    unit horizontal ``axis`` along its length; ``part`` its name."""
    import shapely
    from shapely.geometry import MultiPoint

    V = _world_vertices(parent, part)
    z = float(V[:, 2].max())
    top = V[V[:, 2] >= z - TOP_BAND]
    rect = MultiPoint([tuple(p) for p in top[:, :2]]).minimum_rotated_rectangle
    if rect.geom_type != "Polygon":
        xy = top[:, :2]
        c = xy.mean(axis=0)
        d = xy.max(axis=0) - xy.min(axis=0)
        k = int(np.argmax(d))
        axis = np.eye(2)[k]
        return z, c, float(d[1 - k]), float(d[k]), axis, part.name
    pts = np.asarray(rect.exterior.coords)[:4]
    e0, e1 = pts[1] - pts[0], pts[2] - pts[1]
    l0, l1 = float(np.linalg.norm(e0)), float(np.linalg.norm(e1))
    axis = e0 / max(l0, 1e-9) if l0 >= l1 else e1 / max(l1, 1e-9)
    c = np.asarray(shapely.centroid(rect).coords[0])
    return z, c, min(l0, l1), max(l0, l1), axis, part.name


def _along_face(parent, c: np.ndarray) -> np.ndarray:
    """The unit horizontal along the parent's face nearest ``c`` (world x, y): across the
    parent's own x or y axis, whichever ``c`` lies furthest along from its centre."""
    R = np.asarray(parent.rotation, float)
    d = R.T @ np.r_[np.asarray(c, float) - np.asarray(parent.position, float)[:2], 0.0]
    k = 0 if abs(d[0]) >= abs(d[1]) else 1
    a = R[:, 1 - k][:2]
    return a / max(float(np.linalg.norm(a)), 1e-9)


def _core(asset: Asset):
    """``(axis, centre)`` of a roll's core (a part labelled in :data:`CORES`, round across its
    longest extent: a toilet roll's cardboard tube), in the asset's frame at unit scale;
    None for anything else."""
    for p in asset.parts:
        if p.label not in CORES:
            continue
        b = np.asarray(p.bounds, float)
        ext = np.ptp(b, axis=0)
        k = int(np.argmax(ext))
        other = np.delete(ext, k)
        if abs(float(other[0] - other[1])) <= 0.15 * float(other.max()):
            return k, b.mean(axis=0), float(other.min())
    return None


def threaded_edge(st: SolveState, oid: str, edge: Edge, asset: Asset, scale: float
                  ) -> tuple[OverEdge, float, str] | None:
    """For a roll (:func:`_core`) ``HANGING_BELOW`` a rod (a toilet roll below its holder's
    bar): the edge it is placed by, threaded on the rod (its core around it, as a real roll
    hangs: not below the bar, where the toilet under it is in the way), and why the edge as
    written is recorded relaxed; None for anything else."""
    if edge.relation != "HANGING_BELOW" or edge.parent.is_room_element \
            or edge.parent.part is None:
        return None
    core = _core(asset)
    parent = st.scene.objects.get(edge.parent.object)
    if core is None or parent is None or not parent.placed or parent.asset is None:
        return None
    parts = parts_for(parent.asset, edge.parent)
    rods = [p for p in parts if _is_rod(parent, p, knob=False)]
    if not rods:
        return None
    ext = np.sort(np.ptp(np.asarray(rods[0].bounds, float), axis=0)) * parent.scale
    if ext[1] >= core[2] * scale:
        return None  # the rod is thicker than the core's hole
    ref, c = edge.parent, edge.child
    bar = format_ref(ref.object, ref.part, ref.index, None)
    child = replace(c, surface=None, text=format_ref(c.object, c.part, c.index, None))
    hung = OverEdge("HANGING_BELOW", child, ref, {"thread": rods[0].name})
    why = (f"{c.object} is a roll: it hangs threaded on {bar}, its core around the rod, not "
           f"below it (write it as is: a roll HANGING_BELOW a rod is threaded on it)")
    return hung, scale, why


def _place_threaded(st: SolveState, oid: str, asset: Asset, scale: float, edge: OverEdge,
                    others: list[Edge], body):
    """A roll threaded on its rod (:func:`threaded_edge`): its core's axis along the rod's,
    its core's centre on the rod's middle; clear of everything but the rod's owner."""
    from ..measure.checks import check_edge

    parent = st.scene.objects[edge.parent.object]
    part = next(p for p in parent.asset.parts if p.name == edge.params["thread"])
    V = _world_vertices(parent, part)
    mid = 0.5 * (V.min(axis=0) + V.max(axis=0))
    a = np.linalg.svd(V - V.mean(axis=0), full_matrices=False)[2][0]
    k, cc, _ = _core(asset)
    up = np.array([0.0, 0.0, 1.0])
    if abs(float(a @ up)) > 0.9:
        raise Fail(f"no room to thread {oid} on {part.name}: the rod is upright")
    a = a - (a @ up) * up
    a /= np.linalg.norm(a)
    j = 2 if k != 2 else 0
    m = 3 - k - j
    last = ""
    for sign in (1.0, -1.0):  # its loose sheet toward the room first, else the other way
        R = np.zeros((3, 3))
        R[:, k], R[:, j] = sign * a, up
        R[:, m] = np.cross(R[:, (m + 1) % 3], R[:, (m + 2) % 3])  # right-handed
        t = mid - R @ (cc * scale)
        cand = PlacedObject(oid, asset.category, asset, scale, R, t)
        checks = []
        for e in others:
            holds, res, detail = check_edge(st.scene, e, cand)
            if not holds and not relaxed_to_nearest(e):
                last = f"{e.relation} {e.child} -> {e.parent}: {detail}"
                break
            checks.append((holds, res, detail))
        else:
            body.move(R, t)
            hit = st.world.collides(body, ignore=frozenset({parent.id}))
            if hit is None:
                top = part.surfaces["bottom"].transformed(parent.transform())
                sup = Support(top, SupportChoice(parent.id, part.name, "bottom"), top.polygon)
                sup.over = True
                return (R, t, sup, body), 2, [(True, {}, ""), *checks], None
            last = f"{hit} in the way"
    raise Fail(f"no room to thread {oid} on {part.name}: {last}")


def over_instance(st: SolveState, library, edge: Edge, category: str, asset: Asset,
                  reqs: list, tried: set[str]) -> tuple[str, Asset]:
    """``(category, asset)``: for a child drawn as an instance that is not soft (a rolled towel)
    on a part that reads as a bar (:func:`bar_of`: a towel written ``ON`` a tub's rim), an
    untried soft instance of its candidates (a flat towel), which hangs over it; the instance
    drawn otherwise (also when none of its candidates is soft)."""
    if not drapes(asset) or not asset.parts or _largest(asset).material.name not in CLOTH \
            or soft(asset, 1.0) is not None or edge.relation not in ("ON", "HANGING_BELOW") \
            or bar_of(st, edge, asset, 1.0) is None:
        # (a cloth thing too thick to drape only: a book is never drawn again as cloth)
        return category, asset
    import zlib

    from .choice import alternative_instance

    # a generator of its own, so that looking leaves the solve's draws as they were
    look = np.random.default_rng(zlib.crc32(asset.asset_id.encode()))
    alt = alternative_instance(library, st.pag.objects[edge.child.object].candidates, reqs,
                               tried, look, key=lambda a: 0.0 if soft(a, 1.0) else 1.0)
    if alt is None or soft(alt[1], 1.0) is None or bar_of(st, edge, alt[1], 1.0) is None:
        return category, asset
    tried.add(alt[1].asset_id)
    return alt


def over_edge(st: SolveState, oid: str, edge: Edge, asset: Asset, scale: float, *,
              after: bool = False) -> tuple[OverEdge, float, str] | None:
    """For a soft child (:func:`soft`) of ``edge`` that reads as over a bar (:func:`bar_of`):
    the edge it is placed by (:class:`OverEdge`), the scale it hangs at (less when shown
    folded) and why the edge as written is relaxed; None for anything else."""
    if not after and (got := threaded_edge(st, oid, edge, asset, scale)) is not None:
        return got
    kind = soft(asset, scale)
    if kind is None:
        return None
    got = bar_of(st, edge, asset, scale, after=after)
    if got is None:
        return None
    ref, parts, side, top = got
    z, c, w, length, ax, name = top
    parent = st.scene.objects[edge.parent.object]
    part = next((p for p in parts if p.name == name), parts[0])
    V = _world_vertices(parent, part)
    if length < SQUARE * w or np.ptp(V[:, 2]) >= length:
        # a post's top, an upright handle's end: along the parent's face it stands out from
        ax = _along_face(parent, c)
        length = np.inf  # nothing to fold it to: it hangs from the handle's end
    drop = z - _hang_floor(st, parent, z, c, w, ax, length, side)
    new, folded = (scale, None) if after else _fold(asset, scale, kind, length, drop)
    params = {"bar": [z, float(c[0]), float(c[1]), w,
                      float(length) if np.isfinite(length) else 0.0, float(ax[0]), float(ax[1])],
              "part": name}
    if side is not None:
        params["side"] = [float(x) for x in side]
    c = edge.child
    child = replace(c, surface=None, text=format_ref(c.object, c.part, c.index, None))
    hung = OverEdge("HANGING_BELOW", child, ref, params)
    bar = format_ref(ref.object, ref.part, ref.index, None)
    how = "by its straps" if kind == "strap" else "down one side"
    if edge.relation == "ON":
        blocked = f"the top of {bar} is {w * 100:.0f} cm wide, too narrow for {c.object} to lie on"
    elif (edge.parent.surface or edge.spec.parent_surface) == "bottom":
        blocked = (f"{bar} is a handle or a knob on a door or a drawer of {ref.object}: "
                   f"{c.object} cannot hang below it")
    else:
        blocked = f"nothing of {bar} faces down for {c.object} to hang below"
    size = ""
    if folded is not None:
        size = f"; shown folded to {folded[0]:.2f} x {folded[1]:.2f} m"
    why = (f"{blocked}: it hangs over {bar} {how}{size} (write it as is: a soft thing ON a "
           f"narrow top, or HANGING_BELOW a part that does not face down, hangs over it)")
    return hung, new, why


def _axes(asset: Asset, kind: str) -> tuple[int, int, int]:
    """``(thin, along, vertical)`` asset axes of a hung child: cloth with its thinnest extent
    across the bar, its longer other extent along it; a bag upright."""
    ext = np.ptp(asset_geometry(asset).hull, axis=0)
    if kind == "strap":
        thin = int(np.argmin(ext[:2]))
        return thin, 1 - thin, 2
    order = [int(k) for k in np.argsort(ext)]
    return order[0], order[2], order[1]


def _fold(asset: Asset, scale: float, kind: str, length: float, z: float
          ) -> tuple[float, tuple[float, float] | None]:
    """The scale a child hangs at over a bar ``length`` m long, ``z`` m above what it may
    reach down to (the floor, a seat: :func:`_hang_floor`): ``scale``, or less (never below
    its size range) so that cloth is no longer than the bar and clears what is below; with its
    size along the bar and down when changed."""
    ext = np.ptp(asset_geometry(asset).hull, axis=0)
    _, along, vert = _axes(asset, kind)
    lo = asset.size_range[0] / max(asset_geometry(asset).size, 1e-6)
    s = scale
    if kind == "cloth":
        s = min(s, length / max(ext[along], 1e-9))
    s = min(s, (z - FLOOR_CLEAR) / max(ext[vert], 1e-9))
    s = max(s, min(lo, scale))
    if s >= scale * 0.999:
        return scale, None
    return s, (float(ext[along] * s), float(ext[vert] * s))


def _rotation(asset: Asset, kind: str, n: np.ndarray, a: np.ndarray) -> np.ndarray:
    """The child's rotation: its thin axis along ``n`` (out from the bar; a bag's straps
    toward the bar), its along axis along ``a``, the vertical one up."""
    thin, along, vert = _axes(asset, kind)
    R = np.zeros((3, 3))
    out = n.copy()
    if kind == "strap":
        c = np.mean(asset_geometry(asset).hull, axis=0)
        straps = [np.mean(np.asarray(p.bounds, float), axis=0) for p in asset.parts
                  if p.label in STRAPS]
        if straps and float(np.mean(straps, axis=0)[thin] - c[thin]) > 0:
            out = -n  # the straps' side toward the bar
    R[:, thin] = out
    R[:, along] = a
    R[:, vert] = (0.0, 0.0, 1.0)
    if np.linalg.det(R) < 0:
        R[:, along] = -a
    return R


def _on_parent(st: SolveState, parent) -> list[np.ndarray]:
    """World hull points of what is placed on ``parent`` (cushions leaning on a sofa's back)."""
    return [world_points(o, hull_only=True, settled=False) for o in st.scene.objects.values()
            if o.placed and o.asset is not None and o.id != parent.id
            and o.support_choice is not None and o.support_choice.owner == parent.id]


def _high_pieces(st: SolveState, parent, z: float) -> list[np.ndarray]:
    """World vertices of the parent's convex pieces, and of what is placed on it, whose tops
    come within :data:`HIGH` of a bar's top ``z`` (and start below it): what the child hanging
    over the bar hangs over as well (a sofa's back frame behind its back cushions, the
    cushions leaning on them in front)."""
    T = parent.transform()
    pts = [pc.vertices @ T[:3, :3].T + T[:3, 3] for p in parent.asset.parts for pc in p.piece_arrays]
    return [v for v in pts + _on_parent(st, parent)
            if float(v[:, 2].max()) >= z - HIGH and float(v[:, 2].min()) < z]


def _hang_floor(st: SolveState, parent, z: float, c: np.ndarray, w: float, ax: np.ndarray,
                length: float, wrote) -> float:
    """The height (m) a child hanging over a bar (top ``z``, centre ``c``, ``w`` wide along
    the unit ``ax``, ``length`` long) may reach down to on the side with the most room: the
    floor, or the top of what lies below the bar within :data:`NEAR_FACE` of where it hangs
    on that side (a sofa's seat in front of its back cushions, the cushions on it); a side where a wall stands right behind the bar (a
    sofa against it) has none. Only the side the writer named (``wrote``), if any."""
    from shapely.geometry import Point

    floor = st.scene.room.elements["floor"].surface
    room = filled(floor.polygon)
    a = np.array([ax[0], ax[1], 0.0])
    n = np.array([-ax[1], ax[0], 0.0])
    sides = [n, -n] if wrote is None else [np.asarray(wrote, float)]
    high = _high_pieces(st, parent, z)
    half = 0.5 * (length if np.isfinite(length) else w)
    # the parent's pieces, and what is placed by it (cushions leaning on a sofa's back)
    T = parent.transform()
    below = [pc.vertices @ T[:3, :3].T + T[:3, 3] for part in parent.asset.parts
             for pc in part.piece_arrays]
    below += _on_parent(st, parent)
    best = None
    for side in sides:
        face = max(_reach(high, c, side, a, -half, half), 0.5 * w)
        p = np.r_[c + (face + 0.03) * side[:2], 0.0]
        if not room.contains(Point(floor.to_2d(p[None, :])[0])):
            continue  # a wall right behind: nothing hangs down there
        low = 0.0
        for v in below:
            top = float(v[:, 2].max())
            if top >= z - HIGH:
                continue
            rel = v[:, :2] - c
            on, out = rel @ a[:2], rel @ side[:2]
            if float(on.max()) < -half or float(on.min()) > half:
                continue
            if float(out.max()) > face and float(out.min()) < face + NEAR_FACE:
                low = max(low, top)
        best = low if best is None else min(best, low)
    return 0.0 if best is None else best


def _reach(pieces: list[np.ndarray], c: np.ndarray, side: np.ndarray, a: np.ndarray,
           lo: float, hi: float) -> float:
    """How far (m) beyond the bar's centre ``c`` along ``side`` the ``pieces`` reach within
    the child's span ``[lo, hi]`` along the bar's axis ``a``; 0 when none does."""
    best = 0.0
    for v in pieces:
        rel = v[:, :2] - c
        on = rel @ a[:2]
        if float(on.max()) < lo or float(on.min()) > hi:
            continue
        best = max(best, float((rel @ side[:2]).max()))
    return best


def place_over(st: SolveState, oid: str, asset: Asset, scale: float, edge: OverEdge,
               others: list[Edge], body, rng: np.random.Generator):
    """Hang ``oid`` over the bar ``edge`` names (module docstring): ``((R, t, sup, body),
    trials, checks, None)`` as placement's own poses, or ``Fail`` saying what is in the way."""
    from shapely.geometry import MultiPoint, Polygon

    if "thread" in edge.params:
        return _place_threaded(st, oid, asset, scale, edge, others, body)
    parent = st.scene.objects[edge.parent.object]
    parts = parts_for(parent.asset, replace(edge.parent, index=None)) \
        if edge.params.get("part") else parts_for(parent.asset, edge.parent)
    kind = soft(asset, scale) or "cloth"
    z, cx, cy, w, length, ax0, ax1 = edge.params["bar"]
    c, ax = np.array([cx, cy]), np.array([ax0, ax1])
    a = np.array([ax[0], ax[1], 0.0])
    n = np.array([-ax[1], ax[0], 0.0])
    centre = np.asarray(parent.position, float)[:2]
    wrote = edge.params.get("side")
    if wrote is not None:
        toward = np.asarray(wrote, float)[:2]
    else:
        toward = c - centre
    if float(n[:2] @ toward) < 0:
        n = -n
    part = next((p for p in parts if p.name == edge.params["part"]), parts[0])
    V = _world_vertices(parent, part)
    # the bar's own points at its top (not a tub's far rim)
    V = V[(V[:, 2] >= z - TOP_BAND) & (np.abs((V[:, :2] - c) @ ax) <= 0.5 * length + 1e-3)
          & (np.abs((V[:, :2] - c) @ n[:2]) <= w)]
    if not len(V):
        V = np.r_[c, z][None, :]
    hull = asset_geometry(asset).hull * scale
    index = next(i for i, q in enumerate(parent.asset.parts_by_label(part.label)) if q is part)
    top = part.surfaces["top"].transformed(parent.transform())
    sup = Support(top, SupportChoice(parent.id, part.name, "top"), top.polygon)
    sup.over = True
    trials, last = 0, "no pose"
    free = max(length - float(np.ptp((hull @ _rotation(asset, kind, n, a).T) @ a)), 0.0)
    shifts = [0.0] + list(rng.uniform(-free / 2, free / 2, 5)) if free > 0 else [0.0]
    high = _high_pieces(st, parent, z)
    floor = st.scene.room.elements["floor"].surface
    room = Polygon(floor.to_3d(np.asarray(filled(floor.polygon).exterior.coords))[:, :2]).buffer(EPS)
    for side in (n, -n):
        R = _rotation(asset, kind, side, a)
        Y = hull @ R.T
        face0 = max(float(np.max((V[:, :2] - c) @ side[:2])), 0.5 * w)
        for shift in shifts:
            along = shift - float(np.mean([np.min(Y @ a), np.max(Y @ a)]))
            # over what of the parent stands as high as the bar on that side too (a sofa's
            # back frame behind its back cushion)
            face = max(face0, _reach(high, c, side, a, along + float(np.min(Y @ a)),
                                     along + float(np.max(Y @ a))))
            for step in STEPS:
                trials += 1
                out = face + EPS + step - float(np.min(Y @ side))
                t = np.r_[c, 0.0] + out * side + along * a
                t[2] = z + EPS - float(np.max(Y[:, 2]))
                if float(np.min(Y[:, 2])) + t[2] < 0:
                    last = f"{oid} would reach the floor"
                    break
                if not room.contains(MultiPoint((Y[:, :2] + t[:2]).tolist())):
                    last = f"{oid} would reach through a wall"  # behind a sofa against it
                    break
                cand = PlacedObject(oid, asset.category, asset, scale, R, t)
                checks, why = relations_and_collisions(st, cand, others, body, R, t)
                if checks is None:
                    last = why
                    continue
                return (R, t, sup, body), trials, [(True, {}, ""), *checks], None
    bar = format_ref(edge.parent.object, part.label, index, None)
    raise Fail(f"no room to hang {oid} over {bar}: {last}")


def over_after(st: SolveState, oid: str, asset: Asset, scale: float, edge: Edge,
               others: list[Edge], body, rng: np.random.Generator):
    """Where hanging a soft child ``HANGING_BELOW`` a rod's bottom as written found no room (a
    towel below a drawer's handle, a door in the way): hung over the rod instead, at its scale,
    as :func:`place_over`, the support carrying why (``why``, for :func:`.hanging.other_hook`);
    None when that reading does not apply or finds no room either."""
    if edge.relation != "HANGING_BELOW" or isinstance(edge, OverEdge):
        return None
    got = over_edge(st, oid, edge, asset, scale, after=True)
    if got is None:
        return None
    try:
        pose, trials, checks, under = place_over(st, oid, asset, scale, got[0], others, body, rng)
    except Fail:
        return None
    pose[2].why = got[2]
    return pose, trials, checks, under
