"""The Scene: a solved (and possibly settled) PAG.

A :class:`Scene` holds the room shell, one :class:`PlacedObject` per PAG object (with its asset,
uniform scale and world pose), the per-relation check results, timings and, once extracted,
the part-level contacts. It is the data the renderer, physics and exporters consume.

World frame: +Z up, metres. An object's world transform maps asset-frame points ``x`` to
``R @ (scale * x) + t``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from ..assets.model import Asset, Part
from ..geometry.frames import make_transform
from ..geometry.meshes import MeshArrays
from ..geometry.surfaces import Surface
from ..pag.model import PAG

if TYPE_CHECKING:
    import trimesh

__all__ = ["SupportChoice", "Repair", "PlacedObject", "ShellElement", "RoomShell", "RelationCheck", "Contact", "Scene"]


@dataclass(frozen=True)
class SupportChoice:
    """The part-level support the solver chose for an object.

    Attributes
    ----------
    owner : str
        The supporting object's id, or ``room`` for a room element.
    part : str or None
        The supporting part's name (``shelf_1``), or the room element (``floor``, ``wall_2``).
    surface : str
        The surface label used (``top``, ``front``, ...).
    """

    owner: str
    part: str | None
    surface: str

    @property
    def text(self) -> str:
        """``owner:part@surface``, or the room element's name."""
        if self.owner == "room":
            return str(self.part)
        return f"{self.owner}:{self.part}@{self.surface}"

    def to_dict(self) -> dict[str, Any]:
        return {"owner": self.owner, "part": self.part, "surface": self.surface}

    @classmethod
    def parse(cls, text: str) -> SupportChoice:
        """Read the ``parse3d-scene/1`` string form back (``desk:tabletop@top``, ``floor``)."""
        if ":" not in text:
            return cls("room", text.removeprefix("room:") or None, "top")
        owner, rest = text.split(":", 1)
        part, _, label = rest.partition("@")
        if owner == "room":
            return cls("room", part, label or "top")
        return cls(owner, part, label or "top")


@dataclass(frozen=True)
class Repair:
    """One repair of an object after settling: its round (1-based), what was wrong (``fell``,
    ``tipped``, ``left_support``, ``support relation``) and what was changed (``pose``,
    ``asset``, or ``rest``: the pose it came to rest in became its own)."""

    round: int
    cause: str
    action: str

    def to_dict(self) -> dict[str, Any]:
        return {"round": int(self.round), "cause": self.cause, "action": self.action}


@dataclass
class PlacedObject:
    """One object of a scene.

    Attributes
    ----------
    id : str
        The PAG object id.
    category : str
        The category chosen among the node's candidates.
    asset : Asset or None
        The asset instance (None when the object failed before an asset was chosen).
    scale : float
        Uniform scale applied to the asset.
    rotation : (3, 3) float
        World rotation of the solved pose.
    position : (3,) float
        World position of the asset origin (centre of its bbox bottom), metres.
    status : str
        ``placed`` or ``failed``.
    reason : str or None
        For failed objects: which constraint could not be met.
    trials : int
        Pose samples drawn before one validated.
    support : str or None
        The part-level support actually used, as text (``parent:part_name@surface`` or
        ``floor``); kept in step with ``support_choice``.
    fixed : bool
        Held in place during settling (SECURED_TO and HANGING_BELOW objects).
    settled_rotation, settled_position : array or None
        The pose after physics, when settled.
    joints : dict of str to float
        Joint values by joint name (radians or metres) for articulated assets; a joint not
        listed is at 0 (closed).
    support_choice : SupportChoice or None
        The typed support (set from ``support`` when only the text is given).
    repairs : list of Repair
        Re-placements after settling.
    stacked_on : str or None
        The id of the same-category object this one rests on in a pile or stack.
    rests_on : str or None
        The child's surface label that rests on its support when it is not the one its support
        relation names (a sheet of music standing on its lower edge on a music stand's ledge,
        leaning back on the desk: ``back``); None otherwise.
    """

    id: str
    category: str
    asset: Asset | None
    scale: float = 1.0
    rotation: np.ndarray = field(default_factory=lambda: np.eye(3))
    position: np.ndarray = field(default_factory=lambda: np.zeros(3))
    status: str = "placed"
    reason: str | None = None
    trials: int = 0
    support: str | None = None
    fixed: bool = False
    settled_rotation: np.ndarray | None = None
    settled_position: np.ndarray | None = None
    flags: list[str] = field(default_factory=list)
    joints: dict[str, float] = field(default_factory=dict)
    support_choice: SupportChoice | None = None
    repairs: list[Repair] = field(default_factory=list)
    stacked_on: str | None = None
    rests_on: str | None = None

    def __post_init__(self):
        if self.support_choice is not None:
            self.support = self.support_choice.text
        elif self.support:
            self.support_choice = SupportChoice.parse(self.support)

    @property
    def placed(self) -> bool:
        return self.status == "placed"

    def transform(self, settled: bool | None = None) -> np.ndarray:
        """(4, 4) asset-to-world transform (scale included).

        ``settled=None`` uses the settled pose when there is one, else the solved pose.
        """
        use_settled = self.settled_position is not None if settled is None else settled
        if use_settled and self.settled_position is not None:
            return make_transform(self.settled_rotation, self.settled_position, self.scale)
        return make_transform(self.rotation, self.position, self.scale)

    def part_mesh(self, part: Part, settled: bool | None = None) -> trimesh.Trimesh:
        """A world-frame copy of one part's mesh."""
        m = part.mesh.copy()
        m.apply_transform(self.transform(settled))
        return m

    def mesh(self, settled: bool | None = None) -> trimesh.Trimesh:
        """The whole object as one world-frame mesh."""
        m = self.asset.mesh()
        m.apply_transform(self.transform(settled))
        return m

    def world_surface(self, part: Part, label: str, settled: bool | None = None) -> Surface:
        return part.surfaces[label].transformed(self.transform(settled))

    def world_bounds(self, settled: bool | None = None) -> np.ndarray:
        """(2, 3) world AABB of the object's visual mesh."""
        T = self.transform(settled)
        pts = np.vstack([p.vertices for p in self.asset.parts]) @ T[:3, :3].T + T[:3, 3]
        return np.array([pts.min(axis=0), pts.max(axis=0)])


