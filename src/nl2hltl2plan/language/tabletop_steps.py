"""Step labels and list numbers of a tabletop instruction (issue 28), read before `tabletop_pairs` pairs
objects and plates: "Step 1: ... Step 2: ..." (or "Round one", "First course") and a numbered list ("1)
... 2) ...") order the steps, as "first" / "then"; beside a remark that frees the whole list ("in any
order", not "within each step, any order") the numbers only list, and so do step labels where each step is
one placement ("Method: Step 1 - A on P. Step 2 - B on Q. Either step may come first."); labels out of turn
("Part 2: ... Part 1: ...") are named, so that no reading orders the steps by where they are written.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from nl2hltl2plan.language.content_words import free_order_remarks, phrase_list_pattern
from nl2hltl2plan.language.headings import heading_pattern, heading_words
from nl2hltl2plan.language.tabletop_freed_steps import runs_freed
from nl2hltl2plan.language.tabletop_wording import NUMBER_WORDS, free_order, frees_every_step

# ("First delivery round:": one word may name the round, h267)
# a label's place in turn: a digit, a number word or an ordinal (a step noun's also with a comma after it:
# "step one, ...; step two, ..."), or (with a colon or bracket after it, so
# that an article or "I" is not one) a letter or a roman numeral ("Part A:", "Phase II)")
_LETTERS = {"a": 1, "b": 2, "c": 3, "d": 4, "i": 1, "ii": 2, "iii": 3, "iv": 4}
_STEP_NOUN = heading_pattern("step_label")  # the nouns of a step label (`heading_heads.txt`)
_TURN = (
    r"(?:(?P<n1>\d|one|two|three|four|first|second|third|fourth)\s*[:.)\-,]|(?P<l1>[a-d]|i{1,3}|iv)\s*[:)])"
)
_LABEL = re.compile(
    rf"(?:^|(?<=[.;!?:,]))\s*(?:{_STEP_NOUN}\s*{_TURN}|(?P<n2>first|second|third|fourth)\s+(?:[a-z]+\s+)?{_STEP_NOUN}"
    r"\s*[:.)\-])\s*",
    re.IGNORECASE,
)
_NOUN_LABEL = re.compile(
    r"(?:^|(?<=[.;!?:,]))\s*(?P<noun>[a-z]+)\s+(?:(?P<n1>\d|one|two|three|four)\s*[:.)\-]|(?P<l1>[a-d]|i{1,3}|iv)"
    r"\s*[:)])(?P<n2>)\s*",
    re.IGNORECASE,
)
# "1) ...", "2. ...", "a) ... b) ..." one a line (a letter with a bracket opening a sentence, so that no
# article is one; "Method: a) ...; b) ... Steps a and b ..." is another reader's), or a number word with a
# comma opening a sentence ("One, ...; two, ...")
_LIST_NUMBER = re.compile(
    r"(?:^|(?<=[\s.;!?]))\(?(?P<n>\d)[.)]\s+|(?:^|(?<=[.!?])|(?<=[.!?]\s))(?P<l>[a-dA-D])\)\s+"
    r"|(?:^|(?<=[.;!?])|(?<=[.;!?]\s))(?i:(?P<w>one|two|three|four)),\s+"
)
# "Plan A: ... Plan B: ...", "Option 1: ...": alternatives, no steps (`tabletop_pairs` refuses them)
_ALTERNATIVE_NOUNS = heading_words()["alternative_label"]
# "Goal 1: ... Goal 2: ...", "Requirement 2:": a spec sheet's identifiers, which list and never order (as the
# handover reader reads them): no step labels (left unread, so refused); "Objective I) ... Objective II)"
# orders its groups (a decision of test_tabletop_pairs)
_NOT_STEPS = _ALTERNATIVE_NOUNS | frozenset("goal requirement constraint".split())


# a label's reference back to another label: ", only after round A", "(after goal 1)", "(once goal 1 is
# done)"; one rule for every label (`_names_the_one_before`). What it adds differs: step labels order
# already, so each reference to the step before is dropped (`label_references_dropped`); a spec sheet's
# identifiers only list, so their order is said only where every one names the one before it
# (`identifiers_chained_read`)
_REFERENCE = (
    r"(?:,|\()\s*(?:but\s+)?(?:only\s+)?(?:after|once|following)\s+(?P<noun2>[a-z]+)\s+(?P<b>\w+)"
    r"(?:\s+is\s+(?:done|finished|complete|completed|over|in))?\s*\)?"
)
# "Round B, only after round A:", "Batch two (after batch one):", "Chapter two, only after chapter one:": a
# label that names the label before it (the same noun, one back in turn) says the order the labels say already
_REFERS_BACK = re.compile(
    rf"(?P<label>(?P<noun>[a-z]+)\s+(?P<t>\w+))\s*{_REFERENCE}\s*(?=[:.)\-])", re.IGNORECASE
)


# "Stage two, only when both of those are in:", "Phase 2, once they are all there:": a later label's
# condition that what was placed just before is in restates the order the labels say already (h220); so
# does one said with the label's own verb and a voice's participle ("Quarter two opens only after both are
# booked:", h267)
_GROUP_DONE = re.compile(
    r"(?P<label>(?:[a-z]+)\s+(?P<t>\w+))(?:\s*,\s*|\s+(?:opens|starts|begins|comes)\s+)(?:but\s+)?(?:only\s+)?"
    r"(?:when|once|after|as\s+soon\s+as)\s+"
    r"(?:both|all|the\s+two|they)(?:\s+of\s+(?:those|them|these))?\s+(?:are|have\s+been|'re)\s+"
    r"(?:both\s+|all\s+)?(?:in|there|done|placed|in\s+place|[a-z]+ed)\s*(?=[:.)\-])",
    re.IGNORECASE,
)


# "The first batch is A and B, into P. The second batch is C and D, into Q, after the first batch.": a stage
# named by its ordinal opening a sentence is a label ("First batch: ...") where two or more of one noun are in
# turn; in a later stage, a reference to the one just before it ("after the first batch", "once the first
# batch is in") says the order the labels say already, and is dropped (any other stays, to be refused)
_ORDINAL_STAGE = re.compile(
    rf"(?:^|(?<=[.;!?]))(?P<lead>\s*)the\s+(?P<n>first|second|third|fourth)\s+(?P<noun>{_STEP_NOUN})"
    r"(?:\s+(?:is|are)\s+|\s*[,:]\s*|\s+[-–—]\s+)",
    re.IGNORECASE,
)
_ORDINAL_BACK = re.compile(
    rf"\s*,?\s*(?:but\s+)?(?:only\s+)?(?:after|once|following)\s+the\s+(?P<b>first|second|third)\s+"
    rf"(?P<noun2>{_STEP_NOUN})(?:\s+(?:is|are|has\s+been)\s+(?:done|in|finished|complete|completed|over))?"
    r"(?=\s*[,.;!?]|\s*$)",
    re.IGNORECASE,
)


# "Warm-up: A and B on P. Main event: C and D on Q.": an opening stage and one that follows it, named by
# their place (`tabletop_stages.txt`), as labels in turn; the later one's reference back to the opening one
# ("Main event, only after the warm-up:") says the order they say already
_OPENING = phrase_list_pattern("tabletop_stages.txt", "opening")
_FOLLOWING = phrase_list_pattern("tabletop_stages.txt", "following")
_NAMED_STAGE = re.compile(
    rf"(?:^|(?<=[.;!?]))\s*(?:the\s+)?(?:(?P<open>{_OPENING})|{_FOLLOWING})"
    rf"(?P<back>\s*,\s*(?:but\s+)?(?:only\s+)?(?:after|once|following)\s+the\s+{_OPENING}"
    r"(?:\s+is\s+(?:done|over|finished))?)?\s*(?::|\s[-–—]\s)\s*",
    re.IGNORECASE,
)


def named_stages_read(text: str) -> str:
    """ "Warm-up: A. Main event: B." -> "Stage 1: A. Stage 2: B." where one opening stage and one that
    follows it are named, in that order, and only the later one looks back; the text as it is otherwise."""
    marks = list(_NAMED_STAGE.finditer(text))
    if [bool(m["open"]) for m in marks] != [True, False] or marks[0]["back"]:
        return text
    for turn, m in reversed(list(enumerate(marks, 1))):
        text = text[: m.start()] + f" Stage {turn}: " + text[m.end() :]
    return text.strip()


def ordinal_stages_read(text: str) -> str:
    """ "The first batch is A. The second batch is B, after the first batch." -> "First batch: A. Second
    batch: B." (see `_ORDINAL_STAGE`); the text as it is unless two or more such stages of one noun are in
    turn."""
    marks = list(_ORDINAL_STAGE.finditer(text))
    turns = [NUMBER_WORDS[m["n"].lower()] for m in marks]
    nouns = {m["noun"].lower() for m in marks}
    if len(marks) < 2 or turns != list(range(1, len(marks) + 1)) or len(nouns) > 1:
        return text

    def back(turn: int) -> Callable[[re.Match[str]], str]:
        def dropped(r: re.Match[str]) -> str:
            return "" if NUMBER_WORDS[r["b"].lower()] == turn - 1 and r["noun2"].lower() == noun else r[0]

        return dropped

    noun = marks[0]["noun"].lower()
    ends = [m.start() for m in marks[1:]] + [len(text)]
    out = text[: marks[0].start()]
    for turn, (m, end) in enumerate(zip(marks, ends, strict=True), 1):
        body = text[m.end() : end]
        body = _ORDINAL_BACK.sub(back(turn), body) if turn > 1 else body
        out += f"{m['lead']}{m['n']} {m['noun']}: {body}"
    return out


# "Step 1 (any order):", "Stage one, in either order:", "Step 2, after step 1 (any order):": a label that
# frees the order inside its own step (h229); read as "within each step, any order" where every step label
# says so, and left (refused) where only some do
_LABEL_FREED = re.compile(
    rf"(?:^|(?<=[.;!?:\n]))(?P<label>\s*{_STEP_NOUN}\s+\w+(?:\s*,\s*(?:only\s+)?(?:after|once|following)\s+"
    rf"{_STEP_NOUN}\s+\w+)?)\s*(?:,\s*|\(\s*)(?P<remark>(?:in\s+)?(?:any|either|whatever|whichever)\s+order)"
    r"\s*\)?\s*(?=:)",
    re.IGNORECASE,
)
_STEP_OPENS = re.compile(
    rf"(?:^|(?<=[.;!?:\n]))\s*{_STEP_NOUN}\s+(?:\d|one|two|three|four|first|second|third|fourth|[a-d]|i{{1,3}}|iv)\b",
    re.IGNORECASE,
)


def label_remarks_read(text: str) -> str:
    """ "Step 1 (any order): A. B. Step 2 (any order): C. D." -> "Step 1: A. B. Step 2: C. D. Within each
    step, any order." where every step label frees its own step and each remark is a free-order remark."""
    freed = [m for m in _LABEL_FREED.finditer(text) if free_order(m["remark"].lower())[1]]
    if not freed or len(freed) != len(_STEP_OPENS.findall(text)):
        return text
    for m in reversed(freed):
        text = text[: m.start()] + m["label"] + text[m.end() :]
    text = text.rstrip()
    return text + ("" if text.endswith((".", "!", "?")) else ".") + " Within each step, any order."


