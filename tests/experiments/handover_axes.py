"""Rephrasings of five Table III handover instructions built from slot tables, one table per axis a
writer varies (verb, counted group, "the opposite", preposition, order sentence, region list, touch
rule, "after all of these", empty region, "at any time", "during this period") and the clause order;
a fixed-seed sample of the combinations (tests only). `near_misses()` changes one slot's meaning."""

from __future__ import annotations

import random

VERBS = ["Move", "Put", "Place", "Transfer", "Carry", "Bring", "Take", "Get", "Relocate", "Shift"]
GROUPS = [
    "the three blocks", "all three blocks", "the 3 blocks", "each of the blocks", "every block", "the blocks",
    "all the blocks", "three blocks", "all of the blocks",
]  # fmt: skip
OPPOSITE = [
    "the opposite side", "the other side", "the opposite regions", "the far side", "the opposite",
    "the regions on the other side",
]  # fmt: skip
PREPS = ["to", "into", "onto", "over to", "across to"]
RED_BEFORE_BLUE = [
    "The red block should be placed before the blue block.",
    "Red must be placed before blue.",
    "The blue block should be placed after the red block.",
    "Place the red block before the blue block.",
    "The red block has to be put down earlier than the blue block.",
    "The red block must be placed prior to the blue block.",
    "The red one goes before the blue one.",
    "Do not place the blue block until the red block has been placed.",
    "The blue block may only be placed once the red block has been placed.",
]
GHI = [
    "regions G, H and I", "regions G, H, and I", "region G, H and I", "G, H and I", "the regions G/H/I",
    "zones G, H and I", "areas G, H and I", "region G, region H and region I",
]  # fmt: skip
TOUCH_RED_FIRST = [
    "No arm may touch the blue block until the red block has been touched.",
    "The blue block must not be touched before the red block has been touched.",
    "Only after the red block has been touched may an arm touch the blue block.",
    "The arms cannot touch the blue block until an arm has touched the red block.",
    "The red block must be picked up before the blue block.",
    "Do not pick up the blue block before the red block has been picked up.",
]
YELLOW_BACK_LAST = [
    "After all of these, put the yellow block back to region G.",
    "Finally, return the yellow block to region G.",
    "Once all this is done, place the yellow block back in region G.",
    "Lastly, move the yellow block back to region G.",
    "When everything else is done, put the yellow block back on region G.",
    "Then put the yellow block back to region G.",
]
EMPTY = ["any empty region", "any free region", "any unoccupied region", "any empty area", "empty regions"]
ANY_TIME = ["at any time", "whenever", "at any point", "in any order, at any time"]
PERIOD = [
    "during this period",
    "meanwhile",
    "in the meantime",
    "while doing so",
    "during this time",
    "throughout",
]
FGH = ["regions F, G and H", "region F, G or H", "F, G and H", "regions F, G, and H"]
YELLOW_I_THEN_G = [
    "First put the yellow block on region I, then on region G",
    "Place the yellow block on region I, then on region G",
    "Move the yellow block to region I and then to region G",
    "Put the yellow block on region I first and then on region G",
    "First move the yellow block to region I; then move it to region G",
]


def _task1(r: random.Random, order: list[str], opposite: list[str]) -> str:
    goal = f"{r.choice(VERBS)} {r.choice(GROUPS)} {r.choice(PREPS)} {r.choice(opposite)}."
    return " ".join(r.sample([goal, r.choice(order)], 2))


def _task4(r: random.Random, touch: list[str], back: list[str]) -> str:
    goal = f"{r.choice(VERBS)} {r.choice(GROUPS)} {r.choice(PREPS)} {r.choice(OPPOSITE)}."
    return f"{goal} {r.choice(touch)} {r.choice(back)}"


def _task6(r: random.Random, order: list[str], regions: list[str]) -> str:
    goal = f"{r.choice(VERBS)} {r.choice(GROUPS)} separately {r.choice(['to', 'onto', 'on', 'into', 'in'])} "
    return " ".join(r.sample([goal + r.choice(regions) + ".", r.choice(order)], 2))


def _task7(r: random.Random, order: list[str], forbidden: list[str]) -> str:
    manner = r.choice(["one after another", "one by one", "one at a time", "sequentially"])
    goal = f"{r.choice(VERBS)} {r.choice(GROUPS)} {manner} {r.choice(['to', 'onto', 'on'])} region I"
    rule = f"no object can be placed on {r.choice(forbidden)} {r.choice(PERIOD)}"
    first = r.choice(order)
    return r.choice(
        [
            f"{goal}, and {rule}. {first}",
            f"{first} {goal}; {rule}.",
            f"{goal}. {first} {rule[0].upper()}{rule[1:]}.",
        ]
    )


def _task8(r: random.Random, yellow: list[str], empty: list[str]) -> str:
    others = (
        f"{r.choice(VERBS)} the red and blue blocks {r.choice(['to', 'onto', 'into'])} {r.choice(empty)} "
    )
    others += r.choice(ANY_TIME)
    steps = r.choice(yellow)
    return r.choice(
        [f"{steps}. {others}.", f"{others}. {steps}.", f"{steps}, and {others[0].lower()}{others[1:]}."]
    )


def sample(n: int = 20, seed: int = 0) -> dict[int, list[str]]:
    """n rephrasings per task of tasks 1, 4, 6, 7 and 8, each meaning what the task says."""
    r = random.Random(seed)
    makers = {
        1: lambda: _task1(r, RED_BEFORE_BLUE, OPPOSITE),
        4: lambda: _task4(r, TOUCH_RED_FIRST, YELLOW_BACK_LAST),
        6: lambda: _task6(r, RED_BEFORE_BLUE, GHI),
        7: lambda: _task7(r, RED_BEFORE_BLUE, FGH),
        8: lambda: _task8(r, YELLOW_I_THEN_G, EMPTY),
    }
    return {task: list(dict.fromkeys(make() for _ in range(n))) for task, make in makers.items()}


def _swap(texts: list[str], a: str, b: str) -> list[str]:
    return [t.replace(a, "\0").replace(b, a).replace("\0", b) for t in texts]


def near_misses(n: int = 6, seed: int = 0) -> dict[int, list[str]]:
    """n sentences per task with one slot's meaning changed: blue before red, the touch rule reversed or
    yellow back at any time, a region swapped or left out, yellow to G before I."""
    r = random.Random(seed)
    yellow_any_time = ["At any time, put the yellow block back to region G."]
    makers = {
        1: lambda: _task1(r, _swap(RED_BEFORE_BLUE, "red", "blue"), OPPOSITE),
        4: lambda: r.choice(
            [
                _task4(r, _swap(TOUCH_RED_FIRST, "red", "blue"), YELLOW_BACK_LAST),
                _task4(r, TOUCH_RED_FIRST, yellow_any_time),
            ]
        ),
        6: lambda: _task6(r, RED_BEFORE_BLUE, ["regions G, H and J", "region G, H or J", "F, H and I"]),
        7: lambda: _task7(r, RED_BEFORE_BLUE, ["regions F and G", "region G or H", "F, G and J"]),
        8: lambda: _task8(r, _swap(YELLOW_I_THEN_G, "region I", "region G"), EMPTY),
    }
    return {task: list(dict.fromkeys(make() for _ in range(n))) for task, make in makers.items()}
