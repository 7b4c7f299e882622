"""Issue 28, the world side of the paper-style sets (h168): a style-set line's optional last column
`trials: ID ...` is its `source_trials`, checked when read, and its world holds those trials' objects, as a
benchmark row's does (`trust_sets.parse_line`, `world_of`; `scripts/style_trials.py` fills the column)."""

from __future__ import annotations

import re
import sys
from collections import Counter
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))  # trust_sets, style_trials

pytestmark = pytest.mark.data

SPOONS = "train/pick_two_obj_and_place-Spoon-None-SideTable-3/trial_T20190908_123320_379413"
LINE = "FloorPlan3 | Move two spoons to the table with the microwave on it. | place_two Spoon SideTable x2 |"


def movable_counts(world) -> Counter[str]:
    return Counter(o.type for o in world.objects.values() if o.affordances.pickupable)


def test_a_line_with_trials_builds_a_world_holding_their_objects() -> None:
    import trust_sets

    from nl2hltl2plan.worlds.floor_plans import alfred_data

    row = trust_sets.parse_line(f"{LINE} | trials: {SPOONS}", "t", 1)
    assert row["source_trials"] == [SPOONS]
    bare = trust_sets.parse_line(LINE, "t", 1)
    assert "source_trials" not in bare and {**bare, "source_trials": [SPOONS]} == row  # text and truth kept
    gt = trust_sets.GTInstance.model_validate(row)
    world, default = trust_sets.world_of(gt.scene, gt.source_trials), trust_sets.world_of(gt.scene)
    # the trial put two spoons on the table; the floor plan's default trial holds one
    assert movable_counts(world)["Spoon"] >= 2 > movable_counts(default)["Spoon"]
    names = {n.rsplit("_", 1)[0] for n, *_ in alfred_data().trials[SPOONS].poses}
    assert names <= set(movable_counts(world))
    assert trust_sets.outcome(gt)[0] == "converted"
    assert trust_sets.outcome(trust_sets.GTInstance.model_validate(bare))[0] == "refused"


def test_a_trial_it_may_not_use_is_a_one_line_error_naming_it() -> None:
    import trust_sets

    from nl2hltl2plan.worlds.floor_plans import alfred_data, excluded_trials

    other = LINE.replace("FloorPlan3", "FloorPlan4", 1)
    said = re.escape(f"t, instruction 2: trial {SPOONS} is in FloorPlan3, not FloorPlan4")
    with pytest.raises(trust_sets.TrialsError, match=f"^{said}$"):
        trust_sets.parse_line(f"{other} | trials: {SPOONS}", "t", 2)
    with pytest.raises(trust_sets.TrialsError, match="no ALFRED trial 'train/nothing'"):
        trust_sets.parse_line(f"{LINE} | trials: {SPOONS} train/nothing", "t", 1)
    banned = sorted(excluded_trials())[0]
    fp = alfred_data().trials[banned].floor_plan
    with pytest.raises(trust_sets.TrialsError, match=f"{re.escape(banned)} is excluded"):
        trust_sets.parse_line(f"{fp} | Put it there. | place Mug CounterTop | | trials: {banned}", "t", 1)


def test_every_paper_line_names_one_matching_trial_per_task() -> None:
    """The committed column agrees with each line's truth (type, object, receptacle, container, lamp,
    slicing); the one line no trial matches (FloorPlan401's candle trials put it on the cart) has none."""
    import style_trials
    import trust_sets

    from nl2hltl2plan.worlds.floor_plans import alfred_data

    records = {r.trial: r for r in alfred_data().example_fields}
    without = []
    for path in sorted(trust_sets.STYLES.glob("paper_h[12]*.txt")):
        lines = [ln for ln in path.read_text().splitlines() if ln.strip() and not ln.startswith("#")]
        for n, line in enumerate(lines, 1):
            row = trust_sets.parse_line(line, path.stem, n)
            trials = row.get("source_trials", [])
            if not trials:
                without.append(row["instruction"])
                continue
            assert len(set(trials)) == len(row["tasks"]), line
            # a trial of ALFRED's test splits has no task type or parameters to match (h169 wrote two floor
            # plans' lines from their annotations alone); its floor plan is still checked (`check_trials`)
            typed = [t for t in trials if records[t].task_type is not None]
            # a line that must be refused (its refusal column) has no reading to match: its trials only build
            # the world ("put it next to the coffee machine", h197's landmark lines)
            matched = len(typed) == len(trials) and row["feasible"]
            for task in row["tasks"] if matched else []:
                assert any(style_trials.matches(records[t], task) for t in trials), (line, task)
    assert without == ["Put a candle on the shelf."]


def test_plan_takes_the_trials_plan_json_sets_passes(capsys) -> None:
    """`plan --trials` builds its world from them (`plan_json_sets` scores a line with the column so), and
    refuses a trial of another floor plan before reading the text."""
    from nl2hltl2plan.cli.main import main

    assert main(["plan", "Move two spoons to the table.", "--world", "FloorPlan4", "--trials", SPOONS]) == 2
    assert f"trial {SPOONS} is in FloorPlan3, not FloorPlan4" in capsys.readouterr().err
