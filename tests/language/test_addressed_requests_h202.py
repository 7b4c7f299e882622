"""Household requests wrapped in words around them (issues 23 and 28, h202): a form of address ("Sweetie,
...", "Kiddo, three jobs: ..."), the note's writer ("Mum here - ...") or addressee ("Note for Sam:"), a tag
where a sentence ends (", ta.", ", okay?"), spoken openers before an order word ("ok so first ..."), a
numbered list's markers and a heading that gives every item its place ("Everything below goes on the
desk: A, B, C") are read as the request; a negation in them is still the negation. The dev set's lines
(users_h202dev.txt) are swept under `-m sweep`."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from household_readings import full_reading

from nl2hltl2plan.language.courtesy import without_framing, without_greetings

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))


EGG, MUG = "place Egg -> Fridge", "place Mug -> SinkBasin"


def read(text: str) -> tuple[list[str], list[tuple[str, str]], list[str], list[str]]:
    from trust_sets import world_of

    return full_reading(text, world_of("FloorPlan28"))


@pytest.mark.data
@pytest.mark.parametrize(
    "text, tasks, before",
    [
        # "sweetie" was read as an action, "mum" as a person to hand things to
        ("Sweetie, the mug goes in the sink, okay? Then put the egg in the fridge.",
         [EGG, MUG], [(MUG, EGG)]),
        ("Mum here - put the egg in the fridge and the mug in the sink, ta.", [EGG, MUG], []),
        # a note's addressee and a count of jobs as its heading, then a numbered list
        ("Note for Sam: two jobs: (1) put the egg in the fridge (2) put the mug in the sink.",
         [EGG, MUG], []),
        # the frame before "could you" was left as words; "ok so" before "first" hid the order
        ("Hiya, when you get a sec could you put the egg in the fridge and the mug in the sink?",
         [EGG, MUG], []),
        ("ok so first the mug goes in the sink, then the egg goes in the fridge",
         [EGG, MUG], [(MUG, EGG)]),
    ],
)  # fmt: skip
def test_the_words_around_a_request_read_as_the_request(text, tasks, before):
    got, order, unread, forbids = read(text)
    names = dict(zip(["A", "B"], got, strict=False))
    assert (sorted(got), sorted((names[a], names[b]) for a, b in order), unread, forbids) == (
        sorted(tasks),
        before,
        [],
        [],
    )


@pytest.mark.data
def test_a_heading_gives_its_place_to_each_item_and_a_negation_stays():
    """Every item of "Everything below goes in the sink:" goes there unless it says a place of its own; a
    negation after an address and before a tag still forbids."""
    got, _, unread, _ = read("Everything below goes in the sink: the mug, then the egg in the fridge.")
    assert (sorted(got), unread) == (sorted([MUG, EGG]), [])
    got, _, unread, forbids = read("Sweetie, don't put the mug in the sink, okay? Put the egg in the fridge.")
    assert (got, unread) == ([EGG], [])
    assert forbids == ["don't put the mug in the sink: forbids put(Mug,SinkBasin)"]
    # "two jobs:" was read as the egg's count (place_two), the negation kept
    got, _, unread, forbids = read(
        "Kiddo, two jobs: put the egg in the fridge, and don't put the mug in the sink, okay?"
    )
    assert (got, unread) == ([EGG], [])
    assert forbids == ["don't put the mug in the sink: forbids put(Mug,SinkBasin)"]


def test_near_misses_stay_as_written():
    """A letter's "Love, Mom" is a sign-off; "right" after a comma may be a side, a note for a name that
    names a thing is no addressee, and a lone "(b)" or "(2 of them)" is no numbered list."""
    assert without_greetings("Put the egg in the fridge. Love, Mom", lambda name: False) == (
        "Put the egg in the fridge."
    )
    assert without_framing("put the mug on the shelf, right.") == "put the mug on the shelf, right."
    said = "Note for Apple: put it in the fridge."
    assert without_greetings(said, lambda name: name == "Apple") == said
    said = "put the mugs (2 of them) in the sink and (b) the egg"
    assert without_framing(said) == said


@pytest.mark.sweep
@pytest.mark.data
def test_h202_dev_set():
    """No line of h202's dev set is read wrong, the line to refuse is refused, and every feasible line
    converts."""
    import trust_sets

    rows = [(gt, trust_sets.outcome(gt)[0]) for gt in trust_sets.load("users_h202dev")]
    assert [gt.instruction for gt, what in rows if what == "wrong"] == []
    assert [gt.instruction for gt, what in rows if not gt.feasible and what == "converted"] == []
    assert all(what == "converted" for gt, what in rows if gt.feasible)


@pytest.mark.data
def test_a_count_of_jobs_in_the_heading_is_checked_against_the_reading() -> None:
    # the framing drops "Kiddo," and the heading with it; the heading's count must still be the tasks read
    tasks, _, unparsed, _ = read("Kiddo, two jobs: put the egg in the fridge and the mug in the sink.")
    assert tasks == [EGG, MUG] and unparsed == []
    tasks, _, unparsed, _ = read("Kiddo, three jobs: put the egg in the fridge and the mug in the sink.")
    assert any("'three jobs' (count)" in u for u in unparsed), unparsed
    # the note's count is the headings' one pattern (`headings._counted`): "we have ... to do" around it too
    said = "Kiddo, we have three jobs to do: put the egg in the fridge and the mug in the sink."
    tasks, _, unparsed, _ = read(said)
    assert any("three jobs to do" in u for u in unparsed), unparsed
