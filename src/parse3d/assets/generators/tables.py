"""Tables and desks: four-leg, pedestal and trestle variants sharing one builder.

Every table has a ``tabletop`` and at least one ``leg``; desks may add a ``drawer`` with a
``handle`` and a ``modesty_panel``. Under the top: a four-leg table's glued ``corner_block`` s
between its aprons and low ``stretcher`` s joining its legs; a pedestal table's two crossed
``cleat`` s the column's ``mounting_plate`` is fixed to by four ``screw`` s; a trestle table's ``corbel`` s bracing each upright under the
top and the ``wedge`` s locking the stretcher's ``tenon`` s.
"""

from __future__ import annotations

import numpy as np

from ...geometry import shapes as S
from .. import materials as M
from ..model import Part, make_part
from ..registry import register
from ._kit import DRAWER_TRAVEL, mount, prismatic


def _top(rng, w, d, h, thick, mat, round_top: bool = False) -> Part:
    if round_top:
        shape = S.cylinder(w / 2, thick, center=(0, 0, h - thick / 2), sections=48)
    else:
        shape = S.box((w, d, thick), center=(0, 0, h - thick / 2), bevel=min(0.006, thick / 4))
    return make_part("tabletop", "tabletop", shape, mat)


def _four_legs(rng, w, d, h_leg, leg_mat, inset: float, leg: float, tapered: bool,
               glide: float = 0.008) -> list[Part]:
    """Four legs standing on floor glides (``foot``, ``glide`` tall) at ``inset`` from the edges."""
    parts = []
    feet = []
    xs = (-w / 2 + inset, w / 2 - inset)
    ys = (-d / 2 + inset, d / 2 - inset)
    i = 0
    hl = h_leg - glide
    glide_mat = M.solid((0.08, 0.08, 0.08), "plastic", 0.7)
    for y in ys:
        for x in xs:
            if tapered:
                shape = S.frustum(leg / 2 * 0.65, leg / 2, hl, center=(x, y, glide), sections=12)
                r = leg / 2 * 0.6
            else:
                shape = S.box((leg, leg, hl), center=(x, y, glide + hl / 2), bevel=leg * 0.12)
                r = leg * 0.4
            parts.append(make_part(f"leg_{i}", "leg", shape, leg_mat))
            feet.append(make_part(f"foot_{i}", "foot", S.cylinder(r, glide, center=(x, y, glide / 2), sections=12),
                                  glide_mat))
            i += 1
    return parts + feet


def _aprons(w, d, h_leg, inset: float, leg: float, mat, *, sides: str = "xy") -> list[Part]:
    """Apron rails under the top between the legs: along x at the front and back (``x`` in
    ``sides``) and along y at the ends (``y``)."""
    ah = min(0.09, h_leg * 0.14)
    t = 0.03
    lx, ly = w - 2 * inset - leg, d - 2 * inset - leg
    out = []
    if "x" in sides:
        out += [make_part(f"apron_{i}", "apron", S.box((lx, t, ah), center=(0, s * (d / 2 - inset), h_leg - ah / 2)), mat)
                for i, s in enumerate((-1, 1))]
    if "y" in sides:
        k = len(out)
        out += [make_part(f"apron_{k + i}", "apron", S.box((t, ly, ah), center=(s * (w / 2 - inset), 0, h_leg - ah / 2)), mat)
                for i, s in enumerate((-1, 1))]
    return out


_GLIDE = 0.006  # height of the floor glides under pedestal bases and trestle feet, metres


def _glides(points, r: float) -> list[Part]:
    """Round floor glides (``foot_k``) of radius ``r`` centred at the (x, y) ``points``."""
    mat = M.solid((0.08, 0.08, 0.08), "plastic", 0.7)
    return [make_part(f"foot_{k}", "foot", S.cylinder(r, _GLIDE, center=(x, y, _GLIDE / 2), sections=12), mat)
            for k, (x, y) in enumerate(points)]


def _corner_blocks(w, d, h_leg, inset: float, leg: float, mat) -> list[Part]:
    """The four glue blocks in the inside corners between the aprons, under the top."""
    ah = min(0.09, h_leg * 0.14)
    b = 0.045
    return [make_part(f"corner_block_{k}", "corner_block",
                      S.box((b, b, ah * 0.7), center=(sx * (w / 2 - inset - leg / 2 - b / 2), sy * (d / 2 - inset - 0.015 - b / 2),
                                                      h_leg - ah * 0.35)), mat)
            for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (-1, 1), (1, 1)])]


