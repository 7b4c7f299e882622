"""`nl2hltl2plan` console script: one sub-command per module in this package.

Each command module exposes `register(subparsers)`, which adds its parser and sets `func`, a
callable taking the parsed arguments and returning the exit code. Errors of the package's own
family are printed as one readable message (exit 2 unless the command says otherwise); the CLI
never shows a traceback for user input. The exit statuses (docs/reliability.md): 0 success, 1 a
definite "no", 2 bad input or usage, 3 LLM requests pending (batch mode), 4 an internal error (a
bug), 130 interrupted, 141 output cut by a closed pipe (`| head`: quiet, as Unix tools).
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from collections.abc import Sequence
from typing import NoReturn

from nl2hltl2plan import __version__
from nl2hltl2plan.cli.commands import COMMANDS
from nl2hltl2plan.config import debug
from nl2hltl2plan.errors import Nl2Hltl2PlanError


class _Parser(argparse.ArgumentParser):
    """Usage errors as one line on stderr (exit 2), pointing at --help instead of dumping the usage."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"error: {self.prog}: {message} (see {self.prog} --help)\n")


def _command_in(argv: Sequence[str]) -> str | None:
    """The sub-command named on the command line: the first word that is not an option (the top-level
    options, -h and --version, take no value)."""
    return next((a for a in argv if not a.startswith("-")), None)


def build_parser(command: str | None = "*") -> argparse.ArgumentParser:
    """The CLI's parser. Only `command`'s module is imported and registered in full (every one for "*");
    each other command is a stub carrying its help line, so `--help` and each command start without
    importing the rest of the package (the pipeline pulls in scipy, networkx, Spot)."""
    parser = _Parser(
        prog="nl2hltl2plan",
        description="Natural language -> Hierarchical Task Tree -> hierarchical sc-LTL -> multi-robot plans.",
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, help_line in COMMANDS.items():
        if command in (name, "*"):
            importlib.import_module(f"nl2hltl2plan.cli.cmd_{name}").register(sub)
        else:
            sub.add_parser(name, help=help_line, add_help=False)
    return parser


INTERNAL_ERROR = 4  # an unexpected exception: a bug of ours, not the user's input
BROKEN_PIPE = 141  # 128 + SIGPIPE: what a shell reports for a Unix tool whose reader went away


def _is_validation_error(exc: Exception) -> bool:
    """A pydantic ValidationError, told without importing pydantic (30 ms of every start-up): one can
    only have been raised if pydantic was imported."""
    pydantic = sys.modules.get("pydantic")
    return pydantic is not None and isinstance(exc, pydantic.ValidationError)


def _one_line(text: str) -> str:
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    return " | ".join(lines) if lines else "unknown error"


def main(argv: list[str] | None = None) -> int:
    try:
        code = _run(argv)
        sys.stdout.flush()  # a closed pipe shows here, while it can still be handled
        return code
    except BrokenPipeError:  # output piped into `head` & co.: stop quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # no second error at exit
        return BROKEN_PIPE


def _run(argv: list[str] | None) -> int:
    if argv is None:
        argv = sys.argv[1:]
    parser = build_parser(_command_in(argv))
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # usage errors (exit 2) and --help (exit 0), already printed
        return int(exc.code or 0) if isinstance(exc.code, int | None) else 2
    if not getattr(args, "func", None):  # no command: usage, then one line saying so (bad usage: 2)
        parser.print_help(sys.stderr)
        print(f"error: {parser.prog}: no command given; choose one of {', '.join(COMMANDS)}",
              file=sys.stderr)  # fmt: skip
        return 2
    try:
        return int(args.func(args) or 0)
    except BrokenPipeError:  # an OSError, but not the user's path: handled by `main`
        raise
    except Nl2Hltl2PlanError as exc:
        print(f"error: {_one_line(str(exc))}", file=sys.stderr)
        return exc.exit_status
    except OSError as exc:  # a path the user gave that cannot be read or written
        where = f" {exc.filename}" if exc.filename else ""
        print(f"error: cannot use{where}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # a bug: one line and its own status; NL2HLTL2PLAN_DEBUG=1 shows the traceback
        if _is_validation_error(exc):  # options validated by a pydantic model: the user's input
            err = exc.errors()[0]  # type: ignore[attr-defined]
            where = ".".join(str(x) for x in err["loc"])
            print(f"error: invalid {where}: {err['msg']}", file=sys.stderr)
            return 2
        if debug():
            raise
        print(
            f"internal error: {type(exc).__name__}: {_one_line(str(exc))} (a bug: please report it with "
            "the command; NL2HLTL2PLAN_DEBUG=1 shows the traceback)",
            file=sys.stderr,
        )
        return INTERNAL_ERROR


if __name__ == "__main__":
    sys.exit(main())
