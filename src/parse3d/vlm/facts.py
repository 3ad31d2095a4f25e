"""What the benchmark knows about one scene and one view: the 3-D ground truth.

Everything comes from the dataset's own files, so a dataset can be turned into a benchmark
on any machine, without the asset library: ``scene.json`` (objects, settled poses, PAG
relations and whether they hold after settling), ``contacts.json`` (the part-level contact
graph), ``scene.glb`` (every part's world mesh) and ``views.json`` with the masks' pixel
counts and boxes.

Visibility by what is seen: an object is visible in a view when its instance mask has at
least ``min_pixels`` pixels and at least ``min_in_image`` of its projection lies inside the
image (the convex hull of its mesh projected on the unbounded image plane, clipped to the
image, over the same hull unclipped; an object reaching behind the near plane is cut off).
The share is a ratio of one hull to itself, so a floor lamp's pole or a cord, which make the
hull large and the mask thin, do not hide the object; occlusion is judged by the pixel floor
alone. A part likewise from the part mask.

Examples
--------
>>> import numpy as np
>>> float(hull_area(np.array([[0, 0], [10, 0], [10, 10], [0, 10], [5, 5]]), 640, 480))
100.0
>>> round(in_image_share(np.array([[-20.5, 0], [19.5, 0], [19.5, 10], [-20.5, 10]]), 640, 480), 3)
0.5
"""

from __future__ import annotations

import contextlib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError
from shapely.geometry import Polygon, box

from ..errors import InputError, Problem
from ..export.gltf import Z_UP_TO_Y_UP
from ..export.walk import node_name
from ..geometry.frames import quat_to_matrix
from ..pag.refs import RefSyntaxError, parse_ref, wall_index
from ..render.camera import Camera
from .vocab import (
    CAMERA_RELATIONS,
    CONTACT_RELATIONS,
    NO_CONTACT,
    RELATION_PHRASES,
    object_label,
    part_label,
)

__all__ = [
    "VisibilityRule",
    "ObjectFacts",
    "ViewFacts",
    "SceneFacts",
    "load_scene_facts",
    "hull_area",
    "in_image_share",
    "relation_sources",
    "view_facts",
    "pair_truth",
    "projected_box",
    "to_grid",
]

_Y_UP_TO_Z_UP = np.linalg.inv(Z_UP_TO_Y_UP)[:3, :3]


@dataclass(frozen=True)
class VisibilityRule:
    """When an object or part counts as visible, and the camera-frame relation margins.

    Attributes
    ----------
    min_pixels : int
        Least mask pixels.
    min_in_image : float
        Least fraction of the object's projection (its projected convex hull) inside the
        image; an object cut off beyond it is not asked about.
    lateral_margin : float
        Metres: ``A left of B`` holds when A's centroid is at least this much further left
        than B's in the camera frame (camera x); within the margin neither holds nor is
        offered as a distractor.
    depth_margin : float
        Metres, the same for ``in front of`` / ``behind`` along the optical axis.
    """

    min_pixels: int = 400
    min_in_image: float = 0.60
    lateral_margin: float = 0.15
    depth_margin: float = 0.30


@dataclass
class ObjectFacts:
    """One placed object.

    Attributes
    ----------
    id, category, label : str
        PAG id, category and the label used in text (``office chair``).
    corners : (8, 3) float
        World corners of the object's oriented box (its settled rotation), metres.
    centroid : (3,) float
        Centre of that box, metres.
    vertices : (N, 3) float
        World vertices of all its parts.
    parts : dict of str to str
        Part name -> part label (``leg_0`` -> ``leg``).
    part_vertices : dict of str to (M, 3) float
    """

    id: str
    category: str
    label: str
    corners: np.ndarray
    centroid: np.ndarray
    vertices: np.ndarray
    parts: dict[str, str]
    part_vertices: dict[str, np.ndarray]


