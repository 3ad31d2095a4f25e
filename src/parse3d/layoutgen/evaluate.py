"""Automatic metrics of generated layouts, in place of the paper's user study.

For every held-out scene the same objects (the scene's placed objects, with their assets) are
laid out by each *row* and measured the same way:

- **solver**: the solver's own poses from the dataset (before settling: the poses its relation
  checks passed on), the upper bound;
- **random**: uniform positions in the footprint, heights in ``[0, room height - object
  height]``, uniform yaw, upright;
- with separation guidance (``separate`` > 0, :mod:`.separate`), every generated row uses it
  and a second random row, **random poses, separated**, gets the same box passes
  (``separate`` + 3) and the same separation on the meshes;
- one row per run: a ``pag`` run conditioned on the PAG, and (trained with condition dropout)
  the same network with the condition dropped; a ``none`` run unconditioned;
- with physics guidance (``guide`` > 0, :mod:`.guide`), every model row is sampled with it (the
  last ``guide`` denoising steps), and the row **random poses, guided (control)** gives the
  random poses the same number of guidance passes: not a baseline the models must beat (the
  random poses have no denoising steps to guide), but what the passes alone make of poses
  that know nothing.

A model row places each given asset at the generated translation and rotation, at the uniform
scale whose volume matches the generated size. Metrics of one layout (:func:`layout_metrics`):

``collision_rate``
    Share of objects that interpenetrate another object by more than 1 cm (FCL, GJK/EPA on
    the objects' convex collision pieces); ``colliding_pairs`` counts such pairs.
``outside``
    Share of objects reaching more than 1 cm outside the room (footprint, floor, ceiling).
``support_rate``
    Share of support relations (ON, IN, HANGING_BELOW, SECURED_TO) whose measured contact gap
    is within 2 cm (for HANGING_BELOW: within 2 cm of its drop range) and, for a supporting
    object, whose child's centre lies over the supporter (inside its bounding box in XY).
``relations``, ``relations_settled``
    Share of the PAG's relations that hold by the solver's own checks, before and after
    settling. Most PAG relations are contacts (``ON``, ``IN``, ``AGAINST``, ...) whose checks
    allow -1...+2 mm and 2 degrees, which a generated pose does not hit before settling;
``relations_spatial``
    so this is the share of the arrangement relations alone (``SIDE_OF``, ``ALONG``, ``NEAR``,
    ``FAR_FROM``, ``TOWARD``: region conditions on centroids, no contact) that hold as
    generated.
``displacement``
    Mean distance (m) the free objects move when the layout is settled in SAPIEN (paper
    parameters).
``stable``
    Share of the free objects that stay where they were generated when settled: moved at most
    1 cm and turned at most 2 degrees (the paper's physical realism, as the solver's own
    ``moved`` test reads it).
``contacts``, ``object_contacts``
    Part-level contacts after settling (the contact graph's edges, 1 mm), all and between two
    objects; pairs still interpenetrating by more than 1 cm are not counted as contacts.
``pairs_child_parent``, ``pairs_siblings``, ``pairs_floor``, ``pairs_other``
    The colliding pairs by what they are to the PAG (:func:`pair_kind`), in ``eval.json``.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from ..measure import check_relations
from ..pag.model import PAG
from ..relations import SUPPORT_RELATIONS
from ..scene.model import Scene
from .data import LayoutScene, find_scenes, load_scene
from .guide import PASSES, guide_poses, piece_boxes
from .pose import rotation_to_6d
from .sample import SampleOptions, generate_poses, layout_scene
from .separate import separate_poses
from .train import LayoutRun

__all__ = ["LayoutMetrics", "pair_kind", "EvalRow", "EvalResult", "layout_metrics", "collisions",
           "outside_room", "random_poses", "evaluate", "held_out_scenes", "write_result",
           "METRICS"]

PENETRATION = 0.01
SUPPORT_TOL = 0.02
_SUPPORT = SUPPORT_RELATIONS
#: Relations judged on centroids and regions, without contact tolerances.
SPATIAL = ("SIDE_OF", "ALONG", "NEAR", "FAR_FROM", "TOWARD")

#: Metric name, direction (+1 higher is better), format.
METRICS = (
    ("collision_rate", -1, "{:.3f}"),
    ("outside", -1, "{:.3f}"),
    ("support_rate", 1, "{:.3f}"),
    ("relations", 1, "{:.3f}"),
    ("relations_spatial", 1, "{:.3f}"),
    ("relations_settled", 1, "{:.3f}"),
    ("displacement", -1, "{:.3f}"),
    ("stable", 1, "{:.3f}"),
    ("contacts", 1, "{:.1f}"),
    ("object_contacts", 1, "{:.1f}"),
)


@dataclass
class LayoutMetrics:
    """The metrics of one layout (see the module docstring); NaN where not measured."""

    objects: int
    colliding_pairs: int
    collision_rate: float
    outside: float
    support_rate: float
    relations: float
    relations_spatial: float = math.nan
    relations_settled: float = math.nan
    displacement: float = math.nan
    stable: float = math.nan
    contacts: float = math.nan
    object_contacts: float = math.nan
    pairs_child_parent: float = 0.0
    pairs_siblings: float = 0.0
    pairs_floor: float = 0.0
    pairs_other: float = 0.0


def pair_kind(pag: PAG, a: str, b: str) -> str:
    """What a colliding pair is to the PAG: ``child_parent`` (one carries the other, at any
    depth of the support tree), ``siblings`` (one support object carries both), ``floor``
    (both stand on, hang from or are fixed to the room) or ``other`` (one carried by an
    object, the other by another object or the room)."""
    def parent(x):
        s = pag.supporter(x)
        return None if s is None or s.parent.is_room_element else str(s.parent.object)

    def chain(x):
        out = []
        while (x := parent(x)) is not None and x not in out:
            out.append(x)
        return out

    if a in chain(b) or b in chain(a):
        return "child_parent"
    pa, pb = parent(a), parent(b)
    if pa is not None and pa == pb:
        return "siblings"
    if pa is None and pb is None:
        return "floor"
    return "other"


def _fcl_pieces(scene: Scene):
    import fcl
    from scipy.spatial import ConvexHull, QhullError

    from ..physics.collision import scene_bodies

    out = []
    for b in scene_bodies(scene, settled=False, include_room=False):
        ps = b.pieces
        objs, boxes = [], []
        for k in range(len(ps.vert_index) - 1):
            v = ps.vertices[ps.vert_index[k]:ps.vert_index[k + 1]]
            try:
                hull = ConvexHull(v)
            except (QhullError, ValueError):
                continue
            faces = np.hstack([np.full((len(hull.simplices), 1), 3), hull.simplices]).ravel()
            objs.append(fcl.CollisionObject(fcl.Convex(v, len(hull.simplices), faces), fcl.Transform()))
            boxes.append(ps.bounds[k])
        out.append((b.id, b.bounds, objs, np.array(boxes).reshape(-1, 2, 3)))
    return out


def _overlap(a: np.ndarray, b: np.ndarray, pad: float = 0.0) -> bool:
    return bool(np.all(a[0] - pad <= b[1]) and np.all(b[0] - pad <= a[1]))


def _deepest_contacts(bodies):
    """For every pair of :func:`_fcl_pieces` bodies whose convex pieces interpenetrate:
    ``(i, j, depth, normal)`` of the deepest contact (FCL's normal, from body i to body j)."""
    import fcl

    req = fcl.CollisionRequest(num_max_contacts=1, enable_contact=True)
    for i in range(len(bodies)):
        _, ba, oa, xa = bodies[i]
        for j in range(i + 1, len(bodies)):
            _, bb, ob, xb = bodies[j]
            if not _overlap(ba, bb):
                continue
            best, normal = 0.0, None
            for pa, ga in zip(oa, xa, strict=True):
                if not _overlap(ga, bb):
                    continue
                for pb, gb in zip(ob, xb, strict=True):
                    if not _overlap(ga, gb):
                        continue
                    res = fcl.CollisionResult()
                    if fcl.collide(pa, pb, req, res):
                        c = max(res.contacts, key=lambda c: c.penetration_depth)
                        if c.penetration_depth > best:
                            best, normal = c.penetration_depth, np.asarray(c.normal, float)
            if normal is not None:
                yield i, j, best, normal


def collisions(scene: Scene, *, depth: float = PENETRATION) -> list[tuple[str, str, float]]:
    """Object pairs interpenetrating deeper than ``depth`` (m): ``(a, b, max depth)``."""
    bodies = _fcl_pieces(scene)
    return [(bodies[i][0], bodies[j][0], d) for i, j, d, _ in _deepest_contacts(bodies)
            if d > depth]


def outside_room(scene: Scene, *, tol: float = PENETRATION) -> list[str]:
    """Ids of objects reaching more than ``tol`` (m) outside the room's volume."""
    import shapely
    from shapely.geometry import Polygon

    from ..physics.collision import scene_bodies

    poly = Polygon(scene.room.footprint).buffer(tol)
    out = []
    for b in scene_bodies(scene, settled=False, include_room=False):
        v = b.pieces.vertices
        inside = shapely.contains_xy(poly, v[:, 0], v[:, 1])
        if (not inside.all() or v[:, 2].min() < -tol
                or v[:, 2].max() > scene.room.height + tol):
            out.append(b.id)
    return out


def _support_ok(scene: Scene) -> list[bool]:
    ok = []
    for c in scene.relations:
        if c.relation not in _SUPPORT or c.holds is None:
            continue
        d = c.residual.get("distance")
        if d is None:
            ok.append(False)
            continue
        edge = scene.pag.relations[c.index]
        if c.relation == "HANGING_BELOW":
            lo, hi = edge.param("drop")
            near = lo - SUPPORT_TOL <= d <= hi + SUPPORT_TOL
        else:
            near = abs(d) <= SUPPORT_TOL
        parent = scene.objects.get(edge.parent.object)
        if near and parent is not None and c.relation != "SECURED_TO":
            # and over the supporter: the child's centre inside the parent's box in XY
            centre = scene.objects[edge.child.object].world_bounds(settled=False).mean(0)
            box = parent.world_bounds(settled=False)
            near = bool(np.all(box[0, :2] <= centre[:2]) and np.all(centre[:2] <= box[1, :2]))
        ok.append(near)
    return ok


def _share(flags) -> float:
    flags = [bool(f) for f in flags]
    return float(np.mean(flags)) if flags else math.nan


def layout_metrics(scene: Scene, *, physics: bool = True) -> LayoutMetrics:
    """Measure one layout; with ``physics`` it is settled (in place) and its contacts counted.

    The scene's relation checks must be current for its (unsettled) poses.
    """
    n = len(scene.placed)
    pairs = collisions(scene)
    hit = {a for a, _, _ in pairs} | {b for _, b, _ in pairs}
    m = LayoutMetrics(n, len(pairs), len(hit) / max(n, 1), len(outside_room(scene)) / max(n, 1),
                      _share(_support_ok(scene)),
                      _share(c.holds for c in scene.relations if c.holds is not None),
                      _share(c.holds for c in scene.relations
                             if c.holds is not None and c.relation in SPATIAL))
    for a, b, _ in pairs:
        k = f"pairs_{pair_kind(scene.pag, a, b)}"
        setattr(m, k, getattr(m, k) + 1.0)
    if physics:
        from ..physics import extract_contacts, settle

        rep = settle(scene)
        check_relations(scene, settled=True)
        free = [mo.displacement for mo in rep.objects.values() if not mo.fixed]
        m.displacement = float(np.mean(free)) if free else 0.0
        moved = set(rep.moved(distance=0.01, angle_deg=2.0))
        ids = [i for i, mo in rep.objects.items() if not mo.fixed]
        m.stable = _share(i not in moved for i in ids)
        m.relations_settled = _share(c.holds_settled for c in scene.relations
                                     if c.holds_settled is not None)
        cs = [c for c in extract_contacts(scene) if c.min_distance >= -PENETRATION]
        m.contacts = float(len(cs))
        m.object_contacts = float(sum(1 for c in cs if not c.a.startswith("room:")
                                      and not c.b.startswith("room:")))
    return m


def random_poses(ls: LayoutScene, rng: np.random.Generator) -> np.ndarray:
    """(N, 12) random poses for a scene's objects (see the module docstring)."""
    from shapely.geometry import Point, Polygon

    poly = Polygon(ls.footprint)
    lo, hi = ls.footprint.min(0), ls.footprint.max(0)
    out = np.array(ls.poses, float, copy=True)
    for k in range(len(out)):
        for _ in range(1000):
            xy = rng.uniform(lo, hi)
            if poly.contains(Point(*xy)):
                break
        h = float(out[k, 5])
        z = rng.uniform(0.0, max(ls.height - h, 0.0))
        a = rng.uniform(-np.pi, np.pi)
        R = np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1.0]])
        out[k, :3] = [xy[0], xy[1], z]
        out[k, 6:] = rotation_to_6d(R)
    return out


