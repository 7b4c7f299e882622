"""Options that several commands share, declared once: the backend choice and the planner group (the
LLM group is `language.llm.llm_options`; value types that refuse bad numbers are `argtypes`)."""

from __future__ import annotations

import argparse
from typing import Any

from nl2hltl2plan.argtypes import int_in, ints_in, seconds
from nl2hltl2plan.language.backends import BACKENDS
from nl2hltl2plan.language.llm.llm_options import add_llm_arguments, llm_settings


def add_backend_argument(
    p: argparse.ArgumentParser, default: str | None = None, help_extra: str = ""
) -> None:
    p.add_argument(
        "--llm",
        choices=BACKENDS,
        default=default,
        help="language backend: offline (grammar + learned slot model, no LLM; alias learned), grammar "
        "(the parser alone), local (llama.cpp GGUF) or openai (any OpenAI-compatible server)" + help_extra,
    )


def add_planner_arguments(p: argparse.ArgumentParser, timeout_help: str = "planner time limit") -> None:
    g = p.add_argument_group("planner")
    g.add_argument(
        "--objective",
        choices=["min", "minmax"],
        default="min",
        help="min: moves + actions over all robots (the paper's cost); minmax: completion "
        "time (default: min)",
    )
    g.add_argument(
        "--mode",
        choices=["fast", "exact"],
        default="fast",
        help="fast: anytime with a proven bound; exact: proven optimal (default: fast)",
    )
    g.add_argument(
        "--timeout",
        type=seconds,
        default=300.0,
        help=f"{timeout_help} in seconds (default 300, at most a week)",
    )


def planner_options(args: argparse.Namespace) -> dict[str, Any]:
    return {"objective": args.objective, "mode": args.mode, "plan_timeout_s": args.timeout}


__all__ = [
    "add_backend_argument",
    "add_llm_arguments",
    "add_planner_arguments",
    "int_in",
    "ints_in",
    "llm_settings",
    "planner_options",
    "seconds",
]
