"""Issue 28 (h240): order scope decided by benchmark/ANNOTATION_GUIDE.md, the same in the grammar and in
the generator's truths (`span_order`): a leading "First X" with no then-word puts X before every later task
that is not free ("Finally Y" mirrored), once per sentence; "in whichever order" leaves a "First" list open;
"before that" covers the clauses coordinated with its own ("B, but before that C and D": both before B)."""

from __future__ import annotations

from nl2hltl2plan.language.learned.span_order import before_pairs, leading_first
from tests.language.test_unseen_classes import read

MUG = "place Mug -> SinkBasin"
APPLE = "place Apple -> Fridge"
EGG = "place Egg -> Microwave"
BREAD = "place Bread -> CounterTop"


def test_a_leading_first_with_adding_joiners_comes_before_each_later_task():
    """Before: "First A, and B, and also C" read A, B, C as a chain (the sentence's "first" on each
    clause)."""
    tasks, order, unread = read(
        "First put the apple in the fridge, and put the mug in the sink, and also put the egg in the "
        "microwave."
    )
    assert len(tasks) == 3 and not unread
    assert order == {(APPLE, MUG), (APPLE, EGG)}


def test_a_leading_first_before_an_also_sentence():
    tasks, order, unread = read("First put the apple in the fridge. Also put the mug in the sink.")
    assert len(tasks) == 2 and not unread and order == {(APPLE, MUG)}


def test_first_then_any_order_list_is_unordered():
    """Before: A, B, C ordered and "in whichever order" named as unread."""
    tasks, order, unread = read(
        "First put the apple in the fridge, put the mug in the sink and put the egg in the microwave in "
        "whichever order please."
    )
    assert len(tasks) == 3 and not unread and order == set()


def _first(text: str, relations: list[str], pairs: list[tuple[int, int]]) -> list[tuple[int, int]]:
    """`leading_first` on a text whose spans are its single capital letters."""
    spans = [(i, i + 1) for i, c in enumerate(text) if c in "XYZW"]
    return leading_first(text, spans, relations, pairs)


def test_the_generator_orders_a_leading_first_as_the_grammar_does():
    assert _first("First X, and Y, and also Z", ["START", "PAR", "PAR"], []) == [(0, 1), (0, 2)]
    assert _first("First, X. Y. At any time, Z", ["START", "BARE", "FREE"], []) == [(0, 1)]
    # "First X, then Y" / "First X. Once X is done, Y": only what the order word states
    assert _first("First X, then Y. Z", ["START", "SEQ", "BARE"], [(0, 1)]) == [(0, 1)]
    assert _first("First X. Once X is done, Y. Z", ["START", "REF", "BARE"], [(0, 1)]) == [(0, 1)]
    assert _first("Please X. Y", ["START", "BARE"], []) == []
    # "First X. Before that, Y": Y stays first; "Oh and Z": an afterthought takes no order from "first"
    assert _first("First X. Before that, Y", ["START", "PRE"], [(1, 0)]) == [(1, 0)]
    assert _first("First X. Y. Oh and Z", ["START", "BARE", "BARE"], []) == [(0, 1)]
    # a closing remark that frees the order (paper_h188dev)
    assert _first("First, X, Y, and Z. Do these in any order.", ["START", "PAR", "PAR"], []) == []


def test_before_that_covers_the_clause_coordinated_with_its_own():
    """ "B, but before that C and D" (START, PRE, PAR): C and D before B; before h240, D joined B's step."""
    assert before_pairs(["START", "PRE", "PAR"]) == [(1, 0), (2, 0)]
    assert before_pairs(["START", "PRE", "PAR", "SEQ"]) == [(0, 3), (1, 0), (2, 0)]
