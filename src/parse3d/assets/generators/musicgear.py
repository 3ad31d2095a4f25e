"""Music gear beside the instruments: record players and vinyl records, metronomes, piano
benches, electronic (MIDI) keyboards and guitar stands.

A record player's dust cover lifts on a hinge along its back edge; a piano bench's seat is a lid
over its music compartment. A guitar stand's cradle holds the instrument's lower bout and its
neck rest (the fork at the top of the post) the neck, facing +Y.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Material, Part, make_part
from ..registry import register
from ._household import ring
from ._kit import OPEN_DOOR, feet4, hinge_parts, legs4, mount, revolute, rot
from ._rods import leg_caps


def _lid_box(w: float, d: float, h: float, t: float, z0: float) -> list[S.Shape]:
    """An open-bottomed box (a dust cover): a top plate and four walls from ``z0`` up."""
    return [S.box((w, d, t), center=(0, 0, z0 + h - t / 2)),
            S.box((w, t, h - t), center=(0, d / 2 - t / 2, z0 + (h - t) / 2)),
            S.box((w, t, h - t), center=(0, -d / 2 + t / 2, z0 + (h - t) / 2)),
            S.box((t, d - 2 * t, h - t), center=(w / 2 - t / 2, 0, z0 + (h - t) / 2)),
            S.box((t, d - 2 * t, h - t), center=(-w / 2 + t / 2, 0, z0 + (h - t) / 2))]


@register("record_player", parts=("base", "platter", "tonearm"),
          extra_parts=("dust_cover", "spindle", "headshell", "counterweight", "knob", "button", "foot",
                       "hinge", "handle", "lever"),
          size_range=(0.3, 0.52), density=450, variants=("hifi", "open", "suitcase"), placement="surface")
def record_player(rng: np.random.Generator, variant: str) -> list:
    w, d = rng.uniform(0.40, 0.46), rng.uniform(0.33, 0.37)
    if variant == "suitcase":
        w, d = rng.uniform(0.33, 0.38), rng.uniform(0.26, 0.29)
    hb = rng.uniform(0.07, 0.1) if variant != "suitcase" else rng.uniform(0.1, 0.12)
    z0 = 0.012 if variant != "suitcase" else 0.008
    plinth = M.wood(rng) if variant == "hifi" else (
        Material(M.jitter(rng, (0.55, 0.2, 0.15)), 0.7, 0.0, "leather") if variant == "suitcase"
        else M.solid((0.08, 0.08, 0.09), "plastic", 0.4))
    alu = M.solid((0.78, 0.78, 0.8), "metal", 0.3, 0.9)
    black = M.solid((0.05, 0.05, 0.05), "rubber", 0.9)
    parts = [make_part("base", "base", S.box((w, d, hb), center=(0, 0, z0 + hb / 2), bevel=0.004), plinth)]
    parts += feet4("foot", w=w, d=d, r=0.02, h=z0, mat=black, inset=0.01)
    zt = z0 + hb
    r = 0.156 if variant != "suitcase" else rng.uniform(0.12, 0.13)  # an LP (30.5 cm) fits a full-size platter
    px = -w / 2 + r + 0.03
    # the platter with its felt mat on top (one part: its top is where a record lies)
    parts.append(make_part("platter", "platter", [S.cylinder(r, 0.02, center=(px, 0.0, zt + 0.01), sections=32),
                                                  S.cylinder(r - 0.0015, 0.003, center=(px, 0.0, zt + 0.0215), sections=32)],
                           alu))
    parts.append(make_part("spindle", "spindle", S.cylinder(0.003, 0.018, center=(px, 0.0, zt + 0.032),
                                                            sections=8), alu))
    # the tonearm: a pivot post at the back right, the arm in its rest beside the platter
    ax, ay = min(px + r + 0.04, w / 2 - 0.025), -0.08
    parts.append(make_part("tonearm_base", "tonearm", S.cylinder(0.022, 0.025, center=(ax, ay, zt + 0.0125),
                                                                 sections=16), alu))
    tip = (max(ax - 0.012, px + r + 0.012), 0.1, zt + 0.035)
    parts.append(make_part("tonearm", "tonearm", S.tube([(ax, ay, zt + 0.035), tip], 0.004, sections=8), alu))
    parts.append(make_part("headshell", "headshell", S.box((0.012, 0.04, 0.01), center=(tip[0], tip[1] + 0.02,
                                                                                     zt + 0.033)), black))
    parts.append(make_part("counterweight", "counterweight", S.cylinder(0.013, 0.025, center=(ax, ay - 0.035, zt + 0.035),
                                                                        axis=(0, 1, 0), sections=12), alu))
    # the cueing lever in front of the arm's pivot, lower than the platter's top
    parts.append(make_part("lever", "lever", S.box((0.006, 0.02, 0.016), center=(ax - 0.012, ay + 0.035, zt + 0.008), bevel=0.001),
                           alu))
    parts.append(make_part("knob", "knob", S.cylinder(0.012, 0.012, center=(w / 2 - 0.035, d / 2 - 0.04, zt + 0.006),
                                                      sections=12), alu))
    for k in range(2):
        parts.append(make_part(f"button_{k}", "button",
                               S.box((0.022, 0.012, 0.006), center=(-w / 2 + 0.04 + 0.03 * k, d / 2 - 0.025, zt + 0.003)),
                               alu))
    if variant == "suitcase":
        parts.append(make_part("handle", "handle", S.tube([(-0.05, d / 2, z0 + hb * 0.7), (-0.05, d / 2 + 0.02, z0 + hb * 0.7),
                                                           (0.05, d / 2 + 0.02, z0 + hb * 0.7), (0.05, d / 2, z0 + hb * 0.7)],
                                                          0.006, sections=8), black))
    if variant == "hifi":
        hc = rng.uniform(0.08, 0.1)
        parts.append(make_part("dust_cover", "dust_cover", _lid_box(w, d, hc, 0.004, zt), M.glass(rng)))
        parts += hinge_parts("hinge", x=zt + 0.006, y=-d / 2 - 0.007, z0=-w / 2, z1=w / 2, mat=black, axis="x",
                             radius=0.007, length=0.04)
        parts.append(revolute("dust_cover_hinge", "base", "dust_cover", axis=(1, 0, 0), origin=(0, -d / 2, zt),
                              opens=OPEN_DOOR * 0.6))
    return parts


@register("vinyl_record", parts=("disc",), extra_parts=("label", "sleeve", "inner_sleeve", "spine"),
          size_range=(0.17, 0.32), density=900, variants=("lp", "single", "bare"), placement="surface")
def vinyl_record(rng: np.random.Generator, variant: str) -> list[Part]:
    r = 0.1524 if variant != "single" else 0.0889
    vinyl = M.solid((0.03, 0.03, 0.035), "plastic", 0.3)
    z = 0.0
    parts = []
    if variant != "bare":  # lying on its card sleeve
        s = 0.314 if variant == "lp" else 0.18
        # the disc lies inside its sleeve (the sleeve's top is the record's top)
        parts.append(make_part("sleeve", "sleeve", S.box((s, s, 0.0045), center=(0, 0, 0.00225)), M.paper(rng)))
        z = 0.0012
    # the disc and its label are rings round the centre hole (7.24 mm; a single's 38 mm), so a
    # record lies on a platter over its spindle
    hole = 0.00362 if variant != "single" else 0.019
    rl = 0.05 if variant != "single" else 0.045
    parts.append(make_part("disc", "disc", ring([(rl, z), (r, z), (r, z + 0.0018), (rl, z + 0.0018)], sections=32), vinyl))
    parts.append(make_part("label", "label", ring([(hole, z + 0.0011), (rl, z + 0.0011), (rl, z + 0.0022), (hole, z + 0.0022)],
                                                  sections=16), M.paper(rng)))
    # side B's label underneath, and the paper inner sleeve inside the card sleeve
    parts.append(make_part("label_1", "label", ring([(hole, z), (rl, z), (rl, z + 0.0011), (hole, z + 0.0011)], sections=16),
                           M.paper(rng)))
    if variant != "bare":
        # the sleeve's spine along its closed edge (-X), where the title is printed
        parts.append(make_part("spine", "spine", S.box((0.003, s, 0.0045), center=(-s / 2 + 0.0015, 0, 0.00225)), M.paper(rng)))
        # (its edge showing at the card sleeve's open side)
        parts.append(make_part("inner_sleeve", "inner_sleeve", S.box((0.024, r * 2 * 0.9, 0.0006), center=(s / 2 - 0.008, 0, 0.0039)),
                               M.solid((0.95, 0.94, 0.9), "paper", 0.8)))
    return parts


@register("metronome", parts=("body", "pendulum"), extra_parts=("base", "weight", "scale", "key", "lid", "foot", "button", "speaker",
                                                                "dial", "screw", "clip", "battery_cover"),
          size_range=(0.1, 0.26), density=600, variants=("pyramid", "digital"), placement="surface")
def metronome(rng: np.random.Generator, variant: str) -> list[Part]:
    wood = M.wood(rng)
    brass = M.solid((0.8, 0.65, 0.3), "metal", 0.3, 0.9)
    if variant == "digital":
        w, d, h = rng.uniform(0.07, 0.09), rng.uniform(0.05, 0.07), rng.uniform(0.1, 0.13)
        body = M.plastic(rng)
        parts = [make_part("base", "base", S.box((w, d, 0.01), center=(0, 0, 0.005), bevel=0.002), body),
                 make_part("body", "body", S.box((w, d * 0.7, h - 0.01), center=(0, -d * 0.1, 0.01 + (h - 0.01) / 2),
                                                 bevel=0.004), body),
                 make_part("scale", "scale", S.box((w * 0.7, 0.002, h * 0.35), center=(0, d * 0.25 + 0.001, h * 0.6)),
                           M.solid((0.6, 0.75, 0.6), "glass", 0.1)),
                 make_part("pendulum", "pendulum", S.box((0.004, 0.002, h * 0.3), center=(0, d * 0.25 + 0.003, h * 0.3)),
                           M.solid((0.9, 0.2, 0.2), "plastic")),
                 make_part("key", "key", S.cylinder(0.008, 0.006, center=(w / 2 - 0.012, -d * 0.1, h + 0.003),
                                                    sections=10), body)]
        # the tempo and start buttons on the front under the display, the speaker grille and the
        # volume dial on the side
        dark = M.solid((0.15, 0.15, 0.16), "plastic", 0.5)
        parts += [make_part(f"button_{k}", "button", S.box((0.012, 0.004, 0.008), center=(x, d * 0.25 + 0.002, h * 0.3)), dark)
                  for k, x in enumerate((-w * 0.25, w * 0.25))]
        parts.append(make_part("speaker", "speaker", S.cylinder(0.012, 0.002, center=(0, d * 0.25 + 0.001, h * 0.14), axis=(0, 1, 0),
                                                                sections=12), dark))
        parts.append(make_part("dial", "dial", S.cylinder(0.01, 0.005, center=(w / 2 + 0.0025, -d * 0.1, h * 0.5), axis=(1, 0, 0),
                                                          sections=12), dark))
        # the battery compartment's cover on the back, flush with it
        parts.append(make_part("battery_cover", "battery_cover",
                               S.box((w * 0.6, 0.001, h * 0.3), center=(0, -d * 0.45 + 0.0005, h * 0.35)), body))
        return parts
    h = rng.uniform(0.2, 0.24)
    bw, bd = rng.uniform(0.1, 0.12), rng.uniform(0.09, 0.11)
    # a pyramid whose front face is open over the scale and the swinging pendulum
    top = (0.025, 0.025)
    parts = [make_part("base", "base", S.box((bw + 0.01, bd + 0.01, 0.015), center=(0, 0, 0.0075), bevel=0.002), wood)]
    pyr = S.hull(np.array([[sx * bw / 2, sy * bd / 2, 0.015] for sx in (-1, 1) for sy in (-1, 1)]
                          + [[sx * top[0], sy * top[1], h] for sx in (-1, 1) for sy in (-1, 1)]))
    parts.append(make_part("body", "body", pyr, wood))
    ff = bd / 2 + 0.001 - (bd / 2 - top[1]) * 0.5  # the front face's y half way up
    tilt = np.arctan2(bd / 2 - top[1], h - 0.015)
    Rf = rot((1, 0, 0), -tilt)
    zc = 0.015 + (h - 0.015) * 0.5
    parts.append(make_part("scale", "scale", S.box((0.02, 0.002, (h - 0.015) * 0.7), center=(0, ff + 0.001, zc), R=Rf),
                           M.solid((0.9, 0.85, 0.7), "paper", 0.8)))
    parts.append(make_part("pendulum", "pendulum", S.box((0.004, 0.003, (h - 0.015) * 0.8),
                                                         center=(0, ff + 0.004, zc), R=Rf), brass))
    parts.append(make_part("weight", "weight", S.box((0.014, 0.008, 0.016), center=(0, ff + 0.007 - 0.04 * np.tan(tilt),
                                                                                     zc + 0.04), R=Rf), brass))
    parts.append(make_part("key", "key", S.box((0.004, 0.02, 0.014), center=(bw / 2 - 0.015, 0, 0.05)), brass))
    # the two brass screws pinning the scale to the face, at its top and bottom ends, and the
    # clip at the top that locks the pendulum still
    ls = (h - 0.015) * 0.35
    for k, dz in enumerate((-ls, ls)):
        c = np.array([0.0, ff + 0.001, zc]) + Rf @ np.array([0.0, 0.0015, dz * 0.97])
        parts.append(make_part(f"screw_{k}", "screw", S.cylinder(0.0025, 0.0015, center=tuple(c), axis=tuple(Rf @ np.array([0, 1.0, 0])),
                                                                 sections=8), brass))
    cc = np.array([0.0, ff + 0.001, zc]) + Rf @ np.array([0.0, 0.002, (h - 0.015) * 0.45])
    parts.append(make_part("clip", "clip", S.box((0.012, 0.004, 0.006), center=tuple(cc), R=Rf), brass))
    return parts


@register("piano_bench", parts=("seat", "leg"), extra_parts=("apron", "lid", "hinge", "stretcher", "knob", "cushion",
                                                            "compartment", "foot", "ferrule"),
          size_range=(0.5, 0.95), density=550, variants=("storage", "adjustable", "duet"))
def piano_bench(rng: np.random.Generator, variant: str) -> list:
    wood = Material(M.jitter(rng, (0.06, 0.05, 0.05), 0.02), 0.25, 0.0, "wood")  # piano black
    if rng.random() < 0.3:
        wood = M.wood(rng)
    w = rng.uniform(0.55, 0.62) if variant != "duet" else rng.uniform(0.76, 0.9)
    d = rng.uniform(0.32, 0.36)
    h = rng.uniform(0.48, 0.52)
    parts = []
    if variant == "adjustable":
        # a padded seat on an X-free scissor: two side frames, a crank knob on each side
        ts = 0.07
        parts.append(make_part("seat", "seat", S.box((w, d, ts), center=(0, 0, h - ts / 2), bevel=0.01),
                               M.leather(rng)))
        parts.append(make_part("apron", "apron", S.box((w - 0.04, d - 0.04, 0.05), center=(0, 0, h - ts - 0.025)), wood))
        parts += legs4("leg", "leg", w=w - 0.04, d=d - 0.04, h=h - ts - 0.05, size=0.045, mat=wood)
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"stretcher_{k}", "stretcher",
                                   S.box((0.025, d - 0.1, 0.03), center=(sx * (w / 2 - 0.045), 0, 0.12)), wood))
            parts.append(make_part(f"knob_{k}", "knob", S.cylinder(0.025, 0.025, center=(sx * (w / 2 - 0.008), 0, h - ts - 0.03),
                                                                   axis=(1, 0, 0), sections=16), wood))
        return parts + _bench_ferrules(parts)
    # storage bench: a box (apron all round) on four legs, the seat a lid hinged at the back
    ta, hl = 0.025, rng.uniform(0.09, 0.12)
    za = h - ta - hl
    parts += legs4("leg", "leg", w=w, d=d, h=za + hl, size=0.05, mat=wood, inset=0.005)
    box = [S.box((w - 0.1, 0.018, hl), center=(0, sy * (d / 2 - 0.014), za + hl / 2)) for sy in (-1, 1)]
    box += [S.box((0.018, d - 0.1, hl), center=(sx * (w / 2 - 0.014), 0, za + hl / 2)) for sx in (-1, 1)]
    parts.append(make_part("apron", "apron", box, wood))
    parts.append(make_part("compartment", "compartment", S.box((w - 0.1, d - 0.046, 0.012), center=(0, 0, za + 0.006)),
                           wood))
    parts.append(make_part("seat", "seat", S.box((w, d, ta), center=(0, 0, h - ta / 2), bevel=0.004), wood))
    if rng.random() < 0.5 or variant == "duet":
        parts.append(make_part("cushion", "cushion", S.box((w - 0.06, d - 0.05, 0.035), center=(0, 0, h + 0.0175),
                                                           bevel=0.01), M.leather(rng)))
        parts.append(mount("seat", "cushion"))
    parts += hinge_parts("hinge", x=h - ta, y=-d / 2 + 0.004, z0=-w / 2 + 0.1, z1=w / 2 - 0.1, mat=M.metal(rng),
                         axis="x", radius=0.005, length=0.05)
    parts.append(revolute("seat_hinge", "apron", "seat", axis=(1, 0, 0), origin=(0, -d / 2, h - ta), opens=1.2))
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"stretcher_{k}", "stretcher", S.box((0.025, d - 0.1, 0.025),
                                                                   center=(sx * (w / 2 - 0.025), 0, 0.1)), wood))
    return parts + _bench_ferrules(parts)


def _bench_ferrules(parts: list) -> list[Part]:
    """Brass ferrules capping a piano bench's square feet."""
    return leg_caps(parts, label="ferrule", mat=M.solid((0.78, 0.62, 0.3), "metal", 0.3, 0.9), height=0.035)


