"""The default run keeps a fixed sample of each large parametrised table; the rest is marked `sweep`."""

from __future__ import annotations

import zlib
from dataclasses import dataclass, field

import pytest
import sampled_tables


@dataclass
class Case:
    """The parts of a collected `pytest.Function` that the sampling reads and writes."""

    nodeid: str
    callspec: object
    keywords: dict = field(default_factory=dict)
    marks: list = field(default_factory=list)

    def get_closest_marker(self, name: str):
        return next((m for m in self.marks if m.name == name), None)

    def add_marker(self, mark) -> None:
        self.marks.append(mark.mark)
        self.keywords[mark.mark.name] = True


@dataclass
class Spec:
    id: str


def table(name: str, n: int, marks: tuple = ()) -> list[Case]:
    return [Case(f"tests/t.py::{name}[case {i}]", Spec(f"case {i}"), marks=list(marks)) for i in range(n)]


def swept(cases: list[Case]) -> list[str]:
    return [c.callspec.id for c in cases if "sweep" in c.keywords]


def test_a_large_table_keeps_its_first_case_and_the_cases_its_key_picks():
    big, small = table("test_big", 40), table("test_small", sampled_tables.MIN_CASES - 1)
    moved = sampled_tables.mark_sampled([*big, *small])
    kept = [c.callspec.id for c in big if "sweep" not in c.keywords]
    assert kept[0] == "case 0" and kept[1:] == [
        f"case {i}" for i in range(1, 40) if zlib.crc32(f"case {i}".encode()) % sampled_tables.EVERY == 0
    ]
    assert 1 < len(kept) < 20 and moved == 40 - len(kept) and swept(small) == []
    # the same cases again (another worker, another run): the same choice; one case more moves no other
    again = table("test_big", 41)
    sampled_tables.mark_sampled(again)
    assert swept(again)[: len(swept(big))] == swept(big)


def test_whole_tables_and_cases_already_in_sweep_are_left_as_they_are():
    whole = table("test_whole", 30, marks=(pytest.mark.whole.mark,))
    sampled_tables.mark_sampled(whole)
    assert swept(whole) == []
    mixed = table("test_mixed", 30)
    for case in mixed[: 30 - sampled_tables.MIN_CASES + 1]:  # 19 cases left: under the size
        case.keywords["sweep"] = True
    assert sampled_tables.mark_sampled(mixed) == 0
