"""One LLM interface over the official `openai` client (chat completions).

The same code path serves GPT-4-class APIs, vLLM, Ollama and llama.cpp servers (ours included):

- JSON by schema where the server supports it (`response_format` json_schema, falling back to
  json_object, then to plain text when the server rejects the format);
- every answer is validated with a pydantic model; an invalid one is re-asked with the validation
  error (at most `max_reasks` times), then `LLMError`;
- transport failures (connection, timeout, rate limit, 5xx) are retried with exponential backoff, or
  after the server's `Retry-After` when it sends one; a wait that would end past the instruction's
  deadline is an error at once, naming the wait;
- answers are cached on disk keyed by the full request, and in batch mode unanswered requests are
  collected instead of sent (`batch.py`).
"""

from __future__ import annotations

import contextlib
import datetime
import email.utils
import functools
import json
import math
import re
import ssl
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any, TypeVar

from pydantic import BaseModel, ValidationError

from nl2hltl2plan.config.llm_settings import LLMSettings
from nl2hltl2plan.errors import LLMError
from nl2hltl2plan.language.llm.batch import BatchCollector, PendingAnswer
from nl2hltl2plan.language.llm.cache import AnswerCache, request_key

T = TypeVar("T", bound=BaseModel)
Validator = Callable[[Any], None]  # extra checks after pydantic; raise ValueError with a readable message


@dataclass
class Stats:
    requests: int = 0  # answers obtained (sent or cached)
    sent: int = 0  # HTTP requests that returned an answer
    cached: int = 0
    reasks: int = 0
    retries: int = 0


def extract_json(text: str) -> Any:
    """The JSON value in an answer: the whole text, a ```json fence, or the outermost {...} / [...]."""
    s = text.strip()
    fence = re.search(r"```(?:json)?\s*(.*?)```", s, flags=re.S)
    if fence:
        s = fence.group(1).strip()
    try:
        return json.loads(s)
    except ValueError:
        pass
    except RecursionError:  # Python's JSON parser recurses: 200,000 nested brackets end here
        raise ValueError("the answer nests JSON too deeply") from None
    for open_, close in (("{", "}"), ("[", "]")):
        a, b = s.find(open_), s.rfind(close)
        if 0 <= a < b:
            try:
                return json.loads(s[a : b + 1])
            except ValueError:
                continue
            except RecursionError:
                raise ValueError("the answer nests JSON too deeply") from None
    raise ValueError("the answer is not JSON")


def _short_validation(exc: ValidationError) -> str:
    return "; ".join(
        f"{'.'.join(str(p) for p in e['loc']) or 'answer'}: {e['msg']}" for e in exc.errors()[:6]
    )


