"""Validation of ``pag/1`` documents: the schema layer, then the meaning layer.

:func:`validate_data` reports every problem of a document in one pass. The schema layer
(:func:`parse3d.pag.schema.schema_problems`) catches structural mistakes; the meaning layer
then checks whatever parts of the document are well-formed, even where the schema layer found
errors elsewhere:

* references: syntax, unknown objects (with the closest id as a suggestion), unknown surface
  labels, parts or ``#k`` on room elements, ``wall_i`` beyond the footprint's walls, parts or
  surfaces on object-level relations, an object related to itself;
* parameters: type, range, ``[low, high]`` order, parameters the relation does not take,
  required parameters that are missing (``side`` of ``SIDE_OF`` and ``ALONG``);
* the graph: duplicate ids, room elements as children, parents a relation cannot use (the
  ceiling under ``ON``), objects with no supporter or with two, cycles over all relations;
* the room: footprint a simple counter-clockwise polygon with area, positive height;
* sizes (finite, documented bounds, so that no input can make later stages run away):
  the footprint fits in a :data:`MAX_ROOM_EXTENT` square with coordinates within
  :data:`MAX_COORDINATE` of the origin and at most :data:`MAX_WALLS` vertices, the height is at
  most :data:`MAX_ROOM_HEIGHT`, scale factors lie in [:data:`MIN_SCALE`, :data:`MAX_SCALE`],
  and a PAG has at most :data:`MAX_OBJECTS` objects and :data:`MAX_RELATIONS` relations;
* the vocabulary, when one is given: category words and part words, resolved through the
  vocabulary file (:mod:`parse3d.words`: synonyms, hypernyms, part words), with suggestions by
  meaning for unknown words.

A document that passes is solvable in principle: no later stage fails for a reason these
checks could have caught.
"""

from __future__ import annotations

import math
import re
from collections import defaultdict
from collections.abc import Sequence
from typing import Any, Protocol

from ..errors import (
    GeometryInputError,
    GraphError,
    InputError,
    ParameterError,
    Problem,
    ReferenceError,
    SchemaError,
    VocabularyError,
)
from ..relations import RELATIONS, SURFACES, Param, Relation
from ..words import Resolver
from ..words import suggest as suggest_word
from .refs import Ref, RefSyntaxError, is_room_element, parse_ref, wall_index
from .schema import schema_problems, suggest

__all__ = ["Vocabulary", "validate_data", "error_for", "ROOM_PARENTS", "ROOM_SURFACES",
           "MAX_ROOM_EXTENT", "MAX_COORDINATE", "MAX_WALLS", "MAX_ROOM_HEIGHT", "MIN_SCALE",
           "MAX_SCALE", "MAX_OBJECTS", "MAX_RELATIONS", "MAX_ID_LENGTH"]

#: Largest footprint, metres: it must fit in a square of this side (1 km).
MAX_ROOM_EXTENT = 1000.0
#: Footprint coordinates lie within this distance of the origin, metres (10 km).
MAX_COORDINATE = 10_000.0
#: Most footprint vertices (walls) a room may have.
MAX_WALLS = 256
#: Highest room, metres.
MAX_ROOM_HEIGHT = 100.0
#: Range of an object's ``scale`` factors.
MIN_SCALE, MAX_SCALE = 0.01, 100.0
#: Most objects and relations of one PAG (PARSE-10K scenes have about 50 objects).
MAX_OBJECTS = 1000
MAX_RELATIONS = 10_000
#: Longest object id, characters.
MAX_ID_LENGTH = 100

_IDENT = re.compile(r"^[A-Za-z_][A-Za-z0-9_\-]*$")

#: The surface each room element offers to relations.
ROOM_SURFACES = {"floor": "top", "ceiling": "bottom", "wall": "front"}

_WALLS = "walls"
#: Which room elements may be the parent of each relation ("walls" is ``wall`` and ``wall_i``).
ROOM_PARENTS: dict[str, frozenset[str]] = {
    "ON": frozenset({"floor"}),
    "IN": frozenset(),
    "HANGING_BELOW": frozenset({"ceiling"}),
    "SECURED_TO": frozenset({_WALLS}),
    **{n: frozenset({_WALLS}) for n, r in RELATIONS.items() if not r.is_support},
}

