"""``parse3d assets``: list, inspect, picture, pre-build and extend the asset library."""

from __future__ import annotations

import difflib
import math
from pathlib import Path

import typer

from .._deps import require
from ..errors import InputError, Problem, VocabularyError
from ._common import console, print_json

__all__ = ["register"]

assets_app = typer.Typer(
    name="assets",
    help="The asset library: categories, their parts, pictures, the pre-built pool, user assets.",
    no_args_is_help=True,
)


def _category(name: str):
    from ..assets import registry

    cats = registry.categories()
    if name in cats:
        return cats[name]
    close = difflib.get_close_matches(name, list(cats), n=1)
    hint = f" — did you mean {close[0]!r}?" if close else " (see `parse3d assets list`)"
    raise VocabularyError(Problem("", f"unknown category {name!r}{hint}", "<command line>", "vocabulary"))


def _generate(category: str, seed: int):
    from ..assets import registry

    _category(category)
    return registry.generate(category, seed)


@assets_app.command("list")
def list_(json_: bool = typer.Option(False, "--json", help="Print JSON.")) -> None:
    """List categories with their part vocabulary and size range.

    Example: parse3d assets list --json
    """
    from ..assets import registry

    rows = [{"category": c.name, "parts": list(c.vocabulary), "required": list(c.parts),
             "size_range": [float(c.size_range[0]), float(c.size_range[1])],
             "placement": c.placement, "variants": list(c.variants), "source": c.source}
            for c in registry.categories().values()]
    if json_:
        print_json(rows)
        return
    from rich.padding import Padding
    from rich.table import Table
    from rich.text import Text

    def parts_of(r: dict) -> str:
        # required parts in bold, and starred for output without styles (a pipe, a file)
        return ", ".join(f"[bold]{p}*[/bold]" if p in r["required"] else p for p in r["parts"])

    out = console.get()
    if out.width >= 140:
        t = Table("category", "parts (* every variant has it)", "size (m)", "placement", "variants")
        for r in rows:
            t.add_row(r["category"], parts_of(r),
                      f"{r['size_range'][0]:.2f}–{r['size_range'][1]:.2f}", r["placement"],
                      ", ".join(r["variants"]))
        out.print(t)
    else:
        # a narrow terminal: one heading line per category, its parts wrapped beneath
        out.print("[dim]category  size range (m)  placement  (variants)\n"
                  "    parts (* every variant has it)[/dim]")
        for r in rows:
            variants = f"  [dim]({', '.join(r['variants'])})[/dim]" if r["variants"] else ""
            out.print(f"[bold cyan]{r['category']}[/bold cyan]  "
                      f"{r['size_range'][0]:.2f}–{r['size_range'][1]:.2f}  {r['placement']}"
                      f"{variants}", overflow="fold")
            out.print(Padding(Text.from_markup(parts_of(r)), (0, 0, 0, 4)), soft_wrap=False)
    console.print(f"{len(rows)} categories")


