"""How the shipped language stage reads the names ALFRED's annotators give things (issue 28: descriptive
furniture names read literally, unknown names).

Each one-sentence annotation (`task_desc`) of a non-excluded ALFRED trial is read as `plan` reads an
instruction (`translate`, the default backend, as `trust_sets.py` does) in its trial's world, and its
types are compared with the trial's `pddl_params` (object_target, mrecep_target, parent_target,
toggle_target; `learned.data.Example`). Train annotations are where words are learned (a sample, fixed
seed); valid_seen and valid_unseen are held out and read whole.

    python scripts/alfred_names.py read --split train --n 2000 --seed 0 -o /tmp/train.jsonl
    python scripts/alfred_names.py read --split valid_seen -o /tmp/vs.jsonl
    python scripts/alfred_names.py summary /tmp/train.jsonl [--top 40]
    python scripts/alfred_names.py compare BEFORE.jsonl AFTER.jsonl
    python scripts/alfred_names.py read --split train --n 300 --seed 0 --steps -o /tmp/steps.jsonl

`read` writes one record per annotation (about a quarter of a second each: keep the file);
`summary` gives the rate of annotations whose types are all read right, the refusals by cause, and the top
classes (unknown names with the types their annotations' trials use, wrong types with the phrase said);
`compare` the same two numbers side by side and the annotations whose outcome changed. `--steps` reads the
same annotation's step-by-step sentences (`high_descs`, navigation included) joined into one instruction
instead: the kind of text test50's multi-task instructions are built of.
"""

from __future__ import annotations

import argparse
import json
import random
import re
from collections import Counter, defaultdict
from dataclasses import replace
from functools import lru_cache
from pathlib import Path
from typing import Any

from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.grounding import find_mentions
from nl2hltl2plan.language.learned.data import Example, load_examples
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.translate import apply_choices, top_candidates, translate
from nl2hltl2plan.worlds import load_world
from nl2hltl2plan.worlds.floor_plans import alfred_data
from nl2hltl2plan.worlds.world import World

SLOTS = ("object", "container", "receptacle", "light")
# a refusal's cause, from the first line of its kind (in this order)
CAUSES = (
    ("unknown name", re.compile(r"^'([^']+)' \(\w+\): no object of this world is called so")),
    ("unknown word before a name", re.compile(r"^'([^']+)' \(\w+\): no reading uses this word before")),
    ("no such type in the world", re.compile(r"^no (\w+).* in FloorPlan")),
    ("place cannot hold it", re.compile(r"^nothing named '([^']+)' here can hold")),
    ("type guessed, not said", re.compile(r"^'(\w+)' \(invented\)")),
    ("word the tasks do not use", re.compile(r"^'([^']+)' \(\w+\): no base task")),
)


def sample(split: str, n: int, seed: int) -> list[Example]:
    rows = load_examples()[split]
    return rows if n <= 0 or n >= len(rows) else random.Random(seed).sample(rows, n)


def as_steps(examples: list[Example]) -> list[Example]:
    """Each example with its annotation's step-by-step sentences joined into one text (each closed by a
    full stop), in place of its one-sentence summary."""
    steps: dict[tuple[str, str], str] = {}
    for row in alfred_data().example_fields:
        for ann in row.annotations:
            said = [" ".join(h.split()).rstrip(".") + "." for h in ann.get("high_descs", []) if h.strip()]
            steps[(row.trial, " ".join(ann.get("task_desc", "").split()))] = " ".join(said)
    return [replace(e, text=steps[(e.trial, e.text)]) for e in examples if steps.get((e.trial, e.text))]


def read_one(e: Example) -> dict[str, Any]:
    """One annotation read as `plan` reads it in the trial's world (an ambiguity takes its top-ranked
    type, as the benchmarks and `trust_sets.py` do)."""
    rec: dict[str, Any] = {"text": e.text, "trial": e.trial, "split": e.split}
    rec["gold"] = {s: e.slot(s) for s in SLOTS if e.slot(s)}
    tasks: list[BaseTaskSpec] = []
    try:
        res = translate(e.text, _world(e.floor_plan, e.trial), "offline", build=False, actions="none")
        why = list(res.unparsed)
        tasks = apply_choices(res, top_candidates(res.ambiguities)).tasks if not res.partial else []
    except Nl2Hltl2PlanError as exc:
        why = [str(exc)]
    rec["read"] = {s: sorted({t for task in tasks for t in getattr(task, s) or []}) for s in SLOTS}
    rec["refused"], rec["why"] = bool(why), why
    return rec


@lru_cache(maxsize=8)
def _world(floor_plan: str, trial: str) -> World:
    return load_world(floor_plan, [trial])


def cause(rec: dict[str, Any]) -> tuple[str, str]:
    """(cause, the word or type it names) of a refused record."""
    for name, pat in CAUSES:
        for line in rec["why"]:
            m = pat.search(line)
            if m:
                return name, m.group(1)
    return "other", (rec["why"] or [""])[0][:60]


