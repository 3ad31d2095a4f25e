"""Assorted objects people name in rooms: stationery, kitchen tools and food, music gear,
workshop tools, clothes and bags, lights and decor, pet and game things, and a few room pieces
(a window unit, a fireplace).

Compact generators: each has several labelled parts, built from boxes, cylinders and hulls in
the canonical frame (front +Y, standing or lying on z = 0; long thin things lie along X).
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Joint, Part, make_part
from ..registry import register
from ._casework import black, white
from ._detail_b import each
from ._household import ring, shell
from ._kit import rot


def _b(name, label, size, center, mat, bevel=0.0, R=None) -> Part:
    return make_part(name, label, S.box(size, center=center, bevel=bevel, R=R), mat)


def _c(name, label, r, h, center, mat, axis=(0, 0, 1), sections=20) -> Part:
    return make_part(name, label, S.cylinder(r, h, center=center, axis=axis, sections=sections), mat)


def _colour(rng, name="plastic"):
    return M.solid(M.jitter(rng, (0.5, 0.5, 0.5), 0.35)[:3], name, 0.5)


# ------------------------------------------------------------------ stationery and desk things


@register("brochure_holder", parts=("base", "pocket"), extra_parts=("brochure", "back_panel", "foot", "side"), size_range=(0.15, 0.35), density=1200,
          variants=("single", "tiered", "wide"), placement="surface")
def brochure_holder(rng: np.random.Generator, variant: str) -> list[Part]:
    n = 3 if variant == "tiered" else 1
    w = 0.3 if variant == "wide" else 0.16
    clear = M.glass(rng)
    out = [_b("base", "base", (w, 0.08 * n + 0.02, 0.008), (0, 0, 0.004), clear)]
    for k in range(n):
        y = -0.04 * (n - 1) + 0.08 * k
        z = 0.06 + 0.05 * (n - 1 - k)
        out.append(_b(f"pocket_{k}", "pocket", (w, 0.004, z), (0, y + 0.03, 0.008 + z / 2), clear))
        out.append(_b(f"brochure_{k}", "brochure", (w * 0.7, 0.006, z + 0.08), (0, y + 0.02, 0.008 + (z + 0.08) / 2), M.paper(rng)))
        # the pocket's two side walls that keep the brochures from sliding out sideways
        for j, sx in enumerate((-1, 1)):
            out.append(_b(f"side_{2 * k + j}", "side", (0.004, 0.034, z * 0.8), (sx * (w / 2 - 0.002), y + 0.011, 0.008 + z * 0.4), clear))
    # the back panel the brochures lean on, and clear bumpers let into the base's underside
    yb = -0.04 * (n - 1) + 0.004
    zb = 0.06 + 0.05 * (n - 1) + 0.06
    out.append(_b("back_panel", "back_panel", (w, 0.004, zb), (0, yb, 0.008 + zb / 2), clear))
    d = 0.08 * n + 0.02
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        out.append(_c(f"foot_{k}", "foot", 0.005, 0.002, (sx * (w / 2 - 0.01), sy * (d / 2 - 0.01), 0.001),
                      M.solid((0.9, 0.9, 0.9), "rubber", 0.5), sections=8))
    return out


# ------------------------------------------------------------------------------- music gear


@register("cello", parts=("body", "neck", "scroll"),
          extra_parts=("endpin", "string", "bridge", "fingerboard", "tailpiece", "peg", "f_hole"),
          size_range=(1.15, 1.5), density=400, variants=("upright", "on_stand", "lying"))
def cello(rng: np.random.Generator, variant: str) -> list[Part]:
    # standing on its endpin, front (strings) toward +Y
    L = rng.uniform(0.74, 0.78)
    pin = rng.uniform(0.2, 0.3)
    wl, d = rng.uniform(0.42, 0.46), rng.uniform(0.2, 0.24)
    wood = M.wood(rng)
    z0 = pin
    pts = []
    for z, hw in ((0.0, wl * 0.35), (0.15, wl / 2), (0.35, wl * 0.32), (0.55, wl * 0.43), (L, wl * 0.2)):
        for sx in (-1, 1):
            for sy in (-1, 1):
                pts.append([sx * hw, sy * d / 2, z0 + z])
    out = [make_part("body", "body", S.hull(np.array(pts)), wood),
           _c("endpin", "endpin", 0.006, pin, (0, 0, pin / 2), M.metal(rng), sections=8),
           _b("neck", "neck", (0.04, 0.04, 0.32), (0, d / 2 - 0.02, z0 + L + 0.16), wood),
           _b("fingerboard", "fingerboard", (0.05, 0.01, 0.5), (0, d / 2 + 0.005, z0 + L * 0.8 + 0.1), black("wood")),
           make_part("scroll", "scroll", S.ellipsoid((0.025, 0.04, 0.06), center=(0, d / 2 - 0.02, z0 + L + 0.32 + 0.05)), wood),
           _b("bridge", "bridge", (0.08, 0.01, 0.06), (0, d / 2 + 0.005, z0 + L * 0.35), M.wood(rng))]
    steel = M.metal(rng)
    out += [_b(f"string_{k}", "string", (0.0015, 0.0015, L * 0.75), (x, d / 2 + 0.014, z0 + L * 0.55), steel)
            for k, x in enumerate((-0.012, -0.004, 0.004, 0.012))]
    # the tailpiece the strings hang from, the two f-holes, the four pegs through the pegbox
    ebony = black("wood")
    out.append(make_part("tailpiece", "tailpiece", S.hull(np.array(
        [[sx * hw, y, z0 + z] for sx in (-1, 1) for y in (d / 2, d / 2 + 0.012)
         for hw, z in ((0.012, L * 0.08), (0.03, L * 0.25))])), ebony))
    for k, sx in enumerate((-1, 1)):
        out.append(_b(f"f_hole_{k}", "f_hole", (0.012, 0.002, 0.1), (sx * wl * 0.2, d / 2 + 0.001, z0 + L * 0.4), ebony,
                      R=rot((0, 1, 0), sx * 0.12)))
    for k in range(4):
        sx = -1 if k % 2 == 0 else 1
        zp = z0 + L + 0.27 - (k // 2) * 0.035 - (k % 2) * 0.017
        out.append(_c(f"peg_{k}", "peg", 0.006, 0.05, (sx * 0.035, d / 2 - 0.02, zp), ebony, axis=(1, 0, 0), sections=8))
    return out


@register("drum", parts=("shell", "head"), extra_parts=("rim", "lug", "stand", "leg", "ring", "rope", "strainer", "tension_rod",
                                                     "badge", "vent", "resonant_head"), size_range=(0.3, 0.75), density=300,
          variants=("snare", "floor_tom", "djembe"), placement="floor")
def drum(rng: np.random.Generator, variant: str) -> list[Part]:
    if variant == "djembe":
        r, h = rng.uniform(0.15, 0.17), rng.uniform(0.55, 0.62)
        wood = M.wood(rng)
        rope = M.solid(M.jitter(rng, (0.85, 0.8, 0.65), 0.05), "fabric", 0.9)
        out = [make_part("shell", "shell", S.lathe([(r * 0.7, 0.0), (r * 0.45, h * 0.45), (r, h * 0.95)]), wood),
               _c("head", "head", r * 1.01, 0.006, (0, 0, h * 0.95 + 0.003), M.leather(rng)),
               make_part("rim", "rim", ring([(r, h * 0.9), (r + 0.01, h * 0.9), (r + 0.01, h * 0.93), (r, h * 0.93)], sections=24),
                         M.fabric(rng)),
               # the lower ring the tuning ropes are laced to, at the waist
               make_part("ring", "ring", ring([(r * 0.47, h * 0.5), (r * 0.47 + 0.008, h * 0.5), (r * 0.47 + 0.008, h * 0.52),
                                               (r * 0.47, h * 0.52)], sections=20), rope)]
        # the tuning ropes, laced from the top ring down to the lower ring
        prof = [(r * 0.7, 0.0), (r * 0.45, h * 0.45), (r, h * 0.95)]
        for k, a in enumerate(np.linspace(0, 2 * np.pi, 8, endpoint=False)):
            top = np.array([np.cos(a) * (r + 0.004), np.sin(a) * (r + 0.004), h * 0.9])
            rb = float(np.interp(h * 0.52, [q[1] for q in prof], [q[0] for q in prof])) + 0.004
            bot = np.array([np.cos(a + 0.2) * rb, np.sin(a + 0.2) * rb, h * 0.52])
            mid_z = h * 0.72
            rm = float(np.interp(mid_z, [q[1] for q in prof], [q[0] for q in prof])) + 0.004
            mid = np.array([np.cos(a + 0.1) * rm, np.sin(a + 0.1) * rm, mid_z])
            out.append(make_part(f"rope_{k}", "rope", S.tube([top, mid, bot], 0.002, sections=6), rope))
        return out
    r = rng.uniform(0.17, 0.19) if variant == "snare" else rng.uniform(0.2, 0.23)
    dh = rng.uniform(0.12, 0.15) if variant == "snare" else rng.uniform(0.35, 0.42)
    z0 = 0.45 if variant == "snare" else 0.12
    steel = M.metal(rng)
    out = [_c("shell", "shell", r, dh, (0, 0, z0 + dh / 2), _colour(rng, "wood"), sections=28),
           _c("head", "head", r * 1.01, 0.004, (0, 0, z0 + dh + 0.002), white(rng, "plastic"), sections=28),
           make_part("rim", "rim", ring([(r, z0 + dh - 0.01), (r + 0.008, z0 + dh - 0.01), (r + 0.008, z0 + dh + 0.006), (r, z0 + dh + 0.006)],
                                        sections=28), steel)]
    for k, a in enumerate(np.linspace(0, 2 * np.pi, 3, endpoint=False)):
        out.append(make_part(f"leg_{k}", "leg", S.tube([(np.cos(a) * r * 0.9, np.sin(a) * r * 0.9, z0 + 0.02),
                                                        (np.cos(a) * (r + 0.08), np.sin(a) * (r + 0.08), 0.01)],
                                                       0.008, sections=8), steel))
    # the bottom hoop, and the tension lugs round the shell between the hoops
    out.append(make_part("rim_1", "rim", ring([(r, z0 - 0.006), (r + 0.008, z0 - 0.006), (r + 0.008, z0 + 0.01),
                                               (r, z0 + 0.01)], sections=28), steel))
    n_lugs = 8 if variant == "snare" else 6
    lh = min(0.06, dh * 0.4)
    for k, a in enumerate(np.linspace(0, 2 * np.pi, n_lugs, endpoint=False) + np.pi / n_lugs):
        out.append(_b(f"lug_{k}", "lug", (0.016, 0.014, lh), (np.cos(a) * (r + 0.006), np.sin(a) * (r + 0.006), z0 + dh / 2),
                      steel, R=rot((0, 0, 1), a)))
        # the tension rod from the top hoop down into the lug
        rr = r + 0.011
        out.append(make_part(f"tension_rod_{k}", "tension_rod", S.cylinder(0.003, dh / 2 - lh / 2 + 0.004,
                                                                           center=(np.cos(a) * rr, np.sin(a) * rr,
                                                                                   z0 + dh - (dh / 2 - lh / 2 + 0.004) / 2 + 0.002),
                                                                           sections=6), steel))
        # and the bottom hoop's rod up into the same lug
        out.append(make_part(f"tension_rod_{n_lugs + k}", "tension_rod", S.cylinder(0.003, dh / 2 - lh / 2 + 0.004,
                                                                                    center=(np.cos(a) * rr, np.sin(a) * rr,
                                                                                            z0 + (dh / 2 - lh / 2 + 0.004) / 2 - 0.002),
                                                                                    sections=6), steel))
    # the resonant head under the shell, held by the bottom hoop
    out.append(_c("resonant_head", "resonant_head", r * 1.01, 0.004, (0, 0, z0 - 0.002 + 0.004), white(rng, "plastic"), sections=28))
    # the maker's badge with the air vent through the shell, on the back
    out.append(_b("badge", "badge", (0.04, 0.002, 0.025), (0, -r - 0.001, z0 + dh * 0.5), M.solid((0.8, 0.7, 0.3), "metal", 0.3, 0.9)))
    out.append(make_part("vent", "vent", S.cylinder(0.005, 0.003, center=(0, -r - 0.0025, z0 + dh * 0.5 + 0.02), axis=(0, 1, 0),
                                                    sections=8), steel))
    if variant == "snare":
        # the snare strainer's throw-off lever on the front
        out.append(_b("strainer", "strainer", (0.03, 0.02, 0.05), (0, r + 0.01, z0 + dh / 2), steel))
    return out


# ----------------------------------------------------------------------------- clothes and bags
@register("shirt", parts=("body", "sleeve"), extra_parts=("collar", "button", "pocket", "cuff", "tag"), size_range=(0.25, 1.6), density=200,
          variants=("folded", "laid_flat", "t_shirt"), placement="surface")
def shirt(rng: np.random.Generator, variant: str) -> list[Part]:
    fab = M.solid(M.jitter(rng, (0.6, 0.6, 0.7), 0.3)[:3], "fabric", 0.9)
    if variant == "folded":
        w, d = rng.uniform(0.26, 0.32), rng.uniform(0.2, 0.26)
        out = [_b("body", "body", (w, d, 0.025), (0, 0, 0.0125), fab, bevel=0.006),
               _b("sleeve", "sleeve", (w * 0.9, 0.04, 0.01), (0, -d * 0.2, 0.03), fab),
               _b("collar", "collar", (0.12, 0.03, 0.008), (0, d / 2 - 0.03, 0.029), fab),
               # the chest pocket and the placket's buttons showing on the folded front
               _b("pocket", "pocket", (0.07, 0.08, 0.002), (w * 0.22, d * 0.15, 0.026), fab)]
        btn = white(rng, "plastic")
        out += [_c(f"button_{k}", "button", 0.005, 0.002, (0, y, 0.026), btn, sections=10)
                for k, y in enumerate((d * 0.25, d * 0.02))]
        return out
    w, L = rng.uniform(0.45, 0.55), rng.uniform(0.65, 0.75)
    out = [_b("body", "body", (w, L, 0.01), (0, 0, 0.005), fab, bevel=0.003)]
    sl = 0.2 if variant == "t_shirt" else 0.55
    out += [_b(f"sleeve_{k}", "sleeve", (sl, 0.18, 0.008), (sx * (w / 2 + sl / 2 - 0.01), L * 0.3, 0.004), fab,
               R=rot((0, 0, 1), sx * -0.4)) for k, sx in enumerate((-1, 1))]
    out.append(_b("collar", "collar", (0.16, 0.05, 0.006), (0, L / 2 - 0.025, 0.013), fab))
    # the chest pocket, and the care label inside the neck
    out.append(_b("pocket", "pocket", (0.1, 0.12, 0.002), (-w * 0.22, L * 0.22, 0.011), fab))
    out.append(_b("tag", "tag", (0.04, 0.02, 0.001), (0, L / 2 - 0.06, 0.0105), white(rng, "fabric")))
    if variant == "laid_flat":
        btn = white(rng, "plastic")
        out += [_c(f"button_{k}", "button", 0.006, 0.003, (0, y, 0.0115), btn, sections=10)
                for k, y in enumerate(np.linspace(-L * 0.4, L * 0.4, 6))]
        # the cuffs at the sleeves' ends
        for k, sx in enumerate((-1, 1)):
            a = sx * -0.4
            c = np.array([sx * (w / 2 + sl / 2 - 0.01), L * 0.3]) + sx * (sl / 2 - 0.03) * np.array([np.cos(a), np.sin(a)])
            out.append(_b(f"cuff_{k}", "cuff", (0.06, 0.185, 0.009), (c[0], c[1], 0.0045), fab, R=rot((0, 0, 1), a)))
    return out


@register("socks", parts=("sock",), extra_parts=("cuff", "heel", "toe"), size_range=(0.08, 0.3), density=200,
          variants=("pair", "rolled", "single"), placement="surface")
def socks(rng: np.random.Generator, variant: str) -> list[Part]:
    fab = M.solid(M.jitter(rng, (0.5, 0.5, 0.5), 0.35)[:3], "fabric", 0.9)
    if variant == "rolled":
        r = rng.uniform(0.035, 0.045)
        # the outer sock's cuff turned back over the ball; its heel and toe show on the ball,
        # the inner sock's toe in the cuff's mouth
        patch = M.solid(M.jitter(rng, (0.3, 0.3, 0.3), 0.1)[:3], "fabric", 0.9)
        return [make_part("sock", "sock", S.ellipsoid((r * 1.3, r, r * 0.9), center=(0, 0, r * 0.9)), fab),
                make_part("cuff", "cuff", S.ellipsoid((r * 0.6, r * 1.02, r * 0.6), center=(r * 0.5, 0, r * 0.9)), fab),
                make_part("heel", "heel", S.ellipsoid((r * 0.35, r * 0.5, r * 0.2), center=(-r * 0.3, 0, r * 1.55)), patch),
                make_part("toe", "toe", S.ellipsoid((r * 0.2, r * 0.55, r * 0.45), center=(-r * 1.08, 0, r * 0.9)), patch),
                make_part("sock_1", "sock", S.ellipsoid((r * 0.15, r * 0.45, r * 0.35), center=(r * 1.05, 0, r * 0.9)), fab),
                make_part("toe_1", "toe", S.ellipsoid((r * 0.08, r * 0.3, r * 0.22), center=(r * 1.17, 0, r * 0.9)), patch)]
    n = 2 if variant == "pair" else 1
    L = rng.uniform(0.2, 0.27)
    out = []
    for k in range(n):
        y = (k - (n - 1) / 2) * 0.1
        out.append(make_part(f"sock_{k}", "sock", [S.box((L * 0.65, 0.08, 0.012), center=(-L * 0.175, y, 0.006)),
                                                   S.box((L * 0.4, 0.08, 0.012), center=(L * 0.3, y + 0.02, 0.006), R=rot((0, 0, 1), 0.5))], fab))
        out.append(_b(f"cuff_{k}", "cuff", (0.04, 0.082, 0.014), (-L / 2 + 0.02, y, 0.007), fab))
        # the reinforced heel where the leg turns into the foot, and the toe at the foot's end
        patch = M.solid(M.jitter(rng, (0.3, 0.3, 0.3), 0.1)[:3], "fabric", 0.9)
        out.append(_b(f"heel_{k}", "heel", (0.04, 0.081, 0.0125), (L * 0.1, y - 0.001, 0.00625), patch))
        a = 0.5
        tc = np.array([L * 0.3, y + 0.02]) + (L * 0.2 - 0.02) * np.array([np.cos(a), np.sin(a)])
        out.append(_b(f"toe_{k}", "toe", (0.04, 0.081, 0.0125), (tc[0], tc[1], 0.00625), patch, R=rot((0, 0, 1), a)))
    return out


@register("duffel_bag", parts=("body", "handle"), extra_parts=("strap", "zipper", "pocket", "end_cap", "zipper_pull", "clip", "grip",
                                                               "foot"), size_range=(0.45, 0.8),
          density=150, variants=("gym", "travel", "barrel"), placement="floor")
def duffel_bag(rng: np.random.Generator, variant: str) -> list[Part]:
    L = rng.uniform(0.5, 0.75)
    r = rng.uniform(0.13, 0.18)
    fab = M.fabric(rng)
    # a round bag stands on its four studs, its lowest line clear of the floor (it would roll
    # on it otherwise); the travel bag's flat bottom rests on the floor with its studs
    lift = 0.004 if variant != "travel" else 0.0
    body = (S.cylinder(r, L, center=(0, 0, r + lift), axis=(1, 0, 0), sections=20) if variant != "travel" else
            S.box((L, 2 * r, 1.6 * r), center=(0, 0, 0.8 * r), bevel=0.04))
    top = 2 * r + lift if variant != "travel" else 1.6 * r
    web = black("fabric")
    out = [make_part("body", "body", body, fab),
           _b("zipper", "zipper", (L * 0.8, 0.012, 0.004), (0, 0.0, top + 0.001), M.metal(rng))]
    # the two carry handles either side of the zip, sewn on at both ends
    for k, sy in enumerate((-1, 1)):
        y = sy * 0.03
        out.append(make_part(f"handle_{k}", "handle", S.tube([(-0.11, y, top - 0.01), (-0.05, y, top + 0.06),
                                                              (0.05, y, top + 0.06), (0.11, y, top - 0.01)], 0.008), web))
    # the zip's pull tab, and the shoulder strap clipped to the ends, lying over the bag's side
    out.append(_b("zipper_pull", "zipper_pull", (0.012, 0.004, 0.03), (L * 0.3, 0.008, top - 0.012), M.metal(rng)))
    ys = -r - 0.004 if variant != "travel" else -r - 0.004
    out.append(make_part("strap", "strap", S.tube([(-L / 2 + 0.03, ys + 0.004, top * 0.75), (-L * 0.2, ys, top * 0.3),
                                                   (L * 0.2, ys, top * 0.3), (L / 2 - 0.03, ys + 0.004, top * 0.75)],
                                                  0.006, sections=6), web))
    # the snap hooks clipping the strap to the bag's ends, the grip wrapped round both handles,
    # and four studs under the bottom
    for k, sx in enumerate((-1, 1)):
        out.append(_b(f"clip_{k}", "clip", (0.03, 0.008, 0.02), (sx * (L / 2 - 0.03), ys + 0.004, top * 0.75), M.metal(rng)))
    out.append(_b("grip", "grip", (0.1, 0.09, 0.025), (0, 0, top + 0.055), web, bevel=0.006))
    ry = r * 0.5
    # on a round bag each stud reaches from the floor up into the curved bottom above it
    hf = 0.004 if variant == "travel" else lift + r - float(np.sqrt(r * r - ry * ry)) + 0.002
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        out.append(_c(f"foot_{k}", "foot", 0.008, hf, (sx * L * 0.35, sy * ry, hf / 2), M.metal(rng), sections=8))
    if variant == "gym":
        for k, sx in enumerate((-1, 1)):
            out.append(make_part(f"end_cap_{k}", "end_cap", S.cylinder(r * 1.01, 0.01, center=(sx * (L / 2 - 0.005), 0, r + lift),
                                                                      axis=(1, 0, 0)), web))
    else:
        # the zipped pocket on the front
        yp = r if variant == "travel" else r * 0.98
        out.append(_b("pocket", "pocket", (L * 0.45, 0.02, top * 0.35), (0, yp - 0.005, top * 0.45), fab, bevel=0.006))
    return out


@register("garment_bag", parts=("body", "hook"), extra_parts=("zipper", "handle", "window", "zipper_pull", "pocket"), size_range=(0.55, 1.5), density=150,
          variants=("hanging", "folded", "long"), placement="wall")
def garment_bag(rng: np.random.Generator, variant: str) -> list[Part]:
    w = rng.uniform(0.55, 0.62)
    fab = M.solid(M.jitter(rng, (0.2, 0.2, 0.25), 0.05), "fabric", 0.9)
    if variant == "folded":  # folded in half, lying flat on a bed or a rack
        return [_b("body", "body", (w, 0.55, 0.08), (0, 0, 0.04), fab, bevel=0.02),
                make_part("hook", "hook", S.tube([(0, 0.28, 0.06), (0, 0.33, 0.06), (0, 0.34, 0.03)], 0.003), M.metal(rng)),
                _b("handle", "handle", (0.15, 0.03, 0.02), (0, -0.2, 0.09), black("fabric")),
                # the zip round the folded edge, with its pull
                _b("zipper", "zipper", (w * 0.85, 0.01, 0.004), (0, 0.1, 0.081), M.metal(rng)),
                _b("zipper_pull", "zipper_pull", (0.012, 0.03, 0.004), (w * 0.3, 0.08, 0.083), M.metal(rng)),
                # the name window and the accessory pocket on the upper face
                _b("window", "window", (w * 0.4, 0.12, 0.002), (0, -0.05, 0.081), M.solid((0.85, 0.88, 0.9), "plastic", 0.1)),
                _b("pocket", "pocket", (w * 0.6, 0.12, 0.008), (0, 0.2, 0.076), fab, bevel=0.003)]
    L = rng.uniform(0.9, 1.05) if variant == "hanging" else rng.uniform(1.3, 1.4)
    return [_b("body", "body", (w, 0.08, L), (0, 0.06, L / 2), fab, bevel=0.02),
            make_part("hook", "hook", S.tube([(0, 0.06, L), (0, 0.06, L + 0.06), (0, 0.02, L + 0.08)], 0.003), M.metal(rng)),
            _b("zipper", "zipper", (0.01, 0.004, L * 0.9), (0, 0.1 + 0.002, L / 2), M.metal(rng)),
            _b("window", "window", (w * 0.4, 0.002, 0.12), (0, 0.101, L * 0.75), M.glass(rng)),
            # the zip's pull, the accessory pocket low on the front, the carry handle on the side
            _b("zipper_pull", "zipper_pull", (0.012, 0.004, 0.03), (0, 0.106, L * 0.92), M.metal(rng)),
            _b("pocket", "pocket", (w * 0.6, 0.012, L * 0.18), (0, 0.106, L * 0.18), fab, bevel=0.004),
            _b("handle", "handle", (0.012, 0.03, 0.14), (w / 2 + 0.006, 0.06, L * 0.55), black("fabric"))]


# --------------------------------------------------------------------- lights, signs and decor


@register("bird_cage", parts=("base", "bars", "top"), extra_parts=("door", "perch", "hook", "feeder", "hoop"),
          size_range=(0.3, 0.6), density=800, variants=("round", "square", "dome"), placement="surface",
          groups={"bars": ("bar",)})
def bird_cage(rng: np.random.Generator, variant: str) -> list[Part]:
    r = rng.uniform(0.14, 0.2)
    h = rng.uniform(0.3, 0.45)
    metal = M.metal(rng) if variant != "round" else M.solid((0.85, 0.75, 0.4), "metal", 0.3, 0.8)
    n = 16
    bars = [S.cylinder(0.002, h - 0.03, center=(np.cos(a) * r, np.sin(a) * r, 0.03 + (h - 0.03) / 2), sections=6)
            for a in np.linspace(0, 2 * np.pi, n, endpoint=False)]
    base = (S.cylinder(r + 0.01, 0.03, center=(0, 0, 0.015)) if variant != "square" else
            S.box((2 * r + 0.02, 2 * r + 0.02, 0.03), center=(0, 0, 0.015)))
    top = (S.lathe([(r, h), (r * 0.6, h + r * 0.35), (0.02, h + r * 0.5)]) if variant != "square" else
           S.box((2 * r, 2 * r, 0.02), center=(0, 0, h + 0.01)))
    top_z = h + (r * 0.5 if variant != "square" else 0.02)
    out = [make_part("base", "base", base, M.wood(rng)), make_part("top", "top", top, metal),
           _c("perch", "perch", 0.005, r * 1.6, (0, 0, h * 0.4), M.wood(rng), axis=(1, 0, 0), sections=8),
           make_part("hook", "hook", ring([(0.02, top_z - 0.005), (0.028, top_z - 0.005), (0.028, top_z + 0.005), (0.02, top_z + 0.005)],
                                          sections=12), metal)]
    # each upright bar (the ``bars`` group), held by two hoops round the cage
    out += [make_part(f"bar_{k}", "bar", b, metal) for k, b in enumerate(bars)]
    for k, z in enumerate((0.03 + (h - 0.03) * 0.35, 0.03 + (h - 0.03) * 0.7)):
        out.append(make_part(f"hoop_{k}", "hoop", ring([(r - 0.0025, z - 0.002), (r + 0.0025, z - 0.002), (r + 0.0025, z + 0.002),
                                                        (r - 0.0025, z + 0.002)], sections=16), metal))
    # the little door on the front (+Y) between two bars, and the seed cup hung on the bars
    a0 = np.pi / 2
    dz0, dz1 = 0.04, 0.04 + min(0.12, h * 0.35)
    xs = [np.cos(a0 + da) * r for da in (-np.pi / n, np.pi / n)]
    out.append(make_part("door", "door", S.box((abs(xs[1] - xs[0]) + 0.006, 0.004, dz1 - dz0),
                                                center=(0, r + 0.004, (dz0 + dz1) / 2)), metal))
    out.append(make_part("feeder", "feeder", shell([(0.022, 0.05), (0.026, 0.08)], 0.002, sections=12).moved((np.cos(-np.pi / 4) * (r - 0.029), np.sin(-np.pi / 4) * (r - 0.029), 0)),
                         white(rng, "plastic")))
    return out


@register("window", parts=("frame", "glass"),
          extra_parts=("sill", "mullion", "sash", "handle", "casing", "hinge", "lock", "lift", "apron", "glazing_bead"),
          size_range=(0.6, 2.2),
          density=800, variants=("casement", "double_hung", "picture"), placement="wall")
def window(rng: np.random.Generator, variant: str) -> list[Part]:
    """A window unit as seen from the room: frame, panes and sill on the wall's face; the sill
    reaches 8 to 22 cm into the room in front of the frame (pot plants stand on it)."""
    w, h = rng.uniform(0.6, 1.6), rng.uniform(0.8, 1.5)
    f, t = 0.06, 0.05
    frame_mat = white(rng, "wood")
    out = [make_part("frame", "frame", [S.box((w, t, f), center=(0, t / 2, f / 2)), S.box((w, t, f), center=(0, t / 2, h - f / 2)),
                                        S.box((f, t, h - 2 * f), center=(-w / 2 + f / 2, t / 2, h / 2)),
                                        S.box((f, t, h - 2 * f), center=(w / 2 - f / 2, t / 2, h / 2))], frame_mat),
           _b("glass", "glass", (w - 2 * f, 0.006, h - 2 * f), (0, t / 2, h / 2), M.glass(rng)),
           _b("sill", "sill", (w + 0.08, 0.12, 0.025), (0, 0.06, -0.0125 + 0.0125), frame_mat)]
    out[0] = make_part("frame", "frame", [S.box((w, t, f), center=(0, t / 2, 0.025 + f / 2)), S.box((w, t, f), center=(0, t / 2, 0.025 + h - f / 2)),
                                          S.box((f, t, h - 2 * f), center=(-w / 2 + f / 2, t / 2, 0.025 + h / 2)),
                                          S.box((f, t, h - 2 * f), center=(w / 2 - f / 2, t / 2, 0.025 + h / 2))], frame_mat)
    out[1] = _b("glass", "glass", (w - 2 * f, 0.006, h - 2 * f), (0, t / 2, 0.025 + h / 2), M.glass(rng))
    out[2] = _b("sill", "sill", (w + 0.08, 0.12, 0.025), (0, 0.06, 0.0125), frame_mat)
    # the casing boards round the frame on the wall: the head over it and a side casing each side
    cw, ct = 0.07, 0.015
    out.append(_b("head_casing", "casing", (w + 2 * cw, ct, cw), (0, ct / 2, 0.025 + h + cw / 2), frame_mat))
    for k, sx in enumerate((-1, 1)):
        out.append(_b(f"side_casing_{k}", "casing", (cw, ct, h), (sx * (w / 2 + cw / 2), ct / 2, 0.025 + h / 2), frame_mat))
    # the apron trim under the sill, and the glazing beads holding the glass in the frame
    out.append(_b("apron", "apron", (w, ct, 0.05), (0, ct / 2, -0.025), frame_mat))
    gb = 0.012
    beads = [S.box((w - 2 * f, gb, gb), center=(0, t / 2 + 0.009, 0.025 + f + gb / 2)),
             S.box((w - 2 * f, gb, gb), center=(0, t / 2 + 0.009, 0.025 + h - f - gb / 2)),
             S.box((gb, gb, h - 2 * f - 2 * gb), center=(-w / 2 + f + gb / 2, t / 2 + 0.009, 0.025 + h / 2)),
             S.box((gb, gb, h - 2 * f - 2 * gb), center=(w / 2 - f - gb / 2, t / 2 + 0.009, 0.025 + h / 2))]
    out += each("glazing_bead", "glazing_bead", beads, frame_mat)  # four strips, bottom, top, left, right
    hw = M.metal(rng)
    if variant == "double_hung":
        out.append(_b("sash", "sash", (w - 2 * f, t * 0.6, 0.04), (0, t * 0.6, 0.025 + h / 2), frame_mat))
        # the sash lock on the meeting rail and the two lifts on the lower sash
        out.append(_b("lock", "lock", (0.06, 0.02, 0.012), (0, t * 0.6 + 0.01, 0.025 + h / 2 + 0.026), hw))
        for k, sx in enumerate((-1, 1)):
            out.append(_b(f"lift_{k}", "lift", (0.05, 0.02, 0.015), (sx * (w / 2 - f - 0.1), t * 0.6 + 0.01, 0.025 + h / 2 - 0.04), hw))
    elif variant == "casement":
        out.append(_b("mullion", "mullion", (0.04, t * 0.8, h - 2 * f), (0, t / 2, 0.025 + h / 2), frame_mat))
        out.append(_b("handle", "handle", (0.02, 0.03, 0.08), (0.04, t + 0.015, 0.025 + h / 2), hw))
        # the hinges of the two casements, on the frame's sides
        for k, (sx, z) in enumerate([(-1, 0.2), (-1, 0.8), (1, 0.2), (1, 0.8)]):
            out.append(_c(f"hinge_{k}", "hinge", 0.006, 0.06, (sx * (w / 2 - f - 0.004), t + 0.006, 0.025 + h * z), hw,
                          sections=8))
    # the sill's depth, drawn last: 8 to 22 cm in front of the frame (a narrow sill of a
    # timber-framed wall to the deep one of a kitchen window)
    sd = t + rng.uniform(0.08, 0.22)
    out[2] = _b("sill", "sill", (w + 0.08, sd, 0.025), (0, sd / 2, 0.0125), frame_mat)
    return out


@register("fireplace", parts=("firebox", "mantel", "hearth"),
          extra_parts=("surround", "grate", "log", "screen", "corbel", "control_panel", "frieze", "plinth", "vent",
                       "andiron"),
          size_range=(1.0, 1.9), density=1500, variants=("brick", "stone", "electric"))
def fireplace(rng: np.random.Generator, variant: str) -> list[Part]:
    """A fireplace against a wall: the hearth on the floor, the surround and firebox, the mantel
    shelf on top (things stand ON its mantel)."""
    w, h, d = rng.uniform(1.1, 1.8), rng.uniform(1.0, 1.25), rng.uniform(0.3, 0.45)
    mat = M.stone(rng) if variant != "brick" else M.solid(M.jitter(rng, (0.55, 0.25, 0.18), 0.04), "stone", 0.9)
    ow, oh = w * 0.45, h * 0.5
    hearth_h = 0.05
    out = [_b("hearth", "hearth", (w + 0.1, d + 0.2, hearth_h), (0, 0.1, hearth_h / 2), mat),
           make_part("surround", "surround", [S.box(((w - ow) / 2, d, h - hearth_h - 0.06), center=(sx * (w / 2 - (w - ow) / 4), 0, hearth_h + (h - hearth_h - 0.06) / 2))
                                              for sx in (-1, 1)] + [S.box((ow, d, h - hearth_h - 0.06 - oh), center=(0, 0, hearth_h + oh + (h - hearth_h - 0.06 - oh) / 2))],
                     mat),
           _b("firebox", "firebox", (ow, d * 0.6, oh), (0, -d * 0.2, hearth_h + oh / 2), black("stone")),
           _b("mantel", "mantel", (w + 0.12, d + 0.08, 0.06), (0, 0.04, h - 0.03), M.wood(rng), bevel=0.005)]
    # the corbels under the mantel shelf's ends
    for k, sx in enumerate((-1, 1)):
        out.append(_b(f"corbel_{k}", "corbel", (0.06, 0.06, 0.1), (sx * (w / 2 - 0.05), d / 2 + 0.03, h - 0.06 - 0.05),
                      M.wood(rng), bevel=0.004))
    # the frieze board under the mantel shelf, and the plinth blocks the surround's legs stand on
    # (proud of the legs at the front and the sides, flush with them at the back, on the wall)
    trim = out[3].material
    out.append(_b("frieze", "frieze", (w - 0.2, 0.02, 0.08), (0, d / 2 + 0.01, h - 0.06 - 0.04), trim))
    for k, sx in enumerate((-1, 1)):
        out.append(_b(f"plinth_{k}", "plinth", ((w - ow) / 2 + 0.02, d + 0.02, 0.1),
                      (sx * (w / 2 - (w - ow) / 4), 0.01, hearth_h + 0.05), mat))
    if variant == "electric":
        out.append(_b("screen", "screen", (ow, 0.01, oh), (0, d / 2 - 0.005, hearth_h + oh / 2), M.glass(rng)))
        # the heater's outlet grille below the screen
        out.append(_b("vent", "vent", (ow * 0.8, 0.01, 0.03), (0, d / 2 - 0.004, hearth_h + 0.025), black("metal")))
        out.append(_b("control_panel", "control_panel", (0.12, 0.01, 0.03), (ow / 2 - 0.08, d / 2 - 0.005,
                                                                             hearth_h + oh + 0.03), black()))
    else:
        wood = M.wood(rng)
        for k in range(2):
            out.append(make_part(f"log_{k}", "log", S.cylinder(0.05, ow * 0.7, center=(0, -d * 0.1 + k * 0.06, hearth_h + 0.05 + k * 0.04),
                                                                axis=(1, 0, 0)), wood))
        # the iron grate the logs lie on: two bars front to back and a front rail
        iron = black("metal")
        grate = [S.box((0.015, d * 0.5, 0.015), center=(sx * ow * 0.3, -d * 0.15, hearth_h + 0.0075)) for sx in (-1, 1)]
        grate.append(S.box((ow * 0.7, 0.015, 0.05), center=(0, d * 0.08, hearth_h + 0.025)))
        out.append(make_part("grate", "grate", grate, iron))
        # the two andirons standing either side of the grate, their finials facing the room
        for k, sx in enumerate((-1, 1)):
            x = sx * ow * 0.42
            out.append(make_part(f"andiron_{k}", "andiron", [S.box((0.02, d * 0.45, 0.02), center=(x, -d * 0.1, hearth_h + 0.01)),
                                                             S.cylinder(0.012, 0.2, center=(x, d * 0.1, hearth_h + 0.1), sections=8),
                                                             S.ellipsoid((0.025, 0.025, 0.025), center=(x, d * 0.1, hearth_h + 0.21),
                                                                         subdivisions=1)], iron))
    return out


# ------------------------------------------------------------------- bar, shop and game room


def prismatic_joint(name: str, parent: str, child: str, travel: float) -> Joint:
    return Joint(name, "prismatic", parent, child, (0.0, 1.0, 0.0), (0.0, 0.0, 0.0), (0.0, float(travel)))


# ----------------------------------------------------------------------------- home and pets


@register("rolling_tv_stand", parts=("base", "pole", "mount"), extra_parts=("caster", "shelf", "bracket", "cap", "clip", "brake"),
          size_range=(1.2, 1.9),
          density=1500, variants=("single_pole", "dual_pole", "with_shelf"), groups={"base": ("base", "base_rail")})
def rolling_tv_stand(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.7, 0.9), rng.uniform(0.5, 0.6)
    h = rng.uniform(1.3, 1.8)
    steel = black("metal")
    ch = 0.08
    xs = (0.0,) if variant == "single_pole" else (-0.2, 0.2)
    # the base: a cross member (``base``) between two rails carrying the casters (``base`` covers all three)
    out = [*[make_part(f"base_rail_{k}", "base_rail", S.box((0.06, d, 0.04), center=(sx * w / 2 - sx * 0.03, 0, ch + 0.02)), steel)
             for k, sx in enumerate((-1, 1))],
           make_part("base", "base", S.box((w - 0.12, 0.06, 0.04), center=(0, 0, ch + 0.02)), steel),
           _b("mount", "mount", (0.4, 0.03, 0.3), (0, 0.04, h * 0.8), steel)]
    hp = h - ch - 0.04 - 0.01
    for k, x in enumerate(xs):
        out.append(_b(f"pole_{k}", "pole", (0.05, 0.05, hp), (x, 0, ch + 0.04 + hp / 2), steel))
        out.append(_b(f"cap_{k}", "cap", (0.052, 0.052, 0.01), (x, 0, h - 0.005), black("plastic")))
    for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)]):
        out.append(_c(f"caster_{k}", "caster", ch / 2, 0.03, (sx * (w / 2 - 0.03), sy * (d / 2 - 0.04), ch / 2),
                      black("rubber"), axis=(1, 0, 0)))
    # the VESA arms that carry the screen on the mount plate
    for k, sz in enumerate((-1, 1)):
        out.append(_b(f"bracket_{k}", "bracket", (0.04, 0.02, 0.34), (sz * 0.12, 0.065, h * 0.8), steel))
    if variant == "with_shelf":
        out.append(_b("shelf", "shelf", (0.5, 0.35, 0.012), (0, 0.12, h * 0.45), M.glass(rng)))
    # the cable clips on the back of each pole, and the brake levers on the two front casters
    n_clip = 0
    for x in xs:
        for z in (h * 0.35, h * 0.6):
            out.append(_b(f"clip_{n_clip}", "clip", (0.03, 0.012, 0.03), (x, -0.031, z), black("plastic")))
            n_clip += 1
    for k, sx in enumerate((-1, 1)):
        out.append(_b(f"brake_{k}", "brake", (0.02, 0.03, 0.008), (sx * (w / 2 - 0.03), d / 2 - 0.04 + 0.03, ch * 0.8), black("plastic")))
    return out


# ---------------------------------------------------------- pub, café, bathroom, tea room


@register("pint_glass", parts=("body",), extra_parts=("beer", "foam", "rim", "heel", "logo", "fill_line"), size_range=(0.14, 0.18), density=2500,
          variants=("empty", "full", "nonic"), placement="surface")
def pint_glass(rng: np.random.Generator, variant: str) -> list[Part]:
    h, r0, r1 = rng.uniform(0.145, 0.16), 0.03, rng.uniform(0.042, 0.045)
    prof = [(r0, 0.0), (r1, h)] if variant != "nonic" else [(r0, 0.0), (r1, h * 0.82), (r1 * 1.06, h * 0.88), (r1, h)]
    glass = M.glass(rng)
    out = [make_part("body", "body", shell(prof, 0.003, bottom=0.01, sections=24), glass)]
    # the rolled lip at the top, where the drinker's mouth goes, and the thick heel it stands on
    rt = prof[-1][0]
    out.append(make_part("rim", "rim", ring([(rt - 0.003, h - 0.003), (rt, h - 0.003), (rt, h), (rt - 0.003, h)],
                                             sections=16), glass))
    out.append(make_part("heel", "heel", ring([(r0 - 0.005, 0.0), (r0, 0.0), (r0, 0.006), (r0 - 0.005, 0.006)],
                                               sections=16), glass))
    # the brewery's printed logo on the front and the etched fill line above it
    zl = h * 0.45
    rl = r0 + (r1 - r0) * zl / h
    out.append(make_part("logo", "logo", S.box((0.02, 0.0006, 0.03), center=(0, rl - 0.0008, zl)),
                         white(rng, "paint")))
    zf = h * (0.74 if variant == "nonic" else 0.9)
    rf = r0 + (r1 - r0) * zf / (h * 0.82 if variant == "nonic" else h)
    rf = min(rf, r1)
    out.append(make_part("fill_line", "fill_line", ring([(rf - 0.0004, zf), (rf + 0.0002, zf), (rf + 0.0002, zf + 0.0008),
                                                         (rf - 0.0004, zf + 0.0008)], sections=16), white(rng, "paint")))
    if variant == "full":
        out.append(make_part("beer", "beer", S.frustum(r0 - 0.003, r1 * 0.94, h * 0.8, center=(0, 0, 0.01), sections=20),
                             M.food(rng, (0.8, 0.5, 0.1))))
        out.append(_c("foam", "foam", r1 * 0.93, h * 0.06, (0, 0, 0.01 + h * 0.83), white(rng, "food"), sections=20))
    return out


def hinge_barrels(prefix: str, *, x: float, y: float, z0: float, z1: float, mat) -> list[Part]:
    return [make_part(f"{prefix}_{k}", "hinge", S.cylinder(0.006, 0.05, center=(x, y, z), sections=10), mat)
            for k, z in enumerate((z0 + 0.15, z1 - 0.15))]


@register("shampoo_bottle", parts=("body", "cap"), extra_parts=("label", "pump", "back_label", "flip_lid", "collar"), size_range=(0.14, 0.3), density=1000,
          variants=("flip_cap", "pump", "tall"), placement="surface")
def shampoo_bottle(rng: np.random.Generator, variant: str) -> list[Part]:
    w, d = rng.uniform(0.06, 0.08), rng.uniform(0.035, 0.05)
    h = rng.uniform(0.15, 0.2) if variant != "tall" else rng.uniform(0.22, 0.26)
    col = _colour(rng)
    out = [_b("body", "body", (w, d, h), (0, 0, h / 2), col, bevel=0.012),
           _c("cap", "cap", 0.016, 0.025, (0, 0, h + 0.0125), white(rng, "plastic"), sections=14),
           _b("label", "label", (w * 0.8, 0.001, h * 0.5), (0, d / 2 + 0.0005, h * 0.45), M.paper(rng))]
    out.append(_b("back_label", "back_label", (w * 0.7, 0.001, h * 0.4), (0, -d / 2 - 0.0005, h * 0.42), M.paper(rng)))
    out.append(_c("collar", "collar", 0.018, 0.004, (0, 0, h + 0.002), white(rng, "plastic"), sections=14))
    if variant == "pump":
        out.append(_b("pump", "pump", (0.01, 0.04, 0.01), (0, 0.012, h + 0.03), white(rng, "plastic")))
    else:
        # the flip-top lid on the cap, hinged at its back
        out.append(_b("flip_lid", "flip_lid", (0.026, 0.026, 0.006), (0, 0.0, h + 0.022), white(rng, "plastic")))
    return out


@register("sippy_cup", parts=("body", "lid"), extra_parts=("spout", "handle", "straw", "vent", "grip", "scale", "valve", "collar",
                                                             "foot_ring"), size_range=(0.1, 0.2), density=1000,
          variants=("handles", "plain", "straw"), placement="surface")
def sippy_cup(rng: np.random.Generator, variant: str) -> list[Part]:
    r, h = rng.uniform(0.035, 0.04), rng.uniform(0.1, 0.13)
    col = _colour(rng)
    out = [_c("body", "body", r, h, (0, 0, h / 2), col, sections=20),
           _c("lid", "lid", r * 1.05, 0.015, (0, 0, h + 0.0075), white(rng, "plastic"), sections=20),
           make_part("spout", "spout", S.frustum(0.012, 0.006, 0.025, center=(0, r * 0.5, h + 0.015)), white(rng, "plastic"))]
    # the air vent on the lid and the soft grip band round the body
    out.append(_c("vent", "vent", 0.003, 0.002, (0, -r * 0.5, h + 0.016), black(), sections=8))
    out.append(make_part("grip", "grip", ring([(r - 0.0005, h * 0.35), (r + 0.002, h * 0.35), (r + 0.002, h * 0.6),
                                               (r - 0.0005, h * 0.6)], sections=20), M.solid((0.9, 0.9, 0.9), "rubber", 0.6)))
    # the ounce marks moulded up the front
    out.append(make_part("scale", "scale", [S.box((0.008 if k % 2 else 0.014, 0.0008, 0.0012), center=(0, r + 0.0003, h * (0.15 + 0.04 * k)))
                                            for k in range(5)], white(rng, "plastic")))
    if variant == "handles":
        for k, sx in enumerate((-1, 1)):
            out.append(_b(f"handle_{k}", "handle", (0.02, 0.012, 0.05), (sx * (r + 0.01), 0, h * 0.55), col))
    elif variant == "straw":
        out.append(_c("straw", "straw", 0.003, h + 0.01, (0, r * 0.5, (h + 0.01) / 2 + 0.012), white(rng, "plastic"), sections=8))
    # the silicone valve in the spout's mouth, the lid's screw collar, and the non-slip ring under
    # the base
    out.append(_c("valve", "valve", 0.004, 0.002, (0, r * 0.5, h + 0.039), M.solid((0.85, 0.85, 0.8), "rubber", 0.6),
                  sections=8))
    out.append(make_part("collar", "collar", ring([(r - 0.0005, h - 0.008), (r + 0.0012, h - 0.008), (r + 0.0012, h),
                                                   (r - 0.0005, h)], sections=20), white(rng, "plastic")))
    out.append(make_part("foot_ring", "foot_ring", ring([(r * 0.7, 0.0), (r * 0.85, 0.0), (r * 0.85, 0.002), (r * 0.7, 0.002)],
                                                        sections=20), M.solid((0.9, 0.9, 0.9), "rubber", 0.6)))
    return out
