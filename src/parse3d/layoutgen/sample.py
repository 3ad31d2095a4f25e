"""Generating a layout for a PAG with a trained run, as a normal scene.

:func:`sample_layout` runs the reverse diffusion (DDPM, the run's scheduler, ``steps``
evenly spaced timesteps) for the PAG's objects and turns the generated 12-D poses into a
:class:`~parse3d.scene.model.Scene`: per object the pool asset of its category whose extents
fit the generated size best, at the uniform scale that matches the generated volume, placed
at the generated position and rotation. The scene's relations are checked on these poses
(``holds``); ``parse3d settle`` and ``parse3d render`` accept the folder it is written to.

Per object, the category is drawn among the node's candidates that the run has seen, and the
shape features the network conditions on are those of a pool asset of that category drawn
from the same ``rng``.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from ..assets.model import Asset
from ..assets.pool import default_pool
from ..errors import InputError, Problem
from ..measure import check_relations
from ..pag.model import PAG
from ..scene.model import PlacedObject, Scene
from ..scene.shell import build_shell
from ..solver.intent import lying_face
from .data import graph_arrays, pag_relations, support_parents
from .guide import PASSES, grounded, guide_push, pag_supports, piece_boxes, still
from .pose import denormalise_poses, room_box, rotation_from_6d
from .separate import box_push
from .train import LayoutRun, make_scheduler, scene_tensors

__all__ = ["SampleOptions", "sample_layout", "generate_poses", "fit_asset", "layout_scene",
           "SCALE_RANGE", "RefineReport", "snap_proposals", "refine_layout", "nearest_walls"]

#: The uniform scale chosen for an asset is clipped to this range.
SCALE_RANGE = (0.25, 4.0)
_FIXED = ("SECURED_TO", "HANGING_BELOW")


@dataclass(frozen=True)
class SampleOptions:
    """How to sample.

    Attributes
    ----------
    steps : int
        Denoising steps (evenly spaced over the 1000 training timesteps).
    guidance : float
        Classifier-free guidance weight ``w``: ``eps_u + w (eps_c - eps_u)``; 1 is the plain
        conditional model, 0 the unconditioned one.
    cond : bool
        False samples a ``pag`` run unconditioned (condition dropped), as its "none" row.
    separate : int
        Separation guidance (:mod:`.separate`): the last ``separate`` denoising steps push
        overlapping boxes apart, and once the assets are placed what still interpenetrates is
        moved apart on the meshes; 0 (default) samples without it.
    fit : bool
        The relation-aware step (:mod:`.fit`): once the assets are placed, contacts the PAG
        names are brought to their surfaces and what still collides is moved within the
        freedom its relations leave (before the separation on the meshes, with ``separate``).
        It uses the PAG: part of the PAG-conditioned sampler.
    guide : int
        Physics guidance (:mod:`.guide`): in the last ``guide`` denoising steps the estimate
        of the clean poses is moved so that the objects' collision pieces do not overlap and
        stay in the room (up to :data:`.guide.PASSES` passes per step), and the noise estimate is
        made consistent with it; 0 (default) samples without it. Conditioned on the PAG
        (``cond`` and a ``pag`` run), the guidance uses the PAG's supports too (children
        lifted onto their parents, siblings apart on their support); unconditioned, none.
    """

    steps: int = 100
    guidance: float = 1.0
    cond: bool = True
    separate: int = 0
    fit: bool = False
    guide: int = 0


def _pick_categories(pag: PAG, run: LayoutRun, rng: np.random.Generator,
                     file: str | None) -> dict[str, str]:
    known = set(run.categories)
    out, problems = {}, []
    for k, (oid, node) in enumerate(pag.objects.items()):
        seen = [c for c in node.candidates if c in known]
        if not seen:
            names = ", ".join(repr(c) for c in node.candidates)
            problems.append(Problem(f"/objects/{k}/category",
                                    f"object {oid!r}: category {names} never seen in training "
                                    f"(the run knows {len(known)} categories, e.g. "
                                    f"{', '.join(sorted(known)[:6])}) — use one of them or "
                                    "train on a dataset that has it", file, "vocabulary"))
            continue
        out[oid] = seen[int(rng.integers(len(seen)))] if len(seen) > 1 else seen[0]
    if problems:
        raise InputError(problems)
    return out


def generate_poses(run: LayoutRun, categories: list[str], assets: list[Asset], relations,
                   footprint: np.ndarray, height: float, *, seed: int,
                   options: SampleOptions = SampleOptions()) -> np.ndarray:
    """(N, 12) world poses for one scene graph (see :mod:`.pose`)."""
    import torch

    dev = next(run.model.parameters()).device
    ga = graph_arrays(categories, assets, relations, footprint, height,
                      shape_encoder=run.shape_encoder, relation_encoder=run.relation_encoder,
                      stats=run.stats)
    g = scene_tensors(ga, dev)
    n = len(categories)
    sched = make_scheduler()
    sched.set_timesteps(options.steps)
    gen = torch.Generator(device="cpu")
    gen.manual_seed(int(np.random.SeedSequence([seed, 11]).generate_state(1)[0]))
    x = torch.randn((1, n, 12), generator=gen).to(dev)
    use_cond = options.cond and run.config.cond == "pag"
    w = options.guidance if use_cond else 0.0
    parents = support_parents(relations, n) if run.config.frame == "parent" else None
    lo, hi = room_box(footprint, height)
    span = np.maximum(hi - lo, 1e-6)

    def moved(x0: np.ndarray, world: np.ndarray, d: np.ndarray) -> np.ndarray:
        """``x0`` with world displacements ``d`` applied in the model's own coordinates."""
        if parents is not None:  # a supported object moves in its parent's frame
            R = rotation_from_6d(world[:, 6:12])
            rel = parents >= 0
            d = d.copy()
            d[rel] = np.einsum("nji,nj->ni", R[parents[rel]], d[rel])
        out = x0.copy()
        out[:, :3] += (2.0 * d / span).astype(out.dtype)
        return out

    def push(x0: np.ndarray) -> np.ndarray:
        """One separation pass on normalised poses, in the model's own coordinates."""
        world = denormalise_poses(x0, footprint, height, run.stats, parents)
        return moved(x0, world, box_push(world, footprint, height))

    boxes = piece_boxes(assets) if options.guide > 0 else None
    # the PAG steers the guidance of the rows conditioned on it, and of those only
    supports = pag_supports(relations, n) if options.guide > 0 and w != 0.0 else None

    def guide(x0: np.ndarray) -> np.ndarray:
        """The physics guidance passes of one step (:mod:`.guide`) on normalised poses."""
        ground = None
        for _ in range(PASSES):
            world = denormalise_poses(x0, footprint, height, run.stats, parents)
            if ground is None:
                ground = grounded(world, boxes)
            d = guide_push(world, boxes, footprint, height, ground=ground, supports=supports)
            x0 = moved(x0, world, d)
            if still(d):
                break
        return x0

    def last(k: int) -> set[int]:
        return set(sched.timesteps[max(len(sched.timesteps) - k, 0):].tolist()) if k > 0 else set()

    separated, guided = last(options.separate), last(options.guide)
    with torch.no_grad():
        cond = run.model.condition(g)
        for t in sched.timesteps:
            tt = torch.full((1,), int(t), device=dev)
            if w == 0.0:
                eps = run.model(x, tt, g, torch.zeros(1, device=dev), cond=cond)
            elif w == 1.0:
                eps = run.model(x, tt, g, torch.ones(1, device=dev), cond=cond)
            else:
                both = run.model(x.expand(2, -1, -1), tt.expand(2),
                                 g, torch.tensor([0.0, 1.0], device=dev), cond=cond)
                eps = both[:1] + w * (both[1:] - both[:1])
            eps, x = eps.cpu(), x.cpu()
            if int(t) in separated or int(t) in guided:
                # move the clean-pose estimate, and the noise to match it
                ab = float(sched.alphas_cumprod[int(t)])
                x0 = ((x - (1 - ab) ** 0.5 * eps) / ab ** 0.5).clamp(-1, 1)
                x1 = x0[0].numpy()
                if int(t) in separated:
                    x1 = push(x1)
                if int(t) in guided:
                    x1 = guide(x1)
                eps = eps + (ab / (1 - ab)) ** 0.5 * (x0 - torch.as_tensor(x1)[None])
            x = sched.step(eps, t, x, generator=gen).prev_sample.to(dev)
    x = x[0].cpu().numpy()
    if options.separate > 0:
        for _ in range(3):
            x = push(x)
    return denormalise_poses(x, footprint, height, run.stats, parents)


