"""Why the language stage fails on the validation sets: every failure put in one class.

    python scripts/language_failures.py [--sets faithful_unseen,heldout_unseen,...] [--n 400]
        [--save-rows DIR] [--rows DIR] [--show CLASS] [--long] [--outcomes FILE] [--reader grammar]
        [--plurals ask|two]

Sets with ground truth (never test50, never the excluded trials): `faithful_seen`, `faithful_unseen`,
`trainstyle_unseen`, `heldout_unseen`, the reference-style `refsdev_seen/unseen`, `refsheld_seen/unseen`
and `refsnew_seen/unseen` (`suites.alfred.structure_validation.rows_of_set`; `NAME:SEED` composes one with
another seed), `plain` (issue 23's user-style set), and any style set by its name (`users`, `users_heldout`,
`paper_h159held`: tests/language/data/styles/NAME.txt; a line's `trials:` column builds its world, as a
benchmark row's `source_trials`).
A composed set depends on the lexicon (its text-faithful labels), so `--save-rows DIR` keeps the rows and
`--rows DIR` scores another version of the code on exactly those rows (before/after on the same
instructions); `--outcomes FILE` writes each row's class, why and the text as the reader rewrote it (JSON
lines) to compare two versions row by row.

What is measured (`--reader`, `READERS`): by default the shipped reading, as `plan --world SCENE` reads
(`household_reading`: `translate` in the row's floor plan, the household reader's rewriting, check 1 with
the floor plan's instance counts, the referents' refusals, an ambiguous word's top candidate);
`--reader grammar` is the earlier measure (the learned parse of the text as written, then check 1), kept
so that earlier numbers can be compared. Classes of a failure:
- `accounting false refusal`: the reading matches the ground truth, only check 1 names a word;
- `unread clause, reading right`: the reading matches, but the grammar left a clause unread;
- `refused, reading wrong`: words are unread and the reading is wrong too, or no task is read at all (a
  right refusal);
- `structure: task count` / `structure: order`: read completely, the number of tasks or the order is wrong;
- `grounding: type`: kinds and counts right, a type is outside the accepted ones (lenient match passes);
- `slot: kind/count/sliced/type`: any other wrong task;
- `world: the floor plan lacks it`: refused because the row's world lacks an object the row names, or
  holds fewer than it asks (a generator row's world holds the objects of the trials it composes, so this
  is left to rows whose trials lack them too, and to user rows);
- `error`: refused with another error (a contradictory order, one thing moved twice).
A complete reading that is wrong (the `structure`, `grounding` and `slot` classes) exits 0 in `plan`.

`--long`: the 177 long instructions of alfred_multiagent (no ground truth): the language stage in each
floor plan's world, and why an instruction is not accepted (the world lacks an object, a task the world
cannot do, unread words by category, an unread clause).
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path
from typing import Any, get_args

from nl2hltl2plan.domain.plurals import Plurals
from nl2hltl2plan.errors import Nl2Hltl2PlanError, WorldError
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grounding import scene_types
from nl2hltl2plan.language.learned.inference import parse_instruction
from nl2hltl2plan.language.referents import check_referents
from nl2hltl2plan.language.result import LanguageResult
from nl2hltl2plan.language.scoring import match
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.translate import apply_choices, scene_instances, top_candidates, translate
from nl2hltl2plan.suites.alfred.conversion import scenario_world
from nl2hltl2plan.suites.alfred.structure_validation import rows_of_set
from nl2hltl2plan.worlds.world import World

sys.path.insert(0, str(Path(__file__).resolve().parent))
from trust_sets import TrialsError, parse_line, world_of  # noqa: E402

STYLES = Path(__file__).resolve().parent.parent / "tests" / "language" / "data" / "styles"
FINDING = re.compile(r"^'(.+?)' \((\w+)\): (.*)$")  # one finding of check 1 (`accounting.Unread`)
CLASSES = (
    "ok",
    "accounting false refusal",
    "unread clause, reading right",
    "refused, reading wrong",
    "structure: task count",
    "structure: order",
    "grounding: type",
    "slot: kind/count/sliced/type",
    "world: the floor plan lacks it",
    "error",
)
WORLD = CLASSES[-2]
NOTHING_READ = "the offline parser understood no task in "  # `translate._parse`'s refusal
# a refusal of the floor plan's: an object it lacks ("no Statue in FloorPlan17"), too few of one
# ("'two pillows': FloorPlan301 holds only 1 pillow")
LACKING = re.compile(r"^no \w+(?: \(for .*?\))? in FloorPlan|: FloorPlan\d+ holds only ")


def rows(name: str, n: int) -> list[dict[str, Any]]:
    """A set's rows: a style set's (tests/language/data/styles/NAME.txt: `users*`, `paper_*`, ...; a line's
    `trials:` column is its `source_trials`, whose objects `scenario_world` builds) or a composed set's."""
    if (STYLES / f"{name}.txt").exists():
        lines = [
            ln for ln in (STYLES / f"{name}.txt").read_text().splitlines() if ln.strip() and ln[0] != "#"
        ]
        return [parse_line(ln, name, k) for k, ln in enumerate(lines, 1)]
    return rows_of_set(name, n)



