"""`nl2hltl2plan serve [--host 127.0.0.1] [--port 8000]`: the local web app (needs the `[web]` extra)."""

from __future__ import annotations

import argparse
import importlib.util
import ipaddress
import re
import socket

from nl2hltl2plan.cli.commands import COMMANDS
from nl2hltl2plan.errors import Nl2Hltl2PlanError


class MissingExtraError(Nl2Hltl2PlanError):
    """An optional dependency group is not installed."""


class ServeError(Nl2Hltl2PlanError):
    """The web server cannot start on the address asked for."""


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "serve",
        help=COMMANDS["serve"],
        description="Serve a page where one types an instruction, chooses a world, a team and the "
        "planner's options, watches it being planned (and may cancel), and sees and downloads the HTT, "
        "the spec, the plan on the map and its Gantt chart; POST /api/plan returns the JSON of "
        "`plan --json`, POST /api/plan/stream the same as Server-Sent Events. Plans run in worker "
        "processes, one per CPU, with a bounded queue (docs/web.md; the API at /docs).",
    )
    p.add_argument(
        "--host", default="127.0.0.1", help="interface to listen on (default 127.0.0.1: this machine)"
    )
    p.add_argument("--port", type=_port, default=8000, help="TCP port (default 8000)")
    p.set_defaults(func=run)


def _port(text: str) -> int:
    try:
        port = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"a port is a whole number, got {text!r}") from None
    if not 1 <= port <= 65535:
        raise argparse.ArgumentTypeError(f"a port is between 1 and 65535, got {port}")
    return port


APP_FACTORY = "nl2hltl2plan.web.app:create_app"  # by name: cli and web are independent layers


def run(args: argparse.Namespace) -> int:
    missing = [m for m in ("fastapi", "uvicorn") if importlib.util.find_spec(m) is None]
    if missing:
        raise MissingExtraError(f"the web app needs {' and '.join(missing)}: pip install 'nl2hltl2plan[web]'")
    import uvicorn

    check_listen_address(args.host, args.port)
    print(f"serving on http://{args.host}:{args.port}/  (Ctrl-C to stop)", flush=True)
    try:
        uvicorn.run(APP_FACTORY, factory=True, host=args.host, port=args.port, log_level="warning")
    except SystemExit as exc:  # uvicorn's own exit statuses (1, 3) are not ours: a failed start is bad input
        if exc.code not in (None, 0):
            raise ServeError(
                f"the web server on {args.host}:{args.port} stopped (uvicorn status {exc.code})"
            ) from None
    return 0


def check_listen_address(host: str, port: int) -> None:
    """Refuse, before starting, a host that does not resolve (`256.1.1.1`) or an address that cannot be
    listened on (port taken, not this machine's interface): uvicorn would exit with status 3 or 1."""
    if re.fullmatch(r"[0-9.]+", host):  # looks like IPv4: checked here, never sent to a DNS resolver
        try:
            ipaddress.IPv4Address(host)
        except ValueError as exc:
            raise ServeError(f"cannot listen on --host {host!r}: {exc}") from None
    try:
        infos = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE)
    except (socket.gaierror, UnicodeError) as exc:
        raise ServeError(f"cannot listen on --host {host!r}: not a host name or address ({exc})") from None
    family, kind, proto, _, address = infos[0]
    try:
        with socket.socket(family, kind, proto) as probe:
            probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)  # as uvicorn binds
            probe.bind(address)
    except OSError as exc:
        raise ServeError(f"cannot listen on {host}:{port}: {exc.strerror or exc}") from None
