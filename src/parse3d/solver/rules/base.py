"""The :class:`RelationRule` interface: what one relation family means to the solver.

A rule says how a relation turns the child (stage 3 of Algorithm 1), how it clips the region
of the child's origin on its support (stages 4 and 5, phase ``object`` or ``part``), in which
order it is relaxed when it cannot be met, and, for the support relations, which surfaces hold
the child and at what height. Each relation name has exactly one rule, registered in
:data:`RULES` by :func:`register`; the family modules (``support``, ``contact``,
``alignment``, ``layout``) hold them. The flags of the relation itself ("is support", "is
contact", "symmetric") stay on the relation data in :mod:`parse3d.relations`.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from shapely.geometry.base import BaseGeometry

from ...assets.model import Asset
from ...geometry import regions as RG
from ...geometry.surfaces import Surface, surface_from_bbox
from ...measure.checks import object_centroid, outer_part
from ...pag.model import PAG, Edge
from ...pag.refs import Ref
from ...relations import SURFACES
from ..config import Fail
from ..geometry import asset_geometry, part_points
from ..state import SolveState, angle_to, parts_for, wrap
from ..support import Support

__all__ = ["RelationRule", "RULES", "register", "Orientation", "RegionContext",
           "contact_normal", "parent_surface_world", "parent_frame", "emptied",
           "free_room_text", "turn_to_face", "touching_frame", "clip_to_line", "support_plane", "measured_after"]


@dataclass
class Orientation:
    """The rotation being built for one child on one support.

    Attributes
    ----------
    R0 : (3, 3) float
        Turns the child's support contact normal onto minus the support normal.
    n_s : (3,) float
        The support normal (world).
    phi : float or None
        Angle about ``n_s`` once a rule has fixed it (radians).
    source : str or None
        What fixed ``phi`` (for messages).
    toward : str or None
        The object the child turns to face, per sampled position.
    lean : tuple or None
        ``(edge, parent surface normal)`` of a LEANING_AGAINST.
    """

    R0: np.ndarray
    n_s: np.ndarray
    phi: float | None = None
    source: str | None = None
    toward: str | None = None
    lean: tuple | None = None


@dataclass
class RegionContext:
    """The posed child a region is built for.

    Attributes
    ----------
    st : SolveState
    oid : str
    asset : Asset
    scale : float
    R : (3, 3) float
        The child's rotation.
    h : float
        Height of the child's origin above the support plane (m).
    sup : Support
    off : (2,) float
        The child's bbox centre relative to its origin, in plane coordinates.
    off3 : (3,) float
        The same offset in the world, height above the plane included.
    """

    st: SolveState
    oid: str
    asset: Asset
    scale: float
    R: np.ndarray
    h: float
    sup: Support
    off: np.ndarray
    off3: np.ndarray


class RelationRule:
    """What one relation family means to the solver; subclasses override the hooks their
    relations use (the defaults leave rotation and region alone)."""

    #: The relation names this rule serves (each name has exactly one rule).
    names: tuple[str, ...] = ()
    #: ``support``, ``contact``, ``alignment`` or ``layout`` (the module holding the rule).
    family: str = ""
    #: The relations' kind in :mod:`parse3d.relations` (``support``, ``part``, ``object``).
    kind: str = ""
    #: Whether the relations hold only with the two touching (:attr:`Relation.is_contact`).
    contact: bool = False
    #: When the region rule clips: ``object`` (first), ``part`` (then) or ``none``.
    region_phase: str = "none"
    #: Whether the rotation rule fixes the child's angle about the support normal.
    fixes_yaw: bool = False
    #: Order of relaxation of an unmet relation: object-level relations (0) before part-level
    #: contacts (1); None for support relations, which are never relaxed.
    relax_order: int | None = None
    #: Support rules: the child is held in place (mounted, hung), not free to settle.
    fixed: bool = False
    #: Support rules: the child hangs below its support (its region is built from its
    #: attachment, not its footprint).
    hangs: bool = False
    #: Support rules: :meth:`band` clips the region (a height range on a wall).
    banded: bool = False
    #: Support rules: the child rests on the parent's internal support surfaces.
    internal: bool = False

    def rotate(self, st: SolveState, asset: Asset, o: Orientation, e: Edge) -> None:
        """Constrain the rotation ``o`` being built for edge ``e``'s child (in place)."""

    def region(self, ctx: RegionContext, e: Edge, region: BaseGeometry) -> BaseGeometry:
        """``region`` (positions of the child's origin, plane coordinates) clipped to where
        ``e`` can hold; ``Fail`` naming what blocked it when nothing is left."""
        return region

    def needs(self, pag: PAG, oid: str, e: Edge, text: str) -> list[tuple]:
        """What ``e`` asks of the asset of ``oid`` beyond the parts it names: ``(part label,
        index or None, text, kind)`` entries of :func:`parse3d.solver.choice.requirements`."""
        return []

    def part_needs(self, e: Edge, ref: Ref, role: str, text: str) -> list[tuple]:
        """What ``e`` asks of the part ``ref`` names (``role``: ``child`` or ``parent``),
        beyond existing; entries as :meth:`needs`."""
        return []

    def surfaces(self, st: SolveState, edge: Edge) -> list[Support]:
        """Support rules: the parent's surfaces that may hold the child, in the order tried."""
        raise TypeError(f"{edge.relation} is not a support relation")

    def offset(self, edge: Edge, rng: np.random.Generator) -> float:
        """Support rules: metres between the support surface and the child (0: touching)."""
        return 0.0

    def band(self, ctx: RegionContext, edge: Edge, region: BaseGeometry) -> BaseGeometry:
        """Support rules: ``region`` clipped to the heights the support edge allows."""
        return region