@register("midi_keyboard", parts=("body", "key"),
          extra_parts=("knob", "pad", "slider", "wheel", "display", "button", "foot"),
          size_range=(0.3, 1.0), density=400, variants=("mini", "controller49", "controller61"), placement="surface")
def midi_keyboard(rng: np.random.Generator, variant: str) -> list[Part]:
    n_white = {"mini": 15, "controller49": 29, "controller61": 36}[variant]
    kw = 0.0235 if variant != "mini" else rng.uniform(0.017, 0.019)
    kd = 0.15 if variant != "mini" else 0.085
    side = rng.uniform(0.03, 0.07) if variant != "mini" else 0.015
    panel = rng.uniform(0.08, 0.12) if variant != "mini" else rng.uniform(0.06, 0.08)
    w = n_white * kw + 2 * side + (0.06 if variant != "mini" else 0.0)
    d = kd + panel + 0.02
    h = rng.uniform(0.05, 0.07) if variant != "mini" else rng.uniform(0.03, 0.04)
    case = M.solid(M.jitter(rng, (0.12, 0.12, 0.13), 0.02)[:3], "plastic", 0.5)
    white = M.solid((0.94, 0.94, 0.92), "plastic", 0.35)
    blackk = M.solid((0.04, 0.04, 0.04), "plastic", 0.35)
    zf = 0.006
    parts = feet4("foot", w=w, d=d, r=0.012, h=zf, mat=M.solid((0.05, 0.05, 0.05), "rubber", 0.9), inset=0.02)
    kz = zf + h * 0.45  # the keybed's level
    yk = d / 2 - kd / 2 - 0.01
    body = [S.box((w, d, h * 0.45), center=(0, 0, zf + h * 0.225), bevel=0.003),
            S.box((w, panel + 0.01, h * 0.55), center=(0, -d / 2 + (panel + 0.01) / 2, kz + h * 0.275), bevel=0.003)]
    parts.append(make_part("body", "body", body, case))
    x0 = -w / 2 + side + (0.06 if variant != "mini" else 0.0)
    for k in range(n_white):  # white keys, then the black ones between them (no black after E and B)
        parts.append(make_part(f"key_{k}", "key", S.box((kw - 0.001, kd, 0.016), center=(x0 + kw * (k + 0.5), yk, kz + 0.008)),
                               white))
    nb = 0
    for k in range(n_white - 1):
        if k % 7 in (2, 6):
            continue
        parts.append(make_part(f"key_black_{nb}", "key", S.box((kw * 0.55, kd * 0.62, 0.012),
                                                              center=(x0 + kw * (k + 1), yk - kd * 0.19, kz + 0.022)), blackk))
        nb += 1
    zp = kz + h * 0.55
    if variant != "mini":
        for k in range(2):  # pitch and modulation wheels left of the keys
            parts.append(make_part(f"wheel_{k}", "wheel", S.cylinder(0.025, 0.014, center=(-w / 2 + side + 0.015 + 0.028 * k,
                                                                                          yk, kz + 0.012),
                                                                    axis=(1, 0, 0), sections=16), case))
    n_knob = 8 if variant != "mini" else 4
    for k in range(n_knob):
        parts.append(make_part(f"knob_{k}", "knob", S.cylinder(0.007, 0.014, center=(w * 0.05 + k * 0.028, -d / 2 + panel * 0.35,
                                                                                     zp + 0.007), sections=12), blackk))
    n_pad = 8 if variant != "mini" else 4
    for k in range(n_pad):
        parts.append(make_part(f"pad_{k}", "pad", S.box((0.022, 0.022, 0.006), center=(-w * 0.3 + k * 0.027,
                                                                                     -d / 2 + panel * 0.6, zp + 0.003),
                                                       bevel=0.002), M.solid((0.35, 0.35, 0.38), "rubber", 0.8)))
    if variant != "mini":
        parts.append(make_part("display", "display", S.box((0.07, 0.035, 0.002), center=(-w * 0.05 - 0.06, -d / 2 + panel * 0.35,
                                                                                         zp + 0.001)),
                               M.solid((0.2, 0.45, 0.6), "glass", 0.1)))
        for k in range(4):
            parts.append(make_part(f"slider_{k}", "slider", S.box((0.008, 0.012, 0.01), center=(w * 0.32 + 0.025 * k,
                                                                                             -d / 2 + panel * 0.5, zp + 0.005)),
                                   white))
    for k in range(3):
        parts.append(make_part(f"button_{k}", "button", S.box((0.012, 0.008, 0.005), center=(-w / 2 + side + 0.01 + 0.018 * k,
                                                                                           -d / 2 + panel * 0.5, zp + 0.0025)),
                               blackk))
    return parts


