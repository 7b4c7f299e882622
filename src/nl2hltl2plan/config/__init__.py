"""Settings read from the environment, in one place: this package (`config.llm_settings` holds the LLM's
and the learned translator's, `config.reading_settings` the offline readers', as pydantic-settings models;
nothing else in the package reads the environment).

`NL2HLTL2PLAN_DATA` points at the shared data folder (ALFRED layouts, trials, benchmark ground
truth...). Default: `../shared/data` relative to the repository root, falling back to the current
directory's `../shared/data`. The data is read in place and never copied into the repository.

`user_cache_dir()` is where the package writes for the user (LLM answers, a retrained language model):
`$XDG_CACHE_HOME/nl2hltl2plan`, default `~/.cache/nl2hltl2plan`; never the installed package.
"""

from __future__ import annotations

import os
from pathlib import Path

from nl2hltl2plan.errors import DataError

DATA_ENV = "NL2HLTL2PLAN_DATA"
DEBUG_ENV = "NL2HLTL2PLAN_DEBUG"  # set: an internal error shows its traceback
MAX_SECONDS = 7 * 24 * 3600.0  # a week: above any sensible time limit, below what timers accept
# what the data folder must hold, named in every message about a missing folder or file
DATA_CONTENTS = (
    "alfred/ (layouts/, trials.jsonl.gz, affordances), alfred_multiagent/, benchmark/ (ground truth), "
    "smartllm/ and nl2ltl/ — see the data README"
)
_REPO_ROOT = Path(__file__).resolve().parents[3]  # config/__init__.py -> the repository


def debug() -> bool:
    """Whether NL2HLTL2PLAN_DEBUG asks for tracebacks of internal errors."""
    return bool(os.environ.get(DEBUG_ENV))


def user_cache_dir() -> Path:
    """The user's cache folder of the package (it may not exist yet)."""
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "nl2hltl2plan"


def data_dir(required: bool = True) -> Path | None:
    """The shared data folder, or None (required=False) / DataError (required=True) when absent."""
    env = os.environ.get(DATA_ENV)
    candidates = (
        [Path(env)] if env else [_REPO_ROOT.parent / "shared" / "data", Path.cwd().parent / "shared" / "data"]
    )
    for path in candidates:
        if path.is_dir():
            return path
    if required:
        where = f"{DATA_ENV}={env}" if env else f"{DATA_ENV} is unset and " + " or ".join(
            str(c) for c in candidates) + " does not exist"
        raise DataError(
            f"shared data folder not found ({where}); set {DATA_ENV} to the folder that holds {DATA_CONTENTS}"
        )
    return None


def data_path(*parts: str) -> Path:
    """A file inside the shared data folder; DataError naming it when it does not exist."""
    base = data_dir(required=True)
    assert base is not None
    path = base.joinpath(*parts)
    if not path.exists():
        raise DataError(
            f"missing data file {path} in the data folder {base} ({DATA_ENV}); "
            f"the folder must hold {DATA_CONTENTS}"
        )
    return path
