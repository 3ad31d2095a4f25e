"""Meeting rooms and offices: projectors and screens, conference phones, lecterns, desk
organisers and filing cabinets.

A filing cabinet's drawers are prismatic joints sliding out along +Y; each drawer is its front
panel (label ``drawer``) on an open box (``drawer_box``, its floor an internal support for
``IN``), with the handle and label holder mounted on the front.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Material, Part, make_part
from ..registry import register
from ._casework import bar_pull, black, white
from ._dB_case import glides
from ._kit import DRAWER_TRAVEL, feet4, mount, prismatic, rot


@register("projector", parts=("body", "lens"), extra_parts=("foot", "vent", "button", "focus_ring", "zoom_ring", "sensor", "indicator",
                                                          "port", "lamp_cover", "screw", "lock_slot", "release_button"),
          size_range=(0.2, 0.45),
          density=600, variants=("compact", "business", "short_throw"), placement="surface")
def projector(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = {"compact": (rng.uniform(0.2, 0.26), rng.uniform(0.15, 0.2), rng.uniform(0.07, 0.09)),
               "business": (rng.uniform(0.3, 0.36), rng.uniform(0.22, 0.28), rng.uniform(0.09, 0.12)),
               "short_throw": (rng.uniform(0.33, 0.4), rng.uniform(0.28, 0.34), rng.uniform(0.1, 0.13))}[variant]
    shell = white(rng, "plastic") if rng.random() < 0.6 else M.solid((0.15, 0.15, 0.17), "plastic", 0.4)
    fh = 0.012
    parts = feet4("foot", w=w, d=d, r=0.012, h=fh, mat=black(), inset=0.02)
    parts.append(make_part("body", "body", S.box((w, d, h), center=(0, 0, fh + h / 2), bevel=0.012), shell))
    lx = w * 0.25
    if variant == "short_throw":
        lens = S.box((w * 0.4, 0.04, h * 0.4), center=(0, d / 2 - 0.05, fh + h + 0.015), bevel=0.01)
    else:
        lens = S.cylinder(h * 0.32, 0.03, center=(lx, d / 2 + 0.012, fh + h / 2), axis=(0, 1, 0), sections=20)
    parts.append(make_part("lens", "lens", lens, M.solid((0.1, 0.12, 0.15), "glass", 0.05)))
    if variant != "short_throw":
        parts.append(make_part("focus_ring", "focus_ring", S.cylinder(h * 0.36, 0.01, center=(lx, d / 2 + 0.003, fh + h / 2),
                                                                      axis=(0, 1, 0), sections=20), black()))
    parts.append(make_part("vent", "vent", S.box((0.004, d * 0.5, h * 0.5), center=(-w / 2 - 0.0015, 0, fh + h / 2)), black()))
    for k in range(4):
        parts.append(make_part(f"button_{k}", "button", S.cylinder(0.006, 0.006, center=(-w * 0.3 + 0.02 * k, -d * 0.3, fh + h + 0.002),
                                                                   sections=10), black()))
    # the zoom ring before the focus ring, the exhaust vent on the other side, the remote's
    # infrared window on the front, the power and lamp lights and the input ports at the back
    if variant != "short_throw":
        parts.append(make_part("zoom_ring", "zoom_ring", S.cylinder(h * 0.38, 0.006, center=(lx, d / 2 + 0.014, fh + h / 2),
                                                                    axis=(0, 1, 0), sections=20), black()))
    parts.append(make_part("vent_1", "vent", S.box((0.004, d * 0.5, h * 0.5), center=(w / 2 + 0.0015, 0, fh + h / 2)), black()))
    parts.append(make_part("sensor", "sensor", S.box((0.02, 0.003, 0.012), center=(-w * 0.3, d / 2 + 0.0015, fh + h * 0.5)),
                           M.solid((0.2, 0.05, 0.05), "glass", 0.1)))
    parts += [make_part(f"indicator_{k}", "indicator", S.cylinder(0.003, 0.002, center=(-w * 0.3 + 0.02 * k, -d * 0.15, fh + h + 0.001),
                                                                  sections=8), M.solid(c, "plastic", 0.2))
              for k, c in enumerate(((0.1, 0.8, 0.2), (0.9, 0.5, 0.1)))]
    parts += [make_part(f"port_{k}", "port", S.box((0.016, 0.003, 0.008), center=(-w * 0.25 + 0.03 * k, -d / 2 - 0.0015, fh + h * 0.4)),
                        black()) for k in range(3)]
    # underneath, flush with the shell: the lamp door and the screw holding it shut; the
    # security lock slot at the back; the button on the front releasing the tilt foot
    parts.append(make_part("lamp_cover", "lamp_cover", S.box((w * 0.35, d * 0.35, 0.001), center=(-w * 0.1, 0, fh + 0.0005)), shell))
    parts.append(make_part("screw", "screw", S.cylinder(0.003, 0.001, center=(-w * 0.1 + w * 0.15, 0, fh + 0.0005), sections=8),
                           M.solid((0.6, 0.6, 0.62), "metal", 0.4)))
    parts.append(make_part("lock_slot", "lock_slot", S.box((0.007, 0.002, 0.003), center=(w * 0.4, -d / 2 + 0.0008, fh + h * 0.3)), black()))
    parts.append(make_part("release_button", "release_button", S.box((0.014, 0.002, 0.008), center=(-w * 0.3, d / 2 - 0.0008, fh + h * 0.2)),
                           black()))
    return parts


@register("projector_screen", parts=("screen",), extra_parts=("case", "bottom_bar", "frame", "pull_handle", "end_cap", "bracket",
                                                              "corner", "spring", "screw"),
          size_range=(1.2, 3.2), density=300, variants=("pull_down", "fixed_frame"), placement="wall")
def projector_screen(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(1.5, 3.0)
    h = w * rng.choice([0.5625, 0.75])
    fabric = M.solid((0.96, 0.96, 0.95), "fabric", 0.9)
    if variant == "fixed_frame":
        f = 0.08
        frame = [S.box((w, 0.04, f), center=(0, 0.02, f / 2)), S.box((w, 0.04, f), center=(0, 0.02, h - f / 2)),
                 S.box((f, 0.04, h - 2 * f), center=(-w / 2 + f / 2, 0.02, h / 2)),
                 S.box((f, 0.04, h - 2 * f), center=(w / 2 - f / 2, 0.02, h / 2))]
        # the frame's mitred corners are joined by corner brackets on its back; it hangs on two
        # wall brackets along its top
        steel = M.solid((0.5, 0.5, 0.52), "metal", 0.4, 0.8)
        # behind the screen, the tension springs round its edge pulling the fabric taut onto the
        # frame, about every 30 cm
        springs = []
        for horizontal in (True, False):
            span = (w if horizontal else h) - 2 * f
            n = max(2, int(span / 0.3))
            for s in np.linspace(-span / 2, span / 2, n + 2)[1:-1]:
                for side in (-1, 1):
                    if horizontal:
                        c, axis = (s, 0.014, h / 2 + side * (h / 2 - f - 0.02)), (0, 0, 1)
                    else:
                        c, axis = (side * (w / 2 - f - 0.02), 0.014, h / 2 + s), (1, 0, 0)
                    springs.append(make_part(f"spring_{len(springs)}", "spring", S.cylinder(0.004, 0.04, center=c, axis=axis, sections=8),
                                             steel))
        return [make_part("frame", "frame", frame, M.solid((0.05, 0.05, 0.05), "fabric", 0.95)), *springs,
                make_part("screen", "screen", S.box((w - 2 * f, 0.004, h - 2 * f), center=(0, 0.03, h / 2)), fabric),
                *[make_part(f"corner_{k}", "corner", S.box((0.12, 0.004, 0.12), center=(sx * (w / 2 - 0.06), -0.002, z)), steel)
                  for k, (sx, z) in enumerate([(-1, 0.06), (1, 0.06), (-1, h - 0.06), (1, h - 0.06)])],
                *[make_part(f"bracket_{k}", "bracket", S.box((0.06, 0.012, 0.1), center=(sx * w * 0.3, -0.006, h - 0.05)), steel)
                  for k, sx in enumerate((-1, 1))]]
    case_r = 0.045
    zc = h + 0.06
    parts = [make_part("case", "case", S.box((w + 0.08, 0.09, 0.09), center=(0, 0.045, zc), bevel=0.02), white(rng, "metal")),
             make_part("screen", "screen", S.box((w, 0.003, h), center=(0, 0.05, zc - case_r - h / 2)), fabric),
             make_part("bottom_bar", "bottom_bar", S.box((w + 0.02, 0.02, 0.03), center=(0, 0.05, zc - case_r - h - 0.015)),
                       M.solid((0.1, 0.1, 0.1), "metal", 0.4))]
    for i, s in enumerate((-1, 1)):
        parts.append(make_part(f"end_cap_{i}", "end_cap", S.box((0.02, 0.1, 0.1), center=(s * (w / 2 + 0.05), 0.05, zc)), black()))
    parts.append(make_part("pull_handle", "pull_handle", S.box((0.04, 0.02, 0.06), center=(0, 0.05, zc - case_r - h - 0.06)), black()))
    # the case hangs on a bracket at each end, each screwed to the wall above and below the case;
    # a plastic cap closes each end of the bottom bar
    steel = M.solid((0.5, 0.5, 0.52), "metal", 0.4, 0.8)
    parts += [make_part(f"bracket_{k}", "bracket", S.box((0.05, 0.02, 0.12), center=(s * (w / 2 - 0.05), -0.01, zc)), steel)
              for k, s in enumerate((-1, 1))]
    parts += [make_part(f"screw_{2 * k + j}", "screw", S.cylinder(0.004, 0.002, center=(s * (w / 2 - 0.05), 0.001, zc + sz * 0.0525), axis=(0, 1, 0),
                                                                  sections=8), steel)
              for k, s in enumerate((-1, 1)) for j, sz in enumerate((-1, 1))]
    parts += [make_part(f"end_cap_{2 + k}", "end_cap", S.box((0.006, 0.022, 0.032), center=(s * (w / 2 + 0.013), 0.05, zc - case_r - h - 0.015)),
                        black()) for k, s in enumerate((-1, 1))]
    return parts


@register("conference_phone", parts=("body",), extra_parts=("display", "key", "speaker_grille", "microphone", "status_light",
                                                             "foot", "mute_button"),
          size_range=(0.18, 0.4), density=700, variants=("triangle", "round"), placement="surface")
def conference_phone(rng: np.random.Generator, variant: str) -> list[Part]:
    s, h = rng.uniform(0.2, 0.34), rng.uniform(0.035, 0.05)
    shell = M.solid(M.jitter(rng, (0.12, 0.12, 0.13), 0.02), "plastic", 0.4)
    if variant == "triangle":
        a = np.deg2rad([90, 210, 330])
        tri = np.c_[np.cos(a), np.sin(a)] * s / 1.8
        body = S.hull(np.vstack([np.c_[tri, np.zeros(3)], np.c_[tri * 0.85, np.full(3, h)]]))
        mics = [(tri[i] * 0.7) for i in range(3)]
    else:
        body = S.frustum(s / 2, s / 2 * 0.85, h, sections=32)
        mics = [np.array([np.cos(b), np.sin(b)]) * s * 0.3 for b in np.linspace(0, 2 * np.pi, 3, endpoint=False)]
    parts = [make_part("body", "body", body, shell),
             make_part("speaker_grille", "speaker_grille", S.cylinder(s * 0.14, 0.003, center=(0, 0, h + 0.001), sections=24),
                       M.solid((0.3, 0.3, 0.32), "metal", 0.5, 0.5)),
             make_part("display", "display", S.box((s * 0.22, s * 0.09, 0.003), center=(0, -s * 0.2, h - 0.001),
                                                   R=rot((1, 0, 0), 0.0)), M.solid((0.1, 0.2, 0.3), "glass", 0.1))]
    for k in range(12):
        x = (k % 3 - 1) * 0.014
        y = -s * 0.2 + 0.028 + (k // 3) * 0.011 - 0.06 if variant == "round" else s * 0.04 + (k // 3) * 0.011 - 0.02
        parts.append(make_part(f"key_{k}", "key", S.box((0.01, 0.008, 0.004), center=(x + 0.06, y, h), bevel=0.001),
                               M.solid((0.7, 0.7, 0.72), "plastic", 0.5)))
    for i, (x, y) in enumerate(mics):
        parts.append(make_part(f"microphone_{i}", "microphone", S.cylinder(0.005, 0.003, center=(x, y, h * 0.95), sections=8),
                               black()))
        # the status light beside each microphone, flush with the top, and a rubber foot under it
        parts.append(make_part(f"status_light_{i}", "status_light", S.cylinder(0.003, 0.003, center=(x * 1.12, y * 1.12, h - 0.0015),
                                                                               sections=8), M.solid((0.2, 0.8, 0.3), "glass", 0.1)))
        parts.append(make_part(f"foot_{i}", "foot", S.cylinder(0.008, 0.002, center=(x, y, 0.001), sections=8),
                               M.solid((0.1, 0.1, 0.1), "rubber", 0.8)))
        # the mute button by each microphone (inward of it on a triangle, beside it on a round one)
        u = np.array([x, y]) / np.hypot(x, y)
        c = np.array([x, y]) * 0.8 if variant == "triangle" else np.array([x, y]) + 0.015 * np.array([-u[1], u[0]])
        parts.append(make_part(f"mute_button_{i}", "mute_button", S.box((0.012, 0.008, 0.003), center=(c[0], c[1], h),
                                                                         R=rot((0, 0, 1), float(np.arctan2(u[1], u[0])) + np.pi / 2)),
                               M.solid((0.75, 0.1, 0.1), "plastic", 0.4)))
    return parts


@register("lectern", parts=("body", "desk"), extra_parts=("ledge", "shelf", "base", "side_panel", "microphone", "front_panel",
                                                          "windscreen", "reading_light", "plaque", "flange", "glide"),
          size_range=(1.0, 1.45), density=500, variants=("box", "pedestal", "acrylic"), placement="floor")
def lectern(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d, h = rng.uniform(0.5, 0.7), rng.uniform(0.4, 0.55), rng.uniform(1.05, 1.25)
    mat = M.wood(rng) if variant != "acrylic" else Material((0.85, 0.9, 0.95, 0.45), 0.05, 0.0, "plastic")
    t = 0.02
    tilt = np.deg2rad(rng.uniform(12, 20))
    z_desk = h - d / 2 * np.sin(tilt)
    parts = []
    if variant == "pedestal":
        parts.append(make_part("base", "base", S.box((w * 0.8, d * 0.8, 0.05), center=(0, 0, 0.025), bevel=0.01), mat))
        parts += glides((-w * 0.4 + 0.04, w * 0.4 - 0.04), (-d * 0.4 + 0.04, d * 0.4 - 0.04))
        parts.append(make_part("body", "body", S.box((0.18, 0.18, z_desk - 0.1), center=(0, 0, 0.05 + (z_desk - 0.1) / 2)), mat))
        parts.append(make_part("shelf", "shelf", S.box((w * 0.6, d * 0.5, t), center=(0, -0.02, z_desk * 0.55)), mat))
    else:
        zb = z_desk - 0.06
        parts.append(make_part("base", "base", S.box((w, d, 0.06), center=(0, 0, 0.03)), mat))
        parts += glides((-w / 2 + 0.04, w / 2 - 0.04), (-d / 2 + 0.04, d / 2 - 0.04))
        for i, s in enumerate((-1, 1)):
            parts.append(make_part(f"side_panel_{i}", "side_panel", S.box((t, d * 0.9, zb - 0.06),
                                                                           center=(s * (w / 2 - t / 2), -d * 0.05, (zb + 0.06) / 2)), mat))
        parts.append(make_part("front_panel", "front_panel", S.box((w - 2 * t, t, zb - 0.06), center=(0, d * 0.4 - t / 2, (zb + 0.06) / 2)),
                               mat))
        parts.append(make_part("body", "body", S.box((w - 2 * t, d * 0.85, t), center=(0, -d * 0.025, zb - t / 2)), mat))
        parts.append(make_part("shelf", "shelf", S.box((w - 2 * t, d * 0.8, t), center=(0, -d * 0.05, zb * 0.5)), mat))
    R = rot((1, 0, 0), tilt)
    parts.append(make_part("desk", "desk", S.box((w, d, t), center=(0, 0, z_desk), R=R), mat))
    fy, fz = d / 2 * np.cos(tilt), z_desk - d / 2 * np.sin(tilt)
    parts.append(make_part("ledge", "ledge", S.box((w, 0.015, 0.03), center=(0, fy, fz + 0.02)), mat))
    parts.append(make_part("microphone", "microphone",
                           S.tube([(w / 2 - 0.06, -d / 2 + 0.05, h + 0.005), (w / 2 - 0.06, -d / 2 + 0.05, h + 0.15),
                                   (w / 2 - 0.08, -d / 2 + 0.2, h + 0.22)], 0.005), black()))
    # the foam windscreen on the microphone's head, a gooseneck reading light on the other side
    # and the name plaque on the front
    parts.append(make_part("windscreen", "windscreen", S.ellipsoid((0.015, 0.022, 0.015), center=(w / 2 - 0.08, -d / 2 + 0.215, h + 0.225),
                                                                   subdivisions=1), M.solid((0.1, 0.1, 0.1), "fabric", 0.9)))
    parts.append(make_part("reading_light", "reading_light", [S.tube([(-w / 2 + 0.06, -d / 2 + 0.05, h + 0.005),
                                                                     (-w / 2 + 0.06, -d / 2 + 0.05, h + 0.1),
                                                                     (-w / 2 + 0.1, -d / 2 + 0.15, h + 0.14)], 0.004),
                                                             S.frustum(0.012, 0.02, 0.03, center=(-w / 2 + 0.1, -d / 2 + 0.15, h + 0.14),
                                                                       axis=(0.3, 0.3, -1.0), sections=10)], M.metal(rng)))
    # the threaded flanges the microphone's and the light's goosenecks screw into
    parts += [make_part(f"flange_{k}", "flange", S.cylinder(0.016, 0.012, center=(x, -d / 2 + 0.05, h + 0.005), sections=12),
                        M.solid((0.1, 0.1, 0.1), "metal", 0.4, 0.6))
              for k, x in enumerate((-w / 2 + 0.06, w / 2 - 0.06))]
    y_front = d * 0.4 if variant != "pedestal" else 0.09
    parts.append(make_part("plaque", "plaque", S.box((min(0.3, w * 0.5), 0.004, 0.08), center=(0, y_front + 0.002, z_desk * 0.7)),
                           M.solid((0.8, 0.65, 0.3), "metal", 0.3, 0.9)))
    return parts


@register("desk_organizer", parts=("base",), extra_parts=("divider", "pen_cup", "tray", "wall", "riser", "pad"), size_range=(0.12, 0.4),
          density=500, variants=("compartments", "trays", "pen_cups"), placement="surface")
def desk_organizer(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.wood(rng) if rng.random() < 0.5 else M.plastic(rng)
    t = 0.005
    if variant == "trays":
        w, d = rng.uniform(0.26, 0.34), rng.uniform(0.32, 0.38)
        n = int(rng.integers(2, 4))
        parts = [make_part("base", "base", S.box((w, d, t), center=(0, 0, t / 2)), mat)]
        for k in range(n):
            z = t + k * 0.07
            tray = [S.box((w, d, 0.003), center=(0, 0, z + 0.0015))]
            tray += [S.box((t, d, 0.05), center=(s * (w / 2 - t / 2), 0, z + 0.025)) for s in (-1, 1)]
            tray.append(S.box((w - 2 * t, t, 0.05), center=(0, -d / 2 + t / 2, z + 0.025)))
            parts.append(make_part(f"tray_{k}", "tray", tray, mat))
            if k:  # the two risers at the open front that carry this tray on the one below
                parts += [make_part(f"riser_{2 * (k - 1) + i}", "riser",
                                    S.box((t, 0.012, 0.02), center=(s * (w / 2 - t / 2), d / 2 - 0.006, z - 0.01)), mat)
                          for i, s in enumerate((-1, 1))]
        for i, s in enumerate((-1, 1)):
            parts.append(make_part(f"wall_{i}", "wall", S.box((0.01, 0.02, n * 0.07), center=(s * (w / 2 + 0.005), d / 2 - 0.02,
                                                                                               t + n * 0.035)), mat))
        return parts + _pads(w, d)
    w, d, h = rng.uniform(0.2, 0.32), rng.uniform(0.1, 0.15), rng.uniform(0.08, 0.12)
    parts = [make_part("base", "base", S.box((w, d, t), center=(0, 0, t / 2)), mat)]
    walls = [S.box((w, t, h), center=(0, s * (d / 2 - t / 2), h / 2)) for s in (-1, 1)]
    walls += [S.box((t, d - 2 * t, h), center=(s * (w / 2 - t / 2), 0, h / 2)) for s in (-1, 1)]
    # the four walls, each board its own
    parts += [make_part("wall" if k == 0 else f"wall_{k}", "wall", wall, mat) for k, wall in enumerate(walls)]
    if variant == "compartments":
        n = int(rng.integers(2, 5))
        for k in range(1, n):
            x = -w / 2 + w * k / n
            hh = h * (0.6 + 0.4 * (k % 2))
            parts.append(make_part(f"divider_{k - 1}", "divider", S.box((t, d - 2 * t, hh), center=(x, 0, hh / 2)), mat))
    else:
        for k in range(int(rng.integers(2, 4))):
            x = -w / 2 + 0.04 + k * 0.07
            parts.append(make_part(f"pen_cup_{k}", "pen_cup", S.vessel([(0.03, t), (0.032, t + h * 1.2)], thickness=0.006,
                                                                       piece_sections=24).moved((x, 0, 0)), M.plastic(rng)))
    return parts + _pads(w, d)


def _pads(w: float, d: float) -> list[Part]:
    """The four felt pads under a desk organizer's base, set flush into it."""
    felt = M.solid((0.15, 0.15, 0.15), "fabric", 0.9)
    return [make_part(f"pad_{k}", "pad", S.cylinder(0.006, 0.002, center=(sx * (w / 2 - 0.012), sy * (d / 2 - 0.012), 0.001), sections=8),
                      felt) for k, (sx, sy) in enumerate((sx, sy) for sx in (-1, 1) for sy in (-1, 1))]


