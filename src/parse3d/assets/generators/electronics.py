"""Electronics: televisions, monitors, laptops, keyboards, speakers and remote controls.

Screens and speaker drivers face +Y. TVs and monitors come on feet, a pedestal or a stand and
base, or made for a wall or a mount (``wall_mount``: no stand, a VESA plate on the back). Displays are a bevelled housing (``body``) with a glass
``screen`` panel standing 1–2 mm proud of it, so the screen's front surface is the part's +Y face.

Speakers are registered with placement ``floor``: a bookshelf speaker is at home on the floor or a
shelf, a floor-standing one only on the floor.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from ...geometry.frames import rot_x, rot_z
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._detail_b import studs


def _screen_glass() -> Material:
    return Material((0.03, 0.035, 0.045, 1.0), 0.08, 0.0, "glass")


def _housing(rng) -> Material:
    c = [(0.08, 0.08, 0.09), (0.15, 0.15, 0.16), (0.75, 0.76, 0.78), (0.93, 0.93, 0.93)]
    return M.solid(M.jitter(rng, c[int(rng.integers(len(c)))], 0.01), "plastic", 0.45)


def _display(rng, w: float, h: float, depth: float, z0: float, bezel: float) -> list[Part]:
    """A housing of ``w`` x ``depth`` x ``h`` whose bottom is at ``z0`` (front face at
    y = depth / 2) with a rear bump, and its screen panel."""
    mat = _housing(rng)
    body = [S.box((w, depth, h), center=(0, 0, z0 + h / 2), bevel=min(0.004, depth / 4))]
    bump_d = depth * rng.uniform(0.4, 1.0)
    body.append(S.box((w * rng.uniform(0.4, 0.7), bump_d, h * rng.uniform(0.4, 0.6)),
                      center=(0, -depth / 2 - bump_d / 2, z0 + h * 0.45), bevel=0.004))
    screen = S.box((w - 2 * bezel, 0.002, h - 2 * bezel), center=(0, depth / 2 + 0.001, z0 + h / 2))
    parts = [make_part("body", "body", body[0], mat), make_part("back_cover", "back_cover", body[1], mat),
             make_part("screen", "screen", screen, _screen_glass())]
    # control buttons under the bottom edge at the right, and the power light in the bezel
    dark = M.solid((0.05, 0.05, 0.06), "plastic", 0.5)
    for k in range(4):
        parts.append(make_part(f"button_{k}", "button", S.box((0.012, 0.008, 0.004), center=(w / 2 - 0.04 - 0.02 * k, depth / 2 - 0.006,
                                                                                           z0 - 0.002)), dark))
    parts.append(make_part("indicator", "indicator", S.cylinder(0.002, 0.002, center=(w / 2 - bezel / 2 - 0.01, depth / 2 + 0.001,
                                                                                     z0 + bezel / 2), axis=(0, 1, 0), sections=8),
                           M.solid((0.2, 0.8, 0.3), "plastic", 0.3)))
    # the maker's logo on the bottom bezel; on the rear bump the input ports, the power inlet
    # and the four threaded VESA mounting points
    parts.append(make_part("logo", "logo", S.box((0.04, 0.001, min(0.008, bezel * 0.6)),
                                                 center=(0, depth / 2 + 0.0005, z0 + bezel / 2)),
                           M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.8)))
    bb = body[1].mesh.bounds
    yb = bb[0, 1]
    for k in range(3):
        parts.append(make_part(f"port_{k}", "port", S.box((0.016, 0.002, 0.007),
                                                          center=(bb[1, 0] - 0.03 - 0.025 * k, yb - 0.001, bb[0, 2] + 0.03)), dark))
    parts.append(make_part("power_inlet", "power_inlet", S.box((0.02, 0.002, 0.012), center=(bb[0, 0] + 0.03, yb - 0.001, bb[0, 2] + 0.03)),
                           dark))
    cx, cz, v = 0.0, (bb[0, 2] + bb[1, 2]) / 2 + 0.01, min(0.05, (bb[1, 0] - bb[0, 0]) * 0.2, (bb[1, 2] - bb[0, 2]) * 0.2)
    for k, (sx, sz) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        parts.append(make_part(f"vesa_mount_{k}", "vesa_mount", S.cylinder(0.005, 0.002, center=(cx + sx * v, yb - 0.001, cz + sz * v),
                                                                          axis=(0, 1, 0), sections=8), dark))
    return parts


def _vesa_plate(rng, parts: list[Part]) -> Part:
    """The wall plate of a screen made for a wall or a mount: a steel plate over the four VESA
    points on the back of its rear bump (``back_cover``), its back the screen's furthest back."""
    back = next(p for p in parts if p.name == "back_cover")
    pts = [p.bounds for p in parts if p.label == "vesa_mount"]
    lo, hi = np.min([b[0] for b in pts], axis=0), np.max([b[1] for b in pts], axis=0)
    t = rng.uniform(0.006, 0.012)
    yb = float(back.bounds[0][1])
    plate = S.box((hi[0] - lo[0] + 0.04, t, hi[2] - lo[2] + 0.04), center=((lo[0] + hi[0]) / 2, yb - t / 2, (lo[2] + hi[2]) / 2),
                  bevel=0.001)
    return make_part("vesa_plate", "vesa_plate", plate, M.solid((0.12, 0.12, 0.13), "metal", 0.4, 0.8))


