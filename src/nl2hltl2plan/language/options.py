"""The LLM client's command-line options, declared once for every command and script that talks to an
LLM (each option can also be set by its NL2HLTL2PLAN_LLM_* variable, see `llm/settings.py`)."""

from __future__ import annotations

import argparse

from nl2hltl2plan.argtypes import positive_float, positive_int
from nl2hltl2plan.language.llm.settings import LLMSettings


def add_llm_arguments(p: argparse.ArgumentParser) -> None:
    """The LLM client's options (each also readable from an NL2HLTL2PLAN_LLM_* variable)."""
    g = p.add_argument_group("LLM backend (environment: NL2HLTL2PLAN_LLM_*)")
    g.add_argument(
        "--base-url",
        default=None,
        help="OpenAI-compatible endpoint (vLLM, Ollama, llama.cpp ...) (default: none)",
    )
    g.add_argument("--model", default=None, help="model name (default: gpt-4o)")
    g.add_argument("--api-key", default=None, help="API key (better: NL2HLTL2PLAN_LLM_API_KEY)")
    g.add_argument("--temperature", type=float, default=None, help="sampling temperature (default 0)")
    g.add_argument(
        "--llm-timeout",
        type=positive_float,
        default=None,
        help="seconds an LLM request may take in total (default 120)",
    )
    g.add_argument("--retries", type=int, default=None, help="retries of failed requests (default 3)")
    g.add_argument(
        "--gguf", default=None, help="GGUF model file for --llm local (default: the SmolLM2 test model)"
    )
    g.add_argument(
        "--threads", type=positive_int, default=None, help="CPU threads of the local server (default 1)"
    )
    g.add_argument(
        "--cache", default=None, help="answer cache folder, or 'off' (default ~/.cache/nl2hltl2plan/llm)"
    )
    g.add_argument(
        "--batch-out",
        default=None,
        help="batch mode: write pending requests (OpenAI Batch JSONL) here (default: off)",
    )
    g.add_argument(
        "--batch-answers",
        default=None,
        help="load an OpenAI Batch API output file into the cache first (default: none)",
    )


def llm_settings(args: argparse.Namespace) -> LLMSettings:
    return LLMSettings.from_env(
        base_url=args.base_url,
        model=args.model,
        api_key=args.api_key,
        temperature=args.temperature,
        timeout=args.llm_timeout,
        max_retries=args.retries,
        gguf=args.gguf,
        threads=args.threads,
        cache_dir=args.cache,
    )
