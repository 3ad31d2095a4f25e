"""Training the layout diffusion model, and loading a trained run.

A run folder holds (all written by :func:`train`):

- ``config.json``: the :class:`TrainConfig`, the network's :class:`~.model.ModelConfig`, the
  shape encoder's configuration (its category vocabulary) and the dataset it was trained on;
- ``split.json``: train/val/test scene ids (by scene, seeded);
- ``stats.json``: the pose normalisation (:class:`~.pose.PoseStats`);
- ``checkpoint.pt``: network, EMA weights, optimiser, step and the loss history (written
  every ``checkpoint_every`` steps and at the end; :func:`train` resumes from it);
- ``loss.png`` / ``losses.csv``: the training loss curve (and the validation loss);
- ``relation_text.npz``: the cached phrase embeddings of the text relation encoder;
- ``shape_encoder.pt``: the learned point-cloud shape encoder (``shape="pointcloud"`` only).

Recipe (paper, Appendix A.4): DDPM with 1000 steps, squared-cosine betas, epsilon prediction;
AdamW (lr 8e-4, weight decay 1e-4, betas 0.9/0.999); one scene per step with 16 independent
noise draws and timesteps; EMA of all weights (max decay 0.9999, inv_gamma 1.0, power 0.75),
used for sampling. Condition dropout (default 0.1 for ``cond="pag"``) trains the same network
unconditioned as well, for classifier-free guidance.

Randomness: the scene order of epoch ``k`` is ``default_rng([seed, k]).permutation``; the
noise, timesteps and dropout mask of step ``s`` come from a torch generator seeded with
``(seed, s)``. A resumed run therefore continues exactly as an uninterrupted one.
"""

from __future__ import annotations

import contextlib
import json
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path

import numpy as np

from .._files import _first_line, read_json, read_torch
from ..errors import InputError, Problem
from ..scene.io import atomic_write_bytes, atomic_write_text
from .data import GraphArrays, LayoutScene, graph_arrays, load_dataset, split_scenes
from .encoders import ShapeDescriptor, ShapeEncoder, make_relation_encoder
from .pose import PoseStats

__all__ = ["TrainConfig", "TrainReport", "LayoutRun", "train", "load_run", "scene_tensors",
           "make_scheduler"]

EMA_MAX_DECAY = 0.9999
EMA_INV_GAMMA = 1.0
EMA_POWER = 0.75


