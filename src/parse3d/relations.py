"""The relation dictionary of PAGs, as frozen data.

This mirrors the paper's supplementary table "Dictionary of Spatial Relations". Each relation is
a :class:`Relation` with its kind (``support``, ``part`` or ``object``), its default child and
parent surfaces, its parameters (type, unit, allowed range and default) and a one-line meaning
used in documentation and generated text. What a relation *means* geometrically is one check
rule per relation family in :mod:`parse3d.measure` (``CHECK_RULES``, the exact tests are in
docs/pag.md); how the solver constructs poses that satisfy it lives in :mod:`parse3d.solver`.

Examples
--------
>>> from parse3d.relations import RELATIONS
>>> RELATIONS["ON"].is_support
True
>>> RELATIONS["NEAR"].param("distance").default
1.0
"""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType

__all__ = [
    "SURFACES",
    "SUPPORT",
    "PART",
    "OBJECT",
    "Param",
    "Relation",
    "RELATIONS",
    "SUPPORT_RELATIONS",
    "CONTACT_RELATIONS",
    "relation_names",
    "get_relation",
]

#: The six directional surface labels of a part (DESIGN §3), with their outward normal in the
#: asset's canonical frame (+Z up, front +Y, right +X).
SURFACES: MappingProxyType[str, tuple[float, float, float]] = MappingProxyType(
    {
        "top": (0.0, 0.0, 1.0),
        "bottom": (0.0, 0.0, -1.0),
        "front": (0.0, 1.0, 0.0),
        "back": (0.0, -1.0, 0.0),
        "right": (1.0, 0.0, 0.0),
        "left": (-1.0, 0.0, 0.0),
    }
)

SUPPORT = "support"
PART = "part"
OBJECT = "object"

_CONTACT_PART_RELATIONS = frozenset({"AGAINST", "LEANING_AGAINST"})
_SYMMETRIC_RELATIONS = frozenset({"NEAR", "FAR_FROM", "ALIGNED_WITH", "OPPOSITE_TO", "PARALLEL_TO"})


@dataclass(frozen=True)
class Param:
    """One parameter of a relation.

    Attributes
    ----------
    name : str
        Key in the relation edge (``"distance"``, ``"angle_deg"``). Keys that carry degrees end
        in ``_deg``.
    type : str
        ``"float"`` (a number), ``"range"`` (a number or ``[low, high]``), or ``"enum"``.
    unit : str
        ``"m"``, ``"deg"``, ``"fraction"`` or ``""``.
    low, high : float or None
        Inclusive bounds of every allowed value (numeric types only).
    default : float, tuple of float, str or None
        The value used when the edge does not give one. ``None`` means the parameter is required.
    choices : tuple of str
        Allowed values of an ``enum``.
    doc : str
        One line saying what the parameter means.
    """

    name: str
    type: str
    unit: str = ""
    low: float | None = None
    high: float | None = None
    default: float | tuple[float, float] | str | None = None
    choices: tuple[str, ...] = ()
    doc: str = ""

    @property
    def required(self) -> bool:
        return self.default is None


@dataclass(frozen=True)
class Relation:
    """A relation type of the PAG.

    Attributes
    ----------
    name : str
        Upper-case name used in files (``"ON"``).
    kind : str
        ``"support"`` (defines the child's unique supporter and the assembly tree), ``"part"``
        (a fine-grained constraint between two part surfaces) or ``"object"`` (a coarse layout
        constraint between object centroids).
    child_surface, parent_surface : str or None
        Default surfaces used when a reference names none. ``None`` for object-level relations.
        For ``IN`` the parent surface is an *internal* upward support surface.
    params : tuple of Param
    meaning : str
        One line, written so that "<child> <meaning> <parent>" reads as a sentence.
    constraints : str
        The geometric constraints the solver enforces, as in the paper's table.
    phrase : str
        A short English phrase ("on", "leaning against").
    """

    name: str
    kind: str
    child_surface: str | None
    parent_surface: str | None
    params: tuple[Param, ...]
    meaning: str
    constraints: str
    phrase: str = ""

    @property
    def is_contact(self) -> bool:
        """Whether the relation holds only with the two touching: every support relation,
        ``AGAINST`` and ``LEANING_AGAINST`` (``ALIGNED_WITH`` and the other surface relations
        hold at any distance)."""
        return self.kind == SUPPORT or self.name in _CONTACT_PART_RELATIONS

    @property
    def is_symmetric(self) -> bool:
        """Whether "A rel B" says the same as "B rel A" (``NEAR``, ``FAR_FROM``,
        ``ALIGNED_WITH``, ``OPPOSITE_TO``, ``PARALLEL_TO``)."""
        return self.name in _SYMMETRIC_RELATIONS

    @property
    def is_support(self) -> bool:
        return self.kind == SUPPORT

    @property
    def is_object_level(self) -> bool:
        return self.kind == OBJECT

    def param(self, name: str) -> Param:
        for p in self.params:
            if p.name == name:
                return p
        raise KeyError(f"relation {self.name} has no parameter {name!r}")

    @property
    def param_names(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.params)


_SIDE = Param(
    "side",
    "enum",
    choices=("left", "right", "front", "back"),
    default=None,
    doc="which side of the parent, in the parent's own frame (or the camera's: `frame`)",
)
_FRAME = Param(
    "frame",
    "enum",
    choices=("parent", "camera"),
    default="parent",
    doc="whose left, right, front and back `side` means: the parent's own frame, or the "
    "camera's (as seen from the PAG's `viewpoint`, where the photograph was taken)",
)