_ROOM_HINT = {
    "floor": "the floor carries objects through ON",
    "ceiling": "use HANGING_BELOW to hang an object from the ceiling",
    _WALLS: "use SECURED_TO to mount an object on a wall",
}

_ERROR_OF_KIND = {
    "schema": SchemaError,
    "syntax": SchemaError,
    "reference": ReferenceError,
    "graph": GraphError,
    "parameter": ParameterError,
    "geometry": GeometryInputError,
    "vocabulary": VocabularyError,
}

_SUPPORT_NAMES = ", ".join(n for n, r in RELATIONS.items() if r.is_support)


class Vocabulary(Protocol):
    """What the validator asks of a category vocabulary (see ``parse3d.assets.registry``)."""

    def has_category(self, name: str) -> bool: ...

    def categories(self) -> list[str]: ...

    def parts(self, category: str) -> tuple[str, ...]: ...


def error_for(problems: Sequence[Problem], *, file: str | None = None) -> InputError:
    """The :class:`InputError` for some problems: the most specific subclass they all share."""
    kinds = {p.kind for p in problems}
    cls = _ERROR_OF_KIND.get(kinds.pop(), InputError) if len(kinds) == 1 else InputError
    return cls(list(problems), file=file)


def validate_data(
    data: Any,
    *,
    file: str | None = None,
    vocabulary: Vocabulary | None = None,
    raise_errors: bool = False,
) -> list[Problem]:
    """Every problem of a ``pag/1`` document, schema and meaning, in one pass.

    Parameters
    ----------
    data : any
        The parsed document (a dict for anything close to valid). Never raises on malformed
        input other than through ``raise_errors``.
    file : str, optional
        Recorded in each problem.
    vocabulary : Vocabulary, optional
        Category names and part labels to check against, e.g.
        ``parse3d.assets.registry.vocabulary()``. Without it, categories and part labels are
        not checked.
    raise_errors : bool
        Raise an :class:`InputError` (the most specific subclass shared by all problems)
        instead of returning a non-empty list.

    Returns
    -------
    list of Problem
        Schema problems first, then meaning problems in document order; empty when valid.
    """
    problems = _size_problems(data, file)
    if problems:  # checked first: the schema layer's time grows with the document
        if raise_errors:
            raise error_for(problems, file=file)
        return problems
    problems = schema_problems(data, file=file)
    if isinstance(data, dict):
        seen = {p.pointer for p in problems}
        for p in _Checker(data, vocabulary).run():
            if p.pointer not in seen:
                problems.append(Problem(p.pointer, p.message, file, p.kind))
        # a number JSON cannot hold, wherever it is (in ``meta`` too): the PAG could not be
        # written back
        seen = {p.pointer for p in problems}
        for ptr, v in _non_finite(data, ""):
            if not any(ptr == q or ptr.startswith(q + "/") for q in seen):
                problems.append(Problem(ptr, f"{v} is not a finite number (JSON has no NaN or "
                                        f"infinity): write a number or leave the field out",
                                        file, "parameter"))
    if raise_errors and problems:
        raise error_for(problems, file=file)
    return problems


def _non_finite(v: Any, pointer: str):
    """``(pointer, value)`` of every float in ``v`` that is NaN or infinite."""
    if isinstance(v, float) and not math.isfinite(v):
        yield pointer, v
    elif isinstance(v, dict):
        for k, x in v.items():
            yield from _non_finite(x, f"{pointer}/{str(k).replace('~', '~0').replace('/', '~1')}")
    elif isinstance(v, list):
        for i, x in enumerate(v):
            yield from _non_finite(x, f"{pointer}/{i}")


def _size_problems(data: Any, file: str | None) -> list[Problem]:
    out = []
    if isinstance(data, dict):
        for key, limit in (("objects", MAX_OBJECTS), ("relations", MAX_RELATIONS)):
            items = data.get(key)
            if isinstance(items, list) and len(items) > limit:
                out.append(Problem(f"/{key}", f"{len(items)} {key}: a PAG may have at most "
                                   f"{limit} (split the scene into several PAGs)", file,
                                   "parameter"))
    return out


