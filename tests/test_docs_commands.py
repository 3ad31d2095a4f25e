"""Every command README.md and docs/*.md show names a real subcommand, real options, real files.

The docs are parsed for shell commands (fenced ``bash``/``sh``/``console``/untagged blocks, and
inline code spans that start with ``parse3d``, ``python``, ``make`` or ``.venv/bin/...``). Then:

- ``parse3d A B --opt``: ``A B`` is a command path of the typer application and ``--opt`` is one
  of that command's options (the click tree is walked, nothing is run);
- ``python benchmarks/X.py --opt`` (or ``examples/...``): the script exists and its argparse
  parser knows ``--opt`` (its ``--help``, run once per script);
- ``make T``: ``T`` is a target of the Makefile.

Running the commands themselves is other tests' work (solving, rendering, datasets).
"""

from __future__ import annotations

import functools
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest
import typer

ROOT = Path(__file__).resolve().parents[1]
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]

_FENCE = re.compile(r"^```(\w*)\s*$")
_SHELL_TAGS = {"", "bash", "sh", "shell", "console"}
_INLINE = re.compile(r"`([^`]+)`")
_STARTS = ("parse3d ", ".venv/bin/", "python ", "python3 ", "make ")
#: Words that stand for a value the reader picks, where a command path could also go.
_PLACEHOLDERS = {"...", "FILE", "DIR", "RUN", "PAG", "N", "CMD", "COMMAND"}


def _logical_lines(text: str) -> list[str]:
    """Lines of a shell block with ``\\`` continuations joined and ``#`` comments dropped."""
    out: list[str] = []
    pending = ""
    for raw in text.splitlines():
        line = raw.rstrip()
        if line.startswith("$ "):
            line = line[2:]
        if line.endswith("\\"):
            pending += line[:-1] + " "
            continue
        line = pending + line
        pending = ""
        try:
            lexer = shlex.shlex(line, posix=True, punctuation_chars=False)
            lexer.whitespace_split = True
            lexer.commenters = "#"
            words = list(lexer)
        except ValueError:
            words = line.split()
        if words:
            out.append(shlex.join(words))
    return out


def _split_commands(line: str) -> list[list[str]]:
    """One shell line into its simple commands (split at ``&&``, ``||``, ``;``, ``|``), with
    environment assignments, ``nice``/``time`` prefixes and redirections removed."""
    try:
        words = shlex.split(line)
    except ValueError:
        return []
    commands: list[list[str]] = [[]]
    for w in words:
        if w in {"&&", "||", ";", "|", "&"}:
            commands.append([])
        else:
            commands[-1].append(w)
    cleaned = []
    for cmd in commands:
        while cmd and (re.match(r"^[A-Za-z_][A-Za-z0-9_]*=", cmd[0]) or cmd[0] in {"nice", "time"}
                       or re.match(r"^-n$|^-?\d+$", cmd[0])):
            cmd = cmd[1:]
        cut = next((i for i, w in enumerate(cmd) if w[:1] in {">", "<"} or w in {"2>&1", "2>"}),
                   len(cmd))
        if cmd[:cut]:
            cleaned.append(cmd[:cut])
    return cleaned


def doc_commands() -> list[tuple[str, int, list[str]]]:
    """(doc name, line number, words) for every shell command the docs show."""
    found: list[tuple[str, int, list[str]]] = []
    for doc in DOCS:
        lines = doc.read_text(encoding="utf-8").splitlines()
        tag: str | None = None
        block: list[str] = []
        start = 0
        para: list[str] = []  # the lines of the paragraph being read, outside code blocks
        para_start = 0
        for i, line in enumerate(lines, 1):
            m = _FENCE.match(line.strip())
            if m and tag is None:
                tag, block, start = m.group(1).lower(), [], i
                continue
            if line.strip() == "```" and tag is not None:
                if tag in _SHELL_TAGS:
                    logicals: list[str] = []
                    for logical in _logical_lines("\n".join(block)):
                        if logicals and logical.lstrip("'").startswith(("[", "--")):  # a wrapped option list
                            logicals[-1] += " " + logical
                        else:
                            logicals.append(logical)
                    for logical in logicals:
                        for cmd in _split_commands(logical):
                            found.append((doc.name, start, cmd))
                tag = None
                continue
            if tag is not None:
                block.append(line)
                continue
            if line.strip():
                if not para:
                    para_start = i
                para.append(line.strip())
                if i < len(lines) and lines[i].strip() and not lines[i].lstrip().startswith("```"):
                    continue  # the paragraph goes on: a code span may wrap onto the next line
            text = "\n".join(para)
            for m in _INLINE.finditer(text):
                span = m.group(1).replace("\n", " ")
                if span.startswith(_STARTS) and not span.startswith("python -c"):
                    for cmd in _split_commands(span):
                        found.append((doc.name, para_start + text.count("\n", 0, m.start()), cmd))
            para = []
    return found


def _program(words: list[str]) -> tuple[str, list[str]] | None:
    """("parse3d" | "python" | "make", the words after it), or None for other programs."""
    if not words:
        return None
    head = words[0].rsplit("/", 1)[-1]
    if head == "parse3d":
        return "parse3d", words[1:]
    if head in {"python", "python3"}:
        rest = words[1:]
        if rest[:2] == ["-m", "parse3d"]:
            return "parse3d", rest[2:]
        if rest[:1] == ["-m"]:
            return None
        return "python", rest
    if head == "make":
        return "make", words[1:]
    return None