@dataclass(frozen=True)
class TrainConfig:
    """What :func:`train` does (saved as ``config.json``).

    Attributes
    ----------
    cond : str
        ``pag`` (relation-conditioned) or ``none`` (unconditioned).
    steps : int
        Optimiser steps in total (a resumed run continues up to this).
    preset : str
        Network size: ``cpu`` (d=128, 4 layers), ``small`` (d=64, 3 layers), ``paper``
        (512-d) or ``tiny`` (tests).
    relations : str
        Relation encoder: ``text`` (all-MiniLM-L6-v2 phrases) or ``learned``.
    shape : str
        Shape encoder: ``descriptor`` (fixed) or ``pointcloud`` (learned, :mod:`.pointcloud`).
    shape_steps : int
        Training steps of the ``pointcloud`` encoder (before the layout model's).
    noise_draws : int
        Noise samples per scene and step (paper: 16).
    lr, weight_decay : float
    cond_dropout : float
        Probability of dropping the PAG condition of a draw (``pag`` runs only).
    seed : int
        Initialisation, scene order, noise and (without ``split_seed``) the split.
    split_seed : int or None
        Seed of the train/val/test split (default: ``seed``); runs trained with different
        seeds on one split are compared on the same held-out scenes.
    checkpoint_every : int
    device : str
        ``cpu`` or ``cuda``.
    frame : str
        Where a ``pag`` run generates the translation of an object that has a support parent
        in the PAG (``ON``/``IN``/``HANGING_BELOW``/``SECURED_TO`` another object):
        ``world`` (in the room) or ``parent`` (in the parent's frame, composed along the
        support tree when sampling; see :mod:`.pose`). ``none`` runs have no graph: ``world``.
    time_limit : float or None
        Minutes of wall time after which training stops (with a checkpoint) before ``steps``;
        not part of the run's settings (a resumed run may give another).
    cpu_limit : float or None
        Minutes of CPU time of the training process (all its threads, loading and encoding
        included, as ``/usr/bin/time`` counts user + system) after which training stops with a
        checkpoint before ``steps``; like ``time_limit`` not part of the run's settings, and
        counted per process (a resumed run gets its own allowance).
    """

    cond: str = "pag"
    steps: int = 2000
    preset: str = "cpu"
    relations: str = "text"
    shape: str = "descriptor"
    shape_steps: int = 400
    noise_draws: int = 16
    lr: float = 8e-4
    weight_decay: float = 1e-4
    cond_dropout: float = 0.1
    seed: int = 0
    split_seed: int | None = None
    checkpoint_every: int = 250
    device: str = "cpu"
    frame: str = "world"
    time_limit: float | None = None
    cpu_limit: float | None = None

    def check(self) -> None:
        """InputError for an impossible setting."""
        from .model import PRESETS

        bad = []
        if self.cond not in ("pag", "none"):
            bad.append(("--cond", f"must be 'pag' or 'none', got {self.cond!r}"))
        if self.preset not in PRESETS:
            bad.append(("--preset", f"must be one of {', '.join(PRESETS)}, got {self.preset!r}"))
        if self.relations not in ("text", "learned"):
            bad.append(("--relations", f"must be 'text' or 'learned', got {self.relations!r}"))
        if self.shape not in ("descriptor", "pointcloud"):
            bad.append(("--shape", f"must be 'descriptor' or 'pointcloud', got {self.shape!r}"))
        if self.steps < 1:
            bad.append(("--steps", f"must be at least 1, got {self.steps}"))
        if self.device not in ("cpu", "cuda"):
            bad.append(("--device", f"must be 'cpu' or 'cuda', got {self.device!r}"))
        if not 0.0 <= self.cond_dropout < 1.0:
            bad.append(("--cond-dropout", f"must be in [0, 1), got {self.cond_dropout}"))
        if self.frame not in ("world", "parent"):
            bad.append(("--frame", f"must be 'world' or 'parent', got {self.frame!r}"))
        elif self.frame == "parent" and self.cond != "pag":
            bad.append(("--frame", "'parent' needs the PAG's support tree: only with --cond pag"))
        if self.time_limit is not None and not self.time_limit > 0:
            bad.append(("--time-limit", f"must be positive (minutes), got {self.time_limit}"))
        if self.cpu_limit is not None and not self.cpu_limit > 0:
            bad.append(("--cpu-limit", f"must be positive (minutes), got {self.cpu_limit}"))
        if self.noise_draws < 1 or self.checkpoint_every < 1:
            bad.append(("--noise-draws", "noise draws and checkpoint interval must be >= 1"))
        if bad:
            raise InputError([Problem("", msg, opt, "parameter") for opt, msg in bad])


@dataclass
class TrainReport:
    """What a :func:`train` call did.

    Attributes
    ----------
    run : Path
    start_step, steps : int
        The step it started from (0, or where a resumed run was) and the final step.
    seconds : float
        Wall time of the optimisation loop.
    losses : list of float
        Training loss of every step since step 0.
    val_losses : list of (int, float)
        (step, validation loss) at every checkpoint.
    """

    run: Path
    start_step: int
    steps: int
    seconds: float
    losses: list[float] = field(default_factory=list)
    val_losses: list[tuple[int, float]] = field(default_factory=list)


def make_scheduler():
    """The paper's DDPM scheduler (1000 steps, squared cosine, epsilon)."""
    from diffusers import DDPMScheduler

    return DDPMScheduler(num_train_timesteps=1000, beta_schedule="squaredcos_cap_v2",
                         prediction_type="epsilon")


def scene_tensors(g: GraphArrays, device) -> dict:
    """The torch tensors of one scene graph on ``device``."""
    import torch

    return {k: torch.as_tensor(getattr(g, k), device=device)
            for k in ("x0", "shape", "rel_vec", "rel_child", "rel_parent", "room_geo", "room_ctx")}


@dataclass
class LayoutRun:
    """A trained run loaded for sampling (EMA weights).

    Attributes
    ----------
    path : Path
    config : TrainConfig
    model : LayoutDenoiser
        In eval mode, EMA weights loaded.
    shape_encoder : ShapeEncoder
    relation_encoder : RelationEncoder
    stats : PoseStats
    split : dict of str to list of str
    dataset : str
        The dataset folder it was trained on.
    step : int
    """

    path: Path
    config: TrainConfig
    model: object
    shape_encoder: ShapeEncoder
    relation_encoder: object
    stats: PoseStats
    split: dict[str, list[str]]
    dataset: str
    step: int

    @property
    def categories(self) -> tuple[str, ...]:
        return self.shape_encoder.categories

    @property
    def name(self) -> str:
        return self.path.name