def _names_the_one_before(noun: str, turn: int | None, reference: re.Match[str]) -> bool:
    """Does the reference (`noun2`, `b` of `_REFERENCE`) of the label `noun` at place `turn` name the label
    just before it: the same noun, one back in turn ("Round B, only after round A", "Goal 2 (after goal
    1)", "step 2 starts after step 1")?"""
    same_noun = noun.lower() == reference["noun2"].lower()
    return same_noun and turn is not None and _place_in_turn(reference["b"]) == turn - 1


# a remark after the labelled or numbered steps that confirms the order they give: "Please keep that
# sequence.", "Follow that order.", "In this order, please." (`_KEEP`); or that restates one step after the
# one before it, "Constraint: step 2 starts after step 1 is done." (`_STEP_AFTER`, the same noun, one back)
_SENTENCE_START = r"(?:^|(?<=[.;!?]))\s*"
_KEEP = re.compile(
    rf"{_SENTENCE_START}(?:please\s+)?(?:(?:keep|follow|stick\s+to|respect|maintain|observe|go\s+in|do\s+"
    r"(?:it|them|this|these|everything)\s+in)\s+(?:that|this|the\s+(?:same|given|above|listed|numbered))\s+"
    r"(?:order|sequence)|in\s+(?:that|this)\s+(?:order|sequence))(?:\s*,?\s*please)?\s*(?:[.!]+|$)",
    re.IGNORECASE,
)
_STEP_AFTER = re.compile(
    rf"{_SENTENCE_START}(?:(?:constraint|rule|note|order(?:ing)?|sequence)\s*:\s*)?(?P<noun>{_STEP_NOUN})\s+"
    r"(?P<t>\w+)\s+(?:(?:only|must|should|can|may)\s+)*(?:(?:starts?|begins?|comes?|goes|go|happens?|is\s+done|"
    r"be\s+done)\s+)?(?:only\s+)?(?:after|once)\s+(?P<noun2>[a-z]+)\s+(?P<b>\w+)(?:\s+(?:is|has\s+been)\s+"
    r"(?:done|finished|complete|completed|over))?\s*(?:[.!]+|$)",
    re.IGNORECASE,
)


