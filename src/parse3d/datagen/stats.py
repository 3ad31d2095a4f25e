"""Statistics of a built dataset, as the paper reports them for PARSE-10K.

:func:`dataset_stats` reads ``DIR/manifest.parquet`` and ``DIR/dataset.json`` (no scene file
is opened); :func:`write_stats` draws the paper's figures as PNG files and writes the summary
and the comparison with the paper's Table 1 as Markdown and JSON:

===========================  =================================================================
``categories.png``           object instances per category (paper: "Distribution of Object
                             Categories")
``parts_per_object.png``     parts per distinct asset used ("Number of Parts per Object")
``room_types.png``           scenes per room type ("Distribution of Room Types")
``object_density.png``       placed objects per m² of floor, with the 1.35 threshold
``contacts_per_scene.png``   part-level contacts per scene, with the 50 threshold
``objects_per_scene.png``    placed objects per scene
``stats.md``, ``stats.json`` the summary and Table 1
===========================  =================================================================

Counting rules: statistics are over the scenes written (status ``ok`` or ``incomplete``); an
object counts when the solver placed it; "#objects" in Table 1 is the number of distinct assets the scenes use
(the paper's column counts its asset library); contacts are all edges of the part-level
contact graph (room shell included), as written to ``contacts.json``.
"""

from __future__ import annotations

import json
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .._files import read_json
from ..errors import InputError, Problem

__all__ = ["PAPER_TABLE", "DENSITY_THRESHOLD", "CONTACTS_THRESHOLD", "DatasetStats",
           "dataset_stats", "write_stats"]

#: Objects per m² above which the paper counts a scene as dense (more than 55% of PARSE-10K).
DENSITY_THRESHOLD = 1.35
#: Part-level contacts above which the paper counts a scene as contact-rich (more than 57%).
CONTACTS_THRESHOLD = 50

#: The rows of the paper's Table 1 (comparison of indoor 3D scene datasets).
PAPER_TABLE: tuple[dict[str, Any], ...] = (
    {"dataset": "HSSD-200", "scenes": 211, "objects": 18656, "avg_objects": 329.7,
     "layout": "Human-designed", "physics": False, "parts": False, "part_contacts": False},
    {"dataset": "3D-FRONT", "scenes": 18968, "objects": 13151, "avg_objects": 6.9,
     "layout": "Human-designed", "physics": False, "parts": False, "part_contacts": False},
    {"dataset": "FurniScene", "scenes": 111698, "objects": 39691, "avg_objects": 14.4,
     "layout": "Human-designed", "physics": False, "parts": False, "part_contacts": False},
    {"dataset": "METASCENES", "scenes": 706, "objects": 15366, "avg_objects": None,
     "layout": "Real-world scanned", "physics": True, "parts": False, "part_contacts": False},
    {"dataset": "PARSE-10K (paper)", "scenes": 10000, "objects": 17372, "avg_objects": 49.9,
     "layout": "Real-image guided", "physics": True, "parts": True, "part_contacts": True},
)