def _known_only(ls: LayoutScene, known: set[str]) -> LayoutScene:
    """``ls`` without the objects of categories outside ``known`` and those they support."""
    from dataclasses import replace

    from .data import pag_relations

    kept: list[int] = []
    ids = set()
    for k, (oid, cat) in enumerate(zip(ls.object_ids, ls.categories, strict=True)):
        sup = ls.pag.supporter(oid)
        carried_by = None if sup is None or sup.parent.is_room_element else sup.parent.object
        if cat in known and (carried_by is None or carried_by in ids):
            kept.append(k)
            ids.add(oid)
    if len(kept) == len(ls.object_ids):
        return ls
    obj = [ls.object_ids[k] for k in kept]
    cats = [ls.categories[k] for k in kept]
    rels = pag_relations(ls.pag, {o: i for i, o in enumerate(obj)}, dict(zip(obj, cats, strict=True)))
    return replace(ls, object_ids=obj, categories=cats, asset_info=[ls.asset_info[k] for k in kept],
                   poses=ls.poses[kept], scales=ls.scales[kept], relations=rels,
                   solved_poses=None if ls.solved_poses is None else ls.solved_poses[kept])


def _sub_pag(ls: LayoutScene) -> PAG:
    """The scene's PAG restricted to its placed objects."""
    keep = set(ls.object_ids)
    pag = ls.pag
    rels = [e for e in pag.relations if e.child.object in keep
            and (e.parent.is_room_element or e.parent.object in keep)]
    return PAG(pag.name, pag.room, [pag.objects[o] for o in ls.object_ids], rels, meta=pag.meta,
               viewpoint=pag.viewpoint)