#: Every relation name's rule.
RULES: dict[str, RelationRule] = {}


def register(cls: type[RelationRule]) -> type[RelationRule]:
    """Class decorator: register one instance of ``cls`` under each of its names."""
    rule = cls()
    for n in cls.names:
        if n in RULES:
            raise ValueError(f"relation {n} already has a rule ({type(RULES[n]).__name__})")
        RULES[n] = rule
    return cls


def contact_normal(ref: Ref, default_label: str) -> np.ndarray:
    """The asset-frame normal of the surface a reference names (or the default)."""
    return np.array(SURFACES[ref.surface or default_label], float)


def parent_surface_world(st: SolveState, ref: Ref, default_label: str) -> tuple[Surface, str, str]:
    """World surface of a parent reference (object part or room element)."""
    scene = st.scene
    label = ref.surface or default_label
    if ref.is_room_element:
        if ref.object == "wall":
            raise Fail("'wall' (any wall) can only be a support parent")
        el = scene.room.elements[ref.object].surface
        return el, ref.object, el.label
    parent = scene.objects[ref.object]
    if not parent.placed:
        raise Fail(f"parent {ref.object!r} was not placed")
    parts = parts_for(parent.asset, ref)
    if not parts:
        raise Fail(f"{ref.object!r} has no part {ref.part!r}")
    if ref.part is None:  # the whole object's face: the bbox face of the asset
        s = surface_from_bbox(label, asset_geometry(parent.asset).bounds)
        return s.transformed(parent.transform()), "", label
    p = outer_part(parts, label)  # a label several parts share: the outermost face
    return p.surfaces[label].transformed(parent.transform()), p.name, label


