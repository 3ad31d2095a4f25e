"""Workshop things beside the bench and the pegboard: a bench vise, pliers, paint cans,
toolboxes and wall coat hooks.

Pliers lie flat like the other hand tools, handles along -X and the jaws at +X, closed (rigid). A vise stands on
a bench with its jaws across X, the moving jaw and its screw handle at the front (+Y). A toolbox's
lid lifts on a hinge along its back edge and its lift-out ``tray`` is an internal support. A coat
hook's ``plate`` is its back (-Y, against the wall) and its hooks reach out along +Y.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import open_box, ring
from ._kit import OPEN_DOOR, hinge_parts, mount, prismatic, revolute
from ._rods import rod, segments


@register("vise", parts=("jaw", "base"),
          extra_parts=("body", "jaw_plate", "screw", "handle", "anvil", "bolt", "clamp", "jaw_screw"),
          size_range=(0.18, 0.42), density=5000, variants=("bench", "swivel", "clamp_on"), placement="surface")
def vise(rng: np.random.Generator, variant: str) -> list:
    iron = Material(M.jitter(rng, [(0.15, 0.3, 0.6), (0.2, 0.35, 0.2), (0.55, 0.1, 0.1), (0.25, 0.25, 0.27)][int(rng.integers(4))],
                              0.03), 0.5, 0.4, "metal")
    steel = M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)
    jw = rng.uniform(0.1, 0.15)  # jaw width
    L = jw * 1.6
    parts = []
    zb = 0.0
    if variant == "clamp_on":  # a C-clamp under the bench edge: the vise sits on the bench, the clamp hangs behind
        zb = 0.0
        parts.append(make_part("base", "base", S.box((jw * 0.8, L * 0.6, 0.02), center=(0, -L * 0.1, 0.01)), iron))
        parts.append(make_part("clamp", "clamp", [S.box((0.03, 0.03, 0.1), center=(0, -L * 0.4 - 0.015, 0.05)),
                                                  S.cylinder(0.006, 0.05, center=(0, -L * 0.4 + 0.02, 0.03), axis=(0, 1, 0),
                                                             sections=8)], iron))
        zb = 0.02
    else:
        hb = 0.03 if variant == "bench" else 0.045
        parts.append(make_part("base", "base", S.box((jw * 1.1, L * 0.7, hb), center=(0, -L * 0.1, hb / 2), bevel=0.004), iron))
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"bolt_{k}", "bolt", S.cylinder(0.008, 0.008, center=(sx * jw * 0.45, -L * 0.3, hb + 0.004),
                                                                   sections=8), steel))
        if variant == "swivel":
            parts.append(make_part("swivel_handle", "handle", S.cylinder(0.005, 0.06, center=(jw * 0.55 + 0.03, -L * 0.1, hb * 0.5),
                                                                         axis=(1, 0, 0), sections=8), steel))
        zb = hb
    hj = jw * 0.6
    # the body (the fixed jaw and its housing) at the back, the anvil behind it
    yf = -0.01  # the fixed jaw's face
    parts.append(make_part("body", "body", S.box((jw * 0.6, L * 0.45, hj * 0.7), center=(0, yf - L * 0.225, zb + hj * 0.35),
                                                 bevel=0.004), iron))
    parts.append(make_part("jaw_0", "jaw", S.box((jw, 0.03, hj * 0.6), center=(0, yf - 0.015, zb + hj * 0.7 + hj * 0.3 - hj * 0.3),
                                                bevel=0.003), iron))
    parts.append(make_part("jaw_plate_0", "jaw_plate", S.box((jw, 0.006, hj * 0.35), center=(0, yf + 0.003, zb + hj * 0.82)), steel))
    if variant != "clamp_on":
        parts.append(make_part("anvil", "anvil", S.box((jw * 0.5, L * 0.2, 0.025), center=(0, yf - L * 0.35, zb + hj * 0.7 + 0.0125)),
                               iron))
    # the moving jaw at the front on a slide bar running back inside the body, the screw below it
    open_gap = 0.004
    yj = yf + open_gap + 0.006
    parts.append(make_part("jaw_plate_1", "jaw_plate", S.box((jw, 0.006, hj * 0.35), center=(0, yj - 0.003 + 0.0, zb + hj * 0.82)),
                           steel))
    parts.append(make_part("jaw_1", "jaw", [S.box((jw, 0.05, hj * 0.9), center=(0, yj + 0.025, zb + hj * 0.55), bevel=0.003),
                                            S.box((jw * 0.4, L * 0.4, hj * 0.35), center=(0, yj - L * 0.2, zb + hj * 0.3))], iron))
    parts.append(make_part("screw", "screw", S.cylinder(0.009, 0.05, center=(0, yj + 0.05 + 0.025, zb + hj * 0.3), axis=(0, 1, 0),
                                                        sections=10), steel))
    hx = jw * 0.7
    parts.append(make_part("handle", "handle", [S.cylinder(0.006, 2 * hx, center=(0, yj + 0.09, zb + hj * 0.3), axis=(1, 0, 0),
                                                           sections=8),
                                                S.ellipsoid((0.01, 0.01, 0.01), center=(-hx - 0.005, yj + 0.09, zb + hj * 0.3), subdivisions=1),
                                                S.ellipsoid((0.01, 0.01, 0.01), center=(hx + 0.005, yj + 0.09, zb + hj * 0.3), subdivisions=1)],
                           steel))
    # the two countersunk screws holding each hardened jaw plate on its jaw, flush with its face
    zs = zb + hj * 0.82
    for k, (yc, sy) in enumerate(((yf + 0.0055, 1), (yj - 0.0055, -1))):
        for j, sx in enumerate((-1, 1)):
            parts.append(make_part(f"jaw_screw_{2 * k + j}", "jaw_screw",
                                   S.frustum(0.0025, 0.0045, 0.001, center=(sx * jw * 0.3, yc, zs), axis=(0, sy, 0), sections=8),
                                   steel))
    travel = L * 0.3
    parts += [prismatic("jaw_1_slide", "body", "jaw_1", travel=travel),
              mount("jaw_1", "jaw_plate_1"), mount("jaw_1", "screw"), mount("jaw_1", "handle"),
              mount("jaw_1", "jaw_screw_2"), mount("jaw_1", "jaw_screw_3")]
    return parts


@register("pliers", parts=("jaw", "handle"), extra_parts=("grip", "pivot", "adjuster", "cutter"),
          size_range=(0.12, 0.28), density=5000, variants=("combination", "needle_nose", "locking"), placement="surface")
def pliers(rng: np.random.Generator, variant: str) -> list:
    steel = M.solid((0.6, 0.6, 0.62), "metal", 0.35, 0.9)
    grip = M.solid(M.jitter(rng, [(0.8, 0.1, 0.1), (0.1, 0.3, 0.7), (0.9, 0.6, 0.1), (0.1, 0.1, 0.1)][int(rng.integers(4))], 0.03)[:3],
                   "rubber", 0.8)
    L = rng.uniform(0.16, 0.22) if variant != "needle_nose" else rng.uniform(0.15, 0.2)
    lj = L * (0.25 if variant != "needle_nose" else 0.38)
    lh = L - lj
    t = 0.009
    # two halves crossing at the pivot (x = 0): half 0 carries the +Y jaw and the -Y handle, half 1 the opposite ones
    spread = 0.02 if variant != "locking" else 0.018
    parts = []
    for k, s in enumerate((1, -1)):
        z = t / 2 + (t if k == 1 else 0.0)
        tipw = 0.004 if variant == "needle_nose" else 0.008
        jaw = S.hull(np.array([[0.0, s * 0.0, z - t / 2], [0.0, s * 0.012, z - t / 2], [lj, s * 0.0, z - t / 2], [lj, s * tipw, z - t / 2],
                               [0.0, s * 0.0, z + t / 2], [0.0, s * 0.012, z + t / 2], [lj, s * 0.0, z + t / 2], [lj, s * tipw, z + t / 2]]))
        parts.append(make_part(f"jaw_{k}", "jaw", jaw, steel))
        handle = rod((0.0, -s * 0.004, z), (-lh, -s * spread, z), 0.0045, sections=8)
        parts.append(make_part(f"handle_{k}", "handle", handle, steel))
        parts.append(make_part(f"grip_{k}", "grip", rod((-lh * 0.3, -s * (0.004 + (spread - 0.004) * 0.3), z),
                                                            (-lh + 0.005, -s * (spread - 0.0003), z), 0.0075, sections=10), grip))
    parts.append(make_part("pivot", "pivot", S.cylinder(0.008, 2 * t + 0.002, center=(0, 0, t), sections=12), steel))
    if variant == "locking":
        parts.append(make_part("adjuster", "adjuster", S.cylinder(0.006, 0.02, center=(-lh - 0.008, spread, t * 1.5), axis=(1, 0, 0),
                                                                  sections=10), steel))
    if variant == "combination":
        parts.append(make_part("cutter", "cutter", S.box((0.01, 0.006, t * 2), center=(0.012, 0, t)), steel))
    return parts


@register("paint_can", parts=("body", "lid"), extra_parts=("rim", "handle", "ear", "label", "bottom_rim", "spout", "grip", "tab"),
          size_range=(0.1, 0.42), density=1300, variants=("gallon", "quart", "bucket"), placement="floor")
def paint_can(rng: np.random.Generator, variant: str) -> list[Part]:
    tin = M.solid((0.75, 0.75, 0.77), "metal", 0.35, 0.85)
    if variant == "bucket":
        r, h = rng.uniform(0.14, 0.15), rng.uniform(0.36, 0.38)
        body = M.solid(M.jitter(rng, (0.92, 0.92, 0.9), 0.02)[:3], "plastic", 0.5)
        parts = [make_part("body", "body", S.frustum(r * 0.9, r, h, center=(0, 0, 0), sections=32), body),
                 make_part("lid", "lid", S.cylinder(r + 0.006, 0.012, center=(0, 0, h + 0.006), sections=32), body),
                 # the pour spout folded down into a well of the lid, its cap flush with the lid's
                 # top (buckets stack lid on lid)
                 make_part("spout", "spout", S.cylinder(0.025, 0.008, center=(r * 0.55, 0, h + 0.008), sections=16), body)]
        hz = h * 0.85
        rim_mat = body
    else:
        r, h = (0.084, 0.19) if variant == "gallon" else (0.055, 0.12)
        r, h = r * rng.uniform(0.98, 1.02), h * rng.uniform(0.98, 1.02)
        parts = [make_part("body", "body", S.cylinder(r - 0.002, h - 0.008, center=(0, 0, 0.004 + (h - 0.008) / 2), sections=32),
                           tin),
                 make_part("bottom_rim", "bottom_rim", ring([(r - 0.004, 0.0), (r, 0.0), (r, 0.006), (r - 0.004, 0.006)]), tin),
                 make_part("rim", "rim", ring([(r - 0.01, h - 0.007), (r, h - 0.007), (r, h), (r - 0.01, h)]), tin),
                 make_part("lid", "lid", S.cylinder(r + 0.001, 0.004, center=(0, 0, h + 0.002), sections=32),
                           M.solid(M.jitter(rng, (0.7, 0.7, 0.7), 0.1)[:3], "metal", 0.4, 0.6))]
        parts.append(make_part("label", "label", ring([(r - 0.0015, h * 0.2), (r + 0.0005, h * 0.2), (r + 0.0005, h * 0.75),
                                                       (r - 0.0015, h * 0.75)]), M.paper(rng)))
        hz = h * 0.8
        rim_mat = tin
    # the bail handle between two ears on the sides, folded down round the front (cans stack)
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"ear_{k}", "ear", S.box((0.006, 0.02, 0.02), center=(sx * (r + 0.003), 0, hz)), rim_mat))
    a = np.linspace(0.0, np.pi, 9)
    rr = r + 0.008
    arc = [(rr * np.cos(t), rr * np.sin(t), hz - 0.02 * np.sin(t)) for t in a]
    parts.append(make_part("handle", "handle", segments(arc, 0.0022, sections=6), M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8)))
    # the plastic grip threaded on the bail at its middle
    mid = np.asarray(arc[4], float)
    parts.append(make_part("grip", "grip", S.cylinder(0.007, 0.07, center=tuple(mid), axis=(1, 0, 0), sections=10),
                           M.solid((0.1, 0.1, 0.1), "plastic", 0.6)))
    if variant == "bucket":  # the tamper-evident tabs round the lid's skirt
        parts += [make_part(f"tab_{k}", "tab", S.box((0.03, 0.006, 0.016), center=(np.cos(a_) * (r + 0.009), np.sin(a_) * (r + 0.009),
                                                                                   h - 0.002), R=_rz(a_ + np.pi / 2)), rim_mat)
                  for k, a_ in enumerate(np.linspace(0, 2 * np.pi, 4, endpoint=False) + np.pi / 4)]
    return parts


def _rz(a: float) -> np.ndarray:
    c, s_ = np.cos(a), np.sin(a)
    return np.array([[c, -s_, 0], [s_, c, 0], [0, 0, 1]])


@register("toolbox", parts=("body", "handle"), extra_parts=("lid", "tray", "latch", "hinge", "foot", "divider", "hasp", "rivet",
                                                            "nail"),
          size_range=(0.3, 0.62), density=500, variants=("metal", "plastic", "tote"), placement="floor")
def toolbox(rng: np.random.Generator, variant: str) -> list:
    w, d = rng.uniform(0.4, 0.56), rng.uniform(0.2, 0.26)
    shell = (Material(M.jitter(rng, [(0.75, 0.1, 0.08), (0.15, 0.3, 0.65), (0.2, 0.2, 0.22)][int(rng.integers(3))], 0.03), 0.4, 0.5,
                      "metal")
             if variant == "metal" else Material(M.jitter(rng, [(0.1, 0.1, 0.1), (0.9, 0.55, 0.1), (0.15, 0.35, 0.7)][int(rng.integers(3))],
                                                           0.03), 0.6, 0.0, "plastic") if variant == "plastic"
             else M.wood(rng))
    dark = M.solid((0.08, 0.08, 0.08), "plastic", 0.6)
    t = 0.004 if variant != "tote" else 0.012
    parts = []
    if variant == "tote":  # an open wooden tote: a centre board with the handle slot, dividers either side
        h = rng.uniform(0.16, 0.22)
        parts.append(make_part("body", "body", open_box(w, d, h, t), shell))
        hh = h + rng.uniform(0.1, 0.14)
        parts.append(make_part("divider", "divider", S.box((w - 2 * t, t, hh - t), center=(0, 0, t + (hh - t) / 2)), shell))
        parts.append(make_part("handle", "handle", S.cylinder(0.014, w - 2 * t, center=(0, 0.0, hh - 0.03), axis=(1, 0, 0),
                                                              sections=12), shell))
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"divider_{k}", "divider", S.box((t, d / 2 - 1.5 * t, h * 0.7),
                                                                    center=(sx * w / 6, d / 4, t + h * 0.35)), shell))
        # and the back half's pair, splitting it into a long bay and two short ones
        for k, sx in enumerate((-1, 1), start=2):
            parts.append(make_part(f"divider_{k}", "divider", S.box((t, d / 2 - 1.5 * t, h * 0.7),
                                                                    center=(sx * w / 4, -d / 4, t + h * 0.35)), shell))
        # the nails through each end board into the front, the back and the bottom, their heads
        # flush with the end's outer face
        nails = [(sx * (w / 2 - 0.0005), sy * (d / 2 - t / 2), z) for sx in (-1, 1) for sy in (-1, 1) for z in (h * 0.3, h * 0.75)]
        nails += [(sx * (w / 2 - 0.0005), 0.0, t / 2) for sx in (-1, 1)]
        parts += [make_part(f"nail_{k}", "nail", S.cylinder(0.003, 0.001, center=c, axis=(1, 0, 0), sections=8),
                            M.solid((0.35, 0.35, 0.37), "metal", 0.5, 0.8)) for k, c in enumerate(nails)]
        return parts
    h = rng.uniform(0.18, 0.24)
    hl = 0.045  # the lid's depth
    hb = h - hl
    zf = 0.008
    parts += [make_part(f"foot_{k}", "foot", S.box((0.04, d - 0.03, zf), center=(sx * (w / 2 - 0.04), 0, zf / 2)), dark)
              for k, sx in enumerate((-1, 1))]
    parts.append(make_part("body", "body", [s.moved((0, 0, zf)) for s in open_box(w, d, hb, t)], shell))
    # the lift-out tray resting on ledges just below the rim, its floor an internal support
    ht = 0.05
    ledge = [S.box((t * 2, d - 2 * t, 0.006), center=(sx * (w / 2 - 2 * t), 0, zf + hb - ht - 0.003)) for sx in (-1, 1)]
    parts.append(make_part("ledge", "divider", ledge, shell))
    parts.append(make_part("tray", "tray", [s.moved((0, 0, zf + hb - ht)) for s in open_box(w - 6 * t, d - 2 * t - 0.002, ht - 0.002,
                                                                                           0.003)], dark))
    zl = zf + hb
    lid = [S.box((w, d, t), center=(0, 0, zl + hl - t / 2))] + [
        S.box((w, t, hl - t), center=(0, sy * (d / 2 - t / 2), zl + (hl - t) / 2)) for sy in (-1, 1)] + [
        S.box((t, d - 2 * t, hl - t), center=(sx * (w / 2 - t / 2), 0, zl + (hl - t) / 2)) for sx in (-1, 1)]
    parts.append(make_part("lid", "lid", lid, shell))
    hw = w * 0.45
    parts.append(make_part("handle", "handle", [S.box((0.025, 0.02, 0.03), center=(sx * hw / 2, 0, zl + hl + 0.015)) for sx in (-1, 1)]
                           + [S.box((hw + 0.025, 0.028, 0.02), center=(0, 0, zl + hl + 0.04), bevel=0.006)], dark))
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"latch_{k}", "latch", S.box((0.035, 0.008, 0.04), center=(sx * w * 0.3, d / 2 + 0.004, zl),
                                                            bevel=0.002), M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9)))
    parts += hinge_parts("hinge", x=zl, y=-d / 2 - 0.005, z0=-w / 2 + 0.03, z1=w / 2 - 0.03, mat=dark, axis="x", radius=0.005,
                         length=0.04)
    # the hasp for a padlock between the latches
    steel = M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9)
    parts.append(make_part("hasp", "hasp", S.box((0.02, 0.006, 0.03), center=(0, d / 2 + 0.003, zl), bevel=0.002), steel))
    # the two rivets fixing each latch's base plate to the front, below the latch
    parts += [make_part(f"rivet_{2 * k + j}", "rivet", S.cylinder(0.0025, 0.002, center=(sx * w * 0.3 + dx, d / 2 + 0.001, zl - 0.028),
                                                                  axis=(0, 1, 0), sections=8), steel)
              for k, sx in enumerate((-1, 1)) for j, dx in enumerate((-0.011, 0.011))]
    parts += [revolute("lid_hinge", "body", "lid", axis=(1, 0, 0), origin=(0, -d / 2, zl), opens=OPEN_DOOR),
              mount("lid", "handle")]
    return parts


@register("coat_hook", parts=("hook", "plate"), extra_parts=("screw", "tip", "rail"),
          size_range=(0.05, 1.0), density=3000, variants=("single", "double", "rail"), placement="wall")
def coat_hook(rng: np.random.Generator, variant: str) -> list[Part]:
    metal = M.metal(rng) if rng.random() < 0.7 else M.solid((0.05, 0.05, 0.05), "metal", 0.5, 0.6)
    t = 0.006
    r = rng.uniform(0.004, 0.006)
    parts = []
    if variant == "rail":  # a board with a row of hooks
        n = int(rng.integers(3, 7))
        pitch = rng.uniform(0.1, 0.15)
        w, hp = n * pitch, rng.uniform(0.09, 0.12)
        parts.append(make_part("plate", "plate", S.box((w, 0.018, hp), center=(0, 0.009, hp / 2), bevel=0.003), M.wood(rng)))
        xs = [-w / 2 + pitch * (k + 0.5) for k in range(n)]
        y0, zc = 0.018, hp / 2
        for k, x in enumerate((-w / 2 + 0.03, w / 2 - 0.03)):
            parts.append(make_part(f"screw_{k}", "screw", S.cylinder(0.005, 0.002, center=(x, y0 + 0.001, zc), axis=(0, 1, 0),
                                                                     sections=8), metal))
    else:
        hp = rng.uniform(0.05, 0.07)
        wp = 0.025
        parts.append(make_part("plate", "plate", S.box((wp, t, hp), center=(0, t / 2, hp / 2), bevel=0.002), metal))
        for k, sz in enumerate((-1, 1)):
            parts.append(make_part(f"screw_{k}", "screw", S.cylinder(0.004, 0.002, center=(0, t + 0.001, hp / 2 + sz * hp * 0.3),
                                                                     axis=(0, 1, 0), sections=8), metal))
        xs, y0, zc = [0.0], t, hp * 0.35
    reach = rng.uniform(0.05, 0.08)
    for k, x in enumerate(xs):
        # out from the plate, down a little, then up to a knobbed tip: coats hang from the bottom bend
        path = [(x, y0 - 0.002, zc), (x, y0 + reach * 0.7, zc - 0.02), (x, y0 + reach, zc + 0.01)]
        parts.append(make_part(f"hook_{k}", "hook", segments(path, r), metal))
        if variant == "rail":  # each hook's own base plate screwed to the board, a screw above and below
            parts.append(make_part(f"hook_plate_{k}", "plate", S.box((0.02, 0.003, 0.05), center=(x, y0 + 0.0015, zc), bevel=0.001),
                                   metal))
            parts += [make_part(f"hook_screw_{k}_{j}", "screw", S.cylinder(0.0035, 0.0015, center=(x, y0 + 0.00375, zc + sz * 0.018),
                                                                           axis=(0, 1, 0), sections=8), metal)
                      for j, sz in enumerate((-1, 1))]
        parts.append(make_part(f"tip_{k}", "tip", S.ellipsoid((r * 1.6, r * 1.6, r * 1.6), center=(x, y0 + reach, zc + 0.01 + r),
                                                              subdivisions=1), metal))
        if variant == "double":  # the upper, shorter arm for a hat
            up = [(x, y0 - 0.002, zc + 0.012), (x, y0 + reach * 0.5, zc + 0.05)]
            parts.append(make_part(f"hook_upper_{k}", "hook", segments(up, r * 0.9), metal))
            parts.append(make_part(f"tip_upper_{k}", "tip", S.ellipsoid((r * 1.5, r * 1.5, r * 1.5),
                                                                        center=(x, y0 + reach * 0.5, zc + 0.05 + r * 0.5),
                                                                        subdivisions=1), metal))
    return parts