def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _fmt(x: float) -> str:
    return f"{x:g}"


class _Checker:
    """One pass of meaning checks over a (possibly malformed) document."""

    def __init__(self, data: dict[str, Any], vocabulary: Vocabulary | None):
        self.data = data
        self.vocab = vocabulary
        self.resolver = Resolver(vocabulary) if vocabulary is not None else None
        #: per object id, the categories that came from a hypernym (any member may serve)
        self.drawn: dict[str, set[str]] = {}
        self.problems: list[Problem] = []
        self.n_walls: int | None = None
        self.ids: dict[str, int] = {}
        self.candidates: dict[str, tuple[str, ...]] = {}
        self.objects_known = True  # False when the object list is unreadable

    def add(self, pointer: str, message: str, kind: str) -> None:
        self.problems.append(Problem(pointer, message, None, kind))

    def run(self) -> list[Problem]:
        self.check_room(self.data.get("room"))
        self.check_objects(self.data.get("objects"))
        self.check_relations(self.data.get("relations"))
        self.check_viewpoint(self.data.get("viewpoint"))
        return self.problems

    def check_viewpoint(self, vp: Any) -> None:
        """The viewpoint names a wall or a position and a point looked at (not both); relations
        read in the camera's frame need one."""
        rels = self.data.get("relations")
        camera = [i for i, r in enumerate(rels if isinstance(rels, list) else [])
                  if isinstance(r, dict) and r.get("frame") == "camera"]
        if vp is None:
            if camera:
                self.add(f"/relations/{camera[0]}/frame", "\"frame\": \"camera\" reads the side as "
                         "seen from the PAG's viewpoint, and this PAG has none: add "
                         "\"viewpoint\": {\"wall\": \"wall_i\"} (the wall the photograph was taken "
                         "from) or {\"position\": [x, y], \"look_at\": [x, y]} at the top level",
                         "reference")
            return
        if not isinstance(vp, dict):
            return
        has_wall, has_pos = "wall" in vp, ("position" in vp or "look_at" in vp)
        if has_wall and has_pos:
            self.add("/viewpoint", "give either \"wall\" or \"position\" with \"look_at\", "
                     "not both", "reference")
        elif not has_wall and not ("position" in vp and "look_at" in vp):
            self.add("/viewpoint", "a viewpoint needs \"wall\": \"wall_i\", or both "
                     "\"position\": [x, y] and \"look_at\": [x, y]", "reference")
        elif has_wall:
            w = vp["wall"]
            if isinstance(w, str) and w.startswith("wall_") and w[5:].isdigit() \
                    and self.n_walls is not None and int(w[5:]) >= self.n_walls:
                self.add("/viewpoint/wall", f"{w!r} does not exist: this room has walls wall_0 "
                         f"to wall_{self.n_walls - 1}", "reference")
        else:
            p, q = vp["position"], vp["look_at"]
            if all(isinstance(v, list) and len(v) == 2 and all(_is_number(c) for c in v)
                   for v in (p, q)) and math.hypot(q[0] - p[0], q[1] - p[1]) < 1e-3:
                self.add("/viewpoint/look_at", "the point looked at must differ from the "
                         "position (at least 1 mm away on the floor plan)", "geometry")

    # ------------------------------------------------------------------ room
    def check_room(self, room: Any) -> None:
        if not isinstance(room, dict):
            return
        fp = room.get("footprint")
        if isinstance(fp, list):
            self.n_walls = len(fp)
            pts = []
            for v in fp:
                if not (isinstance(v, list) and len(v) == 2 and all(_is_number(c) for c in v)):
                    pts = None
                    break
                pts.append((float(v[0]), float(v[1])))
            if pts is not None:
                self.check_footprint(pts)
        h = room.get("height")
        if _is_number(h) and not (math.isfinite(h) and 0 < h <= MAX_ROOM_HEIGHT):
            self.add("/room/height", f"the room height must be a positive number of metres up "
                     f"to {MAX_ROOM_HEIGHT:g}, got {h}", "geometry")

    def check_footprint(self, pts: list[tuple[float, float]]) -> None:
        ptr = "/room/footprint"
        if len(pts) < 3:
            self.add(ptr, f"a footprint needs at least 3 vertices, got {len(pts)}", "geometry")
            return
        if not all(math.isfinite(c) for p in pts for c in p):
            self.add(ptr, "footprint coordinates must be finite numbers", "geometry")
            return
        if len(pts) > MAX_WALLS:
            self.add(ptr, f"a footprint may have at most {MAX_WALLS} vertices, got {len(pts)}",
                     "geometry")
            return
        far = next((k for k, p in enumerate(pts) if max(abs(p[0]), abs(p[1])) > MAX_COORDINATE),
                   None)
        if far is not None:
            self.add(f"{ptr}/{far}", f"footprint coordinates must lie within "
                     f"{MAX_COORDINATE:g} m of the origin, got {list(pts[far])}: move the room "
                     "nearer to (0, 0)", "geometry")
            return
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        extent = max(max(xs) - min(xs), max(ys) - min(ys))
        if extent > MAX_ROOM_EXTENT:
            self.add(ptr, f"the footprint spans {extent:g} m: a room must fit in a "
                     f"{MAX_ROOM_EXTENT:g} m square", "geometry")
            return
        n = len(pts)
        for i in range(n):
            j = (i + 1) % n
            if pts[i] == pts[j]:
                extra = (" (do not repeat the first vertex at the end: the polygon closes "
                         "itself)" if j == 0 else "")
                self.add(f"{ptr}/{j}", f"vertices {i} and {j} coincide, so wall_{i} would have "
                         f"zero length{extra}", "geometry")
                return
        area2 = sum(pts[i][0] * pts[(i + 1) % n][1] - pts[(i + 1) % n][0] * pts[i][1]
                    for i in range(n))
        scale = max(max(abs(c) for c in p) for p in pts) or 1.0
        x0, y0 = pts[0]
        ux, uy = max(((x - x0, y - y0) for x, y in pts), key=lambda d: abs(d[0]) + abs(d[1]))
        if all(abs(ux * (y - y0) - uy * (x - x0)) <= 1e-9 * scale * scale for x, y in pts):
            self.add(ptr, "the footprint encloses no area (its vertices are collinear)",
                     "geometry")
            return
        crossing = _self_crossing(pts)
        if crossing is not None:
            a, b = crossing
            self.add(ptr, f"the footprint is not a simple polygon: wall_{a} crosses wall_{b}",
                     "geometry")
            return
        if abs(area2) <= 1e-9 * scale * scale:
            self.add(ptr, "the footprint encloses no area", "geometry")
            return
        if area2 < 0:
            self.add(ptr, "the footprint is clockwise: list the vertices counter-clockwise "
                     "(seen from above), so that wall_i runs from vertex i to vertex i+1 with "
                     "the room on its left", "geometry")

    # --------------------------------------------------------------- objects
    def check_objects(self, objects: Any) -> None:
        if not isinstance(objects, list):
            self.objects_known = False
            return
        for j, o in enumerate(objects):
            if not isinstance(o, dict):
                continue
            base = f"/objects/{j}"
            oid = o.get("id")
            valid_id = isinstance(oid, str) and _IDENT.match(oid) is not None
            if valid_id and len(oid) > MAX_ID_LENGTH:
                self.add(f"{base}/id", f"object ids may have at most {MAX_ID_LENGTH} "
                         f"characters, got {len(oid)}", "reference")
                valid_id = False
            if valid_id:
                if is_room_element(oid):
                    self.add(f"{base}/id", f"{oid!r} names a room element; choose another id",
                             "reference")
                    valid_id = False
                elif oid in self.ids:
                    self.add(f"{base}/id", f"duplicate object id {oid!r} (first declared at "
                             f"/objects/{self.ids[oid]})", "reference")
                    valid_id = False
                else:
                    self.ids[oid] = j
            cands, drawn = self.check_category(base, o.get("category"))
            if valid_id:
                self.candidates[oid] = cands
                self.drawn[oid] = drawn
            self.check_scale(base, o.get("scale"))

    def check_category(self, base: str, cat: Any) -> tuple[tuple[str, ...], set[str]]:
        """The categories an object's words name, and those of them a hypernym gave."""
        if isinstance(cat, str):
            items = [(f"{base}/category", cat)]
        elif isinstance(cat, list):
            items = [(f"{base}/category/{k}", c) for k, c in enumerate(cat) if isinstance(c, str)]
        else:
            return (), set()
        known: list[str] = []
        drawn: set[str] = set()
        explicit: set[str] = set()
        for ptr, c in items:
            if not c:
                continue
            if self.resolver is None:
                known.append(c)
                continue
            got = self.resolver.categories_for(c)
            if got:
                known += [m for m in got if m not in known]
                if self.resolver.is_hypernym(c):
                    drawn.update(got)
                else:
                    explicit.update(got)
                continue
            self.add(ptr, f"unknown category {c!r}{suggest_word(c, self.resolver.words())}",
                     "vocabulary")
        return tuple(known), drawn - explicit

    def check_scale(self, base: str, scale: Any) -> None:
        if not (isinstance(scale, list) and len(scale) == 2 and all(map(_is_number, scale))):
            return
        lo, hi = scale
        if not (math.isfinite(lo) and math.isfinite(hi)) or lo <= 0 or hi <= 0:
            self.add(f"{base}/scale", f"scale factors must be positive, got [{lo}, {hi}]",
                     "parameter")
        elif not (MIN_SCALE <= lo <= MAX_SCALE and MIN_SCALE <= hi <= MAX_SCALE):
            self.add(f"{base}/scale", f"scale factors must lie in [{MIN_SCALE:g}, "
                     f"{MAX_SCALE:g}], got [{_fmt(lo)}, {_fmt(hi)}]", "parameter")
        elif lo > hi:
            self.add(f"{base}/scale", f"scale low {_fmt(lo)} is above high {_fmt(hi)}: write "
                     "[low, high]", "parameter")

    # ------------------------------------------------------------- relations
    def check_relations(self, relations: Any) -> None:
        supports: dict[str, list[tuple[int, str, str]]] = defaultdict(list)
        unsure: set[str] = set()  # children of relations whose name is unreadable
        edges: list[tuple[str, str, int]] = []
        if isinstance(relations, list):
            for i, r in enumerate(relations):
                if isinstance(r, dict):
                    self.check_relation(i, r, supports, unsure, edges)
        for oid, j in self.ids.items():
            sup = supports.get(oid)
            if not sup:
                if oid not in unsure:
                    self.add(f"/objects/{j}", f"object {oid!r} has no supporter: give it exactly "
                             f"one relation {_SUPPORT_NAMES} with child {oid!r} (e.g. ON floor)",
                             "graph")
            elif len(sup) > 1:
                (i0, r0, p0), (i1, r1, p1) = sup[0], sup[1]
                more = f" (and {len(sup) - 2} more)" if len(sup) > 2 else ""
                self.add(f"/relations/{i1}", f"object {oid!r} has two supporters: /relations/"
                         f"{i0} ({r0} {p0}) and /relations/{i1} ({r1} {p1}){more}; keep "
                         "exactly one support relation per object", "graph")
        for cycle, idx in _cycles(list(self.ids), edges):
            path = " -> ".join(cycle + [cycle[0]])
            where = ", ".join(f"/relations/{i}" for i in idx)
            self.add(f"/relations/{max(idx)}", f"the relations form a cycle: {path} (each arrow "
                     f"goes from child to parent, and a parent is placed before its children); "
                     f"remove or reverse one of {where}", "graph")

    def check_relation(self, i, r, supports, unsure, edges) -> None:
        base = f"/relations/{i}"
        name = r.get("relation")
        spec: Relation | None = RELATIONS.get(name) if isinstance(name, str) else None
        if isinstance(name, str) and spec is None:
            self.add(f"{base}/relation", f"unknown relation {name!r}"
                     f"{suggest(name.upper(), RELATIONS)} (one of: {', '.join(RELATIONS)})",
                     "reference")
        refs: dict[str, Ref] = {}
        for side in ("child", "parent"):
            text = r.get(side)
            if not isinstance(text, str):
                continue
            try:
                ref = parse_ref(text)
            except RefSyntaxError as e:
                self.add(f"{base}/{side}", str(e), "reference")
                continue
            if self.check_ref(f"{base}/{side}", side, ref, spec):
                refs[side] = ref
        child, parent = refs.get("child"), refs.get("parent")
        if spec is None:
            if child is not None and child.object in self.ids:
                unsure.add(child.object)
            return
        self.check_params(base, r, spec)
        if child is None or parent is None:
            if spec.is_support and child is not None:
                supports[child.object].append((i, name, str(r.get("parent"))))
            return
        if child.object == parent.object:
            if spec.is_support:
                supports[child.object].append((i, name, str(parent)))
            self.add(base, f"{child.object!r} cannot be related to itself: child and parent "
                     "must be different objects", "graph")
            return
        if parent.is_room_element:
            self.check_room_parent(f"{base}/parent", spec, parent)
        if spec.is_support:
            supports[child.object].append((i, name, str(parent)))
        if not parent.is_room_element:
            edges.append((child.object, parent.object, i))

    def check_ref(self, ptr: str, side: str, ref: Ref, spec: Relation | None) -> bool:
        """Check one reference; True when it names a real object or room element."""
        ok = True
        obj = ref.object
        if ref.surface is not None and ref.surface not in SURFACES:
            self.add(ptr, f"unknown surface {ref.surface!r}{suggest(ref.surface, SURFACES)} "
                     f"(surfaces: {', '.join(SURFACES)})", "reference")
        if is_room_element(obj):
            if side == "child":
                self.add(ptr, f"room element {obj!r} cannot be a child: the room is fixed; "
                         "objects are children of room elements (swap child and parent?)",
                         "graph")
                return False
            if ref.part is not None:
                self.add(ptr, f"room element {obj!r} has no parts: write {obj!r} without "
                         f"':{ref.part}'", "reference")
            k = wall_index(obj)
            if k is not None and self.n_walls is not None and k >= self.n_walls:
                self.add(ptr, f"there is no {obj!r}: the footprint has {self.n_walls} walls "
                         f"(wall_0 … wall_{self.n_walls - 1})", "reference")
                ok = False
            face = ROOM_SURFACES["wall" if obj.startswith("wall") else obj]
            if ref.surface in SURFACES and ref.surface != face:
                self.add(ptr, f"room element {obj!r} offers only its {face!r} surface, not "
                         f"{ref.surface!r}", "reference")
            return ok
        if obj not in self.ids:
            if not self.objects_known:
                return False
            pool = list(self.ids) + ["floor", "ceiling", "wall"]
            self.add(ptr, f"unknown object {obj!r}{suggest(obj, pool)}", "reference")
            return False
        if spec is not None and spec.is_object_level and (ref.part or ref.surface):
            self.add(ptr, f"{spec.name} relates whole objects: write {obj!r} without a part or "
                     "surface", "reference")
        if ref.part is not None and self.resolver is not None:
            self.check_part(ptr, obj, ref)
        return ok

    def check_part(self, ptr: str, obj: str, ref: Ref) -> None:
        """A part word must name parts of every category the object may be; of a hypernym's
        members, those that have it are drawn among (at least one must)."""
        cands = self.candidates.get(obj, ())
        drawn = self.drawn.get(obj, set())
        results = {c: self.resolver.part(c, ref.part, ref.surface) for c in cands}
        ambiguous = [r.problem for r in results.values()
                     if r.label is None and "names several" in (r.problem or "")]
        if ambiguous:
            self.add(ptr, ambiguous[0], "vocabulary")
            return
        for c, r in results.items():
            if r.label is None and c not in drawn:
                self.add(ptr, r.problem, "vocabulary")
        if drawn and not any(results[c].label for c in drawn if c in results):
            first = next(c for c in cands if c in drawn)
            self.add(ptr, f"no {'/'.join(sorted(drawn))} has a part {ref.part!r}: "
                     f"{results[first].problem}", "vocabulary")

    def check_room_parent(self, ptr: str, spec: Relation, parent: Ref) -> None:
        obj = parent.object
        key = _WALLS if obj.startswith("wall") else obj
        allowed = ROOM_PARENTS[spec.name]
        if key in allowed:
            return
        if allowed:
            names = " or ".join("a wall" if a == _WALLS else a for a in sorted(allowed))
            what = f"among room elements only {names} can be its parent"
        else:
            what = "its parent must be an object (a container), not a room element"
        hint = _ROOM_HINT[key] if spec.is_support else ""
        self.add(ptr, f"{spec.name} cannot use {obj!r} as parent: {what}"
                 + (f"; {hint}" if hint else ""), "reference")

    def check_params(self, base: str, r: dict[str, Any], spec: Relation) -> None:
        allowed = spec.param_names
        for key, value in r.items():
            if key in ("relation", "child", "parent"):
                continue
            if key not in allowed:
                if key in _ALL_PARAMS:
                    takes = (f"allowed: {', '.join(allowed)}" if allowed
                             else f"{spec.name} takes no parameters")
                    self.add(f"{base}/{key}", f"parameter {key!r} is not allowed for "
                             f"{spec.name} ({takes})", "parameter")
                continue
            msg = _param_problem(spec.param(key), value)
            if msg:
                self.add(f"{base}/{key}", msg, "parameter")
        for p in spec.params:
            if p.required and p.name not in r:
                choices = f" (one of {', '.join(p.choices)})" if p.choices else ""
                self.add(base, f"{spec.name} needs the parameter {p.name!r}{choices}",
                         "parameter")


