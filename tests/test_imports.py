"""The import contract: the layering table of the design (DESIGN §2), checked on the source.

Every ``import`` of a ``parse3d`` module counts, including imports inside functions: a lazy
import is still a dependency, and hiding one is how layering drifted before. A package may
import the packages its row lists and everything those may import (the table's "lower layers"),
never a higher one. Packages that do not exist yet (``measure``, ``export``, ``vlm``,
``layoutgen``, ``web``) are checked as soon as they do.
"""

from __future__ import annotations

import ast
from functools import cache
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parent.parent / "src" / "parse3d"

#: DESIGN §2: package -> the packages it may import directly. ``_files`` and ``_deps`` are
#: helpers under every layer (they import only ``errors``; ``_lru``, the process caches' LRU
#: mapping, imports nothing); ``scenes`` (the bundled example PAGs and ``generate``'s
#: template choice) sits at the ``datagen`` layer; ``render`` draws assets (thumbnails,
#: galleries) and so may import ``assets``.
LAYERS: dict[str, set[str]] = {
    "errors": set(),
    "_files": {"errors"},
    "_deps": {"errors"},
    "_hooks": set(),
    "_lru": set(),
    "relations": {"errors"},
    "words": {"errors"},
    "geometry": {"errors", "relations"},
    "pag": {"relations", "geometry", "words", "_files"},
    "assets": {"relations", "geometry", "words", "_files", "_lru"},
    "scene": {"pag", "assets", "_files", "_hooks"},
    "measure": {"scene", "pag", "assets", "geometry"},
    "solver": {"measure", "scene", "pag", "assets", "geometry"},
    "physics": {"measure", "scene", "assets", "export", "_deps"},
    "render": {"scene", "assets"},
    "export": {"scene", "assets"},
    "pipeline": {"measure", "solver", "physics", "render", "export", "scene", "pag", "assets",
                 "geometry", "_deps"},
    "outputs": {"pipeline", "export", "physics", "render", "scene", "_files"},
    "datagen": {"pipeline", "scenes", "_deps"},
    "scenes": {"datagen", "pipeline"},
    "vlm": {"datagen"},
    "layoutgen": {"datagen"},
    "web": {"datagen"},
    "cli": {"*"},
    "__main__": {"cli"},
    "parse3d": {"*"},  # the package's own __init__: the public API re-exports
}

@cache
def allowed(pkg: str) -> frozenset[str]:
    """Every package ``pkg`` may import: its row, and recursively what those may import."""
    out: set[str] = set()
    todo = list(LAYERS.get(pkg, set()))
    while todo:
        p = todo.pop()
        if p == "*":
            return frozenset(LAYERS)
        if p not in out:
            out.add(p)
            todo += [q for q in LAYERS.get(p, set()) if q != p]
    return frozenset(out)


