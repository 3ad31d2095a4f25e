"""``parse3d vlm build``: a built dataset -> the VLM benchmark (JSONL splits and a card).

Output folder::

    VLM_DIR/
      vlm.json                 the card (format parse3d-vlm/1): settings, counts per split,
                               task, relation, answer letter and room type, "no contact" share
      train.jsonl val.jsonl test.jsonl
      dataset_info.json        the three splits declared for LLaMA-Factory (sharegpt layout)
      images/NNNNN/vK.jpg      the view (SGG) and copies with the red/blue boxes (MCQ)
      renders/NNNNN/           views rendered by --views for scenes that had too few

One JSONL line per question, in the ``messages`` + ``images`` layout of LLaMA-Factory and
ms-swift (image paths relative to the JSONL's folder)::

    {"id": "00012-v1-rel0", "task": "relation_mcq", "scene": "00012", "view": 1,
     "messages": [{"role": "user", "content": "<image>The image displays ..."},
                  {"role": "assistant", "content": "C"}],
     "images": ["images/00012/v1-rel0.jpg"],
     "meta": {"room_type": "study", "answer": "C", "relation": "ON", "options": [...]}}

The same dataset, settings and seed give the same files.
"""

from __future__ import annotations

import json
import os
import time
from collections import Counter
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from PIL import Image, ImageDraw

from .._files import read_json
from ..errors import InputError, Problem
from .balance import (
    ContactCandidate,
    ContactPrior,
    RelationQuestion,
    contact_candidates,
    contact_counts,
    contact_prior,
    plan_contact_questions,
    plan_relation_questions,
    relation_asked,
    relation_candidates,
)
from .facts import SceneFacts, VisibilityRule, load_scene_facts, view_facts
from .items import (
    LETTERS,
    Item,
    TaskLimits,
    contact_items,
    relation_items,
    sgg_item,
)
from .vocab import NO_CONTACT, RELATION_PHRASES, object_label, part_label

__all__ = ["VLM_FORMAT", "TASKS", "BuildOptions", "BuildResult", "build_benchmark",
           "scene_folders", "split_scenes", "read_jsonl", "candidate_objects", "part_map",
           "record_schema"]

VLM_FORMAT = "parse3d-vlm/1"
TASKS = ("relation_mcq", "contact_mcq", "sgg")
_SHORT = {"relation_mcq": "rel", "contact_mcq": "con", "sgg": "sgg"}
_COLORS = {"red": (230, 25, 25), "blue": (30, 80, 240)}


@dataclass(frozen=True)
class BuildOptions:
    """Settings of a benchmark build (saved in ``vlm.json``).

    Attributes
    ----------
    seed : int
        Splits, pairs, distractors and answer letters derive from it.
    views : int
        Views per scene; scenes with fewer rendered views get this many rendered under
        ``VLM_DIR/renders`` (0: use the dataset's views and render none).
    boxes : str
        SGG boxes: ``projected`` (3-D boxes, the paper) or ``mask``.
    split : (float, float, float)
        Train/val/test shares of the scenes.
    visibility : VisibilityRule
    limits : TaskLimits
    jpeg_quality : int
    """

    seed: int = 0
    views: int = 0
    boxes: str = "projected"
    split: tuple[float, float, float] = (0.8, 0.1, 0.1)
    visibility: VisibilityRule = field(default_factory=VisibilityRule)
    limits: TaskLimits = field(default_factory=TaskLimits)
    jpeg_quality: int = 90


@dataclass
class BuildResult:
    """What a build wrote: the card and its wall time (seconds)."""

    out: Path
    card: dict[str, Any]
    wall: float
    rendered: int = 0


def record_schema() -> dict[str, Any]:
    """The JSON Schema of one benchmark record (``vlm-record-1.schema.json``)."""
    return json.loads((Path(__file__).parent / "vlm-record-1.schema.json").read_text())


def read_jsonl(path: str | Path) -> list[dict[str, Any]]:
    """Read a JSONL file of objects through the bounded reader (a regular file of at most
    64 MiB, UTF-8, nesting at most 64 deep); a broken line is an :class:`InputError` naming it.
    """
    from .._files import read_json_lines

    rows = []
    for n, row in read_json_lines(path, what="JSON Lines file"):
        if not isinstance(row, dict):
            raise InputError(Problem(f"line {n}", "expected a JSON object", str(path), "syntax"))
        rows.append(row)
    return rows


