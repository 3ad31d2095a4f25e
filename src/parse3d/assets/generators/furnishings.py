"""Small furnishings the outsiders' rooms name: coasters, jewelry boxes, folding screens, dog
beds, laptop stands, console tables, a dais, paper towel holders, and a croissant for the café
table.

A jewelry box's lid lifts on a back hinge over a lift-out ``tray`` (an internal support); a
folding screen stands as a zigzag of ``panel``s, its back (-Y) the side towards a wall; a
laptop stand's ``platform`` slopes up towards the back, a ``lip`` at its front edge holding the
laptop.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._casework import black
from ._dA_fixings import screws_under
from ._dD_detail import flush_screws
from ._detail_b import each
from ._household import open_box, ring
from ._kit import OPEN_DOOR, feet4, hinge_parts, legs4, mount, prismatic, revolute, rot


@register("coaster", parts=("body",), extra_parts=("pad", "rim", "design", "border", "edge_band"),
          size_range=(0.08, 0.12), density=800, variants=("round", "square", "rimmed"), placement="surface")
def coaster(rng: np.random.Generator, variant: str) -> list[Part]:
    s = rng.uniform(0.09, 0.105)
    mat = [M.wood(rng), M.stone(rng), M.ceramic(rng), Material(M.jitter(rng, (0.7, 0.55, 0.35), 0.03), 0.9, 0.0, "wood")][int(rng.integers(4))]
    cork = Material(M.jitter(rng, (0.65, 0.5, 0.35), 0.03), 0.95, 0.0, "wood")
    tp = 0.0015
    t = rng.uniform(0.004, 0.008)
    zt = tp + t  # the top face the glass stands on
    gold = Material((0.8, 0.65, 0.3, 1.0), 0.35, 0.8, "metal")
    ink = M.solid((0.15, 0.15, 0.2), "paper", 0.6)
    if variant == "square":
        parts = [make_part("pad", "pad", S.box((s - 0.004, s - 0.004, tp), center=(0, 0, tp / 2)), cork),
                 make_part("body", "body", S.box((s, s, t), center=(0, 0, tp + t / 2), bevel=0.001), mat),
                 # the printed design on the top face
                 make_part("design", "design", S.box((s * 0.75, s * 0.75, 0.0004), center=(0, 0, zt + 0.0002)),
                           M.solid(M.jitter(rng, (0.4, 0.4, 0.5), 0.3)[:3], "paper", 0.6))]
        # the printed line framing the design, the gilded band round the edge, and the maker's
        # stamp on the cork underneath
        a, b = s * 0.82, s * 0.012
        frame = [S.box((a, b, 0.0004), center=(0, sy * (a - b) / 2, zt + 0.0002)) for sy in (-1, 1)]
        frame += [S.box((b, a - 2 * b, 0.0004), center=(sx * (a - b) / 2, 0, zt + 0.0002)) for sx in (-1, 1)]
        parts.append(make_part("border", "border", frame, ink))
        e = 0.0006
        band = [S.box((s + 2 * e, e, t * 0.4), center=(0, sy * (s + e) / 2, tp + t * 0.5)) for sy in (-1, 1)]
        band += [S.box((e, s, t * 0.4), center=(sx * (s + e) / 2, 0, tp + t * 0.5)) for sx in (-1, 1)]
        parts.append(make_part("edge_band", "edge_band", band, gold))
        return parts
    parts = [make_part("pad", "pad", S.cylinder(s / 2 - 0.002, tp, center=(0, 0, tp / 2), sections=24), cork),
             make_part("body", "body", S.cylinder(s / 2, t, center=(0, 0, tp + t / 2), sections=24), mat)]
    if variant == "rimmed":
        parts.append(make_part("rim", "rim", ring([(s / 2 - 0.004, zt), (s / 2, zt), (s / 2, zt + 0.004),
                                                   (s / 2 - 0.004, zt + 0.004)], sections=24), mat))
    parts.append(make_part("design", "design", S.cylinder(s * 0.38, 0.0004, center=(0, 0, zt + 0.0002), sections=20),
                           M.solid(M.jitter(rng, (0.4, 0.4, 0.5), 0.3)[:3], "paper", 0.6)))
    rb = s * 0.41
    parts.append(make_part("border", "border", ring([(rb, zt), (rb + s * 0.012, zt), (rb + s * 0.012, zt + 0.0004),
                                                     (rb, zt + 0.0004)], sections=24), ink))
    parts.append(make_part("edge_band", "edge_band", ring([(s / 2 - 0.0003, tp + t * 0.3), (s / 2 + 0.0006, tp + t * 0.3),
                                                           (s / 2 + 0.0006, tp + t * 0.7), (s / 2 - 0.0003, tp + t * 0.7)],
                                                          sections=24), gold))
    return parts


@register("croissant", parts=("body",), extra_parts=("horn", "tip"),
          size_range=(0.09, 0.18), density=250, variants=("curved", "straight", "mini"), placement="surface")
def croissant(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.12, 0.16) if variant != "mini" else rng.uniform(0.09, 0.1)
    crust = M.food(rng, (0.78, 0.52, 0.22))
    rmax = L * 0.22
    bend = 0.0 if variant == "straight" else L * 0.25
    parts = []
    n = 5 if variant == "mini" else 7  # a full-size croissant shows seven rolls of dough, a mini five
    for k in range(n):  # rolled segments, fattest in the middle, bending towards -Y at the ends
        f = (k - (n - 1) / 2) / ((n - 1) / 2)
        x = f * L * 0.38
        y = -bend * f * f
        r = rmax * (1 - 0.55 * f * f)
        pts = S.ellipsoid((L * 0.13, r * 0.95, r * 0.75), center=(x, y, r * 0.6), subdivisions=1).mesh.vertices.copy()
        pts[:, 2] = np.maximum(pts[:, 2], 0.0)  # baked flat where it lay on the tray
        seg = S.hull(pts)
        name = "body" if k == n // 2 else (f"horn_{0 if k < n // 2 else 1}" if k in (0, n - 1) else f"body_{k}")
        label = "horn" if k in (0, n - 1) else "body"
        parts.append(make_part(name, label, seg, crust))
    # the point of the rolled dough triangle, laid over the middle roll's front
    parts.append(make_part("tip", "tip", S.ellipsoid((L * 0.05, rmax * 0.45, rmax * 0.1), center=(0, rmax * 0.4, rmax * 1.16),
                                                     subdivisions=1), crust))
    return parts


@register("jewelry_box", parts=("body", "lid"), extra_parts=("tray", "mirror", "clasp", "hinge", "foot", "drawer", "drawer_box",
                                                             "knob", "lining", "divider", "ring_roll", "lid_stay", "screw"),
          size_range=(0.12, 0.4), density=600, variants=("hinged", "drawers", "chest"), placement="surface")
def jewelry_box(rng: np.random.Generator, variant: str) -> list:
    wood = M.wood(rng) if rng.random() < 0.7 else M.leather(rng)
    velvet = Material(M.jitter(rng, [(0.5, 0.05, 0.1), (0.1, 0.15, 0.35), (0.1, 0.1, 0.1)][int(rng.integers(3))], 0.03), 0.95, 0.0, "fabric")
    brass = M.solid((0.78, 0.62, 0.3), "metal", 0.3, 0.9)
    w, d = rng.uniform(0.2, 0.3), rng.uniform(0.13, 0.2)
    t = 0.008
    zf = 0.006
    parts = feet4("foot", w=w, d=d, r=0.008, h=zf, mat=brass, inset=0.005)
    z = zf
    if variant == "drawers":  # a drawer below the lidded compartment
        hd = rng.uniform(0.045, 0.06)
        parts.append(make_part("case", "body", [S.box((w, d, t), center=(0, 0, z + t / 2)),
                                                S.box((w, t, hd), center=(0, -d / 2 + t / 2, z + hd / 2)),
                                                S.box((t, d - t, hd), center=(-w / 2 + t / 2, t / 2, z + hd / 2)),
                                                S.box((t, d - t, hd), center=(w / 2 - t / 2, t / 2, z + hd / 2))], wood))
        bw, bd, bh = w - 2 * t - 0.004, d - t - 0.006, hd - t - 0.004
        parts.append(make_part("drawer_box", "drawer_box", [s.moved((0, -d / 2 + t + 0.002 + bd / 2 - 0.003, z + t + 0.001))
                                                            for s in open_box(bw, bd, bh, 0.005)], velvet))
        parts.append(make_part("drawer", "drawer", S.box((w - 2 * t, 0.008, hd - t - 0.002), center=(0, d / 2 - 0.004, z + t + (hd - t) / 2)),
                               wood))
        parts.append(make_part("knob", "knob", S.ellipsoid((0.007, 0.007, 0.007), center=(0, d / 2 + 0.004, z + t + (hd - t) / 2),
                                                           subdivisions=1), brass))
        parts += [prismatic("drawer_slide", "case", "drawer_box", travel=bd * 0.7), mount("drawer_box", "drawer"), mount("drawer", "knob")]
        z += hd
    h = rng.uniform(0.075, 0.095)
    parts.append(make_part("body", "body", [s.moved((0, 0, z)) for s in open_box(w, d, h, t)], wood))
    parts.append(make_part("lining", "lining", S.box((w - 2 * t, d - 2 * t, 0.003), center=(0, 0, z + t + 0.0015)), velvet))
    ht = 0.046  # deep enough to hold rings and watches under the closed lid
    parts.append(make_part("tray", "tray", [s.moved((0, 0, z + h - ht - 0.002)) for s in open_box(w - 2 * t - 0.004, d - 2 * t - 0.004, ht, 0.004)],
                           velvet))
    # the tray's divider walling off a ring compartment on the left, and the velvet ring roll in it
    tw, td, zt = w - 2 * t - 0.004, d - 2 * t - 0.004, z + h - ht - 0.002
    parts.append(make_part("divider", "divider", S.box((0.004, td - 0.008, ht - 0.006),
                                                       center=(-tw / 6, 0, zt + 0.004 + (ht - 0.006) / 2)), velvet))
    # three rows of ring rolls side by side across the compartment's depth
    for k, dy in enumerate((-td * 0.28, 0.0, td * 0.28)):
        parts.append(make_part("ring_roll" if k == 0 else f"ring_roll_{k}", "ring_roll",
                               S.cylinder(min(0.009, td * 0.13), tw / 3 - 0.012, center=(-tw / 3, dy, zt + 0.004 + min(0.009, td * 0.13)),
                                          axis=(1, 0, 0), sections=10), velvet))
    zl = z + h
    hl = rng.uniform(0.02, 0.03) if variant != "chest" else rng.uniform(0.05, 0.06)
    if variant == "chest":  # a rounded chest lid
        lid = S.hull(np.vstack([[sx * w / 2, sy * d / 2, zl] for sx in (-1, 1) for sy in (-1, 1)]
                               + [[sx * w / 2, d / 2 * np.cos(a), zl + hl * np.sin(a)] for sx in (-1, 1)
                                  for a in np.linspace(0.3, np.pi - 0.3, 5)]))
    else:
        lid = S.box((w, d, hl), center=(0, 0, zl + hl / 2), bevel=0.003)
    parts.append(make_part("lid", "lid", lid, wood))
    if variant != "chest":
        parts.append(make_part("mirror", "mirror", S.box((w - 2 * t - 0.01, d - 2 * t - 0.01, 0.002), center=(0, 0, zl - 0.001 + 0.0)),
                               M.solid((0.8, 0.85, 0.9), "glass", 0.05, 0.9)))
        parts.append(mount("lid", "mirror"))
    parts.append(make_part("clasp", "clasp", S.box((0.02, 0.004, 0.02), center=(0, d / 2 + 0.002, zl)), brass))
    # the folding brass stay inside the right wall that holds the lid open, folded down
    parts.append(make_part("lid_stay", "lid_stay", S.box((0.003, d * 0.45, 0.004), center=(w / 2 - t - 0.0025, -d * 0.15, zl - 0.004)), brass))
    parts += hinge_parts("hinge", x=zl, y=-d / 2 - 0.003, z0=-w / 2 + 0.02, z1=w / 2 - 0.02, mat=brass, axis="x", radius=0.003,
                         length=0.025)
    parts.append(revolute("lid_hinge", "body", "lid", axis=(1, 0, 0), origin=(0, -d / 2, zl), opens=OPEN_DOOR * 0.6))
    # a brass screw through each hinge's lower leaf into the back wall and, on a flat lid, one
    # through its upper leaf into the lid's back edge (it turns with the lid)
    xs = [-w / 2 + 0.02 + (w - 0.04) * f for f in (0.12, 0.88)]
    parts += flush_screws("screw", [(x, -d / 2, zl - 0.007) for x in xs], axis=(0.0, -1.0, 0.0), radius=0.002, mat=brass)
    if variant != "chest":
        parts += flush_screws("screw", [(x, -d / 2, zl + hl * 0.5) for x in xs], axis=(0.0, -1.0, 0.0), radius=0.002, mat=brass,
                              start=2)
        parts += [mount("lid", "screw_2"), mount("lid", "screw_3")]
    return parts


@register("folding_screen", parts=("panel",), extra_parts=("frame", "hinge", "glide", "screw"),
          size_range=(1.2, 2.4), density=400, variants=("three_panel", "four_panel", "shoji"))
def folding_screen(rng: np.random.Generator, variant: str) -> list[Part]:
    n = 4 if variant == "four_panel" else 3
    pw, h = rng.uniform(0.4, 0.55), rng.uniform(1.6, 1.85)
    t = 0.025
    ang = np.deg2rad(rng.uniform(20, 35))
    wood = M.wood(rng)
    infill = M.fabric(rng) if variant != "shoji" else M.solid((0.95, 0.93, 0.86), "paper", 0.9)
    parts = []
    x = -n * pw * np.cos(ang) / 2
    y = 0.0
    prev = 0.0  # the previous panel's direction
    for k in range(n):
        s = 1 if k % 2 == 0 else -1  # a zigzag: each panel turns back the other way
        dx, dy = pw * np.cos(ang), s * pw * np.sin(ang)
        cx, cy = x + dx / 2, y + dy / 2
        R = rot((0, 0, 1), float(np.arctan2(dy, dx)))
        zf = 0.0  # the leaves stand on their bottom rails
        parts.append(make_part(f"panel_{k}", "panel", S.box((pw, t, h - 0.03), center=(cx, cy, (h - 0.03) / 2), R=R), infill))
        frame = [S.box((0.03, t, h - zf), center=(cx + sgn * (pw / 2 - 0.015) * np.cos(np.arctan2(dy, dx)),
                                               cy + sgn * (pw / 2 - 0.015) * np.sin(np.arctan2(dy, dx)), zf + (h - zf) / 2), R=R)
                 for sgn in (-1, 1)]
        frame += [S.box((pw - 0.06, t, 0.03), center=(cx, cy, zc), R=R) for zc in (zf + 0.015, h - 0.015)]
        if variant == "shoji":
            frame += [S.box((pw - 0.06, t * 0.6, 0.012), center=(cx, cy, zf + (h - zf) * f), R=R) for f in (0.25, 0.5, 0.75)]
        parts.append(make_part(f"frame_{k}", "frame", frame, wood))
        # a nylon glide let into the foot of each stile
        ca, sa = np.cos(np.arctan2(dy, dx)), np.sin(np.arctan2(dy, dx))
        for j, sgn in enumerate((-1, 1)):
            parts.append(make_part(f"glide_{2 * k + j}", "glide",
                                   S.cylinder(0.01, 0.004, center=(cx + sgn * (pw / 2 - 0.015) * ca, cy + sgn * (pw / 2 - 0.015) * sa, 0.002),
                                              sections=8), M.solid((0.85, 0.85, 0.82), "plastic", 0.4)))
        if k > 0:
            brass = M.solid((0.78, 0.62, 0.3), "metal", 0.3, 0.9)
            hinges = hinge_parts(f"hinge_{k}", x=x, y=y, z0=zf, z1=h, mat=brass, n=3, radius=0.008, length=0.06)
            parts += hinges
            # each hinge's two leaves lie on the front faces of the stiles either side of it, a
            # brass screw through each leaf into its stile
            a0, a1 = prev, float(np.arctan2(dy, dx))
            for j, hp in enumerate(hinges):
                zc = float(hp.mesh.bounds[:, 2].mean())
                pts = [((x - 0.015 * np.cos(a0)) - np.sin(a0) * t / 2, (y - 0.015 * np.sin(a0)) + np.cos(a0) * t / 2, zc, a0),
                       ((x + 0.015 * np.cos(a1)) - np.sin(a1) * t / 2, (y + 0.015 * np.sin(a1)) + np.cos(a1) * t / 2, zc, a1)]
                for i, (px, py, pz, a) in enumerate(pts):
                    parts += flush_screws(f"screw_{k}_{j}", [(px, py, pz)], axis=(-np.sin(a), np.cos(a), 0.0), radius=0.003,
                                          mat=brass, start=i)
        prev = float(np.arctan2(dy, dx))
        x, y = x + dx, y + dy
    return parts


@register("dog_bed", parts=("cushion",), extra_parts=("bolster", "base", "frame", "leg", "pillow", "piping", "zipper", "tag", "foot",
                                                     "grip", "corner"),
          size_range=(0.5, 1.2), density=150, variants=("round", "rectangular", "elevated"))
def dog_bed(rng: np.random.Generator, variant: str) -> list[Part]:
    fab = M.fabric(rng)
    inner = M.fabric(rng)
    if variant == "round":  # a donut: a cushion inside a bolster ring
        r = rng.uniform(0.3, 0.5)
        hb = rng.uniform(0.15, 0.22)
        return [make_part("base", "base", S.cylinder(r, 0.03, center=(0, 0, 0.015), sections=24), fab),
                make_part("bolster", "bolster", ring([(r * 0.65, 0.03), (r, 0.03), (r, hb), (r * 0.7, hb), (r * 0.62, hb * 0.6)],
                                                     sections=24), fab),
                make_part("cushion", "cushion", S.cylinder(r * 0.64, 0.06, center=(0, 0, 0.06), sections=24), inner),
                # the piping round the base seam, the cover's zip at the back, the care tag
                make_part("piping", "piping", ring([(r - 0.004, 0.024), (r + 0.006, 0.024), (r + 0.006, 0.036),
                                                    (r - 0.004, 0.036)], sections=24), inner),
                make_part("zipper", "zipper", S.box((0.3, 0.006, 0.012), center=(0, -r - 0.001, hb * 0.45)), black()),
                make_part("tag", "tag", S.box((0.05, 0.003, 0.03), center=(r * 0.7, r * 0.715, 0.06)),
                          M.solid((0.95, 0.95, 0.92), "fabric", 0.8)),
                # the piping round the bolster's crown
                make_part("piping_1", "piping", ring([(r * 0.8, hb - 0.006), (r * 0.9, hb - 0.006), (r * 0.9, hb + 0.002),
                                                      (r * 0.8, hb + 0.002)], sections=24), inner),
                *_grip_dots([(r * 0.5 * np.cos(a), r * 0.5 * np.sin(a)) for a in np.pi / 4 + np.arange(4) * np.pi / 2])]
    w, d = rng.uniform(0.6, 1.1), rng.uniform(0.5, 0.8)
    if variant == "elevated":  # a fabric sling on a frame with four short legs
        hl = rng.uniform(0.12, 0.2)
        metal = M.solid((0.2, 0.2, 0.22), "metal", 0.4, 0.7)
        fh = 0.012  # the rubber caps the legs stand on
        parts = legs4("leg", "leg", w=w, d=d, h=hl - fh, size=0.03, mat=metal, round_=True, z0=fh)
        parts += feet4("foot", w=w, d=d, r=0.017, h=fh, mat=black("rubber"), inset=-0.002)
        # the frame's four tubes (``frame``, ``frame_1``, ...), joined by the corner pieces
        parts += each("frame", "frame", [S.box((w, 0.03, 0.03), center=(0, sy * (d / 2 - 0.015), hl + 0.015)) for sy in (-1, 1)]
                      + [S.box((0.03, d - 0.06, 0.03), center=(sx * (w / 2 - 0.015), 0, hl + 0.015)) for sx in (-1, 1)], metal)
        parts.append(make_part("cushion", "cushion", S.box((w - 0.06, d - 0.06, 0.012), center=(0, 0, hl + 0.024)), fab))
        # the moulded corner pieces joining the frame's tubes over each leg
        for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"corner_{k}", "corner", S.box((0.045, 0.045, 0.036), center=(sx * (w / 2 - 0.0225), sy * (d / 2 - 0.0225),
                                                                                            hl + 0.015), bevel=0.005), black()))
        return parts
    hb = rng.uniform(0.18, 0.25)
    b = 0.1
    parts = [make_part("base", "base", S.box((w, d, 0.04), center=(0, 0, 0.02), bevel=0.01), fab)]
    parts.append(make_part("cushion", "cushion", S.box((w - 2 * b, d - b, 0.06), center=(0, b / 2, 0.07), bevel=0.02), inner))
    parts.append(make_part("bolster_0", "bolster", S.box((w, b, hb - 0.04), center=(0, -d / 2 + b / 2, 0.04 + (hb - 0.04) / 2), bevel=0.04),
                           fab))
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"bolster_{k + 1}", "bolster", S.box((b, d - b, hb * 0.8 - 0.04), center=(sx * (w / 2 - b / 2), b / 2,
                                                                                                         0.04 + (hb * 0.8 - 0.04) / 2),
                                                                    bevel=0.04), fab))
    parts.append(make_part("zipper", "zipper", S.box((w * 0.5, 0.006, 0.012), center=(0, -d / 2 - 0.001, 0.02)), black()))
    parts.append(make_part("tag", "tag", S.box((0.003, 0.05, 0.03), center=(w / 2 + 0.0015, d * 0.3, 0.02)),
                           M.solid((0.95, 0.95, 0.92), "fabric", 0.8)))
    # the piping along the back bolster's top seam, and the grip dots under the base
    parts.append(make_part("piping", "piping", S.box((w - 0.08, 0.012, 0.012), center=(0, -d / 2 + b / 2, hb - 0.006)), inner))
    parts += _grip_dots([(sx * w * 0.35, sy * d * 0.35) for sx, sy in [(-1, -1), (1, -1), (-1, 1), (1, 1)]])
    return parts


def _grip_dots(xy) -> list[Part]:
    """The rubber non-slip dots printed on a pet bed's underside at ``xy``."""
    return [make_part(f"grip_{k}", "grip", S.cylinder(0.02, 0.002, center=(x, y, 0.001), sections=10), black("rubber"))
            for k, (x, y) in enumerate(xy)]