def _place_in_turn(word: str) -> int | None:
    word = word.lower()
    return int(word) if word.isdigit() else NUMBER_WORDS.get(word, _LETTERS.get(word))


# a spec sheet's identifier ("Goal 2 (after goal 1):", "Goal 1 - ..."), with the reference back it may carry
_IDENTIFIER = re.compile(
    r"(?:^|(?<=[.;!?]))\s*(?P<noun>goal|requirement)\s+(?P<t>\w+)\s*(?P<ref>[^:.;!?]*?)\s*(?::|\s[-–—]\s)",
    re.IGNORECASE,
)
_NUMBERED_IDENTIFIER = re.compile(
    r"\b(?:goal|requirement)\s+(?:\d+|one|two|three|four|five|first|second|third|fourth|[a-d]|i{1,3}|iv)\b",
    re.IGNORECASE,
)


def identifiers_chained_read(text: str) -> str:
    """A spec sheet's identifiers ("Goal 1: ... Goal 2: ...") list and never order; where each one after the
    first names the one just before it ("Goal 2 (after goal 1):", "Requirement 3, only after requirement
    2:") and the first names none, the words say the order: the labels are steps in turn ("Step 2:"). One
    identifier alone, numbered 1 and opening the text, is a heading ("Goal 1: A on P. Then B on Q." is
    "Goal: A on P. Then B on Q.").

    >>> identifiers_chained_read("Goal 1: A on P. Goal 2 (after goal 1): B on Q.")
    'Step 1: A on P. Step 2: B on Q.'
    """
    marks = list(_IDENTIFIER.finditer(text))
    lone = len(_NUMBERED_IDENTIFIER.findall(text)) == 1  # no other goal numbered anywhere (a line, a mention)
    if len(marks) == 1 and lone and not text[: marks[0].start()].strip() and not marks[0]["ref"]:
        # "Goal 1: A on P. Then B on Q.": the one identifier, opening the text, numbers nothing else, so it
        # lists nothing: a heading ("Goal:"), and the words after it say the order
        m = marks[0]
        heading = f"{text[: m.end('noun')]}:{_space(m)}{text[m.end() :]}"
        return heading if _place_in_turn(m["t"]) == 1 else text
    if len(marks) < 2 or len({m["noun"].lower() for m in marks}) != 1:
        return text
    for turn, m in enumerate(marks, 1):
        back = re.fullmatch(_REFERENCE, m["ref"], re.IGNORECASE) if m["ref"] else None
        said_back = back is not None and _names_the_one_before(m["noun"], turn, back)
        if _place_in_turn(m["t"]) != turn or (turn > 1 and not said_back) or (turn == 1 and m["ref"]):
            return text
    out, pos = "", 0
    for turn, m in enumerate(marks, 1):
        out += text[pos : m.start("noun")] + f"Step {turn}:{_space(m)}"
        pos = m.end()
    return out + text[pos:]


