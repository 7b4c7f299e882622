"""Step 2 of the offline parser: clauses, and elided verbs restored."""

from nl2hltl2plan.language.grammar.clauses import expand_gapping, split_clauses


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


def test_a_stated_rule_is_not_read_as_an_elided_object_list() -> None:
    """ "The arm cannot touch the blue block until ..." after "Transfer ... into ..." states a rule; it must
    not borrow the previous verb and become a task (which then got an invented order)."""
    from nl2hltl2plan.language.grammar import parse_instruction

    r = parse_instruction(
        "Transfer the boxes into the opposite regions. The robot arm cannot touch blue block until any of "
        "the robot arm touched the red block. After all of these, place yellow block back to region G."
    )
    assert [t.object for t in r.tasks] == [["Box"], ["YellowBlock"]]  # no task made of the rule
    assert r.before == [("A", "B")]  # "after all of these" is a real order
    assert any("cannot touch" in u for u in r.unparsed)  # the rule is reported, not guessed