@register("laptop_stand", parts=("platform", "base"), extra_parts=("lip", "arm", "leg", "pad", "hinge", "foot", "screw", "knob"),
          size_range=(0.2, 0.4), density=1500, variants=("angled", "adjustable", "riser"), placement="surface")
def laptop_stand(rng: np.random.Generator, variant: str) -> list[Part]:
    alu = M.solid(M.jitter(rng, (0.78, 0.78, 0.8), 0.03)[:3], "metal", 0.3, 0.9)
    rubber = M.solid((0.08, 0.08, 0.08), "rubber", 0.9)
    w, d = rng.uniform(0.24, 0.3), rng.uniform(0.22, 0.26)
    parts = []
    if variant == "riser":  # a flat shelf on four short legs
        h = rng.uniform(0.08, 0.14)
        parts += legs4("leg", "leg", w=w, d=d, h=h - 0.012, size=0.02, mat=alu)
        parts.append(make_part("platform", "platform", S.box((w, d, 0.012), center=(0, 0, h - 0.006), bevel=0.002), M.wood(rng)))
        # the two runners the legs stand on, front and back
        for k, sy in enumerate((-1, 1)):
            parts.append(make_part("base" if k == 0 else "base_1", "base",
                                   S.box((w, 0.02, 0.01), center=(0, sy * (d / 2 - 0.01), 0.005)), alu))
        parts += _stand_feet([(sx * w * 0.4, sy * (d / 2 - 0.01)) for sy in (-1, 1) for sx in (-1, 1)], rubber)
        # a countersunk screw up through each runner into the foot of the leg above it
        parts += flush_screws("screw", [(sx * (w / 2 - 0.01), sy * (d / 2 - 0.01), 0.0) for sy in (-1, 1) for sx in (-1, 1)],
                              axis=(0.0, 0.0, -1.0), radius=0.003)
        return parts
    tilt = np.deg2rad(rng.uniform(15, 25))
    hf = 0.03  # the platform's front edge height
    hb_ = hf + d * np.sin(tilt)
    R = rot((1, 0, 0), -tilt)  # sloping up towards the back (-Y)
    parts.append(make_part("platform", "platform", S.box((w, d, 0.006), center=(0, 0, (hf + hb_) / 2), R=R), alu))
    parts.append(make_part("lip", "lip", S.box((w * 0.8, 0.008, 0.018), center=(0, d / 2 * np.cos(tilt) - 0.004, hf + 0.009)), alu))
    parts.append(make_part("base", "base", S.box((w * 0.9, d * 0.9, 0.008), center=(0, 0, 0.004)), alu))
    if variant == "angled":
        # a side arm each side: a rail under the platform on an upright at the back
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"arm_{k}", "arm",
                                   [S.box((0.012, d * 0.85, 0.012), center=(sx * w * 0.4, 0, (hf + hb_) / 2 - 0.01), R=R),
                                    S.box((0.012, 0.012, hb_ - 0.01), center=(sx * w * 0.4, -d * 0.4 * np.cos(tilt),
                                                                              (hb_ - 0.01) / 2 + 0.004))], alu))
            # the two screws fixing each arm's upright to the base, heads on its outer face
            parts += [make_part(f"screw_{2 * k + j}", "screw", S.cylinder(0.003, 0.0015, center=(sx * (w * 0.4 + 0.00675), -d * 0.4 * np.cos(tilt),
                                                                                             zs), axis=(1, 0, 0), sections=8), alu)
                      for j, zs in enumerate((0.014, 0.014 + (hb_ - 0.02) * 0.5))]
    else:  # an arm on hinges: one strut from the base's front to the platform's back
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"arm_{k}", "arm", S.tube([(sx * w * 0.35, d * 0.35, 0.008), (sx * w * 0.35, -d * 0.35, hb_ - 0.012)],
                                                             0.008, sections=8), alu))
        parts += hinge_parts("hinge", x=0.012, y=d * 0.35, z0=-w * 0.4, z1=w * 0.4, mat=alu, axis="x", radius=0.008, length=0.03)
        # the tension knob on each hinge's outer end that locks the angle
        parts += [make_part(f"knob_{k}", "knob", S.cylinder(0.012, 0.008, center=(sx * (w * 0.4 + 0.015 + 0.004), d * 0.35, 0.012), axis=(1, 0, 0),
                                                            sections=12), M.solid((0.1, 0.1, 0.1), "plastic", 0.5))
                  for k, sx in enumerate((-1, 1))]
    for k, (x, y) in enumerate([(-w * 0.3, -d * 0.2), (w * 0.3, -d * 0.2), (-w * 0.3, d * 0.3), (w * 0.3, d * 0.3)]):
        parts.append(make_part(f"pad_{k}", "pad", S.cylinder(0.012, 0.002, center=(x, y, hf + (hb_ - hf) * (0.5 - y / d) + 0.004),
                                                             sections=10), rubber))
    parts += _stand_feet([(sx * w * 0.38, sy * d * 0.38) for sy in (-1, 1) for sx in (-1, 1)], rubber)
    return parts