@register("tv", parts=("screen",),
          extra_parts=("stand", "body", "back_cover", "button", "indicator", "logo", "port", "power_inlet", "vesa_mount", "pad",
                       "vesa_plate"),
          size_range=(0.7, 1.75),
          density=350, variants=("feet", "pedestal", "wall_mount"))
def tv(rng: np.random.Generator, variant: str) -> list[Part]:
    """A flat TV on two feet or a pedestal, or made for a wall or a mount (``wall_mount``: no
    stand, a VESA plate on its back)."""
    w = rng.uniform(0.72, 1.65)
    bezel = rng.uniform(0.006, 0.015)
    h = w * 9 / 16 + 2 * bezel
    depth = rng.uniform(0.025, 0.05)
    metal = M.metal(rng) if rng.random() < 0.5 else _housing(rng)
    if variant == "wall_mount":
        parts = _display(rng, w, h, depth, 0.0, bezel)
        return [*parts, _vesa_plate(rng, parts)]
    if variant == "feet":
        z0 = rng.uniform(0.04, 0.09)
        reach = rng.uniform(0.16, 0.26)
        inset = rng.uniform(0.06, 0.22) * w
        parts = _display(rng, w, h, depth, z0, bezel)
        for k, sx in enumerate((-1, 1)):
            x = sx * (w / 2 - inset)
            top = [(x + dx, dy, z0 + 0.03) for dx in (-0.02, 0.02) for dy in (-0.01, 0.01)]
            bot = [(x + dx, dy, z) for dx in (-0.02, 0.02) for dy in (-reach / 2, reach / 2)
                   for z in (0.0, 0.012)]
            parts.append(make_part(f"stand_{k}", "stand", S.hull(np.array(top + bot)), metal))
            # a felt pad under each end of the foot
            parts += studs("pad", "pad", [(x, sy * (reach / 2 - 0.015), 0.001) for sy in (-1, 1)], r=0.008, h=0.002,
                           mat=M.solid((0.1, 0.1, 0.1), "fabric", 0.9), start=2 * k)
        return parts
    z0 = rng.uniform(0.06, 0.12)
    parts = _display(rng, w, h, depth, z0, bezel)
    plate_w, plate_d, plate_t = w * rng.uniform(0.28, 0.42), rng.uniform(0.2, 0.28), rng.uniform(0.012, 0.022)
    neck_w = rng.uniform(0.06, 0.1)
    # the neck's top is buried in the housing; the plate is centred under the neck
    neck = S.box((neck_w, 0.03, z0 + 0.08 - plate_t), center=(0, -0.01, (z0 + 0.08 + plate_t) / 2))
    plate = S.box((plate_w, plate_d, plate_t), center=(0, -0.01, plate_t / 2), bevel=0.004)
    parts.append(make_part("stand", "stand", [neck, plate], metal))
    parts += studs("pad", "pad", [(sx * (plate_w / 2 - 0.02), -0.01 + sy * (plate_d / 2 - 0.02), 0.001) for sx in (-1, 1) for sy in (-1, 1)],
                   r=0.008, h=0.002, mat=M.solid((0.1, 0.1, 0.1), "fabric", 0.9))
    return parts


