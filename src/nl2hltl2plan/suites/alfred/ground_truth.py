"""The benchmark ground truth as `GTInstance`s: the one loader for `alfred_test50_gt.jsonl` and for any
JSON-lines file with its schema (`bench alfred --gt FILE`)."""

from __future__ import annotations

from functools import cache
from pathlib import Path

from pydantic import ValidationError

from nl2hltl2plan.config import data_path
from nl2hltl2plan.errors import DataError, WorldError
from nl2hltl2plan.io import read_jsonl
from nl2hltl2plan.worlds.tasks import GTInstance


def _parse(path: Path) -> tuple[GTInstance, ...]:
    out = []
    for n, obj in enumerate(read_jsonl(path, "ground-truth file"), start=1):
        try:
            out.append(GTInstance.model_validate(obj))
        except ValidationError as exc:
            err = exc.errors()[0]
            where = ".".join(str(x) for x in err["loc"])
            raise DataError(
                f"{path}: record {n} is not a ground-truth instance: {where}: {err['msg']}"
            ) from None
    return tuple(out)


@cache
def _default() -> tuple[GTInstance, ...]:
    return _parse(data_path("benchmark", "alfred_test50_gt.jsonl"))


def load_gt(path: str | Path | None = None) -> list[GTInstance]:
    """All instances in file order: the benchmark's 200 (default) or those of `path`."""
    return list(_default() if path is None else _parse(Path(path)))


def gt_instance(instance_id: str) -> GTInstance:
    for inst in _default():
        if inst.id == instance_id:
            return inst
    raise WorldError(f"no benchmark instance {instance_id!r} in alfred_test50_gt.jsonl")
