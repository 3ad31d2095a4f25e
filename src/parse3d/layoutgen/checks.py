"""The relation checks the layout package measures with (its only import of them).

The solver's own geometric checks (``check_relations``): a generated layout is judged by
exactly the tolerances the solver places with (docs/solver.md). They live in
``parse3d.measure``; trees from before that package existed have them in
``parse3d.solver.checks`` with the same signature.
"""

from __future__ import annotations

try:
    from ..measure import check_relations
except ImportError:  # a tree from before parse3d.measure
    from ..solver.checks import check_relations

__all__ = ["check_relations"]
