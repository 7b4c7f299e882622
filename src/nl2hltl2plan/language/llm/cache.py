"""A disk cache of LLM answers keyed by the full request (reproducible, resumable runs).

The key is the SHA-256 of the canonical JSON of the request body (model, messages, temperature,
response format, token limit, seed): the same request always gets the same recorded answer, whichever
server URL it was sent to. One small JSON file per answer, `<dir>/<key[:2]>/<key>.json`, written
atomically, holding the request and the answer text.
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
from pathlib import Path
from typing import Any


def request_key(request: dict[str, Any]) -> str:
    canon = json.dumps(request, sort_keys=True, ensure_ascii=False, separators=(",", ":"))
    return hashlib.sha256(canon.encode()).hexdigest()


class AnswerCache:
    def __init__(self, directory: str | Path) -> None:
        self.dir = Path(directory)

    def _path(self, key: str) -> Path:
        return self.dir / key[:2] / f"{key}.json"

    def get(self, key: str) -> str | None:
        try:
            return json.loads(self._path(key).read_text())["answer"]
        except (OSError, ValueError, KeyError):
            return None

    def put(
        self, key: str, request: dict[str, Any] | None, answer: str, meta: dict[str, Any] | None = None
    ) -> None:
        path = self._path(key)
        path.parent.mkdir(parents=True, exist_ok=True)
        payload = {"key": key, "request": request, "answer": answer, **(meta or {})}
        fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
        with os.fdopen(fd, "w") as f:
            json.dump(payload, f, ensure_ascii=False, indent=1)
        os.replace(tmp, path)

    def __contains__(self, key: str) -> bool:
        return self._path(key).exists()

    def __len__(self) -> int:
        return sum(1 for _ in self.dir.glob("*/*.json")) if self.dir.exists() else 0
