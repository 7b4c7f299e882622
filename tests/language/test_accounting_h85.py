"""Check 1 (`accounting.account`) on words its reading uses: a second task's own treatment after an order
word, "a mug of water" (the rinse), "get me the salt and put it ..." (for whom, not where), and a place
named again as where another task's place stands ("the pan on the stove")."""

from __future__ import annotations

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.task_specs import BaseTaskSpec


def task(kind: str, obj: str, rec: str, tid: str = "A", text: str = "", **kw: object) -> BaseTaskSpec:
    return BaseTaskSpec(kind=kind, object=[obj], receptacle=[rec], id=tid, text=text, **kw)  # type: ignore[arg-type]


def unread(text: str, tasks: list[BaseTaskSpec], before: list[tuple[str, str]] | None = None) -> list[str]:
    return [u.words for u in account(text, tasks, before or [])]


def test_a_treatment_after_then_that_opens_another_task_is_that_tasks_own():
    text = "First place a heated tomato in a sink, then cook a tomato and put it into the sink."
    a = task("heat_place", "Tomato", "SinkBasin", "A", "place a heated tomato in a sink")
    b = task("heat_place", "Tomato", "SinkBasin", "B", "cook a tomato and put it into the sink")
    assert unread(text, [a, b], [("A", "B")]) == []
    # one task placed, then treated: still the opposite of what the task does
    whole = task("heat_place", "Apple", "Fridge", "A", "put the apple in the fridge, then heat it")
    assert unread("put the apple in the fridge, then heat it", [whole]) == ["then heat"]
    # the other task does another treatment: "cook" is no words of it
    cooled = task("cool_place", "Tomato", "SinkBasin", "B", "cook a tomato and put it into the sink")
    assert "then cook" in unread(text, [a, cooled], [("A", "B")])


def test_a_container_of_water_names_the_rinse():
    rinsed = [task("clean_place", "Mug", "CoffeeMachine")]
    assert unread("Put a mug of water in the coffee maker.", rinsed) == []
    assert unread("put a bowl full of water in the cupboard", [task("clean_place", "Bowl", "Cabinet")]) == []
    # water with another word, or no water at all, names no rinse
    said = unread("Put a mug with water in the cabinet.", [task("clean_place", "Mug", "Cabinet")])
    assert said == ["clean_place"]
    assert unread("put a mug in the cabinet", [task("clean_place", "Mug", "Cabinet")]) == ["clean_place"]


def test_get_me_names_for_whom_when_a_task_places_the_thing():
    salt = [task("place", "SaltShaker", "DiningTable")]
    assert unread("get me the salt and put it on the table", salt) == []
    assert unread("grab me a salt shaker and put it on the table", salt) == []
    # "bring me" hands it to the person, which no task does
    assert unread("bring me the salt and put it on the table", salt) == ["me"]
    # the thing after "me" is not what the task places
    pepper = [task("place", "PepperShaker", "DiningTable")]
    assert "me" in unread("get me the salt and put the pepper on the table", pepper)


def test_a_thing_that_is_one_tasks_place_says_where_it_is_in_another_clause():
    """The pans fill three slots, one of them a place (the knife's container): "on the stove" says where
    that pan is, though the matching gives the pans' words to a chilled pan's object slot."""
    text = (
        "Move fork into mug, move both on counter and put the knife to the pan on the stove, move the pan "
        "into the sink in any order. Once both are done, chill a pan and put it on a counter. At any time, "
        "put a cleaned pan on a counter top."
    )
    fork = BaseTaskSpec(
        kind="place_in_container", object=["Fork"], receptacle=["CounterTop"], container=["Mug"], id="A"
    )
    knife = BaseTaskSpec(
        kind="place_in_container", object=["Knife"], receptacle=["SinkBasin"], container=["Pan"], id="B"
    )
    pans = [task("cool_place", "Pan", "CounterTop", "C"), task("clean_place", "Pan", "CounterTop", "D")]
    assert unread(text, [fork, knife, *pans], [("A", "C"), ("B", "C")]) == []