_ALL_PARAMS = frozenset(p.name for r in RELATIONS.values() for p in r.params)


def _param_problem(p: Param, value: Any) -> str | None:
    unit = f" {p.unit}" if p.unit in ("m", "deg") else ""
    bounds = f"[{_fmt(p.low)}, {_fmt(p.high)}]{unit}" if p.low is not None else ""
    if p.type == "enum":
        if not isinstance(value, str) or value not in p.choices:
            hint = suggest(value, p.choices) if isinstance(value, str) else ""
            return f"{p.name} must be one of {', '.join(p.choices)}, got {value!r}{hint}"
        return None
    if p.type == "range" and isinstance(value, list):
        if len(value) != 2 or not all(map(_is_number, value)):
            return f"{p.name} must be a number or [low, high], got {value!r}"
        lo, hi = value
        if not (math.isfinite(lo) and math.isfinite(hi)):
            return f"{p.name} must be finite, got {value!r}"
        if lo > hi:
            return f"{p.name} low {_fmt(lo)} is above high {_fmt(hi)}: write [low, high]"
        for v in (lo, hi):
            if p.low is not None and not (p.low <= v <= p.high):
                return f"{p.name} {_fmt(v)}{unit} is out of range {bounds}"
        return None
    if not _is_number(value):
        form = "a number or [low, high]" if p.type == "range" else "a number"
        return f"{p.name} must be {form}, got {value!r}"
    if not math.isfinite(value):
        return f"{p.name} must be finite, got {value!r}"
    if p.low is not None and not (p.low <= value <= p.high):
        return f"{p.name} {_fmt(value)}{unit} is out of range {bounds}"
    return None


