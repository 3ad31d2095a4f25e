"""Material palettes for procedural assets. Every function draws from an explicit ``rng``."""

from __future__ import annotations

import numpy as np

from .model import Material

__all__ = ["wood", "metal", "fabric", "ceramic", "glass", "plastic", "paper", "stone", "plant",
           "food", "leather", "jitter", "solid"]

_WOODS = [(0.55, 0.38, 0.24), (0.70, 0.53, 0.36), (0.40, 0.26, 0.16), (0.82, 0.68, 0.50),
          (0.30, 0.20, 0.13), (0.62, 0.45, 0.30)]
_METALS = [(0.75, 0.75, 0.77), (0.20, 0.20, 0.22), (0.80, 0.68, 0.45), (0.55, 0.56, 0.58)]
_FABRICS = [(0.45, 0.50, 0.58), (0.62, 0.58, 0.52), (0.30, 0.35, 0.45), (0.55, 0.30, 0.28),
            (0.35, 0.45, 0.35), (0.80, 0.78, 0.72), (0.25, 0.25, 0.28), (0.70, 0.60, 0.45)]
_CERAMICS = [(0.95, 0.95, 0.93), (0.85, 0.88, 0.92), (0.92, 0.85, 0.75), (0.40, 0.55, 0.65),
             (0.75, 0.35, 0.30), (0.30, 0.30, 0.32)]
_PLASTICS = [(0.92, 0.92, 0.92), (0.15, 0.15, 0.16), (0.80, 0.25, 0.22), (0.25, 0.45, 0.75),
             (0.95, 0.80, 0.25), (0.35, 0.65, 0.40), (0.60, 0.62, 0.65)]
_PAPERS = [(0.85, 0.20, 0.20), (0.20, 0.35, 0.65), (0.20, 0.55, 0.35), (0.90, 0.75, 0.30),
           (0.35, 0.25, 0.45), (0.15, 0.15, 0.15), (0.90, 0.88, 0.82), (0.60, 0.30, 0.15)]


def jitter(rng: np.random.Generator, rgb, amount: float = 0.04) -> tuple[float, float, float, float]:
    c = np.clip(np.asarray(rgb, float) + rng.normal(0, amount, 3), 0.0, 1.0)
    return (float(c[0]), float(c[1]), float(c[2]), 1.0)


def _pick(rng: np.random.Generator, palette):
    return palette[int(rng.integers(len(palette)))]


def solid(rgb, name: str = "plastic", roughness: float = 0.6, metallic: float = 0.0) -> Material:
    """A fixed colour, no randomness."""
    return Material((*[float(c) for c in rgb[:3]], 1.0), roughness, metallic, name)


def wood(rng: np.random.Generator) -> Material:
    return Material(jitter(rng, _pick(rng, _WOODS)), 0.65, 0.0, "wood")


def metal(rng: np.random.Generator) -> Material:
    return Material(jitter(rng, _pick(rng, _METALS), 0.02), 0.35, 0.9, "metal")


def fabric(rng: np.random.Generator) -> Material:
    return Material(jitter(rng, _pick(rng, _FABRICS)), 0.95, 0.0, "fabric")


def leather(rng: np.random.Generator) -> Material:
    return Material(jitter(rng, _pick(rng, [(0.35, 0.20, 0.12), (0.15, 0.12, 0.10), (0.55, 0.35, 0.20)])),
                    0.55, 0.0, "leather")


def ceramic(rng: np.random.Generator) -> Material:
    return Material(jitter(rng, _pick(rng, _CERAMICS), 0.02), 0.25, 0.0, "ceramic")


def glass(rng: np.random.Generator) -> Material:
    c = jitter(rng, (0.80, 0.88, 0.92), 0.02)
    return Material((c[0], c[1], c[2], 0.35), 0.05, 0.0, "glass")


def plastic(rng: np.random.Generator) -> Material:
    return Material(jitter(rng, _pick(rng, _PLASTICS)), 0.5, 0.0, "plastic")


def paper(rng: np.random.Generator) -> Material:
    return Material(jitter(rng, _pick(rng, _PAPERS)), 0.85, 0.0, "paper")


def stone(rng: np.random.Generator) -> Material:
    return Material(jitter(rng, _pick(rng, [(0.85, 0.85, 0.82), (0.30, 0.30, 0.32), (0.65, 0.60, 0.55)])),
                    0.4, 0.0, "stone")


def plant(rng: np.random.Generator) -> Material:
    return Material(jitter(rng, _pick(rng, [(0.20, 0.45, 0.18), (0.28, 0.55, 0.25), (0.15, 0.35, 0.20)])),
                    0.8, 0.0, "plant")


def food(rng: np.random.Generator, rgb) -> Material:
    return Material(jitter(rng, rgb), 0.6, 0.0, "food")
