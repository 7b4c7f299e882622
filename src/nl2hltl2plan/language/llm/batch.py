"""Batch mode: collect pending requests as one JSONL file in the OpenAI Batch API format, and read the
answers file back into the answer cache.

A run in batch mode answers every request it can from the cache; each request that has no recorded
answer is written (once) to the batch file and the instruction waits (`PendingAnswer`). Submit the file
(`openai.batches.create(input_file=..., endpoint="/v1/chat/completions")`), download the output file,
load it with `read_answers` (CLI: `--batch-answers FILE`) and run again: the next stage's requests are
pending then, until every instruction is complete (each stage depends on the previous one's answer).

Request line:  {"custom_id": KEY, "method": "POST", "url": "/v1/chat/completions", "body": REQUEST}
Answer line:   {"custom_id": KEY, "response": {"status_code": 200, "body": CHAT_COMPLETION}, "error": null}
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import DataError, LLMError
from nl2hltl2plan.io import read_text, write_text
from nl2hltl2plan.language.llm.cache import AnswerCache

ENDPOINT = "/v1/chat/completions"


class PendingAnswer(LLMError):
    """Raised in batch mode when a request has no recorded answer yet (it was added to the batch)."""

    def __init__(self, key: str) -> None:
        super().__init__(f"answer {key[:12]} pending (batch mode)")
        self.key = key


class BatchCollector:
    def __init__(self) -> None:
        self.requests: dict[str, dict[str, Any]] = {}

    def add(self, key: str, request: dict[str, Any]) -> None:
        self.requests.setdefault(key, request)

    def __len__(self) -> int:
        return len(self.requests)

    def write(self, path: str | Path) -> int:
        """Write the pending requests (JSONL, Batch API format); returns how many."""
        lines = [
            json.dumps({"custom_id": key, "method": "POST", "url": ENDPOINT, "body": req}, ensure_ascii=False)
            for key, req in self.requests.items()
        ]
        write_text(path, "\n".join(lines) + ("\n" if lines else ""), "batch file")  # atomic
        return len(lines)


def _read_text(path: str | Path, what: str) -> str:
    """The file's text: a regular UTF-8 file (a FIFO is refused before opening, not waited on)."""
    try:
        return read_text(path, what)
    except DataError as exc:
        raise LLMError(str(exc)) from None


def read_requests(path: str | Path) -> dict[str, dict[str, Any]]:
    out: dict[str, dict[str, Any]] = {}
    for n, line in enumerate(_read_text(path, "batch requests").splitlines(), 1):
        if line.strip():
            try:
                row = json.loads(line)
                out[row["custom_id"]] = row.get("body")
            except (ValueError, KeyError, TypeError, AttributeError, RecursionError):
                raise LLMError(f"batch requests {path} line {n}: not a Batch API request line") from None
    return out


def read_answers(
    path: str | Path, cache: AnswerCache, requests: str | Path | None = None
) -> tuple[int, list[str]]:
    """Store every successful answer of a Batch API output file in `cache`; (stored, error messages)."""
    text = _read_text(path, "batch answers")
    bodies = read_requests(requests) if requests else {}
    stored, errors = 0, []
    for n, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        try:
            row = json.loads(line)
            key = str(row["custom_id"])
        except (ValueError, KeyError, TypeError, RecursionError):
            errors.append(f"line {n}: not a batch answer")
            continue
        if not isinstance(row, dict) or not isinstance(row.get("response") or {}, dict):
            errors.append(f"line {n}: not a batch answer")
            continue
        resp = row.get("response") or {}
        if row.get("error") or resp.get("status_code", 200) != 200:
            errors.append(f"{key[:12]}: {row.get('error') or resp.get('status_code')}")
            continue
        try:
            content = resp["body"]["choices"][0]["message"]["content"]
        except (KeyError, IndexError, TypeError):
            content = None
        if not isinstance(content, str):
            errors.append(f"{key[:12]}: answer has no message content")
            continue
        cache.put(key, bodies.get(key), content, {"source": "batch"})
        stored += 1
    return stored, errors
