"""Issue 23's own test sets: build their ground truth, and measure the language stage on them.

    python scripts/trust_sets.py build     # tests/language/data/trust/*.txt -> *.jsonl (benchmark format)
    python scripts/trust_sets.py measure [--backend offline|grammar] [--sets plain,mixed] [--plurals ask|two]
        # refused / partial / converted / wrong, as `plan` reads each line (a user-style set by its name)
    python scripts/trust_sets.py validation [--split valid_seen] [--n 2000] [--seed 1]  # check 1's flags

The .txt files are hand-written, one instruction a line: `scene | instruction | base tasks | before |
what must be refused | constraints`. Constraints (what a negation forbids): `;`-separated, each the
forbidden action patterns separated by blanks (`put(Cup,SinkBasin)`, `any(Tomato)` for every action the
world allows on a tomato), optionally `until A` (the base task that lifts it).
Base tasks: `kind Object[/Alt] Destination [x2|xN] [sliced] [in Container]` (`xN`, N > 2: "all the X", every
one of the N the line's world holds, checked at `build`) or
`set_state Object state`,
`;`-separated, ids A, B, ... in order; before: `A<B, ...`. A line with something to refuse has
`feasible: false` and that text in `issues` (its base tasks are the part a world can do).
A style-set line may end with a column `trials: ID ID ...`: the ALFRED trials it was composed from (ids as
a benchmark row's `source_trials`, each a non-excluded trial of the line's floor plan, else a one-line
error). Its world then holds those trials' objects, as a benchmark row's does (`world_of`); a line without
the column gets the floor plan's default world (its first trial), as `plan --world FloorPlanN`.

`measure` runs the `plan` command's language stage (no planning) on each line in its floor plan and
sorts the outcome: refused (an error, exit 2), partial (`unparsed` names words), converted (the base
tasks, orderings and constraints match the ground truth, lenient types) or wrong (anything else: a plan
whose spec misses or changes part of the text).
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import Counter
from pathlib import Path
from typing import get_args

from nl2hltl2plan.domain.plurals import Plurals
from nl2hltl2plan.errors import Nl2Hltl2PlanError, WorldError
from nl2hltl2plan.language.scoring import match
from nl2hltl2plan.language.translate import apply_choices, top_candidates, translate
from nl2hltl2plan.suites.alfred.conversion import scenario_world
from nl2hltl2plan.worlds.tasks import GTInstance
from nl2hltl2plan.worlds.world import World

TRUST = Path(__file__).resolve().parent.parent / "tests" / "language" / "data" / "trust"
STYLES = TRUST.parent / "styles"


def parse_task(text: str, task_id: str) -> dict:
    words = text.split()
    if words[0] == "set_state":  # set_state Object state
        return {
            "id": task_id,
            "text": "",
            "kind": "set_state",
            "object": words[1].split("/"),
            "count": 1,
            "sliced": False,
            "container": None,
            "receptacle": None,
            "light": None,
            "state": words[2],
        }
    kind, obj, dest = words[0], words[1].split("/"), words[2].split("/")
    rest = words[3:]
    task = {
        "id": task_id,
        "text": "",
        "kind": kind,
        "object": obj,
        "count": 1,
        "sliced": "sliced" in rest,
        "container": None,
        "receptacle": dest,
        "light": None,
    }
    for word in rest:  # "x2" (place_two), or "xN" for "all the X" over N instances (issue 23: every one)
        if re.fullmatch(r"x[2-9]", word):
            task["count"] = int(word[1:])
    if "in" in rest:
        task["container"] = rest[rest.index("in") + 1].split("/")
    if kind == "examine_in_light":
        task["light"], task["receptacle"] = dest, None
    return task


class TrialsError(ValueError):
    """A style set's `trials:` column names a trial it may not use (`check_trials`)."""


TRIALS_TAG = "trials:"  # the optional last column of a style-set line: the ALFRED trials it was composed from


def parse_line(line: str, name: str, n: int) -> dict:
    parts = [p.strip() for p in line.split("|")]
    trials = parts.pop()[len(TRIALS_TAG) :].split() if parts[-1].startswith(TRIALS_TAG) else []
    scene, instruction, tasks_text, before_text = parts[:4]
    refuse = parts[4] if len(parts) > 4 else ""
    constraints = [parse_constraint(c) for c in (parts[5] if len(parts) > 5 else "").split(";") if c.strip()]
    tasks = [parse_task(t.strip(), chr(65 + k)) for k, t in enumerate(tasks_text.split(";")) if t.strip()]
    before = [p.strip().split("<") for p in before_text.split(",") if p.strip()]
    row = {
        "id": f"trust.{name}.{n}",
        "scene": scene,
        "n_base": len(tasks),
        "instruction": instruction,
        "tasks": tasks,
        "before": before,
        "feasible": not refuse,
        "issues": [refuse] if refuse else [],
        "ambiguous": False,
        "notes": ["written for issue 23"],
        "constraints": constraints,
    }
    if trials:  # as a benchmark row's: its world holds these trials' objects (`world_of`)
        row["source_trials"] = check_trials(scene, trials, f"{name}, instruction {n}")
    return row


