"""The structure model's second training family (issue 28, h193): connectives and numbered lists the
first lacks, and clause voices ("do the same with X", "put it ...", "X goes in Y", landmarks), with the
structured reading that gives a "do the same" span its words back."""

from __future__ import annotations

import random
import re

import pytest

from nl2hltl2plan.language.learned import parse_instruction
from nl2hltl2plan.language.learned.compose import HELDOUT_STYLE, TRAIN_STYLE, Synth, synthesise
from nl2hltl2plan.language.learned.compose_refs import DEV_REFS, HELDOUT_REFS, NEW_REFS
from nl2hltl2plan.language.learned.compose_voices import VOICE_STYLE, listed
from nl2hltl2plan.language.learned.structured import resolved
from nl2hltl2plan.language.learned.train import text_faithful_items
from nl2hltl2plan.language.task_specs import BaseTaskSpec


def _words(template: str) -> str:
    return re.sub(r"\{\w+\}", "_", template.lower()).strip(" .,;:-")


def _templates(style) -> set[str]:  # type: ignore[no-untyped-def]
    out = {_words(t) for ts in style.joiners.values() for t in ts} | {_words(t) for t in style.openers}
    out |= {_words(t) for ts in style.endings.values() for t in ts}
    return out | {_words(t) for t, _ in style.pairs}


def test_the_voices_are_new_connectives_and_none_is_a_validation_phrasing() -> None:
    mine = _templates(VOICE_STYLE) - {"_"}
    assert len(mine) >= 10 + 10  # at least ten the composer lacked, with margin
    assert not mine & _templates(TRAIN_STYLE)
    assert not mine & _templates(HELDOUT_STYLE)
    for family in (NEW_REFS, HELDOUT_REFS, DEV_REFS):  # the validation families of references
        held = {_words(t) for group in vars(family).values() if isinstance(group, tuple) for t in group}
        assert not mine & held


def test_a_numbered_list_is_a_sequence_whose_spans_are_the_clauses() -> None:
    clauses = ["put the mug in the sink", "put the apple in the fridge", "heat the egg"]
    for seed in range(8):
        text, spans, rels, _ = listed(clauses, random.Random(seed))
        assert [text[a:b] for a, b in spans] == clauses
        assert rels == ["START", "SEQ", "SEQ"]
        assert re.search(r"\b(2|Second)\b", text)  # numbered, not only joined


def _voiced() -> list[Synth]:
    return synthesise(text_faithful_items("valid_unseen"), 120, VOICE_STYLE, seed=5, said_only=False)


def test_voices_rewrite_clauses_and_keep_their_truth() -> None:
    made = _voiced()
    texts = [s.text.lower() for s in made]
    assert any(re.search(r"\bsame (with|for) the\b", t) for t in texts)
    assert any(" goes " in t for t in texts)
    assert any(re.search(r"\b(next to|near|beside) the\b", t) for t in texts)
    for s in made:
        for (a, b), t in zip(s.spans, s.tasks, strict=False):
            span = s.text[a:b].lower()
            if re.match(r"^(do )?(the )?same (with|for)", span):
                prev = s.tasks[s.tasks.index(t) - 1]
                assert (t.kind, t.receptacle) == (prev.kind, prev.receptacle)  # the task before, its thing
    # the first family is untouched: the same seed composes the same instructions as before the voices
    plain = synthesise(text_faithful_items("valid_unseen"), 30, TRAIN_STYLE, seed=5)
    assert not any(re.search(r"\bsame (with|for) the\b| goes (in|on) the", s.text.lower()) for s in plain)


def test_a_do_the_same_span_gets_the_task_before_for_its_thing() -> None:
    task = BaseTaskSpec(id="A", text="", kind="place", object=["Mug"], receptacle=["SinkBasin"])
    before = ("put the mug in the sink", task)
    assert resolved("do the same with the cup", before) == "Put the cup in the sink"
    # near miss: a span that says its own task is left as it is
    assert resolved("put the cup in the fridge", before) == "put the cup in the fridge"


@pytest.mark.sweep  # reads the train split's annotations (2 s)
def test_the_second_family_is_trained_only_when_asked() -> None:
    from nl2hltl2plan.language.learned.structure_train import training_data

    plain, voiced = training_data(40), training_data(40, voices=5000)
    assert len(voiced) == len(plain) + 20 and [s.text for s in voiced[:40]] == [s.text for s in plain]
    assert not any(re.search(r"\b(same (with|for) the|goes (in|on) the)\b", s.text.lower()) for s in plain)


def test_a_do_the_same_sentence_reads_as_the_task_before_for_its_thing() -> None:
    # the committed CRF cuts "do the same with the cup" as a span, and its reading (`resolved`) agrees
    # with the grammar's (`grammar.repeats`), so the arbitration keeps it
    p = parse_instruction(
        "Put the mug in the sink. Then do the same with the cup.", {"Mug", "Cup", "SinkBasin", "Sink"}
    )
    assert [(t.kind, t.object, t.receptacle) for t in p.tasks] == [
        ("place", ["Mug"], ["SinkBasin"]),
        ("place", ["Cup"], ["SinkBasin"]),
    ]
    assert p.before == [("A", "B")] and not p.unparsed