def _stand_feet(xy, rubber) -> list[Part]:
    """Rubber feet let into the underside of a stand's base at ``xy`` (it stands as before)."""
    return [make_part(f"foot_{k}", "foot", S.cylinder(0.008, 0.002, center=(x, y, 0.001), sections=8), rubber)
            for k, (x, y) in enumerate(xy)]


@register("console_table", parts=("tabletop", "leg"), extra_parts=("shelf", "apron", "drawer", "drawer_box", "knob", "stretcher", "foot",
                                                             "tenon", "corbel", "corner_block", "kicker", "screw"),
          size_range=(0.8, 1.6), density=600, variants=("shelf", "drawers", "trestle"))
def console_table(rng: np.random.Generator, variant: str) -> list:
    w, d, h = rng.uniform(0.9, 1.5), rng.uniform(0.3, 0.42), rng.uniform(0.74, 0.82)
    wood = M.wood(rng)
    t = 0.03
    parts = [make_part("tabletop", "tabletop", S.box((w, d, t), center=(0, 0, h - t / 2), bevel=0.004), wood)]
    ha = 0.08
    apron = [S.box((w - 0.08, 0.02, ha), center=(0, sy * (d / 2 - 0.03), h - t - ha / 2)) for sy in (-1, 1)]
    apron += [S.box((0.02, d - 0.08, ha), center=(sx * (w / 2 - 0.03), 0, h - t - ha / 2)) for sx in (-1, 1)]
    if variant == "trestle":  # two panel ends joined by a stretcher
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"leg_{k}", "leg", S.box((0.04, d - 0.04, h - t), center=(sx * (w / 2 - 0.06), 0, (h - t) / 2)), wood))
        parts.append(make_part("stretcher", "stretcher", S.box((w - 0.16, 0.04, 0.06), center=(0, 0, 0.2)), wood))
        parts += [make_part(f"apron_{k}", "apron", a, wood) for k, a in enumerate(apron[:2])]
        # the feet under each trestle end
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"foot_{k}", "foot", S.box((0.08, d - 0.02, 0.03), center=(sx * (w / 2 - 0.06), 0, 0.015),
                                                             bevel=0.004), wood))
        # the stretcher's through-tenons standing out past each end, and the corbels under the
        # top's overhang on each end
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"tenon_{k}", "tenon", S.box((0.04, 0.03, 0.045), center=(sx * (w / 2 - 0.06 + 0.04), 0, 0.2)), wood))
            parts.append(make_part(f"corbel_{k}", "corbel", S.box((0.05, d - 0.08, 0.06),
                                                                 center=(sx * (w / 2 - 0.06 + 0.045), 0, h - t - 0.03)), wood))
        return parts
    parts += legs4("leg", "leg", w=w, d=d, h=h - t, size=0.04, mat=wood, inset=0.01)
    # glide caps round the legs' ends, and the glued blocks in the apron's corners
    cap = M.solid((0.1, 0.1, 0.1), "plastic", 0.7)
    lx, ly = w / 2 - 0.03, d / 2 - 0.03
    corners = [(-1, -1), (1, -1), (-1, 1), (1, 1)]
    parts += [make_part(f"foot_{k}", "foot", S.cylinder(0.024, 0.008, center=(sx * lx, sy * ly, 0.004), sections=10), cap)
              for k, (sx, sy) in enumerate(corners)]
    parts += [make_part(f"corner_block_{k}", "corner_block",
                        S.box((0.04, 0.04, 0.05), center=(sx * (lx - 0.05), sy * (ly - 0.05), h - t - 0.025)), wood)
              for k, (sx, sy) in enumerate(corners)]
    if variant == "drawers":
        parts += [make_part(f"apron_{k}", "apron", a, wood) for k, a in enumerate([apron[0]] + apron[2:])]
        n = 2
        dw = (w - 0.1) / n
        for k in range(n):
            x = -w / 2 + 0.05 + dw * (k + 0.5)
            bd = d - 0.08
            parts.append(make_part(f"drawer_{k}_box", "drawer_box", [s.moved((x, 0.0, h - t - ha + 0.004))
                                                                     for s in open_box(dw - 0.02, bd, ha - 0.012, 0.008)], wood))
            parts.append(make_part(f"drawer_{k}", "drawer", S.box((dw - 0.012, 0.018, ha - 0.008), center=(x, d / 2 - 0.03 + 0.009, h - t - ha / 2)),
                                   wood))
            parts.append(make_part(f"knob_{k}", "knob", S.ellipsoid((0.012, 0.012, 0.012), center=(x, d / 2 - 0.012 + 0.01, h - t - ha / 2),
                                                                    subdivisions=1), M.metal(rng)))
            parts += [prismatic(f"drawer_{k}_slide", "tabletop", f"drawer_{k}_box", travel=bd * 0.7),
                      mount(f"drawer_{k}_box", f"drawer_{k}"), mount(f"drawer_{k}", f"knob_{k}")]
        # the kicker strips above each drawer's sides that keep it from tipping as it opens
        for k in range(n):
            x = -w / 2 + 0.05 + dw * (k + 0.5)
            for j, sx in enumerate((-1, 1)):
                parts.append(make_part(f"kicker_{2 * k + j}", "kicker",
                                       S.box((0.015, d - 0.1, 0.003), center=(x + sx * (dw / 2 - 0.02), -0.01, h - t - 0.0015)), wood))
    else:
        parts += [make_part(f"apron_{k}", "apron", a, wood) for k, a in enumerate(apron)]
        zs = rng.uniform(0.15, 0.25)
        parts.append(make_part("shelf", "shelf", S.box((w - 0.02, d - 0.02, 0.02), center=(0, 0, zs)), wood))
        # the stretchers the shelf rests on, joining each end's pair of legs
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"stretcher_{k}", "stretcher", S.box((0.03, d - 0.1, 0.04), center=(sx * (w / 2 - 0.03), 0, zs - 0.03)),
                                   wood))
    # each corner block is screwed up into the top
    return parts + screws_under(parts, "corner_block")