def _orient(a: tuple[float, float], b: tuple[float, float], c: tuple[float, float]) -> int:
    """Sign of the turn a -> b -> c: 1 left, -1 right, 0 collinear (exact)."""
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    mag = max(abs(b[0] - a[0]), abs(b[1] - a[1]), abs(c[0] - a[0]), abs(c[1] - a[1]))
    if abs(d) <= 1e-9 * mag * mag:  # near zero: decide in exact rational arithmetic
        from fractions import Fraction as F

        d = ((F(b[0]) - F(a[0])) * (F(c[1]) - F(a[1]))
             - (F(b[1]) - F(a[1])) * (F(c[0]) - F(a[0])))
    return (d > 0) - (d < 0)


def _on_segment(p, q, r) -> bool:
    """r, collinear with segment pq, lies on it (ends included)."""
    return min(p[0], q[0]) <= r[0] <= max(p[0], q[0]) and min(p[1], q[1]) <= r[1] <= max(p[1], q[1])


def _segments_meet(p1, p2, q1, q2) -> bool:
    """Closed segments p1p2 and q1q2 share at least one point."""
    o1, o2 = _orient(p1, p2, q1), _orient(p1, p2, q2)
    o3, o4 = _orient(q1, q2, p1), _orient(q1, q2, p2)
    if o1 != o2 and o3 != o4 and 0 not in (o1, o2, o3, o4):
        return True
    return ((o1 == 0 and _on_segment(p1, p2, q1)) or (o2 == 0 and _on_segment(p1, p2, q2))
            or (o3 == 0 and _on_segment(q1, q2, p1)) or (o4 == 0 and _on_segment(q1, q2, p2)))