def fit_asset(category: str, size: np.ndarray, *, fallback: Asset | None = None
              ) -> tuple[Asset, float]:
    """The pool asset of ``category`` whose extents best fit ``size`` (3,), and its scale.

    Candidates are the category's slots already in the pool on disk (plus ``fallback``); the
    scale is ``(prod(size) / prod(extents)) ** (1/3)`` (equal volume), clipped to
    :data:`SCALE_RANGE`; the fit error is the distance of the log extents after scaling.
    """
    pool = default_pool()
    cands = [pool.load(category, s) for s in range(pool.per_category)
             if pool.path(category, s).is_file()]
    if fallback is not None:
        cands.append(fallback)
    if not cands:
        cands = [pool.load(category, 0)]
    size = np.maximum(np.asarray(size, float), 1e-3)
    best, best_err, best_s = None, np.inf, 1.0
    for a in cands:
        e = np.maximum(a.extents, 1e-4)
        s = float(np.clip(np.cbrt(np.prod(size) / np.prod(e)), *SCALE_RANGE))
        err = float(np.linalg.norm(np.log(s * e) - np.log(size)))
        if err < best_err:
            best, best_err, best_s = a, err, s
    return best, best_s


def layout_scene(pag: PAG, object_ids: list[str], categories: list[str], poses: np.ndarray, *,
                 seed: int, assets: list[Asset] | None = None,
                 scales: list[float] | None = None, meta: dict | None = None,
                 separate: bool = False, fit: bool = False) -> Scene:
    """A Scene with the objects at the given (N, 12) poses; relations checked on them.

    With ``assets``/``scales`` the given assets are used as they are; otherwise each object
    gets its best-fitting pool asset (:func:`fit_asset`). ``fit``: the poses are fitted to the
    PAG's contacts (:func:`.fit.fit_scene`); ``separate``: then objects still interpenetrating
    are moved apart on their meshes (:func:`.separate.separate_scene`).
    """
    scene = Scene(pag, int(seed), build_shell(pag.room), meta=dict(meta or {}))
    R = rotation_from_6d(poses[:, 6:12])
    for k, (oid, cat) in enumerate(zip(object_ids, categories, strict=True)):
        if assets is not None:
            asset, s = assets[k], float(scales[k])
        else:
            asset, s = fit_asset(cat, poses[k, 3:6])
        sup = pag.supporter(oid)
        scene.objects[oid] = PlacedObject(
            oid, cat, asset, s, R[k], np.asarray(poses[k, :3], float), "placed",
            support=None if sup is None else str(sup.parent),
            fixed=sup is not None and sup.relation in _FIXED)
        if sup is not None and sup.relation == "ON":  # a notebook lying on its cover
            scene.objects[oid].rests_on = lying_face(asset, R[k])
    if fit:  # contacts first: what the PAG can place exactly it places
        from .fit import fit_scene

        scene.meta["fit"] = fit_scene(scene).to_dict()
    if separate:  # then the same generic separation as every row, on what still collides
        from .separate import separate_scene

        scene.meta["separated"] = separate_scene(scene)
    scene.meta["resolved"] = nearest_walls(scene)
    scene.relations = check_relations(scene)
    return scene


