import itertools

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nl2hltl2plan.errors import FormulaError
from nl2hltl2plan.logic import spot_backend as sb
from nl2hltl2plan.logic.relations import check_translation, compile_relations

IV_D_CHILDREN = ["task1.1", "task1.2", "task1.3", "task1.4"]
IV_D_BEFORE = [("task1.1", "task1.2"), ("task1.1", "task1.3"), ("task1.1", "task1.4")]


def test_section_iv_d_compiled_equals_correct_and_differs_from_erroneous():
    """'First 1.1, then 1.2, 1.3, and 1.4 can be completed in any sequence' (Section IV-D)."""
    correct = "F(task1.1 & F task1.2 & F task1.3 & F task1.4)"
    erroneous = "F(task1.1 & F(task1.2 & (task1.3 & task1.4)))"
    assert check_translation(correct, IV_D_CHILDREN, IV_D_BEFORE).equivalent
    wrong = check_translation(erroneous, IV_D_CHILDREN, IV_D_BEFORE)
    assert not wrong.equivalent
    assert wrong.witness_satisfies == "reference" and "differs" in wrong.describe()


def test_single_pair_is_literally_the_paper_form():
    assert sb.parse(compile_relations(["a", "b"], [("a", "b")])) == sb.parse("F(a & F b)")


@pytest.mark.parametrize(
    "before, match",
    [([("a", "b"), ("b", "a")], "cyclic"), ([("a", "z")], "not a child"), ([("a", "a")], "itself")],
)
def test_bad_relations(before, match):
    with pytest.raises(FormulaError, match=match):
        compile_relations(["a", "b"], before)


@st.composite
def relations_and_trace(draw):
    n = draw(st.integers(1, 5))
    names = [f"c{i}" for i in range(n)]
    order = draw(st.permutations(names))  # pairs follow a random topological order: acyclic
    pairs = [(a, b) for a, b in itertools.combinations(order, 2) if draw(st.booleans())]
    # each child completes at most once, at a random step (None: never)
    steps = {c: draw(st.one_of(st.none(), st.integers(1, 4))) for c in names}
    return names, pairs, steps


@settings(max_examples=150, deadline=None)
@given(relations_and_trace())
def test_compiled_formula_holds_iff_relations_respected(case):
    names, pairs, steps = case
    dfa = sb.dfa(sb.parse(compile_relations(names, pairs)))
    horizon = max([s for s in steps.values() if s] + [1])
    word = [{c for c in names if steps[c] == t} for t in range(1, horizon + 1)]
    expected = all(steps[c] is not None for c in names) and all(steps[a] <= steps[b] for a, b in pairs)
    assert dfa.accepts(word) == expected
