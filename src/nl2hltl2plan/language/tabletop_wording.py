"""The tabletop reading's wording rules (issue 28): what a tabletop instruction says besides its object
and plate names, read before `tabletop_pairs` pairs them.

- statements: a clause that says where something is or was ("the carrot is on the blue plate", "the
  blue plate had the carrot") is a task only under a wish or goal said before it in its sentence ("make
  sure", "I want", "should", "Final layout:", "once"); `stated_not_asked` finds the first one that is not;
- free-order remarks ("in any order", "the order is of no consequence", "whichever way round"): read,
  then removed; they leave the order inside each group free (the groups keep theirs);
- corrections: "the blue plate, sorry, the yellow plate" keeps the second name, "no wait" too;
- plurals: "the apples" / "both apples" name every object the world has with that head noun, when the
  count, if one is said, is theirs;
- labels and numbers: "Step 1: ... Step 2: ..." (or "Round one", "First course") and a numbered list
  ("1) ... 2) ...") order the steps; beside a remark that frees the whole list ("in any order", not
  "within each step, any order") the numbers only list, and "lastly" / "finally" only mark its last item;
- politeness that carries nothing: "it would please me if", "I would be grateful if you could", "let me
  see", "chop chop", "go ahead and".
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from nl2hltl2plan.language.content_words import free_order_phrase, phrase_list_pattern
from nl2hltl2plan.language.grounding import sentence_start
from nl2hltl2plan.language.statements import WHERE_VERB, asked_before

# ---- statements ---------------------------------------------------------------------------------------
# where it is: on or in a place, or "fine where it is" / "good as it is" / "fine there"
_LOCATIVE = (
    r"(?:\s+(?:on|in|onto|into|upon|inside|at)\b|\s+(?:fine|ok|okay|good|alright|all\s+right)\s+"
    r"(?:where\s+(?:it|they)\s+(?:is|are)|as\s+(?:it|they)\s+(?:is|are)|there)\b)"
)
_HOLDS = r"\s+(?:has|had|holds|held|contains|contained|carries|carried)\s+(?=(?:the|a|an|both|two)\b)"
# "please" before a state clause asks for it too: the polite frames below are read as it ("it would please
# me if X were on Y": "please X were on Y"); the other wishes, goals and references are `statements`'
_PLEASE = re.compile(r"\bplease\b")


def stated_not_asked(text: str, names: Iterable[str]) -> str | None:
    """The first clause of `text` that states where a named thing is, was or has been put with no wish or
    goal before it in its sentence ("the carrot is on the blue plate, please put ..."); None when there is
    none. `names`: the world's object and plate names, in words ("blue plate")."""
    lowered = polite_frames(text.lower())
    mention = mention_pattern(names).pattern.removesuffix(r"\b")
    state = re.compile(
        rf"{mention}(?:\s+(?:both|all|too|also))?{WHERE_VERB}{_LOCATIVE}|{mention}{_HOLDS}"
    )
    for m in state.finditer(lowered):
        if not asked_before(lowered, m.start()) and not _PLEASE.search(
            lowered, sentence_start(lowered, m.start()), m.start()
        ):
            clause_end = re.compile(r"[,.;!?]|$").search(lowered, m.end())
            return lowered[m.start() : clause_end.start() if clause_end else None].strip()
    return None


# ---- free-order remarks ---------------------------------------------------------------------------------
# the shared list (free_order.txt), anywhere in the text: "in any order", "the order is up to you", also
# with a comma between its words ("Which order, is not important", "Within each step, any order")
_FREE_ORDER = re.compile(r"\b" + free_order_phrase().replace(r"\s+", r",?\s+") + r"\b")
# a remark about the order inside each step ("within each step, any order"), which leaves the steps' own
_WITHIN_STEPS = re.compile(r"\bwithin\b")
# under a remark that frees the whole list, "lastly" / "finally" only mark its last item ("..., and, lastly,
# the red apple on the pink plate. The order doesn't matter.")
_LAST_LISTED = re.compile(r"\b(?:lastly|finally)\b\s*,?")


# a free-order remark about the last group alone: "those last two can go in any order"
_LAST_GROUP_FREE = re.compile(
    r"\b(?:and\s+)?(?:those|these|the)\s+(?:last\s+)?(?P<n>two|three|four)(?:\s+ones)?\s+(?:can|may|could)\s+"
    r"(?:go|be\s+(?:done|placed|put))\s+in\s+(?:any|either|whatever)\s+order\b"
)


