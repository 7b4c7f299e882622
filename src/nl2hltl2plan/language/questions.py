"""An instruction written as questions and answers, as the plain instruction it states (`answered`);
every world's reader may apply it (`headings` re-exports it).

"Q: Where does the mug go? A: In the sink. Q: And the apple? A: The fridge. Q: Order? A: Mug first."
reads as "put the mug in the sink, then put the apple in the fridge". Each answer fills its question's
gap: where an object goes, what goes somewhere, what to do with an object, what the task is (the answer
is an instruction), whether there is more, and the order. A follow-up ("And the apple?", "What about
in the sink?") asks the question before it again with its new object or place. A thing's name asked
alone is where it goes, where the answer is a place's name alone ("Carrot? Blue plate."; a place is a
receptacle of `lexicon.txt` or a `place_type` of `questions.txt`). "What goes where?" is answered by a
list of placements, each put. Steps asked in turn ("What first?", "Then?", "What next?", "Last?") are
chained in that order, each answer a placement or an instruction; a "then" after one task asked
otherwise follows that task. The order answer names
the tasks by their objects ("mug first", "red before blue", "the apple, then the mug"), or frees the
order ("any", "doesn't matter"; `questions.txt` lists these phrases). Names that match no object asked
about (a colour within a group: "Where do the blocks go? ... red before blue") are left to the reader as
a sentence of their own.

Anything else is refused by name (HTTError): a question no frame covers, a question with no answer or an
answer with no question, an answer that says nothing certain ("not sure"), an order answer that names
one task and not another ("the mug before the bowl" where no bowl was asked about), a name asked alone
that is not a thing answered by a place ("Blue plate? Carrot."), a list item or step with no place, an
order inside a list, a step whose place in the order is unclear, steps and an order answer together.

>>> answered("Q: Where does the mug go? A: In the sink. Q: And the apple? A: The fridge.")
'put the mug in the sink. put the apple in the fridge.'
>>> answered("Q: Where does the mug go? A: In the sink. Q: And the apple? A: The fridge. Q: Order? A: Any.")
'put the mug in the sink. put the apple in the fridge. In any order.'
>>> answered("put the apple in the fridge")
'put the apple in the fridge'
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache
from importlib import resources

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.content_words import categories, phrase_list_pattern, phrase_words
from nl2hltl2plan.language.grounding import find_mentions
from nl2hltl2plan.language.prepositions import PLACE_OR_LANDMARK, preposition_pattern

# "Q:", "Question 2:", "A:", "Answer:"; a label opens the text or follows a sentence's end or a blank
_LABEL = re.compile(r"(?:^|(?<=[\s.!?;]))(?P<who>q|question|a|answer)\s*\d*\s*:\s*", re.I)
_HAS_QUESTION = re.compile(r"(?:^|(?<=[\s.!?;]))(?:q|question)\s*\d*\s*:", re.I)
_HAS_ANSWER = re.compile(r"(?:^|(?<=[\s.!?;]))(?:a|answer)\s*\d*\s*:", re.I)
_DET = r"(?:the|a|an|my|your|our|this|that|these|those|some|both|all|two|three)\s"
_AUX = r"(?:does|do|should|shall|will|would|can|could|must|is|are|did)"
_PLACE_VERBS = r"(?:go|goes|belong|belongs|be put|be placed|be kept|be stored|be moved|be left|be set|end up)"
_PUT_VERBS = r"(?:put|place|move|leave|store|keep|set|take|bring|stick|pop|stash|drop|toss|throw)"
# where an object goes: the gap is its place
_WHERE = (
    re.compile(rf"^where {_AUX} (?P<obj>.+?) {_PLACE_VERBS}(?: now| then| next)?$", re.I),
    re.compile(rf"^where {_AUX} (?:i|we|you) (?P<verb>{_PUT_VERBS}) (?P<obj>.+?)$", re.I),
    re.compile(rf"^where (?:to|should) (?P<verb>{_PUT_VERBS}) (?P<obj>.+?)$", re.I),
    re.compile(rf"^(?P<obj>{_DET}.+?) (?:goes|go|should go|belongs) where$", re.I),
    re.compile(r"^where (?:do|would) you (?:want|like|need) (?P<obj>.+?)(?: to go| put| placed)?$", re.I),
)
# a place's preposition: a destination or a landmark (the grammar's lists, `prepositions`)
_PREP = preposition_pattern(PLACE_OR_LANDMARK)
# what goes somewhere: the gap is its object
_WHAT = (
    re.compile(rf"^what {_AUX}? ?(?:go|goes|belong|belongs|be put|be placed)\s(?P<place>{_PREP} .+)$", re.I),
    re.compile(rf"^what {_AUX} (?:i|we|you) (?P<verb>{_PUT_VERBS}) (?P<place>{_PREP} .+)$", re.I),
    re.compile(rf"^what (?:needs|has|is) to (?:go|be put) (?P<place>{_PREP} .+)$", re.I),
    re.compile(rf"^what (?:do|would) you (?:want|like|need) (?P<place>{_PREP} .+)$", re.I),
)
# what to do with an object: the answer is an instruction about it
_DO_WITH = re.compile(rf"^what (?:{_AUX} (?:i|we|you) do|to do|about doing) with (?P<obj>.+)$", re.I)
_FOLLOW_UP = re.compile(
    r"^(?:and|and what about|what about|how about|and how about|same for|then) (?P<gap>.+)$", re.I
)
_PRONOUN = re.compile(r"\b(?:it|them|that one|this one)\b", re.I)
_GOES = re.compile(
    r"^(?:it|they|that|this|those|these)(?:'s| is| are)? (?:goes|go|should go|belongs?|can go)\s", re.I
)
# a placement's place after its thing ("the carrot on the blue plate"), and order words a list may not hold
_PLACED = re.compile(rf"\s(?:{_PREP})\s", re.I)
_ORDER_WORD = re.compile(r"\b(?:first|then|before|after|last|next|finally|afterwards)\b", re.I)
_ITEM_GOES = re.compile(rf"\s(?:goes|go|should go|belongs?|can go)(?=\s{_PREP}\s)", re.I)
# what may come before a thing's name in a question of its name alone ("Carrot?", "And the carrot?" is a
# follow-up)
_NAME_ONLY = re.compile(rf"(?:{_DET})?", re.I)
_ORDER_SAID = re.compile(r"\b(?:first|last|then|before|after)\b|,", re.I)
_CHAIN = re.compile(r"\s*(?:,?\s*(?:and )?then\b|,?\s*followed by\b|\bbefore\b|->|>|,|;)\s*", re.I)
_NO_THEN = re.compile(r"^(?:no|nope|nah)\s*[,.;:!-]\s*", re.I)
_ORDER_FILLER = frozenset(
    "the a an do first firstly then one ones with put task please should must can go goes come comes be is "
    "done start begin end finish by".split()
)


@dataclass
class _Frame:
    """The gap a question leaves: `where` (an object's place), `what` (the object of a place), `do`
    (what to do with an object); `verb` is the question's verb ("where should I store the mug")."""

    kind: str
    verb: str = "put"


@dataclass
class _Clause:
    text: str
    obj: str | None  # the object it is about, for the order answer's names
    step: bool = False  # one of the steps asked in turn ("What first?", "Then?"), ordered as asked


def answered(text: str) -> str:
    """`text` with its questions and answers as the instruction they state (see the module docstring);
    text with no "Q:" label, or no "A:" label, comes back as it is. Raises HTTError naming what cannot be
    read."""
    if not _HAS_QUESTION.search(text) or not _HAS_ANSWER.search(text):
        return text  # no answer at all: a request labelled as a question ("Question: could you put ...")
    pieces = _LABEL.split(text)  # [before, who, words, who, words, ...]
    clauses = [_Clause(pieces[0].strip(), None)] if pieces[0].strip() else []
    pairs = [(pieces[k].lower()[0], pieces[k + 1].strip()) for k in range(1, len(pieces), 2)]
    frame: _Frame | None = None
    order: str | None = None
    for k in range(0, len(pairs), 2):
        (who, question), answer = pairs[k], pairs[k + 1] if k + 1 < len(pairs) else ("", "")
        if who != "q":
            raise HTTError(f"the answer {question!r} answers no question (write 'Q: ... A: ...')")
        if answer[0] != "a" or not _bare(answer[1]):
            raise HTTError(f"the question {question!r} has no answer (write 'Q: ... A: ...')")
        said, reply = _bare(question), _bare(answer[1])
        if step := _step_asked(said, reply):
            _add_step(clauses, step, _step_clause(reply, question), question)
            continue
        if _is(said, "order", "order_matters", "order_free", "order_either"):
            order = _order_answer(said, reply, order)
            if re.search(r"\bfirst\b", said, re.I) and not _ORDER_SAID.search(order):
                order += " first"  # "Which first? The mug."
            continue
        if _is(said, "layout"):
            clauses.extend(_layout(reply, question))
            continue
        frame, clause = _answer_clause(said, reply, frame, question)
        if clause is not None:
            clauses.append(clause)
    return _stated(clauses, order)


def _bare(words: str) -> str:
    """Words without their closing punctuation and spare blanks, the first in lower case (an answer is
    written into a sentence)."""
    words = " ".join(words.split()).strip(" .!?;,")
    return words[:1].lower() + words[1:] if not re.match(r"I\b", words) else words


@cache
def _phrases(kind: str) -> re.Pattern[str]:
    return re.compile(rf"(?:{phrase_list_pattern('questions.txt', kind)})", re.I)


def _is(words: str, *kinds: str) -> bool:
    return any(_phrases(kind).fullmatch(words) for kind in kinds)


def _answer_clause(
    question: str, answer: str, frame: _Frame | None, said: str
) -> tuple[_Frame | None, _Clause | None]:
    """(the frame the question leaves for a follow-up, the clause its answer states or None)."""
    if _is(answer, "unclear"):
        raise HTTError(f"the answer {answer!r} to {said!r} says nothing certain; say what is meant")
    if _is(question, "task", "more"):
        if _is(answer, "nothing") or _is(_NO_THEN.sub("", answer), "nothing"):  # "no, that's all"
            return frame, None
        return frame, _Clause(_without_yes(answer), None)
    for pattern in _WHERE:
        if m := pattern.fullmatch(question):
            frame = _Frame("where", (m.groupdict().get("verb") or "put").lower())
            return frame, _placed(m["obj"], answer, frame, said)
    for pattern in _WHAT:
        if m := pattern.fullmatch(question):
            frame = _Frame("what", (m.groupdict().get("verb") or "put").lower())
            return frame, _of_place(m["place"], answer, frame, said)
    if m := _DO_WITH.fullmatch(question):
        frame = _Frame("do")
        return frame, _done_with(m["obj"], answer, said)
    if (m := _FOLLOW_UP.fullmatch(question)) and frame is not None:
        gap = m["gap"]
        if frame.kind == "what":
            return frame, _of_place(gap, answer, frame, said)
        if frame.kind == "do":
            return frame, _done_with(gap, answer, said)
        return frame, _placed(gap, answer, frame, said)
    if _bare_names(question, answer):  # "Carrot? Blue plate.": a thing asked, its place answered
        frame = _Frame("where")
        thing = question if re.match(_DET, question, re.I) else f"the {question}"
        return frame, _placed(thing, answer, frame, said)
    if _name_alone(question):
        raise HTTError(
            f"the question {said!r} is a name alone, read only as a thing whose place the answer names "
            f"alone ('Carrot? Blue plate.'), and {answer!r} is not that; say where what goes"
        )
    raise HTTError(
        f"the question {said!r} is not one the reader knows (ask where something goes, what goes "
        "somewhere, what to do with something, or the order)"
    )


def _without_yes(answer: str) -> str:
    m = re.match(rf"^(?:{phrase_list_pattern('questions.txt', 'yes')})\s*[,:;!-]\s*", answer, re.I)
    return answer[m.end() :] if m else answer


def _placed(obj: str, answer: str, frame: _Frame, said: str) -> _Clause:
    """The clause "put OBJ <answer's place>"; an answer that is an instruction keeps its verb."""
    answer = _GOES.sub("", _without_yes(answer))
    if _is(answer, "no", "nothing", "yes"):
        raise HTTError(f"the answer {answer!r} to {said!r} names no place; say where it goes")
    if _is_instruction(answer):
        return _done_with(obj, answer, said)
    if re.match(rf"{_PREP}\s", answer, re.I):
        return _Clause(f"{frame.verb} {obj} {answer}", obj)
    return _Clause(f"{frame.verb} {obj} in {answer}", obj)


def _of_place(place: str, answer: str, frame: _Frame, said: str) -> _Clause:
    """The clause "put <answer's object> PLACE"; a follow-up's bare place takes the preposition before."""
    answer = _without_yes(answer)
    if _is(answer, "no", "nothing", "yes"):
        raise HTTError(f"the answer {answer!r} to {said!r} names no object; say what goes there")
    if _is_instruction(answer):
        return _Clause(answer, None)
    if not re.match(rf"{_PREP}\s", place, re.I):
        place = f"in {place}"
    return _Clause(f"{frame.verb} {answer} {place}", answer)


def _done_with(obj: str, answer: str, said: str) -> _Clause:
    """The answer to "what do I do with OBJ": an instruction whose first pronoun is OBJ."""
    answer = _without_yes(answer)
    if not _is_instruction(answer):
        if _is(answer, "no", "nothing", "yes"):
            raise HTTError(f"the answer {answer!r} to {said!r} says nothing to do")
        return _placed(obj, answer, _Frame("where"), said)
    if _PRONOUN.search(answer):
        return _Clause(_PRONOUN.sub(obj, answer, count=1), obj)
    if _head(obj) & _words(answer):
        return _Clause(answer, obj)
    raise HTTError(f"the answer {answer!r} to {said!r} does not say what to do with {obj}")


def _is_instruction(answer: str) -> bool:
    """Does the answer open with a verb of a task ("chill it", "put it in the sink")?"""
    first = answer.split()[0].lower() if answer.split() else ""
    return any(c.startswith("verb_") and c != "verb_step" for c in categories(first))


def _words(text: str) -> set[str]:
    return {w.rstrip("s") for w in re.findall(r"[a-z]+", text.lower())}


def _head(phrase: str) -> set[str]:
    return _words(phrase) - _ORDER_FILLER


def _order_answer(question: str, answer: str, before: str | None) -> str:
    """The order an answer states: "free" or the answer's chain of names; refuses an unclear one."""
    if before is not None:
        raise HTTError("the order is asked twice; say it once")
    if _is(answer, "unclear"):
        raise HTTError(f"the answer {answer!r} about the order says nothing certain; say which goes first")
    if _is(answer, "free_answer") and not (_is(question, "order_free") and _is(answer, "no")):
        if _is(answer, "no") and _is(question, "order_either"):
            raise HTTError(f"the answer {answer!r} to {question!r} can mean either order or an order asked")
        return "free"
    if _is(answer, "yes"):
        if _is(question, "order_free"):
            return "free"
        raise HTTError(f"the answer {answer!r} to {question!r} does not say which order")
    if _is(answer, "no"):
        raise HTTError(f"the answer {answer!r} to {question!r} does not say which order")
    m = re.match(r"^(?:yes|no|yeah|nope)\s*[,:;-]\s*", answer, re.I)
    return answer[m.end() :] if m else answer


def _stated(clauses: list[_Clause], order: str | None) -> str:
    """The clauses as sentences, in the order the answer gives, or freed."""
    if not clauses:
        raise HTTError("nothing to do: the answers ask no task")
    if any(c.step for c in clauses):
        if order is not None:
            raise HTTError(f"the order is said twice, by the steps asked in turn and by {order!r}; once")
        chain = ", then ".join(c.text.rstrip(" .") for c in clauses if c.step) + "."
        return " ".join([chain, *(c.text.rstrip(" .") + "." for c in clauses if not c.step)])
    sentences = [c.text.rstrip(" .") + "." for c in clauses]
    if order is None:
        return " ".join(sentences)
    if order == "free":
        return " ".join([*sentences, "In any order."])
    return " ".join(_ordered(clauses, order, sentences))


def _ordered(clauses: list[_Clause], order: str, sentences: list[str]) -> list[str]:
    """The sentences ordered as `order` names their objects: a chain over every task becomes "A, then B,
    then C"; "X first" (or "X last") keeps the sentences and says it; names of no task asked about stay
    a sentence for the reader; a chain that names some tasks and not others is refused."""
    reverse = bool(re.search(r"\bafter\b", order, re.I))
    parts = re.split(r"\bafter\b", order, flags=re.I) if reverse else _CHAIN.split(order)
    names = [p for p in (part.strip() for part in parts) if _head(p) - {"last"}]
    if reverse:
        names.reverse()
    found = [_matching(name, clauses) for name in names]
    if all(f is None for f in found) and all(c.obj is not None for c in clauses):
        return [*sentences, order[0].upper() + order[1:] + "."]
    missing = [n for n, f in zip(names, found, strict=True) if f is None]
    if missing or len(set(found)) < len(found):
        named = ", ".join(repr(n) for n in (missing or names))
        raise HTTError(f"the order {order!r} names {named}, not one task each of those asked about")
    picked = [f for f in found if f is not None]
    if len(picked) == 1 and re.search(r"\b(?:first|last|start|begin|end|finish)\b", order, re.I):
        last = bool(re.search(r"\b(?:last|end|finish)\b", order, re.I))
        if len(clauses) == 2:  # the one named first (last), the other after (before)
            picked = [picked[0], 1 - picked[0]][:: -1 if last else 1]
        else:
            return [*sentences, f"Do {clauses[picked[0]].obj or names[0]} {'last' if last else 'first'}."]
    if len(picked) < len(clauses):
        raise HTTError(f"the order {order!r} leaves the order of the other tasks unsaid")
    return [", then ".join(clauses[k].text.rstrip(" .") for k in picked) + "."]


def _matching(name: str, clauses: list[_Clause]) -> int | None:
    """The one clause whose object the name's words are part of, or its words where the object is not
    known (an answer that is an instruction); None: none, or several."""
    words = _head(name) - {"last"}
    hits = [k for k, c in enumerate(clauses) if words <= _head(c.obj if c.obj is not None else c.text)]
    return hits[0] if len(hits) == 1 else None


def _step_asked(question: str, answer: str) -> str | None:
    """"first", "then" or "last" for a question that asks a step in turn ("What first?", "And then?",
    "What next?", "Last?"); None for any other. "Which first?" answered by a name alone ("The mug.") is
    the order question, answered by a placement ("The mug in the sink.") a step."""
    asked_task = _is(question, "task") and re.search(r"\b(?:next|then|after that|afterwards)\b", question)
    if _is(question, "step_then") or asked_task:
        return "then"
    if _is(question, "step_last"):
        return "last"
    if _is(question, "step_first") and (_is_instruction(answer) or _PLACED.search(answer)):
        return "first"
    return None


def _step_clause(answer: str, said: str) -> _Clause:
    """The step an answer states: an instruction as it is, a placement ("The carrot on the plate") put."""
    answer = _without_yes(answer)
    if _is(answer, "unclear"):
        raise HTTError(f"the answer {answer!r} to {said!r} says nothing certain; say what is meant")
    if _is_instruction(answer):
        return _Clause(answer, None, step=True)
    if _PLACED.search(answer) and not _ORDER_WORD.search(answer):
        return _Clause(f"put {answer}", None, step=True)
    raise HTTError(f"the answer {answer!r} to the step {said!r} names no place; say what goes where")


def _add_step(clauses: list[_Clause], step: str, clause: _Clause, said: str) -> None:
    """Add a step asked in turn. "First" opens the steps; "then" (or "last") follows the step before it,
    or the one task asked before it ("Where does the mug go? ... Then? ..."); "last" ends them. A step
    whose place in the order is unclear is refused by name."""
    steps = [c for c in clauses if c.step]
    if steps and (clauses[-1] is not steps[-1] or steps[-1].obj == "last"):
        raise HTTError(f"the step {said!r} comes after a task or a last step; say where it goes in the order")
    if step == "first" and clauses:
        raise HTTError(f"the step {said!r} comes after tasks already asked; say which goes first")
    if step != "first" and not steps and clauses:  # with nothing before, "What next?" opens the steps
        if len(clauses) != 1:
            raise HTTError(f"the step {said!r} follows {len(clauses)} tasks, not one; say what comes before")
        clauses[0].step = True
    clause.obj = "last" if step == "last" else None
    clauses.append(clause)


def _layout(answer: str, said: str) -> list[_Clause]:
    """The answer to "What goes where?": an instruction, or a list of placements, each put."""
    answer = _without_yes(answer)
    if _is_instruction(answer):
        return [_Clause(answer, None)]
    if _ORDER_WORD.search(answer):
        raise HTTError(f"the answer {answer!r} to {said!r} says an order inside a list; ask 'Order?' of it")
    split = re.split(r"\s*[,;]\s*(?:and\s+)?", answer)
    items = [_ITEM_GOES.sub("", item) for item in split if item]  # "the mug goes in the sink"
    for item in items:
        if not (m := _PLACED.search(item)) or m.start() == 0:
            raise HTTError(f"the answer {item!r} to {said!r} names no place and thing; say what goes where")
    return [_Clause(f"put {item}", _PLACED.split(item)[0]) for item in items]


def _bare_names(question: str, answer: str) -> bool:
    """Is the question a thing's name alone and the answer a place's name alone ("Carrot? Blue plate.")?
    A place is a receptacle of the floor plans, a coloured plate or a region (`_place_types`)."""
    asked, told = find_mentions(question), find_mentions(answer)
    if not _name_alone(question) or len(told) != 1 or asked[0].entry.generic:
        return False
    place = re.fullmatch(rf"(?:{_PREP}\s)?(?:{_DET})?", answer[: told[0].char_start], re.I)
    return bool(
        place and not answer[told[0].char_end :]
        and asked[0].entry.types[0] not in _place_types()
        and told[0].entry.types[0] in _place_types()
    )


def _name_alone(question: str) -> bool:
    """Is the question one name of the lexicon alone, after a determiner at most ("Carrot?", "The mug?")?"""
    names = find_mentions(question)
    return len(names) == 1 and names[0].char_end == len(question) and bool(
        _NAME_ONLY.fullmatch(question[: names[0].char_start])
    )


@cache
def _place_types() -> frozenset[str]:
    """The types a bare answer may name as a place: those of `lexicon.txt`'s receptacles section, and the
    `place_type` words of `questions.txt` (the tabletop's coloured plates, the handover's regions)."""
    text = resources.files("nl2hltl2plan.language").joinpath("lexicon.txt").read_text()
    section = text.split("# --- receptacles", 1)[1].split("\n# ---", 1)[0]
    types = {t for line in section.splitlines()[1:] if " : " in line for t in line.split(" : ")[1].split()}
    return frozenset(types | phrase_words("questions.txt", "place_type"))
