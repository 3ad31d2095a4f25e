"""Graph algorithms over a :class:`~parse3d.pag.model.PAG`.

Every relation points from child to parent and the parent is placed first. Room elements
(``floor``, ``ceiling``, ``wall``, ``wall_i``) are fixed roots: they appear as parents but are
never placed, so they are not part of the assembly order.

All functions are linear in the size of the graph and deterministic: ties are broken by the
order in which objects are declared.

Examples
--------
>>> from parse3d.pag import PAG, Room
>>> pag = PAG("corner", Room("study", ((0, 0), (4, 0), (4, 3), (0, 3)), 2.7))
>>> for oid, cat in [("mug", "mug"), ("desk", "desk"), ("chair", "office_chair")]:
...     _ = pag.add(oid, cat)
>>> _ = pag.relate("mug", "ON", "desk:tabletop")
>>> _ = pag.relate("desk", "ON", "floor")
>>> _ = pag.relate("chair", "ON", "floor")
>>> _ = pag.relate("chair", "TOWARD", "desk")
>>> assembly_order(pag)
['desk', 'mug', 'chair']
>>> descendants(pag, "desk")
['mug', 'chair']
"""

from __future__ import annotations

import heapq
from collections import defaultdict
from typing import TYPE_CHECKING

from ..errors import GraphError, Problem
from .model import PAG
from .refs import is_room_element

if TYPE_CHECKING:  # networkx costs a large share of a light command's start-up
    import networkx as nx

__all__ = ["support_tree", "support_depth", "assembly_order", "descendants", "dependency_graph"]


def support_tree(pag: PAG) -> dict[str, str]:
    """The supporter of each object: ``{child_id: parent_object_or_room_element}``.

    Built from the support relations (``ON``, ``IN``, ``HANGING_BELOW``, ``SECURED_TO``);
    in a valid PAG every object appears exactly once. Where a file gives two supporters the
    first one wins (validation reports the second).
    """
    tree: dict[str, str] = {}
    for e in pag.relations:
        if e.is_support and e.child.object not in tree:
            tree[e.child.object] = e.parent.object
    return tree


def support_depth(pag: PAG) -> dict[str, int]:
    """Depth of every object in the support tree: 1 for objects on a room element.

    Room elements have depth 0 (not listed). Objects without a supporter get depth 1, and an
    object whose support chain loops (an invalid PAG) gets the depth where the loop was found.
    """
    tree = support_tree(pag)
    depth: dict[str, int] = {}
    for oid in pag.objects:
        chain: list[str] = []
        on_chain: set[str] = set()
        v = oid
        # Walk up to a room element, an already known depth, or a loop.
        while v in pag.objects and v not in depth and v not in on_chain and v in tree:
            on_chain.add(v)
            chain.append(v)
            v = tree[v]
        if v in depth:
            base = depth[v]
        elif v in pag.objects and v not in on_chain:  # an object without a supporter
            depth[v] = base = 1
        else:  # a room element, an unknown parent, or a loop
            base = 0
        for k, w in enumerate(reversed(chain)):
            depth.setdefault(w, base + k + 1)
    return {oid: depth.get(oid, 1) for oid in pag.objects}


def _object_edges(pag: PAG) -> list[tuple[str, str]]:
    """(parent, child) pairs between declared objects, in relation order."""
    out = []
    for e in pag.relations:
        c, p = e.child.object, e.parent.object
        if c != p and c in pag.objects and p in pag.objects:
            out.append((p, c))
    return out


def assembly_order(pag: PAG) -> list[str]:
    """Object ids in an order where every parent comes before its children.

    Topological over all relations (support and constraint edges alike), parents first;
    among objects that are ready at the same time the one declared first goes first. Room
    elements are roots and are not listed.

    Raises
    ------
    GraphError
        If the relations form a cycle (validation reports it with the objects in order).
    """
    rank = {oid: k for k, oid in enumerate(pag.objects)}
    children: dict[str, list[str]] = defaultdict(list)
    indeg = dict.fromkeys(pag.objects, 0)
    for p, c in _object_edges(pag):
        children[p].append(c)
        indeg[c] += 1
    ready = [rank[o] for o, d in indeg.items() if d == 0]
    heapq.heapify(ready)
    ids = list(pag.objects)
    order: list[str] = []
    while ready:
        v = ids[heapq.heappop(ready)]
        order.append(v)
        for c in children[v]:
            indeg[c] -= 1
            if indeg[c] == 0:
                heapq.heappush(ready, rank[c])
    if len(order) < len(ids):
        stuck = [o for o in ids if indeg[o] > 0]
        raise GraphError(Problem("/relations", "the relations form a cycle through "
                                 f"{', '.join(repr(s) for s in stuck[:10])}", None, "graph"))
    return order


def descendants(pag: PAG, object_id: str) -> list[str]:
    """Every object that depends on ``object_id`` through any chain of relations.

    ``object_id`` may be an object or a room element (``descendants(pag, "wall_0")`` lists what
    is placed against wall 0 and everything that depends on those). The result is in
    assembly order and excludes ``object_id`` itself.

    Raises
    ------
    KeyError
        If ``object_id`` is neither an object of the PAG nor a room element.
    """
    if object_id not in pag.objects and not is_room_element(object_id):
        raise KeyError(f"unknown object {object_id!r}")
    children: dict[str, list[str]] = defaultdict(list)
    for e in pag.relations:
        c, p = e.child.object, e.parent.object
        if c != p and c in pag.objects:
            children[p].append(c)
    found = set()
    stack = [object_id]
    while stack:
        v = stack.pop()
        for c in children[v]:
            if c not in found and c != object_id:
                found.add(c)
                stack.append(c)
    try:
        order = assembly_order(pag)
    except GraphError:
        order = list(pag.objects)
    return [o for o in order if o in found]


def dependency_graph(pag: PAG) -> nx.DiGraph:
    """The PAG as a networkx graph with edges from parent to child.

    Nodes are the objects (attributes ``kind="object"``, ``category``, ``depth``) and the
    room elements that some relation names (``kind="room"``). Each edge carries
    ``relations``: the list of ``(relation, child_ref, parent_ref)`` between the two nodes, in
    file order, and ``support``: whether one of them is a support relation. So
    ``nx.topological_sort`` gives a valid assembly order and ``nx.descendants`` the dependants.
    """
    import networkx as nx

    g = nx.DiGraph(name=pag.name)
    depth = support_depth(pag)
    for oid, node in pag.objects.items():
        g.add_node(oid, kind="object", category=node.category, depth=depth[oid])
    for e in pag.relations:
        c, p = e.child.object, e.parent.object
        if c == p:
            continue
        for n in (c, p):
            if n not in g:
                g.add_node(n, kind="room" if is_room_element(n) else "unknown", depth=0)
        if g.has_edge(p, c):
            data = g.edges[p, c]
        else:
            g.add_edge(p, c, relations=[], support=False)
            data = g.edges[p, c]
        data["relations"].append((e.relation, str(e.child), str(e.parent)))
        data["support"] = data["support"] or e.is_support
    return g