def _scene_for(ls: LayoutScene, pag: PAG, poses: np.ndarray, seed: int, *, given_scale: bool,
               label: str, separate: bool = False, fit: bool = False) -> Scene:
    if given_scale:
        scales = list(ls.scales)
    else:  # equal volume of the given asset and the generated size
        scales = [float(np.clip(np.cbrt(np.prod(np.maximum(p[3:6], 1e-3))
                                        / np.prod(np.maximum(a.extents, 1e-4))), 0.25, 4.0))
                  for p, a in zip(poses, ls.assets, strict=True)]
    return layout_scene(pag, ls.object_ids, ls.categories, poses, seed=seed, assets=ls.assets,
                        scales=scales, meta={"generator": label}, separate=separate, fit=fit)


@dataclass
class EvalRow:
    """One row of the table: per seed, the metrics averaged over scenes.

    Attributes
    ----------
    name : str
    kind : str
        ``solver``, ``random``, ``pag`` or ``none``.
    per_seed : list of dict
        Per sampling seed: metric name to its mean over the scenes.
    per_scene : list of dict
        Every (scene, seed) measurement.
    """

    name: str
    kind: str
    per_seed: list[dict[str, float]] = field(default_factory=list)
    per_scene: list[dict] = field(default_factory=list)

    def mean_std(self, metric: str) -> tuple[float, float]:
        v = np.array([s[metric] for s in self.per_seed], float)
        v = v[np.isfinite(v)]
        if not len(v):
            return math.nan, math.nan
        return float(v.mean()), float(v.std())


