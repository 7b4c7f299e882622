"""The opt-in reading counter (tests/reading_counts.py) counts repeats by value and changes no reading."""

from __future__ import annotations

import json

import reading_counts

import nl2hltl2plan.language.translate as reader
from nl2hltl2plan.worlds import demo_world

TEXT = "put the apple in the fridge"


def test_the_counter_keys_by_text_world_and_options_and_unwraps(tmp_path):
    plain, before = reader.translate(TEXT, demo_world()), reader.translate
    finish = reading_counts.install(str(tmp_path))
    try:
        counted = [reader.translate(TEXT, demo_world()) for _ in range(2)]  # two equal worlds: one key
        counted.append(reader.translate(TEXT, demo_world(), plurals="two"))
    finally:
        finish()
    assert reader.translate is before  # unwrapped
    assert all(c.model_dump() == plain.model_dump() for c in counted)
    [written] = tmp_path.glob("*.jsonl")
    rows = [json.loads(line) for line in written.read_text().splitlines()]
    assert len(rows) == 3 and len({json.dumps(r["key"]) for r in rows}) == 2
    assert rows[0]["test"].endswith("test_the_counter_keys_by_text_world_and_options_and_unwraps")
    lines = reading_counts.summary({written.stem: rows})
    assert lines[1].startswith("repeats within a process: 1 calls")
    assert lines[2] == "repeats over the run: 1 calls"
