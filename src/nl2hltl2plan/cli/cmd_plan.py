"""`nl2hltl2plan plan "INSTRUCTION" --world demo|FloorPlanN --robots N [--llm offline|local|openai]`

Instruction -> HTT -> hierarchical LTL -> multi-robot plan, executed and checked (`pipeline.run`).
Prints the HTT, the base tasks, the hierarchical LTL and the plan with its travel cost and completion
time; `--json` prints one object (docs/plan_schema.md); `-o DIR` writes result.json, spec.json,
spec.hoa and the pictures htt, world, plan (the map with numbered actions) and gantt (who does what
when), each as .png and .svg.
Exit status: 0 a checked plan, 1 no plan (infeasible or timeout, with the reason), 2 bad input
(a constraint that forbids what a task requires: "the instruction contradicts itself: ..."),
3 LLM requests pending (batch mode), 4 an internal error (a bug). Without `--llm`, an LLM configured
by NL2HLTL2PLAN_LLM_* is used, else the offline backend (said on stderr).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

from nl2hltl2plan.cli.commands import COMMANDS
from nl2hltl2plan.cli.options import (
    add_backend_argument,
    add_llm_arguments,
    add_planner_arguments,
    llm_settings,
    planner_options,
)
from nl2hltl2plan.domain.plurals import PLURALS

EXIT_OK, EXIT_NO_PLAN, EXIT_PENDING = 0, 1, 3


def register(sub: Any) -> None:
    p = sub.add_parser(
        "plan",
        help=COMMANDS["plan"],
        description=__doc__.split("\n\n")[1],
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("instruction", help="the natural-language instruction (quote it)")
    p.add_argument(
        "--world", default="demo", help="demo (built in) or an ALFRED floor plan FloorPlanN (default: demo)"
    )
    p.add_argument(
        "--trials",
        nargs="+",
        metavar="TRIAL",
        help="ALFRED trial ids of the floor plan whose movable objects the world holds (default: its first)",
    )
    p.add_argument(
        "--robots",
        default="1",
        help="the team: a number of robots that can do everything, robot profile names from "
        "smartllm/robots.json ('robot1,robot5'), or a JSON team file (default 1)",
    )
    p.add_argument("--starts", default=None, help="robot start cells 'r,c;r,c' (default: the world's)")
    add_backend_argument(p, help_extra=" (default: openai when configured, else offline)")
    p.add_argument(
        "--ltl",
        choices=["compiler", "llm", "learned"],
        default="compiler",
        help="flat LTL per non-leaf node: the exact compiler, the LLM, or a learned translator "
        "(NL2HLTL2PLAN_TRANSLATOR_BASE_URL); LLM/learned answers are checked against the "
        "compiler (default: compiler)",
    )
    p.add_argument(
        "--actions",
        choices=["auto", "recipe", "llm"],
        default="auto",
        help="leaf actions: worlds recipes or LLM action completion (default auto: recipes "
        "offline, LLM otherwise)",
    )
    p.add_argument(
        "--lenient",
        action="store_true",
        help="keep objects the scene lacks (reported as issues) instead of failing",
    )
    p.add_argument(
        "--partial",
        action="store_true",
        help="plan what was understood when part of the instruction was not (the result says partial; "
        "default: refuse, exit 2)",
    )
    p.add_argument(
        "--plurals",
        choices=PLURALS,
        default="ask",
        help="a plural with no number of more things than the task takes ('the forks' of 3): refuse "
        "naming it (ask, default) or read the world's convention (two: ALFRED's pick-two, said as an "
        "assumption)",
    )
    p.add_argument(
        "--ask",
        action="store_true",
        help="ask on the terminal which scene type an ambiguous word means ('the table': dining "
        "or side table?) instead of taking the top-ranked one (backend learned)",
    )
    p.add_argument("--json", action="store_true", help="print one JSON object (docs/plan_schema.md)")
    p.add_argument(
        "-o",
        "--out",
        type=Path,
        default=None,
        help="write result.json and pictures to this folder (default: none)",
    )
    add_planner_arguments(p)
    add_llm_arguments(p, batch=True)
    p.set_defaults(func=run)


Callback = Callable[[Any], None]


def _spinner(
    enabled: bool,
) -> tuple[contextlib.AbstractContextManager[Any], Callback | None, Callback | None]:
    """A rich spinner on stderr that says the stage the run is in (the pipeline's progress hook, the
    same one the web page streams) and each LLM request; the two callbacks that update it."""
    if not enabled:
        return contextlib.nullcontext(), None, None
    from rich.console import Console

    status = Console(stderr=True).status("starting ...")
    count = [0]

    def on_request(name: str) -> None:
        count[0] += 1
        status.update(f"asking the LLM: {name} (request {count[0]})")

    def on_progress(p: Any) -> None:
        status.update(f"{p.stage}: {p.detail}")

    return status, on_request, on_progress


def run(args: argparse.Namespace) -> int:
    from nl2hltl2plan.io import check_new_file, ensure_writable_dir
    from nl2hltl2plan.language.backends import load_batch_answers, open_client, resolve_backend
    from nl2hltl2plan.language.llm.batch import BatchCollector, PendingAnswer
    from nl2hltl2plan.pipeline import PipelineOptions
    from nl2hltl2plan.pipeline import run as run_pipeline
    from nl2hltl2plan.worlds import load_world
    from nl2hltl2plan.worlds.starts import parse_cells
    from nl2hltl2plan.worlds.team import parse_team

    settings = llm_settings(args)
    backend, note = resolve_backend(args.llm, settings)
    options = PipelineOptions(
        backend=backend,
        ltl=args.ltl,
        actions=args.actions,
        strict=not args.lenient,
        partial=args.partial,
        plurals=args.plurals,
        starts=parse_cells(args.starts) if args.starts else None,
        **planner_options(args),
    )
    if args.out is not None:
        ensure_writable_dir(args.out)
    if args.batch_out:
        check_new_file(args.batch_out, "batch file")
    if note:
        print(f"note: {note}", file=sys.stderr)
    if args.batch_answers:
        n, errors = load_batch_answers(args.batch_answers, settings)
        for e in errors[:5]:
            print(f"warning: batch answer {e}", file=sys.stderr)
        print(f"loaded {n} batch answers into the cache", file=sys.stderr)
    team = parse_team(args.robots)  # before the world: a bad team is refused without loading anything
    world = load_world(args.world, args.trials)
    batch = BatchCollector() if args.batch_out else None
    # not while --ask prompts on the terminal, nor where stderr is not one
    spinner, on_request, on_progress = _spinner(
        batch is None and not args.json and not args.ask and sys.stderr.isatty()
    )
    try:
        with spinner, open_client(backend, settings, batch=batch, on_request=on_request) as client:
            ask = _ask_on_terminal if args.ask else None
            instruction = args.instruction
            outcome = run_pipeline(instruction, world, team, options, client, ask=ask, progress=on_progress)
    except PendingAnswer:
        assert batch is not None
        n = batch.write(args.batch_out)
        print(
            f"{n} LLM request(s) pending, written to {args.batch_out} (OpenAI Batch API format). Submit "
            "it, then run again with --batch-answers OUTPUT.jsonl",
            file=sys.stderr,
        )
        return EXIT_PENDING
    payload = outcome.to_json()
    if args.out is not None:
        _write_outputs(args.out, outcome, payload)
    if args.json:
        print(json.dumps(payload, indent=1, default=str))
    else:
        _print_human(outcome)
    if outcome.language.partial:
        print("partial: only part of the instruction is planned (--partial)", file=sys.stderr)
    if not outcome.ok:
        print(f"error: no plan: {outcome.status.value}: {outcome.result.reason}", file=sys.stderr)
        return EXIT_NO_PLAN
    return EXIT_OK


def _ask_on_terminal(ambiguities: list[Any]) -> dict[str, str]:
    """Ask which type each ambiguous word means (one number per word on standard input)."""
    from nl2hltl2plan.errors import HTTError

    choices: dict[str, str] = {}
    for a in ambiguities:
        print(f"{a.word!r} ({a.role} of task {a.task}) could mean:", file=sys.stderr)
        confidence = a.confidence or [0.0] * len(a.candidates)
        for k, (cand, conf) in enumerate(zip(a.candidates, confidence, strict=True), 1):
            print(f"  {k}. {cand} ({conf:.0%})", file=sys.stderr)
        print("choose a number [1]: ", end="", file=sys.stderr, flush=True)
        answer = sys.stdin.readline()
        if not answer:
            raise HTTError("--ask needs an answer on standard input (got end of input)")
        pick = answer.strip() or "1"
        if not pick.isdigit() or not 1 <= int(pick) <= len(a.candidates):
            raise HTTError(f"--ask: {pick!r} is not one of 1..{len(a.candidates)}")
        choices[f"{a.task}.{a.role}"] = a.candidates[int(pick) - 1]
    return choices


def _print_human(outcome: Any) -> None:
    from nl2hltl2plan.domain.task_kinds import SLOTS
    from nl2hltl2plan.present.htt_pictures import htt_lines

    lang, r = outcome.language, outcome.result
    print(f"backend: {lang.backend}   world: {outcome.world.name}   team: {outcome.team}")
    print("\nHierarchical Task Tree")
    for line in htt_lines(lang.htt, leaf_specs=lang.leaf_specs):
        print("  " + line)
    print("\nBase tasks")
    for line in lang.summary_lines():
        print("  " + line)
    if lang.before:
        print("  before: " + ", ".join(f"{a} < {b}" for a, b in lang.before))
    print("\nHierarchical LTL")
    print("  " + (lang.spec_text or "(not built)").replace("\n", "\n  "))
    for w in lang.unparsed:
        print(f"not understood: {w}", file=sys.stderr)
    for w in lang.assumptions:
        print(f"note: assumption: {w}", file=sys.stderr)  # a reading the text left open, not an error
    for w in lang.issues + lang.warnings + lang.ltl_checks:
        print(f"warning: {w}", file=sys.stderr)
    kept = {(t.id, role): getattr(t, role) or [] for t in lang.tasks for role in SLOTS}
    for a in lang.ambiguities:
        chosen = kept.get((a.task, a.role), [])
        what = f"using {chosen[0]}" if len(chosen) == 1 else "any of them is accepted (--ask to choose)"
        print(
            f"note: {a.word!r} ({a.role} of {a.task}) could be {' / '.join(a.candidates)}; {what}",
            file=sys.stderr,
        )
    print("\nPlan")
    if r.plan is None:
        print(f"  {r.status}: {r.reason}")
        return
    for rp in r.plan.robots:
        moves = sum(1 for st in rp.steps if st.verb == "move")
        acts = [
            f"t{st.t} {st.verb}({','.join(st.objects)})" + (f" [{st.task}]" if st.task else "")
            for st in rp.steps
            if st.verb not in ("move", "wait")
        ]
        print(f"  robot {rp.robot} from {tuple(rp.start)}: {moves} moves; " + ("; ".join(acts) or "idle"))
    print(f"  travel cost: {r.travel_m:.2f} m   completion time: {r.steps} steps")
    print(f"  {r.optimality} ({r.model})")
    note = outcome.idle_note()
    if note:
        print(f"  {note}")
    for choice in outcome.place_choices():  # "the fridge or the microwave": which, and that either does
        print(f"  {choice.describe()}")


def _write_outputs(folder: Path, outcome: Any, payload: dict[str, Any]) -> None:
    """result.json, the spec (JSON and HOA) and the pictures (PNG and SVG), all drawn from the outcome
    (nothing is re-run): the same files the web page offers for download (`present.outputs.write_outputs`)."""
    from nl2hltl2plan.present.outputs import write_outputs

    for warning in write_outputs(folder, outcome, payload):
        print(f"warning: {warning}", file=sys.stderr)
