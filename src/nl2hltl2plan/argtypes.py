"""argparse value types that refuse bad numbers before any work starts: nan, inf, 0, negatives, and
anything past an upper bound (every count and time option is bounded, so no typo runs for days).

>>> int_in(1, 8)("3"), seconds("2.5"), ints_in(1, 64)("1,2,4")
(3, 2.5, [1, 2, 4])
>>> int_in(1, 8)("9")
Traceback (most recent call last):
argparse.ArgumentTypeError: expected a whole number from 1 to 8, got '9'
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable

from nl2hltl2plan.config import MAX_SECONDS

MAX_SEED = 2**32 - 1  # numpy's seeds
MAX_ROBOTS = 64  # a team's size: far above the paper's (4) and the planner's practical range


def _whole(text: str) -> int:
    """An int written in ASCII digits (int() also takes '٣' and '1_0'; '²' passes isdigit but not int)."""
    s = text.strip()
    body = s[1:] if s[:1] in "+-" else s
    if not body or not body.isascii() or not body.isdigit():
        raise argparse.ArgumentTypeError(f"expected a whole number, got {text!r}")
    return int(s)


def int_in(lo: int, hi: int) -> Callable[[str], int]:
    """A whole number in [lo, hi]."""

    def parse(text: str) -> int:
        value = _whole(text)
        if not lo <= value <= hi:
            raise argparse.ArgumentTypeError(f"expected a whole number from {lo} to {hi}, got {text!r}")
        return value

    parse.__name__ = f"whole number {lo}..{hi}"  # argparse names the type in some messages
    return parse


def ints_in(lo: int, hi: int, max_items: int = 64) -> Callable[[str], list[int]]:
    """Comma-separated whole numbers in [lo, hi], e.g. 1,2,4 (at most `max_items` of them)."""
    one = int_in(lo, hi)

    def parse(text: str) -> list[int]:
        parts = [x for x in text.split(",") if x.strip()]
        if not parts:
            raise argparse.ArgumentTypeError(f"expected comma-separated whole numbers, got {text!r}")
        if len(parts) > max_items:
            raise argparse.ArgumentTypeError(f"expected at most {max_items} numbers, got {len(parts)}")
        try:
            return [one(x) for x in parts]
        except argparse.ArgumentTypeError:
            raise argparse.ArgumentTypeError(
                f"expected comma-separated whole numbers from {lo} to {hi}, got {text!r}"
            ) from None

    parse.__name__ = f"list of whole numbers {lo}..{hi}"
    return parse


def seconds(text: str) -> float:
    """A time limit: a finite number of seconds > 0 and at most a week (refuses nan, inf, 0, negatives)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number of seconds, got {text!r}") from None
    if not math.isfinite(value) or not 0 < value <= MAX_SECONDS:
        raise argparse.ArgumentTypeError(
            f"expected a number of seconds > 0 and at most {MAX_SECONDS:g} (a week), got {text!r}"
        )
    return value


seed = int_in(0, MAX_SEED)
seed.__name__ = "seed"