@register("monitor", parts=("screen",),
          extra_parts=("stand", "base", "body", "back_cover", "button", "indicator", "logo", "port", "power_inlet", "vesa_mount",
                       "hinge", "foot", "vesa_plate"),
          size_range=(0.45, 0.85),
          density=400, variants=("rect_base", "round_base", "v_base", "wall_mount"), placement="surface")
def monitor(rng: np.random.Generator, variant: str) -> list[Part]:
    """A monitor on a stand's arm and base, or made for a monitor arm, a cart's mount or a wall
    (``wall_mount``: no stand, a VESA plate on its back)."""
    w = rng.uniform(0.48, 0.8)
    bezel = rng.uniform(0.006, 0.014)
    h = w * rng.uniform(0.54, 0.62)
    depth = rng.uniform(0.015, 0.03)
    z0 = rng.uniform(0.08, 0.16)
    if variant == "wall_mount":
        parts = _display(rng, w, h, depth, 0.0, bezel)
        return [*parts, _vesa_plate(rng, parts)]
    parts = _display(rng, w, h, depth, z0, bezel)
    mat = _housing(rng) if rng.random() < 0.6 else M.metal(rng)
    t = rng.uniform(0.008, 0.016)
    yb = -depth / 2 - rng.uniform(0.03, 0.06)
    arm_w, arm_d = rng.uniform(0.035, 0.07), rng.uniform(0.02, 0.03)
    arm_top = z0 + h * 0.55
    arm = S.box((arm_w, arm_d, arm_top - t), center=(0, -depth / 2 - arm_d / 2 - 0.02, (arm_top + t) / 2),
                bevel=0.003)
    hinge = S.box((arm_w * 1.2, 0.025, 0.05), center=(0, -depth / 2 - 0.0125, arm_top - 0.04), bevel=0.003)
    if variant == "rect_base":
        base = S.box((w * rng.uniform(0.3, 0.42), rng.uniform(0.17, 0.23), t), center=(0, yb, t / 2),
                     bevel=0.003)
    elif variant == "round_base":
        r = rng.uniform(0.09, 0.13)
        base = S.frustum(r, r * 0.93, t, center=(0, yb, 0), sections=28)
    else:
        L, a = rng.uniform(0.18, 0.26), np.deg2rad(rng.uniform(20, 35))
        base = []
        v_pads = [(0.0, yb - 0.03 + 0.012)]  # the heel, then each arm's tip
        for s in (-1, 1):
            R = rot_z(s * a)
            c = np.array([0.0, yb - 0.03, t / 2]) + R @ np.array([0.0, L / 2, 0.0])
            base.append(S.box((0.03, L, t), center=c, R=R, bevel=0.003))
            tip = np.array([0.0, yb - 0.03, 0.0]) + R @ np.array([0.0, L - 0.02, 0.0])
            v_pads.append((float(tip[0]), float(tip[1])))
    # the stand's arm, the tilt hinge it carries the display on, and the base
    parts += [make_part("stand", "stand", arm, mat), make_part("hinge", "hinge", hinge, mat),
              make_part("base", "base", base, mat)]
    # the rubber pads set into the base's underside
    bb = parts[-1].bounds
    cx, cy = (bb[0, :2] + bb[1, :2]) / 2
    hx, hy = (bb[1, :2] - bb[0, :2]) / 2
    if variant == "v_base":  # under the tips of the V and its heel
        pads = v_pads
    else:
        f = 0.55 if variant == "round_base" else 0.75
        pads = [(cx + sx * hx * f, cy + sy * hy * f) for sx in (-1, 1) for sy in (-1, 1)]
    parts += studs("foot", "foot", [(x, y, 0.001) for x, y in pads], r=0.006, h=0.002, mat=M.solid((0.1, 0.1, 0.1), "rubber", 0.8))
    return parts


