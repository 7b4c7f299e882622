"""The LLM client's command-line options, declared once for every command and script that talks to an
LLM (each option can also be set by its NL2HLTL2PLAN_LLM_* variable, see `config.llm_settings`)."""

from __future__ import annotations

import argparse

from nl2hltl2plan.argtypes import int_in, seconds
from nl2hltl2plan.config.llm_settings import LLMSettings


def add_llm_arguments(p: argparse.ArgumentParser, batch: bool = False) -> None:
    """The LLM client's options (each also readable from an NL2HLTL2PLAN_LLM_* variable); `batch`: also
    --batch-out / --batch-answers (only commands that implement batch mode offer them)."""
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
        type=seconds,
        default=None,
        help="seconds one LLM request may take in total (default 30; raise it for slow servers)",
    )
    g.add_argument(
        "--llm-instruction-timeout",
        type=seconds,
        default=None,
        help="seconds all LLM requests of one instruction may take, retries and waits included (default 60)",
    )
    g.add_argument(
        "--retries", type=int_in(0, 20), default=None, help="retries of failed requests, 0..20 (default 3)"
    )
    g.add_argument(
        "--gguf", default=None, help="GGUF model file for --llm local (default: the SmolLM2 test model)"
    )
    g.add_argument(
        "--threads", type=int_in(1, 256), default=None, help="local server CPU threads, 1..256 (default 1)"
    )
    g.add_argument(
        "--cache", default=None, help="answer cache folder, or 'off' (default ~/.cache/nl2hltl2plan/llm)"
    )
    if not batch:
        return
    g.add_argument(
        "--batch-out",
        default=None,
        help="batch mode: write pending requests (OpenAI Batch JSONL) to this new file; an existing "
        "file is refused, never overwritten (default: off)",
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
        instruction_timeout=args.llm_instruction_timeout,
        max_retries=args.retries,
        gguf=args.gguf,
        threads=args.threads,
        cache_dir=args.cache,
    )
