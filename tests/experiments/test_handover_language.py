"""The language stage on the handover worlds: the eight Table III instructions and our own rephrasings
give the written specs, node by node (Spot equivalence); what the rules cannot read is refused."""

from __future__ import annotations

import json

import pytest
from handover_axes import near_misses, sample
from handover_heldout import (
    FIXING_VARIANTS,
    H43_NEAR_MISSES,
    H43_ROUNDS,
    H43_VARIANTS,
    HELD_OUT,
    LEAD_HELD_OUT,
    LEAD_SESSION9,
    LEAD_SESSION9_BATCH8,
    LEAD_SESSION9_BATCH9,
    NEAR_MISSES,
    SEEN_WHILE_FIXING,
    STACKED_MARKER_NEAR_MISSES,
    STACKED_MARKERS,
)
from handover_rephrasings import REPHRASINGS
from handover_session10 import NEAR_MISSES_DEV10, NEAR_MISSES_S10, REASONS_READ, STILL_REFUSED, STYLES
from handover_specs import (
    TASKS,
    assert_not_the_written_spec,
    assert_refused_by_name,
    assert_written_spec,
    assert_written_spec_or_refused,
    cases,
)
from handover_specs import spec_of as _spec

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.translate import translate
from nl2hltl2plan.suites.handover.handover_bench import instance, specs_equivalent

# a whole committed batch read sentence by sentence: `python -m pytest -m sweep` (the default run leaves
# them to `scripts/bench_handover_styles.py --batch all`, which measures the same sentences)
SWEEP = pytest.mark.sweep


@pytest.mark.parametrize("task_id", sorted(TASKS))
def test_table3_instructions_give_the_written_specs(task_id):
    task = TASKS[task_id]
    equal, why = specs_equivalent(_spec(task_id, task.instruction), task.hierarchical())
    assert equal, why


@pytest.mark.parametrize(("task_id", "text"), cases(REPHRASINGS))
def test_rephrasings_give_the_same_specs(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), cases(HELD_OUT))
def test_held_out_rephrasings_give_the_same_specs(task_id, text):
    """Written after the rules, kept apart from REPHRASINGS: 13 of 17 gave the spec at first, the other 4
    were refused (exit 2, never a different spec) until the phrases they use were added generally."""
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(
    ("task_id", "text"),
    cases(SEEN_WHILE_FIXING, FIXING_VARIANTS, H43_VARIANTS, STACKED_MARKERS),
)
def test_rephrasings_seen_while_fixing_give_the_same_specs(task_id, text):
    """The refused sentences of the lead's held-out sets (issue 24) and our variants along each axis a
    writer varies."""
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(
    ("task_id", "text"),
    [
        (1, "Transfer three blocks into the opposite. The blue block should be placed before the red block."),
        (3, "Move the three pillars to regions E, F and G."),  # the prohibition is missing
        (4, "Transfer three blocks into the opposite regions. Then place the yellow block on region G."),
        (7, "Place the three objects one after another to region I, no objects can be placed on region F."),
        # the phrase classes of SEEN_WHILE_FIXING with one thing changed
        (
            1,
            "Bring all three blocks over to the opposite side, making sure the blue one gets placed before "
            "the red one.",
        ),
        (1, "The blue block goes down before the red block; move three blocks to the opposite."),
        (3, "Move the three pillars over to regions E, F and G, next to arm a and arm b."),  # no prohibition
        (3, "Get the three pillars into regions E, F and G. Objects must not be placed on region H."),
        (
            4,
            "Transfer the three blocks into the opposite regions, but the red block cannot be touched by "
            "any arm until the blue block has been touched. Finally, return the yellow block to region G.",
        ),
        (
            5,
            "Place the blue block before the red block while exchanging their positions. The yellow block "
            "goes to the opposite side at any time.",
        ),
        (
            7,
            "One after another, put the three blocks on region I, and during this period nothing can be "
            "placed on region F and G; the red block comes before the blue block.",
        ),
        (
            7,
            "One after another, put the three blocks on region I, and during this period nothing can be "
            "placed on region F, G and H; the blue block comes before the red block.",
        ),
    ],
)
def test_a_different_meaning_gives_a_different_spec(task_id, text):
    equal, _ = specs_equivalent(_spec(task_id, text), TASKS[task_id].hierarchical())
    assert not equal


@pytest.mark.parametrize(
    ("task_id", "text"),
    cases(NEAR_MISSES, H43_NEAR_MISSES, STACKED_MARKER_NEAR_MISSES, NEAR_MISSES_S10, NEAR_MISSES_DEV10),
)
def test_near_misses_are_refused_or_give_another_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)


