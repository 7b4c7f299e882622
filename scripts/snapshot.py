"""A deterministic snapshot of the system's behaviour, to compare before and after a refactor.

    python scripts/snapshot.py OUT.jsonl            # about two minutes on a loaded 2-core machine
    diff <(python scripts/snapshot.py /dev/stdout) OLD.jsonl

One JSON line per observation, sorted keys, timings and machine facts left out:
- `plan`: the `plan --json` command on the built-in worlds (demo, tabletop, handover) and on ALFRED
  floor plans with the offline backend: spec, plan, costs, the planner's status and bound;
- `oracle`: oracle specs of the issue-23 trust instructions (tests/language/data/trust/plain.jsonl,
  the project's own set, never test50) planned with `pipeline.planning_stage` and judged by the checker;
- `language`: the offline and grammar language stages on every trust instruction: the HTT, base
  tasks, orderings and the printed hierarchical spec, or the refusal's message;
- `bench`: the tabletop, handover and SMART-LLM (oracle) summaries and rows, run through the CLI.

It goes through the CLI and the stable entry points (`pipeline`, `planning.oracle_spec`,
`worlds.load_world`), so the same script runs before and after modules move.
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
TRUST = ROOT / "tests" / "language" / "data" / "trust"
TIMING = ("_s", "_ms", "memory_mb", "runtime", "time_s")  # key endings that measure the machine, not us

PLANS: list[tuple[str, str, str]] = [  # (world, robots, instruction)
    ("demo", "1", "put the apple in the fridge"),
    ("demo", "2", "put the plates and the mugs in the lower rack, then the cups in the upper rack"),
    ("demo", "2", "slice the bread and put a mug in the sink; after that turn on the floor lamp"),
    ("tabletop", "1", "Place the green apple in the blue plate and the orange in the yellow plate."),
    ("handover-square", "4", "Transfer the red block into the opposite."),
    ("FloorPlan1", "2", "put an apple in the fridge and then put the mug in the sink"),
    ("FloorPlan301", "1", "turn on the desk lamp and look at the alarm clock under it"),
    ("FloorPlan11", "2", "put a clean mug in the coffee machine"),
]


def clean(value: Any) -> Any:
    """Drop timing keys, recursively."""
    if isinstance(value, dict):
        return {k: clean(v) for k, v in value.items() if not k.endswith(TIMING)}
    if isinstance(value, list):
        return [clean(v) for v in value]
    return value


def cli(*args: str) -> tuple[int, str, str]:
    proc = subprocess.run(
        [sys.executable, "-m", "nl2hltl2plan", *args], capture_output=True, text=True, check=False
    )
    last = proc.stderr.strip().splitlines()[-1:]  # the one-line error of a refusal
    return proc.returncode, proc.stdout, last[0] if last else ""


def plan_rows() -> list[dict]:
    rows = []
    for world, robots, text in PLANS:
        rc, out, err = cli("plan", text, "--world", world, "--robots", robots, "--llm", "offline", "--json")
        body = clean(json.loads(out)) if out.strip().startswith("{") else {"stderr": err}
        rows.append({"kind": "plan", "world": world, "robots": robots, "text": text, "rc": rc, "out": body})
    return rows


def trust(name: str) -> list[Any]:
    from nl2hltl2plan.worlds import GTInstance

    lines = (TRUST / f"{name}.jsonl").read_text().splitlines()
    return [GTInstance.model_validate_json(line) for line in lines if line.strip()]


def oracle_rows() -> list[dict]:
    from nl2hltl2plan.errors import Nl2Hltl2PlanError
    from nl2hltl2plan.logic.hierarchical import format_spec
    from nl2hltl2plan.pipeline import planning_stage
    from nl2hltl2plan.planning import oracle_spec
    from nl2hltl2plan.worlds import load_world
    from nl2hltl2plan.worlds.starts import start_cells

    rows = []
    for gt in trust("plain")[::4]:  # every fourth line: all six floor plans, a few seconds
        world = load_world(gt.scene)
        row: dict[str, Any] = {"kind": "oracle", "id": gt.id}
        try:
            spec = oracle_spec(gt, world).spec
            planned = planning_stage(world, spec, start_cells(world, 2), gt=gt)
            res = planned.result
            row |= {
                "spec": format_spec(spec),
                "status": str(res.status),
                "cost": res.cost,
                "plan": res.plan.model_dump(mode="json") if res.plan else None,
                "check": None if planned.check is None else planned.check.model_dump(mode="json"),
            }
        except Nl2Hltl2PlanError as exc:
            row["error"] = str(exc)
        rows.append(row)
    return rows


def language_rows() -> list[dict]:
    from nl2hltl2plan.errors import Nl2Hltl2PlanError
    from nl2hltl2plan.logic.hierarchical import format_spec
    from nl2hltl2plan.pipeline import PipelineOptions, language_stage
    from nl2hltl2plan.worlds import load_world

    rows = []
    for backend in ("offline", "grammar"):
        options = PipelineOptions(backend=backend)
        for name in ("plain", "mixed"):
            for gt in trust(name):
                row: dict[str, Any] = {"kind": "language", "backend": backend, "id": gt.id}
                try:
                    res = language_stage(gt.instruction, load_world(gt.scene), options)
                    row |= res.model_dump(mode="json", exclude={"llm_calls"})
                    row["spec"] = format_spec(res.spec) if res.spec is not None else None
                except Nl2Hltl2PlanError as exc:
                    row["error"] = f"{type(exc).__name__}: {exc}"
                rows.append(row)
    return rows


def bench_rows() -> list[dict]:
    rows = []
    runs = {
        "tabletop": ["--instances", "2", "--baseline", "none"],
        "handover": ["--instances", "1", "--baseline", "none"],
        "smartllm": ["--oracle", "--quiet"],
    }
    with tempfile.TemporaryDirectory() as tmp:
        for suite, extra in runs.items():
            out = Path(tmp) / suite
            rc, _, err = cli("bench", suite, "-o", str(out), *extra)
            rows.append({"kind": "bench", "suite": suite, "rc": rc, "stderr": err if rc else ""})
            if (out / "summary.json").exists():
                summary = json.loads((out / "summary.json").read_text())
                rows.append({"kind": "bench-summary", "suite": suite, "summary": clean(summary)})
            if (out / "rows.jsonl").exists():
                for line in (out / "rows.jsonl").read_text().splitlines():
                    rows.append({"kind": "bench-row", "suite": suite, "row": clean(json.loads(line))})
    return rows


def main() -> int:
    if len(sys.argv) != 2:
        print("usage: python scripts/snapshot.py OUT.jsonl", file=sys.stderr)
        return 2
    rows = plan_rows() + oracle_rows() + language_rows() + bench_rows()
    text = "".join(json.dumps(r, sort_keys=True) + "\n" for r in rows)
    Path(sys.argv[1]).write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
