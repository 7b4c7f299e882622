"""An instruction written as questions and answers, as the plain instruction it states (`answered`);
every world's reader may apply it (`headings` re-exports it).

"Q: Where does the mug go? A: In the sink. Q: And the apple? A: The fridge. Q: Order? A: Mug first."
reads as "put the mug in the sink, then put the apple in the fridge". Each answer fills its question's
gap: where an object goes, what goes somewhere, what to do with an object, what the task is (the answer
is an instruction), whether there is more, and the order. A follow-up ("And the apple?", "What about
in the sink?") asks the question before it again with its new object or place. The order answer names
the tasks by their objects ("mug first", "red before blue", "the apple, then the mug"), or frees the
order ("any", "doesn't matter"; `questions.txt` lists these phrases). Names that match no object asked
about (a colour within a group: "Where do the blocks go? ... red before blue") are left to the reader as
a sentence of their own.

Anything else is refused by name (HTTError): a question no frame covers, a question with no answer or an
answer with no question, an answer that says nothing certain ("not sure"), an order answer that names
one task and not another ("the mug before the bowl" where no bowl was asked about).

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

from nl2hltl2plan.errors import HTTError
from nl2hltl2plan.language.content_words import categories, phrase_list_pattern

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
_PREP = r"(?:in|into|inside|on|onto|on top of|to|under|at|by|beside|next to|in front of|behind|towards?)"
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
        said = _bare(question)
        if _is(said, "order", "order_matters", "order_free", "order_either"):
            order = _order_answer(said, _bare(answer[1]), order)
            if re.search(r"\bfirst\b", said, re.I) and not _ORDER_SAID.search(order):
                order += " first"  # "Which first? The mug."
            continue
        frame, clause = _answer_clause(said, _bare(answer[1]), frame, question)
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