@SWEEP
@pytest.mark.parametrize(
    ("batch", "style"),
    [
        (batch, style)
        for batch in ("dev", "dev2", "dev3", "dev4", "dev5", "dev6", "dev7", "dev8", "dev9", "dev10")
        for style in STYLES[batch]
    ],
)
def test_session10_styles_give_the_written_specs_or_are_refused_by_name(batch, style):
    """Our rephrasings by style (plain, terse, formal, explanatory, passive, numbered steps, non-native,
    typos, constraints first): each gives the written spec, but for `STILL_REFUSED`, refused by name."""
    for task, text in STYLES[batch][style].items():
        if text in STILL_REFUSED:
            assert_refused_by_name(int(task), text)
        else:
            assert_written_spec(int(task), text)


@SWEEP
@pytest.mark.parametrize("style", sorted(STYLES["validation"]))
def test_session10_validation_is_read_right_or_refused_never_misread(style):
    """Our validation batch, written with `dev` and measured once on the frozen reader (56 of 72 gave the
    written spec, 16 were refused by name, 0 another spec; 65 / 7 / 0 after h50's round, which fixed refusals
    listed in results/handover/generality_session10.md)."""
    for task, text in STYLES["validation"][style].items():
        assert_written_spec_or_refused(int(task), text)


@SWEEP
@pytest.mark.parametrize("style", sorted(STYLES["validation2"]))
def test_session10_second_validation_is_read_right_or_refused_never_misread(style):
    """h50's validation batch, written with `dev10` and measured once on the final reader (15 of 24 gave
    the written spec, 9 were refused by name, 0 another spec)."""
    for task, text in STYLES["validation2"][style].items():
        assert_written_spec_or_refused(int(task), text)


@pytest.mark.parametrize(("task_id", "text"), cases(REASONS_READ))
def test_a_reason_that_names_a_region_is_read_not_dropped(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), cases(sample()))
def test_combinations_of_the_axes_give_the_same_specs(task_id, text):
    """A fixed-seed sample of slot combinations (verb x group x "the opposite" x order sentence x ...)."""
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), cases(near_misses()))
def test_combinations_with_one_meaning_changed_give_another_spec(task_id, text):
    """Never the written spec: another spec, or a refusal by name ("At any time, put the yellow block back
    to region G" beside its move to the opposite side orders nothing "back" could mean: refused)."""
    assert_not_the_written_spec(task_id, text)


def test_the_opposite_side_is_resolved_against_where_the_blocks_start():
    """Task 3's instances start the blocks on H, I, J: there 'the opposite' is E, F, G."""
    spec = _spec(3, "Move the three blocks to the opposite side.")
    atoms = spec.atoms()
    assert {"at(Red,E)", "at(Red,F)", "at(Red,G)"} <= atoms
    assert not any(a.endswith(("H)", "I)", "J)")) for a in atoms)


@pytest.mark.parametrize(
    ("text", "named"),
    [
        ("Transfer three blocks into the opposite gently.", "gently"),
        ("Move two blocks to region H.", "names two blocks"),
        ("Put the green block in region H.", "green"),
        ("Put the red block in region K.", "cannot use"),
        ("The red block should be placed before the blue block.", "no goal"),
        ("Put the red block in region H unless it rains.", "rains"),
        # no order is guessed: "first" names no clause here
        ("Swap the red block and the blue block. Yellow first.", "first among which"),
        ("Move the three blocks to the opposite side. Red before blue. Blue before red.", "cycle"),
        ("Move any block to region H.", "'any'"),  # one block, but which?
        # a negated order says what may not happen, not what must: not read as "blue before red"
        (
            "Move the three blocks to the opposite side; the red block must not be placed before the blue "
            "block.",
            "not",
        ),
        # 'but' before a goal may be an exception; 'all blocks but red' is one
        ("Move three blocks to the opposite side, but the red block goes to region G.", "'but'"),
        ("Move all blocks but the red block to the opposite side.", "but"),
        ("Move the three blocks next to arm a and arm b.", "next to arm a"),  # a landmark is not a place
        ("Move the three blocks to regions E, F and G, next to arm c.", "name different places"),
        ("Fill regions H, I and J with the red block and the blue block.", "as many named regions"),
        ("Move the three blocks to the opposite side while swapping their positions.", "their"),
        ("The red block comes before the blue block; swap them.", "them"),  # 'them' across a sentence
        ("Move the three blocks to the opposite side. Objects must not be placed anywhere.", "anywhere"),
        # an exchanged block that also goes elsewhere: its position is its start or that goal
        (
            "Move the red block to region H and the blue block to region I, then swap their positions.",
            "exchanged",
        ),
        ("Move the red block to region H. Then swap the red block and the blue block.", "exchanged"),
        # a place pronoun with no place named before it, a reason that states what is not modelled
        ("Do not place any object on them. Move the three blocks to the opposite side.", "them"),
        ("Because the red block is heavy, move the three blocks to the opposite side.", "heavy"),
        ("Move the blocks to the opposite side, all two of them.", "names two blocks"),
        # a scene said without the rule it gives, a heading that forbids what is not a place
        ("Move the three blocks to the opposite side. Regions H, I and J are reserved.", "reserved"),
        ("Move the three blocks to the opposite side. Forbidden: the red block.", "forbidden"),
        # a place that names a block is named as it was said, never with the reader's block marker
        ("Move the three blocks to the opposite side but leave the red block where it is.", "'where it is'"),
    ],
)
def test_what_the_rules_cannot_read_is_refused_by_name(text, named):
    with pytest.raises(HTTError, match=named) as exc:
        translate(text, instance(TASKS[1], 0, 0).as_world())
    assert "\n" not in str(exc.value)


