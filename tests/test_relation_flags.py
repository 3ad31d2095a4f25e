"""What kind of relation each is lives on the relation data (``parse3d.relations``), not in
lists copied across modules."""

from __future__ import annotations

from parse3d.relations import CONTACT_RELATIONS, RELATIONS, SUPPORT_RELATIONS


def test_support_and_contact_relations_come_from_the_relation_data():
    assert SUPPORT_RELATIONS == ("ON", "IN", "HANGING_BELOW", "SECURED_TO")
    assert CONTACT_RELATIONS == SUPPORT_RELATIONS + ("AGAINST", "LEANING_AGAINST")
    assert all(RELATIONS[n].is_contact for n in SUPPORT_RELATIONS)
    # surfaces parallel or coplanar at any distance, and layout relations, are not contacts
    assert not any(RELATIONS[n].is_contact for n in ("ALIGNED_WITH", "OPPOSITE_TO", "PARALLEL_TO",
                                                      "SIDE_OF", "NEAR", "TOWARD"))


def test_symmetric_relations_read_the_same_both_ways():
    sym = {n for n, r in RELATIONS.items() if r.is_symmetric}
    assert sym == {"NEAR", "FAR_FROM", "ALIGNED_WITH", "OPPOSITE_TO", "PARALLEL_TO"}
    # a side, a support or a facing direction is not
    assert not (sym & {"SIDE_OF", "ALONG", "TOWARD", "ON", "AGAINST", "LEANING_AGAINST"})