@assets_app.command("show")
def show(category: str = typer.Argument(..., help="Category name."),
         seed: int = typer.Option(0, "--seed", min=0, max=2**32 - 1, help="Asset seed."),
         json_: bool = typer.Option(False, "--json", help="Print JSON.")) -> None:
    """Show one asset: parts, their surfaces (normal, area), internal surfaces, size.

    Example: parse3d assets show mug --seed 3
    """
    asset = _generate(category, seed)
    summary = asset.summary()
    summary["size"] = round(asset.size, 4)
    summary["variant_parts"] = _variant_parts(category)
    if json_:
        print_json(summary)
        return
    from rich.table import Table

    console.print(f"[bold]{asset.asset_id}[/bold]  size {asset.size:.3f} m  extents "
                  f"{[round(float(x), 3) for x in asset.extents]}  mass {asset.mass:.2f} kg")
    # What a PAG can name comes first: each part label, how to reference it, what it is made of
    by_label: dict[str, list] = {}
    for p in asset.parts:
        by_label.setdefault(p.label, []).append(p)
    t = Table("label", "count", f"reference (object id {category!r})", "material",
              title="parts a PAG can name",
              title_justify="left")
    for label, ps in by_label.items():
        ref = (f"{category}:{label}" if len(ps) == 1
               else f"{category}:{label}#k  (k = 0..{len(ps) - 1}: bottom to top, then "
                    "left to right)")
        t.add_row(label, str(len(ps)), ref,
                  ", ".join(dict.fromkeys(p.material.name for p in ps)))
    console.print(t)
    if asset.internal:
        t2 = Table("internal surface of", "height (m)", "area (m²)", "clearance (m)", "depth (m)",
                   title="internal surfaces (targets of IN)", title_justify="left")
        for s in asset.internal:
            t2.add_row(s.part, f"{s.surface.origin[2]:.3f}", f"{s.surface.area:.4f}",
                       "open" if s.clearance == float("inf") else f"{s.clearance:.3f}", f"{s.depth:.3f}")
        console.print(t2)
    if asset.joints:
        console.print("joints: " + ", ".join(
            f"{j.child_part} ({j.type} on {j.parent_part})" for j in asset.joints))
    spread = {k: v for k, v in summary["variant_parts"].items()
              if len(v["variants"]) < len(_variants(category)) or v["min"] != v["max"]}
    if spread:
        # what another draw of the category may have: counts differ by variant and seed, so a
        # `#k` valid here may not be on every asset (the solver draws one that has it)
        t4 = Table("label", "count", "variants that have it",
                   title=f"parts that differ between assets ({VARIANT_SEEDS} seeds of each variant)",
                   title_justify="left")
        for label, v in spread.items():
            count = str(v["min"]) if v["min"] == v["max"] else f"{v['min']}–{v['max']}"
            t4.add_row(label, count, ", ".join(v["variants"]))
        console.print(t4)
    # then the detail: every part's six directional surfaces
    t3 = Table("part", "label", "pieces", "surfaces (area m²; * = bounding-box fallback)",
               title="surfaces of each part", title_justify="left")
    for p in asset.parts:
        surf = "  ".join(f"{k}{'*' if s.source == 'bbox' else ''} {s.area:.4f}"
                         for k, s in p.surfaces.items())
        t3.add_row(p.name, p.label, str(len(p.pieces)), surf)
    console.print(t3)


#: Seeds of each variant `assets show` looks at for the parts that differ between assets.
VARIANT_SEEDS = 3


def _variants(category: str) -> tuple[str, ...]:
    from ..assets import registry

    cat = registry.get(category)
    return cat.variants if cat.generator is not None else ()


def _variant_parts(category: str) -> dict[str, dict]:
    """Label -> ``{"min", "max", "variants"}``: how many parts of each label the category's
    assets have over ``VARIANT_SEEDS`` seeds of every variant (counts of 0 included in
    ``min``), and the variants where some asset has one. Empty for a loaded category."""
    from collections import Counter

    from ..assets import registry

    drawn = [(v, Counter(p.label for p in registry.generate(category, s, v).parts))
             for v in _variants(category) for s in range(VARIANT_SEEDS)]
    labels = dict.fromkeys(label for _, c in drawn for label in c)
    return {label: {"min": min(c[label] for _, c in drawn), "max": max(c[label] for _, c in drawn),
                    "variants": list(dict.fromkeys(v for v, c in drawn if c[label]))}
            for label in labels}


@assets_app.command("render")
def render(category: str = typer.Argument(..., help="Category name."),
           seed: int = typer.Option(0, "--seed", min=0, max=2**32 - 1, help="Asset seed."),
           out: Path = typer.Option(..., "-o", "--out", help="PNG file to write.")) -> None:
    """Render one asset with its materials, seen from the front-right (a thumbnail).

    Example: parse3d assets render desk --seed 2 -o desk.png
    """
    from ..render.gallery import save_thumbnail

    require("moderngl", feature="assets render")
    asset = _generate(category, seed)
    save_thumbnail(asset, out)
    console.print(f"wrote {out}")