def wrong_slots(rec: dict[str, Any]) -> list[tuple[str, str, list[str]]]:
    """(slot, gold type, read types) of each slot whose gold type the reading does not allow."""
    return [(s, g, rec["read"][s]) for s, g in rec["gold"].items() if g not in rec["read"][s]]


def outcome(rec: dict[str, Any]) -> str:
    if rec["refused"]:
        return "refused: " + cause(rec)[0]
    return "types wrong" if wrong_slots(rec) else "types right"


def said_for(rec: dict[str, Any], types: list[str]) -> str:
    """The phrase of the text read as one of `types` (the last one), else '-'."""
    said = [m.surface.lower() for m in find_mentions(rec["text"]) if set(m.entry.types) & set(types)]
    return said[-1] if said else "-"


def summary(recs: list[dict[str, Any]], top: int) -> str:
    n = len(recs)
    outcomes = Counter(outcome(r) for r in recs)
    right = outcomes["types right"]
    lines = [f"{n} annotations: types right {right} ({100 * right / n:.1f}%)"]
    lines += [f"  {k}: {v} ({100 * v / n:.1f}%)" for k, v in outcomes.most_common() if k != "types right"]
    names: dict[str, Counter[str]] = defaultdict(Counter)
    for r in recs:
        if r["refused"] and cause(r)[0] in ("unknown name", "unknown word before a name"):
            names[cause(r)[1].lower()].update(set(r["gold"].values()))
    lines.append(f"\nunknown words (annotations; the gold types of their trials), top {top}:")
    for w, c in sorted(names.items(), key=lambda kv: -kv[1].total())[:top]:
        n_w = sum(1 for r in recs if r["refused"] and cause(r)[1].lower() == w)
        lines.append(f"  {n_w:4d} {w!r}: " + ", ".join(f"{t} {k}" for t, k in c.most_common(4)))
    wrong: Counter[tuple[str, str, str, str]] = Counter()
    for r in recs:
        if not r["refused"]:
            for s, g, got in wrong_slots(r):
                wrong[(s, said_for(r, got) if got else "-", "/".join(got) or "none", g)] += 1
    lines.append(f"\nwrong types (slot: phrase said -> read, gold), top {top}:")
    lines += [f"  {k:4d} {s}: {p!r} -> {got}, gold {g}" for (s, p, got, g), k in wrong.most_common(top)]
    return "\n".join(lines)


def load(path: Path) -> list[dict[str, Any]]:
    return [json.loads(line) for line in path.read_text().splitlines() if line.strip()]


def compare(before: list[dict[str, Any]], after: list[dict[str, Any]]) -> str:
    a = {(r["trial"], r["text"]): r for r in after}
    lines: list[str] = []
    moved: Counter[tuple[str, str]] = Counter()
    for r in before:
        r2 = a.get((r["trial"], r["text"]))
        if r2 and outcome(r) != outcome(r2):
            moved[(outcome(r), outcome(r2))] += 1
            lines.append(f"  {outcome(r)} -> {outcome(r2)}: {r['text']!r} gold {r['gold']} read {r2['read']}")
    n = len(before)
    right = [sum(outcome(x) == "types right" for x in rs) for rs in (before, after)]
    refused = [sum(x["refused"] for x in rs) for rs in (before, after)]
    head = [
        f"types right {right[0]}/{n} ({100 * right[0] / n:.1f}%) -> {right[1]} ({100 * right[1] / n:.1f}%)",
        f"refused {refused[0]} ({100 * refused[0] / n:.1f}%) -> {refused[1]} ({100 * refused[1] / n:.1f}%)",
        *(f"  {k}: {v}" for k, v in moved.most_common()),
    ]
    return "\n".join(head + lines)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("read")
    r.add_argument("--split", choices=("train", "valid_seen", "valid_unseen"), default="train")
    r.add_argument("--n", type=int, default=0, help="sample size (0: every annotation)")
    r.add_argument("--seed", type=int, default=0)
    r.add_argument("--steps", action="store_true", help="read the step-by-step sentences joined instead")
    r.add_argument("-o", "--out", type=Path, required=True)
    s = sub.add_parser("summary")
    s.add_argument("file", type=Path)
    s.add_argument("--top", type=int, default=40)
    c = sub.add_parser("compare")
    c.add_argument("before", type=Path)
    c.add_argument("after", type=Path)
    args = ap.parse_args()
    if args.cmd == "read":
        chosen = sample(args.split, args.n, args.seed)
        recs = [read_one(e) for e in (as_steps(chosen) if args.steps else chosen)]
        args.out.write_text("".join(json.dumps(x) + "\n" for x in recs))
        print(summary(recs, 20))
    elif args.cmd == "summary":
        print(summary(load(args.file), args.top))
    else:
        print(compare(load(args.before), load(args.after)))


if __name__ == "__main__":
    main()
