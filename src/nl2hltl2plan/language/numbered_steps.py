"""An order said by step number in a numbered recipe ("Method: 1. put ... 2. put ... Step 2 comes first."),
applied before the household grammar reads (`step_order`): the steps are written out in the order said,
"A, then B". Without it, the grammar read the steps' numbers as their order and "step 2 comes first" as
nothing (step 1 before step 2: the opposite of what was asked).

- "step N first" / "do step N first" / "the second step comes first" / "step N last": the named step first
  (last), and the others in their numbered turn ("1. A 2. B 3. C. Do step 3 first." is "C, then A, then
  B"): the numbers of a recipe may mean a sequence (steps numbered in turn are read so), and
  an order the text may mean is kept rather than dropped;
- "step N before step M" / "step M after step N": with two steps, that order;
- no order said: steps numbered in turn are that sequence ("Step one: A. Step two: B." is "A, then B", the
  label's number no count; a step that frees what it lists, "Step two: B and C in any order", is a sentence
  of its own after "After that"); numbered out of turn, refused; with a free-order remark of its own
  sentence ("Any order is fine."), the numbers go;
- labels other than "step" (h292): "#2", "(2)", "(b)" (letters count from a), "Item 2:", "Job 2:", "Task 2:",
  "Cue 2:"; a group of them ("Items 3 and 4 after item 1", "Cues 2 and 4 go before everything else", "Jobs 1
  and 2 first"), a chain ("Job 2 first, then job 1") and "step two can wait until step one is done". An
  order between some of three or more steps orders only those (the guide's "no temporal words, no order"):
  the steps it does not name are free, each a sentence of its own; a lone step "first" or "last" keeps the
  others in their numbered turn, as before;
- an order that names a step the recipe does not have is refused by name. An order the steps may come in
  freely ("Either step may come first") is `free_order.txt`'s, which the grammar reads.

>>> step_order("1. put the mug in the sink. 2. put the egg in the fridge. Step 2 comes first.")
'put the egg in the fridge, then put the mug in the sink.'
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.content_words import free_order_remarks

_ORDINALS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "one": 1, "two": 2, "three": 3, "four": 4}
_NUMBER = r"(?:\d+|one|two|three|four)"
# a step's label word ("Step 2", "Job 2", "Item 2", "Task 2": h292), and a label that is a sign and a number
# or a letter ("#2", "(2)", "(b)": h292), a letter counting from a
_LABEL_WORD = r"(?:step|item|job|task|cue|part)"
_SIGNED = r"(?:\#\d+|\((?:\d+|[a-h])\))"
# "step 2", "job #2", "the second step", a signed label, and a step's bare number ("do 2 first", "1 last",
# "3 before 2": h190), which names a step only where the text numbers two or more (`_bare_without_steps`)
_STEP_REF = (
    rf"(?:{_LABEL_WORD}\s+(?:number\s+)?\#?{_NUMBER}|the\s+(?:first|second|third|fourth)\s+{_LABEL_WORD}|"
    rf"{_SIGNED}|(?:number\s+)?\d+)"
)
# a numbered step: "1." / "1)" / "Step 1:" / "Job 2:" opening the text or following a sentence's end or a
# colon, or a signed label ("#1 ...", "#1: ...", "(b) ...") opening it or set apart by a space
_STEP = re.compile(
    rf"(?:(?:^|(?<=[.:;!?])\s+|\s+(?=\d[.)]\s))(?:{_LABEL_WORD}\s+\#?)?(?P<n>{_NUMBER})\s*[.):]\s+|"
    r"(?:^|(?<=[.:;!?])\s+|\s+(?=[#(]))(?:\#(?P<hash>\d+)|\((?P<paren>\d+|[a-h])\))\s*[.:)-]?\s+)",
    re.I,
)
# several steps named at once ("steps 1 and 2", "Items 3 and 4", "#1, #2 and #3", "(a) & (b)": h292)
_JOIN = r"(?:\s*,\s*(?:and\s+)?|\s+and\s+|\s*&\s*)"
_REFS = (
    rf"(?:(?:{_LABEL_WORD}s\s+\#?{_NUMBER}(?:{_JOIN}\#?{_NUMBER})+)|{_STEP_REF}(?:{_JOIN}{_STEP_REF})*)"
)
_VERB = r"(?:(?:should|must|can|will)\s+)?(?:comes?|go(?:es)?|happens?|(?:is|are|be)\s+done)"
_SAID = (
    re.compile(rf"^(?:do\s+)?(?P<a>{_REFS})\s+(?:{_VERB}\s+)?(?P<where>first|last)$", re.I),
    re.compile(
        rf"^(?:do\s+)?(?P<a>{_REFS})\s+(?:{_VERB}\s+)?(?P<rel>before|after)\s+"
        r"(?:(?P<rest>everything\s+else|the\s+rest|the\s+others|all\s+the\s+others)|"
        rf"(?P<b>{_REFS}))$",
        re.I,
    ),
    # "Job 2 first, then job 1" (h292): the steps named, in that order
    re.compile(
        rf"^(?:do\s+)?(?P<chain>{_STEP_REF}\s+first(?:\s*,?\s*(?:and\s+)?then\s+{_STEP_REF})+)$", re.I
    ),
    # "Step two can wait until step one is done" (h292): the first named after the second
    re.compile(
        rf"^(?P<a>{_REFS})\s+(?:can|should|must|will|has\s+to)\s+(?P<rel>wait)\s+(?:until|till|for)\s+"
        rf"(?P<b>{_REFS})(?:\s+(?:is|are)\s+(?:done|finished|over))?$",
        re.I,
    ),
)
# one step's number in a reference ("#2", "(b)", "two", "the second")
_REF_NUMBER = re.compile(
    r"\#?\d+|\((?:\d+|[a-h])\)|\b(?:one|two|three|four|first|second|third|fourth)\b", re.I
)
# any other order said by step numbers ("2 before 1, and 4 last"): read in the steps' numbered turn, it was
# the opposite of what was asked, so it is refused by name
# (or by a group of them, "do 1 n 2 first, 3 n 4 after": h266, read in turn as 1 < 2 < 3 < 4 at exit 0)
_ORDER_SAID = (
    rf"(?:do\s+)?(?:{_REFS}|{_STEP_REF}(?:\s*(?:,|and|n|&)\s*{_STEP_REF})*)\s+(?:{_VERB}\s+)?"
    r"(?:first|last|before|after)\b"
)
_LOOSE = re.compile(rf"^{_ORDER_SAID}", re.I)
# an order line set off by a dash after the last step ("1. A 2. B 3. C - do 2 before 3"): its own sentence
_DASHED_ORDER = re.compile(rf"\s+[-\u2013\u2014]\s+(?={_ORDER_SAID})", re.I)


# a list of bullets ("To do: - put the keychain in the box - put the pillow on the armchair"): a dash or a
# bullet opening the text or following its heading's colon, and one more set apart by spaces; a dash inside
# a sentence ("Robot - put ...", "1) kitchen - put ...") opens no list
# (its heading may hold a hyphen, "To-do:", or stand before a bullet with no colon, "To do \u2022 ...", and an
# item may open with a checkbox, "- [ ] ...": h223)
_BULLETED = re.compile(
    r"^(?P<head>(?:[^-\u2022*:.!?]|(?<=\w)-(?=\w))*:\s*|to[\s-]?do(?:\s+list)?\s+(?=\u2022))?"
    r"[-\u2022*]\s+(?=\S.*\s[-\u2022*]\s+\S)",
    re.I,
)
_BULLET = re.compile(r"\s+[-\u2022*]\s+")
_CHECKBOX = re.compile(r"^\[\s*[x\u2713]?\s*\]\s*", re.I)


def bullets_apart(text: str) -> str:
    """A list of bullets as one sentence an item, in no order (a bullet, unlike a number, says none):

    >>> bullets_apart("To do: - put the mug in the sink - put the egg in the fridge")
    'To do: put the mug in the sink. put the egg in the fridge.'
    """
    if (m := _BULLETED.match(text.strip())) is None:
        return text
    said = [item.strip(" .;!?") for item in _BULLET.split(text.strip()[m.end() :])]
    # a ticked box says the item is done: doing it again (or dropping it unsaid) is no careful reading
    if ticked := [item for item in said if (box := _CHECKBOX.match(item)) and box[0].strip("[] ")]:
        raise HTTError(f"{ticked[0]!r} is ticked as done: untick it to have it done, or leave it out")
    items = (_CHECKBOX.sub("", item) for item in said)
    head = (m["head"] or "").strip()
    head = f"{head}: " if head and not head.endswith(":") else f"{head} " if head else ""
    return head + " ".join(f"{item}." for item in items if item)


# an order said by the person a chore chart labels ("Zoe: A. Finn: B. Zoe again: C. Zoe does hers first"):
# the labels were read in turn, A < B < C at exit 0 (h266); it is refused by name
_PERSON_LABEL = re.compile(r"(?:^|(?<=[.!?:])\s+)(?P<name>[A-Z][a-z]+)(?:\s+again)?\s*:", re.M)
_PERSON_ORDER = re.compile(
    r"\b(?P<name>[A-Z][a-z]+)(?:'s\s+\w+|\s+(?:does|do)\s+(?:his|hers|theirs|her\s+\w+|his\s+\w+))?\s+"
    r"(?:goes|go|comes|come|is|are)?\s*(?:first|last)\b"
)


def _person_order(text: str) -> None:
    """Raises HTTError for an order said by a chore chart's person label (see `_PERSON_ORDER`)."""
    labels = {m["name"] for m in _PERSON_LABEL.finditer(text)}
    if len(labels) >= 2 and (m := _PERSON_ORDER.search(text)) and m["name"] in labels:
        raise HTTError(
            f"{m[0]!r} orders the tasks by who does them, which no task says: say which tasks come first"
        )