@register("dais", parts=("top", "base"), extra_parts=("fascia", "foot", "nosing", "handle"),
          size_range=(0.6, 2.6), density=500, variants=("tokonoma", "stage", "plinth"))
def dais(rng: np.random.Generator, variant: str) -> list[Part]:
    wood = M.wood(rng)
    if variant == "tokonoma":  # a low alcove platform: a thick board on a frame, a lacquered front fascia
        w, d, h = rng.uniform(1.2, 1.9), rng.uniform(0.45, 0.7), rng.uniform(0.08, 0.15)
    elif variant == "stage":
        w, d, h = rng.uniform(1.6, 2.5), rng.uniform(1.0, 1.6), rng.uniform(0.2, 0.4)
    else:
        w, d, h = rng.uniform(0.6, 1.0), rng.uniform(0.5, 0.8), rng.uniform(0.2, 0.35)
    t = 0.03
    zf = 0.01
    parts = [make_part("base", "base", S.box((w - 0.04, d - 0.04, h - t - zf), center=(0, -0.01, zf + (h - t - zf) / 2)), wood),
             make_part("top", "top", S.box((w, d, t), center=(0, 0, h - t / 2), bevel=0.003), wood),
             make_part("fascia", "fascia", S.box((w, 0.02, h - t), center=(0, d / 2 - 0.01, (h - t) / 2)),
                       Material(M.jitter(rng, (0.1, 0.06, 0.05), 0.02), 0.3, 0.0, "wood"))]
    parts += feet4("foot", w=w - 0.06, d=d - 0.06, r=0.02, h=zf, mat=wood)
    # the fascia boards on the two ends, the rounded nosing along the top's front edge, and a
    # hand grip let into each end for carrying it
    dark = parts[2].material
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"fascia_{k + 1}", "fascia", S.box((0.012, d - 0.02, h - t), center=(sx * (w / 2 - 0.006), -0.01, (h - t) / 2)),
                               dark))
    parts.append(make_part("nosing", "nosing", S.box((w, 0.012, 0.012), center=(0, d / 2 - 0.006, h - t - 0.006), bevel=0.003), wood))
    metal = M.solid((0.2, 0.2, 0.22), "metal", 0.5, 0.6)
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"handle_{k}", "handle", S.box((0.004, min(0.12, d * 0.3), min(0.03, (h - t) * 0.3)),
                                                             center=(sx * (w / 2 - 0.001), -0.01, (h - t) * 0.6)), metal))
    return parts