def _file_drawer(name: str, *, x0: float, x1: float, z0: float, z1: float, y_front: float, depth: float,
                 mat: Material, handle_mat: Material, parent: str) -> list[Part | Joint]:
    """A drawer of a filing cabinet: front panel, open box, bar pull and label holder, sliding out
    on a prismatic joint (the box is the joint's child; the front is mounted on it, the pull and
    the label holder on the front)."""
    w, h = x1 - x0, z1 - z0
    cx, cz = (x0 + x1) / 2, (z0 + z1) / 2
    ft, t = 0.02, 0.01
    bw, bh = w - 0.022, h - 0.04  # 2 mm runner gap to the carcass sides
    yb = y_front - ft
    box = [S.box((bw, depth, t), center=(cx, yb - depth / 2, z0 + 0.01 + t / 2)),
           S.box((t, depth, bh), center=(cx - bw / 2 + t / 2, yb - depth / 2, z0 + 0.01 + bh / 2)),
           S.box((t, depth, bh), center=(cx + bw / 2 - t / 2, yb - depth / 2, z0 + 0.01 + bh / 2)),
           S.box((bw - 2 * t, t, bh), center=(cx, yb - depth + t / 2, z0 + 0.01 + bh / 2))]
    out: list[Part | Joint] = [
        make_part(name, "drawer", S.box((w, ft, h), center=(cx, y_front - ft / 2, cz), bevel=0.003), mat),
        make_part(f"{name}_box", "drawer_box", box, mat),
        make_part(f"{name}_handle", "handle", bar_pull((cx, y_front, cz + h * 0.15), min(0.16, w * 0.4), vertical=False),
                  handle_mat),
        make_part(f"{name}_label", "label_holder", S.box((0.08, 0.004, 0.04), center=(cx, y_front + 0.002, cz + h * 0.33)),
                  handle_mat),
        # the paper card in the holder, and the steel slide rail along each side of the box
        make_part(f"{name}_label_card", "label_card", S.box((0.07, 0.001, 0.03), center=(cx, y_front + 0.0025, cz + h * 0.33)),
                  M.solid((0.97, 0.96, 0.9), "paper", 0.8)),
        *[make_part(f"{name}_rail_{i}", "slide_rail", S.box((0.0018, depth * 0.9, min(0.03, bh * 0.5)),
                                                            center=(cx + sx * (bw / 2 + 0.001), yb - depth * 0.5, z0 + 0.01 + bh * 0.5)),
                    M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)) for i, sx in enumerate((-1, 1))],
        prismatic(f"{name}_slide", parent, f"{name}_box", travel=DRAWER_TRAVEL * depth),
        mount(f"{name}_box", name), mount(name, f"{name}_handle"), mount(name, f"{name}_label"),
        mount(f"{name}_label", f"{name}_label_card"), mount(f"{name}_box", f"{name}_rail_0"), mount(f"{name}_box", f"{name}_rail_1"),
    ]
    if bh > 0.15:  # a file drawer's follower: the plate near the back that keeps the files upright
        out += [make_part(f"{name}_follower", "follower", S.box((bw - 2 * t - 0.004, 0.003, bh * 0.6),
                                                                  center=(cx, yb - depth + t + 0.06, z0 + 0.01 + t + bh * 0.3)), M.solid((0.7, 0.7, 0.72), "metal", 0.3, 0.9)),
                mount(f"{name}_box", f"{name}_follower")]
    return out


