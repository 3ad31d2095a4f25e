"""Run a group of hostile cases in one process: ``python runner.py CASES.json RESULTS.json``.

Each case runs ``parse3d.cli.main(argv)`` in-process with its own working folder,
environment overrides and blocked modules, under a 60 s alarm, with stdout and stderr
captured. After each case the whole case root is compared with a snapshot taken before it:
any file created, changed or removed outside the case's declared outputs is reported.
Results are written as JSON, one entry per case, in order.
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import signal
import sys
import time
import traceback
from pathlib import Path

CASE_LIMIT_S = 60


class CaseTimeout(BaseException):
    pass


def _alarm(signum, frame):
    raise CaseTimeout()


def snapshot(root: Path) -> dict[str, tuple]:
    out = {}
    for dirpath, dirnames, filenames in os.walk(root):
        for n in dirnames + filenames:
            p = Path(dirpath) / n
            try:
                st = p.lstat()
            except OSError:
                continue
            kind = "d" if p.is_dir() and not p.is_symlink() else "f"
            out[str(p.relative_to(root))] = (kind, 0 if kind == "d" else st.st_size,
                                             0 if kind == "d" else st.st_mtime_ns)
    return out


def changed(before: dict, after: dict) -> set[str]:
    keys = set(before) | set(after)
    return {k for k in keys if before.get(k) != after.get(k)}


def run_case(case: dict, root: Path) -> dict:
    from parse3d.cli import main

    work = root / case["id"]
    allowed = [str(Path(case["id"]) / a) for a in case.get("outputs", [])]
    before = snapshot(root)
    old_env = {k: os.environ.get(k) for k in case.get("env", {})}
    for k, v in case.get("env", {}).items():
        os.environ[k] = v
    blocked = {m: sys.modules.get(m) for m in case.get("block", [])}
    for m in blocked:
        sys.modules[m] = None  # type: ignore[assignment]  # import and find_spec now fail
    out, err = io.StringIO(), io.StringIO()
    cwd = os.getcwd()
    code: int | str = 0
    tb = None
    t0 = time.monotonic()
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(CASE_LIMIT_S)
    try:
        os.chdir(work)
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            main(case["argv"])
    except SystemExit as e:
        code = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
    except CaseTimeout:
        code = "timeout"
    except BaseException:  # noqa: BLE001 - a traceback is exactly what a case must not give
        code = "traceback"
        tb = traceback.format_exc()
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
        os.chdir(cwd)
        for k, v in old_env.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
        for m, mod in blocked.items():
            if mod is None:
                sys.modules.pop(m, None)
            else:
                sys.modules[m] = mod
    wall = time.monotonic() - t0
    diff = changed(before, snapshot(root))
    outside = sorted(d for d in diff
                     if not any(d == a or d.startswith(a + os.sep) for a in allowed))
    return {"id": case["id"], "code": code, "stdout": out.getvalue(), "stderr": err.getvalue(),
            "traceback": tb, "wall": wall, "outside": outside,
            "exists": {p: (work / p).exists() for p in case.get("absent", []) +
                       case.get("present", [])}}


def main() -> None:
    cases = json.loads(Path(sys.argv[1]).read_text())
    root = Path(cases["root"])
    results = []
    for case in cases["cases"]:
        results.append(run_case(case, root))
        Path(sys.argv[2]).write_text(json.dumps(results))


if __name__ == "__main__":
    main()