@dataclass
class EvalResult:
    """All rows, the scenes they were measured on and where previews went."""

    rows: list[EvalRow]
    scenes: list[str]
    seeds: int
    physics: bool
    previews: list[str] = field(default_factory=list)
    left_out: int = 0

    def to_dict(self) -> dict:
        return {"format": "parse3d-layout-eval/1", "scenes": self.scenes, "seeds": self.seeds,
                "physics": self.physics, "previews": self.previews,
                "objects_left_out": self.left_out,
                "rows": [{"name": r.name, "kind": r.kind,
                          "metrics": {m: dict(zip(("mean", "std"), r.mean_std(m), strict=True))
                                      for m, _, _ in METRICS},
                          "per_seed": r.per_seed, "per_scene": r.per_scene} for r in self.rows]}

    def markdown(self) -> str:
        cols = [m for m, _, _ in METRICS if self.physics or m in
                ("collision_rate", "outside", "support_rate", "relations", "relations_spatial")]
        arrows = {m: ("↑" if d > 0 else "↓") for m, d, _ in METRICS}
        fmt = {m: f for m, _, f in METRICS}
        head = "| row | " + " | ".join(f"{c} {arrows[c]}" for c in cols) + " |"
        lines = [head, "|" + "---|" * (len(cols) + 1)]
        for r in self.rows:
            cells = []
            for c in cols:
                mu, sd = r.mean_std(c)
                cells.append("n/a" if not math.isfinite(mu) else
                             fmt[c].format(mu) + (f" ± {fmt[c].format(sd)}" if len(r.per_seed) > 1 else ""))
            lines.append(f"| {r.name} | " + " | ".join(cells) + " |")
        lines.append("")
        lines.append(f"{len(self.scenes)} held-out scenes, {self.seeds} sampling seed(s) per "
                     "model and random row (mean ± standard deviation over seeds of the "
                     "per-seed mean over scenes)."
                     + (f" {self.left_out} object(s) of categories a run never saw (and what "
                        "they carried) were left out of the scenes." if self.left_out else ""))
        return "\n".join(lines) + "\n"