def parent_frame(st: SolveState, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """Centroid, rotation frame (columns: right, front, up) and hull points of a parent."""
    if name in st.scene.room.elements:
        s = st.scene.room.elements[name].surface
        front = s.normal
        up = np.array([0, 0, 1.0]) if abs(front[2]) < 0.9 else np.array([0, 1.0, 0])
        right = np.cross(front, up)
        return s.origin.copy(), np.c_[right, front, up], None
    o = st.scene.objects[name]
    if not o.placed:
        raise Fail(f"parent {name!r} was not placed")
    return object_centroid(o), o.rotation, st.hulls[name]


def emptied(e: Edge, sup: Support, why: str = "", side: str = "") -> Fail:
    """The failure of a rule that emptied the region (``side``: the edge's side, as text)."""
    return Fail(f"{e.relation} {e.child} -> {e.parent}{side} emptied the feasible region on "
                f"{sup.name}{': ' + why if why else ''}")


def free_room_text(region: BaseGeometry) -> str:
    """Where the free positions were before a rule emptied them, for messages."""
    if region.is_empty:
        return "no free space was left there"
    b = region.bounds
    return f"the free positions span {b[2] - b[0]:.2f} x {b[3] - b[1]:.2f} m elsewhere"


def turn_to_face(st: SolveState, o: Orientation, e: Edge, nA: np.ndarray,
                 sign: float) -> Surface | None:
    """Fix the angle about the support normal at which the child's surface normal ``nA``
    (asset frame) is ``sign`` times the parent surface's (-1: the two face each other, +1:
    they face the same way); ``Fail`` when no angle does or another rule fixed a different
    one. Returns the parent's world surface, or None when any angle satisfies it."""
    rel = e.relation
    sB, _, _ = parent_surface_world(st, e.parent, e.spec.parent_surface)
    ang = angle_to(o.R0 @ nA, sign * sB.normal, o.n_s)
    if ang is None:
        if abs(np.dot(o.R0 @ nA, sign * sB.normal) - 1) < 1e-3:
            return None  # already satisfied whatever the angle
        raise Fail(f"{rel} {e.child} -> {e.parent}: the surfaces cannot be turned to face each "
                   f"other on this support", intrinsic=True)
    if o.phi is not None and abs(wrap(ang - o.phi)) > np.deg2rad(1.0):
        raise Fail(f"{rel} {e.child} -> {e.parent} needs a different orientation than {o.source}")
    o.phi, o.source = ang, f"{rel} {e.child} -> {e.parent}"
    return sB


def touching_frame(ctx: RegionContext, e: Edge):
    """What a part-level region rule measures: ``(sB, g, parts, pts, base)``, the parent's
    world surface, its normal in plane coordinates, the child's named parts, their points
    (rotated and scaled, relative to the origin) and the origin's plane at the child's
    height; ``Fail`` when the parent surface is parallel to the support or the part is
    missing."""
    s = ctx.sup.surface
    sB, _, _ = parent_surface_world(ctx.st, e.parent, e.spec.parent_surface)
    nB = sB.normal
    g = np.array([s.u @ nB, s.v @ nB])
    if np.linalg.norm(g) < 1e-6:
        raise Fail(f"{e.relation} {e.child} -> {e.parent}: the parent surface is parallel to the "
                   f"support, no position satisfies it")
    parts = parts_for(ctx.asset, e.child)
    if not parts:
        raise Fail(f"{e.child.object!r} has no part {e.child.part!r}")
    pts = (part_points(parts) * ctx.scale) @ ctx.R.T
    base = s.origin + ctx.h * s.normal
    return sB, g, parts, pts, base


def clip_to_line(ctx: RegionContext, e: Edge, region: BaseGeometry, gg: np.ndarray,
                 c: float) -> BaseGeometry:
    """``region`` clipped to the line ``gg . x = c`` (plane coordinates); ``Fail`` when the
    line misses it."""
    nrm = np.linalg.norm(gg)
    ln = RG.line(np.zeros(2), gg / nrm, c / nrm)
    new = RG.clip(region, ln)
    if new.is_empty:
        raise emptied(e, ctx.sup, f"where {e.child} touches {e.parent}, {free_room_text(region)}")
    return new


def support_plane(st: SolveState, support_edge: Edge) -> Surface | None:
    """The plane the child's support edge puts it on, when it is known before the support is
    chosen: a room element's, or the named surface of an ``ON`` parent; else None."""
    ref = support_edge.parent
    if ref.is_room_element:
        el = st.scene.room.elements.get(ref.object)
        return None if el is None else el.surface
    if support_edge.relation != "ON":
        return None
    try:
        return parent_surface_world(st, ref, support_edge.spec.parent_surface)[0]
    except Fail:
        return None


def measured_after(e: Edge) -> Edge:
    """``e`` as written, marked so that its check does not reject a pose (the mark
    :func:`.layout.relaxed_to_nearest` reads, as for a layout relation relaxed to its nearest
    positions): the relation is measured on the placed object and recorded relaxed when it
    does not hold."""
    out = replace(e)
    object.__setattr__(out, "_nearest", True)
    return out