@register("laptop", parts=("base", "screen"), extra_parts=("keyboard", "display", "touchpad", "key"),
          size_range=(0.26, 0.42), density=900, variants=("thin", "standard", "compact"),
          placement="surface")
def laptop(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "compact":
        w, d, hb = rng.uniform(0.27, 0.3), rng.uniform(0.19, 0.21), rng.uniform(0.016, 0.022)
    elif variant == "thin":
        w, d, hb = rng.uniform(0.3, 0.36), rng.uniform(0.21, 0.245), rng.uniform(0.01, 0.015)
    else:
        w, d, hb = rng.uniform(0.33, 0.385), rng.uniform(0.23, 0.26), rng.uniform(0.018, 0.026)
    mat = M.metal(rng) if variant == "thin" else _housing(rng)
    dark = M.solid((0.1, 0.1, 0.11), "plastic", 0.6)
    base = S.box((w, d, hb), center=(0, 0, hb / 2), bevel=0.003)
    keys = S.box((w * 0.86, d * 0.42, 0.0012), center=(0, -d * 0.12, hb + 0.0006))
    pad = S.box((w * rng.uniform(0.3, 0.4), d * 0.24, 0.0008), center=(0, d * 0.3, hb + 0.0004))
    tl = rng.uniform(0.004, 0.007) if variant == "thin" else rng.uniform(0.006, 0.009)
    L = d * rng.uniform(0.92, 1.0)
    beta = np.deg2rad(rng.uniform(100, 115) - 90)  # lid leans back past vertical
    R = rot_x(beta)
    p0 = np.array([0.0, -d / 2 + tl + 0.002, hb])
    lid = S.box((w, tl, L), center=p0 + R @ np.array([0, -tl / 2, L / 2]), R=R, bevel=0.0015)
    glass = S.box((w - 0.024, 0.001, L - 0.03), center=p0 + R @ np.array([0, 0.0005, L / 2 + 0.004]), R=R)
    parts = [make_part("base", "base", base, mat), make_part("keyboard", "keyboard", keys, dark),
             make_part("touchpad", "touchpad", pad, dark), make_part("screen", "screen", lid, mat),
             make_part("display", "display", glass, _screen_glass())]
    # individual keycaps on the key bed, five rows of thirteen
    kw, kd = w * 0.86, d * 0.42
    cap = M.solid((0.16, 0.16, 0.17), "plastic", 0.5)
    for r in range(5):
        for c in range(13):
            x = -kw / 2 + kw * (c + 0.5) / 13
            y = -d * 0.12 + kd / 2 - kd * (r + 0.5) / 5
            parts.append(make_part(f"key_{13 * r + c}", "key", S.box((kw / 13 * 0.82, kd / 5 * 0.8, 0.0008),
                                                                     center=(x, y, hb + 0.0012 + 0.0004)), cap))
    return parts


@register("keyboard", parts=("body", "keys"), extra_parts=("foot", "bumper"), size_range=(0.28, 0.48), density=600,
          variants=("full", "tenkeyless", "compact"), placement="surface")
def keyboard(rng: np.random.Generator, variant: str) -> list[Part]:
    w = {"full": rng.uniform(0.43, 0.46), "tenkeyless": rng.uniform(0.35, 0.37),
         "compact": rng.uniform(0.29, 0.31)}[variant]
    d = rng.uniform(0.12, 0.15)
    hf, hb = rng.uniform(0.012, 0.018), rng.uniform(0.022, 0.032)
    b = 0.004
    pts = [(x, y, 0.0) for x in (-w / 2, w / 2) for y in (-d / 2, d / 2)]
    pts += [(sx * (w / 2 - b), sy * (d / 2 - b), hb if sy < 0 else hf) for sx in (-1, 1) for sy in (-1, 1)]
    pts += [(sx * w / 2, sy * d / 2, (hb if sy < 0 else hf) - b) for sx in (-1, 1) for sy in (-1, 1)]
    mat = _housing(rng)
    parts = [make_part("body", "body", S.hull(np.array(pts)), mat)]
    key_mat = M.solid(M.jitter(rng, (0.2, 0.2, 0.22) if rng.random() < 0.6 else (0.9, 0.9, 0.9), 0.01),
                      "plastic", 0.5)
    n_rows = 5 if variant == "compact" else 6
    margin = 0.012
    pitch = (d - 2 * margin) / n_rows
    main_w = 0.29 if variant != "compact" else w - 2 * margin
    x_main = -w / 2 + margin + main_w / 2
    rows = []
    k = 0
    for i in range(n_rows):
        y = d / 2 - margin - pitch * (i + 0.5)
        z = hf + (hb - hf) * (d / 2 - y) / d  # the top slopes up towards the back
        # the main block key by key, in groups of keycaps (the front row: modifiers and the space bar)
        widths = [1.5] * 9 if i > 0 else [1.25, 1.25, 1.25, 6.0, 1.25, 1.25, 1.25, 1.25]
        unit = main_w / sum(widths)
        x = x_main - main_w / 2
        for kwid in widths:
            parts.append(make_part(f"key_{k}", "keys", S.box((kwid * unit - 0.003, pitch * 0.78, 0.008),
                                                             center=(x + kwid * unit / 2, y, z + 0.002), bevel=0.0015),
                                   key_mat))
            x += kwid * unit
            k += 1
        blocks = []
        if variant != "compact":
            nav_x0 = x_main + main_w / 2 + 0.012
            blocks.append(S.box((0.055, pitch * 0.78, 0.008), center=(nav_x0 + 0.0275, y, z + 0.002),
                                bevel=0.0015))
            if variant == "full":
                blocks.append(S.box((0.075, pitch * 0.78, 0.008),
                                    center=(w / 2 - margin - 0.0375, y, z + 0.002), bevel=0.0015))
        rows += blocks
    if rows:  # navigation and number blocks, one part per row
        parts += [make_part(f"key_block_{i}", "keys", b, key_mat) for i, b in enumerate(rows)]
    # underneath: the two flip-out feet at the back and the rubber pads at the front, folded
    # flush into the bottom
    parts += [make_part(f"foot_{k}", "foot", S.box((0.03, 0.012, 0.002), center=(sx * (w / 2 - 0.035), -d / 2 + 0.015, 0.001)),
                        key_mat) for k, sx in enumerate((-1, 1))]
    parts += studs("bumper", "bumper", [(sx * (w / 2 - 0.03), d / 2 - 0.012, 0.001) for sx in (-1, 1)], r=0.005, h=0.002,
                   mat=M.solid((0.1, 0.1, 0.1), "rubber", 0.8))
    return parts


def _driver(k: int, r: float, x: float, z: float, y: float, tweeter: bool) -> Part:
    """A driver of radius ``r`` on the front face (y) of a cabinet: its cone and surround (the
    dust cap is a part of its own)."""
    dark = M.solid((0.06, 0.06, 0.07), "plastic", 0.7)
    rim = S.cylinder(r, 0.006, center=(x, y + 0.003, z), axis=(0, 1, 0), sections=20)
    return make_part(f"driver_{k}", "driver", rim, dark)


@register("speaker", parts=("body",), extra_parts=("driver", "plinth", "dust_cap", "port", "terminal", "badge", "foot", "screw",
                                                    "terminal_plate"),
          size_range=(0.2, 1.2),
          density=500, variants=("bookshelf", "floor_standing"))
def speaker(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.wood(rng) if rng.random() < 0.5 else _housing(rng)
    if variant == "bookshelf":
        w, d, h = rng.uniform(0.15, 0.22), rng.uniform(0.18, 0.27), rng.uniform(0.24, 0.36)
        z0 = 0.0
    else:
        w, d, h = rng.uniform(0.18, 0.26), rng.uniform(0.24, 0.34), rng.uniform(0.85, 1.1)
        z0 = rng.uniform(0.02, 0.035)
    parts = [make_part("body", "body", S.box((w, d, h - z0), center=(0, 0, z0 + (h - z0) / 2),
                                              bevel=0.005), mat)]
    if z0 > 0:
        plinth = S.box((w + 0.04, d + 0.04, z0), center=(0, 0, z0 / 2), bevel=0.004)
        parts.append(make_part("plinth", "plinth", plinth, M.solid((0.1, 0.1, 0.1), "plastic")))
    y = d / 2
    r_tw = w * 0.12
    z_tw = h - max(0.05, w * 0.3)
    parts.append(_driver(0, r_tw, 0.0, z_tw, y, tweeter=True))
    r_wf = w * rng.uniform(0.33, 0.4)
    n_wf = 1 if variant == "bookshelf" else int(rng.integers(2, 4))
    # every woofer fits on the baffle above the cabinet's bottom edge
    r_wf = min(r_wf, ((z_tw - r_tw - 0.02 - z0 - 0.03) / n_wf - 0.02) / 2)
    z = z_tw - r_tw - 0.02 - r_wf
    for k in range(n_wf):
        parts.append(_driver(k + 1, r_wf, 0.0, z, y, tweeter=False))
        z -= 2 * r_wf + 0.02
    # each driver's dust cap, the maker's badge; the bass reflex port and binding posts at the back
    dark = M.solid((0.06, 0.06, 0.07), "plastic", 0.7)
    for p in [q for q in parts if q.label == "driver"]:
        c = p.mesh.bounds.mean(axis=0)
        rr = (p.mesh.bounds[1, 0] - p.mesh.bounds[0, 0]) / 2
        cap_r = rr * (0.6 if p.name == "driver_0" else 0.32)
        parts.append(make_part(p.name.replace("driver", "dust_cap"), "dust_cap",
                               S.ellipsoid((cap_r, cap_r * 0.5, cap_r), center=(c[0], y + 0.006, c[2]), subdivisions=1),
                               M.solid((0.15, 0.15, 0.16), "plastic", 0.5)))
    # the four screws through each woofer's frame into the baffle
    steel = M.solid((0.25, 0.25, 0.27), "metal", 0.4, 0.7)
    n_screw = 0
    for p in [q for q in parts if q.label == "driver" and q.name != "driver_0"]:
        c = p.mesh.bounds.mean(axis=0)
        rr = (p.mesh.bounds[1, 0] - p.mesh.bounds[0, 0]) / 2 * 0.88
        for a in np.pi / 4 + np.pi / 2 * np.arange(4):
            parts.append(make_part(f"screw_{n_screw}", "screw", S.cylinder(0.003, 0.002, center=(c[0] + rr * np.cos(a), y + 0.007,
                                                                                                c[2] + rr * np.sin(a)),
                                                                          axis=(0, 1, 0), sections=8), steel))
            n_screw += 1
    # the plate at the back carrying the binding posts
    parts.append(make_part("terminal_plate", "terminal_plate", S.box((0.06, 0.003, 0.04), center=(0, -d / 2 - 0.0015, z0 + 0.08)), dark))
    parts.append(make_part("port", "port", S.cylinder(0.025, 0.004, center=(0, -d / 2 - 0.002, z0 + (h - z0) * 0.6),
                                                      axis=(0, 1, 0), sections=16), dark))
    parts.append(make_part("badge", "badge", S.box((0.03, 0.002, 0.008), center=(0, y + 0.001, z0 + 0.02)),
                           M.solid((0.8, 0.8, 0.82), "metal", 0.3, 0.9)))
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"terminal_{k}", "terminal", S.cylinder(0.006, 0.015, center=(sx * 0.015, -d / 2 - 0.0075, z0 + 0.08),
                                                                       axis=(0, 1, 0), sections=10),
                               M.solid((0.7, 0.1, 0.1) if k else (0.1, 0.1, 0.1), "metal", 0.3, 0.6)))
    if variant == "bookshelf":
        for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"foot_{k}", "foot", S.cylinder(0.008, 0.003, center=(sx * (w / 2 - 0.015), sy * (d / 2 - 0.015), 0.0015),
                                                                   sections=8), M.solid((0.1, 0.1, 0.1), "rubber", 0.9)))
    return parts