def classify(
    row: dict[str, Any], reader: str = "household", plurals: Plurals = "ask"
) -> tuple[str, str, str]:
    """(class, why, the text as the reader rewrote it) of one instruction with ground truth, as `reader`
    reads it (`READERS`) under the `plurals` setting; the classes judge the reading of the rewritten text,
    which check 1 reads."""
    try:
        tasks, before, unread, read = READERS[reader](row, plurals)
    except Nl2Hltl2PlanError as exc:
        if _lacking(exc):
            return WORLD, str(exc), ""
        # no task read at all: words are unread and there is no reading (the grammar reader's empty parse)
        return ("refused, reading wrong" if NOTHING_READ in str(exc) else "error"), str(exc), ""
    cls, why = _judged(row, tasks, before, unread)
    return cls, why, read


def _judged(
    row: dict[str, Any], tasks: list[BaseTaskSpec], before: list[tuple[str, str]], unread: list[str]
) -> tuple[str, str]:
    """(class, why) of a reading that was not refused outright."""
    verdict = match(tasks, before, row["tasks"], row["before"], strict=True)
    if verdict.order_ok:
        if not unread:
            return "ok", ""
        only_check1 = all(FINDING.match(u) for u in unread)
        return ("accounting false refusal" if only_check1 else "unread clause, reading right"), "; ".join(
            unread
        )
    why = "; ".join(verdict.reasons)
    if unread:
        return "refused, reading wrong", "; ".join(unread) + " || " + why
    if len(tasks) != len(row["tasks"]):
        return "structure: task count", why
    if verdict.tasks_ok:
        return "structure: order", why
    if match(tasks, before, row["tasks"], row["before"], strict=False).order_ok:
        return "grounding: type", why
    return "slot: kind/count/sliced/type", why


# tasks, order, unread (each with its why), the text as the reader rewrote it
Reading = tuple[list[BaseTaskSpec], list[tuple[str, str]], list[str], str]


def household_reading(row: dict[str, Any], plurals: Plurals = "ask") -> Reading:
    """The shipped reading, as `plan --world SCENE` reads (`--long` alike): `translate` in the row's world
    (`conversion.scenario_world`: a composed row's floor plan holds the objects of the ALFRED trials it
    was composed from, as a benchmark scenario's; a user's row, the floor plan's first trial), the
    household reader's rewriting included (`world_readers`: greetings, colon lists, topic
    questions, descriptive names, self-corrections, "respectively", step numbers, negations), check 1
    with the floor plan's instance counts and the referents' refusals; an ambiguous word takes its top
    candidate. The reader's rewritten text is what check 1 reads, so the classes below hold for it."""
    r = shipped(row["instruction"], scenario_world(row), plurals)
    return r.tasks, r.before, list(r.unparsed), r.instruction


