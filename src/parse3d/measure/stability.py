"""Post-settle verification: which objects fell, tipped, left their support or broke their
support relation while the scene settled.

The definitions (docs/solver.md, "Verification after settling") are the project's one
definition of "unstable": the repair after settling (:func:`parse3d.pipeline.unstable_objects`)
uses them as they are. For every placed object that settling moved freely (``fixed`` objects are
held kinematic and never reported):

``fell``
    its origin dropped more than ``fall_distance`` (default 5 cm), and it is really off: its
    centre of mass is no longer over the (settled) footprint of the object that held it up (the
    container the solver chose where it rests beside a round parent), or, standing on the room, its centre of mass dropped more than ``fall_distance``;
``tipped``
    its up axis turned more than ``tip_angle_deg`` (default 15 degrees) away from its solved up
    axis, its centre of mass dropped more than ``TIP_DROP`` (2 cm: it fell over, it was not
    just turned), it is not round (an apple rolls rather than tips) and it is not still resting
    as meant (:func:`settled_rest`: a content tumbled within its container, a leaner slumped
    against what it leans on);
``left_support``
    settling found no contact within ``contact_threshold`` (default 1 mm) between it and the
    part that supported it (the ``left_support`` flag :func:`parse3d.physics.settle` sets from
    its part-level contact extraction), and its centre of mass is no longer over the
    supporting object's footprint (an apple that rolled within its bowl has not left it);
``broke_support``
    it still touches its supporter, but its support relation no longer holds on the settled
    poses (centre of mass off the support polygon, tilted off the surface, out of the
    enclosure, ...), measured by the relation's check rule. Objects resting on a pile
    (``stacked_on``) are judged by where they ended (the three causes above), not by this. An
    object still resting as meant (:func:`settled_rest`) whose support check fails on its turn
    is reported ``broke_support`` (the first repair round re-places it), never ``tipped``.

The thresholds default to the ones the scene was settled with (``scene.meta["settle"]``).

>>> from parse3d.measure import INSTABILITY_CAUSES
>>> INSTABILITY_CAUSES
('fell', 'tipped', 'left_support', 'broke_support')
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..scene.model import Scene
from .checks import check_edge, select_parts, world_points
from .geometry import asset_geometry, hull_extents, is_round
from .reach import lean_up, piece_data, pieces_distance

__all__ = ["INSTABILITY_CAUSES", "Instability", "verify_settled", "supported_by", "is_round",
           "SettledSummary", "summarize_settled", "broken_after_settling", "settled_rest",
           "lies_flat"]

#: The causes :func:`verify_settled` reports, in the order it reports them per object.
INSTABILITY_CAUSES = ("fell", "tipped", "left_support", "broke_support")
_DEFAULTS = {"fall_distance": 0.05, "tip_angle_deg": 15.0}


@dataclass(frozen=True)
class Instability:
    """One way one object did not stay where the solver put it.

    Attributes
    ----------
    object_id : str
    cause : str
        One of :data:`INSTABILITY_CAUSES`.
    detail : str
        One line with what was measured, e.g. ``"dropped 0.412 m (more than 0.05 m)"``.
    value : float
        The measured quantity: the drop (m) for ``fell``, the tilt (degrees) for ``tipped``,
        NaN otherwise.
    relation : int or None
        Index of the broken support relation in ``scene.pag.relations`` (``broke_support``).
    carries : tuple of str
        Placed objects it supports, directly or through others (they move with it).
    """

    object_id: str
    cause: str
    detail: str
    value: float = float("nan")
    relation: int | None = None
    carries: tuple[str, ...] = ()

    def to_dict(self) -> dict:
        d = {"object": self.object_id, "cause": self.cause, "detail": self.detail}
        if np.isfinite(self.value):
            d["value"] = round(float(self.value), 6)
        if self.relation is not None:
            d["relation"] = self.relation
        if self.carries:
            d["carries"] = list(self.carries)
        return d


def supported_by(scene: Scene, object_id: str) -> tuple[str, ...]:
    """Placed objects whose chain of support relations passes through ``object_id``, in
    scene order."""
    out = []
    for oid, o in scene.objects.items():
        if oid == object_id or not o.placed:
            continue
        seen = {oid}
        e = scene.pag.supporter(oid)
        while e is not None and not e.parent.is_room_element:
            p = e.parent.object
            if p == object_id:
                out.append(oid)
                break
            if p in seen:
                break
            seen.add(p)
            e = scene.pag.supporter(p)
    return tuple(out)


def verify_settled(scene: Scene, *, fall_distance: float | None = None,
                   tip_angle_deg: float | None = None) -> list[Instability]:
    """Report every object that fell, tipped, left its support or broke its support relation.

    Parameters
    ----------
    scene : Scene
        A settled scene (``parse3d.physics.settle`` has run: settled poses and flags are set).
    fall_distance : float, optional
        Metres; default: the settling run's ``fall_distance`` (0.05).
    tip_angle_deg : float, optional
        Degrees; default: the settling run's ``tip_angle_deg`` (15).

    Returns
    -------
    list of Instability
        In scene order, causes per object in :data:`INSTABILITY_CAUSES` order; empty when the
        scene stayed as solved.

    Raises
    ------
    ValueError
        The scene has not been settled.
    """
    if not scene.settled:
        raise ValueError("verify_settled needs a settled scene: run parse3d.physics.settle first")
    cfg = dict(_DEFAULTS)
    cfg.update({k: v for k, v in scene.meta.get("settle", {}).get("config", {}).items()
                if k in cfg})
    fall = cfg["fall_distance"] if fall_distance is None else float(fall_distance)
    tip = cfg["tip_angle_deg"] if tip_angle_deg is None else float(tip_angle_deg)
    resolved = {int(k): v for k, v in scene.meta.get("resolved", {}).items()}
    settled_checks = {c.index: c for c in scene.relations}
    index = {id(e): i for i, e in enumerate(scene.pag.relations)}
    out: list[Instability] = []
    for oid, o in scene.objects.items():
        if not o.placed or o.fixed or o.settled_position is None:
            continue
        found: list[Instability] = []
        edge = scene.pag.supporter(oid)
        owner = scene.objects.get(_holder(edge, o)) if edge is not None else None
        owner = owner if owner is not None and owner.placed else None
        com0, com1 = _com(o, settled=False), _com(o, settled=True)
        sunk = float(com0[2] - com1[2])
        # really off: the centre of mass no longer over what held it up
        off = owner is not None and not _over(owner, com1)
        drop = float(o.position[2] - o.settled_position[2])
        if drop > fall and (off or (owner is None and sunk > fall)):
            found.append(Instability(oid, "fell", f"dropped {drop:.3f} m (more than {fall} m)"
                                     + (f", off {owner.id}" if off else ""), drop))
        up0 = np.asarray(o.rotation)[:, 2]
        up1 = np.asarray(o.settled_rotation)[:, 2]
        tilt = float(np.degrees(np.arccos(np.clip(up0 @ up1 / (np.linalg.norm(up0) *
                                                              np.linalg.norm(up1)), -1, 1))))
        # turned and lower, unless round or still held as the writer meant: fallen over
        if tilt > tip and sunk > TIP_DROP and not is_round(o) and (
                off or "left_support" in o.flags or settled_rest(scene, o) is None):
            found.append(Instability(oid, "tipped", f"up axis turned {tilt:.1f} deg "
                                     f"(more than {tip} deg), centre of mass {sunk:.3f} m lower",
                                     tilt))
        if "left_support" in o.flags and off:
            found.append(Instability(oid, "left_support",
                                     f"no longer touches {edge.parent if edge else 'its support'}"))
        elif edge is not None and not o.stacked_on:
            i = index[id(edge)]
            parent = scene.objects.get(edge.parent.object)
            c = settled_checks.get(i)
            if c is not None and c.relaxed is not None and c.holds is False:
                pass  # relaxed when solved (placed by another part, beside a round parent)
            elif parent is None or parent.placed:
                holds, detail = True, ""
                if c is None or c.holds_settled is not True:  # measure it (and say why)
                    holds, _, detail = check_edge(scene, edge, o, resolved=resolved.get(i),
                                                  settled=True)
                if not holds:
                    found.append(Instability(oid, "broke_support",
                                             f"{edge.relation} {edge.child} -> {edge.parent}: "
                                             f"{detail}", relation=i))
        if found:
            carries = supported_by(scene, oid)
            out.extend(Instability(f.object_id, f.cause, f.detail, f.value, f.relation, carries)
                       for f in found)
    return out


#: Metres the centre of mass must drop for a turned object to count as ``tipped``.
TIP_DROP = 0.02
#: Metres within which a settled object still touches what it leans on (the contacts' 1 mm,
#: plus the gap PhysX keeps between resting bodies).
LEAN_TOUCH = 0.003
#: Height, as a share of its longest horizontal extent, up to which a content lies (has no
#: upright to fall from).
LYING = 1.0


def settled_rest(scene: Scene, obj) -> str | None:
    """Why a settled object that turned is still resting as its PAG meant, or None.

    Two kinds of object have no upright pose to fall from (docs/solver.md, "Verification after
    settling"):

    ``"in its container"``
        a content lying in its container (``IN`` a bowl, a basket, a crate, or resting there
        beside a round parent it was written ``ON``; placed no taller than (:data:`LYING` times)
        its length) whose centre of mass ends over the container's settled footprint, no higher
        above its top than its own length (on the heap): fruit, bread and bananas tumble in a bowl, they do not tip (a book
        standing in a bookcase has an upright and still tips);
    ``"still leaning"``
        a child ``LEANING_AGAINST`` an object that still touches the part it leans on (the
        parts its reference names, else any; within :data:`LEAN_TOUCH`, exact convex
        distances) at a tilt the relation dictionary allows (at most ``angle_deg``'s upper
        bound, 60 degrees): a pillow slumped further against a headboard, a cushion against an
        armchair's back.

    The caller checks the rest: the object still touches its supporter and its centre of mass
    is over it.
    """
    edge = scene.pag.supporter(obj.id)
    if edge is None:
        return None
    holder = _holder(edge, obj)
    under = scene.pag.supporter(holder) if holder in scene.pag.objects else None
    if edge.relation == "ON" and holder == edge.parent.object and under is not None \
            and under.relation == "IN" and set(scene.pag.objects[obj.id].candidates) \
            & set(scene.pag.objects[holder].candidates):
        holder = under.parent.object  # ON one of its kind in a container: a pile there
    box = scene.objects.get(holder)
    if box is not None and box.placed and (edge.relation == "IN" or holder != edge.parent.object) \
            and _lying(obj):
        com = _com(obj, settled=True)
        # on the heap in it, not above it
        top = float(world_points(box, hull_only=True, settled=True)[:, 2].max()) \
            + float(hull_extents(obj.asset)[0].max()) * obj.scale
        if com[2] <= top and _over(box, com):
            return "in its container"
    for e in scene.pag.edges_of(obj.id):
        if e.relation != "LEANING_AGAINST" or e.parent.is_room_element:
            continue
        other = scene.objects.get(e.parent.object)
        if other is None or not other.placed:
            continue
        parts = select_parts(other, e.parent) or list(other.asset.parts)
        if _lean_tilt(scene, obj) <= e.spec.param("angle_deg").high + 1.0 \
                and _distance(obj, other, parts) <= LEAN_TOUCH:
            return "still leaning"
    return None


#: Share of its middle extent up to which an object's smallest extent makes it flat (a plate, a
#: photo frame, a pillow, a slab of yokan): lying on its broad face is a rest it can keep.
FLAT_SHARE = 0.5
#: Degrees from vertical within which a flat object's thin axis lies for it to lie flat (or
#: leaned back on its broad face: a photo frame fallen back against the wall behind the mantel).
LIE_DEG = 45.0


def lies_flat(scene: Scene, obj) -> str | None:
    """Where a settled flat object that fell over lies, or None.

    A flat object (its smallest extent at most :data:`FLAT_SHARE` of the next) that settling
    laid on its broad face (its thin axis within :data:`LIE_DEG` of vertical: lying, or fallen
    back against something behind it) on what held it up
    (it touches it within :data:`LEAN_TOUCH`, exact convex distances, with its centre of mass
    over it) keeps that rest: a plate stood on its rim that fell flat on the shelf, a photo
    frame with no stand lying on the mantel. The repair after settling takes that pose as the
    object's own rather than failing it (``parse3d.pipeline.settle_and_repair``). A lamp or a
    cup on its side is not flat, and one that left its support (on the floor below) is not
    where the writer put it.
    """
    edge = scene.pag.supporter(obj.id)
    if edge is None or not obj.placed or obj.fixed or obj.settled_rotation is None:
        return None
    holder = scene.objects.get(_holder(edge, obj))
    if holder is None or not holder.placed or holder.settled_rotation is None:
        return None
    ext, order = hull_extents(obj.asset)
    if float(ext[order[0]]) > FLAT_SHARE * float(ext[order[1]]):
        return None
    thin = np.asarray(obj.settled_rotation, float)[:, order[0]]
    if abs(float(thin[2])) < np.cos(np.radians(LIE_DEG)):
        return None
    if not _over(holder, _com(obj, settled=True)) \
            or _distance(obj, holder, list(holder.asset.parts)) > LEAN_TOUCH:
        return None
    return f"lies on its broad face on {holder.id}"


def _holder(edge, obj) -> str:
    """The id of what holds ``obj`` up: the support the solver chose where it is another object
    than written (an apple resting in the bowl beside its round parent), else the parent."""
    choice = obj.support_choice
    if choice is not None and choice.owner not in ("room", edge.parent.object):
        return choice.owner
    return edge.parent.object


def _lying(obj) -> bool:
    """Whether ``obj`` was placed lying: its height at most :data:`LYING` of its longest
    horizontal extent (solved pose)."""
    ext = np.ptp(world_points(obj, hull_only=True, settled=False), axis=0)
    return bool(ext[2] <= LYING * max(ext[0], ext[1]))


def _lean_tilt(scene: Scene, obj) -> float:
    """Degrees between vertical and the settled up axis a leaning child leans by (its back for a
    flat child standing on its edge, as the ``LEANING_AGAINST`` check reads it)."""
    u = np.asarray(obj.settled_rotation) @ lean_up(obj.asset, scene.pag, obj.id)
    return float(np.degrees(np.arccos(np.clip(u[2] / np.linalg.norm(u), -1, 1))))


def _distance(a, b, parts: list) -> float:
    """Exact distance (m) between a settled object's collision pieces and those of ``parts``
    of another."""
    return pieces_distance(piece_data(a.asset, a.asset.parts), a.transform(True),
                           piece_data(b.asset, parts), b.transform(True), limit=LEAN_TOUCH)



def _com(obj, *, settled: bool) -> np.ndarray:
    """World centre of mass, (3,), at the solved or settled pose."""
    T = obj.transform(settled)
    return T[:3, :3] @ asset_geometry(obj.asset).com + T[:3, 3]


def _over(owner, com: np.ndarray) -> bool:
    """Whether ``com`` lies over the settled horizontal footprint of ``owner`` (1 cm margin)."""
    from shapely.geometry import MultiPoint, Point

    fp = MultiPoint(world_points(owner, hull_only=True, settled=True)[:, :2]).convex_hull
    return bool(fp.buffer(0.01).contains(Point(com[:2])))


@dataclass(frozen=True)
class SettledSummary:
    """Counts that say whether a solved and settled scene is what its PAG asked for.

    Attributes
    ----------
    objects, placed : int
    support_total, support_held : int
        Support relations (ON, IN, HANGING_BELOW, SECURED_TO) of placed children, and those
        that hold on the settled poses.
    other_total, other_held : int
        The same for every other relation.
    unstable : int
        Objects :func:`verify_settled` reports (any cause).
    """

    objects: int
    placed: int
    support_total: int
    support_held: int
    other_total: int
    other_held: int
    unstable: int

    @property
    def complete(self) -> bool:
        """Every object placed."""
        return self.placed == self.objects

    @property
    def other_fraction(self) -> float:
        return self.other_held / self.other_total if self.other_total else 1.0

    def keeps_relations(self, other: float = 0.95) -> bool:
        """Every support relation and at least ``other`` of the rest hold after settling."""
        return self.support_held == self.support_total and self.other_fraction >= other


def summarize_settled(scene: Scene) -> SettledSummary:
    """Count placed objects, relations holding after settling and unstable objects.

    A relation of an unplaced child counts as not holding.
    """
    if not scene.settled:
        raise ValueError("summarize_settled needs a settled scene: run parse3d.physics.settle first")
    held = {c.index: c.holds_settled for c in scene.relations}
    st, sh, ot, oh = 0, 0, 0, 0
    for i, e in enumerate(scene.pag.relations):
        ok = held.get(i) is True
        if e.is_support:
            st, sh = st + 1, sh + ok
        else:
            ot, oh = ot + 1, oh + ok
    return SettledSummary(len(scene.objects), sum(o.placed for o in scene.objects.values()),
                          st, sh, ot, oh, len({i.object_id for i in verify_settled(scene)}))


def broken_after_settling(scene: Scene) -> list[str]:
    """Every relation of a placed child that held after solving and fails on the settled
    poses, as ``"ON plate2 -> plate1:body (normals off by 10.77 deg)"`` lines, in PAG order;
    empty for a scene not settled."""
    if not scene.settled:
        return []
    out = []
    for c in scene.relations:
        if c.holds is True and c.holds_settled is False:
            e = scene.pag.relations[c.index]
            child = scene.objects.get(e.child.object)
            if child is None or not child.placed:
                continue
            res = c.residual_settled or {}
            what = ", ".join(f"{k} {v:g}" for k, v in res.items())
            out.append(f"{c.relation} {c.child} -> {c.parent}" + (f" ({what})" if what else ""))
    return out
