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


def test_run_on_commands_split_at_the_imperative_verb_after_a_whole_command() -> None:
    """Plain users leave out "and" and commas (issue 28): a clause starts at a verb after a whole command,
    "can you" mid-line is a request of its own, and "last" before a verb is "lastly"."""
    said = {
        "put the phone on the desk throw the pencil in the trash": [
            ("put the phone on the desk", ""), ("throw the pencil in the trash", "and")
        ],
        "grab the mug can you put it in the sink": [("grab the mug", ""), ("put it in the sink", "and")],
        "rinse the cloth put it in the tub last put 2 spray bottles in the cabinet": [
            ("rinse the cloth", ""),
            ("put it in the tub", "and"),
            ("put 2 spray bottles in the cabinet", "finally"),
        ],
    }
    for text, clauses in said.items():
        assert [(c[0], c[3]) for c in split_clauses(text)] == clauses, text


def test_no_run_on_split_inside_a_noun_phrase_or_a_subordinate_clause() -> None:
    for text in (
        "put the soap on the wash cloth",  # "wash" after an article: a noun
        "put a cook book on the shelf",
        "chill a slice of lettuce",  # "slice of": a noun
        "put the tv set on the stand",  # a placing without its place is not a whole command
        "put 2 keychains in the safe after you look at the vase",  # a subordinate clause's verb
        # h227: "A last put B" after one command: "A, lastly B" or "A last, then B", opposite orders
        "put the apple in the fridge last put the egg in the fridge",
        "put the cup in the sink put two in the cabinet",  # a count with no noun: two of which?
    ):
        assert len(split_clauses(text)) == 1, text


def test_run_on_commands_and_a_comma_less_list_give_their_tasks() -> None:
    from nl2hltl2plan.language.grammar import parse_instruction

    types = {"CellPhone", "Desk", "Pencil", "GarbageCan"}
    r = parse_instruction("put the phone on the desk throw the pencil in the trash", types)
    assert [(t.object, t.receptacle) for t in r.tasks] == [
        (["CellPhone"], ["Desk"]),
        (["Pencil"], ["GarbageCan"]),
    ]
    assert r.unparsed == []
    r = parse_instruction(
        "look at the remote the vase and a keychain under the floor lamp",
        {"RemoteControl", "Vase", "KeyChain", "FloorLamp"},
    )
    assert [t.object for t in r.tasks] == [["RemoteControl"], ["Vase"], ["KeyChain"]]
    # h227: a relative clause without "that" is no list item ("the remote [that] the watch is on")
    from nl2hltl2plan.language.accounting import account

    text = "look at the remote the watch is on under the floor lamp"
    r = parse_instruction(text, {"RemoteControl", "Watch", "FloorLamp"})
    assert [t.object for t in r.tasks] == [["RemoteControl"]]  # no task made of the watch
    assert any("watch" in u.words for u in account(text, r.tasks, r.before))  # named, so never exit 0
    # h227: after a destination, a thing to move starts the next item; it is never read into the place
    types = {"Watch", "Box", "KeyChain", "Sofa"}
    r = parse_instruction("put the watch in the box the keys on the sofa", types)
    assert [(t.object, t.receptacle) for t in r.tasks] == [(["Watch"], ["Box"]), (["KeyChain"], ["Sofa"])]
    r = parse_instruction("put the pan in the sink plate the egg", {"Pan", "SinkBasin", "Plate", "Egg"})
    assert [(t.object, t.receptacle) for t in r.tasks] != [(["Pan"], ["Plate"])]  # "the egg" not dropped
    assert r.unparsed


def test_a_room_is_never_the_thing_of_the_task_before() -> None:
    """h227: "clean the kitchen" after a placing named no thing; the apple was cleaned instead, at exit 0."""
    from nl2hltl2plan.language.grammar import parse_instruction

    for text in (
        "put the apple in the fridge and clean the kitchen",
        "put the apple in the fridge heat the kitchen",
    ):
        r = parse_instruction(text, {"Apple", "Fridge"})
        assert [t.kind for t in r.tasks] == ["place"], text
        assert any("kitchen" in u for u in r.unparsed), text
