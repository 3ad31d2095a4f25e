"""The music room: drum kits, music and microphone stands, keyboard stands, violins, amplifiers
and sheet music.

Instruments stand upright in the canonical frame (a violin's strings face +Y, its scroll is at
the top) so they can lean against a wall or stand on a stand; a drum kit faces its audience at +Y
with the throne at the back.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._dF_slots import slots
from ._household import ring
from ._kit import feet4, rot


def _tripod(prefix: str, x: float, y: float, *, top: float, spread: float, r: float, mat: Material,
            phase: float = 0.0) -> list[Part]:
    """Three splayed legs meeting a post at height ``top`` (one part per leg)."""
    out = []
    for k in range(3):
        a = phase + 2 * np.pi * k / 3
        foot = (x + spread * np.cos(a), y + spread * np.sin(a), r)
        out.append(make_part(f"{prefix}_{k}", "leg", S.tube([(x, y, top), foot], r, sections=8), mat))
    return out


def _tripod_fittings(x: float, y: float, *, top: float, spread: float, r: float, mat: Material,
                     phase: float = 0.0) -> list[Part]:
    """The rubber ``foot`` tip on each leg of :func:`_tripod` and the ``hub`` collar the legs are
    hinged to at its top."""
    rubber = M.solid((0.03, 0.03, 0.03), "rubber", 0.8)
    out = [make_part(f"foot_{k}", "foot", S.cylinder(r * 1.5, r * 2, center=(x + spread * np.cos(a), y + spread * np.sin(a), r),
                                                     sections=8), rubber)
           for k, a in enumerate(phase + 2 * np.pi * np.arange(3) / 3)]
    out.append(make_part("hub", "hub", S.cylinder(r * 2.6, 0.05, center=(x, y, top), sections=12), mat))
    return out


def _drum(r: float, h: float, center, *, axis=(0, 0, 1)) -> S.Shape:
    return S.cylinder(r, h, center=center, axis=axis, sections=24)


def _drum_hardware(name: str, r: float, h: float, center, mat: Material, *, n_lugs: int, lying: bool = False) -> list[Part]:
    """A drum's two hoops (one each end) and its tension lugs round the shell: a standing drum's
    hoops clamp outside the shell, flush with its ends (each hoop with the head inside it, one
    collision piece); a lying bass drum's are rings flush with its shell, so the drum still rests
    on its shell, and lugs that would reach the floor are left out."""
    c = np.asarray(center, float)
    out = []
    T = np.eye(4)
    T[:3, 3] = c
    T[:3, :3] = rot((1, 0, 0), np.pi / 2)
    for k, e in enumerate((-1, 1)):
        z = e * (h / 2 - 0.008)
        if lying:
            hoop = S.transformed(ring([(r - 0.01, z - 0.008), (r, z - 0.008), (r, z + 0.008), (r - 0.01, z + 0.008)], sections=16), T)
        else:
            hoop = S.cylinder(r + 0.008, 0.016, center=c + (0, 0, z), sections=24)
        out.append(make_part(f"hoop_{name}_{k}", "hoop", hoop, mat))
    rl = r + 0.006
    lh = min(0.05, h * 0.35)
    for a in np.linspace(0, 2 * np.pi, n_lugs, endpoint=False) + np.pi / n_lugs:
        if lying:
            if c[2] + np.sin(a) * rl - 0.01 < 0.002:
                continue
            lug = S.box((0.012, lh, 0.014), center=(c[0] + np.cos(a) * rl, c[1], c[2] + np.sin(a) * rl), R=rot((0, 1, 0), -a))
        else:
            lug = S.box((0.012, 0.014, lh), center=(c[0] + np.cos(a) * rl, c[1] + np.sin(a) * rl, c[2]), R=rot((0, 0, 1), a))
        out.append(make_part(f"lug_{name}_{len(out) - 2}", "lug", lug, mat))
    return out


@register("drum_kit", parts=("bass_drum", "snare_drum", "cymbal", "seat"),
          extra_parts=("tom", "stand", "leg", "pedal", "hoop", "lug", "spur", "beater"), size_range=(1.0, 2.0), density=150,
          variants=("rock", "compact", "jazz"))
def drum_kit(rng: np.random.Generator, variant: str) -> list[Part]:
    shell = Material(M.jitter(rng, [(0.7, 0.1, 0.1), (0.1, 0.1, 0.12), (0.15, 0.25, 0.6),
                                    (0.85, 0.85, 0.85)][int(rng.integers(4))], 0.03), 0.3, 0.2, "wood")
    chrome = M.solid((0.8, 0.8, 0.82), "metal", 0.25, 0.9)
    brass = M.solid((0.78, 0.62, 0.3), "metal", 0.3, 0.9)
    k = {"rock": 1.0, "compact": 0.85, "jazz": 0.9}[variant]
    rb = {"rock": rng.uniform(0.25, 0.28), "compact": rng.uniform(0.2, 0.23), "jazz": rng.uniform(0.22, 0.25)}[variant]
    lb = rng.uniform(0.35, 0.45) * k
    parts = [make_part("bass_drum", "bass_drum", _drum(rb, lb, (0, 0.15, rb),
                                                       axis=(0, 1, 0)), shell),
             make_part("pedal", "pedal", S.box((0.09, 0.28, 0.04), center=(0, -0.2, 0.02), bevel=0.005), chrome)]
    parts += _drum_hardware("bass", rb, lb, (0, 0.15, rb), shell, n_lugs=10, lying=True)
    # the two spurs bracing the bass drum, and the pedal's beater resting against its head
    parts += [make_part(f"spur_{j}", "spur", S.tube([(sx * rb * 0.95, 0.15 - lb / 2 + 0.08, rb * 0.7), (sx * (rb + 0.06), -0.05, 0.008)],
                                                     0.007, sections=8), chrome) for j, sx in enumerate((-1, 1))]
    parts.append(make_part("beater", "beater", [S.tube([(0, -0.12, 0.04), (0, 0.15 - lb / 2 - 0.03, rb * 0.75)], 0.004, sections=6),
                                                S.cylinder(0.025, 0.03, center=(0, 0.15 - lb / 2 - 0.017, rb * 0.75), axis=(0, 1, 0),
                                                           sections=10)], chrome))
    zs = rng.uniform(0.58, 0.66)
    xs = -0.32 * k
    parts.append(make_part("snare_drum", "snare_drum", _drum(0.178, 0.14, (xs, -0.2, zs + 0.07)),
                           M.solid((0.75, 0.75, 0.76), "metal", 0.3, 0.8)))
    parts += _drum_hardware("snare", 0.178, 0.14, (xs, -0.2, zs + 0.07), chrome, n_lugs=8)
    parts.append(make_part("stand_0", "stand", S.cylinder(0.011, zs - 0.02, center=(xs, -0.2, (zs - 0.02) / 2 + 0.01),
                                                          sections=10), chrome))
    parts += _tripod("leg_snare", xs, -0.2, top=0.3, spread=0.22, r=0.008, mat=chrome)
    n_toms = {"rock": 2, "compact": 1, "jazz": 1}[variant]
    for t in range(n_toms):
        x = (t - (n_toms - 1) / 2) * 0.3
        parts.append(make_part(f"tom_{t}", "tom", _drum(0.14 - 0.01 * t, 0.18, (x, 0.1, 2 * rb + 0.12),
                                                         axis=(0, 0, 1)), shell))
        parts += _drum_hardware(f"tom_{t}", 0.14 - 0.01 * t, 0.18, (x, 0.1, 2 * rb + 0.12), chrome, n_lugs=6)
    parts.append(make_part("stand_1", "stand", S.cylinder(0.012, 0.14, center=(0, 0.1, 2 * rb + 0.05), sections=10),
                           chrome))
    # floor tom on three legs
    rf = 0.19 * k
    fx = 0.45 * k
    parts.append(make_part("tom_floor", "tom", _drum(rf, 0.32 * k, (fx, -0.15, 0.28 + 0.16 * k)), shell))
    parts += _drum_hardware("floor_tom", rf, 0.32 * k, (fx, -0.15, 0.28 + 0.16 * k), chrome, n_lugs=8)
    for i, (dx, dy) in enumerate([(rf + 0.01, 0.0), (-0.5 * rf, 0.87 * rf + 0.01), (-0.5 * rf, -0.87 * rf - 0.01)]):
        parts.append(make_part(f"leg_floor_tom_{i}", "leg",
                               S.tube([(fx + dx, -0.15 + dy, 0.55), (fx + dx * 1.25, -0.15 + dy * 1.25, 0.008)],
                                      0.007, sections=8), chrome))
    # hi-hat and crash
    hx, hz = -0.62 * k, rng.uniform(0.85, 0.95)
    parts.append(make_part("stand_2", "stand", S.cylinder(0.011, hz, center=(hx, -0.05, hz / 2), sections=10), chrome))
    parts += _tripod("leg_hihat", hx, -0.05, top=0.3, spread=0.2, r=0.008, mat=chrome, phase=0.5)
    parts.append(make_part("cymbal_0", "cymbal", S.cylinder(0.178, 0.006, center=(hx, -0.05, hz + 0.005),
                                                             sections=24), brass))
    parts.append(make_part("cymbal_1", "cymbal", S.cylinder(0.178, 0.006, center=(hx, -0.05, hz + 0.035),
                                                             sections=24), brass))
    if variant != "compact":
        cx, cz = 0.55 * k, rng.uniform(1.2, 1.4)
        parts.append(make_part("stand_3", "stand", S.cylinder(0.011, cz, center=(cx, 0.35, cz / 2), sections=10), chrome))
        parts += _tripod("leg_crash", cx, 0.35, top=0.35, spread=0.25, r=0.008, mat=chrome, phase=0.2)
        parts.append(make_part("cymbal_2", "cymbal", S.cylinder(0.2 + 0.02 * (variant == "jazz"), 0.006,
                                                                 center=(cx, 0.35, cz + 0.005), sections=24), brass))
    # throne
    zt = rng.uniform(0.48, 0.55)
    parts.append(make_part("seat", "seat", S.cylinder(0.17, 0.08, center=(0, -0.62, zt + 0.04), sections=20),
                           M.solid((0.08, 0.08, 0.09), "leather", 0.6)))
    parts.append(make_part("stand_4", "stand", S.cylinder(0.015, zt, center=(0, -0.62, zt / 2), sections=10), chrome))
    parts += _tripod("leg_throne", 0.0, -0.62, top=0.25, spread=0.24, r=0.01, mat=chrome, phase=np.pi / 2)
    return parts


@register("music_stand", parts=("desk", "post"), extra_parts=("leg", "ledge", "knob", "base", "page_clip", "collar", "foot", "hub", "bracket"),
          size_range=(0.9, 1.5), density=700, variants=("folding", "orchestral", "wooden"))
def music_stand(rng: np.random.Generator, variant: str) -> list[Part]:
    h = rng.uniform(1.05, 1.35)
    w, dh = rng.uniform(0.46, 0.55), rng.uniform(0.3, 0.36)
    metal = M.solid((0.08, 0.08, 0.09), "metal", 0.5, 0.6)
    desk_mat = M.wood(rng) if variant == "wooden" else metal
    tilt = np.deg2rad(rng.uniform(15, 25))
    # the desk leans back (its top away from the player in front, +y), the ledge along its
    # lower front edge, where sheets stand leaning on it
    R = rot((1, 0, 0), tilt)
    zc = h - dh / 2 * np.cos(tilt)
    parts = [make_part("desk", "desk", S.box((w, 0.006 if variant != "wooden" else 0.012, dh), center=(0, 0, zc), R=R),
                       desk_mat)]
    lz = zc - dh / 2 * np.cos(tilt)
    ly = dh / 2 * np.sin(tilt)
    parts.append(make_part("ledge", "ledge", S.box((w, 0.06, 0.012), center=(0, ly + 0.025, lz + 0.006)), desk_mat))
    post_top = zc - 0.05
    if variant == "wooden":
        parts.append(make_part("base", "base", S.cylinder(0.16, 0.03, center=(0, -0.05, 0.015), sections=24), desk_mat))
        parts.append(make_part("post", "post", S.cylinder(0.018, post_top - 0.03, center=(0, -0.05, (post_top + 0.03) / 2),
                                                          sections=12), desk_mat))
    else:
        parts.append(make_part("post", "post", S.cylinder(0.011, post_top - 0.2, center=(0, -0.05, (post_top + 0.2) / 2),
                                                          sections=10), metal))
        parts += _tripod("leg", 0.0, -0.05, top=0.32, spread=0.28 if variant == "orchestral" else 0.24, r=0.007,
                         mat=metal, phase=np.pi / 2)
        parts += _tripod_fittings(0.0, -0.05, top=0.32, spread=0.28 if variant == "orchestral" else 0.24, r=0.007,
                                  mat=metal, phase=np.pi / 2)
    parts.append(make_part("knob", "knob", S.cylinder(0.012, 0.025, center=(0.015, -0.05, h * 0.6), axis=(1, 0, 0),
                                                      sections=10), metal))
    # the height clamp's collar the knob screws through, and a spring page clip at each upper
    # corner of the desk
    parts.append(make_part("collar", "collar", S.cylinder(0.02, 0.04, center=(0, -0.05, h * 0.6), sections=12), metal))
    for k, sx in enumerate((-1, 1)):
        c = np.array([sx * (w / 2 - 0.04), 0.0, zc]) + R @ np.array([0.0, 0.006, dh / 2 - 0.03])
        parts.append(make_part(f"page_clip_{k}", "page_clip", S.box((0.012, 0.004, 0.05), center=c, R=R), metal))
    # the tilt bracket joining the post's head to the back of the desk, and the clutch knob that
    # locks the desk's angle
    # it reaches the desk's back face at its own top edge, never through to the front where
    # sheets lean
    half = (0.006 if variant != "wooden" else 0.012) / 2
    yb0, yb1 = -0.05 - 0.02, (zc - post_top - 0.03) * np.tan(tilt) - half / np.cos(tilt)
    parts.append(make_part("bracket", "bracket", S.box((0.05, yb1 - yb0, 0.06), center=(0, (yb0 + yb1) / 2, post_top)), metal))
    parts.append(make_part("knob_1", "knob", S.cylinder(0.014, 0.02, center=(0.025 + 0.01, -0.03, post_top), axis=(1, 0, 0),
                                                        sections=10), metal))
    if variant == "wooden":  # the turned collar where the post is set into the base
        parts.append(make_part("collar_1", "collar", ring([(0.017, 0.03), (0.03, 0.03), (0.022, 0.05), (0.017, 0.05)],
                                                                 sections=16).moved((0, -0.05, 0)), desk_mat))
    return parts


@register("violin", parts=("body", "neck", "string"),
          extra_parts=("fingerboard", "scroll", "peg", "bridge", "tailpiece", "chin_rest"),
          size_range=(0.52, 0.75), density=400, variants=("violin", "viola"), placement="floor")
def violin(rng: np.random.Generator, variant: str) -> list[Part]:
    s = 1.0 if variant == "violin" else rng.uniform(1.1, 1.16)
    wood = Material(M.jitter(rng, (0.55, 0.25, 0.08), 0.04), 0.25, 0.0, "wood")
    ebony = M.solid((0.05, 0.04, 0.04), "wood", 0.4)
    L = 0.356 * s
    lb, ub, th = 0.105 * s, 0.085 * s, 0.021 * s
    body = S.union([S.ellipsoid((lb, th, L * 0.3), center=(0, 0, L * 0.3), subdivisions=2),
                    S.ellipsoid((ub, th, L * 0.24), center=(0, 0, L * 0.76), subdivisions=2),
                    S.box((0.11 * s, 2 * th * 0.85, L * 0.3), center=(0, 0, L * 0.52))])
    parts = [make_part("body", "body", body, wood)]
    nl = 0.13 * s
    parts.append(make_part("neck", "neck", S.box((0.024, 0.022, nl), center=(0, 0, L + nl / 2 - 0.004)), wood))
    parts.append(make_part("fingerboard", "fingerboard",
                           S.box((0.034, 0.007, 0.27 * s), center=(0, th * 0.55 + 0.008, L + nl - 0.135 * s)), ebony))
    ztop = L + nl
    parts.append(make_part("pegbox", "scroll", S.box((0.022, 0.03, 0.07), center=(0, -0.003, ztop + 0.035)), wood))
    parts.append(make_part("scroll", "scroll", S.ellipsoid((0.014, 0.02, 0.022), center=(0, -0.003, ztop + 0.09)),
                           wood))
    for k in range(4):
        side = -1 if k % 2 == 0 else 1
        z = ztop + 0.015 + 0.015 * k
        parts.append(make_part(f"peg_{k}", "peg", S.cylinder(0.0045, 0.05, center=(side * 0.02, -0.003, z),
                                                             axis=(1, 0, 0), sections=8), ebony))
    yb = th + 0.012
    parts.append(make_part("bridge", "bridge", S.box((0.042, 0.004, 0.03), center=(0, th * 0.7, L * 0.42)),
                           M.solid((0.85, 0.72, 0.5), "wood")))
    parts.append(make_part("tailpiece", "tailpiece",
                           S.hull([[-0.02, th * 0.8, 0.04], [0.02, th * 0.8, 0.04], [-0.008, th * 0.8, 0.15 * s],
                                   [0.008, th * 0.8, 0.15 * s], [-0.02, th * 1.1, 0.04], [0.02, th * 1.1, 0.04],
                                   [-0.008, th * 1.1, 0.15 * s], [0.008, th * 1.1, 0.15 * s]]), ebony))
    for k in range(4):
        x = (k - 1.5) * 0.006
        parts.append(make_part(f"string_{k}", "string",
                               S.cylinder(0.0009, ztop - 0.15 * s, center=(x, yb, (ztop + 0.15 * s) / 2), sections=6),
                               M.solid((0.85, 0.85, 0.8), "metal", 0.3, 0.9)))
    parts.append(make_part("chin_rest", "chin_rest", S.ellipsoid((0.035, 0.012, 0.025), center=(-0.045, th * 0.8, 0.035)),
                           ebony))
    return parts


@register("amplifier", parts=("cabinet", "grille"), extra_parts=("knob", "handle", "control_panel", "foot", "head", "jack", "switch",
                                                                 "light", "vent", "power_inlet"),
          size_range=(0.3, 1.4), density=350, variants=("combo", "stack", "practice"))
def amplifier(rng: np.random.Generator, variant: str) -> list[Part]:
    tolex = M.solid(M.jitter(rng, [(0.08, 0.08, 0.08), (0.85, 0.8, 0.7), (0.5, 0.1, 0.1)][int(rng.integers(3))], 0.02),
                    "leather", 0.7)
    grill = M.solid(M.jitter(rng, (0.25, 0.24, 0.22), 0.03), "fabric", 0.9)
    chrome = M.solid((0.75, 0.75, 0.77), "metal", 0.3, 0.9)
    if variant == "practice":
        w, d, h = rng.uniform(0.3, 0.38), rng.uniform(0.17, 0.22), rng.uniform(0.3, 0.36)
    elif variant == "combo":
        w, d, h = rng.uniform(0.5, 0.65), rng.uniform(0.24, 0.28), rng.uniform(0.42, 0.52)
    else:
        w, d, h = rng.uniform(0.7, 0.78), rng.uniform(0.32, 0.36), rng.uniform(0.7, 0.78)
    fh = 0.015
    parts = feet4("foot", w=w, d=d, r=0.02, h=fh, mat=M.solid((0.05, 0.05, 0.05), "plastic"), inset=0.02)
    parts.append(make_part("cabinet", "cabinet", S.box((w, d, h), center=(0, 0, fh + h / 2), bevel=0.01), tolex))
    gz1 = fh + h * (0.78 if variant != "stack" else 0.95)
    parts.append(make_part("grille", "grille", S.box((w - 0.05, 0.006, gz1 - fh - 0.03),
                                                     center=(0, d / 2 + 0.002, (gz1 + fh + 0.03) / 2 - 0.01)), grill))
    if variant == "stack":
        hw, hd, hh = w, d * 0.8, rng.uniform(0.22, 0.27)
        zt = fh + h + hh
        parts.append(make_part("head", "head", S.box((hw, hd, hh), center=(0, 0, fh + h + hh / 2), bevel=0.008), tolex))
        zp, yp = fh + h + hh / 2, hd / 2
    else:
        zt = fh + h
        zp, yp = fh + h * 0.88, d / 2
    parts.append(make_part("control_panel", "control_panel",
                           S.box((w - 0.06, 0.004, 0.05), center=(0, yp + 0.002, zp)), chrome))
    n = int(rng.integers(4, 8))
    for k in range(n):
        x = -w / 2 + 0.06 + (w - 0.12) * k / max(n - 1, 1)
        parts.append(make_part(f"knob_{k}", "knob", S.cylinder(0.01, 0.02, center=(x, yp + 0.012, zp), axis=(0, 1, 0),
                                                               sections=10), M.solid((0.05, 0.05, 0.05), "plastic")))
    # beside the knobs: the two input jacks at the left end, the power switch and its jewel pilot
    # light at the right
    for k, x in enumerate((-w / 2 + 0.015, -w / 2 + 0.035)):
        parts.append(make_part(f"jack_{k}", "jack", S.cylinder(0.006, 0.008, center=(x, yp + 0.008, zp), axis=(0, 1, 0), sections=10),
                               chrome))
    parts.append(make_part("switch", "switch", S.box((0.012, 0.012, 0.02), center=(w / 2 - 0.04, yp + 0.01, zp)),
                           M.solid((0.05, 0.05, 0.05), "plastic")))
    parts.append(make_part("light", "light", S.cylinder(0.006, 0.008, center=(w / 2 - 0.018, yp + 0.008, zp), axis=(0, 1, 0),
                                                        sections=10), M.solid((0.8, 0.1, 0.1), "glass", 0.1)))
    # on the back: the vent slots over the valves or the power stage, and the mains inlet below them
    yb = -(hd if variant == "stack" else d) / 2 - 0.001
    zv = zp if variant == "stack" else fh + h * 0.8
    parts += slots("vent", "vent", n=4, x0=-w * 0.3, x1=w * 0.3, z0=zv - 0.04, z1=zv + 0.04, y=yb, thick=0.002,
                   mat=M.solid((0.05, 0.05, 0.05), "plastic"))
    parts.append(make_part("power_inlet", "power_inlet", S.box((0.028, 0.003, 0.022), center=(w * 0.35, yb - 0.0005, zv - 0.06)),
                           M.solid((0.05, 0.05, 0.05), "plastic")))
    hl = min(0.25, w * 0.4)
    parts.append(make_part("handle", "handle", S.tube([(-hl / 2, 0, zt - 0.002), (-hl / 2, 0, zt + 0.02),
                                                       (hl / 2, 0, zt + 0.02), (hl / 2, 0, zt - 0.002)], 0.008), tolex))
    return parts


@register("keyboard_stand", parts=("arm", "leg"), extra_parts=("foot", "knob", "rail", "end_cap", "bolt"), size_range=(0.6, 1.2),
          density=700, variants=("x_frame", "table", "z_frame"))
def keyboard_stand(rng: np.random.Generator, variant: str) -> list[Part]:
    w, h = rng.uniform(0.7, 1.0), rng.uniform(0.62, 0.9)
    d = rng.uniform(0.36, 0.45)
    steel = M.solid((0.08, 0.08, 0.09), "metal", 0.5, 0.6)
    rubber = M.solid((0.03, 0.03, 0.03), "plastic", 0.8)
    r = 0.014
    parts = []
    if variant == "x_frame":
        for i, y in enumerate((-0.04, 0.04)):
            parts.append(make_part(f"leg_{2 * i}", "leg", S.tube([(-w / 2 + r, y, r), (w / 2 - r, y, h - 0.04)], r), steel))
            parts.append(make_part(f"leg_{2 * i + 1}", "leg", S.tube([(w / 2 - r, y, r), (-w / 2 + r, y, h - 0.04)], r),
                                   steel))
        parts.append(make_part("knob", "knob", S.cylinder(0.025, 0.12, center=(0, 0, h / 2 - 0.02), axis=(0, 1, 0),
                                                          sections=12), rubber))
        foot_x = (-w / 2 + r, w / 2 - r)
        for i, x in enumerate(foot_x):
            parts.append(make_part(f"foot_{i}", "foot", S.box((0.04, d * 0.9, 0.025), center=(x, 0, 0.0125), bevel=0.005),
                                   rubber))
        arm_x = (-w * 0.32, w * 0.32)
        # the bolts pinning each leg's lower end in its foot, heads on the legs' outer faces
        bolts = [((sx * (w / 2 - r), sy * (0.04 + r + 0.001), r + 0.002), (0, 1, 0)) for sx in (-1, 1) for sy in (-1, 1)]
    elif variant == "z_frame":
        for i, x in enumerate((-w / 2 + 0.03, w / 2 - 0.03)):
            parts.append(make_part(f"leg_{i}", "leg", S.tube([(x, d / 2 - 0.03, 0.02), (x, -d / 2 + 0.03, h * 0.5),
                                                              (x, d / 2 - 0.05, h - 0.03)], r), steel))
            parts.append(make_part(f"foot_{i}", "foot", S.box((0.05, d, 0.025), center=(x, 0, 0.0125), bevel=0.005),
                                   rubber))
        parts.append(make_part("rail", "rail", S.tube([(-w / 2 + 0.03, -d / 2 + 0.03, h * 0.5),
                                                       (w / 2 - 0.03, -d / 2 + 0.03, h * 0.5)], 0.012), steel))
        arm_x = (-w / 2 + 0.03, w / 2 - 0.03)
        # the bolt through each foot into its leg, its head flush with the foot's outer face
        bolts = [((sx * (w / 2 - 0.005 - 0.0005), d / 2 - 0.03, 0.0125), (1, 0, 0)) for sx in (-1, 1)]
    else:
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"leg_{i}", "leg", S.box((0.03, 0.03, h - 0.03),
                                                            center=(sx * (w / 2 - 0.02), sy * (d / 2 - 0.02), (h - 0.03) / 2)),
                                   steel))
        for i, y in enumerate((-d / 2 + 0.02, d / 2 - 0.02)):
            parts.append(make_part(f"rail_{i}", "rail", S.box((w - 0.07, 0.025, 0.025), center=(0, y, 0.15)), steel))
        arm_x = (-w / 2 + 0.02, w / 2 - 0.02)
        # the bolts through each leg: into the arm above (outer face, just under it) and into
        # the low rail (front or back face)
        bolts = [((sx * (w / 2 - 0.004), sy * (d / 2 - 0.02), h - 0.045), (1, 0, 0)) for sx in (-1, 1) for sy in (-1, 1)]
        bolts += [((sx * (w / 2 - 0.02), sy * (d / 2 - 0.004), 0.15), (0, 1, 0)) for sx in (-1, 1) for sy in (-1, 1)]
    for k, (c, ax) in enumerate(bolts):
        parts.append(make_part(f"bolt_{k}", "bolt", S.cylinder(0.007, 0.002, center=c, axis=ax, sections=8),
                               M.solid((0.6, 0.6, 0.62), "metal", 0.4, 0.8)))
    for i, x in enumerate(arm_x):
        parts.append(make_part(f"arm_{i}", "arm", S.box((0.035, d, 0.03), center=(x, 0, h - 0.015), bevel=0.003), steel))
        # the caps closing the arm tube's ends
        parts += [make_part(f"end_cap_{2 * i + j}", "end_cap", S.box((0.037, 0.01, 0.032), center=(x, sy * (d / 2 + 0.005), h - 0.015)),
                            rubber) for j, sy in enumerate((-1, 1))]
    return parts


@register("microphone_stand", parts=("pole", "microphone"), extra_parts=("leg", "base", "boom", "clip", "clutch", "foot", "hub",
                                                                       "counterweight", "boom_clutch", "cable", "knob",
                                                                       "connector"),
          size_range=(1.0, 1.9), density=900, variants=("tripod_boom", "round_base", "tripod_straight"))
def microphone_stand(rng: np.random.Generator, variant: str) -> list[Part]:
    h = rng.uniform(1.0, 1.45)
    steel = M.solid((0.07, 0.07, 0.08), "metal", 0.45, 0.7)
    parts = []
    if variant == "round_base":
        parts.append(make_part("base", "base", S.frustum(0.15, 0.13, 0.025, sections=24), steel))
        pz0 = 0.025
    else:
        parts += _tripod("leg", 0.0, 0.0, top=0.3, spread=0.32, r=0.009, mat=steel, phase=np.pi / 2)
        parts += _tripod_fittings(0.0, 0.0, top=0.3, spread=0.32, r=0.009, mat=steel, phase=np.pi / 2)
        pz0 = 0.2
    parts.append(make_part("pole", "pole", S.cylinder(0.011, h - pz0, center=(0, 0, (h + pz0) / 2), sections=10), steel))
    parts.append(make_part("clutch", "clutch", S.cylinder(0.018, 0.05, center=(0, 0, h * 0.6), sections=12), steel))
    mic = M.solid((0.2, 0.2, 0.22), "metal", 0.4, 0.8)
    if variant == "tripod_boom":
        a = np.deg2rad(rng.uniform(20, 40))
        L = rng.uniform(0.5, 0.7)
        back = (0, -0.25 * L * np.cos(a), h - 0.25 * L * np.sin(a))
        tip = np.array([0, 0.75 * L * np.cos(a), h + 0.75 * L * np.sin(a)])
        parts.append(make_part("boom", "boom", S.tube([back, tip], 0.009), steel))
        # the weight on the boom's short end and the knob that locks its angle at the pivot
        parts.append(make_part("counterweight", "counterweight", S.cylinder(0.022, 0.06, center=back, axis=(0, np.cos(a), np.sin(a)),
                                                                            sections=12), steel))
        parts.append(make_part("boom_clutch", "boom_clutch", S.cylinder(0.02, 0.05, center=(0.0, 0.0, h), axis=(1, 0, 0), sections=12),
                               steel))
        head = tip + np.array([0, 0.03, 0.0])
    else:
        head = np.array([0, 0.0, h + 0.03])
    parts.append(make_part("clip", "clip", S.box((0.03, 0.03, 0.04), center=head - (0, 0.015, 0.0)), steel))
    body = S.union([S.cylinder(0.02, 0.12, center=head + (0, 0.07, 0.0), axis=(0, 1, 0), sections=12),
                    S.ellipsoid((0.026, 0.028, 0.026), center=head + (0, 0.14, 0.0), subdivisions=2)])
    parts.append(make_part("microphone", "microphone", body, mic))
    # the thumbscrew on the clip's side that sets its angle, and the connector on the cable's
    # end, plugged into the microphone's tail inside the clip
    parts.append(make_part("knob", "knob", S.cylinder(0.01, 0.012, center=head - (-0.021, 0.015, 0.0), axis=(1, 0, 0), sections=10),
                           steel))
    cdir = np.array([0.02, -0.025, -0.068])
    parts.append(make_part("connector", "connector", S.cylinder(0.009, 0.028, center=head + (0.008, -0.005, -0.039),
                                                                axis=tuple(cdir / np.linalg.norm(cdir)), sections=10),
                           M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)))
    # the cable plugged into the microphone's tail, running down beside the clip
    parts.append(make_part("cable", "cable", S.tube([head + (0, 0.005, -0.012), head + (0.02, -0.02, -0.08), head + (0.03, -0.03, -0.2)],
                                                    0.003, sections=6), M.solid((0.03, 0.03, 0.03), "rubber", 0.8)))
    return parts


@register("sheet_music", parts=("page",), extra_parts=("cover", "staple", "clip"), size_range=(0.22, 0.36), density=700,
          variants=("booklet", "loose"), placement="surface")
def sheet_music(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.21, 0.24), rng.uniform(0.297, 0.31)
    paper = M.solid(M.jitter(rng, (0.95, 0.94, 0.9), 0.01), "paper", 0.9)
    parts = []
    if variant == "booklet":
        t = rng.uniform(0.003, 0.012)
        cov = M.paper(rng)
        parts.append(make_part("cover_0", "cover", S.box((w, d, 0.0008), center=(0, 0, 0.0004)), cov))
        parts.append(make_part("pages", "page", S.box((w - 0.003, d - 0.004, t), center=(0, 0, 0.0008 + t / 2)), paper))
        parts.append(make_part("cover_1", "cover", S.box((w, d, 0.0008), center=(0, 0, 0.0012 + t)), cov))
        # saddle-stitched: two staples through the fold along the left edge
        steel = M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)
        parts += [make_part(f"staple_{k}", "staple", S.box((0.0012, 0.012, t + 0.0024), center=(-w / 2 + 0.0006, y, (t + 0.0024) / 2 + 0.0002)),
                            steel) for k, y in enumerate((-d * 0.25, d * 0.25))]
    else:
        n = int(rng.integers(3, 7))
        for k in range(n):
            a = rng.uniform(-0.12, 0.12)
            off = rng.uniform(-0.01, 0.01, 2)
            parts.append(make_part(f"page_{k}", "page", S.box((w, d, 0.0006), center=(off[0], off[1], 0.0003 + 0.0007 * k),
                                                               R=rot((0, 0, 1), a)), paper))
        # a paper clip holding the pile at its top left corner
        zt = 0.0007 * n
        parts.append(make_part("clip", "clip", [S.box((0.008, 0.03, 0.001), center=(-w * 0.35, d * 0.45, zt + 0.0005)),
                                                S.box((0.008, 0.03, 0.001), center=(-w * 0.35, d * 0.45, -0.0005))],
                               M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)))
    return parts
