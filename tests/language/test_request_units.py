"""The request-unit classifier (issue 28, h287; `learned/request_units.py`): a message's units (lines,
sentences, labels) as REQUEST or FRAME, and the household reader dropping the units it is sure are FRAME
and that name nothing check 1 asks about (on by default; NL2HLTL2PLAN_REQUEST_UNITS=0 turns it off)."""

from __future__ import annotations

import random
import re
import time

import pytest

from nl2hltl2plan.config.reading_settings import REQUEST_UNITS_ENV
from nl2hltl2plan.errors import Nl2Hltl2PlanError
from nl2hltl2plan.language.learned import request_units as ru
from nl2hltl2plan.language.learned.slot_model import packaged_path
from tests.language.test_household_frames_h244 import EGG, MUG, REQUEST, read

VOICED = f"Hi Priya! {REQUEST} Ollie here."


def test_a_message_splits_into_lines_sentences_and_labels() -> None:
    text = "Note 3: put the mug in the sink. Then heat it.\nThanks,\nMum"
    assert [text[a:b] for a, b in ru.units(text)] == [
        "Note 3:", "put the mug in the sink.", "Then heat it.", "Thanks,", "Mum"
    ]


def test_the_model_tells_a_frame_sentence_from_a_request() -> None:
    text = "Lovely weather today. Put the mug in the sink. Thanks a lot!"
    p = ru.load_request_model().frame_probability(text, ru.units(text))
    assert p[0] >= ru.THRESHOLD and p[2] >= ru.THRESHOLD and p[1] < 0.5


def test_set_off_the_text_is_unchanged(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(REQUEST_UNITS_ENV, "0")
    assert ru.frames_classified(VOICED, frozenset(), []) == VOICED
    monkeypatch.delenv(REQUEST_UNITS_ENV)  # the default (on)
    assert ru.frames_classified(VOICED, frozenset(), []) != VOICED


def test_the_setting_reads_yes_and_no_and_refuses_anything_else(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(REQUEST_UNITS_ENV, "false")
    assert ru.frames_classified(VOICED, frozenset(), []) == VOICED
    monkeypatch.setenv(REQUEST_UNITS_ENV, "true")
    assert ru.frames_classified(VOICED, frozenset(), []) != VOICED
    monkeypatch.setenv(REQUEST_UNITS_ENV, "sometimes")
    with pytest.raises(Nl2Hltl2PlanError, match=f"^{REQUEST_UNITS_ENV} must be 1 or 0"):
        ru.frames_classified(VOICED, frozenset(), [])


@pytest.mark.parametrize(
    "text, kept",
    [
        (f"{REQUEST} Do them in that order. Cheers, Kofi", "Do them in that order."),  # an order said
        (f"Hi Sam! {REQUEST} Two more tomorrow.", "Two more tomorrow."),  # a count
        # a name said again
        ("Leo: put the egg in the fridge. Mia: put the mug in the sink. Leo first.", "Mia:"),
    ],
)
def test_a_unit_that_names_content_is_never_dropped(
    monkeypatch: pytest.MonkeyPatch, text: str, kept: str
) -> None:
    monkeypatch.setenv(REQUEST_UNITS_ENV, "1")
    assert kept in ru.frames_classified(text, frozenset({"egg", "mug", "fridge", "sink"}), [])


@pytest.mark.data
def test_on_a_voiced_line_reads_and_says_what_it_dropped(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(REQUEST_UNITS_ENV, "0")
    assert read(VOICED)[2]  # off: the greeting and the writer's "Ollie here." are left unread
    monkeypatch.setenv(REQUEST_UNITS_ENV, "1")
    tasks, before, unparsed, assumptions = read(VOICED)
    assert (tasks, before, unparsed) == ([EGG, MUG], [("A", "B")], [])
    assert any("'Hi Priya'" in a and "'Ollie here'" in a for a in assumptions), assumptions


def test_no_frame_sentence_pool_names_content() -> None:
    """No pool entry names an object, action, count, negation or order by the lexicon (a frame sentence
    the model learns as FRAME must be one check 1 would let go)."""
    named = {"thing", "verb", "count", "noun", "negation", "order"}
    pools = ru._sentence_pools()
    for which in ("train", "held"):
        for entries in (e for kind, e in pools[which].items()):
            assert not [e for e in entries if ru._kinds(re.sub(r"\{\w+\}", "", e)) & named], which
        rng = random.Random(0)
        assert not [s for s in (ru.frame_sentence(which, rng) for _ in range(50)) if ru._kinds(s) & named]


def test_held_pools_share_no_entry_with_train_pools() -> None:
    pools = ru._sentence_pools()
    for kind, entries in pools["held"].items():
        if kind != "sentence":
            assert not set(entries) & set(pools["train"].get(kind, [])), kind


def test_the_artifact_is_small_and_loads_fast() -> None:
    path = packaged_path(ru.ARTIFACT)
    assert path.stat().st_size < 1_000_000
    t0 = time.perf_counter()
    ru.RequestModel.load(path)
    assert time.perf_counter() - t0 < 0.2
