"""`nl2hltl2plan plan "INSTRUCTION" --world demo|FloorPlanN --robots N [--llm offline|local|openai]`

Instruction -> HTT -> hierarchical LTL -> multi-robot plan (planning.plan). Prints the HTT,
the base tasks, the hierarchical LTL and the plan with its travel cost and completion time; `--json`
prints one object (keys backend, htt, tasks, spec, plan ...); `-o DIR` writes pictures and result.json.
Without `--llm`, an LLM configured by NL2HLTL2PLAN_LLM_* is used, else the offline parser (said on stderr).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import sys
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import LLMError, PlanningError
from nl2hltl2plan.language.llm.batch import BatchCollector, PendingAnswer
from nl2hltl2plan.language.pipeline import (
    BACKENDS,
    LanguageResult,
    add_llm_arguments,
    load_batch_answers,
    open_client,
    resolve_backend,
    settings_from_args,
    translate,
)

EXIT_PENDING = 3


def register(sub: Any) -> None:
    p = sub.add_parser(
        "plan",
        help="instruction -> HTT -> hierarchical LTL -> multi-robot plan",
        description=__doc__.split("\n\n")[1],
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("instruction", help="the natural-language instruction (quote it)")
    p.add_argument("--world", default="demo", help="demo (built in) or an ALFRED floor plan FloorPlanN")
    p.add_argument("--robots", type=int, default=1, help="number of robots (default 1)")
    p.add_argument(
        "--llm",
        choices=BACKENDS,
        default=None,
        help="language backend (default: openai when configured, else offline)",
    )
    p.add_argument(
        "--ltl",
        choices=["compiler", "llm", "learned"],
        default="compiler",
        help="flat LTL per non-leaf node: the exact compiler (default), the LLM, or a learned translator "
        "(NL2HLTL2PLAN_TRANSLATOR_BASE_URL); LLM/learned answers are checked against the compiler",
    )
    p.add_argument(
        "--actions",
        choices=["auto", "recipe", "llm"],
        default="auto",
        help="leaf actions: worlds recipes or LLM action completion (auto: recipe offline, llm else)",
    )
    p.add_argument(
        "--lenient",
        action="store_true",
        help="keep objects the scene lacks (reported as issues) instead of failing",
    )
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.add_argument(
        "-o", "--out", type=Path, default=None, help="write pictures and result.json to this folder"
    )
    g = p.add_argument_group("planner")
    g.add_argument(
        "--objective",
        choices=["min", "minmax"],
        default="min",
        help="min: moves + actions over all robots (the paper's cost); minmax: completion time",
    )
    g.add_argument(
        "--mode", choices=["fast", "exact"], default="fast", help="planner mode (see docs/planning.md)"
    )
    g.add_argument("--plan-timeout", type=float, default=300.0, help="planner time limit in seconds")
    g.add_argument("--starts", default=None, help="robot start cells 'r,c;r,c' (default: the world's)")
    add_llm_arguments(p)
    p.set_defaults(func=run)


def _status(enabled: bool) -> tuple[Any, Any]:
    """A rich spinner on stderr while the LLM works, and the callback that updates it."""
    if not enabled:
        return contextlib.nullcontext(), None
    from rich.console import Console

    console = Console(stderr=True)
    status = console.status("asking the LLM ...")
    count = [0]

    def on_request(name: str) -> None:
        count[0] += 1
        status.update(f"asking the LLM: {name} (request {count[0]})")

    return status, on_request


def run(args: argparse.Namespace) -> int:
    from nl2hltl2plan.worlds import load_world

    if args.robots < 1:
        raise PlanningError("--robots must be at least 1")
    settings = settings_from_args(args)
    backend, note = resolve_backend(args.llm, settings)
    if note:
        print(f"note: {note}", file=sys.stderr)
    if args.batch_answers:
        n = load_batch_answers(args.batch_answers, settings)
        print(f"loaded {n} batch answers into the cache", file=sys.stderr)
    world = load_world(args.world)
    batch = BatchCollector() if args.batch_out else None
    status, on_request = _status(backend != "offline" and batch is None)
    try:
        with status, open_client(backend, settings, batch=batch, on_request=on_request) as client:
            result = translate(
                args.instruction,
                world,
                backend,
                client,
                ltl=args.ltl,
                actions=args.actions,
                strict=not args.lenient,
            )
    except PendingAnswer:
        assert batch is not None
        n = batch.write(args.batch_out)
        print(
            f"{n} LLM request(s) pending, written to {args.batch_out} (OpenAI Batch API format). Submit it, "
            f"then run again with --batch-answers OUTPUT.jsonl",
            file=sys.stderr,
        )
        return EXIT_PENDING
    plan_info = _plan(result, world, args)
    payload = _payload(result, args, plan_info)
    if args.out:
        _write_outputs(args.out, result, world, plan_info, payload)
    if args.json:
        print(json.dumps(payload, indent=1, default=str))
    else:
        _print_human(result, plan_info, args)
    return 0


# ----- planner --------------------------------------------------------------------------------------------
def start_cells(world: Any, robots: int, given: str | None = None) -> list[tuple[int, int]]:
    """Robot start cells: `--starts "r,c;r,c"`, else the world's default starts, else free cells spread
    evenly over the grid (deterministic)."""
    from nl2hltl2plan.errors import PlanningError

    if given:
        try:
            cells = [tuple(int(x) for x in part.split(",")) for part in given.split(";") if part.strip()]
        except ValueError:
            raise PlanningError(f"--starts must look like 'r,c;r,c', got {given!r}") from None
        if len(cells) != robots or any(len(c) != 2 for c in cells):
            raise PlanningError(f"--starts gives {len(cells)} cells for {robots} robot(s)")
        return [(c[0], c[1]) for c in cells]
    defaults = list(getattr(world, "default_starts", ()) or ())
    if len(defaults) >= robots:
        return defaults[:robots]
    free = sorted(world.cells)
    step = max(1, len(free) // robots)
    return defaults + [c for c in free[::step] if c not in defaults][: robots - len(defaults)]


def _plan(result: LanguageResult, world: Any, args: argparse.Namespace) -> dict[str, Any]:
    """Run `planning.plan(world, spec, starts, ...)` on the hierarchical spec."""
    try:
        from nl2hltl2plan.planning import plan
    except ImportError:
        return {"available": False, "message": "planner not available"}
    if result.spec is None:
        why = "; ".join(result.warnings) or "no hierarchical spec"
        return {"available": False, "message": f"planner not run: {why}"}
    starts = start_cells(world, args.robots, args.starts)
    planner: Any = plan
    if getattr(world, "kind", "") == "handover":  # four fixed arms passing blocks: cooperative planner
        from nl2hltl2plan.planning.coop import plan_world as planner
    out = planner(
        world, result.spec, starts, objective=args.objective, mode=args.mode, timeout_s=args.plan_timeout
    )
    info: dict[str, Any] = {"available": True, "result": out, "starts": starts, "status": out.status}
    info.update(
        {
            "plan": out.plan,
            "travel_m": out.travel_m,
            "completion_time": out.steps,
            "total_cost": out.total_cost,
            "message": out.reason,
        }
    )
    return info


# ----- output ---------------------------------------------------------------------------------------------
def _dump(x: Any) -> Any:
    if x is None:
        return None
    if hasattr(x, "model_dump"):
        return x.model_dump(mode="json")
    if hasattr(x, "to_dict"):
        return x.to_dict()
    return x


def _payload(result: LanguageResult, args: argparse.Namespace, plan_info: dict[str, Any]) -> dict[str, Any]:
    spec: Any = None
    if result.spec is not None:
        spec = result.spec.to_json_obj() if hasattr(result.spec, "to_json_obj") else str(result.spec)
    plan: Any = None
    if plan_info.get("available"):
        plan = _dump(plan_info.get("plan"))
    return {
        "backend": result.backend,
        "instruction": result.instruction,
        "world": args.world,
        "robots": args.robots,
        "htt": json.loads(result.htt.to_json()),
        "tasks": [t.model_dump() for t in result.tasks],
        "before": [list(p) for p in result.before],
        "task_node": result.task_node,
        "leaf_specs": result.leaf_specs,
        "spec": spec,
        "plan": plan,
        "travel_cost_m": plan_info.get("travel_m"),
        "completion_time": plan_info.get("completion_time"),
        "planner": _planner_summary(plan_info),
        "unparsed": result.unparsed,
        "issues": result.issues,
        "warnings": result.warnings,
        "ltl_checks": result.ltl_checks,
        "llm_calls": result.llm_calls,
    }


def _planner_summary(plan_info: dict[str, Any]) -> dict[str, Any]:
    if not plan_info.get("available"):
        return {"status": "not run", "reason": plan_info.get("message")}
    out = plan_info["result"].to_dict(with_plan=False)
    out["starts"] = [list(c) for c in plan_info.get("starts", [])]
    return out


def _print_human(result: LanguageResult, plan_info: dict[str, Any], args: argparse.Namespace) -> None:
    from nl2hltl2plan.language.render import htt_lines

    print(f"backend: {result.backend}   world: {args.world}   robots: {args.robots}")
    print("\nHierarchical Task Tree")
    for line in htt_lines(result.htt, leaf_specs=result.leaf_specs):
        print("  " + line)
    print("\nBase tasks")
    for line in result.summary_lines():
        print("  " + line)
    if result.before:
        print("  before: " + ", ".join(f"{a} < {b}" for a, b in result.before))
    print("\nHierarchical LTL")
    print("  " + (result.spec_text or "(not built)").replace("\n", "\n  "))
    for w in result.unparsed:
        print(f"not understood: {w}", file=sys.stderr)
    for w in result.issues + result.warnings + result.ltl_checks:
        print(f"warning: {w}", file=sys.stderr)
    print("\nPlan")
    if not plan_info.get("available"):
        print(f"  {plan_info.get('message')}")
        return
    if plan_info.get("status") != "solved":
        print(f"  {plan_info.get('status')}: {plan_info.get('message')}")
        return
    plan = plan_info["plan"]
    for rp in plan.robots:
        moves = sum(1 for st in rp.steps if st.verb == "move")
        acts = [
            f"t{st.t} {st.verb}({','.join(st.objects)})" + (f" [{st.task}]" if st.task else "")
            for st in rp.steps
            if st.verb not in ("move", "wait")
        ]
        print(f"  robot {rp.robot} from {tuple(rp.start)}: {moves} moves; " + ("; ".join(acts) or "idle"))
    print(f"  travel cost: {plan_info.get('travel_m'):.2f} m")
    print(f"  completion time: {plan_info.get('completion_time')} steps")


def _write_outputs(
    folder: Path, result: LanguageResult, world: Any, plan_info: dict[str, Any], payload: dict[str, Any]
) -> None:
    from nl2hltl2plan.language.render import draw_htt

    folder.mkdir(parents=True, exist_ok=True)
    draw_htt(result.htt, folder / "htt.png", title=result.instruction)
    (folder / "result.json").write_text(json.dumps(payload, indent=1, default=str))
    try:
        from nl2hltl2plan.worlds import pictures

        pictures.draw_world(world, folder / "world.png", title=getattr(world, "name", None))
        plan = plan_info.get("plan")
        if plan is not None:
            from nl2hltl2plan.worlds import execute

            pictures.draw_execution(execute(world, plan), folder / "plan.png")
    except (ImportError, AttributeError) as exc:  # pictures of worlds are optional
        print(f"warning: world pictures not written ({exc})", file=sys.stderr)


__all__ = ["register", "run", "LLMError"]
