"""A contact named on a part that another part of the object overhangs.

``AGAINST toaster:body@back -> wall_2`` where the toaster's cord reaches 3 cm further back than
its body: with a ``gap`` of 5 cm written, the body keeps its gap and the cord ends 2 cm off the
wall, the relation met exactly; with no gap, the toaster goes flush with the cord touching the
wall and the relation is recorded relaxed (``holds: false``, the body's gap its residual,
naming the part that touches instead). The object is placed either way; what it carries
goes on.

Pads ending the named part toward the contact (a fridge's vent grille on its back, a chair
leg's glide: :func:`parse3d.measure.checks.end_pads`) count as the named part, as they do in
the relation's check: a grille 4 mm proud of the back does not keep the back off the wall.

A part hung below a small part (a mug by its handle on a cup hook, a saucepan by its handle on
a pot rail's bar) is overhung only by what comes under that part: the mug's rim, a centimetre
higher than its handle, stands beside the hook, not under it (:func:`clears_beside`; placed by
:func:`parse3d.solver.hanging.hung_by_part`). The
test is local to the parent surface's extent for a finite parent part; a wall, the floor, the
ceiling or a large face is an unbounded plane to it.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..assets.model import Asset
from ..measure.checks import DIST_TOL, end_pads
from ..pag.model import Edge
from ..relations import SURFACES
from .geometry import part_points
from .intent import whole_object

__all__ = ["FLUSH_RELATIONS", "reach", "touching_parts", "excess", "flush_edge",
           "flush_reason", "flush_edges", "least_overhung_key", "over_tolerance",
           "flush_plan", "clears_beside", "BESIDE_TURNS"]

#: Contact relations whose named child part goes flush with what overhangs it.
FLUSH_RELATIONS = ("AGAINST",)

_REACH: dict[tuple, tuple[float, float, str, tuple[str, ...]]] = {}


def _reach(asset: Asset, e: Edge) -> tuple[float, float, str, tuple[str, ...]]:
    c = e.child
    side = c.surface or e.spec.child_surface
    key = (asset.asset_id, c.part, c.index, side)
    got = _REACH.get(key)
    if got is not None:
        return got
    n = np.asarray(SURFACES[side], float)
    pts = {p.name: part_points([p]) for p in asset.parts}
    far = {name: float(np.max(q @ n)) for name, q in pts.items()}
    whole = max(far.values())
    ps = asset.parts_by_label(c.part) if c.part is not None else list(asset.parts)
    if c.index is not None:
        ps = ps[c.index:c.index + 1]
    if not ps:
        got = (-np.inf, whole, "", ())
    else:
        named = {p.name for p in ps}
        others = [(name, q) for name, q in pts.items() if name not in named]
        touching = (*named, *end_pads([pts[name] for name in named], others, n))
        mine = max(far[name] for name in touching)
        rest = [name for name in far if name not in touching]
        who = max(rest, key=far.__getitem__, default=None)
        label = asset.part(who).label if who is not None and whole > mine else ""
        got = (mine, whole, label, touching)
    if len(_REACH) > 8192:
        _REACH.clear()
    _REACH[key] = got
    return got


def reach(asset: Asset, e: Edge) -> tuple[float, float, str]:
    """How far the named child part(s) of ``e`` with their end pads, and the whole object,
    reach along the normal of the named child surface, and the label of the part reaching
    furthest when it is not one of those: ``(named, whole, label)`` in metres, asset frame,
    unscaled; ``(-inf, whole, "")`` when the asset lacks the part."""
    return _reach(asset, e)[:3]


def touching_parts(asset: Asset, e: Edge) -> list:
    """The named child parts of ``e`` and the pads ending them toward the parent: the parts
    that touch it when the named part does."""
    names = set(_reach(asset, e)[3])
    return [p for p in asset.parts if p.name in names]


def excess(asset: Asset, e: Edge, scale: float = 1.0) -> float:
    """Metres by which another part of ``asset`` at ``scale`` reaches further toward the
    parent than the named part of ``e``, beyond the ``gap`` written (0 when the named part can
    keep its gap without another part entering the parent; inf when the asset lacks it)."""
    named, whole, _ = reach(asset, e)
    if not np.isfinite(named):
        return float("inf")
    return max(0.0, (whole - named) * scale - _gap(e))


def _gap(e: Edge) -> float:
    return float(e.param("gap") or 0.0) if e.relation == "AGAINST" else 0.0


def flush_edge(e: Edge) -> Edge:
    """``e`` placed by the whole object, the part reaching furthest touching (``gap`` 0: as
    near as the written gap of the named part allows)."""
    out = whole_object(e)
    if _gap(e) > 0:
        named = out._named_part
        out = replace(out, params={**out.params, "gap": 0.0})
        object.__setattr__(out, "_named_part", named)
    return out


def flush_reason(asset: Asset, e: Edge, scale: float) -> str:
    """Why ``e`` went flush by another part, and what the writer could say instead."""
    named, whole, who = reach(asset, e)
    oid, side = e.child.object, e.child.surface or e.spec.child_surface
    return (f"{e.relation} {e.child} -> {e.parent}: {oid}:{who} reaches "
            f"{(whole - named) * scale:.2f} m further {side} than {oid}:{e.child.part} (asset "
            f"{asset.asset_id}): name {oid}:{who}@{side} or {oid}@{side}")


def flush_edges(edges: list[Edge]) -> list[Edge]:
    """The contacts among ``edges`` that :data:`FLUSH_RELATIONS` place by a named child part."""
    return [e for e in edges if e.relation in FLUSH_RELATIONS and e.child.part is not None]


def least_overhung_key(edges: list[Edge]):
    """A key ranking instances by how far other parts overhang the named child parts of the
    contacts among ``edges`` (beyond their gaps; 0: every named part can touch), or None when
    no contact names a child part."""
    fl = flush_edges(edges)
    if not fl:
        return None
    return lambda a: max(excess(a, e) for e in fl)


def over_tolerance(x: float) -> bool:
    """Whether an overhang of ``x`` metres keeps the named part off its parent (beyond the
    contact checks' distance tolerance)."""
    return x > DIST_TOL


def flush_plan(asset: Asset, scale: float, edges: list[Edge],
               leave) -> dict[int, tuple[Edge, str]]:
    """For one object's ``edges`` (``pag.edges_of``: the support first), the contacts among
    those not in ``leave`` (indices) whose named child part ``asset`` at ``scale`` cannot
    bring to its gap: index -> (the edge placed instead, flush by the part reaching furthest;
    why, recorded as the relation's relaxation)."""
    return {i: (flush_edge(e), flush_reason(asset, e, scale))
            for i, e in enumerate(edges) if i > 0 and i not in leave
            and e in flush_edges([e]) and over_tolerance(excess(asset, e, scale))}



#: Headings (over a half turn) tried for the side of the named part its overhanging parts lie
#: beyond, by :func:`clears_beside`.
BESIDE_TURNS = 24


def clears_beside(asset: Asset, e: Edge, scale: float, sides: tuple[float, float]):
    """The named child part of ``e`` (``HANGING_BELOW`` naming a child part by its ``top``)
    by which ``asset`` at ``scale`` can hang below a parent surface of ``sides`` (short, long;
    metres): at some heading, with the parent centred over that part, every other part
    reaching further up than it lies beside the parent's extent, not under it (a mug's rim
    beside a cup hook, a saucepan's lid knob off a pot rail's bar); of several parts of that
    name (a casserole's two handles), the first that can. None when none can, and for a
    support of another kind or side (judged as against a plane: :func:`.intent.overhang`)."""
    if e.relation != "HANGING_BELOW" or e.child.part is None \
            or (e.child.surface or e.spec.child_surface) != "top":
        return None
    ps = asset.parts_by_label(e.child.part)
    if e.child.index is not None:
        ps = ps[e.child.index:e.child.index + 1]
    w, length = (max(float(x), 1e-3) for x in sides)
    for p in ps:
        if _beside(asset, p, scale, w, length):
            return p
    return None


def _beside(asset: Asset, part, scale: float, w: float, length: float) -> bool:
    mine = part_points([part]) * scale
    top = float(mine[:, 2].max())
    up = [q for q in (part_points([o]) * scale for o in asset.parts if o is not part)
          if float(q[:, 2].max()) > top + DIST_TOL]
    if not up:
        return True
    for a in np.linspace(0.0, np.pi, BESIDE_TURNS, endpoint=False):
        u = np.array([np.cos(a), np.sin(a), 0.0])
        v = np.array([-np.sin(a), np.cos(a), 0.0])
        # the parent's rectangle (short side across u) centred over the part's middle
        cu = 0.5 * float((mine @ u).min() + (mine @ u).max())
        cv = 0.5 * float((mine @ v).min() + (mine @ v).max())
        if all(float((q @ u).min()) > cu + w / 2 or float((q @ u).max()) < cu - w / 2
               or float((q @ v).min()) > cv + length / 2
               or float((q @ v).max()) < cv - length / 2 for q in up):
            return True
    return False