def _stretchers(w, d, h_leg, inset: float, leg: float, mat, *, centre: bool) -> list[Part]:
    """Low rails joining each end's legs, and (``centre``) one joining their middles: an H."""
    z = h_leg * 0.18
    t = min(0.03, leg * 0.6)
    out = [make_part(f"stretcher_{k}", "stretcher", S.box((t, d - 2 * inset - leg, 0.03), center=(sx * (w / 2 - inset), 0, z)), mat)
           for k, sx in enumerate((-1, 1))]
    if centre:
        out.append(make_part("stretcher_2", "stretcher", S.box((w - 2 * inset - t, t, 0.03), center=(0, 0, z)), mat))
    return out


def _pedestal(rng, h_leg, leg_mat, r_base: float) -> list[Part]:
    """A turned column on a round base that stands on four glides."""
    g = _GLIDE
    col = S.lathe([(r_base, g), (r_base, g + 0.025), (r_base * 0.35, g + 0.06), (r_base * 0.22, g + 0.12),
                   (r_base * 0.2, h_leg - 0.05), (r_base * 0.45, h_leg)], sections=32)
    rg = r_base * 0.78
    pts = [(rg * np.cos(a), rg * np.sin(a)) for a in np.pi / 4 + np.pi / 2 * np.arange(4)]
    # two battens crossed under the top, which the column's head is screwed to
    cl = r_base * 2.4
    cleats = [make_part(f"cleat_{k}", "cleat", S.box((cl, 0.05, 0.025) if k == 0 else (0.05, cl, 0.025),
                                                     center=(0, 0, h_leg - 0.0125)), leg_mat) for k in range(2)]
    # the steel plate on the column's head, under the cleats, and the four lag screws through
    # its corners into the cleats (one each side of the crossing)
    steel = M.solid((0.25, 0.25, 0.27), "metal", 0.45, 0.8)
    pw, pt = r_base * 0.9, 0.006
    z_plate = h_leg - 0.025 - pt / 2
    plate = make_part("mounting_plate", "mounting_plate", S.box((pw, pw, pt), center=(0, 0, z_plate)), steel)
    head = 0.009
    screws = [make_part(f"screw_{k}", "screw", S.cylinder(head, 0.003, center=(x, y, z_plate - pt / 2 - 0.0015), sections=8),
                        steel)
              for k, (x, y) in enumerate([(pw * 0.4, 0), (-pw * 0.4, 0), (0, pw * 0.4), (0, -pw * 0.4)])]
    return [make_part("leg_0", "leg", col, leg_mat), *_glides(pts, min(0.02, r_base * 0.12)), *cleats, plate, *screws]


def _trestle(rng, w, d, h_leg, leg_mat, leg: float) -> list[Part]:
    """Two trestles (upright, foot and cap) joined by a stretcher; each foot on two glides."""
    parts = []
    g = _GLIDE
    for i, x in enumerate((-w / 2 + 0.12, w / 2 - 0.12)):
        upright = S.box((leg, leg * 1.4, h_leg - 0.05 - g), center=(x, 0, (h_leg - 0.05 - g) / 2 + 0.05 + g))
        foot = S.box((leg * 1.2, d * 0.8, 0.05), center=(x, 0, g + 0.025), bevel=0.008)
        cap = S.box((leg * 1.2, d * 0.8, 0.04), center=(x, 0, h_leg - 0.02), bevel=0.006)
        parts.append(make_part(f"leg_{i}", "leg", [upright, foot, cap], leg_mat))
    bar = S.box((w - 0.24 - leg, 0.04, 0.06), center=(0, 0, 0.25))
    parts.append(make_part("stretcher", "stretcher", bar, leg_mat))
    # the stretcher's tenons come through the uprights, each locked by a wedge driven down
    # through it outside; corbels brace each upright under the top, front and back
    for i, sx in enumerate((-1, 1)):
        x = sx * (w / 2 - 0.12)
        parts.append(make_part(f"tenon_{i}", "tenon", S.box((0.04, 0.036, 0.05), center=(x + sx * (leg / 2 + 0.02), 0, 0.25)),
                               leg_mat))
        parts.append(make_part(f"wedge_{i}", "wedge", S.box((0.012, 0.026, 0.09), center=(x + sx * (leg / 2 + 0.026), 0, 0.25)),
                               leg_mat))
        for j, sy in enumerate((-1, 1)):
            y0 = sy * leg * 0.7  # the upright's face
            yz = [(y0, h_leg - 0.04), (y0 + sy * 0.12, h_leg - 0.04), (y0, h_leg - 0.2)]
            pts = [(x + dx, y, z) for dx in (-leg * 0.4, leg * 0.4) for y, z in yz]
            parts.append(make_part(f"corbel_{2 * i + j}", "corbel", S.hull(np.array(pts)), leg_mat))
    r = min(0.018, leg * 0.45)
    parts += _glides([(x, y) for x in (-w / 2 + 0.12, w / 2 - 0.12) for y in (-d * 0.4 + r + 0.01, d * 0.4 - r - 0.01)], r)
    return parts