@register("guitar_stand", parts=("cradle", "leg"),
          extra_parts=("neck_rest", "post", "yoke", "padding", "knob", "foot", "frame", "collar", "hinge"),
          size_range=(0.3, 1.0), density=600, variants=("tripod", "a_frame", "wooden"))
def guitar_stand(rng: np.random.Generator, variant: str) -> list[Part]:
    metal = M.solid((0.06, 0.06, 0.07), "metal", 0.5, 0.6)
    rubber = M.solid((0.1, 0.1, 0.1), "rubber", 0.9)
    parts = []
    if variant == "a_frame":  # a folding A-frame: two legs in front, a back leg, a padded cradle, no neck rest
        h = rng.uniform(0.3, 0.4)
        wide = rng.uniform(0.26, 0.32)
        zc = rng.uniform(0.12, 0.16)
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"leg_{k}", "leg", S.tube([(sx * wide / 2, 0.12, 0.01), (sx * 0.04, -0.02, h)], 0.009,
                                                           sections=8), metal))
            parts.append(make_part(f"cradle_{k}", "cradle", S.tube([(sx * 0.13, 0.08, zc), (sx * 0.13, 0.16, zc + 0.03)],
                                                                 0.012, sections=8), rubber))
        parts.append(make_part("leg_2", "leg", S.tube([(0, -0.02, h), (0, -0.2, 0.01)], 0.009, sections=8), metal))
        parts.append(make_part("frame", "frame", S.tube([(-0.13, 0.08, zc), (0.13, 0.08, zc)], 0.008, sections=8), metal))
        parts.append(make_part("padding", "padding", S.box((0.08, 0.025, 0.1), center=(0, -0.01, h - 0.06)), rubber))
        parts += [make_part(f"foot_{k}", "foot", S.cylinder(0.014, 0.012, center=c, sections=10), rubber)
                  for k, c in enumerate([(-wide / 2, 0.12, 0.006), (wide / 2, 0.12, 0.006), (0, -0.2, 0.006)])]
        # the hinge block at the top where the three legs fold together
        parts.append(make_part("hinge", "hinge", S.cylinder(0.014, 0.1, center=(0, -0.02, h), axis=(1, 0, 0), sections=10), metal))
        return parts
    h = rng.uniform(0.7, 0.85)
    if variant == "wooden":
        wood = M.wood(rng)
        # two runners (the legs) on the floor, the base plate on them, the post at its back
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"leg_{k}", "leg", S.box((0.03, 0.3, 0.03), center=(sx * 0.145, 0, 0.015)), wood))
        parts.append(make_part("base", "frame", S.box((0.32, 0.3, 0.025), center=(0, 0, 0.0425), bevel=0.003), wood))
        parts.append(make_part("post", "post", S.box((0.04, 0.04, h - 0.055), center=(0, -0.1, 0.055 + (h - 0.055) / 2)), wood))
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"cradle_{k}", "cradle", S.box((0.05, 0.09, 0.07), center=(sx * 0.1, 0.09, 0.09)), wood))
        parts.append(make_part("padding", "padding", S.box((0.22, 0.02, 0.02), center=(0, 0.06, 0.13)), rubber))
        yk = -0.1
    else:
        for k in range(3):  # tripod legs splayed from a collar
            a = np.pi / 2 + 2 * np.pi * k / 3 + np.pi / 3
            parts.append(make_part(f"leg_{k}", "leg", S.tube([(0, -0.05, 0.25), (0.25 * np.cos(a), -0.05 + 0.25 * np.sin(a), 0.01)],
                                                           0.008, sections=8), metal))
            # the rubber foot capping the leg's end, flush with its underside
            parts.append(make_part(f"foot_{k}", "foot", S.cylinder(0.011, 0.012, center=(0.245 * np.cos(a), -0.05 + 0.245 * np.sin(a),
                                                                                           0.0081), sections=10), rubber))
        # the collar on the post that the legs are pinned to
        parts.append(make_part("collar", "collar", S.cylinder(0.018, 0.04, center=(0, -0.05, 0.24), sections=10), metal))
        parts.append(make_part("post", "post", S.cylinder(0.012, h - 0.05, center=(0, -0.05, 0.05 + (h - 0.05) / 2),
                                                          sections=10), metal))
        parts.append(make_part("yoke", "frame", S.tube([(-0.13, 0.06, 0.2), (0, -0.05, 0.24), (0.13, 0.06, 0.2)], 0.009,
                                                       sections=8), metal))
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"cradle_{k}", "cradle", S.tube([(sx * 0.13, 0.06, 0.2), (sx * 0.13, 0.14, 0.24)], 0.014,
                                                                 sections=8), rubber))
        parts.append(make_part("knob", "knob", S.cylinder(0.012, 0.03, center=(0.02, -0.05, 0.45), axis=(1, 0, 0),
                                                          sections=10), metal))
        yk = -0.05
    # the neck rest: a padded fork at the top of the post, open towards the front
    for k, sx in enumerate((-1, 1)):
        parts.append(make_part(f"neck_rest_{k}", "neck_rest", S.tube([(sx * 0.012, yk, h - 0.02), (sx * 0.03, yk + 0.05, h)],
                                                                   0.01, sections=8), rubber))
    return parts