def _space(identifier: re.Match[str]) -> str:
    """The space a dash after an identifier took with it ("Goal 1 - A on P"), given back after its colon."""
    return " " if identifier[0][-1].isspace() else ""


def label_references_dropped(text: str) -> str:
    """ "Round B, only after round A:" -> "Round B:" where the label it names is the one just before it in
    turn; any other such reference is left (and refused where it is read); a spec sheet's identifiers each
    naming the one before as steps (`identifiers_chained_read`)."""
    text = identifiers_chained_read(ordinal_stages_read(named_stages_read(text)))

    def dropped(m: re.Match[str]) -> str:
        return m["label"] if _names_the_one_before(m["noun"], _place_in_turn(m["t"]), m) else m[0]

    def group_done(m: re.Match[str]) -> str:
        return m["label"] if (_place_in_turn(m["t"]) or 0) >= 2 else m[0]

    return _second_step_after_unlabelled(_GROUP_DONE.sub(group_done, _REFERS_BACK.sub(dropped, text)))


def _second_step_after_unlabelled(text: str) -> str:
    """ "Put A and B on P first. Stage two: C and D on Q." -> "... then C and D on Q.": one label alone,
    second in turn, after a sentence with no label: that sentence is the first step, as the label says."""
    labels = _labels(text)
    if len(labels) != 1 or _turn(labels[0]) != 2 or not re.search(r"[.;!?]\s*$", text[: labels[0].start()]):
        return text
    return text[: labels[0].start()] + " then " + text[labels[0].end() :]


