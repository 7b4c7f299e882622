"""Issue 24, seventh round (h64): a timing or order remark in parentheses ("(at any time)", "(one after
another, red before blue)") attached to the clause before it, "in that order" after a clause that orders
its steps with "then", modal "is to" before a verb of holding ("each region is to hold one block") and "X
gets to P" (`language/handover_registers.py`). Each class has sentences of our own that must give the
written spec and near misses that must be refused or give another spec (never the written one)."""

from __future__ import annotations

import pytest
from handover_specs import assert_not_the_written_spec, assert_refused_by_name, assert_written_spec

READ = [
    # a parenthesised timing remark after a goal
    (5, "Swap the red and blue blocks, red placed first, and take yellow over to the opposite side "
     "(whenever)."),
    (8, "Put yellow on region I, then on region G; red and blue each go to any empty region (any time)."),
    (8, "First the yellow block to region I, then to G. Red and blue to any empty region (at any point)."),
    # a parenthesised order remark, alone or after a manner
    (6, "Place the three objects on regions G, H and I, one per region (red before blue)."),
    (7, "Put all three objects onto region I (one by one, red before blue); nothing on F, G or H meanwhile."),
    (1, "Move the three blocks to the opposite side (red goes before blue)."),
    # "in that order" after a clause that says "then"
    (8, "Yellow goes first to region I and then to region G, in that order; red and blue go to any empty "
     "region at any time."),
    # modal "is to" before a verb of holding
    (2, "The three blocks go onto H, I and J; every region is to hold exactly one block."),
    (6, "The three objects are to be placed on G, H and I, each region is to take only one object, and red "
     "is to be placed before blue."),
    # "is to take" before a goal's blocks is the goal itself, not a rule
    (3, "What I want you to do is to take the three pillars over to regions E, F and G beside arms a and b, "
     "and nothing may be placed on any other region."),
    # "gets to" a place
    (5, "Exchange red and blue, red first, and see that the yellow block gets to the opposite side at any "
     "time."),
    (8, "The yellow block gets to region I first and then to region G; red and blue go to any empty region "
     "at any time."),
]

REFUSED = [
    # a parenthesis that is no timing or order remark stays unread
    (5, "Exchange the red and blue blocks (red placed first) and move the yellow block to the opposite "
     "side (at noon)."),
    (7, "Place the three objects on region I (one after another, red before the lamp); nothing on F, G or "
     "H meanwhile."),
    # "in that order" with no "then" before it: which order?
    (8, "Move the yellow block to region I and region G (in that order), and the red and blue blocks to "
     "any empty region at any time."),
    # "is to hold" a count the world cannot give; "gets to" with no place after it
    (2, "The three blocks are to go onto regions H, I and J, and each region is to hold two blocks."),
    (5, "Swap the red and blue blocks, red first. Also the yellow block gets to stay, whenever."),
]

OTHER = [
    # the parenthesised order the other way round
    (6, "Place the three objects on regions G, H and I, one per region (blue before red)."),
    # "red first" in parentheses puts red before both other objects, not only before blue
    (7, "Put all three objects onto region I (one by one, red first); nothing on F, G or H meanwhile."),
]


@pytest.mark.parametrize(("task_id", "text"), READ)
def test_seventh_round_forms_give_the_written_specs(task_id, text):
    assert_written_spec(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), REFUSED)
def test_seventh_round_near_misses_are_refused(task_id, text):
    assert_refused_by_name(task_id, text)


@pytest.mark.parametrize(("task_id", "text"), OTHER)
def test_seventh_round_forms_that_say_something_else_do_not_give_the_written_spec(task_id, text):
    assert_not_the_written_spec(task_id, text)
