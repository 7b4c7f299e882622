"""LLM backends: one OpenAI-compatible client, a local llama.cpp server, an answer cache, batch files."""

from nl2hltl2plan.config.llm_settings import LLMSettings
from nl2hltl2plan.language.llm.batch import BatchCollector, PendingAnswer, read_answers
from nl2hltl2plan.language.llm.cache import AnswerCache, request_key
from nl2hltl2plan.language.llm.client import LLMClient, extract_json
from nl2hltl2plan.language.llm.local_server import LocalServer, smollm2_path, xllamacpp_available

__all__ = [
    "AnswerCache",
    "BatchCollector",
    "LLMClient",
    "LLMSettings",
    "LocalServer",
    "PendingAnswer",
    "extract_json",
    "read_answers",
    "request_key",
    "smollm2_path",
    "xllamacpp_available",
]