@dataclass
class DatasetStats:
    """What :func:`dataset_stats` measured.

    Attributes
    ----------
    name : str
        The dataset folder's name.
    config : dict
        ``dataset.json``.
    status : dict of str to int
        Scenes per status (``ok``, ``failed``, ``timeout``).
    rows : list of dict
        Manifest rows of the written scenes (``ok`` or ``incomplete``), by index.
    """

    name: str
    config: dict[str, Any]
    status: dict[str, int]
    rows: list[dict[str, Any]] = field(default_factory=list)

    # ---- derived arrays -------------------------------------------------------------------
    def _col(self, key: str) -> np.ndarray:
        return np.array([r[key] if r[key] is not None else np.nan for r in self.rows], float)

    @property
    def objects_per_scene(self) -> np.ndarray:
        """(S,) placed objects per ok scene."""
        return self._col("placed")

    @property
    def density(self) -> np.ndarray:
        """(S,) placed objects per m² of floor."""
        return self._col("density")

    @property
    def contacts(self) -> np.ndarray:
        """(S,) part-level contacts per scene (NaN where not settled)."""
        return self._col("contacts")

    @property
    def categories(self) -> Counter:
        """Object instances per category."""
        return Counter(c for r in self.rows for c in r["categories"])

    @property
    def room_types(self) -> Counter:
        return Counter(r["room_type"] for r in self.rows)

    @property
    def parts_per_asset(self) -> np.ndarray:
        """(A,) number of parts of every distinct asset used."""
        seen: dict[str, int] = {}
        for r in self.rows:
            for a, p in zip(r["assets"], r["parts"], strict=True):
                seen.setdefault(a, int(p))
        return np.array(list(seen.values()), int)

    # ---- tables ----------------------------------------------------------------------------
    def table(self) -> dict[str, Any]:
        """The summary and Table 1 as JSON-ready data."""
        n = len(self.rows)
        obj = self.objects_per_scene
        dens = self.density
        con = self.contacts
        parts = self.parts_per_asset
        placed = sum(int(r["placed"]) for r in self.rows)
        wanted = sum(int(r["objects"]) for r in self.rows)
        settled = bool(self.config.get("settle", True))
        has_con = n > 0 and not np.isnan(con).all()
        src = (self.config.get("source") or {}).get("kind", "templates")

        cats = self.categories
        total = sum(cats.values())
        top = cats.most_common(1)[0] if total else None

        def share(x: np.ndarray, thr: float) -> float | None:
            x = x[~np.isnan(x)]
            return round(float(np.mean(x > thr)), 4) if x.size else None

        def mean(x: np.ndarray) -> float | None:
            x = x[~np.isnan(x)] if x.dtype.kind == "f" else x
            return round(float(np.mean(x)), 2) if x.size else None

        summary = {
            "scenes": n,
            "scenes_ok": int(self.status.get("ok", 0)),
            "scenes_attempted": int(sum(self.status.values())),
            "scenes_failed": int(self.status.get("failed", 0)),
            "scenes_timeout": int(self.status.get("timeout", 0)),
            "room_types": len(self.room_types),
            "objects": placed,
            "objects_requested": wanted,
            "placed_fraction": round(placed / wanted, 4) if wanted else None,
            "distinct_assets": int(parts.size),
            "categories": len(self.categories),
            "largest_category": top[0] if top else None,
            "largest_category_share": round(top[1] / total, 4) if top else None,
            "avg_objects": mean(obj),
            "avg_parts_per_asset": mean(parts.astype(float)),
            "avg_density": mean(dens),
            "share_density_above_1.35": share(dens, DENSITY_THRESHOLD),
            "avg_contacts": mean(con) if has_con else None,
            "share_contacts_above_50": share(con, CONTACTS_THRESHOLD) if has_con else None,
        }
        ours = {"dataset": f"{self.name} (parse3d)", "scenes": n, "objects": int(parts.size),
                "avg_objects": mean(obj),
                "layout": "PAG templates" if src == "templates" else "PAG files",
                "physics": settled, "parts": True, "part_contacts": settled and has_con}
        return {"dataset": self.name, "summary": summary,
                "paper": {"share_density_above_1.35": "> 0.55",
                          "share_contacts_above_50": "> 0.57", "avg_objects": 49.9,
                          "avg_parts_per_asset": 17.4, "room_types": 17, "categories": 132},
                "table1": [*PAPER_TABLE, ours]}

    def markdown(self, top_categories: int = 10) -> str:
        """The summary, Table 1 and the largest categories' shares of all objects as Markdown."""
        t = self.table()
        s = t["summary"]

        def fmt(v: Any) -> str:
            if v is None:
                return "-"
            if isinstance(v, bool):
                return "yes" if v else "no"
            if isinstance(v, float):
                return f"{v:,.2f}" if abs(v) < 1000 else f"{v:,.0f}"
            if isinstance(v, int):
                return f"{v:,}"
            return str(v)

        def pct(v):
            return ("-" if v is None else f"{100 * v:.1f}%")
        lines = [f"# Statistics of {self.name}", "",
                 "| measure | this dataset | PARSE-10K (paper) |", "|---|---:|---:|",
                 f"| scenes written (ok + incomplete) / attempted | {fmt(s['scenes_ok'])} + "
                 f"{fmt(s['scenes'] - s['scenes_ok'])} / {fmt(s['scenes_attempted'])} | 10,000 |",
                 f"| room types | {s['room_types']} | 17 |",
                 f"| objects placed (share of requested) | {fmt(s['objects'])} "
                 f"({pct(s['placed_fraction'])}) | - |",
                 f"| distinct assets / categories | {fmt(s['distinct_assets'])} / "
                 f"{s['categories']} | 17,372 / 132 |",
                 f"| largest category (share of objects) | {s['largest_category'] or '-'} "
                 f"({pct(s['largest_category_share'])}) | - |",
                 f"| average objects per scene | {fmt(s['avg_objects'])} | 49.9 |",
                 f"| average parts per asset | {fmt(s['avg_parts_per_asset'])} | 17.4 |",
                 f"| average objects per m² | {fmt(s['avg_density'])} | - |",
                 f"| scenes above {DENSITY_THRESHOLD} objects/m² | "
                 f"{pct(s['share_density_above_1.35'])} | > 55% |",
                 f"| average part-level contacts per scene | {fmt(s['avg_contacts'])} | - |",
                 f"| scenes with more than {CONTACTS_THRESHOLD} part-level contacts | "
                 f"{pct(s['share_contacts_above_50'])} | > 57% |",
                 "", "## Comparison with the paper's Table 1", "",
                 "| dataset | # scenes | # objects | avg. objects | layout generation | "
                 "physical optimisation | part annots. | part-level contact annots. |",
                 "|---|---:|---:|---:|---|:-:|:-:|:-:|"]
        for r in t["table1"]:
            lines.append(f"| {r['dataset']} | {fmt(r['scenes'])} | {fmt(r['objects'])} | "
                         f"{fmt(r['avg_objects'])} | {r['layout']} | {fmt(r['physics'])} | "
                         f"{fmt(r['parts'])} | {fmt(r['part_contacts'])} |")
        cats = self.categories
        total = sum(cats.values())
        if total:
            lines += ["", f"## Objects per category (the {min(top_categories, len(cats))} "
                      f"largest of {len(cats)}; categories.png draws them all)", "",
                      "| category | objects | share |", "|---|---:|---:|"]
            lines += [f"| {c} | {k:,} | {pct(k / total)} |"
                      for c, k in cats.most_common(top_categories)]
        lines += ["", "*# objects*: distinct assets (the paper counts its asset library); "
                  "statistics over the scenes written (status ok or incomplete).", ""]
        return "\n".join(lines)


