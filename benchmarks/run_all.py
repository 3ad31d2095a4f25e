"""Run every benchmark in turn with its default (quick) settings and print its figures.

Usage::

    python benchmarks/run_all.py [--only solver,physics]
"""

from __future__ import annotations

import argparse
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
BENCHES = {
    "validate": [],
    "assets": ["--per-category", "2"],
    "solver": [],
    "physics": [],
    "settle": ["--scenes", "4", "--rounds", "1"],
    "render": [],
    "preview": ["--scenes", "2", "--rounds", "1"],
    "dataset": ["--scenes", "12"],
    "robustness": ["--quick"],
    "export": ["--repeats", "1"],
}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", default="", help="comma-separated subset of " + ", ".join(BENCHES))
    args = ap.parse_args()
    names = [n for n in args.only.split(",") if n] or list(BENCHES)
    status = 0
    for name in names:
        print(f"\n=== bench_{name} ===", flush=True)
        r = subprocess.run([sys.executable, str(HERE / f"bench_{name}.py"), *BENCHES[name]])
        status = status or r.returncode
    return status


if __name__ == "__main__":
    sys.exit(main())