@functools.cache
def _root():
    from parse3d.cli import app

    return typer.main.get_command(app)


def _option_names(command) -> set[str]:
    names = {"--help", "-h"}
    for p in command.params:
        if getattr(p, "param_type_name", None) == "option":
            names.update(p.opts)
            names.update(p.secondary_opts)
    return names


def check_parse3d(args: list[str]) -> list[str]:
    """What is wrong with ``parse3d <args>`` (an empty list: nothing)."""
    command = _root()
    path = ["parse3d"]
    words = [w.strip("[]") for w in args]
    i = 0
    while hasattr(command, "list_commands") and i < len(words):
        w = words[i]
        if w.startswith("-") or w in _PLACEHOLDERS or w == "/":
            break
        sub = command.get_command(None, w)
        if sub is None:
            return [f"{' '.join(path)} has no subcommand {w!r}"]
        command, path = sub, [*path, w]
        i += 1
    problems = []
    known = _option_names(command)
    for w in words[i:]:
        if w == "/":  # "list / show / render": alternatives written in one span
            break
        if w.startswith("-") and w not in {"-", "--"} and not re.match(r"^-\d", w):
            name = w.split("=", 1)[0]
            if name not in known:
                problems.append(f"{' '.join(path)} has no option {name}")
    return problems


@functools.cache
def _script_options(script: str) -> frozenset[str]:
    proc = subprocess.run([sys.executable, str(ROOT / script), "--help"], capture_output=True,
                          text=True, cwd=ROOT, timeout=120)
    assert proc.returncode == 0, f"{script} --help failed:\n{proc.stderr[-2000:]}"
    return frozenset(re.findall(r"(?<![\w-])(--?[A-Za-z][\w-]*)", proc.stdout))


def check_python(args: list[str]) -> list[str]:
    """What is wrong with ``python <args>``: the script exists and knows every option."""
    if not args or not args[0].endswith(".py"):
        return []
    script = args[0]
    if "<" in script or Path(script).stem == "X":
        return []
    if not (ROOT / script).is_file():
        return [f"no file {script}"]
    problems = []
    for w in args[1:]:
        w = w.strip("[]")
        if w.startswith("--"):
            name = w.split("=", 1)[0]
            if name not in _script_options(script):
                problems.append(f"{script} has no option {name}")
    return problems


_REPO_DIRS = ("examples/", "benchmarks/", "tests/", "src/", "docs/", "web/")
_OUTPUT_OPTIONS = {"-o", "--out", "--screenshots"}


def check_paths(args: list[str]) -> list[str]:
    """Repository files a command reads (not what it writes) exist."""
    problems = []
    words = [w.strip("[]") for w in args]
    for before, w in zip(["", *words], words, strict=False):
        if (w.startswith(_REPO_DIRS) and before not in _OUTPUT_OPTIONS and "<" not in w
                and not (ROOT / w).exists()):
            problems.append(f"no file {w} in the repository")
    return problems


def check_make(args: list[str]) -> list[str]:
    targets = set(re.findall(r"^([\w.-]+):", (ROOT / "Makefile").read_text(), re.M))
    return [f"Makefile has no target {t!r}" for t in args
            if not t.startswith("-") and "=" not in t and t not in targets]


def test_docs_show_commands():
    commands = [(doc, line, _program(w)) for doc, line, w in doc_commands()]
    commands = [(doc, line, p) for doc, line, p in commands if p is not None]
    kinds = {p[0] for _, _, p in commands}
    assert {"parse3d", "python", "make"} <= kinds, kinds
    assert len(commands) > 50


def test_every_documented_command_exists():
    problems = []
    for doc, line, words in doc_commands():
        prog = _program(words)
        if prog is None:
            continue
        kind, args = prog
        check = {"parse3d": check_parse3d, "python": check_python, "make": check_make}[kind]
        found = check(args) + check_paths(args[1:] if kind == "python" else args)
        problems += [f"{doc}:{line}: `{shlex.join(words)}`: {p}" for p in found]
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize("args, bad", [
    (["solve", "x.json", "--seed", "0", "--no-such-option"], "--no-such-option"),
    (["assets", "no-such-command"], "no-such-command"),
])
def test_checker_catches_a_wrong_command(args, bad):
    problems = check_parse3d(args)
    assert problems and bad in problems[0]
    assert not check_parse3d(["solve", "x.json", "--seed", "0", "--out", "DIR"])


def test_make_bench_runs_scripts_that_exist():
    import ast

    tree = ast.parse((ROOT / "benchmarks" / "run_all.py").read_text(encoding="utf-8"))
    benches = next(ast.literal_eval(node.value) for node in tree.body
                   if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "BENCHES")
    missing = [n for n in benches if not (ROOT / "benchmarks" / f"bench_{n}.py").is_file()]
    assert not missing, f"benchmarks/run_all.py runs scripts that do not exist: {missing}"
    for name, args in benches.items():
        assert not [p for p in check_python([f"benchmarks/bench_{name}.py", *args])], name
