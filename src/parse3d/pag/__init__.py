"""Part-centric Assembly Graphs: the model, the ``pag/1`` file, validation, graph algorithms.

Examples
--------
>>> from parse3d.pag import PAG, Room, assembly_order
>>> pag = PAG("corner", Room("study", ((0, 0), (4, 0), (4, 3), (0, 3)), 2.7))
>>> _ = pag.add("desk", "desk"); _ = pag.add("mug", "mug")
>>> _ = pag.relate("desk", "ON", "floor"); _ = pag.relate("mug", "ON", "desk:tabletop")
>>> assembly_order(pag.validate())
['desk', 'mug']
"""

from .algorithms import assembly_order, dependency_graph, descendants, support_depth, support_tree
from .io import dumps_pag, load_pag, read_document, save_pag
from .model import PAG, PAG_FORMAT, Edge, ObjectNode, Room, Viewpoint, param_value
from .refs import Ref, RefSyntaxError, is_room_element, parse_ref
from .schema import pag_schema, schema_problems
from .validate import validate_data

__all__ = [
    "PAG",
    "PAG_FORMAT",
    "Room",
    "Viewpoint",
    "ObjectNode",
    "Edge",
    "Ref",
    "RefSyntaxError",
    "param_value",
    "parse_ref",
    "is_room_element",
    "load_pag",
    "save_pag",
    "read_document",
    "dumps_pag",
    "pag_schema",
    "schema_problems",
    "validate_data",
    "support_tree",
    "support_depth",
    "assembly_order",
    "descendants",
    "dependency_graph",
]