def shipped(text: str, world: World, plurals: Plurals = "ask") -> LanguageResult:
    """The language stage as `plan --world [--plurals]` runs it, up to the base tasks (no leaf actions, no
    spec)."""
    return translate(text, world, "offline", ask=top_candidates, build=False, actions="none", plurals=plurals)


def grammar_reading(row: dict[str, Any], plurals: Plurals = "ask") -> Reading:
    """The earlier measure (`--reader grammar`, kept to compare with its numbers): the learned parse of the
    text as written (`learned.inference.parse_instruction`, no household reader), the top candidate of
    each ambiguous word, then check 1 and the referents' refusals. The rows of the committed user-style
    sets (written for `plan --world SCENE`) get that world's instance counts; a generator row, which
    composes ALFRED trials whose own objects the bare floor plan may lack ("two pillows" where it has one),
    is judged without counts."""
    p = parse_instruction(row["instruction"], scene_types(row["scene"]), row["scene"], strict=False)
    apply_choices(p, top_candidates(p.ambiguities))  # its result unused, as the earlier measure had it
    trust = str(row["id"]).startswith("trust.")
    world = world_of(row["scene"], row.get("source_trials", ())) if trust else None
    instances = scene_instances(world) if world is not None else None
    scene = world.name if world is not None else "the scene"
    found = [str(u) for u in account(row["instruction"], p.tasks, p.before, instances, scene)]
    convention = world.plurals if world is not None else None
    # as `translate._finish`
    check_referents(row["instruction"], p.tasks, p.before, instances, scene, convention, plurals)
    return p.tasks, p.before, list(p.unparsed) + found, row["instruction"]


READERS = {"household": household_reading, "grammar": grammar_reading}


def _lacking(exc: Exception) -> bool:
    """Is a refusal the floor plan's (an object it lacks, fewer instances than asked) rather than the
    reading's?"""
    return isinstance(exc, WorldError) or bool(LACKING.search(str(exc)))


def report_set(
    name: str,
    data: list[dict[str, Any]],
    show: str | None,
    outcomes: list[dict[str, Any]] | None = None,
    reader: str = "household",
    plurals: Plurals = "ask",
) -> None:
    per: dict[Any, Counter[str]] = defaultdict(Counter)
    for k, row in enumerate(data):
        cls, why, read = classify(row, reader, plurals)
        if outcomes is not None:
            said = {"instruction": row["instruction"], "read": read}
            outcomes.append({"set": name, "row": k, **said, "class": cls, "why": why})
        for key in (row["n_base"], "all"):
            per[key][cls] += 1
        if show and cls == show:
            print(f"  {row['instruction']!r}: {why[:300]}", file=sys.stderr)
    keys = sorted(k for k in per if k != "all") + ["all"]
    setting = ", plurals two" if plurals == "two" else ""
    print(f"\n{name} ({len(data)} instructions, {reader} reader{setting}): outcome per number of base tasks")
    print("| class | " + " | ".join(str(k) for k in keys) + " |")
    print("| --- |" + " --- |" * len(keys))
    for cls in CLASSES:
        if per["all"][cls]:
            print(f"| {cls} | " + " | ".join(str(per[k][cls]) for k in keys) + " |")
    print("| converted | " + " | ".join(f"{per[k]['ok']}/{sum(per[k].values())}" for k in keys) + " |")
    if per["all"][WORLD]:  # the same, leaving out the rows the built floor plan cannot hold
        held = [f"{per[k]['ok']}/{sum(per[k].values()) - per[k][WORLD]}" for k in keys]
        print("| converted, the floor plan holding what the row names | " + " | ".join(held) + " |")


