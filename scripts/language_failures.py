"""Why the language stage fails on the validation sets: every failure put in one class.

    python scripts/language_failures.py [--sets faithful_unseen,heldout_unseen,...] [--n 400]
        [--save-rows DIR] [--rows DIR] [--show CLASS] [--long] [--outcomes FILE]

Sets with ground truth (never test50, never the excluded trials): `faithful_seen`, `faithful_unseen`,
`trainstyle_unseen`, `heldout_unseen`, the reference-style `refsdev_seen/unseen`, `refsheld_seen/unseen`
and `refsnew_seen/unseen` (`suites.alfred.structure_validation.rows_of_set`; `NAME:SEED` composes one with
another seed), `plain` (issue 23's user-style set), `users` and `users_heldout` (tests/language/data/styles/).
A composed set depends on the lexicon (its text-faithful labels), so `--save-rows DIR` keeps the rows and
`--rows DIR` scores another version of the code on exactly those rows (before/after on the same
instructions); `--outcomes FILE` writes each row's class and why (JSON lines) to compare two versions row
by row.

Classes of a failure (the default offline backend, its reading after the top candidate of each
ambiguous word, then check 1, `accounting.account`, with the floor plan's instance counts as `plan` gives
them):
- `accounting false refusal`: the reading matches the ground truth, only check 1 names a word;
- `unread clause, reading right`: the reading matches, but the grammar left a clause unread;
- `refused, reading wrong`: words are unread and the reading is wrong too (a right refusal);
- `structure: task count` / `structure: order`: read completely, the number of tasks or the order is wrong;
- `grounding: type`: kinds and counts right, a type is outside the accepted ones (lenient match passes);
- `slot: kind/count/sliced/type`: any other wrong task;
- `error`: refused with an error (a contradictory order, an impossible count).

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
from functools import cache
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grounding import scene_types
from nl2hltl2plan.language.learned.inference import parse_instruction
from nl2hltl2plan.language.referents import check_referents
from nl2hltl2plan.language.scoring import match
from nl2hltl2plan.language.translate import apply_choices, scene_instances, top_candidates, translate
from nl2hltl2plan.suites.alfred.structure_validation import rows_of_set
from nl2hltl2plan.worlds import load_world
from nl2hltl2plan.worlds.world import World

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_multiagent_long import instructions  # noqa: E402
from trust_sets import parse_line  # noqa: E402

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
    "error",
)


def rows(name: str, n: int) -> list[dict[str, Any]]:
    if name.startswith("users"):
        lines = [
            ln for ln in (STYLES / f"{name}.txt").read_text().splitlines() if ln.strip() and ln[0] != "#"
        ]
        return [parse_line(ln, name, k) for k, ln in enumerate(lines, 1)]
    return rows_of_set(name, n)


@cache
def _world(scene: str) -> World:
    return load_world(scene)


def classify(row: dict[str, Any]) -> tuple[str, str]:
    """(class, why) of one instruction with ground truth. The rows of the committed sets, written for
    `plan --world SCENE`, give check 1 that world's instance counts, as `plan` does
    (`translate.account_words`): counts against the scene, "the same X" and picking one of several are
    judged too. A generator row composes ALFRED trials whose own objects the bare floor plan may lack
    ("two pillows" where it has one), so it is judged without counts, as before."""
    try:
        p = parse_instruction(row["instruction"], scene_types(row["scene"]), row["scene"], strict=False)
        apply_choices(p, top_candidates(p.ambiguities))
        world = _world(row["scene"]) if str(row["id"]).startswith("trust.") else None
        instances = scene_instances(world) if world is not None else None
        scene = world.name if world is not None else "the scene"
        found = [str(u) for u in account(row["instruction"], p.tasks, p.before, instances, scene)]
        check_referents(row["instruction"], p.tasks, p.before, instances, scene)  # as `translate._finish`
    except Nl2Hltl2PlanError as exc:
        return "error", str(exc)
    unread = list(p.unparsed) + found
    verdict = match(p.tasks, p.before, row["tasks"], row["before"], strict=True)
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
    if len(p.tasks) != len(row["tasks"]):
        return "structure: task count", why
    if verdict.tasks_ok:
        return "structure: order", why
    if match(p.tasks, p.before, row["tasks"], row["before"], strict=False).order_ok:
        return "grounding: type", why
    return "slot: kind/count/sliced/type", why


def report_set(
    name: str, data: list[dict[str, Any]], show: str | None, outcomes: list[dict[str, Any]] | None = None
) -> None:
    per: dict[Any, Counter[str]] = defaultdict(Counter)
    for k, row in enumerate(data):
        cls, why = classify(row)
        if outcomes is not None:
            outcomes.append(
                {"set": name, "row": k, "instruction": row["instruction"], "class": cls, "why": why}
            )
        for key in (row["n_base"], "all"):
            per[key][cls] += 1
        if show and cls == show:
            print(f"  {row['instruction']!r}: {why[:300]}", file=sys.stderr)
    keys = sorted(k for k in per if k != "all") + ["all"]
    print(f"\n{name} ({len(data)} instructions): outcome per number of base tasks")
    print("| class | " + " | ".join(str(k) for k in keys) + " |")
    print("| --- |" + " --- |" * len(keys))
    for cls in CLASSES:
        if per["all"][cls]:
            print(f"| {cls} | " + " | ".join(str(per[k][cls]) for k in keys) + " |")
    print("| converted | " + " | ".join(f"{per[k]['ok']}/{sum(per[k].values())}" for k in keys) + " |")


def long_reason(text: str, world: Any) -> list[str]:
    """Why the language stage does not accept one long instruction (empty: accepted)."""
    try:
        r = translate(text, world, "offline", ask=top_candidates, build=False, actions="none")
    except Nl2Hltl2PlanError as exc:
        msg = str(exc)
        if re.match(r"no \w+ in FloorPlan", msg):
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
    first: Counter[str] = Counter()
    anywhere: Counter[str] = Counter()
    accepted = total = 0
    for n_base in range(5, 10):
        for key, text, _ in instructions(n_base):
            scene = key.split(".")[0]
            reasons = long_reason(text, _world(scene))
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
    args = ap.parse_args()
    outcomes: list[dict[str, Any]] | None = [] if args.outcomes else None
    for name in [s for s in args.sets.split(",") if s]:
        saved = args.rows / f"{name}.json" if args.rows else None
        data = json.loads(saved.read_text()) if saved and saved.exists() else rows(name, args.n)
        if args.save_rows:
            args.save_rows.mkdir(parents=True, exist_ok=True)
            (args.save_rows / f"{name}.json").write_text(json.dumps(data))
        report_set(name, data, args.show, outcomes)
    if args.outcomes and outcomes is not None:
        args.outcomes.write_text("".join(json.dumps(o) + "\n" for o in outcomes))
    if args.long:
        report_long()
    return 0


if __name__ == "__main__":
    sys.exit(main())
