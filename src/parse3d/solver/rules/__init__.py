"""What each relation means to the solver: one :class:`RelationRule` per relation family,
registered by relation name in :data:`RULES`.

========== ====================================================== ==========================
module     relations                                              region phase, relaxation
========== ====================================================== ==========================
support    ON, IN, HANGING_BELOW, SECURED_TO                      none; never relaxed
contact    AGAINST, LEANING_AGAINST                               part; after layout
alignment  ALIGNED_WITH, OPPOSITE_TO, PARALLEL_TO                 part (none: PARALLEL_TO)
layout     SIDE_OF, ALONG, NEAR, FAR_FROM, TOWARD                 object; first
========== ====================================================== ==========================

>>> from parse3d.solver.rules import RULES
>>> RULES["NEAR"].region_phase, RULES["AGAINST"].relax_order
('object', 1)
"""

from __future__ import annotations

from . import alignment, contact, layout, support  # noqa: F401  (each registers its rules)
from .base import (
    RULES,
    Orientation,
    RegionContext,
    RelationRule,
    contact_normal,
    parent_frame,
    parent_surface_world,
)
from .layout import side_vector

__all__ = ["RULES", "RelationRule", "rule_for", "Orientation", "RegionContext",
           "contact_normal", "parent_frame", "parent_surface_world", "side_vector"]


def rule_for(relation: str) -> RelationRule:
    """The rule of a relation name (``KeyError`` for a name not in the dictionary)."""
    return RULES[relation]
