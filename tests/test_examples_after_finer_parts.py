"""Finer parts and new joints must not break PAGs written before them: the bundled examples
still validate and solve at seed 0 with every object placed."""

from __future__ import annotations

from pathlib import Path

import pytest

import parse3d
from parse3d.pag import load_pag

EXAMPLES = sorted(p for p in (Path(__file__).parent.parent / "examples").glob("*.*")
                  if p.suffix in (".json", ".yaml"))  # not the notebook


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_example_solves_with_every_object_placed(path: Path) -> None:
    pag = load_pag(path)
    scene = parse3d.solve(pag, seed=0)
    failed = {o.id: o.reason for o in scene.objects.values() if not o.placed}
    assert not failed, failed
