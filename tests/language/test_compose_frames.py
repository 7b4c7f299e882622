"""The structure model's third training family (issue 28, h272): composed instructions in a voice's frame
(greetings, names, sign-offs, headings, numbers, times, asides, fillers), whose words lie in no span."""

from __future__ import annotations

import random

import pytest

from nl2hltl2plan.language.grounding import find_mentions
from nl2hltl2plan.language.learned.compose import Synth
from nl2hltl2plan.language.learned.compose_frames import POOLS, frame_all, framed
from nl2hltl2plan.language.learned.structure import tags_of
from nl2hltl2plan.language.task_specs import BaseTaskSpec

_TASKS = [
    BaseTaskSpec(id="A", text="", kind="place", object=["Mug"], receptacle=["SinkBasin"]),
    BaseTaskSpec(id="B", text="", kind="place", object=["Apple"], receptacle=["Fridge"]),
]


def _synth() -> Synth:
    text = "Put the mug in the sink. Then, put the apple in the fridge."
    spans = [(0, 23), (31, 58)]
    return Synth(text, spans, ["START", "SEQ"], _TASKS, [("A", "B")], "FloorPlan1", [None, None])


def test_a_frame_keeps_every_span_its_words_and_the_order() -> None:
    s = _synth()
    clauses = [s.text[a:b] for a, b in s.spans]
    for which in ("train", "held"):
        for f in frame_all([s] * 40, which, seed=3):
            assert [f.text[a:b] for a, b in f.spans] == clauses
            assert (f.relations, f.before, f.tasks) == (s.relations, s.before, s.tasks)
    # the frame's words are tagged O: only the clauses' words are in spans
    f = framed(s, "train", random.Random(0))
    words, tags = tags_of(f.text, f.spans, f.relations)
    assert len(f.text) > len(s.text) and tags.count("O") > tags_of(s.text, s.spans, s.relations)[1].count("O")
    assert [t for t in tags if t.startswith("B-")] == ["B-START", "B-SEQ"]


def test_held_out_pools_share_no_template_or_word_with_the_trained_ones() -> None:
    train, held = POOLS["train"], POOLS["held"]
    assert set(train) == set(held)  # the same kinds of part
    for kind in train:
        assert not set(train[kind]) & set(held[kind]), kind
    assert len(train["frame"]) >= 15 and len(held["frame"]) >= 10


@pytest.mark.parametrize("which", ["train", "held"])
def test_no_frame_word_names_an_object_or_place(which: str) -> None:
    # the frame must be O by the lexicon too: a frame word naming a thing would teach the CRF to drop one
    for kind, entries in POOLS[which].items():
        for entry in entries:
            assert not find_mentions(entry.replace("{", " ").replace("}", " ")), (kind, entry)
