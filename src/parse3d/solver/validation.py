"""Checking a candidate pose: the object's relations measured as :mod:`parse3d.measure` does,
then collisions."""

from __future__ import annotations

from ..measure.checks import check_edge
from ..pag.model import Edge
from ..scene.model import PlacedObject
from .rules import RULES
from .rules.layout import relaxed_to_nearest
from .state import SolveState
from .support import Support

__all__ = ["validate_pose", "resolution", "relations_and_collisions"]


def validate_pose(st: SolveState, cand: PlacedObject, support_edge: Edge, others: list[Edge],
                  sup: Support) -> tuple[bool, str, list]:
    """Check a candidate pose against the support edge (resolved on ``sup``) and the object's
    other relations, in that order (a layout relation relaxed to its nearest positions does not
    reject it): ``(True, "", checks)`` with one ``(holds, residuals,
    detail)`` per edge, or ``(False, why the first one failed, [])``."""
    results = []
    for e in [support_edge, *others]:
        holds, res, detail = check_edge(st.scene, e, cand, resolved=resolution(e, sup.choice))
        if not holds and not relaxed_to_nearest(e):
            return False, f"{e.relation} {e.child} -> {e.parent}: {detail}", []
        results.append((holds, res, detail))
    return True, "", results


def resolution(edge: Edge, choice, *, final: bool = False) -> dict | None:
    """What the checks need to know of a support edge's resolution (part, element, surface);
    ``final`` is the form kept in ``scene.meta["resolved"]`` (no surface for room elements)."""
    if not edge.is_support:
        return None
    room = choice.owner == "room"
    return {"parent_part": None if room else choice.part,
            "parent_element": choice.part if room else None,
            "parent_surface": None if room and final else choice.surface,
            "internal": RULES[edge.relation].internal and not (room and final)}


def relations_and_collisions(st, cand, others, body, R, t) -> tuple[list | None, str]:
    """Check a piled candidate pose against the object's other relations, then for collisions
    (``body`` is moved to the pose). Returns ``(checks, "")``, or ``(None, why it failed)``."""
    checks = []
    for e in others:
        holds, res, detail = check_edge(st.scene, e, cand)
        if not holds and not relaxed_to_nearest(e):
            return None, f"{e.relation} {e.child} -> {e.parent}: {detail}"
        checks.append((holds, res, detail))
    body.move(R, t)
    hit = st.world.collides(body)
    if hit is not None:
        return None, f"collides with {hit}"
    return checks, ""