def check_trials(scene: str, trials: list[str], where: str) -> list[str]:
    """The `trials:` column's ids, each a non-excluded ALFRED trial of the line's floor plan; anything else
    is a one-line error naming it (TrialsError): the world builder's own check, and the exclusions."""
    from nl2hltl2plan.worlds.floor_plans import check_trial, excluded_trials

    banned = excluded_trials()
    for tid in trials:
        try:
            check_trial(scene, tid)
        except WorldError as exc:
            raise TrialsError(f"{where}: {exc}") from None
        if tid in banned:
            raise TrialsError(f"{where}: trial {tid} is excluded (benchmark/training_exclusions.txt)")
    return trials


def parse_constraint(text: str) -> dict:
    """`pattern pattern ... [until A]` -> {"forbid": [...], "until": "A" or None}."""
    words = text.split()
    until = words[words.index("until") + 1] if "until" in words else None
    return {"forbid": [w for w in words if w != "until" and w != until], "until": until}


def constraints_match(got: list, truth: list[dict], world) -> bool:
    """Do the language stage's constraints forbid exactly what the ground truth's do (`any(X)`: every
    action the world allows on X), each lifted by the same task?"""
    from nl2hltl2plan.language.grounding import world_lookup
    from nl2hltl2plan.language.negations import patterns

    def expand(forbid: list[str]) -> frozenset[str]:
        out: set[str] = set()
        for p in forbid:
            out |= set(patterns("any", [p[4:-1]], look=world_lookup(world))) if p.startswith("any(") else {p}
        return frozenset(out)

    want = sorted((sorted(expand(c["forbid"])), c["until"] or "") for c in truth)
    have = sorted((sorted(c.forbid), c.until or "") for c in got)
    return want == have


def build() -> None:
    for src in sorted(TRUST.glob("*.txt")):
        lines = [ln for ln in src.read_text().splitlines() if ln.strip() and not ln.startswith("#")]
        rows = [parse_line(ln, src.stem, n) for n, ln in enumerate(lines, 1)]
        for r in rows:
            GTInstance.model_validate(r)
            check_counts(r)
        src.with_suffix(".jsonl").write_text("".join(json.dumps(r) + "\n" for r in rows))
        print(f"{src.with_suffix('.jsonl')}: {len(rows)} instructions")


def check_counts(row: dict) -> None:
    """A count above two ("all the watches" as `x4`) is every instance the line's world holds of the type:
    any other is a one-line error naming the line (a pair, `x2`, is ALFRED's own, maybe fewer than held)."""
    from nl2hltl2plan.worlds.floor_plans import instance_counts

    for task in row["tasks"]:
        if task["count"] <= 2:
            continue
        have = instance_counts(row["scene"], row.get("source_trials") or None)
        if task["count"] != max(have.get(o, 0) for o in task["object"]):
            held = {o: have.get(o, 0) for o in task["object"]}
            where = f"{row['id']}: x{task['count']}"
            raise ValueError(f"{where} is not every instance of {held} in {row['scene']}")


def world_of(scene: str, trials: list[str] | tuple[str, ...] = ()) -> World:
    """A line's world as the benchmark builds a row's (`conversion.scenario_world`): the floor plan with the
    objects of the line's `trials:` (its `source_trials`), or of the floor plan's first trial where it names
    none. Cached there: `translate` only reads a world, and the sets load the same few hundreds of times."""
    return scenario_world({"scene": scene, "source_trials": list(trials)})


def outcome(gt: GTInstance, backend: str = "offline", plurals: Plurals = "ask") -> tuple[str, str]:
    """(refused | partial | converted | wrong, detail) for one line, as `plan [--plurals]` would treat it."""
    return read_line(gt, backend, plurals)[:2]


def read_line(
    gt: GTInstance, backend: str = "offline", plurals: Plurals = "ask"
) -> tuple[str, str, list[str]]:
    """`outcome`, and the assumptions the reading stated (`--plurals two`: "'the forks': read as 2 ...")."""
    world = world_of(gt.scene, gt.source_trials)
    try:
        res = translate(gt.instruction, world, backend, build=False, actions="none", plurals=plurals)
    except Nl2Hltl2PlanError as exc:
        return "refused", str(exc), []
    if res.partial:
        return "partial", "; ".join(res.unparsed), res.assumptions
    res = apply_choices(res, top_candidates(res.ambiguities))
    verdict = match(res.tasks, res.before, [t.model_dump() for t in gt.tasks], gt.before, strict=False)
    truth = constraints_of(gt)
    if gt.feasible and verdict.order_ok and constraints_match(res.constraint_specs, truth, world):
        return "converted", "", res.assumptions
    if gt.feasible and verdict.order_ok:
        why = f"constraints {[c.describe() for c in res.constraint_specs]}, not {truth}"
        return "wrong", why, res.assumptions
    return "wrong", "; ".join(verdict.reasons) or f"not refused: {gt.issues}", res.assumptions