def test_plan_json_lists_tasks_before_and_constraints(capsys):
    from nl2hltl2plan.cli.main import main

    text = TASKS[4].instruction
    assert main(["plan", text, "--world", "handover-square", "--json"]) == 2  # red does not start on G here
    assert "name different places" in capsys.readouterr().err
    text = "Put the red and blue blocks on the opposite side; the red block before the blue block. No block "
    text += "can be placed on region F during this period."
    assert main(["plan", text, "--world", "handover-square", "--json"]) == 0
    payload = json.loads(capsys.readouterr().out)
    assert payload["status"] == "solved"
    assert [t["receptacle"] for t in payload["tasks"]] == [["RegionH", "RegionI", "RegionJ"]] * 2
    assert payload["before"] == [["A", "B"]]
    assert payload["constraints"] == sorted(payload["constraints"])
    assert "until red is on H|I|J: none of drop(F)" in payload["constraints"]
    assert any(c.startswith("at once: red on H|I|J, blue on H|I|J") for c in payload["constraints"])


def test_bench_handover_plans_from_the_language_stage(tmp_path):
    """`bench handover --llm offline`: each instance is planned from the language stage's spec and judged
    against the written one; rows say language_equal; the budget is expansions."""
    import argparse

    from nl2hltl2plan.cli.bench_experiments import register
    from nl2hltl2plan.suites.handover.handover_bench import run_bench

    parser = argparse.ArgumentParser()
    register(parser.add_subparsers(dest="suite"))
    args = parser.parse_args(["handover", "-o", "d", "--llm", "offline", "--expansions", "5000"])
    assert args.llm == "offline" and args.expansions == 5000
    summary = run_bench(
        tmp_path, instances=2, task_ids=[3], picture=False, backend="offline", max_expansions=5000
    )
    assert (
        summary["specs"].startswith("language stage (offline)")
        and "5000 expansions" in summary["planner_budget"]
    )
    task3 = summary["tasks"][0]
    assert task3["language_equal"] is True and task3["success_rate"] == 1.0
    assert all(r["language_equal"] and r["expanded"] <= 5000 for r in task3["per_instance"])
    assert "language_equal" in (tmp_path / "report.md").read_text()


@pytest.mark.parametrize(("task_id", "text"), cases(LEAD_HELD_OUT))
def test_unseen_rephrasings_are_read_right_or_refused_never_misread(task_id, text):
    assert_written_spec_or_refused(task_id, text)


@SWEEP
@pytest.mark.parametrize("task_id", sorted(TASKS))
def test_h43_rounds_are_read_right_or_refused_never_misread(task_id):
    """One case per task (the sentences of a task in one loop, to keep the file fast)."""
    for text in H43_ROUNDS.get(task_id, []):
        assert_written_spec_or_refused(task_id, text)


@SWEEP
@pytest.mark.parametrize(
    ("name", "batch"),
    [
        ("lead session 9", LEAD_SESSION9),
        ("lead session 9, batch 8", LEAD_SESSION9_BATCH8),
        ("lead session 9, batch 9", LEAD_SESSION9_BATCH9),
    ],
)
@pytest.mark.parametrize("task_id", sorted(TASKS))
def test_the_leads_batches_give_the_written_specs(name, batch, task_id):
    """All 80 sentences of the lead's session-9 batches are read now (the last refusal, batch 9's "regions F,
    G and H can't have any object placed on them", since session 10): a reader change that loses one fails."""
    for text in batch.get(task_id, []):
        equal, why = specs_equivalent(_spec(task_id, text), TASKS[task_id].hierarchical())
        assert equal, (text, why)