def dataset_stats(path: str | Path) -> DatasetStats:
    """Read a dataset folder's manifest and configuration.

    Raises
    ------
    InputError
        When ``path`` holds no ``manifest.parquet``.
    """
    from .manifest import COMMITTED, read_manifest

    path = Path(path)
    man = path / "manifest.parquet"
    if not man.exists():
        raise InputError(Problem("", "no manifest.parquet here — build a dataset first "
                                     f"(parse3d dataset build --scenes N --out {path})",
                                 str(path), "io"))
    try:
        rows = read_manifest(man)
    except Exception as e:  # noqa: BLE001 - any damage to the file: one line, not a traceback
        raise InputError(Problem("", f"cannot read the manifest ({type(e).__name__}): run the "
                                     f"same parse3d dataset build again to rebuild it from the "
                                     "per-scene records", str(man), "io")) from None
    cfg_file = path / "dataset.json"
    try:
        config = read_json(cfg_file, what="build configuration") if cfg_file.exists() else {}
    except (OSError, ValueError) as e:
        raise InputError(Problem("", f"cannot read the build configuration: {e}",
                                 str(cfg_file), "io")) from None
    if not isinstance(config, dict):
        raise InputError(Problem("", "the build configuration is not a JSON object",
                                 str(cfg_file), "schema"))
    status = Counter(r["status"] for r in rows)
    return DatasetStats(name=path.resolve().name, config=config, status=dict(status),
                        rows=[r for r in rows if r["status"] in COMMITTED])


# --------------------------------------------------------------------------------------------
# plots


def _int_hist(ax, values: np.ndarray, *, color: str, max_bins: int = 60) -> None:
    v = values[~np.isnan(values)] if values.dtype.kind == "f" else values
    if v.size == 0:
        ax.text(0.5, 0.5, "no data", ha="center", va="center", transform=ax.transAxes)
        return
    lo, hi = int(np.floor(v.min())), int(np.ceil(v.max()))
    step = max(1, int(np.ceil((hi - lo + 1) / max_bins)))
    bins = np.arange(lo, hi + step + 1, step) - 0.5
    ax.hist(v, bins=bins, color=color, edgecolor="white", linewidth=0.5)


def _threshold(ax, values: np.ndarray, thr: float, unit: str) -> None:
    v = values[~np.isnan(values)]
    if v.size == 0:
        return
    ax.axvline(thr, color="#c0392b", linestyle="--", linewidth=1.2,
               label=f"{100 * np.mean(v > thr):.1f}% of scenes above {thr:g} {unit}")
    ax.set_xlim(left=0)


def _mean_line(ax, values: np.ndarray, unit: str) -> None:
    v = values[~np.isnan(values)] if values.dtype.kind == "f" else values
    if v.size == 0:
        return
    m = float(np.mean(v))
    ax.axvline(m, color="#2c3e50", linestyle=":", linewidth=1.4, label=f"mean {m:.1f} {unit}")


