"""Step 2 of the offline parser: clauses, and elided verbs restored."""

from nl2hltl2plan.language.offline.clauses import expand_gapping, split_clauses


def test_split_before_each_verb_with_its_joiner() -> None:
    assert split_clauses("pick up the pen and then put it in the drawer") == [
        ("pick up the pen", 0, 15, ""),
        ("put it in the drawer", 25, 45, "then"),
    ]


def test_a_sentence_without_a_second_verb_is_one_clause() -> None:
    assert [c[0] for c in split_clauses("put the pen and the pencil in the drawer")] == [
        "put the pen and the pencil in the drawer"
    ]


def test_elided_verb_comes_back_for_each_object() -> None:
    clauses = expand_gapping(
        split_clauses("put the plates in the lower rack, then the cups in the upper rack"), "", ""
    )
    assert [(c.text, c.joiner, c.gap) for c in clauses] == [
        ("put the plates in the lower rack", "", -1),
        ("put the cups in the upper rack", "then", -1),  # own destinations: no group
    ]


def test_verbless_list_takes_the_previous_verb_and_shares_the_destination() -> None:
    clauses = expand_gapping(split_clauses("first the saucers, then the cups, in the upper rack"), "put", "")
    assert [c.text for c in clauses] == [
        "put the saucers in the upper rack",
        "put the cups in the upper rack",
    ]
    assert clauses[0].gap == clauses[1].gap >= 0  # one shared destination: one group
    assert clauses[1].joiner == "then"