_RELATIONS = (
    Relation(
        "ON",
        SUPPORT,
        "bottom",
        "top",
        (),
        "rests stably on",
        "contact dist(S_A, S_B) ~ 0; normals anti-parallel; centre of mass over the support polygon",
        "on",
    ),
    Relation(
        "IN",
        SUPPORT,
        "bottom",
        "top",
        (
            Param(
                "min_enclosure",
                "float",
                "fraction",
                0.0,
                1.0,
                0.5,
                doc="least fraction of rays from the child's centroid that must hit the parent "
                "(containers; open shelves need none)",
            ),
        ),
        "is contained inside",
        "contact with an internal upward support surface (or a pile on it); on a shelf part the child's "
        "centroid inside the parent's bbox footprint, in other containers ray-cast enclosure >= min_enclosure "
        "(rays from the centroid, at most halfway up from the surface to the parent's top)",
        "in",
    ),
    Relation(
        "HANGING_BELOW",
        SUPPORT,
        "top",
        "bottom",
        (
            Param(
                "drop",
                "range",
                "m",
                0.0,
                5.0,
                (0.0, 0.0),
                doc="gap between the parent's surface and the child's top, bridged by a cord or chain",
            ),
        ),
        "hangs below",
        "child top at `drop` below the parent's bottom surface; normals anti-parallel",
        "hanging below",
    ),
    Relation(
        "SECURED_TO",
        SUPPORT,
        "back",
        "front",
        (
            Param(
                "height",
                "range",
                "m",
                0.0,
                10.0,
                (1.2, 1.7),
                doc="height of the child's centre above the floor",
            ),
        ),
        "is fixed to",
        "contact dist(S_A, S_B) ~ 0; normals anti-parallel; centre height within `height`",
        "mounted on",
    ),
    Relation(
        "AGAINST",
        PART,
        "front",
        "front",
        (Param("gap", "float", "m", 0.0, 1.0, 0.0, doc="distance left between the two surfaces"),),
        "is pushed against",
        "dist(S_A, S_B) ~ gap; normals anti-parallel",
        "against",
    ),
    Relation(
        "LEANING_AGAINST",
        PART,
        "back",
        "front",
        (
            Param(
                "angle_deg",
                "range",
                "deg",
                1.0,
                60.0,
                (8.0, 16.0),
                doc="tilt of the child's up axis from vertical",
            ),
        ),
        "leans against",
        "the named part touches the parent surface (dist ~ 0), its named surface facing it, with the "
        "up axis tilted from vertical by angle_deg",
        "leaning against",
    ),
    Relation(
        "ALIGNED_WITH",
        PART,
        "front",
        "front",
        (),
        "is flush with",
        "coplanar surfaces; normals parallel",
        "aligned with",
    ),
    Relation(
        "OPPOSITE_TO",
        PART,
        "front",
        "front",
        (),
        "is back to back with",
        "coplanar surfaces; normals anti-parallel",
        "opposite to",
    ),
    Relation(
        "PARALLEL_TO",
        PART,
        "front",
        "front",
        (),
        "faces the same way as",
        "normals parallel, any distance",
        "parallel to",
    ),
    Relation(
        "SIDE_OF",
        OBJECT,
        None,
        None,
        (_SIDE, _FRAME),
        "is on one side of",
        "(x_A - x_B) . n_side > 0, with n_side in the parent's frame (or, with frame camera, "
        "the camera's)",
        "beside",
    ),
    Relation(
        "ALONG",
        OBJECT,
        None,
        None,
        (
            _SIDE,
            Param("width", "float", "m", 0.01, 20.0, 0.6, doc="depth of the strip along that side"),
            _FRAME,
        ),
        "is lined up along",
        "0 <= (x_A - x_B) . n_side - h_B <= width + h_A and |(x_A - x_B) . n_side^perp| <= "
        "max(e, e_A)/2: beside the parent's side face, the gap between the faces at most width "
        "(h_B from the parent's centroid to that face, h_A from the child's centroid to its near "
        "face, e the face's extent, e_A the child's extent along it)",
        "along",
    ),
    Relation(
        "NEAR",
        OBJECT,
        None,
        None,
        (Param("distance", "float", "m", 0.0, 50.0, 1.0, doc="largest centroid distance"),),
        "is near",
        "horizontal |x_A - x_B| < distance (to a wall: distance to its plane)",
        "near",
    ),
    Relation(
        "FAR_FROM",
        OBJECT,
        None,
        None,
        (Param("distance", "float", "m", 0.0, 50.0, 2.0, doc="smallest centroid distance"),),
        "is far from",
        "horizontal |x_A - x_B| > distance (to a wall: distance to its plane)",
        "far from",
    ),
    Relation(
        "TOWARD",
        OBJECT,
        None,
        None,
        (
            Param(
                "tolerance_deg",
                "float",
                "deg",
                0.0,
                180.0,
                10.0,
                doc="largest angle between the child's front and the direction to the parent",
            ),
        ),
        "faces",
        "horizontal angle between the child's front and x_B - x_A <= tolerance_deg (180: always holds)",
        "facing",
    ),
)

#: Every relation by name, in the paper's order.
RELATIONS: MappingProxyType[str, Relation] = MappingProxyType({r.name: r for r in _RELATIONS})
#: Names of the support relations (each object has exactly one), in the paper's order.
SUPPORT_RELATIONS: tuple[str, ...] = tuple(r.name for r in _RELATIONS if r.is_support)
#: Names of the relations that hold only in contact (:attr:`Relation.is_contact`).
CONTACT_RELATIONS: tuple[str, ...] = tuple(r.name for r in _RELATIONS if r.is_contact)


def relation_names() -> tuple[str, ...]:
    """Names of all relations, in the paper's order."""
    return tuple(RELATIONS)


def get_relation(name: str) -> Relation:
    """Look up a relation by name (case-sensitive, as in files)."""
    return RELATIONS[name]