def _rows_for(runs: list[LayoutRun], guidance: float = 1.0, separate: int = 0,
              fit: bool = False, guide: int = 0
              ) -> list[tuple[str, str, LayoutRun | None, bool, bool, bool]]:
    """(name, kind, run, cond, fit, guided) per row; ``cond`` of a random row: separated;
    ``guided``: the random control row of physics guidance."""
    rows = [("solver (solved poses)", "solver", None, False, False, False),
            ("random poses", "random", None, False, False, False)]
    if separate > 0:
        rows.append(("random poses, separated", "random", None, True, False, False))
    if fit:
        rows.append((f"random poses{', separated' if separate > 0 else ''}, relation-aware",
                     "random", None, separate > 0, True, False))
    if guide > 0:
        rows.append(("random poses, guided (control)", "random", None, False, False, True))
    w = "" if guidance == 1.0 else f", guidance {guidance:g}"
    sep = ("" if separate <= 0 else f", separated {separate}") + \
        ("" if guide <= 0 else f", guided {guide}")
    # conditioned on the PAG, the guidance uses it too (:mod:`.guide`); unconditioned, not
    psep = sep if guide <= 0 or guidance == 0.0 else sep.replace("guided", "PAG-guided")
    for run in runs:
        if run.config.cond == "pag":
            rows.append((f"PAG-conditioned ({run.name}{w}{psep})", "pag", run, True, False,
                         False))
            if fit:
                rows.append((f"PAG-conditioned ({run.name}{w}{psep}, relation-aware)", "pag",
                             run, True, True, False))
            if run.config.cond_dropout > 0:
                rows.append((f"unconditioned ({run.name}, condition dropped{sep})", "none", run,
                             False, False, False))
        else:
            rows.append((f"unconditioned ({run.name}{sep})", "none", run, False, False, False))
    return rows


