"""Numbered steps of a handover instruction that a sentence right after them frees by number (issue 24):

- "Step 3 may happen at any time", "Steps 3 and 4 can be done at any time": those steps leave the sequence
  and are said after it, each "..., at any time";
- "Steps 1 to 3 may happen in any order", "The first two steps can be done in either order": the first
  steps, a run of two or more, become one sentence ("A , and B"), whose goals carry no order among them,
  and each step after them follows it in turn ("After all of these, C", "Then D");
- "The steps may happen in any order", "The order of the steps does not matter": every step, in one
  sentence, as goals in one list.

The steps are "Step N:" labels or a numbered list ("1) ...", as `split_sentences` writes "1. ..."), 1, 2,
... in turn. Anything else stays as it is, to be read or refused as before: a freeing sentence that is
not right after the steps, a number that names no step or one step twice, steps freed "in any order" that
are not the first ones (a later run, "Steps 3 and 4 in any order", stays refused), or a step that says its
own place in the order ("then", "after", "first") or speaks of the other steps' blocks too ("one block per
region", "each", "the others").
"""

from __future__ import annotations

import re

_NUMBERED = re.compile(
    r"^\s*(?:step\s+(?P<word>[1-9]|one|two|three|four|five)\s*[:.)-]|(?P<digit>[1-9])\))\s*", re.IGNORECASE
)
_NUMBER = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5}
_MAY = r"(?:(?:may|can|could)\s+(?:happen|be\s+done|be\s+carried\s+out|be\s+performed|take\s+place|come)\s+)"
_FREES = re.compile(
    r"\s*(?:(?:the\s+)?steps?\s+(?P<named>[1-9](?:\s*(?:,|,?\s*and|&)\s*[1-9])*|(?P<lo>[1-9])\s+(?:to|through|-)"
    r"\s+(?P<hi>[1-9]))|the\s+(?P<end>first|last)\s+(?P<count>two|three|four)\s+steps)\s+"
    rf"(?:{_MAY}at\s+any\s+(?P<time>time|point)|{_MAY}?in\s+(?:any|either)\s+order)\s*",
    re.IGNORECASE,
)
# "The steps may happen in any order", "the order of the steps does not matter": every step freed, the
# steps then only list the goals, which are one sentence (as goals in one list, read without an order)
_ALL_FREE = re.compile(
    r"\s*(?:(?:the|these|all(?:\s+the)?|all\s+(?:two|three|four))\s+)?steps\s+(?:may|can|could)\s+"
    r"(?:happen|be\s+done|be\s+carried\s+out|be\s+performed|come|be\s+taken)\s+in\s+any\s+order\s*"
    r"|\s*the\s+order\s+of\s+the\s+steps\s+does\s+(?:not|n't)\s+matter\s*",
    re.IGNORECASE,
)
# a step that says its own place in the order cannot be freed of it; nor can one that says something of
# the other steps' blocks too ("..., one block per region", "each", "the others"): out of its place, the
# reader would bind that to the step's own block alone
_ORDERED = re.compile(
    r"\b(?:then|after|before|first|next|finally|last|lastly|once|per|each|every|all|both|other|others|rest|"
    r"remaining|them|they|their|together|separately)\b",
    re.IGNORECASE,
)


def _number(label: re.Match[str]) -> int:
    word = label["word"] or label["digit"]
    return _NUMBER.get(word.lower()) or int(word)


def _named(frees: re.Match[str], steps: int) -> list[int]:
    """The step numbers a freeing sentence names, in the order said."""
    if frees["lo"]:
        return list(range(int(frees["lo"]), int(frees["hi"]) + 1))
    if frees["named"]:
        return [int(n) for n in re.findall(r"[1-9]", frees["named"])]
    count = _NUMBER[frees["count"].lower()]
    first = 1 if frees["end"].lower() == "first" else steps - count + 1
    return list(range(first, first + count))


def steps_freed(sentences: list[str]) -> list[str]:
    """The sentences with the steps a sentence right after them frees said as free (see the module's
    docstring); else the sentences as they are."""
    free = [i for i, s in enumerate(sentences) if _FREES.fullmatch(s) or _ALL_FREE.fullmatch(s)]
    if len(free) != 1:
        return sentences
    steps: list[str] = []
    for s in reversed(sentences[: free[0]]):  # the numbered steps right before the freeing sentence
        if _NUMBERED.match(s) is None:
            break
        steps.insert(0, s)
    labels = [m for m in map(_NUMBERED.match, steps) if m]
    if len(steps) < 2 or [_number(m) for m in labels] != list(range(1, len(steps) + 1)):
        return sentences
    texts = [_NUMBERED.sub("", s) for s in steps]
    start = free[0] - len(steps)
    if _ALL_FREE.fullmatch(sentences[free[0]]):  # every step, in the order said: nothing leaves its place
        # ("the steps" are all of them: a numbered step elsewhere leaves it open which ones)
        if any(_NUMBERED.match(s) for s in [*sentences[:start], *sentences[free[0] + 1 :]]):
            return sentences
        return [*sentences[:start], " , and ".join(texts), *sentences[free[0] + 1 :]]
    frees = _FREES.fullmatch(sentences[free[0]])
    assert frees is not None
    named = _named(frees, len(steps))
    if len(set(named)) != len(named) or not set(named) <= set(range(1, len(steps) + 1)):
        return sentences
    if any(_ORDERED.search(texts[n - 1]) for n in named):
        return sentences
    if frees["time"]:
        kept = [t for n, t in enumerate(texts, 1) if n not in named]
        said = [f"{texts[n - 1]} , at any time" for n in named]
        kept = [f"Step {i}: {t}" for i, t in enumerate(kept, 1)] if len(kept) > 1 else kept
    else:
        # a run of the first steps (or all of them): one goal of its own, then the rest in turn after it;
        # a later run is not read ("after all of these, C , and D" would put only C after the steps before)
        if len(named) < 2 or sorted(named) != list(range(1, len(named) + 1)):
            return sentences
        if any(_ORDERED.search(t) for t in texts[len(named) :]):
            return sentences
        rest = texts[len(named) :]
        kept = [" , and ".join(texts[: len(named)])]
        kept += [f"{'After all of these' if i == 0 else 'Then'}, {t}" for i, t in enumerate(rest)]
        said = []
    return [*sentences[:start], *kept, *said, *sentences[free[0] + 1 :]]