def last_group_free(text: str) -> tuple[str, int | None]:
    """`text` without a free-order remark about its last group, and how many things the remark names."""
    m = _LAST_GROUP_FREE.search(text)
    if m is None:
        return text, None
    return text[: m.start()] + " " + text[m.end() :], _NUMBER_WORDS[m["n"]]


def free_order(text: str) -> tuple[str, list[str]]:
    """`text` (lowercased) without its free-order remarks, and the remarks."""
    return _FREE_ORDER.sub(" ", text), [m[0] for m in _FREE_ORDER.finditer(text)]


def frees_every_step(remarks: list[str]) -> bool:
    """Does one of the remarks free the whole list, not only the order inside each step?"""
    return any(_WITHIN_STEPS.search(r) is None for r in remarks)


def last_item_unmarked(text: str) -> str:
    """`text` without "lastly" / "finally", for a list whose order a remark frees."""
    return _LAST_LISTED.sub(" ", text)


# ---- corrections, plurals, politeness ---------------------------------------------------------------------
_CORRECTION = re.compile(
    r"^[\s,.;:!\-]*(?:(?:no|sorry|wait|oops|whoops|actually|rather|or\s+rather|i\s+mean[t]?|make\s+that|"
    r"correction|scratch\s+that|my\s+mistake|my\s+bad)\b[\s,.;:!\-]*)+(?:the\s+|a\s+|an\s+)?$"
)
_POLITE = re.compile(rf"\b{phrase_list_pattern('courtesy.txt', 'wish')}\b")  # courtesy.txt's polite wishes
_FILLER = re.compile(
    r"^\W*(?:let\s+me\s+see|let's\s+see)\b|\bchop\s+chop\b|\bfind\s+(?:below|attached|enclosed)\b|"
    r"\bgo\s+ahead\s+and\b"
)
_THE_FOLLOWING = re.compile(r"\b(?:the\s+)?following(?=\s*:)")  # a list's heading: "arrange the following:"
# an aside that only describes the thing before it: "the green apple, the nice shiny one, goes ..."
_APPOSITION = re.compile(r",\s*the\s+(?P<words>(?:[a-z]+\s+){1,3})one\s*,")
_ORDINALS = {"1st": "first", "2nd": "second", "3rd": "third", "4th": "fourth"}
# "pair" as the verb of a placement ("pair the carrot with the blue plate"), not the count "a pair of"
_PAIR_VERB = re.compile(r"\bpair(?:\s+up)?(?=\s+(?:the|a|an)\s)")


def polite_frames(text: str) -> str:
    """ "it would please me greatly if X were on Y" -> "please X were on Y": a wish, read as one."""
    return _POLITE.sub("please", text)


def plain_words(text: str, kinds: dict[str, bool], heads: dict[str, list[str]]) -> str:
    """The lowercased text with ordinals spelt out, politeness that carries nothing removed, the verb
    "pair" read as "match", corrections applied and plurals named. `kinds`: each object or plate name
    (in words) -> is it a plate; `heads`: a head noun that several objects share ("apple") -> their
    names."""
    text = re.sub(r"\b(1st|2nd|3rd|4th)\b", lambda m: _ORDINALS[m[1]], text.lower())
    text = _THE_FOLLOWING.sub("these", _FILLER.sub(" ", polite_frames(text)))
    text = _PAIR_VERB.sub("match", text)
    text = _APPOSITION.sub(lambda m: m[0] if _names_a_word(m["words"], kinds) else ",", text)
    text = corrected(text, kinds)
    return _plurals_named(text, kinds, heads)


def mention_pattern(names: Iterable[str], flags: int = 0) -> re.Pattern[str]:
    """Each name by its words ("green apple"), longest first, with a plural allowed so that a plural is
    seen (and refused) rather than missed."""
    ordered = sorted(names, key=len, reverse=True)
    alternatives = "|".join(r"\s+".join(map(re.escape, n.split())) + "s?" for n in ordered)
    return re.compile(rf"\b(?:{alternatives})\b", flags)


def corrected(text: str, kinds: dict[str, bool]) -> str:
    """A name followed by a correction marker and a name of the same kind (a plate for a plate, an object
    for an object) is replaced by it: "on the blue plate, sorry, the yellow plate" -> "on the yellow
    plate" (case kept; the names are found in any case)."""
    found = list(mention_pattern(kinds, re.IGNORECASE).finditer(text))
    for first, second in reversed(list(zip(found, found[1:], strict=False))):
        same_kind = kinds.get(_name(first[0].lower())) == kinds.get(_name(second[0].lower()))
        if same_kind and _CORRECTION.match(text[first.end() : second.start()].lower()):
            text = text[: first.start()] + text[second.start() :]
    return text