def nearest_walls(scene: Scene) -> dict[str, dict]:
    """Which wall each relation to ``wall`` (any wall) means: the wall segment nearest the
    child's centre in plan, as the relation checks' ``resolved`` entries (the solver records
    its own choice; without one the checks take the nearest wall *plane*, which in an L-shaped
    room can be the plane of a wall on the far side)."""
    fp = np.asarray(scene.room.footprint, float)
    a, b = fp, np.roll(fp, -1, axis=0)
    d = b - a
    out = {}
    for i, e in enumerate(scene.pag.relations):
        o = scene.objects.get(e.child.object)
        if e.parent.object != "wall" or o is None or not o.placed:
            continue
        c = o.world_bounds(settled=False).mean(0)[:2]
        u = np.clip(np.einsum("ij,ij->i", c - a, d) / np.maximum(np.einsum("ij,ij->i", d, d),
                                                                  1e-12), 0.0, 1.0)
        k = int(np.argmin(np.linalg.norm(a + u[:, None] * d - c, axis=1)))
        out[str(i)] = {"parent_part": None, "parent_element": f"wall_{k}",
                       "parent_surface": None, "internal": False}
    return out


def sample_layout(run: LayoutRun, pag: PAG, *, seed: int = 0,
                  options: SampleOptions = SampleOptions(), file: str | None = None) -> Scene:
    """Generate a scene for ``pag`` with ``run`` (deterministic for a seed).

    Raises InputError (naming ``file`` and the object) for a category the run never saw.
    """
    t0 = time.perf_counter()
    rng = np.random.default_rng([seed, 5])
    cats = _pick_categories(pag, run, rng, file)
    ids = list(pag.objects)
    if not ids:
        raise InputError(Problem("/objects", "the PAG has no objects", file, "schema"))
    pool = default_pool()
    drawn = [pool.get(cats[o], rng) for o in ids]
    cat_list = [cats[o] for o in ids]
    rels = pag_relations(pag, {o: i for i, o in enumerate(ids)}, cats)
    fp = np.array(pag.room.footprint, float)
    poses = generate_poses(run, cat_list, drawn, rels, fp, pag.room.height, seed=seed,
                           options=options)
    t1 = time.perf_counter()
    placed: dict = {}
    if options.guide > 0:  # the assets the guidance kept apart, not a better fitting slot
        placed = {"assets": drawn, "scales": list(piece_boxes(drawn).scales(poses))}
    scene = layout_scene(pag, ids, cat_list, poses, seed=seed, **placed, meta={
        "generator": "layoutgen", "run": run.name, "run_step": run.step,
        "cond": run.config.cond if options.cond else "none", "guidance": options.guidance,
        "sample_steps": options.steps, **({"guide": options.guide} if options.guide else {})},
        separate=options.separate > 0, fit=options.fit)
    scene.timings["generate"] = round(t1 - t0, 4)
    scene.timings["assets"] = round(time.perf_counter() - t1, 4)
    return scene