class LLMClient:
    """Ask an OpenAI-compatible server for pydantic-validated JSON answers."""

    def __init__(
        self,
        settings: LLMSettings,
        *,
        cache: AnswerCache | None = None,
        batch: BatchCollector | None = None,
        on_request: Callable[[str], None] | None = None,
        sleep: Callable[[float], None] = time.sleep,
    ) -> None:
        self.settings = settings
        self.cache = (
            cache if cache is not None else (AnswerCache(settings.cache_dir) if settings.cache_dir else None)
        )
        self.batch = batch
        self.on_request = on_request
        self.stats = Stats()
        self._sleep = sleep
        self._json_mode: str = settings.json_mode
        self._client: Any = None
        self._deadline: float | None = None  # of the current instruction (monotonic clock)
        self._explicit_deadline: float | None = None  # set by `with client.instruction():`

    # ------------------------------------------------------------------------------------------------
    @property
    def client(self) -> Any:
        if self._client is None:
            import openai

            self._client = openai.OpenAI(
                base_url=self.settings.base_url,
                api_key=self.settings.api_key or "none",
                timeout=self.settings.timeout,
                max_retries=0,
                http_client=_http_client(self.settings.timeout),
            )
        return self._client

    def _format(self, schema: type[BaseModel], name: str) -> dict[str, Any] | None:
        mode = "schema" if self._json_mode == "auto" else self._json_mode
        if mode == "schema":
            return {
                "type": "json_schema",
                "json_schema": {"name": name, "schema": schema.model_json_schema(), "strict": False},
            }
        if mode == "object":
            return {"type": "json_object"}
        return None

    def request_for(
        self, messages: list[dict[str, str]], schema: type[BaseModel], name: str
    ) -> dict[str, Any]:
        req: dict[str, Any] = {
            "model": self.settings.model,
            "messages": messages,
            "temperature": self.settings.temperature,
            "max_tokens": self.settings.max_tokens,
        }
        if self.settings.seed is not None:
            req["seed"] = self.settings.seed
        fmt = self._format(schema, name)
        if fmt is not None:
            req["response_format"] = fmt
        return req

    # ------------------------------------------------------------------------------------------------
    def ask(
        self, messages: list[dict[str, str]], schema: type[T], name: str, validate: Validator | None = None
    ) -> T:
        """Send `messages`, parse the answer as `schema` (plus `validate`), re-ask on invalid answers."""
        msgs = list(messages)
        last_err = ""
        for attempt in range(self.settings.max_reasks + 1):
            req = self.request_for(msgs, schema, name)
            content = self.complete(req, name)
            try:
                value = schema.model_validate(extract_json(content))
                if validate is not None:
                    validate(value)
                return value
            except ValidationError as exc:
                last_err = _short_validation(exc)
            except ValueError as exc:
                last_err = str(exc)
            if attempt < self.settings.max_reasks:
                self.stats.reasks += 1
                msgs = msgs + [
                    {"role": "assistant", "content": content[:4000]},
                    {
                        "role": "user",
                        "content": (
                            f"That answer is not valid: {last_err}. Answer again with only a JSON object "
                            f"that follows "
                            f"the schema: {json.dumps(schema.model_json_schema())}"
                        ),
                    },
                ]
        raise LLMError(f"{name}: no valid answer after {self.settings.max_reasks + 1} attempts ({last_err})")

    def complete(self, request: dict[str, Any], name: str = "request") -> str:
        """One chat completion (cache, batch, retries, response-format fallback); the answer text."""
        key = request_key(request, self.settings.scope)
        if self.cache is not None:
            hit = self.cache.get(key)
            if hit is not None:
                self.stats.requests += 1
                self.stats.cached += 1
                return hit
        if self.batch is not None:
            self.batch.add(key, request)
            raise PendingAnswer(key)
        if self.on_request is not None:
            self.on_request(name)
        content = self._send(request, name)
        self.stats.requests += 1
        self.stats.sent += 1
        if self.cache is not None:
            self.cache.put(key, request, content, {"name": name, "scope": self.settings.scope})
        return content

    # ----- deadlines ------------------------------------------------------------------------------------
    @contextlib.contextmanager
    def instruction(self, timeout_s: float | None = None) -> Iterator[None]:
        """Every request inside shares one deadline (`instruction_timeout` by default)."""
        outer = self._explicit_deadline
        self._deadline = self._explicit_deadline = time.monotonic() + (
            timeout_s if timeout_s is not None else self.settings.instruction_timeout
        )
        try:
            yield
        finally:
            self._explicit_deadline = outer
            self._deadline = outer

    def start_instruction(self) -> None:
        """Start the per-instruction clock (the first stage calls this) unless `instruction()` set one."""
        if self._explicit_deadline is None:
            self._deadline = time.monotonic() + self.settings.instruction_timeout

    def _time_left(self) -> float:
        """Seconds until the instruction's deadline (a whole instruction's time when none is running)."""
        if self._deadline is None:
            return self.settings.instruction_timeout
        return self._deadline - time.monotonic()

    def _budget(self, name: str) -> float:
        """Seconds the next request may take: the request timeout, cut by the instruction's deadline."""
        budget = self.settings.timeout
        if self._deadline is not None:
            left = self._deadline - time.monotonic()
            if left <= 0:
                limit = self.settings.instruction_timeout
                raise LLMError(f"{name}: the instruction's LLM requests ran past their deadline ({limit:g}s)")
            budget = min(budget, left)
        return budget

    def _create(self, request: dict[str, Any], budget: float) -> Any:
        """`chat.completions.create` under a total deadline: HTTP timeouts are per read, so a server
        trickling a byte at a time would never time out; the call runs in a helper thread that is
        abandoned (and its connection pool closed) when the deadline passes."""
        client = self.client
        box: dict[str, Any] = {}

        def call() -> None:
            try:
                box["value"] = client.chat.completions.create(**request, timeout=budget)
            except BaseException as exc:  # handed to the caller's thread
                box["error"] = exc

        worker = threading.Thread(target=call, name="llm-request", daemon=True)
        worker.start()
        worker.join(budget)
        if worker.is_alive():
            self._client = None  # a fresh client next time; closing ends the abandoned read
            threading.Thread(target=_close_quietly, args=(client,), daemon=True).start()
            raise _DeadlineExceeded(f"no complete answer within {budget:g}s")
        if "error" in box:
            raise box["error"]
        return box["value"]

    def _send(self, request: dict[str, Any], name: str) -> str:
        s = self.settings
        where = s.base_url or "the OpenAI API"
        delay = s.backoff
        attempt = 0
        while True:
            budget = self._budget(name)
            try:
                return _content(self._create(request, budget), name, where)
            except _retried() as exc:
                if attempt >= s.max_retries:
                    timed_out = isinstance(exc, _DeadlineExceeded) or type(exc).__name__ == "APITimeoutError"
                    what = "timed out" if timed_out else "failed"
                    raise LLMError(
                        f"{name}: request to {where} {what} after {attempt + 1} attempts "
                        f"(timeout {s.timeout:g}s): {_msg(exc)}"
                    ) from None
                wait = _retry_after(exc)
                if wait is not None and wait > self._time_left():
                    raise LLMError(
                        f"{name}: the server at {where} asks to retry after {wait:.0f}s, past the "
                        f"instruction's LLM deadline ({max(0.0, self._time_left()):.0f}s left of "
                        f"{s.instruction_timeout:g}s): {_msg(exc)}"
                    ) from None
                self.stats.retries += 1
                attempt += 1
                self._sleep(wait if wait is not None else min(delay, max(0.0, self._budget(name) - 0.01)))
                delay *= 2
            except _openai().BadRequestError as exc:
                if "response_format" in request and s.json_mode == "auto" and _format_rejected(exc):
                    request = self._without_format(request)
                    continue
                raise LLMError(f"{name}: the server at {where} rejected the request: {_msg(exc)}") from None
            except _openai().APIStatusError as exc:
                raise _status_error(exc, name, where, s.model) from None
            except (ValueError, RecursionError) as exc:  # a 200 whose body is not JSON
                raise LLMError(
                    f"{name}: the server at {where} answered a body that is not JSON ({_msg(exc)})"
                ) from None

    def _without_format(self, request: dict[str, Any]) -> dict[str, Any]:
        """The server does not support this JSON mode: fall back (schema -> object -> none)."""
        nxt = "object" if request["response_format"].get("type") == "json_schema" else "none"
        self._json_mode = nxt
        request = dict(request)
        if nxt == "object":
            request["response_format"] = {"type": "json_object"}
        else:
            request.pop("response_format")
        return request