@dataclass
class ViewFacts:
    """One rendered view and what is visible in it.

    Attributes
    ----------
    index : int
    camera : Camera
    rgb : Path
        The view's colour image.
    objects : dict of str to dict
        Visible objects: id -> ``{"pixels", "bbox", "share"}`` (bbox inclusive pixels).
    parts : dict of str to dict
        Visible parts: ``object:part`` -> the same.
    """

    index: int
    camera: Camera
    rgb: Path
    objects: dict[str, dict[str, Any]]
    parts: dict[str, dict[str, Any]]


@dataclass
class SceneFacts:
    """The ground truth of one scene.

    Attributes
    ----------
    name : str
        Folder name under ``scenes/`` (``00012``).
    index : int
    room_type : str
    objects : dict of str to ObjectFacts
        Placed objects in scene order.
    pag : set of (str, str, str)
        ``(child, RELATION, parent)`` between two objects that holds after settling.
    contacts : dict of (str, str) to set of (str, str)
        Ordered object pair -> contacting ``(part of first, part of second)`` names; both
        orders are present.
    views : list of dict
        The ``views.json`` entries.
    views_folder : Path
        The folder the view images are in.
    """

    name: str
    index: int
    room_type: str
    objects: dict[str, ObjectFacts]
    pag: set[tuple[str, str, str]]
    contacts: dict[tuple[str, str], set[tuple[str, str]]]
    views: list[dict[str, Any]]
    views_folder: Path
    meta: dict[str, Any] = field(default_factory=dict)


def _read_json(path: Path) -> Any:
    from .._files import read_json

    if not path.exists() and not path.is_symlink():
        raise InputError(Problem("", "missing file — is this a scene folder of a dataset built "
                                     "by parse3d dataset build?", str(path), "io"))
    return read_json(path, what="scene file")


@contextlib.contextmanager
def _damaged(file: Path):
    """A scene or views file of the wrong shape (a missing key, a list for an object, a box
    outside its image) is one :class:`InputError` naming it."""
    try:
        yield
    except InputError:
        raise
    except (KeyError, TypeError, ValueError, AttributeError, IndexError) as e:
        what = f"missing {e}" if isinstance(e, KeyError) else str(e).splitlines()[0][:200]
        raise InputError(Problem("", f"damaged file ({what}): rebuild this scene", str(file),
                                 "schema")) from None


def _object_of(ref: str) -> str | None:
    """The object id of a PAG reference, or None for a room element."""
    try:
        r = parse_ref(ref)
    except RefSyntaxError:
        return None
    if r.is_room_element or wall_index(r.object) is not None:
        return None
    return r.object


def _glb_vertices(path: Path) -> dict[str, np.ndarray]:
    ts = trimesh.load(str(path), force="scene")
    out: dict[str, np.ndarray] = {}
    for node in ts.graph.nodes_geometry:
        T, gname = ts.graph[node]
        v = np.asarray(ts.geometry[gname].vertices, float)
        v = v @ T[:3, :3].T + T[:3, 3]
        out[str(node)] = v @ _Y_UP_TO_Z_UP.T
    return out


def load_scene_facts(scene_dir: str | Path, *, views_folder: str | Path | None = None
                     ) -> SceneFacts:
    """Read one scene folder of a dataset.

    Parameters
    ----------
    scene_dir : path
        ``DATASET/scenes/NNNNN``.
    views_folder : path, optional
        Where ``views.json`` and the view images are (default: the scene folder; the
        benchmark's own renders live under its output folder).
    """
    d = Path(scene_dir)
    sj = _read_json(d / "scene.json")
    contacts = _read_json(d / "contacts.json")
    vf = Path(views_folder) if views_folder is not None else d
    views_doc = _read_json(vf / "views.json") if (vf / "views.json").exists() else {"views": []}
    with _damaged(vf / "views.json"):
        views = list(views_doc["views"])
        if not all(isinstance(v, dict) for v in views):
            raise TypeError("every view must be an object")
    if not isinstance(contacts, list) or not all(isinstance(c, dict) for c in contacts):
        raise InputError(Problem("", "damaged file (expected a list of contacts): rebuild this "
                                     "scene", str(d / "contacts.json"), "schema"))
    if not (d / "scene.glb").exists():
        raise InputError(Problem("", "missing scene.glb — rebuild this scene", str(d), "io"))
    verts = _glb_vertices(d / "scene.glb")
    with _damaged(d / "scene.json"):
        return _scene_facts(d, sj, contacts, verts, views, vf)