def _rounded_slab(length: float, width: float, height: float, r: float, b: float) -> S.Shape:
    """A slab with rounded corners (radius ``r`` in plan) and chamfered top and bottom edges
    (``b``), long axis along y, bottom on z = 0."""
    a = np.linspace(0, np.pi / 2, 5)
    corners = []
    for sx, sy, a0 in ((1, 1, 0), (-1, 1, np.pi / 2), (-1, -1, np.pi), (1, -1, 1.5 * np.pi)):
        c = (sx * (width / 2 - r), sy * (length / 2 - r))
        corners.append(np.c_[c[0] + r * np.cos(a + a0), c[1] + r * np.sin(a + a0)])
    ring = np.concatenate(corners)
    shrink = np.c_[ring[:, 0] * (1 - 2 * b / width), ring[:, 1] * (1 - 2 * b / length)]
    pts = [np.c_[shrink, np.zeros(len(ring))], np.c_[ring, np.full(len(ring), b)],
           np.c_[ring, np.full(len(ring), height - b)], np.c_[shrink, np.full(len(ring), height)]]
    return S.hull(np.concatenate(pts))


@register("remote_control", parts=("body",), extra_parts=("button", "ir_window", "battery_cover"), size_range=(0.1, 0.25),
          density=700, variants=("tv", "slim"), placement="surface")