@assets_app.command("gallery")
def gallery(out: Path = typer.Option(Path("gallery.png"), "--out", "-o",
                                     help="PNG file (default: gallery.png here)."),
            seeds: int = typer.Option(3, "--seeds", min=1, max=20,
                                      help="Assets per category, 1..20."),
            categories: str = typer.Option("", "--categories", help="Comma-separated subset.")) -> None:
    """A contact sheet of every category (or a subset) over a few seeds.

    Example: parse3d assets gallery --out gallery.png --seeds 3
    """
    from rich.progress import track

    from ..assets import registry
    from ..render.gallery import contact_sheet

    require("moderngl", feature="assets gallery")
    names = [c.strip() for c in categories.split(",") if c.strip()] or list(registry.categories())
    for n in names:
        _category(n)
    rows = [(n, [registry.generate(n, s) for s in range(seeds)])
            for n in track(names, description="generating", console=console.get())]
    contact_sheet(rows, out)
    console.print(f"wrote {out} ({len(rows)} categories x {seeds} seeds)")


@assets_app.command("build")
def build(per_category: int = typer.Option(20, "--per-category", min=1, max=10_000,
                                          help="Assets per category (K), 1..10000."),
          workers: int = typer.Option(2, "--workers", min=1, max=512, help="Worker processes."),
          categories: str = typer.Option("", "--categories", help="Comma-separated subset."),
          json_: bool = typer.Option(False, "--json", help="Print JSON.")) -> None:
    """Pre-generate the asset pool (K assets per category) into the cache.

    Example: parse3d assets build --per-category 20 --workers 2
    """
    from ..assets.pool import AssetPool

    names = [c.strip() for c in categories.split(",") if c.strip()] or None
    for n in names or []:
        _category(n)
    pool = AssetPool(per_category=per_category)
    rep = pool.build(names, workers=workers, progress=not json_)
    data = {"root": str(pool.root), "generated": rep.generated, "cached": rep.cached,
            "seconds": round(rep.seconds, 2),
            "median_seconds_per_category": {k: round(v, 4) for k, v in rep.per_category.items()},
            "failures": rep.failures}
    if json_:
        print_json(data)
    else:
        console.print(f"pool {pool.root}: {rep.generated} generated, {rep.cached} already cached, "
                      f"{rep.seconds:.1f} s")
        for k, v in rep.failures.items():
            console.print(f"[red]failed[/red] {k}: {v}")
    if rep.failures:
        raise typer.Exit(1)


def _parse_range(text: str | None) -> tuple[float, float] | None:
    if not text:
        return None
    try:
        lo, hi = (float(x) for x in text.split(","))
        if not (math.isfinite(lo) and math.isfinite(hi)):
            raise ValueError
    except ValueError:
        raise InputError(Problem("", f"--size-range {text!r} must be two numbers 'low,high' in metres",
                                 "<command line>", "parameter")) from None
    return lo, hi


@assets_app.command("add")
def add(src: Path = typer.Argument(..., help="Folder of .glb/.gltf files and/or PartNet-Mobility folders."),
        category: str = typer.Option(..., "--category", help="Category to create or extend."),
        mapping: Path = typer.Option(None, "--mapping", help="JSON/YAML {node or link name: part label}."),
        parts: str = typer.Option("", "--parts", help="Part vocabulary of a new category, comma-separated."),
        size_range: str = typer.Option("", "--size-range", help="'low,high': largest extent in metres."),
        up: str = typer.Option("", "--up", help="Source up axis (z, y, -y...); default per format."),
        front: str = typer.Option("", "--front", help="Source front axis (+z, -x...); default per format."),
        scale: float = typer.Option(1.0, "--scale", help="Metres per source unit."),
        placement: str = typer.Option("", "--placement", help="floor, surface, wall, ceiling or inside."),
        json_: bool = typer.Option(False, "--json", help="Print JSON.")) -> None:
    """Add real part-split assets to the user library.

    Example: parse3d assets add ./my_chairs --category armchair --mapping map.json --up y --front +z
    """
    from ..assets.loaders import GLTF_FRAME, PARTNET_FRAME, SourceFrame, add_assets, find_sources

    if not src.exists():
        raise InputError(Problem("", "folder not found", str(src), "io"))
    frame = None
    if up or front or scale != 1.0:
        # fill what was not given from the format's own convention
        sources = find_sources(src) if src.exists() else []
        base = PARTNET_FRAME if sources and sources[0].is_dir() else GLTF_FRAME
        if up and not front:
            raise InputError(Problem("", "--up needs --front as well (the front axis must be "
                                     "perpendicular to the up axis)", "<command line>", "parameter"))
        if not (math.isfinite(scale) and 1e-6 <= scale <= 1e6):
            raise InputError(Problem("", f"--scale {scale} must be a finite number of metres per "
                                     "source unit in [1e-6, 1e6]", "--scale", "parameter"))
        frame = SourceFrame(up or base.up, front or base.front, scale)
    cat = add_assets(src, category=category, mapping=mapping,
                     parts=tuple(p.strip() for p in parts.split(",") if p.strip()) or None,
                     size_range=_parse_range(size_range), frame=frame,
                     placement=placement or None)
    data = {"category": cat.name, "parts": list(cat.vocabulary), "required": list(cat.parts),
            "size_range": list(cat.size_range), "assets": list(cat.loaded_assets),
            "procedural": cat.generator is not None}
    if json_:
        print_json(data)
    else:
        kind = "added to procedural category" if cat.generator is not None else "category"
        console.print(f"{kind} {cat.name!r}: {len(cat.loaded_assets)} loaded asset(s), parts "
                      f"{', '.join(cat.vocabulary)}; size {cat.size_range[0]:.2f}–{cat.size_range[1]:.2f} m")


