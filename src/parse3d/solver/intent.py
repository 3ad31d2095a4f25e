"""Intent over letter for support relations: what the writer meant, where the letter fails.

A writer who says ``ON armchair:frame@bottom -> floor`` means that the armchair stands on the
floor; when the asset's frame is raised on legs, the letter cannot be met, the intent can. The
instance whose named part reaches furthest toward the support is drawn first (every pool slot
is ranked); when even that one is overhung by another part, the object is placed by the whole
object (the part reaching furthest touches) and the relation is recorded as relaxed, naming
the part that touches instead. Pads at the end of the named parts (a chair leg's glide) count
as the named parts (:func:`parse3d.measure.checks.end_pads`).

Likewise a round thing written ``ON`` one of its kind (an apple on an apple) rests beside it,
a heap (:func:`beside`), and the base of such a stack is drawn even when no instance is flat
(:data:`SOFT_REQUIREMENTS`).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..assets.model import Asset
from ..measure.checks import DIST_TOL, end_pads
from ..measure.geometry import is_round
from ..measure.reach import WIDE_LEAN_DEG
from ..pag.model import Edge
from ..relations import SURFACES
from .geometry import part_points
from .resting import box_like

__all__ = ["LOOSE_SUPPORTS", "names_part", "overhang", "whole_object", "loose_reason", "soft",
           "beside", "lies_on_cover", "lies_flat", "lies_in_stack", "lying_face"]

#: Support relations whose named child part is placed by the whole object when another part
#: of the instance reaches further toward the support.
LOOSE_SUPPORTS = ("ON", "SECURED_TO", "HANGING_BELOW")

_OVER: dict[tuple, tuple[float, str]] = {}


def names_part(e: Edge) -> bool:
    """Whether ``e`` is a support relation of :data:`LOOSE_SUPPORTS` naming a child part."""
    return e.relation in LOOSE_SUPPORTS and e.child.part is not None


def overhang(asset: Asset, e: Edge) -> tuple[float, str]:
    """Metres by which another part of ``asset`` reaches further along the normal of the child
    surface ``e`` names than the named part(s) with their end pads, and that part's label
    (``(inf, "")`` when the asset lacks the part, ``(0, "")`` when nothing overhangs it)."""
    label, idx = e.child.part, e.child.index
    side = e.child.surface or e.spec.child_surface
    key = (asset.asset_id, label, idx, side)
    got = _OVER.get(key)
    if got is not None:
        return got
    ps = asset.parts_by_label(label)
    if not ps or (idx is not None and idx >= len(ps)):
        got = (float("inf"), "")
    else:
        ps = ps[idx:idx + 1] if idx is not None else ps
        n = np.asarray(SURFACES[side], float)
        named = {id(p) for p in ps}
        others = [(p.name, part_points([p])) for p in asset.parts if id(p) not in named]
        pads = set(end_pads([part_points([p]) for p in ps], others, n))
        mine = max(float(np.max(q @ n)) for name, q in others if name in pads) if pads else -np.inf
        mine = max(mine, float(np.max(part_points(ps) @ n)))
        who = max(((name, float(np.max(q @ n))) for name, q in others if name not in pads),
                  key=lambda x: x[1], default=("", -np.inf))
        d = who[1] - mine
        got = (d, asset.part(who[0]).label) if d > DIST_TOL else (0.0, "")
    if len(_OVER) > 8192:
        _OVER.clear()
    _OVER[key] = got
    return got


def whole_object(e: Edge) -> Edge:
    """The edge ``e`` by the whole child object (no part named): the part that reaches
    furthest then touches (a shelf flush by its posts when its back panel is set in); a lean
    on an object up to the widest tilt (the tilts written tried first: ``_written_tilt``). The
    part as written is kept as ``_named_part`` (the choice of the least overhung instance)."""
    from ..pag.refs import format_ref

    c = e.child
    out = replace(e, child=replace(c, part=None, index=None,
                                   text=format_ref(c.object, None, None, c.surface)))
    if e.relation == "LEANING_AGAINST" and "angle_deg" in e.params \
            and not e.parent.is_room_element:
        # leaning on an object, further than written when the tilts written do not hold (a
        # backpack that stands up by itself there): relaxed, the tilt is the residual
        lo, hi = (float(x) for x in e.param("angle_deg"))
        out = replace(out, params={**e.params, "angle_deg": [lo, max(hi, WIDE_LEAN_DEG[1])]})
        object.__setattr__(out, "_written_tilt", (lo, hi))
    object.__setattr__(out, "_named_part", (c.part, c.index) if c.part else None)
    return out


def loose_reason(asset: Asset, e: Edge, scale: float) -> str:
    """Why the support ``e`` was placed by the whole object, with what to write instead."""
    d, who = overhang(asset, e)
    oid, side = e.child.object, e.child.surface or e.spec.child_surface
    way = {"bottom": "down", "top": "up"}.get(side, side)
    return (f"{oid}:{e.child.part} cannot touch {e.parent} ({asset.asset_id}: {oid}:{who} "
            f"reaches {d * scale:.2f} m further {way}), so {oid}:{who} touches it: name "
            f"{oid}:{who}@{side} or {oid}@{side}")


#: Stack requirements a parent may be drawn without when no instance meets them (the base of
#: a stack of round things: what would stack on it rests beside it instead).
SOFT_REQUIREMENTS = ("stack_base",)


def soft(reqs: list) -> list:
    """``reqs`` without :data:`SOFT_REQUIREMENTS`, and with an inside asked of a named part
    (``IN basket1:basket``, a shopping basket's woven shell) asked of the whole object: what
    goes IN the part rests on the object's inside within that part (its floor, the ``base``;
    ``support.py``)."""
    return [(None, None, r[2], r[3]) if r[3] == "internal" and r[0] is not None else r
            for r in reqs if r[3] not in SOFT_REQUIREMENTS]


def beside(pag, scene, e: Edge, rolls) -> tuple[Edge, Edge, str] | None:
    """For ``ON child -> parent`` where the placed parent is of the child's kind and round
    (extents within 30%, not box-like: ``resting.box_like``, a stack of towels) or rolls (``rolls(asset, ref)``: neither its top nor its bottom is
    flat): an apple, a tomato; a heap:
    the child takes the parent's own support relation (the crate, the bowl) and a ``NEAR``
    to the parent close enough to touch it, so it rests beside it or, on a pile, in the hollow
    by it. Returns (the support edge placed, the NEAR edge, why), or None."""
    if e.relation != "ON" or e.parent.is_room_element:
        return None
    cid, pid = e.child.object, e.parent.object
    parent = scene.objects.get(pid)
    if parent is None or not parent.placed or not (
            set(pag.objects[cid].candidates) & set(pag.objects[pid].candidates)):
        return None
    under = pag.supporter(pid)
    if under is None or under.relation not in ("ON", "IN") or not (
            (is_round(parent) and not box_like(parent.asset)) or rolls(parent.asset, e.parent)):
        return None
    from .geometry import asset_geometry

    sup = replace(under, child=e.child)
    ext = np.ptp(asset_geometry(parent.asset).bounds, axis=0) * parent.scale
    near = Edge("NEAR", replace(e.child, part=None, index=None, surface=None, text=cid),
                replace(e.parent, part=None, index=None, surface=None, text=pid),
                {"distance": round(float(1.6 * max(ext[:2])), 4)})
    why = (f"{pid} ({parent.asset.asset_id}) is round: nothing stacks on it, so {cid} rests "
           f"beside it, {under.relation} {under.parent} (write {under.relation} {cid} -> "
           f"{under.parent}, a heap, or stack on a flat base)")
    return sup, near, why


#: A part is a panel when its thinnest extent is at most this share of its middle one.
PANEL_THIN = 0.25
#: An object lies on a cover panel when its extent across the panel is at most this share of
#: its smaller other extent (a notebook, a magazine; not a cabinet by its side panel).
FLAT_OBJECT = 0.5
#: Metres within which a panel's outer face counts as the object's outside.
OUTSIDE_TOL = 2e-3


def _covered(asset: Asset) -> int | None:
    """The thin axis of a flat object modelled standing whose both large outsides are panels
    each spanning at least :data:`COVER_SPAN` of the object (a book's, a notebook's, a
    magazine's covers; not a picture frame's back, a monitor's screen or a box's side); None
    for anything else."""
    ob = asset_bounds(asset)
    ext = ob[1] - ob[0]
    axis = int(np.argmin(ext))
    rest = [k for k in range(3) if k != axis]
    if axis == 2 or ext[axis] > FLAT_OBJECT * min(float(ext[k]) for k in rest):
        return None
    sides = set()
    for p in asset.parts:
        b = np.asarray(p.bounds, float)
        pe = b[1] - b[0]
        if pe[axis] > PANEL_THIN * min(float(pe[k]) for k in rest) \
                or any(pe[k] < COVER_SPAN * ext[k] for k in rest):
            continue
        if b[1][axis] >= ob[1][axis] - OUTSIDE_TOL and b[0][axis] > ob[0][axis] + OUTSIDE_TOL:
            sides.add(1)
        elif b[0][axis] <= ob[0][axis] + OUTSIDE_TOL and b[1][axis] < ob[1][axis] - OUTSIDE_TOL:
            sides.add(0)
    return axis if sides == {0, 1} else None


def lying_face(asset: Asset, R: np.ndarray) -> str | None:
    """The face (``back``/``front``/``left``/``right``) a covered flat object modelled standing
    (:func:`_covered`: a book, a notebook, a magazine) lies on at the rotation ``R`` (its thin
    axis within 18 degrees of vertical), as the solver records it in ``rests_on``; None when it
    stands or is no such object. For scenes whose poses come from elsewhere (generated
    layouts), so the ``ON`` check measures the face it lies on."""
    axis = _covered(asset)
    if axis is None:
        return None
    up = float(np.asarray(R, float)[2, axis])
    if abs(up) < 0.95:
        return None
    return (("left", "back") if up > 0 else ("right", "front"))[axis]


#: Share of an object's extents a cover panel spans (:func:`_covered`).
COVER_SPAN = 0.9

#: Relations by which a flat object stands in a row (books side by side on a shelf, leaning on
#: a bookend): written with one of them it keeps standing as modelled.
_ROW = ("SIDE_OF", "AGAINST", "LEANING_AGAINST", "ALONG")


def lies_flat(edge: Edge, asset: Asset, pag) -> Edge | None:
    """``ON`` with no child part named, for a covered flat object modelled standing (a
    notebook, a magazine: :func:`_covered`): the edge by which it lies on its back cover's
    outer face, as a person means a notebook on a desk; None (standing as modelled) when the
    object stands in a row (a relation of :data:`_ROW` of its own), and for anything else."""
    c = edge.child
    if edge.relation != "ON" or c.part is not None or c.surface not in (None, "bottom"):
        return None
    if any(e.relation in _ROW and c.object in (e.child.object, e.parent.object)
           for e in pag.relations):
        return None
    axis = _covered(asset)
    if axis is None:
        return None
    from ..pag.refs import format_ref

    side = ("left", "back")[axis]
    return replace(edge, child=replace(c, surface=side,
                                       text=format_ref(c.object, None, None, side)))


def lies_on_cover(edge: Edge, asset: Asset) -> Edge | None:
    """The support edge by which a flat object modelled standing (a notebook, a magazine)
    lies on one of its outer panels when written ``ON obj:panel@bottom`` (``ON
    notebook:back_cover@bottom -> desk:top``): the panel's outer face, its large face on the
    object's outside, so the object lies on it as the writer meant rather than standing on
    the panel's lower edge; None for anything else (the edge as written). The placed object
    records the face as ``rests_on``, which the ``ON`` check measures."""
    c = edge.child
    if edge.relation != "ON" or c.part is None or c.surface != "bottom":
        return None
    ps = asset.parts_by_label(c.part)
    if c.index is not None:
        ps = ps[c.index:c.index + 1]
    if not ps:
        return None
    b = np.vstack([np.asarray(p.bounds, float) for p in ps])
    lo, hi = b.min(axis=0), b.max(axis=0)
    ext = hi - lo
    axis = int(np.argmin(ext))
    if axis == 2 or ext[axis] > PANEL_THIN * float(np.sort(ext)[1]):
        return None
    ob = np.asarray(asset_bounds(asset), float)
    oext = ob[1] - ob[0]
    if oext[axis] > FLAT_OBJECT * min(float(oext[k]) for k in range(3) if k != axis):
        return None
    if hi[axis] >= ob[1][axis] - OUTSIDE_TOL and lo[axis] > ob[0][axis] + OUTSIDE_TOL:
        side = ("right", "front")[axis]
    elif lo[axis] <= ob[0][axis] + OUTSIDE_TOL and hi[axis] < ob[1][axis] - OUTSIDE_TOL:
        side = ("left", "back")[axis]
    else:
        return None  # the panel spans the object (a record's sleeve): it stands as written
    from ..pag.refs import format_ref

    return replace(edge, child=replace(c, surface=side,
                                       text=format_ref(c.object, c.part, c.index, side)))


#: The outer panel a flat object modelled standing lies on in a stack.
STACK_PANEL = "back_cover"


def lies_in_stack(edge: Edge, asset: Asset, parent: Asset | None, above: list[str],
                  category: str) -> Edge | None:
    """The support edge by which a flat object modelled standing (a book, a notebook, a
    magazine) lies on its back cover in a stack, when written ``ON`` with no part of its own:
    on another such object (``ON book2 -> book1``), or with another of its category written
    ``ON`` it (the bottom book of a stack on a side table). ``parent`` is the placed parent's
    asset (None for the room or an unplaced one), ``above`` the categories written ``ON`` the
    object. A person writing a stack of books means them lying, not each standing on the
    top edge of the one below; None for anything else (the edge as written)."""
    c = edge.child
    if edge.relation != "ON" or c.part is not None or not asset.parts_by_label(STACK_PANEL):
        return None
    from ..pag.refs import format_ref

    lying = replace(edge, child=replace(c, part=STACK_PANEL, index=None, surface="bottom",
                                        text=format_ref(c.object, STACK_PANEL, None, "bottom")))
    cover = lies_on_cover(lying, asset)
    if cover is None:
        return None
    on_like = parent is not None and lies_on_cover(lying, parent) is not None
    if not on_like and category not in above:
        return None
    return cover


def asset_bounds(asset: Asset) -> np.ndarray:
    """(2, 3) bounds of all of ``asset``'s parts (unit scale)."""
    b = np.vstack([np.asarray(p.bounds, float) for p in asset.parts])
    return np.stack([b.min(axis=0), b.max(axis=0)])