def _plurals_named(text: str, kinds: dict[str, bool], heads: dict[str, list[str]]) -> str:
    """ "the apples" / "both apples" / "the two apples" -> "the green apple and the red apple" when the
    world has several objects with that head noun and the count, if one is said, is theirs; a plural
    after a modifier ("green apples") or with another count is left (and refused)."""
    if not heads:
        return text
    modifiers = {w for n in kinds for w in n.split()[:-1]}
    counts = {"both": 2, "two": 2, "three": 3, "four": 4}
    plural = re.compile(
        r"\b(?:(?:all\s+(?:of\s+)?)?(?:the\s+)?(?P<count>both|two|three|four)\s+(?:of\s+the\s+)?|"
        rf"all\s+(?:of\s+)?the\s+|the\s+|all\s+)?(?P<head>{'|'.join(map(re.escape, heads))})s\b"
    )

    def named(m: re.Match[str]) -> str:
        before = text[: m.start("head")].split()
        said = counts.get(m["count"] or "")
        if (before and before[-1] in modifiers) or (said is not None and said != len(heads[m["head"]])):
            return m[0]
        return " and ".join(f"the {n}" for n in heads[m["head"]])

    return plural.sub(named, text)


def _names_a_word(words: str, kinds: dict[str, bool]) -> bool:
    """Does an aside use a word of a name ("the green one" could be another thing: it is left)?"""
    return not {w for n in kinds for w in n.split()}.isdisjoint(words.split())


def _name(found: str) -> str:
    return " ".join(found.split())


# ---- step labels and list numbers ----------------------------------------------------------------------
_NUMBER_WORDS = {"one": 1, "two": 2, "three": 3, "four": 4, "first": 1, "second": 2, "third": 3, "fourth": 4}
_STEP_NOUN = r"(?:step|phase|stage|part|round|course|batch)"
_LABEL = re.compile(
    rf"(?:^|(?<=[.;!?:,]))\s*(?:{_STEP_NOUN}\s*(?P<n1>\d|one|two|three|four|first|second|third|fourth)|"
    rf"(?P<n2>first|second|third|fourth)\s+{_STEP_NOUN})\s*[:.)\-]\s*"
)
_LIST_NUMBER = re.compile(r"(?:^|(?<=[\s.;!?]))\(?(?P<n>\d)[.)]\s+")


def steps_read(text: str, listed: bool) -> str | None:
    """Step labels, and bare list numbers, as "first" / "then" (numbered 1, 2, ... in turn); bare list
    numbers beside a remark that frees the whole list (`listed`: "1) ... 2) ... in any order") only list,
    and are removed. None: labels or numbers out of turn."""
    labels = list(_LABEL.finditer(text))
    if [_step_number(m["n1"] or m["n2"]) for m in labels] != list(range(1, len(labels) + 1)):
        return None
    text = _as_steps(text, labels)
    return list_numbers_read(text, listed)


def list_numbers_read(text: str, listed: bool) -> str | None:
    """A numbered list's numbers ("1) ... 2) ...") as "first" / "then", or removed when a remark frees the
    whole list (`listed`); None when they are not 1, 2, ... in turn."""
    numbers = list(_LIST_NUMBER.finditer(text))
    if [int(m["n"]) for m in numbers] != list(range(1, len(numbers) + 1)):
        return None
    if not listed:
        return _as_steps(text, numbers)
    for m in reversed(numbers):  # each item its own sentence: "1) A on P 2) B on Q" is two placements
        text = text[: m.start()] + ("" if m.start() == numbers[0].start() else ". ") + text[m.end() :]
    return text


def numbered_steps(text: str) -> str:
    """`text` with the numbers of a numbered list of two or more steps read (`list_numbers_read`: as
    "first" / "then", or removed beside a remark that frees the whole list), so that every reader orders
    the steps as the numbers do; the text as it is with no such list."""
    if len(_LIST_NUMBER.findall(text)) < 2:
        return text
    read = list_numbers_read(text, frees_every_step(free_order(text.lower())[1]))
    return " ".join(read.split()) if read is not None else text


def _as_steps(text: str, marks: list[re.Match[str]]) -> str:
    """Each step's label or number as "first" (the first one) or "then"."""
    for m in reversed(marks):
        word = " first " if m.start() == marks[0].start() else " then "
        text = text[: m.start()] + word + text[m.end() :]
    return text


def _step_number(word: str) -> int:
    return int(word) if word.isdigit() else _NUMBER_WORDS[word]