def test_an_order_said_of_named_things_must_be_the_readings_order():
    """ "Prior to putting the pillows, put a vase in the safe": the vase's task first; a reading that
    orders them the other way (or not at all) leaves the words unread."""
    pillows = task("place_two", "Pillow", "Sofa", "A", count=2)
    vase = task("place", "Vase", "Safe", "B")
    text = "Put two pillows on a couch. Prior to putting the pillows, put a vase in a safe."
    assert unread(text, [pillows, vase], [("B", "A")]) == []
    assert unread(text, [pillows, vase], [("A", "B")]) == ["Prior to putting the pillows"]
    ahead = "put a vase in a safe ahead of putting the pillows on the couch"
    assert unread(ahead, [pillows, vase], [("A", "B")]) == ["ahead of putting the pillows"]
    later = "put the vase in the safe after you put the pillows on the couch"
    assert unread(later, [vase, pillows], [("A", "B")]) == []
    assert unread(later, [vase, pillows], [("B", "A")]) == ["after you put the pillows"]
    # a clause opened after a comma: "then, after putting the pencil on the desk, put the book on the bed"
    pen, pencil, book = (
        task("place", o, r, i)
        for o, r, i in [("Pen", "Drawer", "A"), ("Pencil", "Desk", "B"), ("Book", "Bed", "C")]
    )
    text = "put the pen in the drawer, then, after putting the pencil on the desk, put the book on the bed"
    assert unread(text, [pen, pencil, book], [("A", "C"), ("B", "C")]) == []
    assert unread(text, [pen, pencil, book], [("A", "B"), ("C", "B")]) == ["after putting the pencil"]


def test_an_order_under_a_negation_or_of_a_step_is_not_judged_here():
    """A negation's sentence, "after that the newspaper" (that step), and "Once finished, move the
    plunger" (the plunger is the main clause's) are judged by the other checks, not this one."""
    soap, plunger = task("place", "SoapBar", "CounterTop", "A"), task("place", "Plunger", "Cabinet", "B")
    rag = task("place", "Cloth", "Dresser", "C")
    rest = "move the plunger to the cabinet, and put a rag on the dresser."
    finished = f"Place soap on a counter. Once finished, {rest}"
    assert unread(finished, [soap, plunger, rag], [("A", "B"), ("A", "C")]) == []
    egg, apple = task("place", "Egg", "Fridge", "A"), task("place", "Apple", "Fridge", "B")
    text = "do not put the egg in the fridge before the apple is in the fridge"
    assert unread(text, [egg, apple], [("B", "A")]) == []
    pillow, paper = task("place", "Pillow", "ArmChair", "A"), task("place", "Newspaper", "Sofa", "B")
    assert (
        unread(
            "put the pillow on the armchair and after that the newspaper on the sofa",
            [pillow, paper],
            [("A", "B")],
        )
        == []
    )


def test_the_thing_and_place_after_once_pick_the_task_it_refers_to():
    """ "Once the soap is on the toilet, put a rag on the counter": after the task that puts soap on
    the toilet, not after another soap's task; "the moment" orders as "once"."""
    bottle = task("place", "SoapBottle", "Toilet", "A")
    bars = task("place_two", "SoapBar", "Cabinet", "B", count=2)
    rag = task("place", "Cloth", "CounterTop", "C")
    text = (
        "Move a soap bottle to the toilet. Put two bars of soap in a cabinet. Once the soap is on the "
        "toilet, put a rag on the counter."
    )
    assert unread(text, [bottle, bars, rag], [("A", "C")]) == []
    assert unread(text, [bottle, bars, rag], [("B", "C")]) == ["Once the soap"]
    cards, clock = (
        task("place_two", "CreditCard", "Safe", "A", count=2),
        task("examine_in_light", "AlarmClock", "", "B"),
    )
    moment = (
        "Place two credit cards in the safe. The moment the credit cards are in the safe, look at the "
        "clock under the lamp."
    )
    assert "The moment the credit cards" in unread(moment, [cards, clock])


def test_an_ordinal_of_a_place_after_a_preposition_is_no_step():
    plate, salt = task("clean_place", "Plate", "CounterTop", "A"), task("place", "SaltShaker", "Drawer", "B")
    text = "Put a clean plate on the counter. Place salt in second drawer to the left of stove."
    assert unread(text, [plate, salt]) == []
    # "second" as a step, with the two tasks unordered, is unread
    assert unread("put the clean plate on the counter and second the salt in the drawer", [plate, salt]) == [
        "second"
    ]