class _DeadlineExceeded(Exception):
    """A request ran past its total deadline (internal: becomes an LLMError after the retries)."""


def _openai() -> Any:
    import openai

    return openai


@functools.cache
def _tls_context() -> ssl.SSLContext:
    """The process's one TLS context: the CA certificates OpenSSL finds (SSL_CERT_FILE and
    SSL_CERT_DIR included, as the SDK's default context honours them). Loading the bundle takes 30
    to 90 ms, and a client is built per instruction run (the web server, bench runs, the tests); one
    context serves any number of connections."""
    return ssl.create_default_context()


def _http_client(timeout: float) -> Any:
    """The SDK's HTTP client with its defaults (limits, redirects) on the shared TLS context; its
    connections are its own."""
    return _http_client_class()(timeout=timeout, verify=_tls_context())


@functools.cache
def _http_client_class() -> Any:
    class _Http(_openai().DefaultHttpxClient):  # type: ignore[misc]
        def __del__(self) -> None:  # closed when dropped, as the SDK's own client is
            with contextlib.suppress(Exception):
                if not self.is_closed:
                    self.close()

    return _Http


def _retried() -> tuple[type[BaseException], ...]:
    """The failures worth retrying (resolved when one happens: openai imports slowly)."""
    o = _openai()
    return (
        _DeadlineExceeded,
        o.APITimeoutError,
        o.APIConnectionError,
        o.RateLimitError,
        o.InternalServerError,
    )


