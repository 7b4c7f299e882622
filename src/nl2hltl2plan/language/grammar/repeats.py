"""A sentence that asks for the task before it again, for another thing (issue 23): "Wash the mug and put
it on the counter. The cup too." is "... Wash the cup and put it on the counter." The fragment forms
(`REPEAT_FRAGMENT`): "The cup too.", "And the egg as well.", "Same for the bowl.", "Do the same with the
tomato.", "Also the pencil.".

The task before is repeated only where its sentence is one plain task: a task verb opening it, then the
thing it acts on (one thing, singular), then only task verbs, "and", "it", prepositions and one place;
and where the fragment says nothing but its things ("The red tomato too." and "The tomato in the
microwave too." stay).
Any other fragment stays as written, and check 1 names it unless a task does the whole of the task before
for the thing it names (`unsupported_steps.repeats_for_another`).

>>> repeated_for_another("Wash the mug and put it on the counter. The cup too.")
'Wash the mug and put it on the counter. Wash the cup and put it on the counter.'
>>> repeated_for_another("Put the mug in the sink after the apple is in the fridge. The cup too.")
'Put the mug in the sink after the apple is in the fridge. The cup too.'
>>> repeated_for_another("Put the apple in the fridge. The tomato in the microwave too.")
'Put the apple in the fridge. The tomato in the microwave too.'
"""

from __future__ import annotations

import re

from nl2hltl2plan.language.content_words import DETERMINERS, categories
from nl2hltl2plan.language.grounding import Mention, find_mentions, tokens

_DET = r"(?:the|a|an|my|your|his|her|their|our|this|that|these|those)"
# a word of a noun phrase: no preposition, joiner or verb ("the tomato in the microwave too" says a place)
_W = r"(?!(?:in|into|on|onto|inside|to|at|under|near|by|from|with|and|then|too|also|as|is|are|goes)\b)[a-z]+"
_NP = rf"{_DET}\s+{_W}(?:\s+{_W}){{0,2}}"
_NPS = rf"{_NP}(?:\s*,?\s*(?:and\s+)?{_NP})*"
REPEAT_FRAGMENT = re.compile(
    r"^\s*(?:(?:and|also|plus)\s+)*"
    rf"(?:(?:please\s+)?(?:do\s+)?(?:the\s+)?same\s+(?:thing\s+)?(?:for|with|to)\s+{_NPS}"
    rf"|{_NPS}\s*,?\s+(?:too|as\s+well|also)"
    rf"|(?:and|also|plus)\s+{_NPS})"
    r"\s*(?:,?\s*(?:too|as\s+well|also|please))?\s*$",
    re.I,
)
_SENTENCE = re.compile(r"[^.;!?\n]+[.;!?\n]*")
# "Then do the same with the cup.", "After that, the cup too.": the repeat comes after the task before; the
# connective stays before the task written out (the order the words say)
_ORDER_LEAD = re.compile(
    r"^\s*(?:(?:and\s+)?then|after\s+that|afterwards|next|once\s+(?:that's|that\s+is)\s+done"
    r"|once\s+you(?:'ve|\s+have)\s+done\s+that)\s*,?\s+",
    re.I,
)
# "X, and then do the same with the cup": the repeat said inside the sentence of its task is a sentence
_SAME_INSIDE = re.compile(
    r"(?:,\s*(?:and\s+)?|\s+and\s+)(?P<conn>then|after\s+that|once\s+(?:that's|that\s+is)\s+done"
    r"|once\s+you(?:'ve|\s+have)\s+done\s+that)(?=\s*,?\s+(?:do\s+)?(?:the\s+)?same\s+(?:thing\s+)?(?:for|with|to)\s)",
    re.I,
)
# the words a plain one-task sentence may hold besides its thing and its place
_PLAIN = DETERMINERS | {"and", "it", "please", "in", "into", "on", "onto", "inside", "to", "then"}
_PLAIN |= {"at", "under", "by", "light", "of"}  # "look at the vase by the light of the lamp"
_FRAGMENT_WORDS = DETERMINERS | set("and also plus please do same thing for with to too as well".split())
_TASK_VERBS = frozenset(
    {"verb_any", "verb_clean_place", "verb_heat_place", "verb_cool_place", "verb_sliced"}
    | {"verb_examine_in_light"}
)


def repeated_for_another(text: str) -> str:
    """Each fragment sentence that repeats a plain one-task sentence for other things, written out."""
    out: list[str] = []
    task = ""  # the last sentence that is not a fragment
    written = False  # the sentence split off by `_SAME_INSIDE` is kept only where its repeat is written out
    for s in _SENTENCE.finditer(_SAME_INSIDE.sub(lambda m: ". " + m["conn"].capitalize(), text)):
        body = s.group(0)
        core = body.rstrip(" .;!?\n")
        said = _ORDER_LEAD.match(core)
        fragment = core[said.end() :] if said else core
        if task and REPEAT_FRAGMENT.match(fragment):
            things = [m for m in find_mentions(fragment) if not m.entry.generic]
            copies = [c for c in (_with_thing(task, m) for m in things) if c]
            # after an order word, one thing only ("then the cup and the bowl": their own order unsaid)
            one = not said or len(things) == 1
            if things and len(copies) == len(things) and _only_things(fragment, things) and one:
                lead = core[: len(core) - len(core.lstrip())]
                copies = [c[:1].upper() + c[1:] for c in copies]  # the task's order word is not copied
                if said:  # "Then put the cup on the counter."
                    lead, copies = said.group(0), [c[:1].lower() + c[1:] for c in copies]
                out.append(lead + ". ".join(copies) + body[len(core) :])
                written = True
                continue
        if not REPEAT_FRAGMENT.match(fragment):
            task = fragment.strip()  # its order word stays with it ("After that, look at X. Then the Y too.")
        out.append(body)
    return "".join(out) if written else text


def _only_things(fragment: str, things: list[Mention]) -> bool:
    """The fragment says nothing but its things ("the tomato in the microwave too" says a place)."""
    in_thing = {i for m in things for i in range(m.start, m.end)}
    return all(i in in_thing or w in _FRAGMENT_WORDS for i, (w, _, _) in enumerate(tokens(fragment)))


def _with_thing(sentence: str, thing: Mention) -> str | None:
    """`sentence` with its thing replaced by `thing`, where it is a plain one-task sentence (None else)."""
    if thing.plural:
        return None
    toks = tokens(sentence)
    named = [m for m in find_mentions(sentence) if not m.entry.generic and not _light_of(m, toks)]
    if len(named) != 2 or named[0].plural or len(toks) < 3:
        return None
    if named[0].entry.types[0] == thing.entry.types[0]:
        return None  # "the mug ... Same for the coffee mug": one type, the atoms cannot tell them apart
    at = named[0].start - 1  # the thing follows the opening verb ("look at") and its determiner
    if not (at == 1 or (at == 2 and toks[1][0] == "at")) or toks[at][0] not in DETERMINERS:
        return None
    if not categories(toks[0][0]) & _TASK_VERBS:
        return None
    in_mention = {i for m in named for i in range(m.start, m.end)}
    for i, (word, _, _) in enumerate(toks):
        if i not in in_mention and word not in _PLAIN and not categories(word) & _TASK_VERBS:
            return None
    return sentence[: named[0].char_start] + thing.surface + sentence[named[0].char_end :]


def _light_of(m: Mention, toks: list[tuple[str, int, int]]) -> bool:
    """"the light of the lamp": the lamp's light, no thing of its own."""
    return m.surface.lower() == "light" and m.end < len(toks) and toks[m.end][0] == "of"
