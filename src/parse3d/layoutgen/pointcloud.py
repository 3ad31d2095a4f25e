"""A small learned shape encoder: a point-cloud auto-encoder over the asset pool's surfaces.

:class:`PointCloudEncoder` implements the :class:`~.encoders.ShapeEncoder` interface (one
token per asset, like the fixed :class:`~.encoders.ShapeDescriptor`): the category one-hot,
the asset's log extents (metres, asset frame) and a ``latent``-d code of its *shape*, the code
of a PointNet encoder (shared per-point MLP, max-pooled) that was trained with a folding-free
MLP decoder to reconstruct the asset's surface points (Chamfer distance). The points are
sampled area-uniformly on the asset's mesh with a fixed seed and scaled by the asset's largest
extent about its bounding-box centre, so the code describes form and proportions and the
extents carry the size.

It is trained by :func:`train_point_encoder` on the assets of the training scenes plus the
pool slots of their categories already on disk (a minute of CPU for a few hundred assets),
saved with the run as ``shape_encoder.pt`` and loaded with it. A pretrained encoder (the
paper's Michelangelo) replaces it by implementing the same interface.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from pathlib import Path

import numpy as np

from ..assets.model import Asset
from ..errors import InputError, Problem
from .data import load_asset_ref
from .encoders import AssetInfo

__all__ = ["surface_points", "PointCloudEncoder", "train_point_encoder", "POINTS",
           "LATENT"]

#: Surface points per asset.
POINTS = 256
#: Width of the learned shape code.
LATENT = 16
_RECON = 128


def surface_points(asset: Asset, n: int = POINTS, *, seed: int = 0) -> np.ndarray:
    """(n, 3) float32 points on ``asset``'s surface, centred on its bounding box and divided
    by its largest extent (so within [-0.5, 0.5]); the same for the same asset and seed."""
    import trimesh

    mesh = asset.mesh()
    pts, _ = trimesh.sample.sample_surface(mesh, n, seed=seed)
    b = asset.bounds
    centre = (b[0] + b[1]) / 2
    return ((pts - centre) / max(float(np.max(b[1] - b[0])), 1e-6)).astype(np.float32)


def _nets(latent: int):
    from torch import nn

    enc = nn.Sequential(nn.Linear(3, 64), nn.ReLU(), nn.Linear(64, 128), nn.ReLU(),
                        nn.Linear(128, latent))
    dec = nn.Sequential(nn.Linear(latent, 256), nn.ReLU(), nn.Linear(256, _RECON * 3))
    return enc, dec


def _code(enc, pts):
    """(B, P, 3) points to (B, latent) codes: per-point MLP, max over points, tanh."""
    import torch

    return torch.tanh(enc(pts).max(dim=1).values)


def _chamfer(a, b):
    import torch

    d = torch.cdist(a, b)
    return d.min(2).values.pow(2).mean() + d.min(1).values.pow(2).mean()


def train_point_encoder(assets: Iterable[Asset], *, latent: int = LATENT, steps: int = 400,
                        batch: int = 32, seed: int = 0,
                        log: Callable[[str], None] | None = None) -> tuple[dict, list[float]]:
    """Train the auto-encoder on ``assets`` (distinct by ``asset_id``).

    Returns the encoder's ``state_dict`` and the training losses (Chamfer, per step). Each
    step draws ``batch`` assets and a random half of each one's points (a different half per
    step), so the code does not depend on which points were sampled.
    """
    import torch

    uniq = {a.asset_id: a for a in assets}
    clouds = torch.as_tensor(np.stack([surface_points(a) for a in uniq.values()]))
    if log is not None:
        log(f"training the point-cloud shape encoder on {len(uniq)} assets ({steps} steps)")
    with torch.random.fork_rng(devices=[]):
        torch.manual_seed(seed)
        enc, dec = _nets(latent)
        opt = torch.optim.Adam([*enc.parameters(), *dec.parameters()], lr=2e-3)
        gen = torch.Generator().manual_seed(seed)
        losses = []
        for _ in range(steps):
            idx = torch.randint(len(clouds), (min(batch, len(clouds)),), generator=gen)
            x = clouds[idx]
            keep = torch.rand(x.shape[:2], generator=gen).argsort(1)[:, : POINTS // 2]
            xin = torch.gather(x, 1, keep[..., None].expand(-1, -1, 3))
            rec = dec(_code(enc, xin)).view(len(idx), _RECON, 3)
            loss = _chamfer(rec, x)
            opt.zero_grad(set_to_none=True)
            loss.backward()
            opt.step()
            losses.append(float(loss.detach()))
    return enc.state_dict(), losses


class PointCloudEncoder:
    """The learned shape encoder (one token: category one-hot, log extents, shape code).

    Parameters
    ----------
    categories : sequence of str
        The category vocabulary (one-hot order).
    state : dict
        The PointNet's ``state_dict`` (:func:`train_point_encoder`).
    latent : int
    """

    name = "pointcloud"

    def __init__(self, categories, state: dict, *, latent: int = LATENT):
        import torch

        self.categories = tuple(sorted(set(categories)))
        self._index = {c: i for i, c in enumerate(self.categories)}
        self.latent = int(latent)
        self.dim = len(self.categories) + 3 + self.latent
        self.state = state
        self._enc, _ = _nets(self.latent)
        self._enc.load_state_dict(state)
        self._enc.eval()
        self._torch = torch
        self._codes: dict[str, np.ndarray] = {}

    def code(self, asset: Asset | AssetInfo) -> np.ndarray:
        """(latent,) float32 shape code of ``asset`` (memoised by ``asset_id``; an
        :class:`~.encoders.AssetInfo` is loaded when its code is not known yet)."""
        c = self._codes.get(asset.asset_id)
        if c is None:
            if isinstance(asset, AssetInfo):
                asset = load_asset_ref(dict(asset.ref))
            with self._torch.no_grad():
                pts = self._torch.as_tensor(surface_points(asset))[None]
                c = _code(self._enc, pts)[0].numpy().astype(np.float32)
            self._codes[asset.asset_id] = c
        return c

    def encode(self, asset: Asset | AssetInfo, category: str) -> np.ndarray:
        v = np.zeros(self.dim, np.float32)
        v[self._index[category]] = 1.0
        k = len(self.categories)
        v[k:k + 3] = np.log(np.maximum(np.asarray(asset.extents, float), 1e-3))
        v[k + 3:] = self.code(asset)
        return v[None, :]

    def config(self) -> dict:
        return {"name": self.name, "categories": list(self.categories), "latent": self.latent,
                "weights": "shape_encoder.pt"}

    def save(self, folder: str | Path) -> Path:
        """Write the weights to ``folder/shape_encoder.pt`` (atomically)."""
        import io

        from ..scene.io import atomic_write_bytes

        buf = io.BytesIO()
        self._torch.save(self.state, buf)
        p = Path(folder) / "shape_encoder.pt"
        atomic_write_bytes(p, buf.getvalue())
        return p

    @classmethod
    def load(cls, folder: str | Path, config: dict) -> PointCloudEncoder:
        from .._files import read_torch

        name = config.get("weights", "shape_encoder.pt")
        if not isinstance(name, str) or Path(name).name != name or name.startswith("."):
            raise InputError(Problem("/shape_encoder/weights", f"{name!r} is not a file name in "
                                     "the run folder", str(Path(folder) / "config.json"),
                                     "schema"))
        state = read_torch(Path(folder) / name, what="shape encoder")
        return cls(config["categories"], state, latent=int(config.get("latent", LATENT)))
