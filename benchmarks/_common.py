"""Helpers shared by the benchmarks: the tables-and-tabletop workload, and running another git
revision of the package side by side (``--baseline-rev``)."""

from __future__ import annotations

import contextlib
import json
import math
import os
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: Small objects put on the tables, in turn (the peer benchmark uses the same kinds).
TABLETOP = ("mug", "plate", "bowl", "bottle", "book")
#: Objects per table: the table and this many small objects less one on its top.
PER_TABLE = 5
#: Floor area per table (m^2): the density held constant as the room grows.
AREA_PER_TABLE = 6.0


def tables_layout(n: int) -> dict:
    """The tables-and-tabletop room of ``n`` objects as plain data.

    ``ceil(n / PER_TABLE)`` dining tables ON the floor of a square room of ``AREA_PER_TABLE``
    m^2 per table, and the other objects (kinds from :data:`TABLETOP` in turn) ON the tables'
    tops, dealt round-robin. Returns ``{"side": m, "tables": [...], "items": [(id, kind,
    table), ...]}``.
    """
    n_tables = max(1, math.ceil(n / PER_TABLE))
    side = round(math.sqrt(AREA_PER_TABLE * n_tables), 3)
    tables = [f"table{i}" for i in range(n_tables)]
    items = [(f"item{k}", TABLETOP[k % len(TABLETOP)], tables[k % n_tables])
             for k in range(n - n_tables)]
    return {"side": side, "tables": tables, "items": items}


def tables_room(n: int):
    """The tables-and-tabletop workload of ``n`` objects as a PAG (see :func:`tables_layout`)."""
    from parse3d.pag import PAG, Room

    lay = tables_layout(n)
    s = lay["side"]
    pag = PAG(f"tables-{n}", Room("dining", ((0, 0), (s, 0), (s, s), (0, s)), 2.8))
    for t in lay["tables"]:
        pag.add(t, "dining_table")
        pag.relate(t, "ON", "floor")
    for oid, kind, table in lay["items"]:
        pag.add(oid, kind)
        pag.relate(oid, "ON", f"{table}:tabletop")
    return pag


@contextlib.contextmanager
def revision_tree(rev: str) -> Iterator[Path]:
    """A temporary detached git worktree of ``rev`` (removed afterwards)."""
    with tempfile.TemporaryDirectory(prefix="parse3d-baseline-") as tmp:
        wt = Path(tmp) / "tree"
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(wt), rev],
                       check=True, capture_output=True)
        try:
            yield wt
        finally:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(wt)],
                           check=False, capture_output=True)


class Worker:
    """A benchmark script running as a long-lived subprocess that answers JSON requests.

    The script is started as ``python SCRIPT --_worker`` (with ``PYTHONPATH`` set to ``src``
    when given: another revision's package) and must answer each JSON line read from stdin
    with one JSON line on stdout (see :func:`serve`). Keeping the process alive keeps it
    warm, and lets a benchmark interleave rounds of two revisions or two programs.
    """

    def __init__(self, script: Path | str, *, python: str | None = None,
                 src: Path | None = None, cwd: Path | None = None, args: tuple = ()):
        env = dict(os.environ)
        if src is not None:
            env["PYTHONPATH"] = str(src)
        self.proc = subprocess.Popen([python or sys.executable, str(script), "--_worker", *args],
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True,
                                     env=env, cwd=str(cwd or ROOT))

    def ask(self, **request) -> dict:
        self.proc.stdin.write(json.dumps(request) + "\n")
        self.proc.stdin.flush()
        line = self.proc.stdout.readline()
        if not line:
            raise RuntimeError(f"benchmark worker exited (code {self.proc.wait()})")
        return json.loads(line)

    def close(self) -> None:
        if self.proc.poll() is None:
            self.proc.stdin.close()
            self.proc.wait(timeout=60)

    def __enter__(self) -> Worker:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def serve(handle) -> None:
    """The worker's side of :class:`Worker`: answer each JSON request line with ``handle``'s
    result (a dict) on one line; anything else printed goes to stderr."""
    out = sys.stdout
    sys.stdout = sys.stderr
    for line in sys.stdin:
        if line.strip():
            try:
                answer = handle(json.loads(line))
            except Exception as e:  # noqa: BLE001 - e.g. a category an older revision lacks
                answer = {"error": f"{type(e).__name__}: {e}"}
            out.write(json.dumps(answer) + "\n")
            out.flush()


def fit_exponent(ns, ts) -> float:
    """Least-squares slope of log(time) against log(objects): the scaling exponent."""
    lx = [math.log(n) for n in ns]
    ly = [math.log(max(t, 1e-9)) for t in ts]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    sxx = sum((x - mx) ** 2 for x in lx)
    return sum((x - mx) * (y - my) for x, y in zip(lx, ly, strict=True)) / max(sxx, 1e-12)