def step_order(text: str) -> str:
    """`text` with an order said by step number written out as the steps in that order (see the module
    docstring), a list of bullets as its sentences (`bullets_apart`); text with no such order comes back
    as it is. Raises HTTError naming what cannot be read."""
    text = bullets_apart(text)
    _person_order(text)
    if len(_marks(text)) >= 2:
        text = _DASHED_ORDER.sub(". ", text)
    sentences = _sentences(text)
    said = _orders_said(sentences)
    if len(said) == 1 and _bare_without_steps(said[0][1], sentences, said[0][0]):
        # "Put the pen in the box. Do 2 before 1.": the line was read as nothing, at exit 0
        raise HTTError(f"{said[0][1][0]!r} names steps by number, but the instruction numbers fewer than two")
    if not said:
        loose = [sentences[k] for k in _loose_orders(sentences) if _steps_of(sentences, k)]
        if loose:
            said_as = loose[0].strip(" .")
            raise HTTError(f"{said_as!r}: say the steps' order one way (\"do step 2 first\")")
        return _in_turn(text)
    if len(said) > 1:
        raise HTTError("the order of the steps is said twice; say it once")
    k, m = said[0]
    rest = " ".join(sentences[:k] + sentences[k + 1 :])
    return _ordered(m, _steps(rest))


