"""The Part-centric Assembly Graph (PAG) data model.

A :class:`PAG` stores a room, object nodes and relation edges exactly as a ``pag/1`` file
describes them, so that ``PAG.from_dict(d).to_dict() == d`` for every valid document. The
support edge of each object is indexed by child (``PAG.supporter``), so "exactly one supporter"
is a property the builder keeps by construction and the validator reports when a file breaks it.

Algorithms over the graph (support tree, assembly order, descendants) are free functions in
:mod:`parse3d.pag.algorithms`; validation lives in :mod:`parse3d.pag.validate`.
"""

from __future__ import annotations

import copy
import math
import operator
from dataclasses import dataclass, field
from typing import Any

from ..relations import RELATIONS, Param
from .refs import Ref, parse_ref

__all__ = ["PAG_FORMAT", "Room", "Viewpoint", "ObjectNode", "Edge", "PAG", "param_value"]

PAG_FORMAT = "pag/1"


@dataclass(frozen=True)
class Room:
    """The room shell.

    Attributes
    ----------
    type : str
        Room type (``"bedroom"``, ``"kitchen"``, ...).
    footprint : tuple of (x, y)
        Simple polygon in metres, counter-clockwise; ``wall_i`` runs from vertex i to i+1.
    height : float
        Floor-to-ceiling height in metres.
    """

    type: str
    footprint: tuple[tuple[float, float], ...]
    height: float

    @property
    def n_walls(self) -> int:
        return len(self.footprint)

    def element_names(self) -> tuple[str, ...]:
        """All room element names: floor, ceiling, wall, wall_0 ... wall_{n-1}."""
        return ("floor", "ceiling", "wall") + tuple(f"wall_{i}" for i in range(self.n_walls))

    def to_dict(self) -> dict[str, Any]:
        return {
            "type": self.type,
            "footprint": [list(p) for p in self.footprint],
            "height": self.height,
        }


@dataclass(frozen=True)
class Viewpoint:
    """Where the scene is seen from: the camera of the photograph a PAG describes.

    Relations with ``"frame": "camera"`` (``SIDE_OF``, ``ALONG``) read their ``side`` as seen
    from here: ``left``/``right`` as the viewer sees them, ``front`` nearer the viewer, ``back``
    further away. Give either a wall (the camera stands at the middle of that wall's inner face,
    looking straight into the room) or a position and a point looked at (metres, floor plan).

    Attributes
    ----------
    wall : str or None
        ``"wall_i"``.
    position, look_at : (x, y) or None
    """

    wall: str | None = None
    position: tuple[float, float] | None = None
    look_at: tuple[float, float] | None = None

    def to_dict(self) -> dict[str, Any]:
        if self.wall is not None:
            return {"wall": self.wall}
        return {"position": list(self.position), "look_at": list(self.look_at)}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Viewpoint:
        if "wall" in d:
            return cls(wall=str(d["wall"]))
        return cls(position=(float(d["position"][0]), float(d["position"][1])),
                   look_at=(float(d["look_at"][0]), float(d["look_at"][1])))

    def view_direction(self, room: Room) -> tuple[float, float]:
        """Horizontal unit vector the camera looks along (world frame)."""
        if self.wall is not None:
            i = int(self.wall.split("_")[1])
            (x0, y0), (x1, y1) = room.footprint[i], room.footprint[(i + 1) % room.n_walls]
            dx, dy = -(y1 - y0), x1 - x0  # the inward normal of a counter-clockwise footprint
        else:
            dx, dy = self.look_at[0] - self.position[0], self.look_at[1] - self.position[1]
        n = math.hypot(dx, dy)
        return (dx / n, dy / n)

    def side_direction(self, room: Room, side: str) -> tuple[float, float, float]:
        """World unit vector of ``side`` as the camera sees it: ``right`` is the viewer's
        right, ``front`` points toward the camera, ``back`` away from it."""
        dx, dy = self.view_direction(room)
        return {"right": (dy, -dx, 0.0), "left": (-dy, dx, 0.0),
                "front": (-dx, -dy, 0.0), "back": (dx, dy, 0.0)}[side]


@dataclass(frozen=True)
class ObjectNode:
    """An object node: a semantic query, not a specific asset.

    Attributes
    ----------
    id : str
    category : str or tuple of str
        One category, or candidates the solver chooses among. Kept as written (a string stays a
        string) for exact round-trip; use :attr:`candidates` to read it.
    scale : tuple (low, high) or None
        Factor range applied on top of the category's own size range.
    extra : dict
        Any further keys of the node (kept for round-trip; the schema limits what is allowed).
    """

    id: str
    category: str | tuple[str, ...]
    scale: tuple[float, float] | None = None
    extra: dict[str, Any] = field(default_factory=dict, compare=True, hash=False)

    @property
    def candidates(self) -> tuple[str, ...]:
        return (self.category,) if isinstance(self.category, str) else tuple(self.category)

    def to_dict(self) -> dict[str, Any]:
        d: dict[str, Any] = {"id": self.id}
        d["category"] = self.category if isinstance(self.category, str) else list(self.category)
        if self.scale is not None:
            d["scale"] = list(self.scale)
        d.update(copy.deepcopy(self.extra))
        return d


