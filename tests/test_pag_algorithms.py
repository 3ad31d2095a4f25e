"""Support tree, assembly order, descendants and the dependency graph."""

from __future__ import annotations

from pathlib import Path

import networkx as nx
import pytest

from parse3d.errors import GraphError
from parse3d.pag import (
    PAG,
    Room,
    assembly_order,
    dependency_graph,
    descendants,
    load_pag,
    support_depth,
    support_tree,
)

EXAMPLES = sorted(p for p in (Path(__file__).parent.parent / "examples").glob("*.*")
                  if p.suffix in (".json", ".yaml"))  # not the notebook


def small() -> PAG:
    pag = PAG("t", Room("study", ((0, 0), (4, 0), (4, 3), (0, 3)), 2.7))
    for oid, cat in [("mug", "mug"), ("chair", "office_chair"), ("desk", "desk"),
                     ("lamp", "pendant_lamp"), ("book", "book"), ("shelf", "bookcase")]:
        pag.add(oid, cat)
    pag.relate("mug", "ON", "desk:tabletop")
    pag.relate("chair", "ON", "floor")
    pag.relate("chair", "TOWARD", "desk")
    pag.relate("desk", "ON", "floor")
    pag.relate("lamp", "HANGING_BELOW", "ceiling")
    pag.relate("book", "IN", "shelf:shelf#1")
    pag.relate("shelf", "ON", "floor")
    pag.relate("shelf:back_panel@back", "AGAINST", "wall_2")
    return pag


def test_support_tree_and_depth():
    pag = small()
    assert support_tree(pag) == {"mug": "desk", "chair": "floor", "desk": "floor",
                                 "lamp": "ceiling", "book": "shelf", "shelf": "floor"}
    assert support_depth(pag) == {"mug": 2, "chair": 1, "desk": 1, "lamp": 1, "book": 2,
                                  "shelf": 1}


def test_assembly_order_is_parents_first_ties_by_declaration():
    pag = small()
    assert assembly_order(pag) == ["desk", "mug", "chair", "lamp", "shelf", "book"]


def test_descendants():
    pag = small()
    assert descendants(pag, "desk") == ["mug", "chair"]
    assert descendants(pag, "floor") == ["desk", "mug", "chair", "shelf", "book"]
    assert descendants(pag, "wall_2") == ["shelf", "book"]
    assert descendants(pag, "mug") == []
    with pytest.raises(KeyError):
        descendants(pag, "sofa")


def test_dependency_graph():
    g = dependency_graph(small())
    assert g.nodes["desk"]["kind"] == "object" and g.nodes["floor"]["kind"] == "room"
    assert g.edges["desk", "chair"]["relations"] == [("TOWARD", "chair", "desk")]
    assert g.edges["desk", "chair"]["support"] is False
    assert g.edges["shelf", "book"]["support"] is True
    assert nx.is_directed_acyclic_graph(g)
    assert set(nx.descendants(g, "desk")) == {"mug", "chair"}


def test_cycle_raises_graph_error():
    pag = small()
    pag.relate("desk", "NEAR", "chair")
    with pytest.raises(GraphError, match="cycle"):
        assembly_order(pag)


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_examples_assembly_order_respects_every_edge(path):
    pag = load_pag(path)
    order = assembly_order(pag)
    assert sorted(order) == sorted(pag.objects)
    rank = {o: k for k, o in enumerate(order)}
    for e in pag.relations:
        if not e.parent.is_room_element:
            assert rank[e.parent.object] < rank[e.child.object], e
    assert set(support_tree(pag)) == set(pag.objects)
