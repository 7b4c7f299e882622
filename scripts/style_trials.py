"""Fill the `trials:` column of the paper-style sets: the ALFRED trials each line's tasks come from.

    python scripts/style_trials.py paper_h159dev paper_h159held ...   # rewrite those style sets in place
    python scripts/style_trials.py --check paper_h159dev ...          # print what would change, write nothing

The paper-style sets (tests/language/data/styles/paper_*.txt) were composed from ALFRED trials of one floor
plan each, but their lines named only the floor plan, so a scorer built the floor plan's default world, which
may hold fewer of an object than the trials had ("two pillows" where the default trial has one). For each
task of a line this picks one trial deterministically:

- the candidates are the floor plan's trials that are not in training_exclusions.txt and whose task type,
  object, receptacle, movable container, lamp and slicing match the task (a lenient `Mug/Cup` matches
  either; `place_two` / `x2` is ALFRED's pick-two type);
- among them, the one whose own annotations name most of the line's words (the trial the line was written
  from says "the gold vase", "the keurig"); ties go to the lowest `sha1(AUTHOR + trial)`, the order the
  sets' authors drew trials in (AUTHOR: "h159" of paper_h159dev);
- each task of a line gets a trial of its own where the floor plan has one.

A line with a task no trial matches keeps no column (and is printed); a line's text and truth are never
changed: the column is appended after its last field.
"""

from __future__ import annotations

import argparse
import hashlib
import re
import sys
from pathlib import Path

from nl2hltl2plan.language.learned.data import KIND_OF_TASK_TYPE
from nl2hltl2plan.worlds.floor_plans import TrialRecord, alfred_data, excluded_trials

sys.path.insert(0, str(Path(__file__).resolve().parent))
from trust_sets import STYLES, TRIALS_TAG, parse_line  # noqa: E402

WORD = re.compile(r"[a-z]+")
# words every annotation says: they tell no trial from another
COMMON = frozenset(
    "the a an and then it its to in on of from into onto with up down put place set take pick go turn "
    "walk move left right front back side top bottom open close that this there is are be you your"
    .split()
)


def words(text: str) -> set[str]:
    return {w for w in WORD.findall(text.lower()) if len(w) > 2 and w not in COMMON}


def annotation_words(rec: TrialRecord) -> set[str]:
    said: set[str] = set()
    for ann in rec.annotations:
        said |= words(" ".join([ann.get("task_desc", ""), *ann.get("high_descs", [])]))
    return said


def matches(rec: TrialRecord, task: dict) -> bool:
    """Does the trial's type and pddl_params give this ground-truth task?"""
    if rec.task_type is None or KIND_OF_TASK_TYPE.get(rec.task_type) != task["kind"]:
        return False
    p = rec.pddl_params or {}
    if p.get("object_target") not in task["object"] or bool(p.get("object_sliced")) != task["sliced"]:
        return False
    if task["kind"] == "examine_in_light":
        return p.get("toggle_target") in (task["light"] or [])
    if p.get("parent_target") not in (task["receptacle"] or []):
        return False
    if task["kind"] == "place_in_container":
        return p.get("mrecep_target") in (task["container"] or [])
    return True


def pick(row: dict, author: str) -> list[str] | None:
    """One trial per task of a parsed style-set row, or None where a task matches no trial."""
    banned, records = excluded_trials(), alfred_data().example_fields
    floor = [r for r in records if r.floor_plan == row["scene"] and r.trial not in banned]
    said = words(row["instruction"])
    chosen: list[str] = []
    for task in row["tasks"]:
        cands = [r for r in floor if matches(r, task)]
        if not cands:
            return None
        fresh = [r for r in cands if r.trial not in chosen] or cands

        def rank(r: TrialRecord) -> tuple[int, str]:
            return (-len(said & annotation_words(r)), hashlib.sha1((author + r.trial).encode()).hexdigest())

        best = min(fresh, key=rank).trial
        if best not in chosen:
            chosen.append(best)
    return chosen


def fill(name: str, check: bool) -> list[str]:
    """Rewrite one set with the column on every line it can fill; the lines left without one."""
    path = STYLES / f"{name}.txt"
    author = re.sub(r"^paper_|(dev|held)$", "", name)
    out, missing, n = [], [], 0
    for line in path.read_text().splitlines():
        if not line.strip() or line.startswith("#"):
            out.append(line)
            continue
        n += 1
        row = parse_line(line, name, n)
        if row.get("source_trials"):  # filled before: kept as it is
            out.append(line)
            continue
        trials = pick(row, author)
        if trials is None:
            missing.append(f"{name} {n}: {row['instruction']}")
            out.append(line)
            continue
        out.append(f"{line.rstrip()} | {TRIALS_TAG} {' '.join(trials)}")
    if not check:
        path.write_text("\n".join(out) + "\n")
    return missing


def main() -> int:
    ap = argparse.ArgumentParser(prog="python scripts/style_trials.py")
    ap.add_argument("sets", nargs="+", help="style-set names (tests/language/data/styles/NAME.txt)")
    ap.add_argument("--check", action="store_true", help="write nothing; print the lines no trial matches")
    args = ap.parse_args()
    for name in args.sets:
        for line in fill(name, args.check):
            print(f"no trial: {line}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
