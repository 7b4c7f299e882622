"""Which LLM backend to use, and its client for the length of a run."""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator
from typing import Literal, get_args

from nl2hltl2plan.config.llm_settings import LLMSettings
from nl2hltl2plan.errors import LLMError
from nl2hltl2plan.language.llm.batch import BatchCollector
from nl2hltl2plan.language.llm.client import LLMClient
from nl2hltl2plan.language.parsers import PARSERS  # the backends that need no LLM

Backend = Literal["offline", "learned", "grammar", "local", "openai"]
BACKENDS: tuple[str, ...] = get_args(Backend)


def resolve_backend(requested: str | None, settings: LLMSettings) -> tuple[Backend, str | None]:
    """The backend to use and a note for stderr (None: nothing to say)."""
    if requested in (None, "", "auto"):
        if settings.configured:
            return "openai", None
        return "offline", (
            "no LLM configured (NL2HLTL2PLAN_LLM_BASE_URL / NL2HLTL2PLAN_LLM_API_KEY): using the "
            "offline parser (grammar + learned model)"
        )
    for name in get_args(Backend):
        if requested == name:
            return name, None
    raise LLMError(f"unknown LLM backend {requested!r}; choose one of {', '.join(BACKENDS)}")


LOCAL_TIMEOUTS = {"timeout": 300.0, "instruction_timeout": 900.0}  # --llm local on this machine's CPU


@contextlib.contextmanager
def open_client(
    backend: str,
    settings: LLMSettings,
    batch: BatchCollector | None = None,
    on_request: Callable[[str], None] | None = None,
) -> Iterator[LLMClient | None]:
    """An `LLMClient` for the backend (None for the parsers); the local backend runs its server meanwhile."""
    if backend in PARSERS:
        yield None
        return
    if backend not in LLM_CLIENTS:
        raise LLMError(f"unknown LLM backend {backend!r}; choose one of {', '.join(BACKENDS)}")
    with LLM_CLIENTS[backend](settings, batch, on_request) as client:
        yield client


@contextlib.contextmanager
def _server_client(
    settings: LLMSettings, batch: BatchCollector | None, on_request: Callable[[str], None] | None
) -> Iterator[LLMClient]:
    """`openai`: any OpenAI-compatible server the settings name."""
    if not settings.configured and batch is None:
        raise LLMError(
            "no LLM configured: set NL2HLTL2PLAN_LLM_BASE_URL and/or NL2HLTL2PLAN_LLM_API_KEY "
            "(or --base-url / --api-key), or use --llm local / --llm offline"
        )
    yield LLMClient(settings, batch=batch, on_request=on_request)


@contextlib.contextmanager
def _local_client(
    settings: LLMSettings, batch: BatchCollector | None, on_request: Callable[[str], None] | None
) -> Iterator[LLMClient]:
    """`local`: a llama.cpp server on a GGUF file, started for the length of the run."""
    from nl2hltl2plan.language.llm.local_server import LocalServer, smollm2_path

    gguf = settings.gguf or smollm2_path()
    # the server's port changes every run: name the model file in cache keys instead; a small model
    # generating on a CPU is slow but alive, so unless the user set them, its deadlines are longer
    slow = {k: v for k, v in LOCAL_TIMEOUTS.items() if k not in settings.model_fields_set}
    local = settings.model_copy(
        update={"model": gguf.name, "api_key": "none", "cache_scope": f"local:{gguf.name}", **slow}
    )
    if batch is not None:  # batch mode answers from the cache only: no server needed
        yield LLMClient(local, batch=batch, on_request=on_request)
        return
    with LocalServer(gguf, threads=settings.threads, ctx=settings.ctx) as server:
        yield LLMClient(local.model_copy(update={"base_url": server.base_url}), on_request=on_request)


# the backends that talk to an LLM, by name (those that need none are `parsers.PARSERS`)
LLM_CLIENTS = {"openai": _server_client, "local": _local_client}


def load_batch_answers(path: str, settings: LLMSettings) -> tuple[int, list[str]]:
    """Load an OpenAI Batch API output file into the answer cache: (answers loaded, error lines)."""
    from nl2hltl2plan.language.llm.batch import read_answers
    from nl2hltl2plan.language.llm.cache import AnswerCache

    if settings.cache_dir is None:
        raise LLMError("--batch-answers needs the answer cache (do not combine it with --cache off)")
    n, errors = read_answers(path, AnswerCache(settings.cache_dir))
    return n, list(errors)
