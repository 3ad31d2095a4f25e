"""The typer application behind ``parse3d``: every command and its options (``--help``).

Each command group lives in its own module of this package and exposes ``register(app)``.
:func:`parse3d.cli.main` runs a plain ``parse3d solve`` line without it (see ``_fast``).
"""

from __future__ import annotations

import importlib
import importlib.util

import typer

from . import _params

__all__ = ["app", "main"]

# Command modules, in the order their commands appear in --help.
_MODULES = ("validate", "pag", "solve", "settle", "render", "export", "assets", "template", "dataset",
            "vlm", "layout", "serve", "demo")

#: The commands each module registers, so that only the module of the command being run is
#: imported (start-up time; tests/test_cli_startup.py checks this table against ``register``).
#: A module of ``_MODULES`` missing here is imported and registered eagerly.
_LAZY = {"validate": ("validate",), "pag": ("pag",), "solve": ("solve", "generate"),
         "settle": ("settle",), "render": ("render",), "export": ("export",),
         "assets": ("assets",), "template": ("template",), "dataset": ("dataset",),
         "vlm": ("vlm",), "layout": ("layout",), "serve": ("serve",), "demo": ("demo",)}

_EAGER: dict[str, tuple[str, ...]] = {}  # module -> the commands it registered at start-up
_LOADED: dict[str, dict[str, typer.core.TyperGroup]] = {}  # module -> its click commands


def _module_commands(module: str) -> dict:
    """Import one command module and build its click commands (once per process)."""
    if module not in _LOADED:
        sub = typer.Typer(add_completion=False, pretty_exceptions_enable=False)
        importlib.import_module(f"{__package__}.{module}").register(sub)
        commands = dict(typer.main.get_group(sub).commands)
        for command in commands.values():
            _params.install(command)
        _LOADED[module] = commands
    return _LOADED[module]


def _lazy_module(cmd_name: str) -> str | None:
    """The module of ``_LAZY`` that registers ``cmd_name`` (None: not a lazy command)."""
    for m, names in _LAZY.items():
        if cmd_name in names and m in _MODULES and importlib.util.find_spec(
                f"{__package__}.{m}") is not None:
            return m
    return None


class _LazyCommands(dict):
    """The root group's commands: looking one up imports its module; listing them all (help,
    completion, tests walking the tree) imports every module."""

    def _load(self, name) -> None:
        if isinstance(name, str) and not dict.__contains__(self, name):
            m = _lazy_module(name)
            if m is not None:
                for k, v in _module_commands(m).items():
                    dict.setdefault(self, k, v)

    def _load_all(self) -> None:
        for m in _MODULES:
            for name in _LAZY.get(m, ()):
                self._load(name)

    def get(self, name, default=None):
        self._load(name)
        return dict.get(self, name, default)

    def __getitem__(self, name):
        self._load(name)
        return dict.__getitem__(self, name)

    def __contains__(self, name) -> bool:
        return dict.__contains__(self, name) or _lazy_module(name) is not None

    def __iter__(self):
        self._load_all()
        return dict.__iter__(self)

    def __len__(self) -> int:
        self._load_all()
        return dict.__len__(self)

    def keys(self):
        self._load_all()
        return dict.keys(self)

    def values(self):
        self._load_all()
        return dict.values(self)

    def items(self):
        self._load_all()
        return dict.items(self)


class _LazyGroup(typer.core.TyperGroup):
    """The root command group: a command's module is imported when the command is run or
    listed (``parse3d --help`` lists them all, so it imports them all)."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.commands = _LazyCommands(self.commands)
        _params.install(self)

    def list_commands(self, ctx) -> list[str]:
        names: list[str] = []
        for m in _MODULES:
            names.extend(_LAZY[m] if m in _LAZY else _EAGER.get(m, ()))
        return list(dict.fromkeys(names + [n for n in dict.keys(self.commands)
                                           if n not in names]))

    def get_command(self, ctx, cmd_name: str):
        return self.commands.get(cmd_name)


app = typer.Typer(
    name="parse3d",
    help="Part-aware relational spatial modelling: PAG files to settled 3D scenes.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    cls=_LazyGroup,
)

for _name in _MODULES:
    if _name not in _LAZY and importlib.util.find_spec(f"{__package__}.{_name}") is not None:
        _before = ({c.name for c in app.registered_commands}
                   | {g.name for g in app.registered_groups})
        importlib.import_module(f"{__package__}.{_name}").register(app)
        _EAGER[_name] = tuple(n for n in [*(c.name for c in app.registered_commands),
                                          *(g.name for g in app.registered_groups)]
                              if n not in _before)


def _version(value: bool) -> None:
    if value:
        from importlib.metadata import PackageNotFoundError, version

        try:
            v = version("parse3d")
        except PackageNotFoundError:
            v = "unknown (not installed)"
        typer.echo(f"parse3d {v}")
        raise typer.Exit()


@app.callback()
def _root(
    show_version: bool = typer.Option(False, "--version", callback=_version, is_eager=True,
                                      help="Print the version and exit."),
) -> None:
    """Part-aware relational spatial modelling: PAG files to settled 3D scenes.

    Example: parse3d solve examples/study.json --seed 0 --out out/study
    """


def main(argv: list[str] | None = None) -> None:
    """Run the command line ``argv`` (default ``sys.argv[1:]``) through typer."""
    from . import run_guarded

    run_guarded(lambda: app(args=argv, standalone_mode=True))
