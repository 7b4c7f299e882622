"""Settings of the offline readers: one pydantic-settings model filled from environment variables, as the
LLM's are (`config.llm_settings`).

| variable | meaning | default |
| --- | --- | --- |
| `NL2HLTL2PLAN_REQUEST_UNITS` | the request-unit classifier on (`1`, `true`) or off (`0`, `false`) | 1 |

On, the household reader drops the units the classifier is sure are a voice's frame
(`language.learned.request_units.frames_classified`, h287); off, the rules alone read them.
Read on each call, so a test or a script may turn it off and on again within one process.
"""

from __future__ import annotations

from pydantic import ValidationError
from pydantic_settings import BaseSettings, SettingsConfigDict

from nl2hltl2plan.errors import Nl2Hltl2PlanError

REQUEST_UNITS_ENV = "NL2HLTL2PLAN_REQUEST_UNITS"


class ReadingSettings(BaseSettings):
    """The offline readers' settings (table above)."""

    model_config = SettingsConfigDict(env_prefix="NL2HLTL2PLAN_", extra="ignore")

    # measured and adopted: over every committed set 5 more lines convert and none is lost or read wrong
    # (results/language/h287.md)
    request_units: bool = True


def request_units_on() -> bool:
    """Whether the request-unit classifier drops frame units (`NL2HLTL2PLAN_REQUEST_UNITS`); a value that
    is no yes or no is refused in one line."""
    try:
        return ReadingSettings().request_units
    except ValidationError:
        raise Nl2Hltl2PlanError(f"{REQUEST_UNITS_ENV} must be 1 or 0 (true or false)") from None