def _named(refs: str | None) -> list[int]:
    """The step numbers a reference names ("step 2", "Items 3 and 4", "#1 and (b)"), in the order said."""
    # the "first" of a chain ("Job 2 first, then job 1") is its order, not a step
    refs = re.sub(r"\s+first(?=\s*,?\s*(?:and\s+)?then\b)", "", refs or "", flags=re.I)
    return list(dict.fromkeys(_number(ref) for ref in _REF_NUMBER.findall(refs)))


def _ordered(m: re.Match[str], steps: dict[int, str]) -> str:
    """The steps written out in the order the sentence `m` (one of `_SAID`) says."""
    said = m.groupdict()
    first, then = _named(said.get("a") or said.get("chain")), _named(said.get("b"))
    if len(steps) < 2 or any(n not in steps for n in first + then):
        raise HTTError(f"{m[0]!r} names a step the instruction does not number")
    others = [n for n in steps if n not in first + then]
    if said.get("chain"):  # the steps named in the order said, the others after them in turn
        return ", then ".join(steps[n] for n in [*first, *others]) + "."
    if said.get("where") and len(first) == 1:  # the named step to the front (the end), the others in turn
        chain = [*first, *others] if m["where"].lower() == "first" else [*others, *first]
        return ", then ".join(steps[n] for n in chain) + "."
    if set(first) & set(then):
        raise HTTError(f"{m[0]!r} orders a step against itself")
    if said.get("where") or said.get("rest"):  # "Cues 8 and 10 first": the named before all the others
        then, others = others, []
        if (said.get("where") or "").lower() == "last" or (said.get("rel") or "").lower() == "after":
            first, then = then, first
    elif m["rel"].lower() in ("after", "wait"):
        first, then = then, first
    if not first or not then:
        raise HTTError(f"{m[0]!r} leaves nothing to order the named steps against")
    # only what is said is ordered: the steps it does not name are free, each a sentence of its own
    join = ", then " if len(first) == len(then) == 1 else ". After that, "
    free = "".join(f" {steps[n]}." for n in others)
    return f"{_any_order(steps, first)}{join}{_any_order(steps, then)}.{free}"


