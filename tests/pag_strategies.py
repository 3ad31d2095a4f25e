"""Hypothesis strategies for PAG documents (shared by the PAG property tests)."""

from __future__ import annotations

from hypothesis import strategies as st

from parse3d.relations import RELATIONS

CATEGORIES = {
    "desk": ("tabletop", "leg"),
    "bookcase": ("shelf", "side_panel", "back_panel"),
    "mug": ("body", "handle"),
    "book": ("front_cover", "back_cover", "spine", "pages"),
    "pendant_lamp": ("cord", "shade"),
    "picture_frame": ("frame", "canvas"),
}
SUPPORTS = ("ON", "IN", "HANGING_BELOW", "SECURED_TO")
CONSTRAINTS = tuple(n for n, r in RELATIONS.items() if not r.is_support)
SURF = ("top", "bottom", "front", "back", "left", "right")


@st.composite
def pag_documents(draw, max_objects: int = 10) -> dict:
    """A random valid ``pag/1`` document: a random support forest plus random constraints.

    Objects are generated in a hidden topological order and declared in a random
    permutation of it, so declaration order and dependency order differ.
    """
    w = draw(st.floats(2.0, 8.0, allow_nan=False)).__round__(2)
    d = draw(st.floats(2.0, 8.0, allow_nan=False)).__round__(2)
    n_walls = 4
    n = draw(st.integers(1, max_objects))
    cats = [draw(st.sampled_from(sorted(CATEGORIES))) for _ in range(n)]
    ids = [f"o{k}" for k in range(n)]

    def ref(k: int, *, object_level: bool) -> str:
        if object_level:
            return ids[k]
        s = ids[k]
        if draw(st.booleans()):
            s += ":" + draw(st.sampled_from(CATEGORIES[cats[k]]))
            if draw(st.booleans()):
                s += f"#{draw(st.integers(0, 3))}"
        if draw(st.booleans()):
            s += "@" + draw(st.sampled_from(SURF))
        return s

    relations = []
    for k in range(n):
        parent = draw(st.integers(-1, k - 1)) if k else -1
        if parent < 0:
            room = draw(st.sampled_from(["floor", "ceiling", "wall", "wall_i"]))
            rel = {"floor": "ON", "ceiling": "HANGING_BELOW"}.get(room, "SECURED_TO")
            if room == "wall_i":
                room = f"wall_{draw(st.integers(0, n_walls - 1))}"
            edge = {"relation": rel, "child": ref(k, object_level=False), "parent": room}
        else:
            rel = draw(st.sampled_from(SUPPORTS))
            edge = {"relation": rel, "child": ref(k, object_level=False),
                    "parent": ref(parent, object_level=False)}
        if rel == "SECURED_TO" and draw(st.booleans()):
            lo = draw(st.floats(0.5, 1.5)).__round__(2)
            edge["height"] = [lo, lo + 0.3]
        if rel == "HANGING_BELOW" and draw(st.booleans()):
            edge["drop"] = draw(st.floats(0.0, 1.0)).__round__(3)
        relations.append(edge)
    for _ in range(draw(st.integers(0, 2 * n))):
        if n < 2:
            break
        k = draw(st.integers(1, n - 1))
        j = draw(st.integers(0, k - 1))
        rel = draw(st.sampled_from(CONSTRAINTS))
        spec = RELATIONS[rel]
        obj = spec.is_object_level
        edge = {"relation": rel, "child": ref(k, object_level=obj),
                "parent": ref(j, object_level=obj)}
        for p in spec.params:
            if p.required or draw(st.booleans()):
                if p.type == "enum":
                    edge[p.name] = draw(st.sampled_from(p.choices))
                elif p.type == "float":
                    edge[p.name] = draw(st.floats(p.low, p.high)).__round__(3)
                else:
                    lo = draw(st.floats(p.low, p.high)).__round__(3)
                    edge[p.name] = [lo, max(lo, min(p.high, lo + 1.0))]
        relations.append(edge)
    if draw(st.booleans()) and n > 1:
        k = draw(st.integers(1, n - 1))
        relations.append({"relation": "AGAINST",
                          "child": ref(k, object_level=False), "parent": "wall"})
    perm = draw(st.permutations(range(n)))
    objects = []
    for k in perm:
        o = {"id": ids[k], "category": cats[k]}
        if draw(st.booleans()):
            o["category"] = [cats[k]]
        if draw(st.booleans()):
            lo = draw(st.floats(0.5, 1.0)).__round__(2)
            o["scale"] = [lo, lo + 0.2]
        objects.append(o)
    relations = draw(st.permutations(relations))
    doc = {
        "format": "pag/1",
        "name": draw(st.text("abcdefgh-", min_size=1, max_size=12)),
        "room": {"type": draw(st.sampled_from(["study", "bedroom", "kitchen"])),
                 "footprint": [[0, 0], [w, 0], [w, d], [0, d]],
                 "height": draw(st.floats(2.2, 4.0)).__round__(2)},
        "objects": objects,
        "relations": list(relations),
    }
    if any(r.get("frame") == "camera" for r in relations) or draw(st.booleans()):
        # sides read in the camera's frame need a viewpoint
        doc["viewpoint"] = draw(st.one_of(
            st.builds(lambda i: {"wall": f"wall_{i}"}, st.integers(0, n_walls - 1)),
            st.just({"position": [0.5, 0.5], "look_at": [w / 2, d / 2]})))
    if draw(st.booleans()):
        doc["meta"] = {"source": "hypothesis", "seed": draw(st.integers(0, 99))}
    return doc