def scene_folders(dataset: str | Path) -> list[Path]:
    """The finished scene folders of a dataset, in index order."""
    d = Path(dataset)
    if not (d / "scenes").is_dir():
        hint = " (a scene folder? pass the dataset folder above scenes/)" if (
            d / "scene.json").exists() else ""
        raise InputError(Problem("", f"not a dataset folder: no scenes/ inside{hint} — build "
                                     "one with parse3d dataset build --views 4", str(d), "io"))
    out = sorted(p for p in (d / "scenes").iterdir()
                 if p.is_dir() and (p / "scene.json").exists())
    if not out:
        raise InputError(Problem("", "the dataset has no finished scenes", str(d), "io"))
    return out


def split_scenes(names: list[str], seed: int, shares=(0.8, 0.1, 0.1)) -> dict[str, str]:
    """Scene name -> ``train`` / ``val`` / ``test`` (whole scenes; 80/10/10 by default).

    With three scenes or more, val and test get at least one scene each.
    """
    n = len(names)
    order = np.random.default_rng([int(seed), 0x53504C54]).permutation(n)
    n_test = int(round(shares[2] * n))
    n_val = int(round(shares[1] * n))
    if n >= 3:
        n_test, n_val = max(1, n_test), max(1, n_val)
    n_train = n - n_test - n_val
    out = {}
    for rank, i in enumerate(order):
        out[names[int(i)]] = ("train" if rank < n_train else
                              "val" if rank < n_train + n_val else "test")
    return out


def candidate_objects(extra: list[str] = ()) -> list[str]:
    """The SGG prompt's object names: every category label, sorted."""
    from ..assets.registry import vocabulary

    return sorted({object_label(c) for c in vocabulary().categories()} | set(extra))


def part_map() -> dict[str, list[str]]:
    """Category label -> its part labels (the prebuilt object-part mapping)."""
    from ..assets.registry import vocabulary

    v = vocabulary()
    return {object_label(c): sorted({part_label(p) for p in v.parts(c)})
            for c in v.categories()}


def _render_missing(scene_dir: Path, out: Path, n: int, seed: int) -> Path:
    """Render ``n`` views of a scene into ``out`` (never into the dataset)."""
    from ..render import Renderer, sample_views, write_views
    from ..scene.io import read_scene

    scene = read_scene(scene_dir)
    size = (640, 480)
    card = scene_dir.parent.parent / "dataset.json"
    if card.exists():  # the dataset's own view size
        doc = read_json(card, what="dataset card")
        got = doc.get("view_size", size) if isinstance(doc, dict) else None
        if not (isinstance(got, list | tuple) and len(got) == 2
                and all(isinstance(v, int) and 0 < v <= 8192 for v in got)):
            raise InputError(Problem("/view_size", "damaged dataset card: view_size must be two "
                                                   "sizes of at most 8192", str(card), "schema"))
        size = (int(got[0]), int(got[1]))
    r = Renderer()
    rng = np.random.default_rng([int(seed), 0x56494557])
    cams = sample_views(scene, n, rng, width=size[0], height=size[1], renderer=r)
    write_views(scene, cams, out, renderer=r,
                meta={"seed": int(seed), "requested_views": n, "size": list(size)})
    return out


