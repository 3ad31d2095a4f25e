"""Time loading and validating a 10,000-object PAG (goal: under 2 s).

Run: ``python benchmarks/bench_validate.py [N_OBJECTS]``. The PAG is a realistic mix: rows of
furniture on the floor against walls, small objects on their tops and in their shelves, wall
items, and object-level constraints between neighbours.
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

from parse3d.pag import PAG, Room, assembly_order, load_pag, save_pag, validate_data


def build(n_objects: int) -> PAG:
    side = max(6.0, (n_objects / 1.5) ** 0.5)
    pag = PAG("benchmark", Room("storage", ((0, 0), (side, 0), (side, side), (0, side)), 3.0))
    k = 0
    while k < n_objects:
        shelf = f"shelf{k}"
        pag.add(shelf, "bookcase")
        pag.relate(shelf, "ON", "floor")
        pag.relate(f"{shelf}:back_panel@back", "AGAINST", f"wall_{k % 4}")
        if k:
            pag.relate(shelf, "NEAR", f"shelf{k - 10}" if k >= 10 else "shelf0", distance=3.0)
        k += 1
        for j in range(8):
            if k >= n_objects:
                break
            oid = f"book{k}"
            pag.add(oid, "book", scale=(0.9, 1.1))
            pag.relate(oid, "IN", f"{shelf}:shelf#{j % 4}")
            if j:
                pag.relate(oid, "SIDE_OF", f"book{k - 1}", side="right")
            k += 1
        if k < n_objects:
            oid = f"frame{k}"
            pag.add(oid, "picture_frame")
            pag.relate(f"{oid}:frame@back", "SECURED_TO", f"wall_{k % 4}", height=[1.4, 1.8])
            k += 1
    return pag


def main(n_objects: int = 10_000) -> None:
    t0 = time.perf_counter()
    pag = build(n_objects)
    t1 = time.perf_counter()
    with tempfile.TemporaryDirectory() as d:
        path = save_pag(pag, Path(d) / "big.json")
        size = path.stat().st_size
        t2 = time.perf_counter()
        loaded = load_pag(path)  # read + schema + meaning checks + model
        t3 = time.perf_counter()
    assert loaded == pag
    data = pag.to_dict()
    t4 = time.perf_counter()
    problems = validate_data(data)
    t5 = time.perf_counter()
    order = assembly_order(pag)
    t6 = time.perf_counter()
    assert not problems and len(order) == n_objects
    print(f"objects {len(pag.objects)}, relations {len(pag.relations)}, file {size / 1e6:.1f} MB")
    print(f"build {t1 - t0:.2f} s")
    print(f"load + validate {t3 - t2:.2f} s (goal < 2 s)")
    print(f"validate only {t5 - t4:.2f} s")
    print(f"assembly order {t6 - t5:.3f} s")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10_000)
