"""Plain seats: a chair, a stool, a bench, an ottoman and a folding chair.

Seats face +Y (a sitter looks toward +Y); the back, where there is one, is at -Y. Legs stand on
z = 0. The ``chair`` is the everyday side chair people mean when they write "chair": four legs,
a seat and a back, in wood, a moulded shell or stacking tube.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._dA_fixings import screws_under
from ._dD_detail import flush_screws, rivets_through
from ._kit import legs4, rot


def _stretchers(w: float, d: float, z: float, size: float, inset: float, mat,
                label: str = "stretcher") -> list[Part]:
    """Four bars joining four corner legs at height ``z`` (left, right, back, front)."""
    xs, ys = w / 2 - inset - size / 2, d / 2 - inset - size / 2
    bars = [S.box((size * 0.7, 2 * ys, size * 0.7), center=(-xs, 0, z)),
            S.box((size * 0.7, 2 * ys, size * 0.7), center=(xs, 0, z)),
            S.box((2 * xs, size * 0.7, size * 0.7), center=(0, -ys, z)),
            S.box((2 * xs, size * 0.7, size * 0.7), center=(0, ys, z))]
    return [make_part(f"{label}_{k}", label, b, mat) for k, b in enumerate(bars)]


def _aprons(w: float, d: float, z_top: float, leg: float, inset: float, mat, *, height: float = 0.07,
            thick: float = 0.02, blocks: bool = True) -> list[Part]:
    """The seat frame under a seat whose underside is at ``z_top``: four apron boards between the
    tops of four corner legs (``leg`` wide, ``inset`` from the edges), flush with the legs'
    outer faces, and a glued corner block inside each corner, screwed up into the seat (the
    ``screw`` heads just under the blocks)."""
    xs, ys = w / 2 - inset - leg / 2, d / 2 - inset - leg / 2
    zc = z_top - height / 2
    boards = [S.box((thick, 2 * ys - leg, height), center=(sx * (xs + leg / 2 - thick / 2), 0, zc)) for sx in (-1, 1)]
    boards += [S.box((2 * xs - leg, thick, height), center=(0, sy * (ys + leg / 2 - thick / 2), zc)) for sy in (-1, 1)]
    out = [make_part(f"apron_{k}", "apron", b, mat) for k, b in enumerate(boards)]
    if blocks:
        c = 0.045
        for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            out.append(make_part(f"corner_block_{k}", "corner_block",
                                 S.box((c, c, height * 0.6), center=(sx * (xs - leg / 2 - c / 2), sy * (ys - leg / 2 - c / 2),
                                                                     z_top - height * 0.3)), mat))
        steel = M.solid((0.55, 0.55, 0.57), "metal", 0.35, 0.9)
        for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            out.append(make_part(f"screw_{k}", "screw",
                                 S.cylinder(0.0045, 0.002, center=(sx * (xs - leg / 2 - c / 2), sy * (ys - leg / 2 - c / 2),
                                                                   z_top - height * 0.6 - 0.001), sections=8), steel))
    return out


@register("chair", parts=("seat", "back", "leg"),
          extra_parts=("stretcher", "back_post", "slat", "foot", "apron", "corner_block", "bracket", "rail", "screw"),
          size_range=(0.72, 1.0),
          density=600, variants=("wooden", "shell", "stacking"))
def chair(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.40, 0.48), rng.uniform(0.40, 0.47)
    hs = rng.uniform(0.43, 0.47)
    hb = rng.uniform(0.34, 0.44)  # back height above the seat
    out: list[Part] = []
    if variant == "wooden":
        mat = M.wood(rng)
        st, leg = 0.025, rng.uniform(0.032, 0.04)
        out.append(make_part("seat", "seat", S.box((w, d, st), center=(0, 0, hs - st / 2),
                                                   bevel=0.004), mat))
        out += legs4("leg", "leg", w=w, d=d, h=hs - st, size=leg, mat=mat, inset=0.01)
        out += _stretchers(w, d, rng.uniform(0.12, 0.18), leg, 0.01, mat)
        out += _leg_caps(w, d, leg, 0.01)
        px = w / 2 - 0.01 - leg / 2
        py = -d / 2 + 0.01 + leg / 2
        for k, sx in enumerate((-1, 1)):
            out.append(make_part(f"back_post_{k}", "back_post",
                                 S.box((leg, leg, hb), center=(sx * px, py, hs + hb / 2)), mat))
        rail = rng.uniform(0.08, 0.14)
        out.append(make_part("back", "back", S.box((2 * px - leg, leg * 0.8, rail),
                                                   center=(0, py, hs + hb - rail / 2)), mat))
        n = int(rng.integers(2, 5))
        zl = hs + 0.05
        for k in range(n):
            x = -px + leg / 2 + (2 * px - leg) * (k + 0.5) / n
            out.append(make_part(f"slat_{k}", "slat",
                                 S.box((0.018, leg * 0.5, hb - rail - 0.05),
                                       center=(x, py, zl + (hb - rail - 0.05) / 2)), mat))
        # the seat frame the seat is screwed to, and the lower back rail the slats rise from
        out += _aprons(w, d, hs - st, leg, 0.01, mat)
        out.append(make_part("rail", "rail", S.box((2 * px - leg, leg * 0.8, 0.03), center=(0, py, zl - 0.015)), mat))
        return out
    shell = variant == "shell"
    body = M.plastic(rng)
    metal = M.metal(rng)
    st = 0.012 if shell else 0.02
    r = 0.011 if shell else 0.012
    out.append(make_part("seat", "seat", S.box((w, d, st), center=(0, 0, hs - st / 2),
                                               bevel=0.004), body))
    tilt = rot((1, 0, 0), -0.12)
    back_c = (0, -d / 2 + 0.02, hs + hb / 2 + 0.02)
    out.append(make_part("back", "back", S.box((w * 0.95, st, hb * 0.8), center=back_c,
                                               bevel=0.003, R=tilt), body))
    # legs splayed a little (shell) or straight tubes (stacking)
    splay = 0.03 if shell else 0.0
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        top = np.array([sx * (w / 2 - 0.05), sy * (d / 2 - 0.05), hs - st])
        foot = top + np.array([sx * splay, sy * splay, 0.0])
        foot[2] = r
        out.append(make_part(f"leg_{k}", "leg", S.tube([foot, top], r, sections=10), metal))
        out.append(make_part(f"foot_{k}", "foot", S.cylinder(r * 1.2, 0.008,
                                                            center=(foot[0], foot[1], 0.004)),
                             M.solid((0.1, 0.1, 0.1))))
    if not shell:  # the stacking chair's back posts run from the back legs up the back
        for k, sx in enumerate((-1, 1)):
            x = sx * (w / 2 - 0.05)
            out.append(make_part(f"back_post_{k}", "back_post",
                                 S.tube([(x, -d / 2 + 0.05, hs - st), (x, -d / 2 + 0.03, hs + hb * 0.7)],
                                        r, sections=10), metal))
            # the bracket screwing the back to its post
            zb = hs + hb * 0.55
            out.append(make_part(f"bracket_{k}", "bracket",
                                 S.box((0.03, 0.012, 0.05), center=(x - sx * 0.012, -d / 2 + 0.036, zb)), metal))
    # the seat frame: a rail along each side joining the legs' tops, the leg frame's front
    # stretcher low down, and the plates the seat is screwed to over each leg
    zr = hs - st - r
    for k, sx in enumerate((-1, 1)):
        x = sx * (w / 2 - 0.05)
        out.append(make_part(f"rail_{k}", "rail", S.tube([(x, -d / 2 + 0.05, zr), (x, d / 2 - 0.05, zr)], r * 0.8,
                                                        sections=8), metal))
    ys = d / 2 - 0.05 + splay
    zs = 0.16
    xs = w / 2 - 0.05 + splay * (1 - (zs - r) / (hs - st - r))
    out.append(make_part("stretcher", "stretcher", S.tube([(-xs, ys - splay * (zs - r) / (hs - st - r), zs),
                                                           (xs, ys - splay * (zs - r) / (hs - st - r), zs)], r * 0.7,
                                                          sections=8), metal))
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        out.append(make_part(f"bracket_{k + (0 if shell else 2)}", "bracket",
                             S.box((0.05, 0.05, 0.004), center=(sx * (w / 2 - 0.05), sy * (d / 2 - 0.05), hs - st - 0.002)),
                             metal))
        # the screw up through each plate's outer corner into the seat, its head under the plate
        out.append(make_part(f"screw_{k}", "screw",
                             S.cylinder(0.0045, 0.002, center=(sx * (w / 2 - 0.035), sy * (d / 2 - 0.035), hs - st - 0.005),
                                        sections=8), metal))
    return out


@register("stool", parts=("seat", "leg"), extra_parts=("stretcher", "foot", "step", "apron", "tread", "corner_block", "screw"),
          size_range=(0.28, 0.68), density=600, variants=("round", "square", "step"))
def stool(rng: np.random.Generator, variant: str) -> list[Part]:
    mat = M.wood(rng)
    if variant == "step":  # a two-step kitchen step stool
        w, d, h = rng.uniform(0.38, 0.45), rng.uniform(0.32, 0.4), rng.uniform(0.4, 0.5)
        t = 0.022
        out = [make_part("seat", "seat", S.box((w, d * 0.55, t), center=(0, -d * 0.225, h - t / 2),
                                               bevel=0.003), mat),
               make_part("step", "step", S.box((w, d * 0.45, t),
                                               center=(0, d * 0.275, h * 0.5 - t / 2),
                                               bevel=0.003), mat)]
        for k, sx in enumerate((-1, 1)):
            out.append(make_part(f"leg_{k}", "leg", S.box((t, d, h - t), center=(sx * (w / 2 - t / 2),
                                                                                0, (h - t) / 2)),
                                 mat))
        # rubber treads on the step and the top, and rubber shoes on the side boards' ends
        rubber = M.solid((0.1, 0.1, 0.1), "rubber", 0.9)
        out.append(make_part("tread_0", "tread", S.box((w - 2 * t - 0.02, d * 0.3, 0.002),
                                                       center=(0, d * 0.275, h * 0.5 + 0.001)), rubber))
        out.append(make_part("tread_1", "tread", S.box((w - 2 * t - 0.02, d * 0.35, 0.002),
                                                       center=(0, -d * 0.225, h + 0.001)), rubber))
        for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            out.append(make_part(f"foot_{k}", "foot", S.box((t + 0.004, 0.04, 0.012),
                                                             center=(sx * (w / 2 - t / 2), sy * (d / 2 - 0.02), 0.006)),
                                 rubber))
        # the back rail under the top and the kick rail under the step, housed in the side boards
        out.append(make_part("stretcher_0", "stretcher", S.box((w - 2 * t, t, 0.06), center=(0, -d / 2 + t / 2, h - t - 0.03)), mat))
        out.append(make_part("stretcher_1", "stretcher", S.box((w - 2 * t, t, 0.05),
                                                               center=(0, d / 2 - t / 2, h * 0.5 - t - 0.025)), mat))
        return out
    h = rng.uniform(0.42, 0.6)
    st = 0.03
    if variant == "round":
        r = rng.uniform(0.15, 0.18)
        seat = S.cylinder(r, st, center=(0, 0, h - st / 2), sections=28)
        w = d = r * 1.4
    else:
        w = d = rng.uniform(0.3, 0.36)
        seat = S.box((w, d, st), center=(0, 0, h - st / 2), bevel=0.004)
    out = [make_part("seat", "seat", seat, mat)]
    leg = 0.03
    out += legs4("leg", "leg", w=w, d=d, h=h - st, size=leg, mat=mat, round_=variant == "round")
    out += _stretchers(w, d, h * 0.3, leg, 0.0, mat)
    out += _leg_caps(w, d, leg, 0.0)
    if variant == "square":  # the aprons under the seat, between the legs' tops
        out += _stretchers(w, d, h - st - 0.03, leg, 0.0, mat, label="apron")
    else:  # a round seat sits on a square frame of aprons, glued blocks in its corners
        out += _aprons(w, d, h - st, leg, 0.0, mat, height=0.05)
    return out


def _leg_caps(w: float, d: float, size: float, inset: float) -> list[Part]:
    """Plastic caps round the foot of four corner legs (the legs still reach the floor)."""
    cap = M.solid((0.1, 0.1, 0.1), "plastic", 0.7)
    xs, ys = w / 2 - inset - size / 2, d / 2 - inset - size / 2
    return [make_part(f"foot_{k}", "foot", S.cylinder(size * 0.62, 0.01, center=(sx * xs, sy * ys, 0.005), sections=10), cap)
            for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)])]


@register("bench", parts=("seat", "leg"), extra_parts=("rail", "back", "armrest", "frame", "stretcher", "foot", "button",
                                                    "screw", "piping", "corner_block", "dust_cover"),
          size_range=(0.9, 1.9), density=550, variants=("slatted", "park", "upholstered"))
def bench(rng: np.random.Generator, variant: str) -> list[Part]:
    """The seat is what one sits on: the slats of a slatted or park bench (on two rails), the
    padded top of an upholstered one (on its frame)."""
    w, d = rng.uniform(1.0, 1.8), rng.uniform(0.32, 0.45)
    hs = rng.uniform(0.42, 0.47)
    wood, metal = M.wood(rng), M.metal(rng)
    out: list[Part] = []
    t = 0.03
    if variant == "upholstered":
        out.append(make_part("frame", "frame", S.box((w, d, 0.04), center=(0, 0, hs - 0.1),
                                                     bevel=0.004), wood))
        out.append(make_part("seat", "seat", S.box((w - 0.02, d - 0.02, 0.06),
                                                   center=(0, 0, hs - 0.03), bevel=0.015),
                             M.fabric(rng)))
        out += legs4("leg", "leg", w=w, d=d, h=hs - 0.12, size=0.045, mat=wood, inset=0.03)
        out += _leg_caps(w, d, 0.045, 0.03)
        # the tufting buttons along the padded top
        n_b = max(2, int(w / 0.3))
        for k in range(n_b):
            out.append(make_part(f"button_{k}", "button", S.cylinder(0.012, 0.006, center=(-w / 2 + w * (k + 0.5) / n_b, 0, hs - 0.002),
                                                                     sections=10), M.fabric(rng)))
        # the piping round the pad's lower seam, the frame's corner blocks under it, and the
        # dust cover stapled under the frame
        zp = hs - 0.055
        pipe = [S.box((w - 0.012, 0.008, 0.01), center=(0, sy * (d / 2 - 0.012), zp)) for sy in (-1, 1)]
        pipe += [S.box((0.008, d - 0.032, 0.01), center=(sx * (w / 2 - 0.012), 0, zp)) for sx in (-1, 1)]
        out.append(make_part("piping", "piping", pipe, out[1].material))
        c = 0.06
        for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
            out.append(make_part(f"corner_block_{k}", "corner_block",
                                 S.box((c, c, 0.03), center=(sx * (w / 2 - 0.075 - c / 2), sy * (d / 2 - 0.075 - c / 2), hs - 0.135)),
                                 wood))
        out.append(make_part("dust_cover", "dust_cover", S.box((w - 0.02, d - 0.02, 0.002), center=(0, 0, hs - 0.119)),
                             M.solid((0.06, 0.06, 0.07), "fabric", 0.9)))
        # each corner block is screwed up into the frame (heads under the blocks)
        return out + screws_under(out, "corner_block")
    n = int(rng.integers(3, 6))
    gap = 0.012
    sw = (d - gap * (n - 1)) / n
    for k in range(n):
        y = -d / 2 + sw / 2 + k * (sw + gap)
        out.append(make_part(f"seat_{k}", "seat", S.box((w, sw, t), center=(0, y, hs - t / 2),
                                                        bevel=0.003), wood))
    # two rails along the length carry the slats, each slat screwed down to both
    for k, sy in enumerate((-1, 1)):
        out.append(make_part("rail" if k == 0 else "rail_1", "rail",
                             S.box((w - 0.1, 0.03, 0.05), center=(0, sy * (d / 2 - 0.05), hs - t - 0.025)),
                             wood if variant == "slatted" else metal))
    steel = M.solid((0.55, 0.55, 0.57), "metal", 0.4, 0.9)
    for k in range(n):
        y = -d / 2 + sw / 2 + k * (sw + gap)
        for j, sx in enumerate((-1, 1)):
            out.append(make_part(f"screw_{2 * k + j}", "screw",
                                 S.cylinder(0.005, 0.003, center=(sx * (w / 2 - 0.08), y, hs - 0.0016), sections=8), steel))
    legmat = wood if variant == "slatted" else metal
    out += legs4("leg", "leg", w=w - 0.1, d=d, h=hs - t - 0.05, size=0.045, mat=legmat, inset=0.0)
    out += _leg_caps(w - 0.1, d, 0.045, 0.0)
    # the stretchers joining each end's pair of legs, low down
    for k, sx in enumerate((-1, 1)):
        out.append(make_part(f"stretcher_{k}", "stretcher", S.box((0.03, d - 0.09, 0.03),
                                                                 center=(sx * ((w - 0.1) / 2 - 0.0225), 0, 0.12)), legmat))
    if variant == "park":
        hb = rng.uniform(0.35, 0.45)
        back = [S.box((w, 0.025, 0.08), center=(0, -d / 2 - 0.03, hs + z), bevel=0.003)
                for z in (hb * 0.35, hb * 0.75)]
        out.append(make_part("back", "back", back, wood))
        for k, sx in enumerate((-1, 1)):
            x = sx * (w / 2 - 0.05)
            out.append(make_part(f"armrest_{k}", "armrest",
                                 [S.tube([(x, -d / 2 - 0.03, hs + 0.2), (x, d / 2 - 0.04, hs + 0.2)],
                                         0.012, sections=10),
                                  S.tube([(x, d / 2 - 0.04, hs + 0.2), (x, d / 2 - 0.04, hs)],
                                         0.012, sections=10)], metal))
    return out


@register("ottoman", parts=("body", "cushion"), extra_parts=("foot", "button", "piping", "glide", "handle", "dust_cover", "plate"),
          size_range=(0.35, 1.0), density=300, variants=("cube", "round", "tufted"))
def ottoman(rng: np.random.Generator, variant: str) -> list[Part]:
    h = rng.uniform(0.38, 0.46)
    fab = M.fabric(rng)
    foot_h = 0.04 if variant != "round" else 0.0
    top = 0.08
    if variant == "round":
        r = rng.uniform(0.2, 0.3)
        body = S.cylinder(r, h - top, center=(0, 0, (h - top) / 2), sections=28)
        cush = S.cylinder(r, top, center=(0, 0, h - top / 2), sections=28)
        out = [make_part("body", "body", body, fab), make_part("cushion", "cushion", cush, fab)]
        out.append(make_part("piping", "piping", S.cylinder(r + 0.006, 0.012,
                                                           center=(0, 0, h - top), sections=28), fab))
        # the piping round the bottom seam, and the button in the cushion's centre
        out.append(make_part("piping_1", "piping", S.cylinder(r + 0.006, 0.012, center=(0, 0, 0.006), sections=28), fab))
        out.append(make_part("button", "button", S.cylinder(0.014, 0.008, center=(0, 0, h - 0.003), sections=10), fab))
        # the carrying loop sewn to the side
        out.append(make_part("handle", "handle", S.tube([(r, -0.04, h * 0.55), (r + 0.02, -0.03, h * 0.55), (r + 0.02, 0.03, h * 0.55),
                                                         (r, 0.04, h * 0.55)], 0.006, sections=6), fab))
        out += _underside(0.0, [(r * 0.6 * np.cos(a), r * 0.6 * np.sin(a)) for a in np.arange(4) * np.pi / 2 + np.pi / 4],
                          S.cylinder(r - 0.02, 0.002, center=(0, 0, 0.001), sections=20))
        return out
    w = rng.uniform(0.42, 0.95)
    d = min(w, rng.uniform(0.42, 0.6))
    out = [make_part("body", "body", S.box((w, d, h - top - foot_h),
                                           center=(0, 0, foot_h + (h - top - foot_h) / 2),
                                           bevel=0.01), fab),
           make_part("cushion", "cushion", S.box((w, d, top), center=(0, 0, h - top / 2),
                                                 bevel=0.02), fab)]
    wood = M.wood(rng)
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        out.append(make_part(f"foot_{k}", "foot",
                             S.cylinder(0.02, foot_h, center=(sx * (w / 2 - 0.05), sy * (d / 2 - 0.05),
                                                             foot_h / 2), sections=12), wood))
        # the steel mounting plate screwed under the frame that the foot's hanger bolt threads into
        out.append(make_part(f"plate_{k}", "plate", S.box((0.06, 0.06, 0.002), center=(sx * (w / 2 - 0.05), sy * (d / 2 - 0.05), foot_h - 0.001)),
                             M.solid((0.55, 0.55, 0.57), "metal", 0.35, 0.9)))
    # the piping along the cushion's bottom seam
    zp = h - top
    pipe = [S.box((w + 0.008, 0.008, 0.012), center=(0, sy * (d / 2 + 0.002), zp)) for sy in (-1, 1)]
    pipe += [S.box((0.008, d, 0.012), center=(sx * (w / 2 + 0.002), 0, zp)) for sx in (-1, 1)]
    out.append(make_part("piping", "piping", pipe, fab))
    # the piping round the body's bottom seam, above the feet
    pipe = [S.box((w + 0.008, 0.008, 0.012), center=(0, sy * (d / 2 + 0.002), foot_h + 0.006)) for sy in (-1, 1)]
    pipe += [S.box((0.008, d, 0.012), center=(sx * (w / 2 + 0.002), 0, foot_h + 0.006)) for sx in (-1, 1)]
    out.append(make_part("piping_1", "piping", pipe, fab))
    out += _underside(foot_h, [(sx * (w / 2 - 0.05), sy * (d / 2 - 0.05)) for sx, sy in [(-1, -1), (1, -1), (-1, 1), (1, 1)]],
                      S.box((w - 0.04, d - 0.04, 0.002), center=(0, 0, foot_h + 0.001)))
    if variant == "tufted":
        for i in range(3):
            for j in range(2):
                x, y = (i - 1) * w / 4, (j - 0.5) * d / 2.5
                out.append(make_part(f"button_{i}_{j}", "button",
                                     S.cylinder(0.012, 0.008, center=(x, y, h - 0.003),
                                                sections=10), fab))
    return out


def _underside(z: float, xy, cloth: S.Shape) -> list[Part]:
    """What is under an upholstered seat standing at height ``z``: the black dust cover stapled
    over the frame's bottom, and a nail-in glide under each foot at ``xy`` (or under the frame
    where there are no feet), set into the wood so the seat stands as before."""
    black = M.solid((0.06, 0.06, 0.07), "fabric", 0.9)
    nylon = M.solid((0.85, 0.85, 0.82), "plastic", 0.4)
    out = [make_part("dust_cover", "dust_cover", cloth, black)]
    out += [make_part(f"glide_{k}", "glide", S.cylinder(0.012, 0.005, center=(x, y, 0.0025), sections=10), nylon)
            for k, (x, y) in enumerate(xy)]
    return out


@register("folding_chair", parts=("seat", "back", "leg"), extra_parts=("crossbar", "foot", "pivot", "rail", "link", "rivet", "screw"),
          size_range=(0.72, 0.95), density=700, variants=("open", "folded"))
def folding_chair(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.42, 0.46)
    hs, hb = rng.uniform(0.43, 0.46), rng.uniform(0.36, 0.42)
    metal, body = M.metal(rng), M.plastic(rng)
    r = 0.011
    out: list[Part] = []
    if variant == "folded":  # seat swung up against the back: a flat frame standing upright
        depth = 0.06
        for k, sx in enumerate((-1, 1)):
            x = sx * (w / 2 - r)
            out.append(make_part(f"leg_{k}", "leg", S.tube([(x, 0, r), (x, 0, hs + hb)], r,
                                                           sections=10), metal))
            out.append(make_part(f"leg_{k + 2}", "leg", S.tube([(x * 0.9, depth - r, r),
                                                               (x * 0.9, depth - r, hs + 0.05)],
                                                              r, sections=10), metal))
        out.append(make_part("back", "back", S.box((w - 4 * r, 0.012, hb * 0.45),
                                                   center=(0, 0.0, hs + hb * 0.7)), body))
        out.append(make_part("seat", "seat", S.box((w * 0.9 - 4 * r, 0.012, 0.4),
                                                   center=(0, depth / 2, hs * 0.55)), body))
        out.append(make_part("crossbar", "crossbar", S.tube([(-w / 2 + r, 0, 0.15),
                                                             (w / 2 - r, 0, 0.15)], r * 0.8),
                             metal))
        out += _tube_feet([(sx * (w / 2 - r), 0.0) for sx in (-1, 1)] + [(sx * 0.9 * (w / 2 - r), depth - r) for sx in (-1, 1)], r)
        # the front legs' own crossbar, and the rivets the front legs pivot on
        out.append(make_part("crossbar_1", "crossbar", S.tube([(-w * 0.45 + r, depth - r, 0.12),
                                                               (w * 0.45 - r, depth - r, 0.12)], r * 0.8), metal))
        for k, sx in enumerate((-1, 1)):
            out.append(make_part(f"pivot_{k}", "pivot", S.cylinder(0.006, 0.006, center=(sx * (w / 2 - r), r + 0.003, hs),
                                                                   axis=(0, 1, 0), sections=8), metal))
        out += _back_rivets(w, 0.0, hs, hb, r)
        return out
    d = rng.uniform(0.4, 0.45)
    out.append(make_part("seat", "seat", S.box((w - 4 * r, d, 0.015), center=(0, 0, hs - 0.0075),
                                               bevel=0.003), body))
    for k, sx in enumerate((-1, 1)):
        x = sx * (w / 2 - r)
        # the back legs rise into the back posts; the front legs run to the back's foot
        out.append(make_part(f"leg_{k}", "leg", S.tube([(x, -d / 2, r), (x, -d / 2 + 0.02, hs + hb)],
                                                       r, sections=10), metal))
        out.append(make_part(f"leg_{k + 2}", "leg", S.tube([(x * 0.93, d / 2 - 0.02, r),
                                                           (x * 0.93, -d / 2 + 0.1, hs - 0.02)],
                                                          r, sections=10), metal))
    out.append(make_part("back", "back", S.box((w - 4 * r, 0.012, hb * 0.45),
                                               center=(0, -d / 2 + 0.02, hs + hb * 0.7)), body))
    out.append(make_part("crossbar", "crossbar", S.tube([(-w / 2 + r, -d / 2 + 0.01, 0.2),
                                                         (w / 2 - r, -d / 2 + 0.01, 0.2)], r * 0.8),
                         metal))
    out += _tube_feet([(sx * (w / 2 - r), -d / 2) for sx in (-1, 1)] + [(sx * 0.93 * (w / 2 - r), d / 2 - 0.02) for sx in (-1, 1)], r)
    # the rivets the seat pivots on, where it meets the back legs
    for k, sx in enumerate((-1, 1)):
        out.append(make_part(f"pivot_{k}", "pivot", S.cylinder(0.006, 0.006, center=(sx * (w / 2 - r - r - 0.003), -d / 2 + 0.015, hs - 0.02),
                                                               axis=(1, 0, 0), sections=8), metal))
    # the seat's side rails it pivots with, the links tying them to the front legs, and the
    # front legs' own crossbar low down
    zr = hs - 0.015 - r * 0.8
    for k, sx in enumerate((-1, 1)):
        x = sx * (w / 2 - 2 * r - 0.004)
        out.append(make_part(f"rail_{k}", "rail", S.tube([(x, -d / 2 + 0.02, zr), (x, d / 2 - 0.03, zr)], r * 0.8,
                                                        sections=8), metal))
        out.append(make_part(f"link_{k}", "link", S.box((0.004, 0.09, 0.018), center=(x * 0.96, -d / 2 + 0.1, hs - 0.06),
                                                        R=rot((1, 0, 0), 0.6)), metal))
    out += _back_rivets(w, -d / 2 + 0.02, hs, hb, r)
    # the four screws up through the side rails into the seat's underside, near each end
    out += flush_screws("screw", [(sx * (w / 2 - 2 * r - 0.004), y, zr - r * 0.8) for sx in (-1, 1)
                                  for y in (-d / 2 + 0.05, d / 2 - 0.06)], axis=(0, 0, -1), radius=0.0035)
    xc = 0.93 * (w / 2 - r)
    out.append(make_part("crossbar_1", "crossbar", S.tube([(-xc, d / 2 - 0.045, 0.14), (xc, d / 2 - 0.045, 0.14)], r * 0.8),
                         metal))
    return out


def _back_rivets(w: float, y: float, hs: float, hb: float, r: float) -> list[Part]:
    """The four rivets through the back posts into the back panel's ends, two a side, their
    heads flush with the posts' outer faces."""
    zs = (hs + hb * 0.7 - hb * 0.14, hs + hb * 0.7 + hb * 0.14)
    return rivets_through("rivet", [(sx * (w / 2 - r), y, z) for sx in (-1, 1) for z in zs], length=2 * r,
                          axis=(1, 0, 0), radius=0.003)


def _tube_feet(xy, r: float) -> list[Part]:
    """Plastic caps on the ends of tube legs standing at ``xy`` (the legs still reach the floor)."""
    cap = M.solid((0.1, 0.1, 0.1), "plastic", 0.7)
    return [make_part(f"foot_{k}", "foot", S.cylinder(r * 1.3, 0.012, center=(x, y, 0.006), sections=10), cap)
            for k, (x, y) in enumerate(xy)]