_CONSTRAINTS: dict[str, list[dict]] = {}  # row id -> its constraints (GTInstance ignores the field)


def constraints_of(gt: GTInstance) -> list[dict]:
    """The ground truth's constraints, as `load` read them."""
    return _CONSTRAINTS.get(gt.id, [])


def load(name: str) -> list[GTInstance]:
    """A trust set's rows (`trust/NAME.jsonl`), or a user-style set's (`styles/NAME.txt`, built here)."""
    path = TRUST / f"{name}.jsonl"
    if not path.exists():
        lines = (STYLES / f"{name}.txt").read_text().splitlines()
        said = [ln for ln in lines if ln.strip() and not ln.startswith("#")]
        rows = [parse_line(ln, name, n) for n, ln in enumerate(said, 1)]
        _CONSTRAINTS.update({r["id"]: r.get("constraints", []) for r in rows})
        return [GTInstance.model_validate(r) for r in rows]
    rows = [json.loads(line) for line in path.read_text().splitlines() if line.strip()]
    _CONSTRAINTS.update({r["id"]: r.get("constraints", []) for r in rows})
    return [GTInstance.model_validate(r) for r in rows]


def measure(backend: str, show: bool, names: list[str], plurals: Plurals = "ask") -> None:
    """The table of outcomes per set; `assumed`: lines read under a stated assumption (`--plurals two`)."""
    print("| set | n | refused | partial | converted | wrong | assumed |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    details = []
    for name in names:
        gts = load(name)
        counts: Counter[str] = Counter()
        for gt in gts:
            what, why, assumed = read_line(gt, backend, plurals)
            counts[what] += 1
            counts["assumed"] += bool(assumed)
            said = f" [assumed: {'; '.join(assumed)}]" if assumed else ""
            if what == "wrong" or (show and what != "converted"):
                details.append(f"{name} {what}: {gt.instruction!r}: {why}{said}")
        cells = " | ".join(str(counts[k]) for k in ("refused", "partial", "converted", "wrong", "assumed"))
        print(f"| {name} | {len(gts)} | {cells} |")
    print("\n".join(details), file=sys.stderr)


def validation(split: str, n: int, seed: int) -> None:
    """Check 1 on composed ALFRED validation instructions: how many correct conversions it flags (false
    refusals) and how many wrong ones it turns into refusals."""
    from nl2hltl2plan.language.accounting import account
    from nl2hltl2plan.language.grounding import scene_types
    from nl2hltl2plan.language.learned.inference import parse_instruction
    from nl2hltl2plan.suites.alfred.learned_validation import validation_rows

    counts: Counter[tuple[bool, bool]] = Counter()
    for row in validation_rows(split, n, seed):
        try:
            r = parse_instruction(row["instruction"], scene_types(row["scene"]), row["scene"], strict=False)
            r = apply_choices(r, top_candidates(r.ambiguities))
            flagged = bool(r.unparsed or account(row["instruction"], r.tasks, r.before))
            ok = match(r.tasks, r.before, row["tasks"], row["before"], strict=True).order_ok
        except Nl2Hltl2PlanError:
            flagged, ok = True, False
        counts[(ok, flagged)] += 1
    right, wrong = (
        counts[(True, False)] + counts[(True, True)],
        counts[(False, False)] + counts[(False, True)],
    )
    print(
        f"{split} ({n}, seed {seed}): correct conversions flagged {counts[(True, True)]} of {right}; "
        f"wrong conversions flagged {counts[(False, True)]} of {wrong}"
    )


def main() -> int:
    ap = argparse.ArgumentParser(prog="python scripts/trust_sets.py")
    ap.add_argument("what", choices=["build", "measure", "validation"])
    ap.add_argument("--split", default="valid_seen", choices=["valid_seen", "valid_unseen"])
    ap.add_argument("--n", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--backend", default="offline", choices=["offline", "grammar"])
    ap.add_argument("--show", action="store_true", help="print every line that is not converted")
    ap.add_argument("--plurals", default="ask", choices=get_args(Plurals), help="as `plan --plurals`")
    ap.add_argument(
        "--sets", default="plain,mixed", help="trust sets, or user-style sets (tests/language/data/styles)"
    )
    args = ap.parse_args()
    try:
        run(args)
    except TrialsError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return 0


def run(args: argparse.Namespace) -> None:
    if args.what == "build":
        build()
    elif args.what == "validation":
        validation(args.split, args.n, args.seed)
    else:
        measure(args.backend, args.show, args.sets.split(","), args.plurals)


if __name__ == "__main__":
    sys.exit(main())
