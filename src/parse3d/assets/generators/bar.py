"""The bar: liquor bottles, wine racks, cocktail shakers and ice buckets.

Liquor bottles are closed solids like the grocery bottles (contents not modelled) but with the
shapes of spirits: square whisky bottles, tall round gin bottles and squat flasks. A wine rack
holds bottles lying in rows of cradles; each row is its own ``shelf`` part so ``IN`` finds a
support on it.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._casework import black
from ._dD_detail import flush_screws
from ._household import ring, shell
from ._kit import feet4


@register("liquor_bottle", parts=("body", "cap"),
          extra_parts=("label", "neck", "shoulder_label", "back_label", "seal", "pour_spout", "emblem"),
          size_range=(0.15, 0.36), density=1000, variants=("square", "round", "flask"), placement="surface")
def liquor_bottle(rng: np.random.Generator, variant: str) -> list[Part]:
    tint = [(0.75, 0.45, 0.15), (0.85, 0.88, 0.9), (0.2, 0.35, 0.2), (0.35, 0.2, 0.1)][int(rng.integers(4))]
    glass = Material((*M.jitter(rng, tint, 0.04)[:3], 0.55), 0.08, 0.0, "glass")
    cap_mat = Material(M.jitter(rng, [(0.1, 0.1, 0.1), (0.7, 0.55, 0.3), (0.6, 0.1, 0.1)][int(rng.integers(3))], 0.03),
                       0.4, 0.5, "metal")
    parts = []
    if variant == "square":
        w, h = rng.uniform(0.075, 0.09), rng.uniform(0.2, 0.26)
        hb = h * 0.72
        parts.append(make_part("body", "body", S.box((w, w, hb), center=(0, 0, hb / 2), bevel=0.006), glass))
        parts.append(make_part("label", "label", S.box((w * 0.8, 0.002, hb * 0.45), center=(0, w / 2 + 0.0005, hb * 0.45)),
                               M.paper(rng)))
        nz0, nr = hb, 0.014
    elif variant == "round":
        r, h = rng.uniform(0.036, 0.045), rng.uniform(0.26, 0.32)
        hb = h * 0.66
        parts.append(make_part("body", "body", S.lathe([(r * 0.95, 0), (r, 0.005), (r, hb - 0.02), (r * 0.9, hb)],
                                                       sections=24), glass))
        parts.append(make_part("label", "label", ring([(r - 0.0005, hb * 0.25), (r + 0.0008, hb * 0.25),
                                                       (r + 0.0008, hb * 0.7), (r - 0.0005, hb * 0.7)], sections=24),
                               M.paper(rng)))
        nz0, nr = hb, 0.013
    else:
        w, d, h = rng.uniform(0.09, 0.11), rng.uniform(0.035, 0.045), rng.uniform(0.15, 0.2)
        hb = h * 0.75
        parts.append(make_part("body", "body", S.box((w, d, hb), center=(0, 0, hb / 2), bevel=0.012), glass))
        parts.append(make_part("label", "label", S.box((w * 0.7, 0.002, hb * 0.4), center=(0, d / 2 + 0.0005, hb * 0.5)),
                               M.paper(rng)))
        nz0, nr = hb, 0.011
    nh = h - nz0 - 0.025
    parts.append(make_part("neck", "neck", S.frustum(nr * 1.6, nr, nh, center=(0, 0, nz0 - 0.002), sections=16), glass))
    parts.append(make_part("shoulder_label", "shoulder_label",
                           ring([(nr * 1.2, nz0 + nh * 0.45), (nr * 1.35, nz0 + nh * 0.45), (nr * 1.3, nz0 + nh * 0.6),
                                 (nr * 1.15, nz0 + nh * 0.6)], sections=16), M.paper(rng)))
    parts.append(make_part("cap", "cap", S.cylinder(nr + 0.002, 0.028, center=(0, 0, h - 0.014), sections=16), cap_mat))
    # the tax seal strip over the cap, the back label, and the ring of the pourer under the cap
    parts.append(make_part("seal", "seal", S.box((0.008, 2 * nr + 0.0052, 0.02), center=(0, 0, h - 0.015)), M.paper(rng)))
    if variant == "round":
        parts.append(make_part("back_label", "back_label", S.box((r * 0.9, 0.001, hb * 0.2),
                                                                center=(0, -r - 0.0003, hb * 0.85 - hb * 0.1)), M.paper(rng)))
    else:
        parts.append(make_part("back_label", "back_label", S.box((0.04, 0.001, hb * 0.25),
                                                                center=(0, -(w if variant == "square" else d) / 2 - 0.0005, hb * 0.4)),
                               M.paper(rng)))
    parts.append(make_part("pour_spout", "pour_spout", S.cylinder(nr + 0.0015, 0.004, center=(0, 0, h - 0.03),
                                                                  sections=16), black()))
    # the distillery's crest embossed on the shoulder's front
    yf = r if variant == "round" else (w / 2 if variant == "square" else d / 2)
    parts.append(make_part("emblem", "emblem", S.box((0.02, 0.001, 0.02), center=(0, yf + 0.0003, hb * 0.85 if variant != "round" else hb - 0.03)),
                           glass))
    return parts


@register("wine_rack", parts=("shelf", "side_panel"), extra_parts=("top_panel", "foot", "cradle", "screw"), size_range=(0.3, 1.9),
          density=550, variants=("floor", "countertop", "tall"))
def wine_rack(rng: np.random.Generator, variant: str) -> list[Part]:
    cols = {"floor": int(rng.integers(4, 7)), "countertop": int(rng.integers(3, 5)), "tall": int(rng.integers(2, 4))}[variant]
    rows = {"floor": int(rng.integers(3, 6)), "countertop": 2, "tall": int(rng.integers(6, 10))}[variant]
    pitch, d = rng.uniform(0.095, 0.11), rng.uniform(0.25, 0.32)
    wood = M.wood(rng)
    t = 0.018
    w = cols * pitch + 2 * t
    rh = pitch
    h = rows * rh + t + 0.04
    parts = [make_part(f"side_panel_{i}", "side_panel", S.box((t, d, h), center=(s * (w / 2 - t / 2), 0, h / 2)), wood)
             for i, s in enumerate((-1, 1))]
    parts.append(make_part("top_panel", "top_panel", S.box((w, d, t), center=(0, 0, h + t / 2), bevel=0.003), wood))
    iw = w - 2 * t
    for k in range(rows):
        z = 0.04 + k * rh
        parts.append(make_part(f"shelf_{k}", "shelf", S.box((iw, d, 0.012), center=(0, 0, z + 0.006)), wood))
        # cradle bars in front and back keep the bottles from rolling; 13 cm apart at most, so
        # that a bottle's body (not its narrower neck) lies on both
        yb = min(d / 2 - 0.03, 0.065)
        bars = [S.box((iw, 0.015, 0.02), center=(0, y, z + 0.022)) for y in (-yb, yb)]
        parts.append(make_part(f"cradle_{k}", "cradle", bars, wood))
        # a screw through each side panel into the shelf's end, its head flush with the side
        for j, sx in enumerate((-1, 1)):
            parts += flush_screws(f"screw_{k}", [(sx * w / 2, 0.0, z + 0.006)], axis=(sx, 0, 0), radius=0.0045,
                                  start=j)
    parts += feet4("foot", w=w, d=d, r=0.015, h=0.04 - 0.0, mat=wood)
    return parts


@register("cocktail_shaker", parts=("body", "cap"), extra_parts=("strainer", "base_ring", "seam", "band", "lip"),
          size_range=(0.15, 0.3),
          density=800, variants=("cobbler", "boston"), placement="surface")
def cocktail_shaker(rng: np.random.Generator, variant: str) -> list[Part]:
    steel = M.solid((0.82, 0.82, 0.84), "metal", 0.2, 0.95)
    r, h = rng.uniform(0.04, 0.046), rng.uniform(0.14, 0.18)
    parts = [make_part("body", "body", S.frustum(r * 0.75, r, h, sections=24), steel)]
    if variant == "cobbler":
        parts.append(make_part("strainer", "strainer", S.frustum(r, r * 0.45, h * 0.35, center=(0, 0, h - 0.001),
                                                                 sections=24), steel))
        parts.append(make_part("cap", "cap", S.cylinder(r * 0.45, 0.03, center=(0, 0, h + h * 0.35 + 0.013), sections=16),
                               steel))
    else:
        parts.append(make_part("strainer", "strainer", S.cylinder(r * 0.95, 0.004, center=(0, 0, h + 0.002), sections=24),
                               steel))
        parts.append(make_part("cap", "cap", S.frustum(r * 0.92, r * 0.8, h * 0.6, center=(0, 0, h + 0.004), sections=24),
                               Material((0.85, 0.9, 0.95, 0.4), 0.05, 0.0, "glass")))
    # the rolled foot ring it stands on and the rolled lip where the top fits
    parts.append(make_part("base_ring", "base_ring", ring([(r * 0.75 - 0.002, 0.0), (r * 0.75 + 0.002, 0.0),
                                                           (r * 0.76 + 0.002, 0.006), (r * 0.76 - 0.002, 0.006)],
                                                          sections=24), steel))
    parts.append(make_part("seam", "seam", ring([(r - 0.002, h - 0.008), (r + 0.0015, h - 0.007), (r + 0.0015, h - 0.001),
                                                 (r - 0.002, h - 0.001)], sections=24), steel))
    # the pressed grip band round the body's waist, and the rolled lip the top seals on
    zg = h * 0.3
    rg = r * 0.75 + r * 0.25 * 0.3
    parts.append(make_part("band", "band", ring([(rg - 0.002, zg - 0.006), (rg + 0.0012, zg - 0.005), (rg + 0.0012, zg + 0.005),
                                                 (rg - 0.002, zg + 0.006)], sections=24), steel))
    if variant == "cobbler":  # the strainer's spout lip under the cap
        parts.append(make_part("lip", "lip", ring([(r * 0.45 - 0.002, h + h * 0.35 - 0.006), (r * 0.45 + 0.0015, h + h * 0.35 - 0.005),
                                                   (r * 0.45 + 0.0015, h + h * 0.35 - 0.001), (r * 0.45 - 0.002, h + h * 0.35 - 0.001)],
                                                  sections=16), steel))
    else:  # the mixing glass's thickened rim, at the top
        zt = h + 0.004 + h * 0.6
        parts.append(make_part("lip", "lip", ring([(r * 0.8 - 0.003, zt - 0.006), (r * 0.8 + 0.001, zt - 0.005), (r * 0.8 + 0.001, zt),
                                                   (r * 0.8 - 0.003, zt)], sections=24), parts[2].material))
    return parts


@register("ice_bucket", parts=("body",), extra_parts=("handle", "tongs", "lid", "knob", "rim", "foot_ring", "liner", "handle_plate", "rivet"), size_range=(0.14, 0.32), density=600,
          variants=("open", "lidded"), placement="surface")
def ice_bucket(rng: np.random.Generator, variant: str) -> list[Part]:
    r, h = rng.uniform(0.08, 0.11), rng.uniform(0.16, 0.22)
    steel = M.solid(M.jitter(rng, (0.8, 0.8, 0.82), 0.02), "metal", 0.2, 0.95)
    parts = [make_part("body", "body", S.vessel([(r * 0.82, 0.0), (r, h)], thickness=0.008, piece_sections=32), steel)]
    for i, s in enumerate((-1, 1)):
        parts.append(make_part(f"handle_{i}", "handle",
                               S.tube([(s * (r * 0.95), 0.015, h * 0.75), (s * (r + 0.022), 0.015, h * 0.75),
                                       (s * (r + 0.022), -0.015, h * 0.75), (s * (r * 0.95), -0.015, h * 0.75)], 0.004),
                               steel))
    # the plates riveting each handle to the wall
    for i, sx in enumerate((-1, 1)):
        parts.append(make_part(f"handle_plate_{i}", "handle_plate", S.box((0.003, 0.05, 0.02), center=(sx * (r * 0.95 + 0.0035), 0, h * 0.75)),
                               steel))
        # its two rivets, a domed head at each end of the plate
        parts += [make_part(f"rivet_{2 * i + j}", "rivet", S.cylinder(0.0035, 0.002, center=(sx * (r * 0.95 + 0.006), sy * 0.02, h * 0.75),
                                                                      axis=(1, 0, 0), sections=8), steel)
                  for j, sy in enumerate((-1, 1))]
    # the rolled rim, the foot ring and the insulated inner liner
    parts.append(make_part("rim", "rim", ring([(r - 0.008, h - 0.006), (r + 0.003, h - 0.005), (r + 0.003, h),
                                               (r - 0.008, h)], sections=24), steel))
    parts.append(make_part("foot_ring", "foot_ring", ring([(r * 0.82 - 0.006, 0.0), (r * 0.82 + 0.002, 0.0),
                                                           (r * 0.82 + 0.002, 0.008), (r * 0.82 - 0.006, 0.008)],
                                                          sections=24), steel))
    parts.append(make_part("liner", "liner", shell([(r * 0.82 - 0.01, 0.012), (r - 0.0095, h - 0.01)], 0.002, sections=20), M.plastic(rng)))
    if variant == "lidded":
        parts.append(make_part("lid", "lid", S.cylinder(r + 0.004, 0.01, center=(0, 0, h + 0.005), sections=24), steel))
        parts.append(make_part("knob", "knob", S.ellipsoid((0.015, 0.015, 0.012), center=(0, 0, h + 0.014)), steel))
    else:
        parts.append(make_part("tongs", "tongs", S.box((0.012, 0.02, h * 0.9), center=(r * 0.5, 0, h * 0.55),
                                                       R=np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1.0]])), steel))
    return parts
