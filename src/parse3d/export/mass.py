"""Masses of exported parts: solid volume times the category's density, or, for things built
as thin shells (a kettle, a lamp shade, a suitcase), the shell's volume times its material's
density.

A category's density (``Category.density``) is a bulk figure for its solid collision volume,
which suits solid or packed things (a book, a mattress, a sofa). A hollow thing modelled as a
closed solid (an electric kettle is a lathe-turned body) weighs that density times a volume
that is mostly air: 6.9 kg for a kettle that weighs about 1 kg. For the categories of
:data:`SHELLS` a part weighs its material's density (:data:`MATERIAL_DENSITY`, by the
material family of :class:`~parse3d.assets.model.Material`) times the smaller of its volume
and its surface area times the category's wall thickness: a closed body becomes a shell, and
a part already modelled thin (a cord, a handle) keeps its own volume.

Units: metres, kilograms. Areas and volumes are of the convex collision pieces (what the
simulators collide), at the object's uniform scale (volume ``s**3``, area ``s**2``; the wall
keeps its thickness).
"""

from __future__ import annotations

import numpy as np

__all__ = ["MATERIAL_DENSITY", "WALL", "SHELLS", "is_shell", "pieces_area", "part_mass"]

#: kg / m^3 of the material a shell is made of, by material family. Engineering handbook
#: values (e.g. The Engineering ToolBox, "Densities of Solids"): stainless and mild steel
#: 7,800-8,000; ABS and polypropylene 900-1,100; porcelain and stoneware 2,300-2,500; soda-lime
#: glass 2,500; plywood and hardwood 500-800; wicker, paper shades and fabric on a frame are
#: given the density of the sheet they are.
MATERIAL_DENSITY: dict[str, float] = {
    "metal": 7800.0, "plastic": 1050.0, "rubber": 1200.0, "ceramic": 2400.0, "glass": 2500.0,
    "wood": 650.0, "paper": 800.0, "fabric": 400.0, "leather": 900.0, "stone": 2600.0,
    "plant": 600.0, "food": 1000.0,
}

#: Wall thickness of a shell by material family, metres: sheet steel of appliance housings and
#: pots (0.5-0.8 mm), moulded plastic housings (about 2 mm), drinking and lamp glass (about
#: 3 mm), stoneware (about 5 mm), plywood of cases and instrument bodies (about 3 mm).
WALL: dict[str, float] = {
    "metal": 0.0006, "plastic": 0.002, "rubber": 0.002, "ceramic": 0.005, "glass": 0.003,
    "wood": 0.003, "paper": 0.0005, "fabric": 0.002, "leather": 0.002, "stone": 0.01,
    "plant": 0.002, "food": 0.002,
}

#: Categories built as shells. Objects with contents or solid bulk (books, bottles full of
#: liquid, furniture, dumbbells) keep the solid model, and so do housings full of machinery
#: (printers, projectors, air conditioners, game consoles), whose bulk density is nearer
#: the truth than their shell.
SHELLS: frozenset[str] = frozenset({
    # small appliances: moulded plastic or sheet metal housings around little else
    "kettle", "toaster", "toaster_oven", "coffee_maker", "microwave", "paper_towel_dispenser",
    # lamps: shades, canopies and bases are sheet metal, glass or ceramic
    "pendant_lamp", "table_lamp", "ceiling_light",
    # vessels, tableware and bins: modelled either as closed bodies or with their walls, their
    # material's density is right for the walls either way
    "cooking_pot", "trash_can", "mug", "cup", "tea_cup", "bowl", "vase",
    # cases and hollow instruments
    "suitcase", "guitar_case", "violin_case", "cello",
})


def is_shell(category: str) -> bool:
    """Whether a category is built as a shell (:data:`SHELLS`)."""
    return category in SHELLS


def pieces_area(pieces: list[tuple[np.ndarray, np.ndarray]]) -> float:
    """Total surface area of convex pieces ``(vertices (V, 3), triangles (F, 3))``, m^2."""
    area = 0.0
    for v, f in pieces:
        tri = np.asarray(v, float)[np.asarray(f)]
        area += 0.5 * float(np.linalg.norm(
            np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1).sum())
    return area


def part_mass(volume: float, area: float, *, scale: float, density: float,
              material: str, shell: bool) -> float:
    """The mass of one part, kg.

    Parameters
    ----------
    volume, area : float
        Of the part's collision pieces at scale 1, m^3 and m^2.
    scale : float
        The object's uniform scale.
    density : float
        The category's bulk density, kg / m^3 (the solid model).
    material : str
        The part's material family (``Material.name``).
    shell : bool
        Whether the category is built as a shell (:func:`is_shell`); else solid.

    >>> round(part_mass(1e-3, 0.06, scale=1.0, density=1500.0, material="plastic",
    ...                 shell=True), 4)  # a 1-litre body as a 2 mm plastic shell
    0.126
    """
    v = volume * scale**3
    if not shell:
        return density * v
    family = material if material in MATERIAL_DENSITY else "plastic"
    return MATERIAL_DENSITY[family] * min(v, area * scale**2 * WALL[family])
