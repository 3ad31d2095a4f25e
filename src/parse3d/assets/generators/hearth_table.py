"""Things people name at a set table, by a fireplace and in a hallway: a cloth napkin, a
decanter, a mantel clock, a log of firewood, a closed umbrella and a free-standing clothes rack.

Each stands or lies on its bottom at z = 0, front toward +Y. The umbrella stands furled on its
tip with its handle up (it leans or hangs by the handle in a scene; it does not stand alone).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._household import arc, ring


@register("napkin", parts=("body",), extra_parts=("fold", "hem"), size_range=(0.08, 0.26),
          density=300, variants=("square", "oblong", "triangle"), placement="surface")
def napkin(rng: np.random.Generator, variant: str) -> list[Part]:
    """A cloth napkin folded flat: in quarters (square), in three along its length (oblong) or
    corner to corner (triangle). ``fold`` is the folded edge, ``hem`` the stitched border."""
    mat = M.fabric(rng)
    hem_mat = M.solid(tuple(min(1.0, c * 0.85) for c in mat.color[:3]), "fabric", 0.9)
    t = rng.uniform(0.005, 0.009)  # four to six layers of cotton
    if variant == "triangle":
        a = rng.uniform(0.14, 0.2)  # the folded edge along x; the point toward +Y
        tri = np.array([[-a / 2, -a / 4], [a / 2, -a / 4], [0.0, a / 4]])
        body = S.prism(tri, 0.0, t)
        fold = S.box((a * 0.96, 0.006, t * 0.4), center=(0, -a / 4 + 0.004, t + t * 0.2))
        return [make_part("body", "body", body, mat), make_part("fold", "fold", fold, mat)]
    if variant == "square":
        w = d = rng.uniform(0.1, 0.15)
    else:
        w, d = rng.uniform(0.18, 0.24), rng.uniform(0.07, 0.1)
    body = S.box((w, d, t), center=(0, 0, t / 2), bevel=min(t * 0.45, 0.003))
    # the folded edge (a rounded roll along the front) and the hem line along the back
    fold = S.cylinder(t * 0.55, w * 0.97, center=(0, -d / 2 + t * 0.55, t * 0.55), axis=(1, 0, 0),
                      sections=10)
    hem = S.box((w * 0.94, 0.004, 0.0008), center=(0, d / 2 - 0.008, t + 0.0004))
    return [make_part("body", "body", body, mat), make_part("fold", "fold", fold, mat),
            make_part("hem", "hem", hem, hem_mat)]


@register("decanter", parts=("body",), extra_parts=("neck", "stopper", "lip", "base"),
          size_range=(0.2, 0.38), density=1000, variants=("wine", "whisky", "carafe"),
          placement="surface")
def decanter(rng: np.random.Generator, variant: str) -> list[Part]:
    """A glass decanter: a wide low bowl with a long neck (wine), a heavy squared bottle with a
    ball stopper (whisky) or a plain carafe with a flared lip and no stopper."""
    glass = M.glass(rng)
    parts: list[Part] = []
    if variant == "whisky":
        w = rng.uniform(0.085, 0.11)
        hb = rng.uniform(0.14, 0.18)
        base = S.box((w, w, 0.018), center=(0, 0, 0.009), bevel=0.004)
        body = S.box((w * 0.97, w * 0.97, hb - 0.018), center=(0, 0, 0.018 + (hb - 0.018) / 2), bevel=0.01)
        rn = w * 0.2
        neck = S.lathe([(w * 0.42, hb - 0.002), (rn, hb + 0.02), (rn, hb + 0.045)], sections=20)
        lip = ring([(rn * 0.7, hb + 0.045), (rn * 1.15, hb + 0.045), (rn * 1.15, hb + 0.052),
                    (rn * 0.7, hb + 0.052)], sections=20)
        ball = rng.uniform(0.024, 0.032)
        stopper = S.union([S.cylinder(rn * 0.7, 0.02, center=(0, 0, hb + 0.042), sections=12),
                           S.ellipsoid((ball, ball, ball * 0.9), center=(0, 0, hb + 0.052 + ball * 0.85))])
        parts += [make_part("base", "base", base, glass), make_part("body", "body", body, glass)]
    else:
        r = rng.uniform(0.08, 0.11) if variant == "wine" else rng.uniform(0.05, 0.065)
        h = rng.uniform(0.24, 0.3) if variant == "wine" else rng.uniform(0.2, 0.26)
        rn = rng.uniform(0.018, 0.024)
        if variant == "wine":  # a broad shallow bowl that narrows into a long neck
            prof = [(r * 0.55, 0.0), (r * 0.85, 0.012), (r, h * 0.14), (r * 0.8, h * 0.3),
                    (rn * 1.6, h * 0.45), (rn, h * 0.55)]
        else:  # a carafe: a straight-sided jug narrowing to its shoulder
            prof = [(r * 0.92, 0.0), (r, 0.01), (r, h * 0.55), (r * 0.7, h * 0.72), (rn * 1.3, h * 0.82)]
        body = S.lathe(prof, sections=32)
        z_neck = prof[-1][1]
        top = h * 0.95
        neck = S.lathe([(prof[-1][0], z_neck - 0.001), (rn, z_neck + 0.02), (rn, top - 0.006)], sections=20)
        flare = rn * (1.5 if variant == "carafe" else 1.2)
        lip = ring([(rn * 0.75, top - 0.008), (flare, top - 0.002), (flare, top), (rn * 0.75, top)],
                   sections=24)
        parts.append(make_part("body", "body", body, glass))
        hb = top - 0.045
        stopper = None
        if variant == "wine":
            stopper = S.union([S.cylinder(rn * 0.7, 0.025, center=(0, 0, top - 0.004), sections=12),
                               S.lathe([(rn * 0.5, top + 0.008), (rn * 1.6, top + 0.03),
                                        (rn * 0.3, top + 0.06)], sections=16)])
        # a ring of raised glass where the bowl meets the table
        base = ring([(prof[0][0] * 0.8, 0.0), (prof[0][0] + 0.004, 0.0), (prof[0][0] + 0.004, 0.003),
                     (prof[0][0] * 0.8, 0.003)], sections=24)
        parts.append(make_part("base", "base", base, glass))
    parts += [make_part("neck", "neck", neck, glass), make_part("lip", "lip", lip, glass)]
    if stopper is not None:
        parts.append(make_part("stopper", "stopper", stopper, glass))
    return parts


@register("mantel_clock", parts=("body", "face"), extra_parts=("hand", "bezel", "foot", "handle", "finial"),
          size_range=(0.12, 0.42), density=700, variants=("arched", "carriage", "drum"),
          placement="surface")
def mantel_clock(rng: np.random.Generator, variant: str) -> list[Part]:
    """A clock that stands on a mantel or a shelf, its dial to the front (+Y): a wooden case
    with an arched top, a brass carriage clock with a carrying handle, or a round drum on a
    plinth."""
    wood = M.wood(rng)
    brass = M.solid(M.jitter(rng, (0.78, 0.62, 0.3), 0.03), "metal", 0.3, 0.9)
    dial = M.solid((0.95, 0.93, 0.86), "paint", 0.5)
    black = M.solid((0.05, 0.05, 0.05), "paint", 0.4)
    parts: list[Part] = []
    if variant == "carriage":
        w, d, h = rng.uniform(0.08, 0.11), rng.uniform(0.07, 0.09), rng.uniform(0.11, 0.15)
        body = S.box((w, d, h), center=(0, 0, h / 2), bevel=0.003)
        parts.append(make_part("body", "body", body, brass))
        # the carrying handle folded down over the top, its hinges at the sides
        hp = arc((0, 0, h), w * 0.42, 0.0, np.pi, n=9, u=(1, 0, 0), v=(0, 0, 1), squash=0.35)
        parts.append(make_part("handle", "handle", S.tube(hp, 0.003, sections=8), brass))
        rf = min(w, h) * 0.34
        zf = h * 0.55
    elif variant == "drum":
        rd = rng.uniform(0.06, 0.09)
        pw, pd, ph = rd * 2.6, rd * 1.1, rng.uniform(0.025, 0.035)
        plinth = S.box((pw, pd, ph), center=(0, 0, ph / 2), bevel=0.004)
        drum = S.cylinder(rd, rd * 0.9, center=(0, 0, ph + rd), axis=(0, 1, 0), sections=32)
        parts += [make_part("foot", "foot", plinth, wood), make_part("body", "body", drum, brass)]
        d = rd * 0.9
        rf = rd * 0.82
        zf = ph + rd
    else:  # arched: a tombstone case, a flat-sided box under a half-round top
        w, d = rng.uniform(0.18, 0.28), rng.uniform(0.09, 0.12)
        hs = rng.uniform(0.16, 0.22)
        arch = S.cylinder(w / 2, d, center=(0, 0, hs), axis=(0, 1, 0), sections=32)
        box = S.box((w, d, hs), center=(0, 0, hs / 2))
        # the lower half of the arch's cylinder lies inside the box: hull the two into one case
        case = S.hull(np.vstack([box.mesh.vertices, arch.mesh.vertices[arch.mesh.vertices[:, 2] >= hs]]))
        parts.append(make_part("body", "body", case, wood))
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"foot_{k}", "foot", S.box((0.03, d * 0.9, 0.012),
                                                              center=(sx * (w / 2 - 0.025), 0, -0.006)), brass))
        parts.append(make_part("finial", "finial", S.ellipsoid((0.012, 0.012, 0.016), center=(0, 0, hs + w / 2 + 0.012)),
                               brass))
        rf = min(w * 0.34, hs * 0.45)
        zf = hs * 0.75 + rf * 0.3
    y0 = d / 2
    face = S.cylinder(rf, 0.003, center=(0, y0 + 0.0015, zf), axis=(0, 1, 0), sections=32)
    bezel = ring([(rf, 0.0), (rf + 0.006, 0.0), (rf + 0.006, 0.006), (rf, 0.006)], sections=32)
    bezel = S.transformed(bezel, _turned(ABOUT_Y, (0, y0, zf)))
    parts += [make_part("face", "face", face, dial), make_part("bezel", "bezel", bezel, brass)]
    for k, (ang, ln) in enumerate(((0.6, 0.55), (2.4, 0.8))):  # hour and minute hands
        hx, hz = np.sin(ang) * rf * ln, np.cos(ang) * rf * ln
        parts.append(make_part(f"hand_{k}", "hand", S.hull(np.array(
            [[-0.002, y0 + 0.003, zf], [0.002, y0 + 0.003, zf], [hx, y0 + 0.003, zf + hz],
             [-0.002, y0 + 0.0045, zf], [0.002, y0 + 0.0045, zf], [hx, y0 + 0.0045, zf + hz]])), black))
    return parts


#: Rotations turning a ring about +Z into one about +Y (a clock's bezel) or about +X (a log's
#: bark).
ABOUT_Y = np.array([[1.0, 0, 0], [0, 0, 1.0], [0, -1.0, 0]])
ABOUT_X = np.array([[0, 0, 1.0], [0, 1.0, 0], [-1.0, 0, 0]])


def _turned(R: np.ndarray, at) -> np.ndarray:
    """The (4, 4) transform rotating by ``R`` and moving the origin to ``at``."""
    T = np.eye(4)
    T[:3, :3] = R
    T[:3, 3] = at
    return T


@register("firewood", parts=("body",), extra_parts=("bark", "end_grain"), size_range=(0.25, 0.5),
          density=650, variants=("round", "split", "half"), placement="floor")
def firewood(rng: np.random.Generator, variant: str) -> list[Part]:
    """A log of firewood lying along x: a whole round with its bark, a quarter split from a
    round (bark on its curved side) or a half round lying on its flat face."""
    wood = M.solid(M.jitter(rng, (0.72, 0.55, 0.36), 0.05), "wood", 0.8)
    bark = M.solid(M.jitter(rng, (0.3, 0.22, 0.15), 0.04), "wood", 0.95)
    length = rng.uniform(0.26, 0.45)
    r = rng.uniform(0.045, 0.08)
    if variant == "round":
        core = S.cylinder(r * 0.92, length, center=(0, 0, r), axis=(1, 0, 0), sections=16)
        skin = ring([(r * 0.9, -length / 2 + 0.003), (r, -length / 2 + 0.003), (r, length / 2 - 0.003),
                     (r * 0.9, length / 2 - 0.003)], sections=16)
        skin = S.transformed(skin, _turned(ABOUT_X, (0, 0, r)))
        ends = [S.cylinder(r * 0.9, 0.002, center=(sx * (length / 2 - 0.001), 0, r), axis=(1, 0, 0), sections=16)
                for sx in (-1, 1)]
        return [make_part("body", "body", core, wood), make_part("bark", "bark", skin, bark),
                *[make_part(f"end_grain_{k}", "end_grain", e, wood) for k, e in enumerate(ends)]]
    a = np.linspace(0, np.pi if variant == "half" else np.pi / 2, 7)
    if variant == "half":  # flat face down, the curved bark up
        sec_in = np.c_[(r - 0.008) * np.cos(a), (r - 0.008) * np.sin(a)]
    else:  # a quarter: one flat face down, the other toward -Y, the bark up and to the front
        sec_in = np.vstack([[0.0, 0.0], np.c_[(r - 0.008) * np.cos(a), (r - 0.008) * np.sin(a)]])
    body = S.hull(np.vstack([np.c_[np.full(len(sec_in), -length / 2), sec_in[:, 0], sec_in[:, 1]],
                             np.c_[np.full(len(sec_in), length / 2), sec_in[:, 0], sec_in[:, 1]]]))
    skin = [S.hull(np.array([[x, r0 * np.cos(t), r0 * np.sin(t)] for x in (-length / 2 + 0.003, length / 2 - 0.003)
                             for t in (t0, t1) for r0 in (r - 0.009, r)]))
            for t0, t1 in zip(a[:-1], a[1:], strict=True)]
    return [make_part("body", "body", body, wood), make_part("bark", "bark", skin, bark)]


@register("umbrella", parts=("canopy", "shaft", "handle"), extra_parts=("tip", "strap", "runner"),
          size_range=(0.25, 1.0), density=400, variants=("crook", "straight", "compact"),
          placement="floor")
def umbrella(rng: np.random.Generator, variant: str) -> list[Part]:
    """A closed umbrella standing on its tip: the furled canopy round the shaft, held by its
    strap, and a crook handle (hangs on a hook), a straight grip or, for a compact folding
    umbrella, a short grip over a short furled canopy."""
    cloth = M.solid(M.jitter(rng, [(0.05, 0.05, 0.08), (0.5, 0.08, 0.1), (0.1, 0.2, 0.45),
                                   (0.15, 0.3, 0.15)][int(rng.integers(4))], 0.03), "fabric", 0.8)
    metal = M.metal(rng)
    grip = M.wood(rng) if variant == "crook" else M.solid((0.08, 0.08, 0.08), "rubber", 0.8)
    if variant == "compact":
        length, rc, rs = rng.uniform(0.22, 0.28), rng.uniform(0.025, 0.032), 0.006
    else:
        length, rc, rs = rng.uniform(0.72, 0.82), rng.uniform(0.03, 0.04), 0.005
    z_tip = 0.03
    canopy = S.lathe([(rs + 0.001, z_tip), (rc, z_tip + length * 0.45), (rc * 0.8, length * 0.72),
                      (rs + 0.002, length * 0.8)], sections=16)
    shaft = S.cylinder(rs, length - 0.005, center=(0, 0, (length - 0.005) / 2 + 0.005), sections=10)
    tip = S.frustum(0.003, rs + 0.002, z_tip, center=(0, 0, z_tip / 2), sections=10)
    zs = length * 0.5
    strap = ring([(rc * 0.8, zs), (rc * 1.08, zs), (rc * 1.08, zs + 0.025), (rc * 0.8, zs + 0.025)],
                 sections=16)
    runner = S.cylinder(rs + 0.004, 0.03, center=(0, 0, length * 0.8 + 0.02), sections=10)
    parts = [make_part("canopy", "canopy", canopy, cloth), make_part("shaft", "shaft", shaft, metal),
             make_part("tip", "tip", tip, metal), make_part("strap", "strap", strap, cloth),
             make_part("runner", "runner", runner, metal)]
    if variant == "crook":  # a J bent toward -Y, open downward: it hangs on a hook by its bend
        rr = rng.uniform(0.045, 0.055)
        stem = np.array([[0, 0, length - 0.01], [0, 0, length + 0.08]])
        bend = arc((0, -rr, length + 0.08), rr, 0.0, np.pi, n=11, u=(0, 1, 0), v=(0, 0, 1))
        path = np.vstack([stem, bend[1:], [[0, -2 * rr, length + 0.05]]])
        handle = S.tube(path, 0.011, sections=12)
    else:
        hl = 0.11 if variant == "straight" else 0.09
        handle = S.lathe([(0.011, length - 0.01), (0.015, length + 0.01), (0.016, length + hl * 0.8),
                          (0.01, length + hl)], sections=16)
    parts.append(make_part("handle", "handle", handle, grip))
    return parts



@register("clothes_rack", parts=("rail", "upright"), extra_parts=("foot", "caster", "end_cap", "wing", "brace"),
          size_range=(0.9, 1.8), density=800, variants=("plain", "rolling", "extendable"),
          placement="floor")
def clothes_rack(rng: np.random.Generator, variant: str) -> list[Part]:
    """A free-standing garment rack: a top rail (things hang below it) on two uprights, each
    standing on a foot bar across the depth, on the floor (plain) or on casters (rolling); the
    extendable one has wings sliding out of the rail's ends. Long along x."""
    steel = M.solid(M.jitter(rng, [(0.75, 0.75, 0.77), (0.1, 0.1, 0.1), (0.85, 0.85, 0.83)][int(rng.integers(3))],
                             0.02), "metal", 0.35, 0.9)
    rubber = M.solid((0.08, 0.08, 0.08), "rubber", 0.8)
    w = rng.uniform(0.85, 1.3)
    h = rng.uniform(1.45, 1.7)
    d = rng.uniform(0.4, 0.5)
    rt, ru = 0.0125, 0.0125
    z_foot = 0.085 if variant != "plain" else ru
    parts: list[Part] = []
    for k, sx in enumerate((-1, 1)):
        x = sx * w / 2
        parts.append(make_part(f"upright_{k}", "upright", S.cylinder(ru, h - z_foot, center=(x, 0, z_foot + (h - z_foot) / 2),
                                                                    sections=12), steel))
        parts.append(make_part(f"foot_{k}", "foot", S.cylinder(ru, d, center=(x, 0, z_foot), axis=(0, 1, 0),
                                                              sections=12), steel))
        for j, sy in enumerate((-1, 1)):
            y = sy * (d / 2 - 0.01)
            if variant == "plain":  # rubber caps on the foot bar's ends, on the floor
                parts.append(make_part(f"end_cap_{k}_{j}", "end_cap",
                                       S.cylinder(ru * 1.2, 0.024, center=(x, y, ru), axis=(0, 1, 0), sections=12), rubber))
            else:  # a swivel caster under each end of the foot bar
                parts.append(make_part(f"caster_{k}_{j}", "caster",
                                       S.union([S.cylinder(0.03, 0.022, center=(x, y, 0.03), axis=(1, 0, 0), sections=16),
                                                S.box((0.03, 0.03, 0.03), center=(x, y, 0.06))]), rubber))
    # the rail across the uprights' tops, and a brace low between them
    parts.append(make_part("rail", "rail", S.cylinder(rt, w + 2 * ru, center=(0, 0, h - rt), axis=(1, 0, 0), sections=12),
                           steel))
    parts.append(make_part("brace", "brace", S.cylinder(0.008, w, center=(0, 0, z_foot + 0.12), axis=(1, 0, 0),
                                                        sections=10), steel))
    if variant == "extendable":  # the wings pulled part-way out of the rail's ends
        reach = rng.uniform(0.1, 0.25)
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"wing_{k}", "wing",
                                   S.cylinder(rt * 0.8, reach + 0.05, center=(sx * (w / 2 + ru + reach / 2 - 0.025), 0, h - rt),
                                              axis=(1, 0, 0), sections=10), steel))
    return parts