@register("filing_cabinet", parts=("body", "drawer"), extra_parts=("drawer_box", "handle", "label_holder", "top_panel",
                                                                    "caster", "label_card", "slide_rail", "lock", "glide", "follower"),
          size_range=(0.45, 1.45), density=400, variants=("vertical", "lateral", "mobile_pedestal"))
def filing_cabinet(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    if variant == "vertical":
        w, d, h, n = rng.uniform(0.38, 0.47), rng.uniform(0.6, 0.7), rng.uniform(1.0, 1.35), 4
    elif variant == "lateral":
        w, d, h, n = rng.uniform(0.75, 0.95), rng.uniform(0.45, 0.5), rng.uniform(0.7, 1.05), int(rng.integers(2, 4))
    else:
        w, d, h, n = rng.uniform(0.38, 0.42), rng.uniform(0.5, 0.58), rng.uniform(0.55, 0.62), 3
    steel = M.solid(M.jitter(rng, [(0.55, 0.56, 0.58), (0.9, 0.9, 0.88), (0.15, 0.15, 0.16)][int(rng.integers(3))], 0.02),
                    "metal", 0.4, 0.6)
    hmat = M.metal(rng)
    t = 0.012
    z0 = 0.05 if variant == "mobile_pedestal" else 0.03
    db = d - 0.02
    body = [S.box((t, db, h - z0), center=(s * (w / 2 - t / 2), -0.01, z0 + (h - z0) / 2)) for s in (-1, 1)]
    body += [S.box((w - 2 * t, db, t), center=(0, -0.01, z0 + t / 2)),
             S.box((w - 2 * t, t, h - z0 - 2 * t), center=(0, -d / 2 + t / 2, z0 + (h - z0) / 2))]
    if variant != "mobile_pedestal":
        body.append(S.box((w - 0.02, db - 0.04, z0), center=(0, -0.01, z0 / 2)))
    parts: list[Part | Joint] = [make_part("body", "body", body, steel),
                                 make_part("top_panel", "top_panel", S.box((w, d - 0.02, t), center=(0, -0.01, h + t / 2),
                                                                           bevel=0.002), steel)]
    if variant == "mobile_pedestal":
        for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            parts.append(make_part(f"caster_{i}", "caster", S.cylinder(0.022, 0.02, center=(sx * (w / 2 - 0.04), sy * (d / 2 - 0.05),
                                                                                           0.025), axis=(1, 0, 0),
                                                                      sections=12), black()))
    yf = d / 2
    zs = np.linspace(z0 + t, h, n + 1)
    if variant == "mobile_pedestal":  # a shallow pencil drawer over two file drawers
        zs = np.array([z0 + t, z0 + t + (h - z0 - t) * 0.4, z0 + t + (h - z0 - t) * 0.8, h])
    for k in range(n):
        parts += _file_drawer(f"drawer_{k}", x0=-w / 2 + 0.003, x1=w / 2 - 0.003, z0=zs[k] + 0.002, z1=zs[k + 1] - 0.002,
                              y_front=yf, depth=db - 0.06, mat=steel, handle_mat=hmat, parent="body")
    # the key lock in the top drawer's front corner, which locks every drawer
    top = f"drawer_{n - 1}"
    parts.append(make_part("lock", "lock", S.cylinder(0.009, 0.006, center=(w / 2 - 0.04, yf + 0.003, zs[n] - 0.03), axis=(0, 1, 0),
                                                      sections=12), hmat))
    parts.append(mount(top, "lock"))
    if variant != "mobile_pedestal":  # levelling glides under the base's corners
        parts += glides((-w / 2 + 0.03, w / 2 - 0.03), (-d / 2 + 0.04, d / 2 - 0.06))
    return parts
