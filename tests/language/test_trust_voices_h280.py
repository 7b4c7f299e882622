"""Session 33's trust bugs found by h270's held-out tabletop voices (issue 23, h280), through `plan`.

- A sentence (or a part set off by a comma) in which the reader knows no word and some word no list of
  English knows ("Rien ne va plus.", "Zorblax quing.") is never read as nothing: it is refused by name
  (`unknown_words.foreign_sentences`); only the frame rule drops a sentence, and it lists what it drops.
- A refusal for a thing the world lacks names the words and the sentence it came from ("Check your
  mirrors and off you go"), where the word is not the type's own name or the text says more than one
  sentence (`missing_where.named_where`).
- A handover refusal quotes the user's words: "as follows" and an imperative "Follow me" are not
  rewritten to "comes after", and a word no rewrite of the user's own made is never named."""

from __future__ import annotations

import pytest

from nl2hltl2plan.cli.main import main

GOAL = "Move the green apple onto the blue plate."


def plan(capsys: pytest.CaptureFixture[str], text: str, world: str = "tabletop") -> tuple[int, str]:
    rc = main(["plan", text, "--world", world])
    return rc, capsys.readouterr().err


@pytest.mark.parametrize("said", ["Rien ne va plus", "Zorblax quing"])
def test_a_sentence_of_unknown_words_is_refused_by_name(capsys, said):
    rc, err = plan(capsys, f"{GOAL} {said}.")
    assert rc == 2 and f"'{said}' (words)" in err


def test_a_known_courtesy_or_frame_is_still_planned(capsys):
    rc, _ = plan(capsys, f"{GOAL} Thx!")
    assert rc == 0
    rc, _ = plan(capsys, f"{GOAL} Best of luck!")
    assert rc == 0


def test_a_missing_thing_names_the_sentence_it_came_from(capsys):
    rc, err = plan(capsys, f"{GOAL} Check your mirrors and off you go.")
    assert rc == 2 and "no Mirror (for 'mirrors' in 'Check your mirrors and off you go') in tabletop" in err


def test_a_missing_thing_said_as_its_name_alone_keeps_the_short_message(capsys):
    rc, err = plan(capsys, "put the mirror on the blue plate")
    assert rc == 2 and "error: no Mirror in tabletop" in err


@pytest.mark.parametrize(
    "frame, words",
    [
        ("Next stage, notes as follows.", "'notes', 'as', 'follows'"),
        ("Follow me down.", "'follow', 'me', 'down'"),
    ],
)
def test_a_handover_refusal_quotes_the_users_words(capsys, frame, words):
    rc, err = plan(capsys, f"{frame} Move all three blocks to the opposite side.", "handover-line")
    assert rc == 2 and f"cannot use {words} in" in err and "comes" not in err
