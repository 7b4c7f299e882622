"""The benchmark ground truth (benchmark/alfred_test50_gt.jsonl) as `GTInstance`s."""

from __future__ import annotations

import json
from functools import cache

from pydantic import ValidationError

from nl2hltl2plan.config import data_path
from nl2hltl2plan.errors import DataError, WorldError
from nl2hltl2plan.worlds.tasks import GTInstance


@cache
def _load() -> tuple[GTInstance, ...]:
    path = data_path("benchmark", "alfred_test50_gt.jsonl")
    out = []
    for n, line in enumerate(path.read_text().splitlines(), 1):
        if not line.strip():
            continue
        try:
            out.append(GTInstance.model_validate_json(line))
        except ValidationError as exc:
            raise DataError(f"{path}:{n}: not a ground-truth instance: {exc.errors()[0]['msg']}") from None
        except json.JSONDecodeError as exc:  # pragma: no cover - pydantic wraps this
            raise DataError(f"{path}:{n}: {exc}") from None
    return tuple(out)


def load_gt() -> list[GTInstance]:
    """All 200 instances, in file order."""
    return list(_load())


def gt_instance(instance_id: str) -> GTInstance:
    for inst in _load():
        if inst.id == instance_id:
            return inst
    raise WorldError(f"no benchmark instance {instance_id!r} in alfred_test50_gt.jsonl")