def _scene_facts(d: Path, sj: dict, contacts: list, verts: dict, views: list, vf: Path
                 ) -> SceneFacts:
    objects: dict[str, ObjectFacts] = {}
    for od in sj["objects"]:
        if od.get("status") != "placed":
            continue
        oid = od["id"]
        parts = {p["name"]: part_label(p.get("label", p["name"])) for p in od.get("parts", [])}
        # scene.glb names a part's node "<object>__<part>" (node_name: viewers drop colons);
        # datasets written before that named it "<object>:<part>"
        pv = {n: verts[k] for n in parts
              for k in dict.fromkeys((node_name(f"{oid}:{n}"), f"{oid}:{n}")) if k in verts}
        if not pv:
            continue
        allv = np.vstack(list(pv.values()))
        pose = od.get("settled_pose") or od["pose"]
        R = quat_to_matrix(pose["quaternion"])
        local = allv @ R  # rows: R.T @ v
        lo, hi = local.min(axis=0), local.max(axis=0)
        grid = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                         for z in (lo[2], hi[2])])
        corners = grid @ R.T
        objects[oid] = ObjectFacts(oid, od["category"], object_label(od["category"]), corners,
                                   corners.mean(axis=0), allv, parts, pv)
    pag: set[tuple[str, str, str]] = set()
    for r in sj.get("relations", []):
        held = r.get("holds_settled")
        if held is None:
            held = r.get("holds")
        if not held or r["relation"] not in RELATION_PHRASES:
            continue
        c, p = _object_of(r["child"]), _object_of(r["parent"])
        if c in objects and p in objects and c != p:
            pag.add((c, r["relation"], p))
    pairs: dict[tuple[str, str], set[tuple[str, str]]] = {}
    for c in contacts:
        a, _, pa = c["a"].partition(":")
        b, _, pb = c["b"].partition(":")
        if a == b or a not in objects or b not in objects:
            continue
        pairs.setdefault((a, b), set()).add((pa, pb))
        pairs.setdefault((b, a), set()).add((pb, pa))
    return SceneFacts(d.name, int(d.name) if d.name.isdigit() else 0,
                      sj.get("pag", {}).get("room", {}).get("type", sj["room"].get("type", "")),
                      objects, pag, pairs, views, vf, {"seed": sj.get("seed")})


def hull_area(uv: np.ndarray, width: int, height: int) -> float:
    """Area (pixels²) of the convex hull of image points, clipped to the image.

    Parameters
    ----------
    uv : (N, 2) float
        Pixel coordinates (OpenCV: u right, v down).
    width, height : int
        Image size; the image covers ``[-0.5, width - 0.5] x [-0.5, height - 0.5]``.
    """
    uv = np.asarray(uv, float)
    uv = uv[np.isfinite(uv).all(axis=1)]
    if len(uv) < 3:
        return 0.0
    try:
        hull = ConvexHull(uv)
    except QhullError:
        return 0.0
    poly = Polygon(uv[hull.vertices])
    if not poly.is_valid:
        poly = poly.buffer(0)
    return float(poly.intersection(box(-0.5, -0.5, width - 0.5, height - 0.5)).area)