class ShellElement:
    """A static element of the room shell: the floor, a wall or the ceiling.

    Attributes
    ----------
    name : str
        ``floor``, ``ceiling`` or ``wall_i``.
    mesh : trimesh.Trimesh
        World-frame slab (walls and floor have thickness, outside the room volume). It may be
        given as :class:`~parse3d.geometry.meshes.MeshArrays` and is then made when first
        asked for; :attr:`mesh_arrays` reads the arrays without making it.
    surface : Surface
        The surface facing into the room (floor: up, ceiling: down, wall: inward).
    """

    def __init__(self, name: str, mesh, surface: Surface):
        self.name = name
        self._mesh = mesh
        self.surface = surface

    def __repr__(self) -> str:
        return f"ShellElement(name={self.name!r}, surface={self.surface.label!r})"

    @property
    def mesh(self) -> trimesh.Trimesh:
        if isinstance(self._mesh, MeshArrays):
            self._mesh = self._mesh.to_trimesh()
        return self._mesh

    @property
    def mesh_arrays(self) -> MeshArrays:
        """The slab's vertices and faces, without making a ``trimesh.Trimesh``."""
        m = self._mesh
        return m if isinstance(m, MeshArrays) else MeshArrays(np.asarray(m.vertices), np.asarray(m.faces))


