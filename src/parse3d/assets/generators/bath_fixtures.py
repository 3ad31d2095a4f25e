"""Bathroom fixtures: shower enclosures.

A corner shower stands on its ``base`` (the tray), its tiled ``wall_panel``s at the back (-Y)
and on the right (+X) go against the room's walls, the ``glass`` screen and the ``door`` close
the front and the left. A ``niche`` shelf in the back panel holds bottles
(``ON shower:niche``); the ``shower_head`` hangs from its ``arm`` over the tray, the ``mixer``
below it. The door slides along the front (``corner_slider``) or swings out on hinges
(``hinged``); a ``walk_in`` has one fixed screen and no door.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Material, Part, make_part
from ..registry import register
from ._detail_b import ring_points, studs
from ._kit import hinge_parts, mount, prismatic, revolute


@register("shower", parts=("base", "wall_panel", "glass"),
          extra_parts=("door", "handle", "shower_head", "arm", "mixer", "drain", "niche", "hinge", "track", "clamp", "sweep",
                       "flange", "trim_plate", "wall_channel", "support_bar", "nozzle", "roller"),
          size_range=(1.9, 2.3), density=300, variants=("corner_slider", "hinged", "walk_in"),
          placement="floor")
def shower(rng: np.random.Generator, variant: str) -> list[Part | Joint]:
    w, d = rng.uniform(0.8, 1.0), rng.uniform(0.8, 1.0)
    if variant == "walk_in":
        w = rng.uniform(1.1, 1.4)
    H = rng.uniform(1.95, 2.1)
    tb = rng.uniform(0.04, 0.06)
    tile = Material(M.jitter(rng, [(0.92, 0.92, 0.9), (0.7, 0.75, 0.78), (0.35, 0.38, 0.4)][int(rng.integers(3))],
                             0.02), 0.3, 0.0, "ceramic")
    chrome = Material((0.88, 0.88, 0.9, 1.0), 0.08, 1.0, "metal")
    glass = M.glass(rng)
    tp = 0.04  # wall panel thickness
    parts: list[Part | Joint] = [make_part("base", "base", S.box((w, d, tb), center=(0, 0, tb / 2), bevel=0.006),
                                           Material((0.95, 0.95, 0.94, 1.0), 0.2, 0.0, "ceramic"))]
    parts.append(make_part("drain", "drain", S.cylinder(0.045, 0.002, center=(0, 0, tb + 0.0005), sections=16), chrome))
    parts.append(make_part("wall_panel_0", "wall_panel", S.box((w, tp, H - tb), center=(0, -d / 2 + tp / 2, (H + tb) / 2)),
                           tile))
    parts.append(make_part("wall_panel_1", "wall_panel",
                           S.box((tp, d - tp, H - tb), center=(w / 2 - tp / 2, tp / 2, (H + tb) / 2)), tile))
    # a niche shelf set into the back panel
    zn = rng.uniform(1.1, 1.3)
    nw = min(0.4, w * 0.4)
    niche = [S.box((nw, 0.1, 0.02), center=(0, -d / 2 + tp + 0.05 - 0.001, zn)),
             S.box((nw, 0.1, 0.02), center=(0, -d / 2 + tp + 0.05 - 0.001, zn + 0.3)),
             S.box((0.02, 0.1, 0.28), center=(-nw / 2 + 0.01, -d / 2 + tp + 0.05 - 0.001, zn + 0.15)),
             S.box((0.02, 0.1, 0.28), center=(nw / 2 - 0.01, -d / 2 + tp + 0.05 - 0.001, zn + 0.15))]
    parts.append(make_part("niche", "niche", niche, tile))
    # shower head on an arm from the right-hand panel, the mixer below
    xs = w / 2 - tp
    zh = H - rng.uniform(0.05, 0.15)
    parts.append(make_part("arm", "arm", S.tube([(xs - 0.005, -d * 0.1, zh), (xs - 0.25, -d * 0.1, zh)], 0.01, sections=8),
                           chrome))
    parts.append(make_part("shower_head", "shower_head", S.cylinder(0.1, 0.012, center=(xs - 0.3, -d * 0.1, zh - 0.016),
                                                                   sections=24), chrome))
    # the rubber nozzles on the head's face: a ring of six round the centre one
    face = (xs - 0.3, -d * 0.1, zh - 0.022)
    parts += studs("nozzle", "nozzle", np.vstack([ring_points(6, 0.05, center=face), [face]]), r=0.0035, h=0.003,
                   mat=Material((0.1, 0.1, 0.1, 1.0), 0.8, 0.0, "rubber"), sections=8)
    mixer = [S.cylinder(0.035, 0.02, center=(xs - 0.01, -d * 0.1, 1.1), axis=(1, 0, 0), sections=16),
             S.box((0.02, 0.08, 0.015), center=(xs - 0.035, -d * 0.1, 1.1))]
    parts.append(make_part("mixer", "mixer", mixer, chrome))
    # the round flange where the arm leaves the wall, the square trim plate behind the mixer,
    # and the aluminium channel holding the side screen's back edge against the wall
    parts.append(make_part("flange", "flange", S.cylinder(0.03, 0.008, center=(xs - 0.004, -d * 0.1, zh), axis=(1, 0, 0), sections=16), chrome))
    parts.append(make_part("trim_plate", "trim_plate", S.box((0.004, 0.14, 0.14), center=(xs - 0.002, -d * 0.1, 1.1), bevel=0.001), chrome))
    parts.append(make_part("wall_channel", "wall_channel", S.box((0.02, 0.012, H - tb - 0.02),
                                                                 center=(-w / 2 + 0.013, -d / 2 + tp + 0.006, (H + tb) / 2)), chrome))
    # the glass: a left screen along the side, then the front
    tg = 0.008
    xl = -w / 2 + tg / 2 + 0.005
    parts.append(make_part("glass_0", "glass", S.box((tg, d - tp - 0.01, H - tb - 0.01),
                                                      center=(xl, tp / 2, (H + tb) / 2)), glass))
    yf = d / 2 - tg / 2 - 0.005
    # the two clamps holding the side screen to the back wall panel
    for k, z in enumerate((tb + 0.3, H - 0.3)):
        parts.append(make_part(f"clamp_{k}", "clamp", S.box((0.03, 0.04, 0.05), center=(xl, -d / 2 + tp + 0.02, z), bevel=0.004), chrome))
    if variant == "walk_in":
        parts.append(make_part("glass_1", "glass", S.box((w * 0.45, tg, H - tb - 0.01),
                                                          center=(-w / 2 + w * 0.225 + 0.01, yf, (H + tb) / 2)), glass))
        # the stabiliser bar from the front screen's top edge back to the side screen
        parts.append(make_part("support_bar", "support_bar", S.cylinder(0.009, d - tp - 0.03, center=(-w / 2 + w * 0.3, tp / 2, H - 0.03),
                                                                        axis=(0, 1, 0), sections=10), chrome))
        return parts
    xg0 = -w / 2 + 0.01
    if variant == "corner_slider":
        gw = (w - tp) * 0.52
        parts.append(make_part("glass_1", "glass", S.box((gw, tg, H - tb - 0.06),
                                                          center=(xg0 + gw / 2, yf - tg, (H + tb) / 2 - 0.02)), glass))
        track = S.box((w - tp - 0.01, 0.03, 0.025), center=(-tp / 2, yf - 0.005, H - 0.0125))
        parts.append(make_part("track", "track", track, chrome))
        dw = (w - tp) * 0.52
        xd1 = w / 2 - tp - 0.005
        door = S.box((dw, tg, H - tb - 0.06), center=(xd1 - dw / 2, yf + 0.004, (H + tb) / 2 - 0.02))
        parts.append(make_part("door", "door", door, glass))
        handle = S.tube([(xd1 - dw + 0.05, yf + 0.008, 1.0), (xd1 - dw + 0.05, yf + 0.04, 1.0),
                         (xd1 - dw + 0.05, yf + 0.04, 1.3), (xd1 - dw + 0.05, yf + 0.008, 1.3)], 0.01, sections=8)
        parts.append(make_part("handle", "handle", handle, chrome))
        # the two rollers on the door's top edge that run in the track
        for k, sx in enumerate((-1, 1)):
            parts.append(make_part(f"roller_{k}", "roller", S.cylinder(0.012, 0.008, center=(xd1 - dw / 2 + sx * dw * 0.35, yf + 0.004, H - 0.037),
                                                                      axis=(0, 1, 0), sections=10), chrome))
        parts += [prismatic("door_slide", "track", "door", travel=dw * 0.85, axis=(-1, 0, 0)),
                  mount("door", "handle"), mount("door", "roller_0"), mount("door", "roller_1")]
        return parts
    # hinged: a fixed panel on the right of the front, the door hinged on the left edge
    fw = (w - tp) * 0.35
    parts.append(make_part("glass_1", "glass", S.box((fw, tg, H - tb - 0.01),
                                                      center=(w / 2 - tp - fw / 2, yf, (H + tb) / 2)), glass))
    dw = w - tp - fw - 0.03
    xd0 = xl + tg / 2 + 0.004
    door = S.box((dw, tg, H - tb - 0.05), center=(xd0 + dw / 2, yf, (H + tb) / 2 - 0.015))
    parts.append(make_part("door", "door", door, glass))
    handle = S.tube([(xd0 + dw - 0.05, yf + 0.004, 1.0), (xd0 + dw - 0.05, yf + 0.04, 1.0),
                     (xd0 + dw - 0.05, yf + 0.04, 1.25), (xd0 + dw - 0.05, yf + 0.004, 1.25)], 0.01, sections=8)
    parts.append(make_part("handle", "handle", handle, chrome))
    parts += hinge_parts("door_hinge", x=xd0 - 0.002, y=yf, z0=tb + 0.1, z1=H - 0.1, mat=chrome, radius=0.012,
                         length=0.06)
    # the sweep seal along the door's bottom edge (it swings with the door)
    parts.append(make_part("sweep", "sweep", S.box((dw - 0.02, 0.016, 0.012), center=(xd0 + dw / 2, yf, tb + 0.01)),
                           Material((0.85, 0.88, 0.9, 0.6), 0.3, 0.0, "plastic")))
    parts += [revolute("door_hinge", "glass_0", "door", axis=(0, 0, 1), origin=(xd0 - 0.002, yf, tb),
                       opens=1.4),
              mount("door", "handle"), mount("door", "sweep")]
    return parts