def in_image_share(uv: np.ndarray, width: int, height: int) -> float:
    """Fraction of the convex hull of image points that lies inside the image.

    Parameters
    ----------
    uv : (N, 2) float
        Pixel coordinates on the unbounded image plane (OpenCV: u right, v down).
    width, height : int
        Image size.

    Returns
    -------
    float
        0 when the points span no area.
    """
    uv = np.asarray(uv, float).reshape(-1, 2)
    uv = uv[np.isfinite(uv).all(axis=1)]
    if len(uv) < 3:
        return 0.0
    try:
        full = float(ConvexHull(uv).volume)  # a 2-D hull's volume is its area
    except QhullError:
        return 0.0
    return min(hull_area(uv, width, height) / full, 1.0) if full > 0 else 0.0


def _share_in_view(cam: Camera, pts: np.ndarray) -> float:
    """In-image share of points seen by ``cam``; 0 when any reaches behind the near plane."""
    uv, z = cam.project(pts)
    if (z <= cam.near).any():
        return 0.0
    return in_image_share(uv, cam.width, cam.height)


def view_facts(scene: SceneFacts, view: dict[str, Any], rule: VisibilityRule) -> ViewFacts:
    """Visible objects and parts of one ``views.json`` entry.

    Raises
    ------
    InputError
        The entry is damaged, a mask's box lies outside the camera's image, or the image on
        disk has another size than the camera's (boxes would be wrong).
    """
    with _damaged(scene.views_folder / "views.json"):
        return _view_facts(scene, view, rule)


def _check_box(bbox: Any, w: int, h: int) -> list[int]:
    b = [int(v) for v in bbox]
    if len(b) != 4 or not (0 <= b[0] <= b[2] < w and 0 <= b[1] <= b[3] < h):
        raise ValueError(f"the mask box {b} is not inside the {w}x{h} image")
    return b


def _view_facts(scene: SceneFacts, view: dict[str, Any], rule: VisibilityRule) -> ViewFacts:
    cam = Camera.from_dict(view["camera"])
    w, h = cam.width, cam.height
    objs: dict[str, dict[str, Any]] = {}
    for rec in view.get("objects", []):
        oid = rec["object"]
        o = scene.objects.get(oid)
        if rec.get("room") or o is None or rec["pixels"] < rule.min_pixels:
            continue
        share = _share_in_view(cam, o.vertices)
        if share >= rule.min_in_image:
            objs[oid] = {"pixels": int(rec["pixels"]), "bbox": _check_box(rec["bbox"], w, h),
                         "share": round(min(share, 1.0), 3)}
    parts: dict[str, dict[str, Any]] = {}
    for rec in view.get("parts", []):
        oid, _, pname = rec["part"].partition(":")
        o = scene.objects.get(oid)
        if rec.get("room") or o is None or pname not in o.part_vertices:
            continue
        if rec["pixels"] < rule.min_pixels:
            continue
        share = _share_in_view(cam, o.part_vertices[pname])
        if share >= rule.min_in_image:
            parts[rec["part"]] = {"pixels": int(rec["pixels"]), "bbox": _check_box(rec["bbox"], w, h),
                                  "share": round(min(share, 1.0), 3)}
    name = view["files"]["rgb"]
    if not isinstance(name, str) or Path(name).name != name:
        raise ValueError(f"the image {name!r} is not a file name in the views folder")
    rgb = scene.views_folder / name
    if rgb.is_file():
        from PIL import Image, UnidentifiedImageError

        try:
            with Image.open(rgb) as im:  # reads the header only
                size = im.size
        except (OSError, UnidentifiedImageError):
            raise InputError(Problem("", "not a readable image: rebuild this scene", str(rgb),
                                     "io")) from None
        if size != (w, h):
            raise ValueError(f"{name} is {size[0]}x{size[1]} but its camera is {w}x{h}")
    return ViewFacts(int(view["index"]), cam, rgb, objs, parts)


def _horizontal_distance(a: ObjectFacts, b: ObjectFacts) -> float:
    return float(np.linalg.norm(a.centroid[:2] - b.centroid[:2]))