def _any_order(steps: dict[int, str], named: list[int]) -> str:
    """The steps `named` as one phrase: a step alone, or several "in any order"."""
    words = [steps[n] for n in named]
    return words[0] if len(words) == 1 else " and ".join(words) + " in any order"


def orders_by_label(text: str) -> bool:
    """Whether a sentence of `text` orders steps by their labels ("Do (3) first", "Items 3 and 4 after item
    1"): the household reader asks it once, before its strippers take labels off (`world_readers`), so
    that a list of "(1) ... (2) ..." or "Item 1 - ..." is left for `step_order`, which reads the order or
    refuses it."""
    sentences = _sentences(text)
    return bool(_orders_said(sentences) or _loose_orders(sentences))


def _sentences(text: str) -> list[str]:
    return re.split(r"(?<=[.!?])\s+", text.strip())


def _orders_said(sentences: list[str]) -> list[tuple[int, re.Match[str]]]:
    """Each sentence that says an order by step labels (`_SAID`), with its place among `sentences`."""
    return [(k, m) for k, s in enumerate(sentences) for p in _SAID if (m := p.match(_unpleased(s)))]


def _loose_orders(sentences: list[str]) -> list[int]:
    """The places of the sentences after the first that open with any other order by step labels
    (`_LOOSE`: "2 before 1, and 4 last")."""
    return [k for k, s in enumerate(sentences) if k and _LOOSE.match(s.strip())]


def _steps_of(sentences: list[str], k: int) -> dict[int, str]:
    """The numbered steps of the text without its sentence `k`, where it numbers two or more (else none)."""
    rest = " ".join(sentences[:k] + sentences[k + 1 :])
    marks = _marks(rest)
    try:  # from the first step: a heading before it ("hey! 4 things pls:") holds no step
        steps = _steps(rest[marks[0].start() :].lstrip() if marks else rest)
    except HTTError:
        return {}
    return steps if len(steps) > 1 else {}


def _bare_without_steps(m: re.Match[str], sentences: list[str], k: int) -> bool:
    """A bare number ("Do 2 first") where the text numbers fewer than two steps names no step."""
    bare = not re.search(r"step", m[0], re.I)
    return bare and not _steps_of(sentences, k)