def long_reason(text: str, world: World) -> list[str]:
    """Why the language stage does not accept one long instruction (empty: accepted)."""
    try:
        r = shipped(text, world)
    except Nl2Hltl2PlanError as exc:
        msg = str(exc)
        if re.match(r"no \w+(?: \(for .*?\))? in FloorPlan", msg):
            return ["world: names an object the world lacks"]
        if "cannot be done" in msg:
            return ["world: a task the world cannot do"]
        if "contradictory" in msg:
            return ["a contradictory order"]
        return ["refused: " + msg[:40]]
    out = []
    for u in r.unparsed:
        m = FINDING.match(u)
        out.append(f"check 1: {m.group(2)} word" if m else "grammar: an unread clause")
    return sorted(set(out))


def report_long() -> None:
    from bench_multiagent_long import instructions  # imports the planner: only here

    first: Counter[str] = Counter()
    anywhere: Counter[str] = Counter()
    accepted = total = 0
    for n_base in range(5, 10):
        for key, text, _ in instructions(n_base):
            scene = key.split(".")[0]
            reasons = long_reason(text, world_of(scene))
            total += 1
            accepted += not reasons
            if reasons:
                first[
                    reasons[0] if reasons[0].startswith(("world", "a contra", "refused")) else "unread words"
                ] += 1
            anywhere.update(reasons)
    print(f"\nalfred_multiagent long instructions: language stage accepts {accepted} of {total}")
    print("| not accepted because | instructions |\n| --- | --- |")
    for k, v in first.most_common():
        print(f"| {k} | {v} |")
    print("\n| unread words, by kind (an instruction may have several) | instructions |\n| --- | --- |")
    for k, v in anywhere.most_common():
        if k.startswith(("check 1", "grammar")):
            print(f"| {k} | {v} |")


def main() -> int:
    ap = argparse.ArgumentParser(prog="python scripts/language_failures.py")
    ap.add_argument("--sets", default="plain,users,faithful_unseen,trainstyle_unseen,heldout_unseen")
    ap.add_argument("--n", type=int, default=400)
    ap.add_argument("--save-rows", type=Path, default=None, help="write each set's rows to DIR/<set>.json")
    ap.add_argument("--rows", type=Path, default=None, help="read the rows saved in DIR instead")
    ap.add_argument("--show", default=None, help="print the instructions of this class on stderr")
    ap.add_argument("--long", action="store_true", help="also the alfred_multiagent long instructions")
    ap.add_argument(
        "--outcomes", type=Path, default=None, help="write every row's class and why to FILE (JSON lines)"
    )
    ap.add_argument(
        "--reader",
        choices=sorted(READERS),
        default="household",
        help="household: the shipped reading (translate); grammar: the earlier measure, to compare",
    )
    ap.add_argument(
        "--plurals",
        choices=get_args(Plurals),
        default="ask",
        help="a bare plural of more than the task takes: refused (ask, `plan`'s default) or the world's "
        "convention (two: ALFRED's pick-two, `bench alfred`'s protocol)",
    )
    args = ap.parse_args()
    outcomes: list[dict[str, Any]] | None = [] if args.outcomes else None
    for name in [s for s in args.sets.split(",") if s]:
        saved = args.rows / f"{name}.json" if args.rows else None
        try:
            data = json.loads(saved.read_text()) if saved and saved.exists() else rows(name, args.n)
        except TrialsError as exc:  # a style line's `trials:` id it may not use
            print(f"error: {exc}", file=sys.stderr)
            return 2
        if args.save_rows:
            args.save_rows.mkdir(parents=True, exist_ok=True)
            (args.save_rows / f"{name}.json").write_text(json.dumps(data))
        report_set(name, data, args.show, outcomes, args.reader, args.plurals)
    if args.outcomes and outcomes is not None:
        args.outcomes.write_text("".join(json.dumps(o) + "\n" for o in outcomes))
    if args.long:
        report_long()
    return 0


if __name__ == "__main__":
    sys.exit(main())
