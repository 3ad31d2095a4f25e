"""The relation checks the layout package measures with (its only import of them).

The solver's own geometric checks (``parse3d.solver.checks.check_relations``): a generated
layout is judged by exactly the tolerances the solver places with (docs/solver.md). When the
checks move to ``parse3d.measure`` this is the one line to change.
"""

from __future__ import annotations

from ..solver.checks import check_relations

__all__ = ["check_relations"]