@dataclass(frozen=True)
class Edge:
    """A relation edge from ``child`` to ``parent`` (the parent is placed first).

    Attributes
    ----------
    relation : str
        A name from :data:`parse3d.relations.RELATIONS`.
    child, parent : Ref
    params : dict
        Parameters as written in the file (defaults are not filled in; see :meth:`param`).
    """

    relation: str
    child: Ref
    parent: Ref
    params: dict[str, Any] = field(default_factory=dict, hash=False)

    @property
    def spec(self):
        return RELATIONS[self.relation]

    @property
    def is_support(self) -> bool:
        return self.spec.is_support

    def param(self, name: str) -> Any:
        """A parameter value with its default filled in; ranges come back as ``(low, high)``."""
        p = self.spec.param(name)
        return param_value(p, self.params.get(name, p.default))

    def to_dict(self) -> dict[str, Any]:
        d: dict[str, Any] = {
            "relation": self.relation,
            "child": str(self.child),
            "parent": str(self.parent),
        }
        d.update(copy.deepcopy(self.params))
        return d


def param_value(p: Param, value: Any) -> Any:
    """Normalise a parameter value: a range parameter given as a number becomes ``(v, v)``."""
    if value is None:
        return None
    if p.type == "range":
        if isinstance(value, (int, float)):
            return (float(value), float(value))
        lo, hi = value
        return (float(lo), float(hi))
    if p.type == "float":
        return float(value)
    return value