def order_confirmed_dropped(text: str, listed: bool) -> str:
    """The remarks that confirm the order of the steps (`_KEEP`, `_STEP_AFTER`) dropped where two or more
    steps are labelled or numbered in turn and no remark frees the whole list (`listed`, or one still in
    the text); anywhere else (no steps to keep in order, a step said after another than the one before it,
    or a remark that frees the whole list beside it: "1) ... 2) ... any order. Keep that sequence." says
    both) they stay, to be refused."""
    marks = _labels(text)
    labels = [_turn(m) for m in marks]
    numbers = [_list_number(m) for m in _LIST_NUMBER.finditer(text)]
    if not any(len(t) >= 2 and t == list(range(1, len(t) + 1)) for t in (labels, numbers)):
        return text
    # a freeing remark beside labelled steps of two placements or more frees each step alone (`steps_read`)
    ordered_anyway = len(labels) >= 2 and not _one_placement_each(text, marks)
    if (listed or frees_every_step(free_order(text.lower())[1])) and not ordered_anyway:
        return text

    def restated(m: re.Match[str]) -> str:
        turn = _place_in_turn(m["t"])
        said = len(labels) >= 2 and _names_the_one_before(m["noun"], turn, m) and (turn or 0) <= len(labels)
        return " " if said else m[0]

    return _STEP_AFTER.sub(restated, _KEEP.sub(" ", text))


def steps_read(text: str, listed: bool) -> str | None:
    """Step labels, and bare list numbers, as "first" / "then" (numbered 1, 2, ... in turn); bare list
    numbers beside a remark that frees the whole list (`listed`: "1) ... 2) ... in any order") only list,
    and are removed, and so are step labels there where each step is one placement ("Step 1 - A on P. Step
    2 - B on Q. The steps may be done in any order."; with two in a step, the remark may free the order
    within each step alone). None: labels or numbers out of turn."""
    text = order_confirmed_dropped(label_references_dropped(text), listed)
    labels = _labels(text)
    if [_turn(m) for m in labels] != list(range(1, len(labels) + 1)):
        return None
    if listed and len(labels) > 1 and _one_placement_each(text, labels):
        return list_numbers_read(_as_items(text, labels), listed)
    text = _as_steps(text, labels)
    return list_numbers_read(text, listed)


def labelled_steps(text: str) -> int:
    """How many steps `text` labels ("Stage one: ... Stage two: ...") or numbers ("1) ... 2) ..."), where
    they are 1, 2, ... in turn; 0 otherwise."""
    labels = [_turn(m) for m in _labels(label_references_dropped(text))]
    listed = [_list_number(m) for m in _LIST_NUMBER.finditer(text)]
    for turns in (labels, listed):
        if turns and turns == list(range(1, len(turns) + 1)):
            return len(turns)
    return 0


def _one_placement_each(text: str, labels: list[re.Match[str]]) -> bool:
    """Does each labelled step say one placement (no "and", comma or "&" in it)?"""
    ends = [m.start() for m in labels[1:]] + [len(text)]
    steps = [text[m.end() : end] for m, end in zip(labels, ends, strict=True)]
    return not any(re.search(r"\band\b|[,&]", step) for step in steps)


def _as_items(text: str, marks: list[re.Match[str]]) -> str:
    """Each step's label or number removed, each step its own sentence."""
    for m in reversed(marks):
        text = text[: m.start()] + ("" if m.start() == marks[0].start() else ". ") + text[m.end() :]
    return text