#: ``near`` holds below this horizontal centroid distance (metres) and is false beyond
#: :data:`NEAR_FALSE`; ``far from`` holds beyond :data:`FAR_TRUE` and is false below
#: :data:`FAR_FALSE`; between the two the relation is undecided.
NEAR_TRUE, NEAR_FALSE, FAR_FALSE, FAR_TRUE = 0.9, 1.1, 1.8, 2.2
#: A resting object's lowest point lies within this many metres of the top of the parts of
#: its support it touches.
SUPPORT_GAP = 0.03

#: How a true relation was derived (``relation_sources`` values).
SOURCES = ("pag+contact", "contact", "pag+settled", "camera", "distance", "no contact")


def _rests_on(scene: SceneFacts, a: str, b: str) -> bool:
    """``a`` rests on ``b`` in the settled geometry: the two touch (``contacts.json``), the
    lowest point of ``a`` is within :data:`SUPPORT_GAP` of the top of the parts of ``b`` it
    touches, and ``a``'s centre lies over ``b``'s oriented box (in plan)."""
    pairs = scene.contacts.get((a, b))
    if not pairs:
        return False
    oa, ob = scene.objects[a], scene.objects[b]
    touched = [ob.part_vertices[q] for _, q in pairs if q in ob.part_vertices]
    if not touched:
        return False
    top = max(float(v[:, 2].max()) for v in touched)
    if abs(float(oa.vertices[:, 2].min()) - top) > SUPPORT_GAP or oa.centroid[2] <= top:
        return False
    c = ob.corners[:, :2]
    ux, uy = c[4] - c[0], c[2] - c[0]  # the box's two plan edges (corner order x, y, z)
    d = oa.centroid[:2] - c[0]
    s, t = d @ ux / max(ux @ ux, 1e-12), d @ uy / max(uy @ uy, 1e-12)
    return bool(0 <= s <= 1 and 0 <= t <= 1)


def relation_sources(scene: SceneFacts, cam: Camera, a: str, b: str, rule: VisibilityRule
                     ) -> tuple[dict[str, str], set[str]]:
    """The relations that hold for "``a`` REL ``b``", each with how it was derived, and
    those left undecided.

    Derivations (:data:`SOURCES`):

    - ``pag+contact``: a contact relation (``on``, ``in``, ``against``, ...) stated in the PAG,
      holding after settling, and the two objects touch in ``contacts.json``;
    - ``contact``: ``on`` from the settled geometry alone (:func:`_rests_on`);
    - ``pag+settled``: a PAG relation without a contact or distance test (``facing``,
      ``aligned with``, ...) that the dataset reports as holding after settling;
    - ``camera``: ``left of`` / ``right of`` / ``in front of`` / ``behind`` on the oriented-box
      centres in the camera frame beyond the rule's margins;
    - ``distance``: ``near`` / ``far from`` by the horizontal centroid distance (below
      :data:`NEAR_TRUE` / above :data:`FAR_TRUE`); a PAG-stated ``near`` or ``far from`` is
      true only when this test agrees;
    - ``no contact``: no part-level contact in ``contacts.json``.

    Returns
    -------
    true : dict of str to str
        Relation -> derivation.
    undecided : set of str
        Relations that may or may not hold (a contact relation not stated between two objects
        that touch, a camera-frame relation inside its margin, a distance in the undecided
        band, a PAG relation without a geometric test not stated): never a distractor.
    """
    oa, ob = scene.objects[a], scene.objects[b]
    true: dict[str, str] = {}
    undecided: set[str] = set()
    pa = cam.R @ oa.centroid + cam.t
    pb = cam.R @ ob.centroid + cam.t
    dx, dz = pa[0] - pb[0], pa[2] - pb[2]
    for rel, val, margin in (("LEFT_OF", -dx, rule.lateral_margin),
                             ("RIGHT_OF", dx, rule.lateral_margin),
                             ("IN_FRONT_OF", -dz, rule.depth_margin),
                             ("BEHIND", dz, rule.depth_margin)):
        if val > margin:
            true[rel] = "camera"
        elif val > -margin:
            undecided.add(rel)
    touching = (a, b) in scene.contacts
    if not touching:
        true[NO_CONTACT] = "no contact"
    dist = _horizontal_distance(oa, ob)
    if dist < NEAR_TRUE:
        true["NEAR"] = "distance"
    elif dist <= NEAR_FALSE:
        undecided.add("NEAR")
    if dist > FAR_TRUE:
        true["FAR_FROM"] = "distance"
    elif dist >= FAR_FALSE:
        undecided.add("FAR_FROM")
    for rel in RELATION_PHRASES:
        if rel in CAMERA_RELATIONS or rel in ("NEAR", "FAR_FROM", NO_CONTACT):
            continue
        stated = (a, rel, b) in scene.pag
        if rel in CONTACT_RELATIONS:
            if stated and touching:
                true[rel] = "pag+contact"
            elif rel == "ON" and _rests_on(scene, a, b):
                true[rel] = "contact"
            elif touching:
                undecided.add(rel)
            # without contact a contact relation is decidably false
        elif stated:
            true[rel] = "pag+settled"
        else:
            undecided.add(rel)
    undecided -= set(true)
    return true, undecided


