"""What one run leaves behind: the files `plan -o DIR` writes and the web page offers for download.

- `result.json`: the JSON of `plan --json` (`Outcome.to_json()`, docs/plan.schema.json);
- `spec.json`: the hierarchical sc-LTL specification (levels of named flat formulas);
- `spec.hoa`: every flat formula's automaton in the HOA format (written by Spot), one after another;
- `htt`, `world`, `plan`, `gantt` pictures, each as `.png` and `.svg` (`plan` and `gantt` only when
  there is a plan).

Every file is written to a temporary name and renamed, so a killed run leaves no torn file.

>>> [name for name in output_names(has_plan=False) if name.endswith(".svg")]
['htt.svg', 'world.svg']
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.io import atomic_path, save_figure
from nl2hltl2plan.pipeline import Outcome

PICTURES = ("htt", "world", "plan", "gantt")
PLAN_PICTURES = ("plan", "gantt")  # drawn only when there is a plan
FORMATS = ("png", "svg")
DPI = 110


def output_names(has_plan: bool, formats: tuple[str, ...] = FORMATS) -> list[str]:
    """The files `write_outputs` writes, in order (spec.hoa may be left out: see its warnings)."""
    pictures = [p for p in PICTURES if has_plan or p not in PLAN_PICTURES]
    return ["result.json", "spec.json", "spec.hoa"] + [f"{p}.{f}" for p in pictures for f in formats]


def _replace(path: Path, data: bytes) -> None:
    with atomic_path(path, "output file") as tmp:
        tmp.write_bytes(data)


def _figure(outcome: Outcome, name: str) -> Any:
    from nl2hltl2plan.present.gantt import draw_gantt
    from nl2hltl2plan.present.htt_pictures import htt_figure, htt_orderings, htt_task_words
    from nl2hltl2plan.present.pictures import draw_execution, draw_world

    execution = outcome.result.execution
    if name == "htt":
        return htt_figure(outcome.language.htt, title=outcome.instruction)
    if name == "world":
        return draw_world(outcome.world, title=outcome.world.name)
    assert execution is not None
    if name == "plan":
        return draw_execution(execution)
    htt = outcome.language.htt
    return draw_gantt(execution, before=htt_orderings(htt), words=htt_task_words(htt))


def _hoa(outcome: Outcome) -> str:
    from nl2hltl2plan.logic import spot_backend

    spec = outcome.spec
    return "".join(spot_backend.hoa(spec.formula(name)) for name in spec.names)


def write_outputs(
    folder: str | Path,
    outcome: Outcome,
    payload: dict[str, Any] | None = None,
    formats: tuple[str, ...] = FORMATS,
) -> list[str]:
    """Write the run's files into `folder` (it must exist); returns warnings (a file not written and
    why: an automaton too large for Spot's limits leaves spec.hoa out)."""
    import matplotlib.pyplot as plt

    out = Path(folder)
    warnings: list[str] = []
    result = payload if payload is not None else outcome.to_json()
    _replace(out / "result.json", json.dumps(result, indent=1, default=str).encode())
    _replace(out / "spec.json", outcome.spec.to_json(indent=1).encode())  # with its constraints, if any
    try:
        hoa = _hoa(outcome)
    except Nl2Hltl2PlanError as exc:
        warnings.append(f"spec.hoa not written: {exc}")
    else:
        _replace(out / "spec.hoa", hoa.encode())
    has_plan = outcome.result.execution is not None
    for name in PICTURES:
        if name in PLAN_PICTURES and not has_plan:
            continue
        fig = _figure(outcome, name)
        try:
            dpi = "figure" if name == "htt" else DPI  # the tree chooses its own, to fit 1,600 px
            for fmt in formats:
                save_figure(fig, out / f"{name}.{fmt}", "picture", dpi=dpi, bbox_inches="tight")
        finally:
            plt.close(fig)
    return warnings