# --------------------------------------------------------------------------- assets words
def _look_up(resolver, text: str) -> dict:
    """What one word (``throw``) or reference (``book:cover@front``) names: a category, a
    synonym's or hypernym's categories, or a part label; else the problem with suggestions."""
    from ..words import normalize, singulars, suggest

    ref, _, surface = text.partition("@")
    word, _, part = ref.partition(":")
    part = part.split("#", 1)[0]
    row: dict = {"word": text}
    cats = resolver.categories_for(word)
    if cats is None:
        row["problem"] = f"no category {word!r}" + (
            suggest(word, resolver.words()) or " (see `parse3d assets words`)")
        return row
    w = normalize(word)
    lex = resolver.lex
    form = next((f for f in [w, *singulars(w)]
                 if f in lex.hypernyms or f in cats or f in lex.synonyms), w)
    row["kind"] = ("hypernym" if form in lex.hypernyms else
                   "category" if form in cats else "synonym")
    row["categories"] = list(cats)
    if not part:
        row["part_words"] = {c: resolver.part_words(c) for c in cats}
        return row
    labels, problems = {}, []
    for c in cats:
        r = resolver.part(c, part, surface or None)
        if r.label is not None:
            labels[c] = r.label
        else:
            problems.append(r.problem)
    row["part"] = labels
    if not labels:
        row["problem"] = problems[0]
    return row


@assets_app.command("words")
def words(items: list[str] = typer.Argument(None, help="Words or references to look up "
                                            "(`throw`, `chair`, `book:cover@front`)."),
          json_: bool = typer.Option(False, "--json", help="Print JSON.")) -> None:
    """The words a PAG may use besides category names: with no argument every synonym and
    hypernym of the vocabulary file; with words, what each names (its categories, and for
    `object:part@surface` the part label), or suggestions. Exits 2 when a word names nothing.

    Example: parse3d assets words throw chair book:cover@front
    """
    from ..words import Resolver
    from ._vocab import cli_vocabulary

    resolver = Resolver(cli_vocabulary())
    if not items:
        lex = resolver.lex
        rows = ([{"word": w, "kind": "synonym", "categories": list(resolver.categories_for(w))}
                 for w in sorted(lex.synonyms) if resolver.categories_for(w)]
                + [{"word": w, "kind": "hypernym", "categories": list(resolver.categories_for(w))}
                   for w in sorted(lex.hypernyms) if resolver.categories_for(w)])
        if json_:
            print_json(rows)
            return
        for r in rows:
            arrow = "any of" if r["kind"] == "hypernym" else "is"
            console.print(f"{r['word']:<24} {arrow} {', '.join(r['categories'])}", highlight=False,
                          markup=False, soft_wrap=True)
        console.print(f"{sum(r['kind'] == 'synonym' for r in rows)} synonyms, "
                      f"{sum(r['kind'] == 'hypernym' for r in rows)} hypernyms; a category's own "
                      "name, its plural and any case, spaces or hyphens work too", highlight=False)
        return
    rows = [_look_up(resolver, t) for t in items]
    if json_:
        print_json(rows)
    else:
        for r in rows:
            if "problem" in r:
                console.print(f"{r['word']}: {r['problem']}", highlight=False, markup=False)
            elif "part" in r:
                got = ", ".join(f"{c}:{lab}" for c, lab in r["part"].items())
                console.print(f"{r['word']}: the part {got}", highlight=False, markup=False)
            else:
                say = {"category": "the category", "synonym": "a synonym of",
                       "hypernym": "any of (one is drawn)"}[r["kind"]]
                console.print(f"{r['word']}: {say} {', '.join(r['categories'])}",
                              highlight=False, markup=False)
                for c, ws in r["part_words"].items():
                    console.print(f"    {c} parts: {', '.join(ws)}", highlight=False,
                                  markup=False, soft_wrap=True)
    if any("problem" in r for r in rows):
        raise typer.Exit(2)