def _package(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "parse3d"


def imports() -> list[tuple[str, str, str, int]]:
    """``(importing module, imported module, file, line)`` of every parse3d import."""
    out = []
    for f in sorted(SRC.rglob("*.py")):
        rel = f.relative_to(SRC.parent).with_suffix("")
        parts = list(rel.parts)
        is_init = parts[-1] == "__init__"
        if is_init:
            parts = parts[:-1]
        mod = ".".join(parts)
        pkg_parts = parts if is_init else parts[:-1]
        for node in ast.walk(ast.parse(f.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = pkg_parts[:len(pkg_parts) - (node.level - 1)]
                    if node.module:
                        targets = [".".join(base + [node.module])]
                    else:
                        targets = [".".join(base + [a.name]) for a in node.names]
                else:
                    targets = [node.module or ""]
            else:
                continue
            out += [(mod, t, str(f.relative_to(SRC.parent)), node.lineno)
                    for t in targets if t == "parse3d" or t.startswith("parse3d.")]
    return out


def test_every_package_is_in_the_table():
    pkgs = {p.name for p in SRC.iterdir() if p.is_dir() and (p / "__init__.py").exists()}
    pkgs |= {p.stem for p in SRC.glob("*.py") if p.stem != "__init__"}
    assert pkgs - set(LAYERS) == set(), "add new packages to DESIGN §2 and to LAYERS"


def test_imports_follow_the_layers():
    bad = []
    for mod, target, file, line in imports():
        a, b = _package(mod), _package(target)
        if a == b or b in allowed(a):
            continue
        bad.append(f"{file}:{line}: {a} imports {target}")
    assert bad == [], "layering violations (DESIGN §2):\n" + "\n".join(bad)


@pytest.mark.parametrize("low, high", [("pag", "solver"), ("scene", "physics"),
                                       ("geometry", "pag"), ("assets", "scene")])
def test_the_contract_rejects_an_upward_import(low, high):
    assert high not in allowed(low)


#: Inside the solver, each module's level: a module imports only modules of lower levels (the
#: stages of Algorithm 1 build on the relation rules, the rules on the solver's state).
SOLVER_LEVELS: dict[str, int] = {
    "config": 0, "geometry": 0, "collision": 0, "library": 0, "walls": 0, "resting": 0,
    "state": 1, "intent": 1,
    "support": 2, "flush": 2, "bars": 2, "coverings": 3,
    "rules.base": 3, "rows": 3,
    "rules.support": 4, "rules.contact": 4, "rules.alignment": 4, "rules.layout": 4,
    "rules": 5,
    "regions": 6, "rotation": 6,
    "nesting": 6,
    "hanging": 7, "ledge": 7,
    "standing": 8, "leaning": 8, "fit": 8, "slots": 8,
    "choice": 9, "validation": 9,
    "sampling": 10, "upright": 10,
    "stacking": 11, "mounting": 11, "over": 11,
    "placement": 12,
    "search": 13,
    "__init__": 14,
}

#: Imports up the levels, made inside a function: leaning on an object's face (a finite
#: patch, not a plane) is worked out in ``leaning`` for the rotation and the contact rule.
SOLVER_UPWARD = {("rotation", "leaning"), ("rules.contact", "leaning")}


def _solver_module(name: str) -> str:
    return name[len("parse3d.solver"):].lstrip(".") or "__init__"


def test_every_solver_module_has_a_level():
    solver = SRC / "solver"
    mods = {_solver_module("parse3d." + ".".join(f.relative_to(SRC).with_suffix("").parts)
                           .replace(".__init__", "")) for f in solver.rglob("*.py")}
    assert mods - set(SOLVER_LEVELS) == set(), "add new solver modules to SOLVER_LEVELS"


def test_solver_modules_import_only_lower_levels():
    bad = []
    for mod, target, file, line in imports():
        if not (mod.startswith("parse3d.solver") and target.startswith("parse3d.solver")):
            continue
        a, b = _solver_module(mod), _solver_module(target)
        if a == b or (a, b) in SOLVER_UPWARD:
            continue
        if SOLVER_LEVELS.get(b, 99) >= SOLVER_LEVELS.get(a, -1):
            bad.append(f"{file}:{line}: solver.{a} imports solver.{b}")
    assert bad == [], "solver layering (SOLVER_LEVELS):\n" + "\n".join(bad)


def test_every_relation_has_exactly_one_rule_that_agrees_with_its_flags():
    from parse3d.relations import OBJECT, RELATIONS, SUPPORT
    from parse3d.solver.rules import RULES

    assert set(RULES) == set(RELATIONS)
    rules = {id(r): r for r in RULES.values()}.values()
    for name, rel in RELATIONS.items():
        assert sum(name in r.names for r in rules) == 1, name
        rule = RULES[name]
        assert type(rule).__module__ == f"parse3d.solver.rules.{rule.family}", name
        assert rule.kind == rel.kind, name
        assert rule.contact == rel.is_contact, name
        assert rule.region_phase in ("object", "part", "none"), name
        # support is hard; object-level relations relax before part-level contacts
        assert (rule.relax_order is None) == rel.is_support, name
        if rel.kind == OBJECT:
            assert rule.relax_order < min(r.relax_order for r in rules
                                          if r.kind not in (OBJECT, SUPPORT)), name
            assert rule.region_phase != "part", name
        if rel.kind != SUPPORT:
            assert not (rule.fixed or rule.hangs or rule.banded), name


def test_a_relation_cannot_get_a_second_rule():
    from parse3d.solver.rules.base import RelationRule, register

    class Another(RelationRule):
        names = ("NEAR",)

    with pytest.raises(ValueError, match="NEAR already has a rule"):
        register(Another)