def _compose(images: list[tuple[str, np.ndarray]], path: Path) -> None:
    from PIL import Image, ImageDraw

    h = max(im.shape[0] for _, im in images)
    w = sum(im.shape[1] for _, im in images)
    canvas = Image.new("RGB", (w, h + 22), "white")
    draw = ImageDraw.Draw(canvas)
    x = 0
    for label, im in images:
        canvas.paste(Image.fromarray(im[..., :3]), (x, 22))
        draw.text((x + 6, 5), label, fill=(0, 0, 0))
        x += im.shape[1]
    path.parent.mkdir(parents=True, exist_ok=True)
    canvas.save(path)


def evaluate(runs: list[LayoutRun], scene_files: list[Path], *, seeds: int = 3,
             physics: bool = True, sample_steps: int = 100, previews: int = 2,
             out: Path | None = None, progress: Callable[[str], None] | None = None,
             guidance: float = 1.0, separate: int = 0, fit: bool = False,
             guide: int = 0) -> EvalResult:
    """Lay out every scene with every row and measure it (see the module docstring).

    Parameters
    ----------
    runs : list of LayoutRun
    scene_files : list of path
        ``scene.json`` files of held-out scenes.
    seeds : int
        Sampling seeds for the model and random rows.
    physics : bool
        Settle every layout and count contacts (slow: seconds per layout).
    sample_steps : int
        Denoising steps.
    previews : int
        Scenes (the first ones) to render side by side into ``out/previews/``.
    out : path, optional
        Where previews go (nothing rendered without it).
    progress : callable, optional
        Called with a short label before every layout.
    guidance : float
        Classifier-free guidance weight of the PAG-conditioned rows (1: plain conditional).
    separate : int
        Separation guidance of every model row (the last ``separate`` denoising steps, see
        :mod:`.separate`), plus a separated random row; 0: none.
    fit : bool
        Adds, after every PAG-conditioned row, the same samples with the relation-aware step
        (:mod:`.fit`), and the random poses with it as a control row.
    guide : int
        Physics guidance of every model row (the last ``guide`` denoising steps, see
        :mod:`.guide`), plus the random poses after as many guidance passes as a control
        row; 0: none.
    """
    rows = _rows_for(runs, guidance, separate, fit, guide)
    result = EvalResult([EvalRow(name, kind) for name, kind, *_ in rows], [], seeds, physics)
    acc: list[list[list[dict]]] = [[[] for _ in range(seeds)] for _ in rows]
    for si, f in enumerate(scene_files):
        ls = load_scene(f)
        if runs:  # objects of a category some run never saw cannot be generated by every row
            n0 = len(ls.object_ids)
            ls = _known_only(ls, set.intersection(*(set(r.categories) for r in runs)))
            result.left_out += n0 - len(ls.object_ids)
        if not ls.object_ids:
            continue
        result.scenes.append(ls.scene_id)
        pag = _sub_pag(ls)
        shots: list[tuple[str, np.ndarray]] = []
        cam = None
        generated: dict[tuple, np.ndarray] = {}  # a relation-aware row reuses its samples
        for ri, (name, kind, run, cond, fit_row, guided) in enumerate(rows):
            for seed in range(1 if kind == "solver" else seeds):
                if progress is not None:
                    progress(f"{ls.scene_id}: {name}, seed {seed}")
                if kind == "solver":
                    solved = ls.poses if ls.solved_poses is None else ls.solved_poses
                    scene = _scene_for(ls, pag, solved, seed, given_scale=True, label=kind)
                elif kind == "random":
                    rng = np.random.default_rng([seed, si, 17])
                    poses = random_poses(ls, rng)
                    if cond:  # the separated random row
                        poses = separate_poses(poses, ls.footprint, ls.height, rounds=separate + 3)
                    if guided:  # the control row: as many passes as a guided sample gets
                        poses = guide_poses(poses, piece_boxes(ls.assets), ls.footprint,
                                            ls.height, passes=guide * PASSES, scales=ls.scales)
                    scene = _scene_for(ls, pag, poses, seed, given_scale=True, label=kind,
                                       separate=cond, fit=fit_row)
                else:
                    key = (str(run.path), cond, seed)
                    if key not in generated:
                        generated[key] = generate_poses(
                            run, ls.categories, ls.assets, ls.relations, ls.footprint,
                            ls.height, seed=seed, options=SampleOptions(
                                steps=sample_steps, cond=cond, guidance=guidance,
                                separate=separate, guide=guide))
                    scene = _scene_for(ls, pag, generated[key], seed, given_scale=False,
                                       label=name, separate=separate > 0, fit=fit_row)
                if out is not None and si < previews and seed == 0:
                    from ..render import overview_camera, render_scene

                    if cam is None:  # the solver's view, shared by every row of the scene
                        cam = overview_camera(scene, width=400, height=300)
                    shots.append((name, render_scene(scene, cam, settled=False).rgb))
                m = asdict(layout_metrics(scene, physics=physics))
                acc[ri][seed].append(m)
                result.rows[ri].per_scene.append({"scene": ls.scene_id, "seed": seed, **m})
        if shots:
            p = Path(out) / "previews" / f"{ls.scene_id}.png"
            _compose(shots, p)
            result.previews.append(str(p))
    for ri, row in enumerate(result.rows):
        for seed_ms in acc[ri]:
            if not seed_ms:
                continue
            row.per_seed.append({k: float(np.nanmean([m[k] for m in seed_ms]))
                                 if any(np.isfinite(m[k]) for m in seed_ms) else math.nan
                                 for k in seed_ms[0]})
    return result


