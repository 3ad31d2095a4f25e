"""Relation checks on posed geometry, shared by the solver, settling and evaluations.

:mod:`.checks` holds one check rule per relation family, registered by relation name
(:data:`CHECK_RULES`); :mod:`.stability` verifies a settled scene (:func:`verify_settled`:
what fell, tipped, left its support or broke its support relation); :mod:`.geometry` is the
cached per-asset geometry they measure with.

>>> from parse3d.measure import CHECK_RULES
>>> from parse3d.relations import RELATIONS
>>> set(CHECK_RULES) == set(RELATIONS)
True
"""

from __future__ import annotations

from .checks import (
    ANGLE_TOL_DEG,
    CHECK_RULES,
    DIST_TOL,
    EPS,
    PENETRATION_TOL,
    Check,
    CheckContext,
    check_edge,
    check_relations,
    check_rule,
    object_centroid,
    select_parts,
    world_points,
)
from .stability import (
    INSTABILITY_CAUSES,
    Instability,
    SettledSummary,
    summarize_settled,
    supported_by,
    verify_settled,
)

__all__ = ["ANGLE_TOL_DEG", "CHECK_RULES", "DIST_TOL", "EPS", "PENETRATION_TOL", "Check",
           "CheckContext", "check_edge", "check_relations", "check_rule", "object_centroid",
           "select_parts", "world_points", "INSTABILITY_CAUSES", "Instability", "supported_by",
           "verify_settled", "SettledSummary", "summarize_settled"]