def _draw(src: Path, marks, dst: Path, quality: int, cache: dict[Path, Image.Image]) -> None:
    img = cache.get(src)
    if img is None:
        try:
            img = Image.open(src).convert("RGB")
        except (OSError, ValueError) as e:  # missing, truncated or not an image
            raise InputError(Problem("", f"not a readable image ({e}): render the scene again",
                                     str(src), "io")) from None
        cache.clear()
        cache[src] = img
    if marks:
        img = img.copy()
        d = ImageDraw.Draw(img)
        lw = max(2, img.width // 200)
        for color, (x1, y1, x2, y2) in marks:
            d.rectangle([x1 - lw, y1 - lw, x2 + lw, y2 + lw], outline=_COLORS[color], width=lw)
    img.save(dst, quality=quality)


def _record(item: Item, rid: str, scene: SceneFacts, view: int, image: str) -> dict[str, Any]:
    meta = {"room_type": scene.room_type, **item.meta}
    return {"id": rid, "task": item.task, "scene": scene.name, "view": view,
            "messages": [{"role": "user", "content": "<image>" + item.prompt},
                         {"role": "assistant", "content": item.answer}],
            "images": [image], "meta": meta}


def _scene_views(folder: Path, out: Path, options: BuildOptions) -> tuple[Path, int]:
    """Where a scene's views are (rendering them into ``out`` when too few): folder, rendered."""
    n_views = 0
    if (folder / "views.json").exists():
        views = read_json(folder / "views.json", what="views file")
        views = views.get("views") if isinstance(views, dict) else None
        if not isinstance(views, list):
            raise InputError(Problem("/views", "damaged views file (no list of views): render "
                                               "the scene again", str(folder / "views.json"),
                                     "schema"))
        n_views = len(views)
    if options.views > 0 and n_views < options.views:
        doc = read_json(folder / "scene.json", what="scene file")
        seed = doc.get("seed", 0) if isinstance(doc, dict) else 0
        if isinstance(seed, bool) or not isinstance(seed, int) or not 0 <= seed < 2**32:
            seed = 0
        return _render_missing(folder, out / "renders" / folder.name, options.views, seed), 1
    return folder, 0


def _scene_survey(job):
    """First pass over one scene: its views (rendered when missing), its touching part pairs
    by label, and the object pairs a part-contact or relation question may ask about."""
    folder, out, options = job
    vf, rendered = _scene_views(folder, out, options)
    scene = load_scene_facts(folder, views_folder=vf)
    cands, rel_cands = [], []
    for v in scene.views:
        view = view_facts(scene, v, options.visibility)
        cands += contact_candidates(scene, view)
        rel_cands += relation_candidates(scene, view, options.visibility)
    return folder.name, vf, rendered, contact_counts(scene), cands, rel_cands


def _scene_rows(job) -> tuple[str, list[dict[str, Any]]]:
    """All records of one scene (run in the driver or a worker process)."""
    folder, vf, out, options, candidates, parts, plan, prior, questions, asked = job
    rule = options.visibility
    scene = load_scene_facts(folder, views_folder=vf)
    present = {o.label for o in scene.objects.values()}
    labels = [c for c in candidates if c not in present]
    img_dir = out / "images" / folder.name
    img_dir.mkdir(parents=True, exist_ok=True)
    cache: dict[Path, Image.Image] = {}
    counts = {t: dict.fromkeys(LETTERS, 0) for t in TASKS}
    rows = []
    for v in scene.views:
        view = view_facts(scene, v, rule)
        rng = np.random.default_rng([int(options.seed), scene.index, view.index])
        items = relation_items(scene, view, [q for q in questions if q.view == view.index],
                               asked, labels, rule, counts["relation_mcq"], rng)
        items += contact_items(scene, view, [c for c in plan if c.view == view.index], prior,
                               parts, rule, counts["contact_mcq"], rng)
        sg = sgg_item(scene, view, candidates, rule, boxes=options.boxes)
        if sg is not None:
            items.append(sg)
        per_task: Counter[str] = Counter()
        for item in items:
            k = per_task[item.task]
            per_task[item.task] += 1
            rid = f"{scene.name}-v{view.index}-{_SHORT[item.task]}{k}"
            name = (f"v{view.index}.jpg" if not item.marks
                    else f"v{view.index}-{_SHORT[item.task]}{k}.jpg")
            _draw(view.rgb, item.marks, img_dir / name, options.jpeg_quality, cache)
            rows.append(_record(item, rid, scene, view.index, f"images/{scene.name}/{name}"))
    return scene.name, rows


def _contact_plan(survey, splits: dict[str, str], options: BuildOptions
                  ) -> tuple[dict[str, list[ContactCandidate]], dict[str, ContactPrior]]:
    """The part-contact questions of every scene, balanced per split and category pair
    (:mod:`parse3d.vlm.balance`), and the prior each scene's options draw from."""
    plan: dict[str, list[ContactCandidate]] = {name: [] for name, *_ in survey}
    asked: Counter = Counter()
    for split in ("train", "val", "test"):
        cands = [c for name, _, _, _, cs, *_ in survey if splits[name] == split for c in cs]
        rng = np.random.default_rng([int(options.seed), 0x434F4E54, ("train", "val",
                                                                      "test").index(split)])
        for c in plan_contact_questions(cands, per_view=options.limits.contact, rng=rng):
            plan[c.scene].append(c)
            if split == "train":
                asked[c.key] += 1
    if not asked:  # too few training scenes: every split's questions
        asked.update(c.key for cs in plan.values() for c in cs)
    counts = {name: cnt for name, _, _, cnt, *_ in survey}
    priors = {name: contact_prior(name, counts, splits, asked) for name in plan}
    for cs in plan.values():
        cs.sort(key=lambda c: (c.view, c.a, c.b))
    return plan, priors


def _relation_plan(survey, splits: dict[str, str], options: BuildOptions
                   ) -> tuple[dict[str, list[RelationQuestion]], dict[str, list[dict]]]:
    """The relation questions of every scene, balanced per split, category pair and couple
    (:mod:`parse3d.vlm.balance`), and per split the tables the other pair of options draws
    from: how often that split asks each category pair and couple, then every split."""
    plan: dict[str, list[RelationQuestion]] = {s[0]: [] for s in survey}
    per_split: dict[str, list[RelationQuestion]] = {}
    for split in ("train", "val", "test"):
        cands = [c for s in survey if splits[s[0]] == split for c in s[5]]
        rng = np.random.default_rng([int(options.seed), 0x52454C, ("train", "val",
                                                                    "test").index(split)])
        per_split[split] = plan_relation_questions(cands, per_view=options.limits.relation,
                                                   rng=rng)
        for q in per_split[split]:
            plan[q.scene].append(q)
    for qs in plan.values():
        qs.sort(key=lambda q: (q.view, q.a, q.b))
    everything = relation_asked([q for qs in per_split.values() for q in qs])
    return plan, {split: [relation_asked(qs), everything] for split, qs in per_split.items()}


def _check_views(folders: list[Path], views: int, dataset: Path) -> None:
    if views > 0:
        return
    missing = [f.name for f in folders if not (f / "views.json").exists()]
    if missing:
        show = ", ".join(missing[:5]) + (" ..." if len(missing) > 5 else "")
        raise InputError(Problem(
            "", f"{len(missing)} of {len(folders)} scenes have no rendered views ({show}); "
                "pass --views 4 to render them into the output folder, or build the dataset "
                "with parse3d dataset build --views 4", str(dataset), "io"))


def dataset_info() -> dict[str, Any]:
    """LLaMA-Factory's ``dataset_info.json`` for a benchmark folder: ``parse3d_vlm_train``,
    ``_val`` and ``_test``, in the sharegpt layout with OpenAI-style role tags. Image paths in
    the records are relative to the folder, which LLaMA-Factory resolves against its
    ``dataset_dir`` (pass the benchmark folder)."""
    tags = {"role_tag": "role", "content_tag": "content", "user_tag": "user",
            "assistant_tag": "assistant"}
    return {f"parse3d_vlm_{split}": {"file_name": f"{split}.jsonl", "formatting": "sharegpt",
                                     "columns": {"messages": "messages", "images": "images"},
                                     "tags": tags}
            for split in ("train", "val", "test")}


def build_benchmark(dataset: str | Path, out: str | Path, options: BuildOptions = BuildOptions(),
                    *, workers: int = 1, progress=None) -> BuildResult:
    """Build the benchmark of a dataset into ``out``.

    Parameters
    ----------
    dataset : path
        A dataset folder (``parse3d dataset build``) with ``scenes/NNNNN/``.
    out : path
        The benchmark folder; created, and its JSONL files and card replaced.
    options : BuildOptions
    workers : int
        Worker processes (one scene each at a time); the output does not depend on it.
    progress : callable, optional
        Called with ``(done, total)`` after each scene of each of the two passes (the
        survey that chooses the questions, then the items): ``total`` is twice the scenes.
    """
    t0 = time.perf_counter()
    ds, out = Path(dataset), Path(out)
    if out.resolve() == ds.resolve() or ds.resolve() in out.resolve().parents:
        raise InputError(Problem("", "the output folder must be outside the dataset folder "
                                     "(the dataset is never written to)", str(out), "io"))
    if options.boxes not in ("projected", "mask"):
        raise InputError(Problem("", f"boxes must be 'projected' or 'mask', got "
                                     f"{options.boxes!r}", "--boxes", "parameter"))
    folders = scene_folders(ds)
    _check_views(folders, options.views, ds)
    splits = split_scenes([f.name for f in folders], options.seed, options.split)
    out.mkdir(parents=True, exist_ok=True)
    candidates = candidate_objects()
    parts = part_map()
    rows: dict[str, list[dict[str, Any]]] = {"train": [], "val": [], "test": []}
    pool = None
    if workers > 1 and len(folders) > 1:
        import multiprocessing as mp
        from concurrent.futures import ProcessPoolExecutor

        pool = ProcessPoolExecutor(min(workers, len(folders)),
                                   mp_context=mp.get_context("forkserver"))
    try:
        run = pool.map if pool is not None else map
        survey = []
        for done, res in enumerate(run(_scene_survey, [(f, out, options) for f in folders]),
                                   1):
            survey.append(res)
            if progress is not None:
                progress(done, 2 * len(folders))
        rendered = sum(s[2] for s in survey)
        plan, priors = _contact_plan(survey, splits, options)
        rplan, asked = _relation_plan(survey, splits, options)
        jobs = [(folder, vf, out, options, candidates, parts, plan[name], priors[name],
                 rplan[name], asked[splits[name]])
                for folder, (name, vf, *_) in zip(folders, survey, strict=True)]
        for done, (name, srows) in enumerate(run(_scene_rows, jobs), 1):
            rows[splits[name]].extend(srows)
            if progress is not None:
                progress(len(folders) + done, 2 * len(folders))
    finally:
        if pool is not None:
            pool.shutdown()
    if not any(rows.values()):  # nothing visible: say so rather than write empty splits
        raise InputError(Problem(
            "", f"no object is visible in any view of the {len(folders)} scenes (at least "
                f"{options.visibility.min_pixels} mask pixels and "
                f"{options.visibility.min_in_image:.0%} of the projection in the image): lower "
                "--min-pixels / --min-in-image, or render the views again", str(ds), "io"))
    for split, rs in rows.items():
        tmp = out / f".{split}.jsonl.tmp"
        tmp.write_text("".join(json.dumps(r) + "\n" for r in rs))
        os.replace(tmp, out / f"{split}.jsonl")
    card = _card(ds, options, splits, rows, time.perf_counter() - t0, rendered)
    (out / "vlm.json").write_text(json.dumps(card, indent=1) + "\n")
    (out / "dataset_info.json").write_text(json.dumps(dataset_info(), indent=1) + "\n")
    return BuildResult(out, card, time.perf_counter() - t0, rendered)


def _card(ds: Path, options: BuildOptions, splits: dict[str, str],
          rows: dict[str, list[dict[str, Any]]], wall: float, rendered: int) -> dict[str, Any]:
    def counts(rs: list[dict[str, Any]]) -> dict[str, Any]:
        task = Counter(r["task"] for r in rs)
        rel = Counter(r["meta"]["relation"] for r in rs if r["task"] == "relation_mcq")
        sgg_rel = Counter(t[1] for r in rs if r["task"] == "sgg" for t in r["meta"]["triplets"])
        letters = {t: dict(sorted(Counter(r["meta"]["answer"] for r in rs
                                          if r["task"] == t).items()))
                   for t in ("relation_mcq", "contact_mcq")}
        rooms = Counter(r["meta"]["room_type"] for r in rs)
        n_rel = task.get("relation_mcq", 0)
        n_con = task.get("contact_mcq", 0)
        nc_rel = rel.get(NO_CONTACT, 0)
        nc_con = sum(1 for r in rs if r["task"] == "contact_mcq"
                     and r["meta"]["relation"] == "no contact")
        return {"items": len(rs), "tasks": dict(sorted(task.items())),
                "relations": {RELATION_PHRASES[k]: v for k, v in sorted(rel.items())},
                "sgg_relations": dict(sorted(sgg_rel.items())),
                "answer_letters": letters, "room_types": dict(sorted(rooms.items())),
                "no_contact_share": {
                    "relation_mcq": round(nc_rel / n_rel, 4) if n_rel else 0.0,
                    "contact_mcq": round(nc_con / n_con, 4) if n_con else 0.0},
                "sgg_objects": sum(len(r["meta"]["objects"]) for r in rs if r["task"] == "sgg"),
                "sgg_triplets": sum(len(r["meta"]["triplets"]) for r in rs
                                    if r["task"] == "sgg")}

    everything = [r for rs in rows.values() for r in rs]
    opts = asdict(options)
    return {"format": VLM_FORMAT, "dataset": str(ds.resolve()), "options": opts,
            "scenes": {s: sorted(n for n, v in splits.items() if v == s)
                       for s in ("train", "val", "test")},
            "vocabulary": {"relations": dict(RELATION_PHRASES)},
            "counts": {"all": counts(everything), **{s: counts(rs) for s, rs in rows.items()}},
            "rendered_scenes": rendered, "wall_s": round(wall, 2)}
