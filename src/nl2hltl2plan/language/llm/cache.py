"""A disk cache of LLM answers keyed by the full request (reproducible, resumable runs).

The key is the SHA-256 of the canonical JSON of the request body (model, messages, temperature,
response format, token limit, seed) and of the scope, which names the server that answered (its base
URL unless `cache_scope` is set): the same request to the same server always gets the same recorded
answer, and one server's answers are never replayed as another's. One small JSON file per answer,
`<dir>/<key[:2]>/<key>.json`, written atomically, holding the request and the answer text.
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
from pathlib import Path
from typing import Any


def request_key(request: dict[str, Any], scope: str | None = None) -> str:
    keyed: dict[str, Any] = request if scope is None else {"scope": scope, "request": request}
    canon = json.dumps(keyed, sort_keys=True, ensure_ascii=False, separators=(",", ":"))
    return hashlib.sha256(canon.encode()).hexdigest()


class AnswerCache:
    def __init__(self, directory: str | Path) -> None:
        self.dir = Path(directory)

    def _path(self, key: str) -> Path:
        return self.dir / key[:2] / f"{key}.json"

    def get(self, key: str) -> str | None:
        try:
            answer = json.loads(self._path(key).read_text())["answer"]
        except (OSError, ValueError, KeyError, TypeError, RecursionError):  # absent or damaged: ask again
            return None
        return answer if isinstance(answer, str) else None

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