def _labels(text: str) -> list[re.Match[str]]:
    """The step labels of `text`: "Step 1:", "First course:", or any one noun numbered ("Priority 1: ...
    Priority 2: ...")."""
    labels = list(_LABEL.finditer(text))
    if not labels:
        labels = [m for m in _NOUN_LABEL.finditer(text) if m["noun"].lower() not in _NOT_STEPS]
        if len(labels) < 2 or len({m["noun"].lower() for m in labels}) != 1:
            return []
    return labels


def labels_out_of_turn(text: str) -> str | None:
    """The labels or list numbers of `text` (lowercased) when they are not 1, 2, ... in turn ("Part 2: ...
    Part 1: ..."): no reading may order the steps by where they are written."""
    numbers = [m[0].strip() for m in (*_labels(text), *_LIST_NUMBER.finditer(text))]
    turns = [_turn(m) for m in _labels(text)]
    listed = [_list_number(m) for m in _LIST_NUMBER.finditer(text)]
    if turns == list(range(1, len(turns) + 1)) and listed in ([], list(range(1, len(listed) + 1))):
        return None
    return ", ".join(numbers)


def list_numbers_read(text: str, listed: bool) -> str | None:
    """A numbered list's numbers ("1) ... 2) ...") as "first" / "then", or removed when a remark frees the
    whole list (`listed`); None when they are not 1, 2, ... in turn."""
    numbers = list(_LIST_NUMBER.finditer(text))
    if [_list_number(m) for m in numbers] != list(range(1, len(numbers) + 1)):
        return None
    # each item its own sentence when the list is freed: "1) A on P 2) B on Q" is two placements
    return _as_items(text, numbers) if listed else _as_steps(text, numbers)


def _list_number(m: re.Match[str]) -> int:
    if m["l"]:
        return _LETTERS[m["l"].lower()]
    return int(m["n"]) if m["n"] else NUMBER_WORDS[m["w"].lower()]


def numbered_steps(text: str) -> str:
    """`text` with its step labels read as "first" / "then" when there are two or more in turn ("Part A:
    ... Part B: ..."), and the numbers of a numbered list of two or more steps read (`list_numbers_read`:
    as "first" / "then", or removed beside a remark that frees the whole list), so that every reader
    orders the steps as the labels and numbers do; the text as it is with no such list."""
    text = order_confirmed_dropped(label_references_dropped(runs_freed(text)), False)
    labels = _labels(text)
    if len(labels) >= 2 and [_turn(m) for m in labels] == list(range(1, len(labels) + 1)):
        text = " ".join(_as_steps(text, labels).split())
    if len(_LIST_NUMBER.findall(text)) < 2:
        return text
    listed = list_freed(text, free_order(text.lower())[1])
    read = list_numbers_read(text, listed)
    return " ".join(read.split()) if read is not None else text


def list_freed(text: str, remarks: list[str]) -> bool:
    """Does one of the free-order `remarks` of `text` free the whole list, not only the order inside each
    step, nor only an item of a numbered list ("1. A and B, either order. 2. ...": that item alone)?"""
    return frees_every_step(remarks) and not _inside_an_item(text)


def _inside_an_item(text: str) -> bool:
    """Is a free-order remark said inside an item of the numbered list, before its last number ("1) A and B,
    in any order. 2) C and D, in any order.")? Then it frees that item alone, not the list."""
    numbers = list(_LIST_NUMBER.finditer(text))
    lowered = text.lower()
    return len(numbers) >= 2 and any(
        numbers[0].end() <= r.start < numbers[-1].start() for r in free_order_remarks(lowered)
    )


def _as_steps(text: str, marks: list[re.Match[str]]) -> str:
    """Each step's label or number as "first" (the first one) or "then"."""
    for m in reversed(marks):
        word = " first " if m.start() == marks[0].start() else " then "
        text = text[: m.start()] + word + text[m.end() :]
    return text


def _turn(label: re.Match[str]) -> int:
    """A label's place in turn: "Step 2:" -> 2, "Part B:" -> 2."""
    if label["l1"]:
        return _LETTERS[label["l1"].lower()]
    word = (label["n1"] or label["n2"]).lower()
    return int(word) if word.isdigit() else NUMBER_WORDS[word]
