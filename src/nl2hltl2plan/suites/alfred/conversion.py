"""Measure conversion quality on the benchmark: generated base tasks vs the ground truth.

    python -m nl2hltl2plan.suites.alfred.conversion --backend offline
    python -m nl2hltl2plan.suites.alfred.conversion --backend local --sample 20 --seed 0

For each instruction of benchmark/alfred_test50_gt.jsonl the language stage produces base tasks and
`before` pairs for the instruction's scene; `scoring.match` compares them with the ground truth. The
table gives, per number of base tasks, the share with matching tasks and the share with matching tasks
and order (strict: generated types within the accepted types), on all instructions and on the
feasible-and-unambiguous ones.
"""

from __future__ import annotations

import argparse
import contextlib
import random
import sys
import time
from collections import Counter
from collections.abc import Callable, Iterator
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from nl2hltl2plan.domain.plurals import Plurals
from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.io import write_json
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grounding import scene_types
from nl2hltl2plan.language.referents import check_referents
from nl2hltl2plan.language.scoring import match
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.worlds.world import ALFRED_PICK_TWO, World

if TYPE_CHECKING:
    from nl2hltl2plan.language.learned.inference import Policy
    from nl2hltl2plan.language.learned.slot_model import SlotModel

BENCHMARK = ("benchmark", "alfred_test50_gt.jsonl")
Generator = Callable[[str, set[str], str], tuple[list[BaseTaskSpec], list[tuple[str, str]], list[str]]]


def load_benchmark() -> list[dict[str, Any]]:
    """The benchmark's instances as plain dicts (the ground truth's one loader,
    `suites.alfred.ground_truth`)."""
    from nl2hltl2plan.suites.alfred.ground_truth import load_gt

    return [g.model_dump(mode="json") for g in load_gt()]


@contextlib.contextmanager
def llm_generator(backend: str, argv: list[str]) -> Iterator[Generator]:
    """A generator function (instruction, types, scene) -> (tasks, before, problems) over an LLM backend;
    `argv`: the LLM options of `nl2hltl2plan plan` (--base-url, --model, --cache, --batch-out ...)."""
    from nl2hltl2plan.language.backends import load_batch_answers, open_client
    from nl2hltl2plan.language.llm.batch import BatchCollector, PendingAnswer
    from nl2hltl2plan.language.llm.llm_options import add_llm_arguments, llm_settings
    from nl2hltl2plan.language.translate import translate

    ap = argparse.ArgumentParser()
    add_llm_arguments(ap, batch=True)
    args = ap.parse_args(argv)
    settings = llm_settings(args)
    batch = BatchCollector() if args.batch_out else None
    if args.batch_answers:
        load_batch_answers(args.batch_answers, settings)
    with open_client(backend, settings, batch=batch) as client:

        def generate(
            instruction: str, types: set[str], scene: str
        ) -> tuple[list[BaseTaskSpec], list[tuple[str, str]], list[str]]:
            try:
                r = translate(
                    instruction,
                    _Scene(scene, types),
                    backend,
                    client,
                    strict=False,
                    build=False,
                    actions="none",
                )
            except PendingAnswer:
                return [], [], ["pending (batch mode)"]
            return r.tasks, r.before, r.unparsed + r.issues

        yield generate
    if batch is not None and len(batch):
        n = batch.write(args.batch_out)
        print(f"{n} requests pending, written to {args.batch_out}", file=sys.stderr)


class _Scene:
    """A scene known only by its name and object types (enough for the language stage)."""

    def __init__(self, name: str, types: set[str]) -> None:
        self.name, self._types = name, types

    def object_types(self) -> set[str]:
        return self._types


def offline_generator(
    instruction: str, types: set[str], scene: str
) -> tuple[list[BaseTaskSpec], list[tuple[str, str]], list[str]]:
    """The default `offline` backend: the grammar with the learned slot model (`language.learned`)."""
    from nl2hltl2plan.language.learned import parse_instruction

    r = parse_instruction(instruction, types, scene, strict=False)
    return r.tasks, r.before, r.unparsed


def grammar_generator(
    instruction: str, types: set[str], scene: str
) -> tuple[list[BaseTaskSpec], list[tuple[str, str]], list[str]]:
    """The `grammar` backend: the offline grammar parser alone."""
    from nl2hltl2plan.language.grammar import parse_instruction

    r = parse_instruction(instruction, types, scene, strict=False)
    return r.tasks, r.before, r.unparsed


def learned_generator(policy: Policy | None = None, model: SlotModel | None = None) -> Generator:
    """The default backend as the benchmarks run it: an ambiguous word takes its top-ranked type."""

    from nl2hltl2plan.language.learned.inference import parse_instruction
    from nl2hltl2plan.language.translate import apply_choices, top_candidates

    def generate(
        instruction: str, types: set[str], scene: str
    ) -> tuple[list[BaseTaskSpec], list[tuple[str, str]], list[str]]:
        r = parse_instruction(instruction, types, scene, strict=False, policy=policy, model=model)
        r = apply_choices(r, top_candidates(r.ambiguities))
        return r.tasks, r.before, r.unparsed

    return generate


def scenario_world(row: dict[str, Any]) -> World:
    """A row's world as the benchmark builds a scenario's (`worlds.build_benchmark_world`): its floor plan
    with the movable objects of the ALFRED trials it was composed from (`source_trials`), so that "two
    pillows" finds the pillows of the trials that had them; a row that names none (a user's instruction)
    gets the floor plan's first trial, as `plan --world FloorPlanN`."""
    return _world(row["scene"], tuple(row.get("source_trials") or ()))