def _device(name: str):
    import torch

    if name == "cuda" and not torch.cuda.is_available():
        raise InputError(Problem("", "CUDA is not available on this machine — use --device cpu",
                                 "--device", "parameter"))
    return torch.device(name)


def _build_model(cfg: TrainConfig, shape_dim: int, rel_dim: int, seed: int):
    import torch

    from .model import PRESETS, LayoutDenoiser, ModelConfig

    mcfg = ModelConfig(**PRESETS[cfg.preset], shape_dim=shape_dim, rel_dim=rel_dim)
    with torch.random.fork_rng(devices=[]):
        torch.manual_seed(seed)
        model = LayoutDenoiser(mcfg)
    return model, mcfg


def _make_ema(model):
    from diffusers.training_utils import EMAModel

    return EMAModel(model.parameters(), decay=EMA_MAX_DECAY, use_ema_warmup=True,
                    inv_gamma=EMA_INV_GAMMA, power=EMA_POWER)


def _loss_plot(path: Path, losses: list[float], val: list[tuple[int, float]], title: str) -> None:
    import io

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 3.6), dpi=110)
    y = np.asarray(losses, float)
    ax.plot(np.arange(1, len(y) + 1), y, color="#bbbbbb", lw=0.6, label="train (per step)")
    if len(y) >= 10:
        k = max(5, len(y) // 50)
        sm = np.convolve(y, np.ones(k) / k, mode="valid")
        ax.plot(np.arange(k, len(y) + 1), sm, color="#1f77b4", lw=1.5, label=f"train ({k}-step mean)")
    if val:
        ax.plot([s for s, _ in val], [v for _, v in val], "o-", color="#d62728", ms=3, label="validation")
    ax.set_xlabel("step")
    ax.set_ylabel("epsilon MSE")
    ax.set_yscale("log")
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    plt.close(fig)
    atomic_write_bytes(path, buf.getvalue())


def _step_generator(seed: int, step: int, device):
    import torch

    g = torch.Generator(device="cpu")
    g.manual_seed(int(np.random.SeedSequence([seed, step]).generate_state(1)[0]))
    return g


def _batch_loss(model, sched, g: dict, gen, draws: int, drop: float, cond: str, device):
    import torch

    x0 = g["x0"]
    N = x0.shape[0]
    t = torch.randint(0, sched.config.num_train_timesteps, (draws,), generator=gen)
    noise = torch.randn((draws, N, x0.shape[1]), generator=gen)
    keep = (torch.rand((draws,), generator=gen) >= drop).float()
    if cond == "none":
        keep = torch.zeros(draws)
    t, noise, keep = t.to(device), noise.to(device), keep.to(device)
    x_t = sched.add_noise(x0[None].expand(draws, -1, -1), noise, t)
    pred = model(x_t, t, g, keep)
    return torch.nn.functional.mse_loss(pred, noise)


def _config_doc(cfg: TrainConfig, mcfg, shape_enc: ShapeEncoder, dataset: str) -> dict:
    return {"format": "parse3d-layout-run/1", "train": asdict(cfg), "model": mcfg.to_dict(),
            "shape_encoder": shape_enc.config(), "relation_encoder": cfg.relations,
            "dataset": dataset, "scheduler": {"num_train_timesteps": 1000,
                                              "beta_schedule": "squaredcos_cap_v2",
                                              "prediction_type": "epsilon"},
            "ema": {"max_decay": EMA_MAX_DECAY, "inv_gamma": EMA_INV_GAMMA, "power": EMA_POWER}}


_RESUME_KEYS = ("cond", "preset", "relations", "shape", "shape_steps", "noise_draws", "lr",
                "weight_decay", "cond_dropout", "seed", "frame")


def train(dataset: str | Path, out: str | Path, config: TrainConfig, *,
          progress: Callable[[int, int, float], None] | None = None,
          log: Callable[[str], None] | None = None) -> TrainReport:
    """Train (or resume) a layout model on a dataset's train split.

    Parameters
    ----------
    dataset : path
        A dataset folder (see :func:`~.data.find_scenes`).
    out : path
        The run folder; resumed when it holds a checkpoint of the same settings.
    config : TrainConfig
    progress : callable, optional
        ``progress(step, total, loss)`` after every step.
    log : callable, optional
        Receives one-line status messages.

    Returns
    -------
    TrainReport
    """
    import torch

    config.check()
    device = _device(config.device)
    out = Path(out)
    say = log or (lambda s: None)
    ckpt_path = out / "checkpoint.pt"
    resume = ckpt_path.is_file()
    if resume:
        old = read_json(out / "config.json", what="run configuration")
        if not isinstance(old, dict) or not isinstance(old.get("train"), dict):
            raise InputError(Problem("/train", "damaged run configuration: choose another "
                                               "--out", str(out / "config.json"), "schema"))
        defaults = TrainConfig()
        diff = [k for k in _RESUME_KEYS
                if old["train"].get(k, getattr(defaults, k)) != getattr(config, k)]
        if diff:
            raise InputError(Problem("", f"{out} holds a run with other settings ("
                                         + ", ".join(f"{k}={old['train'][k]!r}" for k in diff)
                                         + ") — choose another --out or the same settings",
                                     str(out / "config.json"), "parameter"))
    say(f"reading {dataset}")
    scenes = load_dataset(dataset)
    by_id = {s.scene_id: s for s in scenes}
    if len(by_id) != len(scenes):  # folders of two datasets share names: use paths
        by_id = {str(s.path): s for s in scenes}
        for s in scenes:
            s.scene_id = str(s.path)
    if resume:
        split = read_json(out / "split.json", what="run split")
        with _damaged(out / "stats.json"):
            stats = PoseStats.from_dict(read_json(out / "stats.json", what="run statistics"))
        with _damaged(out / "config.json"):
            cats = list(old["shape_encoder"]["categories"])
        with _damaged(out / "split.json"):
            if not all(isinstance(i, str) for k in ("train", "val") for i in split[k]):
                raise TypeError("scene names must be strings")
    else:
        split_seed = config.seed if config.split_seed is None else config.split_seed
        split = split_scenes(list(by_id), np.random.default_rng([split_seed, 7]))
        train_ids = split["train"]
        stats = PoseStats.fit([by_id[i].poses for i in train_ids])
        cats = sorted({c for i in train_ids for c in by_id[i].categories})
    missing = [i for i in split["train"] if i not in by_id]
    if missing:
        raise InputError(Problem("", f"the run's train scenes {missing[:3]} are not in {dataset}",
                                 str(out / "split.json"), "io"))
    train_scenes = [by_id[i] for i in split["train"]]
    shape_enc = _shape_encoder(config, cats, train_scenes, out, resume, say)
    rel_enc = make_relation_encoder(config.relations, cache=out / "relation_text.npz")
    val_scenes = [by_id[i] for i in split["val"] if i in by_id][:8]
    out.mkdir(parents=True, exist_ok=True)

    def arrays(s: LayoutScene) -> dict:
        keep = [k for k, c in enumerate(s.categories) if c in shape_enc._index]
        if len(keep) != len(s.categories):  # val scene with a category unseen in training
            idx = {o: n for n, o in enumerate(keep)}
            rels = [r for r in s.relations if r.child in idx and (r.parent < 0 or r.parent in idx)]
            rels = [replace(r, child=idx[r.child], parent=idx.get(r.parent, -1)) for r in rels]
            s = replace(s, categories=[s.categories[k] for k in keep],
                        asset_info=[s.asset_info[k] for k in keep], poses=s.poses[keep],
                        relations=rels,
                        solved_poses=None)
        ga = graph_arrays(s.categories, s.asset_info, s.relations, s.footprint, s.height,
                          shape_encoder=shape_enc, relation_encoder=rel_enc, stats=stats,
                          poses=s.poses, frame=config.frame)
        return scene_tensors(ga, device)

    say(f"encoding {len(train_scenes)} training scenes ({config.relations} relations)")
    train_t = [arrays(s) for s in train_scenes]
    val_t = [a for a in (arrays(s) for s in val_scenes) if a["x0"].shape[0] > 0]
    model, mcfg = _build_model(config, shape_enc.dim, rel_enc.dim, config.seed)
    model.to(device)
    opt = torch.optim.AdamW(model.parameters(), lr=config.lr, weight_decay=config.weight_decay,
                            betas=(0.9, 0.999))
    ema = _make_ema(model)
    losses: list[float] = []
    val_losses: list[tuple[int, float]] = []
    step = 0
    if resume:
        ck = read_torch(ckpt_path)
        with _damaged(ckpt_path):
            model.load_state_dict(ck["model"])
            opt.load_state_dict(ck["optimizer"])
            ema.load_state_dict(ck["ema"])
            step, losses = int(ck["step"]), [float(v) for v in ck["losses"]]
            val_losses = [(int(a), float(b)) for a, b in ck["val_losses"]]
        say(f"resuming {out} at step {step}")
    doc = _config_doc(config, mcfg, shape_enc, str(Path(dataset).resolve()))
    atomic_write_text(out / "config.json", json.dumps(doc, indent=1) + "\n")
    atomic_write_text(out / "split.json", json.dumps(split, indent=1) + "\n")
    atomic_write_text(out / "stats.json", json.dumps(stats.to_dict(), indent=1) + "\n")
    sched = make_scheduler()
    sched.alphas_cumprod = sched.alphas_cumprod.to(device)
    drop = config.cond_dropout if config.cond == "pag" else 1.0
    n = len(train_t)
    start = step
    t0 = time.perf_counter()

    def save():
        val = _val_loss(model, sched, val_t, config, device)
        if val is not None:
            val_losses.append((step, val))
        buf = __import__("io").BytesIO()
        torch.save({"model": model.state_dict(), "optimizer": opt.state_dict(),
                    "ema": ema.state_dict(), "step": step, "losses": losses,
                    "val_losses": val_losses}, buf)
        atomic_write_bytes(ckpt_path, buf.getvalue())
        atomic_write_text(out / "losses.csv", "step,loss\n" + "".join(
            f"{i + 1},{v:.6g}\n" for i, v in enumerate(losses)))
        _loss_plot(out / "loss.png", losses, val_losses,
                   f"{out.name}: cond={config.cond}, preset={config.preset}, {n} train scenes")

    model.train()
    deadline = None if config.time_limit is None else t0 + 60.0 * config.time_limit
    cpu_deadline = None if config.cpu_limit is None else 60.0 * config.cpu_limit
    while step < config.steps:
        limit = None
        if deadline is not None and time.perf_counter() >= deadline:
            limit = f"time limit of {config.time_limit:g} min"
        elif cpu_deadline is not None and _process_cpu() >= cpu_deadline:
            limit = f"CPU limit of {config.cpu_limit:g} min"
        if limit is not None:
            say(f"{limit} reached at step {step}")
            if step > start and step % config.checkpoint_every != 0:
                save()
            break
        epoch, pos = divmod(step, n)
        order = np.random.default_rng([config.seed, epoch]).permutation(n)
        g = train_t[int(order[pos])]
        gen = _step_generator(config.seed, step, device)
        loss = _batch_loss(model, sched, g, gen, config.noise_draws, drop, config.cond, device)
        opt.zero_grad(set_to_none=True)
        loss.backward()
        torch.nn.utils.clip_grad_norm_(model.parameters(), 1.0)
        opt.step()
        ema.step(model.parameters())
        step += 1
        losses.append(float(loss.detach()))
        if progress is not None:
            progress(step, config.steps, losses[-1])
        if step % config.checkpoint_every == 0 or step == config.steps:
            save()
    if step == start and not (out / "loss.png").exists():
        save()
    return TrainReport(out, start, step, time.perf_counter() - t0, losses, val_losses)


def _process_cpu() -> float:
    """Seconds of CPU time (user + system, all threads) this process has used."""
    import resource

    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def _shape_encoder(config: TrainConfig, cats: list[str], scenes: list[LayoutScene], out: Path,
                   resume: bool, say) -> ShapeEncoder:
    if config.shape == "descriptor":
        return ShapeDescriptor(cats)
    from .pointcloud import PointCloudEncoder, train_point_encoder

    if resume and (out / "shape_encoder.pt").is_file():
        with _damaged(out / "config.json"):
            doc = read_json(out / "config.json", what="run configuration")["shape_encoder"]
            return PointCloudEncoder.load(out, doc)
    from ..assets.pool import default_pool

    pool = default_pool()
    assets = [a for s in scenes for a in s.assets]
    assets += [pool.load(c, k) for c in cats for k in range(pool.per_category)
               if pool.path(c, k).is_file()]
    state, _ = train_point_encoder(assets, steps=config.shape_steps, seed=config.seed, log=say)
    enc = PointCloudEncoder(cats, state)
    out.mkdir(parents=True, exist_ok=True)
    enc.save(out)
    return enc


def _val_loss(model, sched, val_t: list[dict], config: TrainConfig, device) -> float | None:
    """Mean epsilon MSE over the validation scenes with fixed noise (condition kept)."""
    import torch

    if not val_t:
        return None
    model.eval()
    tot = []
    with torch.no_grad():
        for k, g in enumerate(val_t):
            gen = _step_generator(config.seed + 1_000_003, k, device)
            tot.append(float(_batch_loss(model, sched, g, gen, config.noise_draws, 0.0,
                                         config.cond, device)))
    model.train()
    return float(np.mean(tot))


def load_run(run: str | Path, *, device: str = "cpu") -> LayoutRun:
    """Load a trained run with its EMA weights; InputError when it is not a run folder."""

    p = Path(run)
    ck = p / "checkpoint.pt"
    if not ck.is_file() or not (p / "config.json").is_file():
        raise InputError(Problem("", "no checkpoint.pt here — train one with "
                                     f"'parse3d layout train DATASET --out {p}'", str(p), "io"))
    doc = read_json(p / "config.json", what="run configuration")
    if not isinstance(doc, dict) or doc.get("format") != "parse3d-layout-run/1":
        got = doc.get("format") if isinstance(doc, dict) else type(doc).__name__
        raise InputError(Problem("/format", f"expected 'parse3d-layout-run/1', got {got!r}",
                                 str(p / "config.json"), "schema"))
    with _damaged(p / "config.json"):
        cfg = TrainConfig(**doc["train"])
        cfg.check()
        enc_doc, rel_doc, dataset = doc["shape_encoder"], doc["relation_encoder"], doc["dataset"]
        if not isinstance(enc_doc, dict) or not isinstance(dataset, str):
            raise TypeError("shape_encoder must be an object and dataset a string")
    dev = _device(device)
    with _damaged(p / "config.json"):
        if enc_doc.get("name") == "pointcloud":
            from .pointcloud import PointCloudEncoder

            shape_enc = PointCloudEncoder.load(p, enc_doc)
        else:
            shape_enc = ShapeDescriptor(list(enc_doc["categories"]))
        rel_enc = make_relation_encoder(rel_doc, cache=p / "relation_text.npz")
        model, _ = _build_model(cfg, shape_enc.dim, rel_enc.dim, cfg.seed)
    state = read_torch(ck)
    with _damaged(ck):
        try:
            model.load_state_dict(state["model"])
        except RuntimeError:
            raise InputError(Problem("", "the checkpoint does not fit this version's network "
                                         "(it was trained by an older parse3d) — train it again",
                                     str(ck), "schema")) from None
        ema = _make_ema(model)
        ema.load_state_dict(state["ema"])
        ema.copy_to(model.parameters())
        step = int(state["step"])
    model.to(dev).eval()
    with _damaged(p / "stats.json"):
        stats = PoseStats.from_dict(read_json(p / "stats.json", what="run statistics"))
    split = read_json(p / "split.json", what="run split")
    with _damaged(p / "split.json"):
        if not isinstance(split, dict) or not all(
                isinstance(v, list) and all(isinstance(x, str) for x in v)
                for v in split.values()):
            raise TypeError("expected an object of lists of scene names")
    return LayoutRun(p, cfg, model, shape_enc, rel_enc, stats, split, dataset, step)


@contextlib.contextmanager
def _damaged(file: Path):
    """Turn what a damaged run file makes the loaders raise into one ``InputError`` naming it
    (a missing key, a value of the wrong type or shape, an unknown setting)."""
    try:
        yield
    except InputError:
        raise
    except (KeyError, TypeError, ValueError, IndexError, AttributeError, RuntimeError) as e:
        what = f"missing {e}" if isinstance(e, KeyError) else _first_line(e)
        raise InputError(Problem("", f"damaged run file ({what}): train the run again",
                                 str(file), "schema")) from None