def held_out_scenes(run: LayoutRun, dataset: str | Path | None = None) -> list[Path]:
    """The held-out scenes: ``dataset``'s scenes, or the run's test split of its dataset."""
    if dataset is not None:
        return find_scenes(dataset)
    files = find_scenes(run.dataset)
    test = set(run.split.get("test", []))
    return [f for f in files if f.parent.name in test or str(f.parent) in test]


def _finite(x):
    """NaN (not measured) as null, so the file is strict JSON."""
    if isinstance(x, dict):
        return {k: _finite(v) for k, v in x.items()}
    if isinstance(x, list | tuple):
        return [_finite(v) for v in x]
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


def write_result(result: EvalResult, out: str | Path) -> tuple[Path, Path]:
    """``eval.json`` and ``eval.md`` in ``out``."""
    from ..scene.io import atomic_write_text

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    atomic_write_text(out / "eval.json", json.dumps(_finite(result.to_dict()), indent=1) + "\n")
    md = "# Layout generation: automatic metrics\n\n" + result.markdown()
    if result.previews:
        md += "\n" + "\n".join(f"![{Path(p).stem}](previews/{Path(p).name})" for p in result.previews) + "\n"
    atomic_write_text(out / "eval.md", md)
    return out / "eval.json", out / "eval.md"