@dataclass
class RoomShell:
    """The room: footprint polygon (counter-clockwise), height, wall thickness and elements."""

    footprint: np.ndarray
    height: float
    wall_thickness: float
    elements: dict[str, ShellElement]

    @property
    def walls(self) -> list[ShellElement]:
        return [e for n, e in self.elements.items() if n.startswith("wall_")]

    @property
    def area(self) -> float:
        x, y = self.footprint[:, 0], self.footprint[:, 1]
        return float(0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


@dataclass
class RelationCheck:
    """Whether one PAG relation holds, measured on the geometry.

    Attributes
    ----------
    index : int
        Position of the edge in the PAG's ``relations``.
    relation, child, parent : str
        As written in the PAG.
    holds : bool or None
        After solving (None when the child failed).
    residual : dict
        Measured quantities (``distance`` m, ``angle_deg``, ``enclosure``, ``height`` ...).
    holds_settled : bool or None
        After settling (None until settled).
    residual_settled : dict or None
    relaxed : dict or None
        For a relation the solver relaxed (it could not be met with the object's support):
        ``{"blocked": what blocked it, "instead": what the writer could say instead}``.
    """

    index: int
    relation: str
    child: str
    parent: str
    holds: bool | None
    residual: dict[str, float] = field(default_factory=dict)
    holds_settled: bool | None = None
    residual_settled: dict[str, float] | None = None
    detail: str = ""
    relaxed: dict[str, str] | None = None


@dataclass(frozen=True)
class Contact:
    """One edge of the part-level contact graph.

    ``a`` and ``b`` are ``<object_id>:<part_name>`` (``room:floor`` for the shell), sorted.
    """

    a: str
    b: str
    samples: int
    min_distance: float

    def to_dict(self) -> dict[str, Any]:
        return {"a": self.a, "b": self.b, "samples": int(self.samples),
                "min_distance": round(float(self.min_distance), 6)}


def _outputs():
    # parse3d.outputs, found through the package root (it sits above this layer)
    from .._hooks import scene_outputs

    return scene_outputs()


@dataclass
class Scene:
    """A solved PAG.

    Attributes
    ----------
    pag : PAG
        The graph as given.
    seed : int
    room : RoomShell
    objects : dict of str to PlacedObject
        In assembly order.
    relations : list of RelationCheck
    timings : dict of str to float
        Seconds per stage (``solve``, ``settle``, ``contacts``, ...).
    contacts : list of Contact or None
    settled : bool
    meta : dict
        Solver configuration and statistics.
    log : list of str
        Internal errors met while solving, with their tracebacks (written to ``solve.log``,
        not to scene.json).
    """

    pag: PAG
    seed: int
    room: RoomShell
    objects: dict[str, PlacedObject] = field(default_factory=dict)
    relations: list[RelationCheck] = field(default_factory=list)
    timings: dict[str, float] = field(default_factory=dict)
    contacts: list[Contact] | None = None
    settled: bool = False
    meta: dict[str, Any] = field(default_factory=dict)
    log: list[str] = field(default_factory=list)

    @property
    def placed(self) -> list[PlacedObject]:
        return [o for o in self.objects.values() if o.placed]

    @property
    def failed(self) -> list[PlacedObject]:
        return [o for o in self.objects.values() if not o.placed]

    @property
    def ok(self) -> bool:
        return not self.failed

    @property
    def relaxed(self) -> list[RelationCheck]:
        """Relations the solver relaxed and that do not hold."""
        return [c for c in self.relations if c.relaxed]

    def save(self, out, *, formats=("glb",), preview: bool = False):
        """Write the scene into the folder ``out`` as ``parse3d solve`` does: ``scene.json``,
        ``contacts.json`` when extracted, ``scene.glb`` (or ``formats``), ``preview.png`` with
        ``preview``. Read it back with :func:`parse3d.load_scene`. Returns the folder."""
        return _outputs().save_scene(self, out, formats=tuple(formats), preview=preview)

    def export(self, path, *, settled: bool | None = None):
        """Write the scene to ``path`` in the format its suffix names: ``.glb``, ``.gltf``,
        ``.usd``/``.usda``/``.usdc``, ``.xml`` (MJCF), ``.urdf`` (the folder ``urdf/`` beside
        it), ``.obj``. ``settled`` picks the pose (None: the scene's own). Returns the files
        written."""
        return _outputs().export_file(self, path, settled=settled)

    def render(self, width: int = 640, height: int = 480, *, camera=None,
               settled: bool | None = None) -> np.ndarray:
        """The scene as an (H, W, 3) uint8 sRGB image, from the preview's viewpoint
        (:func:`parse3d.render.preview_camera`) or ``camera`` (a
        :class:`parse3d.render.Camera`, whose own size then applies). Depth and instance and
        part masks: :func:`parse3d.render.render_scene`."""
        return _outputs().render_scene_rgb(self, width, height, camera=camera, settled=settled)

    def show(self, path=None, *, open_browser: bool = True):
        """Open the scene in the web browser: a self-contained three.js page (orbit, zoom,
        hover names the object and part), written to ``path`` or a temporary file, which is
        returned. In a Jupyter notebook the viewer is shown in the cell's output instead (as
        when the scene is the cell's value)."""
        return _outputs().show_scene(self, path=path, open_browser=open_browser)

    def _repr_html_(self) -> str:
        return _outputs().repr_html(self)

    def __repr__(self) -> str:
        # the dataclass repr would print every mesh of every asset (hundreds of kB)
        n_c = "not extracted" if self.contacts is None else len(self.contacts)
        return (f"Scene({self.pag.name!r}, room={self.pag.room.type!r}, seed={self.seed}, "
                f"objects={len(self.objects)} ({len(self.placed)} placed), "
                f"relations={len(self.relations)}, contacts={n_c}, settled={self.settled})")