def remote_control(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "tv":
        L, W, H = rng.uniform(0.17, 0.22), rng.uniform(0.045, 0.055), rng.uniform(0.018, 0.024)
    else:
        L, W, H = rng.uniform(0.12, 0.16), rng.uniform(0.034, 0.04), rng.uniform(0.011, 0.015)
    body = _rounded_slab(L, W, H, W * 0.3, H * 0.25)
    dark = rng.random() < 0.7
    parts = [make_part("body", "body", body, M.solid((0.1, 0.1, 0.11) if dark else (0.85, 0.85, 0.86),
                                                     "plastic", 0.5))]
    btn = M.solid((0.35, 0.35, 0.37) if dark else (0.2, 0.2, 0.22), "plastic", 0.5)

    def button(r, x, y):
        return S.cylinder(r, 0.0025, center=(x, y, H + 0.00075), sections=10)

    # the end that points at the device is +Y: power button and d-pad sit towards it
    power = button(0.0045, -W * 0.25, L / 2 - 0.015)
    parts.append(make_part("power_button", "button", power, M.solid((0.8, 0.15, 0.12), "plastic", 0.5)))
    dpad_y = L / 2 - (0.05 if variant == "tv" else 0.035)
    keys = [button(W * 0.28, 0.0, dpad_y)]
    keys += [button(0.0038, x, dpad_y - W * 0.45) for x in (-W * 0.25, W * 0.25)]
    if variant == "tv":
        for i in range(4):
            for j in range(3):
                keys.append(button(0.0038, (j - 1) * W * 0.28, dpad_y - W * 0.95 - i * 0.014))
    if variant == "tv":  # the four colour keys between the power button and the d-pad
        parts += [make_part(f"colour_button_{j}", "button", S.box((W * 0.14, 0.003, 0.0025), center=((j - 1.5) * W * 0.2, L / 2 - 0.026,
                                                                                                   H + 0.00075)),
                            M.solid(c, "plastic", 0.5))
                  for j, c in enumerate(((0.8, 0.15, 0.12), (0.15, 0.6, 0.2), (0.9, 0.8, 0.15), (0.15, 0.3, 0.8)))]
    else:  # home, back, play and mute under the d-pad's pair
        keys += [button(0.0038, x, dpad_y - W * 0.45 - 0.012 * (i + 1)) for i in range(2) for x in (-W * 0.25, W * 0.25)]
    parts += [make_part(f"button_{k}", "button", key, btn) for k, key in enumerate(keys)]
    # the infrared window at the pointing end and the battery cover in the back, both flush
    parts.append(make_part("ir_window", "ir_window", S.box((W * 0.3, 0.003, H * 0.3), center=(0, L / 2 - 0.0025, H * 0.5)),
                           M.solid((0.15, 0.02, 0.02), "glass", 0.2)))
    parts.append(make_part("battery_cover", "battery_cover", S.box((W * 0.7, L * 0.35, 0.0008), center=(0, -L * 0.25, 0.0004)),
                           parts[0].material))
    return parts
