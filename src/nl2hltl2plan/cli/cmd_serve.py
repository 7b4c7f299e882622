"""`nl2hltl2plan serve [--host 127.0.0.1] [--port 8000]`: the local web app (needs the `[web]` extra)."""

from __future__ import annotations

import argparse
import importlib.util

from nl2hltl2plan.errors import Nl2Hltl2PlanError


class MissingExtraError(Nl2Hltl2PlanError):
    """An optional dependency group is not installed."""


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "serve",
        help="the local web app: instruction -> HTT, spec, animated plan and Gantt chart",
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

    print(f"serving on http://{args.host}:{args.port}/  (Ctrl-C to stop)")
    uvicorn.run(APP_FACTORY, factory=True, host=args.host, port=args.port, log_level="warning")
    return 0