def _table(rng, variant: str, *, w_rng, d_rng, h_rng, round_ok: bool = False,
           desk: bool = False, shelf: bool = False) -> list[Part]:
    w = rng.uniform(*w_rng)
    d = rng.uniform(*d_rng)
    h = rng.uniform(*h_rng)
    thick = rng.uniform(0.025, 0.045)
    top_mat = M.wood(rng) if rng.random() < 0.8 else M.stone(rng)
    leg_mat = top_mat if rng.random() < 0.6 else M.metal(rng)
    round_top = round_ok and variant == "pedestal" and rng.random() < 0.6
    if round_top:
        d = w
    parts = [_top(rng, w, d, h, thick, top_mat, round_top)]
    h_leg = h - thick
    leg = rng.uniform(0.04, 0.06)
    if variant == "four_leg":
        inset = leg / 2 + rng.uniform(0.01, 0.05)
        parts += _four_legs(rng, w, d, h_leg, leg_mat, inset=inset, leg=leg, tapered=rng.random() < 0.4)
        parts += _aprons(w, d, h_leg, inset, leg, top_mat, sides="y" if desk else "xy")
        parts += _corner_blocks(w, d, h_leg, inset, leg, top_mat)
        parts += _stretchers(w, d, h_leg, inset, leg, leg_mat, centre=not desk and not shelf)
    elif variant == "pedestal":
        parts += _pedestal(rng, h_leg, leg_mat, r_base=min(w, d) * rng.uniform(0.28, 0.36))
    elif variant == "trestle":
        parts += _trestle(rng, w, d, h_leg, leg_mat, leg)
    if desk:
        # between the legs, or between the trestle caps
        span = w - 2 * leg - 0.06 if variant == "four_leg" else w - 0.24 - leg * 1.2 - 0.02
        panel = S.box((span, 0.018, h_leg * 0.4),
                      center=(0, -d / 2 + leg / 2 + 0.02, h_leg - h_leg * 0.2 - 0.01))
        parts.append(make_part("modesty_panel", "modesty_panel", panel, top_mat))
        if rng.random() < 0.7 or variant == "trestle":
            dw, dh = min(0.45, w * 0.35), 0.09
            x = span / 2 - dw / 2
            front = S.box((dw, 0.02, dh), center=(x, d / 2 - 0.03, h_leg - dh / 2 - 0.005), bevel=0.003)
            # the box runs just under the top, which carries its slides
            box_ = S.box((dw - 0.02, d * 0.6, dh - 0.02), center=(x, d / 2 - 0.04 - d * 0.3, h_leg - 0.003 - (dh - 0.02) / 2))
            parts.append(make_part("drawer_0", "drawer", front, top_mat))
            parts.append(make_part("drawer_0_box", "drawer_box", box_, top_mat))
            parts += [prismatic("drawer_0_slide", "tabletop", "drawer_0_box", travel=DRAWER_TRAVEL * d * 0.6),
                      mount("drawer_0_box", "drawer_0"), mount("drawer_0", "handle_0")]
            handle = S.tube([[x - 0.05, d / 2 - 0.02, h_leg - dh / 2], [x - 0.05, d / 2 + 0.005, h_leg - dh / 2],
                             [x + 0.05, d / 2 + 0.005, h_leg - dh / 2], [x + 0.05, d / 2 - 0.02, h_leg - dh / 2]],
                            0.005, sections=8)
            parts.append(make_part("handle_0", "handle", handle, M.metal(rng)))
    return parts