def _finish_axes(ax) -> None:
    from matplotlib.ticker import MaxNLocator

    if ax.get_ylabel() in ("scenes", "distinct assets"):  # counts of a histogram
        ax.yaxis.set_major_locator(MaxNLocator(integer=True))
    if ax.get_legend_handles_labels()[0]:
        ax.legend(loc="upper right", fontsize=9, framealpha=0.9)


def write_stats(stats: DatasetStats, out: str | Path, *, top_categories: int = 40) -> list[Path]:
    """Draw the figures and write ``stats.md`` and ``stats.json`` into ``out``.

    Returns
    -------
    list of Path
        The files written.
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    files: list[Path] = []
    n = len(stats.rows)

    def save(fig, name: str) -> None:
        for ax in fig.axes:
            _finish_axes(ax)
        fig.tight_layout()
        p = out / name
        fig.savefig(p, dpi=120)
        plt.close(fig)
        files.append(p)

    # categories
    cats = stats.categories.most_common()
    shown = cats[:top_categories]
    rest = sum(c for _, c in cats[top_categories:])
    if rest:
        shown.append((f"{len(cats) - top_categories} other categories", rest))
    fig, ax = plt.subplots(figsize=(8, max(3.0, 0.22 * len(shown) + 1.2)))
    if shown:
        names, counts = zip(*shown, strict=True)
        ax.barh(range(len(shown)), counts, color="#2e86c1")
        ax.set_yticks(range(len(shown)), names, fontsize=8)
        ax.invert_yaxis()
    ax.set_xlabel("object instances")
    ax.set_title(f"Object categories ({len(cats)} categories, {sum(c for _, c in cats):,} "
                 f"objects in {n:,} scenes)")
    save(fig, "categories.png")

    # parts per distinct asset
    parts = stats.parts_per_asset
    fig, ax = plt.subplots(figsize=(7, 4))
    _int_hist(ax, parts, color="#8e44ad")
    _mean_line(ax, parts.astype(float), "parts")
    ax.set_xlabel("parts per object")
    ax.set_ylabel("distinct assets")
    ax.set_title(f"Parts per object ({parts.size:,} distinct assets)")
    save(fig, "parts_per_object.png")

    # room types
    rooms = stats.room_types.most_common()
    fig, ax = plt.subplots(figsize=(8, 4))
    if rooms:
        names, counts = zip(*rooms, strict=True)
        ax.bar(range(len(rooms)), counts, color="#17a589")
        ax.set_xticks(range(len(rooms)), [r.replace("_", " ") for r in names], rotation=40,
                      ha="right", fontsize=9)
    ax.set_ylabel("scenes")
    ax.set_title(f"Room types ({len(rooms)} types, {n:,} scenes)")
    save(fig, "room_types.png")

    # object density
    dens = stats.density
    fig, ax = plt.subplots(figsize=(7, 4))
    d = dens[~np.isnan(dens)]
    if d.size:
        ax.hist(d, bins=min(40, max(5, d.size // 3)), color="#d68910", edgecolor="white",
                linewidth=0.5)
    _threshold(ax, dens, DENSITY_THRESHOLD, "objects/m²")
    ax.set_xlabel("objects per m² of floor")
    ax.set_ylabel("scenes")
    ax.set_title("Object density per room")
    save(fig, "object_density.png")

    # contacts per scene
    con = stats.contacts
    fig, ax = plt.subplots(figsize=(7, 4))
    c = con[~np.isnan(con)]
    if c.size:
        ax.hist(c, bins=min(40, max(5, c.size // 3)), color="#cb4335", edgecolor="white",
                linewidth=0.5, alpha=0.85)
    else:
        ax.text(0.5, 0.5, "not settled: no contacts", ha="center", va="center",
                transform=ax.transAxes)
    _threshold(ax, con, CONTACTS_THRESHOLD, "contacts")
    ax.set_xlabel("part-level contacts per scene")
    ax.set_ylabel("scenes")
    ax.set_title("Part-level contacts per scene")
    save(fig, "contacts_per_scene.png")

    # objects per scene
    obj = stats.objects_per_scene
    fig, ax = plt.subplots(figsize=(7, 4))
    _int_hist(ax, obj, color="#2874a6")
    _mean_line(ax, obj, "objects")
    ax.set_xlabel("placed objects per scene")
    ax.set_ylabel("scenes")
    ax.set_title("Objects per scene")
    save(fig, "objects_per_scene.png")

    from ..scene.io import atomic_write_text

    md = out / "stats.md"
    atomic_write_text(md, stats.markdown())
    js = out / "stats.json"
    atomic_write_text(js, json.dumps(stats.table(), indent=1) + "\n")
    files += [md, js]
    return files