@register("paper_towel_holder", parts=("roll", "rod"), extra_parts=("bracket", "base", "arm", "cap", "core", "tail", "screw", "foot"),
          size_range=(0.25, 0.4), density=300, variants=("under_cabinet", "wall", "countertop"), placement="wall")
def paper_towel_holder(rng: np.random.Generator, variant: str) -> list[Part]:
    L, rr = rng.uniform(0.27, 0.28), rng.uniform(0.055, 0.065)
    metal = M.solid(M.jitter(rng, (0.75, 0.75, 0.77), 0.03)[:3], "metal", 0.3, 0.9) if rng.random() < 0.6 else M.wood(rng)
    towel = M.solid((0.96, 0.96, 0.94), "paper", 0.95)
    parts = []
    if variant == "countertop":  # a round base with an upright rod, the roll standing on it
        parts.append(make_part("base", "base", S.cylinder(0.08, 0.015, center=(0, 0, 0.0075), sections=24), metal))
        parts.append(make_part("rod", "rod", S.cylinder(0.01, L + 0.03, center=(0, 0, 0.015 + (L + 0.03) / 2), sections=12), metal))
        parts.append(make_part("roll", "roll", S.cylinder(rr, L, center=(0, 0, 0.016 + L / 2), sections=20), towel))
        parts.append(make_part("cap", "cap", S.ellipsoid((0.016, 0.016, 0.016), center=(0, 0, 0.015 + L + 0.03), subdivisions=1), metal))
        # the cardboard core showing at the roll's top, the loose sheet hanging down its side,
        # and the rubber feet let into the base
        parts.append(make_part("core", "core", ring([(0.02, 0.016 + L - 0.002), (0.022, 0.016 + L - 0.002), (0.022, 0.016 + L + 0.001),
                                                      (0.02, 0.016 + L + 0.001)], sections=16), M.paper(rng)))
        parts.append(make_part("tail", "tail", S.box((0.1, 0.0015, L * 0.4), center=(0, rr + 0.00075, 0.016 + L * 0.55)), towel))
        for k, a in enumerate(np.linspace(0, 2 * np.pi, 3, endpoint=False)):
            parts.append(make_part(f"foot_{k}", "foot", S.cylinder(0.008, 0.002, center=(0.06 * np.cos(a), 0.06 * np.sin(a), 0.001),
                                                                   sections=8), black("rubber")))
        return parts
    # a rod across two arms; under a cabinet the bracket is on top, on a wall it is at the back
    arm = rr + 0.02
    if variant == "under_cabinet":
        zc = arm
        parts.append(make_part("bracket", "bracket", S.box((L + 0.05, 0.06, 0.006), center=(0, 0, 2 * arm - 0.003)), metal))
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"arm_{k}", "arm", S.box((0.006, 0.04, arm), center=(sx * (L / 2 + 0.015), 0, 2 * arm - 0.006 - arm / 2)),
                                   metal))
        yc = 0.0
    else:
        zc = arm
        parts.append(make_part("bracket", "bracket", S.box((L + 0.05, 0.006, 0.06), center=(0, 0.003, zc)), metal))
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"arm_{k}", "arm", S.box((0.006, arm, 0.04), center=(sx * (L / 2 + 0.015), 0.006 + arm / 2, zc)), metal))
        yc = 0.006 + arm
    parts.append(make_part("rod", "rod", S.cylinder(0.01, L + 0.03, center=(0, yc, zc), axis=(1, 0, 0), sections=12), metal))
    parts.append(make_part("roll", "roll", S.cylinder(rr, L, center=(0, yc, zc), axis=(1, 0, 0), sections=20), towel))
    # the cardboard core at the roll's end, the loose sheet hanging from its front, and the
    # screws holding the bracket
    parts.append(make_part("core", "core", ring([(0.02, L / 2 - 0.002), (0.022, L / 2 - 0.002), (0.022, L / 2 + 0.001),
                                                  (0.02, L / 2 + 0.001)], sections=16)
                           .apply(np.array([[0, 0, 1, 0], [0, 1, 0, yc], [-1, 0, 0, zc], [0, 0, 0, 1.0]])), M.paper(rng)))
    parts.append(make_part("tail", "tail", S.box((L * 0.9, 0.0015, zc * 0.6), center=(0, yc + rr + 0.00075, zc - zc * 0.3 + 0.001)), towel))
    for k, sx in enumerate((-1, 1)):
        if variant == "under_cabinet":
            c, ax = (sx * L * 0.35, 0, 2 * arm - 0.0065), (0, 0, 1)
        else:
            c, ax = (sx * L * 0.35, 0.0065, zc), (0, 1, 0)
        parts.append(make_part(f"screw_{k}", "screw", S.cylinder(0.004, 0.001, center=c, axis=ax, sections=8), metal))
    return parts
