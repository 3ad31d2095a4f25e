"""The denoising network: a graph transformer over objects (nodes) and ordered pairs (edges).

Per block (paper, Appendix A.4, after InstructScene's graph transformer):

1. **Edge-modulated self-attention.** For nodes ``i, j`` and head ``h`` the attention logit
   ``s_ij = q_i . k_j / sqrt(d_h)`` is modulated by the edge features,
   ``s_ij <- s_ij * (1 + E_mul(e_ij)) + E_add(e_ij)``; the head's output is
   ``sum_j a_ij v_j`` plus a projection of ``sum_j a_ij e_ij`` (so the relation of the pair a
   head attended to reaches the node, not only its weight); the modulated logits (gated by the
   edge) and both end nodes update the edge stream. (InstructScene modulates every channel;
   modulating per head keeps the pair tensors ``d / heads`` times smaller, which is what makes
   CPU training of 50-object scenes affordable.)
2. **FiLM of the relation condition** on the attention output of every node:
   ``o_i <- o_i * (1 + gamma(c_i)) + beta(c_i)``, where ``c_i`` embeds the node's PAG relations.
3. **Cross-attention** of every node to its own shape tokens.
4. **Separate feed-forward networks** for the node and edge streams.

Every sub-layer is pre-normalised with an AdaLayerNorm whose scale and shift come from the
timestep embedding (sinusoidal -> 128-d MLP, plus the room context). The edge stream starts
from the embedded PAG relations of both directions of a pair; with the condition dropped
(``cond_mask`` 0, or a ``cond="none"`` model) it starts from the embedding of "no relation".

Shapes: ``B`` noise draws of one scene with ``N`` objects; ``x_t`` is ``(B, N, 12)``.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import torch
from torch import nn

from .data import ROOM_CTX_DIM, ROOM_GEO_DIM
from .pose import POSE_DIM

__all__ = ["ModelConfig", "PRESETS", "LayoutDenoiser", "sinusoidal"]


@dataclass(frozen=True)
class ModelConfig:
    """Network sizes.

    Attributes
    ----------
    d : int
        Node width.
    d_edge : int
        Edge width.
    layers, heads : int
    t_dim : int
        Timestep embedding width (paper: 128).
    shape_dim : int
        Width of a shape feature token (from the shape encoder).
    shape_tokens : int
        Tokens each shape feature token is expanded into for cross-attention.
    rel_dim : int
        Width of a relation vector (from the relation encoder).
    ffn_mult : int
    """

    d: int = 128
    d_edge: int = 32
    layers: int = 4
    heads: int = 4
    t_dim: int = 128
    shape_dim: int = 32
    shape_tokens: int = 4
    rel_dim: int = 384
    ffn_mult: int = 2

    def to_dict(self) -> dict:
        return asdict(self)


#: ``--preset``: sizes without the encoder-dependent widths.
PRESETS = {
    "cpu": {"d": 128, "d_edge": 32, "layers": 4, "heads": 4},
    "paper": {"d": 512, "d_edge": 128, "layers": 8, "heads": 8},
    "small": {"d": 64, "d_edge": 16, "layers": 3, "heads": 4},
    "tiny": {"d": 32, "d_edge": 16, "layers": 2, "heads": 2},
}


def sinusoidal(x: torch.Tensor, dim: int, *, max_period: float = 10000.0) -> torch.Tensor:
    """(...,) values to (..., dim) sinusoidal features (cos then sin)."""
    half = dim // 2
    freqs = torch.exp(-math.log(max_period) * torch.arange(half, dtype=torch.float32,
                                                           device=x.device) / half)
    a = x.float()[..., None] * freqs
    return torch.cat([torch.cos(a), torch.sin(a)], dim=-1)


class AdaLayerNorm(nn.Module):
    """LayerNorm without affine parameters, scaled and shifted by the timestep embedding."""

    def __init__(self, dim: int, t_dim: int):
        super().__init__()
        self.norm = nn.LayerNorm(dim, elementwise_affine=False)
        self.mod = nn.Linear(t_dim, 2 * dim)
        nn.init.zeros_(self.mod.weight)
        nn.init.zeros_(self.mod.bias)

    def forward(self, x: torch.Tensor, t: torch.Tensor) -> torch.Tensor:
        scale, shift = self.mod(nn.functional.silu(t)).chunk(2, dim=-1)
        extra = x.dim() - 2  # broadcast (B, C) over the node / pair axes
        for _ in range(extra):
            scale, shift = scale[:, None], shift[:, None]
        return self.norm(x) * (1 + scale) + shift


def _ffn(dim: int, mult: int) -> nn.Sequential:
    return nn.Sequential(nn.Linear(dim, mult * dim), nn.GELU(), nn.Linear(mult * dim, dim))


class GraphBlock(nn.Module):
    def __init__(self, cfg: ModelConfig):
        super().__init__()
        d, de, h = cfg.d, cfg.d_edge, cfg.heads
        self.h, self.dh = h, d // h
        self.norm_n1, self.norm_e1 = AdaLayerNorm(d, cfg.t_dim), AdaLayerNorm(de, cfg.t_dim)
        self.qkv = nn.Linear(d, 3 * d)
        self.e_mod = nn.Linear(de, 3 * h)
        self.film = nn.Linear(d, 2 * d)
        nn.init.zeros_(self.film.weight)
        nn.init.zeros_(self.film.bias)
        self.e_val = nn.Linear(h * de, d)
        self.out_n = nn.Linear(d, d)
        self.out_e = nn.Linear(h, de)
        self.pair_i, self.pair_j = nn.Linear(d, de), nn.Linear(d, de, bias=False)
        self.norm_n2 = AdaLayerNorm(d, cfg.t_dim)
        self.q_x = nn.Linear(d, d)
        self.kv_x = nn.Linear(d, 2 * d)
        self.out_x = nn.Linear(d, d)
        self.norm_n3, self.norm_e2 = AdaLayerNorm(d, cfg.t_dim), AdaLayerNorm(de, cfg.t_dim)
        self.ffn_n, self.ffn_e = _ffn(d, cfg.ffn_mult), _ffn(de, cfg.ffn_mult)
        self.e_null = nn.Parameter(torch.zeros(de))

    def forward(self, h: torch.Tensor, e: torch.Tensor, c: torch.Tensor, t: torch.Tensor,
                shape: torch.Tensor, pairs: dict[str, torch.Tensor]
                ) -> tuple[torch.Tensor, torch.Tensor]:
        B, N, d = h.shape
        H, dh = self.h, self.dh
        ii, jj, w = pairs["i"], pairs["j"], pairs["keep"]  # (E,), (E,), (B, E, 1)
        E = len(ii)
        hn = self.norm_n1(h, t)
        q, k, v = self.qkv(hn).view(B, N, 3, H, dh).unbind(2)
        en = self.norm_e1(e, t)  # (B, E, de): the pairs of the edge stream
        e0 = self.norm_e1(self.e_null.expand(B, 1, -1), t)  # (B, 1, de): every other pair
        mul, add, gate = self.e_mod(en).view(B, E, 3, H).unbind(2)
        mul0, add0, _ = self.e_mod(e0).view(B, 1, 3, H).unbind(2)
        mul, add = w * mul + (1 - w) * mul0, w * add + (1 - w) * add0
        ev = w * en + (1 - w) * e0  # a dropped pair looks like any other
        s_raw = torch.einsum("bihd,bjhd->bijh", q, k) / math.sqrt(dh)  # (B, N, N, H)
        s_e = s_raw[:, ii, jj] * (1 + mul) + add  # (B, E, H)
        s = s_raw * (1 + mul0[:, :, None]) + add0[:, :, None]
        s = s.permute(1, 2, 0, 3).index_put((ii, jj), s_e.permute(1, 0, 2)).permute(2, 0, 1, 3)
        a = torch.softmax(s, dim=2)  # over j
        o = torch.einsum("bijh,bjhd->bihd", a, v).reshape(B, N, d)
        # what each head attended to: the edge features of the pairs it weighted, so a node
        # can tell its parent's value from a neighbour's (the relation reaches the values)
        a_e = a[:, ii, jj]  # (B, E, H)
        agg = torch.zeros(B, N, H, ev.shape[-1], dtype=h.dtype, device=h.device).index_add(
            1, ii, a_e[..., None] * ev[:, :, None, :])
        rest = 1 - torch.zeros(B, N, H, dtype=h.dtype, device=h.device).index_add(1, ii, a_e)
        agg = agg + rest[..., None] * e0[:, :, None, :]
        o = o + self.e_val(agg.reshape(B, N, H * ev.shape[-1]))
        gamma, beta = self.film(c).chunk(2, dim=-1)
        o = o * (1 + gamma) + beta
        h = h + self.out_n(o)
        # the edge stream: the modulated scores (gated by the edge) and both end nodes
        e = e + self.out_e(s_e * torch.sigmoid(gate)) + self.pair_i(hn)[:, ii] \
            + self.pair_j(hn)[:, jj]
        # cross-attention to the object's own shape tokens (N, S, d)
        qx = self.q_x(self.norm_n2(h, t)).view(B, N, H, dh)
        kx, vx = self.kv_x(shape).view(N, -1, 2, H, dh).unbind(2)
        ax = torch.softmax(torch.einsum("bnhd,nshd->bnhs", qx, kx) / math.sqrt(dh), dim=-1)
        h = h + self.out_x(torch.einsum("bnhs,nshd->bnhd", ax, vx).reshape(B, N, d))
        h = h + self.ffn_n(self.norm_n3(h, t))
        e = e + self.ffn_e(self.norm_e2(e, t))
        return h, e


class LayoutDenoiser(nn.Module):
    """Predicts the noise of noisy normalised poses.

    Parameters
    ----------
    cfg : ModelConfig
    """

    POS_DIM = 16

    def __init__(self, cfg: ModelConfig):
        super().__init__()
        self.cfg = cfg
        d, de, dr = cfg.d, cfg.d_edge, cfg.rel_dim
        self.node_in = nn.Linear(POSE_DIM + self.POS_DIM + cfg.shape_dim, d)
        self.shape_in = nn.Linear(cfg.shape_dim, cfg.shape_tokens * d)
        self.edge_in = nn.Sequential(nn.Linear(2 * dr + 1, de), nn.SiLU(), nn.Linear(de, de))
        self.cond_in = nn.Sequential(nn.Linear(3 * dr + ROOM_GEO_DIM, d), nn.SiLU(),
                                     nn.Linear(d, d))
        self.t_mlp = nn.Sequential(nn.Linear(cfg.t_dim, cfg.t_dim), nn.SiLU(),
                                   nn.Linear(cfg.t_dim, cfg.t_dim))
        self.room_in = nn.Linear(ROOM_CTX_DIM, cfg.t_dim)
        self.blocks = nn.ModuleList([GraphBlock(cfg) for _ in range(cfg.layers)])
        self.out_norm = AdaLayerNorm(d, cfg.t_dim)
        self.out = nn.Linear(d, POSE_DIM)

    def condition(self, g: dict[str, torch.Tensor]) -> dict[str, torch.Tensor]:
        """Embed a scene's relations once: edge and node conditions with and without PAG.

        ``g`` holds the tensors of :class:`~.data.GraphArrays` (``rel_vec``, ``rel_child``,
        ``rel_parent``, ``room_geo``, ``room_ctx``, ``shape``).
        """
        shape = g["shape"]
        N = shape.shape[0]
        dr = self.cfg.rel_dim
        dev = shape.device
        rv, rc, rp = g["rel_vec"], g["rel_child"], g["rel_parent"]
        pair = torch.zeros(N, N, 2 * dr, device=dev)
        node = torch.zeros(N, 3 * dr, device=dev)
        obj = rp >= 0
        if obj.any():
            pair.index_put_((rc[obj], rp[obj]), torch.nn.functional.pad(rv[obj], (0, dr)),
                            accumulate=True)
            pair.index_put_((rp[obj], rc[obj]), torch.nn.functional.pad(rv[obj], (dr, 0)),
                            accumulate=True)
            node.index_put_((rc[obj],), torch.nn.functional.pad(rv[obj], (dr, dr)), accumulate=True)
            node.index_put_((rp[obj],), torch.nn.functional.pad(rv[obj], (2 * dr, 0)),
                            accumulate=True)
        room = ~obj
        if room.any():
            node.index_put_((rc[room],), torch.nn.functional.pad(rv[room], (0, 2 * dr)),
                            accumulate=True)
        eye = torch.eye(N, device=dev, dtype=torch.bool)
        stream = eye.clone()  # the pairs of the edge stream: related ones and each node itself
        if obj.any():
            stream[rc[obj], rp[obj]] = True
            stream[rp[obj], rc[obj]] = True
        ii, jj = stream.nonzero(as_tuple=True)
        self_pair = (ii == jj).float()[:, None]
        node = torch.cat([node, g["room_geo"]], dim=-1)
        return {
            "edge": self.edge_in(torch.cat([pair[ii, jj], self_pair], -1)),
            "edge_null": self.edge_in(torch.cat([torch.zeros_like(pair[ii, jj]), self_pair], -1)),
            "i": ii, "j": jj, "related": 1.0 - self_pair,
            "node": self.cond_in(node),
            "node_null": self.cond_in(torch.zeros_like(node)),
        }

    def forward(self, x_t: torch.Tensor, t: torch.Tensor, g: dict[str, torch.Tensor],
                cond_mask: torch.Tensor, *, cond: dict[str, torch.Tensor] | None = None
                ) -> torch.Tensor:
        """Predicted noise, (B, N, 12).

        Parameters
        ----------
        x_t : (B, N, 12) float
        t : (B,) int
            Diffusion timesteps.
        g : dict of tensors
            One scene (see :meth:`condition`).
        cond_mask : (B,) float
            1 keeps the PAG condition of a draw, 0 drops it.
        cond : dict, optional
            :meth:`condition`'s result, to reuse across denoising steps.
        """
        B, N, _ = x_t.shape
        cond = self.condition(g) if cond is None else cond
        m = cond_mask.float()
        # a pair's relation is used where the draw keeps its condition (a node's own pair always)
        keep = 1 - cond["related"][None] * (1 - m[:, None, None])  # (B, E, 1)
        e = keep * cond["edge"] + (1 - keep) * cond["edge_null"]
        c = m[:, None, None] * cond["node"] + (1 - m[:, None, None]) * cond["node_null"]
        pairs = {"i": cond["i"], "j": cond["j"], "keep": keep}
        shape = g["shape"]
        shape_mean = shape.mean(1)
        tokens = self.shape_in(shape).reshape(N, -1, self.cfg.d)
        pos = sinusoidal(torch.arange(N, device=x_t.device), self.POS_DIM)
        h = self.node_in(torch.cat([x_t, pos.expand(B, N, -1), shape_mean.expand(B, N, -1)], -1))
        temb = self.t_mlp(sinusoidal(t, self.cfg.t_dim)) + self.room_in(g["room_ctx"])[None]
        for blk in self.blocks:
            h, e = blk(h, e, c, temb, tokens, pairs)
        return self.out(self.out_norm(h, temb))