def _self_crossing(pts: list[tuple[float, float]]) -> tuple[int, int] | None:
    """The first pair of walls that meet other than at their shared corner, else None.

    Non-adjacent walls may not touch at all; adjacent walls (sharing a corner) may not fold
    back along each other. Exact predicates in plain Python (no geometry library to import,
    which would dominate ``parse3d validate``'s start-up).
    """
    n = len(pts)
    segs = [(tuple(pts[i]), tuple(pts[(i + 1) % n])) for i in range(n)]
    for a in range(n):
        for b in range(a + 1, n):
            if b == a + 1 or (a == 0 and b == n - 1):
                # the shared corner, and the far ends of the two walls
                (s0, s1), (t0, t1) = segs[a], segs[b]
                q, u, v = (s1, s0, t1) if b == a + 1 else (s0, s1, t0)
                if _orient(q, u, v) == 0 and ((u[0] - q[0]) * (v[0] - q[0])
                                              + (u[1] - q[1]) * (v[1] - q[1])) > 0:
                    return a, b
                continue
            if _segments_meet(*segs[a], *segs[b]):
                return a, b
    return None


def _cycles(nodes: list[str], edges: list[tuple[str, str, int]]):
    """Yield (cycle, relation indices) for each strongly connected group of objects.

    The cycle lists objects in order, each depending on the next; it starts at the group's
    first declared object. Iterative Tarjan: linear in the graph size.
    """
    adj: dict[str, list[tuple[str, int]]] = defaultdict(list)
    for c, p, i in edges:
        adj[c].append((p, i))
    order = {n: k for k, n in enumerate(nodes)}
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    on_stack: set[str] = set()
    stack: list[str] = []
    comps: list[list[str]] = []
    counter = 0
    for root in nodes:
        if root in index:
            continue
        work = [(root, 0)]
        while work:
            v, k = work.pop()
            if k == 0:
                index[v] = low[v] = counter
                counter += 1
                stack.append(v)
                on_stack.add(v)
            nbrs = adj.get(v, ())
            if k < len(nbrs):
                work.append((v, k + 1))
                w = nbrs[k][0]
                if w not in index:
                    work.append((w, 0))
                elif w in on_stack:
                    low[v] = min(low[v], index[w])
                continue
            if work:
                u = work[-1][0]
                low[u] = min(low[u], low[v])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on_stack.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                if len(comp) > 1:
                    comps.append(comp)
    for comp in sorted(comps, key=lambda c: min(order[n] for n in c)):
        members = set(comp)
        start = min(comp, key=order.__getitem__)
        # Breadth-first search for the shortest way back to start inside the group.
        prev: dict[str, tuple[str, int]] = {}
        frontier = [start]
        found = None
        while frontier and found is None:
            nxt = []
            for v in frontier:
                for w, i in adj.get(v, ()):
                    if w not in members:
                        continue
                    if w == start:
                        found = (v, i)
                        break
                    if w not in prev:
                        prev[w] = (v, i)
                        nxt.append(w)
                if found:
                    break
            frontier = nxt
        v, i = found
        path, idx = [], [i]
        while v != start:
            path.append(v)
            v, i = prev[v]
            idx.append(i)
        path.append(start)
        yield path[::-1], sorted(idx)