def _retry_after(exc: BaseException) -> float | None:
    """Seconds the server asks to wait (`Retry-After`: seconds or an HTTP date; `retry-after-ms`)."""
    headers = getattr(getattr(exc, "response", None), "headers", None)
    if headers is None:
        return None
    millis, value = headers.get("retry-after-ms"), headers.get("retry-after")
    seconds = _number(millis)
    if seconds is not None:
        seconds /= 1000
    elif value is not None:
        seconds = _number(value)
        if seconds is None:
            try:
                when = email.utils.parsedate_to_datetime(value)
            except (TypeError, ValueError):
                return None
            if when.tzinfo is None:
                return None
            seconds = (when - datetime.datetime.now(datetime.UTC)).total_seconds()
    return None if seconds is None else max(0.0, seconds)


def _number(text: str | None) -> float | None:
    try:
        value = float(text) if text is not None else None
    except ValueError:
        return None
    return value if value is not None and math.isfinite(value) else None


def _content(resp: Any, name: str, where: str) -> str:
    """The message text of a chat completion; LLMError naming what is wrong with anything else."""
    try:
        content = resp.choices[0].message.content
    except (AttributeError, IndexError, KeyError, TypeError):
        if isinstance(resp, (str, bytes)):  # the client hands back bodies that are not JSON as text
            what = f"a body that is not JSON ({' '.join(str(resp[:60]).split())!r})"
        else:
            what = "JSON without choices[0].message (not a chat completion)"
        raise LLMError(f"{name}: the server at {where} answered {what}") from None
    if content is None:
        raise LLMError(f"{name}: the server at {where} returned no message content")
    if not isinstance(content, str):
        raise LLMError(f"{name}: the server at {where} returned message content that is not text")
    return content


def _status_error(exc: Exception, name: str, where: str, model: str) -> LLMError:
    o = _openai()
    if isinstance(exc, o.AuthenticationError):
        return LLMError(
            f"{name}: authentication failed at {where} (set NL2HLTL2PLAN_LLM_API_KEY): {_msg(exc)}"
        )
    if isinstance(exc, o.NotFoundError):
        return LLMError(f"{name}: not found at {where} (model {model!r}?): {_msg(exc)}")
    return LLMError(f"{name}: the server at {where} answered {getattr(exc, 'status_code', '?')}: {_msg(exc)}")


def _close_quietly(client: Any) -> None:
    try:
        client.close()
    except Exception:  # noqa: BLE001 - best effort on an abandoned client
        pass


def _msg(exc: BaseException) -> str:
    text = getattr(exc, "message", None) or str(exc)
    return text.splitlines()[0][:300] if text else exc.__class__.__name__


def _format_rejected(exc: Exception) -> bool:
    text = (getattr(exc, "message", "") or str(exc)).lower()
    return any(w in text for w in ("response_format", "json_schema", "json schema", "json_object", "grammar"))
