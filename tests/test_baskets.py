"""Picture books IN a basket on a shelf of a small bookcase: the basket drawn has a floor that
takes a book standing, at the scale the shelf leaves it (solver/standing.py)."""

from __future__ import annotations

import pytest

from test_rooms import solved

SEEDS = (0, 1, 2)


@pytest.mark.parametrize("seed", SEEDS)
def test_books_stand_in_a_basket_on_a_shelf(seed):
    """Every book is placed IN the basket, the relation holds after settling (or is recorded
    relaxed with its reason), and nothing fell."""
    scene = solved("books_in_baskets_on_a_low_shelf", seed)
    assert not scene.failed, [(o.id, o.reason) for o in scene.failed]
    ins = [c for c in scene.relations if c.relation == "IN" and c.parent.startswith("basket_a")]
    assert len(ins) == 3
    bad = [(c.child, c.residual_settled) for c in ins
           if c.holds_settled is not True and not getattr(c, "relaxed", None)]
    assert not bad, bad
    assert not [o.id for o in scene.objects.values() if o.flags and "fell" in o.flags]