# --------------------------------------------------------------------------- assets stats
@assets_app.command("stats")
def stats(seeds: int = typer.Option(3, "--seeds", min=1, help="Assets per category (the first pool slots)."),
          categories: str = typer.Option("", "--categories", help="Comma-separated subset."),
          json_: bool = typer.Option(False, "--json", help="Print JSON.")) -> None:
    """Library breadth and depth: ScanNet200's object labels that resolve to a category,
    categories, variants, parts per asset (mean, p10), articulated categories, generation time
    per asset (median), beside the paper's figures. A progress bar shows on stderr.

    Example: parse3d assets stats --seeds 3 --json
    """
    from ..assets.stats import library_stats

    names = [c.strip() for c in categories.split(",") if c.strip()] or None
    for n in names or []:
        _category(n)
    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn

    from ..assets import registry

    total = len(names) if names else len(registry.categories())
    # the bar goes to stderr, so that --json output stays clean
    with Progress(TextColumn("generating {task.description:<28}"), BarColumn(), MofNCompleteColumn(),
                  console=Console(stderr=True), transient=True) as bar:
        task = bar.add_task("", total=total)
        seen: list[str] = []

        def step(name: str) -> None:  # called before each category is measured
            bar.update(task, description=name, completed=len(seen))
            seen.append(name)

        st = library_stats(names, seeds=seeds, progress=step)
    if json_:
        print_json(st.to_dict())
        return
    from rich.table import Table

    t = Table("measure", "parse3d", "paper (PARSE-10K)")
    t.add_row("categories", str(st.categories), str(st.paper["categories"]))
    ref = st.scannet200
    t.add_row("ScanNet200 object labels resolved",
              f"{ref['resolved']} / {ref['object_labels']} ({ref['fraction']:.0%})", "")
    t.add_row("structural variants", str(st.variants), "")
    t.add_row("parts per asset (mean)", f"{st.parts_per_asset_mean:.1f}", f"{st.paper['parts_per_asset_mean']:.1f}")
    t.add_row("parts per asset (p10 / median)", f"{st.parts_per_asset_p10:.0f} / {st.parts_per_asset_median:.0f}", "")
    t.add_row("articulated categories", str(len(st.articulated_categories)), "")
    t.add_row("movable joints per asset (mean)", f"{st.joints_per_asset_mean:.2f}", "")
    t.add_row("generation time per asset (median / p90)", f"{st.generation_ms_median:.0f} / {st.generation_ms_p90:.0f} ms", "")
    console.print(t)
    console.print(f"{st.assets} assets ({seeds} per category); articulated: "
                  f"{', '.join(st.articulated_categories) or 'none'}")
    if ref["unresolved"]:
        console.print(f"ScanNet200 labels without a category: {', '.join(ref['unresolved'])}")


def register(app: typer.Typer) -> None:
    """Add the ``assets`` command group to the ``parse3d`` app."""
    app.add_typer(assets_app, name="assets")