def _in_turn(text: str) -> str:
    """A recipe numbered in turn ("Step 1: A. Step 2: B.", "1. A 2. B", "Step one: A. Step two: B.") with no
    order said: its steps in that order, "A, then B", or, with a free-order remark of its own sentence,
    its steps without their numbers. A first step left unnumbered before "Step 2" is step 1; steps
    numbered out of turn are refused; anything else comes back as it is."""
    marks = _marks(text)
    if len(marks) < 2 and not (marks and _marked(marks[0]) == 2):
        return text
    before = text[: marks[0].start()].strip(" .;")
    numbered = _steps(text[marks[0].start() :].lstrip())  # from the first mark: nothing stands outside
    steps = numbered if not before or before.endswith(":") else {1: before, **numbered}
    if len(steps) < 2:
        return text
    if list(steps) != list(range(1, len(steps) + 1)):
        raise HTTError(f"the steps are numbered out of turn ({', '.join(map(str, steps))}); say their order")
    if _frees_the_steps(steps.values()):  # the numbers go, the remark that frees the order stays
        return ". ".join(steps.values()) + "."
    if before and (frees := free_order_remarks(before)):
        # "Checklist (any order): 1) A 2) B": the heading frees the steps; its remark goes in a sentence of
        # its own after them, which the grammar reads (inside the heading it was left unread)
        head = re.sub(r"\s*\(\s*\)|\s*,\s*(?=:)", "", before[: frees[0].start] + before[frees[0].end :])
        return f"{head} " + ". ".join(steps.values()) + f". {frees[0].words[0].upper()}{frees[0].words[1:]}."
    # a step that frees what it lists goes in a sentence of its own: ", then B and C in any order" would
    # order C after nothing
    then = ". After that, " if any(free_order_remarks(w) for w in steps.values()) else ", then "
    return then.join(steps.values()) + "."


def _frees_the_steps(steps: Iterable[str]) -> bool:
    """A free-order remark in a sentence of its own frees the steps' order ("1. A. 2. B. Any order is
    fine."); one inside a step's own sentence frees what that step lists ("Step two: B and C in any
    order")."""
    return any(
        free_order_remarks(later)
        for words in steps
        for later in re.split(r"(?<=[.!?])\s+", words)[1:]
    )


def _unpleased(sentence: str) -> str:
    """A sentence without its stop and a closing "please" ("#1 last, please.")."""
    return re.sub(r",?\s+please$", "", sentence.strip(" .!?"), flags=re.I)


def _marks(text: str) -> list[re.Match[str]]:
    """The step marks of `text` (`_STEP`). A signed label ("#2", "(b)") numbers steps only where the first
    one opens the text or a sentence: inside one ("cloth #1: wash it") it is part of a thing's name."""
    marks = list(_STEP.finditer(text))
    signed = [m for m in marks if m["n"] is None]
    if signed and text[: signed[0].start()].rstrip()[-1:] not in ("", ".", ":", ";", "!", "?"):
        return [m for m in marks if m["n"] is not None]
    return marks


def _number(ref: str) -> int:
    """The number a step's label or reference says ("step two", "the second job", "#2", "(b)")."""
    words = ref.lower().replace("(", " ").replace(")", " ").replace("#", " ").split()
    word = words[1] if words[0] == "the" else words[-1]
    if len(word) == 1 and word.isalpha():  # "(b)": the letters count from a
        return ord(word) - ord("a") + 1
    return int(word) if word.isdigit() else _ORDINALS[word]


def _marked(mark: re.Match[str]) -> int:
    """The number of a step's mark (`_STEP`)."""
    return _number(mark["n"] or mark["hash"] or mark["paren"])


def _steps(text: str) -> dict[int, str]:
    """Step number -> its words (a heading before the first step, "Method:", is left out)."""
    marks = _marks(text)
    out: dict[int, str] = {}
    if not marks:
        return out
    if not re.fullmatch(r"\s*(?:(?:[A-Za-z']+\s+){0,4}[A-Za-z']+\s*:)?\s*", text[: marks[0].start()]):
        outside = text[: marks[0].start()].strip()
        raise HTTError(f"{outside!r} stands outside the numbered steps; number it too")
    for m, nxt in zip(marks, [*marks[1:], None], strict=True):
        words = text[m.end() : nxt.start() if nxt else len(text)].strip(" .;")
        out[_marked(m)] = words
    return out
