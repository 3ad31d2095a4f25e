"""A small category vocabulary for PAG tests, independent of the asset registry.

It lists the categories and part labels that the example PAGs use, so the validator's
vocabulary checks can be exercised without generating any asset.
"""

from __future__ import annotations

_TABLE = ("tabletop", "leg")

PLANNED_PARTS: dict[str, tuple[str, ...]] = {
    "bed": ("frame", "mattress", "headboard"),
    "bunk_bed": ("frame", "mattress", "ladder"),
    "nightstand": ("body", "top_panel", "drawer"),
    "wardrobe": ("body", "door", "shelf"),
    "dresser": ("body", "top_panel", "drawer"),
    "desk": _TABLE,
    "office_chair": ("seat", "back", "base"),
    "dining_chair": ("seat", "back", "leg"),
    "armchair": ("seat", "back", "armrest"),
    "sofa": ("seat_cushion", "back_cushion", "armrest"),
    "coffee_table": _TABLE,
    "dining_table": _TABLE,
    "side_table": _TABLE,
    "tea_table": _TABLE,
    "conference_table": _TABLE,
    "bookcase": ("shelf", "side_panel", "back_panel"),
    "storage_cabinet": ("body", "door", "shelf"),
    "tv_stand": ("top_panel", "body"),
    "kitchen_counter": ("countertop", "body", "door"),
    "wall_cabinet": ("body", "door", "shelf"),
    "refrigerator": ("body", "door", "shelf"),
    "stove": ("body", "cooktop", "burner"),
    "bathroom_vanity": ("countertop", "basin", "faucet"),
    "toilet": ("bowl", "tank", "seat"),
    "bathtub": ("tub",),
    "washing_machine": ("body", "door"),
    "storage_rack": ("shelf", "post"),
    "grocery_shelf": ("shelf", "back_panel"),
    "bar_counter": ("countertop", "body"),
    "bar_stool": ("seat", "leg"),
    "piano": ("body", "keyboard", "lid"),
    "pool_table": ("playing_surface", "rail", "leg"),
    "floor_lamp": ("base", "pole", "shade"),
    "potted_plant": ("pot", "plant"),
    "rug": ("body",),
    "coat_rack": ("base", "pole", "hook"),
    "picture_frame": ("frame", "canvas"),
    "mirror": ("frame", "glass"),
    "wall_clock": ("body", "face"),
    "wall_shelf": ("shelf", "bracket"),
    "tv": ("screen", "stand"),
    "whiteboard": ("board", "tray"),
    "pendant_lamp": ("cord", "shade"),
    "towel_bar": ("bar",),
    "book": ("front_cover", "back_cover", "spine", "pages"),
    "mug": ("body", "handle"),
    "cup": ("body",),
    "bowl": ("body",),
    "plate": ("body",),
    "bottle": ("body", "cap"),
    "wine_glass": ("bowl", "stem", "foot"),
    "vase": ("body",),
    "table_lamp": ("base", "stem", "shade"),
    "laptop": ("base", "screen"),
    "monitor": ("screen", "stand", "base"),
    "keyboard": ("body",),
    "basket": ("body",),
    "storage_box": ("body", "lid"),
    "bucket": ("body", "handle"),
    "pillow": ("body",),
    "towel": ("body",),
    "apple": ("body",),
    "cooking_pot": ("body", "lid", "handle"),
    "frying_pan": ("body", "handle"),
    "kettle": ("body", "spout", "handle"),
    "teapot": ("body", "spout", "handle", "lid"),
    "tea_cup": ("body",),
    "guitar": ("body", "neck", "head"),
    "broom": ("handle", "head"),
    "trash_can": ("body",),
    "laundry_basket": ("body",),
    "canned_food": ("body",),
    "cereal_box": ("body",),
    "detergent_bottle": ("body", "cap"),
    "speaker": ("body",),
    "candle": ("body",),
    "remote_control": ("body",),
}


class FakeVocabulary:
    """The validator's vocabulary protocol over a plain dict of category -> part labels."""

    def __init__(self, parts: dict[str, tuple[str, ...]]):
        self._parts = dict(parts)

    def has_category(self, name: str) -> bool:
        return name in self._parts

    def categories(self) -> list[str]:
        return sorted(self._parts)

    def parts(self, category: str) -> tuple[str, ...]:
        return self._parts[category]