@register("desk", parts=("tabletop", "leg"), extra_parts=("drawer", "handle", "modesty_panel", "stretcher", "drawer_box", "apron", "foot",
                                                       "corner_block", "corbel", "wedge", "tenon"),
          size_range=(1.0, 1.7), density=600, variants=("four_leg", "trestle"))
def desk(rng: np.random.Generator, variant: str) -> list[Part]:
    return _table(rng, variant, w_rng=(1.1, 1.6), d_rng=(0.6, 0.8), h_rng=(0.72, 0.76), desk=True)


@register("dining_table", parts=("tabletop", "leg"), extra_parts=("stretcher", "apron", "foot", "corner_block", "cleat", "mounting_plate", "screw", "corbel", "wedge", "tenon"),
          size_range=(1.2, 2.2), density=600, variants=("four_leg", "pedestal", "trestle"))
def dining_table(rng: np.random.Generator, variant: str) -> list[Part]:
    return _table(rng, variant, w_rng=(1.3, 2.0), d_rng=(0.8, 1.0), h_rng=(0.73, 0.77), round_ok=True)


@register("coffee_table", parts=("tabletop", "leg"), extra_parts=("stretcher", "apron", "foot", "corner_block", "cleat", "mounting_plate", "screw", "corbel", "wedge", "tenon"),
          size_range=(0.8, 1.4), density=600, variants=("four_leg", "pedestal"))
def coffee_table(rng: np.random.Generator, variant: str) -> list[Part]:
    return _table(rng, variant, w_rng=(0.9, 1.3), d_rng=(0.5, 0.7), h_rng=(0.38, 0.46), round_ok=True)


@register("side_table", parts=("tabletop", "leg"), extra_parts=("stretcher", "apron", "foot", "shelf", "corner_block", "cleat", "mounting_plate", "screw", "corbel", "wedge", "tenon"),
          size_range=(0.4, 0.7), density=600, variants=("four_leg", "pedestal"))
def side_table(rng: np.random.Generator, variant: str) -> list[Part]:
    parts = _table(rng, variant, w_rng=(0.4, 0.6), d_rng=(0.4, 0.6), h_rng=(0.5, 0.62), round_ok=True,
                   shelf=variant == "four_leg")
    legs = [p for p in parts if p.label == "leg"]
    if variant == "four_leg" and len(legs) == 4:
        # a lower shelf between the legs (for magazines, a lamp's books)
        lo = np.min([p.bounds[0] for p in legs], axis=0)
        hi = np.max([p.bounds[1] for p in legs], axis=0)
        top = next(p for p in parts if p.label == "tabletop")
        parts.append(make_part("shelf", "shelf", S.box((hi[0] - lo[0] - 0.01, hi[1] - lo[1] - 0.01, 0.015),
                                                       center=((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2] + 0.12)),
                               top.material))
    return parts


@register("tea_table", parts=("tabletop", "leg"), extra_parts=("stretcher", "apron", "foot", "corner_block", "cleat", "mounting_plate", "screw", "corbel", "wedge", "tenon"),
          size_range=(0.6, 1.2), density=650, variants=("four_leg", "pedestal"))
def tea_table(rng: np.random.Generator, variant: str) -> list[Part]:
    return _table(rng, variant, w_rng=(0.7, 1.1), d_rng=(0.5, 0.7), h_rng=(0.32, 0.5), round_ok=True)


@register("conference_table", parts=("tabletop", "leg"), extra_parts=("stretcher", "apron", "foot", "corner_block", "cleat", "mounting_plate", "screw", "corbel", "wedge", "tenon"),
          size_range=(2.0, 4.0), density=600, variants=("four_leg", "trestle"))
def conference_table(rng: np.random.Generator, variant: str) -> list[Part]:
    return _table(rng, variant, w_rng=(2.2, 3.6), d_rng=(1.0, 1.4), h_rng=(0.73, 0.76))