class PAG:
    """A Part-centric Assembly Graph.

    Build one from a file with :func:`parse3d.pag.load_pag`, from a dict with
    :meth:`from_dict`, or in Python with :meth:`add` and :meth:`relate`::

        pag = PAG("reading-corner", Room("study", ((0, 0), (4, 0), (4, 3.5), (0, 3.5)), 2.7))
        pag.add("desk", "desk")
        pag.relate("desk", "ON", "floor")
        pag.relate("desk:tabletop@back", "AGAINST", "wall_0")
        pag.add("lamp", ["table_lamp", "floor_lamp"], scale=(0.9, 1.1))
        pag.relate("lamp", "ON", "desk:tabletop")
        pag.validate()  # raises InputError listing every problem

    Attributes
    ----------
    name : str
    room : Room
    objects : dict of str to ObjectNode
        In declaration order.
    relations : list of Edge
        In declaration order.
    meta : dict
        Free-form metadata (kept for round-trip).
    viewpoint : Viewpoint or None
        Where the scene is seen from, for relations with ``"frame": "camera"``.
    """

    def __init__(
        self,
        name: str,
        room: Room,
        objects: list[ObjectNode] | None = None,
        relations: list[Edge] | None = None,
        *,
        meta: dict[str, Any] | None = None,
        viewpoint: Viewpoint | None = None,
    ):
        self.name = name
        self.room = room
        self.objects: dict[str, ObjectNode] = {}
        self.relations: list[Edge] = []
        self.meta: dict[str, Any] = dict(meta or {})
        self.viewpoint = viewpoint
        for o in objects or []:
            self.objects[o.id] = o
        for e in relations or []:
            self.relations.append(e)

    # ------------------------------------------------------------------ builder
    def add(
        self,
        id: str,
        category: str | list[str] | tuple[str, ...],
        *,
        scale: tuple[float, float] | None = None,
        yaw: str | None = None,
    ) -> ObjectNode:
        """Add an object node. Returns it. Raises InputError for a duplicate id.

        ``yaw="free"`` leaves the object's free angle unsquared (file key ``"yaw"``)."""
        from ..errors import InputError, Problem

        if id in self.objects:
            raise InputError(Problem(f"/objects/{len(self.objects)}/id",
                                     f"duplicate object id {id!r}", kind="reference"))
        cat = category if isinstance(category, str) else tuple(category)
        node = ObjectNode(id, cat, tuple(float(s) for s in scale) if scale is not None else None,
                          {"yaw": yaw} if yaw is not None else {})
        self.objects[id] = node
        return node

    def relate(self, child: str, relation: str, parent: str, **params: Any) -> Edge:
        """Add a relation edge ``child RELATION parent`` with parameters as keywords.

        Reference syntax is checked at once; everything else by :meth:`validate`.
        """
        from ..errors import InputError, Problem
        from .refs import RefSyntaxError

        i = len(self.relations)
        try:
            c = parse_ref(child)
            p = parse_ref(parent)
        except RefSyntaxError as e:
            raise InputError(Problem(f"/relations/{i}", str(e), kind="syntax")) from None
        norm = {k: (list(v) if isinstance(v, tuple) else v) for k, v in params.items()}
        edge = Edge(relation, c, p, norm)
        self.relations.append(edge)
        return edge

    def validate(self, *, vocabulary=None, file: str | None = None, words: bool = True) -> PAG:
        """Validate this graph as ``parse3d validate`` validates a file; raise InputError with
        every problem.

        Category and part words are checked against ``vocabulary``, by default the asset
        library's (the one the command line uses); ``words=False`` skips those checks.
        """
        from ..words import library_vocabulary
        from .validate import validate_data

        if vocabulary is None and words:
            vocabulary = library_vocabulary()
        validate_data(self.to_dict(), file=file, vocabulary=vocabulary, raise_errors=True)
        return self

    # --------------------------------------------------------------- accessors
    @property
    def object_ids(self) -> list[str]:
        return list(self.objects)

    def supporter(self, object_id: str) -> Edge | None:
        """The support edge of an object (ON, IN, HANGING_BELOW or SECURED_TO), if any."""
        es = self._by_child().get(object_id)
        return es[0] if es and es[0].relation in RELATIONS and es[0].is_support else None

    def edges_of(self, object_id: str) -> list[Edge]:
        """All edges whose child is ``object_id``, support edge first, then in file order."""
        return list(self._by_child().get(object_id, ()))

    def _by_child(self) -> dict[str, list[Edge]]:
        """Edges per child object, support edges first (a stable sort): an index rebuilt
        whenever ``relations`` is not the list of edges it was built from."""
        rel = self.relations
        got = self.__dict__.get("_child_index")
        # the same edges in the same order: compared by identity, item by item, in C
        if got is None or len(got[0]) != len(rel) or not all(map(operator.is_, got[0], rel)):
            idx: dict[str, list[Edge]] = {}
            for e in self.relations:
                idx.setdefault(e.child.object, []).append(e)
            for k, es in idx.items():
                idx[k] = sorted(es, key=lambda e: 0 if e.relation in RELATIONS
                                and e.is_support else 1)
            got = (list(rel), idx)
            self.__dict__["_child_index"] = got
        return got[1]

    def __len__(self) -> int:
        return len(self.objects)

    def __repr__(self) -> str:
        return (f"PAG(name={self.name!r}, room={self.room.type!r}, "
                f"objects={len(self.objects)}, relations={len(self.relations)})")

    def __eq__(self, other: object) -> bool:
        return isinstance(other, PAG) and self.to_dict() == other.to_dict()

    # ------------------------------------------------------------------- I/O
    def to_dict(self) -> dict[str, Any]:
        """The ``pag/1`` document of this graph."""
        d: dict[str, Any] = {
            "format": PAG_FORMAT,
            "name": self.name,
            "room": self.room.to_dict(),
            "objects": [o.to_dict() for o in self.objects.values()],
            "relations": [e.to_dict() for e in self.relations],
        }
        if self.viewpoint is not None:
            d["viewpoint"] = self.viewpoint.to_dict()
        if self.meta:
            d["meta"] = copy.deepcopy(self.meta)
        return d

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> PAG:
        """Build from a ``pag/1`` document that has passed validation.

        Use :func:`parse3d.pag.load_pag` or :func:`parse3d.pag.validate.validate_data` for
        documents that have not been validated: this constructor trusts its input.
        """
        room_d = data["room"]
        room = Room(
            str(room_d["type"]),
            tuple((float(x), float(y)) for x, y in room_d["footprint"]),
            float(room_d["height"]),
        )
        objects = []
        for o in data.get("objects", []):
            cat = o["category"]
            cat = cat if isinstance(cat, str) else tuple(cat)
            scale = tuple(float(s) for s in o["scale"]) if "scale" in o else None
            extra = {k: copy.deepcopy(v) for k, v in o.items() if k not in ("id", "category", "scale")}
            objects.append(ObjectNode(o["id"], cat, scale, extra))
        relations = []
        for r in data.get("relations", []):
            params = {k: copy.deepcopy(v) for k, v in r.items()
                      if k not in ("relation", "child", "parent")}
            relations.append(Edge(r["relation"], parse_ref(r["child"]), parse_ref(r["parent"]), params))
        return cls(str(data.get("name", "")), room, objects, relations,
                   meta=copy.deepcopy(data.get("meta") or {}),
                   viewpoint=Viewpoint.from_dict(data["viewpoint"]) if "viewpoint" in data else None)

    def copy(self) -> PAG:
        return PAG.from_dict(self.to_dict())
