"""``parse3d serve``: the PAG designer in the browser."""

from __future__ import annotations

from pathlib import Path

import typer

from ..errors import InputError, Problem
from ._common import console, err_console

__all__ = ["register"]


def register(app: typer.Typer) -> None:
    @app.command("serve")
    def serve_cmd(
        port: int = typer.Option(8765, "--port", min=0, max=65535, help="TCP port."),
        host: str = typer.Option("127.0.0.1", "--host",
                                 help="Address to bind (default: this machine only)."),
        open_browser: bool = typer.Option(False, "--open", help="Open the designer in a browser."),
        workdir: Path = typer.Option(Path("."), "--workdir",
                                     help="The folder PAG files are read from and saved to, and "
                                          "solved scenes written under (out/); the only folder "
                                          "the server writes."),
    ) -> None:
        """Start the PAG designer: build a PAG by clicking parts, validate, solve, view.

        Example:

            mkdir -p my-rooms && parse3d serve --port 8765 --workdir my-rooms --open
        """
        try:
            import uvicorn

            from ..web import create_app
        except ImportError as e:
            raise InputError(Problem("", f"the designer needs the web extra ({e.name} is "
                                     "missing): pip install 'parse3d[web]'", "serve", "io")
                             ) from None
        if not workdir.is_dir():
            raise InputError(Problem("", "no such folder: create it or choose another "
                                     "--workdir", str(workdir), "io"))
        family, loopback = _check_address(host)
        port = _check_port(host, port, family)
        if not loopback:
            err_console.print(
                f"[bold yellow]warning:[/] --host {host} opens the designer to the network: "
                "anyone who can reach this machine may read and overwrite the PAG files in "
                f"{workdir.resolve()} and start solves (the API has no login). Use the default "
                "127.0.0.1 unless this network is yours alone.")
        application = create_app(workdir, host=host, port=port,
                                  other_hosts=_machine_names() if host in ("0.0.0.0", "::")
                                  else ())
        shown = host if host not in ("0.0.0.0", "::") else "127.0.0.1"
        url = f"http://{shown if ':' not in shown else f'[{shown}]'}:{port}/"
        console.print(f"PAG designer on [bold]{url}[/] (working folder {workdir.resolve()}); "
                      "Ctrl+C stops it")
        if open_browser:
            import threading
            import webbrowser

            threading.Timer(1.0, webbrowser.open, args=(url,)).start()
        uvicorn.run(application, host=host, port=port, log_level="warning")


def _check_address(host: str) -> tuple[int, bool]:
    """(address family, whether only this machine can connect) of ``--host``; an InputError
    when the name does not resolve to an address of this machine's kind."""
    import ipaddress
    import socket

    try:
        infos = socket.getaddrinfo(host, None, type=socket.SOCK_STREAM)
    except (socket.gaierror, UnicodeError) as e:
        raise InputError(Problem("", f"--host {host!r} is not an address of this machine "
                                     f"({getattr(e, 'strerror', None) or e}): use 127.0.0.1",
                                 "serve", "parameter")) from None
    family = infos[0][0]
    loopback = all(ipaddress.ip_address(i[4][0].split("%")[0]).is_loopback for i in infos)
    return family, loopback


def _check_port(host: str, port: int, family: int) -> int:
    """``port`` if it can be bound on ``host`` now (0: a free one), else a one-line InputError."""
    import errno
    import socket

    with socket.socket(family, socket.SOCK_STREAM) as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            s.bind((host, port))
        except OSError as e:
            why = ("is in use by another program: stop it or choose another --port"
                   if e.errno == errno.EADDRINUSE else
                   f"cannot be opened ({e.strerror}): choose another --port or --host")
            raise InputError(Problem("", f"port {port} on {host} {why}", "serve", "parameter")
                             ) from None
        return s.getsockname()[1] if port == 0 else port


def _machine_names() -> tuple[str, ...]:
    """This machine's host names and addresses: what a browser on the network puts in the
    ``Host`` header when the server listens on every interface."""
    import contextlib
    import socket

    names = {socket.gethostname(), socket.getfqdn()}
    with contextlib.suppress(socket.gaierror, UnicodeError):
        names |= {i[4][0] for i in socket.getaddrinfo(socket.gethostname(), None)}
    return tuple(sorted(n for n in names if n))