#: An object whose up axis is within this angle of the world's is proposed upright (yaw only).
UPRIGHT_DEG = 30.0
#: Height above the generated parent's top at which an ``ON``-an-object child is proposed; the
#: solver drops it onto the parent's geometry.
DROP_LIFT = 0.01


def snap_proposals(pag: PAG, scene: Scene) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """The generated poses of ``scene`` as the solver's first proposals, ``{id: (R, t)}``.

    A generated pose is never exact to the millimetre the solver's checks ask for, so each is
    snapped first, parents before children:

    - an object whose up axis is within :data:`UPRIGHT_DEG` of the world's is turned upright,
      keeping the yaw of its front (+y) axis;
    - ``ON floor``: its lowest point (the asset origin, upright) at the contact gap above the
      floor;
    - ``ON`` an object: moved with its parent's snap, then lifted to :data:`DROP_LIFT` above
      the parent's generated top when lower (the solver lowers it onto the parent's geometry);
    - anything else (walls, ceilings, ``IN``) keeps its generated height.

    Translations are the asset origin (bottom centre) in world metres, as ``solve`` expects.
    """
    from ..measure.checks import EPS
    from ..pag.algorithms import assembly_order

    out: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    dz: dict[str, float] = {}
    top: dict[str, float] = {}
    for oid in assembly_order(pag):
        o = scene.objects.get(oid)
        if o is None or not o.placed:
            continue
        R = np.asarray(o.rotation, float)
        t = np.asarray(o.position, float).copy()
        up = float(np.clip(R[2, 2], -1.0, 1.0))
        upright = np.degrees(np.arccos(up)) <= UPRIGHT_DEG
        if upright:
            f = R[:, 1]
            yaw = float(np.arctan2(-f[0], f[1]))
            c, sn = np.cos(yaw), np.sin(yaw)
            R = np.array([[c, -sn, 0.0], [sn, c, 0.0], [0.0, 0.0, 1.0]])
        sup = pag.supporter(oid)
        z0 = float(t[2])
        if sup is not None and sup.relation == "ON" and sup.parent.object == "floor" and upright:
            t[2] = EPS
        elif sup is not None and not sup.parent.is_room_element:
            parent = str(sup.parent.object)
            t[2] += dz.get(parent, 0.0)
            if sup.relation == "ON" and parent in top:
                t[2] = max(t[2], top[parent] + DROP_LIFT)
        dz[oid] = float(t[2]) - z0
        height = float(np.ptp(o.world_bounds(settled=False)[:, 2]))
        top[oid] = float(t[2]) + (height if upright else 0.0)
        out[oid] = (R, t)
    return out


