"""What a new user meets in the first hour: readable listings, a visible progress bar, counts
that say what they count, articles that read right, an install without warnings."""

from __future__ import annotations

import os
import pty
import re
import select
import subprocess
import sys
from pathlib import Path

import tomllib
import yaml

ROOT = Path(__file__).resolve().parent.parent
ENV = {**os.environ, "NO_COLOR": "1",
       "PYTHONPATH": os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")])}


def _cli(*args: str, columns: int = 80) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "parse3d", *args], capture_output=True,
                          text=True, env={**ENV, "COLUMNS": str(columns)}, timeout=300)


def test_assets_list_is_readable_at_80_columns():
    r = _cli("assets", "list")
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert max(len(ln.rstrip()) for ln in lines) <= 80
    # one heading line per category, its parts (whole words) indented beneath
    heads = [ln for ln in lines if ln and not ln.startswith(" ")]
    names = [h.split()[0] for h in heads[1:-1]]
    assert "desk" in names and "air_conditioner" in names
    desk = lines.index(next(h for h in heads if h.split()[0] == "desk"))
    parts = " ".join(ln.strip() for ln in lines[desk + 1:desk + 4] if ln.startswith("    "))
    # required parts (every variant has them) starred, as a pipe or a file shows them
    assert "tabletop*" in parts.split(", ") or "tabletop*," in parts.split()
    assert "drawer" in parts.split(", ") or "drawer," in parts.split()
    n = int(lines[-1].split()[0])  # "316 categories"
    assert len(lines) <= 2.5 * n + 5, len(lines)  # bordered cells wrapped to ~3.6 lines each


def test_assets_show_puts_what_a_pag_can_name_first():
    r = _cli("assets", "show", "bookcase", columns=100)
    assert r.returncode == 0, r.stderr
    out = r.stdout
    first_ref = out.index("bookcase:shelf#k")
    first_surface_row = out.index("side_panel_0")
    assert first_ref < out.index("internal surfaces") < out.index("surfaces of each part")
    assert first_ref < first_surface_row
    assert re.search(r"shelf\s*│\s*6\s*│", out)  # the six shelves counted in one row


def test_assets_stats_shows_progress_in_a_terminal():
    # a real terminal on stderr (the bar goes there; stdout keeps the table)
    master, slave = pty.openpty()
    p = subprocess.Popen([sys.executable, "-m", "parse3d", "assets", "stats", "--seeds", "1",
                          "--categories", "mug,desk,bookcase"], stdout=subprocess.PIPE,
                         stderr=slave, env={**ENV, "COLUMNS": "100", "TERM": "xterm"})
    os.close(slave)
    seen = b""
    while True:
        ready, _, _ = select.select([master], [], [], 120)
        if not ready:
            break
        try:
            chunk = os.read(master, 4096)
        except OSError:
            break
        if not chunk:
            break
        seen += chunk
    out, _ = p.communicate(timeout=300)
    os.close(master)
    assert p.returncode == 0
    text = seen.decode("utf-8", "replace")
    assert "generating" in text and re.search(r"\d/3", text), text[-500:]
    assert b"categories" in out


def test_template_check_says_objects_per_seed():
    from parse3d.cli.template import objects_by_seed

    assert objects_by_seed([63, 62]) == "62-63 objects (by seed: 63, 62)"
    assert objects_by_seed([40, 40, 40]) == "40 objects (each seed)"
    assert objects_by_seed([12]) == "12 objects"
    assert "/" not in objects_by_seed([63, 62])


#: Words spelt with a vowel that start with a consonant sound ("a utility room", "a one-off").
_CONSONANT_SOUND = ("uni", "use", "usu", "uti", "ura", "uro", "eu", "one", "once")
_SILENT_H = ("hour", "honest", "heir")


def _article_mistakes(text: str) -> list[str]:
    bad = []
    for art, word in re.findall(r"\b([Aa]n?) ([A-Za-z][\w-]*)", text):
        w = word.lower()
        vowel = ((w[0] in "aeiou" and not w.startswith(_CONSONANT_SOUND))
                 or w.startswith(_SILENT_H))
        if re.match(r"[A-Z](-|$)", word):  # a letter said by its name: "an L-shaped", "a U-"
            vowel = word[0] in "AEFHILMNORSX"
        if (art.lower() == "a") == vowel:
            bad.append(f"{art} {word}")
    return bad


def test_articles_in_template_and_motif_descriptions():
    assert _article_mistakes("A attic bedroom, an desk, a utility room, an open plan, "
                             "an L-shaped hall, a U-shaped bar, a L-shaped den") == [
        "A attic", "an desk", "a L-shaped"]
    folder = ROOT / "src" / "parse3d" / "datagen"
    files = sorted(folder.glob("templates/**/*.yaml")) + sorted(folder.glob("motifs/**/*.yaml"))
    assert len(files) > 100
    bad = {}
    for f in files:
        desc = (yaml.safe_load(f.read_text()) or {}).get("description", "")
        if m := _article_mistakes(desc):
            bad[f.name] = m
    assert not bad, bad


def test_licence_is_an_spdx_expression():
    # setuptools >= 77 reads a plain SPDX string; a {text = ...} table or a licence classifier
    # prints a deprecation box on every install
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())
    project = meta["project"]
    assert project["license"] == "Apache-2.0"
    assert not any(c.startswith("License ::") for c in project.get("classifiers", []))
    req = next(r for r in meta["build-system"]["requires"] if r.startswith("setuptools"))
    assert int(re.search(r">=(\d+)", req).group(1)) >= 77