def pair_truth(scene: SceneFacts, cam: Camera, a: str, b: str, rule: VisibilityRule
               ) -> tuple[set[str], set[str]]:
    """Which vocabulary relations hold for "``a`` REL ``b``", and which are undecided
    (:func:`relation_sources` without the derivations)."""
    true, undecided = relation_sources(scene, cam, a, b, rule)
    return set(true), undecided


def projected_box(cam: Camera, corners: np.ndarray, *, clip: bool = True
                  ) -> list[float] | None:
    """2-D box ``[x1, y1, x2, y2]`` (pixels) of projected 3-D box corners, clipped to the image
    (``clip=False``: on the unbounded image plane).

    Corners behind the camera are replaced by the box's points on the near plane (the edges
    of the box are clipped), so a box that reaches behind the camera still gets a box.
    """
    pc = np.asarray(corners, float) @ cam.R.T + cam.t
    near = cam.near + 1e-6
    pts = [p for p in pc if p[2] > near]
    if not pts:
        return None
    edges = [(i, j) for i in range(8) for j in range(i + 1, 8) if bin(i ^ j).count("1") == 1]
    for i, j in edges:
        zi, zj = pc[i, 2], pc[j, 2]
        if (zi - near) * (zj - near) < 0:
            s = (near - zi) / (zj - zi)
            pts.append(pc[i] + s * (pc[j] - pc[i]))
    p = np.array(pts)
    uv = p[:, :2] / p[:, 2:3] * [cam.fx, cam.fy] + [cam.cx, cam.cy]
    if not clip:
        return [float(v) for v in (*uv.min(axis=0), *uv.max(axis=0))]
    x1, y1 = np.clip(uv.min(axis=0), [0, 0], [cam.width - 1, cam.height - 1])
    x2, y2 = np.clip(uv.max(axis=0), [0, 0], [cam.width - 1, cam.height - 1])
    if x2 <= x1 or y2 <= y1:
        return None
    return [float(x1), float(y1), float(x2), float(y2)]


def to_grid(bbox: list[float], width: int, height: int) -> list[int]:
    """Pixel box -> the paper's 0-1000 grid: ``x / width`` and ``y / height``, rounded.

    Inclusive pixel boxes (masks) cover ``[x1, x2 + 1)``; pass them with ``x2 + 1``.
    """
    x1, y1, x2, y2 = bbox
    g = [x1 / width, y1 / height, x2 / width, y2 / height]
    return [int(round(min(max(v, 0.0), 1.0) * 1000)) for v in g]