@dataclass
class RefineReport:
    """What the solver made of the generated poses.

    Attributes
    ----------
    proposed : int
        Objects handed to the solver with a proposal.
    kept : list of str
        Objects the solver placed at their proposal (same rotation and horizontal position;
        an ``ON`` child may have been lowered onto its parent).
    placed, failed : int
        Objects the solver placed (at the proposal or elsewhere) / could not place.
    """

    proposed: int
    kept: list[str]
    placed: int
    failed: int

    def to_dict(self) -> dict:
        return {"proposed": self.proposed, "kept": len(self.kept), "kept_ids": self.kept,
                "placed": self.placed, "failed": self.failed}


def refine_layout(generated: Scene, *, seed: int = 0, library=None) -> tuple[Scene, RefineReport]:
    """Solve ``generated``'s PAG with its (snapped) poses as the first proposal per object.

    Returns the solver's scene, with the report also under ``scene.meta["refine"]``.
    """
    from ..solver import solve

    pag = generated.pag
    props = snap_proposals(pag, generated)
    t0 = time.perf_counter()
    # each proposal with the generated asset and scale: the pose fits that asset, not the one
    # the solver would draw
    full = {oid: (R, t, generated.objects[oid].asset, generated.objects[oid].scale)
            for oid, (R, t) in props.items() if generated.objects[oid].asset is not None}
    scene = solve(pag, seed=seed, library=library, proposals={**props, **full})
    kept = []
    for oid, (R, t) in props.items():
        o = scene.objects.get(oid)
        if o is None or not o.placed:
            continue
        if (np.linalg.norm(np.asarray(o.position)[:2] - t[:2]) <= 1e-6
                and np.allclose(np.asarray(o.rotation), R, atol=1e-6)
                and o.position[2] <= t[2] + 1e-6):
            kept.append(oid)
    rep = RefineReport(len(props), kept, len(scene.placed), len(scene.failed))
    scene.meta.update({k: v for k, v in generated.meta.items() if k not in scene.meta})
    scene.meta["refine"] = rep.to_dict()
    scene.timings.update({k: v for k, v in generated.timings.items() if k not in scene.timings})
    scene.timings["refine"] = round(time.perf_counter() - t0, 4)
    return scene, rep
