"""``parse3d serve``: the PAG designer in the browser."""

from __future__ import annotations

from pathlib import Path

import typer

from ..errors import InputError, Problem
from ._common import console

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
        application = create_app(workdir)
        url = f"http://{host if host not in ('0.0.0.0', '::') else '127.0.0.1'}:{port}/"
        console.print(f"PAG designer on [bold]{url}[/] (working folder {workdir.resolve()}); "
                      "Ctrl+C stops it")
        if open_browser:
            import threading
            import webbrowser

            threading.Timer(1.0, webbrowser.open, args=(url,)).start()
        uvicorn.run(application, host=host, port=port, log_level="warning")
