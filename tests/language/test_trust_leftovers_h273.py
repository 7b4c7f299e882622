"""Session 32's trust leftovers (issue 23, h273), through the public reading path (`translate`, `plan`).

- One reader of the time a request is for (`request_times`): a later day set off at the end of a request
  ("..., tomorrow", "..., on Friday") is a start a plan made now cannot honour, refused by name; a deadline
  ("..., by tonight"), a note's leading day ("Tonight, ...") and a greeting's day ("Happy Friday!", "Have a
  lovely weekend!") are frame, as before.
- A closing state word no task makes ("..., salted") is refused by name; a treatment said as done already
  ("mug, washed already -> cabinet") or to come later ("gets cleaned later") is never read as a duty.
- Check 1: a place said after a verb that says where its subject goes ("A potato slice goes in the fridge")
  is a destination, never a landmark: a reading that swallows that sentence into the task before it (the
  carried verb's object) is not passed.
The dev set's lines (users_h273dev.txt) are swept under `-m sweep` (`test_user_styles`)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.task_specs import BaseTaskSpec
from nl2hltl2plan.language.translate import translate

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))

WINE = "place WineBottle -> Fridge"


def read(text: str, scene: str = "FloorPlan7") -> tuple[list[str], list[str], list[str]] | str:
    """(the tasks' summaries, what is left unread, the assumptions), or "refused"."""
    from trust_sets import world_of

    try:
        res = translate(text, world_of(scene), build=False, actions="none")
    except Nl2Hltl2PlanError:
        return "refused"
    return [t.summary() for t in res.tasks], res.unparsed, res.assumptions


@pytest.mark.data
@pytest.mark.parametrize(
    "text, day",
    [
        ("Put the wine bottle in the fridge, tomorrow.", "tomorrow"),
        ("Put the wine bottle in the fridge, on Friday.", "on Friday"),
    ],
)
def test_a_closing_later_day_is_refused_by_name(text: str, day: str) -> None:
    said = read(text)
    assert said != "refused"
    tasks, unparsed, assumptions = said
    assert any(u.startswith(f"'{day}' (time)") for u in unparsed), unparsed
    assert not any(day in a for a in assumptions), assumptions  # never said as dropped frame too


@pytest.mark.data
@pytest.mark.parametrize(
    "text",
    [
        "Put the wine bottle in the fridge, by tonight.",
        "Hello, robot. Tonight, put the wine bottle in the fridge.",
        "Put the wine bottle in the fridge. Have a lovely weekend!",
        "Chore chart, Saturday. Tom: put the wine bottle in the fridge.",  # a heading's day, no request's
    ],
)
def test_a_deadline_a_leading_day_and_a_greeting_stay_frame(text: str) -> None:
    assert read(text)[:2] == ([WINE], [])


@pytest.mark.data
def test_plan_refuses_a_closing_later_day_naming_it(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["plan", "Put the wine bottle in the fridge, tonight.", "--world", "FloorPlan7"]) == 2
    assert "'tonight' (time)" in capsys.readouterr().err


@pytest.mark.data
@pytest.mark.parametrize(
    "text, scene",
    [
        ("Put the potato on the counter, salted.", "FloorPlan5"),  # a state no task makes: refused by name
        ("The pan gets cleaned later; put it on the stove for now.", "FloorPlan13"),  # no duty now
    ],
)
def test_a_state_no_task_makes_now_is_never_dropped_or_done(text: str, scene: str) -> None:
    assert read(text, scene) == "refused"


@pytest.mark.data
def test_a_treatment_said_as_done_already_is_not_done() -> None:
    said = read("Quick list: mug, washed already -> cabinet; spoon -> drawer.", "FloorPlan13")
    assert said == "refused" or "clean_place Mug -> Cabinet" not in said[0] and said[1], said


# "Take the pan to the counter. A potato slice goes in the fridge.", read as a rewrite that carried the first
# sentence's verb and place over the second once did (before 42a65c5d): the slice's "goes in the fridge"
# swallowed into the object of "take ... to the counter"
SWALLOWED = "Take the pan to the counter. A potato slice goes in the fridge."
PAN = BaseTaskSpec(
    id="A", text="Take the pan to the counter", kind="place", object=["Pan"], receptacle=["CounterTop"]
)
SLICE_TO = "Take A potato slice goes in the fridge to the counter"


@pytest.mark.parametrize(
    "text, place",
    [
        (SWALLOWED, "fridge"),
        ("Take the pan to the counter. The potato slice belongs in the drawer.", "drawer"),
        ("Take the pan to the counter. A potato slice sits on the plate.", "plate"),
    ],
)
def test_check1_never_passes_a_carried_verbs_object_with_its_own_verb_and_place(text: str, place: str):
    swallowed = BaseTaskSpec(
        id="B", text=SLICE_TO, kind="place", object=["Potato"], sliced=True, receptacle=["CounterTop"]
    )
    assert any(u.words == place for u in account(text, [PAN, swallowed], [])), place
    # the reading that puts the slice there passes, and "the mug that sits on the shelf" stays a landmark
    goes = swallowed.model_copy(update={"receptacle": [place.capitalize()], "text": ""})
    assert not account(text, [PAN, goes], [])


def test_check1_keeps_a_place_said_in_a_relative_clause_a_landmark() -> None:
    mug = BaseTaskSpec(id="A", text="", kind="place", object=["Mug"], receptacle=["SinkBasin"])
    assert not account("Put the mug that sits on the shelf in the sink.", [mug], [])


@pytest.mark.data
def test_plan_refuses_the_swallowed_reading(monkeypatch: pytest.MonkeyPatch, capsys) -> None:
    """Through `plan`: with the grammar's mend undone (a slice said as the subject of "goes" loses its own
    "put" again), the reading carries "take ... to the counter" over the second sentence, and check 1
    names the fridge: exit 2, never the slice on the counter at exit 0."""
    from nl2hltl2plan.language.grammar import sentences, verbless_items

    monkeypatch.setattr(sentences, "names_holder_before", verbless_items.names_object_before)
    assert main(["plan", SWALLOWED, "--world", "FloorPlan1", "--llm", "grammar"]) == 2
    assert "'fridge' (place)" in capsys.readouterr().err