@lru_cache(maxsize=64)  # a composed set's rows share few trial sets, a user set's rows few floor plans
def _world(scene: str, trials: tuple[str, ...]) -> World:
    from nl2hltl2plan.worlds import load_world

    return load_world(scene, list(trials) or None)


def scenario_counts(row: dict[str, Any]) -> Counter[str]:
    """How many objects of each type `scenario_world(row)` holds (`floor_plans.instance_counts`: the
    same counts without building the world)."""
    from nl2hltl2plan.worlds.floor_plans import instance_counts

    return instance_counts(row["scene"], row.get("source_trials") or None)


def evaluate(
    rows: list[dict[str, Any]], generate: Generator, progress: bool = False, plurals: Plurals = "two"
) -> list[dict[str, Any]]:
    """One record per instruction: ids, n_base, flags, match results, and the generated tasks. Check 1
    and the referents' refusals judge a reading with the counts of the row's world (`scenario_counts`)
    and, under `plurals` (`bench alfred`'s default), ALFRED's pick-two convention."""
    out = []
    for k, row in enumerate(rows):
        t0 = time.monotonic()
        err = ""
        try:
            tasks, before, unparsed = generate(row["instruction"], scene_types(row["scene"]), row["scene"])
            # check 1 (word accounting) and the referents' refusals (a thing moved twice, "the dishes"),
            # as `plan` applies them: a partial or refused conversion is a failure
            counts, scene, text = scenario_counts(row), row["scene"], row["instruction"]
            unparsed = unparsed + [str(u) for u in account(text, tasks, before, counts, scene)]
            check_referents(text, tasks, before, counts, scene, ALFRED_PICK_TWO, plurals)
        except Nl2Hltl2PlanError as exc:
            tasks, before, unparsed, err = [], [], [], str(exc)
        refused = bool(err or unparsed)
        strict = match(tasks, before, row["tasks"], row["before"], strict=True)
        lenient = match(tasks, before, row["tasks"], row["before"], strict=False)
        out.append(
            {
                "id": row["id"],
                "n_base": row["n_base"],
                "clean": bool(row["feasible"] and not row["ambiguous"]),
                "tasks_ok": strict.tasks_ok and not refused,
                "ok": strict.order_ok and not refused,
                "lenient_ok": lenient.order_ok and not refused,
                "refused": refused,
                "reasons": strict.reasons,
                "error": err,
                "unparsed": unparsed,
                "tasks": [t.model_dump() for t in tasks],
                "before": before,
                "seconds": round(time.monotonic() - t0, 2),
            }
        )
        if progress:
            print(f"\r{k + 1}/{len(rows)}", end="", file=sys.stderr, flush=True)
    if progress:
        print(file=sys.stderr)
    return out


def table(records: list[dict[str, Any]]) -> str:
    """Markdown table: per n_base, tasks-match and full-match shares with counts (all /
    feasible-and-unambiguous)."""
    lines = [
        "| base tasks | n | refused or partial | tasks match | tasks+order match | lenient types | clean n "
        "| clean refused or partial | clean tasks+order |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    groups = sorted({r["n_base"] for r in records})
    for g in [*groups, "all"]:
        rs = [r for r in records if g == "all" or r["n_base"] == g]
        cl = [r for r in rs if r["clean"]]

        def pct(xs: list[dict[str, Any]], key: str) -> str:
            k = sum(x[key] for x in xs)
            return f"{100 * k / len(xs):.0f}% ({k})" if xs else "-"

        lines.append(
            f"| {g} | {len(rs)} | {pct(rs, 'refused')} | {pct(rs, 'tasks_ok')} | {pct(rs, 'ok')} | "
            f"{pct(rs, 'lenient_ok')} | {len(cl)} | {pct(cl, 'refused')} | {pct(cl, 'ok')} |"
        )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(
        prog="python -m nl2hltl2plan.suites.alfred.conversion", description=__doc__.split("\n")[0]
    )
    ap.add_argument("--backend", default="offline", choices=["offline", "grammar", "local", "openai"])
    ap.add_argument("--sample", type=int, default=0, help="evaluate a random sample of this many per n_base")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--n-base", type=int, nargs="*", default=None, help="only these numbers of base tasks")
    ap.add_argument("--json", type=Path, default=None, help="write the per-instruction records here")
    ap.add_argument("--show-failures", action="store_true")
    args, rest = ap.parse_known_args(argv)
    rows = load_benchmark()
    if args.n_base:
        rows = [r for r in rows if r["n_base"] in args.n_base]
    if args.sample:
        rng = random.Random(args.seed)
        picked = []
        for g in sorted({r["n_base"] for r in rows}):
            grp = [r for r in rows if r["n_base"] == g]
            picked += rng.sample(grp, min(args.sample, len(grp)))
        rows = picked
    parsers: dict[str, Generator] = {"offline": offline_generator, "grammar": grammar_generator}
    if args.backend in parsers:  # the backends that need no LLM
        records = evaluate(rows, parsers[args.backend], progress=sys.stderr.isatty())
    else:
        with llm_generator(args.backend, rest) as generate:
            records = evaluate(rows, generate, progress=sys.stderr.isatty())
    print(f"backend {args.backend}, {len(records)} instructions")
    print(table(records))
    if args.show_failures:
        for r in records:
            if not r["ok"]:
                print(f"- {r['id']}: {'; '.join(r['reasons'])} {r['error']} {r['unparsed'] or ''}")
    if args.json:
        write_json(args.json, records, "records file")
    return 0


if __name__ == "__main__":
    sys.exit(main())
